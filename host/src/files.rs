//! Files a reader never sees half written: the text goes to a temporary
//! file beside the target (`NAME.partial`), which is then renamed over it
//! (a rename within one directory is atomic on the file systems fwav runs
//! on). A run killed at any moment leaves either the old file or the new
//! one, and at worst a stray `.partial` that the next write replaces.

use std::path::{Path, PathBuf};

/// A file could not be written.
#[derive(Debug, thiserror::Error)]
#[error("writing {path}: {source}")]
pub struct WriteError {
    /// The file.
    pub path: PathBuf,
    /// The cause.
    pub source: std::io::Error,
}

/// Writes `contents` to `dir/name` atomically (module docs).
pub fn write_atomic(
    dir: &Path,
    name: &str,
    contents: impl AsRef<[u8]>,
) -> Result<PathBuf, WriteError> {
    let path = dir.join(name);
    write_atomic_to(&path, contents)?;
    Ok(path)
}

/// Writes `contents` to `path` atomically (module docs), through
/// `path.partial` beside it.
pub fn write_atomic_to(path: &Path, contents: impl AsRef<[u8]>) -> Result<(), WriteError> {
    let mut temporary = path.as_os_str().to_owned();
    temporary.push(".partial");
    let error = |source| WriteError {
        path: path.to_path_buf(),
        source,
    };
    std::fs::write(&temporary, contents).map_err(error)?;
    std::fs::rename(&temporary, path).map_err(error)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The file appears whole, replaces an older one and leaves no
    /// temporary behind; a missing directory is an error naming the file.
    #[test]
    fn writes_whole_files() {
        let dir = std::env::temp_dir().join(format!("fwav-files-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        write_atomic(&dir, "a.txt", "old").unwrap();
        let path = write_atomic(&dir, "a.txt", "new").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        assert!(!dir.join("a.txt.partial").exists());
        let e = write_atomic(&dir.join("missing"), "b.txt", "x").unwrap_err();
        assert!(e.to_string().contains("b.txt"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
