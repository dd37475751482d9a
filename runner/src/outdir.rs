//! The exclusive lock on a run's output directory: two runs into the same `--out` would interleave
//! results.jsonl and overwrite each other's reports, so the second one stops before touching
//! anything (exit code 96) and names the holder's pid.
//!
//! The lock is an advisory `flock` on `OUT/.shadowcheck.lock` (the fs4 crate), held for the whole
//! run and released by the kernel when the process ends, even by SIGKILL: a stale lock file never
//! blocks a later run. The file holds the holder's pid, for the message only.

use fs4::FileExt;
use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// The lock file's name inside the output directory.
pub const LOCK_FILE: &str = ".shadowcheck.lock";

#[derive(Debug, thiserror::Error)]
pub enum LockError {
    #[error("{dir} is in use by another shadowcheck run{} (its lock is {dir}/{LOCK_FILE}); wait for it, or give another --out", .pid.map(|p| format!(" (pid {p})")).unwrap_or_default())]
    Busy { dir: String, pid: Option<u32> },
    #[error("locking {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// Held for as long as the directory is in use; dropping it releases the lock.
#[derive(Debug)]
pub struct OutLock {
    _file: File,
}

impl OutLock {
    /// Takes the lock on `dir` (which must exist) without waiting.
    pub fn acquire(dir: &Path) -> Result<OutLock, LockError> {
        let path = dir.join(LOCK_FILE);
        let io = |source| LockError::Io {
            path: path.clone(),
            source,
        };
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(io)?;
        match FileExt::try_lock(&file) {
            Ok(()) => {}
            Err(fs4::TryLockError::WouldBlock) => {
                let mut text = String::new();
                let _ = file.read_to_string(&mut text);
                return Err(LockError::Busy {
                    dir: dir.display().to_string(),
                    pid: text.trim().parse().ok(),
                });
            }
            Err(fs4::TryLockError::Error(e)) => return Err(io(e)),
        }
        file.set_len(0).map_err(io)?;
        file.rewind().map_err(io)?;
        file.write_all(format!("{}\n", std::process::id()).as_bytes())
            .map_err(io)?;
        Ok(OutLock { _file: file })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_lock_on_the_same_directory_is_refused_with_the_pid_until_released() {
        let d = std::env::temp_dir().join(format!("shadowcheck-lock-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let first = OutLock::acquire(&d).unwrap();
        // flock locks belong to the open file description: a second open in this process conflicts.
        match OutLock::acquire(&d) {
            Err(LockError::Busy { pid, .. }) => assert_eq!(pid, Some(std::process::id())),
            other => panic!("{other:?}"),
        }
        drop(first);
        assert!(OutLock::acquire(&d).is_ok());
    }
}
