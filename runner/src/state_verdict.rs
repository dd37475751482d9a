//! Verdicts on state cases: what a context observed after a TexParameter / GetTexParameter call
//! against the oracle's [`StateExpect`] in the fixture. Pass when the error and the value read back
//! are the expected ones, Fail otherwise (there is no Warn: state has no precision).

use crate::records::Outcome;
use shadowcheck_model::{StateCase, StateExpect, StateObserved};

fn error_text(e: Option<shadowcheck_model::GlError>, other: Option<u32>) -> String {
    match (e, other) {
        (Some(e), _) => format!("GL_{}", e.name()),
        (None, Some(code)) => format!("GL error 0x{code:04X}"),
        (None, None) => "no error".into(),
    }
}

/// What the expectation says, e.g. `GL_INVALID_ENUM, value 0x0000`.
pub fn expected_text(e: &StateExpect) -> String {
    match e.value {
        Some(v) => format!("{}, value {v}", error_text(e.error, None)),
        None => error_text(e.error, None),
    }
}

/// What was observed, in the same words.
pub fn observed_text(o: &StateObserved) -> String {
    let err = error_text(o.error, o.other_error);
    match o.value {
        Some(v) => format!("{err}, value {v}"),
        None => err,
    }
}

/// The verdict on one observation of `case` (Fail with both sides and the citations when it
/// differs; a case without an expectation cannot be judged: Fail saying so).
pub fn judge_state(case: &StateCase, o: &StateObserved) -> (Outcome, Option<String>) {
    let Some(e) = &case.expect else {
        return (
            Outcome::Fail,
            Some("the state case carries no expectation (fixture without `expect`)".into()),
        );
    };
    let error_ok = o.error == e.error && o.other_error.is_none();
    let value_ok = match (e.value, o.value) {
        (None, _) => true,
        // Floats are compared as the f32 both sides hold.
        (Some(want), Some(got)) => want == got,
        (Some(_), None) => false,
    };
    if error_ok && value_ok {
        return (Outcome::Pass, None);
    }
    let unchanged = if e.error.is_some() && e.value.is_some() {
        " (state unchanged after the error)"
    } else {
        ""
    };
    (
        Outcome::Fail,
        Some(format!(
            "{} on {}: expected {}{unchanged}, got {}; {}",
            case.call,
            case.pname.name(),
            expected_text(e),
            observed_text(o),
            e.citations.join("; ")
        )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{ApiPath, GlError, Spec, StateCall, StatePname, StateValue, Target};

    fn case(error: Option<GlError>, value: Option<StateValue>) -> StateCase {
        StateCase {
            id: "s".into(),
            spec: Spec::Gl46,
            api: vec![ApiPath::GlslCore],
            target: Target::T2d,
            pname: StatePname::CompareMode,
            call: StateCall::SetInt(0x1234),
            read_back: true,
            expect: Some(StateExpect {
                error,
                value,
                citations: vec!["GL 4.6 §8.10".into()],
            }),
        }
    }

    #[test]
    fn error_and_unchanged_value_both_decide() {
        let c = case(Some(GlError::InvalidEnum), Some(StateValue::Enum(0)));
        let ok = StateObserved {
            error: Some(GlError::InvalidEnum),
            other_error: None,
            value: Some(StateValue::Enum(0)),
        };
        assert_eq!(judge_state(&c, &ok).0, Outcome::Pass);
        // No error raised and the illegal value stored: Fail naming both.
        let stored = StateObserved {
            error: None,
            other_error: None,
            value: Some(StateValue::Enum(0x1234)),
        };
        let (o, why) = judge_state(&c, &stored);
        assert_eq!(o, Outcome::Fail);
        let why = why.unwrap_or_default();
        assert!(
            why.contains("expected GL_INVALID_ENUM, value 0x0000"),
            "{why}"
        );
        assert!(why.contains("got no error, value 0x1234"), "{why}");
        // The right error but the state changed anyway: Fail.
        let changed = StateObserved {
            value: Some(StateValue::Enum(0x1234)),
            ..ok.clone()
        };
        assert_eq!(judge_state(&c, &changed).0, Outcome::Fail);
        // Another error code: Fail.
        let other = StateObserved {
            error: None,
            other_error: Some(0x0505),
            value: Some(StateValue::Enum(0)),
        };
        assert_eq!(judge_state(&c, &other).0, Outcome::Fail);
    }
}
