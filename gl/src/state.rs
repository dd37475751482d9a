//! State cases on a GL context: the TexParameter / GetTexParameter call of a
//! [`StateCase`] on a fresh texture object, observed (the first GL error after the call, the value
//! read back afterwards) and never judged: the runner compares with the oracle's expectation.

use glow::HasContext;
use shadowcheck_model::{GlErrorCode, StateCall, StateCase, StateObserved, StateType, StateValue};

/// The first pending GL error, then drains the rest (so the next call starts clean).
unsafe fn take_error(gl: &glow::Context) -> (Option<GlErrorCode>, Option<u32>) {
    let first = gl.get_error();
    let mut guard = 0;
    while gl.get_error() != glow::NO_ERROR && guard < 16 {
        guard += 1;
    }
    GlErrorCode::classify(first)
}

/// GetTexParameter of `case.pname` in the type the pname is stored as.
unsafe fn read(gl: &glow::Context, case: &StateCase) -> StateValue {
    let (target, pname) = (case.target.gl(), case.pname.gl());
    match case.pname.value_type() {
        StateType::Bool => StateValue::Bool(gl.get_tex_parameter_i32(target, pname) != 0),
        StateType::Enum => StateValue::Enum(gl.get_tex_parameter_i32(target, pname) as u32),
        StateType::Float => StateValue::Float(gl.get_tex_parameter_f32(target, pname)),
    }
}

/// Runs `case` on a fresh texture object bound to its target (unit 0) and reports what happened.
/// For `Initial` the error is GetTexParameter's own; otherwise the error is TexParameter's and the
/// value is read afterwards (only when `case.read_back`; a failing read then shows as an error
/// only if the call itself raised none).
///
/// # Safety
/// The context of `gl` must be current.
pub unsafe fn observe(gl: &glow::Context, case: &StateCase) -> StateObserved {
    while gl.get_error() != glow::NO_ERROR {}
    let tex = gl.create_texture().ok();
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(case.target.gl(), tex);
    let (target, pname) = (case.target.gl(), case.pname.gl());
    let observed = match case.call {
        StateCall::Initial => {
            let v = read(gl, case);
            let (error, other_error) = take_error(gl);
            StateObserved {
                error,
                other_error,
                value: (case.read_back && error.is_none() && other_error.is_none()).then_some(v),
            }
        }
        call => {
            match call {
                StateCall::SetFloat(f) => gl.tex_parameter_f32(target, pname, f),
                StateCall::SetInt(i) => gl.tex_parameter_i32(target, pname, i),
                StateCall::Initial => {}
            }
            let (error, other_error) = take_error(gl);
            let value = if case.read_back {
                let v = read(gl, case);
                let read_failed = gl.get_error() != glow::NO_ERROR;
                (!read_failed).then_some(v)
            } else {
                None
            };
            StateObserved {
                error,
                other_error,
                value,
            }
        }
    };
    gl.bind_texture(case.target.gl(), None);
    if let Some(t) = tex {
        gl.delete_texture(t);
    }
    while gl.get_error() != glow::NO_ERROR {}
    observed
}
