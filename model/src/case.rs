//! A case: one texture, one sampler state, one lookup, and (in fixtures) the oracle's expectation.

use crate::enums::*;
use crate::expect::Expectation;
use serde::{Deserialize, Serialize};

/// Stored depth values of one image (one mip level, all layers / cube faces).
///
/// Layout: x fastest, then y, then layer. Cube faces are layers in GL order
/// (+X, -X, +Y, -Y, +Z, -Z); a cube array has 6 layers per cube.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Texels {
    /// Unorm integers at the format's bit depth (also R8 colour values). Uploaded as integers so the
    /// stored value is exact.
    Unorm(Vec<u32>),
    /// Floating-point depth (D32F, D32F_S8). Finite values; the upload clamps them to [0,1].
    Float(Vec<f32>),
    /// A colour format of more than one component (RG8, RGB8, RGBA8, RGBA4): per texel the unorm
    /// integers (R, G, B, A) at the format's bits per component; the components the base format
    /// lacks (B and A of RG, A of RGB) are 0 and not uploaded.
    Colour(Vec<[u32; 4]>),
}

impl Texels {
    pub fn len(&self) -> usize {
        match self {
            Texels::Unorm(v) => v.len(),
            Texels::Float(v) => v.len(),
            Texels::Colour(v) => v.len(),
        }
    }
    /// One component of colour texels as unorm integers (component 0 of [`Texels::Unorm`] is the
    /// texels themselves); `None` for float texels or a component out of range.
    pub fn component(&self, i: usize) -> Option<Vec<u32>> {
        match self {
            Texels::Unorm(v) if i == 0 => Some(v.clone()),
            Texels::Colour(v) if i < 4 => Some(v.iter().map(|c| c[i]).collect()),
            _ => None,
        }
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One mip level.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Level {
    pub width: u32,
    pub height: u32,
    /// Array layers (6 for a cube, 6 x n for a cube array, 1 otherwise).
    pub layers: u32,
    pub depth: Texels,
    /// Stencil indices for DEPTH_STENCIL formats, same layout as `depth`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stencil: Option<Vec<u8>>,
}

impl Level {
    pub fn texel_count(&self) -> usize {
        self.width as usize * self.height as usize * self.layers as usize
    }
}

/// The texture object: target, format and the images of its levels (levels[0] is level base).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Texture {
    pub target: Target,
    pub format: Format,
    /// TEXTURE_BASE_LEVEL; `levels[0]` is this level.
    #[serde(default)]
    pub base_level: u32,
    pub levels: Vec<Level>,
}

/// Sampler / texture-parameter state that takes part in the lookup.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sampler {
    pub compare_mode: CompareMode,
    pub compare_func: CompareFunc,
    /// DEPTH_TEXTURE_MODE (compatibility / legacy paths only). `None`: the context's default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth_texture_mode: Option<DepthTextureMode>,
    /// DEPTH_STENCIL_TEXTURE_MODE. `None`: default (DEPTH_COMPONENT).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth_stencil_mode: Option<DepthStencilMode>,
    pub min_filter: Filter,
    pub mag_filter: Filter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub wrap_r: Wrap,
    /// TEXTURE_BORDER_COLOR; the depth border is its first component.
    pub border: [f32; 4],
    #[serde(default = "default_min_lod")]
    pub min_lod: f32,
    #[serde(default = "default_max_lod")]
    pub max_lod: f32,
    /// TEXTURE_LOD_BIAS (not in ES).
    #[serde(default)]
    pub lod_bias: f32,
    /// TEXTURE_MAX_LEVEL; `None`: default (1000).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_level: Option<u32>,
    /// TEXTURE_COMPARE_FAIL_VALUE_ARB (arb_ambient) or SHADOW_AMBIENT_SGIX (sgix_ambient).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fail_value: Option<f32>,
    /// TEXTURE_SWIZZLE_R/G/B/A (texture state, GL 3.3+ / ES 3.0+), applied to the base colour Cb
    /// (GL 4.6 §15.2.1). `None`: the initial value (RED, GREEN, BLUE, ALPHA).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub swizzle: Option<[Swizzle; 4]>,
    /// The context's TEXTURE_CUBE_MAP_SEAMLESS enable (GL 3.2+, §8.13.1) while the lookup runs.
    /// `None`: the context default (GL: disabled; ES 3.x: always seamless, no such enable).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seamless: Option<bool>,
    /// The state of a sampler object bound to the texture unit (GL 3.3+ / ES 3.0+, §8.2). Its
    /// state is used instead of the texture's sampling state above (§8.17.1); `None`: no sampler
    /// object bound (the texture's own state is used). Kept beside the texture state so that the
    /// pair is one value wherever "the sampling state of a case" is compared.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler_object: Option<SamplerObject>,
}

/// The parameters of a sampler object (GL 4.6 Table 23.18 / ES 3.2 §8.2): everything but
/// DEPTH_STENCIL_TEXTURE_MODE, DEPTH_TEXTURE_MODE, the swizzle, TEXTURE_BASE_LEVEL and
/// TEXTURE_MAX_LEVEL, which stay texture state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SamplerObject {
    pub compare_mode: CompareMode,
    pub compare_func: CompareFunc,
    pub min_filter: Filter,
    pub mag_filter: Filter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub wrap_r: Wrap,
    pub border: [f32; 4],
    #[serde(default = "default_min_lod")]
    pub min_lod: f32,
    #[serde(default = "default_max_lod")]
    pub max_lod: f32,
    /// TEXTURE_LOD_BIAS (not in ES).
    #[serde(default)]
    pub lod_bias: f32,
}

impl Sampler {
    /// The sampling parameters a lookup uses: with a sampler object bound, its parameters replace
    /// the texture's (GL 4.6 §8.17.1: "the sampling state for that unit is taken from the sampler
    /// object"); the rest (DEPTH_TEXTURE_MODE, DEPTH_STENCIL_TEXTURE_MODE, swizzle, MAX_LEVEL, fail
    /// value) stays the texture's. For backends choosing a sampler type or declaring a feature;
    /// the oracle and the soft unit resolve the two states on their own.
    pub fn in_effect(&self) -> std::borrow::Cow<'_, Sampler> {
        let Some(o) = &self.sampler_object else {
            return std::borrow::Cow::Borrowed(self);
        };
        std::borrow::Cow::Owned(Sampler {
            compare_mode: o.compare_mode,
            compare_func: o.compare_func,
            min_filter: o.min_filter,
            mag_filter: o.mag_filter,
            wrap_s: o.wrap_s,
            wrap_t: o.wrap_t,
            wrap_r: o.wrap_r,
            border: o.border,
            min_lod: o.min_lod,
            max_lod: o.max_lod,
            lod_bias: o.lod_bias,
            sampler_object: None,
            ..self.clone()
        })
    }
}

impl SamplerObject {
    /// A sampler object holding `s`'s sampler-object parameters.
    pub fn from_sampler(s: &Sampler) -> SamplerObject {
        SamplerObject {
            compare_mode: s.compare_mode,
            compare_func: s.compare_func,
            min_filter: s.min_filter,
            mag_filter: s.mag_filter,
            wrap_s: s.wrap_s,
            wrap_t: s.wrap_t,
            wrap_r: s.wrap_r,
            border: s.border,
            min_lod: s.min_lod,
            max_lod: s.max_lod,
            lod_bias: s.lod_bias,
        }
    }
}

fn default_min_lod() -> f32 {
    -1000.0
}
fn default_max_lod() -> f32 {
    1000.0
}

/// The lookup: coordinates, reference value and level of detail.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Lookup {
    /// (s, t, r, q) as passed to the API. Meaning by target: 1D (s), 2D/rect (s,t), 1D array
    /// (s, layer), 2D array (s,t,layer), cube (s,t,r direction), cube array (s,t,r direction; the
    /// layer is `layer`). Rectangle coordinates are unnormalized.
    #[serde(with = "crate::real::array4")]
    pub coord: [f64; 4],
    /// For cube arrays: the layer (cube index) coordinate.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub layer: f64,
    /// The reference value R / Dref as passed (before any projective divide).
    #[serde(with = "crate::real")]
    pub dref: f64,
    /// Projective lookup: s, t, (r) and Dref are divided by q.
    #[serde(default, skip_serializing_if = "is_false")]
    pub projective: bool,
    /// log2 of the scale factor (lambda_base), as realized by explicit LOD or gradients.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub lod: f64,
    /// Shader bias added to lambda_base (GLSL bias argument).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub bias: f64,
    /// Texel offset (δu, δv, δw) of the GLSL `*Offset` lookup functions, added to u, v, w in the
    /// selected level's texel units (GL 4.6 §8.14.2 (8.10), §8.14.3); zero when the lookup
    /// function takes no offset. Components a target does not use are 0.
    #[serde(default, skip_serializing_if = "is_zero3")]
    pub offset: [i32; 3],
    /// A `textureGather*` lookup on a shadow sampler (GL 4.6 §8.14.2, GLSL 4.60 §8.9.4): four
    /// comparisons against the reference, one per texel of the base level's LINEAR footprint.
    /// `None`: a filtered lookup (every other function).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gather: Option<Gather>,
    /// How the shader receives the lookup's values ([`Delivery`]); `literal` (the default, not
    /// written) is what every case without the field means.
    #[serde(default, skip_serializing_if = "Delivery::is_literal")]
    pub delivery: Delivery,
    /// The shader stage of the lookup ([`Stage`]); `fragment` (the default, not written) is what
    /// every case without the field means.
    #[serde(default, skip_serializing_if = "Stage::is_fragment")]
    pub stage: Stage,
}

/// The gather variant. `textureGather` has no offset; `textureGatherOffset` takes
/// [`Lookup::offset`] (δu, δv); `textureGatherOffsets` takes one (δu, δv) per result component.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Gather {
    /// `textureGatherOffsets`: the offsets of the components (R, G, B, A) in order; each selects
    /// τi0j0 of its own footprint (GL 4.6 §8.14.2). `None`: `textureGather(Offset)`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub offsets: Option<[[i32; 2]; 4]>,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}
fn is_zero3(v: &[i32; 3]) -> bool {
    *v == [0; 3]
}
fn is_false(v: &bool) -> bool {
    !*v
}

/// One test case. Fixture files hold these with `expect` filled in by the oracle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Case {
    /// Stable, readable id, e.g. `gl46/2d/d24/nearest/lequal/ref=0.5/dt=0.25`.
    pub id: String,
    pub spec: Spec,
    /// The API paths this case applies to.
    pub api: Vec<ApiPath>,
    pub texture: Texture,
    pub sampler: Sampler,
    pub lookup: Lookup,
    /// The oracle's expectation (present in fixtures).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expect: Option<Expectation>,
    /// More lookups on the same texture and sampling state, each with its own expectation
    /// ([`crate::sweep`]); empty for a case of one lookup.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sweep: Vec<crate::sweep::SweepPoint>,
}

impl Sampler {
    /// A sampler with the GL defaults for everything but the compare state and filters.
    pub fn new(compare_mode: CompareMode, compare_func: CompareFunc, filter: Filter) -> Sampler {
        let mag = if matches!(
            filter,
            Filter::Nearest | Filter::NearestMipmapNearest | Filter::NearestMipmapLinear
        ) {
            Filter::Nearest
        } else {
            Filter::Linear
        };
        Sampler {
            compare_mode,
            compare_func,
            depth_texture_mode: None,
            depth_stencil_mode: None,
            min_filter: filter,
            mag_filter: mag,
            wrap_s: Wrap::ClampToEdge,
            wrap_t: Wrap::ClampToEdge,
            wrap_r: Wrap::ClampToEdge,
            border: [0.0; 4],
            min_lod: default_min_lod(),
            max_lod: default_max_lod(),
            lod_bias: 0.0,
            max_level: None,
            fail_value: None,
            swizzle: None,
            seamless: None,
            sampler_object: None,
        }
    }
}
