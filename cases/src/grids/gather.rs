//! The `gather` family: shadow `textureGather`, `textureGatherOffset` and `textureGatherOffsets`
//! (GL 4.6 / ES 3.2 §8.14.2, GLSL 4.60 §8.9.4) on the sampler types that have them (2D, 2D array,
//! cube, cube array; rectangle on GL).
//!
//! Every texel of every image holds its own value, v(layer, x, y) = (16·layer + 4y + x + ½) / (16·n)
//! (n images), so that the four comparisons against one reference give a pattern that tells the
//! texels apart: with the footprint i0 = j0 = 1 the four texels are increasing in the order
//! τi0j0 < τi1j0 < τi0j1 < τi1j1, and the references between them give (1,1,1,0), (1,1,0,0) and
//! (0,1,0,0) under LEQUAL: a rotated component order, a missing comparison or another image shows.
//! Coordinates sit a quarter texel from the footprint boundary (u − ½ = 1.25), never on it.

use super::draft::{lookup, texture, Cell, Draft};
use super::families::{cell, fixed_fmt, main_func};
use super::specs::SpecDims;
use crate::build::{self, At};
use shadowcheck_model::*;

/// Width and height of level base.
const SIZE: u32 = 4;

/// The image values of a `SIZE`×`SIZE` level of `images` layers (cube faces count as layers).
fn values(images: u32) -> Vec<f64> {
    let n = (16 * images) as f64;
    (0..images * SIZE * SIZE)
        .map(|k| (k as f64 + 0.5) / n)
        .collect()
}

/// The level of the cell's target and format (arrays: 2 layers, cube arrays: 2 cubes).
fn level(c: &Cell) -> (Level, u32) {
    let (w, h, layers) = build::dims(c.target, SIZE, 2);
    let vals = values(layers);
    (build::level(c.format, w, h, layers, &vals), layers)
}

/// The image the lookups read: layer 1 of arrays, face 4 (+Z) of cubes, cube 1 of cube arrays.
fn image(target: Target) -> (f64, u32, u32) {
    match target {
        Target::T2dArray => (1.0, 0, 1),
        Target::Cube => (0.0, 4, 4),
        Target::CubeArray => (1.0, 4, 10),
        _ => (0.0, 0, 0),
    }
}

/// References between the footprint texels at i0 = j0 = 1 of image `img` (of `n`): between
/// τi0j0 and τi1j0, τi1j0 and τi0j1, τi0j1 and τi1j1.
fn refs(img: u32, n: u32) -> [f64; 3] {
    let d = (16 * n) as f64;
    let base = 16.0 * img as f64;
    [(base + 6.0) / d, (base + 8.0) / d, (base + 10.0) / d]
}

/// A gather draft at texel-space (u, v) of `c`'s image with reference `dref`.
fn draft(c: Cell, tex: Texture, u: f64, v: f64, dref: f64, tags: String) -> Draft {
    let (layer, face, _) = image(c.target);
    let at = At {
        s: u / SIZE as f64,
        t: v / SIZE as f64,
        layer,
        face,
    };
    let mut lk = lookup(c.target, at, SIZE, SIZE, dref);
    lk.gather = Some(Gather { offsets: None });
    Draft::new("gather", c, tex, lk, tags)
}

/// The gather family of spec `d` (GL 4.6, ES 3.2, Vulkan and WebGPU).
pub fn gather(d: &SpecDims) -> Vec<Draft> {
    if !matches!(
        d.spec,
        Spec::Gl46 | Spec::Gles32 | Spec::Vulkan | Spec::WebGpu
    ) {
        return Vec::new();
    }
    let targets: Vec<Target> = [
        Target::T2d,
        Target::T2dArray,
        Target::Cube,
        Target::CubeArray,
        Target::Rect,
    ]
    .into_iter()
    .filter(|t| d.targets.contains(t))
    .collect();
    let mut out = Vec::new();
    // Every target, both filter classes (ignored by gather), the three references; the fixed-point
    // format and D32F; LEQUAL, and GREATER on 2D.
    for &t in &targets {
        let mut formats = vec![fixed_fmt(d)];
        if d.formats.contains(&Format::D32f) {
            formats.push(Format::D32f);
        }
        for &format in &formats {
            for filter in [Filter::Nearest, Filter::Linear] {
                let mut funcs = vec![main_func(d)];
                if t == Target::T2d && format == fixed_fmt(d) {
                    funcs.push(CompareFunc::Greater);
                }
                for func in funcs {
                    let c = cell(d, t, format, filter, func);
                    let (lvl, n) = level(&c);
                    let tex = texture(&c, vec![lvl]);
                    let img = image(t).2;
                    for r in refs(img, n) {
                        out.push(draft(
                            c,
                            tex.clone(),
                            1.75,
                            2.25,
                            r,
                            format!("uv=1.75_2.25/ref={}", build::num(r)),
                        ));
                    }
                }
            }
        }
    }
    out.extend(wraps(d, &targets));
    out.extend(offsets(d, &targets));
    out.extend(lod_ignored(d));
    // Vulkan: an image view's component mapping is not TEXTURE_SWIZZLE (not modelled here);
    // WebGPU has no swizzle on a depth view.
    if !super::specs::sampler_create(d.spec) {
        out.extend(swizzles(d, &targets));
    }
    out
}

/// TEXTURE_SWIZZLE_R on a gather: each texel's post-swizzle R component (GL 4.6 / ES 3.2 §8.14.2,
/// Figure 8.4), so RED gives the comparisons, GREEN / BLUE / ZERO 0 and ALPHA / ONE 1; the
/// unswizzled comparisons are the named other reading (contradiction `gather-swizzle`). The middle
/// reference gives the mixed pattern (1,1,0,0), so every reading is told apart from the others.
fn swizzles(d: &SpecDims, targets: &[Target]) -> Vec<Draft> {
    use Swizzle::*;
    const SW: [[Swizzle; 4]; 4] = [
        [Zero, Green, Blue, Alpha],
        [Alpha, Red, Red, Red],
        [Green, Red, Blue, Alpha],
        [Red, One, Zero, Green],
    ];
    let mut out = Vec::new();
    for &t in targets
        .iter()
        .filter(|t| matches!(t, Target::T2d | Target::Cube))
    {
        let c = cell(d, t, fixed_fmt(d), Filter::Linear, main_func(d));
        let (lvl, n) = level(&c);
        let tex = texture(&c, vec![lvl]);
        let r = refs(image(t).2, n)[1];
        for sw in SW {
            let key: Vec<&str> = sw.iter().map(|c| c.key()).collect();
            let mut x = draft(
                c,
                tex.clone(),
                1.75,
                2.25,
                r,
                format!(
                    "swizzle={}/uv=1.75_2.25/ref={}",
                    key.join("_"),
                    build::num(r)
                ),
            );
            x.sampler.swizzle = Some(sw);
            out.push(x);
        }
    }
    out
}

/// Footprints that leave the image: the wrap applies to each texel (i0 = −1 and j1 = SIZE).
fn wraps(d: &SpecDims, targets: &[Target]) -> Vec<Draft> {
    let mut out = Vec::new();
    for &t in targets.iter().filter(|t| !t.is_cube()) {
        let c = cell(d, t, fixed_fmt(d), Filter::Linear, main_func(d));
        let (lvl, n) = level(&c);
        let img = image(t).2;
        let wraps: Vec<Wrap> = d
            .wraps
            .iter()
            .copied()
            .filter(|w| *w != Wrap::Clamp)
            .filter(|w| t != Target::Rect || matches!(w, Wrap::ClampToEdge | Wrap::ClampToBorder))
            .collect();
        for wrap in wraps {
            let borders: &[f32] = if wrap == Wrap::ClampToBorder {
                &[0.0, 1.0]
            } else {
                &[0.0]
            };
            for &b in borders {
                let tex = texture(&c, vec![lvl.clone()]);
                let dn = (16 * n) as f64;
                for r in [
                    (16.0 * img as f64 + 2.0) / dn,
                    (16.0 * img as f64 + 14.0) / dn,
                ] {
                    let mut x = draft(
                        c,
                        tex.clone(),
                        0.25,
                        3.75,
                        r,
                        format!("wrap={wrap}/border={b}/uv=0.25_3.75/ref={}", build::num(r)),
                    );
                    x.sampler.wrap_s = wrap;
                    x.sampler.wrap_t = wrap;
                    x.sampler.border = [b, 0.0, 0.0, 0.0];
                    out.push(x);
                }
            }
        }
    }
    out
}

/// textureGatherOffset and textureGatherOffsets on the non-cube targets, REPEAT (rectangles:
/// CLAMP_TO_EDGE), including the extremes every implementation supports (−8, 7).
fn offsets(d: &SpecDims, targets: &[Target]) -> Vec<Draft> {
    const ONE: [[i32; 2]; 4] = [[1, 0], [-1, -1], [-8, 7], [7, -8]];
    const FOUR: [[[i32; 2]; 4]; 3] = [
        // The plain gather's own texels, by offsets.
        [[0, 1], [1, 1], [1, 0], [0, 0]],
        [[0, 0], [0, 0], [0, 0], [0, 0]],
        [[-8, 7], [7, -8], [2, -1], [-1, 2]],
    ];
    let mut out = Vec::new();
    for &t in targets.iter().filter(|t| !t.is_cube()) {
        let c = cell(d, t, fixed_fmt(d), Filter::Nearest, main_func(d));
        let (lvl, n) = level(&c);
        let tex = texture(&c, vec![lvl]);
        let img = image(t).2;
        let wrap = if t == Target::Rect {
            Wrap::ClampToEdge
        } else {
            Wrap::Repeat
        };
        let r = refs(img, n)[1];
        for o in ONE {
            let mut x = draft(
                c,
                tex.clone(),
                1.75,
                2.25,
                r,
                format!("offset={}_{}/wrap={wrap}/ref={}", o[0], o[1], build::num(r)),
            );
            x.lookup.offset = [o[0], o[1], 0];
            (x.sampler.wrap_s, x.sampler.wrap_t) = (wrap, wrap);
            out.push(x);
        }
        // WGSL has no textureGatherOffsets (textureGatherCompare takes one const offset).
        let four: &[[[i32; 2]; 4]] = if d.spec == Spec::WebGpu { &[] } else { &FOUR };
        for (k, &o) in four.iter().enumerate() {
            let mut x = draft(
                c,
                tex.clone(),
                1.75,
                2.25,
                r,
                format!("offsets={k}/wrap={wrap}/ref={}", build::num(r)),
            );
            x.lookup.gather = Some(Gather { offsets: Some(o) });
            (x.sampler.wrap_s, x.sampler.wrap_t) = (wrap, wrap);
            out.push(x);
        }
    }
    out
}

/// A mipmapped 2D texture and a λ that would pick level 1 (all 1: every texel passes) under a
/// mipmap filter: gather reads level base ("the minification and magnification filters are
/// ignored"; "the texture image of level levelbase").
fn lod_ignored(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    for filter in [Filter::NearestMipmapNearest, Filter::LinearMipmapLinear] {
        if !d.filters.contains(&filter) {
            continue;
        }
        let c = cell(d, Target::T2d, fixed_fmt(d), filter, main_func(d));
        let (l0, n) = level(&c);
        let l1 = build::level(c.format, 2, 2, 1, &[1.0; 4]);
        let l2 = build::level(c.format, 1, 1, 1, &[1.0]);
        let tex = texture(&c, vec![l0, l1, l2]);
        for r in refs(0, n) {
            let mut x = draft(
                c,
                tex.clone(),
                1.75,
                2.25,
                r,
                format!("lod=1/uv=1.75_2.25/ref={}", build::num(r)),
            );
            x.lookup.lod = 1.0;
            out.push(x);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gather_cases_exist_for_gl_es_vulkan_and_webgpu_only_and_all_evaluate() {
        for d in super::super::specs::all() {
            let v = gather(&d);
            assert_eq!(
                !v.is_empty(),
                matches!(
                    d.spec,
                    Spec::Gl46 | Spec::Gles32 | Spec::Vulkan | Spec::WebGpu
                ),
                "{:?}",
                d.spec
            );
            for x in v {
                let case = x.into_case();
                assert!(case.lookup.gather.is_some());
                assert!(case.api.iter().all(|a| matches!(
                    a,
                    ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
                )));
                let e = shadowcheck_oracle::evaluate(&case)
                    .unwrap_or_else(|e| panic!("{}: {e}", case.id));
                assert!(e.expect.gather.is_some(), "{}", case.id);
            }
        }
    }

    #[test]
    fn the_three_references_give_three_patterns() {
        // LEQUAL at i0 = j0 = 1 of a 2D image: τ(1,1) < τ(2,1) < τ(1,2) < τ(2,2).
        let v = values(1);
        let at = |x: usize, y: usize| v[y * SIZE as usize + x];
        let [a, b, c] = refs(0, 1);
        assert!(at(1, 1) < a && a < at(2, 1) && at(2, 1) < b && b < at(1, 2));
        assert!(at(1, 2) < c && c < at(2, 2));
    }
}
