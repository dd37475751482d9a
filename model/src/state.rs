//! A state case: one TexParameter / GetTexParameter call on a fresh texture object and the state
//! and error it must leave (the second kind of test besides the lookup [`crate::Case`]).
//!
//! The case names the context kinds it runs in by API path (`core`: core profile, `ff`:
//! compatibility profile, `es300`: OpenGL ES 3): TexParameter state belongs to the context, not to
//! a lookup path, so each state case lists the one path that exists only in its context kind.

use crate::enums::{ApiPath, Spec, Target};
use crate::ModelError;
use serde::{Deserialize, Serialize};

macro_rules! pnames {
    ($($(#[$m:meta])* $var:ident = $key:literal, $gl:literal, $name:literal, $ty:ident;)+) => {
        /// A depth-comparison texture parameter name.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
        pub enum StatePname { $($(#[$m])* #[serde(rename = $key)] $var),+ }
        impl StatePname {
            pub const ALL: &'static [StatePname] = &[$(StatePname::$var),+];
            /// The short key used in ids and fixtures.
            pub fn key(self) -> &'static str { match self { $(StatePname::$var => $key),+ } }
            /// The GL token.
            pub fn gl(self) -> u32 { match self { $(StatePname::$var => $gl),+ } }
            /// The GL name without the `GL_` prefix.
            pub fn name(self) -> &'static str { match self { $(StatePname::$var => $name),+ } }
            /// How the parameter is stored (and so queried: `GetTexParameteriv` for booleans and
            /// enums, `GetTexParameterfv` for floats).
            pub fn value_type(self) -> StateType { match self { $(StatePname::$var => StateType::$ty),+ } }
            pub fn from_gl(token: u32) -> Option<StatePname> {
                StatePname::ALL.iter().copied().find(|p| p.gl() == token)
            }
        }
    };
}

pnames! {
    /// TEXTURE_COMPARE_SGIX (SGIX_shadow), boolean.
    CompareSgix = "compare_sgix", 0x819A, "TEXTURE_COMPARE_SGIX", Bool;
    /// TEXTURE_COMPARE_OPERATOR_SGIX (SGIX_shadow).
    CompareOperatorSgix = "compare_operator_sgix", 0x819B, "TEXTURE_COMPARE_OPERATOR_SGIX", Enum;
    /// TEXTURE_COMPARE_FAIL_VALUE_ARB (ARB_shadow_ambient); the same token is SHADOW_AMBIENT_SGIX.
    CompareFailValue = "compare_fail_value", 0x80BF, "TEXTURE_COMPARE_FAIL_VALUE_ARB", Float;
    /// TEXTURE_COMPARE_MODE.
    CompareMode = "compare_mode", 0x884C, "TEXTURE_COMPARE_MODE", Enum;
    /// TEXTURE_COMPARE_FUNC.
    CompareFunc = "compare_func", 0x884D, "TEXTURE_COMPARE_FUNC", Enum;
    /// DEPTH_TEXTURE_MODE (compatibility).
    DepthTextureMode = "depth_texture_mode", 0x884B, "DEPTH_TEXTURE_MODE", Enum;
    /// DEPTH_STENCIL_TEXTURE_MODE (GL 4.3, ES 3.1).
    DepthStencilMode = "depth_stencil_mode", 0x90EA, "DEPTH_STENCIL_TEXTURE_MODE", Enum;
}

/// How a parameter's value is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StateType {
    Bool,
    Enum,
    Float,
}

/// A parameter's value as stored and read back.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StateValue {
    Bool(bool),
    /// A GL enum token.
    Enum(u32),
    Float(f32),
}

impl std::fmt::Display for StateValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StateValue::Bool(b) => write!(f, "{}", if *b { "TRUE" } else { "FALSE" }),
            StateValue::Enum(e) => write!(f, "0x{e:04X}"),
            StateValue::Float(v) => write!(f, "{v}"),
        }
    }
}

/// The call a state case makes on a fresh texture object bound to its target.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StateCall {
    /// GetTexParameter only: the initial value (or the error when the pname does not exist).
    Initial,
    /// TexParameteri(target, pname, value), then GetTexParameter.
    SetInt(i32),
    /// TexParameterf(target, pname, value), then GetTexParameter.
    SetFloat(f32),
}

impl std::fmt::Display for StateCall {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StateCall::Initial => f.write_str("GetTexParameter"),
            StateCall::SetInt(v) if *v >= 0 => write!(f, "TexParameteri(0x{v:04X})"),
            StateCall::SetInt(v) => write!(f, "TexParameteri({v})"),
            StateCall::SetFloat(v) => write!(f, "TexParameterf({v})"),
        }
    }
}

/// The GL error codes a state call can raise (glGetError's INVALID_ENUM, INVALID_VALUE,
/// INVALID_OPERATION; GL 4.6 §2.3.1 Table 2.3). A code the GL reports, not a failure of the
/// harness. On the wire a variant is its snake_case name (`"invalid_enum"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GlErrorCode {
    InvalidEnum,
    InvalidValue,
    InvalidOperation,
}

impl GlErrorCode {
    pub const ALL: &'static [GlErrorCode] = &[
        GlErrorCode::InvalidEnum,
        GlErrorCode::InvalidValue,
        GlErrorCode::InvalidOperation,
    ];
    /// The GL error code.
    pub fn gl(self) -> u32 {
        match self {
            GlErrorCode::InvalidEnum => 0x0500,
            GlErrorCode::InvalidValue => 0x0501,
            GlErrorCode::InvalidOperation => 0x0502,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            GlErrorCode::InvalidEnum => "INVALID_ENUM",
            GlErrorCode::InvalidValue => "INVALID_VALUE",
            GlErrorCode::InvalidOperation => "INVALID_OPERATION",
        }
    }
    pub fn from_gl(code: u32) -> Option<GlErrorCode> {
        GlErrorCode::ALL.iter().copied().find(|e| e.gl() == code)
    }
    /// A glGetError code as [`StateObserved`] holds it: (`error`, `other_error`); NO_ERROR (0)
    /// is (None, None).
    pub fn classify(code: u32) -> (Option<GlErrorCode>, Option<u32>) {
        match code {
            0 => (None, None),
            code => match GlErrorCode::from_gl(code) {
                Some(e) => (Some(e), None),
                None => (None, Some(code)),
            },
        }
    }
}

/// What a state call must leave: the first GL error it raises (`None`: NO_ERROR) and the value
/// GetTexParameter then reads (`None`: not read, the pname does not exist in this context). After
/// an error the value is the initial one: "the command that generated the error is ignored"
/// (GL 4.6 §2.3.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StateExpect {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<GlErrorCode>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<StateValue>,
    /// The sentences that decide it.
    pub citations: Vec<String>,
    /// What is expected instead on a context that exposes a named extension defining the pname
    /// the spec under test lacks (e.g. TEXTURE_COMPARE_FAIL_VALUE_ARB with
    /// `GL_ARB_shadow_ambient`); the first whose extension the context reports applies
    /// ([`StateExpect::for_extensions`]). Empty when no extension changes the expectation.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub with_extension: Vec<ExtensionExpect>,
}

/// The expectation of a state case on a context exposing `extension`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExtensionExpect {
    /// The extension name as the context's extension string lists it, e.g. `GL_ARB_shadow_ambient`.
    pub extension: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<GlErrorCode>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<StateValue>,
    /// The sentences that decide it (the extension's own).
    pub citations: Vec<String>,
}

/// The expectation that applies on one context: the base one or one extension's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AppliedExpect<'a> {
    /// The extension whose expectation applies (`None`: the base expectation).
    pub extension: Option<&'a str>,
    pub error: Option<GlErrorCode>,
    pub value: Option<StateValue>,
    pub citations: &'a [String],
}

impl StateExpect {
    /// The expectation on a context whose extension string lists `extensions`: the first
    /// [`StateExpect::with_extension`] entry whose extension is listed, else the base one (so a
    /// backend that reports no extensions is judged against the base expectation).
    pub fn for_extensions<S: AsRef<str>>(&self, extensions: &[S]) -> AppliedExpect<'_> {
        let exposed = |name: &str| extensions.iter().any(|e| e.as_ref() == name);
        match self.with_extension.iter().find(|w| exposed(&w.extension)) {
            Some(w) => AppliedExpect {
                extension: Some(&w.extension),
                error: w.error,
                value: w.value,
                citations: &w.citations,
            },
            None => AppliedExpect {
                extension: None,
                error: self.error,
                value: self.value,
                citations: &self.citations,
            },
        }
    }
}

/// What an implementation observed for one state case on one API path (context kind).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StateObserved {
    /// The first error glGetError returned after the call (`None`: NO_ERROR); any other code as
    /// `other` holds it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<GlErrorCode>,
    /// An error code that is none of [`GlErrorCode`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other_error: Option<u32>,
    /// The value read back (absent when the case's expectation reads none, or the read failed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<StateValue>,
}

/// One state test case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StateCase {
    /// e.g. `state/gl46/core/2d/compare_mode/set=0x1234`.
    pub id: String,
    pub spec: Spec,
    /// The context kinds it runs in, as the API path that exists only there (`core`, `ff`, `es300`).
    pub api: Vec<ApiPath>,
    /// The texture target the fresh texture object is bound to.
    pub target: Target,
    pub pname: StatePname,
    pub call: StateCall,
    /// Whether GetTexParameter reads the value back after the call (false when the pname cannot
    /// exist in the context, neither in its spec nor in an extension it may expose: the read would
    /// only raise INVALID_ENUM again).
    pub read_back: bool,
    /// The oracle's expectation (present in fixtures).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expect: Option<StateExpect>,
}

/// Checks the structure of a state case (id characters, API paths).
pub fn validate_state(case: &StateCase) -> Result<(), ModelError> {
    let invalid = |field: &str, msg: String| ModelError::Invalid {
        case: case.id.clone(),
        field: field.to_string(),
        msg,
    };
    if case.id.is_empty() {
        return Err(invalid("id", "empty id".into()));
    }
    if let Some(c) = case.id.chars().find(|c| !crate::validate::id_char_ok(*c)) {
        return Err(invalid("id", format!("{c:?} in the id")));
    }
    if case.api.is_empty() {
        return Err(invalid("api", "no API path".into()));
    }
    for (i, a) in case.api.iter().enumerate() {
        if case.api[..i].contains(a) {
            return Err(invalid(
                &format!("api[{i}]"),
                format!("duplicate API path `{}`", a.key()),
            ));
        }
    }
    if let StateCall::SetFloat(v) = case.call {
        if !v.is_finite() {
            return Err(invalid("call", "non-finite value".into()));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn state_case_json_round_trips_and_keys_are_stable() {
        let c = StateCase {
            id: "state/gl46/core/2d/compare_mode/set=0x1234".into(),
            spec: Spec::Gl46,
            api: vec![ApiPath::GlslCore],
            target: Target::T2d,
            pname: StatePname::CompareMode,
            call: StateCall::SetInt(0x1234),
            read_back: true,
            expect: Some(StateExpect {
                error: Some(GlErrorCode::InvalidEnum),
                value: Some(StateValue::Enum(0)),
                citations: vec!["x".into()],
                with_extension: vec![],
            }),
        };
        let s = serde_json::to_string(&c).unwrap_or_default();
        assert_eq!(
            s,
            r#"{"id":"state/gl46/core/2d/compare_mode/set=0x1234","spec":"gl46","api":["core"],"target":"2d","pname":"compare_mode","call":{"set_int":4660},"read_back":true,"expect":{"error":"invalid_enum","value":{"enum":0},"citations":["x"]}}"#
        );
        let back: StateCase = serde_json::from_str(&s).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(back, c);
        assert!(validate_state(&back).is_ok());
        for p in StatePname::ALL {
            assert_eq!(StatePname::from_gl(p.gl()), Some(*p));
        }
        assert_eq!(
            GlErrorCode::from_gl(0x0502),
            Some(GlErrorCode::InvalidOperation)
        );
        assert_eq!(GlErrorCode::classify(0), (None, None));
        assert_eq!(
            GlErrorCode::classify(0x0500),
            (Some(GlErrorCode::InvalidEnum), None)
        );
        assert_eq!(GlErrorCode::classify(0x0505), (None, Some(0x0505)));
        let bad = StateCase {
            id: "a b".into(),
            ..c
        };
        assert!(validate_state(&bad).is_err());
    }

    #[test]
    fn an_error_code_keeps_its_wire_name_and_gl_value() {
        // The fixtures under cases/fixtures/state and the workers' answers spell the codes so.
        let wire: Vec<(String, u32)> = GlErrorCode::ALL
            .iter()
            .map(|e| (serde_json::to_string(e).unwrap_or_default(), e.gl()))
            .collect();
        assert_eq!(
            wire,
            [
                ("\"invalid_enum\"".to_string(), 0x0500),
                ("\"invalid_value\"".to_string(), 0x0501),
                ("\"invalid_operation\"".to_string(), 0x0502),
            ]
        );
        for e in GlErrorCode::ALL {
            let back: GlErrorCode =
                serde_json::from_str(&serde_json::to_string(e).unwrap_or_default())
                    .unwrap_or_else(|err| panic!("{err}"));
            assert_eq!(back, *e);
        }
    }

    #[test]
    fn the_first_exposed_extension_expectation_applies_else_the_base_one() {
        let e = StateExpect {
            error: Some(GlErrorCode::InvalidEnum),
            value: None,
            citations: vec!["base".into()],
            with_extension: vec![
                ExtensionExpect {
                    extension: "GL_ARB_shadow_ambient".into(),
                    error: None,
                    value: Some(StateValue::Float(0.0)),
                    citations: vec!["arb".into()],
                },
                ExtensionExpect {
                    extension: "GL_SGIX_shadow_ambient".into(),
                    error: None,
                    value: Some(StateValue::Float(0.0)),
                    citations: vec!["sgix".into()],
                },
            ],
        };
        let none: [&str; 0] = [];
        let base = e.for_extensions(&none);
        assert_eq!(
            (base.extension, base.error, base.citations),
            (
                None,
                Some(GlErrorCode::InvalidEnum),
                &["base".to_string()][..]
            )
        );
        let sgix = e.for_extensions(&["GL_ARB_shadow", "GL_SGIX_shadow_ambient"]);
        assert_eq!(sgix.extension, Some("GL_SGIX_shadow_ambient"));
        assert_eq!(sgix.value, Some(StateValue::Float(0.0)));
        let both = e.for_extensions(&["GL_SGIX_shadow_ambient", "GL_ARB_shadow_ambient"]);
        assert_eq!(both.extension, Some("GL_ARB_shadow_ambient"));
        // The field is left out of the JSON when empty, so older fixtures read the same.
        let plain = StateExpect {
            with_extension: vec![],
            ..e.clone()
        };
        let s = serde_json::to_string(&plain).unwrap_or_default();
        assert_eq!(s, r#"{"error":"invalid_enum","citations":["base"]}"#);
        let s = serde_json::to_string(&e).unwrap_or_default();
        assert!(
            s.contains(r#""with_extension":[{"extension":"GL_ARB_shadow_ambient","#),
            "{s}"
        );
        let back: StateExpect = serde_json::from_str(&s).unwrap_or_else(|err| panic!("{err}"));
        assert_eq!(back, e);
    }
}
