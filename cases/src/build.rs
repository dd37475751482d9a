//! Building blocks for cases: stored texel values per format, textures per target, lookups placed at
//! known texel positions and filter weights, and the case id.
//!
//! Values are chosen by their *nominal* real value (e.g. 0.25) and stored as the format stores them:
//! unorm formats as the integer round(v x (2^b - 1)) (GL 4.6 §2.3.5), float formats as the f32
//! nearest to v. Lookups then compare against the *stored* value, so an id's `dt=` lists nominal
//! values and the fixture carries the exact integers.

use shadowcheck_model::*;

/// Largest unorm integer of `bits` bits.
pub fn unorm_max(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// The value `format` stores for the nominal real `v` (unorm: nearest integer of the clamped value;
/// float: nearest f32, not clamped — the upload clamp is the oracle's business).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stored {
    Unorm(u32),
    Float(f32),
}

pub fn store(format: Format, v: f64) -> Stored {
    match format.unorm_bits() {
        Some(b) => Stored::Unorm((v.clamp(0.0, 1.0) * unorm_max(b) as f64).round() as u32),
        None => Stored::Float(v as f32),
    }
}

/// The real number a stored value stands for (c / (2^b - 1) for unorm, after the upload clamp).
pub fn real(format: Format, s: Stored) -> f64 {
    match (s, format.unorm_bits()) {
        (Stored::Unorm(c), Some(b)) => c as f64 / unorm_max(b) as f64,
        (Stored::Float(f), _) => (f as f64).clamp(0.0, 1.0),
        (Stored::Unorm(c), None) => c as f64,
    }
}

/// Stored value of nominal `v`, as the real it stands for.
pub fn stored_real(format: Format, v: f64) -> f64 {
    real(format, store(format, v))
}

/// Nearest f32, as f64 (the API passes f32).
pub fn f32r(v: f64) -> f64 {
    v as f32 as f64
}

/// The next f32 above / below `v` (v itself an f32 value).
pub fn f32_next_up(v: f64) -> f64 {
    let f = v as f32;
    let bits = f.to_bits();
    let next = if f == 0.0 {
        f32::from_bits(1)
    } else if f > 0.0 {
        f32::from_bits(bits + 1)
    } else {
        f32::from_bits(bits - 1)
    };
    next as f64
}
pub fn f32_next_down(v: f64) -> f64 {
    -f32_next_up(-v)
}

/// The nominal components (R, G, B, A) of a colour texel of nominal value `v`: R = v, G = 1 − v,
/// B = v / 2, A = (1 + v) / 2, so that every component of a footprint differs from the others
/// and a channel read from the wrong component shows.
pub fn colour_components(v: f64) -> [f64; 4] {
    [v, 1.0 - v, v / 2.0, (1.0 + v) / 2.0]
}

/// A colour texel of a format of several components from nominal components (absent ones 0).
pub fn colour_texel(format: Format, comps: [f64; 4]) -> [u32; 4] {
    let n = format.components();
    let b = format.unorm_bits().unwrap_or(8);
    let mut t = [0u32; 4];
    for (i, v) in comps.iter().enumerate().take(n) {
        t[i] = (v.clamp(0.0, 1.0) * unorm_max(b) as f64).round() as u32;
    }
    t
}

/// Texels of one level from nominal values (a colour format of several components: the
/// components of [`colour_components`]).
pub fn texels(format: Format, vals: &[f64]) -> Texels {
    if format.is_multi_colour() {
        return Texels::Colour(
            vals.iter()
                .map(|v| colour_texel(format, colour_components(*v)))
                .collect(),
        );
    }
    if format.unorm_bits().is_some() {
        Texels::Unorm(
            vals.iter()
                .map(|v| match store(format, *v) {
                    Stored::Unorm(c) => c,
                    Stored::Float(_) => 0,
                })
                .collect(),
        )
    } else {
        Texels::Float(vals.iter().map(|v| *v as f32).collect())
    }
}

/// Texels given directly as stored unorm integers (or f32 values for float formats).
pub fn texels_exact(format: Format, vals: &[Stored]) -> Texels {
    if format.is_multi_colour() {
        // The stored integer in every component the format has.
        let n = format.components();
        return Texels::Colour(
            vals.iter()
                .map(|s| {
                    let c = if let Stored::Unorm(c) = s { *c } else { 0 };
                    let mut t = [0u32; 4];
                    t.iter_mut().take(n).for_each(|x| *x = c);
                    t
                })
                .collect(),
        );
    }
    if format.unorm_bits().is_some() {
        Texels::Unorm(
            vals.iter()
                .map(|s| if let Stored::Unorm(c) = s { *c } else { 0 })
                .collect(),
        )
    } else {
        Texels::Float(
            vals.iter()
                .map(|s| if let Stored::Float(f) = s { *f } else { 0.0 })
                .collect(),
        )
    }
}

/// (width, height, layers) of level 0 for a target with `size` texels a side and `n` layers
/// (array layers; cube arrays: n cubes).
pub fn dims(target: Target, size: u32, n: u32) -> (u32, u32, u32) {
    match target {
        Target::T1d => (size, 1, 1),
        Target::T1dArray => (size, 1, n),
        Target::T2d | Target::Rect => (size, size, 1),
        Target::T2dArray => (size, size, n),
        Target::Cube => (size, size, 6),
        Target::CubeArray => (size, size, 6 * n),
    }
}

/// A level of `format` from nominal values (stencil filled with a fixed pattern for
/// DEPTH_STENCIL formats, so that stencil lookups have known values).
pub fn level(format: Format, w: u32, h: u32, layers: u32, vals: &[f64]) -> Level {
    Level {
        width: w,
        height: h,
        layers,
        depth: texels(format, vals),
        stencil: stencil_for(format, vals.len()),
    }
}

pub fn level_exact(format: Format, w: u32, h: u32, layers: u32, vals: &[Stored]) -> Level {
    Level {
        width: w,
        height: h,
        layers,
        depth: texels_exact(format, vals),
        stencil: stencil_for(format, vals.len()),
    }
}

/// Stencil pattern: texel i holds (37 i + 5) mod 256.
pub fn stencil_value(i: usize) -> u8 {
    ((37 * i + 5) % 256) as u8
}

fn stencil_for(format: Format, n: usize) -> Option<Vec<u8>> {
    format
        .has_stencil()
        .then(|| (0..n).map(stencil_value).collect())
}

/// A direction vector hitting cube face `face` (GL order +X,-X,+Y,-Y,+Z,-Z) at face coordinates
/// (s, t) in [0,1], by inverting GL 4.6 §8.13 Table 8.19 with |ma| = 1.
pub fn cube_dir(face: u32, s: f64, t: f64) -> [f64; 3] {
    let sc = 2.0 * s - 1.0;
    let tc = 2.0 * t - 1.0;
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

/// Where a lookup samples: normalized (s, t) inside the image, the array layer (or cube index for
/// cube arrays) and the cube face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct At {
    pub s: f64,
    pub t: f64,
    pub layer: f64,
    pub face: u32,
}

impl At {
    pub fn st(s: f64, t: f64) -> At {
        At {
            s,
            t,
            layer: 0.0,
            face: 0,
        }
    }
}

/// The lookup coordinates for `at` on `target` (rectangle: unnormalized with width/height `w`,`h`).
pub fn coord(target: Target, at: At, w: u32, h: u32) -> ([f64; 4], f64) {
    match target {
        Target::T1d => ([at.s, 0.0, 0.0, 1.0], 0.0),
        Target::T2d => ([at.s, at.t, 0.0, 1.0], 0.0),
        Target::Rect => ([at.s * w as f64, at.t * h as f64, 0.0, 1.0], 0.0),
        Target::T1dArray => ([at.s, at.layer, 0.0, 1.0], 0.0),
        Target::T2dArray => ([at.s, at.t, at.layer, 1.0], 0.0),
        Target::Cube => {
            let d = cube_dir(at.face, at.s, at.t);
            ([d[0], d[1], d[2], 1.0], 0.0)
        }
        Target::CubeArray => {
            let d = cube_dir(at.face, at.s, at.t);
            ([d[0], d[1], d[2], 1.0], at.layer)
        }
    }
}

/// Index of the first texel of layer `layer` / face `face` (cube arrays: cube `layer`) in a level.
pub fn image_offset(target: Target, w: u32, h: u32, layer: u32, face: u32) -> usize {
    let per = (w * h) as usize;
    match target {
        Target::Cube => face as usize * per,
        Target::CubeArray => (layer * 6 + face) as usize * per,
        Target::T1dArray | Target::T2dArray => layer as usize * per,
        _ => 0,
    }
}

/// Formats a real for an id: shortest round-trip form, non-finite as `nan`, `inf`, `-inf`.
pub fn num(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else if v != 0.0 && (v.abs() >= 1e6 || v.abs() < 1e-4) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// An underscore-separated list (ids need no CSV quoting) of reals for an id.
pub fn nums(vs: &[f64]) -> String {
    vs.iter().map(|v| num(*v)).collect::<Vec<_>>().join("_")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm_store_is_nearest_integer() {
        assert_eq!(store(Format::D16, 0.5), Stored::Unorm(32768));
        assert_eq!(store(Format::D24, 1.0), Stored::Unorm(16_777_215));
        assert_eq!(store(Format::D32, 1.0), Stored::Unorm(u32::MAX));
        assert_eq!(store(Format::D16, -3.0), Stored::Unorm(0));
        assert_eq!(real(Format::D16, Stored::Unorm(65535)), 1.0);
    }

    #[test]
    fn f32_neighbours() {
        assert_eq!(f32_next_up(1.0), 1.0 + f32::EPSILON as f64);
        assert_eq!(f32_next_down(1.0), 1.0 - f32::EPSILON as f64 / 2.0);
        assert_eq!(f32_next_up(0.0), f32::from_bits(1) as f64);
        assert_eq!(f32_next_down(0.0), -(f32::from_bits(1) as f64));
    }

    #[test]
    fn cube_dirs_select_their_face() {
        // GL 4.6 Table 8.19: the major axis is the largest magnitude component.
        for face in 0..6 {
            let d = cube_dir(face, 0.25, 0.75);
            let (axis, _) = d.iter().enumerate().fold((0, 0.0f64), |acc, (i, v)| {
                if v.abs() > acc.1 {
                    (i, v.abs())
                } else {
                    acc
                }
            });
            let neg = d[axis] < 0.0;
            assert_eq!(axis as u32 * 2 + neg as u32, face, "{d:?}");
        }
        // +X: sc = -rz, tc = -ry; s = (sc + 1) / 2.
        let d = cube_dir(0, 0.25, 0.75);
        assert_eq!(((-d[2]) + 1.0) / 2.0, 0.25);
        assert_eq!(((-d[1]) + 1.0) / 2.0, 0.75);
    }

    #[test]
    fn id_numbers_are_short() {
        assert_eq!(num(0.5), "0.5");
        assert_eq!(num(f64::NEG_INFINITY), "-inf");
        assert_eq!(num(1e30), "1e30");
        assert_eq!(num(-0.1), "-0.1");
    }
}
