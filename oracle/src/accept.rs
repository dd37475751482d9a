//! From per-texel possibilities to acceptance intervals: the idea of VK-GL-CTS tcuTexCompareVerifier
//! (enumerate the pass/fail assignments of ambiguous texels, interpolate over weight bounds), written
//! for this oracle's data.

use crate::profile::{ProfileSpec, PROFILES};
use crate::sample::TexelEval;
use crate::unorm::{f32_candidates, unorm_max, Exact};
use shadowcheck_model::{Acceptance, Interval};

/// The texels one level contributes and their bilinear / linear weights' parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Taps {
    /// NEAREST: one texel, weight 1.
    One(usize),
    /// 1D LINEAR: τ = (1 − α)τ_i0 + ατ_i1.
    Lin1([usize; 2], f64),
    /// 2D LINEAR (§8.14.2): τ = (1−α)(1−β)τ_i0j0 + α(1−β)τ_i1j0 + (1−α)βτ_i0j1 + αβτ_i1j1.
    Lin2([usize; 4], f64, f64),
}

impl Taps {
    /// (texel, weight) pairs for the given α, β.
    pub fn weighted(&self, a: f64, b: f64) -> ([usize; 4], [f64; 4], usize) {
        match *self {
            Taps::One(i) => ([i, 0, 0, 0], [1.0, 0.0, 0.0, 0.0], 1),
            Taps::Lin1([i0, i1], _) => ([i0, i1, 0, 0], [1.0 - a, a, 0.0, 0.0], 2),
            Taps::Lin2(t, _, _) => (
                t,
                [(1.0 - a) * (1.0 - b), a * (1.0 - b), (1.0 - a) * b, a * b],
                4,
            ),
        }
    }
    fn ab(&self) -> (f64, f64) {
        match *self {
            Taps::One(_) => (0.0, 0.0),
            Taps::Lin1(_, a) => (a, 0.0),
            Taps::Lin2(_, a, b) => (a, b),
        }
    }
    pub fn texels(&self) -> &[usize] {
        match self {
            Taps::One(i) => std::slice::from_ref(i),
            Taps::Lin1(t, _) => t,
            Taps::Lin2(t, _, _) => t,
        }
    }
}

/// One way the lookup may be carried out: one level, or two levels blended by f ∈ [f_lo, f_hi].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scen {
    pub a: (u32, Taps),
    pub b: Option<(u32, Taps)>,
    pub f: f64,
    pub f_lo: f64,
    pub f_hi: f64,
}

impl Scen {
    /// More than one texel takes part (a filtered result).
    pub fn filtered(&self) -> bool {
        self.b.is_some() || !matches!(self.a.1, Taps::One(_))
    }
}

fn bounds(x: f64, tol: f64) -> [f64; 2] {
    [(x - tol).max(0.0), (x + tol).min(1.0)]
}

/// min and max of one level's filtered value over the weight box, texel values from `val`.
fn level_range(t: &Taps, tol: f64, val: &dyn Fn(usize) -> (f64, f64)) -> (f64, f64) {
    let (a, b) = t.ab();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    // The value is multilinear in (α, β): its extremes over the box are at the corners.
    for a in bounds(a, tol) {
        for b in bounds(b, tol) {
            let (ix, w, n) = t.weighted(a, b);
            let (mut l, mut h) = (0.0, 0.0);
            for k in 0..n {
                let (vl, vh) = val(ix[k]);
                l += w[k] * vl;
                h += w[k] * vh;
            }
            lo = lo.min(l);
            hi = hi.max(h);
        }
    }
    (lo, hi)
}

fn blend(s: &Scen, tol: f64, r1: (f64, f64), r2: Option<(f64, f64)>) -> Interval {
    match r2 {
        None => Interval::new(r1.0, r1.1),
        Some(r2) => {
            // "τ = [1 − frac(λ)]τ1 + frac(λ)τ2": linear in f, extremes at the ends of its range.
            let fs = [(s.f_lo - tol).max(0.0), (s.f_hi + tol).min(1.0)];
            let lo = fs
                .iter()
                .map(|f| (1.0 - f) * r1.0 + f * r2.0)
                .fold(f64::INFINITY, f64::min);
            let hi = fs
                .iter()
                .map(|f| (1.0 - f) * r1.1 + f * r2.1)
                .fold(f64::NEG_INFINITY, f64::max);
            Interval::new(lo, hi)
        }
    }
}

/// Largest number of ambiguous texels enumerated one assignment at a time (2^8 for trilinear).
const MAX_ENUMERATED: usize = 10;

/// Appends the intervals `prof` (the `pi`-th entry of `PROFILES`) accepts for one scenario.
/// `should_proportional`: a comparison under a spec that leaves filtered r "implementation-dependent"
/// and says only that it "should be ... proportional to the number of comparison passes or failures"
/// (GL 4.6 §8.23.1); a profile with `mixed_footprint_any` then takes any value between the fail
/// value and 1 for a filtered footprint that may hold both a pass and a fail.
pub fn scen_intervals(
    s: &Scen,
    texels: &[TexelEval],
    pi: usize,
    prof: &ProfileSpec,
    should_proportional: bool,
    out: &mut Vec<Interval>,
) {
    let poss = |i: usize| texels[i].poss[pi];
    let hull = |i: usize| (poss(i).lo, poss(i).hi);
    let all = || {
        s.a.1
            .texels()
            .iter()
            .chain(s.b.iter().flat_map(|b| b.1.texels()))
    };
    if prof.mixed_footprint_any && should_proportional && s.filtered() {
        // Every value the footprint's texels may take: two different ones means a pass and a fail.
        let lo = all().map(|&i| poss(i).lo).fold(f64::INFINITY, f64::min);
        let hi = all().map(|&i| poss(i).hi).fold(f64::NEG_INFINITY, f64::max);
        if lo < hi {
            out.push(Interval::new(lo, hi));
            return;
        }
    }
    let mut amb: Vec<usize> = Vec::new();
    for t in all() {
        if poss(*t).two && !amb.contains(t) {
            amb.push(*t);
        }
    }
    let tol = prof.weight_tol;
    if amb.len() > MAX_ENUMERATED {
        let r1 = level_range(&s.a.1, tol, &hull);
        let r2 = s.b.as_ref().map(|b| level_range(&b.1, tol, &hull));
        out.push(blend(s, tol, r1, r2));
        return;
    }
    for mask in 0u32..(1u32 << amb.len()) {
        let val = |i: usize| match amb.iter().position(|a| *a == i) {
            Some(k) => {
                let v = if mask >> k & 1 == 1 {
                    poss(i).hi
                } else {
                    poss(i).lo
                };
                (v, v)
            }
            None => hull(i),
        };
        let r1 = level_range(&s.a.1, tol, &val);
        let r2 = s.b.as_ref().map(|b| level_range(&b.1, tol, &val));
        out.push(blend(s, tol, r1, r2));
    }
}

/// The spec value of a scenario: exact weights and each texel's exact r. `None` if any texel with a
/// non-zero weight has none.
pub fn spec_value(s: &Scen, texels: &[TexelEval]) -> Option<f64> {
    let level = |t: &Taps| -> Option<f64> {
        let (a, b) = t.ab();
        let (ix, w, n) = t.weighted(a, b);
        let mut sum = 0.0;
        for k in 0..n {
            if w[k] != 0.0 {
                sum += w[k] * texels[ix[k]].exact?;
            }
        }
        Some(sum)
    };
    let v1 = level(&s.a.1)?;
    match &s.b {
        None => Some(v1),
        Some(_) if s.f == 0.0 => Some(v1),
        Some(b) => Some((1.0 - s.f) * v1 + s.f * level(&b.1)?),
    }
}

/// (texel, exact weight) of a scenario, for the footprint.
pub fn weights(s: &Scen) -> Vec<(usize, f64)> {
    let mut out: Vec<(usize, f64)> = Vec::new();
    let mut add = |t: &Taps, scale: f64| {
        let (a, b) = t.ab();
        let (ix, w, n) = t.weighted(a, b);
        for k in 0..n {
            match out.iter_mut().find(|(i, _)| *i == ix[k]) {
                Some(e) => e.1 += w[k] * scale,
                None => out.push((ix[k], w[k] * scale)),
            }
        }
    };
    match &s.b {
        None => add(&s.a.1, 1.0),
        Some(b) => {
            add(&s.a.1, 1.0 - s.f);
            add(&b.1, s.f);
        }
    }
    out
}

/// Sorts and merges overlapping intervals.
pub fn merge(mut v: Vec<Interval>) -> Vec<Interval> {
    v.sort_by(|a, b| a.lo.total_cmp(&b.lo));
    let mut out: Vec<Interval> = Vec::with_capacity(v.len());
    for i in v {
        match out.last_mut() {
            Some(l) if i.lo <= l.hi => l.hi = l.hi.max(i.hi),
            _ => out.push(i),
        }
    }
    out
}

/// The last steps from per-scenario intervals to the acceptance sets, one per profile in `PROFILES`
/// order:
/// - `colour_bits` (filtered colour lookups only): a filtered colour value may be returned at the
///   format's precision (either neighbour, §2.3.5.2): ends between two multiples of 1/(2^b − 1) widen
///   to them; an end on a multiple stays (a single texel is exactly c/(2^b − 1), (2.1));
/// - `value_slack` (lookups that return a value, not a comparison): a profile with a reference
///   precision 2^-b also takes the returned value within 2^-b (GL 4.6 §2.3.4.1: "individual results
///   of floating-point operations are accurate to about 1 part in 10^5"), not past [0, 1];
/// - the result reaches the observer as an f32: ends widen outward to the nearest f32;
/// - sets stay inside `range` (r ∈ [fail, 1] for a comparison), and rounding noise of weighted sums
///   (an ulp) is absorbed so that the sets hold the spec value;
/// - a looser profile never accepts less: each set is united with the (final) one before it.
pub fn finalize(
    mut sets: Vec<Vec<Interval>>,
    colour_bits: Option<u32>,
    value_slack: bool,
    range: (f64, f64),
    spec_value: Option<f64>,
) -> Vec<Acceptance> {
    for (set, prof) in sets.iter_mut().zip(PROFILES) {
        for iv in set.iter_mut() {
            if let Some(bits) = colour_bits {
                // An end already on a multiple of 1/(2^b − 1) (up to f64 noise) stays there: (2.1)
                // f = c/(2^b − 1) is exact, only a value between two multiples may go to either.
                let m = unorm_max(bits) as f64;
                let snap = |x: f64, up: bool| {
                    let k = x * m;
                    if (k - k.round()).abs() < 1e-6 {
                        k.round() / m
                    } else if up {
                        k.ceil() / m
                    } else {
                        k.floor() / m
                    }
                };
                (iv.lo, iv.hi) = (snap(iv.lo, false), snap(iv.hi, true));
            }
            if let (true, Some(bits)) = (value_slack, prof.ref_bits) {
                let t = (bits as f64).exp2().recip();
                (iv.lo, iv.hi) = (
                    (iv.lo - t).max(iv.lo.min(0.0)),
                    (iv.hi + t).min(iv.hi.max(1.0)),
                );
            }
            (iv.lo, iv.hi) = (
                f32_candidates(Exact::F(iv.lo))[0],
                f32_candidates(Exact::F(iv.hi))[1],
            );
            (iv.lo, iv.hi) = (iv.lo.max(range.0), iv.hi.min(range.1));
        }
        if let Some(v) = spec_value {
            if !set.iter().any(|i| i.contains(v)) {
                if let Some(iv) = set
                    .iter_mut()
                    .find(|i| (i.lo - v).abs() <= 1e-12 || (i.hi - v).abs() <= 1e-12)
                {
                    (iv.lo, iv.hi) = (iv.lo.min(v), iv.hi.max(v));
                }
            }
        }
    }
    let mut out: Vec<Acceptance> = Vec::with_capacity(sets.len());
    for mut set in sets {
        if let Some(stricter) = out.last() {
            set.extend(stricter.0.iter().copied());
        }
        out.push(Acceptance(merge(set)));
    }
    out
}
