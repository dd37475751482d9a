//! GL compatibility profile paths (fixed-function, GLSL 1.20 / 1.30, ARB fragment programs) on every
//! driver, against GL 2.1 Table 3.20 / GL 4.6 compatibility Table 16.1 (DEPTH_TEXTURE_MODE layouts)
//! and the compare table of EXT_shadow_funcs / GL 4.6 Table 8.23.
//!
//! Mesa deviates from the specs in a few places; those are listed in `KNOWN` with the value the
//! driver returns, so the test fails both on a new deviation and when a driver gets fixed.
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

const PATHS: [ApiPath; 4] = [
    ApiPath::FixedFunction,
    ApiPath::Glsl120,
    ApiPath::Glsl130,
    ApiPath::ArbFp,
];

/// The legacy vec4 layout of r by DEPTH_TEXTURE_MODE (LUMINANCE is the compatibility default).
fn layout(mode: Option<DepthTextureMode>, r: f64) -> [f64; 4] {
    match mode.unwrap_or(DepthTextureMode::Luminance) {
        DepthTextureMode::Luminance => [r, r, r, 1.0],
        DepthTextureMode::Intensity => [r, r, r, r],
        DepthTextureMode::Alpha => [0.0, 0.0, 0.0, r],
        DepthTextureMode::Red => [r, 0.0, 0.0, 1.0],
    }
}

/// Known deviations: (driver, path, case id prefix, observed rgba).
const KNOWN: &[(&str, ApiPath, &str, [f64; 4])] = &[
    // zink returns (r,r,r,r) for the legacy vec4 paths whatever DEPTH_TEXTURE_MODE says.
    ("zink", ApiPath::Glsl120, "none/r=0", [0.0; 4]),
    ("zink", ApiPath::Glsl120, "luminance/r=0", [0.0; 4]),
    ("zink", ApiPath::Glsl120, "alpha/r=1", [1.0; 4]),
    ("zink", ApiPath::Glsl120, "red/r=1", [1.0; 4]),
    ("zink", ApiPath::Glsl120, "red/r=0", [0.0; 4]),
    ("zink", ApiPath::ArbFp, "none/r=0", [0.0; 4]),
    ("zink", ApiPath::ArbFp, "luminance/r=0", [0.0; 4]),
    ("zink", ApiPath::ArbFp, "alpha/r=1", [1.0; 4]),
    ("zink", ApiPath::ArbFp, "red/r=1", [1.0; 4]),
    ("zink", ApiPath::ArbFp, "red/r=0", [0.0; 4]),
    // Fixed function too, seen through the COMBINE read-out of the whole source colour (piglit
    // hole H1; reports/README.md cause 6).
    ("zink", ApiPath::FixedFunction, "none/r=0", [0.0; 4]),
    ("zink", ApiPath::FixedFunction, "luminance/r=0", [0.0; 4]),
    ("zink", ApiPath::FixedFunction, "alpha/r=1", [1.0; 4]),
    ("zink", ApiPath::FixedFunction, "red/r=1", [1.0; 4]),
    ("zink", ApiPath::FixedFunction, "red/r=0", [0.0; 4]),
];

/// The fixed-function LUMINANCE (default) layout of r, or zink's known (r,r,r,r) (cause 6).
fn ff_luminance(backend: &str, r: f64) -> [f64; 4] {
    if backend.split(':').nth(1) == Some("zink") {
        [r; 4]
    } else {
        [r, r, r, 1.0]
    }
}

/// Flaky deviations (Mesa 22.3, EGL, with or without Mesa's shader cache): the same input gives the spec
/// layout or this one from run to run, even for one ARB program alone in its process. Either is
/// accepted here; the runner's flake detection is what reports them.
const FLAKY: &[(&str, ApiPath, &str, [f64; 4])] = &[
    // An ARB fp SHADOW2D lookup with DEPTH_TEXTURE_MODE = ALPHA returns (r,r,r,r) or (0,0,0,r).
    ("llvmpipe", ApiPath::ArbFp, "alpha/r=1", [1.0; 4]),
    ("softpipe", ApiPath::ArbFp, "alpha/r=1", [1.0; 4]),
];

fn flaky(backend: &str, path: ApiPath, id: &str) -> Option<[f64; 4]> {
    let driver = backend.split(':').nth(1).unwrap_or("");
    FLAKY
        .iter()
        .find(|(d, p, pre, _)| *d == driver && *p == path && id.starts_with(pre))
        .map(|k| k.3)
}

fn known(backend: &str, path: ApiPath, id: &str) -> Option<[f64; 4]> {
    let driver = backend.split(':').nth(1).unwrap_or("");
    KNOWN
        .iter()
        .find(|(d, p, pre, _)| *d == driver && *p == path && id.starts_with(pre))
        .map(|k| k.3)
}

#[test]
fn depth_texture_mode_layouts_on_every_legacy_path() {
    let mut failures = Vec::new();
    for b in backends("compat", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        for spec in ["gl46", "arb", "ext_funcs"] {
            assert!(
                s.caps("specs").contains(&spec.to_string()),
                "{b}: {:?}",
                s.caps("specs")
            );
        }
        assert_eq!(
            s.caps("api"),
            vec!["ff", "glsl120", "glsl130", "arbfp"],
            "{b}"
        );
        let mut cases = Vec::new();
        for mode in [
            None,
            Some(DepthTextureMode::Luminance),
            Some(DepthTextureMode::Intensity),
            Some(DepthTextureMode::Alpha),
            Some(DepthTextureMode::Red),
        ] {
            // Dt = 32768/65535; LEQUAL passes for 0.1 (r = 1) and fails for 0.9 (r = 0).
            for (dref, r) in [(0.1, 1.0), (0.9, 0.0)] {
                let name = mode.map_or("none".to_string(), |m| m.key().to_string());
                let mut c = d16_case(
                    &format!("{name}/r={r}"),
                    Spec::Arb,
                    &PATHS,
                    Target::T2d,
                    32768,
                    dref,
                );
                c.sampler.depth_texture_mode = mode;
                cases.push((c, r));
            }
        }
        let (cs, rs): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
        let answers = s.run(&cs);
        for ((c, r), a) in cs.iter().zip(rs).zip(&answers) {
            for p in PATHS {
                let got = Session::rgba(a, p);
                let want = if p == ApiPath::Glsl130 {
                    // GLSL 1.30 texture() on a shadow sampler returns a float: r in channel 0.
                    [r, got[1], got[2], got[3]]
                } else {
                    layout(c.sampler.depth_texture_mode, r)
                };
                let want = known(&b, p, &c.id).unwrap_or(want);
                if got != want && flaky(&b, p, &c.id) != Some(got) {
                    failures.push(format!("{b} {} {p}: got {got:?}, want {want:?}", c.id));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn ext_shadow_funcs_compare_table_on_ff_and_glsl130() {
    let dt = 32768.0 / 65535.0;
    for b in backends("compat", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut cs = Vec::new();
        for f in CompareFunc::CORE {
            for d in [0.25, 0.75] {
                let mut c = d16_case(
                    &format!("{f}/{d}"),
                    Spec::ExtFuncs,
                    &[ApiPath::FixedFunction, ApiPath::Glsl130],
                    Target::T2d,
                    32768,
                    d,
                );
                c.sampler.compare_func = f;
                cs.push(c);
            }
        }
        let answers = s.run(&cs);
        for (c, a) in cs.iter().zip(&answers) {
            let d = c.lookup.dref;
            // EXT_shadow_funcs: r = 1.0 when "R <op> Dt" holds, else 0.0.
            let pass = match c.sampler.compare_func {
                CompareFunc::Never => false,
                CompareFunc::Always => true,
                CompareFunc::Less => d < dt,
                CompareFunc::Lequal => d <= dt,
                CompareFunc::Greater => d > dt,
                CompareFunc::Gequal => d >= dt,
                CompareFunc::Equal => d == dt,
                _ => d != dt,
            };
            let r = if pass { 1.0 } else { 0.0 };
            assert_eq!(
                Session::rgba(a, ApiPath::FixedFunction),
                ff_luminance(&b, r),
                "{b} {}",
                c.id
            );
            assert_eq!(Session::rgba(a, ApiPath::Glsl130)[0], r, "{b} {}", c.id);
        }
    }
}

#[test]
fn fixed_function_1d_uses_texture_coordinate_r_as_the_reference() {
    // ARB_shadow: R is texture coordinate r. Mesa's fixed-function 1D shadow lookup ignores r (every
    // driver: LEQUAL always passes, as if R were 0); GLSL 1.20 shadow1D takes R from coord.p and is
    // right, which shows the worker passes r.
    for b in backends("compat", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let c = d16_case(
            "1d/r=0",
            Spec::Arb,
            &[ApiPath::FixedFunction, ApiPath::Glsl120],
            Target::T1d,
            32768,
            0.9,
        );
        let a = s.run(&[c]);
        let want120 = known(&b, ApiPath::Glsl120, "none/r=0").unwrap_or([0.0, 0.0, 0.0, 1.0]);
        assert_eq!(
            Session::rgba(&a[0], ApiPath::Glsl120),
            want120,
            "{b}: {}",
            a[0]
        );
        let ff = Session::rgba(&a[0], ApiPath::FixedFunction);
        assert_eq!(
            ff,
            [1.0, 1.0, 1.0, 1.0],
            "{b}: known Mesa deviation (spec: [0,0,0,1]) changed: {}",
            a[0]
        );
    }
}

#[test]
fn fixed_function_realizes_lod_and_bias_and_says_why_it_skips() {
    for b in backends("compat", true) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        // NEAREST_MIPMAP_NEAREST picks level nearest(lambda) (§8.14.3): only level 1 holds 1.0.
        // Fixed-function gets lambda from coordinates varying across the pixel quad and the shader
        // bias from the texture unit's TEXTURE_LOD_BIAS.
        let mut cs = Vec::new();
        let mut want = Vec::new();
        for (lod, bias, r) in [
            (0.0, 0.0, 0.0),
            (1.0, 0.0, 1.0),
            (2.0, 0.0, 0.0),
            (0.0, 1.0, 1.0),
            (2.0, -1.0, 1.0),
        ] {
            cs.push(mip_case(
                &format!("mip/lod={lod}/bias={bias}"),
                Spec::Gl46,
                &[ApiPath::FixedFunction],
                Target::T2d,
                lod,
                bias,
            ));
            want.push(r);
        }
        // No fixed-function shadow lookup on a cube map (ARB_shadow covers 1D and 2D targets).
        cs.push(d16_case(
            "cube",
            Spec::Gl46,
            &[ApiPath::FixedFunction, ApiPath::Glsl130],
            Target::Cube,
            32768,
            0.1,
        ));
        let a = s.run(&cs);
        for ((c, r), a) in cs.iter().zip(want).zip(&a) {
            assert_eq!(
                Session::rgba(a, ApiPath::FixedFunction),
                ff_luminance(&b, r),
                "{b} {}: {a}",
                c.id
            );
        }
        let cube = &a[5];
        assert_eq!(Session::rgba(cube, ApiPath::Glsl130)[0], 1.0, "{b}: {cube}");
        assert_eq!(cube["skipped"][0]["api"], "ff", "{b}: {cube}");
        assert!(
            cube["skipped"][0]["reason"]
                .as_str()
                .unwrap()
                .contains("cube"),
            "{b}: {cube}"
        );
    }
}

#[test]
fn legacy_specs_see_the_colour_texture_as_luminance8() {
    // ARB_shadow: a non-depth texture "operates in the normal manner"; in GL 2.1 terms the colour
    // texture is LUMINANCE8, read as (L, L, L, 1) (Table 3.20; the fixed-function COMBINE read-out
    // passes (Cs, As) through).
    for b in backends("compat", false).into_iter().take(2) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut c = d16_case(
            "arb/r8",
            Spec::Arb,
            &[ApiPath::FixedFunction, ApiPath::Glsl120],
            Target::T2d,
            0,
            0.5,
        );
        c.texture.format = Format::R8;
        c.texture.levels[0].depth = Texels::Unorm(vec![51; 4]);
        c.sampler.compare_mode = CompareMode::None;
        let a = s.run(&[c]);
        let l = 51.0 / 255.0;
        for p in [ApiPath::FixedFunction, ApiPath::Glsl120] {
            let got = Session::rgba(&a[0], p);
            assert!(
                got[..3].iter().all(|v| (v - l).abs() < 1e-6) && got[3] == 1.0,
                "{b} {p}: {}",
                a[0]
            );
        }
        assert_eq!(
            a[0]["results"][0]["stored"]["unorm"],
            serde_json::json!([51, 51, 51, 51]),
            "{b}"
        );
    }
}
