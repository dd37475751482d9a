//! A case before the oracle has seen it: the grid coordinates it came from (for ids, file split and
//! coverage), the texture, sampler and lookup.

use super::specs;
use crate::build::{self, At};
use shadowcheck_model::*;

/// The coordinates of a case in the main product: spec x target x format x filter x compare mode /
/// func x DEPTH_TEXTURE_MODE.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub spec: Spec,
    pub target: Target,
    pub format: Format,
    pub filter: Filter,
    pub mode: CompareMode,
    pub func: CompareFunc,
    pub dtm: Option<DepthTextureMode>,
}

impl Cell {
    pub fn new(spec: Spec) -> Cell {
        let d = specs::dims(spec);
        Cell {
            spec,
            target: Target::T2d,
            format: d.formats[0],
            filter: Filter::Nearest,
            mode: CompareMode::Compare,
            func: d.funcs[0],
            dtm: None,
        }
    }
    /// The func column of ids and coverage: the function, or `none` when compare mode is NONE.
    pub fn func_key(&self) -> &'static str {
        match self.mode {
            CompareMode::None => "none",
            CompareMode::Compare => self.func.key(),
        }
    }
    /// A sampler with GL defaults and this cell's compare state, filter and DEPTH_TEXTURE_MODE.
    pub fn sampler(&self) -> Sampler {
        let mut s = Sampler::new(self.mode, self.func, self.filter);
        s.depth_texture_mode = self.dtm;
        if matches!(self.spec, Spec::Sgix | Spec::SgixAmbient) {
            // SGIX_shadow's Table 3.8 lists only CLAMP and REPEAT (not the harness default
            // CLAMP_TO_EDGE, GL 1.2).
            (s.wrap_s, s.wrap_t, s.wrap_r) = (Wrap::Clamp, Wrap::Clamp, Wrap::Clamp);
        }
        s
    }
}

/// One case under construction.
#[derive(Debug, Clone)]
pub struct Draft {
    /// Which family of the grid made it (`cell`, `clamp`, `exact`, ...): second-to-last id part.
    pub family: &'static str,
    pub cell: Cell,
    pub texture: Texture,
    pub sampler: Sampler,
    pub lookup: Lookup,
    /// The distinguishing tail of the id, e.g. `ref=0.5/dt=0.25_0.75`.
    pub tags: String,
}

impl Draft {
    pub fn new(
        family: &'static str,
        cell: Cell,
        texture: Texture,
        lookup: Lookup,
        tags: String,
    ) -> Draft {
        Draft {
            family,
            cell,
            sampler: cell.sampler(),
            texture,
            lookup,
            tags,
        }
    }

    /// `spec/target/format/filter/func/family/tags`.
    pub fn id(&self) -> String {
        let c = &self.cell;
        let mut id = format!(
            "{}/{}/{}/{}/{}",
            c.spec,
            c.target,
            c.format,
            c.filter,
            c.func_key()
        );
        if self.family != "cell" {
            id.push('/');
            id.push_str(self.family);
        }
        if !self.tags.is_empty() {
            id.push('/');
            id.push_str(&self.tags);
        }
        id
    }

    /// The fixture file (relative path) this case goes to: `spec/target/filter.json`.
    pub fn file(&self, grid: &str) -> String {
        let c = &self.cell;
        match grid {
            "default" => format!("{}/{}/{}.json", c.spec, c.target, c.filter),
            _ => format!("{}.json", c.spec),
        }
    }

    pub fn into_case(self) -> Case {
        let id = self.id();
        let mut api = specs::apis(self.cell.spec, self.texture.target, &self.sampler);
        if self.lookup.offset != [0; 3] {
            // Only GLSL >= 1.30, GLSL ES 3.00 and SPIR-V (the ConstOffset image operand) have
            // lookups with a texel offset.
            api.retain(|a| {
                matches!(
                    a,
                    ApiPath::Glsl130
                        | ApiPath::GlslCore
                        | ApiPath::Es300
                        | ApiPath::Vulkan
                        | ApiPath::Wgsl
                )
            });
        }
        if self.lookup.gather.is_some() {
            // Shadow textureGather: GLSL 4.00 (core), GLSL ES 3.10+ (GLSL 4.60 §8.9.4) and
            // SPIR-V's OpImageDrefGather, WGSL's textureGatherCompare.
            api.retain(|a| {
                matches!(
                    a,
                    ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
                )
            });
        }
        if !self.lookup.delivery.is_literal() {
            // Uniforms and flat inputs: GLSL 1.30+, GLSL ES 3.00+ (`validate::DELIVERY_PATHS`).
            api.retain(|a| validate::DELIVERY_PATHS.contains(a));
        }
        match self.lookup.stage {
            Stage::Fragment => {}
            // A vertex-shader lookup: GLSL 1.20+, GLSL ES 3.00+ (`validate::STAGE_PATHS`).
            Stage::Vertex => api.retain(|a| validate::STAGE_PATHS.contains(a)),
            // A compute shader: GLSL 4.30, GLSL ES 3.10 (`validate::COMPUTE_PATHS`).
            Stage::Compute => api.retain(|a| validate::COMPUTE_PATHS.contains(a)),
        }
        Case {
            sweep: vec![],
            id,
            spec: self.cell.spec,
            api,
            texture: self.texture,
            sampler: self.sampler,
            lookup: self.lookup,
            expect: None,
        }
    }
}

/// A lookup at `at` with reference `dref` (level of detail 0).
pub fn lookup(target: Target, at: At, w: u32, h: u32, dref: f64) -> Lookup {
    let (coord, layer) = build::coord(target, at, w, h);
    Lookup {
        coord,
        layer,
        dref,
        projective: false,
        lod: 0.0,
        bias: 0.0,
        offset: [0; 3],
        gather: None,
        delivery: Default::default(),
        stage: Default::default(),
    }
}

/// A single-level texture of `cell`'s target and format.
pub fn texture(cell: &Cell, levels: Vec<Level>) -> Texture {
    Texture {
        target: cell.target,
        format: cell.format,
        base_level: 0,
        levels,
    }
}
