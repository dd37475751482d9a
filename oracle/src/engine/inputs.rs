//! Phase "prepare": which computation the lookup makes (comparison, r = Dt, colour, stencil), the
//! coordinates and Dref as the API passes them (projective divide, the spec's clamp, the values an
//! implementation may compare with) and the pass / fail values.

use super::Eval;
use crate::rules::{RefClamp, Rules};
use crate::sample::{Kind, TexelCtx};
use crate::unorm::{f32_candidates, f32r, Exact};
use shadowcheck_model::{Case, CompareFunc, CompareMode, DepthStencilMode, Sampler, Spec, Target};
use std::borrow::Cow;

/// The coordinates as the API passes them (f32) and the projective divisor q (1 when not projective).
pub(super) struct Coords {
    pub c: [f64; 4],
    pub q: f64,
}

/// GL 4.6 §8.2 (outside the spec pack, quoted from the specification).
const SAMPLER_STATE_REFUSED: &str = "GL 4.6 §8.2: \"If state is present in a sampler object bound to a texture unit that would have been rejected by a call to TexParameter* for the texture bound to that unit, the behavior of the implementation is as if the texture were incomplete.\"";

/// The state the lookup uses (the "effective" state): with a sampler object bound, its sampling
/// parameters replace the texture's (GL 4.6 §8.17.1, ES 3.2 §8.17.1), while DEPTH_TEXTURE_MODE,
/// DEPTH_STENCIL_TEXTURE_MODE, the swizzle, TEXTURE_MAX_LEVEL and the fail value remain texture
/// state (§8.2: not in Table 23.18); and the cube seamless rule of the context (§8.13.1: the
/// enable when the case sets it, otherwise the spec's default). The third value says why the
/// texture is incomplete when the sampler object holds state that TexParameter would refuse for the
/// bound texture, GL 4.6 §8.2: "If state is present in a sampler object bound to a texture unit that
/// would have been rejected by a call to TexParameter* for the texture bound to that unit, the
/// behavior of the implementation is as if the texture were incomplete" (its example: REPEAT wraps
/// on a rectangle texture).
pub(super) fn effective<'a>(
    e: &mut Eval,
    rules: Rules,
    case: &'a Case,
) -> (Cow<'a, Case>, Rules, Option<String>) {
    let mut rules = rules;
    if let (Some(on), Some(cite)) = (case.sampler.seamless, rules.seamless_enable) {
        rules.seamless_cube = on;
        if case.texture.target.is_cube() {
            let what = if on { "enabled" } else { "disabled" };
            e.step(format!("TEXTURE_CUBE_MAP_SEAMLESS {what}"), cite);
        }
    }
    let (Some(o), Some(cite)) = (&case.sampler.sampler_object, rules.sampler_objects) else {
        return (Cow::Borrowed(case), rules, None);
    };
    let t = &case.sampler;
    let s = Sampler {
        compare_mode: o.compare_mode,
        compare_func: o.compare_func,
        min_filter: o.min_filter,
        mag_filter: o.mag_filter,
        wrap_s: o.wrap_s,
        wrap_t: o.wrap_t,
        wrap_r: o.wrap_r,
        border: o.border,
        min_lod: o.min_lod,
        max_lod: o.max_lod,
        lod_bias: o.lod_bias,
        sampler_object: None,
        ..t.clone()
    };
    let mut changed = Vec::new();
    let mut diff = |name: &str, a: String, b: String| {
        if a != b {
            changed.push(format!("{name} {b} (texture: {a})"));
        }
    };
    diff(
        "compare mode",
        t.compare_mode.to_string(),
        s.compare_mode.to_string(),
    );
    diff(
        "compare func",
        t.compare_func.to_string(),
        s.compare_func.to_string(),
    );
    diff(
        "min filter",
        t.min_filter.to_string(),
        s.min_filter.to_string(),
    );
    diff(
        "mag filter",
        t.mag_filter.to_string(),
        s.mag_filter.to_string(),
    );
    diff("wrap s", t.wrap_s.to_string(), s.wrap_s.to_string());
    diff("wrap t", t.wrap_t.to_string(), s.wrap_t.to_string());
    diff("wrap r", t.wrap_r.to_string(), s.wrap_r.to_string());
    diff(
        "border",
        format!("{:?}", t.border),
        format!("{:?}", s.border),
    );
    diff("min lod", t.min_lod.to_string(), s.min_lod.to_string());
    diff("max lod", t.max_lod.to_string(), s.max_lod.to_string());
    diff("lod bias", t.lod_bias.to_string(), s.lod_bias.to_string());
    let list = if changed.is_empty() {
        "the same values as the texture".to_string()
    } else {
        changed.join(", ")
    };
    e.step(
        format!("a sampler object is bound: its sampling state is used: {list}"),
        cite,
    );
    let refused = (case.texture.target == Target::Rect)
        .then(|| crate::check::rect_rejects(&s))
        .flatten()
        .map(|why| {
            format!("the sampler object holds {why}, which TexParameter would refuse: the texture is treated as incomplete (GL 4.6 §8.2)")
        });
    if let Some(why) = &refused {
        e.step(why.clone(), SAMPLER_STATE_REFUSED);
    }
    let mut eff = case.clone();
    eff.sampler = s;
    (Cow::Owned(eff), rules, refused)
}

/// Which computation: §8.23.1 "If the base internal format is DEPTH_STENCIL and the value of
/// DEPTH_STENCIL_TEXTURE_MODE is STENCIL_INDEX, then r = St. Otherwise, if the value of
/// TEXTURE_COMPARE_MODE is NONE, then r = Dt."
pub(super) fn kind(e: &mut Eval, rules: &Rules, case: &Case) -> Kind {
    let s = &case.sampler;
    let fmt = case.texture.format;
    if !fmt.is_depth() {
        e.step(
            format!("format {fmt} is not a depth format: \"texture comparison is bypassed\", r = the colour value"),
            rules.table_cite,
        );
        if let Some(n) = rules.colour_note {
            e.note(n);
        }
        Kind::Colour
    } else if fmt.has_stencil() && s.depth_stencil_mode == Some(DepthStencilMode::StencilIndex) {
        e.step(
            "DEPTH_STENCIL texture with DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX: r = St".into(),
            "GL 4.6 §8.23.1, §8.16",
        );
        Kind::Stencil
    } else if s.compare_mode == CompareMode::None {
        e.step(
            "TEXTURE_COMPARE_MODE = NONE: r = Dt".into(),
            rules.table_cite,
        );
        Kind::Depth
    } else {
        Kind::Compare
    }
}

/// A lookup whose result the text leaves undefined as a whole (every value r can take is accepted,
/// labelled), with the sentence.
pub(super) fn undefined_request(rules: &Rules, case: &Case, kind: Kind) -> Option<&'static str> {
    let compare = case.sampler.compare_mode != CompareMode::None;
    match kind {
        // A stencil read goes through an unsigned integer (non-shadow) sampler.
        Kind::Stencil if compare => Some(
            "a stencil read with TEXTURE_COMPARE_MODE not NONE: GL 4.6 §11.1.3.5 \"the results of a texture lookup are undefined if ... The sampler used in a texture lookup function is not one of the shadow sampler types, the texture object's base internal format is DEPTH_COMPONENT or DEPTH_STENCIL, and the TEXTURE_COMPARE_MODE is not NONE\"",
        ),
        Kind::Colour if compare && matches!(rules.spec, Spec::Sgix | Spec::SgixAmbient) => Some(
            "SGIX_shadow's operators on a colour texture: \"These operators are defined only for textures with internal format DEPTH_COMPONENT or DEPTH_COMPONENTS*_SGI\" (SGIX_shadow, Notes); the result is left open",
        ),
        _ => None,
    }
}

/// Coordinates: "The API passes floats" (COMMON.md); projective: divided by q.
pub(super) fn coords(case: &Case) -> Coords {
    let c = case.lookup.coord.map(f32r);
    let q = if case.lookup.projective { c[3] } else { 1.0 };
    Coords { c, q }
}

/// Dref (divided, clamped per the spec, its candidates) and the pass / fail values: everything a
/// texel evaluation needs that does not depend on the texel.
pub(super) fn texel_ctx<'a>(
    e: &mut Eval,
    rules: &'a Rules,
    case: &'a Case,
    kind: Kind,
    co: &Coords,
) -> TexelCtx<'a> {
    let s = &case.sampler;
    let proj = case.lookup.projective;
    let q = co.q;
    let dref_in = f32r(case.lookup.dref);
    let dref_raw = dref_in / q;
    if proj {
        e.step(
            format!("projective: s, t, r and Dref divided by q = {q}; Dref = {dref_in} / {q} = {dref_raw}"),
            "GLSL 1.30 §8.7 textureProj / GL 4.6 §8.14.1",
        );
    }
    let fixed = case.texture.format.is_fixed_point();
    let clamp_ref = match rules.ref_clamp {
        RefClamp::Always => true,
        RefClamp::FixedPointOnly => fixed,
        RefClamp::Unstated => false,
    };
    let dref = if clamp_ref {
        dref_raw.clamp(0.0, 1.0)
    } else {
        dref_raw
    };
    let mut dref_cands: Vec<f64> = if proj {
        f32_candidates(Exact::F(dref_raw)).to_vec()
    } else {
        vec![dref_raw]
    };
    if dref_raw != 0.0 && dref_raw.abs() < f32::MIN_POSITIVE as f64 {
        // GLSL 4.60 §4.7.1: "Any denormalized value input into a shader or potentially generated by any
        // operation in a shader can be flushed to 0."
        dref_cands.push(0.0);
    }
    if rules.ref_clamp == RefClamp::Unstated {
        let clamped: Vec<f64> = dref_cands.iter().map(|d| d.clamp(0.0, 1.0)).collect();
        if !(0.0..=1.0).contains(&dref_raw) {
            e.note(format!(
                "{} leaves the clamping of the reference unstated ({}); both readings are accepted",
                rules.doc, rules.clamp_cite
            ));
        }
        dref_cands.extend(clamped);
    } else if clamp_ref {
        dref_cands.iter_mut().for_each(|d| *d = d.clamp(0.0, 1.0));
    }
    if kind == Kind::Compare {
        let how = match (rules.ref_clamp, clamp_ref) {
            (RefClamp::Unstated, _) => "not clamped (literal reading; clamped also accepted)",
            (_, true) => "clamped to [0,1]",
            (_, false) => "not clamped (floating-point depth format)",
        };
        e.step(
            format!("Dref = {dref_raw}: {how} → {dref}"),
            rules.clamp_cite,
        );
        if dref.is_nan() && !matches!(s.compare_func, CompareFunc::Always | CompareFunc::Never) {
            e.note("Dref is NaN: the comparison tables give no result for an unordered reference");
        }
    }
    let (pass_v, fail_v) = pass_fail_values(e, rules, case, kind);
    TexelCtx {
        case,
        rules,
        kind,
        func: s.compare_func,
        dref,
        dref_cands,
        pass_v,
        fail_v,
        component: 0,
    }
}

/// r for a passing and a failing texel: 1 and 0, or the fail / ambient value (clamped to [0,1]) in
/// place of 0 (in place of 1 under SGIX_shadow_ambient's overview reading, contradiction `sgix-ambient`).
fn pass_fail_values(e: &mut Eval, rules: &Rules, case: &Case, kind: Kind) -> (f64, f64) {
    let fail_v = if rules.fail_value_cite.is_some() {
        (case.sampler.fail_value.unwrap_or(0.0) as f64).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (pass_v, fail_v) = if rules.ambient_on_pass {
        (fail_v, 0.0)
    } else {
        (1.0, fail_v)
    };
    if let (Some(cite), Kind::Compare) = (rules.fail_value_cite, kind) {
        e.step(
            format!("fail value (clamped to [0,1]) = {fail_v}: replaces 0.0 for a failing texel"),
            cite,
        );
    }
    (pass_v, fail_v)
}
