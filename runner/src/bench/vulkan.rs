//! The Vulkan backends' rows: each driver over the `vulkan/` fixtures, cold (an empty Mesa shader
//! cache: lavapipe keeps one on disk, SwiftShader none), warm (the same worker again) and cached
//! (a new worker over the filled cache), and the cost per check once the pipelines exist, with
//! the pipelines the worker compiled (its `vk-worker: N pipelines` line is for `run -v`; here the
//! count of distinct shader keys the cases plan is given).

use super::run::BenchOptions;
use super::{ids, suite, Measurement, Unavailable};
use std::collections::HashSet;
use std::path::PathBuf;

/// The Vulkan backends a bench measures (`vk:native` would be one of them again here).
pub const BACKENDS: [&str; 2] = ["vk:lavapipe", "vk:swiftshader"];

/// The fixtures of the Vulkan rows: the whole `vulkan/` grid (quick: its 2D NEAREST file).
fn fixtures(o: &BenchOptions) -> Vec<PathBuf> {
    let (sub, file) = ("vulkan", "vulkan/2d/nearest.json");
    o.fixtures
        .iter()
        .map(|f| if o.quick { f.join(file) } else { f.join(sub) })
        .filter(|p| p.exists())
        .collect()
}

/// Distinct `vk` shader keys the cases plan: one pipeline each in the worker.
fn shader_keys(fixtures: &[PathBuf]) -> usize {
    let set = crate::run::load_cases(fixtures);
    let cases: Vec<shadowcheck_model::Case> = set.cases.into_iter().map(|l| l.case).collect();
    let mut keys = HashSet::new();
    for job in shadowcheck_plan::sweep::jobs(&cases) {
        if let Ok(p) = shadowcheck_plan::paths::plan_in(
            shadowcheck_model::ApiPath::Vulkan,
            job.case,
            &job.lookup,
            shadowcheck_plan::LookupForm::Auto,
            false,
        ) {
            keys.insert(p.key);
        }
    }
    keys.len()
}

/// Per Vulkan backend that starts: its end-to-end rows; what could not run is in the second list.
pub fn rows(
    o: &BenchOptions,
    progress: &mut dyn FnMut(&str),
) -> (Vec<Measurement>, Vec<Unavailable>) {
    let mut rows = Vec::new();
    let mut missing = Vec::new();
    let fx = fixtures(o);
    if fx.is_empty() {
        missing.push(Unavailable {
            what: "vulkan".into(),
            backend: None,
            reason: "no vulkan/ fixtures under --fixtures".into(),
        });
        return (rows, missing);
    }
    let keys = shader_keys(&fx);
    for name in BACKENDS {
        if !o.backends.is_empty() && !o.backends.iter().any(|b| b == name) {
            continue;
        }
        progress(&format!("{name}: end to end over the vulkan/ fixtures"));
        let e = match suite::e2e(name, &fx) {
            Ok(e) => e,
            Err(e) => {
                missing.push(Unavailable {
                    what: "vulkan end to end".into(),
                    backend: Some(name.into()),
                    reason: e,
                });
                continue;
            }
        };
        let what = format!(
            "{} verified tests ({} skipped) of {} cases, {} checks, at most {keys} pipelines",
            e.verified, e.skipped, e.cases_loaded, e.checks
        );
        rows.push(Measurement::new(
            ids::VK_E2E,
            Some(name),
            e.per_s(),
            "cases/s",
            format!("cold (empty shader cache), {what}: {:.2} s", e.total_s()),
        ));
        rows.push(Measurement::new(
            ids::VK_E2E_WARM,
            Some(name),
            e.warm_per_s(),
            "cases/s",
            format!(
                "the same cases again on the same worker ({:.3} s, the median of {} passes)",
                e.warm_run_s, e.warm_passes
            ),
        ));
        rows.push(Measurement::new(
            ids::VK_E2E_CACHED,
            Some(name),
            e.cached_per_s(),
            "cases/s",
            format!(
                "a new worker over the shader cache the cold pass filled ({:.2} s incl. worker start)",
                e.cached_s
            ),
        ));
        rows.push(Measurement::new(
            ids::VK_PER_CHECK,
            Some(name),
            e.warm_run_s / e.checks.max(1) as f64 * 1e6,
            "us/check",
            format!(
                "the warm pass ({:.3} s for {} checks): upload, draw, read-back and verdict once the pipelines exist",
                e.warm_run_s, e.checks
            ),
        ));
    }
    (rows, missing)
}
