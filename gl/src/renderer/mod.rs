//! Drawing a batch of cases: each (case, API path) owns one 2x2 pixel quad of an RGBA32F
//! framebuffer and its result is the quad's lower-left pixel, so results are not quantized, all
//! four channels are observed, and a batched draw of implicit-derivative lookups gives every case
//! a quad of its own (derivatives are differences within a quad); the batch is read back at once
//! (slots, clearing and read-back: `readback.rs`).
//!
//! Consecutive cases with the same texture and sampler state (a case and its sweep points, or
//! the grid's neighbours: only the reference or the coordinate changes) share one texture object.
//! The texture states of a batch are dealt into bundles (`shadowcheck_plan::units`): the states of
//! a bundle are bound together, state i on texture unit i, and each program samples all of them,
//! so a driver that compiles a variant per sampler state compiles one per bundle. On the core and
//! ES paths every case of a bundle that uses one program is drawn with one draw, each case two
//! triangles over its own quad with its values (and its unit) as vertex attributes (see
//! `batched.rs`). Compatibility contexts give each API path of a bundle textures of their own
//! (see `compat.rs`).

mod batched;
mod compat;
mod readback;
mod units;

use crate::legacy::{self, Legacy};
use crate::programs::{Compiled, ProgramCache};
use crate::texture;
use crate::WorkerError;
use glow::HasContext;
use shadowcheck_model::{ApiPath, Stage, Target, Texels};
use shadowcheck_plan::layout::{pixel, CAPACITY, FB_SIZE};
use shadowcheck_plan::shaders::{self, arbfp_unit_weights, ARBFP_WEIGHTS, UNIT_ATTRIB};
use shadowcheck_plan::units::{self as plan_units, ProgramKey};
use shadowcheck_plan::{Answer, GlInfo, Job, LodForm, Plan, ShaderKey};
use shadowcheck_protocol::{PathResult, PathSkip};
use std::collections::HashSet;

/// Most textures kept alive for a deferred read-back.
const MAX_DEFERRED: usize = 4096;

/// The GL objects of a worker and its program cache.
pub struct Renderer {
    pub gl: glow::Context,
    pub info: GlInfo,
    pub(crate) legacy: Option<Legacy>,
    pub(crate) fbo: glow::Framebuffer,
    /// The framebuffer's RGBA32F colour texture: the image a compute-stage lookup stores its
    /// result in (image unit 0, `shaders::stage`).
    pub(crate) colour: glow::Texture,
    pub(crate) vao: glow::VertexArray,
    /// The per-case values of batched draws (`batched.rs`) and the vertex array reading them as
    /// vertex attributes; created when a batch first needs them.
    pub(crate) params: Option<(glow::Buffer, glow::VertexArray)>,
    /// Slots drawn since the framebuffer was last cleared (their quad rows are cleared next).
    pub(crate) drawn: usize,
    pub(crate) programs: ProgramCache,
    /// The last read-back of the framebuffer (`readback.rs`) and the bytes of the last
    /// parameter upload (`batched.rs`), kept so that a batch allocates neither.
    pub(crate) readback: Vec<u8>,
    pub(crate) upload: Vec<u8>,
    /// Sampler states one program samples at most (texture units bound together, `units.rs`).
    pub(crate) states_per_program: usize,
    pub(crate) drawn_sets: Drawn,
}

/// What a renderer has drawn with programs (GLSL, ARB fragment programs; fixed function, drawn one
/// state at a time, is not counted), in the terms a driver that compiles one shader variant per
/// (program, sampler states of its units) sees: distinct sampling states
/// ([`plan_units::sampling_fingerprint`]), so a set drawn again, in a later batch or with other
/// texels, is counted once.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Distinct (lookup, sampling state) pairs drawn: the variants one state per program compiles.
    pub states: usize,
    /// Distinct (program, sampling states in unit order) sets drawn: the variants compiled when
    /// states share programs.
    pub state_sets: usize,
    /// The units of those sets, added up (each unit's sampling code is compiled in its set).
    pub units: usize,
}

/// The distinct pairs and sets behind [`RenderStats`].
#[derive(Debug, Default)]
pub(crate) struct Drawn {
    pairs: HashSet<(ShaderKey, u64)>,
    sets: HashSet<(ProgramKey, Vec<u64>)>,
    units: usize,
}

/// A drawn path waiting for read-back.
pub(crate) struct Pending {
    pub(crate) case: usize,
    pub(crate) path: ApiPath,
    pub(crate) slot: usize,
    pub(crate) note: String,
}

/// Answers and pixels of a batch in progress.
pub(crate) struct BatchState {
    pub(crate) answers: Vec<Option<Answer>>,
    pub(crate) results: Vec<Vec<PathResult>>,
    pub(crate) stored: Vec<Option<Texels>>,
    pub(crate) pending: Vec<Pending>,
    /// The next free slot of the framebuffer. Not `pending.len()`: a failed case's pixels leave
    /// `pending` but stay drawn, and a later draw must not reuse their slots.
    pub(crate) next_slot: usize,
    /// Textures whose level 0 is read back after the batch is drawn (reading back between draws
    /// makes the driver finish the queued draws first): texture, its case, the cases sharing it.
    pub(crate) readbacks: Vec<(glow::Texture, usize, Vec<usize>)>,
    /// Per case: the API paths it names that this context cannot run, with the reason.
    pub(crate) skipped: Vec<Vec<PathSkip>>,
}

impl BatchState {
    /// Case `ci` fails: its drawn pixels are dropped and it answers `error`.
    pub(crate) fn fail(&mut self, ci: usize, msg: String) {
        self.pending.retain(|p| p.case != ci);
        self.results[ci].clear();
        self.answers[ci] = Some(Answer::Error(msg));
    }

    /// Every case of `cis` not answered yet fails with `msg`.
    pub(crate) fn fail_unanswered(&mut self, cis: impl IntoIterator<Item = usize>, msg: &str) {
        for ci in cis {
            if self.answers[ci].is_none() {
                self.fail(ci, msg.to_string());
            }
        }
    }
}

impl Renderer {
    /// Sets up the framebuffer and the full-screen triangle.
    ///
    /// # Safety
    /// `gl` must be current on this thread for the Renderer's whole life.
    pub unsafe fn new(
        gl: glow::Context,
        info: GlInfo,
        legacy: Option<Legacy>,
    ) -> Result<Renderer, WorkerError> {
        let (fbo, colour) =
            texture::rgba32f_framebuffer(&gl, FB_SIZE, info.compute()).map_err(WorkerError::Gl)?;
        gl.bind_texture(glow::TEXTURE_2D, None);
        let vao = gl.create_vertex_array().map_err(WorkerError::Gl)?;
        gl.bind_vertex_array(Some(vao));
        let vbo = gl.create_buffer().map_err(WorkerError::Gl)?;
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        let tri: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
        let bytes: Vec<u8> = tri.iter().flat_map(|f| f.to_ne_bytes()).collect();
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
        gl.vertex_attrib_pointer_f32(0, 2, glow::FLOAT, false, 8, 0);
        gl.enable_vertex_attrib_array(0);
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.disable(glow::DITHER);
        texture::check(&gl, "framebuffer setup")?;
        Ok(Renderer {
            gl,
            info,
            legacy,
            fbo,
            colour,
            vao,
            params: None,
            // The colour texture's contents are undefined until the first clear.
            drawn: CAPACITY,
            programs: ProgramCache::default(),
            readback: Vec::new(),
            upload: Vec::new(),
            states_per_program: plan_units::DEFAULT_STATES_PER_PROGRAM,
            drawn_sets: Drawn::default(),
        })
    }

    /// Sampler states one program samples at most from now on (1: one state per program).
    pub fn set_states_per_program(&mut self, k: usize) {
        self.states_per_program = k.max(1);
    }

    /// Sampler states one program samples at most.
    pub fn states_per_program(&self) -> usize {
        self.states_per_program
    }

    /// What has been drawn so far.
    pub fn stats(&self) -> RenderStats {
        let d = &self.drawn_sets;
        RenderStats {
            states: d.pairs.len(),
            state_sets: d.sets.len(),
            units: d.units,
        }
    }

    /// Programs compiled so far (GLSL and ARB fragment programs).
    pub fn programs_compiled(&self) -> usize {
        self.programs.compiled()
    }

    /// Counts one bundle's draws: the program `program` over the states `cases` (one per unit,
    /// their first cases) bound together.
    pub(crate) fn count_bundle<'c>(
        &mut self,
        program: ProgramKey,
        cases: impl IntoIterator<Item = &'c shadowcheck_model::Case>,
    ) {
        if program.key.path == ApiPath::FixedFunction {
            return;
        }
        let fps: Vec<u64> = cases
            .into_iter()
            .map(plan_units::sampling_fingerprint)
            .collect();
        let d = &mut self.drawn_sets;
        for &fp in &fps {
            d.pairs.insert((program.key, fp));
        }
        let units = fps.len();
        if d.sets.insert((program, fps)) {
            d.units += units;
        }
    }

    /// Draws `plan` into `slot` alone, with the program of `units` samplers and the case's state
    /// on texture unit `unit`.
    pub(crate) unsafe fn draw(
        &mut self,
        plan: &Plan,
        target: Target,
        slot: usize,
        (unit, units): (usize, usize),
    ) -> Result<(), String> {
        let pk = ProgramKey {
            key: plan.key,
            units,
            batched: false,
        };
        let compiled = self
            .programs
            .get(&self.gl, &self.info, self.legacy.as_ref(), pk, None)?;
        let (x, y) = pixel(slot);
        let gl = &self.gl;
        let [vx, vy, vw, vh] = shaders::single_draw_viewport(&plan.key, (x, y));
        gl.viewport(vx, vy, vw, vh);
        let centre = [x as f32 + 0.5, y as f32 + 0.5];
        match compiled {
            Compiled::Glsl(p) if plan.key.stage == Stage::Compute => {
                // One invocation stores the result at the slot's pixel of the colour texture
                // (image unit 0); the barrier makes the store visible to the framebuffer reads
                // and clears that follow (GL 4.6 / ES 3.2, "Shader Memory Access Synchronization":
                // MemoryBarrier with FRAMEBUFFER_BARRIER_BIT).
                // The framebuffer is unbound around the dispatch: softpipe (Mesa 22.3.6) keeps
                // the texture's framebuffer tiles cached across the barrier and would read back
                // what was there before the store (reports/README.md, "compute results").
                gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                gl.use_program(Some(p.program));
                gl.bind_image_texture(
                    0,
                    Some(self.colour),
                    0,
                    false,
                    0,
                    glow::WRITE_ONLY,
                    glow::RGBA32F,
                );
                if units > 1 {
                    gl.uniform_1_i32(p.u_unit.as_ref(), unit as i32);
                }
                gl.uniform_4_f32_slice(p.u_p.as_ref(), &plan.p);
                gl.uniform_1_f32(p.u_x.as_ref(), plan.x);
                gl.uniform_2_i32(p.u_at.as_ref(), x, y);
                gl.dispatch_compute(1, 1, 1);
                gl.memory_barrier(glow::ALL_BARRIER_BITS);
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.fbo));
            }
            Compiled::Glsl(p) => {
                gl.use_program(Some(p.program));
                if units > 1 {
                    // The current value of the unit attribute (its array is never enabled).
                    gl.vertex_attrib_1_f32(UNIT_ATTRIB.0, unit as f32);
                }
                gl.uniform_4_f32_slice(p.u_p.as_ref(), &plan.p);
                gl.uniform_1_f32(p.u_x.as_ref(), plan.x);
                gl.uniform_4_f32_slice(p.u_dx.as_ref(), &plan.dx);
                gl.uniform_4_f32_slice(p.u_dy.as_ref(), &plan.dy);
                gl.uniform_2_f32(p.u_c.as_ref(), centre[0], centre[1]);
                if p.u_o.is_some() {
                    gl.uniform_2_i32(p.u_o.as_ref(), plan.o[0], plan.o[1]);
                }
                gl.bind_vertex_array(Some(self.vao));
                gl.draw_arrays(glow::TRIANGLES, 0, 3);
            }
            Compiled::Arb(id) => {
                let l = self
                    .legacy
                    .as_ref()
                    .ok_or("legacy entry points not loaded")?;
                gl.use_program(None);
                gl.enable(legacy::GL_FRAGMENT_PROGRAM_ARB);
                l.bind_arbfp(*id);
                l.arbfp_local(0, plan.p);
                l.arbfp_local(1, plan.dx);
                l.arbfp_local(2, plan.dy);
                l.arbfp_local(3, [centre[0], centre[1], 0.0, 0.0]);
                if units > 1 {
                    for (j, w) in arbfp_unit_weights(unit, units).into_iter().enumerate() {
                        l.arbfp_local(ARBFP_WEIGHTS + j as u32, w);
                    }
                }
                l.fullscreen_triangle();
                gl.disable(legacy::GL_FRAGMENT_PROGRAM_ARB);
            }
            Compiled::Fixed => {
                if unit != 0 {
                    return Err("fixed function draws texture unit 0 alone".into());
                }
                let l = self
                    .legacy
                    .as_ref()
                    .ok_or("legacy entry points not loaded")?;
                gl.use_program(None);
                let enable = target.gl();
                gl.enable(enable);
                // COMBINE with REPLACE of SOURCE0 = TEXTURE, OPERAND0 = SRC_COLOR / SRC_ALPHA: the
                // fragment colour is the source colour (Cs, As) of GL 2.1 Table 3.20 in all four
                // channels (plain REPLACE would take the RGB of an ALPHA texture and the alpha of a
                // LUMINANCE one from the fragment and hide them: reports/piglit, hole H1).
                for (pname, value) in [
                    (legacy::GL_TEXTURE_ENV_MODE, legacy::GL_COMBINE),
                    (legacy::GL_COMBINE_RGB, legacy::GL_REPLACE),
                    (legacy::GL_COMBINE_ALPHA, legacy::GL_REPLACE),
                    (legacy::GL_SOURCE0_RGB, legacy::GL_TEXTURE),
                    (legacy::GL_SOURCE0_ALPHA, legacy::GL_TEXTURE),
                    (legacy::GL_OPERAND0_RGB, legacy::GL_SRC_COLOR),
                    (legacy::GL_OPERAND0_ALPHA, legacy::GL_SRC_ALPHA),
                ] {
                    l.tex_envi(legacy::GL_TEXTURE_ENV, pname, value as i32);
                }
                // Seen only where texturing is disabled (an incomplete texture, §3.8.10).
                l.color4f([0.0, 0.0, 0.0, 1.0]);
                let tc = match target {
                    Target::Cube => [plan.p[0], plan.p[1], plan.p[2], 1.0],
                    _ => plan.p,
                };
                if let LodForm::Implicit(bias) = plan.key.form {
                    // Vertex (X, Y) in NDC lies (X/2, Y/2) pixels from the pixel centre (1x1
                    // viewport): the coordinate there is tc + X/2 * dx + Y/2 * dy.
                    let b = if bias { plan.x } else { 0.0 };
                    l.tex_envf(
                        legacy::GL_TEXTURE_FILTER_CONTROL,
                        legacy::GL_TEXTURE_LOD_BIAS,
                        b,
                    );
                    let at = |ox: f32, oy: f32| -> [f32; 4] {
                        let mut v = tc;
                        for (i, c) in v.iter_mut().enumerate() {
                            *c += ox * plan.dx[i] + oy * plan.dy[i];
                        }
                        v
                    };
                    l.triangle_with_tex_coords([at(-0.5, -0.5), at(1.5, -0.5), at(-0.5, 1.5)]);
                    l.tex_envf(
                        legacy::GL_TEXTURE_FILTER_CONTROL,
                        legacy::GL_TEXTURE_LOD_BIAS,
                        0.0,
                    );
                } else {
                    l.tex_coord4f(tc);
                    l.fullscreen_triangle();
                }
                gl.disable(enable);
            }
        }
        Ok(())
    }

    /// Runs a batch and answers every job, in order.
    ///
    /// # Safety
    /// The renderer's context must be current.
    pub unsafe fn draw_jobs(&mut self, jobs: &[Job]) -> Vec<Answer> {
        let mut st = BatchState {
            answers: vec![None; jobs.len()],
            results: vec![Vec::new(); jobs.len()],
            stored: vec![None; jobs.len()],
            pending: Vec::new(),
            next_slot: 0,
            readbacks: Vec::new(),
            skipped: vec![Vec::new(); jobs.len()],
        };
        self.clear();
        // Consecutive cases with equal texture and sampler form one group (one texture state),
        // and the groups are dealt into bundles, one per program, of states drawn together.
        let plan = plan_units::plan_batch(&self.info, jobs, self.states_per_program);
        for (ci, why) in plan.unplanned {
            st.answers[ci] = Some(Answer::Skip(why));
        }
        st.skipped = plan.skipped;
        let (groups, bundles) = (plan.groups, plan.bundles);
        if self.info.compat {
            self.run_compat(jobs, &groups, &bundles, &mut st);
        } else {
            self.run_batched(jobs, &groups, &bundles, &mut st);
        }
        let mut pending = std::mem::take(&mut st.pending);
        self.collect(&mut pending, &mut st.results);
        self.finish_readbacks(jobs, &mut st);
        st.answers
            .into_iter()
            .zip(st.results)
            .zip(st.stored)
            .zip(st.skipped)
            .zip(jobs)
            .map(|((((a, mut r), stored), skipped), job)| {
                a.unwrap_or_else(|| {
                    r.sort_by_key(|e| job.case.api.iter().position(|p| p.key() == e.api));
                    for e in &mut r {
                        e.stored = stored.clone();
                    }
                    Answer::Observation(r, skipped)
                })
            })
            .collect()
    }

    /// Reads back the deferred textures and deletes them.
    pub(crate) unsafe fn finish_readbacks(&mut self, jobs: &[Job], st: &mut BatchState) {
        for (tex, ci, sharing) in std::mem::take(&mut st.readbacks) {
            let stored = texture::read_back(&self.gl, tex, jobs[ci].case).ok();
            for c in sharing.into_iter().filter(|c| !jobs[*c].point) {
                st.stored[c] = stored.clone();
            }
            self.gl.delete_texture(tex);
        }
    }

    /// Queues `tex` for read-back (desktop GL) or deletes it (ES has no glGetTexImage).
    pub(crate) unsafe fn retire(
        &mut self,
        jobs: &[Job],
        st: &mut BatchState,
        tex: glow::Texture,
        ci: usize,
        sharing: Vec<usize>,
    ) {
        if self.info.es {
            self.gl.delete_texture(tex);
            return;
        }
        st.readbacks.push((tex, ci, sharing));
        if st.readbacks.len() >= MAX_DEFERRED {
            self.finish_readbacks(jobs, st);
        }
    }

    /// After a bundle's draws: a GL error makes the cases `cis` not answered yet fail.
    pub(crate) unsafe fn check_group(
        &self,
        cis: impl IntoIterator<Item = usize>,
        st: &mut BatchState,
    ) {
        if let Err(e) = texture::check(&self.gl, "drawing") {
            st.fail_unanswered(cis, &e.to_string());
        }
    }
}
