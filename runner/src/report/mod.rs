//! Reporters: subscribers to the runner's [`Event`](crate::events::Event) stream.
//!
//! Files written under the output directory:
//! - `results.jsonl`: one JSON record per line, appended and flushed as each test finishes
//!   ([`jsonl`]); what `--resume` and `merge` read back;
//! - `results.csv`: `test,status,duration,backend` (deqp-runner's columns plus the backend);
//! - `failures.csv`: `test,Status` of every failing test, usable as the next `--baseline`;
//! - `junit.xml`: one test suite per backend (quick-junit);
//! - `report.json`: summary and every result, with `schema_version`;
//! - `report.md`: summary tables and failure dumps.
//!
//! The terminal reporter shows progress on stderr and the summary on stdout.

pub mod atomic;
pub mod csv;
pub mod headline;
pub mod html;
pub mod json;
pub mod jsonl;
pub mod junit;
pub mod markdown;
pub mod terminal;

use crate::events::Reporter;
use crate::records::{Outcome, Status, TestResult};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// A number as short as it reads (no trailing zeros), non-finite as nan/inf.
pub fn num(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else {
        format!("{v}")
    }
}

/// Tests whose outcome deserves a dump: anything that did not plainly pass or skip.
pub fn wants_dump(r: &TestResult) -> bool {
    matches!(
        r.outcome,
        Outcome::Fail | Outcome::Warn | Outcome::Crash | Outcome::Timeout
    ) || r.status.is_improvement()
}

/// The failure dump of one test: id, expected (spec value and acceptance per profile), observed
/// (four channels), the footprint (texels, stored depth, per-texel compare, weights) and the
/// command that re-runs the case alone. `indent` prefixes every line.
pub fn dump(r: &TestResult, indent: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{indent}{}  {}  [{}]", r.status, r.test, r.backend);
    if let Some(reason) = &r.reason {
        let _ = writeln!(s, "{indent}  reason:    {reason}");
    }
    if let Some(e) = &r.expected {
        let sv = e.spec_value.map(num).unwrap_or_else(|| "none".into());
        let _ = writeln!(
            s,
            "{indent}  expected:  spec value {sv}; strict {}; quality {}; layout ({}); verdict by {}",
            e.strict, e.quality, e.layout, e.profile
        );
        if !e.citations.is_empty() {
            let _ = writeln!(s, "{indent}  cites:     {}", e.citations.join("; "));
        }
    }
    if let Some(o) = &r.observed {
        let ch: Vec<String> = o.0.iter().map(|v| num(*v)).collect();
        let _ = writeln!(s, "{indent}  observed:  rgba ({})", ch.join(", "));
    }
    if let Some(f) = &r.footprint {
        let _ = writeln!(
            s,
            "{indent}  footprint: Dref {} ({} texels)",
            num(f.dref),
            f.texels.len()
        );
        let _ = writeln!(s, "{indent}    level texel x,y,layer  stored         Dt                   compare  weight");
        for t in &f.texels {
            let xyz = t
                .xyz
                .map(|[x, y, z]| format!("{x},{y},{z}"))
                .unwrap_or_else(|| "border".into());
            let pass = match t.pass {
                Some(true) => "pass",
                Some(false) => "fail",
                None => "either",
            };
            let _ = writeln!(
                s,
                "{indent}    {:<5} {:<16} {:<14} {:<20} {:<8} {}",
                t.level,
                xyz,
                num(t.stored),
                num(t.dt),
                pass,
                num(t.weight)
            );
        }
    }
    let _ = writeln!(s, "{indent}  re-run:    {}", r.rerun_command());
    s
}

/// Per-value counts for one grid dimension.
#[derive(Debug, Default, Clone)]
pub struct Row {
    pub tests: usize,
    pub pass: usize,
    pub warn: usize,
    pub fail: usize,
    pub skip: usize,
    pub other: usize,
}

/// Counts by spec, compare func, filter and format (the dimensions of the summary tables).
pub fn breakdown(results: &[TestResult]) -> Vec<(&'static str, BTreeMap<String, Row>)> {
    type Key = fn(&TestResult) -> &str;
    let dims: [(&'static str, Key); 4] = [
        ("spec", |r| &r.tags.spec),
        ("func", |r| &r.tags.func),
        ("filter", |r| &r.tags.filter),
        ("format", |r| &r.tags.format),
    ];
    dims.iter()
        .map(|(name, key)| {
            let mut m: BTreeMap<String, Row> = BTreeMap::new();
            for r in results {
                let row = m.entry(key(r).to_string()).or_default();
                row.tests += 1;
                match r.status.column() {
                    "Pass" => row.pass += 1,
                    "Warn" => row.warn += 1,
                    "Fail" | "Crash" | "Timeout" => row.fail += 1,
                    "Skip" => row.skip += 1,
                    _ => row.other += 1,
                }
            }
            (*name, m)
        })
        .collect()
}

/// The files written when a run ends (removed when a run starts, so a killed run leaves none stale).
pub const FINAL_FILES: [&str; 5] = [
    "results.csv",
    "failures.csv",
    "junit.xml",
    "report.json",
    "report.md",
];

/// Which file reporters to attach.
#[derive(Debug, Clone)]
pub struct FileReports {
    pub csv: bool,
    pub junit: bool,
    pub json: bool,
    pub markdown: bool,
    /// Passing tests in report.json and junit.xml too (`--full-report`); by default those files
    /// hold only what did not pass ([`in_detail`]).
    pub full: bool,
    /// The run's baseline: report.md lists its entries that excuse nothing.
    pub baseline: Option<crate::baseline::Baseline>,
    /// The run's loaded cases: report.md's layer attribution (a layered backend and the Vulkan
    /// driver under it in the same run, `crate::attribute`) reads them; `None`: no attribution.
    pub cases: Option<std::sync::Arc<crate::run::CaseSet>>,
}

/// Whether `r` goes into report.json and junit.xml: everything with `full`, otherwise every test
/// that did not pass (deqp-runner's habit: results.csv for everything, details for what failed).
/// Pass results are counted in the summary and listed in results.csv and results.jsonl.
pub fn in_detail(r: &TestResult, full: bool) -> bool {
    full || r.status != Status::Plain(Outcome::Pass)
}

impl Default for FileReports {
    fn default() -> Self {
        FileReports {
            csv: true,
            junit: true,
            json: true,
            markdown: true,
            full: false,
            baseline: None,
            cases: None,
        }
    }
}

/// The end-of-run file reporters for `dir` (results.jsonl is attached separately, since `merge`
/// does not rewrite it the same way).
pub fn file_reporters(dir: &Path, which: &FileReports) -> Vec<Box<dyn Reporter>> {
    let mut v: Vec<Box<dyn Reporter>> = vec![];
    if which.csv {
        v.push(Box::new(csv::CsvReporter::new(dir)));
    }
    if which.junit {
        v.push(Box::new(junit::JunitReporter::new(dir, which.full)));
    }
    if which.json {
        v.push(Box::new(json::JsonReporter::new(dir, which.full)));
    }
    if which.markdown {
        v.push(Box::new(markdown::MarkdownReporter::new(
            dir,
            which.baseline.clone(),
            which.cases.clone(),
        )));
    }
    v
}
