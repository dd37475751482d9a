//! Reading results.jsonl back: for `--resume` (skip what is done) and `shadowcheck merge`.
//!
//! A run killed mid-write may leave a truncated last line: it is ignored (and cut off before
//! appending, see [`truncate_partial_line`]). For each (backend, test) the last record wins (a
//! flake re-run appends the final record of a test after its first one). Load errors are
//! de-duplicated.

use crate::events::{Line, LoadError, RunMeta, TestResult};
use std::collections::{BTreeSet, HashMap};
use std::io::{BufRead, BufReader, Seek, SeekFrom};
use std::path::Path;

pub const RESULTS_FILE: &str = "results.jsonl";

#[derive(Debug, thiserror::Error)]
pub enum ResumeError {
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

/// What a results.jsonl holds.
#[derive(Debug, Default, Clone)]
pub struct Prior {
    pub meta: Option<RunMeta>,
    /// Final record per (backend, test), in first-seen order.
    pub results: Vec<TestResult>,
    index: HashMap<(String, String), usize>,
    pub load_errors: BTreeSet<LoadError>,
}

impl Prior {
    pub fn get(&self, backend: &str, test: &str) -> Option<&TestResult> {
        self.index
            .get(&(backend.to_string(), test.to_string()))
            .map(|&i| &self.results[i])
    }

    pub fn insert(&mut self, r: TestResult) {
        let key = (r.backend.clone(), r.test.clone());
        match self.index.get(&key) {
            Some(&i) => self.results[i] = r,
            None => {
                self.index.insert(key, self.results.len());
                self.results.push(r);
            }
        }
    }

    /// Reads `path` (a results.jsonl). Lines that do not parse are an error, except a last line
    /// without its newline (a write cut short by a kill), which is dropped.
    pub fn read(path: &Path) -> Result<Prior, ResumeError> {
        let io = |source| ResumeError::Io {
            file: path.display().to_string(),
            source,
        };
        let text = std::fs::read_to_string(path).map_err(io)?;
        let mut prior = Prior::default();
        let complete = text.ends_with('\n');
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let parsed: Result<Line, _> = serde_json::from_str(line);
            match parsed {
                Ok(Line::Meta(m)) => prior.meta = Some(m),
                Ok(Line::LoadError(e)) => {
                    prior.load_errors.insert(e);
                }
                Ok(Line::Result(r)) => prior.insert(*r),
                Err(_) if i + 1 == lines.len() && !complete => {}
                Err(e) => {
                    return Err(ResumeError::Bad {
                        file: path.display().to_string(),
                        line: i + 1,
                        msg: e.to_string(),
                    })
                }
            }
        }
        Ok(prior)
    }
}

/// Cuts a results file after its last complete line, so appending continues on a fresh line.
pub fn truncate_partial_line(path: &Path) -> Result<(), ResumeError> {
    let io = |source| ResumeError::Io {
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
        let prior = Prior::read(&p).unwrap();
        assert_eq!(prior.meta, Some(RunMeta::new()));
        assert_eq!(prior.load_errors.len(), 1, "duplicates collapse");
        truncate_partial_line(&p).unwrap();
        assert_eq!(
            std::fs::read_to_string(&p).unwrap(),
            format!("{meta}\n{err}\n{err}\n")
        );
        // A bad line in the middle is an error naming the line.
        std::fs::write(&p, format!("{meta}\nnot json\n{err}\n")).unwrap();
        let e = Prior::read(&p).unwrap_err().to_string();
        assert!(e.starts_with(&format!("{}:2: ", p.display())), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
