//! The plan is the API-neutral description of what to draw: it must build and test on a machine
//! with no GL, browser or process machinery, and the WebGL worker must draw from it rather than
//! from the GL worker. Checked on the manifests, where such a dependency would come in.

use std::path::Path;

/// The names in a manifest's `[dependencies]` table (not dev- or build-dependencies).
fn dependencies(manifest: &Path) -> Vec<String> {
    let text =
        std::fs::read_to_string(manifest).unwrap_or_else(|e| panic!("{}: {e}", manifest.display()));
    let mut in_deps = false;
    let mut out = Vec::new();
    for line in text.lines().map(str::trim) {
        if line.starts_with('[') {
            in_deps = line == "[dependencies]";
        } else if in_deps && !line.is_empty() && !line.starts_with('#') {
            if let Some((name, _)) = line.split_once('=') {
                out.push(name.trim().to_string());
            }
        }
    }
    out
}

#[test]
fn the_plan_depends_on_no_gl_browser_or_process_crate() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
    let deps = dependencies(&manifest);
    let allowed = [
        "shadowcheck-model.workspace",
        "shadowcheck-protocol.workspace",
        "serde_json.workspace",
        "thiserror.workspace",
    ];
    assert!(
        !deps.is_empty(),
        "no [dependencies] read from {}",
        manifest.display()
    );
    for d in &deps {
        assert!(
            allowed.contains(&d.as_str()),
            "shadowcheck-plan depends on `{d}`"
        );
    }
}

#[test]
fn the_webgl_worker_draws_from_the_plan_not_from_the_gl_worker() {
    let webgl = Path::new(env!("CARGO_MANIFEST_DIR")).join("../webgl/Cargo.toml");
    let deps = dependencies(&webgl);
    assert!(
        deps.iter().any(|d| d == "shadowcheck-plan.workspace"),
        "{deps:?}"
    );
    assert!(
        !deps.iter().any(|d| d.starts_with("shadowcheck-gl")),
        "{deps:?}"
    );
}

#[test]
fn the_webgpu_worker_draws_from_the_plan_not_from_the_gl_worker() {
    let webgpu = Path::new(env!("CARGO_MANIFEST_DIR")).join("../webgpu/Cargo.toml");
    let deps = dependencies(&webgpu);
    assert!(
        deps.iter().any(|d| d == "shadowcheck-plan.workspace"),
        "{deps:?}"
    );
    assert!(
        !deps.iter().any(|d| d.starts_with("shadowcheck-gl")),
        "{deps:?}"
    );
}
