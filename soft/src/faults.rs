//! Seedable faults: realistic texture-unit bugs that can be switched on one at a time (or several)
//! to check that the harness catches them (`shadowcheck mutants`).
//!
//! A [`SoftUnit`](crate::SoftUnit) carries a [`Faults`] bitset. The sampler code tests single bits
//! at the places where the corresponding real-world bug would sit; with no fault set every test is
//! one predictable branch on a field that is already in cache, so the correct unit pays almost
//! nothing for the switches.

use shadowcheck_model::Spec;
use std::fmt;

macro_rules! faults {
    ($( $(#[$m:meta])* $var:ident = $key:literal ),+ $(,)?) => {
        /// One seedable fault. The key is the name used on the command line and in reports.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[repr(u8)]
        pub enum Fault { $( $(#[$m])* $var ),+ }
        impl Fault {
            /// Every fault, in declaration order.
            pub const ALL: &'static [Fault] = &[$(Fault::$var),+];
            /// Short stable name (kebab-case).
            pub fn key(self) -> &'static str { match self { $(Fault::$var => $key),+ } }
            /// Parses a name written by [`Fault::key`].
            pub fn from_key(s: &str) -> Option<Fault> { match s { $($key => Some(Fault::$var),)+ _ => None } }
        }
    };
}

faults! {
    // --- reference value and Dt clamping (GL 4.6 §8.23.1, ARB_shadow, EXT_shadow_samplers) ---
    /// Dref clamped to [0,1] even for floating-point depth formats (GL 3.0+ clamps only fixed-point).
    RefClampedForFloat = "ref-clamped-for-float",
    /// Dref never clamped, even for fixed-point formats / specs that always clamp.
    RefNotClamped = "ref-not-clamped",
    /// Dt clamped to [0,1] at sample time for floating-point formats (visible with a border > 1).
    DtClampedForFloat = "dt-clamped-for-float",
    /// Dt (incl. the border depth) not clamped for fixed-point formats.
    DtNotClamped = "dt-not-clamped",
    // --- filtering (PCF) ---
    /// Filter the depth values first, then compare once (no percentage-closer filtering).
    FilterThenCompare = "filter-then-compare",
    /// LINEAR weights computed from u instead of u - 1/2 (footprint and weights off by half a texel).
    PcfHalfTexelOff = "pcf-half-texel-off",
    /// LINEAR filtering ignores the second texel in each direction (weights 1,0).
    LinearAsNearest = "linear-as-nearest",
    // --- comparison functions (Table 8.23) ---
    /// LEQUAL and GEQUAL swapped.
    LequalGequalSwapped = "lequal-gequal-swapped",
    /// LESS evaluated as LEQUAL.
    LessAsLequal = "less-as-lequal",
    /// GREATER evaluated as GEQUAL.
    GreaterAsGequal = "greater-as-gequal",
    /// EQUAL / NOTEQUAL compare with a tolerance of 2^-12 instead of exactly.
    EqualWithTolerance = "equal-with-tolerance",
    /// NOTEQUAL implemented as (Dref < Dt || Dref > Dt): a NaN reference fails instead of passing.
    NanOrderedNotequal = "nan-ordered-notequal",
    /// ALWAYS and NEVER swapped.
    AlwaysNeverSwapped = "always-never-swapped",
    /// SGIX operators read as ARB issue 2 describes them (R <= texel for TEXTURE_LEQUAL_R_SGIX).
    SgixOperatorsReversed = "sgix-operators-reversed",
    // --- fail / ambient value ---
    /// The ambient / fail value replaces 1.0 for passing texels instead of 0.0 for failing ones.
    AmbientAppliedToPass = "ambient-applied-to-pass",
    /// The ambient / fail value is ignored (0.0 used).
    AmbientIgnored = "ambient-ignored",
    /// TEXTURE_COMPARE_FAIL_VALUE_ARB / SHADOW_AMBIENT_SGIX used as set, not clamped to [0, 1].
    FailValueNotClamped = "fail-value-not-clamped",
    // --- result layout (DEPTH_TEXTURE_MODE, Table 16.1) ---
    /// DEPTH_TEXTURE_MODE RED returned as LUMINANCE (r,r,r,1).
    RedModeAsLuminance = "red-mode-as-luminance",
    /// INTENSITY returned as LUMINANCE (alpha 1 instead of r).
    IntensityAsLuminance = "intensity-as-luminance",
    /// Wrong default DEPTH_TEXTURE_MODE in compatibility paths (RED instead of LUMINANCE).
    WrongDefaultDepthMode = "wrong-default-depth-mode",
    /// GLSL 1.30 shadow lookup with DEPTH_TEXTURE_MODE ALPHA returns Cs[0] of (0, 0, 0, r), i.e. 0.
    AlphaModeZeroOnGlsl130 = "alpha-mode-zero-on-glsl130",
    /// GLSL 1.20 vec4 `shadow*()` ignores DEPTH_TEXTURE_MODE (always LUMINANCE).
    Glsl120IgnoresDepthMode = "glsl120-ignores-depth-mode",
    // --- which textures take part ---
    /// Comparison applied to a colour (R8) texture instead of being bypassed.
    CompareAppliedToColour = "compare-applied-to-colour",
    /// A colour texture of several components (RG8, RGB8, RGBA8, RGBA4) read as RED: (R, 0, 0, 1),
    /// the other components dropped (Table 15.1 not followed past R).
    ColourAsRed = "colour-as-red",
    /// The A of an RG / RGB colour texture read as 0 instead of 1 (Table 15.1: Ab = 1).
    ColourAlphaZero = "colour-alpha-zero",
    /// DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX ignored (depth returned).
    StencilModeIgnored = "stencil-mode-ignored",
    /// STENCIL_INDEX mode honoured, but with TEXTURE_COMPARE_MODE on the stencil index is compared
    /// with Dref (the sampler's compare state not turned off for stencil sampling).
    StencilCompared = "stencil-compared",
    // --- completeness (§8.17, §11.1.3.5) ---
    /// An incomplete texture is sampled as if complete instead of returning 0 / (0,0,0,1).
    IncompleteNotZero = "incomplete-not-zero",
    /// An incomplete texture read through an unsigned integer sampler (STENCIL_INDEX) returns
    /// (0, 0, 0, 0) instead of the (0, 0, 0, 1) of a non-shadow sampler (§11.1.3.5).
    IncompleteStencilAlphaZero = "incomplete-stencil-alpha-zero",
    /// Missing mip levels not detected (mipmap filters sample what exists).
    MipmapCompletenessIgnored = "mipmap-completeness-ignored",
    /// The ES rule "sized depth, compare NONE, non-NEAREST filter is incomplete" ignored.
    EsDepthFilterCompletenessIgnored = "es-depth-filter-completeness-ignored",
    // --- coordinates ---
    /// Projective lookups: nothing is divided by q.
    ProjectiveDivideMissing = "projective-divide-missing",
    /// Projective lookups: coordinates divided by q but Dref not.
    RefNotDividedByQ = "ref-not-divided-by-q",
    /// Array layer truncated (floor) instead of rounded.
    LayerTruncated = "layer-truncated",
    /// Array layer rounded to nearest even (the NEAREST formula of §8.14.2) also under LINEAR, where
    /// the text gives ⌊r + 1/2⌋ (layer 0.5 → 0 instead of 1).
    LayerRneUnderLinear = "layer-rne-under-linear",
    /// Cube map -Y face: t_c taken as +r_z instead of -r_z.
    CubeNegYFlipped = "cube-neg-y-flipped",
    /// The texel offset of `textureOffset` & co. dropped.
    OffsetIgnored = "offset-ignored",
    /// The texel offset applied in texels of the base level at every level (converted once to a
    /// normalized offset), instead of in texels of the selected level (§8.14.3).
    OffsetInBaseLevelTexels = "offset-in-base-level-texels",
    /// The texel offset added to the already wrapped texel index and clamped into the image,
    /// instead of to u, v before wrapping (REPEAT does not wrap the offset texel).
    OffsetAfterWrap = "offset-after-wrap",
    // --- level of detail (§8.14) ---
    /// NEAREST-mipmap level selection one level too far (d + 1, clamped to q).
    MipLevelOffByOne = "mip-level-off-by-one",
    /// Trilinear (… _MIPMAP_LINEAR) filters use level d1 only, no blend.
    TrilinearNoBlend = "trilinear-no-blend",
    /// TEXTURE_LOD_BIAS ignored.
    LodBiasIgnored = "lod-bias-ignored",
    /// TEXTURE_MIN_LOD / TEXTURE_MAX_LOD clamp ignored.
    LodClampIgnored = "lod-clamp-ignored",
    /// TEXTURE_MAX_LEVEL ignored when computing q.
    MaxLevelIgnored = "max-level-ignored",
    // --- wrapping and border (§8.14.2) ---
    /// CLAMP_TO_BORDER behaves as CLAMP_TO_EDGE (border never used).
    BorderIgnored = "border-ignored",
    /// Border depth read from the alpha component of TEXTURE_BORDER_COLOR.
    BorderDepthFromAlpha = "border-depth-from-alpha",
    /// MIRRORED_REPEAT mirrors without the (size - 1) offset (off by one texel).
    MirroredRepeatOffByOne = "mirrored-repeat-off-by-one",
    // --- shadow textureGather (GL 4.6 §8.14.2, GLSL 4.60 §8.9.4) ---
    /// Gather components taken in a rotated texel order (τi0j0, τi0j1, τi1j1, τi1j0) instead of
    /// (τi0j1, τi1j1, τi1j0, τi0j0).
    GatherOrderRotated = "gather-order-rotated",
    /// Shadow gather returns the texels' depth values, ignoring refZ (no comparison).
    GatherIgnoresRef = "gather-ignores-ref",
    /// Gather reads the level the filters' λ selects instead of level base.
    GatherUsesLodLevel = "gather-uses-lod-level",
    /// textureGatherOffset with an offset that is not a constant expression (a uniform, a flat
    /// input or a per-fragment value; GLSL 4.60 §8.9.4: "the offset can be variable (non
    /// constant)") gathers at offset (0, 0), as by a compiler that folds only constant offsets
    /// into its gather instruction and drops the rest.
    VariableGatherOffsetZero = "variable-gather-offset-zero",
    /// A vertex-stage lookup of an implicit-LOD function given the λ_base a fragment shader
    /// would compute from the coordinates' derivatives, where GLSL 4.60 / GLSL ES 3.20 §8.9 says
    /// "Other shaders operate as though the base level-of-detail were computed as zero" (a unit
    /// that runs its fragment LOD path for every stage).
    VertexLodFromDerivatives = "vertex-lod-from-derivatives",
    /// The same in a compute shader: the compute-stage lookup given the fragment shader's λ_base
    /// (GLSL 4.60 / GLSL ES 3.20 §8.9 names every stage but the fragment one alike).
    ComputeLodFromDerivatives = "compute-lod-from-derivatives",
    // --- unit state: swizzle, seamless enable, sampler objects (GL 3.2 / 3.3, ES 3.0) ---
    /// TEXTURE_SWIZZLE_* ignored (the unswizzled base colour returned).
    SwizzleIgnored = "swizzle-ignored",
    /// The swizzle applied to the stored depth before the comparison (Dref compared with Cs[0]
    /// of (Dt, 0, 0, 1)) instead of to the comparison result Cb = (Rt, 0, 0, 1).
    SwizzleBeforeCompare = "swizzle-before-compare",
    /// GL's TEXTURE_CUBE_MAP_SEAMLESS enable ignored (cube maps filtered per face).
    SeamlessIgnored = "seamless-ignored",
    /// Vulkan's Cube Map Edge Handling skipped: LINEAR filtering at a cube face edge clamps within
    /// the face, as GL does with TEXTURE_CUBE_MAP_SEAMLESS disabled (a GL-derived texture unit
    /// under a Vulkan driver keeping GL's default).
    VkCubeEdgePerFace = "vk-cube-edge-per-face",
    /// A bound sampler object's state ignored in favour of the texture's own parameters.
    SamplerObjectIgnored = "sampler-object-ignored",
    // --- WebGPU / WGSL only (no effect on a unit for another spec, see [`Fault::spec`]) ---
    /// GPUCompareFunction applied with the operands the other way round: the sampled value
    /// compared against the provided depth_ref ("less" passes when texel < depth_ref), as by a
    /// backend that maps the enum onto an API whose comparison reads the other way.
    WgpuCompareOperandsSwapped = "wgpu-compare-operands-swapped",
    /// WGSL array_index wrapped modulo the layer (cube) count instead of clamped to
    /// [0, textureNumLayers(t) − 1] (a shader translator's robustness pass that wraps the index).
    WgpuArrayIndexWrapped = "wgpu-array-index-wrapped",
    /// A "cube" / "cube-array" view filtered per face, not seamlessly across faces (a WebGPU
    /// implementation on desktop OpenGL that never enables TEXTURE_CUBE_MAP_SEAMLESS).
    WgpuCubePerFace = "wgpu-cube-per-face",
    /// A texture_depth_cube_array's array_index added to the face's layer (layer index + face)
    /// instead of selecting the cube (6 · index + face), as by a backend that emulates cube
    /// arrays on a 2D array texture and forgets the 6 layers per cube.
    WgpuCubeArrayIndexAsLayer = "wgpu-cube-array-index-as-layer",
    /// Shadow gather returns the unswizzled comparisons: TEXTURE_SWIZZLE_R not applied to each
    /// texel's (Rt, 0, 0, 1) before its R component is gathered (GL 4.6 §8.14.2) — a unit that
    /// routes textureGather around the swizzle stage, or follows only GLSL 4.60 §8.9.4's wording.
    GatherIgnoresSwizzle = "gather-ignores-swizzle",
    /// Shadow gather with the whole swizzle applied to the gathered vector, as to a filtered
    /// colour (component i = the swizzle's i-th pick of (τi0j1, τi1j1, τi1j0, τi0j0)), instead of
    /// TEXTURE_SWIZZLE_R to each texel's (Rt, 0, 0, 1): a unit that runs its ordinary post-filter
    /// swizzle on the result of textureGather.
    GatherSwizzlesVector = "gather-swizzles-vector",
    /// The swizzle ignored on the fixed-function / GLSL 1.20 paths (compatibility): the
    /// DEPTH_TEXTURE_MODE vec4 returned as is, as by a driver that swizzles only in its GLSL
    /// 1.30+ sampler code.
    CompatSwizzleDropped = "compat-swizzle-dropped",
    /// The sampler object's rectangle-illegal state (wrap S/T REPEAT, MIRRORED_REPEAT,
    /// MIRROR_CLAMP_TO_EDGE or a mipmap min filter) used as if legal instead of making the
    /// texture incomplete (GL 4.6 §8.2): the unit samples a rectangle texture with REPEAT.
    SamplerObjectRectComplete = "sampler-object-rect-complete",
    /// A shadow gather samples with the texture's own parameters although a sampler object is
    /// bound (GL 4.6 §8.17.1: the unit's sampling state is the sampler object's), as by a unit
    /// whose gather path builds its sampler state from the texture object: a pair interaction
    /// (gather x sampler object) that neither feature's own cases show.
    GatherIgnoresSamplerObject = "gather-ignores-sampler-object",
    // --- storage ---
    /// Unorm conversion c / 2^b instead of c / (2^b - 1).
    UnormDividedByPowerOfTwo = "unorm-divided-by-power-of-two",
    /// Floating-point depth not clamped to [0, 1] at upload (§8.5).
    UploadNotClamped = "upload-not-clamped",
    /// Colour (R8) conversion c/256 instead of c/255 (eq. (2.1)); depth formats converted correctly.
    ColourDividedBy256 = "colour-divided-by-256",
    // --- TexParameter state (state cases, GL 4.6 §8.10, Table 23.15) ---
    /// A new texture's TEXTURE_COMPARE_FUNC is LESS instead of LEQUAL.
    WrongInitialCompareFunc = "wrong-initial-compare-func",
    /// An illegal enum value for a depth-comparison pname is stored instead of raising INVALID_ENUM.
    IllegalValueStored = "illegal-value-stored",
    /// A pname an exposed extension adds (TEXTURE_COMPARE_FAIL_VALUE_ARB with ARB_shadow_ambient,
    /// the SGIX_shadow pnames) rejected with INVALID_ENUM, as if the extension string did not list
    /// the extension (seen only by a context that exposes it).
    ExtensionPnameRejected = "extension-pname-rejected",
}

impl Fault {
    /// The one spec whose variant the fault belongs to, for faults modelled on one API's own
    /// rules (`None`: any spec's unit can have it). A unit for another spec ignores the fault
    /// ([`Faults::for_spec`]).
    pub fn spec(self) -> Option<Spec> {
        match self {
            Fault::VkCubeEdgePerFace => Some(Spec::Vulkan),
            Fault::WgpuCompareOperandsSwapped
            | Fault::WgpuArrayIndexWrapped
            | Fault::WgpuCubePerFace
            | Fault::WgpuCubeArrayIndexAsLayer => Some(Spec::WebGpu),
            _ => None,
        }
    }

    /// Whether the fault sits in TexParameter state (seen by state cases, never by a lookup case,
    /// whose sampler state is always set explicitly).
    pub fn is_state(self) -> bool {
        matches!(
            self,
            Fault::WrongInitialCompareFunc
                | Fault::IllegalValueStored
                | Fault::ExtensionPnameRejected
        )
    }
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// A set of faults (bitset over [`Fault`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Faults(u128);

impl Faults {
    /// No fault: the correct texture unit.
    pub const NONE: Faults = Faults(0);

    pub fn with(self, f: Fault) -> Faults {
        Faults(self.0 | (1u128 << f as u8))
    }
    #[inline(always)]
    pub fn has(self, f: Fault) -> bool {
        self.0 & (1u128 << f as u8) != 0
    }
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
    /// The faults of this set that a unit for `spec` has: those of [`Fault::spec`] `None` or
    /// `spec` (a WebGPU-only fault does nothing in a GL unit).
    pub fn for_spec(self, spec: Spec) -> Faults {
        self.iter()
            .filter(|f| f.spec().is_none_or(|s| s == spec))
            .collect()
    }
    /// The faults in the set, in declaration order.
    pub fn iter(self) -> impl Iterator<Item = Fault> {
        Fault::ALL.iter().copied().filter(move |f| self.has(*f))
    }
}

impl FromIterator<Fault> for Faults {
    fn from_iter<I: IntoIterator<Item = Fault>>(it: I) -> Faults {
        it.into_iter().fold(Faults::NONE, Faults::with)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_round_trip_and_fit_the_bitset() {
        assert!(Fault::ALL.len() >= 30 && Fault::ALL.len() <= 128);
        for f in Fault::ALL {
            assert_eq!(Fault::from_key(f.key()), Some(*f));
        }
        let set: Faults = [Fault::BorderIgnored, Fault::LessAsLequal]
            .into_iter()
            .collect();
        assert!(set.has(Fault::BorderIgnored) && set.has(Fault::LessAsLequal));
        assert!(!set.has(Fault::AmbientIgnored));
        assert_eq!(set.iter().count(), 2);
        assert!(Faults::NONE.is_empty());
    }

    #[test]
    fn spec_only_faults_are_dropped_for_other_specs() {
        let set: Faults = [Fault::WgpuCubePerFace, Fault::LessAsLequal]
            .into_iter()
            .collect();
        assert_eq!(set.for_spec(Spec::WebGpu), set);
        let gl = set.for_spec(Spec::Gl46);
        assert!(gl.has(Fault::LessAsLequal) && !gl.has(Fault::WgpuCubePerFace));
        let vk = Faults::NONE.with(Fault::VkCubeEdgePerFace);
        assert!(vk.for_spec(Spec::WebGpu).is_empty());
    }
}
