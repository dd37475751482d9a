//! GL core profile (`core` path) on every driver, through EGL and OSMesa, against values derived
//! from GL 4.6 §8.23.1 (Table 8.23) and §8.14 (level selection).
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

/// GL 4.6 Table 8.23: the comparison result for Dref vs Dt.
fn table_8_23(f: CompareFunc, dref: f64, dt: f64) -> f64 {
    let pass = match f {
        CompareFunc::Never => false,
        CompareFunc::Always => true,
        CompareFunc::Less => dref < dt,
        CompareFunc::Lequal => dref <= dt,
        CompareFunc::Greater => dref > dt,
        CompareFunc::Gequal => dref >= dt,
        CompareFunc::Equal => dref == dt,
        CompareFunc::Notequal => dref != dt,
        _ => unreachable!(),
    };
    if pass {
        1.0
    } else {
        0.0
    }
}

fn compare_cases(spec: Spec, api: ApiPath, targets: &[Target]) -> Vec<(Case, f64)> {
    let c = 32768u32;
    let dt = c as f64 / 65535.0;
    let mut v = Vec::new();
    // A D16 texel c = 32768 with LEQUAL: refs just below / above c/65535 give 1.0 / 0.0.
    for &t in targets {
        for (d, want) in [(dt - 1e-4, 1.0), (dt + 1e-4, 0.0)] {
            v.push((
                d16_case(&format!("{t}/lequal/{d}"), spec, &[api], t, c, d),
                want,
            ));
        }
    }
    for f in CompareFunc::CORE {
        for d in [0.25, 0.75] {
            let mut k = d16_case(&format!("2d/{f}/{d}"), spec, &[api], Target::T2d, c, d);
            k.sampler.compare_func = f;
            v.push((k, table_8_23(f, d, dt)));
        }
    }
    v
}

const ALL_TARGETS: [Target; 7] = [
    Target::T1d,
    Target::T2d,
    Target::Rect,
    Target::Cube,
    Target::T1dArray,
    Target::T2dArray,
    Target::CubeArray,
];

#[test]
fn core_compare_table_and_every_target() {
    for b in backends("core", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        assert_eq!(s.caps("specs"), vec!["gl46"], "{b}");
        assert_eq!(s.caps("api"), vec!["core"], "{b}");
        let cases = compare_cases(Spec::Gl46, ApiPath::GlslCore, &ALL_TARGETS);
        let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
        let answers = s.run(&cs);
        for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
            let rgba = Session::rgba(a, ApiPath::GlslCore);
            assert_eq!(rgba[0], w, "{b} {}: {a}", c.id);
            // GL 4.6 §8.23: the float result is (r, 0, 0, 1) before the swizzle.
            assert_eq!(&rgba[1..], &[0.0, 0.0, 1.0], "{b} {}", c.id);
            // Desktop GL reads back what was stored: the uploaded integers exactly.
            assert_eq!(a["results"][0]["stored"]["unorm"][0], 32768, "{b} {}", c.id);
        }
    }
}

#[test]
fn core_level_selection_follows_lod_and_bias() {
    for b in backends("core", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut cases = Vec::new();
        for t in [
            Target::T2d,
            Target::Cube,
            Target::T2dArray,
            Target::CubeArray,
            Target::T1d,
        ] {
            let t = if t == Target::T1d { continue } else { t };
            for (lod, bias, want) in [
                (0.0, 0.0, 0.0),
                (1.0, 0.0, 1.0),
                (2.0, 0.0, 0.0),
                (0.0, 1.0, 1.0),
                (2.0, -1.0, 1.0),
            ] {
                // NEAREST_MIPMAP_NEAREST picks level nearest(lambda) (§8.14.3): only level 1 holds 1.0.
                cases.push((
                    mip_case(
                        &format!("{t}/lod={lod}/bias={bias}"),
                        Spec::Gl46,
                        &[ApiPath::GlslCore],
                        t,
                        lod,
                        bias,
                    ),
                    want,
                ));
            }
        }
        let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
        let answers = s.run(&cs);
        for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
            if a["type"] == "skip" {
                // Only a shader bias on a sampler type without a bias form, LOD or gradient form.
                assert!(
                    c.lookup.bias != 0.0 && c.texture.target == Target::CubeArray,
                    "{b} {}: {a}",
                    c.id
                );
                continue;
            }
            assert_eq!(
                Session::rgba(a, ApiPath::GlslCore)[0],
                w,
                "{b} {}: {a}",
                c.id
            );
        }
    }
}

#[test]
fn core_reads_back_exact_24_bit_and_float_texels() {
    for b in backends("core", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut d24 = d16_case("d24", Spec::Gl46, &[ApiPath::GlslCore], Target::T2d, 0, 0.5);
        d24.texture.format = Format::D24;
        let vals = vec![0u32, 1, 0x800000, 0xFFFFFF];
        d24.texture.levels[0].depth = Texels::Unorm(vals.clone());
        // Texel (0,1) holds 0x800000 = 0.50000003 > 0.5: LEQUAL passes.
        d24.lookup.coord = [0.25, 0.75, 0.0, 1.0];
        let mut f = d24.clone();
        f.id = "d32f".into();
        f.texture.format = Format::D32f;
        f.texture.levels[0].depth = Texels::Float(vec![0.0, 0.25, 0.75, 1.0]);
        f.lookup.dref = 0.8;
        let a = s.run(&[d24, f]);
        assert_eq!(
            a[0]["results"][0]["stored"]["unorm"],
            serde_json::json!(vals),
            "{b}: {}",
            a[0]
        );
        assert_eq!(
            Session::rgba(&a[0], ApiPath::GlslCore)[0],
            1.0,
            "{b}: {}",
            a[0]
        );
        assert_eq!(
            a[1]["results"][0]["stored"]["float"],
            serde_json::json!([0.0, 0.25, 0.75, 1.0]),
            "{b}: {}",
            a[1]
        );
        assert_eq!(
            Session::rgba(&a[1], ApiPath::GlslCore)[0],
            0.0,
            "{b}: 0.8 <= 0.75 fails: {}",
            a[1]
        );
    }
}

#[test]
fn batched_draws_keep_every_case_in_its_own_pixel() {
    // 700 cases on one 4x4 texture (distinct texels): more than two framebuffer rows, one draw.
    // Each looks up one texel centre with Dref just below or above it: LEQUAL gives 1 / 0.
    for b in ["egl:llvmpipe:core", "egl:softpipe:es3"] {
        let Some(mut s) = Session::start(b) else {
            continue;
        };
        let es = b.ends_with("es3");
        let (spec, api) = if es {
            (Spec::Gles32, ApiPath::Es300)
        } else {
            (Spec::Gl46, ApiPath::GlslCore)
        };
        let texels: Vec<u32> = (0..16).map(|i| 1000 + i * 4000).collect();
        let mut cs = Vec::new();
        let mut want = Vec::new();
        for i in 0..700usize {
            let (x, y) = (i % 4, (i / 4) % 4);
            let dt = texels[y * 4 + x] as f64 / 65535.0;
            let above = i % 7 < 3;
            let mut c = d16_case(
                &format!("b/{i}"),
                spec,
                &[api],
                Target::T2d,
                0,
                if above { dt + 1e-4 } else { dt - 1e-4 },
            );
            c.texture.levels[0] = Level {
                width: 4,
                height: 4,
                layers: 1,
                depth: Texels::Unorm(texels.clone()),
                stencil: None,
            };
            c.lookup.coord = [(x as f64 + 0.5) / 4.0, (y as f64 + 0.5) / 4.0, 0.0, 1.0];
            cs.push(c);
            want.push(if above { 0.0 } else { 1.0 });
        }
        let answers = s.run(&cs);
        for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
            assert_eq!(Session::rgba(a, api)[0], w, "{b} {}: {a}", c.id);
            assert!(
                a["results"][0]["note"]
                    .as_str()
                    .unwrap()
                    .contains("batched"),
                "{b}: {a}"
            );
        }
    }
}

#[test]
fn core_texel_offsets_are_added_before_wrapping() {
    // GL 4.6 (8.10): u = w·s + δu, then the wrap mode (Table 8.20). A 4x1 D16 texture where only
    // texel 3 holds 1.0; s = 0.375 is texel 1; LEQUAL with Dref 0.5 passes on texel 3 only.
    for b in backends("core", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut cases = Vec::new();
        for (offset, wrap, lod, want) in [
            (0, Wrap::ClampToEdge, 0.0, 0.0),  // texel 1
            (2, Wrap::ClampToEdge, 0.0, 1.0),  // u = 3.5: texel 3
            (-2, Wrap::ClampToEdge, 0.0, 0.0), // u = -0.5: clamped to texel 0
            (-2, Wrap::Repeat, 0.0, 1.0),      // u = -0.5: repeats to texel 3
            (6, Wrap::Repeat, 0.0, 1.0),       // u = 7.5: texel 7 mod 4 = 3
            (2, Wrap::ClampToEdge, 0.5, 1.0), // explicit LOD (textureLodOffset); NEAREST, one level
        ] {
            let mut c = d16_case(
                &format!("offset={offset}/{wrap}/lod={lod}"),
                Spec::Gl46,
                &[ApiPath::GlslCore],
                Target::T2d,
                0,
                0.5,
            );
            c.texture.levels[0].width = 4;
            c.texture.levels[0].height = 1;
            c.texture.levels[0].depth = Texels::Unorm(vec![0, 0, 0, 65535]);
            c.sampler.wrap_s = wrap;
            c.lookup.coord = [0.375, 0.5, 0.0, 1.0];
            c.lookup.offset = [offset, 0, 0];
            c.lookup.lod = lod;
            cases.push((c, want));
        }
        let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
        let answers = s.run(&cs);
        for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
            assert_eq!(
                Session::rgba(a, ApiPath::GlslCore)[0],
                w,
                "{b} {}: {a}",
                c.id
            );
        }
    }
}

#[test]
fn core_every_lookup_form_selects_the_levels_of_8_14_3() {
    // The backend name's fourth part picks textureLod, textureGrad or texture() with derivatives;
    // λ = 0, 1, 2 and λ = 0 + bias 1 must select level nearest(λ) whichever form realizes it
    // (GL 4.6 §8.14.1 / §8.14.3): only level 1 holds 1.0.
    for b in backends("core", false) {
        for form in ["lod", "grad", "implicit"] {
            let name = format!("{b}:{form}");
            let Some(mut s) = Session::start(&name) else {
                continue;
            };
            let mut cases = Vec::new();
            for (lod, bias, want) in [
                (0.0, 0.0, 0.0),
                (1.0, 0.0, 1.0),
                (2.0, 0.0, 0.0),
                (0.0, 1.0, 1.0),
            ] {
                cases.push((
                    mip_case(
                        &format!("{form}/lod={lod}/bias={bias}"),
                        Spec::Gl46,
                        &[ApiPath::GlslCore],
                        Target::T2d,
                        lod,
                        bias,
                    ),
                    want,
                ));
            }
            let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
            let answers = s.run(&cs);
            for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
                assert_eq!(
                    Session::rgba(a, ApiPath::GlslCore)[0],
                    w,
                    "{name} {}: {a}",
                    c.id
                );
                let note = a["results"][0]["note"].as_str().unwrap_or("");
                let expected_fn = match form {
                    "lod" => "explicit LOD",
                    "grad" => "gradients",
                    _ => "implicit derivatives",
                };
                assert!(
                    note.contains(expected_fn),
                    "{name} {}: realized as `{note}`",
                    c.id
                );
            }
        }
    }
}
