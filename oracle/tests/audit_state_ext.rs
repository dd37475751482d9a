//! State cases whose pname only an extension defines: on a GL 4.6 compatibility context the
//! oracle lists, beside INVALID_ENUM, what a context exposing the extension must do, from the
//! extension's own rules (the ARB_shadow_ambient, SGIX_shadow and SGIX_shadow_ambient specifications). Core and ES contexts get no such
//! alternative (`shadowcheck_oracle::state::extension_ctx`).

use shadowcheck_model::{
    ApiPath, ExtensionExpect, GlErrorCode, Spec, StateCall, StateCase, StateExpect, StatePname,
    StateValue, Target,
};
use shadowcheck_oracle::state::{self, Ctx};

fn case(api: ApiPath, pname: StatePname, call: StateCall) -> StateCase {
    let ctx = state::ctx_of(api);
    StateCase {
        id: "state/test".into(),
        spec: if ctx == Ctx::Es {
            Spec::Gles32
        } else {
            Spec::Gl46
        },
        api: vec![api],
        target: Target::T2d,
        pname,
        call,
        read_back: state::reads_back(Spec::Gl46, ctx, pname.gl()),
        expect: None,
    }
}

fn expect(api: ApiPath, pname: StatePname, call: StateCall) -> StateExpect {
    state::expect_state(&case(api, pname, call)).unwrap_or_else(|e| panic!("{e}"))
}

fn alt<'a>(e: &'a StateExpect, ext: &str) -> &'a ExtensionExpect {
    e.with_extension
        .iter()
        .find(|w| w.extension == ext)
        .unwrap_or_else(|| panic!("no alternative for {ext} in {e:?}"))
}

/// ARB_shadow_ambient, New Tokens: "Accepted by the <pname> parameter of TexParameterf,
/// TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv:
/// TEXTURE_COMPARE_FAIL_VALUE_ARB 0x80BF"; §3.8.4: "The value set by
/// TEXTURE_COMPARE_FAIL_VALUE_ARB is clamped to lie in [0, 1]."; New State: initial 0.0.
/// SGIX_shadow_ambient (the same token, ARB_shadow_ambient Issues item 6): "When SHADOW_AMBIENT_SGIX is
/// set, the <param> value is clamped to the range [0.0, 1.0]"; initial 0.0.
#[test]
fn fail_value_is_invalid_enum_in_gl46_compat_unless_an_ambient_extension_is_exposed() {
    let ff = ApiPath::FixedFunction;
    let p = StatePname::CompareFailValue;
    let init = expect(ff, p, StateCall::Initial);
    // The base expectation is unchanged: GL 4.6 has no such pname.
    assert_eq!(
        (init.error, init.value),
        (Some(GlErrorCode::InvalidEnum), None)
    );
    let names: Vec<&str> = init
        .with_extension
        .iter()
        .map(|w| w.extension.as_str())
        .collect();
    assert_eq!(names, ["GL_ARB_shadow_ambient", "GL_SGIX_shadow_ambient"]);
    for ext in ["GL_ARB_shadow_ambient", "GL_SGIX_shadow_ambient"] {
        let a = alt(&init, ext);
        assert_eq!((a.error, a.value), (None, Some(StateValue::Float(0.0))));
        assert!(a.citations[0].contains("Accepted by the <pname> parameter"));
        for (set, stored) in [(1.5, 1.0), (-0.5, 0.0), (0.25, 0.25)] {
            let e = expect(ff, p, StateCall::SetFloat(set));
            let a = alt(&e, ext);
            assert_eq!(
                (a.error, a.value),
                (None, Some(StateValue::Float(stored))),
                "{ext} TexParameterf({set})"
            );
            assert_eq!(e.error, Some(GlErrorCode::InvalidEnum));
        }
    }
    assert!(alt(&init, "GL_ARB_shadow_ambient")
        .citations
        .iter()
        .any(|c| c.contains("ARB_shadow_ambient §3.8.4")));
}

/// SGIX_shadow, Table 3.8: "TEXTURE_COMPARE_SGIX boolean TRUE or FALSE",
/// "TEXTURE_COMPARE_OPERATOR_SGIX integer TEXTURE_LEQUAL_R_SGIX, TEXTURE_GEQUAL_R_SGIX"; Errors:
/// "INVALID_OPERATION is generated if TexParameter[if] parameter <pname> is
/// TEXTURE_COMPARE_OPERATOR_SGIX and parameter <param> is not TEXTURE_LEQUAL_R_SGIX,or
/// TEXTURE_GEQUAL_R_SGIX"; New State: "TEXTURE_COMPARE_SGIX ... False",
/// "TEXTURE_COMPARE_OPERATOR_SGIX ... TEXTURE_LEQUAL_R_SGIX".
#[test]
fn sgix_pnames_follow_sgix_shadow_when_it_is_exposed() {
    let ff = ApiPath::FixedFunction;
    let sgix = "GL_SGIX_shadow";
    let e = expect(ff, StatePname::CompareSgix, StateCall::Initial);
    assert_eq!(e.error, Some(GlErrorCode::InvalidEnum));
    let a = alt(&e, sgix);
    assert_eq!((a.error, a.value), (None, Some(StateValue::Bool(false))));
    let e = expect(ff, StatePname::CompareSgix, StateCall::SetInt(2));
    assert_eq!(
        (alt(&e, sgix).error, alt(&e, sgix).value),
        (None, Some(StateValue::Bool(true)))
    );
    let op = StatePname::CompareOperatorSgix;
    let e = expect(ff, op, StateCall::Initial);
    assert_eq!(
        (alt(&e, sgix).error, alt(&e, sgix).value),
        (None, Some(StateValue::Enum(state::TEXTURE_LEQUAL_R_SGIX)))
    );
    let e = expect(ff, op, StateCall::SetInt(0x819D));
    assert_eq!(
        (alt(&e, sgix).error, alt(&e, sgix).value),
        (None, Some(StateValue::Enum(state::TEXTURE_GEQUAL_R_SGIX)))
    );
    // LEQUAL is ARB_shadow's token, not an SGIX operator: INVALID_OPERATION, state unchanged.
    let e = expect(ff, op, StateCall::SetInt(0x0203));
    let a = alt(&e, sgix);
    assert_eq!(
        (a.error, a.value),
        (
            Some(GlErrorCode::InvalidOperation),
            Some(StateValue::Enum(state::TEXTURE_LEQUAL_R_SGIX))
        )
    );
    assert!(a.citations.iter().any(|c| c.contains("SGIX_shadow")));
    // Only SGIX_shadow adds these pnames.
    assert_eq!(e.with_extension.len(), 1);
}

/// The extensions are written against OpenGL 1.0 / 1.3 and amend the compatibility texture
/// parameter table: a core profile's list is closed (GL 4.6 §8.10, Table 8.17) and OpenGL ES has
/// its own extensions, so core and ES cases keep INVALID_ENUM alone. A pname the spec itself
/// defines never gets an alternative.
#[test]
fn no_alternative_on_core_or_es_nor_for_a_pname_the_spec_defines() {
    for api in [ApiPath::GlslCore, ApiPath::Es300] {
        for p in [
            StatePname::CompareFailValue,
            StatePname::CompareSgix,
            StatePname::CompareOperatorSgix,
        ] {
            let e = expect(api, p, StateCall::Initial);
            assert!(e.with_extension.is_empty(), "{api:?} {p:?}");
            assert_eq!(e.error, Some(GlErrorCode::InvalidEnum));
        }
    }
    let e = expect(
        ApiPath::FixedFunction,
        StatePname::CompareMode,
        StateCall::Initial,
    );
    assert!(e.with_extension.is_empty());
    assert!(state::pname_extensions(
        Spec::ArbAmbient,
        Ctx::Compat,
        state::TEXTURE_COMPARE_FAIL_VALUE_ARB
    )
    .is_empty());
}

/// Every extension's pnames are in its spec's own table (the rules are reused, not copied).
#[test]
fn every_extension_pname_is_in_its_specs_table() {
    for ext in state::PNAME_EXTENSIONS {
        for &p in ext.pnames {
            assert!(
                state::param(ext.spec, Ctx::Compat, p).is_ok(),
                "{} {p:#x}",
                ext.name
            );
        }
    }
}
