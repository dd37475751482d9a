//! Shadow `textureGather*`: four comparisons, no filtering.
//!
//! GLSL 4.60 §8.9.4: "the minification and magnification filters are ignored, and the rules for
//! LINEAR filtering in the OpenGL Specification are applied to the base level of the texture image
//! to identify the four texels i0 j1, i1 j1, i1 j0, and i0 j0"; "each of the four texel lookups
//! perform a depth comparison against the depth reference value passed in (refZ)".
//! textureGatherOffsets: each component is τi0j0 of the footprint moved by its own offset.

use crate::compare::passes;
use crate::cube;
use crate::faults::Fault;
use crate::filter::Coords;
use crate::lod::{self, LevelChoice};
use crate::sampler::SamplerState;
use crate::storage::{clamp01, PreparedTexture};
use crate::wrap;
use shadowcheck_model::{Target, Wrap};

/// Component k of the result reads texel ORDER[k] of the footprint [i0j0, i1j0, i0j1, i1j1].
const ORDER: [usize; 4] = [2, 3, 1, 0];
/// The fault `gather-order-rotated`: (τi0j0, τi0j1, τi1j1, τi1j0).
const ROTATED: [usize; 4] = [0, 2, 3, 1];

impl PreparedTexture {
    /// The four gather components for `c` (offset `c.offset`, or `offsets` per component).
    pub fn gather(
        &self,
        st: &SamplerState,
        c: &Coords,
        offsets: Option<[[i32; 2]; 4]>,
    ) -> [f32; 4] {
        if self.levels().is_empty() {
            return [0.0; 4];
        }
        let f = st.faults;
        let level = if f.has(Fault::GatherUsesLodLevel) {
            let lambda = lod::lambda(&st.lod, c.lambda_base, c.bias, f);
            match lod::choose(&st.lod, lambda, f) {
                LevelChoice::Single { level, .. } => level,
                LevelChoice::Blend { d1, .. } => d1,
            }
        } else {
            st.lod.level_base
        };
        let dref = if st.clamp.dref {
            clamp01(c.dref)
        } else {
            c.dref
        };
        let addr = self.address(st, c);
        let order = if f.has(Fault::GatherOrderRotated) {
            ROTATED
        } else {
            ORDER
        };
        let mut out = [0.0f32; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let (d, tap) = match offsets {
                Some(offs) => (offs[k], 0),
                None => (c.offset, order[k]),
            };
            let quad = self.quad(st, level, &addr, d, dref);
            *o = quad[tap];
        }
        out
    }

    /// The results of the 2x2 LINEAR footprint [i0j0, i1j0, i0j1, i1j1] of `level` at `a` moved
    /// by `d` texels (§8.14.2 (8.10)); seamless cube faces take their neighbours' texels
    /// (§8.13.1), a corner with no neighbour the mean of the other three.
    fn quad(
        &self,
        st: &SamplerState,
        level: u32,
        a: &crate::filter::Address,
        d: [i32; 2],
        dref: f32,
    ) -> [f32; 4] {
        let l = self.level_desc(st, level);
        let layer = self.storage_layer(st, l, a);
        let (w, h) = (l.width, l.height);
        let f = st.faults;
        let rect = self.target() == Target::Rect;
        let (du, dv) = (d[0] as f32, d[1] as f32);
        let u = if rect { a.s + du } else { a.s * w as f32 + du };
        let v = if rect { a.t + dv } else { a.t * h as f32 + dv };
        let (ws, wt) = if st.seamless {
            (Wrap::ClampToBorder, Wrap::ClampToBorder)
        } else {
            (st.wrap_s, st.wrap_t)
        };
        let (i0, i1, _) = wrap::linear(ws, u, w, f);
        let (j0, j1, _) = wrap::linear(wt, v, h, f);
        let mut pos = [
            (i0, j0, layer),
            (i1, j0, layer),
            (i0, j1, layer),
            (i1, j1, layer),
        ];
        let mut missing = None;
        if let (true, Some(face)) = (st.seamless, a.face) {
            let base = layer - face as u32;
            for (k, p) in pos.iter_mut().enumerate() {
                match cube::neighbour(face, p.0, p.1, w as i64) {
                    Some((nf, ni, nj)) => *p = (ni, nj, base + nf as u32),
                    None => missing = Some(k),
                }
            }
        }
        let mut vals = [0.0f32; 4];
        for (k, (i, j, ly)) in pos.into_iter().enumerate() {
            if missing == Some(k) {
                continue;
            }
            let raw = self.fetch(st, l, i, j, ly);
            vals[k] = if f.has(Fault::GatherIgnoresRef) {
                if st.clamp.dt {
                    clamp01(raw)
                } else {
                    raw
                }
            } else {
                let dt = if st.clamp.dt { clamp01(raw) } else { raw };
                if passes(st.op, dref, dt, f) {
                    st.pass
                } else {
                    st.fail
                }
            };
        }
        if let Some(m) = missing {
            vals[m] = (vals.iter().sum::<f32>() - vals[m]) / 3.0;
        }
        vals
    }
}
