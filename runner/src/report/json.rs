//! report.json: the summary, the load errors and every result, with `schema_version`.

use crate::events::{Event, Reporter};
use crate::records::{LoadError, Summary, TestResult};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The document written to report.json (stable serde type; see `schema_version`).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsonReport {
    pub schema_version: u32,
    pub summary: Summary,
    pub load_errors: Vec<LoadError>,
    pub results: Vec<TestResult>,
}

pub struct JsonReporter {
    dir: PathBuf,
}

impl JsonReporter {
    pub fn new(dir: &Path) -> JsonReporter {
        JsonReporter {
            dir: dir.to_path_buf(),
        }
    }
}

impl Reporter for JsonReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        if let Event::RunFinished {
            results,
            load_errors,
            summary,
        } = ev
        {
            let doc = JsonReport {
                schema_version: shadowcheck_model::SCHEMA_VERSION,
                summary: (*summary).clone(),
                load_errors: load_errors.to_vec(),
                results: results.to_vec(),
            };
            super::atomic::write_with(&self.dir.join("report.json"), |w| {
                serde_json::to_writer_pretty(w, &doc).map_err(std::io::Error::from)
            })?;
        }
        Ok(())
    }
}
