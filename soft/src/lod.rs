//! Level of detail and mip level selection (GL 4.6 §8.14.1, §8.14.3, §8.15; ES 3.2 same sections).
//!
//! λ′ = λ_base + bias_texobj + bias_shader (8.8; ES has no bias_texobj), λ = clamp(λ′, lod_min,
//! lod_max) (8.9). λ ≤ 0 magnifies (level_base, TEXTURE_MAG_FILTER), λ > 0 minifies.
//! The implementation-defined clamp of the bias sum to ±MAX_TEXTURE_LOD_BIAS is not applied.

use crate::faults::{Fault, Faults};
use shadowcheck_model::Filter;

/// What to sample for one lookup: one level, or two levels blended with weight `frac` on `d2`.
/// Levels are absolute level numbers (level_base is the first stored level).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LevelChoice {
    /// Sample level `level` with LINEAR (true) or NEAREST (false) filtering within it.
    Single { level: u32, linear: bool },
    /// Sample `d1` and `d2`, τ = (1 − frac(λ)) τ1 + frac(λ) τ2 (§8.14.3).
    Blend {
        d1: u32,
        d2: u32,
        frac: f32,
        linear: bool,
    },
}

/// Level parameters that do not depend on the lookup.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LodParams {
    pub lod_bias: f32,
    pub min_lod: f32,
    pub max_lod: f32,
    pub level_base: u32,
    /// q = min(p, level_max) of §8.14.3 (absolute level number).
    pub q: u32,
    pub min_filter: Filter,
    pub mag_filter: Filter,
}

/// λ of equation 8.9, in f32.
#[inline(always)]
pub fn lambda(p: &LodParams, lambda_base: f32, shader_bias: f32, faults: Faults) -> f32 {
    let texobj = if faults.has(Fault::LodBiasIgnored) {
        0.0
    } else {
        p.lod_bias
    };
    let l = lambda_base + (texobj + shader_bias);
    if faults.has(Fault::LodClampIgnored) {
        l
    } else {
        // Explicit comparisons keep NaN out of the clamp's way: a NaN λ′ becomes lod_min.
        if l > p.max_lod {
            p.max_lod
        } else if l >= p.min_lod {
            l
        } else {
            p.min_lod
        }
    }
}

/// Chooses level(s) and filter for λ (§8.14.3, §8.15).
#[inline]
pub fn choose(p: &LodParams, lambda: f32, faults: Faults) -> LevelChoice {
    if lambda <= 0.0 {
        // §8.15: magnification always uses level_base.
        return LevelChoice::Single {
            level: p.level_base,
            linear: p.mag_filter != Filter::Nearest,
        };
    }
    let base = p.level_base as f32;
    let q = p.q;
    let x = base + lambda;
    match p.min_filter {
        Filter::Nearest => LevelChoice::Single {
            level: p.level_base,
            linear: false,
        },
        Filter::Linear => LevelChoice::Single {
            level: p.level_base,
            linear: true,
        },
        Filter::NearestMipmapNearest | Filter::LinearMipmapNearest => {
            // (8.14): d = nearest(λ) if level_base + λ ≤ q + ½, else q;
            // nearest(λ) = ⌈level_base + λ + ½⌉ − 1 (the preferred form).
            let mut d = if x <= q as f32 + 0.5 {
                // ⌈y⌉ − 1 for y = x + ½ > 0, without a libm call: truncate, round up non-integers.
                let y = x + 0.5;
                let t = y as u32;
                if (t as f32) < y {
                    t
                } else {
                    t - 1
                }
            } else {
                q
            };
            if faults.has(Fault::MipLevelOffByOne) {
                d = (d + 1).min(q);
            }
            LevelChoice::Single {
                level: d.min(q),
                linear: p.min_filter == Filter::LinearMipmapNearest,
            }
        }
        Filter::NearestMipmapLinear | Filter::LinearMipmapLinear => {
            let linear = p.min_filter == Filter::LinearMipmapLinear;
            // (8.15), (8.16): d1 = d2 = q if level_base + λ ≥ q, else ⌊level_base + λ⌋ and d1 + 1.
            if x >= q as f32 {
                LevelChoice::Single { level: q, linear }
            } else {
                let d1 = x as u32; // x > 0: truncation is ⌊x⌋
                if faults.has(Fault::TrilinearNoBlend) {
                    return LevelChoice::Single { level: d1, linear };
                }
                let frac = crate::wrap::floor_frac(lambda).1;
                LevelChoice::Blend {
                    d1,
                    d2: d1 + 1,
                    frac,
                    linear,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const F: Faults = Faults::NONE;

    fn params(min: Filter, base: u32, q: u32) -> LodParams {
        LodParams {
            lod_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            level_base: base,
            q,
            min_filter: min,
            mag_filter: Filter::Linear,
        }
    }

    #[test]
    fn lambda_adds_biases_then_clamps() {
        let mut p = params(Filter::Linear, 0, 0);
        p.lod_bias = 0.5;
        assert_eq!(lambda(&p, 1.0, 0.25, F), 1.75);
        p.max_lod = 1.5;
        assert_eq!(lambda(&p, 1.0, 0.25, F), 1.5);
        p.min_lod = 0.5;
        assert_eq!(lambda(&p, -3.0, 0.0, F), 0.5);
        assert_eq!(lambda(&p, 1.0, 0.25, F.with(Fault::LodClampIgnored)), 1.75);
        assert_eq!(lambda(&p, 1.0, 0.0, F.with(Fault::LodBiasIgnored)), 1.0);
    }

    #[test]
    fn magnification_uses_base_level_and_mag_filter() {
        let mut p = params(Filter::NearestMipmapNearest, 2, 5);
        p.mag_filter = Filter::Nearest;
        assert_eq!(
            choose(&p, 0.0, F),
            LevelChoice::Single {
                level: 2,
                linear: false
            }
        );
        assert_eq!(
            choose(&p, -1.0, F),
            LevelChoice::Single {
                level: 2,
                linear: false
            }
        );
    }

    #[test]
    fn nearest_mipmap_rounding_8_14() {
        let p = params(Filter::NearestMipmapNearest, 0, 3);
        // nearest(λ) = ⌈λ + ½⌉ − 1: λ = 0.5 -> 0 (preferred form rounds the half down), 0.51 -> 1.
        let lv = |l: f32| match choose(&p, l, F) {
            LevelChoice::Single { level, .. } => level,
            c => panic!("{c:?}"),
        };
        assert_eq!(lv(0.5), 0);
        assert_eq!(lv(0.51), 1);
        assert_eq!(lv(1.49), 1);
        assert_eq!(lv(1.5), 1);
        assert_eq!(lv(3.5), 3);
        assert_eq!(lv(3.6), 3); // beyond q + ½: q
        assert_eq!(lv(100.0), 3);
        // level_base 1: d = ⌈1 + λ + ½⌉ − 1.
        let p = params(Filter::LinearMipmapNearest, 1, 3);
        assert_eq!(
            choose(&p, 0.75, F),
            LevelChoice::Single {
                level: 2,
                linear: true
            }
        );
        assert_eq!(
            choose(&p, 0.75, F.with(Fault::MipLevelOffByOne)),
            LevelChoice::Single {
                level: 3,
                linear: true
            }
        );
    }

    #[test]
    fn linear_mipmap_levels_8_15_8_16() {
        let p = params(Filter::LinearMipmapLinear, 0, 2);
        assert_eq!(
            choose(&p, 0.25, F),
            LevelChoice::Blend {
                d1: 0,
                d2: 1,
                frac: 0.25,
                linear: true
            }
        );
        assert_eq!(
            choose(&p, 1.75, F),
            LevelChoice::Blend {
                d1: 1,
                d2: 2,
                frac: 0.75,
                linear: true
            }
        );
        assert_eq!(
            choose(&p, 2.0, F),
            LevelChoice::Single {
                level: 2,
                linear: true
            }
        );
        assert_eq!(
            choose(&p, 7.0, F),
            LevelChoice::Single {
                level: 2,
                linear: true
            }
        );
        let p = params(Filter::NearestMipmapLinear, 1, 3);
        assert_eq!(
            choose(&p, 1.5, F),
            LevelChoice::Blend {
                d1: 2,
                d2: 3,
                frac: 0.5,
                linear: false
            }
        );
    }

    #[test]
    fn non_mipmap_min_filters_use_base() {
        assert_eq!(
            choose(&params(Filter::Linear, 1, 4), 2.0, F),
            LevelChoice::Single {
                level: 1,
                linear: true
            }
        );
        assert_eq!(
            choose(&params(Filter::Nearest, 0, 4), 2.0, F),
            LevelChoice::Single {
                level: 0,
                linear: false
            }
        );
    }
}
