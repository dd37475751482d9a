//! Cube map face selection (GL 4.6 §8.13, Table 8.19) and seamless filtering (§8.13.1).

/// Faces in GL order: +X, −X, +Y, −Y, +Z, −Z (layer index within a cube).
pub const FACE_NAMES: [&str; 6] = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"];

/// Table 8.19 "Selection of cube map images based on major axis direction":
/// returns (sc, tc, ma) for `face` and direction r.
fn sc_tc_ma(face: usize, r: [f64; 3]) -> (f64, f64, f64) {
    let [rx, ry, rz] = r;
    match face {
        0 => (-rz, -ry, rx), // +rx  TEXTURE_CUBE_MAP_POSITIVE_X  −rz −ry rx
        1 => (rz, -ry, rx),  // −rx  TEXTURE_CUBE_MAP_NEGATIVE_X   rz −ry rx
        2 => (rx, rz, ry),   // +ry  TEXTURE_CUBE_MAP_POSITIVE_Y   rx  rz ry
        3 => (rx, -rz, ry),  // −ry  TEXTURE_CUBE_MAP_NEGATIVE_Y   rx −rz ry
        4 => (rx, -ry, rz),  // +rz  TEXTURE_CUBE_MAP_POSITIVE_Z   rx −ry rz
        _ => (-rx, -ry, rz), // −rz  TEXTURE_CUBE_MAP_NEGATIVE_Z  −rx −ry rz
    }
}

/// "s = 1/2 (sc/|ma| + 1), t = 1/2 (tc/|ma| + 1)" on `face`.
pub fn face_st(face: usize, r: [f64; 3]) -> (f64, f64) {
    let (sc, tc, ma) = sc_tc_ma(face, r);
    let m = ma.abs();
    (0.5 * (sc / m + 1.0), 0.5 * (tc / m + 1.0))
}

/// The faces the direction selects: "the largest magnitude coordinate direction (the major axis
/// direction). If two or more coordinates have the identical magnitude, the implementation may define
/// the rule to disambiguate this situation." Every tied face is returned, x before y before z; the
/// first is the one the oracle's spec value uses. Empty for the zero vector (or NaN).
pub fn faces(r: [f64; 3]) -> Vec<usize> {
    let m = r.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if m.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || r.iter().any(|v| v.is_nan()) {
        return Vec::new();
    }
    (0..3)
        .filter(|&a| r[a].abs() == m)
        .map(|a| 2 * a + usize::from(r[a] < 0.0))
        .collect()
}

/// Inverse of Table 8.19 with |ma| = 1: the direction through face coordinates (sc, tc).
fn direction(face: usize, sc: f64, tc: f64) -> [f64; 3] {
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

/// Seamless filtering (§8.13.1): "If a texture sample location would lie in the texture border in
/// either u or v, instead select the corresponding texel from the appropriate neighboring face."
/// Maps the texel (i, j) just outside `face` (size n) through its centre's direction to the face and
/// texel it lands on. `None` for a corner (outside in both u and v): "there is no unique neighboring
/// face" and the implementation constructs that texel.
pub fn neighbour(face: usize, i: i64, j: i64, n: i64) -> Option<(usize, i64, i64)> {
    let out_i = i < 0 || i >= n;
    let out_j = j < 0 || j >= n;
    if out_i && out_j {
        return None;
    }
    if !out_i && !out_j {
        return Some((face, i, j));
    }
    let nf = n as f64;
    let sc = 2.0 * (i as f64 + 0.5) / nf - 1.0;
    let tc = 2.0 * (j as f64 + 0.5) / nf - 1.0;
    let d = direction(face, sc, tc);
    let f = *faces(d).first()?;
    let (s, t) = face_st(f, d);
    let x = ((s * nf).floor() as i64).clamp(0, n - 1);
    let y = ((t * nf).floor() as i64).clamp(0, n - 1);
    Some((f, x, y))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn major_axis_and_ties() {
        assert_eq!(faces([1.0, 0.5, -0.2]), vec![0]);
        assert_eq!(faces([0.1, -0.9, 0.2]), vec![3]);
        assert_eq!(faces([0.0, 0.0, -2.0]), vec![5]);
        assert_eq!(faces([1.0, -1.0, 0.0]), vec![0, 3]);
        assert!(faces([0.0; 3]).is_empty());
    }

    #[test]
    fn table_8_19_coordinates() {
        // +X face, direction (1, 0, 0) hits the centre.
        assert_eq!(face_st(0, [1.0, 0.0, 0.0]), (0.5, 0.5));
        // +X: sc = −rz: rz = −0.5 → s = 0.75; tc = −ry: ry = 0.5 → t = 0.25.
        assert_eq!(face_st(0, [1.0, 0.5, -0.5]), (0.75, 0.25));
        // −Z: sc = −rx.
        assert_eq!(face_st(5, [0.5, 0.0, -1.0]), (0.25, 0.5));
    }

    #[test]
    fn seamless_neighbour_is_the_adjacent_edge_texel() {
        // Left of +Z (sc < −1, i.e. towards −X): lands on −X's right edge column, same row.
        for j in 0..4 {
            assert_eq!(neighbour(4, -1, j, 4), Some((1, 3, j)));
        }
        // Every in-face texel maps to itself; every edge neighbour lands on another face's edge.
        for f in 0..6 {
            for k in 0..4 {
                for (i, j) in [(-1, k), (4, k), (k, -1), (k, 4)] {
                    let (g, x, y) = neighbour(f, i, j, 4).unwrap();
                    assert_ne!(g, f);
                    assert!(x == 0 || x == 3 || y == 0 || y == 3);
                }
            }
        }
        assert_eq!(neighbour(2, -1, -1, 4), None);
    }
}
