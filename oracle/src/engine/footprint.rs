//! Phase "compare / combine" as the spec itself reads it: the texels of the spec's own scenario with
//! their exact weights, their comparison outcomes (the footprint and one derivation step per texel),
//! and the citations of the comparison and filtering rules used.

use super::Eval;
use crate::accept::{self, Scen};
use crate::rules::{Filtering, Rules};
use crate::sample::{Key, Kind, TexelCtx, TexelEval};
use crate::Step;
use shadowcheck_model::{Footprint, FootprintTexel, Format};

/// The footprint of the spec's own scenario; adds a step per texel and the citations.
pub(super) fn footprint(
    e: &mut Eval,
    rules: &Rules,
    tcx: &TexelCtx,
    spec_scen: &Scen,
    texels: &[TexelEval],
) -> Footprint {
    let kind = tcx.kind;
    let w = accept::weights(spec_scen);
    let mut fp = Footprint {
        dref: tcx.dref,
        texels: Vec::with_capacity(w.len()),
    };
    let (mut passes, mut fails) = (0, 0);
    for &(i, weight) in &w {
        let t = &texels[i];
        if let (Some(u), true) = (t.undefined, weight > 0.0) {
            e.note(u);
        }
        if weight > 0.0 {
            match t.pass {
                Some(true) => passes += 1,
                Some(false) => fails += 1,
                None => {}
            }
        }
        let (level, xyz) = match t.key {
            Key::Texel { level, x, y, layer } => (level, Some([x as u32, y as u32, layer as u32])),
            Key::Border { level } | Key::Corner { level, .. } => (level, None),
        };
        // Either outcome within the strictest profile: no single pass/fail to show.
        let either = t.strictest().two;
        let pass = if kind == Kind::Compare && !either {
            t.pass
        } else {
            None
        };
        fp.texels.push(FootprintTexel {
            level,
            xyz,
            stored: t.stored,
            dt: t.dt,
            pass,
            weight,
        });
        e.steps.push(Step {
            what: texel_step(t, kind, tcx.dref, either, weight),
            cite: rules.table_cite.to_string(),
        });
    }
    if kind == Kind::Compare {
        e.cite(rules.table_cite);
    }
    e.cite("GL 4.6 §8.14.2");
    if matches!(tcx.case.texture.format, Format::D32f | Format::D32fS8) {
        e.cite("GL 4.6 §8.5 (depth upload clamped to [0,1])");
    } else {
        e.cite("GL 4.6 §2.3.5.1 (2.1)");
    }
    if spec_scen.filtered() && kind == Kind::Compare {
        e.cite(rules.filter_cite);
        if rules.filtering == Filtering::ImplementationDependent && passes > 0 && fails > 0 {
            e.note(format!("filtered r is implementation-dependent, \"proportional to the number of comparison passes or failures\" ({}); the spec value is the bilinear-weighted fraction", rules.filter_cite));
        }
    }
    fp
}

/// One texel's derivation step.
fn texel_step(t: &TexelEval, kind: Kind, dref: f64, either: bool, weight: f64) -> String {
    match kind {
        Kind::Compare => format!(
            "{}: stored {} → Dt = {}; Dref {} vs Dt → {} (weight {})",
            t.key,
            t.stored,
            t.dt,
            dref,
            match (t.pass, either) {
                (_, true) if t.undefined.is_some() =>
                    "either (the texel's value is left to the implementation)".to_string(),
                (_, true) => "either (within reference precision)".to_string(),
                (Some(p), _) =>
                    if p {
                        "pass".to_string()
                    } else {
                        "fail".to_string()
                    },
                (None, _) => "unordered".to_string(),
            },
            weight
        ),
        _ => format!(
            "{}: stored {} → r = {} (weight {})",
            t.key, t.stored, t.dt, weight
        ),
    }
}
