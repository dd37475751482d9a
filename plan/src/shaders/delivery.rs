//! How a single-case GLSL program receives the lookup's values ([`Delivery`]): from uniforms
//! (`literal` and `uniform`: `u_p`, `u_x`, `u_dx`, `u_dy`, and a variable gather offset `u_o`),
//! or from flat inputs the vertex shader copies those uniforms into (`flat`, `per_fragment`).
//!
//! `per_fragment` changes the values on the three fragments of the 2x2 pixel quad that are not
//! read: the single-case draw covers the whole aligned quad holding the measured pixel
//! ([`super::single_draw_viewport`]); the measured fragment, the one at `u_c`, gets the case's
//! values unchanged, does its lookup and writes it; the other three do theirs with their own
//! values and are discarded after it, so no pixel but the measured one is written (the WebGL page
//! packs its slots one pixel each). The others get a reference 0.25 higher and a gather offset with its lowest bit
//! flipped (still in [-8, 7]); where the lookup takes no implicit derivatives (explicit LOD,
//! gradients, gathers) also coordinates 0.25 further and a LOD 0.25 higher. Where λ comes from
//! implicit derivatives the coordinates and the bias stay as they are, so that λ at the measured
//! fragment is the case's.

use super::Language;
use crate::{GatherCall, LodForm, SamplerKind, ShaderKey};
use shadowcheck_model::{Delivery, Target};

/// The key delivers a variable gather offset.
fn variable_offset(key: &ShaderKey) -> bool {
    key.gather == Some(GatherCall::Variable)
}

/// The delivery reads flat inputs.
fn flat(key: &ShaderKey) -> bool {
    matches!(key.delivery, Delivery::Flat | Delivery::PerFragment)
}

/// The fragment shader's declarations of the values of a single-case program.
pub(super) fn fragment_inputs(key: &ShaderKey) -> String {
    let o = variable_offset(key);
    if flat(key) {
        let mut s = "uniform vec2 u_c;\nflat in vec4 v_p;\nflat in float v_x;\nflat in vec4 v_dx;\nflat in vec4 v_dy;\n".to_string();
        if o {
            s += "flat in ivec2 v_o;\n";
        }
        s
    } else {
        let mut s = "uniform vec4 u_p;\nuniform float u_x;\nuniform vec4 u_dx;\nuniform vec4 u_dy;\nuniform vec2 u_c;\n".to_string();
        if o {
            s += "uniform ivec2 u_o;\n";
        }
        s
    }
}

/// The statements that bring flat inputs into the names the lookup call uses (`u_x`, `u_dx`,
/// `u_dy`, `u_o`), and the name of P's value.
pub(super) fn read_values(key: &ShaderKey) -> (String, &'static str) {
    if !flat(key) {
        return (String::new(), "u_p");
    }
    let mut s = "\n  vec4 u_dx = v_dx;\n  vec4 u_dy = v_dy;\n  float u_x = v_x;".to_string();
    if variable_offset(key) {
        s += "\n  ivec2 u_o = v_o;";
    }
    (s, "v_p")
}

/// Which components of P change on the other fragments of a `per_fragment` lookup, as a vec4 of
/// 0.25 and 0, and whether `u_x` changes.
fn changed(key: &ShaderKey) -> ([bool; 4], bool) {
    match key.form {
        LodForm::Lod | LodForm::Grad | LodForm::Gather(_) => ([true; 4], true),
        LodForm::Implicit(bias) => {
            let shadow = key.kind == SamplerKind::Shadow;
            let mut p = [false; 4];
            match key.target {
                _ if !shadow => {}
                Target::T1d | Target::T2d | Target::Rect | Target::T1dArray => p[2] = true,
                Target::T2dArray | Target::Cube => p[3] = true,
                // The reference is `u_x` (the bias form has none on this sampler).
                Target::CubeArray => {}
            }
            let x = shadow && key.target == Target::CubeArray && !bias;
            (p, x)
        }
        LodForm::Constant => ([false; 4], false),
    }
}

/// The `per_fragment` statements after P is computed (nothing for the other deliveries).
pub(super) fn per_fragment(key: &ShaderKey) -> String {
    if key.delivery != Delivery::PerFragment {
        return String::new();
    }
    let (p, x) = changed(key);
    let v = p.map(|c| if c { "0.25" } else { "0.0" }).join(", ");
    let mut s = "\n  bool m = all(equal(ivec2(gl_FragCoord.xy), ivec2(u_c)));".to_string();
    if p.contains(&true) {
        s += &format!("\n  p = m ? p : p + vec4({v});");
    }
    if x {
        s += "\n  u_x = m ? u_x : u_x + 0.25;";
    }
    if variable_offset(key) {
        s += "\n  u_o = m ? u_o : u_o ^ ivec2(1);";
    }
    s
}

/// What follows the lookup: `per_fragment` discards the fragments that are not measured (after
/// their lookups, so that every fragment of the quad has run its own).
pub(super) fn after_lookup(key: &ShaderKey) -> &'static str {
    if key.delivery == Delivery::PerFragment {
        "\n  if (!m) discard;"
    } else {
        ""
    }
}

/// The vertex shader of a single-case `flat` / `per_fragment` program: the full-screen triangle,
/// the values read from uniforms and passed on as flat outputs (and the unit, as
/// `vertex_shader` does for several units).
pub(super) fn flat_vertex_shader(lang: &Language, key: &ShaderKey, units: usize) -> String {
    let (header, vin) = (&lang.header, lang.vin);
    let mut decl = format!("{vin} vec2 a_pos;\nuniform vec4 u_p;\nuniform float u_x;\nuniform vec4 u_dx;\nuniform vec4 u_dy;\nflat out vec4 v_p;\nflat out float v_x;\nflat out vec4 v_dx;\nflat out vec4 v_dy;\n");
    let mut body =
        "gl_Position = vec4(a_pos, 0.0, 1.0); v_p = u_p; v_x = u_x; v_dx = u_dx; v_dy = u_dy;"
            .to_string();
    if variable_offset(key) {
        decl += "uniform ivec2 u_o;\nflat out ivec2 v_o;\n";
        body += " v_o = u_o;";
    }
    if units > 1 {
        let (loc_name, vout) = (super::UNIT_ATTRIB.1, lang.vout);
        decl += &format!("{vin} float {loc_name};\n{vout} float v_unit;\n");
        body += &format!(" v_unit = {loc_name};");
    }
    format!("{header}{decl}void main() {{ {body} }}\n")
}

#[cfg(test)]
mod tests {
    use crate::paths::{plan, plan_for};
    use crate::shaders::{batchable, glsl, single_draw_viewport};
    use crate::test_case::{case, info};
    use crate::{ContextApi, GatherCall};
    use shadowcheck_model::{ApiPath, Delivery, Gather, Target};

    /// A 2D gather with offset (1, -2) delivered as `d`.
    fn gather(d: Delivery) -> shadowcheck_model::Case {
        let mut c = case(Target::T2d, 4, 4, 1);
        c.lookup.gather = Some(Gather { offsets: None });
        c.lookup.offset = [1, -2, 0];
        c.lookup.delivery = d;
        c
    }

    #[test]
    fn a_literal_gather_offset_is_a_constant_and_a_delivered_one_a_value() {
        let lit = plan(ApiPath::GlslCore, &gather(Delivery::Literal)).expect("literal");
        assert_eq!(
            (lit.key.gather, lit.key.offset),
            (Some(GatherCall::Single), [1, -2])
        );
        let core = info(ContextApi::Core, 460);
        for d in [Delivery::Uniform, Delivery::Flat, Delivery::PerFragment] {
            let c = gather(d);
            let p = plan_for(&core, ApiPath::GlslCore, &c, &c.lookup).expect("core 4.60");
            assert_eq!(p.key.gather, Some(GatherCall::Variable), "{d}");
            assert_eq!((p.key.offset, p.o), ([0, 0], [1, -2]), "{d}");
            assert!(!batchable(&p.key), "{d}: one case a draw");
            let (vs, fs) = glsl(&core, &p.key, None, 1);
            assert!(
                fs.contains("textureGatherOffset(u_tex, p.xy, p.z, u_o)"),
                "{fs}"
            );
            match d {
                Delivery::Uniform => {
                    assert!(fs.contains("uniform ivec2 u_o;") && !vs.contains("u_o"));
                }
                _ => {
                    assert!(vs.contains("uniform ivec2 u_o;") && vs.contains("v_o = u_o;"));
                    assert!(fs.contains("flat in ivec2 v_o;") && fs.contains("vec4 p = v_p;"));
                }
            }
            let pf = d == Delivery::PerFragment;
            assert_eq!(fs.contains("u_o = m ? u_o : u_o ^ ivec2(1);"), pf, "{fs}");
            assert_eq!(fs.contains("if (!m) discard;"), pf, "{fs}");
            let vp = single_draw_viewport(&p.key, (5, 7));
            assert_eq!(vp, if pf { [4, 6, 2, 2] } else { [5, 7, 1, 1] });
        }
        // GLSL 3.30 and GLSL ES 3.10 have no variable gather offset.
        let c = gather(Delivery::Uniform);
        let why = plan_for(
            &info(ContextApi::Core, 330),
            ApiPath::GlslCore,
            &c,
            &c.lookup,
        )
        .expect_err("GLSL 3.30");
        assert!(why.contains("GLSL 4.00"), "{why}");
        let mut es = gather(Delivery::Flat);
        es.api = vec![ApiPath::Es300];
        assert!(plan_for(&info(ContextApi::Es3, 310), ApiPath::Es300, &es, &es.lookup).is_err());
        assert!(plan_for(&info(ContextApi::Es3, 320), ApiPath::Es300, &es, &es.lookup).is_ok());
    }

    #[test]
    fn per_fragment_changes_only_what_leaves_lambda_alone() {
        let core = info(ContextApi::Core, 460);
        // Explicit LOD: every component of P and the LOD change on the other fragments.
        let mut c = case(Target::T2d, 4, 4, 1);
        c.lookup.delivery = Delivery::PerFragment;
        c.lookup.lod = 0.5;
        let p = plan_for(&core, ApiPath::GlslCore, &c, &c.lookup).expect("lod");
        let (_, fs) = glsl(&core, &p.key, None, 1);
        assert!(
            fs.contains("p = m ? p : p + vec4(0.25, 0.25, 0.25, 0.25);"),
            "{fs}"
        );
        assert!(fs.contains("u_x = m ? u_x : u_x + 0.25;"), "{fs}");
        // Implicit derivatives on a cube: only the reference (P.w) changes.
        let mut c = case(Target::Cube, 4, 4, 6);
        c.lookup.delivery = Delivery::PerFragment;
        c.lookup.coord = [1.0, 0.25, 0.25, 1.0];
        let mut implicit = core.clone();
        implicit.form = crate::LookupForm::Implicit;
        let p = plan_for(&implicit, ApiPath::GlslCore, &c, &c.lookup).expect("cube");
        let (_, fs) = glsl(&implicit, &p.key, None, 1);
        assert!(
            fs.contains("p = m ? p : p + vec4(0.0, 0.0, 0.0, 0.25);"),
            "{fs}"
        );
        assert!(!fs.contains("u_x = m"), "{fs}");
        // Vulkan and WGSL are not given a delivered case.
        c.api = vec![ApiPath::Vulkan];
        assert!(plan(ApiPath::Vulkan, &c).unwrap_err().contains("delivery"));
        let mut l = case(Target::T2d, 4, 4, 1);
        l.lookup.delivery = Delivery::Uniform;
        assert!(plan(ApiPath::Wgsl, &l).unwrap_err().contains("delivery"));
    }
}
