//! `shadowcheck summarize -o DIR RUN_DIR... --platform NAME`: condenses `shadowcheck run --out`
//! directories into a reference-results folder (what reports/mesa-22.3.6/run.sh commits).
//!
//! Each RUN_DIR holds one backend's run (by convention named `r-<backend with ':' as '-'>`). The
//! backend, and so its label and its folder DIR/<backend with ':' as '-'>/, comes from the run's
//! meta line, never from the folder's name (a renamed folder would label another driver's
//! results); the implementation's own name and version (its protocol hello, e.g. GL_VERSION and
//! GL_RENDERER) heads its summary.md and is listed under SUMMARY.md's table. A run that did not
//! finish (no closing record, a cut-off last line, fewer tests than the run has:
//! `records::Results::unfinished`) is refused with its file named: its counts would be wrong.
//! The folder gets:
//! - `failures.csv`: copied as the run wrote it (the baseline);
//! - `warnings.csv`: `test,Warn` for every test whose final status is Warn, sorted;
//! - `summary.md`: status counts per API path, the most frequent skip reasons, and the non-pass
//!   groups (spec/target/format/filter/func) with one example test each;
//! - `report.md`: the run's report.md, cut at the last line break before [`REPORT_CAP`] characters.
//!
//! DIR/SUMMARY.md gets one table over every backend x API path (rows where everything was
//! skipped are left out). `--update-readme README.md` (alone or after the above) regenerates
//! README's headline result tables from the committed summaries (`report::headline`). Only results.jsonl (read by the shared reader, `records::read_results`:
//! the last record of a test wins), failures.csv and report.md of each run are read.

use anyhow::{bail, Context};
use shadowcheck_runner::records::{self, exit, Results, TestResult, RESULTS_FILE};
use shadowcheck_runner::report::csv::field;
use shadowcheck_runner::report::headline;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The status columns every table has, in this order; other statuses (UnexpectedImprovement(..))
/// follow, sorted.
const STATUSES: [&str; 9] = [
    "Pass",
    "Warn",
    "Fail",
    "Skip",
    "Crash",
    "Timeout",
    "Flake",
    "KnownFlake",
    "ExpectedFail",
];
/// The length at which a copied report.md is cut, in characters.
pub const REPORT_CAP: usize = 150_000;
/// Skip reasons listed per API path.
const SKIP_REASONS: usize = 12;

#[derive(clap::Args)]
pub struct Args {
    /// Folder to write: DIR/<backend>/ per run directory, and DIR/SUMMARY.md.
    #[arg(short = 'o', long = "out", value_name = "DIR", required_unless_present = "update_readme", requires_all = ["runs", "platform"])]
    outroot: Option<PathBuf>,
    /// `shadowcheck run --out` directories, one backend each, named r-<backend with ':' as '-'>.
    #[arg(value_name = "RUN_DIR", requires = "outroot")]
    runs: Vec<PathBuf>,
    /// What the runs ran on, for the headings (e.g. "Mesa 22.3.6").
    #[arg(long, value_name = "NAME", requires = "outroot")]
    platform: Option<String>,
    /// Then regenerate FILE's headline result tables (between its `results:NAME:begin` /
    /// `results:NAME:end` markers) from reports/headline.json and the committed
    /// reports/*/SUMMARY.md beside FILE; alone, only that.
    #[arg(long, value_name = "FILE")]
    update_readme: Option<PathBuf>,
}

/// Status counts per API path: api → status → tests.
type Counts = BTreeMap<String, BTreeMap<String, usize>>;

/// A non-pass group of one API path: (api, status, spec/target/format/filter/func).
type Group = (String, String, String);

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    if let (Some(outroot), Some(platform)) = (&a.outroot, &a.platform) {
        summarize_runs(outroot, &a.runs, platform)?;
    }
    if let Some(readme) = &a.update_readme {
        let reports = readme
            .parent()
            .unwrap_or_else(|| Path::new("."))
            .join("reports");
        let new = headline::regenerate(readme, &reports)?;
        shadowcheck_runner::report::atomic::write(readme, new.as_bytes())
            .with_context(|| format!("writing {}", readme.display()))?;
        shadowcheck_runner::errln!(
            "summarize: updated the result tables in {} from {}",
            readme.display(),
            reports.join("headline.json").display()
        );
    }
    Ok(ExitCode::from(exit::SUCCESS))
}

/// Writes `outroot`/<backend>/ for every run and `outroot`/SUMMARY.md.
fn summarize_runs(outroot: &Path, runs: &[PathBuf], platform: &str) -> anyhow::Result<()> {
    let mut all_cols: Vec<String> = STATUSES.iter().map(|s| s.to_string()).collect();
    let mut rows = vec![];
    for run in runs {
        let (backend, implementation, counts, cols) = summarize(outroot, run, platform)
            .with_context(|| format!("summarizing {}", run.display()))?;
        for c in cols {
            if !all_cols.contains(&c) {
                all_cols.push(c);
            }
        }
        if rows.iter().any(|(b, _, _)| *b == backend) {
            bail!("two run directories hold the runs of `{backend}`; give one per backend");
        }
        rows.push((backend, implementation, counts));
    }
    let mut out = vec![
        format!("# {platform} reference results (default fixtures)\n"),
        "One row per backend x API path; a test is one case on one API path. See ../README.md for the causes.\n".to_string(),
        format!("| backend | API path | {} |", all_cols.join(" | ")),
        format!("|---|---|{}", "---:|".repeat(all_cols.len())),
    ];
    for (backend, _, counts) in &rows {
        for (api, c) in counts {
            let n = |s: &String| c.get(s).copied().unwrap_or(0);
            if all_cols.iter().filter(|s| *s != "Skip").all(|s| n(s) == 0) {
                continue; // everything skipped (another spec's API path)
            }
            let cells: Vec<String> = all_cols.iter().map(|s| n(s).to_string()).collect();
            out.push(format!("| {backend} | {api} | {} |", cells.join(" | ")));
        }
    }
    let named: Vec<String> = rows
        .iter()
        .filter_map(|(b, i, _)| Some(format!("- {b}: {}", i.as_deref()?)))
        .collect();
    if !named.is_empty() {
        out.push("\nImplementations (as each run's meta line names them):\n".to_string());
        out.extend(named);
    }
    let path = outroot.join("SUMMARY.md");
    shadowcheck_runner::report::atomic::write(&path, (out.join("\n") + "\n").as_bytes())
        .with_context(|| format!("writing {}", path.display()))
}

/// The label and folder name of a backend: its name with ':' as '-' (`egl-llvmpipe-es3`).
fn label_of(backend: &str) -> String {
    backend.replace(['/', '\\'], "_").replace(':', "-")
}

/// The one backend of a run and its implementation's name, from the meta line of `results`
/// (`file` names it in errors); a run that did not finish is refused.
fn backend_of(file: &Path, results: &Results) -> anyhow::Result<(String, Option<String>)> {
    let Some(meta) = &results.meta else {
        bail!(
            "{}: no meta line (not a results.jsonl written by shadowcheck run)",
            file.display()
        );
    };
    if let Some(why) = results.unfinished() {
        bail!(
            "{}: the run did not finish: {why}; finish it with the same `shadowcheck run` command plus `--resume`, then summarize",
            file.display()
        );
    }
    let [backend] = meta.backends.as_slice() else {
        bail!(
            "{}: a run of {} backends ({}); summarize takes one backend's run per directory",
            file.display(),
            meta.backends.len(),
            meta.backends.join(", ")
        );
    };
    Ok((backend.clone(), meta.implementations.get(backend).cloned()))
}

/// Writes DIR/<backend>/ for one run; returns the backend's label, its implementation's name,
/// its counts and its status columns.
fn summarize(
    outroot: &Path,
    run: &Path,
    platform: &str,
) -> anyhow::Result<(String, Option<String>, Counts, Vec<String>)> {
    let file = run.join(RESULTS_FILE);
    let read = records::read_results(&file)?;
    let (name, implementation) = backend_of(&file, &read)?;
    let backend = label_of(&name);
    let dir_name = run.file_name().map(|n| n.to_string_lossy().into_owned());
    if dir_name.as_deref() != Some(&format!("r-{backend}")) {
        shadowcheck_runner::errln!(
            "shadowcheck summarize: note: {} holds the run of `{name}` (its meta line): summarized as {backend}",
            run.display()
        );
    }
    let dst = outroot.join(&backend);
    std::fs::create_dir_all(&dst).with_context(|| format!("creating {}", dst.display()))?;
    let results = read.results;
    let mut counts = Counts::new();
    // Per API path, skip reasons in order of first appearance (ties keep that order).
    let mut skips: BTreeMap<String, Vec<(String, usize)>> = BTreeMap::new();
    let mut groups: BTreeMap<String, BTreeMap<Group, usize>> = BTreeMap::new();
    let mut examples: HashMap<Group, String> = HashMap::new();
    let mut warns: Vec<&str> = vec![];
    for r in &results {
        let api = r.api.key().to_string();
        let st = r.status.to_string();
        *counts
            .entry(api.clone())
            .or_default()
            .entry(st.clone())
            .or_default() += 1;
        if st == "Skip" {
            let reason = r
                .reason
                .as_deref()
                .filter(|s| !s.is_empty())
                .unwrap_or("(no reason)");
            let list = skips.entry(api.clone()).or_default();
            match list.iter_mut().find(|(x, _)| x == reason) {
                Some((_, n)) => *n += 1,
                None => list.push((reason.to_string(), 1)),
            }
        } else if st != "Pass" {
            let key = (api.clone(), st.clone(), group_of(r));
            examples
                .entry(key.clone())
                .or_insert_with(|| r.test.clone());
            *groups.entry(api).or_default().entry(key).or_default() += 1;
        }
        if st == "Warn" {
            warns.push(&r.test);
        }
    }

    let copy = |name: &str| -> anyhow::Result<()> {
        std::fs::copy(run.join(name), dst.join(name))
            .with_context(|| format!("copying {}", run.join(name).display()))?;
        Ok(())
    };
    copy("failures.csv")?;
    warns.sort_unstable();
    let warnings: String = warns
        .iter()
        .map(|t| format!("{},Warn\r\n", field(t)))
        .collect();
    write(&dst.join("warnings.csv"), &warnings)?;
    let report = run.join("report.md");
    let text = std::fs::read_to_string(&report)
        .with_context(|| format!("reading {}", report.display()))?;
    write(&dst.join("report.md"), &cap_report(&text))?;

    let mut extra: Vec<String> = counts
        .values()
        .flat_map(|c| c.keys())
        .filter(|s| !STATUSES.contains(&s.as_str()))
        .cloned()
        .collect();
    extra.sort();
    extra.dedup();
    let cols: Vec<String> = STATUSES
        .iter()
        .map(|s| s.to_string())
        .chain(extra)
        .collect();
    let mut lines = vec![format!("# {backend} on {platform}\n")];
    if let Some(i) = &implementation {
        lines.push(format!("Implementation (the run's meta line): {i}\n"));
    }
    lines.extend([
        "Status per API path (tests = case x API path):\n".to_string(),
        format!("| API path | {} | total |", cols.join(" | ")),
        format!("|---|{}", "---:|".repeat(cols.len() + 1)),
    ]);
    for (api, c) in &counts {
        let cells: Vec<String> = cols
            .iter()
            .map(|s| c.get(s).copied().unwrap_or(0).to_string())
            .collect();
        let total: usize = c.values().sum();
        lines.push(format!("| {api} | {} | {total} |", cells.join(" | ")));
    }
    lines.push("\n## Skip reasons\n".to_string());
    for (api, reasons) in &mut skips {
        // Most frequent first; a stable sort keeps first appearance among equals.
        reasons.sort_by_key(|r| std::cmp::Reverse(r.1));
        for (reason, n) in reasons.iter().take(SKIP_REASONS) {
            lines.push(format!("- `{api}` {n}: {reason}"));
        }
    }
    lines.push(
        "\n## Non-pass groups (spec/target/format/filter/func), with one example test\n"
            .to_string(),
    );
    lines.push(
        "| API path | status | group | tests | example |\n|---|---|---|---:|---|".to_string(),
    );
    for g in groups.values() {
        let mut g: Vec<(&Group, &usize)> = g.iter().collect();
        g.sort_by(|a, b| b.1.cmp(a.1).then_with(|| a.0.cmp(b.0)));
        for (key, n) in g {
            let (api, st, group) = key;
            let example = examples.get(key).map_or("", |s| s.as_str());
            lines.push(format!("| {api} | {st} | `{group}` | {n} | `{example}` |"));
        }
    }
    write(&dst.join("summary.md"), &(lines.join("\n") + "\n"))?;
    Ok((backend, implementation, counts, cols))
}

/// `spec/target/format/filter/func` of a record.
fn group_of(r: &TestResult) -> String {
    let t = &r.tags;
    format!(
        "{}/{}/{}/{}/{}",
        t.spec, t.target, t.format, t.filter, t.func
    )
}

/// A report.md longer than [`REPORT_CAP`] characters, cut at its last line break before the cap,
/// with a note saying so (the note says bytes, as the committed files do).
pub fn cap_report(text: &str) -> String {
    let chars = text.chars().count();
    let Some((at, _)) = text.char_indices().nth(REPORT_CAP) else {
        return text.to_string();
    };
    let cut = text[..at].rfind('\n').unwrap_or(at);
    format!(
        "{}\n\n... report.md capped at {REPORT_CAP} bytes of {chars}; re-run with run.sh for the full file.\n",
        &text[..cut]
    )
}

fn write(path: &Path, text: &str) -> anyhow::Result<()> {
    shadowcheck_runner::report::atomic::write(path, text.as_bytes())
        .with_context(|| format!("writing {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_report_is_cut_at_a_line_break_before_the_cap_counted_in_characters() {
        let short = "λ\n".repeat(10);
        assert_eq!(cap_report(&short), short);
        let exact = "é".repeat(REPORT_CAP);
        assert_eq!(cap_report(&exact), exact, "at the cap: kept whole");
        let line = format!("{}\n", "λ".repeat(99)); // 100 characters, 199 bytes
        let long = line.repeat(REPORT_CAP / 100 + 5);
        let capped = cap_report(&long);
        let kept = &line.repeat(REPORT_CAP / 100)[..];
        assert_eq!(
            capped,
            format!(
                "{}\n\n... report.md capped at 150000 bytes of {}; re-run with run.sh for the full file.\n",
                &kept[..kept.len() - 1],
                long.chars().count()
            )
        );
    }

    #[test]
    fn a_backend_is_labelled_with_colons_as_dashes() {
        assert_eq!(label_of("egl:llvmpipe:es3"), "egl-llvmpipe-es3");
        assert_eq!(
            label_of("egl:zink+swiftshader:core"),
            "egl-zink+swiftshader-core"
        );
        assert_eq!(label_of("egl@/opt/x:native:es3"), "egl@_opt_x-native-es3");
    }
}
