//! ARB_shadow (21 January 2002) and ARB_shadow_ambient (12 December 2001), with ARB_depth_texture's
//! DEPTH_TEXTURE_MODE. Source: the OpenGL Registry texts of ARB_shadow, ARB_shadow_ambient and
//! ARB_depth_texture.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, RefClamp, Rules,
};
use crate::state::{self, Ctx, GlErrorKind::*, Param, ParamKind, Stored};
use shadowcheck_model::{ApiPath, CompareFunc, DepthTextureMode, Format, Spec, Target, Wrap};
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
        seamless_enable: None,
        swizzle: None,
        sampler_objects: None,
        lod_bias: true,
        sampler_create: None,
        layer_rne_always: None,
        ambient_on_pass: false,
        fail_value_cite: if ambient {
            Some("ARB_shadow_ambient §3.8.13.1")
        } else {
            None
        },
        targets: LEGACY_TARGETS,
        wraps: LEGACY_WRAPS,
        apis: LEGACY_APIS,
        // ARB_depth_texture: "DEPTH_TEXTURE_MODE_ARB enum LUMINANCE, INTENSITY, ALPHA".
        depth_modes: LEGACY_DEPTH_MODES,
        depth_stencil_mode: false,
        // Revision history, 21 January 2002: "Fixed error to be INVALID_ENUM instead of INVALID_OPERATION."
        bad_func_error: "INVALID_ENUM",
        formats: LEGACY_FORMATS,
        mode_pname: state::TEXTURE_COMPARE_MODE,
        func_pname: state::TEXTURE_COMPARE_FUNC,
        params,
        no_lod_state: None,
        no_lookup_bias: None,
        fixed_depth_mode: None,
        // A colour texture "operates in the normal manner": GL 2.1 knows it as LUMINANCE8 (Table 3.20).
        colour_luminance: true,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[crate::rules::VERTEX_BASE_TEXTURE],
    }
}

/// Floating-point depth arrives with ARB_depth_buffer_float (GL 3.0); before it every depth texture
/// is fixed-point. DEPTH_STENCIL comes from EXT_packed_depth_stencil.
pub const LEGACY_FORMATS: &[Format] = &[
    Format::D16,
    Format::D24,
    Format::D32,
    Format::D24S8,
    Format::DepthUnsized,
    Format::R8,
    // GL 1.1's sized colour formats (GL 2.1 Table 3.16): ARB_shadow "Otherwise, the texture unit
    // operates in the normal manner" for them too. RG8 is GL 3.0's (ARB_texture_rg).
    Format::Rgba8,
    Format::Rgb8,
    Format::Rgba4,
];

/// The TexParameter state of ARB_shadow (with ARB_depth_texture's DEPTH_TEXTURE_MODE, and
/// ARB_shadow_ambient's fail value for `Spec::ArbAmbient`); compatibility contexts only.
pub fn params(spec: Spec, ctx: Ctx) -> Vec<Param> {
    let mut v = Vec::new();
    if ctx != Ctx::Compat {
        return v;
    }
    // ARB_shadow Errors: "INVALID_ENUM is generated if ... TEXTURE_COMPARE_MODE_ARB and
    // parameter <param> is not NONE or COMPARE_R_TO_TEXTURE"; New State: initial NONE.
    v.push(Param::compare_mode(
        "TEXTURE_COMPARE_MODE",
        "ARB_shadow Errors, New State",
    ));
    // ARB_shadow Errors: "... TEXTURE_COMPARE_FUNC_ARB and parameter <param> is not LEQUAL
    // or GEQUAL"; initial LEQUAL.
    v.push(Param::new(
        state::TEXTURE_COMPARE_FUNC,
        "TEXTURE_COMPARE_FUNC",
        ParamKind::Enum(&[state::LEQUAL, state::GEQUAL], InvalidEnum),
        Stored::Enum(state::LEQUAL),
        "ARB_shadow Errors, New State",
    ));
    // ARB_depth_texture: "INVALID_ENUM is generated if TexParameter[if] parameter <pname> is
    // DEPTH_TEXTURE_MODE_ARB and parameter <param> is not ALPHA, LUMINANCE, or INTENSITY";
    // "Initially, depth textures are interpreted as LUMINANCE."
    v.push(Param::new(
        state::DEPTH_TEXTURE_MODE,
        "DEPTH_TEXTURE_MODE",
        ParamKind::Enum(
            &[state::LUMINANCE, state::INTENSITY, state::ALPHA],
            InvalidEnum,
        ),
        Stored::Enum(state::LUMINANCE),
        "ARB_depth_texture Errors, §3.8.4",
    ));
    if spec == Spec::ArbAmbient {
        // "The value set by TEXTURE_COMPARE_FAIL_VALUE_ARB is clamped to lie in [0, 1]";
        // Errors: "None."; initial 0.0.
        v.push(Param::new(
            state::TEXTURE_COMPARE_FAIL_VALUE_ARB,
            "TEXTURE_COMPARE_FAIL_VALUE_ARB",
            ParamKind::Unit,
            Stored::Float(0.0),
            "ARB_shadow_ambient §3.8.4, New State",
        ));
    }
    v
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
