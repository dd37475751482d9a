//! The runner's side of the `webgl:*` backends: the command of their `shadowcheck webgl-worker`
//! child (the worker is the shadowcheck-webgl crate: headless Chromium over the DevTools pipe, on
//! the ANGLE back end and driver of its instance, `shadowcheck_webgl::instance::INSTANCES`) and
//! whether the browser and that driver are installed.

use super::exec::ProcessCommand;
use super::kinds::{Found, WEBGL_WORKER};
use shadowcheck_webgl::instance::{self, INSTANCES};

/// How to start the worker for `webgl:<rest>`.
pub fn worker_command(rest: &str) -> Result<ProcessCommand, String> {
    let inst = instance::instance(rest).map_err(|e| e.to_string())?;
    let exe = super::gl::shadowcheck_exe().map_err(|e| e.to_string())?;
    Ok(ProcessCommand {
        program: exe,
        args: vec![
            WEBGL_WORKER.subcommand.into(),
            "--backend".into(),
            inst.name(),
        ],
        env: vec![],
    })
}

/// The instances of the kind `prefix` (`webgl`) for a run that names no backend: each runs when
/// the browser and its driver's files are installed, else it is absent with the command that
/// installs them. (An installed one that cannot start is a backend that cannot start.)
pub fn probe_kind(prefix: &str) -> Vec<(String, Found)> {
    INSTANCES
        .iter()
        .map(|i| {
            let found = match i.installed() {
                Ok(()) => Found::Runs,
                Err(why) => Found::Absent(why.to_string()),
            };
            (format!("{prefix}:{}", i.key), found)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_instance_gets_its_own_worker_argument() {
        for (rest, name) in [
            ("chromium", "webgl:chromium"),
            ("chromium-gles", "webgl:chromium-gles"),
            ("chromium-lavapipe", "webgl:chromium-lavapipe"),
        ] {
            // Without a shadowcheck executable beside the test binary the command cannot be
            // made; the instance is checked first.
            if let Ok(c) = worker_command(rest) {
                assert_eq!(c.args, [WEBGL_WORKER.subcommand, "--backend", name]);
                assert!(c.env.is_empty());
            }
        }
        assert!(worker_command("firefox").is_err_and(|e| e.contains("webgl:chromium-gles")));
    }

    #[test]
    fn lavapipe_under_angle_is_the_icd_vk_lavapipe_loads() {
        let (icd, _) = shadowcheck_vk::Driver::Lavapipe.icd().unwrap_or_default();
        assert_eq!(icd, instance::LAVAPIPE_ICD);
    }
}
