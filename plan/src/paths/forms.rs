//! Which lookup functions each shading language has: the per-dialect tables of GLSL 4.60 / GLSL
//! ES 3.20 §8.9.2, GLSL 1.20 §8.7, EXT_shadow_samplers, ARB_fragment_program(_shadow), and the
//! overloads EXT_texture_shadow_lod adds.

use super::{LodForm, SamplerKind, ShaderKey};
use shadowcheck_model::{ApiPath, Target};

/// The shading-language dialect of a path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Dialect {
    Modern,
    Es3,
    Glsl120,
    Es100,
    ArbFp,
    Ff,
    Wgsl,
}

fn dialect(path: ApiPath) -> Dialect {
    match path {
        // GLSL 4.50 for Vulkan (GL_KHR_vulkan_glsl) keeps GLSL 4.50's lookup functions.
        ApiPath::GlslCore | ApiPath::Glsl130 | ApiPath::Vulkan => Dialect::Modern,
        ApiPath::Es300 => Dialect::Es3,
        ApiPath::Glsl120 => Dialect::Glsl120,
        ApiPath::Es100Ext => Dialect::Es100,
        ApiPath::ArbFp => Dialect::ArbFp,
        ApiPath::FixedFunction => Dialect::Ff,
        ApiPath::Wgsl => Dialect::Wgsl,
    }
}

/// Does the language have this lookup function? (GLSL 4.60 §8.9.2, GLSL ES 3.20 §8.9.2,
/// GLSL 1.20 §8.7, EXT_shadow_samplers, ARB_fragment_program(_shadow).)
pub fn available(
    path: ApiPath,
    kind: SamplerKind,
    target: Target,
    form: LodForm,
    proj: bool,
) -> bool {
    available_with(path, kind, target, form, proj, false)
}

/// [`available`], with the overloads of EXT_texture_shadow_lod where `shadow_lod`: "float
/// textureLod(sampler2DArrayShadow sampler, vec4 P, float lod)", "textureLod(samplerCubeShadow
/// ...)", "textureLod(samplerCubeArrayShadow sampler, vec4 P, float compare, float lod)" and
/// "float texture(sampler2DArrayShadow sampler, vec4 P [, float bias])" (the extension, §8.9.2;
/// GLSL 4.60 §8.9.2 itself lists none of them).
pub fn available_with(
    path: ApiPath,
    kind: SamplerKind,
    target: Target,
    form: LodForm,
    proj: bool,
    shadow_lod: bool,
) -> bool {
    use Target::*;
    let d = dialect(path);
    let es_target = matches!(target, T2d | Cube | T2dArray | CubeArray);
    if matches!(d, Dialect::Es3) && !es_target {
        return false;
    }
    if proj && !matches!(target, T1d | T2d | Rect) {
        return false;
    }
    match d {
        Dialect::Ff => {
            matches!(form, LodForm::Constant | LodForm::Implicit(_))
                && (matches!(target, T1d | T2d | Rect)
                    || (kind != SamplerKind::Shadow && target == Cube))
        }
        Dialect::ArbFp => match form {
            LodForm::Implicit(bias) => {
                kind != SamplerKind::Uint
                    && (matches!(target, T1d | T2d | Rect)
                        || (kind == SamplerKind::Float && target == Cube))
                    && !(bias && (proj || target == Rect))
            }
            _ => false,
        },
        Dialect::Es100 => {
            target == T2d && kind != SamplerKind::Uint && form == LodForm::Implicit(false)
        }
        Dialect::Glsl120 => match form {
            LodForm::Implicit(bias) => {
                kind != SamplerKind::Uint
                    && (matches!(target, T1d | T2d | Rect)
                        || (kind == SamplerKind::Float && target == Cube))
                    && !(bias && target == Rect)
            }
            _ => false,
        },
        // WGSL texture built-in functions: the depth-comparison built-ins take a texture_depth_2d, _2d_array, _cube or
        // _cube_array and no projection: textureSampleCompare (implicit derivatives, no bias) and
        // textureSampleCompareLevel (`Lod`: "always samples texels from mip level 0", so only a
        // case whose level of detail selects level 0 may use it).
        Dialect::Wgsl => {
            kind == SamplerKind::Shadow
                && !proj
                && matches!(target, T2d | T2dArray | Cube | CubeArray)
                && matches!(form, LodForm::Lod | LodForm::Implicit(false))
        }
        Dialect::Modern | Dialect::Es3 => {
            let es = d == Dialect::Es3;
            if kind == SamplerKind::Shadow {
                let ext = shadow_lod && !proj;
                match form {
                    LodForm::Lod => {
                        matches!(target, T1d | T2d)
                            || (!proj && target == T1dArray)
                            || (ext && matches!(target, T2dArray | Cube | CubeArray))
                    }
                    LodForm::Grad => target != CubeArray,
                    LodForm::Implicit(true) => {
                        matches!(target, T1d | T2d)
                            || (!proj && matches!(target, Cube | T1dArray))
                            || (ext && target == T2dArray)
                    }
                    LodForm::Implicit(false) => true,
                    LodForm::Constant | LodForm::Gather(_) => false,
                }
            } else {
                match form {
                    LodForm::Lod => target != Rect && !(proj && es && target != T2d),
                    LodForm::Grad => true,
                    LodForm::Implicit(bias) => !(bias && target == Rect),
                    LodForm::Constant | LodForm::Gather(_) => false,
                }
            }
        }
    }
}

/// Does the `*Offset` variant of this lookup exist (GLSL 4.60 §8.9.2, GLSL ES 3.00 §8.8)? The
/// 2D, 1D and 1D-array shadow samplers have every form; sampler2DRectShadow has no LOD form and
/// its textureOffset no bias; sampler2DArrayShadow has only textureGradOffset (its textureOffset
/// came with GLSL 4.30, later than the versions the worker writes); ES has offsets on 2D and 2D
/// arrays only. Cube maps take none.
pub fn offset_available(path: ApiPath, kind: SamplerKind, target: Target, form: LodForm) -> bool {
    offset_available_with(path, kind, target, form, false)
}

/// [`offset_available`], with EXT_texture_shadow_lod's "float textureOffset(sampler2DArrayShadow
/// sampler, vec4 P, ivec2 offset [, float bias])" and "textureLodOffset(sampler2DArrayShadow ...)"
/// where `shadow_lod`.
pub fn offset_available_with(
    path: ApiPath,
    kind: SamplerKind,
    target: Target,
    form: LodForm,
    shadow_lod: bool,
) -> bool {
    use Target::*;
    let shadow = kind == SamplerKind::Shadow;
    let es = path == ApiPath::Es300;
    if path == ApiPath::Wgsl {
        // WGSL texture built-in functions: the offset overloads exist for texture_depth_2d and texture_depth_2d_array.
        return matches!(target, T2d | T2dArray);
    }
    match target {
        Cube | CubeArray => false,
        T2d => true,
        T1d | T1dArray => !es,
        Rect => !es && matches!(form, LodForm::Grad | LodForm::Implicit(false)),
        T2dArray => {
            !shadow
                || form == LodForm::Grad
                || (shadow_lod && matches!(form, LodForm::Lod | LodForm::Implicit(_)))
        }
    }
}

/// The lookup function uses an EXT_texture_shadow_lod overload (the shader then enables the
/// extension): textureLod on 2D-array, cube and cube-array shadow samplers, the bias form on a
/// 2D-array shadow sampler, textureOffset / textureLodOffset on a 2D-array shadow sampler.
pub fn uses_shadow_lod(key: &ShaderKey) -> bool {
    use Target::*;
    key.path != ApiPath::Wgsl
        && key.kind == SamplerKind::Shadow
        && !key.proj
        && key.gather.is_none()
        && match key.form {
            LodForm::Lod => matches!(key.target, T2dArray | Cube | CubeArray),
            LodForm::Implicit(bias) => key.target == T2dArray && (bias || key.offset != [0, 0]),
            _ => false,
        }
}
