//! Shader and ARB fragment program text for a [`ShaderKey`].
//!
//! A single-case program reads the case from uniforms (exact f32 values): `u_p` the lookup vector P,
//! `u_x` the LOD / bias / cube-array compare value, `u_dx`/`u_dy` the gradients and `u_c` the centre
//! of the written pixel. With implicit derivatives the coordinate is
//! `u_p + (gl_FragCoord.x - u_c.x) * u_dx + (gl_FragCoord.y - u_c.y) * u_dy`, which is exactly `u_p`
//! at the written pixel and varies by the gradients across its 2x2 quad. A batched program gets
//! the same values as flat inputs, two triangles over one 2x2 pixel quad per case (see `glsl`).
//!
//! Every program can discard, but never does: a GLSL program discards where the slot index
//! `u_base` (batched) or the pixel centre `u_c` (single case) is negative, an ARB program kills
//! where the centre is, and neither ever is. The discard changes no lookup: the branch depends
//! on a uniform, so control flow stays uniform and derivatives are defined. It only changes
//! what llvmpipe and lavapipe compile. A shader that cannot discard is "opaque" to them. For such a shader they compile a
//! second fragment function for fully covered tiles, beside the one for partly covered tiles.
//! These draws cover one pixel or a few 2x2 quads, so they only ever run the partial-tile
//! function. Without the never-taken discard a cold compatibility run spent a sixth of its time
//! compiling the whole-tile function it never uses (reports/BENCH.md). The fixed-function path cannot discard.

use crate::units::sampler_name;
use crate::{GatherCall, GlInfo, LodForm, SamplerKind, ShaderKey};
use shadowcheck_model::{ApiPath, Delivery, Stage, Target};

fn sampler_type(kind: SamplerKind, target: Target) -> String {
    let base = match target {
        Target::T1d => "1D",
        Target::T2d => "2D",
        Target::Rect => "2DRect",
        Target::Cube => "Cube",
        Target::T1dArray => "1DArray",
        Target::T2dArray => "2DArray",
        Target::CubeArray => "CubeArray",
    };
    match kind {
        SamplerKind::Shadow => format!("sampler{base}Shadow"),
        SamplerKind::Float => format!("sampler{base}"),
        SamplerKind::Uint => format!("usampler{base}"),
    }
}

/// The argument P built from the vec4 `p` (layout from `paths::plan`).
fn p_expr(kind: SamplerKind, target: Target, proj: bool) -> &'static str {
    use Target::*;
    if proj {
        return "p";
    }
    match (kind == SamplerKind::Shadow, target) {
        (true, T1d | T2d | Rect | T1dArray) => "p.xyz",
        (true, Cube | T2dArray | CubeArray) => "p",
        (false, T1d) => "p.x",
        (false, T2d | Rect | T1dArray) => "p.xy",
        (false, Cube | T2dArray) => "p.xyz",
        (false, CubeArray) => "p",
    }
}

fn grad_swizzle(target: Target) -> &'static str {
    match target {
        Target::T1d | Target::T1dArray => ".x",
        Target::T2d | Target::Rect | Target::T2dArray => ".xy",
        Target::Cube | Target::CubeArray => ".xyz",
    }
}

/// The shadow gather call (GLSL 4.60 / GLSL ES 3.20 §8.9.4): P and refZ split out of `p` (cube
/// arrays: refZ in `u_x`), then the offset or the four offsets as constant expressions.
fn gather_call(key: &ShaderKey, call: GatherCall, tex: &str) -> String {
    let (p, refz) = match key.target {
        Target::CubeArray => ("p", "u_x"),
        Target::T2dArray | Target::Cube => ("p.xyz", "p.w"),
        _ => ("p.xy", "p.z"),
    };
    let iv = |o: [i8; 2]| format!("ivec2({}, {})", o[0], o[1]);
    match call {
        GatherCall::Offsets(o) => format!(
            "textureGatherOffsets({tex}, {p}, {refz}, ivec2[4]({}))",
            o.map(iv).join(", ")
        ),
        GatherCall::Single if key.offset != [0, 0] => {
            format!(
                "textureGatherOffset({tex}, {p}, {refz}, {})",
                iv(key.offset)
            )
        }
        GatherCall::Single => format!("textureGather({tex}, {p}, {refz})"),
        GatherCall::Variable => format!("textureGatherOffset({tex}, {p}, {refz}, u_o)"),
    }
}

/// The lookup call for GLSL >= 1.30 and GLSL ES 3.00 on the sampler `tex`.
fn modern_call(key: &ShaderKey, tex: &str) -> String {
    if let Some(call) = key.gather {
        return gather_call(key, call, tex);
    }
    let s = if key.proj { "Proj" } else { "" };
    let p = p_expr(key.kind, key.target, key.proj);
    let g = grad_swizzle(key.target);
    let cube_array_shadow = key.kind == SamplerKind::Shadow && key.target == Target::CubeArray;
    // *Offset forms (GLSL 4.60 §8.9.2): the constant offset follows P (and the LOD or the
    // gradients) and precedes the bias.
    let (o, oa) = match key.offset {
        [0, 0] => ("", String::new()),
        [a, _] if matches!(key.target, Target::T1d | Target::T1dArray) => {
            ("Offset", format!(", {a}"))
        }
        [a, b] => ("Offset", format!(", ivec2({a}, {b})")),
    };
    match key.form {
        // EXT_texture_shadow_lod: textureLod(samplerCubeArrayShadow, P, compare, lod).
        LodForm::Lod if cube_array_shadow => format!("textureLod({tex}, p, u_x, u_dx.x)"),
        LodForm::Lod => format!("texture{s}Lod{o}({tex}, {p}, u_x{oa})"),
        LodForm::Grad => format!("texture{s}Grad{o}({tex}, {p}, u_dx{g}, u_dy{g}{oa})"),
        LodForm::Implicit(true) => format!("texture{s}{o}({tex}, {p}{oa}, u_x)"),
        LodForm::Implicit(false) if cube_array_shadow => format!("texture({tex}, p, u_x)"),
        LodForm::Implicit(false) | LodForm::Constant | LodForm::Gather(_) => {
            format!("texture{s}{o}({tex}, {p}{oa})")
        }
    }
}

/// The lookup call for GLSL 1.20 (`shadow1D`, `shadow2DRectProj`, `texture2D`, ...) and ES 1.00
/// on the sampler `tex`.
fn legacy_call(key: &ShaderKey, tex: &str) -> String {
    let s = if key.proj { "Proj" } else { "" };
    let p = p_expr(key.kind, key.target, key.proj);
    let t = match key.target {
        Target::T1d => "1D",
        Target::Rect => "2DRect",
        Target::Cube => "Cube",
        _ => "2D",
    };
    let f = match (key.path, key.kind) {
        (ApiPath::Es100Ext, SamplerKind::Shadow) => format!("shadow2D{s}EXT"),
        (_, SamplerKind::Shadow) => format!("shadow{t}{s}"),
        _ => format!("texture{t}{s}"),
    };
    let bias = if key.form == LodForm::Implicit(true) {
        ", u_x"
    } else {
        ""
    };
    format!("{f}({tex}, {p}{bias})")
}

/// Floats per vertex in the parameter buffer of batched draws (six vertices, two triangles, per
/// case): the corner, (x, k, unit), P, dx, dy ([`PARAM_ATTRIBS`]).
pub const PARAM_FLOATS: usize = 17;
/// A batched program's vertex attributes: (location, name, size, offset in floats). `a_pos` is
/// the quad corner (0 or 1 in x and y; in a single-case program, the full-screen triangle), `a_x`
/// is (x, k, unit), k the case's index in its draw and unit the texture unit holding its state
/// (`units.rs`; a one-unit program reads only x and k); P, dx and dy are the case's. Every vertex
/// of a case carries the case's values, so the flat inputs are its values whatever the provoking
/// vertex.
pub const PARAM_ATTRIBS: [(u32, &str, i32, usize); 5] = [
    (0, "a_pos", 2, 0),
    (4, "a_x", 3, 2),
    (1, "a_p", 4, 5),
    (2, "a_dx", 4, 9),
    (3, "a_dy", 4, 13),
];

/// The attribute of a single-case program of several samplers that names the case's unit (a
/// current value, `glVertexAttrib1f`): (location, name).
pub const UNIT_ATTRIB: (u32, &str) = (5, "a_unit");

/// Can this key draw many cases at once, each its own pixel quad with its values as vertex
/// attributes read as flat inputs (GLSL 3.30 core, GLSL ES 3.00)? The
/// compatibility contexts' paths draw one pixel per case (`draw::run_compat_group`).
pub fn batchable(key: &ShaderKey) -> bool {
    matches!(
        key.path,
        ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan
    ) && key.form != LodForm::Constant
        && key.delivery.is_literal()
        && key.stage == Stage::Fragment
}

/// The statement that runs `store` on the sampler of the case's unit `var` (an int), one of
/// `units` (> 1): an if-chain, since a sampler array indexed by a value that is not dynamically
/// uniform is undefined (GLSL 4.60 §4.1.7).
pub(crate) fn unit_chain(units: usize, var: &str, store: &dyn Fn(&str) -> String) -> String {
    (0..units)
        .map(|u| {
            let s = store(&sampler_name(u, units));
            if u == 0 {
                format!("if ({var} == 0) {s}")
            } else if u + 1 == units {
                format!("else {s}")
            } else {
                format!("else if ({var} == {u}) {s}")
            }
        })
        .collect::<Vec<_>>()
        .join("\n  ")
}

/// The viewport (x, y, width, height) of a single-case draw of this key whose result is read at
/// pixel `at`: the 2x2 pixel quad at even window coordinates that holds it where the values
/// differ between the fragments of the quad (`per_fragment` delivery, see `delivery.rs`; the
/// other three fragments are discarded after their lookups), else the one pixel.
pub fn single_draw_viewport(key: &ShaderKey, at: (i32, i32)) -> [i32; 4] {
    if key.delivery == Delivery::PerFragment {
        [at.0 & !1, at.1 & !1, 2, 2]
    } else {
        [at.0, at.1, 1, 1]
    }
}

/// (vertex source, fragment source) for a GLSL path. `batched`: case k of a draw is the case in
/// slot `u_base + k`, drawn as two triangles covering that slot's 2x2 pixel quad of the
/// framebuffer (`fb_width` pixels wide, the viewport); its values come as vertex attributes
/// ([`PARAM_ATTRIBS`]) and reach the fragment shader as flat inputs, bit for bit. An implicit-derivative lookup's P
/// varies across its quad by the case's gradients and is the case's P at the quad's lower-left
/// pixel, whose result is read.
///
/// `units`: the samplers the program declares, `u_tex0` on unit 0 to `u_tex{units-1}`, all of the
/// key's type; each case names its unit (batched: the third component of `a_x`; single case: the
/// attribute [`UNIT_ATTRIB`], passed on to the fragment shader) and the lookup runs on that sampler
/// alone (`units.rs`). One unit: the plain `u_tex`, no selection.
pub fn glsl(
    info: &GlInfo,
    key: &ShaderKey,
    batched: Option<i32>,
    units: usize,
) -> (String, String) {
    if key.path == ApiPath::Vulkan {
        // One sampler a program, always batched (the Vulkan worker binds one descriptor set a
        // case): the interface is Vulkan's own.
        return vulkan::glsl(key, batched.unwrap_or(crate::layout::FB_SIZE));
    }
    let lang = language(info, key);
    let units = units.max(1);
    match key.stage {
        Stage::Vertex => return stage::program(&lang, key, units),
        // No draw program: a compute-stage key's program is one compute shader
        // (`compute_glsl`); a caller that draws it anyway gets a compile error saying so.
        Stage::Compute => {
            let fs = "#error a compute-stage key has no draw program: shaders::compute_glsl
";
            return (fs.to_string(), fs.to_string());
        }
        Stage::Fragment => {}
    }
    let vs = match key.delivery {
        Delivery::Flat | Delivery::PerFragment if batched.is_none() => {
            delivery::flat_vertex_shader(&lang, key, units)
        }
        _ => vertex_shader(&lang, batched, units),
    };
    (vs, fragment_shader(&lang, key, batched, units))
}

/// The compute shader of a compute-stage key ([`Stage::Compute`], `stage.rs`) on `units`
/// samplers; `None` for a key of another stage (its program is [`glsl`]'s).
pub fn compute_glsl(info: &GlInfo, key: &ShaderKey, units: usize) -> Option<String> {
    (key.stage == Stage::Compute).then(|| stage::compute(&language(info, key), key, units.max(1)))
}

/// The vertex shader: a full-screen triangle, or (batched) two triangles over each case's quad
/// with the case's values as flat outputs.
fn vertex_shader(lang: &Language, batched: Option<i32>, units: usize) -> String {
    let (header, vin) = (&lang.header, lang.vin);
    match batched {
        Some(fb_width) => {
            let quads = fb_width / 2;
            let (x_type, unit_out, unit_set) = if units > 1 {
                ("vec3", "flat out int v_unit;\n", "  v_unit = int(a_x.z);\n")
            } else {
                ("vec2", "", "")
            };
            format!(
                "{header}{vin} vec2 a_pos;\n{vin} vec4 a_p;\n{vin} vec4 a_dx;\n{vin} vec4 a_dy;\n{vin} {x_type} a_x;\nuniform int u_base;\nflat out vec4 v_p;\nflat out vec4 v_dx;\nflat out vec4 v_dy;\nflat out float v_x;\n{unit_out}void main() {{\n  int s = u_base + int(a_x.y);\n  ivec2 corner = 2 * ivec2(s % {quads}, s / {quads}) + 2 * ivec2(a_pos);\n  gl_Position = vec4(vec2(corner) / {quads}.0 - 1.0, 0.0, 1.0);\n  v_p = a_p;\n  v_dx = a_dx;\n  v_dy = a_dy;\n  v_x = a_x.x;\n{unit_set}}}\n"
            )
        }
        None if units > 1 => {
            let (loc_name, vout) = (UNIT_ATTRIB.1, lang.vout);
            format!(
                "{header}{vin} vec2 a_pos;\n{vin} float {loc_name};\n{vout} float v_unit;\nvoid main() {{ gl_Position = vec4(a_pos, 0.0, 1.0); v_unit = {loc_name}; }}\n"
            )
        }
        None => format!(
            "{header}{vin} vec2 a_pos;\nvoid main() {{ gl_Position = vec4(a_pos, 0.0, 1.0); }}\n"
        ),
    }
}

/// The fragment shader: the lookup at the fragment's coordinate (varying across the quad for
/// implicit derivatives), its result stored as RGBA.
fn fragment_shader(lang: &Language, key: &ShaderKey, batched: Option<i32>, units: usize) -> String {
    let (header, fout, out_decl) = (&lang.header, lang.fout, lang.out_decl);
    let prec = if matches!(key.path, ApiPath::Es300 | ApiPath::Es100Ext) {
        "highp "
    } else {
        ""
    };
    let implicit = matches!(key.form, LodForm::Implicit(_) | LodForm::Gather(true));
    let p_line = match (batched, key.form) {
        (Some(_), _) => {
            // `u_base`, a slot index, is never negative: a discard never taken (module docs).
            let mut l = "if (u_base < 0) discard;\n  vec4 p = v_p;\n  vec4 u_dx = v_dx;\n  vec4 u_dy = v_dy;\n  float u_x = v_x;".to_string();
            if implicit {
                l += "\n  ivec2 q = ivec2(gl_FragCoord.xy) / 2;\n  vec2 c = vec2(q * 2) + 0.5;\n  p = p + (gl_FragCoord.x - c.x) * u_dx + (gl_FragCoord.y - c.y) * u_dy;";
            }
            l
        }
        // `u_c` is a pixel centre, never negative: the discard is never taken (module docs).
        (None, _) => {
            let (read, u_p) = delivery::read_values(key);
            let p = if implicit {
                format!("vec4 p = {u_p} + (gl_FragCoord.x - u_c.x) * u_dx + (gl_FragCoord.y - u_c.y) * u_dy;")
            } else {
                format!("vec4 p = {u_p};")
            };
            format!(
                "{NEVER_DISCARD}{read}\n  {p}{}",
                delivery::per_fragment(key)
            )
        }
    };
    let mut uniforms = if batched.is_some() {
        "uniform int u_base;\nflat in vec4 v_p;\nflat in vec4 v_dx;\nflat in vec4 v_dy;\nflat in float v_x;\n".to_string()
    } else {
        delivery::fragment_inputs(key)
    };
    let unit = match (units > 1, batched.is_some()) {
        (false, _) => "",
        (true, true) => {
            uniforms += "flat in int v_unit;\n";
            "v_unit"
        }
        (true, false) => {
            // A vertex attribute's current value, the same at every vertex, not a uniform: a
            // driver may compile a variant per value of a uniform that a branch reads (zink
            // inlines such uniforms), which would undo the bundling.
            uniforms += &format!("{} float v_unit;\n", lang.fin);
            "int(v_unit + 0.5)"
        }
    };
    let vec4_result = matches!(key.path, ApiPath::Glsl120)
        || key.kind != SamplerKind::Shadow
        || key.gather.is_some();
    let store = |tex: &str| {
        let call = match key.path {
            ApiPath::Glsl120 | ApiPath::Es100Ext => legacy_call(key, tex),
            _ => modern_call(key, tex),
        };
        if vec4_result {
            format!("{fout} = vec4({call});")
        } else {
            format!("{fout} = vec4({call}, 0.0, 0.0, 1.0);")
        }
    };
    // Several units: the case's own, chosen by an if-chain (a sampler array indexed by a value
    // that is not dynamically uniform is undefined, GLSL 4.60 §4.1.7); every fragment of a
    // case's quad takes the same branch, so derivatives stay defined within the quad.
    let lookup = if units > 1 {
        let pick = if unit == "v_unit" {
            String::new()
        } else {
            format!("int unit = {unit};\n  ")
        };
        let unit = if unit == "v_unit" { "v_unit" } else { "unit" };
        let chain = unit_chain(units, unit, &store);
        format!("{pick}{chain}")
    } else {
        store("u_tex")
    };
    let samplers = sampler_decls(prec, key, units);
    let after = delivery::after_lookup(key);
    format!(
        "{header}{samplers}{uniforms}{out_decl}void main() {{\n  {p_line}\n  {lookup}{after}\n}}\n"
    )
}

/// `var = ` the lookup `call` as a vec4: as it is (`vec4_result`: a gather, a colour or GLSL
/// 1.20's vec4 result), else the shadow lookup's float as (r, 0, 0, 1).
pub(super) fn as_vec4(var: &str, call: &str, vec4_result: bool) -> String {
    if vec4_result {
        format!("{var} = vec4({call});")
    } else {
        format!("{var} = vec4({call}, 0.0, 0.0, 1.0);")
    }
}

/// The declarations of the key's `units` samplers, `u_tex` or `u_tex0` .. (`units.rs`), with the
/// precision qualifier `prec` (ES: `highp `).
pub(super) fn sampler_decls(prec: &str, key: &ShaderKey, units: usize) -> String {
    (0..units)
        .map(|u| {
            format!(
                "uniform {prec}{} {};\n",
                sampler_type(key.kind, key.target),
                sampler_name(u, units)
            )
        })
        .collect()
}

/// The single-case GLSL program's discard that is never taken (`u_c`, the pixel centre, is never
/// negative): see the module docs.
const NEVER_DISCARD: &str = "if (u_c.x < 0.0) discard;";

/// ARB fragment program text (ARB_fragment_program + ARB_fragment_program_shadow); the program
/// locals are 0 = P, 1 = dx, 2 = dy, 3 = pixel centre (x, y, 0, 0). `KIL c` kills where a
/// component of `c` is negative, which none is: a kill that never happens (module docs).
///
/// `units` > 1: the lookup on each of `texture[0]` .. `texture[units-1]` (an instruction names its
/// unit as a constant, and the language has no branch), combined as r = sum of t_i * w_i with the
/// weights w in locals 4 .. ([`arbfp_unit_weights`]): 1 for the case's unit, 0 for the others.
/// With finite lookup results (depth, comparison and normalized colour values) each product is
/// exactly t_i or 0 and each sum exact, so r is the case's lookup bit for bit.
pub fn arbfp(key: &ShaderKey, units: usize) -> String {
    let shadow = key.kind == SamplerKind::Shadow;
    let target = match key.target {
        Target::T1d => "1D",
        Target::Rect => "RECT",
        Target::Cube => "CUBE",
        _ => "2D",
    };
    let op = match (key.proj, key.form) {
        (true, _) => "TXP",
        (false, LodForm::Implicit(true)) => "TXB",
        _ => "TEX",
    };
    let option = if shadow {
        "OPTION ARB_fragment_program_shadow;\n"
    } else {
        ""
    };
    let t = if shadow {
        format!("SHADOW{target}")
    } else {
        target.to_string()
    };
    let head = format!(
        "!!ARBfp1.0\n{option}PARAM p = program.local[0];\nPARAM dx = program.local[1];\nPARAM dy = program.local[2];\nPARAM c = program.local[3];\n"
    );
    let coord = "KIL c;\nSUB d, fragment.position, c;\nMAD q, d.x, dx, p;\nMAD q, d.y, dy, q;\n";
    if units <= 1 {
        return format!("{head}TEMP d, q;\n{coord}{op} result.color, q, texture[0], {t};\nEND\n");
    }
    let weights: String = (0..units.div_ceil(4))
        .map(|j| {
            format!(
                "PARAM w{j} = program.local[{}];\n",
                ARBFP_WEIGHTS as usize + j
            )
        })
        .collect();
    let lookups: String = (0..units)
        .map(|u| {
            let w = format!("w{}.{}", u / 4, ['x', 'y', 'z', 'w'][u % 4]);
            let combine = if u == 0 {
                format!("MUL r, t, {w};\n")
            } else {
                format!("MAD r, t, {w}, r;\n")
            };
            format!("{op} t, q, texture[{u}], {t};\n{combine}")
        })
        .collect();
    format!("{head}{weights}TEMP d, q, t, r;\n{coord}{lookups}MOV result.color, r;\nEND\n")
}

/// The first program local of an ARB program's unit weights ([`arbfp`]).
pub const ARBFP_WEIGHTS: u32 = 4;

/// The weights of [`arbfp`] for a case on `unit` of `units`: one vec4 per four units, 1 for
/// `unit`, 0 elsewhere.
pub fn arbfp_unit_weights(unit: usize, units: usize) -> Vec<[f32; 4]> {
    (0..units.div_ceil(4))
        .map(|j| {
            let mut w = [0.0; 4];
            for (i, v) in w.iter_mut().enumerate() {
                if 4 * j + i == unit {
                    *v = 1.0;
                }
            }
            w
        })
        .collect()
}

mod delivery;
mod language;
use language::{language, Language};
pub mod stage;
#[cfg(test)]
mod tests;
pub mod vulkan;
pub mod wgsl;
