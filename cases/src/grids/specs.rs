//! What each specification variant allows: the values of each grid dimension, and the API paths a
//! case reaches. Everything a spec does not define is left out here (or pruned by a named filter in
//! the grids), so that no generated case is one the oracle answers with a GL error.

use shadowcheck_model::*;

/// The dimensions one spec allows.
#[derive(Debug, Clone)]
pub struct SpecDims {
    pub spec: Spec,
    /// Compare functions (SGIX: its two operators; ARB_shadow: LEQUAL/GEQUAL; later: the eight).
    pub funcs: &'static [CompareFunc],
    pub targets: &'static [Target],
    pub formats: &'static [Format],
    pub filters: &'static [Filter],
    /// DEPTH_TEXTURE_MODE values that can be set (`None` = default, always present).
    pub dtms: &'static [DepthTextureMode],
    pub wraps: &'static [Wrap],
    /// TEXTURE_LOD_BIAS exists (not in ES).
    pub lod_bias: bool,
    /// TEXTURE_MIN_LOD / MAX_LOD / BASE_LEVEL / MAX_LEVEL exist (GL 1.2+, ES 3.0+; not ES 2.0).
    pub lod_state: bool,
    /// The shading language has a bias argument for shadow lookups (not `shadow2DEXT`, and not
    /// reachable from fixed function in the legacy variants).
    pub shader_bias: bool,
    /// DEPTH_STENCIL_TEXTURE_MODE exists (GL 4.3, ES 3.1).
    pub stencil_mode: bool,
    /// The fail / ambient value exists (sgix_ambient, arb_ambient).
    pub fail_value: bool,
}

use CompareFunc as F;
use DepthTextureMode as M;
use Format as Fo;
use Target as T;
use Wrap as W;

const SGIX_FUNCS: &[CompareFunc] = &[F::LequalRSgix, F::GequalRSgix];
const ARB_FUNCS: &[CompareFunc] = &[F::Lequal, F::Gequal];
const CORE_FUNCS: &[CompareFunc] = &CompareFunc::CORE;
const ALL_FILTERS: &[Filter] = Filter::ALL;
/// Formats of the ARB_depth_texture / SGIX_depth_texture era, plus a colour texture.
const LEGACY_FORMATS: &[Format] = &[Fo::DepthUnsized, Fo::D16, Fo::D24, Fo::D32, Fo::R8];
const LEGACY_DTMS: &[DepthTextureMode] = &[M::Luminance, M::Intensity, M::Alpha];

/// The specs, in the order grids and coverage tables list them.
pub fn all() -> Vec<SpecDims> {
    Spec::ALL.iter().map(|s| dims(*s)).collect()
}

pub fn dims(spec: Spec) -> SpecDims {
    match spec {
        // SGIX_shadow: GL 1.1-era fixed function; SGIX_depth_texture formats; wraps CLAMP, REPEAT
        // (the SGIX_shadow state table); the result is always LUMINANCE.
        Spec::Sgix | Spec::SgixAmbient => SpecDims {
            spec,
            funcs: SGIX_FUNCS,
            targets: &[T::T1d, T::T2d],
            formats: LEGACY_FORMATS,
            filters: ALL_FILTERS,
            dtms: &[],
            wraps: &[W::Clamp, W::Repeat],
            lod_bias: false,
            lod_state: true,
            shader_bias: false,
            stencil_mode: false,
            fail_value: spec == Spec::SgixAmbient,
        },
        // ARB_shadow / EXT_shadow_funcs: ARB_depth_texture (1D, 2D) plus rectangle textures
        // (ARB_fragment_program_shadow SHADOWRECT); GL 1.4 wrap modes.
        Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs => SpecDims {
            spec,
            funcs: if spec == Spec::ExtFuncs {
                CORE_FUNCS
            } else {
                ARB_FUNCS
            },
            targets: &[T::T1d, T::T2d, T::Rect],
            formats: LEGACY_FORMATS,
            filters: ALL_FILTERS,
            dtms: LEGACY_DTMS,
            wraps: &[
                W::Repeat,
                W::Clamp,
                W::ClampToEdge,
                W::ClampToBorder,
                W::MirroredRepeat,
            ],
            lod_bias: true,
            lod_state: true,
            shader_bias: false,
            stencil_mode: false,
            fail_value: spec == Spec::ArbAmbient,
        },
        // ES 2.0 + OES_depth_texture (TEXTURE_2D only, unsized DEPTH_COMPONENT) + EXT_shadow_samplers.
        Spec::Es2Ext => SpecDims {
            spec,
            funcs: CORE_FUNCS,
            targets: &[T::T2d],
            formats: &[Fo::DepthUnsized, Fo::R8],
            filters: ALL_FILTERS,
            dtms: &[],
            wraps: &[W::Repeat, W::ClampToEdge, W::MirroredRepeat],
            lod_bias: false,
            lod_state: false,
            shader_bias: false,
            stencil_mode: false,
            fail_value: false,
        },
        Spec::Gl46 => SpecDims {
            spec,
            funcs: CORE_FUNCS,
            targets: Target::ALL,
            // The main product's formats; the colour formats of several components are the
            // `formats` family's (grids/families/formats.rs).
            formats: &[
                Fo::D16,
                Fo::D24,
                Fo::D32,
                Fo::D32f,
                Fo::D24S8,
                Fo::D32fS8,
                Fo::DepthUnsized,
                Fo::R8,
            ],
            filters: ALL_FILTERS,
            dtms: &[M::Luminance, M::Intensity, M::Alpha, M::Red],
            wraps: &[
                W::Repeat,
                W::ClampToEdge,
                W::ClampToBorder,
                W::MirroredRepeat,
                W::MirrorClampToEdge,
                W::Clamp,
            ],
            lod_bias: true,
            lod_state: true,
            shader_bias: true,
            stencil_mode: true,
            fail_value: false,
        },
        // ES 3.2: no 1D, rectangle or unsized/32-bit unorm depth; CLAMP_TO_BORDER since 3.2.
        Spec::Gles32 => SpecDims {
            spec,
            funcs: CORE_FUNCS,
            targets: &[T::T2d, T::Cube, T::T2dArray, T::CubeArray],
            formats: &[Fo::D16, Fo::D24, Fo::D32f, Fo::D24S8, Fo::D32fS8, Fo::R8],
            filters: ALL_FILTERS,
            dtms: &[],
            wraps: &[
                W::Repeat,
                W::ClampToEdge,
                W::MirroredRepeat,
                W::ClampToBorder,
            ],
            lod_bias: false,
            lod_state: true,
            shader_bias: true,
            stencil_mode: true,
            fail_value: false,
        },
        // Vulkan 1.3: the VkImageViewType targets but rectangles, the five depth formats with a
        // Vulkan equivalent (no 32-bit UNORM, no unsized, no colour image with a Dref lookup),
        // the VkSamplerAddressMode values, mipLodBias, minLod/maxLod and the view's level range.
        Spec::Vulkan => SpecDims {
            spec,
            funcs: CORE_FUNCS,
            targets: &[
                T::T1d,
                T::T2d,
                T::Cube,
                T::T1dArray,
                T::T2dArray,
                T::CubeArray,
            ],
            formats: &[Fo::D16, Fo::D24, Fo::D32f, Fo::D24S8, Fo::D32fS8],
            filters: ALL_FILTERS,
            dtms: &[],
            wraps: &[
                W::Repeat,
                W::ClampToEdge,
                W::ClampToBorder,
                W::MirroredRepeat,
                W::MirrorClampToEdge,
            ],
            lod_bias: true,
            lod_state: true,
            shader_bias: true,
            stencil_mode: false,
            fail_value: false,
        },
        // WebGPU: the WGSL depth texture types (2D, 2D array, cube, cube array), the five depth
        // formats (depth32float-stencil8 with its feature), GPUAddressMode (no border),
        // lodMinClamp / lodMaxClamp and the view's mip range; no LOD bias anywhere (WebGPU
        // GPUSamplerDescriptor; WGSL).
        Spec::WebGpu => SpecDims {
            spec,
            funcs: CORE_FUNCS,
            targets: &[T::T2d, T::Cube, T::T2dArray, T::CubeArray],
            formats: &[Fo::D16, Fo::D24, Fo::D32f, Fo::D24S8, Fo::D32fS8],
            filters: ALL_FILTERS,
            dtms: &[],
            wraps: &[W::Repeat, W::ClampToEdge, W::MirroredRepeat],
            lod_bias: false,
            lod_state: true,
            shader_bias: false,
            stencil_mode: false,
            fail_value: false,
        },
    }
}

/// Whether the spec reads a depth texture with comparison off through its lookups (compare mode
/// NONE). Not Vulkan: its depth comparison is an OpImage*Dref* instruction on a sampler with
/// compareEnable (§16 Depth Compare Operation); a plain depth read is another instruction. Not
/// WebGPU: a comparison is a `sampler_comparison` in a compare built-in (WGSL texture built-in functions); a plain
/// depth read is textureSample through a `sampler`.
pub fn compare_none(spec: Spec) -> bool {
    !sampler_create(spec)
}

/// The spec sets sampling state when a sampler is created (Vulkan's VkSamplerCreateInfo,
/// WebGPU's GPUSamplerDescriptor): no TexParameter, no incomplete textures, no GL sampler
/// objects or seamless enable.
pub fn sampler_create(spec: Spec) -> bool {
    shadowcheck_oracle::rules::rules_for(spec)
        .sampler_create
        .is_some()
}

/// Rectangle textures allow only NEAREST and LINEAR minification (GL 4.6 §8.10: INVALID_ENUM
/// otherwise) and have one level.
pub fn filter_allowed(target: Target, filter: Filter) -> bool {
    !(target.is_rect() && filter.is_mipmap())
}

/// The API paths through which a case reaches the texture unit (see cases/README.md, "API paths").
///
/// - SGIX_shadow: fixed function only (it predates programmable shading).
/// - ARB_shadow (+ambient), EXT_shadow_funcs: fixed function, ARB_fragment_program_shadow
///   (SHADOW1D/2D/RECT) and GLSL 1.10/1.20 `shadow1D/2D/2DRect` (vec4 by DEPTH_TEXTURE_MODE). GLSL 1.30
///   is GL 3.0, whose rules (no clamp for float depth, RED mode) are the `gl46` variant's.
/// - ES 2.0 + EXT_shadow_samplers: GLSL ES 1.00 `shadow2DEXT`.
/// - GL 3.0-4.6: core GLSL for every target; in a compatibility context GLSL 1.30 (every target but
///   cube arrays, which need GLSL 4.00), GLSL 1.20 (1D, 2D, rectangle) and fixed function (1D, 2D,
///   rectangle, and cube maps, whose Dref is the q coordinate: GL 4.6 compatibility §8.23.1). ARB
///   fragment programs are left to the legacy variants. DEPTH_TEXTURE_MODE and CLAMP exist only in the
///   compatibility profile, so cases setting them leave out `core`; stencil texturing needs an
///   integer sampler (GLSL 4.30+), so it is `core` only.
/// - ES 3.x: GLSL ES 3.00.
/// - Vulkan: GLSL 4.50 for Vulkan compiled to SPIR-V (`vk`).
/// - WebGPU: WGSL (`wgsl`).
/// - A case setting the texture swizzle keeps GLSL 1.30 (compare NONE only), core and GLSL ES 3.00
///   (the swizzle is modelled on the shader lookups of GL 4.6 §15.2.1).
pub fn apis(spec: Spec, target: Target, sampler: &Sampler) -> Vec<ApiPath> {
    let mut v = state_apis(spec, target, sampler);
    if sampler.swizzle.is_some() {
        // The swizzle is modelled on fixed function (compatibility §16.1) and the GLSL lookups
        // (GL 4.6 §15.2.1), not on ARB fragment programs (their text is outside the spec pack).
        v.retain(|a| *a != ApiPath::ArbFp);
    }
    v
}

fn state_apis(spec: Spec, target: Target, sampler: &Sampler) -> Vec<ApiPath> {
    use ApiPath as A;
    let legacy_target = matches!(target, T::T1d | T::T2d | T::Rect);
    let stencil = sampler.depth_stencil_mode == Some(DepthStencilMode::StencilIndex);
    let compat_only = sampler.depth_texture_mode.is_some()
        || [sampler.wrap_s, sampler.wrap_t, sampler.wrap_r].contains(&W::Clamp);
    match spec {
        Spec::Sgix | Spec::SgixAmbient => vec![A::FixedFunction],
        Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs => {
            vec![A::FixedFunction, A::ArbFp, A::Glsl120]
        }
        Spec::Es2Ext => vec![A::Es100Ext],
        Spec::Gles32 => vec![A::Es300],
        Spec::Vulkan => vec![A::Vulkan],
        Spec::WebGpu => vec![A::Wgsl],
        Spec::Gl46 => {
            if stencil {
                return vec![A::GlslCore];
            }
            let mut v = Vec::new();
            if legacy_target || target == T::Cube {
                v.push(A::FixedFunction);
            }
            if legacy_target {
                v.push(A::Glsl120);
            }
            if !matches!(target, T::CubeArray) {
                v.push(A::Glsl130);
            }
            if !compat_only {
                v.push(A::GlslCore);
            }
            v.sort();
            v
        }
    }
}
