//! ARB_shadow (21 January 2002) and ARB_shadow_ambient (12 December 2001), with ARB_depth_texture's
//! DEPTH_TEXTURE_MODE. Source: specs/registry/ARB_shadow.txt, ARB_shadow_ambient.txt, ARB_depth_texture.txt.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, RefClamp, Rules,
};
use shadowcheck_model::{ApiPath, CompareFunc, DepthTextureMode, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// ARB_shadow §3.8.13.1 (as inserted):
/// "if TEXTURE_COMPARE_FUNC_ARB = LEQUAL  r = 1.0 if R <= Dt, 0.0 if R > Dt
///  else if TEXTURE_COMPARE_FUNC_ARB = GEQUAL  r = 1.0 if R >= Dt, 0.0 if R < Dt"
/// ARB_shadow_ambient replaces "0.0" by "TEXTURE_COMPARE_FAIL_VALUE_ARB" in both rows.
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // Errors: "INVALID_ENUM is generated if TexParameter[if] parameter <pname> is
        // TEXTURE_COMPARE_FUNC_ARB and parameter <param> is not LEQUAL or GEQUAL."
        _ => return Err(NotInTable),
    })
}

/// Rules of ARB_shadow; with `Spec::ArbAmbient` also ARB_shadow_ambient.
pub fn rules(spec: Spec) -> Rules {
    let ambient = spec == Spec::ArbAmbient;
    Rules {
        spec,
        doc: if ambient {
            "ARB_shadow + ARB_shadow_ambient"
        } else {
            "ARB_shadow"
        },
        table: table as CompareTable,
        table_cite: "ARB_shadow §3.8.13.1",
        // "Let Dt (D subscript t) be the depth texture value, in the range [0, 1]. Let R be the
        //  interpolated texture coordinate clamped to the range [0, 1]."
        ref_clamp: RefClamp::Always,
        clamp_cite: "ARB_shadow §3.8.13.1 (R clamped to [0,1], Dt in [0,1]); issue 6",
        border: BorderRule::ClampUnit,
        // "r may be computed by comparing more than one depth texture value to the texture R
        //  coordinate. The details of this are implementation-dependent but r should be a value in the
        //  range [0, 1] which is proportional to the number of comparison passes or failures."
        // (ARB_shadow_ambient: "in the range [TEXTURE_COMPARE_FAIL_VALUE_ARB, 1]".)
        filtering: Filtering::ImplementationDependent,
        filter_cite: if ambient {
            "ARB_shadow_ambient §3.8.13.1 (filtered r in [fail, 1])"
        } else {
            "ARB_shadow §3.8.13.1 (filtered r implementation-dependent)"
        },
        incomplete: Incomplete::Legacy0001,
        es_depth_completeness: false,
        seamless_cube: false,
        lod_bias: true,
        ambient_on_pass: false,
        has_fail_value: ambient,
        targets: LEGACY_TARGETS,
        wraps: LEGACY_WRAPS,
        apis: LEGACY_APIS,
        // ARB_depth_texture: "DEPTH_TEXTURE_MODE_ARB enum LUMINANCE, INTENSITY, ALPHA".
        depth_modes: LEGACY_DEPTH_MODES,
        depth_stencil_mode: false,
        // Revision history, 21 January 2002: "Fixed error to be INVALID_ENUM instead of INVALID_OPERATION."
        bad_func_error: "INVALID_ENUM",
    }
}

/// Depth textures of the GL 1.4 - 2.1 era: 1D, 2D (ARB_depth_texture) and rectangle
/// (ARB_texture_rectangle, SHADOWRECT of ARB_fragment_program_shadow).
pub const LEGACY_TARGETS: &[Target] = &[Target::T1d, Target::T2d, Target::Rect];
/// Wrap modes of a GL 2.1 compatibility context.
pub const LEGACY_WRAPS: &[Wrap] = &[
    Wrap::Clamp,
    Wrap::Repeat,
    Wrap::ClampToEdge,
    Wrap::ClampToBorder,
    Wrap::MirroredRepeat,
];
/// Fixed-function, ARB fragment programs (ARB_fragment_program_shadow) and GLSL 1.10/1.20 shadow2D.
pub const LEGACY_APIS: &[ApiPath] = &[ApiPath::FixedFunction, ApiPath::ArbFp, ApiPath::Glsl120];
pub const LEGACY_DEPTH_MODES: &[DepthTextureMode] = &[
    DepthTextureMode::Luminance,
    DepthTextureMode::Intensity,
    DepthTextureMode::Alpha,
];
