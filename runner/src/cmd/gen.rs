//! `shadowcheck gen`: generates the fixtures of a named grid with the oracle's expectations, prints
//! the coverage table and the total size.
//!
//! `shadowcheck gen --grid default -o cases/fixtures` regenerates the committed fixtures;
//! `--check` compares with the files in the output folder instead of writing (exit 1 on a difference).
use anyhow::Context;
use shadowcheck_cases::{coverage::Coverage, fixtures, grids};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

/// Exit code of `--check` when a generated file differs from the one in the output folder.
const DIFFERS: u8 = 1;

#[derive(clap::Args)]
pub struct Args {
    /// The grid: smoke (one of everything, < 1000 cases), default (committed under cases/fixtures),
    /// exhaustive (every D16 value x 3 refs x 8 funcs, 1.5 M cases, written file by file).
    #[arg(long, default_value = "default")]
    grid: String,
    /// Seed of the seeded random family (the committed fixtures use 0).
    #[arg(long, default_value_t = grids::DEFAULT_SEED)]
    seed: u64,
    /// Output folder. Default: cases/fixtures for `default`, target/fixtures/<grid> otherwise.
    #[arg(short = 'o', long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Compare the generated files with those in the output folder instead of writing them.
    #[arg(long)]
    check: bool,
    /// Also rewrite the coverage section of this README (between the coverage markers).
    #[arg(long, value_name = "README")]
    update_readme: Option<PathBuf>,
    /// Do not print the per-spec coverage tables (only the summary).
    #[arg(long)]
    summary_only: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    if !grids::names().contains(&args.grid.as_str()) {
        anyhow::bail!(
            "unknown grid `{}` (known: {})",
            args.grid,
            grids::names().join(", ")
        );
    }
    let out = out_dir(&args);
    let g = generate(&args, &out)?;
    // The report is assembled first and written once; a closed pipe (`| head`) is not an error
    // here (the files are already written).
    let mut report = coverage_report(&args, &g.coverage);
    if let Some(readme) = &args.update_readme {
        update_readme(readme, &g.coverage)?;
    }
    report.push_str(&format!(
        "grid `{}` seed {}: {} cases in {} files, {} bytes ({:.1} MiB), generated in {:.2} s -> {}\n",
        args.grid,
        args.seed,
        g.coverage.total,
        g.nfiles,
        g.bytes,
        g.bytes as f64 / (1024.0 * 1024.0),
        g.gen_time.as_secs_f64(),
        out.display()
    ));
    {
        use std::io::Write;
        let mut stdout = std::io::stdout().lock();
        let _ = stdout
            .write_all(report.as_bytes())
            .and_then(|_| stdout.flush());
    }
    if args.check && !g.differ.is_empty() {
        for d in &g.differ {
            shadowcheck_runner::errln!("differs: {}", out.join(d).display());
        }
        shadowcheck_runner::errln!(
            "{} file(s) differ; regenerate with `cargo run --release -- gen --grid {} -o {}`",
            g.differ.len(),
            args.grid,
            out.display()
        );
        return Ok(ExitCode::from(DIFFERS));
    }
    Ok(ExitCode::SUCCESS)
}

/// `-o`, or the grid's default folder.
fn out_dir(args: &Args) -> PathBuf {
    args.out
        .clone()
        .unwrap_or_else(|| match args.grid.as_str() {
            "default" => PathBuf::from("cases/fixtures"),
            g => PathBuf::from("target/fixtures").join(g),
        })
}

/// What generating the grid gave: sizes, the files that differ (`--check`), the coverage.
struct Generated {
    bytes: usize,
    nfiles: usize,
    differ: Vec<String>,
    coverage: Coverage,
    gen_time: Duration,
}

/// The files of a grid held in memory until all are generated (every grid but `exhaustive`).
#[derive(Default)]
struct Collected {
    cases: Vec<shadowcheck_model::Case>,
    states: Vec<shadowcheck_model::StateCase>,
    files: Vec<(String, fixtures::FixtureFile)>,
}

/// Generates the grid's files and writes them to `out` (or, with `--check`, compares them with
/// it). `exhaustive` is written file by file as generated; the others once all are generated.
fn generate(args: &Args, out: &Path) -> anyhow::Result<Generated> {
    let start = Instant::now();
    let mut g = Generated {
        bytes: 0,
        nfiles: 0,
        differ: Vec::new(),
        coverage: Coverage::default(),
        gen_time: Duration::ZERO,
    };
    let mut collected = Collected::default();
    let streaming = args.grid == "exhaustive";
    let mut streamed = std::collections::BTreeSet::new();
    grids::for_each_file(&args.grid, args.seed, |rel, file| {
        let text = fixtures::to_string(&file).map_err(|e| fixtures::FixtureError::Write {
            file: out.join(&rel),
            source: std::io::Error::other(e),
        })?;
        g.bytes += text.len();
        g.nfiles += 1;
        if args.check {
            let path = out.join(&rel);
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                g.differ.push(rel.clone());
            }
        }
        if streaming {
            add_coverage(&mut g.coverage, &file);
            if !args.check {
                streamed.insert(fixtures::write_file(out, &rel, &file)?);
            }
        } else {
            collected.cases.extend(file.cases.iter().cloned());
            collected.states.extend(file.state_cases.iter().cloned());
            collected.files.push((rel, file));
        }
        Ok(())
    })
    .with_context(|| format!("generating grid `{}`", args.grid))?;
    g.gen_time = start.elapsed();
    if streaming {
        if !args.check {
            fixtures::remove_stale(out, &streamed)
                .with_context(|| format!("cleaning {}", out.display()))?;
        }
    } else {
        g.coverage = Coverage::of(&collected.cases).with_states(&collected.states);
        if args.check {
            g.differ.extend(stale_files(out, &collected.files));
        } else {
            fixtures::write_dir(out, &collected.files)
                .with_context(|| format!("writing {}", out.display()))?;
        }
    }
    Ok(g)
}

/// Adds one streamed file's coverage to the running total.
fn add_coverage(coverage: &mut Coverage, file: &fixtures::FixtureFile) {
    let cov = Coverage::of(&file.cases).with_states(&file.state_cases);
    for (k, n) in cov.counts {
        *coverage.counts.entry(k).or_default() += n;
    }
    for (k, (n, read_back, ext)) in cov.state {
        let e = coverage.state.entry(k).or_insert((0, read_back, ext));
        e.0 += n;
    }
    coverage.total += cov.total;
}

/// `--check`: the fixture files in `out` that the grid does not generate, as `<rel> (stale)`.
fn stale_files(out: &Path, written: &[(String, fixtures::FixtureFile)]) -> Vec<String> {
    let mut stale = Vec::new();
    if let Ok(existing) = fixtures::fixture_paths(out) {
        let wanted = grids::paths(written);
        for p in existing {
            let rel = p
                .strip_prefix(out)
                .unwrap_or(&p)
                .to_string_lossy()
                .replace('\\', "/");
            if !wanted.contains(rel.as_str()) {
                stale.push(format!("{rel} (stale)"));
            }
        }
    }
    stale
}

/// The coverage tables (unless `--summary-only` or streamed), the summary, what was pruned and
/// what the default grid lacks.
fn coverage_report(args: &Args, coverage: &Coverage) -> String {
    let mut report = String::new();
    if !args.summary_only && args.grid != "exhaustive" {
        report.push_str(&coverage.markdown());
        report.push('\n');
    }
    report.push_str(&coverage.summary());
    if args.grid != "exhaustive" {
        for (why, n) in grids::pruned() {
            report.push_str(&format!("pruned {n} combinations: {why}\n"));
        }
    }
    let missing = coverage.missing();
    if args.grid == "default" && !missing.is_empty() {
        report.push_str(&format!(
            "{} allowed spec x target x format x filter x func combinations have no case\n",
            missing.len()
        ));
    }
    report
}

/// `--update-readme`: rewrites the coverage section of `readme`.
fn update_readme(readme: &Path, coverage: &Coverage) -> anyhow::Result<()> {
    let text =
        std::fs::read_to_string(readme).with_context(|| format!("reading {}", readme.display()))?;
    let new = shadowcheck_cases::coverage::replace_section(&text, &coverage.markdown())
        .with_context(|| format!("{}: no coverage markers", readme.display()))?;
    std::fs::write(readme, new).with_context(|| format!("writing {}", readme.display()))?;
    Ok(())
}
