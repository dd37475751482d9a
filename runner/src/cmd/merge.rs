//! `shadowcheck merge -o OUT IN...`: combines the results.jsonl of shards (or of separate runs) into
//! one set of reports in OUT, the same as an unsharded run would write. Exit codes as `run`.
//!
//! Each input is read by the shared reader (`records::read_results`: within one file the last
//! record of a test wins); across inputs a test may appear twice only with the same record.
//!
//! Refused (exit 96, saying why), as nextest refuses to merge archives of other builds: inputs
//! whose selection differs (fixtures, `--cases`, baseline: unrelated runs), an input without
//! its meta line, an input whose run did not finish (no closing record, a cut-off last line, fewer
//! tests than the run has: `records::Results::unfinished`; its missing tests would vanish from
//! the totals, and its Fails with them), and shards that do not make a whole (`K/N` with some K
//! missing, or with different N, among the inputs of the same backends).
//!
//! Writing: a results.jsonl or report that cannot be written (a full disk) does not hide the
//! regressions read: as `run`, the exit code is decided once by [`Ending`] (`exit code 100
//! (regressions; also 96: ...)`).

use anyhow::{bail, Context};
use shadowcheck_runner::events::{Event, Fanout, Reporter};
use shadowcheck_runner::records::{self, exit, exit::Ending, RunMeta, RESULTS_FILE};
use shadowcheck_runner::report::{
    self, jsonl::JsonlReporter, terminal, terminal::TerminalReporter, FileReports,
};
use shadowcheck_runner::run;
use shadowcheck_runner::shard::Shard;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Output directory for the merged reports.
    #[arg(short = 'o', long, value_name = "DIR")]
    out: PathBuf,
    /// Output directories (or results.jsonl files) of the runs to merge.
    #[arg(required = true)]
    inputs: Vec<PathBuf>,
    /// Keep passing tests in full in results.jsonl, report.json and junit.xml too (as
    /// `run --full-report`).
    #[arg(long)]
    full_report: bool,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let mut merged = records::Results::default();
    let mut backends: Vec<String> = vec![];
    let mut meta: Option<RunMeta> = None;
    let mut metas: Vec<(String, RunMeta)> = vec![];
    let mut read = vec![];
    let mut unfinished = vec![];
    for input in &a.inputs {
        let path = if input.is_dir() {
            input.join(RESULTS_FILE)
        } else {
            input.clone()
        };
        let p =
            records::read_results(&path).with_context(|| format!("reading {}", path.display()))?;
        match &p.meta {
            Some(m) => metas.push((path.display().to_string(), m.clone())),
            None => bail!(
                "{}: no meta line (not a results.jsonl written by shadowcheck run)",
                path.display()
            ),
        }
        if let Some(why) = p.unfinished() {
            unfinished.push(format!("{}: the run did not finish: {why}", path.display()));
        }
        read.push((path, p));
    }
    if !unfinished.is_empty() {
        bail!(
            "{}\nfinish each with the same `shadowcheck run` command plus `--out DIR --resume`, then merge again",
            unfinished.join("\n")
        );
    }
    // Before anything is combined: unrelated runs and missing shards are refused.
    check_related(&metas)?;
    for (path, p) in read {
        if let Some(m) = &p.meta {
            for b in &m.backends {
                if !backends.contains(b) {
                    backends.push(b.clone());
                }
            }
            let merged_meta = meta.get_or_insert_with(|| RunMeta {
                shard: None,
                ..m.clone()
            });
            for (b, i) in &m.implementations {
                merged_meta
                    .implementations
                    .entry(b.clone())
                    .or_insert_with(|| i.clone());
            }
        }
        for r in p.results {
            if let Some(prev) = merged.get(&r.backend, &r.test) {
                if prev != &r {
                    bail!(
                        "{}: test `{}` on `{}` is also in an earlier input, with another result",
                        path.display(),
                        r.test,
                        r.backend
                    );
                }
            }
            merged.insert(r);
        }
        merged.load_errors.extend(p.load_errors);
        // Shards and backends of one selection: each input counts its own not-applicable cases.
        for (b, n) in p.not_applicable {
            *merged.not_applicable.entry(b).or_default() += n;
        }
    }
    std::fs::create_dir_all(&a.out).with_context(|| format!("creating {}", a.out.display()))?;
    let _lock = shadowcheck_runner::outdir::OutLock::acquire(&a.out)?;
    let meta = RunMeta {
        backends: backends.clone(),
        ..meta.unwrap_or_default()
    };
    let mut fanout = Fanout::default();
    fanout
        .reporters
        .push(Box::new(TerminalReporter::new(false, false)));
    let errors: Vec<_> = merged.load_errors.iter().cloned().collect();
    let mut results = merged.results;
    let not_applicable = merged.not_applicable.values().sum();
    run::sort_results(&mut results);
    // A results.jsonl that cannot be written is said at the end, beside the regressions read.
    let results_path = a.out.join(RESULTS_FILE);
    let jsonl_error = write_results(
        &results_path,
        &meta,
        a.full_report,
        &merged.not_applicable,
        &errors,
        &results,
    )
    .err()
    .map(|e| format!("writing {}: {e}", results_path.display()));
    fanout.reporters.extend(report::file_reporters(
        &a.out,
        &FileReports {
            full: a.full_report,
            ..FileReports::default()
        },
    ));
    let summary = run::finish(backends, &mut results, &errors, not_applicable, &mut fanout);
    let mut ending = Ending::new(summary.exit_code);
    if let Some(e) = jsonl_error {
        shadowcheck_runner::errln!("shadowcheck: error: {e}");
        ending.add(exit::SETUP, e);
    }
    if let Some((_, e)) = &fanout.error {
        shadowcheck_runner::errln!("shadowcheck: error: {e} (in {})", a.out.display());
        ending.add(exit::SETUP, e.to_string());
    }
    terminal::print_final_line(&summary, &ending);
    Ok(ExitCode::from(ending.code))
}

/// Writes the merged results.jsonl: the meta line, load errors, not-applicable counts (with each
/// backend's tests), the records in report order, and the closing record.
fn write_results(
    path: &std::path::Path,
    meta: &RunMeta,
    full: bool,
    not_applicable: &std::collections::BTreeMap<String, usize>,
    errors: &[records::LoadError],
    results: &[records::TestResult],
) -> std::io::Result<()> {
    let mut jsonl = JsonlReporter::create(path, meta, full)?;
    for e in errors {
        jsonl.event(&Event::LoadError(e))?;
    }
    for b in &meta.backends {
        let tests = results.iter().filter(|r| &r.backend == b).count();
        let cases = not_applicable.get(b).copied().unwrap_or(0);
        jsonl.not_applicable(b, cases, tests)?;
    }
    for r in results {
        jsonl.event(&Event::CaseFinished {
            result: r,
            replayed: false,
        })?;
    }
    jsonl.end(results)
}

/// The inputs come from one run: the same selection, and for each set of backends either one
/// unsharded run or every shard `1..=N` of one `N`.
fn check_related(metas: &[(String, RunMeta)]) -> anyhow::Result<()> {
    let Some((first_path, first)) = metas.first() else {
        return Ok(());
    };
    let selection = |m: &RunMeta| (m.fixtures.clone(), m.cases.clone(), m.baseline.clone());
    for (path, m) in &metas[1..] {
        if selection(m) != selection(first) {
            bail!(
                "{path} and {first_path} are unrelated runs (fixtures {:?} / {:?}, --cases {:?} / {:?}, baseline {:?} / {:?}); merge combines shards or backends of one selection",
                m.fixtures, first.fixtures, m.cases, first.cases, m.baseline, first.baseline
            );
        }
    }
    let mut groups: std::collections::BTreeMap<Vec<String>, Vec<(&str, Option<&str>)>> =
        Default::default();
    for (path, m) in metas {
        let mut b = m.backends.clone();
        b.sort();
        groups
            .entry(b)
            .or_default()
            .push((path.as_str(), m.shard.as_deref()));
    }
    for (backends, inputs) in groups {
        let shards: Vec<(&str, Shard)> = inputs
            .iter()
            .filter_map(|(p, s)| s.and_then(|s| s.parse::<Shard>().ok()).map(|s| (*p, s)))
            .collect();
        if shards.is_empty() {
            continue;
        }
        let who = backends.join(", ");
        if shards.len() != inputs.len() {
            bail!("runs of {who}: sharded and unsharded inputs mixed");
        }
        let n = shards[0].1.n;
        if let Some((p, s)) = shards.iter().find(|(_, s)| s.n != n) {
            bail!("runs of {who}: {p} is shard {s}, another input is a shard of {n}");
        }
        let missing: Vec<String> = (1..=n)
            .filter(|k| !shards.iter().any(|(_, s)| s.k == *k))
            .map(|k| format!("{k}/{n}"))
            .collect();
        if !missing.is_empty() {
            bail!(
                "runs of {who}: shard(s) {} missing (merge needs all {n} shards)",
                missing.join(", ")
            );
        }
    }
    Ok(())
}
