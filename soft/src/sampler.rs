//! The sampler state resolved once per (spec, sampler, texture): what a texel contributes, the
//! comparison, clamping, fail value, wrap modes, border, level range and completeness.
//!
//! Everything that can be decided without the lookup's coordinates is decided here, so the
//! per-lookup code only reads plain fields. Which state a spec defines at all is `defined`.

use crate::compare::{self, ClampRule, CompareOp};
use crate::faults::{Fault, Faults};
use crate::lod::LodParams;
use crate::storage::{clamp01, PreparedTexture};
use crate::unitstate::StateSource;
use crate::SoftError;
use shadowcheck_model::{CompareMode, DepthStencilMode, Filter, Format, Sampler, Spec, Wrap};

/// What a fetched texel turns into before filtering.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Depth texture with TEXTURE_COMPARE_MODE = COMPARE_*: each texel becomes pass / fail value.
    Compare,
    /// Depth texture with compare mode NONE: r = Dt.
    Depth,
    /// Colour texture (R8): comparison bypassed (§8.23.1 "texture comparison is bypassed").
    Colour,
    /// DEPTH_STENCIL with DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX: r = St (§8.23.1).
    Stencil,
}

/// Resolved sampler state (see the module docs). Build with [`SamplerState::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct SamplerState {
    pub kind: Kind,
    pub op: CompareOp,
    pub clamp: ClampRule,
    /// Value of a passing / failing texel (1.0 / 0.0, or the ambient / fail value).
    pub pass: f32,
    pub fail: f32,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    /// The value a border texel holds (TEXTURE_BORDER_COLOR[0] for depth, §8.14.2).
    pub border: f32,
    pub lod: LodParams,
    /// Seamless cube filtering (§8.13.1; always on in ES 3.x, off by default in GL).
    pub seamless: bool,
    /// Texture completeness (§8.17) for this sampler.
    pub complete: bool,
    pub faults: Faults,
    /// Set only by [`Fault::StencilCompared`]: stencil indices go through the comparison.
    pub stencil_compare: bool,
    /// Set only by [`Fault::SwizzleBeforeCompare`]: the value every texel compares as.
    pub swizzled_dt: Option<f32>,
}

pub(crate) fn undefined(spec: Spec, what: &'static str) -> SoftError {
    SoftError::Undefined { spec, what }
}

/// Filters that need only one texel: MAG NEAREST with MIN NEAREST or NEAREST_MIPMAP_NEAREST.
pub fn is_nearest_only(s: &Sampler) -> bool {
    s.mag_filter == Filter::Nearest
        && matches!(s.min_filter, Filter::Nearest | Filter::NearestMipmapNearest)
}

impl SamplerState {
    /// Resolves `s` (the texture's own parameters) for `tex` under `spec`. Errors name state the
    /// spec does not define.
    pub fn new(
        spec: Spec,
        s: &Sampler,
        tex: &PreparedTexture,
        faults: Faults,
    ) -> Result<SamplerState, SoftError> {
        SamplerState::resolve(spec, s, StateSource::Texture, tex, faults)
    }

    /// Resolves `s` for `tex` under `spec`, `s` coming from `source` (the texture's parameters or
    /// a bound sampler object, see [`crate::unitstate::effective`]).
    pub fn resolve(
        spec: Spec,
        s: &Sampler,
        source: StateSource,
        tex: &PreparedTexture,
        faults: Faults,
    ) -> Result<SamplerState, SoftError> {
        let format = tex.format();
        let sampler_object_incomplete = crate::defined::check_state(spec, s, source, tex, faults)?;
        let (kind, stencil_mode) = texel_kind(spec, s, tex, faults)?;
        let compare_on = s.compare_mode == CompareMode::Compare;
        // Faulty only: the stencil index compared with Dref ([`Fault::StencilCompared`]).
        let stencil_compare =
            kind == Kind::Stencil && compare_on && faults.has(Fault::StencilCompared);
        let op = if kind == Kind::Compare || stencil_compare {
            compare::resolve_op(spec, s.compare_func, faults)?
        } else {
            CompareOp::Always
        };
        let clamp = compare::clamp_rule(spec, format, faults);
        let (pass, fail) = compare::pass_fail_values(spec, s.fail_value, faults);
        let border = border_depth(spec, s, format, faults);
        let range = LevelRange::new(s, tex, faults);
        let complete = is_complete(
            spec,
            s,
            tex,
            &range,
            stencil_mode,
            sampler_object_incomplete,
            faults,
        );
        if spec == Spec::Vulkan && !complete {
            // An image view has levelCount levels and LOD selection clamps to them (Vulkan
            // Image Views, Level-of-Detail Operation): no Vulkan image has a short chain.
            return Err(undefined(
                spec,
                "a texture whose mip chain GL would find incomplete (no such Vulkan image view)",
            ));
        }
        if spec == Spec::WebGpu && !complete {
            // A GPUTextureView has baseMipLevel and mipLevelCount (WebGPU createView.1), every level
            // of a GPUTexture exists from creation: no WebGPU view has a short chain.
            return Err(undefined(
                spec,
                "a texture whose mip chain GL would find incomplete (no such WebGPU view)",
            ));
        }

        Ok(SamplerState {
            kind,
            op,
            clamp,
            pass,
            fail,
            wrap_s: s.wrap_s,
            wrap_t: s.wrap_t,
            border,
            lod: LodParams {
                lod_bias: s.lod_bias,
                min_lod: s.min_lod,
                max_lod: s.max_lod,
                level_base: range.base,
                q: range.q.max(range.base),
                min_filter: s.min_filter,
                mag_filter: s.mag_filter,
            },
            seamless: tex.target().is_cube() && crate::unitstate::seamless(spec, s, faults),
            complete,
            faults,
            stencil_compare,
            swizzled_dt: crate::unitstate::pre_compare_dt(s, faults),
        })
    }
}

/// Which texels take part (§8.23.1): what a fetched texel turns into, and whether
/// DEPTH_STENCIL_TEXTURE_MODE selects stencil indices.
fn texel_kind(
    spec: Spec,
    s: &Sampler,
    tex: &PreparedTexture,
    faults: Faults,
) -> Result<(Kind, bool), SoftError> {
    let format = tex.format();
    let stencil_mode =
        format.has_stencil() && s.depth_stencil_mode == Some(DepthStencilMode::StencilIndex);
    if stencil_mode && !matches!(spec, Spec::Gl46 | Spec::Gles32) {
        return Err(undefined(spec, "DEPTH_STENCIL_TEXTURE_MODE"));
    }
    let compare_on = s.compare_mode == CompareMode::Compare;
    let kind = if !format.is_depth() {
        if compare_on && faults.has(Fault::CompareAppliedToColour) {
            Kind::Compare
        } else {
            Kind::Colour
        }
    } else if stencil_mode && !faults.has(Fault::StencilModeIgnored) {
        if !tex.has_stencil() {
            return Err(SoftError::Invalid(
                "DEPTH_STENCIL_TEXTURE_MODE is STENCIL_INDEX but the case has no stencil values"
                    .into(),
            ));
        }
        Kind::Stencil
    } else if compare_on {
        Kind::Compare
    } else {
        Kind::Depth
    };
    Ok((kind, stencil_mode))
}

/// The border texel's value (§8.14.2): the first component is the depth value; ES 3.2 clamps
/// border values to the format's range ([0, 1] for unorm).
fn border_depth(spec: Spec, s: &Sampler, format: Format, faults: Faults) -> f32 {
    let border = if faults.has(Fault::BorderDepthFromAlpha) {
        s.border[3]
    } else {
        s.border[0]
    };
    if spec == Spec::Gles32 && format.is_fixed_point() {
        clamp01(border)
    } else {
        border
    }
}

/// The level range (§8.14.3): p = ⌊log2(maxsize)⌋ + level_base, q = min(p, level_max).
#[derive(Clone, Copy)]
struct LevelRange {
    base: u32,
    level_max: u32,
    q: u32,
}

impl LevelRange {
    fn new(s: &Sampler, tex: &PreparedTexture, faults: Faults) -> LevelRange {
        let base = tex.base_level;
        let level_max = s.max_level.unwrap_or(1000);
        let p = tex.max_mip_index() + base;
        let q = if faults.has(Fault::MaxLevelIgnored) {
            p
        } else {
            p.min(level_max)
        };
        LevelRange { base, level_max, q }
    }
}

/// Texture completeness (§8.17) for this sampler.
fn is_complete(
    spec: Spec,
    s: &Sampler,
    tex: &PreparedTexture,
    range: &LevelRange,
    stencil_mode: bool,
    sampler_object_incomplete: bool,
    faults: Faults,
) -> bool {
    if faults.has(Fault::IncompleteNotZero) {
        return true;
    }
    let format = tex.format();
    let LevelRange { base, level_max, q } = *range;
    let mip_complete = base <= level_max && q - base.min(q) < tex.chain_len;
    if s.min_filter.is_mipmap() && !mip_complete && !faults.has(Fault::MipmapCompletenessIgnored) {
        return false;
    }
    // Vulkan has no completeness: an image view always has its levels. A texture whose mip chain
    // GL would find short is refused before this (`SamplerState::resolve`).
    let nearest_only = is_nearest_only(s);
    if !nearest_only && stencil_mode {
        return false;
    }
    if spec == Spec::Gles32
        && !nearest_only
        && format.is_depth()
        && format.is_sized()
        && s.compare_mode != CompareMode::Compare
        && !faults.has(Fault::EsDepthFilterCompletenessIgnored)
    {
        // ES 3.2 §8.17: sized depth format, TEXTURE_COMPARE_MODE NONE, non-NEAREST filtering.
        return false;
    }
    !sampler_object_incomplete
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{CompareFunc, Level, Target, Texels, Texture};

    fn tex(format: Format, sizes: &[(u32, u32)]) -> PreparedTexture {
        let levels = sizes
            .iter()
            .map(|&(w, h)| {
                let n = (w * h) as usize;
                let depth = if format.is_fixed_point() {
                    Texels::Unorm(vec![0; n])
                } else {
                    Texels::Float(vec![0.0; n])
                };
                Level {
                    width: w,
                    height: h,
                    layers: 1,
                    depth,
                    stencil: format.has_stencil().then(|| vec![0; n]),
                }
            })
            .collect();
        PreparedTexture::new(
            &Texture {
                target: Target::T2d,
                format,
                base_level: 0,
                levels,
            },
            Faults::NONE,
        )
        .unwrap()
    }
    fn sampler(filter: Filter) -> Sampler {
        Sampler::new(CompareMode::Compare, CompareFunc::Lequal, filter)
    }

    #[test]
    fn mipmap_filter_needs_full_chain() {
        let t = tex(Format::D16, &[(4, 4), (2, 2)]);
        let st = SamplerState::new(
            Spec::Gl46,
            &sampler(Filter::NearestMipmapNearest),
            &t,
            Faults::NONE,
        )
        .unwrap();
        assert!(!st.complete);
        // TEXTURE_MAX_LEVEL 1 makes q = 1: the two levels suffice.
        let mut s = sampler(Filter::NearestMipmapNearest);
        s.max_level = Some(1);
        assert!(
            SamplerState::new(Spec::Gl46, &s, &t, Faults::NONE)
                .unwrap()
                .complete
        );
        // Non-mipmap filters only need the base level.
        assert!(
            SamplerState::new(Spec::Gl46, &sampler(Filter::Linear), &t, Faults::NONE)
                .unwrap()
                .complete
        );
        let t = tex(Format::D16, &[(4, 4), (2, 2), (1, 1)]);
        assert!(
            SamplerState::new(
                Spec::Gl46,
                &sampler(Filter::LinearMipmapLinear),
                &t,
                Faults::NONE
            )
            .unwrap()
            .complete
        );
    }

    #[test]
    fn es_sized_depth_with_compare_none_and_linear_is_incomplete() {
        let t = tex(Format::D24, &[(2, 2)]);
        let mut s = sampler(Filter::Linear);
        s.compare_mode = CompareMode::None;
        assert!(
            !SamplerState::new(Spec::Gles32, &s, &t, Faults::NONE)
                .unwrap()
                .complete
        );
        assert!(
            SamplerState::new(Spec::Gl46, &s, &t, Faults::NONE)
                .unwrap()
                .complete
        );
        s.compare_mode = CompareMode::Compare;
        assert!(
            SamplerState::new(Spec::Gles32, &s, &t, Faults::NONE)
                .unwrap()
                .complete
        );
        // The unsized format is not caught by the rule.
        let mut s = sampler(Filter::Linear);
        s.compare_mode = CompareMode::None;
        assert!(
            SamplerState::new(
                Spec::Gles32,
                &s,
                &tex(Format::DepthUnsized, &[(2, 2)]),
                Faults::NONE
            )
            .unwrap()
            .complete
        );
    }

    #[test]
    fn stencil_mode_needs_nearest() {
        let t = tex(Format::D24S8, &[(2, 2)]);
        let mut s = sampler(Filter::Linear);
        s.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
        let st = SamplerState::new(Spec::Gl46, &s, &t, Faults::NONE).unwrap();
        assert_eq!((st.kind, st.complete), (Kind::Stencil, false));
        let mut s = sampler(Filter::Nearest);
        s.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
        assert!(
            SamplerState::new(Spec::Gl46, &s, &t, Faults::NONE)
                .unwrap()
                .complete
        );
        assert!(SamplerState::new(Spec::Arb, &s, &t, Faults::NONE).is_err());
    }

    #[test]
    fn spec_specific_state_errors() {
        let t = tex(Format::D16, &[(2, 2)]);
        let mut s = sampler(Filter::Nearest);
        s.lod_bias = 1.0;
        assert!(SamplerState::new(Spec::Gles32, &s, &t, Faults::NONE).is_err());
        assert!(SamplerState::new(Spec::Gl46, &s, &t, Faults::NONE).is_ok());
        let mut s = sampler(Filter::Nearest);
        s.wrap_s = Wrap::ClampToBorder;
        assert!(SamplerState::new(Spec::Es2Ext, &s, &t, Faults::NONE).is_err());
        assert!(SamplerState::new(Spec::Gles32, &s, &t, Faults::NONE).is_ok());
        assert!(SamplerState::new(
            Spec::Gles32,
            &sampler(Filter::Nearest),
            &tex(Format::D32, &[(1, 1)]),
            Faults::NONE
        )
        .is_err());
    }

    #[test]
    fn es_border_is_clamped_for_unorm() {
        let mut s = sampler(Filter::Nearest);
        s.border = [1.5, 0.0, 0.0, 0.0];
        assert_eq!(
            SamplerState::new(Spec::Gles32, &s, &tex(Format::D16, &[(1, 1)]), Faults::NONE)
                .unwrap()
                .border,
            1.0
        );
        assert_eq!(
            SamplerState::new(
                Spec::Gles32,
                &s,
                &tex(Format::D32f, &[(1, 1)]),
                Faults::NONE
            )
            .unwrap()
            .border,
            1.5
        );
    }
}
