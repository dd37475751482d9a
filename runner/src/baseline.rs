//! Baselines, skips and flakes lists, in deqp-runner's formats.
//!
//! - Baseline: CSV lines `test,Status[,...]` (e.g. `gl46/2d/d16/...@core,Fail`; further fields are
//!   ignored, as deqp-runner does); `#` starts a comment, blank lines are ignored, a test listed
//!   twice is an error. `failures.csv` of a run is a valid baseline. A name may carry a backend
//!   prefix (`egl:llvmpipe:core/gl46/...@core`, as a multi-backend run's failures.csv writes it):
//!   it then applies to that backend only; a bare name applies to every backend.
//! - Skips and flakes: one regular expression per line (matched anywhere in the test name, anchor
//!   with `^...$` for exact names), `#` comments.

use crate::records::{qualified_name, Outcome, Status, TestResult};
use regex::RegexSet;
use std::collections::HashMap;
use std::path::Path;

#[derive(Debug, thiserror::Error)]
pub enum ListError {
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

fn read(path: &Path) -> Result<String, ListError> {
    std::fs::read_to_string(path).map_err(|source| ListError::Io {
        file: path.display().to_string(),
        source,
    })
}

/// Expected statuses of known failures.
#[derive(Debug, Default, Clone)]
pub struct Baseline {
    entries: HashMap<String, Status>,
}

impl Baseline {
    pub fn load(path: &Path) -> Result<Baseline, ListError> {
        Baseline::parse(&read(path)?, &path.display().to_string())
    }

    pub fn parse(text: &str, file: &str) -> Result<Baseline, ListError> {
        let mut entries = HashMap::new();
        for (i, raw) in text.lines().enumerate() {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let bad = |msg: String| ListError::Bad {
                file: file.to_string(),
                line: i + 1,
                msg,
            };
            // As deqp-runner reads it: the name, then the status; further fields (results.csv's
            // duration and backend) are ignored. A quoted name (RFC 4180) is unquoted.
            let (test, rest) =
                split_name(line).ok_or_else(|| bad("expected `test,Status`".into()))?;
            let status = rest.split(',').next().unwrap_or_default();
            let status: Status = status.trim().parse().map_err(bad)?;
            let status = match status {
                Status::Plain(o) => Status::Plain(o),
                // deqp-runner writes the raw status; accept a final status only where it is one.
                s => {
                    return Err(bad(format!(
                    "`{s}` is not a status a baseline can expect (use Fail, Crash, Timeout, ...)"
                )))
                }
            };
            if entries.insert(test.clone(), status).is_some() {
                return Err(bad(format!("`{test}` is listed twice")));
            }
        }
        Ok(Baseline { entries })
    }

    pub fn get(&self, test: &str) -> Option<Status> {
        self.entries.get(test).copied()
    }

    /// The entry for `test` on `backend`: `<backend>/<test>` (a multi-backend run's failures.csv,
    /// [`qualified_name`]) before the bare `<test>` (a single-backend run's, which applies to
    /// every backend of the run).
    pub fn get_for(&self, backend: &str, test: &str) -> Option<Status> {
        self.get(&qualified_name(backend, test))
            .or_else(|| self.get(test))
    }

    /// Entries that excuse nothing, one line each (for stderr and report.md), at most `max` lines
    /// per kind plus a count of the rest: entries whose status is not a failure (a baseline lists
    /// Fail, Crash or Timeout; `Pass`, `Warn`, `Skip` there have no effect) and entries that name
    /// no test of `results` (bare, or `<backend>/` prefixed with a backend of the run).
    pub fn notes(&self, results: &[TestResult], max: usize) -> Vec<String> {
        let mut names = std::collections::HashSet::new();
        for r in results {
            names.insert(r.test.clone());
            names.insert(qualified_name(&r.backend, &r.test));
        }
        let mut not_failures = vec![];
        let mut unmatched = vec![];
        for (name, st) in self.entries() {
            if !matches!(st, Status::Plain(o) if o.is_failure()) {
                not_failures.push(format!(
                    "baseline entry `{name},{st}` has no effect: a baseline lists failures (Fail, Crash, Timeout)"
                ));
            }
            if !names.contains(name) {
                unmatched.push(format!(
                    "baseline entry `{name}` matches no test of this run"
                ));
            }
        }
        let mut out = vec![];
        for list in [not_failures, unmatched] {
            let n = list.len();
            out.extend(list.into_iter().take(max));
            if n > max {
                out.push(format!("... and {} more like it", n - max));
            }
        }
        out
    }

    /// Every entry, sorted by name.
    pub fn entries(&self) -> Vec<(&str, Status)> {
        let mut v: Vec<(&str, Status)> =
            self.entries.iter().map(|(k, s)| (k.as_str(), *s)).collect();
        v.sort_by(|a, b| a.0.cmp(b.0));
        v
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}

/// The first CSV field of `line` (unquoted when quoted) and the rest after its comma.
fn split_name(line: &str) -> Option<(String, &str)> {
    if let Some(q) = line.strip_prefix('"') {
        // The closing quote is the first `"` not doubled.
        let mut i = 0;
        let b = q.as_bytes();
        while i < b.len() {
            if b[i] == b'"' {
                if b.get(i + 1) == Some(&b'"') {
                    i += 2;
                    continue;
                }
                let rest = q[i + 1..].strip_prefix(',')?;
                return Some((q[..i].replace("\"\"", "\""), rest));
            }
            i += 1;
        }
        return None;
    }
    let (name, rest) = line.split_once(',')?;
    Some((name.trim().to_string(), rest))
}

/// A list of regular expressions (skips, flakes).
#[derive(Debug, Clone)]
pub struct RegexList {
    set: RegexSet,
    regexes: Vec<regex::Regex>,
    patterns: Vec<String>,
}

impl Default for RegexList {
    fn default() -> Self {
        RegexList {
            set: RegexSet::empty(),
            regexes: vec![],
            patterns: vec![],
        }
    }
}

impl RegexList {
    pub fn load(path: &Path) -> Result<RegexList, ListError> {
        RegexList::parse(&read(path)?, &path.display().to_string())
    }

    pub fn parse(text: &str, file: &str) -> Result<RegexList, ListError> {
        let mut patterns = vec![];
        let mut regexes = vec![];
        for (i, raw) in text.lines().enumerate() {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            regexes.push(regex::Regex::new(line).map_err(|e| ListError::Bad {
                file: file.to_string(),
                line: i + 1,
                msg: e.to_string(),
            })?);
            patterns.push(line.to_string());
        }
        let set = RegexSet::new(&patterns).map_err(|e| ListError::Bad {
            file: file.to_string(),
            line: 0,
            msg: e.to_string(),
        })?;
        Ok(RegexList {
            set,
            regexes,
            patterns,
        })
    }

    /// The first pattern matching `test`.
    pub fn matching(&self, test: &str) -> Option<&str> {
        self.set
            .matches(test)
            .iter()
            .next()
            .map(|i| self.patterns[i].as_str())
    }

    /// The first pattern matching `test` on `backend`: its bare name, or its name qualified by
    /// the backend (`<backend>/<test>`, as a multi-backend run's CSV files write it) with a match
    /// that starts in the backend part and reaches the `/` or crosses it, so `^egl:zink:core/` names one
    /// backend's tests while a pattern that only matches inside a backend's name (`n=0001` in
    /// `mock:fail=n=0001`) selects nothing.
    pub fn matching_for(&self, backend: &str, test: &str) -> Option<&str> {
        if let Some(p) = self.matching(test) {
            return Some(p);
        }
        let q = qualified_name(backend, test);
        let sep = q.len() - test.len() - 1;
        self.set
            .matches(&q)
            .iter()
            .find(|&i| {
                self.regexes[i]
                    .find_iter(&q)
                    .any(|m| m.start() < sep && m.end() >= sep)
            })
            .map(|i| self.patterns[i].as_str())
    }
}

/// Everything that turns an outcome into a final status.
#[derive(Debug, Default, Clone)]
pub struct Lists {
    pub baseline: Baseline,
    pub skips: RegexList,
    pub flakes: RegexList,
}

impl Lists {
    /// The final status of `outcome` for `test`, as deqp-runner decides it:
    /// a failure matching the flakes list is KnownFlake; a failure listed in the baseline with the
    /// same status is ExpectedFail (with another failure status it stays a regression); a test
    /// listed as failing that passes, warns or is skipped is UnexpectedImprovement.
    /// The baseline entry is looked up per backend ([`Baseline::get_for`]).
    pub fn status(&self, backend: &str, test: &str, outcome: Outcome) -> (Status, Option<String>) {
        let listed = self.baseline.get_for(backend, test);
        if outcome.is_failure() {
            if self.flakes.matching_for(backend, test).is_some() {
                return (Status::KnownFlake, None);
            }
            return match listed {
                Some(Status::Plain(o)) if o == outcome => (Status::ExpectedFail, None),
                Some(s) => (
                    Status::Plain(outcome),
                    Some(format!("baseline expects {s}")),
                ),
                None => (Status::Plain(outcome), None),
            };
        }
        match listed {
            Some(Status::Plain(o)) if o.is_failure() => (
                Status::UnexpectedImprovement(outcome),
                Some(format!("baseline expects {o}")),
            ),
            _ => (Status::Plain(outcome), None),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn baseline_reads_deqp_csv_and_rejects_duplicates() {
        let b = Baseline::parse("# known\n\na@core,Fail\nb@ff,Crash\n", "b.csv").unwrap();
        assert_eq!(b.get("a@core"), Some(Status::Plain(Outcome::Fail)));
        assert_eq!(b.get("b@ff"), Some(Status::Plain(Outcome::Crash)));
        assert_eq!(b.len(), 2);
        let e = Baseline::parse("a@core,Fail\na@core,Crash\n", "b.csv")
            .unwrap_err()
            .to_string();
        assert!(e.contains("b.csv:2") && e.contains("twice"), "{e}");
        assert!(Baseline::parse("a@core,Broken\n", "b.csv").is_err());
        assert!(Baseline::parse("just-a-name\n", "b.csv").is_err());
        // As deqp-runner: name and status, further fields ignored; a quoted name is unquoted.
        let b = Baseline::parse(
            "\"x/dt=0.25,0.75@core\",Fail\ny/dt=1_0@ff,Timeout,0.5,egl:llvmpipe:core\n",
            "b.csv",
        )
        .unwrap();
        assert_eq!(
            b.get("x/dt=0.25,0.75@core"),
            Some(Status::Plain(Outcome::Fail))
        );
        assert_eq!(b.get("y/dt=1_0@ff"), Some(Status::Plain(Outcome::Timeout)));
    }

    #[test]
    fn entries_that_excuse_nothing_are_noted() {
        let b = Baseline::parse(
            "t@core,Fail\nsoft/u@core,Crash\np@core,Pass\ngone@ff,Fail\n",
            "b",
        )
        .unwrap();
        let result = |backend: &str, test: &str| -> TestResult {
            serde_json::from_value(serde_json::json!({
                "backend": backend, "test": test, "case_id": "c", "api": "core",
                "status": "Pass", "outcome": "Pass", "duration": 0.0,
                "tags": {"spec": "gl46", "target": "2d", "format": "d16", "func": "lequal",
                         "filter": "nearest/nearest"}
            }))
            .unwrap()
        };
        let rs = [
            result("egl:llvmpipe:core", "t@core"),
            result("soft", "u@core"),
            result("soft", "p@core"),
        ];
        let notes = b.notes(&rs, 10);
        assert_eq!(
            notes,
            [
                "baseline entry `p@core,Pass` has no effect: a baseline lists failures (Fail, Crash, Timeout)",
                "baseline entry `gone@ff` matches no test of this run",
            ],
            "{notes:?}"
        );
        assert_eq!(
            b.notes(&[], 1).last().map(String::as_str),
            Some("... and 3 more like it")
        );
    }

    #[test]
    fn a_qualified_entry_applies_to_its_backend_only() {
        let b = Baseline::parse("egl:llvmpipe:core/t@core,Fail\nu@core,Crash\n", "b").unwrap();
        let fail = Some(Status::Plain(Outcome::Fail));
        assert_eq!(b.get_for("egl:llvmpipe:core", "t@core"), fail);
        assert_eq!(b.get_for("egl:zink:core", "t@core"), None);
        let crash = Some(Status::Plain(Outcome::Crash));
        assert_eq!(b.get_for("egl:zink:core", "u@core"), crash);
        assert_eq!(b.get_for("soft", "u@core"), crash);
        // Backend names with characters a test name may not hold are written with `_`.
        assert_eq!(
            qualified_name("exec:./impl --fast", "t@ff"),
            "exec:./impl_--fast/t@ff"
        );
    }

    #[test]
    fn lists_decide_like_deqp_runner() {
        let lists = Lists {
            baseline: Baseline::parse("f@core,Fail\nc@core,Crash\n", "b").unwrap(),
            skips: RegexList::default(),
            flakes: RegexList::parse("# flaky\n^flaky/\n", "f").unwrap(),
        };
        assert_eq!(
            lists.status("b", "f@core", Outcome::Fail).0,
            Status::ExpectedFail
        );
        assert_eq!(
            lists.status("b", "f@core", Outcome::Pass).0,
            Status::UnexpectedImprovement(Outcome::Pass)
        );
        assert_eq!(
            lists.status("b", "f@core", Outcome::Skip).0,
            Status::UnexpectedImprovement(Outcome::Skip)
        );
        assert_eq!(
            lists.status("b", "c@core", Outcome::Fail).0,
            Status::Plain(Outcome::Fail)
        );
        assert_eq!(
            lists.status("b", "new@core", Outcome::Timeout).0,
            Status::Plain(Outcome::Timeout)
        );
        assert_eq!(
            lists.status("b", "flaky/x@core", Outcome::Crash).0,
            Status::KnownFlake
        );
        assert_eq!(
            lists.status("b", "flaky/x@core", Outcome::Pass).0,
            Status::Plain(Outcome::Pass)
        );
    }

    #[test]
    fn regex_list_reports_bad_line() {
        let e = RegexList::parse("ok\n(unclosed\n", "s.txt")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("s.txt:2:"), "{e}");
        let l = RegexList::parse("lequal", "s").unwrap();
        assert_eq!(l.matching("gl46/2d/lequal@core"), Some("lequal"));
        assert_eq!(l.matching("gl46/2d/gequal@core"), None);
    }

    #[test]
    fn a_pattern_may_name_one_backend() {
        let l = RegexList::parse("^egl:zink:core/gl46/\n", "flakes.txt").unwrap();
        assert_eq!(
            l.matching_for("egl:zink:core", "gl46/2d/lequal@core"),
            Some("^egl:zink:core/gl46/")
        );
        assert_eq!(
            l.matching_for("egl:llvmpipe:core", "gl46/2d/lequal@core"),
            None
        );
        let l = RegexList::parse("^egl:zink:core\n", "flakes.txt").unwrap();
        assert!(l
            .matching_for("egl:zink:core", "gl46/2d/lequal@core")
            .is_some());
        // Only inside the backend's name: not a match.
        let l = RegexList::parse("n=0001", "flakes.txt").unwrap();
        assert_eq!(l.matching_for("mock:fail=n=0001,x", "n=0000@core"), None);
        // A bare pattern applies to every backend.
        let l = RegexList::parse("^gl46/", "skips.txt").unwrap();
        assert!(l
            .matching_for("egl:llvmpipe:core", "gl46/2d/lequal@core")
            .is_some());
        let lists = Lists {
            flakes: RegexList::parse("^b1/f", "flakes.txt").unwrap(),
            ..Lists::default()
        };
        assert_eq!(
            lists.status("b1", "f@core", Outcome::Fail).0,
            Status::KnownFlake
        );
        assert_eq!(
            lists.status("b2", "f@core", Outcome::Fail).0,
            Status::Plain(Outcome::Fail)
        );
    }
}
