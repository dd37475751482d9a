//! Unit state beyond the texture's own parameters: a bound sampler object, the context's
//! TEXTURE_CUBE_MAP_SEAMLESS enable and the texture swizzle. This unit resolves them on its own
//! (independent of the oracle):
//! - a bound sampler object supplies every sampling parameter (GL 4.6 §8.17.1 "the sampling state
//!   for that unit is taken from the sampler object"); DEPTH_TEXTURE_MODE,
//!   DEPTH_STENCIL_TEXTURE_MODE, the swizzle, TEXTURE_MAX_LEVEL and the fail value stay on the
//!   texture (§8.2: not sampler state);
//! - cube maps are seamless in ES 3.x, Vulkan and WebGPU; in GL when the case enables
//!   TEXTURE_CUBE_MAP_SEAMLESS;
//! - a sampler object holding state that TexParameter would reject for the bound texture (a
//!   rectangle texture: wrap S/T REPEAT, MIRRORED_REPEAT, MIRROR_CLAMP_TO_EDGE, or a mipmap min
//!   filter) makes the texture incomplete (§8.2), while the same state set on the texture itself
//!   is an INVALID_ENUM error (§8.10) and refused;
//! - the swizzle picks each output channel from the base colour (§15.2.1); a shadow lookup on a
//!   float path returns Cs[0] of the swizzled (Rt, 0, 0, 1) (§11.1.3.5); on the compatibility
//!   fixed-function and GLSL 1.20 paths the base colour is the DEPTH_TEXTURE_MODE vec4 of Table
//!   16.1; a shadow gather takes the post-swizzle R of each texel's (Rt, 0, 0, 1) (§8.14.2).

use crate::faults::{Fault, Faults};
use crate::layout;
use crate::sampler::Kind;
use crate::SoftError;
use shadowcheck_model::{ApiPath, Case, Filter, Sampler, Spec, Swizzle, Wrap};
use std::borrow::Cow;

/// Specs with sampler objects and the texture swizzle (GL 3.3+, ES 3.0+).
fn has_gl33_state(spec: Spec) -> bool {
    matches!(spec, Spec::Gl46 | Spec::Gles32)
}

/// Where the sampling parameters in effect come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StateSource {
    /// The texture's own parameters, set with TexParameter.
    Texture,
    /// A sampler object bound to the unit (GL 3.3+ / ES 3.0+).
    SamplerObject,
}

/// What TexParameter rejects for a rectangle texture among the sampling parameters, GL 4.6 §8.10:
/// "An INVALID_ENUM error is generated if the effective target is TEXTURE_RECTANGLE and either of
/// pnames TEXTURE_WRAP_S or TEXTURE_WRAP_T is set to either MIRROR_CLAMP_TO_EDGE, MIRRORED_REPEAT
/// or REPEAT. An INVALID_ENUM error is generated if the effective target is TEXTURE_RECTANGLE and
/// pname TEXTURE_MIN_FILTER is set to a value other than NEAREST or LINEAR". TEXTURE_WRAP_R is not
/// in the list. `Some(the rejected wrap mode)` for a wrap, `Some(None)` for the min filter.
pub fn rect_rejects(s: &Sampler) -> Option<Option<Wrap>> {
    let bad = |w: Wrap| {
        matches!(
            w,
            Wrap::MirrorClampToEdge | Wrap::MirroredRepeat | Wrap::Repeat
        )
    };
    if bad(s.wrap_s) {
        return Some(Some(s.wrap_s));
    }
    if bad(s.wrap_t) {
        return Some(Some(s.wrap_t));
    }
    if !matches!(s.min_filter, Filter::Nearest | Filter::Linear) {
        return Some(None);
    }
    None
}

/// The sampling state the unit uses for `case` (see the module docs) and where it comes from.
pub fn effective(
    spec: Spec,
    case: &Case,
    faults: Faults,
) -> Result<(Cow<'_, Sampler>, StateSource), SoftError> {
    let s = &case.sampler;
    if s.seamless.is_some() && spec != Spec::Gl46 {
        return Err(SoftError::Undefined {
            spec,
            what: "a TEXTURE_CUBE_MAP_SEAMLESS enable",
        });
    }
    if s.swizzle.is_some() && !has_gl33_state(spec) {
        return Err(SoftError::Undefined {
            spec,
            what: "TEXTURE_SWIZZLE_*",
        });
    }
    let Some(o) = &s.sampler_object else {
        return Ok((Cow::Borrowed(s), StateSource::Texture));
    };
    if !has_gl33_state(spec) {
        return Err(SoftError::Undefined {
            spec,
            what: "sampler objects",
        });
    }
    if faults.has(Fault::SamplerObjectIgnored)
        || (faults.has(Fault::GatherIgnoresSamplerObject) && case.lookup.gather.is_some())
    {
        return Ok((Cow::Borrowed(s), StateSource::Texture));
    }
    let mut eff = s.clone();
    eff.compare_mode = o.compare_mode;
    eff.compare_func = o.compare_func;
    eff.min_filter = o.min_filter;
    eff.mag_filter = o.mag_filter;
    eff.wrap_s = o.wrap_s;
    eff.wrap_t = o.wrap_t;
    eff.wrap_r = o.wrap_r;
    eff.border = o.border;
    eff.min_lod = o.min_lod;
    eff.max_lod = o.max_lod;
    eff.lod_bias = o.lod_bias;
    Ok((Cow::Owned(eff), StateSource::SamplerObject))
}

/// Whether cube lookups filter across faces.
pub fn seamless(spec: Spec, s: &Sampler, faults: Faults) -> bool {
    match spec {
        // Vulkan Cube Map Edge Handling: LINEAR filtering at a face edge reads the neighbouring
        // face; there is no non-seamless mode without VK_EXT_non_seamless_cube_map.
        Spec::Gles32 => true,
        Spec::Vulkan => !faults.has(Fault::VkCubeEdgePerFace),
        // WebGPU createView.1, GPUTextureViewDimension "cube": "Sampling is done seamlessly across the
        // faces of the cubemap"; a "cube-array" view is "a packed array of n cubemaps, each with
        // 6 array layers behaving like one "cube" view".
        Spec::WebGpu => !faults.has(Fault::WgpuCubePerFace),
        Spec::Gl46 if !faults.has(Fault::SeamlessIgnored) => s.seamless == Some(true),
        _ => false,
    }
}

/// The value a comparison sees for Dt when the swizzle is (wrongly) applied to the stored depth
/// before the comparison ([`Fault::SwizzleBeforeCompare`]): Cs[0] of (Dt, 0, 0, 1) for a
/// swizzle that does not read red; `None` when it reads red or no such fault is set.
pub fn pre_compare_dt(s: &Sampler, faults: Faults) -> Option<f32> {
    let sw = s.swizzle?;
    if !faults.has(Fault::SwizzleBeforeCompare) || sw[0] == Swizzle::Red {
        return None;
    }
    Some(sw[0].pick([f32::NAN, 0.0, 0.0, 1.0], 0.0, 1.0))
}

/// The swizzled result of a complete lookup: `rgba` is the layout's output for r on `api`.
///
/// Paths: the swizzle exists on gl46 / gles32 only (refused for the other specs by
/// [`effective`]); ARB_fragment_program is refused by the unit, since that extension's own text,
/// which would say how its TEX result meets TEXTURE_SWIZZLE_*, is outside the spec pack.
/// - GLSL 1.30+ / ES 3.00 shadow lookups (float paths): GL 4.6 §11.1.3.5 "expanding the resulting
///   value Rt to a color Cb = (Rt, 0, 0, 1). In either case, swizzling of Cb is then performed as
///   described above, but only the first component Cs[0] is returned to the shader" — also in a
///   compatibility context (GLSL 1.30), where Cb is this (Rt, 0, 0, 1), not the Table 16.1 vec4.
/// - Fixed function and GLSL 1.20 (compatibility): GL 4.6 compatibility §16.1 forms the texture
///   source colour by Table 16.1 (for a depth texture by DEPTH_TEXTURE_MODE: LUMINANCE
///   (r, r, r, 1), INTENSITY (r, r, r, r), ALPHA (0, 0, 0, r), RED (r, 0, 0, 1)), and §15.2.1's
///   swizzle ("Cs[0] = Cb[0] ... Ab ... 0 ... 1") applies to that colour: `rgba` is that vec4
///   (the colour layout for R8, (St, 0, 0, 1) for stencil).
/// - Non-shadow reads elsewhere: the swizzle picks from the layout's vec4 the same way.
pub fn swizzle(s: &Sampler, api: ApiPath, kind: Kind, rgba: [f32; 4], faults: Faults) -> [f32; 4] {
    let Some(sw) = s.swizzle else {
        return rgba;
    };
    if faults.has(Fault::SwizzleIgnored) {
        return rgba;
    }
    if matches!(api, ApiPath::FixedFunction | ApiPath::Glsl120)
        && faults.has(Fault::CompatSwizzleDropped)
    {
        return rgba;
    }
    if kind == Kind::Compare && faults.has(Fault::SwizzleBeforeCompare) {
        // Already applied to Dt before the comparison.
        return rgba;
    }
    let shadow_float = kind == Kind::Compare && layout::is_float_path(api);
    if shadow_float {
        let cs0 = sw[0].pick([rgba[0], 0.0, 0.0, 1.0], 0.0, 1.0);
        return [cs0, 0.0, 0.0, 1.0];
    }
    sw.map(|c| c.pick(rgba, 0.0, 1.0))
}

/// The swizzled components of a complete shadow gather; `results[k]` is the comparison result of
/// the texel component k reads. GL 4.6 §8.14.2: "Each texel is then converted to a texture source
/// color (Rs,Gs,Bs,As) according to table 15.1 and then swizzled as described in section 15.2.1.
/// A four-component vector is then assembled by taking a single component from the swizzled
/// texture source colors of the four texels"; "If comp is omitted, it is treated as identifying
/// the Rs component" (a shadow gather has no comp), and Figure 8.4: "each component is taken from
/// the post-swizzle R component of the corresponding texel". A texel's base colour is the
/// comparison expanded to Cb = (Rt, 0, 0, 1) (§11.1.3.5), so component k is TEXTURE_SWIZZLE_R
/// applied to (Rt_k, 0, 0, 1): RED gives Rt_k, GREEN / BLUE / ZERO 0, ALPHA / ONE 1.
/// (GLSL 4.60 §8.9.4's "returns the result of that comparison in the appropriate component" reads
/// as the unswizzled results; the API's text is the one implemented.)
pub fn gather_swizzle(s: &Sampler, results: [f32; 4], faults: Faults) -> [f32; 4] {
    let Some(sw) = s.swizzle else {
        return results;
    };
    if faults.has(Fault::SwizzleIgnored) || faults.has(Fault::GatherIgnoresSwizzle) {
        return results;
    }
    if faults.has(Fault::GatherSwizzlesVector) {
        return sw.map(|c| c.pick(results, 0.0, 1.0));
    }
    results.map(|rt| sw[0].pick([rt, 0.0, 0.0, 1.0], 0.0, 1.0))
}
