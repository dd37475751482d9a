//! shadowcheck's own texture unit with depth comparison ("shadow" sampling), one variant per
//! specification ([`Spec`]): SGIX_shadow (+ ambient), ARB_shadow (+ ambient), EXT_shadow_funcs,
//! ES 2.0 + EXT_shadow_samplers, GL 3.0–4.6, ES 3.x, Vulkan and WebGPU (WGSL).
//!
//! It is written from the specification texts independently of the oracle (this crate depends on
//! the model only), so the two check each other. It is an *implementation*: one answer per lookup,
//! in f32 arithmetic like a GPU, with percentage-closer filtering where the specs leave filtered
//! comparisons implementation-dependent.
//!
//! Layers:
//! - [`SoftUnit`]: a case in, RGBA per API path out ([`SoftUnit::sample`], [`SoftUnit::sample_batch`]).
//! - [`PreparedTexture`] + [`SamplerState`] + [`Coords`]: the raw lookup
//!   ([`PreparedTexture::lookup`]) for benchmarks: prepare once, look up many times, no allocation.
//! - [`tex_param`]: its own TexParameter / GetTexParameter state ([`SoftUnit::tex_parameter`]).
//! - [`Fault`] / [`Faults`]: seedable bugs for mutation testing ([`SoftUnit::with_fault`]).
//!
//! Module map: `storage` (texel conversion), `wrap` (Table 8.20), `lod` (§8.14.1/§8.14.3),
//! `cube` (§8.13), `compare` (per-spec comparison rules), `defined` (which state each spec
//! has), `sampler` (resolved state, completeness), `filter` (the lookup, PCF), `observe` (what a
//! lookup reports), `layout` (RGBA per API path), `webgpu` (what a WGSL lookup may ask for,
//! WGSL's integer array index), `faults`.

pub mod bench;
mod colour;
pub mod compare;
pub mod cube;
mod defined;
pub mod faults;
pub mod filter;
pub mod gather;
pub mod layout;
pub mod lod;
pub mod observe;
pub mod sampler;
mod stage;
pub mod storage;
pub mod tex_param;
pub mod unitstate;
pub mod webgpu;
pub mod witness;
pub mod wrap;

/// Runs `f` on this thread's scratch texture buffer (allocation-free after warm-up), or on a
/// fresh one if the scratch is in use (re-entered, which cannot happen today).
fn with_scratch<R>(f: impl FnOnce(&mut PreparedTexture) -> R) -> R {
    thread_local! {
        static SCRATCH: std::cell::RefCell<PreparedTexture> = std::cell::RefCell::new(PreparedTexture::default());
    }
    SCRATCH.with(|t| match t.try_borrow_mut() {
        Ok(mut tex) => f(&mut tex),
        Err(_) => f(&mut PreparedTexture::default()),
    })
}

#[cfg(test)]
mod tests;

pub use faults::{Fault, Faults};
pub use filter::Coords;
pub use layout::Layout;
pub use observe::{Observer, TexelVisit, Trace};
pub use sampler::{Kind, SamplerState};
pub use storage::PreparedTexture;

use shadowcheck_model::{
    ApiPath, Case, CompareFunc, Footprint, FootprintTexel, Format, Lookup, Spec, Target, Texels,
    Wrap,
};

/// Why the unit gives no result for a case. Every variant is a reason suitable for a Skip.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SoftError {
    #[error("invalid case: {0}")]
    Invalid(String),
    #[error("this unit implements {unit}, the case is for {case}")]
    SpecMismatch { unit: Spec, case: Spec },
    #[error("{spec} does not define {what}")]
    Undefined { spec: Spec, what: &'static str },
    #[error("{spec} does not define compare function {func}")]
    CompareFunc { spec: Spec, func: CompareFunc },
    #[error("{spec} does not accept wrap mode {wrap} for this texture")]
    Wrap { spec: Spec, wrap: Wrap },
    #[error("{spec} has no internal format {format}")]
    Format { spec: Spec, format: Format },
    #[error("API path {api} does not exist under {spec}")]
    ApiPath { spec: Spec, api: ApiPath },
    #[error("API path {api} has no shadow lookup for {target} textures")]
    Target { api: ApiPath, target: Target },
    #[error("projective lookups do not exist for {target} textures")]
    Projective { target: Target },
    #[error("the result is undefined: {0}")]
    UndefinedResult(&'static str),
}

/// The API paths each spec variant has (see `layout` for what each returns).
pub fn path_exists(spec: Spec, api: ApiPath) -> bool {
    use ApiPath as A;
    match spec {
        Spec::Sgix | Spec::SgixAmbient => matches!(api, A::FixedFunction | A::ArbFp | A::Glsl120),
        Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs => {
            matches!(api, A::FixedFunction | A::ArbFp | A::Glsl120 | A::Glsl130)
        }
        Spec::Gl46 => matches!(
            api,
            A::FixedFunction | A::ArbFp | A::Glsl120 | A::Glsl130 | A::GlslCore
        ),
        Spec::Es2Ext => api == A::Es100Ext,
        Spec::Gles32 => api == A::Es300,
        Spec::Vulkan => api == A::Vulkan,
        // WebGPU, Shader Modules, GPUShaderModuleDescriptor "code: The WGSL source code for
        // the shader module": WGSL is the only path.
        Spec::WebGpu => api == A::Wgsl,
    }
}

/// The targets a path can sample with a shadow lookup: fixed function 1D/2D/rect/cube;
/// ARB_fragment_program_shadow SHADOW1D/2D/RECT; GLSL 1.20 shadow1D/2D/2DRect; GLSL ≥ 1.30 all;
/// EXT_shadow_samplers 2D; GLSL ES 3.x 2D, 2D array, cube, cube array.
pub fn path_targets(api: ApiPath, target: Target) -> bool {
    use Target as T;
    match api {
        ApiPath::FixedFunction => matches!(target, T::T1d | T::T2d | T::Rect | T::Cube),
        ApiPath::ArbFp | ApiPath::Glsl120 => matches!(target, T::T1d | T::T2d | T::Rect),
        ApiPath::Glsl130 | ApiPath::GlslCore => true,
        ApiPath::Es100Ext => target == T::T2d,
        ApiPath::Es300 => matches!(target, T::T2d | T::T2dArray | T::Cube | T::CubeArray),
        // VkImageViewType has no rectangle textures.
        ApiPath::Vulkan => target != T::Rect,
        // WGSL textureSampleCompare: overloads for texture_depth_2d,
        // texture_depth_2d_array, texture_depth_cube and texture_depth_cube_array only.
        ApiPath::Wgsl => matches!(target, T::T2d | T::T2dArray | T::Cube | T::CubeArray),
    }
}

/// One result of [`SoftUnit::sample_batch`]: case index, API path, RGBA or the reason for none.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchResult {
    pub case: usize,
    pub api: ApiPath,
    pub rgba: Result<[f32; 4], SoftError>,
}

/// A texture unit implementing one specification variant, optionally with seeded faults.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SoftUnit {
    spec: Spec,
    faults: Faults,
}

impl SoftUnit {
    /// The correct unit for `spec`.
    pub fn new(spec: Spec) -> SoftUnit {
        SoftUnit {
            spec,
            faults: Faults::NONE,
        }
    }
    /// The same unit with `fault` switched on as well. A fault of another spec's variant
    /// ([`Fault::spec`], e.g. a WebGPU-only fault on a GL unit) is not taken.
    pub fn with_fault(self, fault: Fault) -> SoftUnit {
        SoftUnit {
            faults: self.faults.with(fault).for_spec(self.spec),
            ..self
        }
    }
    /// The same unit with exactly the faults in `faults` that belong to its spec
    /// ([`Faults::for_spec`]).
    pub fn with_faults(self, faults: Faults) -> SoftUnit {
        SoftUnit {
            faults: faults.for_spec(self.spec),
            ..self
        }
    }
    pub fn spec(&self) -> Spec {
        self.spec
    }
    pub fn faults(&self) -> Faults {
        self.faults
    }

    /// A TexParameter / GetTexParameter state case on API path (context kind) `api`.
    pub fn tex_parameter(
        &self,
        case: &shadowcheck_model::StateCase,
        api: ApiPath,
    ) -> shadowcheck_model::StateObserved {
        tex_param::observe(self.spec, self.faults, case, api)
    }

    /// The same on a context whose extension string lists `exposed`
    /// ([`tex_param::STATE_EXTENSIONS`] add pnames on compatibility contexts).
    pub fn tex_parameter_exposing(
        &self,
        case: &shadowcheck_model::StateCase,
        api: ApiPath,
        exposed: &[&str],
    ) -> shadowcheck_model::StateObserved {
        tex_param::observe_exposing(self.spec, self.faults, case, api, exposed)
    }

    /// Converts the case's texture (allocates; see [`PreparedTexture::prepare_into`] to reuse).
    pub fn prepare_texture(&self, case: &Case) -> Result<PreparedTexture, SoftError> {
        PreparedTexture::new(&case.texture, self.faults)
    }

    /// Resolves the case's sampler state against a prepared texture.
    pub fn sampler_state(
        &self,
        case: &Case,
        tex: &PreparedTexture,
    ) -> Result<SamplerState, SoftError> {
        let (s, source) = unitstate::effective(self.spec, case, self.faults)?;
        SamplerState::resolve(self.spec, &s, source, tex, self.faults)
    }

    /// The lookup coordinates of `case` as f32, after the projective divide (s, t, (r) and Dref
    /// divided by q), with the layer coordinate moved to `layer` for array targets.
    pub fn coords(&self, target: Target, l: &Lookup) -> Result<Coords, SoftError> {
        let f = self.faults;
        let (mut s, mut t, mut r) = (l.coord[0] as f32, l.coord[1] as f32, l.coord[2] as f32);
        let mut dref = l.dref as f32;
        if l.projective {
            if !matches!(target, Target::T1d | Target::T2d | Target::Rect) {
                return Err(SoftError::Projective { target });
            }
            let q = l.coord[3] as f32;
            if !f.has(Fault::ProjectiveDivideMissing) {
                s /= q;
                t /= q;
                r /= q;
                if !f.has(Fault::RefNotDividedByQ) {
                    dref /= q;
                }
            }
        }
        let layer = match target {
            Target::T1dArray => t,
            Target::T2dArray => r,
            Target::CubeArray => l.layer as f32,
            _ => 0.0,
        };
        // WGSL's array_index is an integer (see `webgpu::array_index`).
        let layer = webgpu::layer_coordinate(self.spec, target, layer);
        if target.is_cube() && cube::select(s, t, r, f).is_none() {
            return Err(SoftError::UndefinedResult(
                "cube direction has no major axis (zero or NaN)",
            ));
        }
        Ok(Coords {
            s,
            t,
            r,
            layer,
            dref,
            lambda_base: stage::lambda_base(l, f),
            bias: l.bias as f32,
            offset: if f.has(Fault::VariableGatherOffsetZero)
                && l.gather.is_some()
                && !l.delivery.is_literal()
            {
                [0, 0]
            } else {
                [l.offset[0], l.offset[1]]
            },
        })
    }

    /// Checks that `api` exists for this spec and can sample the case's target and wrap modes.
    fn check_path(&self, case: &Case, api: ApiPath) -> Result<(), SoftError> {
        if !path_exists(self.spec, api) {
            return Err(SoftError::ApiPath {
                spec: self.spec,
                api,
            });
        }
        let target = case.texture.target;
        if !path_targets(api, target) {
            return Err(SoftError::Target { api, target });
        }
        if api == ApiPath::Wgsl {
            webgpu::check_lookup(self.spec, case)?;
        }
        stage::check(self.spec, api, &case.lookup)?;
        if case.lookup.offset != [0; 3]
            && !matches!(
                api,
                ApiPath::Glsl130
                    | ApiPath::GlslCore
                    | ApiPath::Es300
                    | ApiPath::Vulkan
                    | ApiPath::Wgsl
            )
        {
            // GLSL 1.20, GLSL ES 1.00, fixed function and ARB programs have no offset lookups
            // (SPIR-V has the Offset / ConstOffset image operands, WGSL the `offset` overloads).
            return Err(SoftError::Undefined {
                spec: self.spec,
                what: "a texel offset on a path without *Offset lookup functions",
            });
        }
        if api == ApiPath::Es100Ext && case.lookup.bias != 0.0 {
            // EXT_shadow_samplers: shadow2DEXT(sampler, vec3) and shadow2DProjEXT(sampler, vec4) only.
            return Err(SoftError::Undefined {
                spec: self.spec,
                what: "a bias argument to shadow2DEXT",
            });
        }
        let s = &case.sampler;
        // The swizzle (gl46 / gles32 state) applies on every GL 4.6 path that reads a texture
        // source colour (`unitstate::swizzle`), fixed function and GLSL 1.20 included (GL 4.6
        // compatibility §16.1 + §15.2.1). ARB_fragment_program is refused: how its TEX result
        // meets TEXTURE_SWIZZLE_* is for ARB_fragment_program's own text, outside the spec pack.
        if s.swizzle.is_some() && api == ApiPath::ArbFp {
            return Err(SoftError::Undefined {
                spec: self.spec,
                what: "the texture swizzle on the ARB_fragment_program path",
            });
        }
        if api == ApiPath::GlslCore && [s.wrap_s, s.wrap_t, s.wrap_r].contains(&Wrap::Clamp) {
            // CLAMP exists only in the compatibility profile.
            return Err(SoftError::Wrap {
                spec: self.spec,
                wrap: Wrap::Clamp,
            });
        }
        Ok(())
    }

    /// A shadow gather exists on GLSL 4.00+ and GLSL ES 3.10+ (`core`, `es300`), SPIR-V (`vk`)
    /// and WGSL (`wgsl`, textureGatherCompare), for 2D, 2D array, cube, cube array and rectangle
    /// shadow samplers, with comparison enabled, never projective; the *Offset(s) forms take no
    /// cube sampler; offsets within [-8, 7].
    fn check_gather(&self, case: &Case, api: ApiPath, st: &SamplerState) -> Result<(), SoftError> {
        let undefined = |what| {
            Err(SoftError::Undefined {
                spec: self.spec,
                what,
            })
        };
        // SPIR-V: OpImageDrefGather (with ConstOffset / ConstOffsets); WGSL
        // textureGatherCompare.
        if !matches!(
            api,
            ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
        ) {
            return undefined("textureGather on this API path");
        }
        if api == ApiPath::Wgsl {
            webgpu::check_gather(self.spec, case)?;
        }
        let t = case.texture.target;
        if !matches!(
            t,
            Target::T2d | Target::T2dArray | Target::Cube | Target::CubeArray | Target::Rect
        ) {
            return Err(SoftError::Target { api, target: t });
        }
        if case.lookup.projective {
            return Err(SoftError::Projective { target: t });
        }
        if st.kind != Kind::Compare {
            return Err(SoftError::UndefinedResult(
                "a shadow gather on a texture without depth comparison",
            ));
        }
        let l = &case.lookup;
        let offs = l.gather.as_ref().and_then(|g| g.offsets);
        let any_offset = l.offset != [0; 3] || offs.is_some();
        if any_offset && t.is_cube() {
            return undefined("textureGatherOffset on a cube sampler");
        }
        let all = offs
            .map(|o| o.to_vec())
            .unwrap_or_else(|| vec![[l.offset[0], l.offset[1]]]);
        if l.offset[2] != 0 || all.iter().flatten().any(|v| !(-8..=7).contains(v)) {
            return Err(SoftError::UndefinedResult(
                "a gather offset outside MIN/MAX_PROGRAM_TEXTURE_GATHER_OFFSET's guaranteed range",
            ));
        }
        Ok(())
    }

    /// RGBA for one case on one API path. The case must be for this unit's spec.
    ///
    /// Allocation-free after warm-up: the texture is converted into a per-thread scratch buffer.
    pub fn sample(&self, case: &Case, api: ApiPath) -> Result<[f32; 4], SoftError> {
        with_scratch(|tex| self.sample_with(case, api, tex))
    }

    /// A sweep case on one API path: the RGBA of the case's own lookup, then of each point of its
    /// sweep in order (texture and sampler state prepared once; a point changes only the
    /// coordinates and the reference).
    pub fn sample_sweep(&self, case: &Case, api: ApiPath) -> Result<Vec<[f32; 4]>, SoftError> {
        with_scratch(|tex| {
            let (st, coords) = self.prepare_case(case, tex)?;
            let mut out = Vec::with_capacity(case.lookup_count());
            out.push(self.finish(case, api, tex, &st, &coords)?);
            for p in &case.sweep {
                let c = self.coords(case.texture.target, &case.point_lookup(p))?;
                out.push(self.finish(case, api, tex, &st, &c)?);
            }
            Ok(out)
        })
    }

    /// RGBA for every API path of the case, in `case.api` order.
    pub fn sample_all(&self, case: &Case) -> Vec<(ApiPath, Result<[f32; 4], SoftError>)> {
        let mut out = Vec::with_capacity(case.api.len());
        self.sample_batch(std::slice::from_ref(case), &mut out);
        out.into_iter().map(|b| (b.api, b.rgba)).collect()
    }

    /// Batch form: appends one [`BatchResult`] to `out` for every (case, API path) pair, cases in
    /// order and each case's paths in `case.api` order. The texture of each case is converted
    /// once (into one reused scratch buffer) and shared by its paths; nothing is allocated per
    /// case except error messages. Cases for another spec give [`SoftError::SpecMismatch`].
    pub fn sample_batch(&self, cases: &[Case], out: &mut Vec<BatchResult>) {
        let mut tex = PreparedTexture::default();
        for (i, case) in cases.iter().enumerate() {
            match self.prepare_case(case, &mut tex) {
                Ok((st, coords)) => {
                    for &api in &case.api {
                        let rgba = self.finish(case, api, &tex, &st, &coords);
                        out.push(BatchResult { case: i, api, rgba });
                    }
                }
                Err(e) => {
                    for &api in &case.api {
                        out.push(BatchResult {
                            case: i,
                            api,
                            rgba: Err(e.clone()),
                        });
                    }
                }
            }
        }
    }

    fn sample_with(
        &self,
        case: &Case,
        api: ApiPath,
        tex: &mut PreparedTexture,
    ) -> Result<[f32; 4], SoftError> {
        let (st, coords) = self.prepare_case(case, tex)?;
        self.finish(case, api, tex, &st, &coords)
    }

    /// Path-independent part: validation, texture conversion, sampler state, coordinates.
    fn prepare_case(
        &self,
        case: &Case,
        tex: &mut PreparedTexture,
    ) -> Result<(SamplerState, Coords), SoftError> {
        if case.spec != self.spec {
            return Err(SoftError::SpecMismatch {
                unit: self.spec,
                case: case.spec,
            });
        }
        shadowcheck_model::validate::validate(case)
            .map_err(|e| SoftError::Invalid(e.to_string()))?;
        tex.prepare_into(&case.texture, self.faults)?;
        let (s, source) = unitstate::effective(self.spec, case, self.faults)?;
        let st = SamplerState::resolve(self.spec, &s, source, tex, self.faults)?;
        let coords = self.coords(case.texture.target, &case.lookup)?;
        Ok((st, coords))
    }

    /// Path-dependent part: path checks, completeness, the lookup, the layout.
    fn finish(
        &self,
        case: &Case,
        api: ApiPath,
        tex: &PreparedTexture,
        st: &SamplerState,
        c: &Coords,
    ) -> Result<[f32; 4], SoftError> {
        self.check_path(case, api)?;
        if let Some(g) = &case.lookup.gather {
            self.check_gather(case, api, st)?;
            if !st.complete {
                // "Incomplete textures ... return a texture source color of (0.0, 0.0, 0.0, 1.0)
                // ... for all four source texels" (GL 4.6 §8.14.2): R of each is 0.
                return Ok([0.0; 4]);
            }
            let results = tex.gather(st, c, g.offsets);
            return Ok(unitstate::gather_swizzle(
                &case.sampler,
                results,
                self.faults,
            ));
        }
        if case.texture.format.is_multi_colour() {
            return colour::sample(self.spec, case, api, tex, st, c, self.faults);
        }
        let lay = layout::resolve(
            self.spec,
            api,
            st.kind,
            case.sampler.depth_texture_mode,
            self.faults,
        )?;
        if !st.complete {
            if st.kind == Kind::Stencil && self.faults.has(Fault::IncompleteStencilAlphaZero) {
                return Ok([0.0; 4]);
            }
            return Ok(layout::INCOMPLETE);
        }
        let rgba = lay.apply(tex.lookup(st, c));
        Ok(unitstate::swizzle(
            &case.sampler,
            api,
            st.kind,
            rgba,
            self.faults,
        ))
    }
}

impl SoftUnit {
    /// The texels this unit reads for `case` (path-independent), as a model [`Footprint`] for
    /// failure dumps: level relative to the base, (x, y, layer) or `None` for the border, the
    /// stored value as written in the case (the unorm integer, or the float), Dt after clamping,
    /// the per-texel outcome and the weight. An incomplete texture reads nothing (empty list).
    pub fn footprint(&self, case: &Case) -> Result<Footprint, SoftError> {
        let mut tex = PreparedTexture::default();
        let (st, coords) = self.prepare_case(case, &mut tex)?;
        let mut trace = Trace::default();
        if st.complete {
            tex.lookup_observed(&st, &coords, &mut trace);
        } else {
            trace.dref = if st.clamp.dref {
                storage::clamp01(coords.dref)
            } else {
                coords.dref
            };
        }
        let base = case.texture.base_level;
        let texels = trace
            .texels
            .iter()
            .map(|t| {
                let rel = t.level.saturating_sub(base);
                let stored = match t.xyz {
                    None => t.raw as f64,
                    Some([x, y, layer]) => {
                        let lvl = case.texture.levels.get(rel as usize);
                        lvl.map_or(t.raw as f64, |l| {
                            let i = ((layer * l.height + y) * l.width + x) as usize;
                            match (&l.depth, st.kind) {
                                (_, Kind::Stencil) => l
                                    .stencil
                                    .as_ref()
                                    .and_then(|s| s.get(i))
                                    .map_or(0.0, |&v| v as f64),
                                (Texels::Unorm(v), _) => v.get(i).map_or(0.0, |&c| c as f64),
                                (Texels::Float(v), _) => v.get(i).map_or(0.0, |&d| d as f64),
                                (Texels::Colour(v), _) => v.get(i).map_or(0.0, |c| c[0] as f64),
                            }
                        })
                    }
                };
                FootprintTexel {
                    level: rel,
                    xyz: t.xyz,
                    stored,
                    dt: t.dt as f64,
                    pass: t.pass,
                    weight: t.weight as f64,
                }
            })
            .collect();
        Ok(Footprint {
            dref: trace.dref as f64,
            texels,
        })
    }
}

/// Samples `case` on `api` with the unit for `case.spec` (and `faults`).
pub fn sample_case(case: &Case, api: ApiPath, faults: Faults) -> Result<[f32; 4], SoftError> {
    SoftUnit::new(case.spec)
        .with_faults(faults)
        .sample(case, api)
}
