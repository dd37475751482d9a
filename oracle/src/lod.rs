//! Level of detail, mipmap level selection and completeness: GL 4.6 §8.14.1, §8.14.3, §8.15, §8.17
//! (ES 3.2 the same sections; no TEXTURE_LOD_BIAS in ES).

use crate::rules::Rules;
use shadowcheck_model::{CompareMode, Filter, Sampler, Target, Texture};

/// The smallest MAX_TEXTURE_LOD_BIAS an implementation may have (GL 4.6 Table 23.53: 2.0). A bias sum
/// beyond it may or may not be clamped: "The sum of these values is clamped to the range
/// [−bias_max, bias_max] where bias_max is the value of the implementation defined constant".
pub const MIN_MAX_TEXTURE_LOD_BIAS: f64 = 2.0;

/// λ as the spec computes it and the range an implementation may use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lambda {
    pub spec: f64,
    pub lo: f64,
    pub hi: f64,
    /// Why the range is wider than a point (implementation-defined choices), if it is.
    pub note: Option<&'static str>,
}

/// (8.8) "λ′ = λ_base + clamp(bias_texobj + bias_shader)" and (8.9) the clamp to [lod_min, lod_max].
/// `lod`, `bias` are the lookup's (already f32); `texobj_bias` is TEXTURE_LOD_BIAS (0 in ES).
pub fn lambda(lod: f64, texobj_bias: f64, bias: f64, s: &Sampler) -> Lambda {
    let sum = texobj_bias + bias;
    let clamped = sum.clamp(-MIN_MAX_TEXTURE_LOD_BIAS, MIN_MAX_TEXTURE_LOD_BIAS);
    let mut note = None;
    let (mut lo, mut hi, spec) = (lod + clamped.min(sum), lod + clamped.max(sum), lod + sum);
    if clamped != sum {
        note = Some(
            "the bias sum exceeds the minimum MAX_TEXTURE_LOD_BIAS (2.0); whether it is clamped is implementation-defined (GL 4.6 §8.14.1)",
        );
    }
    let (mn, mx) = (s.min_lod as f64, s.max_lod as f64);
    // (8.9): "undefined, lod_min > lod_max"
    if mn > mx {
        return Lambda {
            spec: f64::NAN,
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
            note: Some("TEXTURE_MIN_LOD > TEXTURE_MAX_LOD: λ is undefined (GL 4.6 §8.14.1 (8.9))"),
        };
    }
    lo = lo.clamp(mn, mx);
    hi = hi.clamp(mn, mx);
    Lambda {
        spec: spec.clamp(mn, mx),
        lo,
        hi,
        note,
    }
}

/// §8.14.3: "maxsize = w_s (1D, 1D array), max(w_s, h_s) (2D, 2D array, cube map, cube map array)";
/// "there are ⌊log2(maxsize)⌋ + 1 levels". Returns q relative to level_base (q − level_base), or
/// `None` when level_base > level_max.
pub fn q_rel(tex: &Texture, s: &Sampler) -> Option<u32> {
    let l0 = &tex.levels[0];
    let maxsize = match tex.target {
        Target::T1d | Target::T1dArray => l0.width,
        _ => l0.width.max(l0.height),
    };
    let p = 31 - maxsize.max(1).leading_zeros(); // ⌊log2(maxsize)⌋
    let max_level = s.max_level.unwrap_or(1000);
    if max_level < tex.base_level {
        return None;
    }
    // "q = min(p, level_max)"
    Some(p.min(max_level - tex.base_level))
}

/// §8.17 "A texture is mipmap complete if ... The dimensions of the images follow the sequence described
/// in section 8.14.3 ... level_base ≤ level_max". Returns why not, if not.
pub fn mipmap_incomplete(tex: &Texture, s: &Sampler) -> Option<String> {
    let Some(q) = q_rel(tex, s) else {
        return Some("TEXTURE_BASE_LEVEL > TEXTURE_MAX_LEVEL".into());
    };
    let l0 = &tex.levels[0];
    for i in 0..=q {
        let Some(l) = tex.levels.get(i as usize) else {
            return Some(format!(
                "level base+{i} is missing (mipmap levels base..q = base+{q} must be defined)"
            ));
        };
        let w = (l0.width >> i).max(1);
        let h = if matches!(tex.target, Target::T1d | Target::T1dArray) {
            1
        } else {
            (l0.height >> i).max(1)
        };
        if l.width != w || l.height != h || l.layers != l0.layers {
            return Some(format!(
                "level base+{i} is {}x{}x{}, expected {w}x{h}x{}",
                l.width, l.height, l.layers, l0.layers
            ));
        }
    }
    None
}

/// §8.17 "A texture is complete unless any of the following conditions hold true": why this one is
/// not, if it is not (`stencil`: read in STENCIL_INDEX mode).
pub fn incomplete(rules: &Rules, tex: &Texture, s: &Sampler, stencil: bool) -> Option<String> {
    let fmt = tex.format;
    // "The minification filter requires a mimap ... and the texture is not mipmap complete."
    if s.min_filter.is_mipmap() {
        if let Some(why) = mipmap_incomplete(tex, s) {
            return Some(format!("not mipmap complete: {why}"));
        }
    }
    // "either the magnification filter is not NEAREST, or the minification filter is neither NEAREST
    // nor NEAREST_MIPMAP_NEAREST; and any of ..."
    let nearest_only = s.mag_filter == Filter::Nearest
        && matches!(s.min_filter, Filter::Nearest | Filter::NearestMipmapNearest);
    if nearest_only {
        return None;
    }
    // "The internal format of the texture is DEPTH_STENCIL, and the value of
    // DEPTH_STENCIL_TEXTURE_MODE for the texture is STENCIL_INDEX."
    if stencil {
        return Some(
            "DEPTH_STENCIL in STENCIL_INDEX mode with a non-NEAREST filter (§8.17)".into(),
        );
    }
    // ES 3.2 only: "The effective internal format specified for the texture images is a sized
    // internal depth or depth and stencil format (see table 8.11), and the value of
    // TEXTURE_COMPARE_MODE is NONE."
    if rules.es_depth_completeness
        && fmt.is_depth()
        && fmt.is_sized()
        && s.compare_mode == CompareMode::None
    {
        return Some("\"a sized internal depth or depth and stencil format ... and the value of TEXTURE_COMPARE_MODE is NONE\" with non-NEAREST filtering (ES 3.2 §8.17)".into());
    }
    None
}

/// One way the lookup may use the mipmap: a single level or two blended levels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pick {
    /// Level `level` (relative to base), filtered NEAREST (`linear` false) or LINEAR.
    One { level: u32, linear: bool },
    /// "τ = [1 − frac(λ)]τ1 + frac(λ)τ2" with frac(λ) in [f_lo, f_hi] (f: the spec's frac(λ)).
    Two {
        d1: u32,
        d2: u32,
        linear: bool,
        f: f64,
        f_lo: f64,
        f_hi: f64,
    },
}

fn within(f: Filter) -> bool {
    matches!(
        f,
        Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear
    )
}

/// "nearest(λ) = ⌈level_base + λ + 1/2⌉ − 1 (preferred) or ⌊level_base + λ + 1/2⌋ (alternative)",
/// relative to level_base, with (8.14)'s "q, λ > 0, level_base + λ > q + 1/2".
fn nearest_level(l: f64, q: u32, preferred: bool) -> u32 {
    if l > q as f64 + 0.5 {
        return q;
    }
    let d = if preferred {
        (l + 0.5).ceil() - 1.0
    } else {
        (l + 0.5).floor()
    };
    d.clamp(0.0, q as f64) as u32
}

/// The picks for λ in [lo, hi] (§8.14.1: "If λ(x,y) is less than or equal to zero, the texture is said to
/// be magnified; if it is greater, the texture is minified"; §8.15: "The level-of-detail level_base
/// texture image is always used for magnification"). `q` is None for non-mipmapped use.
pub fn picks(s: &Sampler, lo: f64, hi: f64, q: u32, out: &mut Vec<Pick>) {
    if lo <= 0.0 {
        push(
            out,
            Pick::One {
                level: 0,
                linear: s.mag_filter == Filter::Linear,
            },
        );
    }
    if hi <= 0.0 {
        return;
    }
    let a = lo.max(0.0);
    let lin = within(s.min_filter);
    match s.min_filter {
        Filter::Nearest | Filter::Linear => push(
            out,
            Pick::One {
                level: 0,
                linear: lin,
            },
        ),
        Filter::NearestMipmapNearest | Filter::LinearMipmapNearest => {
            // (8.14), both roundings of nearest(λ) at each end of the range.
            let d0 = nearest_level(a, q, true).min(nearest_level(a, q, false));
            let d1 = nearest_level(hi, q, true).max(nearest_level(hi, q, false));
            for level in d0..=d1 {
                push(out, Pick::One { level, linear: lin });
            }
        }
        Filter::NearestMipmapLinear | Filter::LinearMipmapLinear => {
            // (8.15) "d1 = q if level_base + λ ≥ q, otherwise ⌊level_base + λ⌋"; (8.16) "d2 = q if
            // level_base + λ ≥ q, otherwise d1 + 1".
            let qf = q as f64;
            let k0 = a.floor().min(qf) as u32;
            let k1 = hi.floor().min(qf) as u32;
            for k in k0..=k1 {
                let kf = k as f64;
                if k >= q {
                    push(
                        out,
                        Pick::One {
                            level: q,
                            linear: lin,
                        },
                    );
                    continue;
                }
                let seg_lo = a.max(kf) - kf;
                let seg_hi = hi.min(kf + 1.0) - kf;
                if seg_hi < seg_lo {
                    continue;
                }
                push(
                    out,
                    Pick::Two {
                        d1: k,
                        d2: k + 1,
                        linear: lin,
                        f: seg_lo,
                        f_lo: seg_lo,
                        f_hi: seg_hi.min(1.0),
                    },
                );
            }
        }
    }
}

fn push(out: &mut Vec<Pick>, p: Pick) {
    if !out.contains(&p) {
        out.push(p);
    }
}

/// The pick the spec value uses: λ exact, the preferred nearest(λ).
pub fn spec_pick(s: &Sampler, l: f64, q: u32) -> Pick {
    if l <= 0.0 {
        return Pick::One {
            level: 0,
            linear: s.mag_filter == Filter::Linear,
        };
    }
    let lin = within(s.min_filter);
    match s.min_filter {
        Filter::Nearest | Filter::Linear => Pick::One {
            level: 0,
            linear: lin,
        },
        Filter::NearestMipmapNearest | Filter::LinearMipmapNearest => Pick::One {
            level: nearest_level(l, q, true),
            linear: lin,
        },
        _ => {
            if l >= q as f64 {
                Pick::One {
                    level: q,
                    linear: lin,
                }
            } else {
                let d1 = l.floor() as u32;
                let f = l - l.floor();
                Pick::Two {
                    d1,
                    d2: d1 + 1,
                    linear: lin,
                    f,
                    f_lo: f,
                    f_hi: f,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{CompareFunc, CompareMode};

    fn sampler(f: Filter) -> Sampler {
        Sampler::new(CompareMode::Compare, CompareFunc::Lequal, f)
    }

    #[test]
    fn nearest_level_rounding_choices() {
        // λ = 0.5: preferred ⌈1⌉ − 1 = 0, alternative ⌊1⌋ = 1.
        assert_eq!(nearest_level(0.5, 4, true), 0);
        assert_eq!(nearest_level(0.5, 4, false), 1);
        assert_eq!(nearest_level(0.7, 4, true), 1);
        assert_eq!(nearest_level(9.0, 4, true), 4);
        let mut v = vec![];
        picks(&sampler(Filter::NearestMipmapNearest), 0.5, 0.5, 4, &mut v);
        assert_eq!(
            v,
            vec![
                Pick::One {
                    level: 0,
                    linear: false
                },
                Pick::One {
                    level: 1,
                    linear: false
                }
            ]
        );
    }

    #[test]
    fn magnification_at_zero_and_blend_above() {
        let s = sampler(Filter::LinearMipmapLinear);
        assert_eq!(
            spec_pick(&s, 0.0, 3),
            Pick::One {
                level: 0,
                linear: true
            }
        );
        assert_eq!(
            spec_pick(&s, 1.25, 3),
            Pick::Two {
                d1: 1,
                d2: 2,
                linear: true,
                f: 0.25,
                f_lo: 0.25,
                f_hi: 0.25
            }
        );
        assert_eq!(
            spec_pick(&s, 3.5, 3),
            Pick::One {
                level: 3,
                linear: true
            }
        );
    }

    #[test]
    fn lambda_clamps_and_bias() {
        let mut s = sampler(Filter::Nearest);
        s.min_lod = 0.5;
        s.max_lod = 2.0;
        let l = lambda(3.0, 0.0, 0.0, &s);
        assert_eq!((l.spec, l.lo, l.hi), (2.0, 2.0, 2.0));
        s.min_lod = -1000.0;
        s.max_lod = 1000.0;
        let l = lambda(0.0, 1.0, 2.0, &s);
        assert_eq!((l.spec, l.lo, l.hi), (3.0, 2.0, 3.0));
        assert!(l.note.is_some());
    }
}
