//! The review queue as Markdown: the units table, the classes table and one section per class.

use super::{front_end_of, lineage_of, CitationSource, Class, Entry, Queue};
use crate::records::ExpectedSummary;
use shadowcheck_protocol::Rgba;
use std::collections::{BTreeMap, BTreeSet};

/// An answer as `(r, g, b, a)`, unused channels as `-`.
fn rgba_text(v: &Rgba, compared: &str) -> String {
    let parts: Vec<String> = ['r', 'g', 'b', 'a']
        .iter()
        .zip(v.0)
        .map(|(c, x)| {
            if compared.contains(*c) {
                format!("{x}")
            } else {
                "-".to_string()
            }
        })
        .collect();
    format!("({})", parts.join(", "))
}

fn expected_text(e: &Option<ExpectedSummary>) -> String {
    let Some(e) = e else {
        return "(not recorded)".into();
    };
    let spec = e
        .spec_value
        .map(|v| format!("spec value {v}; "))
        .unwrap_or_default();
    format!(
        "{spec}quality {}, strict {}; layout {}",
        e.quality, e.strict, e.layout
    )
}

/// The first citation and how many follow (the class's section lists them all).
fn citations_brief(c: &[String]) -> String {
    match c {
        [] => "(none found)".into(),
        [one] => one.clone(),
        [first, rest @ ..] => format!("{first} (+{} more)", rest.len()),
    }
}

/// Markdown table cells may not hold `|` or line breaks.
fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace('\n', " ")
}

/// Appends `s` and a line break.
fn line(o: &mut String, s: &str) {
    o.push_str(s);
    o.push('\n');
}

/// The queue as Markdown.
pub fn markdown(q: &Queue) -> String {
    let mut o = String::new();
    intro(&mut o, q);
    units_table(&mut o, q);
    if q.is_empty() {
        line(&mut o, "No test on the queue.");
        return o;
    }
    classes_table(&mut o, q);
    for (i, c) in q.classes.iter().enumerate() {
        class_section(&mut o, i + 1, c);
    }
    o
}

/// The title, what the queue holds, and its inputs and size.
fn intro(o: &mut String, q: &Queue) {
    line(o, "# Oracle review queue\n");
    line(
        o,
        &format!(
            "Tests where at least {} independent texture units return the same answer and the oracle \
             rejects it (outcome Fail). When independent implementations agree against the oracle, \
             suspect the oracle first: start from the sentences cited.\n",
            q.min_units
        ),
    );
    line(
        o,
        &format!(
            "- inputs: {}\n- answers agree when every compared channel differs by at most 2^-16 \
             (the `quality` reference precision); channels the layout marks unused (`-`) are not \
             compared\n- only results that carry an observed value are compared: Fail and Warn \
             (passes only under `run --full-report`); a unit whose backends passed a test supports \
             no rejected answer\n- {} tests had a comparable answer; {} are on the queue, in {} \
             classes (same grid family and citations)\n",
            q.runs.join(", "),
            q.tests_compared,
            q.len(),
            q.classes.len()
        ),
    );
}

/// The units table (one row per texture unit, its backends and why they share code) and the
/// note on shared front ends under it.
fn units_table(o: &mut String, q: &Queue) {
    line(
        o,
        "## Units (backends that share texture-unit code count once)\n",
    );
    line(
        o,
        "| unit | backends | API front ends | why they share code |\n|---|---|---|---|",
    );
    let mut units: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (b, u) in &q.backends {
        units.entry(u).or_default().push(b);
    }
    for (u, bs) in &units {
        let mut why: Vec<&str> = bs
            .iter()
            .filter_map(|b| lineage_of(b).map(|l| l.why))
            .collect();
        why.dedup();
        let why = if why.is_empty() {
            "its own unit (no shared lineage known)".to_string()
        } else {
            why.join("; ")
        };
        let names: Vec<String> = bs.iter().map(|b| format!("`{}`", cell(b))).collect();
        let fronts: BTreeSet<String> = bs.iter().map(|b| front_end_of(b)).collect();
        let fronts: Vec<String> = fronts.into_iter().collect();
        line(
            o,
            &format!(
                "| {} | {} | {} | {} |",
                cell(u),
                names.join(", "),
                cell(&fronts.join(", ")),
                cell(&why)
            ),
        );
    }
    line(
        o,
        "\nUnits are independent in their sampling code. Several Mesa drivers share Mesa's GL front \
         end (state validation, completeness, DEPTH_TEXTURE_MODE routing, fixed function): an \
         entry whose answer comes through one front end only (column `front ends`) is first a \
         suspected shared front-end defect, then a suspected oracle error.\n",
    );
}

/// The classes table: one row per class.
fn classes_table(o: &mut String, q: &Queue) {
    line(o, "## Classes\n");
    line(
        o,
        "| # | grid family | tests | front ends | citations |\n|---:|---|---:|---|---|",
    );
    for (i, c) in q.classes.iter().enumerate() {
        let fronts: BTreeSet<&str> = c
            .tests
            .iter()
            .flat_map(|e| e.front_ends.iter().map(|f| f.as_str()))
            .collect();
        line(
            o,
            &format!(
                "| {} | `{}` | {} | {} | {} |",
                i + 1,
                cell(&c.family),
                c.tests.len(),
                cell(&fronts.into_iter().collect::<Vec<_>>().join(", ")),
                cell(&citations_brief(&c.citations))
            ),
        );
    }
}

/// The section of class number `number`: its citations, then one row per test.
fn class_section(o: &mut String, number: usize, c: &Class) {
    let n = c.tests.len();
    line(
        o,
        &format!(
            "\n## Class {}: `{}`: {n} test{}, one cause?\n",
            number,
            c.family,
            if n == 1 { "" } else { "s" }
        ),
    );
    line(o, "The oracle's sentences:\n");
    if c.citations.is_empty() {
        let why = match c.tests.first().map(|e| &e.citations_from) {
            Some(CitationSource::Missing(w)) => w.clone(),
            _ => String::new(),
        };
        line(o, &format!("- (no citations found: {why})"));
    }
    for s in &c.citations {
        line(o, &format!("- {s}"));
    }
    if let Some(CitationSource::Fixtures(f)) = c.tests.first().map(|e| &e.citations_from) {
        line(
            o,
            &format!("\n(citations from the case in {f}; the records had none)"),
        );
    }
    line(o, "\n| test | agreed answer (r, g, b, a) | units: backends | front ends | oracle expected |\n|---|---|---|---|---|");
    for e in &c.tests {
        line(o, &test_row(e));
    }
}

/// One test's row in its class's table.
fn test_row(e: &Entry) -> String {
    let units: Vec<String> = e
        .units
        .iter()
        .map(|u| {
            let bs: Vec<String> = u
                .backends
                .iter()
                .map(|b| format!("`{}` ({})", cell(&b.backend), b.outcome))
                .collect();
            match u.backends.as_slice() {
                // A unit of its own: the backend names it.
                [b] if b.backend == u.unit => bs.join(", "),
                _ => format!("{}: {}", cell(&u.unit), bs.join(", ")),
            }
        })
        .collect();
    format!(
        "| `{}` | {} | {} | {} | {} |",
        cell(&e.test),
        rgba_text(&e.answer, &e.compared),
        units.join("<br>"),
        cell(&e.front_ends.join(", ")),
        cell(&expected_text(&e.expected))
    )
}
