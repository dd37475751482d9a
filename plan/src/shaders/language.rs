//! The dialect of a GLSL program: what its text starts with (`#version`, the `#extension`
//! directives the key needs, ES precision statements) and how it names its vertex inputs, the
//! values passed on to the fragment shader and the fragment result, per API path and context.

use crate::paths::uses_shadow_lod;
use crate::{GlInfo, ShaderKey};
use shadowcheck_model::{ApiPath, Stage, Target};

/// What a GLSL dialect's program text starts with and how it names its inputs and result.
pub(super) struct Language {
    /// `#version`, the `#extension` directives the key needs, ES precision statements.
    pub(super) header: String,
    /// The vertex-input qualifier: `in` (GLSL 1.30+, ES 3.00) or `attribute`.
    pub(super) vin: &'static str,
    /// The fragment result: `o` (declared by `out_decl`) or `gl_FragColor`.
    pub(super) fout: &'static str,
    pub(super) out_decl: &'static str,
    /// The qualifiers of a value passed from vertex to fragment shader unchanged: `flat out` /
    /// `flat in` (GLSL 1.30+, ES 3.00) or `varying` (GLSL 1.10/1.20, ES 1.00: interpolated, so
    /// read with a margin).
    pub(super) vout: &'static str,
    pub(super) fin: &'static str,
}

/// The dialect of the key's API path on this context (GLSL 1.10/1.20, 1.30, 3.30+/4.00, ES).
pub(super) fn language(info: &GlInfo, key: &ShaderKey) -> Language {
    let cube_array = key.target == Target::CubeArray;
    let rect = key.target == Target::Rect;
    let (header, vin, fout, out_decl) = match key.path {
        ApiPath::GlslCore if key.stage == Stage::Compute => {
            // Compute shaders and image stores: GLSL 4.30 (`GlInfo::compute`).
            (
                "#version 430 core\n".to_string(),
                "in",
                "o",
                "out vec4 o;\n",
            )
        }
        ApiPath::GlslCore => {
            let v = if info.glsl >= 400 {
                "#version 400 core\n"
            } else {
                "#version 330 core\n"
            };
            let mut h = v.to_string();
            if cube_array && info.glsl < 400 {
                h += "#extension GL_ARB_texture_cube_map_array : require\n";
            }
            (h, "in", "o", "out vec4 o;\n")
        }
        ApiPath::Glsl130 => {
            let mut h = "#version 130\n".to_string();
            if rect {
                h += "#extension GL_ARB_texture_rectangle : require\n";
            }
            if cube_array {
                h += "#extension GL_ARB_texture_cube_map_array : require\n";
            }
            (h, "in", "o", "out vec4 o;\n")
        }
        ApiPath::Es300 => {
            // Shadow gather and compute shaders: GLSL ES 3.10.
            let es31 = key.gather.is_some() || key.stage == Stage::Compute;
            let mut h = if es31 && !cube_array {
                // textureGatherOffsets: 3.20 (`paths::plan_for`).
                if info.glsl >= 320 {
                    "#version 320 es\n".to_string()
                } else {
                    "#version 310 es\n".to_string()
                }
            } else if cube_array && info.glsl >= 320 {
                "#version 320 es\n".to_string()
            } else if cube_array {
                "#version 310 es\n#extension GL_OES_texture_cube_map_array : require\n".to_string()
            } else {
                "#version 300 es\n".to_string()
            };
            h += "precision highp float;\nprecision highp int;\n";
            (h, "in", "o", "out vec4 o;\n")
        }
        ApiPath::Glsl120 => {
            let mut h = "#version 120\n".to_string();
            if rect {
                h += "#extension GL_ARB_texture_rectangle : require\n";
            }
            (h, "attribute", "gl_FragColor", "")
        }
        ApiPath::Es100Ext => (
            "#version 100\n#extension GL_EXT_shadow_samplers : require\nprecision highp float;\n"
                .to_string(),
            "attribute",
            "gl_FragColor",
            "",
        ),
        ApiPath::FixedFunction | ApiPath::ArbFp => (String::new(), "in", "o", ""),
        // WGSL is no GLSL dialect: the WebGPU page's shader text is written elsewhere.
        ApiPath::Wgsl => (String::new(), "in", "o", ""),
        // Not used for program text ([`vulkan::glsl`] writes it); the dialect for completeness.
        ApiPath::Vulkan => (
            "#version 450\n".to_string(),
            "in",
            "o",
            "layout(location = 0) out vec4 o;\n",
        ),
    };
    // EXT_texture_shadow_lod's overloads: the directive right after #version.
    let header = if uses_shadow_lod(key) {
        match header.split_once('\n') {
            Some((version, rest)) => {
                format!("{version}\n#extension GL_EXT_texture_shadow_lod : require\n{rest}")
            }
            None => header,
        }
    } else {
        header
    };
    let (vout, fin) = if vin == "attribute" {
        ("varying", "varying")
    } else {
        ("flat out", "flat in")
    };
    Language {
        header,
        vin,
        fout,
        out_decl,
        vout,
        fin,
    }
}
