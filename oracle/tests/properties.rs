//! Properties that hold for every case the oracle answers.

mod common;
use common::*;
use proptest::prelude::*;
use shadowcheck_model::*;
use shadowcheck_oracle::evaluate;
use shadowcheck_oracle::profile::PROFILES;

fn spec_with_eight() -> impl Strategy<Value = Spec> {
    prop_oneof![
        Just(Spec::Gl46),
        Just(Spec::Gles32),
        Just(Spec::ExtFuncs),
        Just(Spec::Es2Ext)
    ]
}

fn format_for(spec: Spec) -> Vec<Format> {
    match spec {
        Spec::Gl46 => vec![
            Format::D16,
            Format::D24,
            Format::D32,
            Format::D32f,
            Format::D24S8,
            Format::D32fS8,
            Format::DepthUnsized,
        ],
        Spec::Gles32 => vec![Format::D16, Format::D24, Format::D32f, Format::D24S8],
        Spec::Es2Ext => vec![Format::D16, Format::D24, Format::D24S8],
        _ => vec![Format::D16, Format::D24, Format::D32],
    }
}

fn any_case() -> impl Strategy<Value = Case> {
    let spec = prop_oneof![
        Just(Spec::Gl46),
        Just(Spec::Gles32),
        Just(Spec::ExtFuncs),
        Just(Spec::Es2Ext),
        Just(Spec::Arb),
        Just(Spec::ArbAmbient),
        Just(Spec::Sgix),
        Just(Spec::SgixAmbient)
    ];
    (
        spec,
        0usize..8,
        0usize..8,
        0usize..6,
        prop::collection::vec(0.0f64..=1.0, 16),
        (-0.25f64..1.25, -0.25f64..1.25),
        -0.5f64..1.5,
        0.0f64..1.0,
        -1.0f64..3.0,
        any::<bool>(),
    )
        .prop_map(|(spec, fi, fu, fl, vals, st, dref, fail, lod, border)| {
            let formats = match spec {
                Spec::Sgix | Spec::SgixAmbient => vec![Format::D16, Format::D24, Format::D32],
                Spec::Arb | Spec::ArbAmbient => vec![Format::D16, Format::D24],
                s => format_for(s),
            };
            let format = formats[fi % formats.len()];
            let funcs: Vec<CompareFunc> = match spec {
                Spec::Sgix | Spec::SgixAmbient => {
                    vec![CompareFunc::LequalRSgix, CompareFunc::GequalRSgix]
                }
                Spec::Arb | Spec::ArbAmbient => vec![CompareFunc::Lequal, CompareFunc::Gequal],
                _ => CompareFunc::CORE.to_vec(),
            };
            let filters = [
                Filter::Nearest,
                Filter::Linear,
                Filter::NearestMipmapNearest,
                Filter::LinearMipmapNearest,
                Filter::NearestMipmapLinear,
                Filter::LinearMipmapLinear,
            ];
            let filter = filters[fl];
            // A complete 4x4 mipmap: levels 4x4, 2x2, 1x1.
            let mut c = case2d(
                spec,
                format,
                funcs[fu % funcs.len()],
                filter,
                4,
                4,
                &vals,
                st,
                dref,
            );
            for (n, off) in [(2u32, 0usize), (1, 4)] {
                let v = &vals[off..off + (n * n) as usize];
                c.texture.levels.push(Level {
                    width: n,
                    height: n,
                    layers: 1,
                    depth: texels(format, v),
                    stencil: format.has_stencil().then(|| vec![0; (n * n) as usize]),
                });
            }
            c.lookup.lod = lod;
            if matches!(spec, Spec::ArbAmbient | Spec::SgixAmbient) {
                c.sampler.fail_value = Some(fail as f32);
            }
            if border && !matches!(spec, Spec::Es2Ext | Spec::Sgix | Spec::SgixAmbient) {
                c.sampler.wrap_s = Wrap::ClampToBorder;
                c.sampler.border = [vals[3] as f32, 0.0, 0.0, 0.0];
            }
            c
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Away from NaN, LESS = not GEQUAL and GREATER = not LEQUAL (for the spec value and for every texel).
    #[test]
    fn less_is_not_gequal_and_greater_is_not_lequal(spec in spec_with_eight(), fi in 0usize..8, dref in -2.0f64..2.0, dt in 0.0f64..=1.0) {
        let formats = format_for(spec);
        let f = formats[fi % formats.len()];
        let v = |func| value(&one(spec, f, func, dref, dt));
        prop_assert_eq!(v(CompareFunc::Less), 1.0 - v(CompareFunc::Gequal));
        prop_assert_eq!(v(CompareFunc::Greater), 1.0 - v(CompareFunc::Lequal));
        prop_assert_eq!(v(CompareFunc::Notequal), 1.0 - v(CompareFunc::Equal));
    }

    /// Every acceptance interval lies in [fail value, 1] and the strict set contains the spec value;
    /// the quality set contains the strict set.
    #[test]
    fn acceptance_is_in_range_contains_the_spec_value_and_quality_is_looser(c in any_case()) {
        let e = evaluate(&c).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let fail = c.sampler.fail_value.map(|f| (f as f64).clamp(0.0, 1.0)).unwrap_or(0.0);
        let lo = fail.min(0.0);
        for (p, acc) in &e.expect.accept {
            prop_assert!(!acc.0.is_empty(), "{p:?} empty");
            for i in &acc.0 {
                prop_assert!(i.lo >= lo.min(fail) - 1e-12 && i.hi <= 1.0 + 1e-12 && i.lo <= i.hi, "{p:?} {i:?} fail {fail}");
                if c.sampler.compare_mode == CompareMode::Compare {
                    prop_assert!(i.lo >= fail - 1e-12, "{p:?} {i:?} below fail {fail}");
                }
            }
            if let Some(v) = e.expect.spec_value {
                prop_assert!(acc.contains(v), "{p:?} {acc} lacks spec value {v}");
            }
        }
        // Each tier accepts at least what the one before it accepts.
        for w in PROFILES.windows(2) {
            let (a, b) = (&e.expect.accept[&w[0].profile], &e.expect.accept[&w[1].profile]);
            prop_assert!(a.is_subset_of(b), "{} {a} ⊄ {} {b}", w[0].profile, w[1].profile);
        }
        prop_assert_eq!(e.expect.layout.len(), c.api.len());
    }
}

fn wide_case() -> impl Strategy<Value = Case> {
    (
        (
            0usize..8,
            0usize..7,
            0usize..8,
            0usize..10,
            0usize..6,
            0usize..2,
        ),
        (0usize..6, 0usize..6, 1u32..5, 1u32..4, 0u32..3),
        prop::collection::vec(-0.5f64..1.5, 4),
        prop_oneof![Just(f64::NAN), Just(f64::INFINITY), -3.0f64..3.0],
        (-4.0f64..6.0, -3.0f64..3.0, any::<bool>(), -2.0f64..8.0),
        (0usize..7, 0u32..3),
    )
        .prop_map(
            |(
                (si, ti, fi, fu, fl, mode),
                (ws, wt, w, layers, nlev),
                coord,
                dref,
                (lod, bias, proj, layer),
                (api, base),
            )| {
                let spec = Spec::ALL[si];
                let rules = shadowcheck_oracle::rules::rules_for(spec);
                let target = rules.targets[ti % rules.targets.len()];
                let format = Format::ALL[fi];
                let func = CompareFunc::ALL[fu];
                let filter = Filter::ALL[fl];
                let (w, h, l) = match target {
                    Target::T1d => (w, 1, 1),
                    Target::T1dArray => (w, 1, layers),
                    Target::T2dArray => (w, w, layers),
                    Target::Cube => (w, w, 6),
                    Target::CubeArray => (w, w, 6 * layers),
                    _ => (w, w, 1),
                };
                let mut levels = Vec::new();
                for i in 0..=nlev {
                    let (lw, lh) = ((w >> i).max(1), if h == 1 { 1 } else { (h >> i).max(1) });
                    let n = (lw * lh * l) as usize;
                    let vals: Vec<f64> = (0..n).map(|k| (k as f64 * 0.37).fract()).collect();
                    levels.push(Level {
                        width: lw,
                        height: lh,
                        layers: l,
                        depth: texels(format, &vals),
                        stencil: format.has_stencil().then(|| vec![3; n]),
                    });
                }
                let mut s = Sampler::new(
                    if mode == 0 {
                        CompareMode::Compare
                    } else {
                        CompareMode::None
                    },
                    func,
                    filter,
                );
                s.wrap_s = rules.wraps[ws % rules.wraps.len()];
                s.wrap_t = rules.wraps[wt % rules.wraps.len()];
                s.border = [coord[3] as f32, 0.0, 0.0, 0.0];
                Case {
                    sweep: vec![],
                    id: "wide".into(),
                    spec,
                    api: vec![rules.apis[api % rules.apis.len()]],
                    texture: Texture {
                        target,
                        format,
                        base_level: base,
                        levels,
                    },
                    sampler: s,
                    lookup: Lookup {
                        coord: [
                            coord[0],
                            coord[1],
                            coord[2],
                            if proj { coord[3] + 2.0 } else { 1.0 },
                        ],
                        layer,
                        dref,
                        projective: proj,
                        lod,
                        bias,
                        offset: [0; 3],
                        gather: None,
                        delivery: Default::default(),
                        stage: Default::default(),
                    },
                    expect: None,
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    /// Any structurally valid case gets an answer or an error, never a panic; answers keep their invariants.
    #[test]
    fn any_valid_case_is_answered(c in wide_case()) {
        if shadowcheck_model::validate::validate(&c).is_ok() {
            if let Ok(e) = evaluate(&c) {
                let strict = &e.expect.accept[&Profile::strictest()];
                prop_assert!(!strict.0.is_empty());
                for w in PROFILES.windows(2) {
                    let (a, b) = (&e.expect.accept[&w[0].profile], &e.expect.accept[&w[1].profile]);
                    prop_assert!(a.is_subset_of(b), "{} {a} ⊄ {} {b}", w[0].profile, w[1].profile);
                }
                if let Some(v) = e.expect.spec_value {
                    prop_assert!(strict.contains(v), "{strict} lacks {v}");
                }
                prop_assert_eq!(e.expect.layout.len(), c.api.len());
            }
        }
    }
}
