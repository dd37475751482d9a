//! The families that test where a lookup reads: mip levels and LOD state, wrap modes and the
//! border, cube faces, array layers, and mixed filter classes.

use super::super::cells::{pattern_texture, PATTERN};
use super::super::draft::{lookup, texture, Cell, Draft};
use super::super::specs::SpecDims;
use super::{cell, clamp_formats, fixed_fmt, main_func};
use crate::build::{self, num, nums, At};
use shadowcheck_model::*;

/// Nominal value of each level of the mip family's 4x4 chain.
const MIP: [f64; 3] = [0.2, 0.8, 0.4];

fn mip_chain(c: &Cell, base_level: u32) -> Texture {
    let mut levels = Vec::new();
    for (i, size) in [4u32, 2, 1]
        .into_iter()
        .enumerate()
        .skip(base_level as usize)
    {
        levels.push(build::level(
            c.format,
            size,
            size,
            1,
            &vec![MIP[i]; (size * size) as usize],
        ));
    }
    Texture {
        target: c.target,
        format: c.format,
        base_level,
        levels,
    }
}

/// Level selection: a 4x4 -> 1x1 chain with levels 0.2, 0.8, 0.4 at lambda from -1 (magnification)
/// to 3 (past the last level), R 0.3 and 0.5 (together they tell all three levels apart); then the
/// LOD state: MIN_LOD, MAX_LOD, BASE_LEVEL, MAX_LEVEL, TEXTURE_LOD_BIAS and the shader bias.
pub fn mip(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    let tags = format!("levels={}", nums(&MIP));
    for &filter in d.filters.iter().filter(|f| f.is_mipmap()) {
        let c = cell(d, Target::T2d, fmt, filter, func);
        let tex = mip_chain(&c, 0);
        for lod in [-1.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0] {
            for r in [0.3, 0.5] {
                let mut lk = lookup(Target::T2d, At::st(0.5, 0.5), 4, 4, r);
                lk.lod = lod;
                out.push(Draft::new(
                    "mip",
                    c,
                    tex.clone(),
                    lk,
                    format!("lod={lod}/ref={r}/{tags}"),
                ));
            }
        }
        type Variant = (&'static str, fn(&mut Draft));
        // Every variant is generated; the spec's filters (grids::spec_grid) drop the state a spec
        // does not have.
        let variants: [Variant; 6] = [
            ("min_lod=1", |x| x.sampler.min_lod = 1.0),
            ("max_lod=0.5", |x| x.sampler.max_lod = 0.5),
            ("max_level=1", |x| x.sampler.max_level = Some(1)),
            ("base_level=1", |x| x.texture = mip_chain(&x.cell, 1)),
            ("lod_bias=1", |x| x.sampler.lod_bias = 1.0),
            ("bias=1", |x| x.lookup.bias = 1.0),
        ];
        for (name, apply) in variants {
            for lod in [0.0, 2.0] {
                let mut lk = lookup(Target::T2d, At::st(0.5, 0.5), 4, 4, 0.5);
                lk.lod = lod;
                let mut x = Draft::new(
                    "mip",
                    c,
                    tex.clone(),
                    lk,
                    format!("{name}/lod={lod}/ref=0.5/{tags}"),
                );
                apply(&mut x);
                out.push(x);
            }
        }
    }
    out
}

/// Wrap modes with coordinates outside [0,1], and a border depth (1.0) that differs from every
/// edge texel (pattern 0.2 .. 0.8), R = 0.5. D32F also gets a border outside [0,1].
pub fn wrap(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    const COORDS: [(f64, f64); 7] = [
        (-0.25, 0.25),
        (-0.75, 0.25),
        (1.25, 0.25),
        (1.6, 0.75),
        (2.3, 0.25),
        (-1.3, 0.75),
        (0.25, 1.25),
    ];
    for &wrap in d.wraps {
        for filter in [Filter::Nearest, Filter::Linear] {
            let c = cell(d, Target::T2d, fmt, filter, func);
            let (tex, w, h, _) = pattern_texture(&c);
            for (s, t) in COORDS {
                let mut x = Draft::new(
                    "wrap",
                    c,
                    tex.clone(),
                    lookup(Target::T2d, At::st(s, t), w, h, 0.5),
                    format!("wrap={wrap}/st={s}_{t}/border=1/ref=0.5"),
                );
                x.sampler.wrap_s = wrap;
                x.sampler.wrap_t = wrap;
                x.sampler.wrap_r = wrap;
                x.sampler.border = [1.0, 0.0, 0.0, 0.0];
                out.push(x);
            }
        }
    }
    out.extend(wrap_texel_centres(d));
    out.extend(wrap_pairs(d));
    out.extend(rect_wraps(d));
    if d.formats.contains(&Format::D32f) && d.wraps.contains(&Wrap::ClampToBorder) {
        let c = cell(d, Target::T2d, Format::D32f, Filter::Nearest, func);
        let (tex, w, h, _) = pattern_texture(&c);
        for (border, r) in [(1.5, 1.25), (-0.5, -0.25), (-0.5, 0.0)] {
            let mut x = Draft::new(
                "wrap",
                c,
                tex.clone(),
                lookup(Target::T2d, At::st(-0.25, 0.25), w, h, r),
                format!(
                    "wrap=border/st=-0.25_0.25/border={}/ref={}",
                    num(border),
                    num(r)
                ),
            );
            x.sampler.wrap_s = Wrap::ClampToBorder;
            x.sampler.wrap_t = Wrap::ClampToBorder;
            x.sampler.border = [border as f32, 0.0, 0.0, 0.0];
            out.push(x);
        }
    }
    // ARB_shadow 3.8.13.1 puts Dt in [0, 1] for the pre-3.0 specs (GL 4.6 leaves a fixed-point border
    // outside [0, 1] undefined, ES 3.2 clamps it): border 1.5 reads as 1, -0.5 as 0.
    if matches!(d.spec, Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs)
        && d.wraps.contains(&Wrap::ClampToBorder)
    {
        let pairs = [
            (1.5, 1.0, CompareFunc::Gequal),
            (-0.5, 0.0, CompareFunc::Lequal),
        ];
        for (border, r, func) in pairs {
            let c = cell(d, Target::T2d, fmt, Filter::Nearest, func);
            let (tex, w, h, _) = pattern_texture(&c);
            let mut x = Draft::new(
                "wrap",
                c,
                tex.clone(),
                lookup(Target::T2d, At::st(-0.25, 0.25), w, h, r),
                format!(
                    "wrap=border/st=-0.25_0.25/border={}/ref={}",
                    num(border),
                    num(r)
                ),
            );
            x.sampler.wrap_s = Wrap::ClampToBorder;
            x.sampler.wrap_t = Wrap::ClampToBorder;
            x.sampler.border = [border as f32, 0.0, 0.0, 0.0];
            out.push(x);
        }
    }
    out
}

/// LINEAR exactly at texel centres of the repetitions left and right of the image (s = -0.25 and
/// 1.75 on the 2-texel pattern: α = 0, so one texel alone is the result, §8.14.2), read with compare
/// NONE (the value names the texel) and compared with R = 0.3, between the texels 0.2 and 0.4 that
/// a wrong mirrored index would swap (piglit's `texwrap formats` on softpipe: reports/piglit, H2).
/// ES has no NONE read here: a sized depth texture with COMPARE_MODE NONE and LINEAR is incomplete
/// there (ES 3.2 §8.17), which the `incomplete` family covers. The border colour is set only for
/// the modes that read it.
fn wrap_texel_centres(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let modes: &[CompareMode] = if matches!(
        d.spec,
        Spec::Gles32 | Spec::Es2Ext | Spec::Vulkan | Spec::WebGpu
    ) {
        &[CompareMode::Compare]
    } else {
        &[CompareMode::None, CompareMode::Compare]
    };
    for &wrap in d.wraps {
        for &mode in modes {
            let c = Cell {
                mode,
                ..cell(d, Target::T2d, fmt, Filter::Linear, main_func(d))
            };
            let (tex, w, h, _) = pattern_texture(&c);
            for s in [-0.25, 1.75] {
                let what = if mode == CompareMode::None {
                    "read".to_string()
                } else {
                    "ref=0.3".to_string()
                };
                let mut x = Draft::new(
                    "wrap",
                    c,
                    tex.clone(),
                    lookup(Target::T2d, At::st(s, 0.25), w, h, 0.3),
                    format!("wrap={wrap}/centre/st={s}_0.25/{what}"),
                );
                x.sampler.wrap_s = wrap;
                x.sampler.wrap_t = wrap;
                x.sampler.wrap_r = wrap;
                if matches!(wrap, Wrap::ClampToBorder | Wrap::Clamp) {
                    x.sampler.border = [1.0, 0.0, 0.0, 0.0];
                }
                out.push(x);
            }
        }
    }
    out
}

/// s and t wrapped by different modes (Table 8.20 applies each coordinate's own TEXTURE_WRAP_S /
/// _T): both coordinates off the image, so a lookup that wraps t by s's mode (or the reverse)
/// reads other texels; border 1.0 as in [`wrap`], R = 0.5.
fn wrap_pairs(d: &SpecDims) -> Vec<Draft> {
    use Wrap::*;
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let pairs = [
        (Repeat, ClampToEdge),
        (ClampToEdge, Repeat),
        (MirroredRepeat, ClampToBorder),
        (ClampToBorder, MirroredRepeat),
        (Clamp, Repeat),
    ];
    // WebGPU has no border colour (GPUSamplerDescriptor): its pairs keep the default.
    let border: u8 = if d.spec == Spec::WebGpu { 0 } else { 1 };
    for (ws, wt) in pairs
        .into_iter()
        .filter(|(a, b)| d.wraps.contains(a) && d.wraps.contains(b))
    {
        for filter in [Filter::Nearest, Filter::Linear] {
            let c = cell(d, Target::T2d, fmt, filter, main_func(d));
            let (tex, w, h, _) = pattern_texture(&c);
            for (s, t) in [(1.25, -0.25), (-0.75, 1.6)] {
                let mut x = Draft::new(
                    "wrap",
                    c,
                    tex.clone(),
                    lookup(Target::T2d, At::st(s, t), w, h, 0.5),
                    format!("wrap_s={ws}/wrap_t={wt}/st={s}_{t}/border={border}/ref=0.5"),
                );
                x.sampler.wrap_s = ws;
                x.sampler.wrap_t = wt;
                x.sampler.border = [f32::from(border), 0.0, 0.0, 0.0];
                out.push(x);
            }
        }
    }
    out
}

/// Rectangle textures with the wrap modes they allow (GL 4.6 §8.10: only the clamp modes; REPEAT
/// and the mirrored modes are an INVALID_ENUM, which the oracle's `check` rejects): unnormalized
/// coordinates off the image in s, in t and in both, border 1.0, R = 0.5.
fn rect_wraps(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !d.targets.contains(&Target::Rect) {
        return out;
    }
    let fmt = fixed_fmt(d);
    for wrap in [Wrap::ClampToEdge, Wrap::ClampToBorder, Wrap::Clamp] {
        if !d.wraps.contains(&wrap) {
            continue;
        }
        for filter in [Filter::Nearest, Filter::Linear] {
            let c = cell(d, Target::Rect, fmt, filter, main_func(d));
            let (tex, w, h, _) = pattern_texture(&c);
            for (s, t) in [(-0.25, 0.25), (1.3, 0.75), (0.25, 1.6), (-0.5, 1.5)] {
                let mut x = Draft::new(
                    "wrap",
                    c,
                    tex.clone(),
                    lookup(Target::Rect, At::st(s, t), w, h, 0.5),
                    format!("wrap={wrap}/st={s}_{t}/border=1/ref=0.5"),
                );
                x.sampler.wrap_s = wrap;
                x.sampler.wrap_t = wrap;
                x.sampler.border = [1.0, 0.0, 0.0, 0.0];
                out.push(x);
            }
        }
    }
    out
}

/// Cube faces: every face (each major axis, both signs) holds its own values, 0.1 + 0.13 face +
/// 0.02 texel; NEAREST hits texels 0 and 3 of each face with R just below and above; LINEAR samples
/// each face's centre (2 of 4 texels pass) and near an edge (s = 0.9, where seamless filtering
/// matters).
pub fn cube(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let func = main_func(d);
    for &target in d.targets.iter().filter(|t| t.is_cube()) {
        for fmt in clamp_formats(d) {
            let n = if target == Target::CubeArray { 2 } else { 1 };
            let (w, h, layers) = build::dims(target, 2, n);
            let face_vals = |f: u32| -> Vec<f64> {
                (0..4)
                    .map(|i| 0.1 + 0.13 * f as f64 + 0.02 * i as f64)
                    .collect()
            };
            let mut vals = Vec::new();
            for l in 0..layers {
                let f = l % 6;
                let fv = face_vals(f);
                let sampled = target == Target::Cube || l / 6 == 1;
                vals.extend(fv.iter().map(|v| if sampled { *v } else { 1.0 - *v }));
            }
            let cube_index = if target == Target::CubeArray {
                1.0
            } else {
                0.0
            };
            for filter in [Filter::Nearest, Filter::Linear] {
                let c = cell(d, target, fmt, filter, func);
                let tex = texture(&c, vec![build::level(fmt, w, h, layers, &vals)]);
                for face in 0..6u32 {
                    let fv = face_vals(face);
                    if filter == Filter::Nearest {
                        for (i, s, t) in [(0usize, 0.25, 0.25), (3, 0.75, 0.75)] {
                            for (tag, dr) in [("below", -0.01), ("above", 0.01)] {
                                let r = fv[i] + dr;
                                let lk = lookup(
                                    target,
                                    At {
                                        s,
                                        t,
                                        layer: cube_index,
                                        face,
                                    },
                                    w,
                                    h,
                                    r,
                                );
                                out.push(Draft::new(
                                    "cube",
                                    c,
                                    tex.clone(),
                                    lk,
                                    format!("face={face}/texel={i}/ref={tag}"),
                                ));
                            }
                        }
                    } else {
                        let r = fv[1] + 0.01;
                        for (tag, s) in [("centre", 0.5), ("edge", 0.9)] {
                            let lk = lookup(
                                target,
                                At {
                                    s,
                                    t: 0.5,
                                    layer: cube_index,
                                    face,
                                },
                                w,
                                h,
                                r,
                            );
                            out.push(Draft::new(
                                "cube",
                                c,
                                tex.clone(),
                                lk,
                                format!("face={face}/{tag}/ref={}", num(r)),
                            ));
                        }
                    }
                }
            }
        }
    }
    out
}

/// The wrap modes [`cube_wraps`] sets on cube faces (those of a spec's list).
pub const CUBE_WRAPS: [Wrap; 3] = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToBorder];

/// Cube faces with the wrap modes other than CLAMP_TO_EDGE, LINEAR at an edge (s = 0.9) and a
/// corner (s = t = 0.9) of faces +X and +Z, border 1.0: where cube filtering is seamless the modes
/// are ignored (GL 4.6 §8.13.1: "If LINEAR filtering is done within a miplevel, always apply wrap
/// mode CLAMP_TO_BORDER" to reach the adjacent face); where it is not (GL's default), the face is
/// a 2D image wrapped by the modes (§8.13: "the new s and t are used to find a texture value in the
/// determined face's two-dimensional image using the rules given in sections 8.14 through 8.15").
pub fn cube_wraps(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let func = main_func(d);
    let fmt = fixed_fmt(d);
    let wraps = CUBE_WRAPS;
    for &target in d.targets.iter().filter(|t| t.is_cube()) {
        let n = if target == Target::CubeArray { 2 } else { 1 };
        let (w, h, layers) = build::dims(target, 2, n);
        // Texel k of layer l: 0.1 + 0.13 (l mod 6) + 0.02 k, so every face and texel differs.
        let vals: Vec<f64> = (0..layers)
            .flat_map(|l| (0..4).map(move |k| 0.1 + 0.13 * (l % 6) as f64 + 0.02 * k as f64))
            .collect();
        let cube_index = if target == Target::CubeArray {
            1.0
        } else {
            0.0
        };
        for wrap in wraps.into_iter().filter(|w| d.wraps.contains(w)) {
            let c = cell(d, target, fmt, Filter::Linear, func);
            let tex = texture(&c, vec![build::level(fmt, w, h, layers, &vals)]);
            for face in [0u32, 4] {
                let r = 0.1 + 0.13 * face as f64 + 0.03;
                for (tag, s, t) in [("edge", 0.9, 0.5), ("corner", 0.9, 0.9)] {
                    let at = At {
                        s,
                        t,
                        layer: cube_index,
                        face,
                    };
                    let mut x = Draft::new(
                        "cube",
                        c,
                        tex.clone(),
                        lookup(target, at, w, h, r),
                        format!("wrap={wrap}/face={face}/{tag}/border=1/ref={}", num(r)),
                    );
                    x.sampler.wrap_s = wrap;
                    x.sampler.wrap_t = wrap;
                    x.sampler.wrap_r = wrap;
                    x.sampler.border = [1.0, 0.0, 0.0, 0.0];
                    out.push(x);
                }
            }
        }
    }
    out
}

/// Array layer selection: layers hold 0.2, 0.8, 0.4 (cube arrays: per cube); the layer coordinate
/// is rounded (floor(layer + 0.5)) and clamped to [0, d-1] (GL 4.6 §8.14.2).
pub fn layer(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    const VALS: [f64; 3] = [0.2, 0.8, 0.4];
    // NEAREST: RNE(r) or ⌊r + 1/2⌋ (footnote 4); LINEAR: ⌊r + 1/2⌋ only, so its ties are covered too.
    let runs: [(Filter, &[f64]); 2] = [
        (
            Filter::Nearest,
            &[-1.0, -0.5, -0.49, 0.49, 0.5, 1.4999, 1.5, 2.5, 3.7],
        ),
        (Filter::Linear, &[-0.5, 0.49, 0.5, 1.5, 2.5]),
    ];
    for &target in d.targets.iter().filter(|t| t.is_array()) {
        for (filter, ls) in runs {
            let c = cell(d, target, fmt, filter, func);
            let (w, h, layers) = build::dims(target, 2, 3);
            let per = (w * h) as usize * if target.is_cube() { 6 } else { 1 };
            let vals: Vec<f64> = (0..layers as usize * (w * h) as usize)
                .map(|i| VALS[i / per])
                .collect();
            let tex = texture(&c, vec![build::level(fmt, w, h, layers, &vals)]);
            for &l in ls {
                for r in [0.3, 0.6] {
                    let lk = lookup(
                        target,
                        At {
                            s: 0.25,
                            t: 0.25,
                            layer: l,
                            face: 0,
                        },
                        w,
                        h,
                        r,
                    );
                    out.push(Draft::new(
                        "layer",
                        c,
                        tex.clone(),
                        lk,
                        format!("layer={l}/ref={r}/layers={}", nums(&VALS)),
                    ));
                }
            }
        }
        // Mipmapped: a 2-level chain with the same values on every level of a layer, λ = 0.5 (both
        // levels under *_MIPMAP_LINEAR), the layer at its rounding ties: every level reads the same
        // layer "l = clamp(RNE(r), 0, d_s − 1)" (§8.14.2; footnote 4 allows ⌊r + 1/2⌋ instead).
        for &filter in d.filters.iter().filter(|f| f.is_mipmap()) {
            let c = cell(d, target, fmt, filter, func);
            let chain: Vec<Level> = [2u32, 1]
                .into_iter()
                .map(|size| {
                    let (w, h, layers) = build::dims(target, size, 3);
                    let per = (w * h) as usize * if target.is_cube() { 6 } else { 1 };
                    let vals: Vec<f64> = (0..layers as usize * (w * h) as usize)
                        .map(|i| VALS[i / per])
                        .collect();
                    build::level(fmt, w, h, layers, &vals)
                })
                .collect();
            let (w, h, _) = build::dims(target, 2, 3);
            let tex = texture(&c, chain);
            for l in [-0.5, 0.5, 1.5, 2.5] {
                for r in [0.3, 0.6] {
                    let mut lk = lookup(
                        target,
                        At {
                            s: 0.25,
                            t: 0.25,
                            layer: l,
                            face: 0,
                        },
                        w,
                        h,
                        r,
                    );
                    lk.lod = 0.5;
                    out.push(Draft::new(
                        "layer",
                        c,
                        tex.clone(),
                        lk,
                        format!("layer={l}/lod=0.5/ref={r}/layers={}", nums(&VALS)),
                    ));
                }
            }
        }
    }
    out
}

/// Mixed filter classes (GL 4.6 §8.23.1, ES 3.2 §8.20.1: with MAG_FILTER not NEAREST or MIN_FILTER
/// not NEAREST / NEAREST_MIPMAP_NEAREST, "r may be computed by comparing more than one depth texture
/// value", whichever filter the lookup ends up using): min NEAREST + mag LINEAR and min LINEAR + mag
/// NEAREST, each magnified (λ = -1), at the crossover (λ = 0, magnified) and minified (λ = 1), on the
/// 2x2 PCF pattern.
pub fn mixfilter(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    for (min, mag) in [
        (Filter::Nearest, Filter::Linear),
        (Filter::Linear, Filter::Nearest),
    ] {
        let c = cell(d, Target::T2d, fmt, min, func);
        let (tex, w, h, _) = pattern_texture(&c);
        // λ = 0 is the crossover itself: "less than or equal to zero" magnifies (§8.14.1).
        for lod in [-1.0, 0.0, 1.0] {
            for r in [0.3, 0.5, 0.7] {
                let mut lk = lookup(Target::T2d, At::st(0.375, 0.375), w, h, r);
                lk.lod = lod;
                let mut dr = Draft::new(
                    "mixfilter",
                    c,
                    tex.clone(),
                    lk,
                    format!("mag={}/lod={lod}/ref={r}/dt={}", mag.key(), nums(&PATTERN)),
                );
                dr.sampler.mag_filter = mag;
                out.push(dr);
            }
        }
    }
    out
}
