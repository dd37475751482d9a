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

use super::draw::{BatchState, Job, Pending, Renderer};
use super::framebuffer::FB_SIZE;
use super::paths::{Plan, ShaderKey};
use super::programs::Compiled;
use super::shaders::{self, PARAM_ATTRIBS, PARAM_FLOATS};
use super::unitstate;
use glow::HasContext;

/// Most cases one batched draw serves (its quads must fit the framebuffer: `CAPACITY`).
pub(super) const DRAW_CASES: usize = 1024;

/// One batched draw: a program, the (case, plan) pairs it serves (slot k of the draw is item k),
/// and where item 0's values are in the parameter buffer (in cases).
pub(super) struct Batch<'p> {
    key: ShaderKey,
    items: Vec<(usize, &'p Plan)>,
    first: usize,
}

/// The parameter values of a worker batch: six vertices per case ([`PARAM_FLOATS`] each).
#[derive(Default)]
pub(super) struct ParamStaging {
    values: Vec<f32>,
}

/// Vertices per case: two triangles covering its quad.
const CASE_VERTICES: usize = 6;
/// The quad's corners, as two triangles of the same winding.
const CORNERS: [[f32; 2]; CASE_VERTICES] = [
    [0.0, 0.0],
    [1.0, 0.0],
    [0.0, 1.0],
    [0.0, 1.0],
    [1.0, 0.0],
    [1.0, 1.0],
];

impl ParamStaging {
    /// Stages the values of one draw's `plans`; returns the index of the first in the buffer (in
    /// cases). Each vertex of case k of the draw: corner, (x, k), P, dx, dy.
    fn stage(&mut self, plans: &[(usize, &Plan)]) -> usize {
        let first = self.values.len() / (PARAM_FLOATS * CASE_VERTICES);
        for (k, (_, p)) in plans.iter().enumerate() {
            for corner in CORNERS {
                self.values.extend_from_slice(&corner);
                self.values.extend_from_slice(&[p.x, k as f32]);
                self.values.extend_from_slice(&p.p);
                self.values.extend_from_slice(&p.dx);
                self.values.extend_from_slice(&p.dy);
            }
        }
        first
    }
}

/// The batched draws of `group`: batchable (case, plan) pairs by program in first-appearance
/// order, at most [`DRAW_CASES`] a draw, their values staged in `staging`. A batchable path is always drawn batched, even
/// alone, so the driver compiles one variant per (program, state), not a batched and a
/// single-pixel one.
pub(super) fn batches_of<'p>(
    group: &'p [(usize, Vec<Plan>)],
    staging: &mut ParamStaging,
) -> Vec<Batch<'p>> {
    let mut by_key: Vec<(ShaderKey, Vec<(usize, &Plan)>)> = Vec::new();
    for (ci, plans) in group {
        for plan in plans.iter().filter(|p| shaders::batchable(&p.key)) {
            match by_key.iter_mut().find(|(k, _)| *k == plan.key) {
                Some((_, v)) => v.push((*ci, plan)),
                None => by_key.push((plan.key, vec![(*ci, plan)])),
            }
        }
    }
    let mut out = Vec::new();
    for (key, items) in by_key {
        for chunk in items.chunks(DRAW_CASES) {
            let first = staging.stage(chunk);
            out.push(Batch {
                key,
                items: chunk.to_vec(),
                first,
            });
        }
    }
    out
}

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
    pub(super) unsafe fn draw_batched(
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
    pub(super) unsafe fn upload_staged(&mut self, staging: &ParamStaging) -> Result<(), String> {
        if staging.values.is_empty() {
            return Ok(());
        }
        let (buffer, _) = self.param_buffer()?;
        let mut bytes = std::mem::take(&mut self.upload);
        bytes.clear();
        bytes.extend(staging.values.iter().flat_map(|f| f.to_ne_bytes()));
        self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
        self.gl
            .buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STREAM_DRAW);
        self.upload = bytes;
        Ok(())
    }

    /// Runs a group of cases sharing texture and sampler state: the paths that cannot be batched
    /// one pixel each, then `batches` (the group's, from [`batches_of`], values uploaded).
    pub(super) unsafe fn run_group(
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paths;
    use shadowcheck_model::{ApiPath, Target};

    /// `n` cases of one program, case k with P.x = k + offset (so each value names its case).
    fn group(n: usize, first_ci: usize, offset: f32) -> Vec<(usize, Vec<Plan>)> {
        let case = crate::test_case::case(Target::T2d, 2, 2, 1);
        (0..n)
            .map(|k| {
                let mut p = paths::plan(ApiPath::GlslCore, &case).expect("core plan");
                p.p[0] = k as f32 + offset;
                (first_ci + k, vec![p])
            })
            .collect()
    }

    #[test]
    fn staged_values_sit_where_each_draw_reads_them() {
        let a = group(1500, 0, 0.0);
        let b = group(30, 1500, 5000.0);
        let mut staging = ParamStaging::default();
        let ba = batches_of(&a, &mut staging);
        let bb = batches_of(&b, &mut staging);
        assert!(shaders::batchable(&a[0].1[0].key));
        // A group is split at DRAW_CASES; the second group's values follow the first's.
        assert_eq!(
            ba.iter()
                .chain(&bb)
                .map(|b| (b.items.len(), b.first))
                .collect::<Vec<_>>(),
            vec![(DRAW_CASES, 0), (1500 - DRAW_CASES, DRAW_CASES), (30, 1500)]
        );
        assert_eq!(staging.values.len(), 1530 * CASE_VERTICES * PARAM_FLOATS);
        // Every vertex of case k of a draw (case first + k of the buffer) carries its corner,
        // (x, k), P, dx and dy where PARAM_ATTRIBS says.
        let attrib = |name: &str| {
            let (_, _, size, at) = PARAM_ATTRIBS.into_iter().find(|a| a.1 == name).expect(name);
            at..at + size as usize
        };
        for batch in ba.iter().chain(&bb) {
            for (k, (_, plan)) in batch.items.iter().enumerate() {
                for (vi, corner) in CORNERS.iter().enumerate() {
                    let at = ((batch.first + k) * CASE_VERTICES + vi) * PARAM_FLOATS;
                    let v = &staging.values[at..at + PARAM_FLOATS];
                    assert_eq!(v[attrib("a_pos")], corner[..]);
                    assert_eq!(v[attrib("a_x")], [plan.x, k as f32]);
                    assert_eq!(v[attrib("a_p")], plan.p);
                    assert_eq!(v[attrib("a_dx")], plan.dx);
                    assert_eq!(v[attrib("a_dy")], plan.dy);
                }
            }
        }
    }
}
