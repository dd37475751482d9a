//! State cases on the page: the TexParameter / GetTexParameter call of a [`StateCase`] on a fresh
//! WebGL texture, observed as the GL worker observes it (`shadowcheck_gl::state::observe`: the
//! first error after the call, the value read back afterwards) and never judged.

use super::browser::Browser;
use super::WebglError;
use serde::{Deserialize, Serialize};
use shadowcheck_model::{GlErrorCode, StateCall, StateCase, StateObserved, StateType, StateValue};

/// What `shadowcheck.state` in page.js gets.
#[derive(Serialize)]
struct PageRequest {
    target: u32,
    pname: u32,
    /// `initial`, `int` (texParameteri) or `float` (texParameterf).
    call: &'static str,
    /// The value set, as a JavaScript number literal ("NaN", "Infinity" included).
    value: String,
    read_back: bool,
}

/// What it answers: glGetError after the call (0: NO_ERROR), the value read (a number; null when
/// getTexParameter returned none) and glGetError after that read.
#[derive(Deserialize)]
struct PageState {
    error: u32,
    value: Option<f64>,
    read_error: u32,
}

fn js_number(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "Infinity" } else { "-Infinity" }.into()
    } else {
        format!("{v:?}")
    }
}

/// Runs `case` in the page (`lose`: the test fault, the context lost before the call). A lost
/// context is [`WebglError::ContextLost`], never an observation.
pub fn observe(
    browser: &mut Browser,
    case: &StateCase,
    lose: bool,
) -> Result<StateObserved, WebglError> {
    let (call, value) = match case.call {
        StateCall::Initial => ("initial", 0.0),
        StateCall::SetInt(i) => ("int", i as f64),
        StateCall::SetFloat(f) => ("float", f as f64),
    };
    let req = PageRequest {
        target: case.target.gl(),
        pname: case.pname.gl(),
        call,
        value: js_number(value),
        read_back: case.read_back,
    };
    let arg = serde_json::to_string(&req).map_err(|e| WebglError::Page(e.to_string()))?;
    let v = browser.evaluate(&format!("shadowcheck.state({arg}, {{\"lose\": {lose}}})"))?;
    if let Some(why) = v.get("lost") {
        return Err(WebglError::ContextLost(
            why.as_str().unwrap_or("").to_string(),
        ));
    }
    let page: PageState = serde_json::from_value(v.clone())
        .map_err(|e| WebglError::Page(format!("state answered {v}: {e}")))?;
    let (error, other_error) = GlErrorCode::classify(page.error);
    // As on GL: the initial value counts only when the query raised no error; a set value only
    // when its read raised none.
    let read_ok = match case.call {
        StateCall::Initial => error.is_none() && other_error.is_none(),
        _ => page.read_error == 0,
    };
    let value =
        page.value
            .filter(|_| case.read_back && read_ok)
            .map(|v| match case.pname.value_type() {
                StateType::Bool => StateValue::Bool(v != 0.0),
                StateType::Enum => StateValue::Enum(v as u32),
                StateType::Float => StateValue::Float(v as f32),
            });
    Ok(StateObserved {
        error,
        other_error,
        value,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_reach_the_page_as_javascript_numbers() {
        assert_eq!(js_number(0x884E as f64), "34894.0");
        assert_eq!(js_number(-0.5), "-0.5");
        assert_eq!(js_number(f64::NAN), "NaN");
        assert_eq!(js_number(f64::NEG_INFINITY), "-Infinity");
    }
}
