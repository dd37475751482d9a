//! Picking the physical device of a driver and creating the logical device with the features a
//! case may need (Vulkan 1.3 §5 "Devices and Queues", §47 "Features", §48 "Limits").

use super::{version, vk_format, FormatInfo, Gpu, Loaded, Support, RELEVANT_EXTENSIONS};
use crate::{Check, Driver, VkError};
use ash::vk;
use shadowcheck_model::Format;
use std::ffi::CStr;

/// What one physical device says about itself.
struct Candidate {
    physical: vk::PhysicalDevice,
    props: vk::PhysicalDeviceProperties,
    driver_id: vk::DriverId,
    driver: String,
    name: String,
}

fn c_text(bytes: &[std::ffi::c_char]) -> String {
    let b: Vec<u8> = bytes
        .iter()
        .take_while(|c| **c != 0)
        .map(|c| *c as u8)
        .collect();
    String::from_utf8_lossy(&b).into_owned()
}

fn candidates(inst: &ash::Instance) -> Result<Vec<Candidate>, VkError> {
    // SAFETY: a valid instance.
    let devices =
        unsafe { inst.enumerate_physical_devices() }.check("vkEnumeratePhysicalDevices")?;
    Ok(devices
        .into_iter()
        .map(|pd| {
            // SAFETY: `pd` comes from this instance.
            let props = unsafe { inst.get_physical_device_properties(pd) };
            let mut driver_id = vk::DriverId::default();
            let mut driver = String::new();
            // VkPhysicalDeviceDriverProperties is Vulkan 1.2 core (§5.1).
            if props.api_version >= vk::API_VERSION_1_2 {
                let mut dp = vk::PhysicalDeviceDriverProperties::default();
                let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut dp);
                // SAFETY: `pd` comes from this instance, a 1.2 device; the chain is valid.
                unsafe { inst.get_physical_device_properties2(pd, &mut p2) };
                driver_id = dp.driver_id;
                driver = format!("{} {}", c_text(&dp.driver_name), c_text(&dp.driver_info));
            }
            Candidate {
                physical: pd,
                props,
                driver_id,
                driver: driver.trim().to_string(),
                name: c_text(&props.device_name),
            }
        })
        .collect())
}

/// The rank of a device type for the native driver: a real GPU first, a CPU last.
fn rank(t: vk::PhysicalDeviceType) -> u8 {
    match t {
        vk::PhysicalDeviceType::DISCRETE_GPU => 0,
        vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
        vk::PhysicalDeviceType::VIRTUAL_GPU => 2,
        vk::PhysicalDeviceType::CPU => 4,
        _ => 3,
    }
}

/// Creates the device of `driver` on `loaded`'s instance.
pub(super) fn device(loaded: Loaded, driver: Driver) -> Result<Gpu, VkError> {
    let inst = &loaded.instance;
    let all = candidates(inst)?;
    let found = all
        .iter()
        .map(|c| c.name.clone())
        .collect::<Vec<_>>()
        .join(", ");
    let c = all
        .into_iter()
        .filter(|c| driver.matches(c.driver_id, &c.name))
        .min_by_key(|c| rank(c.props.device_type))
        .ok_or_else(|| VkError::NoDevice {
            wanted: driver.key(),
            found: if found.is_empty() {
                "no device".into()
            } else {
                found
            },
        })?;
    let pd = c.physical;
    let api = c.props.api_version;
    // SAFETY: `pd` comes from this instance.
    let families = unsafe { inst.get_physical_device_queue_family_properties(pd) };
    let family = families
        .iter()
        .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
        .ok_or_else(|| VkError::Setup(format!("{}: no graphics queue", c.name)))?
        as u32;
    // SAFETY: `pd` comes from this instance.
    let exts = unsafe { inst.enumerate_device_extension_properties(pd) }
        .check("vkEnumerateDeviceExtensionProperties")?;
    let has = |n: &CStr| exts.iter().any(|e| e.extension_name_as_c_str() == Ok(n));
    let custom_ext = has(ash::ext::custom_border_color::NAME);
    let mirror_ext = has(ash::khr::sampler_mirror_clamp_to_edge::NAME);

    // What the device has (§47.1 "Feature Queries").
    let mut v12 = vk::PhysicalDeviceVulkan12Features::default();
    let mut cbc = vk::PhysicalDeviceCustomBorderColorFeaturesEXT::default();
    let mut f2 = vk::PhysicalDeviceFeatures2::default();
    if api >= vk::API_VERSION_1_2 {
        f2 = f2.push_next(&mut v12);
    }
    if custom_ext {
        f2 = f2.push_next(&mut cbc);
    }
    // SAFETY: `pd` comes from this instance; the chain holds structures of its version.
    unsafe { inst.get_physical_device_features2(pd, &mut f2) };
    let core = f2.features;
    let mirror_feature = api >= vk::API_VERSION_1_2 && v12.sampler_mirror_clamp_to_edge == vk::TRUE;
    let custom = custom_ext && cbc.custom_border_colors == vk::TRUE;

    // What the worker enables: only what it may use.
    let enabled_core = vk::PhysicalDeviceFeatures::default()
        .image_cube_array(core.image_cube_array == vk::TRUE)
        .shader_image_gather_extended(core.shader_image_gather_extended == vk::TRUE);
    let mut en12 =
        vk::PhysicalDeviceVulkan12Features::default().sampler_mirror_clamp_to_edge(mirror_feature);
    let mut en_cbc =
        vk::PhysicalDeviceCustomBorderColorFeaturesEXT::default().custom_border_colors(custom);
    let mut en_f2 = vk::PhysicalDeviceFeatures2::default().features(enabled_core);
    let mut names: Vec<*const std::ffi::c_char> = vec![];
    if api >= vk::API_VERSION_1_2 {
        en_f2 = en_f2.push_next(&mut en12);
    } else if mirror_ext {
        // Before 1.2 the extension alone enables the mode (VK_KHR_sampler_mirror_clamp_to_edge).
        names.push(ash::khr::sampler_mirror_clamp_to_edge::NAME.as_ptr());
    }
    if custom {
        names.push(ash::ext::custom_border_color::NAME.as_ptr());
        en_f2 = en_f2.push_next(&mut en_cbc);
    }
    let priorities = [1.0f32];
    let queues = [vk::DeviceQueueCreateInfo::default()
        .queue_family_index(family)
        .queue_priorities(&priorities)];
    let dci = vk::DeviceCreateInfo::default()
        .queue_create_infos(&queues)
        .enabled_extension_names(&names)
        .push_next(&mut en_f2);
    // SAFETY: valid create info of features the device reported; names outlive the call.
    let device = unsafe { inst.create_device(pd, &dci, None) }.check("vkCreateDevice")?;
    // SAFETY: the family and index exist (one queue of `family` was created).
    let queue = unsafe { device.get_device_queue(family, 0) };
    // SAFETY: `pd` comes from this instance.
    let memory = unsafe { inst.get_physical_device_memory_properties(pd) };
    let l = &c.props.limits;
    let support = Support {
        image_cube_array: core.image_cube_array == vk::TRUE,
        gather_extended: core.shader_image_gather_extended == vk::TRUE,
        mirror_clamp_to_edge: mirror_feature || (api < vk::API_VERSION_1_2 && mirror_ext),
        custom_border: custom,
        max_lod_bias: l.max_sampler_lod_bias,
        texel_offset: (l.min_texel_offset, l.max_texel_offset),
        gather_offset: (l.min_texel_gather_offset, l.max_texel_gather_offset),
        extensions: RELEVANT_EXTENSIONS
            .iter()
            .filter(|n| has(n))
            .map(|n| n.to_string_lossy().into_owned())
            .collect(),
    };
    let formats = Format::ALL
        .iter()
        .filter_map(|&f| vk_format(f).map(|v| format_info(inst, pd, api, f, v)))
        .collect();
    let description = format!(
        "{}; Vulkan {}; {}",
        c.name,
        version(api),
        if c.driver.is_empty() {
            format!("driver version {:#x}", c.props.driver_version)
        } else {
            format!("{} ({:?})", c.driver, c.driver_id)
        }
    );
    Ok(Gpu {
        physical: pd,
        device,
        queue,
        queue_family: family,
        memory,
        support,
        formats,
        description,
        loaded,
    })
}

/// What the device supports of `vk` with optimal tiling ("Format Feature Flags"); the depth-comparison bit from
/// VkFormatProperties3 on a Vulkan 1.3 device.
fn format_info(
    inst: &ash::Instance,
    pd: vk::PhysicalDevice,
    api: u32,
    format: Format,
    vkf: vk::Format,
) -> FormatInfo {
    let (f, depth_compare) = if api >= vk::API_VERSION_1_3 {
        let mut p3 = vk::FormatProperties3::default();
        let mut p2 = vk::FormatProperties2::default().push_next(&mut p3);
        // SAFETY: `pd` comes from this instance, a 1.3 device.
        unsafe { inst.get_physical_device_format_properties2(pd, vkf, &mut p2) };
        let f = p2.format_properties.optimal_tiling_features;
        let compare = p3
            .optimal_tiling_features
            .contains(vk::FormatFeatureFlags2::SAMPLED_IMAGE_DEPTH_COMPARISON);
        (f, Some(compare))
    } else {
        // SAFETY: `pd` comes from this instance.
        let p = unsafe { inst.get_physical_device_format_properties(pd, vkf) };
        (p.optimal_tiling_features, None)
    };
    let need = vk::FormatFeatureFlags::SAMPLED_IMAGE
        | vk::FormatFeatureFlags::TRANSFER_DST
        | vk::FormatFeatureFlags::TRANSFER_SRC;
    FormatInfo {
        format,
        vk: vkf,
        usable: f.contains(need),
        filter_linear: f.contains(vk::FormatFeatureFlags::SAMPLED_IMAGE_FILTER_LINEAR),
        depth_compare,
    }
}
