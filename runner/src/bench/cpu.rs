//! Single-thread CPU measurements: the oracle's verdicts and the `soft` unit's raw lookups.

use super::{ids, targets, targets17, Goal, Measurement, Target};
use shadowcheck_model::{
    Acceptance, ApiPath, Case, Channel, Expectation, Filter, KeyMap, PointExpectation, Profile,
    Spec,
};
use shadowcheck_soft::bench::Workload;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Repeats `f` (one pass over a workload) until at least `min` has elapsed (and at least once);
/// returns (passes, seconds).
pub fn repeat_for(min: Duration, mut f: impl FnMut()) -> (u64, f64) {
    let t0 = Instant::now();
    let mut n = 0u64;
    loop {
        f();
        n += 1;
        let e = t0.elapsed();
        if e >= min {
            return (n, e.as_secs_f64());
        }
    }
}

/// What an exact implementation returns through `api`: the spec value (or the middle of the first
/// strict interval) placed per the expectation's layout; `None` without a layout.
pub fn exact_rgba(e: &Expectation, api: ApiPath) -> Option<[f64; 4]> {
    let layout = e.layout.get(&api)?;
    let r = exact_r(e.spec_value, &e.accept);
    Some(layout.map(|c| {
        match c {
            Channel::R | Channel::ROrZero => r,
            Channel::Zero | Channel::Unused => 0.0,
            Channel::One => 1.0,
            Channel::G0 | Channel::G1 | Channel::G2 | Channel::G3 => c
                .gather_index()
                .and_then(|k| e.gather.as_ref()?[k].get(&shadowcheck_model::Profile::strictest()))
                .and_then(|a| a.0.first())
                .map_or(r, |i| (i.lo + i.hi) / 2.0),
        }
    }))
}

/// r of an exact implementation: the spec value, else the middle of the first interval of the
/// strictest profile present.
fn exact_r(spec_value: Option<f64>, accept: &KeyMap<Profile, Acceptance>) -> f64 {
    spec_value
        .or_else(|| {
            accept
                .values()
                .next()
                .and_then(|a| a.0.first())
                .map(|i| (i.lo + i.hi) / 2.0)
        })
        .unwrap_or(0.0)
}

/// What an exact implementation returns for a sweep point read through `layout`: r (as
/// [`exact_r`]) in the R channels, the constants elsewhere.
fn exact_point_rgba(pe: &PointExpectation, layout: &[Channel; 4]) -> [f64; 4] {
    let r = exact_r(pe.spec_value, &pe.accept);
    layout.map(|c| match c {
        Channel::One => 1.0,
        Channel::Zero | Channel::Unused => 0.0,
        _ => r,
    })
}

/// The oracle over `cases`, one thread: `evaluate` once per case and `Expectation::judge` of the
/// exact answer once per API path (a verdict = one judged (case, path)); then `judge` alone
/// against the stored expectations, which is what a run does per observation. Cases the oracle
/// rejects (GL errors, not applicable) count as evaluated, with no verdict.
pub fn oracle_rows(cases: &[Case], min: Duration) -> Vec<Measurement> {
    let mut verdicts_per_pass = 0u64;
    let (passes, secs) = repeat_for(min, || {
        let mut v = 0u64;
        for c in cases {
            if let Ok(ev) = shadowcheck_oracle::evaluate(black_box(c)) {
                for &api in &c.api {
                    if let Some(rgba) = exact_rgba(&ev.expect, api) {
                        black_box(ev.expect.judge(api, rgba));
                        v += 1;
                    }
                }
            }
        }
        verdicts_per_pass = v;
    });
    let verdicts = verdicts_per_pass * passes;
    let mut rows = vec![Measurement::new(
        ids::ORACLE_VERDICTS,
        None,
        verdicts as f64 / secs,
        "verdicts/s/core",
        format!("evaluate + judge, {} cases ({verdicts_per_pass} case x path verdicts) x {passes} passes in {secs:.2} s, 1 thread", cases.len()),
    )
    .with_target(Target::new(Goal::AtLeast, targets::ORACLE_VERDICTS_PER_S, "throughput goal"))];

    // judge only: the stored expectation against the exact answer, for every check a run judges
    // (a case's own lookup through `Expectation::judge`, each sweep point through
    // `PointExpectation::passes`, the fast path a run takes for a point inside its strict set).
    let judged: Vec<(&Expectation, ApiPath, [f64; 4])> = cases
        .iter()
        .filter_map(|c| c.expect.as_ref().map(|e| (c, e)))
        .flat_map(|(c, e)| {
            c.api
                .iter()
                .filter_map(move |&api| exact_rgba(e, api).map(|rgba| (e, api, rgba)))
        })
        .collect();
    let points: Vec<(&PointExpectation, &[Channel; 4], [f64; 4])> = cases
        .iter()
        .filter_map(|c| c.expect.as_ref().map(|e| (c, e)))
        .flat_map(|(c, e)| {
            c.api
                .iter()
                .filter_map(|api| e.layout.get(api))
                .flat_map(|layout| {
                    c.sweep.iter().filter_map(move |p| {
                        let pe = p.expect.as_ref()?;
                        Some((pe, layout, exact_point_rgba(pe, layout)))
                    })
                })
        })
        .collect();
    let per_pass = judged.len() + points.len();
    if per_pass > 0 {
        let (passes, secs) = repeat_for(min, || {
            for (e, api, rgba) in &judged {
                black_box(black_box(*e).judge(black_box(*api), black_box(*rgba)));
            }
            for (pe, layout, rgba) in &points {
                black_box(black_box(*pe).passes(black_box(layout), black_box(*rgba)));
            }
        });
        rows.push(Measurement::new(
            ids::ORACLE_JUDGE,
            None,
            (per_pass as u64 * passes) as f64 / secs,
            "verdicts/s/core",
            format!("Expectation::judge against the fixtures' stored expectations ({} case x path verdicts) and PointExpectation::passes for their sweep points ({}), x {passes} passes in {secs:.2} s, 1 thread", judged.len(), points.len()),
        ).with_target(Target::new(Goal::AtLeast, targets17::JUDGE_PER_S, "cold-run goal")));
    }
    rows
}

/// Size of the bench texture (texels per side) shared by the soft workload and the GL floor.
pub const BENCH_TEXTURE: u32 = 64;

/// The `soft` unit's raw lookups per second, one thread, on `soft::bench::Workload` (D24 2D,
/// LEQUAL, REPEAT) with NEAREST (the figure compared with llvmpipe) and LINEAR (PCF, 4 texels).
pub fn soft_rows(lookups: usize, min: Duration) -> Result<Vec<Measurement>, String> {
    let mut rows = Vec::new();
    for (id, filter) in [
        (ids::SOFT_LOOKUPS, Filter::Nearest),
        (ids::SOFT_LOOKUPS_LINEAR, Filter::Linear),
    ] {
        let w =
            Workload::new(Spec::Gl46, BENCH_TEXTURE, filter, lookups).map_err(|e| e.to_string())?;
        let mut sum = 0.0;
        let (passes, secs) = repeat_for(min, || sum += black_box(&w).run());
        black_box(sum);
        rows.push(Measurement::new(
            id,
            None,
            (lookups as u64 * passes) as f64 / secs,
            "lookups/s/core",
            format!(
                "PreparedTexture::lookup, {BENCH_TEXTURE}x{BENCH_TEXTURE} d24 2d {} lequal, {lookups} lookups x {passes} passes in {secs:.2} s, 1 thread",
                filter.key()
            ),
        ));
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::Interval;

    #[test]
    fn exact_rgba_follows_the_layout_and_is_judged_strict() {
        let mut accept = KeyMap::new();
        for &p in Profile::ALL {
            accept.insert(p, Acceptance(vec![Interval::point(1.0)]));
        }
        let mut layout = KeyMap::new();
        layout.insert(
            ApiPath::GlslCore,
            [Channel::R, Channel::Zero, Channel::Zero, Channel::One],
        );
        let e = Expectation {
            spec_value: Some(1.0),
            accept,
            layout,
            other_layouts: Default::default(),
            gather: None,
            implementation_defined: None,
            citations: vec![],
        };
        let rgba = exact_rgba(&e, ApiPath::GlslCore).unwrap();
        assert_eq!(rgba, [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(
            e.judge(ApiPath::GlslCore, rgba),
            Some(shadowcheck_model::Judgement::Strictest)
        );
        assert!(exact_rgba(&e, ApiPath::Es300).is_none());
    }

    #[test]
    fn exact_point_rgba_passes_its_own_strict_set_and_a_miss_does_not() {
        let mut accept = KeyMap::new();
        accept.insert(
            Profile::strictest(),
            Acceptance(vec![Interval::new(0.25, 0.5)]),
        );
        let pe = PointExpectation {
            spec_value: None,
            accept,
            implementation_defined: None,
        };
        let layout = [Channel::R, Channel::R, Channel::R, Channel::One];
        let rgba = exact_point_rgba(&pe, &layout);
        assert_eq!(rgba, [0.375, 0.375, 0.375, 1.0]);
        assert!(pe.passes(&layout, rgba));
        assert!(!pe.passes(&layout, [0.75, 0.375, 0.375, 1.0]));
    }
}
