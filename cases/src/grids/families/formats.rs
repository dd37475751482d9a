//! Every format a rule applies to (the audit of cases/README.md, "Rules by format", checked by
//! `cases/tests/format_audit.rs`): the colour formats a compare mode can meet (RG8, RGB8, RGBA8,
//! RGBA4, with R8 for completeness) read with comparison on and off, every channel judged; and, on
//! each depth format the other families leave out of a rule, the reference clamp, the upload clamp
//! of floating-point depth, the border clamp, and completeness for shadow, non-shadow and
//! unsigned-integer (STENCIL_INDEX) reads.

use super::super::cells::{pattern_texture, PATTERN};
use super::super::draft::{lookup, Cell, Draft};
use super::super::specs::SpecDims;
use super::{cell, clamp_formats, func_pair, main_func, one_texel};
use crate::build::{self, num, nums, At};
use shadowcheck_model::*;

/// The colour formats of several components the spec's rules define (GL 4.6, ES 3.2: RG8, RGB8,
/// RGBA8, RGBA4; the pre-3.0 extension specs: RGB8, RGBA8, RGBA4).
pub fn multi_colour_formats(spec: Spec) -> Vec<Format> {
    shadowcheck_oracle::rules::rules_for(spec)
        .formats
        .iter()
        .copied()
        .filter(|f| f.is_multi_colour())
        .collect()
}

/// The family: colour formats, then the rule x depth-format additions.
pub fn formats(d: &SpecDims) -> Vec<Draft> {
    if d.fail_value || matches!(d.spec, Spec::Sgix | Spec::SgixAmbient) {
        // The *_ambient variants: the fail value does not reach a colour texture; SGIX_shadow
        // leaves its operators undefined on one (the main product's R8 case says so).
        return Vec::new();
    }
    let mut out = colour(d);
    if matches!(d.spec, Spec::Gl46 | Spec::Gles32) {
        out.extend(rules_by_format(d));
    }
    out
}

/// Colour textures with the compare state set: NEAREST (texel 1 of the pattern) and LINEAR (α =
/// 0.25, β = 0.5) with comparison on (bypassed) and off, a reference outside [0, 1] (ignored), the
/// swizzle, a border colour whose components differ, and an incomplete texture.
fn colour(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let swizzle = shadowcheck_oracle::rules::rules_for(d.spec)
        .swizzle
        .is_some();
    let border = d.wraps.contains(&Wrap::ClampToBorder);
    for fmt in multi_colour_formats(d.spec) {
        for mode in [CompareMode::Compare, CompareMode::None] {
            for filter in [Filter::Nearest, Filter::Linear] {
                let c = Cell {
                    mode,
                    ..cell(d, Target::T2d, fmt, filter, main_func(d))
                };
                let (tex, w, h, _) = pattern_texture(&c);
                let (at, tag) = if filter == Filter::Nearest {
                    (At::st(0.75, 0.25), "texel1")
                } else {
                    (At::st(0.375, 0.5), "a=0.25_0.5")
                };
                let refs: &[f64] = if mode == CompareMode::Compare {
                    &[0.5, 1.5]
                } else {
                    &[0.5]
                };
                for &r in refs {
                    out.push(Draft::new(
                        "formats",
                        c,
                        tex.clone(),
                        lookup(Target::T2d, at, w, h, r),
                        format!("bypass/{tag}/ref={}/dt={}", num(r), nums(&PATTERN)),
                    ));
                }
            }
        }
        let c = cell(d, Target::T2d, fmt, Filter::Nearest, main_func(d));
        let (tex, w, h, _) = pattern_texture(&c);
        if swizzle {
            let sw = [Swizzle::Alpha, Swizzle::Blue, Swizzle::Green, Swizzle::Red];
            let mut x = Draft::new(
                "formats",
                c,
                tex.clone(),
                lookup(Target::T2d, At::st(0.75, 0.25), w, h, 0.5),
                "bypass/swizzle=abgr/texel1/ref=0.5".into(),
            );
            x.sampler.swizzle = Some(sw);
            out.push(x);
        }
        if border {
            let mut x = Draft::new(
                "formats",
                c,
                tex.clone(),
                lookup(Target::T2d, At::st(-0.25, 0.25), w, h, 0.5),
                "bypass/wrap=border/st=-0.25_0.25/border=0.25_0.5_0.75_1/ref=0.5".into(),
            );
            x.sampler.wrap_s = Wrap::ClampToBorder;
            x.sampler.wrap_t = Wrap::ClampToBorder;
            x.sampler.border = [0.25, 0.5, 0.75, 1.0];
            out.push(x);
        }
    }
    let mut incomplete_fmts = multi_colour_formats(d.spec);
    if d.formats.contains(&Format::R8) {
        incomplete_fmts.push(Format::R8);
    }
    for fmt in incomplete_fmts {
        out.extend(level0_only(d, fmt, None));
    }
    out
}

/// A one-level texture with a mipmap filter (incomplete, GL 4.6 §8.17), texel 1, compare on and
/// off; `dsm` set: read as STENCIL_INDEX (compare off: a stencil read through a usampler).
fn level0_only(d: &SpecDims, fmt: Format, dsm: Option<DepthStencilMode>) -> Vec<Draft> {
    let modes: &[CompareMode] = if dsm == Some(DepthStencilMode::StencilIndex) {
        &[CompareMode::None]
    } else {
        &[CompareMode::Compare, CompareMode::None]
    };
    let mut out = Vec::new();
    for &mode in modes {
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
        let tag = dsm.map_or(String::new(), |m| format!("dsm={m}/"));
        let mut x = Draft::new(
            "formats",
            c,
            tex,
            lookup(Target::T2d, At::st(0.75, 0.25), w, h, 0.3),
            format!("incomplete/{tag}level0-only/texel1/ref=0.3"),
        );
        x.sampler.depth_stencil_mode = dsm;
        out.push(x);
    }
    out
}

/// The depth formats each rule misses in the other families: the reference clamp (R outside [0, 1]
/// against Dt 0 and 1, the pair of functions), the upload clamp of a stored float outside [0, 1],
/// the border clamp (border depth 1.5 and −0.5), completeness for shadow and non-shadow reads,
/// and for DEPTH_STENCIL formats completeness of a STENCIL_INDEX read.
fn rules_by_format(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    let covered = clamp_formats(d);
    let depth: Vec<Format> = d.formats.iter().copied().filter(|f| f.is_depth()).collect();
    for &fmt in &depth {
        if !covered.contains(&fmt) {
            for func in func_pair(d) {
                let c = cell(d, Target::T2d, fmt, Filter::Nearest, func);
                for dt in [0.0, 1.0] {
                    let tex = one_texel(&c, build::store(fmt, dt));
                    for r in [-0.5, 1.5] {
                        out.push(Draft::new(
                            "formats",
                            c,
                            tex.clone(),
                            lookup(Target::T2d, At::st(0.5, 0.5), 1, 1, r),
                            format!("ref-clamp/dt={}/ref={}", num(dt), num(r)),
                        ));
                    }
                }
            }
        }
        if fmt.unorm_bits().is_none() && fmt != Format::D32f {
            // Stored outside [0, 1]: "the depth value is clamped to [0, 1]" at upload (§8.5).
            let c = cell(d, Target::T2d, fmt, Filter::Nearest, main_func(d));
            for dt in [-0.5, 1.5] {
                let tex = one_texel(&c, build::Stored::Float(dt as f32));
                for r in [-0.25, 0.0, 1.0, 1.25] {
                    out.push(Draft::new(
                        "formats",
                        c,
                        tex.clone(),
                        lookup(Target::T2d, At::st(0.5, 0.5), 1, 1, r),
                        format!("float-range/dt={}/ref={}", num(dt), num(r)),
                    ));
                }
            }
        }
        if d.wraps.contains(&Wrap::ClampToBorder) {
            let c = cell(d, Target::T2d, fmt, Filter::Nearest, main_func(d));
            let (tex, w, h, _) = pattern_texture(&c);
            for (b, r) in [(1.5f32, 1.25), (-0.5, -0.25)] {
                let mut x = Draft::new(
                    "formats",
                    c,
                    tex.clone(),
                    lookup(Target::T2d, At::st(-0.25, 0.25), w, h, r),
                    format!(
                        "border-clamp/st=-0.25_0.25/border={}/ref={}",
                        num(b as f64),
                        num(r)
                    ),
                );
                x.sampler.wrap_s = Wrap::ClampToBorder;
                x.sampler.wrap_t = Wrap::ClampToBorder;
                x.sampler.border = [b, 0.0, 0.0, 0.0];
                out.push(x);
            }
        }
        out.extend(level0_only(d, fmt, None));
        if fmt.has_stencil() && d.stencil_mode {
            out.extend(level0_only(d, fmt, Some(DepthStencilMode::StencilIndex)));
        }
    }
    out
}
