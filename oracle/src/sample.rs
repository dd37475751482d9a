//! One texel of a footprint: where its Dt comes from (stored texel, border, seamless cube corner), how
//! the spec clamps it, and which results each profile allows for it.

use crate::profile::PROFILES;
use crate::rules::{BorderRule, RefClamp, Rules};
use crate::unorm::{f32_candidates, float_to_unorm, unorm_max, Exact};
use shadowcheck_model::{Case, CompareFunc, Format, Texels};
use std::cmp::Ordering;

/// Which texel: a stored texel, the border of a level, or a cube corner built from three texels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Key {
    Texel {
        level: u32,
        x: i64,
        y: i64,
        layer: i64,
    },
    Border {
        level: u32,
    },
    /// §8.13.1: "there is no unique neighboring face from which to extract one texel"; the three
    /// available samples (x, y, layer).
    Corner {
        level: u32,
        from: [(i64, i64, i64); 3],
    },
}

/// What the lookup computes per texel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Depth comparison: r ∈ {fail value, 1}.
    Compare,
    /// TEXTURE_COMPARE_MODE NONE on a depth texture: "r = Dt".
    Depth,
    /// Colour texture: "texture comparison is bypassed", r = the colour value.
    Colour,
    /// DEPTH_STENCIL with DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX: "r = St".
    Stencil,
}

/// The values a texel may contribute under one profile: the two points {lo, hi} (`two`: a comparison
/// that may go either way) or every value in [lo, hi].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Poss {
    pub lo: f64,
    pub hi: f64,
    pub two: bool,
}

impl std::fmt::Display for Key {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Key::Texel { level, x, y, layer } => {
                write!(f, "texel ({x},{y}) layer {layer} level {level}")
            }
            Key::Border { level } => write!(f, "border texel, level {level}"),
            Key::Corner { level, .. } => {
                write!(f, "cube corner texel (built from three), level {level}")
            }
        }
    }
}

impl Poss {
    fn point(v: f64) -> Poss {
        Poss {
            lo: v,
            hi: v,
            two: false,
        }
    }
}

/// One evaluated texel.
#[derive(Debug, Clone)]
pub struct TexelEval {
    pub key: Key,
    /// As stored in the fixture (the integer for unorm formats).
    pub stored: f64,
    /// Dt after the spec's clamping (nearest double).
    pub dt: f64,
    /// This texel's r under the spec's exact arithmetic (`None`: the spec gives no single value).
    pub exact: Option<f64>,
    /// The exact comparison outcome (compare kind only).
    pub pass: Option<bool>,
    /// The allowed values per profile, in `PROFILES` order.
    pub poss: Vec<Poss>,
    /// Why this texel's value is left open, if it is.
    pub undefined: Option<&'static str>,
}

impl TexelEval {
    /// The values the strictest profile allows.
    pub fn strictest(&self) -> Poss {
        self.poss.first().copied().unwrap_or(Poss::point(self.dt))
    }
}

/// The wider fixed-point storages a `bits`-bit unorm texel of `format` may be held in.
///
/// GL 4.6 §8.5.1 and ES 3.2 §8.5.1 (the same sentence): "Requesting one of these sized internal
/// formats for any texture type will allocate at least the internal component sizes, and exactly the
/// component types shown for that format" (DEPTH_COMPONENT16/24, DEPTH24_STENCIL8 are ticked "Req.
/// format"; ES 3.2 Table 8.11 gives "minimum component resolutions"). So a D16 may be stored with 24 or
/// 32 bits, a D24 with 32, always fixed-point. The unsized format's precision is the implementation's,
/// and DEPTH_COMPONENT32 is not a required format (GL 4.6 Table 8.13: "desired component resolutions",
/// allocated "as closely as possible", §8.5): it may be held at 24 bits. Widths at which c/(2^b−1) is
/// exact (16 → 32: 2^32−1 = 65535·65537) add nothing new but cost nothing either.
pub fn wider_storage(format: Format, bits: u32) -> &'static [u32] {
    match (format, bits) {
        (Format::DepthUnsized | Format::D32, _) => &[24],
        (Format::D16, _) => &[24, 32],
        (Format::D24 | Format::D24S8, _) => &[32],
        _ => &[],
    }
}

/// Everything a texel evaluation needs that does not depend on the texel.
pub struct TexelCtx<'a> {
    pub case: &'a Case,
    pub rules: &'a Rules,
    pub kind: Kind,
    pub func: CompareFunc,
    /// Dref after divide and the spec's clamp (the spec value's reading).
    pub dref: f64,
    /// The Dref values an implementation may compare with (strict), clamped.
    pub dref_cands: Vec<f64>,
    /// r for a passing / failing texel.
    pub pass_v: f64,
    pub fail_v: f64,
    /// The component of a colour texture's texels and border colour this evaluation reads (0:
    /// R; a colour format of several components is evaluated once per component, GL 4.6
    /// Table 15.1 building Cb from them). 0 for every other format.
    pub component: usize,
}

struct Source {
    value: Exact,
    cands: Vec<Exact>,
    stored: f64,
    undefined: Option<&'static str>,
}

impl TexelCtx<'_> {
    fn fixed(&self) -> bool {
        self.case.texture.format.is_fixed_point()
    }

    /// Dt is clamped unless the spec clamps only fixed-point formats and this one is floating-point.
    fn clamps_dt(&self) -> bool {
        self.rules.ref_clamp != RefClamp::FixedPointOnly || self.fixed()
    }

    fn stored_texel(&self, level: u32, x: i64, y: i64, layer: i64) -> Source {
        let tex = &self.case.texture;
        let Some(l) = tex.levels.get(level as usize) else {
            return Source {
                value: Exact::F(0.0),
                cands: vec![],
                stored: f64::NAN,
                undefined: Some("texel outside the defined levels"),
            };
        };
        let idx = (x + y * l.width as i64 + layer * (l.width as i64 * l.height as i64)) as usize;
        if self.kind == Kind::Stencil {
            return match l.stencil.as_ref().and_then(|s| s.get(idx)) {
                Some(&st) => Source {
                    value: Exact::F(st as f64),
                    cands: vec![],
                    stored: st as f64,
                    undefined: None,
                },
                // GL 4.6 §8.5: "If the base internal format is DEPTH_STENCIL and format is not
                // DEPTH_STENCIL, then the values of the stencil index texture components are undefined."
                None => Source {
                    value: Exact::F(0.0),
                    cands: vec![],
                    stored: f64::NAN,
                    undefined: Some("stencil values were not uploaded: undefined (GL 4.6 §8.5)"),
                },
            };
        }
        let colour = match &l.depth {
            Texels::Colour(v) => Some(v.get(idx).map_or(0, |c| c[self.component.min(3)])),
            _ => None,
        };
        match &l.depth {
            Texels::Unorm(_) | Texels::Colour(_) => {
                let c = match (&l.depth, colour) {
                    (_, Some(c)) => c as u64,
                    (Texels::Unorm(v), None) => v.get(idx).copied().unwrap_or(0) as u64,
                    _ => 0,
                };
                let bits = tex.format.unorm_bits().unwrap_or(16);
                let value = Exact::Q {
                    c,
                    m: unorm_max(bits),
                };
                let mut cands = vec![value];
                for &w in wider_storage(tex.format, bits) {
                    // A wider store holds either neighbour of c·(2^w−1)/(2^b−1) (§2.3.5.2 (2.3)).
                    let mw = unorm_max(w);
                    let mb = unorm_max(bits);
                    let num = c * mw;
                    let (lo, hi) = (num / mb, num.div_ceil(mb));
                    cands.push(Exact::Q { c: lo, m: mw });
                    cands.push(Exact::Q { c: hi, m: mw });
                }
                Source {
                    value,
                    cands,
                    stored: c as f64,
                    undefined: None,
                }
            }
            // §8.5: "For depth component groups, the depth value is clamped to [0, 1]."
            Texels::Float(v) => {
                let f = v.get(idx).copied().unwrap_or(0.0) as f64;
                let value = Exact::F(f.clamp(0.0, 1.0));
                let mut cands = vec![value];
                if value.approx() != 0.0 && value.approx().abs() < f32::MIN_POSITIVE as f64 {
                    // GLSL 4.60 §4.7.1: "Any denormalized value ... can be flushed to 0."
                    cands.push(Exact::F(0.0));
                }
                Source {
                    value,
                    cands,
                    stored: f,
                    undefined: None,
                }
            }
        }
    }

    fn border(&self) -> Source {
        // TEXTURE_BORDER_COLOR: its first component for a depth texture (§8.14.2), the component
        // being evaluated for a colour texture ("the border values are used as the texel").
        let b = self.case.sampler.border[self.component.min(3)] as f64;
        let fixed = self.fixed();
        if self.kind == Kind::Stencil {
            return Source {
                value: Exact::F(0.0),
                cands: vec![],
                stored: b,
                undefined: Some("stencil border value is not defined for a depth border"),
            };
        }
        let (v, undefined) = match self.rules.border {
            BorderRule::ClampUnit | BorderRule::None => (b.clamp(0.0, 1.0), None),
            BorderRule::ClampToFormat => (if fixed { b.clamp(0.0, 1.0) } else { b }, None),
            BorderRule::UndefinedOutOfRange if fixed && !(0.0..=1.0).contains(&b) => (
                b.clamp(0.0, 1.0),
                Some("border depth out of range for a fixed-point format: \"the result is undefined\" (GL 4.6 §8.14.2)"),
            ),
            BorderRule::UndefinedOutOfRange => (b, None),
        };
        let value = Exact::F(v);
        let mut cands = vec![value];
        if let Some(bits) = self.case.texture.format.unorm_bits() {
            // The border may be held at the format's precision: either neighbour (§2.3.5.2).
            let (p, o) = float_to_unorm(v, bits);
            cands.push(Exact::Q {
                c: p,
                m: unorm_max(bits),
            });
            cands.push(Exact::Q {
                c: o,
                m: unorm_max(bits),
            });
        }
        Source {
            value,
            cands,
            stored: b,
            undefined,
        }
    }

    fn source(&self, key: Key) -> Source {
        match key {
            Key::Texel { level, x, y, layer } => self.stored_texel(level, x, y, layer),
            Key::Border { .. } => self.border(),
            Key::Corner { level, from } => {
                let s: Vec<Source> = from
                    .iter()
                    .map(|&(x, y, l)| self.stored_texel(level, x, y, l))
                    .collect();
                let vals: Vec<f64> = s.iter().map(|s| s.value.approx()).collect();
                let avg = vals.iter().sum::<f64>() / 3.0;
                let same = s.iter().all(|x| x.value == s[0].value);
                // "The recommended method to generate this texel is to average the values of the three
                // available samples. However, implementations are free to construct this fourth texel in
                // another way, so long as, when the three available samples have the same value, this
                // texel also has that value."
                if same {
                    Source {
                        value: s[0].value,
                        cands: s[0].cands.clone(),
                        stored: s[0].stored,
                        undefined: None,
                    }
                } else {
                    Source {
                        value: Exact::F(avg),
                        cands: vec![Exact::F(avg)],
                        stored: avg,
                        undefined: Some("seamless cube corner texel built by the implementation (GL 4.6 §8.13.1)"),
                    }
                }
            }
        }
    }

    fn table(&self, ord: Option<Ordering>) -> (bool, bool) {
        let one = |o: Option<Ordering>| match (self.rules.table)(self.func, o) {
            Ok(Some(p)) => (p, !p),
            _ => (true, true),
        };
        match ord {
            Some(_) => one(ord),
            // An unordered operand (NaN): whatever ordering the implementation's compare yields.
            None => [Ordering::Less, Ordering::Equal, Ordering::Greater]
                .iter()
                .fold((false, false), |acc, o| {
                    let (p, f) = one(Some(*o));
                    (acc.0 || p, acc.1 || f)
                }),
        }
    }

    /// The values r may take when Dt is unknown: the comparison table over every ordering (ALWAYS
    /// and NEVER stay exact).
    pub fn open_outcome(&self) -> Poss {
        self.two(self.table(None))
    }

    fn two(&self, (p, f): (bool, bool)) -> Poss {
        match (p, f) {
            (true, true) => Poss {
                lo: self.pass_v.min(self.fail_v),
                hi: self.pass_v.max(self.fail_v),
                two: true,
            },
            (true, false) => Poss::point(self.pass_v),
            _ => Poss::point(self.fail_v),
        }
    }

    /// Evaluates one texel.
    pub fn eval(&self, key: Key) -> TexelEval {
        let src = self.source(key);
        let clamp = |e: Exact| match e {
            Exact::F(v) if self.clamps_dt() && self.kind != Kind::Stencil => {
                Exact::F(v.clamp(0.0, 1.0))
            }
            other => other,
        };
        let value = clamp(src.value);
        let dt = value.approx();
        // Strict Dt candidates: each stored candidate and its f32 neighbours.
        let mut cands: Vec<f64> = Vec::with_capacity(6);
        let mut exact_cands: Vec<Exact> = Vec::with_capacity(3);
        for c in src.cands.iter().map(|c| clamp(*c)) {
            exact_cands.push(c);
            cands.extend(f32_candidates(c));
        }
        match self.kind {
            Kind::Compare => {
                let exact_ord = value.cmp_from(self.dref);
                let exact = (self.rules.table)(self.func, exact_ord).ok().flatten();
                let mut strict = (false, false);
                fn add_to(s: &mut (bool, bool), o: (bool, bool)) {
                    s.0 |= o.0;
                    s.1 |= o.1;
                }
                if src.undefined.is_some() {
                    // The texel's value is open, the comparison table is not: Tables 8.22/8.23 give
                    // "ALWAYS | 1.0" and "NEVER | 0.0" whatever Dt is, so evaluate the table over every
                    // ordering of Dref and the unknown Dt (as for a NaN operand).
                    add_to(&mut strict, self.table(None));
                }
                for &d in &self.dref_cands {
                    for e in &exact_cands {
                        add_to(&mut strict, self.table(e.cmp_from(d)));
                    }
                    for &c in &cands {
                        add_to(&mut strict, self.table(d.partial_cmp(&c)));
                    }
                }
                if strict == (false, false) {
                    add_to(&mut strict, self.table(exact_ord));
                }
                let mut poss = vec![self.two(strict); PROFILES.len()];
                if let (Key::Corner { .. }, Some(_)) = (key, src.undefined) {
                    // §8.13.1 leaves the fourth corner texel to the implementation ("free to
                    // construct this fourth texel in another way"); built from the three texels'
                    // comparison results (their average, the recommended method applied to the
                    // values the filter combines), it holds any value between a fail and a pass.
                    let o = self.open_outcome();
                    poss = vec![Poss { two: false, ..o }; PROFILES.len()];
                }
                for (i, p) in PROFILES.iter().enumerate() {
                    if matches!(key, Key::Corner { .. }) && src.undefined.is_some() {
                        continue;
                    }
                    if let Some(bits) = p.ref_bits {
                        let mut o = strict;
                        // 0 and 1 survive every fixed-point quantization exactly: an exact tie there
                        // is not within reference precision.
                        let exact_end =
                            exact_ord == Some(Ordering::Equal) && (dt == 0.0 || dt == 1.0);
                        if ((self.dref - dt).abs() <= (bits as f64).exp2().recip() && !exact_end)
                            || self.dref.is_nan()
                        {
                            o = self.table(None);
                            o = (o.0 || strict.0, o.1 || strict.1);
                        }
                        poss[i] = self.two(o);
                    }
                }
                // An ordered pair the table assigns no value to (EXT_shadow_samplers GREATER at
                // D_ref = Dt): the result is open, labelled like an undefined texel.
                let open_row = exact.is_none() && exact_ord.is_some() && src.undefined.is_none();
                TexelEval {
                    key,
                    stored: src.stored,
                    dt,
                    exact: exact.map(|p| if p { self.pass_v } else { self.fail_v }),
                    pass: exact,
                    poss,
                    undefined: if open_row {
                        Some("the comparison table assigns no value at this ordering of Dref and Dt (EXT_shadow_samplers Table 3.X: GREATER \"1.0, if D_ref > Dt\", \"0.0, if D_ref < Dt\"): either value")
                    } else {
                        src.undefined
                    },
                }
            }
            Kind::Depth | Kind::Colour | Kind::Stencil => {
                let (mut lo, mut hi) = (dt, dt);
                for c in &cands {
                    lo = lo.min(*c);
                    hi = hi.max(*c);
                }
                let mut poss = vec![Poss { lo, hi, two: false }; PROFILES.len()];
                if src.undefined.is_some() {
                    let top = if self.kind == Kind::Stencil {
                        255.0
                    } else {
                        1.0f64.max(hi)
                    };
                    poss = vec![
                        Poss {
                            lo: lo.min(0.0),
                            hi: top,
                            two: false,
                        };
                        PROFILES.len()
                    ];
                }
                for (i, p) in PROFILES.iter().enumerate() {
                    if let (Some(bits), false) = (p.ref_bits, self.kind == Kind::Stencil) {
                        let t = (bits as f64).exp2().recip();
                        let (lo, hi) = (poss[i].lo, poss[i].hi);
                        // Widened, but not past the range the values can take.
                        poss[i] = Poss {
                            lo: (lo - t).max(lo.min(0.0)),
                            hi: (hi + t).min(hi.max(1.0)),
                            two: false,
                        };
                    }
                }
                TexelEval {
                    key,
                    stored: src.stored,
                    dt,
                    exact: src.undefined.is_none().then_some(dt),
                    pass: None,
                    poss,
                    undefined: src.undefined,
                }
            }
        }
    }
}
