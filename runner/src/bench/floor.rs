//! The GL bare-draw floor: what a driver costs per shadow lookup when nothing but the lookups runs.
//!
//! A child process (`shadowcheck bench --floor-child NAME`, started with the backend's driver
//! environment, see [`crate::backend::gl::worker_command`]) creates the backend's context, a 64x64
//! DEPTH_COMPONENT24 texture sampled NEAREST with LEQUAL comparison (like the 2D NEAREST cases),
//! an RGBA32F framebuffer of `size`x`size` pixels (the format the GL worker reads results from),
//! and draws one full-screen triangle per repetition whose fragments each do one `textureLod`
//! shadow lookup with coordinates and reference computed from `gl_FragCoord`: no case upload, no
//! read-back beyond `glFinish` and one pixel. It prints one JSON line ([`FloorResult`]).

use super::cpu::BENCH_TEXTURE;
use glow::HasContext;
use serde::{Deserialize, Serialize};
use shadowcheck_gl::context::GlContext;
use shadowcheck_gl::names::{BackendName, ContextApi};
use std::process::Stdio;
use std::time::{Duration, Instant};

/// The child's answer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FloorResult {
    pub ok: bool,
    #[serde(default)]
    pub error: Option<String>,
    #[serde(default)]
    pub lookups: u64,
    #[serde(default)]
    pub seconds: f64,
    #[serde(default)]
    pub draws: u32,
    #[serde(default)]
    pub renderer: String,
    #[serde(default)]
    pub version: String,
}

impl FloorResult {
    fn err(e: impl std::fmt::Display) -> FloorResult {
        FloorResult {
            ok: false,
            error: Some(e.to_string()),
            lookups: 0,
            seconds: 0.0,
            draws: 0,
            renderer: String::new(),
            version: String::new(),
        }
    }
    pub fn per_s(&self) -> f64 {
        self.lookups as f64 / self.seconds
    }
}

fn header(api: ContextApi) -> &'static str {
    match api {
        ContextApi::Core => "#version 330 core\n",
        ContextApi::Compat => "#version 130\n",
        ContextApi::Es3 | ContextApi::Es2 => {
            "#version 300 es\nprecision highp float;\nprecision highp int;\n"
        }
    }
}

/// Vertex shader: the full-screen triangle from gl_VertexID (no vertex buffer).
fn vertex_source(api: ContextApi) -> String {
    format!(
        "{}void main() {{ gl_Position = vec4(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1), 0.0, 1.0); }}\n",
        header(api)
    )
}

/// Fragment shader: one shadow lookup per fragment, parameters from gl_FragCoord.
fn fragment_source(api: ContextApi) -> String {
    let prec = if api.is_es() { "highp " } else { "" };
    format!(
        "{}uniform {prec}sampler2DShadow u_tex;\nout vec4 o;\nvoid main() {{\n  vec2 uv = gl_FragCoord.xy * (0.37 / {BENCH_TEXTURE}.0);\n  float dref = fract(dot(gl_FragCoord.xy, vec2(0.0123, 0.0457)));\n  o = vec4(textureLod(u_tex, vec3(uv, dref), 0.0), 0.0, 0.0, 1.0);\n}}\n",
        header(api)
    )
}

/// Child side: measure on this process's context. `min`: time to keep drawing.
pub fn measure(name: BackendName, size: i32, min: Duration) -> FloorResult {
    let ctx = match GlContext::create(name) {
        Ok(c) => c,
        Err(e) => return FloorResult::err(e),
    };
    if ctx.get_proc("glGetString").is_null() {
        return FloorResult::err("glGetString missing");
    }
    // SAFETY: the context is current on this thread and the loader returns its entry points.
    let gl = unsafe { glow::Context::from_loader_function(|s| ctx.get_proc(s)) };
    // SAFETY: as above; every GL call below is on the current context.
    match unsafe { draw_loop(&gl, name, size, min) } {
        Ok(r) => r,
        Err(e) => FloorResult::err(e),
    }
}

unsafe fn compile(gl: &glow::Context, api: ContextApi) -> Result<glow::Program, String> {
    let program = gl.create_program()?;
    for (ty, src) in [
        (glow::VERTEX_SHADER, vertex_source(api)),
        (glow::FRAGMENT_SHADER, fragment_source(api)),
    ] {
        let sh = gl.create_shader(ty)?;
        gl.shader_source(sh, &src);
        gl.compile_shader(sh);
        if !gl.get_shader_compile_status(sh) {
            return Err(format!(
                "shader compile failed: {}\n{src}",
                gl.get_shader_info_log(sh)
            ));
        }
        gl.attach_shader(program, sh);
        gl.delete_shader(sh);
    }
    gl.link_program(program);
    if !gl.get_program_link_status(program) {
        return Err(format!("link failed: {}", gl.get_program_info_log(program)));
    }
    Ok(program)
}

unsafe fn draw_loop(
    gl: &glow::Context,
    name: BackendName,
    size: i32,
    min: Duration,
) -> Result<FloorResult, String> {
    let renderer = gl.get_parameter_string(glow::RENDERER);
    let version = gl.get_parameter_string(glow::VERSION);
    if !name.driver.renderer_matches(&renderer) {
        return Err(format!("wrong driver: GL_RENDERER is `{renderer}`"));
    }
    // The result framebuffer, left bound for the draws below.
    shadowcheck_gl::texture::rgba32f_framebuffer(gl, size, false)?;
    // Depth texture: pseudo-random 24-bit values, NEAREST, LEQUAL, REPEAT.
    let n = BENCH_TEXTURE as i32;
    let mut x = 0x9E37_79B9u32;
    let texels: Vec<u8> = (0..n * n)
        .flat_map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            (x & 0xFFFF_FF00).to_ne_bytes()
        })
        .collect();
    let depth = gl.create_texture()?;
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(glow::TEXTURE_2D, Some(depth));
    gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        glow::TEXTURE_2D,
        0,
        glow::DEPTH_COMPONENT24 as i32,
        n,
        n,
        0,
        glow::DEPTH_COMPONENT,
        glow::UNSIGNED_INT,
        glow::PixelUnpackData::Slice(Some(&texels)),
    );
    for (p, v) in [
        (glow::TEXTURE_MIN_FILTER, glow::NEAREST),
        (glow::TEXTURE_MAG_FILTER, glow::NEAREST),
        (glow::TEXTURE_WRAP_S, glow::REPEAT),
        (glow::TEXTURE_WRAP_T, glow::REPEAT),
        (glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE),
        (glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL),
    ] {
        gl.tex_parameter_i32(glow::TEXTURE_2D, p, v as i32);
    }
    if !name.api.is_es() {
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, 0);
    }
    let program = compile(gl, name.api)?;
    gl.use_program(Some(program));
    if let Some(u) = gl.get_uniform_location(program, "u_tex") {
        gl.uniform_1_i32(Some(&u), 0);
    }
    let vao = gl.create_vertex_array()?;
    gl.bind_vertex_array(Some(vao));
    gl.viewport(0, 0, size, size);
    gl.disable(glow::DITHER);
    let err = gl.get_error();
    if err != glow::NO_ERROR {
        return Err(format!("GL error 0x{err:04X} during setup"));
    }
    // Warm-up: the first draw compiles the shader variant.
    gl.draw_arrays(glow::TRIANGLES, 0, 3);
    gl.finish();
    let t0 = Instant::now();
    let mut draws = 0u32;
    while draws == 0 || t0.elapsed() < min {
        gl.draw_arrays(glow::TRIANGLES, 0, 3);
        gl.finish();
        draws += 1;
    }
    let seconds = t0.elapsed().as_secs_f64();
    let mut px = [0u8; 16];
    gl.read_pixels(
        size / 2,
        size / 2,
        1,
        1,
        glow::RGBA,
        glow::FLOAT,
        glow::PixelPackData::Slice(Some(&mut px)),
    );
    let r = f32::from_ne_bytes([px[0], px[1], px[2], px[3]]);
    if r != 0.0 && r != 1.0 {
        return Err(format!(
            "a NEAREST shadow lookup returned {r}, not 0 or 1: the draw did not run as intended"
        ));
    }
    let err = gl.get_error();
    if err != glow::NO_ERROR {
        return Err(format!("GL error 0x{err:04X} while drawing"));
    }
    Ok(FloorResult {
        ok: true,
        error: None,
        lookups: draws as u64 * (size as u64 * size as u64),
        seconds,
        draws,
        renderer,
        version,
    })
}

/// Parent side: run the floor child for `backend` with its driver environment plus `extra_env`.
pub fn run_child(
    backend: &str,
    size: i32,
    min: Duration,
    extra_env: &[(&str, &str)],
) -> FloorResult {
    let wc = match crate::backend::gl::worker_command(backend) {
        Ok(w) => w,
        Err(e) => return FloorResult::err(e),
    };
    let mut c = std::process::Command::new(&wc.program);
    c.args([
        "bench",
        "--floor-child",
        backend,
        "--floor-size",
        &size.to_string(),
        "--floor-seconds",
        &min.as_secs_f64().to_string(),
    ]);
    for (k, v) in &wc.env {
        c.env(k, v);
    }
    for (k, v) in extra_env {
        c.env(k, v);
    }
    c.stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let out = match c.output() {
        Ok(o) => o,
        Err(e) => return FloorResult::err(format!("cannot start {}: {e}", wc.program.display())),
    };
    let stdout = String::from_utf8_lossy(&out.stdout);
    match stdout
        .lines()
        .rev()
        .find(|l| l.trim_start().starts_with('{'))
        .map(serde_json::from_str::<FloorResult>)
    {
        Some(Ok(r)) => r,
        _ => {
            use std::os::unix::process::ExitStatusExt;
            let how = match out.status.signal() {
                Some(s) => format!("floor child killed by signal {s}"),
                None => format!("floor child exited with {}", out.status),
            };
            let stderr = String::from_utf8_lossy(&out.stderr);
            let tail: Vec<&str> = stderr.lines().rev().take(3).collect();
            FloorResult::err(format!(
                "{how}: {}",
                tail.into_iter().rev().collect::<Vec<_>>().join(" | ")
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shaders_use_an_explicit_lod_shadow_lookup_per_context_kind() {
        let f = fragment_source(ContextApi::Es3);
        assert!(
            f.starts_with("#version 300 es")
                && f.contains("highp sampler2DShadow")
                && f.contains("textureLod(u_tex, vec3(uv, dref), 0.0)"),
            "{f}"
        );
        assert!(fragment_source(ContextApi::Core).starts_with("#version 330 core"));
        assert!(vertex_source(ContextApi::Compat).contains("gl_VertexID"));
    }
}
