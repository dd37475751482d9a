//! Pairwise coverage of the unit-state feature interactions: the seven factors (gather function,
//! texture swizzle, bound sampler object, seamless cube enable, DEPTH_TEXTURE_MODE, target, API
//! path), the level of each factor a test (case x API path) sits at, which level pairs each spec
//! allows (from the `interact` grid's candidates, [`crate::grids::interact`]) and which a set of
//! cases covers, and the Markdown table committed in cases/README.md.

use crate::grids::{interact, specs};
use shadowcheck_model::*;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// The factors, in the order of a [`Row`].
pub const FACTORS: [&str; 7] = [
    "gather",
    "swizzle",
    "sampler object",
    "seamless",
    "DEPTH_TEXTURE_MODE",
    "target",
    "API path",
];

/// The level of each factor (in [`FACTORS`] order) of one test.
pub type Row = [String; 7];

/// Two factor levels: (factor index, level, factor index, level), the first factor before the second.
pub type Pair = (usize, String, usize, String);

/// The gather level of a lookup: `none` (a filtered lookup), `gather`, `offset`
/// (textureGatherOffset) or `offsets` (textureGatherOffsets).
pub fn gather_level(l: &Lookup) -> &'static str {
    match &l.gather {
        None => "none",
        Some(g) if g.offsets.is_some() => "offsets",
        Some(_) if l.offset != [0; 3] => "offset",
        Some(_) => "gather",
    }
}

/// A swizzle as four letters (`r`, `g`, `b`, `a`, `0`, `1`), e.g. `gbar`.
pub fn swizzle_letters(sw: [Swizzle; 4]) -> String {
    sw.iter()
        .map(|c| match c {
            Swizzle::Red => 'r',
            Swizzle::Green => 'g',
            Swizzle::Blue => 'b',
            Swizzle::Alpha => 'a',
            Swizzle::Zero => '0',
            Swizzle::One => '1',
        })
        .collect()
}

/// The levels of a test: `case` drawn on `api`.
pub fn row(case: &Case, api: ApiPath) -> Row {
    let s = &case.sampler;
    [
        gather_level(&case.lookup).to_string(),
        s.swizzle.map_or("none".into(), swizzle_letters),
        if s.sampler_object.is_some() {
            "bound"
        } else {
            "none"
        }
        .to_string(),
        match s.seamless {
            None => "unset",
            Some(true) => "on",
            Some(false) => "off",
        }
        .to_string(),
        s.depth_texture_mode
            .map_or("unset", |m| m.key())
            .to_string(),
        case.texture.target.key().to_string(),
        api.key().to_string(),
    ]
}

/// Every pair of levels in `row`.
pub fn pairs(row: &Row) -> impl Iterator<Item = Pair> + '_ {
    (0..row.len())
        .flat_map(move |i| (i + 1..row.len()).map(move |j| (i, row[i].clone(), j, row[j].clone())))
}

/// The level pairs a spec allows: those of every test of every candidate of its `interact` grid
/// (empty for a spec without unit-state factors).
pub fn allowed(spec: Spec) -> BTreeSet<Pair> {
    interact::allowed_rows(&specs::dims(spec))
        .iter()
        .flat_map(|r| pairs(r).collect::<Vec<_>>())
        .collect()
}

/// The rows (tests) of a set of cases, per spec: all cases, and those of the `interact` family.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PairCoverage {
    pub all: BTreeMap<Spec, BTreeSet<Row>>,
    pub interact: BTreeMap<Spec, BTreeSet<Row>>,
    /// Cases of the `interact` family per spec.
    pub interact_cases: BTreeMap<Spec, usize>,
}

impl PairCoverage {
    pub fn add(&mut self, c: &Case) {
        let own = c.id.contains(&format!("/{}/", interact::FAMILY));
        if own {
            *self.interact_cases.entry(c.spec).or_default() += 1;
        }
        for &api in &c.api {
            let r = row(c, api);
            if own {
                self.interact.entry(c.spec).or_default().insert(r.clone());
            }
            self.all.entry(c.spec).or_default().insert(r);
        }
    }

    /// The pairs the rows of `spec` cover (in all cases, or in the `interact` family only).
    pub fn covered(&self, spec: Spec, interact_only: bool) -> BTreeSet<Pair> {
        let rows = if interact_only {
            &self.interact
        } else {
            &self.all
        };
        rows.get(&spec)
            .into_iter()
            .flatten()
            .flat_map(|r| pairs(r).collect::<Vec<_>>())
            .collect()
    }

    /// The allowed pairs of every spec that no test covers (`interact_only`: no `interact` test).
    pub fn missing(&self, interact_only: bool) -> Vec<(Spec, Pair)> {
        let mut out = Vec::new();
        for d in specs::all() {
            let covered = self.covered(d.spec, interact_only);
            for p in allowed(d.spec).difference(&covered) {
                out.push((d.spec, p.clone()));
            }
        }
        out
    }

    /// Per spec with unit-state factors, per factor pair: level pairs the spec allows, covered by
    /// the `interact` family, covered by all cases.
    pub fn markdown(&self) -> String {
        let mut s = String::from(
            "#### Unit-state interactions: level pairs covered (covering array of strength 2)\n\n",
        );
        s.push_str("Per factor pair: the level pairs the spec allows on its API paths (`allowed`), those the `interact` family covers (a test is a case on one API path), and those all cases cover. Levels: gather none / gather / offset / offsets; swizzle none or its letters; sampler object none / bound; seamless unset / on / off; DEPTH_TEXTURE_MODE unset or the mode; the target; the API path. Factor pairs with a factor of one allowed level (a feature the spec or its paths lack) are left out.\n\n");
        for d in specs::all() {
            let allowed = allowed(d.spec);
            if allowed.is_empty() {
                continue;
            }
            let own = self.covered(d.spec, true);
            let all = self.covered(d.spec, false);
            // A factor with one allowed level (the spec or its paths lack the feature) pairs
            // trivially with every other: left out.
            let levels = |f: usize| {
                allowed
                    .iter()
                    .flat_map(|p| [(p.0, &p.1), (p.2, &p.3)])
                    .filter(|(g, _)| *g == f)
                    .map(|(_, l)| l)
                    .collect::<BTreeSet<_>>()
                    .len()
            };
            let _ = writeln!(
                s,
                "##### {}: {} `interact` cases, {} tests\n",
                d.spec,
                self.interact_cases.get(&d.spec).copied().unwrap_or(0),
                self.interact.get(&d.spec).map_or(0, |r| r.len())
            );
            s.push_str(
                "| factor pair | allowed | by `interact` | by all cases |\n|---|---:|---:|---:|\n",
            );
            for (i, fi) in FACTORS.iter().enumerate() {
                for (j, fj) in FACTORS.iter().enumerate().skip(i + 1) {
                    if levels(i) < 2 || levels(j) < 2 {
                        continue;
                    }
                    let of = |set: &BTreeSet<Pair>| {
                        set.iter()
                            .filter(|p| p.0 == i && p.2 == j && allowed.contains(*p))
                            .count()
                    };
                    let _ = writeln!(
                        s,
                        "| {fi} x {fj} | {} | {} | {} |",
                        of(&allowed),
                        of(&own),
                        of(&all)
                    );
                }
            }
            s.push('\n');
        }
        s
    }
}
