//! The WebGPU worker: starts the browser, loads a page with WebGPU, asks for the adapter of its
//! variant and a device, declares what it runs (its hello), and answers batches through the
//! plan's protocol loop ([`shadowcheck_plan::serve::serve`]): each lookup planned on the `wgsl`
//! path, a batch's lookups drawn in as few page jobs as [`job`] allows, each one round trip.

use crate::job::{self, DeviceCaps, PageAnswer};
use crate::launch::Variant;
use crate::WebgpuError;
use serde::Deserialize;
use serde_json::{json, Value};
use shadowcheck_model::{ApiPath, Case, Format, Spec, Target};
use shadowcheck_plan::serve::{self, Serve};
use shadowcheck_plan::shaders::wgsl::TEXEL_WRITER;
use shadowcheck_plan::{sweep, Answer};
use shadowcheck_protocol::{Capabilities, Hello, PROTOCOL_VERSION};
use shadowcheck_webgl::browser::Browser;
use std::time::{Duration, Instant};

/// The page script (evaluated once per browser).
const PAGE_JS: &str = include_str!("page.js");

/// The page the script runs in: a file in the browser's profile folder (a file:// URL is a
/// secure context, WebGPU "navigator.gpu" is `[SecureContext]`; about:blank is not one).
const PAGE_FILE: &str = "shadowcheck-webgpu.html";
const PAGE_HTML: &str = "<!doctype html><meta charset=utf-8><title>shadowcheck webgpu</title>\n";

/// How long the page has to load after `Page.navigate`.
const LOAD_TIMEOUT: Duration = Duration::from_secs(20);

/// Environment variable of the worker's test faults (the runner's tests): `invalid-sampler`
/// (every batch's samplers get lodMinClamp -1, a validation error: every lookup of it must fail
/// quoting the message) or `destroy-device` (GPUDevice.destroy() after each submission: the
/// worker ends, its cases are re-run in a fresh browser and end as Crash).
pub const TEST_FAULT_ENV: &str = "SHADOWCHECK_WEBGPU_TEST_FAULT";

/// What `shadowcheck.init()` answers.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct AdapterInfo {
    #[serde(default)]
    pub error: Option<String>,
    #[serde(default)]
    pub vendor: String,
    #[serde(default)]
    pub architecture: String,
    #[serde(default)]
    pub device: String,
    #[serde(default)]
    pub description: String,
    #[serde(default)]
    pub is_fallback_adapter: bool,
    /// The device's features.
    #[serde(default)]
    pub features: Vec<String>,
    #[serde(default, rename = "maxTextureDimension2D")]
    pub max_texture_dimension_2d: u32,
    #[serde(default)]
    pub max_texture_array_layers: u32,
}

/// A browser with the page loaded and a device made.
pub struct WebgpuWorker {
    pub variant: Variant,
    browser: Browser,
    pub adapter: AdapterInfo,
    caps: Capabilities,
    device: DeviceCaps,
    fault: Option<String>,
    /// Lookups drawn so far, and page jobs.
    drawn: usize,
    jobs: usize,
}

/// The error that ends the protocol loop when the implementation is gone (the browser, the
/// page's renderer, or the device): the cases in flight get no answer, so the runner's crash
/// handling decides them (runner/PROTOCOL.md, "Failures").
fn gone(e: WebgpuError) -> std::io::Error {
    std::io::Error::other(format!(
        "{e}; the cases in flight are not answered (nothing read from a lost device is an observation)"
    ))
}

/// Evaluates `expression` in the page and awaits its promise (Runtime.evaluate with
/// awaitPromise); a thrown exception is [`WebgpuError::Page`].
fn evaluate(browser: &mut Browser, expression: &str) -> Result<Value, WebgpuError> {
    let r = browser.call(
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
        return Err(WebgpuError::Page(text.to_string()));
    }
    Ok(r.pointer("/result/value").cloned().unwrap_or(Value::Null))
}

/// `path` as a file:// URL (bytes outside the unreserved set percent-encoded).
fn file_url(path: &std::path::Path) -> String {
    let mut url = "file://".to_string();
    for b in path.to_string_lossy().bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
            url.push(b as char);
        } else {
            url.push_str(&format!("%{b:02X}"));
        }
    }
    url
}

/// Navigates the browser's page to a file:// page and waits until it has loaded.
fn load_page(browser: &mut Browser) -> Result<(), WebgpuError> {
    let file = browser.profile().join(PAGE_FILE);
    std::fs::write(&file, PAGE_HTML)
        .map_err(|e| WebgpuError::Page(format!("writing {}: {e}", file.display())))?;
    let url = file_url(&file);
    browser.call("Page.navigate", json!({ "url": url }), true)?;
    let deadline = Instant::now() + LOAD_TIMEOUT;
    loop {
        let v = browser.evaluate("[location.href, document.readyState]")?;
        if v[0].as_str() == Some(url.as_str()) && v[1].as_str() == Some("complete") {
            return Ok(());
        }
        if Instant::now() > deadline {
            return Err(WebgpuError::Page(format!(
                "{url} did not load within {} s (the page is at {v})",
                LOAD_TIMEOUT.as_secs()
            )));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The capabilities of a device: spec `webgpu`, path `wgsl`; the targets of WGSL's depth
/// textures (cube arrays in core only), the five depth formats (depth32float-stencil8 only with
/// its feature: without it its cases are Skip with that reason, decided per case), and shadow
/// gathers (textureGatherCompare). No LOD bias, border, swizzle, stencil aspect or sampler-object
/// state: WebGPU has none of them.
pub fn capabilities(device: &DeviceCaps) -> Capabilities {
    let mut targets = vec![Target::T2d, Target::Cube, Target::T2dArray];
    if device.cube_array {
        targets.push(Target::CubeArray);
    }
    let formats = [
        Format::D16,
        Format::D24,
        Format::D24S8,
        Format::D32f,
        Format::D32fS8,
    ];
    Capabilities {
        specs: Some(vec![Spec::WebGpu.key().to_string()]),
        api: Some(vec![ApiPath::Wgsl.key().to_string()]),
        targets: Some(targets.iter().map(|t| t.key().to_string()).collect()),
        formats: Some(formats.iter().map(|f| f.key().to_string()).collect()),
        features: Some(vec!["gather".to_string()]),
        extensions: vec![],
    }
}

impl WebgpuWorker {
    /// Starts the browser of `variant`, loads the page and makes the device.
    pub fn start(variant: Variant) -> Result<WebgpuWorker, WebgpuError> {
        let fault = std::env::var(TEST_FAULT_ENV).ok().filter(|f| !f.is_empty());
        if let Some(f) = &fault {
            if !["invalid-sampler", "destroy-device"].contains(&f.as_str()) {
                return Err(WebgpuError::Page(format!(
                    "{TEST_FAULT_ENV}={f}: expected invalid-sampler or destroy-device"
                )));
            }
        }
        let mut browser = Browser::start(&variant.launch())?;
        load_page(&mut browser)?;
        browser.evaluate(PAGE_JS)?;
        let opts = json!({"featureLevel": variant.feature_level(), "writer": TEXEL_WRITER});
        let v = evaluate(&mut browser, &format!("shadowcheck.init({opts})"))?;
        let adapter: AdapterInfo = serde_json::from_value(v.clone())
            .map_err(|e| WebgpuError::Page(format!("init answered {v}: {e}")))?;
        if let Some(e) = &adapter.error {
            return Err(WebgpuError::Adapter(e.clone()));
        }
        let has = |f: &str| adapter.features.iter().any(|x| x == f);
        let device = DeviceCaps {
            d32fs8: has("depth32float-stencil8"),
            cube_array: has("core-features-and-limits"),
            max_dimension: adapter.max_texture_dimension_2d,
            max_layers: adapter.max_texture_array_layers,
        };
        let caps = capabilities(&device);
        Ok(WebgpuWorker {
            variant,
            browser,
            adapter,
            caps,
            device,
            fault,
            drawn: 0,
            jobs: 0,
        })
    }

    /// E.g. `webgpu:chromium (google swiftshader, device 0xc0de, SwiftShader Device (Subzero),
    /// fallback adapter; features depth32float-stencil8 ...; maxTextureDimension2D 8192,
    /// maxTextureArrayLayers 256; Chrome/156.0.8078.108)`.
    pub fn display_name(&self) -> String {
        let a = &self.adapter;
        let mut adapter: Vec<String> = vec![];
        let who = format!("{} {}", a.vendor, a.architecture);
        if !who.trim().is_empty() {
            adapter.push(who.trim().to_string());
        }
        if !a.device.is_empty() {
            adapter.push(format!("device {}", a.device));
        }
        if !a.description.is_empty() {
            adapter.push(a.description.clone());
        }
        if a.is_fallback_adapter {
            adapter.push("fallback adapter".into());
        }
        if !self.device.cube_array {
            adapter.push("compatibility mode".into());
        }
        let features = if a.features.is_empty() {
            "none".to_string()
        } else {
            a.features.join(" ")
        };
        format!(
            "{} ({}; features {features}; maxTextureDimension2D {}, maxTextureArrayLayers {}; {})",
            self.variant.name(),
            adapter.join(", "),
            a.max_texture_dimension_2d,
            a.max_texture_array_layers,
            self.browser.product
        )
    }

    pub fn capabilities(&self) -> &Capabilities {
        &self.caps
    }

    /// Lookups drawn and page jobs run so far.
    pub fn stats(&self) -> String {
        format!(
            "webgpu-worker: {} lookups drawn in {} page jobs",
            self.drawn, self.jobs
        )
    }

    /// One answer per job (lookup): Skip where WebGPU or this device cannot express it, else
    /// what the page drew.
    fn plan_and_draw(
        &mut self,
        jobs: &[shadowcheck_plan::Job],
    ) -> std::io::Result<Vec<Option<Answer>>> {
        let (mut out, built) = job::build(jobs, &self.device);
        for b in built {
            let arg = serde_json::to_string(&b.page).map_err(std::io::Error::other)?;
            let opts = json!({ "fault": self.fault });
            let v = match evaluate(
                &mut self.browser,
                &format!("shadowcheck.run({arg}, {opts})"),
            ) {
                Ok(v) => v,
                // The page threw outside its error scopes: every lookup of the job answers with
                // the message.
                Err(WebgpuError::Page(msg)) => json!({ "errors": [format!("page: {msg}")] }),
                Err(e) => return Err(gone(e)),
            };
            let page: PageAnswer = serde_json::from_value(v)
                .map_err(|e| std::io::Error::other(format!("page answer: {e}")))?;
            if let Some(why) = page.lost {
                return Err(gone(WebgpuError::DeviceLost(format!(
                    "{why}; while drawing a batch of {} lookups on {} textures",
                    b.page.slots,
                    b.page.textures.len()
                ))));
            }
            self.jobs += 1;
            self.drawn += b.page.slots;
            for (j, a) in job::answers(b, jobs, page) {
                if let Some(slot) = out.get_mut(j) {
                    *slot = Some(a);
                }
            }
        }
        Ok(out)
    }
}

impl Serve for WebgpuWorker {
    fn hello(&self) -> Hello {
        Hello {
            sweeps: false,
            protocol: PROTOCOL_VERSION,
            name: Some(self.display_name()),
            capabilities: self.caps.clone(),
            wants_expect: false,
        }
    }

    fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
        // Admission: the declared capabilities decide, as the runner's did before sending.
        let serve::Admission {
            runnable,
            early,
            left_out,
        } = serve::admit(&self.caps, cases);
        let jobs = sweep::jobs(&runnable);
        let answers = self.plan_and_draw(&jobs)?;
        Ok(serve::assemble(early, left_out, &jobs, answers))
    }
}

/// `--probe`: start the browser, the page and the device; `ok <name>` or `unavailable: <reason>`.
pub fn probe_line(variant: Variant) -> (bool, String) {
    match WebgpuWorker::start(variant) {
        Ok(w) => (true, format!("ok {}", w.display_name())),
        Err(e) => (false, format!("unavailable: {e}")),
    }
}
