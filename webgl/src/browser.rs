//! Headless Chromium driven over the Chrome DevTools Protocol on `--remote-debugging-pipe`: the
//! browser reads requests on its fd 3 and writes answers and events on its fd 4, each a JSON
//! object terminated by a NUL byte. One page (about:blank) is attached in flat mode and scripts
//! run in it with `Runtime.evaluate`.
//!
//! Every wait on the pipe is in slices that also watch the browser process: a browser that exits
//! (even while a child of its keeps the pipe open), whose page's renderer crashes
//! (`Inspector.targetCrashed`), or that never answers its first command is an error naming what
//! happened, with the browser's last stderr lines, never a wait without end.

use super::WebglError;
use command_fds::{CommandFdExt, FdMapping};
use nix::fcntl::OFlag;
use serde_json::{json, Value};
use std::collections::VecDeque;
use std::io::{BufRead, Read, Write};
use std::os::fd::AsFd;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Environment variable naming the browser executable (default: `chromium` on PATH).
pub const CHROMIUM_ENV: &str = "SHADOWCHECK_CHROMIUM";

/// How long a started browser has to answer its first DevTools command (`Browser.getVersion`):
/// less than the runner's 30 s for a hello, so that the runner shows this worker's reason.
pub const START_TIMEOUT: Duration = Duration::from_secs(20);

/// How long `Browser.close` has to end the browser before it is killed.
pub const CLOSE_GRACE: Duration = Duration::from_secs(2);

/// How often a wait on the DevTools pipe checks that the browser is still running.
const SLICE: Duration = Duration::from_millis(200);

/// Lines of the browser's stderr kept for an error's reason, and the most characters of each.
const TAIL_LINES: usize = 6;
const TAIL_CHARS: usize = 300;

/// The prefix of a browser profile folder in the temporary directory; the worker's pid follows.
pub const PROFILE_PREFIX: &str = "shadowcheck-chromium-";

/// The command that installs the browser on Debian.
pub const INSTALL: &str = "apt-get install -y chromium";

/// Flags of every browser start, whatever its graphics stack. The machine may have no network:
/// no background networking, component updates, sync or QUIC, and a fresh profile.
pub const COMMON_FLAGS: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--remote-debugging-pipe",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--mute-audio",
];

/// The graphics flags of `webgl:chromium`: WebGL 2.0 on ANGLE's Vulkan back end over SwiftShader
/// (the same texture unit on every machine, GPU or not; `--disable-gpu` keeps a host GPU out and
/// does not disable WebGL when SwiftShader is allowed).
pub const SWIFTSHADER_FLAGS: &[&str] = &[
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-gpu",
];

/// How one browser is started: its graphics flags (after [`COMMON_FLAGS`]) and the environment
/// variables set for it (e.g. `VK_ICD_FILENAMES` naming the Vulkan driver ANGLE or Dawn loads).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Launch {
    pub flags: Vec<String>,
    pub env: Vec<(String, String)>,
}

impl Launch {
    /// `webgl:chromium`'s start: ANGLE on SwiftShader ([`SWIFTSHADER_FLAGS`]).
    pub fn swiftshader() -> Launch {
        Launch {
            flags: SWIFTSHADER_FLAGS.iter().map(|f| f.to_string()).collect(),
            env: vec![],
        }
    }
}

impl Default for Launch {
    fn default() -> Launch {
        Launch::swiftshader()
    }
}

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
    /// Why the page is gone (its renderer process crashed, or it was detached), once known.
    page_gone: Option<String>,
    /// `Browser.getVersion`'s product, e.g. `Chrome/156.0.8078.79`.
    pub product: String,
    /// The last lines the browser wrote to stderr (each also copied to the worker's stderr).
    tail: Arc<Mutex<VecDeque<String>>>,
    profile: tempfile::TempDir,
}

fn pipe() -> Result<(std::os::fd::OwnedFd, std::os::fd::OwnedFd), WebglError> {
    nix::unistd::pipe2(OFlag::O_CLOEXEC).map_err(|e| WebglError::Browser(format!("pipe: {e}")))
}

/// Removes the profile folders under `dir` left by workers that no longer run (a worker killed
/// with SIGKILL cannot remove its own): `shadowcheck-chromium-<pid>-*` whose pid is not a running
/// process. A folder of a running process (or of one this user may not signal) is kept, as are
/// names without a pid. Returns how many were removed.
pub fn remove_stale_profiles(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let mut removed = 0;
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(PROFILE_PREFIX))
            .and_then(|rest| rest.split_once('-'))
            .and_then(|(pid, _)| pid.parse::<i32>().ok())
            .filter(|&p| p > 0)
        else {
            continue;
        };
        let gone = matches!(
            nix::sys::signal::kill(nix::unistd::Pid::from_raw(pid), None),
            Err(nix::errno::Errno::ESRCH)
        );
        if gone && std::fs::remove_dir_all(e.path()).is_ok() {
            removed += 1;
        }
    }
    removed
}

/// Copies the browser's stderr to ours line by line, keeping the last [`TAIL_LINES`] (clipped).
fn keep_tail(stderr: std::process::ChildStderr, tail: Arc<Mutex<VecDeque<String>>>) {
    std::thread::spawn(move || {
        let mut r = std::io::BufReader::new(stderr);
        let mut raw = Vec::new();
        loop {
            raw.clear();
            match r.read_until(b'\n', &mut raw) {
                Ok(0) | Err(_) => return,
                Ok(_) => {}
            }
            let line = String::from_utf8_lossy(&raw);
            let line = line.trim_end();
            eprintln!("{line}");
            let clipped: String = line.chars().take(TAIL_CHARS).collect();
            if let Ok(mut t) = tail.lock() {
                if t.len() == TAIL_LINES {
                    t.pop_front();
                }
                t.push_back(clipped);
            }
        }
    });
}

impl Browser {
    /// Starts the browser ([`chromium_exe`]) as `launch` says and attaches a blank page.
    pub fn start(launch: &Launch) -> Result<Browser, WebglError> {
        Browser::start_with(&chromium_exe()?, START_TIMEOUT, launch)
    }

    /// Starts `exe` as the browser, which must answer its first command within `start_timeout`.
    pub fn start_with(
        exe: &Path,
        start_timeout: Duration,
        launch: &Launch,
    ) -> Result<Browser, WebglError> {
        let tmp = std::env::temp_dir();
        remove_stale_profiles(&tmp);
        let profile = tempfile::Builder::new()
            .prefix(&format!("{PROFILE_PREFIX}{}-", std::process::id()))
            .tempdir_in(&tmp)
            .map_err(|e| WebglError::Browser(format!("temporary profile: {e}")))?;
        let (req_read, req_write) = pipe()?;
        let (ans_read, ans_write) = pipe()?;
        let mut cmd = Command::new(exe);
        cmd.args(COMMON_FLAGS)
            .args(&launch.flags)
            .envs(launch.env.iter().map(|(k, v)| (k, v)))
            .arg(format!("--user-data-dir={}", profile.path().display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            // Chromium's logs (D-Bus, GPU) are copied to the worker's stderr as diagnostics, never
            // parsed; the last lines go into the reason of an error.
            .stderr(Stdio::piped());
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
        let mut child = cmd
            .spawn()
            .map_err(|e| WebglError::NoBrowser(format!("cannot start {}: {e}", exe.display())))?;
        // The parent's copies of the child's ends were moved into the Command and are closed
        // with it, so a browser that exits gives end of file here (unless a child of its keeps
        // them: the waits also watch the process).
        drop(cmd);
        let tail = Arc::new(Mutex::new(VecDeque::new()));
        if let Some(stderr) = child.stderr.take() {
            keep_tail(stderr, tail.clone());
        }
        let mut b = Browser {
            child,
            to_browser: std::fs::File::from(req_write),
            from_browser: std::fs::File::from(ans_read),
            buf: Vec::new(),
            next_id: 0,
            session: String::new(),
            page_gone: None,
            product: String::new(),
            tail,
            profile,
        };
        let v = b
            .call_until(
                "Browser.getVersion",
                json!({}),
                false,
                Some(Instant::now() + start_timeout),
            )
            .map_err(|e| match e {
                WebglError::Browser(m) if m.contains("no answer within") => {
                    WebglError::Browser(format!("{} did not start: {m}", exe.display()))
                }
                e => e,
            })?;
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
        // Inspector.targetCrashed: the page's renderer process died (a command sent to the page
        // would never be answered).
        b.call("Inspector.enable", json!({}), true)?;
        Ok(b)
    }

    /// How the browser ended, or that it still runs, with its last stderr lines.
    fn state(&mut self) -> String {
        let status = match self.child.try_wait() {
            Ok(Some(s)) => s.to_string(),
            Ok(None) => "still running".to_string(),
            Err(e) => format!("status unknown: {e}"),
        };
        let tail: Vec<String> = self
            .tail
            .lock()
            .map(|t| t.iter().cloned().collect())
            .unwrap_or_default();
        if tail.is_empty() {
            format!("{status}; no stderr output")
        } else {
            format!("{status}; its last stderr lines: {}", tail.join(" | "))
        }
    }

    /// Waits for the pipe to be readable until `deadline`, in slices that check the browser.
    fn wait_readable(&mut self, deadline: Option<Instant>) -> Result<(), WebglError> {
        loop {
            let slice = match deadline {
                Some(d) => {
                    let left = d.saturating_duration_since(Instant::now());
                    if left.is_zero() {
                        return Err(WebglError::Browser(format!(
                            "no answer within the time allowed ({})",
                            self.state()
                        )));
                    }
                    left.min(SLICE)
                }
                None => SLICE,
            };
            let ms = u16::try_from(slice.as_millis()).unwrap_or(u16::MAX);
            let mut fds = [nix::poll::PollFd::new(
                self.from_browser.as_fd(),
                nix::poll::PollFlags::POLLIN,
            )];
            match nix::poll::poll(&mut fds, ms) {
                Ok(n) if n > 0 => return Ok(()),
                Ok(_) | Err(nix::errno::Errno::EINTR) => {}
                Err(e) => {
                    return Err(WebglError::Browser(format!(
                        "polling the DevTools pipe: {e}"
                    )))
                }
            }
            // Nothing to read: has the browser gone while something else keeps the pipe open?
            if let Ok(Some(_)) = self.child.try_wait() {
                return Err(WebglError::Browser(format!(
                    "the browser exited without answering ({})",
                    self.state()
                )));
            }
        }
    }

    fn read_message(&mut self, deadline: Option<Instant>) -> Result<Value, WebglError> {
        loop {
            if let Some(end) = self.buf.iter().position(|&b| b == 0) {
                let msg: Vec<u8> = self.buf.drain(..=end).collect();
                return serde_json::from_slice(&msg[..end]).map_err(|e| {
                    WebglError::Browser(format!("bad DevTools message ({e}): {}", {
                        String::from_utf8_lossy(&msg[..end.min(200)])
                    }))
                });
            }
            self.wait_readable(deadline)?;
            let mut chunk = [0u8; 1 << 16];
            let n = self
                .from_browser
                .read(&mut chunk)
                .map_err(|e| WebglError::Browser(format!("reading the DevTools pipe: {e}")))?;
            if n == 0 {
                // Give a dying browser a moment to be reaped, so its status is known.
                for _ in 0..25 {
                    if let Ok(Some(_)) = self.child.try_wait() {
                        break;
                    }
                    std::thread::sleep(Duration::from_millis(20));
                }
                return Err(WebglError::Browser(format!(
                    "the browser closed the DevTools pipe ({})",
                    self.state()
                )));
            }
            self.buf.extend_from_slice(&chunk[..n]);
        }
    }

    /// Notes an event that says the page is gone.
    fn watch(&mut self, m: &Value) {
        let method = m.get("method").and_then(Value::as_str).unwrap_or("");
        let ours = |v: Option<&Value>| v.and_then(Value::as_str) == Some(self.session.as_str());
        let gone = match method {
            "Inspector.targetCrashed" if ours(m.get("sessionId")) => {
                "the page's renderer process died (Inspector.targetCrashed)"
            }
            "Inspector.detached" if ours(m.get("sessionId")) => {
                "the page was detached (Inspector.detached)"
            }
            "Target.detachedFromTarget" if ours(m.pointer("/params/sessionId")) => {
                "the page was detached (Target.detachedFromTarget)"
            }
            _ => return,
        };
        if self.page_gone.is_none() {
            let detail = m
                .pointer("/params/reason")
                .and_then(Value::as_str)
                .map(|r| format!(": {r}"))
                .unwrap_or_default();
            self.page_gone = Some(format!("{gone}{detail}"));
        }
    }

    /// Writes one DevTools command (to the page when `on_page`); returns its id.
    fn send(&mut self, method: &str, params: Value, on_page: bool) -> Result<u64, WebglError> {
        if on_page {
            if let Some(why) = &self.page_gone {
                return Err(WebglError::Browser(format!("{method}: {why}")));
            }
        }
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
        Ok(id)
    }

    /// Sends one DevTools command (to the page when `on_page`) and returns its `result`. Events
    /// read on the way are dropped, except those that say the page is gone: then a command to
    /// the page is an error at once.
    pub fn call(
        &mut self,
        method: &str,
        params: Value,
        on_page: bool,
    ) -> Result<Value, WebglError> {
        self.call_until(method, params, on_page, None)
    }

    /// [`Browser::call`], waiting for the answer until `deadline` at most.
    fn call_until(
        &mut self,
        method: &str,
        params: Value,
        on_page: bool,
        deadline: Option<Instant>,
    ) -> Result<Value, WebglError> {
        let id = self.send(method, params, on_page)?;
        loop {
            let m = self.read_message(deadline)?;
            if m.get("id").and_then(Value::as_u64) != Some(id) {
                self.watch(&m);
                if on_page {
                    if let Some(why) = &self.page_gone {
                        return Err(WebglError::Browser(format!("{method}: {why}")));
                    }
                }
                continue;
            }
            if let Some(err) = m.get("error") {
                return Err(WebglError::Browser(format!("{method}: {err}")));
            }
            return Ok(m.get("result").cloned().unwrap_or(Value::Null));
        }
    }

    /// The browser's process id.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// The browser's profile folder (removed when the browser is dropped).
    pub fn profile(&self) -> &Path {
        self.profile.path()
    }

    /// Test fault: crashes the page's renderer process (`Page.crash`, never answered); the next
    /// command to the page meets its `Inspector.targetCrashed`.
    pub fn crash_renderer(&mut self) -> Result<(), WebglError> {
        self.send("Page.crash", json!({}), true).map(|_| ())
    }

    /// Evaluates `expression` in the page and returns its value (JSON), awaiting it when it is a
    /// promise; a thrown exception (or a rejected promise) is an error with its text.
    pub fn evaluate(&mut self, expression: &str) -> Result<Value, WebglError> {
        let r = self.call(
            "Runtime.evaluate",
            json!({"expression": expression, "returnByValue": true, "awaitPromise": true}),
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
        // Browser.close ends it cleanly; whatever it does, it is killed after CLOSE_GRACE (a
        // browser that never answers or never exits cannot hold the worker).
        let deadline = Instant::now() + CLOSE_GRACE;
        let _ = self.call_until("Browser.close", json!({}), false, Some(deadline));
        while Instant::now() < deadline {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
