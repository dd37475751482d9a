//! The runner's side of the Vulkan backends (`vk:lavapipe`, `vk:swiftshader`, `vk:native`): the
//! command of a backend's `shadowcheck vk-worker` child (the loader is pointed at the driver's ICD
//! manifest with `VK_ICD_FILENAMES`, read when the loader starts, so each backend gets its own
//! process) and which of them this machine runs. The worker itself is the shadowcheck-vk crate's.

use super::exec::ProcessCommand;
use super::kinds::{Found, VK_WORKER};
use shadowcheck_vk::Driver;
use std::process::Stdio;
use std::time::{Duration, Instant};

/// The environment that selects the driver of `vk:<driver>`: `VK_ICD_FILENAMES` naming its ICD
/// manifest (an error naming the file and the install command when it is absent); none for
/// `vk:native`.
pub fn driver_env(name: &str) -> Result<Vec<(String, String)>, String> {
    let driver = shadowcheck_vk::parse_backend(name).map_err(|e| e.to_string())?;
    let mut env = vec![];
    if let Some((icd, install)) = driver.icd() {
        if !std::path::Path::new(icd).is_file() {
            return Err(format!("{icd} not found; `{install}`"));
        }
        env.push(("VK_ICD_FILENAMES".to_string(), icd.to_string()));
    }
    Ok(env)
}

/// How to start the worker for `vk:<driver>`.
pub fn worker_command(name: &str) -> Result<ProcessCommand, String> {
    let env = driver_env(name)?;
    let exe = super::gl::shadowcheck_exe().map_err(|e| e.to_string())?;
    Ok(ProcessCommand {
        program: exe,
        args: vec![
            VK_WORKER.subcommand.into(),
            "--backend".into(),
            name.to_string(),
        ],
        env,
    })
}

/// What to install when a Vulkan backend cannot start (`None` for `vk:native`, whose driver is
/// the machine's own).
pub fn missing_hint(name: &str) -> Option<&'static str> {
    match shadowcheck_vk::parse_backend(name).ok()? {
        Driver::Lavapipe => Some("vk:lavapipe needs Mesa's Vulkan drivers and glslang: apt-get install -y mesa-vulkan-drivers glslang-tools"),
        Driver::Swiftshader => Some("vk:swiftshader needs Chromium's SwiftShader ICD and glslang: apt-get install -y chromium glslang-tools"),
        Driver::Native => None,
    }
}

/// Longest a probe child may take (opening a device and checking the compiler).
const PROBE_TIMEOUT: Duration = Duration::from_secs(60);

/// The instances of the kind `prefix` (`vk`) for a run that names no backend: lavapipe and
/// SwiftShader (`vk:native` only when named: here it would be one of those again), each probed in
/// a child (`vk-worker --probe`), all started before any is waited for. An ICD manifest that is
/// not installed is absent, with the command that installs it.
pub fn probe_kind(prefix: &str) -> Vec<(String, Found)> {
    let mut running = vec![];
    let mut out: Vec<(String, Found)> = vec![];
    for d in [Driver::Lavapipe, Driver::Swiftshader] {
        let name = format!("{prefix}:{}", d.key());
        if let Some((icd, install)) = d.icd() {
            if !std::path::Path::new(icd).is_file() {
                out.push((name, Found::Absent(format!("{icd} not found; `{install}`"))));
                continue;
            }
        }
        let spawned = worker_command(&name).and_then(|wc| {
            wc.to_command()
                .arg("--probe")
                .stdin(Stdio::null())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .map_err(|e| format!("cannot start {}: {e}", wc.program.display()))
        });
        match spawned {
            Ok(child) => running.push((name, child)),
            Err(why) => out.push((name, Found::Missing(why))),
        }
    }
    let start = Instant::now();
    for (name, mut child) in running {
        let found = loop {
            match child.try_wait() {
                Ok(Some(_)) => break probe_result(child),
                Ok(None) if start.elapsed() > PROBE_TIMEOUT => {
                    let _ = child.kill();
                    let _ = child.wait();
                    break Found::Missing(format!(
                        "probe timed out after {}s",
                        PROBE_TIMEOUT.as_secs()
                    ));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(20)),
                Err(e) => break Found::Missing(e.to_string()),
            }
        };
        out.push((name, found));
    }
    let order = |n: &str| Driver::ALL.iter().position(|d| n.ends_with(d.key()));
    out.sort_by_key(|(n, _)| order(n));
    out
}

fn probe_result(child: std::process::Child) -> Found {
    let o = match child.wait_with_output() {
        Ok(o) => o,
        Err(e) => return Found::Missing(e.to_string()),
    };
    let stdout = String::from_utf8_lossy(&o.stdout);
    let line = stdout
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("");
    if o.status.success() && line.starts_with("ok") {
        return Found::Runs;
    }
    if let Some(why) = line.strip_prefix("unavailable: ") {
        return Found::Missing(why.to_string());
    }
    let stderr = String::from_utf8_lossy(&o.stderr);
    let tail: Vec<&str> = stderr.lines().rev().take(3).collect();
    Found::Missing(format!(
        "worker exited with {}: {}",
        o.status,
        tail.into_iter().rev().collect::<Vec<_>>().join(" | ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_driver_gets_its_icd_and_native_keeps_the_environment() {
        for (name, icd) in [
            ("vk:lavapipe", "lvp_icd.x86_64.json"),
            ("vk:swiftshader", "vk_swiftshader_icd.json"),
        ] {
            match driver_env(name) {
                Ok(env) => {
                    assert_eq!(env.len(), 1);
                    assert!(env[0].0 == "VK_ICD_FILENAMES" && env[0].1.ends_with(icd));
                }
                // Not installed here: the error names the file and the command.
                Err(why) => assert!(
                    why.contains(icd) && why.contains("apt-get install"),
                    "{why}"
                ),
            }
        }
        assert_eq!(driver_env("vk:native"), Ok(vec![]));
        assert!(driver_env("vk:other").is_err());
        assert_eq!(missing_hint("vk:native"), None);
        assert!(missing_hint("vk:lavapipe").is_some_and(|h| h.contains("mesa-vulkan-drivers")));
    }
}
