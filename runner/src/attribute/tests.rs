use super::*;
use crate::records::{Status, Tags};
use shadowcheck_model::{CompareFunc, DepthTextureMode, Format, Target};
use shadowcheck_protocol::Rgba;

/// The committed fixtures' cases by id.
fn fixtures() -> HashMap<String, Case> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures");
    let mut m = HashMap::new();
    for (_, f) in shadowcheck_cases::fixtures::load_path(&root).unwrap() {
        for c in f.cases {
            m.insert(c.id.clone(), c);
        }
    }
    m
}

fn record(backend: &str, case: &Case, api: ApiPath, outcome: Outcome, r: f64) -> TestResult {
    TestResult {
        backend: backend.into(),
        test: TestResult::name(&case.id, api),
        case_id: case.id.clone(),
        api,
        status: Status::Plain(outcome),
        outcome,
        reason: (outcome == Outcome::Skip).then(|| "no such format".into()),
        duration: 0.0,
        tags: Tags::of(case),
        observed: Some(Rgba([r, 0.0, 0.0, 1.0])),
        expected: None,
        footprint: None,
        rerun: None,
        fixtures: None,
    }
}

/// A committed 2D D24 GL 4.6 core case whose Vulkan counterpart is a committed Vulkan fixture.
fn pair(cases: &HashMap<String, Case>) -> (Case, Case) {
    let mut ids: Vec<&String> = cases
        .keys()
        .filter(|k| k.starts_with("gl46/2d/d24/"))
        .collect();
    ids.sort();
    for id in ids {
        let gl = &cases[id];
        if !gl.api.contains(&ApiPath::GlslCore) {
            continue;
        }
        if let Ok(vk) = vulkan_counterpart(gl) {
            if cases
                .get(&vk.id)
                .is_some_and(|f| same_lookup(gl, f) == Some(f.sweep.len()))
            {
                return (gl.clone(), cases[&vk.id].clone());
            }
        }
    }
    panic!("no GL 4.6 case with a Vulkan counterpart in the fixtures");
}

#[test]
fn each_answer_of_the_driver_gives_its_layer() {
    let cases = fixtures();
    let (gl, vk) = pair(&cases);
    let attribute_with = |lower: Option<(Outcome, f64)>| {
        let mut res = Results::default();
        res.insert(record(
            "egl:zink:core",
            &gl,
            ApiPath::GlslCore,
            Outcome::Fail,
            0.25,
        ));
        if let Some((o, r)) = lower {
            res.insert(record("vk:lavapipe", &vk, ApiPath::Vulkan, o, r));
        }
        let rows = attribute(&res, &cases);
        assert_eq!(rows.len(), 1, "{rows:?}");
        assert_eq!(rows[0].lower, "vk:lavapipe");
        rows[0].clone()
    };
    assert_eq!(
        attribute_with(Some((Outcome::Pass, 1.0))).layer,
        Layer::Upper
    );
    assert_eq!(
        attribute_with(Some((Outcome::Skip, 0.0))).layer,
        Layer::Upper
    );
    assert_eq!(
        attribute_with(Some((Outcome::Fail, 0.25))).layer,
        Layer::Lower
    );
    assert_eq!(
        attribute_with(Some((Outcome::Fail, 0.75))).layer,
        Layer::Both
    );
    let none = attribute_with(None);
    assert_eq!(none.layer, Layer::NoEquivalent);
    assert_eq!(
        none.counterpart.as_deref(),
        Some(TestResult::name(&vk.id, ApiPath::Vulkan).as_str())
    );
}

#[test]
fn gl_only_state_is_the_upper_layers_and_other_backends_are_not_attributed() {
    let cases = fixtures();
    let (gl, vk) = pair(&cases);
    let mut mode = gl.clone();
    mode.id = "gl46/2d/d24/nearest/lequal/attribute-test".into();
    mode.sampler.depth_texture_mode = Some(DepthTextureMode::Alpha);
    mode.api = vec![ApiPath::Glsl130];
    let mut all = cases.clone();
    all.insert(mode.id.clone(), mode.clone());
    let mut res = Results::default();
    res.insert(record(
        "egl:zink+swiftshader:compat",
        &mode,
        ApiPath::Glsl130,
        Outcome::Fail,
        0.0,
    ));
    // Not a layered backend: not attributed.
    res.insert(record(
        "egl:llvmpipe:core",
        &gl,
        ApiPath::GlslCore,
        Outcome::Fail,
        0.0,
    ));
    // A pass of a layered backend: nothing to attribute.
    res.insert(record(
        "egl:zink:core",
        &gl,
        ApiPath::GlslCore,
        Outcome::Pass,
        1.0,
    ));
    res.insert(record(
        "vk:swiftshader",
        &vk,
        ApiPath::Vulkan,
        Outcome::Fail,
        0.0,
    ));
    let rows = attribute(&res, &all);
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!(rows[0].layer, Layer::Upper);
    assert_eq!(rows[0].lower, "vk:swiftshader");
    assert!(rows[0].counterpart.is_none());
    assert!(
        rows[0].why.contains("DEPTH_TEXTURE_MODE"),
        "{}",
        rows[0].why
    );
    // A read without comparison has a Vulkan equivalent outside the Vulkan cases.
    let mut read = gl.clone();
    read.sampler.compare_mode = shadowcheck_model::CompareMode::None;
    read.id = "gl46/2d/d24/nearest/none/attribute-test".into();
    all.insert(read.id.clone(), read.clone());
    let mut res2 = Results::default();
    res2.insert(record(
        "egl:zink:core",
        &read,
        ApiPath::GlslCore,
        Outcome::Fail,
        0.5,
    ));
    let none = attribute(&res2, &all);
    assert_eq!(none[0].layer, Layer::NoEquivalent, "{none:?}");
    assert!(
        none[0].why.contains("without comparison"),
        "{}",
        none[0].why
    );
    let md = markdown(&rows);
    assert!(
        md.contains("| egl:zink+swiftshader:compat | vk:swiftshader | 1 | 0 | 0 | 0 |"),
        "{md}"
    );
}

#[test]
fn a_counterpart_keeps_the_lookup_and_refuses_what_vulkan_lacks() {
    let cases = fixtures();
    let (gl, vk) = pair(&cases);
    assert_eq!(vulkan_counterpart(&gl).unwrap().id, vk.id);
    assert!(vk.id.starts_with("vulkan/2d/d24/"));
    let mut rect = gl.clone();
    rect.texture.target = Target::Rect;
    assert!(vulkan_counterpart(&rect).is_err());
    let mut d32 = gl.clone();
    d32.texture.format = Format::D32;
    assert!(vulkan_counterpart(&d32).is_err());
    let mut sgix = gl;
    sgix.sampler.compare_func = CompareFunc::LequalRSgix;
    assert!(vulkan_counterpart(&sgix).is_err());
    assert_eq!(
        layering_of("egl:zink:es3").map(|l| l.lower),
        Some("vk:lavapipe")
    );
    assert_eq!(
        layering_of("egl:zink+swiftshader:core").map(|l| l.lower),
        Some("vk:swiftshader")
    );
    assert!(layering_of("egl:llvmpipe:core").is_none());
    // The WebGL instances by their whole name: `webgl:chromium` is not a prefix of its siblings.
    for (b, lower) in [
        ("webgl:chromium", "vk:swiftshader"),
        ("webgl:chromium-lavapipe", "vk:lavapipe"),
        ("webgl:chromium-gles", "egl:llvmpipe:es3"),
    ] {
        assert_eq!(layering_of(b).map(|l| l.lower), Some(lower), "{b}");
    }
    assert!(layering_of("webgl:chromium-other").is_none());
    assert!(layering_of("osmesa:zink:core").is_some());
}

#[test]
fn under_angles_gles_back_end_the_lower_layer_answers_the_same_test() {
    let cases = fixtures();
    let mut ids: Vec<&String> = cases
        .keys()
        .filter(|k| k.starts_with("gles32/2d/d24/"))
        .collect();
    ids.sort();
    let es = &cases[ids[0]];
    let attribute_with = |lower: Option<(Outcome, f64)>| {
        let mut res = Results::default();
        res.insert(record(
            "webgl:chromium-gles",
            es,
            ApiPath::Es300,
            Outcome::Fail,
            0.25,
        ));
        // The Vulkan drivers' records are not asked.
        res.insert(record(
            "vk:lavapipe",
            es,
            ApiPath::Vulkan,
            Outcome::Pass,
            1.0,
        ));
        if let Some((o, r)) = lower {
            res.insert(record("egl:llvmpipe:es3", es, ApiPath::Es300, o, r));
        }
        let rows = attribute(&res, &cases);
        assert_eq!(rows.len(), 1, "{rows:?}");
        assert_eq!(rows[0].lower, "egl:llvmpipe:es3");
        assert_eq!(
            rows[0].counterpart.as_deref(),
            Some(TestResult::name(&es.id, ApiPath::Es300).as_str())
        );
        rows[0].clone()
    };
    let pass = attribute_with(Some((Outcome::Pass, 1.0)));
    assert_eq!(pass.layer, Layer::Upper);
    assert!(pass.why.contains("egl:llvmpipe:es3 passes"), "{}", pass.why);
    let lower = attribute_with(Some((Outcome::Fail, 0.25)));
    assert_eq!(lower.layer, Layer::Lower);
    assert_eq!(
        attribute_with(Some((Outcome::Warn, 0.5))).layer,
        Layer::Both
    );
    assert_eq!(attribute_with(None).layer, Layer::NoEquivalent);
    // Nothing to write for it: its counterpart is a test of the committed fixtures already.
    let mut res = Results::default();
    res.insert(record(
        "webgl:chromium-gles",
        es,
        ApiPath::Es300,
        Outcome::Fail,
        0.25,
    ));
    assert!(counterparts_to_run(&res, &cases).is_empty());
    let md = markdown(&[lower]);
    assert!(
        md.contains("| webgl:chromium-gles | egl:llvmpipe:es3 | 0 | 1 | 0 | 0 |"),
        "{md}"
    );
}

#[test]
fn a_missing_counterpart_is_written_to_run_and_then_attributed() {
    let cases = fixtures();
    let (gl, _) = pair(&cases);
    // A GL case whose Vulkan id the grid does not hold.
    let mut lone = gl.clone();
    lone.id = format!("{}/attribute-lone", gl.id);
    let mut all = cases.clone();
    all.insert(lone.id.clone(), lone.clone());
    let mut res = Results::default();
    res.insert(record(
        "egl:zink:core",
        &lone,
        ApiPath::GlslCore,
        Outcome::Fail,
        0.25,
    ));
    let before = attribute(&res, &all);
    assert_eq!(before[0].layer, Layer::NoEquivalent, "{before:?}");
    let written = counterparts_to_run(&res, &all);
    assert_eq!(written.len(), 1, "{written:?}");
    let vk = &written[0];
    assert!(
        vk.id.starts_with("vulkan/") && vk.id.ends_with("/of=gl46"),
        "{}",
        vk.id
    );
    assert_eq!(vk.spec, Spec::Vulkan);
    assert!(vk.expect.is_some());
    assert_eq!(vk.sweep.len(), lone.sweep.len());
    assert!(vk.sweep.iter().all(|p| p.expect.is_some()));
    // Run (here: a Pass recorded for it) and attribute again with it among the cases.
    all.insert(vk.id.clone(), vk.clone());
    res.insert(record(
        "vk:lavapipe",
        vk,
        ApiPath::Vulkan,
        Outcome::Pass,
        1.0,
    ));
    let after = attribute(&res, &all);
    assert_eq!(after[0].layer, Layer::Upper, "{after:?}");
    assert_eq!(
        after[0].counterpart.as_deref(),
        Some(TestResult::name(&vk.id, ApiPath::Vulkan).as_str())
    );
    // Nothing is written twice, nor what the cases already hold.
    assert!(counterparts_to_run(&res, &all).is_empty());
}

#[test]
fn a_webgpu_failure_is_attributed_against_swiftshaders_vulkan_driver_under_dawn() {
    let cases = fixtures();
    // A committed WebGPU case whose Vulkan counterpart (same grid coordinates) is committed too.
    let mut ids: Vec<&String> = cases
        .keys()
        .filter(|k| k.starts_with("webgpu/2d/"))
        .collect();
    ids.sort();
    let (wg, vk) = ids
        .into_iter()
        .find_map(|id| {
            let wg = &cases[id];
            let vk = vulkan_counterpart(wg).ok()?;
            let f = cases.get(&vk.id)?;
            (same_lookup(wg, f) == Some(f.sweep.len())).then(|| (wg.clone(), f.clone()))
        })
        .expect("a WebGPU fixture with a Vulkan counterpart");
    assert_eq!(
        layering_of("webgpu:chromium").map(|l| l.lower),
        Some("vk:swiftshader")
    );
    let mut res = Results::default();
    res.insert(record(
        "webgpu:chromium",
        &wg,
        ApiPath::Wgsl,
        Outcome::Fail,
        0.25,
    ));
    res.insert(record(
        "vk:swiftshader",
        &vk,
        ApiPath::Vulkan,
        Outcome::Fail,
        0.25,
    ));
    let rows = attribute(&res, &cases);
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!(rows[0].layer, Layer::Lower, "{rows:?}");
    assert_eq!(rows[0].lower, "vk:swiftshader");
}
