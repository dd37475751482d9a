//! Human-readable explanation of one evaluation (used by `shadowcheck explain` and failure dumps):
//! spec value, acceptance per profile, layouts, derivation with citations, footprint and the
//! contradictions the case touches with the value under the other reading. No I/O: returns text.

use crate::profile::spec_of;
use crate::{contradictions, evaluate_reading, Evaluation, OracleError};
use shadowcheck_model::{Case, Channel};
use std::fmt::Write;

fn fmt_value(v: Option<f64>) -> String {
    match v {
        Some(v) => format!("{v}"),
        None => "none (the spec gives no single value)".into(),
    }
}

/// One line summing up an evaluation under some reading (value and strict set), or its error.
pub fn summary(r: &Result<Evaluation, OracleError>) -> String {
    match r {
        Ok(e) => {
            let strict = e
                .expect
                .accept
                .get(&shadowcheck_model::Profile::Strict)
                .map(|a| a.to_string())
                .unwrap_or_default();
            format!(
                "r = {}, strict accepts {}",
                fmt_value(e.expect.spec_value),
                strict
            )
        }
        Err(e) => format!("{e}"),
    }
}

/// The full text explanation of `case` given its evaluation.
pub fn render(case: &Case, result: &Result<Evaluation, OracleError>) -> String {
    let mut o = String::new();
    let s = &case.sampler;
    let _ = writeln!(o, "case {}", case.id);
    let _ = writeln!(
        o,
        "  spec {} | target {} | format {} | compare {} {} | filter min {} mag {} | wrap {},{},{} | Dref {}{}",
        case.spec,
        case.texture.target,
        case.texture.format,
        s.compare_mode,
        s.compare_func,
        s.min_filter,
        s.mag_filter,
        s.wrap_s,
        s.wrap_t,
        s.wrap_r,
        case.lookup.dref,
        if case.lookup.projective { " (projective)" } else { "" }
    );
    match result {
        Err(e) => {
            let _ = writeln!(o, "\nno lookup: {e}");
        }
        Ok(ev) => {
            let x = &ev.expect;
            let _ = writeln!(o, "\nspec value: r = {}", fmt_value(x.spec_value));
            let _ = writeln!(o, "acceptance:");
            for (p, acc) in &x.accept {
                let _ = writeln!(
                    o,
                    "  {:<8} {}    [{}]",
                    p.key(),
                    acc,
                    spec_of(*p).map(|s| s.describe()).unwrap_or_default()
                );
            }
            if let Some(g) = &x.gather {
                let _ = writeln!(
                    o,
                    "gather components (g0 τi0j1, g1 τi1j1, g2 τi1j0, g3 τi0j0; r above is g0):"
                );
                for (k, m) in g.iter().enumerate() {
                    let sets: Vec<String> =
                        m.iter().map(|(p, a)| format!("{} {a}", p.key())).collect();
                    let _ = writeln!(o, "  g{k}       {}", sets.join(", "));
                }
            }
            if let Some(why) = &x.implementation_defined {
                let _ = writeln!(o, "implementation-defined: {why}");
            }
            let _ = writeln!(o, "layout (channel: r / 0 / 1 / - unused / r|0 r or 0):");
            for (api, l) in &x.layout {
                let l: Vec<&str> = l.iter().map(|c: &Channel| c.key()).collect();
                let _ = writeln!(o, "  {:<8} ({})", api.key(), l.join(", "));
                for other in x.other_layouts.get(api).into_iter().flatten() {
                    let l: Vec<&str> = other.layout.iter().map(|c| c.key()).collect();
                    let _ = writeln!(
                        o,
                        "  {:<8} ({})   also accepted: the other reading, contradiction `{}`",
                        "",
                        l.join(", "),
                        other.reading
                    );
                }
            }
            let _ = writeln!(o, "derivation:");
            for (i, st) in ev.steps.iter().enumerate() {
                let _ = writeln!(o, "  {:>2}. {}\n      [{}]", i + 1, st.what, st.cite);
            }
            if !ev.footprint.texels.is_empty() {
                let _ = writeln!(o, "footprint (Dref = {}):", ev.footprint.dref);
                let _ = writeln!(
                    o,
                    "  {:<6} {:<16} {:>14} {:>22} {:>7} {:>10}",
                    "level", "x,y,layer", "stored", "Dt", "pass", "weight"
                );
                for t in &ev.footprint.texels {
                    let xyz = t
                        .xyz
                        .map(|v| format!("{},{},{}", v[0], v[1], v[2]))
                        .unwrap_or_else(|| "border".into());
                    let pass = match t.pass {
                        Some(true) => "1",
                        Some(false) => "0",
                        None => "either",
                    };
                    let _ = writeln!(
                        o,
                        "  {:<6} {:<16} {:>14} {:>22} {:>7} {:>10}",
                        t.level, xyz, t.stored, t.dt, pass, t.weight
                    );
                }
            }
            let _ = writeln!(o, "citations: {}", x.citations.join("; "));
        }
    }
    let mut touched = contradictions::touching(case);
    if let Err(OracleError::GlError { .. }) = result {
        if let Some(c) = contradictions::get("bad-operator-error") {
            touched.push(c);
        }
    }
    if !touched.is_empty() {
        let _ = writeln!(o, "where the documents disagree:");
        for c in touched {
            let _ = writeln!(o, "  [{}] {}", c.id, c.title);
            let _ = writeln!(o, "    encoded: {}", c.defended);
            let _ = writeln!(o, "    other:   {}", c.other);
            if let Some(alt) = evaluate_reading(case, c.id) {
                let _ = writeln!(o, "    under the other reading: {}", summary(&alt));
            }
            let _ = writeln!(o, "    sources: {}", c.sources);
        }
    }
    o
}
