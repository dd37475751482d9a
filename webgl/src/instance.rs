//! The instances of the `webgl` kind: which ANGLE back end over which driver each browser start
//! gives WebGL 2.0, the files that driver needs, and the renderer string that shows the page got
//! it (a Chromium that falls back to another implementation is not that backend).
//!
//! - `webgl:chromium`: ANGLE's Vulkan back end over SwiftShader (Chromium's own ICD);
//! - `webgl:chromium-gles`: ANGLE's OpenGL ES back end over Mesa's llvmpipe (EGL);
//! - `webgl:chromium-lavapipe`: ANGLE's Vulkan back end over Mesa's lavapipe.

use super::browser::{Launch, INSTALL};
use super::WebglError;
use std::path::Path;

/// The graphics flags of `webgl:chromium-gles`: ANGLE's OpenGL ES back end through EGL. Chromium
/// blocklists software GL, so WebGL 2.0 needs `--ignore-gpu-blocklist`; `--disable-gpu` would
/// leave no WebGL 2.0 at all, and `--enable-unsafe-swiftshader` is left out so that a GPU process
/// that cannot start on Mesa does not fall back to SwiftShader.
pub const GLES_FLAGS: &[&str] = &["--use-angle=gles-egl", "--ignore-gpu-blocklist"];

/// Mesa's variables for `webgl:chromium-gles` (those of the GL worker's `egl:llvmpipe:*`): the
/// software rasterizer, llvmpipe, even on a machine with a GPU; EGL's default platform surfaceless.
pub const GLES_ENV: &[(&str, &str)] = &[
    ("LIBGL_ALWAYS_SOFTWARE", "1"),
    ("GALLIUM_DRIVER", "llvmpipe"),
    ("EGL_PLATFORM", "surfaceless"),
];

/// The graphics flags of `webgl:chromium-lavapipe`: ANGLE's Vulkan back end on the Vulkan driver
/// `VK_ICD_FILENAMES` names. Chromium's GPU driver bug list applies `disable_texture_storage` to
/// lavapipe, which takes texStorage (OpenGL ES 3.0) and with it WebGL 2.0 away (only WebGL 1.0
/// remains); `--disable-gpu-driver-bug-workarounds` turns the list off. The other entries it drops
/// there (timer queries, exit_on_context_lost, KHR_blend_equation_advanced) do not touch sampling.
pub const LAVAPIPE_FLAGS: &[&str] = &[
    "--use-angle=vulkan",
    "--ignore-gpu-blocklist",
    "--disable-gpu-driver-bug-workarounds",
];

/// Mesa's lavapipe ICD manifest (mesa-vulkan-drivers): the file `vk:lavapipe` loads too.
pub const LAVAPIPE_ICD: &str = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

/// Mesa's EGL vendor library for glvnd (libegl-mesa0), by its vendor manifest.
pub const MESA_EGL_VENDOR: &str = "/usr/share/glvnd/egl_vendor.d/50_mesa.json";

/// Where Mesa's software DRI driver (llvmpipe and softpipe, libgl1-mesa-dri) may be.
pub const SWRAST_DIRS: &[&str] = &[
    "/usr/lib/x86_64-linux-gnu/dri",
    "/usr/lib/aarch64-linux-gnu/dri",
    "/usr/lib64/dri",
    "/usr/lib/dri",
];

impl Launch {
    /// `webgl:chromium-gles`'s start: ANGLE's OpenGL ES back end on Mesa's llvmpipe.
    pub fn gles() -> Launch {
        Launch {
            flags: GLES_FLAGS.iter().map(|f| f.to_string()).collect(),
            env: GLES_ENV
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
        }
    }

    /// `webgl:chromium-lavapipe`'s start: ANGLE's Vulkan back end on Mesa's lavapipe.
    pub fn lavapipe() -> Launch {
        Launch {
            flags: LAVAPIPE_FLAGS.iter().map(|f| f.to_string()).collect(),
            env: vec![("VK_ICD_FILENAMES".to_string(), LAVAPIPE_ICD.to_string())],
        }
    }
}

/// One instance of the kind: `webgl:<key>`.
#[derive(Debug)]
pub struct Instance {
    /// The part of the backend name after `webgl:`.
    pub key: &'static str,
    /// The ANGLE back end and the driver under it.
    pub what: &'static str,
    /// How the browser is started.
    pub launch: fn() -> Launch,
    /// Words the page's renderer string (WEBGL_debug_renderer_info's UNMASKED_RENDERER_WEBGL)
    /// must all hold, compared without case: the back end and the driver.
    pub renderer: &'static [&'static str],
    /// The command that installs the browser and the driver.
    pub install: &'static str,
    /// A file the driver needs that is missing here (what it is), if any.
    pub missing: fn() -> Option<String>,
}

/// Every instance, in the order help and a default run list them.
pub const INSTANCES: &[Instance] = &[
    Instance {
        key: "chromium",
        what: "ANGLE's Vulkan back end on SwiftShader",
        launch: Launch::swiftshader,
        renderer: &["Vulkan", "SwiftShader"],
        install: INSTALL,
        missing: nothing_missing,
    },
    Instance {
        key: "chromium-gles",
        what: "ANGLE's OpenGL ES back end on Mesa's llvmpipe (EGL)",
        launch: Launch::gles,
        renderer: &["OpenGL ES", "llvmpipe"],
        install: "apt-get install -y chromium libegl-mesa0 libgl1-mesa-dri",
        missing: mesa_egl_missing,
    },
    Instance {
        key: "chromium-lavapipe",
        what: "ANGLE's Vulkan back end on Mesa's lavapipe",
        launch: Launch::lavapipe,
        renderer: &["Vulkan", "llvmpipe"],
        install: "apt-get install -y chromium mesa-vulkan-drivers",
        missing: lavapipe_missing,
    },
];

fn nothing_missing() -> Option<String> {
    None
}

fn mesa_egl_missing() -> Option<String> {
    if !Path::new(MESA_EGL_VENDOR).is_file() {
        return Some(format!("Mesa's EGL ({MESA_EGL_VENDOR} not found)"));
    }
    if !SWRAST_DIRS
        .iter()
        .any(|d| Path::new(d).join("swrast_dri.so").is_file())
    {
        return Some(format!(
            "Mesa's llvmpipe (swrast_dri.so not found in {})",
            SWRAST_DIRS.join(", ")
        ));
    }
    None
}

fn lavapipe_missing() -> Option<String> {
    (!Path::new(LAVAPIPE_ICD).is_file())
        .then(|| format!("Mesa's lavapipe ({LAVAPIPE_ICD} not found)"))
}

impl Instance {
    /// The backend name, `webgl:<key>`.
    pub fn name(&self) -> String {
        format!("webgl:{}", self.key)
    }

    /// `Ok` when the browser and the driver's files are installed, else what is missing with
    /// the command that installs it.
    pub fn installed(&self) -> Result<(), WebglError> {
        super::browser::chromium_exe().map_err(|e| match e {
            WebglError::NoBrowser(m) if self.install != INSTALL => {
                WebglError::NoBrowser(m.replace(INSTALL, self.install))
            }
            e => e,
        })?;
        match (self.missing)() {
            None => Ok(()),
            Some(what) => Err(WebglError::NoBrowser(format!(
                "{what}; install it with `{}`",
                self.install
            ))),
        }
    }

    /// `Ok` when `renderer` names this instance's back end and driver, else why not.
    pub fn check_renderer(&self, renderer: &str) -> Result<(), WebglError> {
        let lower = renderer.to_lowercase();
        match self
            .renderer
            .iter()
            .find(|w| !lower.contains(&w.to_lowercase()))
        {
            None => Ok(()),
            Some(w) => Err(WebglError::Context(format!(
                "the page's renderer is `{renderer}`, without `{w}`: Chromium did not start {} \
                 (another implementation is not this backend)",
                self.what
            ))),
        }
    }
}

/// The instance `key` (the part after `webgl:`), or the error naming the known ones.
pub fn instance(key: &str) -> Result<&'static Instance, WebglError> {
    INSTANCES.iter().find(|i| i.key == key).ok_or_else(|| {
        WebglError::Context(format!(
            "unknown WebGL backend `webgl:{key}` (expected one of: {})",
            INSTANCES
                .iter()
                .map(Instance::name)
                .collect::<Vec<_>>()
                .join(", ")
        ))
    })
}

/// The instance of a backend name (`webgl:<key>`).
pub fn of_backend(name: &str) -> Result<&'static Instance, WebglError> {
    match name.strip_prefix("webgl:") {
        Some(key) => instance(key),
        None => Err(WebglError::Context(format!(
            "`{name}` is not a WebGL backend name (webgl:<instance>)"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::browser::SWIFTSHADER_FLAGS;

    #[test]
    fn each_instance_has_its_launch_and_renderer_words() {
        let names: Vec<String> = INSTANCES.iter().map(Instance::name).collect();
        assert_eq!(
            names,
            [
                "webgl:chromium",
                "webgl:chromium-gles",
                "webgl:chromium-lavapipe"
            ]
        );
        assert_eq!(
            (INSTANCES[0].launch)().flags,
            SWIFTSHADER_FLAGS
                .iter()
                .map(|s| s.to_string())
                .collect::<Vec<_>>()
        );
        let gles = Launch::gles();
        assert!(gles.flags.iter().any(|f| f == "--use-angle=gles-egl"));
        assert!(!gles
            .flags
            .iter()
            .any(|f| f == "--disable-gpu" || f == "--enable-unsafe-swiftshader"));
        let lvp = Launch::lavapipe();
        assert!(lvp
            .flags
            .iter()
            .any(|f| f == "--disable-gpu-driver-bug-workarounds"));
        assert_eq!(
            lvp.env,
            [("VK_ICD_FILENAMES".to_string(), LAVAPIPE_ICD.to_string())]
        );
        assert!(of_backend("webgl:chromium-gles").is_ok_and(|i| i.key == "chromium-gles"));
        assert!(of_backend("webgl:firefox")
            .is_err_and(|e| e.to_string().contains("webgl:chromium-lavapipe")));
        assert!(of_backend("vk:lavapipe").is_err());
    }

    #[test]
    fn a_renderer_of_another_implementation_is_refused() {
        let [ss, gles, lvp] = [&INSTANCES[0], &INSTANCES[1], &INSTANCES[2]];
        let r_ss = "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)";
        let r_gles = "ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL ES 3.2)";
        let r_lvp =
            "ANGLE (Mesa, Vulkan 1.3.230 (llvmpipe (LLVM 15.0.6 256 bits) (0x00000000)), llvmpipe)";
        assert!(ss.check_renderer(r_ss).is_ok());
        assert!(gles.check_renderer(r_gles).is_ok());
        assert!(lvp.check_renderer(r_lvp).is_ok());
        assert!(ss.check_renderer(r_lvp).is_err());
        assert!(gles.check_renderer(r_lvp).is_err());
        assert!(gles.check_renderer(r_ss).is_err());
        assert!(lvp
            .check_renderer(r_ss)
            .is_err_and(|e| e.to_string().contains("lavapipe")));
        assert!(lvp.check_renderer(r_gles).is_err());
    }
}
