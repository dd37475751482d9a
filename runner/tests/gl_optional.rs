//! The default run with the optional implementations beyond Mesa not installed: they are announced
//! with the install command, not counted as missing (no exit 96). One test per process: it points
//! the SwiftShader locations at nothing through the environment the probe children inherit.
use shadowcheck_runner::backend::{self, gl};

#[test]
fn absent_optional_backends_are_announced_not_missing() {
    std::env::set_var(gl::WORKER_EXE_ENV, env!("CARGO_BIN_EXE_shadowcheck"));
    std::env::set_var("SHADOWCHECK_SWIFTSHADER_DIR", "/no/such/swiftshader");
    std::env::set_var("SHADOWCHECK_VK_SWIFTSHADER_ICD", "/no/such/icd.json");
    let backend::Defaults {
        run,
        missing,
        absent,
        ..
    } = backend::default_backends();
    for name in [
        "egl:swiftshader:es3",
        "egl:swiftshader:es2",
        "egl:zink+swiftshader:core",
        "egl:zink+swiftshader:compat",
        "egl:zink+swiftshader:es3",
    ] {
        assert!(!run.iter().any(|n| n == name), "{name} in {run:?}");
        assert!(
            !missing.iter().any(|(n, _)| n == name),
            "{name} in {missing:?}"
        );
        let (_, how) = absent
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("{name} not announced: {absent:?}"));
        let install = if name.contains("zink") {
            "apt-get install -y chromium-common"
        } else {
            "sh gl/fetch-swiftshader.sh"
        };
        assert!(how.contains(install) && how.contains("/no/such/"), "{how}");
    }
    // Impossible combinations are in no list.
    assert!(!absent.iter().any(|(n, _)| n.starts_with("osmesa:")));
}
