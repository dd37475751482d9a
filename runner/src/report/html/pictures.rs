//! The report's pictures, as inline SVG made with the `svg` crate.
//!
//! - [`heatmap`]: for one compare func on one backend, x = Dt (the stored texel value after the
//!   spec's clamping), y = Dref, binned by 0.05 with one bin each side for values below 0 and
//!   above 1. A bin's colour is the observed r where every test matched (light = 0, dark = 1, so
//!   the compare function's step shows), orange where one only met the quality profile, red
//!   with a black outline where one was outside every acceptance set.
//! - [`plot`]: for filtered / mipmapped tests, each test's quality acceptance interval (light
//!   bar), strict interval (dark bar) and the observed r (diamond, coloured by outcome); values
//!   outside the axis are drawn at its edge as triangles.

use super::matrix::CellShade;
use std::fmt::Write as _;
use svg::node::element::{Group, Line, Path, Rectangle, Text, Title};
use svg::Document;

/// One test placed on a heatmap.
#[derive(Debug, Clone)]
pub struct HeatPoint {
    pub dt: f64,
    pub dref: f64,
    pub shade: CellShade,
    /// The observed r (None for a crash or timeout).
    pub observed: Option<f64>,
    pub test: String,
}

/// 0.05-wide bins centred on 0, 0.05, ..., 1, plus "< 0" and "> 1".
pub const BINS: usize = 23;

/// The bin of a value; NaN has none.
pub fn bin(v: f64) -> Option<usize> {
    if v.is_nan() {
        None
    } else if v < -0.025 {
        Some(0)
    } else if v > 1.025 {
        Some(BINS - 1)
    } else {
        Some(1 + ((v / 0.05).round().clamp(0.0, 20.0) as usize))
    }
}

fn label(b: usize) -> String {
    match b {
        0 => "<0".into(),
        b if b == BINS - 1 => ">1".into(),
        b => format!("{:.2}", (b - 1) as f64 * 0.05),
    }
}

#[derive(Default, Clone)]
struct Bin {
    n: usize,
    warn: usize,
    fail: usize,
    sum_r: f64,
    n_r: usize,
    example: Option<String>,
}

/// Observed r in [0, 1] → fill colour from pale to dark blue.
fn tone(r: f64) -> String {
    let t = r.clamp(0.0, 1.0);
    let lerp = |a: f64, b: f64| (a + (b - a) * t).round() as u8;
    format!(
        "#{:02x}{:02x}{:02x}",
        lerp(207.0, 24.0),
        lerp(220.0, 60.0),
        lerp(243.0, 140.0)
    )
}

pub const WARN_COLOUR: &str = "#f0a020";
pub const FAIL_COLOUR: &str = "#d62728";
/// Observed values that passed, on the plots.
pub const PASS_MARK: &str = "#17305c";

/// Coordinates to 0.1 px: the svg crate writes f64 in full, which would triple the page size.
fn q(v: f64) -> f64 {
    (v * 10.0).round() / 10.0
}

fn text(x: f64, y: f64, s: &str, anchor: &str) -> Text {
    Text::new(s)
        .set("x", q(x))
        .set("y", q(y))
        .set("text-anchor", anchor)
}

/// The heatmap of `points` (one func, one backend). `title` heads it.
pub fn heatmap(title: &str, points: &[HeatPoint]) -> String {
    const CELL: f64 = 11.0;
    const LEFT: f64 = 34.0;
    const TOP: f64 = 18.0;
    let size = CELL * BINS as f64;
    let mut bins = vec![Bin::default(); BINS * BINS];
    for p in points {
        let (Some(x), Some(y)) = (bin(p.dt), bin(p.dref)) else {
            continue;
        };
        let b = &mut bins[y * BINS + x];
        b.n += 1;
        match p.shade {
            CellShade::Warn => b.warn += 1,
            CellShade::Fail => b.fail += 1,
            _ => {}
        }
        if let Some(r) = p.observed.filter(|r| r.is_finite()) {
            b.sum_r += r;
            b.n_r += 1;
        }
        if b.example.is_none() || (p.shade >= CellShade::Warn && b.fail + b.warn == 1) {
            b.example = Some(p.test.clone());
        }
    }
    let (w, h) = (LEFT + size + 6.0, TOP + size + 30.0);
    let mut doc = Document::new()
        .set("viewBox", (0, 0, w, h))
        .set("width", w)
        .set("height", h)
        .set("class", "heatmap")
        .add(text(LEFT, 12.0, title, "start").set("class", "t"));
    // Frame, the tie diagonal Dref = Dt, and the 0 / 1 edges.
    doc = doc.add(
        Rectangle::new()
            .set("x", LEFT)
            .set("y", TOP)
            .set("width", size)
            .set("height", size)
            .set("class", "frame"),
    );
    let y_of = |b: usize| TOP + size - (b as f64 + 1.0) * CELL;
    let mut cells = Group::new();
    let mut marked = Group::new().set("class", "miss");
    for y in 0..BINS {
        for x in 0..BINS {
            let b = &bins[y * BINS + x];
            if b.n == 0 {
                continue;
            }
            let fill = if b.fail > 0 {
                FAIL_COLOUR.to_string()
            } else if b.warn > 0 {
                WARN_COLOUR.to_string()
            } else if b.n_r > 0 {
                tone(b.sum_r / b.n_r as f64)
            } else {
                "#999".into()
            };
            let tip = format!(
                "Dt {}, Dref {}: {} tests, {} fail, {} warn{}{}",
                label(x),
                label(y),
                b.n,
                b.fail,
                b.warn,
                if b.n_r > 0 {
                    format!(", mean observed r {:.3}", b.sum_r / b.n_r as f64)
                } else {
                    String::new()
                },
                b.example
                    .as_deref()
                    .map(|e| format!("\ne.g. {e}"))
                    .unwrap_or_default()
            );
            let rect = Rectangle::new()
                .set("x", q(LEFT + x as f64 * CELL))
                .set("y", q(y_of(y)))
                .set("width", CELL)
                .set("height", CELL)
                .set("fill", fill)
                .add(Title::new(tip));
            if b.fail + b.warn > 0 {
                marked = marked.add(rect);
            } else {
                cells = cells.add(rect);
            }
        }
    }
    doc = doc.add(cells).add(marked);
    let diag = Line::new()
        .set("x1", LEFT + CELL)
        .set("y1", y_of(1) + CELL)
        .set("x2", LEFT + size - CELL)
        .set("y2", y_of(BINS - 2))
        .set("class", "diag");
    doc = doc.add(diag);
    for b in [0, 1, 6, 11, 16, 21, BINS - 1] {
        // 0.50 -> 0.5, 1.00 -> 1, 0.00 -> 0; the edge bins keep "<0" and ">1".
        let l = match label(b).parse::<f64>() {
            Ok(v) => format!("{v}"),
            Err(_) => label(b),
        };
        let l = l.as_str();
        doc = doc
            .add(text(
                LEFT + (b as f64 + 0.5) * CELL,
                TOP + size + 11.0,
                l,
                "middle",
            ))
            .add(text(LEFT - 3.0, y_of(b) + CELL * 0.8, l, "end"));
    }
    doc = doc
        .add(
            text(
                LEFT + size / 2.0,
                TOP + size + 24.0,
                "Dt (stored texel)",
                "middle",
            )
            .set("class", "ax"),
        )
        .add(
            text(9.0, TOP + size / 2.0, "Dref", "middle")
                .set("class", "ax")
                .set("transform", format!("rotate(-90 9 {})", TOP + size / 2.0)),
        );
    doc.to_string()
}

/// One filtered / mipmapped test on an acceptance plot.
#[derive(Debug, Clone)]
pub struct PlotItem {
    pub test: String,
    pub shade: CellShade,
    pub observed: Option<f64>,
    /// Acceptance intervals of r, strict and quality (from the record's expected summary).
    pub strict: Vec<(f64, f64)>,
    pub quality: Vec<(f64, f64)>,
    pub spec_value: Option<f64>,
}

/// Parses an acceptance set as the runner writes it: `{v}` or `[lo, hi]`, joined by ` ∪ `;
/// `{}` is empty. Returns None for text it does not recognise.
pub fn parse_acceptance(s: &str) -> Option<Vec<(f64, f64)>> {
    let s = s.trim();
    if s == "{}" || s.is_empty() {
        return Some(vec![]);
    }
    s.split('∪')
        .map(|part| {
            let p = part.trim();
            if let Some(v) = p.strip_prefix('{').and_then(|p| p.strip_suffix('}')) {
                let v: f64 = v.trim().parse().ok()?;
                Some((v, v))
            } else {
                let inner = p.strip_prefix('[')?.strip_suffix(']')?;
                let (lo, hi) = inner.split_once(',')?;
                Some((lo.trim().parse().ok()?, hi.trim().parse().ok()?))
            }
        })
        .collect()
}

/// The acceptance plot of `items` (already selected and ordered). `title` heads it.
pub fn plot(title: &str, items: &[PlotItem], caption: &str) -> String {
    const LEFT: f64 = 34.0;
    const TOP: f64 = 18.0;
    const H: f64 = 160.0;
    const LO: f64 = -0.1;
    const HI: f64 = 1.1;
    let n = items.len().max(1) as f64;
    let step = (520.0 / n).clamp(4.0, 14.0);
    let width = step * n;
    let (w, h) = (q(LEFT + width + 8.0), TOP + H + 30.0);
    let y = |v: f64| TOP + H - (v.clamp(LO, HI) - LO) / (HI - LO) * H;
    let mut doc = Document::new()
        .set("viewBox", (0, 0, w, h))
        .set("width", w)
        .set("height", h)
        .set("class", "plot")
        .add(text(LEFT, 12.0, title, "start").set("class", "t"))
        .add(
            Rectangle::new()
                .set("x", LEFT)
                .set("y", TOP)
                .set("width", q(width))
                .set("height", H)
                .set("class", "frame"),
        );
    for v in [0.0, 0.25, 0.5, 0.75, 1.0] {
        doc = doc
            .add(
                Line::new()
                    .set("x1", LEFT)
                    .set("x2", q(LEFT + width))
                    .set("y1", q(y(v)))
                    .set("y2", q(y(v)))
                    .set("class", "grid"),
            )
            .add(text(LEFT - 3.0, y(v) + 3.0, &format!("{v}"), "end"));
    }
    // All bars of a kind, and all markers of a colour, go into one path each: a plot of a hundred
    // tests is then a few kilobytes. Warnings and failures also get an invisible hover target.
    let mut len_d = String::new();
    let mut str_d = String::new();
    let mut marks: [String; 3] = Default::default();
    let mut hits = Group::new().set("class", "hit");
    let bar = |d: &mut String, x: f64, bw: f64, (lo, hi): (f64, f64)| {
        let (top, bottom) = (y(hi) - 1.0, y(lo) + 1.0);
        let _ = write!(
            d,
            "M{} {}h{}v{}h{}z",
            q(x),
            q(top),
            q(bw),
            q(bottom - top),
            q(-bw)
        );
    };
    for (i, it) in items.iter().enumerate() {
        let x0 = LEFT + i as f64 * step;
        let cx = x0 + step / 2.0;
        for &iv in &it.quality {
            bar(&mut len_d, x0 + step * 0.1, step * 0.8, iv);
        }
        for &iv in &it.strict {
            bar(&mut str_d, x0 + step * 0.3, step * 0.4, iv);
        }
        let m = &mut marks[match it.shade {
            CellShade::Fail => 2,
            CellShade::Warn => 1,
            _ => 0,
        }];
        let r = (step * 0.3).clamp(1.8, 3.0);
        match it.observed.filter(|v| !v.is_nan()) {
            // A diamond at the observed value.
            Some(v) if (LO..=HI).contains(&v) => {
                let _ = write!(m, "M{} {}l{r} {r}l{r} -{r}l-{r} -{r}z", q(cx - r), q(y(v)));
            }
            // Off the axis: a triangle at the edge, pointing out.
            Some(v) => {
                let (edge, dir) = if v < LO { (TOP + H, 1.0) } else { (TOP, -1.0) };
                let _ = write!(
                    m,
                    "M{} {}h7l-3.5 {}z",
                    q(cx - 3.5),
                    q(edge - dir * 5.0),
                    q(dir * 5.0)
                );
            }
            None => {}
        }
        if it.shade >= CellShade::Warn {
            let obs = match it.observed {
                Some(v) if v.is_nan() => "nan".to_string(),
                Some(v) => format!("{v}"),
                None => "none".into(),
            };
            // The intervals are drawn; the dump in the details has them in full.
            let tip = format!("{} — observed r {obs}", it.test);
            hits = hits.add(
                Rectangle::new()
                    .set("x", q(x0))
                    .set("y", TOP)
                    .set("width", q(step))
                    .set("height", H)
                    .add(Title::new(tip)),
            );
        }
    }
    for (d, class) in [(len_d, "len"), (str_d, "str")] {
        if !d.is_empty() {
            doc = doc.add(Path::new().set("d", d).set("class", class));
        }
    }
    for (d, colour) in marks.into_iter().zip([PASS_MARK, WARN_COLOUR, FAIL_COLOUR]) {
        if !d.is_empty() {
            doc = doc.add(Path::new().set("d", d).set("fill", colour));
        }
    }
    doc = doc.add(hits);
    doc = doc.add(text(LEFT, TOP + H + 14.0, caption, "start").set("class", "ax"));
    doc.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_put_grid_values_in_their_own_column_and_the_rest_at_the_edges() {
        assert_eq!(bin(0.0), Some(1));
        assert_eq!(bin(0.2), Some(5));
        assert_eq!(bin(1.0), Some(21));
        assert_eq!(bin(-0.1), Some(0));
        assert_eq!(bin(1e30), Some(BINS - 1));
        assert_eq!(bin(f64::NAN), None);
        assert_eq!(label(0), "<0");
        assert_eq!(label(11), "0.50");
        let s = heatmap("t", &[]);
        assert!(
            s.contains(">\n&lt;0\n<") && s.contains(">\n0.5\n<") && s.contains(">\n1\n<"),
            "tick labels: {s}"
        );
    }

    #[test]
    fn acceptance_text_round_trips_the_runners_format() {
        assert_eq!(parse_acceptance("{1}"), Some(vec![(1.0, 1.0)]));
        assert_eq!(
            parse_acceptance("[0.25, 0.5] ∪ {1}"),
            Some(vec![(0.25, 0.5), (1.0, 1.0)])
        );
        assert_eq!(parse_acceptance("{}"), Some(vec![]));
        assert_eq!(parse_acceptance("(none)"), None);
        // The runner writes the sets with Acceptance's Display; parse what it writes.
        let a = shadowcheck_model::Acceptance(vec![
            shadowcheck_model::Interval::new(0.125, 0.75),
            shadowcheck_model::Interval::point(0.0),
        ]);
        assert_eq!(
            parse_acceptance(&a.to_string()),
            Some(vec![(0.125, 0.75), (0.0, 0.0)])
        );
    }

    #[test]
    fn a_mismatch_is_red_and_outlined_and_a_match_is_toned_by_r() {
        let p = |dt, dref, shade, r| HeatPoint {
            dt,
            dref,
            shade,
            observed: Some(r),
            test: "t".into(),
        };
        let s = heatmap(
            "lequal",
            &[
                p(0.2, 0.5, CellShade::Pass, 0.0),
                p(0.8, 0.5, CellShade::Fail, 0.0),
            ],
        );
        assert!(s.starts_with("<svg"));
        assert_eq!(s.matches(FAIL_COLOUR).count(), 1);
        assert!(s.contains(&tone(0.0)));
        assert!(s.contains("class=\"miss\""));
        let q = plot(
            "x",
            &[PlotItem {
                test: "a".into(),
                shade: CellShade::Warn,
                observed: Some(-1.0),
                strict: vec![(0.5, 0.5)],
                quality: vec![(0.25, 0.75)],
                spec_value: Some(0.5),
            }],
            "c",
        );
        assert!(
            q.contains("<path") && q.contains(WARN_COLOUR),
            "off-axis observation drawn as a triangle"
        );
    }
}
