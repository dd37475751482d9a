//! results.jsonl: one [`Line`] per record, appended as each test finishes and written out after each
//! batch, so a killed run leaves everything finished so far on disk (and `--resume` can continue it).
//!
//! Only whole lines reach the file: records are collected in memory and written at each batch's end;
//! when a write fails part-way (a full disk), the file is cut back to its last complete line and the
//! reporter stops writing (the error is returned once; the run goes on and says so at the end).

use crate::events::{Event, Reporter};
use crate::records::{Line, RunMeta};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::Path;

/// Where the lines go: a file that can be cut back to a length.
pub trait Store: Send {
    fn append(&mut self, bytes: &[u8]) -> std::io::Result<()>;
    /// Cuts the store back to `len` bytes (what was there before a failed append).
    fn truncate(&mut self, len: u64) -> std::io::Result<()>;
}

impl Store for File {
    fn append(&mut self, bytes: &[u8]) -> std::io::Result<()> {
        self.write_all(bytes)
    }
    fn truncate(&mut self, len: u64) -> std::io::Result<()> {
        // Opened in append mode: later writes go to the (new) end.
        self.set_len(len)
    }
}

/// Pending bytes (whole lines) written out before the batch ends.
const PENDING_MAX: usize = 1 << 20;

pub struct JsonlReporter<S: Store = File> {
    store: S,
    /// Complete lines not yet written.
    pending: Vec<u8>,
    /// Bytes known to be in the store, all of them whole lines.
    written: u64,
    /// A write failed: nothing more is written (the file holds whole lines only).
    failed: bool,
}

impl JsonlReporter<File> {
    /// Starts `path` afresh with `meta` as its first line.
    pub fn create(path: &Path, meta: &RunMeta) -> std::io::Result<JsonlReporter> {
        let file = OpenOptions::new()
            .create(true)
            .write(true)
            .truncate(true)
            .open(path)?;
        drop(file);
        let mut r = JsonlReporter::over(OpenOptions::new().append(true).open(path)?, 0);
        r.push(&Line::Meta(meta.clone()))?;
        r.flush()?;
        Ok(r)
    }

    /// Appends to an existing file (`--resume`; cut any partial last line first).
    pub fn append(path: &Path) -> std::io::Result<JsonlReporter> {
        let file = OpenOptions::new().append(true).open(path)?;
        let len = file.metadata()?.len();
        Ok(JsonlReporter::over(file, len))
    }
}

impl<S: Store> JsonlReporter<S> {
    /// A reporter appending to `store`, which already holds `len` bytes of whole lines.
    pub fn over(store: S, len: u64) -> JsonlReporter<S> {
        JsonlReporter {
            store,
            pending: Vec::with_capacity(1 << 16),
            written: len,
            failed: false,
        }
    }

    fn push(&mut self, line: &Line) -> std::io::Result<()> {
        if self.failed {
            return Ok(());
        }
        serde_json::to_writer(&mut self.pending, line)?;
        self.pending.push(b'\n');
        // A long batch (or `merge`, which writes everything at once) does not pile up in memory.
        if self.pending.len() >= PENDING_MAX {
            return self.flush();
        }
        Ok(())
    }

    /// Writes the pending lines; on a failure cuts the store back to its last whole line.
    fn flush(&mut self) -> std::io::Result<()> {
        if self.failed || self.pending.is_empty() {
            self.pending.clear();
            return Ok(());
        }
        match self.store.append(&self.pending) {
            Ok(()) => {
                self.written += self.pending.len() as u64;
                self.pending.clear();
                Ok(())
            }
            Err(e) => {
                self.failed = true;
                self.pending = Vec::new();
                let cut = self.store.truncate(self.written);
                let msg = match cut {
                    Ok(()) => format!("writing results.jsonl: {e} (cut back to its last whole line; nothing more is written to it)"),
                    Err(c) => format!("writing results.jsonl: {e} (and cutting it back to its last whole line failed: {c})"),
                };
                Err(std::io::Error::new(e.kind(), msg))
            }
        }
    }
}

impl<S: Store> Reporter for JsonlReporter<S> {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        match ev {
            Event::CaseFinished {
                result,
                replayed: false,
            } => self.push(&Line::Result(Box::new((*result).clone()))),
            Event::LoadError(e) => self.push(&Line::LoadError((*e).clone())),
            Event::BatchFinished { .. }
            | Event::BackendStarted { .. }
            | Event::BackendFinished { .. }
            | Event::RunFinished { .. } => self.flush(),
            _ => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::records::LoadError;

    /// A disk that takes `room` bytes, then fails (keeping the part of a write that fitted, as a
    /// real full disk does).
    struct FullDisk {
        bytes: Vec<u8>,
        room: usize,
    }

    impl Store for FullDisk {
        fn append(&mut self, bytes: &[u8]) -> std::io::Result<()> {
            let fit = bytes.len().min(self.room - self.bytes.len());
            self.bytes.extend_from_slice(&bytes[..fit]);
            if fit < bytes.len() {
                return Err(std::io::Error::other("No space left on device"));
            }
            Ok(())
        }
        fn truncate(&mut self, len: u64) -> std::io::Result<()> {
            self.bytes.truncate(len as usize);
            Ok(())
        }
    }

    #[test]
    fn a_full_disk_leaves_whole_lines_only_and_reports_the_error_once() {
        let mut r = JsonlReporter::over(
            FullDisk {
                bytes: vec![],
                room: 300,
            },
            0,
        );
        let mut errors = 0;
        for batch in 0..10 {
            for i in 0..3 {
                let e = LoadError {
                    file: format!("f{batch}"),
                    case: Some(format!("case {i}")),
                    message: "bad".into(),
                };
                r.event(&Event::LoadError(&e)).unwrap();
            }
            if r.event(&Event::BatchFinished { backend: "b" }).is_err() {
                errors += 1;
            }
        }
        assert_eq!(errors, 1);
        let text = String::from_utf8(r.store.bytes.clone()).unwrap();
        assert!(!text.is_empty() && text.ends_with('\n'), "{text:?}");
        for line in text.lines() {
            serde_json::from_str::<Line>(line).unwrap();
        }
        // Less than the room: the batch that did not fit is gone entirely.
        assert!(text.len() < 300);
    }
}
