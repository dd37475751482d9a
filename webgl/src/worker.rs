//! The `webgl:*` worker: starts the browser as its instance says ([`Instance`]), loads the page,
//! checks the renderer is that instance's, declares what WebGL 2.0 can run, and answers batches
//! through the plan's protocol loop ([`shadowcheck_plan::serve::serve`]).

use super::browser::Browser;
use super::instance::Instance;
use super::job;
use super::WebglError;
use serde::Deserialize;
use shadowcheck_model::{ApiPath, Case, Format, Spec, StateCase, StateObserved, Target};
use shadowcheck_plan::serve::{state_reply, Serve};
use shadowcheck_plan::{sweep, Answer, ContextApi, GlInfo, LookupForm};
use shadowcheck_protocol::{Capabilities, Hello, Reply, Support, PROTOCOL_VERSION};

/// The page script (evaluated once per browser).
const PAGE_JS: &str = include_str!("page.js");

/// Cases per `Runtime.evaluate` (one read-back each).
pub const JOB_CASES: usize = 64;

/// Targets of WebGL 2.0 (OpenGL ES 3.0): no 1D, rectangle or cube-map-array textures.
pub const TARGETS: [Target; 3] = [Target::T2d, Target::Cube, Target::T2dArray];

/// Formats whose texels WebGL 2.0 can upload from the fixture: not DEPTH_COMPONENT32 (no ES
/// format), not unsized DEPTH_COMPONENT (ES 3.0 Table 3.2 has no unsized depth format), and not
/// DEPTH32F_STENCIL8: WebGL 2.0 §3.7.6 (texImage2D/texImage3D) accepts type
/// FLOAT_32_UNSIGNED_INT_24_8_REV only with null pixels (INVALID_OPERATION otherwise). The colour
/// formats are ES 3.0 Table 3.2's (RGBA4 uploaded as UNSIGNED_SHORT_4_4_4_4).
pub const FORMATS: [Format; 9] = [
    Format::D16,
    Format::D24,
    Format::D24S8,
    Format::D32f,
    Format::R8,
    Format::Rgba8,
    Format::Rgb8,
    Format::Rgba4,
    Format::Rg8,
];

/// What `shadowcheck.init()` answers.
#[derive(Debug, Clone, Deserialize)]
pub struct PageInfo {
    #[serde(default)]
    pub error: Option<String>,
    #[serde(default)]
    pub version: String,
    #[serde(default)]
    pub glsl: String,
    #[serde(default)]
    pub renderer: String,
    #[serde(default)]
    pub vendor: String,
    #[serde(default)]
    pub extensions: Vec<String>,
    /// Extensions the page enabled (getExtension).
    #[serde(default)]
    pub enabled: Vec<String>,
}

/// Environment variable of the worker's test faults (the tests of the runner and the crate): a
/// fault made in the real browser at every page call, `lose-context` (WEBGL_lose_context's
/// loseContext() once the job's first bundle is drawn, or before a state case's call) or
/// `crash-renderer` (the page's renderer process crashed by `Page.crash` before each job).
pub const TEST_FAULT_ENV: &str = "SHADOWCHECK_WEBGL_TEST_FAULT";

/// A fault of [`TEST_FAULT_ENV`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TestFault {
    LoseContext,
    CrashRenderer,
}

impl TestFault {
    /// The fault asked for by [`TEST_FAULT_ENV`], if any.
    pub fn from_env() -> Result<Option<TestFault>, WebglError> {
        match std::env::var(TEST_FAULT_ENV).ok().as_deref() {
            None | Some("") => Ok(None),
            Some("lose-context") => Ok(Some(TestFault::LoseContext)),
            Some("crash-renderer") => Ok(Some(TestFault::CrashRenderer)),
            Some(other) => Err(WebglError::Browser(format!(
                "{TEST_FAULT_ENV}={other}: expected lose-context or crash-renderer"
            ))),
        }
    }
}

/// A browser with the page loaded.
pub struct WebglWorker {
    instance: &'static Instance,
    browser: Browser,
    pub page: PageInfo,
    info: GlInfo,
    caps: Capabilities,
    fault: Option<TestFault>,
}

/// The error that ends the protocol loop when the implementation is gone (the browser, the page's
/// renderer, or the WebGL context): the cases in flight get no answer, so the runner's crash
/// handling decides them (runner/PROTOCOL.md, "Failures"), never an observation read from it.
fn gone(e: WebglError) -> std::io::Error {
    std::io::Error::other(format!(
        "{e}; the cases in flight are not answered (nothing read from a lost context is an observation)"
    ))
}

/// The capabilities of a page that enabled `enabled` (WebGL extension names).
pub fn capabilities(enabled: &[String], extensions: &[String]) -> Capabilities {
    let stencil = enabled.iter().any(|e| e == "WEBGL_stencil_texturing");
    Capabilities {
        specs: Some(vec![Spec::Gles32.key().to_string()]),
        api: Some(vec![ApiPath::Es300.key().to_string()]),
        targets: Some(TARGETS.iter().map(|t| t.key().to_string()).collect()),
        formats: Some(FORMATS.iter().map(|f| f.key().to_string()).collect()),
        // No TEXTURE_LOD_BIAS, TEXTURE_BORDER_COLOR or CLAMP_TO_BORDER in WebGL 2.0 (ES 3.0), no
        // texture swizzle and no seamless enable (cube maps are always seamless); sampler objects
        // (WebGL 2.0 §3.7.14, createSampler / bindSampler); DEPTH_STENCIL_TEXTURE_MODE with
        // WEBGL_stencil_texturing.
        features: Some({
            let mut f = vec![
                "sampler_objects".to_string(),
                shadowcheck_protocol::TEX_PARAMETER.to_string(),
            ];
            if stencil {
                f.push("stencil_texturing".to_string());
            }
            f
        }),
        extensions: extensions.to_vec(),
    }
}

impl WebglWorker {
    /// Starts the browser as `instance` says, loads the page and creates its WebGL 2.0 context,
    /// which must be on the instance's back end and driver (its renderer string).
    pub fn start(instance: &'static Instance) -> Result<WebglWorker, WebglError> {
        let fault = TestFault::from_env()?;
        instance.installed()?;
        let mut browser = Browser::start(&(instance.launch)())?;
        browser.evaluate(PAGE_JS)?;
        let v = browser.evaluate("shadowcheck.init()")?;
        let page: PageInfo = serde_json::from_value(v.clone())
            .map_err(|e| WebglError::Page(format!("init answered {v}: {e}")))?;
        if let Some(e) = &page.error {
            return Err(WebglError::Context(e.clone()));
        }
        instance.check_renderer(&page.renderer)?;
        let info = GlInfo {
            api: ContextApi::Es3,
            es: true,
            compat: false,
            version: (3, 0),
            glsl: 300,
            renderer: page.renderer.clone(),
            version_string: page.version.clone(),
            extensions: Default::default(),
            form: LookupForm::Auto,
            version_override: false,
        };
        let caps = capabilities(&page.enabled, &page.extensions);
        Ok(WebglWorker {
            instance,
            browser,
            page,
            info,
            caps,
            fault,
        })
    }

    /// E.g. `webgl:chromium (WebGL 2.0 (OpenGL ES 3.0 Chromium); ANGLE (Google, Vulkan 1.3.0
    /// (SwiftShader Device (Subzero) ...)); Chrome/156.0.8078.79)`, or `webgl:chromium-gles
    /// (...; ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL ES 3.2); ...)`.
    pub fn display_name(&self) -> String {
        format!(
            "{} ({}; {}; {})",
            self.instance.name(),
            self.page.version,
            self.page.renderer,
            self.browser.product
        )
    }

    pub fn capabilities(&self) -> &Capabilities {
        &self.caps
    }

    /// The case as drawn (its supported paths), or why it does not run (the same decision as
    /// the runner's, [`Capabilities::support`]).
    fn admit(&self, case: &Case) -> Result<Case, String> {
        let apis = match self.caps.support(case) {
            Support::Skip(reason) | Support::NotApplicable(reason) => return Err(reason),
            Support::Run { apis, .. } => apis,
        };
        let mut drawn = case.clone();
        drawn.api = apis;
        Ok(drawn)
    }

    /// Draws up to [`JOB_CASES`] admitted cases in the page.
    fn run_job(&mut self, cases: &[Case]) -> std::io::Result<Vec<Answer>> {
        let built = job::build(&self.info, cases);
        let arg = serde_json::to_string(&built.job).map_err(std::io::Error::other)?;
        if self.fault == Some(TestFault::CrashRenderer) {
            self.browser.crash_renderer().map_err(gone)?;
        }
        let lose = self.fault == Some(TestFault::LoseContext);
        let v = match self
            .browser
            .evaluate(&format!("shadowcheck.run({arg}, {{\"lose\": {lose}}})"))
        {
            Ok(v) => v,
            // The page threw with its context intact (page.js answers a loss instead): every
            // case of the job answers with the message.
            Err(WebglError::Page(msg)) => {
                return Ok(vec![Answer::Error(format!("page: {msg}")); cases.len()])
            }
            // The browser or the page's renderer is gone: so is this worker (the runner finds
            // the case that did it).
            Err(e) => return Err(gone(e)),
        };
        if let Some(why) = v.get("lost") {
            let why = why.as_str().unwrap_or("").to_string();
            return Err(gone(WebglError::ContextLost(why)));
        }
        let page: job::PageAnswer = serde_json::from_value(v)
            .map_err(|e| std::io::Error::other(format!("page answer: {e}")))?;
        Ok(job::answers(built, cases, page))
    }
}

impl Serve for WebglWorker {
    fn hello(&self) -> Hello {
        Hello {
            sweeps: false,
            protocol: PROTOCOL_VERSION,
            name: Some(self.display_name()),
            capabilities: self.caps.clone(),
            wants_expect: false,
        }
    }

    fn answer_state(&mut self, case: &StateCase) -> std::io::Result<Reply> {
        let caps = self.caps.clone();
        let lose = self.fault == Some(TestFault::LoseContext);
        let mut failed = None;
        let reply = state_reply(&caps, None, case, |c| {
            match super::state::observe(&mut self.browser, c, lose) {
                Ok(o) => o,
                Err(e) => {
                    failed = Some(e);
                    StateObserved {
                        error: None,
                        other_error: None,
                        value: None,
                    }
                }
            }
        });
        match failed {
            // The page threw: an error answer, as for a lookup.
            Some(WebglError::Page(m)) => Ok(Reply::Error {
                case_id: case.id.clone(),
                message: format!("page: {m}"),
            }),
            // A lost context, a dead renderer or browser: no answer.
            Some(e) => Err(gone(e)),
            None => Ok(reply),
        }
    }

    fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
        // The page is sent whole cases: each sweep point as a case of its own.
        let cases = sweep::expand(cases);
        let mut answers: Vec<Option<Answer>> = Vec::with_capacity(cases.len());
        let mut runnable: Vec<Case> = Vec::new();
        for c in &cases {
            match self.admit(c) {
                Ok(d) => {
                    runnable.push(d);
                    answers.push(None);
                }
                Err(reason) => answers.push(Some(Answer::Skip(reason))),
            }
        }
        let mut drawn = Vec::with_capacity(runnable.len());
        for chunk in runnable.chunks(JOB_CASES) {
            drawn.extend(self.run_job(chunk)?);
        }
        let mut drawn = drawn.into_iter();
        Ok(answers
            .into_iter()
            .map(|a| {
                a.or_else(|| drawn.next())
                    .unwrap_or_else(|| Answer::Error("internal: missing answer".into()))
            })
            .collect())
    }
}

/// `--probe`: start the browser and the page; `ok <name>` or `unavailable: <reason>`.
pub fn probe_line(instance: &'static Instance) -> (bool, String) {
    match WebglWorker::start(instance) {
        Ok(w) => (true, format!("ok {}", w.display_name())),
        Err(e) => (false, format!("unavailable: {e}")),
    }
}
