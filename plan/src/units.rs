//! Many sampler states per compiled program.
//!
//! llvmpipe, lavapipe (so zink) and SwiftShader compile one fragment variant per program *and* the
//! sampler state of every texture unit the program reads: a lookup key drawn over N texture states
//! one at a time costs N compilations. A program that declares K samplers of one type on units
//! 0..K-1 and picks the unit per case (a flat input of each case's quad on batched draws, a
//! uniform on single-case draws) is compiled once for all K states bound together, and a variant
//! of K states costs far less than K variants of one (reports/BENCH.md).
//!
//! The texture states of a worker batch (consecutive cases with equal texture and sampler state,
//! one texture object each) are dealt into [`bundles`], one per program: the states whose cases
//! use that program's lookup ([`ShaderKey`]), up to K of them, state i of a bundle on unit i. A
//! variant samples every unit of its program, so a bundle holds only states that the program's
//! lookup is drawn on (a state whose cases use several lookups is in one bundle per lookup, on
//! a unit of each). Everything here is deterministic from the batch: the same cases give the same
//! bundles with the same units, so a re-run, and Mesa's on-disk shader cache, see the same
//! programs over the same states in the same order (a driver compiles a new variant when the same
//! states are bound to the units in another order).
//!
//! What one bundle may mix: its program fixes the sampler type (target and family, GLSL 4.60
//! §4.1.7) and DEPTH_TEXTURE_MODE ([`ShaderKey::mode`]); TEXTURE_CUBE_MAP_SEAMLESS is context
//! state (GL 4.6 §8.13.1), not unit state, so it splits bundles. Sampler objects are per unit
//! (§8.2), so they mix freely.
//!
//! Fixed function draws one unit at a time ([`states_per_program`]): a texture environment that
//! shows one of several enabled units' result in a quad would need a per-quad selection that
//! the GL 1.3 combiners make only through arithmetic on the results (INTERPOLATE by a constant
//! colour), which does not return a unit's value bit for bit.

use crate::{paths, shaders, GlInfo, Job, Plan, ShaderKey};
use shadowcheck_model::{ApiPath, Case};
use shadowcheck_protocol::PathSkip;

/// Sampler states a program samples at most, where the context allows as many texture units: the
/// gain levels off near 16 on llvmpipe (about 8 ms of a variant is fixed cost and 4 ms each
/// state's sampling code: reports/BENCH.md), and WebGL 2.0 guarantees 16 fragment texture units.
pub const DEFAULT_STATES_PER_PROGRAM: usize = 16;

/// What a bundle needs to know of one texture state: the context state it sets
/// (TEXTURE_CUBE_MAP_SEAMLESS enabled) and the lookups its cases use, in first-use order.
#[derive(Debug, Clone, PartialEq)]
pub struct StateUse {
    pub seamless: bool,
    pub keys: Vec<ShaderKey>,
}

impl StateUse {
    /// The use of `case`'s texture state by lookups of `keys` (repeats dropped).
    pub fn new(case: &Case, keys: impl IntoIterator<Item = ShaderKey>) -> StateUse {
        let mut u = StateUse {
            seamless: case.sampler.seamless == Some(true),
            keys: Vec::new(),
        };
        for k in keys {
            if !u.keys.contains(&k) {
                u.keys.push(k);
            }
        }
        u
    }
}

/// One program drawn over texture states bound together: `states[i]` (an index into the batch's
/// states) on texture unit i; the program declares as many samplers as the bundle has states (a
/// sampler without a texture would still cost its sampling code in every variant: on llvmpipe a
/// cold gl46 run took 22 s with every program declaring 16 samplers against 18 s with exactly
/// the bundle's).
#[derive(Debug, Clone, PartialEq)]
pub struct Bundle {
    pub key: ShaderKey,
    pub states: Vec<usize>,
}

impl Bundle {
    /// The samplers of the bundle's program.
    pub fn units(&self) -> usize {
        self.states.len()
    }
}

/// Sampler states one program of `path` samples: `k` (the context's units, at most
/// [`DEFAULT_STATES_PER_PROGRAM`] unless asked otherwise), 1 for fixed function (module docs).
pub fn states_per_program(path: ApiPath, k: usize) -> usize {
    if path == ApiPath::FixedFunction {
        1
    } else {
        k.max(1)
    }
}

/// The batch's texture states `uses` dealt into bundles of at most `k` states
/// ([`states_per_program`]): each (state, lookup) joins the open bundle of its lookup and
/// seamless enable, and a bundle closes when full. Bundles are listed in the order they were
/// opened; a bundle's states keep their batch order, which is their unit order.
pub fn bundles(uses: &[StateUse], k: usize) -> Vec<Bundle> {
    let mut open: Vec<((ShaderKey, bool), usize)> = Vec::new();
    let mut out: Vec<Bundle> = Vec::new();
    for (i, state) in uses.iter().enumerate() {
        for &key in &state.keys {
            let class = (key, state.seamless);
            let b = match open.iter().position(|(c, _)| *c == class) {
                Some(j) => open[j].1,
                None => {
                    out.push(Bundle {
                        key,
                        states: Vec::new(),
                    });
                    open.push((class, out.len() - 1));
                    out.len() - 1
                }
            };
            out[b].states.push(i);
            if out[b].states.len() >= states_per_program(key.path, k) {
                open.retain(|(c, _)| *c != class);
            }
        }
    }
    out
}

/// The order to send `cases` (each with the API paths it runs on a backend) in, so that the cases
/// drawn with one program arrive in the same batches and their states fill bundles: cases by
/// their programs ([`paths::plan`] of each path, the seamless enable), each set of programs in
/// the order it first appears, cases of one set in their given order (so a case's grid
/// neighbours of the same state stay together). A permutation of the indices; deterministic.
/// The keys are the plan's on a context with every feature (the worker may plan another form
/// where its context lacks one): an order, not a promise.
pub fn program_order<'c>(cases: impl IntoIterator<Item = (&'c Case, &'c [ApiPath])>) -> Vec<usize> {
    let mut signatures: Vec<(Vec<ShaderKey>, bool)> = Vec::new();
    let mut ranked: Vec<(usize, usize)> = Vec::new();
    for (i, (case, apis)) in cases.into_iter().enumerate() {
        let keys: Vec<ShaderKey> = apis
            .iter()
            .filter_map(|&path| paths::plan(path, case).ok().map(|p| p.key))
            .collect();
        let sig = (keys, case.sampler.seamless == Some(true));
        let rank = match signatures.iter().position(|s| *s == sig) {
            Some(r) => r,
            None => {
                signatures.push(sig);
                signatures.len() - 1
            }
        };
        ranked.push((rank, i));
    }
    ranked.sort_unstable();
    ranked.into_iter().map(|(_, i)| i).collect()
}

/// A fingerprint of what a driver compiles of `case`'s texture state into a shader variant: the
/// state that decides which sampling code runs (target, format, whether the texture has mipmaps
/// and power-of-two level 0 sides, the sampler state in effect: compare mode and function,
/// filters, wraps, the depth modes, swizzle, seamless, and whether there is a border colour, a
/// LOD bias, a fail value), not the values that code reads (texels, sizes, LOD limits, the border
/// colour). Equal sampling states give equal fingerprints; two states with equal fingerprints
/// are what llvmpipe's variant keys come close to treating alike. Counts only (the GL worker's
/// stats): nothing is drawn by it.
pub fn sampling_fingerprint(case: &Case) -> u64 {
    use std::hash::{Hash, Hasher};
    let t = &case.texture;
    let s = case.sampler.in_effect();
    let pot = t
        .levels
        .first()
        .map(|l| (l.width.is_power_of_two(), l.height.is_power_of_two()));
    let mut h = std::collections::hash_map::DefaultHasher::new();
    format!(
        "{:?}{:?}{}{:?}|{:?}{:?}{:?}{:?}{:?}{:?}{:?}|{:?}{:?}{:?}{:?}|{}{}{}",
        t.target,
        t.format,
        t.levels.len() > 1,
        pot,
        s.compare_mode,
        s.compare_func,
        s.min_filter,
        s.mag_filter,
        s.wrap_s,
        s.wrap_t,
        s.wrap_r,
        s.depth_texture_mode,
        s.depth_stencil_mode,
        s.swizzle,
        s.seamless,
        s.border != [0.0; 4],
        s.lod_bias != 0.0,
        s.fail_value.is_some(),
    )
    .hash(&mut h);
    h.finish()
}

/// A worker batch planned for a context: each job's plans on its API paths (or why none runs),
/// its texture states and their bundles. The GL worker draws exactly this.
#[derive(Debug)]
pub struct BatchPlan {
    /// Per job: the API paths this context cannot run, with the reason (a job none of whose paths
    /// runs is in `unplanned` instead).
    pub skipped: Vec<Vec<PathSkip>>,
    /// Jobs with no path to run: (job, the reasons joined).
    pub unplanned: Vec<(usize, String)>,
    /// The texture states: consecutive jobs with equal texture and sampler state, each job with
    /// its plans.
    pub groups: Vec<Vec<(usize, Vec<Plan>)>>,
    /// The states dealt into bundles ([`bundles`]).
    pub bundles: Vec<Bundle>,
}

/// Plans `jobs` on the context `info`, at most `k` sampler states per program.
pub fn plan_batch(info: &GlInfo, jobs: &[Job], k: usize) -> BatchPlan {
    let mut skipped = vec![Vec::new(); jobs.len()];
    let mut unplanned = Vec::new();
    let mut groups: Vec<Vec<(usize, Vec<Plan>)>> = Vec::new();
    for (ci, job) in jobs.iter().enumerate() {
        let mut plans = Vec::new();
        let mut skips = Vec::new();
        for &path in &job.case.api {
            match paths::plan_for(info, path, job.case, &job.lookup) {
                Ok(p) => plans.push(p),
                Err(reason) => skips.push(PathSkip {
                    api: path.key().to_string(),
                    reason,
                }),
            }
        }
        if plans.is_empty() {
            let why: Vec<String> = skips.into_iter().map(|s| s.reason).collect();
            unplanned.push((ci, why.join("; ")));
            continue;
        }
        skipped[ci] = skips;
        match groups.last_mut() {
            Some(group) if jobs[group[0].0].same_texture(job) => group.push((ci, plans)),
            _ => groups.push(vec![(ci, plans)]),
        }
    }
    let uses: Vec<StateUse> = groups
        .iter()
        .map(|g| {
            let keys = g.iter().flat_map(|(_, plans)| plans.iter().map(|p| p.key));
            StateUse::new(jobs[g[0].0].case, keys)
        })
        .collect();
    let bundles = bundles(&uses, k);
    BatchPlan {
        skipped,
        unplanned,
        groups,
        bundles,
    }
}

impl BatchPlan {
    /// The programs the batch draws with: one per bundle's lookup and size, batched where the
    /// lookup can be ([`shaders::batchable`]); fixed function compiles none.
    pub fn programs(&self) -> Vec<ProgramKey> {
        let mut out: Vec<ProgramKey> = Vec::new();
        for b in &self.bundles {
            if b.key.path == ApiPath::FixedFunction {
                continue;
            }
            let pk = ProgramKey {
                key: b.key,
                units: b.units(),
                batched: shaders::batchable(&b.key),
            };
            if !out.contains(&pk) {
                out.push(pk);
            }
        }
        out
    }
}

/// A program: the lookup of `key` on `units` samplers (unit `i` named `u_tex{i}`; one unit: the
/// plain `u_tex`), and whether it draws many cases at once (batched).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ProgramKey {
    pub key: ShaderKey,
    pub units: usize,
    pub batched: bool,
}

/// The name of the sampler of `unit` in a program of `units` samplers.
pub fn sampler_name(unit: usize, units: usize) -> String {
    if units <= 1 {
        "u_tex".to_string()
    } else {
        format!("u_tex{unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{LodForm, SamplerKind};
    use shadowcheck_model::Target;

    fn key(path: ApiPath, target: Target, form: LodForm) -> ShaderKey {
        ShaderKey {
            path,
            target,
            kind: SamplerKind::Shadow,
            form,
            proj: false,
            mode: None,
            offset: [0, 0],
            gather: None,
            delivery: shadowcheck_model::Delivery::Literal,
            stage: shadowcheck_model::Stage::Fragment,
        }
    }

    fn state(seamless: bool, keys: &[ShaderKey]) -> StateUse {
        StateUse {
            seamless,
            keys: keys.to_vec(),
        }
    }

    #[test]
    fn states_of_one_lookup_share_bundles_of_k_in_batch_order() {
        let lod = key(ApiPath::GlslCore, Target::T2d, LodForm::Lod);
        let grad = key(ApiPath::GlslCore, Target::T2d, LodForm::Grad);
        let cube = key(ApiPath::GlslCore, Target::Cube, LodForm::Lod);
        let uses = [
            state(false, &[lod]),
            state(false, &[cube]),
            state(false, &[lod, grad]),
            state(false, &[lod]),
            state(true, &[cube]),
            state(false, &[cube]),
            state(false, &[grad, lod]),
            state(false, &[lod]),
        ];
        let b = |key, states: &[usize]| Bundle {
            key,
            states: states.to_vec(),
        };
        assert_eq!(
            bundles(&uses, 3),
            vec![
                b(lod, &[0, 2, 3]),
                b(cube, &[1, 5]),
                b(grad, &[2, 6]),
                b(cube, &[4]),
                b(lod, &[6, 7]),
            ]
        );
        // Every (state, lookup) is in exactly one bundle, whatever k.
        for k in [1, 2, 16] {
            let mut seen: Vec<(usize, ShaderKey)> = bundles(&uses, k)
                .iter()
                .flat_map(|b| b.states.iter().map(|&s| (s, b.key)).collect::<Vec<_>>())
                .collect();
            seen.sort_by_key(|(s, k)| (*s, format!("{k:?}")));
            let mut want: Vec<(usize, ShaderKey)> = uses
                .iter()
                .enumerate()
                .flat_map(|(i, u)| u.keys.iter().map(move |k| (i, *k)))
                .collect();
            want.sort_by_key(|(s, k)| (*s, format!("{k:?}")));
            assert_eq!(seen, want, "k = {k}");
            assert!(bundles(&uses, k).iter().all(|b| b.states.len() <= k));
        }
        // One state per program: a bundle per (state, lookup).
        assert_eq!(bundles(&uses, 1).len(), 10);
        assert_eq!(bundles(&uses, 0), bundles(&uses, 1));
    }

    #[test]
    fn cases_are_sent_by_program_and_otherwise_in_their_order() {
        let base = crate::test_case::case(Target::T2d, 2, 2, 1);
        let mut biased = base.clone();
        biased.lookup.bias = 1.0;
        let mut cube = crate::test_case::case(Target::Cube, 2, 2, 6);
        cube.lookup.coord = [1.0, 0.5, 0.5, 1.0];
        let cases = [&base, &cube, &biased, &base, &cube, &base];
        let order = program_order(cases.iter().map(|c| (*c, c.api.as_slice())));
        // textureLod on 2D first (cases 0, 3, 5), then the cube (1, 4), then the biased lookup.
        assert_eq!(order, vec![0, 3, 5, 1, 4, 2]);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..cases.len()).collect::<Vec<_>>());
    }

    #[test]
    fn the_sampling_fingerprint_ignores_what_the_sampling_code_reads() {
        let a = crate::test_case::case(Target::T2d, 2, 2, 1);
        let mut b = a.clone();
        b.id = "another".into();
        b.texture.levels[0].depth = shadowcheck_model::Texels::Unorm(vec![7; 4]);
        b.sampler.max_lod = 3.0;
        assert_eq!(sampling_fingerprint(&a), sampling_fingerprint(&b));
        let mut c = a.clone();
        c.sampler.compare_func = shadowcheck_model::CompareFunc::Greater;
        assert_ne!(sampling_fingerprint(&a), sampling_fingerprint(&c));
        let mut d = crate::test_case::case(Target::T2d, 3, 2, 1);
        assert_ne!(sampling_fingerprint(&a), sampling_fingerprint(&d));
        d = crate::test_case::case(Target::T2d, 4, 2, 1);
        assert_eq!(sampling_fingerprint(&a), sampling_fingerprint(&d));
    }

    #[test]
    fn fixed_function_samples_one_state_per_draw() {
        let ff = key(ApiPath::FixedFunction, Target::T2d, LodForm::Constant);
        let uses = [state(false, &[ff]), state(false, &[ff])];
        assert_eq!(bundles(&uses, 16).len(), 2);
        assert_eq!(states_per_program(ApiPath::FixedFunction, 16), 1);
        assert_eq!(states_per_program(ApiPath::ArbFp, 16), 16);
        assert_eq!(states_per_program(ApiPath::GlslCore, 0), 1);
        assert_eq!(sampler_name(3, 16), "u_tex3");
        assert_eq!(sampler_name(0, 1), "u_tex");
    }
}
