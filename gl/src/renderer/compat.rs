//! Drawing a batch on a compatibility context: every path (fixed function, ARB fragment
//! programs, GLSL 1.10/1.20, GLSL 1.30) draws one pixel per case, with the case's values as
//! uniforms or program locals. Each API path gets textures of its own: Mesa keeps per-texture
//! sampler views whose DEPTH_TEXTURE_MODE swizzle depends on which path drew before, and one
//! path's answer must not depend on another path. Within a path, the cases of a state share its
//! texture as on a core context, and the path's bundles (`shadowcheck_plan::units`) bind their
//! states together: a GLSL program picks the case's unit by an attribute's current value, an ARB program
//! by the weights of its locals, and fixed function draws one unit alone. A state's texture of
//! the first path it is drawn on is the one read back.

use super::units::{state_case, Groups, StateObjects};
use super::{BatchState, Renderer};
use shadowcheck_model::ApiPath;
use shadowcheck_plan::units::Bundle;
use shadowcheck_plan::Job;

impl Renderer {
    /// Runs `groups` (a batch's texture states) path by path, each path's `bundles` in order.
    pub(crate) unsafe fn run_compat(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundles: &[Bundle],
        st: &mut BatchState,
    ) {
        let mut paths: Vec<ApiPath> = Vec::new();
        for b in bundles {
            if !paths.contains(&b.key.path) {
                paths.push(b.key.path);
            }
        }
        let mut read_back = vec![false; groups.len()];
        for path in paths {
            // Fresh textures for the states with a case still to draw on this path.
            let mut objects: Vec<Option<StateObjects>> = Vec::with_capacity(groups.len());
            for (g, group) in groups.iter().enumerate() {
                let users: Vec<usize> = group
                    .iter()
                    .filter(|(ci, plans)| {
                        st.answers[*ci].is_none() && plans.iter().any(|p| p.key.path == path)
                    })
                    .map(|(ci, _)| *ci)
                    .collect();
                objects.push(if users.is_empty() {
                    None
                } else {
                    self.create_state(state_case(jobs, groups, g), users, st)
                });
            }
            // Each bundle: its states bound together, each case of them that uses the bundle's
            // program drawn into a pixel of its own on its state's unit.
            for b in bundles.iter().filter(|b| b.key.path == path) {
                let bound = self.bind_bundle(jobs, groups, b, &objects, st);
                self.draw_singly(jobs, groups, b, &bound, st);
                self.finish_bundle(jobs, groups, b, &objects, &bound, st);
            }
            for (g, o) in objects.into_iter().enumerate() {
                if let Some(o) = o {
                    let first = !read_back[g];
                    read_back[g] = true;
                    self.release_state(jobs, groups, g, o, first, st);
                }
            }
        }
    }
}
