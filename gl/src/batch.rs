//! Drawing a group of cases that share one texture and sampler state (core and ES contexts).
//!
//! On the GLSL 1.30+ paths every case of the group that uses the same program is drawn by one
//! full-screen draw: each case's values (P, gradients, LOD) go into an RGBA32F parameter texture,
//! each fragment finds its case from its 2x2 pixel quad and reads them with texelFetch (exact). An
//! implicit-derivative lookup varies P across its own quad by the case's gradients, so the
//! derivatives the driver takes within the quad are the case's (GL 4.6 §15.2.3 / ES 3.2 §14.2.3
//! leave the neighbours open; every implementation this project runs forms quads at even window
//! coordinates, as dEQP also assumes). The other paths draw one pixel per case.

use super::draw::{BatchState, Pending, Renderer};
use super::paths::{Plan, ShaderKey};
use super::shaders::{self, PARAM_CASES, PARAM_TEXELS, PARAM_WIDTH};
use super::unitstate;
use glow::HasContext;
use shadowcheck_model::Case;

impl Renderer {
    /// Uploads the values of `plans` to the next parameter texture of the ring (case k at texels
    /// 4k..4k+3) and binds it to unit 1.
    unsafe fn upload_params(&mut self, plans: &[&Plan]) {
        let texels = plans.len() as i32 * PARAM_TEXELS;
        let rows = (texels + PARAM_WIDTH - 1) / PARAM_WIDTH;
        let mut data: Vec<f32> = Vec::with_capacity((rows * PARAM_WIDTH * 4) as usize);
        for p in plans {
            data.extend_from_slice(&p.p);
            data.extend_from_slice(&p.dx);
            data.extend_from_slice(&p.dy);
            data.extend_from_slice(&[p.x, 0.0, 0.0, 0.0]);
        }
        data.resize((rows * PARAM_WIDTH * 4) as usize, 0.0);
        let bytes: Vec<u8> = data.iter().flat_map(|f| f.to_ne_bytes()).collect();
        let tex = self.next_param_texture();
        self.gl.active_texture(glow::TEXTURE1);
        self.gl.bind_texture(glow::TEXTURE_2D, Some(tex));
        self.gl.tex_sub_image_2d(
            glow::TEXTURE_2D,
            0,
            0,
            0,
            PARAM_WIDTH,
            rows,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelUnpackData::Slice(Some(&bytes)),
        );
        self.gl.active_texture(glow::TEXTURE0);
    }

    /// Runs a group of cases sharing texture and sampler state.
    pub(super) unsafe fn run_group(
        &mut self,
        cases: &[Case],
        group: Vec<(usize, Vec<Plan>)>,
        st: &mut BatchState,
    ) {
        let first = &cases[group[0].0];
        let Some((tex, so)) = self.bind_group_texture(first, group.iter().map(|(ci, _)| *ci), st)
        else {
            return;
        };
        // Batchable (case, plan) pairs by program, in first-appearance order. A batchable path is
        // always drawn batched, even alone, so the driver compiles one variant per (program,
        // state), not a batched and a single-pixel one.
        let mut batches: Vec<(ShaderKey, Vec<(usize, &Plan)>)> = Vec::new();
        for (ci, plans) in &group {
            for plan in plans {
                if shaders::batchable(&plan.key) {
                    match batches.iter_mut().find(|(k, _)| *k == plan.key) {
                        Some((_, v)) => v.push((*ci, plan)),
                        None => batches.push((plan.key, vec![(*ci, plan)])),
                    }
                } else {
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
        }
        for (key, items) in batches {
            for chunk in items.chunks(PARAM_CASES) {
                let live: Vec<(usize, &Plan)> = chunk
                    .iter()
                    .filter(|(ci, _)| st.answers[*ci].is_none())
                    .copied()
                    .collect();
                if live.is_empty() {
                    continue;
                }
                let slot0 = self.take_slots(st, live.len());
                let plans: Vec<&Plan> = live.iter().map(|(_, p)| *p).collect();
                self.upload_params(&plans);
                match self.draw_batched(&key, slot0, live.len()) {
                    Ok(()) => {
                        for (k, (ci, p)) in live.iter().enumerate() {
                            st.pending.push(Pending {
                                case: *ci,
                                path: p.key.path,
                                slot: slot0 + k,
                                note: format!("{}, batched", p.note),
                            });
                        }
                    }
                    Err(e) => {
                        for (ci, _) in &live {
                            st.fail(*ci, format!("{}: {e}", key.path));
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
