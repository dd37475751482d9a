//! The GL enum values a plan names (from the Khronos registry's gl.xml; the same numbers in GL,
//! GL ES and WebGL 2.0). The GL worker's test `plan_enums_match_glow` checks each against glow's.

pub const UNSIGNED_BYTE: u32 = 0x1401;
pub const UNSIGNED_SHORT: u32 = 0x1403;
pub const UNSIGNED_INT: u32 = 0x1405;
pub const FLOAT: u32 = 0x1406;
pub const DEPTH_COMPONENT: u32 = 0x1902;
pub const RED: u32 = 0x1903;
pub const DEPTH_COMPONENT16: u32 = 0x81A5;
pub const DEPTH_COMPONENT24: u32 = 0x81A6;
pub const DEPTH_COMPONENT32: u32 = 0x81A7;
pub const DEPTH_COMPONENT32F: u32 = 0x8CAC;
pub const DEPTH_STENCIL: u32 = 0x84F9;
pub const UNSIGNED_INT_24_8: u32 = 0x84FA;
pub const DEPTH24_STENCIL8: u32 = 0x88F0;
pub const DEPTH32F_STENCIL8: u32 = 0x8CAD;
pub const FLOAT_32_UNSIGNED_INT_24_8_REV: u32 = 0x8DAD;
pub const R8: u32 = 0x8229;
pub const RG: u32 = 0x8227;
pub const RGB: u32 = 0x1907;
pub const RGBA: u32 = 0x1908;
pub const RG8: u32 = 0x822B;
pub const RGB8: u32 = 0x8051;
pub const RGBA8: u32 = 0x8058;
pub const RGBA4: u32 = 0x8056;
pub const UNSIGNED_SHORT_4_4_4_4: u32 = 0x8033;

pub const TEXTURE_BORDER_COLOR: u32 = 0x1004;
pub const TEXTURE_MAG_FILTER: u32 = 0x2800;
pub const TEXTURE_MIN_FILTER: u32 = 0x2801;
pub const TEXTURE_WRAP_S: u32 = 0x2802;
pub const TEXTURE_WRAP_T: u32 = 0x2803;
pub const TEXTURE_WRAP_R: u32 = 0x8072;
pub const TEXTURE_MIN_LOD: u32 = 0x813A;
pub const TEXTURE_MAX_LOD: u32 = 0x813B;
pub const TEXTURE_BASE_LEVEL: u32 = 0x813C;
pub const TEXTURE_MAX_LEVEL: u32 = 0x813D;
pub const TEXTURE_LOD_BIAS: u32 = 0x8501;
pub const TEXTURE_COMPARE_MODE: u32 = 0x884C;
pub const TEXTURE_COMPARE_FUNC: u32 = 0x884D;
pub const TEXTURE_SWIZZLE_R: u32 = 0x8E42;
pub const TEXTURE_SWIZZLE_G: u32 = 0x8E43;
pub const TEXTURE_SWIZZLE_B: u32 = 0x8E44;
pub const TEXTURE_SWIZZLE_A: u32 = 0x8E45;
/// ARB_depth_texture; compatibility profile only (GL 4.6 compatibility §8.23.1).
pub const DEPTH_TEXTURE_MODE: u32 = 0x884B;
/// GL 4.3 / ARB_stencil_texturing.
pub const DEPTH_STENCIL_TEXTURE_MODE: u32 = 0x90EA;
/// ARB_shadow_ambient.
pub const TEXTURE_COMPARE_FAIL_VALUE_ARB: u32 = 0x80BF;
