//! Feature coverage: behaviours that no single grid dimension names (mixed filter classes, a wrap
//! mode per coordinate, wraps on cube faces and rectangles, filtered projective lookups, texel
//! offsets under every wrap mode, layer ties under filters that blend), as predicates over cases,
//! with the specs that allow each. `shadowcheck gen --update-readme` prints the table into
//! cases/README.md; a test fails on an empty cell a spec allows.
//!
//! Adding a feature: one [`Feature`] in [`FEATURES`].

use crate::grids::families;
use crate::grids::specs::{self, SpecDims};
use shadowcheck_model::*;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// One behaviour, how to recognise a case of it, and which specs define it.
pub struct Feature {
    pub name: &'static str,
    /// Where the behaviour is specified.
    pub cite: &'static str,
    /// The case exercises the behaviour.
    pub applies: fn(&Case) -> bool,
    /// The spec defines the behaviour and its grid covers it (the `*_ambient` variants differ from
    /// their base spec only in the fail value and get no sampling-geometry families).
    pub allowed: fn(&SpecDims) -> bool,
}

/// Filters in one level: LINEAR for LINEAR and LINEAR_MIPMAP_*, NEAREST for the others.
fn within_linear(f: Filter) -> bool {
    matches!(
        f,
        Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear
    )
}

fn geometry(d: &SpecDims) -> bool {
    !d.fail_value
}

fn is_layer_tie(c: &Case) -> bool {
    let l = match c.texture.target {
        Target::T1dArray => c.lookup.coord[1],
        Target::T2dArray => c.lookup.coord[2],
        Target::CubeArray => c.lookup.layer,
        _ => return false,
    };
    (l - l.floor()) == 0.5
}

/// The features, in table order.
pub const FEATURES: &[Feature] = &[
    Feature {
        name: "mixed filter classes (min NEAREST + mag LINEAR or the reverse)",
        cite: "GL 4.6 §8.14.1, §8.15; §8.23.1",
        applies: |c| within_linear(c.sampler.min_filter) != within_linear(c.sampler.mag_filter),
        allowed: geometry,
    },
    Feature {
        name: "wrap_s ≠ wrap_t",
        cite: "GL 4.6 §8.14.2 Table 8.20",
        applies: |c| c.texture.target.dims() == 2 && c.sampler.wrap_s != c.sampler.wrap_t,
        allowed: |d| d.wraps.len() >= 2,
    },
    Feature {
        name: "cube face with a wrap other than CLAMP_TO_EDGE",
        cite: "GL 4.6 §8.13, §8.13.1",
        applies: |c| c.texture.target.is_cube() && c.sampler.wrap_s != Wrap::ClampToEdge,
        allowed: |d| {
            geometry(d)
                && d.targets.iter().any(|t| t.is_cube())
                && families::CUBE_WRAPS.iter().any(|w| d.wraps.contains(w))
        },
    },
    Feature {
        name: "rectangle with CLAMP or CLAMP_TO_BORDER",
        cite: "GL 4.6 §8.10, §8.14.2",
        applies: |c| {
            c.texture.target.is_rect()
                && matches!(c.sampler.wrap_s, Wrap::Clamp | Wrap::ClampToBorder)
        },
        allowed: |d| {
            d.targets.contains(&Target::Rect)
                && (d.wraps.contains(&Wrap::Clamp) || d.wraps.contains(&Wrap::ClampToBorder))
        },
    },
    Feature {
        name: "array layer tie under LINEAR or a mipmapped filter",
        cite: "GL 4.6 §8.14.2 (layer l), §8.14.3",
        applies: |c| {
            is_layer_tie(c)
                && (within_linear(c.sampler.min_filter) || c.sampler.min_filter.is_mipmap())
        },
        // WebGPU's array index is an integer (WGSL textureSampleCompare): no tie to round.
        allowed: |d| {
            geometry(d) && d.targets.iter().any(|t| t.is_array()) && d.spec != Spec::WebGpu
        },
    },
    Feature {
        name: "projective lookup with LINEAR or a mipmapped filter",
        cite: "GL 4.6 §8.14.1, §8.23.1",
        applies: |c| c.lookup.projective && c.sampler.min_filter != Filter::Nearest,
        // WGSL has no projective texture built-in.
        allowed: |d| geometry(d) && d.spec != Spec::WebGpu,
    },
    Feature {
        name: "texel offset with MIRRORED_REPEAT or CLAMP_TO_BORDER",
        cite: "GL 4.6 §8.14.2 (8.10), Table 8.20",
        applies: |c| {
            c.lookup.offset != [0; 3]
                && matches!(c.sampler.wrap_s, Wrap::MirroredRepeat | Wrap::ClampToBorder)
        },
        allowed: |d| {
            matches!(d.spec, Spec::Gl46 | Spec::Gles32)
                && (d.wraps.contains(&Wrap::MirroredRepeat)
                    || d.wraps.contains(&Wrap::ClampToBorder))
        },
    },
];

/// Cases per (feature index, spec).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FeatureCounts(pub BTreeMap<(usize, Spec), usize>);

impl FeatureCounts {
    pub fn add(&mut self, c: &Case) {
        for (i, f) in FEATURES.iter().enumerate() {
            if (f.applies)(c) {
                *self.0.entry((i, c.spec)).or_default() += 1;
            }
        }
    }

    pub fn count(&self, feature: usize, spec: Spec) -> usize {
        self.0.get(&(feature, spec)).copied().unwrap_or(0)
    }

    /// (feature name, spec) cells a spec allows with no case.
    pub fn missing(&self) -> Vec<(&'static str, Spec)> {
        let mut out = Vec::new();
        for (i, f) in FEATURES.iter().enumerate() {
            for d in specs::all() {
                if (f.allowed)(&d) && self.count(i, d.spec) == 0 {
                    out.push((f.name, d.spec));
                }
            }
        }
        out
    }

    /// A row per feature, a column per spec; `-` where the spec does not define the feature (or,
    /// for the `*_ambient` variants, where it is counted on the base spec).
    pub fn markdown(&self) -> String {
        let all = specs::all();
        let mut s = String::from("#### Features\n\n");
        s.push_str("Cases per feature and spec (`-`: the spec does not define it, or an `*_ambient` variant whose sampling geometry is that of its base spec).\n\n");
        let _ = writeln!(
            s,
            "| feature | section | {} |",
            all.iter()
                .map(|d| d.spec.key())
                .collect::<Vec<_>>()
                .join(" | ")
        );
        let _ = writeln!(s, "|---|---|{}", "---:|".repeat(all.len()));
        for (i, f) in FEATURES.iter().enumerate() {
            let cells: Vec<String> = all
                .iter()
                .map(|d| {
                    if (f.allowed)(d) {
                        self.count(i, d.spec).to_string()
                    } else {
                        "-".into()
                    }
                })
                .collect();
            let _ = writeln!(s, "| {} | {} | {} |", f.name, f.cite, cells.join(" | "));
        }
        s.push('\n');
        s
    }
}
