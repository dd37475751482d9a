//! How r reaches the observed RGBA on each API path.
//!
//! - Float-returning shadow lookups (GLSL 1.30 `texture()`, GLSL ≥ 3.30 core, ES 1.00
//!   `shadow2DEXT`, ES 3.00): Cb = (Rt, 0, 0, 1) and only Cs[0] is returned (GL 4.6 §11.1.3.5);
//!   the harness writes the float to channel 0 and fills the rest with (0, 0, 1). Core and ES 3
//!   non-shadow reads (compare NONE, colour, stencil) give the same (r, 0, 0, 1).
//! - Non-shadow reads on the compatibility GLSL 1.30 path follow DEPTH_TEXTURE_MODE (below); on
//!   ES 2.0 a depth texture reads as LUMINANCE (d, d, d, 1) (OES_depth_texture issue 2).
//! - Vec4 paths (fixed function, ARB_fragment_program, GLSL 1.10/1.20 `shadow*()`): r goes to Lt,
//!   It, At or Rt by DEPTH_TEXTURE_MODE (ARB_shadow 3.8.13.1; GL 4.6 compatibility §8.23.1) and
//!   Table 16.1 (GL 2.1 Table 3.20) expands it: LUMINANCE (r,r,r,1), INTENSITY (r,r,r,r),
//!   ALPHA (0,0,0,r), RED (r,0,0,1). The default mode is LUMINANCE (compatibility §8.12).
//!   SGIX_shadow results are "treated as if the texture internal format were LUMINANCE".
//! - Colour textures on vec4 paths: RED (r,0,0,1) for GL 3.0+ (R8), LUMINANCE (r,r,r,1) for the
//!   pre-3.0 extension specs (a LUMINANCE8 texture there). Stencil: (St, 0, 0, 1).
//! - Incomplete texture: 0 to a shadow sampler (GL ≥ 3.0 §11.1.3.5) and (0,0,0,1) on the legacy
//!   paths (GL 2.1 §3.11.2, ARB_fragment_program_shadow); with the float layout both read
//!   (0, 0, 0, 1).

use crate::faults::{Fault, Faults};
use crate::sampler::Kind;
use crate::SoftError;
use shadowcheck_model::{ApiPath, DepthTextureMode, Spec};

/// A resolved result layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// (r, 0, 0, 1)
    Float,
    /// (r, r, r, 1)
    Luminance,
    /// (r, r, r, r)
    Intensity,
    /// (0, 0, 0, r)
    Alpha,
    /// (r, 0, 0, 1) through DEPTH_TEXTURE_MODE RED / a RED colour texture.
    Red,
}

impl Layout {
    #[inline(always)]
    pub fn apply(self, r: f32) -> [f32; 4] {
        match self {
            Layout::Float | Layout::Red => [r, 0.0, 0.0, 1.0],
            Layout::Luminance => [r, r, r, 1.0],
            Layout::Intensity => [r, r, r, r],
            Layout::Alpha => [0.0, 0.0, 0.0, r],
        }
    }
}

/// The RGBA an incomplete texture gives on any path (see the module docs).
pub const INCOMPLETE: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

/// Paths returning a float (channel 0).
pub fn is_float_path(api: ApiPath) -> bool {
    matches!(
        api,
        ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es100Ext | ApiPath::Es300 | ApiPath::Vulkan
    )
}

/// Pre-GL-3.0 extension specs (no RED depth mode, colour textures are LUMINANCE).
fn is_legacy(spec: Spec) -> bool {
    matches!(
        spec,
        Spec::Sgix | Spec::SgixAmbient | Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs
    )
}

/// The layout of r on `api` for a texture of `kind` under `spec` with DEPTH_TEXTURE_MODE `mode`.
pub fn resolve(
    spec: Spec,
    api: ApiPath,
    kind: Kind,
    mode: Option<DepthTextureMode>,
    faults: Faults,
) -> Result<Layout, SoftError> {
    // Shadow lookups on the float paths return a float. Compare mode NONE (and colour textures) are
    // read through a matching non-shadow sampler, which returns a vec4: in a compatibility context
    // (GLSL 1.30) laid out by DEPTH_TEXTURE_MODE like the legacy paths, and in ES 2.0 as
    // LUMINANCE (d, d, d, 1) (OES_depth_texture issue 2).
    let vec4 = match api {
        ApiPath::FixedFunction | ApiPath::ArbFp | ApiPath::Glsl120 => true,
        ApiPath::Glsl130 => kind != Kind::Compare,
        ApiPath::Es100Ext => kind == Kind::Depth,
        // OpImageSampleDref* returns one float (SPIR-V); the shader writes (r, 0, 0, 1).
        ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl => false,
    };
    if !vec4 {
        if api == ApiPath::Glsl130
            && kind == Kind::Compare
            && mode == Some(DepthTextureMode::Alpha)
            && faults.has(Fault::AlphaModeZeroOnGlsl130)
        {
            // Cs[0] of the ALPHA expansion (0, 0, 0, r): channel 0 reads 0.
            return Ok(Layout::Alpha);
        }
        return Ok(Layout::Float);
    }
    if spec == Spec::Es2Ext {
        return Ok(Layout::Luminance);
    }
    match kind {
        Kind::Stencil => Ok(Layout::Red),
        Kind::Colour => Ok(if is_legacy(spec) {
            Layout::Luminance
        } else {
            Layout::Red
        }),
        Kind::Compare | Kind::Depth => depth_mode_layout(spec, api, mode, faults),
    }
}

/// A depth value on a vec4 path: the expansion DEPTH_TEXTURE_MODE `mode` selects (Table 16.1).
fn depth_mode_layout(
    spec: Spec,
    api: ApiPath,
    mode: Option<DepthTextureMode>,
    faults: Faults,
) -> Result<Layout, SoftError> {
    if matches!(spec, Spec::Sgix | Spec::SgixAmbient) {
        // SGIX_shadow: the modified texels are treated as LUMINANCE; there is no DEPTH_TEXTURE_MODE.
        return Ok(Layout::Luminance);
    }
    let default = if faults.has(Fault::WrongDefaultDepthMode) {
        DepthTextureMode::Red
    } else {
        DepthTextureMode::Luminance
    };
    let mode = if api == ApiPath::Glsl120 && faults.has(Fault::Glsl120IgnoresDepthMode) {
        DepthTextureMode::Luminance
    } else {
        mode.unwrap_or(default)
    };
    if mode == DepthTextureMode::Red && is_legacy(spec) && mode != default {
        // RED became a legal DEPTH_TEXTURE_MODE with GL 3.0 (ARB_depth_texture: LUMINANCE,
        // INTENSITY, ALPHA).
        return Err(SoftError::Undefined {
            spec,
            what: "DEPTH_TEXTURE_MODE RED (GL 3.0 compatibility)",
        });
    }
    Ok(match mode {
        DepthTextureMode::Luminance => Layout::Luminance,
        DepthTextureMode::Intensity => {
            if faults.has(Fault::IntensityAsLuminance) {
                Layout::Luminance
            } else {
                Layout::Intensity
            }
        }
        DepthTextureMode::Alpha => Layout::Alpha,
        DepthTextureMode::Red => {
            if faults.has(Fault::RedModeAsLuminance) {
                Layout::Luminance
            } else {
                Layout::Red
            }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    const F: Faults = Faults::NONE;

    #[test]
    fn depth_texture_modes_table_16_1() {
        let r = 0.25;
        let lay = |m| {
            resolve(Spec::Gl46, ApiPath::FixedFunction, Kind::Compare, m, F)
                .unwrap()
                .apply(r)
        };
        assert_eq!(lay(None), [r, r, r, 1.0]); // default LUMINANCE in compatibility
        assert_eq!(lay(Some(DepthTextureMode::Luminance)), [r, r, r, 1.0]);
        assert_eq!(lay(Some(DepthTextureMode::Intensity)), [r, r, r, r]);
        assert_eq!(lay(Some(DepthTextureMode::Alpha)), [0.0, 0.0, 0.0, r]);
        assert_eq!(lay(Some(DepthTextureMode::Red)), [r, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn float_paths_ignore_the_mode() {
        for api in [
            ApiPath::Glsl130,
            ApiPath::GlslCore,
            ApiPath::Es100Ext,
            ApiPath::Es300,
        ] {
            let l = resolve(
                Spec::Gl46,
                api,
                Kind::Compare,
                Some(DepthTextureMode::Alpha),
                F,
            )
            .unwrap();
            assert_eq!(l.apply(0.5), [0.5, 0.0, 0.0, 1.0]);
        }
    }

    #[test]
    fn non_shadow_reads_on_compat_and_es2() {
        // Compare NONE through GLSL 1.30 in a compatibility context: DEPTH_TEXTURE_MODE applies.
        assert_eq!(
            resolve(Spec::Gl46, ApiPath::Glsl130, Kind::Depth, None, F).unwrap(),
            Layout::Luminance
        );
        assert_eq!(
            resolve(Spec::Gl46, ApiPath::Glsl130, Kind::Compare, None, F).unwrap(),
            Layout::Float
        );
        assert_eq!(
            resolve(Spec::Gl46, ApiPath::GlslCore, Kind::Depth, None, F).unwrap(),
            Layout::Float
        );
        // ES 2.0: OES_depth_texture reads depth as (d, d, d, 1).
        assert_eq!(
            resolve(Spec::Es2Ext, ApiPath::Es100Ext, Kind::Depth, None, F).unwrap(),
            Layout::Luminance
        );
        assert_eq!(
            resolve(Spec::Es2Ext, ApiPath::Es100Ext, Kind::Compare, None, F).unwrap(),
            Layout::Float
        );
    }

    #[test]
    fn sgix_is_luminance_and_red_needs_gl3() {
        let l = resolve(
            Spec::Sgix,
            ApiPath::FixedFunction,
            Kind::Compare,
            Some(DepthTextureMode::Alpha),
            F,
        )
        .unwrap();
        assert_eq!(l, Layout::Luminance);
        assert!(resolve(
            Spec::Arb,
            ApiPath::Glsl120,
            Kind::Compare,
            Some(DepthTextureMode::Red),
            F
        )
        .is_err());
        let l = resolve(
            Spec::Arb,
            ApiPath::ArbFp,
            Kind::Compare,
            Some(DepthTextureMode::Alpha),
            F,
        )
        .unwrap();
        assert_eq!(l.apply(1.0), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn colour_textures() {
        assert_eq!(
            resolve(Spec::Gl46, ApiPath::FixedFunction, Kind::Colour, None, F).unwrap(),
            Layout::Red
        );
        assert_eq!(
            resolve(Spec::Arb, ApiPath::FixedFunction, Kind::Colour, None, F).unwrap(),
            Layout::Luminance
        );
    }

    #[test]
    fn layout_faults() {
        let f = F.with(Fault::RedModeAsLuminance);
        assert_eq!(
            resolve(
                Spec::Gl46,
                ApiPath::Glsl120,
                Kind::Compare,
                Some(DepthTextureMode::Red),
                f
            )
            .unwrap(),
            Layout::Luminance
        );
        let f = F.with(Fault::WrongDefaultDepthMode);
        assert_eq!(
            resolve(Spec::Gl46, ApiPath::Glsl120, Kind::Compare, None, f).unwrap(),
            Layout::Red
        );
        assert_eq!(
            resolve(Spec::Arb, ApiPath::Glsl120, Kind::Compare, None, f).unwrap(),
            Layout::Red
        );
    }
}
