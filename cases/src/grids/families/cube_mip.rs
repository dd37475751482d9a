//! Level selection on cube maps: a three-level chain whose levels hold different values, so that
//! a lookup one level off is seen (the `mip` family's chain is 2D; the cube and seamless families
//! have two levels, where λ + 1 clamps to the same last level as λ).

use super::super::draft::{lookup, texture, Draft};
use super::super::specs::SpecDims;
use super::{cell, fixed_fmt, main_func};
use crate::build::{self, nums, At};
use shadowcheck_model::*;

/// Nominal value of each level of the 4x4 -> 1x1 cube chain (every face alike).
const LEVELS: [f64; 3] = [0.2, 0.8, 0.4];

/// Cube and cube-array textures of three levels (4x4, 2x2, 1x1) at λ 0, 1 and 2 (GL 4.6 §8.14.3:
/// NEAREST_MIPMAP_NEAREST and LINEAR_MIPMAP_NEAREST use level d = ⌈level_base + λ + 1/2⌉ − 1), at
/// the centre of +X and of -Z, R 0.3 and 0.5 (together they tell the three levels apart), with the
/// seamless enable off and on where the spec has it (GL 4.6 §8.13.1). The lookup is at a face
/// centre, so the footprint never leaves its face and seamless filtering changes nothing: only
/// the level may differ.
pub fn cube_mip(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    let seamless: &[Option<bool>] = if d.spec == Spec::Gl46 {
        &[Some(false), Some(true)]
    } else {
        &[None]
    };
    let tags = format!("levels={}", nums(&LEVELS));
    for &target in d.targets.iter().filter(|t| t.is_cube()) {
        let n = if target == Target::CubeArray { 2 } else { 1 };
        let cube_index = (n - 1) as f64;
        for &filter in d.filters.iter().filter(|f| {
            matches!(
                f,
                Filter::NearestMipmapNearest | Filter::LinearMipmapNearest
            )
        }) {
            let c = cell(d, target, fmt, filter, func);
            let levels = [4u32, 2, 1]
                .into_iter()
                .zip(LEVELS)
                .map(|(size, v)| {
                    let (w, h, layers) = build::dims(target, size, n);
                    build::level(fmt, w, h, layers, &vec![v; (w * h * layers) as usize])
                })
                .collect();
            let tex = texture(&c, levels);
            for &on in seamless {
                let seam = match on {
                    Some(true) => "/seamless=on",
                    Some(false) => "/seamless=off",
                    None => "",
                };
                for (face, fname) in [(0u32, "px"), (5, "nz")] {
                    for lod in [0.0, 1.0, 2.0] {
                        for r in [0.3, 0.5] {
                            let at = At {
                                s: 0.5,
                                t: 0.5,
                                layer: cube_index,
                                face,
                            };
                            let mut lk = lookup(target, at, 4, 4, r);
                            lk.lod = lod;
                            let mut x = Draft::new(
                                "cube_mip",
                                c,
                                tex.clone(),
                                lk,
                                format!("face={fname}/lod={lod}/ref={r}{seam}/{tags}"),
                            );
                            x.sampler.seamless = on;
                            out.push(x);
                        }
                    }
                }
            }
        }
    }
    out
}
