//! What a backend is sent: the cases of a set that are tests of it and not finished already (a
//! resumed run, the skips list, a target or format it lacks), and in which order.

use super::judge::ToSend;
use super::{applicable_apis, base_result, CaseSet, Ctx};
use crate::records::{Results, TestResult};
use shadowcheck_protocol::Capabilities;
use std::borrow::Cow;

/// `to_send` in the plan's program order (`shadowcheck_plan::units::program_order`): a backend
/// that compiles a shader variant per sampler state gets the cases of one program in the same
/// batches, so that it binds many of their states together and compiles one variant for them.
/// Results still come out per case; only the order they are sent (and reported) in changes.
pub(super) fn in_program_order(to_send: Vec<ToSend<'_>>) -> Vec<ToSend<'_>> {
    let order =
        shadowcheck_plan::units::program_order(to_send.iter().map(|(c, apis, _)| (*c, &**apis)));
    let mut slots: Vec<Option<ToSend<'_>>> = to_send.into_iter().map(Some).collect();
    order.into_iter().filter_map(|i| slots[i].take()).collect()
}

/// The lookup cases of `set` the backend `name` (with `caps`) is sent, each with the API paths it
/// runs. The rest are finished here: tests already in `prior` are replayed, tests on the skips
/// list and cases the backend implements but cannot run are Skip with the reason; a case of a spec
/// or API path it does not implement is no test of it.
pub(super) fn cases_to_send<'a>(
    caps: &Capabilities,
    name: &str,
    set: &'a CaseSet,
    prior: &Results,
    ctx: &mut Ctx<'_>,
) -> Vec<ToSend<'a>> {
    let settings = ctx.settings;
    let lists = &settings.lists;
    let mut to_send: Vec<ToSend<'a>> = Vec::new();
    for l in &set.cases {
        let case = &l.case;
        let fixtures = settings
            .explicit_fixtures
            .then(|| set.files[l.file].as_str());
        // Only the API paths this backend implements are tests of it.
        let Some((applicable, skip_reason)) = applicable_apis(caps, case) else {
            continue;
        };
        // Resumed: every test of the case already on disk.
        let done: Vec<&TestResult> = applicable
            .iter()
            .filter_map(|&a| prior.get(name, &TestResult::name(&case.id, a)))
            .collect();
        if done.len() == applicable.len() {
            for r in done {
                ctx.finish(r.clone(), true);
            }
            continue;
        }
        let mut apis = Vec::with_capacity(applicable.len());
        for &api in &applicable {
            let test = TestResult::name(&case.id, api);
            match lists.skips.matching_for(name, &test) {
                Some(re) => {
                    let mut r = base_result(name, case, api, fixtures);
                    r.reason = Some(format!("skips list: `{re}`"));
                    ctx.finish(r, false);
                }
                None => apis.push(api),
            }
        }
        if let Some(reason) = skip_reason {
            for &api in &apis {
                let mut r = base_result(name, case, api, fixtures);
                r.reason = Some(reason.clone());
                ctx.finish(r, false);
            }
            continue;
        }
        if apis.is_empty() {
            continue;
        }
        if apis.len() == case.api.len() {
            to_send.push((case, Cow::Borrowed(case.api.as_slice()), fixtures));
        } else {
            to_send.push((case, Cow::Owned(apis), fixtures));
        }
    }
    to_send
}
