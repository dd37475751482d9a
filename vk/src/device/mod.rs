//! The Vulkan device of a worker: the loader (opened at run time), the instance (with
//! VK_LAYER_KHRONOS_validation and a VK_EXT_debug_utils messenger when [`VALIDATION_ENV`] is
//! `1`), the physical device of the backend's driver, the features a case may need and the
//! properties of each depth format.

use crate::{Check, Driver, VkError, VALIDATION_ENV};
use ash::vk;
use shadowcheck_model::Format;
use std::ffi::{c_void, CStr};
use std::sync::Mutex;

/// Messages of the validation layer (warnings and errors) not yet reported.
static MESSAGES: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// The messages the validation layer gave since the last call (each also printed to stderr when
/// it came).
pub fn take_messages() -> Vec<String> {
    match MESSAGES.lock() {
        Ok(mut m) => std::mem::take(&mut *m),
        Err(p) => std::mem::take(&mut *p.into_inner()),
    }
}

/// VK_EXT_debug_utils callback (Vulkan 1.3 §4.3 "Debug Utilities"): keeps the message.
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    _user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes a valid callback data pointer whose p_message, when not null, is
    // a NUL-terminated string, for the duration of the call.
    let text = unsafe {
        data.as_ref()
            .filter(|d| !d.p_message.is_null())
            .map(|d| CStr::from_ptr(d.p_message).to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let line = format!("vulkan validation ({severity:?}): {text}");
    eprintln!("{line}");
    if let Ok(mut m) = MESSAGES.lock() {
        m.push(line);
    }
    vk::FALSE
}

/// The model's depth formats as Vulkan formats (Vulkan 1.3 "Formats"); D32 (unorm) and
/// unsized depth have none; R8, RG8, RGB8, RGBA8 and RGBA4 are colour formats this worker does not
/// run (Vulkan 1.3 §16 Depth Compare Operation: a Dref instruction needs a depth image, so no
/// colour image meets compareEnable; such a case is not applicable).
pub fn vk_format(f: Format) -> Option<vk::Format> {
    match f {
        Format::D16 => Some(vk::Format::D16_UNORM),
        Format::D24 => Some(vk::Format::X8_D24_UNORM_PACK32),
        Format::D32f => Some(vk::Format::D32_SFLOAT),
        Format::D24S8 => Some(vk::Format::D24_UNORM_S8_UINT),
        Format::D32fS8 => Some(vk::Format::D32_SFLOAT_S8_UINT),
        Format::D32
        | Format::DepthUnsized
        | Format::R8
        | Format::Rgba8
        | Format::Rgb8
        | Format::Rgba4
        | Format::Rg8 => None,
    }
}

/// What the device supports of a format with optimal tiling ("Format Feature Flags").
#[derive(Debug, Clone, Copy)]
pub struct FormatInfo {
    pub format: Format,
    pub vk: vk::Format,
    /// SAMPLED_IMAGE, TRANSFER_DST and TRANSFER_SRC: it can be uploaded, sampled, read back.
    pub usable: bool,
    /// SAMPLED_IMAGE_FILTER_LINEAR.
    pub filter_linear: bool,
    /// SAMPLED_IMAGE_DEPTH_COMPARISON (VkFormatProperties3, Vulkan 1.3); `None` where the device
    /// cannot say (an older device: the bit did not exist, comparison was always allowed).
    pub depth_compare: Option<bool>,
}

/// Features and limits a case may need.
#[derive(Debug, Clone, Default)]
pub struct Support {
    pub image_cube_array: bool,
    pub gather_extended: bool,
    pub mirror_clamp_to_edge: bool,
    pub custom_border: bool,
    pub max_lod_bias: f32,
    pub texel_offset: (i32, u32),
    pub gather_offset: (i32, u32),
    /// Relevant device extensions present (reported in the hello).
    pub extensions: Vec<String>,
}

/// The loader and the instance (with its messenger), destroyed last.
pub struct Loaded {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    messenger: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    pub validation: bool,
}

impl Drop for Loaded {
    fn drop(&mut self) {
        // SAFETY: the device made from the instance is destroyed before (`Gpu`'s own Drop runs
        // before its fields are dropped).
        unsafe {
            if let Some((du, m)) = self.messenger.take() {
                du.destroy_debug_utils_messenger(m, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

/// The device and what was learnt about it.
pub struct Gpu {
    pub physical: vk::PhysicalDevice,
    pub device: ash::Device,
    pub queue: vk::Queue,
    pub queue_family: u32,
    pub memory: vk::PhysicalDeviceMemoryProperties,
    pub support: Support,
    pub formats: Vec<FormatInfo>,
    /// e.g. `llvmpipe (LLVM 15.0.6, 256 bits); Vulkan 1.3.230; Mesa 22.3.6 (MESA_LLVMPIPE)`.
    pub description: String,
    pub loaded: Loaded,
}

const RELEVANT_EXTENSIONS: [&CStr; 3] = [
    c"VK_EXT_custom_border_color",
    c"VK_KHR_sampler_mirror_clamp_to_edge",
    c"VK_EXT_depth_range_unrestricted",
];

fn version(v: u32) -> String {
    format!(
        "{}.{}.{}",
        vk::api_version_major(v),
        vk::api_version_minor(v),
        vk::api_version_patch(v)
    )
}

impl Gpu {
    /// Opens the loader, creates the instance and the device of `driver`.
    pub fn open(driver: Driver) -> Result<Gpu, VkError> {
        let loaded = Loaded::open()?;
        create::device(loaded, driver)
    }
}

impl Loaded {
    fn open() -> Result<Loaded, VkError> {
        // SAFETY: loading the system's Vulkan loader runs its initialisers; nothing else here
        // has loaded it.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| VkError::Loader(e.to_string()))?;
        let validation = std::env::var(VALIDATION_ENV).is_ok_and(|v| v == "1");
        // SAFETY: a valid entry.
        let loader_version = unsafe { entry.try_enumerate_instance_version() }
            .check("vkEnumerateInstanceVersion")?
            .unwrap_or(vk::API_VERSION_1_0);
        if loader_version < vk::API_VERSION_1_1 {
            return Err(VkError::Setup(format!(
                "the Vulkan loader is {}; this worker needs 1.1",
                version(loader_version)
            )));
        }
        let mut layers: Vec<*const std::ffi::c_char> = vec![];
        let mut extensions: Vec<*const std::ffi::c_char> = vec![];
        if validation {
            // SAFETY: a valid entry.
            let have = unsafe { entry.enumerate_instance_layer_properties() }
                .check("vkEnumerateInstanceLayerProperties")?;
            let name = c"VK_LAYER_KHRONOS_validation";
            if !have.iter().any(|l| l.layer_name_as_c_str() == Ok(name)) {
                return Err(VkError::Setup(format!(
                    "{VALIDATION_ENV}=1 but VK_LAYER_KHRONOS_validation is not installed; `apt-get install -y vulkan-validationlayers`"
                )));
            }
            layers.push(name.as_ptr());
            extensions.push(ash::ext::debug_utils::NAME.as_ptr());
        }
        let app = vk::ApplicationInfo::default()
            .application_name(c"shadowcheck")
            .api_version(loader_version.min(vk::API_VERSION_1_3));
        let ci = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layers)
            .enabled_extension_names(&extensions);
        // SAFETY: valid create info; the names outlive the call.
        let instance = unsafe { entry.create_instance(&ci, None) }.check("vkCreateInstance")?;
        let mut loaded = Loaded {
            entry,
            instance,
            messenger: None,
            validation,
        };
        if validation {
            let du = ash::ext::debug_utils::Instance::new(&loaded.entry, &loaded.instance);
            let mci = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                        | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION,
                )
                .pfn_user_callback(Some(on_message));
            // SAFETY: valid instance with VK_EXT_debug_utils enabled.
            let m = unsafe { du.create_debug_utils_messenger(&mci, None) }
                .check("vkCreateDebugUtilsMessengerEXT")?;
            loaded.messenger = Some((du, m));
        }
        Ok(loaded)
    }
}

mod create;

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: every object made from the device was destroyed by its owner first (the
        // worker drops its pipelines and buffers before the Gpu); waiting for idle makes that
        // safe. The instance (`loaded`) is dropped after this.
        unsafe {
            let _ = self.device.device_wait_idle();
            self.device.destroy_device(None);
        }
    }
}

impl Gpu {
    /// A memory type of `bits` with `flags` (§11.2.1 "Device Memory Properties"), preferring
    /// one with `prefer` too.
    pub fn memory_type(
        &self,
        bits: u32,
        flags: vk::MemoryPropertyFlags,
        prefer: vk::MemoryPropertyFlags,
    ) -> Option<u32> {
        let types = &self.memory.memory_types[..self.memory.memory_type_count as usize];
        let ok = |i: usize, f: vk::MemoryPropertyFlags| {
            bits & (1 << i) != 0 && types[i].property_flags.contains(f)
        };
        (0..types.len())
            .find(|&i| ok(i, flags | prefer))
            .or_else(|| (0..types.len()).find(|&i| ok(i, flags)))
            .map(|i| i as u32)
    }

    /// The device's information about `f`, if it has a Vulkan format.
    pub fn format(&self, f: Format) -> Option<&FormatInfo> {
        self.formats.iter().find(|i| i.format == f)
    }
}
