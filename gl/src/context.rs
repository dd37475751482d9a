//! Creating a current GL context through EGL (surfaceless, or an EGL 1.4 pbuffer: `egl.rs`) or OSMesa, with every library loaded at
//! run time so a machine without Mesa still builds and reports "unavailable" with the install command.

use super::names::{BackendName, ContextApi, Driver, Platform};
use super::WorkerError;
use std::ffi::{c_void, CString};
use std::os::raw::{c_char, c_int, c_uint};

/// The command that installs what a backend needs (apt-get for Mesa and chromium-common, the
/// fetch script for SwiftShader's GLES).
pub fn install_hint(b: BackendName) -> String {
    let mut pkgs = match b.platform {
        Platform::Egl => vec!["libegl1", "libegl-mesa0", "libgl1-mesa-dri"],
        Platform::Osmesa => vec!["libosmesa6", "libgl1-mesa-dri"],
    };
    match b.driver {
        Driver::Zink => pkgs.push("mesa-vulkan-drivers"),
        Driver::ZinkSwiftshader => pkgs.extend(["libvulkan1", "chromium-common"]),
        Driver::Swiftshader => return crate::libdir::SWIFTSHADER_FETCH.to_string(),
        Driver::Native => {
            return "the EGL driver of the implementation (its vendor's package)".into()
        }
        Driver::Llvmpipe | Driver::Softpipe => {}
    }
    format!("apt-get install -y {}", pkgs.join(" "))
}

/// Environment variables naming the libraries to load instead of the system's (a locally built
/// Mesa, or a test of the missing-library path).
pub const LIBEGL_ENV: &str = "SHADOWCHECK_LIBEGL";
pub const LIBOSMESA_ENV: &str = "SHADOWCHECK_LIBOSMESA";

fn lib_name(env: &str, default: &str) -> std::ffi::OsString {
    std::env::var_os(env).unwrap_or_else(|| default.into())
}

const OSMESA_FORMAT: c_int = 0x22;
const OSMESA_RGBA: c_int = 0x1908;
const OSMESA_DEPTH_BITS: c_int = 0x30;
const OSMESA_STENCIL_BITS: c_int = 0x31;
const OSMESA_ACCUM_BITS: c_int = 0x32;
const OSMESA_PROFILE: c_int = 0x33;
const OSMESA_CORE_PROFILE: c_int = 0x34;
const OSMESA_COMPAT_PROFILE: c_int = 0x35;
const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;

type OsMesaCreate = unsafe extern "C" fn(*const c_int, *mut c_void) -> *mut c_void;
type OsMesaMakeCurrent = unsafe extern "C" fn(*mut c_void, *mut c_void, c_uint, c_int, c_int) -> u8;
type OsMesaGetProc = unsafe extern "C" fn(*const c_char) -> *const c_void;

enum Inner {
    Egl {
        ctx: super::egl::EglContext,
    },
    Osmesa {
        _lib: libloading::Library,
        get_proc: OsMesaGetProc,
        /// The colour buffer OSMesa insists on; we render into FBOs.
        _buffer: Vec<u8>,
    },
}

/// A current context on this thread. Dropping it leaves the libraries loaded (drivers do not
/// survive being unloaded); the process exits soon after anyway.
pub struct GlContext {
    inner: Inner,
}

impl GlContext {
    /// Creates and makes current a context for `b`. The driver env vars must already be set.
    pub fn create(b: BackendName) -> Result<GlContext, WorkerError> {
        if let Some(why) = b.static_unavailability() {
            return Err(WorkerError::Unavailable(why));
        }
        // The runner checked the files; a library named by the runner is what is loaded.
        if std::env::var_os(LIBEGL_ENV).is_none() {
            check_files(b)?;
        }
        match b.platform {
            Platform::Egl => create_egl(b),
            Platform::Osmesa => create_osmesa(b),
        }
    }

    /// How an EGL context was made current (`None` for OSMesa).
    pub fn egl_mode(&self) -> Option<super::egl::SurfaceMode> {
        match &self.inner {
            Inner::Egl { ctx } => Some(ctx.mode),
            Inner::Osmesa { .. } => None,
        }
    }

    /// Looks up a GL entry point (core, extension or legacy) for the current context.
    pub fn get_proc(&self, name: &str) -> *const c_void {
        match &self.inner {
            Inner::Egl { ctx } => ctx.get_proc(name),
            Inner::Osmesa { get_proc, .. } => match CString::new(name) {
                // SAFETY: OSMesaGetProcAddress takes a NUL-terminated name and returns a pointer or null.
                Ok(c) => unsafe { get_proc(c.as_ptr()) },
                Err(_) => std::ptr::null(),
            },
        }
    }
}

/// Whether the files a backend needs beyond the system's libraries are here (SwiftShader's Vulkan
/// ICD for zink+swiftshader); the error names the file and the install command.
pub fn check_files(b: BackendName) -> Result<(), WorkerError> {
    match b.missing_file() {
        None => Ok(()),
        Some((path, install)) => Err(WorkerError::MissingLibrary {
            lib: path.display().to_string(),
            detail: "no such file".into(),
            install: install.into(),
        }),
    }
}

fn create_egl(b: BackendName) -> Result<GlContext, WorkerError> {
    let name = lib_name(LIBEGL_ENV, "libEGL.so.1");
    let ctx = super::egl::create(b, &name, install_hint(b))?;
    Ok(GlContext {
        inner: Inner::Egl { ctx },
    })
}

fn create_osmesa(b: BackendName) -> Result<GlContext, WorkerError> {
    let name = lib_name(LIBOSMESA_ENV, "libOSMesa.so.8");
    let missing = |detail: String| WorkerError::MissingLibrary {
        lib: name.to_string_lossy().into_owned(),
        detail,
        install: install_hint(b),
    };
    // SAFETY: loading the system OSMesa library by name.
    let lib = unsafe { libloading::Library::new(&name) }.map_err(|e| missing(e.to_string()))?;
    // SAFETY: the symbol types match OSMesa's C declarations (osmesa.h).
    let (create, make_current, get_proc) = unsafe {
        let c = *lib
            .get::<OsMesaCreate>(b"OSMesaCreateContextAttribs\0")
            .map_err(|e| missing(e.to_string()))?;
        let m = *lib
            .get::<OsMesaMakeCurrent>(b"OSMesaMakeCurrent\0")
            .map_err(|e| missing(e.to_string()))?;
        let g = *lib
            .get::<OsMesaGetProc>(b"OSMesaGetProcAddress\0")
            .map_err(|e| missing(e.to_string()))?;
        (c, m, g)
    };
    let profile = if b.api == ContextApi::Core {
        OSMESA_CORE_PROFILE
    } else {
        OSMESA_COMPAT_PROFILE
    };
    let (w, h) = (16, 16);
    let mut buffer = vec![0u8; (w * h * 4) as usize];
    for &(maj, min) in super::egl::versions(b.api) {
        let attrs = [
            OSMESA_FORMAT,
            OSMESA_RGBA,
            OSMESA_DEPTH_BITS,
            0,
            OSMESA_STENCIL_BITS,
            0,
            OSMESA_ACCUM_BITS,
            0,
            OSMESA_PROFILE,
            profile,
            OSMESA_CONTEXT_MAJOR_VERSION,
            maj,
            OSMESA_CONTEXT_MINOR_VERSION,
            min,
            0,
        ];
        // SAFETY: zero-terminated attribute list, no share context.
        let ctx = unsafe { create(attrs.as_ptr(), std::ptr::null_mut()) };
        if ctx.is_null() {
            continue;
        }
        // SAFETY: buffer outlives the context (kept in GlContext); 0x1401 = GL_UNSIGNED_BYTE.
        let ok = unsafe { make_current(ctx, buffer.as_mut_ptr() as *mut c_void, 0x1401, w, h) };
        if ok == 0 {
            return Err(WorkerError::ContextFailed(
                "OSMesaMakeCurrent failed".into(),
            ));
        }
        return Ok(GlContext {
            inner: Inner::Osmesa {
                _lib: lib,
                get_proc,
                _buffer: buffer,
            },
        });
    }
    Err(WorkerError::ContextFailed(
        "OSMesaCreateContextAttribs returned NULL for every version".into(),
    ))
}
