//! `shadowcheck repro`: a standalone reproducer (a C program, or a page for WebGPU and WebGL) and a
//! bug report for a failing test (a lookup or a TexParameter state case) on a GL, Vulkan, WebGPU or
//! WebGL backend, or one per failure class of a results directory (`--all-failures`). The
//! generator is `shadowcheck_runner::repro`; this file parses the flags, runs it and prints what
//! was written.
//!
//! Exit codes: 0 written (a Fail reproduced: REPORT.md beside repro.c; or `--allow-pass`);
//! 1 the test is not a Fail on this backend (Pass or Warn: no bug report; repro.c, build.sh and
//! output.txt are kept); 96 bad arguments or setup (no compiler, no driver, unknown case).
//!
//! `--all-failures`: 0 when at least one class's reproducer was written (index.md says why any
//! other was not, and links only the folders written); 4 when the results hold no Fail to
//! reproduce (nothing is written); 96 when there are Fails but no reproducer could be written for
//! any of their classes (a backend repro does not write, no compiler: each reason on stderr).

use anyhow::{bail, Context};
use shadowcheck_runner::records::{exit, read_results, Outcome, RESULTS_FILE};
use shadowcheck_runner::repro::{self, classes, Judgement, Reproducer, RunOutput};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// The backend the test failed on (egl:*, egl@DIR:*, osmesa:*, vk:*, webgpu:* or webgl:*, as in
    /// `run -b`).
    #[arg(
        long = "backend",
        short = 'b',
        value_name = "B",
        required_unless_present = "all_failures"
    )]
    backend: Option<String>,
    /// The test: `<case id>@<api>` as in results and baselines (api: ff, arbfp, glsl120, glsl130,
    /// core, es100, es300, vk, wgsl); `<case id>/sweep=<k>@<api>`: the case's sweep point k.
    #[arg(
        long = "case",
        value_name = "ID",
        required_unless_present = "all_failures"
    )]
    case: Option<String>,
    /// Fixture file or directory to find the case in (repeatable). Default: cases/fixtures; with
    /// --all-failures, each record's own fixture file first.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Output directory. Default: out/repro/<backend>/<test> (one test), RESULTS_DIR/repro
    /// (--all-failures).
    #[arg(short = 'o', long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// One reproducer per failure class of the Fails in RESULTS_DIR/results.jsonl, and index.md.
    #[arg(long, value_name = "RESULTS_DIR", conflicts_with_all = ["backend", "case"])]
    all_failures: Option<PathBuf>,
    /// Keep going when the test is not a Fail here: write repro.c, build.sh and output.txt (never
    /// REPORT.md: only a "shall" violation is a bug report) and exit 0.
    #[arg(long)]
    allow_pass: bool,
}

fn slug(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.=".contains(c) {
                c
            } else {
                '_'
            }
        })
        .take(120)
        .collect()
}

/// Builds and runs the reproducer of `s` in `dir` and judges what it observed as the runner does.
fn reproduce(s: &Reproducer, dir: &Path) -> anyhow::Result<(RunOutput, Judgement)> {
    s.write_sources(dir)?;
    Ok(s.run(dir)?)
}

fn write_report(s: &Reproducer, dir: &Path, run: &RunOutput, j: &Judgement) -> anyhow::Result<()> {
    std::fs::write(dir.join(repro::REPORT_MD), s.report(run, j)).context("writing REPORT.md")
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    if let Some(results) = &a.all_failures {
        return all_failures(results, a.out.as_deref(), &a.fixtures);
    }
    let (Some(backend), Some(test)) = (a.backend.as_deref(), a.case.as_deref()) else {
        bail!("--backend and --case are required (or --all-failures RESULTS_DIR)");
    };
    let fixtures = if a.fixtures.is_empty() {
        vec![PathBuf::from(super::run::DEFAULT_FIXTURES)]
    } else {
        a.fixtures.clone()
    };
    let s = repro::reproducer(backend, test, &fixtures)?;
    let dir = a.out.clone().unwrap_or_else(|| {
        Path::new("out/repro")
            .join(slug(&s.backend().to_string()))
            .join(slug(&s.test()))
    });
    let (run, judged) = reproduce(&s, &dir)?;
    super::outln!("{}", run.stdout.trim_end())?;
    if judged.outcome() == Outcome::Fail {
        write_report(&s, &dir, &run, &judged)?;
        super::outln!(
            "wrote {}/{{{},{},{},{}}}",
            dir.display(),
            s.program_file(),
            repro::BUILD_SH,
            repro::OUTPUT_TXT,
            repro::REPORT_MD
        )?;
        return Ok(ExitCode::SUCCESS);
    }
    let what = format!(
        "{} is a {} on {} here, not a Fail: only a \"shall\" violation gets a bug report (no {} written; {} and {} are in {})",
        s.test(),
        judged.outcome().as_str(),
        s.backend(),
        repro::REPORT_MD,
        s.program_file(),
        repro::BUILD_SH,
        dir.display()
    );
    if a.allow_pass {
        super::outln!("{what}")?;
        Ok(ExitCode::SUCCESS)
    } else {
        shadowcheck_runner::errln!(
            "shadowcheck repro: {what}; --allow-pass keeps a passing reproducer with exit 0"
        );
        Ok(ExitCode::from(1))
    }
}

fn all_failures(
    results: &Path,
    out: Option<&Path>,
    extra_fixtures: &[PathBuf],
) -> anyhow::Result<ExitCode> {
    let file = if results.is_dir() {
        results.join(RESULTS_FILE)
    } else {
        results.to_path_buf()
    };
    let res = read_results(&file)?;
    let out = out.map_or_else(|| results.join("repro"), Path::to_path_buf);
    let cs = classes::classes(&res.results);
    let fails = res
        .results
        .iter()
        .filter(|r| classes::is_reproducible_fail(r))
        .count();
    if cs.is_empty() {
        shadowcheck_runner::errln!(
            "shadowcheck repro: no Fail to reproduce in {} ({} results; only Fails count, not Crash, Timeout, Flake or KnownFlake): nothing written",
            file.display(),
            res.results.len()
        );
        return Ok(ExitCode::from(exit::NOTHING));
    }
    let mut index = format!(
        "# Reproducers: {} failure classes of {fails} Fails in `{}`\n\nOne reproducer per class. Class key: backend, API path, compare or not, the channels that missed and the rule broken (the expectation's citations, under \"Tests per class\"); see `runner/src/repro/classes.rs`. Flaky failures are left out.\n\n| class | backend | API path | compare | missed | targets | tests | representative | result here |\n|---|---|---|---|---|---|--:|---|---|\n",
        cs.len(),
        file.display()
    );
    let mut details = String::from("\n## Tests per class\n");
    let mut reproduced = 0;
    let mut written = 0;
    let mut not_written = vec![];
    for (i, c) in cs.iter().enumerate() {
        let r = &c.representative;
        let dir = out.join(classes::slug(i, c));
        let mut fixtures: Vec<PathBuf> = r.fixtures.iter().map(PathBuf::from).collect();
        fixtures.extend(extra_fixtures.iter().cloned());
        if fixtures.is_empty() {
            fixtures.push(PathBuf::from(super::run::DEFAULT_FIXTURES));
        }
        let mut sources = false;
        let result = repro::reproducer(&r.backend, &repro::failing_test(r), &fixtures)
            .map_err(anyhow::Error::from)
            .and_then(|s| {
                s.write_sources(&dir)?;
                sources = true;
                let (run, judged) = s.run(&dir)?;
                if judged.outcome() == Outcome::Fail {
                    write_report(&s, &dir, &run, &judged)?;
                }
                Ok(judged.outcome())
            });
        let cell = match result {
            Ok(Outcome::Fail) => {
                reproduced += 1;
                format!(
                    "Fail reproduced: [REPORT.md]({}/REPORT.md)",
                    classes::slug(i, c)
                )
            }
            Ok(o) => format!("did not reproduce: {} (no REPORT.md)", o.as_str()),
            Err(e) => {
                let first = e.to_string().lines().next().unwrap_or_default().to_string();
                not_written.push(format!("{}: {first}", classes::slug(i, c)));
                format!("no reproducer: {}", first.replace('|', "/"))
            }
        };
        let slug = classes::slug(i, c);
        // Only a folder that holds a reproducer is linked.
        let name = if sources {
            written += 1;
            format!("[{slug}]({slug}/)")
        } else {
            slug.clone()
        };
        let _ = writeln!(
            index,
            "| {name} | `{}` | {} | {} | {} | {} | {} | `{}` | {cell} |",
            c.parts[0],
            c.parts[1],
            c.parts[2],
            c.parts[3],
            c.targets.join(", "),
            c.tests.len(),
            r.test,
        );
        let _ = writeln!(details, "\n### {slug}\n\nRule: {}\n", c.rule);
        for t in &c.tests {
            let _ = writeln!(details, "- `{t}`");
        }
    }
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    std::fs::write(out.join("index.md"), index + &details).context("writing index.md")?;
    for n in &not_written {
        shadowcheck_runner::errln!("shadowcheck repro: no reproducer for class {n}");
    }
    if written == 0 {
        shadowcheck_runner::errln!(
            "shadowcheck repro: no reproducer could be written for any of the {} classes of {} (index: {})",
            cs.len(),
            file.display(),
            out.join("index.md").display()
        );
        return Ok(ExitCode::from(exit::SETUP));
    }
    super::outln!(
        "{} classes, {written} reproducers written, {reproduced} reproduced as Fail; index: {}",
        cs.len(),
        out.join("index.md").display()
    )?;
    Ok(ExitCode::SUCCESS)
}
