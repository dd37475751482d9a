//! The families of the unit state beyond the texture's own sampling parameters: the
//! texture swizzle, GL's TEXTURE_CUBE_MAP_SEAMLESS enable (and ES's always-seamless rule) and a
//! bound sampler object whose state differs from the texture's.

use super::super::draft::{lookup, texture, Cell, Draft};
use super::super::specs::SpecDims;
use super::{cell, fixed_fmt, func_pair, main_func};
use crate::build::{self, num, At};
use shadowcheck_model::*;

/// Specs with the texture swizzle and sampler objects (GL 3.3+, ES 3.0+).
fn has_gl33_state(d: &SpecDims) -> bool {
    matches!(d.spec, Spec::Gl46 | Spec::Gles32)
}

/// TEXTURE_SWIZZLE_RGBA values: each picks r, 0 or 1 into different channels.
const SWIZZLES: [[Swizzle; 4]; 5] = {
    use Swizzle::*;
    [
        [Zero, Green, Blue, Alpha],
        [One, Red, Zero, Red],
        [Green, Red, Alpha, Blue],
        [Alpha, Alpha, Red, Zero],
        [Red, Red, Red, One],
    ]
};

fn swizzle_key(sw: [Swizzle; 4]) -> String {
    sw.iter().map(|c| c.key()).collect::<Vec<_>>().join("_")
}

/// A 2x1 texture holding 0.2 and 0.8 (one texel fails and one passes at R = 0.5).
fn pair_texture(c: &Cell) -> Texture {
    texture(c, vec![build::level(c.format, 2, 1, 1, &[0.2, 0.8])])
}

/// The texture swizzle on the shadow result (Cb = (Rt, 0, 0, 1), then the swizzle, then Cs[0],
/// GL 4.6 §11.1.3.5) and on non-shadow depth reads (compare NONE: all four channels of the
/// swizzled (Dt, 0, 0, 1); in a compatibility context, of the DEPTH_TEXTURE_MODE expansion).
/// NEAREST on each texel (r = 0 or 1, Dt 0.2 or 0.8) and LINEAR between them (r = 0.5), with
/// LEQUAL and GEQUAL, so that a swizzle applied to Dt before the comparison changes r.
pub fn swizzle(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !has_gl33_state(d) {
        return out;
    }
    let fmt = fixed_fmt(d);
    let mut push = |c: Cell, sw: [Swizzle; 4], at: f64, tag: &str| {
        let mut x = Draft::new(
            "swizzle",
            c,
            pair_texture(&c),
            lookup(Target::T2d, At::st(at, 0.5), 2, 1, 0.5),
            format!("swizzle={}/{tag}/ref=0.5", swizzle_key(sw)),
        );
        x.sampler.swizzle = Some(sw);
        out.push(x);
    };
    for sw in SWIZZLES {
        for func in func_pair(d) {
            for filter in [Filter::Nearest, Filter::Linear] {
                let c = cell(d, Target::T2d, fmt, filter, func);
                if filter == Filter::Nearest {
                    push(c, sw, 0.25, "texel0");
                    push(c, sw, 0.75, "texel1");
                } else {
                    push(c, sw, 0.5, "half");
                }
            }
        }
        // Compare NONE: r = Dt (NEAREST: ES 3.2 §8.17 makes a LINEAR one incomplete).
        let c = Cell {
            mode: CompareMode::None,
            ..cell(d, Target::T2d, fmt, Filter::Nearest, main_func(d))
        };
        push(c, sw, 0.75, "texel1");
        for &m in d.dtms {
            // GLSL 1.30 in a compatibility context: the DEPTH_TEXTURE_MODE expansion, then the
            // swizzle.
            push(
                Cell { dtm: Some(m), ..c },
                sw,
                0.75,
                &format!("dtm={m}/texel1"),
            );
        }
    }
    out
}

/// Cube values: +X holds 0.2 in column 0 and 0.6 in column 1 (level 0), the other faces one value
/// each (-X 0.3, +Y 0.85, -Y 0.75, +Z 0.9, -Z 0.65); level 1 is one texel a face with the same
/// face values (+X 0.2). At R = 0.5 and 0.7 (LEQUAL) seamless filtering (the +Z / -Y neighbours)
/// and per-face filtering with CLAMP_TO_EDGE or REPEAT give three different r near the edges.
fn seamless_texture(c: &Cell) -> Texture {
    seamless_texture_with(c, [0.2, 0.6])
}

/// [`seamless_texture`] with +X's level-0 columns holding `x`.
fn seamless_texture_with(c: &Cell, x: [f64; 2]) -> Texture {
    const FACES: [f64; 6] = [0.2, 0.3, 0.85, 0.75, 0.9, 0.65];
    let l0: Vec<f64> = (0..6)
        .flat_map(|f| (0..4).map(move |i| if f == 0 { x[i % 2] } else { FACES[f] }))
        .collect();
    texture(
        c,
        vec![
            build::level(c.format, 2, 2, 6, &l0),
            build::level(c.format, 1, 1, 6, &FACES),
        ],
    )
}

/// The id part of a seamless case: GL's enable off or on, ES's rule, Vulkan's edge handling.
fn seamless_tag(d: &SpecDims, on: Option<bool>) -> &'static str {
    match on {
        Some(true) => "on",
        Some(false) => "off",
        None if matches!(d.spec, Spec::Vulkan | Spec::WebGpu) => "always",
        None => "es",
    }
}

/// Seamless cube filtering (GL 4.6 §8.13.1): LINEAR at level 0, LINEAR_MIPMAP_LINEAR between
/// levels 0 and 1 and LINEAR_MIPMAP_NEAREST at level 1, on +X near its +Z edge, its -Y edge, the
/// corner between them and inside; GL with the enable off and on, with CLAMP_TO_EDGE and REPEAT
/// (ignored while seamless); ES with its rule (always seamless, no enable); Vulkan with its Cube
/// Map Edge Handling (always across faces); WebGPU's cube views ("Sampling is done seamlessly
/// across the faces of the cubemap").
pub fn seamless(d: &SpecDims) -> Vec<Draft> {
    // Vulkan requires one of its 24-bit depth formats or D32_SFLOAT, not both ("Required Format
    // Support"): SwiftShader has no D24, so the D32F copy is what runs there.
    let mut formats = vec![fixed_fmt(d)];
    if d.spec == Spec::Vulkan && d.formats.contains(&Format::D32f) {
        formats.push(Format::D32f);
    }
    formats
        .into_iter()
        .flat_map(|f| seamless_in(d, f))
        .collect()
}

/// [`seamless`] in format `fmt`.
fn seamless_in(d: &SpecDims, fmt: Format) -> Vec<Draft> {
    let mut out = Vec::new();
    if !d.targets.contains(&Target::Cube)
        || !(has_gl33_state(d) || matches!(d.spec, Spec::Vulkan | Spec::WebGpu))
    {
        return out;
    }
    let settings: &[Option<bool>] = if d.spec == Spec::Gl46 {
        &[Some(false), Some(true)]
    } else {
        &[None]
    };
    let func = main_func(d);
    let points = [
        ("edge_s", 0.05, 0.5),
        ("edge_t", 0.75, 0.95),
        ("corner", 0.05, 0.95),
        ("inside", 0.75, 0.5),
    ];
    for &on in settings {
        for wrap in [Wrap::ClampToEdge, Wrap::Repeat] {
            for (filter, lod) in [
                (Filter::Linear, 0.0),
                (Filter::LinearMipmapLinear, 0.5),
                (Filter::LinearMipmapNearest, 1.0),
            ] {
                let c = cell(d, Target::Cube, fmt, filter, func);
                let tex = seamless_texture(&c);
                for (name, s, t) in points {
                    for r in [0.5, 0.7] {
                        let mut lk = lookup(
                            Target::Cube,
                            At {
                                s,
                                t,
                                layer: 0.0,
                                face: 0,
                            },
                            2,
                            2,
                            r,
                        );
                        lk.lod = lod;
                        let mode = seamless_tag(d, on);
                        let mut x = Draft::new(
                            "seamless",
                            c,
                            tex.clone(),
                            lk,
                            format!(
                                "seamless={mode}/wrap={wrap}/lod={lod}/{name}/ref={}",
                                num(r)
                            ),
                        );
                        x.sampler.seamless = on;
                        (x.sampler.wrap_s, x.sampler.wrap_t, x.sampler.wrap_r) = (wrap, wrap, wrap);
                        out.push(x);
                    }
                }
            }
            // +X column 0 passes, column 1 fails (0.9 | 0.2): at its +Z edge the seamless
            // footprint passes everywhere (r = 1 exactly, whatever a profile allows for mixed
            // footprints), while per-face REPEAT mixes in column 1.
            let c = cell(d, Target::Cube, fmt, Filter::Linear, func);
            let at = At {
                s: 0.05,
                t: 0.5,
                layer: 0.0,
                face: 0,
            };
            let mode = seamless_tag(d, on);
            let mut x = Draft::new(
                "seamless",
                c,
                seamless_texture_with(&c, [0.9, 0.2]),
                lookup(Target::Cube, at, 2, 2, 0.5),
                format!("seamless={mode}/wrap={wrap}/x0=0.9/edge_s/ref=0.5"),
            );
            x.sampler.seamless = on;
            (x.sampler.wrap_s, x.sampler.wrap_t, x.sampler.wrap_r) = (wrap, wrap, wrap);
            out.push(x);
        }
    }
    out
}

/// A bound sampler object whose state differs from the texture's so that using the texture's
/// state changes r (GL 4.6 §8.17.1, ES 3.2 §8.17.1). Each variant changes one parameter of the
/// sampler object (compare mode, function, filter, wrap, LOD clamp, LOD bias, border); the
/// compare-mode variants on ES also exercise §8.17's depth-texture completeness rule, which
/// reads the sampler object's compare mode. One variant keeps a texture swizzle, which stays
/// texture state.
pub fn sampler_object(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !has_gl33_state(d) {
        return out;
    }
    let fmt = fixed_fmt(d);
    let [leq, geq] = func_pair(d);
    type Variant = (&'static str, Filter, CompareMode, fn(&mut SamplerObject));
    let variants: [Variant; 10] = [
        ("so_compare", Filter::Nearest, CompareMode::None, |o| {
            o.compare_mode = CompareMode::Compare
        }),
        (
            "so_compare_linear",
            Filter::Linear,
            CompareMode::None,
            |o| o.compare_mode = CompareMode::Compare,
        ),
        ("so_none", Filter::Nearest, CompareMode::Compare, |o| {
            o.compare_mode = CompareMode::None
        }),
        (
            "so_none_linear",
            Filter::Linear,
            CompareMode::Compare,
            |o| o.compare_mode = CompareMode::None,
        ),
        // The function and the swizzle variants take `geq` below.
        ("so_func", Filter::Nearest, CompareMode::Compare, |_| {}),
        ("so_linear", Filter::Nearest, CompareMode::Compare, |o| {
            (o.min_filter, o.mag_filter) = (Filter::Linear, Filter::Linear)
        }),
        ("so_nearest", Filter::Linear, CompareMode::Compare, |o| {
            (o.min_filter, o.mag_filter) = (Filter::Nearest, Filter::Nearest)
        }),
        ("so_repeat", Filter::Nearest, CompareMode::Compare, |o| {
            (o.wrap_s, o.wrap_t) = (Wrap::Repeat, Wrap::Repeat)
        }),
        ("so_border", Filter::Nearest, CompareMode::Compare, |o| {
            (o.wrap_s, o.wrap_t) = (Wrap::ClampToBorder, Wrap::ClampToBorder);
            o.border = [1.0, 0.0, 0.0, 0.0];
        }),
        ("so_swizzle", Filter::Nearest, CompareMode::Compare, |_| {}),
    ];
    for (name, filter, mode, apply) in variants {
        let c = Cell {
            mode,
            ..cell(d, Target::T2d, fmt, filter, leq)
        };
        // 2x1 texture 0.2 | 0.8. NEAREST at texel 1 (s = 0.75) or LINEAR at s = 0.5; the
        // wrap variants look up at s = -0.25 (CLAMP_TO_EDGE: texel 0, REPEAT: texel 1,
        // CLAMP_TO_BORDER: the border 1.0).
        let s = match (name, filter) {
            ("so_repeat" | "so_border", _) => -0.25,
            (_, Filter::Linear) | ("so_linear", _) => 0.5,
            _ => 0.75,
        };
        let lk = lookup(Target::T2d, At::st(s, 0.5), 2, 1, 0.5);
        let mut x = Draft::new(
            "sampler_object",
            c,
            pair_texture(&c),
            lk,
            format!("{name}/s={}/ref=0.5", num(s)),
        );
        let mut o = SamplerObject::from_sampler(&x.sampler);
        apply(&mut o);
        if name == "so_func" || name == "so_swizzle" {
            // LEQUAL passes on 0.8, the sampler object's GEQUAL fails.
            o.compare_func = geq;
        }
        if name == "so_swizzle" {
            x.sampler.swizzle = Some([Swizzle::One, Swizzle::Red, Swizzle::Zero, Swizzle::Red]);
        }
        x.sampler.sampler_object = Some(o);
        out.push(x);
    }
    out.extend(rect_sampler_object(d));
    // LOD state of the sampler object: level 0 holds 0.2, level 1 0.8 (NEAREST_MIPMAP_NEAREST).
    let c = cell(d, Target::T2d, fmt, Filter::NearestMipmapNearest, leq);
    let tex = texture(
        &c,
        vec![
            build::level(c.format, 2, 2, 1, &[0.2; 4]),
            build::level(c.format, 1, 1, 1, &[0.8]),
        ],
    );
    type LodVariant = (&'static str, f64, fn(&mut SamplerObject));
    let lods: [LodVariant; 3] = [
        ("so_min_lod=1", 0.0, |o| o.min_lod = 1.0),
        ("so_max_lod=0", 1.0, |o| o.max_lod = 0.0),
        ("so_lod_bias=1", 0.0, |o| o.lod_bias = 1.0),
    ];
    for (name, lod, apply) in lods {
        let mut lk = lookup(Target::T2d, At::st(0.5, 0.5), 2, 2, 0.5);
        lk.lod = lod;
        let mut x = Draft::new(
            "sampler_object",
            c,
            tex.clone(),
            lk,
            format!("{name}/lod={lod}/ref=0.5"),
        );
        let mut o = SamplerObject::from_sampler(&x.sampler);
        apply(&mut o);
        x.sampler.sampler_object = Some(o);
        out.push(x);
    }
    out
}

/// A sampler object holding state that TexParameter refuses for the bound rectangle texture (GL
/// 4.6 §8.10: wrap S/T REPEAT, MIRRORED_REPEAT or MIRROR_CLAMP_TO_EDGE; a mipmap minification
/// filter): no error, the texture is "as if ... incomplete" (§8.2), r = 0. The 2x1 rectangle
/// 0.8 | 0.6 passes everywhere at R = 0.5 (LEQUAL), so any texel a wrap mode reads at u = 2.5 (past
/// the right edge) gives 1: only the incompleteness gives 0. The CLAMP_TO_EDGE and
/// CLAMP_TO_BORDER (border 1.0) variants are the legal controls.
fn rect_sampler_object(d: &SpecDims) -> Vec<Draft> {
    let mut out = Vec::new();
    if !d.targets.contains(&Target::Rect) {
        return out;
    }
    let fmt = fixed_fmt(d);
    let [leq, _] = func_pair(d);
    let c = cell(d, Target::Rect, fmt, Filter::Nearest, leq);
    let tex = texture(&c, vec![build::level(c.format, 2, 1, 1, &[0.8, 0.6])]);
    let mut variants: Vec<(String, Wrap, Filter)> = [
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::MirrorClampToEdge,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ]
    .into_iter()
    .filter(|w| d.wraps.contains(w))
    .map(|w| (format!("so_rect_wrap={w}"), w, Filter::Nearest))
    .collect();
    variants.push((
        "so_rect_min=nmn".to_string(),
        Wrap::ClampToEdge,
        Filter::NearestMipmapNearest,
    ));
    for (name, wrap, min) in variants {
        let mut x = Draft::new(
            "sampler_object",
            c,
            tex.clone(),
            lookup(Target::Rect, At::st(1.25, 0.5), 2, 1, 0.5),
            format!("{name}/u=2.5/ref=0.5"),
        );
        (x.sampler.wrap_s, x.sampler.wrap_t) = (Wrap::ClampToEdge, Wrap::ClampToEdge);
        let mut o = SamplerObject::from_sampler(&x.sampler);
        o.wrap_s = wrap;
        o.min_filter = min;
        o.border = [1.0, 0.0, 0.0, 0.0];
        x.sampler.sampler_object = Some(o);
        out.push(x);
    }
    out
}
