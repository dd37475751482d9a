//! `shadowcheck mutants`: the fixtures against every seeded fault of the soft unit; prints the kill
//! matrix and the mutation score (runner/src/mutants/mod.rs has the definitions).
//!
//! Exit codes: 0 every selected mutant killed or documented as unobservable through the API; 1 some
//! observable mutant not killed (warn-only or survived);
//! 2 the correct unit fails a case (the score is meaningless); 96 setup error (runner/README.md).

use anyhow::Context;
use shadowcheck_runner::mutants::{self, render, KillStatus, Suite};
use std::path::PathBuf;
use std::process::ExitCode;

/// Exit code when some observable mutant is not killed (warn-only or survived).
const SURVIVORS: u8 = 1;
/// Exit code when the correct unit fails a case: the score is meaningless.
const UNIT_FAILS: u8 = 2;
use std::time::Instant;

#[derive(clap::Args)]
pub struct Args {
    /// Fixture file or directory (repeatable). Default: cases/fixtures.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Use a named grid generated in memory (smoke, default, exhaustive) instead of fixture files.
    #[arg(long, value_name = "NAME", conflicts_with = "fixtures")]
    grid: Option<String>,
    /// Run only this mutant (repeatable; keys as listed by --list).
    #[arg(long, value_name = "KEY")]
    mutant: Vec<String>,
    /// List the mutants (key and the defect each is modelled on) and exit.
    #[arg(long)]
    list: bool,
    /// Print the report as JSON on stdout instead of the table.
    #[arg(long)]
    json: bool,
    /// Also write the Markdown report (kill matrix, score, survivors) to FILE.
    #[arg(long, value_name = "FILE")]
    markdown: Option<PathBuf>,
    /// Rewrite the kill-matrix section of FILE (between the `mutants:begin` / `mutants:end`
    /// markers, e.g. README.md); the rest of the file is kept.
    #[arg(long, value_name = "FILE")]
    update_readme: Option<PathBuf>,
    /// Worker threads (default: the available parallelism).
    #[arg(long, short = 'j', value_name = "N")]
    jobs: Option<usize>,
    /// No progress lines on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// The command line as it would be typed to reproduce the run (for the report header).
fn command_line(a: &Args) -> String {
    let mut s = String::from("shadowcheck mutants");
    for f in &a.fixtures {
        s += &format!(" --fixtures {}", f.display());
    }
    if let Some(g) = &a.grid {
        s += &format!(" --grid {g}");
    }
    for m in &a.mutant {
        s += &format!(" --mutant {m}");
    }
    if let Some(o) = &a.markdown {
        s += &format!(" --markdown {}", o.display());
    }
    if let Some(r) = &a.update_readme {
        s += &format!(" --update-readme {}", r.display());
    }
    s
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let t0 = Instant::now();
    if a.list {
        for f in shadowcheck_soft::Fault::ALL {
            super::print_out(&format!("{:<40} {}\n", f.key(), mutants::about(*f)))?;
        }
        return Ok(ExitCode::SUCCESS);
    }
    let faults = mutants::select(&a.mutant)?;
    let mut states = Vec::new();
    let (source, cases) = match &a.grid {
        Some(g) => {
            let files = shadowcheck_cases::grids::generate(g, 0)
                .with_context(|| format!("generating grid `{g}`"))?;
            let mut cases = Vec::new();
            for (_, f) in files {
                cases.extend(f.cases);
                states.extend(f.state_cases);
            }
            (format!("grid {g}"), cases)
        }
        None => {
            let paths = if a.fixtures.is_empty() {
                vec![PathBuf::from(super::run::DEFAULT_FIXTURES)]
            } else {
                a.fixtures.clone()
            };
            let mut cases = Vec::new();
            for path in &paths {
                let files = shadowcheck_cases::fixtures::load_path(path).with_context(|| {
                    format!(
                        "loading fixtures (generate them with `shadowcheck gen --grid default -o {}`)",
                        path.display()
                    )
                })?;
                for (_, f) in files {
                    cases.extend(f.cases);
                    states.extend(f.state_cases);
                }
            }
            let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
            (names.join(", "), cases)
        }
    };
    if !a.quiet {
        shadowcheck_runner::errln!(
            "mutants: {} cases from {source} loaded in {:.2} s; sampling the correct unit",
            cases.len(),
            t0.elapsed().as_secs_f64()
        );
    }
    let suite = Suite::new(cases)?.with_states(states);
    let threads = a.jobs.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    });
    let total = faults.len();
    let quiet = a.quiet;
    let mut report = mutants::run(&suite, &source, &faults, threads, |done, m| {
        if !quiet {
            let n = if m.status == KillStatus::Killed {
                m.killing_cases
            } else {
                m.warn_cases
            };
            shadowcheck_runner::errln!(
                "[{done:>2}/{total}] {:<40} {:<9} {n:>6} cases  {:.2} s",
                m.key,
                m.status.as_str(),
                m.seconds
            );
        }
    });
    report.wall_seconds = t0.elapsed().as_secs_f64();
    if a.json {
        super::print_out(&format!("{}\n", serde_json::to_string_pretty(&report)?))?;
    } else {
        super::print_out(&render::table(&report))?;
    }
    if let Some(path) = &a.markdown {
        shadowcheck_runner::report::atomic::write(
            path,
            render::markdown(&report, &command_line(&a)).as_bytes(),
        )
        .with_context(|| format!("writing {}", path.display()))?;
        if !a.quiet {
            shadowcheck_runner::errln!("mutants: wrote {}", path.display());
        }
    }
    if let Some(path) = &a.update_readme {
        let text =
            std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        let new = shadowcheck_cases::markers::replace(
            &text,
            render::README_BEGIN,
            render::README_END,
            &render::readme_section(&report),
        )
        .with_context(|| {
            format!(
                "{}: no kill-matrix markers (add the lines `{}` and `{}` where the matrix goes)",
                path.display(),
                render::README_BEGIN,
                render::README_END
            )
        })?;
        shadowcheck_runner::report::atomic::write(path, new.as_bytes())
            .with_context(|| format!("writing {}", path.display()))?;
        if !a.quiet {
            shadowcheck_runner::errln!("mutants: updated the kill matrix in {}", path.display());
        }
    }
    Ok(if !report.unmutated.ok() {
        shadowcheck_runner::errln!(
            "mutants: the correct unit fails {} test(s); fix the unit or the fixtures first",
            report.unmutated.fail
        );
        ExitCode::from(UNIT_FAILS)
    } else if report.killed + report.unobservable < report.mutants.len() {
        ExitCode::from(SURVIVORS)
    } else {
        ExitCode::SUCCESS
    })
}
