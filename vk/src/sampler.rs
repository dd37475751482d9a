//! A case's sampler and image view as Vulkan state (Vulkan 1.3 §13 "Samplers", §12.5 "Image
//! Views"), or why Vulkan, or this device, cannot express it: such a case is Skip with the reason,
//! never drawn with other state and never a call the validation layer would reject.

use crate::device::{FormatInfo, Support};
use ash::vk;
use shadowcheck_model::{Case, CompareFunc, Filter, Target, Wrap};
use shadowcheck_plan::SamplerKind;

/// What the sampler and the view of a case are.
#[derive(Debug, Clone, PartialEq)]
pub struct SamplerState {
    pub mag: vk::Filter,
    pub min: vk::Filter,
    pub mipmap: vk::SamplerMipmapMode,
    pub address: [vk::SamplerAddressMode; 3],
    pub compare: Option<vk::CompareOp>,
    pub min_lod: f32,
    pub max_lod: f32,
    pub lod_bias: f32,
    pub border: vk::BorderColor,
    /// VK_EXT_custom_border_color's colour, with `border` FLOAT_CUSTOM_EXT.
    pub custom_border: Option<[f32; 4]>,
    /// Levels of the view (from level base): 1 for a non-mipmapped minification filter, else up
    /// to TEXTURE_MAX_LEVEL.
    pub view_levels: u32,
    /// The aspect the view samples: depth, or stencil (DEPTH_STENCIL_TEXTURE_MODE STENCIL_INDEX).
    pub aspect: vk::ImageAspectFlags,
}

fn compare_op(f: CompareFunc) -> Option<vk::CompareOp> {
    Some(match f {
        CompareFunc::Never => vk::CompareOp::NEVER,
        CompareFunc::Less => vk::CompareOp::LESS,
        CompareFunc::Equal => vk::CompareOp::EQUAL,
        CompareFunc::Lequal => vk::CompareOp::LESS_OR_EQUAL,
        CompareFunc::Greater => vk::CompareOp::GREATER,
        CompareFunc::Notequal => vk::CompareOp::NOT_EQUAL,
        CompareFunc::Gequal => vk::CompareOp::GREATER_OR_EQUAL,
        CompareFunc::Always => vk::CompareOp::ALWAYS,
        CompareFunc::LequalRSgix | CompareFunc::GequalRSgix => return None,
    })
}

fn address(w: Wrap, support: &Support) -> Result<vk::SamplerAddressMode, String> {
    Ok(match w {
        Wrap::Repeat => vk::SamplerAddressMode::REPEAT,
        Wrap::ClampToEdge => vk::SamplerAddressMode::CLAMP_TO_EDGE,
        Wrap::ClampToBorder => vk::SamplerAddressMode::CLAMP_TO_BORDER,
        Wrap::MirroredRepeat => vk::SamplerAddressMode::MIRRORED_REPEAT,
        Wrap::MirrorClampToEdge if support.mirror_clamp_to_edge => {
            vk::SamplerAddressMode::MIRROR_CLAMP_TO_EDGE
        }
        Wrap::MirrorClampToEdge => {
            return Err("MIRROR_CLAMP_TO_EDGE needs samplerMirrorClampToEdge (Vulkan 1.2) or VK_KHR_sampler_mirror_clamp_to_edge, which this device lacks".into())
        }
        Wrap::Clamp => return Err("GL's CLAMP has no Vulkan address mode".into()),
    })
}

/// The Vulkan sampler and view of `case`, sampled as `kind`, on a device with `support` and a
/// format with `format`; `Err`: why it does not run here.
pub fn state(
    case: &Case,
    kind: SamplerKind,
    format: &FormatInfo,
    support: &Support,
) -> Result<SamplerState, String> {
    let s = case.sampler.in_effect();
    let t = case.texture.target;
    if s.depth_texture_mode.is_some() {
        return Err("DEPTH_TEXTURE_MODE has no Vulkan equivalent".into());
    }
    let filter = |f: Filter| match f {
        Filter::Nearest | Filter::NearestMipmapNearest | Filter::NearestMipmapLinear => {
            vk::Filter::NEAREST
        }
        Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear => {
            vk::Filter::LINEAR
        }
    };
    if s.mag_filter.is_mipmap() {
        return Err(format!(
            "magnification filter {} is not a Vulkan filter",
            s.mag_filter
        ));
    }
    let (mag, min) = (filter(s.mag_filter), filter(s.min_filter));
    let mipmap = match s.min_filter {
        Filter::NearestMipmapLinear | Filter::LinearMipmapLinear => vk::SamplerMipmapMode::LINEAR,
        _ => vk::SamplerMipmapMode::NEAREST,
    };
    let linear = mag == vk::Filter::LINEAR
        || min == vk::Filter::LINEAR
        || mipmap == vk::SamplerMipmapMode::LINEAR;
    let aspect = match kind {
        SamplerKind::Uint => vk::ImageAspectFlags::STENCIL,
        _ => vk::ImageAspectFlags::DEPTH,
    };
    match kind {
        // "Texel Filtering" / VUID-vkCmdDraw-magFilter-04553 and -mipmapMode-04770: LINEAR
        // without comparison needs SAMPLED_IMAGE_FILTER_LINEAR on the view's format.
        SamplerKind::Float | SamplerKind::Uint if linear && !format.filter_linear => {
            return Err(format!(
                "LINEAR filtering without comparison needs SAMPLED_IMAGE_FILTER_LINEAR, which {:?} lacks on this device",
                format.vk
            ))
        }
        SamplerKind::Uint if linear => {
            return Err("the stencil aspect is an integer: no LINEAR filtering".into())
        }
        // VUID-vkCmdDraw-None-06479: a comparison needs SAMPLED_IMAGE_DEPTH_COMPARISON.
        SamplerKind::Shadow if format.depth_compare == Some(false) => {
            return Err(format!(
                "{:?} lacks SAMPLED_IMAGE_DEPTH_COMPARISON on this device",
                format.vk
            ))
        }
        _ => {}
    }
    let compare = match kind {
        SamplerKind::Shadow => Some(
            compare_op(s.compare_func)
                .ok_or_else(|| format!("{} is not a Vulkan compare op", s.compare_func))?,
        ),
        _ => None,
    };
    // Coordinates the target addresses with a wrap mode; cube maps ignore the address modes
    // ("Cube Map Edge Handling") and an array's layer is clamped, not wrapped.
    let used = [true, matches!(t, Target::T2d | Target::T2dArray), false];
    let cube = t.is_cube();
    let mut modes = [vk::SamplerAddressMode::CLAMP_TO_EDGE; 3];
    for (i, w) in [s.wrap_s, s.wrap_t, s.wrap_r].into_iter().enumerate() {
        if used[i] && !cube {
            modes[i] = address(w, support)?;
        }
    }
    let bordered = modes.contains(&vk::SamplerAddressMode::CLAMP_TO_BORDER);
    let (border, custom_border) = border_color(s.border, bordered, kind, support)?;
    if s.max_lod < s.min_lod {
        // VUID-VkSamplerCreateInfo-maxLod-01973.
        return Err(format!(
            "max_lod {} below min_lod {}: Vulkan requires maxLod >= minLod",
            s.max_lod, s.min_lod
        ));
    }
    if s.lod_bias.abs() > support.max_lod_bias {
        // VUID-VkSamplerCreateInfo-mipLodBias-01069.
        return Err(format!(
            "lod bias {} beyond maxSamplerLodBias {}",
            s.lod_bias, support.max_lod_bias
        ));
    }
    let levels = case.texture.levels.len() as u32;
    let view_levels = if s.min_filter.is_mipmap() {
        match s.max_level {
            Some(m) if m < case.texture.base_level => {
                return Err(
                    "TEXTURE_MAX_LEVEL below the base level: Vulkan has no incomplete texture"
                        .into(),
                )
            }
            Some(m) => levels.min(m - case.texture.base_level + 1),
            None => levels,
        }
    } else {
        1
    };
    Ok(SamplerState {
        mag,
        min,
        mipmap,
        address: modes,
        compare,
        min_lod: s.min_lod,
        max_lod: s.max_lod,
        lod_bias: s.lod_bias,
        border,
        custom_border,
        view_levels,
        aspect,
    })
}

/// The border colour (§13 VkBorderColor): one of the fixed ones, or custom with
/// VK_EXT_custom_border_color; any colour when no coordinate clamps to the border.
fn border_color(
    c: [f32; 4],
    bordered: bool,
    kind: SamplerKind,
    support: &Support,
) -> Result<(vk::BorderColor, Option<[f32; 4]>), String> {
    let int = kind == SamplerKind::Uint;
    if !bordered {
        return Ok((
            if int {
                vk::BorderColor::INT_TRANSPARENT_BLACK
            } else {
                vk::BorderColor::FLOAT_TRANSPARENT_BLACK
            },
            None,
        ));
    }
    let fixed = match (c, int) {
        ([0.0, 0.0, 0.0, 0.0], false) => Some(vk::BorderColor::FLOAT_TRANSPARENT_BLACK),
        ([0.0, 0.0, 0.0, 1.0], false) => Some(vk::BorderColor::FLOAT_OPAQUE_BLACK),
        ([1.0, 1.0, 1.0, 1.0], false) => Some(vk::BorderColor::FLOAT_OPAQUE_WHITE),
        ([0.0, 0.0, 0.0, 0.0], true) => Some(vk::BorderColor::INT_TRANSPARENT_BLACK),
        ([0.0, 0.0, 0.0, 1.0], true) => Some(vk::BorderColor::INT_OPAQUE_BLACK),
        ([1.0, 1.0, 1.0, 1.0], true) => Some(vk::BorderColor::INT_OPAQUE_WHITE),
        _ => None,
    };
    match fixed {
        Some(b) => Ok((b, None)),
        None if int => Err(format!(
            "border colour {c:?} on the stencil aspect: not a fixed Vulkan border colour"
        )),
        None if support.custom_border => Ok((vk::BorderColor::FLOAT_CUSTOM_EXT, Some(c))),
        None => Err(format!(
            "border colour {c:?} is none of Vulkan's fixed ones and the device lacks VK_EXT_custom_border_color"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::Format;
    use shadowcheck_plan::test_case::case;

    fn d16(filter_linear: bool) -> FormatInfo {
        FormatInfo {
            format: Format::D16,
            vk: vk::Format::D16_UNORM,
            usable: true,
            filter_linear,
            depth_compare: Some(true),
        }
    }

    fn support() -> Support {
        Support {
            max_lod_bias: 15.0,
            ..Support::default()
        }
    }

    #[test]
    fn filters_compare_and_levels_follow_the_case() {
        let mut c = case(Target::T2d, 4, 4, 1);
        c.sampler.min_filter = Filter::LinearMipmapLinear;
        c.sampler.mag_filter = Filter::Linear;
        c.sampler.max_level = Some(1);
        c.texture.levels.push(c.texture.levels[0].clone());
        c.texture.levels.push(c.texture.levels[0].clone());
        let s = state(&c, SamplerKind::Shadow, &d16(false), &support()).expect("runs");
        assert_eq!(
            (s.mag, s.min, s.mipmap, s.compare, s.view_levels),
            (
                vk::Filter::LINEAR,
                vk::Filter::LINEAR,
                vk::SamplerMipmapMode::LINEAR,
                Some(vk::CompareOp::LESS_OR_EQUAL),
                2
            )
        );
        // Without comparison LINEAR needs the format's FILTER_LINEAR bit.
        let why = state(&c, SamplerKind::Float, &d16(false), &support()).unwrap_err();
        assert!(why.contains("SAMPLED_IMAGE_FILTER_LINEAR"), "{why}");
        assert!(state(&c, SamplerKind::Float, &d16(true), &support()).is_ok());
        // A non-mipmapped minification filter samples level base only.
        c.sampler.min_filter = Filter::Linear;
        let s = state(&c, SamplerKind::Shadow, &d16(false), &support()).expect("runs");
        assert_eq!(s.view_levels, 1);
    }

    #[test]
    fn borders_and_modes_the_device_lacks_are_skips() {
        let mut c = case(Target::T2d, 4, 4, 1);
        c.sampler.wrap_s = Wrap::ClampToBorder;
        c.sampler.border = [0.5, 0.0, 0.0, 0.0];
        let why = state(&c, SamplerKind::Shadow, &d16(false), &support()).unwrap_err();
        assert!(why.contains("VK_EXT_custom_border_color"), "{why}");
        let custom = Support {
            custom_border: true,
            ..support()
        };
        let s = state(&c, SamplerKind::Shadow, &d16(false), &custom).expect("custom");
        assert_eq!(s.border, vk::BorderColor::FLOAT_CUSTOM_EXT);
        c.sampler.border = [1.0; 4];
        let s = state(&c, SamplerKind::Shadow, &d16(false), &support()).expect("white");
        assert_eq!(s.border, vk::BorderColor::FLOAT_OPAQUE_WHITE);
        c.sampler.wrap_t = Wrap::MirrorClampToEdge;
        assert!(state(&c, SamplerKind::Shadow, &d16(false), &support()).is_err());
        c.sampler.lod_bias = 16.0;
        c.sampler.wrap_t = Wrap::Repeat;
        assert!(state(&c, SamplerKind::Shadow, &d16(false), &support())
            .unwrap_err()
            .contains("maxSamplerLodBias"));
    }
}
