//! Verdicts: from what a backend observed to an [`Outcome`].
//!
//! An observation is judged against the case's expectation (the oracle's, stored in the fixture),
//! re-evaluated by the oracle when the backend read back the stored texels (only within the upload
//! allowance, [`outside_upload_allowance`]; outside it a Fail of its own): Pass inside the
//! `strict` acceptance set, Warn inside `quality` only, Fail outside `quality`. The baseline then
//! turns the outcome into a [`Status`](crate::records::Status) ([`crate::baseline`]); both types,
//! and the [`ExpectedSummary`] kept in the record, are in [`crate::records`].

use crate::records::{ExpectedSummary, Outcome};
use shadowcheck_model::{Case, Channel, Expectation, Footprint, Judgement, Profile, Texels};

/// The verdict on one observation.
#[derive(Debug, Clone)]
pub struct Judged {
    pub outcome: Outcome,
    pub reason: Option<String>,
    pub expected: Option<ExpectedSummary>,
    /// The oracle's footprint of the lookup, filled for Warn and Fail (for the dump).
    pub footprint: Option<Footprint>,
}

/// Runs the oracle, turning a panic (e.g. a part not written yet) into an error string, so that a
/// single bad case never takes the run down.
pub fn oracle_evaluate(case: &Case) -> Result<shadowcheck_oracle::Evaluation, String> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        shadowcheck_oracle::evaluate(case)
    })) {
        Ok(Ok(ev)) => Ok(ev),
        Ok(Err(e)) => Err(e.to_string()),
        Err(p) => Err(format!(
            "oracle panicked: {}",
            p.downcast_ref::<&str>()
                .copied()
                .or(p.downcast_ref::<String>().map(|s| s.as_str()))
                .unwrap_or("?")
        )),
    }
}

fn layout_text(layout: &[Channel; 4]) -> String {
    layout.iter().map(|c| c.key()).collect::<Vec<_>>().join(",")
}

/// Which channels of `rgba` break the acceptance of `profile`, e.g. `g = 0 (expected r in {0.4})`.
fn channel_misses(
    e: &Expectation,
    layout: &[Channel; 4],
    profile: Profile,
    rgba: [f64; 4],
) -> String {
    let mut out = vec![];
    for ((name, ch), v) in ['r', 'g', 'b', 'a'].iter().zip(layout).zip(rgba) {
        let acc = e.channel_acceptance(profile, *ch);
        if !e.channel_accepts(profile, *ch, v) {
            let want = match ch {
                Channel::R => format!("r in {}", acc.map(|a| a.to_string()).unwrap_or_default()),
                Channel::G0 | Channel::G1 | Channel::G2 | Channel::G3 => format!(
                    "{} in {}",
                    ch.key(),
                    acc.map(|a| a.to_string()).unwrap_or_default()
                ),
                Channel::ROrZero => format!(
                    "0 or r in {}",
                    acc.map(|a| a.to_string()).unwrap_or_default()
                ),
                Channel::Zero => "0".to_string(),
                _ => "1".to_string(),
            };
            out.push(format!("{name} = {v} (expected {want})"));
        }
    }
    out.join(", ")
}

/// For a Fail on a path whose layout has other readings ([`Expectation::other_layouts`]): what each
/// of them found wrong too, e.g. `; under the other reading `gather-swizzle` (g0,g1,g2,g3): ...`.
fn other_readings_missed(
    e: &Expectation,
    api: shadowcheck_model::ApiPath,
    profile: Profile,
    rgba: [f64; 4],
) -> String {
    e.other_layouts
        .get(&api)
        .into_iter()
        .flatten()
        .map(|o| {
            format!(
                "; under the other reading `{}` ({}): {}",
                o.reading,
                layout_text(&o.layout),
                channel_misses(e, &o.layout, profile, rgba)
            )
        })
        .collect()
}

fn summary(e: &Expectation, layout: &[Channel; 4], profile: Profile) -> ExpectedSummary {
    let get = |p| {
        e.accept
            .get(&p)
            .map(|a| a.to_string())
            .unwrap_or_else(|| "(none)".into())
    };
    ExpectedSummary {
        spec_value: e.spec_value,
        strict: get(Profile::Strict),
        quality: get(Profile::Quality),
        layout: layout_text(layout),
        profile,
        citations: e.citations.clone(),
    }
}

/// The first stored texel outside the upload allowance, as "texel i: fixture X, stored Y".
///
/// An implementation may store a texel only as the upload defines it: a unorm value as the fixture's
/// integer or either neighbouring integer (§2.3.5.2 (2.3): "one of the two unsigned binary integer
/// values ... closest"), a float depth as the fixture's value clamped to [0,1] (§8.5: "For depth
/// component groups, the depth value is clamped to [0, 1]"; a subnormal may be flushed to 0). Anything
/// else (another value, another type, another count) is not a storage choice but an upload bug, or a
/// backend that lies about `stored` to turn its Fails into Passes.
///
/// A format the oracle lets an implementation hold at another precision
/// (`shadowcheck_oracle::sample::wider_storage`: §8.5.1 "at least", DEPTH_COMPONENT32 held at 24
/// bits or as a float) is read back at its nominal width after that storage: the texel may then be
/// off by one step of the storage width plus one step of the read-back width.
pub fn outside_upload_allowance(
    format: shadowcheck_model::Format,
    fixture: &Texels,
    stored: &Texels,
) -> Option<String> {
    match (fixture, stored) {
        (Texels::Unorm(f), Texels::Unorm(s)) => {
            if f.len() != s.len() {
                return Some(format!(
                    "{} texels in the fixture, {} stored",
                    f.len(),
                    s.len()
                ));
            }
            let bits = format.unorm_bits().unwrap_or(32);
            let step = |b: u32| 1.0 / ((1u64 << b) - 1) as f64;
            let widths = shadowcheck_oracle::sample::wider_storage(format, bits);
            let ok = |a: u32, b: u32| {
                a.abs_diff(b) <= 1
                    || widths
                        .iter()
                        .any(|&w| (a.abs_diff(b) as f64) * step(bits) <= step(w) + step(bits))
            };
            f.iter()
                .zip(s)
                .enumerate()
                .find(|(_, (a, b))| !ok(**a, **b))
                .map(|(i, (a, b))| format!("texel {i}: fixture {a}, stored {b}"))
        }
        (Texels::Float(f), Texels::Float(s)) => {
            if f.len() != s.len() {
                return Some(format!(
                    "{} texels in the fixture, {} stored",
                    f.len(),
                    s.len()
                ));
            }
            let ok = |a: f32, b: f32| {
                let c = a.clamp(0.0, 1.0);
                b == c || (b == 0.0 && c.abs() < f32::MIN_POSITIVE)
            };
            f.iter()
                .zip(s)
                .enumerate()
                .find(|(_, (a, b))| !ok(**a, **b))
                .map(|(i, (a, b))| format!("texel {i}: fixture {a}, stored {b}"))
        }
        // A colour format of several components: each component an integer of the format's
        // bits, stored as uploaded or as a neighbour (§2.3.5.2 (2.3)).
        (Texels::Colour(f), Texels::Colour(s)) => {
            if f.len() != s.len() {
                return Some(format!(
                    "{} texels in the fixture, {} stored",
                    f.len(),
                    s.len()
                ));
            }
            f.iter()
                .zip(s)
                .enumerate()
                .find(|(_, (a, b))| a.iter().zip(b.iter()).any(|(x, y)| x.abs_diff(*y) > 1))
                .map(|(i, (a, b))| format!("texel {i}: fixture {a:?}, stored {b:?}"))
        }
        _ => Some("the stored texels are of another type than the fixture's".to_string()),
    }
}

/// Judges `rgba` observed through `api` for `case`. `stored`: the level-0 texels the backend read
/// back; within the upload allowance ([`outside_upload_allowance`]) the oracle re-evaluates the case
/// with those texels (PROTOCOL.md §2), outside it the observation is a Fail of its own.
pub fn judge(
    case: &Case,
    api: shadowcheck_model::ApiPath,
    rgba: [f64; 4],
    stored: Option<&Texels>,
) -> Judged {
    // The case the verdict is about: with the texels the implementation really stored, if known.
    let fixture_texels = case.texture.levels.first().map(|l| &l.depth);
    if let (Some(f), Some(s)) = (fixture_texels, stored) {
        if let Some(what) = outside_upload_allowance(case.texture.format, f, s) {
            let expected = case.expect.as_ref().and_then(|e| {
                e.layout
                    .get(&api)
                    .map(|l| summary(e, l, Profile::loosest()))
            });
            return Judged {
                outcome: Outcome::Fail,
                reason: Some(format!("stored texel outside the upload allowance: {what}")),
                expected,
                footprint: None,
            };
        }
    }
    let restored;
    let (subject, mut evaluation) = match stored {
        Some(t) if case.texture.levels.first().map(|l| &l.depth) != Some(t) => {
            let mut c = case.clone();
            if let Some(l) = c.texture.levels.first_mut() {
                l.depth = t.clone();
            }
            c.expect = None;
            restored = c;
            (&restored, None)
        }
        _ => (case, None),
    };
    let expect: std::borrow::Cow<'_, Expectation> = match &subject.expect {
        Some(e) => std::borrow::Cow::Borrowed(e),
        None => match oracle_evaluate(subject) {
            Ok(ev) => {
                let e = ev.expect.clone();
                evaluation = Some(ev);
                std::borrow::Cow::Owned(e)
            }
            Err(msg) => {
                return Judged {
                    outcome: Outcome::Skip,
                    reason: Some(format!("no expectation for this case: {msg}")),
                    expected: None,
                    footprint: None,
                }
            }
        },
    };
    let Some(layout) = expect.layout.get(&api).copied() else {
        return Judged {
            outcome: Outcome::Skip,
            reason: Some(format!(
                "the expectation has no layout for API path `{api}`"
            )),
            expected: None,
            footprint: None,
        };
    };
    let judgement = expect.judge(api, rgba).unwrap_or(Judgement::Outside);
    let (outcome, profile) = match judgement {
        Judgement::Strictest => (Outcome::Pass, Profile::strictest()),
        Judgement::Looser(p) => (Outcome::Warn, p),
        Judgement::Outside => (Outcome::Fail, Profile::loosest()),
    };
    let mut footprint = None;
    let mut reason = None;
    if outcome != Outcome::Pass {
        reason = Some(match judgement {
            Judgement::Looser(p) => {
                let strictest = Profile::strictest();
                format!(
                    "inside the {p} acceptance set, outside {strictest}: {}",
                    channel_misses(&expect, &layout, strictest, rgba)
                )
            }
            _ => format!(
                "outside the {profile} acceptance set: {}{}",
                channel_misses(&expect, &layout, profile, rgba),
                other_readings_missed(&expect, api, profile, rgba)
            ),
        });
        let ev = match evaluation {
            Some(ev) => Ok(ev),
            None => oracle_evaluate(subject),
        };
        match ev {
            Ok(ev) => footprint = Some(ev.footprint),
            Err(msg) => reason = reason.map(|r| format!("{r} (no footprint: {msg})")),
        }
    }
    // What was expected is kept for the reports only where something is to be explained (the
    // fixture has it for the rest), which keeps results.jsonl small and the pass path cheap.
    let expected = (outcome != Outcome::Pass).then(|| summary(&expect, &layout, profile));
    Judged {
        outcome,
        reason,
        expected,
        footprint,
    }
}

/// The verdict on a test's lookups: the case's own and its sweep's points ([`Case::sweep`]), and
/// the RGBA the verdict is about. The outcome is the worst of them (Pass < Warn < Skip < Fail);
/// the reason, expected values and footprint are those of the first lookup with that outcome,
/// and a point's reason names it. A point inside its strictest acceptance set is a pass without
/// building its case; any other is judged like a case of its own ([`Case::point_case`]), the
/// backend's stored texels included.
pub fn judge_sweep(
    case: &Case,
    api: shadowcheck_model::ApiPath,
    rgba: [f64; 4],
    stored: Option<&Texels>,
    sweep: &[[f64; 4]],
) -> (Judged, [f64; 4]) {
    let main = judge(case, api, rgba, stored);
    if case.sweep.is_empty() && sweep.is_empty() {
        return (main, rgba);
    }
    if sweep.len() != case.sweep.len() {
        let j = Judged {
            outcome: Outcome::Fail,
            reason: Some(format!(
                "implementation error: {} sweep results; the case has {} points",
                sweep.len(),
                case.sweep.len()
            )),
            expected: None,
            footprint: None,
        };
        return (j, rgba);
    }
    let rank = |o: Outcome| match o {
        Outcome::Pass => 0,
        Outcome::Warn => 1,
        Outcome::Skip => 2,
        _ => 3,
    };
    let layout = case.expect.as_ref().and_then(|e| e.layout.get(&api));
    let fixture_texels = case.texture.levels.first().map(|l| &l.depth);
    let same_texels = stored.is_none() || stored == fixture_texels;
    let mut worst = (main, rgba);
    for (k, (p, &got)) in case.sweep.iter().zip(sweep).enumerate() {
        let fast = same_texels
            && layout
                .zip(p.expect.as_ref())
                .is_some_and(|(l, e)| e.passes(l, got));
        if fast {
            continue;
        }
        let Some(point) = case.point_case(k) else {
            continue;
        };
        let mut j = judge(&point, api, got, stored);
        if rank(j.outcome) > rank(worst.0.outcome) {
            j.reason = j.reason.map(|r| {
                format!(
                    "sweep point {k} (coord {:?}, Dref {}): {r}",
                    p.coord, p.dref
                )
            });
            worst = (j, got);
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::KeyMap;
    use shadowcheck_model::*;

    /// GL 4.6 core, 2x1 D16 texture (Dt = 0 and 1), NEAREST at the centre of texel 0, LEQUAL, Dref 0.5:
    /// Table 8.23 gives r = 0 (0.5 <= 0 is false).
    fn case(with_expect: bool) -> Case {
        let expect = with_expect.then(|| {
            let mut accept = KeyMap::new();
            accept.insert(Profile::Strict, Acceptance(vec![Interval::point(0.0)]));
            accept.insert(Profile::Quality, Acceptance(vec![Interval::new(0.0, 0.1)]));
            let mut layout = KeyMap::new();
            layout.insert(
                ApiPath::GlslCore,
                [
                    Channel::R,
                    Channel::Unused,
                    Channel::Unused,
                    Channel::Unused,
                ],
            );
            Expectation {
                spec_value: Some(0.0),
                accept,
                layout,
                other_layouts: Default::default(),
                gather: None,
                implementation_defined: None,
                citations: vec![],
            }
        });
        Case {
            sweep: vec![],
            id: "t".into(),
            spec: Spec::Gl46,
            api: vec![ApiPath::GlslCore],
            texture: Texture {
                target: Target::T2d,
                format: Format::D16,
                base_level: 0,
                levels: vec![Level {
                    width: 2,
                    height: 1,
                    layers: 1,
                    depth: Texels::Unorm(vec![0, 65535]),
                    stencil: None,
                }],
            },
            sampler: Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest),
            lookup: Lookup {
                coord: [0.25, 0.5, 0.0, 1.0],
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
            expect,
        }
    }

    #[test]
    fn judge_by_profile_and_layout() {
        let c = case(true);
        assert_eq!(
            judge(&c, ApiPath::GlslCore, [0.0, 7.0, 7.0, 7.0], None).outcome,
            Outcome::Pass
        );
        let w = judge(&c, ApiPath::GlslCore, [0.05, 0.0, 0.0, 1.0], None);
        assert_eq!(w.outcome, Outcome::Warn);
        assert!(w.reason.unwrap().contains("r = 0.05 (expected r in {0})"));
        let f = judge(&c, ApiPath::GlslCore, [1.0, 0.0, 0.0, 1.0], None);
        assert_eq!(f.outcome, Outcome::Fail);
        assert_eq!(f.expected.unwrap().strict, "{0}");
        // The oracle's footprint: texel (0,0,0), stored 0, failing the compare, weight 1.
        let fp = f.footprint.expect("footprint from the oracle");
        assert_eq!(fp.texels.len(), 1);
        assert_eq!(
            (fp.texels[0].xyz, fp.texels[0].pass, fp.texels[0].weight),
            (Some([0, 0, 0]), Some(false), 1.0)
        );
        assert_eq!(
            judge(&c, ApiPath::FixedFunction, [0.0; 4], None).outcome,
            Outcome::Skip
        );
    }

    #[test]
    fn either_reading_of_a_two_reading_layout_passes_and_a_fail_names_both() {
        // The case's expectation with a second reading on `core`: (r,-,-,-) or (0,0,0,0), as a
        // swizzled gather's or a compatibility depth read's readings are (`other_layouts`).
        let mut c = case(true);
        if let Some(e) = c.expect.as_mut() {
            e.other_layouts.insert(
                ApiPath::GlslCore,
                vec![shadowcheck_model::OtherLayout {
                    reading: "gather-swizzle".into(),
                    layout: [Channel::One; 4],
                }],
            );
        }
        let judge_core = |rgba| judge(&c, ApiPath::GlslCore, rgba, None);
        assert_eq!(judge_core([0.0, 7.0, 7.0, 7.0]).outcome, Outcome::Pass);
        assert_eq!(judge_core([1.0; 4]).outcome, Outcome::Pass);
        let f = judge_core([0.5, 1.0, 1.0, 1.0]);
        assert_eq!(f.outcome, Outcome::Fail);
        let why = f.reason.unwrap_or_default();
        assert!(
            why.contains("r = 0.5 (expected r in [0, 0.1])")
                && why.contains(
                    "under the other reading `gather-swizzle` (1,1,1,1): r = 0.5 (expected 1)"
                ),
            "{why}"
        );
    }

    #[test]
    fn stored_texels_outside_the_upload_allowance_are_a_fail_of_their_own() {
        // The implementation claims it stored 65535 in texel 0 (the fixture holds 0): no storage
        // choice gives that, so r = 1 is not re-judged as a Pass.
        let c = case(true);
        let stored = Texels::Unorm(vec![65535, 65535]);
        let j = judge(&c, ApiPath::GlslCore, [1.0, 0.0, 0.0, 1.0], Some(&stored));
        assert_eq!(j.outcome, Outcome::Fail);
        let why = j.reason.unwrap_or_default();
        assert!(
            why.contains("stored texel outside the upload allowance")
                && why.contains("fixture 0, stored 65535"),
            "{why}"
        );
        // Float depth: the [0,1] clamp is the only change allowed.
        let f = Texels::Float(vec![1.5, 0.25]);
        let d32f = Format::D32f;
        assert_eq!(
            outside_upload_allowance(d32f, &f, &Texels::Float(vec![1.0, 0.25])),
            None
        );
        assert!(outside_upload_allowance(d32f, &f, &Texels::Float(vec![1.5, 0.25])).is_some());
        assert!(outside_upload_allowance(d32f, &f, &Texels::Unorm(vec![1, 0])).is_some());
    }

    #[test]
    fn d32_held_at_24_bits_or_as_a_float_is_inside_the_upload_allowance() {
        // DEPTH_COMPONENT32 may be held at 24 bits (GL 4.6 Table 8.13 "desired component
        // resolutions"): 0.8 = 0xCCCCCCCC stored as f32 0.800000011920929 reads back as 0xCCCCCCFF
        // (Mesa 22.3 does this). One 24-bit step plus one 32-bit step is the most it may move.
        let f = Texels::Unorm(vec![0xCCCC_CCCC]);
        assert_eq!(
            outside_upload_allowance(Format::D32, &f, &Texels::Unorm(vec![0xCCCC_CCFF])),
            None
        );
        let step24 = 257; // one 24-bit step in 32-bit units, rounded up: (2^32-1)/(2^24-1) = 256.00002
        assert_eq!(
            outside_upload_allowance(Format::D32, &f, &Texels::Unorm(vec![0xCCCC_CCCC + step24])),
            None
        );
        assert!(outside_upload_allowance(
            Format::D32,
            &f,
            &Texels::Unorm(vec![0xCCCC_CCCC + 3 * step24])
        )
        .is_some());
        // A D16 is never held with fewer bits: only the neighbouring integers.
        let f16 = Texels::Unorm(vec![1000]);
        assert_eq!(
            outside_upload_allowance(Format::D16, &f16, &Texels::Unorm(vec![1001])),
            None
        );
        assert!(outside_upload_allowance(Format::D16, &f16, &Texels::Unorm(vec![1002])).is_some());
    }

    #[test]
    fn stored_texels_read_back_are_re_evaluated_by_the_oracle() {
        // Stored one integer off (texel 0 = 1, inside the upload allowance): re-evaluated, Dt = 1/65535
        // and LEQUAL 0.5 still fails: r = 0 passes, r = 1 fails.
        let c = case(true);
        let stored = Texels::Unorm(vec![1, 65535]);
        assert_eq!(
            judge(&c, ApiPath::GlslCore, [0.0, 0.0, 0.0, 1.0], Some(&stored)).outcome,
            Outcome::Pass
        );
        assert_eq!(
            judge(&c, ApiPath::GlslCore, [1.0, 0.0, 0.0, 1.0], Some(&stored)).outcome,
            Outcome::Fail
        );
        assert_eq!(
            judge(&c, ApiPath::GlslCore, [1.0, 0.0, 0.0, 1.0], None).outcome,
            Outcome::Fail
        );
        // Without a stored expectation the oracle supplies one.
        assert_eq!(
            judge(&case(false), ApiPath::GlslCore, [0.0, 0.0, 0.0, 1.0], None).outcome,
            Outcome::Pass
        );
    }
}
