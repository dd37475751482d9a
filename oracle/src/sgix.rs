//! SGIX_shadow (rev 1.15, 1997) and SGIX_shadow_ambient (rev 1.3).
//! Source: the OpenGL Registry texts of SGIX_shadow and SGIX_shadow_ambient (SGIX_shadow's HTML
//! rendering reads the same).

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, Reading, RefClamp,
    Rules,
};
use crate::state::{self, Ctx, GlErrorKind::*, Param, ParamKind, Stored};
use shadowcheck_model::{ApiPath, CompareFunc, DepthTextureMode, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// SGIX_shadow, Additions to Chapter 3, Notes:
/// "The test for operator TEXTURE_LEQUAL_R_SGIX passes if the texel value is less than or equal to R.
///  The test for operator TEXTURE_GEQUAL_R_SGIX passes if the texel value is greater than or equal to R."
/// `ord` is R compared with the texel, so "texel <= R" is "R >= texel".
/// "The value of the test is zero if the test fails, and one if it passes."
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // texel <= R
        CompareFunc::LequalRSgix => passes_if(ord, &[Greater, Equal]),
        // texel >= R
        CompareFunc::GequalRSgix => passes_if(ord, &[Less, Equal]),
        // Errors: "INVALID_OPERATION is generated if TexParameter[if] parameter <pname> is
        // TEXTURE_COMPARE_OPERATOR_SGIX and parameter <param> is not TEXTURE_LEQUAL_R_SGIX,or
        // TEXTURE_GEQUAL_R_SGIX."
        _ => return Err(NotInTable),
    })
}

/// The reading of ARB_shadow issue 2 (named, not defended): "the GL_TEXTURE_LEQUAL_R_SGIX token should
/// really have been named GL_R_LEQUAL_TEXTURE_SGIX since we're comparing R <= TEXTURE".
pub fn table_arb_issue2(
    func: CompareFunc,
    ord: Option<Ordering>,
) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        CompareFunc::LequalRSgix => passes_if(ord, &[Less, Equal]),
        CompareFunc::GequalRSgix => passes_if(ord, &[Greater, Equal]),
        _ => return Err(NotInTable),
    })
}

/// SGIX_shadow's Table 3.8: "TEXTURE_WRAP_S integer CLAMP, REPEAT" (likewise T and R_EXT).
pub const TABLE_3_8_WRAPS: &[Wrap] = &[Wrap::Clamp, Wrap::Repeat];

/// Why a case's state lies outside what SGIX_shadow's Table 3.8 lists (wrap modes other than CLAMP and
/// REPEAT, a TEXTURE_LOD_BIAS), if it does: the text says nothing of such a lookup, so the case is
/// not applicable rather than an error of the GL of the time (later GLs accept the state).
pub fn outside_table_3_8(s: &shadowcheck_model::Sampler) -> Option<String> {
    for (name, w) in [("S", s.wrap_s), ("T", s.wrap_t), ("R_EXT", s.wrap_r)] {
        if !TABLE_3_8_WRAPS.contains(&w) {
            return Some(format!(
                "TEXTURE_WRAP_{name} `{w}`: SGIX_shadow's Table 3.8 lists only CLAMP and REPEAT"
            ));
        }
    }
    (s.lod_bias != 0.0).then(|| {
        "TEXTURE_LOD_BIAS: SGIX_shadow's Table 3.8 has no level-of-detail bias".to_string()
    })
}

/// Rules of SGIX_shadow; with `Spec::SgixAmbient` also SGIX_shadow_ambient.
pub fn rules(spec: Spec) -> Rules {
    let ambient = spec == Spec::SgixAmbient;
    Rules {
        spec,
        doc: if ambient { "SGIX_shadow + SGIX_shadow_ambient" } else { "SGIX_shadow" },
        table: table as CompareTable,
        table_cite: "SGIX_shadow, Additions to Chapter 3 (Notes: TEXTURE_LEQUAL_R_SGIX passes if texel <= R)",
        // "The specification is unclear if the R texture coordinate is clamped to the range [0,1].
        //  NVIDIA hardware supporting this extension does clamp" (NVIDIA Implementation Details).
        ref_clamp: RefClamp::Unstated,
        clamp_cite: "SGIX_shadow, Notes (\"texture components are treated as though they range from 0.0 through 1.0\") and NVIDIA Implementation Details (R clamp unclear)",
        // Table 3.8 as updated: "TEXTURE_BORDER_COLOR 4 floats any 4 values in [0,1]".
        border: BorderRule::ClampUnit,
        // Overview: "two new operations to be performed on texture values before they are passed on
        // to the filtering subsystem"; Notes: "operators which alter the sampled texture values before
        // they are filtered".
        filtering: Filtering::BeforeFilter,
        filter_cite: "SGIX_shadow, Overview and Notes (compare before filtering)",
        incomplete: Incomplete::Legacy0001,
        es_depth_completeness: false,
        seamless_cube: false,
        seamless_enable: None,
        swizzle: None,
        sampler_objects: None,
        // Table 3.8 as updated by SGIX_shadow lists no TEXTURE_LOD_BIAS (EXT_texture_lod_bias, GL 1.4):
        // a case that sets it is outside this text (`outside_table_3_8`).
        lod_bias: false,
        sampler_create: None,
        layer_rne_always: None,
        // SGIX_shadow_ambient Notes: "the value of the SHADOW_AMBIENT_SGIX parameter is returned,
        // instead of 0.0".
        ambient_on_pass: false,
        fail_value_cite: if ambient {
            Some("SGIX_shadow_ambient Notes")
        } else {
            None
        },
        // "These operators are defined only for textures with internal format DEPTH_COMPONENT"; the
        // depth textures of the time (SGIX_depth_texture) are 1D and 2D.
        targets: &[Target::T1d, Target::T2d],
        wraps: &[Wrap::Clamp, Wrap::Repeat, Wrap::ClampToEdge, Wrap::ClampToBorder, Wrap::MirroredRepeat],
        // "The modified texels ... are treated as if the texture internal format were LUMINANCE":
        // fixed-function texturing only (the extension predates programmable lookups).
        apis: &[ApiPath::FixedFunction],
        depth_modes: &[],
        depth_stencil_mode: false,
        bad_func_error: "INVALID_OPERATION",
        // Floating-point depth arrives with ARB_depth_buffer_float (GL 3.0); before it every depth
        // texture is fixed-point. DEPTH_STENCIL comes from EXT_packed_depth_stencil.
        formats: &[
            Format::D16,
            Format::D24,
            Format::D32,
            Format::DepthUnsized,
            Format::R8,
        ],
        mode_pname: state::TEXTURE_COMPARE_SGIX,
        func_pname: state::TEXTURE_COMPARE_OPERATOR_SGIX,
        params,
        no_lod_state: None,
        no_lookup_bias: None,
        // "treated as if the texture internal format were LUMINANCE".
        fixed_depth_mode: Some(DepthTextureMode::Luminance),
        colour_luminance: true,
        colour_note: Some("SGIX_shadow defines its operators \"only for textures with internal format DEPTH_COMPONENT\"; the bypass is ARB_shadow's (issue 5)"),
        non_fragment_base_texture: false,
        readings: if ambient { READINGS_AMBIENT } else { READINGS },
    }
}

/// Contradiction `sgix-lequal-direction`: the other reading is ARB_shadow issue 2's table.
fn lequal_direction(r: Rules) -> Rules {
    Rules {
        table: table_arb_issue2,
        ..r
    }
}

/// Contradiction `ref-clamp`: the other reading of SGIX is NVIDIA's clamp.
fn nvidia_clamp(r: Rules) -> Rules {
    Rules {
        ref_clamp: RefClamp::Always,
        ..r
    }
}

/// Contradiction `sgix-ambient`: the overview's reading, the ambient value on a pass.
fn ambient_on_pass(r: Rules) -> Rules {
    Rules {
        ambient_on_pass: true,
        ..r
    }
}

const READINGS: &[Reading] = &[
    Reading {
        id: "sgix-lequal-direction",
        other: Some(lequal_direction),
    },
    Reading {
        id: "ref-clamp",
        other: Some(nvidia_clamp),
    },
];

const READINGS_AMBIENT: &[Reading] = &[
    Reading {
        id: "sgix-lequal-direction",
        other: Some(lequal_direction),
    },
    Reading {
        id: "sgix-ambient",
        other: Some(ambient_on_pass),
    },
    Reading {
        id: "ref-clamp",
        other: Some(nvidia_clamp),
    },
];

/// The TexParameter state of SGIX_shadow (and SGIX_shadow_ambient); compatibility contexts only.
pub fn params(spec: Spec, ctx: Ctx) -> Vec<Param> {
    let mut v = Vec::new();
    if ctx != Ctx::Compat {
        return v;
    }
    // Table 3.8: "TEXTURE_COMPARE_SGIX boolean TRUE or FALSE"; New State: initial "False".
    v.push(Param::new(
        state::TEXTURE_COMPARE_SGIX,
        "TEXTURE_COMPARE_SGIX",
        ParamKind::Bool,
        Stored::Bool(false),
        "SGIX_shadow Table 3.8, New State",
    ));
    // "TEXTURE_COMPARE_OPERATOR_SGIX integer TEXTURE_LEQUAL_R_SGIX, TEXTURE_GEQUAL_R_SGIX";
    // Errors: "INVALID_OPERATION is generated if ... <param> is not TEXTURE_LEQUAL_R_SGIX, or
    // TEXTURE_GEQUAL_R_SGIX"; initial "TEXTURE_LEQUAL_R_SGIX".
    v.push(Param::new(
        state::TEXTURE_COMPARE_OPERATOR_SGIX,
        "TEXTURE_COMPARE_OPERATOR_SGIX",
        ParamKind::Enum(
            &[state::TEXTURE_LEQUAL_R_SGIX, state::TEXTURE_GEQUAL_R_SGIX],
            InvalidOperation,
        ),
        Stored::Enum(state::TEXTURE_LEQUAL_R_SGIX),
        "SGIX_shadow Table 3.8, Errors, New State",
    ));
    if spec == Spec::SgixAmbient {
        // "When SHADOW_AMBIENT_SGIX is set, the <param> value is clamped to the range [0.0, 1.0]";
        // Errors: "None"; initial 0.0.
        v.push(Param::new(
            state::SHADOW_AMBIENT_SGIX,
            "SHADOW_AMBIENT_SGIX",
            ParamKind::Unit,
            Stored::Float(0.0),
            "SGIX_shadow_ambient Notes, New State",
        ));
    }
    v
}
