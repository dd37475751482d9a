//! OpenGL ES 2.0 with EXT_shadow_samplers (rev 4, 2012) and OES_depth_texture.
//! Source: the OpenGL Registry texts of EXT_shadow_samplers and OES_depth_texture.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, Reading, RefClamp,
    Rules,
};
use crate::state::{self, Ctx, Param};
use shadowcheck_model::{ApiPath, CompareFunc, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// §3.7.14.1, Table 3.X "Depth texture comparison functions":
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "LEQUAL r = { 1.0, if D_ref <= Dt  { 0.0, if D_ref > Dt"
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "GEQUAL r = { 1.0, if D_ref >= Dt  { 0.0, if D_ref < Dt"
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "LESS r = { 1.0, if D_ref < Dt  { 0.0, if D_ref >= Dt"
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "GREATER r = { 1.0, if D_ref > Dt  { 0.0, if D_ref < Dt"
        // The printed rows assign nothing at D_ref == Dt (contradiction `es2-greater-row`): the text
        // leaves the result open there, so either value is accepted and labelled
        // implementation-defined. (EXT_shadow_funcs, on which the extension is based, has "0.0, if
        // R <= Dt": the other reading.)
        CompareFunc::Greater if ord == Some(Equal) => None,
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "EQUAL r = { 1.0, if D_ref == Dt  { 0.0, if D_ref != Dt"
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "NOTEQUAL r = { 1.0, if D_ref != Dt  { 0.0, if D_ref == Dt"
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "ALWAYS r = 1.0"
        CompareFunc::Always => Some(true),
        // "NEVER r = 0.0"
        CompareFunc::Never => Some(false),
        // Table 3.10 as appended lists only these eight; ES reports other values with INVALID_ENUM.
        _ => return Err(NotInTable),
    })
}

/// The other reading of the GREATER row: EXT_shadow_funcs' "0.0, if R <= Dt", so r = 0 at equality.
pub fn table_greater_row_funcs(
    func: CompareFunc,
    ord: Option<Ordering>,
) -> Result<Option<bool>, NotInTable> {
    match (func, ord) {
        (CompareFunc::Greater, Some(Equal)) => Ok(Some(false)),
        _ => table(func, ord),
    }
}

pub fn rules() -> Rules {
    Rules {
        spec: Spec::Es2Ext,
        doc: "ES 2.0 + EXT_shadow_samplers",
        table: table as CompareTable,
        table_cite: "EXT_shadow_samplers §3.7.14.1 Table 3.X",
        // "Let D_t be the depth texture value and D_ref be the reference value, provided by the
        //  shader's texture lookup function. D_t and D_ref are clamped to the range [0,1]."
        ref_clamp: RefClamp::Always,
        clamp_cite: "EXT_shadow_samplers §3.7.14.1 (D_t and D_ref clamped to [0,1])",
        border: BorderRule::None,
        // "The details of this are implementation-dependent, but r should be a value in the range
        //  [0, 1] which is proportional to the number of comparison passes or failures."
        filtering: Filtering::ImplementationDependent,
        filter_cite: "EXT_shadow_samplers §3.7.14.1 (filtered r implementation-dependent)",
        // ES 2.0 §3.8.2: an incomplete texture returns (0,0,0,1); shadow2DEXT returns its R.
        incomplete: Incomplete::Legacy0001,
        es_depth_completeness: false,
        seamless_cube: true,
        seamless_enable: None,
        swizzle: None,
        sampler_objects: None,
        lod_bias: false,
        sampler_create: None,
        layer_rne_always: None,
        ambient_on_pass: false,
        fail_value_cite: None,
        // GLSL additions: "sampler2DShadow  a handle for accessing a 2D depth texture with comparison";
        // OES_depth_texture allows TEXTURE_2D only.
        targets: &[Target::T2d],
        wraps: &[Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat],
        apis: &[ApiPath::Es100Ext],
        depth_modes: &[],
        depth_stencil_mode: false,
        bad_func_error: "INVALID_ENUM",
        // OES_depth_texture: UNSIGNED_SHORT / UNSIGNED_INT data into DEPTH_COMPONENT; DEPTH_STENCIL_OES.
        formats: &[
            Format::D16,
            Format::D24,
            Format::D24S8,
            Format::DepthUnsized,
            Format::R8,
        ],
        mode_pname: state::TEXTURE_COMPARE_MODE,
        func_pname: state::TEXTURE_COMPARE_FUNC,
        params,
        // ES 2.0 Table 3.10 has no TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, TEXTURE_MIN_LOD or
        // TEXTURE_MAX_LOD: setting them is an INVALID_ENUM.
        no_lod_state: Some("TEXTURE_BASE_LEVEL / TEXTURE_MAX_LEVEL / TEXTURE_MIN_LOD / TEXTURE_MAX_LOD are not ES 2.0 state"),
        // EXT_shadow_samplers: "float shadow2DEXT(sampler2DShadow sampler, vec3 coord); float
        // shadow2DProjEXT(sampler2DShadow sampler, vec4 coord);" — no bias argument.
        no_lookup_bias: Some("shadow2DEXT / shadow2DProjEXT take no bias argument"),
        fixed_depth_mode: None,
        // A colour texture is R8 / LUMINANCE8 read as (r,0,0,1), as in ES 3.x.
        colour_luminance: false,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[Reading {
            id: "es2-greater-row",
            other: Some(greater_row_funcs),
        }],
    }
}

/// Contradiction `es2-greater-row`: EXT_shadow_funcs' GREATER row (0.0 at equality).
fn greater_row_funcs(r: Rules) -> Rules {
    Rules {
        table: table_greater_row_funcs,
        ..r
    }
}

/// The TexParameter state of EXT_shadow_samplers; ES contexts only.
pub fn params(_: Spec, ctx: Ctx) -> Vec<Param> {
    if ctx != Ctx::Es {
        return Vec::new();
    }
    // Table 3.10 as appended: "TEXTURE_COMPARE_MODE_EXT enum NONE, COMPARE_REF_TO_TEXTURE_EXT",
    // "TEXTURE_COMPARE_FUNC_EXT enum LEQUAL, GEQUAL, LESS, GREATER, EQUAL, NOTEQUAL, ALWAYS,
    // NEVER". The extension has no Errors or New State section: ES 2.0 §2.5 reports an
    // unaccepted enum value with INVALID_ENUM, and the initial values are those of ARB_shadow.
    vec![
        Param::compare_mode(
            "TEXTURE_COMPARE_MODE_EXT",
            "EXT_shadow_samplers §3.7.4 (table 3.10)",
        ),
        Param::compare_func8(
            "TEXTURE_COMPARE_FUNC_EXT",
            "EXT_shadow_samplers §3.7.4 (table 3.10)",
        ),
    ]
}
