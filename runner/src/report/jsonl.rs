//! results.jsonl: one [`Line`] per record, appended as each test finishes and written out after each
//! batch, so a killed run leaves everything finished so far on disk (and `--resume` can continue it).
//!
//! Only whole lines reach the file: records are collected in memory and written at each batch's end;
//! when a write fails part-way (a full disk), the file is cut back to its last complete line and the
//! reporter stops writing (the error is returned once; the run goes on and says so at the end).
//!
//! Plain passes are kept in the compact form ([`Passed`]: consecutive passes of a backend whose cases
//! share their tags on one line, about 50 bytes a test, observed values left out) unless the
//! reporter is asked for full records (`--full-report`). A backend's open compact line is written
//! before any full record of that backend, so the reader's "last record wins" still sees records in
//! the order they were made (a crash re-emits a case's earlier passes as Crash).
//!
//! A run that finishes (not interrupted, every backend with a record of each of its tests) ends
//! the file with the closing record ([`Line::End`]); `merge` and `summarize` refuse a file
//! without it ([`crate::records::Results::unfinished`]).

use crate::events::{Event, Reporter};
use crate::records::{Line, Passed, RunMeta, TestResult};
use std::collections::BTreeMap;
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
    /// Every test as a full record (`--full-report`), none in the compact form.
    full: bool,
    /// Per backend, the compact line of passing tests being filled (at most one per backend).
    open: Vec<Passed>,
    /// Per backend started, its tests in the selection (what the closing record needs).
    started: BTreeMap<String, usize>,
}

impl JsonlReporter<File> {
    /// Starts `path` afresh with `meta` as its first line; `full`: every test as a full record.
    pub fn create(path: &Path, meta: &RunMeta, full: bool) -> std::io::Result<JsonlReporter> {
        let file = OpenOptions::new()
            .create(true)
            .write(true)
            .truncate(true)
            .open(path)?;
        drop(file);
        let mut r = JsonlReporter::over(OpenOptions::new().append(true).open(path)?, 0, full);
        r.push(&Line::Meta(meta.clone()))?;
        r.flush()?;
        Ok(r)
    }

    /// Appends to an existing file (`--resume`; cut any partial last line first).
    pub fn append(path: &Path, full: bool) -> std::io::Result<JsonlReporter> {
        let file = OpenOptions::new().append(true).open(path)?;
        let len = file.metadata()?.len();
        Ok(JsonlReporter::over(file, len, full))
    }
}

impl<S: Store> JsonlReporter<S> {
    /// A reporter appending to `store`, which already holds `len` bytes of whole lines.
    pub fn over(store: S, len: u64, full: bool) -> JsonlReporter<S> {
        JsonlReporter {
            store,
            pending: Vec::with_capacity(1 << 16),
            written: len,
            failed: false,
            full,
            open: vec![],
            started: BTreeMap::new(),
        }
    }

    /// Takes one test's final record: into its case's compact line when it passed plainly,
    /// otherwise as a full record after the backend's open compact line.
    fn result(&mut self, r: &TestResult) -> std::io::Result<()> {
        let at = self.open.iter().position(|p| p.backend == r.backend);
        if !self.full && Passed::admits(r) {
            match at {
                Some(i) if self.open[i].holds(r) => self.open[i].push(r),
                Some(i) => {
                    let done = std::mem::replace(&mut self.open[i], Passed::first(r));
                    self.push(&Line::Passed(done))?;
                }
                None => self.open.push(Passed::first(r)),
            }
            return Ok(());
        }
        if let Some(i) = at {
            let done = self.open.swap_remove(i);
            self.push(&Line::Passed(done))?;
        }
        self.push(&Line::Result(Box::new(r.clone())))
    }

    /// Records how many cases are not tests of `backend` and how many tests it has (a
    /// `not_applicable` line) and writes it.
    pub fn not_applicable(
        &mut self,
        backend: &str,
        cases: usize,
        tests: usize,
    ) -> std::io::Result<()> {
        self.started.insert(backend.to_string(), tests);
        self.push(&Line::NotApplicable {
            backend: backend.to_string(),
            cases,
            tests: Some(tests),
        })?;
        self.close_and_flush()
    }

    /// Writes the closing record ([`Line::End`]) when every backend started has a record of each
    /// of its tests among `results` (the run's final records); otherwise the file stays without
    /// one, the mark of a run that did not finish.
    pub fn end(&mut self, results: &[TestResult]) -> std::io::Result<()> {
        let mut have: BTreeMap<String, usize> =
            self.started.keys().map(|b| (b.clone(), 0)).collect();
        for r in results {
            *have.entry(r.backend.clone()).or_default() += 1;
        }
        let whole = self
            .started
            .iter()
            .all(|(b, n)| have.get(b).is_some_and(|h| h >= n));
        if whole {
            self.close_and_flush()?;
            self.push(&Line::End { tests: have })?;
        }
        self.close_and_flush()
    }

    /// Writes everything taken so far (for writers that send no end-of-run event, as `merge`).
    pub fn finish(&mut self) -> std::io::Result<()> {
        self.close_and_flush()
    }

    /// Writes the open compact lines, then the pending lines.
    fn close_and_flush(&mut self) -> std::io::Result<()> {
        for p in std::mem::take(&mut self.open) {
            self.push(&Line::Passed(p))?;
        }
        self.flush()
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
            } => self.result(result),
            Event::LoadError(e) => self.push(&Line::LoadError((*e).clone())),
            Event::BackendStarted {
                backend,
                not_applicable,
                tests,
            } => self.not_applicable(backend, *not_applicable, *tests),
            // An interrupted run has not finished: no flake re-run was made, `--resume` goes on.
            Event::RunFinished { results, .. } if !crate::interrupt::requested() => {
                self.end(results)
            }
            Event::BatchFinished { .. }
            | Event::BackendFinished { .. }
            | Event::RunFinished { .. } => self.close_and_flush(),
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
            false,
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

    /// A store that keeps everything.
    impl Store for Vec<u8> {
        fn append(&mut self, bytes: &[u8]) -> std::io::Result<()> {
            self.extend_from_slice(bytes);
            Ok(())
        }
        fn truncate(&mut self, len: u64) -> std::io::Result<()> {
            Vec::truncate(self, len as usize);
            Ok(())
        }
    }

    /// The closing record is written when every backend started has a record of each of its
    /// tests, and not when one lacks some (a run that stopped early).
    #[test]
    fn the_closing_record_is_written_only_when_every_test_has_a_record() {
        use crate::records::{Outcome, Results, Status};
        let pass = |t: &str| TestResult::sample(t, Status::Plain(Outcome::Pass));
        let (x, y) = (pass("x@core"), pass("y@core"));
        for (results, whole) in [(vec![x.clone(), y.clone()], true), (vec![x.clone()], false)] {
            let mut r = JsonlReporter::over(Vec::new(), 0, false);
            r.push(&Line::Meta(RunMeta {
                backends: vec!["b".into()],
                ..RunMeta::new()
            }))
            .unwrap();
            r.not_applicable("b", 0, 2).unwrap();
            for t in &results {
                r.result(t).unwrap();
            }
            r.end(&results).unwrap();
            let text = String::from_utf8(r.store.clone()).unwrap();
            assert_eq!(
                text.contains(r#"{"kind":"end","tests":{"b":2}}"#),
                whole,
                "{text}"
            );
            let read = Results::parse("r", &text).unwrap();
            assert_eq!(read.unfinished().is_none(), whole, "{text}");
        }
    }
}
