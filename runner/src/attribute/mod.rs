//! Layer attribution (`shadowcheck attribute`): for a failure on a layered implementation (GL on
//! Vulkan through zink, WebGL on Vulkan or on OpenGL ES through ANGLE, WebGPU on Vulkan through
//! Dawn), which layer broke the lookup.
//!
//! Where the lower layer is an OpenGL ES driver ([`Counterpart::SameTest`]: ANGLE's OpenGL ES back
//! end on Mesa's llvmpipe), the counterpart is the same test (case and `es300` path) on that
//! driver's backend, and the classification below is the same.
//!
//! The plan of a GL, GL ES or WebGPU case is API-neutral: the same texture, sampler state and lookup as a
//! Vulkan case ([`vulkan_counterpart`]) where Vulkan 1.3 defines it (the oracle's `vulkan` rules
//! accept it). The Vulkan driver under the layer ([`LAYERS`]) answers that counterpart in the same
//! runs, and the failure is classified ([`Layer`]):
//!
//! - **upper**: the Vulkan driver answers the counterpart correctly; or the case has no Vulkan
//!   counterpart (GL-only state such as DEPTH_TEXTURE_MODE, a fixed-function path, a rectangle
//!   texture, a 32-bit UNORM depth format), or the driver lacks what it needs (a Skip: a format it does not have), so the layer
//!   must emulate it and the emulation is what failed;
//! - **lower**: the driver fails the counterpart with the same observed r;
//! - **both**: the driver fails the counterpart too, with another r;
//! - **no equivalent**: the counterpart exists but no run holds the driver's answer to it (not
//!   run, or a Vulkan fixture of that id that is not the same lookup), or the failure is a read
//!   without comparison (Vulkan has one, a non-Dref sample, but the Vulkan cases are depth
//!   comparisons only).
//!
//! A case id names its grid coordinates after the spec (`gl46/2d/d24/...`); the Vulkan grid uses
//! the same families, so the counterpart's id is the Vulkan spec key in front of the same rest,
//! and the fixture of that id is checked to hold the same lookup.

use crate::records::{Outcome, Results, TestResult};
use serde::Serialize;
use shadowcheck_model::{ApiPath, Case, CompareMode, Spec};
use std::collections::HashMap;

/// A layered implementation: the backends of the upper layer and the backend of the driver under
/// it.
#[derive(Debug, Clone, Copy)]
pub struct Layering {
    /// The upper layer's backends: this name, or names starting with it followed by `:` (a prefix
    /// ending in `:` takes any name after it).
    pub upper_prefix: &'static str,
    /// The backend of the driver the upper layer runs on.
    pub lower: &'static str,
    /// What the lower backend is asked for a failure.
    pub counterpart: Counterpart,
    pub what: &'static str,
}

/// How a failure's counterpart on the lower layer is found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Counterpart {
    /// The same lookup recast as a Vulkan case ([`vulkan_counterpart`]): a Vulkan driver.
    Vulkan,
    /// The same test (case id and API path): an OpenGL ES driver under a layer that runs the
    /// same ES cases.
    SameTest,
}

/// The layerings shadowcheck runs: zink on lavapipe (Mesa's default zink here), zink on
/// SwiftShader's Vulkan driver, WebGL 2.0 in Chromium on three ANGLE back ends (Vulkan on
/// SwiftShader, Vulkan on lavapipe, OpenGL ES on Mesa's llvmpipe: the same `es300` tests on
/// `egl:llvmpipe:es3`), and WebGPU in Chromium on Dawn's Vulkan back end on SwiftShader.
pub const LAYERS: &[Layering] = &[
    Layering {
        upper_prefix: "egl:zink+swiftshader:",
        lower: "vk:swiftshader",
        counterpart: Counterpart::Vulkan,
        what: "zink on SwiftShader's Vulkan driver",
    },
    Layering {
        upper_prefix: "egl:zink:",
        lower: "vk:lavapipe",
        counterpart: Counterpart::Vulkan,
        what: "zink on lavapipe",
    },
    Layering {
        upper_prefix: "osmesa:zink",
        lower: "vk:lavapipe",
        counterpart: Counterpart::Vulkan,
        what: "zink on lavapipe",
    },
    Layering {
        upper_prefix: "webgl:chromium",
        lower: "vk:swiftshader",
        counterpart: Counterpart::Vulkan,
        what: "ANGLE's Vulkan back end on SwiftShader",
    },
    Layering {
        upper_prefix: "webgl:chromium-lavapipe",
        lower: "vk:lavapipe",
        counterpart: Counterpart::Vulkan,
        what: "ANGLE's Vulkan back end on lavapipe",
    },
    Layering {
        upper_prefix: "webgl:chromium-gles",
        lower: "egl:llvmpipe:es3",
        counterpart: Counterpart::SameTest,
        what: "ANGLE's OpenGL ES back end on Mesa's llvmpipe",
    },
    Layering {
        upper_prefix: "webgpu:chromium",
        lower: "vk:swiftshader",
        counterpart: Counterpart::Vulkan,
        what: "Dawn's Vulkan back end on SwiftShader",
    },
];

/// The layering a backend belongs to, if it is an upper layer.
pub fn layering_of(backend: &str) -> Option<&'static Layering> {
    LAYERS.iter().find(|l| {
        backend.strip_prefix(l.upper_prefix).is_some_and(|rest| {
            l.upper_prefix.ends_with(':') || rest.is_empty() || rest.starts_with(':')
        })
    })
}

/// Which layer a failure is attributed to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Layer {
    Upper,
    Lower,
    Both,
    NoEquivalent,
}

impl Layer {
    pub fn as_str(self) -> &'static str {
        match self {
            Layer::Upper => "upper",
            Layer::Lower => "lower",
            Layer::Both => "both",
            Layer::NoEquivalent => "no equivalent",
        }
    }
}

/// One attributed failure.
#[derive(Debug, Clone, Serialize)]
pub struct Attribution {
    pub backend: String,
    pub test: String,
    pub outcome: Outcome,
    /// The Vulkan backend asked, and the counterpart's test name (`None`: no counterpart).
    pub lower: &'static str,
    pub counterpart: Option<String>,
    pub layer: Layer,
    pub why: String,
}

/// The Vulkan case with `case`'s texture, sampler state and lookup, where Vulkan 1.3 defines that
/// lookup; `Err` with the oracle's reason where it does not (GL-only state or path).
pub fn vulkan_counterpart(case: &Case) -> Result<Case, String> {
    let rest = case
        .id
        .split_once('/')
        .map(|(_, r)| r)
        .unwrap_or(case.id.as_str());
    let mut c = case.clone();
    c.id = format!("{}/{rest}", Spec::Vulkan.key());
    c.spec = Spec::Vulkan;
    c.api = vec![ApiPath::Vulkan];
    c.expect = None;
    match shadowcheck_oracle::evaluate(&c) {
        Ok(_) => Ok(c),
        Err(e) => Err(e.to_string()),
    }
}

/// The id of a counterpart that `counterparts_to_run` writes: the grid's Vulkan id with the GL
/// case's spec after it (`vulkan/2d/.../rand/seed=0/21/of=arb`), never an id of the grid's own.
fn own_id(vk: &Case, gl: &Case) -> String {
    format!("{}/of={}", vk.id, gl.spec.key())
}

/// The Vulkan counterparts of the layered failures in `results` that no case of `cases` holds
/// (the "no equivalent" rows of a missing or different Vulkan fixture), with the oracle's
/// expectations (sweep points included) and ids of their own ([`own_id`]): a fixture to run on
/// the Vulkan driver, after which `attribute` classifies those failures too.
pub fn counterparts_to_run(results: &Results, cases: &HashMap<String, Case>) -> Vec<Case> {
    let mut out: Vec<Case> = Vec::new();
    for t in &results.results {
        if !matches!(layering_of(&t.backend), Some(l) if l.counterpart == Counterpart::Vulkan)
            || !matches!(t.outcome, Outcome::Fail | Outcome::Warn)
        {
            continue;
        }
        let Some(gl) = cases.get(&t.case_id) else {
            continue;
        };
        if gl_only_read(gl).is_some() {
            continue;
        }
        let Ok(mut vk) = vulkan_counterpart(gl) else {
            continue;
        };
        let held = |id: &str| cases.get(id).and_then(|f| same_lookup(gl, f)).is_some();
        let id = own_id(&vk, gl);
        if held(&vk.id) || held(&id) || out.iter().any(|c| c.id == id) {
            continue;
        }
        vk.id = id;
        let Ok(ev) = shadowcheck_oracle::evaluate(&vk) else {
            continue;
        };
        vk.expect = Some(ev.expect);
        let mut points = Vec::new();
        for k in 0..vk.sweep.len() {
            let mut p = vk.sweep[k].clone();
            let mut one = vk.clone();
            one.sweep = vec![];
            one.lookup = vk.point_lookup(&p);
            if let Some(pe) = shadowcheck_oracle::evaluate(&one)
                .ok()
                .and_then(|e| shadowcheck_model::sweep::PointExpectation::of(&e.expect))
            {
                p.expect = Some(pe);
                points.push(p);
            }
        }
        vk.sweep = points;
        out.push(vk);
    }
    out
}

/// A read without comparison (compare mode NONE): Vulkan has it (a sample that is not
/// OpImage*Dref*), but the Vulkan cases are depth comparisons only, so its layer is not known
/// (no equivalent); unless it also needs what Vulkan lacks altogether (GL's incompleteness,
/// DEPTH_TEXTURE_MODE, ...), which the layer emulates (upper). `None` for a comparison.
fn gl_only_read(case: &Case) -> Option<(Layer, String)> {
    if case.sampler.in_effect().compare_mode != CompareMode::None {
        return None;
    }
    let rules = shadowcheck_oracle::rules::rules_for(case.spec);
    let s = case.sampler.in_effect();
    if let Some(why) = shadowcheck_oracle::lod::incomplete(&rules, &case.texture, &s, false) {
        return Some((
            Layer::Upper,
            format!("GL calls the texture incomplete ({why}): Vulkan has no incomplete textures, the layer emulates GL's rule"),
        ));
    }
    if !case.texture.format.is_depth() {
        return Some((
            Layer::NoEquivalent,
            "a colour read: Vulkan has it (R8_UNORM, a non-Dref sample), outside the Vulkan cases (depth comparison only)".into(),
        ));
    }
    let mut compared = case.clone();
    compared.sampler.compare_mode = CompareMode::Compare;
    if let Some(o) = compared.sampler.sampler_object.as_mut() {
        o.compare_mode = CompareMode::Compare;
    }
    Some(match vulkan_counterpart(&compared) {
        Err(why) => (
            Layer::Upper,
            format!("no Vulkan counterpart, the layer emulates it: {why}"),
        ),
        Ok(_) => (
            Layer::NoEquivalent,
            "a read without comparison: Vulkan has it (a non-Dref sample), outside the Vulkan cases (depth comparison only)".into(),
        ),
    })
}

/// The same lookup: texture, sampler state and lookup (compared as written in a fixture, so that a
/// NaN reference equals itself), and every sweep point of `vk` one of `gl`'s (a sweep keeps the
/// points its spec defines). `Some(n)`: the same, `vk` holding `n` of `gl`'s points.
fn same_lookup(gl: &Case, vk: &Case) -> Option<usize> {
    let text = |c: &Case| {
        (
            serde_json::to_string(&c.texture).ok(),
            serde_json::to_string(&c.sampler).ok(),
            serde_json::to_string(&c.lookup).ok(),
        )
    };
    let point = |p: &shadowcheck_model::sweep::SweepPoint| format!("{:?} {:?}", p.coord, p.dref);
    let gl_points: Vec<String> = gl.sweep.iter().map(point).collect();
    let all_in = vk.sweep.iter().all(|p| gl_points.contains(&point(p)));
    (text(gl) == text(vk) && all_in).then_some(vk.sweep.len())
}

/// The observed r of a record, if it has one.
fn r_of(t: &TestResult) -> Option<f64> {
    t.observed.as_ref().map(|o| o.0[0])
}

/// Attributes every failure (Fail or Warn outcome) of an upper-layer backend in `results`.
/// `cases`: the fixtures' cases by id (both the GL and the Vulkan ones).
pub fn attribute(results: &Results, cases: &HashMap<String, Case>) -> Vec<Attribution> {
    let mut out = Vec::new();
    for t in &results.results {
        let Some(layering) = layering_of(&t.backend) else {
            continue;
        };
        if !matches!(t.outcome, Outcome::Fail | Outcome::Warn) {
            continue;
        }
        let mut row = Attribution {
            backend: t.backend.clone(),
            test: t.test.clone(),
            outcome: t.outcome,
            lower: layering.lower,
            counterpart: None,
            layer: Layer::NoEquivalent,
            why: String::new(),
        };
        if layering.counterpart == Counterpart::SameTest {
            // The lower backend ran this very case on the same API path: no recasting and no
            // fixture check; its record decides as a Vulkan counterpart's does.
            row.counterpart = Some(t.test.clone());
            (row.layer, row.why) = classify(
                layering.lower,
                t,
                results.get(layering.lower, &t.test),
                &t.test,
            );
            out.push(row);
            continue;
        }
        let Some(case) = cases.get(&t.case_id) else {
            row.why = format!("case `{}` is not in the fixtures read", t.case_id);
            out.push(row);
            continue;
        };
        if let Some(why) = gl_only_read(case) {
            // Vulkan samples depth and colour images without a comparison too, through another
            // instruction than OpImage*Dref*: an equivalent exists, outside the oracle's
            // Vulkan rules (depth comparison only), so nothing says which layer is at fault.
            row.layer = why.0;
            row.why = why.1;
            out.push(row);
            continue;
        }
        let vk = match vulkan_counterpart(case) {
            Ok(vk) => vk,
            Err(why) => {
                row.layer = Layer::Upper;
                row.why = format!("no Vulkan counterpart, the layer emulates it: {why}");
                out.push(row);
                continue;
            }
        };
        // A counterpart written by `counterparts_to_run` carries its spec in the id when the
        // grid's own Vulkan case of that id is another lookup or absent.
        let vk = match cases.get(&own_id(&vk, case)) {
            Some(f)
                if cases
                    .get(&vk.id)
                    .and_then(|g| same_lookup(case, g))
                    .is_none() =>
            {
                Case {
                    id: f.id.clone(),
                    ..vk
                }
            }
            _ => vk,
        };
        let name = TestResult::name(&vk.id, ApiPath::Vulkan);
        row.counterpart = Some(name.clone());
        // Where Vulkan's rule gives another value than the GL spec's (GL's non-seamless cube maps,
        // its LINEAR layer rounding), the layer must emulate the GL rule: said with the verdict.
        let mut differs = String::new();
        match cases.get(&vk.id).map(|f| (f, same_lookup(case, f))) {
            Some((f, Some(points))) => {
                if points < case.sweep.len() {
                    differs = format!(
                        " (the Vulkan case has {points} of the {} sweep points)",
                        case.sweep.len()
                    );
                }
                let value = |c: &Case| c.expect.as_ref().and_then(|x| x.spec_value);
                if value(f) != value(case) {
                    differs += &format!(
                        " (Vulkan's spec value here is {}, GL's {}: the layer must emulate GL's rule)",
                        value(f).map_or("none".into(), |v| v.to_string()),
                        value(case).map_or("none".into(), |v| v.to_string())
                    );
                }
            }
            Some((_, None)) => {
                row.why = format!("the Vulkan fixture `{}` is another lookup", vk.id);
                out.push(row);
                continue;
            }
            None => {
                row.why = format!("no Vulkan fixture `{}`", vk.id);
                out.push(row);
                continue;
            }
        }
        (row.layer, row.why) =
            classify(layering.lower, t, results.get(layering.lower, &name), &name);
        row.why += &differs;
        out.push(row);
    }
    out
}

/// The layer of the failure `t` given the lower backend's record `low` of its counterpart `name`.
fn classify(lower: &str, t: &TestResult, low: Option<&TestResult>, name: &str) -> (Layer, String) {
    let Some(low) = low else {
        return (
            Layer::NoEquivalent,
            format!("no result of {lower} for {name} in the runs"),
        );
    };
    match low.outcome {
        Outcome::Pass => (Layer::Upper, format!("{lower} passes the same lookup")),
        Outcome::Skip => (
            Layer::Upper,
            format!(
                "{} cannot run the same lookup ({}): the layer emulates it",
                lower,
                low.reason.as_deref().unwrap_or("skipped")
            ),
        ),
        Outcome::Fail | Outcome::Warn => match (r_of(t), r_of(low)) {
            (Some(a), Some(b)) if (a - b).abs() <= 1e-6 => {
                (Layer::Lower, format!("{lower} returns the same r = {b}"))
            }
            (a, b) => (
                Layer::Both,
                format!(
                    "{} fails it too, with r = {} (upper: {})",
                    lower,
                    b.map_or("?".into(), |v| v.to_string()),
                    a.map_or("?".into(), |v| v.to_string())
                ),
            ),
        },
        other => (
            Layer::NoEquivalent,
            format!("{lower} gave no answer ({})", other.as_str()),
        ),
    }
}

mod render;
pub use render::{classes, markdown, report_section, tally, Class};

#[cfg(test)]
mod tests;
