//! The rows of the backends that draw a spec grid of their own through a worker: the Vulkan drivers
//! over the `vulkan/` fixtures and WebGPU in headless Chromium over the `webgpu/` fixtures. Each is
//! measured cold (an empty Mesa shader cache: lavapipe keeps one on disk, SwiftShader none, Dawn's
//! is the browser profile's, new per worker), warm (the same worker again) and cached (a new worker
//! over the filled cache), and the cost per check once the pipelines exist, with the pipelines the
//! cases plan (the count of distinct shader keys; the workers compile one pipeline per key).

use super::run::BenchOptions;
use super::{ids, suite, Measurement, Unavailable};
use shadowcheck_model::ApiPath;
use std::collections::HashSet;
use std::path::PathBuf;

/// One API's grid and the backends measured over it.
pub struct Grid {
    /// The fixture subdirectory of the spec (`vulkan`, `webgpu`).
    pub sub: &'static str,
    /// The API path the backends draw.
    pub api: ApiPath,
    /// The backends a bench measures (`vk:native` would be one of them again here).
    pub backends: &'static [&'static str],
    /// The row ids: cold, warm, cached, cost per check.
    pub ids: [&'static str; 4],
}

/// The grids measured, in report order.
pub const GRIDS: [Grid; 2] = [
    Grid {
        sub: "vulkan",
        api: ApiPath::Vulkan,
        backends: &["vk:lavapipe", "vk:swiftshader"],
        ids: [
            ids::VK_E2E,
            ids::VK_E2E_WARM,
            ids::VK_E2E_CACHED,
            ids::VK_PER_CHECK,
        ],
    },
    Grid {
        sub: "webgpu",
        api: ApiPath::Wgsl,
        backends: &["webgpu:chromium"],
        ids: [
            ids::WEBGPU_E2E,
            ids::WEBGPU_E2E_WARM,
            ids::WEBGPU_E2E_CACHED,
            ids::WEBGPU_PER_CHECK,
        ],
    },
];

/// Is `name` one of the backends of [`GRIDS`]?
pub fn is_measured(name: &str) -> bool {
    GRIDS.iter().any(|g| g.backends.contains(&name))
}

/// The backends of [`GRIDS`], in report order.
pub fn names() -> Vec<&'static str> {
    GRIDS
        .iter()
        .flat_map(|g| g.backends.iter().copied())
        .collect()
}

/// The fixtures of a grid's rows: the whole grid (quick: its 2D NEAREST file).
fn fixtures(o: &BenchOptions, g: &Grid) -> Vec<PathBuf> {
    let file = format!("{}/2d/nearest.json", g.sub);
    o.fixtures
        .iter()
        .map(|f| {
            if o.quick {
                f.join(&file)
            } else {
                f.join(g.sub)
            }
        })
        .filter(|p| p.exists())
        .collect()
}

/// Distinct shader keys the cases plan on `api`: one pipeline each in the worker.
fn shader_keys(fixtures: &[PathBuf], api: ApiPath) -> usize {
    let set = crate::run::load_cases(fixtures);
    let cases: Vec<shadowcheck_model::Case> = set.cases.into_iter().map(|l| l.case).collect();
    let mut keys = HashSet::new();
    for job in shadowcheck_plan::sweep::jobs(&cases) {
        if let Ok(p) = shadowcheck_plan::paths::plan_in(
            api,
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

/// Per backend of every grid that starts: its end-to-end rows; what could not run is in the second
/// list.
pub fn rows(
    o: &BenchOptions,
    progress: &mut dyn FnMut(&str),
) -> (Vec<Measurement>, Vec<Unavailable>) {
    let mut rows = Vec::new();
    let mut missing = Vec::new();
    for g in &GRIDS {
        grid_rows(o, g, &mut rows, &mut missing, progress);
    }
    (rows, missing)
}

fn grid_rows(
    o: &BenchOptions,
    g: &Grid,
    rows: &mut Vec<Measurement>,
    missing: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) {
    if !o.backends.is_empty() && !g.backends.iter().any(|b| o.backends.iter().any(|o| o == b)) {
        return;
    }
    let fx = fixtures(o, g);
    if fx.is_empty() {
        missing.push(Unavailable {
            what: g.sub.into(),
            backend: None,
            reason: format!("no {}/ fixtures under --fixtures", g.sub),
        });
        return;
    }
    let keys = shader_keys(&fx, g.api);
    for &name in g.backends {
        if !o.backends.is_empty() && !o.backends.iter().any(|b| b == name) {
            continue;
        }
        progress(&format!("{name}: end to end over the {}/ fixtures", g.sub));
        let e = match suite::e2e(name, &fx) {
            Ok(e) => e,
            Err(e) => {
                missing.push(Unavailable {
                    what: format!("{} end to end", g.sub),
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
            g.ids[0],
            Some(name),
            e.per_s(),
            "cases/s",
            format!("cold (empty shader cache), {what}: {:.2} s", e.total_s()),
        ));
        rows.push(Measurement::new(
            g.ids[1],
            Some(name),
            e.warm_per_s(),
            "cases/s",
            format!(
                "the same cases again on the same worker ({:.3} s, the median of {} passes)",
                e.warm_run_s, e.warm_passes
            ),
        ));
        rows.push(Measurement::new(
            g.ids[2],
            Some(name),
            e.cached_per_s(),
            "cases/s",
            format!(
                "a new worker over the shader cache the cold pass filled ({:.2} s incl. worker start)",
                e.cached_s
            ),
        ));
        rows.push(Measurement::new(
            g.ids[3],
            Some(name),
            e.warm_run_s / e.checks.max(1) as f64 * 1e6,
            "us/check",
            format!(
                "the warm pass ({:.3} s for {} checks): upload, draw, read-back and verdict once the pipelines exist",
                e.warm_run_s, e.checks
            ),
        ));
    }
}
