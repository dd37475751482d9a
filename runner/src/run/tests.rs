//! Unit tests of the run core (sequential runs against scripted backends).

use super::*;
use crate::backend::{ApiAnswer, Capabilities};
use crate::events::{Event, Reporter};
use shadowcheck_model::KeyMap;
use shadowcheck_model::*;

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
    fn answer_batch(&mut self, cases: &[Sent<'_>]) -> Vec<CaseAnswer> {
        cases
            .iter()
            .map(|c| {
                self.sent.push((c.case.id.clone(), c.api.to_vec()));
                CaseAnswer::Observed(
                    c.api
                        .iter()
                        .map(|&a| {
                            (
                                a,
                                ApiAnswer::Rgba {
                                    rgba: [1.0, 1.0, 1.0, 1.0],
                                    stored: None,
                                    sweep: vec![],
                                },
                            )
                        })
                        .collect(),
                )
            })
            .collect()
    }
}

/// Counts CaseFinished events; keeps the test count of BackendStarted and the not-applicable
/// count of BackendFinished.
#[derive(Default)]
struct Seen {
    finished: usize,
    started_tests: usize,
    not_applicable: usize,
}
struct Count(std::rc::Rc<std::cell::RefCell<Seen>>);
impl Reporter for Count {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        let mut seen = self.0.borrow_mut();
        match ev {
            Event::CaseFinished { .. } => seen.finished += 1,
            Event::BackendStarted { tests, .. } => seen.started_tests = *tests,
            Event::BackendFinished { counts, .. } => seen.not_applicable = counts.not_applicable,
            _ => {}
        }
        Ok(())
    }
}

fn case(id: &str, spec: Spec, api: Vec<ApiPath>) -> Case {
    let mut accept = KeyMap::new();
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
        sweep: vec![],
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
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: Some(Expectation {
            spec_value: Some(1.0),
            accept,
            layout,
            other_layouts: Default::default(),
            gather: None,
            implementation_defined: None,
            citations: vec![],
        }),
    }
}

#[test]
fn capabilities_and_skips_narrow_what_is_sent_and_not_applicable_paths_are_no_tests() {
    let set = CaseSet {
        files: vec!["f.json".into()],
        states: vec![],
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
            Loaded {
                case: Case {
                    texture: Texture {
                        target: Target::T1d,
                        ..case("x", Spec::Gl46, vec![]).texture
                    },
                    ..case(
                        "gl46/c",
                        Spec::Gl46,
                        vec![ApiPath::GlslCore, ApiPath::FixedFunction],
                    )
                },
                file: 0,
            },
        ],
        errors: vec![],
    };
    let mut fake = Fake {
        caps: Capabilities {
            specs: Some(vec!["gl46".into()]),
            api: Some(vec!["core".into(), "glsl130".into()]),
            targets: Some(vec!["2d".into()]),
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
    let seen = std::rc::Rc::new(std::cell::RefCell::new(Seen::default()));
    let mut fanout = Fanout::default();
    fanout.reporters.push(Box::new(Count(seen.clone())));
    let (results, timing) =
        run_backend(&mut fake, &set, &Results::default(), &settings, &mut fanout);
    assert_eq!(fake.sent, [("gl46/a".to_string(), vec![ApiPath::GlslCore])]);
    assert_eq!(timing.cases_sent, 1);
    // 6 API paths: gl46/a@ff, gles32/b@es300 and gl46/c@ff are no tests of this backend (spec or
    // path not implemented): no record, outside the count. The other 3 are tests.
    let seen = seen.borrow();
    assert_eq!(seen.finished, 3);
    assert_eq!(seen.started_tests, 3);
    assert_eq!(seen.not_applicable, 3);
    assert_eq!(set.tests_on(&fake.caps), (3, 3));
    let by: HashMap<&str, (&Status, Option<&str>)> = results
        .iter()
        .map(|r| (r.test.as_str(), (&r.status, r.reason.as_deref())))
        .collect();
    assert_eq!(by.len(), 3, "{by:?}");
    assert_eq!(by["gl46/a@core"].0, &Status::Plain(Outcome::Pass));
    assert_eq!(
        by["gl46/a@glsl130"],
        (
            &Status::Plain(Outcome::Skip),
            Some("skips list: `@glsl130$`")
        )
    );
    // A target the backend lacks is a real Skip, with its reason.
    assert_eq!(
        by["gl46/c@core"],
        (
            &Status::Plain(Outcome::Skip),
            Some("target `1d` not supported by this backend")
        )
    );
}

#[test]
fn resumed_tests_are_replayed_not_rerun() {
    let set = CaseSet {
        files: vec!["f.json".into()],
        states: vec![],
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
