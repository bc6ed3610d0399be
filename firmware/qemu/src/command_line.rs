//! The command line QEMU passes to the program (`-append "..."`), read
//! over semihosting (`SYS_GET_CMDLINE`), and its `key=value` words.

/// Reads the command line into `buf`; empty if there is none or it does
/// not fit (QEMU refuses a buffer too small for it).
pub fn read(buf: &mut [u8]) -> &str {
    if buf.is_empty() {
        return "";
    }
    let block = [buf.as_mut_ptr() as usize, buf.len()];
    // SAFETY: SYS_GET_CMDLINE writes at most `block[1]` bytes (the text and
    // its NUL) into `buf`, which lives through the call; it returns 0 on
    // success.
    let status =
        unsafe { cortex_m_semihosting::syscall(cortex_m_semihosting::nr::GET_CMDLINE, &block) };
    if status != 0 {
        return "";
    }
    let len = buf.iter().position(|&b| b == 0).unwrap_or(0);
    core::str::from_utf8(&buf[..len]).unwrap_or("")
}

/// The value of `key=value` among the whitespace-separated words of `line`.
pub fn value<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    line.split_whitespace()
        .find_map(|word| word.strip_prefix(key)?.strip_prefix('='))
}
