//! The self-contained HTML report written by `shadowcheck report RESULTS... -o DIR`.
//!
//! One file, `DIR/index.html`, with everything inline (style, a few lines of script, SVG
//! pictures): it loads nothing, so it can be attached to a bug or committed. It shows:
//! - a summary per backend (final statuses, as the runner counts them);
//! - the cross-driver [`matrix`]: rows spec × compare func × filter × format, one column per
//!   backend, cells pass / warn / fail linking to the dumps of their cases (capped per cell);
//! - [`pictures`]: per compare func and backend, a Dt × Dref heatmap of single-texel lookups
//!   (observed against expected, mismatches outlined) and, for filtered / mipmapped lookups, a
//!   plot of each observed r against its acceptance intervals.
//!
//! Inputs are read by [`load`]; the heatmaps place every test with the oracle's footprint of its
//! fixture case ([`geometry`]).

pub mod geometry;
pub mod layers;
pub mod load;
pub mod matrix;
pub mod page;
pub mod pictures;

use crate::records::TestResult;
use geometry::Geometry;
use load::ReportInput;
use matrix::{CellShade, DetailCaps, Matrix};
use page::esc;
use pictures::{HeatPoint, PlotItem};
use shadowcheck_model::{Channel, Profile};
use std::collections::BTreeSet;
use std::fmt::Write as _;

/// The name of the page written into the output directory.
pub const INDEX: &str = "index.html";

/// What to show and how much.
#[derive(Debug, Clone)]
pub struct PageOptions {
    /// The page's title; `None`: made from what the inputs hold ([`default_title`]).
    pub title: Option<String>,
    pub details: DetailCaps,
    /// Tests drawn per acceptance plot (every warning / failure first, then an even sample).
    pub plot_points: usize,
}

impl Default for PageOptions {
    fn default() -> Self {
        PageOptions {
            title: None,
            details: DetailCaps {
                per_cell: 50,
                total: 600,
            },
            plot_points: 48,
        }
    }
}

/// The observed r: the first channel the API path's layout (`r,-,-,-`, `0,0,0,r`, ...) calls r.
/// The layout comes from the record's expected summary (Warn / Fail) or the fixture's expectation.
pub fn observed_r(r: &TestResult, geo: &Geometry) -> Option<f64> {
    let obs = r.observed.as_ref()?;
    let idx = match (
        &r.expected,
        geo.expectation(r).and_then(|e| e.layout.get(&r.api)),
    ) {
        (Some(e), _) => e
            .layout
            .split(',')
            .position(|c| matches!(c.trim(), "r" | "g0"))?,
        (None, Some(layout)) => layout
            .iter()
            .position(|c| matches!(c, Channel::R | Channel::G0))?,
        (None, None) => 0,
    };
    obs.0.get(idx).copied()
}

/// `s` cut to `n` characters (with an ellipsis) for picture titles.
fn short(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars()
            .take(n.saturating_sub(1))
            .chain(std::iter::once('…'))
            .collect()
    }
}

/// Lookups whose result is a filtered or mipmapped value (anything but NEAREST / NEAREST).
pub fn is_filtered(r: &TestResult) -> bool {
    r.tags.filter != "nearest/nearest"
}

/// `n` items of `v`, evenly spaced (all of them when there are no more than `n`).
fn even<T: Clone>(v: &[T], n: usize) -> Vec<T> {
    if v.len() <= n {
        return v.to_vec();
    }
    (0..n).map(|k| v[k * v.len() / n].clone()).collect()
}

/// Picks at most `cap` items: warnings and failures first (up to three quarters of the cap when
/// there are passes to show beside them, evenly spaced), then passes evenly spaced; the result is
/// ordered by expected value, then name, so the plot reads as a staircase.
fn select_plot(mut items: Vec<PlotItem>, cap: usize) -> (Vec<PlotItem>, usize) {
    let total = items.len();
    if total > cap {
        let (bad, good): (Vec<PlotItem>, Vec<PlotItem>) =
            items.into_iter().partition(|i| i.shade >= CellShade::Warn);
        let n_bad = bad
            .len()
            .min((cap * 3 / 4).max(cap.saturating_sub(good.len())));
        items = even(&bad, n_bad);
        items.extend(even(&good, cap - n_bad));
    }
    let key = |i: &PlotItem| {
        i.spec_value
            .or_else(|| i.quality.first().map(|&(a, b)| (a + b) / 2.0))
            .unwrap_or(f64::NAN)
    };
    items.sort_by(|a, b| key(a).total_cmp(&key(b)).then_with(|| a.test.cmp(&b.test)));
    (items, total)
}

fn plot_item(r: &TestResult, geo: &Geometry) -> Option<PlotItem> {
    let (strict, quality, spec_value) = match (&r.expected, geo.expectation(r)) {
        (Some(e), _) => (
            pictures::parse_acceptance(&e.strict)?,
            pictures::parse_acceptance(&e.quality)?,
            e.spec_value,
        ),
        (None, Some(e)) => {
            let get = |p| {
                e.accept
                    .get(&p)
                    .map(|a| a.0.iter().map(|i| (i.lo, i.hi)).collect::<Vec<_>>())
            };
            (get(Profile::Strict)?, get(Profile::Quality)?, e.spec_value)
        }
        (None, None) => return None,
    };
    Some(PlotItem {
        test: r.test.clone(),
        shade: CellShade::of(r.outcome),
        observed: observed_r(r, geo),
        strict,
        quality,
        spec_value,
    })
}

/// The pictures section: per compare func, the heatmaps of every backend, then their plots.
fn render_pictures(input: &ReportInput, geo: &Geometry, opts: &PageOptions, out: &mut String) {
    let funcs: BTreeSet<&str> = input.results.iter().map(|r| r.tags.func.as_str()).collect();
    let mut drew = 0;
    for func in funcs {
        let mut maps = String::new();
        let mut plots = String::new();
        for b in &input.backends {
            let mine: Vec<&TestResult> = input
                .results
                .iter()
                .filter(|r| {
                    r.backend == *b
                        && r.tags.func == func
                        && r.outcome != crate::records::Outcome::Skip
                })
                .collect();
            let points: Vec<HeatPoint> = mine
                .iter()
                .filter_map(|r| {
                    let (dt, dref) = geo.point(r)?;
                    Some(HeatPoint {
                        dt,
                        dref,
                        shade: CellShade::of(r.outcome),
                        observed: observed_r(r, geo),
                        test: r.test.clone(),
                    })
                })
                .collect();
            if !points.is_empty() {
                let bad = points.iter().filter(|p| p.shade >= CellShade::Warn).count();
                maps.push_str(&pictures::heatmap(
                    &format!("{} — {} tests, {bad} off", short(b, 24), points.len()),
                    &points,
                ));
            }
            let items: Vec<PlotItem> = mine
                .iter()
                .filter(|r| is_filtered(r))
                .filter_map(|r| plot_item(r, geo))
                .collect();
            if !items.is_empty() {
                let (sel, total) = select_plot(items, opts.plot_points);
                let bad = sel.iter().filter(|i| i.shade >= CellShade::Warn).count();
                let caption = if sel.len() < total {
                    format!("{} of {total} filtered/mipmap tests: {bad} warn/fail and passes, evenly sampled; by expected value", sel.len())
                } else {
                    format!(
                        "all {total} filtered/mipmap tests ({bad} warn/fail), by expected value"
                    )
                };
                plots.push_str(&pictures::plot(
                    &format!("{} — filtered / mipmap", short(b, 60)),
                    &sel,
                    &caption,
                ));
            }
        }
        if maps.is_empty() && plots.is_empty() {
            continue;
        }
        drew += 1;
        let _ = writeln!(out, "<h3 id=\"func-{0}\">func {0}</h3>", esc(func));
        if !maps.is_empty() {
            let _ = writeln!(out, "<div class=\"pics\">{maps}</div>");
        }
        if !plots.is_empty() {
            let _ = writeln!(out, "<div class=\"pics\">{plots}</div>");
        }
    }
    if drew == 0 {
        out.push_str("<p>No test with an observation to draw.</p>\n");
    }
}

/// A title from what the page holds: the backends grouped by kind (`egl: llvmpipe, zink`), with
/// the Mesa versions the implementations name.
pub fn default_title(input: &ReportInput) -> String {
    let mut kinds: Vec<(String, Vec<String>)> = vec![];
    for b in &input.backends {
        let mut parts = b.splitn(3, ':');
        let kind = parts.next().unwrap_or_default().to_string();
        let what = parts.next().map(str::to_string);
        match kinds.iter_mut().find(|(k, _)| *k == kind) {
            Some((_, w)) => {
                if let Some(x) = what.filter(|x| !w.contains(x)) {
                    w.push(x);
                }
            }
            None => kinds.push((kind, what.into_iter().collect())),
        }
    }
    let groups: Vec<String> = kinds
        .iter()
        .map(|(k, w)| {
            if w.is_empty() {
                k.clone()
            } else {
                format!("{k}: {}", w.join(", "))
            }
        })
        .collect();
    let mut versions: Vec<&str> = input
        .implementations
        .values()
        .filter_map(|i| {
            let at = i.find("Mesa ")?;
            let rest = &i[at..];
            let end = rest[5..]
                .find(|c: char| !(c.is_ascii_digit() || c == '.'))
                .map_or(rest.len(), |e| e + 5);
            Some(rest[..end].trim_end_matches('.'))
        })
        .filter(|v| v.len() > 5)
        .collect();
    versions.sort();
    versions.dedup();
    let versions = if versions.is_empty() {
        String::new()
    } else {
        format!(" ({})", versions.join(", "))
    };
    format!(
        "shadowcheck: {} backend{}{versions}: {}",
        input.backends.len(),
        if input.backends.len() == 1 { "" } else { "s" },
        groups.join("; ")
    )
}

/// The whole page.
pub fn render(input: &ReportInput, geo: &Geometry, opts: &PageOptions) -> String {
    let mut o = String::with_capacity(1 << 20);
    let title = opts.title.clone().unwrap_or_else(|| default_title(input));
    let _ = write!(
        o,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title>\
         <meta name=\"viewport\" content=\"width=device-width\"><style>{}</style></head><body>\n",
        esc(&title),
        page::STYLE
    );
    let _ = writeln!(o, "<h1>{}</h1>", esc(&title));
    // The inputs are counted, not named: their paths are the machine's that made the page.
    let implementations: Vec<String> = input
        .backends
        .iter()
        .filter_map(|b| {
            let i = input.implementations.get(b)?;
            Some(format!("<li><code>{}</code>: {}</li>", esc(b), esc(i)))
        })
        .collect();
    let _ = writeln!(
        o,
        "<div class=\"note\">shadowcheck {} · {} tests on {} backends · from {} input(s){}</div>",
        env!("CARGO_PKG_VERSION"),
        input.results.len(),
        input.backends.len(),
        input.sources.len(),
        if implementations.is_empty() {
            String::new()
        } else {
            format!(
                " · <details style=\"display:inline\"><summary>implementations</summary><ul>{}</ul></details>",
                implementations.join("")
            )
        }
    );
    for why in &input.unfinished {
        let _ = writeln!(
            o,
            "<p class=\"note\"><b>Partial run</b>: {}. The page shows the tests it holds.</p>",
            esc(why)
        );
    }
    o.push_str("<nav><a href=\"#s-summary\">Summary</a><a href=\"#s-matrix\">Matrix</a><a href=\"#s-layers\">Layers</a><a href=\"#s-pictures\">Pictures</a><a href=\"#s-details\">Details</a></nav>\n");

    o.push_str("<h2 id=\"s-summary\">Summary per backend</h2>\n");
    page::summary(&input.backends, &input.results, &mut o);
    if input.replaced > 0 {
        let _ = writeln!(o, "<p class=\"note\">{} results appeared in several inputs with different records; the last input's record is shown.</p>", input.replaced);
    }
    if !input.load_errors.is_empty() {
        let _ = writeln!(o, "<h3>Load errors ({})</h3><ul>", input.load_errors.len());
        for e in input.load_errors.iter().take(50) {
            let _ = writeln!(
                o,
                "<li>{}{}: {}</li>",
                esc(&e.file),
                e.case
                    .as_deref()
                    .map(|c| format!(" [{}]", esc(c)))
                    .unwrap_or_default(),
                esc(&e.message)
            );
        }
        o.push_str("</ul>\n");
    }

    let m = Matrix::build(&input.backends, &input.results);
    o.push_str("<h2 id=\"s-matrix\">Cross-driver matrix</h2>\n");
    matrix::render(&m, &mut o);

    layers::render(input, geo, &mut o);

    o.push_str("<h2 id=\"s-pictures\">Pictures</h2>\n");
    o.push_str(
        "<p class=\"note legend\">Heatmaps: single-texel lookups by stored texel Dt (x) and reference Dref (y), 0.05 bins; \
         matching bins shaded by observed r<span style=\"background:#e8f0fe\"></span>0<span style=\"background:#183c8c\"></span>1 \
         <span style=\"background:#f0a020\"></span>warn (quality only)<span style=\"background:#d62728\"></span>mismatch (outlined); \
         dashed line: Dref = Dt. Plots: filtered / mipmapped lookups, quality interval<span style=\"background:#c9d3e3\"></span>\
         strict interval<span style=\"background:#6b7fa8\"></span>observed r as a diamond coloured by the test's outcome (▲▼ off the axis; a test can fail on another channel than r, see its dump). Hover for values.</p>\n",
    );
    if geo.fixtures.is_empty() {
        o.push_str("<p class=\"note\">No fixture files were found (give --fixtures): the heatmaps place only the tests whose records carry a footprint (warnings and failures).</p>\n");
    } else if geo.missing > 0 {
        let _ = writeln!(o, "<p class=\"note\">{} cases of the results are not in the fixtures {}; they are placed only when their record carries a footprint.</p>", geo.missing, esc(&geo.fixtures.join(", ")));
    }
    render_pictures(input, geo, opts, &mut o);

    o.push_str("<h2 id=\"s-details\">Details</h2>\n");
    let _ = writeln!(
        o,
        "<p class=\"note\">The warnings and failures of each cell, at most {} per cell and {} in all: expected value and acceptance per profile, observed RGBA, footprint, and the command that re-runs the case. Every record is in the runs' results.jsonl.</p>",
        matrix::per_cell_share(&m, opts.details),
        opts.details.total
    );
    matrix::render_details(&m, &input.results, opts.details, &mut o);
    let _ = write!(o, "<script>{}</script>\n</body></html>\n", page::SCRIPT);
    o
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::records::{ExpectedSummary, Outcome, Status, Tags};
    use shadowcheck_model::ApiPath;
    use shadowcheck_protocol::Rgba;

    #[test]
    fn the_default_title_says_what_the_page_holds_and_no_input_path_is_shown() {
        let mut input = ReportInput {
            backends: vec![
                "soft".into(),
                "egl:llvmpipe:core".into(),
                "egl:zink:es3".into(),
                "osmesa:llvmpipe:compat".into(),
                "webgl:chromium".into(),
            ],
            sources: vec!["/tmp/machine-only/run/results.jsonl".into()],
            ..ReportInput::default()
        };
        input.implementations.insert(
            "egl:llvmpipe:core".into(),
            "egl:llvmpipe:core (4.5 (Core Profile) Mesa 22.3.6; llvmpipe)".into(),
        );
        input.implementations.insert(
            "webgl:chromium".into(),
            "webgl:chromium (WebGL 2.0 (OpenGL ES 3.0 Chromium))".into(),
        );
        assert_eq!(
            default_title(&input),
            "shadowcheck: 5 backends (Mesa 22.3.6): soft; egl: llvmpipe, zink; osmesa: llvmpipe; webgl: chromium"
        );
        let page = render(&input, &Geometry::default(), &PageOptions::default());
        assert!(page.contains("<title>shadowcheck: 5 backends (Mesa 22.3.6)"));
        assert!(
            !page.contains("/tmp/machine-only"),
            "an input path on the page"
        );
        assert!(
            page.contains("from 1 input(s)") && page.contains("WebGL 2.0 (OpenGL ES 3.0 Chromium)")
        );
        let named = PageOptions {
            title: Some("given".into()),
            ..PageOptions::default()
        };
        assert!(render(&input, &Geometry::default(), &named).contains("<h1>given</h1>"));
    }

    fn result(backend: &str, id: &str, outcome: Outcome, r: f64) -> TestResult {
        TestResult {
            backend: backend.into(),
            test: format!("{id}@core"),
            case_id: id.into(),
            api: ApiPath::GlslCore,
            status: Status::Plain(outcome),
            outcome,
            reason: None,
            duration: 0.0,
            tags: Tags {
                spec: "gl46".into(),
                target: "2d".into(),
                format: "d16".into(),
                func: "lequal".into(),
                filter: "linear/linear".into(),
            },
            observed: Some(Rgba([r, 0.0, 0.0, 1.0])),
            expected: Some(ExpectedSummary {
                spec_value: Some(0.5),
                strict: "{0.5}".into(),
                quality: "[0.25, 0.75]".into(),
                layout: "r,-,-,-".into(),
                profile: Profile::Strict,
                citations: vec![],
            }),
            footprint: None,
            rerun: None,
            fixtures: None,
        }
    }

    #[test]
    fn page_has_matrix_cells_linking_to_capped_details() {
        let mut results: Vec<TestResult> = (0..5)
            .map(|i| result("mock:a", &format!("c{i}"), Outcome::Fail, -1.0))
            .collect();
        results.push(result("soft", "c0", Outcome::Pass, 0.5));
        let input = ReportInput {
            backends: vec!["soft".into(), "mock:a".into()],
            results,
            ..ReportInput::default()
        };
        let opts = PageOptions {
            details: DetailCaps {
                per_cell: 2,
                total: 100,
            },
            ..PageOptions::default()
        };
        let html = render(&input, &Geometry::default(), &opts);
        assert!(html.contains("<table id=\"matrix\""));
        assert!(
            html.contains("<a href=\"#d0-1\">5 fail</a>"),
            "the failing cell links to its details"
        );
        assert!(html.contains("id=\"d0-1\""));
        assert_eq!(
            html.matches("<pre class=\"dump").count(),
            2,
            "capped at 2 per cell"
        );
        assert!(html.contains("showing 2 of 5 tests"));
        assert!(
            html.contains("shadowcheck run --backend mock:a"),
            "re-run command in the dump"
        );
        assert!(html.contains("<svg"), "the acceptance plots are drawn");
        assert!(
            !html.contains("http://")
                || html.matches("http://").count()
                    == html.matches("xmlns=\"http://www.w3.org/2000/svg\"").count(),
            "no external reference except the SVG namespace"
        );
    }

    #[test]
    fn plot_selection_favours_failures_and_keeps_passes_beside_them() {
        let mut items: Vec<PlotItem> = (0..100)
            .map(|i| {
                plot_item(
                    &result("b", &format!("p{i:03}"), Outcome::Pass, 0.5),
                    &Geometry::default(),
                )
                .unwrap()
            })
            .collect();
        items.extend((0..3).map(|i| {
            plot_item(
                &result("b", &format!("f{i}"), Outcome::Fail, 0.0),
                &Geometry::default(),
            )
            .unwrap()
        }));
        let (sel, total) = select_plot(items, 10);
        assert_eq!((sel.len(), total), (10, 103));
        assert_eq!(sel.iter().filter(|i| i.shade == CellShade::Fail).count(), 3);
        // Many failures: three quarters of the plot for them, the rest for passes beside them.
        let many: Vec<PlotItem> = (0..40)
            .map(|i| {
                let o = if i % 2 == 0 {
                    Outcome::Fail
                } else {
                    Outcome::Pass
                };
                plot_item(
                    &result("b", &format!("t{i:02}"), o, 0.0),
                    &Geometry::default(),
                )
                .unwrap()
            })
            .collect();
        let (sel, _) = select_plot(many, 8);
        assert_eq!(sel.iter().filter(|i| i.shade == CellShade::Fail).count(), 6);
        assert_eq!(sel.iter().filter(|i| i.shade == CellShade::Pass).count(), 2);
    }

    #[test]
    fn observed_r_follows_the_layout() {
        let mut r = result("b", "c", Outcome::Pass, 0.5);
        r.observed = Some(Rgba([0.0, 0.0, 0.0, 0.75]));
        r.expected.as_mut().unwrap().layout = "0,0,0,r".into();
        assert_eq!(observed_r(&r, &Geometry::default()), Some(0.75));
    }
}
