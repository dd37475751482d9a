//! The backend kinds, as a table: the single source of what the runner knows about each kind of
//! backend. Each [`BackendKind`] says the names it answers to, how to open one, which of its
//! instances a run that names no backend runs (and how they are found), which hidden `shadowcheck`
//! subcommand its child process runs, what to print when one cannot start, and its help line.
//! [`open`](super::open), [`default_backends`](super::default_backends), the unknown-backend
//! error, `run --help`, `run`'s notes and the worker subcommands of `main.rs` all read [`KINDS`].
//! Adding a kind: README.md, "Adding a backend".

use super::exec::{self, ExecBackend, ProcessCommand};
use super::{gl, mock, soft, vk, webgl, webgpu, Backend, BackendError, Options};

/// Opens a backend of one kind: the full name, the part after the first `:` (empty when none),
/// and the options of child-process backends.
pub type Opener = fn(&str, &str, &Options) -> Result<Box<dyn Backend>, BackendError>;

/// What a probe found for one instance of a kind (a full backend name).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Found {
    /// It starts and can run cases: a default run runs it.
    Runs,
    /// It starts but exposes none of the specs its kind implements (why): left out as not
    /// applicable.
    RunsNothing(String),
    /// It cannot start here (why): the run goes on without it and exits 96 unless
    /// `--skip-missing`.
    Missing(String),
    /// An optional implementation whose files are not installed (what is missing and the command
    /// that installs it): announced, not an error.
    Absent(String),
    /// A combination that can never work (OSMesa with ES): in no list.
    Impossible,
}

/// Probes the instances of a kind on this machine, given the kind's prefix: each full name with
/// what was found, in the order a default run lists them.
pub type Prober = fn(&str) -> Vec<(String, Found)>;

/// Which instances of a kind a run that names no backend includes.
#[derive(Clone, Copy)]
pub enum DefaultInstances {
    /// None: an instance needs what only its name carries (a command line, a script).
    OnlyNamed,
    /// Always this one.
    Always(&'static str),
    /// Those the probe finds running here; the text says which, for `run --help`.
    Probed(Prober, &'static str),
}

/// A hidden `shadowcheck` subcommand that runs a kind's implementation as a child process
/// speaking runner/PROTOCOL.md (several kinds may share one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Worker {
    /// The subcommand (`shadowcheck <subcommand> ...`).
    pub subcommand: &'static str,
    /// Its one-line description (hidden from `shadowcheck --help`, shown by `<subcommand> --help`).
    pub about: &'static str,
}

/// The GL drivers' child: one GL context through EGL or OSMesa (shadowcheck-gl).
pub const GL_WORKER: Worker = Worker {
    subcommand: "gl-worker",
    about: "(internal) A GL worker process speaking runner/PROTOCOL.md on stdin/stdout.",
};
/// The `webgl:*` backends' child: headless Chromium with a WebGL 2.0 page (shadowcheck-webgl).
pub const WEBGL_WORKER: Worker = Worker {
    subcommand: "webgl-worker",
    about: "(internal) The `webgl:*` worker: headless Chromium speaking runner/PROTOCOL.md.",
};
/// The Vulkan drivers' child: one Vulkan device through ash (shadowcheck-vk).
pub const VK_WORKER: Worker = Worker {
    subcommand: "vk-worker",
    about:
        "(internal) A Vulkan worker process (`vk:*`) speaking runner/PROTOCOL.md on stdin/stdout.",
};
/// The WebGPU backends' child: headless Chromium with a WebGPU page (shadowcheck-webgpu).
pub const WEBGPU_WORKER: Worker = Worker {
    subcommand: "webgpu-worker",
    about:
        "(internal) The `webgpu:*` worker: WebGPU in headless Chromium speaking runner/PROTOCOL.md.",
};
/// `mock:<script>`'s child: the scripted implementation of [`mock`].
pub const MOCK_WORKER: Worker = Worker {
    subcommand: "mock-worker",
    about:
        "(internal) The `mock:` backend's process, speaking runner/PROTOCOL.md (runner self-tests).",
};

/// One kind of backend.
pub struct BackendKind {
    /// The part of the name before the first `:` (and before `@`, for `egl@<lib-dir>:...`).
    pub prefix: &'static str,
    /// The names it answers to, as written in errors and help.
    pub pattern: &'static str,
    /// One line for `run --help` (which adds the worker child, if any).
    pub help: &'static str,
    pub open: Opener,
    /// The instances a run that names no backend includes.
    pub defaults: DefaultInstances,
    /// The `shadowcheck` subcommand its implementation runs in, if it runs in a worker child of
    /// this executable (`exec:` runs an outside command; `soft` runs in the runner).
    pub worker: Option<Worker>,
    /// Printed once (`shadowcheck: {hint}`) when an instance cannot start, given its name: what
    /// to install. `None` for a name it does not apply to.
    pub missing_hint: fn(&str) -> Option<&'static str>,
    /// Whether `run --fast-compile` changes its implementation's code generation (the run's meta
    /// then says so beside the implementation's name).
    pub fast_compile: bool,
}

/// Every backend kind, in the order help, errors and a default run list them.
pub const KINDS: &[BackendKind] = &[
    BackendKind {
        prefix: "soft",
        pattern: "soft, soft:<spec>",
        help: "the project's own texture unit (each case under its own spec, or one spec only)",
        open: open_soft,
        defaults: DefaultInstances::Always("soft"),
        worker: None,
        missing_hint: no_hint,
        fast_compile: false,
    },
    BackendKind {
        prefix: "exec",
        pattern: "exec:<command>",
        help: "an external implementation speaking runner/PROTOCOL.md",
        open: open_exec,
        defaults: DefaultInstances::OnlyNamed,
        worker: None,
        missing_hint: no_hint,
        fast_compile: false,
    },
    BackendKind {
        prefix: "egl",
        pattern: "egl:*",
        help: "egl[@<lib-dir>]:<driver>:<api>[:<form>], a GL driver through EGL (surfaceless, or EGL 1.4 pbuffer)",
        open: open_gl,
        defaults: DefaultInstances::Probed(gl::probe_kind, "every EGL driver found on this machine"),
        worker: Some(GL_WORKER),
        missing_hint: gl::missing_hint,
        fast_compile: true,
    },
    BackendKind {
        prefix: "osmesa",
        pattern: "osmesa:*",
        help: "osmesa:<driver>:<api>[:<form>], a Mesa driver through OSMesa",
        open: open_gl,
        defaults: DefaultInstances::Probed(gl::probe_kind, "every OSMesa driver found on this machine"),
        worker: Some(GL_WORKER),
        missing_hint: gl::missing_hint,
        fast_compile: true,
    },
    BackendKind {
        prefix: "webgl",
        pattern: "webgl:*",
        help: "webgl:chromium|chromium-gles|chromium-lavapipe, WebGL 2.0 in headless Chromium on ANGLE's Vulkan back end on SwiftShader, its OpenGL ES back end on Mesa's llvmpipe, its Vulkan back end on Mesa's lavapipe, the es300 path",
        open: open_webgl,
        defaults: DefaultInstances::Probed(webgl::probe_kind, "webgl:chromium when Chromium is installed, webgl:chromium-gles and webgl:chromium-lavapipe when Mesa's llvmpipe and lavapipe are too"),
        worker: Some(WEBGL_WORKER),
        missing_hint: no_hint,
        fast_compile: false,
    },
    BackendKind {
        prefix: "vk",
        pattern: "vk:*",
        help: "vk:lavapipe|swiftshader|native, a Vulkan driver through ash, the vk path (GLSL 4.50 for Vulkan, SPIR-V by glslangValidator)",
        open: open_vk,
        defaults: DefaultInstances::Probed(vk::probe_kind, "vk:lavapipe and vk:swiftshader when their ICDs are installed"),
        worker: Some(VK_WORKER),
        missing_hint: vk::missing_hint,
        fast_compile: false,
    },
    BackendKind {
        prefix: "webgpu",
        pattern: "webgpu:chromium, webgpu:chromium-compat",
        help: "WebGPU in headless Chromium (Dawn on SwiftShader; -compat: Dawn's OpenGL ES backend on ANGLE, compatibility mode), the wgsl path",
        open: open_webgpu,
        defaults: DefaultInstances::Probed(webgpu::probe_kind, "webgpu:chromium when Chromium is installed"),
        worker: Some(WEBGPU_WORKER),
        missing_hint: webgpu_hint,
        fast_compile: false,
    },
    BackendKind {
        prefix: "mock",
        pattern: "mock:<script>",
        help: "a scripted implementation for testing the runner itself",
        open: open_mock,
        defaults: DefaultInstances::OnlyNamed,
        worker: Some(MOCK_WORKER),
        missing_hint: no_hint,
        fast_compile: false,
    },
];

/// The kind a backend name belongs to.
pub fn kind_of(name: &str) -> Option<&'static BackendKind> {
    let prefix = name.split_once(':').map_or(name, |(k, _)| k);
    // `egl@<lib-dir>:...`: an EGL backend with its library directory.
    let prefix = prefix.split_once('@').map_or(prefix, |(k, _)| k);
    KINDS.iter().find(|k| k.prefix == prefix)
}

/// The worker subcommands of the kinds, each once, in table order.
pub fn workers() -> Vec<Worker> {
    let mut v: Vec<Worker> = Vec::new();
    for w in KINDS.iter().filter_map(|k| k.worker) {
        if !v.contains(&w) {
            v.push(w);
        }
    }
    v
}

/// The name patterns, comma-separated (`soft, soft:<spec>, exec:<command>, ...`).
pub fn patterns() -> String {
    KINDS
        .iter()
        .map(|k| k.pattern)
        .collect::<Vec<_>>()
        .join(", ")
}

/// What a run that names no backend includes, from [`BackendKind::defaults`]
/// (`soft, every EGL driver found on this machine, ...`).
pub fn default_help() -> String {
    KINDS
        .iter()
        .filter_map(|k| match k.defaults {
            DefaultInstances::OnlyNamed => None,
            DefaultInstances::Always(name) => Some(name),
            DefaultInstances::Probed(_, which) => Some(which),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The `--backend` help of `shadowcheck run`: the patterns, the default, then one line per kind
/// (with its worker child, if any).
pub fn help() -> String {
    let mut s = format!(
        "Backend to run (repeatable): {}. Default: {}.",
        patterns(),
        default_help()
    );
    for k in KINDS {
        s.push_str(&format!("\n  {}: {}", k.pattern, k.help));
        if let Some(w) = k.worker {
            s.push_str(&format!(", in a {} child", w.subcommand));
        }
    }
    s
}

/// Probes every kind whose instances are probed, each kind on its own thread (a GL probe starts
/// one child per driver and waits for them), and answers each instance with what was found, in
/// table order; an `Always` kind's instance is answered as running, `OnlyNamed` kinds have none.
pub fn probe_defaults() -> Vec<(String, Found)> {
    /// One kind's instances: known at once, or found by a probe running on its own thread.
    enum Probe<'s> {
        Known(Vec<(String, Found)>),
        Running(std::thread::ScopedJoinHandle<'s, Vec<(String, Found)>>),
    }
    std::thread::scope(|s| {
        let probes: Vec<Probe<'_>> = KINDS
            .iter()
            .map(|k| match k.defaults {
                DefaultInstances::OnlyNamed => Probe::Known(vec![]),
                DefaultInstances::Always(name) => {
                    Probe::Known(vec![(name.to_string(), Found::Runs)])
                }
                DefaultInstances::Probed(probe, _) => {
                    Probe::Running(s.spawn(move || probe(k.prefix)))
                }
            })
            .collect();
        let mut out = Vec::new();
        for (k, p) in KINDS.iter().zip(probes) {
            match p {
                Probe::Known(found) => out.extend(found),
                Probe::Running(handle) => match handle.join() {
                    Ok(found) => out.extend(found),
                    // A probe that panicked found nothing that starts: said, not passed on.
                    Err(_) => out.push((
                        k.pattern.to_string(),
                        Found::Missing("the probe of this kind failed".into()),
                    )),
                },
            }
        }
        out
    })
}

fn no_hint(_: &str) -> Option<&'static str> {
    None
}

fn webgpu_hint(_: &str) -> Option<&'static str> {
    Some("the WebGPU backends need Chromium: apt-get install -y chromium")
}

fn setup(name: &str, msg: impl ToString) -> BackendError {
    BackendError::Setup {
        backend: name.into(),
        msg: msg.to_string(),
    }
}

fn open_soft(name: &str, rest: &str, _: &Options) -> Result<Box<dyn Backend>, BackendError> {
    Ok(Box::new(soft::SoftBackend::new(name, rest)?))
}

fn open_exec(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let argv = exec::split_command(rest).map_err(|msg| setup(name, msg))?;
    let Some((program, args)) = argv.split_first() else {
        return Err(setup(name, "empty command"));
    };
    let cmd = ProcessCommand {
        program: program.into(),
        args: args.to_vec(),
        env: vec![],
    };
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_gl(name: &str, _: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let mut cmd = gl::worker_command(name).map_err(|e| setup(name, e))?;
    if opts.fast_compile {
        cmd.env.push(("GALLIVM_PERF".into(), "nopt".into()));
    }
    cmd.env.push((
        shadowcheck_gl::worker::STATES_PER_PROGRAM_ENV.into(),
        opts.states_per_program.to_string(),
    ));
    let compiles = gl::compiles_per_state(name);
    Ok(Box::new(
        ExecBackend::start(name, cmd, opts)?.with_compiles_per_state(compiles),
    ))
}

fn open_webgl(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let cmd = webgl::worker_command(rest).map_err(|e| setup(name, e))?;
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_vk(name: &str, _: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let cmd = vk::worker_command(name).map_err(|e| setup(name, e))?;
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_webgpu(name: &str, _: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let cmd = webgpu::worker_command(name).map_err(|e| setup(name, e))?;
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_mock(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let exe = std::env::current_exe().map_err(|e| setup(name, e))?;
    mock::Script::parse(rest).map_err(|msg| setup(name, msg))?;
    let cmd = ProcessCommand {
        program: exe,
        args: vec![MOCK_WORKER.subcommand.into(), rest.to_string()],
        env: vec![],
    };
    Ok(Box::new(
        ExecBackend::start(name, cmd, opts)?.with_compiles_per_state(false),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unknown_backend_error_lists_every_kind() {
        assert_eq!(
            patterns(),
            "soft, soft:<spec>, exec:<command>, egl:*, osmesa:*, webgl:*, vk:*, webgpu:chromium, webgpu:chromium-compat, mock:<script>"
        );
        assert!(kind_of("egl:llvmpipe:core").is_some_and(|k| k.prefix == "egl"));
        assert!(kind_of("soft").is_some_and(|k| k.prefix == "soft"));
        assert!(kind_of("nonsense:x").is_none());
        assert!(kind_of("egl@/opt/vendor/lib:native:es3").is_some_and(|k| k.prefix == "egl"));
        assert_eq!(help().lines().count(), KINDS.len() + 1);
        assert!(help().contains("\n  webgl:*: webgl:chromium|chromium-gles|chromium-lavapipe, WebGL 2.0 in headless Chromium on ANGLE's Vulkan back end on SwiftShader, its OpenGL ES back end on Mesa's llvmpipe, its Vulkan back end on Mesa's lavapipe, the es300 path, in a webgl-worker child\n"));
        assert!(kind_of("webgl:chromium-lavapipe").is_some_and(|k| k.prefix == "webgl"));
        assert!(help().ends_with("\n  mock:<script>: a scripted implementation for testing the runner itself, in a mock-worker child"));
    }

    #[test]
    fn the_default_run_is_described_from_the_table() {
        assert_eq!(
            default_help(),
            "soft, every EGL driver found on this machine, every OSMesa driver found on this \
             machine, webgl:chromium when Chromium is installed, webgl:chromium-gles and \
             webgl:chromium-lavapipe when Mesa's llvmpipe and lavapipe are too, vk:lavapipe and \
             vk:swiftshader when their ICDs are installed, webgpu:chromium when Chromium is \
             installed"
        );
        assert!(help().lines().next().is_some_and(|l| l.ends_with(
            "Default: soft, every EGL driver found on this machine, every OSMesa driver found on \
             this machine, webgl:chromium when Chromium is installed, webgl:chromium-gles and \
             webgl:chromium-lavapipe when Mesa's llvmpipe and lavapipe are too, vk:lavapipe and \
             vk:swiftshader when their ICDs are installed, webgpu:chromium when Chromium is \
             installed."
        )));
    }

    #[test]
    fn each_kind_is_found_by_its_own_names() {
        for (i, k) in KINDS.iter().enumerate() {
            assert!(
                KINDS[..i].iter().all(|o| o.prefix != k.prefix),
                "{} twice",
                k.prefix
            );
            // The first pattern names the kind (`egl:*` stands for `egl:<anything>`).
            let first = k.pattern.split(", ").next().unwrap_or_default();
            let name = first.replace('*', "x");
            assert!(
                kind_of(&name).is_some_and(|f| f.prefix == k.prefix),
                "{name} is not of {}",
                k.prefix
            );
            if let DefaultInstances::Always(n) = k.defaults {
                assert!(kind_of(n).is_some_and(|f| f.prefix == k.prefix), "{n}");
            }
        }
    }

    fn of_kind(n: &str) -> Option<Worker> {
        kind_of(n).and_then(|k| k.worker)
    }

    #[test]
    fn workers_are_listed_once_each() {
        assert_eq!(
            workers(),
            [
                GL_WORKER,
                WEBGL_WORKER,
                VK_WORKER,
                WEBGPU_WORKER,
                MOCK_WORKER
            ]
        );
        assert_eq!(of_kind("webgpu:chromium"), Some(WEBGPU_WORKER));
        assert_eq!(of_kind("webgpu:chromium-compat"), Some(WEBGPU_WORKER));
        assert_eq!(of_kind("vk:lavapipe"), Some(VK_WORKER));
        let of = of_kind;
        assert_eq!(of("egl:llvmpipe:core"), Some(GL_WORKER));
        assert_eq!(of("osmesa:llvmpipe:core"), Some(GL_WORKER));
        assert_eq!(of("webgl:chromium"), Some(WEBGL_WORKER));
        assert_eq!(of("webgl:chromium-gles"), Some(WEBGL_WORKER));
        assert_eq!(of("mock:pass"), Some(MOCK_WORKER));
        assert_eq!(of("soft"), None);
        assert_eq!(of("exec:./impl"), None);
    }

    #[test]
    fn the_install_hint_and_fast_compile_follow_the_kind() {
        let hint = |n: &str| kind_of(n).and_then(|k| (k.missing_hint)(n));
        assert_eq!(hint("egl:llvmpipe:core"), Some(gl::MESA_HINT));
        assert_eq!(hint("osmesa:softpipe:compat"), Some(gl::MESA_HINT));
        // A vendor's libEGL is not Mesa's: installing Mesa would not help it.
        assert_eq!(hint("egl@/opt/vendor/lib:native:es3"), None);
        assert_eq!(hint("soft"), None);
        assert_eq!(hint("webgl:chromium"), None);
        assert!(hint("vk:swiftshader").is_some_and(|h| h.contains("apt-get install -y chromium")));
        assert_eq!(hint("vk:native"), None);
        assert!(hint("webgpu:chromium").is_some_and(|h| h.contains("apt-get install -y chromium")));
        assert_eq!(hint("mock:crash"), None);
        let fast = |n: &str| kind_of(n).is_some_and(|k| k.fast_compile);
        assert!(fast("egl:llvmpipe:core") && fast("osmesa:llvmpipe:core"));
        assert!(!fast("soft") && !fast("webgl:chromium") && !fast("mock:x"));
        assert!(!fast("webgpu:chromium"));
    }

    #[test]
    fn a_webgl_default_is_absent_or_runs_never_missing() {
        let found = webgl::probe_kind("webgl");
        let names: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "webgl:chromium",
                "webgl:chromium-gles",
                "webgl:chromium-lavapipe"
            ]
        );
        for (name, f) in &found {
            match f {
                Found::Runs => {}
                // What is missing, with the command that installs the browser and the driver.
                Found::Absent(why) => {
                    assert!(why.contains("apt-get install -y chromium"), "{name}: {why}")
                }
                other => panic!("{name}: {other:?}"),
            }
        }
    }
}
