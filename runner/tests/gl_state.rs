//! TexParameter state self-check (`gl-worker --state-check`) on every driver and context kind:
//! initial values, accepted values and the errors for rejected ones must match the oracle's state
//! tables (GL 4.6 Table 8.17 / §8.10, ES 3.2 §8.10, compatibility DEPTH_TEXTURE_MODE).
mod gl_support;
use gl_support::*;
use std::path::PathBuf;
use std::process::Stdio;

#[test]
fn state_defaults_and_errors_match_the_oracle() {
    let mut names = Vec::new();
    for api in ["core", "compat", "es3"] {
        names.extend(backends(api, api != "es3"));
    }
    for b in names {
        let mut wc = shadowcheck_runner::backend::gl::worker_command(&b).expect("worker command");
        wc.program = PathBuf::from(env!("CARGO_BIN_EXE_shadowcheck"));
        let out = wc
            .to_command()
            .arg("--state-check")
            .stdin(Stdio::null())
            .output()
            .expect("run worker");
        let stdout = String::from_utf8_lossy(&out.stdout);
        if stdout.trim().is_empty() {
            unavailable(&b, String::from_utf8_lossy(&out.stderr).trim());
            continue;
        }
        let checks: Vec<serde_json::Value> = stdout
            .lines()
            .map(|l| serde_json::from_str(l).expect("json line"))
            .collect();
        // At least TEXTURE_COMPARE_MODE and _FUNC: a default and several values each.
        assert!(checks.len() >= 20, "{b}: only {} checks", checks.len());
        let failing: Vec<String> = checks
            .iter()
            .filter(|c| c["ok"] != true)
            .map(|c| c.to_string())
            .collect();
        assert!(failing.is_empty(), "{b}:\n{}", failing.join("\n"));
        assert!(out.status.success(), "{b}: exit {}", out.status);
    }
}
