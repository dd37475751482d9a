//! The committed fixtures cover every pair of unit-state factor levels each spec allows (gather x
//! swizzle x sampler object x seamless x DEPTH_TEXTURE_MODE x target x API path): the `interact`
//! family alone, and so the whole grid. A missing pair is named.

use shadowcheck_cases::fixtures;
use shadowcheck_cases::pairs::{self, PairCoverage, FACTORS};
use shadowcheck_model::*;
use std::path::PathBuf;

fn committed() -> Vec<Case> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fixtures");
    fixtures::load_path(&dir)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect()
}

fn describe(missing: &[(Spec, pairs::Pair)]) -> String {
    missing
        .iter()
        .map(|(spec, (i, a, j, b))| {
            format!("{spec}: {} = {a} with {} = {b}", FACTORS[*i], FACTORS[*j])
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn committed_interact_cases_cover_every_allowed_pair_of_every_spec() {
    let cases = committed();
    let mut cov = PairCoverage::default();
    for c in &cases {
        cov.add(c);
    }
    for interact_only in [true, false] {
        let missing = cov.missing(interact_only);
        assert!(
            missing.is_empty(),
            "{} level pairs allowed but not covered by the committed {} (run `cargo run --release -- gen --grid default -o cases/fixtures`):\n{}",
            missing.len(),
            if interact_only { "`interact` cases" } else { "cases" },
            describe(&missing)
        );
    }
    // The check can fail: without the gl46 `interact` cases, pairs go missing.
    let mut without = PairCoverage::default();
    for c in cases
        .iter()
        .filter(|c| !(c.spec == Spec::Gl46 && c.id.contains("/interact/")))
    {
        without.add(c);
    }
    assert!(without.missing(true).iter().any(|(s, _)| *s == Spec::Gl46));
}

#[test]
fn the_specs_with_unit_state_allow_the_pairs_the_tracker_asks_for() {
    let has = |spec: Spec, a: (&str, &str), b: (&str, &str)| {
        let fi = FACTORS.iter().position(|f| *f == a.0).unwrap();
        let fj = FACTORS.iter().position(|f| *f == b.0).unwrap();
        pairs::allowed(spec).contains(&(fi, a.1.to_string(), fj, b.1.to_string()))
    };
    // A gather with a swizzle, with a sampler object, at a seamless cube edge.
    assert!(has(Spec::Gl46, ("gather", "gather"), ("swizzle", "gbar")));
    assert!(has(
        Spec::Gles32,
        ("gather", "offsets"),
        ("sampler object", "bound")
    ));
    assert!(has(Spec::Gl46, ("gather", "gather"), ("seamless", "on")));
    // A sampler object on a rectangle texture; a compatibility swizzle on ff and glsl120.
    assert!(has(
        Spec::Gl46,
        ("sampler object", "bound"),
        ("target", "rect")
    ));
    assert!(has(Spec::Gl46, ("swizzle", "1r0g"), ("API path", "ff")));
    assert!(has(
        Spec::Gl46,
        ("swizzle", "rrr1"),
        ("API path", "glsl120")
    ));
    assert!(has(
        Spec::Gl46,
        ("swizzle", "gbar"),
        ("DEPTH_TEXTURE_MODE", "alpha")
    ));
    // Never: a gather on fixed function, a DEPTH_TEXTURE_MODE on core, a seamless enable on ES, a
    // gather with an offset on a cube map, a swizzle on Vulkan.
    assert!(!has(Spec::Gl46, ("gather", "gather"), ("API path", "ff")));
    assert!(!has(
        Spec::Gl46,
        ("DEPTH_TEXTURE_MODE", "red"),
        ("API path", "core")
    ));
    assert!(!has(Spec::Gles32, ("seamless", "on"), ("target", "cube")));
    assert!(!has(Spec::Gl46, ("gather", "offset"), ("target", "cube")));
    assert!(!has(Spec::Vulkan, ("swizzle", "gbar"), ("target", "2d")));
    // The legacy specs have DEPTH_TEXTURE_MODE on their three paths; ES 2.0 and SGIX nothing.
    assert!(has(
        Spec::Arb,
        ("DEPTH_TEXTURE_MODE", "intensity"),
        ("API path", "arbfp")
    ));
    assert!(pairs::allowed(Spec::Es2Ext).is_empty());
    assert!(pairs::allowed(Spec::Sgix).is_empty());
}
