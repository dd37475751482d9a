//! Targets, wrapping, level selection and the contradictions' other readings, through `evaluate`.

mod common;
use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{contradictions, evaluate_reading};

fn cube_case(spec: Spec, faces: [f64; 6], dir: [f64; 3], dref: f64) -> Case {
    let mut c = one(spec, Format::D16, CompareFunc::Lequal, dref, 0.0);
    c.texture.target = Target::Cube;
    c.texture.levels[0].layers = 6;
    c.texture.levels[0].depth = texels(Format::D16, &faces);
    c.lookup.coord = [dir[0], dir[1], dir[2], 1.0];
    c
}

#[test]
fn cube_face_selection_table_8_19() {
    // One value per face; Dref 0.5 passes LEQUAL only on faces holding 1.
    for (i, dir) in [
        [1.0, 0.2, 0.1],
        [-1.0, 0.2, 0.1],
        [0.1, 1.0, 0.2],
        [0.1, -1.0, 0.2],
        [0.1, 0.2, 1.0],
        [0.1, 0.2, -1.0],
    ]
    .iter()
    .enumerate()
    {
        let mut f = [0.0; 6];
        f[i] = 1.0;
        assert_eq!(value(&cube_case(Spec::Gl46, f, *dir, 0.5)), 1.0, "face {i}");
    }
    // A tie between +X and +Y: the implementation's rule decides, both faces accepted.
    let e = eval(&cube_case(
        Spec::Gl46,
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        0.5,
    ));
    let acc = &e.expect.accept[&Profile::Strict];
    assert!(acc.contains(0.0) && acc.contains(1.0));
}

#[test]
fn array_layer_rounding() {
    let mut c = one(Spec::Gl46, Format::D16, CompareFunc::Lequal, 0.5, 0.0);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0].layers = 4;
    c.texture.levels[0].depth = texels(Format::D16, &[0.0, 0.0, 1.0, 0.0]);
    c.lookup.coord = [0.5, 0.5, 1.6, 1.0];
    assert_eq!(value(&c), 1.0); // RNE(1.6) = 2
    c.lookup.coord[2] = 2.5; // RNE → 2, ⌊2.5 + 1/2⌋ → 3 (footnote 4): either
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(1.0));
    assert!(e.expect.accept[&Profile::Strict].contains(0.0));
    c.lookup.coord[2] = 9.0; // clamped to the last layer
    assert_eq!(value(&c), 0.0);
}

#[test]
fn wrap_modes_pick_the_texel_of_table_8_20() {
    // 4x1 texture, only texel 3 passes (holds 1.0); s = −0.125 → u = −0.5, ⌊u⌋ = −1.
    let mk = |w: Wrap| {
        let mut c = case2d(
            Spec::Gl46,
            Format::D16,
            CompareFunc::Lequal,
            Filter::Nearest,
            4,
            1,
            &[0.0, 0.0, 0.0, 1.0],
            (-0.125, 0.5),
            0.5,
        );
        c.sampler.wrap_s = w;
        c
    };
    assert_eq!(value(&mk(Wrap::Repeat)), 1.0); // −1 mod 4 = 3
    assert_eq!(value(&mk(Wrap::ClampToEdge)), 0.0); // texel 0
    assert_eq!(value(&mk(Wrap::MirroredRepeat)), 0.0); // mirror → texel 0
    let mut b = mk(Wrap::ClampToBorder);
    b.sampler.border = [1.0, 0.0, 0.0, 0.0];
    assert_eq!(value(&b), 1.0); // the border texel
}

#[test]
fn texel_offsets_are_added_to_u_before_wrapping_in_the_selected_levels_texels() {
    // (8.10): u = w·s + δu. 4x1, only texel 3 passes; s = 0.375 → u = 1.5 (texel 1).
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Lequal,
        Filter::Nearest,
        4,
        1,
        &[0.0, 0.0, 0.0, 1.0],
        (0.375, 0.5),
        0.5,
    );
    assert_eq!(value(&c), 0.0);
    c.lookup.offset = [2, 0, 0]; // u = 3.5: texel 3
    assert_eq!(value(&c), 1.0);
    c.lookup.offset = [-2, 0, 0]; // u = -0.5: CLAMP_TO_EDGE texel 0; REPEAT wraps to texel 3
    assert_eq!(value(&c), 0.0);
    c.sampler.wrap_s = Wrap::Repeat;
    assert_eq!(value(&c), 1.0);
    // §8.14.3: level d's (u, v) "as in equation 8.10, with w_s, h_s, d_s" of level d, so the
    // offset counts level-d texels. Level 1 (2x2 of a 4x4 chain) = [0, 1 / 0, 1], s = 0.1:
    // u = 0.2 + 1 = 1.2 reads texel 1 (pass); one base texel (½ level-1 texel) would stay on 0.
    let mut m = case2d(
        Spec::Gles32,
        Format::D16,
        CompareFunc::Lequal,
        Filter::NearestMipmapNearest,
        4,
        4,
        &[0.0; 16],
        (0.1, 0.1),
        0.5,
    );
    for (w, vals) in [(2u32, vec![0.0, 1.0, 0.0, 1.0]), (1, vec![0.0])] {
        m.texture.levels.push(Level {
            width: w,
            height: w,
            layers: 1,
            depth: texels(Format::D16, &vals),
            stencil: None,
        });
    }
    m.lookup.lod = 1.0;
    assert_eq!(value(&m), 0.0);
    m.lookup.offset = [1, 0, 0];
    assert_eq!(value(&m), 1.0);
}

#[test]
fn mipmap_level_selection_and_blend() {
    // 4x4 base (all 0), 2x2 level 1 (all 1), 1x1 level 2 (0). Dref 0.5, LEQUAL passes on level 1 only.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Lequal,
        Filter::NearestMipmapNearest,
        4,
        4,
        &[0.0; 16],
        (0.5, 0.5),
        0.5,
    );
    c.texture.levels.push(Level {
        width: 2,
        height: 2,
        layers: 1,
        depth: texels(Format::D16, &[1.0; 4]),
        stencil: None,
    });
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: texels(Format::D16, &[0.0]),
        stencil: None,
    });
    c.lookup.lod = 1.0;
    assert_eq!(value(&c), 1.0);
    c.lookup.lod = 0.25; // nearest(0.25) = level 0
    assert_eq!(value(&c), 0.0);
    c.lookup.lod = 0.5; // preferred ⌈1⌉−1 = 0, alternative ⌊1⌋ = 1
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.0));
    assert!(e.expect.accept[&Profile::Strict].contains(1.0));
    // NEAREST_MIPMAP_LINEAR at λ = 1.25: 0.75·level1 + 0.25·level2 = 0.75.
    c.sampler.min_filter = Filter::NearestMipmapLinear;
    c.lookup.lod = 1.25;
    assert_eq!(value(&c), 0.75);
    // TEXTURE_MAX_LEVEL 1 makes q = 1: λ = 1.25 ≥ q → level 1 alone.
    c.sampler.max_level = Some(1);
    assert_eq!(value(&c), 1.0);
}

#[test]
fn seamless_cube_in_es_and_per_face_wrap_in_gl() {
    // 2x2 faces; +Z face all 0, −X face all 1. LINEAR lookup near the left edge of +Z.
    let mut vals = vec![0.0; 24];
    for v in &mut vals[4..8] {
        *v = 1.0; // −X
    }
    let mut c = one(Spec::Gles32, Format::D16, CompareFunc::Lequal, 0.5, 0.0);
    c.api = vec![ApiPath::Es300];
    c.texture.target = Target::Cube;
    c.texture.levels[0] = Level {
        width: 2,
        height: 2,
        layers: 6,
        depth: texels(Format::D16, &vals),
        stencil: None,
    };
    c.sampler = Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Linear);
    // +Z, sc = rx = −0.75 → s = 0.125, u = 0.25: α = 0.75 between the −X neighbour and texel 0.
    c.lookup.coord = [-0.75, 0.0, 1.0, 1.0];
    assert_eq!(value(&c), 0.25);
    // GL 4.6 (seamless disabled by default): CLAMP_TO_EDGE within +Z → 0.
    c.spec = Spec::Gl46;
    c.api = vec![ApiPath::GlslCore];
    assert_eq!(value(&c), 0.0);
}

#[test]
fn contradictions_show_the_other_reading() {
    // An SGIX LEQUAL case shows ARB_shadow issue 2's reading: texel 0.3, R 0.5 gives 1, the other 0.
    let c = one(Spec::Sgix, Format::D24, CompareFunc::LequalRSgix, 0.5, 0.3);
    let ids: Vec<&str> = contradictions::touching(&c).iter().map(|x| x.id).collect();
    assert!(ids.contains(&"sgix-lequal-direction"));
    let alt = evaluate_reading(&c, "sgix-lequal-direction")
        .unwrap()
        .unwrap();
    assert_eq!(alt.expect.spec_value, Some(0.0));
    // SGIX_shadow_ambient's overview reading puts the ambient value on a pass.
    let mut a = one(
        Spec::SgixAmbient,
        Format::D16,
        CompareFunc::LequalRSgix,
        0.5,
        0.3,
    );
    a.sampler.fail_value = Some(0.25);
    assert_eq!(value(&a), 1.0);
    assert_eq!(
        evaluate_reading(&a, "sgix-ambient")
            .unwrap()
            .unwrap()
            .expect
            .spec_value,
        Some(0.25)
    );
    // EXT_shadow_samplers GREATER at equality: either under the printed rows (encoded), 0 under
    // EXT_shadow_funcs' row (the other reading).
    let g = one(Spec::Es2Ext, Format::D16, CompareFunc::Greater, 1.0, 1.0);
    assert!(eval(&g).expect.accept[&Profile::Strict].contains(1.0));
    let alt = evaluate_reading(&g, "es2-greater-row").unwrap().unwrap();
    assert_eq!(alt.expect.spec_value, Some(0.0));
    assert!(!alt.expect.accept[&Profile::Strict].contains(1.0));
    // GL 4.6 D32F under an always-clamp reading: ref 1.5 vs 1.0 passes.
    let d = one(Spec::Gl46, Format::D32f, CompareFunc::Lequal, 1.5, 1.0);
    assert_eq!(
        evaluate_reading(&d, "ref-clamp")
            .unwrap()
            .unwrap()
            .expect
            .spec_value,
        Some(1.0)
    );
    // Explain text names both.
    let text = shadowcheck_oracle::explain::render(&c, &shadowcheck_oracle::evaluate(&c));
    assert!(
        text.contains("R_LEQUAL_TEXTURE") && text.contains("under the other reading: r = 0"),
        "{text}"
    );
}

#[test]
fn footprint_reports_texels_weights_and_passes() {
    let c = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Lequal,
        Filter::Linear,
        2,
        2,
        &[0.25, 0.75, 0.75, 1.0],
        (0.5, 0.5),
        0.5,
    );
    let e = eval(&c);
    assert_eq!(e.footprint.texels.len(), 4);
    let w: f64 = e.footprint.texels.iter().map(|t| t.weight).sum();
    assert_eq!(w, 1.0);
    let passes: Vec<Option<bool>> = e.footprint.texels.iter().map(|t| t.pass).collect();
    assert_eq!(
        passes,
        vec![Some(false), Some(true), Some(true), Some(true)]
    );
    assert_eq!(e.footprint.texels[0].stored, 16384.0);
}
