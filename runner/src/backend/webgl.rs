//! The runner's side of `webgl:chromium`: the command of its `shadowcheck webgl-worker` child
//! (the worker is the shadowcheck-webgl crate: headless Chromium over the DevTools pipe) and
//! whether the browser is installed.

use super::exec::ProcessCommand;
use super::kinds::{Found, WEBGL_WORKER};
use shadowcheck_webgl::browser;

/// The one browser this kind knows.
pub const BROWSERS: &[&str] = &["chromium"];

/// How to start the worker for `webgl:<browser>`.
pub fn worker_command(browser: &str) -> Result<ProcessCommand, String> {
    if !BROWSERS.contains(&browser) {
        return Err(format!(
            "unknown browser `{browser}` (expected one of: {})",
            BROWSERS.join(", ")
        ));
    }
    let exe = super::gl::shadowcheck_exe().map_err(|e| e.to_string())?;
    Ok(ProcessCommand {
        program: exe,
        args: vec![WEBGL_WORKER.subcommand.into()],
        env: vec![],
    })
}

/// `Ok(())` when the browser is installed (found as the worker will look for it), else why not,
/// with the install command.
pub fn installed() -> Result<(), String> {
    browser::chromium_exe()
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// The instances of the kind `prefix` (`webgl`) for a run that names no backend: one per browser,
/// running when the browser is installed, else absent with the install command.
pub fn probe_kind(prefix: &str) -> Vec<(String, Found)> {
    BROWSERS
        .iter()
        .map(|b| {
            let found = match installed() {
                Ok(()) => Found::Runs,
                Err(why) => Found::Absent(why),
            };
            (format!("{prefix}:{b}"), found)
        })
        .collect()
}
