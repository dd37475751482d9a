//! SGIX_shadow (rev 1.15, 1997) and SGIX_shadow_ambient (rev 1.3).
//! Source: specs/registry/SGIX_shadow.txt, specs/registry/SGIX_shadow_ambient.txt (and seeds/SGIX_shadow.txt).

use crate::rules::{
    passes_if, BorderRule, CompareTable, Filtering, Incomplete, NotInTable, RefClamp, Rules,
};
use shadowcheck_model::{ApiPath, CompareFunc, Spec, Target, Wrap};
use std::cmp::Ordering::{self, *};

/// SGIX_shadow, Additions to Chapter 3, Notes:
/// "The test for operator TEXTURE_LEQUAL_R_SGIX passes if the texel value is less than or equal to R.
///  The test for operator TEXTURE_GEQUAL_R_SGIX passes if the texel value is greater than or equal to R."
/// `ord` is R compared with the texel, so "texel <= R" is "R >= texel".
/// "The value of the test is zero if the test fails, and one if it passes."
pub fn table(func: CompareFunc, ord: Option<Ordering>) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        // texel <= R
        CompareFunc::LequalRSgix => passes_if(ord, &[Greater, Equal]),
        // texel >= R
        CompareFunc::GequalRSgix => passes_if(ord, &[Less, Equal]),
        // Errors: "INVALID_OPERATION is generated if TexParameter[if] parameter <pname> is
        // TEXTURE_COMPARE_OPERATOR_SGIX and parameter <param> is not TEXTURE_LEQUAL_R_SGIX,or
        // TEXTURE_GEQUAL_R_SGIX."
        _ => return Err(NotInTable),
    })
}

/// The reading of ARB_shadow issue 2 (named, not defended): "the GL_TEXTURE_LEQUAL_R_SGIX token should
/// really have been named GL_R_LEQUAL_TEXTURE_SGIX since we're comparing R <= TEXTURE".
pub fn table_arb_issue2(
    func: CompareFunc,
    ord: Option<Ordering>,
) -> Result<Option<bool>, NotInTable> {
    Ok(match func {
        CompareFunc::LequalRSgix => passes_if(ord, &[Less, Equal]),
        CompareFunc::GequalRSgix => passes_if(ord, &[Greater, Equal]),
        _ => return Err(NotInTable),
    })
}

/// Rules of SGIX_shadow; with `Spec::SgixAmbient` also SGIX_shadow_ambient.
pub fn rules(spec: Spec) -> Rules {
    let ambient = spec == Spec::SgixAmbient;
    Rules {
        spec,
        doc: if ambient { "SGIX_shadow + SGIX_shadow_ambient" } else { "SGIX_shadow" },
        table: table as CompareTable,
        table_cite: "SGIX_shadow, Additions to Chapter 3 (Notes: TEXTURE_LEQUAL_R_SGIX passes if texel <= R)",
        // "The specification is unclear if the R texture coordinate is clamped to the range [0,1].
        //  NVIDIA hardware supporting this extension does clamp" (NVIDIA Implementation Details).
        ref_clamp: RefClamp::Unstated,
        clamp_cite: "SGIX_shadow, Notes (\"texture components are treated as though they range from 0.0 through 1.0\") and NVIDIA Implementation Details (R clamp unclear)",
        // Table 3.8 as updated: "TEXTURE_BORDER_COLOR 4 floats any 4 values in [0,1]".
        border: BorderRule::ClampUnit,
        // Overview: "two new operations to be performed on texture values before they are passed on
        // to the filtering subsystem"; Notes: "operators which alter the sampled texture values before
        // they are filtered".
        filtering: Filtering::BeforeFilter,
        filter_cite: "SGIX_shadow, Overview and Notes (compare before filtering)",
        incomplete: Incomplete::Legacy0001,
        es_depth_completeness: false,
        seamless_cube: false,
        lod_bias: true,
        // SGIX_shadow_ambient Notes: "the value of the SHADOW_AMBIENT_SGIX parameter is returned,
        // instead of 0.0".
        ambient_on_pass: false,
        has_fail_value: ambient,
        // "These operators are defined only for textures with internal format DEPTH_COMPONENT"; the
        // depth textures of the time (SGIX_depth_texture) are 1D and 2D.
        targets: &[Target::T1d, Target::T2d],
        wraps: &[Wrap::Clamp, Wrap::Repeat, Wrap::ClampToEdge, Wrap::ClampToBorder, Wrap::MirroredRepeat],
        // "The modified texels ... are treated as if the texture internal format were LUMINANCE":
        // fixed-function texturing only (the extension predates programmable lookups).
        apis: &[ApiPath::FixedFunction],
        depth_modes: &[],
        depth_stencil_mode: false,
        bad_func_error: "INVALID_OPERATION",
    }
}
