//! End-to-end tests of the unit (case in, RGBA out). Every expected value is computed by hand from
//! the specification text cited next to it, never taken from a driver.

use crate::*;
use shadowcheck_model::*;

mod addressing;
mod comparison;
mod unit_state;
mod webgpu;

/// A 2D case on `spec` with one level of `w`×`h` unorm texels.
pub(super) fn case2d(
    spec: Spec,
    format: Format,
    w: u32,
    h: u32,
    texels: Vec<u32>,
    func: CompareFunc,
    filter: Filter,
) -> Case {
    let api = match spec {
        Spec::Es2Ext => ApiPath::Es100Ext,
        Spec::Gles32 => ApiPath::Es300,
        Spec::Gl46 => ApiPath::GlslCore,
        Spec::Vulkan => ApiPath::Vulkan,
        Spec::WebGpu => ApiPath::Wgsl,
        _ => ApiPath::FixedFunction,
    };
    let depth = if format.is_fixed_point() {
        Texels::Unorm(texels)
    } else {
        Texels::Float(texels.iter().map(|&x| x as f32 / 4.0).collect())
    };
    Case {
        sweep: vec![],
        id: "t".into(),
        spec,
        api: vec![api],
        texture: Texture {
            target: Target::T2d,
            format,
            base_level: 0,
            levels: vec![Level {
                width: w,
                height: h,
                layers: 1,
                depth,
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, func, filter),
        lookup: Lookup {
            coord: [0.5, 0.5, 0.0, 1.0],
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

pub(super) fn float_case(spec: Spec, texels: Vec<f32>, func: CompareFunc) -> Case {
    let mut c = case2d(spec, Format::D32f, 1, 1, vec![0], func, Filter::Nearest);
    c.texture.levels[0].width = texels.len() as u32;
    c.texture.levels[0].depth = Texels::Float(texels);
    c
}

pub(super) fn r(case: &Case) -> f32 {
    let api = case.api[0];
    SoftUnit::new(case.spec).sample(case, api).unwrap()[0]
}

/// The D16 integer nearest to x (exact for multiples of 1/5, 1/3, 1/17, … since 65535 = 3·5·17·257).
pub(super) fn d16(x: f64) -> u32 {
    (x * 65535.0).round() as u32
}
