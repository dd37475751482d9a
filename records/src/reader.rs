//! The one reader of `results.jsonl`, shared by `run --resume` (skip what is done), `merge`,
//! `report`, `summarize` and `consensus`.
//!
//! The rules:
//! - a run killed mid-write may leave a truncated last line (no newline at its end): it is dropped
//!   when read (and [`Results::truncated`] says so), and cut off before `--resume` appends
//!   ([`truncate_partial_line`]); any other line that does not parse is an error naming the file
//!   and line;
//! - a meta line of another `schema_version` than [`SCHEMA_VERSION`] is an error naming the file:
//!   its records may mean something else;
//! - a run that finished ends with a closing record ([`Line::End`], the tests per backend); what a
//!   file without it, or with fewer tests than it says, lacks is [`Results::unfinished`] (`merge`
//!   and `summarize` refuse such a file: its missing tests would vanish from the totals);
//! - a `passed` line (the compact form of passing tests) stands for one record per test it lists;
//! - for each (backend, test) the last record wins (a flake re-run appends the final record of a
//!   test after its first one), kept at the place of the first;
//! - load errors are de-duplicated;
//! - the last metadata line is the run's [`RunMeta`]; the last not-applicable count of a backend
//!   is its count;
//! - a record whose footprint does not read back (serde_json writes a non-finite footprint number
//!   as `null`) keeps everything else: only the footprint is dropped.
//!
//! Readers that combine several files ([`Results::insert`]) choose their own rule for a
//! (backend, test) seen in more than one: `merge` refuses a different record, `report` takes the
//! later one and counts it.

use super::{Line, LoadError, RunMeta, TestResult};
use shadowcheck_model::SCHEMA_VERSION;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::io::{BufRead, BufReader, Seek, SeekFrom};
use std::path::Path;

/// The name of the file in a `--out` directory.
pub const RESULTS_FILE: &str = "results.jsonl";

/// Why a results.jsonl could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("{file}: {source}")]
    Io {
        file: String,
        source: std::io::Error,
    },
    #[error("{file}:{line}: {msg}")]
    Bad {
        file: String,
        line: usize,
        msg: String,
    },
}

/// What a results.jsonl holds, after the rules above.
#[derive(Debug, Default, Clone)]
pub struct Results {
    /// The last metadata line, if any.
    pub meta: Option<RunMeta>,
    /// Final record per (backend, test), in first-seen order.
    pub results: Vec<TestResult>,
    index: HashMap<(String, String), usize>,
    pub load_errors: BTreeSet<LoadError>,
    /// Per backend, the cases that are not tests of it (the last count written for it).
    pub not_applicable: BTreeMap<String, usize>,
    /// Per backend, the tests it has in the run's selection (from its `not_applicable` line).
    pub tests: BTreeMap<String, usize>,
    /// The closing record's tests per backend, when the file ends with one.
    pub end: Option<BTreeMap<String, usize>>,
    /// The last line was cut off (no newline, not a whole record) and dropped.
    pub truncated: bool,
}

impl Results {
    pub fn get(&self, backend: &str, test: &str) -> Option<&TestResult> {
        self.index
            .get(&(backend.to_string(), test.to_string()))
            .map(|&i| &self.results[i])
    }

    /// Adds `r`, replacing the record of the same (backend, test) in place; returns the replaced
    /// record.
    pub fn insert(&mut self, r: TestResult) -> Option<TestResult> {
        let key = (r.backend.clone(), r.test.clone());
        match self.index.get(&key) {
            Some(&i) => Some(std::mem::replace(&mut self.results[i], r)),
            None => {
                self.index.insert(key, self.results.len());
                self.results.push(r);
                None
            }
        }
    }

    /// Why this is not the record of a finished run (each reason, with what is missing), or `None`
    /// when it is: the last line cut off, no closing record (killed, interrupted, or a write that
    /// failed), or fewer tests of a backend than the run has.
    pub fn unfinished(&self) -> Option<String> {
        let mut why = vec![];
        if self.truncated {
            why.push("its last line is cut off (the run was killed while writing it)".to_string());
        }
        let mut have: BTreeMap<&str, usize> = BTreeMap::new();
        for r in &self.results {
            *have.entry(r.backend.as_str()).or_default() += 1;
        }
        let backends = self
            .meta
            .as_ref()
            .map_or(&[][..], |m| m.backends.as_slice());
        let count = |b: &str| have.get(b).copied().unwrap_or(0);
        match &self.end {
            None => {
                why.push("no closing record (the run was killed or interrupted, or results.jsonl could not be written whole)".to_string());
                for b in backends {
                    match self.tests.get(b) {
                        Some(&n) => why.push(format!("`{b}`: {} of {n} tests written", count(b))),
                        None if count(b) == 0 => why.push(format!("`{b}`: never started")),
                        None => why.push(format!("`{b}`: {} tests written", count(b))),
                    }
                }
            }
            Some(end) => {
                for b in backends {
                    match end.get(b) {
                        Some(&n) if count(b) < n => {
                            why.push(format!("`{b}`: {} of {n} tests written", count(b)))
                        }
                        Some(_) => {}
                        None => why.push(format!("`{b}`: not in the closing record")),
                    }
                }
            }
        }
        (!why.is_empty()).then(|| why.join("; "))
    }

    /// Parses the text of a results.jsonl; `file` names it in errors.
    pub fn parse(file: &str, text: &str) -> Result<Results, ReadError> {
        let mut out = Results::default();
        let complete = text.ends_with('\n');
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let parsed = parse_line(line);
            // Records after a closing record: a resumed run that has not finished again.
            if !matches!(parsed, Ok(Line::End { .. }) | Err(_)) {
                out.end = None;
            }
            match parsed {
                Ok(Line::Meta(m)) if m.schema_version != SCHEMA_VERSION => {
                    return Err(ReadError::Bad {
                        file: file.to_string(),
                        line: i + 1,
                        msg: format!(
                            "schema_version {} is not one this shadowcheck reads (it reads {SCHEMA_VERSION}): written by another version of shadowcheck, or not by shadowcheck",
                            m.schema_version
                        ),
                    })
                }
                Ok(Line::Meta(m)) => out.meta = Some(m),
                Ok(Line::End { tests }) => out.end = Some(tests),
                Ok(Line::LoadError(e)) => {
                    out.load_errors.insert(e);
                }
                Ok(Line::Result(r)) => {
                    out.insert(*r);
                }
                Ok(Line::NotApplicable {
                    backend,
                    cases,
                    tests,
                }) => {
                    if let Some(t) = tests {
                        out.tests.insert(backend.clone(), t);
                    }
                    out.not_applicable.insert(backend, cases);
                }
                Ok(Line::Passed(p)) => match p.results() {
                    Ok(rs) => {
                        for r in rs {
                            out.insert(r);
                        }
                    }
                    Err(e) => {
                        return Err(ReadError::Bad {
                            file: file.to_string(),
                            line: i + 1,
                            msg: e.to_string(),
                        })
                    }
                },
                Err(_) if i + 1 == lines.len() && !complete => out.truncated = true,
                Err(e) => {
                    return Err(ReadError::Bad {
                        file: file.to_string(),
                        line: i + 1,
                        msg: e.to_string(),
                    })
                }
            }
        }
        Ok(out)
    }
}

/// Reads `path` (a results.jsonl).
pub fn read_results(path: &Path) -> Result<Results, ReadError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|source| ReadError::Io {
        file: file.clone(),
        source,
    })?;
    Results::parse(&file, &text)
}

/// One line of results.jsonl; a record whose footprint does not read back loses the footprint.
fn parse_line(line: &str) -> Result<Line, serde_json::Error> {
    serde_json::from_str(line).or_else(|e| {
        let mut v: serde_json::Value = serde_json::from_str(line)?;
        match v.as_object_mut().and_then(|o| o.remove("footprint")) {
            Some(_) => serde_json::from_value(v),
            None => Err(e),
        }
    })
}

/// Cuts a results file after its last complete line, so appending continues on a fresh line.
pub fn truncate_partial_line(path: &Path) -> Result<(), ReadError> {
    let io = |source| ReadError::Io {
        file: path.display().to_string(),
        source,
    };
    let f = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(path)
        .map_err(io)?;
    let mut keep = 0u64;
    let mut pos = 0u64;
    let mut r = BufReader::new(&f);
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let n = r.read_until(b'\n', &mut buf).map_err(io)?;
        if n == 0 {
            break;
        }
        pos += n as u64;
        if buf.ends_with(b"\n") {
            keep = pos;
        }
    }
    if keep < pos {
        f.set_len(keep).map_err(io)?;
        let mut f = f;
        f.seek(SeekFrom::End(0)).map_err(io)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Outcome;

    #[test]
    fn a_truncated_last_line_is_dropped_and_cut_before_appending() {
        let dir =
            std::env::temp_dir().join(format!("shadowcheck-resume-unit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(RESULTS_FILE);
        let meta = serde_json::to_string(&Line::Meta(RunMeta::new())).unwrap();
        let err = serde_json::to_string(&Line::LoadError(LoadError {
            file: "f".into(),
            case: None,
            message: "m".into(),
        }))
        .unwrap();
        std::fs::write(
            &p,
            format!("{meta}\n{err}\n{err}\n{{\"kind\":\"result\",\"back"),
        )
        .unwrap();
        let prior = read_results(&p).unwrap();
        assert_eq!(prior.meta, Some(RunMeta::new()));
        assert_eq!(prior.load_errors.len(), 1, "duplicates collapse");
        truncate_partial_line(&p).unwrap();
        assert_eq!(
            std::fs::read_to_string(&p).unwrap(),
            format!("{meta}\n{err}\n{err}\n")
        );
        // A bad line in the middle is an error naming the line.
        std::fs::write(&p, format!("{meta}\nnot json\n{err}\n")).unwrap();
        let e = read_results(&p).unwrap_err().to_string();
        assert!(e.starts_with(&format!("{}:2: ", p.display())), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_record_whose_footprint_does_not_read_back_keeps_the_rest() {
        let meta = r#"{"kind":"meta","schema_version":1,"backends":["b"],"fixtures":["f"]}"#;
        let rec = r#"{"kind":"result","backend":"b","test":"c@core","case_id":"c","api":"core","status":"Fail","outcome":"Fail","duration":0.0,"tags":{"spec":"gl46","target":"2d","format":"d24","func":"lequal","filter":"nearest/nearest"},"observed":[-1.0,0.0,0.0,1.0],"footprint":{"dref":null,"texels":[]}}"#;
        let later = rec.replace("\"Fail\"", "\"Pass\"");
        let text = format!("{meta}\n{rec}\n{later}\n{{\"kind\":\"res");
        let read = Results::parse("x.jsonl", &text).unwrap();
        let m = read.meta.unwrap();
        assert_eq!(
            (m.backends, m.fixtures),
            (vec!["b".to_string()], vec!["f".to_string()])
        );
        assert_eq!(
            read.results.len(),
            1,
            "the later record of the same test replaces the first"
        );
        assert_eq!(read.results[0].outcome, Outcome::Pass);
        assert!(read.results[0].footprint.is_none());
        assert!(Results::parse("x.jsonl", &format!("{meta}\nnot json\n{rec}\n")).is_err());
    }

    /// The closing record, the test counts and a cut-off last line say whether a run finished.
    #[test]
    fn a_run_without_its_closing_record_or_with_fewer_tests_is_unfinished() {
        let meta = serde_json::to_string(&Line::Meta(RunMeta {
            backends: vec!["b".into()],
            ..RunMeta::new()
        }))
        .unwrap();
        let na = r#"{"kind":"not_applicable","backend":"b","cases":0,"tests":2}"#;
        let rec = |t: &str| {
            serde_json::to_string(&Line::Result(Box::new(TestResult::sample(
                t,
                crate::Status::Plain(Outcome::Pass),
            ))))
            .unwrap()
        };
        let (x, y) = (rec("x@core"), rec("y@core"));
        let end = r#"{"kind":"end","tests":{"b":2}}"#;
        let read = |text: String| Results::parse("r.jsonl", &text).unwrap();

        let whole = read(format!("{meta}\n{na}\n{x}\n{y}\n{end}\n"));
        assert_eq!(whole.unfinished(), None);
        let killed = read(format!("{meta}\n{na}\n{x}\n"));
        let why = killed.unfinished().unwrap();
        assert!(
            why.contains("no closing record") && why.contains("`b`: 1 of 2 tests written"),
            "{why}"
        );
        let cut = read(format!("{meta}\n{na}\n{x}\n{y}\n{}", &end[..12]));
        let why = cut.unfinished().unwrap();
        assert!(why.contains("last line is cut off"), "{why}");
        let fewer = read(format!("{meta}\n{na}\n{y}\n{end}\n"));
        assert_eq!(fewer.unfinished().unwrap(), "`b`: 1 of 2 tests written");
        // A resumed run appending after an earlier closing record has not finished again.
        let resumed = read(format!("{meta}\n{na}\n{x}\n{y}\n{end}\n{na}\n{y}\n"));
        assert!(resumed.unfinished().is_some());
        let never = read(format!("{meta}\n"));
        assert!(never.unfinished().unwrap().contains("`b`: never started"));
    }

    #[test]
    fn an_unknown_schema_version_is_an_error_naming_the_file() {
        let meta = r#"{"kind":"meta","schema_version":99,"backends":["b"],"fixtures":["f"]}"#;
        let e = Results::parse("x.jsonl", &format!("{meta}\n"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("x.jsonl:1: schema_version 99 is not one"),
            "{e}"
        );
    }
}
