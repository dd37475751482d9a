//! Unit tests of [`super::validate`] and the checks it runs.

use super::*;
use crate::*;

fn case() -> Case {
    Case {
        sweep: vec![],
        id: "t".into(),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: 2,
                height: 1,
                layers: 1,
                depth: Texels::Unorm(vec![0, 65535]),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest),
        lookup: Lookup {
            coord: [0.25, 0.5, 0.0, 1.0],
            layer: 0.0,
            dref: 0.5,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: None,
    }
}

#[test]
fn accepts_a_good_case_and_round_trips() {
    let c = case();
    validate(&c).unwrap();
    let json = serde_json::to_string(&c).unwrap();
    let back: Case = serde_json::from_str(&json).unwrap();
    assert_eq!(back, c);
}

#[test]
fn non_finite_reference_round_trips_as_string() {
    let mut c = case();
    c.lookup.dref = f64::NAN;
    c.lookup.coord[0] = f64::NEG_INFINITY;
    let json = serde_json::to_string(&c).unwrap();
    assert!(json.contains("\"dref\":\"nan\""), "{json}");
    assert!(json.contains("\"-inf\""), "{json}");
    let back: Case = serde_json::from_str(&json).unwrap();
    assert!(back.lookup.dref.is_nan());
    assert_eq!(back.lookup.coord[0], f64::NEG_INFINITY);
}

#[test]
fn rejects_out_of_range_unorm_naming_the_field() {
    let mut c = case();
    c.texture.levels[0].depth = Texels::Unorm(vec![0, 70000]);
    let e = validate(&c).unwrap_err().to_string();
    assert!(
        e.contains("texture.levels[0].depth[1]") && e.contains("`t`"),
        "{e}"
    );
}

#[test]
fn texel_offsets_need_a_glsl_130_path_a_target_with_offsets_and_a_supported_value() {
    let mut c = case();
    c.lookup.offset = [-8, 7, 0];
    validate(&c).unwrap();
    let json = serde_json::to_string(&c).unwrap();
    assert!(json.contains("\"offset\":[-8,7,0]"), "{json}");
    assert!(!serde_json::to_string(&case()).unwrap().contains("offset"));
    c.lookup.offset = [8, 0, 0];
    let e = validate(&c).unwrap_err().to_string();
    assert!(
        e.contains("lookup.offset[0]") && e.contains("-8..=7"),
        "{e}"
    );
    c.lookup.offset = [1, 0, 1];
    assert!(validate(&c)
        .unwrap_err()
        .to_string()
        .contains("lookup.offset[2]"));
    c.lookup.offset = [1, 0, 0];
    c.api = vec![ApiPath::GlslCore, ApiPath::Glsl120];
    assert!(validate(&c).unwrap_err().to_string().contains("`glsl120`"));
    c.api = vec![ApiPath::Es300];
    c.texture.target = Target::Cube;
    c.texture.levels = vec![Level {
        width: 1,
        height: 1,
        layers: 6,
        depth: Texels::Unorm(vec![0; 6]),
        stencil: None,
    }];
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("cube map lookups take no texel offset"), "{e}");
}

#[test]
fn ids_that_would_need_csv_quoting_are_rejected() {
    for bad in [
        "a/dt=0.2,0.4",
        "a/\"q\"",
        "a/it's",
        "a b",
        "a\nb",
        "a\tb",
        "a\u{7f}",
    ] {
        let mut c = case();
        c.id = bad.into();
        let e = validate(&c).unwrap_err().to_string();
        assert!(e.contains("field `id`"), "{bad:?}: {e}");
        assert!(e.contains("need no quoting"), "{bad:?}: {e}");
    }
    let mut c = case();
    c.id = "gl46/2d/d16/nearest/lequal/a=0.25_0.5/offset=-1_0/ref=0.5".into();
    validate(&c).unwrap();
}

#[test]
fn duplicate_api_paths_are_rejected() {
    let mut c = case();
    let first = c.api[0];
    c.api.push(first);
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("duplicate API path"), "{e}");
    assert!(e.contains(&format!("api[{}]", c.api.len() - 1)), "{e}");
}

#[test]
fn rejects_absurd_sizes() {
    let mut c = case();
    c.texture.levels[0].width = 1 << 30;
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("width"), "{e}");
}

#[test]
fn rejects_texel_count_mismatch_and_unknown_enum() {
    let mut c = case();
    c.texture.levels[0].depth = Texels::Unorm(vec![1]);
    assert!(validate(&c).unwrap_err().to_string().contains("depth"));
    let json = serde_json::to_string(&case())
        .unwrap()
        .replace("\"lequal\"", "\"lequalish\"");
    let e = serde_json::from_str::<Case>(&json).unwrap_err().to_string();
    assert!(e.contains("lequalish"), "{e}");
}

#[test]
fn judge_uses_layout_and_profiles() {
    let mut accept = crate::KeyMap::new();
    accept.insert(Profile::Strict, Acceptance(vec![Interval::point(1.0)]));
    accept.insert(Profile::Quality, Acceptance(vec![Interval::new(0.9, 1.0)]));
    let mut layout = crate::KeyMap::new();
    layout.insert(
        ApiPath::FixedFunction,
        [Channel::R, Channel::R, Channel::R, Channel::One],
    );
    let e = Expectation {
        spec_value: Some(1.0),
        accept,
        layout,
        other_layouts: Default::default(),
        gather: None,
        implementation_defined: None,
        citations: vec![],
    };
    assert_eq!(
        e.judge(ApiPath::FixedFunction, [1.0, 1.0, 1.0, 1.0]),
        Some(Judgement::Strictest)
    );
    assert_eq!(
        e.judge(ApiPath::FixedFunction, [0.95, 1.0, 1.0, 1.0]),
        Some(Judgement::Looser(Profile::Quality))
    );
    assert_eq!(
        e.judge(ApiPath::FixedFunction, [1.0, 1.0, 1.0, 0.0]),
        Some(Judgement::Outside)
    );
    assert_eq!(e.judge(ApiPath::GlslCore, [1.0; 4]), None);
}

#[test]
fn footprint_with_nan_reference_round_trips() {
    let f = Footprint {
        dref: f64::NAN,
        texels: vec![FootprintTexel {
            level: 0,
            xyz: Some([0, 0, 0]),
            stored: 1.0,
            dt: f64::INFINITY,
            pass: None,
            weight: 1.0,
        }],
    };
    let json = serde_json::to_string(&f).unwrap();
    assert!(
        json.contains("\"dref\":\"nan\"") && json.contains("\"dt\":\"inf\""),
        "{json}"
    );
    let back: Footprint = serde_json::from_str(&json).unwrap();
    assert!(back.dref.is_nan());
    assert_eq!(back.texels[0].dt, f64::INFINITY);
}

#[test]
fn delivery_is_left_out_when_literal_and_rejected_where_the_language_wants_a_constant() {
    assert!(!serde_json::to_string(&case()).unwrap().contains("delivery"));
    let mut c = case();
    c.lookup.delivery = Delivery::PerFragment;
    validate(&c).unwrap();
    let json = serde_json::to_string(&c).unwrap();
    assert!(json.contains("\"delivery\":\"per_fragment\""), "{json}");
    assert_eq!(serde_json::from_str::<Case>(&json).unwrap(), c);
    // textureOffset's offset is a constant expression.
    c.lookup.offset = [1, 0, 0];
    let e = validate(&c).unwrap_err().to_string();
    assert!(
        e.contains("lookup.delivery") && e.contains("must be a constant expression"),
        "{e}"
    );
    // textureGatherOffset's may be variable; textureGatherOffsets' may not.
    c.lookup.gather = Some(Gather { offsets: None });
    validate(&c).unwrap();
    c.lookup.gather = Some(Gather {
        offsets: Some([[0, 0], [1, 0], [0, 1], [1, 1]]),
    });
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("constant integral expressions"), "{e}");
    // Drawn on the GLSL 1.30+ / ES 3.00 paths only.
    let mut c = case();
    c.lookup.delivery = Delivery::Uniform;
    c.api = vec![ApiPath::GlslCore, ApiPath::Vulkan];
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("`vk`") && e.contains("lookup.delivery"), "{e}");
}

#[test]
fn stage_is_left_out_when_fragment_and_takes_no_bias_outside_it() {
    assert!(!serde_json::to_string(&case()).unwrap().contains("stage"));
    let mut c = case();
    c.lookup.stage = Stage::Vertex;
    c.lookup.lod = 1.0;
    validate(&c).unwrap();
    let json = serde_json::to_string(&c).unwrap();
    assert!(json.contains("\"stage\":\"vertex\""), "{json}");
    assert_eq!(serde_json::from_str::<Case>(&json).unwrap(), c);
    // "The bias parameter is not accepted in any other shader stage" (GLSL 4.60 §8.9).
    c.lookup.bias = 0.5;
    let e = validate(&c).unwrap_err().to_string();
    assert!(
        e.contains("lookup.bias") && e.contains("not accepted in any other shader stage"),
        "{e}"
    );
    // A compute lookup: the GLSL 4.30 / GLSL ES 3.10, Vulkan and WGSL paths only (no compute
    // shader in GLSL 1.20 / 1.30), never with a bias.
    let mut c = case();
    c.lookup.stage = Stage::Compute;
    c.api = vec![ApiPath::GlslCore, ApiPath::Es300];
    validate(&c).unwrap();
    assert!(serde_json::to_string(&c)
        .unwrap()
        .contains("\"stage\":\"compute\""));
    c.lookup.bias = 0.25;
    assert!(validate(&c).is_err());
    c.lookup.bias = 0.0;
    c.api = vec![ApiPath::GlslCore, ApiPath::Glsl130];
    let e = validate(&c).unwrap_err().to_string();
    assert!(e.contains("`glsl130`") && e.contains("GLSL 4.30"), "{e}");
    // Only the paths with a vertex-shader lookup: not the fixed function, not Vulkan.
    for api in [ApiPath::FixedFunction, ApiPath::Vulkan] {
        let mut c = case();
        c.lookup.stage = Stage::Vertex;
        c.api = vec![ApiPath::GlslCore, api];
        let e = validate(&c).unwrap_err().to_string();
        assert!(
            e.contains(&format!("`{}`", api.key())) && e.contains("lookup.stage"),
            "{e}"
        );
    }
}
