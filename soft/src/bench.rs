//! A deterministic raw-lookup workload for throughput measurements (`shadowcheck bench`, the
//! `lookup_rate` example). Nothing here is timed: the caller times [`Workload::run`].

use crate::filter::Coords;
use crate::sampler::SamplerState;
use crate::storage::PreparedTexture;
use crate::{Faults, SoftError};
use shadowcheck_model::{
    CompareFunc, CompareMode, Filter, Format, Level, Sampler, Spec, Target, Texels, Texture, Wrap,
};

/// One prepared texture, its sampler state and a list of lookups.
#[derive(Debug, Clone)]
pub struct Workload {
    pub texture: PreparedTexture,
    pub state: SamplerState,
    pub coords: Vec<Coords>,
}

/// xorshift64*: a small deterministic generator (same sequence on every machine).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

impl Workload {
    /// A `size`×`size` DEPTH_COMPONENT24 2D texture of pseudo-random depths (with a full mip
    /// chain), sampled with LEQUAL comparison, REPEAT wrapping and `filter`, at `lookups`
    /// pseudo-random coordinates and references (λ in [−1, 3) for mipmap filters, else 0).
    pub fn new(
        spec: Spec,
        size: u32,
        filter: Filter,
        lookups: usize,
    ) -> Result<Workload, SoftError> {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut levels = Vec::new();
        let mut w = size.max(1);
        loop {
            let depth = (0..w * w).map(|_| (rng.next() >> 40) as u32).collect();
            levels.push(Level {
                width: w,
                height: w,
                layers: 1,
                depth: Texels::Unorm(depth),
                stencil: None,
            });
            if w == 1 || !filter.is_mipmap() {
                break;
            }
            w /= 2;
        }
        let tex = Texture {
            target: Target::T2d,
            format: Format::D24,
            base_level: 0,
            levels,
        };
        let texture = PreparedTexture::new(&tex, Faults::NONE)?;
        let mut s = Sampler::new(CompareMode::Compare, CompareFunc::Lequal, filter);
        (s.wrap_s, s.wrap_t) = (Wrap::Repeat, Wrap::Repeat);
        let state = SamplerState::new(spec, &s, &texture, Faults::NONE)?;
        let coords = (0..lookups)
            .map(|_| Coords {
                s: rng.unit() * 2.0 - 0.5,
                t: rng.unit() * 2.0 - 0.5,
                r: 0.0,
                layer: 0.0,
                dref: rng.unit(),
                lambda_base: if filter.is_mipmap() {
                    rng.unit() * 4.0 - 1.0
                } else {
                    0.0
                },
                bias: 0.0,
                offset: [0; 2],
            })
            .collect();
        Ok(Workload {
            texture,
            state,
            coords,
        })
    }

    /// Performs every lookup once; returns the sum of the results (so the work is not optimized
    /// away, and as a checksum).
    pub fn run(&self) -> f64 {
        let mut sum = 0.0f64;
        for c in &self.coords {
            sum += self.texture.lookup(&self.state, c) as f64;
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn workload_is_deterministic_and_results_are_fractions() {
        let a = Workload::new(Spec::Gl46, 16, Filter::LinearMipmapLinear, 1000).unwrap();
        let b = Workload::new(Spec::Gl46, 16, Filter::LinearMipmapLinear, 1000).unwrap();
        assert_eq!(a.run(), b.run());
        for c in &a.coords {
            let r = a.texture.lookup(&a.state, c);
            assert!((0.0..=1.0).contains(&r), "{r}");
        }
        assert!(a.state.complete);
    }
}
