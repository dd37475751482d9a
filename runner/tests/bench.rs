//! `shadowcheck bench --quick --json`: the report has the rows of `bench::ids`, each a
//! positive finite number. No timing is asserted (speed is what the bench reports, not what tests check).

use std::path::Path;
use std::process::Command;

fn positive(rep: &serde_json::Value, id: &str, backend: Option<&str>) -> f64 {
    let rows = rep["rows"].as_array().expect("rows");
    let row = rows
        .iter()
        .find(|r| r["id"] == id && r["backend"].as_str() == backend)
        .unwrap_or_else(|| panic!("no row {id} {backend:?} in {rep:#}"));
    let v = row["value"]
        .as_f64()
        .unwrap_or_else(|| panic!("{id}: value is not a number: {row}"));
    assert!(v.is_finite() && v > 0.0, "{id} {backend:?}: {v}");
    if let Some(t) = row.get("target").filter(|t| !t.is_null()) {
        assert!(
            row["met"].is_boolean(),
            "a row with a target says whether it was met: {row}"
        );
        assert!(
            t["bound"]
                .as_f64()
                .is_some_and(|b| b.is_finite() && b > 0.0),
            "{row}"
        );
    }
    v
}

#[test]
fn quick_json_has_every_row_with_positive_finite_values() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
        .args(["bench", "--quick", "--json"])
        .current_dir(&root)
        .output()
        .expect("run shadowcheck bench");
    assert!(
        out.status.success(),
        "exit {}: {}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let rep: serde_json::Value =
        serde_json::from_slice(&out.stdout).expect("bench --json prints one JSON document");
    assert_eq!(rep["schema"], 1);
    assert_eq!(rep["quick"], true);
    assert!(rep["machine"]["nproc"].as_u64().is_some_and(|n| n >= 1));
    assert!(!rep["machine"]["cpu"].as_str().unwrap_or("").is_empty());

    positive(&rep, "oracle_verdicts_per_s", None);
    positive(&rep, "oracle_judge_only_per_s", None);
    positive(&rep, "soft_lookups_per_s", None);
    positive(&rep, "soft_lookups_per_s_linear", None);
    positive(&rep, "suite_wall_s", Some("soft"));
    positive(&rep, "suite_wall_cached_s", Some("soft"));
    positive(&rep, "suite_peak_rss_mib", Some("soft"));
    // Checks per compiled state for every API path of the fixtures.
    for path in [
        "ff", "arbfp", "glsl120", "glsl130", "core", "es100", "es300", "vk", "wgsl",
    ] {
        positive(&rep, "checks_per_compiled_state", Some(path));
    }

    // Vulkan and WebGPU rows exist exactly when the backend starts; otherwise the report says why.
    for (vk, prefix) in [
        ("vk:lavapipe", "vk"),
        ("vk:swiftshader", "vk"),
        ("webgpu:chromium", "webgpu"),
    ] {
        let cold = format!("{prefix}_e2e_cases_per_s");
        let ran = rep["rows"]
            .as_array()
            .unwrap()
            .iter()
            .any(|r| r["id"] == cold.as_str() && r["backend"] == vk);
        if ran {
            for id in [
                "e2e_cases_per_s",
                "e2e_warm_cases_per_s",
                "e2e_cached_cases_per_s",
                "warm_us_per_check",
            ] {
                positive(&rep, &format!("{prefix}_{id}"), Some(vk));
            }
        } else {
            let why = rep["unavailable"].as_array().expect("unavailable");
            assert!(why.iter().any(|u| u["backend"] == vk), "{rep:#}");
            if std::env::var("CI").is_ok_and(|v| v == "true") {
                panic!("CI=true and {vk} is unavailable: {why:?}");
            }
        }
    }

    // GL rows exist exactly when the driver could be used; otherwise the report says why.
    let llvmpipe = "egl:llvmpipe:core";
    let gl_ran = rep["rows"]
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["id"] == "gl_floor_lookups_per_s" && r["backend"] == llvmpipe);
    if gl_ran {
        positive(&rep, "gl_floor_lookups_per_s", Some(llvmpipe));
        positive(&rep, "gl_floor_lookups_per_s_1thread", Some(llvmpipe));
        positive(&rep, "gl_e2e_cases_per_s", Some(llvmpipe));
        positive(&rep, "gl_e2e_steady_cases_per_s", Some(llvmpipe));
        positive(&rep, "gl_e2e_warm_cases_per_s", Some(llvmpipe));
        positive(&rep, "gl_e2e_cached_cases_per_s", Some(llvmpipe));
        positive(&rep, "gl_e2e_over_floor", Some(llvmpipe));
        positive(&rep, "gl_warm_us_per_check", Some(llvmpipe));
        positive(&rep, "compile_ms_per_variant", Some(llvmpipe));
        positive(&rep, "suite_mesa_cold_s", None);
        positive(&rep, "suite_mesa_cached_s", None);
        positive(&rep, "suite_mesa_fast_compile_cold_s", None);
        positive(&rep, "suite_peak_rss_mib", Some("mesa"));
        positive(&rep, "cold_floor_s", None);
        positive(&rep, "cold_floor_states_s", None);
        positive(&rep, "suite_mesa_cold_over_floor", None);
        // soft is compared with llvmpipe's single-thread rate.
        let soft = rep["rows"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["id"] == "soft_lookups_per_s")
            .unwrap();
        assert!(soft["target"]["bound"].as_f64().is_some(), "{soft}");
    } else {
        let why = rep["unavailable"].as_array().expect("unavailable");
        assert!(why.iter().any(|u| u["backend"] == llvmpipe && !u["reason"].as_str().unwrap_or("").is_empty()), "{rep:#}");
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("CI=true and egl:llvmpipe:core is unavailable: {why:?}");
        }
    }
}
