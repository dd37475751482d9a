//! `shadowcheck consensus`: the oracle's review queue. Across the results of several runs, the
//! tests where at least [`Options::min_units`] independent texture units return the same answer
//! and the oracle rejects it (outcome Fail: outside every profile's acceptance set).
//!
//! Why: an implementation that fails alone is most likely wrong; several implementations that
//! share no sampling code and agree on one answer against the oracle make the oracle the first
//! suspect (a misread sentence, a missed reading, a precision tier too tight). Each entry carries
//! the sentences the oracle used (the expectation's citations), so the reader starts from them.
//!
//! The rules:
//! - backends that share texture-unit code count once: [`LINEAGE`] maps a backend to its *unit*;
//! - two answers agree when every compared channel differs by at most [`TOLERANCE`] (2^-16, the
//!   `quality` profile's reference precision; NaN agrees with NaN, an infinity with itself).
//!   Channels the expectation's layout marks unused (`-`) are not compared; when the records give
//!   no layout all four are. Closeness is not transitive: a group is every answer within 2^-16 of
//!   one returned answer (the one with the widest support), so two members may differ by 2^-15;
//! - a unit supports an answer when any of its backends returned it, so a unit counts once however
//!   many backends it has;
//! - a test is listed when some answer is supported by at least `min_units` units and at least one
//!   of the backends returning it has outcome Fail.
//!
//! Only results that carry an observed value can be compared: Fail and Warn (and passes of a run
//! with `--full-report`). Plain passes are stored compactly (`passed` lines) without their values,
//! so a unit whose backends passed a test supports no rejected answer, which is the right count: it
//! agrees with the oracle.
//!
//! Results are read with [`records::read_results`](crate::records::read_results), the one reader
//! of results.jsonl; the record of a (backend, test) in a later run directory replaces an earlier
//! one (as `report` does).

use crate::records::{self, ExpectedSummary, Outcome, ReadError, Results, TestResult};
use serde::Serialize;
use shadowcheck_protocol::Rgba;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::{Path, PathBuf};

mod lineage;
mod markdown;

pub use lineage::{front_end_of, lineage_of, unit_of, Lineage, LINEAGE};
pub use markdown::markdown;

/// Two channels agree when they differ by at most this: 2^-16, the reference precision of the
/// `quality` profile (oracle/src/profile.rs), the loosest tolerance the oracle itself grants one
/// value. Two answers closer than this cannot be told apart by any verdict.
pub const TOLERANCE: f64 = 1.0 / 65536.0;

/// The default of `--min-units`.
pub const DEFAULT_MIN_UNITS: usize = 3;

/// What to look for.
#[derive(Debug, Clone)]
pub struct Options {
    /// Distinct units that must support a rejected answer.
    pub min_units: usize,
    /// Where to find a case whose records carry no citations and name no fixture file.
    pub default_fixtures: PathBuf,
}

/// One run directory's results.
#[derive(Debug)]
pub struct Run {
    /// The directory (or results.jsonl) as given.
    pub path: String,
    pub results: Results,
}

/// Reads `path`/results.jsonl (or `path` itself when it is a file).
pub fn read_run(path: &Path) -> Result<Run, ReadError> {
    let file = if path.is_file() {
        path.to_path_buf()
    } else {
        path.join(records::RESULTS_FILE)
    };
    Ok(Run {
        path: path.display().to_string(),
        results: records::read_results(&file)?,
    })
}

/// One backend's answer to a listed test.
#[derive(Debug, Clone, Serialize)]
pub struct BackendAnswer {
    pub backend: String,
    pub observed: Rgba,
    pub outcome: Outcome,
}

/// One unit supporting the answer, with the backends that returned it.
#[derive(Debug, Clone, Serialize)]
pub struct UnitSupport {
    pub unit: String,
    pub backends: Vec<BackendAnswer>,
}

/// Where an entry's citations came from.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CitationSource {
    /// The failing record's expected summary.
    Record,
    /// The case in this fixture file or directory.
    Fixtures(String),
    /// Neither: why not.
    Missing(String),
}

/// A test on the queue.
#[derive(Debug, Clone, Serialize)]
pub struct Entry {
    /// `<case id>@<api>`.
    pub test: String,
    pub case_id: String,
    /// The agreeing answer (the one the most units support, as one of them returned it).
    pub answer: Rgba,
    /// The channels compared (`rgba`, or those the layout does not mark unused).
    pub compared: String,
    pub units: Vec<UnitSupport>,
    /// The API front ends of the backends that returned the answer. One front end for several
    /// units (Mesa's, under llvmpipe, softpipe and zink on SwiftShader) means the units are
    /// independent in their sampling only: completeness, state validation, DEPTH_TEXTURE_MODE
    /// routing and fixed function are one piece of code, so a shared defect there is the first
    /// suspect, before the oracle.
    pub front_ends: Vec<String>,
    /// What the oracle expected, as the failing record holds it.
    pub expected: Option<ExpectedSummary>,
    /// The sentences the oracle used.
    pub citations: Vec<String>,
    pub citations_from: CitationSource,
    /// The fixture file the failing record names, if any.
    #[serde(skip)]
    fixtures: Option<String>,
}

/// Tests with the same citations in the same grid family: presumably one cause.
#[derive(Debug, Clone, Serialize)]
pub struct Class {
    /// The case id with its parameter parts (`key=value`, bare numbers) replaced by `*`.
    pub family: String,
    pub citations: Vec<String>,
    pub tests: Vec<Entry>,
}

/// The review queue.
#[derive(Debug, Clone, Serialize)]
pub struct Queue {
    pub runs: Vec<String>,
    pub min_units: usize,
    pub tolerance: f64,
    /// Every backend of the inputs and its unit.
    pub backends: BTreeMap<String, String>,
    /// Tests with at least one comparable answer (an observed value: Fail, Warn, or a pass under
    /// `--full-report`).
    pub tests_compared: usize,
    /// Largest class first.
    pub classes: Vec<Class>,
}

impl Queue {
    pub fn len(&self) -> usize {
        self.classes.iter().map(|c| c.tests.len()).sum()
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Builds the queue from `runs`, loading fixtures only for entries whose records lack citations.
pub fn queue(runs: &[Run], opts: &Options) -> Queue {
    let mut all = Results::default();
    for run in runs {
        for r in &run.results.results {
            all.insert(r.clone());
        }
    }
    let backends: BTreeMap<String, String> = all
        .results
        .iter()
        .map(|r| (r.backend.clone(), unit_of(&r.backend)))
        .collect();
    let mut by_test: BTreeMap<&str, Vec<&TestResult>> = BTreeMap::new();
    for r in &all.results {
        let comparable = matches!(r.outcome, Outcome::Pass | Outcome::Warn | Outcome::Fail);
        if comparable && r.observed.is_some() {
            by_test.entry(&r.test).or_default().push(r);
        }
    }
    let tests_compared = by_test.len();
    let mut entries = vec![];
    for (_, mut rs) in by_test {
        rs.sort_by(|a, b| a.backend.cmp(&b.backend));
        entries.extend(entries_of(&rs, opts.min_units.max(1)));
    }
    fill_citations(&mut entries, &opts.default_fixtures);
    Queue {
        runs: runs.iter().map(|r| r.path.clone()).collect(),
        min_units: opts.min_units,
        tolerance: TOLERANCE,
        backends,
        tests_compared,
        classes: classes(entries),
    }
}

/// The channels to compare, from the layout of the first record that has one (`-`: unused).
fn mask_of(rs: &[&TestResult]) -> [bool; 4] {
    let layout = rs
        .iter()
        .find_map(|r| r.expected.as_ref().map(|e| &e.layout));
    let Some(layout) = layout else {
        return [true; 4];
    };
    let parts: Vec<&str> = layout.split(',').collect();
    if parts.len() != 4 {
        return [true; 4];
    }
    let mut m = [true; 4];
    for (m, p) in m.iter_mut().zip(&parts) {
        *m = p.trim() != "-";
    }
    m
}

/// Whether two answers agree on the channels of `mask`.
pub fn agree(a: &Rgba, b: &Rgba, mask: [bool; 4]) -> bool {
    a.0.iter()
        .zip(&b.0)
        .zip(mask)
        .all(|((x, y), m)| !m || x == y || (x.is_nan() && y.is_nan()) || (x - y).abs() <= TOLERANCE)
}

/// The entries of one test (its comparable records, sorted by backend). Clusters are taken
/// greedily, most units first: the answer of the record with the widest support, then the rest
/// among the records not yet taken, until no answer has `min_units` units.
fn entries_of(rs: &[&TestResult], min_units: usize) -> Vec<Entry> {
    let units: Vec<String> = rs.iter().map(|r| unit_of(&r.backend)).collect();
    if units.iter().collect::<BTreeSet<_>>().len() < min_units {
        return vec![];
    }
    let mask = mask_of(rs);
    let obs = |i: usize| rs[i].observed.unwrap_or(Rgba([f64::NAN; 4]));
    let mut left: Vec<usize> = (0..rs.len()).collect();
    let mut out = vec![];
    loop {
        // (units, records, anchor) of the widest-supported answer among the records left.
        let best = left
            .iter()
            .map(|&a| {
                let members: Vec<usize> = left
                    .iter()
                    .copied()
                    .filter(|&j| agree(&obs(a), &obs(j), mask))
                    .collect();
                let n = members
                    .iter()
                    .map(|&j| &units[j])
                    .collect::<BTreeSet<_>>()
                    .len();
                (n, a, members)
            })
            // Among equals the earliest anchor wins (max_by keeps the last maximum, hence the
            // reversed comparison of positions), so the result does not depend on ties.
            .max_by(|x, y| x.0.cmp(&y.0).then(y.1.cmp(&x.1)));
        let Some((n, anchor, members)) = best else {
            break;
        };
        if n < min_units {
            break;
        }
        left.retain(|j| !members.contains(j));
        let failing = members
            .iter()
            .copied()
            .find(|&j| rs[j].outcome == Outcome::Fail);
        let Some(failing) = failing else {
            continue; // the oracle accepts this answer: agreement, not a queue entry
        };
        let mut support: BTreeMap<&str, Vec<BackendAnswer>> = BTreeMap::new();
        for &j in &members {
            support.entry(&units[j]).or_default().push(BackendAnswer {
                backend: rs[j].backend.clone(),
                observed: obs(j),
                outcome: rs[j].outcome,
            });
        }
        let f = rs[failing];
        let expected = f.expected.clone();
        let citations = expected
            .as_ref()
            .map(|e| e.citations.clone())
            .unwrap_or_default();
        out.push(Entry {
            test: f.test.clone(),
            case_id: f.case_id.clone(),
            answer: obs(anchor),
            compared: ['r', 'g', 'b', 'a']
                .iter()
                .zip(mask)
                .filter(|(_, m)| *m)
                .map(|(c, _)| *c)
                .collect(),
            front_ends: members
                .iter()
                .map(|&j| front_end_of(&rs[j].backend))
                .collect::<BTreeSet<_>>()
                .into_iter()
                .collect(),
            units: support
                .into_iter()
                .map(|(unit, backends)| UnitSupport {
                    unit: unit.to_string(),
                    backends,
                })
                .collect(),
            citations_from: if citations.is_empty() {
                CitationSource::Missing("the record has none".into())
            } else {
                CitationSource::Record
            },
            citations,
            expected,
            fixtures: f.fixtures.clone(),
        });
    }
    out
}

/// Fills the citations of entries whose records carry none from the case in the fixtures the
/// record names, else in `default_fixtures`. Each fixture path is read once, only if needed.
fn fill_citations(entries: &mut [Entry], default_fixtures: &Path) {
    let mut wanted: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for e in entries.iter().filter(|e| e.citations.is_empty()) {
        let root = e
            .fixtures
            .clone()
            .unwrap_or_else(|| default_fixtures.display().to_string());
        wanted.entry(root).or_default().insert(e.case_id.clone());
    }
    let mut found: HashMap<(String, String), Vec<String>> = HashMap::new();
    let mut failed: HashMap<String, String> = HashMap::new();
    for (root, ids) in &wanted {
        let paths = match shadowcheck_cases::fixtures::fixture_paths(Path::new(root)) {
            Ok(p) => p,
            Err(e) => {
                failed.insert(root.clone(), e.to_string());
                continue;
            }
        };
        for p in paths {
            // A bad case elsewhere in the file does not hide the good ones.
            let Ok((file, _)) = shadowcheck_cases::fixtures::load_file_lenient(&p) else {
                continue;
            };
            for case in file.cases {
                if let (true, Some(x)) = (ids.contains(&case.id), &case.expect) {
                    found.insert((root.clone(), case.id.clone()), x.citations.clone());
                }
            }
        }
    }
    for e in entries.iter_mut().filter(|e| e.citations.is_empty()) {
        let root = e
            .fixtures
            .clone()
            .unwrap_or_else(|| default_fixtures.display().to_string());
        match found.get(&(root.clone(), e.case_id.clone())) {
            Some(c) if !c.is_empty() => {
                e.citations = c.clone();
                e.citations_from = CitationSource::Fixtures(root);
            }
            Some(_) => {
                e.citations_from =
                    CitationSource::Missing(format!("neither the record nor the case in {root}"))
            }
            None => {
                let why = failed
                    .get(&root)
                    .cloned()
                    .unwrap_or_else(|| format!("the case is not in {root}"));
                e.citations_from =
                    CitationSource::Missing(format!("none in the record, and {why}"));
            }
        }
    }
}

/// The grid family of a case id: its parameter parts (`key=value`, bare numbers such as a random
/// case's index) replaced by `*`, e.g. `gl46/2d/d24/linear/lequal/ref=*/dt=*`.
pub fn family(case_id: &str) -> String {
    case_id
        .split('/')
        .map(|seg| match seg.split_once('=') {
            Some((k, _)) => format!("{k}=*"),
            None if !seg.is_empty() && seg.chars().all(|c| c.is_ascii_digit()) => "*".into(),
            None => seg.to_string(),
        })
        .collect::<Vec<_>>()
        .join("/")
}

/// Entries grouped by (family, citations), largest class first, then by family.
fn classes(entries: Vec<Entry>) -> Vec<Class> {
    let mut map: BTreeMap<(String, Vec<String>), Vec<Entry>> = BTreeMap::new();
    for e in entries {
        map.entry((family(&e.case_id), e.citations.clone()))
            .or_default()
            .push(e);
    }
    let mut out: Vec<Class> = map
        .into_iter()
        .map(|((family, citations), tests)| Class {
            family,
            citations,
            tests,
        })
        .collect();
    // Stable: equal sizes keep the (family, citations) order.
    out.sort_by_key(|c| std::cmp::Reverse(c.tests.len()));
    out
}

#[cfg(test)]
mod tests;
