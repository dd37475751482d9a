//! `shadowcheck run`: fixtures → backends → verdicts → reports. Exit codes: runner/README.md.

use anyhow::{bail, Context};
use shadowcheck_runner::backend::{self, Backend, BackendError, Options};
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

/// The Debian packages that provide the GL drivers the GL backends use.
pub const MESA_INSTALL: &str =
    "apt-get install -y libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers";

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
        Ok(Options {
            timeout: Duration::from_secs_f64(self.timeout),
            group: self.group,
            give_up: self.give_up_after,
            fast_compile: self.fast_compile,
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

    // Backends that cannot start here: named with the reason and the install hint; the run goes on
    // without them and exits 96 unless --skip-missing.
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
        match backend::open(n, &opts) {
            Ok(b) => backends.push(b),
            Err(e @ BackendError::Unknown(_)) => return Err(e.into()),
            Err(BackendError::Setup { msg, .. }) => missing.push((n.clone(), msg)),
        }
    }
    let what = if a.skip_missing {
        "warning: left out (--skip-missing)"
    } else {
        "error"
    };
    for (n, why) in &missing {
        shadowcheck_runner::errln!("shadowcheck: {what}: backend `{n}` cannot start here: {why}");
    }
    if missing
        .iter()
        .any(|(n, _)| n.starts_with("egl:") || n.starts_with("osmesa:"))
    {
        shadowcheck_runner::errln!(
            "shadowcheck: the GL backends need Mesa's drivers: {MESA_INSTALL}"
        );
    }
    if !missing.is_empty() && !a.skip_missing {
        shadowcheck_runner::errln!("shadowcheck: the run goes on without {} backend(s) and will exit {}; pass --skip-missing to run without them", missing.len(), exit::SETUP);
    }
    if backends.is_empty() {
        bail!("no backend could start");
    }
    let names: Vec<String> = backends.iter().map(|b| b.name().to_string()).collect();
    let out_dir = a.out.clone().unwrap_or_else(|| default_out(&a.backends));
    std::fs::create_dir_all(&out_dir).with_context(|| format!("creating {}", out_dir.display()))?;
    // Held until the process ends: a second run into this directory stops here (exit 96).
    let _lock = OutLock::acquire(&out_dir)?;

    let meta = RunMeta {
        backends: names.clone(),
        fixtures: fixtures.iter().map(|p| p.display().to_string()).collect(),
        cases: a.cases.clone(),
        shard: a.shard.map(|s| s.to_string()),
        baseline: a.baseline.as_ref().map(|p| p.display().to_string()),
        implementations: backends
            .iter()
            .filter_map(|b| {
                let i = b.implementation()?;
                let gl = backend::kinds::kind_of(b.name())
                    .is_some_and(|k| k.prefix == "egl" || k.prefix == "osmesa");
                let i = if a.exchange.fast_compile && gl {
                    format!("{i} [--fast-compile: GALLIVM_PERF=nopt]")
                } else {
                    i
                };
                Some((b.name().to_string(), i))
            })
            .collect(),
        ..RunMeta::new()
    };

    let mut set = run::load_cases(&fixtures);
    let loaded_any = !set.files.is_empty();
    set.select(pattern.as_ref(), a.shard);
    if !loaded_any && set.cases.is_empty() {
        for e in &set.errors {
            shadowcheck_runner::errln!("shadowcheck: error: {}: {}", e.file, e.message);
        }
        bail!(
            "no fixture could be loaded from {}",
            meta.fixtures.join(", ")
        );
    }

    let results_path = out_dir.join(RESULTS_FILE);
    let (prior, jsonl) = if a.resume && results_path.exists() {
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
        (prior, JsonlReporter::append(&results_path, a.full_report)?)
    } else {
        (
            records::Results::default(),
            JsonlReporter::create(&results_path, &meta, a.full_report)?,
        )
    };

    // Final reports of an earlier run in this folder would be stale until this run ends.
    for f in report::FINAL_FILES {
        let _ = std::fs::remove_file(out_dir.join(f));
    }

    let mut fanout = Fanout::default();
    fanout.reporters.push(Box::new(TerminalReporter::new(
        a.timings,
        a.exchange.verbose,
    )));
    fanout.reporters.push(Box::new(jsonl));
    fanout.reporters.extend(report::file_reporters(
        &out_dir,
        &FileReports {
            full: a.full_report,
            baseline: a.baseline.is_some().then(|| lists.baseline.clone()),
            ..FileReports::default()
        },
    ));
    let baseline = a.baseline.is_some().then(|| lists.baseline.clone());
    let settings = Settings {
        lists,
        rerun_regressions: !a.no_rerun,
        explicit_fixtures: !a.fixtures.is_empty(),
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
    // The exit code, decided once, printed as it is returned.
    let mut ending = Ending::new(summary.exit_code);
    if !missing.is_empty() && !a.skip_missing {
        let list: Vec<&str> = missing.iter().map(|(n, _)| n.as_str()).collect();
        ending.add(
            exit::SETUP,
            format!("backends that could not start: {}", list.join(", ")),
        );
    }
    if let Some((_, e)) = &fanout.error {
        shadowcheck_runner::errln!("shadowcheck: error: {e} (in {})", out_dir.display());
        ending.add(exit::SETUP, e.to_string());
    }
    if interrupt::requested() {
        shadowcheck_runner::errln!(
            "shadowcheck: interrupted: {} of {total} tests finished; they are kept in {} and the reports in {} cover them. Resume with:\n  {}",
            results.len(),
            out_dir.join(RESULTS_FILE).display(),
            out_dir.display(),
            resume_command(&out_dir)
        );
        ending.add(exit::INTERRUPTED, "interrupted");
    }
    if !not_applicable.is_empty() {
        let list: Vec<String> = not_applicable
            .iter()
            .map(|(n, why)| format!("`{n}` ({why})"))
            .collect();
        shadowcheck_runner::errln!(
            "shadowcheck: not applicable here, left out of this default run: {}: these contexts start but expose none of the specs they implement, so every case would be a Skip",
            list.join(", ")
        );
    }
    terminal::print_final_line(&summary, &ending);
    Ok(ExitCode::from(ending.code))
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
