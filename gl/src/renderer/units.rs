//! A batch's texture states as GL objects, and a bundle's states bound together: state i of a
//! bundle on texture unit i (`shadowcheck_plan::units`). Each state's texture and sampler object
//! are made once and live while its bundles draw; a bundle binds them to its units, draws, and
//! unbinds them, so a program never sees a unit left bound by another bundle.

use super::{BatchState, Pending, Renderer};
use crate::{texture, unitstate};
use glow::HasContext;
use shadowcheck_model::Case;
use shadowcheck_plan::shaders;
use shadowcheck_plan::units::{Bundle, ProgramKey};
use shadowcheck_plan::{Job, LodForm, Plan};

/// The GL objects of one texture state: its texture (the sampler state on it, TexParameter)
/// and its sampler object, if the cases bind one.
pub(crate) struct StateObjects {
    pub(crate) tex: glow::Texture,
    pub(crate) so: Option<glow::Sampler>,
}

/// A batch's texture states: groups of (case, plans) sharing one texture.
pub(crate) type Groups = [Vec<(usize, Vec<Plan>)>];

/// The first case of group `g`: the texture and sampler state the group shares.
pub(crate) fn state_case<'j>(jobs: &[Job<'j>], groups: &Groups, g: usize) -> &'j Case {
    jobs[groups[g][0].0].case
}

/// The cases of group `g`.
pub(crate) fn group_cases(groups: &Groups, g: usize) -> impl Iterator<Item = usize> + '_ {
    groups[g].iter().map(|(ci, _)| *ci)
}

impl Renderer {
    /// Makes the texture (left unbound) and sampler object of `first`'s state, shared by the cases
    /// `cis`; on an error those cases fail and `None` is returned.
    pub(crate) unsafe fn create_state(
        &mut self,
        first: &Case,
        cis: impl IntoIterator<Item = usize>,
        st: &mut BatchState,
    ) -> Option<StateObjects> {
        while self.gl.get_error() != glow::NO_ERROR {}
        let made = texture::create(&self.gl, &self.info, first);
        self.gl.bind_texture(first.texture.target.gl(), None);
        let tex = match made {
            Ok(t) => t,
            Err(e) => {
                st.fail_unanswered(cis, &e.to_string());
                return None;
            }
        };
        match unitstate::create_sampler_object(&self.gl, first) {
            Ok(so) => Some(StateObjects { tex, so }),
            Err(e) => {
                self.gl.delete_texture(tex);
                st.fail_unanswered(cis, &e.to_string());
                None
            }
        }
    }

    /// Binds the states of `bundle` to their units (state i on unit i); returns, per state, whether
    /// it is bound. A state without objects (its texture failed) or whose unit state fails (its
    /// cases then fail) leaves its unit empty.
    pub(crate) unsafe fn bind_bundle(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        objects: &[Option<StateObjects>],
        st: &mut BatchState,
    ) -> Vec<bool> {
        let mut bound = Vec::with_capacity(bundle.states.len());
        for (unit, &g) in bundle.states.iter().enumerate() {
            let Some(o) = &objects[g] else {
                bound.push(false);
                continue;
            };
            let case = state_case(jobs, groups, g);
            let unit = unit as u32;
            self.gl.active_texture(glow::TEXTURE0 + unit);
            self.gl.bind_texture(case.texture.target.gl(), Some(o.tex));
            match unitstate::bind_unit_state(&self.gl, case, unit, o.so) {
                Ok(()) => bound.push(true),
                Err(e) => {
                    unitstate::unbind_unit_state(&self.gl, case, unit, o.so);
                    self.gl.bind_texture(case.texture.target.gl(), None);
                    st.fail_unanswered(group_cases(groups, g), &e.to_string());
                    bound.push(false);
                }
            }
        }
        self.gl.active_texture(glow::TEXTURE0);
        bound
    }

    /// Undoes [`Renderer::bind_bundle`] (`bound`: its answer).
    pub(crate) unsafe fn unbind_bundle(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        objects: &[Option<StateObjects>],
        bound: &[bool],
    ) {
        for (unit, &g) in bundle.states.iter().enumerate() {
            let (Some(o), true) = (&objects[g], bound[unit]) else {
                continue;
            };
            let case = state_case(jobs, groups, g);
            unitstate::unbind_unit_state(&self.gl, case, unit as u32, o.so);
            self.gl.active_texture(glow::TEXTURE0 + unit as u32);
            self.gl.bind_texture(case.texture.target.gl(), None);
        }
        self.gl.active_texture(glow::TEXTURE0);
    }

    /// Draws every case of `bundle`'s bound states that uses its program and is not answered yet
    /// into a pixel of its own, on its state's unit (the paths that are not batched).
    pub(crate) unsafe fn draw_singly(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        bound: &[bool],
        st: &mut BatchState,
    ) {
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
    }

    /// After `bundle`'s draws: counted ([`Renderer::count_bundle`]), unbound, and a GL error makes
    /// its cases that use its program and are not answered yet fail.
    pub(crate) unsafe fn finish_bundle(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        bundle: &Bundle,
        objects: &[Option<StateObjects>],
        bound: &[bool],
        st: &mut BatchState,
    ) {
        let program = ProgramKey {
            key: bundle.key,
            units: bundle.units(),
            batched: shaders::batchable(&bundle.key),
        };
        self.count_bundle(
            program,
            bundle.states.iter().map(|&g| state_case(jobs, groups, g)),
        );
        self.unbind_bundle(jobs, groups, bundle, objects, bound);
        let cis: Vec<usize> = bundle
            .states
            .iter()
            .flat_map(|&g| {
                groups[g]
                    .iter()
                    .filter(|(_, plans)| plans.iter().any(|p| p.key == bundle.key))
                    .map(|(ci, _)| *ci)
            })
            .collect();
        self.check_group(cis, st);
    }

    /// Done with group `g`'s objects: its sampler object is deleted, its texture queued for
    /// read-back (`read_back`) or deleted.
    pub(crate) unsafe fn release_state(
        &mut self,
        jobs: &[Job],
        groups: &Groups,
        g: usize,
        objects: StateObjects,
        read_back: bool,
        st: &mut BatchState,
    ) {
        if let Some(so) = objects.so {
            self.gl.delete_sampler(so);
        }
        if read_back {
            let sharing: Vec<usize> = group_cases(groups, g).collect();
            self.retire(jobs, st, objects.tex, groups[g][0].0, sharing);
        } else {
            self.gl.delete_texture(objects.tex);
        }
    }
}
