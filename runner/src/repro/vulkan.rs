//! The Vulkan reproducer of a `vk:*` test: `repro.c`, a C program against `<vulkan/vulkan.h>` that
//! does for one case what the Vulkan worker (shadowcheck-vk) does for it, and the worker's shaders
//! for the case's lookup, which build.sh compiles to SPIR-V with glslangValidator (Vulkan 1.3
//! "Shader Modules" takes SPIR-V only): `vert.glsl` / `frag.glsl` for a fragment-stage lookup
//! (`shaders::vulkan::glsl`), `comp.glsl` for a compute-stage one (`shaders::vulkan::compute_glsl`).
//!
//! What it mirrors, and from where: the instance and device (`vk/src/device/`: API version
//! min(loader, 1.3), the same optional features enabled where the device has them), the image
//! (`texture::shape`: image type, extent, levels, layers, CUBE_COMPATIBLE; the format of
//! `device::vk_format`) with the bytes `texture::depth_bytes` / `texture::stencil_bytes` give
//! (uploaded with vkCmdCopyBufferToImage, "Copying Data Between Buffers and Images"), the image
//! view and sampler of `sampler::state` ("Image Views", "Samplers"), one descriptor set; this part
//! is `vk_common.c`, the same for both stages. Then, by the lookup's stage:
//!
//! - fragment (`vk_fragment.c`): the graphics pipeline of the plan's shaders, the push constant
//!   `u_base` = 0 and the six vertices of slot 0 exactly as `vk/src/draw.rs` stages them, drawn in
//!   a render pass that clears the colour target to -1;
//! - compute (`vk_compute.c`): the compute pipeline of `compute_glsl` (`vk/src/compute.rs`), the
//!   descriptor set with the sampler at binding 0 and the result image as a storage image at
//!   binding 1 (GENERAL layout), the push constants `compute::push_constants(plan, 0)` gives (P, x,
//!   padding, pixel (0, 0): written as those bytes' fields), one vkCmdDispatch(1, 1, 1), and the
//!   barriers of `record_dispatches` around it. The worker clears the result image in the render
//!   pass of its draws before the dispatches; the reproducer, which draws nothing, clears it with
//!   vkCmdClearColorImage (the same -1 in every texel, made visible to the compute shader by a
//!   barrier). It records no draw before the dispatch on purpose: on SwiftShader a dispatch after
//!   a draw that sampled the same image gives a different (correct) result
//!   (reports/vulkan/repro/compute-cube-edge).
//!
//! Both read back pixel (0, 0) and judge it. One difference from the worker: it renders or stores
//! into a 256x256 image (slot k a 2x2 quad), the reproducer into a 2x2 one (the shaders written
//! for a framebuffer 2 pixels wide: one quad per row); slot 0's quad and its pixel (0, 0) are the
//! same pixels either way.
//!
//! What the device must have (a format feature, `imageCubeArray`, a border colour only
//! VK_EXT_custom_border_color gives, ...) is checked by the program at run time: the generator
//! assumes a device that has everything, as `sampler::state` is asked with full support; where
//! the device lacks it the program says so and exits 2 (the harness answers such a test Skip).

use super::{csource, io, ReproError, Subject, REPRO_C};
use ash::vk;
use shadowcheck_model::{ApiPath, Format, Stage};
use shadowcheck_plan::layout::CORNERS;
use shadowcheck_plan::shaders::vulkan::COMPUTE_PUSH_BYTES;
use shadowcheck_plan::shaders::{self, PARAM_ATTRIBS, PARAM_FLOATS};
use shadowcheck_plan::{paths, GatherCall, LookupForm, Plan, SamplerKind};
use shadowcheck_vk::device::{vk_format, FormatInfo, Support};
use shadowcheck_vk::sampler::{self, SamplerState};
use shadowcheck_vk::texture::{self, Shape};
use shadowcheck_vk::Driver;
use std::fmt::Write;
use std::path::Path;

/// The shader sources written beside repro.c: a fragment-stage lookup's two, a compute-stage
/// lookup's one.
pub const VERT_GLSL: &str = "vert.glsl";
pub const FRAG_GLSL: &str = "frag.glsl";
pub const COMP_GLSL: &str = "comp.glsl";

/// The build command of a fragment-stage lookup: the two shaders to SPIR-V, then the program.
pub const BUILD_LINE: &str = "glslangValidator --quiet -V -S vert -o vert.spv vert.glsl && glslangValidator --quiet -V -S frag -o frag.spv frag.glsl && gcc -std=c99 -O1 -Wall -o repro repro.c -lvulkan -lm";

/// The build command of a compute-stage lookup: the compute shader to SPIR-V, then the program.
pub const COMPUTE_BUILD_LINE: &str = "glslangValidator --quiet -V -S comp -o comp.spv comp.glsl && gcc -std=c99 -O1 -Wall -o repro repro.c -lvulkan -lm";

/// The build command of `s`'s reproducer.
pub fn build_line(s: &Subject) -> &'static str {
    if s.case.lookup.stage == Stage::Compute {
        COMPUTE_BUILD_LINE
    } else {
        BUILD_LINE
    }
}

/// The `key: value` lines the program prints about the device (`RunOutput::field`).
pub const FIELDS: [&str; 3] = ["VK_DEVICE", "VK_API_VERSION", "VK_DRIVER"];

/// Width and height of the program's colour target: one 2x2 quad, slot 0's.
const FB: i32 = 2;

/// Is the driver's ICD manifest installed (the run line points the loader at it)?
pub fn check_driver(d: Driver) -> Result<(), ReproError> {
    match d.icd() {
        Some((icd, install)) if !Path::new(icd).is_file() => Err(ReproError::BadBackend(format!(
            "vk:{}: {icd} not found; `{install}`",
            d.key()
        ))),
        _ => Ok(()),
    }
}

/// The Debian packages the build needs and those the run needs.
pub fn packages(d: Driver) -> (String, String) {
    let run = match d {
        Driver::Lavapipe => "libvulkan1 mesa-vulkan-drivers",
        // SwiftShader's Vulkan ICD as Debian ships it (with Chromium).
        Driver::Swiftshader => "libvulkan1 chromium-common",
        Driver::Native => "libvulkan1",
    };
    ("gcc libvulkan-dev glslang-tools".into(), run.into())
}

/// `VK_ICD_FILENAMES=<manifest>`, the worker's choice of driver; nothing for `vk:native`.
pub fn env_words(d: Driver) -> String {
    d.icd()
        .map(|(icd, _)| format!("VK_ICD_FILENAMES={icd}"))
        .unwrap_or_default()
}

/// A failed build, named by what is missing where the log says (the shader compiler, the Vulkan
/// headers or link library, the C compiler).
pub fn build_error(log: &str) -> ReproError {
    let missing = |what: &str, package: &str| ReproError::Missing {
        missing: what.into(),
        package: package.into(),
        log: log.into(),
    };
    if log.contains("glslangValidator: not found")
        || log.contains("glslangValidator: command not found")
    {
        missing("glslangValidator is not installed", "glslang-tools")
    } else if log.contains("vulkan/vulkan.h") {
        missing(
            "the Vulkan headers (vulkan/vulkan.h) are not installed",
            "libvulkan-dev",
        )
    } else if log.contains("-lvulkan") {
        missing(
            "the Vulkan link library (libvulkan.so) is not installed",
            "libvulkan-dev",
        )
    } else if log.contains("gcc: not found") || log.contains("gcc: command not found") {
        missing("no C compiler (gcc)", "gcc")
    } else {
        ReproError::Build {
            packages: format!("apt-get install -y {}", packages(Driver::Native).0),
            log: log.into(),
        }
    }
}

/// The sources of a reproducer: the program and its shaders, `vert` and `frag` for a
/// fragment-stage lookup, `comp` for a compute-stage one (the shaders the lookup does not use
/// are empty and not written).
pub struct Program {
    pub c: String,
    pub vert: String,
    pub frag: String,
    pub comp: String,
}

impl Program {
    /// The shader files to write beside repro.c, by name.
    pub fn shaders(&self) -> Vec<(&'static str, &str)> {
        [
            (VERT_GLSL, self.vert.as_str()),
            (FRAG_GLSL, self.frag.as_str()),
            (COMP_GLSL, self.comp.as_str()),
        ]
        .into_iter()
        .filter(|(_, text)| !text.is_empty())
        .collect()
    }
}

/// Writes repro.c, the shaders (vert.glsl and frag.glsl, or comp.glsl) and build.sh into `dir`
/// (created).
pub fn write_sources(s: &Subject, dir: &Path) -> Result<(), ReproError> {
    let p = program(s).map_err(ReproError::NotPlanned)?;
    std::fs::create_dir_all(dir).map_err(io(format!("creating {}", dir.display())))?;
    let build = super::build_sh(s);
    let mut files = vec![(REPRO_C, p.c.as_str())];
    files.extend(p.shaders());
    files.push((super::BUILD_SH, build.as_str()));
    for (name, text) in files {
        std::fs::write(dir.join(name), text).map_err(io(format!("writing {name}")))?;
    }
    Ok(())
}

/// A device that has every feature: the program checks the real one.
fn full_support() -> Support {
    Support {
        image_cube_array: true,
        gather_extended: true,
        mirror_clamp_to_edge: true,
        custom_border: true,
        max_lod_bias: f32::INFINITY,
        texel_offset: (i32::MIN, u32::MAX),
        gather_offset: (i32::MIN, u32::MAX),
        extensions: vec![],
    }
}

/// The program text and shaders, or why the worker would not draw this case (it Skips it).
pub fn program(s: &Subject) -> Result<Program, String> {
    if s.api != ApiPath::Vulkan {
        return Err(format!(
            "a Vulkan backend runs the `vk` path, not `{}`",
            s.api
        ));
    }
    // As the worker plans a job (`worker::plan_job`): the preferred order, no EXT_texture_shadow_lod.
    let plan = paths::plan_in(
        ApiPath::Vulkan,
        &s.case,
        &s.case.lookup,
        LookupForm::Auto,
        false,
    )?;
    let format = s.case.texture.format;
    let vkf = vk_format(format).ok_or_else(|| format!("format {format} has no Vulkan format"))?;
    let info = FormatInfo {
        format,
        vk: vkf,
        usable: true,
        filter_linear: true,
        depth_compare: Some(true),
    };
    let kind = paths::sampler_kind(&s.case);
    let state = sampler::state(&s.case, kind, &info, &full_support())?;
    let shape = texture::shape(&s.case)?;
    let compute = plan.key.stage == Stage::Compute;
    let run = format!("{} ./repro", env_words(driver(s)))
        .trim()
        .to_string();
    let lookup = if compute {
        "\n * comp.glsl is the worker's compute shader (build.sh compiles it to comp.spv), dispatched once\n * (one invocation) with slot 0's push constants; it stores its result at pixel (0, 0) of a 2x2\n * RGBA32F storage image cleared to -1"
    } else {
        " vert.glsl / frag.glsl are the worker's shaders (build.sh compiles them to\n * vert.spv / frag.spv), drawn as slot 0's 2x2 quad into a 2x2 RGBA32F image cleared to -1"
    };
    let mut c = format!(
        "/* shadowcheck reproducer: {test} on {backend}\n *\n * Build: {build}\n * Run:   {run}\n *        (add VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation to run it under the validation layer)\n *\n * Generated by `shadowcheck repro`: what shadowcheck's Vulkan worker does for this test, with no\n * shadowcheck code. Device: the loader's (the driver VK_ICD_FILENAMES names; of several, a GPU\n * before a CPU, as the worker picks for vk:native), with the worker's features. Image: the texel bytes the worker copies, the same view and sampler.\n * Lookup: {how};{lookup}.\n * Prints the device, the expected result (spec value and accepted set, computed by shadowcheck's\n * oracle, written here as constants) and the observed RGBA of pixel (0, 0); exits 1 when the\n * observation is outside the accepted set, 0 when inside, 2 when setup fails or the device lacks\n * what the test needs.\n */\n#include <vulkan/vulkan.h>\n#include <math.h>\n#include <stdint.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n",
        test = s.test(),
        backend = s.backend,
        build = build_line(s),
        how = plan.note,
    );
    c += &csource::expectation(s);
    c += csource::VERDICT;
    c += &image_and_sampler(&shape, vkf, &state, kind, &plan);
    c += &texels(s, &shape, format)?;
    if compute {
        c += &push_constants(&plan)?;
        c += MAIN;
        c += COMPUTE_MAIN;
        let comp = shaders::vulkan::compute_glsl(&plan.key);
        return Ok(Program {
            c,
            vert: String::new(),
            frag: String::new(),
            comp,
        });
    }
    let (vert, frag) = shaders::vulkan::glsl(&plan.key, FB);
    c += &vertices(&plan);
    c += MAIN;
    c += FRAGMENT_MAIN;
    Ok(Program {
        c,
        vert,
        frag,
        comp: String::new(),
    })
}

fn driver(s: &Subject) -> Driver {
    match s.backend {
        super::Backend::Vk(d) => d,
        super::Backend::Gl(_) | super::Backend::Webgpu(_) | super::Backend::Webgl(_) => {
            Driver::Native
        }
    }
}

/// `value /* NAME */`: a Vulkan enum as its number, named in a comment (`prefix` + ash's name,
/// e.g. `VK_FILTER_` + `LINEAR`; an image type's `TYPE_2D` is `VK_IMAGE_TYPE_2D`).
fn named(raw: i32, prefix: &str, debug: impl std::fmt::Debug) -> String {
    let d = format!("{debug:?}");
    let d = d.strip_prefix("TYPE_").unwrap_or(&d);
    format!("{raw} /* {prefix}{d} */")
}

fn aspect_names(a: vk::ImageAspectFlags) -> String {
    let mut n = vec![];
    if a.contains(vk::ImageAspectFlags::DEPTH) {
        n.push("VK_IMAGE_ASPECT_DEPTH_BIT");
    }
    if a.contains(vk::ImageAspectFlags::STENCIL) {
        n.push("VK_IMAGE_ASPECT_STENCIL_BIT");
    }
    format!("0x{:x} /* {} */", a.as_raw(), n.join(" | "))
}

fn flag(b: bool) -> &'static str {
    if b {
        "1"
    } else {
        "0"
    }
}

/// The image, view and sampler create infos (case state as numbers, named in comments), what the
/// device must have for them, and the texel offset the lookup uses.
fn image_and_sampler(
    shape: &Shape,
    vkf: vk::Format,
    st: &SamplerState,
    kind: SamplerKind,
    plan: &Plan,
) -> String {
    let e = shape.extent;
    let cube = shape.flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE);
    let fmt = named(vkf.as_raw(), "VK_FORMAT_", vkf);
    let all_aspects = if vk_has_stencil(vkf) {
        vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL
    } else {
        vk::ImageAspectFlags::DEPTH
    };
    let addr = |m: vk::SamplerAddressMode| named(m.as_raw(), "VK_SAMPLER_ADDRESS_MODE_", m);
    let filter = |f: vk::Filter| named(f.as_raw(), "VK_FILTER_", f);
    let compare = st.compare.unwrap_or(vk::CompareOp::NEVER);
    let linear = [st.mag, st.min].contains(&vk::Filter::LINEAR)
        || st.mipmap == vk::SamplerMipmapMode::LINEAR;
    let mut out = format!(
        "/* The image (\"Images\"), as vk/src/texture.rs `shape` makes it. */\nstatic const VkImageCreateInfo IMAGE = {{\n    .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,\n    .flags = {flags},\n    .imageType = {ty},\n    .format = {fmt},\n    .extent = {{{w}, {h}, 1}},\n    .mipLevels = {levels},\n    .arrayLayers = {layers},\n    .samples = VK_SAMPLE_COUNT_1_BIT,\n    .tiling = VK_IMAGE_TILING_OPTIMAL,\n    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,\n    .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,\n}};\n#define IMAGE_ASPECTS ({aspects})\n#define FORMAT_NAME \"VK_FORMAT_{fmt_name:?}\"\n\n/* The view (\"Image Views\") and the sampler (\"Samplers\") of vk/src/sampler.rs `state`. */\nstatic const VkImageViewCreateInfo VIEW = {{\n    .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,\n    .viewType = {view},\n    .format = {fmt},\n    .subresourceRange = {{{aspect}, 0, {view_levels}, 0, {layers}}},\n}};\nstatic const VkSamplerCreateInfo SAMPLER = {{\n    .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,\n    .magFilter = {mag},\n    .minFilter = {min},\n    .mipmapMode = {mip},\n    .addressModeU = {u},\n    .addressModeV = {v},\n    .addressModeW = {wm},\n    .mipLodBias = {bias},\n    .anisotropyEnable = VK_FALSE,\n    .compareEnable = {cmp_on},\n    .compareOp = {cmp},\n    .minLod = {min_lod},\n    .maxLod = {max_lod},\n    .borderColor = {border},\n    .unnormalizedCoordinates = VK_FALSE,\n}};\n",
        flags = if cube {
            "0x10 /* VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT */"
        } else {
            "0"
        },
        ty = named(shape.image_type.as_raw(), "VK_IMAGE_TYPE_", shape.image_type),
        w = e.width,
        h = e.height,
        levels = shape.levels,
        layers = shape.layers,
        fmt_name = vkf,
        aspects = aspect_names(all_aspects),
        view = named(shape.view_type.as_raw(), "VK_IMAGE_VIEW_TYPE_", shape.view_type),
        aspect = aspect_names(st.aspect),
        view_levels = st.view_levels,
        mag = filter(st.mag),
        min = filter(st.min),
        mip = named(st.mipmap.as_raw(), "VK_SAMPLER_MIPMAP_MODE_", st.mipmap),
        u = addr(st.address[0]),
        v = addr(st.address[1]),
        wm = addr(st.address[2]),
        bias = csource::cf(st.lod_bias),
        cmp_on = if st.compare.is_some() {
            "VK_TRUE"
        } else {
            "VK_FALSE"
        },
        cmp = named(compare.as_raw(), "VK_COMPARE_OP_", compare),
        min_lod = csource::cf(st.min_lod),
        max_lod = csource::cf(st.max_lod),
        border = named(st.border.as_raw(), "VK_BORDER_COLOR_", st.border),
    );
    if let Some(c) = st.custom_border {
        let v: Vec<String> = c.iter().map(|x| csource::cf(*x)).collect();
        let _ = writeln!(
            out,
            "/* VK_EXT_custom_border_color's colour (VkSamplerCustomBorderColorCreateInfoEXT). */\nstatic const float CUSTOM_BORDER_COLOR[4] = {{{}}};",
            v.join(", ")
        );
    }
    let mut offsets = vec![plan.key.offset];
    if let Some(GatherCall::Offsets(o)) = plan.key.gather {
        offsets.extend(o);
    }
    let offsets: Vec<String> = offsets
        .iter()
        .map(|o| format!("{{{}, {}}}", o[0], o[1]))
        .collect();
    let _ = write!(
        out,
        "\n/* What the device must have for this test (checked at run time; without it the harness\n * answers the test Skip). */\n#define NEED_IMAGE_CUBE_ARRAY {}\n#define NEED_MIRROR_CLAMP_TO_EDGE {}\n#define NEED_CUSTOM_BORDER_COLOR {}\n/* LINEAR filtering without comparison needs SAMPLED_IMAGE_FILTER_LINEAR (\"Texel Filtering\"). */\n#define NEED_FILTER_LINEAR {}\n#define NEED_DEPTH_COMPARISON {}\n/* textureGatherOffsets' four offsets need shaderImageGatherExtended. */\n#define NEED_GATHER_EXTENDED {}\n/* The lookup's texel offsets (GLSL `*Offset`, and textureGatherOffsets' four), within\n * minTexelOffset..maxTexelOffset (a gather's: minTexelGatherOffset..maxTexelGatherOffset). */\n#define IS_GATHER {}\nstatic const int TEXEL_OFFSETS[][2] = {{{}}};\n\n",
        flag(shape.view_type == vk::ImageViewType::CUBE_ARRAY),
        flag(st.address.contains(&vk::SamplerAddressMode::MIRROR_CLAMP_TO_EDGE)),
        flag(st.custom_border.is_some()),
        flag(kind != SamplerKind::Shadow && linear),
        flag(kind == SamplerKind::Shadow),
        flag(matches!(plan.key.gather, Some(GatherCall::Offsets(_)))),
        flag(plan.key.gather.is_some()),
        offsets.join(", "),
    );
    out
}

fn vk_has_stencil(f: vk::Format) -> bool {
    matches!(
        f,
        vk::Format::D24_UNORM_S8_UINT | vk::Format::D32_SFLOAT_S8_UINT
    )
}

/// The texel bytes of every level and aspect as C arrays, and the copies that upload them.
fn texels(s: &Subject, shape: &Shape, format: Format) -> Result<String, String> {
    let mut data = String::from(
        "/* The texels: the bytes shadowcheck's worker copies (vk/src/texture.rs `depth_bytes`,\n * `stencil_bytes`), per level and aspect, tightly packed (x, then y, then layer). */\n",
    );
    let mut uploads = String::new();
    let rows = |vals: Vec<String>| {
        vals.chunks(8)
            .map(|c| format!("    {}", c.join(", ")))
            .collect::<Vec<_>>()
            .join(",\n")
    };
    for (i, lvl) in s.case.texture.levels.iter().enumerate() {
        let bytes = texture::depth_bytes(format, lvl)?;
        let (cty, vals, note): (&str, Vec<String>, &str) = match format {
            Format::D16 => (
                "uint16_t",
                bytes
                    .chunks_exact(2)
                    .map(|c| u16::from_ne_bytes([c[0], c[1]]).to_string())
                    .collect(),
                "",
            ),
            Format::D32f | Format::D32fS8 => (
                "float",
                bytes
                    .chunks_exact(4)
                    .map(|c| csource::cf(f32::from_ne_bytes([c[0], c[1], c[2], c[3]])))
                    .collect(),
                " (clamped to [0, 1], as a copy into D32_SFLOAT must be)",
            ),
            _ => (
                "uint32_t",
                bytes
                    .chunks_exact(4)
                    .map(|c| format!("{}u", u32::from_ne_bytes([c[0], c[1], c[2], c[3]])))
                    .collect(),
                " (the 24-bit value in the low bits of a 32-bit word)",
            ),
        };
        let (w, h) = (
            (shape.extent.width >> i).max(1),
            (shape.extent.height >> i).max(1),
        );
        let _ = writeln!(
            data,
            "/* level {i}, depth aspect: {w}x{h}x{layers}{note} */\nstatic const {cty} DEPTH{i}[] = {{\n{}\n}};",
            rows(vals),
            layers = shape.layers,
        );
        let _ = writeln!(
            uploads,
            "    {{DEPTH{i}, sizeof DEPTH{i}, VK_IMAGE_ASPECT_DEPTH_BIT, {i}, {w}, {h}}},"
        );
        if format.has_stencil() {
            let st: Vec<String> = texture::stencil_bytes(lvl)
                .iter()
                .map(|b| b.to_string())
                .collect();
            let _ = writeln!(
                data,
                "/* level {i}, stencil aspect */\nstatic const uint8_t STENCIL{i}[] = {{\n{}\n}};",
                rows(st)
            );
            let _ = writeln!(
                uploads,
                "    {{STENCIL{i}, sizeof STENCIL{i}, VK_IMAGE_ASPECT_STENCIL_BIT, {i}, {w}, {h}}},"
            );
        }
    }
    Ok(format!(
        "{data}static const struct {{\n    const void *data;\n    size_t size;\n    VkImageAspectFlags aspect;\n    uint32_t level, width, height;\n}} UPLOADS[] = {{\n{uploads}}};\n\n"
    ))
}

/// Slot 0's six vertices as `vk/src/draw.rs` stages them, and the vertex inputs that read them.
fn vertices(plan: &Plan) -> String {
    let v4 = |v: [f32; 4]| {
        v.iter()
            .map(|x| csource::cf(*x))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut rows = String::new();
    for corner in CORNERS {
        let _ = writeln!(
            rows,
            "    {{{}, {}, /* x, k, unit */ {}, 0.0f, 0.0f, /* P */ {}, /* dx */ {}, /* dy */ {}}},",
            csource::cf(corner[0]),
            csource::cf(corner[1]),
            csource::cf(plan.x),
            v4(plan.p),
            v4(plan.dx),
            v4(plan.dy),
        );
    }
    let mut attrs = String::new();
    for &(loc, name, size, at) in PARAM_ATTRIBS.iter() {
        let f = match size {
            1 => "VK_FORMAT_R32_SFLOAT",
            2 => "VK_FORMAT_R32G32_SFLOAT",
            3 => "VK_FORMAT_R32G32B32_SFLOAT",
            _ => "VK_FORMAT_R32G32B32A32_SFLOAT",
        };
        let _ = writeln!(attrs, "    {{{loc}, {f}, {at}}}, /* {name} */");
    }
    format!(
        "/* Slot 0's quad: six vertices of PARAM_FLOATS floats (corner, (x, k, unit), P, dx, dy; the\n * flat inputs of the shaders), as shadowcheck's worker stages them (vk/src/draw.rs). P = ({p}),\n * x (LOD / bias / compare value) = {x}. */\n#define FB {FB}\n#define PARAM_FLOATS {PARAM_FLOATS}\nstatic const float VERTICES[6][PARAM_FLOATS] = {{\n{rows}}};\nstatic const struct {{\n    uint32_t location;\n    VkFormat format;\n    uint32_t offset_floats;\n}} ATTRIBS[] = {{\n{attrs}}};\n\n",
        p = v4(plan.p),
        x = csource::cf(plan.x),
    )
}

/// The push constants of slot 0's compute-stage lookup, exactly the bytes the worker pushes
/// (`shadowcheck_vk::compute::push_constants(plan, 0)`, read back into their fields: P at offset
/// 0, x at 16, 4 bytes of padding, the pixel at 24), and the result image's size.
fn push_constants(plan: &Plan) -> Result<String, String> {
    let b = shadowcheck_vk::compute::push_constants(plan, 0);
    let word = |i: usize| -> Result<[u8; 4], String> {
        b.get(i..i + 4)
            .and_then(|w| w.try_into().ok())
            .ok_or_else(|| {
                format!(
                    "the worker's push constants are {} bytes, not {COMPUTE_PUSH_BYTES}",
                    b.len()
                )
            })
    };
    if b.len() != COMPUTE_PUSH_BYTES as usize {
        return Err(format!(
            "the worker's push constants are {} bytes, not {COMPUTE_PUSH_BYTES}",
            b.len()
        ));
    }
    let f = |i: usize| word(i).map(|w| csource::cf(f32::from_ne_bytes(w)));
    let n = |i: usize| word(i).map(i32::from_ne_bytes);
    let p = [f(0)?, f(4)?, f(8)?, f(12)?].join(", ");
    let x = f(16)?;
    let pad = u32::from_ne_bytes(word(20)?);
    let (ax, ay) = (n(24)?, n(28)?);
    Ok(format!(
        "/* Slot 0's push constants, the bytes shadowcheck's worker pushes for it (vk/src/compute.rs\n * `push_constants`): comp.glsl's block `vec4 u_p; float u_x; ivec2 u_at;` at offsets 0, 16 and\n * 24 ({COMPUTE_PUSH_BYTES} bytes; 4 bytes of padding align the ivec2 to 8).\n * P = ({p}), x (LOD / bias / compare value) = {x},\n * the pixel slot 0's invocation stores at = ({ax}, {ay}). */\n#define FB {FB}\nstatic const struct {{\n    float u_p[4];\n    float u_x;\n    uint32_t padding;\n    int32_t u_at[2];\n}} PUSH = {{{{{p}}}, {x}, {pad}u, {{{ax}, {ay}}}}};\ntypedef char push_constants_are_{COMPUTE_PUSH_BYTES}_bytes[sizeof PUSH == {COMPUTE_PUSH_BYTES} ? 1 : -1];\n\n"
    ))
}

/// Device, image, view, sampler, descriptor set, upload, read-back, verdict: the fixed part of
/// the program that both stages share. A fragment of C, not a program of its own.
const MAIN: &str = include_str!("vk_common.c");

/// The fragment stage's target, graphics pipeline and commands (the draw of slot 0's quad).
const FRAGMENT_MAIN: &str = include_str!("vk_fragment.c");

/// The compute stage's result image, compute pipeline and commands (the dispatch of slot 0's
/// lookup).
const COMPUTE_MAIN: &str = include_str!("vk_compute.c");

#[cfg(test)]
#[path = "vulkan_tests.rs"]
mod tests;
