//! Structural validation of a case. Anything a backend or the oracle would choke on is rejected here
//! with an error naming the case and the field. (Semantic legality, e.g. a compare function a spec
//! does not define, is the oracle's business: it answers with that spec's GL error.)

use crate::{ApiPath, Case, Level, ModelError, Target, Texels};

/// Largest texel count accepted for one level (16 Mi texels); larger is treated as absurd input.
pub const MAX_TEXELS_PER_LEVEL: usize = 1 << 24;
/// Largest width, height or layer count.
pub const MAX_DIMENSION: u32 = 16384;

fn invalid(case: &Case, field: impl Into<String>, msg: impl Into<String>) -> ModelError {
    ModelError::Invalid {
        case: case.id.clone(),
        field: field.into(),
        msg: msg.into(),
    }
}

/// Whether `c` may appear in a case id. A test name (`<id>@<api>`) is a field of results.csv,
/// failures.csv and baselines, which deqp-runner splits on every comma without unquoting, so ids
/// hold no comma, quote, whitespace or control character (as dEQP and piglit names never do).
pub fn id_char_ok(c: char) -> bool {
    !(c == ',' || c == '"' || c == '\'' || c.is_whitespace() || c.is_control())
}

/// Checks the structure of `case`: its id and API paths, texture, sampler, lookup (offset and
/// sweep included), in that order; the first error found is returned.
pub fn validate(case: &Case) -> Result<(), ModelError> {
    validate_id_and_api(case)?;
    validate_texture(case)?;
    validate_sampler(case)?;
    validate_lookup(case)?;
    validate_sweep(case)
}

/// A non-empty id a test name can hold, and distinct API paths, at least one.
fn validate_id_and_api(case: &Case) -> Result<(), ModelError> {
    if case.id.is_empty() {
        return Err(invalid(case, "id", "empty id"));
    }
    if let Some(c) = case.id.chars().find(|c| !id_char_ok(*c)) {
        return Err(invalid(
            case,
            "id",
            format!(
                "{:?} in the id: test names are CSV fields that need no quoting \
                 (no commas, quotes, whitespace or control characters)",
                c
            ),
        ));
    }
    if case.api.is_empty() {
        return Err(invalid(case, "api", "no API path"));
    }
    for (i, a) in case.api.iter().enumerate() {
        if case.api[..i].contains(a) {
            return Err(invalid(
                case,
                format!("api[{i}]"),
                format!("duplicate API path `{}`", a.key()),
            ));
        }
    }
    Ok(())
}

/// The level count and base level, then each level ([`validate_level`]).
fn validate_texture(case: &Case) -> Result<(), ModelError> {
    let tex = &case.texture;
    if tex.levels.is_empty() {
        return Err(invalid(case, "texture.levels", "no levels"));
    }
    if tex.levels.len() > 16 {
        return Err(invalid(
            case,
            "texture.levels",
            format!("{} levels (at most 16)", tex.levels.len()),
        ));
    }
    if tex.base_level > 15 {
        return Err(invalid(
            case,
            "texture.base_level",
            format!("{} (at most 15)", tex.base_level),
        ));
    }
    if tex.target.is_rect() && tex.levels.len() > 1 {
        return Err(invalid(
            case,
            "texture.levels",
            "rectangle textures have exactly one level",
        ));
    }
    for (i, lvl) in tex.levels.iter().enumerate() {
        validate_level(case, i, lvl)?;
    }
    Ok(())
}

/// One level: its size within bounds and of the target's shape, then its texels
/// ([`validate_texels`]).
fn validate_level(case: &Case, i: usize, lvl: &Level) -> Result<(), ModelError> {
    let tex = &case.texture;
    let f = |name: &str| format!("texture.levels[{i}].{name}");
    for (name, v) in [
        ("width", lvl.width),
        ("height", lvl.height),
        ("layers", lvl.layers),
    ] {
        if v == 0 || v > MAX_DIMENSION {
            return Err(invalid(
                case,
                f(name),
                format!("{v} is outside 1..={MAX_DIMENSION}"),
            ));
        }
    }
    let n = lvl.texel_count();
    if n > MAX_TEXELS_PER_LEVEL {
        return Err(invalid(
            case,
            f("width"),
            format!("{n} texels in one level (at most {MAX_TEXELS_PER_LEVEL})"),
        ));
    }
    match tex.target {
        Target::T1d | Target::T1dArray if lvl.height != 1 => {
            return Err(invalid(case, f("height"), "1D targets have height 1"));
        }
        Target::Cube | Target::CubeArray => {
            if lvl.width != lvl.height {
                return Err(invalid(case, f("width"), "cube faces must be square"));
            }
            if !lvl.layers.is_multiple_of(6) {
                return Err(invalid(
                    case,
                    f("layers"),
                    "cube layers must be a multiple of 6",
                ));
            }
            if tex.target == Target::Cube && lvl.layers != 6 {
                return Err(invalid(case, f("layers"), "a cube map has 6 faces"));
            }
        }
        Target::T1d | Target::T2d | Target::Rect if lvl.layers != 1 => {
            return Err(invalid(case, f("layers"), "non-array targets have 1 layer"));
        }
        _ => {}
    }
    validate_texels(case, i, lvl)
}

/// One level's depth values (as many as texels, stored as the format stores them, in range) and
/// stencil values (only for a format with stencil, as many as texels).
fn validate_texels(case: &Case, i: usize, lvl: &Level) -> Result<(), ModelError> {
    let tex = &case.texture;
    let f = |name: &str| format!("texture.levels[{i}].{name}");
    let n = lvl.texel_count();
    let bits = tex.format.unorm_bits();
    if lvl.depth.len() != n {
        return Err(invalid(
            case,
            f("depth"),
            format!("{} values for {} texels", lvl.depth.len(), n),
        ));
    }
    let multi = tex.format.is_multi_colour();
    match (&lvl.depth, bits) {
        (Texels::Colour(v), Some(b)) if multi => {
            let max = (1u32 << b) - 1;
            let n = tex.format.components();
            for (j, c) in v.iter().enumerate() {
                for (k, &x) in c.iter().enumerate() {
                    let bad = if k < n {
                        (x > max).then(|| format!("{x} exceeds {b}-bit unorm maximum {max}"))
                    } else {
                        (x != 0).then(|| format!("component {k} is {x}, but format {} has {n} components (an absent component is 0)", tex.format))
                    };
                    if let Some(why) = bad {
                        return Err(invalid(case, format!("{}[{j}][{k}]", f("depth")), why));
                    }
                }
            }
        }
        (Texels::Colour(_), _) => {
            return Err(invalid(
                case,
                f("depth"),
                format!(
                    "format {} is not a colour format of several components, got colour texels",
                    tex.format
                ),
            ));
        }
        (_, Some(_)) if multi => {
            return Err(invalid(
                case,
                f("depth"),
                format!(
                    "format {} stores colour texels ({{\"colour\": [[r,g,b,a], ...]}})",
                    tex.format
                ),
            ));
        }
        (Texels::Unorm(v), Some(b)) => {
            let max = if b == 32 { u32::MAX } else { (1u32 << b) - 1 };
            if let Some((j, x)) = v.iter().enumerate().find(|(_, x)| **x > max) {
                return Err(invalid(
                    case,
                    format!("{}[{j}]", f("depth")),
                    format!("{x} exceeds {b}-bit unorm maximum {max}"),
                ));
            }
        }
        (Texels::Float(v), None) => {
            if let Some((j, x)) = v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
                return Err(invalid(
                    case,
                    format!("{}[{j}]", f("depth")),
                    format!("{x} is not finite"),
                ));
            }
        }
        (Texels::Unorm(_), None) => {
            return Err(invalid(
                case,
                f("depth"),
                format!("format {} stores floats, got unorm integers", tex.format),
            ));
        }
        (Texels::Float(_), Some(_)) => {
            return Err(invalid(
                case,
                f("depth"),
                format!("format {} stores unorm integers, got floats", tex.format),
            ));
        }
    }
    match (&lvl.stencil, tex.format.has_stencil()) {
        (Some(s), true) if s.len() != n => {
            return Err(invalid(
                case,
                f("stencil"),
                format!("{} values for {} texels", s.len(), n),
            ));
        }
        (Some(_), false) => {
            return Err(invalid(
                case,
                f("stencil"),
                format!("format {} has no stencil", tex.format),
            ));
        }
        _ => {}
    }
    Ok(())
}

/// The sampler's LOD range, bias, fail value and border (and the sampler object's) are finite.
fn validate_sampler(case: &Case) -> Result<(), ModelError> {
    let s = &case.sampler;
    for (name, v) in [
        ("min_lod", s.min_lod),
        ("max_lod", s.max_lod),
        ("lod_bias", s.lod_bias),
    ] {
        if !v.is_finite() {
            return Err(invalid(
                case,
                format!("sampler.{name}"),
                format!("{v} is not finite"),
            ));
        }
    }
    if let Some(v) = s.fail_value {
        if !v.is_finite() {
            return Err(invalid(
                case,
                "sampler.fail_value",
                format!("{v} is not finite"),
            ));
        }
    }
    if let Some((j, v)) = s.border.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(invalid(
            case,
            format!("sampler.border[{j}]"),
            format!("{v} is not finite"),
        ));
    }
    if let Some(o) = &s.sampler_object {
        let floats = [
            ("min_lod", o.min_lod),
            ("max_lod", o.max_lod),
            ("lod_bias", o.lod_bias),
        ];
        let border = o.border.iter().enumerate().map(|(j, v)| (j, *v));
        let named = floats.into_iter().map(|(n, v)| (n.to_string(), v));
        let all = named.chain(border.map(|(j, v)| (format!("border[{j}]"), v)));
        for (name, v) in all {
            if !v.is_finite() {
                return Err(invalid(
                    case,
                    format!("sampler.sampler_object.{name}"),
                    format!("{v} is not finite"),
                ));
            }
        }
    }
    Ok(())
}

/// The lookup's LOD, bias and layer are finite, a projective q is not 0, an offset is legal
/// ([`validate_offset`]).
fn validate_lookup(case: &Case) -> Result<(), ModelError> {
    let l = &case.lookup;
    for (name, v) in [("lod", l.lod), ("bias", l.bias), ("layer", l.layer)] {
        if !v.is_finite() {
            return Err(invalid(
                case,
                format!("lookup.{name}"),
                format!("{v} is not finite"),
            ));
        }
    }
    if l.projective && l.coord[3] == 0.0 {
        return Err(invalid(
            case,
            "lookup.coord[3]",
            "projective lookup with q = 0",
        ));
    }
    if l.offset != [0; 3] {
        validate_offset(case)?;
    }
    lookup_dims::validate_delivery(case)?;
    lookup_dims::validate_stage(case)
}

/// A sweep's points: a bounded number, on a filtered lookup (a gather answers four values, a
/// point one), each with a usable projective divisor.
fn validate_sweep(case: &Case) -> Result<(), ModelError> {
    if case.sweep.is_empty() {
        return Ok(());
    }
    if case.sweep.len() > crate::MAX_SWEEP_POINTS {
        return Err(invalid(
            case,
            "sweep",
            format!(
                "{} points (at most {})",
                case.sweep.len(),
                crate::MAX_SWEEP_POINTS
            ),
        ));
    }
    if case.lookup.gather.is_some() {
        return Err(invalid(
            case,
            "sweep",
            "a gather lookup has no sweep (each point answers one value)",
        ));
    }
    for (k, p) in case.sweep.iter().enumerate() {
        if case.lookup.projective && p.coord[3] == 0.0 {
            return Err(invalid(
                case,
                format!("sweep[{k}].coord[3]"),
                "projective lookup with q = 0",
            ));
        }
    }
    Ok(())
}

/// Smallest MIN_PROGRAM_TEXEL_OFFSET and largest MAX_PROGRAM_TEXEL_OFFSET every GL 3.0+ / ES 3.0+
/// implementation supports (GL 4.6 Table 23.55, ES 3.2 Table 21.41: -8 and 7; Vulkan 1.3's
/// required limits minTexelOffset and maxTexelOffset are the same, and WGSL makes any other
/// offset a shader-creation error); outside them the
/// lookup is undefined (GL 4.6 §8.14.2), so a fixture may not ask for it.
pub const TEXEL_OFFSET_RANGE: std::ops::RangeInclusive<i32> = -8..=7;

/// A texel offset needs a lookup function that takes one (GLSL >= 1.30, GLSL ES 3.00), a target
/// with texel offsets (not cube maps), zeros in the components the target ignores, and values
/// every implementation supports.
fn validate_offset(case: &Case) -> Result<(), ModelError> {
    let o = case.lookup.offset;
    if let Some(api) = case.api.iter().find(|a| {
        !matches!(
            a,
            ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
        )
    }) {
        return Err(invalid(
            case,
            "lookup.offset",
            format!("API path `{}` has no lookup function with a texel offset (GLSL >= 1.30, GLSL ES 3.00, SPIR-V's Offset operands and WGSL's offset overloads only)", api.key()),
        ));
    }
    let used = match case.texture.target {
        Target::Cube | Target::CubeArray => 0,
        Target::T1d | Target::T1dArray => 1,
        Target::T2d | Target::Rect | Target::T2dArray => 2,
    };
    if used == 0 {
        return Err(invalid(
            case,
            "lookup.offset",
            "cube map lookups take no texel offset",
        ));
    }
    if let Some(j) = (used..3).find(|&j| o[j] != 0) {
        return Err(invalid(
            case,
            format!("lookup.offset[{j}]"),
            format!("{} but the target has no such coordinate (must be 0)", o[j]),
        ));
    }
    if let Some(j) = (0..3).find(|&j| !TEXEL_OFFSET_RANGE.contains(&o[j])) {
        return Err(invalid(
            case,
            format!("lookup.offset[{j}]"),
            format!(
                "{} is outside {}..={}, the range every implementation supports",
                o[j],
                TEXEL_OFFSET_RANGE.start(),
                TEXEL_OFFSET_RANGE.end()
            ),
        ));
    }
    Ok(())
}

mod lookup_dims;
pub use lookup_dims::{COMPUTE_PATHS, DELIVERY_PATHS, STAGE_PATHS};
#[cfg(test)]
mod tests;
