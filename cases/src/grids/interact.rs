//! The `interact` family: a covering array of strength 2 over the unit-state features that no
//! other family combines: gather function x texture swizzle x bound sampler object x seamless
//! cube enable x DEPTH_TEXTURE_MODE x target x API path ([`crate::pairs::FACTORS`]).
//!
//! The candidates are every combination of levels the spec has (gathers: GL 4.0 / ES 3.1 and
//! Vulkan, WebGPU; swizzle and sampler objects: GL 3.3 / ES 3.0; the seamless enable: desktop GL
//! 3.2; DEPTH_TEXTURE_MODE: compatibility contexts and the legacy specs) whose case reaches at
//! least one API path (the paths come from [`specs::apis`]: a DEPTH_TEXTURE_MODE leaves out
//! `core`, a gather keeps only the GLSL 4.00 / ES 3.10 / SPIR-V / WGSL paths). A deterministic
//! greedy (AETG-style, over the whole candidate list) then takes, while a pair of levels is
//! uncovered, the candidate whose tests (case x each of its paths) cover the most uncovered pairs
//! (the first in candidate order on a tie).
//!
//! Every case makes each factor observable: the texture holds a different value in every texel
//! of every image (v = (16·image + 4y + x + ½) / 16n, as the gather family), the reference splits
//! the footprint (LEQUAL: the j1 row passes, the j0 row fails), so a swizzle, a sampler object
//! (compare function GEQUAL against the texture's LEQUAL: the pattern inverts) and, on cube maps,
//! the seamless enable (the lookup sits a quarter texel inside +Z's edge, so the LINEAR and the
//! gather footprint leave the face) each change the result.

use super::draft::{lookup, texture, Cell, Draft};
use super::families::{cell, fixed_fmt, func_pair};
use super::specs::SpecDims;
use crate::build::{self, At};
use crate::pairs::{self, Pair, Row};
use shadowcheck_model::*;
use std::collections::HashMap;

/// The family name (id part).
pub const FAMILY: &str = "interact";

/// Width and height of the texture's images.
const SIZE: u32 = 4;

/// The non-identity swizzles: post-swizzle R from GREEN (0 for a shadow result and for each
/// gathered texel), RED (the comparison) and ONE; the other components differ too.
const SWIZZLES: [[Swizzle; 4]; 3] = {
    use Swizzle::*;
    [
        [Green, Blue, Alpha, Red],
        [Red, Red, Red, One],
        [One, Red, Zero, Green],
    ]
};

/// The gather level of a candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
enum GatherLevel {
    None,
    Gather,
    Offset,
    Offsets,
}

/// One candidate: a level of every factor but the API path (the case's paths follow from these).
#[derive(Debug, Clone, Copy)]
struct Config {
    gather: GatherLevel,
    swizzle: Option<[Swizzle; 4]>,
    sampler_object: bool,
    seamless: Option<bool>,
    dtm: Option<DepthTextureMode>,
    target: Target,
}

/// Specs with TEXTURE_SWIZZLE_* and sampler objects (GL 3.3, ES 3.0).
fn has_gl33_state(d: &SpecDims) -> bool {
    matches!(d.spec, Spec::Gl46 | Spec::Gles32)
}

fn gathers(d: &SpecDims) -> Vec<GatherLevel> {
    match d.spec {
        Spec::Gl46 | Spec::Gles32 | Spec::Vulkan => vec![
            GatherLevel::None,
            GatherLevel::Gather,
            GatherLevel::Offset,
            GatherLevel::Offsets,
        ],
        // WGSL's textureGatherCompare takes one const offset: no textureGatherOffsets.
        Spec::WebGpu => vec![GatherLevel::None, GatherLevel::Gather, GatherLevel::Offset],
        _ => vec![GatherLevel::None],
    }
}

/// Whether `spec` has a unit-state factor with more than one level (else no `interact` cases).
fn has_factors(d: &SpecDims) -> bool {
    gathers(d).len() > 1 || has_gl33_state(d) || !d.dtms.is_empty()
}

/// Every candidate of the spec, in a fixed order.
fn configs(d: &SpecDims) -> Vec<Config> {
    if !has_factors(d) {
        return Vec::new();
    }
    let swizzles: Vec<Option<[Swizzle; 4]>> = if has_gl33_state(d) {
        std::iter::once(None)
            .chain(SWIZZLES.iter().copied().map(Some))
            .collect()
    } else {
        vec![None]
    };
    let objects: &[bool] = if has_gl33_state(d) {
        &[false, true]
    } else {
        &[false]
    };
    // The TEXTURE_CUBE_MAP_SEAMLESS enable: desktop GL 3.2 (ES 3.x cube maps are always seamless,
    // ES 3.2 §8.13.1; Vulkan and WebGPU filter across faces, no enable).
    let seamless: &[Option<bool>] = if d.spec == Spec::Gl46 {
        &[None, Some(true), Some(false)]
    } else {
        &[None]
    };
    let dtms: Vec<Option<DepthTextureMode>> = std::iter::once(None)
        .chain(d.dtms.iter().copied().map(Some))
        .collect();
    let mut out = Vec::new();
    for &target in d.targets {
        for &gather in &gathers(d) {
            for &swizzle in &swizzles {
                for &sampler_object in objects {
                    for &seam in seamless {
                        for &dtm in &dtms {
                            out.push(Config {
                                gather,
                                swizzle,
                                sampler_object,
                                seamless: seam,
                                dtm,
                                target,
                            });
                        }
                    }
                }
            }
        }
    }
    out
}

/// Whether the gather function exists for the target (GLSL 4.60 §8.9.4: 2D, 2D array, cube, cube
/// array, rectangle; textureGatherOffset(s) take no cube sampler).
fn gather_target(g: GatherLevel, t: Target) -> bool {
    match g {
        GatherLevel::None => true,
        GatherLevel::Gather => matches!(
            t,
            Target::T2d | Target::T2dArray | Target::Cube | Target::CubeArray | Target::Rect
        ),
        GatherLevel::Offset | GatherLevel::Offsets => {
            matches!(t, Target::T2d | Target::T2dArray | Target::Rect)
        }
    }
}

/// The image the lookup reads: (layer coordinate, cube face, image index among the level's
/// images): layer 1 of arrays, face +Z of cubes, cube 1's +Z of cube arrays.
fn image(target: Target) -> (f64, u32, u32) {
    match target {
        Target::T1dArray | Target::T2dArray => (1.0, 0, 1),
        Target::Cube => (0.0, 4, 4),
        Target::CubeArray => (1.0, 4, 10),
        _ => (0.0, 0, 0),
    }
}

/// The texture: every texel of every image its own value (rows of 1D images: v = (16·image + 4x
/// + ½) / 16n, so that the reference between x = 1 and x = 2 splits a 1D footprint too).
fn the_texture(c: &Cell) -> (Texture, u32) {
    let (w, h, images) = build::dims(c.target, SIZE, 2);
    let n = (16 * images) as f64;
    let vals: Vec<f64> = (0..images)
        .flat_map(|img| {
            (0..h).flat_map(move |y| {
                (0..w).map(move |x| {
                    let k = if h == 1 { 4 * x } else { 4 * y + x };
                    (16.0 * img as f64 + k as f64 + 0.5) / n
                })
            })
        })
        .collect();
    (
        texture(c, vec![build::level(c.format, w, h, images, &vals)]),
        images,
    )
}

fn tags(cfg: &Config) -> String {
    let mut parts: Vec<String> = Vec::new();
    match cfg.gather {
        GatherLevel::None => {}
        GatherLevel::Gather => parts.push("gather".into()),
        GatherLevel::Offset => parts.push("gather_offset".into()),
        GatherLevel::Offsets => parts.push("gather_offsets".into()),
    }
    if let Some(sw) = cfg.swizzle {
        parts.push(format!("swizzle={}", pairs::swizzle_letters(sw)));
    }
    if cfg.sampler_object {
        parts.push("sampler_object".into());
    }
    match cfg.seamless {
        None => {}
        Some(true) => parts.push("seamless=on".into()),
        Some(false) => parts.push("seamless=off".into()),
    }
    if let Some(m) = cfg.dtm {
        parts.push(format!("dtm={m}"));
    }
    if parts.is_empty() {
        parts.push("plain".into());
    }
    parts.join("+")
}

/// The draft of a candidate, `None` where the gather function does not exist for the target.
fn draft(d: &SpecDims, cfg: &Config) -> Option<Draft> {
    if !gather_target(cfg.gather, cfg.target) {
        return None;
    }
    let [leq, geq] = func_pair(d);
    let c = Cell {
        dtm: cfg.dtm,
        ..cell(d, cfg.target, fixed_fmt(d), Filter::Linear, leq)
    };
    let (tex, images) = the_texture(&c);
    let (layer, face, img) = image(cfg.target);
    // Cube maps: a quarter texel inside +Z's left edge (the footprint leaves the face); else
    // inside the image, a quarter texel from the footprint boundary.
    let u = if cfg.target.is_cube() { 0.25 } else { 1.75 };
    let at = At {
        s: u / SIZE as f64,
        t: 2.25 / SIZE as f64,
        layer,
        face,
    };
    let dref = (16.0 * img as f64 + 8.0) / (16 * images) as f64;
    let mut lk = lookup(cfg.target, at, SIZE, SIZE, dref);
    match cfg.gather {
        GatherLevel::None => {}
        GatherLevel::Gather => lk.gather = Some(Gather { offsets: None }),
        GatherLevel::Offset => {
            lk.gather = Some(Gather { offsets: None });
            lk.offset = [1, 0, 0];
        }
        GatherLevel::Offsets => {
            // Each component's τi0j0: (1,1) fails, (1,2) and (2,2) pass, (2,1) fails.
            lk.gather = Some(Gather {
                offsets: Some([[0, 0], [0, 1], [1, 1], [1, 0]]),
            });
        }
    }
    let mut x = Draft::new(FAMILY, c, tex, lk, tags(cfg));
    x.sampler.swizzle = cfg.swizzle;
    x.sampler.seamless = cfg.seamless;
    if cfg.sampler_object {
        // The sampler object's function is the opposite of the texture's (GL 4.6 §8.17.1: a
        // bound sampler object's state replaces the texture's sampling state).
        let mut o = SamplerObject::from_sampler(&x.sampler);
        o.compare_func = geq;
        x.sampler.sampler_object = Some(o);
    }
    Some(x)
}

/// The candidates that reach an API path, each with its tests' rows.
fn candidates(d: &SpecDims) -> Vec<(Draft, Vec<Row>)> {
    configs(d)
        .iter()
        .filter_map(|cfg| draft(d, cfg))
        .filter_map(|x| {
            let case = x.clone().into_case();
            let rows: Vec<Row> = case.api.iter().map(|&a| pairs::row(&case, a)).collect();
            (!rows.is_empty()).then_some((x, rows))
        })
        .collect()
}

/// The tests (rows) of every candidate of the spec: what [`crate::pairs::allowed`] takes the
/// allowed level pairs from.
pub fn allowed_rows(d: &SpecDims) -> Vec<Row> {
    candidates(d).into_iter().flat_map(|(_, r)| r).collect()
}

/// The covering array of spec `d` (see the module docs).
pub fn interact(d: &SpecDims) -> Vec<Draft> {
    let cands = candidates(d);
    // Number the pairs; each candidate's set of pair numbers.
    let mut ids: HashMap<Pair, usize> = HashMap::new();
    let sets: Vec<Vec<usize>> = cands
        .iter()
        .map(|(_, rows)| {
            let mut v: Vec<usize> = rows
                .iter()
                .flat_map(|r| pairs::pairs(r).collect::<Vec<_>>())
                .map(|p| {
                    let n = ids.len();
                    *ids.entry(p).or_insert(n)
                })
                .collect();
            v.sort_unstable();
            v.dedup();
            v
        })
        .collect();
    let mut covered = vec![false; ids.len()];
    let mut left = ids.len();
    let mut out = Vec::new();
    while left > 0 {
        let gain = |k: usize| sets[k].iter().filter(|&&p| !covered[p]).count();
        let mut best = (0, 0);
        for k in 0..cands.len() {
            let g = gain(k);
            if g > best.1 {
                best = (k, g);
            }
        }
        if best.1 == 0 {
            break;
        }
        for &p in &sets[best.0] {
            if !covered[p] {
                covered[p] = true;
                left -= 1;
            }
        }
        out.push(cands[best.0].0.clone());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::specs;
    use super::*;
    use std::collections::BTreeSet;

    #[test]
    fn the_array_covers_every_allowed_pair_of_every_spec_and_evaluates() {
        for d in specs::all() {
            let cases: Vec<Case> = interact(&d).into_iter().map(|x| x.into_case()).collect();
            let mut covered = BTreeSet::new();
            for c in &cases {
                for &a in &c.api {
                    covered.extend(pairs::pairs(&pairs::row(c, a)));
                }
                shadowcheck_oracle::evaluate(c).unwrap_or_else(|e| panic!("{}: {e}", c.id));
            }
            let allowed = pairs::allowed(d.spec);
            let missing: Vec<_> = allowed.difference(&covered).collect();
            assert!(missing.is_empty(), "{}: {missing:?}", d.spec);
            assert_eq!(cases.is_empty(), allowed.is_empty(), "{}", d.spec);
        }
    }

    #[test]
    fn the_array_is_much_smaller_than_the_candidates() {
        let d = specs::dims(Spec::Gl46);
        let n = interact(&d).len();
        let all = candidates(&d).len();
        assert!(n > 0 && n * 10 < all, "{n} of {all}");
    }

    /// What a test checks of an expectation: the value, the gather components, the layouts.
    fn outcome(d: &SpecDims, cfg: &Config) -> String {
        let x = draft(d, cfg).unwrap_or_else(|| panic!("{cfg:?}: no draft"));
        let c = x.into_case();
        let e = shadowcheck_oracle::evaluate(&c)
            .unwrap_or_else(|e| panic!("{}: {e}", c.id))
            .expect;
        format!("{:?}", (e.spec_value, e.accept, e.gather, e.layout))
    }

    #[test]
    fn each_factor_changes_the_expected_result() {
        let d = specs::dims(Spec::Gl46);
        let base = Config {
            gather: GatherLevel::None,
            swizzle: None,
            sampler_object: false,
            seamless: None,
            dtm: None,
            target: Target::T2d,
        };
        let gather = Config {
            gather: GatherLevel::Gather,
            ..base
        };
        let cube = |g: GatherLevel, on: bool| Config {
            gather: g,
            seamless: Some(on),
            target: Target::Cube,
            ..base
        };
        let flips: [(Config, Config); 7] = [
            // The sampler object's GEQUAL, on a filtered lookup and on a gather.
            (
                base,
                Config {
                    sampler_object: true,
                    ..base
                },
            ),
            (
                gather,
                Config {
                    sampler_object: true,
                    ..gather
                },
            ),
            // Post-swizzle R from GREEN, on a filtered lookup and on a gather.
            (
                base,
                Config {
                    swizzle: Some(SWIZZLES[0]),
                    ..base
                },
            ),
            (
                gather,
                Config {
                    swizzle: Some(SWIZZLES[0]),
                    ..gather
                },
            ),
            // The seamless enable at +Z's edge, filtered and gathered.
            (
                cube(GatherLevel::None, false),
                cube(GatherLevel::None, true),
            ),
            (
                cube(GatherLevel::Gather, false),
                cube(GatherLevel::Gather, true),
            ),
            // DEPTH_TEXTURE_MODE ALPHA against the LUMINANCE default (compatibility paths).
            (
                base,
                Config {
                    dtm: Some(DepthTextureMode::Alpha),
                    ..base
                },
            ),
        ];
        for (a, b) in flips {
            assert_ne!(outcome(&d, &a), outcome(&d, &b), "{a:?} vs {b:?}");
        }
    }

    #[test]
    fn a_gather_with_a_dtm_reaches_no_path_and_is_no_candidate() {
        let d = specs::dims(Spec::Gl46);
        for (x, rows) in candidates(&d) {
            if x.lookup.gather.is_some() {
                assert!(x.sampler.depth_texture_mode.is_none(), "{}", x.id());
                assert!(rows.iter().all(|r| r[6] == "core"), "{}", x.id());
            }
        }
    }
}
