//! The TexParameter / GetTexParameter state cases (`state/<spec>.json`): for each context kind a
//! spec describes as a whole (GL 4.6 core and compatibility, OpenGL ES 3.2), every
//! depth-comparison pname of `shadowcheck_model::StatePname`: its initial value, every candidate
//! value set through TexParameteri (legal ones stored, illegal ones an error with the state
//! unchanged), TexParameterf on the float pname, and the pnames the context does not have
//! (INVALID_ENUM on GetTexParameter and TexParameter). A pname the spec lacks but an extension a
//! compatibility context may expose adds (ARB_shadow_ambient, SGIX_shadow, SGIX_shadow_ambient) gets
//! every call of a pname that exists, read back: INVALID_ENUM without the extension, the
//! extension's rules with it (`StateExpect::with_extension`). On 2D textures all of that; on the other
//! targets the context has, the initial values and one legal value of TEXTURE_COMPARE_MODE and
//! _FUNC (the state is per texture object, whatever the target).
//!
//! The legacy specs (sgix, arb, ext_funcs...) get no state cases: their tables describe GL 1.x
//! implementations, while every context here is a GL 4.6 / ES 3.2 one whose state follows the
//! tables of `gl46` / `gles32` (the legacy tables stay covered by the oracle's unit tests).

use super::GridError;
use crate::fixtures::FixtureFile;
use shadowcheck_model::{
    ApiPath, Spec, StateCall, StateCase, StatePname, StateType, Target, SCHEMA_VERSION,
};
use shadowcheck_oracle::state::{self as ostate, Ctx};

/// Enum values tried on every enum pname: legal for some pname of some spec, or junk (0x1234,
/// -1).
const CANDIDATES: &[i32] = &[
    0x0000, 0x884E, 0x0200, 0x0201, 0x0202, 0x0203, 0x0204, 0x0205, 0x0206, 0x0207, 0x819C, 0x819D,
    0x1909, 0x8049, 0x1906, 0x1903, 0x1902, 0x1901, 0x1234, -1,
];

/// The context kinds with state cases: (spec, context, its API path, id part).
pub const CONTEXTS: &[(Spec, Ctx, ApiPath, &str)] = &[
    (Spec::Gl46, Ctx::Core, ApiPath::GlslCore, "core"),
    (Spec::Gl46, Ctx::Compat, ApiPath::FixedFunction, "compat"),
    (Spec::Gles32, Ctx::Es, ApiPath::Es300, "es"),
];

fn targets(ctx: Ctx) -> &'static [Target] {
    match ctx {
        Ctx::Es => &[Target::Cube, Target::T2dArray, Target::CubeArray],
        _ => &[
            Target::T1d,
            Target::Rect,
            Target::Cube,
            Target::T1dArray,
            Target::T2dArray,
            Target::CubeArray,
        ],
    }
}

fn call_tag(call: StateCall) -> String {
    match call {
        StateCall::Initial => "initial".into(),
        StateCall::SetInt(v) if v >= 0 => format!("set=0x{v:04X}"),
        StateCall::SetInt(v) => format!("set={v}"),
        StateCall::SetFloat(v) => format!("setf={v}"),
    }
}

/// The calls tried on `pname` where it exists.
fn calls(pname: StatePname) -> Vec<StateCall> {
    let mut v = vec![StateCall::Initial];
    match pname.value_type() {
        StateType::Bool => v.extend([0, 1, 2].map(StateCall::SetInt)),
        StateType::Enum => v.extend(CANDIDATES.iter().map(|c| StateCall::SetInt(*c))),
        StateType::Float => v.extend([-0.5, 0.25, 1.5].map(StateCall::SetFloat)),
    }
    v
}

/// The state cases of one spec, without expectations.
pub fn cases_of(spec: Spec) -> Vec<StateCase> {
    let mut out = Vec::new();
    for &(s, ctx, api, tag) in CONTEXTS.iter().filter(|c| c.0 == spec) {
        let mut push = |target: Target, pname: StatePname, call: StateCall, read_back: bool| {
            out.push(StateCase {
                id: format!(
                    "state/{}/{tag}/{}/{}/{}",
                    s.key(),
                    target.key(),
                    pname.key(),
                    call_tag(call)
                ),
                spec: s,
                api: vec![api],
                target,
                pname,
                call,
                read_back,
                expect: None,
            })
        };
        for &pname in StatePname::ALL {
            // A pname of this context, or one an extension the context may expose adds
            // (`ostate::PNAME_EXTENSIONS`, compatibility only): every call, read back, so that a
            // context exposing the extension is checked against the extension's rules.
            if ostate::reads_back(s, ctx, pname.gl()) {
                for call in calls(pname) {
                    push(Target::T2d, pname, call, true);
                }
            } else {
                // Not a pname of this context: GetTexParameter and TexParameter both fail.
                push(Target::T2d, pname, StateCall::Initial, false);
                push(Target::T2d, pname, StateCall::SetInt(0), false);
            }
        }
        for &target in targets(ctx) {
            push(target, StatePname::CompareMode, StateCall::Initial, true);
            push(
                target,
                StatePname::CompareMode,
                StateCall::SetInt(0x884E),
                true,
            );
            push(target, StatePname::CompareFunc, StateCall::Initial, true);
            push(
                target,
                StatePname::CompareFunc,
                StateCall::SetInt(0x0206),
                true,
            );
        }
    }
    out
}

/// The state fixture files of a grid without expectations.
pub fn unfilled_files(grid: &str, seed: u64) -> Vec<(String, FixtureFile)> {
    [Spec::Gl46, Spec::Gles32]
        .into_iter()
        .map(|spec| {
            (
                format!("state/{}.json", spec.key()),
                FixtureFile {
                    schema_version: SCHEMA_VERSION,
                    generator: super::GENERATOR.to_string(),
                    grid: grid.to_string(),
                    seed,
                    cases: vec![],
                    state_cases: cases_of(spec),
                },
            )
        })
        .collect()
}

/// The state fixture files of a grid (`state/<spec>.json`), expectations filled by the oracle.
pub fn files(grid: &str, seed: u64) -> Result<Vec<(String, FixtureFile)>, GridError> {
    let mut files = unfilled_files(grid, seed);
    for (_, f) in &mut files {
        for c in &mut f.state_cases {
            let e = ostate::expect_state(c).map_err(|msg| GridError::State {
                grid: grid.into(),
                id: c.id.clone(),
                msg,
            })?;
            c.expect = Some(e);
        }
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{GlErrorCode, StateValue};

    fn find<'a>(v: &'a [StateCase], id: &str) -> &'a StateCase {
        v.iter()
            .find(|c| c.id == id)
            .unwrap_or_else(|| panic!("no case {id}"))
    }

    #[test]
    fn state_files_hold_the_oracle_tables() {
        let files = files("default", 0).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(files.len(), 2);
        let gl = &files[0].1.state_cases;
        // GL 4.6 §8.10: an illegal compare mode is INVALID_ENUM and the state stays NONE (§2.3.1).
        let c = find(gl, "state/gl46/core/2d/compare_mode/set=0x1234");
        let e = c.expect.as_ref().unwrap_or_else(|| panic!("no expect"));
        assert_eq!(e.error, Some(GlErrorCode::InvalidEnum));
        assert_eq!(e.value, Some(StateValue::Enum(0)));
        // Table 23.15: TEXTURE_COMPARE_FUNC starts as LEQUAL.
        let c = find(gl, "state/gl46/core/cube/compare_func/initial");
        let e = c.expect.as_ref().unwrap_or_else(|| panic!("no expect"));
        assert_eq!((e.error, e.value), (None, Some(StateValue::Enum(0x0203))));
        // DEPTH_TEXTURE_MODE: compatibility only (RED legal there), INVALID_ENUM in core.
        let c = find(gl, "state/gl46/compat/2d/depth_texture_mode/set=0x1903");
        let e = c.expect.as_ref().unwrap_or_else(|| panic!("no expect"));
        assert_eq!((e.error, e.value), (None, Some(StateValue::Enum(0x1903))));
        let c = find(gl, "state/gl46/core/2d/depth_texture_mode/initial");
        let e = c.expect.as_ref().unwrap_or_else(|| panic!("no expect"));
        assert_eq!(
            (e.error, e.value, c.read_back),
            (Some(GlErrorCode::InvalidEnum), None, false)
        );
        let es = &files[1].1.state_cases;
        assert!(es.iter().all(|c| c.api == [ApiPath::Es300]));
        assert!(!es.iter().any(|c| c.target == Target::Rect));
        // Every id is unique.
        let mut ids: Vec<&str> = gl.iter().chain(es).map(|c| c.id.as_str()).collect();
        let n = ids.len();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), n);
    }
}
