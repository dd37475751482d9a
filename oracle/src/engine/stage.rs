//! The shader stage of the lookup ([`Stage`]). Outside the fragment stage there are no implicit
//! derivatives, and the texts give the level of detail in two sentences that do not always agree:
//!
//! - reading A, GLSL 4.60 / GLSL ES 3.20 §8.9: "level-of-detail is implicitly computed only for
//!   fragment shaders. Other shaders operate as though the base level-of-detail were computed as
//!   zero." λ_base = 0, then the usual pipeline of GL 4.6 / ES 3.2 §8.14.1 and §8.14.3 (the
//!   texture's TEXTURE_LOD_BIAS, the MIN_LOD / MAX_LOD clamp, magnification for λ ≤ c, else
//!   minification). The spec value follows it.
//! - reading B, the same section's next paragraph (GLSL 1.20 / 1.30 §8.7, GLSL ES 3.00 §8.8 have
//!   only this one): "If it is mipmapped and running in a non-fragment shader, then the base
//!   texture is used." level_base, whatever the biases and clamps; the sentence names the level
//!   and not the filter within it, so both the magnification filter (what λ = 0 would pick) and
//!   the minification filter's filtering within a level (the mipmapped filter with its level
//!   fixed) are accepted.
//!
//! Both are accepted and named (contradiction `non-fragment-base-texture`); `Rules::non_fragment_base_texture`
//! is reading B as the spec value, for `explain`.

use super::Eval;
use crate::lod::Pick;
use crate::rules::Rules;
use shadowcheck_model::{ApiPath, Case, Filter, Sampler, Stage};

/// The contradiction's id.
pub(super) const READING: &str = "non-fragment-base-texture";

/// The section that says "as though the base level-of-detail were computed as zero" (reading A):
/// GLSL 4.60 §8.9, GLSL ES 3.20 §8.9 (the earlier languages say only that it is not computed;
/// GLSL 4.60 is also the language of Vulkan's shaders, GL_KHR_vulkan_glsl). WGSL has no implicit
/// level of detail outside the fragment stage: its lookup there is textureSampleCompareLevel,
/// which "always samples texels from mip level 0" (or a gather, which reads level 0 anyway).
fn cite_a(case: &Case) -> &'static str {
    match case.spec {
        shadowcheck_model::Spec::Gles32 => "GLSL ES 3.20 §8.9",
        shadowcheck_model::Spec::WebGpu => "WGSL textureSampleCompareLevel",
        _ => "GLSL 4.60 §8.9",
    }
}

/// The sections of the case's paths' languages that say "the base texture is used" (reading B).
fn cite_b(case: &Case) -> String {
    // A compute shader exists from GLSL 4.30 and GLSL ES 3.10 on: the languages' current texts.
    let compute = case.lookup.stage == Stage::Compute;
    let mut v: Vec<&str> = case
        .api
        .iter()
        .map(|a| match a {
            ApiPath::Glsl120 => "GLSL 1.20 §8.7",
            ApiPath::Glsl130 => "GLSL 1.30 §8.7",
            ApiPath::Es300 if compute => "GLSL ES 3.20 §8.9",
            ApiPath::Es300 => "GLSL ES 3.00 §8.8, GLSL ES 3.20 §8.9",
            _ => "GLSL 4.60 §8.9",
        })
        .collect();
    v.dedup();
    v.join("; ")
}

/// λ_base and the shader bias the lookup gets: the case's in the fragment stage; (0, 0) in any
/// other (reading A; no bias is accepted there, `shadowcheck_model::validate`), with a step.
pub(super) fn lambda_inputs(e: &mut Eval, case: &Case) -> (f64, f64) {
    let l = &case.lookup;
    if l.stage == Stage::Fragment {
        return (l.lod, l.bias);
    }
    let sentence = if case.spec == shadowcheck_model::Spec::WebGpu {
        "the lookup is textureSampleCompareLevel, which \"always samples texels from mip level 0\""
    } else {
        "\"Other shaders operate as though the base level-of-detail were computed as zero\""
    };
    e.step(
        format!(
            "{} stage: {sentence}: λ_base = 0 (a fragment shader would compute {})",
            l.stage, l.lod
        ),
        cite_a(case),
    );
    (0.0, 0.0)
}

/// Whether the lookup meets the two readings: outside the fragment stage, on a mipmapped texture
/// ("If it is mipmapped and running in a non-fragment shader"; a texture that is not mipmapped
/// "is used directly", which both readings agree on).
pub(crate) fn touches(case: &Case) -> bool {
    case.lookup.stage != Stage::Fragment
        && case.lookup.gather.is_none()
        && case.sampler.in_effect().min_filter.is_mipmap()
}

/// Filtering within a level by the minification filter (`*_MIPMAP_*` name it first).
fn min_linear(s: &Sampler) -> bool {
    matches!(
        s.min_filter,
        Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear
    )
}

/// Reading B's picks: level_base filtered by the magnification filter or by the minification
/// filter within a level (the sentence says which level, not which filter).
pub(super) fn base_texture_picks(s: &Sampler) -> Vec<Pick> {
    let mag = Pick::One {
        level: 0,
        linear: s.mag_filter != Filter::Nearest,
    };
    let min = Pick::One {
        level: 0,
        linear: min_linear(s),
    };
    if mag == min {
        vec![mag]
    } else {
        vec![mag, min]
    }
}

/// The picks reading B adds for this case (none where it does not apply), with a step and a note
/// naming the readings where they add a pick reading A does not make; under
/// `Rules::non_fragment_base_texture` reading B is the spec's own pick (the magnification filter's).
pub(super) fn other_picks(e: &mut Eval, rules: &Rules, case: &Case, spec: Pick) -> Vec<Pick> {
    if !touches(case) {
        return Vec::new();
    }
    let picks = base_texture_picks(&case.sampler);
    if picks.iter().all(|p| *p == spec) {
        return Vec::new();
    }
    let what = if rules.non_fragment_base_texture {
        "reading B (the spec value here)"
    } else {
        "the other reading"
    };
    e.step(
        format!(
            "{what}: \"If it is mipmapped and running in a non-fragment shader, then the base texture is used\": level base+0, by the magnification filter or the minification filter within a level (contradiction `{READING}`)"
        ),
        &cite_b(case),
    );
    e.note(format!(
        "outside the fragment stage the texts give two readings: λ_base = 0 through the usual level-of-detail pipeline, or the base texture (contradiction `{READING}`)"
    ));
    picks
}
