//! The evaluation of one case: prepare Dref and coordinates, decide completeness, enumerate the ways
//! the lookup may be carried out (cube face, layer rounding, mip levels, per profile), and combine the
//! texels into the spec value and the acceptance sets.

use crate::accept;
use crate::lod::{self, Pick};
use crate::profile::PROFILES;
use crate::rules::{Filtering, Incomplete, RefClamp, Rules};
use crate::sample::{Key, Kind, TexelCtx, TexelEval};
use crate::select::{build, Geo};
use crate::unorm::{f32_candidates, f32r, Exact};
use crate::{check, cube, layout, wrap, Evaluation, OracleError, Step};
use shadowcheck_model::{
    Acceptance, Case, CompareMode, DepthStencilMode, Expectation, Footprint, FootprintTexel,
    Interval, Target,
};
use std::collections::BTreeMap;

struct Eval {
    rules: Rules,
    steps: Vec<Step>,
    cites: Vec<String>,
    notes: Vec<String>,
}

impl Eval {
    fn step(&mut self, what: String, cite: &str) {
        self.steps.push(Step {
            what,
            cite: cite.to_string(),
        });
        self.cite(cite);
    }
    fn cite(&mut self, cite: &str) {
        if !self.cites.iter().any(|c| c == cite) {
            self.cites.push(cite.to_string());
        }
    }
    fn note(&mut self, n: impl Into<String>) {
        let n = n.into();
        if !self.notes.contains(&n) {
            self.notes.push(n);
        }
    }
}

/// Evaluates `case` under `rules` (the spec's own, or an alternative reading from `contradictions`).
pub fn run(case: &Case, rules: Rules) -> Result<Evaluation, OracleError> {
    check::check(case, &rules)?;
    let mut e = Eval {
        rules,
        steps: Vec::new(),
        cites: Vec::new(),
        notes: Vec::new(),
    };
    let s = &case.sampler;
    let tex = &case.texture;
    let fmt = tex.format;

    // Which computation: §8.23.1 "If the base internal format is DEPTH_STENCIL and the value of
    // DEPTH_STENCIL_TEXTURE_MODE is STENCIL_INDEX, then r = St. Otherwise, if the value of
    // TEXTURE_COMPARE_MODE is NONE, then r = Dt."
    let kind = if !fmt.is_depth() {
        e.step(
            format!("format {fmt} is not a depth format: \"texture comparison is bypassed\", r = the colour value"),
            rules.table_cite,
        );
        if matches!(
            rules.spec,
            shadowcheck_model::Spec::Sgix | shadowcheck_model::Spec::SgixAmbient
        ) {
            e.note("SGIX_shadow defines its operators \"only for textures with internal format DEPTH_COMPONENT\"; the bypass is ARB_shadow's (issue 5)");
        }
        Kind::Colour
    } else if fmt.has_stencil() && s.depth_stencil_mode == Some(DepthStencilMode::StencilIndex) {
        e.step(
            "DEPTH_STENCIL texture with DEPTH_STENCIL_TEXTURE_MODE = STENCIL_INDEX: r = St".into(),
            "GL 4.6 §8.23.1, §8.16",
        );
        Kind::Stencil
    } else if s.compare_mode == CompareMode::None {
        e.step(
            "TEXTURE_COMPARE_MODE = NONE: r = Dt".into(),
            rules.table_cite,
        );
        Kind::Depth
    } else {
        Kind::Compare
    };

    // Completeness (§8.17).
    let incomplete = lod::incomplete(&rules, tex, s, kind == Kind::Stencil);
    let mode = s.depth_texture_mode;
    let mut layouts = BTreeMap::new();
    for &api in &case.api {
        let (l, cite) = layout::layout(&e.rules, api, kind, mode, incomplete.is_some());
        e.step(
            format!(
                "layout on `{api}`: ({})",
                l.iter().map(|c| c.key()).collect::<Vec<_>>().join(",")
            ),
            cite,
        );
        layouts.insert(api, l);
    }
    if let Some(why) = incomplete {
        let cite = match rules.incomplete {
            Incomplete::Legacy0001 => {
                "GL 2.1 §3.11.2 / ARB_fragment_program_shadow / ES 2.0 §3.8.2: (0,0,0,1)"
            }
            Incomplete::ShadowZero => "GL 4.6 / ES 3.2 §11.1.3.5: 0 for a shadow sampler",
        };
        e.step(format!("texture incomplete: {why}; r = 0"), cite);
        e.cite(if rules.es_depth_completeness {
            "ES 3.2 §8.17"
        } else {
            "GL 4.6 §8.17"
        });
        let acc = Acceptance(vec![Interval::point(0.0)]);
        return Ok(finish(
            e,
            Some(0.0),
            [acc.clone(), acc],
            layouts,
            Footprint::default(),
        ));
    }

    // Coordinates and Dref: "The API passes floats" (COMMON.md); projective: divided by q.
    let c = case.lookup.coord.map(f32r);
    let proj = case.lookup.projective;
    let q = if proj { c[3] } else { 1.0 };
    let dref_in = f32r(case.lookup.dref);
    let dref_raw = dref_in / q;
    if proj {
        e.step(
            format!("projective: s, t, r and Dref divided by q = {q}; Dref = {dref_in} / {q} = {dref_raw}"),
            "GLSL 1.30 §8.7 textureProj / GL 4.6 §8.14.1",
        );
    }
    let fixed = fmt.is_fixed_point();
    let clamp_ref = match rules.ref_clamp {
        RefClamp::Always => true,
        RefClamp::FixedPointOnly => fixed,
        RefClamp::Unstated => false,
    };
    let dref = if clamp_ref {
        dref_raw.clamp(0.0, 1.0)
    } else {
        dref_raw
    };
    let mut dref_cands: Vec<f64> = if proj {
        f32_candidates(Exact::F(dref_raw)).to_vec()
    } else {
        vec![dref_raw]
    };
    if dref_raw != 0.0 && dref_raw.abs() < f32::MIN_POSITIVE as f64 {
        // GLSL 4.60 §4.7.1: "Any denormalized value input into a shader or potentially generated by any
        // operation in a shader can be flushed to 0."
        dref_cands.push(0.0);
    }
    if rules.ref_clamp == RefClamp::Unstated {
        let clamped: Vec<f64> = dref_cands.iter().map(|d| d.clamp(0.0, 1.0)).collect();
        if !(0.0..=1.0).contains(&dref_raw) {
            e.note("SGIX_shadow leaves the clamping of R unstated (NVIDIA Implementation Details); both readings are accepted");
        }
        dref_cands.extend(clamped);
    } else if clamp_ref {
        dref_cands.iter_mut().for_each(|d| *d = d.clamp(0.0, 1.0));
    }
    if kind == Kind::Compare {
        let how = match (rules.ref_clamp, clamp_ref) {
            (RefClamp::Unstated, _) => "not clamped (literal reading; clamped also accepted)",
            (_, true) => "clamped to [0,1]",
            (_, false) => "not clamped (floating-point depth format)",
        };
        e.step(
            format!("Dref = {dref_raw}: {how} → {dref}"),
            rules.clamp_cite,
        );
        if dref.is_nan()
            && !matches!(
                s.compare_func,
                shadowcheck_model::CompareFunc::Always | shadowcheck_model::CompareFunc::Never
            )
        {
            e.note("Dref is NaN: the comparison tables give no result for an unordered reference");
        }
    }
    let fail_v = if rules.has_fail_value {
        (s.fail_value.unwrap_or(0.0) as f64).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (pass_v, fail_v) = if rules_ambient_on_pass(&e.rules) {
        (fail_v, 0.0)
    } else {
        (1.0, fail_v)
    };
    if rules.has_fail_value && kind == Kind::Compare {
        e.step(
            format!("fail value (clamped to [0,1]) = {fail_v}: replaces 0.0 for a failing texel"),
            if rules.spec == shadowcheck_model::Spec::ArbAmbient {
                "ARB_shadow_ambient §3.8.13.1"
            } else {
                "SGIX_shadow_ambient Notes"
            },
        );
    }
    let tcx = TexelCtx {
        case,
        rules: &rules,
        kind,
        func: s.compare_func,
        dref,
        dref_cands,
        pass_v,
        fail_v,
    };

    // Geometry: faces (§8.13) and layers (§8.14.2) an implementation may choose.
    let mut geos: Vec<Geo> = Vec::new();
    let (s0, t0) = (c[0] / q, c[1] / q);
    let layers_of = |n: i64, x: f64| {
        let (a, b) = wrap::layer(x, n);
        if a == b {
            vec![a]
        } else {
            vec![a, b]
        }
    };
    let l0 = &tex.levels[0];
    match tex.target {
        Target::T1d => geos.push(Geo {
            s: s0,
            t: 0.0,
            layer: 0,
            face: None,
        }),
        Target::T2d | Target::Rect => geos.push(Geo {
            s: s0,
            t: t0,
            layer: 0,
            face: None,
        }),
        Target::T1dArray => layers_of(l0.layers as i64, c[1]).into_iter().for_each(|l| {
            geos.push(Geo {
                s: s0,
                t: 0.0,
                layer: l,
                face: None,
            })
        }),
        Target::T2dArray => layers_of(l0.layers as i64, c[2]).into_iter().for_each(|l| {
            geos.push(Geo {
                s: s0,
                t: t0,
                layer: l,
                face: None,
            })
        }),
        Target::Cube | Target::CubeArray => {
            let dir = [c[0], c[1], c[2]];
            let cubes = if tex.target == Target::Cube {
                vec![0]
            } else {
                layers_of(l0.layers as i64 / 6, f32r(case.lookup.layer))
            };
            for f in cube::faces(dir) {
                let (fs, ft) = cube::face_st(f, dir);
                for &cu in &cubes {
                    geos.push(Geo {
                        s: fs,
                        t: ft,
                        layer: cu * 6 + f as i64,
                        face: Some(f),
                    });
                }
            }
            if let Some(g) = geos.first() {
                e.step(
                    format!(
                        "cube face {} (major axis), s = {}, t = {}",
                        cube::FACE_NAMES[g.face.unwrap_or(0)],
                        g.s,
                        g.t
                    ),
                    "GL 4.6 §8.13 Table 8.19",
                );
            }
        }
    }
    let mut choice_notes: Vec<&str> = Vec::new();
    if geos.len() > 1 {
        choice_notes
            .push("the major axis or the layer is tied: the implementation's rounding/tie rule decides (GL 4.6 §8.13, §8.14.2 footnote 4)");
    }
    if tex.target.is_array() {
        if let Some(g) = geos.first() {
            let l = if tex.target == Target::CubeArray {
                g.layer / 6
            } else {
                g.layer
            };
            e.step(
                format!("layer = clamp(RNE(layer coordinate), 0, d − 1) = {l}"),
                "GL 4.6 §8.14.2 (l = clamp(RNE(r), 0, d_s − 1))",
            );
        }
    }
    let o = case.lookup.offset;
    if o != [0; 3] {
        e.step(
            format!(
                "texel offset (δu, δv, δw) = ({}, {}, {}): u = w·s + δu, v = h·t + δv in the texels of each selected level, before wrapping",
                o[0], o[1], o[2]
            ),
            "GL 4.6 §8.14.2 (8.10), §8.14.3; GLSL 4.60 §8.9.2 textureOffset",
        );
    }
    let finite = geos.iter().all(|g| g.s.is_finite() && g.t.is_finite());
    if geos.is_empty() || !finite {
        return Ok(undefined(
            e,
            &tcx,
            layouts,
            "the texture coordinates are not finite or the cube direction is zero: the texel selection is undefined",
        ));
    }

    // Level of detail (§8.14.1) and the picks per profile (§8.14.3, §8.15).
    let texobj_bias = if rules.lod_bias {
        s.lod_bias as f64
    } else {
        0.0
    };
    let lam = lod::lambda(
        f32r(case.lookup.lod),
        texobj_bias,
        f32r(case.lookup.bias),
        s,
    );
    if let Some(n) = lam.note {
        e.note(n);
    }
    let q_rel = if s.min_filter.is_mipmap() {
        lod::q_rel(tex, s).unwrap_or(0)
    } else {
        0
    };
    let spec_lambda = if lam.spec.is_nan() {
        lam.lo.max(0.0).min(q_rel as f64)
    } else {
        lam.spec
    };
    let spec_pick = lod::spec_pick(s, spec_lambda, q_rel);
    e.step(
        format!(
            "λ = {} (λ_base {} + biases, clamped to [{}, {}]) → {}",
            lam.spec,
            f32r(case.lookup.lod),
            s.min_lod,
            s.max_lod,
            describe_pick(spec_pick, lam.spec)
        ),
        "GL 4.6 §8.14.1, §8.14.3 (8.14)-(8.16), §8.15",
    );

    let mut texels: Vec<TexelEval> = Vec::new();
    let spec_scen = build(&rules, case, &tcx, &mut texels, geos[0], spec_pick);
    let mut accept: [Vec<Interval>; 2] = [Vec::new(), Vec::new()];
    let fraction = kind == Kind::Compare && rules.filtering == Filtering::ImplementationDependent;
    let mut many_picks = false;
    for (pi, prof) in PROFILES.iter().enumerate() {
        let mut picks = Vec::new();
        lod::picks(
            s,
            lam.lo - prof.lod_tol,
            lam.hi + prof.lod_tol,
            q_rel,
            &mut picks,
        );
        if pi == 0 && picks.len() > 1 {
            many_picks = true;
        }
        // Coordinates off by up to coord_tol texels of the base level (a NEAREST boundary may go either way).
        let (w0, h0) = if tex.target == Target::Rect {
            (1.0, 1.0)
        } else {
            (l0.width as f64, l0.height as f64)
        };
        let shifts: &[f64] = if prof.coord_tol > 0.0 {
            &[-1.0, 0.0, 1.0]
        } else {
            &[0.0]
        };
        for g in &geos {
            for ds in shifts {
                for dt in shifts {
                    let g = Geo {
                        s: g.s + ds * prof.coord_tol / w0,
                        t: g.t + dt * prof.coord_tol / h0,
                        ..*g
                    };
                    for p in &picks {
                        let sc = build(&rules, case, &tcx, &mut texels, g, *p);
                        accept::scen_intervals(&sc, &texels, pi, prof, fraction, &mut accept[pi]);
                    }
                }
            }
        }
    }
    if many_picks {
        choice_notes.push("the level of detail sits on a level-selection boundary: nearest(λ) preferred/alternative or the bias clamp lets either level be used (GL 4.6 §8.14.3)");
    }

    // Spec value and footprint.
    let spec_value = if lam.spec.is_nan() {
        None
    } else {
        accept::spec_value(&spec_scen, &texels)
    };
    let w = accept::weights(&spec_scen);
    let mut fp = Footprint {
        dref,
        texels: Vec::with_capacity(w.len()),
    };
    let (mut passes, mut fails) = (0, 0);
    for &(i, weight) in &w {
        let t = &texels[i];
        if let (Some(u), true) = (t.undefined, weight > 0.0) {
            e.note(u);
        }
        if weight > 0.0 {
            match t.pass {
                Some(true) => passes += 1,
                Some(false) => fails += 1,
                None => {}
            }
        }
        let (level, xyz) = match t.key {
            Key::Texel { level, x, y, layer } => (level, Some([x as u32, y as u32, layer as u32])),
            Key::Border { level } | Key::Corner { level, .. } => (level, None),
        };
        let pass = if kind == Kind::Compare && !t.poss[0].two {
            t.pass
        } else {
            None
        };
        fp.texels.push(FootprintTexel {
            level,
            xyz,
            stored: t.stored,
            dt: t.dt,
            pass,
            weight,
        });
        let what = match kind {
            Kind::Compare => format!(
                "{}: stored {} → Dt = {}; Dref {} vs Dt → {} (weight {})",
                t.key,
                t.stored,
                t.dt,
                dref,
                match (t.pass, t.poss[0].two) {
                    (_, true) if t.undefined.is_some() =>
                        "either (the texel's value is left to the implementation)".to_string(),
                    (_, true) => "either (within reference precision)".to_string(),
                    (Some(p), _) =>
                        if p {
                            "pass".to_string()
                        } else {
                            "fail".to_string()
                        },
                    (None, _) => "unordered".to_string(),
                },
                weight
            ),
            _ => format!(
                "{}: stored {} → r = {} (weight {})",
                t.key, t.stored, t.dt, weight
            ),
        };
        e.steps.push(Step {
            what,
            cite: rules.table_cite.to_string(),
        });
    }
    if kind == Kind::Compare {
        e.cite(rules.table_cite);
    }
    e.cite("GL 4.6 §8.14.2");
    if matches!(
        fmt,
        shadowcheck_model::Format::D32f | shadowcheck_model::Format::D32fS8
    ) {
        e.cite("GL 4.6 §8.5 (depth upload clamped to [0,1])");
    } else {
        e.cite("GL 4.6 §2.3.5.1 (2.1)");
    }
    if spec_scen.filtered() && kind == Kind::Compare {
        e.cite(rules.filter_cite);
        if rules.filtering == Filtering::ImplementationDependent && passes > 0 && fails > 0 {
            e.note(format!("filtered r is implementation-dependent, \"proportional to the number of comparison passes or failures\" ({}); the spec value is the bilinear-weighted fraction", rules.filter_cite));
        }
    }
    let colour_bits = if kind == Kind::Colour {
        fmt.unorm_bits()
    } else {
        None
    };
    let range = match kind {
        Kind::Compare => (pass_v.min(fail_v), pass_v.max(fail_v)),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    };
    let [strict, lenient] = accept::finalize(accept, colour_bits, range, spec_value);
    // A choice the spec leaves to the implementation is worth a label only where it changes the result.
    if !matches!(spec_value, Some(v) if strict.0 == [Interval::point(v)]) {
        choice_notes.into_iter().for_each(|n| e.note(n));
    }
    Ok(finish(e, spec_value, [strict, lenient], layouts, fp))
}

fn describe_pick(p: Pick, l: f64) -> String {
    let f = |lin: bool| if lin { "LINEAR" } else { "NEAREST" };
    match p {
        Pick::One { level, linear } => format!(
            "level base+{level}, {} ({})",
            f(linear),
            if l <= 0.0 {
                "magnification"
            } else {
                "minification"
            }
        ),
        Pick::Two {
            d1,
            d2,
            linear,
            f: w,
            ..
        } => format!(
            "levels base+{d1} and base+{d2}, {} each, blended with frac(λ) = {w}",
            f(linear)
        ),
    }
}

/// SGIX_shadow_ambient's overview reading (contradiction `sgix-ambient`): the ambient value on a pass.
fn rules_ambient_on_pass(r: &Rules) -> bool {
    r.ambient_on_pass
}

/// A lookup whose texel selection the spec leaves undefined: every value r can take is accepted.
fn undefined(
    mut e: Eval,
    tcx: &TexelCtx,
    layouts: BTreeMap<shadowcheck_model::ApiPath, [shadowcheck_model::Channel; 4]>,
    why: &str,
) -> Evaluation {
    e.note(why);
    let iv = match tcx.kind {
        Kind::Compare => Interval::new(tcx.pass_v.min(tcx.fail_v), tcx.pass_v.max(tcx.fail_v)),
        Kind::Stencil => Interval::new(0.0, 255.0),
        _ => Interval::new(0.0, 1.0),
    };
    let acc = Acceptance(vec![iv]);
    finish(e, None, [acc.clone(), acc], layouts, Footprint::default())
}

fn finish(
    e: Eval,
    spec_value: Option<f64>,
    acc: [Acceptance; 2],
    layout: BTreeMap<shadowcheck_model::ApiPath, [shadowcheck_model::Channel; 4]>,
    footprint: Footprint,
) -> Evaluation {
    let [strict, lenient] = acc;
    let mut accept = BTreeMap::new();
    accept.insert(PROFILES[0].profile, strict);
    accept.insert(PROFILES[1].profile, lenient);
    let implementation_defined = if e.notes.is_empty() {
        None
    } else {
        Some(e.notes.join("; "))
    };
    Evaluation {
        expect: Expectation {
            spec_value,
            accept,
            layout,
            implementation_defined,
            citations: e.cites,
        },
        footprint,
        steps: e.steps,
    }
}
