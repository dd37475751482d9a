//! OpenGL 3.0 - 4.6 (core profile text, with the compatibility-profile DEPTH_TEXTURE_MODE layouts for
//! the legacy API paths). Source: the OpenGL 4.6 core specification (5 May 2022); for the legacy
//! result layouts, GL 4.6 compatibility §8.23 with Table 16.1 and GLSL 1.20 / 1.30's shadow functions.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, Reading, RefClamp,
    Rules,
};
use crate::state::{self, Ctx, GlErrorKind::*, Param, ParamKind, Stored};
use shadowcheck_model::{ApiPath, CompareFunc, DepthTextureMode, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// §8.23.1, Table 8.23 "Depth texture comparison functions":
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "LEQUAL r = 1.0, Dref ≤ Dt; 0.0, Dref > Dt"
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "GEQUAL r = 1.0, Dref ≥ Dt; 0.0, Dref < Dt"
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "LESS r = 1.0, Dref < Dt; 0.0, Dref ≥ Dt"
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "GREATER r = 1.0, Dref > Dt; 0.0, Dref ≤ Dt"
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "EQUAL r = 1.0, Dref = Dt; 0.0, Dref ≠ Dt"
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "NOTEQUAL r = 1.0, Dref ≠ Dt; 0.0, Dref = Dt"
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "ALWAYS r = 1.0"
        CompareFunc::Always => Some(true),
        // "NEVER r = 0.0"
        CompareFunc::Never => Some(false),
        // §8.10 Errors: "An INVALID_ENUM error is generated if the type of the parameter specified by
        // pname is enum, and any value specified by param or params is not among the legal values".
        _ => return Err(NotInTable),
    })
}

pub fn rules() -> Rules {
    Rules {
        spec: Spec::Gl46,
        doc: "GL 4.6",
        table: table as CompareTable,
        table_cite: "GL 4.6 §8.23.1 Table 8.23",
        // "If the texture's internal format indicates a fixed-point depth texture, then Dt and Dref
        //  are clamped to the range [0, 1]; otherwise no clamping is performed."
        ref_clamp: RefClamp::FixedPointOnly,
        clamp_cite: "GL 4.6 §8.23.1 (Dt, Dref clamped only for fixed-point depth)",
        // §8.14.2: "If border values are out-of-range with respect to the texture's internal format,
        // the result is undefined."
        border: BorderRule::UndefinedOutOfRange,
        // "r may be computed by comparing more than one depth texture value to the texture reference
        //  value. The details of this are implementation-dependent, but r should be a value in the
        //  range [0, 1] which is proportional to the number of comparison passes or failures."
        filtering: Filtering::ImplementationDependent,
        filter_cite: "GL 4.6 §8.23.1 (filtered r implementation-dependent)",
        // §11.1.3.5: "(0.0, 0.0, 0.0, 1.0), in floating-point, will be returned for a non-shadow
        // sampler and 0 for a shadow sampler".
        incomplete: Incomplete::ShadowZero,
        es_depth_completeness: false,
        // §8.13.1: "Initially, it is disabled."
        seamless_cube: false,
        seamless_enable: Some("GL 4.6 §8.13.1: \"Seamless cube map filtering is enabled or disabled by calling Enable or Disable with target TEXTURE_CUBE_MAP_SEAMLESS.\""),
        swizzle: Some("GL 4.6 §15.2.1: the texture base color Cb is converted \"followed by swizzling the components of Cb, controlled by the values of the texture parameters TEXTURE_SWIZZLE_R, TEXTURE_SWIZZLE_G, TEXTURE_SWIZZLE_B, and TEXTURE_SWIZZLE_A\"; §11.1.3.5: \"swizzling of Cb is then performed as described above, but only the first component Cs[0] is returned to the shader\""),
        sampler_objects: Some("GL 4.6 §8.17.1: \"If a sampler object and a texture object are simultaneously bound to the same texture unit, then the sampling state for that unit is taken from the sampler object\"; §8.2: \"Texture state listed in tables 23.16- 23.17 but not listed here and in the sampler state in table 23.18 is not part of the sampler state, and remains in the texture object.\""),
        lod_bias: true,
        sampler_create: None,
        layer_rne_always: None,
        ambient_on_pass: false,
        fail_value_cite: None,
        targets: &[
            Target::T1d,
            Target::T2d,
            Target::Rect,
            Target::Cube,
            Target::T1dArray,
            Target::T2dArray,
            Target::CubeArray,
        ],
        // Table 8.17 (CLAMP: compatibility profile only).
        wraps: &[
            Wrap::ClampToEdge,
            Wrap::Repeat,
            Wrap::ClampToBorder,
            Wrap::MirroredRepeat,
            Wrap::MirrorClampToEdge,
            Wrap::Clamp,
        ],
        apis: &[
            ApiPath::FixedFunction,
            ApiPath::ArbFp,
            ApiPath::Glsl120,
            ApiPath::Glsl130,
            ApiPath::GlslCore,
        ],
        // Compatibility Table 8.25: "DEPTH_TEXTURE_MODE enum RED, LUMINANCE, INTENSITY, ALPHA".
        depth_modes: &[
            DepthTextureMode::Red,
            DepthTextureMode::Luminance,
            DepthTextureMode::Intensity,
            DepthTextureMode::Alpha,
        ],
        // Table 8.17: "DEPTH_STENCIL_TEXTURE_MODE enum DEPTH_COMPONENT, STENCIL_INDEX".
        depth_stencil_mode: true,
        bad_func_error: "INVALID_ENUM",
        formats: Format::ALL,
        mode_pname: state::TEXTURE_COMPARE_MODE,
        func_pname: state::TEXTURE_COMPARE_FUNC,
        params,
        no_lod_state: None,
        no_lookup_bias: None,
        fixed_depth_mode: None,
        // A colour texture is R8: Table 15.1, (Rt,0,0),1.
        colour_luminance: false,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[
            Reading {
                id: "mirror-parens",
                other: None,
            },
            crate::rules::VERTEX_BASE_TEXTURE,
        ],
    }
}

/// The TexParameter state of GL 4.6 (core and compatibility contexts).
pub fn params(_: Spec, ctx: Ctx) -> Vec<Param> {
    if ctx == Ctx::Es {
        return Vec::new();
    }
    // Table 8.17, §8.10 Errors ("INVALID_ENUM ... not among the legal values"), §8.22 / Table
    // 23.15 initial values NONE, LEQUAL, DEPTH_COMPONENT.
    let mut v = vec![
        Param::compare_mode(
            "TEXTURE_COMPARE_MODE",
            "GL 4.6 Table 8.17, §8.10, Table 23.15",
        ),
        Param::compare_func8(
            "TEXTURE_COMPARE_FUNC",
            "GL 4.6 Table 8.17, §8.10, Table 23.15",
        ),
        Param::depth_stencil_mode("GL 4.6 Table 8.17, §8.10, Table 23.15"),
    ];
    if ctx == Ctx::Compat {
        // Compatibility Table 8.25: "DEPTH_TEXTURE_MODE enum RED, LUMINANCE, INTENSITY, ALPHA";
        // §8.22: initial LUMINANCE (§8.12: RED in a forward-compatible context). Removed from
        // the core profile (E.2.2), where the pname is an INVALID_ENUM.
        v.push(Param::new(
            state::DEPTH_TEXTURE_MODE,
            "DEPTH_TEXTURE_MODE",
            ParamKind::Enum(
                &[state::RED, state::LUMINANCE, state::INTENSITY, state::ALPHA],
                InvalidEnum,
            ),
            Stored::Enum(state::LUMINANCE),
            "GL 4.6 compatibility Table 8.25, §8.12, §8.22",
        ));
    }
    v
}
