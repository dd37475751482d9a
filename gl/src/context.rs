//! Creating a current GL context through EGL (surfaceless) or OSMesa, with every library loaded at
//! run time so a machine without Mesa still builds and reports "unavailable" with the install command.

use super::names::{BackendName, ContextApi, Driver, Platform};
use super::GlError;
use std::ffi::{c_void, CString};
use std::os::raw::{c_char, c_int, c_uint};

/// apt-get command that installs what a platform needs.
pub fn install_hint(b: BackendName) -> String {
    let mut pkgs = match b.platform {
        Platform::Egl => vec!["libegl1", "libegl-mesa0", "libgl1-mesa-dri"],
        Platform::Osmesa => vec!["libosmesa6", "libgl1-mesa-dri"],
    };
    match b.driver {
        Driver::Zink => pkgs.push("mesa-vulkan-drivers"),
        Driver::ZinkSwiftshader => pkgs.extend(["libvulkan1", "chromium-common"]),
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

const EGL_PLATFORM_SURFACELESS_MESA: khronos_egl::Enum = 0x31DD;
const EGL_CONTEXT_MAJOR_VERSION: khronos_egl::Int = 0x3098;
const EGL_CONTEXT_MINOR_VERSION: khronos_egl::Int = 0x30FB;
const EGL_CONTEXT_OPENGL_PROFILE_MASK: khronos_egl::Int = 0x30FD;
const EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT: khronos_egl::Int = 1;
const EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT: khronos_egl::Int = 2;

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
        egl: Box<khronos_egl::DynamicInstance<khronos_egl::EGL1_5>>,
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
    /// The (major, minor) asked for that succeeded.
    pub requested: (i32, i32),
}

impl GlContext {
    /// Creates and makes current a context for `b`. The driver env vars must already be set.
    pub fn create(b: BackendName) -> Result<GlContext, GlError> {
        if let Some(why) = b.static_unavailability() {
            return Err(GlError::Unavailable(why));
        }
        check_files(b)?;
        match b.platform {
            Platform::Egl => create_egl(b),
            Platform::Osmesa => create_osmesa(b),
        }
    }

    /// Looks up a GL entry point (core, extension or legacy) for the current context.
    pub fn get_proc(&self, name: &str) -> *const c_void {
        match &self.inner {
            Inner::Egl { egl } => egl
                .get_proc_address(name)
                .map_or(std::ptr::null(), |f| f as *const c_void),
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
pub fn check_files(b: BackendName) -> Result<(), GlError> {
    match b.missing_file() {
        None => Ok(()),
        Some((path, install)) => Err(GlError::MissingLibrary {
            lib: path.display().to_string(),
            detail: "no such file".into(),
            install: install.into(),
        }),
    }
}

/// Versions to try, highest first: drivers refuse versions above what they support.
fn versions(api: ContextApi) -> &'static [(i32, i32)] {
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

fn create_egl(b: BackendName) -> Result<GlContext, GlError> {
    // SAFETY: loading the system EGL library; khronos-egl checks every required symbol.
    let name = lib_name(LIBEGL_ENV, "libEGL.so.1");
    let egl = unsafe {
        khronos_egl::DynamicInstance::<khronos_egl::EGL1_5>::load_required_from_filename(&name)
    }
    .map_err(|e| GlError::MissingLibrary {
        lib: format!("{} (EGL 1.5)", name.to_string_lossy()),
        detail: e.to_string(),
        install: install_hint(b),
    })?;
    // SAFETY: the surfaceless platform takes no native display.
    let display = unsafe {
        egl.get_platform_display(
            EGL_PLATFORM_SURFACELESS_MESA,
            khronos_egl::DEFAULT_DISPLAY,
            &[khronos_egl::ATTRIB_NONE],
        )
    }
    .map_err(|e| {
        GlError::ContextFailed(format!(
            "eglGetPlatformDisplay(SURFACELESS_MESA): {e} (install: {})",
            install_hint(b)
        ))
    })?;
    egl.initialize(display).map_err(|e| {
        GlError::ContextFailed(format!(
            "eglInitialize: {e} (is libegl-mesa0 installed? {})",
            install_hint(b)
        ))
    })?;
    let api = if b.api.is_es() {
        khronos_egl::OPENGL_ES_API
    } else {
        khronos_egl::OPENGL_API
    };
    egl.bind_api(api)
        .map_err(|e| GlError::ContextFailed(format!("eglBindAPI: {e}")))?;
    // SAFETY: EGL_NO_CONFIG_KHR is the null config (EGL_KHR_no_config_context, exposed by Mesa).
    let no_config = unsafe { khronos_egl::Config::from_ptr(std::ptr::null_mut()) };
    let mut last = String::new();
    for &(maj, min) in versions(b.api) {
        let mut attrs = vec![
            EGL_CONTEXT_MAJOR_VERSION,
            maj,
            EGL_CONTEXT_MINOR_VERSION,
            min,
        ];
        match b.api {
            ContextApi::Core => attrs.extend([
                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            ]),
            ContextApi::Compat => attrs.extend([
                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
            ]),
            _ => {}
        }
        attrs.push(khronos_egl::NONE);
        match egl.create_context(display, no_config, None, &attrs) {
            Ok(ctx) => {
                egl.make_current(display, None, None, Some(ctx))
                    .map_err(|e| {
                        GlError::ContextFailed(format!("eglMakeCurrent(no surface): {e}"))
                    })?;
                return Ok(GlContext {
                    inner: Inner::Egl { egl: Box::new(egl) },
                    requested: (maj, min),
                });
            }
            Err(e) => last = format!("eglCreateContext {}.{}: {e}", maj, min),
        }
    }
    Err(GlError::ContextFailed(format!(
        "{last} (no version of this context kind could be created)"
    )))
}

fn create_osmesa(b: BackendName) -> Result<GlContext, GlError> {
    let name = lib_name(LIBOSMESA_ENV, "libOSMesa.so.8");
    let missing = |detail: String| GlError::MissingLibrary {
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
    for &(maj, min) in versions(b.api) {
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
            return Err(GlError::ContextFailed("OSMesaMakeCurrent failed".into()));
        }
        return Ok(GlContext {
            inner: Inner::Osmesa {
                _lib: lib,
                get_proc,
                _buffer: buffer,
            },
            requested: (maj, min),
        });
    }
    Err(GlError::ContextFailed(
        "OSMesaCreateContextAttribs returned NULL for every version".into(),
    ))
}
