//! Unit tests of the Vulkan program text (no device, no compiler).

use super::super::Backend;
use super::*;
use shadowcheck_model::*;

/// Vulkan, 2x2 D16 (stored 0, 21845, 43690, 65535), NEAREST at the centre of texel (1,0),
/// LESS_OR_EQUAL, Dref 0.5: r = 0.
fn subject(format: Format, wrap: Wrap, border: [f32; 4]) -> Subject {
    let depth = match format {
        Format::D32f | Format::D32fS8 => Texels::Float(vec![0.0, 1.5, -0.25, 1.0]),
        _ => Texels::Unorm(vec![0, 21845, 43690, 65535]),
    };
    let mut sampler = Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest);
    sampler.wrap_s = wrap;
    sampler.border = border;
    let case = Case {
        sweep: vec![],
        id: "vulkan/2d/d16/nearest/lequal/unit".into(),
        spec: Spec::Vulkan,
        api: vec![ApiPath::Vulkan],
        texture: shadowcheck_model::Texture {
            target: Target::T2d,
            format,
            base_level: 0,
            levels: vec![Level {
                width: 2,
                height: 2,
                layers: 1,
                depth,
                stencil: format.has_stencil().then(|| vec![1, 2, 3, 4]),
            }],
        },
        sampler,
        lookup: Lookup {
            coord: [0.75, 0.25, 0.0, 1.0],
            layer: 0.0,
            dref: 0.5,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: None,
    };
    let ev = shadowcheck_oracle::evaluate(&case).unwrap();
    Subject {
        backend: Backend::Vk(Driver::Lavapipe),
        case,
        api: ApiPath::Vulkan,
        expect: ev.expect,
        steps: ev.steps,
        explain: String::new(),
        fixture: "unit.json".into(),
        lib_dir: None,
    }
}

#[test]
fn program_carries_the_image_the_sampler_the_bytes_the_vertices_and_the_oracle_set() {
    let s = subject(Format::D16, Wrap::ClampToEdge, [0.0; 4]);
    let p = program(&s).unwrap();
    for want in [
        ".imageType = 1 /* VK_IMAGE_TYPE_2D */,",
        ".format = 124 /* VK_FORMAT_D16_UNORM */,",
        ".extent = {2, 2, 1},",
        ".viewType = 1 /* VK_IMAGE_VIEW_TYPE_2D */,",
        ".subresourceRange = {0x2 /* VK_IMAGE_ASPECT_DEPTH_BIT */, 0, 1, 0, 1},",
        ".magFilter = 0 /* VK_FILTER_NEAREST */,",
        ".addressModeU = 2 /* VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE */,",
        ".compareEnable = VK_TRUE,",
        ".compareOp = 3 /* VK_COMPARE_OP_LESS_OR_EQUAL */,",
        ".borderColor = 0 /* VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK */,",
        "static const uint16_t DEPTH0[] = {\n    0, 21845, 43690, 65535\n};",
        "{DEPTH0, sizeof DEPTH0, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 2, 2},",
        // Slot 0's first vertex: corner (0, 0), x = LOD 0, k = 0, unit 0, P = (s, t, Dref, 1).
        "{0.0f, 0.0f, /* x, k, unit */ 0.0f, 0.0f, 0.0f, /* P */ 0.75f, 0.25f, 0.5f, 1.0f,",
        "{1, VK_FORMAT_R32G32B32A32_SFLOAT, 5}, /* a_p */",
        "#define NEED_DEPTH_COMPARISON 1",
        "#define NEED_FILTER_LINEAR 0",
        "#define NEED_CUSTOM_BORDER_COLOR 0",
        "static const double ACCEPTED[][2] = {{0.0, 0.0}};",
        "static int judge(const float px[4])",
        "return judge(px);",
        "VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json ./repro",
    ] {
        assert!(p.c.contains(want), "missing `{want}` in\n{}", p.c);
    }
    // The shaders are the worker's for a framebuffer 2 pixels wide: one quad per row.
    assert!(p.vert.contains("ivec2(s % 1, s / 1)"), "{}", p.vert);
    assert!(p.frag.contains("sampler2DShadow u_tex"), "{}", p.frag);
    assert!(!p.c.contains("CUSTOM_BORDER_COLOR[4]"));
}

#[test]
fn float_depth_is_clamped_stencil_goes_up_and_a_custom_border_is_required() {
    let s = subject(Format::D32fS8, Wrap::ClampToBorder, [0.5, 0.0, 0.0, 0.0]);
    let p = program(&s).unwrap();
    for want in [
        "static const float DEPTH0[] = {\n    0.0f, 1.0f, 0.0f, 1.0f\n};",
        "static const uint8_t STENCIL0[] = {\n    1, 2, 3, 4\n};",
        "{STENCIL0, sizeof STENCIL0, VK_IMAGE_ASPECT_STENCIL_BIT, 0, 2, 2},",
        "#define IMAGE_ASPECTS (0x6 /* VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT */)",
        ".borderColor = 1000287003 /* VK_BORDER_COLOR_FLOAT_CUSTOM_EXT */,",
        "static const float CUSTOM_BORDER_COLOR[4] = {0.5f, 0.0f, 0.0f, 0.0f};",
        "#define NEED_CUSTOM_BORDER_COLOR 1",
    ] {
        assert!(p.c.contains(want), "missing `{want}` in\n{}", p.c);
    }
}

#[test]
fn what_vulkan_cannot_express_is_not_written() {
    // (The oracle refuses such a case before; the generator says why on its own too.)
    let mut s = subject(Format::D16, Wrap::ClampToEdge, [0.0; 4]);
    s.case.sampler.wrap_s = Wrap::Clamp;
    assert!(program(&s).err().unwrap_or_default().contains("CLAMP"));
    s.case.sampler.wrap_s = Wrap::Repeat;
    s.case.texture.target = Target::Rect;
    assert!(program(&s).is_err());
}

#[test]
fn a_failed_build_names_the_missing_package() {
    for (log, package) in [
        ("build.sh: 5: glslangValidator: not found", "glslang-tools"),
        (
            "repro.c:1:10: fatal error: vulkan/vulkan.h: No such file or directory",
            "libvulkan-dev",
        ),
        (
            "/usr/bin/ld: cannot find -lvulkan: No such file",
            "libvulkan-dev",
        ),
        ("build.sh: 5: gcc: not found", "gcc"),
    ] {
        match build_error(log) {
            ReproError::Missing { package: p, .. } => assert_eq!(p, package, "{log}"),
            e => panic!("{log}: {e}"),
        }
    }
    assert!(matches!(
        build_error("something else"),
        ReproError::Build { .. }
    ));
}

/// REPORT.md of a Vulkan Fail names the device and driver the program printed, the packages of
/// the driver and the Vulkan build line (the observation here is made up: r = 1 where the spec
/// requires 0).
#[test]
fn a_vulkan_report_names_the_device_the_driver_and_its_packages() {
    let s = subject(Format::D16, Wrap::ClampToEdge, [0.0; 4]);
    let run = super::super::RunOutput {
        code: 1,
        stdout: "VK_DEVICE: llvmpipe (LLVM 15.0.6, 256 bits)\nVK_API_VERSION: 1.3.230\nVK_DRIVER: llvmpipe Mesa 22.3.6 (driverID 13)\nobserved:  (1, 0, 0, 1)\n".into(),
        stderr: String::new(),
    };
    let judged = crate::verdict::judge(&s.case, s.api, [1.0, 0.0, 0.0, 1.0], None);
    assert_eq!(judged.outcome, crate::records::Outcome::Fail);
    let versions = vec!["mesa-vulkan-drivers 22.3.6-1+deb12u2".to_string()];
    let r = super::super::report::render(&s, &run, &judged, &versions);
    for want in [
        "# llvmpipe (vk path): d16 2d, LEQUAL compare",
        "Read from the Vulkan device the reproducer created here",
        "- VK_DEVICE: `llvmpipe (LLVM 15.0.6, 256 bits)`",
        "- VK_DRIVER: `llvmpipe Mesa 22.3.6 (driverID 13)`",
        "- driver selected by: `VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json`",
        "- mesa-vulkan-drivers 22.3.6-1+deb12u2",
        "apt-get install -y gcc libvulkan-dev glslang-tools libvulkan1 mesa-vulkan-drivers",
        "glslangValidator --quiet -V -S vert",
        "**Fail**",
        "shadowcheck repro --backend vk:lavapipe",
    ] {
        assert!(r.contains(want), "missing `{want}` in\n{r}");
    }
    assert!(!r.contains("GL_RENDERER"), "{r}");
}

/// A compute-stage lookup: comp.glsl is the worker's compute shader (`compute_glsl`), no vertex
/// or fragment shader is written, build.sh compiles `-S comp`, and the program dispatches it with
/// the worker's push constants of slot 0 into a storage image cleared by vkCmdClearColorImage
/// (no render pass, no draw before the dispatch).
#[test]
fn a_compute_stage_case_dispatches_the_workers_compute_shader() {
    let mut s = subject(Format::D16, Wrap::ClampToEdge, [0.0; 4]);
    s.case.lookup.stage = Stage::Compute;
    let p = program(&s).unwrap();
    let plan = paths::plan_in(
        ApiPath::Vulkan,
        &s.case,
        &s.case.lookup,
        LookupForm::Auto,
        false,
    )
    .unwrap();
    assert_eq!(p.comp, shaders::vulkan::compute_glsl(&plan.key));
    assert!(p.comp.contains("imageStore(u_out, u_at, r)"), "{}", p.comp);
    assert!(p.vert.is_empty() && p.frag.is_empty());
    let names: Vec<&str> = p.shaders().iter().map(|(n, _)| *n).collect();
    assert_eq!(names, [COMP_GLSL]);
    assert_eq!(build_line(&s), COMPUTE_BUILD_LINE);
    assert!(COMPUTE_BUILD_LINE.contains("-S comp -o comp.spv comp.glsl"));
    for want in [
        // P = (s, t, Dref, 1), x = 0, padding, pixel (0, 0): compute::push_constants(plan, 0).
        "} PUSH = {{0.75f, 0.25f, 0.5f, 1.0f}, 0.0f, 0u, {0, 0}};",
        "typedef char push_constants_are_32_bytes[sizeof PUSH == 32 ? 1 : -1];",
        "#define FB 2",
        "Build: glslangValidator --quiet -V -S comp -o comp.spv comp.glsl && gcc",
        "comp.glsl is the worker's compute shader",
        "make_rgba32f(VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, &result, &result_view);",
        "bindings[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;",
        "VkPushConstantRange pc = {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof PUSH};",
        "ci.stage.module = shader_module(\"comp.spv\");",
        "VkDescriptorSet set = make_set(set_layout, result_view);",
        "record_upload(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);",
        "vkCmdClearColorImage(cmd, result, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &b.subresourceRange);",
        "b.newLayout = VK_IMAGE_LAYOUT_GENERAL;",
        "vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof PUSH, &PUSH);",
        "vkCmdDispatch(cmd, 1, 1, 1);",
        "b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;",
        "record_read_back(cmd, result, readback.buffer);",
        "static const double ACCEPTED[][2] = {{0.0, 0.0}};",
        "return judge(px);",
    ] {
        assert!(p.c.contains(want), "missing `{want}` in\n{}", p.c);
    }
    // The clear, then the dispatch; nothing of the fragment path.
    let at = |w: &str| p.c.find(w).unwrap_or(usize::MAX);
    assert!(at("vkCmdClearColorImage(") < at("vkCmdDispatch("));
    for absent in [
        "vkCmdDraw(",
        "vkCmdBeginRenderPass(",
        "VERTICES",
        "vert.spv",
        "frag.spv",
    ] {
        assert!(!p.c.contains(absent), "`{absent}` in\n{}", p.c);
    }
}

/// The fragment path keeps its program: a render pass and a draw, no dispatch.
#[test]
fn a_fragment_stage_case_draws_and_dispatches_nothing() {
    let s = subject(Format::D16, Wrap::ClampToEdge, [0.0; 4]);
    let p = program(&s).unwrap();
    assert!(p.comp.is_empty());
    assert_eq!(build_line(&s), BUILD_LINE);
    let names: Vec<&str> = p.shaders().iter().map(|(n, _)| *n).collect();
    assert_eq!(names, [VERT_GLSL, FRAG_GLSL]);
    for want in [
        "vkCmdDraw(cmd, 6, 1, 0, 0);",
        "record_upload(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);",
        "VkDescriptorSet set = make_set(set_layout, VK_NULL_HANDLE);",
    ] {
        assert!(p.c.contains(want), "missing `{want}` in\n{}", p.c);
    }
    for absent in ["vkCmdDispatch(", "comp.spv", "PUSH"] {
        assert!(!p.c.contains(absent), "`{absent}` in\n{}", p.c);
    }
}
