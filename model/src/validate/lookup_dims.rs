//! The shader-side dimensions of a lookup: how its values reach the lookup function
//! ([`Delivery`]) and the shader stage it runs in ([`Stage`]). The forms the shading languages do not allow are rejected here, naming the
//! sentence; which GLSL version a context needs for the rest is the plan's business
//! (`shadowcheck-plan`, `paths::plan_for`).

use super::invalid;
use crate::{ApiPath, Case, Delivery, ModelError, Stage};

/// The API paths that draw a non-literal delivery: GLSL 1.30+ and GLSL ES 3.00+ (uniforms and
/// `flat` inputs, GLSL 1.30 §4.3.6). Vulkan and WebGPU answer such a case as not applicable.
pub const DELIVERY_PATHS: [ApiPath; 3] = [ApiPath::Glsl130, ApiPath::GlslCore, ApiPath::Es300];

/// A non-literal delivery: on a path that has it, never a non-gather texel offset (GLSL 4.60
/// §8.9.2 textureOffset: "The offset value must be a constant expression"), never
/// textureGatherOffsets (GLSL 4.60 §8.9.4: "The specified values in offsets must be constant
/// integral expressions"); textureGatherOffset's offset "can be variable (non constant)" (GLSL
/// 4.60 / GLSL ES 3.20 §8.9.4).
pub(super) fn validate_delivery(case: &Case) -> Result<(), ModelError> {
    let l = &case.lookup;
    let d = l.delivery;
    if d == Delivery::Literal {
        return Ok(());
    }
    if let Some(api) = case.api.iter().find(|a| !DELIVERY_PATHS.contains(a)) {
        return Err(invalid(
            case,
            "lookup.delivery",
            format!(
                "delivery `{d}` is drawn on the GLSL 1.30+ and GLSL ES 3.00+ paths only (glsl130, core, es300), not on `{}`",
                api.key()
            ),
        ));
    }
    match &l.gather {
        None if l.offset != [0; 3] => Err(invalid(
            case,
            "lookup.delivery",
            format!(
                "delivery `{d}` with a texel offset on a non-gather lookup: the offset of textureOffset & co. \"must be a constant expression\" (GLSL 4.60 §8.9.2); only textureGatherOffset's may be variable"
            ),
        )),
        Some(g) if g.offsets.is_some() => Err(invalid(
            case,
            "lookup.delivery",
            format!(
                "delivery `{d}` with textureGatherOffsets: \"The specified values in offsets must be constant integral expressions\" (GLSL 4.60 §8.9.4)"
            ),
        )),
        _ => Ok(()),
    }
}

/// The API paths that have a shadow lookup in the vertex shader: GLSL 1.20 (§8.7: "available to
/// both vertex and fragment shaders"), GLSL 1.30+ and GLSL ES 3.00+ (§8.9 / §8.7: "available in
/// all shading stages" / "to vertex and fragment shaders"). The fixed-function, ARB program and
/// ES 1.00 paths have no vertex-stage shadow lookup here; Vulkan and WebGPU answer such a case as
/// not applicable.
pub const STAGE_PATHS: [ApiPath; 4] = [
    ApiPath::Glsl120,
    ApiPath::Glsl130,
    ApiPath::GlslCore,
    ApiPath::Es300,
];

/// The API paths that have a compute shader: the core path (GL 4.3, GLSL 4.30 §2.6 "Compute
/// Processor") and the ES path (ES 3.1, GLSL ES 3.10), where the context must offer them
/// (`shadowcheck-plan`); Vulkan (the GLCompute execution model) and WebGPU (WGSL compute shader
/// stage: `textureSampleCompareLevel` and `textureGatherCompare` "may be invoked in any shader
/// stage"). The compatibility paths' languages (GLSL 1.20 / 1.30) have none.
pub const COMPUTE_PATHS: [ApiPath; 4] = [
    ApiPath::GlslCore,
    ApiPath::Es300,
    ApiPath::Vulkan,
    ApiPath::Wgsl,
];

/// A lookup outside the fragment stage: on a path that has it, never with a bias (GLSL 4.60 /
/// GLSL ES 3.20 §8.9: "The bias parameter is not accepted in any other shader stage").
pub(super) fn validate_stage(case: &Case) -> Result<(), ModelError> {
    let l = &case.lookup;
    let st = l.stage;
    if st == Stage::Fragment {
        return Ok(());
    }
    let (paths, which): (&[ApiPath], &str) = if st == Stage::Compute {
        (
            &COMPUTE_PATHS,
            "the GLSL 4.30+, GLSL ES 3.10+, Vulkan and WGSL paths only (core, es300, vk, wgsl)",
        )
    } else {
        (
            &STAGE_PATHS,
            "the GLSL 1.20+ and GLSL ES 3.00+ paths only (glsl120, glsl130, core, es300)",
        )
    };
    if let Some(api) = case.api.iter().find(|a| !paths.contains(a)) {
        return Err(invalid(
            case,
            "lookup.stage",
            format!("stage `{st}` is drawn on {which}, not on `{}`", api.key()),
        ));
    }
    if l.bias != 0.0 {
        return Err(invalid(
            case,
            "lookup.bias",
            format!(
                "a bias in the {st} stage: \"The bias parameter is not accepted in any other shader stage\" than the fragment shader (GLSL 4.60 / GLSL ES 3.20 §8.9)"
            ),
        ));
    }
    Ok(())
}
