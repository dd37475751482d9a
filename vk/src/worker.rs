//! The Vulkan worker: opens the device of its driver, declares what it runs (its hello), and
//! answers batches through the plan's protocol loop ([`shadowcheck_plan::serve::serve`]): each
//! lookup planned on the `vk` path, the lookups of a batch drawn in as few submissions as the
//! result image and `draw::MAX_TEXTURES` allow.

use crate::device::{self, take_messages, Gpu};
use crate::draw::{Renderer, TextureSpec};
use crate::{sampler, spirv, texture, Driver, VkError};
use shadowcheck_model::{ApiPath, Case, Spec, Target};
use shadowcheck_plan::layout::CAPACITY;
use shadowcheck_plan::serve::{self, Serve};
use shadowcheck_plan::{paths, sweep, Answer, GatherCall, Job, LookupForm, Plan};
use shadowcheck_protocol::PROTOCOL_VERSION;
use shadowcheck_protocol::{Capabilities, Hello, PathResult, Rgba};

/// A live worker.
pub struct VkWorker {
    pub driver: Driver,
    renderer: Renderer,
    caps: Capabilities,
    /// The compiler's version line.
    pub compiler: String,
    /// Why the device is gone, once it is: the next batch ends the worker.
    lost: Option<String>,
    /// Validation messages not yet attached to an answer.
    pending: Vec<String>,
}

/// The extension-like string saying a format has SAMPLED_IMAGE_FILTER_LINEAR (Vulkan 1.3
/// "Format Feature Flags"): where it is absent, a LINEAR comparison "may be computed in an
/// implementation-dependent manner" ("Texel Filtering").
pub fn format_linear(f: shadowcheck_model::Format) -> String {
    format!("format_linear:{}", f.key())
}

/// What a device runs (the hello's capabilities).
pub fn capabilities(gpu: &Gpu) -> Capabilities {
    let mut targets = vec![
        Target::T1d,
        Target::T2d,
        Target::Cube,
        Target::T1dArray,
        Target::T2dArray,
    ];
    if gpu.support.image_cube_array {
        targets.push(Target::CubeArray);
    }
    let usable: Vec<&device::FormatInfo> = gpu.formats.iter().filter(|f| f.usable).collect();
    let mut extensions = gpu.support.extensions.clone();
    extensions.extend(
        usable
            .iter()
            .filter(|f| f.filter_linear)
            .map(|f| format_linear(f.format)),
    );
    Capabilities {
        specs: Some(vec![Spec::Vulkan.key().to_string()]),
        api: Some(vec![ApiPath::Vulkan.key().to_string()]),
        targets: Some(targets.iter().map(|t| t.key().to_string()).collect()),
        formats: Some(usable.iter().map(|f| f.format.key().to_string()).collect()),
        // mipLodBias, CLAMP_TO_BORDER (colours the device cannot express are Skip per case),
        // shadow gathers (OpImageDrefGather), the stencil aspect of a depth/stencil image.
        features: Some(
            ["lod_bias", "border_clamp", "gather", "stencil_texturing"]
                .iter()
                .map(|s| s.to_string())
                .collect(),
        ),
        extensions,
    }
}

impl VkWorker {
    /// Checks the compiler, opens the device of `driver` and makes the fixed objects.
    pub fn start(driver: Driver) -> Result<VkWorker, VkError> {
        let compiler = spirv::check_compiler()?;
        let gpu = Gpu::open(driver)?;
        let caps = capabilities(&gpu);
        let renderer = Renderer::new(gpu)?;
        Ok(VkWorker {
            driver,
            renderer,
            caps,
            compiler,
            lost: None,
            pending: take_messages(),
        })
    }

    /// E.g. `vk:lavapipe (llvmpipe (LLVM 15.0.6, 256 bits); Vulkan 1.3.230; llvmpipe Mesa 22.3.6
    /// (MESA_LLVMPIPE))`, with `; validation` when the layer is on.
    pub fn display_name(&self) -> String {
        let g = &self.renderer.gpu;
        let v = if g.loaded.validation {
            "; validation"
        } else {
            ""
        };
        format!("vk:{} ({}{v})", self.driver.key(), g.description)
    }

    pub fn capabilities(&self) -> &Capabilities {
        &self.caps
    }

    /// Pipelines compiled and lookups drawn so far.
    pub fn stats(&self) -> String {
        format!(
            "vk-worker: {} pipelines, {} lookups drawn",
            self.renderer.pipelines(),
            self.renderer.drawn
        )
    }

    /// Why a planned lookup cannot run on this device (texel offsets beyond its limits, the four
    /// offsets of textureGatherOffsets without shaderImageGatherExtended).
    fn limits(&self, plan: &Plan) -> Result<(), String> {
        let s = &self.renderer.gpu.support;
        let within = |o: i8, (lo, hi): (i32, u32)| (o as i32) >= lo && (o as i64) <= hi as i64;
        let range = if plan.key.gather.is_some() {
            s.gather_offset
        } else {
            s.texel_offset
        };
        let mut offsets = vec![plan.key.offset];
        if let Some(GatherCall::Offsets(o)) = plan.key.gather {
            if !s.gather_extended {
                return Err(
                    "textureGatherOffsets needs shaderImageGatherExtended, which this device lacks"
                        .into(),
                );
            }
            offsets.extend(o);
        }
        match offsets.iter().flatten().find(|o| !within(**o, range)) {
            Some(o) => Err(format!(
                "texel offset {o} outside this device's [{}, {}]",
                range.0, range.1
            )),
            None => Ok(()),
        }
    }

    /// The texture of `case` as Vulkan state, or why it does not run here.
    fn texture_spec<'c>(&self, case: &'c Case) -> Result<TextureSpec<'c>, String> {
        let g = &self.renderer.gpu;
        let format = *g
            .format(case.texture.format)
            .filter(|f| f.usable)
            .ok_or_else(|| format!("format {} not supported here", case.texture.format))?;
        let kind = paths::sampler_kind(case);
        let state = sampler::state(case, kind, &format, &g.support)?;
        let shape = texture::shape(case)?;
        Ok(TextureSpec {
            case,
            state,
            shape,
            format,
        })
    }
}

/// The lookups of a batch that are drawn: the texture (index into the batch's textures) and plan
/// of job `job`.
struct Planned {
    job: usize,
    texture: usize,
    plan: Plan,
}

impl Serve for VkWorker {
    fn hello(&self) -> Hello {
        Hello {
            sweeps: false,
            protocol: PROTOCOL_VERSION,
            name: Some(self.display_name()),
            capabilities: self.caps.clone(),
            wants_expect: false,
        }
    }

    fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
        if let Some(why) = &self.lost {
            return Err(std::io::Error::other(format!(
                "the Vulkan device is lost ({why}); the worker ends"
            )));
        }
        // Admission: the declared capabilities decide, as the runner's did before sending.
        let serve::Admission {
            runnable,
            early,
            left_out,
        } = serve::admit(&self.caps, cases);
        let jobs = sweep::jobs(&runnable);
        let answers = self.plan_and_draw(&jobs);
        Ok(serve::assemble(early, left_out, &jobs, answers))
    }
}

mod batch;

/// `--probe`: open the device; `ok <name>` or `unavailable: <reason>`.
pub fn probe_line(driver: Driver) -> (bool, String) {
    match VkWorker::start(driver) {
        Ok(w) => (true, format!("ok {}", w.display_name())),
        Err(e) => (false, format!("unavailable: {e}")),
    }
}

/// The preferred lookup form of the `vk` path: explicit LOD first, as on the core path.
const FORM: LookupForm = LookupForm::Auto;

/// Plans job `j` on the `vk` path (no EXT_texture_shadow_lod: glslang 12 has no such
/// extension, and GLSL 4.50 lists none of its overloads).
fn plan_job(j: &Job) -> Result<Plan, String> {
    paths::plan_in(ApiPath::Vulkan, j.case, &j.lookup, FORM, false)
}

/// The RGBA of a lookup as the protocol carries it.
fn result(rgba: [f32; 4], plan: &Plan, stored: Option<shadowcheck_model::Texels>) -> PathResult {
    PathResult {
        sweep: vec![],
        api: ApiPath::Vulkan.key().to_string(),
        rgba: Rgba(rgba.map(|c| c as f64)),
        stored,
        note: Some(plan.note.clone()),
    }
}

/// Groups of consecutive jobs on equal textures (one texture each).
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
