//! OpenGL ES 3.0 - 3.2. Source: the OpenGL ES 3.2 specification (5 May 2022).
//! Differences from GL 4.6 that matter here: the §8.17 completeness rule for sized depth textures,
//! border values clamped to the format (§8.14.2), cube maps always seamless (§8.13.1), no
//! TEXTURE_LOD_BIAS (§8.14.1), no DEPTH_TEXTURE_MODE, no 1D or rectangle textures.

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, RefClamp, Rules,
};
use crate::state::{self, Ctx, Param};
use shadowcheck_model::{ApiPath, CompareFunc, Format, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// §8.20.1, Table 8.22 "Depth texture comparison functions":
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // "LEQUAL r = 1.0, Dref ≤ Dt; 0.0, Dref > Dt"
        CompareFunc::Lequal => passes_if(ord, &[Less, Equal]),
        // "GEQUAL r = 1.0, Dref ≥ Dt; 0.0, Dref < Dt"
        CompareFunc::Gequal => passes_if(ord, &[Greater, Equal]),
        // "LESS r = 1.0, Dref < Dt; 0.0, Dref ≥ Dt"
        CompareFunc::Less => passes_if(ord, &[Less]),
        // "GREATER r = 1.0, Dref > Dt; 0.0, Dref ≤ Dt"
        CompareFunc::Greater => passes_if(ord, &[Greater]),
        // "EQUAL r = 1.0, Dref = Dt; 0.0, Dref ≠ Dt"
        CompareFunc::Equal => passes_if(ord, &[Equal]),
        // "NOTEQUAL r = 1.0, Dref ≠ Dt; 0.0, Dref = Dt"
        CompareFunc::Notequal => passes_if(ord, &[Less, Greater]),
        // "ALWAYS r = 1.0"
        CompareFunc::Always => Some(true),
        // "NEVER r = 0.0"
        CompareFunc::Never => Some(false),
        // §8.10 Errors: INVALID_ENUM for a value not among the legal values of Table 8.19.
        _ => return Err(NotInTable),
    })
}

pub fn rules() -> Rules {
    Rules {
        spec: Spec::Gles32,
        doc: "ES 3.2",
        table: table as CompareTable,
        table_cite: "ES 3.2 §8.20.1 Table 8.22",
        // "If the texture's internal format indicates a fixed-point depth texture, then Dt and Dref
        //  are clamped to the range [0, 1]; otherwise no clamping is performed."
        ref_clamp: RefClamp::FixedPointOnly,
        clamp_cite: "ES 3.2 §8.20.1 (Dt, Dref clamped only for fixed-point depth)",
        // §8.14.2: "Border values are clamped before they are used, according to the format in which
        // texture components are stored. For signed and unsigned normalized fixed-point formats,
        // border values are clamped to [−1, 1] and [0, 1], respectively."
        border: BorderRule::ClampToFormat,
        filtering: Filtering::ImplementationDependent,
        filter_cite: "ES 3.2 §8.20.1 (filtered r implementation-dependent)",
        incomplete: Incomplete::ShadowZero,
        // §8.17: "The effective internal format specified for the texture images is a sized internal
        // depth or depth and stencil format (see table 8.11), and the value of TEXTURE_COMPARE_MODE
        // is NONE." (with non-NEAREST filtering) makes the texture incomplete.
        es_depth_completeness: true,
        // §8.13.1 footnote: cube map filtering is always seamless in ES 3.x.
        seamless_cube: true,
        seamless_enable: None,
        swizzle: Some("ES 3.2 §11.1.3.5 / §14.2.1 (as GL 4.6 §15.2.1): Cb = (Rt, 0, 0, 1), then TEXTURE_SWIZZLE_R/G/B/A, then only Cs[0] is returned for a shadow sampler"),
        sampler_objects: Some("ES 3.2 §8.17.1 / §8.2 (as GL 4.6): the sampling state of a unit with a bound sampler object is taken from the sampler object; state not in the sampler state table remains in the texture object"),
        lod_bias: false,
        sampler_create: None,
        layer_rne_always: None,
        ambient_on_pass: false,
        fail_value_cite: None,
        // §8.10: "target ... must be one of TEXTURE_2D, TEXTURE_3D, TEXTURE_2D_ARRAY,
        // TEXTURE_CUBE_MAP, TEXTURE_CUBE_MAP_ARRAY, ..."
        targets: &[
            Target::T2d,
            Target::Cube,
            Target::T2dArray,
            Target::CubeArray,
        ],
        // Table 8.19: "CLAMP_TO_EDGE, REPEAT, MIRRORED_REPEAT, CLAMP_TO_BORDER".
        wraps: &[
            Wrap::ClampToEdge,
            Wrap::Repeat,
            Wrap::MirroredRepeat,
            Wrap::ClampToBorder,
        ],
        apis: &[ApiPath::Es300],
        depth_modes: &[],
        depth_stencil_mode: true,
        bad_func_error: "INVALID_ENUM",
        // ES 3.2 Table 8.11 has no DEPTH_COMPONENT32 (unorm).
        formats: &[
            Format::D16,
            Format::D24,
            Format::D32f,
            Format::D24S8,
            Format::D32fS8,
            Format::DepthUnsized,
            Format::R8,
            // ES 3.2 Table 8.10's colour formats a compare mode can meet: comparison is bypassed.
            Format::Rgba8,
            Format::Rgb8,
            Format::Rgba4,
            Format::Rg8,
        ],
        mode_pname: state::TEXTURE_COMPARE_MODE,
        func_pname: state::TEXTURE_COMPARE_FUNC,
        params,
        no_lod_state: None,
        no_lookup_bias: None,
        fixed_depth_mode: None,
        // A colour texture is R8: (Rt,0,0),1.
        colour_luminance: false,
        colour_note: None,
        non_fragment_base_texture: false,
        readings: &[crate::rules::VERTEX_BASE_TEXTURE],
    }
}

/// The TexParameter state of ES 3.2; ES contexts only.
pub fn params(_: Spec, ctx: Ctx) -> Vec<Param> {
    if ctx != Ctx::Es {
        return Vec::new();
    }
    // ES 3.2 Table 8.19, §8.10 Errors, §8.19 initial values.
    vec![
        Param::compare_mode("TEXTURE_COMPARE_MODE", "ES 3.2 Table 8.19, §8.10, §8.19"),
        Param::compare_func8("TEXTURE_COMPARE_FUNC", "ES 3.2 Table 8.19, §8.10, §8.19"),
        Param::depth_stencil_mode("ES 3.2 Table 8.19, §8.10, §8.19"),
    ]
}
