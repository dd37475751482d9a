//! Unit tests of a case's texture, view and sampler as WebGPU objects, and of its texel values.
use super::*;
use shadowcheck_model::{ApiPath, CompareMode, Level};
use shadowcheck_plan::test_case::case;

fn wgpu_case(target: Target, w: u32, h: u32, layers: u32) -> Case {
    let mut c = case(target, w, h, layers);
    c.api = vec![ApiPath::Wgsl];
    c
}

#[test]
fn the_sampler_follows_the_case_and_gl_filters_without_mipmaps_view_one_level() {
    let mut c = wgpu_case(Target::T2d, 4, 4, 1);
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    c.sampler.mag_filter = Filter::Linear;
    c.sampler.wrap_s = Wrap::Repeat;
    c.sampler.wrap_t = Wrap::MirroredRepeat;
    c.sampler.compare_func = CompareFunc::Gequal;
    c.sampler.max_level = Some(1);
    for _ in 0..2 {
        let mut l = c.texture.levels[0].clone();
        l.width = (l.width / 2).max(1);
        l.height = (l.height / 2).max(1);
        l.depth = Texels::Unorm(vec![0; (l.width * l.height) as usize]);
        c.texture.levels.push(l);
    }
    let (s, levels) = sampler(&c).expect("sampler");
    assert_eq!(
        (s.mag_filter, s.min_filter, s.mipmap_filter, s.compare),
        ("linear", "linear", "linear", "greater-equal")
    );
    assert_eq!(
        (s.address_mode_u, s.address_mode_v, s.address_mode_w),
        ("repeat", "mirror-repeat", "clamp-to-edge")
    );
    // lodMinClamp is never negative; lodMaxClamp never below it.
    assert_eq!((s.lod_min_clamp, s.lod_max_clamp), (0.0, 1000.0));
    assert_eq!(levels, 2);
    c.sampler.min_filter = Filter::Linear;
    assert_eq!(sampler(&c).expect("sampler").1, 1);
    c.sampler.min_lod = 3.0;
    c.sampler.max_lod = 2.0;
    let (s, _) = sampler(&c).expect("sampler");
    assert_eq!((s.lod_min_clamp, s.lod_max_clamp), (3.0, 3.0));
    c.sampler.max_lod = f32::INFINITY;
    assert_eq!(sampler(&c).expect("sampler").0.lod_max_clamp, f32::MAX);
    // The descriptor is written with createSampler's member names.
    let json = serde_json::to_value(&s).expect("json");
    assert_eq!(json["addressModeU"], "repeat");
    assert_eq!(json["lodMinClamp"], 3.0);
}

#[test]
fn what_webgpu_has_no_state_for_is_a_reason() {
    let mut c = wgpu_case(Target::T2d, 2, 2, 1);
    c.sampler.wrap_s = Wrap::ClampToBorder;
    assert!(sampler(&c).unwrap_err().contains("GPUAddressMode"));
    let mut c = wgpu_case(Target::T2d, 2, 2, 1);
    c.sampler.lod_bias = 1.0;
    assert!(sampler(&c).unwrap_err().contains("LOD bias"));
    let mut c = wgpu_case(Target::T2d, 2, 2, 1);
    c.sampler.compare_mode = CompareMode::None;
    assert!(sampler(&c).unwrap_err().contains("comparison only"));
    // Cube maps ignore the address modes: clamp-to-edge whatever the case says.
    let mut c = wgpu_case(Target::Cube, 2, 2, 6);
    c.sampler.wrap_s = Wrap::ClampToBorder;
    let (s, _) = sampler(&c).expect("cube");
    assert_eq!(s.address_mode_u, "clamp-to-edge");
    let mut points = vec![];
    let mut c = wgpu_case(Target::Rect, 2, 2, 1);
    assert!(describe(&c, &mut points).is_err());
    c.texture.target = Target::T2d;
    c.texture.format = Format::D32;
    assert!(describe(&c, &mut points)
        .unwrap_err()
        .contains("no WebGPU depth format"));
    let c = wgpu_case(Target::Cube, 2, 2, 5);
    assert!(describe(&c, &mut points).is_err());
}

#[test]
fn unorm_texels_are_written_as_the_nearest_f32_and_convert_back() {
    let level = |depth| Level {
        width: 4,
        height: 1,
        layers: 1,
        depth,
        stencil: None,
    };
    let d16 =
        texel_values(Format::D16, &level(Texels::Unorm(vec![0, 1, 32768, 65535]))).expect("d16");
    // Round to nearest of v * (2^16 - 1) gives k back (the attachment's conversion).
    for (k, v) in [0u32, 1, 32768, 65535].iter().zip(&d16) {
        assert_eq!((*v as f64 * 65535.0).round() as u32, *k);
    }
    let max = (1u32 << 24) - 1;
    let d24 =
        texel_values(Format::D24, &level(Texels::Unorm(vec![0, 1, 1 << 23, max]))).expect("d24");
    for (k, v) in [0u32, 1, 1 << 23, max].iter().zip(&d24) {
        assert_eq!((*v as f64 * max as f64).round() as u32, *k);
    }
    assert!(texel_values(Format::D16, &level(Texels::Unorm(vec![0, 0, 0, 65536]))).is_err());
    let f = texel_values(
        Format::D32f,
        &level(Texels::Float(vec![-0.5, 0.25, 1.5, 0.0])),
    )
    .expect("d32f");
    assert_eq!(f, vec![-0.5, 0.25, 1.5, 0.0]);
    assert!(texel_values(Format::D32f, &level(Texels::Unorm(vec![0; 4]))).is_err());
    // What is read back decodes to the fixture's encoding.
    assert_eq!(
        decode(Format::D16, &[1, 0, 0xff, 0xff]),
        Some(Texels::Unorm(vec![1, 65535]))
    );
    assert_eq!(
        decode(Format::D32fS8, &0.5f32.to_le_bytes()),
        Some(Texels::Float(vec![0.5]))
    );
    assert_eq!(decode(Format::D24, &[0; 4]), None);
}

#[test]
fn every_level_and_layer_is_a_subresource_of_points_at_its_texels() {
    let mut c = wgpu_case(Target::T2dArray, 2, 2, 3);
    c.texture.levels[0].depth = Texels::Unorm((0..12).collect());
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 3,
        depth: Texels::Unorm(vec![100, 200, 300]),
        stencil: None,
    });
    let mut points = vec![9.0; 3];
    let d = describe(&c, &mut points).expect("describe");
    assert_eq!(
        (d.view, d.levels, d.layers, d.readback),
        ("2d-array", 2, 3, Some(2))
    );
    assert_eq!(d.subresources.len(), 6);
    let s = &d.subresources[1];
    assert_eq!((s.level, s.layer, s.first, s.count), (0, 1, 5, 4));
    // Texel (1, 0) of layer 1 (the fixture's texel 5) is the second point of that layer, at
    // the centre of pixel (1, 0): x right, row 0 at the top.
    let p = &points[3 * (s.first as usize + 1)..3 * (s.first as usize + 2)];
    assert_eq!(p[0..2], [0.5, 0.5]);
    assert_eq!((p[2] as f64 * 65535.0).round(), 5.0);
    let last = &d.subresources[5];
    assert_eq!(
        (last.level, last.layer, last.first, last.count),
        (1, 2, 15, 1)
    );
    assert_eq!(points.len(), 3 * 16);
}
