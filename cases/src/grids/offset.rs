//! The `offset` family: texel offsets of the GLSL `*Offset` lookup functions (GL 4.6 §8.14.2
//! (8.10), §8.14.3; GLSL 4.60 §8.9.2 `textureOffset`), for the specs whose shading language has them
//! (GL 3.0+ core / GLSL 1.30, GLES 3.x): 2D in depth (wraps, LINEAR, mip levels, projective), then
//! 1D, rectangle and array textures.
//!
//! Every texture is "one-hot": the texel the offset lookup should read holds 0.75, every other
//! texel 0.25, and Dref is 0.5, so LEQUAL gives 1 exactly when the right texel is read (and NONE
//! returns 0.75). The hot texel is placed by the rule the cases test (u = w·s + δu in the texels of
//! the sampled level, then wrap); the expectation still comes from the oracle.

use super::draft::{Cell, Draft};
use super::families::{fixed_fmt, main_func};
use super::specs::SpecDims;
use crate::build;
use shadowcheck_model::*;

const HOT: f64 = 0.75;
const COLD: f64 = 0.25;
/// Width and height of the base level.
const SIZE: u32 = 4;

/// Offsets at level 0: small ones, and the extremes every implementation supports (-8, 7).
const OFFSETS: [[i32; 2]; 6] = [[1, 0], [0, 1], [-1, -1], [2, -1], [-8, 7], [7, -8]];

/// The texel index i + d on a level `n` texels wide under `wrap` (Table 8.20 for the modes used).
fn wrapped(i: i64, d: i32, n: u32, wrap: Wrap) -> i64 {
    let n = n as i64;
    let x = i + d as i64;
    match wrap {
        Wrap::Repeat => x.rem_euclid(n),
        _ => x.clamp(0, n - 1),
    }
}

/// A `w`×`h` level of `format` with the hot texel at (hx, hy).
fn one_hot(format: Format, w: u32, h: u32, hot: Option<(i64, i64)>) -> Level {
    let vals: Vec<f64> = (0..(w * h) as i64)
        .map(|k| if hot == Some((k % w as i64, k / w as i64)) { HOT } else { COLD })
        .collect();
    build::level(format, w, h, 1, &vals)
}

fn lookup_at(s: f64, t: f64, dref: f64, offset: [i32; 2]) -> Lookup {
    Lookup {
        coord: [s, t, 0.0, 1.0],
        layer: 0.0,
        dref,
        projective: false,
        lod: 0.0,
        bias: 0.0,
        offset: [offset[0], offset[1], 0],
    }
}

fn texture(cell: &Cell, levels: Vec<Level>) -> Texture {
    Texture {
        target: Target::T2d,
        format: cell.format,
        base_level: 0,
        levels,
    }
}

/// The offset family of spec `d` (empty for specs without offset lookups).
pub fn offset(d: &SpecDims) -> Vec<Draft> {
    if !matches!(d.spec, Spec::Gl46 | Spec::Gles32) {
        return Vec::new();
    }
    let mut out = Vec::new();
    let cell = |filter: Filter, mode: CompareMode| Cell {
        spec: d.spec,
        target: Target::T2d,
        format: fixed_fmt(d),
        filter,
        mode,
        func: main_func(d),
        dtm: None,
    };
    // Level 0, NEAREST: from texel (1, 2), every offset, clamped and repeated; LEQUAL and NONE.
    let (i, j) = (1i64, 2i64);
    for wrap in [Wrap::ClampToEdge, Wrap::Repeat] {
        for mode in [CompareMode::Compare, CompareMode::None] {
            let c = cell(Filter::Nearest, mode);
            for o in OFFSETS {
                let hot = (wrapped(i, o[0], SIZE, wrap), wrapped(j, o[1], SIZE, wrap));
                let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, Some(hot))]);
                let (s, t) = ((i as f64 + 0.5) / SIZE as f64, (j as f64 + 0.5) / SIZE as f64);
                let mut x = Draft::new(
                    "offset",
                    c,
                    tex,
                    lookup_at(s, t, 0.5, o),
                    format!("wrap={wrap}/texel={i},{j}/offset={},{}/ref=0.5", o[0], o[1]),
                );
                x.sampler.wrap_s = wrap;
                x.sampler.wrap_t = wrap;
                out.push(x);
            }
        }
    }
    // LINEAR (PCF) a quarter texel right of the centre of texel (1, 2): the hot texel (the offset
    // one) weighs 3/4; with the footprint of the offset, 1/4 of the next texel.
    for wrap in [Wrap::ClampToEdge, Wrap::Repeat] {
        let c = cell(Filter::Linear, CompareMode::Compare);
        for o in [[1, 0], [-1, -1], [7, -8]] {
            let hot = (wrapped(i, o[0], SIZE, wrap), wrapped(j, o[1], SIZE, wrap));
            let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, Some(hot))]);
            let (s, t) = ((i as f64 + 0.75) / SIZE as f64, (j as f64 + 0.5) / SIZE as f64);
            let mut x = Draft::new(
                "offset",
                c,
                tex,
                lookup_at(s, t, 0.5, o),
                format!("wrap={wrap}/texel={i}.25,{j}/offset={},{}/ref=0.5", o[0], o[1]),
            );
            x.sampler.wrap_s = wrap;
            x.sampler.wrap_t = wrap;
            out.push(x);
        }
    }
    // Level 1 (2x2) of a 4x4 chain, at s = t = 0.1 (u = v = 0.2): offset +1 reads texel 1 of level
    // 1; read in base-level texels it would be half a texel and stay on texel 0. Explicit LOD 1
    // (textureLodOffset) and, where the spec has the shader bias, LOD 0 + bias 1 (textureOffset).
    for &filter in d.filters.iter().filter(|f| matches!(f, Filter::NearestMipmapNearest | Filter::LinearMipmapNearest)) {
        let c = cell(filter, CompareMode::Compare);
        for o in [[1, 0], [0, 1], [1, 1]] {
            let hot = (o[0] as i64, o[1] as i64);
            let tex = texture(
                &c,
                vec![
                    one_hot(c.format, SIZE, SIZE, None),
                    one_hot(c.format, SIZE / 2, SIZE / 2, Some(hot)),
                    one_hot(c.format, 1, 1, None),
                ],
            );
            let mut forms: Vec<(&str, f64, f64)> = vec![("lod=1", 1.0, 0.0)];
            if d.shader_bias {
                forms.push(("lod=0/bias=1", 0.0, 1.0));
            }
            for (name, lod, bias) in forms {
                let mut lk = lookup_at(0.1, 0.1, 0.5, o);
                lk.lod = lod;
                lk.bias = bias;
                out.push(Draft::new(
                    "offset",
                    c,
                    tex.clone(),
                    lk,
                    format!("level=1/st=0.1,0.1/offset={},{}/{name}/ref=0.5", o[0], o[1]),
                ));
            }
        }
    }
    // Projective (textureProjOffset): P = (s, t, Dref, 1)·q with q = 2.
    let c = cell(Filter::Nearest, CompareMode::Compare);
    for o in [[1, 0], [-1, 1]] {
        let hot = (wrapped(i, o[0], SIZE, Wrap::ClampToEdge), wrapped(j, o[1], SIZE, Wrap::ClampToEdge));
        let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, Some(hot))]);
        let (s, t) = ((i as f64 + 0.5) / SIZE as f64, (j as f64 + 0.5) / SIZE as f64);
        let q = 2.0;
        let mut lk = lookup_at(s * q, t * q, 0.5 * q, o);
        lk.coord[3] = q;
        lk.projective = true;
        out.push(Draft::new(
            "offset",
            c,
            tex,
            lk,
            format!("proj/q=2/texel={i},{j}/offset={},{}/ref=0.5", o[0], o[1]),
        ));
    }
    out.extend(other_targets(d));
    out
}

/// The other targets with offset lookups (GLSL 4.60 §8.9.2; not cube maps): 1D, rectangle and the
/// arrays (GL), the 2D array (ES). NEAREST, LEQUAL, from texel (1, 2) (1D: texel 1) of the sampled
/// image (arrays: layer 1, whose other layer is all cold), CLAMP_TO_EDGE and, except rectangles
/// (which have no REPEAT), REPEAT.
fn other_targets(d: &SpecDims) -> Vec<Draft> {
    let targets: &[Target] = match d.spec {
        Spec::Gl46 => &[Target::T1d, Target::Rect, Target::T1dArray, Target::T2dArray],
        _ => &[Target::T2dArray],
    };
    let mut out = Vec::new();
    for &target in targets.iter().filter(|t| d.targets.contains(t)) {
        let c = Cell {
            spec: d.spec,
            target,
            format: fixed_fmt(d),
            filter: Filter::Nearest,
            mode: CompareMode::Compare,
            func: main_func(d),
            dtm: None,
        };
        let one_d = target.dims() == 1;
        let (layers, layer) = if target.is_array() { (2u32, 1u32) } else { (1, 0) };
        let (w, h) = if one_d { (SIZE, 1) } else { (SIZE, SIZE) };
        let (i, j) = if one_d { (1i64, 0i64) } else { (1, 2) };
        let offsets: &[[i32; 2]] = if one_d { &[[1, 0], [-1, 0], [2, 0], [-8, 0]] } else { &[[1, 0], [-1, -1], [2, -1], [7, -8]] };
        let wraps: &[Wrap] = if target == Target::Rect { &[Wrap::ClampToEdge] } else { &[Wrap::ClampToEdge, Wrap::Repeat] };
        for &wrap in wraps {
            for &o in offsets {
                let hot = (wrapped(i, o[0], w, wrap), if one_d { 0 } else { wrapped(j, o[1], h, wrap) });
                let hot_k = (hot.0 + hot.1 * w as i64) as usize + (layer * w * h) as usize;
                let vals: Vec<f64> = (0..(w * h * layers) as usize).map(|k| if k == hot_k { HOT } else { COLD }).collect();
                let tex = Texture {
                    target,
                    format: c.format,
                    base_level: 0,
                    levels: vec![build::level(c.format, w, h, layers, &vals)],
                };
                let at = build::At {
                    s: (i as f64 + 0.5) / w as f64,
                    t: (j as f64 + 0.5) / h as f64,
                    layer: layer as f64,
                    face: 0,
                };
                let (coord, lk_layer) = build::coord(target, at, w, h);
                let lk = Lookup {
                    coord,
                    layer: lk_layer,
                    dref: 0.5,
                    projective: false,
                    lod: 0.0,
                    bias: 0.0,
                    offset: [o[0], o[1], 0],
                };
                let pos = if one_d { format!("{i}") } else { format!("{i},{j}") };
                let off = if one_d { format!("{}", o[0]) } else { format!("{},{}", o[0], o[1]) };
                let mut x = Draft::new("offset", c, tex, lk, format!("wrap={wrap}/texel={pos}/offset={off}/ref=0.5"));
                x.sampler.wrap_s = wrap;
                x.sampler.wrap_t = wrap;
                out.push(x);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_specs_with_offset_lookups_get_the_family_and_every_case_has_an_offset() {
        for d in super::super::specs::all() {
            let v = offset(&d);
            assert_eq!(!v.is_empty(), matches!(d.spec, Spec::Gl46 | Spec::Gles32), "{:?}", d.spec);
            for x in v {
                assert_ne!(x.lookup.offset, [0; 3], "{}", x.id());
                let case = x.into_case();
                shadowcheck_model::validate::validate(&case).unwrap();
                assert!(case.api.iter().all(|a| matches!(a, ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es300)));
            }
        }
    }

    #[test]
    fn wrapped_follows_table_8_20_for_clamp_and_repeat() {
        assert_eq!(wrapped(1, -8, 4, Wrap::Repeat), 1);
        assert_eq!(wrapped(2, 7, 4, Wrap::Repeat), 1);
        assert_eq!(wrapped(1, -8, 4, Wrap::ClampToEdge), 0);
        assert_eq!(wrapped(2, 7, 4, Wrap::ClampToEdge), 3);
    }
}
