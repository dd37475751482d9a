//! The expectation of a lookup as C constants (TEST, SPEC_VALUE, ACCEPTED, STRICT, the gather
//! values' sets, LAYOUTS and READINGS), shared by the GL and the Vulkan programs and read by
//! `verdict.c`.

use super::csource::layout_char;
use super::Subject;
use shadowcheck_model::{Acceptance, Channel, Expectation, Profile};
use std::fmt::Write;

/// A C `double` literal that reads back as exactly `v`.
pub(super) fn cd(v: f64) -> String {
    if v.is_nan() {
        "NAN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "INFINITY" } else { "-INFINITY" }.into()
    } else {
        format!("{v:?}")
    }
}

fn intervals(a: Option<&Acceptance>) -> (String, usize) {
    let v: Vec<String> = a
        .map(|a| {
            a.0.iter()
                .map(|i| format!("{{{}, {}}}", cd(i.lo), cd(i.hi)))
                .collect()
        })
        .unwrap_or_default();
    let n = v.len();
    // C has no empty initializer list: an empty set is one interval nothing lies in.
    let body = if v.is_empty() {
        "{1.0, 0.0}".to_string()
    } else {
        v.join(", ")
    };
    (format!("{{{body}}}"), n)
}

/// The expectation as C constants (shared with the Vulkan program: [`super::vulkan`]).
pub fn expectation(s: &Subject) -> String {
    let e = &s.expect;
    let (quality, nq) = intervals(e.accept.get(&Profile::loosest()));
    let (strict, ns) = intervals(e.accept.get(&Profile::strictest()));
    let chars = |l: &[Channel; 4]| {
        l.iter()
            .map(|c| format!("'{}'", layout_char(*c)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let layout: String = e
        .layout
        .get(&s.api)
        .map(chars)
        .unwrap_or_else(|| "'-', '-', '-', '-'".into());
    // The other readings of the layout the texts allow (`Expectation::other_layouts`): a result any
    // of them accepts is accepted, as shadowcheck's verdict does.
    let others: Vec<&shadowcheck_model::OtherLayout> =
        e.other_layouts.get(&s.api).into_iter().flatten().collect();
    let mut layouts = vec![format!("{{{layout}}}")];
    layouts.extend(others.iter().map(|o| format!("{{{}}}", chars(&o.layout))));
    let mut readings = vec!["\"the spec value's\"".to_string()];
    readings.extend(
        others
            .iter()
            .map(|o| format!("\"{}\"", o.reading.replace('"', "'"))),
    );
    let spec_value = e
        .spec_value
        .map(|v| format!("r = {v}"))
        .unwrap_or_else(|| "no single value".into());
    let show = |p: Profile| {
        e.accept
            .get(&p)
            .map(|a| a.to_string())
            .unwrap_or_else(|| "(none)".into())
    };
    let (gather, gather_strict) = (
        gather_sets(e, Profile::loosest()),
        gather_sets(e, Profile::strictest()),
    );
    format!(
        "/* Expected, from shadowcheck's oracle (`shadowcheck explain` shows the derivation). The accepted\n * set is what a conforming implementation may return for r (the `{q}` tier: outside it a \"shall\"\n * is violated); inside the `{st}` tier too is a plain pass. Layout per channel: 'r' the result,\n * '0'/'1' exactly that, 'z' r or 0, '-' not produced by this path, 'A'..'D' gather value 0..3 (a\n * textureGather's four comparisons, each judged by its own set in GATHER_ACCEPTED). */\nstruct set {{ const double (*v)[2]; int n; }};\nstatic const char *TEST = \"{test}\";\nstatic const char *SPEC_VALUE = \"{spec_value}\";\nstatic const char *ACCEPTED_TEXT = \"{qt}\";\nstatic const char *STRICT_TEXT = \"{stt}\";\nstatic const double ACCEPTED[][2] = {quality};\nstatic const int N_ACCEPTED = {nq};\nstatic const double STRICT[][2] = {strict};\nstatic const int N_STRICT = {ns};\n{gather}{gather_strict}static const char LAYOUT[4] = {{{layout}}};\n/* Every reading of the layout the texts allow, the spec value's first (READINGS names each). */\nstatic const char LAYOUTS[][4] = {{{layouts}}};\nstatic const char *READINGS[] = {{{readings}}};\nstatic const int N_LAYOUTS = {n_layouts};\n\n",
        q = Profile::loosest(),
        st = Profile::strictest(),
        test = s.test(),
        qt = show(Profile::loosest()).replace('"', "'"),
        stt = show(Profile::strictest()).replace('"', "'"),
        layouts = layouts.join(", "),
        readings = readings.join(", "),
        n_layouts = layouts.len(),
    )
}

/// A gather's four accepted sets under `p` as C (`GATHER_ACCEPTED` for the loosest tier,
/// `GATHER_STRICT` for the strictest), with `GATHER_TEXT` / `GATHER_STRICT_TEXT` (NULL for a
/// lookup that is no gather: its sets are empty and no layout reads them).
fn gather_sets(e: &Expectation, p: Profile) -> String {
    let name = if p == Profile::loosest() {
        "GATHER_ACCEPTED"
    } else {
        "GATHER_STRICT"
    };
    let mut out = String::new();
    let mut refs = vec![];
    let mut texts = vec![];
    for i in 0..4 {
        let acc = e.gather.as_ref().and_then(|g| g[i].get(&p));
        let (body, n) = intervals(acc);
        let _ = writeln!(out, "static const double {name}_{i}[][2] = {body};");
        refs.push(format!("{{{name}_{i}, {n}}}"));
        texts.push(
            acc.map(|a| a.to_string())
                .unwrap_or_else(|| "(none)".into()),
        );
    }
    let text = if e.gather.is_some() {
        format!("\"{}\"", texts.join(", ").replace('"', "'"))
    } else {
        "NULL".into()
    };
    let _ = writeln!(
        out,
        "static const struct set {name}[4] = {{{}}};\nstatic const char *{name}_TEXT = {text};",
        refs.join(", ")
    );
    out
}
