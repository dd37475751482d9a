//! `shadowcheck gen`: generates the fixtures of a named grid with the oracle's expectations, prints
//! the coverage table and the total size.
//!
//! `shadowcheck gen --grid default -o cases/fixtures` regenerates the committed fixtures;
//! `--check` compares with the files in the output folder instead of writing (exit 1 on a difference).
use anyhow::Context;
use shadowcheck_cases::{coverage::Coverage, fixtures, grids};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

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
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| match args.grid.as_str() {
            "default" => PathBuf::from("cases/fixtures"),
            g => PathBuf::from("target/fixtures").join(g),
        });
    let start = Instant::now();
    let mut bytes = 0usize;
    let mut nfiles = 0usize;
    let mut differ: Vec<String> = Vec::new();
    let mut all_cases = Vec::new();
    let mut all_states = Vec::new();
    let mut written: Vec<(String, fixtures::FixtureFile)> = Vec::new();
    let streaming = args.grid == "exhaustive";
    let mut coverage = Coverage::default();
    let mut streamed = std::collections::BTreeSet::new();
    grids::for_each_file(&args.grid, args.seed, |rel, file| {
        let text = fixtures::to_string(&file).map_err(|e| fixtures::FixtureError::Write {
            file: out.join(&rel),
            source: std::io::Error::other(e),
        })?;
        bytes += text.len();
        nfiles += 1;
        if args.check {
            let path = out.join(&rel);
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                differ.push(rel.clone());
            }
        }
        if streaming {
            let cov = Coverage::of(&file.cases).with_states(&file.state_cases);
            for (k, n) in cov.counts {
                *coverage.counts.entry(k).or_default() += n;
            }
            for (k, (n, read_back, ext)) in cov.state {
                let e = coverage.state.entry(k).or_insert((0, read_back, ext));
                e.0 += n;
            }
            coverage.total += cov.total;
            if !args.check {
                streamed.insert(fixtures::write_file(&out, &rel, &file)?);
            }
        } else {
            all_cases.extend(file.cases.iter().cloned());
            all_states.extend(file.state_cases.iter().cloned());
            written.push((rel, file));
        }
        Ok(())
    })
    .with_context(|| format!("generating grid `{}`", args.grid))?;
    let gen_time = start.elapsed();
    if streaming && !args.check {
        fixtures::remove_stale(&out, &streamed)
            .with_context(|| format!("cleaning {}", out.display()))?;
    }
    if !streaming {
        coverage = Coverage::of(&all_cases).with_states(&all_states);
        if args.check {
            if let Ok(existing) = fixtures::fixture_paths(&out) {
                let wanted = grids::paths(&written);
                for p in existing {
                    let rel = p
                        .strip_prefix(&out)
                        .unwrap_or(&p)
                        .to_string_lossy()
                        .replace('\\', "/");
                    if !wanted.contains(rel.as_str()) {
                        differ.push(format!("{rel} (stale)"));
                    }
                }
            }
        } else {
            fixtures::write_dir(&out, &written)
                .with_context(|| format!("writing {}", out.display()))?;
        }
    }
    // The report is assembled first and written once; a closed pipe (`| head`) is not an error
    // here (the files are already written).
    let mut report = String::new();
    if !args.summary_only && !streaming {
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
    if let Some(readme) = &args.update_readme {
        let text = std::fs::read_to_string(readme)
            .with_context(|| format!("reading {}", readme.display()))?;
        let new = shadowcheck_cases::coverage::replace_section(&text, &coverage.markdown())
            .with_context(|| format!("{}: no coverage markers", readme.display()))?;
        std::fs::write(readme, new).with_context(|| format!("writing {}", readme.display()))?;
    }
    report.push_str(&format!(
        "grid `{}` seed {}: {} cases in {} files, {} bytes ({:.1} MiB), generated in {:.2} s -> {}\n",
        args.grid,
        args.seed,
        coverage.total,
        nfiles,
        bytes,
        bytes as f64 / (1024.0 * 1024.0),
        gen_time.as_secs_f64(),
        out.display()
    ));
    {
        use std::io::Write;
        let mut stdout = std::io::stdout().lock();
        let _ = stdout
            .write_all(report.as_bytes())
            .and_then(|_| stdout.flush());
    }
    if args.check && !differ.is_empty() {
        for d in &differ {
            shadowcheck_runner::errln!("differs: {}", out.join(d).display());
        }
        shadowcheck_runner::errln!(
            "{} file(s) differ; regenerate with `cargo run --release -- gen --grid {} -o {}`",
            differ.len(),
            args.grid,
            out.display()
        );
        return Ok(ExitCode::from(DIFFERS));
    }
    Ok(ExitCode::SUCCESS)
}
