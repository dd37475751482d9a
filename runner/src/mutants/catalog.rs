//! The fault catalog as the report tells it: what real defect each fault is modelled on, which
//! faults cannot be observed through the API (and why), the grid change that kills an observable
//! fault the default grid misses, and the witness case for each fault.

use shadowcheck_model::{ApiPath, Case, Spec};
use shadowcheck_soft::Fault;

/// The case that shows `fault`: the soft crate's witness, except where that witness sits on state
/// the specifications leave undefined, where a case from the grid change ([`grid_change`]) replaces it.
pub fn witness(fault: Fault) -> (Case, ApiPath) {
    let (mut case, api) = shadowcheck_soft::witness::witness(fault);
    if fault == Fault::DtNotClamped {
        // GL 4.6 leaves a fixed-point border outside [0,1] undefined; ARB_shadow has Dt in [0,1]:
        // border 1.5 reads as Dt = 1, and GEQUAL with R = 1 passes (r = 1; unclamped, 1 >= 1.5 fails).
        case.spec = Spec::Arb;
        case.api = vec![ApiPath::FixedFunction];
        case.sampler.compare_func = shadowcheck_model::CompareFunc::Gequal;
        case.lookup.dref = 1.0;
        return (case, ApiPath::FixedFunction);
    }
    (case, api)
}

/// The real-world defect each fault is modelled on (for the report).
pub fn about(f: Fault) -> &'static str {
    use Fault as F;
    match f {
        F::RefClampedForFloat => {
            "Dref clamped to [0,1] for a D32F texture (pre-GL 3.0 rule kept for float depth)"
        }
        F::RefNotClamped => "Dref not clamped for fixed-point formats",
        F::DtClampedForFloat => {
            "Dt clamped to [0,1] at sample time for float depth (border > 1 visible)"
        }
        F::DtNotClamped => "Dt (border) not clamped for fixed-point formats",
        F::FilterThenCompare => "filter the depths, then compare once (no PCF)",
        F::PcfHalfTexelOff => "PCF footprint and weights off by half a texel",
        F::LinearAsNearest => "LINEAR comparison sampled as NEAREST",
        F::LequalGequalSwapped => "LEQUAL and GEQUAL swapped (SGIX/ARB operator confusion)",
        F::LessAsLequal => "LESS treated as LEQUAL",
        F::GreaterAsGequal => "GREATER treated as GEQUAL",
        F::EqualWithTolerance => "EQUAL / NOTEQUAL with a tolerance",
        F::NanOrderedNotequal => "NOTEQUAL as an ordered compare (NaN Dref fails)",
        F::AlwaysNeverSwapped => "ALWAYS and NEVER swapped",
        F::SgixOperatorsReversed => "SGIX operators read as ARB issue 2 describes them",
        F::AmbientAppliedToPass => "ambient / fail value applied to passing texels",
        F::AmbientIgnored => "ambient / fail value ignored",
        F::FailValueNotClamped => {
            "TEXTURE_COMPARE_FAIL_VALUE_ARB / SHADOW_AMBIENT_SGIX not clamped to [0,1]"
        }
        F::RedModeAsLuminance => "DEPTH_TEXTURE_MODE RED returned as LUMINANCE",
        F::IntensityAsLuminance => "DEPTH_TEXTURE_MODE INTENSITY returned as LUMINANCE",
        F::WrongDefaultDepthMode => "wrong default DEPTH_TEXTURE_MODE in the compatibility profile",
        F::AlphaModeZeroOnGlsl130 => {
            "GLSL 1.30 shadow lookup with DEPTH_TEXTURE_MODE ALPHA returns 0 (Cs[0] of (0,0,0,r))"
        }
        F::Glsl120IgnoresDepthMode => "vec4 shadow2D (GLSL 1.20) ignoring DEPTH_TEXTURE_MODE",
        F::CompareAppliedToColour => "comparison applied to a colour (R8) texture",
        F::ColourAsRed => {
            "a colour texture of several components read as RED, (R,0,0,1) (Table 15.1 not followed past R)"
        }
        F::ColourAlphaZero => "the alpha of an RG / RGB colour texture read as 0 instead of 1 (Table 15.1)",
        F::IncompleteStencilAlphaZero => {
            "an incomplete texture read through a usampler (STENCIL_INDEX) returns (0,0,0,0), ANGLE's Vulkan back end (reports/webgl-cts)"
        }
        F::StencilModeIgnored => "DEPTH_STENCIL_TEXTURE_MODE STENCIL_INDEX ignored (depth sampled)",
        F::StencilCompared => "stencil index sampled with the comparison on under STENCIL_INDEX",
        F::IncompleteNotZero => "incomplete texture sampled instead of returning 0",
        F::MipmapCompletenessIgnored => "missing mip levels not detected",
        F::EsDepthFilterCompletenessIgnored => {
            "ES rule: sized depth + compare NONE + LINEAR not incomplete"
        }
        F::ProjectiveDivideMissing => "projective divide missing",
        F::RefNotDividedByQ => "projective divide of the coordinates but not of Dref",
        F::LayerTruncated => "array layer truncated instead of rounded",
        F::CubeNegYFlipped => "cube -Y face t coordinate flipped",
        F::OffsetIgnored => "texel offset of textureOffset & co. dropped",
        F::OffsetInBaseLevelTexels => "texel offset in base-level texels at every mip level",
        F::OffsetAfterWrap => {
            "texel offset added after wrapping (REPEAT does not wrap the offset texel)"
        }
        F::MipLevelOffByOne => "NEAREST-mipmap level off by one",
        F::TrilinearNoBlend => "trilinear filtering without the level blend",
        F::LodBiasIgnored => "TEXTURE_LOD_BIAS ignored",
        F::LodClampIgnored => "TEXTURE_MIN_LOD / MAX_LOD ignored",
        F::MaxLevelIgnored => "TEXTURE_MAX_LEVEL ignored",
        F::BorderIgnored => "border depth ignored (CLAMP_TO_BORDER as CLAMP_TO_EDGE)",
        F::BorderDepthFromAlpha => "border depth read from the alpha component",
        F::MirroredRepeatOffByOne => "MIRRORED_REPEAT off by one texel",
        F::UnormDividedByPowerOfTwo => "unorm conversion c/2^b instead of c/(2^b-1)",
        F::UploadNotClamped => "floating-point depth upload not clamped to [0,1]",
        F::LayerRneUnderLinear => {
            "array layer rounded to nearest even under LINEAR (GL 4.6 §8.14.2 LINEAR: ⌊r + 1/2⌋)"
        }
        F::ColourDividedBy256 => "colour (R8) conversion c/256 instead of c/255 (eq. (2.1))",
        F::GatherOrderRotated => {
            "shadow textureGather components in a rotated texel order (gather4_c emulation)"
        }
        F::GatherIgnoresRef => "shadow textureGather returns depths, refZ ignored (no comparison)",
        F::GatherUsesLodLevel => "textureGather reads the level λ selects instead of level base",
        F::VariableGatherOffsetZero => {
            "a non-constant textureGatherOffset offset (uniform, flat, per fragment) dropped"
        }
        F::VertexLodFromDerivatives => {
            "a vertex-shader texture() given the fragment shader's λ_base, not 0 (GLSL 4.60 §8.9)"
        }
        F::ComputeLodFromDerivatives => {
            "a compute-shader texture() given the fragment shader's λ_base, not 0 (GLSL 4.60 §8.9)"
        }
        F::WrongInitialCompareFunc => {
            "a new texture's TEXTURE_COMPARE_FUNC is LESS, not LEQUAL (GL 4.6 Table 23.15): seen by state cases"
        }
        F::IllegalValueStored => {
            "an illegal TexParameter enum value stored instead of INVALID_ENUM (GL 4.6 §8.10): seen by state cases"
        }
        F::ExtensionPnameRejected => {
            "a pname the exposed extension adds rejected with INVALID_ENUM (ARB_shadow_ambient / SGIX_shadow New Tokens): seen by state cases on a context exposing it"
        }
        F::SwizzleIgnored => "TEXTURE_SWIZZLE_* not applied to the depth / shadow result",
        F::SwizzleBeforeCompare => {
            "swizzle applied to the stored depth before the comparison, not to Cb = (Rt,0,0,1) (a translation layer swizzling the texel)"
        }
        F::SeamlessIgnored => {
            "GL's TEXTURE_CUBE_MAP_SEAMLESS enable ignored (cube maps filtered per face)"
        }
        F::VkCubeEdgePerFace => {
            "Vulkan Cube Map Edge Handling skipped: LINEAR at a face edge clamps within the face (GL's non-seamless default kept under Vulkan)"
        }
        F::WgpuCompareOperandsSwapped => {
            "WebGPU GPUCompareFunction applied as texel OP depth_ref instead of depth_ref OP texel (\"a provided value passes ... if it is less than the sampled value\", WebGPU, Samplers: GPUSamplerDescriptor)"
        }
        F::WgpuArrayIndexWrapped => {
            "WGSL array_index wrapped modulo the layer count instead of clamped to [0, textureNumLayers(t) - 1] (WGSL)"
        }
        F::WgpuCubePerFace => {
            "WebGPU cube views filtered per face, not seamlessly (a WebGPU implementation on desktop GL that never enables TEXTURE_CUBE_MAP_SEAMLESS; WebGPU createView.1)"
        }
        F::WgpuCubeArrayIndexAsLayer => {
            "texture_depth_cube_array's array_index counted in layers (index + face) instead of cubes (6 * index + face), as by a cube-array emulation on a 2D array (WebGPU createView.1 \"cube-array\")"
        }
        F::SamplerObjectIgnored => {
            "a bound sampler object's compare / filter / wrap / LOD state ignored in favour of the texture's"
        }
        F::GatherIgnoresSwizzle => {
            "shadow gather returns the unswizzled comparisons, not the post-swizzle R of each texel's (Rt,0,0,1) (GL 4.6 §8.14.2)"
        }
        F::GatherSwizzlesVector => {
            "the whole swizzle applied to the gathered vector as to a filtered colour, not TEXTURE_SWIZZLE_R to each texel's (Rt,0,0,1) (GL 4.6 §8.14.2)"
        }
        F::CompatSwizzleDropped => {
            "the swizzle ignored on the fixed-function / GLSL 1.20 paths (the Table 16.1 vec4 returned unswizzled)"
        }
        F::SamplerObjectRectComplete => {
            "a sampler object's rectangle-illegal state (REPEAT / MIRRORED_REPEAT / MIRROR_CLAMP_TO_EDGE, mipmap min filter) used as if legal instead of making the texture incomplete (GL 4.6 §8.2)"
        }
        F::GatherIgnoresSamplerObject => {
            "a shadow gather sampled with the texture's own compare function and wraps although a sampler object is bound (GL 4.6 §8.17.1): a gather x sampler object interaction only the `interact` covering array combines"
        }
        #[allow(unreachable_patterns)]
        _ => "",
    }
}

/// Why a fault cannot be observed through the API, for the faults where no conforming application
/// can tell the faulty unit from the correct one. Only reported for mutants the suite does not kill
/// and whose witness the oracle accepts.
pub fn unobservable(f: Fault) -> Option<&'static str> {
    Some(match f {
        Fault::NanOrderedNotequal => {
            "a NaN reference has no defined comparison result: Table 8.23 (and every extension's table) orders Dref and Dt, \
             GL 4.6 / ES 3.2 §2.3.4.1 leave the result of a NaN input unspecified, and clamping a NaN (fixed-point formats, \
             EXT_shadow_samplers) is not defined either; the oracle accepts 0 and 1 for every NaN-reference case, so treating \
             NOTEQUAL as ordered (NaN fails) is as conforming as IEEE != (NaN passes)"
        }
        Fault::AlphaModeZeroOnGlsl130 => {
            "a GLSL 1.30 shadow lookup in a compatibility context with DEPTH_TEXTURE_MODE ALPHA has two readings in the \
             texts: compatibility §11.1.3.5 returns Cs[0] of Cb = (Rt, 0, 0, 1) (r), while §8.23.1 with Table 16.1 assigns \
             r to At for ALPHA, so Cs[0] = 0; the oracle accepts both (contradiction `compat-float-alpha`), so returning 0 \
             is one of the two conforming readings"
        }
        Fault::GatherIgnoresSwizzle => {
            "a shadow gather's swizzle has two readings in the texts: GL 4.6 / ES 3.2 §8.14.2 gathers each texel's \
             post-swizzle R component (Figure 8.4), while GLSL 4.60 §8.9.4 says each comparison's result is returned \
             \"in the appropriate component of the result vector\"; the oracle accepts both (contradiction \
             `gather-swizzle`), so the unswizzled comparisons are one of the two conforming readings (the fault \
             `gather-swizzles-vector`, which neither reading allows, stands for a defect here)"
        }
        Fault::StencilCompared => {
            "a stencil read with TEXTURE_COMPARE_MODE not NONE has undefined results: GL 4.6 §11.1.3.5 \"the results of a \
             texture lookup are undefined if ... The sampler used in a texture lookup function is not one of the shadow \
             sampler types, the texture object's base internal format is DEPTH_COMPONENT or DEPTH_STENCIL, and the \
             TEXTURE_COMPARE_MODE is not NONE\" (a stencil read uses an unsigned integer sampler); the oracle accepts any \
             index there, so comparing the index is as conforming as ignoring the comparison"
        }
        _ => return None,
    })
}

/// The grid change (cases/src/grids) that kills a fault the default grid misses, where known; the
/// witness case is the generic answer.
pub fn grid_change(f: Fault) -> Option<&'static str> {
    Some(match f {
        Fault::EqualWithTolerance => {
            "cases/src/grids/families.rs `exact`: for EQUAL and NOTEQUAL also R = at ± 2^-14 (outside the quality \
             16-bit reference precision, inside the 2^-12 tolerance); the present at± (adjacent f32) cases only Warn"
        }
        Fault::DtNotClamped => {
            "cases/src/grids/families.rs `wrap`: for the pre-3.0 specs (sgix, arb, arb_ambient, ext_funcs), whose Dt is \
             in [0,1] (ARB_shadow 3.8.13.1), also the fixed-point format with CLAMP_TO_BORDER, border 1.5, R = 1, GEQUAL \
             (r = 1; unclamped Dt 1.5 gives 0) and border -0.5, R = 0, LEQUAL; GL 4.6 leaves a fixed-point border outside \
             [0,1] undefined and ES 3.2 clamps it, so gl46/gles32 cannot show this fault"
        }
        Fault::FailValueNotClamped => {
            "cases/src/grids/families.rs `ambient`: fail values 1.5 and -0.5 besides 0, 0.25, 0.5, 1 \
             (ARB_shadow_ambient: the value is clamped to [0,1] when specified)"
        }
        Fault::LayerTruncated => "cases/src/grids/families.rs `layer`: layer coordinates with a fraction of at least 0.5 (e.g. 1.5)",
        Fault::GatherIgnoresSamplerObject => {
            "cases/src/grids/interact.rs `interact`: a shadow gather with a bound sampler object whose compare function \
             differs from the texture's (GEQUAL against LEQUAL, a footprint split by rows); no other family combines them"
        }
        Fault::CubeNegYFlipped => "cases/src/grids/families.rs `cube`: -Y face lookups whose rows differ",
        Fault::OffsetInBaseLevelTexels | Fault::OffsetAfterWrap | Fault::OffsetIgnored => {
            "cases/src/grids/families.rs `offset`: offset lookups on a mip level above the base and with REPEAT \
             across the edge"
        }
        Fault::DtClampedForFloat => {
            "cases/src/grids/families.rs `wrap`: D32F with a border outside [0,1] and a function that tells 1 from 1.5"
        }
        _ => return None,
    })
}
