//! Rendering a [`BenchReport`]: an aligned text table for the terminal and Markdown for reports/BENCH.md.
//!
//! `-o FILE` rewrites only the part of FILE between [`BEGIN`] and [`END`] when both markers are
//! there, so hand-written analysis around the generated table (profiles of missed targets) stays.

use super::{fmt_num, BenchReport, Measurement};

pub const BEGIN: &str =
    "<!-- shadowcheck bench: begin (generated; text outside the markers is kept) -->";
pub const END: &str = "<!-- shadowcheck bench: end -->";

fn label(id: &str) -> &'static str {
    use super::ids::*;
    match id {
        ORACLE_VERDICTS => "oracle: evaluate + judge",
        ORACLE_JUDGE => "oracle: judge only (stored expectation)",
        SOFT_LOOKUPS => "soft: raw lookups, 2D NEAREST",
        SOFT_LOOKUPS_LINEAR => "soft: raw lookups, 2D LINEAR (PCF)",
        GL_FLOOR => "GL bare-draw floor",
        GL_FLOOR_1T => "GL bare-draw floor, LP_NUM_THREADS=1",
        GL_E2E => "GL end to end, 2D NEAREST",
        GL_E2E_STEADY => "GL end to end, no load / worker start",
        GL_E2E_WARM => "GL end to end, warm (same worker again, median pass)",
        GL_E2E_CACHED => "GL end to end, new worker, shader cache filled",
        GL_RATIO => "GL end to end / floor",
        VK_E2E => "Vulkan end to end, vulkan/ fixtures, cold",
        VK_E2E_WARM => "Vulkan end to end, warm (same worker again, median pass)",
        VK_E2E_CACHED => "Vulkan end to end, new worker, shader cache filled",
        VK_PER_CHECK => "Vulkan cost per check after the pipelines (warm)",
        WEBGPU_E2E => "WebGPU end to end, webgpu/ fixtures, cold (new browser)",
        WEBGPU_E2E_WARM => "WebGPU end to end, warm (same worker again, median pass)",
        WEBGPU_E2E_CACHED => "WebGPU end to end, new worker (new browser profile)",
        WEBGPU_PER_CHECK => "WebGPU cost per check after the pipelines (warm)",
        SUITE_WALL => "default suite: wall",
        SUITE_RSS => "default suite: peak RSS",
        SUITE_WALL_CACHED => "default suite: wall, shader cache filled",
        MESA_COLD => "default suite, every Mesa backend, one run: cold",
        MESA_CACHED => "default suite, every Mesa backend, one run: shader cache filled",
        MESA_FAST_COMPILE => "same, cold, `--fast-compile` (opt-in)",
        CHECKS_PER_STATE => "checks per compiled sampler state",
        HARNESS_PER_CHECK => "cost per check after compilation (warm)",
        MESA_ONE_STATE => "same, cold, one state per program (`--states-per-program 1`)",
        MESA_COLD_OVER_ONE_STATE => "cold suite / cold suite with one state per program",
        MESA_VERDICTS_DIFFERING => "tests whose status differs, one vs many states per program",
        STATES_PER_SET => "states per compiled variant (distinct program-state sets)",
        STATES_PER_CACHE_ENTRY => "distinct states per shader cache entry, cold gl46",
        COMPILE_PER_VARIANT => "compile time per shader variant, one state per program",
        COMPILE_PER_STATE => "compile time per state, many states per program",
        COMPILE_PER_SET => "compile time per variant of many states",
        COLD_FLOOR_STATES => "cold floor of one state per program: states x compile time / cores",
        COLD_FLOOR => "cold floor of what the run compiled: sets and states x their costs / cores",
        COLD_OVER_FLOOR => "cold suite / cold floor",
        _ => "",
    }
}

fn cells(r: &Measurement) -> [String; 6] {
    let name = match label(&r.id) {
        "" => r.id.clone(),
        l => l.to_string(),
    };
    let target = r
        .target
        .as_ref()
        .map(|t| format!("{} ({})", t.describe(&r.unit), t.source))
        .unwrap_or_default();
    let met = match r.met {
        Some(true) => "met",
        Some(false) => "MISSED",
        None => "",
    };
    [
        name,
        r.backend.clone().unwrap_or_default(),
        fmt_num(r.value),
        r.unit.clone(),
        target,
        met.to_string(),
    ]
}

const HEADERS: [&str; 6] = ["measure", "backend", "value", "unit", "target", ""];

/// Aligned plain-text table with the machine line and what could not be measured.
pub fn text(rep: &BenchReport) -> String {
    let rows: Vec<[String; 6]> = rep.rows.iter().map(cells).collect();
    let mut w = HEADERS.map(|h| h.chars().count());
    for r in &rows {
        for (i, c) in r.iter().enumerate() {
            w[i] = w[i].max(c.chars().count());
        }
    }
    let line = |c: [&str; 6]| {
        let mut s = String::new();
        for (i, x) in c.iter().enumerate() {
            let pad = w[i] - x.chars().count();
            if i == 2 {
                s += &format!("{}{x}  ", " ".repeat(pad));
            } else {
                s += &format!("{x}{}  ", " ".repeat(pad));
            }
        }
        s.trim_end().to_string() + "\n"
    };
    let mut s = machine_line(rep) + "\n";
    s += &line(HEADERS);
    for r in &rows {
        s += &line([&r[0], &r[1], &r[2], &r[3], &r[4], &r[5]]);
    }
    for u in &rep.unavailable {
        s += &format!(
            "not measured: {}{}: {}\n",
            u.what,
            u.backend
                .as_deref()
                .map(|b| format!(" ({b})"))
                .unwrap_or_default(),
            u.reason
        );
    }
    s
}

fn machine_line(rep: &BenchReport) -> String {
    let m = &rep.machine;
    format!(
        "{} logical CPUs ({}), {} MiB, {}, Linux {}, load average {:.2} at start, finished {}{}",
        m.nproc,
        m.cpu,
        m.memory_mib,
        m.mesa,
        m.kernel,
        m.load_average,
        m.date,
        if rep.quick { ", --quick" } else { "" }
    )
}

/// The generated Markdown block (between the markers).
pub fn block(rep: &BenchReport) -> String {
    let mut s = format!("{BEGIN}\n\n**Machine:** {}\n\n", machine_line(rep));
    s += "| measure | backend | value | unit | target | |\n|---|---|--:|---|---|---|\n";
    for r in &rep.rows {
        let c = cells(r);
        s += &format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            c[0],
            c[1],
            c[2],
            c[3],
            c[4],
            if c[5] == "MISSED" {
                "**MISSED**"
            } else {
                &c[5]
            }
        );
    }
    s += "\nHow each row was measured:\n\n";
    for r in &rep.rows {
        s += &format!(
            "- {}{}: {}\n",
            cells(r)[0],
            r.backend
                .as_deref()
                .map(|b| format!(" ({b})"))
                .unwrap_or_default(),
            r.detail
        );
    }
    if !rep.unavailable.is_empty() {
        s += "\nNot measured:\n\n";
        for u in &rep.unavailable {
            s += &format!(
                "- {}{}: {}\n",
                u.what,
                u.backend
                    .as_deref()
                    .map(|b| format!(" ({b})"))
                    .unwrap_or_default(),
                u.reason
            );
        }
    }
    s + "\n" + END + "\n"
}

/// The file's new text: `old` with the block between the markers replaced, or a new document.
pub fn document(rep: &BenchReport, old: Option<&str>) -> String {
    if let Some(old) = old {
        if let (Some(b), Some(e)) = (old.find(BEGIN), old.find(END)) {
            if b < e {
                let tail = &old[e + END.len()..];
                let tail = tail.strip_prefix('\n').unwrap_or(tail);
                return format!("{}{}{}", &old[..b], block(rep), tail);
            }
        }
    }
    format!(
        "# shadowcheck bench\n\nWritten by `shadowcheck bench --markdown reports/BENCH.md`.\n\n{}",
        block(rep)
    )
}

#[cfg(test)]
mod tests {
    use super::super::{machine::Machine, Goal, Target};
    use super::*;

    fn report() -> BenchReport {
        BenchReport {
            schema: 1,
            quick: true,
            machine: Machine {
                nproc: 2,
                cpu: "cpu".into(),
                memory_mib: 1,
                mesa: "Mesa 1".into(),
                load_average: 0.5,
                kernel: "6".into(),
                date: "d".into(),
            },
            rows: vec![Measurement::new(
                super::super::ids::ORACLE_VERDICTS,
                None,
                2.0e6,
                "verdicts/s/core",
                "how".into(),
            )
            .with_target(Target::new(Goal::AtLeast, 5e7, "throughput goal"))],
            unavailable: vec![],
        }
    }

    #[test]
    fn markdown_marks_misses_and_keeps_text_outside_the_markers() {
        let rep = report();
        let doc = document(&rep, None);
        assert!(doc.contains("| oracle: evaluate + judge |  | 2.00M | verdicts/s/core | >= 50.0M verdicts/s/core (throughput goal) | **MISSED** |"), "{doc}");
        let edited = doc.replace("# shadowcheck bench\n", "# shadowcheck bench\n\nintro\n")
            + "\n## Profiles\nkept\n";
        let again = document(&rep, Some(&edited));
        assert!(
            again.contains("intro") && again.ends_with("## Profiles\nkept\n"),
            "{again}"
        );
        assert_eq!(again.matches(BEGIN).count(), 1);
    }

    #[test]
    fn text_table_is_aligned() {
        let t = text(&report());
        assert!(t.lines().nth(1).unwrap().starts_with("measure"));
        assert!(t.contains("MISSED"));
    }
}
