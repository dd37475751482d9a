//! The families that test what the texture state makes of a texel: DEPTH_TEXTURE_MODE,
//! DEPTH_STENCIL_TEXTURE_MODE, completeness, projective lookups and the fail / ambient value.

use super::super::cells::{mip_texture, pattern_texture, LEVELS};
use super::super::draft::{lookup, Cell, Draft};
use super::super::specs::SpecDims;
use super::{cell, fixed_fmt, func_pair, main_func};
use crate::build::{self, nums, At};
use shadowcheck_model::*;

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
        out.extend(proj_filtered(d, target));
    }
    out
}

/// Projective lookups that filter: LINEAR on the PCF pattern between texels (2 of 4 pass at
/// R = 0.5), and each mipmapped filter of the spec on the mip chain (levels 0.2, 0.8, 0.4) at
/// λ = 0.25 and 1.25, R = 0.5 and 0.3. The divide by q happens before the footprint and λ are
/// computed (GL 4.6 §8.14.1 and (8.10) use the divided coordinates; λ here is the explicit level
/// of detail, which the divide does not change).
fn proj_filtered(d: &SpecDims, target: Target) -> Vec<Draft> {
    let mut out = Vec::new();
    let fmt = fixed_fmt(d);
    let func = main_func(d);
    let divide = |lk: &mut Lookup, q: f64| {
        for i in 0..3 {
            lk.coord[i] *= q;
        }
        lk.dref *= q;
        lk.coord[3] = q;
        lk.projective = true;
    };
    let c = cell(d, target, fmt, Filter::Linear, func);
    let (tex, w, h, _) = pattern_texture(&c);
    let at = if target.dims() == 1 {
        At::st(0.375, 0.0)
    } else {
        At::st(0.5, 0.5)
    };
    for q in [2.0, 0.5] {
        for r in [0.3, 0.5, 0.7] {
            let mut lk = lookup(target, at, w, h, r);
            divide(&mut lk, q);
            out.push(Draft::new(
                "proj",
                c,
                tex.clone(),
                lk,
                format!("q={q}/between/ref={r}"),
            ));
        }
    }
    if target.is_rect() {
        return out;
    }
    for &filter in d.filters.iter().filter(|f| f.is_mipmap()) {
        let c = cell(d, target, fmt, filter, func);
        let (tex, at) = mip_texture(&c);
        let (w, h) = (tex.levels[0].width, tex.levels[0].height);
        // Away from the λ = 0.5 rounding tie of the *_MIPMAP_NEAREST filters, so that a path with
        // implicit derivatives (GLSL 1.20, ARB fp) has one nearest level.
        for lod in [0.25, 1.25] {
            for r in [0.3, 0.5] {
                let mut lk = lookup(target, at, w, h, r);
                lk.lod = lod;
                divide(&mut lk, 2.0);
                out.push(Draft::new(
                    "proj",
                    c,
                    tex.clone(),
                    lk,
                    format!("q=2/lod={lod}/ref={r}/levels={}", nums(&LEVELS)),
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
