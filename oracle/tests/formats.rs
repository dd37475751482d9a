//! Colour formats of several components (comparison bypassed, every component of Cb judged) and
//! the incomplete STENCIL_INDEX read (all four channels, the alpha's two readings).

mod common;
use common::*;
use shadowcheck_model::*;

/// One texel of `format` holding `c` (unorm per component), compare mode on, LEQUAL, Dref 0.5.
fn colour(spec: Spec, format: Format, c: [u32; 4]) -> Case {
    let mut k = one(spec, Format::D16, CompareFunc::Lequal, 0.5, 0.0);
    k.texture.format = format;
    k.texture.levels[0].depth = Texels::Colour(vec![c]);
    k
}

#[test]
fn a_colour_texture_of_several_components_returns_its_base_colour_on_every_channel() {
    let c = colour(Spec::Gl46, Format::Rgba8, [51, 102, 153, 204]);
    let e = eval(&c).expect;
    let api = api_for(Spec::Gl46);
    assert_eq!(e.layout.get(&api), Some(&Channel::GATHER));
    let judge = |rgba| e.judge(api, rgba);
    assert_eq!(judge([0.2, 0.4, 0.6, 0.8]), Some(Judgement::Strictest));
    // The comparison's result (0.5 <= 0.2 fails: 0) and the RED layout are wrong.
    assert_eq!(judge([0.0, 0.0, 0.0, 1.0]), Some(Judgement::Outside));
    assert_eq!(judge([0.2, 0.0, 0.0, 1.0]), Some(Judgement::Outside));
    // RGB8: A is 1 (Table 15.1); RG8: B 0, A 1; RGBA4: c / 15.
    let rgb = eval(&colour(Spec::Gles32, Format::Rgb8, [51, 102, 153, 0])).expect;
    let es = api_for(Spec::Gles32);
    assert_eq!(
        rgb.layout.get(&es),
        Some(&[Channel::G0, Channel::G1, Channel::G2, Channel::One])
    );
    assert_eq!(
        rgb.judge(es, [0.2, 0.4, 0.6, 1.0]),
        Some(Judgement::Strictest)
    );
    assert_eq!(
        rgb.judge(es, [0.2, 0.4, 0.6, 0.0]),
        Some(Judgement::Outside)
    );
    let rg = eval(&colour(Spec::Gles32, Format::Rg8, [51, 102, 0, 0])).expect;
    assert_eq!(
        rg.judge(es, [0.2, 0.4, 0.0, 1.0]),
        Some(Judgement::Strictest)
    );
    let r4 = eval(&colour(Spec::Gl46, Format::Rgba4, [3, 6, 9, 12])).expect;
    assert_eq!(
        r4.judge(api, [0.2, 0.4, 0.6, 0.8]),
        Some(Judgement::Strictest)
    );
}

#[test]
fn the_swizzle_and_the_border_colour_act_per_component() {
    let mut c = colour(Spec::Gl46, Format::Rgba8, [51, 102, 153, 204]);
    c.sampler.swizzle = Some([Swizzle::Alpha, Swizzle::Blue, Swizzle::One, Swizzle::Red]);
    let e = eval(&c).expect;
    let api = api_for(Spec::Gl46);
    assert_eq!(
        e.judge(api, [0.8, 0.6, 1.0, 0.2]),
        Some(Judgement::Strictest)
    );
    let mut b = colour(Spec::Gl46, Format::Rgba8, [51, 102, 153, 204]);
    b.sampler.wrap_s = Wrap::ClampToBorder;
    b.sampler.border = [0.25, 0.5, 0.75, 1.0];
    b.lookup.coord[0] = -0.5;
    let e = eval(&b).expect;
    assert_eq!(
        e.judge(api, [0.25, 0.5, 0.75, 1.0]),
        Some(Judgement::Strictest)
    );
    assert_eq!(
        e.judge(api, [0.25, 0.0, 0.0, 1.0]),
        Some(Judgement::Outside)
    );
}

#[test]
fn an_incomplete_stencil_read_checks_every_channel_and_names_both_alphas() {
    let mut c = case2d(
        Spec::Gl46,
        Format::D24S8,
        CompareFunc::Lequal,
        Filter::NearestMipmapNearest,
        2,
        2,
        &[0.2, 0.4, 0.6, 0.8],
        (0.25, 0.25),
        0.5,
    );
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c.api = vec![ApiPath::GlslCore];
    let e = eval(&c).expect;
    let judge = |rgba| e.judge(ApiPath::GlslCore, rgba);
    assert_eq!(judge([0.0, 0.0, 0.0, 1.0]), Some(Judgement::Strictest));
    // "in floating-point" read literally: 1.0f's bits in the alpha word (Mesa 22.3.6).
    assert_eq!(
        judge([0.0, 0.0, 0.0, 1065353216.0]),
        Some(Judgement::Strictest)
    );
    // ANGLE's Vulkan back end (WebGL CTS, webgl-stencil-texturing): neither reading.
    assert_eq!(judge([0.0, 0.0, 0.0, 0.0]), Some(Judgement::Outside));
    assert!(e
        .implementation_defined
        .unwrap_or_default()
        .contains("incomplete-uint-alpha"));
}
