//! A batch of lookups as jobs for the page (`page.js`), and the page's answers as protocol
//! answers. Everything is decided here from the lookup plan (shadowcheck-plan): the lookup form
//! (`paths::plan_in` on the `wgsl` path), the WGSL module of each shader key
//! (`shaders::wgsl::module`), the slot of each lookup in the result image (`layout`), the texel
//! values and the sampler descriptor of each texture (`texture.rs`). Consecutive lookups on equal
//! textures (a case and its sweep points) share one texture; consecutive lookups of one texture
//! and one module are one instanced draw, or, for a compute-stage module, one dispatch of one
//! workgroup per lookup. A texture's fragment-stage lookups take their slots first and its
//! compute-stage ones after them, so the fragment draws are the ones the batch would have without
//! the compute lookups.

use crate::texture::{self, TextureDesc};
use base64::Engine;
use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Format, Stage, Target};
use shadowcheck_plan::layout::{CAPACITY, FB_SIZE};
use shadowcheck_plan::shaders::wgsl::{self, COMPUTE_BINDINGS, INSTANCE_ATTRIBS, INSTANCE_FLOATS};
use shadowcheck_plan::{paths, Answer, Job, LookupForm, Plan};
use shadowcheck_protocol::{PathResult, Rgba};

/// Most textures one page job creates.
pub const MAX_TEXTURES: usize = 256;

/// What the device can do beyond core WebGPU's guarantees (from the page's `init`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DeviceCaps {
    /// The "depth32float-stencil8" feature (WebGPU "Feature Index"), requested when the
    /// adapter has it.
    pub d32fs8: bool,
    /// "cube-array" view dimensions: core WebGPU has them; compatibility mode does not.
    pub cube_array: bool,
    /// The device's maxTextureDimension2D and maxTextureArrayLayers (WebGPU "Limits");
    /// 0: not known, no check.
    pub max_dimension: u32,
    pub max_layers: u32,
}

/// One module of a page job: its WGSL, the view dimension its texture binding takes, and whether
/// it is a compute-stage module (entry point `cs`, dispatched) or a fragment-stage one (`vs` and
/// `fs`, drawn).
#[derive(Debug, Clone, Serialize)]
pub struct Module {
    pub wgsl: String,
    pub view: &'static str,
    pub compute: bool,
}

/// One instanced draw (or, with a compute module, one dispatch of `count` workgroups): `count`
/// lookups of texture `texture` with module `module`, slots `first` and on (instance or
/// workgroup i is slot first + i).
#[derive(Debug, Clone, Serialize)]
pub struct Draw {
    pub texture: usize,
    pub module: usize,
    pub first: usize,
    pub count: usize,
}

/// What the page's `shadowcheck.run` gets.
#[derive(Debug, Serialize)]
pub struct PageJob {
    pub modules: Vec<Module>,
    pub textures: Vec<TextureDesc>,
    /// The texel points of every texture, base64 of little-endian f32 triples.
    pub points: String,
    /// The lookups' instance values, base64 of little-endian f32 ([`INSTANCE_FLOATS`] a slot).
    pub instances: String,
    pub attributes: [(u32, &'static str, usize); 4],
    /// The compute modules' buffer bindings (`wgsl::COMPUTE_BINDINGS`).
    #[serde(rename = "computeBindings")]
    pub compute_bindings: [(&'static str, u32, &'static str); 3],
    /// Bytes per instance.
    pub stride: usize,
    pub draws: Vec<Draw>,
    pub slots: usize,
}

/// A page job and what its slots mean: the lookup (index into the batch's jobs) and plan note of
/// each slot, the format of each texture.
pub struct Built {
    pub page: PageJob,
    slots: Vec<(usize, String)>,
    formats: Vec<Format>,
    /// Per slot, its texture.
    slot_texture: Vec<usize>,
}

/// The page's answer to a job.
#[derive(Debug, Deserialize)]
pub struct PageAnswer {
    #[serde(default)]
    pub lost: Option<String>,
    #[serde(default)]
    pub errors: Vec<String>,
    #[serde(default)]
    pub pixels: Option<String>,
    #[serde(default)]
    pub stored: Vec<Option<String>>,
}

/// Plans job `j` on the `wgsl` path, with the module its key compiles to.
fn plan_job(j: &Job, caps: &DeviceCaps) -> Result<(Plan, String), String> {
    let plan = paths::plan_in(ApiPath::Wgsl, j.case, &j.lookup, LookupForm::Auto, false)?;
    if plan.key.target == Target::CubeArray && !caps.cube_array {
        return Err("cube-array texture views are not in WebGPU's compatibility mode (this device has no \"core-features-and-limits\")".into());
    }
    let module = wgsl::module(&plan.key, FB_SIZE)?;
    Ok((plan, module))
}

/// Why the device cannot hold the texture of `j`, if so: a format without its feature, a size
/// beyond the device's limits (createTexture would be a validation error).
fn device_lacks(j: &Job, caps: &DeviceCaps) -> Option<String> {
    let t = &j.case.texture;
    if t.format == Format::D32fS8 && !caps.d32fs8 {
        return Some("depth32float-stencil8 needs the \"depth32float-stencil8\" feature, which this adapter does not have".into());
    }
    let base = t.levels.first()?;
    let over = |v: u32, max: u32| max > 0 && v > max;
    if over(base.width.max(base.height), caps.max_dimension) {
        return Some(format!(
            "a {}x{} texture exceeds this device's maxTextureDimension2D {}",
            base.width, base.height, caps.max_dimension
        ));
    }
    if over(base.layers, caps.max_layers) {
        return Some(format!(
            "{} layers exceed this device's maxTextureArrayLayers {}",
            base.layers, caps.max_layers
        ));
    }
    None
}

/// Groups of consecutive jobs on equal textures.
fn groups(jobs: &[Job]) -> Vec<std::ops::Range<usize>> {
    let mut out: Vec<std::ops::Range<usize>> = vec![];
    for (i, j) in jobs.iter().enumerate() {
        match out.last_mut() {
            Some(r) if jobs[r.start].same_texture(j) && r.len() < CAPACITY => r.end = i + 1,
            _ => out.push(i..i + 1),
        }
    }
    out
}

/// A page job being filled.
#[derive(Default)]
struct Filling {
    modules: Vec<Module>,
    textures: Vec<TextureDesc>,
    formats: Vec<Format>,
    points: Vec<f32>,
    instances: Vec<f32>,
    draws: Vec<Draw>,
    slots: Vec<(usize, String)>,
    slot_texture: Vec<usize>,
}

impl Filling {
    fn finish(self) -> Built {
        let b64 = |v: &[f32]| {
            let bytes: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
            base64::engine::general_purpose::STANDARD.encode(bytes)
        };
        Built {
            page: PageJob {
                modules: self.modules,
                textures: self.textures,
                points: b64(&self.points),
                instances: b64(&self.instances),
                attributes: INSTANCE_ATTRIBS,
                compute_bindings: COMPUTE_BINDINGS,
                stride: 4 * INSTANCE_FLOATS,
                draws: self.draws,
                slots: self.slots.len(),
            },
            slots: self.slots,
            formats: self.formats,
            slot_texture: self.slot_texture,
        }
    }

    /// Adds a texture (its points described into `points`) and its planned lookups.
    fn add(
        &mut self,
        mut desc: TextureDesc,
        points: Vec<f32>,
        format: Format,
        lookups: Vec<(usize, Plan, String)>,
    ) {
        let offset = (self.points.len() / wgsl::TEXEL_FLOATS) as u32;
        for s in &mut desc.subresources {
            s.first += offset;
        }
        self.points.extend(points);
        let view = desc.view;
        let texture = self.textures.len();
        self.textures.push(desc);
        self.formats.push(format);
        // Fragment lookups first, compute lookups after (a stable partition): the fragment draws
        // are not split by compute lookups between them.
        let (fragment, compute): (Vec<_>, Vec<_>) = lookups
            .into_iter()
            .partition(|(_, plan, _)| plan.key.stage != Stage::Compute);
        for (job, plan, wgsl_text) in fragment.into_iter().chain(compute) {
            let module = match self.modules.iter().position(|m| m.wgsl == wgsl_text) {
                Some(m) => m,
                None => {
                    self.modules.push(Module {
                        wgsl: wgsl_text,
                        view,
                        compute: plan.key.stage == Stage::Compute,
                    });
                    self.modules.len() - 1
                }
            };
            let slot = self.slots.len();
            match self.draws.last_mut() {
                Some(d) if d.texture == texture && d.module == module => d.count += 1,
                _ => self.draws.push(Draw {
                    texture,
                    module,
                    first: slot,
                    count: 1,
                }),
            }
            self.instances.extend(wgsl::instance_values(&plan));
            self.slots.push((job, plan.note));
            self.slot_texture.push(texture);
        }
    }
}

/// Plans `jobs`: the answers decided without drawing (Skip: what WebGPU, WGSL or this device
/// cannot express), and the page jobs for the others, each at most [`CAPACITY`] lookups and
/// [`MAX_TEXTURES`] textures.
pub fn build(jobs: &[Job], caps: &DeviceCaps) -> (Vec<Option<Answer>>, Vec<Built>) {
    let mut out: Vec<Option<Answer>> = vec![None; jobs.len()];
    let mut built = vec![];
    let mut cur = Filling::default();
    for r in groups(jobs) {
        let j0 = &jobs[r.start];
        let mut points = vec![];
        let desc = match device_lacks(j0, caps)
            .map_or_else(|| texture::describe(j0.case, &mut points), Err)
        {
            Ok(d) => d,
            Err(why) => {
                r.for_each(|i| out[i] = Some(Answer::Skip(why.clone())));
                continue;
            }
        };
        let mut lookups = vec![];
        for i in r {
            match plan_job(&jobs[i], caps) {
                Ok((plan, module)) => lookups.push((i, plan, module)),
                Err(why) => out[i] = Some(Answer::Skip(why)),
            }
        }
        if lookups.is_empty() {
            continue;
        }
        if cur.slots.len() + lookups.len() > CAPACITY || cur.textures.len() >= MAX_TEXTURES {
            built.push(std::mem::take(&mut cur).finish());
        }
        cur.add(desc, points, j0.case.texture.format, lookups);
    }
    if !cur.slots.is_empty() {
        built.push(cur.finish());
    }
    (out, built)
}

/// The answers of built job `b` from the page's answer: `(job index, answer)` per slot. Errors
/// caught by the page's error scopes make every lookup of the job an error quoting them.
pub fn answers(b: Built, jobs: &[Job], page: PageAnswer) -> Vec<(usize, Answer)> {
    let fail = |msg: String| -> Vec<(usize, Answer)> {
        b.slots
            .iter()
            .map(|(j, _)| (*j, Answer::Error(msg.clone())))
            .collect()
    };
    if !page.errors.is_empty() {
        return fail(format!(
            "WebGPU reported an error in this batch (a harness bug: nothing it drew is an observation): {}",
            page.errors.join(" | ")
        ));
    }
    let decode = |s: &str| base64::engine::general_purpose::STANDARD.decode(s.as_bytes());
    let px = match page.pixels.as_deref().map(decode) {
        Some(Ok(px)) if px.len() == 16 * b.slots.len() => px,
        Some(Ok(px)) => {
            return fail(format!(
                "page answer: {} result bytes for {} lookups",
                px.len(),
                b.slots.len()
            ))
        }
        Some(Err(e)) => return fail(format!("page answer: pixels are not base64 ({e})")),
        None => return fail("page answer: no pixels".into()),
    };
    let stored: Vec<Option<shadowcheck_model::Texels>> = b
        .formats
        .iter()
        .enumerate()
        .map(|(t, f)| {
            let bytes = decode(page.stored.get(t)?.as_deref()?).ok()?;
            texture::decode(*f, &bytes)
        })
        .collect();
    b.slots
        .into_iter()
        .zip(b.slot_texture)
        .enumerate()
        .map(|(slot, ((j, note), t))| {
            let c = &px[16 * slot..16 * slot + 16];
            let f = |i: usize| f32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]) as f64;
            let own = !jobs.get(j).is_some_and(|x| x.point);
            let result = PathResult {
                sweep: vec![],
                api: ApiPath::Wgsl.key().to_string(),
                rgba: Rgba([f(0), f(4), f(8), f(12)]),
                stored: if own {
                    stored.get(t).cloned().flatten()
                } else {
                    None
                },
                note: own.then_some(note),
            };
            (j, Answer::Observation(vec![result], vec![]))
        })
        .collect()
}

#[cfg(test)]
mod tests;
