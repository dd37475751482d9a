mod common;
use common::*;
use shadowcheck_model::*;

#[test]
fn brief_examples() {
    // ref 1.5 against Dt 1.0 with LEQUAL: 1 for D24 under GL 4.6, 0 for D32F.
    assert_eq!(value(&one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 1.5, 1.0)), 1.0);
    assert_eq!(value(&one(Spec::Gl46, Format::D32f, CompareFunc::Lequal, 1.5, 1.0)), 0.0);
    assert_eq!(value(&one(Spec::Arb, Format::D24, CompareFunc::Lequal, 1.5, 1.0)), 1.0);
    assert_eq!(value(&one(Spec::Es2Ext, Format::D24, CompareFunc::Lequal, 1.5, 1.0)), 1.0);
    assert_eq!(value(&one(Spec::Sgix, Format::D24, CompareFunc::LequalRSgix, 0.5, 0.3)), 1.0);
    let mut c = one(Spec::ArbAmbient, Format::D24, CompareFunc::Lequal, 0.8, 0.3);
    c.sampler.fail_value = Some(0.25);
    assert_eq!(value(&c), 0.25);
    let e = eval(&c);
    println!("{}", serde_json::to_string_pretty(&e).unwrap());
}

#[test]
fn linear_smoke() {
    let c = case2d(Spec::Gl46, Format::D16, CompareFunc::Lequal, Filter::Linear, 2, 2, &[0.25, 0.75, 0.75, 1.0], (0.5, 0.5), 0.5);
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.75));
    println!("{:?} {:?}", e.expect.accept, e.expect.implementation_defined);
}
