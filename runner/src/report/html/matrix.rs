//! The cross-driver matrix: one row per (spec, compare func, filter, format), one column per
//! backend; each cell counts the raw outcomes of its tests and links to the dumps of the ones
//! that did not pass (capped per cell, with the count of the rest).
//!
//! Cells use the raw outcome, not the final status: the matrix answers "is this driver right?",
//! which a baseline does not change. The final statuses are in the summary and in each dump.

use super::page::esc;
use crate::records::Outcome;
use crate::records::TestResult;
use crate::report::{dump, wants_dump};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The worst raw outcome in a cell decides its colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum CellShade {
    Empty,
    Skip,
    Pass,
    Warn,
    Fail,
}

impl CellShade {
    pub fn class(self) -> &'static str {
        match self {
            CellShade::Empty => "n",
            CellShade::Skip => "s",
            CellShade::Pass => "p",
            CellShade::Warn => "w",
            CellShade::Fail => "f",
        }
    }
    /// Fail, Crash and Timeout are failures; Warn is quality-only; Skip is not run.
    pub fn of(o: Outcome) -> CellShade {
        match o {
            Outcome::Pass => CellShade::Pass,
            Outcome::Warn => CellShade::Warn,
            Outcome::Skip => CellShade::Skip,
            Outcome::Fail | Outcome::Crash | Outcome::Timeout => CellShade::Fail,
        }
    }
}

/// The tests of one row on one backend.
#[derive(Debug, Default, Clone)]
pub struct Cell {
    pub pass: usize,
    pub warn: usize,
    pub fail: usize,
    pub skip: usize,
    /// Indices (into the results) of the tests that deserve a dump, in result order.
    pub dumps: Vec<usize>,
}

impl Cell {
    pub fn shade(&self) -> CellShade {
        if self.fail > 0 {
            CellShade::Fail
        } else if self.warn > 0 {
            CellShade::Warn
        } else if self.pass > 0 {
            CellShade::Pass
        } else if self.skip > 0 {
            CellShade::Skip
        } else {
            CellShade::Empty
        }
    }
    pub fn total(&self) -> usize {
        self.pass + self.warn + self.fail + self.skip
    }
    /// More than one kind of outcome (the cell's text shows only the worst).
    pub fn mixed(&self) -> bool {
        [self.pass, self.warn, self.fail, self.skip]
            .iter()
            .filter(|&&n| n > 0)
            .count()
            > 1
    }
}

/// `spec / func / filter / format`.
pub type RowKey = [String; 4];

pub struct Matrix {
    pub backends: Vec<String>,
    pub rows: Vec<(RowKey, Vec<Cell>)>,
}

impl Matrix {
    pub fn build(backends: &[String], results: &[TestResult]) -> Matrix {
        let col: BTreeMap<&str, usize> = backends
            .iter()
            .enumerate()
            .map(|(i, b)| (b.as_str(), i))
            .collect();
        let mut rows: BTreeMap<RowKey, Vec<Cell>> = BTreeMap::new();
        for (i, r) in results.iter().enumerate() {
            let Some(&c) = col.get(r.backend.as_str()) else {
                continue;
            };
            let t = &r.tags;
            let key = [
                t.spec.clone(),
                t.func.clone(),
                t.filter.clone(),
                t.format.clone(),
            ];
            let cell = &mut rows
                .entry(key)
                .or_insert_with(|| vec![Cell::default(); backends.len()])[c];
            match CellShade::of(r.outcome) {
                CellShade::Pass => cell.pass += 1,
                CellShade::Warn => cell.warn += 1,
                CellShade::Fail => cell.fail += 1,
                _ => cell.skip += 1,
            }
            if wants_dump(r) {
                cell.dumps.push(i);
            }
        }
        Matrix {
            backends: backends.to_vec(),
            rows: rows.into_iter().collect(),
        }
    }

    /// Rows where some backend warned or failed, or where backends disagree on pass vs skip.
    pub fn differs(cells: &[Cell]) -> bool {
        cells
            .iter()
            .any(|c| c.warn + c.fail > 0 || !c.dumps.is_empty())
    }

    pub fn rows_differing(&self) -> usize {
        self.rows.iter().filter(|(_, c)| Matrix::differs(c)).count()
    }
}

fn anchor(row: usize, col: usize) -> String {
    format!("d{row}-{col}")
}

fn cell_text(c: &Cell) -> String {
    match c.shade() {
        CellShade::Empty | CellShade::Skip => String::new(),
        CellShade::Pass => format!("{}", c.pass),
        CellShade::Warn => format!("{} warn", c.warn),
        CellShade::Fail => format!("{} fail", c.fail),
    }
}

/// The matrix as an HTML table (`id="matrix"`). Rows without a warning or failure carry class
/// `same`, hidden while the table has class `only-diff`. Cells omit their end tags (as HTML
/// allows) and skipped cells their text, so 1500 rows × 17 backends stay well under a megabyte.
pub fn render(m: &Matrix, out: &mut String) {
    let differing = m.rows_differing();
    let only_diff = differing > 0;
    let _ = writeln!(
        out,
        "<p class=\"note\">{} rows (spec / compare func / min/mag filter / format) × {} backends; {} rows have a warning or failure. \
         A cell counts its tests by raw outcome: a number alone is all pass; <span class=\"w pill\">warn</span> inside the quality \
         profile only; <span class=\"f pill\">fail</span> outside quality, crash or timeout; <span class=\"s pill\">grey</span> not run (skipped). \
         Hover a cell for its counts, click it for its cases.</p>",
        m.rows.len(),
        m.backends.len(),
        differing
    );
    let _ = writeln!(
        out,
        "<label><input type=\"checkbox\" id=\"only-diff\"{}> only rows with a warning or failure</label>",
        if only_diff { " checked" } else { "" }
    );
    let _ = write!(out, "<table id=\"matrix\" class=\"matrix{}\"><thead><tr><th>spec</th><th>func</th><th>filter</th><th>format</th>", if only_diff { " only-diff" } else { "" });
    for b in &m.backends {
        // Break long names at their colons (egl / llvmpipe / compat) to keep columns narrow.
        let name = b.split(':').map(esc).collect::<Vec<_>>().join(":<br>");
        let _ = write!(out, "<th class=\"be\" title=\"{}\">{name}</th>", esc(b));
    }
    out.push_str("</tr></thead><tbody>\n");
    for (ri, (key, cells)) in m.rows.iter().enumerate() {
        let class = if Matrix::differs(cells) {
            "diff"
        } else {
            "same"
        };
        let _ = write!(out, "<tr class=\"{class}\">");
        for k in key {
            let _ = write!(out, "<td>{}", esc(k));
        }
        for (ci, c) in cells.iter().enumerate() {
            let title = if c.mixed() {
                format!(
                    " title=\"{}\"",
                    esc(&format!(
                        "{}: pass {}, warn {}, fail {}, skip {}",
                        m.backends[ci], c.pass, c.warn, c.fail, c.skip
                    ))
                )
            } else {
                String::new()
            };
            let text = cell_text(c);
            if c.dumps.is_empty() {
                let _ = write!(out, "<td class={}{title}>{text}", c.shade().class());
            } else {
                let _ = write!(
                    out,
                    "<td class={}{title}><a href=\"#{}\">{text}</a>",
                    c.shade().class(),
                    anchor(ri, ci)
                );
            }
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody></table>\n");
}

/// Limits on the details.
#[derive(Debug, Clone, Copy)]
pub struct DetailCaps {
    /// Dumps shown per cell.
    pub per_cell: usize,
    /// Dumps shown in the whole report.
    pub total: usize,
}

/// How many dumps each cell shows: `caps.per_cell`, lowered so that every cell with dumps gets
/// its share of `caps.total` (but at least 3), rather than the first cells taking it all.
pub fn per_cell_share(m: &Matrix, caps: DetailCaps) -> usize {
    let cells = m
        .rows
        .iter()
        .flat_map(|(_, c)| c)
        .filter(|c| !c.dumps.is_empty())
        .count()
        .max(1);
    caps.per_cell.min((caps.total / cells).max(3))
}

/// The dumps of every cell with warnings or failures (id, backend, API path, expected per
/// profile, observed RGBA, footprint, re-run command), at most [`per_cell_share`] per cell and
/// `caps.total` in all; each section says how many it leaves out.
pub fn render_details(m: &Matrix, results: &[TestResult], caps: DetailCaps, out: &mut String) {
    let mut shown_total = 0usize;
    let mut any = false;
    let share = per_cell_share(m, caps);
    for (ri, (key, cells)) in m.rows.iter().enumerate() {
        for (ci, c) in cells.iter().enumerate() {
            if c.dumps.is_empty() {
                continue;
            }
            any = true;
            let room = share.min(caps.total.saturating_sub(shown_total));
            let show = c.dumps.len().min(room);
            shown_total += show;
            let _ = writeln!(
                out,
                "<section class=\"cell\" id=\"{}\"><h3><span class=\"{} pill\">{}</span> {} — {}</h3>",
                anchor(ri, ci),
                c.shade().class(),
                esc(&cell_text(c)),
                esc(&key.join(" / ")),
                esc(&m.backends[ci])
            );
            if show < c.dumps.len() {
                let _ = writeln!(
                    out,
                    "<p class=\"note\">showing {show} of {} tests; the rest are in the run's results.jsonl / report.md.</p>",
                    c.dumps.len()
                );
            }
            for &i in &c.dumps[..show] {
                let r = &results[i];
                let _ = writeln!(
                    out,
                    "<pre class=\"dump {}\">{}</pre>",
                    CellShade::of(r.outcome).class(),
                    esc(dump(r, "").trim_end())
                );
            }
            out.push_str("</section>\n");
        }
    }
    if !any {
        out.push_str("<p>No test warned or failed.</p>\n");
    }
}
