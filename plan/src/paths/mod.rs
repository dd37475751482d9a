//! How each API path realizes a case: which sampler type and lookup function, and the values that
//! go into the shader's uniforms.
//!
//! The case's level of detail is lambda_base = `lookup.lod` plus the shader bias `lookup.bias`
//! (GL 4.6 §8.14.1). A path realizes it, in order of preference:
//! - `Lod`: an explicit-LOD function (`textureLod`), exact;
//! - `Grad`: explicit gradients (`textureGrad`) whose scale factor is 2^lod;
//! - `Implicit`: the implicit-derivative function (`texture`, `shadow2D`, ARB `TEX`/`TXB`) on a
//!   coordinate that varies across the 2x2 pixel quad by exactly those gradients, while being exactly
//!   the case's coordinate at the written pixel's centre (the offset is 0 there); the bias form
//!   passes `lookup.bias`.
//!
//! Where a sampler type has no bias form but has `Lod`/`Grad`, the bias is folded into the explicit
//! LOD (same lambda' by §8.14.1, noted in the result). Anything else is skipped with the reason.

use crate::{GlInfo, LookupForm};
use shadowcheck_model::{
    ApiPath, Case, CompareMode, Delivery, DepthStencilMode, DepthTextureMode, Filter, Lookup,
    Stage, Target,
};

/// The GLSL sampler family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SamplerKind {
    /// `sampler*Shadow`: depth comparison.
    Shadow,
    /// `sampler*`: compare mode NONE or a colour texture (r = the filtered value).
    Float,
    /// `usampler*`: DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX.
    Uint,
}

/// How lambda is realized.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LodForm {
    Lod,
    Grad,
    /// Implicit derivatives; `true`: the bias form.
    Implicit(bool),
    /// Fixed-function: constant texture coordinates (lambda_base = -inf).
    Constant,
    /// A shadow `textureGather*` (no λ: GLSL 4.60 §8.9.4 "the minification and magnification
    /// filters are ignored"); `true`: the coordinate still varies across the pixel quad by the
    /// case's gradients, so that an implementation that wrongly selects a level by λ shows it.
    Gather(bool),
}

/// The gather function of a [`ShaderKey`] with [`LodForm::Gather`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GatherCall {
    /// `textureGather`, or `textureGatherOffset` with the key's `offset`.
    Single,
    /// `textureGatherOffsets` with these four constant offsets (R, G, B, A).
    Offsets([[i8; 2]; 4]),
    /// `textureGatherOffset` with an offset that is not a constant expression: the plan's `o`,
    /// delivered as the key's [`Delivery`] says (GLSL 4.00+ / GLSL ES 3.20 §8.9.4: "the offset can
    /// be variable (non constant)").
    Variable,
}

/// The shader variant: programs are cached by this key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ShaderKey {
    pub path: ApiPath,
    pub target: Target,
    pub kind: SamplerKind,
    pub form: LodForm,
    pub proj: bool,
    /// DEPTH_TEXTURE_MODE: one program per mode, so that a driver's per-program variant caching
    /// cannot carry one mode's layout into another mode's draws.
    pub mode: Option<DepthTextureMode>,
    /// Texel offset (δu, δv) of a `*Offset` lookup (a constant expression in GLSL, so part of
    /// the program); [0, 0]: the plain function.
    pub offset: [i8; 2],
    /// Shadow gather (`form` is [`LodForm::Gather`]); `None` for every other lookup.
    pub gather: Option<GatherCall>,
    /// How the values reach the lookup (the case's [`Lookup::delivery`]): `literal` as always;
    /// the others draw one case per draw ([`crate::shaders::batchable`]) from uniforms, or from
    /// flat inputs written by the vertex shader (per fragment: changed on the quad's other three
    /// fragments, `shaders::per_fragment`).
    pub delivery: Delivery,
    /// The shader stage of the lookup (the case's [`Lookup::stage`]): `vertex` runs the lookup in
    /// the vertex shader, which passes its result to the fragment shader as a flat output;
    /// `compute` in a compute shader of one invocation, which stores it in the result image
    /// (`shaders::stage`); one case per draw or dispatch.
    pub stage: Stage,
}

/// One API path's plan for one case.
#[derive(Debug, Clone)]
pub struct Plan {
    pub key: ShaderKey,
    /// The lookup vector P (layout per target, see `shaders::p_expr`).
    pub p: [f32; 4],
    /// lod / bias / cube-array compare value.
    pub x: f32,
    pub dx: [f32; 4],
    pub dy: [f32; 4],
    /// The offset of a [`GatherCall::Variable`] gather (the uniform `u_o`); [0, 0] otherwise.
    pub o: [i32; 2],
    pub note: String,
}

/// The sampler family a case needs.
pub fn sampler_kind(case: &Case) -> SamplerKind {
    let f = case.texture.format;
    if f.has_stencil() && case.sampler.depth_stencil_mode == Some(DepthStencilMode::StencilIndex) {
        SamplerKind::Uint
    } else if f.is_depth() && case.sampler.in_effect().compare_mode == CompareMode::Compare {
        SamplerKind::Shadow
    } else {
        SamplerKind::Float
    }
}

/// The `c` of GL 4.6 §8.14 (mag/min switch-over point).
fn switch_over(case: &Case) -> f64 {
    let s = case.sampler.in_effect();
    if s.mag_filter == Filter::Linear
        && matches!(
            s.min_filter,
            Filter::NearestMipmapNearest | Filter::NearestMipmapLinear
        )
    {
        0.5
    } else {
        0.0
    }
}

/// Is the fixed-function lookup (constant coordinates: lambda_base = -inf, so lambda' = min_lod)
/// certain to give the same filter and level as the case's lambda?
fn constant_coords_equivalent(case: &Case, l: &Lookup) -> bool {
    let s = case.sampler.in_effect();
    let f32r = |v: f64| v as f32 as f64;
    let lam = (f32r(l.lod) + s.lod_bias as f64 + f32r(l.bias))
        .clamp(s.min_lod as f64, (s.max_lod as f64).max(s.min_lod as f64));
    let lam_ff = s.min_lod as f64;
    let c = switch_over(case);
    (lam <= c && lam_ff <= c) || (lam > c && lam_ff > c && !s.min_filter.is_mipmap())
}

/// Plans `path` for `case`, or says why it cannot be run.
pub fn plan(path: ApiPath, case: &Case) -> Result<Plan, String> {
    plan_with(path, case, LookupForm::Auto)
}

/// [`plan`] with a preferred lookup function: the preferred form is tried first, then the usual
/// order (the backend name's fourth part, see `names::LookupForm`).
pub fn plan_with(path: ApiPath, case: &Case, prefer: LookupForm) -> Result<Plan, String> {
    plan_in(path, case, &case.lookup, prefer, false)
}

/// The plan on a context: [`plan_with`] with the context's preferred form and, where it exposes
/// EXT_texture_shadow_lod, that extension's overloads ([`GlInfo::shadow_lod`]). `lookup` is the
/// case's own or one of its sweep's ([`Case::point_lookup`]), on the case's texture and sampler.
pub fn plan_for(
    info: &GlInfo,
    path: ApiPath,
    case: &Case,
    lookup: &Lookup,
) -> Result<Plan, String> {
    let offsets = lookup.gather.as_ref().is_some_and(|g| g.offsets.is_some());
    if offsets && info.es && info.glsl < 320 {
        return Err("textureGatherOffsets needs GLSL ES 3.20 (GLSL ES 3.10 has textureGather and textureGatherOffset only)".into());
    }
    if lookup.stage == Stage::Compute && !info.compute() {
        if info.version_override {
            return Err(format!(
                "a compute-stage lookup needs compute shaders, which this context's driver does not claim: its version ({}) is raised by MESA_GL(ES)_VERSION_OVERRIDE and it does not expose GL_ARB_compute_shader",
                info.version_string
            ));
        }
        return Err(format!(
            "a compute-stage lookup needs GL 4.3 / GLSL 4.30 or ES 3.1 / GLSL ES 3.10 (this context: {} {}.{}, GLSL{} {})",
            if info.es { "ES" } else { "GL" },
            info.version.0,
            info.version.1,
            if info.es { " ES" } else { "" },
            info.glsl
        ));
    }
    let plan = plan_in(path, case, lookup, info.form, info.shadow_lod())?;
    if plan.key.gather == Some(GatherCall::Variable) && info.glsl < if info.es { 320 } else { 400 }
    {
        return Err(format!(
            "a variable textureGatherOffset offset needs GLSL 4.00 / GLSL ES 3.20 (this context: GLSL{} {})",
            if info.es { " ES" } else { "" },
            info.glsl
        ));
    }
    Ok(plan)
}

/// `shadow_lod`: the extension's overloads may be used, and only where the preferred form asks
/// for them (`prefer` Lod: textureLod; Implicit: the bias form), so that the default order (and
/// every committed result of it) is what it was without the extension.
pub fn plan_in(
    path: ApiPath,
    case: &Case,
    l: &Lookup,
    prefer: LookupForm,
    shadow_lod: bool,
) -> Result<Plan, String> {
    if path == ApiPath::Wgsl {
        if let Some(why) = wgsl::unexpressible(case, l) {
            return Err(why);
        }
    }
    if !l.delivery.is_literal() && !shadowcheck_model::validate::DELIVERY_PATHS.contains(&path) {
        return Err(format!(
            "delivery `{}` is drawn on the GLSL 1.30+ / GLSL ES 3.00 paths only, not on {path}",
            l.delivery
        ));
    }
    if l.stage != Stage::Fragment {
        stage_drawable(path, l)?;
    }
    if l.gather.is_some() {
        return gather::plan(path, case, l);
    }
    let kind = sampler_kind(case);
    let offset = texel_offset(path, case.texture.target, l)?;
    let (form, how) = if l.stage == Stage::Compute && path == ApiPath::Wgsl {
        // WGSL's one filtered compare outside the fragment stage (WGSL textureSampleCompareLevel:
        // "may be invoked in any shader stage"), level 0 only.
        if !wgsl::level_zero_equivalent(case, l) {
            return Err(format!(
                "a WGSL compute shader's lookup is textureSampleCompareLevel, which \"always samples texels from mip level 0\": it realizes a case at lod 0 with min_lod <= 0 only (this case: lod {}, min_lod {})",
                l.lod,
                case.sampler.in_effect().min_lod
            ));
        }
        (
            LodForm::Lod,
            "textureSampleCompareLevel in a compute shader",
        )
    } else if l.stage != Stage::Fragment {
        // The implicit-LOD function, whose λ_base is 0 outside the fragment shader (GLSL 4.60
        // §8.9): the case's `lod` is the fragment shader's, which this draw does not realize.
        (
            LodForm::Implicit(false),
            if l.stage == Stage::Vertex {
                "implicit LOD in the vertex shader"
            } else {
                "implicit LOD in a compute shader"
            },
        )
    } else {
        choose_form(path, case, l, kind, offset, prefer, shadow_lod)?
    };
    let key = ShaderKey {
        path,
        target: case.texture.target,
        kind,
        form,
        proj: l.projective,
        mode: case.sampler.depth_texture_mode,
        offset,
        gather: None,
        delivery: l.delivery,
        stage: l.stage,
    };
    let how = if uses_shadow_lod(&key) {
        format!("{how} (EXT_texture_shadow_lod overload)")
    } else if path == ApiPath::Wgsl {
        wgsl::note(form).to_string()
    } else {
        how.to_string()
    };
    let (mut p, x, dx, dy) = shader_values(case, l, &key);
    let bias = l.bias as f32;
    if path == ApiPath::ArbFp && form == LodForm::Implicit(true) {
        // TXB takes the bias in the fourth component.
        p[3] = bias;
        return Ok(Plan {
            key,
            p,
            x,
            dx,
            dy,
            o: [0, 0],
            note: format!("ARB fp TXB, {how}"),
        });
    }
    Ok(Plan {
        key,
        p,
        x,
        dx,
        dy,
        o: [0, 0],
        note: delivery_note(how, l.delivery),
    })
}

/// What the programs of the other stages draw (`shaders::stage`): literal values, on a path
/// whose language has the stage (`validate::STAGE_PATHS`, `validate::COMPUTE_PATHS`); a vertex
/// shader a filtered lookup, a compute shader a filtered lookup or a gather.
fn stage_drawable(path: ApiPath, l: &Lookup) -> Result<(), String> {
    use shadowcheck_model::validate::{COMPUTE_PATHS, STAGE_PATHS};
    let (paths, which) = if l.stage == Stage::Compute {
        (&COMPUTE_PATHS[..], "the GLSL 4.30 / GLSL ES 3.10")
    } else {
        (&STAGE_PATHS[..], "the GLSL 1.20+ / GLSL ES 3.00")
    };
    if !paths.contains(&path) {
        return Err(format!(
            "stage `{}` is drawn on {which} paths only, not on {path}",
            l.stage
        ));
    }
    if l.stage == Stage::Compute && l.delivery.is_literal() {
        return Ok(());
    }
    if l.gather.is_some() || !l.delivery.is_literal() {
        return Err(format!(
            "stage `{}` is drawn for filtered lookups with literal values only (no gather, no delivery)",
            l.stage
        ));
    }
    Ok(())
}

/// The plan's note with the delivery, where it is not the literal one.
pub(crate) fn delivery_note(how: String, d: Delivery) -> String {
    match d {
        Delivery::Literal => how,
        Delivery::Uniform => format!("{how}, values from uniforms"),
        Delivery::Flat => format!("{how}, values from flat inputs"),
        Delivery::PerFragment => format!("{how}, values differing across the pixel quad"),
    }
}

/// The lookup's texel offset as the shader writes it: none, or (u, v) on the paths whose
/// functions take one (GLSL 1.30+ `*Offset`, §8.9.2), never on a cube map.
fn texel_offset(path: ApiPath, t: Target, l: &Lookup) -> Result<[i8; 2], String> {
    if l.offset == [0; 3] {
        Ok([0, 0])
    } else if path == ApiPath::Wgsl && !t.is_cube() {
        wgsl::offset(l.offset)
    } else if !matches!(
        path,
        ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan
    ) {
        Err(format!("{path} has no lookup function with a texel offset"))
    } else if t.is_cube() {
        Err("cube map lookups take no texel offset".to_string())
    } else {
        match (i8::try_from(l.offset[0]), i8::try_from(l.offset[1])) {
            (Ok(a), Ok(b)) => Ok([a, b]),
            _ => Err(format!("texel offset {:?} out of range", l.offset)),
        }
    }
}

/// How the path realizes the case's level of detail: the first form in order of preference (the
/// backend's preferred one first) that the path's language has for this sampler, target, projection
/// and offset, with the note that says how.
fn choose_form(
    path: ApiPath,
    case: &Case,
    l: &Lookup,
    kind: SamplerKind,
    offset: [i8; 2],
    prefer: LookupForm,
    shadow_lod: bool,
) -> Result<(LodForm, &'static str), String> {
    let t = case.texture.target;
    let proj = l.projective;
    let bias = l.bias as f32;
    let mut forms: Vec<(LodForm, &'static str)> = if path == ApiPath::FixedFunction {
        vec![(LodForm::Constant, "constant texture coordinates")]
    } else if bias == 0.0 {
        vec![
            (LodForm::Lod, "explicit LOD"),
            (LodForm::Grad, "explicit gradients"),
            (LodForm::Implicit(false), "implicit derivatives"),
        ]
    } else {
        vec![
            (LodForm::Implicit(true), "implicit derivatives with bias"),
            (LodForm::Lod, "explicit LOD = lod + bias"),
            (LodForm::Grad, "gradients for lod + bias"),
        ]
    };
    let preferred = |f: &LodForm| match prefer {
        LookupForm::Auto => false,
        LookupForm::Lod => *f == LodForm::Lod,
        LookupForm::Grad => *f == LodForm::Grad,
        LookupForm::Implicit => matches!(f, LodForm::Implicit(_)),
    };
    // Stable: the preferred form first, the others in their usual order.
    forms.sort_by_key(|(f, _)| !preferred(f));
    if path == ApiPath::Wgsl && !wgsl::level_zero_equivalent(case, l) {
        // textureSampleCompareLevel reads level 0 only (`wgsl.rs`).
        forms.retain(|(f, _)| *f != LodForm::Lod);
    }
    let ext_for = |f: &LodForm| {
        shadow_lod
            && match prefer {
                LookupForm::Lod => *f == LodForm::Lod,
                LookupForm::Implicit => matches!(f, LodForm::Implicit(_)),
                _ => false,
            }
    };
    let (form, how) = forms
        .into_iter()
        .find(|(f, _)| {
            let ext = ext_for(f);
            available_with(path, kind, t, *f, proj, ext)
                && (offset == [0, 0] || offset_available_with(path, kind, t, *f, ext))
        })
        .ok_or_else(|| {
            format!(
                "{} has no {}{:?} lookup on a {} texture{}",
                path,
                if proj { "projective " } else { "" },
                kind,
                t,
                if bias != 0.0 {
                    " with a shader bias"
                } else {
                    ""
                }
            )
        })?;
    // Fixed-function: constant coordinates are exact but give lambda_base = -inf; where that
    // changes the filter or level, the coordinates vary across the pixel quad instead (by the
    // gradients, interpolated by the rasterizer) and the shader bias goes to the texture unit's
    // TEXTURE_LOD_BIAS (GL 4.6 compatibility §8.14.1: bias_texunit + bias_shader).
    if form == LodForm::Constant && !constant_coords_equivalent(case, l) {
        return Ok((
            LodForm::Implicit(bias != 0.0),
            "fixed-function, coordinates varying 2^lod texels per pixel (interpolated), bias via TEXTURE_LOD_BIAS",
        ));
    }
    Ok((form, how))
}

/// The values the shader of `key` receives for lookup `l`: P, the extra scalar `x` (explicit LOD,
/// shader bias, or a cube-array shadow lookup's reference) and the gradients dx, dy.
fn shader_values(case: &Case, l: &Lookup, key: &ShaderKey) -> ([f32; 4], f32, [f32; 4], [f32; 4]) {
    let (t, form, proj) = (key.target, key.form, key.proj);
    let (lod, bias) = (l.lod as f32, l.bias as f32);
    let folded = matches!(form, LodForm::Lod | LodForm::Grad) && bias != 0.0;
    let lod_eff = if folded { lod + bias } else { lod };
    let c = [
        l.coord[0] as f32,
        l.coord[1] as f32,
        l.coord[2] as f32,
        l.coord[3] as f32,
    ];
    let q = if proj { c[3] } else { 1.0 };
    let dref = l.dref as f32;
    let shadow = key.kind == SamplerKind::Shadow;
    // P by target (see shaders::p_expr).
    let p = match t {
        Target::T1d | Target::T2d | Target::Rect => [
            c[0],
            if t == Target::T1d { 0.0 } else { c[1] },
            if shadow { dref } else { 0.0 },
            q,
        ],
        Target::T1dArray => [c[0], c[1], dref, 1.0],
        Target::T2dArray => [c[0], c[1], c[2], dref],
        Target::Cube => [c[0], c[1], c[2], dref],
        Target::CubeArray => [c[0], c[1], c[2], l.layer as f32],
    };
    let x = match form {
        _ if shadow && t == Target::CubeArray => dref,
        LodForm::Lod => lod_eff,
        LodForm::Implicit(true) => bias,
        _ => 0.0,
    };
    let (mut dx, mut dy) = gradients(case, l, lod_eff);
    if shadow && t == Target::CubeArray && form == LodForm::Lod {
        // textureLod(samplerCubeArrayShadow, P, compare, lod): the compare value is in `x`, the
        // LOD goes in dx.x (the gradients are unused by textureLod).
        dx[0] = lod_eff;
    }
    if let LodForm::Implicit(_) = form {
        if proj {
            // The function divides by q, so the coordinate must vary q times faster.
            for g in [&mut dx, &mut dy] {
                g[0] *= q;
                g[1] *= q;
            }
        }
    }
    (p, x, dx, dy)
}

/// Screen-space gradients of the lookup coordinate giving a scale factor rho = 2^lod
/// (GL 4.6 §8.14.1: u = s * w_base, rho = max of the lengths of the derivative vectors; cube maps
/// measure the face coordinates sc/|ma|, tc/|ma| mapped to [0,1] by (x+1)/2, §8.13).
pub fn gradients(case: &Case, l: &Lookup, lod: f32) -> ([f32; 4], [f32; 4]) {
    let scale = (lod.clamp(-64.0, 64.0) as f64).exp2();
    let lvl = &case.texture.levels[0];
    let (w, h) = (lvl.width as f64, lvl.height as f64);
    let mut dx = [0f32; 4];
    let mut dy = [0f32; 4];
    match case.texture.target {
        Target::T1d | Target::T1dArray => dx[0] = (scale / w) as f32,
        Target::T2d | Target::T2dArray => {
            dx[0] = (scale / w) as f32;
            dy[1] = (scale / h) as f32;
        }
        Target::Rect => {
            dx[0] = scale as f32;
            dy[1] = scale as f32;
        }
        Target::Cube | Target::CubeArray => {
            let c = &l.coord;
            let m = (0..3)
                .max_by(|&a, &b| c[a].abs().total_cmp(&c[b].abs()))
                .unwrap_or(2);
            let ma = c[m].abs().max(f64::MIN_POSITIVE);
            let g = (scale * 2.0 * ma / w) as f32;
            let minor: Vec<usize> = (0..3).filter(|&i| i != m).collect();
            dx[minor[0]] = g;
            dy[minor[1]] = g;
        }
    }
    (dx, dy)
}

mod forms;
mod gather;
#[cfg(test)]
mod tests;
pub mod wgsl;

pub use forms::{
    available, available_with, offset_available, offset_available_with, uses_shadow_lod,
};
