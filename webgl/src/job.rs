//! A batch of cases as one job for the page (`page.js`), and the page's answer as protocol
//! answers. Everything is decided by the lookup plan (shadowcheck-plan), as for the GL worker, so
//! the WebGL port runs the same es300 path: the lookup (`paths::plan_with`), the shader text
//! (`shaders::glsl`), the bytes of every level (`texels::level_bytes`, `transfer_for`) and the
//! TexParameter calls (`unit::tex_params`). Consecutive cases with equal texture and sampler share one texture
//! object, and the texture states are drawn in the plan's bundles (`units::plan_batch`): state i
//! of a bundle on texture unit i, one program sampling them all, the case's unit a uniform, as
//! on the GL worker's single-case paths.

use base64::Engine;
use serde::Serialize;
use shadowcheck_model::{Case, Target};
use shadowcheck_plan::texels::{level_bytes, transfer_for};
use shadowcheck_plan::unit::{sampler_params, tex_params, ParamValue, TexParam};
use shadowcheck_plan::{shaders, sweep, units, Answer, GlInfo, PlanError};
use shadowcheck_protocol::{PathResult, PathSkip, Rgba};

/// Most (case, path) pixels of one job (the page's framebuffer is 256 x 256).
pub const MAX_SLOTS: usize = 256 * 256;

#[derive(Debug, Serialize)]
pub struct Job {
    /// (vertex, fragment) source per program.
    programs: Vec<[String; 2]>,
    slots: usize,
    /// The texture states, each made once.
    groups: Vec<Group>,
    /// The draws, bundle after bundle, each with its states bound to units 0, 1, ...
    bundles: Vec<BundleJob>,
}

#[derive(Debug, Serialize)]
struct Group {
    cases: Vec<usize>,
    /// `None` (absent): the texture could not be described; its cases answer the error and its
    /// units stay empty.
    #[serde(skip_serializing_if = "Option::is_none")]
    texture: Option<Texture>,
}

#[derive(Debug, Serialize)]
struct BundleJob {
    /// The groups bound to units 0, 1, ...
    states: Vec<usize>,
    draws: Vec<Draw>,
}

#[derive(Debug, Serialize)]
struct Texture {
    target: u32,
    /// `2d`, `3d` (texImage3D) or `cube` (six texImage2D per level).
    upload: &'static str,
    levels: Vec<Level>,
    params: Vec<Param>,
    /// SamplerParameter calls of a bound sampler object (`shadowcheck_plan::unit::sampler_params`); empty:
    /// no sampler object.
    sampler: Vec<Param>,
}

#[derive(Debug, Serialize)]
struct Level {
    level: u32,
    ifmt: i32,
    fmt: u32,
    #[serde(rename = "type")]
    ty: u32,
    bpt: usize,
    width: u32,
    height: u32,
    layers: u32,
    /// level_bytes, base64.
    data: String,
}

#[derive(Debug, Serialize)]
struct Param {
    pname: u32,
    call: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    int: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Js>,
}

#[derive(Debug, Serialize)]
struct Draw {
    case: usize,
    api: String,
    slot: usize,
    program: usize,
    /// The texture unit of the case's state (the program's `u_unit`).
    unit: usize,
    p: [Js; 4],
    x: Js,
    dx: [Js; 4],
    dy: [Js; 4],
    /// A variable gather offset (the program's `u_o`), where the lookup has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    o: Option<[i32; 2]>,
    /// The viewport (x, y, width, height) of the draw (`shaders::single_draw_viewport`): the slot's
    /// pixel, or the 2x2 quad holding it for a per-fragment delivery.
    viewport: [i32; 4],
}

/// Width of the page's framebuffer in pixels (`FB` in page.js): slot s is pixel (s % FB, s / FB).
const FB: usize = 256;

/// An f32 as the page reads it: a JSON number when finite (shortest round-trip text, so the
/// page's `Number` and WebGL's conversion to float give the same f32), else `"Infinity"`,
/// `"-Infinity"` or `"NaN"` (JSON has no such numbers; serde_json would write `null`), which
/// JavaScript's `Number()` reads back.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Js(pub f32);

impl Serialize for Js {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let v = self.0;
        if v.is_finite() {
            s.serialize_f32(v)
        } else if v.is_nan() {
            s.serialize_str("NaN")
        } else if v > 0.0 {
            s.serialize_str("Infinity")
        } else {
            s.serialize_str("-Infinity")
        }
    }
}

fn js4(v: [f32; 4]) -> [Js; 4] {
    v.map(Js)
}

/// What a job's pixels mean: per slot, the case, its path and the plan's note.
#[derive(Debug, Default)]
pub struct Layout {
    slots: Vec<(usize, String, String)>,
}

/// Cases planned for the es300 path: the answers decided without drawing (Skip), the job, and
/// where each pixel goes.
pub struct Built {
    pub answers: Vec<Option<Answer>>,
    pub skipped: Vec<Vec<PathSkip>>,
    pub job: Job,
    pub layout: Layout,
}

fn texture_of(info: &GlInfo, case: &Case) -> Result<Texture, PlanError> {
    let t = &case.texture;
    let (ifmt, fmt, ty, bpt) = transfer_for(case);
    let mut levels = Vec::with_capacity(t.levels.len());
    for (i, lvl) in t.levels.iter().enumerate() {
        let bytes = level_bytes(t.format, lvl)?;
        levels.push(Level {
            level: t.base_level + i as u32,
            ifmt,
            fmt,
            ty,
            bpt,
            width: lvl.width,
            height: lvl.height,
            layers: lvl.layers,
            data: base64::engine::general_purpose::STANDARD.encode(bytes),
        });
    }
    let param = |p: TexParam| {
        let (int, float) = match p.value {
            ParamValue::Int(v) => (Some(v), None),
            ParamValue::Float(v) => (None, Some(Js(v))),
            ParamValue::Floats(_) => (None, None),
        };
        Param {
            pname: p.pname,
            call: p.call(),
            int,
            float,
        }
    };
    let params = tex_params(info.compat, case)
        .into_iter()
        .map(param)
        .collect();
    let sampler = sampler_params(case).into_iter().map(param).collect();
    let upload = match t.target {
        Target::Cube => "cube",
        Target::T2dArray | Target::CubeArray => "3d",
        _ => "2d",
    };
    Ok(Texture {
        target: t.target.gl(),
        upload,
        levels,
        params,
        sampler,
    })
}

/// Plans every case's paths and builds the job. At most [`MAX_SLOTS`] paths in all (the caller
/// splits larger batches).
pub fn build(info: &GlInfo, cases: &[Case]) -> Built {
    let mut b = Built {
        answers: vec![None; cases.len()],
        skipped: vec![Vec::new(); cases.len()],
        job: Job {
            programs: vec![],
            slots: 0,
            groups: vec![],
            bundles: vec![],
        },
        layout: Layout::default(),
    };
    let jobs: Vec<sweep::Job> = cases.iter().map(sweep::Job::own).collect();
    let plan = units::plan_batch(info, &jobs, units::DEFAULT_STATES_PER_PROGRAM);
    for (ci, why) in plan.unplanned {
        b.answers[ci] = Some(Answer::Skip(why));
    }
    b.skipped = plan.skipped;
    for group in &plan.groups {
        let cis: Vec<usize> = group.iter().map(|(ci, _)| *ci).collect();
        let texture = match texture_of(info, &cases[cis[0]]) {
            Ok(t) => Some(t),
            Err(e) => {
                for &ci in &cis {
                    b.answers[ci] = Some(Answer::Error(e.to_string()));
                }
                None
            }
        };
        b.job.groups.push(Group {
            cases: cis,
            texture,
        });
    }
    let mut sources: Vec<[String; 2]> = Vec::new();
    for bundle in &plan.bundles {
        let (vs, fs) = shaders::glsl(info, &bundle.key, None, bundle.units());
        let src = [vs, fs];
        let program = match sources.iter().position(|s| *s == src) {
            Some(i) => i,
            None => {
                sources.push(src);
                sources.len() - 1
            }
        };
        let mut draws = Vec::new();
        for (unit, &g) in bundle.states.iter().enumerate() {
            for (ci, plans) in &plan.groups[g] {
                if b.answers[*ci].is_some() {
                    continue;
                }
                for p in plans.iter().filter(|p| p.key == bundle.key) {
                    let slot = b.layout.slots.len();
                    b.layout
                        .slots
                        .push((*ci, p.key.path.key().to_string(), p.note.clone()));
                    draws.push(Draw {
                        case: *ci,
                        api: p.key.path.key().to_string(),
                        slot,
                        program,
                        unit,
                        p: js4(p.p),
                        x: Js(p.x),
                        dx: js4(p.dx),
                        dy: js4(p.dy),
                        o: (p.key.gather == Some(shadowcheck_plan::GatherCall::Variable))
                            .then_some(p.o),
                        viewport: shaders::single_draw_viewport(
                            &p.key,
                            ((slot % FB) as i32, (slot / FB) as i32),
                        ),
                    });
                }
            }
        }
        b.job.bundles.push(BundleJob {
            states: bundle.states.clone(),
            draws,
        });
    }
    b.job.programs = sources;
    b.job.slots = b.layout.slots.len();
    b
}

/// The page's answer to a job: `{pixels: base64, errors: {case: message}}`.
#[derive(Debug, serde::Deserialize)]
pub struct PageAnswer {
    pixels: String,
    #[serde(default)]
    errors: std::collections::BTreeMap<usize, String>,
}

/// The answers of a built job from the page's answer, one per case in order.
pub fn answers(mut built: Built, cases: &[Case], page: PageAnswer) -> Vec<Answer> {
    let bytes = match base64::engine::general_purpose::STANDARD.decode(page.pixels.as_bytes()) {
        Ok(b) => b,
        Err(e) => {
            let msg = format!("page answer: pixels are not base64 ({e})");
            return built
                .answers
                .into_iter()
                .map(|a| a.unwrap_or_else(|| Answer::Error(msg.clone())))
                .collect();
        }
    };
    let px: Vec<[f32; 4]> = bytes
        .chunks_exact(16)
        .map(|c| {
            let f = |i: usize| f32::from_ne_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]);
            [f(0), f(4), f(8), f(12)]
        })
        .collect();
    for (ci, msg) in page.errors {
        if let Some(a) = built.answers.get_mut(ci) {
            *a = Some(Answer::Error(msg));
        }
    }
    let mut results: Vec<Vec<PathResult>> = vec![Vec::new(); cases.len()];
    for (slot, (ci, api, note)) in built.layout.slots.into_iter().enumerate() {
        if built.answers[ci].is_some() {
            continue;
        }
        let v = px.get(slot).copied().unwrap_or([f32::NAN; 4]);
        results[ci].push(PathResult {
            sweep: vec![],
            api,
            rgba: Rgba(v.map(|c| c as f64)),
            stored: None,
            note: Some(note),
        });
    }
    built
        .answers
        .into_iter()
        .zip(results)
        .zip(built.skipped)
        .map(|((a, r), skipped)| a.unwrap_or(Answer::Observation(r, skipped)))
        .collect()
}

#[cfg(test)]
mod tests;
