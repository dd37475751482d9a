//! report.md: totals, tables by spec / func / filter / format, load errors and failure dumps.

use super::{breakdown, dump, wants_dump};
use crate::baseline::Baseline;
use crate::events::{Event, Reporter};
use crate::records::{LoadError, Summary, TestResult};
use crate::run::CaseSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Dumps beyond this many are summarized (the full list is in report.json).
const MAX_DUMPS: usize = 500;

pub struct MarkdownReporter {
    dir: PathBuf,
    baseline: Option<Baseline>,
    cases: Option<Arc<CaseSet>>,
}

impl MarkdownReporter {
    /// `baseline`: the run's baseline, whose entries that excuse nothing get a section;
    /// `cases`: the run's, for the layer attribution when the run holds a layered backend and
    /// the Vulkan driver under it.
    pub fn new(
        dir: &Path,
        baseline: Option<Baseline>,
        cases: Option<Arc<CaseSet>>,
    ) -> MarkdownReporter {
        MarkdownReporter {
            dir: dir.to_path_buf(),
            baseline,
            cases,
        }
    }
}

/// Baseline entries shown in report.md per kind (the rest are counted).
pub const MAX_BASELINE_NOTES: usize = 50;

pub fn render(results: &[TestResult], errors: &[LoadError], summary: &Summary) -> String {
    let mut s = String::new();
    let c = &summary.counts;
    let _ = writeln!(s, "# shadowcheck report\n");
    let _ = writeln!(
        s,
        "Backends: {}\n",
        summary
            .backends
            .iter()
            .map(|b| format!("`{b}`"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let _ = writeln!(s, "| status | tests |\n|---|---:|");
    for (name, n) in [
        ("Pass", c.pass),
        ("Warn", c.warn),
        ("Fail", c.fail),
        ("Crash", c.crash),
        ("Timeout", c.timeout),
        ("Skip", c.skip),
        ("ExpectedFail", c.expected_fail),
        ("UnexpectedImprovement", c.unexpected_improvement),
        ("Flake", c.flake),
        ("KnownFlake", c.known_flake),
    ] {
        if n > 0 {
            let _ = writeln!(s, "| {name} | {n} |");
        }
    }
    let _ = writeln!(s, "| **total** | **{}** |\n", c.total());
    if c.not_applicable > 0 {
        let _ = writeln!(
            s,
            "Not applicable (not tests, outside the total): {} (spec or API path the backend does not implement).\n",
            c.not_applicable
        );
    }
    let _ = writeln!(
        s,
        "Load errors: {}. Exit code from these results: {} ({}); the run's own exit code also counts backends that could not start, reports that could not be written and an interruption (the last line the run printed).\n",
        summary.load_errors,
        summary.exit_code,
        crate::records::exit::meaning(summary.exit_code)
    );
    for b in &summary.idle_backends {
        let _ = writeln!(s, "Backend `{b}` ran no test: every test was skipped.\n");
    }
    for (dim, rows) in breakdown(results) {
        let _ = writeln!(s, "## By {dim}\n\n| {dim} | tests | pass | warn | fail | skip | other |\n|---|---:|---:|---:|---:|---:|---:|");
        for (k, r) in rows {
            let _ = writeln!(
                s,
                "| `{k}` | {} | {} | {} | {} | {} | {} |",
                r.tests, r.pass, r.warn, r.fail, r.skip, r.other
            );
        }
        s.push('\n');
    }
    if !errors.is_empty() {
        let _ = writeln!(s, "## Load errors\n");
        for e in errors {
            let _ = writeln!(
                s,
                "- `{}` {}: {}",
                e.file,
                e.case
                    .as_deref()
                    .map(|c| format!("case `{c}`"))
                    .unwrap_or_default(),
                e.message
            );
        }
        s.push('\n');
    }
    let dumps: Vec<&TestResult> = results.iter().filter(|r| wants_dump(r)).collect();
    if !dumps.is_empty() {
        let _ = writeln!(s, "## Failures and warnings ({})\n", dumps.len());
        for r in dumps.iter().take(MAX_DUMPS) {
            let _ = writeln!(s, "```text\n{}```\n", dump(r, ""));
        }
        if dumps.len() > MAX_DUMPS {
            let _ = writeln!(
                s,
                "... and {} more (see report.json).",
                dumps.len() - MAX_DUMPS
            );
        }
    }
    s
}

impl Reporter for MarkdownReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        if let Event::RunFinished {
            results,
            load_errors,
            summary,
        } = ev
        {
            let mut text = render(results, load_errors, summary);
            if let Some(b) = &self.baseline {
                let notes = b.notes(results, MAX_BASELINE_NOTES);
                if !notes.is_empty() {
                    let _ = writeln!(text, "\n## Baseline entries that excuse nothing\n");
                    for n in notes {
                        let _ = writeln!(text, "- {n}");
                    }
                }
            }
            if let Some(layers) =
                crate::attribute::report_section(results, &summary.backends, self.cases.as_deref())
            {
                text.push('\n');
                text += &layers;
            }
            super::atomic::write(&self.dir.join("report.md"), text.as_bytes())?;
        }
        Ok(())
    }
}
