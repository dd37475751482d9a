//! Vulkan 1.3: a depth image view sampled by an `OpImage*Dref*` instruction through a sampler with
//! `compareEnable`. Source: the Vulkan 1.3 specification, chapter "Image Operations" (§16:
//! Texel Input Operations, Texel Replacement, Depth Compare Operation, Texel Filtering, Texel
//! Gathering) and the format-feature description of `VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT`
//! (§34.3 Format Properties).
//!
//! Differences from GL 4.6 that matter here: no TexParameter (the sampling state is the
//! `VkSamplerCreateInfo` and the image view), so there are no GL errors, no DEPTH_TEXTURE_MODE, no
//! fail value and no incomplete textures (an image view always has `levelCount` levels; what GL
//! calls incomplete cannot be expressed, so such a case is not applicable); only Dref is clamped,
//! and only for UNORM formats; the border colour is one of the fixed `VkBorderColor` values; cube
//! maps are always filtered across faces; no rectangle textures, no CLAMP wrap, no colour texture
//! with a Dref instruction.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, Reading, RefClamp,
    Rules,
};
use crate::state::{Ctx, Param};
use shadowcheck_model::{ApiPath, CompareFunc, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// §16 Depth Compare Operation: "The reference value from the SPIR-V operand Dref and the texel
/// depth value Dtex are used as the reference and test values, respectively, in that operation",
/// with `VkCompareOp` (§26.6 / VkCompareOp): `ord` is reference (Dref) compared with test (Dtex).
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "VK_COMPARE_OP_NEVER specifies that the comparison always evaluates false."
        CompareFunc::Never => Some(false),
        // "VK_COMPARE_OP_LESS specifies that the comparison evaluates reference < test."
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "VK_COMPARE_OP_EQUAL specifies that the comparison evaluates reference = test."
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "VK_COMPARE_OP_LESS_OR_EQUAL specifies that the comparison evaluates reference ≤ test."
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "VK_COMPARE_OP_GREATER specifies that the comparison evaluates reference > test."
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "VK_COMPARE_OP_NOT_EQUAL specifies that the comparison evaluates reference ≠ test."
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "VK_COMPARE_OP_GREATER_OR_EQUAL specifies that the comparison evaluates reference ≥ test."
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "VK_COMPARE_OP_ALWAYS specifies that the comparison always evaluates true."
        CompareFunc::Always => Some(true),
        // The SGIX operators are no VkCompareOp value.
        _ => return Err(NotInTable),
    })
}

/// The sampling state is a sampler's create info, not TexParameter calls.
pub const SAMPLER_CREATE: &str = "Vulkan 1.3 §13 Samplers: the sampling state is the VkSamplerCreateInfo (compareEnable, compareOp, filters, mipmapMode, address modes, borderColor, minLod, maxLod, mipLodBias) and the image view's level range; a value outside the API's enums is invalid usage, never a runtime error";

/// The array layer rule, the same under every filter.
pub const LAYER_RNE: &str = "Vulkan 1.3 §16 (u,v,w,a) to (i,j,k,l,n) Transformation (l = clamp(RNE(a), 0, layerCount − 1), RNE = roundTiesToEven preferred, ⌊a + 0.5⌋ alternative)";

/// The sentence that loosens filtering where the format lacks the linear-filter feature.
pub const FILTER_LINEAR_BIT: &str = "Vulkan 1.3 §34.3 VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT: \"Where depth comparison is supported it may be linear filtered whether this bit is present or not, but where this bit is not present the filtered value may be computed in an implementation-dependent manner which differs from the normal rules of linear filtering. The resulting value must be in the range [0,1] and should be proportional to, or a weighted average of, the number of comparison passes or failures.\"";

pub fn rules() -> Rules {
    Rules {
        spec: Spec::Vulkan,
        doc: "Vulkan 1.3",
        table: table as CompareTable,
        table_cite: "Vulkan 1.3 §16 Depth Compare Operation, VkCompareOp",
        // "If the image being sampled has an unsigned normalized fixed-point format, then Dref is
        //  clamped to [0,1] before the compare operation." (A UNORM Dtex already lies in [0,1].)
        ref_clamp: RefClamp::FixedPointOnly,
        clamp_cite: "Vulkan 1.3 §16 Depth Compare Operation (Dref clamped only for UNORM formats)",
        // Texel Replacement: "Depth aspect: D = Br"; the fixed VkBorderColor values are 0.0 or
        // 1.0, and a custom colour "may be rounded ... must not exceed one ULP of the image's
        // format": no sentence clamps an out-of-range one.
        border: BorderRule::UndefinedOutOfRange,
        // The comparison is a texel input operation ("This value replaces the depth component
        // D"), so filtering combines the 0/1 results: with SAMPLED_IMAGE_FILTER_LINEAR that is the
        // weighted average of §16 Texel Linear Filtering; without it, FILTER_LINEAR_BIT. A fixture
        // does not know the device's format features, so the looser rule is encoded (the exact
        // weighted average is the spec value, anything else in [0,1] is a quality Warn).
        filtering: Filtering::ImplementationDependent,
        filter_cite: "Vulkan 1.3 §16 Depth Compare Operation, Texel Linear Filtering; §34.3 SAMPLED_IMAGE_FILTER_LINEAR_BIT (filtered compare in [0,1], should be proportional)",
        incomplete: Incomplete::NotApplicable("Vulkan 1.3 has no incomplete textures: an image view has levelCount levels (§12.5 Image Views) and mipmap selection clamps to them (§16 Level-of-Detail Operation); a case GL calls incomplete describes no Vulkan image"),
        es_depth_completeness: false,
        // Cube Map Edge Handling: with LINEAR filtering "sampling at the edges is performed as
        // described earlier in the Cube map edge handling section" (no non-seamless mode in core).
        seamless_cube: true,
        seamless_enable: None,
        // The image view's component mapping exists, but a Dref lookup's swizzle is not modelled.
        swizzle: None,
        // Every Vulkan sampler is its own object; there is no texture state beside it.
        sampler_objects: None,
        // VkSamplerCreateInfo::mipLodBias.
        lod_bias: true,
        sampler_create: Some(SAMPLER_CREATE),
        // §16 (u,v,w,a) to (i,j,k,l,n) Transformation: "l = clamp(RNE(a), 0, layerCount − 1) +
        // baseArrayLayer" with RNE "roundTiesToEven(a)" preferred and "⌊a + 0.5⌋" the
        // alternative, for NEAREST and LINEAR alike.
        layer_rne_always: Some(LAYER_RNE),
        ambient_on_pass: false,
        fail_value_cite: None,
        // VkImageViewType 1D, 2D, CUBE, 1D_ARRAY, 2D_ARRAY, CUBE_ARRAY (no rectangle textures).
        targets: &[
            Target::T1d,
            Target::T2d,
            Target::Cube,
            Target::T1dArray,
            Target::T2dArray,
            Target::CubeArray,
        ],
        // VkSamplerAddressMode (Vulkan 1.2+ core MIRROR_CLAMP_TO_EDGE, with its feature).
        wraps: &[
            Wrap::Repeat,
            Wrap::MirroredRepeat,
            Wrap::ClampToEdge,
            Wrap::ClampToBorder,
            Wrap::MirrorClampToEdge,
        ],
        apis: &[ApiPath::Vulkan],
        depth_modes: &[],
        // The aspect is chosen by the image view, not by a sampler mode.
        depth_stencil_mode: false,
        bad_func_error: "invalid usage (no VkCompareOp)",
        // D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, D24_UNORM_S8_UINT, D32_SFLOAT_S8_UINT.
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
        no_lookup_bias: None,
        fixed_depth_mode: None,
        colour_luminance: false,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[Reading {
            id: "vk-filter-linear-bit",
            other: None,
        }],
    }
}

/// No TexParameter table: Vulkan sets sampling state at sampler creation.
pub fn params(_: Spec, _: Ctx) -> Vec<Param> {
    Vec::new()
}
