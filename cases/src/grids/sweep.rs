//! Sweeps: every compiled sampling state of the grid checks many lookups.
//!
//! Drivers such as llvmpipe compile one shader variant per sampling state, so what a state costs
//! is fixed and what it checks is the grid's choice. For every (spec, compiled state) of the
//! grid's cases ([`crate::coverage::state_key`]) the first cases covering its API paths become
//! hosts and get a sweep of up to [`POINTS`] more lookups on their own texture and sampler: the
//! host's lookup moved across level base (texel centres, quarter and half texels, past the edge,
//! so the wrap modes take part) with references at, just below and just above every stored value
//! of the texture (both sides of each tie), at 0 and at 1. Each point's expectation is the
//! oracle's, computed like any case's; a point the oracle rejects, or whose result layout differs
//! from its host's, is not written.

use crate::build::{real, Stored};
use crate::coverage::{state_key, StateKey};
use shadowcheck_model::{
    ApiPath, Case, CompareMode, PointExpectation, Spec, SweepPoint, Target, Texels,
};
use std::collections::BTreeMap;

/// Points per sweep (at most; fewer where the oracle rejects some or they would leave a cube
/// face) on a host that runs on a GLSL 1.30+ / ES 3.00 path ...
pub const POINTS: usize = 28;
/// ... and on the other hosts: the legacy paths (ff, arbfp, glsl120, es100) share each state
/// among up to four specs' hosts, so fewer points per host give them as many checks per state.
pub const LEGACY_POINTS: usize = 16;

/// Distance of the references just below and just above a stored value (more than the
/// reference precision of every depth format: 2^-10).
const NEAR: f64 = 1.0 / 1024.0;

/// Shifts of the lookup (along s, along t) in texels of level base, one per point: odd
/// multiples of 1/8, so that from the grid's positions (texel centres, quarter texels, texel
/// edges of LINEAR lookups) a point never lands on a texel edge, where NEAREST selection is
/// decided by the last bit of the coordinate arithmetic; [`off_edges`] rejects the rest.
/// More, odd multiples of 1/16 and then shifts of under half a texel (what fits on a cube face
/// of 2x2 texels), are tried when some of the first are rejected.
const SHIFTS: [(f64, f64); 40] = [
    (0.125, 0.125),
    (0.375, -0.125),
    (-0.375, 0.375),
    (0.625, 0.625),
    (-0.625, -0.375),
    (0.875, 0.125),
    (1.125, -0.625),
    (-1.125, 0.875),
    (1.375, 1.125),
    (-0.125, -0.875),
    (1.875, 0.375),
    (-1.875, 1.375),
    (2.625, -1.125),
    (2.125, -1.625),
    (-0.875, 2.125),
    (3.125, 0.625),
    (0.0625, 0.1875),
    (0.3125, -0.4375),
    (-0.1875, 0.6875),
    (0.5625, -0.0625),
    (-0.5625, 0.3125),
    (0.9375, -0.3125),
    (-0.9375, 0.5625),
    (1.0625, 0.9375),
    (1.3125, -0.8125),
    (-1.3125, -0.1875),
    (1.6875, 0.4375),
    (-1.6875, 1.0625),
    (2.3125, -1.3125),
    (-2.0625, 0.8125),
    (2.8125, -0.5625),
    (-2.5625, 1.5625),
    (-0.125, -0.125),
    (0.125, -0.375),
    (-0.3125, -0.3125),
    (0.4375, 0.4375),
    (-0.4375, 0.0625),
    (0.1875, -0.1875),
    (-0.0625, 0.4375),
    (-0.1875, -0.0625),
];

/// Closest a point's coordinate may come to a texel edge of level base (in texels).
const EDGE_MARGIN: f64 = 1.0 / 32.0;

/// Adds sweeps to `cases` (already evaluated: hosts need their expectation).
pub fn add_sweeps(cases: &mut [Case]) {
    for (host, points) in plan(cases) {
        cases[host].sweep = points;
    }
}

/// The hosts and their points, computed on all cores.
fn plan(cases: &[Case]) -> Vec<(usize, Vec<SweepPoint>)> {
    let hosts = hosts(cases);
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, 16);
    let chunk = hosts.len().div_ceil(threads).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = hosts
            .chunks(chunk)
            .map(|part| {
                s.spawn(move || {
                    part.iter()
                        .map(|&h| (h, points(&cases[h])))
                        .filter(|(_, p)| !p.is_empty())
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    })
}

/// Per (spec, state): the first cases, in generation order, that cover every API path the state
/// is run on (a case with more paths first).
fn hosts(cases: &[Case]) -> Vec<usize> {
    let mut groups: BTreeMap<(Spec, StateKey), Vec<usize>> = BTreeMap::new();
    for (i, c) in cases.iter().enumerate() {
        if can_host(c) {
            groups.entry((c.spec, state_key(c))).or_default().push(i);
        }
    }
    let mut out = Vec::new();
    for (_, mut members) in groups {
        members.sort_by_key(|&i| std::cmp::Reverse(cases[i].api.len()));
        let mut covered: Vec<ApiPath> = Vec::new();
        for i in members {
            if cases[i].api.iter().any(|a| !covered.contains(a)) {
                covered.extend(cases[i].api.iter().copied());
                out.push(i);
            }
        }
    }
    out.sort_unstable();
    out
}

/// A case can carry a sweep: a depth comparison (COMPARE_REF_TO_TEXTURE in effect) with finite
/// inputs and an expectation, not a gather. Plain depth reads (compare mode NONE) get none: a
/// LINEAR read of equal texels is exact under `strict`, and the f32 arithmetic of a weighted sum
/// (the soft unit's included) lands one ulp off it, a Warn that says nothing about comparison.
fn can_host(c: &Case) -> bool {
    c.sampler.in_effect().compare_mode == CompareMode::Compare
        && c.lookup.gather.is_none()
        && !c.texture.format.is_multi_colour()
        && c.expect.is_some()
        && c.lookup.dref.is_finite()
        && c.lookup.coord.iter().all(|v| v.is_finite())
        && !c.texture.levels.is_empty()
}

/// The references of a sweep: each distinct stored value of level base, just below and just
/// above it, 0 and 1 (sorted, distinct).
fn references(c: &Case) -> Vec<f64> {
    let format = c.texture.format;
    let mut stored: Vec<f64> = match &c.texture.levels[0].depth {
        Texels::Unorm(v) => v.iter().map(|&x| real(format, Stored::Unorm(x))).collect(),
        Texels::Float(v) => v.iter().map(|&x| real(format, Stored::Float(x))).collect(),
        // A colour texture's reference changes nothing (comparison is bypassed).
        Texels::Colour(_) => vec![],
    };
    stored.sort_by(f64::total_cmp);
    stored.dedup();
    let mut refs = vec![0.0, 1.0];
    for v in stored.into_iter().take(8) {
        refs.extend([v - NEAR, v, v + NEAR]);
    }
    let mut refs: Vec<f64> = refs
        .into_iter()
        .map(|v| v.clamp(0.0, 1.0) as f32 as f64)
        .collect();
    refs.sort_by(f64::total_cmp);
    refs.dedup();
    refs
}

/// The cube-map major axis of a direction (s, t, r): the component of largest magnitude.
fn major_axis(coord: &[f64; 4]) -> usize {
    (0..3)
        .max_by(|&a, &b| coord[a].abs().total_cmp(&coord[b].abs()))
        .unwrap_or(2)
}

/// The host's coordinates moved by (ds, dt) texels of level base, in the form the lookup passes
/// them (normalized, or texels for a rectangle; times q for a projective lookup; on a cube map,
/// along the two axes of the selected face).
fn moved(c: &Case, ds: f64, dt: f64) -> [f64; 4] {
    let l = &c.lookup;
    let level = &c.texture.levels[0];
    let (w, h) = (level.width.max(1) as f64, level.height.max(1) as f64);
    let q = if l.projective { l.coord[3] } else { 1.0 };
    let mut coord = l.coord;
    match c.texture.target {
        Target::Rect => {
            coord[0] += ds * q;
            coord[1] += dt * q;
        }
        Target::T1d | Target::T1dArray => coord[0] += ds / w * q,
        Target::T2d | Target::T2dArray => {
            coord[0] += ds / w * q;
            coord[1] += dt / h * q;
        }
        Target::Cube | Target::CubeArray => {
            // The major axis stays; the other two move by 2|ma|/w per texel of the face.
            let m = major_axis(&coord);
            let scale = 2.0 * coord[m].abs() / w;
            let others: Vec<usize> = (0..3).filter(|&a| a != m).collect();
            coord[others[0]] += ds * scale;
            coord[others[1]] += dt * scale;
        }
    }
    coord
}

/// The texel-space position (u, v) on level base of coordinates `coord` of case `c` (after the
/// projective divide; on a cube map, on the face of the major axis, with whether the point stays
/// within the face's outermost texel centres).
fn texel_position(c: &Case, coord: &[f64; 4]) -> (f64, f64, bool) {
    let level = &c.texture.levels[0];
    let (w, h) = (level.width.max(1) as f64, level.height.max(1) as f64);
    let q = if c.lookup.projective { coord[3] } else { 1.0 };
    match c.texture.target {
        Target::Rect => (coord[0] / q, coord[1] / q, true),
        Target::T1d | Target::T1dArray => (coord[0] / q * w, 0.5, true),
        Target::T2d | Target::T2dArray => (coord[0] / q * w, coord[1] / q * h, true),
        Target::Cube | Target::CubeArray => {
            let m = major_axis(coord);
            let ma = coord[m].abs().max(f64::MIN_POSITIVE);
            let others: Vec<f64> = (0..3).filter(|&a| a != m).map(|a| coord[a] / ma).collect();
            // A LINEAR footprint stays on the face at every level the lookup may reach: no edge
            // or corner texels, whose values the specs leave to the implementation's arithmetic.
            let bias = f64::from(c.sampler.lod_bias);
            let top = (c.lookup.lod + c.lookup.bias + bias).max(0.0).ceil() as u32 + 1;
            let last = top.min(c.texture.levels.len().saturating_sub(1) as u32);
            let inside = (0..=last).all(|n| {
                let wn = ((w as u32) >> n).max(1) as f64;
                others.iter().all(|x| {
                    let u = (x + 1.0) / 2.0 * wn;
                    (0.5..=wn - 0.5).contains(&u)
                })
            });
            let u = (others[0] + 1.0) / 2.0 * w;
            let v = (others[1] + 1.0) / 2.0 * w;
            (u, v, inside)
        }
    }
}

/// Whether a point at `coord` stays off the texel edges of level base (and, on a cube map,
/// within the face its host is on: a face change is the cube families' business).
fn off_edges(c: &Case, coord: &[f64; 4]) -> bool {
    let (u, v, inside) = texel_position(c, coord);
    let clear = |x: f64| (x - x.round()).abs() >= EDGE_MARGIN;
    inside && clear(u) && clear(v)
}

/// Up to [`POINTS`] points for host `c`, each evaluated by the oracle.
fn points(c: &Case) -> Vec<SweepPoint> {
    let Some(host) = c.expect.as_ref() else {
        return vec![];
    };
    let refs = references(c);
    let q = if c.lookup.projective {
        c.lookup.coord[3]
    } else {
        1.0
    };
    let modern = c
        .api
        .iter()
        .any(|a| matches!(a, ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es300));
    let want = if modern { POINTS } else { LEGACY_POINTS };
    let mut out: Vec<SweepPoint> = Vec::with_capacity(want);
    for (k, &(ds, dt)) in SHIFTS.iter().enumerate() {
        if out.len() == want {
            break;
        }
        // References visited with a stride that is coprime with most list lengths, so the
        // coordinates and references mix.
        let r = refs[(k * 5 + 1) % refs.len()];
        let p = SweepPoint {
            coord: moved(c, ds, dt),
            dref: r * q,
            expect: None,
        };
        if (p.coord == c.lookup.coord && p.dref == c.lookup.dref)
            || out.iter().any(|o| o.coord == p.coord && o.dref == p.dref)
            || !off_edges(c, &p.coord)
        {
            continue;
        }
        let probe = Case {
            lookup: c.point_lookup(&p),
            expect: None,
            sweep: vec![],
            ..c.clone()
        };
        let Ok(ev) = shadowcheck_oracle::evaluate(&probe) else {
            continue;
        };
        if ev.expect.layout != host.layout {
            continue;
        }
        if let Some(e) = PointExpectation::of(&ev.expect) {
            out.push(SweepPoint {
                expect: Some(e),
                ..p
            });
        }
    }
    out
}
