//! Not a test group: the `fwav` program run as a user runs it, from the
//! workspace root (where the README's commands run, and its relative
//! paths, `configs/coarse.toml` say, resolve), for every group that
//! drives the program as a process.

use std::io::Read as _;
use std::process::{Command, Output, Stdio};

/// Runs `fwav args` from the workspace root and waits for it: its exit
/// status and everything it printed.
pub fn fwav(args: &[&str]) -> Output {
    fwav_command(args).output().expect("the fwav binary runs")
}

/// A fresh, empty scratch directory `fwav-NAME-PID` in the system's
/// temporary directory, for the files one test gives the program and
/// the ones it writes (absolute, so they resolve from any working
/// directory).
pub fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("fwav-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `fwav args` to be run from the workspace root with nothing on its
/// standard input (as in CI), for a test that sets more (arguments that
/// are paths, its output's pipes, the environment) or starts it and acts
/// while it runs.
pub fn fwav_command(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_fwav"));
    command
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .stdin(Stdio::null());
    command
}

/// A pseudo-terminal `columns` wide: its master side, and the slave side
/// as a file to hand to a child.
pub fn terminal(columns: u16) -> (std::fs::File, std::fs::File) {
    use rustix::pty::{grantpt, openpt, ptsname, unlockpt, OpenptFlags};
    let master = openpt(OpenptFlags::RDWR | OpenptFlags::NOCTTY | OpenptFlags::CLOEXEC).unwrap();
    grantpt(&master).unwrap();
    unlockpt(&master).unwrap();
    let name = ptsname(&master, Vec::new()).unwrap();
    let slave = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(name.to_str().unwrap())
        .unwrap();
    let size = rustix::termios::Winsize {
        ws_row: 24,
        ws_col: columns,
        ws_xpixel: 0,
        ws_ypixel: 0,
    };
    rustix::termios::tcsetwinsize(&slave, size).unwrap();
    (std::fs::File::from(master), slave)
}

/// Runs `fwav args` from the workspace root with its standard error on a
/// terminal `columns` wide (as a person runs it) and waits for it: its
/// exit status and standard output, and all the terminal showed.
pub fn fwav_on_terminal(args: &[&str], columns: u16) -> (Output, String) {
    let (mut master, slave) = terminal(columns);
    // A terminal that says what it is (indicatif draws nothing on one
    // whose TERM is unset or "dumb", as CI's may be).
    let child = fwav_command(args)
        .env("TERM", "xterm")
        .stdout(Stdio::piped())
        .stderr(Stdio::from(slave))
        .spawn()
        .expect("the fwav binary runs");
    // The terminal read as the program writes (its buffer is small); the
    // read ends when the program's side closes.
    let reader = std::thread::spawn(move || {
        let (mut text, mut buffer) = (Vec::new(), [0u8; 4096]);
        while let Ok(n) = master.read(&mut buffer) {
            if n == 0 {
                break;
            }
            text.extend_from_slice(&buffer[..n]);
        }
        text
    });
    let out = child.wait_with_output().unwrap();
    let text = reader.join().unwrap();
    (out, String::from_utf8_lossy(&text).into_owned())
}
