//! Coverage of a set of cases: counts per spec x target x format x filter x func (compare mode NONE
//! counted as func `none`), the combinations a spec allows that no case covers, the checks per
//! compiled sampler state on each API path, and the Markdown tables printed by `shadowcheck gen` and
//! committed in cases/README.md.

use crate::features::FeatureCounts;
use crate::grids::specs;
use shadowcheck_model::*;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// (spec, target, format, filter, func key)
pub type Key = (Spec, Target, Format, Filter, String);

/// What a driver that compiles one shader variant per sampler state (llvmpipe, lavapipe) bakes
/// into the variant: target, format, compare mode and function, min / mag filters, the three wraps
/// and the depth modes. Texel values, Dref, coordinates, LOD and border colour are not in it.
pub type StateKey = (
    Target,
    Format,
    String,
    Filter,
    Filter,
    [Wrap; 3],
    Option<DepthTextureMode>,
    Option<DepthStencilMode>,
);

/// Per API path: the tests (case x path) it runs, the lookups they check (a sweep case checks
/// its own lookup and each point), and the distinct [`StateKey`]s among them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Density {
    pub tests: usize,
    pub checks: usize,
    pub states: BTreeSet<StateKey>,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Coverage {
    pub counts: BTreeMap<Key, usize>,
    pub total: usize,
    pub per_path: BTreeMap<ApiPath, Density>,
    /// Cases per feature of [`crate::features::FEATURES`] and spec.
    pub features: FeatureCounts,
    /// Shadow gather tests (case x path) per (spec, API path, target, function).
    pub gather: BTreeMap<GatherKey, usize>,
    /// State cases per (API path standing for the context kind, pname): (cases, whether the pname
    /// is read back there, whether it exists only with an extension the context may expose).
    pub state: BTreeMap<(ApiPath, StatePname), (usize, bool, bool)>,
    /// Per API path: tests per unit-state column ([`UNIT_STATE`]).
    pub unit_state: BTreeMap<ApiPath, [usize; UNIT_STATE.len()]>,
    /// The unit-state interaction factors' levels of every test ([`crate::pairs`]).
    pub pairs: crate::pairs::PairCoverage,
}

/// (spec, API path, target, gather function).
pub type GatherKey = (Spec, ApiPath, Target, GatherFn);

/// The three shadow gather functions (GLSL 4.60 §8.9.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum GatherFn {
    Gather,
    Offset,
    Offsets,
}

impl GatherFn {
    pub const ALL: [GatherFn; 3] = [GatherFn::Gather, GatherFn::Offset, GatherFn::Offsets];
    pub fn name(self) -> &'static str {
        match self {
            GatherFn::Gather => "textureGather",
            GatherFn::Offset => "textureGatherOffset",
            GatherFn::Offsets => "textureGatherOffsets",
        }
    }
    fn of(l: &Lookup) -> Option<GatherFn> {
        let g = l.gather.as_ref()?;
        Some(if g.offsets.is_some() {
            GatherFn::Offsets
        } else if l.offset != [0; 3] {
            GatherFn::Offset
        } else {
            GatherFn::Gather
        })
    }
    /// Whether the function exists for `target` on `api` (cube samplers take no offsets; GLSL ES
    /// has no rectangle textures).
    pub fn allowed(self, api: ApiPath, target: Target) -> bool {
        let targets_ok = matches!(
            target,
            Target::T2d | Target::T2dArray | Target::Cube | Target::CubeArray
        ) || (target == Target::Rect && api == ApiPath::GlslCore);
        // WGSL texture built-in functions: textureGatherCompare takes one const offset; no textureGatherOffsets.
        let fn_ok = !(api == ApiPath::Wgsl && self == GatherFn::Offsets);
        targets_ok && fn_ok && (self == GatherFn::Gather || !target.is_cube())
    }
}

/// The (spec, API path) pairs with shadow gather.
const GATHER_PATHS: [(Spec, ApiPath); 4] = [
    (Spec::Gl46, ApiPath::GlslCore),
    (Spec::Gles32, ApiPath::Es300),
    (Spec::Vulkan, ApiPath::Vulkan),
    (Spec::WebGpu, ApiPath::Wgsl),
];

/// One unit-state column: its name, whether a case falls in it, the API paths that have it.
pub type UnitStateColumn = (&'static str, fn(&Case) -> bool, &'static [ApiPath]);

/// The unit-state dimensions (texture swizzle, the seamless cube enable, sampler objects): (column, whether a test falls in it, the API paths on
/// which it exists). Swizzle: GL 3.3 / ES 3.0 shader lookups (a GLSL 1.30 shadow lookup has two
/// readings, oracle `check`); the seamless enable: GL 3.2 cube lookups (ff, glsl130, core); the ES
/// rule: filtered cube lookups of ES 3.x, always seamless; sampler objects: GL 3.3 / ES 3.0.
pub const UNIT_STATE: [UnitStateColumn; 6] = {
    use ApiPath::*;
    [
        (
            "swizzle, shadow",
            |c| {
                c.sampler.swizzle.is_some()
                    && c.sampler.in_effect().compare_mode != CompareMode::None
            },
            &[GlslCore, Es300],
        ),
        (
            "swizzle, depth read",
            |c| {
                c.sampler.swizzle.is_some()
                    && c.sampler.in_effect().compare_mode == CompareMode::None
            },
            &[Glsl130, GlslCore, Es300],
        ),
        (
            "seamless off",
            |c| c.sampler.seamless == Some(false),
            &[FixedFunction, Glsl130, GlslCore],
        ),
        (
            "seamless on",
            |c| c.sampler.seamless == Some(true),
            &[FixedFunction, Glsl130, GlslCore],
        ),
        (
            "ES always seamless (filtered cube)",
            |c| {
                c.spec == Spec::Gles32
                    && c.texture.target.is_cube()
                    && c.sampler.in_effect().mag_filter == Filter::Linear
            },
            &[Es300],
        ),
        (
            "sampler object",
            |c| c.sampler.sampler_object.is_some(),
            &[FixedFunction, Glsl120, Glsl130, GlslCore, Es300],
        ),
    ]
};

/// The [`StateKey`] of `case`: the sampling state in effect (a bound sampler object's, GL 4.6
/// §8.17.1) with the texture's target, format and depth modes. Scheduling (`shadowcheck run`
/// orders compile-heavy backends by it) and the density table both count compiled states with it.
pub fn state_key(c: &Case) -> StateKey {
    let s = c.sampler.in_effect();
    (
        c.texture.target,
        c.texture.format,
        func_key(&s),
        s.min_filter,
        s.mag_filter,
        [s.wrap_s, s.wrap_t, s.wrap_r],
        s.depth_texture_mode,
        s.depth_stencil_mode,
    )
}

fn func_key(s: &Sampler) -> String {
    match s.compare_mode {
        CompareMode::None => "none".into(),
        CompareMode::Compare => s.compare_func.key().into(),
    }
}

impl Coverage {
    pub fn of<'a>(cases: impl IntoIterator<Item = &'a Case>) -> Coverage {
        let mut cov = Coverage::default();
        for c in cases {
            let key = (
                c.spec,
                c.texture.target,
                c.texture.format,
                c.sampler.min_filter,
                func_key(&c.sampler),
            );
            *cov.counts.entry(key).or_default() += 1;
            cov.total += 1;
            cov.features.add(c);
            cov.pairs.add(c);
            for &api in &c.api {
                let d = cov.per_path.entry(api).or_default();
                d.tests += 1;
                d.checks += c.lookup_count();
                d.states.insert(state_key(c));
                if let Some(f) = GatherFn::of(&c.lookup) {
                    *cov.gather
                        .entry((c.spec, api, c.texture.target, f))
                        .or_default() += 1;
                }
                let u = cov.unit_state.entry(api).or_default();
                for (i, (_, used, _)) in UNIT_STATE.iter().enumerate() {
                    u[i] += used(c) as usize;
                }
            }
        }
        cov
    }

    /// Func columns of a spec: its functions, then `none`.
    fn funcs(spec: Spec) -> Vec<String> {
        let mut v: Vec<String> = specs::dims(spec)
            .funcs
            .iter()
            .map(|f| f.key().to_string())
            .collect();
        if specs::compare_none(spec) {
            v.push("none".into());
        }
        v
    }

    /// Every combination a spec allows (see [`specs::dims`]) with no case.
    pub fn missing(&self) -> Vec<Key> {
        let mut out = Vec::new();
        for d in specs::all() {
            for &t in d.targets {
                for &fo in d.formats {
                    for &fi in d.filters.iter().filter(|fi| specs::filter_allowed(t, **fi)) {
                        for func in Self::funcs(d.spec) {
                            let k = (d.spec, t, fo, fi, func);
                            if !self.counts.contains_key(&k) {
                                out.push(k);
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// Every (spec, path, target, gather function) the specs allow with no test.
    pub fn missing_gather(&self) -> Vec<GatherKey> {
        let mut out = Vec::new();
        for (spec, api) in GATHER_PATHS {
            for &t in specs::dims(spec).targets {
                for f in GatherFn::ALL.into_iter().filter(|f| f.allowed(api, t)) {
                    if !self.gather.contains_key(&(spec, api, t, f)) {
                        out.push((spec, api, t, f));
                    }
                }
            }
        }
        out
    }

    /// The shadow gather table: tests per spec / API path / target and function (`-` where the
    /// function does not exist for the target).
    pub fn gather_markdown(&self) -> String {
        let mut s = String::from("#### Shadow textureGather (tests per API path)\n\n");
        let names: Vec<&str> = GatherFn::ALL.iter().map(|f| f.name()).collect();
        let _ = writeln!(s, "| spec | API path | target | {} |", names.join(" | "));
        let _ = writeln!(s, "|---|---|---|{}", "---:|".repeat(names.len()));
        for (spec, api) in GATHER_PATHS {
            for &t in specs::dims(spec).targets {
                if !GatherFn::Gather.allowed(api, t) {
                    continue;
                }
                let cells: Vec<String> = GatherFn::ALL
                    .iter()
                    .map(|f| {
                        if f.allowed(api, t) {
                            self.gather
                                .get(&(spec, api, t, *f))
                                .copied()
                                .unwrap_or(0)
                                .to_string()
                        } else {
                            "-".into()
                        }
                    })
                    .collect();
                let _ = writeln!(s, "| {spec} | {api} | {t} | {} |", cells.join(" | "));
            }
        }
        s.push('\n');
        s
    }

    fn count(&self, k: &Key) -> usize {
        self.counts.get(k).copied().unwrap_or(0)
    }

    /// The same coverage with the TexParameter state cases `states` counted too.
    pub fn with_states<'a>(mut self, states: impl IntoIterator<Item = &'a StateCase>) -> Coverage {
        for c in states {
            for &api in &c.api {
                // A pname only an extension the context may expose adds (filled or not).
                use shadowcheck_oracle::state as ostate;
                let ext =
                    !ostate::pname_extensions(c.spec, ostate::ctx_of(api), c.pname.gl()).is_empty();
                let e = self
                    .state
                    .entry((api, c.pname))
                    .or_insert((0, c.read_back, ext));
                e.0 += 1;
                e.1 |= c.read_back;
                e.2 |= ext;
            }
        }
        self
    }

    /// The state cases per pname and context kind (`n`: cases; `n (absent)`: the pname does not
    /// exist there, so the cases check INVALID_ENUM; `n (extension)`: it exists only where the
    /// context exposes an extension that adds it, INVALID_ENUM otherwise).
    pub fn state_markdown(&self) -> String {
        let mut s = String::from("#### TexParameter / GetTexParameter state cases\n\n");
        let apis: Vec<ApiPath> = {
            let mut v: Vec<ApiPath> = self.state.keys().map(|k| k.0).collect();
            v.dedup();
            v.sort();
            v.dedup();
            v
        };
        let total: usize = self.state.values().map(|v| v.0).sum();
        let _ = writeln!(
            s,
            "Tests per pname and context kind (by its API path: `core` core profile, `ff` compatibility, `es300` ES 3); `absent`: the pname does not exist there (INVALID_ENUM); `extension`: it exists only with an extension the context may expose (INVALID_ENUM without it). {total} tests.\n"
        );
        let names: Vec<&str> = apis.iter().map(|a| a.key()).collect();
        let _ = writeln!(s, "| pname | {} |", names.join(" | "));
        let _ = writeln!(s, "|---|{}", "---:|".repeat(apis.len()));
        for &p in StatePname::ALL {
            let cells: Vec<String> = apis
                .iter()
                .map(|a| match self.state.get(&(*a, p)) {
                    Some((n, _, true)) => format!("{n} (extension)"),
                    Some((n, true, false)) => n.to_string(),
                    Some((n, false, false)) => format!("{n} (absent)"),
                    None => "0".into(),
                })
                .collect();
            let _ = writeln!(s, "| {} | {} |", p.name(), cells.join(" | "));
        }
        s
    }

    /// One Markdown table per spec: a row per target / format / filter, a column per func; cells
    /// count cases (`-` where the spec does not allow the combination).
    pub fn markdown(&self) -> String {
        let mut s = String::new();
        for d in specs::all() {
            let spec_total: usize = self
                .counts
                .iter()
                .filter(|(k, _)| k.0 == d.spec)
                .map(|(_, n)| n)
                .sum();
            let funcs = Self::funcs(d.spec);
            let _ = writeln!(s, "#### {} ({} cases)\n", d.spec, spec_total);
            let _ = writeln!(
                s,
                "| target | format | filter | {} | total |",
                funcs.join(" | ")
            );
            let _ = writeln!(s, "|---|---|---|{}---:|", "---:|".repeat(funcs.len()));
            for &t in d.targets {
                for &fo in d.formats {
                    for &fi in d.filters {
                        let allowed = specs::filter_allowed(t, fi);
                        let cells: Vec<String> = funcs
                            .iter()
                            .map(|f| {
                                if allowed {
                                    self.count(&(d.spec, t, fo, fi, f.clone())).to_string()
                                } else {
                                    "-".into()
                                }
                            })
                            .collect();
                        if !allowed {
                            continue;
                        }
                        let row_total: usize = funcs
                            .iter()
                            .map(|f| self.count(&(d.spec, t, fo, fi, f.clone())))
                            .sum();
                        let _ = writeln!(
                            s,
                            "| {t} | {fo} | {fi} | {} | {row_total} |",
                            cells.join(" | ")
                        );
                    }
                }
            }
            s.push('\n');
        }
        let _ = writeln!(s, "Total: {} cases.\n", self.total);
        s.push_str(&self.features.markdown());
        s.push_str(&self.gather_markdown());
        s.push_str(&self.density_markdown());
        if !self.state.is_empty() {
            s.push('\n');
            s.push_str(&self.state_markdown());
        }
        s.push('\n');
        s.push_str(&self.unit_state_markdown());
        s.push('\n');
        s.push_str(&self.pairs.markdown());
        s
    }

    /// Tests per API path in each unit-state dimension ([`UNIT_STATE`]); `-` where the path has
    /// no such state.
    pub fn unit_state_markdown(&self) -> String {
        let mut s = String::from("#### Unit state: tests per API path\n\n");
        let names: Vec<&str> = UNIT_STATE.iter().map(|u| u.0).collect();
        let _ = writeln!(s, "| API path | {} |", names.join(" | "));
        let _ = writeln!(s, "|---|{}", "---:|".repeat(names.len()));
        for api in ApiPath::ALL {
            let counts = self.unit_state.get(api).copied().unwrap_or_default();
            let cells: Vec<String> = UNIT_STATE
                .iter()
                .zip(counts)
                .map(|((_, _, paths), n)| {
                    if paths.contains(api) {
                        n.to_string()
                    } else {
                        "-".into()
                    }
                })
                .collect();
            let _ = writeln!(s, "| {api} | {} |", cells.join(" | "));
        }
        s
    }

    /// Unit-state cells a path allows with no test.
    pub fn unit_state_missing(&self) -> Vec<(ApiPath, &'static str)> {
        let mut out = Vec::new();
        for api in ApiPath::ALL {
            let counts = self.unit_state.get(api).copied().unwrap_or_default();
            for ((name, _, paths), n) in UNIT_STATE.iter().zip(counts) {
                if paths.contains(api) && n == 0 {
                    out.push((*api, *name));
                }
            }
        }
        out
    }

    /// Checks per compiled sampler state on each API path: tests, the lookups they check,
    /// distinct [`StateKey`]s, and checks per state (what a driver compiling one variant per state
    /// gets for each compilation).
    pub fn density_markdown(&self) -> String {
        let mut s = String::from("#### Checks per compiled sampler state\n\n");
        s.push_str("State = target, format, compare mode/func, min/mag filters, wraps, depth modes of the sampling state in effect (what llvmpipe and lavapipe bake into a shader variant). A check is one lookup judged: a test checks its case's lookup and each point of the case's sweep (`sweep`, above). Goal: at least 16 checks per state on every path (`shadowcheck bench` reports this table as `checks_per_compiled_state`).\n\n");
        s.push_str(
            "| API path | tests | checks | distinct states | checks per state |\n|---|---:|---:|---:|---:|\n",
        );
        for (api, d) in &self.per_path {
            let per = d.checks as f64 / d.states.len().max(1) as f64;
            let _ = writeln!(
                s,
                "| {api} | {} | {} | {} | {per:.1} |",
                d.tests,
                d.checks,
                d.states.len()
            );
        }
        s
    }

    /// A compact per-spec summary (spec, cases, cells covered / allowed).
    pub fn summary(&self) -> String {
        let missing = self.missing();
        let mut s = String::from("spec          cases   cells covered/allowed\n");
        for d in specs::all() {
            let n: usize = self
                .counts
                .iter()
                .filter(|(k, _)| k.0 == d.spec)
                .map(|(_, n)| n)
                .sum();
            let covered = self.counts.keys().filter(|k| k.0 == d.spec).count();
            let miss = missing.iter().filter(|k| k.0 == d.spec).count();
            let _ = writeln!(
                s,
                "{:<12} {:>6}   {}/{}",
                d.spec.key(),
                n,
                covered,
                covered + miss
            );
        }
        let _ = writeln!(s, "total        {:>6}", self.total);
        s
    }
}

/// Marker lines around the generated coverage section of cases/README.md.
pub const BEGIN: &str = "<!-- coverage:begin (generated by `shadowcheck gen --grid default --update-readme cases/README.md`) -->";
pub const END: &str = "<!-- coverage:end -->";

/// The text between the coverage markers of `readme`, if both are there.
pub fn section(readme: &str) -> Option<&str> {
    crate::markers::section(readme, BEGIN, END)
}

/// `readme` with the text between the coverage markers replaced by `table`.
pub fn replace_section(readme: &str, table: &str) -> Option<String> {
    crate::markers::replace(readme, BEGIN, END, table)
}
