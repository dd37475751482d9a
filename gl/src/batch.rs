//! Drawing a group of cases that share one texture and sampler state (core and ES contexts).
//!
//! On the GLSL 1.30+ paths every case of the group that uses the same program is drawn by one
//! full-screen draw: each case's values (P, gradients, LOD) go into an RGBA32F parameter texture,
//! each fragment finds its case from its 2x2 pixel quad and reads them with texelFetch (exact). An
//! implicit-derivative lookup varies P across its own quad by the case's gradients, so the
//! derivatives the driver takes within the quad are the case's (GL 4.6 §15.2.3 / ES 3.2 §14.2.3
//! leave the neighbours open; every implementation this project runs forms quads at even window
//! coordinates, as dEQP also assumes). The other paths draw one pixel per case.
//!
//! The values of every batched draw of a worker batch are staged first ([`batches_of`]) and
//! uploaded at once ([`Renderer::upload_staged`]) before the first draw: a texture written while
//! queued draws read it makes the driver finish them first (llvmpipe flushes its scene), and one
//! upload per batch instead of one per draw saves a texture update per group.

use super::draw::{BatchState, Job, Pending, Renderer};
use super::framebuffer::{pixel, FB_SIZE};
use super::paths::{Plan, ShaderKey};
use super::programs::Compiled;
use super::shaders::{self, PARAM_CASES, PARAM_TEXELS, PARAM_WIDTH};
use super::texture;
use super::unitstate;
use glow::HasContext;

/// One batched draw: a program, the (case, plan) pairs it serves (slot k of the draw is item k),
/// and where item 0's values are: parameter texture `texture`, case index `first` in it.
pub(super) struct Batch<'p> {
    key: ShaderKey,
    items: Vec<(usize, &'p Plan)>,
    texture: usize,
    first: usize,
}

/// The parameter values of a worker batch, per parameter texture (four RGBA texels per case).
#[derive(Default)]
pub(super) struct ParamStaging {
    textures: Vec<Vec<f32>>,
}

impl ParamStaging {
    /// Stages the values of `plans` (at most [`PARAM_CASES`]) in one texture; returns (texture,
    /// index of the first case in it).
    fn stage(&mut self, plans: &[(usize, &Plan)]) -> (usize, usize) {
        let per_case = (PARAM_TEXELS * 4) as usize;
        let fits = |d: &Vec<f32>| d.len() / per_case + plans.len() <= PARAM_CASES;
        if !self.textures.last().is_some_and(fits) {
            self.textures.push(Vec::new());
        }
        let texture = self.textures.len() - 1;
        let data = &mut self.textures[texture];
        let first = data.len() / per_case;
        for (_, p) in plans {
            data.extend_from_slice(&p.p);
            data.extend_from_slice(&p.dx);
            data.extend_from_slice(&p.dy);
            data.extend_from_slice(&[p.x, 0.0, 0.0, 0.0]);
        }
        (texture, first)
    }
}

/// The batched draws of `group`: batchable (case, plan) pairs by program in first-appearance
/// order, at most [`PARAM_CASES`] a draw, their values staged in `staging`. A batchable path is
/// always drawn batched, even alone, so the driver compiles one variant per (program, state), not
/// a batched and a single-pixel one.
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
        for chunk in items.chunks(PARAM_CASES) {
            let (texture, first) = staging.stage(chunk);
            out.push(Batch {
                key,
                items: chunk.to_vec(),
                texture,
                first,
            });
        }
    }
    out
}

impl Renderer {
    /// Parameter texture `k`, created (with those before it) when missing.
    pub(super) unsafe fn param_texture(&mut self, k: usize) -> Result<glow::Texture, String> {
        let rows = shaders::PARAM_CASES as i32 * shaders::PARAM_TEXELS / shaders::PARAM_WIDTH;
        while self.params.len() <= k {
            self.gl.active_texture(glow::TEXTURE1);
            let t = texture::rgba32f(&self.gl, shaders::PARAM_WIDTH, rows);
            self.gl.active_texture(glow::TEXTURE0);
            self.params.push(t?);
        }
        Ok(self.params[k])
    }

    /// One batched draw: the values of its `n` cases are in parameter texture `param.0` from case
    /// `param.1` on, their results go to slots `slot0..slot0+n`.
    pub(super) unsafe fn draw_batched(
        &mut self,
        key: &ShaderKey,
        slot0: usize,
        n: usize,
        param: (usize, usize),
    ) -> Result<(), String> {
        let params = self.param_texture(param.0)?;
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
        // Only the quads of the draw's slots are rasterized: the rows they span, and within a
        // single row only its columns (quads stay at even window coordinates).
        let (x0, y0) = pixel(slot0);
        let (x1, y1) = pixel(slot0 + n - 1);
        if y0 == y1 {
            gl.viewport(x0, y0, x1 + 2 - x0, 2);
        } else {
            gl.viewport(0, y0, FB_SIZE, y1 + 2 - y0);
        }
        gl.active_texture(glow::TEXTURE1);
        gl.bind_texture(glow::TEXTURE_2D, Some(params));
        gl.active_texture(glow::TEXTURE0);
        gl.use_program(Some(p.program));
        gl.uniform_1_i32(p.u_base.as_ref(), slot0 as i32);
        gl.uniform_1_i32(p.u_count.as_ref(), n as i32);
        gl.uniform_1_i32(p.u_param0.as_ref(), param.1 as i32);
        gl.bind_vertex_array(Some(self.vao));
        gl.draw_arrays(glow::TRIANGLES, 0, 3);
        Ok(())
    }

    /// Uploads the staged values, texture k of `staging` to parameter texture k (created when
    /// there are fewer), only the rows that hold values.
    pub(super) unsafe fn upload_staged(&mut self, staging: &ParamStaging) -> Result<(), String> {
        for (k, data) in staging.textures.iter().enumerate() {
            let tex = self.param_texture(k)?;
            let row = (PARAM_WIDTH * 4) as usize;
            let rows = data.len().div_ceil(row);
            let mut bytes = std::mem::take(&mut self.upload);
            bytes.clear();
            bytes.extend(data.iter().flat_map(|f| f.to_ne_bytes()));
            bytes.resize(rows * row * 4, 0);
            self.gl.active_texture(glow::TEXTURE1);
            self.gl.bind_texture(glow::TEXTURE_2D, Some(tex));
            self.gl.tex_sub_image_2d(
                glow::TEXTURE_2D,
                0,
                0,
                0,
                PARAM_WIDTH,
                rows as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelUnpackData::Slice(Some(&bytes)),
            );
            self.gl.active_texture(glow::TEXTURE0);
            self.upload = bytes;
        }
        Ok(())
    }

    /// Runs a group of cases sharing texture and sampler state: the paths that cannot be batched
    /// one pixel each, then `batches` (the group's, from [`batches_of`], values uploaded).
    pub(super) unsafe fn run_group(
        &mut self,
        cases: &[Job],
        group: &[(usize, Vec<Plan>)],
        batches: Vec<Batch<'_>>,
        st: &mut BatchState,
    ) {
        let first = cases[group[0].0].case;
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
            match self.draw_batched(&b.key, slot0, b.items.len(), (b.texture, b.first)) {
                Ok(()) => {
                    for (k, (ci, p)) in b.items.iter().enumerate() {
                        if st.answers[*ci].is_none() {
                            // A sweep point's answer keeps only its RGBA (`sweep::merge`).
                            let note = if cases[*ci].point {
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
        self.retire(cases, st, tex, group[0].0, sharing);
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
        let per_case = (PARAM_TEXELS * 4) as usize;
        let a = group(PARAM_CASES + 10, 0, 0.0);
        let b = group(30, PARAM_CASES + 10, 5000.0);
        let mut staging = ParamStaging::default();
        let ba = batches_of(&a, &mut staging);
        let bb = batches_of(&b, &mut staging);
        assert!(shaders::batchable(&a[0].1[0].key));
        // A group larger than one texture is split at PARAM_CASES; a batch never straddles
        // textures, so the second group's 30 start a texture only where the rest does not fit.
        assert_eq!(
            ba.iter()
                .map(|b| (b.items.len(), b.texture, b.first))
                .collect::<Vec<_>>(),
            vec![(PARAM_CASES, 0, 0), (10, 1, 0)]
        );
        assert_eq!(
            bb.iter()
                .map(|b| (b.items.len(), b.texture, b.first))
                .collect::<Vec<_>>(),
            vec![(30, 1, 10)]
        );
        assert_eq!(staging.textures[0].len(), PARAM_CASES * per_case);
        assert_eq!(staging.textures[1].len(), 40 * per_case);
        // Item k of a draw is read at case index first + k of its texture: P, dx, dy, (x, 0, 0, 0).
        for batch in ba.iter().chain(&bb) {
            let data = &staging.textures[batch.texture];
            for (k, (_, plan)) in batch.items.iter().enumerate() {
                let at = (batch.first + k) * per_case;
                assert_eq!(data[at..at + 4], plan.p);
                assert_eq!(data[at + 4..at + 8], plan.dx);
                assert_eq!(data[at + 8..at + 12], plan.dy);
                assert_eq!(data[at + 12..at + 16], [plan.x, 0.0, 0.0, 0.0]);
            }
        }
    }
}
