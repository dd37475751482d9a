//! The single-case programs of lookups outside the fragment stage, where "the base
//! level-of-detail" is "computed as zero" (GLSL 4.60 / GLSL ES 3.20 §8.9); both use the
//! implicit-LOD function (`texture`, GLSL 1.20 `shadow2D` & co.) on `u_p`, or a gather.
//!
//! - [`Stage::Vertex`]: the vertex shader does the lookup and passes the result on as a flat
//!   output (GLSL 1.20: a varying, every vertex writing the same value); the fragment shader
//!   stores it. Every vertex of the full-screen triangle does the same lookup with the same
//!   values, so the provoking vertex's result is the lookup's.
//! - [`Stage::Compute`]: a compute shader of one invocation (`local_size` 1, dispatched as one
//!   work group) does the lookup and stores the result with `imageStore` at `u_at`, the result
//!   pixel, in the RGBA32F result image bound to image unit 0 (the framebuffer's colour texture,
//!   read back like a drawn pixel). A case on one of several units names it by the uniform
//!   `u_unit` (a compute shader has no vertex attributes).

use super::{as_vec4, legacy_call, modern_call, Language, NEVER_DISCARD, UNIT_ATTRIB};
use crate::{SamplerKind, ShaderKey};
use shadowcheck_model::ApiPath;
#[cfg(doc)]
use shadowcheck_model::Stage;

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
        as_vec4("v_r", &call, vec4_result)
    };
    let samplers = super::sampler_decls(prec, key, units);
    let (unit_decl, lookup) = if units > 1 {
        let chain = super::unit_chain(units, "unit", &store);
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

/// The uniform naming the case's unit in a compute shader of several samplers.
pub const UNIT_UNIFORM: &str = "u_unit";

/// The compute shader of the key with `units` samplers (module docs).
pub(super) fn compute(lang: &Language, key: &ShaderKey, units: usize) -> String {
    let es = key.path == ApiPath::Es300;
    let prec = if es { "highp " } else { "" };
    let vec4_result = key.kind != SamplerKind::Shadow || key.gather.is_some();
    let store = |tex: &str| as_vec4("r", &modern_call(key, tex), vec4_result);
    let samplers = super::sampler_decls(prec, key, units);
    let (unit_decl, lookup) = if units > 1 {
        let chain = super::unit_chain(units, UNIT_UNIFORM, &store);
        (format!("uniform int {UNIT_UNIFORM};\n"), chain)
    } else {
        (String::new(), store("u_tex"))
    };
    format!(
        "{}layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;\nlayout(rgba32f, binding = 0) writeonly uniform {prec}image2D u_out;\n{samplers}{unit_decl}uniform vec4 u_p;\nuniform float u_x;\nuniform ivec2 u_at;\nvoid main() {{\n  vec4 p = u_p;\n  vec4 r = vec4(0.0);\n  {lookup}\n  imageStore(u_out, u_at, r);\n}}\n",
        lang.header
    )
}

#[cfg(test)]
mod tests {
    use crate::paths::plan;
    use crate::shaders::{batchable, glsl};
    use crate::test_case::{case, info};
    use crate::{ContextApi, LodForm};
    use shadowcheck_model::{ApiPath, Delivery, Stage, Target};

    #[test]
    fn the_vertex_shader_looks_up_and_the_fragment_shader_stores_its_result() {
        let mut c = case(Target::T2d, 4, 4, 1);
        c.lookup.stage = Stage::Vertex;
        c.lookup.lod = 1.0;
        for (api, ctx, glsl_v, call, out) in [
            (
                ApiPath::GlslCore,
                ContextApi::Core,
                460,
                "v_r = vec4(texture(u_tex, p.xyz), 0.0, 0.0, 1.0);",
                "flat out vec4 v_r;",
            ),
            (
                ApiPath::Es300,
                ContextApi::Es3,
                300,
                "v_r = vec4(texture(u_tex, p.xyz), 0.0, 0.0, 1.0);",
                "flat out vec4 v_r;",
            ),
            (
                ApiPath::Glsl120,
                ContextApi::Compat,
                460,
                "v_r = vec4(shadow2D(u_tex, p.xyz));",
                "varying vec4 v_r;",
            ),
        ] {
            let p = plan(api, &c).expect("a vertex-stage plan");
            assert_eq!(p.key.form, LodForm::Implicit(false), "{api}");
            assert_eq!(p.key.stage, Stage::Vertex);
            assert!(!batchable(&p.key), "{api}: one case a draw");
            let (vs, fs) = glsl(&info(ctx, glsl_v), &p.key, None, 1);
            assert!(vs.contains(call) && vs.contains(out), "{api}: {vs}");
            assert!(!fs.contains("texture") && !fs.contains("shadow2D"), "{fs}");
            assert!(fs.contains("v_r;\n"), "{fs}");
            if api == ApiPath::Es300 {
                assert!(vs.contains("uniform highp sampler2DShadow u_tex;"), "{vs}");
            }
            // Several units: the case's unit chosen in the vertex shader.
            let (vs, _) = glsl(&info(ctx, glsl_v), &p.key, None, 2);
            assert!(
                vs.contains("int unit = int(a_unit + 0.5);") && vs.contains("u_tex1"),
                "{vs}"
            );
        }
        // No vertex-stage lookup on Vulkan; no gather or delivered values in this program.
        assert!(plan(ApiPath::Vulkan, &c).is_err());
        c.lookup.delivery = Delivery::Uniform;
        assert!(plan(ApiPath::GlslCore, &c).is_err());
    }

    #[test]
    fn a_compute_shader_looks_up_once_and_stores_at_the_result_pixel() {
        use crate::paths::plan_for;
        use crate::shaders::compute_glsl;
        let mut c = case(Target::T2d, 4, 4, 1);
        c.lookup.stage = Stage::Compute;
        c.lookup.lod = 1.0;
        for (ctx, glsl_v, version) in [
            (ContextApi::Core, 460, "#version 430 core\n"),
            (ContextApi::Es3, 320, "#version 320 es\n"),
        ] {
            let api = if ctx == ContextApi::Es3 {
                ApiPath::Es300
            } else {
                ApiPath::GlslCore
            };
            let i = info(ctx, glsl_v);
            let p = plan_for(&i, api, &c, &c.lookup).expect("a compute-stage plan");
            assert_eq!(p.key.form, LodForm::Implicit(false), "{api}");
            assert!(!batchable(&p.key), "{api}: one case a dispatch");
            let cs = compute_glsl(&i, &p.key, 1).expect("a compute shader");
            assert!(cs.starts_with(version), "{cs}");
            for line in [
                "layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;",
                "r = vec4(texture(u_tex, p.xyz), 0.0, 0.0, 1.0);",
                "imageStore(u_out, u_at, r);",
            ] {
                assert!(cs.contains(line), "{api}: {line} in {cs}");
            }
            assert_eq!(
                cs.contains("writeonly uniform highp image2D u_out;"),
                api == ApiPath::Es300,
                "{cs}"
            );
            // Several units: the case's own named by a uniform.
            let cs = compute_glsl(&i, &p.key, 3).expect("a compute shader");
            assert!(
                cs.contains("uniform int u_unit;") && cs.contains("if (u_unit == 0)"),
                "{cs}"
            );
            // Not a compute key: no compute shader.
            let mut frag = p.key;
            frag.stage = Stage::Fragment;
            assert!(compute_glsl(&i, &frag, 1).is_none());
        }
        // A context without compute shaders (GL 4.2, ES 3.0) and a path without them.
        let mut old = info(ContextApi::Core, 420);
        old.version = (4, 2);
        let e = plan_for(&old, ApiPath::GlslCore, &c, &c.lookup).unwrap_err();
        assert!(e.contains("GL 4.3") && e.contains("GLSL 420"), "{e}");
        assert!(plan_for(&info(ContextApi::Es3, 300), ApiPath::Es300, &c, &c.lookup).is_err());
        assert!(plan(ApiPath::Glsl130, &c).is_err());
        // A version raised by an override: compute only where the driver claims it.
        let mut raised = info(ContextApi::Core, 460);
        raised.version_override = true;
        let e = plan_for(&raised, ApiPath::GlslCore, &c, &c.lookup).unwrap_err();
        assert!(e.contains("GL_ARB_compute_shader"), "{e}");
        raised.extensions.insert("GL_ARB_compute_shader".into());
        assert!(plan_for(&raised, ApiPath::GlslCore, &c, &c.lookup).is_ok());
        let mut raised_es = info(ContextApi::Es3, 310);
        raised_es.version_override = true;
        assert!(plan_for(&raised_es, ApiPath::Es300, &c, &c.lookup).is_err());
        // A gather in a compute shader: the case's P, no derivatives.
        c.lookup.gather = Some(shadowcheck_model::Gather { offsets: None });
        let i = info(ContextApi::Core, 460);
        let p = plan_for(&i, ApiPath::GlslCore, &c, &c.lookup).expect("a compute gather");
        assert_eq!((p.key.form, p.dx), (LodForm::Gather(false), [0.0; 4]));
        let cs = compute_glsl(&i, &p.key, 1).expect("a compute shader");
        assert!(cs.contains("r = vec4(textureGather(u_tex"), "{cs}");
    }
}
