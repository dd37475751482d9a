//! OpenGL ES contexts through EGL: GLSL ES 3.00 (`es300`) against GLES 3.2 §8.20 Table 8.22 and
//! §8.14 level selection; ES 2.0 paths are reported unavailable where EXT_shadow_samplers is not
//! exposed (every Mesa driver here).
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

#[test]
fn es3_compare_and_targets() {
    let dt = 32768.0 / 65535.0;
    for b in backends("es3", false) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        assert_eq!(s.caps("specs"), vec!["gles32"], "{b}");
        assert!(
            !s.caps("formats").contains(&"d32".to_string()),
            "ES has no DEPTH_COMPONENT32: {b}"
        );
        let mut cs = Vec::new();
        let mut want = Vec::new();
        for t in [
            Target::T2d,
            Target::Cube,
            Target::T2dArray,
            Target::CubeArray,
        ] {
            for (d, r) in [(dt - 1e-4, 1.0), (dt + 1e-4, 0.0)] {
                cs.push(d16_case(
                    &format!("{t}/{d}"),
                    Spec::Gles32,
                    &[ApiPath::Es300],
                    t,
                    32768,
                    d,
                ));
                want.push(r);
            }
            for (lod, bias, r) in [
                (0.0, 0.0, 0.0),
                (1.0, 0.0, 1.0),
                (2.0, 0.0, 0.0),
                (0.0, 1.0, 1.0),
            ] {
                cs.push(mip_case(
                    &format!("{t}/lod={lod}/bias={bias}"),
                    Spec::Gles32,
                    &[ApiPath::Es300],
                    t,
                    lod,
                    bias,
                ));
                want.push(r);
            }
        }
        let answers = s.run(&cs);
        for ((c, r), a) in cs.iter().zip(want).zip(&answers) {
            if a["type"] == "skip" {
                // GLSL ES has no bias form, explicit LOD or gradient form for cube-array shadow lookups.
                assert!(
                    c.texture.target == Target::CubeArray && c.lookup.bias != 0.0,
                    "{b} {}: {a}",
                    c.id
                );
                continue;
            }
            let rgba = Session::rgba(a, ApiPath::Es300);
            assert_eq!(rgba[0], r, "{b} {}: {a}", c.id);
            // ES reads nothing back: there is no glGetTexImage.
            assert!(a["results"][0].get("stored").is_none(), "{b} {}", c.id);
        }
    }
}

#[test]
fn es2_without_ext_shadow_samplers_declares_es2_ext_and_skips_naming_the_extension() {
    for b in backends("es2", false) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        if s.caps("extensions")
            .contains(&"GL_EXT_shadow_samplers".to_string())
        {
            assert_eq!(s.caps("specs"), vec!["es2_ext"], "{b}");
            continue;
        }
        // ES 2 implements es2_ext on es100 (so its cases are tests of this backend, not "not
        // applicable"); the missing extension makes each a Skip naming it.
        assert_eq!(s.caps("specs"), vec!["es2_ext"], "{b}: {}", s.hello);
        let c = d16_case(
            "es2",
            Spec::Es2Ext,
            &[ApiPath::Es100Ext],
            Target::T2d,
            32768,
            0.5,
        );
        let a = s.run(&[c]);
        assert_eq!(a[0]["type"], "skip", "{b}: {}", a[0]);
        assert!(
            a[0]["reason"]
                .as_str()
                .unwrap()
                .contains("GL_EXT_shadow_samplers not exposed"),
            "{b}: {}",
            a[0]
        );
    }
}

#[test]
fn es3_lod_bias_state_is_a_skip_not_an_error() {
    // GLES 3.2 has no TEXTURE_LOD_BIAS (§8.10 lists no such parameter).
    for b in backends("es3", false).into_iter().take(1) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut c = d16_case(
            "es/lodbias",
            Spec::Gles32,
            &[ApiPath::Es300],
            Target::T2d,
            32768,
            0.5,
        );
        c.sampler.lod_bias = 1.0;
        let a = s.run(&[c]);
        assert_eq!(a[0]["type"], "skip", "{}", a[0]);
        assert!(
            a[0]["reason"]
                .as_str()
                .unwrap()
                .contains("TEXTURE_LOD_BIAS"),
            "{}",
            a[0]
        );
    }
}
