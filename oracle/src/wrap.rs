//! Coordinate wrapping and texel selection: GL 4.6 §8.14.2 (ES 3.2 §8.14.2), Table 8.20 / 8.21,
//! and the legacy CLAMP mode of GL 2.1 §3.8.7.

use shadowcheck_model::Wrap;

/// Table 8.20: "mirror(a) returns a if a ≥ 0, and −(1 + a) otherwise."
fn mirror(a: i64) -> i64 {
    if a >= 0 {
        a
    } else {
        -(1 + a)
    }
}

/// Table 8.20 "Texel location wrap mode application". `coord` is an integer texel location.
/// CLAMP (legacy) has clamped the coordinate already (see [`prewrap`]); its texel locations then
/// behave as CLAMP_TO_BORDER for LINEAR and CLAMP_TO_EDGE for NEAREST (`nearest`).
pub fn wrap(mode: Wrap, coord: i64, size: i64, nearest: bool) -> i64 {
    match mode {
        // "CLAMP_TO_EDGE clamp(coord, 0, size − 1)"
        Wrap::ClampToEdge => coord.clamp(0, size - 1),
        // "CLAMP_TO_BORDER clamp(coord, −1, size)"
        Wrap::ClampToBorder => coord.clamp(-1, size),
        // "REPEAT coord mod size" (ES 3.2: "fmod(coord, size)", fmod(a,b) = a − b⌊a/b⌋)
        Wrap::Repeat => coord.rem_euclid(size),
        // "MIRRORED_REPEAT (size − 1) − mirror((coord mod (2 × size)) − size)" (the well-formed ES 3.2
        // Table 8.21 form; GL 4.6 prints unbalanced parentheses, contradiction `mirror-parens`).
        Wrap::MirroredRepeat => (size - 1) - mirror(coord.rem_euclid(2 * size) - size),
        // "MIRROR_CLAMP_TO_EDGE clamp(mirror(coord), 0, size − 1)"
        Wrap::MirrorClampToEdge => mirror(coord).clamp(0, size - 1),
        // GL 2.1 CLAMP: coordinates clamped to [0,1]; NEAREST then never leaves the image, LINEAR
        // blends with the border at the edges.
        Wrap::Clamp => {
            if nearest {
                coord.clamp(0, size - 1)
            } else {
                coord.clamp(-1, size)
            }
        }
    }
}

/// The legacy CLAMP mode clamps the unnormalized coordinate u to [0, size] before texel selection
/// (GL 2.1 §3.8.7: "CLAMP causes s, t, and r coordinates to be clamped to the range [0,1]").
pub fn prewrap(mode: Wrap, u: f64, size: i64) -> f64 {
    if mode == Wrap::Clamp {
        u.clamp(0.0, size as f64)
    } else {
        u
    }
}

/// f64 → i64 for texel locations; out-of-range values saturate, which no wrap mode distinguishes.
fn to_i(x: f64) -> i64 {
    x as i64
}

/// NEAREST: "i = wrap(⌊u′⌋)" (§8.14.2).
pub fn nearest(mode: Wrap, u: f64, size: i64) -> i64 {
    let u = prewrap(mode, u, size);
    wrap(mode, to_i(u.floor()), size, true)
}

/// LINEAR: "i0 = wrap(⌊u′ − 1/2⌋), i1 = wrap(⌊u′ − 1/2⌋ + 1), α = frac(u′ − 1/2)" (§8.14.2).
pub fn linear(mode: Wrap, u: f64, size: i64) -> (i64, i64, f64) {
    let u = prewrap(mode, u, size) - 0.5;
    let f = u.floor();
    let i = to_i(f);
    (
        wrap(mode, i, size, false),
        wrap(mode, i.saturating_add(1), size, false),
        u - f,
    )
}

/// Array layer under NEAREST, §8.14.2: "l = clamp(RNE(r), 0, d_s − 1)" with footnote 4:
/// "Implementations may instead round the texture layer using the nearly equivalent computation
/// ⌊value + 1/2⌋." Returns (RNE, floor) choices; they differ only at halves of even numbers (e.g.
/// 2.5 → 2 or 3). Under LINEAR the layer is [`layer_linear`].
pub fn layer(x: f64, n: i64) -> (i64, i64) {
    let rne = to_i(x.round_ties_even()).clamp(0, n - 1);
    let fl = to_i((x + 0.5).floor()).clamp(0, n - 1);
    (rne, fl)
}

/// Array layer under LINEAR, GL 4.6 §8.14.2: "For two-dimensional array textures, all texels are
/// obtained from layer l, where l = clamp(⌊r + 1/2⌋, 0, d_s − 1)" (1D arrays: "both texels are
/// obtained from layer l, where l = clamp(⌊t + 1/2⌋, 0, h_s − 1)"; ES 3.2: ⌊r + 0.5⌋). No RNE and no
/// footnote here: footnote 4 belongs to the NEAREST formula.
pub fn layer_linear(x: f64, n: i64) -> i64 {
    to_i((x + 0.5).floor()).clamp(0, n - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_8_20() {
        assert_eq!(wrap(Wrap::Repeat, -1, 4, true), 3);
        assert_eq!(wrap(Wrap::Repeat, 5, 4, true), 1);
        // mirrored repeat over 2×size: 0 1 2 3 | 3 2 1 0 | 0 1 ...
        let m: Vec<i64> = (-4..12)
            .map(|c| wrap(Wrap::MirroredRepeat, c, 4, true))
            .collect();
        assert_eq!(m, vec![3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1, 2, 3]);
        assert_eq!(wrap(Wrap::MirrorClampToEdge, -3, 4, true), 2);
        assert_eq!(wrap(Wrap::MirrorClampToEdge, 9, 4, true), 3);
        assert_eq!(wrap(Wrap::ClampToBorder, -7, 4, false), -1);
        assert_eq!(wrap(Wrap::ClampToBorder, 7, 4, false), 4);
    }

    #[test]
    fn linear_selection_and_weights() {
        // u = 1.0 on a 4-wide image: u − 1/2 = 0.5 → i0 = 0, i1 = 1, α = 0.5.
        assert_eq!(linear(Wrap::ClampToEdge, 1.0, 4), (0, 1, 0.5));
        // At the left edge with CLAMP_TO_EDGE both texels are texel 0.
        assert_eq!(linear(Wrap::ClampToEdge, 0.25, 4), (0, 0, 0.75));
        assert_eq!(linear(Wrap::ClampToBorder, 0.25, 4), (-1, 0, 0.75));
        assert_eq!(nearest(Wrap::ClampToEdge, 4.0, 4), 3);
        assert_eq!(nearest(Wrap::Clamp, 4.0, 4), 3);
    }

    #[test]
    fn layer_rounding_choices() {
        assert_eq!(layer(2.5, 8), (2, 3));
        assert_eq!(layer(1.5, 8), (2, 2));
        assert_eq!(layer(-3.0, 8), (0, 0));
        assert_eq!(layer(99.0, 8), (7, 7));
    }
}
