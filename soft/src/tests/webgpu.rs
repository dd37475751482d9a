//! The WebGPU variant end to end (the `wgsl` path), each expected value computed by hand from the
//! WebGPU and WGSL sentences cited beside it.

use super::*;

/// A WebGPU 2D case: `w`×1 D16 texels, NEAREST, Dref ½ at the centre.
fn wgpu(w: u32, texels: Vec<u32>, func: CompareFunc) -> Case {
    case2d(
        Spec::WebGpu,
        Format::D16,
        w,
        1,
        texels,
        func,
        Filter::Nearest,
    )
}

fn sample(c: &Case) -> Result<[f32; 4], SoftError> {
    SoftUnit::new(Spec::WebGpu).sample(c, ApiPath::Wgsl)
}

/// A 2D array of 1x1 D16 layers with the given texels.
fn array(layers: Vec<u32>) -> Case {
    let mut c = wgpu(1, vec![0], CompareFunc::Lequal);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0] = Level {
        width: 1,
        height: 1,
        layers: layers.len() as u32,
        depth: Texels::Unorm(layers),
        stencil: None,
    };
    c
}

#[test]
fn provided_value_compared_with_the_sampled_value() {
    // WebGPU, Samplers: GPUSamplerDescriptor GPUCompareFunction "less": "A provided value passes the comparison test if
    // it is less than the sampled value": depth_ref 0.25 < texel 0.75 passes.
    let mut c = wgpu(1, vec![d16(0.75)], CompareFunc::Less);
    c.lookup.dref = 0.25;
    assert_eq!(sample(&c).unwrap(), [1.0, 0.0, 0.0, 1.0]); // WGSL returns an f32
    c.sampler.compare_func = CompareFunc::Greater;
    assert_eq!(r(&c), 0.0);
    c.sampler.compare_func = CompareFunc::Gequal;
    c.lookup.dref = 0.75;
    assert_eq!(r(&c), 1.0); // "greater than or equal to"
    c.sampler.compare_func = CompareFunc::Never; // "Comparison tests never pass."
    assert_eq!(r(&c), 0.0);
}

#[test]
fn depth_ref_is_not_clamped() {
    // No sentence clamps depth_ref (WGSL "The reference value to compare the sampled
    // depth value against"); the unit takes it as given, also for unorm formats: 1.5 ≤ 1 fails.
    let mut c = wgpu(1, vec![65535], CompareFunc::Lequal);
    c.lookup.dref = 1.5;
    assert_eq!(r(&c), 0.0);
    // -0.5 ≥ 0 fails too (a clamp would make it 0 ≥ 0).
    let mut c = wgpu(1, vec![0], CompareFunc::Gequal);
    c.lookup.dref = -0.5;
    assert_eq!(r(&c), 0.0);
}

#[test]
fn array_index_is_clamped() {
    // WGSL: "This value will be clamped to the range [0, textureNumLayers(t) - 1]".
    // Layers [fail, fail, pass] with LEQUAL ½.
    let mut c = array(vec![0, 0, 65535]);
    for (index, want) in [(2.0, 1.0), (5.0, 1.0), (-2.0, 0.0), (1.0, 0.0)] {
        c.lookup.coord[2] = index;
        assert_eq!(r(&c), want, "array_index {index}");
    }
    // A fractional layer coordinate has no WGSL counterpart: the nearest integer, halves to
    // even (WGSL round): 1.5 → 2 (passes), 2.5 → 2, 0.5 → 0 (fails).
    for (index, want) in [(1.5, 1.0), (2.5, 1.0), (0.5, 0.0), (1.4999, 0.0)] {
        c.lookup.coord[2] = index;
        assert_eq!(r(&c), want, "array_index {index}");
    }
    // Cube arrays: the index selects the cube (WebGPU createView.1 "cube-array": "a packed array of
    // n cubemaps, each with 6 array layers"); index 3 of 2 cubes clamps to cube 1.
    let mut c = wgpu(1, vec![0], CompareFunc::Lequal);
    c.texture.target = Target::CubeArray;
    let mut texels = vec![0; 6];
    texels.extend([65535; 6]);
    c.texture.levels[0] = Level {
        width: 1,
        height: 1,
        layers: 12,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c.lookup.coord = [0.0, -1.0, 0.2, 1.0];
    for (index, want) in [(0.0, 0.0), (1.0, 1.0), (3.0, 1.0), (-1.0, 0.0)] {
        c.lookup.layer = index;
        assert_eq!(r(&c), want, "cube index {index}");
    }
}

#[test]
fn cube_views_filter_across_faces() {
    // WebGPU createView.1 "cube": "Sampling is done seamlessly across the faces of the cubemap".
    // 2x2 faces, +Z passes, the rest fails; direction (1, 0, 0.9) on +X: s = 0.05, u − ½ = −0.4,
    // i0 = −1 lies on +Z, α = 0.6: r = 1 − α = 0.4 (as in `seamless_cube_edge_in_es`).
    let mut c = wgpu(2, vec![], CompareFunc::Lequal);
    c.texture.target = Target::Cube;
    let mut texels = vec![0; 24];
    texels[16..20].copy_from_slice(&[65535; 4]);
    c.texture.levels[0] = Level {
        width: 2,
        height: 2,
        layers: 6,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c.lookup.coord = [1.0, 0.0, 0.9, 1.0];
    assert!((r(&c) - 0.4).abs() < 1e-6);
}

#[test]
fn filtering_is_the_weighted_average_of_the_comparisons() {
    // WebGPU, Samplers: GPUSamplerDescriptor: "After comparison, if texture filtering is enabled, the filtering step
    // occurs ... Filtering should behave as usual". 2x1 [0, 1] at s = ½ with LINEAR: u − ½ = ½,
    // α = ½; LEQUAL ½ fails on texel 0 and passes on texel 1: r = ½.
    let mut c = wgpu(2, vec![0, 65535], CompareFunc::Lequal);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    assert_eq!(r(&c), 0.5);
    // "mirror-repeat": "the texture is flipped when the integer part of the coordinate is odd":
    // s = 1.25 reads as 1 − 0.25 = 0.75, u = 1.5, NEAREST texel 1 (passes).
    let mut c = wgpu(2, vec![0, 65535], CompareFunc::Lequal);
    c.sampler.wrap_s = Wrap::MirroredRepeat;
    c.lookup.coord[0] = 1.25;
    assert_eq!(r(&c), 1.0);
    c.sampler.wrap_s = Wrap::Repeat; // u = 2.5 → texel 2 mod 2 = 0 (fails)
    assert_eq!(r(&c), 0.0);
}

#[test]
fn gather_compare_order_and_level() {
    // WGSL textureGatherCompare: x (umin, vmax), y (umax, vmax), z (umax, vmin),
    // w (umin, vmin). 2x2 [0, ¼ / ¾, 1] at the centre, LEQUAL ½: (¾, 1, ¼, 0) → (1, 1, 0, 0).
    let mut c = wgpu(2, vec![0, d16(0.25), d16(0.75), 65535], CompareFunc::Lequal);
    c.texture.levels[0].height = 2;
    c.lookup.gather = Some(Gather { offsets: None });
    assert_eq!(sample(&c).unwrap(), [1.0, 1.0, 0.0, 0.0]);
    // "from mip level 0": λ = 1 with a mipmap filter still reads level 0 (all Dt 0 fail), not
    // level 1 (all Dt 1).
    let mut c = wgpu(2, vec![0; 4], CompareFunc::Lequal);
    c.texture.levels[0].height = 2;
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: Texels::Unorm(vec![65535]),
        stencil: None,
    });
    c.sampler.min_filter = Filter::NearestMipmapNearest;
    c.lookup.lod = 1.0;
    assert_eq!(r(&c), 1.0); // textureSampleCompare at λ = 1 reads level 1
    c.lookup.gather = Some(Gather { offsets: None });
    assert_eq!(sample(&c).unwrap(), [0.0; 4]);
    // No textureGatherOffsets in WGSL.
    c.lookup.gather = Some(Gather {
        offsets: Some([[0, 0]; 4]),
    });
    assert!(sample(&c).is_err());
}

#[test]
fn state_webgpu_does_not_have_is_refused() {
    let base = wgpu(1, vec![65535], CompareFunc::Lequal);
    let refused = |f: &dyn Fn(&mut Case)| {
        let mut c = base.clone();
        f(&mut c);
        sample(&c).is_err()
    };
    assert!(!refused(&|_| {}));
    // GPUAddressMode has no border (WebGPU, Samplers: GPUSamplerDescriptor).
    assert!(refused(&|c| c.sampler.wrap_s = Wrap::ClampToBorder));
    assert!(refused(&|c| c.sampler.wrap_t = Wrap::MirrorClampToEdge));
    // A comparison needs a `sampler_comparison` (WGSL).
    assert!(refused(&|c| c.sampler.compare_mode = CompareMode::None));
    // No LOD bias in GPUSamplerDescriptor, no bias argument in the compare built-ins.
    assert!(refused(&|c| c.sampler.lod_bias = 1.0));
    assert!(refused(&|c| c.lookup.bias = 1.0));
    // No projective built-in.
    assert!(refused(&|c| c.lookup.projective = true));
    // Only the five depth formats (WebGPU, Texture Formats).
    assert!(refused(&|c| c.texture.format = Format::D32));
    assert!(refused(&|c| c.texture.format = Format::R8));
    // texture_depth_2d, _2d_array, _cube, _cube_array only.
    assert!(refused(&|c| c.texture.target = Target::Rect));
    assert!(refused(&|c| c.texture.target = Target::T1d));
    // lodMaxClamp ≥ lodMinClamp (WebGPU, Sampler Creation).
    assert!(refused(&|c| {
        c.sampler.min_lod = 2.0;
        c.sampler.max_lod = 1.0
    }));
    // A mip chain GL would find incomplete (2x1 without its 1x1 level): no such GPUTextureView.
    let mut short = wgpu(2, vec![65535, 65535], CompareFunc::Lequal);
    short.sampler.min_filter = Filter::LinearMipmapLinear;
    assert!(sample(&short).is_err());
    // Other paths do not exist under WebGPU.
    assert!(SoftUnit::new(Spec::WebGpu)
        .sample(&base, ApiPath::GlslCore)
        .is_err());
}
