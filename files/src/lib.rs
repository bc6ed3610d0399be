//! Files a reader never sees half written: the text goes to a temporary
//! file beside the target (`NAME.partial`), which is then renamed over it
//! (a rename within one directory is atomic on the file systems fwav runs
//! on). A run killed at any moment leaves either the old file or the new
//! one, and at worst a stray `.partial` that the next write replaces.
//! That is for the files a run owns (a design run's directory,
//! [`Existing::Replace`]).
//!
//! A file the user names (`--plot`, an output directory's files) is
//! never replaced: [`create_new`] and [`write_new`] make it under a
//! temporary name beside its target and give it the target's name only
//! if nothing has it (`tempfile`'s `persist_noclobber`: a no-replace
//! rename, or a link where the file system has none; one with neither
//! cannot take such files), so a file that was there, or was made while
//! the run went on, is left as it was, and a killed run leaves no half
//! file under the name (at worst a hidden `.NAME.*.partial` beside it).
//! The commands also refuse such a name before they start, so that a
//! long run is not lost at its end.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

use std::path::{Path, PathBuf};

/// What a write does with a file that has its name already.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Existing {
    /// Replace it: a file the run owns ([`write_atomic_to`]).
    Replace,
    /// Keep it and refuse: a file the user named ([`write_new`]).
    Keep,
}

/// A file could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// Something has the name already, and is kept ([`Existing::Keep`]).
    #[error(
        "{path} exists, and is left as it is (an existing file is never overwritten): \
         choose a new name or remove it"
    )]
    Exists {
        /// The name.
        path: PathBuf,
    },
    /// The file system refused (no such directory, no permission, disk
    /// full).
    #[error("writing {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// Writes `contents` to `path` as `existing` says: atomically over what
/// is there ([`write_atomic_to`]), or only if nothing is ([`write_new`]).
pub fn write_to(
    path: &Path,
    contents: impl AsRef<[u8]>,
    existing: Existing,
) -> Result<(), WriteError> {
    match existing {
        Existing::Replace => write_atomic_to(path, contents),
        Existing::Keep => write_new(path, contents),
    }
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
    let error = |source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    };
    std::fs::write(&temporary, contents).map_err(error)?;
    std::fs::rename(&temporary, path).map_err(error)
}

/// Makes the file `path`, which must not exist, by `make` and nothing
/// else (module docs): `make` writes a temporary file beside `path`, whose
/// name it is given (it ends in `path`'s extension, which some writers
/// read the format from); the file then takes the name `path` if nothing
/// has it, and is removed otherwise, or if `make` fails.
///
/// Errors: `make`'s, or [`WriteError`] (into `E`): `path` exists
/// (before or after `make`: [`WriteError::Exists`]), or its directory
/// cannot hold the file.
pub fn create_new<E: From<WriteError>>(
    path: &Path,
    make: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    let taken = || WriteError::Exists {
        path: path.to_path_buf(),
    };
    let io = |source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    };
    if std::fs::symlink_metadata(path).is_ok() {
        return Err(taken().into());
    }
    let dir = directory_of(path);
    let mut suffix = String::from(".partial");
    if let Some(extension) = path.extension() {
        suffix.push('.');
        suffix.push_str(&extension.to_string_lossy());
    }
    let prefix = format!(
        ".{}.",
        path.file_name().unwrap_or_default().to_string_lossy()
    );
    let mut builder = tempfile::Builder::new();
    // A file anyone may read, as the umask allows (a temporary file's own
    // default is its owner's only).
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    // The directory's own error, not one naming the temporary file.
    std::fs::metadata(dir).map_err(io)?;
    let temporary = builder
        .prefix(&prefix)
        .suffix(&suffix)
        .tempfile_in(dir)
        .map_err(|e| io(without_path(e)))?;
    // On failure the temporary file is removed when dropped.
    make(temporary.path())?;
    temporary.persist_noclobber(path).map_err(|e| {
        if e.error.kind() == std::io::ErrorKind::AlreadyExists {
            taken()
        } else {
            io(without_path(e.error))
        }
    })?;
    Ok(())
}

/// Why a file cannot be made new under a name ([`check_new`]).
#[derive(Debug, thiserror::Error)]
pub enum NewFileError {
    /// Something has the name (a file, a directory, a link).
    #[error("{0} exists")]
    Taken(PathBuf),
    /// The name's directory is not one.
    #[error("{0} is not a directory")]
    NotADirectory(PathBuf),
    /// The name's directory cannot be read (missing, no permission).
    #[error("its directory {dir}: {source}")]
    Directory {
        /// The directory.
        dir: PathBuf,
        /// The file system's reason.
        source: std::io::Error,
    },
}

/// Checks, before a run that ends by writing it, that `path` can be made
/// new: nothing has the name, and its directory is one. The commands
/// word the error for their flag; [`create_new`] checks again when it
/// writes.
///
/// # Errors
/// [`NewFileError`], the first that applies.
pub fn check_new(path: &Path) -> Result<(), NewFileError> {
    if std::fs::symlink_metadata(path).is_ok() {
        return Err(NewFileError::Taken(path.to_path_buf()));
    }
    let dir = directory_of(path);
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(NewFileError::NotADirectory(dir.to_path_buf())),
        Err(source) => Err(NewFileError::Directory {
            dir: dir.to_path_buf(),
            source,
        }),
    }
}

/// The directory `path` is in: its parent, or the current directory for
/// a bare name.
pub fn directory_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// `tempfile`'s error without the temporary file's name it adds (a name
/// the user never gave): the system's error, or its kind.
fn without_path(e: std::io::Error) -> std::io::Error {
    let code = e
        .get_ref()
        .and_then(|inner| inner.source())
        .and_then(|source| source.downcast_ref::<std::io::Error>())
        .and_then(std::io::Error::raw_os_error);
    match code {
        Some(code) => std::io::Error::from_raw_os_error(code),
        None => e.kind().into(),
    }
}

/// Writes `contents` to `path`, which must not exist, as [`create_new`]
/// does.
pub fn write_new(path: &Path, contents: impl AsRef<[u8]>) -> Result<(), WriteError> {
    create_new(path, |temporary| {
        std::fs::write(temporary, contents).map_err(|source| WriteError::Io {
            path: path.to_path_buf(),
            source,
        })
    })
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

    /// The names in `dir`, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    /// A user's file is never replaced: not one there before, not one
    /// made while the new one was being written; a failed or refused
    /// write leaves no temporary file; a missing directory is named.
    #[test]
    fn a_new_file_never_replaces_one() {
        let dir = std::env::temp_dir().join(format!("fwav-new-files-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mine = dir.join("plot.png");
        std::fs::write(&mine, "mine").unwrap();
        let e = write_new(&mine, "new").unwrap_err();
        assert!(
            matches!(&e, WriteError::Exists { path } if path == &mine),
            "{e}"
        );
        assert!(e.to_string().contains("never overwritten"), "{e}");
        assert_eq!(std::fs::read_to_string(&mine).unwrap(), "mine");
        assert_eq!(names(&dir), ["plot.png"]);

        // Made meanwhile: the maker's file is dropped, the other kept.
        let late = dir.join("late.csv");
        let e = create_new(&late, |temporary| {
            assert!(temporary.to_string_lossy().ends_with(".csv"));
            std::fs::write(temporary, "new").unwrap();
            std::fs::write(&late, "theirs").unwrap();
            Ok::<(), WriteError>(())
        })
        .unwrap_err();
        assert!(matches!(e, WriteError::Exists { .. }), "{e}");
        assert_eq!(std::fs::read_to_string(&late).unwrap(), "theirs");
        assert_eq!(names(&dir), ["late.csv", "plot.png"]);

        // A maker that fails leaves nothing.
        let failed = dir.join("failed.png");
        let e = create_new(&failed, |_| {
            Err(WriteError::Io {
                path: failed.clone(),
                source: std::io::Error::other("the encoder gave up"),
            })
        })
        .unwrap_err();
        assert!(e.to_string().contains("the encoder gave up"), "{e}");
        assert_eq!(names(&dir), ["late.csv", "plot.png"]);

        // A new name gets the whole file, and only it is left.
        let fresh = dir.join("history.csv");
        write_new(&fresh, "t,cl\n").unwrap();
        assert_eq!(std::fs::read_to_string(&fresh).unwrap(), "t,cl\n");
        assert_eq!(names(&dir), ["history.csv", "late.csv", "plot.png"]);

        let e = write_new(&dir.join("missing").join("b.txt"), "x").unwrap_err();
        assert!(
            matches!(&e, WriteError::Io { path, .. } if path.ends_with("missing/b.txt")),
            "{e}"
        );
        // The system's reason, not the temporary file's name.
        assert!(!e.to_string().contains(".partial"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
