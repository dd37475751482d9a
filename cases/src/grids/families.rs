//! Focused families of the default grid, each crossing fewer dimensions than the main product but
//! with the edge values that make a verdict mean something (see cases/README.md, "Grids").

use super::cells::{pattern_texture, PATTERN};
use super::draft::{lookup, texture, Cell, Draft};
use super::specs::SpecDims;
use crate::build::{self, num, nums, At, Stored};
use shadowcheck_model::*;

/// A fixed-point depth format of the spec (D24, else D16, else unsized).
pub fn fixed_fmt(d: &SpecDims) -> Format {
    [Format::D24, Format::D16, Format::DepthUnsized]
        .into_iter()
        .find(|f| d.formats.contains(f))
        .unwrap_or(d.formats[0])
}

/// The formats whose clamping rules differ: one fixed-point, and D32F where the spec has it.
fn clamp_formats(d: &SpecDims) -> Vec<Format> {
    let mut v = vec![fixed_fmt(d)];
    if d.formats.contains(&Format::D32f) {
        v.push(Format::D32f);
    }
    v
}

/// Depth formats without stencil (those whose stored values differ in precision).
pub(super) fn plain_depth_formats(d: &SpecDims) -> Vec<Format> {
    d.formats
        .iter()
        .copied()
        .filter(|f| f.is_depth() && !f.has_stencil())
        .collect()
}

/// The function the single-function families use: LEQUAL (R <= Dt) where the spec has it, else
/// its first operator (SGIX: TEXTURE_LEQUAL_R_SGIX). Never NEVER/ALWAYS, whose constant result
/// would hide a wrong texel, level, layer or face.
pub fn main_func(d: &SpecDims) -> CompareFunc {
    if d.funcs.contains(&CompareFunc::Lequal) {
        CompareFunc::Lequal
    } else {
        d.funcs[0]
    }
}

/// Two functions with opposite results away from ties: LEQUAL and GEQUAL (SGIX: its two operators).
pub fn func_pair(d: &SpecDims) -> [CompareFunc; 2] {
    if d.funcs.contains(&CompareFunc::Gequal) {
        [CompareFunc::Lequal, CompareFunc::Gequal]
    } else {
        [d.funcs[0], d.funcs[d.funcs.len() - 1]]
    }
}

pub(super) fn cell(
    d: &SpecDims,
    target: Target,
    format: Format,
    filter: Filter,
    func: CompareFunc,
) -> Cell {
    Cell {
        spec: d.spec,
        target,
        format,
        filter,
        mode: CompareMode::Compare,
        func,
        dtm: None,
    }
}

/// A 1x1 2D texture holding `v` (exact stored value).
fn one_texel(c: &Cell, v: Stored) -> Texture {
    texture(c, vec![build::level_exact(c.format, 1, 1, 1, &[v])])
}

/// R and Dt at and beyond the clamping edges: R in {-inf, -0.1, 0, 0.5, 1, 1.1, 1e30, inf,
/// NaN} against Dt in {0, 0.5, 1}; for D32F also stored values outside [0,1] (the upload clamp).
pub fn clamp(d: &SpecDims) -> Vec<Draft> {
    const REFS: [f64; 9] = [
        f64::NEG_INFINITY,
        -0.1,
        0.0,
        0.5,
        1.0,
        1.1,
        1e30,
        f64::INFINITY,
        f64::NAN,
    ];
    let mut out = Vec::new();
    for fmt in clamp_formats(d) {
        let mut dts = vec![0.0, 0.5, 1.0];
        if fmt == Format::D32f {
            dts.extend([-0.5, 1.5]);
        }
        for &func in d.funcs {
            let c = cell(d, Target::T2d, fmt, Filter::Nearest, func);
            for &dt in &dts {
                let tex = one_texel(&c, build::store(fmt, dt));
                for r in REFS {
                    let lk = lookup(Target::T2d, At::st(0.5, 0.5), 1, 1, r);
                    out.push(Draft::new(
                        "clamp",
                        c,
                        tex.clone(),
                        lk,
                        format!("dt={}/ref={}", num(dt), num(r)),
                    ));
                }
            }
        }
    }
    out
}

/// Exactly stored values against R at, just below and just above them (adjacent f32 values):
/// unorm c in {0, 1, 2^(b-1), 2^b - 1}; D32F 0, 2^-24, 0.5, 1. Where c / (2^b - 1) is not an f32,
/// "at" is its nearest f32 and the oracle marks the tie.
pub fn exact(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    for fmt in plain_depth_formats(d) {
        let stored: Vec<Stored> = match fmt.unorm_bits() {
            Some(b) => {
                let max = build::unorm_max(b) as u32;
                vec![
                    Stored::Unorm(0),
                    Stored::Unorm(1),
                    Stored::Unorm(1 << (b - 1)),
                    Stored::Unorm(max),
                ]
            }
            None => vec![
                Stored::Float(0.0),
                Stored::Float(2f32.powi(-24)),
                Stored::Float(0.5),
                Stored::Float(1.0),
            ],
        };
        for &func in d.funcs {
            let c = cell(d, Target::T2d, fmt, Filter::Nearest, func);
            for &s in &stored {
                let tex = one_texel(&c, s);
                let at = build::f32r(build::real(fmt, s));
                let label = match s {
                    Stored::Unorm(v) => format!("c={v}"),
                    Stored::Float(v) => format!("dt={}", num(v as f64)),
                };
                let mut refs = vec![
                    ("at-", build::f32_next_down(at)),
                    ("at", at),
                    ("at+", build::f32_next_up(at)),
                ];
                if matches!(func, CompareFunc::Equal | CompareFunc::Notequal) {
                    // Near misses beyond the quality 16-bit reference precision: an EQUAL with a
                    // tolerance (mutant equal-with-tolerance) passes them.
                    refs.push(("at-2^-14", build::f32r(at - 2f64.powi(-14))));
                    refs.push(("at+2^-14", build::f32r(at + 2f64.powi(-14))));
                }
                for (tag, r) in refs {
                    let lk = lookup(Target::T2d, At::st(0.5, 0.5), 1, 1, r);
                    out.push(Draft::new(
                        "exact",
                        c,
                        tex.clone(),
                        lk,
                        format!("{label}/ref={tag}"),
                    ));
                }
            }
        }
    }
    out
}

/// Bilinear footprints with 0 to 4 passing texels at known weights: the 2x2 pattern 0.2, 0.4,
/// 0.6, 0.8 sampled at (alpha, beta) in {(0.25,0.5), (0.5,0.5), (0.25,0.75)} with R in {0.1, 0.3,
/// 0.5, 0.7, 0.9}.
pub fn pcf(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    for fmt in clamp_formats(d) {
        for &func in d.funcs {
            let c = cell(d, Target::T2d, fmt, Filter::Linear, func);
            let (tex, w, h, _) = pattern_texture(&c);
            for (a, b) in [(0.25, 0.5), (0.5, 0.5), (0.25, 0.75)] {
                for r in [0.1, 0.3, 0.5, 0.7, 0.9] {
                    let lk = lookup(
                        Target::T2d,
                        At::st((0.5 + a) / 2.0, (0.5 + b) / 2.0),
                        w,
                        h,
                        r,
                    );
                    out.push(Draft::new(
                        "pcf",
                        c,
                        tex.clone(),
                        lk,
                        format!("a={a}_{b}/ref={r}/dt={}", nums(&PATTERN)),
                    ));
                }
            }
        }
    }
    out
}

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
    }
    out
}

/// Mixed filter classes (GL 4.6 §8.23.1, ES 3.2 §8.20.1: with MAG_FILTER not NEAREST or MIN_FILTER
/// not NEAREST / NEAREST_MIPMAP_NEAREST, "r may be computed by comparing more than one depth texture
/// value", whichever filter the lookup ends up using): min NEAREST + mag LINEAR and min LINEAR + mag
/// NEAREST, each magnified (λ = -1) and minified (λ = 1), on the 2x2 PCF pattern.
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
        for lod in [-1.0, 1.0] {
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

/// DEPTH_TEXTURE_MODE (each value) x format x compare mode, NEAREST 2D, with LEQUAL and GEQUAL
/// (one passes, one fails; the mode only decides where r goes, not r itself).
pub fn dtm(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if d.dtms.is_empty() {
        return out;
    }
    for &m in d.dtms {
        for &fmt in d.formats {
            for mode in [CompareMode::Compare, CompareMode::None] {
                let funcs: Vec<CompareFunc> = if mode == CompareMode::None {
                    vec![d.funcs[0]]
                } else {
                    func_pair(d).to_vec()
                };
                for func in funcs {
                    let c = Cell {
                        dtm: Some(m),
                        mode,
                        ..cell(d, Target::T2d, fmt, Filter::Nearest, func)
                    };
                    let (tex, w, h, _) = pattern_texture(&c);
                    let lk = lookup(Target::T2d, At::st(0.75, 0.25), w, h, 0.3);
                    out.push(Draft::new(
                        "dtm",
                        c,
                        tex,
                        lk,
                        format!("dtm={m}/texel1/ref=0.3"),
                    ));
                }
            }
        }
    }
    out
}

/// DEPTH_STENCIL_TEXTURE_MODE: STENCIL_INDEX reads the stencil integer (no compare), DEPTH_COMPONENT
/// (explicit) compares as usual; NEAREST and LINEAR (a stencil texture with LINEAR is incomplete).
pub fn stencil(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !d.stencil_mode {
        return out;
    }
    for &fmt in d.formats.iter().filter(|f| f.has_stencil()) {
        for dsm in [
            DepthStencilMode::StencilIndex,
            DepthStencilMode::DepthComponent,
        ] {
            for filter in [Filter::Nearest, Filter::Linear] {
                for mode in [CompareMode::Compare, CompareMode::None] {
                    let c = Cell {
                        mode,
                        ..cell(d, Target::T2d, fmt, filter, main_func(d))
                    };
                    let (tex, w, h, _) = pattern_texture(&c);
                    for (i, s, t) in [(1, 0.75, 0.25), (2, 0.25, 0.75)] {
                        let mut x = Draft::new(
                            "stencil",
                            c,
                            tex.clone(),
                            lookup(Target::T2d, At::st(s, t), w, h, 0.5),
                            format!(
                                "dsm={dsm}/texel{i}/ref=0.5/stencil={}",
                                build::stencil_value(i)
                            ),
                        );
                        x.sampler.depth_stencil_mode = Some(dsm);
                        out.push(x);
                    }
                }
            }
        }
    }
    out
}

/// Texture completeness: a mipmap filter with only level 0 (incomplete), the same with
/// MAX_LEVEL = 0 (complete), and a chain with a wrongly sized level 1 (incomplete).
pub fn incomplete(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    for mode in [CompareMode::Compare, CompareMode::None] {
        let c = Cell {
            mode,
            ..cell(
                d,
                Target::T2d,
                fmt,
                Filter::NearestMipmapNearest,
                main_func(d),
            )
        };
        let (tex, w, h, _) = pattern_texture(&c);
        let lk = lookup(Target::T2d, At::st(0.75, 0.25), w, h, 0.3);
        out.push(Draft::new(
            "incomplete",
            c,
            tex.clone(),
            lk.clone(),
            "level0-only/texel1/ref=0.3".into(),
        ));
        let mut x = Draft::new(
            "incomplete",
            c,
            tex.clone(),
            lk.clone(),
            "level0-only/max_level=0/texel1/ref=0.3".into(),
        );
        x.sampler.max_level = Some(0);
        out.push(x);
        let mut bad = tex.clone();
        bad.levels.push(bad.levels[0].clone());
        out.push(Draft::new(
            "incomplete",
            c,
            bad,
            lk,
            "level1-size=2x2/texel1/ref=0.3".into(),
        ));
    }
    out
}

/// Projective lookups: s, t and R divided by q (q = 2, 0.5, -1) at texel 2 (0.6); R = 0.8 after
/// the divide is 1.6 before it, so clamping before the divide would change the result.
pub fn proj(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let funcs = func_pair(d);
    for &target in d
        .targets
        .iter()
        .filter(|t| matches!(t, Target::T1d | Target::T2d | Target::Rect))
    {
        for func in funcs {
            let c = cell(d, target, fmt, Filter::Nearest, func);
            let (tex, w, h, _) = pattern_texture(&c);
            let at = if target.dims() == 1 {
                At::st(2.5 / 4.0, 0.0)
            } else {
                At::st(0.25, 0.75)
            };
            for (q, r) in [
                (2.0, 0.5),
                (2.0, 0.7),
                (2.0, 0.8),
                (0.5, 0.5),
                (0.5, 0.7),
                (-1.0, 0.5),
            ] {
                let mut lk = lookup(target, at, w, h, r * q);
                for i in 0..3 {
                    lk.coord[i] *= q;
                }
                lk.coord[3] = q;
                lk.projective = true;
                out.push(Draft::new(
                    "proj",
                    c,
                    tex.clone(),
                    lk,
                    format!("q={q}/texel2/ref={r}"),
                ));
            }
        }
    }
    out
}

/// Fail / ambient values 0, 0.25, 0.5, 1 with NEAREST (pass and fail) and LINEAR (2 of 4 pass).
pub fn ambient(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !d.fail_value {
        return out;
    }
    for fmt in [fixed_fmt(d), Format::DepthUnsized] {
        for &func in d.funcs {
            for filter in [Filter::Nearest, Filter::Linear] {
                let c = cell(d, Target::T2d, fmt, filter, func);
                let (tex, w, h, _) = pattern_texture(&c);
                // 1.5 and -0.5: the value is clamped to [0, 1] when specified (ARB_shadow_ambient).
                for fail in [0.0f32, 0.25, 0.5, 1.0, 1.5, -0.5] {
                    let lks: Vec<(At, f64, &str)> = if filter == Filter::Nearest {
                        vec![
                            (At::st(0.75, 0.25), 0.3, "texel1"),
                            (At::st(0.75, 0.25), 0.5, "texel1"),
                        ]
                    } else {
                        vec![(At::st(0.375, 0.5), 0.5, "a=0.25_0.5")]
                    };
                    for (at, r, tag) in lks {
                        let mut x = Draft::new(
                            "ambient",
                            c,
                            tex.clone(),
                            lookup(Target::T2d, at, w, h, r),
                            format!("fail={fail}/{tag}/ref={r}"),
                        );
                        x.sampler.fail_value = Some(fail);
                        out.push(x);
                    }
                }
            }
        }
    }
    out
}
