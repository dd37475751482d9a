//! Case builders shared by the oracle's integration tests.
#![allow(dead_code)]

use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, Evaluation};

/// The API paths a spec's lookups go through (the first one each spec defines).
pub fn api_for(spec: Spec) -> ApiPath {
    match spec {
        Spec::Sgix | Spec::SgixAmbient | Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs => {
            ApiPath::FixedFunction
        }
        Spec::Es2Ext => ApiPath::Es100Ext,
        Spec::Gl46 => ApiPath::GlslCore,
        Spec::Gles32 => ApiPath::Es300,
        Spec::Vulkan => ApiPath::Vulkan,
        Spec::WebGpu => ApiPath::Wgsl,
    }
}

/// Unorm integer for a value in [0,1] (exact for 0 and 1).
pub fn unorm(v: f64, bits: u32) -> u32 {
    (v * ((1u64 << bits) - 1) as f64).round() as u32
}

/// The depth texels of `format` for the given values (floats for D32F, nearest integers otherwise).
pub fn texels(format: Format, vals: &[f64]) -> Texels {
    match format.unorm_bits() {
        Some(b) => Texels::Unorm(vals.iter().map(|v| unorm(*v, b)).collect()),
        None => Texels::Float(vals.iter().map(|v| *v as f32).collect()),
    }
}

#[allow(clippy::too_many_arguments)]
/// A 2D case: `w`x`h` texture of `vals`, lookup at (s, t) with `dref`.
pub fn case2d(
    spec: Spec,
    format: Format,
    func: CompareFunc,
    filter: Filter,
    w: u32,
    h: u32,
    vals: &[f64],
    st: (f64, f64),
    dref: f64,
) -> Case {
    let stencil = if format.has_stencil() {
        Some(vec![0u8; (w * h) as usize])
    } else {
        None
    };
    Case {
        sweep: vec![],
        id: format!(
            "test/{}/{}/{}/{}",
            spec.key(),
            format.key(),
            func.key(),
            dref
        ),
        spec,
        api: vec![api_for(spec)],
        texture: Texture {
            target: Target::T2d,
            format,
            base_level: 0,
            levels: vec![Level {
                width: w,
                height: h,
                layers: 1,
                depth: texels(format, vals),
                stencil,
            }],
        },
        sampler: spec_sampler(spec, func, filter),
        lookup: Lookup {
            coord: [st.0, st.1, 0.0, 1.0],
            layer: 0.0,
            dref,
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

/// A comparing sampler with the harness defaults; SGIX_shadow's Table 3.8 lists only CLAMP and
/// REPEAT, so its cases clamp with CLAMP.
pub fn spec_sampler(spec: Spec, func: CompareFunc, filter: Filter) -> Sampler {
    let mut s = Sampler::new(CompareMode::Compare, func, filter);
    if matches!(spec, Spec::Sgix | Spec::SgixAmbient) {
        (s.wrap_s, s.wrap_t, s.wrap_r) = (Wrap::Clamp, Wrap::Clamp, Wrap::Clamp);
    }
    s
}

/// A 1x1 NEAREST case: one texel `dt`, reference `dref`.
pub fn one(spec: Spec, format: Format, func: CompareFunc, dref: f64, dt: f64) -> Case {
    case2d(
        spec,
        format,
        func,
        Filter::Nearest,
        1,
        1,
        &[dt],
        (0.5, 0.5),
        dref,
    )
}

pub fn eval(c: &Case) -> Evaluation {
    evaluate(c).unwrap_or_else(|e| panic!("{}: {e}", c.id))
}

/// The spec value of a case.
pub fn value(c: &Case) -> f64 {
    eval(c)
        .expect
        .spec_value
        .unwrap_or_else(|| panic!("{}: no spec value", c.id))
}

/// The default 'compare' function of a spec: LEQUAL, or SGIX's LEQUAL_R.
pub fn lequal(spec: Spec) -> CompareFunc {
    if matches!(spec, Spec::Sgix | Spec::SgixAmbient) {
        CompareFunc::LequalRSgix
    } else {
        CompareFunc::Lequal
    }
}
