//! The one hand-built case the plan's and the GL worker's unit tests start from (a D16 texture of
//! zeros, GL 4.6 core, LEQUAL NEAREST, Dref 0.5 at the centre); each test changes what it is
//! about. Built for tests only (the `test-support` feature outside this crate).
use shadowcheck_model::*;

/// A `w` x `h` x `layers` D16 case of `target` on the core path.
pub fn case(target: Target, w: u32, h: u32, layers: u32) -> Case {
    Case {
        sweep: vec![],
        id: "t".into(),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        texture: Texture {
            target,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: w,
                height: h,
                layers,
                depth: Texels::Unorm(vec![0; (w * h * layers) as usize]),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest),
        lookup: Lookup {
            coord: [0.5, 0.5, 0.5, 1.0],
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

/// A GL 4.6-era context of `api` with GLSL version `glsl` and no extensions.
pub fn info(api: crate::ContextApi, glsl: u32) -> crate::GlInfo {
    crate::GlInfo {
        api,
        es: api == crate::ContextApi::Es3,
        compat: api == crate::ContextApi::Compat,
        version: (4, 6),
        glsl,
        renderer: String::new(),
        version_string: String::new(),
        extensions: Default::default(),
        version_override: false,
        form: Default::default(),
    }
}
