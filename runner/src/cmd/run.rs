//! `shadowcheck run`: fixtures → backends → verdicts → reports. Exit codes: runner/README.md.

use anyhow::{bail, Context};
use shadowcheck_runner::backend::{self, kinds, Backend, BackendError, Options, Unavailable};
use shadowcheck_runner::baseline::{Baseline, Lists, RegexList};
use shadowcheck_runner::events::Fanout;
use shadowcheck_runner::interrupt;
use shadowcheck_runner::outdir::OutLock;
use shadowcheck_runner::records::{self, exit, exit::Ending, RunMeta, RESULTS_FILE};
use shadowcheck_runner::report::{
    self, jsonl::JsonlReporter, terminal, terminal::TerminalReporter, FileReports,
};
use shadowcheck_runner::run::{self, Settings};
use shadowcheck_runner::schedule;
use shadowcheck_runner::shard::Shard;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

/// The fixtures run when `--fixtures` is not given.
pub const DEFAULT_FIXTURES: &str = "cases/fixtures";

#[derive(clap::Args)]
pub struct Args {
    /// Backend to run (repeatable); the text comes from the table of backend kinds.
    #[arg(long = "backend", short = 'b', value_name = "B", help = backend::kinds::help())]
    backends: Vec<String>,
    /// Fixture file or directory (repeatable). Default: cases/fixtures.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Only cases whose id matches this regular expression.
    #[arg(long, value_name = "PATTERN")]
    cases: Option<String>,
    /// Only shard K of N (1-based; by a hash of the case id).
    #[arg(long, value_name = "K/N")]
    shard: Option<Shard>,
    /// Expected failures, deqp-runner `test,Status` CSV (a previous failures.csv works).
    #[arg(long, value_name = "FILE")]
    baseline: Option<PathBuf>,
    /// Tests to skip: one regex per line, `#` comments.
    #[arg(long, value_name = "FILE")]
    skips: Option<PathBuf>,
    /// Tests known to be flaky: one regex per line; their failures are KnownFlake.
    #[arg(long, value_name = "FILE")]
    flakes: Option<PathBuf>,
    /// Output directory. Default: out/<backend names>.
    #[arg(short = 'o', long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Finish an interrupted run in --out: tests already in results.jsonl are not run again.
    #[arg(long)]
    resume: bool,
    /// Keep passing tests in full in results.jsonl, report.json and junit.xml too (by default
    /// report.json and junit.xml hold what did not pass and results.jsonl keeps plain passes in a
    /// compact line per case; results.csv lists every test either way).
    #[arg(long)]
    full_report: bool,
    #[command(flatten)]
    exchange: Exchange,
    /// Backends run at once, each on its own thread (default: the number of CPUs).
    #[arg(long, short = 'j', value_name = "N")]
    jobs: Option<usize>,
    /// Print the time spent per backend (lookups vs. verdicts and reporting).
    #[arg(long)]
    timings: bool,
    /// Do not re-run regressions to detect flakes.
    #[arg(long)]
    no_rerun: bool,
    /// Run without the backends that cannot start here (a driver not installed), saying which,
    /// instead of exiting 96 at the end.
    #[arg(long)]
    skip_missing: bool,
}

/// How the runner talks to an implementation: the flags `run` and `gtest` share, with one meaning.
#[derive(clap::Args)]
pub struct Exchange {
    /// Seconds an external implementation may take for one group of cases.
    #[arg(
        long,
        value_name = "SECS",
        default_value_t = 10.0,
        allow_negative_numbers = true
    )]
    pub timeout: f64,
    /// Cases written to an implementation process before each flush (a GPU implementation draws
    /// one batch per group; the timeout applies per group).
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub group: usize,
    /// After this many cases in a row end in Timeout, the rest of that implementation's cases are
    /// Timeout without being sent (0: never give up).
    #[arg(long, value_name = "K", default_value_t = backend::GIVE_UP_AFTER)]
    pub give_up_after: usize,
    /// Show implementations' stderr lines and restarts.
    #[arg(long, short = 'v')]
    pub verbose: bool,
    /// Cold runs in about half the time: GL workers run with GALLIVM_PERF=nopt, so llvmpipe and
    /// lavapipe (zink) skip LLVM's optimisation passes when compiling shader variants. It changes
    /// the driver's code generation, so it is never the default; the run's meta records it.
    #[arg(long)]
    pub fast_compile: bool,
    /// Sampler states one compiled program samples at most on the GL backends: the texture states
    /// of a batch are bound together, one per texture unit, and each program picks a case's unit,
    /// so a driver that compiles one variant per sampler state (llvmpipe, zink) compiles one per
    /// N states. Capped by the context's MAX_TEXTURE_IMAGE_UNITS; fixed function always draws one.
    /// 1 gives one state per program (the earlier behaviour, for comparisons).
    #[arg(long, value_name = "N", default_value_t = shadowcheck_plan::units::DEFAULT_STATES_PER_PROGRAM)]
    pub states_per_program: usize,
}

impl Exchange {
    /// The backend options these flags give, or why they are out of range.
    pub fn options(&self) -> anyhow::Result<Options> {
        // At most a year: Duration cannot hold 1e20 s, and no run waits that long on purpose.
        if !(self.timeout > 0.0 && self.timeout <= 365.0 * 86400.0) {
            bail!("--timeout must be a positive number of seconds, at most 31536000 (a year)");
        }
        if self.group == 0 {
            bail!("--group must be at least 1");
        }
        if self.states_per_program == 0 {
            bail!("--states-per-program must be at least 1");
        }
        Ok(Options {
            timeout: Duration::from_secs_f64(self.timeout),
            group: self.group,
            give_up: self.give_up_after,
            fast_compile: self.fast_compile,
            states_per_program: self.states_per_program,
        })
    }
}

/// `out/<backends>` with characters unfit for a file name replaced.
fn default_out(backends: &[String]) -> PathBuf {
    let name = if backends.is_empty() {
        "all".to_string()
    } else {
        backends.join("+")
    };
    let slug: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_+.=".contains(c) {
                c
            } else {
                '_'
            }
        })
        .take(80)
        .collect();
    Path::new("out").join(slug)
}

fn lists(a: &Args) -> anyhow::Result<Lists> {
    Ok(Lists {
        baseline: a
            .baseline
            .as_deref()
            .map(Baseline::load)
            .transpose()?
            .unwrap_or_default(),
        skips: a
            .skips
            .as_deref()
            .map(RegexList::load)
            .transpose()?
            .unwrap_or_default(),
        flakes: a
            .flakes
            .as_deref()
            .map(RegexList::load)
            .transpose()?
            .unwrap_or_default(),
    })
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let pattern = a
        .cases
        .as_deref()
        .map(regex::Regex::new)
        .transpose()
        .context("--cases")?;
    let opts = a.exchange.options()?;
    let lists = lists(&a)?;
    let fixtures = if a.fixtures.is_empty() {
        vec![PathBuf::from(DEFAULT_FIXTURES)]
    } else {
        a.fixtures.clone()
    };
    let Chosen {
        mut backends,
        missing,
        not_applicable,
    } = choose_backends(&a, &opts)?;
    let out_dir = a.out.clone().unwrap_or_else(|| default_out(&a.backends));
    std::fs::create_dir_all(&out_dir).with_context(|| format!("creating {}", out_dir.display()))?;
    // Held until the process ends: a second run into this directory stops here (exit 96).
    let _lock = OutLock::acquire(&out_dir)?;

    let meta = run_meta(&a, &backends, &fixtures);
    // Shared with report.md's layer attribution, which reads the run's cases at the end.
    let set = std::sync::Arc::new(load_fixtures(&fixtures, pattern.as_ref(), a.shard)?);
    let (prior, jsonl) = open_results(&a, &out_dir, &meta)?;
    // Final reports of an earlier run in this folder would be stale until this run ends.
    for f in report::FINAL_FILES {
        let _ = std::fs::remove_file(out_dir.join(f));
    }
    let mut fanout = reporters(&a, &out_dir, jsonl, &lists, &set);
    let baseline = a.baseline.is_some().then(|| lists.baseline.clone());
    let settings = Settings {
        lists,
        rerun_regressions: !a.no_rerun,
        explicit_fixtures: !a.fixtures.is_empty(),
        close_backends: true,
    };
    let jobs = a
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    install_interrupt_handler();
    let (results, summary, _) = schedule::run_all(
        &mut backends,
        &set,
        &prior,
        &settings,
        &mut fanout,
        &out_dir,
        jobs,
    );
    // The tests of the run: on each backend, those of its cases it implements (not-applicable
    // ones are no tests of it, as in the summary).
    let total: usize = backends
        .iter()
        .map(|b| set.tests_on(b.capabilities()).0)
        .sum();
    drop(backends);
    // Baseline entries that excuse nothing: said on stderr (and in report.md), not ignored.
    if let Some(b) = &baseline {
        for n in b.notes(&results, 10) {
            shadowcheck_runner::errln!("shadowcheck: warning: {n}");
        }
    }
    let ended = Ended {
        missing: &missing,
        not_applicable: &not_applicable,
        finished: results.len(),
        total,
    };
    let ending = ending(&a, &summary, &fanout, &out_dir, &ended);
    terminal::print_final_line(&summary, &ending);
    Ok(ExitCode::from(ending.code))
}

/// The cases of the fixture files under `fixtures`, selected by `--cases` and `--shard`. The errors
/// of files that do not load stay in the set (the run reports them and they count in its exit
/// code); none loading at all is an error here.
fn load_fixtures(
    fixtures: &[PathBuf],
    pattern: Option<&regex::Regex>,
    shard: Option<Shard>,
) -> anyhow::Result<run::CaseSet> {
    let mut set = run::load_cases(fixtures);
    let loaded_any = !set.files.is_empty();
    set.select(pattern, shard);
    if !loaded_any && set.cases.is_empty() {
        for e in &set.errors {
            shadowcheck_runner::errln!("shadowcheck: error: {}: {}", e.file, e.message);
        }
        let names: Vec<String> = fixtures.iter().map(|p| p.display().to_string()).collect();
        bail!("no fixture could be loaded from {}", names.join(", "));
    }
    Ok(set)
}

/// The backends of a run, opened, and those left out of it with the reason.
struct Chosen {
    backends: Vec<Box<dyn Backend>>,
    /// Named or defaults that cannot start here ([`backend::Defaults::missing`]).
    missing: Vec<Unavailable>,
    /// Defaults that start but can run no case here ([`backend::Defaults::not_applicable`]).
    not_applicable: Vec<Unavailable>,
}

/// The backends named with `-b`, or each kind's default instances ([`backend::default_backends`]),
/// opened. Those that cannot start are named with the reason and what to install; the run goes on
/// without them and exits 96 unless --skip-missing. An unknown name, a name given twice or no
/// backend that starts is an error.
fn choose_backends(a: &Args, opts: &Options) -> anyhow::Result<Chosen> {
    let backend::Defaults {
        run: requested,
        mut missing,
        absent,
        not_applicable,
    } = if a.backends.is_empty() {
        backend::default_backends()
    } else {
        backend::Defaults {
            run: a.backends.clone(),
            ..backend::Defaults::default()
        }
    };
    for (n, how) in &absent {
        shadowcheck_runner::errln!(
            "shadowcheck: note: optional backend `{n}` is not installed here: {how}"
        );
    }
    for (i, n) in requested.iter().enumerate() {
        if requested[..i].contains(n) {
            bail!("backend `{n}` is named twice");
        }
    }
    if a.exchange.fast_compile {
        shadowcheck_runner::errln!("shadowcheck: --fast-compile: GL workers run with GALLIVM_PERF=nopt (LLVM's optimisation passes off); the results are of that code generation");
    }
    let mut backends: Vec<Box<dyn Backend>> = Vec::with_capacity(requested.len());
    for n in &requested {
        match backend::open(n, opts) {
            Ok(b) => backends.push(b),
            Err(e @ BackendError::Unknown(_)) => return Err(e.into()),
            Err(BackendError::Setup { msg, .. }) => missing.push((n.clone(), msg)),
        }
    }
    say_missing(&missing, a.skip_missing);
    if backends.is_empty() {
        bail!("no backend could start");
    }
    Ok(Chosen {
        backends,
        missing,
        not_applicable,
    })
}

/// Names each backend that cannot start with the reason, then, once each, what its kind says to
/// install ([`kinds::BackendKind::missing_hint`]), and what the run will do about them.
fn say_missing(missing: &[Unavailable], skip_missing: bool) {
    let what = if skip_missing {
        "warning: left out (--skip-missing)"
    } else {
        "error"
    };
    for (n, why) in missing {
        shadowcheck_runner::errln!("shadowcheck: {what}: backend `{n}` cannot start here: {why}");
    }
    let mut hints: Vec<&str> = Vec::new();
    for (n, _) in missing {
        if let Some(h) = kinds::kind_of(n).and_then(|k| (k.missing_hint)(n)) {
            if !hints.contains(&h) {
                hints.push(h);
            }
        }
    }
    for h in hints {
        shadowcheck_runner::errln!("shadowcheck: {h}");
    }
    if !missing.is_empty() && !skip_missing {
        shadowcheck_runner::errln!("shadowcheck: the run goes on without {} backend(s) and will exit {}; pass --skip-missing to run without them", missing.len(), exit::SETUP);
    }
}

/// The run's meta line: its selection and what each implementation called itself (marked when
/// `--fast-compile` changed its code generation, [`kinds::BackendKind::fast_compile`]).
fn run_meta(a: &Args, backends: &[Box<dyn Backend>], fixtures: &[PathBuf]) -> RunMeta {
    RunMeta {
        backends: backends.iter().map(|b| b.name().to_string()).collect(),
        fixtures: fixtures.iter().map(|p| p.display().to_string()).collect(),
        cases: a.cases.clone(),
        shard: a.shard.map(|s| s.to_string()),
        baseline: a.baseline.as_ref().map(|p| p.display().to_string()),
        implementations: backends
            .iter()
            .filter_map(|b| {
                let i = b.implementation()?;
                let recompiled = kinds::kind_of(b.name()).is_some_and(|k| k.fast_compile);
                let i = if a.exchange.fast_compile && recompiled {
                    format!("{i} [--fast-compile: GALLIVM_PERF=nopt]")
                } else {
                    i
                };
                Some((b.name().to_string(), i))
            })
            .collect(),
        ..RunMeta::new()
    }
}

/// The results already in `out_dir` (with `--resume`, after checking they are of this selection)
/// and the results.jsonl writer: appending to them, or a new file.
fn open_results(
    a: &Args,
    out_dir: &Path,
    meta: &RunMeta,
) -> anyhow::Result<(records::Results, JsonlReporter)> {
    let results_path = out_dir.join(RESULTS_FILE);
    if !(a.resume && results_path.exists()) {
        return Ok((
            records::Results::default(),
            JsonlReporter::create(&results_path, meta, a.full_report)?,
        ));
    }
    records::truncate_partial_line(&results_path)?;
    let prior = records::read_results(&results_path)?;
    match &prior.meta {
        Some(m) if m.selection() != meta.selection() => bail!(
            "--resume: {} was written by a different selection ({:?}); give the same --backend/--fixtures/--cases/--shard/--baseline, or drop --resume",
            results_path.display(),
            m
        ),
        Some(_) => {}
        // Without its selection nothing says these records belong to this run.
        None => bail!(
            "--resume: {} has no meta line (the run's selection), so it cannot be continued: not a results.jsonl written by shadowcheck run; drop --resume to start afresh",
            results_path.display()
        ),
    }
    Ok((prior, JsonlReporter::append(&results_path, a.full_report)?))
}

/// The run's reporters: the terminal, results.jsonl, and the files of `out_dir`.
fn reporters(
    a: &Args,
    out_dir: &Path,
    jsonl: JsonlReporter,
    lists: &Lists,
    set: &std::sync::Arc<run::CaseSet>,
) -> Fanout {
    let mut fanout = Fanout::default();
    fanout.reporters.push(Box::new(TerminalReporter::new(
        a.timings,
        a.exchange.verbose,
    )));
    fanout.reporters.push(Box::new(jsonl));
    fanout.reporters.extend(report::file_reporters(
        out_dir,
        &FileReports {
            full: a.full_report,
            baseline: a.baseline.is_some().then(|| lists.baseline.clone()),
            cases: Some(set.clone()),
            ..FileReports::default()
        },
    ));
    fanout
}

/// What the end of a run needs besides the summary.
struct Ended<'a> {
    missing: &'a [Unavailable],
    not_applicable: &'a [Unavailable],
    /// Tests finished, and tests of the run.
    finished: usize,
    total: usize,
}

/// The exit code, decided once from the summary and what else happened (backends that could not
/// start, a reporter's error, an interrupt), each said on stderr.
fn ending(
    a: &Args,
    summary: &records::Summary,
    fanout: &Fanout,
    out_dir: &Path,
    e: &Ended<'_>,
) -> Ending {
    let mut ending = Ending::new(summary.exit_code);
    if !e.missing.is_empty() && !a.skip_missing {
        let list: Vec<&str> = e.missing.iter().map(|(n, _)| n.as_str()).collect();
        ending.add(
            exit::SETUP,
            format!("backends that could not start: {}", list.join(", ")),
        );
    }
    if let Some((_, err)) = &fanout.error {
        shadowcheck_runner::errln!("shadowcheck: error: {err} (in {})", out_dir.display());
        ending.add(exit::SETUP, err.to_string());
    }
    if interrupt::requested() {
        shadowcheck_runner::errln!(
            "shadowcheck: interrupted: {} of {} tests finished; they are kept in {} and the reports in {} cover them. Resume with:\n  {}",
            e.finished,
            e.total,
            out_dir.join(RESULTS_FILE).display(),
            out_dir.display(),
            resume_command(out_dir)
        );
        ending.add(exit::INTERRUPTED, "interrupted");
    }
    if !e.not_applicable.is_empty() {
        let list: Vec<String> = e
            .not_applicable
            .iter()
            .map(|(n, why)| format!("`{n}` ({why})"))
            .collect();
        shadowcheck_runner::errln!(
            "shadowcheck: not applicable here, left out of this default run: {}: these contexts start but expose none of the specs they implement, so every case would be a Skip",
            list.join(", ")
        );
    }
    ending
}

/// SIGINT/SIGTERM: the first asks the run to stop after the batch in flight and write its reports;
/// a second exits at once (results.jsonl keeps every finished test).
fn install_interrupt_handler() {
    // Only fails when a handler is already installed (a second run in one process): keep it.
    let _ = ctrlc::set_handler(|| {
        if interrupt::request() {
            shadowcheck_runner::errln!("shadowcheck: interrupted again; stopping now (results.jsonl keeps every finished test; resume with --resume)");
            std::process::exit(i32::from(exit::INTERRUPTED));
        }
        shadowcheck_runner::errln!("shadowcheck: interrupted; finishing the batch in flight and writing the reports of the finished tests (Ctrl-C again stops at once)");
    });
}

/// This command line with `--out` and `--resume`, to finish an interrupted run.
fn resume_command(out_dir: &Path) -> String {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut words = vec!["shadowcheck".to_string()];
    words.extend(args.iter().map(|w| records::shell_quote(w)));
    let has = |f: &[&str]| {
        args.iter()
            .any(|w| f.iter().any(|f| w == f || w.starts_with(&format!("{f}="))))
    };
    if !has(&["--out", "-o"]) {
        words.push("--out".into());
        words.push(records::shell_quote(&out_dir.display().to_string()));
    }
    if !has(&["--resume"]) {
        words.push("--resume".into());
    }
    words.join(" ")
}
