//! The page's "Layer attribution" section: the failure classes of `crate::attribute` when the
//! inputs hold a layered backend (zink, WebGL on ANGLE) with failures and the driver under it
//! (a Vulkan driver, or the OpenGL ES driver under ANGLE's OpenGL ES back end).

use super::geometry::Geometry;
use super::load::ReportInput;
use super::page::esc;
use crate::attribute;
use std::fmt::Write as _;

/// The layer attribution (`crate::attribute`), when the inputs hold a layered backend with
/// failures and the Vulkan driver under it: the tally per backend, then the failure classes.
pub fn render(input: &ReportInput, geo: &Geometry, o: &mut String) {
    if geo.cases.is_empty() {
        return;
    }
    let mut all = crate::records::Results::default();
    for r in &input.results {
        all.insert(r.clone());
    }
    let rows: Vec<attribute::Attribution> = attribute::attribute(&all, &geo.cases)
        .into_iter()
        .filter(|r| input.backends.iter().any(|b| b == r.lower))
        .collect();
    if rows.is_empty() {
        return;
    }
    o.push_str("<h2 id=\"s-layers\">Layer attribution</h2>\n<p class=\"note\">Each Warn and Fail of a layered backend against the lower layer's answer: the Vulkan driver's to the same lookup, or the OpenGL ES driver's to the same test under ANGLE's OpenGL ES back end (<code>shadowcheck attribute</code>): upper (the layer; also where Vulkan has no such lookup and the layer emulates it), lower (the driver fails it the same way), both, or no equivalent.</p>\n<table><tr><th>backend</th><th>lower layer</th><th>upper</th><th>lower</th><th>both</th><th>no equivalent</th></tr>\n");
    let t = attribute::tally(&rows);
    let mut backends: Vec<&str> = rows.iter().map(|r| r.backend.as_str()).collect();
    backends.sort();
    backends.dedup();
    for b in backends {
        let n = |l| t.get(&(b.to_string(), l)).copied().unwrap_or(0);
        let lower = attribute::layering_of(b).map_or("?", |l| l.lower);
        let _ = writeln!(
            o,
            "<tr><td><code>{}</code></td><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(b),
            esc(lower),
            n(attribute::Layer::Upper),
            n(attribute::Layer::Lower),
            n(attribute::Layer::Both),
            n(attribute::Layer::NoEquivalent)
        );
    }
    o.push_str("</table>\n<p class=\"note\">Failure classes (the reason with its case ids and values left out), largest first per backend:</p>\n<table><tr><th>backend</th><th>layer</th><th>tests</th><th>why</th><th>example</th></tr>\n");
    for c in attribute::classes(&rows) {
        let _ = writeln!(
            o,
            "<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td><code>{}</code></td></tr>",
            esc(&c.backend),
            c.layer.as_str(),
            c.tests,
            esc(&c.why),
            esc(&c.example.test)
        );
    }
    o.push_str("</table>\n");
}
