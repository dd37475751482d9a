//! The plan of a shadow `textureGather*` case (GLSL 4.60 / GLSL ES 3.20 §8.9.4):
//! `textureGather(sampler*Shadow, P, refZ)`, `textureGatherOffset(..., refZ, ivec2)` and
//! `textureGatherOffsets(..., refZ, ivec2[4])` on 2D, 2D array, cube, cube array and (desktop)
//! rectangle shadow samplers.

use super::{gradients, sampler_kind, GatherCall, LodForm, Plan, SamplerKind, ShaderKey};
use shadowcheck_model::{ApiPath, Case, Lookup, Target};

/// Plans a gather case on `path`, or says why it cannot run.
pub(super) fn plan(path: ApiPath, case: &Case, l: &Lookup) -> Result<Plan, String> {
    let t = case.texture.target;
    // GLSL 4.50 for Vulkan has GLSL 4.50's gathers (SPIR-V OpImageDrefGather; the four offsets
    // of textureGatherOffsets need shaderImageGatherExtended, which the Vulkan worker checks).
    // WGSL textureGatherCompare: texture_depth_2d (with an optional const offset),
    // _2d_array (likewise), _cube and _cube_array; no four-offset form.
    if !matches!(
        path,
        ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
    ) {
        return Err(format!("{path} has no shadow textureGather"));
    }
    let kind = sampler_kind(case);
    if kind != SamplerKind::Shadow {
        return Err("textureGather here is the shadow form only (comparison enabled)".into());
    }
    let es_target = matches!(
        t,
        Target::T2d | Target::T2dArray | Target::Cube | Target::CubeArray
    );
    let gl_target = es_target || t == Target::Rect;
    if !(gl_target && (!matches!(path, ApiPath::Es300 | ApiPath::Wgsl) || es_target))
        || l.projective
    {
        return Err(format!(
            "{path} has no shadow textureGather on a {t} texture"
        ));
    }
    let i8s = |v: i32| i8::try_from(v).map_err(|_| format!("gather offset {v} out of range"));
    if path == ApiPath::Wgsl && l.gather.as_ref().is_some_and(|g| g.offsets.is_some()) {
        return Err(
            "WGSL has no textureGatherCompare with four offsets (WGSL texture built-in functions)"
                .into(),
        );
    }
    let offset = if path == ApiPath::Wgsl && l.offset != [0; 3] && !t.is_cube() {
        super::wgsl::offset(l.offset)?
    } else {
        [i8s(l.offset[0])?, i8s(l.offset[1])?]
    };
    let variable = !l.delivery.is_literal() && l.offset != [0; 3];
    let call = match l.gather.as_ref().and_then(|g| g.offsets) {
        Some(o) => {
            let mut k = [[0i8; 2]; 4];
            for (dst, src) in k.iter_mut().zip(o) {
                *dst = [i8s(src[0])?, i8s(src[1])?];
            }
            GatherCall::Offsets(k)
        }
        None if variable => GatherCall::Variable,
        None => GatherCall::Single,
    };
    if t.is_cube() && (offset != [0, 0] || call != GatherCall::Single) {
        return Err("textureGatherOffset(s) takes no cube sampler".into());
    }
    // λ plays no part; a case with a level of detail draws with the coordinate varying by its
    // gradients (unbatched), so that a level chosen by λ would show.
    // Outside the fragment stage there are no derivatives: the case's P alone.
    let lod = (l.lod + l.bias) as f32;
    let derivs = lod != 0.0 && l.stage == shadowcheck_model::Stage::Fragment;
    let key = ShaderKey {
        path,
        target: t,
        kind,
        form: LodForm::Gather(derivs),
        proj: false,
        mode: None,
        // A variable offset is the plan's `o`, not part of the program.
        offset: if variable { [0, 0] } else { offset },
        gather: Some(call),
        delivery: l.delivery,
        stage: l.stage,
    };
    let c = l.coord.map(|v| v as f32);
    let dref = l.dref as f32;
    // P as for the other shadow lookups (shaders::gather_call splits it into P and refZ).
    let p = match t {
        Target::T2d | Target::Rect => [c[0], c[1], dref, 1.0],
        Target::CubeArray => [c[0], c[1], c[2], l.layer as f32],
        _ => [c[0], c[1], c[2], dref],
    };
    let (dx, dy) = if derivs {
        gradients(case, l, lod)
    } else {
        ([0.0; 4], [0.0; 4])
    };
    Ok(Plan {
        key,
        p,
        x: dref,
        dx,
        dy,
        o: if variable {
            [i32::from(offset[0]), i32::from(offset[1])]
        } else {
            [0, 0]
        },
        note: super::delivery_note(
            match (path == ApiPath::Wgsl, derivs) {
                (true, true) => "textureGatherCompare, coordinate varying by the case's λ gradients (ignored by gather)".into(),
                (true, false) => "textureGatherCompare".into(),
                (false, true) => "textureGather, coordinate varying by the case's λ gradients (ignored by gather)".into(),
                (false, false) => "textureGather".into(),
            },
            l.delivery,
        ),
    })
}
