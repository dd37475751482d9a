//! Shadow `textureGather*` (GL 4.6 / ES 3.2 §8.14.2, GLSL 4.60 / GLSL ES 3.20 §8.9.4): four
//! independent comparisons against the reference, one per texel of the LINEAR footprint on the
//! base level, returned in the order τi0j1, τi1j1, τi1j0, τi0j0. No filtering, no level of detail.
//!
//! The rule, verbatim: "The textureGather and textureGatherOffset built-in shader functions return
//! a vector derived from sampling a 2 × 2 block of texels in the texture image of level levelbase.
//! The rules for the LINEAR minification filter are applied to identify the four selected texels.
//! ... A four-component vector is then assembled by taking a single component from the swizzled
//! texture source colors of the four texels, in the order τi0j1, τi1j1, τi1j0, and τi0j0" (GL 4.6
//! §8.14.2); "For texture gather functions using a texture-combined shadow sampler type, each of the
//! four texel lookups perform a depth comparison against the depth reference value passed in
//! (refZ), and returns the result of that comparison in the appropriate component of the result
//! vector" (GLSL 4.60 §8.9.4); "When performing a texture gather operation, the minification and
//! magnification filters are ignored" (ibid.). textureGatherOffsets: "Each of the four texels is
//! obtained by applying the corresponding offset in the four-element array offsets as a (u,v)
//! coordinate offset to the coordinates coord, identifying the four-texel LINEAR footprint, and then
//! selecting the texel τi0j0 of that footprint" (GL 4.6 §8.14.2).

use super::{channels, geometry, inputs, Eval, Layouts};
use crate::accept::{self, Taps};
use crate::layout::GATHER_SWIZZLE;
use crate::lod::Pick;
use crate::profile::PROFILES;
use crate::rules::Rules;
use crate::sample::{Key, TexelCtx, TexelEval};
use crate::select::{build, Geo};
use crate::{Evaluation, Step};
use shadowcheck_model::{
    Acceptance, Case, Channel, Expectation, Footprint, FootprintTexel, Interval, KeyMap, Profile,
    Swizzle, Target,
};

/// The sentence of the rule, cited by every gather evaluation.
pub const GATHER_CITE: &str = "GL 4.6 / ES 3.2 §8.14.2 (textureGather: LINEAR footprint of level base, order τi0j1, τi1j1, τi1j0, τi0j0); GLSL 4.60 §8.9.4 (shadow gather: four comparisons against refZ, filters ignored)";
const OFFSETS_CITE: &str =
    "GL 4.6 / ES 3.2 §8.14.2 (textureGatherOffsets: τi0j0 of each offset's LINEAR footprint)";
const GATHER_SWIZZLE_CITE: &str = "GL 4.6 / ES 3.2 §8.14.2 (each texel converted by Table 15.1, then swizzled, §15.2.1; Figure 8.4: \"the post-swizzle R component\")";
const INCOMPLETE_CITE: &str = "GL 4.6 / ES 3.2 §8.14.2 (gather on an incomplete texture: source colour (0,0,0,1) for all four texels)";

/// Which texel of the 2x2 LINEAR footprint `Taps::Lin2([i0j0, i1j0, i0j1, i1j1])` each result
/// component takes: R = τi0j1, G = τi1j1, B = τi1j0, A = τi0j0.
pub const COMPONENT_TAP: [usize; 4] = [2, 3, 1, 0];
/// The components' texel names, for the derivation.
const COMPONENT_NAME: [&str; 4] = ["R = τi0j1", "G = τi1j1", "B = τi1j0", "A = τi0j0"];

/// The gather layout on every API path of the case. Each texel's comparison result Rt is expanded
/// to Cb = (Rt, 0, 0, 1) (§11.1.3.5) and swizzled (§15.2.1) before its R component is taken: "Each
/// texel is then converted to a texture source color (Rs,Gs,Bs,As) according to table 15.1 and then
/// swizzled as described in section 15.2.1" (GL 4.6 / ES 3.2 §8.14.2); Figure 8.4: "each component
/// is taken from the post-swizzle R component of the corresponding texel". So TEXTURE_SWIZZLE_R
/// alone decides: RED the comparison, GREEN / BLUE / ZERO 0, ALPHA / ONE 1. GLSL 4.60 §8.9.4 ("returns
/// the result of that comparison in the appropriate component of the result vector") can be read
/// without the swizzle: that reading (contradiction `gather-swizzle`) is accepted too. An incomplete
/// texture's texels are "considered to return a texture source color of (0.0, 0.0, 0.0, 1.0)": a
/// source colour, already swizzled, so its R is 0 whatever the swizzle.
fn gather_layouts(e: &mut Eval, rules: &Rules, case: &Case, incomplete: bool) -> Layouts {
    let mut layouts = Layouts::default();
    let sw_r = case
        .sampler
        .swizzle
        .filter(|_| rules.swizzle.is_some() && !incomplete)
        .map(|sw| sw[0]);
    for &api in &case.api {
        let main = match sw_r {
            None | Some(Swizzle::Red) => Channel::GATHER,
            Some(c) => {
                [c.pick(
                    [Channel::R, Channel::Zero, Channel::Zero, Channel::One],
                    Channel::Zero,
                    Channel::One,
                ); 4]
            }
        };
        e.step(
            format!(
                "layout on `{api}`: ({}), one comparison per component",
                channels(&main)
            ),
            GATHER_CITE,
        );
        if let Some(c) = sw_r.filter(|&c| c != Swizzle::Red) {
            e.step(
                format!(
                    "TEXTURE_SWIZZLE_R = {} takes each texel's post-swizzle R component from (Rt, 0, 0, 1)",
                    c.key()
                ),
                GATHER_SWIZZLE_CITE,
            );
        }
        let others = if main == Channel::GATHER {
            Vec::new()
        } else {
            vec![(GATHER_SWIZZLE, Channel::GATHER)]
        };
        layouts.add(api, main, others, e);
    }
    layouts
}

/// Evaluates a shadow gather. `incomplete`: why the texture is incomplete, if it is.
pub(super) fn run(
    mut e: Eval,
    rules: &Rules,
    case: &Case,
    incomplete: Option<String>,
) -> Evaluation {
    let kind = inputs::kind(&mut e, rules, case);
    let layouts = gather_layouts(&mut e, rules, case, incomplete.is_some());
    e.cite(GATHER_CITE);
    if let Some(why) = incomplete {
        e.step(
            format!("texture incomplete: {why}; each texel's source colour is (0,0,0,1), every component 0"),
            INCOMPLETE_CITE,
        );
        let zero = vec![Acceptance(vec![Interval::point(0.0)]); PROFILES.len()];
        return finish(
            e,
            [zero.clone(), zero.clone(), zero.clone(), zero],
            [Some(0.0); 4],
            layouts,
            Footprint::default(),
        );
    }
    let coords = inputs::coords(case);
    let tcx = inputs::texel_ctx(&mut e, rules, case, kind, &coords);
    let mut choices: Vec<&'static str> = Vec::new();
    e.step(
        "gather: the minification and magnification filters and the level of detail are ignored; the LINEAR rule on level base selects the texels".into(),
        GATHER_CITE,
    );
    let geos = geometry::geometries(&mut e, rules, case, &coords, true, &mut choices);
    let finite = geos.iter().all(|g| g.s.is_finite() && g.t.is_finite());
    let Some(&spec_geo) = geos.first().filter(|_| finite) else {
        e.note("the texture coordinates are not finite or the cube direction is zero: the texel selection is undefined");
        let p = tcx.open_outcome();
        let open = vec![Acceptance(vec![Interval::new(p.lo, p.hi)]); PROFILES.len()];
        return finish(
            e,
            [open.clone(), open.clone(), open.clone(), open],
            [None; 4],
            layouts,
            Footprint::default(),
        );
    };
    let mut texels: Vec<TexelEval> = Vec::new();
    // The spec's own texel per component.
    let spec_idx: [usize; 4] =
        std::array::from_fn(|k| component_texel(rules, case, &tcx, &mut texels, spec_geo, k));
    let spec_values: [Option<f64>; 4] = spec_idx.map(|i| texels[i].exact);
    let fp = footprint(&mut e, rules, &tcx, &spec_idx, &texels);
    // Per profile and component: every texel an implementation may select (each geometry, and the
    // coordinates off by the profile's weight / coordinate tolerance: a footprint boundary may go
    // either way), each with the results the profile allows for it.
    let tex = &case.texture;
    let (w0, h0) = match tex.levels.first() {
        Some(l0) if tex.target != Target::Rect => (l0.width as f64, l0.height as f64),
        _ => (1.0, 1.0),
    };
    let mut shifted_footprint = false;
    let mut sets: [Vec<Vec<Interval>>; 4] = Default::default();
    for (pi, prof) in PROFILES.iter().enumerate() {
        let tol = prof.coord_tol.max(prof.weight_tol);
        let mut out: [Vec<Interval>; 4] = Default::default();
        for g in &geos {
            for ds in [-1.0, 0.0, 1.0] {
                for dt in [-1.0, 0.0, 1.0] {
                    let g = Geo {
                        s: g.s + ds * tol / w0,
                        t: g.t + dt * tol / h0,
                        ..*g
                    };
                    for (k, o) in out.iter_mut().enumerate() {
                        let i = component_texel(rules, case, &tcx, &mut texels, g, k);
                        if pi == 0 && i != spec_idx[k] {
                            shifted_footprint = true;
                        }
                        let p = texels[i].poss[pi];
                        if p.two {
                            o.push(Interval::point(p.lo));
                            o.push(Interval::point(p.hi));
                        } else {
                            o.push(Interval::new(p.lo, p.hi));
                        }
                    }
                }
            }
        }
        for (k, o) in out.into_iter().enumerate() {
            sets[k].push(o);
        }
    }
    if shifted_footprint {
        choices.push("the coordinate sits within the weight precision of a LINEAR footprint boundary: either 2x2 block may be gathered (GL 4.6 §8.14.2, the precision of α, β)");
    }
    let range = (tcx.pass_v.min(tcx.fail_v), tcx.pass_v.max(tcx.fail_v));
    let mut k = 0;
    let acc: [Vec<Acceptance>; 4] = sets.map(|s| {
        let a = accept::finalize(s, None, false, range, spec_values[k]);
        k += 1;
        a
    });
    let all_points = acc
        .iter()
        .zip(spec_values)
        .all(|(a, v)| matches!((v, a.first()), (Some(v), Some(s)) if s.0 == [Interval::point(v)]));
    if !all_points {
        choices.into_iter().for_each(|n| e.note(n));
    }
    finish(e, acc, spec_values, layouts, fp)
}

/// The texel result component `k` takes for geometry `g`: τ of the LINEAR footprint on level base
/// (with the lookup's offset), or with `textureGatherOffsets` τi0j0 of component k's own footprint.
fn component_texel(
    rules: &Rules,
    case: &Case,
    tcx: &TexelCtx,
    texels: &mut Vec<TexelEval>,
    g: Geo,
    k: usize,
) -> usize {
    let pick = Pick::One {
        level: 0,
        linear: true,
    };
    let offsets = case.lookup.gather.as_ref().and_then(|x| x.offsets);
    let (scen, tap) = match offsets {
        Some(o) => {
            let mut c = case.clone();
            c.lookup.offset = [o[k][0], o[k][1], 0];
            (build(rules, &c, tcx, texels, g, pick), 0)
        }
        None => (build(rules, case, tcx, texels, g, pick), COMPONENT_TAP[k]),
    };
    match scen.a.1 {
        Taps::Lin2(t, _, _) => t[tap],
        // Gather targets are two-dimensional: `check` refuses the others.
        Taps::Lin1(t, _) => t[tap.min(1)],
        Taps::One(i) => i,
    }
}

/// The four texels of the spec's reading, one step each.
fn footprint(
    e: &mut Eval,
    rules: &Rules,
    tcx: &TexelCtx,
    idx: &[usize; 4],
    texels: &[TexelEval],
) -> Footprint {
    if tcx
        .case
        .lookup
        .gather
        .as_ref()
        .is_some_and(|g| g.offsets.is_some())
    {
        e.cite(OFFSETS_CITE);
    }
    e.cite(rules.table_cite);
    let mut fp = Footprint {
        dref: tcx.dref,
        texels: Vec::with_capacity(4),
    };
    for (k, &i) in idx.iter().enumerate() {
        let t = &texels[i];
        let either = t.strictest().two;
        let (level, xyz) = match t.key {
            Key::Texel { level, x, y, layer } => (level, Some([x as u32, y as u32, layer as u32])),
            Key::Border { level } | Key::Corner { level, .. } => (level, None),
        };
        fp.texels.push(FootprintTexel {
            level,
            xyz,
            stored: t.stored,
            dt: t.dt,
            pass: if either { None } else { t.pass },
            weight: 1.0,
        });
        let outcome = match (t.pass, either) {
            (_, true) => "either (within reference precision)",
            (Some(true), _) => "pass",
            (Some(false), _) => "fail",
            (None, _) => "unordered",
        };
        e.steps.push(Step {
            what: format!(
                "component {}: {}: stored {} → Dt = {}; Dref {} vs Dt → {outcome}",
                COMPONENT_NAME[k], t.key, t.stored, t.dt, tcx.dref
            ),
            cite: rules.table_cite.to_string(),
        });
    }
    fp
}

/// The evaluation: component 0 in `accept` / `spec_value`, all four in `gather`.
fn finish(
    e: Eval,
    acc: [Vec<Acceptance>; 4],
    spec_values: [Option<f64>; 4],
    layout: Layouts,
    footprint: Footprint,
) -> Evaluation {
    let maps: [KeyMap<Profile, Acceptance>; 4] =
        acc.map(|a| PROFILES.iter().map(|p| p.profile).zip(a).collect());
    let implementation_defined = if e.notes.is_empty() {
        None
    } else {
        Some(e.notes.join("; "))
    };
    Evaluation {
        expect: Expectation {
            spec_value: spec_values[0],
            accept: maps[0].clone(),
            layout: layout.main,
            other_layouts: layout.others,
            gather: Some(maps),
            implementation_defined,
            citations: e.cites,
        },
        footprint,
        steps: e.steps,
    }
}
