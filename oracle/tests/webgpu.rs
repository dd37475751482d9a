//! The WebGPU rules (oracle/src/webgpu.rs) on cases built by hand: the compare direction of
//! GPUCompareFunction, the unstated clamp of depth_ref, the filtering "should", and what WebGPU
//! cannot express (not applicable, never a GL error).

mod common;

use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};

fn strict(c: &Case) -> Acceptance {
    eval(c)
        .expect
        .accept
        .get(&Profile::Strict)
        .cloned()
        .unwrap()
}

#[test]
fn less_passes_when_the_provided_value_is_less_than_the_sampled_one() {
    // "less": "A provided value passes the comparison test if it is less than the sampled value."
    let c = one(Spec::WebGpu, Format::D32f, CompareFunc::Less, 0.25, 0.5);
    assert_eq!(value(&c), 1.0);
    let c = one(Spec::WebGpu, Format::D32f, CompareFunc::Less, 0.75, 0.5);
    assert_eq!(value(&c), 0.0);
    let c = one(Spec::WebGpu, Format::D32f, CompareFunc::Greater, 0.75, 0.5);
    assert_eq!(value(&c), 1.0);
}

#[test]
fn an_out_of_range_reference_is_unclamped_in_the_spec_value_and_both_readings_are_accepted() {
    // Dref 1.5 against a D16 texel at 1.0 with LEQUAL: unclamped 1.5 <= 1 fails (0), clamped
    // 1 <= 1 passes (1). WebGPU says neither: the literal reading is the spec value, the clamp
    // (what a Vulkan-backed implementation does for UNORM formats) is accepted too.
    let c = one(Spec::WebGpu, Format::D16, CompareFunc::Lequal, 1.5, 1.0);
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.0));
    let s = strict(&c);
    assert!(s.contains(0.0) && s.contains(1.0), "{s:?}");
    assert!(e.expect.implementation_defined.is_some());
    // Vulkan decides it: D16 is UNORM, so Dref is clamped and only 1 is accepted.
    let v = one(Spec::Vulkan, Format::D16, CompareFunc::Lequal, 1.5, 1.0);
    let sv = strict(&v);
    assert!(sv.contains(1.0) && !sv.contains(0.0), "{sv:?}");
}

#[test]
fn a_filtered_comparison_should_be_the_weighted_average_and_may_be_anything_in_0_1() {
    // 2x1 LINEAR between a passing and a failing texel at their midpoint: 0.5 is the spec value;
    // "Filtering should behave as usual, however it may be computed with lower precision or not
    // mix results at all": quality accepts [0, 1], strict only the average.
    let c = case2d(
        Spec::WebGpu,
        Format::D32f,
        CompareFunc::Lequal,
        Filter::Linear,
        2,
        1,
        &[0.25, 0.75],
        (0.5, 0.5),
        0.5,
    );
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.5));
    let s = strict(&c);
    assert!(
        s.contains(0.5) && !s.contains(0.0) && !s.contains(1.0),
        "{s:?}"
    );
    let q = e.expect.accept.get(&Profile::Quality).cloned().unwrap();
    assert!(q.contains(0.0) && q.contains(1.0), "{q:?}");
}

#[test]
fn the_result_is_one_f32_in_the_first_channel() {
    let c = one(Spec::WebGpu, Format::D24, CompareFunc::Always, 0.5, 0.5);
    let e = eval(&c);
    assert_eq!(
        e.expect.layout.get(&ApiPath::Wgsl),
        Some(&[
            Channel::R,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ])
    );
}

fn not_applicable(c: &Case) -> String {
    match evaluate(c) {
        Err(OracleError::NotApplicable { why, .. }) => why,
        other => panic!("{}: {other:?}", c.id),
    }
}

#[test]
fn what_webgpu_cannot_express_is_not_applicable_never_a_gl_error() {
    // No clamp-to-border address mode.
    let mut c = one(Spec::WebGpu, Format::D16, CompareFunc::Lequal, 0.5, 0.5);
    c.sampler.wrap_s = Wrap::ClampToBorder;
    assert!(!not_applicable(&c).is_empty());
    // No 1D depth texture type.
    let mut c = one(Spec::WebGpu, Format::D16, CompareFunc::Lequal, 0.5, 0.5);
    c.texture.target = Target::T1d;
    assert!(!not_applicable(&c).is_empty());
    // No projective built-in.
    let mut c = one(Spec::WebGpu, Format::D16, CompareFunc::Lequal, 0.5, 0.5);
    c.lookup.projective = true;
    assert!(not_applicable(&c).contains("projective"));
    // No SGIX operator is a GPUCompareFunction.
    let c = one(
        Spec::WebGpu,
        Format::D16,
        CompareFunc::LequalRSgix,
        0.5,
        0.5,
    );
    assert!(!not_applicable(&c).is_empty());
    // No 32-bit UNORM depth format.
    let c = one(Spec::WebGpu, Format::D32, CompareFunc::Lequal, 0.5, 0.5);
    assert!(not_applicable(&c).contains("d32"));
}
