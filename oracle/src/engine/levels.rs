//! Phases "levels" and "acceptance": the level of detail (§8.14.1) and the level picks (§8.14.3,
//! §8.15), then, per precision profile, every way the lookup may be carried out (geometry ×
//! coordinate shift × pick) filtered and combined into that profile's intervals.

use super::Eval;
use crate::accept;
use crate::lod::{self, Lambda, Pick};
use crate::profile::PROFILES;
use crate::rules::{Filtering, Rules};
use crate::sample::{Kind, TexelCtx, TexelEval};
use crate::select::{build, Geo};
use crate::unorm::f32r;
use shadowcheck_model::{Case, Interval, Target};

/// The level of detail of the lookup: λ with its range, the number of levels past the base and the
/// spec's own pick.
pub(super) struct Lod {
    pub lam: Lambda,
    pub q_rel: u32,
    pub spec_pick: Pick,
    /// Picks another reading of the texts accepts too (`stage::other_picks`).
    pub other: Vec<Pick>,
}

/// λ and the spec's pick of levels.
pub(super) fn lod(e: &mut Eval, rules: &Rules, case: &Case) -> Lod {
    let s = &case.sampler;
    let tex = &case.texture;
    let texobj_bias = if rules.lod_bias {
        s.lod_bias as f64
    } else {
        0.0
    };
    let (lod_base, shader_bias) = super::stage::lambda_inputs(e, case);
    let lam = lod::lambda(f32r(lod_base), texobj_bias, f32r(shader_bias), s);
    if let Some(n) = lam.note {
        e.note(n);
    }
    let q_rel = if s.min_filter.is_mipmap() {
        lod::q_rel(tex, s).unwrap_or(0)
    } else {
        0
    };
    let spec_lambda = if lam.spec.is_nan() {
        lam.lo.max(0.0).min(q_rel as f64)
    } else {
        lam.spec
    };
    let mut spec_pick = lod::spec_pick(s, spec_lambda, q_rel);
    e.step(
        format!(
            "λ = {} (λ_base {} + biases, clamped to [{}, {}]) → {}",
            lam.spec,
            f32r(lod_base),
            s.min_lod,
            s.max_lod,
            describe_pick(spec_pick, lam.spec)
        ),
        "GL 4.6 §8.14.1, §8.14.3 (8.14)-(8.16), §8.15",
    );
    let other = super::stage::other_picks(e, rules, case, spec_pick);
    if rules.non_fragment_base_texture {
        if let Some(&b) = other.first() {
            spec_pick = b;
        }
    }
    Lod {
        lam,
        q_rel,
        spec_pick,
        other,
    }
}

fn describe_pick(p: Pick, l: f64) -> String {
    let f = |lin: bool| if lin { "LINEAR" } else { "NEAREST" };
    match p {
        Pick::One { level, linear } => format!(
            "level base+{level}, {} ({})",
            f(linear),
            if l <= 0.0 {
                "magnification"
            } else {
                "minification"
            }
        ),
        Pick::Two {
            d1,
            d2,
            linear,
            f: w,
            ..
        } => format!(
            "levels base+{d1} and base+{d2}, {} each, blended with frac(λ) = {w}",
            f(linear)
        ),
    }
}

/// GL 4.6 §8.23.1 (ES 3.2 §8.20.1, ARB_shadow, EXT_shadow_samplers): "If the value of
/// TEXTURE_MAG_FILTER is not NEAREST, or the value of TEXTURE_MIN_FILTER is not NEAREST or
/// NEAREST_MIPMAP_NEAREST, then r may be computed by comparing more than one depth texture value to the
/// texture reference value." The condition is on the filter *state*, not on the filter the lookup
/// ends up using (min NEAREST + mag LINEAR while minified may still return a PCF value).
pub(crate) fn multi_texel_state(s: &shadowcheck_model::Sampler) -> bool {
    use shadowcheck_model::Filter;
    s.mag_filter != Filter::Nearest
        || !matches!(s.min_filter, Filter::Nearest | Filter::NearestMipmapNearest)
}

/// The same levels filtered LINEAR within each level, for a NEAREST pick (`None` if already LINEAR).
fn as_linear(p: Pick) -> Option<Pick> {
    match p {
        Pick::One {
            level,
            linear: false,
        } => Some(Pick::One {
            level,
            linear: true,
        }),
        Pick::Two {
            d1,
            d2,
            linear: false,
            f,
            f_lo,
            f_hi,
        } => Some(Pick::Two {
            d1,
            d2,
            linear: true,
            f,
            f_lo,
            f_hi,
        }),
        _ => None,
    }
}

/// The intervals each profile accepts (in `PROFILES` order), before `accept::finalize`. Texels are
/// evaluated once and cached in `texels`. A level-selection boundary under the strictest profile is
/// recorded in `choices`.
pub(super) fn profile_intervals(
    rules: &Rules,
    tcx: &TexelCtx,
    geos: &[Geo],
    lod: &Lod,
    texels: &mut Vec<TexelEval>,
    choices: &mut Vec<&'static str>,
) -> Vec<Vec<Interval>> {
    let case = tcx.case;
    let s = &case.sampler;
    let tex = &case.texture;
    let should_proportional =
        tcx.kind == Kind::Compare && rules.filtering == Filtering::ImplementationDependent;
    // Coordinates off by up to coord_tol texels of the base level (a NEAREST boundary may go either way).
    let (w0, h0) = match tex.levels.first() {
        Some(l0) if tex.target != Target::Rect => (l0.width as f64, l0.height as f64),
        _ => (1.0, 1.0),
    };
    let mut many_picks = false;
    let mut multi_texel = false;
    let mut sets = Vec::with_capacity(PROFILES.len());
    for (pi, prof) in PROFILES.iter().enumerate() {
        let mut out = Vec::new();
        let mut picks = Vec::new();
        lod::picks(
            s,
            lod.lam.lo - prof.lod_tol,
            lod.lam.hi + prof.lod_tol,
            lod.q_rel,
            &mut picks,
        );
        if pi == 0 && picks.len() > 1 {
            many_picks = true;
        }
        let extra: Vec<Pick> = lod
            .other
            .iter()
            .copied()
            .filter(|p| !picks.contains(p))
            .collect();
        picks.extend(extra);
        if should_proportional && multi_texel_state(s) {
            let nearest: Vec<Pick> = picks.iter().filter_map(|p| as_linear(*p)).collect();
            if !nearest.is_empty() {
                multi_texel = true;
                picks.extend(nearest);
            }
        }
        let shifts: &[f64] = if prof.coord_tol > 0.0 {
            &[-1.0, 0.0, 1.0]
        } else {
            &[0.0]
        };
        for g in geos {
            for ds in shifts {
                for dt in shifts {
                    let g = Geo {
                        s: g.s + ds * prof.coord_tol / w0,
                        t: g.t + dt * prof.coord_tol / h0,
                        ..*g
                    };
                    for p in &picks {
                        let sc = build(rules, case, tcx, texels, g, *p);
                        accept::scen_intervals(
                            &sc,
                            texels,
                            pi,
                            prof,
                            should_proportional,
                            &mut out,
                        );
                    }
                }
            }
        }
        sets.push(out);
    }
    if multi_texel {
        choices.push("the filter state is not all NEAREST, so \"r may be computed by comparing more than one depth texture value\" even where this lookup filters NEAREST: the LINEAR footprint's results are accepted too (GL 4.6 §8.23.1, ES 3.2 §8.20.1)");
    }
    if many_picks {
        choices.push("the level of detail sits on a level-selection boundary: nearest(λ) preferred/alternative or the bias clamp lets either level be used (GL 4.6 §8.14.3)");
    }
    sets
}
