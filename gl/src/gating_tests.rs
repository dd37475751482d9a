//! Contexts by capability: what a GL 2.1 compat or an OpenGL ES 3.0 context declares, and that a
//! case needing more is Skip with its reason through [`Capabilities::support`] (never sent to the
//! driver, so never a GL error counted as Fail).
use super::declared_capabilities;
use crate::names::{ContextApi, LookupForm};
use shadowcheck_model::*;
use shadowcheck_plan::GlInfo;
use shadowcheck_protocol::Support;
use std::collections::HashSet;

fn info(api: ContextApi, version: (u32, u32), glsl: u32, exts: &[&str]) -> GlInfo {
    GlInfo {
        api,
        es: api.is_es(),
        compat: api == ContextApi::Compat,
        version,
        glsl,
        renderer: "test".into(),
        version_string: "test".into(),
        extensions: exts.iter().map(|e| e.to_string()).collect::<HashSet<_>>(),
        version_override: false,
        form: LookupForm::Auto,
    }
}

fn case(spec: Spec, api: ApiPath, target: Target, format: Format) -> Case {
    let layers = if target.is_cube() { 6 } else { 1 };
    let mut c = shadowcheck_plan::test_case::case(target, 2, 2, layers);
    c.spec = spec;
    c.api = vec![api];
    c.texture.format = format;
    c
}

fn skip_reason(s: Support) -> String {
    match s {
        Support::Skip(why) => why,
        other => panic!("expected Skip, got {other:?}"),
    }
}

#[test]
fn es_3_0_skips_border_clamp_stencil_texturing_and_cube_map_arrays_with_the_reason() {
    let es30 = declared_capabilities(&info(ContextApi::Es3, (3, 0), 300, &[]));
    let plain = case(Spec::Gles32, ApiPath::Es300, Target::T2d, Format::D24);
    assert!(matches!(es30.support(&plain), Support::Run { .. }));

    let mut border = plain.clone();
    border.sampler.wrap_s = Wrap::ClampToBorder;
    assert!(skip_reason(es30.support(&border)).contains("border_clamp"));
    let mut colour = plain.clone();
    colour.sampler.border = [1.0, 0.0, 0.0, 0.0];
    assert!(skip_reason(es30.support(&colour)).contains("TEXTURE_BORDER_COLOR"));
    // wrap_r of a 2D texture is never set, so it needs nothing.
    let mut unused = plain.clone();
    unused.sampler.wrap_r = Wrap::ClampToBorder;
    assert!(matches!(es30.support(&unused), Support::Run { .. }));

    let mut stencil = case(Spec::Gles32, ApiPath::Es300, Target::T2d, Format::D24S8);
    stencil.sampler.depth_stencil_mode = Some(DepthStencilMode::DepthComponent);
    assert!(skip_reason(es30.support(&stencil)).contains("DEPTH_STENCIL_TEXTURE_MODE"));

    let cube_array = case(Spec::Gles32, ApiPath::Es300, Target::CubeArray, Format::D24);
    assert!(skip_reason(es30.support(&cube_array)).starts_with("target"));

    // The same cases run on ES 3.2, and on ES 3.0 with the extensions that add the state.
    let es32 = declared_capabilities(&info(ContextApi::Es3, (3, 2), 320, &[]));
    for c in [&border, &colour, &stencil, &cube_array] {
        assert!(matches!(es32.support(c), Support::Run { .. }), "{c:?}");
    }
    let es30_ext = declared_capabilities(&info(
        ContextApi::Es3,
        (3, 0),
        300,
        &[
            "GL_OES_texture_border_clamp",
            "GL_OES_texture_cube_map_array",
        ],
    ));
    for c in [&border, &colour, &cube_array] {
        assert!(matches!(es30_ext.support(c), Support::Run { .. }), "{c:?}");
    }
    assert!(matches!(es30_ext.support(&stencil), Support::Skip(_)));
}

#[test]
fn gl_2_1_compat_declares_targets_by_extension_and_leaves_glsl_1_30_out() {
    let bare = info(ContextApi::Compat, (2, 1), 120, &[]);
    let caps = declared_capabilities(&bare);
    let c = case(Spec::Gl46, ApiPath::Glsl120, Target::T2dArray, Format::D24);
    assert!(skip_reason(caps.support(&c)).starts_with("target"));
    let rect = case(
        Spec::Gl46,
        ApiPath::FixedFunction,
        Target::Rect,
        Format::D24,
    );
    assert!(matches!(caps.support(&rect), Support::Skip(_)));
    assert!(!bare.paths().contains(&ApiPath::Glsl130));
    assert!(bare.paths().contains(&ApiPath::Glsl120));
    assert!(bare.paths().contains(&ApiPath::FixedFunction));

    // zink on SwiftShader's GL 2.1 context: the extensions give arrays, rectangles, cube-map arrays
    // and stencil texturing (what its GL 2.1 context lists, Mesa 22.3.6).
    let zss = info(
        ContextApi::Compat,
        (2, 1),
        120,
        &[
            "GL_EXT_texture_array",
            "GL_ARB_texture_rectangle",
            "GL_ARB_texture_cube_map_array",
            "GL_ARB_stencil_texturing",
        ],
    );
    let caps = declared_capabilities(&zss);
    assert!(matches!(caps.support(&c), Support::Run { .. }));
    assert!(matches!(caps.support(&rect), Support::Run { .. }));
    let mut stencil = case(Spec::Gl46, ApiPath::Glsl120, Target::T2d, Format::D24S8);
    stencil.sampler.depth_stencil_mode = Some(DepthStencilMode::DepthComponent);
    assert!(matches!(caps.support(&stencil), Support::Run { .. }));
    assert!(matches!(
        declared_capabilities(&bare).support(&stencil),
        Support::Skip(_)
    ));
}

#[test]
fn gather_needs_glsl_400_or_glsl_es_310_and_offsets_glsl_es_320() {
    let mut g = case(Spec::Gles32, ApiPath::Es300, Target::T2d, Format::D24);
    g.lookup.gather = Some(Gather { offsets: None });
    let es30 = declared_capabilities(&info(ContextApi::Es3, (3, 0), 300, &[]));
    assert!(skip_reason(es30.support(&g)).contains("gather"));
    let i31 = info(ContextApi::Es3, (3, 1), 310, &[]);
    let es31 = declared_capabilities(&i31);
    assert!(matches!(es31.support(&g), Support::Run { .. }));
    assert!(shadowcheck_plan::paths::plan_for(&i31, ApiPath::Es300, &g, &g.lookup).is_ok());
    let mut four = g.clone();
    four.lookup.gather = Some(Gather {
        offsets: Some([[0, 1], [1, 1], [1, 0], [0, 0]]),
    });
    let why =
        shadowcheck_plan::paths::plan_for(&i31, ApiPath::Es300, &four, &four.lookup).unwrap_err();
    assert!(why.contains("GLSL ES 3.20"), "{why}");
    let i32 = info(ContextApi::Es3, (3, 2), 320, &[]);
    assert!(shadowcheck_plan::paths::plan_for(&i32, ApiPath::Es300, &four, &four.lookup).is_ok());
    let es32 = declared_capabilities(&i32);
    assert!(matches!(es32.support(&g), Support::Run { .. }));
    g.spec = Spec::Gl46;
    g.api = vec![ApiPath::GlslCore];
    let core33 = declared_capabilities(&info(ContextApi::Core, (3, 3), 330, &[]));
    assert!(skip_reason(core33.support(&g)).contains("gather"));
    let core45 = declared_capabilities(&info(ContextApi::Core, (4, 5), 450, &[]));
    assert!(matches!(core45.support(&g), Support::Run { .. }));
}

#[test]
fn unit_state_features_follow_the_context_version() {
    let plain = case(Spec::Gles32, ApiPath::Es300, Target::T2d, Format::D24);
    let mut swizzle = plain.clone();
    swizzle.sampler.swizzle = Some([Swizzle::One, Swizzle::Red, Swizzle::Zero, Swizzle::Red]);
    let mut so = plain.clone();
    so.sampler.sampler_object = Some(SamplerObject::from_sampler(&so.sampler));
    let mut seamless = case(Spec::Gl46, ApiPath::GlslCore, Target::Cube, Format::D24);
    seamless.sampler.seamless = Some(true);
    // ES 3.0 has the swizzle and sampler objects, and no seamless enable (always seamless).
    let es30 = declared_capabilities(&info(ContextApi::Es3, (3, 0), 300, &[]));
    assert!(matches!(es30.support(&swizzle), Support::Run { .. }));
    assert!(matches!(es30.support(&so), Support::Run { .. }));
    let es_seamless = Case {
        spec: Spec::Gles32,
        api: vec![ApiPath::Es300],
        ..seamless.clone()
    };
    assert!(skip_reason(es30.support(&es_seamless)).contains("seamless_toggle"));
    // A GL 2.1 context has none of them; GL 3.2 the enable only; GL 3.3 all three.
    let (mut sw_gl, mut so_gl) = (swizzle.clone(), so.clone());
    for c in [&mut sw_gl, &mut so_gl] {
        c.spec = Spec::Gl46;
        c.api = vec![ApiPath::Glsl120];
    }
    let gl21 = declared_capabilities(&info(ContextApi::Compat, (2, 1), 120, &[]));
    assert!(skip_reason(gl21.support(&sw_gl)).contains("swizzle"));
    assert!(skip_reason(gl21.support(&so_gl)).contains("sampler_objects"));
    let gl32 = declared_capabilities(&info(ContextApi::Core, (3, 2), 150, &[]));
    for c in [&mut sw_gl, &mut so_gl] {
        c.api = vec![ApiPath::GlslCore];
    }
    assert!(matches!(gl32.support(&seamless), Support::Run { .. }));
    assert!(skip_reason(gl32.support(&sw_gl)).contains("swizzle"));
    assert!(skip_reason(gl32.support(&so_gl)).contains("sampler_objects"));
    let gl33 = declared_capabilities(&info(ContextApi::Core, (3, 3), 330, &[]));
    for c in [&sw_gl, &so_gl, &seamless] {
        assert!(matches!(gl33.support(c), Support::Run { .. }), "{c:?}");
    }
}
