//! Cube map face selection (GL 4.6 §8.13, Table 8.19) and the seamless neighbour lookup of
//! §8.13.1 (always on in ES 3.x).
//!
//! Ties between equal-magnitude axes are implementation-defined (§8.13: "the rule must be
//! deterministic and depend only on (rx ry rz)"). Chosen rule: X wins over Y and Z, then Y over Z.

use crate::faults::{Fault, Faults};

/// Cube face index in GL order: +X, −X, +Y, −Y, +Z, −Z (also the layer order of the images).
pub type Face = u8;

/// Selects the face for direction (rx, ry, rz) and returns (face, s, t) with
/// s = ½ (s_c / |m_a| + 1), t = ½ (t_c / |m_a| + 1), computed in f32. `None` for the zero vector
/// or a NaN component (no major axis).
#[inline]
pub fn select(rx: f32, ry: f32, rz: f32, faults: Faults) -> Option<(Face, f32, f32)> {
    let (ax, ay, az) = (rx.abs(), ry.abs(), rz.abs());
    // Table 8.19: (target, s_c, t_c, m_a).
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if rx >= 0.0 {
            (0, -rz, -ry, rx)
        } else {
            (1, rz, -ry, rx)
        }
    } else if ay >= az {
        if ry >= 0.0 {
            (2, rx, rz, ry)
        } else {
            let tc = if faults.has(Fault::CubeNegYFlipped) {
                rz
            } else {
                -rz
            };
            (3, rx, tc, ry)
        }
    } else if rz >= 0.0 {
        (4, rx, -ry, rz)
    } else {
        (5, -rx, -ry, rz)
    };
    let m = ma.abs();
    if m.is_nan() || m == 0.0 {
        return None;
    }
    Some((face, 0.5 * (sc / m + 1.0), 0.5 * (tc / m + 1.0)))
}

/// Direction (in units where the face spans [−n, n]) of the centre of texel (i, j) of `face`,
/// for an n×n face; i or j may be −1 or n (one texel outside the face).
fn texel_direction(face: Face, i: i64, j: i64, n: i64) -> [i64; 3] {
    // s_c = 2i + 1 − n, t_c = 2j + 1 − n, |m_a| = n; invert Table 8.19.
    let sc = 2 * i + 1 - n;
    let tc = 2 * j + 1 - n;
    match face {
        0 => [n, -tc, -sc],
        1 => [-n, -tc, sc],
        2 => [sc, n, tc],
        3 => [sc, -n, -tc],
        4 => [sc, -tc, n],
        _ => [-sc, -tc, -n],
    }
}

/// Seamless filtering (§8.13.1): the texel that location (i, j) of `face` denotes when it lies
/// one texel outside the face in exactly one of u, v. Returns (face, i, j) on the neighbouring
/// face; `None` for a corner (outside in both), which has no unique neighbour.
///
/// Exact integer arithmetic: the texel centre's direction has the out-of-range component of
/// magnitude n + 1 > n, so it becomes the new major axis; the other two components are mapped
/// onto the new face with s = ½ (s_c / |m_a| + 1), index ⌊s·n⌋, which keeps the texel row.
pub fn neighbour(face: Face, i: i64, j: i64, n: i64) -> Option<(Face, i64, i64)> {
    let out_i = i < 0 || i >= n;
    let out_j = j < 0 || j >= n;
    if out_i == out_j {
        return if out_i { None } else { Some((face, i, j)) };
    }
    let [x, y, z] = texel_direction(face, i, j, n);
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let (nf, sc, tc, ma) = if ax > n {
        if x > 0 {
            (0, -z, -y, ax)
        } else {
            (1, z, -y, ax)
        }
    } else if ay > n {
        if y > 0 {
            (2, x, z, ay)
        } else {
            (3, x, -z, ay)
        }
    } else if z > 0 {
        (4, x, -y, az)
    } else {
        (5, -x, -y, az)
    };
    // index = ⌊n (s_c + m_a) / (2 m_a)⌋, with s_c + m_a ≥ 0.
    let idx = |c: i64| ((n * (c + ma)).div_euclid(2 * ma)).clamp(0, n - 1);
    Some((nf, idx(sc), idx(tc)))
}

#[cfg(test)]
mod tests {
    use super::*;
    const F: Faults = Faults::NONE;

    #[test]
    fn table_8_19_major_axes() {
        // +X: s_c = -rz, t_c = -ry, m_a = rx. Direction (1, 0.5, -0.5): s = ½(0.5+1), t = ½(-0.5+1).
        assert_eq!(select(1.0, 0.5, -0.5, F), Some((0, 0.75, 0.25)));
        // -X: s_c = rz, t_c = -ry.
        assert_eq!(select(-2.0, 1.0, 1.0, F), Some((1, 0.75, 0.25)));
        // +Y: s_c = rx, t_c = rz.
        assert_eq!(select(0.5, 1.0, -0.5, F), Some((2, 0.75, 0.25)));
        // -Y: s_c = rx, t_c = -rz.
        assert_eq!(select(0.5, -1.0, 0.5, F), Some((3, 0.75, 0.25)));
        // +Z: s_c = rx, t_c = -ry.
        assert_eq!(select(0.5, 0.5, 1.0, F), Some((4, 0.75, 0.25)));
        // -Z: s_c = -rx, t_c = -ry.
        assert_eq!(select(-0.5, 0.5, -1.0, F), Some((5, 0.75, 0.25)));
    }

    #[test]
    fn ties_and_degenerate_directions() {
        assert_eq!(select(1.0, 1.0, 1.0, F).map(|x| x.0), Some(0));
        assert_eq!(select(0.0, -1.0, 1.0, F).map(|x| x.0), Some(3));
        assert_eq!(select(0.0, 0.0, 0.0, F), None);
        assert_eq!(select(f32::NAN, 0.0, 0.0, F), None);
    }

    #[test]
    fn seamless_neighbours() {
        let n = 4;
        // Left of +X (s_c = -1 side, i.e. direction toward +Z) is +Z's right column (i = 3).
        assert_eq!(neighbour(0, -1, 1, n), Some((4, 3, 1)));
        // Right of +X (toward -Z) is -Z's left column.
        assert_eq!(neighbour(0, 4, 2, n), Some((5, 0, 2)));
        // Above +Z (t_c < -n means +Y direction) is +Y's bottom row (j = 3), same column.
        assert_eq!(neighbour(4, 1, -1, n), Some((2, 1, 3)));
        // Below +Z (toward -Y) is -Y's top row (j = 0).
        assert_eq!(neighbour(4, 2, 4, n), Some((3, 2, 0)));
        // Inside: unchanged; corner: no unique neighbour.
        assert_eq!(neighbour(3, 2, 2, n), Some((3, 2, 2)));
        assert_eq!(neighbour(3, -1, 4, n), None);
    }

    #[test]
    fn neighbour_is_consistent_with_face_selection() {
        // For every edge texel outside a face, the neighbour found by integer arithmetic must be the
        // texel that face selection (§8.13) picks for the same direction.
        let n = 4i64;
        for face in 0..6u8 {
            for k in 0..n {
                for (i, j) in [(-1, k), (n, k), (k, -1), (k, n)] {
                    let (nf, ni, nj) = neighbour(face, i, j, n).unwrap();
                    let [x, y, z] = texel_direction(face, i, j, n);
                    let (sf, s, t) = select(x as f32, y as f32, z as f32, F).unwrap();
                    assert_eq!(nf, sf);
                    assert_eq!(
                        (ni, nj),
                        ((s * n as f32).floor() as i64, (t * n as f32).floor() as i64),
                        "face {face} ({i},{j})"
                    );
                }
            }
        }
    }
}
