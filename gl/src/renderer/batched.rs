//! Drawing a group of cases that share one texture and sampler state (core and ES contexts).
//!
//! On the GLSL 3.30 core and GLSL ES 3.00 paths every case of the group that uses the same
//! program is drawn by one draw: case k is two triangles over the 2x2 pixel quad of its slot,
//! and its values (P, gradients, LOD) come as attributes of its six vertices, passed to the
//! fragment shader as flat inputs (bit for bit). An implicit-derivative lookup varies P across its own quad
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

use super::{BatchState, Pending, Renderer};
use crate::programs::Compiled;
use crate::unitstate;
use glow::HasContext;
use shadowcheck_plan::layout::{Batch, ParamStaging, CASE_VERTICES, FB_SIZE};
use shadowcheck_plan::shaders::{self, PARAM_ATTRIBS, PARAM_FLOATS};
use shadowcheck_plan::{Job, Plan, ShaderKey};

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

    /// One batched draw: case k is the case in slot `slot0 + k`, its vertices from case
    /// `first + k` of the parameter buffer on.
    pub(crate) unsafe fn draw_batched(
        &mut self,
        key: &ShaderKey,
        slot0: usize,
        n: usize,
        first: usize,
    ) -> Result<(), String> {
        let (_, vao) = self.param_buffer()?;
        let compiled = self.programs.get(
            &self.gl,
            &self.info,
            self.legacy.as_ref(),
            key,
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

    /// Runs a group of cases sharing texture and sampler state: the paths that cannot be batched
    /// one pixel each, then `batches` (the group's, from [`batches_of`], values uploaded).
    pub(crate) unsafe fn run_group(
        &mut self,
        jobs: &[Job],
        group: &[(usize, Vec<Plan>)],
        batches: Vec<Batch<'_>>,
        st: &mut BatchState,
    ) {
        let first = jobs[group[0].0].case;
        let Some((tex, so)) = self.bind_group_texture(first, group.iter().map(|(ci, _)| *ci), st)
        else {
            return;
        };
        for (ci, plans) in group {
            for plan in plans.iter().filter(|p| !shaders::batchable(&p.key)) {
                let slot = self.take_slots(st, 1);
                match self.draw(plan, first.texture.target, slot) {
                    Ok(()) => st.pending.push(Pending {
                        case: *ci,
                        path: plan.key.path,
                        slot,
                        note: plan.note.clone(),
                    }),
                    Err(e) => st.fail(*ci, format!("{}: {e}", plan.key.path)),
                }
            }
        }
        for b in batches {
            // A case that failed on another path is drawn with the others (its values are in
            // place) but not read back.
            if b.items.iter().all(|(ci, _)| st.answers[*ci].is_some()) {
                continue;
            }
            let slot0 = self.take_slots(st, b.items.len());
            match self.draw_batched(&b.key, slot0, b.items.len(), b.first) {
                Ok(()) => {
                    for (k, (ci, p)) in b.items.iter().enumerate() {
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
                    for (ci, _) in &b.items {
                        if st.answers[*ci].is_none() {
                            st.fail(*ci, format!("{}: {e}", b.key.path));
                        }
                    }
                }
            }
        }
        unitstate::unbind_unit_state(&self.gl, first, so);
        let sharing: Vec<usize> = group.iter().map(|(ci, _)| *ci).collect();
        self.retire(jobs, st, tex, group[0].0, sharing);
        self.check_group(group.iter().map(|(ci, _)| *ci), st);
    }
}
