//! GL token names for the generated C program: every token it passes is written by name. Every
//! name in the table is in Debian's desktop headers (`GL/gl.h`, `GL/glext.h`); the few that are not
//! in the ES ones (`GLES3/gl32.h`, `GLES2/gl2ext.h`) get an `#ifndef` definition in the programs
//! that use them, so one program builds against either header set.

use std::collections::BTreeMap;

/// (value, name) of every token a reproducer may pass as a parameter value or target.
const NAMES: &[(u32, &str)] = &[
    (0x0000, "GL_NONE"),
    (0x0200, "GL_NEVER"),
    (0x0201, "GL_LESS"),
    (0x0202, "GL_EQUAL"),
    (0x0203, "GL_LEQUAL"),
    (0x0204, "GL_GREATER"),
    (0x0205, "GL_NOTEQUAL"),
    (0x0206, "GL_GEQUAL"),
    (0x0207, "GL_ALWAYS"),
    (0x0DE0, "GL_TEXTURE_1D"),
    (0x0DE1, "GL_TEXTURE_2D"),
    (0x1401, "GL_UNSIGNED_BYTE"),
    (0x1403, "GL_UNSIGNED_SHORT"),
    (0x1405, "GL_UNSIGNED_INT"),
    (0x1406, "GL_FLOAT"),
    (0x1901, "GL_STENCIL_INDEX"),
    (0x1902, "GL_DEPTH_COMPONENT"),
    (0x1903, "GL_RED"),
    (0x1906, "GL_ALPHA"),
    (0x1909, "GL_LUMINANCE"),
    (0x2600, "GL_NEAREST"),
    (0x2601, "GL_LINEAR"),
    (0x2700, "GL_NEAREST_MIPMAP_NEAREST"),
    (0x2701, "GL_LINEAR_MIPMAP_NEAREST"),
    (0x2702, "GL_NEAREST_MIPMAP_LINEAR"),
    (0x2703, "GL_LINEAR_MIPMAP_LINEAR"),
    (0x2900, "GL_CLAMP"),
    (0x2901, "GL_REPEAT"),
    (0x8040, "GL_LUMINANCE8"),
    (0x8049, "GL_INTENSITY"),
    (0x812D, "GL_CLAMP_TO_BORDER"),
    (0x812F, "GL_CLAMP_TO_EDGE"),
    (0x819C, "GL_TEXTURE_LEQUAL_R_SGIX"),
    (0x819D, "GL_TEXTURE_GEQUAL_R_SGIX"),
    (0x81A5, "GL_DEPTH_COMPONENT16"),
    (0x81A6, "GL_DEPTH_COMPONENT24"),
    (0x81A7, "GL_DEPTH_COMPONENT32"),
    (0x8229, "GL_R8"),
    (0x8370, "GL_MIRRORED_REPEAT"),
    (0x84F5, "GL_TEXTURE_RECTANGLE"),
    (0x84F9, "GL_DEPTH_STENCIL"),
    (0x84FA, "GL_UNSIGNED_INT_24_8"),
    (0x8513, "GL_TEXTURE_CUBE_MAP"),
    (0x8515, "GL_TEXTURE_CUBE_MAP_POSITIVE_X"),
    (0x8516, "GL_TEXTURE_CUBE_MAP_NEGATIVE_X"),
    (0x8517, "GL_TEXTURE_CUBE_MAP_POSITIVE_Y"),
    (0x8518, "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y"),
    (0x8519, "GL_TEXTURE_CUBE_MAP_POSITIVE_Z"),
    (0x851A, "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z"),
    (0x8743, "GL_MIRROR_CLAMP_TO_EDGE"),
    (0x884E, "GL_COMPARE_REF_TO_TEXTURE"),
    (0x88F0, "GL_DEPTH24_STENCIL8"),
    (0x8C18, "GL_TEXTURE_1D_ARRAY"),
    (0x8C1A, "GL_TEXTURE_2D_ARRAY"),
    (0x8CAC, "GL_DEPTH_COMPONENT32F"),
    (0x8CAD, "GL_DEPTH32F_STENCIL8"),
    (0x8DAD, "GL_FLOAT_32_UNSIGNED_INT_24_8_REV"),
    (0x9009, "GL_TEXTURE_CUBE_MAP_ARRAY"),
    // Parameter names (the first argument after the target).
    (0x2800, "GL_TEXTURE_MAG_FILTER"),
    (0x2801, "GL_TEXTURE_MIN_FILTER"),
    (0x2802, "GL_TEXTURE_WRAP_S"),
    (0x2803, "GL_TEXTURE_WRAP_T"),
    (0x8072, "GL_TEXTURE_WRAP_R"),
    (0x1004, "GL_TEXTURE_BORDER_COLOR"),
    (0x813A, "GL_TEXTURE_MIN_LOD"),
    (0x813B, "GL_TEXTURE_MAX_LOD"),
    (0x813C, "GL_TEXTURE_BASE_LEVEL"),
    (0x813D, "GL_TEXTURE_MAX_LEVEL"),
    (0x8501, "GL_TEXTURE_LOD_BIAS"),
    (0x884C, "GL_TEXTURE_COMPARE_MODE"),
    (0x884D, "GL_TEXTURE_COMPARE_FUNC"),
    (0x884B, "GL_DEPTH_TEXTURE_MODE"),
    (0x90EA, "GL_DEPTH_STENCIL_TEXTURE_MODE"),
    (0x80BF, "GL_TEXTURE_COMPARE_FAIL_VALUE_ARB"),
    (0x8E42, "GL_TEXTURE_SWIZZLE_R"),
    (0x8E43, "GL_TEXTURE_SWIZZLE_G"),
    (0x8E44, "GL_TEXTURE_SWIZZLE_B"),
    (0x8E45, "GL_TEXTURE_SWIZZLE_A"),
    (0x884F, "GL_TEXTURE_CUBE_MAP_SEAMLESS"),
];

/// Names of the table missing from the ES headers (checked against Debian 12's libgles-dev).
const NOT_IN_ES_HEADERS: &[&str] = &[
    "GL_TEXTURE_1D",
    "GL_CLAMP",
    "GL_LUMINANCE8",
    "GL_INTENSITY",
    "GL_TEXTURE_LEQUAL_R_SGIX",
    "GL_TEXTURE_GEQUAL_R_SGIX",
    "GL_DEPTH_COMPONENT32",
    "GL_TEXTURE_RECTANGLE",
    "GL_MIRROR_CLAMP_TO_EDGE",
    "GL_TEXTURE_1D_ARRAY",
    "GL_TEXTURE_LOD_BIAS",
    "GL_DEPTH_TEXTURE_MODE",
    "GL_TEXTURE_COMPARE_FAIL_VALUE_ARB",
    "GL_TEXTURE_CUBE_MAP_SEAMLESS",
];

/// The tokens one program uses, for the `#ifndef` block at its top.
#[derive(Default)]
pub struct Tokens(BTreeMap<&'static str, u32>);

impl Tokens {
    /// The C expression for `value`: its name (recorded for the defines), or the number in hex
    /// where the table has no name.
    pub fn name(&mut self, value: u32) -> String {
        match NAMES.iter().find(|(v, _)| *v == value) {
            Some((v, n)) => {
                self.0.insert(n, *v);
                (*n).to_string()
            }
            None => format!("0x{value:04X}"),
        }
    }

    /// `#ifndef NAME / #define NAME 0x.... / #endif` for every name used that the ES headers lack.
    pub fn defines(&self) -> String {
        self.0
            .iter()
            .filter(|(n, _)| NOT_IN_ES_HEADERS.contains(n))
            .map(|(n, v)| format!("#ifndef {n}\n#define {n} 0x{v:04X}\n#endif\n"))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_recorded_for_the_defines() {
        let mut seen = std::collections::HashSet::new();
        for (v, n) in NAMES {
            assert!(seen.insert(*v), "0x{v:04X} twice");
            assert!(n.starts_with("GL_"), "{n}");
        }
        for n in NOT_IN_ES_HEADERS {
            assert!(NAMES.iter().any(|(_, m)| m == n), "{n}");
        }
        let mut t = Tokens::default();
        assert_eq!(t.name(0x884E), "GL_COMPARE_REF_TO_TEXTURE");
        assert_eq!(t.name(0x1234), "0x1234");
        assert_eq!(t.defines(), "");
        assert_eq!(t.name(0x884B), "GL_DEPTH_TEXTURE_MODE");
        assert_eq!(
            t.defines(),
            "#ifndef GL_DEPTH_TEXTURE_MODE\n#define GL_DEPTH_TEXTURE_MODE 0x884B\n#endif\n"
        );
    }
}
