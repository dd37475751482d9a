//! The bytes of a case's texture as an API uploads them: the pixel transfer (internal format,
//! format, type, bytes per texel) and the bytes of every level, layer and face in upload order, and
//! the decoding of bytes read back into the fixture's encoding.
//!
//! Unorm formats are uploaded as integers at (or above) the format's bit depth so the stored value
//! is the case's integer whatever rounding the driver does for floats (a FLOAT upload to
//! DEPTH_COMPONENT24 is converted by the implementation, GL 4.6 §8.4.4.2, and Mesa truncates there).

use crate::gl;
use crate::PlanError;
use shadowcheck_model::{Case, Format, Level, Spec, Texels};

/// The transfer of a case's texture: the legacy specs (SGIX_shadow, ARB_shadow, EXT_shadow_funcs)
/// know the colour texture as LUMINANCE8 (GL 2.1 Table 3.20), GL 3.0+ and ES as R8.
pub fn transfer_for(case: &Case) -> (i32, u32, u32, usize) {
    let legacy = matches!(
        case.spec,
        Spec::Sgix | Spec::SgixAmbient | Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs
    );
    if case.texture.format == Format::R8 && legacy {
        const LUMINANCE8: i32 = 0x8040;
        const LUMINANCE: u32 = 0x1909;
        return (LUMINANCE8, LUMINANCE, gl::UNSIGNED_BYTE, 1);
    }
    transfer(case.texture.format)
}

/// Pixel transfer format/type for a texture format: (internal format, format, type, bytes/texel).
pub fn transfer(format: Format) -> (i32, u32, u32, usize) {
    match format {
        Format::D16 => (
            gl::DEPTH_COMPONENT16 as i32,
            gl::DEPTH_COMPONENT,
            gl::UNSIGNED_SHORT,
            2,
        ),
        Format::DepthUnsized => (
            gl::DEPTH_COMPONENT as i32,
            gl::DEPTH_COMPONENT,
            gl::UNSIGNED_SHORT,
            2,
        ),
        Format::D24 => (
            gl::DEPTH_COMPONENT24 as i32,
            gl::DEPTH_COMPONENT,
            gl::UNSIGNED_INT,
            4,
        ),
        Format::D32 => (
            gl::DEPTH_COMPONENT32 as i32,
            gl::DEPTH_COMPONENT,
            gl::UNSIGNED_INT,
            4,
        ),
        Format::D32f => (
            gl::DEPTH_COMPONENT32F as i32,
            gl::DEPTH_COMPONENT,
            gl::FLOAT,
            4,
        ),
        Format::D24S8 => (
            gl::DEPTH24_STENCIL8 as i32,
            gl::DEPTH_STENCIL,
            gl::UNSIGNED_INT_24_8,
            4,
        ),
        Format::D32fS8 => (
            gl::DEPTH32F_STENCIL8 as i32,
            gl::DEPTH_STENCIL,
            gl::FLOAT_32_UNSIGNED_INT_24_8_REV,
            8,
        ),
        Format::R8 => (gl::R8 as i32, gl::RED, gl::UNSIGNED_BYTE, 1),
        // The colour formats of several components: one byte a component, RGBA4 as one packed
        // UNSIGNED_SHORT_4_4_4_4 (R in the top four bits, GL 4.6 Table 8.8), so the stored
        // integers are the case's (§8.4.4.2: a packed component of b bits is c / (2^b - 1)).
        Format::Rg8 => (gl::RG8 as i32, gl::RG, gl::UNSIGNED_BYTE, 2),
        Format::Rgb8 => (gl::RGB8 as i32, gl::RGB, gl::UNSIGNED_BYTE, 3),
        Format::Rgba8 => (gl::RGBA8 as i32, gl::RGBA, gl::UNSIGNED_BYTE, 4),
        Format::Rgba4 => (gl::RGBA4 as i32, gl::RGBA, gl::UNSIGNED_SHORT_4_4_4_4, 2),
    }
}

/// A 24-bit unorm integer as a 32-bit unorm integer that converts to it under every conversion a
/// driver may use (GL 4.6 §2.3.5 allows either neighbour): the 32-bit value is c + 1/4 steps of
/// 2^24-1 (c * (2^32-1)/(2^24-1) + (2^32-1)/(2^24-1)/4, rounded), so rounding and truncation both give c
/// (Mesa truncates: plain bit replication stored 1..65535 as one less), and the low byte is
/// clamped so that dropping it also gives c.
fn widen24(c: u32) -> u32 {
    const R: f64 = 4294967295.0 / 16777215.0;
    let low = ((c as f64 + 0.25) * R - 256.0 * c as f64)
        .round()
        .clamp(0.0, 255.0) as u32;
    (c << 8) | low
}

/// The bytes to upload for one level.
pub fn level_bytes(format: Format, level: &Level) -> Result<Vec<u8>, PlanError> {
    let n = level.texel_count();
    let stencil = |i: usize| {
        level
            .stencil
            .as_ref()
            .and_then(|s| s.get(i))
            .copied()
            .unwrap_or(0) as u32
    };
    let mut out = Vec::with_capacity(n * transfer(format).3);
    match (&level.depth, format) {
        (Texels::Unorm(v), Format::D16 | Format::DepthUnsized) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&(c as u16).to_ne_bytes())),
        (Texels::Unorm(v), Format::D24) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&widen24(c).to_ne_bytes())),
        (Texels::Unorm(v), Format::D32) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&c.to_ne_bytes())),
        (Texels::Unorm(v), Format::D24S8) => v
            .iter()
            .enumerate()
            .for_each(|(i, &c)| out.extend_from_slice(&((c << 8) | stencil(i)).to_ne_bytes())),
        (Texels::Unorm(v), Format::R8) => v.iter().for_each(|&c| out.push(c as u8)),
        (Texels::Colour(v), Format::Rg8 | Format::Rgb8 | Format::Rgba8) => {
            let n = format.components();
            v.iter()
                .for_each(|c| out.extend(c[..n].iter().map(|&x| x as u8)))
        }
        (Texels::Colour(v), Format::Rgba4) => v.iter().for_each(|c| {
            let packed = c.iter().fold(0u16, |acc, &x| (acc << 4) | (x as u16 & 0xF));
            out.extend_from_slice(&packed.to_ne_bytes())
        }),
        (Texels::Float(v), Format::D32f) => v
            .iter()
            .for_each(|&f| out.extend_from_slice(&f.to_ne_bytes())),
        (Texels::Float(v), Format::D32fS8) => v.iter().enumerate().for_each(|(i, &f)| {
            out.extend_from_slice(&f.to_ne_bytes());
            out.extend_from_slice(&stencil(i).to_ne_bytes());
        }),
        _ => return Err(PlanError::Encoding(format)),
    }
    Ok(out)
}

/// Decodes read-back bytes into the fixture's encoding.
pub fn decode_stored(format: Format, bytes: &[u8]) -> Texels {
    let u32s = |step: usize| {
        bytes
            .chunks_exact(step)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
    };
    match format {
        Format::D16 | Format::DepthUnsized => Texels::Unorm(
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]) as u32)
                .collect(),
        ),
        // UNSIGNED_INT from a 24-bit store: c * (2^32-1)/(2^24-1) rounded; the top 24 bits are c.
        Format::D24 | Format::D24S8 => Texels::Unorm(u32s(4).map(|u| u >> 8).collect()),
        Format::D32 => Texels::Unorm(u32s(4).collect()),
        Format::D32f => Texels::Float(u32s(4).map(f32::from_bits).collect()),
        Format::D32fS8 => Texels::Float(u32s(8).map(f32::from_bits).collect()),
        Format::R8 => Texels::Unorm(bytes.iter().map(|&b| b as u32).collect()),
        Format::Rg8 | Format::Rgb8 | Format::Rgba8 => {
            let n = format.components();
            Texels::Colour(
                bytes
                    .chunks_exact(n)
                    .map(|c| {
                        let mut t = [0u32; 4];
                        c.iter().enumerate().for_each(|(i, &b)| t[i] = b as u32);
                        t
                    })
                    .collect(),
            )
        }
        Format::Rgba4 => Texels::Colour(
            bytes
                .chunks_exact(2)
                .map(|c| {
                    let p = u16::from_ne_bytes([c[0], c[1]]) as u32;
                    [(p >> 12) & 0xF, (p >> 8) & 0xF, (p >> 4) & 0xF, p & 0xF]
                })
                .collect(),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn d24_widening_is_exact_under_rounding_truncation_and_shift() {
        // GL 4.6 §2.3.5: f = c / (2^b - 1); a driver may round or truncate c32 * (2^24-1)/(2^32-1),
        // or drop the low byte. Every 24-bit value must survive all three (exact integer arithmetic).
        let (m24, m32) = ((1u64 << 24) - 1, (1u64 << 32) - 1);
        for c in (0..=m24 as u32)
            .step_by(97)
            .chain([1, 2, 65535, 0xFFFFFE, 0xFFFFFF])
        {
            let u = widen24(c) as u64;
            assert_eq!(u * m24 / m32, c as u64, "truncating {c}");
            assert!(2 * u * m24 < (2 * c as u64 + 1) * m32, "rounding {c}");
            assert_eq!(u >> 8, c as u64, "dropping the low byte {c}");
        }
    }

    #[test]
    fn level_bytes_pack_stencil_and_floats() {
        let lvl = Level {
            width: 2,
            height: 1,
            layers: 1,
            depth: Texels::Unorm(vec![1, 0xFFFFFF]),
            stencil: Some(vec![7, 9]),
        };
        let b = level_bytes(Format::D24S8, &lvl).unwrap();
        assert_eq!(u32::from_ne_bytes([b[0], b[1], b[2], b[3]]), (1 << 8) | 7);
        assert_eq!(
            decode_stored(Format::D24S8, &b),
            Texels::Unorm(vec![1, 0xFFFFFF])
        );
        let f = Level {
            width: 1,
            height: 1,
            layers: 1,
            depth: Texels::Float(vec![0.25]),
            stencil: None,
        };
        let b = level_bytes(Format::D32fS8, &f).unwrap();
        assert_eq!(b.len(), 8);
        assert_eq!(decode_stored(Format::D32fS8, &b), Texels::Float(vec![0.25]));
    }

    #[test]
    fn colour_texels_upload_their_components_and_decode_back() {
        let lvl = |texels: Vec<[u32; 4]>| Level {
            width: texels.len() as u32,
            height: 1,
            layers: 1,
            depth: Texels::Colour(texels),
            stencil: None,
        };
        // RGB8: three bytes a texel, A (absent) not uploaded.
        let rgb = lvl(vec![[1, 2, 3, 0], [4, 5, 6, 0]]);
        let b = level_bytes(Format::Rgb8, &rgb).unwrap();
        assert_eq!(b, vec![1, 2, 3, 4, 5, 6]);
        assert_eq!(decode_stored(Format::Rgb8, &b), rgb.depth);
        assert_eq!(transfer(Format::Rgb8).3, 3);
        // RGBA4: UNSIGNED_SHORT_4_4_4_4, R in the top four bits.
        let rgba4 = lvl(vec![[0xA, 0xB, 0xC, 0xD]]);
        let b = level_bytes(Format::Rgba4, &rgba4).unwrap();
        assert_eq!(u16::from_ne_bytes([b[0], b[1]]), 0xABCD);
        assert_eq!(decode_stored(Format::Rgba4, &b), rgba4.depth);
        // RG8 and RGBA8.
        let rg = lvl(vec![[9, 8, 0, 0]]);
        assert_eq!(level_bytes(Format::Rg8, &rg).unwrap(), vec![9, 8]);
        let rgba = lvl(vec![[9, 8, 7, 6]]);
        assert_eq!(level_bytes(Format::Rgba8, &rgba).unwrap(), vec![9, 8, 7, 6]);
        // Unorm texels are no colour encoding.
        assert!(level_bytes(
            Format::Rgba8,
            &Level {
                depth: Texels::Unorm(vec![1]),
                ..rgba
            }
        )
        .is_err());
    }
}
