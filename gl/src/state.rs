//! Worker self-check of TexParameter / GetTexParameter state for the depth-comparison pnames:
//! initial values, accepted values (what is stored) and rejected values (which error, state
//! unchanged), against the oracle's tables (`shadowcheck_oracle::state`, which cites the sections).
//!
//! Run with `shadowcheck gl-worker --backend NAME --state-check` (one JSON line per check).

use super::paths::GlInfo;
use super::texture::error_name;
use glow::HasContext;
use serde::Serialize;
use shadowcheck_model::Spec;
use shadowcheck_oracle::state::{self as ostate, Ctx, ParamKind, Stored, Value};

/// One check and its outcome.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct StateCheck {
    pub spec: String,
    pub pname: String,
    /// `default`, `set <value>` or `get (unknown pname)`.
    pub check: String,
    pub expected: String,
    pub got: String,
    pub ok: bool,
    pub cite: String,
}

/// The spec whose state tables describe this context as a whole.
pub fn spec_and_ctx(info: &GlInfo) -> (Spec, Ctx) {
    if info.es {
        (Spec::Gles32, Ctx::Es)
    } else if info.compat {
        (Spec::Gl46, Ctx::Compat)
    } else {
        (Spec::Gl46, Ctx::Core)
    }
}

/// Enum values tried on every enum pname (legal for some pname of some spec, or junk).
const CANDIDATES: &[u32] = &[
    0x0000, 0x884E, 0x0200, 0x0201, 0x0202, 0x0203, 0x0204, 0x0205, 0x0206, 0x0207, 0x819C, 0x819D,
    0x1909, 0x8049, 0x1906, 0x1903, 0x1902, 0x1901, 0x1234,
];

fn show(s: &Stored) -> String {
    match s {
        Stored::Bool(b) => format!("{b}"),
        Stored::Enum(e) => format!("0x{e:04X}"),
        Stored::Float(f) => format!("{f}"),
    }
}

unsafe fn query(gl: &glow::Context, pname: u32, like: &Stored) -> Stored {
    match like {
        Stored::Bool(_) => Stored::Bool(gl.get_tex_parameter_i32(glow::TEXTURE_2D, pname) != 0),
        Stored::Enum(_) => Stored::Enum(gl.get_tex_parameter_i32(glow::TEXTURE_2D, pname) as u32),
        Stored::Float(_) => Stored::Float(gl.get_tex_parameter_f32(glow::TEXTURE_2D, pname) as f64),
    }
}

fn same(a: &Stored, b: &Stored) -> bool {
    match (a, b) {
        (Stored::Float(x), Stored::Float(y)) => (*x as f32) == (*y as f32),
        _ => a == b,
    }
}

/// Runs every check on fresh TEXTURE_2D objects.
///
/// # Safety
/// The context of `gl` must be current.
pub unsafe fn check(gl: &glow::Context, info: &GlInfo) -> Vec<StateCheck> {
    let (spec, ctx) = spec_and_ctx(info);
    let mut out = Vec::new();
    let fresh = || {
        while gl.get_error() != glow::NO_ERROR {}
        let t = gl.create_texture().ok();
        gl.bind_texture(glow::TEXTURE_2D, t);
        t
    };
    let drop_tex = |t: Option<glow::Texture>| {
        if let Some(t) = t {
            gl.delete_texture(t);
        }
    };
    let params = ostate::params(spec, ctx);
    for pname in ostate::PNAMES {
        let Some(prm) = params.iter().find(|p| p.pname == *pname) else {
            // Not a pname of this spec and context: GetTexParameter raises INVALID_ENUM (§8.10).
            let t = fresh();
            let _ = gl.get_tex_parameter_i32(glow::TEXTURE_2D, *pname);
            let e = gl.get_error();
            out.push(StateCheck {
                spec: spec.key().into(),
                pname: format!("0x{pname:04X}"),
                check: "get (pname not defined here)".into(),
                expected: "GL_INVALID_ENUM".into(),
                got: if e == glow::NO_ERROR {
                    "no error".into()
                } else {
                    error_name(e)
                },
                ok: e == glow::INVALID_ENUM,
                cite: "GL 4.6 §8.10 / ES 3.2 §8.10: pname not in the table".into(),
            });
            drop_tex(t);
            continue;
        };
        let t = fresh();
        let got = query(gl, prm.pname, &prm.default);
        let e = gl.get_error();
        out.push(StateCheck {
            spec: spec.key().into(),
            pname: prm.name.into(),
            check: "default".into(),
            expected: show(&prm.default),
            got: if e == glow::NO_ERROR {
                show(&got)
            } else {
                error_name(e)
            },
            ok: e == glow::NO_ERROR && same(&got, &prm.default),
            cite: prm.cite.into(),
        });
        drop_tex(t);
        let values: Vec<Value> = match prm.kind {
            ParamKind::Bool => vec![Value::Int(0), Value::Int(1), Value::Int(2)],
            ParamKind::Enum(..) => CANDIDATES.iter().map(|v| Value::Int(*v as i64)).collect(),
            ParamKind::Unit => vec![Value::Float(-0.5), Value::Float(0.25), Value::Float(1.5)],
        };
        for v in values {
            let t = fresh();
            match v {
                Value::Int(i) => gl.tex_parameter_i32(glow::TEXTURE_2D, prm.pname, i as i32),
                Value::Float(f) => gl.tex_parameter_f32(glow::TEXTURE_2D, prm.pname, f as f32),
            }
            let e = gl.get_error();
            let after = query(gl, prm.pname, &prm.default);
            let want = ostate::set_param(spec, ctx, prm.pname, v);
            let (expected, ok) = match &want {
                Ok(s) => (show(s), e == glow::NO_ERROR && same(&after, s)),
                // An error leaves the state unchanged.
                Err(k) => (
                    format!("GL_{} (state stays {})", k.name(), show(&prm.default)),
                    e == k.gl() && same(&after, &prm.default),
                ),
            };
            let vs = match v {
                Value::Int(i) => format!("0x{i:04X}"),
                Value::Float(f) => format!("{f}"),
            };
            out.push(StateCheck {
                spec: spec.key().into(),
                pname: prm.name.into(),
                check: format!("set {vs}"),
                expected,
                got: if e == glow::NO_ERROR {
                    show(&after)
                } else {
                    format!("{} (state {})", error_name(e), show(&after))
                },
                ok,
                cite: prm.cite.into(),
            });
            drop_tex(t);
        }
    }
    gl.bind_texture(glow::TEXTURE_2D, None);
    out
}
