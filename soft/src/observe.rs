//! What one lookup does, reported as it happens: the clamped reference value and every texel
//! read with its comparison and weight ([`TexelVisit`]), for footprints and failure dumps. The
//! lookup (`filter.rs`) is generic over the [`Observer`]: `()` observes nothing and costs nothing,
//! [`Trace`] collects the visits.

/// One texel a lookup read (see [`Observer`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexelVisit {
    /// Absolute mip level.
    pub level: u32,
    /// (x, y, storage layer); `None` for a border texel.
    pub xyz: Option<[u32; 3]>,
    /// The stored value as prepared (f32 after conversion), or the border value.
    pub raw: f32,
    /// Dt after the spec's clamping (depth kinds), else `raw`.
    pub dt: f32,
    /// The texel's comparison outcome (`None` when no per-texel comparison is made).
    pub pass: Option<bool>,
    /// Its weight in r (bilinear weight × level blend weight; corner shares folded in).
    pub weight: f32,
}

/// Receives what one lookup does, for footprints and failure dumps. `()` observes nothing and
/// costs nothing (`ACTIVE = false` removes the reporting code).
pub trait Observer {
    const ACTIVE: bool;
    /// The reference value after the projective divide and clamping.
    fn reference(&mut self, dref: f32);
    fn texel(&mut self, t: TexelVisit);
}

impl Observer for () {
    const ACTIVE: bool = false;
    #[inline(always)]
    fn reference(&mut self, _: f32) {}
    #[inline(always)]
    fn texel(&mut self, _: TexelVisit) {}
}

/// Collects the visits of one lookup.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Trace {
    pub dref: f32,
    pub texels: Vec<TexelVisit>,
}

impl Observer for Trace {
    const ACTIVE: bool = true;
    fn reference(&mut self, dref: f32) {
        self.dref = dref;
    }
    fn texel(&mut self, t: TexelVisit) {
        self.texels.push(t);
    }
}
