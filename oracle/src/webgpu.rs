//! WebGPU with WGSL: a depth texture (`texture_depth_*`) sampled through a comparison sampler
//! (`sampler_comparison`, a `GPUSampler` created with `GPUSamplerDescriptor.compare`) by
//! `textureSampleCompare`, `textureSampleCompareLevel` or `textureGatherCompare`. Sources: the
//! WebGPU specification (section "Samplers": GPUSamplerDescriptor, GPUAddressMode, GPUFilterMode,
//! GPUCompareFunction; "Textures and Texture Views": GPUTextureViewDimension; "Texture Formats":
//! depth24plus) and the WGSL specification ("Texture Built-in Functions": textureGatherCompare,
//! textureSampleCompare, textureSampleCompareLevel), editors' drafts of 2026-08.
//!
//! Differences from Vulkan 1.3 that matter here: the reference is never said to be clamped (both
//! readings are accepted, contradiction `ref-clamp`); `depth24plus` is either a 24-bit
//! UNORM or a `depth32float` (`webgpu-depth24plus`); no border colour and no CLAMP_TO_BORDER; no
//! LOD bias; no 1D depth textures; the array index is an integer, clamped to the layers;
//! `textureSampleCompareLevel` and `textureGatherCompare` read level 0 only.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, Reading, RefClamp,
    Rules,
};
use crate::state::{Ctx, Param};
use shadowcheck_model::{ApiPath, CompareFunc, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// WebGPU, Samplers: GPUCompareFunction: "the `depth_ref` is compared to the fetched texel value, and
/// the result of this comparison test is generated (1.0f for pass, or 0.0f for fail)"; the
/// "provided value" is `depth_ref` (Dref), the "sampled value" the texel (Dt): `ord` is Dref
/// compared with Dt.
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "never": "Comparison tests never pass."
        CompareFunc::Never => Some(false),
        // "less": "A provided value passes the comparison test if it is less than the sampled value."
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "equal": "A provided value passes the comparison test if it is equal to the sampled value."
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "less-equal": "... if it is less than or equal to the sampled value."
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "greater": "... if it is greater than the sampled value."
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "not-equal": "... if it is not equal to the sampled value."
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "greater-equal": "... if it is greater than or equal to the sampled value."
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "always": "Comparison tests always pass."
        CompareFunc::Always => Some(true),
        // The SGIX operators are no GPUCompareFunction value.
        _ => return Err(NotInTable),
    })
}

/// The sampling state is a sampler's descriptor, not TexParameter calls.
pub const SAMPLER_CREATE: &str = "WebGPU, Samplers: GPUSamplerDescriptor: the sampling state is the descriptor of createSampler() (addressModeU/V/W, magFilter, minFilter, mipmapFilter, lodMinClamp, lodMaxClamp, compare) and the texture view's mip range; a descriptor outside the enums, or with lodMinClamp < 0 or lodMaxClamp < lodMinClamp, is a validation error, never sent";

/// The array index rule: an integer, clamped.
pub const ARRAY_INDEX: &str = "WGSL textureSampleCompare / textureGatherCompare: \"array_index: The 0-based texture array index to sample. This value will be clamped to the range [0, textureNumLayers(t) - 1]\" (an i32 or u32: the grid's layer coordinates are integers, which every rounding rule leaves as they are)";

/// The filtered comparison: "should" filter as usual, "may" not.
pub const FILTERING: &str = "WebGPU, Samplers (GPUCompareFunction): \"After comparison, if texture filtering is enabled, the filtering step occurs, so that comparison results are mixed together resulting in values in the range [0, 1]. Filtering should behave as usual, however it may be computed with lower precision or not mix results at all.\"";

pub fn rules() -> Rules {
    Rules {
        spec: Spec::WebGpu,
        doc: "WebGPU",
        table: table as CompareTable,
        table_cite: "WebGPU, Samplers: GPUCompareFunction",
        // No sentence of WebGPU or WGSL clamps depth_ref ("The reference value to compare the
        // sampled depth value against"), and the APIs under it differ (Vulkan clamps Dref for
        // UNORM formats only): the literal reading (no clamp) is the spec value, a clamp to
        // [0,1] is accepted too (contradiction `ref-clamp`).
        ref_clamp: RefClamp::Unstated,
        clamp_cite: "WGSL textureSampleCompare: \"depth_ref: The reference value to compare the sampled depth value against\" (no clamp stated)",
        // GPUAddressMode has no clamp-to-border: the grid sends no border case.
        border: BorderRule::None,
        filtering: Filtering::ImplementationDependent,
        filter_cite: FILTERING,
        incomplete: Incomplete::NotApplicable("WebGPU has no incomplete textures: a texture view has mipLevelCount levels (WebGPU createView) and a sampler needs no texture state; a case GL calls incomplete describes no WebGPU texture"),
        es_depth_completeness: false,
        // WebGPU GPUTextureViewDimension "cube": "Sampling is done seamlessly across the faces
        // of the cubemap."
        seamless_cube: true,
        seamless_enable: None,
        // No component swizzle on a depth texture view in WebGPU core.
        swizzle: None,
        // Every GPUSampler is its own object; there is no texture state beside it.
        sampler_objects: None,
        // GPUSamplerDescriptor has no LOD bias, and no compare built-in takes one.
        lod_bias: false,
        sampler_create: Some(SAMPLER_CREATE),
        layer_rne_always: Some(ARRAY_INDEX),
        ambient_on_pass: false,
        fail_value_cite: None,
        // WGSL depth texture types: texture_depth_2d, texture_depth_2d_array, texture_depth_cube,
        // texture_depth_cube_array (no 1D or 3D depth textures, no rectangles).
        targets: &[Target::T2d, Target::Cube, Target::T2dArray, Target::CubeArray],
        // GPUAddressMode: "clamp-to-edge", "repeat", "mirror-repeat".
        wraps: &[Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge],
        apis: &[ApiPath::Wgsl],
        depth_modes: &[],
        // The aspect is chosen by the texture view ("depth-only"), not by a sampler mode.
        depth_stencil_mode: false,
        bad_func_error: "validation error (no GPUCompareFunction)",
        // depth16unorm, depth24plus, depth24plus-stencil8, depth32float, depth32float-stencil8
        // (the last with the "depth32float-stencil8" feature).
        formats: &[
            Format::D16,
            Format::D24,
            Format::D32f,
            Format::D24S8,
            Format::D32fS8,
        ],
        // No TexParameter pnames: `sampler_create` routes every check around the GL tables.
        mode_pname: 0,
        func_pname: 0,
        params,
        no_lod_state: None,
        no_lookup_bias: Some("WGSL texture built-in functions: textureSampleCompare, textureSampleCompareLevel and textureGatherCompare take no bias argument"),
        fixed_depth_mode: None,
        colour_luminance: false,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[
            Reading {
                id: "webgpu-depth24plus",
                other: None,
            },
            Reading {
                id: "webgpu-filter",
                other: None,
            },
        ],
    }
}

/// No TexParameter table: WebGPU sets sampling state at sampler creation.
pub fn params(_: Spec, _: Ctx) -> Vec<Param> {
    Vec::new()
}
