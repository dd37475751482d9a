//! What distinguishes one specification from another, as data. Each spec module (`sgix`, `arb`,
//! `ext_funcs`, `es2_ext`, `gl46`, `gles32`, `vulkan`) fills a [`Rules`] beside the sentences it encodes; the
//! shared machinery (`engine`, `sample`, `select`, `lod`, `layout`, `check`, `state`,
//! `contradictions`) reads only this struct and never matches on the spec itself. [`rules_for`] is
//! the registry: adding a spec is one module and one line there.

use crate::state::{Ctx, Param};
use shadowcheck_model::{ApiPath, CompareFunc, DepthTextureMode, Format, Spec, Target, Wrap};
use std::cmp::Ordering;

/// How the reference value Dref / R is clamped before the comparison.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RefClamp {
    /// Always clamped to [0,1] (ARB_shadow, GL ≤ 2.1, EXT_shadow_samplers).
    Always,
    /// Clamped only for fixed-point depth formats (ARB_depth_buffer_float rev 7, GL 3.0+, ES 3.x).
    FixedPointOnly,
    /// The spec does not say (SGIX_shadow): both readings are accepted, the literal (no clamp) is the
    /// spec value.
    Unstated,
}

/// How a border depth (TEXTURE_BORDER_COLOR[0]) becomes Dt.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BorderRule {
    /// Border colour values lie in [0,1] (GL ≤ 2.1 clamps TEXTURE_BORDER_COLOR when it is set).
    ClampUnit,
    /// GL 4.6 §8.14.2: "If border values are out-of-range with respect to the texture's internal
    /// format, the result is undefined."
    UndefinedOutOfRange,
    /// ES 3.2 §8.14.2: "Border values are clamped before they are used, according to the format".
    ClampToFormat,
    /// ES 2.0 has no CLAMP_TO_BORDER; never reached.
    None,
}

/// How a filtered (multi-texel) comparison result is defined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Filtering {
    /// SGIX_shadow: compare, then filter the 0/1 values: r is exactly the weighted average.
    BeforeFilter,
    /// ARB_shadow and later: "implementation-dependent ... proportional to the number of passes".
    ImplementationDependent,
}

/// The result of a lookup on an incomplete texture.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Incomplete {
    /// GL 2.1 §3.11.2 / ARB_fragment_program_shadow / ES 2.0: (R,G,B,A) = (0,0,0,1).
    Legacy0001,
    /// GL 4.6 / ES 3.2 §11.1.3.5: "0 for a shadow sampler" ((0,0,0,1) for the legacy vec4 paths).
    ShadowZero,
    /// The API has no incomplete textures (Vulkan): a case GL would call incomplete is not
    /// applicable; the sentence says why.
    NotApplicable(&'static str),
}

/// The function is not in the spec's table (setting it is a GL error).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NotInTable;

/// The comparison table of one spec: `ord` is Dref compared with Dt (`Dref.partial_cmp(Dt)`), already
/// clamped per the spec. Returns pass (1.0) / fail (0.0 or the fail value); `None` when the result
/// depends on an unordered (NaN) operand. `Err` when the function is not in this spec's table.
pub type CompareTable = fn(CompareFunc, Option<Ordering>) -> Result<Option<bool>, NotInTable>;

/// A contradiction (see `contradictions`) that concerns this spec in particular, and the rules under
/// its other reading (`None`: the other reading changes no rule).
#[derive(Debug, Clone, Copy)]
pub struct Reading {
    pub id: &'static str,
    pub other: Option<fn(Rules) -> Rules>,
}

/// Everything the shared machinery needs to know about one specification.
#[derive(Debug, Clone, Copy)]
pub struct Rules {
    pub spec: Spec,
    /// Short document name used in citations, e.g. "GL 4.6".
    pub doc: &'static str,
    pub table: CompareTable,
    /// Citation of the comparison table.
    pub table_cite: &'static str,
    pub ref_clamp: RefClamp,
    /// Citation of the clamping sentence.
    pub clamp_cite: &'static str,
    pub border: BorderRule,
    pub filtering: Filtering,
    pub filter_cite: &'static str,
    pub incomplete: Incomplete,
    /// ES 3.2 §8.17: a sized depth texture with compare mode NONE and non-NEAREST filtering is incomplete.
    pub es_depth_completeness: bool,
    /// Cube maps are always seamless (ES 3.x); GL 4.6's TEXTURE_CUBE_MAP_SEAMLESS starts disabled.
    pub seamless_cube: bool,
    /// TEXTURE_CUBE_MAP_SEAMLESS can be enabled and disabled (GL 3.2+): the sentence; `None`
    /// where the spec has no such enable (a case setting it is not applicable).
    pub seamless_enable: Option<&'static str>,
    /// TEXTURE_SWIZZLE_R/G/B/A exist (GL 3.3+, ES 3.0+): the sentence; `None`: no swizzle.
    pub swizzle: Option<&'static str>,
    /// Sampler objects exist (GL 3.3+, ES 3.0+): the sentence saying their state is used instead
    /// of the texture's; `None`: no sampler objects.
    pub sampler_objects: Option<&'static str>,
    /// TEXTURE_LOD_BIAS exists (not in ES).
    pub lod_bias: bool,
    /// The array layer is RNE(a), or ⌊a + 1/2⌋ as the alternative, under every filter (Vulkan):
    /// the sentence. `None`: GL's rule, RNE (or ⌊r + 1/2⌋) under NEAREST and ⌊r + 1/2⌋ under
    /// LINEAR (GL 4.6 / ES 3.2 §8.14.2).
    pub layer_rne_always: Option<&'static str>,
    /// The sampling state is set when a sampler is created, not by TexParameter (Vulkan): the
    /// sentence. A value outside the spec's tables is then not applicable, never a GL error.
    pub sampler_create: Option<&'static str>,
    /// The fail/ambient value replaces 0.0 (ARB_shadow_ambient, SGIX_shadow_ambient): the citation of
    /// that sentence; `None` when the spec has no fail value.
    pub fail_value_cite: Option<&'static str>,
    /// The fail value replaces the *passing* 1.0 instead (the overview reading of SGIX_shadow_ambient,
    /// contradiction `sgix-ambient`; never the defended reading).
    pub ambient_on_pass: bool,
    /// Targets this spec defines depth textures (and shadow lookups) for.
    pub targets: &'static [Target],
    /// Wrap modes accepted by TexParameter in this spec (CLAMP additionally needs a compatibility context).
    pub wraps: &'static [Wrap],
    /// API paths through which this spec's lookups can be made.
    pub apis: &'static [ApiPath],
    /// DEPTH_TEXTURE_MODE values accepted (empty: the pname does not exist).
    pub depth_modes: &'static [DepthTextureMode],
    /// DEPTH_STENCIL_TEXTURE_MODE exists (GL 4.3+, ES 3.1+).
    pub depth_stencil_mode: bool,
    /// The error a compare function outside the table raises (SGIX: INVALID_OPERATION).
    pub bad_func_error: &'static str,
    /// Texture formats this spec defines depth textures (or the colour bypass) for.
    pub formats: &'static [Format],
    /// The pnames that set the compare mode and the compare function (SGIX: its own tokens).
    pub mode_pname: u32,
    pub func_pname: u32,
    /// The depth-comparison TexParameter pnames this spec defines in a context (its table in `state`
    /// terms); `Spec` tells a module's variants apart.
    pub params: fn(Spec, Ctx) -> Vec<Param>,
    /// TEXTURE_BASE_LEVEL / MAX_LEVEL / MIN_LOD / MAX_LOD do not exist: why (setting them is an error).
    pub no_lod_state: Option<&'static str>,
    /// The lookup functions take no bias argument: why (a biased lookup is not applicable).
    pub no_lookup_bias: Option<&'static str>,
    /// The DEPTH_TEXTURE_MODE in effect whatever the sampler says (SGIX: LUMINANCE).
    pub fixed_depth_mode: Option<DepthTextureMode>,
    /// A colour texture reads as LUMINANCE8, (r,r,r,1) (the legacy desktop specs); otherwise as R8.
    pub colour_luminance: bool,
    /// Said when a colour texture is looked up (SGIX defines its operators for depth textures only).
    pub colour_note: Option<&'static str>,
    /// The contradictions that concern this spec in particular and their other readings.
    pub readings: &'static [Reading],
    /// A mipmapped lookup outside the fragment stage takes level_base by the magnification
    /// filter as its spec value ("then the base texture is used", reading B of contradiction
    /// `non-fragment-base-texture`) instead of λ_base = 0 through §8.14 (reading A, every spec's own):
    /// the other reading, for `explain`; both are accepted either way.
    pub non_fragment_base_texture: bool,
}

/// Contradiction `non-fragment-base-texture`'s other reading as rules.
pub(crate) fn non_fragment_base_texture(r: Rules) -> Rules {
    Rules {
        non_fragment_base_texture: true,
        ..r
    }
}

/// The reading every spec with a vertex-stage lookup lists (`readings`).
pub(crate) const VERTEX_BASE_TEXTURE: Reading = Reading {
    id: "non-fragment-base-texture",
    other: Some(non_fragment_base_texture),
};

/// The rules of a spec variant: the registry of spec modules.
pub fn rules_for(spec: Spec) -> Rules {
    match spec {
        Spec::Sgix | Spec::SgixAmbient => crate::sgix::rules(spec),
        Spec::Arb | Spec::ArbAmbient => crate::arb::rules(spec),
        Spec::ExtFuncs => crate::ext_funcs::rules(),
        Spec::Es2Ext => crate::es2_ext::rules(),
        Spec::Gl46 => crate::gl46::rules(),
        Spec::Gles32 => crate::gles32::rules(),
        Spec::Vulkan => crate::vulkan::rules(),
        Spec::WebGpu => crate::webgpu::rules(),
    }
}

/// Helpers shared by the tables: pass when `ord` is one of `pass`.
pub(crate) fn passes_if(ord: Option<Ordering>, pass: &[Ordering]) -> Option<bool> {
    ord.map(|o| pass.contains(&o))
}
