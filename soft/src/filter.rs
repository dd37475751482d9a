//! The lookup: addressing (target, cube face, array layer), texel fetch with border, NEAREST and
//! LINEAR filtering within a level with percentage-closer filtering (compare each texel, then
//! weight), and the blend between two levels.
//!
//! PCF is used for every spec variant: SGIX_shadow compares before filtering by definition; the
//! later specs make the filtered r implementation-dependent ("proportional to the number of
//! comparison passes or failures", GL 4.6 §8.23.1) and comparing each texel of the §8.14.2 LINEAR
//! footprint, then applying the bilinear weights, is the natural implementation of that.

use crate::compare::passes;
use crate::cube;
use crate::faults::Fault;
use crate::lod::{self, LevelChoice};
use crate::observe::{Observer, TexelVisit};
use crate::sampler::{Kind, SamplerState};
use crate::storage::{clamp01, LevelDesc, PreparedTexture};
use crate::wrap;
use shadowcheck_model::{Target, Wrap};

/// Coordinates of one lookup after the projective divide, as f32 (the API passes floats).
///
/// `s`, `t`, `r` per target: 1D (s), 2D / rect (s, t), cube and cube array (s, t, r) direction.
/// `layer` is the array layer coordinate for 1D / 2D arrays and the cube index for cube arrays.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Coords {
    pub s: f32,
    pub t: f32,
    pub r: f32,
    pub layer: f32,
    /// Reference value Dref (after any projective divide, before clamping).
    pub dref: f32,
    /// λ_base (as from derivatives or an explicit LOD).
    pub lambda_base: f32,
    /// Shader bias.
    pub bias: f32,
    /// Texel offset (δu, δv) of the `*Offset` lookup functions (0 for 1D's δv).
    pub offset: [i32; 2],
}

/// Where in the texture one lookup reads: normalized (or, for rectangles, unnormalized) s, t
/// within an image, the layer of that image and, for cubes, the face.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Address {
    pub(crate) s: f32,
    pub(crate) t: f32,
    /// Array layer coordinate (already rounded) before clamping to the level's layer count; for
    /// cube arrays the cube index.
    pub(crate) layer: i64,
    pub(crate) face: Option<cube::Face>,
}

/// layer = clamp(⌊layer + ½⌋, 0, layers − 1) (§8.14.2, the ⌊x + ½⌋ form footnote 4 allows).
#[inline(always)]
fn round_layer(x: f32, st: &SamplerState) -> i64 {
    if st.faults.has(Fault::LayerTruncated) {
        wrap::floor_i64(x)
    } else if st.faults.has(Fault::LayerRneUnderLinear) {
        // RNE everywhere: correct under NEAREST (the spec's formula), wrong under LINEAR.
        x.round_ties_even() as i64
    } else {
        wrap::floor_i64(x + 0.5)
    }
}

impl PreparedTexture {
    /// One lookup: r for `c` under `st` (the comparison result, filtered; Dt for compare mode NONE;
    /// the colour for R8; St for stencil mode). Completeness is not checked here: callers look at
    /// `st.complete` first (an incomplete texture returns 0 / (0,0,0,1), §11.1.3.5).
    #[inline]
    pub fn lookup(&self, st: &SamplerState, c: &Coords) -> f32 {
        self.lookup_observed(st, c, &mut ())
    }

    /// [`PreparedTexture::lookup`] for many coordinates: `out[i]` = lookup of `coords[i]`
    /// (`out` is truncated to the shorter of the two).
    pub fn lookup_many(&self, st: &SamplerState, coords: &[Coords], out: &mut [f32]) {
        for (o, c) in out.iter_mut().zip(coords) {
            *o = self.lookup(st, c);
        }
    }

    /// The lookup, reporting every texel it reads to `obs` (see [`Observer`]). With `()` as the
    /// observer this is exactly [`PreparedTexture::lookup`] (the reporting compiles away).
    pub fn lookup_observed<O: Observer>(&self, st: &SamplerState, c: &Coords, obs: &mut O) -> f32 {
        if self.levels.is_empty() {
            return 0.0;
        }
        let lambda = lod::lambda(&st.lod, c.lambda_base, c.bias, st.faults);
        let choice = lod::choose(&st.lod, lambda, st.faults);
        let addr = self.address(st, c);
        let dref = if st.clamp.dref {
            clamp01(c.dref)
        } else {
            c.dref
        };
        if O::ACTIVE {
            obs.reference(dref);
        }
        match choice {
            LevelChoice::Single { level, linear } => {
                self.sample_level(st, level, linear, &addr, c.offset, dref, 1.0, obs)
            }
            LevelChoice::Blend {
                d1,
                d2,
                frac,
                linear,
            } => {
                let t1 = self.sample_level(st, d1, linear, &addr, c.offset, dref, 1.0 - frac, obs);
                let t2 = self.sample_level(st, d2, linear, &addr, c.offset, dref, frac, obs);
                (1.0 - frac) * t1 + frac * t2
            }
        }
    }

    pub(crate) fn address(&self, st: &SamplerState, c: &Coords) -> Address {
        match self.target() {
            Target::T1d => Address {
                s: c.s,
                t: 0.0,
                layer: 0,
                face: None,
            },
            Target::T2d | Target::Rect => Address {
                s: c.s,
                t: c.t,
                layer: 0,
                face: None,
            },
            Target::T1dArray => Address {
                s: c.s,
                t: 0.0,
                layer: round_layer(c.layer, st),
                face: None,
            },
            Target::T2dArray => Address {
                s: c.s,
                t: c.t,
                layer: round_layer(c.layer, st),
                face: None,
            },
            Target::Cube | Target::CubeArray => {
                // A direction without a major axis is rejected before the lookup; fall back to +X.
                let (face, s, t) = cube::select(c.s, c.t, c.r, st.faults).unwrap_or((0, 0.5, 0.5));
                let layer = if self.target() == Target::CubeArray {
                    round_layer(c.layer, st)
                } else {
                    0
                };
                Address {
                    s,
                    t,
                    layer,
                    face: Some(face),
                }
            }
        }
    }

    /// The prepared level for absolute level `level` (clamped to what exists, which only matters
    /// when a fault lets an incomplete texture be sampled).
    #[inline(always)]
    pub(crate) fn level_desc(&self, st: &SamplerState, level: u32) -> &LevelDesc {
        let i = (level.saturating_sub(st.lod.level_base) as usize)
            .min(self.levels.len().saturating_sub(1));
        &self.levels[i]
    }

    /// The storage layer for the address within level `l`: the layer (cube index) clamped to
    /// [0, n − 1] (GL 4.6 §8.14.2; WGSL "This value will be clamped to the range
    /// [0, textureNumLayers(t) - 1]", where WGSL textureNumLayers "If the texture is based on
    /// cubes, returns the number of cubes in the cube arrayed texture").
    #[inline(always)]
    pub(crate) fn storage_layer(&self, st: &SamplerState, l: &LevelDesc, a: &Address) -> u32 {
        let index = |n: i64| {
            if st.faults.has(Fault::WgpuArrayIndexWrapped) {
                a.layer.rem_euclid(n.max(1))
            } else {
                a.layer.clamp(0, n - 1)
            }
        };
        match a.face {
            None => index(l.layers as i64) as u32,
            Some(face) => {
                let cubes = (l.layers / 6).max(1) as i64;
                if st.faults.has(Fault::WgpuCubeArrayIndexAsLayer) {
                    // Fault only: the index counted in layers, not cubes.
                    return (index(cubes) as u32 + face as u32).min(l.layers.saturating_sub(1));
                }
                (index(cubes) * 6) as u32 + face as u32
            }
        }
    }

    /// The raw value at (i, j) of `layer`, or the border value outside the image.
    #[inline(always)]
    pub(crate) fn fetch(
        &self,
        st: &SamplerState,
        l: &LevelDesc,
        i: i64,
        j: i64,
        layer: u32,
    ) -> f32 {
        if i < 0 || j < 0 || i >= l.width as i64 || j >= l.height as i64 {
            return st.border;
        }
        if st.kind == Kind::Stencil {
            self.stencil_texel(l, i as u32, j as u32, layer)
        } else {
            self.texel(l, i as u32, j as u32, layer)
        }
    }

    /// What one texel contributes to the filter: pass / fail value for comparisons, the clamped Dt,
    /// the colour or the stencil index.
    #[inline(always)]
    pub(crate) fn resolve(&self, st: &SamplerState, v: f32, dref: f32) -> f32 {
        match st.kind {
            Kind::Compare => {
                let v = st.swizzled_dt.unwrap_or(v);
                let dt = if st.clamp.dt { clamp01(v) } else { v };
                if passes(st.op, dref, dt, st.faults) {
                    st.pass
                } else {
                    st.fail
                }
            }
            Kind::Depth => {
                if st.clamp.dt {
                    clamp01(v)
                } else {
                    v
                }
            }
            Kind::Stencil if st.stencil_compare => {
                if passes(st.op, dref, v, st.faults) {
                    st.pass
                } else {
                    st.fail
                }
            }
            Kind::Colour | Kind::Stencil => v,
        }
    }

    /// Texel location (x, y, storage layer) of (i, j), or `None` for a border texel.
    #[inline(always)]
    fn loc(l: &LevelDesc, i: i64, j: i64, layer: u32) -> Option<[u32; 3]> {
        (i >= 0 && j >= 0 && i < l.width as i64 && j < l.height as i64)
            .then_some([i as u32, j as u32, layer])
    }

    /// Reports one texel to the observer.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn report<O: Observer>(
        &self,
        st: &SamplerState,
        obs: &mut O,
        level: u32,
        xyz: Option<[u32; 3]>,
        raw: f32,
        dref: f32,
        weight: f32,
    ) {
        let dt = match st.kind {
            Kind::Compare | Kind::Depth if st.clamp.dt => clamp01(raw),
            _ => raw,
        };
        let pass = (st.kind == Kind::Compare && !st.faults.has(Fault::FilterThenCompare))
            .then(|| passes(st.op, dref, dt, st.faults));
        obs.texel(TexelVisit {
            level,
            xyz,
            raw,
            dt,
            pass,
            weight,
        });
    }

    /// NEAREST or LINEAR filtering within one level (§8.14.2), with PCF for comparisons.
    /// `scale` is the level's weight in the final value (for the observer only).
    #[allow(clippy::too_many_arguments)]
    fn sample_level<O: Observer>(
        &self,
        st: &SamplerState,
        level: u32,
        linear: bool,
        a: &Address,
        offset: [i32; 2],
        dref: f32,
        scale: f32,
        obs: &mut O,
    ) -> f32 {
        let l = self.level_desc(st, level);
        let layer = self.storage_layer(st, l, a);
        let p = self.level_point(st, l, a, offset);
        if !linear || st.faults.has(Fault::LinearAsNearest) {
            self.sample_nearest(st, level, l, layer, &p, dref, scale, obs)
        } else {
            self.sample_linear(st, level, l, layer, a.face, &p, dref, scale, obs)
        }
    }

    /// The point `a` in the texel space of level `l` (u, v of equation 8.10) and the wrap modes
    /// that address it.
    #[inline(always)]
    fn level_point(
        &self,
        st: &SamplerState,
        l: &LevelDesc,
        a: &Address,
        offset: [i32; 2],
    ) -> LevelPoint {
        let target = self.target();
        let rect = target == Target::Rect;
        let (w, h) = (l.width, l.height);
        let f = st.faults;
        // Equation 8.10: u = w_s · s + δu with the size of this level (rectangles: u = s + δu).
        let (du, dv) = if f.has(Fault::OffsetIgnored) {
            (0.0, 0.0)
        } else if f.has(Fault::OffsetInBaseLevelTexels) {
            let b = self.level_desc(st, st.lod.level_base);
            (
                offset[0] as f32 * w as f32 / b.width as f32,
                offset[1] as f32 * h as f32 / b.height as f32,
            )
        } else {
            (offset[0] as f32, offset[1] as f32)
        };
        let after_wrap = f.has(Fault::OffsetAfterWrap);
        let (du, dv) = if after_wrap { (0.0, 0.0) } else { (du, dv) };
        let u = if rect { a.s + du } else { a.s * w as f32 + du };
        let v = if rect { a.t + dv } else { a.t * h as f32 + dv };
        let (ws, wt) = if st.seamless {
            (Wrap::ClampToEdge, Wrap::ClampToEdge)
        } else {
            (st.wrap_s, st.wrap_t)
        };
        LevelPoint {
            u,
            v,
            late_offset: after_wrap.then_some(offset),
            ws,
            wt,
            one_d: matches!(target, Target::T1d | Target::T1dArray),
        }
    }

    /// NEAREST (§8.14.2): the one texel (i, j) holding the point.
    #[allow(clippy::too_many_arguments)]
    fn sample_nearest<O: Observer>(
        &self,
        st: &SamplerState,
        level: u32,
        l: &LevelDesc,
        layer: u32,
        p: &LevelPoint,
        dref: f32,
        scale: f32,
        obs: &mut O,
    ) -> f32 {
        let f = st.faults;
        let i = p.shift(wrap::nearest(p.ws, p.u, l.width, f), 0, l.width);
        let j = if p.one_d {
            0
        } else {
            p.shift(wrap::nearest(p.wt, p.v, l.height, f), 1, l.height)
        };
        let raw = self.fetch(st, l, i, j, layer);
        if O::ACTIVE {
            self.report(st, obs, level, Self::loc(l, i, j, layer), raw, dref, scale);
        }
        self.resolve(st, raw, dref)
    }

    /// LINEAR (§8.14.2): the 2x2 footprint, each texel compared (PCF), then weighted.
    #[allow(clippy::too_many_arguments)]
    fn sample_linear<O: Observer>(
        &self,
        st: &SamplerState,
        level: u32,
        l: &LevelDesc,
        layer: u32,
        face: Option<cube::Face>,
        p: &LevelPoint,
        dref: f32,
        scale: f32,
        obs: &mut O,
    ) -> f32 {
        let fp = Self::linear_footprint(st, l, layer, face, p);
        let mut raw = [0.0f32; 4];
        for (k, (r, &(i, j, ly))) in raw.iter_mut().zip(&fp.pos).enumerate() {
            if fp.missing != Some(k) {
                *r = self.fetch(st, l, i, j, ly);
            }
        }
        if O::ACTIVE {
            self.report_footprint(st, obs, level, l, &fp, &raw, dref, scale);
        }
        if st.kind == Kind::Compare && st.faults.has(Fault::FilterThenCompare) {
            return Self::filter_then_compare(st, &fp, &raw, dref);
        }
        self.percentage_closer(st, &fp, raw, dref)
    }

    /// The LINEAR footprint: i0, i1, α and j0, j1, β (§8.14.2) and the bilinear weights; seamless
    /// cubes use CLAMP_TO_BORDER and then replace border locations by the neighbouring face's
    /// texels (§8.13.1).
    #[inline(always)]
    fn linear_footprint(
        st: &SamplerState,
        l: &LevelDesc,
        layer: u32,
        face: Option<cube::Face>,
        p: &LevelPoint,
    ) -> Footprint {
        let f = st.faults;
        let (w, h) = (l.width, l.height);
        let (ls, lt) = if st.seamless {
            (Wrap::ClampToBorder, Wrap::ClampToBorder)
        } else {
            (p.ws, p.wt)
        };
        let (i0, i1, alpha) = wrap::linear(ls, p.u, w, f);
        let (i0, i1) = (p.shift(i0, 0, w), p.shift(i1, 0, w));
        let (j0, j1, beta) = if p.one_d {
            (0, 0, 0.0)
        } else {
            wrap::linear(lt, p.v, h, f)
        };
        let (j0, j1) = (p.shift(j0, 1, h), p.shift(j1, 1, h));
        let mut pos = [
            (i0, j0, layer),
            (i1, j0, layer),
            (i0, j1, layer),
            (i1, j1, layer),
        ];
        let mut missing = None;
        if let (true, Some(face)) = (st.seamless, face) {
            let base = layer - face as u32;
            for (k, p) in pos.iter_mut().enumerate() {
                match cube::neighbour(face, p.0, p.1, l.width as i64) {
                    Some((nf, ni, nj)) => *p = (ni, nj, base + nf as u32),
                    None => missing = Some(k),
                }
            }
        }
        let weights = [
            (1.0 - alpha) * (1.0 - beta),
            alpha * (1.0 - beta),
            (1.0 - alpha) * beta,
            alpha * beta,
        ];
        Footprint {
            pos,
            weights,
            missing,
        }
    }

    /// Reports the footprint's texels to the observer, each with its share of the value.
    #[allow(clippy::too_many_arguments)]
    fn report_footprint<O: Observer>(
        &self,
        st: &SamplerState,
        obs: &mut O,
        level: u32,
        l: &LevelDesc,
        fp: &Footprint,
        raw: &[f32; 4],
        dref: f32,
        scale: f32,
    ) {
        for (k, &(i, j, ly)) in fp.pos.iter().enumerate() {
            if fp.missing == Some(k) {
                continue;
            }
            // A missing corner's weight is shared equally by the other three texels.
            let wk = fp.weights[k] + fp.missing.map_or(0.0, |m| fp.weights[m] / 3.0);
            self.report(
                st,
                obs,
                level,
                Self::loc(l, i, j, ly),
                raw[k],
                dref,
                wk * scale,
            );
        }
    }

    /// Fault only ([`Fault::FilterThenCompare`]): Dt filtered first, the result compared once.
    fn filter_then_compare(st: &SamplerState, fp: &Footprint, raw: &[f32; 4], dref: f32) -> f32 {
        let mut d = [0.0f32; 4];
        for (dk, &r) in d.iter_mut().zip(raw) {
            *dk = if st.clamp.dt { clamp01(r) } else { r };
        }
        if let Some(m) = fp.missing {
            d[m] = (d.iter().sum::<f32>() - d[m]) / 3.0;
        }
        let filtered: f32 = (0..4).map(|k| fp.weights[k] * d[k]).sum();
        if passes(st.op, dref, filtered, st.faults) {
            st.pass
        } else {
            st.fail
        }
    }

    /// Percentage-closer filtering: each texel resolved (compared), then the bilinear weights.
    #[inline(always)]
    fn percentage_closer(
        &self,
        st: &SamplerState,
        fp: &Footprint,
        mut raw: [f32; 4],
        dref: f32,
    ) -> f32 {
        if let Some(m) = fp.missing {
            // Cube corner: no unique neighbour; the fourth texel is the average of the three
            // available texels' values (the recommended method of §8.13.1), and is then compared
            // like any texel (a comparison yields only the pass or the fail value per texel).
            raw[m] = (raw.iter().sum::<f32>() - raw[m]) / 3.0;
        }
        let mut vals = [0.0f32; 4];
        for k in 0..4 {
            vals[k] = self.resolve(st, raw[k], dref);
        }
        let weights = fp.weights;
        weights[0] * vals[0] + weights[1] * vals[1] + weights[2] * vals[2] + weights[3] * vals[3]
    }
}

/// One level's lookup point in texel space (see [`PreparedTexture::level_point`]).
struct LevelPoint {
    /// u, v of equation 8.10 (the offset already added unless `late_offset` holds it).
    u: f32,
    v: f32,
    /// Fault only ([`Fault::OffsetAfterWrap`]): the offset, added to the wrapped texel index.
    late_offset: Option<[i32; 2]>,
    /// Wrap modes for s and t (CLAMP_TO_EDGE on a seamless cube).
    ws: Wrap,
    wt: Wrap,
    /// 1D and 1D array: j is 0.
    one_d: bool,
}

impl LevelPoint {
    /// Texel index `i` on `axis` (0: i, 1: j) of a level `n` texels wide; under
    /// [`Fault::OffsetAfterWrap`] the offset added to the wrapped index, then clamped into the image.
    #[inline(always)]
    fn shift(&self, i: i64, axis: usize, n: u32) -> i64 {
        match self.late_offset {
            Some(d) if (0..n as i64).contains(&i) => (i + d[axis] as i64).clamp(0, n as i64 - 1),
            _ => i,
        }
    }
}

/// The LINEAR footprint of one level (see [`PreparedTexture::linear_footprint`]).
struct Footprint {
    /// (i, j, storage layer) of τi0j0, τi1j0, τi0j1, τi1j1.
    pos: [(i64, i64, u32); 4],
    /// (1 − α)(1 − β), α(1 − β), (1 − α)β, αβ.
    weights: [f32; 4],
    /// A seamless cube corner's texel with no unique neighbour.
    missing: Option<usize>,
}
