//! Enumerations shared by every crate: the specification variants, API paths and GL state values.
//!
//! Serialized names are the short lower-case keys used in case ids and fixtures. Each enum knows its
//! GL token value (`gl()`), so backends never hard-code numbers.

use serde::{Deserialize, Serialize};

macro_rules! keyed_enum {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $var:ident = $key:literal),+ $(,)? }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
        pub enum $name { $($(#[$vm])* #[serde(rename = $key)] $var),+ }
        impl $name {
            /// Every value, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$var),+];
            /// The short key used in ids, fixtures and on the command line.
            pub fn key(self) -> &'static str { match self { $($name::$var => $key),+ } }
            /// Parses a key as written by [`Self::key`].
            pub fn from_key(s: &str) -> Option<Self> { match s { $($key => Some($name::$var),)+ _ => None } }
        }
        impl crate::keymap::Keyed for $name {
            const ALL: &'static [$name] = $name::ALL;
            fn index(self) -> usize { self as usize }
        }
        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result { f.write_str(self.key()) }
        }
        impl std::str::FromStr for $name {
            type Err = crate::ModelError;
            fn from_str(s: &str) -> Result<Self, Self::Err> {
                Self::from_key(s).ok_or_else(|| crate::ModelError::UnknownKey {
                    kind: stringify!($name),
                    key: s.to_string(),
                    expected: Self::ALL.iter().map(|v| v.key()).collect::<Vec<_>>().join(", "),
                })
            }
        }
    };
}

keyed_enum! {
    /// A specification variant: the document whose rules decide the expected result.
    Spec {
        /// SGIX_shadow (1997): TEXTURE_COMPARE_SGIX, TEXTURE_{L,G}EQUAL_R_SGIX, compare before filtering.
        Sgix = "sgix",
        /// SGIX_shadow plus SGIX_shadow_ambient (SHADOW_AMBIENT_SGIX replaces 0.0 in shadow).
        SgixAmbient = "sgix_ambient",
        /// ARB_shadow: COMPARE_R_TO_TEXTURE, LEQUAL/GEQUAL only, R clamped, DEPTH_TEXTURE_MODE.
        Arb = "arb",
        /// ARB_shadow plus ARB_shadow_ambient (TEXTURE_COMPARE_FAIL_VALUE_ARB).
        ArbAmbient = "arb_ambient",
        /// ARB_shadow plus EXT_shadow_funcs (all eight functions).
        ExtFuncs = "ext_funcs",
        /// OpenGL ES 2.0 with EXT_shadow_samplers.
        Es2Ext = "es2_ext",
        /// OpenGL 3.0 - 4.6 (core rules; compatibility-profile layouts where the API path says so).
        Gl46 = "gl46",
        /// OpenGL ES 3.0 - 3.2.
        Gles32 = "gles32",
        /// Vulkan 1.3: a depth image sampled through a sampler with compareEnable (§16 Texel
        /// Depth Compare); no TexParameter state, no fail value, no incompleteness.
        Vulkan = "vulkan",
        /// WebGPU with WGSL: a depth texture sampled through a comparison sampler
        /// (`GPUSamplerDescriptor.compare`) by textureSampleCompare(Level) or
        /// textureGatherCompare; no border, no TexParameter state, no incompleteness.
        WebGpu = "webgpu",
    }
}

keyed_enum! {
    /// How a lookup reaches the texture unit. Decides how r is laid out in the observed RGBA.
    ApiPath {
        /// GL compatibility, fixed-function texturing, TexEnv REPLACE; R from texture coordinate r.
        FixedFunction = "ff",
        /// GL compatibility, ARB_fragment_program SHADOW1D/2D/RECT targets.
        ArbFp = "arbfp",
        /// GLSL 1.10/1.20 `shadow1D/2D(Proj)`: vec4 laid out by DEPTH_TEXTURE_MODE.
        Glsl120 = "glsl120",
        /// GLSL 1.30 in a compatibility context: `texture()` on a shadow sampler returns a float.
        Glsl130 = "glsl130",
        /// GLSL >= 3.30 in a core context: float result, (Rt,0,0,1) then swizzle.
        GlslCore = "core",
        /// GLSL ES 1.00 with EXT_shadow_samplers: `shadow2DEXT` returns a float.
        Es100Ext = "es100",
        /// GLSL ES 3.00+: float result.
        Es300 = "es300",
        /// Vulkan: GLSL 4.50 for Vulkan compiled to SPIR-V (OpImageSampleDref*, OpImageDrefGather);
        /// float result.
        Vulkan = "vk",
        /// WebGPU: WGSL `texture_depth_*` lookups through a `sampler_comparison`; float result.
        Wgsl = "wgsl",
    }
}

keyed_enum! {
    /// TEXTURE_COMPARE_FUNC (and SGIX's TEXTURE_COMPARE_OPERATOR_SGIX values).
    CompareFunc {
        Never = "never",
        Less = "less",
        Equal = "equal",
        Lequal = "lequal",
        Greater = "greater",
        Notequal = "notequal",
        Gequal = "gequal",
        Always = "always",
        /// SGIX_shadow TEXTURE_LEQUAL_R_SGIX: passes if texel <= R.
        LequalRSgix = "lequal_r_sgix",
        /// SGIX_shadow TEXTURE_GEQUAL_R_SGIX: passes if texel >= R.
        GequalRSgix = "gequal_r_sgix",
    }
}

impl CompareFunc {
    /// The GL token.
    pub fn gl(self) -> u32 {
        match self {
            CompareFunc::Never => 0x0200,
            CompareFunc::Less => 0x0201,
            CompareFunc::Equal => 0x0202,
            CompareFunc::Lequal => 0x0203,
            CompareFunc::Greater => 0x0204,
            CompareFunc::Notequal => 0x0205,
            CompareFunc::Gequal => 0x0206,
            CompareFunc::Always => 0x0207,
            CompareFunc::LequalRSgix => 0x819C,
            CompareFunc::GequalRSgix => 0x819D,
        }
    }
    /// The eight functions of EXT_shadow_funcs / GL core (not the SGIX operators).
    pub const CORE: [CompareFunc; 8] = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::Lequal,
        CompareFunc::Greater,
        CompareFunc::Notequal,
        CompareFunc::Gequal,
        CompareFunc::Always,
    ];
}

keyed_enum! {
    /// TEXTURE_COMPARE_MODE. SGIX's boolean TEXTURE_COMPARE_SGIX maps TRUE to `Compare`.
    /// COMPARE_R_TO_TEXTURE (ARB), COMPARE_REF_TO_TEXTURE(_EXT) (core, ES) share the token 0x884E.
    CompareMode {
        None = "none",
        Compare = "compare",
    }
}

impl CompareMode {
    pub fn gl(self) -> u32 {
        match self {
            CompareMode::None => 0,
            CompareMode::Compare => 0x884E,
        }
    }
}

keyed_enum! {
    /// DEPTH_TEXTURE_MODE (ARB_depth_texture; RED added by GL 3.0 compatibility).
    DepthTextureMode {
        Luminance = "luminance",
        Intensity = "intensity",
        Alpha = "alpha",
        Red = "red",
    }
}

impl DepthTextureMode {
    pub fn gl(self) -> u32 {
        match self {
            DepthTextureMode::Luminance => 0x1909,
            DepthTextureMode::Intensity => 0x8049,
            DepthTextureMode::Alpha => 0x1906,
            DepthTextureMode::Red => 0x1903,
        }
    }
}

keyed_enum! {
    /// DEPTH_STENCIL_TEXTURE_MODE (GL 4.3+, ES 3.1+).
    DepthStencilMode {
        DepthComponent = "depth",
        StencilIndex = "stencil",
    }
}

impl DepthStencilMode {
    pub fn gl(self) -> u32 {
        match self {
            DepthStencilMode::DepthComponent => 0x1902,
            DepthStencilMode::StencilIndex => 0x1901,
        }
    }
}

keyed_enum! {
    /// TEXTURE_MIN_FILTER / TEXTURE_MAG_FILTER values.
    Filter {
        Nearest = "nearest",
        Linear = "linear",
        NearestMipmapNearest = "nmn",
        LinearMipmapNearest = "lmn",
        NearestMipmapLinear = "nml",
        LinearMipmapLinear = "lml",
    }
}

impl Filter {
    pub fn gl(self) -> u32 {
        match self {
            Filter::Nearest => 0x2600,
            Filter::Linear => 0x2601,
            Filter::NearestMipmapNearest => 0x2700,
            Filter::LinearMipmapNearest => 0x2701,
            Filter::NearestMipmapLinear => 0x2702,
            Filter::LinearMipmapLinear => 0x2703,
        }
    }
    /// True for the four mipmap minification filters.
    pub fn is_mipmap(self) -> bool {
        !matches!(self, Filter::Nearest | Filter::Linear)
    }
}

keyed_enum! {
    /// Texture internal format. Unorm depth formats store integers of `bits()` bits.
    Format {
        D16 = "d16",
        D24 = "d24",
        D32 = "d32",
        D32f = "d32f",
        D24S8 = "d24s8",
        D32fS8 = "d32fs8",
        /// Unsized DEPTH_COMPONENT, uploaded as UNSIGNED_SHORT; the stored precision is the
        /// implementation's choice (at least 16 bits).
        DepthUnsized = "depth",
        /// A colour texture (R8 / LUMINANCE8): comparison is bypassed.
        R8 = "r8",
        /// RGBA8 colour (base format RGBA, 8 bits a component): comparison is bypassed, the
        /// result is the base colour Cb = (R, G, B, A) (GL 4.6 Table 15.1).
        Rgba8 = "rgba8",
        /// RGB8 colour (base RGB): Cb = (R, G, B, 1).
        Rgb8 = "rgb8",
        /// RGBA4 colour (base RGBA, 4 bits a component): Cb = (R, G, B, A).
        Rgba4 = "rgba4",
        /// RG8 colour (base RG, GL 3.0 / ES 3.0): Cb = (R, G, 0, 1).
        Rg8 = "rg8",
    }
}

impl Format {
    /// Internal format token.
    pub fn gl(self) -> u32 {
        match self {
            Format::D16 => 0x81A5,
            Format::D24 => 0x81A6,
            Format::D32 => 0x81A7,
            Format::D32f => 0x8CAC,
            Format::D24S8 => 0x88F0,
            Format::D32fS8 => 0x8CAD,
            Format::DepthUnsized => 0x1902,
            Format::R8 => 0x8229,
            Format::Rgba8 => 0x8058,
            Format::Rgb8 => 0x8051,
            Format::Rgba4 => 0x8056,
            Format::Rg8 => 0x822B,
        }
    }
    /// Bits of the stored unorm integer (of each component for a colour format); `None` for
    /// floating-point depth. For the unsized format this is the bits of the uploaded integers (16).
    pub fn unorm_bits(self) -> Option<u32> {
        match self {
            Format::D16 | Format::DepthUnsized => Some(16),
            Format::D24 | Format::D24S8 => Some(24),
            Format::D32 => Some(32),
            Format::R8 | Format::Rgba8 | Format::Rgb8 | Format::Rg8 => Some(8),
            Format::Rgba4 => Some(4),
            Format::D32f | Format::D32fS8 => None,
        }
    }
    /// Base internal format is DEPTH_COMPONENT or DEPTH_STENCIL.
    pub fn is_depth(self) -> bool {
        !self.is_colour()
    }
    /// A colour format (comparison is bypassed: GL 4.6 §8.23 "Otherwise ... texture comparison is
    /// bypassed").
    pub fn is_colour(self) -> bool {
        self.components() > 0
    }
    /// Components of a colour format's base internal format (RED 1, RG 2, RGB 3, RGBA 4); 0 for
    /// depth formats. A colour format with more than one stores [`crate::Texels::Colour`].
    pub fn components(self) -> usize {
        match self {
            Format::R8 => 1,
            Format::Rg8 => 2,
            Format::Rgb8 => 3,
            Format::Rgba8 | Format::Rgba4 => 4,
            _ => 0,
        }
    }
    /// A colour format of more than one component (its texels are [`crate::Texels::Colour`]).
    pub fn is_multi_colour(self) -> bool {
        self.components() > 1
    }
    /// Has a stencil component (base format DEPTH_STENCIL).
    pub fn has_stencil(self) -> bool {
        matches!(self, Format::D24S8 | Format::D32fS8)
    }
    /// Fixed-point (unorm) depth, the formats for which GL 3.0+ clamps Dt and Dref.
    pub fn is_fixed_point(self) -> bool {
        self.unorm_bits().is_some()
    }
    /// The format is sized (everything but unsized DEPTH_COMPONENT).
    pub fn is_sized(self) -> bool {
        !matches!(self, Format::DepthUnsized)
    }
}

keyed_enum! {
    /// Texture target.
    Target {
        T1d = "1d",
        T2d = "2d",
        Rect = "rect",
        Cube = "cube",
        T1dArray = "1darray",
        T2dArray = "2darray",
        CubeArray = "cubearray",
    }
}

impl Target {
    pub fn gl(self) -> u32 {
        match self {
            Target::T1d => 0x0DE0,
            Target::T2d => 0x0DE1,
            Target::Rect => 0x84F5,
            Target::Cube => 0x8513,
            Target::T1dArray => 0x8C18,
            Target::T2dArray => 0x8C1A,
            Target::CubeArray => 0x9009,
        }
    }
    /// Number of coordinates addressing a texel inside one image (1 or 2; cube faces are 2D).
    pub fn dims(self) -> usize {
        match self {
            Target::T1d | Target::T1dArray => 1,
            _ => 2,
        }
    }
    /// Layers are addressed by a coordinate (array targets).
    pub fn is_array(self) -> bool {
        matches!(
            self,
            Target::T1dArray | Target::T2dArray | Target::CubeArray
        )
    }
    pub fn is_cube(self) -> bool {
        matches!(self, Target::Cube | Target::CubeArray)
    }
    /// Rectangle textures use unnormalized coordinates and allow no mipmaps.
    pub fn is_rect(self) -> bool {
        matches!(self, Target::Rect)
    }
}

keyed_enum! {
    /// TEXTURE_WRAP_{S,T,R} values.
    Wrap {
        Repeat = "repeat",
        ClampToEdge = "edge",
        ClampToBorder = "border",
        MirroredRepeat = "mirror",
        MirrorClampToEdge = "mirror_edge",
        /// Legacy CLAMP (compatibility only).
        Clamp = "clamp",
    }
}

impl Wrap {
    pub fn gl(self) -> u32 {
        match self {
            Wrap::Repeat => 0x2901,
            Wrap::ClampToEdge => 0x812F,
            Wrap::ClampToBorder => 0x812D,
            Wrap::MirroredRepeat => 0x8370,
            Wrap::MirrorClampToEdge => 0x8743,
            Wrap::Clamp => 0x2900,
        }
    }
}

keyed_enum! {
    /// A named precision profile (tier) for acceptance sets; the oracle's `profile::PROFILES` holds
    /// each one's tolerances. Declared strictest first: the declaration order is the tiering of
    /// [`crate::Expectation::judge`] (inside the strictest profile's set a pass, inside only a later
    /// one's a warning). Adding a tier is a variant here, in its place, and its entry in `PROFILES`.
    Profile {
        Strict = "strict",
        Quality = "quality",
    }
}

impl Profile {
    /// The strictest profile: an observation inside its set passes.
    pub fn strictest() -> Profile {
        Profile::ALL[0]
    }
    /// The loosest profile: an observation outside its set fails.
    pub fn loosest() -> Profile {
        Profile::ALL[Profile::ALL.len() - 1]
    }
}

keyed_enum! {
    /// What one channel of an observed RGBA must hold.
    Channel {
        /// The comparison result r.
        R = "r",
        /// Exactly 0.
        Zero = "0",
        /// Exactly 1.
        One = "1",
        /// Not produced by this path (e.g. the other three channels of a float result).
        Unused = "-",
        /// r, or 0 under a second reading the texts leave open (a GLSL 1.30 shadow lookup in a
        /// compatibility context with DEPTH_TEXTURE_MODE ALPHA: contradiction `compat-float-alpha`).
        ROrZero = "r|0",
        /// Shadow textureGather: the comparison result of the texel τi0j1 (component R of the
        /// result vector), read from [`crate::Expectation::gather`]`[0]`. The four `g` channels
        /// also read the components of a result with a set per component: a colour texture's base
        /// colour Cb (R, G, B, A), or the alpha of an incomplete usampler read (`g3`).
        G0 = "g0",
        /// Gather component G: texel τi1j1 (`gather[1]`).
        G1 = "g1",
        /// Gather component B: texel τi1j0 (`gather[2]`).
        G2 = "g2",
        /// Gather component A: texel τi0j0 (`gather[3]`).
        G3 = "g3",
    }
}

impl Channel {
    /// The gather layout: component i of the result holds gather value i (GL 4.6 §8.14.2: "in
    /// the order τi0j1, τi1j1, τi1j0, and τi0j0").
    pub const GATHER: [Channel; 4] = [Channel::G0, Channel::G1, Channel::G2, Channel::G3];
    /// Which gather value this channel reads, if it is a gather channel.
    pub fn gather_index(self) -> Option<usize> {
        Channel::GATHER.iter().position(|&c| c == self)
    }
}

keyed_enum! {
    /// TEXTURE_SWIZZLE_R/G/B/A values (GL 4.6 §8.10, §15.2.1).
    Swizzle {
        Red = "red",
        Green = "green",
        Blue = "blue",
        Alpha = "alpha",
        Zero = "zero",
        One = "one",
    }
}

impl Swizzle {
    pub fn gl(self) -> u32 {
        match self {
            Swizzle::Red => 0x1903,
            Swizzle::Green => 0x1904,
            Swizzle::Blue => 0x1905,
            Swizzle::Alpha => 0x1906,
            Swizzle::Zero => 0,
            Swizzle::One => 1,
        }
    }
    /// The initial TEXTURE_SWIZZLE_RGBA (RED, GREEN, BLUE, ALPHA).
    pub const IDENTITY: [Swizzle; 4] =
        [Swizzle::Red, Swizzle::Green, Swizzle::Blue, Swizzle::Alpha];
    /// GL 4.6 §15.2.1: one component of Cs from the base colour `cb` (Cs[i] = Cb[0..3], 0 or 1).
    pub fn pick<T: Copy>(self, cb: [T; 4], zero: T, one: T) -> T {
        match self {
            Swizzle::Red => cb[0],
            Swizzle::Green => cb[1],
            Swizzle::Blue => cb[2],
            Swizzle::Alpha => cb[3],
            Swizzle::Zero => zero,
            Swizzle::One => one,
        }
    }
}

keyed_enum! {
    /// How the lookup's values (coordinates, reference, LOD or bias, gradients and a gather's
    /// texel offset) reach the lookup function in the shader. The expected value never depends on
    /// it: values are values (GLSL 4.60 §8.9.4 textureGatherOffset: "the offset can be variable
    /// (non constant)"); what changes is the code path a compiler takes.
    #[derive(Default)]
    Delivery {
        /// The offsets are constant expressions in the shader text; the other values are
        /// per-case constants in the form the API path chooses (uniforms, or flat inputs of a
        /// batched draw). Every case without a `delivery` field.
        #[default]
        Literal = "literal",
        /// Every value from a uniform of the program (a gather's offset a `uniform ivec2`).
        Uniform = "uniform",
        /// Every value from a `flat` input of the fragment shader, written by the vertex shader.
        Flat = "flat",
        /// As `flat`, but the values differ between the fragments of the 2x2 pixel quad: the
        /// measured (lower-left) fragment gets the case's values, the three others a changed
        /// reference and offset (and changed coordinates and LOD where the lookup function takes
        /// no implicit derivatives), so that a value taken from another fragment shows.
        PerFragment = "per_fragment",
    }
}

impl Delivery {
    /// The default, which fixtures leave out.
    pub fn is_literal(&self) -> bool {
        *self == Delivery::Literal
    }
}

keyed_enum! {
    /// The shader stage the lookup runs in. GLSL 4.60 / GLSL ES 3.20 §8.9: "Texture lookup
    /// functions are available in all shading stages. However, level-of-detail is implicitly
    /// computed only for fragment shaders. Other shaders operate as though the base
    /// level-of-detail were computed as zero."
    #[derive(Default)]
    Stage {
        /// The fragment shader (every case without a `stage` field).
        #[default]
        Fragment = "fragment",
        /// The vertex shader: an implicit-LOD lookup (`texture`, GLSL 1.20 `shadow2D`) with λ_base
        /// 0; the case's `lod` is the λ_base the same lookup would get in a fragment shader.
        Vertex = "vertex",
        /// A compute shader (GL 4.3 / GLSL 4.30, ES 3.1 / GLSL ES 3.10): the same implicit-LOD
        /// lookup with λ_base 0, its result written to an image; `lod` as for `Vertex`.
        Compute = "compute",
    }
}

impl Stage {
    /// The default, which fixtures leave out.
    pub fn is_fragment(&self) -> bool {
        *self == Stage::Fragment
    }
}
