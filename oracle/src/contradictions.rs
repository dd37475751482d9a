//! Where the documents disagree. Each entry quotes the documents involved (`sources`) and
//! names the reading the oracle encodes and the other one; `touching` says which entries a case meets,
//! and `alternative_rules` gives the other reading as rules, so `explain` can show both values.

use crate::rules::{RefClamp, Rules};
use shadowcheck_model::{Case, CompareFunc, CompareMode, Filter, Wrap};

/// One disagreement between the documents.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Contradiction {
    pub id: &'static str,
    pub title: &'static str,
    /// The reading the oracle encodes, and why.
    pub defended: &'static str,
    /// The other reading.
    pub other: &'static str,
    pub sources: &'static str,
}

pub const ALL: &[Contradiction] = &[
    Contradiction {
        id: "incomplete-uint-alpha",
        title: "Alpha of an incomplete texture read through an unsigned integer sampler (STENCIL_INDEX)",
        defended: "Both readings are accepted (the channel's set holds 1 and 1065353216), labelled implementation-defined: §11.1.3.5 gives \"(0.0, 0.0, 0.0, 1.0), in floating-point, ... for a non-shadow sampler\", and a usampler reading a DEPTH_STENCIL texture in STENCIL_INDEX mode is a non-shadow sampler on a supported combination (the sentence's \"undefined values\" are for unsupported ones), so R, G and B are 0 under either reading.",
        other: "\"in floating-point\" read literally: the alpha word holds the bits of 1.0f, 0x3F800000 = 1065353216 as an unsigned integer; or read as the value one: the integer 1 (GLSL ES 3.20 §8.9.4: incomplete textures \"return a texture source color of (0,0,0,1)\").",
        sources: "GL 4.6 §11.1.3.5, ES 3.2 §11.1.3.5 (incomplete textures); GLSL ES 3.20 §8.9.4",
    },
    Contradiction {
        id: "sgix-lequal-direction",
        title: "Direction of TEXTURE_LEQUAL_R_SGIX",
        defended: "SGIX_shadow's own text: TEXTURE_LEQUAL_R_SGIX passes if texel <= R (GEQUAL_R: texel >= R). The normative extension body is the only definition of its tokens.",
        other: "ARB_shadow issue 2: the token \"should really have been named GL_R_LEQUAL_TEXTURE_SGIX since we're comparing R <= TEXTURE\" (and the original spec \"seems to be inconsistant with what was really implemented in hardware\").",
        sources: "SGIX_shadow Additions to Chapter 3 (Notes); ARB_shadow issue 2",
    },
    Contradiction {
        id: "sgix-ambient",
        title: "When SHADOW_AMBIENT_SGIX applies",
        defended: "The body (and seed 002): the value is returned \"when ... a pixel is determined to be in shadow\", \"instead of 0.0\": it replaces the failing result. ARB_shadow_ambient (\"functionally identical\") agrees.",
        other: "The overview: \"a value other than 0.0 to be returned ... in the case when the shadow test passes\": the ambient value replaces the passing result.",
        sources: "SGIX_shadow_ambient Overview vs Notes; ARB_shadow_ambient issue 1",
    },
    Contradiction {
        id: "ref-clamp",
        title: "Clamping of Dt and R / Dref",
        defended: "Per document: SGIX and WebGPU unstated (both accepted, literal = unclamped); ARB_shadow / GL ≤ 2.1: R clamped, Dt in [0,1]; GL 3.0+ / ES 3.x / ARB_depth_buffer_float rev 7 / Vulkan 1.3: clamped only for fixed-point depth; EXT_shadow_samplers: always clamped.",
        other: "The reading of the neighbouring documents (e.g. GL 4.6 D32F under ARB_shadow's always-clamp, or SGIX with NVIDIA's clamp).",
        sources: "SGIX_shadow NVIDIA Implementation Details; ARB_shadow §3.8.13.1; ARB_depth_buffer_float; GL 4.6 §8.23.1; EXT_shadow_samplers §3.7.14.1; Vulkan 1.3 §16 Depth Compare Operation; WGSL textureSampleCompare (depth_ref)",
    },
    Contradiction {
        id: "filtering",
        title: "Filtering of comparison results",
        defended: "SGIX: compare before filtering, r is exactly the weighted average of 0/1. Later specs: implementation-dependent, \"proportional to the number of comparison passes\" — accepted as the PCF range (strict) or, for a footprint with both passes and fails, any value in [fail value, 1] (quality: the \"should\" leaves the proportion open), labelled implementation_defined.",
        other: "Any other filtering of a later spec (e.g. an unweighted pass fraction, or filtering Dt before one compare) — accepted by quality only (Warn).",
        sources: "SGIX_shadow Overview; ARB_shadow §3.8.13.1 and issue 7; GL 4.6 §8.23.1",
    },
    Contradiction {
        id: "result-layout",
        title: "Where r goes",
        defended: "Per document and API path: SGIX LUMINANCE; ARB_shadow/GL ≤ 2.1 Lt/It/At by DEPTH_TEXTURE_MODE; GL compatibility adds RED; GL 3.x+ core / ES 3.x: (Rt,0,0,1), float result.",
        other: "OES_depth_texture (no compare): (d,d,d,1) always.",
        sources: "SGIX_shadow Notes; ARB_shadow §3.8.13.1; GL 4.6 §11.1.3.5; compatibility Table 16.1; OES_depth_texture issue 2",
    },
    Contradiction {
        id: "compat-float-alpha",
        title: "Float shadow lookup (GLSL 1.30, compatibility) with DEPTH_TEXTURE_MODE = ALPHA",
        defended: "Compatibility §11.1.3.5: a shadow lookup expands \"the resulting value Rt to a color Cb = (Rt, 0, 0, 1)\" and returns Cs[0] = r, for every DEPTH_TEXTURE_MODE (the pack's note: this paragraph describes the float-returning lookups; E.2.2: GLSL 1.30 returns (r, 0, 0, 1)). The spec value follows it; the other reading is accepted too (layout `r|0`), labelled implementation-defined.",
        other: "Compatibility §8.23.1 with Table 16.1: for ALPHA r is assigned to At, Cb = (0,0,0), so the float Cs[0] would be 0.",
        sources: "GL 4.6 compatibility §8.23.1, §11.1.3.5, Table 16.1",
    },
    Contradiction {
        id: "compat-depth-cb",
        title: "Base colour of a GLSL 1.30 depth lookup in a compatibility context",
        defended: "Both readings are accepted, each named. A shadow lookup's spec value follows §11.1.3.5 (Cs[0] of the swizzled Cb = (Rt, 0, 0, 1)); a non-shadow read's follows §8.23.1 with Table 16.1 (Cb by DEPTH_TEXTURE_MODE, then swizzled), as the legacy vec4 paths do. Without a swizzle the shadow lookups differ only for ALPHA (contradiction `compat-float-alpha`, layout `r|0`).",
        other: "The other sentence: §11.1.3.5, \"Texture lookups involving textures with depth component data generate a texture base color Cb either using depth data directly or by performing a comparison ... and expanding the resulting value Rt to a color Cb = (Rt, 0, 0, 1)\", against §8.23.1, \"The resulting r is assigned to Rt, Lt, It, or At if the value of DEPTH_TEXTURE_MODE is respectively RED, LUMINANCE, INTENSITY, or ALPHA\" with Table 16.1. With a swizzle such as R = GREEN the two give different values for every mode.",
        sources: "GL 4.6 compatibility §8.23.1, §11.1.3.5, §15.2.1, Table 16.1",
    },
    Contradiction {
        id: "gather-swizzle",
        title: "Texture swizzle on a shadow textureGather",
        defended: "GL 4.6 / ES 3.2 §8.14.2: \"Each texel is then converted to a texture source color (Rs,Gs,Bs,As) according to table 15.1 and then swizzled as described in section 15.2.1\"; Figure 8.4: \"each component is taken from the post-swizzle R component\". A comparison result Rt is Cb = (Rt, 0, 0, 1), so TEXTURE_SWIZZLE_R decides: RED the comparison, GREEN/BLUE/ZERO 0, ALPHA/ONE 1. The spec value follows it.",
        other: "GLSL 4.60 / GLSL ES 3.20 §8.9.4: each of the four texel lookups \"returns the result of that comparison in the appropriate component of the result vector\", read without the swizzle: the four comparisons whatever TEXTURE_SWIZZLE_R says. Accepted too, named.",
        sources: "GL 4.6 / ES 3.2 §8.14.2 and Figure 8.4; GLSL 4.60 / GLSL ES 3.20 §8.9.4",
    },
    Contradiction {
        id: "incomplete",
        title: "Result of an incomplete texture",
        defended: "GL 4.6 / ES 3.2: 0 for a shadow sampler; GL 2.1 / ARB_fragment_program_shadow / ES 2.0: (0,0,0,1).",
        other: "The other era's value.",
        sources: "GL 2.1 §3.11.2; ARB_fragment_program_shadow; GL 4.6 §11.1.3.5",
    },
    Contradiction {
        id: "bad-operator-error",
        title: "Error for a bad compare operator",
        defended: "SGIX_shadow: INVALID_OPERATION; ARB_shadow (changed 21 Jan 2002), EXT_shadow_funcs, core: INVALID_ENUM.",
        other: "ARB_shadow before 21 January 2002: INVALID_OPERATION.",
        sources: "SGIX_shadow Errors; ARB_shadow Errors and revision history",
    },
    Contradiction {
        id: "es2-greater-row",
        title: "EXT_shadow_samplers GREATER at D_ref == Dt",
        defended: "The printed rows, \"1.0, if D_ref > Dt\" and \"0.0, if D_ref < Dt\", assign nothing at equality: the result is left open, either value is accepted and labelled implementation-defined.",
        other: "r = 0.0 as in EXT_shadow_funcs, which the extension is based on (\"0.0, if R <= Dt\").",
        sources: "EXT_shadow_samplers Table 3.X; EXT_shadow_funcs",
    },
    Contradiction {
        id: "vk-filter-linear-bit",
        title: "Vulkan filtered comparison without SAMPLED_IMAGE_FILTER_LINEAR",
        defended: "Vulkan 1.3 §16: the comparison is a texel input operation (\"This value replaces the depth component D\"), then Texel Linear Filtering takes the weighted average of the 0/1 results: that is the spec value, accepted strictly.",
        other: "§34.3 SAMPLED_IMAGE_FILTER_LINEAR_BIT: where the format lacks the bit, \"the filtered value may be computed in an implementation-dependent manner which differs from the normal rules of linear filtering. The resulting value must be in the range [0,1] and should be proportional to, or a weighted average of, the number of comparison passes or failures\": any value in [0,1] for a footprint with passes and fails is accepted by quality (Warn). A fixture cannot know the device's format features, so both are accepted on every device.",
        sources: "Vulkan 1.3 §16 Depth Compare Operation, Texel Linear Filtering; §34.3 Format Properties",
    },
    Contradiction {
        id: "webgpu-depth24plus",
        title: "What a WebGPU depth24plus texel is",
        defended: "WebGPU, Texture Formats (depth24plus): \"The depth component of the depth24plus and depth24plus-stencil8 formats may be implemented as either a 24-bit depth value or a depth32float value.\" The grid's texels are 24-bit UNORM values k / (2^24 − 1), written through frag_depth; the oracle's Dt is that value, and its f32 rounding (the depth32float reading) lies within the strict tier's f32 rounding of the comparison.",
        other: "The depth32float implementation: the texel is the f32 written, and the reference is not clamped where a UNORM format would clamp it (both accepted: contradiction `ref-clamp`).",
        sources: "WebGPU, Texture Formats (depth24plus); Copying Depth/Stencil Textures",
    },
    Contradiction {
        id: "webgpu-filter",
        title: "WebGPU filtered comparison",
        defended: "WebGPU, Samplers (GPUCompareFunction): \"After comparison, if texture filtering is enabled, the filtering step occurs, so that comparison results are mixed together resulting in values in the range [0, 1]. Filtering should behave as usual\": the weighted average of the 0/1 results is the spec value, accepted strictly.",
        other: "\"however it may be computed with lower precision or not mix results at all\" (and GPUSamplerDescriptor.compare's note: \"the sampling results will be implementation-dependent and may differ from the normal filtering rules\"): any value in [0,1] for a footprint with passes and fails is accepted by quality (Warn: the \"should\" not met).",
        sources: "WebGPU Samplers: GPUSamplerDescriptor (compare), GPUCompareFunction",
    },
    Contradiction {
        id: "non-fragment-base-texture",
        title: "Level of detail of an implicit-LOD lookup outside the fragment stage",
        defended: "GLSL 4.60 / GLSL ES 3.20 §8.9: \"level-of-detail is implicitly computed only for fragment shaders. Other shaders operate as though the base level-of-detail were computed as zero\": λ_base = 0, then GL 4.6 / ES 3.2 §8.14.1 and §8.14.3 as for any λ (TEXTURE_LOD_BIAS, the MIN_LOD / MAX_LOD clamp, magnification for λ ≤ c, else minification by the mipmapped filter). The spec value follows it; the other reading is accepted too, named.",
        other: "The same section's next paragraph, and the only text of GLSL 1.20 / 1.30 §8.7 and GLSL ES 3.00 §8.8: \"If it is mipmapped and running in a non-fragment shader, then the base texture is used\": level_base whatever the biases and clamps; the sentence names no filter, so level_base by the magnification filter or by the minification filter within a level is accepted. The two differ where TEXTURE_LOD_BIAS or MIN_LOD > 0 selects another level, or where the magnification and minification filters differ.",
        sources: "GLSL 4.60 §8.9; GLSL ES 3.20 §8.9; GLSL ES 3.00 §8.8; GLSL 1.20 / 1.30 §8.7; GL 4.6 §8.14.1, §8.14.3, §8.15",
    },
    Contradiction {
        id: "mirror-parens",
        title: "GL 4.6 Table 8.20 MIRRORED_REPEAT",
        defended: "ES 3.2 Table 8.21's well-formed (size − 1) − mirror((coord mod (2 × size)) − size).",
        other: "GL 4.6 prints unbalanced parentheses; no other well-formed reading yields a different texel.",
        sources: "GL 4.6 Table 8.20; ES 3.2 Table 8.21",
    },
];

/// The contradiction with this id.
pub fn get(id: &str) -> Option<&'static Contradiction> {
    ALL.iter().find(|c| c.id == id)
}

/// The contradictions a case touches.
pub fn touching(case: &Case) -> Vec<&'static Contradiction> {
    let s = &case.sampler;
    let compare = s.compare_mode == CompareMode::Compare && case.texture.format.is_depth();
    let filtered = s.mag_filter != Filter::Nearest
        || !matches!(s.min_filter, Filter::Nearest | Filter::NearestMipmapNearest);
    let d = case.lookup.dref;
    // The spec-specific contradictions concern a case only under a spec whose rules list them.
    let readings = crate::rules::rules_for(case.spec).readings;
    let concerns = |id: &str| readings.iter().any(|r| r.id == id);
    let mut out = Vec::new();
    for c in ALL {
        let hit = match c.id {
            "sgix-lequal-direction" => concerns(c.id) && compare,
            "sgix-ambient" => concerns(c.id) && compare,
            "ref-clamp" => compare && !(0.0..=1.0).contains(&d),
            "filtering" => compare && filtered,
            "result-layout" => true,
            "incomplete" => s.min_filter.is_mipmap(),
            "compat-float-alpha" => {
                compare
                    && case.api.contains(&shadowcheck_model::ApiPath::Glsl130)
                    && s.depth_texture_mode == Some(shadowcheck_model::DepthTextureMode::Alpha)
            }
            "compat-depth-cb" => {
                case.api.contains(&shadowcheck_model::ApiPath::Glsl130)
                    && case.texture.format.is_depth()
                    && (s.swizzle.is_some() || !compare)
            }
            "gather-swizzle" => {
                case.lookup.gather.is_some()
                    && s.swizzle
                        .is_some_and(|sw| sw[0] != shadowcheck_model::Swizzle::Red)
            }
            "bad-operator-error" => false,
            "es2-greater-row" => {
                concerns(c.id) && compare && s.compare_func == CompareFunc::Greater
            }
            "vk-filter-linear-bit" | "webgpu-filter" => concerns(c.id) && compare && filtered,
            "webgpu-depth24plus" => {
                concerns(c.id)
                    && matches!(
                        case.texture.format,
                        shadowcheck_model::Format::D24 | shadowcheck_model::Format::D24S8
                    )
            }
            "non-fragment-base-texture" => crate::engine::stage_touches(case),
            "mirror-parens" => {
                concerns(c.id) && [s.wrap_s, s.wrap_t, s.wrap_r].contains(&Wrap::MirroredRepeat)
            }
            _ => false,
        };
        if hit {
            out.push(c);
        }
    }
    out
}

/// The rules under the other reading of `id` for this case, where the other reading changes a rule:
/// the spec's own other reading (`Rules::readings`), else for `ref-clamp` the neighbouring
/// documents' clamp.
pub fn alternative_rules(case: &Case, id: &str) -> Option<Rules> {
    let r = crate::rules::rules_for(case.spec);
    if let Some(reading) = r.readings.iter().find(|x| x.id == id) {
        return reading.other.map(|other| other(r));
    }
    match id {
        "ref-clamp" => Some(Rules {
            ref_clamp: match r.ref_clamp {
                RefClamp::Always | RefClamp::Unstated => RefClamp::FixedPointOnly,
                RefClamp::FixedPointOnly => RefClamp::Always,
            },
            ..r
        }),
        _ => None,
    }
}
