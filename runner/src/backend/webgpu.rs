//! The runner's side of `webgpu:chromium` (and `webgpu:chromium-compat`): the command of its
//! `shadowcheck webgpu-worker` child (the worker is the shadowcheck-webgpu crate: WebGPU in
//! headless Chromium over the DevTools pipe) and whether the browser is installed.

use super::exec::ProcessCommand;
use super::kinds::{Found, WEBGPU_WORKER};
use shadowcheck_webgl::browser;
use shadowcheck_webgpu::launch::{parse_backend, Variant};

/// How to start the worker for `webgpu:<variant>`.
pub fn worker_command(name: &str) -> Result<ProcessCommand, String> {
    let variant = parse_backend(name).ok_or_else(|| {
        format!(
            "unknown WebGPU backend `{name}` (expected one of: {})",
            Variant::ALL.map(Variant::name).join(", ")
        )
    })?;
    let exe = super::gl::shadowcheck_exe().map_err(|e| e.to_string())?;
    Ok(ProcessCommand {
        program: exe,
        args: vec![
            WEBGPU_WORKER.subcommand.into(),
            "--backend".into(),
            variant.name(),
        ],
        env: vec![],
    })
}

/// The instances of the kind `prefix` (`webgpu`) for a run that names no backend:
/// `webgpu:chromium`, running when the browser is installed (found as the worker will look for
/// it), else absent with the install command. `webgpu:chromium-compat` runs only when named.
pub fn probe_kind(prefix: &str) -> Vec<(String, Found)> {
    let found = match browser::chromium_exe() {
        Ok(_) => Found::Runs,
        Err(why) => Found::Absent(why.to_string()),
    };
    vec![(format!("{prefix}:{}", Variant::Core.key()), found)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_variant_names_itself_to_the_worker() {
        for v in Variant::ALL {
            let name = v.name();
            let cmd = worker_command(&name).expect("command");
            assert_eq!(cmd.args, ["webgpu-worker", "--backend", name.as_str()]);
        }
        let why = worker_command("webgpu:firefox").unwrap_err();
        assert!(
            why.contains("webgpu:chromium, webgpu:chromium-compat"),
            "{why}"
        );
        let found = probe_kind("webgpu");
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].0, "webgpu:chromium");
        assert!(matches!(found[0].1, Found::Runs | Found::Absent(_)));
    }
}
