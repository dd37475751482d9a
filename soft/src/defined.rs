//! Which sampler state each specification defines: wrap modes, formats, filters, LOD state,
//! the WebGPU sampler descriptor and the rectangle-texture rule. What a spec lacks is refused
//! (a Skip reason); a rectangle-illegal sampler object makes the texture incomplete instead.

use crate::faults::{Fault, Faults};
use crate::sampler::undefined;
use crate::storage::PreparedTexture;
use crate::unitstate::StateSource;
use crate::SoftError;
use shadowcheck_model::{CompareMode, Filter, Format, Sampler, Spec, Wrap};

fn is_es(spec: Spec) -> bool {
    matches!(spec, Spec::Es2Ext | Spec::Gles32)
}

/// Wrap modes the spec accepts (GL 4.6 Table 8.17, ES 3.2 Table 8.19, ES 2.0 Table 3.10). What a
/// rectangle texture rejects besides is [`crate::unitstate::rect_rejects`].
fn check_wrap(spec: Spec, w: Wrap) -> Result<(), SoftError> {
    let ok = match spec {
        Spec::Es2Ext => matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat),
        Spec::Gles32 => !matches!(w, Wrap::MirrorClampToEdge | Wrap::Clamp),
        // VkSamplerAddressMode: REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER,
        // MIRROR_CLAMP_TO_EDGE; GL's legacy CLAMP has no equivalent.
        Spec::Vulkan => w != Wrap::Clamp,
        // WebGPU, Samplers: GPUSamplerDescriptor: "enum GPUAddressMode { "clamp-to-edge", "repeat",
        // "mirror-repeat" }": no border, no mirror-once, no legacy CLAMP. "clamp-to-edge":
        // "Texture coordinates are clamped between 0.0 and 1.0, inclusive" (a texel index
        // clamped into the image, as CLAMP_TO_EDGE); "repeat": "Texture coordinates wrap to the
        // other side of the texture"; "mirror-repeat": "... but the texture is flipped when the
        // integer part of the coordinate is odd" (MIRRORED_REPEAT's rows in `wrap`).
        Spec::WebGpu => matches!(w, Wrap::ClampToEdge | Wrap::Repeat | Wrap::MirroredRepeat),
        _ => true,
    };
    if !ok {
        return Err(SoftError::Wrap { spec, wrap: w });
    }
    Ok(())
}

/// Formats each spec has (ES 3.2 Table 8.11 has no DEPTH_COMPONENT32; ES 2.0 with
/// OES_depth_texture / OES_packed_depth_stencil has no floating-point depth).
fn check_format(spec: Spec, f: Format) -> Result<(), SoftError> {
    let ok = match spec {
        Spec::Gles32 => f != Format::D32,
        Spec::Es2Ext => !matches!(f, Format::D32 | Format::D32f | Format::D32fS8),
        // Vulkan depth formats: D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, D24_UNORM_S8_UINT,
        // D32_SFLOAT_S8_UINT. No 32-bit UNORM depth, no unsized format, and a Dref instruction
        // needs a depth aspect.
        Spec::Vulkan => matches!(
            f,
            Format::D16 | Format::D24 | Format::D32f | Format::D24S8 | Format::D32fS8
        ),
        // WebGPU, Texture Formats: the depth formats "depth16unorm", "depth24plus",
        // "depth24plus-stencil8", "depth32float" and "depth32float-stencil8"; a texture_depth_*
        // binding needs one of them. depth24plus "may be implemented as either a 24-bit depth
        // value or a "depth32float" value": chosen, the 24-bit reading (the case gives 24-bit
        // unorm integers, converted c / (2^24 − 1) in `storage`).
        Spec::WebGpu => matches!(
            f,
            Format::D16 | Format::D24 | Format::D32f | Format::D24S8 | Format::D32fS8
        ),
        _ => true,
    };
    if ok {
        Ok(())
    } else {
        Err(SoftError::Format { spec, format: f })
    }
}

/// Sampler state a GPUSamplerDescriptor cannot hold.
fn check_webgpu(s: &Sampler) -> Result<(), SoftError> {
    let spec = Spec::WebGpu;
    if s.compare_mode != CompareMode::Compare {
        // WGSL textureSampleCompare takes `s: sampler_comparison`; WebGPU, Samplers: GPUSamplerDescriptor
        // "compare: When provided the sampler will be a comparison sampler with the specified
        // GPUCompareFunction". A depth read without comparison is another built-in.
        return Err(undefined(
            spec,
            "a depth-comparison lookup through a sampler without `compare`",
        ));
    }
    if s.lod_bias != 0.0 {
        // WebGPU, Samplers: GPUSamplerDescriptor: GPUSamplerDescriptor has addressMode*, magFilter, minFilter,
        // mipmapFilter, lodMinClamp, lodMaxClamp, compare and maxAnisotropy: no LOD bias.
        return Err(undefined(
            spec,
            "a sampler LOD bias (GPUSamplerDescriptor has none)",
        ));
    }
    // lodMinClamp / lodMaxClamp are min_lod / max_lod ("the minimum and maximum levels of
    // detail, respectively, used internally when sampling a texture", WebGPU, Samplers: GPUSamplerDescriptor), clamping λ
    // as in `lod`. WebGPU, Samplers: requires lodMinClamp ≥ 0; the model's unset value (−1000)
    // stands for the default 0, which gives the same result (λ ≤ 0 selects the base level by the
    // magnification filter either way). "lodMaxClamp ≥ lodMinClamp" is checked with the other
    // specs' rule below. TEXTURE_BASE_LEVEL / TEXTURE_MAX_LEVEL stand for the view's
    // baseMipLevel and its last level, baseMipLevel + mipLevelCount − 1 (WebGPU createView.1): λ and
    // the level range follow GL 4.6 §8.14 as for the other specs (WebGPU, Samplers: GPUSamplerDescriptor refers to
    // Vulkan's "Scale Factor Operation, LOD Operation and Image Level Selection" for "an
    // example of how implicit LODs may be calculated").
    Ok(())
}

/// Refuses state `spec` does not define. `Ok(true)`: a bound sampler object holds state the
/// rectangle texture rejects, so the texture counts as incomplete (see [`rect_rule`]).
pub(crate) fn check_state(
    spec: Spec,
    s: &Sampler,
    source: StateSource,
    tex: &PreparedTexture,
    faults: Faults,
) -> Result<bool, SoftError> {
    check_format(spec, tex.format())?;
    // Only s and t address a rectangle; wrap_r is checked against the spec's enums only.
    check_wrap(spec, s.wrap_s)?;
    check_wrap(spec, s.wrap_t)?;
    check_wrap(spec, s.wrap_r)?;
    if !matches!(s.mag_filter, Filter::Nearest | Filter::Linear) {
        return Err(undefined(spec, "a mipmap TEXTURE_MAG_FILTER"));
    }
    let sampler_object_incomplete = rect_rule(spec, s, source, tex, faults)?;
    if is_es(spec) && s.lod_bias != 0.0 {
        return Err(undefined(spec, "TEXTURE_LOD_BIAS (not in OpenGL ES)"));
    }
    if spec == Spec::Es2Ext {
        // ES 2.0 has no TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, TEXTURE_MIN_LOD, TEXTURE_MAX_LOD.
        if tex.base_level != 0 || s.max_level.is_some() {
            return Err(undefined(
                spec,
                "TEXTURE_BASE_LEVEL / TEXTURE_MAX_LEVEL (not in OpenGL ES 2.0)",
            ));
        }
        if s.min_lod != -1000.0 || s.max_lod != 1000.0 {
            return Err(undefined(
                spec,
                "TEXTURE_MIN_LOD / TEXTURE_MAX_LOD (not in OpenGL ES 2.0)",
            ));
        }
    }
    if spec == Spec::Vulkan && s.compare_mode != CompareMode::Compare {
        return Err(undefined(
            spec,
            "a Dref lookup through a sampler without compareEnable",
        ));
    }
    if spec == Spec::WebGpu {
        check_webgpu(s)?;
    }
    if s.min_lod > s.max_lod {
        return Err(SoftError::UndefinedResult(
            "TEXTURE_MIN_LOD > TEXTURE_MAX_LOD makes λ undefined (eq. 8.9)",
        ));
    }
    Ok(sampler_object_incomplete)
}

/// State a rectangle texture rejects (GL 4.6 §8.10, `rect_rejects`). Set on the texture it is an
/// INVALID_ENUM error: the case cannot be set up (refused). Held by a bound sampler object it is
/// no error but, GL 4.6 §8.2: "If state is present in a sampler object bound to a texture unit
/// that would have been rejected by a call to TexParameter* for the texture bound to that unit,
/// the behavior of the implementation is as if the texture were incomplete. For example, if
/// TEXTURE_WRAP_S or TEXTURE_WRAP_T is set to REPEAT, MIRRORED_REPEAT, or MIRROR_CLAMP_TO_EDGE on
/// the sampler object bound to a texture unit and the texture bound to that unit is a rectangle
/// texture, the texture will be considered incomplete." `Ok(true)`: incomplete so.
fn rect_rule(
    spec: Spec,
    s: &Sampler,
    source: StateSource,
    tex: &PreparedTexture,
    faults: Faults,
) -> Result<bool, SoftError> {
    let rect_rejected = if tex.target().is_rect() {
        crate::unitstate::rect_rejects(s)
    } else {
        None
    };
    match (rect_rejected, source) {
        (None, _) => Ok(false),
        (Some(Some(wrap)), StateSource::Texture) => Err(SoftError::Wrap { spec, wrap }),
        (Some(None), StateSource::Texture) => Err(undefined(
            spec,
            "a mipmap TEXTURE_MIN_FILTER on a rectangle texture (§8.10)",
        )),
        (Some(_), StateSource::SamplerObject) => Ok(!faults.has(Fault::SamplerObjectRectComplete)),
    }
}
