//! shadowcheck-gl: the GL worker. Mesa llvmpipe, softpipe and zink through EGL (surfaceless) and
//! OSMesa: context creation, textures, shaders and programs, the lookup paths, legacy (fixed
//! function, ARB fragment programs), the TexParameter state check, batched drawing, and the
//! [`worker`] serve loop speaking runner/PROTOCOL.md (messages from shadowcheck-protocol).
//!
//! Each backend runs in a `shadowcheck gl-worker --backend NAME` child process: the driver is chosen
//! by environment variables read when Mesa loads, EGL and OSMesa share libglapi, and a driver crash
//! must only take down its worker. The runner side (how to start a worker, probing which backends
//! run here) is shadowcheck-runner's `backend::gl`; this crate is the child side plus the backend
//! names ([`BackendName`]) both sides share.
//!
//! Every library (libEGL, libOSMesa, the GL entry points) is loaded at run time, so a machine without
//! Mesa builds fine and reports the backend unavailable with the apt-get command that fixes it.

pub mod context;
pub mod egl;
pub mod legacy;
pub mod libdir;
pub mod names;
mod programs;
pub mod renderer;
pub mod state;
pub mod stats;
pub mod texture;
pub mod unitstate;
pub mod worker;

pub use names::{BackendName, ContextApi, Driver, Platform};

/// Why the GL worker (or the runner's side of it) could not do what it was asked: a bad backend
/// name, a missing library or entry point, a context that failed, a GL error during a draw.
/// (A GL error code that a state case observes is `shadowcheck_model::GlErrorCode`, an observation.)
#[derive(Debug, thiserror::Error)]
pub enum WorkerError {
    #[error("bad backend name `{name}`: {why}")]
    BadName { name: String, why: String },
    #[error("backend unavailable: {0}")]
    Unavailable(String),
    #[error("{lib} could not be loaded ({detail}); install it with `{install}`")]
    MissingLibrary {
        lib: String,
        detail: String,
        install: String,
    },
    #[error("context creation failed: {0}")]
    ContextFailed(String),
    #[error("wrong driver: asked for {wanted}, GL_RENDERER is `{renderer}`")]
    WrongDriver { wanted: String, renderer: String },
    #[error("GL entry point {0} is missing")]
    MissingEntryPoint(String),
    #[error("cannot find the shadowcheck executable to run the GL worker: {0}")]
    NoExecutable(String),
    #[error("{0}")]
    Gl(String),
    #[error("{var} = `{value}`: expected a whole number of sampler states, at least 1")]
    BadStatesPerProgram { var: &'static str, value: String },
}
