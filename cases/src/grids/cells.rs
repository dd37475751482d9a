//! The main product: every spec x target x format x filter x compare func (and compare mode NONE)
//! the spec allows, each with a few lookups whose results tell the rules apart:
//!
//! - NEAREST: texel 1 of the pattern 0.2, 0.4, 0.6, 0.8 with R below (0.3), at (the stored value
//!   as f32) and above (0.5) it;
//! - LINEAR: a 2x2 footprint at alpha = 0.25, beta = 0.5 (weights 0.375, 0.125, 0.375, 0.125; 1D:
//!   0.75, 0.25) with R between the texel values, so that 1, 2 and 3 texels pass;
//! - mipmap filters: a chain whose levels hold 0.2, 0.8, 0.4 (so a wrong level changes the result),
//!   at lambda 0 (level 0), 1 (level 1) and 1.75 (level 2, or a 1:3 blend of levels 1 and 2).
//!
//! Other layers and cube faces hold the complement 1 - v, so reading the wrong image shows.
//! Compare mode NONE reads the depth value itself (one lookup per filter kind). Formats that add no
//! comparison rule of their own (R8 bypass, the DEPTH_STENCIL formats, which compare like D24 and
//! D32F) get one lookup per cell.

use super::draft::{lookup, texture, Cell, Draft};
use super::specs::{self, SpecDims};
use crate::build::{self, At};
use crate::dsl::Grid;
use shadowcheck_model::*;

/// Every allowed cell of `spec`, as a grid.
pub fn cells(d: &SpecDims) -> Grid<Cell> {
    Grid::new(format!("{}-cells", d.spec), [Cell::new(d.spec)])
        .combine("target", d.targets.iter().copied(), |c, v| c.target = v)
        .combine("format", d.formats.iter().copied(), |c, v| c.format = v)
        .combine("filter", d.filters.iter().copied(), |c, v| c.filter = v)
        .filter(
            "rectangle textures take only NEAREST/LINEAR min filters (GL 4.6 §8.10, INVALID_ENUM)",
            |c| specs::filter_allowed(c.target, c.filter),
        )
        .combine("mode", CompareMode::ALL.iter().copied(), |c, v| c.mode = v)
        .combine_with(
            "func",
            |c| {
                if c.mode == CompareMode::None {
                    vec![d.funcs[0]]
                } else {
                    d.funcs.to_vec()
                }
            },
            |c, v| c.func = v,
        )
}

/// The nominal pattern of the sampled image (4 texels: 2x2, or 4x1 for 1D targets).
pub const PATTERN: [f64; 4] = [0.2, 0.4, 0.6, 0.8];
/// Nominal value of each mip level.
pub const LEVELS: [f64; 3] = [0.2, 0.8, 0.4];

/// Formats that get one lookup per cell. R8 (bypass) and the DEPTH_STENCIL formats (which compare
/// like D24 / D32F) add no comparison rule; D32 and unsized DEPTH_COMPONENT differ from D16/D24 only
/// in stored precision, which the `exact` and `clamp` families test value by value. A spec whose
/// only depth format is one of these keeps the full set.
fn light(spec: Spec, format: Format) -> bool {
    match format {
        Format::R8 | Format::D24S8 | Format::D32fS8 => true,
        Format::D32 | Format::DepthUnsized => spec != Spec::Es2Ext,
        _ => false,
    }
}

/// Layer count (array layers, or cubes) and the sampled layer / face.
fn layout(target: Target) -> (u32, f64, u32) {
    match target {
        Target::T1dArray | Target::T2dArray | Target::CubeArray => (2, 1.0, 1),
        _ => (1, 0.0, 1),
    }
}

/// Values of a whole level: the sampled image holds `img`, every other image its complement.
pub fn fill(w: u32, h: u32, layers: u32, sampled: usize, img: &[f64]) -> Vec<f64> {
    let per = (w * h) as usize;
    let mut v = Vec::with_capacity(per * layers as usize);
    for l in 0..layers as usize {
        for i in 0..per {
            let x = img[i % img.len()];
            v.push(if l == sampled { x } else { 1.0 - x });
        }
    }
    v
}

/// The single-level texture with [`PATTERN`] on the sampled image.
pub fn pattern_texture(cell: &Cell) -> (Texture, u32, u32, At) {
    let (n, layer, face) = layout(cell.target);
    let size = if cell.target.dims() == 1 { 4 } else { 2 };
    let (w, h, layers) = build::dims(cell.target, size, n);
    let sampled = build::image_offset(cell.target, w, h, layer as u32, face) / (w * h) as usize;
    let vals = fill(w, h, layers, sampled, &PATTERN);
    let tex = texture(cell, vec![build::level(cell.format, w, h, layers, &vals)]);
    (
        tex,
        w,
        h,
        At {
            s: 0.0,
            t: 0.0,
            layer,
            face,
        },
    )
}

/// A mip chain (1D and 2D 4 wide, array and cube targets 2 wide to keep fixtures small, down to 1) whose level i holds [`LEVELS`]\[i\] on the sampled
/// image.
pub fn mip_texture(cell: &Cell) -> (Texture, At) {
    let (n, layer, face) = layout(cell.target);
    let size = if cell.target.is_cube() || cell.target.is_array() {
        2
    } else {
        4
    };
    let mut levels = Vec::new();
    let mut s = size;
    let mut i = 0;
    loop {
        let (w, h, layers) = build::dims(cell.target, s, n);
        let sampled = build::image_offset(cell.target, w, h, layer as u32, face) / (w * h) as usize;
        let vals = fill(w, h, layers, sampled, &[LEVELS[i % LEVELS.len()]]);
        levels.push(build::level(cell.format, w, h, layers, &vals));
        if s == 1 {
            break;
        }
        s /= 2;
        i += 1;
    }
    (
        texture(cell, levels),
        At {
            s: 0.5,
            t: 0.5,
            layer,
            face,
        },
    )
}

/// The lookups of one cell.
pub fn drafts(cell: &Cell) -> Vec<Draft> {
    let f = cell.format;
    let one_d = cell.target.dims() == 1;
    let mut out = Vec::new();
    if !cell.filter.is_mipmap() {
        let (tex, w, h, base) = pattern_texture(cell);
        let nominal = crate::build::nums(&PATTERN);
        if cell.filter == Filter::Nearest {
            // Texel 1 (value 0.4): 2D (x=1, y=0); 1D x=1.
            let at = if one_d {
                At {
                    s: 1.5 / 4.0,
                    t: 0.0,
                    ..base
                }
            } else {
                At {
                    s: 0.75,
                    t: 0.25,
                    ..base
                }
            };
            let at_ref = build::f32r(build::stored_real(f, PATTERN[1]));
            let refs: Vec<(String, f64)> = if cell.mode == CompareMode::None {
                vec![("read".into(), 0.5)]
            } else if light(cell.spec, f) {
                vec![("ref=0.3".into(), 0.3)]
            } else {
                vec![
                    ("ref=0.3".into(), 0.3),
                    ("ref=at".into(), at_ref),
                    ("ref=0.5".into(), 0.5),
                ]
            };
            for (tag, r) in refs {
                let lk = lookup(cell.target, at, w, h, r);
                out.push(Draft::new(
                    "cell",
                    *cell,
                    tex.clone(),
                    lk,
                    format!("texel1/{tag}/dt={nominal}"),
                ));
            }
        } else {
            // alpha = 0.25, beta = 0.5 from texel (0,0) (2D) or from texel 1 (1D).
            let at = if one_d {
                At {
                    s: 1.75 / 4.0,
                    t: 0.0,
                    ..base
                }
            } else {
                At {
                    s: 0.375,
                    t: 0.5,
                    ..base
                }
            };
            let refs: &[f64] = if cell.mode == CompareMode::None || light(cell.spec, f) {
                &[0.5]
            } else {
                &[0.3, 0.7]
            };
            for r in refs {
                let lk = lookup(cell.target, at, w, h, *r);
                let tag = if cell.mode == CompareMode::None {
                    "read".to_string()
                } else {
                    format!("ref={r}")
                };
                out.push(Draft::new(
                    "cell",
                    *cell,
                    tex.clone(),
                    lk,
                    format!("a=0.25_0.5/{tag}/dt={nominal}"),
                ));
            }
        }
    } else {
        let (tex, base) = mip_texture(cell);
        let (w, h) = (tex.levels[0].width, tex.levels[0].height);
        let lods: &[(f64, f64)] = if cell.mode == CompareMode::None || light(cell.spec, f) {
            &[(1.0, 0.5)]
        } else {
            &[(1.0, 0.5), (1.75, 0.6)]
        };
        for (lod, r) in lods {
            let mut lk = lookup(cell.target, base, w, h, *r);
            lk.lod = *lod;
            let tag = if cell.mode == CompareMode::None {
                "read".to_string()
            } else {
                format!("ref={r}")
            };
            out.push(Draft::new(
                "cell",
                *cell,
                tex.clone(),
                lk,
                format!("lod={lod}/{tag}/levels={}", crate::build::nums(&LEVELS)),
            ));
        }
    }
    out
}
