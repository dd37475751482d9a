//! A colour texture of several components (RG8, RGB8, RGBA8, RGBA4): the texture unit "operates in
//! the normal manner and texture comparison is bypassed" (GL 4.6 §8.23.1, ES 3.2 §8.20.1), and the
//! result is the texture base colour Cb of Table 15.1 (ES 3.2 Table 14.1; GL 2.1 Table 3.20),
//! swizzled. Each component is filtered on its own ("the filtered texture value τ is computed in
//! the manner described in sections 8.14 and 8.15", §11.1.3.5, component-wise), so the one-
//! component evaluation of an R8 texture is run once per component, each reading that component
//! of the texels and of TEXTURE_BORDER_COLOR. The per-component sets go to the expectation's four
//! component sets (`Expectation::gather`, read by the `g0`..`g3` channels); `accept` and
//! `spec_value` describe component 0 (R), as for a gather.

use super::{finish, undefined, value, Eval, Layouts};
use crate::profile::PROFILES;
use crate::rules::Rules;
use crate::sample::Kind;
use crate::Evaluation;
use shadowcheck_model::{Acceptance, Case, Footprint, Interval, KeyMap, Profile};

const NAMES: [&str; 4] = ["R", "G", "B", "A"];

/// Evaluates a complete colour lookup of `components` (2..=4) components.
pub(super) fn run(
    mut e: Eval,
    rules: &Rules,
    case: &Case,
    layouts: Layouts,
    components: usize,
) -> Evaluation {
    let mut sets: Vec<Vec<Acceptance>> = Vec::with_capacity(4);
    let mut first: Option<(Option<f64>, Footprint)> = None;
    for (c, name) in NAMES.iter().enumerate().take(components) {
        // Component 0's derivation is the case's; the others add one step each (their texel
        // selection, λ and weights are component 0's).
        let mut scratch = Eval {
            steps: Vec::new(),
            cites: Vec::new(),
            notes: Vec::new(),
        };
        let target = if c == 0 { &mut e } else { &mut scratch };
        match value(target, rules, case, Kind::Colour, c) {
            Ok((spec_value, acc, fp)) => {
                if c == 0 {
                    first = Some((spec_value, fp));
                } else {
                    scratch.notes.into_iter().for_each(|n| e.note(n));
                    e.step(
                        format!(
                            "component {} of Cb: {} (filtered like R, from component {c} of the texels and of TEXTURE_BORDER_COLOR)",
                            name,
                            spec_value.map_or("no single value".to_string(), |v| v.to_string())
                        ),
                        "GL 4.6 §11.1.3.5 (τ computed per §8.14, §8.15), Table 15.1",
                    );
                }
                sets.push(acc);
            }
            Err((iv, why)) => return undefined_all(e, iv, layouts, why),
        }
    }
    // The components the base format lacks: G and B read 0, A reads 1 (Table 15.1).
    for c in components..4 {
        let v = if c == 3 { 1.0 } else { 0.0 };
        sets.push(vec![Acceptance(vec![Interval::point(v)]); PROFILES.len()]);
    }
    let (spec_value, fp) = first.unwrap_or((None, Footprint::default()));
    let per: Vec<KeyMap<Profile, Acceptance>> = sets
        .iter()
        .map(|acc| {
            PROFILES
                .iter()
                .map(|p| p.profile)
                .zip(acc.clone())
                .collect()
        })
        .collect();
    let acc0 = sets.first().cloned().unwrap_or_default();
    let mut ev = finish(e, spec_value, acc0, layouts, fp);
    ev.expect.gather = <[KeyMap<Profile, Acceptance>; 4]>::try_from(per).ok();
    ev
}

/// A lookup whose texel selection is undefined: every component may be anything in `iv`.
fn undefined_all(e: Eval, iv: Interval, layouts: Layouts, why: &'static str) -> Evaluation {
    let mut ev = undefined(e, iv, layouts, why);
    let set: KeyMap<Profile, Acceptance> = PROFILES
        .iter()
        .map(|p| (p.profile, Acceptance(vec![iv])))
        .collect();
    ev.expect.gather = Some([set.clone(), set.clone(), set.clone(), set]);
    ev
}
