//! A witness for every seedable fault: a small case (and API path) on which the faulty unit's
//! RGBA differs from the correct unit's. The test below proves each fault switch is live; the
//! mutants command can use the witnesses to tell "the suite misses this fault" from "the fault
//! is dead code". The cases themselves are built in [`cases`].

mod cases;

use crate::faults::Fault;
use cases::*;
use shadowcheck_model::*;

/// A case on which `fault` changes the result, and the API path to look at.
pub fn witness(fault: Fault) -> (Case, ApiPath) {
    use CompareFunc as C;
    use DepthTextureMode as M;
    let c = match fault {
        // The reference and Dt clamps, the comparison operators (§8.23.1).
        Fault::RefClampedForFloat => float1(1.0, 1.5, C::Lequal),
        Fault::RefNotClamped => with_dref(gl(vec![65535], 1, C::Lequal), 1.5),
        Fault::DtClampedForFloat => border(Format::D32f, C::Less, [1.5, 0.0, 0.0, 0.0], 1.2),
        Fault::DtNotClamped => border(Format::D16, C::Less, [1.5, 0.0, 0.0, 0.0], 1.2),
        Fault::UploadNotClamped => float1(1.5, 1.2, C::Lequal),
        Fault::UnormDividedByPowerOfTwo => with_dref(gl(vec![65535], 1, C::Lequal), 1.0),
        Fault::FilterThenCompare | Fault::PcfHalfTexelOff | Fault::LinearAsNearest => linear_pair(),
        Fault::LequalGequalSwapped => gl(vec![65535], 1, C::Lequal),
        Fault::LessAsLequal => with_dref(gl(vec![d16(0.6)], 1, C::Less), 0.6),
        Fault::GreaterAsGequal => with_dref(gl(vec![d16(0.6)], 1, C::Greater), 0.6),
        Fault::EqualWithTolerance => with_dref(gl(vec![d16(0.6)], 1, C::Equal), 0.6001),
        Fault::NanOrderedNotequal => float1(0.5, f64::NAN, C::Notequal),
        Fault::AlwaysNeverSwapped => gl(vec![0], 1, C::Always),
        Fault::SgixOperatorsReversed => case(Spec::Sgix, 1, 1, vec![d16(0.2)], C::LequalRSgix),
        // Pass / fail values and the result's components.
        Fault::AmbientAppliedToPass => ambient(65535, 0.25),
        Fault::AmbientIgnored => ambient(0, 0.25),
        // ARB_shadow_ambient: the fail value is clamped to [0, 1] when set: 1.5 reads as 1.
        Fault::FailValueNotClamped => ambient(0, 1.5),
        Fault::RedModeAsLuminance => depth_mode(ApiPath::FixedFunction, 65535, Some(M::Red)),
        Fault::IntensityAsLuminance => depth_mode(ApiPath::FixedFunction, 0, Some(M::Intensity)),
        Fault::WrongDefaultDepthMode => depth_mode(ApiPath::FixedFunction, 65535, None),
        Fault::AlphaModeZeroOnGlsl130 => depth_mode(ApiPath::Glsl130, 65535, Some(M::Alpha)),
        Fault::Glsl120IgnoresDepthMode => depth_mode(ApiPath::Glsl120, 65535, Some(M::Alpha)),
        Fault::StencilCompared | Fault::StencilModeIgnored => stencil_index(),
        Fault::CompareAppliedToColour => r8(51, CompareMode::Compare),
        // R8 102: exactly 102/255 (eq. (2.1)); the fault reads 102/256.
        Fault::ColourDividedBy256 => r8(102, CompareMode::None),
        // RGBA8 (51, 102, 153, 204) reads (0.2, 0.4, 0.6, 0.8); the fault drops G, B, A.
        Fault::ColourAsRed => colour(Format::Rgba8, [51, 102, 153, 204]),
        // RGB8 reads A = 1 (Table 15.1); the fault reads 0.
        Fault::ColourAlphaZero => colour(Format::Rgb8, [51, 102, 153, 0]),
        Fault::IncompleteStencilAlphaZero => stencil_incomplete(),
        // Completeness (§8.17).
        Fault::IncompleteNotZero | Fault::MipmapCompletenessIgnored => mip_incomplete(),
        Fault::EsDepthFilterCompletenessIgnored => es_linear_depth(),
        Fault::SamplerObjectRectComplete => rect_with_repeat_sampler_object(),
        Fault::GatherIgnoresSamplerObject => gather_with_sampler_object(),
        // Coordinates, addressing and filtering (§8.13, §8.14).
        Fault::ProjectiveDivideMissing | Fault::RefNotDividedByQ => projective(),
        Fault::LayerTruncated => layer_one_and_a_half(),
        Fault::LayerRneUnderLinear => linear_layer_half(),
        Fault::CubeNegYFlipped => cube_neg_y(),
        Fault::SeamlessIgnored => seamless_edge(),
        Fault::VkCubeEdgePerFace => vulkan(seamless_edge()),
        // WebGPU (GPUCompareFunction, WGSL array_index, cube views, cube array index).
        // "less": depth_ref 0.25 < texel 0.75 passes (r = 1); texel < depth_ref fails.
        Fault::WgpuCompareOperandsSwapped => {
            webgpu(with_dref(gl(vec![d16(0.75)], 1, C::Less), 0.25))
        }
        Fault::WgpuArrayIndexWrapped => array_index_minus_one(),
        Fault::WgpuCubePerFace => webgpu(seamless_edge()),
        Fault::WgpuCubeArrayIndexAsLayer => cube_array_index_one(),
        Fault::BorderIgnored | Fault::BorderDepthFromAlpha => {
            border(Format::D16, C::Lequal, [1.0, 0.0, 0.0, 0.0], 0.5)
        }
        Fault::MirroredRepeatOffByOne => mirrored_repeat(),
        Fault::OffsetIgnored => offset_one(),
        Fault::OffsetInBaseLevelTexels => offset_on_level_one(),
        Fault::OffsetAfterWrap => offset_across_repeat(),
        // Level of detail and mipmapping (§8.14.1, §8.14.3).
        Fault::MipLevelOffByOne => mips(Filter::NearestMipmapNearest, 0.25),
        Fault::TrilinearNoBlend => mips(Filter::LinearMipmapLinear, 0.25),
        Fault::LodBiasIgnored => mips_lod_bias(),
        Fault::LodClampIgnored => mips_max_lod(),
        Fault::MaxLevelIgnored => mips_max_level(),
        // Shadow gather (§8.14.2).
        Fault::GatherOrderRotated | Fault::GatherIgnoresRef => gather4(),
        Fault::GatherUsesLodLevel => gather_at_lod_one(),
        Fault::VariableGatherOffsetZero => gather_offset_from_a_uniform(),
        Fault::VertexLodFromDerivatives => stage_mips(Stage::Vertex),
        Fault::ComputeLodFromDerivatives => stage_mips(Stage::Compute),
        // `gather4` compares to (1, 1, 0, 0); TEXTURE_SWIZZLE_R = ALPHA takes the post-swizzle
        // R of each texel's (Rt, 0, 0, 1), i.e. 1 for every texel (GL 4.6 §8.14.2): (1, 1, 1, 1).
        // The faulty unit returns the unswizzled (1, 1, 0, 0).
        Fault::GatherIgnoresSwizzle => gather_swizzled([
            Swizzle::Alpha,
            Swizzle::Green,
            Swizzle::Blue,
            Swizzle::Alpha,
        ]),
        // `gather4` compares to (1, 1, 0, 0); TEXTURE_SWIZZLE_R = ZERO gives 0 for every texel
        // (GL 4.6 §8.14.2), the unswizzled reading (1, 1, 0, 0). The faulty unit swizzles the
        // gathered vector by (ZERO, RED, ONE, GREEN): (0, 1, 1, 1), neither reading.
        Fault::GatherSwizzlesVector => {
            gather_swizzled([Swizzle::Zero, Swizzle::Red, Swizzle::One, Swizzle::Green])
        }
        // Swizzle and sampler objects (GL 4.6 §15.2.1, §8.2).
        // Passes (r = 1); swizzle R = ZERO: Cs[0] = 0 (GL 4.6 §15.2.1).
        Fault::SwizzleIgnored => red_swizzled_to_zero(C::Lequal),
        // GEQUAL, Dt = 1 fails at Dref 0.5: r = 0, and R = ZERO gives Cs[0] = 0 anyway; the
        // faulty unit compares 0.5 >= 0 (ZERO applied to Dt) and passes.
        Fault::SwizzleBeforeCompare => red_swizzled_to_zero(C::Gequal),
        Fault::CompatSwizzleDropped => compat_alpha_swizzled(),
        Fault::SamplerObjectIgnored => sampler_object_greater(),
        // TexParameter state faults: no lookup shows them (a case's sampler state is always set
        // explicitly); their witnesses are state cases (`tex_param`). A plain lookup here.
        Fault::WrongInitialCompareFunc
        | Fault::IllegalValueStored
        | Fault::ExtensionPnameRejected => gl(vec![65535], 1, C::Lequal),
    };
    let api = c.api[0];
    (c, api)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SoftUnit;

    #[test]
    fn every_fault_has_a_witness() {
        // State faults show in state cases only (`tex_param`), never in a lookup.
        for &f in Fault::ALL.iter().filter(|f| !f.is_state()) {
            let (c, api) = witness(f);
            shadowcheck_model::validate::validate(&c).unwrap();
            let good = SoftUnit::new(c.spec).sample(&c, api).unwrap();
            let bad = SoftUnit::new(c.spec).with_fault(f).sample(&c, api).unwrap();
            assert_ne!(
                good.map(f32::to_bits),
                bad.map(f32::to_bits),
                "{f}: correct {good:?}, faulty {bad:?}"
            );
        }
    }

    #[test]
    fn witnesses_give_the_hand_computed_correct_values() {
        // A few of the correct values, from the spec text (see each builder's comment).
        let r = |f| {
            let (c, api) = witness(f);
            SoftUnit::new(c.spec).sample(&c, api).unwrap()
        };
        assert_eq!(r(Fault::FilterThenCompare)[0], 0.5); // PCF ½·0 + ½·1
        assert_eq!(r(Fault::RefClampedForFloat)[0], 0.0); // D32F: 1.5 ≤ 1.0 fails
        assert_eq!(r(Fault::DtClampedForFloat)[0], 1.0); // 1.2 < border 1.5
        assert_eq!(r(Fault::WrongDefaultDepthMode), [1.0, 1.0, 1.0, 1.0]); // LUMINANCE default
        assert_eq!(r(Fault::CubeNegYFlipped)[0], 1.0);
        assert_eq!(r(Fault::MirroredRepeatOffByOne)[0], 0.0); // texel 1 (Dt 0) fails
        assert_eq!(r(Fault::AmbientIgnored), [0.25, 0.25, 0.25, 1.0]);
        // Texel offsets (GL 4.6 (8.10)): u = w·s + δu at the selected level, then wrap.
        assert_eq!(r(Fault::OffsetIgnored)[0], 0.0);
        // Shadow gather (GL 4.6 §8.14.2): (τi0j1, τi1j1, τi1j0, τi0j0) compared with Dref.
        assert_eq!(r(Fault::GatherOrderRotated), [1.0, 1.0, 0.0, 0.0]);
        assert_eq!(r(Fault::GatherUsesLodLevel), [0.0; 4]); // level base, not λ's level 1
        assert_eq!(r(Fault::VariableGatherOffsetZero), [1.0, 1.0, 1.0, 0.0]);
        assert_eq!(r(Fault::VertexLodFromDerivatives)[0], 0.0); // λ_base 0: level 0 (the fault: level 1)
        assert_eq!(r(Fault::ComputeLodFromDerivatives)[0], 0.0); // the same in a compute shader
        assert_eq!(r(Fault::OffsetInBaseLevelTexels)[0], 0.0);
        assert_eq!(r(Fault::OffsetAfterWrap)[0], 0.0);
        // Swizzle, seamless enable, sampler object (GL 4.6 §15.2.1, §8.13.1, §8.17.1).
        assert_eq!(r(Fault::SwizzleIgnored)[0], 0.0);
        assert_eq!(r(Fault::SwizzleBeforeCompare)[0], 0.0);
        assert!((r(Fault::SeamlessIgnored)[0] - 0.4).abs() < 1e-6);
        assert_eq!(r(Fault::SamplerObjectIgnored)[0], 0.0);
        // Gather swizzle, compatibility swizzle, sampler object on a rectangle (§8.14.2, §16.1, §8.2).
        assert_eq!(r(Fault::GatherIgnoresSwizzle), [1.0; 4]);
        assert_eq!(r(Fault::GatherSwizzlesVector), [0.0; 4]);
        assert_eq!(r(Fault::CompatSwizzleDropped), [1.0, 1.0, 0.0, 0.0]);
        assert_eq!(r(Fault::SamplerObjectRectComplete), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(r(Fault::GatherIgnoresSamplerObject), [0.0, 0.0, 1.0, 1.0]);
        // WebGPU (Samplers: GPUCompareFunction, WGSL array_index clamp, cube views).
        assert_eq!(r(Fault::WgpuCompareOperandsSwapped), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(r(Fault::WgpuArrayIndexWrapped)[0], 0.0);
        assert!((r(Fault::WgpuCubePerFace)[0] - 0.4).abs() < 1e-6);
        assert_eq!(r(Fault::WgpuCubeArrayIndexAsLayer)[0], 1.0);
    }
}
