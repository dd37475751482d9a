//! Does the case's state exist under its spec? Illegal TexParameter values become the GL error the
//! spec names (`OracleError::GlError`); targets, formats and API paths the spec does not define become
//! `OracleError::NotApplicable`. What is legal comes from the spec's `Rules` (its pname tables through
//! `state`).

use crate::rules::Rules;
use crate::state::{self, Ctx, GlErrorKind, Value};
use crate::OracleError;
use shadowcheck_model::{
    ApiPath, Case, CompareMode, Delivery, Filter, Sampler, Spec, Target, Wrap,
};

/// The context an API path runs in.
pub fn ctx_of(api: ApiPath) -> Ctx {
    match api {
        ApiPath::FixedFunction | ApiPath::ArbFp | ApiPath::Glsl120 | ApiPath::Glsl130 => {
            Ctx::Compat
        }
        // Vulkan and WebGPU have no GL context; their rules set no TexParameter
        // (`Rules::sampler_create`), so the context only names the core-profile rules for
        // anything shared.
        ApiPath::GlslCore | ApiPath::Vulkan | ApiPath::Wgsl => Ctx::Core,
        ApiPath::Es100Ext | ApiPath::Es300 => Ctx::Es,
    }
}

/// Targets each API path can address with a shadow lookup.
pub fn api_targets(api: ApiPath) -> &'static [Target] {
    use Target::*;
    match api {
        // Fixed-function texturing: 1D, 2D, rectangle and cube maps (compatibility 8.23.1: "For
        // fixed-function, cubemap texture lookups, Dref is the interpolated q texture coordinate").
        ApiPath::FixedFunction => &[T1d, T2d, Rect, Cube],
        // ARB_fragment_program_shadow: "SHADOW1D, SHADOW2D and SHADOWRECT".
        ApiPath::ArbFp => &[T1d, T2d, Rect],
        // GLSL 1.20: sampler1DShadow, sampler2DShadow (sampler2DRectShadow with ARB_texture_rectangle).
        ApiPath::Glsl120 => &[T1d, T2d, Rect],
        // GLSL 1.30: adds samplerCubeShadow, sampler1DArrayShadow, sampler2DArrayShadow.
        ApiPath::Glsl130 => &[T1d, T2d, Rect, Cube, T1dArray, T2dArray],
        ApiPath::GlslCore => &[T1d, T2d, Rect, Cube, T1dArray, T2dArray, CubeArray],
        ApiPath::Es100Ext => &[T2d],
        ApiPath::Es300 => &[T2d, Cube, T2dArray, CubeArray],
        // SPIR-V OpTypeImage Dim 1D, 2D, Cube, Arrayed or not, with Depth 1 (GLSL 4.50 for Vulkan's
        // sampler*Shadow types).
        ApiPath::Vulkan => &[T1d, T2d, Cube, T1dArray, T2dArray, CubeArray],
        // WGSL texture_depth_2d, texture_depth_2d_array, texture_depth_cube,
        // texture_depth_cube_array.
        ApiPath::Wgsl => &[T2d, Cube, T2dArray, CubeArray],
    }
}

fn gl_error(case: &Case, rules: &Rules, e: GlErrorKind, why: String) -> OracleError {
    OracleError::GlError {
        case: case.id.clone(),
        spec: rules.doc.to_string(),
        error: e.name(),
        why,
    }
}

fn not_applicable(case: &Case, rules: &Rules, why: String) -> OracleError {
    OracleError::NotApplicable {
        case: case.id.clone(),
        spec: rules.doc.to_string(),
        why,
    }
}

/// API paths whose result the texture swizzle is modelled on: the GLSL 1.20, GLSL 1.30+ and GLSL
/// ES 3.00 shader lookups of GL 4.6 §15.2.1 / §11.1.3.5 (ES 3.2 §14.2.1), and fixed function
/// (compatibility §16.1: the source colour of Table 16.1, then the swizzle). Not ARB fragment
/// programs: ARB_fragment_program's own texture-access text is outside the spec pack.
pub const SWIZZLE_PATHS: &[ApiPath] = &[
    ApiPath::FixedFunction,
    ApiPath::Glsl120,
    ApiPath::Glsl130,
    ApiPath::GlslCore,
    ApiPath::Es300,
];

/// Whether the unit state of GL 3.3 / ES 3.0 (swizzle, seamless enable, sampler object) exists under
/// the spec and on the case's paths: a case setting state its spec does not have is not applicable.
fn check_lookup_state(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    let s = &case.sampler;
    if s.swizzle.is_some() {
        if rules.swizzle.is_none() {
            return Err(not_applicable(
                case,
                rules,
                format!("{} has no TEXTURE_SWIZZLE_* (GL 3.3 / ES 3.0)", rules.doc),
            ));
        }
        if let Some(api) = case.api.iter().find(|a| !SWIZZLE_PATHS.contains(a)) {
            return Err(not_applicable(
                case,
                rules,
                format!("the swizzle is modelled on fixed function (compatibility §16.1) and GLSL shader lookups (GL 4.6 §15.2.1), not on `{api}`: ARB_fragment_program's texture-access text is outside the spec pack"),
            ));
        }
    }
    if s.seamless.is_some() && rules.seamless_enable.is_none() {
        return Err(not_applicable(
            case,
            rules,
            format!("{} has no TEXTURE_CUBE_MAP_SEAMLESS enable (ES 3.x cube maps are always seamless, §8.13.1)", rules.doc),
        ));
    }
    if s.sampler_object.is_some() && rules.sampler_objects.is_none() {
        return Err(not_applicable(
            case,
            rules,
            format!("{} has no sampler objects (GL 3.3 / ES 3.0)", rules.doc),
        ));
    }
    Ok(())
}

/// What TexParameter refuses for a rectangle texture's sampling state, if anything. GL 4.6 §8.10:
/// "An INVALID_ENUM error is generated if the effective target is TEXTURE_RECTANGLE and either of
/// pnames TEXTURE_WRAP_S or TEXTURE_WRAP_T is set to either MIRROR_CLAMP_TO_EDGE, MIRRORED_REPEAT
/// or REPEAT." ... "if the effective target is TEXTURE_RECTANGLE and pname TEXTURE_MIN_FILTER is
/// set to a value other than NEAREST or LINEAR (no mipmap filtering is permitted)."
pub fn rect_rejects(s: &Sampler) -> Option<String> {
    for (name, w) in [("S", s.wrap_s), ("T", s.wrap_t)] {
        if matches!(
            w,
            Wrap::MirrorClampToEdge | Wrap::MirroredRepeat | Wrap::Repeat
        ) {
            return Some(format!(
                "TEXTURE_WRAP_{name} `{w}` on a rectangle texture (GL 4.6 §8.10)"
            ));
        }
    }
    s.min_filter.is_mipmap().then(|| {
        format!(
            "TEXTURE_MIN_FILTER `{}` on a rectangle texture (GL 4.6 §8.10: no mipmap filtering)",
            s.min_filter
        )
    })
}

/// Checks state legality and applicability; Ok when the lookup is defined.
pub fn check(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    check_state(case, rules, false)
}

/// [`check`] of the effective state, a bound sampler object's sampling state in place of the
/// texture's: state a rectangle texture would refuse raises no error there (SamplerParameter knows
/// no target) but makes the texture incomplete (`engine::inputs::effective`, GL 4.6 §8.2).
pub fn check_effective(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    check_state(case, rules, true)
}

/// The checks in order: the unit state of GL 3.3 / ES 3.0, whether the spec defines the case's
/// paths, target and format, the TexParameter calls in each context, the filter and LOD state,
/// a gather, a rectangle texture's restrictions.
fn check_state(case: &Case, rules: &Rules, effective: bool) -> Result<(), OracleError> {
    check_lookup_state(case, rules)?;
    check_defined(case, rules)?;
    if let Some(why) = rules.sampler_create {
        check_sampler_create(case, rules, why)?;
    } else {
        // Every piece of sampler state is set through TexParameter in every context the case runs in.
        for api in &case.api {
            set_params(case, rules, ctx_of(*api))?;
        }
    }
    check_filter_and_lod(case, rules)?;
    if case.lookup.gather.is_some() {
        check_gather(case, rules)?;
    }
    check_delivery(case, rules)?;
    check_rect(case, rules, effective)
}

/// A lookup whose values are not constant expressions ([`Delivery`] other than `literal`): the
/// values are values, so the expectation is the literal's (GLSL 4.60 §8.9: the functions take
/// their arguments as values; §8.9.4 textureGatherOffset: "the offset can be variable (non
/// constant)"). The forms the language wants constant are rejected by the model (textureOffset's
/// offset "must be a constant expression", §8.9.2; textureGatherOffsets' "must be constant
/// integral expressions", §8.9.4). A variable gather offset exists in GLSL 4.00+ and GLSL ES 3.20
/// (GLSL ES 3.20 §8.9.4 has the same sentence; GLSL ES 3.10's textureGatherOffset takes a
/// constant offset), so under the other specs it is not applicable.
fn check_delivery(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    let l = &case.lookup;
    if l.delivery == Delivery::Literal || l.gather.is_none() || l.offset == [0; 3] {
        return Ok(());
    }
    if !matches!(rules.spec, Spec::Gl46 | Spec::Gles32) {
        return Err(not_applicable(
            case,
            rules,
            format!(
                "a variable textureGatherOffset offset (delivery `{}`) is GLSL 4.00+ / GLSL ES 3.20 only, not {}",
                l.delivery, rules.doc
            ),
        ));
    }
    Ok(())
}

/// Whether the spec defines the case's API paths (and their shadow lookup of its target), its
/// target, its format, a projective lookup on it, and (SGIX) its state in Table 3.8; what it does
/// not define is not applicable.
fn check_defined(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    let s = &case.sampler;
    let t = &case.texture;
    for api in &case.api {
        if !rules.apis.contains(api) {
            return Err(not_applicable(
                case,
                rules,
                format!("API path `{api}` does not exist under {}", rules.doc),
            ));
        }
        if !api_targets(*api).contains(&t.target) {
            return Err(not_applicable(
                case,
                rules,
                format!(
                    "API path `{api}` has no shadow lookup for target `{}`",
                    t.target
                ),
            ));
        }
    }
    if !rules.targets.contains(&t.target) {
        return Err(not_applicable(
            case,
            rules,
            format!(
                "{} defines no depth texture for target `{}`",
                rules.doc, t.target
            ),
        ));
    }
    if !rules.formats.contains(&t.format) {
        return Err(not_applicable(
            case,
            rules,
            format!("{} defines no texture format `{}`", rules.doc, t.format),
        ));
    }
    if case.lookup.projective && !matches!(t.target, Target::T1d | Target::T2d | Target::Rect) {
        return Err(not_applicable(
            case,
            rules,
            format!(
                "no projective shadow lookup exists for target `{}`",
                t.target
            ),
        ));
    }
    if case.lookup.projective && case.api.contains(&ApiPath::Wgsl) {
        return Err(not_applicable(
            case,
            rules,
            "WGSL has no projective texture built-in".to_string(),
        ));
    }
    if matches!(rules.spec, Spec::Sgix | Spec::SgixAmbient) {
        if let Some(why) = crate::sgix::outside_table_3_8(s) {
            return Err(not_applicable(case, rules, why));
        }
    }
    Ok(())
}

/// The sampler state set through TexParameter in context `ctx`: compare mode and function, depth
/// texture and depth/stencil modes, fail value, wraps; the GL error the spec names, if any.
fn set_params(case: &Case, rules: &Rules, ctx: Ctx) -> Result<(), OracleError> {
    let s = &case.sampler;
    let set = |pname: u32, v: Value| state::set_param(rules.spec, ctx, pname, v);
    set(rules.mode_pname, Value::Int(s.compare_mode.gl() as i64))
        .map_err(|e| gl_error(case, rules, e, format!("compare mode `{}`", s.compare_mode)))?;
    set(rules.func_pname, Value::Int(s.compare_func.gl() as i64)).map_err(|e| {
        gl_error(
            case,
            rules,
            e,
            format!(
                "compare function `{}` is not in {}'s table",
                s.compare_func, rules.doc
            ),
        )
    })?;
    if let Some(m) = s.depth_texture_mode {
        set(state::DEPTH_TEXTURE_MODE, Value::Int(m.gl() as i64)).map_err(|e| {
            gl_error(
                case,
                rules,
                e,
                format!("DEPTH_TEXTURE_MODE `{m}` in a {ctx:?} context"),
            )
        })?;
    }
    if let Some(m) = s.depth_stencil_mode {
        set(state::DEPTH_STENCIL_TEXTURE_MODE, Value::Int(m.gl() as i64))
            .map_err(|e| gl_error(case, rules, e, format!("DEPTH_STENCIL_TEXTURE_MODE `{m}`")))?;
    }
    if let Some(v) = s.fail_value {
        set(
            state::TEXTURE_COMPARE_FAIL_VALUE_ARB,
            Value::Float(v as f64),
        )
        .map_err(|e| gl_error(case, rules, e, "fail / ambient value".into()))?;
    }
    for (name, w) in [("S", s.wrap_s), ("T", s.wrap_t), ("R", s.wrap_r)] {
        let legal = rules.wraps.contains(&w) && !(w == Wrap::Clamp && ctx != Ctx::Compat);
        if !legal {
            return Err(gl_error(
                case,
                rules,
                GlErrorKind::InvalidEnum,
                format!(
                    "TEXTURE_WRAP_{name} `{w}` is not a legal value in a {ctx:?} context of {}",
                    rules.doc
                ),
            ));
        }
    }
    Ok(())
}

/// Sampling state that is a sampler's create info (Vulkan): what the spec's tables lack, or a
/// GL-only piece of state, cannot be created at all, so the case is not applicable (`why`: the
/// sentence). No GL error exists to expect.
fn check_sampler_create(case: &Case, rules: &Rules, why: &str) -> Result<(), OracleError> {
    let s = &case.sampler;
    // The citation only; the whole sentence is the rules' (`explain` shows it).
    let cite = why.split_once(':').map_or(why, |(c, _)| c);
    let na = |what: String| Err(not_applicable(case, rules, format!("{what} ({cite})")));
    if (rules.table)(s.compare_func, None) == Err(crate::rules::NotInTable) {
        return na(format!(
            "compare function `{}` is no VkCompareOp",
            s.compare_func
        ));
    }
    if let Some(w) = [s.wrap_s, s.wrap_t, s.wrap_r]
        .into_iter()
        .find(|w| !rules.wraps.contains(w))
    {
        return na(format!("wrap `{w}` is no VkSamplerAddressMode"));
    }
    if s.depth_texture_mode.is_some() || s.depth_stencil_mode.is_some() || s.fail_value.is_some() {
        return na(
            "DEPTH_TEXTURE_MODE, DEPTH_STENCIL_TEXTURE_MODE and a fail value are GL state".into(),
        );
    }
    if !case.texture.format.is_depth() || s.compare_mode == CompareMode::None {
        return na("a Dref lookup needs a depth image and a sampler with compareEnable".into());
    }
    Ok(())
}

/// The magnification filter, LOD bias and LOD state the spec has, and a lookup bias it allows.
fn check_filter_and_lod(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    let s = &case.sampler;
    let t = &case.texture;
    if !matches!(s.mag_filter, Filter::Nearest | Filter::Linear) {
        return Err(gl_error(
            case,
            rules,
            GlErrorKind::InvalidEnum,
            format!(
                "TEXTURE_MAG_FILTER `{}`: only NEAREST, LINEAR",
                s.mag_filter
            ),
        ));
    }
    if s.lod_bias != 0.0 && !rules.lod_bias {
        return Err(gl_error(
            case,
            rules,
            GlErrorKind::InvalidEnum,
            "TEXTURE_LOD_BIAS does not exist in ES (ES 3.2 §8.14.1)".into(),
        ));
    }
    if let Some(why) = rules.no_lod_state {
        let lod_state = t.base_level != 0
            || s.max_level.is_some()
            || s.min_lod != -1000.0
            || s.max_lod != 1000.0;
        if lod_state {
            return Err(gl_error(case, rules, GlErrorKind::InvalidEnum, why.into()));
        }
    }
    if let Some(why) = rules.no_lookup_bias {
        if case.lookup.bias != 0.0 {
            return Err(not_applicable(case, rules, why.into()));
        }
    }
    Ok(())
}

/// What a rectangle texture refuses (GL 4.6 §8.10): mipmap filtering and mirrored or repeating
/// wraps (not for the effective state of a sampler object), a base level other than 0.
fn check_rect(case: &Case, rules: &Rules, effective: bool) -> Result<(), OracleError> {
    let s = &case.sampler;
    let t = &case.texture;
    if t.target == Target::Rect {
        if let Some(why) = rect_rejects(s).filter(|_| !effective) {
            return Err(gl_error(case, rules, GlErrorKind::InvalidEnum, why));
        }
        if t.base_level != 0 {
            return Err(gl_error(
                case,
                rules,
                GlErrorKind::InvalidOperation,
                "TEXTURE_BASE_LEVEL ≠ 0 on a rectangle texture (GL 4.6 §8.10)".into(),
            ));
        }
    }
    Ok(())
}

/// The range every implementation supports: MIN_PROGRAM_TEXTURE_GATHER_OFFSET at most −8 and
/// MAX_PROGRAM_TEXTURE_GATHER_OFFSET at least 7 (the minimum values in the implementation-dependent
/// value tables of GL 4.6 and ES 3.2). An offset outside may be past the implementation's limits, where
/// "the results of the texture lookup are undefined" (§8.14.2).
pub const GATHER_OFFSET_RANGE: (i32, i32) = (-8, 7);

/// A shadow gather exists on GLSL 4.00+ / GLSL ES 3.10+ (the `core` and `es300` paths), for the
/// sampler types of GLSL 4.60 §8.9.4 ("vec4 textureGather(sampler2DShadow sampler, vec2 P, float
/// refZ)", 2DArray, Cube, CubeArray, 2DRect), non-projective, with comparison enabled ("the results
/// of a texture gather are undefined for shadow samplers if the texture referenced is not a depth
/// texture or has depth comparisons disabled"); textureGatherOffset(s) takes no cube sampler.
fn check_gather(case: &Case, rules: &Rules) -> Result<(), OracleError> {
    let t = &case.texture;
    let l = &case.lookup;
    let na = |why: String| Err(not_applicable(case, rules, why));
    if !matches!(
        rules.spec,
        Spec::Gl46 | Spec::Gles32 | Spec::Vulkan | Spec::WebGpu
    ) {
        return na(format!("{} has no textureGather", rules.doc));
    }
    if let Some(api) = case.api.iter().find(|a| {
        !matches!(
            a,
            ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
        )
    }) {
        return na(format!(
            "API path `{api}` has no shadow textureGather (GLSL 4.00 / GLSL ES 3.10)"
        ));
    }
    if case.api.contains(&ApiPath::Wgsl) && l.gather.as_ref().is_some_and(|g| g.offsets.is_some()) {
        return na(
            "WGSL has textureGatherCompare with one const offset, no textureGatherOffsets".into(),
        );
    }
    if !matches!(
        t.target,
        Target::T2d | Target::T2dArray | Target::Cube | Target::CubeArray | Target::Rect
    ) {
        return na(format!("no shadow textureGather for target `{}`", t.target));
    }
    if l.projective {
        return na("textureGather has no projective form".into());
    }
    if !t.format.is_depth() || case.sampler.compare_mode == CompareMode::None {
        return na("a shadow gather needs a depth texture with comparison enabled (GLSL 4.60 §8.9.4: otherwise undefined)".into());
    }
    let offsets: Vec<[i32; 2]> = match l.gather.as_ref().and_then(|g| g.offsets) {
        Some(o) => o.to_vec(),
        None => vec![[l.offset[0], l.offset[1]]],
    };
    let has_offset = l.offset != [0; 3] || l.gather.as_ref().is_some_and(|g| g.offsets.is_some());
    if has_offset && t.target.is_cube() {
        return na("textureGatherOffset(s) takes no cube sampler (GLSL 4.60 §8.9.4)".into());
    }
    if l.offset != [0; 3] && l.gather.as_ref().is_some_and(|g| g.offsets.is_some()) {
        return na("textureGatherOffsets takes its four offsets, not a fifth".into());
    }
    let (lo, hi) = GATHER_OFFSET_RANGE;
    if l.offset[2] != 0 || offsets.iter().flatten().any(|o| !(lo..=hi).contains(o)) {
        return na(format!("a gather offset outside [{lo}, {hi}], the spec's minimum range of MIN/MAX_PROGRAM_TEXTURE_GATHER_OFFSET: the result is undefined (§8.14.2)"));
    }
    Ok(())
}
