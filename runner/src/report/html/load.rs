//! Reading the RESULTS of `shadowcheck report`: `results.jsonl` files (the streaming record of a
//! run), `report.json` documents, or `shadowcheck run --out` directories holding either; several
//! inputs are merged into one [`ReportInput`].
//!
//! A results.jsonl is read by the shared reader ([`crate::records::reader`]: a truncated last line
//! dropped, the last record of a (backend, test) winning, a footprint that does not read back
//! dropped); the records are the runner's own serde types ([`TestResult`], [`LoadError`],
//! [`JsonReport`]); nothing is redefined here. For one (backend, test) seen in several inputs the
//! last input wins (the same rule `results.jsonl` itself uses for a flake re-run), and the number
//! of records replaced by a different one is kept so the page can say so.

use crate::records::{self, LoadError, TestResult, RESULTS_FILE};
use crate::report::json::JsonReport;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Why an input could not be read.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    #[error("{0}: no results.jsonl or report.json in this directory")]
    EmptyDir(String),
    #[error("{file}: {source}")]
    Io {
        file: String,
        source: std::io::Error,
    },
    #[error("{file}: neither a results.jsonl nor a report.json: {msg}")]
    Format { file: String, msg: String },
    #[error(transparent)]
    Jsonl(#[from] records::ReadError),
}

/// Everything the report is made from.
#[derive(Debug, Default, Clone)]
pub struct ReportInput {
    /// The files read, in order.
    pub sources: Vec<String>,
    /// Backends in order of first appearance (run metadata first, then results).
    pub backends: Vec<String>,
    /// One record per (backend, test), in first-seen order.
    pub results: Vec<TestResult>,
    pub load_errors: Vec<LoadError>,
    /// Fixture paths named by the runs' metadata (as the runs wrote them).
    pub fixtures: Vec<String>,
    /// Inputs that are not the record of a finished run, each with what it lacks
    /// ([`records::Results::unfinished`]): the page shows what they hold and says so.
    pub unfinished: Vec<String>,
    /// Per backend, what its implementation called itself (the runs' metadata).
    pub implementations: BTreeMap<String, String>,
    /// Records that a later input replaced with a different result.
    pub replaced: usize,
}

impl ReportInput {
    fn add_backend(&mut self, b: &str) {
        if !self.backends.iter().any(|x| x == b) {
            self.backends.push(b.to_string());
        }
    }
}

/// The file an input path stands for: a directory's results.jsonl (or report.json), else itself.
pub fn resolve(path: &Path) -> Result<PathBuf, InputError> {
    if !path.is_dir() {
        return Ok(path.to_path_buf());
    }
    for name in [RESULTS_FILE, "report.json"] {
        let p = path.join(name);
        if p.is_file() {
            return Ok(p);
        }
    }
    Err(InputError::EmptyDir(path.display().to_string()))
}

/// One input file's records.
struct FileRecords {
    /// Why the file is not a finished run's record (JSON lines only).
    unfinished: Option<String>,
    /// Backends named by its metadata.
    backends: Vec<String>,
    fixtures: Vec<String>,
    implementations: BTreeMap<String, String>,
    results: Vec<TestResult>,
    load_errors: Vec<LoadError>,
}

/// Reads one results file: JSON lines (`.jsonl`, or a first line with a `"kind"` key), else a
/// report.json document.
fn read_file(path: &Path) -> Result<FileRecords, InputError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|source| InputError::Io {
        file: file.clone(),
        source,
    })?;
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    let is_jsonl = path.extension().is_some_and(|e| e == "jsonl")
        || serde_json::from_str::<serde_json::Value>(first).is_ok_and(|v| v.get("kind").is_some());
    if is_jsonl {
        let read = records::Results::parse(&file, &text)?;
        let unfinished = read.unfinished();
        let (backends, fixtures, implementations) = read
            .meta
            .map(|m| (m.backends, m.fixtures, m.implementations))
            .unwrap_or_default();
        return Ok(FileRecords {
            unfinished,
            backends,
            fixtures,
            implementations,
            results: read.results,
            load_errors: read.load_errors.into_iter().collect(),
        });
    }
    // As for JSON lines: results whose footprint does not read back lose only the footprint.
    let doc: JsonReport = serde_json::from_str(&text)
        .or_else(|e| {
            let mut v: serde_json::Value = serde_json::from_str(&text)?;
            let Some(results) = v.get_mut("results").and_then(|r| r.as_array_mut()) else {
                return Err(e);
            };
            for r in results {
                if let Some(o) = r.as_object_mut() {
                    o.remove("footprint");
                }
            }
            serde_json::from_value(v)
        })
        .map_err(|e| InputError::Format {
            file,
            msg: e.to_string(),
        })?;
    Ok(FileRecords {
        unfinished: None,
        backends: doc.summary.backends,
        fixtures: vec![],
        implementations: BTreeMap::new(),
        results: doc.results,
        load_errors: doc.load_errors,
    })
}

/// Reads and merges `paths` (files or run directories), in order.
pub fn read_inputs(paths: &[PathBuf]) -> Result<ReportInput, InputError> {
    let mut input = ReportInput::default();
    let mut merged = records::Results::default();
    for p in paths {
        let file = resolve(p)?;
        let FileRecords {
            unfinished,
            backends,
            fixtures,
            implementations,
            results,
            load_errors,
        } = read_file(&file)?;
        if let Some(why) = unfinished {
            input
                .unfinished
                .push(format!("input {}: {why}", input.sources.len() + 1));
        }
        input.sources.push(file.display().to_string());
        input.implementations.extend(implementations);
        for b in &backends {
            input.add_backend(b);
        }
        for f in fixtures {
            if !input.fixtures.contains(&f) {
                input.fixtures.push(f);
            }
        }
        for r in results {
            input.add_backend(&r.backend);
            if merged.get(&r.backend, &r.test).is_some_and(|old| old != &r) {
                input.replaced += 1;
            }
            merged.insert(r);
        }
        merged.load_errors.extend(load_errors);
    }
    input.results = merged.results;
    input.load_errors = merged.load_errors.into_iter().collect();
    Ok(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_json_documents_and_directories_are_read_and_merged() {
        let dir =
            std::env::temp_dir().join(format!("shadowcheck-html-load-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("run")).unwrap();
        let rec = r#"{"backend":"b","test":"c@core","case_id":"c","api":"core","status":"Fail","outcome":"Fail","duration":0.0,"tags":{"spec":"gl46","target":"2d","format":"d24","func":"lequal","filter":"nearest/nearest"},"footprint":{"dref":null,"texels":[]}}"#;
        let summary = r#"{"schema_version":1,"backends":["b"],"counts":{"pass":0,"warn":0,"fail":1,"skip":0,"crash":0,"timeout":0,"expected_fail":0,"unexpected_improvement":0,"flake":0,"known_flake":0},"load_errors":0,"exit_code":100}"#;
        let doc = format!(
            r#"{{"schema_version":1,"summary":{summary},"load_errors":[],"results":[{rec}]}}"#
        );
        std::fs::write(dir.join("run/report.json"), &doc).unwrap();
        let other = rec
            .replace("\"b\"", "\"b2\"")
            .replace(r#","footprint":{"dref":null,"texels":[]}"#, "");
        std::fs::write(
            dir.join("other.jsonl"),
            format!("{{\"kind\":\"result\",{}\n", &other[1..]),
        )
        .unwrap();
        let finished = other.replace("\"b2\"", "\"b3\"");
        std::fs::write(
            dir.join("finished.jsonl"),
            format!(
                "{{\"kind\":\"result\",{}\n{{\"kind\":\"end\",\"tests\":{{\"b3\":1}}}}\n",
                &finished[1..]
            ),
        )
        .unwrap();
        let input = read_inputs(&[
            dir.join("run"),
            dir.join("other.jsonl"),
            dir.join("finished.jsonl"),
        ])
        .unwrap();
        assert_eq!(input.backends, vec!["b", "b2", "b3"]);
        assert_eq!(input.results.len(), 3);
        // The JSON lines without a closing record are a partial run, said on the page (numbered,
        // not by path); report.json and the finished run are not.
        assert_eq!(input.unfinished.len(), 1, "{:?}", input.unfinished);
        assert!(
            input.unfinished[0].starts_with("input 2: ")
                && input.unfinished[0].contains("no closing record"),
            "{:?}",
            input.unfinished
        );
        let page = super::super::render(
            &input,
            &super::super::Geometry::default(),
            &super::super::PageOptions::default(),
        );
        assert!(page.contains("<b>Partial run</b>: input 2: "));
        assert!(matches!(
            read_inputs(&[dir.join("missing")]),
            Err(InputError::Io { .. })
        ));
        std::fs::create_dir_all(dir.join("empty")).unwrap();
        assert!(matches!(
            read_inputs(&[dir.join("empty")]),
            Err(InputError::EmptyDir(_))
        ));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
