//! How attributions are shown: report.md's "Layer attribution" section, the counts per backend
//! and layer, the failure classes (one row per reason, largest first) and the Markdown table of
//! `attribute --markdown`. What a failure's layer is stays in the parent module.

use super::{attribute, layering_of, Attribution, Counterpart, Layer};
use crate::records::{Outcome, Results, TestResult};
use shadowcheck_model::{Case, Spec};
use std::collections::{BTreeMap, HashMap};

/// report.md's "Layer attribution" section, when the run holds a layered backend with failures
/// and the Vulkan driver under it; the cases are the run's own (`None`: no section).
pub fn report_section(
    results: &[TestResult],
    backends: &[String],
    loaded: Option<&crate::run::CaseSet>,
) -> Option<String> {
    let paired = |b: &String| layering_of(b).is_some_and(|l| backends.iter().any(|x| x == l.lower));
    let failing: std::collections::HashSet<&str> = results
        .iter()
        .filter(|r| paired(&r.backend) && matches!(r.outcome, Outcome::Fail | Outcome::Warn))
        .map(|r| r.case_id.as_str())
        .collect();
    if failing.is_empty() {
        return None;
    }
    // The failing cases and the Vulkan ones: all the attribution reads.
    let cases: HashMap<String, Case> = loaded?
        .cases
        .iter()
        .filter(|l| l.case.spec == Spec::Vulkan || failing.contains(l.case.id.as_str()))
        .map(|l| (l.case.id.clone(), l.case.clone()))
        .collect();
    let mut all = Results::default();
    for r in results {
        all.insert(r.clone());
    }
    let rows: Vec<Attribution> = attribute(&all, &cases)
        .into_iter()
        .filter(|r| backends.iter().any(|b| b == r.lower))
        .collect();
    let mut s = markdown(&rows).replacen("# Layer attribution", "## Layer attribution", 1);
    s = s.replacen(
        "\n\n",
        "\n\nEach Fail and Warn of a layered backend against the lower layer's answer in this run: the Vulkan driver's to the same lookup, or, under ANGLE's OpenGL ES back end, the OpenGL ES driver's to the same test (`shadowcheck attribute`, runner/README.md).\n\n",
        1,
    );
    Some(s)
}

/// Counts per (upper backend, layer).
pub fn tally(rows: &[Attribution]) -> BTreeMap<(String, Layer), usize> {
    let mut m = BTreeMap::new();
    for r in rows {
        *m.entry((r.backend.clone(), r.layer)).or_insert(0) += 1;
    }
    m
}

/// A failure class: the same backend, layer and reason once the case ids, formats and values in
/// the reason are left out.
fn class_of(r: &Attribution) -> (String, Layer, String) {
    static MASKS: std::sync::OnceLock<Vec<(regex::Regex, &'static str)>> =
        std::sync::OnceLock::new();
    let masks = MASKS.get_or_init(|| {
        [
            (r"`[^`]*`", "`…`"),
            (r"r = [-+0-9.e]+|r = \?", "r = …"),
            (r"upper: [-+0-9.e]+|upper: \?", "upper: …"),
            (r"here is [^,]+, GL's [^:]+:", "here differs from GL's:"),
            (r"has \d+ of the \d+ sweep points", "has fewer sweep points"),
            (
                r"\(not mipmap complete: [^)]*\)\)?",
                "(not mipmap complete)",
            ),
        ]
        .into_iter()
        .filter_map(|(re, to)| regex::Regex::new(re).ok().map(|re| (re, to)))
        .collect()
    });
    let mut why = r.why.clone();
    for (re, to) in masks {
        why = re.replace_all(&why, *to).into_owned();
    }
    (r.backend.clone(), r.layer, why)
}

/// A failure class: its backend, layer and reason, how many tests, and the first of them.
#[derive(Debug, Clone)]
pub struct Class<'a> {
    pub backend: String,
    pub layer: Layer,
    pub why: String,
    pub tests: usize,
    pub example: &'a Attribution,
}

/// The failure classes of `rows`, per backend, largest first.
pub fn classes(rows: &[Attribution]) -> Vec<Class<'_>> {
    let mut m: BTreeMap<(String, Layer, String), (usize, &Attribution)> = BTreeMap::new();
    for r in rows {
        m.entry(class_of(r)).or_insert((0, r)).0 += 1;
    }
    let mut v: Vec<Class> = m
        .into_iter()
        .map(|((backend, layer, why), (tests, example))| Class {
            backend,
            layer,
            why,
            tests,
            example,
        })
        .collect();
    v.sort_by(|a, b| (&a.backend, b.tests).cmp(&(&b.backend, a.tests)));
    v
}

/// The Markdown report: the tally per backend and layer, then the failure classes (backend,
/// layer, reason), largest first, each with one example test.
pub fn markdown(rows: &[Attribution]) -> String {
    let mut s = String::from("# Layer attribution\n\n");
    if rows.is_empty() {
        s += "No failure of a layered backend (zink, WebGL on ANGLE) in the runs read.\n";
        return s;
    }
    s += "| backend | lower layer | upper | lower | both | no equivalent |\n|---|---|---:|---:|---:|---:|\n";
    let t = tally(rows);
    let mut backends: Vec<&str> = rows.iter().map(|r| r.backend.as_str()).collect();
    backends.sort();
    backends.dedup();
    for b in backends {
        let n = |l| t.get(&(b.to_string(), l)).copied().unwrap_or(0);
        let lower = layering_of(b).map_or("?", |l| l.lower);
        s += &format!(
            "| {b} | {lower} | {} | {} | {} | {} |\n",
            n(Layer::Upper),
            n(Layer::Lower),
            n(Layer::Both),
            n(Layer::NoEquivalent)
        );
    }
    s += "\nFailure classes (the reason with its case ids and values left out), largest first per backend; every failure is in the JSON output (`--json`).\n\n| backend | layer | tests | why | example (counterpart) |\n|---|---|---:|---|---|\n";
    for c in classes(rows) {
        s += &format!(
            "| {} | {} | {} | {} | `{}`{} |\n",
            c.backend,
            c.layer.as_str(),
            c.tests,
            c.why.replace('|', "\\|"),
            c.example.test,
            c.example
                .counterpart
                .as_deref()
                .map_or(String::new(), |v| format!(" (`{v}`)"))
        );
    }
    let confirm = |c: Counterpart| {
        rows.iter().any(|r| {
            matches!(r.layer, Layer::Lower | Layer::Both)
                && layering_of(&r.backend).is_some_and(|l| l.counterpart == c)
        })
    };
    if confirm(Counterpart::Vulkan) {
        s += "\nA lower or both class is the Vulkan driver's to confirm: `shadowcheck repro -b <lower layer> --case '<Vulkan counterpart>'` writes the standalone Vulkan program of the same lookup (runner/README.md, \"Reproducers\").\n";
    }
    if confirm(Counterpart::SameTest) {
        s += "\nUnder ANGLE's OpenGL ES back end a lower or both class is the OpenGL ES driver's to confirm: `shadowcheck repro -b <lower layer> --case '<counterpart>'` writes the standalone EGL + OpenGL ES program of the same test (runner/README.md, \"Reproducers\").\n";
    }
    s
}
