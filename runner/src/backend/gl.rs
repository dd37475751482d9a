//! The runner's side of the GL backends (`egl:*`, `osmesa:*`): how to start a backend's
//! `shadowcheck gl-worker` child (the driver is chosen by environment variables read when Mesa
//! loads, so each backend gets its own process, and a driver crash only takes down its worker), and
//! probing which backends this machine can run. The worker itself is the GL crate's.

use super::exec::ProcessCommand;
use super::kinds::{Found, GL_WORKER};
use shadowcheck_gl::{libdir, BackendName, Driver, WorkerError};
use std::path::PathBuf;
use std::process::Stdio;
use std::time::{Duration, Instant};

/// Environment variable naming the `shadowcheck` executable to run workers with (tests, wrappers).
pub const WORKER_EXE_ENV: &str = "SHADOWCHECK_EXE";

/// The `shadowcheck` binary: `$SHADOWCHECK_EXE`, the current executable when it is shadowcheck, or
/// `shadowcheck` beside the current executable or its parent (a test binary in target/*/deps).
pub fn shadowcheck_exe() -> Result<PathBuf, WorkerError> {
    if let Some(p) = std::env::var_os(WORKER_EXE_ENV) {
        return Ok(PathBuf::from(p));
    }
    let me = std::env::current_exe().map_err(|e| WorkerError::NoExecutable(e.to_string()))?;
    if me.file_stem().is_some_and(|s| s == "shadowcheck") {
        return Ok(me);
    }
    let mut dir = me.parent();
    for _ in 0..2 {
        if let Some(d) = dir {
            let cand = d.join(format!("shadowcheck{}", std::env::consts::EXE_SUFFIX));
            if cand.is_file() {
                return Ok(cand);
            }
            dir = d.parent();
        }
    }
    Err(WorkerError::NoExecutable(format!(
        "{} is not shadowcheck and none was found beside it; set {WORKER_EXE_ENV}",
        me.display()
    )))
}

/// How to start the worker for one backend name. `egl@<dir>:<driver>:<api>` loads libEGL from
/// `<dir>` (with LD_LIBRARY_PATH there, so it binds its own libGLESv2): the worker gets the name
/// without the directory and the library through its environment.
pub fn worker_command(backend: &str) -> Result<ProcessCommand, WorkerError> {
    let (lib_dir, plain) = libdir::split_lib_dir(backend)?;
    let name: BackendName = plain.parse()?;
    if let Some(why) = name.static_unavailability() {
        return Err(WorkerError::Unavailable(why));
    }
    let mut env = name.env();
    match &lib_dir {
        None => shadowcheck_gl::context::check_files(name)?,
        Some(dir) => {
            let egl = libdir::libegl_in(dir);
            if !egl.is_file() {
                return Err(WorkerError::MissingLibrary {
                    lib: egl.display().to_string(),
                    detail: "no such file".into(),
                    install: "name a directory holding libEGL.so or libEGL.so.1".into(),
                });
            }
            env.retain(|(k, _)| k != "LD_LIBRARY_PATH" && k != shadowcheck_gl::context::LIBEGL_ENV);
            env.extend(libdir::lib_dir_env(dir));
        }
    }
    Ok(ProcessCommand {
        program: shadowcheck_exe()?,
        args: vec![
            GL_WORKER.subcommand.into(),
            "--backend".into(),
            name.to_string(),
        ],
        env,
    })
}

/// Whether the driver behind `backend` compiles a shader variant per sampler state: every driver
/// but softpipe, which interprets its shaders (an unparsable name: assumed to).
pub fn compiles_per_state(backend: &str) -> bool {
    libdir::split_lib_dir(backend)
        .ok()
        .and_then(|(_, plain)| plain.parse::<BackendName>().ok())
        .is_none_or(|n| n.driver != Driver::Softpipe)
}

/// Backend names that can run here (each probed in a child process): those that start and expose
/// at least one spec.
pub fn probe() -> Vec<String> {
    probe_report()
        .into_iter()
        .filter(|(_, r)| matches!(r, Ok(Probed::Runs)))
        .map(|(n, _)| n)
        .collect()
}

/// The instances of the GL kind `prefix` (`egl`, `osmesa`) for a run that names no backend
/// ([`kinds::DefaultInstances::Probed`](super::kinds::DefaultInstances)): every driver and API of
/// the platform, probed, with the optional implementations beyond Mesa whose files are not
/// installed absent and the combinations that can never work impossible.
pub fn probe_kind(prefix: &str) -> Vec<(String, Found)> {
    let names: Vec<BackendName> = BackendName::all()
        .into_iter()
        .filter(|n| {
            n.to_string()
                .split_once(':')
                .is_some_and(|(p, _)| p == prefix)
        })
        .collect();
    probe_names(&names)
        .into_iter()
        .map(|(name, probed)| {
            let parsed = name.parse::<BackendName>().ok();
            let impossible = parsed.and_then(|b| b.static_unavailability()).is_some();
            let not_installed = parsed.and_then(|b| b.missing_file());
            let found = match (probed, not_installed) {
                _ if impossible => Found::Impossible,
                (Ok(Probed::Runs), _) => Found::Runs,
                (Ok(Probed::RunsNothing(why)), _) => Found::RunsNothing(why),
                (Err(_), Some((file, install))) => {
                    Found::Absent(format!("{} not found; `{install}`", file.display()))
                }
                (Err(why), None) => Found::Missing(why),
            };
            (name, found)
        })
        .collect()
}

/// What to do when a GL backend cannot start: install Mesa's drivers (the Debian packages).
pub const MESA_HINT: &str = "the GL backends need Mesa's drivers: apt-get install -y libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers";

/// [`MESA_HINT`] for a GL backend name without a library directory (`egl@<lib-dir>:...` loads a
/// libEGL of its own, which Mesa's packages do not provide).
pub fn missing_hint(name: &str) -> Option<&'static str> {
    matches!(libdir::split_lib_dir(name), Ok((None, _))).then_some(MESA_HINT)
}

/// What the probe of a backend that starts found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Probed {
    /// The context starts and exposes a spec its kind implements.
    Runs,
    /// The context starts but exposes none of the specs its kind implements (why): every case it
    /// would be sent is a Skip, so a default run leaves it out as not applicable.
    RunsNothing(String),
}

/// Longest a probe child may take (context creation on zink starts a Vulkan device).
const PROBE_TIMEOUT: Duration = Duration::from_secs(60);

/// Every backend name with what its probe found or the reason it cannot run here. Probes run in
/// parallel, one child each (`gl-worker --probe`): the child creates the context, checks
/// GL_RENDERER names the driver, and prints one line; a crash is reported with its signal.
pub fn probe_report() -> Vec<(String, Result<Probed, String>)> {
    probe_names(&BackendName::all())
}

/// [`probe_report`] of some backend names, in their order.
fn probe_names(names: &[BackendName]) -> Vec<(String, Result<Probed, String>)> {
    let mut running = Vec::new();
    let mut out: Vec<(String, Result<Probed, String>)> = Vec::new();
    for &name in names {
        let key = name.to_string();
        if let Some(why) = name.static_unavailability() {
            out.push((key, Err(why)));
            continue;
        }
        match worker_command(&key) {
            Err(e) => out.push((key, Err(e.to_string()))),
            Ok(wc) => {
                let mut c = wc.to_command();
                c.arg("--probe")
                    .stdin(Stdio::null())
                    .stdout(Stdio::piped())
                    .stderr(Stdio::piped());
                match c.spawn() {
                    Ok(child) => running.push((key, child)),
                    Err(e) => out.push((
                        key,
                        Err(format!("cannot start {}: {e}", wc.program.display())),
                    )),
                }
            }
        }
    }
    let start = Instant::now();
    for (key, mut child) in running {
        let res = loop {
            match child.try_wait() {
                Ok(Some(_)) => break probe_result(child),
                Ok(None) if start.elapsed() > PROBE_TIMEOUT => {
                    let _ = child.kill();
                    let _ = child.wait();
                    break Err(format!(
                        "probe timed out after {}s",
                        PROBE_TIMEOUT.as_secs()
                    ));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(20)),
                Err(e) => break Err(e.to_string()),
            }
        };
        out.push((key, res));
    }
    let order: Vec<String> = names.iter().map(|b| b.to_string()).collect();
    out.sort_by_key(|(k, _)| order.iter().position(|o| o == k));
    out
}

fn probe_result(child: std::process::Child) -> Result<Probed, String> {
    let o = child.wait_with_output().map_err(|e| e.to_string())?;
    let stdout = String::from_utf8_lossy(&o.stdout);
    let line = stdout
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("")
        .to_string();
    if o.status.success() && line.starts_with("ok") {
        return Ok(Probed::Runs);
    }
    if let Some(why) = line
        .strip_prefix("nothing: ")
        .filter(|_| o.status.success())
    {
        return Ok(Probed::RunsNothing(why.to_string()));
    }
    if let Some(msg) = line.strip_prefix("unavailable: ") {
        return Err(msg.to_string());
    }
    use std::os::unix::process::ExitStatusExt;
    let how = match o.status.signal() {
        Some(sig) => format!("worker killed by signal {sig} while creating the context"),
        None => format!("worker exited with {}", o.status),
    };
    let stderr = String::from_utf8_lossy(&o.stderr);
    let tail: Vec<&str> = stderr.lines().rev().take(3).collect();
    Err(format!(
        "{how}{}",
        if tail.is_empty() {
            String::new()
        } else {
            format!(
                ": {}",
                tail.into_iter().rev().collect::<Vec<_>>().join(" | ")
            )
        }
    ))
}
