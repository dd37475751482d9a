//! Drawing a bundle of texture states (core and ES contexts): groups of cases that share one
//! texture and sampler state, group i's texture on unit i (`shadowcheck_plan::units`).
//!
//! On the GLSL 3.30 core and GLSL ES 3.00 paths every case of the bundle that uses the same
//! lookup is drawn by one draw of one program sampling all the bundle's units: case k is two
//! triangles over the 2x2 pixel quad of its slot, and its values (P, gradients, LOD, its unit)
//! come as attributes of its six vertices, passed to the fragment shader as flat inputs (bit for
//! bit). An implicit-derivative lookup varies P across its own quad
//! by the case's gradients, so the derivatives the driver takes within the quad are the case's
//! (GL 4.6 §15.2.3 / ES 3.2 §14.2.3 leave the neighbours open; every implementation this project
//! runs forms quads at even window coordinates, as dEQP also assumes). The other paths draw one
//! pixel per case.
//!
//! The values of every batched draw of a worker batch are staged first ([`batches_of`]) and
//! uploaded at once ([`Renderer::upload_staged`]) before the first draw: a buffer written while
//! queued draws read it makes the driver finish them first (llvmpipe flushes its scene).
//!
//! The fragment shader reads nothing but its inputs. An earlier form drew a full-screen triangle
//! and fetched each quad's values from a parameter texture with texelFetch; its variants took
//! llvmpipe nearly twice as long to compile (reports/BENCH.md).

use super::units::{group_cases, state_case, Groups, StateObjects};
use super::{BatchState, Pending, Renderer};
use crate::programs::Compiled;
use glow::HasContext;
use shadowcheck_plan::layout::{batches_of, Batch, ParamStaging, CASE_VERTICES, FB_SIZE};
use shadowcheck_plan::shaders::{self, PARAM_ATTRIBS, PARAM_FLOATS};
use shadowcheck_plan::units::{Bundle, ProgramKey};
use shadowcheck_plan::{Job, Plan};

impl Renderer {
    /// The parameter buffer and the vertex array reading it, created on first use.
    unsafe fn param_buffer(&mut self) -> Result<(glow::Buffer, glow::VertexArray), String> {
        if let Some(p) = self.params {
            return Ok(p);
        }
        let gl = &self.gl;
        let buffer = gl.create_buffer()?;
        let vao = gl.create_vertex_array()?;
        gl.bind_vertex_array(Some(vao));
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
        let stride = (PARAM_FLOATS * 4) as i32;
        for (loc, _, size, at) in PARAM_ATTRIBS {
            gl.vertex_attrib_pointer_f32(loc, size, glow::FLOAT, false, stride, (at * 4) as i32);
            gl.enable_vertex_attrib_array(loc);
        }
        gl.bind_vertex_array(Some(self.vao));
        self.params = Some((buffer, vao));
        Ok((buffer, vao))
    }

    /// One batched draw of `batch`: case k is the case in slot `slot0 + k`, its vertices from
    /// case `batch.first + k` of the parameter buffer on.
    pub(crate) unsafe fn draw_batched(
        &mut self,
        batch: &Batch,
        slot0: usize,
    ) -> Result<(), String> {
        let (n, first) = (batch.items.len(), batch.first);
        let (_, vao) = self.param_buffer()?;
        let pk = ProgramKey {
            key: batch.key,
            units: batch.units,
            batched: true,
        };
        let compiled = self.programs.get(
            &self.gl,
            &self.info,
            self.legacy.as_ref(),
            pk,
            Some(FB_SIZE),
        )?;
        let Compiled::Glsl(p) = compiled else {
            return Err("batched program is not GLSL".into());
        };
        let gl = &self.gl;
        gl.viewport(0, 0, FB_SIZE, FB_SIZE);
        gl.use_program(Some(p.program));
        gl.uniform_1_i32(p.u_base.as_ref(), slot0 as i32);
        gl.bind_vertex_array(Some(vao));
        gl.draw_arrays(
            glow::TRIANGLES,
            (first * CASE_VERTICES) as i32,
            (n * CASE_VERTICES) as i32,
        );
        gl.bind_vertex_array(Some(self.vao));
        Ok(())
    }

    /// Uploads the staged values to the parameter buffer (a new store each batch, so no queued
    /// draw waits on it).
    pub(crate) unsafe fn upload_staged(&mut self, staging: &ParamStaging) -> Result<(), String> {
        if staging.values().is_empty() {
            return Ok(());
        }
        let (buffer, _) = self.param_buffer()?;
        let mut bytes = std::mem::take(&mut self.upload);
        bytes.clear();
        bytes.extend(staging.values().iter().flat_map(|f| f.to_ne_bytes()));
        self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
        self.gl
            .buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STREAM_DRAW);
        self.upload = bytes;
        Ok(())
    }

    /// Runs `groups` (a batch's texture states) on a core or ES context: every bundle's batched
    /// draws staged and uploaded first, each state's texture made once, then bundle after bundle
    /// bound and drawn; the textures are read back at the end.
    pub(crate) unsafe fn run_batched(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundles: &[Bundle],
        st: &mut BatchState,
    ) {
        // Every batched draw's values in place before the first draw.
        let mut staging = ParamStaging::default();
        let batches: Vec<Vec<Batch>> = bundles
            .iter()
            .map(|b| {
                let members: Vec<&[(usize, Vec<Plan>)]> =
                    b.states.iter().map(|&g| &groups[g][..]).collect();
                batches_of(b.key, &members, &mut staging)
            })
            .collect();
        if let Err(e) = self.upload_staged(&staging) {
            let all = groups.iter().flatten().map(|(ci, _)| *ci);
            st.fail_unanswered(all, &format!("parameter buffer: {e}"));
            return;
        }
        let mut objects: Vec<Option<StateObjects>> = Vec::with_capacity(groups.len());
        for g in 0..groups.len() {
            objects.push(self.create_state(
                state_case(jobs, groups, g),
                group_cases(groups, g),
                st,
            ));
        }
        for (b, batches) in bundles.iter().zip(batches) {
            self.run_bundle(jobs, groups, b, &objects, batches, st);
        }
        for (g, o) in objects.into_iter().enumerate() {
            if let Some(o) = o {
                self.release_state(jobs, groups, g, o, true, st);
            }
        }
    }

    /// One bundle: its states bound together (state i on unit i), the cases that use its program
    /// drawn: one pixel each where the program cannot be batched, else `batches` (the bundle's,
    /// from [`batches_of`], values uploaded).
    unsafe fn run_bundle(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        objects: &[Option<StateObjects>],
        batches: Vec<Batch<'_>>,
        st: &mut BatchState,
    ) {
        let bound = self.bind_bundle(jobs, groups, bundle, objects, st);
        if !shaders::batchable(&bundle.key) {
            self.draw_singly(jobs, groups, bundle, &bound, st);
        }
        for b in batches {
            // A case that failed on another path (or whose texture failed) is drawn with the
            // others (its values are in place) but not read back.
            if b.items.iter().all(|(ci, _, _)| st.answers[*ci].is_some()) {
                continue;
            }
            let slot0 = self.take_slots(st, b.items.len());
            match self.draw_batched(&b, slot0) {
                Ok(()) => {
                    for (k, (ci, p, _)) in b.items.iter().enumerate() {
                        if st.answers[*ci].is_none() {
                            // A sweep point's answer keeps only its RGBA (`sweep::merge`).
                            let note = if jobs[*ci].point {
                                String::new()
                            } else {
                                format!("{}, batched", p.note)
                            };
                            st.pending.push(Pending {
                                case: *ci,
                                path: p.key.path,
                                slot: slot0 + k,
                                note,
                            });
                        }
                    }
                }
                Err(e) => {
                    for (ci, _, _) in &b.items {
                        if st.answers[*ci].is_none() {
                            st.fail(*ci, format!("{}: {e}", b.key.path));
                        }
                    }
                }
            }
        }
        self.finish_bundle(jobs, groups, bundle, objects, &bound, st);
    }
}
