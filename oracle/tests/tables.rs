//! Every row of every comparison table in the spec texts, for every spec that has it. Expected values
//! are transcribed from the tables of the specification texts, not computed.

mod common;
use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};

/// (Dref, Dt) pairs for Dref < Dt, Dref = Dt, Dref > Dt with values every format stores exactly.
const LT: (f64, f64) = (0.5, 1.0);
const EQ: (f64, f64) = (1.0, 1.0);
const GT: (f64, f64) = (0.5, 0.0);

fn row(spec: Spec, format: Format, func: CompareFunc) -> [f64; 3] {
    [LT, EQ, GT].map(|(d, t)| value(&one(spec, format, func, d, t)))
}

/// The eight-row table shared (row for row) by GL 4.6 Table 8.23, ES 3.2 Table 8.22, EXT_shadow_funcs and
/// EXT_shadow_samplers Table 3.X: [r if Dref < Dt, r if Dref = Dt, r if Dref > Dt].
const EIGHT: [(CompareFunc, [f64; 3]); 8] = [
    (CompareFunc::Lequal, [1.0, 1.0, 0.0]), // 1.0 if Dref ≤ Dt; 0.0 if Dref > Dt
    (CompareFunc::Gequal, [0.0, 1.0, 1.0]), // 1.0 if Dref ≥ Dt; 0.0 if Dref < Dt
    (CompareFunc::Less, [1.0, 0.0, 0.0]),   // 1.0 if Dref < Dt; 0.0 if Dref ≥ Dt
    (CompareFunc::Greater, [0.0, 0.0, 1.0]), // 1.0 if Dref > Dt; 0.0 if Dref ≤ Dt
    (CompareFunc::Equal, [0.0, 1.0, 0.0]),  // 1.0 if Dref = Dt; 0.0 if Dref ≠ Dt
    (CompareFunc::Notequal, [1.0, 0.0, 1.0]), // 1.0 if Dref ≠ Dt; 0.0 if Dref = Dt
    (CompareFunc::Always, [1.0, 1.0, 1.0]), // r = 1.0
    (CompareFunc::Never, [0.0, 0.0, 0.0]),  // r = 0.0
];

#[test]
fn gl46_table_8_23() {
    for f in [
        Format::D16,
        Format::D24,
        Format::D32,
        Format::D32f,
        Format::D24S8,
        Format::D32fS8,
        Format::DepthUnsized,
    ] {
        for (func, want) in EIGHT {
            assert_eq!(row(Spec::Gl46, f, func), want, "GL 4.6 {func} {f}");
        }
    }
}

#[test]
fn gles32_table_8_22() {
    for f in [
        Format::D16,
        Format::D24,
        Format::D32f,
        Format::D24S8,
        Format::D32fS8,
    ] {
        for (func, want) in EIGHT {
            assert_eq!(row(Spec::Gles32, f, func), want, "ES 3.2 {func} {f}");
        }
    }
}

#[test]
fn ext_shadow_funcs_table() {
    for f in [Format::D16, Format::D24, Format::D32] {
        for (func, want) in EIGHT {
            assert_eq!(
                row(Spec::ExtFuncs, f, func),
                want,
                "EXT_shadow_funcs {func} {f}"
            );
        }
    }
}

#[test]
fn ext_shadow_samplers_table_3_x() {
    for f in [Format::D16, Format::D24, Format::D24S8] {
        for (func, want) in EIGHT {
            if func == CompareFunc::Greater {
                // "GREATER r = { 1.0, if D_ref > Dt  { 0.0, if D_ref < Dt": nothing at D_ref == Dt.
                let (lt, gt) = (LT, GT);
                assert_eq!(value(&one(Spec::Es2Ext, f, func, lt.0, lt.1)), 0.0);
                assert_eq!(value(&one(Spec::Es2Ext, f, func, gt.0, gt.1)), 1.0);
                let e = eval(&one(Spec::Es2Ext, f, func, 1.0, 1.0));
                assert_eq!(e.expect.spec_value, None, "{f}");
                let acc = &e.expect.accept[&Profile::Strict];
                assert!(acc.contains(0.0) && acc.contains(1.0), "{f}: {acc:?}");
                let why = e.expect.implementation_defined.unwrap_or_default();
                assert!(why.contains("assigns no value"), "{f}: {why}");
                continue;
            }
            assert_eq!(
                row(Spec::Es2Ext, f, func),
                want,
                "EXT_shadow_samplers {func} {f}"
            );
        }
    }
}

#[test]
fn arb_shadow_has_two_rows_and_rejects_the_rest_with_invalid_enum() {
    // "LEQUAL r = 1.0 if R <= Dt, 0.0 if R > Dt"; "GEQUAL r = 1.0 if R >= Dt, 0.0 if R < Dt".
    for spec in [Spec::Arb, Spec::ArbAmbient] {
        assert_eq!(row(spec, Format::D24, CompareFunc::Lequal), [1.0, 1.0, 0.0]);
        assert_eq!(row(spec, Format::D24, CompareFunc::Gequal), [0.0, 1.0, 1.0]);
        for func in [
            CompareFunc::Less,
            CompareFunc::Greater,
            CompareFunc::Equal,
            CompareFunc::Notequal,
            CompareFunc::Always,
            CompareFunc::Never,
            CompareFunc::LequalRSgix,
        ] {
            match evaluate(&one(spec, Format::D24, func, 0.5, 0.5)) {
                Err(OracleError::GlError { error, .. }) => {
                    assert_eq!(error, "INVALID_ENUM", "{func}")
                }
                other => panic!("{func}: {other:?}"),
            }
        }
    }
}

#[test]
fn sgix_operators_compare_texel_to_r() {
    // "TEXTURE_LEQUAL_R_SGIX passes if the texel value is less than or equal to R"; GEQUAL_R: ">=".
    for spec in [Spec::Sgix, Spec::SgixAmbient] {
        // [texel > R, texel = R, texel < R] in the order LT, EQ, GT of (R, texel).
        assert_eq!(
            row(spec, Format::D16, CompareFunc::LequalRSgix),
            [0.0, 1.0, 1.0]
        );
        assert_eq!(
            row(spec, Format::D16, CompareFunc::GequalRSgix),
            [1.0, 1.0, 0.0]
        );
        // Brief example: texel 0.3, R 0.5, TEXTURE_LEQUAL_R_SGIX → 1.
        assert_eq!(
            value(&one(spec, Format::D24, CompareFunc::LequalRSgix, 0.5, 0.3)),
            1.0
        );
        // Errors: "INVALID_OPERATION is generated if ... <param> is not TEXTURE_LEQUAL_R_SGIX, or TEXTURE_GEQUAL_R_SGIX".
        for func in CompareFunc::CORE {
            match evaluate(&one(spec, Format::D16, func, 0.5, 0.5)) {
                Err(OracleError::GlError { error, .. }) => {
                    assert_eq!(error, "INVALID_OPERATION", "{func}")
                }
                other => panic!("{func}: {other:?}"),
            }
        }
    }
}

#[test]
fn core_specs_reject_sgix_tokens_with_invalid_enum() {
    for spec in [Spec::Gl46, Spec::Gles32, Spec::Es2Ext, Spec::ExtFuncs] {
        match evaluate(&one(spec, Format::D16, CompareFunc::LequalRSgix, 0.5, 0.5)) {
            Err(OracleError::GlError { error, .. }) => assert_eq!(error, "INVALID_ENUM", "{spec}"),
            other => panic!("{spec}: {other:?}"),
        }
    }
}

#[test]
fn fail_value_replaces_zero() {
    // ARB_shadow_ambient: "{ TEXTURE_COMPARE_FAIL_VALUE_ARB, if R > Dt" — brief example 0.25.
    let mut c = one(Spec::ArbAmbient, Format::D24, CompareFunc::Lequal, 0.8, 0.3);
    c.sampler.fail_value = Some(0.25);
    assert_eq!(value(&c), 0.25);
    c.lookup.dref = 0.2;
    assert_eq!(value(&c), 1.0);
    // Clamped to [0,1] when set.
    c.lookup.dref = 0.8;
    c.sampler.fail_value = Some(1.5);
    assert_eq!(value(&c), 1.0);
    // SGIX_shadow_ambient: "the value of the SHADOW_AMBIENT_SGIX parameter is returned, instead of 0.0".
    let mut s = one(
        Spec::SgixAmbient,
        Format::D16,
        CompareFunc::LequalRSgix,
        0.2,
        0.6,
    );
    s.sampler.fail_value = Some(0.4);
    assert_eq!(value(&s), 0.4f32 as f64); // sampler floats are f32 state
                                          // A fail value under a spec without the pname: INVALID_ENUM.
    let mut g = one(Spec::Gl46, Format::D16, CompareFunc::Lequal, 0.2, 0.6);
    g.sampler.fail_value = Some(0.4);
    assert!(matches!(
        evaluate(&g),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
}
