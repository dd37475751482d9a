//! Texel selection on one level (GL 4.6 §8.14.2, §8.13.1): which texels a NEAREST or LINEAR lookup
//! reads, through the wrap modes, the border and seamless cube neighbours.

use crate::accept::{Scen, Taps};
use crate::lod::Pick;
use crate::rules::Rules;
use crate::sample::{Key, TexelCtx, TexelEval};
use crate::{cube, wrap};
use shadowcheck_model::{Case, Target, Wrap};

/// Where one lookup samples inside a level: normalized (s, t) (unnormalized for rectangles), the
/// absolute layer, and the cube face if any.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geo {
    pub s: f64,
    pub t: f64,
    pub layer: i64,
    pub face: Option<usize>,
}

/// Builds the scenario of one geometry and one pick, evaluating (and caching) its texels.
pub fn build(
    rules: &Rules,
    case: &Case,
    tcx: &TexelCtx,
    texels: &mut Vec<TexelEval>,
    g: Geo,
    p: Pick,
) -> Scen {
    match p {
        Pick::One { level, linear } => Scen {
            a: (level, taps(rules, case, tcx, texels, g, level, linear)),
            b: None,
            f: 0.0,
            f_lo: 0.0,
            f_hi: 0.0,
        },
        Pick::Two {
            d1,
            d2,
            linear,
            f,
            f_lo,
            f_hi,
        } => {
            let a = taps(rules, case, tcx, texels, g, d1, linear);
            let b = taps(rules, case, tcx, texels, g, d2, linear);
            Scen {
                a: (d1, a),
                b: Some((d2, b)),
                f,
                f_lo,
                f_hi,
            }
        }
    }
}

fn index(tcx: &TexelCtx, texels: &mut Vec<TexelEval>, key: Key) -> usize {
    if let Some(i) = texels.iter().position(|t| t.key == key) {
        return i;
    }
    texels.push(tcx.eval(key));
    texels.len() - 1
}

/// §8.14.2 texel selection on one level.
fn taps(
    rules: &Rules,
    case: &Case,
    tcx: &TexelCtx,
    texels: &mut Vec<TexelEval>,
    g: Geo,
    level: u32,
    linear: bool,
) -> Taps {
    let tex = &case.texture;
    let s = &case.sampler;
    let l = &tex.levels[(level as usize).min(tex.levels.len() - 1)];
    let (w, h) = (l.width as i64, l.height as i64);
    let rect = tex.target == Target::Rect;
    // (8.10): u = w_s·s + δu, v = h_s·t + δv with the size of the selected level (§8.14.3: "for
    // level d1, the coordinate (u, v, w) is computed as in equation 8.10, with w_s, h_s, and d_s
    // equal to the width, height, and depth of level d1"); rectangles: u = s + δu.
    let (du, dv) = (case.lookup.offset[0] as f64, case.lookup.offset[1] as f64);
    let (u, v) = if rect {
        (g.s + du, g.t + dv)
    } else {
        (g.s * w as f64 + du, g.t * h as f64 + dv)
    };
    let seamless = g.face.is_some() && rules.seamless_cube;
    // §8.13.1: "If NEAREST filtering is done within a miplevel, always apply wrap mode CLAMP_TO_EDGE.
    // If LINEAR filtering is done within a miplevel, always apply wrap mode CLAMP_TO_BORDER."
    let (ws, wt) = match (seamless, linear) {
        (true, false) => (Wrap::ClampToEdge, Wrap::ClampToEdge),
        (true, true) => (Wrap::ClampToBorder, Wrap::ClampToBorder),
        _ => (s.wrap_s, s.wrap_t),
    };
    let one_d = matches!(tex.target, Target::T1d | Target::T1dArray);
    let mut key = |i: i64, j: i64| -> usize {
        let inside = (0..w).contains(&i) && (0..h).contains(&j);
        let k = if inside {
            Key::Texel {
                level,
                x: i,
                y: j,
                layer: g.layer,
            }
        } else if seamless {
            let face = g.face.unwrap_or(0);
            let base = g.layer - face as i64;
            match cube::neighbour(face, i, j, w) {
                Some((f, x, y)) => Key::Texel {
                    level,
                    x,
                    y,
                    layer: base + f as i64,
                },
                None => {
                    let (ci, cj) = (i.clamp(0, w - 1), j.clamp(0, h - 1));
                    let n1 = cube::neighbour(face, ci, j, w).unwrap_or((face, ci, cj));
                    let n2 = cube::neighbour(face, i, cj, w).unwrap_or((face, ci, cj));
                    Key::Corner {
                        level,
                        from: [
                            (n1.1, n1.2, base + n1.0 as i64),
                            (n2.1, n2.2, base + n2.0 as i64),
                            (ci, cj, g.layer),
                        ],
                    }
                }
            }
        } else {
            Key::Border { level }
        };
        index(tcx, texels, k)
    };
    if !linear {
        let i = wrap::nearest(ws, u, w);
        let j = if one_d { 0 } else { wrap::nearest(wt, v, h) };
        return Taps::One(key(i, j));
    }
    let (i0, i1, a) = wrap::linear(ws, u, w);
    if one_d {
        return Taps::Lin1([key(i0, 0), key(i1, 0)], a);
    }
    let (j0, j1, b) = wrap::linear(wt, v, h);
    Taps::Lin2([key(i0, j0), key(i1, j0), key(i0, j1), key(i1, j1)], a, b)
}
