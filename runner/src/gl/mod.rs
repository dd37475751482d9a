//! GL driver backends: Mesa llvmpipe, softpipe and zink through EGL (surfaceless) and OSMesa.
//!
//! Each backend runs in a `shadowcheck gl-worker --backend NAME` child process that speaks
//! runner/PROTOCOL.md: the driver is chosen by environment variables read when Mesa loads, EGL and
//! OSMesa share libglapi, and a driver crash must only take down its worker. This module is the
//! runner-side API (names, probing, how to start a worker); [`worker`] is the child side.
//!
//! Every library (libEGL, libOSMesa, the GL entry points) is loaded at run time, so a machine without
//! Mesa builds fine and reports the backend unavailable with the apt-get command that fixes it.

mod batch;
pub mod context;
pub mod draw;
pub mod legacy;
pub mod names;
pub mod paths;
mod programs;
pub mod shaders;
pub mod state;
pub mod texture;
pub mod worker;

pub use names::{BackendName, ContextApi, Driver, Platform};

#[derive(Debug, thiserror::Error)]
pub enum GlError {
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
}
