//! results.csv (`test,status,duration,backend`, deqp-runner's columns plus the backend) and
//! failures.csv (`test,Status`, a valid `--baseline`).
//!
//! Test names need no quoting: case ids hold no comma, quote or whitespace (the fixture loader
//! rejects them, see `shadowcheck_model::validate::id_char_ok`). A field with such a character
//! (a backend name) is still quoted as RFC 4180 says (`"..."`, inner quotes doubled); the baseline
//! reader takes the status after the last comma, so it reads both quoted and unquoted names.

use crate::events::{Event, Reporter};
use crate::records::{Status, TestResult};
use std::collections::BTreeSet;
use std::io::Write;
use std::path::{Path, PathBuf};

pub struct CsvReporter {
    dir: PathBuf,
}

impl CsvReporter {
    pub fn new(dir: &Path) -> CsvReporter {
        CsvReporter {
            dir: dir.to_path_buf(),
        }
    }
}

/// The status a test fails with now, as a baseline writes it: the raw outcome of Fail, Crash or
/// Timeout, also when the baseline already excused it. Flakes belong in the flakes list instead.
pub fn failing_status(r: &TestResult) -> Option<Status> {
    match r.status {
        Status::Flake | Status::KnownFlake => None,
        _ if r.outcome.is_failure() => Some(Status::Plain(r.outcome)),
        _ => None,
    }
}

/// failures.csv content. A test failing on several backends is listed once (first backend in
/// report order), since a baseline lists each test once.
/// A CSV field, quoted when it holds a comma, a quote or a line break.
pub fn field(s: &str) -> std::borrow::Cow<'_, str> {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\"")).into()
    } else {
        s.into()
    }
}

pub fn failures_csv(results: &[TestResult]) -> String {
    let mut seen = BTreeSet::new();
    let mut s = String::new();
    for r in results {
        if let Some(st) = failing_status(r) {
            if seen.insert(r.test.as_str()) {
                s.push_str(&format!("{},{}\n", field(&r.test), st));
            }
        }
    }
    s
}

pub fn results_csv(results: &[TestResult]) -> String {
    let mut s = String::with_capacity(results.len() * 80);
    for r in results {
        s.push_str(&format!(
            "{},{},{:.6},{}\n",
            field(&r.test),
            r.status,
            r.duration,
            field(&r.backend)
        ));
    }
    s
}

impl Reporter for CsvReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        if let Event::RunFinished { results, .. } = ev {
            std::fs::File::create(self.dir.join("results.csv"))?
                .write_all(results_csv(results).as_bytes())?;
            std::fs::File::create(self.dir.join("failures.csv"))?
                .write_all(failures_csv(results).as_bytes())?;
        }
        Ok(())
    }
}
