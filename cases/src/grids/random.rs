//! The `rand` family of the default grid: seeded random lookups (`shadowcheck gen --seed S`).

use super::draft::{lookup, texture, Draft};
use super::families::{cell, plain_depth_formats};
use super::specs::SpecDims;
use crate::build::{self, At};
use shadowcheck_model::*;

/// splitmix64: a tiny, well-known PRNG, so that the seed fully decides the random family.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[(self.next() % v.len() as u64) as usize]
    }
    /// A multiple of 1/64 in [lo, hi) (exactly representable, readable in ids).
    fn grid(&mut self, lo: f64, hi: f64) -> f64 {
        let steps = ((hi - lo) * 64.0) as u64;
        lo + (self.next() % steps.max(1)) as f64 / 64.0
    }
}

/// Seeded random lookups (`--seed`): random target, depth format, non-mipmap filter and func, a 2x2
/// texture of random stored values, coordinates and R on a 1/64 grid.
pub fn random(d: &SpecDims, seed: u64, n: usize) -> Vec<Draft> {
    let mut rng = Rng(seed ^ (d.spec as u64).wrapping_mul(0x2545_F491_4F6C_DD1D));
    let formats = plain_depth_formats(d);
    let mut out = Vec::new();
    for i in 0..n {
        let target = rng.pick(d.targets);
        let format = rng.pick(&formats);
        let filter = rng.pick(&[Filter::Nearest, Filter::Linear]);
        let func = rng.pick(d.funcs);
        let c = cell(d, target, format, filter, func);
        let (n_layers, layer) = if target.is_array() {
            (2, 1.0)
        } else {
            (1, 0.0)
        };
        let (w, h, layers) = build::dims(target, 2, n_layers);
        let img: Vec<f64> = (0..4).map(|_| rng.grid(0.0, 1.0)).collect();
        let vals: Vec<f64> = (0..(w * h * layers) as usize)
            .map(|i| img[i % img.len()])
            .collect();
        let tex = texture(&c, vec![build::level(format, w, h, layers, &vals)]);
        let at = At {
            s: rng.grid(0.0, 1.0),
            t: rng.grid(0.0, 1.0),
            layer,
            face: (rng.next() % 6) as u32,
        };
        let r = rng.grid(-0.25, 1.25);
        out.push(Draft::new(
            "rand",
            c,
            tex,
            lookup(target, at, w, h, r),
            format!("seed={seed}/{i}"),
        ));
    }
    out
}
