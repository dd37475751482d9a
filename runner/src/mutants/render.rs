//! Text renderings of a [`MutantsReport`]: the terminal table and the Markdown report
//! (reports/MUTANTS.md).

use super::{KillStatus, MutantResult, MutantsReport};
use crate::verdict::Outcome;
use std::fmt::Write as _;

/// `12.3 %` with one decimal.
fn pct(v: f64) -> String {
    format!("{v:.1} %")
}

/// The one-line headline: score, counts, time.
pub fn headline(r: &MutantsReport) -> String {
    format!(
        "mutation score {} ({}/{} killed; {} warn-only, {} survived, {} of them unobservable through the API: {} of the observable faults killed) over {} cases / {} tests in {:.2} s ({:.2} s sampling and judging, {} threads)",
        pct(r.score),
        r.killed,
        r.mutants.len(),
        r.warn_only,
        r.survived,
        r.unobservable,
        pct(r.score_observable),
        r.cases,
        r.tests,
        r.wall_seconds,
        r.run_seconds,
        r.threads
    )
}

fn baseline_line(r: &MutantsReport) -> String {
    let b = &r.baseline;
    format!(
        "baseline (correct unit): {} Pass, {} Warn, {} Fail, {} Skip{}",
        b.pass,
        b.warn,
        b.fail,
        b.skip,
        if b.ok() {
            ""
        } else {
            " -- THE CORRECT UNIT FAILS: the score is meaningless"
        }
    )
}

/// The terminal table: mutant, result, killing cases, minimal killing case (and its API path),
/// first killing case.
pub fn table(r: &MutantsReport) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}", baseline_line(r));
    for f in &r.baseline.failures {
        let _ = writeln!(out, "  FAIL {} @ {}: {}", f.case, f.api, f.reason.as_deref().unwrap_or(""));
    }
    let w = r.mutants.iter().map(|m| m.key.len()).max().unwrap_or(6).max(6);
    let _ = writeln!(
        out,
        "{:<w$}  {:<9}  {:>6}  minimal killing case [api] / first killing case",
        "mutant", "result", "cases"
    );
    for m in &r.mutants {
        let count = match m.status {
            KillStatus::Killed => m.killing_cases,
            _ => m.warn_cases,
        };
        let _ = write!(out, "{:<w$}  {:<9}  {:>6}  ", m.key, m.status.as_str(), count);
        match (&m.minimal, &m.first) {
            (Some(min), Some(first)) => {
                let _ = write!(out, "{} [{}]", min.case, min.api);
                if first.case != min.case {
                    let _ = write!(out, " / {}", first.case);
                }
            }
            _ => {
                let _ = write!(out, "-");
            }
        }
        if m.unobservable.is_some() {
            let _ = write!(out, "  (unobservable through the API, see the report)");
        } else if m.status != KillStatus::Killed {
            let _ = write!(out, "  (observable: needs a grid change, see the report)");
        }
        let _ = writeln!(out);
    }
    let _ = writeln!(out, "{}", headline(r));
    out
}

/// Escapes text for a Markdown table cell.
fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

fn rgba(v: Option<[f32; 4]>) -> String {
    match v {
        Some(v) => format!("({}, {}, {}, {})", v[0], v[1], v[2], v[3]),
        None => "error".to_string(),
    }
}

fn survivor(out: &mut String, m: &MutantResult) {
    let _ = writeln!(out, "### `{}` ({})\n", m.key, m.status.as_str());
    let _ = writeln!(out, "Modelled on: {}. Tests whose result changed: {}.\n", m.about, m.changed_tests);
    if let Some(why) = &m.unobservable {
        let _ = writeln!(out, "**Not observable through the API**: {why}.\n");
    }
    if let Some(change) = &m.grid_change {
        let _ = writeln!(out, "**Observable; grid change that kills it**: {change}.\n");
    }
    if let Some(min) = &m.minimal {
        let _ = writeln!(
            out,
            "Minimal Warn case: `{}` on `{}`: mutant {}, correct {}: {}\n",
            min.case,
            min.api,
            rgba(min.rgba),
            rgba(min.correct),
            min.reason.as_deref().unwrap_or("")
        );
    }
    if let Some(w) = &m.witness {
        let verdict = match w.mutant {
            Outcome::Fail => "the fault is observable through the API: this case kills it, so the grid should contain it (or its family)",
            Outcome::Warn => "observable only as a Warn on this case",
            _ => "the oracle accepts the faulty result on this case too: not observable there",
        };
        let _ = writeln!(
            out,
            "Witness case (`mutants::witness`, from soft/src/witness.rs) on `{}`: correct unit {}, mutant {}: {}. {}\n",
            w.api,
            w.correct,
            w.mutant,
            verdict,
            w.reason.as_deref().unwrap_or("")
        );
        let mut case = w.case.clone();
        case.expect = None;
        if let Ok(json) = serde_json::to_string(&case) {
            let _ = writeln!(out, "```json\n{json}\n```\n");
        }
    }
}

/// The Markdown report. `command`: the command line that produced it.
pub fn markdown(r: &MutantsReport, command: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# Mutation testing: `{}` against seeded faults of the soft unit\n", r.fixtures);
    let _ = writeln!(out, "Generated by `{command}`; regenerate rather than edit.\n");
    let _ = writeln!(
        out,
        "**Mutation score: {} ({} of {} mutants killed)**; warn-only {}, survived {}; {} not killed because the fault \
         cannot be observed through the API (see below), so **{} of the observable faults are killed** (score counting \
         warn-only kills: {}).\n",
        pct(r.score),
        r.killed,
        r.mutants.len(),
        r.warn_only,
        r.survived,
        r.unobservable,
        pct(r.score_observable),
        pct(r.score_with_warn)
    );
    let _ = writeln!(
        out,
        "{} cases, {} tests (case × API path). Wall time {:.2} s for the whole command (fixture loading included), {:.2} s sampling and judging on {} threads.\n",
        r.cases, r.tests, r.wall_seconds, r.run_seconds, r.threads
    );
    let _ = writeln!(out, "{}.\n", baseline_line(r));
    for f in &r.baseline.failures {
        let _ = writeln!(out, "- FAIL `{}` on `{}`: {}", f.case, f.api, f.reason.as_deref().unwrap_or(""));
    }
    let _ = writeln!(out, "## Kill matrix\n");
    let _ = writeln!(
        out,
        "| # | mutant | modelled on | result | killing cases | failing tests | minimal killing case | API | first killing case |"
    );
    let _ = writeln!(out, "|---|---|---|---|---:|---:|---|---|---|");
    for (i, m) in r.mutants.iter().enumerate() {
        let (min, api) = m
            .minimal
            .as_ref()
            .map(|k| (format!("`{}`", cell(&k.case)), format!("`{}`", k.api)))
            .unwrap_or(("-".into(), "-".into()));
        let first = match (&m.first, &m.minimal) {
            (Some(f), Some(k)) if f.case == k.case => "(same)".to_string(),
            (Some(f), _) => format!("`{}`", cell(&f.case)),
            _ => "-".to_string(),
        };
        let result = match m.status {
            KillStatus::Killed => "killed".to_string(),
            _ if m.unobservable.is_some() => format!("{} (unobservable)", m.status.as_str()),
            s => format!("**{}**", s.as_str()),
        };
        let _ = writeln!(
            out,
            "| {} | `{}` | {} | {} | {} | {} | {} | {} | {} |",
            i + 1,
            m.key,
            cell(&m.about),
            result,
            if m.status == KillStatus::WarnOnly {
                format!("0 ({} Warn)", m.warn_cases)
            } else {
                m.killing_cases.to_string()
            },
            m.failing_tests,
            min,
            api,
            first
        );
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "## Why each minimal case kills\n");
    for m in r.mutants.iter().filter(|m| m.status == KillStatus::Killed) {
        if let Some(k) = &m.minimal {
            let _ = writeln!(
                out,
                "- `{}`: `{}` on `{}` ({} texel(s), {} level(s)): mutant {}, correct unit {}; {}",
                m.key,
                k.case,
                k.api,
                k.complexity.texels,
                k.complexity.levels,
                rgba(k.rgba),
                rgba(k.correct),
                k.reason.as_deref().unwrap_or("")
            );
        }
    }
    let _ = writeln!(out);
    let others: Vec<&MutantResult> = r.mutants.iter().filter(|m| m.status != KillStatus::Killed).collect();
    if !others.is_empty() {
        let _ = writeln!(out, "## Mutants not killed\n");
        for m in others {
            survivor(&mut out, m);
        }
    }
    let _ = writeln!(out, "## Definitions\n");
    let _ = writeln!(
        out,
        "- A **mutant** is the soft unit (`shadowcheck-soft`) with one `Fault` switched on (`SoftUnit::with_fault`): a \
         switchable variant, not an edit of the source. Every case is sampled in process on every API path of the case \
         and judged against the expectation stored in the fixture, as `shadowcheck run --backend soft` judges it."
    );
    let _ = writeln!(
        out,
        "- **Killed**: at least one test is Fail (outside the `lenient` acceptance set, or the mutant refuses a lookup \
         the correct unit answers). **Warn-only**: no Fail, at least one Warn (inside `lenient`, outside `strict`); a weaker \
         kill, not counted in the score. **Survived**: every test passes. Tests the correct unit itself fails are not \
         counted against a mutant."
    );
    let _ = writeln!(
        out,
        "- **Minimal killing case**: among the killing cases, the smallest by (texels over all levels and layers, mip \
         levels, API paths, id length, id). **First killing case**: the first killing case in fixture order."
    );
    let _ = writeln!(
        out,
        "- **Unobservable**: a mutant not killed whose fault no conforming application can tell from the correct unit \
         (the reason is documented in runner/src/mutants/mod.rs `unobservable` and stands only while the oracle accepts \
         the fault's witness). The observable score leaves these out."
    );
    let _ = writeln!(
        out,
        "- **Baseline**: the correct unit over the same tests; it must have no Fail, or the command exits non-zero."
    );
    out
}
