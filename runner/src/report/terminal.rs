//! The terminal: a progress bar on stderr for long runs (when stderr is a terminal), load errors
//! and diagnostics on stderr as they come, and at the end the summary table by spec / func /
//! filter / format and the dumps of regressions on stdout.

use super::{breakdown, dump};
use crate::events::{Event, Reporter, Timing};
use crate::records::exit::Ending;
use crate::records::{Counts, LoadError, Summary, TestResult};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::{IsTerminal, Write};

/// Regressions dumped in full on the terminal (all of them are in report.md / report.json).
const MAX_DUMPS: usize = 20;
/// Runs with fewer tests than this show no progress bar.
const BAR_MIN_TESTS: usize = 2000;

pub struct TerminalReporter {
    bar: Option<ProgressBar>,
    /// Print per-backend timings (`--timings`).
    pub timings: bool,
    /// Show diagnostics of implementations (stderr lines, restarts).
    pub verbose: bool,
    /// stdout's reader went away (`shadowcheck run | head`): the summary is not printed, and the
    /// run goes on (its exit code must not change because nobody reads the table).
    stdout_closed: bool,
}

impl TerminalReporter {
    pub fn new(timings: bool, verbose: bool) -> TerminalReporter {
        TerminalReporter {
            bar: None,
            timings,
            verbose,
            stdout_closed: false,
        }
    }

    fn err_line(&self, msg: &str) {
        match &self.bar {
            Some(b) => b.println(msg),
            None => crate::errln!("{msg}"),
        }
    }
}

impl Reporter for TerminalReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        match self.write_event(ev) {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                self.stdout_closed = true;
                Ok(())
            }
            r => r,
        }
    }
}

impl TerminalReporter {
    fn write_event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        match ev {
            Event::RunStarted {
                backends,
                tests,
                out_dir,
            } => self.run_started(backends, *tests, out_dir),
            Event::LoadError(e) => self.load_error(e),
            Event::BackendStarted { backend, .. } => {
                if let Some(b) = &self.bar {
                    b.set_message(backend.to_string());
                }
            }
            Event::Diagnostic { backend, message } => {
                if self.verbose {
                    self.err_line(&format!("[{backend}] {message}"));
                }
            }
            Event::BatchFinished { .. } => {}
            Event::CaseFinished { result, .. } => {
                if let Some(b) = &self.bar {
                    if result.rerun.is_none() {
                        b.inc(1);
                    }
                }
            }
            Event::BackendFinished {
                backend,
                counts,
                timing,
            } => self.backend_finished(backend, counts, timing),
            Event::RunFinished {
                results, summary, ..
            } => {
                if let Some(b) = self.bar.take() {
                    b.finish_and_clear();
                }
                if self.stdout_closed {
                    return Ok(());
                }
                write_summary(&mut std::io::stdout().lock(), results, summary)?;
                // The totals and the exit code come last, from the command, once every report is
                // written ([`final_line`]).
            }
        }
        Ok(())
    }

    /// The run's first line on stderr, and the progress bar for a long run on a terminal.
    fn run_started(&mut self, backends: &[String], tests: usize, out_dir: &std::path::Path) {
        crate::errln!(
            "shadowcheck: {tests} tests on {} -> {}",
            backends.join(", "),
            out_dir.display()
        );
        if tests >= BAR_MIN_TESTS && std::io::stderr().is_terminal() {
            let bar =
                ProgressBar::with_draw_target(Some(tests as u64), ProgressDrawTarget::stderr());
            if let Ok(style) = ProgressStyle::with_template(
                "{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} {msg}",
            ) {
                bar.set_style(style);
            }
            self.bar = Some(bar);
        }
    }

    fn load_error(&self, e: &LoadError) {
        // The loader's messages usually name the file and the case already.
        if e.message.starts_with(&e.file) {
            self.err_line(&format!("error: {}", e.message));
        } else {
            let case = e
                .case
                .as_deref()
                .map(|c| format!(" case `{c}`"))
                .unwrap_or_default();
            self.err_line(&format!("error: {}{case}: {}", e.file, e.message));
        }
    }

    /// A backend's counts on stderr, and its timings under `--timings`.
    fn backend_finished(&self, backend: &str, counts: &Counts, timing: &Timing) {
        let line = format!(
            "{backend}: {} pass, {} warn, {} fail, {} crash, {} timeout, {} skip, {} expected fail, {} improvement, {} flake",
            counts.pass,
            counts.warn,
            counts.fail,
            counts.crash,
            counts.timeout,
            counts.skip,
            counts.expected_fail,
            counts.unexpected_improvement,
            counts.flake + counts.known_flake
        ) + &not_applicable_note(counts.not_applicable);
        self.err_line(&line);
        if self.timings {
            let rate = if timing.backend_s > 0.0 {
                timing.cases_sent as f64 / timing.backend_s
            } else {
                0.0
            };
            self.err_line(&format!(
                "timings {backend}: {} cases sent, {:.3} s in the backend ({rate:.0} cases/s), {:.3} s judging and reporting",
                timing.cases_sent, timing.backend_s, timing.verdict_s
            ));
        }
    }
}

/// The end of a run on stdout: the breakdown tables, the dumps of the first regressions and
/// improvements, and the backends that ran no test.
fn write_summary(
    out: &mut impl Write,
    results: &[TestResult],
    summary: &Summary,
) -> std::io::Result<()> {
    write_breakdown(out, results)?;
    let regressions: Vec<_> = results
        .iter()
        .filter(|r| r.status.is_regression() || r.status.is_improvement())
        .collect();
    for r in regressions.iter().take(MAX_DUMPS) {
        write!(out, "\n{}", dump(r, ""))?;
    }
    if regressions.len() > MAX_DUMPS {
        writeln!(
            out,
            "\n... {} more in report.md",
            regressions.len() - MAX_DUMPS
        )?;
    }
    if summary.counts.total() > 0 && !summary.idle_backends.is_empty() {
        writeln!(out)?;
        for b in &summary.idle_backends {
            writeln!(
                out,
                "shadowcheck: backend `{b}` ran no test (every test was skipped)"
            )?;
        }
    }
    Ok(())
}

/// The summary tables by spec / func / filter / format.
fn write_breakdown(out: &mut impl Write, results: &[TestResult]) -> std::io::Result<()> {
    for (dim, rows) in breakdown(results) {
        writeln!(
            out,
            "{dim:<24} {:>7} {:>7} {:>6} {:>6} {:>7} {:>6}",
            "tests", "pass", "warn", "fail", "skip", "other"
        )?;
        for (k, r) in rows {
            writeln!(
                out,
                "  {k:<22} {:>7} {:>7} {:>6} {:>6} {:>7} {:>6}",
                r.tests, r.pass, r.warn, r.fail, r.skip, r.other
            )?;
        }
    }
    Ok(())
}

/// The run's last line on stdout: the totals and the exit code the process returns, with every
/// reason for it (printed by the command after the reports are written, so it is the real one).
pub fn final_line(summary: &Summary, ending: &Ending) -> String {
    let c = &summary.counts;
    format!(
        "shadowcheck: {} tests: {} pass, {} warn, {} fail, {} crash, {} timeout, {} skip, {} expected fail, {} unexpected improvement, {} flake, {} known flake; {} load errors{}; {}",
        c.total(),
        c.pass,
        c.warn,
        c.fail,
        c.crash,
        c.timeout,
        c.skip,
        c.expected_fail,
        c.unexpected_improvement,
        c.flake,
        c.known_flake,
        summary.load_errors,
        not_applicable_note(c.not_applicable),
        ending.describe()
    )
}

/// Prints [`final_line`] on stdout, after a blank line; a closed stdout is not an error (the exit
/// code says it all).
pub fn print_final_line(summary: &Summary, ending: &Ending) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "\n{}", final_line(summary, ending));
    let _ = out.flush();
}

/// `; N not applicable (...)` for the summary line, empty when there are none.
pub fn not_applicable_note(n: usize) -> String {
    if n == 0 {
        String::new()
    } else {
        format!("; {n} not applicable (spec or API path the backend does not implement: not tests)")
    }
}
