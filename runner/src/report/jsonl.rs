//! results.jsonl: one [`Line`] per record, appended as each test finishes and flushed after each
//! batch, so a killed run leaves everything finished so far on disk (and `--resume` can continue it).

use crate::events::{Event, Reporter};
use crate::records::{Line, RunMeta};
use std::fs::{File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::Path;

pub struct JsonlReporter {
    out: BufWriter<File>,
}

impl JsonlReporter {
    /// Starts `path` afresh with `meta` as its first line.
    pub fn create(path: &Path, meta: &RunMeta) -> std::io::Result<JsonlReporter> {
        let mut r = JsonlReporter {
            out: BufWriter::with_capacity(1 << 16, File::create(path)?),
        };
        r.write(&Line::Meta(meta.clone()))?;
        r.out.flush()?;
        Ok(r)
    }

    /// Appends to an existing file (`--resume`; cut any partial last line first).
    pub fn append(path: &Path) -> std::io::Result<JsonlReporter> {
        Ok(JsonlReporter {
            out: BufWriter::with_capacity(1 << 16, OpenOptions::new().append(true).open(path)?),
        })
    }

    fn write(&mut self, line: &Line) -> std::io::Result<()> {
        serde_json::to_writer(&mut self.out, line)?;
        self.out.write_all(b"\n")
    }
}

impl Reporter for JsonlReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        match ev {
            Event::CaseFinished {
                result,
                replayed: false,
            } => self.write(&Line::Result(Box::new((*result).clone()))),
            Event::LoadError(e) => self.write(&Line::LoadError((*e).clone())),
            Event::BatchFinished { .. }
            | Event::BackendStarted { .. }
            | Event::BackendFinished { .. }
            | Event::RunFinished { .. } => self.out.flush(),
            _ => Ok(()),
        }
    }
}
