//! The GL worker: creates the context for one backend, declares what this context can check (its
//! hello), then draws each batch of cases; the protocol loop around it is
//! [`shadowcheck_plan::serve`].

use super::context::GlContext;
use super::legacy::Legacy;
use super::names::{BackendName, ContextApi};
use super::renderer::Renderer;
use super::WorkerError;
use shadowcheck_model::{ApiPath, Case, Format, Spec, StateCase};
use shadowcheck_plan::serve::{state_reply, Serve};
use shadowcheck_plan::{sweep, units, Answer, GlInfo};

use super::stats::WorkerStats;
use shadowcheck_protocol::{
    Capabilities, Hello, PathSkip, Reply, Support, FEATURES, PROTOCOL_VERSION,
};
use std::ffi::c_void;

/// Extensions reported in the handshake (those that matter for depth comparison). The runner judges
/// state cases by them: GL_ARB_shadow_ambient, GL_SGIX_shadow and GL_SGIX_shadow_ambient add
/// TexParameter pnames GL 4.6 lacks (`shadowcheck_oracle::state::PNAME_EXTENSIONS`), so a context
/// that lists one is held to the extension's rules for them instead of INVALID_ENUM.
const RELEVANT_EXTENSIONS: &[&str] = &[
    "GL_ARB_depth_texture",
    "GL_ARB_shadow",
    "GL_ARB_shadow_ambient",
    "GL_EXT_shadow_funcs",
    "GL_SGIX_shadow",
    "GL_SGIX_shadow_ambient",
    "GL_SGIX_depth_texture",
    "GL_ARB_fragment_program",
    "GL_ARB_fragment_program_shadow",
    "GL_EXT_shadow_samplers",
    "GL_OES_depth_texture",
    "GL_ARB_depth_buffer_float",
    "GL_ARB_texture_rectangle",
    "GL_ARB_texture_cube_map_array",
    "GL_OES_texture_cube_map_array",
    "GL_EXT_texture_cube_map_array",
    "GL_EXT_texture_shadow_lod",
    "GL_ARB_stencil_texturing",
    "GL_ARB_texture_mirror_clamp_to_edge",
    "GL_EXT_texture_mirror_clamp_to_edge",
    "GL_EXT_color_buffer_float",
];

/// Environment variable setting the most sampler states one program samples
/// (`shadowcheck_plan::units`; `run --states-per-program`), below the context's
/// MAX_TEXTURE_IMAGE_UNITS; unset: [`units::DEFAULT_STATES_PER_PROGRAM`].
pub const STATES_PER_PROGRAM_ENV: &str = "SHADOWCHECK_STATES_PER_PROGRAM";

/// The sampler states per program asked for through [`STATES_PER_PROGRAM_ENV`], or the default.
pub fn states_per_program_asked() -> Result<usize, WorkerError> {
    match std::env::var(STATES_PER_PROGRAM_ENV) {
        Err(_) => Ok(units::DEFAULT_STATES_PER_PROGRAM),
        Ok(v) => match v.trim().parse::<usize>() {
            Ok(k) if k >= 1 => Ok(k),
            _ => Err(WorkerError::BadStatesPerProgram {
                var: STATES_PER_PROGRAM_ENV,
                value: v,
            }),
        },
    }
}

/// A live worker: context, GL and renderer.
pub struct Worker {
    pub name: BackendName,
    renderer: Renderer,
    /// What this context runs, declared in the hello and applied to every case received.
    caps: Capabilities,
    ctx: GlContext,
}

fn parse_version(s: &str) -> (u32, u32) {
    let v = s
        .trim_start_matches("OpenGL ES GLSL ES ")
        .trim_start_matches("OpenGL ES ");
    let num = v.split_whitespace().next().unwrap_or("0.0");
    let mut it = num.split('.');
    let major = it.next().and_then(|x| x.parse().ok()).unwrap_or(0);
    let minor = it
        .next()
        .map(|x| {
            x.chars()
                .take_while(|c| c.is_ascii_digit())
                .collect::<String>()
        })
        .and_then(|x| x.parse().ok())
        .unwrap_or(0);
    (major, minor)
}

impl Worker {
    /// Creates the context (driver env vars must already be set) and checks the driver is the one
    /// asked for.
    pub fn start(name: BackendName) -> Result<Worker, WorkerError> {
        let ctx = GlContext::create(name)?;
        let loader = |s: &str| ctx.get_proc(s);
        // glow panics on a missing GL_VERSION; check first.
        let get_string = loader("glGetString");
        if get_string.is_null() {
            return Err(WorkerError::MissingEntryPoint("glGetString".into()));
        }
        type FnGetString = unsafe extern "system" fn(u32) -> *const u8;
        // SAFETY: glGetString has this signature; the context is current.
        let gs: FnGetString =
            unsafe { std::mem::transmute::<*const c_void, FnGetString>(get_string) };
        // SAFETY: GL_VERSION is a valid enum; the result is null or a NUL-terminated string.
        let v = unsafe { gs(glow::VERSION) };
        if v.is_null() {
            return Err(WorkerError::ContextFailed(
                "glGetString(GL_VERSION) returned NULL".into(),
            ));
        }
        // SAFETY: the context is current and the loader returns its entry points.
        let gl = unsafe { glow::Context::from_loader_function(|s| loader(s)) };
        use glow::HasContext;
        // SAFETY: context current.
        let (renderer, version_string, glsl_string) = unsafe {
            (
                gl.get_parameter_string(glow::RENDERER),
                gl.get_parameter_string(glow::VERSION),
                gl.get_parameter_string(glow::SHADING_LANGUAGE_VERSION),
            )
        };
        if !name.driver.renderer_matches(&renderer) {
            return Err(WorkerError::WrongDriver {
                wanted: name.driver.key().into(),
                renderer,
            });
        }
        let (gmaj, gmin) = parse_version(&glsl_string);
        let info = GlInfo {
            api: name.api,
            es: name.api.is_es(),
            compat: name.api == ContextApi::Compat,
            version: parse_version(&version_string),
            glsl: gmaj * 100 + gmin,
            renderer,
            version_string,
            extensions: gl.supported_extensions().clone(),
            form: name.form,
            // The driver's environment ([`BackendName::env`]) or the user's.
            version_override: ["MESA_GL_VERSION_OVERRIDE", "MESA_GLES_VERSION_OVERRIDE"]
                .iter()
                .any(|k| std::env::var_os(k).is_some()),
        };
        let legacy = if info.compat {
            Some(Legacy::load(&loader, info.arbfp_shadow())?)
        } else {
            None
        };
        let asked = states_per_program_asked()?;
        // SAFETY: context current for the worker's life (it owns the context).
        let renderer = unsafe { Renderer::new(gl, info, legacy)? };
        let mut w = Worker {
            name,
            renderer,
            caps: Capabilities::default(),
            ctx,
        };
        w.caps = w.declared_capabilities();
        // A program samples one state per texture unit: at most the fragment stage's units
        // (MAX_TEXTURE_IMAGE_UNITS, also ARB_fragment_program's limit).
        w.set_states_per_program(asked);
        Ok(w)
    }

    /// Runs a state case (observes; the runner judges). Paths of another context kind or a
    /// target the context lacks are skipped with the reason.
    pub fn run_state(&mut self, case: &StateCase) -> Reply {
        let unexposed = self.unexposed(case.spec);
        let gl = &self.renderer.gl;
        // SAFETY: the worker's context is current on this thread.
        state_reply(&self.caps, unexposed, case, |c| unsafe {
            super::state::observe(gl, c)
        })
    }
    pub fn info(&self) -> &GlInfo {
        &self.renderer.info
    }

    /// The renderer: what it has drawn and compiled ([`Renderer::stats`]).
    pub fn renderer(&self) -> &Renderer {
        &self.renderer
    }

    /// What this worker has compiled and drawn so far.
    pub fn stats(&self) -> WorkerStats {
        let r = &self.renderer;
        WorkerStats {
            states_per_program: r.states_per_program(),
            programs: r.programs_compiled(),
            states: r.stats().states,
            sets: r.stats().state_sets,
            units: r.stats().units,
        }
    }

    /// Sampler states one program samples at most from now on, below the context's texture
    /// units (1: one state per program).
    pub fn set_states_per_program(&mut self, k: usize) {
        // SAFETY: the worker's context is current on this thread.
        let max = unsafe {
            use glow::HasContext;
            self.renderer
                .gl
                .get_parameter_i32(glow::MAX_TEXTURE_IMAGE_UNITS)
        };
        self.renderer
            .set_states_per_program(k.min(max.max(1) as usize));
    }

    /// The specs this context can check (only what the driver exposes).
    pub fn specs(&self) -> Vec<Spec> {
        let i = self.info();
        match i.api {
            ContextApi::Core => vec![Spec::Gl46],
            ContextApi::Compat => {
                let mut v = vec![Spec::Gl46];
                if i.has_ext("GL_ARB_shadow") {
                    v.push(Spec::Arb);
                }
                if i.has_ext("GL_ARB_shadow") && i.has_ext("GL_ARB_shadow_ambient") {
                    v.push(Spec::ArbAmbient);
                }
                if i.has_ext("GL_ARB_shadow") && i.has_ext("GL_EXT_shadow_funcs") {
                    v.push(Spec::ExtFuncs);
                }
                v
            }
            ContextApi::Es3 => vec![Spec::Gles32],
            ContextApi::Es2 => {
                if i.shadow_samplers_es2() {
                    vec![Spec::Es2Ext]
                } else {
                    vec![]
                }
            }
        }
    }

    /// Why no case can run on this context, when the driver exposes none of the specs its kind
    /// implements; `None` when at least one can run.
    pub fn runs_nothing(&self) -> Option<String> {
        if !self.specs().is_empty() {
            return None;
        }
        let mut why: Vec<String> = implemented_specs(self.info().api)
            .into_iter()
            .filter_map(|s| self.unexposed(s))
            .collect();
        why.dedup();
        Some(why.join("; "))
    }

    pub fn formats(&self) -> Vec<Format> {
        formats(self.info())
    }

    /// Why a case of `spec` cannot run on this context although it implements the spec (the
    /// driver does not expose what it needs); `None` when it can.
    fn unexposed(&self, spec: Spec) -> Option<String> {
        if self.specs().contains(&spec) {
            return None;
        }
        Some(
            match spec {
                Spec::Arb => "GL_ARB_shadow not exposed",
                Spec::ArbAmbient => "GL_ARB_shadow or GL_ARB_shadow_ambient not exposed",
                Spec::ExtFuncs => "GL_ARB_shadow or GL_EXT_shadow_funcs not exposed",
                Spec::Es2Ext => "GL_EXT_shadow_samplers not exposed",
                _ => "not available on this context",
            }
            .to_string(),
        )
    }

    /// Why API path `api` of this context cannot run here (an extension or GLSL version the
    /// driver lacks); `None` when it can.
    fn unavailable(&self, api: ApiPath) -> Option<String> {
        if self.info().paths().contains(&api) {
            return None;
        }
        Some(
            match api {
                ApiPath::ArbFp => {
                    "GL_ARB_fragment_program or GL_ARB_fragment_program_shadow not exposed"
                }
                ApiPath::Glsl130 => "GLSL 1.30 not supported",
                ApiPath::Es100Ext => "GL_EXT_shadow_samplers not exposed",
                _ => "not available on this context",
            }
            .to_string(),
        )
    }

    /// What this context can run (declared in the hello).
    pub fn capabilities(&self) -> &Capabilities {
        &self.caps
    }

    fn declared_capabilities(&self) -> Capabilities {
        declared_capabilities(self.info())
    }

    /// The implementation's name for the handshake, e.g. `egl:llvmpipe:core (4.5 (Core Profile) Mesa 22.3.6; llvmpipe ...)`.
    /// An EGL 1.4 pbuffer context says so: `...; EGL pbuffer)`.
    pub fn display_name(&self) -> String {
        let pbuffer = if self.ctx.egl_mode() == Some(super::egl::SurfaceMode::Pbuffer) {
            "; EGL pbuffer"
        } else {
            ""
        };
        format!(
            "{} ({}; {}{pbuffer})",
            self.name,
            self.info().version_string,
            self.info().renderer
        )
    }

    /// Whether a case runs here: the declared capabilities decide, by the same
    /// [`Capabilities::support`] the runner applies before sending (so a case the runner sends is
    /// never refused here); the case is valid (checked where it was read, [`serve`]). `Ok` holds
    /// the API paths to draw (the supported ones) and the paths left out, each with the reason.
    fn admit(&self, case: &Case) -> Result<(Vec<ApiPath>, Vec<PathSkip>), String> {
        let (apis, others) = match self.caps.support(case) {
            Support::Skip(reason) | Support::NotApplicable(reason) => return Err(reason),
            Support::Run { apis, others } => (apis, others),
        };
        if let Some(reason) = self.unexposed(case.spec) {
            return Err(reason);
        }
        let mut missing: Vec<PathSkip> = vec![];
        let apis: Vec<ApiPath> = apis
            .into_iter()
            .filter(|a| match self.unavailable(*a) {
                Some(reason) => {
                    missing.push(PathSkip {
                        api: a.key().to_string(),
                        reason,
                    });
                    false
                }
                None => true,
            })
            .collect();
        if apis.is_empty() {
            let why: Vec<String> = missing
                .iter()
                .map(|m| format!("{}: {}", m.api, m.reason))
                .collect();
            return Err(why.join("; "));
        }
        let unavailable: Vec<String> = missing.iter().map(|m| m.api.clone()).collect();
        let left_out = case
            .api
            .iter()
            .filter(|a| !apis.contains(a) && !unavailable.iter().any(|m| m == a.key()))
            .map(|a| PathSkip {
                api: a.key().to_string(),
                reason: others.clone().unwrap_or_default(),
            })
            .chain(missing)
            .collect();
        Ok((apis, left_out))
    }

    /// Answers a batch in order: one answer per lookup, each case's own and then each point of its
    /// sweep ([`super::sweep::jobs`]). The cases must be valid (`validate`): [`serve`] checks each
    /// case once, with its sweep, where it is read.
    pub fn draw_cases(&mut self, cases: Vec<Case>) -> Vec<Answer> {
        let mut answers: Vec<Option<Answer>> = Vec::with_capacity(cases.len());
        let mut runnable: Vec<Case> = Vec::with_capacity(cases.len());
        let mut left_out: Vec<Vec<PathSkip>> = Vec::with_capacity(cases.len());
        for mut c in cases {
            match self.admit(&c) {
                Ok((apis, skips)) => {
                    c.api = apis;
                    answers.extend((0..c.lookup_count()).map(|_| None));
                    runnable.push(c);
                    left_out.push(skips);
                }
                Err(reason) => answers
                    .extend((0..c.lookup_count()).map(|_| Some(Answer::Skip(reason.clone())))),
            }
        }
        let jobs = sweep::jobs(&runnable);
        // SAFETY: the worker's context is current on this thread.
        let mut drawn_jobs = unsafe { self.renderer.draw_jobs(&jobs) }.into_iter();
        // The paths left out of a case are part of the answer for its own lookup.
        let mut drawn = runnable.iter().zip(left_out).flat_map(|(c, skips)| {
            let own = drawn_jobs.next().map(|answer| match answer {
                Answer::Observation(results, mut skipped) => {
                    skipped.extend(skips);
                    Answer::Observation(results, skipped)
                }
                other => other,
            });
            let points: Vec<Option<Answer>> =
                (0..c.sweep.len()).map(|_| drawn_jobs.next()).collect();
            std::iter::once(own).chain(points)
        });
        for a in answers.iter_mut() {
            if a.is_none() {
                *a = drawn.next().flatten();
            }
        }
        answers
            .into_iter()
            .map(|a| a.unwrap_or_else(|| Answer::Error("internal: missing answer".into())))
            .collect()
    }
}

fn formats(i: &GlInfo) -> Vec<Format> {
    Format::ALL
        .iter()
        .copied()
        .filter(|f| !(i.es && *f == Format::D32))
        .collect()
}

/// The specs a kind of context implements, exposed or not: a case of another spec is no test of
/// it (not applicable); one of these whose extension the driver lacks is Skip with the extension
/// named ([`Worker::unexposed`]).
fn implemented_specs(api: ContextApi) -> Vec<Spec> {
    match api {
        ContextApi::Core => vec![Spec::Gl46],
        ContextApi::Compat => vec![Spec::Gl46, Spec::Arb, Spec::ArbAmbient, Spec::ExtFuncs],
        ContextApi::Es3 => vec![Spec::Gles32],
        ContextApi::Es2 => vec![Spec::Es2Ext],
    }
}

/// What a context described by `info` runs (declared in the hello): the spec and API paths its
/// kind implements, the targets, formats and sampler features the driver exposes.
pub fn declared_capabilities(i: &GlInfo) -> Capabilities {
    Capabilities {
        // What the context type implements: the runner counts other specs and paths as not
        // applicable; what the driver does not expose is Skip with its reason (`admit`).
        specs: Some(
            implemented_specs(i.api)
                .iter()
                .map(|s| s.key().to_string())
                .collect(),
        ),
        api: Some(i.api.paths().iter().map(|p| p.key().to_string()).collect()),
        targets: Some(i.targets().iter().map(|t| t.key().to_string()).collect()),
        formats: Some(formats(i).iter().map(|f| f.key().to_string()).collect()),
        features: Some(
            FEATURES
                .iter()
                .filter(|f| match f.key {
                    // ES 3.2 §8.10: no TEXTURE_LOD_BIAS texture parameter.
                    "lod_bias" => !i.es,
                    "fail_value" => i.has_ext("GL_ARB_shadow_ambient"),
                    "border_clamp" => i.border_clamp(),
                    "stencil_texturing" => i.stencil_texturing(),
                    "gather" => i.gather(),
                    // TexParameter / GetTexParameter exist in every context.
                    "tex_parameter" => true,
                    "swizzle" => i.swizzle(),
                    "seamless_toggle" => i.seamless_toggle(),
                    "sampler_objects" => i.sampler_objects(),
                    _ => false,
                })
                .map(|f| f.key.to_string())
                .collect(),
        ),
        extensions: RELEVANT_EXTENSIONS
            .iter()
            .filter(|e| i.has_ext(e))
            .map(|e| e.to_string())
            .collect(),
    }
}

impl Serve for Worker {
    fn hello(&self) -> Hello {
        Hello {
            sweeps: false,
            protocol: PROTOCOL_VERSION,
            name: Some(self.display_name()),
            capabilities: self.capabilities().clone(),
            wants_expect: false,
        }
    }
    fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
        Ok(Worker::draw_cases(self, cases))
    }
    fn run_state(&mut self, case: &StateCase) -> Reply {
        Worker::run_state(self, case)
    }
}

/// `--probe`: create the context and print `ok ...` or `unavailable: reason` on stdout.
/// The probe's one line: `ok <name>`; `nothing: <reason>` for a context that starts but exposes
/// none of the specs its kind implements (an ES 2.0 context without GL_EXT_shadow_samplers: every
/// case it would be sent is a Skip); `unavailable: <reason>` for one that does not start.
pub fn probe_line(name: BackendName) -> (bool, String) {
    match Worker::start(name) {
        Ok(w) => match w.runs_nothing() {
            Some(why) => (true, format!("nothing: {why}")),
            None => (true, format!("ok {}", w.display_name())),
        },
        Err(e) => (false, format!("unavailable: {e}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn versions_parse_from_desktop_and_es_strings() {
        assert_eq!(parse_version("4.5 (Core Profile) Mesa 22.3.6"), (4, 5));
        assert_eq!(parse_version("OpenGL ES 3.2 Mesa 22.3.6"), (3, 2));
        assert_eq!(parse_version("OpenGL ES GLSL ES 3.20"), (3, 20));
        assert_eq!(parse_version("4.50"), (4, 50));
    }

    #[test]
    fn the_hello_reports_every_extension_a_state_expectation_depends_on() {
        for ext in shadowcheck_oracle::state::PNAME_EXTENSIONS {
            assert!(RELEVANT_EXTENSIONS.contains(&ext.name), "{}", ext.name);
        }
    }
}

#[cfg(test)]
#[path = "gating_tests.rs"]
mod gating_tests;
