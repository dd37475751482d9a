//! Unit tests of the TexParameter tables, set/get logic and state-case expectations.

use super::*;
use GlErrorKind::*;

#[test]
fn sgix_operator_error_is_invalid_operation_and_arb_is_invalid_enum() {
    assert_eq!(
        set_param(
            Spec::Sgix,
            Ctx::Compat,
            TEXTURE_COMPARE_OPERATOR_SGIX,
            Value::Int(LEQUAL as i64)
        ),
        Err(InvalidOperation)
    );
    assert_eq!(
        set_param(
            Spec::Sgix,
            Ctx::Compat,
            TEXTURE_COMPARE_OPERATOR_SGIX,
            Value::Int(TEXTURE_GEQUAL_R_SGIX as i64)
        ),
        Ok(Stored::Enum(TEXTURE_GEQUAL_R_SGIX))
    );
    assert_eq!(
        set_param(
            Spec::Arb,
            Ctx::Compat,
            TEXTURE_COMPARE_FUNC,
            Value::Int(0x0201)
        ),
        Err(InvalidEnum)
    );
    assert_eq!(
        set_param(
            Spec::ExtFuncs,
            Ctx::Compat,
            TEXTURE_COMPARE_FUNC,
            Value::Int(0x0201)
        ),
        Ok(Stored::Enum(0x0201))
    );
    assert_eq!(
        set_param(
            Spec::Gl46,
            Ctx::Core,
            TEXTURE_COMPARE_FUNC,
            Value::Int(TEXTURE_LEQUAL_R_SGIX as i64)
        ),
        Err(InvalidEnum)
    );
}

#[test]
fn defaults_per_spec_and_context() {
    assert_eq!(
        default_value(Spec::Sgix, Ctx::Compat, TEXTURE_COMPARE_SGIX),
        Ok(Stored::Bool(false))
    );
    assert_eq!(
        default_value(Spec::Sgix, Ctx::Compat, TEXTURE_COMPARE_OPERATOR_SGIX),
        Ok(Stored::Enum(TEXTURE_LEQUAL_R_SGIX))
    );
    assert_eq!(
        default_value(Spec::SgixAmbient, Ctx::Compat, SHADOW_AMBIENT_SGIX),
        Ok(Stored::Float(0.0))
    );
    assert_eq!(
        default_value(Spec::Arb, Ctx::Compat, TEXTURE_COMPARE_MODE),
        Ok(Stored::Enum(NONE))
    );
    assert_eq!(
        default_value(Spec::Arb, Ctx::Compat, TEXTURE_COMPARE_FUNC),
        Ok(Stored::Enum(LEQUAL))
    );
    assert_eq!(
        default_value(Spec::Arb, Ctx::Compat, DEPTH_TEXTURE_MODE),
        Ok(Stored::Enum(LUMINANCE))
    );
    assert_eq!(
        default_value(Spec::Arb, Ctx::Compat, TEXTURE_COMPARE_FAIL_VALUE_ARB),
        Err(InvalidEnum)
    );
    assert_eq!(
        default_value(
            Spec::ArbAmbient,
            Ctx::Compat,
            TEXTURE_COMPARE_FAIL_VALUE_ARB
        ),
        Ok(Stored::Float(0.0))
    );
    assert_eq!(
        default_value(Spec::Gl46, Ctx::Compat, DEPTH_TEXTURE_MODE),
        Ok(Stored::Enum(LUMINANCE))
    );
    assert_eq!(
        default_value(Spec::Gl46, Ctx::Core, DEPTH_TEXTURE_MODE),
        Err(InvalidEnum)
    );
    assert_eq!(
        default_value(Spec::Gles32, Ctx::Es, DEPTH_TEXTURE_MODE),
        Err(InvalidEnum)
    );
    assert_eq!(
        default_value(Spec::Gles32, Ctx::Es, DEPTH_STENCIL_TEXTURE_MODE),
        Ok(Stored::Enum(DEPTH_COMPONENT))
    );
    assert_eq!(
        default_value(Spec::Es2Ext, Ctx::Es, DEPTH_STENCIL_TEXTURE_MODE),
        Err(InvalidEnum)
    );
}

#[test]
fn every_default_is_a_legal_value_and_every_pname_exists_somewhere() {
    for &pname in PNAMES {
        let mut seen = false;
        for spec in Spec::ALL {
            for ctx in [Ctx::Core, Ctx::Compat, Ctx::Es] {
                if let Ok(p) = param(*spec, ctx, pname) {
                    seen = true;
                    let v = match p.default {
                        Stored::Bool(b) => Value::Int(b as i64),
                        Stored::Enum(e) => Value::Int(e as i64),
                        Stored::Float(f) => Value::Float(f),
                    };
                    assert_eq!(
                        set_param(*spec, ctx, pname, v),
                        Ok(p.default),
                        "{spec} {ctx:?} {}",
                        p.name
                    );
                    assert!(!p.cite.is_empty());
                }
            }
        }
        assert!(seen, "{pname:#x}");
    }
    // Outside their spec / context the pnames are INVALID_ENUM.
    assert_eq!(
        set_param(Spec::Gl46, Ctx::Core, TEXTURE_COMPARE_SGIX, Value::Int(1)),
        Err(InvalidEnum)
    );
    assert_eq!(
        set_param(
            Spec::Gles32,
            Ctx::Es,
            TEXTURE_COMPARE_FAIL_VALUE_ARB,
            Value::Float(0.5)
        ),
        Err(InvalidEnum)
    );
}

#[test]
fn conversions_and_clamps() {
    // Fail value / ambient clamped to [0,1], never an error.
    assert_eq!(
        set_param(
            Spec::ArbAmbient,
            Ctx::Compat,
            TEXTURE_COMPARE_FAIL_VALUE_ARB,
            Value::Float(1.5)
        ),
        Ok(Stored::Float(1.0))
    );
    assert_eq!(
        set_param(
            Spec::SgixAmbient,
            Ctx::Compat,
            SHADOW_AMBIENT_SGIX,
            Value::Float(-0.5)
        ),
        Ok(Stored::Float(0.0))
    );
    // Booleans: non-zero is TRUE.
    assert_eq!(
        set_param(
            Spec::Sgix,
            Ctx::Compat,
            TEXTURE_COMPARE_SGIX,
            Value::Float(0.25)
        ),
        Ok(Stored::Bool(true))
    );
    // Enums given as floats are rounded.
    assert_eq!(
        set_param(
            Spec::Gl46,
            Ctx::Core,
            TEXTURE_COMPARE_MODE,
            Value::Float(COMPARE_REF_TO_TEXTURE as f64 + 0.4)
        ),
        Ok(Stored::Enum(COMPARE_REF_TO_TEXTURE))
    );
    assert_eq!(
        set_param(
            Spec::Gl46,
            Ctx::Compat,
            DEPTH_TEXTURE_MODE,
            Value::Int(RED as i64)
        ),
        Ok(Stored::Enum(RED))
    );
    assert_eq!(
        set_param(
            Spec::Arb,
            Ctx::Compat,
            DEPTH_TEXTURE_MODE,
            Value::Int(RED as i64)
        ),
        Err(InvalidEnum)
    );
    assert_eq!(
        set_param(
            Spec::Gles32,
            Ctx::Es,
            DEPTH_STENCIL_TEXTURE_MODE,
            Value::Int(0x1234)
        ),
        Err(InvalidEnum)
    );
}
