//! What an implementation declares it can run, and the one decision made from it: does a case run
//! (on which API paths), is it Skip and why, or is it no test of this implementation at all (a spec
//! or API path it does not implement: not applicable, as a dEQP caselist would not list it).

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, StateCase};

/// What an implementation can run (fixture keys). `None` for a list means "no restriction
/// declared".
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Capabilities {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specs: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub api: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub targets: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub formats: Option<Vec<String>>,
    /// Sampler features beyond the spec's tokens that a case may need ([`FEATURES`]); a case that
    /// needs one not listed is Skip. `None`: every feature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub features: Option<Vec<String>>,
    /// Extensions the implementation exposes: reports show them, and a state case whose pname only
    /// an extension defines is judged by that extension's rules where it is listed
    /// (`StateExpect::with_extension`); empty (or absent): none.
    #[serde(default)]
    pub extensions: Vec<String>,
}

/// A piece of sampler state that not every implementation of a spec's API paths can set, with
/// the key an implementation lists in `capabilities.features` and what it is.
pub struct Feature {
    pub key: &'static str,
    pub what: &'static str,
    /// Whether the case sets it (to a value other than its default).
    pub used_by: fn(&Case) -> bool,
}

/// Every feature a case may need. OpenGL ES has no TEXTURE_LOD_BIAS (ES 3.2 §8.10 lists no such
/// parameter); TEXTURE_COMPARE_FAIL_VALUE_ARB exists only with GL_ARB_shadow_ambient; an ES 3.0
/// context has neither CLAMP_TO_BORDER / TEXTURE_BORDER_COLOR (ES 3.2) nor
/// DEPTH_STENCIL_TEXTURE_MODE (ES 3.1), so a case setting them is Skip there, never a GL error.
pub const FEATURES: &[Feature] = &[
    Feature {
        key: "lod_bias",
        what: "TEXTURE_LOD_BIAS",
        used_by: |c| c.sampler.in_effect().lod_bias != 0.0 || c.sampler.lod_bias != 0.0,
    },
    Feature {
        key: "fail_value",
        what: "TEXTURE_COMPARE_FAIL_VALUE_ARB (GL_ARB_shadow_ambient)",
        used_by: |c| c.sampler.fail_value.is_some(),
    },
    Feature {
        key: "border_clamp",
        what: "CLAMP_TO_BORDER / TEXTURE_BORDER_COLOR (OpenGL ES 3.2, OES_texture_border_clamp)",
        used_by: uses_border,
    },
    Feature {
        key: "stencil_texturing",
        what: "DEPTH_STENCIL_TEXTURE_MODE (OpenGL 4.3, OpenGL ES 3.1, ARB_stencil_texturing)",
        used_by: |c| c.sampler.depth_stencil_mode.is_some(),
    },
    Feature {
        key: "gather",
        what: "shadow textureGather / textureGatherOffset(s) (GLSL 4.00, GLSL ES 3.10)",
        used_by: |c| c.lookup.gather.is_some(),
    },
    Feature {
        key: TEX_PARAMETER,
        what: "TexParameter / GetTexParameter state cases (the `state` request)",
        // No lookup case needs it; state cases need it (`Capabilities::support_state`).
        used_by: |_| false,
    },
    Feature {
        key: "swizzle",
        what: "TEXTURE_SWIZZLE_R/G/B/A (OpenGL 3.3, OpenGL ES 3.0, ARB_texture_swizzle)",
        used_by: |c| c.sampler.swizzle.is_some(),
    },
    Feature {
        key: "seamless_toggle",
        what: "Enable / Disable(TEXTURE_CUBE_MAP_SEAMLESS) (OpenGL 3.2, ARB_seamless_cube_map)",
        used_by: |c| c.sampler.seamless.is_some(),
    },
    Feature {
        key: "sampler_objects",
        what: "sampler objects (OpenGL 3.3, OpenGL ES 3.0, ARB_sampler_objects)",
        used_by: |c| c.sampler.sampler_object.is_some(),
    },
];

/// The feature an implementation lists to be sent state cases.
pub const TEX_PARAMETER: &str = "tex_parameter";

/// Whether a case sets TEXTURE_BORDER_COLOR or wraps a coordinate its target uses with
/// CLAMP_TO_BORDER (neither exists in OpenGL ES 3.0: ES 3.2 §8.10 added both).
fn uses_border(c: &Case) -> bool {
    let t = c.texture.target;
    sets_border(&c.sampler, t) || sets_border(&c.sampler.in_effect(), t)
}

fn sets_border(s: &shadowcheck_model::Sampler, t: shadowcheck_model::Target) -> bool {
    use shadowcheck_model::Wrap;
    let used = [
        (s.wrap_s, true),
        (s.wrap_t, t.dims() == 2),
        (s.wrap_r, t.is_cube()),
    ];
    s.border != [0.0; 4] || used.iter().any(|(w, on)| *on && *w == Wrap::ClampToBorder)
}

fn listed(list: &Option<Vec<String>>, key: &str) -> bool {
    list.as_ref().is_none_or(|l| l.iter().any(|k| k == key))
}

/// Which API paths of a case a backend will run, or why it runs none.
#[derive(Debug, Clone, PartialEq)]
pub enum Support {
    /// Run these paths (a subset of the case's); the others are not applicable (API paths the
    /// implementation does not implement), with the reason.
    Run {
        apis: Vec<ApiPath>,
        others: Option<String>,
    },
    /// Applicable, but not run here (a target or format the implementation lacks): Skip, with
    /// the reason.
    Skip(String),
    /// No test of this implementation: its spec, or every one of its API paths, is one the
    /// implementation does not implement. Not counted as a test.
    NotApplicable(String),
}

impl Capabilities {
    /// Whether the implementation implements API path `api` (no list declared: every path).
    pub fn implements_api(&self, api: ApiPath) -> bool {
        listed(&self.api, api.key())
    }

    /// Everything allowed.
    pub fn all() -> Capabilities {
        Capabilities::default()
    }

    /// Whether `case` runs here: the runner calls this before sending a case (anything outside
    /// is never sent), and a worker may call it on what it receives. Not applicable (spec, API
    /// paths) is decided before Skip (target, format): a path the backend does not implement is
    /// no test of it, whatever the texture.
    pub fn support(&self, case: &Case) -> Support {
        if !listed(&self.specs, case.spec.key()) {
            return Support::NotApplicable(format!(
                "spec `{}` not supported by this backend",
                case.spec
            ));
        }
        let apis: Vec<ApiPath> = case
            .api
            .iter()
            .copied()
            .filter(|a| self.implements_api(*a))
            .collect();
        if apis.is_empty() {
            return Support::NotApplicable(
                "none of the case's API paths is supported by this backend".to_string(),
            );
        }
        if !listed(&self.targets, case.texture.target.key()) {
            return Support::Skip(format!(
                "target `{}` not supported by this backend",
                case.texture.target
            ));
        }
        if !listed(&self.formats, case.texture.format.key()) {
            return Support::Skip(format!(
                "format `{}` not supported by this backend",
                case.texture.format
            ));
        }
        for f in FEATURES {
            if (f.used_by)(case) && !listed(&self.features, f.key) {
                return Support::Skip(format!(
                    "{} (feature `{}`) not supported by this backend",
                    f.what, f.key
                ));
            }
        }
        let others = (apis.len() < case.api.len())
            .then(|| "API path not supported by this backend".to_string());
        Support::Run { apis, others }
    }
}

impl Capabilities {
    /// Whether a state case runs here, by the same rules as [`Capabilities::support`]: spec and
    /// API paths (context kinds) decide applicability; the target, then the `tex_parameter`
    /// feature, decide Skip.
    pub fn support_state(&self, case: &StateCase) -> Support {
        if !listed(&self.specs, case.spec.key()) {
            return Support::NotApplicable(format!(
                "spec `{}` not supported by this backend",
                case.spec
            ));
        }
        let apis: Vec<ApiPath> = case
            .api
            .iter()
            .copied()
            .filter(|a| self.implements_api(*a))
            .collect();
        if apis.is_empty() {
            return Support::NotApplicable(
                "none of the case's API paths is supported by this backend".to_string(),
            );
        }
        if !listed(&self.features, TEX_PARAMETER) {
            return Support::Skip(format!(
                "TexParameter / GetTexParameter state cases (feature `{TEX_PARAMETER}`) not supported by this backend"
            ));
        }
        if !listed(&self.targets, case.target.key()) {
            return Support::Skip(format!(
                "target `{}` not supported by this backend",
                case.target
            ));
        }
        // DEPTH_STENCIL_TEXTURE_MODE exists from GL 4.3 / ES 3.1 on: a context without it (ES 3.0)
        // answers INVALID_ENUM where the case's spec has the pname. Skip, as for lookups.
        if case.pname == shadowcheck_model::StatePname::DepthStencilMode
            && !listed(&self.features, "stencil_texturing")
        {
            return Support::Skip(
                "DEPTH_STENCIL_TEXTURE_MODE (feature `stencil_texturing`) not supported by this backend"
                    .to_string(),
            );
        }
        let others = (apis.len() < case.api.len())
            .then(|| "API path not supported by this backend".to_string());
        Support::Run { apis, others }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(json: &str) -> Case {
        serde_json::from_str(json).unwrap_or_else(|e| panic!("{e}: {json}"))
    }

    const CASE: &str = r#"{"id":"x","spec":"arb_ambient","api":["ff"],"texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]FAIL},"lookup":{"coord":[0.5,0.5,0,1],"dref":0.5}}"#;

    #[test]
    fn a_case_needing_an_unlisted_feature_is_skip_with_the_reason() {
        let plain = case(&CASE.replace("FAIL", ""));
        let ambient = case(&CASE.replace("FAIL", r#","fail_value":0.25"#));
        let none = Capabilities {
            features: Some(vec![]),
            ..Capabilities::all()
        };
        assert!(matches!(none.support(&plain), Support::Run { .. }));
        match none.support(&ambient) {
            Support::Skip(why) => assert!(why.contains("fail_value"), "{why}"),
            other => panic!("{other:?}"),
        }
        let listed = Capabilities {
            features: Some(vec!["fail_value".into()]),
            ..Capabilities::all()
        };
        assert!(matches!(listed.support(&ambient), Support::Run { .. }));
        // Not declared at all: no restriction (soft, exec implementations that say nothing).
        assert!(matches!(
            Capabilities::all().support(&ambient),
            Support::Run { .. }
        ));
    }
}
