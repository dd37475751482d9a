//! The GL reproducers of the backends that open any EGL 1.4 library as the GL worker does
//! (`gl/src/egl.rs`): SwiftShader's own GLES (`egl:swiftshader:*`, the library fetched by
//! `sh gl/fetch-swiftshader.sh`), the system's libEGL as it is (`egl:native:*`) and another
//! vendor's libEGL in a directory (`egl@<dir>:<driver>:<api>`).
//!
//! The program's `make_context` makes the worker's choice at run time: the surfaceless platform
//! (`EGL_MESA_platform_surfaceless` through `eglGetPlatformDisplayEXT`) where the library offers it
//! and has configless and surfaceless contexts, else EGL 1.4's default display, a config with
//! `EGL_PBUFFER_BIT` and a 16x16 pbuffer made current with the context; `SHADOWCHECK_EGL_PBUFFER=1`
//! forces the pbuffer path, as it does for the worker. The context attributes are the worker's
//! (`egl::context_attributes`): the versions highest first with EGL 1.5 or
//! `EGL_KHR_create_context`, else EGL 1.4's client version only.
//!
//! build.sh links the program against the library's directory (`-L` and an rpath) and runs it with
//! `LD_LIBRARY_PATH` there, as the runner starts the worker (`libdir::lib_dir_env`), so that the
//! library binds its own libGLESv2; SwiftShader's directory is written as the fetch script's
//! default (`$SHADOWCHECK_SWIFTSHADER_DIR`, else the cache directory), not as a path of this machine.

use shadowcheck_gl::{BackendName, ContextApi, Driver};
use std::path::Path;

/// Does this backend open its EGL library as the worker's EGL 1.4 path does?
pub fn applies(b: BackendName, lib_dir: Option<&Path>) -> bool {
    lib_dir.is_some() || matches!(b.driver, Driver::Swiftshader | Driver::Native)
}

/// A shell word quoted for sh.
fn sh_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', "'\\''"))
}

/// The build.sh line that sets `dir` (the library's directory) and checks it holds a libEGL, or
/// `None` for the system's library (`egl:native:*`).
pub fn dir_line(b: BackendName, lib_dir: Option<&Path>) -> Option<String> {
    let (value, hint) = match lib_dir {
        Some(d) => (
            format!(
                "${{SHADOWCHECK_EGL_DIR:-{}}}",
                sh_quote(&d.display().to_string())
            ),
            "name a directory holding libEGL.so or libEGL.so.1 in SHADOWCHECK_EGL_DIR".to_string(),
        ),
        None if b.driver == Driver::Swiftshader => (
            "${SHADOWCHECK_SWIFTSHADER_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/swiftshader-4.0.0.3}"
                .to_string(),
            format!(
                "run '{}' in shadowcheck's source tree",
                shadowcheck_gl::libdir::SWIFTSHADER_FETCH
            ),
        ),
        None => return None,
    };
    Some(format!(
        "dir={value}\n[ -f \"$dir/libEGL.so\" ] || [ -f \"$dir/libEGL.so.1\" ] || {{ echo \"setup failed: no libEGL.so in $dir: {hint}\" >&2; exit 2; }}\n"
    ))
}

/// The build command: linked against the library's directory where there is one.
pub fn build_line(b: BackendName, lib_dir: Option<&Path>) -> String {
    let gl = if b.api.is_es() { "-lGLESv2" } else { "-lGL" };
    match dir_line(b, lib_dir) {
        Some(_) => format!(
            "cc -std=c99 -O1 -Wall -o repro repro.c -L\"$dir\" -Wl,-rpath,\"$dir\" -lEGL {gl} -lm"
        ),
        None => format!("cc -std=c99 -O1 -Wall -o repro repro.c -lEGL {gl} -lm"),
    }
}

/// The run environment, as `NAME=value` words for `env` (the library's directory first on the
/// loader's path).
pub fn env_words(b: BackendName, lib_dir: Option<&Path>) -> String {
    match dir_line(b, lib_dir) {
        Some(_) => "LD_LIBRARY_PATH=\"$dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}\"".into(),
        None => String::new(),
    }
}

/// The context's words for the program's header.
pub fn context_words(b: BackendName) -> String {
    let api = match b.api {
        ContextApi::Core => "desktop GL core profile",
        ContextApi::Compat => "desktop GL compatibility profile",
        ContextApi::Es3 | ContextApi::Es2 => "OpenGL ES",
    };
    format!(
        "any EGL 1.4 or later library, as the GL worker opens it (surfaceless where offered, else an EGL 1.4 pbuffer), {api}, highest version first"
    )
}

/// `die`, `check` and `make_context` for the EGL 1.4 path (the lookup programs' and the state
/// programs' context).
pub fn context_fn(b: BackendName) -> String {
    let vs: Vec<String> = shadowcheck_gl::egl::versions(b.api)
        .iter()
        .map(|(a, c)| format!("{{{a}, {c}}}"))
        .collect();
    let (bind, profile, client, bits) = match b.api {
        ContextApi::Core => (
            "EGL_OPENGL_API",
            "EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, ",
            0,
            "EGL_OPENGL_BIT, EGL_OPENGL_BIT",
        ),
        ContextApi::Compat => (
            "EGL_OPENGL_API",
            "EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, ",
            0,
            "EGL_OPENGL_BIT, EGL_OPENGL_BIT",
        ),
        ContextApi::Es3 => (
            "EGL_OPENGL_ES_API",
            "",
            3,
            "0x40 /* EGL_OPENGL_ES3_BIT */, EGL_OPENGL_ES2_BIT",
        ),
        ContextApi::Es2 => (
            "EGL_OPENGL_ES_API",
            "",
            2,
            "EGL_OPENGL_ES2_BIT, EGL_OPENGL_ES2_BIT",
        ),
    };
    format!(
        r#"static void die(const char *what) {{
    fprintf(stderr, "setup failed: %s\n", what);
    exit(2);
}}

static void check(const char *what) {{
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {{
        fprintf(stderr, "setup failed: %s raised GL error 0x%04X\n", what, e);
        exit(2);
    }}
}}

static int has_ext(const char *list, const char *ext) {{
    size_t n = strlen(ext);
    for (const char *p = list; p && (p = strstr(p, ext)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
    return 0;
}}

/* The context, as shadowcheck's worker opens any EGL 1.4 library (gl/src/egl.rs): surfaceless
 * where the library offers it, else the default display and a 16x16 pbuffer. */
static void make_context(void) {{
    const char *force = getenv("SHADOWCHECK_EGL_PBUFFER");
    int forced = force && strcmp(force, "1") == 0;
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS); /* NULL without EGL_EXT_client_extensions */
    EGLDisplay dpy = EGL_NO_DISPLAY;
    typedef EGLDisplay (*get_platform_display_fn)(EGLenum, void *, const EGLint *);
    get_platform_display_fn gpd = (get_platform_display_fn)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!forced && has_ext(client, "EGL_MESA_platform_surfaceless") && gpd)
        dpy = gpd(0x31DD /* EGL_PLATFORM_SURFACELESS_MESA */, EGL_DEFAULT_DISPLAY, NULL);
    else
        dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) die("eglInitialize");
    const char *exts = eglQueryString(dpy, EGL_EXTENSIONS);
    int create_context = major > 1 || (major == 1 && minor >= 5) || has_ext(exts, "EGL_KHR_create_context");
    int surfaceless = !forced && (has_ext(exts, "EGL_KHR_no_config_context") || has_ext(exts, "EGL_MESA_configless_context")) &&
                      has_ext(exts, "EGL_KHR_surfaceless_context");
    printf("egl:       EGL %d.%d, %s\n", major, minor, surfaceless ? "surfaceless" : "pbuffer");
    if (!eglBindAPI({bind})) die("eglBindAPI");
    EGLConfig config = (EGLConfig)0; /* EGL_NO_CONFIG_KHR */
    EGLSurface surface = EGL_NO_SURFACE;
    if (!surfaceless) {{
        /* A config for a pbuffer of the context's API (the ES 3 bit where the library knows it). */
        const EGLint bits[2] = {{{bits}}};
        int found = 0;
        for (int i = create_context ? 0 : 1; i < 2 && !found; i++) {{
            const EGLint attrs[] = {{EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, bits[i], EGL_NONE}};
            EGLint n = 0;
            found = eglChooseConfig(dpy, attrs, &config, 1, &n) && n > 0;
        }}
        if (!found) die("eglChooseConfig: no pbuffer config renders this API");
        const EGLint size[] = {{EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE}};
        surface = eglCreatePbufferSurface(dpy, config, size);
        if (surface == EGL_NO_SURFACE) die("eglCreatePbufferSurface (EGL_BAD_ALLOC: is LD_LIBRARY_PATH at the library's directory?)");
    }}
    if (create_context) {{
        static const int versions[][2] = {{{vs}}};
        for (unsigned i = 0; i < sizeof versions / sizeof versions[0]; i++) {{
            const EGLint attrs[] = {{0x3098 /* EGL_CONTEXT_MAJOR_VERSION */, versions[i][0], 0x30FB /* EGL_CONTEXT_MINOR_VERSION */, versions[i][1], {profile}EGL_NONE}};
            EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, attrs);
            if (ctx == EGL_NO_CONTEXT) continue;
            if (!eglMakeCurrent(dpy, surface, surface, ctx)) die("eglMakeCurrent");
            printf("context:   asked for %d.%d\n", versions[i][0], versions[i][1]);
            return;
        }}
        die("eglCreateContext: no version of this context kind");
    }}
    /* EGL 1.4: EGL_CONTEXT_CLIENT_VERSION (ES, major version only); nothing for desktop GL. */
    const EGLint es[] = {{0x3098 /* EGL_CONTEXT_CLIENT_VERSION */, {client}, EGL_NONE}};
    const EGLint none[] = {{EGL_NONE}};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, {client} ? es : none);
    if (ctx == EGL_NO_CONTEXT) die("eglCreateContext (EGL 1.4)");
    if (!eglMakeCurrent(dpy, surface, surface, ctx)) die("eglMakeCurrent");
    printf("context:   asked for client version %d\n", {client});
}}

"#,
        vs = vs.join(", "),
    )
}
