//! The soft unit's own TexParameter / GetTexParameter state for the depth-comparison pnames,
//! written from the spec text independently of the oracle's tables (`shadowcheck_oracle::state`),
//! so that state cases check the oracle as lookups do.
//!
//! GL 4.6 Table 8.17 (core) and compatibility Table 8.25 / ES 3.2 Table 8.19: TEXTURE_COMPARE_MODE
//! is NONE or COMPARE_REF_TO_TEXTURE, TEXTURE_COMPARE_FUNC one of NEVER..ALWAYS,
//! DEPTH_STENCIL_TEXTURE_MODE DEPTH_COMPONENT or STENCIL_INDEX; DEPTH_TEXTURE_MODE RED, LUMINANCE,
//! INTENSITY or ALPHA in the compatibility profile only. Initial values (Table 23.15, compatibility
//! §8.22): NONE, LEQUAL, DEPTH_COMPONENT, LUMINANCE. §8.10: "An INVALID_ENUM error is generated if
//! pname is not one of the parameter names" and "... if the type of the parameter specified by pname
//! is enum, and any value specified by param or params is not among the legal values"; §2.3.1: the
//! command that generates an error "is ignored so that it has no effect on GL state".

use crate::faults::{Fault, Faults};
use shadowcheck_model::{
    ApiPath, GlErrorCode, Spec, StateCall, StateCase, StateObserved, StatePname, StateValue,
};

/// The context kind a state case's API path stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Context {
    Core,
    Compat,
    Es,
}

fn context(api: ApiPath) -> Context {
    match api {
        ApiPath::GlslCore => Context::Core,
        ApiPath::Es300 | ApiPath::Es100Ext => Context::Es,
        _ => Context::Compat,
    }
}

/// Initial value and legal values of `pname` in a context of `spec`; `None`: no such pname.
fn table(spec: Spec, ctx: Context, pname: StatePname, faults: Faults) -> Option<(u32, Vec<u32>)> {
    if !matches!(spec, Spec::Gl46 | Spec::Gles32) {
        return None;
    }
    let lequal = if faults.has(Fault::WrongInitialCompareFunc) {
        0x0201 // LESS
    } else {
        0x0203 // LEQUAL
    };
    Some(match pname {
        StatePname::CompareMode => (0x0000, vec![0x0000, 0x884E]),
        StatePname::CompareFunc => (lequal, (0x0200..=0x0207).collect()),
        StatePname::DepthStencilMode => (0x1902, vec![0x1902, 0x1901]),
        StatePname::DepthTextureMode if ctx == Context::Compat => {
            (0x1909, vec![0x1903, 0x1909, 0x8049, 0x1906])
        }
        _ => return None,
    })
}

/// The extensions the soft unit can expose on a compatibility context (only when asked:
/// [`crate::SoftUnit::tex_parameter_exposing`]; the soft backend's hello lists none), each adding
/// TexParameter pnames GL 4.6 lacks. Written from the extension texts:
/// - ARB_shadow_ambient: TEXTURE_COMPARE_FAIL_VALUE_ARB (0x80BF) "float, any value in [0, 1]",
///   "clamped to lie in [0, 1]", initial 0.0, no errors;
/// - SGIX_shadow: TEXTURE_COMPARE_SGIX boolean, initially False; TEXTURE_COMPARE_OPERATOR_SGIX
///   TEXTURE_LEQUAL_R_SGIX or TEXTURE_GEQUAL_R_SGIX, initially TEXTURE_LEQUAL_R_SGIX, any other
///   value INVALID_OPERATION (its Errors section);
/// - SGIX_shadow_ambient: SHADOW_AMBIENT_SGIX (the same 0x80BF) clamped to [0.0, 1.0], initial 0.0.
pub const STATE_EXTENSIONS: &[&str] = &[
    "GL_ARB_shadow_ambient",
    "GL_SGIX_shadow",
    "GL_SGIX_shadow_ambient",
];

/// A state case on a pname that an exposed extension adds, on a compatibility context of a spec
/// whose own table lacks it; `None` when no exposed extension adds it.
fn observe_extension(case: &StateCase, exposed: &[&str], faults: Faults) -> Option<StateObserved> {
    let has = |e: &str| exposed.contains(&e);
    let as_int = |call: StateCall| match call {
        StateCall::SetInt(i) => i as i64,
        StateCall::SetFloat(f) => f.round() as i64,
        StateCall::Initial => 0,
    };
    let (error, value) = match case.pname {
        StatePname::CompareFailValue
            if has("GL_ARB_shadow_ambient") || has("GL_SGIX_shadow_ambient") =>
        {
            let v = match case.call {
                StateCall::Initial => 0.0,
                StateCall::SetInt(i) => (i as f32).clamp(0.0, 1.0),
                StateCall::SetFloat(f) => f.clamp(0.0, 1.0),
            };
            (None, StateValue::Float(v))
        }
        StatePname::CompareSgix if has("GL_SGIX_shadow") => {
            let v = match case.call {
                StateCall::Initial => false,
                StateCall::SetInt(i) => i != 0,
                StateCall::SetFloat(f) => f != 0.0,
            };
            (None, StateValue::Bool(v))
        }
        StatePname::CompareOperatorSgix if has("GL_SGIX_shadow") => {
            const LEQUAL_R: u32 = 0x819C;
            const GEQUAL_R: u32 = 0x819D;
            match case.call {
                StateCall::Initial => (None, StateValue::Enum(LEQUAL_R)),
                call => match u32::try_from(as_int(call)) {
                    Ok(e) if e == LEQUAL_R || e == GEQUAL_R => (None, StateValue::Enum(e)),
                    _ => (
                        Some(GlErrorCode::InvalidOperation),
                        StateValue::Enum(LEQUAL_R),
                    ),
                },
            }
        }
        _ => return None,
    };
    if faults.has(Fault::ExtensionPnameRejected) {
        return Some(StateObserved {
            error: Some(GlErrorCode::InvalidEnum),
            other_error: None,
            value: None,
        });
    }
    Some(StateObserved {
        error,
        other_error: None,
        value: case.read_back.then_some(value),
    })
}

/// One state case on a fresh texture object, in the context kind of `api`, exposing no extension.
pub fn observe(spec: Spec, faults: Faults, case: &StateCase, api: ApiPath) -> StateObserved {
    observe_exposing(spec, faults, case, api, &[])
}

/// One state case on a fresh texture object, in the context kind of `api`, whose extension string
/// lists `exposed` (those of [`STATE_EXTENSIONS`] count, on compatibility contexts only).
pub fn observe_exposing(
    spec: Spec,
    faults: Faults,
    case: &StateCase,
    api: ApiPath,
    exposed: &[&str],
) -> StateObserved {
    let ctx = context(api);
    let Some((initial, legal)) = table(spec, ctx, case.pname, faults) else {
        if ctx == Context::Compat {
            if let Some(o) = observe_extension(case, exposed, faults) {
                return o;
            }
        }
        return StateObserved {
            error: Some(GlErrorCode::InvalidEnum),
            other_error: None,
            value: None,
        };
    };
    let (error, stored) = match case.call {
        StateCall::Initial => (None, initial),
        call => {
            // Enums given as floats are rounded to the nearest integer (GL 4.6 §2.2.1).
            let v = match call {
                StateCall::SetFloat(f) => f.round() as i64,
                StateCall::SetInt(i) => i as i64,
                StateCall::Initial => initial as i64,
            };
            match u32::try_from(v) {
                Ok(e) if legal.contains(&e) => (None, e),
                Ok(e) if faults.has(Fault::IllegalValueStored) => (None, e),
                _ => (Some(GlErrorCode::InvalidEnum), initial),
            }
        }
    };
    StateObserved {
        error,
        other_error: None,
        value: case.read_back.then_some(StateValue::Enum(stored)),
    }
}
