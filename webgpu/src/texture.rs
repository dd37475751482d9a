//! A case's texture as WebGPU objects: the `GPUTextureDescriptor` (format, size, levels), the
//! sampled view (dimension, mip range, the depth aspect) and the `GPUSamplerDescriptor` of the
//! sampler in effect (WebGPU), or why WebGPU cannot express it; and the texel values the
//! page writes with `frag_depth` (see `shadowcheck_plan::shaders::wgsl::TEXEL_WRITER`).
//! Whatever cannot be expressed is Skip with the reason, never drawn with other state and never
//! a call that would be a validation error.

use serde::Serialize;
use shadowcheck_model::{Case, CompareFunc, Filter, Format, Level, Target, Texels, Wrap};
use shadowcheck_plan::paths::sampler_kind;
use shadowcheck_plan::shaders::wgsl::{texel_point, view_dimension, TEXEL_FLOATS};
use shadowcheck_plan::SamplerKind;

/// The `GPUTextureFormat` of a model format (WebGPU "Depth-stencil formats"); `None`
/// for formats WebGPU has no depth format of (32-bit unorm, unsized depth, colour: a
/// `sampler_comparison` takes only a `texture_depth_*`, WGSL texture built-in functions, so a
/// colour texture never meets a compare state and such a case is not applicable).
pub fn format_name(f: Format) -> Option<&'static str> {
    Some(match f {
        Format::D16 => "depth16unorm",
        Format::D24 => "depth24plus",
        Format::D24S8 => "depth24plus-stencil8",
        Format::D32f => "depth32float",
        Format::D32fS8 => "depth32float-stencil8",
        Format::D32
        | Format::DepthUnsized
        | Format::R8
        | Format::Rgba8
        | Format::Rgb8
        | Format::Rgba4
        | Format::Rg8 => return None,
    })
}

/// Bytes per texel of the depth aspect copied to a buffer, for the formats whose depth is a
/// valid texel copy source (WebGPU: depth16unorm, depth32float and depth32float-stencil8;
/// depth24plus's representation is opaque, so it is never read back).
pub fn readback_bytes(f: Format) -> Option<u32> {
    match f {
        Format::D16 => Some(2),
        Format::D32f | Format::D32fS8 => Some(4),
        _ => None,
    }
}

/// `GPUSamplerDescriptor` (WebGPU), serialized as the page passes it to createSampler.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct SamplerDesc {
    pub address_mode_u: &'static str,
    pub address_mode_v: &'static str,
    pub address_mode_w: &'static str,
    pub mag_filter: &'static str,
    pub min_filter: &'static str,
    pub mipmap_filter: &'static str,
    pub lod_min_clamp: f32,
    pub lod_max_clamp: f32,
    pub compare: &'static str,
}

/// One level and layer of the texture (the render attachment its texels are written through):
/// its size and where its points are in the batch's point buffer (in points).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Subresource {
    pub level: u32,
    pub layer: u32,
    pub width: u32,
    pub height: u32,
    pub first: u32,
    pub count: u32,
}

/// A case's texture, view and sampler as the page creates them.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct TextureDesc {
    pub format: &'static str,
    pub width: u32,
    pub height: u32,
    /// depthOrArrayLayers.
    pub layers: u32,
    /// mipLevelCount: the case's levels, level base first (WebGPU has no base level: the view
    /// starts at the texture's level 0, which holds level base).
    pub levels: u32,
    pub has_stencil: bool,
    /// The sampled view's dimension and mip level count (from level 0).
    pub view: &'static str,
    pub view_levels: u32,
    pub sampler: SamplerDesc,
    /// Bytes per texel of level 0's depth copied back, when the format allows it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub readback: Option<u32>,
    pub subresources: Vec<Subresource>,
}

fn compare(f: CompareFunc) -> Option<&'static str> {
    Some(match f {
        CompareFunc::Never => "never",
        CompareFunc::Less => "less",
        CompareFunc::Equal => "equal",
        CompareFunc::Lequal => "less-equal",
        CompareFunc::Greater => "greater",
        CompareFunc::Notequal => "not-equal",
        CompareFunc::Gequal => "greater-equal",
        CompareFunc::Always => "always",
        CompareFunc::LequalRSgix | CompareFunc::GequalRSgix => return None,
    })
}

fn address(w: Wrap) -> Result<&'static str, String> {
    Ok(match w {
        Wrap::Repeat => "repeat",
        Wrap::ClampToEdge => "clamp-to-edge",
        Wrap::MirroredRepeat => "mirror-repeat",
        Wrap::ClampToBorder | Wrap::MirrorClampToEdge | Wrap::Clamp => {
            return Err(format!(
                "wrap {w} is no GPUAddressMode (WebGPU: clamp-to-edge, repeat, mirror-repeat)"
            ))
        }
    })
}

fn filter(f: Filter) -> &'static str {
    match f {
        Filter::Nearest | Filter::NearestMipmapNearest | Filter::NearestMipmapLinear => "nearest",
        Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear => "linear",
    }
}

/// The sampler descriptor and the number of view levels of `case` (the sampler in effect), or
/// why WebGPU has none like it. A GL minification filter without mipmapping samples level base
/// only: a view of one level, as the Vulkan worker does. lodMinClamp is max(min_lod, 0) (WebGPU
/// requires lodMinClamp >= 0; any λ <= 0 selects level base and the magnification filter either
/// way) and lodMaxClamp max(max_lod, lodMinClamp) (it must not be below lodMinClamp).
pub fn sampler(case: &Case) -> Result<(SamplerDesc, u32), String> {
    let s = case.sampler.in_effect();
    if sampler_kind(case) != SamplerKind::Shadow {
        return Err("the wgsl path samples depth with comparison only (sampler_comparison)".into());
    }
    if s.depth_texture_mode.is_some() {
        return Err("DEPTH_TEXTURE_MODE has no WebGPU equivalent".into());
    }
    if s.lod_bias != 0.0 {
        return Err("GPUSamplerDescriptor has no LOD bias (WebGPU)".into());
    }
    if s.mag_filter.is_mipmap() {
        return Err(format!(
            "magnification filter {} is no GPUFilterMode",
            s.mag_filter
        ));
    }
    let compare = compare(s.compare_func)
        .ok_or_else(|| format!("{} is no GPUCompareFunction", s.compare_func))?;
    let t = case.texture.target;
    // Cube maps sample seamlessly whatever the address modes; an array's layer is an integer
    // index, clamped, never wrapped. Unused coordinates get clamp-to-edge.
    let used = [
        !t.is_cube(),
        matches!(t, Target::T2d | Target::T2dArray),
        false,
    ];
    let mut modes = ["clamp-to-edge"; 3];
    for (i, w) in [s.wrap_s, s.wrap_t, s.wrap_r].into_iter().enumerate() {
        if used[i] {
            modes[i] = address(w)?;
        }
    }
    let levels = case.texture.levels.len() as u32;
    let view_levels = if s.min_filter.is_mipmap() {
        match s.max_level {
            Some(m) if m < case.texture.base_level => {
                return Err(
                    "TEXTURE_MAX_LEVEL below the base level: WebGPU has no incomplete texture"
                        .into(),
                )
            }
            Some(m) => levels.min(m - case.texture.base_level + 1),
            None => levels,
        }
    } else {
        1
    };
    if s.min_lod.is_nan() || s.max_lod.is_nan() {
        return Err(format!(
            "LOD range [{}, {}] is not one WebGPU takes",
            s.min_lod, s.max_lod
        ));
    }
    // WebIDL `float` members are finite: an infinite bound is the largest finite one (the view
    // has far fewer levels either way).
    let lod_min_clamp = s.min_lod.clamp(0.0, f32::MAX);
    let lod_max_clamp = s.max_lod.clamp(lod_min_clamp, f32::MAX);
    let desc = SamplerDesc {
        address_mode_u: modes[0],
        address_mode_v: modes[1],
        address_mode_w: modes[2],
        mag_filter: filter(s.mag_filter),
        min_filter: filter(s.min_filter),
        mipmap_filter: match s.min_filter {
            Filter::NearestMipmapLinear | Filter::LinearMipmapLinear => "linear",
            _ => "nearest",
        },
        lod_min_clamp,
        lod_max_clamp,
        compare,
    };
    Ok((desc, view_levels))
}

/// Checks that the levels of `case` form a WebGPU texture: every level the mip level of level
/// base (WebGPU "mipLevelCount": level i is max(1, size >> i)), the layers the same in
/// every level, a cube square with 6 layers per cube.
fn shape(case: &Case) -> Result<(u32, u32, u32), String> {
    let t = &case.texture;
    let base = t.levels.first().ok_or("no levels")?;
    let (w, h, layers) = (base.width, base.height, base.layers);
    if w == 0 || h == 0 || layers == 0 {
        return Err("an empty level".into());
    }
    for (i, l) in t.levels.iter().enumerate() {
        let want = ((w >> i).max(1), (h >> i).max(1), layers);
        if (l.width, l.height, l.layers) != want {
            return Err(format!(
                "level base+{i} is {}x{}x{}, not the mip level {}x{}x{} WebGPU textures have",
                l.width, l.height, l.layers, want.0, want.1, want.2
            ));
        }
        if l.depth.len() != l.texel_count() {
            return Err(format!(
                "level base+{i}: texel count does not match its size"
            ));
        }
    }
    if t.target.is_cube() && (w != h || layers % 6 != 0) {
        return Err("a cube level must be square with 6 layers per cube".into());
    }
    if !t.target.is_array() && !t.target.is_cube() && layers != 1 {
        return Err(format!("{} texture with {layers} layers", t.target));
    }
    if t.target == Target::Cube && layers != 6 {
        return Err(format!("a cube texture with {layers} layers"));
    }
    Ok((w, h, layers))
}

/// The value a texel is written as: the f32 nearest to k / (2^n - 1) for an n-bit unorm texel k
/// (its conversion back to the format gives k), the float itself for a float format (the
/// fragment's depth is clamped to the viewport's [0, 1], WebGPU "Fragment Processing").
pub fn texel_values(format: Format, level: &Level) -> Result<Vec<f32>, String> {
    match (&level.depth, format.unorm_bits(), format) {
        (Texels::Unorm(v), Some(bits @ (16 | 24)), _) => {
            let max = (1u32 << bits) - 1;
            v.iter()
                .map(|&k| {
                    if k > max {
                        Err(format!("{format} texel {k} above {max}"))
                    } else {
                        Ok((k as f64 / max as f64) as f32)
                    }
                })
                .collect()
        }
        (Texels::Float(v), None, Format::D32f | Format::D32fS8) => Ok(v.clone()),
        _ => Err(format!("texel encoding does not match format {format}")),
    }
}

/// The texture of `case` as the page creates it, its texel points appended to `points` (three
/// floats a point: [`TEXEL_FLOATS`]), or why WebGPU cannot express it.
pub fn describe(case: &Case, points: &mut Vec<f32>) -> Result<TextureDesc, String> {
    let f = case.texture.format;
    let format = format_name(f).ok_or_else(|| format!("format {f} has no WebGPU depth format"))?;
    let view = view_dimension(case.texture.target).ok_or_else(|| {
        format!(
            "WebGPU has no depth texture of target {}",
            case.texture.target
        )
    })?;
    let (width, height, layers) = shape(case)?;
    let (sampler, view_levels) = sampler(case)?;
    let mut values = Vec::with_capacity(case.texture.levels.len());
    for level in &case.texture.levels {
        values.push(texel_values(f, level)?);
    }
    let mut subresources = Vec::new();
    for (i, (level, values)) in case.texture.levels.iter().zip(&values).enumerate() {
        let per_layer = (level.width * level.height) as usize;
        for layer in 0..level.layers {
            let first = (points.len() / TEXEL_FLOATS) as u32;
            let at = layer as usize * per_layer;
            for (k, v) in values[at..at + per_layer].iter().enumerate() {
                let (x, y) = (k as u32 % level.width, k as u32 / level.width);
                let [px, py] = texel_point(x, y, level.width, level.height);
                points.extend_from_slice(&[px, py, *v]);
            }
            subresources.push(Subresource {
                level: i as u32,
                layer,
                width: level.width,
                height: level.height,
                first,
                count: per_layer as u32,
            });
        }
    }
    Ok(TextureDesc {
        format,
        width,
        height,
        layers,
        levels: case.texture.levels.len() as u32,
        has_stencil: f.has_stencil(),
        view,
        view_levels,
        sampler,
        readback: readback_bytes(f),
        subresources,
    })
}

/// The texels of level 0 read back (`bytes`, tightly packed, the format's copy footprint per
/// texel: [`readback_bytes`]) in the fixture's encoding: depth16unorm as unorm integers, the
/// 32-bit float formats as floats.
pub fn decode(format: Format, bytes: &[u8]) -> Option<Texels> {
    match format {
        Format::D16 => Some(Texels::Unorm(
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_le_bytes([c[0], c[1]]) as u32)
                .collect(),
        )),
        Format::D32f | Format::D32fS8 => Some(Texels::Float(
            bytes
                .chunks_exact(4)
                .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect(),
        )),
        _ => None,
    }
}

#[cfg(test)]
mod tests;
