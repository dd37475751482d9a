//! Phase "select": the cube faces (§8.13) and array layers (§8.14.2) an implementation may choose,
//! and the texel offset, as the geometries the texel selection starts from.

use super::inputs::Coords;
use super::Eval;
use crate::cube;
use crate::rules::Rules;
use crate::select::Geo;
use crate::unorm::{f32_candidates, f32r, Exact};
use crate::wrap;
use shadowcheck_model::{Case, Target};

/// The geometries of the lookup, the spec's own first; a choice left to the implementation (a tied
/// major axis or layer) is recorded in `choices` (a label only where it changes the result).
/// `linear`: the lookup filters LINEAR within a level (the spec's pick), so the layer is §8.14.2's
/// LINEAR formula ⌊r + 1/2⌋ alone; under NEAREST it is RNE(r) or, by footnote 4, ⌊r + 1/2⌋
/// (and under every filter where the spec says so, `Rules::layer_rne_always`).
pub(super) fn geometries(
    e: &mut Eval,
    rules: &Rules,
    case: &Case,
    co: &Coords,
    linear: bool,
    choices: &mut Vec<&'static str>,
) -> Vec<Geo> {
    let linear = linear && rules.layer_rne_always.is_none();
    let mut geos = faces_and_layers(e, case, co, linear);
    if geos.len() > 1 {
        choices.push("the major axis or the layer is tied: the implementation's rounding/tie rule decides (GL 4.6 §8.13, §8.14.2 footnote 4)");
    }
    if case.lookup.projective && projective_neighbours(&mut geos) {
        choices.push("projective lookup: s/q and t/q are computed in f32, so either f32 neighbour of the exact quotient may select the texels (as for Dref/q)");
    }
    layer_and_offset_steps(e, rules, case, &geos, linear);
    geos
}

/// A projective lookup (1D, 2D, rectangle: one flat geometry) divides s and t by q in f32: each
/// quotient may be either f32 neighbour of the exact one, as Dref/q is (`inputs::texel_ctx`). Adds
/// those geometries after the spec's own; true when any was added.
fn projective_neighbours(geos: &mut Vec<Geo>) -> bool {
    let Some(&g) = geos.first() else {
        return false;
    };
    let n = geos.len();
    for s in f32_candidates(Exact::F(g.s)) {
        for t in f32_candidates(Exact::F(g.t)) {
            if !geos
                .iter()
                .any(|x| x.s == s && x.t == t && x.layer == g.layer)
            {
                geos.push(Geo { s, t, ..g });
            }
        }
    }
    geos.len() > n
}

/// One geometry per cube face and layer the implementation may choose.
fn faces_and_layers(e: &mut Eval, case: &Case, co: &Coords, linear: bool) -> Vec<Geo> {
    let tex = &case.texture;
    let c = co.c;
    let q = co.q;
    let mut geos: Vec<Geo> = Vec::new();
    let (s0, t0) = (c[0] / q, c[1] / q);
    let layers_of = |n: i64, x: f64| {
        if linear {
            return vec![wrap::layer_linear(x, n)];
        }
        let (a, b) = wrap::layer(x, n);
        if a == b {
            vec![a]
        } else {
            vec![a, b]
        }
    };
    let layers = tex.levels.first().map_or(0, |l| l.layers as i64);
    let flat = |s: f64, t: f64, layer: i64| Geo {
        s,
        t,
        layer,
        face: None,
    };
    match tex.target {
        Target::T1d => geos.push(flat(s0, 0.0, 0)),
        Target::T2d | Target::Rect => geos.push(flat(s0, t0, 0)),
        Target::T1dArray => layers_of(layers, c[1])
            .into_iter()
            .for_each(|l| geos.push(flat(s0, 0.0, l))),
        Target::T2dArray => layers_of(layers, c[2])
            .into_iter()
            .for_each(|l| geos.push(flat(s0, t0, l))),
        Target::Cube | Target::CubeArray => {
            let dir = [c[0], c[1], c[2]];
            let cubes = if tex.target == Target::Cube {
                vec![0]
            } else {
                layers_of(layers / 6, f32r(case.lookup.layer))
            };
            for f in cube::faces(dir) {
                let (fs, ft) = cube::face_st(f, dir);
                for &cu in &cubes {
                    geos.push(Geo {
                        s: fs,
                        t: ft,
                        layer: cu * 6 + f as i64,
                        face: Some(f),
                    });
                }
            }
            if let Some(g) = geos.first() {
                e.step(
                    format!(
                        "cube face {} (major axis), s = {}, t = {}",
                        cube::FACE_NAMES[g.face.unwrap_or(0)],
                        g.s,
                        g.t
                    ),
                    "GL 4.6 §8.13 Table 8.19",
                );
            }
        }
    }
    geos
}

/// The steps for the spec's layer and the texel offset.
fn layer_and_offset_steps(e: &mut Eval, rules: &Rules, case: &Case, geos: &[Geo], linear: bool) {
    let tex = &case.texture;
    if tex.target.is_array() {
        if let Some(g) = geos.first() {
            let l = if tex.target == Target::CubeArray {
                g.layer / 6
            } else {
                g.layer
            };
            if linear {
                e.step(
                    format!("layer = clamp(⌊layer coordinate + 1/2⌋, 0, d − 1) = {l} (LINEAR)"),
                    "GL 4.6 §8.14.2 LINEAR (l = clamp(⌊r + 1/2⌋, 0, d_s − 1))",
                );
            } else {
                e.step(
                    format!("layer = clamp(RNE(layer coordinate), 0, d − 1) = {l}"),
                    rules
                        .layer_rne_always
                        .unwrap_or("GL 4.6 §8.14.2 (l = clamp(RNE(r), 0, d_s − 1))"),
                );
            }
        }
    }
    let o = case.lookup.offset;
    if o != [0; 3] {
        e.step(
            format!(
                "texel offset (δu, δv, δw) = ({}, {}, {}): u = w·s + δu, v = h·t + δv in the texels of each selected level, before wrapping",
                o[0], o[1], o[2]
            ),
            "GL 4.6 §8.14.2 (8.10), §8.14.3; GLSL 4.60 §8.9.2 textureOffset",
        );
    }
}
