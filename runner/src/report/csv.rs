//! results.csv (`test,status,duration,backend`, deqp-runner's columns plus the backend) and
//! failures.csv (`test,Status`, a valid `--baseline`). deqp-runner reads both (it takes the first
//! two fields and refuses a name listed twice): a file with several backends' results names each
//! test `<backend>/<test>` ([`csv_names`]).
//!
//! Test names need no quoting: case ids hold no comma, quote or whitespace (the fixture loader
//! rejects them, see `shadowcheck_model::validate::id_char_ok`), as deqp-runner's reader, which
//! splits on every comma, requires. A backend name with such a character is still quoted as RFC
//! 4180 says (`"..."`, inner quotes doubled); the baseline reader takes the status after the last
//! comma, so it reads both quoted and unquoted names.

use crate::events::{Event, Reporter};
use crate::records::{qualified_name, Status, TestResult};
use std::collections::BTreeSet;
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

/// A CSV field, quoted when it holds a comma, a quote or a line break.
pub fn field(s: &str) -> std::borrow::Cow<'_, str> {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\"")).into()
    } else {
        s.into()
    }
}

/// How the CSV files name the tests of `results`: the bare `<case id>@<api>` when they all come
/// from one backend, `<backend>/<case id>@<api>` ([`qualified_name`], deqp-runner's suite
/// `prefix`) when several backends share the file, so that every name appears once.
pub fn csv_names(results: &[TestResult]) -> impl Fn(&TestResult) -> String {
    let first = results.first().map(|r| r.backend.clone());
    let several = results.iter().any(|r| Some(&r.backend) != first.as_ref());
    move |r: &TestResult| {
        if several {
            qualified_name(&r.backend, &r.test)
        } else {
            r.test.clone()
        }
    }
}

/// failures.csv content: `test,Status`, one line per failing test per backend (names as
/// [`csv_names`]), a valid `--baseline` for shadowcheck and deqp-runner.
pub fn failures_csv(results: &[TestResult]) -> String {
    let name = csv_names(results);
    let mut seen = BTreeSet::new();
    let mut s = String::new();
    for r in results {
        if let Some(st) = failing_status(r) {
            let n = name(r);
            if seen.insert(n.clone()) {
                s.push_str(&format!("{},{}\n", field(&n), st));
            }
        }
    }
    s
}

/// results.csv content: `test,status,duration,backend` (deqp-runner's columns plus the backend),
/// names as [`csv_names`].
pub fn results_csv(results: &[TestResult]) -> String {
    let name = csv_names(results);
    let mut s = String::with_capacity(results.len() * 80);
    for r in results {
        s.push_str(&format!(
            "{},{},{:.6},{}\n",
            field(&name(r)),
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
            super::atomic::write(
                &self.dir.join("results.csv"),
                results_csv(results).as_bytes(),
            )?;
            super::atomic::write(
                &self.dir.join("failures.csv"),
                failures_csv(results).as_bytes(),
            )?;
        }
        Ok(())
    }
}
