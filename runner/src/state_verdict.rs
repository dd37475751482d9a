//! Verdicts on state cases: what a context observed after a TexParameter / GetTexParameter call
//! against the oracle's [`StateExpect`] in the fixture. Pass when the error and the value read back
//! are the expected ones, Fail otherwise (there is no Warn: state has no precision). Where the
//! expectation lists what a context exposing an extension must do instead (`with_extension`, e.g.
//! TEXTURE_COMPARE_FAIL_VALUE_ARB with GL_ARB_shadow_ambient), the extensions the backend reported in
//! its hello decide which one applies; a backend reporting none is judged against the base one.

use crate::records::Outcome;
use shadowcheck_model::{
    AppliedExpect, GlErrorCode, StateCase, StateExpect, StateObserved, StateValue,
};

fn error_text(e: Option<GlErrorCode>, other: Option<u32>) -> String {
    match (e, other) {
        (Some(e), _) => format!("GL_{}", e.name()),
        (None, Some(code)) => format!("GL error 0x{code:04X}"),
        (None, None) => "no error".into(),
    }
}

fn expected_words(error: Option<GlErrorCode>, value: Option<StateValue>) -> String {
    match value {
        Some(v) => format!("{}, value {v}", error_text(error, None)),
        None => error_text(error, None),
    }
}

/// What the base expectation says, e.g. `GL_INVALID_ENUM, value 0x0000`.
pub fn expected_text(e: &StateExpect) -> String {
    expected_words(e.error, e.value)
}

/// What was observed, in the same words.
pub fn observed_text(o: &StateObserved) -> String {
    let err = error_text(o.error, o.other_error);
    match o.value {
        Some(v) => format!("{err}, value {v}"),
        None => err,
    }
}

/// The verdict on one observation of `case` on a backend whose extension string lists
/// `extensions` (Fail with both sides and the citations when it differs). A case without an
/// expectation (a fixture without `expect`) is judged against the oracle's, as a lookup case
/// is ([`crate::verdict::judge`]); one the oracle cannot evaluate is Skip with its reason. The
/// reason names the extension whose expectation was used, if any: a Pass under an extension's
/// expectation says so too.
pub fn judge_state<S: AsRef<str>>(
    case: &StateCase,
    o: &StateObserved,
    extensions: &[S],
) -> (Outcome, Option<String>) {
    let evaluated;
    let e = match &case.expect {
        Some(e) => e,
        None => match shadowcheck_oracle::state::expect_state(case) {
            Ok(e) => {
                evaluated = e;
                &evaluated
            }
            Err(msg) => {
                return (
                    Outcome::Skip,
                    Some(format!("no expectation for this state case: {msg}")),
                )
            }
        },
    };
    let AppliedExpect {
        extension,
        error,
        value,
        citations,
    } = e.for_extensions(extensions);
    let error_ok = o.error == error && o.other_error.is_none();
    let value_ok = match (value, o.value) {
        (None, _) => true,
        // Floats are compared as the f32 both sides hold.
        (Some(want), Some(got)) => want == got,
        (Some(_), None) => false,
    };
    let with = extension
        .map(|x| format!("with {x} exposed: "))
        .unwrap_or_default();
    if error_ok && value_ok {
        // A Pass under the base expectation needs no words; one under an extension's says whose.
        let why = extension.map(|_| {
            format!(
                "{with}{} on {}: {}",
                case.call,
                case.pname.name(),
                expected_words(error, value)
            )
        });
        return (Outcome::Pass, why);
    }
    let unchanged = if error.is_some() && value.is_some() {
        " (state unchanged after the error)"
    } else {
        ""
    };
    (
        Outcome::Fail,
        Some(format!(
            "{with}{} on {}: expected {}{unchanged}, got {}; {}",
            case.call,
            case.pname.name(),
            expected_words(error, value),
            observed_text(o),
            citations.join("; ")
        )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{
        ApiPath, GlErrorCode, Spec, StateCall, StatePname, StateValue, Target,
    };

    /// A backend that reports no extensions (soft, exec, mock).
    const NONE: &[&str] = &[];

    fn case(error: Option<GlErrorCode>, value: Option<StateValue>) -> StateCase {
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
                with_extension: vec![],
            }),
        }
    }

    #[test]
    fn error_and_unchanged_value_both_decide() {
        let c = case(Some(GlErrorCode::InvalidEnum), Some(StateValue::Enum(0)));
        let ok = StateObserved {
            error: Some(GlErrorCode::InvalidEnum),
            other_error: None,
            value: Some(StateValue::Enum(0)),
        };
        assert_eq!(judge_state(&c, &ok, NONE).0, Outcome::Pass);
        // No error raised and the illegal value stored: Fail naming both.
        let stored = StateObserved {
            error: None,
            other_error: None,
            value: Some(StateValue::Enum(0x1234)),
        };
        let (o, why) = judge_state(&c, &stored, NONE);
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
        assert_eq!(judge_state(&c, &changed, NONE).0, Outcome::Fail);
        // Another error code: Fail.
        let other = StateObserved {
            error: None,
            other_error: Some(0x0505),
            value: Some(StateValue::Enum(0)),
        };
        assert_eq!(judge_state(&c, &other, NONE).0, Outcome::Fail);
    }
    #[test]
    fn a_case_without_expect_is_judged_by_the_oracle() {
        // GL 4.6 §8.10: TEXTURE_COMPARE_MODE takes NONE or COMPARE_REF_TO_TEXTURE; any other
        // value is INVALID_ENUM (Errors of TexParameter) and the call is ignored (§2.3.1), so the
        // initial NONE (Table 23.15) is read back.
        let mut c = case(None, None);
        c.expect = None;
        let right = StateObserved {
            error: Some(GlErrorCode::InvalidEnum),
            other_error: None,
            value: Some(StateValue::Enum(0)),
        };
        assert_eq!(judge_state(&c, &right, NONE), (Outcome::Pass, None));
        let stored = StateObserved {
            error: None,
            other_error: None,
            value: Some(StateValue::Enum(0x1234)),
        };
        let (o, why) = judge_state(&c, &stored, NONE);
        assert_eq!(o, Outcome::Fail);
        assert!(why
            .unwrap_or_default()
            .contains("expected GL_INVALID_ENUM, value 0x0000"),);
        // A case the oracle cannot place (no API path, so no context kind): Skip, not Fail.
        c.api.clear();
        let (o, why) = judge_state(&c, &right, NONE);
        assert_eq!(o, Outcome::Skip);
        assert!(why.unwrap_or_default().starts_with("no expectation"));
    }

    /// A GL 4.6 compatibility case on a pname only an extension defines, with the oracle's
    /// expectation (base INVALID_ENUM, and the extension's rules beside it).
    fn ext_case(pname: StatePname, call: StateCall) -> StateCase {
        let mut c = StateCase {
            id: "state/gl46/compat/2d/x".into(),
            spec: Spec::Gl46,
            api: vec![ApiPath::FixedFunction],
            target: Target::T2d,
            pname,
            call,
            read_back: true,
            expect: None,
        };
        c.expect = shadowcheck_oracle::state::expect_state(&c).ok();
        c
    }

    fn observed(error: Option<GlErrorCode>, value: Option<StateValue>) -> StateObserved {
        StateObserved {
            error,
            other_error: None,
            value,
        }
    }

    #[test]
    fn arb_shadow_ambient_exposed_makes_the_fail_value_legal_and_says_so() {
        let c = ext_case(StatePname::CompareFailValue, StateCall::SetFloat(1.5));
        let accepted = observed(None, Some(StateValue::Float(1.0)));
        let rejected = observed(Some(GlErrorCode::InvalidEnum), None);
        let arb = &["GL_ARB_shadow", "GL_ARB_shadow_ambient"];
        // Exposed and accepted (clamped to [0,1]): Pass, saying which expectation was used.
        let (o, why) = judge_state(&c, &accepted, arb);
        assert_eq!(o, Outcome::Pass);
        let why = why.unwrap_or_default();
        assert!(
            why.starts_with("with GL_ARB_shadow_ambient exposed: TexParameterf(1.5) on TEXTURE_COMPARE_FAIL_VALUE_ARB: no error, value 1"),
            "{why}"
        );
        // Not exposed but accepted anyway: Fail against the base expectation.
        let (o, why) = judge_state(&c, &accepted, &["GL_ARB_shadow"]);
        assert_eq!(o, Outcome::Fail);
        let why = why.unwrap_or_default();
        assert!(why.starts_with("TexParameterf(1.5) on TEXTURE_COMPARE_FAIL_VALUE_ARB: expected GL_INVALID_ENUM, got no error, value 1"), "{why}");
        // A backend that reports no extension list (exec, soft, mock): the base expectation.
        assert_eq!(judge_state(&c, &rejected, NONE), (Outcome::Pass, None));
        assert_eq!(judge_state(&c, &accepted, NONE).0, Outcome::Fail);
        // Exposed but rejected: Fail under the extension's expectation, unclamped storage too.
        let (o, why) = judge_state(&c, &rejected, arb);
        assert_eq!(o, Outcome::Fail);
        let why = why.unwrap_or_default();
        assert!(
            why.starts_with("with GL_ARB_shadow_ambient exposed: TexParameterf(1.5) on TEXTURE_COMPARE_FAIL_VALUE_ARB: expected no error, value 1, got GL_INVALID_ENUM"),
            "{why}"
        );
        assert!(why.contains("ARB_shadow_ambient"), "{why}");
        let unclamped = observed(None, Some(StateValue::Float(1.5)));
        assert_eq!(judge_state(&c, &unclamped, arb).0, Outcome::Fail);
        // SGIX_shadow_ambient names the same token (0x80BF) with the same rules.
        let sgix = &["GL_SGIX_shadow_ambient"];
        let (o, why) = judge_state(&c, &accepted, sgix);
        assert_eq!(o, Outcome::Pass);
        assert!(why
            .unwrap_or_default()
            .starts_with("with GL_SGIX_shadow_ambient exposed:"));
    }

    #[test]
    fn sgix_shadow_exposed_makes_its_pnames_legal_and_a_bad_operator_invalid_operation() {
        let sgix = &["GL_SGIX_shadow"];
        let c = ext_case(StatePname::CompareOperatorSgix, StateCall::SetInt(0x0203));
        // SGIX_shadow Errors: a value other than TEXTURE_LEQUAL_R_SGIX / _GEQUAL_R_SGIX is
        // INVALID_OPERATION, the operator stays TEXTURE_LEQUAL_R_SGIX.
        let right = observed(
            Some(GlErrorCode::InvalidOperation),
            Some(StateValue::Enum(0x819C)),
        );
        let (o, why) = judge_state(&c, &right, sgix);
        assert_eq!(o, Outcome::Pass);
        assert!(why
            .unwrap_or_default()
            .starts_with("with GL_SGIX_shadow exposed:"));
        // The pname accepted without the extension in the string: Fail.
        assert_eq!(judge_state(&c, &right, NONE).0, Outcome::Fail);
        // INVALID_ENUM for a bad operator where SGIX_shadow says INVALID_OPERATION: Fail.
        let enum_err = observed(
            Some(GlErrorCode::InvalidEnum),
            Some(StateValue::Enum(0x819C)),
        );
        let (o, why) = judge_state(&c, &enum_err, sgix);
        assert_eq!(o, Outcome::Fail);
        assert!(
            why.unwrap_or_default().contains("expected GL_INVALID_OPERATION, value 0x819C (state unchanged after the error), got GL_INVALID_ENUM"),
        );
        // TEXTURE_COMPARE_SGIX initially FALSE with the extension; INVALID_ENUM without.
        let c = ext_case(StatePname::CompareSgix, StateCall::Initial);
        let f = observed(None, Some(StateValue::Bool(false)));
        assert_eq!(judge_state(&c, &f, sgix).0, Outcome::Pass);
        assert_eq!(judge_state(&c, &f, NONE).0, Outcome::Fail);
        let unknown = observed(Some(GlErrorCode::InvalidEnum), None);
        assert_eq!(judge_state(&c, &unknown, NONE), (Outcome::Pass, None));
        // Another extension in the string changes nothing.
        assert_eq!(
            judge_state(&c, &unknown, &["GL_ARB_shadow_ambient"]),
            (Outcome::Pass, None)
        );
    }
}
