//! Unit tests of the run core (sequential runs against scripted backends).

use super::*;
use crate::backend::{ApiOutcome, Capabilities};
use crate::events::{Event, Reporter};
use shadowcheck_model::*;
use std::collections::BTreeMap;

/// Answers r = 1 on every path it is sent, and records what it was sent.
struct Fake {
    caps: Capabilities,
    sent: Vec<(String, Vec<ApiPath>)>,
}

impl Backend for Fake {
    fn name(&self) -> &str {
        "fake"
    }
    fn capabilities(&self) -> &Capabilities {
        &self.caps
    }
    fn run_batch(&mut self, cases: &[&Case]) -> Vec<CaseOutcome> {
        cases
            .iter()
            .map(|c| {
                self.sent.push((c.id.clone(), c.api.clone()));
                CaseOutcome::Observed(
                    c.api
                        .iter()
                        .map(|&a| {
                            (
                                a,
                                ApiOutcome::Rgba {
                                    rgba: [1.0, 1.0, 1.0, 1.0],
                                    stored: None,
                                },
                            )
                        })
                        .collect(),
                )
            })
            .collect()
    }
}

/// Counts CaseFinished events.
struct Count(std::rc::Rc<std::cell::Cell<usize>>);
impl Reporter for Count {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        if let Event::CaseFinished { .. } = ev {
            self.0.set(self.0.get() + 1);
        }
        Ok(())
    }
}

fn case(id: &str, spec: Spec, api: Vec<ApiPath>) -> Case {
    let mut accept = BTreeMap::new();
    for &p in Profile::ALL {
        accept.insert(p, Acceptance(vec![Interval::point(1.0)]));
    }
    let layout = api
        .iter()
        .map(|&a| {
            (
                a,
                [
                    Channel::R,
                    Channel::Unused,
                    Channel::Unused,
                    Channel::Unused,
                ],
            )
        })
        .collect();
    Case {
        id: id.into(),
        spec,
        api,
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: 1,
                height: 1,
                layers: 1,
                depth: Texels::Unorm(vec![65535]),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::Always, Filter::Nearest),
        lookup: Lookup {
            coord: [0.5, 0.5, 0.0, 1.0],
            layer: 0.0,
            dref: 0.5,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
        },
        expect: Some(Expectation {
            spec_value: Some(1.0),
            accept,
            layout,
            implementation_defined: None,
            citations: vec![],
        }),
    }
}

#[test]
fn capabilities_and_skips_narrow_what_is_sent_and_every_path_gets_a_result() {
    let set = CaseSet {
        files: vec!["f.json".into()],
        cases: vec![
            Loaded {
                case: case(
                    "gl46/a",
                    Spec::Gl46,
                    vec![ApiPath::GlslCore, ApiPath::Glsl130, ApiPath::FixedFunction],
                ),
                file: 0,
            },
            Loaded {
                case: case("gles32/b", Spec::Gles32, vec![ApiPath::Es300]),
                file: 0,
            },
        ],
        errors: vec![],
    };
    let mut fake = Fake {
        caps: Capabilities {
            specs: Some(vec!["gl46".into()]),
            api: Some(vec!["core".into(), "glsl130".into()]),
            ..Capabilities::default()
        },
        sent: vec![],
    };
    let settings = Settings {
        lists: Lists {
            skips: crate::baseline::RegexList::parse("@glsl130$", "s").unwrap(),
            ..Lists::default()
        },
        ..Settings::default()
    };
    let n = std::rc::Rc::new(std::cell::Cell::new(0));
    let mut fanout = Fanout::default();
    fanout.reporters.push(Box::new(Count(n.clone())));
    let (results, timing) =
        run_backend(&mut fake, &set, &Results::default(), &settings, &mut fanout);
    assert_eq!(fake.sent, [("gl46/a".to_string(), vec![ApiPath::GlslCore])]);
    assert_eq!(timing.cases_sent, 1);
    assert_eq!(n.get(), 4);
    let by: HashMap<&str, (&Status, Option<&str>)> = results
        .iter()
        .map(|r| (r.test.as_str(), (&r.status, r.reason.as_deref())))
        .collect();
    assert_eq!(by["gl46/a@core"].0, &Status::Plain(Outcome::Pass));
    assert_eq!(
        by["gl46/a@glsl130"],
        (
            &Status::Plain(Outcome::Skip),
            Some("skips list: `@glsl130$`")
        )
    );
    assert_eq!(
        by["gl46/a@ff"],
        (
            &Status::Plain(Outcome::Skip),
            Some("API path not supported by this backend")
        )
    );
    assert_eq!(
        by["gles32/b@es300"],
        (
            &Status::Plain(Outcome::Skip),
            Some("spec `gles32` not supported by this backend")
        )
    );
}

#[test]
fn resumed_tests_are_replayed_not_rerun() {
    let set = CaseSet {
        files: vec!["f.json".into()],
        cases: vec![Loaded {
            case: case("gl46/a", Spec::Gl46, vec![ApiPath::GlslCore]),
            file: 0,
        }],
        errors: vec![],
    };
    let mut fake = Fake {
        caps: Capabilities::all(),
        sent: vec![],
    };
    let mut fanout = Fanout::default();
    let (first, _) = run_backend(
        &mut fake,
        &set,
        &Results::default(),
        &Settings::default(),
        &mut fanout,
    );
    let mut prior = Results::default();
    prior.insert(first[0].clone());
    let mut fake = Fake {
        caps: Capabilities::all(),
        sent: vec![],
    };
    let (again, _) = run_backend(&mut fake, &set, &prior, &Settings::default(), &mut fanout);
    assert!(fake.sent.is_empty());
    assert_eq!(again, first);
}
