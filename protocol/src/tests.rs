use super::*;
use std::collections::BTreeSet;

#[test]
fn requests_parse_flat_and_ignore_unknown_fields() {
    assert!(matches!(
        Request::parse(r#"{"type":"hello","protocol":1,"extra":true}"#),
        Ok(Request::Hello { protocol: 1 })
    ));
    assert!(matches!(
        Request::parse(r#"{"type":"flush"}"#),
        Ok(Request::Flush)
    ));
    assert!(matches!(
        Request::parse(r#"{"type":"bye"}"#),
        Ok(Request::Bye)
    ));
    let case = r#"{"type":"case","case":{"id":"x","spec":"gl46","api":["core"],"texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]},"lookup":{"coord":[0.5,0.5,0,1],"dref":"nan"}}}"#;
    match Request::parse(case) {
        Ok(Request::Case { case }) => assert!(case.lookup.dref.is_nan() && case.id == "x"),
        other => panic!("{other:?}"),
    }
    assert!(Request::parse(r#"{"type":"case"}"#)
        .unwrap_err()
        .contains("without"));
    assert!(Request::parse(r#"{"type":"frobnicate"}"#)
        .unwrap_err()
        .contains("frobnicate"));
}

#[test]
fn written_cases_read_back_and_leave_out_expect_unless_asked() {
    let line = r#"{"type":"case","case":{"id":"x","spec":"gl46","api":["core"],"texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]},"lookup":{"coord":[0.5,0.5,0,1],"dref":0.5}}}"#;
    let Ok(Request::Case { case }) = Request::parse(line) else {
        panic!("case line did not parse")
    };
    let mut buf = Vec::new();
    Request::write_case(&mut buf, &case, false);
    let again = String::from_utf8(buf).unwrap();
    assert!(!again.contains("expect"));
    let Ok(Request::Case { case: back }) = Request::parse(&again) else {
        panic!("{again}")
    };
    assert_eq!(back, case);
    assert!(Request::parse(&Request::hello_line()).is_ok());
}

#[test]
fn answers_parse_with_non_finite_channels_and_unknown_fields() {
    let a = Reply::parse_answer(r#"{"type":"observation","case_id":"x","extra":1,"results":[{"api":"core","rgba":["nan",0,"inf",1]}]}"#).unwrap();
    match a {
        Reply::Observation {
            case_id, results, ..
        } => {
            assert_eq!(case_id, "x");
            assert!(results[0].rgba.0[0].is_nan());
            assert_eq!(results[0].rgba.0[2], f64::INFINITY);
        }
        other => panic!("{other:?}"),
    }
    assert!(Reply::parse_answer(r#"{"type":"bogus","case_id":"x"}"#).is_err());
    assert!(Reply::parse_answer(r#"{"type":"hello","protocol":1}"#).is_err());
    let h =
        Reply::parse_hello(r#"{"type":"hello","protocol":1,"capabilities":{"specs":["gl46"]}}"#)
            .unwrap();
    assert_eq!(h.capabilities.specs, Some(vec!["gl46".to_string()]));
    assert!(h.capabilities.formats.is_none());
    // A version-1 implementation keeps every version-1 feature but is sent no state case.
    let features = h.capabilities.features.unwrap_or_default();
    assert!(features.iter().any(|f| f == "lod_bias"));
    assert!(!features.iter().any(|f| f == TEX_PARAMETER));
    let h2 = Reply::parse_hello(r#"{"type":"hello","protocol":2}"#).unwrap();
    assert!(h2.capabilities.features.is_none());
    assert!(Reply::parse_hello(r#"{"type":"hello","protocol":3}"#).is_err());
    assert!(Reply::parse_hello(r#"{"type":"helo","protocol":1}"#)
        .unwrap_err()
        .contains("expected a hello"));
}

#[test]
fn replies_serialize_as_the_protocol_writes_them() {
    let hello = Reply::Hello(Hello {
        sweeps: false,
        protocol: PROTOCOL_VERSION,
        name: Some("w".into()),
        capabilities: Capabilities {
            specs: Some(vec!["gl46".into()]),
            api: Some(vec!["core".into()]),
            targets: Some(vec!["2d".into()]),
            formats: Some(vec!["d16".into()]),
            features: None,
            extensions: vec![],
        },
        wants_expect: false,
    });
    assert_eq!(
        serde_json::to_string(&hello).unwrap(),
        r#"{"type":"hello","protocol":2,"name":"w","capabilities":{"specs":["gl46"],"api":["core"],"targets":["2d"],"formats":["d16"],"extensions":[]}}"#
    );
    let obs = Reply::Observation {
        case_id: "x".into(),
        results: vec![PathResult {
            sweep: vec![],
            api: "core".into(),
            rgba: Rgba([f64::NAN, 0.0, 1.0, 1.0]),
            stored: None,
            note: Some("texture".into()),
        }],
        skipped: vec![],
    };
    assert_eq!(
        serde_json::to_string(&obs).unwrap(),
        r#"{"type":"observation","case_id":"x","results":[{"api":"core","rgba":["nan",0.0,1.0,1.0],"note":"texture"}]}"#
    );
}

/// The placeholders PROTOCOL.md writes as `{...}` in its case example, filled with a real
/// texture, sampler and lookup.
const FILL: [(&str, &str); 3] = [
    (
        r#""texture":{...}"#,
        r#""texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]}"#,
    ),
    (
        r#""sampler":{...}"#,
        r#""sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]}"#,
    ),
    (
        r#""lookup":{...}"#,
        r#""lookup":{"coord":[0.5,0.5,0,1],"dref":0.5}"#,
    ),
];

/// Every message in runner/PROTOCOL.md: the JSON code blocks (one object per block or per line)
/// and the inline `{"type":...}` spans of the prose.
fn documented_messages() -> Vec<String> {
    let doc = include_str!("../../runner/PROTOCOL.md");
    let mut out = Vec::new();
    let mut block: Option<String> = None;
    for line in doc.lines() {
        match (&mut block, line.trim_start()) {
            (None, l) if l.starts_with("```json") => block = Some(String::new()),
            (Some(b), l) if l.starts_with("```") => {
                if serde_json::from_str::<serde_json::Value>(b).is_ok() {
                    out.push(b.clone());
                } else {
                    out.extend(
                        b.lines()
                            .filter(|l| !l.trim().is_empty())
                            .map(str::to_string),
                    );
                }
                block = None;
            }
            (Some(b), l) => {
                b.push_str(l);
                b.push('\n');
            }
            (None, _) => {
                for span in line.split('`').skip(1).step_by(2) {
                    if span.starts_with(r#"{"type":"#) {
                        out.push(span.to_string());
                    }
                }
            }
        }
    }
    out.into_iter()
        .map(|m| FILL.iter().fold(m, |m, (from, to)| m.replace(from, to)))
        .collect()
}

#[test]
fn every_example_in_protocol_md_parses() {
    let msgs = documented_messages();
    let mut requests = BTreeSet::new();
    let mut replies = BTreeSet::new();
    for m in &msgs {
        let req = Request::parse(m);
        if let Ok(r) = &req {
            requests.insert(match r {
                Request::Hello { protocol } => {
                    assert_eq!(*protocol, PROTOCOL_VERSION);
                    "hello"
                }
                Request::Case { .. } => "case",
                Request::State { .. } => "state",
                Request::Flush => "flush",
                Request::Bye => "bye",
            });
        }
        let reply = Reply::parse_hello(m)
            .map(Reply::Hello)
            .or_else(|_| Reply::parse_answer(m));
        if let Ok(r) = &reply {
            replies.insert(match r {
                Reply::Hello(_) => "hello",
                Reply::Observation { .. } => "observation",
                Reply::StateObservation { .. } => "state_observation",
                Reply::Skip { .. } => "skip",
                Reply::Error { .. } => "error",
            });
        }
        assert!(
            req.is_ok() || reply.is_ok(),
            "PROTOCOL.md example parses as neither a request nor a reply: {m}\n{req:?}\n{reply:?}"
        );
    }
    assert_eq!(
        requests.into_iter().collect::<Vec<_>>(),
        ["bye", "case", "flush", "hello", "state"],
        "request kinds documented in PROTOCOL.md"
    );
    assert_eq!(
        replies.into_iter().collect::<Vec<_>>(),
        ["error", "hello", "observation", "skip", "state_observation"],
        "reply kinds documented in PROTOCOL.md"
    );
}

#[test]
fn state_requests_and_answers_round_trip() {
    use shadowcheck_model::*;
    let case = StateCase {
        id: "state/gl46/core/2d/compare_mode/set=0x1234".into(),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        target: Target::T2d,
        pname: StatePname::CompareMode,
        call: StateCall::SetInt(0x1234),
        read_back: true,
        expect: Some(StateExpect {
            error: Some(GlErrorCode::InvalidEnum),
            value: Some(StateValue::Enum(0)),
            citations: vec![],
            with_extension: vec![],
        }),
    };
    let mut buf = Vec::new();
    Request::write_state(&mut buf, &case, false);
    let line = String::from_utf8(buf).unwrap();
    assert!(
        line.starts_with(r#"{"type":"state","state":{"id":"#),
        "{line}"
    );
    assert!(!line.contains("expect"), "{line}");
    match Request::parse(&line).unwrap() {
        Request::State { case: got } => assert_eq!(got.call, case.call),
        other => panic!("{other:?}"),
    }
    let answer = r#"{"type":"state_observation","case_id":"s","results":[{"api":"core","error":"invalid_enum","value":{"enum":0}}]}"#;
    match Reply::parse_answer(answer).unwrap() {
        Reply::StateObservation {
            case_id, results, ..
        } => {
            assert_eq!(case_id, "s");
            assert_eq!(results[0].observed.error, Some(GlErrorCode::InvalidEnum));
            assert_eq!(results[0].observed.value, Some(StateValue::Enum(0)));
        }
        other => panic!("{other:?}"),
    }
    // The tex_parameter feature decides: Skip with the reason when it is not listed.
    let caps = Capabilities {
        features: Some(vec![]),
        ..Capabilities::all()
    };
    match caps.support_state(&case) {
        Support::Skip(why) => assert!(why.contains(TEX_PARAMETER), "{why}"),
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        Capabilities::all().support_state(&case),
        Support::Run { .. }
    ));
}
