//! Texel addressing end to end: mip levels, cube faces, array layers, rectangles, wrap modes.

use super::*;

fn mip_case(filter: Filter, values: [u32; 3]) -> Case {
    // 4x4 -> 2x2 -> 1x1 with every texel of level i equal to values[i].
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        4,
        4,
        vec![values[0]; 16],
        CompareFunc::Lequal,
        filter,
    );
    c.texture.levels.push(Level {
        width: 2,
        height: 2,
        layers: 1,
        depth: Texels::Unorm(vec![values[1]; 4]),
        stencil: None,
    });
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: Texels::Unorm(vec![values[2]; 1]),
        stencil: None,
    });
    c
}

#[test]
fn mip_level_selection_and_blend() {
    // Only level 1 passes (Dt 1.0 vs Dref 0.5).
    let mut c = mip_case(Filter::NearestMipmapNearest, [0, 65535, 0]);
    c.lookup.lod = 1.0; // d = ⌈1 + ½⌉ − 1 = 1
    assert_eq!(r(&c), 1.0);
    c.lookup.lod = 0.5; // ⌈1.0⌉ − 1 = 0 (the preferred nearest(λ) rounds a half down)
    assert_eq!(r(&c), 0.0);
    c.lookup.lod = 1.4;
    assert_eq!(r(&c), 1.0);
    c.lookup.lod = 0.0; // magnification: level base
    assert_eq!(r(&c), 0.0);
    // Bias and clamp: λ = 0 + 0.75 + 0.5 = 1.25 -> level 1; max_lod 0.4 -> λ = 0.4 -> level 0.
    c.sampler.lod_bias = 0.75;
    c.lookup.bias = 0.5;
    assert_eq!(r(&c), 1.0);
    c.sampler.max_lod = 0.4;
    assert_eq!(r(&c), 0.0);
    // TEXTURE_MAX_LEVEL 0 makes q = 0: λ = 1 stays at level 0.
    let mut c = mip_case(Filter::NearestMipmapNearest, [0, 65535, 0]);
    c.sampler.max_level = Some(0);
    c.lookup.lod = 1.0;
    assert_eq!(r(&c), 0.0);
    // Trilinear: λ = 0.25 blends level 0 (fails) and 1 (passes): 0.75·0 + 0.25·1.
    let mut c = mip_case(Filter::LinearMipmapLinear, [0, 65535, 0]);
    c.lookup.lod = 0.25;
    assert_eq!(r(&c), 0.25);
    c.lookup.lod = 1.5; // levels 1 and 2: 0.5·1 + 0.5·0
    assert_eq!(r(&c), 0.5);
}

fn cube_case(spec: Spec, n: u32, faces: [u32; 6]) -> Case {
    let mut texels = Vec::new();
    for f in faces {
        texels.extend(std::iter::repeat_n(f, (n * n) as usize));
    }
    let mut c = case2d(
        spec,
        Format::D16,
        n,
        n,
        vec![],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.texture.target = Target::Cube;
    c.texture.levels[0] = Level {
        width: n,
        height: n,
        layers: 6,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c
}

#[test]
fn cube_face_selection() {
    // Only face k passes; the direction picks face k (Table 8.19).
    let dirs = [
        [1.0, 0.2, 0.1],
        [-1.0, 0.2, 0.1],
        [0.1, 1.0, 0.2],
        [0.1, -1.0, 0.2],
        [0.1, 0.2, 1.0],
        [0.1, 0.2, -1.0],
    ];
    for (k, d) in dirs.iter().enumerate() {
        let mut faces = [0; 6];
        faces[k] = 65535;
        let mut c = cube_case(Spec::Gl46, 2, faces);
        c.lookup.coord = [d[0], d[1], d[2], 1.0];
        assert_eq!(r(&c), 1.0, "face {k}");
    }
}

#[test]
fn seamless_cube_edge_in_es() {
    // 2x2 faces; +X passes nowhere, +Z passes everywhere. Direction (1, 0, 0.9) hits +X at
    // s = ½(−0.9 + 1) = 0.05 -> u = 0.1, u − ½ = −0.4 -> i0 = −1 (past the +Z edge), α = 0.6.
    // t = ½: v − ½ = 0.5 -> j0 = 0, j1 = 1, β = 0.5. ES (seamless): column i0 comes from +Z and
    // passes: r = (1 − α) = 0.4. GL (not seamless, CLAMP_TO_EDGE): all texels on +X: r = 0.
    let mut c = cube_case(Spec::Gles32, 2, [0, 0, 0, 0, 65535, 0]);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c.lookup.coord = [1.0, 0.0, 0.9, 1.0];
    let got = r(&c);
    assert!((got - 0.4).abs() < 1e-6, "{got}");
    c.spec = Spec::Gl46;
    c.api = vec![ApiPath::GlslCore];
    assert_eq!(r(&c), 0.0);
}

#[test]
fn array_layer_rounding() {
    // 2D array, 3 layers of 1x1; only layer 2 passes. layer = clamp(⌊r + ½⌋, 0, 2).
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.texture.target = Target::T2dArray;
    c.texture.levels[0] = Level {
        width: 1,
        height: 1,
        layers: 3,
        depth: Texels::Unorm(vec![0, 0, 65535]),
        stencil: None,
    };
    for (layer, want) in [(1.49, 0.0), (1.5, 1.0), (7.0, 1.0), (-3.0, 0.0)] {
        c.lookup.coord = [0.5, 0.5, layer, 1.0];
        assert_eq!(r(&c), want, "layer {layer}");
    }
}

#[test]
fn rectangle_uses_unnormalized_coordinates() {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        4,
        1,
        vec![0, 0, 65535, 0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.texture.target = Target::Rect;
    c.lookup.coord = [2.5, 0.5, 0.0, 1.0]; // u = s = 2.5 -> texel 2
    assert_eq!(r(&c), 1.0);
}

#[test]
fn one_d_array_and_cube_array_layers() {
    // 1D array: layer from t (§8.14.2), LINEAR along s only: 2 texels [fail, pass] per layer,
    // layer 1 = [pass, pass]. s = ½ -> α = ½.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.texture.target = Target::T1dArray;
    c.texture.levels[0] = Level {
        width: 2,
        height: 1,
        layers: 2,
        depth: Texels::Unorm(vec![0, 65535, 65535, 65535]),
        stencil: None,
    };
    c.lookup.coord = [0.5, 0.0, 0.0, 1.0];
    assert_eq!(r(&c), 0.5);
    c.lookup.coord = [0.5, 0.7, 0.0, 1.0]; // ⌊0.7 + ½⌋ = 1
    assert_eq!(r(&c), 1.0);
    // Cube array with 2 cubes; only cube 1's +Z face passes. Cube index from lookup.layer.
    let mut texels = vec![0u32; 12];
    texels[6 + 4] = 65535;
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.texture.target = Target::CubeArray;
    c.texture.levels[0] = Level {
        width: 1,
        height: 1,
        layers: 12,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c.lookup.coord = [0.0, 0.0, 1.0, 1.0];
    c.lookup.layer = 0.0;
    assert_eq!(r(&c), 0.0);
    c.lookup.layer = 0.5;
    assert_eq!(r(&c), 1.0);
    c.lookup.layer = 9.0; // clamped to the last cube
    assert_eq!(r(&c), 1.0);
}

#[test]
fn wrap_modes_end_to_end() {
    // 4x1 [pass, fail, fail, fail] (only texel 0 passes), NEAREST, various s.
    let mk = |wrap: Wrap, s: f64| {
        let mut c = case2d(
            Spec::Gl46,
            Format::D16,
            4,
            1,
            vec![65535, 0, 0, 0],
            CompareFunc::Lequal,
            Filter::Nearest,
        );
        c.sampler.wrap_s = wrap;
        c.lookup.coord[0] = s;
        r(&c)
    };
    assert_eq!(mk(Wrap::Repeat, 1.1), 1.0); // u = 4.4 -> 4 mod 4 = 0
    assert_eq!(mk(Wrap::ClampToEdge, 1.1), 0.0); // -> 3
    assert_eq!(mk(Wrap::MirroredRepeat, 1.9), 1.0); // u = 7.6 -> 7: (3) − mirror(7 − 4) = 0
    assert_eq!(mk(Wrap::MirrorClampToEdge, -0.1), 1.0); // u = −0.4 -> −1: mirror = 0
    assert_eq!(mk(Wrap::MirrorClampToEdge, -0.3), 0.0); // u = −1.2 -> −2: mirror = 1
                                                        // Legacy CLAMP exists only in the compatibility profile: an error on the core path,
                                                        // s clamped to 0 on the fixed-function path.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        4,
        1,
        vec![65535, 0, 0, 0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.sampler.wrap_s = Wrap::Clamp;
    c.lookup.coord[0] = -5.0;
    assert!(matches!(
        SoftUnit::new(Spec::Gl46).sample(&c, ApiPath::GlslCore),
        Err(SoftError::Wrap { .. })
    ));
    assert_eq!(
        SoftUnit::new(Spec::Gl46)
            .sample(&c, ApiPath::FixedFunction)
            .unwrap(),
        [1.0; 4]
    );
}

#[test]
fn footprint_weights_sum_to_one() {
    // Trilinear between two levels, and a seamless cube corner (three texels share the fourth's weight).
    let mut c = mip_case(Filter::LinearMipmapLinear, [0, 65535, 0]);
    c.lookup.lod = 0.25;
    c.lookup.coord = [0.3, 0.6, 0.0, 1.0];
    let fp = SoftUnit::new(Spec::Gl46).footprint(&c).unwrap();
    assert_eq!(fp.texels.len(), 8);
    let sum: f64 = fp.texels.iter().map(|t| t.weight).sum();
    assert!((sum - 1.0).abs() < 1e-6, "{sum}");
    assert!(
        fp.texels[..4].iter().all(|t| t.level == 0) && fp.texels[4..].iter().all(|t| t.level == 1)
    );
    let mut c = cube_case(Spec::Gles32, 2, [0, 0, 0, 0, 65535, 0]);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c.lookup.coord = [1.0, 0.9, 0.9, 1.0]; // near the +X/+Y/+Z corner
    let fp = SoftUnit::new(Spec::Gles32).footprint(&c).unwrap();
    assert_eq!(fp.texels.len(), 3);
    let sum: f64 = fp.texels.iter().map(|t| t.weight).sum();
    assert!((sum - 1.0).abs() < 1e-6, "{sum}");
}
