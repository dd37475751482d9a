//! GLSL 4.50 for Vulkan (GL_KHR_vulkan_glsl), the `vk` path's program text, compiled to SPIR-V by
//! the Vulkan worker. The lookups are GLSL 4.50's ([`modern_call`]); what differs from the core
//! path's batched program is the interface (Vulkan 1.3 §15.1 "Shader Interfaces"):
//! - every stage input and output has an explicit `layout(location = N)` (§15.1.4 "Location
//!   Assignment": SPIR-V has no name matching), the vertex inputs at [`PARAM_ATTRIBS`]' locations;
//! - the one sampler is a combined image sampler at set 0, binding 0 (§15.6 "Descriptor Set
//!   Interface");
//! - `u_base` is a push constant (§15.9 "Push Constant Interface"), not a plain uniform, which
//!   Vulkan GLSL does not have outside a block.
//!
//! Always the batched layout ([`crate::layout`]): case k of a draw is slot `u_base + k`, two
//! triangles over its 2x2 pixel quad; its values are flat inputs. Vulkan's framebuffer origin is
//! the upper left (§26.8 "Rasterization": xf = (xc/wc + 1) * px/2 + ox, y likewise with no flip), so
//! the quad of slot s covers framebuffer rows 2*(s / quads) and the next one, and row r of the
//! image read back (vkCmdCopyImageToBuffer, rows in increasing y) is row r of [`crate::layout`]'s
//! pixels, as GL's bottom-up glReadPixels rows are. `gl_FragCoord` is the pixel centre in both.

use super::{as_vec4, modern_call, sampler_type, PARAM_ATTRIBS};
use crate::{LodForm, SamplerKind, ShaderKey};

/// The location of a batched program's vertex input `name` ([`PARAM_ATTRIBS`]).
fn location(name: &str) -> u32 {
    PARAM_ATTRIBS
        .iter()
        .find(|a| a.1 == name)
        .map_or(0, |a| a.0)
}

/// The compute shader of a compute-stage key ([`shadowcheck_model::Stage::Compute`]) on the `vk`
/// path: one invocation (`local_size` 1) does the lookup on `u_tex` (set 0, binding 0) with the
/// case's values from push constants ([`COMPUTE_PUSH_BYTES`]: `u_p` at offset 0, `u_x` at 16,
/// `u_at` at 24, §15.9 "Push Constant Interface" with std430-like offsets), and stores the result
/// with `imageStore` at `u_at`, the slot's pixel, in the result image (set 0, binding 1, an
/// RGBA32F storage image). `texture()` outside the fragment stage is compiled with an explicit
/// LOD of 0 (SPIR-V `OpImageSample*ExplicitLod`, `Lod` 0: "as though the base level-of-detail were
/// computed as zero", GLSL 4.60 §8.9).
pub fn compute_glsl(key: &ShaderKey) -> String {
    let store = as_vec4("r", &modern_call(key, "u_tex"), vec4_result(key));
    format!(
        "#version 450\nlayout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;\nlayout(set = 0, binding = 0) uniform {} u_tex;\nlayout(set = 0, binding = 1, rgba32f) writeonly uniform image2D u_out;\nlayout(push_constant) uniform PC {{ vec4 u_p; float u_x; ivec2 u_at; }};\nvoid main() {{\n  vec4 p = u_p;\n  vec4 r = vec4(0.0);\n  {store}\n  imageStore(u_out, u_at, r);\n}}\n",
        sampler_type(key.kind, key.target)
    )
}

/// Whether the key's lookup returns a vec4 (a gather, a lookup without comparison), not a float.
fn vec4_result(key: &ShaderKey) -> bool {
    key.kind != SamplerKind::Shadow || key.gather.is_some()
}

/// Bytes of the compute shader's push constants: P (16), x (4, padded to 8), the pixel (8).
pub const COMPUTE_PUSH_BYTES: u32 = 32;

/// The push-constant block of both stages (one `int`, at offset 0).
const PUSH_CONSTANT: &str = "layout(push_constant) uniform PC { int u_base; };\n";

/// Bytes of the push-constant range ([`PUSH_CONSTANT`]).
pub const PUSH_CONSTANT_BYTES: u32 = 4;

/// (vertex source, fragment source) of the `vk` path's batched program for `key`, drawn on a
/// framebuffer `fb_width` pixels wide (`crate::layout::FB_SIZE`). The sampler is `u_tex`, set 0
/// binding 0; the result is `o`, location 0.
pub fn glsl(key: &ShaderKey, fb_width: i32) -> (String, String) {
    (vertex_shader(fb_width), fragment_shader(key))
}

/// The vertex shader: case `u_base + a_x.y`'s quad, its values as flat outputs 0..3.
fn vertex_shader(fb_width: i32) -> String {
    let quads = fb_width / 2;
    let inputs: String = [
        ("a_pos", "vec2"),
        ("a_p", "vec4"),
        ("a_dx", "vec4"),
        ("a_dy", "vec4"),
        ("a_x", "vec3"),
    ]
    .iter()
    .map(|(n, t)| format!("layout(location = {}) in {t} {n};\n", location(n)))
    .collect();
    format!(
        "#version 450\n{inputs}{PUSH_CONSTANT}{OUTS}void main() {{\n  int s = u_base + int(a_x.y);\n  ivec2 corner = 2 * ivec2(s % {quads}, s / {quads}) + 2 * ivec2(a_pos);\n  gl_Position = vec4(vec2(corner) / {quads}.0 - 1.0, 0.0, 1.0);\n  v_p = a_p;\n  v_dx = a_dx;\n  v_dy = a_dy;\n  v_x = a_x.x;\n}}\n",
        OUTS = FLAT_VALUES.replace("$", "out"),
    )
}

/// The flat values passed from the vertex to the fragment shader (`$`: `in` or `out`).
const FLAT_VALUES: &str = "layout(location = 0) flat $ vec4 v_p;\nlayout(location = 1) flat $ vec4 v_dx;\nlayout(location = 2) flat $ vec4 v_dy;\nlayout(location = 3) flat $ float v_x;\n";

/// The fragment shader: the lookup (P varying across the quad for implicit derivatives, exactly
/// the case's P at the quad's written pixel), its result as RGBA at location 0.
fn fragment_shader(key: &ShaderKey) -> String {
    let implicit = matches!(key.form, LodForm::Implicit(_) | LodForm::Gather(true));
    // `u_base`, a slot index, is never negative: a discard never taken (see the parent module).
    let mut p_line = "if (u_base < 0) discard;\n  vec4 p = v_p;\n  vec4 u_dx = v_dx;\n  vec4 u_dy = v_dy;\n  float u_x = v_x;".to_string();
    if implicit {
        p_line += "\n  ivec2 q = ivec2(gl_FragCoord.xy) / 2;\n  vec2 c = vec2(q * 2) + 0.5;\n  p = p + (gl_FragCoord.x - c.x) * u_dx + (gl_FragCoord.y - c.y) * u_dy;";
    }
    let store = as_vec4("o", &modern_call(key, "u_tex"), vec4_result(key));
    format!(
        "#version 450\nlayout(set = 0, binding = 0) uniform {} u_tex;\n{PUSH_CONSTANT}{}layout(location = 0) out vec4 o;\nvoid main() {{\n  {p_line}\n  {store}\n}}\n",
        sampler_type(key.kind, key.target),
        FLAT_VALUES.replace("$", "in"),
    )
}
