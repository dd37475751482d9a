//! EXT_shadow_funcs (2002/03/22): the eight comparison functions on top of ARB_shadow.
//! Source: the OpenGL Registry text of EXT_shadow_funcs.

use crate::rules::{passes_if, CompareTable, NotInTable, Rules};
use crate::state::{self, Ctx, Param};
use shadowcheck_model::{CompareFunc, Spec};
use std::cmp::Ordering::{self, *};

/// The updated pseudo-code of ARB_shadow §3.8.13.1:
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "LEQUAL  { 1.0, if R <= Dt  { 0.0, if R > Dt"
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "GEQUAL  { 1.0, if R >= Dt  { 0.0, if R < Dt"
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "LESS    { 1.0, if R < Dt   { 0.0, if R >= Dt"
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "GREATER { 1.0, if R > Dt   { 0.0, if R <= Dt"
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "EQUAL   { 1.0, if R == Dt  { 0.0, if R != Dt"
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "NOTEQUAL { 1.0, if R != Dt { 0.0, if R == Dt"
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "ALWAYS r = 1.0"
        CompareFunc::Always => Some(true),
        // "NEVER r = 0.0"
        CompareFunc::Never => Some(false),
        // Errors: "INVALID_ENUM is generated if ... <param> is not one of LEQUAL, GEQUAL, LESS,
        // GREATER, EQUAL, NOTEQUAL, ALWAYS, or NEVER."
        _ => return Err(NotInTable),
    })
}

/// ARB_shadow's rules with the eight-function table.
pub fn rules() -> Rules {
    Rules {
        spec: Spec::ExtFuncs,
        doc: "ARB_shadow + EXT_shadow_funcs",
        table: table as CompareTable,
        table_cite: "EXT_shadow_funcs (ARB_shadow §3.8.13.1 pseudo-code, updated)",
        params,
        ..crate::arb::rules(Spec::Arb)
    }
}

/// ARB_shadow's state with EXT_shadow_funcs' TEXTURE_COMPARE_FUNC in place of ARB_shadow's.
pub fn params(_: Spec, ctx: Ctx) -> Vec<Param> {
    let mut v = crate::arb::params(Spec::Arb, ctx);
    for p in v.iter_mut() {
        if p.pname == state::TEXTURE_COMPARE_FUNC {
            // EXT_shadow_funcs Errors: "... is not one of LEQUAL, GEQUAL, LESS, GREATER, EQUAL,
            // NOTEQUAL, ALWAYS, or NEVER"; initial LEQUAL.
            *p = Param::compare_func8("TEXTURE_COMPARE_FUNC", "EXT_shadow_funcs Errors, New State");
        }
    }
    v
}
