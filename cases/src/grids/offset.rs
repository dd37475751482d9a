//! The `offset` family: texel offsets of the GLSL `*Offset` lookup functions (GL 4.6 §8.14.2
//! (8.10), §8.14.3; GLSL 4.60 §8.9.2 `textureOffset`), for the specs whose shading language has them
//! (GL 3.0+ core / GLSL 1.30, GLES 3.x): 2D in depth (wraps, LINEAR, mip levels, projective), then
//! 1D, rectangle and array textures.
//!
//! Every texture is "one-hot": the texel the offset lookup should read holds 0.75, every other
//! texel 0.25, and Dref is 0.5, so LEQUAL gives 1 exactly when the right texel is read (and NONE
//! returns 0.75). The hot texel is placed by the rule the cases test (u = w·s + δu in the texels of
//! the sampled level, then wrap); the expectation still comes from the oracle.

use super::draft::{lookup, texture, Cell, Draft};
use super::families::{cell, fixed_fmt, main_func};
use super::specs::SpecDims;
use crate::build::{self, At};
use shadowcheck_model::*;

const HOT: f64 = 0.75;
const COLD: f64 = 0.25;
/// Width and height of the base level.
const SIZE: u32 = 4;

/// Offsets at level 0: small ones, and the extremes every implementation supports (-8, 7).
const OFFSETS: [[i32; 2]; 6] = [[1, 0], [0, 1], [-1, -1], [2, -1], [-8, 7], [7, -8]];

/// The texel index i + d on a level `n` texels wide under `wrap` (Table 8.20 for the modes used;
/// CLAMP_TO_BORDER reads the border outside the image, see [`hot_and_border`]).
fn wrapped(i: i64, d: i32, n: u32, wrap: Wrap) -> i64 {
    let n = n as i64;
    let x = i + d as i64;
    match wrap {
        Wrap::Repeat => x.rem_euclid(n),
        // MIRRORED_REPEAT: (size − 1) − mirror((i mod 2·size) − size), mirror(f) = f or −(1 + f).
        Wrap::MirroredRepeat => {
            let m = x.rem_euclid(2 * n);
            if m < n {
                m
            } else {
                2 * n - 1 - m
            }
        }
        _ => x.clamp(0, n - 1),
    }
}

/// Where the offset lookup from texel (i, j) reads on a `SIZE`×`SIZE` level under `wrap`: the hot
/// texel, or (CLAMP_TO_BORDER off the image) no hot texel and a hot border.
fn hot_and_border(i: i64, j: i64, o: [i32; 2], wrap: Wrap) -> (Option<(i64, i64, u32)>, f32) {
    let inside = |x: i64| (0..SIZE as i64).contains(&x);
    let (x, y) = (i + o[0] as i64, j + o[1] as i64);
    if wrap == Wrap::ClampToBorder && !(inside(x) && inside(y)) {
        return (None, HOT as f32);
    }
    let hot = (
        wrapped(i, o[0], SIZE, wrap),
        wrapped(j, o[1], SIZE, wrap),
        0,
    );
    (Some(hot), COLD as f32)
}

/// A `w`×`h`×`layers` level of `format` whose only hot texel is (x, y) of layer `l`.
fn one_hot(format: Format, w: u32, h: u32, layers: u32, hot: Option<(i64, i64, u32)>) -> Level {
    let vals: Vec<f64> = (0..(w * h * layers) as i64)
        .map(|k| {
            let (x, y, l) = (
                k % w as i64,
                k / w as i64 % h as i64,
                (k / (w * h) as i64) as u32,
            );
            if hot == Some((x, y, l)) {
                HOT
            } else {
                COLD
            }
        })
        .collect();
    build::level(format, w, h, layers, &vals)
}

/// The lookup at `at` with Dref 0.5 and texel offset `o` (δw = 0).
fn offset_lookup(target: Target, at: At, w: u32, h: u32, o: [i32; 2]) -> Lookup {
    let mut l = lookup(target, at, w, h, 0.5);
    l.offset = [o[0], o[1], 0];
    l
}

/// An `offset` draft with `wrap` on s and t.
fn wrap_draft(c: Cell, tex: Texture, lk: Lookup, wrap: Wrap, tags: String) -> Draft {
    let mut x = Draft::new("offset", c, tex, lk, tags);
    x.sampler.wrap_s = wrap;
    x.sampler.wrap_t = wrap;
    x
}

/// The offset family of spec `d` (empty for specs without offset lookups).
pub fn offset(d: &SpecDims) -> Vec<Draft> {
    if !matches!(
        d.spec,
        Spec::Gl46 | Spec::Gles32 | Spec::Vulkan | Spec::WebGpu
    ) {
        return Vec::new();
    }
    let mut out = Vec::new();
    let cell2d = |filter: Filter, mode: CompareMode| Cell {
        mode,
        ..cell(d, Target::T2d, fixed_fmt(d), filter, main_func(d))
    };
    let centre = |i: i64, j: i64, dx: f64| {
        At::st(
            (i as f64 + 0.5 + dx) / SIZE as f64,
            (j as f64 + 0.5) / SIZE as f64,
        )
    };
    // Level 0, NEAREST: from texel (1, 2), every offset under every wrap mode of the spec that
    // moves it (clamp to edge, repeat, mirrored repeat, clamp to border: the offset is added before
    // the wrap, §8.14.2 (8.10), so a border lookup off the image reads the hot border); LEQUAL and NONE.
    let (i, j) = (1i64, 2i64);
    let wraps = [
        Wrap::ClampToEdge,
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToBorder,
    ];
    for wrap in wraps.into_iter().filter(|w| d.wraps.contains(w)) {
        for mode in [CompareMode::Compare, CompareMode::None] {
            let c = cell2d(Filter::Nearest, mode);
            for o in OFFSETS {
                let (hot, border) = hot_and_border(i, j, o, wrap);
                let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, 1, hot)]);
                let lk = offset_lookup(Target::T2d, centre(i, j, 0.0), SIZE, SIZE, o);
                let mut x = wrap_draft(
                    c,
                    tex,
                    lk,
                    wrap,
                    format!("wrap={wrap}/texel={i}_{j}/offset={}_{}/ref=0.5", o[0], o[1]),
                );
                if wrap == Wrap::ClampToBorder {
                    x.sampler.border = [border, 0.0, 0.0, 0.0];
                }
                out.push(x);
            }
        }
    }
    // LINEAR (PCF) a quarter texel right of the centre of texel (1, 2): the hot texel (the offset
    // one) weighs 3/4; with the footprint of the offset, 1/4 of the next texel.
    for wrap in wraps.into_iter().filter(|w| d.wraps.contains(w)) {
        let c = cell2d(Filter::Linear, CompareMode::Compare);
        for o in [[1, 0], [-1, -1], [7, -8]] {
            let (hot, border) = hot_and_border(i, j, o, wrap);
            let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, 1, hot)]);
            let lk = offset_lookup(Target::T2d, centre(i, j, 0.25), SIZE, SIZE, o);
            let mut x = wrap_draft(
                c,
                tex,
                lk,
                wrap,
                format!(
                    "wrap={wrap}/texel={i}.25_{j}/offset={}_{}/ref=0.5",
                    o[0], o[1]
                ),
            );
            if wrap == Wrap::ClampToBorder {
                x.sampler.border = [border, 0.0, 0.0, 0.0];
            }
            out.push(x);
        }
    }
    // Level 1 (2x2) of a 4x4 chain, at s = t = 0.1 (u = v = 0.2): offset +1 reads texel 1 of level
    // 1; read in base-level texels it would be half a texel and stay on texel 0. Explicit LOD 1
    // (textureLodOffset) and, where the spec has the shader bias, LOD 0 + bias 1 (textureOffset).
    for &filter in d.filters.iter().filter(|f| {
        matches!(
            f,
            Filter::NearestMipmapNearest | Filter::LinearMipmapNearest
        )
    }) {
        let c = cell2d(filter, CompareMode::Compare);
        for o in [[1, 0], [0, 1], [1, 1]] {
            let hot = (o[0] as i64, o[1] as i64, 0);
            let tex = texture(
                &c,
                vec![
                    one_hot(c.format, SIZE, SIZE, 1, None),
                    one_hot(c.format, SIZE / 2, SIZE / 2, 1, Some(hot)),
                    one_hot(c.format, 1, 1, 1, None),
                ],
            );
            let mut forms: Vec<(&str, f64, f64)> = vec![("lod=1", 1.0, 0.0)];
            if d.shader_bias {
                forms.push(("lod=0/bias=1", 0.0, 1.0));
            }
            for (name, lod, bias) in forms {
                let mut lk = offset_lookup(Target::T2d, At::st(0.1, 0.1), SIZE, SIZE, o);
                lk.lod = lod;
                lk.bias = bias;
                out.push(Draft::new(
                    "offset",
                    c,
                    tex.clone(),
                    lk,
                    format!("level=1/st=0.1_0.1/offset={}_{}/{name}/ref=0.5", o[0], o[1]),
                ));
            }
        }
    }
    // LINEAR_MIPMAP_LINEAR between levels 0 and 1 (λ = 0.5) with an offset, off the texel centres
    // (level 0: u = 1.75, v = 1.5; level 1: u = 0.875, v = 0.75), REPEAT: the offset moves the
    // bilinear footprint of both levels (GL 4.6 §8.14.2 (8.10) for each level's u, v). Each level
    // is hot at its offset texel, so an offset dropped or applied in base-level texels on one level
    // shows. Under WebGPU this is textureSampleCompare with an offset and implicit derivatives.
    // In D16 too, which every Vulkan driver has (SwiftShader's has no D24).
    let between_formats = [fixed_fmt(d), Format::D16];
    for fmt in between_formats
        .into_iter()
        .filter(|_| d.filters.contains(&Filter::LinearMipmapLinear))
    {
        let c = cell(
            d,
            Target::T2d,
            fmt,
            Filter::LinearMipmapLinear,
            main_func(d),
        );
        for o in [[1, 0], [0, 1], [-1, -1]] {
            let hot0 = (
                wrapped(1, o[0], SIZE, Wrap::Repeat),
                wrapped(1, o[1], SIZE, Wrap::Repeat),
                0,
            );
            let hot1 = (
                wrapped(0, o[0], SIZE / 2, Wrap::Repeat),
                wrapped(0, o[1], SIZE / 2, Wrap::Repeat),
                0,
            );
            let tex = texture(
                &c,
                vec![
                    one_hot(c.format, SIZE, SIZE, 1, Some(hot0)),
                    one_hot(c.format, SIZE / 2, SIZE / 2, 1, Some(hot1)),
                    one_hot(c.format, 1, 1, 1, None),
                ],
            );
            let mut lk = offset_lookup(Target::T2d, At::st(0.4375, 0.375), SIZE, SIZE, o);
            lk.lod = 0.5;
            out.push(wrap_draft(
                c,
                tex,
                lk,
                Wrap::Repeat,
                format!(
                    "between/st=0.4375_0.375/offset={}_{}/lod=0.5/ref=0.5",
                    o[0], o[1]
                ),
            ));
        }
    }
    // Projective (textureProjOffset): P = (s, t, Dref, 1)·q with q = 2.
    let c = cell2d(Filter::Nearest, CompareMode::Compare);
    for o in [[1, 0], [-1, 1]] {
        let hot = (
            wrapped(i, o[0], SIZE, Wrap::ClampToEdge),
            wrapped(j, o[1], SIZE, Wrap::ClampToEdge),
            0,
        );
        let tex = texture(&c, vec![one_hot(c.format, SIZE, SIZE, 1, Some(hot))]);
        let q = 2.0;
        let mut lk = offset_lookup(Target::T2d, centre(i, j, 0.0), SIZE, SIZE, o);
        lk.coord = [lk.coord[0] * q, lk.coord[1] * q, 0.0, q];
        lk.dref *= q;
        lk.projective = true;
        out.push(Draft::new(
            "offset",
            c,
            tex,
            lk,
            format!("proj/q=2/texel={i}_{j}/offset={}_{}/ref=0.5", o[0], o[1]),
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
        Spec::Gl46 => &[
            Target::T1d,
            Target::Rect,
            Target::T1dArray,
            Target::T2dArray,
        ],
        // Vulkan: ConstOffset on every non-cube Dim (SPIR-V Image Operands; §16 Texel
        // Coordinate Offset), i.e. GL's list without rectangles.
        Spec::Vulkan => &[Target::T1d, Target::T1dArray, Target::T2dArray],
        // ES 3.x, and WGSL's offset overloads on texture_depth_2d_array (WGSL texture built-in functions).
        _ => &[Target::T2dArray],
    };
    let mut out = Vec::new();
    for &target in targets.iter().filter(|t| d.targets.contains(t)) {
        let c = cell(d, target, fixed_fmt(d), Filter::Nearest, main_func(d));
        let one_d = target.dims() == 1;
        let (layers, layer) = if target.is_array() {
            (2u32, 1u32)
        } else {
            (1, 0)
        };
        let (w, h) = if one_d { (SIZE, 1) } else { (SIZE, SIZE) };
        let (i, j) = if one_d { (1i64, 0i64) } else { (1, 2) };
        let offsets: &[[i32; 2]] = if one_d {
            &[[1, 0], [-1, 0], [2, 0], [-8, 0]]
        } else {
            &[[1, 0], [-1, -1], [2, -1], [7, -8]]
        };
        let wraps: &[Wrap] = if target == Target::Rect {
            &[Wrap::ClampToEdge]
        } else {
            &[Wrap::ClampToEdge, Wrap::Repeat]
        };
        for &wrap in wraps {
            for &o in offsets {
                let hot = (
                    wrapped(i, o[0], w, wrap),
                    if one_d { 0 } else { wrapped(j, o[1], h, wrap) },
                    layer,
                );
                let tex = texture(&c, vec![one_hot(c.format, w, h, layers, Some(hot))]);
                let at = At {
                    s: (i as f64 + 0.5) / w as f64,
                    t: (j as f64 + 0.5) / h as f64,
                    layer: layer as f64,
                    face: 0,
                };
                let lk = offset_lookup(target, at, w, h, o);
                let pos = if one_d {
                    format!("{i}")
                } else {
                    format!("{i}_{j}")
                };
                let off = if one_d {
                    format!("{}", o[0])
                } else {
                    format!("{}_{}", o[0], o[1])
                };
                out.push(wrap_draft(
                    c,
                    tex,
                    lk,
                    wrap,
                    format!("wrap={wrap}/texel={pos}/offset={off}/ref=0.5"),
                ));
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
                assert_ne!(x.lookup.offset, [0; 3], "{}", x.id());
                let case = x.into_case();
                shadowcheck_model::validate::validate(&case).unwrap();
                assert!(case.api.iter().all(|a| matches!(
                    a,
                    ApiPath::Glsl130
                        | ApiPath::GlslCore
                        | ApiPath::Es300
                        | ApiPath::Vulkan
                        | ApiPath::Wgsl
                )));
            }
        }
    }

    #[test]
    fn wrapped_follows_table_8_20_for_mirrored_repeat_and_border_reads_off_the_image() {
        // 4 texels: ... 1 0 | 0 1 2 3 | 3 2 1 0 | 0 1 ...
        assert_eq!(wrapped(1, -2, 4, Wrap::MirroredRepeat), 0);
        assert_eq!(wrapped(1, -3, 4, Wrap::MirroredRepeat), 1);
        assert_eq!(wrapped(2, 2, 4, Wrap::MirroredRepeat), 3);
        assert_eq!(wrapped(1, 7, 4, Wrap::MirroredRepeat), 0);
        assert_eq!(
            hot_and_border(1, 2, [7, -8], Wrap::ClampToBorder),
            (None, HOT as f32)
        );
        assert_eq!(
            hot_and_border(1, 2, [1, 0], Wrap::ClampToBorder),
            (Some((2, 2, 0)), COLD as f32)
        );
    }

    #[test]
    fn wrapped_follows_table_8_20_for_clamp_and_repeat() {
        assert_eq!(wrapped(1, -8, 4, Wrap::Repeat), 1);
        assert_eq!(wrapped(2, 7, 4, Wrap::Repeat), 1);
        assert_eq!(wrapped(1, -8, 4, Wrap::ClampToEdge), 0);
        assert_eq!(wrapped(2, 7, 4, Wrap::ClampToEdge), 3);
    }
}
