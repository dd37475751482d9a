//! Headless Chromium driven over the Chrome DevTools Protocol on `--remote-debugging-pipe`: the
//! browser reads requests on its fd 3 and writes answers and events on its fd 4, each a JSON
//! object terminated by a NUL byte. One page (about:blank) is attached in flat mode and scripts
//! run in it with `Runtime.evaluate`.

use super::WebglError;
use command_fds::{CommandFdExt, FdMapping};
use nix::fcntl::OFlag;
use serde_json::{json, Value};
use std::io::{Read, Write};
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};

/// Environment variable naming the browser executable (default: `chromium` on PATH).
pub const CHROMIUM_ENV: &str = "SHADOWCHECK_CHROMIUM";

/// The command that installs the browser on Debian.
pub const INSTALL: &str = "apt-get install -y chromium";

/// Flags of every browser start. WebGL 2.0 runs on ANGLE's Vulkan back end over SwiftShader (the
/// same texture unit on every machine, GPU or not; `--disable-gpu` keeps a host GPU out and does
/// not disable WebGL when SwiftShader is allowed). The machine may have no network: no background
/// networking, component updates, sync or QUIC, and a fresh profile.
pub const FLAGS: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-gpu",
    "--remote-debugging-pipe",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--mute-audio",
];

/// The browser executable: `$SHADOWCHECK_CHROMIUM`, else the first of `chromium`,
/// `chromium-browser` on PATH.
pub fn chromium_exe() -> Result<PathBuf, WebglError> {
    if let Some(p) = std::env::var_os(CHROMIUM_ENV) {
        let p = PathBuf::from(p);
        if !p.is_file() {
            return Err(WebglError::NoBrowser(format!(
                "{CHROMIUM_ENV}={} is not a file (unset it to use `chromium` on PATH; install that with `{INSTALL}`)",
                p.display()
            )));
        }
        return Ok(p);
    }
    let path = std::env::var_os("PATH").unwrap_or_default();
    for dir in std::env::split_paths(&path) {
        for name in ["chromium", "chromium-browser"] {
            let cand = dir.join(name);
            if cand.is_file() {
                return Ok(cand);
            }
        }
    }
    Err(WebglError::NoBrowser(format!(
        "chromium not found on PATH (set {CHROMIUM_ENV} to its path); install it with `{INSTALL}`"
    )))
}

/// A running browser and its DevTools pipe, with one attached page.
pub struct Browser {
    child: Child,
    to_browser: std::fs::File,
    from_browser: std::fs::File,
    buf: Vec<u8>,
    next_id: u64,
    session: String,
    /// `Browser.getVersion`'s product, e.g. `Chrome/156.0.8078.79`.
    pub product: String,
    _profile: tempfile::TempDir,
}

fn pipe() -> Result<(std::os::fd::OwnedFd, std::os::fd::OwnedFd), WebglError> {
    nix::unistd::pipe2(OFlag::O_CLOEXEC).map_err(|e| WebglError::Browser(format!("pipe: {e}")))
}

impl Browser {
    /// Starts the browser and attaches a blank page.
    pub fn start() -> Result<Browser, WebglError> {
        let exe = chromium_exe()?;
        let profile = tempfile::Builder::new()
            .prefix("shadowcheck-chromium-")
            .tempdir()
            .map_err(|e| WebglError::Browser(format!("temporary profile: {e}")))?;
        let (req_read, req_write) = pipe()?;
        let (ans_read, ans_write) = pipe()?;
        let mut cmd = Command::new(&exe);
        cmd.args(FLAGS)
            .arg(format!("--user-data-dir={}", profile.path().display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            // Chromium logs (D-Bus, GPU) go to the worker's stderr: diagnostics, never parsed.
            .stderr(Stdio::inherit());
        cmd.fd_mappings(vec![
            FdMapping {
                parent_fd: req_read,
                child_fd: 3,
            },
            FdMapping {
                parent_fd: ans_write,
                child_fd: 4,
            },
        ])
        .map_err(|e| WebglError::Browser(format!("fd mapping: {e}")))?;
        // SAFETY: prctl is async-signal-safe; the closure allocates nothing.
        unsafe {
            cmd.pre_exec(|| {
                // The browser dies with its worker (a worker killed on a timeout takes it along).
                if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        let child = cmd
            .spawn()
            .map_err(|e| WebglError::NoBrowser(format!("cannot start {}: {e}", exe.display())))?;
        // The parent's copies of the child's ends were moved into the Command and are closed
        // with it, so a browser that exits gives end of file here.
        drop(cmd);
        let mut b = Browser {
            child,
            to_browser: std::fs::File::from(req_write),
            from_browser: std::fs::File::from(ans_read),
            buf: Vec::new(),
            next_id: 0,
            session: String::new(),
            product: String::new(),
            _profile: profile,
        };
        let v = b.call("Browser.getVersion", json!({}), false)?;
        b.product = v["product"].as_str().unwrap_or("").to_string();
        let t = b.call("Target.createTarget", json!({"url": "about:blank"}), false)?;
        let target = t["targetId"]
            .as_str()
            .ok_or_else(|| WebglError::Browser(format!("Target.createTarget answered {t}")))?
            .to_string();
        let s = b.call(
            "Target.attachToTarget",
            json!({"targetId": target, "flatten": true}),
            false,
        )?;
        b.session = s["sessionId"]
            .as_str()
            .ok_or_else(|| WebglError::Browser(format!("Target.attachToTarget answered {s}")))?
            .to_string();
        Ok(b)
    }

    fn read_message(&mut self) -> Result<Value, WebglError> {
        loop {
            if let Some(end) = self.buf.iter().position(|&b| b == 0) {
                let msg: Vec<u8> = self.buf.drain(..=end).collect();
                return serde_json::from_slice(&msg[..end]).map_err(|e| {
                    WebglError::Browser(format!("bad DevTools message ({e}): {}", {
                        String::from_utf8_lossy(&msg[..end.min(200)])
                    }))
                });
            }
            let mut chunk = [0u8; 1 << 16];
            let n = self
                .from_browser
                .read(&mut chunk)
                .map_err(|e| WebglError::Browser(format!("reading the DevTools pipe: {e}")))?;
            if n == 0 {
                let status = self.child.try_wait().ok().flatten();
                return Err(WebglError::Browser(format!(
                    "the browser closed the DevTools pipe{}",
                    status.map(|s| format!(" ({s})")).unwrap_or_default()
                )));
            }
            self.buf.extend_from_slice(&chunk[..n]);
        }
    }

    /// Sends one DevTools command (to the page when `on_page`) and returns its `result`; events
    /// read on the way are dropped.
    pub fn call(
        &mut self,
        method: &str,
        params: Value,
        on_page: bool,
    ) -> Result<Value, WebglError> {
        self.next_id += 1;
        let id = self.next_id;
        let mut msg = json!({"id": id, "method": method, "params": params});
        if on_page {
            msg["sessionId"] = Value::String(self.session.clone());
        }
        let mut bytes =
            serde_json::to_vec(&msg).map_err(|e| WebglError::Browser(format!("{method}: {e}")))?;
        bytes.push(0);
        self.to_browser
            .write_all(&bytes)
            .and_then(|_| self.to_browser.flush())
            .map_err(|e| WebglError::Browser(format!("writing the DevTools pipe: {e}")))?;
        loop {
            let m = self.read_message()?;
            if m.get("id").and_then(Value::as_u64) != Some(id) {
                continue;
            }
            if let Some(err) = m.get("error") {
                return Err(WebglError::Browser(format!("{method}: {err}")));
            }
            return Ok(m.get("result").cloned().unwrap_or(Value::Null));
        }
    }

    /// Evaluates `expression` in the page and returns its value (JSON); a thrown exception is an
    /// error with its text.
    pub fn evaluate(&mut self, expression: &str) -> Result<Value, WebglError> {
        let r = self.call(
            "Runtime.evaluate",
            json!({"expression": expression, "returnByValue": true}),
            true,
        )?;
        if let Some(ex) = r.get("exceptionDetails") {
            let text = ex
                .pointer("/exception/description")
                .or_else(|| ex.get("text"))
                .and_then(Value::as_str)
                .unwrap_or("exception");
            return Err(WebglError::Page(text.to_string()));
        }
        Ok(r.pointer("/result/value").cloned().unwrap_or(Value::Null))
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        // Browser.close ends it cleanly; kill if it does not go within a second.
        let _ = self.call("Browser.close", json!({}), false);
        for _ in 0..50 {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
