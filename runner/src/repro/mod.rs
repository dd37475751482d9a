//! `shadowcheck repro`: from one failing test to a standalone reproducer and a bug report.
//!
//! For a Vulkan backend (`vk:*`) the program is [`vulkan`]'s (Vulkan C, with the SPIR-V built from
//! the GLSL files beside it); for a WebGPU backend (`webgpu:*`) it is [`webgpu`]'s page and for a
//! WebGL one (`webgl:*`) [`webgl`]'s (`repro.html`, run by build.sh in headless Chromium); the rest
//! below is the same. A compute-stage lookup is on the GL core and es300 paths only: WebGL 2.0
//! (GLSL ES 3.00) has no compute shaders, and the Vulkan and WGSL paths have no such case, so
//! those writers refuse it with the reason. For a GL backend (`egl:*`, `egl@<dir>:*`, `osmesa:*`; the EGL 1.4 ones through
//! [`egl14`]) and a test `<case id>@<api>` this writes into a directory:
//! - `repro.c` ([`csource`]; a TexParameter state case's from [`state`]): a C program that creates
//!   the worker's context, texture, sampler state and lookup (gathers included), draws once (a
//!   compute-stage lookup: dispatches one compute invocation, `compute.rs`), prints expected (from
//!   the oracle, as constants) and observed, and exits 1 when the observation is outside the
//!   accepted set;
//! - `build.sh`: the one-line build command (also at the top of repro.c) and the run line with the
//!   environment that picks the driver (the worker's, `BackendName::env`);
//! - `output.txt`: what the program printed when [`build_and_run`] ran it here;
//! - `REPORT.md` ([`report`]): a bug report, written only for a Fail (a "shall" violated).
//!
//! `--all-failures` groups the Fails of a results directory into classes ([`classes`]) and writes one
//! reproducer per class with an index.

mod cexpect;
pub mod classes;
mod compute;
pub mod csource;
pub mod egl14;
pub mod report;
mod reproducer;
pub mod state;
mod tokens;
pub mod vulkan;
pub mod webgl;
pub mod webgpu;

use shadowcheck_gl::{BackendName, Driver};
use shadowcheck_model::{ApiPath, Case, Expectation};
use std::path::{Path, PathBuf};
use std::process::Command;

use reproducer::state_subject;
pub use reproducer::{failing_test, Judgement, Reproducer};

#[derive(Debug, thiserror::Error)]
pub enum ReproError {
    #[error("bad test id `{0}`: expected `<case id>@<api>` with api one of ff, arbfp, glsl120, glsl130, core, es100, es300, vk, wgsl")]
    BadTestId(String),
    #[error("{0}")]
    BadBackend(String),
    #[error("case `{id}` not found in {fixtures}")]
    NoCase { id: String, fixtures: String },
    #[error("`{id}` is a TexParameter state case, not a lookup case: `repro::reproducer` writes its program ([`state`])")]
    StateCase { id: String },
    #[error("case `{id}` does not list API path `{api}` (it lists: {listed})")]
    NoPath {
        id: String,
        api: String,
        listed: String,
    },
    #[error("backend {backend} runs the API paths {paths}, not `{api}`")]
    PathNotOnBackend {
        backend: String,
        api: String,
        paths: String,
    },
    #[error("the oracle has no expectation for this case: {0}")]
    NoExpectation(String),
    #[error("the worker would not run this test: {0}")]
    NotPlanned(String),
    #[error("{what}: {source}")]
    Io {
        what: String,
        #[source]
        source: std::io::Error,
    },
    #[error(
        "building the reproducer failed (is gcc and the dev package installed? {packages}):\n{log}"
    )]
    Build { packages: String, log: String },
    #[error("building the reproducer failed: {missing}; `apt-get install -y {package}`:\n{log}")]
    Missing {
        missing: String,
        package: String,
        log: String,
    },
    #[error("the reproducer could not set up (exit {code}):\n{log}")]
    Setup { code: i32, log: String },
}

fn io(what: impl Into<String>) -> impl FnOnce(std::io::Error) -> ReproError {
    let what = what.into();
    move |source| ReproError::Io { what, source }
}

/// The backend a reproducer is written for: a GL one (EGL or OSMesa), a Vulkan driver, or WebGPU
/// in headless Chromium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Backend {
    Gl(BackendName),
    Vk(shadowcheck_vk::Driver),
    Webgpu(shadowcheck_webgpu::launch::Variant),
    /// A `webgl:<key>` instance (`webgl/src/instance.rs`), by its key.
    Webgl(&'static str),
}

impl std::fmt::Display for Backend {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Backend::Gl(b) => b.fmt(f),
            Backend::Vk(d) => write!(f, "vk:{}", d.key()),
            Backend::Webgpu(v) => f.write_str(&v.name()),
            Backend::Webgl(k) => write!(f, "webgl:{k}"),
        }
    }
}

impl std::str::FromStr for Backend {
    type Err = ReproError;
    /// `vk:<driver>` is a Vulkan backend, `webgpu:<variant>` a WebGPU one; anything else must be
    /// a GL backend name.
    fn from_str(s: &str) -> Result<Backend, ReproError> {
        if s.starts_with("webgpu:") {
            return shadowcheck_webgpu::launch::parse_backend(s)
                .map(Backend::Webgpu)
                .ok_or_else(|| {
                    ReproError::BadBackend(format!(
                        "unknown WebGPU backend `{s}` (expected webgpu:chromium or webgpu:chromium-compat)"
                    ))
                });
        }
        if let Some(key) = s.strip_prefix("webgl:") {
            return webgl::instance(key).map(|i| Backend::Webgl(i.key));
        }
        if s.starts_with("vk:") {
            return shadowcheck_vk::parse_backend(s)
                .map(Backend::Vk)
                .map_err(|e| ReproError::BadBackend(e.to_string()));
        }
        s.parse().map(Backend::Gl).map_err(|e: shadowcheck_gl::WorkerError| {
            ReproError::BadBackend(format!(
                "{e} (repro writes C programs for the GL backends egl:*, egl@DIR:* and osmesa:* and the Vulkan backends vk:*, and pages for the WebGPU backends webgpu:* and the WebGL backends webgl:*)"
            ))
        })
    }
}

impl Backend {
    /// The API paths the backend runs.
    fn paths(&self) -> &'static [ApiPath] {
        match self {
            Backend::Gl(b) => b.api.paths(),
            Backend::Vk(_) => &[ApiPath::Vulkan],
            Backend::Webgpu(_) => &[ApiPath::Wgsl],
            Backend::Webgl(_) => &[ApiPath::Es300],
        }
    }
}

/// One test on one backend, with the oracle's expectation.
#[derive(Debug, Clone)]
pub struct Subject {
    pub backend: Backend,
    pub case: Case,
    pub api: ApiPath,
    /// Evaluated by the oracle now (not read from the fixture).
    pub expect: Expectation,
    /// The oracle's derivation steps, each with the section (and sentence) it comes from.
    pub steps: Vec<shadowcheck_oracle::Step>,
    /// The oracle's derivation and footprint, as `shadowcheck explain` prints them.
    pub explain: String,
    /// The fixture file the case came from.
    pub fixture: PathBuf,
    /// The EGL library's directory of an `egl@<dir>:...` backend ([`egl14`]).
    pub lib_dir: Option<PathBuf>,
}

impl Subject {
    /// `<case id>@<api>`, the test's name in results and baselines.
    pub fn test(&self) -> String {
        crate::records::TestResult::name(&self.case.id, self.api)
    }
}

/// Splits `<case id>@<api>` at its last `@`.
pub fn parse_test_id(test: &str) -> Result<(String, ApiPath), ReproError> {
    let (id, api) = test
        .rsplit_once('@')
        .ok_or_else(|| ReproError::BadTestId(test.to_string()))?;
    let api = ApiPath::from_key(api).ok_or_else(|| ReproError::BadTestId(test.to_string()))?;
    if id.is_empty() {
        return Err(ReproError::BadTestId(test.to_string()));
    }
    Ok((id.to_string(), api))
}

/// Finds the case, checks the backend runs the path, and asks the oracle.
pub fn subject(backend: &str, test: &str, fixtures: &[PathBuf]) -> Result<Subject, ReproError> {
    match reproducer(backend, test, fixtures)? {
        Reproducer::Lookup(s) => Ok(*s),
        Reproducer::State(s) => Err(ReproError::StateCase {
            id: s.case.id.clone(),
        }),
    }
}

/// Finds the case (a lookup case or a TexParameter state case), checks the backend runs the path,
/// and asks the oracle.
pub fn reproducer(
    backend: &str,
    test: &str,
    fixtures: &[PathBuf],
) -> Result<Reproducer, ReproError> {
    // `egl@<dir>:<driver>:<api>`: the library's directory, and the name without it.
    let (lib_dir, plain) = shadowcheck_gl::libdir::split_lib_dir(backend)
        .map_err(|e| ReproError::BadBackend(e.to_string()))?;
    let name: Backend = plain.parse()?;
    match name {
        Backend::Gl(b) => {
            if let Some(why) = b.static_unavailability() {
                return Err(ReproError::BadBackend(why));
            }
            match &lib_dir {
                Some(dir) if !shadowcheck_gl::libdir::libegl_in(dir).is_file() => {
                    return Err(ReproError::BadBackend(format!(
                        "{backend}: no libEGL.so or libEGL.so.1 in {}",
                        dir.display()
                    )));
                }
                Some(_) => {}
                None => {
                    if let Err(e) = shadowcheck_gl::context::check_files(b) {
                        return Err(ReproError::BadBackend(e.to_string()));
                    }
                }
            }
        }
        Backend::Vk(d) => vulkan::check_driver(d)?,
        Backend::Webgpu(_) => webgpu::check_browser()?,
        Backend::Webgl(k) => webgl::check_installed(k)?,
    }
    let (id, api) = parse_test_id(test)?;
    if !name.paths().contains(&api) {
        return Err(ReproError::PathNotOnBackend {
            backend: name.to_string(),
            api: api.key().into(),
            paths: keys(name.paths()),
        });
    }
    let set = crate::run::load_cases(fixtures);
    if let Some(l) = set.states.iter().find(|l| l.case.id == id) {
        return state_subject(name, l, &set.files[l.file], api, lib_dir)
            .map(|s| Reproducer::State(Box::new(s)));
    }
    let no_case = || ReproError::NoCase {
        id: id.clone(),
        fixtures: fixtures
            .iter()
            .map(|p| p.display().to_string())
            .collect::<Vec<_>>()
            .join(", "),
    };
    // `<case id>/sweep=<k>`: sweep point k of the case as a case of its own (`Case::point_case`),
    // the lookup a sweep's Fail is about (its record holds the point's RGBA).
    let (case_id, point) = match set.cases.iter().any(|l| l.case.id == id) {
        true => (id.as_str(), None),
        false => match shadowcheck_model::sweep::split_point_id(&id) {
            Some((c, k)) => (c, Some(k)),
            None => (id.as_str(), None),
        },
    };
    let loaded = set
        .cases
        .iter()
        .find(|l| l.case.id == case_id)
        .ok_or_else(no_case)?;
    let fixture = PathBuf::from(&set.files[loaded.file]);
    let case = match point {
        Some(k) => loaded.case.point_case(k).ok_or_else(no_case)?,
        None => loaded.case.clone(),
    };
    if !case.api.contains(&api) {
        return Err(ReproError::NoPath {
            id,
            api: api.key().into(),
            listed: keys(&case.api),
        });
    }
    let mut bare = case.clone();
    bare.expect = None;
    let ev = crate::verdict::oracle_evaluate(&bare).map_err(ReproError::NoExpectation)?;
    if !ev.expect.layout.contains_key(&api) {
        return Err(ReproError::NoExpectation(format!(
            "no layout for API path `{api}`"
        )));
    }
    let explain = shadowcheck_oracle::explain::render(&bare, &Ok(ev.clone()));
    Ok(Reproducer::Lookup(Box::new(Subject {
        backend: name,
        case,
        api,
        expect: ev.expect,
        steps: ev.steps,
        explain,
        fixture,
        lib_dir,
    })))
}

pub(super) fn keys(paths: &[ApiPath]) -> String {
    paths.iter().map(|p| p.key()).collect::<Vec<_>>().join(", ")
}

/// The Debian packages the build needs (headers and link libraries) and those the run needs.
pub fn packages(s: &Subject) -> (String, String) {
    backend_packages(s.backend)
}

/// [`packages`] of a backend.
pub fn backend_packages(backend: Backend) -> (String, String) {
    use shadowcheck_gl::Platform;
    let b = match backend {
        Backend::Gl(b) => b,
        Backend::Vk(d) => return vulkan::packages(d),
        Backend::Webgpu(_) => return webgpu::packages(),
        Backend::Webgl(k) => return webgl::packages(k),
    };
    let dev = match (b.platform, b.api.is_es()) {
        (Platform::Osmesa, _) => "gcc libosmesa6-dev libgl-dev",
        (Platform::Egl, true) => "gcc libegl-dev libgles-dev",
        (Platform::Egl, false) => "gcc libegl-dev libgl-dev",
    };
    let mut run = match b.platform {
        Platform::Egl => vec!["libegl-mesa0", "libgl1-mesa-dri"],
        Platform::Osmesa => vec!["libosmesa6", "libgl1-mesa-dri"],
    };
    match b.driver {
        Driver::Zink => run.push("mesa-vulkan-drivers"),
        // SwiftShader's Vulkan ICD (VK_ICD_FILENAMES in the run line).
        Driver::ZinkSwiftshader => run.push("chromium-common"),
        // SwiftShader's own GLES is fetched (`sh gl/fetch-swiftshader.sh`), a native EGL is the
        // vendor's: the headers are the only packages.
        Driver::Swiftshader | Driver::Native => run.clear(),
        _ => {}
    }
    (dev.to_string(), run.join(" "))
}

/// The build command (one line).
pub fn build_line(s: &Subject) -> String {
    match s.backend {
        Backend::Gl(b) => csource::build_line(b, s.lib_dir.as_deref()),
        Backend::Vk(_) => vulkan::build_line(s).to_string(),
        Backend::Webgpu(_) => webgpu::BUILD_LINE.to_string(),
        Backend::Webgl(_) => webgl::BUILD_LINE.to_string(),
    }
}

/// The environment that picks the driver, as `NAME=value` words (the worker's).
pub fn env_words(s: &Subject) -> String {
    backend_env_words(s.backend, s.lib_dir.as_deref())
}

/// [`env_words`] of a backend.
pub fn backend_env_words(backend: Backend, lib_dir: Option<&Path>) -> String {
    match backend {
        Backend::Gl(b) => csource::env_words(b, lib_dir),
        Backend::Vk(d) => vulkan::env_words(d),
        Backend::Webgpu(_) => String::new(),
        Backend::Webgl(k) => webgl::instance(k)
            .map(|i| {
                (i.launch)()
                    .env
                    .iter()
                    .map(|(k, v)| format!("{k}={v}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .unwrap_or_default(),
    }
}

/// The `key: value` lines the program prints about the implementation it ran on (the GL
/// context's strings; the Vulkan device, API version and driver), first the one naming it.
pub fn driver_fields(s: &Subject) -> &'static [&'static str] {
    backend_fields(s.backend)
}

fn backend_fields(backend: Backend) -> &'static [&'static str] {
    match backend {
        Backend::Gl(_) => &["GL_RENDERER", "GL_VERSION", "GL_SHADING_LANGUAGE_VERSION"],
        Backend::Vk(_) => &vulkan::FIELDS,
        Backend::Webgpu(_) => &webgpu::FIELDS,
        Backend::Webgl(_) => &webgl::FIELDS,
    }
}

/// The text of build.sh: build, then run with the driver's environment; its exit status is the
/// reproducer's.
pub fn build_sh(s: &Subject) -> String {
    match s.backend {
        Backend::Webgpu(v) => return webgpu::run_script(s, v),
        Backend::Webgl(k) => return webgl::run_script(s, k),
        Backend::Gl(_) | Backend::Vk(_) => {}
    }
    c_build_sh(
        &s.test(),
        s.backend,
        s.lib_dir.as_deref(),
        &build_line(s),
        &env_words(s),
    )
}

/// build.sh of a C reproducer: build, then run with the driver's environment.
pub(super) fn c_build_sh(
    test: &str,
    backend: Backend,
    lib_dir: Option<&Path>,
    build: &str,
    env: &str,
) -> String {
    let (dev, run) = backend_packages(backend);
    let dir = match backend {
        Backend::Gl(b) => egl14::dir_line(b, lib_dir).unwrap_or_default(),
        _ => String::new(),
    };
    let label = match (backend, lib_dir) {
        (Backend::Gl(b), Some(d)) => {
            b.to_string()
                .replacen("egl:", &format!("egl@{}:", d.display()), 1)
        }
        _ => backend.to_string(),
    };
    let packages = format!("{dev} {run}");
    format!(
        "#!/bin/sh\n# shadowcheck reproducer for {test} on {label}.\n# Debian 12: apt-get install -y {}\ncd \"$(dirname \"$0\")\" || exit 2\n{dir}{build} || exit 2\nexec {env}./repro\n",
        packages.trim(),
        env = if env.is_empty() {
            String::new()
        } else {
            format!("env {env} ")
        },
    )
}

/// What the reproducer printed and how it exited.
#[derive(Debug, Clone)]
pub struct RunOutput {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

impl RunOutput {
    /// The value of a `key: value` line the program prints (`GL_RENDERER`, `observed`, ...).
    pub fn field(&self, key: &str) -> Option<&str> {
        self.stdout.lines().find_map(|l| {
            l.strip_prefix(key)
                .and_then(|r| r.strip_prefix(':'))
                .map(str::trim)
        })
    }
    /// The observed RGBA (the `observed: (r, g, b, a)` line).
    pub fn observed(&self) -> Option<[f64; 4]> {
        let v: Vec<f64> = self
            .field("observed")?
            .trim_matches(|c| c == '(' || c == ')')
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .ok()?;
        v.try_into().ok()
    }
}

/// The files a reproducer directory holds.
pub const REPRO_C: &str = "repro.c";
pub const BUILD_SH: &str = "build.sh";
pub const OUTPUT_TXT: &str = "output.txt";
pub const REPORT_MD: &str = "REPORT.md";

/// The program file of a reproducer: repro.c, or the WebGPU page repro.html.
pub fn program_file(s: &Subject) -> &'static str {
    match s.backend {
        Backend::Webgpu(_) | Backend::Webgl(_) => webgpu::REPRO_HTML,
        _ => REPRO_C,
    }
}

/// How the reproducer is run, after build.sh has built it (for REPORT.md).
pub fn run_hint(s: &Subject) -> String {
    match s.backend {
        Backend::Webgpu(_) | Backend::Webgl(_) => format!(
            "it runs {} in headless Chromium with the backend's flags",
            webgpu::REPRO_HTML
        ),
        _ => format!("{}; then {} ./repro", build_line(s), env_words(s)),
    }
}

/// Writes repro.c and build.sh (and, for Vulkan, the GLSL) into `dir` (created).
pub fn write_sources(s: &Subject, dir: &Path) -> Result<(), ReproError> {
    let c = match s.backend {
        Backend::Gl(b) => csource::program(s, b).map_err(ReproError::NotPlanned)?,
        Backend::Vk(_) => return vulkan::write_sources(s, dir),
        Backend::Webgpu(v) => return webgpu::write_sources(s, v, dir),
        Backend::Webgl(k) => return webgl::write_sources(s, k, dir),
    };
    std::fs::create_dir_all(dir).map_err(io(format!("creating {}", dir.display())))?;
    std::fs::write(dir.join(REPRO_C), c).map_err(io("writing repro.c"))?;
    std::fs::write(dir.join(BUILD_SH), build_sh(s)).map_err(io("writing build.sh"))?;
    Ok(())
}

/// Runs `sh build.sh` in `dir` and keeps what it printed in output.txt. A build failure (exit 2
/// before the program printed anything) and a setup failure of the program are errors.
pub fn build_and_run(s: &Subject, dir: &Path) -> Result<RunOutput, ReproError> {
    run_build_sh(s.backend, dir)
}

/// [`build_and_run`] for a reproducer of `backend` already written in `dir`.
pub(super) fn run_build_sh(backend: Backend, dir: &Path) -> Result<RunOutput, ReproError> {
    // A binary left from an earlier build must not run when this build fails.
    let _ = std::fs::remove_file(dir.join("repro"));
    let out = Command::new("sh")
        .arg(BUILD_SH)
        .current_dir(dir)
        .output()
        .map_err(io("running sh build.sh"))?;
    let r = RunOutput {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    };
    let text = format!(
        "$ sh build.sh\n{}{}exit {}\n",
        r.stdout,
        if r.stderr.is_empty() {
            String::new()
        } else {
            format!("[stderr]\n{}", r.stderr)
        },
        r.code
    );
    std::fs::write(dir.join(OUTPUT_TXT), text).map_err(io("writing output.txt"))?;
    if r.code != 0 && r.code != 1 {
        let started = backend_fields(backend).iter().any(|k| r.field(k).is_some());
        if let Backend::Webgpu(_) | Backend::Webgl(_) = backend {
            if r.stderr.contains("chromium not found") {
                return Err(ReproError::Missing {
                    missing: "chromium is not installed".into(),
                    package: "chromium".into(),
                    log: r.stderr,
                });
            }
            return Err(ReproError::Setup {
                code: r.code,
                log: format!("{}{}", r.stdout, r.stderr),
            });
        }
        if !started && !dir.join("repro").exists() {
            if let Backend::Vk(_) = backend {
                return Err(vulkan::build_error(&r.stderr));
            }
            return Err(ReproError::Build {
                packages: format!("apt-get install -y {}", backend_packages(backend).0),
                log: r.stderr,
            });
        }
        return Err(ReproError::Setup {
            code: r.code,
            log: format!("{}{}", r.stdout, r.stderr),
        });
    }
    Ok(r)
}
