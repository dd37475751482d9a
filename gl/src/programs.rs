//! Programs per [`ShaderKey`]: GLSL (the lookup as a fragment shader, see `shaders/mod.rs`), ARB
//! fragment programs, or nothing for fixed function; compiled on first use and cached in a
//! [`ProgramCache`] (the renderer's) for the worker's life. Knows nothing of the renderer: it is
//! handed the GL context, what the context offers and the result framebuffer's size.

use super::legacy::Legacy;
use glow::HasContext;
use shadowcheck_model::ApiPath;
use shadowcheck_plan::{shaders, GlInfo, ShaderKey};
use std::collections::HashMap;

/// A linked GLSL program and its uniform locations.
pub(super) struct Program {
    pub(super) program: glow::Program,
    pub(super) u_p: Option<glow::UniformLocation>,
    pub(super) u_x: Option<glow::UniformLocation>,
    pub(super) u_dx: Option<glow::UniformLocation>,
    pub(super) u_dy: Option<glow::UniformLocation>,
    pub(super) u_c: Option<glow::UniformLocation>,
    pub(super) u_base: Option<glow::UniformLocation>,
}

/// What a [`ShaderKey`] compiles to on one path.
pub(super) enum Compiled {
    Glsl(Program),
    Arb(u32),
    Fixed,
}

/// Compiles the GLSL program or ARB fragment program of `key` (fixed function needs none).
/// `batched`: the result framebuffer's size when one draw covers many cases (None: one pixel).
unsafe fn compile(
    gl: &glow::Context,
    info: &GlInfo,
    legacy: Option<&Legacy>,
    key: &ShaderKey,
    batched: Option<i32>,
) -> Result<Compiled, String> {
    match key.path {
        ApiPath::FixedFunction => Ok(Compiled::Fixed),
        ApiPath::ArbFp => {
            let l = legacy.ok_or("legacy entry points not loaded")?;
            l.arbfp_program(gl, &shaders::arbfp(key))
                .map(Compiled::Arb)
                .map_err(|e| e.to_string())
        }
        _ => {
            let (vs, fs) = shaders::glsl(info, key, batched);
            let program = gl.create_program()?;
            for (ty, src) in [(glow::VERTEX_SHADER, &vs), (glow::FRAGMENT_SHADER, &fs)] {
                let sh = gl.create_shader(ty)?;
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
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                return Err(format!(
                    "program link failed: {}\n{fs}",
                    gl.get_program_info_log(program).trim()
                ));
            }
            gl.use_program(Some(program));
            let u = |n: &str| gl.get_uniform_location(program, n);
            if let Some(t) = u("u_tex") {
                gl.uniform_1_i32(Some(&t), 0);
            }
            Ok(Compiled::Glsl(Program {
                program,
                u_p: u("u_p"),
                u_x: u("u_x"),
                u_dx: u("u_dx"),
                u_dy: u("u_dy"),
                u_c: u("u_c"),
                u_base: u("u_base"),
            }))
        }
    }
}

/// Programs by (key, batched), compiled on first use; a failed compile is kept as its message.
#[derive(Default)]
pub(super) struct ProgramCache(HashMap<(ShaderKey, bool), Result<Compiled, String>>);

impl ProgramCache {
    /// The program of `key` (see [`compile`] for `batched`), compiled on first use.
    pub(super) unsafe fn get(
        &mut self,
        gl: &glow::Context,
        info: &GlInfo,
        legacy: Option<&Legacy>,
        key: &ShaderKey,
        batched: Option<i32>,
    ) -> Result<&Compiled, String> {
        self.0
            .entry((*key, batched.is_some()))
            .or_insert_with(|| compile(gl, info, legacy, key, batched))
            .as_ref()
            .map_err(|e| e.clone())
    }
}
