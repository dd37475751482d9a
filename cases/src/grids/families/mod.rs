//! Focused families of the default grid, each crossing fewer dimensions than the main product but
//! with the edge values that make a verdict mean something (see cases/README.md, "Grids").

use super::cells::{pattern_texture, PATTERN};
use super::draft::{lookup, texture, Cell, Draft};
use super::specs::SpecDims;
use crate::build::{self, num, nums, At, Stored};
use shadowcheck_model::*;

mod addressing;
mod cube_mip;
mod formats;
mod state;
mod unitstate;
pub use addressing::{cube, cube_wraps, layer, mip, mixfilter, wrap, CUBE_WRAPS};
pub use cube_mip::cube_mip;
pub use formats::{formats, multi_colour_formats};
pub use state::{ambient, dtm, incomplete, proj, stencil};
pub use unitstate::{sampler_object, seamless, swizzle};

/// A fixed-point depth format of the spec (D24, else D16, else unsized).
pub fn fixed_fmt(d: &SpecDims) -> Format {
    [Format::D24, Format::D16, Format::DepthUnsized]
        .into_iter()
        .find(|f| d.formats.contains(f))
        .unwrap_or(d.formats[0])
}

/// The formats whose clamping rules differ: one fixed-point, and D32F where the spec has it.
pub(super) fn clamp_formats(d: &SpecDims) -> Vec<Format> {
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
pub(super) fn one_texel(c: &Cell, v: Stored) -> Texture {
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
