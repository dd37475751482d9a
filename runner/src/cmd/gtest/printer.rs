//! What `shadowcheck gtest` prints: googletest's `[ RUN      ]` / `[       OK ]` / `[  FAILED  ]` /
//! `[  SKIPPED ]` lines per test in the order the tests were chosen, note lines that no gtest
//! parser reads as a status, and the footer with its exit code (statuses as in the module docs of
//! `gtest.rs`).

use shadowcheck_runner::events::{Event, Sink};
use shadowcheck_runner::interrupt;
use shadowcheck_runner::records::{Outcome, TestResult};
use std::collections::HashMap;
use std::io::Write;
use std::process::ExitCode;

/// The longest note printed for one test (a reason quoting an implementation's stderr is cut).
pub(super) const NOTE_MAX: usize = 2000;

/// A note line under a test: never read as a status line by a gtest parser (deqp-runner takes any
/// `[ X ] Y` in a line for one), so brackets become parentheses and control characters spaces.
pub(super) fn note_lines(kind: &str, reason: &str) -> Vec<String> {
    let mut text: String = reason
        .chars()
        .map(|c| match c {
            '[' => '(',
            ']' => ')',
            '\n' => '\n',
            c if c.is_control() => ' ',
            c => c,
        })
        .collect();
    if text.len() > NOTE_MAX {
        let mut cut = NOTE_MAX;
        while !text.is_char_boundary(cut) {
            cut -= 1;
        }
        text.truncate(cut);
        text.push_str(" ... (cut)");
    }
    text.lines()
        .enumerate()
        .map(|(i, l)| {
            if i == 0 {
                format!("shadowcheck: {kind}: {l}")
            } else {
                format!("shadowcheck:   {l}")
            }
        })
        .collect()
}

/// The lines of one test in googletest's format and whether the output must end after them (a
/// Crash or Timeout: the test is left without its end line).
pub(super) fn test_lines(gtest: &str, r: &TestResult) -> (Vec<String>, bool) {
    let mut lines = vec![format!("[ RUN      ] {gtest}")];
    let ms = (r.duration * 1000.0).round().max(0.0);
    let reason = r.reason.as_deref().unwrap_or("");
    let end = match r.outcome {
        Outcome::Pass => format!("[       OK ] {gtest} ({ms} ms)"),
        Outcome::Warn => {
            let what = "Warn (a quality warning: inside the `quality` acceptance, outside `strict`; a pass)";
            lines.extend(note_lines(what, reason));
            format!("[       OK ] {gtest} ({ms} ms)")
        }
        Outcome::Fail => {
            lines.extend(note_lines("Fail", reason));
            lines.extend(note_lines("re-run alone", &r.rerun_command()));
            format!("[  FAILED  ] {gtest} ({ms} ms)")
        }
        Outcome::Skip => {
            lines.extend(note_lines("Skip", reason));
            format!("[  SKIPPED ] {gtest} ({ms} ms)")
        }
        Outcome::Crash | Outcome::Timeout => {
            let what = format!(
                "{} (googletest has no such status: this test is left without its end line, which a gtest runner reads as a crash)",
                r.outcome
            );
            lines.extend(note_lines(&what, reason));
            return (lines, true);
        }
    };
    lines.push(end);
    (lines, false)
}

/// Prints the results in the order of the tests selected, each once its result is settled: two
/// batch ends have passed since it came, i.e. the two batches after its own have come back (an
/// answer found later, a case answered twice, can still turn an earlier case into a Crash), or
/// the run is over. deqp-runner's per-test timer restarts at each RUN line.
pub(super) struct Printer {
    gtest: Vec<String>,
    index: HashMap<String, usize>,
    results: Vec<Option<TestResult>>,
    settled: Vec<bool>,
    fresh: Vec<usize>,
    older: Vec<usize>,
    next: usize,
    /// The output ended on a Crash or Timeout: nothing more is printed.
    stopped: bool,
    failed: Vec<String>,
    skipped: Vec<String>,
    passed: usize,
    /// Tests printed, then given another outcome (a fault found later).
    revised: Vec<String>,
    verbose: bool,
    /// stdout was closed: the reader went away.
    closed: bool,
}

impl Printer {
    pub(super) fn new(tests: Vec<String>, gtest: Vec<String>, verbose: bool) -> Printer {
        let n = tests.len();
        Printer {
            index: tests.into_iter().enumerate().map(|(i, t)| (t, i)).collect(),
            gtest,
            results: vec![None; n],
            settled: vec![false; n],
            fresh: vec![],
            older: vec![],
            next: 0,
            stopped: false,
            failed: vec![],
            skipped: vec![],
            passed: 0,
            revised: vec![],
            verbose,
            closed: false,
        }
    }

    pub(super) fn out(&mut self, lines: &[String]) {
        if self.closed {
            return;
        }
        let mut o = std::io::stdout().lock();
        let mut text = lines.join("\n");
        text.push('\n');
        if o.write_all(text.as_bytes())
            .and_then(|_| o.flush())
            .is_err()
        {
            self.closed = true;
        }
    }

    fn record(&mut self, r: &TestResult) {
        let Some(&i) = self.index.get(&r.test) else {
            return;
        };
        if i < self.next {
            let was = self.results[i].as_ref().map(|p| p.outcome);
            if was != Some(r.outcome) {
                self.revised.push(format!(
                    "{} was printed as {} but is {} ({})",
                    self.gtest[i],
                    was.map_or("-".into(), |o| o.to_string()),
                    r.outcome,
                    r.reason.as_deref().unwrap_or("")
                ));
            }
            return;
        }
        self.results[i] = Some(r.clone());
        self.settled[i] = false;
        self.fresh.push(i);
    }

    /// A batch ended: results from before the previous batch end are settled.
    fn batch_end(&mut self) {
        for i in std::mem::take(&mut self.older) {
            self.settled[i] = true;
        }
        self.older = std::mem::take(&mut self.fresh);
        self.print_ready();
    }

    fn print_ready(&mut self) {
        while !self.stopped && self.next < self.gtest.len() && self.settled[self.next] {
            let i = self.next;
            let Some(r) = self.results[i].take() else {
                break;
            };
            let (lines, stop) = test_lines(&self.gtest[i], &r);
            match r.outcome {
                Outcome::Pass | Outcome::Warn => self.passed += 1,
                Outcome::Skip => self.skipped.push(self.gtest[i].clone()),
                Outcome::Fail => self.failed.push(self.gtest[i].clone()),
                Outcome::Crash | Outcome::Timeout => {}
            }
            self.results[i] = Some(r);
            self.out(&lines);
            self.next += 1;
            if stop {
                self.stopped = true;
                // No more cases are sent: the gtest runner runs the rest in a new process.
                interrupt::request();
            }
        }
    }

    /// The run is over: `results` are the final ones (the last of a test wins).
    pub(super) fn finish(&mut self, results: &[TestResult]) {
        for r in results {
            if let Some(&i) = self.index.get(&r.test) {
                if i >= self.next {
                    self.results[i] = Some(r.clone());
                } else {
                    self.record(r);
                }
            }
        }
        for s in &mut self.settled {
            *s = true;
        }
        self.print_ready();
    }
}

impl Sink for Printer {
    fn emit(&mut self, ev: &Event<'_>) {
        match ev {
            Event::CaseFinished { result, .. } => self.record(result),
            Event::BatchFinished { .. } => self.batch_end(),
            Event::Diagnostic { backend, message } if self.verbose => {
                shadowcheck_runner::errln!("shadowcheck: {backend}: {message}");
            }
            _ => {}
        }
    }
}

/// After the run: the revisions on stderr, then googletest's footer unless the output ended on a
/// crash or a test got no result; the exit code.
pub(super) fn print_end(
    printer: &mut Printer,
    chosen: usize,
    suites: usize,
    t0: std::time::Instant,
) -> ExitCode {
    for r in &printer.revised {
        shadowcheck_runner::errln!("shadowcheck: warning: {r}");
    }
    if printer.stopped {
        return ExitCode::from(1);
    }
    let missing = chosen - printer.next;
    if missing > 0 {
        // Not expected: every test selected gets a result. The runner reruns the rest.
        shadowcheck_runner::errln!("shadowcheck: error: {missing} selected test(s) got no result");
        return ExitCode::from(1);
    }
    let mut footer = vec![
        format!(
            "[==========] {} tests from {} test suites ran. ({} ms total)",
            chosen,
            suites,
            t0.elapsed().as_millis()
        ),
        format!("[  PASSED  ] {} tests.", printer.passed),
    ];
    if !printer.skipped.is_empty() {
        footer.push(format!(
            "[  SKIPPED ] {} tests, listed below:",
            printer.skipped.len()
        ));
        footer.extend(printer.skipped.iter().map(|n| format!("[  SKIPPED ] {n}")));
    }
    if !printer.failed.is_empty() {
        footer.push(format!(
            "[  FAILED  ] {} tests, listed below:",
            printer.failed.len()
        ));
        footer.extend(printer.failed.iter().map(|n| format!("[  FAILED  ] {n}")));
    }
    printer.out(&footer);
    ExitCode::from(u8::from(!printer.failed.is_empty()))
}
