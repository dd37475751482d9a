//! Texel storage: a texture converted once into the form the sampler reads.
//!
//! - Unorm depth (and R8 colour) integers become f32 by equation 2.1, f = c / (2^b − 1) (GL 4.6
//!   §2.3.5.1), computed as a correctly rounded f64 quotient and then rounded to f32.
//! - Floating-point depth is clamped to [0, 1] at upload (GL 4.6 §8.5, "For depth component
//!   groups, the depth value is clamped to [0, 1]", which covers DEPTH_COMPONENT32F too).
//! - Stencil indices are kept as bytes beside the depth values.
//!
//! All levels live in one `Vec<f32>` with per-level offsets, so a prepared texture is two
//! allocations, and [`PreparedTexture::prepare_into`] reuses them across cases.

use crate::faults::{Fault, Faults};
use crate::SoftError;
use shadowcheck_model::{Format, Level, Target, Texels, Texture};

/// One prepared mip level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LevelDesc {
    pub width: u32,
    pub height: u32,
    pub layers: u32,
    /// Index of the first texel of this level in the shared arrays.
    pub offset: usize,
}

/// A texture ready to be sampled: f32 depth (or colour) per texel, stencil bytes, level table.
#[derive(Debug, Clone, Default)]
pub struct PreparedTexture {
    pub(crate) target: Option<Target>,
    pub(crate) format: Option<Format>,
    pub(crate) base_level: u32,
    pub(crate) levels: Vec<LevelDesc>,
    pub(crate) data: Vec<f32>,
    /// Stencil indices, same indexing as `data`; empty when the texture has none.
    pub(crate) stencil: Vec<u8>,
    /// A colour texture of several components: every texel's (R, G, B, A) as f32, same indexing
    /// as `data` (which holds R); empty for every other texture.
    pub(crate) colour: Vec<[f32; 4]>,
    /// Number of levels, from the base, whose dimensions follow the mipmap sequence of §8.14.3.
    pub(crate) chain_len: u32,
}

impl PreparedTexture {
    /// Converts `tex` (see the module docs). `faults` may alter the conversion
    /// ([`Fault::UnormDividedByPowerOfTwo`]).
    pub fn new(tex: &Texture, faults: Faults) -> Result<PreparedTexture, SoftError> {
        let mut p = PreparedTexture::default();
        p.prepare_into(tex, faults)?;
        Ok(p)
    }

    /// Like [`PreparedTexture::new`] but reuses this value's buffers (no allocation once they are
    /// large enough): the batch path prepares every case's texture into one scratch value.
    pub fn prepare_into(&mut self, tex: &Texture, faults: Faults) -> Result<(), SoftError> {
        self.target = Some(tex.target);
        self.format = Some(tex.format);
        self.base_level = tex.base_level;
        self.levels.clear();
        self.data.clear();
        self.stencil.clear();
        self.colour.clear();
        let total: usize = tex.levels.iter().map(|l| l.texel_count()).sum();
        self.data.reserve(total);
        let has_stencil =
            tex.format.has_stencil() && tex.levels.iter().all(|l| l.stencil.is_some());
        if tex.levels.is_empty() {
            return Err(SoftError::Invalid("texture has no levels".into()));
        }
        for lvl in &tex.levels {
            let n = check_level(tex.target, lvl)?;
            self.levels.push(LevelDesc {
                width: lvl.width,
                height: lvl.height,
                layers: lvl.layers,
                offset: self.data.len(),
            });
            self.push_depth(tex.format, &lvl.depth, faults)?;
            if has_stencil {
                if let Some(s) = &lvl.stencil {
                    if s.len() != n {
                        return Err(SoftError::Invalid(format!(
                            "level has {} stencil values for {} texels",
                            s.len(),
                            n
                        )));
                    }
                    self.stencil.extend_from_slice(s);
                }
            }
        }
        self.chain_len = mip_chain_len(tex.target, &self.levels);
        Ok(())
    }

    /// Appends one level's depth (or colour) values as f32: unorm c / (2^b − 1) (GL 4.6 eq. 2.1),
    /// floats clamped to [0, 1].
    fn push_depth(
        &mut self,
        format: Format,
        depth: &Texels,
        faults: Faults,
    ) -> Result<(), SoftError> {
        let bits = format.unorm_bits();
        match (depth, bits) {
            (Texels::Unorm(v), Some(b)) => {
                let max = ((1u64 << b) - 1) as f64;
                let div = if faults.has(Fault::UnormDividedByPowerOfTwo)
                    || (faults.has(Fault::ColourDividedBy256) && format == Format::R8)
                {
                    max + 1.0
                } else {
                    max
                };
                self.data.extend(v.iter().map(|&c| unorm_to_f32(c, div)));
            }
            (Texels::Colour(v), Some(b)) if format.is_multi_colour() => {
                // Each component by eq. (2.1) with the format's bits per component.
                let div = ((1u64 << b) - 1) as f64;
                for c in v {
                    let t = c.map(|x| unorm_to_f32(x, div));
                    self.data.push(t[0]);
                    self.colour.push(t);
                }
            }
            (Texels::Float(v), None) => {
                // §8.5: depth is clamped to [0, 1] at upload, for every depth format.
                if faults.has(Fault::UploadNotClamped) {
                    self.data.extend_from_slice(v);
                } else {
                    self.data.extend(v.iter().map(|&d| clamp01(d)));
                }
            }
            _ => {
                return Err(SoftError::Invalid(format!(
                    "format {} does not store {} texels",
                    format,
                    if bits.is_some() {
                        "floating-point"
                    } else {
                        "unorm"
                    }
                )))
            }
        }
        Ok(())
    }

    /// The texture with component `i` (0..4) of a colour texture of several components in place
    /// of its R (the sampler filters each component the same way); a copy of `self` otherwise.
    pub fn component(&self, i: usize) -> PreparedTexture {
        let mut t = self.clone();
        if !self.colour.is_empty() {
            t.data = self.colour.iter().map(|c| c[i.min(3)]).collect();
        }
        t
    }

    pub fn target(&self) -> Target {
        self.target.unwrap_or(Target::T2d)
    }
    pub fn format(&self) -> Format {
        self.format.unwrap_or(Format::D16)
    }
    pub fn levels(&self) -> &[LevelDesc] {
        &self.levels
    }
    /// The texture has stencil indices for every level.
    pub fn has_stencil(&self) -> bool {
        !self.stencil.is_empty()
    }

    /// The stored value of texel (x, y, layer) of level `level` (relative to the base level).
    /// The caller guarantees the indices are in range.
    #[inline(always)]
    pub(crate) fn texel(&self, l: &LevelDesc, x: u32, y: u32, layer: u32) -> f32 {
        let idx = l.offset
            + ((layer as usize * l.height as usize + y as usize) * l.width as usize)
            + x as usize;
        self.data[idx]
    }

    #[inline(always)]
    pub(crate) fn stencil_texel(&self, l: &LevelDesc, x: u32, y: u32, layer: u32) -> f32 {
        let idx = l.offset
            + ((layer as usize * l.height as usize + y as usize) * l.width as usize)
            + x as usize;
        self.stencil.get(idx).copied().unwrap_or(0) as f32
    }

    /// `p` of §8.14.3 relative to the base level: ⌊log2(maxsize)⌋.
    pub(crate) fn max_mip_index(&self) -> u32 {
        let Some(l0) = self.levels.first() else {
            return 0;
        };
        let maxsize = match self.target() {
            Target::T1d | Target::T1dArray => l0.width,
            _ => l0.width.max(l0.height),
        };
        31 - maxsize.max(1).leading_zeros()
    }
}

/// Equation 2.1 with the divisor given (2^b − 1 normally).
#[inline]
pub fn unorm_to_f32(c: u32, div: f64) -> f32 {
    (c as f64 / div) as f32
}

/// Clamp to [0, 1]; NaN maps to 0 (the IEEE 754-2008 minNum/maxNum behaviour GPUs implement).
#[inline(always)]
#[allow(clippy::manual_clamp)] // f32::clamp keeps NaN; max/min map it to 0 on purpose
pub fn clamp01(x: f32) -> f32 {
    x.max(0.0).min(1.0)
}

/// Checks one level's structure and returns its texel count. The lookup indexes without further
/// checks, so the structure is checked here even for textures that did not go through `validate`.
fn check_level(target: Target, lvl: &Level) -> Result<usize, SoftError> {
    if lvl.width == 0 || lvl.height == 0 || lvl.layers == 0 {
        return Err(SoftError::Invalid("level with a zero dimension".into()));
    }
    if target.is_cube() && (lvl.width != lvl.height || !lvl.layers.is_multiple_of(6)) {
        return Err(SoftError::Invalid(
            "cube levels must be square with 6 faces per cube".into(),
        ));
    }
    let n = lvl.texel_count();
    if lvl.depth.len() != n {
        return Err(SoftError::Invalid(format!(
            "level has {} values for {} texels",
            lvl.depth.len(),
            n
        )));
    }
    Ok(n)
}

/// How many levels from the base follow the size sequence of §8.14.3 (level i is
/// max(1, ⌊w/2^i⌋) × max(1, ⌊h/2^i⌋), 1D heights stay 1, layer count unchanged).
fn mip_chain_len(target: Target, levels: &[LevelDesc]) -> u32 {
    let Some(l0) = levels.first() else { return 0 };
    let mut n = 0;
    for (i, l) in levels.iter().enumerate() {
        let w = (l0.width >> i.min(31)).max(1);
        let h = match target {
            Target::T1d | Target::T1dArray => 1,
            _ => (l0.height >> i.min(31)).max(1),
        };
        if l.width != w || l.height != h || l.layers != l0.layers {
            break;
        }
        n += 1;
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{Level, Texels};

    fn tex(format: Format, levels: Vec<Level>) -> Texture {
        Texture {
            target: Target::T2d,
            format,
            base_level: 0,
            levels,
        }
    }
    fn lvl(w: u32, h: u32, depth: Texels) -> Level {
        Level {
            width: w,
            height: h,
            layers: 1,
            depth,
            stencil: None,
        }
    }

    #[test]
    fn unorm_conversion_is_c_over_2b_minus_1() {
        // §2.3.5.1 equation 2.1: 0 -> 0.0, 2^b-1 -> 1.0, 32768/65535 for D16.
        let t = tex(
            Format::D16,
            vec![lvl(3, 1, Texels::Unorm(vec![0, 32768, 65535]))],
        );
        let p = PreparedTexture::new(&t, Faults::NONE).unwrap();
        assert_eq!(p.data, vec![0.0, (32768.0f64 / 65535.0) as f32, 1.0]);
        let t = tex(
            Format::D24,
            vec![lvl(1, 1, Texels::Unorm(vec![(1 << 24) - 1]))],
        );
        assert_eq!(
            PreparedTexture::new(&t, Faults::NONE).unwrap().data,
            vec![1.0]
        );
        let t = tex(Format::R8, vec![lvl(1, 1, Texels::Unorm(vec![51]))]);
        assert_eq!(
            PreparedTexture::new(&t, Faults::NONE).unwrap().data,
            vec![0.2]
        );
    }

    #[test]
    fn float_depth_is_clamped_at_upload() {
        // §8.5: depth component groups are clamped to [0, 1], D32F included.
        let t = tex(
            Format::D32f,
            vec![lvl(3, 1, Texels::Float(vec![-0.5, 0.25, 1.5]))],
        );
        assert_eq!(
            PreparedTexture::new(&t, Faults::NONE).unwrap().data,
            vec![0.0, 0.25, 1.0]
        );
    }

    #[test]
    fn mip_chain_follows_halving_sequence() {
        let z = |n| Texels::Unorm(vec![0; n]);
        // 4x2 -> 2x1 -> 1x1: complete chain of 3 levels; p = floor(log2 4) = 2.
        let t = tex(
            Format::D16,
            vec![lvl(4, 2, z(8)), lvl(2, 1, z(2)), lvl(1, 1, z(1))],
        );
        let p = PreparedTexture::new(&t, Faults::NONE).unwrap();
        assert_eq!((p.chain_len, p.max_mip_index()), (3, 2));
        // A wrong second level stops the chain.
        let t = tex(Format::D16, vec![lvl(4, 2, z(8)), lvl(2, 2, z(4))]);
        assert_eq!(PreparedTexture::new(&t, Faults::NONE).unwrap().chain_len, 1);
    }

    #[test]
    fn mismatched_texel_kind_is_an_error() {
        let t = tex(Format::D32f, vec![lvl(1, 1, Texels::Unorm(vec![0]))]);
        assert!(PreparedTexture::new(&t, Faults::NONE).is_err());
    }

    #[test]
    fn malformed_structure_is_an_error() {
        assert!(PreparedTexture::new(&tex(Format::D16, vec![]), Faults::NONE).is_err());
        let mut t = tex(Format::D16, vec![lvl(2, 2, Texels::Unorm(vec![0; 4]))]);
        t.target = Target::Cube;
        assert!(PreparedTexture::new(&t, Faults::NONE).is_err());
    }

    #[test]
    fn prepare_into_reuses_buffers() {
        let mut p = PreparedTexture::new(
            &tex(Format::D16, vec![lvl(2, 1, Texels::Unorm(vec![0, 65535]))]),
            Faults::NONE,
        )
        .unwrap();
        p.prepare_into(
            &tex(Format::D16, vec![lvl(1, 1, Texels::Unorm(vec![65535]))]),
            Faults::NONE,
        )
        .unwrap();
        assert_eq!(p.data, vec![1.0]);
        assert_eq!(p.levels.len(), 1);
    }
}
