//! Drawing a batch on a compatibility context: every path (fixed function, ARB fragment
//! programs, GLSL 1.10/1.20, GLSL 1.30) draws one pixel per case, with the case's values as
//! uniforms or program locals. Each API path gets textures of its own: Mesa keeps per-texture
//! sampler views whose DEPTH_TEXTURE_MODE swizzle depends on which path drew before, and one
//! path's answer must not depend on another path. Within a path, the cases of a state share its
//! texture as on a core context, and the path's bundles (`shadowcheck_plan::units`) bind their
//! states together: a GLSL program picks the case's unit by the uniform `u_unit`, an ARB program
//! by the weights of its locals, and fixed function draws one unit alone. A state's texture of
//! the first path it is drawn on is the one read back.

use super::units::{state_case, Groups, StateObjects};
use super::{BatchState, Pending, Renderer};
use shadowcheck_model::ApiPath;
use shadowcheck_plan::units::{Bundle, ProgramKey};
use shadowcheck_plan::{Job, LodForm};

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
            for b in bundles.iter().filter(|b| b.key.path == path) {
                self.run_compat_bundle(jobs, groups, b, &objects, st);
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

    /// One bundle: its states bound together, each case of them that uses the bundle's program
    /// drawn into a pixel of its own on its state's unit.
    unsafe fn run_compat_bundle(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        objects: &[Option<StateObjects>],
        st: &mut BatchState,
    ) {
        let bound = self.bind_bundle(jobs, groups, bundle, objects, st);
        let units = bundle.units();
        for (unit, &g) in bundle.states.iter().enumerate() {
            if !bound[unit] {
                continue;
            }
            let target = state_case(jobs, groups, g).texture.target;
            for (ci, plans) in &groups[g] {
                if st.answers[*ci].is_some() {
                    continue;
                }
                for plan in plans.iter().filter(|p| p.key == bundle.key) {
                    let slot = self.take_slots(st, 1);
                    match self.draw(plan, target, slot, (unit, units)) {
                        Ok(()) => st.pending.push(Pending {
                            case: *ci,
                            path: plan.key.path,
                            slot,
                            note: if plan.key.form == LodForm::Constant {
                                "fixed-function".to_string()
                            } else {
                                plan.note.clone()
                            },
                        }),
                        Err(e) => st.fail(*ci, format!("{}: {e}", plan.key.path)),
                    }
                }
            }
        }
        let program = ProgramKey {
            key: bundle.key,
            units,
            batched: false,
        };
        self.count_bundle(
            program,
            bundle.states.iter().map(|&g| state_case(jobs, groups, g)),
        );
        self.unbind_bundle(jobs, groups, bundle, objects, &bound);
        let cis = bundle.states.iter().flat_map(|&g| {
            groups[g]
                .iter()
                .filter(|(_, plans)| plans.iter().any(|p| p.key == bundle.key))
                .map(|(ci, _)| *ci)
        });
        let cis: Vec<usize> = cis.collect();
        self.check_group(cis, st);
    }
}
