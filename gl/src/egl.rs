//! EGL context creation for any EGL 1.4 or later library.
//!
//! Where the library offers them, the context is surfaceless and config-less: Mesa's
//! `EGL_MESA_platform_surfaceless` display, `EGL_KHR_no_config_context` and
//! `EGL_KHR_surfaceless_context` (the worker renders into FBOs). Where any is missing (SwiftShader's
//! EGL 1.4, older vendor drivers) it falls back to EGL 1.4: the default display, a config with
//! `EGL_PBUFFER_BIT`, a 16x16 pbuffer surface made current with the context.
//! [`FORCE_PBUFFER_ENV`] forces the fallback (tests run it on Mesa).

use super::names::{BackendName, ContextApi};
use super::WorkerError;
use khronos_egl as egl;
use std::ffi::c_void;

/// Set to `1` to use the EGL 1.4 pbuffer path even where surfaceless contexts exist.
pub const FORCE_PBUFFER_ENV: &str = "SHADOWCHECK_EGL_PBUFFER";

const EGL_PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;
/// EGL_CONTEXT_MAJOR_VERSION (1.5, KHR_create_context) has the value of EGL 1.4's
/// EGL_CONTEXT_CLIENT_VERSION.
const EGL_CONTEXT_MAJOR_VERSION: egl::Int = 0x3098;
const EGL_CONTEXT_MINOR_VERSION: egl::Int = 0x30FB;
const EGL_CONTEXT_OPENGL_PROFILE_MASK: egl::Int = 0x30FD;
const EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT: egl::Int = 1;
const EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT: egl::Int = 2;
/// EGL_OPENGL_ES3_BIT (EGL 1.5, KHR_create_context).
const EGL_OPENGL_ES3_BIT: egl::Int = 0x40;

/// How the context was made current.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceMode {
    /// No surface, no config (EGL 1.5 / Mesa extensions).
    Surfaceless,
    /// A pbuffer surface from a config (EGL 1.4).
    Pbuffer,
}

/// A current EGL context and what it needs to stay alive.
pub struct EglContext {
    egl: Box<egl::DynamicInstance<egl::EGL1_4>>,
    pub mode: SurfaceMode,
    /// (major, minor) of EGL reported by eglInitialize.
    pub egl_version: (i32, i32),
}

impl EglContext {
    /// A GL entry point: eglGetProcAddress, else the symbol as exported by the libraries loaded
    /// in this process (EGL 1.4 without EGL_KHR_get_all_proc_addresses returns no core symbols).
    pub fn get_proc(&self, name: &str) -> *const c_void {
        if let Some(f) = self.egl.get_proc_address(name) {
            return f as *const c_void;
        }
        let this = libloading::os::unix::Library::this();
        let Ok(c) = std::ffi::CString::new(name) else {
            return std::ptr::null();
        };
        // SAFETY: looking up a symbol by name in the global namespace; it is used through a
        // transmute to its GL signature by the caller (as with eglGetProcAddress).
        unsafe { this.get::<*const c_void>(c.as_bytes_with_nul()) }.map_or(std::ptr::null(), |s| *s)
    }
}

fn failed(what: &str, e: impl std::fmt::Display) -> WorkerError {
    WorkerError::ContextFailed(format!("{what}: {e}"))
}

fn has(list: &str, ext: &str) -> bool {
    list.split_whitespace().any(|e| e == ext)
}

/// Versions to try, highest first: drivers refuse versions above what they support.
pub fn versions(api: ContextApi) -> &'static [(i32, i32)] {
    match api {
        // A core profile exists from GL 3.2 on.
        ContextApi::Core => &[
            (4, 6),
            (4, 5),
            (4, 3),
            (4, 2),
            (4, 1),
            (4, 0),
            (3, 3),
            (3, 2),
        ],
        // Down to GL 2.1 (zink on SwiftShader offers no more): fixed function, ARB fragment
        // programs and GLSL 1.20 need no more; what needs more is Skip by capability.
        ContextApi::Compat => &[
            (4, 6),
            (4, 5),
            (4, 3),
            (4, 2),
            (4, 1),
            (4, 0),
            (3, 3),
            (3, 2),
            (3, 1),
            (3, 0),
            (2, 1),
        ],
        ContextApi::Es3 => &[(3, 2), (3, 1), (3, 0)],
        ContextApi::Es2 => &[(2, 0)],
    }
}

/// Loads `lib` and makes a context for `b` current; `install` is the command that provides it.
pub fn create(
    b: BackendName,
    lib: &std::ffi::OsStr,
    install: String,
) -> Result<EglContext, WorkerError> {
    // SAFETY: loading an EGL library; khronos-egl checks every EGL 1.4 symbol.
    let egl = unsafe { egl::DynamicInstance::<egl::EGL1_4>::load_required_from_filename(lib) }
        .map_err(|e| WorkerError::MissingLibrary {
            lib: format!("{} (EGL 1.4)", lib.to_string_lossy()),
            detail: e.to_string(),
            install: install.clone(),
        })?;
    let forced = std::env::var(FORCE_PBUFFER_ENV).is_ok_and(|v| v == "1");
    // Client extensions (EGL_EXT_client_extensions); an EGL 1.4 library without them errors here.
    let client = egl
        .query_string(None, egl::EXTENSIONS)
        .map(|c| c.to_string_lossy().into_owned())
        .unwrap_or_default();
    let platform = egl
        .upcast::<egl::EGL1_5>()
        .filter(|_| has(&client, "EGL_MESA_platform_surfaceless") && !forced);
    let display = match platform {
        // SAFETY: the surfaceless platform takes no native display.
        Some(e15) => unsafe {
            e15.get_platform_display(
                EGL_PLATFORM_SURFACELESS_MESA,
                egl::DEFAULT_DISPLAY,
                &[egl::ATTRIB_NONE],
            )
        }
        .map_err(|e| failed("eglGetPlatformDisplay(SURFACELESS_MESA)", e))?,
        // SAFETY: EGL_DEFAULT_DISPLAY is always a valid argument.
        None => unsafe { egl.get_display(egl::DEFAULT_DISPLAY) }
            .ok_or_else(|| failed("eglGetDisplay(EGL_DEFAULT_DISPLAY)", "no display"))?,
    };
    let egl_version = egl
        .initialize(display)
        .map_err(|e| failed(&format!("eglInitialize (install: {install})"), e))?;
    let exts = egl
        .query_string(Some(display), egl::EXTENSIONS)
        .map(|c| c.to_string_lossy().into_owned())
        .unwrap_or_default();
    let at_least_15 = egl_version >= (1, 5);
    let create_context_ext = at_least_15 || has(&exts, "EGL_KHR_create_context");
    let configless =
        has(&exts, "EGL_KHR_no_config_context") || has(&exts, "EGL_MESA_configless_context");
    let surfaceless = has(&exts, "EGL_KHR_surfaceless_context");
    let mode = if configless && surfaceless && !forced {
        SurfaceMode::Surfaceless
    } else {
        SurfaceMode::Pbuffer
    };
    egl.bind_api(if b.api.is_es() {
        egl::OPENGL_ES_API
    } else {
        egl::OPENGL_API
    })
    .map_err(|e| failed("eglBindAPI", e))?;
    let (config, surface) = match mode {
        // SAFETY: EGL_NO_CONFIG_KHR is the null config (EGL_KHR_no_config_context).
        SurfaceMode::Surfaceless => (unsafe { egl::Config::from_ptr(std::ptr::null_mut()) }, None),
        SurfaceMode::Pbuffer => {
            let config = pbuffer_config(&egl, display, b.api, create_context_ext)?;
            let s = egl
                .create_pbuffer_surface(display, config, &[egl::WIDTH, 16, egl::HEIGHT, 16, egl::NONE])
                .map_err(|e| {
                    failed(
                        "eglCreatePbufferSurface (EGL_BAD_ALLOC: is LD_LIBRARY_PATH at the library's directory?)",
                        e,
                    )
                })?;
            (config, Some(s))
        }
    };
    let mut last = String::new();
    for attrs in context_attributes(b.api, create_context_ext) {
        match egl.create_context(display, config, None, &attrs) {
            Ok(ctx) => {
                egl.make_current(display, surface, surface, Some(ctx))
                    .map_err(|e| failed(&format!("eglMakeCurrent ({mode:?})"), e))?;
                return Ok(EglContext {
                    egl: Box::new(egl),
                    mode,
                    egl_version,
                });
            }
            Err(e) => last = format!("eglCreateContext {attrs:?}: {e}"),
        }
    }
    Err(WorkerError::ContextFailed(format!(
        "{last} (no version of this context kind could be created; {mode:?})"
    )))
}

/// A config for a pbuffer of the context's API (ES 3 bit where the library knows it, else ES 2).
fn pbuffer_config(
    egl: &egl::DynamicInstance<egl::EGL1_4>,
    display: egl::Display,
    api: ContextApi,
    create_context_ext: bool,
) -> Result<egl::Config, WorkerError> {
    let mut bits = match api {
        ContextApi::Es3 if create_context_ext => vec![EGL_OPENGL_ES3_BIT, egl::OPENGL_ES2_BIT],
        ContextApi::Es3 | ContextApi::Es2 => vec![egl::OPENGL_ES2_BIT],
        ContextApi::Core | ContextApi::Compat => vec![egl::OPENGL_BIT],
    };
    for bit in bits.drain(..) {
        let attrs = [
            egl::SURFACE_TYPE,
            egl::PBUFFER_BIT,
            egl::RENDERABLE_TYPE,
            bit,
            egl::NONE,
        ];
        if let Ok(Some(c)) = egl.choose_first_config(display, &attrs) {
            return Ok(c);
        }
    }
    Err(failed(
        "eglChooseConfig",
        format!("no pbuffer config renders {}", api.key()),
    ))
}

/// The attribute lists to try, most capable first. With EGL 1.5 or EGL_KHR_create_context: the
/// versions of [`versions`] with the profile; otherwise EGL 1.4's EGL_CONTEXT_CLIENT_VERSION for ES
/// (major version only) and no attributes for desktop GL.
pub fn context_attributes(api: ContextApi, create_context_ext: bool) -> Vec<Vec<egl::Int>> {
    if !create_context_ext {
        return match api {
            ContextApi::Es3 => vec![vec![EGL_CONTEXT_MAJOR_VERSION, 3, egl::NONE]],
            ContextApi::Es2 => vec![vec![EGL_CONTEXT_MAJOR_VERSION, 2, egl::NONE]],
            ContextApi::Core | ContextApi::Compat => vec![vec![egl::NONE]],
        };
    }
    versions(api)
        .iter()
        .map(|&(maj, min)| {
            let mut a = vec![
                EGL_CONTEXT_MAJOR_VERSION,
                maj,
                EGL_CONTEXT_MINOR_VERSION,
                min,
            ];
            match api {
                ContextApi::Core => a.extend([
                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                ]),
                ContextApi::Compat => a.extend([
                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                    EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                ]),
                ContextApi::Es3 | ContextApi::Es2 => {}
            }
            a.push(egl::NONE);
            a
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn egl_1_4_asks_for_the_client_version_only() {
        assert_eq!(
            context_attributes(ContextApi::Es3, false),
            vec![vec![0x3098, 3, egl::NONE]]
        );
        assert_eq!(
            context_attributes(ContextApi::Compat, false),
            vec![vec![egl::NONE]]
        );
        let with = context_attributes(ContextApi::Compat, true);
        assert_eq!(with.len(), versions(ContextApi::Compat).len());
        assert_eq!(
            with.last().map(|a| a[1..4].to_vec()),
            Some(vec![2, 0x30FB, 1])
        );
        // A core profile is never asked for below 3.2.
        assert!(versions(ContextApi::Core).iter().all(|v| *v >= (3, 2)));
    }
}
