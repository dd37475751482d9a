//! WGSL, the `wgsl` path's program text (the WebGPU worker's shader modules). One module per
//! [`ShaderKey`]: for a fragment-stage key a vertex entry point `vs` and a fragment entry point
//! `fs`, for a compute-stage key a compute entry point `cs` only (see the last items):
//! - the depth texture is `t` (`texture_depth_2d`, `_2d_array`, `_cube` or `_cube_array`), group
//!   0 binding 0 (WGSL §6.6.6 "Depth Texture Types"), and the comparison sampler `s`
//!   (`sampler_comparison`), group 0 binding 1;
//! - each lookup is one instance of a six-vertex draw: instance `i` (WGSL §13.3.1.1.6
//!   `instance_index`, which counts from the draw's firstInstance) is slot `i` of
//!   [`crate::layout`], two triangles over its 2x2 pixel quad; the lookup's values are
//!   per-instance vertex attributes ([`INSTANCE_ATTRIBS`]) passed to the fragment shader with
//!   `@interpolate(flat, either)` (WGSL §13.3.1.4; every vertex of a lookup carries its values, so whichever
//!   vertex provides them, they are the lookup's, bit for bit; `either` is also what WebGPU's
//!   compatibility mode accepts);
//! - the lookup: `textureSampleCompareLevel` for [`LodForm::Lod`] (level 0 only: the plan uses
//!   it only where that is the case's level, `paths::wgsl`), `textureSampleCompare` for
//!   [`LodForm::Implicit`] (implicit derivatives, fragment stage, uniform control flow: the
//!   shader has no branch), `textureGatherCompare` for a gather; an offset is a const-expression
//!   `vec2i(a, b)` in the call (one module per offset);
//! - with implicit derivatives P varies across the quad by the plan's gradients and is exactly
//!   the case's P at the quad's written pixel, as in the GLSL programs (`super::vulkan`);
//! - a compute-stage key (`textureSampleCompareLevel` at level 0 or `textureGatherCompare`, the
//!   forms without derivatives) is `@compute @workgroup_size(1) fn cs`: one workgroup per lookup,
//!   as the GLSL compute programs (`super::stage`); it reads its slot's values bit for bit from
//!   the instance floats bound as a read-only storage buffer and writes its RGBA to a storage
//!   buffer, one vec4f per slot ([`COMPUTE_BINDINGS`]), which the page copies into the slot's
//!   pixel of the read-back image (storage buffers in the compute stage are in core WebGPU and
//!   in compatibility mode alike, whose maxStorageBuffersIn{Vertex,Fragment}Stage limits only the
//!   other stages).
//!
//! WebGPU's framebuffer origin is the top left and its normalized device y points up (WebGPU
//! §3.3 "Coordinate Systems": framebuffer y down; the viewport transform flips NDC y), so the
//! vertex shader writes y = 1 - corner.y / quads: slot s covers framebuffer rows 2*(s / quads)
//! and the next, and row r of the image copied to a buffer (copyTextureToBuffer, rows in
//! increasing y) is row r of [`crate::layout`]'s pixels, as for Vulkan.
//!
//! [`TEXEL_WRITER`] is the module that writes texels: no texel copy writes depth24plus or the
//! depth of depth32float and the combined formats (WebGPU "Depth-stencil formats":
//! only depth16unorm's depth is a valid texel copy destination), so every format's texels are
//! points whose fragments write `@builtin(frag_depth)`, one way for all.

use crate::{GatherCall, LodForm, Plan, ShaderKey};
use shadowcheck_model::Target;

/// Floats per lookup in the instance buffer: P, dx, dy, x ([`INSTANCE_ATTRIBS`]).
pub const INSTANCE_FLOATS: usize = 13;

/// The per-instance vertex attributes: (shader location, WebGPU vertex format, offset in
/// floats). P, the gradients dx and dy, and `x` (a cube-array lookup's reference).
pub const INSTANCE_ATTRIBS: [(u32, &str, usize); 4] = [
    (0, "float32x4", 0),
    (1, "float32x4", 4),
    (2, "float32x4", 8),
    (3, "float32", 12),
];

/// The instance values of a lookup, laid out as [`INSTANCE_ATTRIBS`] says.
pub fn instance_values(plan: &Plan) -> [f32; INSTANCE_FLOATS] {
    let mut v = [0.0; INSTANCE_FLOATS];
    v[0..4].copy_from_slice(&plan.p);
    v[4..8].copy_from_slice(&plan.dx);
    v[8..12].copy_from_slice(&plan.dy);
    v[12] = plan.x;
    v
}

/// The WGSL texture type of a target (WGSL §6.6.6 "Depth Texture Types"); `None` for targets
/// WGSL has no depth texture of (1D, 1D arrays, rectangles).
pub fn texture_type(target: Target) -> Option<&'static str> {
    match target {
        Target::T2d => Some("texture_depth_2d"),
        Target::T2dArray => Some("texture_depth_2d_array"),
        Target::Cube => Some("texture_depth_cube"),
        Target::CubeArray => Some("texture_depth_cube_array"),
        Target::T1d | Target::T1dArray | Target::Rect => None,
    }
}

/// The `GPUTextureViewDimension` a target is sampled through (WebGPU "GPUTextureViewDimension").
pub fn view_dimension(target: Target) -> Option<&'static str> {
    match target {
        Target::T2d => Some("2d"),
        Target::T2dArray => Some("2d-array"),
        Target::Cube => Some("cube"),
        Target::CubeArray => Some("cube-array"),
        Target::T1d | Target::T1dArray | Target::Rect => None,
    }
}

/// The lookup call on `t` and `s` (WGSL texture built-in functions). P comes from `p` (varied across the quad for
/// implicit derivatives), the array index from the flat `v.p` (an integer, never varied), the
/// reference from P or, on cube arrays, from `v.x` (the plan's layout, `paths::shader_values`).
fn call(key: &ShaderKey) -> String {
    let (coords, index, dref) = match key.target {
        Target::T2d => ("p.xy", None, "p.z"),
        Target::T2dArray => ("p.xy", Some("i32(v.p.z)"), "p.w"),
        Target::Cube => ("p.xyz", None, "p.w"),
        _ => ("p.xyz", Some("i32(v.p.w)"), "v.x"),
    };
    let f = match (key.gather, key.form) {
        (Some(_), _) => "textureGatherCompare",
        (None, LodForm::Lod) => "textureSampleCompareLevel",
        (None, _) => "textureSampleCompare",
    };
    let index = index.map(|i| format!(", {i}")).unwrap_or_default();
    let offset = match key.offset {
        [0, 0] => String::new(),
        [a, b] => format!(", vec2i({a}, {b})"),
    };
    format!("{f}(t, s, {coords}{index}, {dref}{offset})")
}

/// The module of `key` on a framebuffer `fb_width` pixels wide (`crate::layout::FB_SIZE`), or
/// why WGSL has no such lookup (a target without a depth texture type, a sampler that is not a
/// comparison, a projective or biased form, four gather offsets).
pub fn module(key: &ShaderKey, fb_width: i32) -> Result<String, String> {
    let ty = texture_type(key.target).ok_or_else(|| {
        format!(
            "WGSL has no depth texture type for a {} texture",
            key.target
        )
    })?;
    if key.kind != crate::SamplerKind::Shadow {
        return Err("the wgsl path samples with comparison only (sampler_comparison)".into());
    }
    if key.proj {
        return Err("WGSL has no projective lookup".into());
    }
    match (key.gather, key.form) {
        (Some(GatherCall::Offsets(_)), _) => {
            return Err("WGSL has no textureGatherCompare with four offsets".into())
        }
        (Some(_), LodForm::Gather(_)) | (None, LodForm::Lod) | (None, LodForm::Implicit(false)) => {
        }
        (_, form) => return Err(format!("WGSL has no compare lookup of the form {form:?}")),
    }
    if key.offset != [0, 0] && key.target.is_cube() {
        return Err("WGSL cube lookups take no offset".into());
    }
    let quads = fb_width / 2;
    if key.stage == shadowcheck_model::Stage::Compute {
        return compute_module(key, ty);
    }
    if key.stage != shadowcheck_model::Stage::Fragment {
        return Err(format!("the wgsl path draws no {}-stage lookup", key.stage));
    }
    let implicit = matches!(key.form, LodForm::Implicit(_) | LodForm::Gather(true));
    let vary = if implicit {
        "\n  let c = vec2f((vec2u(v.pos.xy) / 2u) * 2u) + 0.5;\n  p = p + (v.pos.x - c.x) * v.dx + (v.pos.y - c.y) * v.dy;"
    } else {
        ""
    };
    let store = if key.gather.is_some() {
        format!("return {};", call(key))
    } else {
        format!("return vec4f({}, 0.0, 0.0, 1.0);", call(key))
    };
    let attribs: String = ["p: vec4f", "dx: vec4f", "dy: vec4f", "x: f32"]
        .iter()
        .zip(INSTANCE_ATTRIBS)
        .map(|(decl, (loc, _, _))| format!(",\n  @location({loc}) {decl}"))
        .collect();
    Ok(format!(
        "@group(0) @binding(0) var t: {ty};\n\
         @group(0) @binding(1) var s: sampler_comparison;\n\
         \n\
         {VALUES}\
         \n\
         @vertex\n\
         fn vs(@builtin(vertex_index) vi: u32, @builtin(instance_index) slot: u32{attribs}) -> Values {{\n  \
           var corners = array<vec2f, 6>({CORNERS});\n  \
           let corner = 2.0 * vec2f(f32(slot % {quads}u), f32(slot / {quads}u)) + 2.0 * corners[vi];\n  \
           var o: Values;\n  \
           o.pos = vec4f(corner.x / {quads}.0 - 1.0, 1.0 - corner.y / {quads}.0, 0.0, 1.0);\n  \
           o.p = p;\n  o.dx = dx;\n  o.dy = dy;\n  o.x = x;\n  \
           return o;\n\
         }}\n\
         \n\
         @fragment\n\
         fn fs(v: Values) -> @location(0) vec4f {{\n  \
           var p = v.p;{vary}\n  \
           {store}\n\
         }}\n"
    ))
}

/// The module of a compute-stage key: entry point `cs` only (WGSL §13.3.2 "Compute Shaders and
/// Workgroups"), one workgroup of one invocation per lookup, as the GLSL compute programs do
/// (`super::stage`): the lookup of slot `first.x + workgroup_id.x` reads its values bit for bit
/// from `lookups` ([`COMPUTE_BINDINGS`]: the instance buffer's floats, [`INSTANCE_FLOATS`] a slot,
/// laid out as [`INSTANCE_ATTRIBS`] says) and writes its RGBA to `results[slot]`, which the page
/// copies into the slot's pixel of the read-back image. Only the forms that need no derivatives
/// (`textureSampleCompareLevel`, `textureGatherCompare`: WGSL "may be invoked in any shader
/// stage"); `textureSampleCompare` is fragment-only (WGSL §17.7 "Texture Built-in Functions").
fn compute_module(key: &ShaderKey, ty: &str) -> Result<String, String> {
    if !matches!(key.form, LodForm::Lod | LodForm::Gather(false)) {
        return Err(format!(
            "a WGSL compute shader has no derivatives: no compare lookup of the form {:?}",
            key.form
        ));
    }
    let value = if key.gather.is_some() {
        call(key)
    } else {
        format!("vec4f({}, 0.0, 0.0, 1.0)", call(key))
    };
    let n = INSTANCE_FLOATS;
    let x = INSTANCE_ATTRIBS[3].2;
    let [(_, lookups, _), (_, results, _), (_, first, _)] = COMPUTE_BINDINGS;
    Ok(format!(
        "@group(0) @binding(0) var t: {ty};\n\
         @group(0) @binding(1) var s: sampler_comparison;\n\
         @group(0) @binding({lookups}) var<storage, read> lookups: array<f32>;\n\
         @group(0) @binding({results}) var<storage, read_write> results: array<vec4f>;\n\
         @group(0) @binding({first}) var<uniform> first: vec4u;\n\
         \n\
         struct Lookup {{\n  p: vec4f,\n  x: f32,\n}}\n\
         \n\
         @compute @workgroup_size(1)\n\
         fn cs(@builtin(workgroup_id) id: vec3u) {{\n  \
           let slot = first.x + id.x;\n  \
           let i = {n}u * slot;\n  \
           let v = Lookup(vec4f(lookups[i], lookups[i + 1u], lookups[i + 2u], lookups[i + 3u]), lookups[i + {x}u]);\n  \
           let p = v.p;\n  \
           results[slot] = {value};\n\
         }}\n"
    ))
}

/// The compute module's bindings beyond `t` (0) and `s` (1), group 0: (name, binding, the
/// `GPUBufferBindingType` the page's layout gives it). `lookups`: the job's instance values
/// (read-only storage); `results`: one vec4f per slot of the job (storage); `first`: the
/// dispatch's first slot in `.x` (uniform, one 256-byte aligned entry per dispatch: WebGPU
/// "minUniformBufferOffsetAlignment").
pub const COMPUTE_BINDINGS: [(&str, u32, &str); 3] = [
    ("lookups", 2, "read-only-storage"),
    ("results", 3, "storage"),
    ("first", 4, "uniform"),
];

/// The values passed from the vertex to the fragment stage.
const VALUES: &str = "struct Values {\n  @builtin(position) pos: vec4f,\n  @location(0) @interpolate(flat, either) p: vec4f,\n  @location(1) @interpolate(flat, either) dx: vec4f,\n  @location(2) @interpolate(flat, either) dy: vec4f,\n  @location(3) @interpolate(flat, either) x: f32,\n}\n";

/// The quad's corners as two triangles (`crate::layout::CORNERS`).
const CORNERS: &str = "vec2f(0.0, 0.0), vec2f(1.0, 0.0), vec2f(0.0, 1.0), vec2f(0.0, 1.0), vec2f(1.0, 0.0), vec2f(1.0, 1.0)";

/// Floats per texel point of [`TEXEL_WRITER`]: its position (normalized device x, y: the centre
/// of the texel's pixel in the render attachment, a view of one level and one layer) and its
/// depth.
pub const TEXEL_FLOATS: usize = 3;

/// The module that writes texels (entry points `vs` and `fs`): a `point-list` draw, one point per
/// texel (WebGPU "Point Rasterization": a point is a one-pixel square centred on its position, so
/// it covers the pixel whose centre it is at), whose fragment writes the texel's depth as
/// `@builtin(frag_depth)` (WGSL §13.3.1.1.2), with depthCompare "always" and depth writes on. The value of a depth16unorm or
/// depth24plus texel k is the f32 nearest to k / (2^n - 1); the attachment's conversion to its
/// format gives k back (the worker checks what it can read back).
pub const TEXEL_WRITER: &str = "struct Texel {\n  @builtin(position) pos: vec4f,\n  @location(0) @interpolate(flat, either) depth: f32,\n}\n\n@vertex\nfn vs(@location(0) at: vec2f, @location(1) depth: f32) -> Texel {\n  return Texel(vec4f(at, 0.0, 1.0), depth);\n}\n\n@fragment\nfn fs(t: Texel) -> @builtin(frag_depth) f32 {\n  return t.depth;\n}\n";

/// The point of texel (x, y) of a `w` x `h` attachment: the centre of its pixel in normalized
/// device coordinates (x right, y up: row 0 is the top row, y = 1).
pub fn texel_point(x: u32, y: u32, w: u32, h: u32) -> [f32; 2] {
    let ndc = |i: u32, n: u32| ((2.0 * i as f64 + 1.0) / n as f64 - 1.0) as f32;
    [ndc(x, w), -ndc(y, h)]
}

#[cfg(test)]
mod tests;
