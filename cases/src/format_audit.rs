//! The audit of rules by format (cases/README.md, "Rules by format"): for each clamping,
//! conversion and completeness rule of the oracle, the formats it applies to, and which of them a
//! set of cases exercises it on. `cases/tests/format_audit.rs` holds the committed fixtures to
//! every (rule, format) pair of GL 4.6 and ES 3.2 and keeps the README table in step.

use shadowcheck_model::{Case, CompareMode, DepthStencilMode, Format, Spec, Texels, Wrap};
use shadowcheck_oracle::{lod, rules};
use std::collections::{BTreeMap, BTreeSet};

/// One rule: its key, what it says (with the section), the formats it applies to, and whether a
/// case exercises it.
pub struct Rule {
    pub key: &'static str,
    pub what: &'static str,
    pub applies: fn(Format) -> bool,
    pub exercised: fn(&Case) -> bool,
}

/// The specs whose grids hold every format the rules name (the legacy and ES 2.0 variants have a
/// fixed subset; Vulkan and WebGPU have no incomplete textures, colour compare or stencil reads).
pub const SPECS: [Spec; 2] = [Spec::Gl46, Spec::Gles32];

/// What a case does, resolved once.
struct Facts {
    compare: bool,
    stencil: bool,
    incomplete: bool,
}

fn facts(c: &Case) -> Facts {
    let s = c.sampler.in_effect();
    let f = c.texture.format;
    let stencil = f.has_stencil() && s.depth_stencil_mode == Some(DepthStencilMode::StencilIndex);
    let r = rules::rules_for(c.spec);
    Facts {
        compare: s.compare_mode == CompareMode::Compare,
        stencil,
        incomplete: lod::incomplete(&r, &c.texture, &s, stencil).is_some(),
    }
}

/// The reference as the comparison sees it (divided by q for a projective lookup).
fn dref(c: &Case) -> f64 {
    if c.lookup.projective {
        c.lookup.dref / c.lookup.coord[3]
    } else {
        c.lookup.dref
    }
}

fn depth(f: Format) -> bool {
    f.is_depth()
}

/// The rules, in the order of the README table.
pub const RULES: &[Rule] = &[
    Rule {
        key: "ref-clamp",
        what: "Dref outside [0, 1]: clamped for fixed-point formats, not for floating-point ones (GL 4.6 §8.23.1, ES 3.2 §8.20.1)",
        applies: depth,
        exercised: |c| {
            let x = facts(c);
            let r = dref(c);
            c.texture.format.is_depth()
                && x.compare
                && !x.stencil
                && !x.incomplete
                && r.is_finite()
                && !(0.0..=1.0).contains(&r)
        },
    },
    Rule {
        key: "float-upload-clamp",
        what: "a floating-point depth texel outside [0, 1] is clamped at upload (§8.5)",
        applies: |f| f.is_depth() && f.unorm_bits().is_none(),
        exercised: |c| {
            !facts(c).incomplete
                && c.texture.levels.iter().any(|l| match &l.depth {
                    Texels::Float(v) => v.iter().any(|d| !(0.0..=1.0).contains(d)),
                    _ => false,
                })
        },
    },
    Rule {
        key: "border-clamp",
        what: "a border depth outside [0, 1]: clamped (ES 3.2) or undefined (GL 4.6) for fixed-point formats, kept for floating-point (§8.14.2)",
        applies: depth,
        exercised: |c| {
            let s = c.sampler.in_effect();
            let x = facts(c);
            c.texture.format.is_depth()
                && x.compare
                && !x.stencil
                && !x.incomplete
                && [s.wrap_s, s.wrap_t].contains(&Wrap::ClampToBorder)
                && !(0.0..=1.0).contains(&s.border[0])
        },
    },
    Rule {
        key: "unorm-conversion",
        what: "a stored unorm c reads c / (2^b − 1), per component for colour (eq. (2.1)), seen without comparison",
        applies: |f| f.unorm_bits().is_some(),
        exercised: |c| {
            let x = facts(c);
            (!x.compare || !c.texture.format.is_depth()) && !x.stencil && !x.incomplete
        },
    },
    Rule {
        key: "colour-bypass",
        what: "TEXTURE_COMPARE_MODE on a colour texture: \"texture comparison is bypassed\", the result is Cb (§8.23, Table 15.1)",
        applies: |f| f.is_colour(),
        exercised: |c| {
            let x = facts(c);
            c.texture.format.is_colour() && x.compare && !x.incomplete
        },
    },
    Rule {
        key: "dsm-depth",
        what: "DEPTH_STENCIL_TEXTURE_MODE = DEPTH_COMPONENT set explicitly: the depth compares (§8.23.1)",
        applies: |f| f.has_stencil(),
        exercised: |c| {
            c.sampler.depth_stencil_mode == Some(DepthStencilMode::DepthComponent)
                && !facts(c).incomplete
        },
    },
    Rule {
        key: "dsm-stencil",
        what: "DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX: r = St through a usampler (§8.23.1, §11.1.3.5)",
        applies: |f| f.has_stencil(),
        exercised: |c| {
            let x = facts(c);
            x.stencil && !x.incomplete
        },
    },
    Rule {
        key: "incomplete-shadow",
        what: "an incomplete texture returns 0 to a shadow sampler (§11.1.3.5)",
        applies: depth,
        exercised: |c| {
            let x = facts(c);
            c.texture.format.is_depth() && x.compare && !x.stencil && x.incomplete
        },
    },
    Rule {
        key: "incomplete-non-shadow",
        what: "an incomplete texture returns (0, 0, 0, 1) to a non-shadow sampler (§11.1.3.5)",
        applies: |_| true,
        exercised: |c| {
            let x = facts(c);
            (!x.compare || c.texture.format.is_colour()) && !x.stencil && x.incomplete
        },
    },
    Rule {
        key: "incomplete-stencil",
        what: "an incomplete DEPTH_STENCIL texture read as STENCIL_INDEX through a usampler returns (0, 0, 0, 1) (§11.1.3.5: a non-shadow sampler, a supported combination)",
        applies: |f| f.has_stencil(),
        exercised: |c| {
            let x = facts(c);
            x.stencil && x.incomplete
        },
    },
];

/// The formats a spec's grid has: the main product's and the colour formats of several
/// components its rules define.
pub fn spec_formats(spec: Spec, main: &[Format]) -> Vec<Format> {
    let mut v: Vec<Format> = main.to_vec();
    for &f in rules::rules_for(spec).formats {
        if f.is_multi_colour() && !v.contains(&f) {
            v.push(f);
        }
    }
    v
}

/// (spec, rule key) -> the formats the cases exercise the rule on.
pub type Exercised = BTreeMap<(Spec, &'static str), BTreeSet<Format>>;

/// What `cases` exercise, for the specs of [`SPECS`].
pub fn exercised<'a>(cases: impl IntoIterator<Item = &'a Case>) -> Exercised {
    let mut out = Exercised::new();
    for c in cases.into_iter().filter(|c| SPECS.contains(&c.spec)) {
        for r in RULES {
            if (r.applies)(c.texture.format) && (r.exercised)(c) {
                out.entry((c.spec, r.key))
                    .or_default()
                    .insert(c.texture.format);
            }
        }
    }
    out
}

/// The (spec, rule, format) triples a rule applies to but `have` does not exercise.
pub fn missing(have: &Exercised, formats: impl Fn(Spec) -> Vec<Format>) -> Vec<String> {
    let mut out = Vec::new();
    for spec in SPECS {
        for r in RULES {
            let got = have.get(&(spec, r.key));
            for f in formats(spec).into_iter().filter(|f| (r.applies)(*f)) {
                if !got.is_some_and(|g| g.contains(&f)) {
                    out.push(format!("{spec}: rule `{}` on format `{f}`", r.key));
                }
            }
        }
    }
    out
}

/// The README table: per rule, what it says and the formats it is exercised on per spec.
pub fn table(have: &Exercised) -> String {
    let mut s = String::from("| rule | what | gl46 | gles32 |\n|---|---|---|---|\n");
    for r in RULES {
        let cell = |spec| {
            have.get(&(spec, r.key)).map_or("—".to_string(), |f| {
                f.iter().map(|f| f.key()).collect::<Vec<_>>().join(", ")
            })
        };
        s.push_str(&format!(
            "| `{}` | {} | {} | {} |\n",
            r.key,
            r.what,
            cell(Spec::Gl46),
            cell(Spec::Gles32)
        ));
    }
    s
}
