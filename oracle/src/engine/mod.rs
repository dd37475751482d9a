//! The evaluation of one case, as a list of phases (see [`run`]):
//! - `inputs`: which computation (compare, r = Dt, colour, stencil), coordinates, Dref (projective
//!   divide, the spec's clamp, the values an implementation may compare with), pass / fail values;
//! - completeness (`lod::incomplete`) and the layout of r per API path (`layout`);
//! - `geometry`: the cube faces and array layers an implementation may choose, the texel offset;
//! - `levels`: λ and the level picks, then per profile every way the lookup may be carried out
//!   (texel selection in `select`, comparison per texel in `sample`, filtering in `accept`);
//! - `footprint`: the spec's own texels, weights and outcomes;
//! - acceptance: `accept::finalize` turns the per-profile intervals into the acceptance sets.

mod colour;
mod footprint;
mod gather;
mod geometry;
mod inputs;
mod levels;
mod stage;

pub(crate) use stage::touches as stage_touches;

use crate::accept;
use crate::profile::PROFILES;
use crate::rules::{Incomplete, Rules};
use crate::sample::Kind;
use crate::select::build;
use crate::{check, contradictions, layout, lod, Evaluation, OracleError, Step};
use shadowcheck_model::{
    Acceptance, ApiPath, Case, Channel, Expectation, Footprint, Interval, KeyMap, OtherLayout,
    Profile,
};

/// The derivation so far: steps, citations and notes (implementation-defined choices), in order.
struct Eval {
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

/// How the values reach the lookup function changes nothing in the expectation: a uniform, a
/// flat input or a value that differs between the fragments of a quad is the same value at the
/// fragment that is read (GLSL 4.60 / GLSL ES 3.20 §8.9.4, textureGatherOffset: "the offset can
/// be variable (non constant)"); the derivation says so, with the sentence.
fn delivery(e: &mut Eval, case: &Case) {
    let d = case.lookup.delivery;
    if d.is_literal() {
        return;
    }
    let es = case.spec == shadowcheck_model::Spec::Gles32;
    let (what, cite) = if case.lookup.gather.is_some() && case.lookup.offset != [0; 3] {
        (
            format!("delivery `{d}`: the offset \"can be variable (non constant)\"; the lookup is the one with these values"),
            if es { "GLSL ES 3.20 §8.9.4" } else { "GLSL 4.60 §8.9.4" },
        )
    } else {
        // §8.9's functions take P, the reference, the LOD and the gradients as ordinary
        // arguments; only the offsets are required to be constant expressions.
        (
            format!("delivery `{d}`: the values are not constant expressions; the lookup is the one with these values"),
            if es { "GLSL ES 3.20 §8.9" } else { "GLSL 4.60 §8.9" },
        )
    };
    e.step(what, cite);
}

/// Evaluates `case` under `rules` (the spec's own, or an alternative reading from `contradictions`).
pub fn run(case: &Case, rules: Rules) -> Result<Evaluation, OracleError> {
    check::check(case, &rules)?;
    let mut e = Eval {
        steps: Vec::new(),
        cites: Vec::new(),
        notes: Vec::new(),
    };
    delivery(&mut e, case);
    // The effective sampling state (sampler object, seamless enable); it must be legal too.
    let (case, rules, object_refused) = inputs::effective(&mut e, rules, case);
    let case: &Case = &case;
    check::check_effective(case, &rules)?;
    // Completeness (§8.17), or a sampler object's state the texture would refuse (§8.2).
    let incomplete = |stencil: bool| {
        object_refused
            .clone()
            .or_else(|| lod::incomplete(&rules, &case.texture, &case.sampler, stencil))
    };
    // An API without incomplete textures (Vulkan) has no such case to run.
    if let (Incomplete::NotApplicable(why), Some(what)) = (rules.incomplete, incomplete(false)) {
        return Err(OracleError::NotApplicable {
            case: case.id.clone(),
            spec: rules.doc.to_string(),
            why: format!("GL would call the texture incomplete ({what}): {why}"),
        });
    }
    if case.lookup.gather.is_some() {
        return Ok(gather::run(e, &rules, case, incomplete(false)));
    }
    let kind = inputs::kind(&mut e, &rules, case);
    let incomplete = incomplete(kind == Kind::Stencil);
    // A colour format of several components: every component of Cb is judged (Table 15.1).
    let components = if kind == Kind::Colour && incomplete.is_none() {
        case.texture.format.components().max(1)
    } else {
        1
    };
    let layouts = layouts(&mut e, &rules, case, kind, incomplete.is_some(), components);
    if let Some(why) = incomplete {
        return Ok(incomplete_texture(e, &rules, &why, layouts, kind));
    }
    if components > 1 {
        return Ok(colour::run(e, &rules, case, layouts, components));
    }
    Ok(match value(&mut e, &rules, case, kind, 0) {
        Ok((spec_value, acc, fp)) => finish(e, spec_value, acc, layouts, fp),
        Err((iv, why)) => undefined(e, iv, layouts, why),
    })
}

/// The spec value, the acceptance set per profile (in `PROFILES` order) and the footprint of r.
type Value = (Option<f64>, Vec<Acceptance>, Footprint);

/// r of one component (0 but for a colour texture of several components): the spec value, the
/// acceptance set per profile (in `PROFILES` order) and the footprint; or, where the spec leaves
/// the texel selection undefined, every value r can take and why.
fn value(
    e: &mut Eval,
    rules: &Rules,
    case: &Case,
    kind: Kind,
    component: usize,
) -> Result<Value, (Interval, &'static str)> {
    let coords = inputs::coords(case);
    let mut tcx = inputs::texel_ctx(e, rules, case, kind, &coords);
    tcx.component = component;
    let open = || match kind {
        // ALWAYS / NEVER: 1.0 / 0.0 whatever the texel (Tables 8.22/8.23).
        Kind::Compare => {
            let p = tcx.open_outcome();
            Interval::new(p.lo, p.hi)
        }
        Kind::Stencil => Interval::new(0.0, 255.0),
        _ => Interval::new(0.0, 1.0),
    };
    if let Some(why) = inputs::undefined_request(rules, case, kind) {
        return Err((open(), why));
    }
    // Choices the spec leaves to the implementation; labelled only where they change the result.
    let mut choices: Vec<&'static str> = Vec::new();
    let lod = levels::lod(e, rules, case);
    let linear = match lod.spec_pick {
        lod::Pick::One { linear, .. } | lod::Pick::Two { linear, .. } => linear,
    };
    let geos = geometry::geometries(e, rules, case, &coords, linear, &mut choices);
    let finite = geos.iter().all(|g| g.s.is_finite() && g.t.is_finite());
    let Some(&spec_geo) = geos.first().filter(|_| finite) else {
        return Err((
            open(),
            "the texture coordinates are not finite or the cube direction is zero: the texel selection is undefined",
        ));
    };
    let mut texels = Vec::new();
    let spec_scen = build(rules, case, &tcx, &mut texels, spec_geo, lod.spec_pick);
    let sets = levels::profile_intervals(rules, &tcx, &geos, &lod, &mut texels, &mut choices);
    let spec_value = if lod.lam.spec.is_nan() {
        None
    } else {
        accept::spec_value(&spec_scen, &texels)
    };
    let fp = footprint::footprint(e, rules, &tcx, &spec_scen, &texels);
    // Only a filtered colour value may come back at the format's precision; one texel is exactly
    // c/(2^b − 1) (eq. (2.1)).
    let colour_bits = if kind == Kind::Colour && spec_scen.filtered() {
        case.texture.format.unorm_bits()
    } else {
        None
    };
    let range = match kind {
        Kind::Compare => (tcx.pass_v.min(tcx.fail_v), tcx.pass_v.max(tcx.fail_v)),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    };
    let value_slack = matches!(kind, Kind::Depth | Kind::Colour);
    let acc = accept::finalize(sets, colour_bits, value_slack, range, spec_value);
    if !matches!((spec_value, acc.first()), (Some(v), Some(s)) if s.0 == [Interval::point(v)]) {
        choices.into_iter().for_each(|n| e.note(n));
    }
    Ok((spec_value, acc, fp))
}

/// The layout of r on each of the case's API paths, with a step each, and the other readings of
/// it the texts allow.
fn layouts(
    e: &mut Eval,
    rules: &Rules,
    case: &Case,
    kind: Kind,
    incomplete: bool,
    components: usize,
) -> Layouts {
    let mut layouts = Layouts::default();
    for &api in &case.api {
        let r = if components > 1 {
            layout::colour_readings(rules, api, components, case.sampler.swizzle)
        } else {
            layout::readings(
                rules,
                api,
                kind,
                case.sampler.depth_texture_mode,
                case.sampler.swizzle,
                incomplete,
            )
        };
        if let (Some(sw), Some(before), Some(sw_cite)) =
            (case.sampler.swizzle, r.unswizzled, rules.swizzle)
        {
            e.step(
                format!(
                    "TEXTURE_SWIZZLE_RGBA ({}) on `{api}`: ({}) → ({})",
                    sw.iter().map(|c| c.key()).collect::<Vec<_>>().join(","),
                    channels(&before),
                    channels(&r.main)
                ),
                sw_cite,
            );
        }
        e.step(
            format!("layout on `{api}`: ({})", channels(&r.main)),
            r.cite,
        );
        if r.main.contains(&Channel::ROrZero) {
            e.note(format!("on `{api}` the texts give two readings: the result is r or 0 (contradiction `compat-float-alpha`: {})", r.cite));
        }
        layouts.add(api, r.main, r.others, e);
    }
    layouts
}

/// A layout as its channel keys, e.g. `r,0,0,1`.
fn channels(l: &[Channel; 4]) -> String {
    l.iter().map(|c| c.key()).collect::<Vec<_>>().join(",")
}

/// The layouts of a case: the spec's reading per API path and the other readings.
#[derive(Default)]
struct Layouts {
    main: KeyMap<ApiPath, [Channel; 4]>,
    others: KeyMap<ApiPath, Vec<OtherLayout>>,
}

impl Layouts {
    /// Records `api`'s layout and its other readings, each as a step and a note naming it.
    fn add(
        &mut self,
        api: ApiPath,
        main: [Channel; 4],
        others: Vec<(&'static str, [Channel; 4])>,
        e: &mut Eval,
    ) {
        self.main.insert(api, main);
        if others.is_empty() {
            return;
        }
        let mut v = Vec::new();
        for (id, l) in others {
            let c = contradictions::get(id);
            let cite = c.map(|c| c.sources).unwrap_or("");
            e.step(
                format!(
                    "other reading on `{api}` (contradiction `{id}`): ({})",
                    channels(&l)
                ),
                cite,
            );
            e.note(format!(
                "on `{api}` the texts give two readings: ({}) or ({}) (contradiction `{id}`{})",
                channels(&main),
                channels(&l),
                c.map(|c| format!(": {}", c.title)).unwrap_or_default()
            ));
            v.push(OtherLayout {
                reading: id.to_string(),
                layout: l,
            });
        }
        self.others.insert(api, v);
    }
}

/// An incomplete texture: r = 0 under every profile.
fn incomplete_texture(
    mut e: Eval,
    rules: &Rules,
    why: &str,
    layouts: Layouts,
    kind: Kind,
) -> Evaluation {
    let cite = match rules.incomplete {
        Incomplete::Legacy0001 => {
            "GL 2.1 §3.11.2 / ARB_fragment_program_shadow / ES 2.0 §3.8.2: (0,0,0,1)"
        }
        Incomplete::ShadowZero => "GL 4.6 / ES 3.2 §11.1.3.5: 0 for a shadow sampler",
        // Refused before evaluation (`run`); the sentence stands as the citation.
        Incomplete::NotApplicable(why) => why,
    };
    e.step(format!("texture incomplete: {why}; r = 0"), cite);
    e.cite(if rules.es_depth_completeness {
        "ES 3.2 §8.17"
    } else {
        "GL 4.6 §8.17"
    });
    let uint_alpha = kind == Kind::Stencil && layouts.main.values().any(|l| l[3] == Channel::G3);
    if uint_alpha {
        e.note(format!(
            "the alpha of an incomplete texture read through an unsigned integer sampler is 1 or the bits of 1.0f, {ONE_F32_BITS} (contradiction `incomplete-uint-alpha`)"
        ));
    }
    let acc = Acceptance(vec![Interval::point(0.0)]);
    let mut ev = finish(
        e,
        Some(0.0),
        vec![acc.clone(); PROFILES.len()],
        layouts,
        Footprint::default(),
    );
    if uint_alpha {
        let set = |a: Acceptance| -> KeyMap<Profile, Acceptance> {
            PROFILES.iter().map(|p| (p.profile, a.clone())).collect()
        };
        let alpha = Acceptance(vec![Interval::point(1.0), Interval::point(ONE_F32_BITS)]);
        ev.expect.gather = Some([set(acc.clone()), set(acc.clone()), set(acc), set(alpha)]);
    }
    ev
}

/// 1.0f's bits as an unsigned integer, 0x3F800000.
const ONE_F32_BITS: f64 = 1065353216.0;

/// A lookup whose texel selection the spec leaves undefined: every value r can take (`iv`) is
/// accepted.
fn undefined(mut e: Eval, iv: Interval, layouts: Layouts, why: &str) -> Evaluation {
    e.note(why);
    let acc = Acceptance(vec![iv]);
    finish(
        e,
        None,
        vec![acc; PROFILES.len()],
        layouts,
        Footprint::default(),
    )
}

/// The evaluation; `acc` holds one acceptance set per profile, in `PROFILES` order.
fn finish(
    e: Eval,
    spec_value: Option<f64>,
    acc: Vec<Acceptance>,
    layout: Layouts,
    footprint: Footprint,
) -> Evaluation {
    let accept: KeyMap<Profile, Acceptance> = PROFILES.iter().map(|p| p.profile).zip(acc).collect();
    let implementation_defined = if e.notes.is_empty() {
        None
    } else {
        Some(e.notes.join("; "))
    };
    Evaluation {
        expect: Expectation {
            spec_value,
            accept,
            layout: layout.main,
            other_layouts: layout.others,
            gather: None,
            implementation_defined,
            citations: e.cites,
        },
        footprint,
        steps: e.steps,
    }
}
