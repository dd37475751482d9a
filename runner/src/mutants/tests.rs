//! Unit tests of the mutants module: the minimal-killing-case order, an empty suite, the catalog texts.
use super::*;

#[test]
fn complexity_orders_by_texels_then_levels_then_paths_then_id_length() {
    let small = Complexity {
        texels: 1,
        levels: 3,
        paths: 5,
        id_len: 90,
    };
    let more_texels = Complexity {
        texels: 2,
        levels: 1,
        paths: 1,
        id_len: 10,
    };
    let more_levels = Complexity {
        texels: 1,
        levels: 4,
        paths: 1,
        id_len: 10,
    };
    let longer_id = Complexity {
        texels: 1,
        levels: 3,
        paths: 5,
        id_len: 91,
    };
    assert!(small < more_texels && small < more_levels && small < longer_id);
}

#[test]
fn every_fault_is_described_and_only_the_spec_open_faults_are_called_unobservable() {
    for f in Fault::ALL {
        assert!(!about(*f).is_empty(), "{f}");
    }
    let un: Vec<Fault> = Fault::ALL
        .iter()
        .copied()
        .filter(|f| unobservable(*f).is_some())
        .collect();
    // A NaN reference (no ordered result) and a stencil read with the comparison on (§11.1.3.5:
    // undefined): no conforming result tells the faulty unit from the correct one.
    // A GLSL 1.30 ALPHA-mode shadow lookup has two accepted readings (r or 0), and so has a
    // swizzled shadow gather (the post-swizzle R of each texel, or the comparisons unswizzled).
    let mut want = vec![
        Fault::NanOrderedNotequal,
        Fault::StencilCompared,
        Fault::AlphaModeZeroOnGlsl130,
        Fault::GatherIgnoresSwizzle,
    ];
    want.sort_by_key(|f| Fault::ALL.iter().position(|x| x == f));
    assert_eq!(un, want);
}

#[test]
fn an_empty_suite_is_an_error() {
    assert!(matches!(Suite::new(vec![]), Err(MutantsError::NoCases)));
}
