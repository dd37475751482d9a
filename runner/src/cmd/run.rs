//! `shadowcheck run`: fixtures → backends → verdicts → reports. Exit codes: runner/README.md.

use anyhow::{bail, Context};
use shadowcheck_runner::backend::{self, Backend, Options};
use shadowcheck_runner::baseline::{Baseline, Lists, RegexList};
use shadowcheck_runner::events::Fanout;
use shadowcheck_runner::records::{self, exit, RunMeta, RESULTS_FILE};
use shadowcheck_runner::report::{
    self, jsonl::JsonlReporter, terminal::TerminalReporter, FileReports,
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
    /// Keep passing tests in report.json and junit.xml too (by default they hold what did not
    /// pass; results.csv and results.jsonl list every test either way).
    #[arg(long)]
    full_report: bool,
    /// Seconds an external implementation may take for one group of cases.
    #[arg(
        long,
        value_name = "SECS",
        default_value_t = 10.0,
        allow_negative_numbers = true
    )]
    timeout: f64,
    /// Cases written to an implementation process before each flush (a GPU implementation draws
    /// one batch per group; the timeout applies per group).
    #[arg(long, value_name = "N", default_value_t = 64)]
    group: usize,
    /// Backends run at once, each on its own thread (default: the number of CPUs).
    #[arg(long, short = 'j', value_name = "N")]
    jobs: Option<usize>,
    /// Print the time spent per backend (lookups vs. verdicts and reporting).
    #[arg(long)]
    timings: bool,
    /// Do not re-run regressions to detect flakes.
    #[arg(long)]
    no_rerun: bool,
    /// Show implementations' stderr lines and restarts.
    #[arg(long, short = 'v')]
    verbose: bool,
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
    // At most a year: Duration cannot hold 1e20 s, and no run waits that long on purpose.
    if !(a.timeout > 0.0 && a.timeout <= 365.0 * 86400.0) {
        bail!("--timeout must be a positive number of seconds, at most 31536000 (a year)");
    }
    let lists = lists(&a)?;
    let fixtures = if a.fixtures.is_empty() {
        vec![PathBuf::from(DEFAULT_FIXTURES)]
    } else {
        a.fixtures.clone()
    };

    let names = if a.backends.is_empty() {
        let names = backend::default_backends();
        if names.len() == 1 {
            eprintln!("shadowcheck: no GL driver found on this machine; running the soft backend only. Install Mesa for the GL backends: {MESA_INSTALL}");
        }
        names
    } else {
        a.backends.clone()
    };
    for (i, n) in names.iter().enumerate() {
        if names[..i].contains(n) {
            bail!("backend `{n}` is named twice");
        }
    }
    let out_dir = a.out.clone().unwrap_or_else(|| default_out(&a.backends));
    std::fs::create_dir_all(&out_dir).with_context(|| format!("creating {}", out_dir.display()))?;

    let meta = RunMeta {
        backends: names.clone(),
        fixtures: fixtures.iter().map(|p| p.display().to_string()).collect(),
        cases: a.cases.clone(),
        shard: a.shard.map(|s| s.to_string()),
        baseline: a.baseline.as_ref().map(|p| p.display().to_string()),
        ..RunMeta::new()
    };
    if a.group == 0 {
        bail!("--group must be at least 1");
    }
    let opts = Options {
        timeout: Duration::from_secs_f64(a.timeout),
        group: a.group,
    };
    let mut backends: Vec<Box<dyn Backend>> = Vec::with_capacity(names.len());
    for n in &names {
        backends.push(backend::open(n, &opts)?);
    }

    let mut set = run::load_cases(&fixtures);
    let loaded_any = !set.files.is_empty();
    set.select(pattern.as_ref(), a.shard);
    if !loaded_any && set.cases.is_empty() {
        for e in &set.errors {
            eprintln!("shadowcheck: error: {}: {}", e.file, e.message);
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
        if let Some(m) = &prior.meta {
            if *m != meta {
                bail!(
                    "--resume: {} was written by a different selection ({:?}); give the same --backend/--fixtures/--cases/--shard/--baseline, or drop --resume",
                    results_path.display(),
                    m
                );
            }
        }
        (prior, JsonlReporter::append(&results_path)?)
    } else {
        (
            records::Results::default(),
            JsonlReporter::create(&results_path, &meta)?,
        )
    };

    // Final reports of an earlier run in this folder would be stale until this run ends.
    for f in report::FINAL_FILES {
        let _ = std::fs::remove_file(out_dir.join(f));
    }

    let mut fanout = Fanout::default();
    fanout
        .reporters
        .push(Box::new(TerminalReporter::new(a.timings, a.verbose)));
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
    let (results, summary, _) = schedule::run_all(
        &mut backends,
        &set,
        &prior,
        &settings,
        &mut fanout,
        &out_dir,
        jobs,
    );
    drop(backends);
    // Baseline entries that excuse nothing: said on stderr (and in report.md), not ignored.
    if let Some(b) = &baseline {
        for n in b.notes(&results, 10) {
            eprintln!("shadowcheck: warning: {n}");
        }
    }
    if let Some((_, e)) = fanout.error {
        eprintln!(
            "shadowcheck: error: writing reports in {}: {e}",
            out_dir.display()
        );
        return Ok(ExitCode::from(exit::SETUP));
    }
    Ok(ExitCode::from(summary.exit_code))
}
