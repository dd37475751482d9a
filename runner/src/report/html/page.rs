//! The page around the parts: HTML escaping, the inline style sheet and script (the report
//! loads nothing from anywhere), and the summary per backend.

use crate::records::{Counts, TestResult};
use std::fmt::Write as _;

/// Escapes text for HTML element content and double-quoted attributes.
pub fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            c => o.push(c),
        }
    }
    o
}

pub const STYLE: &str = r#"
body{font:14px/1.4 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0 14px 48px;color:#1d2330;background:#fff}
h1{font-size:22px;margin:18px 0 4px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #ccd;padding-bottom:3px}
h3{font-size:14px;margin:16px 0 6px}nav a{margin-right:14px}.note{color:#556;font-size:13px;margin:4px 0}
table{border-collapse:collapse;font-size:12.5px}th,td{border:1px solid #d0d4dc;padding:2px 6px;text-align:left}
th{background:#eef1f6;position:sticky;top:0}td.num{text-align:right}
.matrix{font-size:12px}.matrix td{padding:2px 4px}.matrix td:nth-child(n+5){text-align:center;min-width:34px;white-space:nowrap}.matrix th.be{font-size:10px;max-width:54px;vertical-align:bottom;font-weight:500;padding:2px 3px}.matrix .f{font-weight:500}
#summary td:first-child{max-width:420px;word-break:break-all}
table.only-diff tr.same{display:none}
.p{background:#cdebd3}.w{background:#ffd98a}.f{background:#f4a3a3;font-weight:600}.s{background:#e4e6ea;color:#667}.n{color:#aab}
td a{color:inherit;display:block}.pill{padding:0 6px;border-radius:8px}
.bar{display:flex;width:240px;height:12px;border:1px solid #bbb}.bar span{display:block;height:100%}
.b-pass{background:#4caf6a}.b-warn{background:#f0a020}.b-fail{background:#d62728}.b-skip{background:#c3c7cf}.b-other{background:#8a6fd1}
.pics{display:flex;flex-wrap:wrap;gap:10px 18px;align-items:flex-start}
svg{font:10px sans-serif;background:#fff}svg .t{font-weight:600;font-size:11px}svg .ax{fill:#556}
svg .frame{fill:#fafbfc;stroke:#9aa}svg .diag{stroke:#000;stroke-opacity:.25;stroke-dasharray:3 3}
svg .miss rect{stroke:#000;stroke-width:1.2}svg .grid{stroke:#dde}svg .len{fill:#c9d3e3}svg .str{fill:#6b7fa8}svg .hit rect{fill:transparent}svg .hit rect:hover{fill:#0001}
pre.dump{background:#f6f7f9;border-left:4px solid #ccc;padding:6px 10px;font-size:12px;white-space:pre-wrap;overflow-wrap:anywhere;margin:6px 0}
pre.dump{background:#f6f7f9}pre.dump.f{border-color:#d62728;font-weight:normal;background:#f6f7f9}pre.dump.w{border-color:#f0a020;background:#f6f7f9}
.legend span{display:inline-block;width:12px;height:12px;vertical-align:middle;margin:0 4px 0 12px;border:1px solid #888}
"#;

pub const SCRIPT: &str = r#"
document.getElementById('only-diff')?.addEventListener('change',e=>{document.getElementById('matrix').classList.toggle('only-diff',e.target.checked)});
"#;

/// The summary table: one row per backend, final statuses (as the runner's summary counts them)
/// and a bar of pass / warn / fail / skip / other.
pub fn summary(backends: &[String], results: &[TestResult], out: &mut String) {
    out.push_str(
        "<table id=\"summary\"><thead><tr><th>backend</th><th>tests</th><th>pass</th><th>warn</th><th>fail</th><th>skip</th>\
         <th>crash</th><th>timeout</th><th>expected fail</th><th>flake</th><th>improved</th><th></th></tr></thead><tbody>\n",
    );
    for b in backends {
        let mut c = Counts::default();
        for r in results.iter().filter(|r| &r.backend == b) {
            c.add(r.status);
        }
        let total = c.total();
        let fail = c.fail + c.crash + c.timeout;
        let other = c.expected_fail + c.flake + c.known_flake + c.unexpected_improvement;
        let mut bar = String::new();
        for (n, class) in [
            (c.pass, "b-pass"),
            (c.warn, "b-warn"),
            (fail, "b-fail"),
            (c.skip, "b-skip"),
            (other, "b-other"),
        ] {
            if n > 0 && total > 0 {
                let _ = write!(
                    bar,
                    "<span class=\"{class}\" style=\"width:{:.2}%\"></span>",
                    100.0 * n as f64 / total as f64
                );
            }
        }
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"num\">{total}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{}</td><td><div class=\"bar\">{bar}</div></td></tr>",
            esc(b),
            c.pass,
            c.warn,
            c.fail,
            c.skip,
            c.crash,
            c.timeout,
            c.expected_fail,
            c.flake + c.known_flake,
            c.unexpected_improvement
        );
    }
    out.push_str("</tbody></table>\n");
}
