//! The lookup of a compute-stage case ([`Stage::Compute`]) in a GL reproducer: what the GL
//! worker's `draw` does for it (gl/src/renderer/mod.rs, its compute arm). The program is one
//! compute shader, the text of `shaders::compute_glsl` (the function the worker compiles), run as
//! one work group of one invocation, which stores the lookup's result with `imageStore` at `u_at`
//! = (0, 0) of the image on unit 0: the framebuffer's RGBA32F colour texture, so that `main` reads
//! the result back with glReadPixels as it reads a drawn pixel.
//!
//! Each rule of that image, as the worker keeps it:
//! - it is made by glTexStorage2D (`main`, where the program defines `COMPUTE_STAGE`): ES binds
//!   only an immutable texture as an image (ES 3.2 "Texture Image Loads and Stores",
//!   BindImageTexture: "An INVALID_OPERATION error is generated if texture is not the name of an
//!   immutable texture object");
//! - glMemoryBarrier(GL_ALL_BARRIER_BITS) after the dispatch: an image store is visible to the
//!   framebuffer read that follows only after a barrier (GL 4.6 / ES 3.2, "Shader Memory Access
//!   Synchronization"), with the framebuffer unbound around the dispatch (softpipe, Mesa 22.3.6,
//!   reads its cached tiles otherwise: reports/README.md, "compute results");
//! - the context must have compute shaders, GLSL 4.30 or GLSL ES 3.10 (`GlInfo::compute`): below
//!   that the worker skips the test, and the program exits 2 saying so.

use super::csource::{cf, cstr, gl_info, SHADER_FN};
use shadowcheck_gl::BackendName;
#[cfg(doc)]
use shadowcheck_model::Stage;
use shadowcheck_plan::{shaders, Plan};
use std::fmt::Write;

/// The compute shader variants, `{minimum GLSL version x 100, source}`, the highest first:
/// `compute_glsl` writes `#version 430 core` on desktop GL, and `#version 320 es` from GLSL ES
/// 3.20, else `310 es`, on ES; the program picks the first whose minimum the context reaches.
fn variants(b: BackendName, plan: &Plan) -> Vec<(u32, String)> {
    let versions: &[u32] = if b.api.is_es() { &[320, 310] } else { &[430] };
    let mut out: Vec<(u32, String)> = vec![];
    for &v in versions {
        let Some(cs) = shaders::compute_glsl(&gl_info(b, v), &plan.key, 1) else {
            continue;
        };
        match out.last_mut() {
            // The same text for a lower version: the lower minimum is the variant's.
            Some(last) if last.1 == cs => last.0 = v,
            _ => out.push((v, cs)),
        }
    }
    out
}

/// `draw` of a compute-stage lookup (module docs), with the `COMPUTE_STAGE` definition `main`
/// reads; `None` when the plan's key is not a compute-stage one.
pub(super) fn dispatch_fn(b: BackendName, plan: &Plan) -> Option<String> {
    let variants = variants(b, plan);
    if variants.is_empty() {
        return None;
    }
    let mut table = String::new();
    for (min, cs) in &variants {
        let _ = writeln!(table, "    {{{min},\n{}}},", cstr(cs, "     "));
    }
    let [p0, p1, p2, p3] = plan.p.map(cf);
    Some(format!(
        r#"/* main makes the colour texture with glTexStorage2D: ES binds only an immutable texture as an
 * image (ES 3.2 "Texture Image Loads and Stores", BindImageTexture). */
#define COMPUTE_STAGE 1

/* The compute shader shadowcheck's worker compiles for this lookup (plan/src/shaders/stage.rs):
 * {{minimum GLSL version x 100, compute}}. Below the last minimum the context has no compute
 * shaders, and shadowcheck skips the test. */
static const struct {{ int min_glsl; const char *cs; }} PROGRAMS[] = {{
{table}}};

{SHADER_FN}static void draw(int glsl) {{
    const unsigned n = sizeof PROGRAMS / sizeof PROGRAMS[0];
    unsigned v = 0;
    while (v < n && PROGRAMS[v].min_glsl > glsl) v++;
    if (v == n) die("no compute shaders here (GLSL 4.30 / GLSL ES 3.10 needed): shadowcheck skips this test");
    GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_COMPUTE_SHADER, PROGRAMS[v].cs));
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) die("program link");
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "u_tex"), 0);
    glUniform4f(glGetUniformLocation(p, "u_p"), {p0}, {p1}, {p2}, {p3});
    glUniform1f(glGetUniformLocation(p, "u_x"), {x});
    /* The result pixel: (0, 0), the one main reads back. */
    glUniform2i(glGetUniformLocation(p, "u_at"), 0, 0);
    /* The framebuffer's colour texture (main's) on image unit 0, the shader's `binding = 0`. */
    GLint color = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &color);
    glBindImageTexture(0, (GLuint)color, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    /* The framebuffer unbound around the dispatch, as the worker does: softpipe (Mesa 22.3.6)
     * otherwise reads back its cached tiles of the texture, not the store. */
    GLint fbo = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDispatchCompute(1, 1, 1);
    /* The store reaches glReadPixels only through a barrier (GL 4.6 / ES 3.2, "Shader Memory
     * Access Synchronization": MemoryBarrier with FRAMEBUFFER_BARRIER_BIT). */
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
    check("compute dispatch");
}}

"#,
        x = cf(plan.x),
    ))
}
