//! Where r appears in the RGBA an API path returns.

use crate::rules::{Incomplete, Rules};
use crate::sample::Kind;
use shadowcheck_model::{ApiPath, Channel, DepthTextureMode, Swizzle};
use Channel::{One, ROrZero, Unused, Zero, R};

/// The DEPTH_TEXTURE_MODE in effect: the sampler's, or the initial value (LUMINANCE: ARB_depth_texture
/// "Initially, depth textures are interpreted as LUMINANCE"; GL 4.6 compatibility §8.22).
/// A spec may fix the mode whatever the sampler says (`Rules::fixed_depth_mode`).
pub fn depth_mode(rules: &Rules, m: Option<DepthTextureMode>) -> DepthTextureMode {
    rules
        .fixed_depth_mode
        .or(m)
        .unwrap_or(DepthTextureMode::Luminance)
}

/// The fixed-function read-out: the worker draws with TexEnv COMBINE, COMBINE_RGB = COMBINE_ALPHA =
/// REPLACE, SOURCE0 = TEXTURE, OPERAND0 = SRC_COLOR / SRC_ALPHA (ARB_texture_env_combine, GL 2.1
/// §3.8.13: REPLACE yields Arg0, and these operands make Arg0 the texture's Cs and As), so the
/// fragment colour is the whole source colour of Table 3.20 / compatibility Table 16.1.
pub const FF_READ_OUT: &str = "GL 2.1 §3.8.14, Table 3.20; compatibility Table 16.1; read through TexEnv COMBINE REPLACE of (Cs, As) (GL 2.1 §3.8.13)";

/// The layout of r for `api`, with a citation. `incomplete`: the texture is incomplete (r = 0).
pub fn layout(
    rules: &Rules,
    api: ApiPath,
    kind: Kind,
    mode: Option<DepthTextureMode>,
    incomplete: bool,
) -> ([Channel; 4], &'static str) {
    let legacy = matches!(
        api,
        ApiPath::FixedFunction | ApiPath::ArbFp | ApiPath::Glsl120
    );
    let ff = api == ApiPath::FixedFunction;
    if incomplete {
        if ff {
            // GL 2.1 §3.8.10 / compatibility §8.17: texturing with an incomplete texture is "as if texture
            // mapping were disabled": the fragment colour passes through, r is not visible.
            return (
                [Unused; 4],
                "GL 2.1 §3.8.10 (incomplete: texturing disabled)",
            );
        }
        // A vec4 (non-shadow) result: (0,0,0,1) under ES 2.0 and GL 2.1, and under GL 4.6 / ES 3.2
        // §11.1.3.5 too: "(0.0, 0.0, 0.0, 1.0), in floating-point, will be returned for a non-shadow
        // sampler and 0 for a shadow sampler". G, B and A are checked, not only r.
        // A stencil read goes through an unsigned integer sampler, a non-shadow sampler reading a
        // supported combination (DEPTH_STENCIL in STENCIL_INDEX mode, usampler): the
        // "(0.0, 0.0, 0.0, 1.0) ... for a non-shadow sampler" of §11.1.3.5 with all four channels
        // checked; the sentence's "undefined values" are for unsupported combinations only.
        if kind == Kind::Stencil && !legacy {
            // A = 1 or the bits of 1.0f (contradiction `incomplete-uint-alpha`): channel `g3`
            // reads the set holding both (`engine::incomplete_texture`).
            return (
                [R, Zero, Zero, Channel::G3],
                "GL 4.6 / ES 3.2 §11.1.3.5: incomplete → (0,0,0,1) \"in floating-point\" for a non-shadow sampler, here an unsigned integer one",
            );
        }
        let vec4_0001 = matches!(kind, Kind::Depth | Kind::Colour)
            || (rules.incomplete == Incomplete::Legacy0001 && kind != Kind::Compare);
        if legacy || vec4_0001 {
            return (
                [R, Zero, Zero, One],
                match (legacy, rules.incomplete) {
                    (false, Incomplete::ShadowZero) => {
                        "GL 4.6 / ES 3.2 §11.1.3.5: incomplete → (0,0,0,1) for a non-shadow sampler"
                    }
                    _ => "GL 2.1 §3.11.2 / ARB_fragment_program_shadow: incomplete → (0,0,0,1)",
                },
            );
        }
        return (
            [R, Unused, Unused, Unused],
            "GL 4.6 / ES 3.2 §11.1.3.5: incomplete → 0 for a shadow sampler",
        );
    }
    match kind {
        Kind::Stencil => (
            [R, Zero, Zero, One],
            "GL 4.6 §11.1.3.5 (stencil read as an unsigned integer into Rt, Cb = (Rt,0,0,1))",
        ),
        Kind::Colour => {
            // A colour texture "operates in the normal manner": legacy specs know it as LUMINANCE8 (Table
            // 3.20: (Lt,Lt,Lt),1), GL 3.0+ / ES as R8 (Table 15.1: (Rt,0,0),1): `Rules::colour_luminance`.
            let base = if rules.colour_luminance {
                [R, R, R, One]
            } else {
                [R, Zero, Zero, One]
            };
            // Fixed function draws through TexEnv COMBINE / REPLACE of the texture's (Cs, As): the
            // source colour itself (see [`FF_READ_OUT`]).
            (
                base,
                if ff {
                    "GL 2.1 Table 3.20 (colour texture, comparison bypassed); §3.8.13 COMBINE REPLACE of (Cs, As)"
                } else {
                    "GL 2.1 Table 3.20 / GL 4.6 Table 15.1 (colour texture, comparison bypassed)"
                },
            )
        }
        Kind::Compare | Kind::Depth => {
            // GLSL 1.30 in a compatibility context reading a depth texture through a non-shadow sampler:
            // compatibility §8.23.1 still routes r by DEPTH_TEXTURE_MODE (Table 16.1).
            let compat_depth_read = api == ApiPath::Glsl130 && kind == Kind::Depth;
            if legacy || compat_depth_read {
                // GL 2.1 §3.8.14 / compatibility §8.23.1: "The resulting r is assigned to Rt, Lt, It, or At
                // if the value of DEPTH_TEXTURE_MODE is respectively RED, LUMINANCE, INTENSITY, or ALPHA";
                // Table 3.20 / 16.1 then give the source colour.
                let cs = by_depth_mode(depth_mode(rules, mode));
                if ff {
                    return (cs, FF_READ_OUT);
                }
                return (
                    cs,
                    "GL 2.1 §3.8.14, Table 3.20; GL 4.6 compatibility §8.23.1, Table 16.1",
                );
            }
            if api == ApiPath::Glsl130
                && kind == Kind::Compare
                && depth_mode(rules, mode) == DepthTextureMode::Alpha
            {
                // Two readings, both accepted (contradiction `compat-float-alpha`): compatibility
                // §11.1.3.5 returns Cs[0] of Cb = (Rt,0,0,1), i.e. r; §8.23.1 with Table 16.1 puts r
                // in At for ALPHA, Cb = (0,0,0,At), so Cs[0] = 0.
                return (
                    [ROrZero, Unused, Unused, Unused],
                    "GL 4.6 compatibility §11.1.3.5 (Cs[0] of (Rt,0,0,1)) or §8.23.1 + Table 16.1 (ALPHA: r in At, Cs[0] = 0)",
                );
            }
            match (api, kind) {
                // OES_depth_texture issue 2: a depth texture reads as LUMINANCE, (d,d,d,1).
                (ApiPath::Es100Ext, Kind::Depth) => (
                    [R, R, R, One],
                    "OES_depth_texture issue 2 (depth reads as LUMINANCE)",
                ),
                // EXT_shadow_samplers: "The resulting r is assigned to R_t"; shadow2DEXT returns a float.
                (ApiPath::Es100Ext, _) => (
                    [R, Unused, Unused, Unused],
                    "EXT_shadow_samplers §3.7.14.1 (r → R_t), shadow2DEXT returns float",
                ),
                // Vulkan 1.3 §16 Depth Compare Operation: the result "replaces the depth component
                // D"; an OpImageSampleDref* instruction's Result Type is a scalar float (SPIR-V
                // §3.37.10), its one component r.
                (ApiPath::Vulkan, _) => (
                    [R, Unused, Unused, Unused],
                    "Vulkan 1.3 §16 Depth Compare Operation (r replaces D); OpImageSampleDref* returns a scalar",
                ),
                // WGSL textureSampleCompare(Level): "Returns: A value in the range
                // [0.0..1.0]", an f32.
                (ApiPath::Wgsl, _) => (
                    [R, Unused, Unused, Unused],
                    "WGSL textureSampleCompare / textureSampleCompareLevel return an f32",
                ),
                // A non-shadow sampler on a depth texture: Cb = (Dt,0,0,1) (§11.1.3.5, Table 15.1).
                (_, Kind::Depth) => (
                    [R, Zero, Zero, One],
                    "GL 4.6 / ES 3.2 §11.1.3.5 (Cb = (Rt,0,0,1), non-shadow sampler)",
                ),
                // "expanding the resulting value Rt to a color Cb = (Rt, 0, 0, 1) ... only the first
                // component Cs[0] is returned to the shader" — for GLSL 1.30 in a compatibility context
                // too, whatever DEPTH_TEXTURE_MODE says (contradiction `compat-float-alpha`; E.2.2:
                // "(r, 0, 0, 1) is always returned from depth texture samplers").
                _ => (
                    [R, Unused, Unused, Unused],
                    "GL 4.6 / ES 3.2 §11.1.3.5 (shadow lookup returns Cs[0] = Rt as a float)",
                ),
            }
        }
    }
}

/// The base colour Cb of a colour texture of `components` (2, 3, 4) components, read through a
/// non-shadow sampler: component i of Cb is the filtered component i (the `g0`..`g3` channels read
/// the per-component sets of [`shadowcheck_model::Expectation::gather`]); the components the base
/// format lacks are 0 (G, B) and 1 (A). GL 4.6 Table 15.1 / ES 3.2 Table 14.1 (RG (Rt,Gt,0) 1;
/// RGB (Rt,Gt,Bt) 1; RGBA (Rt,Gt,Bt) At), the same rows as GL 2.1 Table 3.20 and compatibility
/// Table 16.1, so fixed function (COMBINE REPLACE of (Cs, As)) reads it too.
pub fn colour_base(components: usize) -> [Channel; 4] {
    use Channel::{G0, G1, G2, G3};
    match components {
        2 => [G0, G1, Zero, One],
        3 => [G0, G1, G2, One],
        _ => [G0, G1, G2, G3],
    }
}

/// The readings of a complete lookup of a colour texture of several components on `api`: Cb
/// ([`colour_base`]), then the texture swizzle where the spec has one (§15.2.1: "Cs[i] = Cb[...]";
/// compatibility §16.1 for fixed function). Comparison is bypassed (§8.23 / ES §8.20: "the texture
/// unit operates in the normal manner"), so the path's shadow layout never applies: the lookup is
/// made through a non-shadow sampler (a shadow sampler on a colour texture is undefined,
/// §11.1.3.5, and is not drawn).
pub fn colour_readings(
    rules: &Rules,
    api: ApiPath,
    components: usize,
    sw: Option<[Swizzle; 4]>,
) -> Readings {
    let base = colour_base(components);
    let cite = if api == ApiPath::FixedFunction {
        "GL 2.1 Table 3.20 / compatibility Table 16.1 (colour texture, comparison bypassed: Cb of its base format); §3.8.13 COMBINE REPLACE of (Cs, As)"
    } else {
        "GL 4.6 §8.23.1 / ES 3.2 §8.20.1 (comparison bypassed); GL 4.6 Table 15.1 / ES 3.2 Table 14.1 (Cb of the colour's base format), every component checked"
    };
    let mut out = Readings {
        main: base,
        cite,
        unswizzled: None,
        others: Vec::new(),
    };
    if let Some(sw) = sw.filter(|_| rules.swizzle.is_some()) {
        out.unswizzled = Some(base);
        out.main = swizzled(base, sw);
    }
    out
}

/// Contradiction `compat-depth-cb`: the texture base colour of a GLSL 1.30 lookup of depth data in
/// a compatibility context. Compatibility §11.1.3.5: "Texture lookups involving textures with depth
/// component data generate a texture base color Cb either using depth data directly or by
/// performing a comparison ... and expanding the resulting value Rt to a color Cb = (Rt, 0, 0, 1)";
/// §8.23.1 with Table 16.1: "The resulting r is assigned to Rt, Lt, It, or At if the value of
/// DEPTH_TEXTURE_MODE is respectively RED, LUMINANCE, INTENSITY, or ALPHA", Cb then by Table 16.1.
pub const COMPAT_DEPTH_CB: &str = "compat-depth-cb";
/// Contradiction `gather-swizzle`: whether a shadow gather's components are swizzled.
pub const GATHER_SWIZZLE: &str = "gather-swizzle";

/// Compatibility Table 16.1 (GL 2.1 Table 3.20): the source colour (Cb, Ab) of r assigned to Rt,
/// Lt, It or At by DEPTH_TEXTURE_MODE (§8.23.1).
pub fn by_depth_mode(m: DepthTextureMode) -> [Channel; 4] {
    match m {
        DepthTextureMode::Luminance => [R, R, R, One],
        DepthTextureMode::Intensity => [R, R, R, R],
        DepthTextureMode::Alpha => [Zero, Zero, Zero, R],
        DepthTextureMode::Red => [R, Zero, Zero, One],
    }
}

/// The layouts of one API path: the reading the oracle's spec value follows, the layout it had
/// before the swizzle (for the derivation), and the other readings the texts allow.
pub struct Readings {
    pub main: [Channel; 4],
    pub cite: &'static str,
    /// The unswizzled layout, where a swizzle was applied.
    pub unswizzled: Option<[Channel; 4]>,
    /// Other readings: (contradiction id, layout), each different from `main`.
    pub others: Vec<(&'static str, [Channel; 4])>,
}

/// Every reading of the layout of r on `api` (see [`layout`] for the spec's own), with the texture
/// swizzle `sw` applied where the path has one (§15.2.1; not to an incomplete texture's result,
/// which §11.1.3.5 names outright).
pub fn readings(
    rules: &Rules,
    api: ApiPath,
    kind: Kind,
    mode: Option<DepthTextureMode>,
    sw: Option<[Swizzle; 4]>,
    incomplete: bool,
) -> Readings {
    let (l, cite) = layout(rules, api, kind, mode, incomplete);
    let sw = sw.filter(|_| rules.swizzle.is_some() && !incomplete);
    let mut out = Readings {
        main: l,
        cite,
        unswizzled: None,
        others: Vec::new(),
    };
    if incomplete {
        return out;
    }
    let compat130 = api == ApiPath::Glsl130 && matches!(kind, Kind::Compare | Kind::Depth);
    if let Some(sw) = sw {
        out.unswizzled = Some(l);
        out.main = if compat130 && kind == Kind::Compare {
            // §11.1.3.5's reading: Cs[0] of the swizzled (Rt, 0, 0, 1).
            [
                sw[0].pick([R, Zero, Zero, One], Zero, One),
                Unused,
                Unused,
                Unused,
            ]
        } else {
            swizzled(l, sw)
        };
    }
    let sw = sw.unwrap_or(Swizzle::IDENTITY);
    if compat130 {
        let table = by_depth_mode(depth_mode(rules, mode));
        let other = match kind {
            // The shadow lookup's other reading: Cs[0] of the swizzled Table 16.1 colour. Without a
            // swizzle it differs only for ALPHA, which `layout` already gives as `r|0`
            // (contradiction `compat-float-alpha`, this reading's instance at the identity swizzle).
            Kind::Compare => [sw[0].pick(table, Zero, One), Unused, Unused, Unused],
            // A non-shadow read's other reading: the swizzled (Rt, 0, 0, 1) of §11.1.3.5, the
            // `main` layout being Table 16.1's.
            _ => sw.map(|c| c.pick([R, Zero, Zero, One], Zero, One)),
        };
        // `r|0` already accepts the unswizzled ALPHA case's other reading (0).
        let covered_by_r_or_zero = out.main[0] == ROrZero;
        if other != out.main && !covered_by_r_or_zero {
            out.others.push((COMPAT_DEPTH_CB, other));
        }
    }
    out
}

/// The texture swizzle applied to the layout `l` of a complete lookup (GL 4.6 §15.2.1; ES 3.2
/// §14.2.1): Cs[i] is Cb[0], Cb[1], Cb[2], Ab, 0 or 1 by TEXTURE_SWIZZLE_R/G/B/A. A float shadow
/// lookup returns Cs[0] only (§11.1.3.5: "swizzling of Cb is then performed as described above,
/// but only the first component Cs[0] is returned to the shader"), its Cb being (Rt, 0, 0, 1).
/// On the vec4 paths (fixed function, GLSL 1.20, a non-shadow read) all four channels are the
/// swizzled source colour: compatibility §16.1 (Table 16.1, then the swizzle of §15.2.1) for fixed
/// function; §15.2.1 for shaders. Only the paths of `check::SWIZZLE_PATHS` reach here.
pub fn swizzled(l: [Channel; 4], sw: [Swizzle; 4]) -> [Channel; 4] {
    if l[1..] == [Unused; 3] {
        let cs0 = sw[0].pick([l[0], Zero, Zero, One], Zero, One);
        return [cs0, Unused, Unused, Unused];
    }
    sw.map(|c| c.pick(l, Zero, One))
}
