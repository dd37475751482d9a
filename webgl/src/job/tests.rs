use super::*;
use crate::worker::capabilities;
use shadowcheck_plan::{ContextApi, LookupForm};
use shadowcheck_protocol::{Capabilities, Support};

/// A GLES 3.2 2D D24 NEAREST LEQUAL case with texels 0 and 2^24-1 (`EXTRA` replaced by more
/// sampler fields, `TARGET` / `FORMAT` by keys).
const CASE: &str = r#"{"id":"ID","spec":"gles32","api":["es300"],"texture":{"target":"TARGET","format":"FORMAT","levels":[{"width":2,"height":1,"layers":1,"depth":{"unorm":[0,16777215]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]EXTRA},"lookup":{"coord":[0.25,0.5,0,1],"dref":REF}}"#;

fn case(id: &str, target: &str, format: &str, extra: &str, dref: &str) -> Case {
    let json = CASE
        .replace("ID", id)
        .replace("TARGET", target)
        .replace("FORMAT", format)
        .replace("EXTRA", extra)
        .replace("REF", dref);
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

fn es3() -> GlInfo {
    GlInfo {
        api: ContextApi::Es3,
        es: true,
        compat: false,
        version: (3, 0),
        glsl: 300,
        renderer: String::new(),
        version_string: String::new(),
        extensions: Default::default(),
        form: LookupForm::Auto,
        version_override: false,
    }
}

#[test]
fn non_finite_floats_reach_the_page_as_strings_number_reads() {
    let v = serde_json::to_value([
        Js(f32::INFINITY),
        Js(f32::NEG_INFINITY),
        Js(f32::NAN),
        Js(0.3),
    ])
    .unwrap();
    assert_eq!(v[0], "Infinity");
    assert_eq!(v[1], "-Infinity");
    assert_eq!(v[2], "NaN");
    // Finite values stay numbers whose nearest f32 is the value sent.
    assert_eq!(v[3].as_f64().map(|x| x as f32), Some(0.3f32));
}

#[test]
fn a_job_carries_the_gl_workers_texels_parameters_and_shader() {
    let cases = vec![
        case("a", "2d", "d24", "", "0.5"),
        case("b", "2d", "d24", "", "\"inf\""),
        case("c", "2d", "d16", "", "0.5"),
    ];
    let b = build(&es3(), &cases);
    assert!(b.answers.iter().all(Option::is_none));
    // a and b share one texture (same texture and sampler), c has its own.
    assert_eq!(b.job.groups.len(), 2);
    assert_eq!(b.job.groups[0].cases, vec![0, 1]);
    let tex = b.job.groups[0].texture.as_ref().expect("texture");
    let lvl = &tex.levels[0];
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(&lvl.data)
        .unwrap();
    let want = level_bytes(cases[0].texture.format, &cases[0].texture.levels[0]).unwrap();
    assert_eq!(bytes, want, "texel bytes are the GL worker's");
    assert_eq!(
        (lvl.ifmt, lvl.fmt, lvl.ty),
        (0x81A6, 0x1902, 0x1405),
        "DEPTH_COMPONENT24, DEPTH_COMPONENT, UNSIGNED_INT"
    );
    let calls: Vec<&str> = tex.params.iter().map(|p| p.call.as_str()).collect();
    assert!(
        calls.contains(&"glTexParameteri(TEXTURE_COMPARE_MODE)"),
        "{calls:?}"
    );
    // One bundle (same lookup): both states bound together, group 0 on unit 0, group 1 on
    // unit 1, and one program of two samplers with the es300 shadow lookup.
    assert_eq!(b.job.bundles.len(), 1);
    assert_eq!(b.job.bundles[0].states, vec![0, 1]);
    let units: Vec<(usize, usize)> = b.job.bundles[0]
        .draws
        .iter()
        .map(|d| (d.case, d.unit))
        .collect();
    assert_eq!(units, vec![(0, 0), (1, 0), (2, 1)]);
    assert_eq!(b.job.programs.len(), 1);
    let fs = &b.job.programs[0][1];
    assert!(fs.starts_with("#version 300 es"));
    assert!(
        fs.contains("uniform highp sampler2DShadow u_tex0;")
            && fs.contains("uniform highp sampler2DShadow u_tex1;")
            && fs.contains("float v_unit;"),
        "{fs}"
    );
    // Dref = +inf goes out as a string, not null.
    let json = serde_json::to_value(&b.job).unwrap();
    assert_eq!(json["bundles"][0]["draws"][1]["p"][2], "Infinity");
    assert_eq!(b.job.slots, 3);
}

#[test]
fn page_pixels_become_results_and_page_errors_become_error_answers() {
    let cases = vec![
        case("a", "2d", "d24", "", "0.5"),
        case("b", "2d", "d16", "", "0.5"),
    ];
    let b = build(&es3(), &cases);
    let px: Vec<u8> = [1.0f32, 0.0, 0.0, 1.0, 9.0, 9.0, 9.0, 9.0]
        .iter()
        .flat_map(|f| f.to_ne_bytes())
        .collect();
    let page = PageAnswer {
        pixels: base64::engine::general_purpose::STANDARD.encode(px),
        errors: [(
            1,
            "texture upload (glTexImage*) raised GL_INVALID_OPERATION".to_string(),
        )]
        .into_iter()
        .collect(),
    };
    let a = answers(b, &cases, page);
    match &a[0] {
        Answer::Observation(r, skipped) => {
            assert_eq!(r.len(), 1);
            assert_eq!(r[0].api, "es300");
            assert_eq!(r[0].rgba.0, [1.0, 0.0, 0.0, 1.0]);
            assert!(skipped.is_empty());
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(&a[1], Answer::Error(m) if m.contains("GL_INVALID_OPERATION")));
}

#[test]
fn what_webgl2_lacks_is_skip_with_the_reason_through_capabilities_support() {
    let with = capabilities(&["WEBGL_stencil_texturing".to_string()], &[]);
    let without = capabilities(&[], &[]);
    let skip = |c: &Capabilities, case: &Case| match c.support(case) {
        Support::Skip(why) => why,
        other => panic!("{}: {other:?}", case.id),
    };
    assert!(skip(&with, &case("x", "cubearray", "d24", "", "0.5")).contains("cubearray"));
    assert!(skip(&with, &case("x", "2d", "d32fs8", "", "0.5")).contains("d32fs8"));
    let border = case("x", "2d", "d24", "", "0.5");
    let mut border_wrap = border.clone();
    border_wrap.sampler.wrap_s = shadowcheck_model::Wrap::ClampToBorder;
    assert!(skip(&with, &border_wrap).contains("border_clamp"));
    let dsm = case(
        "x",
        "2d",
        "d24s8",
        r#","depth_stencil_mode":"depth""#,
        "0.5",
    );
    assert!(matches!(with.support(&dsm), Support::Run { .. }));
    assert!(skip(&without, &dsm).contains("stencil_texturing"));
    assert!(matches!(with.support(&border), Support::Run { .. }));
}
