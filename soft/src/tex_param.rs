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
    ApiPath, GlError, Spec, StateCall, StateCase, StateObserved, StatePname, StateValue,
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

/// One state case on a fresh texture object, in the context kind of `api`.
pub fn observe(spec: Spec, faults: Faults, case: &StateCase, api: ApiPath) -> StateObserved {
    let ctx = context(api);
    let Some((initial, legal)) = table(spec, ctx, case.pname, faults) else {
        return StateObserved {
            error: Some(GlError::InvalidEnum),
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
                _ => (Some(GlError::InvalidEnum), initial),
            }
        }
    };
    StateObserved {
        error,
        other_error: None,
        value: case.read_back.then_some(StateValue::Enum(stored)),
    }
}
