//! The small cases the witnesses are built from: one-level D16 images, float and border cases,
//! mip chains, gathers, the DEPTH_TEXTURE_MODE, stencil, colour and completeness cases, each with
//! the values that make one rule visible.

use shadowcheck_model::*;

/// D16 integer for x (exact for the values used here).
pub(super) fn d16(x: f64) -> u32 {
    (x * 65535.0).round() as u32
}

/// A 2D case with one `w`×`h` level of unorm D16 texels, NEAREST, Dref 0.5, lookup at the centre.
pub(super) fn case(spec: Spec, w: u32, h: u32, texels: Vec<u32>, func: CompareFunc) -> Case {
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

pub(super) fn gl(texels: Vec<u32>, w: u32, func: CompareFunc) -> Case {
    case(Spec::Gl46, w, 1, texels, func)
}

pub(super) fn float1(dt: f32, dref: f64, func: CompareFunc) -> Case {
    let mut c = gl(vec![0], 1, func);
    c.texture.format = Format::D32f;
    c.texture.levels[0].depth = Texels::Float(vec![dt]);
    c.lookup.dref = dref;
    c
}

pub(super) fn linear_pair() -> Case {
    // 2x1 [Dt 0, Dt 1], s = ½, LEQUAL with Dref ½: PCF gives ½.
    let mut c = gl(vec![0, 65535], 2, CompareFunc::Lequal);
    c.sampler.min_filter = Filter::Linear;
    c.sampler.mag_filter = Filter::Linear;
    c
}

pub(super) fn border(format: Format, func: CompareFunc, border: [f32; 4], dref: f64) -> Case {
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

pub(super) fn mips(filter: Filter, lod: f64) -> Case {
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
pub(super) fn gather4() -> Case {
    let mut c = gl(vec![0, d16(0.25), d16(0.75), 65535], 2, CompareFunc::Lequal);
    c.texture.levels[0].height = 2;
    c.lookup.gather = Some(Gather { offsets: None });
    c
}

/// [`gather4`] on a 4x2 image [0, ¼, 1, 1 / ¾, 1, 1, 1] moved one texel right by an offset
/// delivered as a uniform: the footprint is texels 1 and 2 of both rows, (τi0j1, τi1j1, τi1j0,
/// τi0j0) = (1, 1, 1, ¼) → (1, 1, 1, 0); at offset 0 it is texels 0 and 1, (¾, 1, ¼, 0) →
/// (1, 1, 0, 0).
pub(super) fn gather_offset_from_a_uniform() -> Case {
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
/// `mips` at the fragment λ 1 drawn in stage `stage` (λ_base 0 there, GLSL 4.60 §8.9), on the
/// core path (the one path with vertex and compute lookups alike).
pub(super) fn stage_mips(stage: Stage) -> Case {
    let mut c = with_api(mips(Filter::NearestMipmapNearest, 1.0), ApiPath::GlslCore);
    c.lookup.stage = stage;
    c
}

pub(super) fn with_api(mut c: Case, api: ApiPath) -> Case {
    c.api = vec![api];
    c
}

pub(super) fn with_dref(mut c: Case, dref: f64) -> Case {
    c.lookup.dref = dref;
    c
}

/// ARB_shadow_ambient, one texel: `fail_value` is TEXTURE_COMPARE_FAIL_VALUE_ARB.
pub(super) fn ambient(texel: u32, fail_value: f32) -> Case {
    let mut c = case(Spec::ArbAmbient, 1, 1, vec![texel], CompareFunc::Lequal);
    c.sampler.fail_value = Some(fail_value);
    c
}

/// One texel on `api` with DEPTH_TEXTURE_MODE `mode` (`None`: the default).
pub(super) fn depth_mode(api: ApiPath, texel: u32, mode: Option<DepthTextureMode>) -> Case {
    let mut c = with_api(gl(vec![texel], 1, CompareFunc::Lequal), api);
    c.sampler.depth_texture_mode = mode;
    c
}

/// A D24S8 texel (Dt 0, stencil 7) read with DEPTH_STENCIL_TEXTURE_MODE STENCIL_INDEX.
pub(super) fn stencil_index() -> Case {
    let mut c = gl(vec![0], 1, CompareFunc::Lequal);
    c.texture.format = Format::D24S8;
    c.texture.levels[0].stencil = Some(vec![7]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c
}

/// One R8 texel with TEXTURE_COMPARE_MODE `mode`.
pub(super) fn r8(texel: u32, mode: CompareMode) -> Case {
    let mut c = gl(vec![texel], 1, CompareFunc::Lequal);
    c.texture.format = Format::R8;
    c.sampler.compare_mode = mode;
    c
}

/// One texel of a colour texture of several components, compare mode on (bypassed).
pub(super) fn colour(format: Format, texel: [u32; 4]) -> Case {
    let mut c = gl(vec![0], 1, CompareFunc::Lequal);
    c.texture.format = format;
    c.texture.levels[0].depth = Texels::Colour(vec![texel]);
    c
}

/// A one-level 2x1 D24S8 texture read as STENCIL_INDEX with a mipmap filter: incomplete (level 1
/// is missing), (0,0,0,1).
pub(super) fn stencil_incomplete() -> Case {
    let mut c = gl(vec![0, 0], 2, CompareFunc::Lequal);
    c.texture.format = Format::D24S8;
    c.texture.levels[0].stencil = Some(vec![7, 7]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.min_filter = Filter::NearestMipmapNearest;
    c
}

/// A 2x2 single-level texture with a mipmap filter: mipmap-incomplete.
pub(super) fn mip_incomplete() -> Case {
    let mut c = case(Spec::Gl46, 2, 2, vec![65535; 4], CompareFunc::Lequal);
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    c
}

/// ES 3.2, a sized depth format with compare mode NONE and LINEAR filtering (incomplete, §8.17).
pub(super) fn es_linear_depth() -> Case {
    let mut c = case(Spec::Gles32, 1, 1, vec![65535], CompareFunc::Lequal);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.min_filter = Filter::Linear;
    c
}

/// A projective lookup, q = 2: (s, t) = (¾, ¼) reads texel 1 (Dt 0.6), Dref 1.2 / 2 = 0.6.
pub(super) fn projective() -> Case {
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
pub(super) fn layer_one_and_a_half() -> Case {
    let mut c = gl(vec![0, 0, 65535], 1, CompareFunc::Lequal);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0].layers = 3;
    c.lookup.coord[2] = 1.5;
    c
}

/// A cube of 2x2 faces holding `texels` (24, face by face).
pub(super) fn cube(texels: Vec<u32>) -> Case {
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
pub(super) fn cube_neg_y() -> Case {
    let mut texels = vec![0; 24];
    texels[12] = 65535;
    texels[13] = 65535;
    let mut c = cube(texels);
    c.lookup.coord = [0.1, -1.0, 0.5, 1.0];
    c
}

/// As `seamless_cube_edge_in_es`: LINEAR near the +X/+Z edge with the GL enable on: column i0
/// comes from +Z and passes, r = 0.4; per-face filtering reads +X only, r = 0.
pub(super) fn seamless_edge() -> Case {
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
pub(super) fn vulkan(mut c: Case) -> Case {
    c.spec = Spec::Vulkan;
    c.api = vec![ApiPath::Vulkan];
    c.sampler.seamless = None;
    c
}

/// `c` as a WebGPU lookup: the `wgsl` path, no GL-only state (cube views are seamless).
pub(super) fn webgpu(mut c: Case) -> Case {
    c.spec = Spec::WebGpu;
    c.api = vec![ApiPath::Wgsl];
    c.sampler.seamless = None;
    c
}

/// A 1x1x3 D16 array [Dt 0, 0, 1], array_index −1, LEQUAL Dref ½: clamped to layer 0 (fails,
/// r = 0, WGSL); wrapped modulo 3 it reads layer 2 (passes, r = 1).
pub(super) fn array_index_minus_one() -> Case {
    let mut c = layer_one_and_a_half();
    c.lookup.coord[2] = -1.0;
    webgpu(c)
}

/// A cube array of two cubes of 1x1 faces, cube 1 all Dt 1 and cube 0 all Dt 0, direction +X,
/// array_index 1, LEQUAL Dref ½: cube 1's +X (layer 6) passes, r = 1; counted in layers, index
/// 1 + face 0 reads cube 0's −X (layer 1), which fails.
pub(super) fn cube_array_index_one() -> Case {
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
pub(super) fn mips_lod_bias() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 0.0);
    c.sampler.lod_bias = 1.0;
    c
}

/// `mips` at λ = 1 clamped by TEXTURE_MAX_LOD 0.4: level 0 fails.
pub(super) fn mips_max_lod() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.sampler.max_lod = 0.4;
    c
}

/// `mips` at λ = 1 with TEXTURE_MAX_LEVEL 0: level 0 fails.
pub(super) fn mips_max_level() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.sampler.max_level = Some(0);
    c
}

/// s = 0.3 on 4 texels: u = 1.2, i = 1 -> (3) − mirror(1 − 4) = 3 − 2 = 1.
pub(super) fn mirrored_repeat() -> Case {
    let mut c = gl(vec![65535, 0, 0, 0], 4, CompareFunc::Lequal);
    c.sampler.wrap_s = Wrap::MirroredRepeat;
    c.lookup.coord[0] = 0.3;
    c
}

/// s = 0.125 on [1, 0, 0, 0]: texel 0 passes; offset +1 reads texel 1 (Dt 0), which fails.
pub(super) fn offset_one() -> Case {
    let mut c = gl(vec![65535, 0, 0, 0], 4, CompareFunc::Lequal);
    c.lookup.coord[0] = 0.125;
    c.lookup.offset = [1, 0, 0];
    c
}

/// Level 1 (2x2) = [1, 0 / 1, 0], s = 0.1: u = 0.2 + 1 reads texel 1 (fails); one base-level
/// texel is half a level-1 texel, u = 0.7 reads texel 0 (passes).
pub(super) fn offset_on_level_one() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.texture.levels[1].depth = Texels::Unorm(vec![65535, 0, 65535, 0]);
    c.lookup.coord[0] = 0.1;
    c.lookup.offset = [1, 0, 0];
    c
}

/// REPEAT, s = 0.875 on [0, 0, 0, 1]: u = 3.5 + 1 wraps to texel 0 (fails); the faulty unit
/// wraps first (texel 3), then adds 1 and clamps back to texel 3 (passes).
pub(super) fn offset_across_repeat() -> Case {
    let mut c = gl(vec![0, 0, 0, 65535], 4, CompareFunc::Lequal);
    c.sampler.wrap_s = Wrap::Repeat;
    c.lookup.coord[0] = 0.875;
    c.lookup.offset = [1, 0, 0];
    c
}

/// LINEAR, layer coordinate 0.5: ⌊0.5 + 1/2⌋ = layer 1 (passes); RNE gives layer 0.
pub(super) fn linear_layer_half() -> Case {
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
pub(super) fn gather_at_lod_one() -> Case {
    let mut c = mips(Filter::NearestMipmapNearest, 1.0);
    c.lookup.gather = Some(Gather { offsets: None });
    c.lookup.coord[1] = 0.375;
    c.lookup.coord[0] = 0.375;
    c
}

/// One passing D16 texel under `func` with TEXTURE_SWIZZLE_R = ZERO.
pub(super) fn red_swizzled_to_zero(func: CompareFunc) -> Case {
    let mut c = gl(vec![65535], 1, func);
    c.sampler.swizzle = Some([Swizzle::Zero, Swizzle::Green, Swizzle::Blue, Swizzle::Alpha]);
    c
}

/// `gather4` with TEXTURE_SWIZZLE_RGBA `swizzle`.
pub(super) fn gather_swizzled(swizzle: [Swizzle; 4]) -> Case {
    let mut c = gather4();
    c.sampler.swizzle = Some(swizzle);
    c
}

/// Texture LEQUAL passes (r = 1); the bound sampler object's GREATER fails (r = 0).
pub(super) fn sampler_object_greater() -> Case {
    let mut c = gl(vec![65535], 1, CompareFunc::Lequal);
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Greater;
    c.sampler.sampler_object = Some(o);
    c
}

/// `gather4` (LEQUAL: (1, 1, 0, 0)) with a bound sampler object whose GEQUAL gives (0, 0, 1, 1)
/// (GL 4.6 §8.17.1); the faulty unit gathers with the texture's LEQUAL.
pub(super) fn gather_with_sampler_object() -> Case {
    let mut c = gather4();
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Gequal;
    c.sampler.sampler_object = Some(o);
    c
}

/// Fixed function, DEPTH_TEXTURE_MODE ALPHA, the texel passes: Table 16.1 gives (0, 0, 0, 1);
/// swizzle (ALPHA, ONE, RED, ZERO) makes it (1, 1, 0, 0) (§15.2.1). The faulty unit returns
/// (0, 0, 0, 1).
pub(super) fn compat_alpha_swizzled() -> Case {
    let mut c = depth_mode(ApiPath::FixedFunction, 65535, Some(DepthTextureMode::Alpha));
    c.sampler.swizzle = Some([Swizzle::Alpha, Swizzle::One, Swizzle::Red, Swizzle::Zero]);
    c
}

/// A 2x1 rectangle [Dt 1, Dt 0] (texture wrap CLAMP_TO_EDGE) with a sampler object whose wrap S
/// is REPEAT, looked up at s = 2.5: the texture is incomplete (GL 4.6 §8.2), core returns 0 →
/// (0, 0, 0, 1). Sampling with REPEAT reads texel 2.5 mod 2 → 0 (Dt 1 passes LEQUAL 0.5) →
/// (1, 0, 0, 1).
pub(super) fn rect_with_repeat_sampler_object() -> Case {
    let mut c = gl(vec![65535, 0], 2, CompareFunc::Lequal);
    c.texture.target = Target::Rect;
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.wrap_s = Wrap::Repeat;
    c.sampler.sampler_object = Some(o);
    c.lookup.coord[0] = 2.5;
    c
}
