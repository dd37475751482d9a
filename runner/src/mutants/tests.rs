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
fn every_fault_is_described_and_only_the_nan_fault_is_called_unobservable() {
    for f in Fault::ALL {
        assert!(!about(*f).is_empty(), "{f}");
    }
    let un: Vec<Fault> = Fault::ALL
        .iter()
        .copied()
        .filter(|f| unobservable(*f).is_some())
        .collect();
    assert_eq!(un, vec![Fault::NanOrderedNotequal]);
}

#[test]
fn an_empty_suite_is_an_error() {
    assert!(matches!(Suite::new(vec![]), Err(MutantsError::NoCases)));
}
