//! The WebGPU reproducer of a `webgpu:*` test: `repro.html`, a plain WebGPU page with no
//! shadowcheck code, that does for one case what the WebGPU worker (shadowcheck-webgpu) does for
//! it, and `build.sh`, which runs it in headless Chromium with the backend's flags and prints what
//! the page wrote (nothing is built: the page is the program).
//!
//! What it mirrors, and from where: the adapter request (`launch::Variant`: flags, featureLevel),
//! the texture, its sampled view and the `GPUSamplerDescriptor` of `texture::describe`, the texel
//! points written through `frag_depth` (`shaders::wgsl::TEXEL_WRITER`), the lookup module of the
//! plan's `wgsl` path (`shaders::wgsl::module`) and slot 0's instance values
//! (`shaders::wgsl::instance_values`). One difference: the worker draws into a 256x256 image (slot
//! k a 2x2 quad), the reproducer into a 2x2 one (the module written for a framebuffer 2 pixels
//! wide); slot 0's quad and its pixel (0, 0) are the same pixels either way.
//!
//! A compute-stage case (`lookup.stage` `compute`) is dispatched as the worker dispatches it
//! (`webgpu/src/page.js`): the same texture, view and sampler; the worker's compute module
//! (`wgsl::module` of the compute key, entry point `cs`; its text does not depend on the image
//! width) with the buffers of `wgsl::COMPUTE_BINDINGS` (slot 0's instance values as the
//! read-only storage buffer `lookups`, the first slot 0 in a uniform `first` entry of
//! minUniformBufferOffsetAlignment bytes, `results` one vec4f); a render pass that only clears
//! the target (the worker's, which draws only fragment-stage lookups), then one compute pass with
//! one dispatch of one workgroup, and `results[0]` copied over pixel (0, 0) of the read-back.
//! No draw samples the texture before the dispatch: on SwiftShader one would change the result
//! (reports/README.md "V1").
//!
//! `build.sh` loads the page in headless Chromium with its console logged to a file, waits for the
//! page's last line (`shadowcheck-repro: end`; at most 60 s), prints the page's lines and exits 1
//! when the page's verdict is FAIL, 0 for pass or warn, 2 when the page printed no verdict (setup
//! failed).

use super::{csource, io, ReproError, Subject, BUILD_SH};
use shadowcheck_model::{ApiPath, Channel, Profile, Stage};
use shadowcheck_plan::shaders::wgsl::{self, COMPUTE_BINDINGS, INSTANCE_ATTRIBS, TEXEL_WRITER};
use shadowcheck_plan::{paths, LookupForm};
use shadowcheck_webgpu::launch::Variant;
use shadowcheck_webgpu::texture;
use std::path::Path;

/// The page.
pub const REPRO_HTML: &str = "repro.html";

/// The `key: value` lines the page prints about the implementation (`RunOutput::field`).
pub const FIELDS: [&str; 2] = ["WEBGPU_ADAPTER", "BROWSER"];

/// What "building" is: nothing; the run line is build.sh's.
pub const BUILD_LINE: &str = "nothing to build: repro.html is the program";

/// Width of the page's colour target: one 2x2 quad, slot 0's.
const FB: i32 = 2;

/// Is the browser installed (the run script starts it)?
pub fn check_browser() -> Result<(), ReproError> {
    shadowcheck_webgl::browser::chromium_exe()
        .map(|_| ())
        .map_err(|e| ReproError::BadBackend(e.to_string()))
}

/// The Debian packages: none to build, Chromium to run.
pub fn packages() -> (String, String) {
    (String::new(), "chromium".into())
}

/// The run script (build.sh): headless Chromium with the backend's flags on repro.html, its
/// console logged to a file (`--enable-logging=stderr`) until the page's last line (or 60 s);
/// prints the page's lines and exits with its verdict.
pub fn run_script(s: &Subject, v: Variant) -> String {
    browser_script(&s.test(), &s.backend.to_string(), &v.launch().flags, &[])
}

/// The run script of a page (the WebGPU and the WebGL one): headless Chromium with `flags` and
/// the environment `env` on repro.html, its console logged to a file until the page's last line
/// (or 60 s); prints the page's lines and exits with its verdict.
pub(super) fn browser_script(
    test: &str,
    backend: &str,
    flags: &[String],
    env: &[(String, String)],
) -> String {
    let flags = flags.join(" ");
    let env = if env.is_empty() {
        String::new()
    } else {
        let words: Vec<String> = env.iter().map(|(k, v)| format!("{k}={v}")).collect();
        format!("env {} ", words.join(" "))
    };
    format!(
        r#"#!/bin/sh
# shadowcheck reproducer for {test} on {backend}: runs {REPRO_HTML} in headless Chromium
# with the backend's flags and prints what the page wrote (its console lines). Debian 12:
# apt-get install -y chromium
# Exit 1: the observation is outside the accepted set; 0: inside; 2: setup failed.
cd "$(dirname "$0")" || exit 2
browser=${{SHADOWCHECK_CHROMIUM:-chromium}}
command -v "$browser" >/dev/null 2>&1 || {{ echo "chromium not found: apt-get install -y chromium" >&2; exit 2; }}
profile=$(mktemp -d)
log="$profile.log"
: >"$log"
{env}"$browser" --headless --no-sandbox {flags} --no-first-run --disable-background-networking   --disable-component-update --disable-sync --user-data-dir="$profile" --enable-logging=stderr --v=0   "file://$(pwd)/{REPRO_HTML}" 2>"$log" &
pid=$!
i=0
while [ $i -lt 600 ] && ! grep -q '"{END}"' "$log" && kill -0 $pid 2>/dev/null; do
  sleep 0.1
  i=$((i + 1))
done
kill $pid 2>/dev/null
wait $pid 2>/dev/null
text=$(sed -n 's/^.*:INFO:CONSOLE[^]]*\] "\(.*\)", source: .*$/\1/p' "$log" | grep -v -e '^{END}$' -e '^\[\.WebGL-')
rm -rf "$profile" "$log"
printf '%s\n' "$text"
case "$text" in
*"verdict:   FAIL"*) exit 1 ;;
*"verdict:"*) exit 0 ;;
*) exit 2 ;;
esac
"#,
        END = END,
    )
}

/// The page's last console line.
pub(super) const END: &str = "shadowcheck-repro: end";

/// Writes repro.html and build.sh into `dir` (created).
pub fn write_sources(s: &Subject, v: Variant, dir: &Path) -> Result<(), ReproError> {
    let page = page(s, v).map_err(ReproError::NotPlanned)?;
    std::fs::create_dir_all(dir).map_err(io(format!("creating {}", dir.display())))?;
    for (name, text) in [(REPRO_HTML, page), (BUILD_SH, run_script(s, v))] {
        std::fs::write(dir.join(name), text).map_err(io(format!("writing {name}")))?;
    }
    Ok(())
}

/// A JavaScript string literal.
pub(super) fn js(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into())
}

/// An f32 as JavaScript reads it back to the same f32 (shortest round-trip text).
pub(super) fn jf(v: f32) -> String {
    if v.is_finite() {
        format!("{v:?}")
    } else if v.is_nan() {
        "NaN".into()
    } else if v > 0.0 {
        "Infinity".into()
    } else {
        "-Infinity".into()
    }
}

/// A layout as the page's judge reads it: 'r' the result, '0'/'1' exactly, 'z' r or 0, '-'
/// unused, 'g0'..'g3' a gather component (judged by its own accepted set).
fn layout_chars(l: &[Channel; 4]) -> String {
    let c: Vec<String> = l
        .iter()
        .map(|c| match c.gather_index() {
            Some(i) => js(&format!("g{i}")),
            None => js(&csource::layout_char(*c).to_string()),
        })
        .collect();
    format!("[{}]", c.join(", "))
}

/// The expectation as JavaScript constants (the C programs' `csource::expectation`).
pub(super) fn expectation(s: &Subject) -> String {
    let e = &s.expect;
    let set = |p: Profile| -> String {
        let v: Vec<String> = e
            .accept
            .get(&p)
            .map(|a| {
                a.0.iter()
                    .map(|i| format!("[{}, {}]", i.lo, i.hi))
                    .collect()
            })
            .unwrap_or_default();
        format!("[{}]", v.join(", "))
    };
    let text = |p: Profile| {
        e.accept
            .get(&p)
            .map(|a| a.to_string())
            .unwrap_or_else(|| "(none)".into())
    };
    let mut layouts = vec![e
        .layout
        .get(&s.api)
        .map(layout_chars)
        .unwrap_or_else(|| "[\"-\", \"-\", \"-\", \"-\"]".into())];
    let mut readings = vec![js("the spec value's")];
    for o in e.other_layouts.get(&s.api).into_iter().flatten() {
        layouts.push(layout_chars(&o.layout));
        readings.push(js(&o.reading));
    }
    let spec_value = e
        .spec_value
        .map(|v| format!("r = {v}"))
        .unwrap_or_else(|| "no single value".into());
    // A gather's four comparisons, each with its own accepted set (`Expectation::gather`).
    let gather = |p: Profile| -> String {
        match &e.gather {
            Some(g) => {
                let sets: Vec<String> = g
                    .iter()
                    .map(|m| {
                        let v: Vec<String> = m
                            .get(&p)
                            .map(|a| {
                                a.0.iter()
                                    .map(|i| format!("[{}, {}]", i.lo, i.hi))
                                    .collect()
                            })
                            .unwrap_or_default();
                        format!("[{}]", v.join(", "))
                    })
                    .collect();
                format!("[{}]", sets.join(", "))
            }
            None => "null".into(),
        }
    };
    format!(
        "// Expected, from shadowcheck's oracle (`shadowcheck explain` shows the derivation). The accepted\n// set is what a conforming implementation may return for r (the `{q}` tier: outside it a \"shall\"\n// is violated); inside the `{st}` tier too is a plain pass. Layout per channel: 'r' the result,\n// '0'/'1' exactly that, 'z' r or 0, '-' not produced by this path.\nconst TEST = {test};\nconst SPEC_VALUE = {sv};\nconst ACCEPTED_TEXT = {qt};\nconst STRICT_TEXT = {stt};\nconst ACCEPTED = {acc};\nconst STRICT = {strict};\n// A gather's components (layout 'g0'..'g3'), each its own accepted set; null for other lookups.\nconst GATHER_ACCEPTED = {gacc};\nconst GATHER_STRICT = {gstrict};\n// Every reading of the layout the texts allow, the spec value's first (READINGS names each).\nconst LAYOUTS = [{layouts}];\nconst READINGS = [{readings}];\n\n",
        q = Profile::loosest(),
        st = Profile::strictest(),
        test = js(&s.test()),
        sv = js(&spec_value),
        qt = js(&text(Profile::loosest())),
        stt = js(&text(Profile::strictest())),
        acc = set(Profile::loosest()),
        strict = set(Profile::strictest()),
        gacc = gather(Profile::loosest()),
        gstrict = gather(Profile::strictest()),
        layouts = layouts.join(", "),
        readings = readings.join(", "),
    )
}

/// The page's text, or why the worker would not draw this case (it Skips it).
pub fn page(s: &Subject, v: Variant) -> Result<String, String> {
    if s.api != ApiPath::Wgsl {
        return Err(format!(
            "a WebGPU backend runs the `wgsl` path, not `{}`",
            s.api
        ));
    }
    // As the worker plans a job (`job::plan_job`).
    let plan = paths::plan_in(
        ApiPath::Wgsl,
        &s.case,
        &s.case.lookup,
        LookupForm::Auto,
        false,
    )?;
    let module = wgsl::module(&plan.key, FB)?;
    let mut points = vec![];
    let desc = texture::describe(&s.case, &mut points)?;
    let desc_json = serde_json::to_string_pretty(&desc).map_err(|e| e.to_string())?;
    let sampler_json = serde_json::to_string_pretty(&desc.sampler).map_err(|e| e.to_string())?;
    let point_rows: Vec<String> = points
        .chunks(3)
        .map(|p| format!("  {}, {}, {},", jf(p[0]), jf(p[1]), jf(p[2])))
        .collect();
    let instance: Vec<String> = wgsl::instance_values(&plan)
        .iter()
        .map(|x| jf(*x))
        .collect();
    let attributes: Vec<String> = INSTANCE_ATTRIBS
        .iter()
        .map(|(loc, f, at)| format!("[{loc}, {}, {at}]", js(f)))
        .collect();
    let bindings: Vec<String> = COMPUTE_BINDINGS
        .iter()
        .map(|(name, binding, ty)| format!("[{}, {binding}, {}]", js(name), js(ty)))
        .collect();
    // A compute-stage module (entry point `cs`) is dispatched (`webgpu_main.js`'s
    // dispatchLookup), as the worker dispatches it; a fragment-stage one drawn.
    let compute = plan.key.stage == Stage::Compute;
    let (drawn, values, attributes, bindings) = if compute {
        (
            "dispatched as one workgroup (slot 0) after a render pass that only clears the 2x2 RGBA32F\n  target to -1 (the worker's; no draw samples the texture first), its results[0] copied over\n  pixel (0, 0) of the read-back",
            "The lookup module (compute entry point `cs`) and slot 0's values (P, dx, dy, x: the\n// `lookups` storage buffer, as the worker lays out slot 0); COMPUTE_BINDINGS: its buffers'\n// [name, binding, GPUBufferBindingType] (`first`, the first slot, is 0).",
            "null".to_string(),
            format!("[{}]", bindings.join(", ")),
        )
    } else {
        (
            "drawn as slot 0's 2x2 quad into a 2x2 RGBA32F target cleared to -1",
            "The lookup module and slot 0's instance values (P, dx, dy, x) at ATTRIBUTES' locations.",
            format!("[{}]", attributes.join(", ")),
            "null".to_string(),
        )
    };
    Ok(format!(
        "<!doctype html>\n<meta charset=utf-8>\n<title>shadowcheck reproducer: {title}</title>\n<!--\n  shadowcheck reproducer: {test} on {backend}\n  Run: sh {BUILD_SH} (headless Chromium with the backend's flags), or open this file in a browser with\n  WebGPU.\n\n  Generated by `shadowcheck repro`: what shadowcheck's WebGPU worker does for this test, with no\n  shadowcheck code. Adapter: requestAdapter({{featureLevel: \"{level}\"}}). Texture: every level and\n  layer written by points whose fragments write @builtin(frag_depth) (WebGPU allows no texel copy\n  into most depth formats); the case's view and GPUSamplerDescriptor. Lookup: {how}; LOOKUP is the\n  worker's WGSL module, {drawn}.\n  Prints the adapter, the expected result (spec value and accepted set, computed by shadowcheck's\n  oracle, written here as constants) and the observed RGBA of pixel (0, 0), then the verdict.\n-->\n<pre id=\"out\"></pre>\n<script>\n\"use strict\";\n{expect}const FEATURE_LEVEL = {level_js};\n\n// The texture, its sampled view and the sampler (shadowcheck-webgpu `texture::describe`).\nconst TEXTURE = {desc_json};\nconst SAMPLER = {sampler_json};\n\n// The texel points: normalized device x, y of the texel's pixel centre, and its depth (an n-bit\n// unorm texel k as the f32 nearest to k / (2^n - 1)); TEXTURE.subresources say which points\n// write which level and layer.\nconst POINTS = new Float32Array([\n{points}\n]);\nconst WRITER = {writer};\n\n// {values}\nconst LOOKUP = {lookup};\nconst INSTANCE = new Float32Array([{instance}]);\nconst ATTRIBUTES = {attributes};\nconst COMPUTE_BINDINGS = {bindings};\n\n{main}</script>\n",
        title = html_escape(&s.test()),
        test = html_escape(&s.test()).replace("--", "- -"),
        backend = s.backend,
        level = v.feature_level(),
        level_js = js(v.feature_level()),
        how = plan.note,
        expect = expectation(s),
        points = point_rows.join("\n"),
        writer = js(TEXEL_WRITER),
        lookup = js(&module),
        instance = instance.join(", "),
        attributes = attributes,
        bindings = bindings,
        drawn = drawn,
        values = values,
        main = MAIN,
    ))
}

pub(super) fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Adapter, device, texture, lookup, read-back, verdict: the fixed part of the page (the verdict
/// and the printing shared with the WebGL page, `page_verdict.js`, first).
const MAIN: &str = concat!(
    include_str!("page_verdict.js"),
    include_str!("webgpu_main.js")
);

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2x2x2 D16 2D-array case, LEQUAL NEAREST, layer 1, offset (1, 0).
    const CASE: &str = r#"{"id":"webgpu/unit","spec":"webgpu","api":["wgsl"],"texture":{"target":"2darray","format":"d16","levels":[{"width":2,"height":2,"layers":2,"depth":{"unorm":[0,1,2,3,4,5,6,7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0.0,0.0,0.0,0.0],"min_lod":-1000.0,"max_lod":1000.0,"lod_bias":0.0},"lookup":{"coord":[0.25,0.75,1.0,1.0],"dref":0.5,"offset":[1,0,0]}}"#;

    fn subject() -> Subject {
        let case: shadowcheck_model::Case = serde_json::from_str(CASE).expect("case");
        let expect = crate::verdict::oracle_evaluate(&case)
            .expect("the oracle evaluates the case")
            .expect;
        Subject {
            backend: super::super::Backend::Webgpu(Variant::Core),
            expect,
            case,
            api: ApiPath::Wgsl,
            steps: vec![],
            explain: String::new(),
            fixture: "f.json".into(),
            lib_dir: None,
        }
    }

    /// A compute-stage case: the page holds the worker's compute module (the text the worker
    /// builds for its 256-wide image: the compute module does not depend on the width), slot 0's
    /// values as the `lookups` storage buffer, the worker's buffer bindings, and is dispatched,
    /// not drawn; the fragment page is not.
    #[test]
    fn a_compute_stage_case_is_dispatched_with_the_workers_module() {
        let mut s = subject();
        s.case.lookup.stage = Stage::Compute;
        let p = page(&s, Variant::Core).expect("a page for a compute-stage case");
        let plan = paths::plan_in(
            ApiPath::Wgsl,
            &s.case,
            &s.case.lookup,
            LookupForm::Auto,
            false,
        )
        .expect("plan");
        let worker = wgsl::module(&plan.key, shadowcheck_plan::layout::FB_SIZE).expect("module");
        assert!(worker.contains("@compute @workgroup_size(1)"), "{worker}");
        assert!(
            p.contains(&format!("const LOOKUP = {};", js(&worker))),
            "{p}"
        );
        let values: Vec<String> = wgsl::instance_values(&plan)
            .iter()
            .map(|x| jf(*x))
            .collect();
        assert!(p.contains(&format!(
            "const INSTANCE = new Float32Array([{}]);",
            values.join(", ")
        )));
        assert!(p.contains("const ATTRIBUTES = null;"), "{p}");
        assert!(
            p.contains("const COMPUTE_BINDINGS = [[\"lookups\", 2, \"read-only-storage\"], [\"results\", 3, \"storage\"], [\"first\", 4, \"uniform\"]];"),
            "{p}"
        );
        assert!(p.contains("textureSampleCompareLevel(t, s, p.xy, i32(v.p.z), p.w, vec2i(1, 0))"));
        assert!(p.contains("dispatched as one workgroup (slot 0)"), "{p}");
        // The fixed part: one dispatch, no draw of the lookup before it.
        assert!(p.contains("cpass.dispatchWorkgroups(1);"));
        assert!(p.contains("else dispatchLookup(device, enc, tex, read);"));
        let f = page(&subject(), Variant::Core).expect("fragment page");
        assert!(f.contains("const COMPUTE_BINDINGS = null;"), "{f}");
        assert!(
            f.contains("const ATTRIBUTES = [[0, \"float32x4\", 0], "),
            "{f}"
        );
        assert!(!f.contains("@compute"));
    }

    #[test]
    fn the_page_holds_the_workers_module_texture_and_sampler() {
        let s = subject();
        let p = page(&s, Variant::Core).expect("page");
        assert!(p.contains("textureSampleCompareLevel(t, s, p.xy, i32(v.p.z), p.w, vec2i(1, 0))"));
        assert!(p.contains("\"view\": \"2d-array\""), "{p}");
        assert!(p.contains("\"compare\": \"less-equal\""), "{p}");
        assert!(p.contains("const FEATURE_LEVEL = \"core\";"));
        assert!(p.contains("frag_depth"));
        // Two layers of 2x2 texels: eight points.
        assert_eq!(p.matches("\n  -0.5, 0.5, ").count(), 2, "{p}");
        assert_eq!(p.matches("\n  0.5, -0.5, ").count(), 2, "{p}");
        let sh = run_script(&s, Variant::Compat);
        assert!(sh.contains("--use-webgpu-adapter=opengles"));
        assert!(
            sh.contains("\"file://$(pwd)/repro.html\" 2>\"$log\" &"),
            "{sh}"
        );
        assert!(p.contains(END));
        let mut bad = s.clone();
        bad.case.lookup.bias = 1.0;
        assert!(page(&bad, Variant::Core).unwrap_err().contains("bias"));
    }
}
