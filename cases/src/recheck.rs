//! The trust check of the fixture loaders: a fixture's `expect` is re-derived with the linked oracle
//! when it loads, and a case whose written expectation (spec value, acceptance sets, layout) differs stops with an error naming the file,
//! the case, the first field that differs and the command that regenerates.
//! A stale or edited expectation would otherwise fail a correct implementation with a dump that
//! contradicts itself.

use crate::fixtures::{CaseRef, FixtureError};
use shadowcheck_model::{Case, Expectation};
use std::path::Path;

/// Checks `case.expect` against the oracle's; a case without `expect` has nothing to check.
pub(crate) fn check(
    file: &Path,
    at: &CaseRef,
    grid: &str,
    case: &Case,
) -> Result<(), FixtureError> {
    let Some(written) = &case.expect else {
        return Ok(());
    };
    let derived = shadowcheck_oracle::evaluate(case)
        .map_err(|e| FixtureError::Case {
            file: file.to_path_buf(),
            at: at.clone(),
            field: "expect".into(),
            msg: format!(
                "the fixture carries an expectation, but the oracle rejects the case: {e}"
            ),
        })?
        .expect;
    let mut diff = first_difference(written, &derived);
    // A sweep's points: each re-derived as the case of its own that it stands for.
    for k in 0..case.sweep.len() {
        if diff.is_some() {
            break;
        }
        let Some(point) = case.point_case(k) else {
            continue;
        };
        let Some(written) = &point.expect else {
            continue;
        };
        let derived = shadowcheck_oracle::evaluate(&point)
            .map_err(|e| FixtureError::Case {
                file: file.to_path_buf(),
                at: at.clone(),
                field: format!("sweep[{k}]"),
                msg: format!(
                    "the fixture carries an expectation for this point, but the oracle rejects it: {e}"
                ),
            })?
            .expect;
        diff = first_difference(written, &derived)
            .map(|(field, a, b)| (format!("sweep[{k}].{field}"), a, b));
    }
    match diff {
        None => Ok(()),
        Some((field, fixture, oracle)) => Err(FixtureError::StaleExpect {
            file: file.to_path_buf(),
            at: at.clone(),
            field,
            msg: format!(
                "the fixture's expectation {fixture} differs from the oracle's {oracle}: the fixture is stale or was edited; regenerate it with `shadowcheck gen --grid {grid} -o DIR` (DIR: the fixture directory it was generated into, e.g. cases/fixtures)"
            ),
        }),
    }
}

/// The first field a verdict rests on (spec value, acceptance per profile, layout per API path) in
/// which two expectations differ: (field path, written, derived). Citations and the
/// implementation-defined note explain a verdict without deciding it; they are not compared, so a
/// hand-written fixture may word them its own way.
fn first_difference(a: &Expectation, b: &Expectation) -> Option<(String, String, String)> {
    let opt = |v: Option<f64>| v.map_or("none".to_string(), |v| v.to_string());
    if a.spec_value != b.spec_value {
        return Some((
            "expect.spec_value".into(),
            opt(a.spec_value),
            opt(b.spec_value),
        ));
    }
    for p in a.accept.keys().chain(b.accept.keys()) {
        let (x, y) = (a.accept.get(p), b.accept.get(p));
        if x != y {
            let show = |v: Option<&shadowcheck_model::Acceptance>| {
                v.map_or("(missing)".to_string(), |v| v.to_string())
            };
            return Some((format!("expect.accept.{p}"), show(x), show(y)));
        }
    }
    for api in a.layout.keys().chain(b.layout.keys()) {
        let (x, y) = (a.layout.get(api), b.layout.get(api));
        if x != y {
            let show = |v: Option<&[shadowcheck_model::Channel; 4]>| {
                v.map_or("(missing)".to_string(), |l| {
                    l.iter().map(|c| c.key()).collect::<Vec<_>>().join(",")
                })
            };
            return Some((format!("expect.layout.{api}"), show(x), show(y)));
        }
    }
    None
}

/// Checks a state case's `expect` against the oracle's ([`shadowcheck_oracle::state::expect_state`]):
/// the error and the value read back (citations explain, they are not compared).
pub(crate) fn check_state(
    file: &Path,
    at: &CaseRef,
    grid: &str,
    case: &shadowcheck_model::StateCase,
) -> Result<(), FixtureError> {
    let Some(written) = &case.expect else {
        return Ok(());
    };
    let derived =
        shadowcheck_oracle::state::expect_state(case).map_err(|e| FixtureError::Case {
            file: file.to_path_buf(),
            at: at.clone(),
            field: "expect".into(),
            msg: format!("the oracle rejects the state case: {e}"),
        })?;
    let differs = if written.error != derived.error {
        Some((
            "expect.error",
            format!("{:?}", written.error),
            format!("{:?}", derived.error),
        ))
    } else if written.value != derived.value {
        Some((
            "expect.value",
            format!("{:?}", written.value),
            format!("{:?}", derived.value),
        ))
    } else {
        // What a context exposing an extension must do: the same extensions, errors and values.
        let outline = |e: &shadowcheck_model::StateExpect| -> Vec<String> {
            e.with_extension
                .iter()
                .map(|w| format!("{}: {:?} {:?}", w.extension, w.error, w.value))
                .collect()
        };
        let (w, d) = (outline(written), outline(&derived));
        (w != d).then(|| ("expect.with_extension", format!("{w:?}"), format!("{d:?}")))
    };
    match differs {
        None => Ok(()),
        Some((field, fixture, oracle)) => Err(FixtureError::StaleExpect {
            file: file.to_path_buf(),
            at: at.clone(),
            field: field.into(),
            msg: format!(
                "the fixture's expectation {fixture} differs from the oracle's {oracle}: the fixture is stale or was edited; regenerate it with `shadowcheck gen --grid {grid} -o DIR` (DIR: the fixture directory it was generated into, e.g. cases/fixtures)"
            ),
        }),
    }
}
