//! The WebGL 2.0 reproducer of a `webgl:*` test: `repro.html`, a plain WebGL 2.0 page with no
//! shadowcheck code, that does for one case what the WebGL worker (shadowcheck-webgl, `job.rs` and
//! `page.js`) does for it, and `build.sh`, which runs it in headless Chromium with the instance's
//! flags and environment (`webgl/src/instance.rs`: which ANGLE back end over which driver) and
//! prints what the page wrote (nothing is built: the page is the program).
//!
//! What it mirrors, and from where (the plan, shadowcheck-plan, as the worker and the C programs
//! draw it): the worker's context (`GlInfo` of WebGL 2.0: OpenGL ES 3.0, GLSL ES 3.00), the
//! lookup of the es300 path (`paths::plan_for`), the program text (`shaders::glsl`), the bytes of
//! every level (`texels::level_bytes` with `transfer_for`'s format and type), the TexParameter calls
//! in their order (`unit::tex_params`) and a sampler object's (`unit::sampler_params`), the
//! extensions the page enables (EXT_color_buffer_float, WEBGL_stencil_texturing), and the renderer
//! the instance must show (a browser that fell back to another implementation is a setup failure,
//! as it is for the worker). One difference, as in the C programs: the worker draws up to 16
//! sampler states with one program (`units::plan_batch`: state i on unit i, a pixel per case in a
//! 256x256 target); the page draws the one state on unit 0 with the single-unit program, into a 1x1
//! viewport of an RGBA32F target cleared to -1.

use super::{io, webgpu, ReproError, Subject, BUILD_SH};
use shadowcheck_model::{ApiPath, Stage};
use shadowcheck_plan::texels::{level_bytes, transfer_for};
use shadowcheck_plan::unit::{sampler_params, tex_params, ParamValue, TexParam};
use shadowcheck_plan::{gl, paths, shaders, ContextApi, GlInfo, LookupForm};
use shadowcheck_webgl::instance::Instance;
use std::fmt::Write;
use std::path::Path;

/// The `key: value` lines the page prints about the implementation (`RunOutput::field`).
pub const FIELDS: [&str; 3] = ["WEBGL_RENDERER", "WEBGL_VERSION", "BROWSER"];

/// What "building" is: nothing; the run line is build.sh's.
pub const BUILD_LINE: &str = "nothing to build: repro.html is the program";

/// The instance of a `webgl:<key>` backend.
pub fn instance(key: &str) -> Result<&'static Instance, ReproError> {
    shadowcheck_webgl::instance::instance(key).map_err(|e| ReproError::BadBackend(e.to_string()))
}

/// Is the browser (and the instance's driver) installed?
pub fn check_installed(key: &str) -> Result<(), ReproError> {
    instance(key)?
        .installed()
        .map_err(|e| ReproError::BadBackend(e.to_string()))
}

/// The Debian packages: none to build, the instance's to run.
pub fn packages(key: &str) -> (String, String) {
    let run = instance(key).map_or("chromium", |i| {
        i.install.trim_start_matches("apt-get install -y ")
    });
    (String::new(), run.to_string())
}

/// The GL context the worker plans for: WebGL 2.0 (`WebglWorker::start`).
fn webgl_info() -> GlInfo {
    GlInfo {
        api: ContextApi::Es3,
        es: true,
        compat: false,
        version: (3, 0),
        glsl: 300,
        renderer: String::new(),
        version_string: String::new(),
        extensions: Default::default(),
        version_override: false,
        form: LookupForm::Auto,
    }
}

/// The run script: headless Chromium with the instance's flags and environment.
pub fn run_script(s: &Subject, key: &str) -> String {
    script(&s.test(), key)
}

/// [`run_script`] of a test (a lookup or a state case) on `webgl:<key>`.
pub fn script(test: &str, key: &str) -> String {
    let launch = instance(key).map(|i| (i.launch)()).unwrap_or_default();
    webgpu::browser_script(test, &format!("webgl:{key}"), &launch.flags, &launch.env)
}

/// Writes repro.html and build.sh into `dir` (created).
pub fn write_sources(s: &Subject, key: &str, dir: &Path) -> Result<(), ReproError> {
    let page = page(s, key).map_err(ReproError::NotPlanned)?;
    std::fs::create_dir_all(dir).map_err(io(format!("creating {}", dir.display())))?;
    for (name, text) in [(webgpu::REPRO_HTML, page), (BUILD_SH, run_script(s, key))] {
        std::fs::write(dir.join(name), text).map_err(io(format!("writing {name}")))?;
    }
    Ok(())
}

/// The typed array WebGL 2.0 takes for a pixel type, and the values of `bytes` in it.
fn typed(ty: u32, bytes: &[u8]) -> Result<(&'static str, Vec<String>), String> {
    let words = |n: usize| bytes.chunks_exact(n);
    Ok(match ty {
        gl::UNSIGNED_BYTE => ("Uint8Array", bytes.iter().map(|b| b.to_string()).collect()),
        gl::UNSIGNED_SHORT => (
            "Uint16Array",
            words(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]).to_string())
                .collect(),
        ),
        gl::UNSIGNED_INT | gl::UNSIGNED_INT_24_8 => (
            "Uint32Array",
            words(4)
                .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]).to_string())
                .collect(),
        ),
        gl::FLOAT => (
            "Float32Array",
            words(4)
                .map(|c| webgpu::jf(f32::from_ne_bytes([c[0], c[1], c[2], c[3]])))
                .collect(),
        ),
        // As the worker's page (`view`): WebGL 2.0 takes no other array for these uploads.
        t => {
            return Err(format!(
            "no typed array for pixel type 0x{t:04X} (the WebGL worker answers this case an error)"
        ))
        }
    })
}

/// One TexParameter / SamplerParameter call as the page makes it.
fn param(p: &TexParam) -> Result<String, String> {
    let call = webgpu::js(&p.call());
    match p.value {
        ParamValue::Int(v) => Ok(format!(
            "{{ pname: 0x{:04X}, int: {v}, call: {call} }}",
            p.pname
        )),
        ParamValue::Float(v) => Ok(format!(
            "{{ pname: 0x{:04X}, float: {}, call: {call} }}",
            p.pname,
            webgpu::jf(v)
        )),
        ParamValue::Floats(_) => Err(format!(
            "{}: WebGL 2.0 has no vector TexParameter (the WebGL worker answers this case an error)",
            p.call()
        )),
    }
}

/// The page's text, or why the worker would not draw this case (it Skips it).
pub fn page(s: &Subject, key: &str) -> Result<String, String> {
    if s.api != ApiPath::Es300 {
        return Err(format!(
            "a WebGL 2.0 backend runs the `es300` path, not `{}`",
            s.api
        ));
    }
    let info = webgl_info();
    // The worker plans with the same context (`paths::plan_for`, `GlInfo::compute`): WebGL 2.0 is
    // OpenGL ES 3.0, whose shading language, GLSL ES 3.00, has no compute shaders (they come with
    // GLSL ES 3.10), so the worker skips a compute-stage case.
    if s.case.lookup.stage == Stage::Compute && !info.compute() {
        return Err("a compute-stage lookup (`lookup.stage`: compute) runs in a compute shader, and WebGL 2.0 has none (OpenGL ES 3.0, GLSL ES 3.00; compute shaders need ES 3.1, GLSL ES 3.10): the WebGL worker skips this case".into());
    }
    let inst = instance(key).map_err(|e| e.to_string())?;
    // The worker's admission (`WebglWorker::admit`): WebGL 2.0's capabilities, stencil texturing
    // assumed offered (the page checks it).
    let caps = shadowcheck_webgl::worker::capabilities(&["WEBGL_stencil_texturing".into()], &[]);
    match caps.support(&s.case) {
        shadowcheck_protocol::Support::Run { .. } => {}
        shadowcheck_protocol::Support::Skip(why)
        | shadowcheck_protocol::Support::NotApplicable(why) => {
            return Err(format!("the WebGL worker does not draw this case: {why}"))
        }
    }
    let plan = paths::plan_for(&info, ApiPath::Es300, &s.case, &s.case.lookup)?;
    let (vs, fs) = shaders::glsl(&info, &plan.key, None, 1);
    let t = &s.case.texture;
    let (ifmt, fmt, ty, bpt) = transfer_for(&s.case);
    let mut levels = String::new();
    for (i, lvl) in t.levels.iter().enumerate() {
        let bytes = level_bytes(t.format, lvl).map_err(|e| e.to_string())?;
        let (array, vals) = typed(ty, &bytes)?;
        let _ = writeln!(
            levels,
            "  {{ level: {}, width: {}, height: {}, layers: {}, data: new {array}([{}]) }},",
            t.base_level as usize + i,
            lvl.width,
            lvl.height,
            lvl.layers,
            vals.join(", ")
        );
    }
    let params: Vec<String> = tex_params(false, &s.case)
        .iter()
        .map(param)
        .collect::<Result<_, _>>()?;
    let sampler: Vec<String> = sampler_params(&s.case)
        .iter()
        .map(param)
        .collect::<Result<_, _>>()?;
    let upload = match t.target {
        shadowcheck_model::Target::Cube => "cube",
        shadowcheck_model::Target::T2dArray | shadowcheck_model::Target::CubeArray => "3d",
        _ => "2d",
    };
    let v4 = |v: [f32; 4]| {
        v.iter()
            .map(|x| webgpu::jf(*x))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let renderer: Vec<String> = inst.renderer.iter().map(|w| webgpu::js(w)).collect();
    Ok(format!(
        "<!doctype html>\n<meta charset=utf-8>\n<title>shadowcheck reproducer: {title}</title>\n<!--\n  shadowcheck reproducer: {test} on {backend} ({what})\n  Run: sh {BUILD_SH} (headless Chromium with the instance's flags and environment), or open this\n  file in a browser with WebGL 2.0.\n\n  Generated by `shadowcheck repro`: what shadowcheck's WebGL worker does for this test, with no\n  shadowcheck code. Context: WebGL 2.0 with EXT_color_buffer_float (and WEBGL_stencil_texturing\n  where offered), its renderer checked against the instance's. Texture: the integers the worker\n  uploads, the same TexParameter calls in the same order. Lookup: {how}; the worker's GLSL ES 3.00\n  program (single unit), drawn into a 1x1 viewport of an RGBA32F target cleared to -1.\n  Prints the renderer, the expected result (spec value and accepted set, computed by shadowcheck's\n  oracle, written here as constants) and the observed RGBA, then the verdict.\n-->\n<pre id=\"out\"></pre>\n<script>\n\"use strict\";\n{expect}// The renderer string (WEBGL_debug_renderer_info) must hold every word: the instance's ANGLE\n// back end and driver.\nconst INSTANCE = {inst_js};\nconst RENDERER_WORDS = [{renderer}];\n\n// The texture (plan/src/texels.rs, unit.rs): target, internal format, format and type of every\n// level's upload, the TexParameter calls in order, and a sampler object's calls (none: no sampler\n// object).\nconst TEXTURE = {{\n  target: 0x{target:04X},\n  upload: \"{upload}\",\n  ifmt: 0x{ifmt:04X},\n  fmt: 0x{fmt:04X},\n  type: 0x{ty:04X},\n  bpt: {bpt},\n  params: [{params}],\n  sampler: [{sampler}],\n}};\nconst LEVELS = [\n{levels}];\n\n// The worker's program for this lookup (plan/src/shaders/mod.rs) and its uniforms.\nconst VS = {vs};\nconst FS = {fs};\nconst LOOKUP = {{ p: [{p}], x: {x}, dx: [{dx}], dy: [{dy}], viewport: [{viewport}] }};\n\n{main}</script>\n",
        title = webgpu::html_escape(&s.test()),
        test = webgpu::html_escape(&s.test()).replace("--", "- -"),
        backend = s.backend,
        what = inst.what,
        how = plan.note,
        expect = webgpu::expectation(s),
        inst_js = webgpu::js(&format!("{} ({})", inst.name(), inst.what)),
        renderer = renderer.join(", "),
        target = t.target.gl(),
        params = params.join(", "),
        sampler = sampler.join(", "),
        vs = webgpu::js(&vs),
        fs = webgpu::js(&fs),
        p = v4(plan.p),
        x = webgpu::jf(plan.x),
        dx = v4(plan.dx),
        dy = v4(plan.dy),
        viewport = shadowcheck_plan::shaders::single_draw_viewport(&plan.key, (0, 0))
            .map(|v| v.to_string())
            .join(", "),
        main = MAIN,
    ))
}

/// Context, texture, program, one draw, read-back, verdict: the fixed part of the page.
const MAIN: &str = concat!(
    include_str!("page_verdict.js"),
    include_str!("webgl_main.js")
);

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2x2 D24 2D case, LEQUAL NEAREST, Dref 0.5.
    const CASE: &str = r#"{"id":"gles32/unit","spec":"gles32","api":["es300"],"texture":{"target":"2d","format":"d24","levels":[{"width":2,"height":2,"layers":1,"depth":{"unorm":[0,4194304,8388608,16777215]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0.0,0.0,0.0,0.0],"min_lod":-1000.0,"max_lod":1000.0,"lod_bias":0.0},"lookup":{"coord":[0.75,0.25,0.0,1.0],"dref":0.5}}"#;

    fn subject() -> Subject {
        let case: shadowcheck_model::Case = serde_json::from_str(CASE).expect("case");
        let expect = crate::verdict::oracle_evaluate(&case)
            .expect("the oracle evaluates the case")
            .expect;
        Subject {
            backend: super::super::Backend::Webgl("chromium-gles"),
            expect,
            case,
            api: ApiPath::Es300,
            steps: vec![],
            explain: String::new(),
            fixture: "f.json".into(),
            lib_dir: None,
        }
    }

    #[test]
    fn the_page_holds_the_workers_program_texels_and_calls() {
        let s = subject();
        let p = page(&s, "chromium-gles").expect("page");
        assert!(p.contains("#version 300 es"), "{p}");
        assert!(p.contains("sampler2DShadow"), "{p}");
        // D24 as UNSIGNED_INT (c << 8 | low byte), the compare mode set by name and number.
        assert!(p.contains("type: 0x1405"), "{p}");
        assert!(
            p.contains("width: 2, height: 2, layers: 1, data: new Uint32Array(["),
            "{p}"
        );
        assert!(p.contains("pname: 0x884C, int: 34894"), "{p}");
        assert!(p.contains("\"OpenGL ES\", \"llvmpipe\""), "{p}");
        let sh = run_script(&s, "chromium-gles");
        assert!(sh.contains("env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless \"$browser\""), "{sh}");
        assert!(sh.contains("--use-angle=gles-egl"), "{sh}");
        let mut es100 = s.clone();
        es100.api = ApiPath::Es100Ext;
        assert!(page(&es100, "chromium").unwrap_err().contains("es300"));
    }

    /// A compute-stage case is refused with the reason: WebGL 2.0 has no compute shaders.
    #[test]
    fn a_compute_stage_case_is_refused() {
        let mut s = subject();
        s.case.lookup.stage = Stage::Compute;
        let why = page(&s, "chromium-gles").expect_err("no page for a compute-stage case");
        assert!(
            why.contains("WebGL 2.0 has none") && why.contains("GLSL ES 3.10"),
            "{why}"
        );
    }
}
