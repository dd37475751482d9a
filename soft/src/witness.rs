//! A witness for every seedable fault: a small case (and API path) on which the faulty unit's
//! RGBA differs from the correct unit's. The test below proves each fault switch is live; the
//! mutants command can use the witnesses to tell "the suite misses this fault" from "the fault
//! is dead code".

use crate::faults::Fault;
use shadowcheck_model::*;

/// D16 integer for x (exact for the values used here).
fn d16(x: f64) -> u32 {
    (x * 65535.0).round() as u32
}

/// A 2D case with one `w`×`h` level of unorm D16 texels, NEAREST, Dref 0.5, lookup at the centre.
fn case(spec: Spec, w: u32, h: u32, texels: Vec<u32>, func: CompareFunc) -> Case {
    Case {
        sweep: vec![],
        id: "witness".into(),
        spec,
        api: vec![match spec {
            Spec::Gl46 => ApiPath::GlslCore,
            Spec::Gles32 => ApiPath::Es300,
            Spec::Es2Ext => ApiPath::Es100Ext,
            _ => ApiPath::FixedFunction,
        }],
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: w,
                height: h,
                layers: 1,
                depth: Texels::Unorm(texels),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, func, Filter::Nearest),
        lookup: Lookup {
            coord: [0.5, 0.5, 0.0, 1.0],
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
    }
}

fn gl(texels: Vec<u32>, w: u32, func: CompareFunc) -> Case {
    case(Spec::Gl46, w, 1, texels, func)
}

fn float1(dt: f32, dref: f64, func: CompareFunc) -> Case {
    let mut c = gl(vec![0], 1, func);
    c.texture.format = Format::D32f;
    c.texture.levels[0].depth = Texels::Float(vec![dt]);
    c.lookup.dref = dref;
    c
}

fn linear_pair() -> Case {
    // 2x1 [Dt 0, Dt 1], s = ½, LEQUAL with Dref ½: PCF gives ½.
    let mut c = gl(vec![0, 65535], 2, CompareFunc::Lequal);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c
}

fn border(format: Format, func: CompareFunc, border: [f32; 4], dref: f64) -> Case {
    let mut c = gl(vec![0, 0], 2, func);
    if format == Format::D32f {
        c.texture.format = format;
        c.texture.levels[0].depth = Texels::Float(vec![0.0, 0.0]);
    }
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = border;
    c.lookup.coord[0] = 1.5;
    c.lookup.dref = dref;
    c
}

fn mips(filter: Filter, lod: f64) -> Case {
    // 4x4 -> 2x2 -> 1x1; only level 1 passes.
    let mut c = case(Spec::Gl46, 4, 4, vec![0; 16], CompareFunc::Lequal);
    c.texture.levels.push(Level {
        width: 2,
        height: 2,
        layers: 1,
        depth: Texels::Unorm(vec![65535; 4]),
        stencil: None,
    });
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: Texels::Unorm(vec![0]),
        stencil: None,
    });
    c.sampler.min_filter = filter;
    c.lookup.lod = lod;
    c
}

/// A shadow gather on a 2x2 D16 image [0, ¼ / ¾, 1] at the centre, LEQUAL Dref ½: the footprint
/// is the whole image, (τi0j1, τi1j1, τi1j0, τi0j0) = (¾, 1, ¼, 0) → (1, 1, 0, 0).
fn gather4() -> Case {
    let mut c = gl(vec![0, d16(0.25), d16(0.75), 65535], 2, CompareFunc::Lequal);
    c.texture.levels[0].height = 2;
    c.lookup.gather = Some(Gather { offsets: None });
    c
}

/// [`gather4`] on a 4x2 image [0, ¼, 1, 1 / ¾, 1, 1, 1] moved one texel right by an offset
/// delivered as a uniform: the footprint is texels 1 and 2 of both rows, (τi0j1, τi1j1, τi1j0,
/// τi0j0) = (1, 1, 1, ¼) → (1, 1, 1, 0); at offset 0 it is texels 0 and 1, (¾, 1, ¼, 0) →
/// (1, 1, 0, 0).
fn gather_offset_from_a_uniform() -> Case {
    let one = 65535;
    let mut c = gl(
        vec![0, d16(0.25), one, one, d16(0.75), one, one, one],
        4,
        CompareFunc::Lequal,
    );
    c.texture.levels[0].height = 2;
    c.lookup.coord[0] = 0.25;
    c.lookup.gather = Some(Gather { offsets: None });
    c.lookup.offset = [1, 0, 0];
    c.lookup.delivery = Delivery::Uniform;
    c
}

/// `mips` looked up in the vertex shader with a fragment λ_base of 1: λ_base is 0 there (GLSL
/// 4.60 §8.9), so level 0 (Dt 0) fails LEQUAL ½; the fragment λ selects level 1 (Dt 1), which passes.
fn vertex_stage_mips() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.lookup.stage = Stage::Vertex;
    c
}

fn with_api(mut c: Case, api: ApiPath) -> Case {
    c.api = vec![api];
    c
}

fn with_dref(mut c: Case, dref: f64) -> Case {
    c.lookup.dref = dref;
    c
}

/// ARB_shadow_ambient, one texel: `fail_value` is TEXTURE_COMPARE_FAIL_VALUE_ARB.
fn ambient(texel: u32, fail_value: f32) -> Case {
    let mut c = case(Spec::ArbAmbient, 1, 1, vec![texel], CompareFunc::Lequal);
    c.sampler.fail_value = Some(fail_value);
    c
}

/// One texel on `api` with DEPTH_TEXTURE_MODE `mode` (`None`: the default).
fn depth_mode(api: ApiPath, texel: u32, mode: Option<DepthTextureMode>) -> Case {
    let mut c = with_api(gl(vec![texel], 1, CompareFunc::Lequal), api);
    c.sampler.depth_texture_mode = mode;
    c
}

/// A D24S8 texel (Dt 0, stencil 7) read with DEPTH_STENCIL_TEXTURE_MODE STENCIL_INDEX.
fn stencil_index() -> Case {
    let mut c = gl(vec![0], 1, CompareFunc::Lequal);
    c.texture.format = Format::D24S8;
    c.texture.levels[0].stencil = Some(vec![7]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c
}

/// One R8 texel with TEXTURE_COMPARE_MODE `mode`.
fn r8(texel: u32, mode: CompareMode) -> Case {
    let mut c = gl(vec![texel], 1, CompareFunc::Lequal);
    c.texture.format = Format::R8;
    c.sampler.compare_mode = mode;
    c
}

/// One texel of a colour texture of several components, compare mode on (bypassed).
fn colour(format: Format, texel: [u32; 4]) -> Case {
    let mut c = gl(vec![0], 1, CompareFunc::Lequal);
    c.texture.format = format;
    c.texture.levels[0].depth = Texels::Colour(vec![texel]);
    c
}

/// A one-level 2x1 D24S8 texture read as STENCIL_INDEX with a mipmap filter: incomplete (level 1
/// is missing), (0,0,0,1).
fn stencil_incomplete() -> Case {
    let mut c = gl(vec![0, 0], 2, CompareFunc::Lequal);
    c.texture.format = Format::D24S8;
    c.texture.levels[0].stencil = Some(vec![7, 7]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.min_filter = Filter::NearestMipmapNearest;
    c
}

/// A 2x2 single-level texture with a mipmap filter: mipmap-incomplete.
fn mip_incomplete() -> Case {
    let mut c = case(Spec::Gl46, 2, 2, vec![65535; 4], CompareFunc::Lequal);
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    c
}

/// ES 3.2, a sized depth format with compare mode NONE and LINEAR filtering (incomplete, §8.17).
fn es_linear_depth() -> Case {
    let mut c = case(Spec::Gles32, 1, 1, vec![65535], CompareFunc::Lequal);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.min_filter = Filter::Linear;
    c
}

/// A projective lookup, q = 2: (s, t) = (¾, ¼) reads texel 1 (Dt 0.6), Dref 1.2 / 2 = 0.6.
fn projective() -> Case {
    let mut c = case(
        Spec::Gl46,
        2,
        2,
        vec![0, d16(0.6), 0, 0],
        CompareFunc::Lequal,
    );
    c.lookup.coord = [1.5, 0.5, 0.0, 2.0];
    c.lookup.dref = 1.2;
    c.lookup.projective = true;
    c
}

/// A 1x1x3 array whose layer 2 passes, looked up at layer coordinate 1.5 (rounds to 2).
fn layer_one_and_a_half() -> Case {
    let mut c = gl(vec![0, 0, 65535], 1, CompareFunc::Lequal);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0].layers = 3;
    c.lookup.coord[2] = 1.5;
    c
}

/// A cube of 2x2 faces holding `texels` (24, face by face).
fn cube(texels: Vec<u32>) -> Case {
    let mut c = case(Spec::Gl46, 2, 2, vec![], CompareFunc::Lequal);
    c.texture.target = Target::Cube;
    c.texture.levels[0] = Level {
        width: 2,
        height: 2,
        layers: 6,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c
}

/// 2x2 faces; on -Y only row 0 passes. Direction (0.1, -1, 0.5): t_c = -r_z -> t = ¼, row 0.
fn cube_neg_y() -> Case {
    let mut texels = vec![0; 24];
    texels[12] = 65535;
    texels[13] = 65535;
    let mut c = cube(texels);
    c.lookup.coord = [0.1, -1.0, 0.5, 1.0];
    c
}

/// As `seamless_cube_edge_in_es`: LINEAR near the +X/+Z edge with the GL enable on: column i0
/// comes from +Z and passes, r = 0.4; per-face filtering reads +X only, r = 0.
fn seamless_edge() -> Case {
    let mut texels = vec![0; 24];
    texels[16..20].copy_from_slice(&[65535; 4]);
    let mut c = cube(texels);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c.sampler.seamless = Some(true);
    c.lookup.coord = [1.0, 0.0, 0.9, 1.0];
    c
}

/// `c` as a Vulkan lookup: the `vk` path, no GL-only state (Vulkan cubes are always seamless).
fn vulkan(mut c: Case) -> Case {
    c.spec = Spec::Vulkan;
    c.api = vec![ApiPath::Vulkan];
    c.sampler.seamless = None;
    c
}

/// `c` as a WebGPU lookup: the `wgsl` path, no GL-only state (cube views are seamless).
fn webgpu(mut c: Case) -> Case {
    c.spec = Spec::WebGpu;
    c.api = vec![ApiPath::Wgsl];
    c.sampler.seamless = None;
    c
}

/// A 1x1x3 D16 array [Dt 0, 0, 1], array_index −1, LEQUAL Dref ½: clamped to layer 0 (fails,
/// r = 0, WGSL); wrapped modulo 3 it reads layer 2 (passes, r = 1).
fn array_index_minus_one() -> Case {
    let mut c = layer_one_and_a_half();
    c.lookup.coord[2] = -1.0;
    webgpu(c)
}

/// A cube array of two cubes of 1x1 faces, cube 1 all Dt 1 and cube 0 all Dt 0, direction +X,
/// array_index 1, LEQUAL Dref ½: cube 1's +X (layer 6) passes, r = 1; counted in layers, index
/// 1 + face 0 reads cube 0's −X (layer 1), which fails.
fn cube_array_index_one() -> Case {
    let mut texels = vec![0; 6];
    texels.extend([65535; 6]);
    let mut c = cube(vec![]);
    c.texture.target = Target::CubeArray;
    c.texture.levels[0] = Level {
        width: 1,
        height: 1,
        layers: 12,
        depth: Texels::Unorm(texels),
        stencil: None,
    };
    c.lookup.coord = [1.0, 0.0, 0.0, 1.0];
    c.lookup.layer = 1.0;
    webgpu(c)
}

/// `mips` with NEAREST_MIPMAP_NEAREST at λ = 0 and TEXTURE_LOD_BIAS 1: level 1 passes.
fn mips_lod_bias() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 0.0);
    c.sampler.lod_bias = 1.0;
    c
}

/// `mips` at λ = 1 clamped by TEXTURE_MAX_LOD 0.4: level 0 fails.
fn mips_max_lod() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.sampler.max_lod = 0.4;
    c
}

/// `mips` at λ = 1 with TEXTURE_MAX_LEVEL 0: level 0 fails.
fn mips_max_level() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.sampler.max_level = Some(0);
    c
}

/// s = 0.3 on 4 texels: u = 1.2, i = 1 -> (3) − mirror(1 − 4) = 3 − 2 = 1.
fn mirrored_repeat() -> Case {
    let mut c = gl(vec![65535, 0, 0, 0], 4, CompareFunc::Lequal);
    c.sampler.wrap_s = Wrap::MirroredRepeat;
    c.lookup.coord[0] = 0.3;
    c
}

/// s = 0.125 on [1, 0, 0, 0]: texel 0 passes; offset +1 reads texel 1 (Dt 0), which fails.
fn offset_one() -> Case {
    let mut c = gl(vec![65535, 0, 0, 0], 4, CompareFunc::Lequal);
    c.lookup.coord[0] = 0.125;
    c.lookup.offset = [1, 0, 0];
    c
}

/// Level 1 (2x2) = [1, 0 / 1, 0], s = 0.1: u = 0.2 + 1 reads texel 1 (fails); one base-level
/// texel is half a level-1 texel, u = 0.7 reads texel 0 (passes).
fn offset_on_level_one() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.texture.levels[1].depth = Texels::Unorm(vec![65535, 0, 65535, 0]);
    c.lookup.coord[0] = 0.1;
    c.lookup.offset = [1, 0, 0];
    c
}

/// REPEAT, s = 0.875 on [0, 0, 0, 1]: u = 3.5 + 1 wraps to texel 0 (fails); the faulty unit
/// wraps first (texel 3), then adds 1 and clamps back to texel 3 (passes).
fn offset_across_repeat() -> Case {
    let mut c = gl(vec![0, 0, 0, 65535], 4, CompareFunc::Lequal);
    c.sampler.wrap_s = Wrap::Repeat;
    c.lookup.coord[0] = 0.875;
    c.lookup.offset = [1, 0, 0];
    c
}

/// LINEAR, layer coordinate 0.5: ⌊0.5 + 1/2⌋ = layer 1 (passes); RNE gives layer 0.
fn linear_layer_half() -> Case {
    let mut c = gl(vec![0, 0, 65535, 65535, 0, 0], 2, CompareFunc::Lequal);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0].layers = 3;
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c.lookup.coord[2] = 0.5;
    c
}

/// λ = 1 with a mipmap filter: level 1 (all Dt 1, every texel passes) would be read; the gather
/// reads level base (all Dt 0, every texel fails with Dref ½).
fn gather_at_lod_one() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.lookup.gather = Some(Gather { offsets: None });
    c.lookup.coord[1] = 0.375;
    c.lookup.coord[0] = 0.375;
    c
}

/// One passing D16 texel under `func` with TEXTURE_SWIZZLE_R = ZERO.
fn red_swizzled_to_zero(func: CompareFunc) -> Case {
    let mut c = gl(vec![65535], 1, func);
    c.sampler.swizzle = Some([Swizzle::Zero, Swizzle::Green, Swizzle::Blue, Swizzle::Alpha]);
    c
}

/// `gather4` with TEXTURE_SWIZZLE_RGBA `swizzle`.
fn gather_swizzled(swizzle: [Swizzle; 4]) -> Case {
    let mut c = gather4();
    c.sampler.swizzle = Some(swizzle);
    c
}

/// Texture LEQUAL passes (r = 1); the bound sampler object's GREATER fails (r = 0).
fn sampler_object_greater() -> Case {
    let mut c = gl(vec![65535], 1, CompareFunc::Lequal);
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Greater;
    c.sampler.sampler_object = Some(o);
    c
}

/// `gather4` (LEQUAL: (1, 1, 0, 0)) with a bound sampler object whose GEQUAL gives (0, 0, 1, 1)
/// (GL 4.6 §8.17.1); the faulty unit gathers with the texture's LEQUAL.
fn gather_with_sampler_object() -> Case {
    let mut c = gather4();
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Gequal;
    c.sampler.sampler_object = Some(o);
    c
}

/// Fixed function, DEPTH_TEXTURE_MODE ALPHA, the texel passes: Table 16.1 gives (0, 0, 0, 1);
/// swizzle (ALPHA, ONE, RED, ZERO) makes it (1, 1, 0, 0) (§15.2.1). The faulty unit returns
/// (0, 0, 0, 1).
fn compat_alpha_swizzled() -> Case {
    let mut c = depth_mode(ApiPath::FixedFunction, 65535, Some(DepthTextureMode::Alpha));
    c.sampler.swizzle = Some([Swizzle::Alpha, Swizzle::One, Swizzle::Red, Swizzle::Zero]);
    c
}

/// A 2x1 rectangle [Dt 1, Dt 0] (texture wrap CLAMP_TO_EDGE) with a sampler object whose wrap S
/// is REPEAT, looked up at s = 2.5: the texture is incomplete (GL 4.6 §8.2), core returns 0 →
/// (0, 0, 0, 1). Sampling with REPEAT reads texel 2.5 mod 2 → 0 (Dt 1 passes LEQUAL 0.5) →
/// (1, 0, 0, 1).
fn rect_with_repeat_sampler_object() -> Case {
    let mut c = gl(vec![65535, 0], 2, CompareFunc::Lequal);
    c.texture.target = Target::Rect;
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.wrap_s = Wrap::Repeat;
    c.sampler.sampler_object = Some(o);
    c.lookup.coord[0] = 2.5;
    c
}

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
        Fault::VertexLodFromDerivatives => vertex_stage_mips(),
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
