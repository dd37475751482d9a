//! A case's texture as a Vulkan image: its shape (image type, extent, levels, layers: Vulkan 1.3
//! "Images"), the bytes of its depth and stencil aspects as vkCmdCopyBufferToImage reads them
//! ("Copying Data Between Buffers and Images": D16 as 16-bit words; X8_D24 and D24S8's depth
//! aspect as 32-bit words with the value in the 24 low bits; D32_SFLOAT and D32_SFLOAT_S8's depth
//! aspect as floats; a stencil aspect as bytes), and the texels read back from level base.

use crate::device::FormatInfo;
use ash::vk;
use shadowcheck_model::{Case, Format, Level, Target, Texels};

/// The image a case needs.
#[derive(Debug, Clone, PartialEq)]
pub struct Shape {
    pub image_type: vk::ImageType,
    pub view_type: vk::ImageViewType,
    pub extent: vk::Extent3D,
    pub levels: u32,
    pub layers: u32,
    pub flags: vk::ImageCreateFlags,
}

/// The image of `case`'s texture, or why Vulkan has none like it (levels that are not the mip
/// chain of level base, layers that change with the level).
pub fn shape(case: &Case) -> Result<Shape, String> {
    let t = &case.texture;
    let base = t.levels.first().ok_or("no levels")?;
    let one_d = t.target.dims() == 1;
    let (w, h) = (base.width, if one_d { 1 } else { base.height });
    if w == 0 || h == 0 || base.layers == 0 {
        return Err("an empty level".into());
    }
    for (i, l) in t.levels.iter().enumerate() {
        let want = (
            (w >> i).max(1),
            if one_d { 1 } else { (h >> i).max(1) },
            base.layers,
        );
        if (l.width, if one_d { 1 } else { l.height }, l.layers) != want {
            return Err(format!(
                "level base+{i} is {}x{}x{}, not the mip level {}x{}x{} Vulkan images have",
                l.width, l.height, l.layers, want.0, want.1, want.2
            ));
        }
        if l.depth.len() != l.texel_count() {
            return Err(format!(
                "level base+{i}: texel count does not match its size"
            ));
        }
    }
    let (image_type, view_type) = match t.target {
        Target::T1d => (vk::ImageType::TYPE_1D, vk::ImageViewType::TYPE_1D),
        Target::T1dArray => (vk::ImageType::TYPE_1D, vk::ImageViewType::TYPE_1D_ARRAY),
        Target::T2d => (vk::ImageType::TYPE_2D, vk::ImageViewType::TYPE_2D),
        Target::T2dArray => (vk::ImageType::TYPE_2D, vk::ImageViewType::TYPE_2D_ARRAY),
        Target::Cube => (vk::ImageType::TYPE_2D, vk::ImageViewType::CUBE),
        Target::CubeArray => (vk::ImageType::TYPE_2D, vk::ImageViewType::CUBE_ARRAY),
        Target::Rect => return Err("Vulkan has no rectangle textures".into()),
    };
    let cube = t.target.is_cube();
    if cube && (w != h || base.layers % 6 != 0) {
        return Err("a cube level must be square with 6 layers per cube".into());
    }
    if !t.target.is_array() && !cube && base.layers != 1 {
        return Err(format!("{} texture with {} layers", t.target, base.layers));
    }
    Ok(Shape {
        image_type,
        view_type,
        extent: vk::Extent3D {
            width: w,
            height: h,
            depth: 1,
        },
        levels: t.levels.len() as u32,
        layers: base.layers,
        flags: if cube {
            vk::ImageCreateFlags::CUBE_COMPATIBLE
        } else {
            vk::ImageCreateFlags::empty()
        },
    })
}

/// The depth aspect's bytes of one level. Float depth is clamped to [0, 1] first: a copy of a
/// value outside into D32_SFLOAT is invalid usage without VK_EXT_depth_range_unrestricted
/// (VUID-vkCmdCopyBufferToImage-pRegions-07931 ... "must be in the range [0,1]"), as GL's upload
/// clamps it (GL 4.6 §8.5).
pub fn depth_bytes(format: Format, level: &Level) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(level.texel_count() * 4);
    match (&level.depth, format) {
        (Texels::Unorm(v), Format::D16) => {
            for &c in v {
                let c = u16::try_from(c).map_err(|_| format!("D16 texel {c} above 65535"))?;
                out.extend_from_slice(&c.to_ne_bytes());
            }
        }
        (Texels::Unorm(v), Format::D24 | Format::D24S8) => {
            for &c in v {
                if c >= 1 << 24 {
                    return Err(format!("D24 texel {c} above 2^24-1"));
                }
                out.extend_from_slice(&c.to_ne_bytes());
            }
        }
        (Texels::Float(v), Format::D32f | Format::D32fS8) => {
            for &f in v {
                out.extend_from_slice(&f.clamp(0.0, 1.0).to_ne_bytes());
            }
        }
        _ => return Err(format!("texel encoding does not match format {format}")),
    }
    Ok(out)
}

/// The stencil aspect's bytes of one level: the level's stencil indices, else 0.
pub fn stencil_bytes(level: &Level) -> Vec<u8> {
    (0..level.texel_count())
        .map(|i| {
            level
                .stencil
                .as_ref()
                .and_then(|s| s.get(i))
                .copied()
                .unwrap_or(0)
        })
        .collect()
}

/// Bytes a texel of the depth aspect takes in a buffer copy.
pub fn depth_texel_bytes(format: Format) -> usize {
    if format == Format::D16 {
        2
    } else {
        4
    }
}

/// The texels read back from a depth aspect (`bytes` as [`depth_bytes`] writes them; the 8 high
/// bits of a D24 word are undefined and dropped).
pub fn decode(format: Format, bytes: &[u8]) -> Texels {
    let words = || {
        bytes
            .chunks_exact(4)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
    };
    match format {
        Format::D16 => Texels::Unorm(
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]) as u32)
                .collect(),
        ),
        Format::D32f | Format::D32fS8 => Texels::Float(words().map(f32::from_bits).collect()),
        _ => Texels::Unorm(words().map(|w| w & 0x00ff_ffff).collect()),
    }
}

/// The aspects an image of `f` has (a barrier names them all).
pub fn aspects(f: &FormatInfo) -> vk::ImageAspectFlags {
    if f.format.has_stencil() {
        vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL
    } else {
        vk::ImageAspectFlags::DEPTH
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_plan::test_case::case;

    #[test]
    fn texels_go_up_and_come_back_in_the_fixture_encoding() {
        let mut c = case(Target::T2d, 2, 1, 1);
        c.texture.levels[0].depth = Texels::Unorm(vec![0, 65535]);
        let b = depth_bytes(Format::D16, &c.texture.levels[0]).expect("d16");
        assert_eq!(decode(Format::D16, &b), c.texture.levels[0].depth);
        c.texture.levels[0].depth = Texels::Unorm(vec![1, 0xff_ffff]);
        let mut b = depth_bytes(Format::D24S8, &c.texture.levels[0]).expect("d24");
        b[3] = 0xab; // the undefined high byte of the first word
        assert_eq!(decode(Format::D24S8, &b), Texels::Unorm(vec![1, 0xff_ffff]));
        c.texture.levels[0].depth = Texels::Float(vec![-0.5, 0.25]);
        let b = depth_bytes(Format::D32f, &c.texture.levels[0]).expect("d32f");
        assert_eq!(decode(Format::D32f, &b), Texels::Float(vec![0.0, 0.25]));
        assert!(depth_bytes(Format::D16, &c.texture.levels[0]).is_err());
    }

    #[test]
    fn shapes_follow_the_target_and_reject_what_is_not_a_mip_chain() {
        let mut c = case(Target::CubeArray, 4, 4, 12);
        let s = shape(&c).expect("cube array");
        assert_eq!((s.view_type, s.layers), (vk::ImageViewType::CUBE_ARRAY, 12));
        assert!(s.flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE));
        let mut l1 = c.texture.levels[0].clone();
        l1.width = 3;
        c.texture.levels.push(l1);
        assert!(shape(&c).unwrap_err().contains("not the mip level"));
        let c = case(Target::T1dArray, 4, 1, 3);
        let s = shape(&c).expect("1d array");
        assert_eq!(
            (s.image_type, s.extent.height, s.layers),
            (vk::ImageType::TYPE_1D, 1, 3)
        );
    }
}
