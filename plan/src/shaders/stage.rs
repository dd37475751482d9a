//! The single-case program of a vertex-stage lookup ([`Stage::Vertex`]): the vertex shader does
//! the lookup with the implicit-LOD function (`texture`, GLSL 1.20 `shadow2D` & co.) on `u_p`,
//! where "the base level-of-detail" is "computed as zero" (GLSL 4.60 / GLSL ES 3.20 §8.9), and
//! passes the result on as a flat output (GLSL 1.20: a varying, every vertex writing the same
//! value); the fragment shader stores it. Every vertex of the full-screen triangle does the same
//! lookup with the same values, so the provoking vertex's result is the lookup's.

use super::{legacy_call, modern_call, sampler_type, Language, NEVER_DISCARD, UNIT_ATTRIB};
use crate::units::sampler_name;
use crate::{SamplerKind, ShaderKey};
use shadowcheck_model::ApiPath;

/// (vertex source, fragment source) of the key's vertex-stage program with `units` samplers
/// (each case names its unit by the attribute [`UNIT_ATTRIB`], as in a fragment-stage program).
pub(super) fn program(lang: &Language, key: &ShaderKey, units: usize) -> (String, String) {
    let (header, vin, vout, fin) = (&lang.header, lang.vin, lang.vout, lang.fin);
    let prec = if key.path == ApiPath::Es300 {
        "highp "
    } else {
        ""
    };
    let vec4_result = key.path == ApiPath::Glsl120 || key.kind != SamplerKind::Shadow;
    let store = |tex: &str| {
        let call = match key.path {
            ApiPath::Glsl120 => legacy_call(key, tex),
            _ => modern_call(key, tex),
        };
        if vec4_result {
            format!("v_r = vec4({call});")
        } else {
            format!("v_r = vec4({call}, 0.0, 0.0, 1.0);")
        }
    };
    let samplers: String = (0..units)
        .map(|u| {
            format!(
                "uniform {prec}{} {};\n",
                sampler_type(key.kind, key.target),
                sampler_name(u, units)
            )
        })
        .collect();
    let (unit_decl, lookup) = if units > 1 {
        let chain = (0..units)
            .map(|u| {
                let s = store(&sampler_name(u, units));
                if u == 0 {
                    format!("if (unit == 0) {s}")
                } else if u + 1 == units {
                    format!("else {s}")
                } else {
                    format!("else if (unit == {u}) {s}")
                }
            })
            .collect::<Vec<_>>()
            .join("\n  ");
        (
            format!("{vin} float {};\n", UNIT_ATTRIB.1),
            format!("int unit = int({} + 0.5);\n  {chain}", UNIT_ATTRIB.1),
        )
    } else {
        (String::new(), store("u_tex"))
    };
    let vs = format!(
        "{header}{vin} vec2 a_pos;\n{unit_decl}{samplers}uniform vec4 u_p;\nuniform float u_x;\n{vout} vec4 v_r;\nvoid main() {{\n  gl_Position = vec4(a_pos, 0.0, 1.0);\n  vec4 p = u_p;\n  {lookup}\n}}\n"
    );
    let (fout, out_decl) = (lang.fout, lang.out_decl);
    let fs = format!(
        "{header}uniform vec2 u_c;\n{fin} vec4 v_r;\n{out_decl}void main() {{\n  {NEVER_DISCARD}\n  {fout} = v_r;\n}}\n"
    );
    (vs, fs)
}
