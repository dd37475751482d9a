//! Comparison, clamping, fail values, layouts, completeness, bypass, batch and faults end to end.

use super::*;

#[test]
fn nearest_selects_floor_texel_and_compares() {
    // 2x2 D16 texels (x fastest): [0.2, 0.8; 0.8, 0.2]. s = 0.75, t = 0.25 -> u = 1.5, v = 0.5 ->
    // texel (1, 0) = 0.8 (§8.14.2: i = ⌊u⌋). LEQUAL: Dref 0.5 ≤ 0.8 -> 1 (Table 8.23).
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        2,
        vec![d16(0.2), d16(0.8), d16(0.8), d16(0.2)],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.lookup.coord = [0.75, 0.25, 0.0, 1.0];
    assert_eq!(r(&c), 1.0);
    c.lookup.coord = [0.25, 0.25, 0.0, 1.0]; // texel (0,0) = 0.2 < 0.5 -> 0
    assert_eq!(r(&c), 0.0);
    c.sampler.compare_func = CompareFunc::Greater;
    assert_eq!(r(&c), 1.0);
}

#[test]
fn linear_pcf_weights() {
    // 2x2 texels [pass, fail; fail, pass] with LEQUAL and Dref 0.5: Dt = [1, 0, 0, 1].
    // s = 0.625, t = 0.375: u = 1.25, v = 0.75; u − ½ = 0.75 -> i0 = 0, i1 = 1, α = 0.75;
    // v − ½ = 0.25 -> j0 = 0, j1 = 1, β = 0.25 (§8.14.2, CLAMP_TO_EDGE).
    // r = (1−α)(1−β)·1 + α(1−β)·0 + (1−α)β·0 + αβ·1 = 0.25·0.75 + 0.75·0.25 = 0.375.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        2,
        vec![65535, 0, 0, 65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.lookup.coord = [0.625, 0.375, 0.0, 1.0];
    assert_eq!(r(&c), 0.375);
    // Same footprint on SGIX (compare before filtering by definition): TEXTURE_LEQUAL_R passes
    // where texel ≤ R, i.e. the other two texels: r = 0.75·0.75 + 0.25·0.25 = 0.625.
    c.spec = Spec::Sgix;
    c.api = vec![ApiPath::FixedFunction];
    c.sampler.compare_func = CompareFunc::LequalRSgix;
    assert_eq!(
        SoftUnit::new(Spec::Sgix)
            .sample(&c, ApiPath::FixedFunction)
            .unwrap(),
        [0.625, 0.625, 0.625, 1.0]
    );
}

#[test]
fn clamping_differs_by_spec_and_format() {
    // GL 4.6 §8.23.1: no clamp for D32F: Dref 1.5 vs Dt 1.0 (upload-clamped from 2.0) with LEQUAL fails.
    let c = float_case(Spec::Gl46, vec![2.0], CompareFunc::Lequal);
    let mut c = c;
    c.lookup.dref = 1.5;
    assert_eq!(r(&c), 0.0);
    // Fixed-point: Dref clamped to 1.0 ≤ Dt 1.0 passes.
    let mut c = case2d(
        Spec::Gl46,
        Format::D24,
        1,
        1,
        vec![(1 << 24) - 1],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.lookup.dref = 1.5;
    assert_eq!(r(&c), 1.0);
    // GEQUAL with Dref −0.5 vs Dt 0: D32F fails (−0.5 < 0), D16 clamps Dref to 0 and passes.
    let mut c = float_case(Spec::Gl46, vec![0.0], CompareFunc::Gequal);
    c.lookup.dref = -0.5;
    assert_eq!(r(&c), 0.0);
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![0],
        CompareFunc::Gequal,
        Filter::Nearest,
    );
    c.lookup.dref = -0.5;
    assert_eq!(r(&c), 1.0);
    // EXT_shadow_samplers always clamps: same as the fixed-point case.
    c.spec = Spec::Es2Ext;
    c.api = vec![ApiPath::Es100Ext];
    assert_eq!(r(&c), 1.0);
}

#[test]
fn border_depth_and_its_clamp() {
    // CLAMP_TO_BORDER, s = 1.5 -> i = ⌊3⌋ = 3 -> clamp(3, −1, 2) = 2 = w: border texel (§8.14.2),
    // whose depth is TEXTURE_BORDER_COLOR[0] = 1.5. D32F: no clamp, LESS 1.2 < 1.5 -> 1.
    let mut c = float_case(Spec::Gl46, vec![0.0, 0.0], CompareFunc::Less);
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.5, 0.0, 0.0, 0.0];
    c.lookup.coord = [1.5, 0.5, 0.0, 1.0];
    c.lookup.dref = 1.2;
    assert_eq!(r(&c), 1.0);
    // D16: Dt and Dref both clamp to 1.0, and 1 < 1 fails.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 0],
        CompareFunc::Less,
        Filter::Nearest,
    );
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.5, 0.0, 0.0, 0.0];
    c.lookup.coord = [1.5, 0.5, 0.0, 1.0];
    c.lookup.dref = 1.2;
    assert_eq!(r(&c), 0.0);
    // Half-border LINEAR footprint: s = 1.0 on 2 texels: u − ½ = 1.5 -> i0 = 1, i1 = 2 (border), α = 0.5.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 0],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.0, 0.0, 0.0, 0.0];
    c.lookup.coord = [1.0, 0.5, 0.0, 1.0];
    assert_eq!(r(&c), 0.5);
}

#[test]
fn ambient_and_fail_values() {
    // ARB_shadow_ambient: failing texels give TEXTURE_COMPARE_FAIL_VALUE_ARB. 2x1 [pass, fail]
    // at the midpoint (α = ½): r = ½·1 + ½·0.25 = 0.625, and LUMINANCE by default.
    let mut c = case2d(
        Spec::ArbAmbient,
        Format::D16,
        2,
        1,
        vec![65535, 0],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.sampler.fail_value = Some(0.25);
    assert_eq!(
        SoftUnit::new(Spec::ArbAmbient)
            .sample(&c, ApiPath::FixedFunction)
            .unwrap(),
        [0.625, 0.625, 0.625, 1.0]
    );
    // SGIX_shadow_ambient: SHADOW_AMBIENT_SGIX replaces 0.0 for a texel in shadow (test failed).
    let mut c = case2d(
        Spec::SgixAmbient,
        Format::D16,
        1,
        1,
        vec![65535],
        CompareFunc::LequalRSgix,
        Filter::Nearest,
    );
    c.sampler.fail_value = Some(0.4);
    assert_eq!(r(&c), 0.4); // texel 1.0 ≤ R 0.5 is false
    c.sampler.compare_func = CompareFunc::GequalRSgix;
    assert_eq!(r(&c), 1.0);
}

#[test]
fn layouts_per_api_path() {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![65535],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.api = vec![
        ApiPath::FixedFunction,
        ApiPath::ArbFp,
        ApiPath::Glsl120,
        ApiPath::Glsl130,
        ApiPath::GlslCore,
    ];
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Alpha);
    let got = SoftUnit::new(Spec::Gl46).sample_all(&c);
    let want = [
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
    ];
    for ((api, res), w) in got.into_iter().zip(want) {
        assert_eq!(res.unwrap(), w, "{api}");
    }
}

#[test]
fn incomplete_textures_return_zero() {
    // §8.17: a mipmap min filter with only level 0 of a 2x2 texture (p = 1) is incomplete;
    // §11.1.3.5: a shadow sampler returns 0.
    let c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        2,
        vec![65535; 4],
        CompareFunc::Lequal,
        Filter::LinearMipmapLinear,
    );
    assert_eq!(
        SoftUnit::new(Spec::Gl46)
            .sample(&c, ApiPath::GlslCore)
            .unwrap(),
        [0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(
        SoftUnit::new(Spec::Gl46)
            .sample(&c, ApiPath::FixedFunction)
            .unwrap(),
        [0.0, 0.0, 0.0, 1.0]
    );
    let u = SoftUnit::new(Spec::Gl46).with_fault(Fault::IncompleteNotZero);
    assert_eq!(
        u.sample(&c, ApiPath::GlslCore).unwrap(),
        [1.0, 0.0, 0.0, 1.0]
    );
    // ES 3.2 §8.17: sized depth, compare NONE, LINEAR -> incomplete.
    let mut c = case2d(
        Spec::Gles32,
        Format::D16,
        1,
        1,
        vec![65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.sampler.compare_mode = CompareMode::None;
    assert_eq!(
        SoftUnit::new(Spec::Gles32)
            .sample(&c, ApiPath::Es300)
            .unwrap(),
        [0.0, 0.0, 0.0, 1.0]
    );
    c.sampler.min_filter = Filter::Nearest;
    c.sampler.mag_filter = Filter::Nearest;
    assert_eq!(
        SoftUnit::new(Spec::Gles32)
            .sample(&c, ApiPath::Es300)
            .unwrap(),
        [1.0, 0.0, 0.0, 1.0]
    );
}

#[test]
fn colour_and_stencil_bypass_comparison() {
    // §8.23.1: a colour texture bypasses the comparison: r = 51/255 = 0.2.
    let mut c = case2d(
        Spec::Gl46,
        Format::R8,
        1,
        1,
        vec![51],
        CompareFunc::Never,
        Filter::Nearest,
    );
    assert_eq!(r(&c), 0.2);
    c.api = vec![ApiPath::FixedFunction];
    assert_eq!(
        SoftUnit::new(Spec::Gl46)
            .sample(&c, ApiPath::FixedFunction)
            .unwrap(),
        [0.2, 0.0, 0.0, 1.0]
    );
    // DEPTH_STENCIL with STENCIL_INDEX mode: r = St.
    let mut c = case2d(
        Spec::Gl46,
        Format::D24S8,
        1,
        1,
        vec![0],
        CompareFunc::Never,
        Filter::Nearest,
    );
    c.texture.levels[0].stencil = Some(vec![7]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    assert_eq!(r(&c), 7.0);
}

#[test]
fn projective_divide() {
    // s, t and Dref divided by q = 2: (1.5, 0.5) -> (0.75, 0.25) -> texel (1, 0); Dref 1.2 -> 0.6.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        2,
        vec![0, d16(0.6), 0, 0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.lookup = Lookup {
        coord: [1.5, 0.5, 0.0, 2.0],
        layer: 0.0,
        dref: 1.2,
        projective: true,
        lod: 0.0,
        bias: 0.0,
        offset: [0; 3],
        gather: None,
        delivery: Default::default(),
        stage: Default::default(),
    };
    // Dt = d16(0.6)/65535 = 39321/65535 = 0.6 exactly representable? 0.6*65535 = 39321 -> Dt = 0.6 (f32),
    // Dref = f32(1.2)/2 = f32(0.6): equal -> LEQUAL passes.
    assert_eq!(r(&c), 1.0);
    let u = SoftUnit::new(Spec::Gl46).with_fault(Fault::RefNotDividedByQ);
    assert_eq!(u.sample(&c, ApiPath::GlslCore).unwrap()[0], 0.0);
}

#[test]
fn nan_reference() {
    // D32F (no clamp): NaN ≠ Dt holds, NaN ≤ Dt does not.
    let mut c = float_case(Spec::Gl46, vec![0.5], CompareFunc::Notequal);
    c.lookup.dref = f64::NAN;
    assert_eq!(r(&c), 1.0);
    c.sampler.compare_func = CompareFunc::Lequal;
    assert_eq!(r(&c), 0.0);
}

#[test]
fn errors_name_what_the_spec_lacks() {
    let c = case2d(
        Spec::Arb,
        Format::D16,
        1,
        1,
        vec![0],
        CompareFunc::Less,
        Filter::Nearest,
    );
    assert!(matches!(
        SoftUnit::new(Spec::Arb).sample(&c, ApiPath::FixedFunction),
        Err(SoftError::CompareFunc { .. })
    ));
    let c = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![0],
        CompareFunc::Less,
        Filter::Nearest,
    );
    assert!(matches!(
        SoftUnit::new(Spec::Gl46).sample(&c, ApiPath::Es300),
        Err(SoftError::ApiPath { .. })
    ));
    assert!(matches!(
        SoftUnit::new(Spec::Gles32).sample(&c, ApiPath::Es300),
        Err(SoftError::SpecMismatch { .. })
    ));
}

#[test]
fn batch_matches_single_samples() {
    let mut a = case2d(
        Spec::Gl46,
        Format::D16,
        1,
        1,
        vec![65535],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    a.api = vec![ApiPath::GlslCore, ApiPath::FixedFunction];
    let b = case2d(
        Spec::Gles32,
        Format::D16,
        1,
        1,
        vec![0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    let mut out = Vec::new();
    SoftUnit::new(Spec::Gl46).sample_batch(&[a.clone(), b], &mut out);
    assert_eq!(out.len(), 3);
    assert_eq!(
        (out[0].case, out[0].api, out[0].rgba.clone()),
        (0, ApiPath::GlslCore, Ok([1.0, 0.0, 0.0, 1.0]))
    );
    assert_eq!(out[1].rgba, Ok([1.0, 1.0, 1.0, 1.0]));
    assert!(matches!(out[2].rgba, Err(SoftError::SpecMismatch { .. })));
    assert_eq!(
        out[1].rgba,
        SoftUnit::new(Spec::Gl46).sample(&a, ApiPath::FixedFunction)
    );
}

#[test]
fn raw_lookup_api() {
    let c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    let u = SoftUnit::new(Spec::Gl46);
    let tex = u.prepare_texture(&c).unwrap();
    let st = u.sampler_state(&c, &tex).unwrap();
    let mut coords = u.coords(c.texture.target, &c.lookup).unwrap();
    // s = 0.5 on 2 texels: α = ½ between a failing and a passing texel.
    assert_eq!(tex.lookup(&st, &coords), 0.5);
    coords.s = 0.75; // u − ½ = 1 -> both taps on texel 1
    assert_eq!(tex.lookup(&st, &coords), 1.0);
}

#[test]
fn filter_faults_change_results() {
    // 2x1 [fail, pass] (Dt 0, 1), s = 0.5: PCF gives ½; filter-then-compare compares Dt = ½ with
    // Dref ½ under LEQUAL -> 1; half-texel-off reads u = 1 -> i0 = 1, α = 0 -> 1.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.lookup.dref = 0.5;
    assert_eq!(r(&c), 0.5);
    let f = |fault| {
        SoftUnit::new(Spec::Gl46)
            .with_fault(fault)
            .sample(&c, ApiPath::GlslCore)
            .unwrap()[0]
    };
    assert_eq!(f(Fault::FilterThenCompare), 1.0);
    assert_eq!(f(Fault::PcfHalfTexelOff), 1.0);
    assert_eq!(f(Fault::LequalGequalSwapped), 0.5);
    assert_eq!(f(Fault::LinearAsNearest), 1.0);
}

#[test]
fn every_function_of_every_spec_end_to_end() {
    // Dt = 0.6 (D16 39321), references below / equal / above; expected r from Table 8.23 (GL 4.6),
    // Table 8.22 (ES 3.2), EXT_shadow_samplers / EXT_shadow_funcs / ARB_shadow tables (R vs Dt),
    // and SGIX_shadow (texel vs R). Ambient variants use fail value 0.25.
    use CompareFunc as C;
    let refs = [0.2, 0.6, 1.0];
    let core: [(C, [bool; 3]); 8] = [
        (C::Lequal, [true, true, false]),
        (C::Gequal, [false, true, true]),
        (C::Less, [true, false, false]),
        (C::Greater, [false, false, true]),
        (C::Equal, [false, true, false]),
        (C::Notequal, [true, false, true]),
        (C::Always, [true, true, true]),
        (C::Never, [false, false, false]),
    ];
    let sgix: [(C, [bool; 3]); 2] = [
        (C::LequalRSgix, [false, true, true]),
        (C::GequalRSgix, [true, true, false]),
    ];
    for spec in Spec::ALL.iter().copied() {
        let rows: Vec<(C, [bool; 3])> = match spec {
            Spec::Sgix | Spec::SgixAmbient => sgix.to_vec(),
            Spec::Arb | Spec::ArbAmbient => core[..2].to_vec(),
            _ => core.to_vec(),
        };
        let fail = if matches!(spec, Spec::SgixAmbient | Spec::ArbAmbient) {
            0.25
        } else {
            0.0
        };
        for (func, want) in rows {
            for (dref, pass) in refs.iter().zip(want) {
                let mut c = case2d(
                    spec,
                    Format::D16,
                    1,
                    1,
                    vec![d16(0.6)],
                    func,
                    Filter::Nearest,
                );
                c.sampler.fail_value = Some(0.25);
                c.lookup.dref = *dref;
                assert_eq!(
                    r(&c),
                    if pass { 1.0 } else { fail },
                    "{spec} {func} Dref {dref}"
                );
            }
        }
    }
}

#[test]
fn compare_none_returns_filtered_depth() {
    // §8.23.1: compare mode NONE -> r = Dt; LINEAR between Dt 0.2 and 0.6 at α = ½ -> 0.4;
    // fixed function with INTENSITY spreads it to all four channels.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![d16(0.2), d16(0.6)],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Intensity);
    let got = SoftUnit::new(Spec::Gl46)
        .sample(&c, ApiPath::FixedFunction)
        .unwrap();
    assert!(got.iter().all(|v| (v - 0.4).abs() < 1e-6), "{got:?}");
}

#[test]
fn footprint_reports_texels_weights_and_outcomes() {
    // The PCF case of `linear_pcf_weights`: α = 0.75, β = 0.25 over [1, 0; 0, 1] with LEQUAL 0.5.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        2,
        vec![65535, 0, 0, 65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.lookup.coord = [0.625, 0.375, 0.0, 1.0];
    let fp = SoftUnit::new(Spec::Gl46).footprint(&c).unwrap();
    assert_eq!(fp.dref, 0.5f32 as f64);
    type Row = (Option<[u32; 3]>, f64, Option<bool>, f64);
    let got: Vec<Row> = fp
        .texels
        .iter()
        .map(|t| (t.xyz, t.stored, t.pass, t.weight))
        .collect();
    assert_eq!(
        got,
        vec![
            (Some([0, 0, 0]), 65535.0, Some(true), 0.1875),
            (Some([1, 0, 0]), 0.0, Some(false), 0.5625),
            (Some([0, 1, 0]), 0.0, Some(false), 0.0625),
            (Some([1, 1, 0]), 65535.0, Some(true), 0.1875),
        ]
    );
    // Border texels have no location; trilinear weights include the level blend.
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.0, 0.0, 0.0, 0.0];
    c.lookup.coord[0] = 1.5;
    let fp = SoftUnit::new(Spec::Gl46).footprint(&c).unwrap();
    assert_eq!(fp.texels.len(), 1);
    assert_eq!(
        (fp.texels[0].xyz, fp.texels[0].dt, fp.texels[0].pass),
        (None, 1.0, Some(true))
    );
}
