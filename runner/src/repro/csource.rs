//! The text of `repro.c`: one self-contained C program that does for one (case, API path) what the
//! GL worker (shadowcheck-gl) does, with nothing of shadowcheck linked in.
//!
//! What it mirrors, and from where: the context (`gl/src/context.rs`: EGL surfaceless or OSMesa,
//! the same API and versions tried highest first), and from the lookup plan (shadowcheck-plan,
//! which the worker draws too): the texture (the bytes `texels::level_bytes` uploads, the transfer
//! of `texels::transfer_for`, the TexParameter and SamplerParameter calls of `unit` in their
//! order), the lookup (`paths::plan_with` gives the shader key and the uniform values;
//! `shaders::glsl` / `shaders::arbfp` give the program text, the same functions the worker
//! compiles), and one draw into a 1x1 viewport of an RGBA32F framebuffer cleared to -1
//! (the GL worker's `renderer`); a compute-stage lookup instead dispatches the compute shader of
//! `shaders::compute_glsl`, which stores into that framebuffer's colour texture (`compute.rs`).
//! One difference: the worker draws `textureLod`/`textureGrad` lookups of core and ES contexts
//! batched, each case an instance whose attributes carry P, the gradients and the LOD; the
//! reproducer passes the same values as uniforms (the shader key and the lookup call are the
//! same).

pub(super) use super::cexpect::expectation;
use super::tokens::Tokens;
use super::{compute, egl14, Subject};
use shadowcheck_gl::{BackendName, Platform};
use shadowcheck_model::{ApiPath, Channel, Format, Stage, Swizzle, Target};
use shadowcheck_plan::texels::{level_bytes, transfer_for};
use shadowcheck_plan::unit::{sampler_params, tex_params, ParamValue};
use shadowcheck_plan::{gl, paths, shaders, ContextApi, GlInfo, LodForm, Plan, SamplerKind};
use std::fmt::Write;
use std::path::Path;

const SWIZZLE_PNAMES: [u32; 4] = [
    gl::TEXTURE_SWIZZLE_R,
    gl::TEXTURE_SWIZZLE_G,
    gl::TEXTURE_SWIZZLE_B,
    gl::TEXTURE_SWIZZLE_A,
];

/// The C name of a swizzle source (GL 4.6 Table 8.26's values).
fn swizzle_source(v: u32) -> &'static str {
    [
        Swizzle::Red,
        Swizzle::Green,
        Swizzle::Blue,
        Swizzle::Alpha,
        Swizzle::Zero,
        Swizzle::One,
    ]
    .into_iter()
    .find(|c| c.gl() == v)
    .map_or("GL_ZERO", |c| match c {
        Swizzle::Red => "GL_RED",
        Swizzle::Green => "GL_GREEN",
        Swizzle::Blue => "GL_BLUE",
        Swizzle::Alpha => "GL_ALPHA",
        Swizzle::Zero => "GL_ZERO",
        Swizzle::One => "GL_ONE",
    })
}

/// A C `float` literal that reads back as exactly `v`.
pub(super) fn cf(v: f32) -> String {
    if v.is_nan() {
        "NAN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "INFINITY" } else { "-INFINITY" }.into()
    } else {
        format!("{v:?}f")
    }
}

/// A C string literal, one source line per line.
pub(super) fn cstr(s: &str, indent: &str) -> String {
    let esc = |l: &str| l.replace('\\', "\\\\").replace('"', "\\\"");
    let lines: Vec<String> = s
        .split_inclusive('\n')
        .map(|l| format!("{indent}\"{}\"", esc(l).replace('\n', "\\n")))
        .collect();
    if lines.is_empty() {
        "\"\"".into()
    } else {
        lines.join("\n")
    }
}

pub(super) fn layout_char(c: Channel) -> char {
    match c {
        Channel::R => 'r',
        Channel::Zero => '0',
        Channel::One => '1',
        Channel::Unused => '-',
        Channel::ROrZero => 'z',
        // A gather's four comparisons: 'A'..'D' read gather value 0..3, each judged by its own
        // accepted set (`GATHER_ACCEPTED` in the program).
        Channel::G0 => 'A',
        Channel::G1 => 'B',
        Channel::G2 => 'C',
        Channel::G3 => 'D',
    }
}

/// The build command (one line) for this platform and API (an EGL 1.4 backend's: [`egl14`]).
pub fn build_line(b: BackendName, lib_dir: Option<&Path>) -> String {
    if egl14::applies(b, lib_dir) {
        return egl14::build_line(b, lib_dir);
    }
    let libs = match (b.platform, b.api.is_es()) {
        (Platform::Osmesa, _) => "-lOSMesa",
        (Platform::Egl, true) => "-lEGL -lGLESv2",
        (Platform::Egl, false) => "-lEGL -lGL",
    };
    format!("cc -std=c99 -O1 -Wall -o repro repro.c {libs} -lm")
}

/// The environment that picks the driver, as `NAME=value` words (the worker's, `BackendName::env`;
/// for an EGL 1.4 backend the library's directory on the loader's path instead of the worker's
/// `SHADOWCHECK_LIBEGL`: [`egl14::env_words`]).
pub fn env_words(b: BackendName, lib_dir: Option<&Path>) -> String {
    let egl = egl14::applies(b, lib_dir);
    let mut words: Vec<String> = b
        .env()
        .iter()
        .filter(|(k, _)| {
            !egl || (k != "LD_LIBRARY_PATH" && k != shadowcheck_gl::context::LIBEGL_ENV)
        })
        .map(|(k, v)| format!("{k}={v}"))
        .collect();
    if egl {
        words.push(egl14::env_words(b, lib_dir));
    }
    words.retain(|w| !w.is_empty());
    words.join(" ")
}

/// The program text, or why this path cannot be planned for this case (the worker would Skip it).
pub fn program(s: &Subject, b: BackendName) -> Result<String, String> {
    // As the GL worker on a driver with EXT_texture_shadow_lod (`paths::plan_for`): a backend
    // name asking for `lod` / `implicit` gets that extension's overloads (the shader requires it).
    let plan = paths::plan_in(s.api, &s.case, &s.case.lookup, b.form, true)?;
    let mut tok = Tokens::default();
    let mut body = String::new();
    let compat = b.api == ContextApi::Compat;
    let _ = write!(body, "{}", expectation(s));
    let lib_dir = s.lib_dir.as_deref();
    let _ = write!(body, "{}", context_fn(b, lib_dir));
    let _ = write!(body, "{}", texture_fn(s, compat, &mut tok)?);
    let _ = write!(body, "{}", draw_fn(s, b, &plan, &mut tok));
    let _ = write!(body, "{VERDICT}{MAIN}");
    let includes = includes(b);
    let run = format!("{} ./repro", env_words(b, lib_dir));
    Ok(format!(
        "/* shadowcheck reproducer: {test} on {backend}\n *\n * Build: {build}\n * Run:   {run}\n *\n * Generated by `shadowcheck repro`: what shadowcheck's GL worker does for this test, with no\n * shadowcheck code.\n * Context: {ctx}.\n * Texture: the integers the worker uploads, the same sampler state.\n * Lookup: {how}; {once}.\n * Prints the expected result (spec value and accepted set, computed by\n * shadowcheck's oracle, written here as constants) and the observed RGBA; exits 1 when the\n * observation is outside the accepted set, 0 when inside, 2 when setup fails.\n */\n#define GL_GLEXT_PROTOTYPES 1\n{includes}#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n{defines}\n{body}",
        test = s.test(),
        backend = b,
        build = build_line(b, lib_dir),
        ctx = context_words(b, lib_dir),
        how = plan.note,
        once = if plan.key.stage == Stage::Compute {
            "one compute invocation, which stores into the RGBA32F framebuffer's colour texture"
        } else {
            "one draw into a 1x1 viewport of an RGBA32F framebuffer"
        },
        defines = tok.defines(),
    ))
}

/// The headers of a GL program on this platform and API.
pub(super) fn includes(b: BackendName) -> &'static str {
    match (b.platform, b.api.is_es()) {
        (_, true) => "#include <EGL/egl.h>\n#include <EGL/eglext.h>\n#include <GLES3/gl32.h>\n#include <GLES2/gl2ext.h>\n",
        (Platform::Egl, false) => "#include <EGL/egl.h>\n#include <EGL/eglext.h>\n#include <GL/gl.h>\n#include <GL/glext.h>\n",
        (Platform::Osmesa, false) => "#include <GL/osmesa.h>\n#include <GL/gl.h>\n#include <GL/glext.h>\n",
    }
}

pub(super) fn context_words(b: BackendName, lib_dir: Option<&Path>) -> String {
    if egl14::applies(b, lib_dir) {
        return egl14::context_words(b);
    }
    let platform = match b.platform {
        Platform::Egl => "EGL, EGL_PLATFORM_SURFACELESS_MESA",
        Platform::Osmesa => "OSMesa",
    };
    let api = match b.api {
        ContextApi::Core => "desktop GL core profile",
        ContextApi::Compat => "desktop GL compatibility profile",
        ContextApi::Es3 | ContextApi::Es2 => "OpenGL ES",
    };
    format!("{platform}, {api}, highest version first")
}

/// The versions the worker tries, highest first (`gl::egl::versions`), as a C initializer.
fn versions(api: ContextApi) -> String {
    let v: Vec<String> = shadowcheck_gl::egl::versions(api)
        .iter()
        .map(|(a, b)| format!("{{{a}, {b}}}"))
        .collect();
    format!("{{{}}}", v.join(", "))
}

pub(super) fn context_fn(b: BackendName, lib_dir: Option<&Path>) -> String {
    if egl14::applies(b, lib_dir) {
        return egl14::context_fn(b);
    }
    let vs = versions(b.api);
    let create = match b.platform {
        Platform::Egl => {
            let (bind, profile) = match b.api {
                ContextApi::Core => ("EGL_OPENGL_API", "EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, "),
                ContextApi::Compat => ("EGL_OPENGL_API", "EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, "),
                ContextApi::Es3 | ContextApi::Es2 => ("EGL_OPENGL_ES_API", ""),
            };
            format!(
                "    EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);\n    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) die(\"eglInitialize (surfaceless)\");\n    if (!eglBindAPI({bind})) die(\"eglBindAPI\");\n    static const int versions[][2] = {vs};\n    for (unsigned i = 0; i < sizeof versions / sizeof versions[0]; i++) {{\n        const EGLint attrs[] = {{EGL_CONTEXT_MAJOR_VERSION, versions[i][0], EGL_CONTEXT_MINOR_VERSION, versions[i][1], {profile}EGL_NONE}};\n        EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);\n        if (ctx == EGL_NO_CONTEXT) continue;\n        if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) die(\"eglMakeCurrent (no surface)\");\n        printf(\"context:   asked for %d.%d\\n\", versions[i][0], versions[i][1]);\n        return;\n    }}\n    die(\"eglCreateContext: no version of this context kind\");\n"
            )
        }
        Platform::Osmesa => {
            let profile = if b.api == ContextApi::Core {
                "OSMESA_CORE_PROFILE"
            } else {
                "OSMESA_COMPAT_PROFILE"
            };
            format!(
                "    static unsigned char buffer[16 * 16 * 4]; /* OSMesa's colour buffer; the draw goes to an FBO */\n    static const int versions[][2] = {vs};\n    for (unsigned i = 0; i < sizeof versions / sizeof versions[0]; i++) {{\n        const int attrs[] = {{OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,\n                             OSMESA_PROFILE, {profile}, OSMESA_CONTEXT_MAJOR_VERSION, versions[i][0],\n                             OSMESA_CONTEXT_MINOR_VERSION, versions[i][1], 0}};\n        OSMesaContext ctx = OSMesaCreateContextAttribs(attrs, NULL);\n        if (!ctx) continue;\n        if (!OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16)) die(\"OSMesaMakeCurrent\");\n        printf(\"context:   asked for %d.%d\\n\", versions[i][0], versions[i][1]);\n        return;\n    }}\n    die(\"OSMesaCreateContextAttribs returned NULL for every version\");\n"
            )
        }
    };
    format!(
        "static void die(const char *what) {{\n    fprintf(stderr, \"setup failed: %s\\n\", what);\n    exit(2);\n}}\n\nstatic void check(const char *what) {{\n    GLenum e = glGetError();\n    if (e != GL_NO_ERROR) {{\n        fprintf(stderr, \"setup failed: %s raised GL error 0x%04X\\n\", what, e);\n        exit(2);\n    }}\n}}\n\n/* The context, as shadowcheck's worker creates it (gl/src/context.rs). */\nstatic void make_context(void) {{\n{create}}}\n\n"
    )
}

/// The C element type of an upload (`texture::transfer_for`'s type) and the values of `bytes`.
fn texel_array(ty: u32, bytes: &[u8]) -> (&'static str, Vec<String>) {
    let words = |n: usize| bytes.chunks_exact(n);
    match ty {
        glow::UNSIGNED_BYTE => ("GLubyte", bytes.iter().map(|b| b.to_string()).collect()),
        glow::UNSIGNED_SHORT | glow::UNSIGNED_SHORT_4_4_4_4 => (
            "GLushort",
            words(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]).to_string())
                .collect(),
        ),
        glow::FLOAT => (
            "GLfloat",
            words(4)
                .map(|c| cf(f32::from_ne_bytes([c[0], c[1], c[2], c[3]])))
                .collect(),
        ),
        // UNSIGNED_INT, UNSIGNED_INT_24_8 and FLOAT_32_UNSIGNED_INT_24_8_REV (float bits, stencil).
        _ => (
            "GLuint",
            words(4)
                .map(|c| format!("{}u", u32::from_ne_bytes([c[0], c[1], c[2], c[3]])))
                .collect(),
        ),
    }
}

fn texture_fn(s: &Subject, compat: bool, tok: &mut Tokens) -> Result<String, String> {
    let t = &s.case.texture;
    let (ifmt, fmt, ty, bpt) = transfer_for(&s.case);
    let target = tok.name(t.target.gl());
    let (ifmt, fmt_n, ty_n) = (tok.name(ifmt as u32), tok.name(fmt), tok.name(ty));
    let mut data = String::new();
    let mut up = String::new();
    for (i, lvl) in t.levels.iter().enumerate() {
        let level = t.base_level as usize + i;
        let bytes = level_bytes(t.format, lvl).map_err(|e| e.to_string())?;
        let (cty, vals) = texel_array(ty, &bytes);
        let rows: Vec<String> = vals
            .chunks(8)
            .map(|c| format!("    {}", c.join(", ")))
            .collect();
        let note = match t.format {
            Format::D24 => {
                " (24-bit values c as 32-bit unorm (c << 8) | low byte: every conversion gives c)"
            }
            Format::D24S8 => " ((depth << 8) | stencil)",
            Format::D32fS8 => " (float bits, then stencil)",
            _ => "",
        };
        let _ = writeln!(
            data,
            "/* level {level}: {}x{}x{}{note} */\nstatic const {cty} LEVEL{level}[] = {{\n{}\n}};",
            lvl.width,
            lvl.height,
            lvl.layers,
            rows.join(",\n")
        );
        let (w, h, l) = (lvl.width, lvl.height, lvl.layers);
        let _ = match t.target {
            Target::T1d => writeln!(up, "    glTexImage1D({target}, {level}, {ifmt}, {w}, 0, {fmt_n}, {ty_n}, LEVEL{level});"),
            Target::T2d | Target::Rect => writeln!(up, "    glTexImage2D({target}, {level}, {ifmt}, {w}, {h}, 0, {fmt_n}, {ty_n}, LEVEL{level});"),
            Target::T1dArray => writeln!(up, "    glTexImage2D({target}, {level}, {ifmt}, {w}, {l}, 0, {fmt_n}, {ty_n}, LEVEL{level});"),
            Target::T2dArray | Target::CubeArray => writeln!(up, "    glTexImage3D({target}, {level}, {ifmt}, {w}, {h}, {l}, 0, {fmt_n}, {ty_n}, LEVEL{level});"),
            Target::Cube => {
                let elem = bpt / if ty == glow::UNSIGNED_SHORT { 2 } else if ty == glow::UNSIGNED_BYTE { 1 } else { 4 };
                let per_face = (w * h) as usize * elem;
                for f in 0..6u32 {
                    let face = tok.name(glow::TEXTURE_CUBE_MAP_POSITIVE_X + f);
                    let _ = writeln!(up, "    glTexImage2D({face}, {level}, {ifmt}, {w}, {h}, 0, {fmt_n}, {ty_n}, LEVEL{level} + {});", f as usize * per_face);
                }
                Ok(())
            }
        };
    }
    let mut st = String::new();
    // The worker's TexParameter calls, in its order (`unit::tex_params`).
    for p in tex_params(compat, &s.case) {
        let name = tok.name(p.pname);
        let _ = match p.value {
            // Levels as numbers, swizzle sources by their names, other enums as tokens.
            ParamValue::Int(v)
                if matches!(p.pname, gl::TEXTURE_BASE_LEVEL | gl::TEXTURE_MAX_LEVEL) =>
            {
                writeln!(st, "    glTexParameteri({target}, {name}, {v});")
            }
            ParamValue::Int(v) if SWIZZLE_PNAMES.contains(&p.pname) => {
                writeln!(
                    st,
                    "    glTexParameteri({target}, {name}, {});",
                    swizzle_source(v)
                )
            }
            ParamValue::Int(v) => {
                let v = tok.name(v);
                writeln!(st, "    glTexParameteri({target}, {name}, {v});")
            }
            ParamValue::Float(v) => {
                writeln!(st, "    glTexParameterf({target}, {name}, {});", cf(v))
            }
            ParamValue::Floats(v) => {
                let b: Vec<String> = v.iter().map(|x| cf(*x)).collect();
                writeln!(
                    st,
                    "    {{ static const GLfloat border[4] = {{{}}}; glTexParameterfv({target}, {name}, border); }}",
                    b.join(", ")
                )
            }
        };
    }
    unit_state(&mut st, s, tok);
    Ok(format!(
        "/* The texture ({fmt} {tgt}): the integers shadowcheck's worker uploads (plan/src/texels.rs). */\n{data}\nstatic void make_texture(void) {{\n    GLuint tex;\n    glGenTextures(1, &tex);\n    glActiveTexture(GL_TEXTURE0);\n    glBindTexture({target}, tex);\n{up}    check(\"texture upload (glTexImage*)\");\n{st}    check(\"sampler state (glTexParameter*)\");\n}}\n\n",
        fmt = t.format,
        tgt = t.target,
    ))
}

/// The seamless enable and the sampler object of the case, as the worker sets them
/// (`unit::sampler_params`, bound to unit 0).
fn unit_state(st: &mut String, s: &Subject, tok: &mut Tokens) {
    let sm = &s.case.sampler;
    if let Some(on) = sm.seamless {
        let cap = tok.name(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        let f = if on { "glEnable" } else { "glDisable" };
        let _ = writeln!(st, "    {f}({cap});");
    }
    if sm.sampler_object.is_some() {
        let _ = writeln!(
            st,
            "    /* A sampler object bound to unit 0: its state replaces the texture's (GL 4.6 8.17.1). */"
        );
        let _ = writeln!(
            st,
            "    {{
        GLuint so;
        glGenSamplers(1, &so);"
        );
        for p in sampler_params(&s.case) {
            let name = tok.name(p.pname);
            let _ = match p.value {
                ParamValue::Int(v) => {
                    let v = tok.name(v);
                    writeln!(st, "        glSamplerParameteri(so, {name}, {v});")
                }
                ParamValue::Float(v) => {
                    writeln!(st, "        glSamplerParameterf(so, {name}, {});", cf(v))
                }
                ParamValue::Floats(v) => {
                    let b: Vec<String> = v.iter().map(|x| cf(*x)).collect();
                    writeln!(
                        st,
                        "        {{ static const GLfloat border[4] = {{{}}}; glSamplerParameterfv(so, {name}, border); }}",
                        b.join(", ")
                    )
                }
            };
        }
        let _ = writeln!(
            st,
            "        glBindSampler(0, so);
    }}"
        );
    }
}

fn vec4(v: [f32; 4]) -> String {
    format!("{}, {}, {}, {}", cf(v[0]), cf(v[1]), cf(v[2]), cf(v[3]))
}

fn draw_fn(s: &Subject, b: BackendName, plan: &Plan, tok: &mut Tokens) -> String {
    let key = &plan.key;
    let centre = [0.5f32, 0.5];
    let mut out = format!(
        "/* The lookup: {path} path, {kind:?} sampler, {how}. P = ({p}), x (LOD / bias / compare value) = {x},\n * dx = ({dx}), dy = ({dy}). */\n",
        path = s.api,
        kind = key.kind,
        how = plan.note,
        p = vec4(plan.p),
        x = cf(plan.x),
        dx = vec4(plan.dx),
        dy = vec4(plan.dy),
    );
    match key.path {
        ApiPath::FixedFunction => {
            let target = tok.name(s.case.texture.target.gl());
            let tc = match s.case.texture.target {
                Target::Cube => [plan.p[0], plan.p[1], plan.p[2], 1.0],
                _ => plan.p,
            };
            let body = if let LodForm::Implicit(bias) = key.form {
                // draw.rs: vertex (X, Y) lies (X/2, Y/2) pixels from the pixel centre.
                let at = |ox: f32, oy: f32| -> [f32; 4] {
                    let mut v = tc;
                    for (i, c) in v.iter_mut().enumerate() {
                        *c += ox * plan.dx[i] + oy * plan.dy[i];
                    }
                    v
                };
                let b = if bias { plan.x } else { 0.0 };
                let mut t = format!("    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, {});\n    glBegin(GL_TRIANGLES);\n", cf(b));
                for (v, (x, y)) in [at(-0.5, -0.5), at(1.5, -0.5), at(-0.5, 1.5)].iter().zip([
                    (-1, -1),
                    (3, -1),
                    (-1, 3),
                ]) {
                    let _ = writeln!(
                        t,
                        "    glTexCoord4f({}); glVertex2f({x}.0f, {y}.0f);",
                        vec4(*v)
                    );
                }
                t + "    glEnd();\n    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);\n"
            } else {
                format!("    glTexCoord4f({}); /* constant coordinates */\n    glBegin(GL_TRIANGLES);\n    glVertex2f(-1.0f, -1.0f); glVertex2f(3.0f, -1.0f); glVertex2f(-1.0f, 3.0f);\n    glEnd();\n", vec4(tc))
            };
            let _ = write!(
                out,
                "static void draw(int glsl) {{\n    (void)glsl;\n    glUseProgram(0);\n    glEnable({target});\n    /* COMBINE REPLACE of the texture's (Cs, As): the fragment colour is the source colour */\n    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);\n    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);\n    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);\n    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);\n    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);\n    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);\n    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);\n    glColor4f(0.0f, 0.0f, 0.0f, 1.0f); /* seen only where texturing is disabled (incomplete) */\n{body}    glDisable({target});\n    check(\"fixed-function draw\");\n}}\n\n"
            );
        }
        ApiPath::ArbFp => {
            let src = shaders::arbfp(key, 1);
            let _ = write!(
                out,
                "static const char *PROGRAM =\n{src};\n\nstatic void draw(int glsl) {{\n    (void)glsl;\n    GLuint id;\n    glGenProgramsARB(1, &id);\n    glBindProgramARB(GL_FRAGMENT_PROGRAM_ARB, id);\n    glProgramStringARB(GL_FRAGMENT_PROGRAM_ARB, GL_PROGRAM_FORMAT_ASCII_ARB, (GLsizei)strlen(PROGRAM), PROGRAM);\n    GLint pos = 0;\n    glGetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &pos);\n    if (pos != -1) {{\n        fprintf(stderr, \"ARB program rejected at %d: %s\\n\", pos, glGetString(GL_PROGRAM_ERROR_STRING_ARB));\n        exit(2);\n    }}\n    glUseProgram(0);\n    glEnable(GL_FRAGMENT_PROGRAM_ARB);\n    glProgramLocalParameter4fARB(GL_FRAGMENT_PROGRAM_ARB, 0, {p});\n    glProgramLocalParameter4fARB(GL_FRAGMENT_PROGRAM_ARB, 1, {dx});\n    glProgramLocalParameter4fARB(GL_FRAGMENT_PROGRAM_ARB, 2, {dy});\n    glProgramLocalParameter4fARB(GL_FRAGMENT_PROGRAM_ARB, 3, {cx}, {cy}, 0.0f, 0.0f);\n    glBegin(GL_TRIANGLES);\n    glVertex2f(-1.0f, -1.0f); glVertex2f(3.0f, -1.0f); glVertex2f(-1.0f, 3.0f);\n    glEnd();\n    glDisable(GL_FRAGMENT_PROGRAM_ARB);\n    check(\"ARB fragment program draw\");\n}}\n\n",
                src = cstr(&src, "    "),
                p = vec4(plan.p),
                dx = vec4(plan.dx),
                dy = vec4(plan.dy),
                cx = cf(centre[0]),
                cy = cf(centre[1]),
            );
        }
        _ => {
            let draw = compute::dispatch_fn(b, plan).unwrap_or_else(|| glsl_draw(b, plan, centre));
            let _ = write!(out, "{draw}");
        }
    }
    out
}

/// What the shader functions need to know of a context of this backend with GLSL version `glsl`
/// (x 100): the program text depends on nothing else (the version itself is found at run time).
pub(super) fn gl_info(b: BackendName, glsl: u32) -> GlInfo {
    GlInfo {
        api: b.api,
        es: b.api.is_es(),
        compat: b.api == ContextApi::Compat,
        version: (0, 0),
        glsl,
        renderer: String::new(),
        version_string: String::new(),
        extensions: Default::default(),
        version_override: false,
        form: b.form,
    }
}

/// The GLSL program variants: `shaders::glsl` writes a different `#version` line above GLSL 4.00
/// (desktop) and 3.20 (ES); the program picks the first whose minimum the context reaches.
fn glsl_variants(b: BackendName, plan: &Plan) -> Vec<(u32, String, String)> {
    let (hi, lo) = if b.api.is_es() {
        (320, 300)
    } else {
        (400, 330)
    };
    let (vh, fh) = shaders::glsl(&gl_info(b, hi), &plan.key, None, 1);
    let (vl, fl) = shaders::glsl(&gl_info(b, lo), &plan.key, None, 1);
    if (&vh, &fh) == (&vl, &fl) {
        vec![(0, vh, fh)]
    } else {
        vec![(hi, vh, fh), (0, vl, fl)]
    }
}

fn glsl_draw(b: BackendName, plan: &Plan, centre: [f32; 2]) -> String {
    let variants = glsl_variants(b, plan);
    let mut table = String::new();
    for (min, vs, fs) in &variants {
        let _ = writeln!(
            table,
            "    {{{min},\n{},\n{}}},",
            cstr(vs, "     "),
            cstr(fs, "     ")
        );
    }
    let uint = if plan.key.kind == SamplerKind::Uint {
        " (usampler: the stencil index)"
    } else {
        ""
    };
    format!(
        "/* The shaders shadowcheck's worker compiles for this lookup (plan/src/shaders/mod.rs){uint}:\n * {{minimum GLSL version x 100, vertex, fragment}}. */\nstatic const struct {{ int min_glsl; const char *vs, *fs; }} PROGRAMS[] = {{\n{table}}};\n\n{SHADER_FN}static void draw(int glsl) {{\n    unsigned v = 0;\n    while (v + 1 < sizeof PROGRAMS / sizeof PROGRAMS[0] && PROGRAMS[v].min_glsl > glsl) v++;\n    GLuint p = glCreateProgram();\n    glAttachShader(p, shader(GL_VERTEX_SHADER, PROGRAMS[v].vs));\n    glAttachShader(p, shader(GL_FRAGMENT_SHADER, PROGRAMS[v].fs));\n    glBindAttribLocation(p, 0, \"a_pos\");\n    glLinkProgram(p);\n    GLint ok = 0;\n    glGetProgramiv(p, GL_LINK_STATUS, &ok);\n    if (!ok) die(\"program link\");\n    glUseProgram(p);\n    glUniform1i(glGetUniformLocation(p, \"u_tex\"), 0);\n    glUniform4f(glGetUniformLocation(p, \"u_p\"), {p});\n    glUniform1f(glGetUniformLocation(p, \"u_x\"), {x});\n    glUniform4f(glGetUniformLocation(p, \"u_dx\"), {dx});\n    glUniform4f(glGetUniformLocation(p, \"u_dy\"), {dy});\n    glUniform2f(glGetUniformLocation(p, \"u_c\"), {cx}, {cy});\n{offset}{viewport}    glDrawArrays(GL_TRIANGLES, 0, 3);\n    check(\"GLSL draw\");\n}}\n\n",
        p = vec4(plan.p),
        x = cf(plan.x),
        dx = vec4(plan.dx),
        dy = vec4(plan.dy),
        cx = cf(centre[0]),
        cy = cf(centre[1]),
        offset = delivered_offset(plan),
        viewport = delivered_viewport(plan),
    )
}

/// The uniform `u_o` of a variable `textureGatherOffset` offset (`delivery` other than literal),
/// set as the GL worker sets it; nothing for every other lookup.
fn delivered_offset(plan: &Plan) -> String {
    if plan.key.gather != Some(paths::GatherCall::Variable) {
        return String::new();
    }
    format!(
        "    /* The gather offset, delivered as a uniform (GLSL 4.60 §8.9.4: \"the offset can be variable (non constant)\"). */\n    glUniform2i(glGetUniformLocation(p, \"u_o\"), {}, {});\n",
        plan.o[0], plan.o[1]
    )
}

/// The viewport of the draw where it is not `main`'s one pixel: a `per_fragment` lookup covers the
/// 2x2 pixel quad whose lower-left pixel is read (`shaders::single_draw_viewport`), the other three
/// fragments doing their lookups with other values and then being discarded.
fn delivered_viewport(plan: &Plan) -> String {
    let [x, y, w, h] = shaders::single_draw_viewport(&plan.key, (0, 0));
    if [w, h] == [1, 1] {
        return String::new();
    }
    format!(
        "    /* Values that differ between the fragments of the pixel quad: the draw covers it. */\n    glViewport({x}, {y}, {w}, {h});\n"
    )
}

/// `shader`: one compiled shader of the program, or exit 2 with the compiler's log. A fragment of
/// C, shared by the draw and the compute programs.
pub(super) const SHADER_FN: &str = "static GLuint shader(GLenum type, const char *src) {
    GLuint sh = glCreateShader(type);
    glShaderSource(sh, 1, &src, NULL);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(sh, sizeof log, NULL, log);
        fprintf(stderr, \"shader compile failed: %s\\n%s\\n\", log, src);
        exit(2);
    }
    return sh;
}

";

/// `main`: context, framebuffer (as `draw::Renderer::new`), texture, one draw, read-back,
/// verdict. A fragment of C, not a program of its own.
const MAIN: &str = include_str!("main.c");

/// The verdict of the observation against the expectation's constants (`judge`), shared with the
/// Vulkan program. A fragment of C.
pub(super) const VERDICT: &str = include_str!("verdict.c");

#[cfg(test)]
#[path = "csource_tests.rs"]
mod tests;
