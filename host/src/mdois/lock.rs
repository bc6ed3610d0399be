//! The lock of a run directory, `fwav.lock`: one process at a time
//! computes in a run. The lock is an advisory `flock` on the file, which
//! the kernel releases when its holder ends, however it ends (SIGKILL
//! too); the file's text names the holder — pid, host, since when — for
//! the message that refuses a second writer. A lock file that names a
//! holder but whose lock is free was left by a process that ended
//! without cleaning up (killed): the next writer takes it over and says
//! so ([`RunLock::stale`]). A holder removes the file when it lets go.

use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, SeekFrom, Write};
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use rustix::fs::{flock, FlockOperation};
use serde::{Deserialize, Serialize};

/// The lock file's name in the run's directory.
pub const LOCK_FILE: &str = "fwav.lock";

/// Who holds (or held) a run directory's lock: the lock file's text.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct LockHolder {
    /// Its process id.
    pub pid: u32,
    /// The host it runs on.
    pub host: String,
    /// When it took the lock, seconds since the Unix epoch.
    pub since_unix_s: u64,
}

impl std::fmt::Display for LockHolder {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "process {} on {}", self.pid, self.host)
    }
}

fn now_unix_s() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// " (for N s)": how long `holder` has held its lock, if known.
fn held_for(holder: &LockHolder) -> String {
    now_unix_s()
        .checked_sub(holder.since_unix_s)
        .map_or_else(String::new, |s| format!(" (for {s} s)"))
}

impl LockHolder {
    /// This process.
    fn this_process() -> Self {
        Self {
            pid: std::process::id(),
            host: rustix::system::uname()
                .nodename()
                .to_string_lossy()
                .into_owned(),
            since_unix_s: now_unix_s(),
        }
    }
}

/// Why a run directory's lock was not taken.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    /// Another process holds it.
    #[error(
        "{dir} is in use: {} computes in it{}, holding {dir}/{LOCK_FILE}; wait for that run to \
         end, or stop it and resume the run then",
        .holder.as_ref().map_or_else(|| "another fwav process".to_string(), ToString::to_string),
        .holder.as_ref().map_or_else(String::new, held_for),
        dir = .dir.display()
    )]
    Held {
        /// The run's directory.
        dir: PathBuf,
        /// The holder, as its lock file names it (`None`: the file does
        /// not name one yet).
        holder: Option<LockHolder>,
    },
    /// The lock file could not be opened, locked or written.
    #[error("the lock file {}: {source}", .path.display())]
    Io {
        /// The lock file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// A run directory's lock, held until dropped.
#[derive(Debug)]
pub struct RunLock {
    file: File,
    path: PathBuf,
    stale: Option<LockHolder>,
}

/// Whether the open `file` is still the one at `path` (its last holder
/// may have removed it after this process opened it).
fn still_at(file: &File, path: &Path) -> bool {
    match (file.metadata(), std::fs::metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// The holder a lock file names, if its text is one.
fn named_holder(file: &mut File) -> Option<LockHolder> {
    let mut text = String::new();
    file.seek(SeekFrom::Start(0)).ok()?;
    file.read_to_string(&mut text).ok()?;
    serde_json::from_str(&text).ok()
}

impl RunLock {
    /// Takes the lock of the run in `dir` (an existing directory), or
    /// says who holds it.
    pub fn acquire(dir: &Path) -> Result<Self, LockError> {
        let path = dir.join(LOCK_FILE);
        let io = |source: std::io::Error| LockError::Io {
            path: path.clone(),
            source,
        };
        // A few tries: the file can be removed by its holder between
        // this process's open and its lock.
        for _ in 0..8 {
            let mut file = OpenOptions::new()
                .read(true)
                .write(true)
                .create(true)
                .truncate(false)
                .open(&path)
                .map_err(io)?;
            match flock(&file, FlockOperation::NonBlockingLockExclusive) {
                Ok(()) => {}
                Err(e) if e == rustix::io::Errno::WOULDBLOCK => {
                    return Err(LockError::Held {
                        dir: dir.to_path_buf(),
                        holder: named_holder(&mut file),
                    });
                }
                Err(e) => return Err(io(e.into())),
            }
            if !still_at(&file, &path) {
                continue;
            }
            let stale = named_holder(&mut file);
            let text = serde_json::to_string(&LockHolder::this_process())
                .map_err(|e| io(std::io::Error::other(e)))?;
            file.set_len(0).map_err(io)?;
            file.seek(SeekFrom::Start(0)).map_err(io)?;
            file.write_all(text.as_bytes()).map_err(io)?;
            file.sync_data().map_err(io)?;
            return Ok(Self { file, path, stale });
        }
        Err(LockError::Held {
            dir: dir.to_path_buf(),
            holder: None,
        })
    }

    /// The holder of a lock left behind by a process that ended without
    /// letting go of it (killed), which this lock took over.
    pub fn stale(&self) -> Option<&LockHolder> {
        self.stale.as_ref()
    }
}

impl Drop for RunLock {
    /// Removes the lock file (while still holding its lock: a process that
    /// opened it meanwhile finds it gone and tries again).
    fn drop(&mut self) {
        if still_at(&self.file, &self.path) {
            std::fs::remove_file(&self.path).ok();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A second lock of the same directory is refused naming this
    /// process; once the first is dropped the file is gone and the lock
    /// free; a file left naming a holder is taken over as stale.
    #[test]
    fn one_holder_at_a_time() {
        let dir = std::env::temp_dir().join(format!("fwav-lock-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let first = RunLock::acquire(&dir).unwrap();
        assert_eq!(first.stale(), None);
        match RunLock::acquire(&dir).unwrap_err() {
            LockError::Held {
                holder: Some(h), ..
            } => assert_eq!(h.pid, std::process::id()),
            other => panic!("{other}"),
        }
        drop(first);
        assert!(!dir.join(LOCK_FILE).exists());
        let left = LockHolder {
            pid: 1,
            host: "elsewhere".into(),
            since_unix_s: 0,
        };
        std::fs::write(dir.join(LOCK_FILE), serde_json::to_string(&left).unwrap()).unwrap();
        let second = RunLock::acquire(&dir).unwrap();
        assert_eq!(second.stale(), Some(&left));
        drop(second);
        std::fs::remove_dir_all(&dir).ok();
    }
}
