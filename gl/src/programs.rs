//! Programs per [`ShaderKey`]: GLSL (the lookup as a fragment shader, see `shaders/mod.rs`, or in
//! a vertex or compute shader, `shaders/stage.rs`), ARB
//! fragment programs, or nothing for fixed function; compiled on first use and cached in a
//! [`ProgramCache`] (the renderer's) for the worker's life. Knows nothing of the renderer: it is
//! handed the GL context, what the context offers and the result framebuffer's size.

use super::legacy::Legacy;
use glow::HasContext;
use shadowcheck_model::ApiPath;
use shadowcheck_plan::units::{sampler_name, ProgramKey};
use shadowcheck_plan::{shaders, GlInfo};
use std::collections::HashMap;

/// A linked GLSL program and its uniform locations.
pub(super) struct Program {
    pub(super) program: glow::Program,
    pub(super) u_p: Option<glow::UniformLocation>,
    pub(super) u_x: Option<glow::UniformLocation>,
    pub(super) u_dx: Option<glow::UniformLocation>,
    pub(super) u_dy: Option<glow::UniformLocation>,
    pub(super) u_c: Option<glow::UniformLocation>,
    /// A variable gather offset (`GatherCall::Variable`).
    pub(super) u_o: Option<glow::UniformLocation>,
    pub(super) u_base: Option<glow::UniformLocation>,
    /// A compute-stage program's result pixel and unit (`shaders::stage`).
    pub(super) u_at: Option<glow::UniformLocation>,
    pub(super) u_unit: Option<glow::UniformLocation>,
}

/// What a [`ShaderKey`] compiles to on one path.
pub(super) enum Compiled {
    Glsl(Program),
    Arb(u32),
    Fixed,
}

/// Compiles the GLSL program or ARB fragment program of `pk` (fixed function needs none).
/// `batched`: the result framebuffer's size when one draw covers many cases (None: one pixel).
unsafe fn compile(
    gl: &glow::Context,
    info: &GlInfo,
    legacy: Option<&Legacy>,
    pk: &ProgramKey,
    batched: Option<i32>,
) -> Result<Compiled, String> {
    let (key, units) = (&pk.key, pk.units);
    match key.path {
        ApiPath::FixedFunction => Ok(Compiled::Fixed),
        ApiPath::ArbFp => {
            let l = legacy.ok_or("legacy entry points not loaded")?;
            l.arbfp_program(gl, &shaders::arbfp(key, units))
                .map(Compiled::Arb)
                .map_err(|e| e.to_string())
        }
        _ => {
            let sources = match shaders::compute_glsl(info, key, units) {
                Some(cs) => vec![(glow::COMPUTE_SHADER, cs)],
                None => {
                    let (vs, fs) = shaders::glsl(info, key, batched, units);
                    vec![(glow::VERTEX_SHADER, vs), (glow::FRAGMENT_SHADER, fs)]
                }
            };
            let program = gl.create_program()?;
            for (ty, src) in &sources {
                let sh = gl.create_shader(*ty)?;
                gl.shader_source(sh, src);
                gl.compile_shader(sh);
                if !gl.get_shader_compile_status(sh) {
                    return Err(format!(
                        "shader compile failed: {}\n{src}",
                        gl.get_shader_info_log(sh).trim()
                    ));
                }
                gl.attach_shader(program, sh);
                gl.delete_shader(sh);
            }
            // `a_pos` at 0 in both kinds of program; a batched one's other values after it.
            for (loc, name, _, _) in shaders::PARAM_ATTRIBS {
                gl.bind_attrib_location(program, loc, name);
            }
            gl.bind_attrib_location(program, shaders::UNIT_ATTRIB.0, shaders::UNIT_ATTRIB.1);
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                let last = sources.last().map(|(_, s)| s.as_str()).unwrap_or_default();
                return Err(format!(
                    "program link failed: {}\n{last}",
                    gl.get_program_info_log(program).trim()
                ));
            }
            gl.use_program(Some(program));
            let u = |n: &str| gl.get_uniform_location(program, n);
            // Sampler i reads texture unit i.
            for unit in 0..units.max(1) {
                if let Some(t) = u(&sampler_name(unit, units)) {
                    gl.uniform_1_i32(Some(&t), unit as i32);
                }
            }
            Ok(Compiled::Glsl(Program {
                program,
                u_p: u("u_p"),
                u_x: u("u_x"),
                u_dx: u("u_dx"),
                u_dy: u("u_dy"),
                u_c: u("u_c"),
                u_o: u("u_o"),
                u_base: u("u_base"),
                u_at: u("u_at"),
                u_unit: u(shaders::stage::UNIT_UNIFORM),
            }))
        }
    }
}

/// Programs by [`ProgramKey`], compiled on first use; a failed compile is kept as its message.
#[derive(Default)]
pub(super) struct ProgramCache(HashMap<ProgramKey, Result<Compiled, String>>);

impl ProgramCache {
    /// The program of `key` on `units` samplers (see [`compile`] for `batched`), compiled on
    /// first use.
    pub(super) unsafe fn get(
        &mut self,
        gl: &glow::Context,
        info: &GlInfo,
        legacy: Option<&Legacy>,
        pk: ProgramKey,
        batched: Option<i32>,
    ) -> Result<&Compiled, String> {
        self.0
            .entry(pk)
            .or_insert_with(|| compile(gl, info, legacy, &pk, batched))
            .as_ref()
            .map_err(|e| e.clone())
    }

    /// Programs compiled so far (GLSL and ARB; fixed function compiles none here).
    pub(super) fn compiled(&self) -> usize {
        self.0
            .iter()
            .filter(|(k, c)| k.key.path != ApiPath::FixedFunction && c.is_ok())
            .count()
    }
}
