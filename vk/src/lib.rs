//! shadowcheck-vk: the Vulkan worker. One Vulkan device (lavapipe, SwiftShader, or the machine's
//! own driver, chosen by the loader's `VK_ICD_FILENAMES`), driven through `ash` with the loader
//! opened at run time, draws the lookup plan's `vk` path (shadowcheck-plan: GLSL 4.50 for Vulkan,
//! compiled to SPIR-V by `glslangValidator`) and speaks runner/PROTOCOL.md through the plan's loop.
//!
//! - [`device`]: instance, validation messenger, physical device, features, format properties;
//! - [`spirv`]: GLSL to SPIR-V;
//! - [`pipeline`]: the result image, render pass and one pipeline per shader key;
//! - [`sampler`]: a case's sampler and image view state, or why Vulkan cannot express it;
//! - [`texture`]: texel bytes as Vulkan copies them, the images of a batch;
//! - [`draw`]: one submission: uploads, draws, read-backs;
//! - [`worker`]: the hello and the batches ([`shadowcheck_plan::serve::Serve`]).

pub mod compute;
pub mod device;
pub mod draw;
pub mod pipeline;
pub mod sampler;
pub mod spirv;
pub mod texture;
pub mod worker;

use ash::vk;

/// The drivers a `vk:<driver>` backend names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Driver {
    /// Mesa's lavapipe (package mesa-vulkan-drivers).
    Lavapipe,
    /// SwiftShader's Vulkan driver as Debian's chromium-common ships it.
    Swiftshader,
    /// Whatever the loader finds with the environment as it is.
    Native,
}

impl Driver {
    pub const ALL: [Driver; 3] = [Driver::Lavapipe, Driver::Swiftshader, Driver::Native];

    pub fn key(self) -> &'static str {
        match self {
            Driver::Lavapipe => "lavapipe",
            Driver::Swiftshader => "swiftshader",
            Driver::Native => "native",
        }
    }

    pub fn from_key(s: &str) -> Option<Driver> {
        Driver::ALL.into_iter().find(|d| d.key() == s)
    }

    /// The ICD manifest the loader is pointed at (`VK_ICD_FILENAMES`), and the command that
    /// installs it; `None` for the native driver (the environment is left as it is).
    pub fn icd(self) -> Option<(&'static str, &'static str)> {
        match self {
            Driver::Lavapipe => Some((
                "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json",
                "apt-get install -y mesa-vulkan-drivers",
            )),
            Driver::Swiftshader => Some((
                "/usr/lib/chromium/vk_swiftshader_icd.json",
                "apt-get install -y chromium",
            )),
            Driver::Native => None,
        }
    }

    /// Is the physical device with these properties this driver's (Vulkan 1.3 §5.1
    /// VkPhysicalDeviceDriverProperties::driverID, else the device name)?
    pub fn matches(self, driver_id: vk::DriverId, device_name: &str) -> bool {
        let name = device_name.to_ascii_lowercase();
        match self {
            Driver::Lavapipe => {
                driver_id == vk::DriverId::MESA_LLVMPIPE || name.contains("llvmpipe")
            }
            Driver::Swiftshader => {
                driver_id == vk::DriverId::GOOGLE_SWIFTSHADER || name.contains("swiftshader")
            }
            Driver::Native => true,
        }
    }
}

/// `vk:<driver>` as a driver.
pub fn parse_backend(name: &str) -> Result<Driver, VkError> {
    name.strip_prefix("vk:")
        .and_then(Driver::from_key)
        .ok_or_else(|| VkError::UnknownBackend(name.to_string()))
}

/// The environment variable that turns on VK_LAYER_KHRONOS_validation and reports every
/// warning and error it gives (`1`).
pub const VALIDATION_ENV: &str = "SHADOWCHECK_VK_VALIDATION";

/// Tests only: `invalid-sampler` makes every submission also create (and destroy) a sampler that
/// breaks a valid-usage rule, so that a test sees the validation layer's message turn the
/// submission's answers into Errors (the messenger path is live).
pub const TEST_FAULT_ENV: &str = "SHADOWCHECK_VK_TEST_FAULT";

/// What goes wrong in the Vulkan worker.
#[derive(Debug, thiserror::Error)]
pub enum VkError {
    #[error("unknown Vulkan backend `{0}` (expected vk:lavapipe, vk:swiftshader or vk:native)")]
    UnknownBackend(String),
    #[error(
        "cannot load the Vulkan loader (libvulkan.so.1): {0}; `apt-get install -y libvulkan1`"
    )]
    Loader(String),
    #[error("{what} failed: {result}")]
    Call {
        what: &'static str,
        result: vk::Result,
    },
    #[error("no Vulkan device of driver `{wanted}` (found: {found})")]
    NoDevice { wanted: &'static str, found: String },
    #[error("{0}")]
    Setup(String),
    #[error("glslangValidator: {0}")]
    Glslang(String),
    #[error("the device was lost ({0})")]
    DeviceLost(String),
}

impl VkError {
    /// A failed Vulkan call; a lost device is named as such.
    pub fn call(what: &'static str, result: vk::Result) -> VkError {
        if result == vk::Result::ERROR_DEVICE_LOST {
            VkError::DeviceLost(what.to_string())
        } else {
            VkError::Call { what, result }
        }
    }
}

/// `.map_err(VkError::call(...))` in short.
pub(crate) trait Check<T> {
    fn check(self, what: &'static str) -> Result<T, VkError>;
}

impl<T> Check<T> for Result<T, vk::Result> {
    fn check(self, what: &'static str) -> Result<T, VkError> {
        self.map_err(|r| VkError::call(what, r))
    }
}
