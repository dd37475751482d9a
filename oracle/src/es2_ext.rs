//! OpenGL ES 2.0 with EXT_shadow_samplers (rev 4, 2012) and OES_depth_texture.
//! Source: specs/registry/EXT_shadow_samplers.txt, OES_depth_texture.txt.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, RefClamp, Rules,
};
use shadowcheck_model::{ApiPath, CompareFunc, Spec, Target, Wrap};
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
        // The printed 0.0 row leaves D_ref == Dt unstated (contradiction `es2-greater-row`). We read
        // the 1.0 row: equality does not satisfy "D_ref > Dt", so r = 0.0, as in EXT_shadow_funcs
        // ("0.0, if R <= Dt"), on which the extension is based.
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

/// The other reading of the GREATER row: at D_ref == Dt the table assigns nothing, so either value.
pub fn table_greater_row_literal(
    func: CompareFunc,
    ord: Option<Ordering>,
) -> Result<Option<bool>, NotInTable> {
    match (func, ord) {
        (CompareFunc::Greater, Some(Equal)) => Ok(None),
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
        lod_bias: false,
        ambient_on_pass: false,
        has_fail_value: false,
        // GLSL additions: "sampler2DShadow  a handle for accessing a 2D depth texture with comparison";
        // OES_depth_texture allows TEXTURE_2D only.
        targets: &[Target::T2d],
        wraps: &[Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat],
        apis: &[ApiPath::Es100Ext],
        depth_modes: &[],
        depth_stencil_mode: false,
        bad_func_error: "INVALID_ENUM",
    }
}
