//! TexParameter / GetTexParameter state of the depth-comparison pnames, per spec and context, as data a
//! GL backend can test against: which pnames exist, their legal values, the error an illegal value
//! raises, the value stored after conversion (GL 4.6 §2.2.1) and clamping, and the initial value.
//! Each spec's table lives in its module (`Rules::params`, e.g. `gl46::params`); this module holds
//! the tokens, the types and the TexParameter / GetTexParameter logic over the tables.

use shadowcheck_model::Spec;

pub const TEXTURE_COMPARE_SGIX: u32 = 0x819A;
pub const TEXTURE_COMPARE_OPERATOR_SGIX: u32 = 0x819B;
pub const TEXTURE_LEQUAL_R_SGIX: u32 = 0x819C;
pub const TEXTURE_GEQUAL_R_SGIX: u32 = 0x819D;
/// SHADOW_AMBIENT_SGIX and TEXTURE_COMPARE_FAIL_VALUE_ARB share 0x80BF (ARB_shadow_ambient, Issues, item 6).
pub const SHADOW_AMBIENT_SGIX: u32 = 0x80BF;
pub const TEXTURE_COMPARE_FAIL_VALUE_ARB: u32 = 0x80BF;
pub const DEPTH_TEXTURE_MODE: u32 = 0x884B;
pub const TEXTURE_COMPARE_MODE: u32 = 0x884C;
pub const TEXTURE_COMPARE_FUNC: u32 = 0x884D;
/// COMPARE_R_TO_TEXTURE(_ARB), COMPARE_REF_TO_TEXTURE(_EXT).
pub const COMPARE_REF_TO_TEXTURE: u32 = 0x884E;
pub const DEPTH_STENCIL_TEXTURE_MODE: u32 = 0x90EA;
pub const NONE: u32 = 0;
pub(crate) const LEQUAL: u32 = 0x0203;
pub(crate) const GEQUAL: u32 = 0x0206;
/// The eight compare functions NEVER ... ALWAYS.
pub(crate) const FUNCS8: &[u32] = &[
    0x0200, 0x0201, 0x0202, 0x0203, 0x0204, 0x0205, 0x0206, 0x0207,
];
pub(crate) const LUMINANCE: u32 = 0x1909;
pub(crate) const INTENSITY: u32 = 0x8049;
pub(crate) const ALPHA: u32 = 0x1906;
pub(crate) const RED: u32 = 0x1903;
pub(crate) const DEPTH_COMPONENT: u32 = 0x1902;
pub(crate) const STENCIL_INDEX: u32 = 0x1901;

/// Every depth-comparison pname any spec here defines (SHADOW_AMBIENT_SGIX is
/// TEXTURE_COMPARE_FAIL_VALUE_ARB's token).
pub const PNAMES: &[u32] = &[
    TEXTURE_COMPARE_SGIX,
    TEXTURE_COMPARE_OPERATOR_SGIX,
    SHADOW_AMBIENT_SGIX,
    TEXTURE_COMPARE_MODE,
    TEXTURE_COMPARE_FUNC,
    DEPTH_TEXTURE_MODE,
    DEPTH_STENCIL_TEXTURE_MODE,
];

/// The kind of context the call is made in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Ctx {
    Core,
    Compat,
    Es,
}

/// The GL errors TexParameter can raise for these pnames.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GlErrorKind {
    InvalidEnum,
    InvalidValue,
    InvalidOperation,
}

impl GlErrorKind {
    pub fn name(self) -> &'static str {
        match self {
            GlErrorKind::InvalidEnum => "INVALID_ENUM",
            GlErrorKind::InvalidValue => "INVALID_VALUE",
            GlErrorKind::InvalidOperation => "INVALID_OPERATION",
        }
    }
    /// The GL error code.
    pub fn gl(self) -> u32 {
        match self {
            GlErrorKind::InvalidEnum => 0x0500,
            GlErrorKind::InvalidValue => 0x0501,
            GlErrorKind::InvalidOperation => 0x0502,
        }
    }
}

/// A value as passed to TexParameteri (`Int`) or TexParameterf (`Float`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    Int(i64),
    Float(f64),
}

/// The value stored in (and queried back from) the state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stored {
    Bool(bool),
    Enum(u32),
    Float(f64),
}

/// The type and legal values of one pname.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamKind {
    /// Boolean: any value converts (zero → FALSE, non-zero → TRUE).
    Bool,
    /// Enum with its legal values and the error for anything else.
    Enum(&'static [u32], GlErrorKind),
    /// Float clamped to [0,1] when set.
    Unit,
}

/// One pname as a spec and context define it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param {
    pub pname: u32,
    pub name: &'static str,
    pub kind: ParamKind,
    pub default: Stored,
    /// Where the legal values, error and initial value are stated.
    pub cite: &'static str,
}

impl Param {
    /// TEXTURE_COMPARE_MODE (spelled `name` by the spec): NONE or COMPARE_REF_TO_TEXTURE, anything
    /// else INVALID_ENUM, initially NONE: the same in every spec that has the pname (each cites its
    /// own sentence).
    pub(crate) const fn compare_mode(name: &'static str, cite: &'static str) -> Param {
        Param::new(
            TEXTURE_COMPARE_MODE,
            name,
            ParamKind::Enum(&[NONE, COMPARE_REF_TO_TEXTURE], GlErrorKind::InvalidEnum),
            Stored::Enum(NONE),
            cite,
        )
    }

    /// TEXTURE_COMPARE_FUNC with the eight functions of EXT_shadow_funcs and later, anything else
    /// INVALID_ENUM, initially LEQUAL.
    pub(crate) const fn compare_func8(name: &'static str, cite: &'static str) -> Param {
        Param::new(
            TEXTURE_COMPARE_FUNC,
            name,
            ParamKind::Enum(FUNCS8, GlErrorKind::InvalidEnum),
            Stored::Enum(LEQUAL),
            cite,
        )
    }

    /// DEPTH_STENCIL_TEXTURE_MODE: DEPTH_COMPONENT or STENCIL_INDEX, anything else INVALID_ENUM,
    /// initially DEPTH_COMPONENT.
    pub(crate) const fn depth_stencil_mode(cite: &'static str) -> Param {
        Param::new(
            DEPTH_STENCIL_TEXTURE_MODE,
            "DEPTH_STENCIL_TEXTURE_MODE",
            ParamKind::Enum(&[DEPTH_COMPONENT, STENCIL_INDEX], GlErrorKind::InvalidEnum),
            Stored::Enum(DEPTH_COMPONENT),
            cite,
        )
    }

    pub(crate) const fn new(
        pname: u32,
        name: &'static str,
        kind: ParamKind,
        default: Stored,
        cite: &'static str,
    ) -> Param {
        Param {
            pname,
            name,
            kind,
            default,
            cite,
        }
    }
}

/// The depth-comparison pnames that exist under `spec` in a context of kind `ctx` (each spec module
/// holds its own table, `Rules::params`).
pub fn params(spec: Spec, ctx: Ctx) -> Vec<Param> {
    (crate::rules::rules_for(spec).params)(spec, ctx)
}

/// The pname as defined under `spec` in `ctx`; INVALID_ENUM when it does not exist there (GL 4.6 §8.10:
/// "An INVALID_ENUM error is generated if pname is not one of the parameter names in table 8.17").
pub fn param(spec: Spec, ctx: Ctx, pname: u32) -> Result<Param, GlErrorKind> {
    params(spec, ctx)
        .into_iter()
        .find(|p| p.pname == pname)
        .ok_or(GlErrorKind::InvalidEnum)
}

/// TexParameter{if}(target, pname, value): the stored value, or the error (state unchanged).
/// Conversions per GL 4.6 §2.2.1: to boolean "zero ... FALSE and non-zero values are converted to TRUE";
/// to enum "Floating-point values are rounded to the nearest integer"; to float, integers convert.
pub fn set_param(spec: Spec, ctx: Ctx, pname: u32, value: Value) -> Result<Stored, GlErrorKind> {
    let prm = param(spec, ctx, pname)?;
    match prm.kind {
        ParamKind::Bool => Ok(Stored::Bool(match value {
            Value::Int(i) => i != 0,
            Value::Float(f) => f != 0.0,
        })),
        ParamKind::Enum(legal, err) => {
            let v = match value {
                Value::Int(i) => i,
                Value::Float(f) => f.round() as i64,
            };
            match u32::try_from(v) {
                Ok(e) if legal.contains(&e) => Ok(Stored::Enum(e)),
                _ => Err(err),
            }
        }
        ParamKind::Unit => {
            let f = match value {
                Value::Int(i) => i as f64,
                Value::Float(f) => f,
            };
            Ok(Stored::Float(f.clamp(0.0, 1.0)))
        }
    }
}

/// GetTexParameter on a new texture object: the initial value, or INVALID_ENUM for an unknown pname.
pub fn default_value(spec: Spec, ctx: Ctx, pname: u32) -> Result<Stored, GlErrorKind> {
    param(spec, ctx, pname).map(|p| p.default)
}

/// The context kind a state case's API path stands for (`core`: core profile; the compatibility
/// paths; the ES paths).
pub fn ctx_of(api: shadowcheck_model::ApiPath) -> Ctx {
    use shadowcheck_model::ApiPath::*;
    match api {
        // Vulkan and WebGPU have no state cases (no TexParameter): the core rules stand in.
        GlslCore | Vulkan | Wgsl => Ctx::Core,
        FixedFunction | ArbFp | Glsl120 | Glsl130 => Ctx::Compat,
        Es100Ext | Es300 => Ctx::Es,
    }
}

/// An extension that adds depth-comparison pnames to TexParameter / GetTexParameter: a context
/// exposing it accepts them although the spec under test (GL 4.6) has none of them. Its rules are
/// those of `spec`'s own table (`arb::params`, `sgix::params`), restricted to the pnames the
/// extension itself adds (the other rows of those tables, e.g. ARB_shadow's two compare functions,
/// are not the extension's and never replace the context's own).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PnameExtension {
    /// The name in the extension string, e.g. `GL_ARB_shadow_ambient`.
    pub name: &'static str,
    /// The spec whose `params` table holds the extension's rules.
    pub spec: Spec,
    /// The pnames it adds.
    pub pnames: &'static [u32],
    /// The extension's sentence that adds them ("New Tokens").
    pub accepts: &'static str,
}

/// The extensions that add a depth-comparison pname, in the order their expectations are listed
/// (the first a context exposes applies; for 0x80BF both ambient extensions agree: item 6 of
/// ARB_shadow_ambient's Issues section makes TEXTURE_COMPARE_FAIL_VALUE_ARB "an alias for GL_SHADOW_AMBIENT_SGIX").
///
/// Only compatibility contexts can expose them ([`extension_ctx`]).
pub const PNAME_EXTENSIONS: &[PnameExtension] = &[
    // ARB_shadow_ambient, New Tokens: "Accepted by the <pname> parameter of TexParameterf,
    // TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv:
    // TEXTURE_COMPARE_FAIL_VALUE_ARB 0x80BF"; §3.8.4 (table 3.19): "float, any value in [0, 1]",
    // "The value set by TEXTURE_COMPARE_FAIL_VALUE_ARB is clamped to lie in [0, 1]"; Errors:
    // "None."; New State: initial 0.0. The rules: `arb::params(Spec::ArbAmbient, ..)`.
    PnameExtension {
        name: "GL_ARB_shadow_ambient",
        spec: Spec::ArbAmbient,
        pnames: &[TEXTURE_COMPARE_FAIL_VALUE_ARB],
        accepts: "ARB_shadow_ambient, New Tokens: \"Accepted by the <pname> parameter of TexParameterf, TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv: TEXTURE_COMPARE_FAIL_VALUE_ARB 0x80BF\"",
    },
    // SGIX_shadow, New Tokens: "Accepted by the <pname> parameter of TexParameterf,
    // TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv, with
    // the <pname> parameter of TRUE or FALSE: TEXTURE_COMPARE_SGIX" and "...:
    // TEXTURE_COMPARE_OPERATOR_SGIX"; Table 3.8: "TEXTURE_COMPARE_SGIX boolean TRUE or FALSE",
    // "TEXTURE_COMPARE_OPERATOR_SGIX integer TEXTURE_LEQUAL_R_SGIX, TEXTURE_GEQUAL_R_SGIX";
    // Errors: "INVALID_OPERATION is generated if TexParameter[if] parameter <pname> is
    // TEXTURE_COMPARE_OPERATOR_SGIX and parameter <param> is not TEXTURE_LEQUAL_R_SGIX,or
    // TEXTURE_GEQUAL_R_SGIX"; New State: initial False, TEXTURE_LEQUAL_R_SGIX. The rules:
    // `sgix::params(Spec::Sgix, ..)`.
    PnameExtension {
        name: "GL_SGIX_shadow",
        spec: Spec::Sgix,
        pnames: &[TEXTURE_COMPARE_SGIX, TEXTURE_COMPARE_OPERATOR_SGIX],
        accepts: "SGIX_shadow, New Tokens: \"Accepted by the <pname> parameter of TexParameterf, TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv\": TEXTURE_COMPARE_SGIX, TEXTURE_COMPARE_OPERATOR_SGIX",
    },
    // SGIX_shadow_ambient, New Tokens: "Accepted by the <pname> parameter of TexParameterf,
    // TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv:
    // SHADOW_AMBIENT_SGIX 0x80BF"; Notes: "When SHADOW_AMBIENT_SGIX is set, the <param> value is
    // clamped to the range [0.0, 1.0]"; Errors: "None"; New State: initial 0.0. The rules:
    // `sgix::params(Spec::SgixAmbient, ..)`.
    PnameExtension {
        name: "GL_SGIX_shadow_ambient",
        spec: Spec::SgixAmbient,
        pnames: &[SHADOW_AMBIENT_SGIX],
        accepts: "SGIX_shadow_ambient, New Tokens: \"Accepted by the <pname> parameter of TexParameterf, TexParameteri, TexParameterfv, TexParameteriv, GetTexParameterfv, and GetTexParameteriv: SHADOW_AMBIENT_SGIX 0x80BF\"",
    },
];

/// Whether a context of kind `ctx` can expose the extensions of [`PNAME_EXTENSIONS`]:
/// compatibility contexts only. ARB_shadow_ambient is "written against the OpenGL 1.3
/// Specification" and requires ARB_shadow and ARB_depth_texture, SGIX_shadow and
/// SGIX_shadow_ambient amend the OpenGL 1.0 Table 3.8: they modify the fixed-function-era texture
/// parameter table that the compatibility profile keeps (GL 4.6 compatibility Table 8.25, with
/// DEPTH_TEXTURE_MODE), and say nothing of a core profile, whose parameter list is closed (GL 4.6
/// core §8.10, Table 8.17: "An INVALID_ENUM error is generated if pname is not one of the
/// parameter names in table 8.17"). OpenGL ES has its own extensions (EXT_shadow_samplers); none of
/// these is an OpenGL ES extension. So a core or ES context that accepts these pnames is judged
/// against its spec alone, whatever its extension string says.
pub fn extension_ctx(ctx: Ctx) -> bool {
    ctx == Ctx::Compat
}

/// The extensions that could make `pname` exist in a `ctx` context of `spec` where the spec itself
/// does not define it (none where it does: the spec's own rule stands).
pub fn pname_extensions(spec: Spec, ctx: Ctx, pname: u32) -> Vec<&'static PnameExtension> {
    if !extension_ctx(ctx) || param(spec, ctx, pname).is_ok() {
        return Vec::new();
    }
    PNAME_EXTENSIONS
        .iter()
        .filter(|e| e.pnames.contains(&pname))
        .collect()
}

/// GL 4.6 §2.3.1 (ES 3.2 §2.3.1 alike), the rule for every error below.
pub const ERROR_IGNORED: &str = "GL 4.6 §2.3.1: \"the command which generates the error is ignored so that it has no effect on GL state\"";
/// GL 4.6 §8.10 Errors (ES 3.2 §8.10 alike): a pname the context does not have.
pub const PNAME_UNKNOWN: &str = "GL 4.6 §8.10 / ES 3.2 §8.10: \"An INVALID_ENUM error is generated if pname is not one of the parameter names in table 8.17\" (8.19 in ES)";
/// GL 4.6 §8.10 Errors (ES 3.2 §8.10 alike): an enum value outside the legal ones.
pub const VALUE_ILLEGAL: &str = "GL 4.6 §8.10 / ES 3.2 §8.10: \"An INVALID_ENUM error is generated if the type of the parameter specified by pname is enum, and any value specified by param or params is not among the legal values shown in table 8.17\"";

fn to_model(s: Stored) -> shadowcheck_model::StateValue {
    use shadowcheck_model::StateValue as V;
    match s {
        Stored::Bool(b) => V::Bool(b),
        Stored::Enum(e) => V::Enum(e),
        Stored::Float(f) => V::Float(f as f32),
    }
}

fn error_to_model(e: GlErrorKind) -> shadowcheck_model::GlErrorCode {
    use shadowcheck_model::GlErrorCode as E;
    match e {
        GlErrorKind::InvalidEnum => E::InvalidEnum,
        GlErrorKind::InvalidValue => E::InvalidValue,
        GlErrorKind::InvalidOperation => E::InvalidOperation,
    }
}

/// What `call` on `pname` leaves under the table of `spec` in `ctx` (the pname must exist there):
/// the error, the value then read back (stored, or initial after an error) and the citations.
fn expect_call(
    spec: Spec,
    ctx: Ctx,
    prm: Param,
    call: shadowcheck_model::StateCall,
) -> (Option<GlErrorKind>, Stored, Vec<String>) {
    use shadowcheck_model::StateCall;
    let mut citations = vec![format!("{}: {}", prm.name, prm.cite)];
    let v = match call {
        StateCall::Initial => return (None, prm.default, citations),
        StateCall::SetFloat(f) => Value::Float(f as f64),
        StateCall::SetInt(i) => Value::Int(i as i64),
    };
    match set_param(spec, ctx, prm.pname, v) {
        Ok(s) => (None, s, citations),
        Err(e) => {
            if matches!(prm.kind, ParamKind::Enum(_, GlErrorKind::InvalidEnum)) {
                citations.push(VALUE_ILLEGAL.into());
            }
            citations.push(ERROR_IGNORED.into());
            (Some(e), prm.default, citations)
        }
    }
}

/// The single context kind of a state case's API paths.
fn case_ctx(case: &shadowcheck_model::StateCase) -> Result<Ctx, String> {
    let ctxs: Vec<Ctx> = case.api.iter().map(|a| ctx_of(*a)).collect();
    match ctxs.first() {
        Some(c) if ctxs.iter().all(|d| d == c) => Ok(*c),
        _ => Err("a state case needs API paths of exactly one context kind".into()),
    }
}

/// Whether a state case on `pname` reads the value back after its call: wherever the pname exists
/// under `spec` in `ctx` or an extension the context may expose adds it ([`pname_extensions`]).
pub fn reads_back(spec: Spec, ctx: Ctx, pname: u32) -> bool {
    param(spec, ctx, pname).is_ok() || !pname_extensions(spec, ctx, pname).is_empty()
}

/// The oracle's expectation of a state case on its (single) context kind: the error of the call
/// and the value GetTexParameter reads afterwards (the stored value, or the initial one after an
/// error). Where the spec lacks the pname but an extension of [`PNAME_EXTENSIONS`] adds it, the
/// expectation on a context exposing that extension is listed beside the base one
/// (`with_extension`), from the extension's own rules. `Err` when the case names no API path or
/// several of different context kinds.
pub fn expect_state(
    case: &shadowcheck_model::StateCase,
) -> Result<shadowcheck_model::StateExpect, String> {
    use shadowcheck_model::{ExtensionExpect, StateExpect};
    let ctx = case_ctx(case)?;
    let pname = case.pname.gl();
    let Ok(prm) = param(case.spec, ctx, pname) else {
        // Neither TexParameter nor GetTexParameter knows the pname: INVALID_ENUM, nothing stored;
        // unless the context exposes an extension that adds it, whose rules then apply.
        let with_extension = pname_extensions(case.spec, ctx, pname)
            .into_iter()
            .filter_map(|ext| {
                let prm = param(ext.spec, Ctx::Compat, pname).ok()?;
                let (error, value, cites) = expect_call(ext.spec, Ctx::Compat, prm, case.call);
                let mut citations = vec![ext.accepts.to_string()];
                citations.extend(cites);
                Some(ExtensionExpect {
                    extension: ext.name.to_string(),
                    error: error.map(error_to_model),
                    value: case.read_back.then(|| to_model(value)),
                    citations,
                })
            })
            .collect();
        return Ok(StateExpect {
            error: Some(shadowcheck_model::GlErrorCode::InvalidEnum),
            value: None,
            citations: vec![PNAME_UNKNOWN.into(), ERROR_IGNORED.into()],
            with_extension,
        });
    };
    let (error, value, citations) = expect_call(case.spec, ctx, prm, case.call);
    Ok(StateExpect {
        error: error.map(error_to_model),
        value: case.read_back.then(|| to_model(value)),
        citations,
        with_extension: Vec::new(),
    })
}

#[cfg(test)]
mod tests;
