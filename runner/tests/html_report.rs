//! Must show: `shadowcheck report` turns real runs into a self-contained HTML page that a browser
//! renders with its matrix. The results are made here: `soft:gl46` over the GL 4.6 2D D16/D24
//! fixture cases (all pass) and a `mock:` backend scripted to fail every LEQUAL case and warn on
//! LINEAR GEQUAL ones, so the matrix has pass, warn and fail cells. The page is then opened in
//! headless Chromium (Debian's `chromium` package): a screenshot must not be blank and must show
//! the red fail cells, and the DOM must hold the matrix table with cells linking to details.
//!
//! Without Chromium the browser part is skipped with a loud message, except under CI=true, where
//! it fails (`.ci/run` installs the package).

mod common;
use common::*;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

const CASES: &str = "^gl46/2d/d(16|24)/";
const MOCK: &str = "mock:fail=/lequal/,warn=/linear/gequal/";

/// Runs the two backends into `tmp/soft` and `tmp/mock`, then the report into `tmp/report`.
fn make_report(tmp: &Path) -> PathBuf {
    let root = workspace();
    assert!(
        root.join("cases/fixtures").is_dir(),
        "cases/fixtures is missing: generate it with `shadowcheck gen`"
    );
    let soft = tmp.join("soft");
    let r = Run::of(
        bin()
            .current_dir(&root)
            .args([
                "run",
                "--backend",
                "soft:gl46",
                "--cases",
                CASES,
                "--out",
                soft.to_str().unwrap(),
            ])
            .output()
            .unwrap(),
    );
    // Whether soft passes is soft_fixtures.rs's business; here it only has to produce results.
    assert!(
        matches!(r.code, 0 | 100),
        "soft:gl46 run: {}{}",
        r.stdout,
        r.stderr
    );
    let mock = tmp.join("mock");
    let r = Run::of(
        bin()
            .current_dir(&root)
            .args([
                "run",
                "--backend",
                MOCK,
                "--no-rerun",
                "--cases",
                CASES,
                "--out",
                mock.to_str().unwrap(),
            ])
            .output()
            .unwrap(),
    );
    assert_eq!(
        r.code, 100,
        "the mock's failures are regressions: {}{}",
        r.stdout, r.stderr
    );
    let out = tmp.join("report");
    // A directory and a results file, as the command accepts both.
    let r = Run::of(
        bin()
            .current_dir(&root)
            .args([
                "report",
                soft.to_str().unwrap(),
                mock.join("results.jsonl").to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ])
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 0, "report: {}{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("on 2 backends"), "{}", r.stdout);
    out.join("index.html")
}

#[test]
fn report_is_self_contained_and_renders_its_matrix_in_headless_chromium() {
    let tmp = tmpdir("html-report");
    let page = make_report(&tmp);
    let html = std::fs::read_to_string(&page).unwrap();

    // Self-contained: no reference to anything outside the file (the SVG namespace is a name, not a fetch).
    let outside = html.matches("http://").count() + html.matches("https://").count();
    assert_eq!(
        outside,
        html.matches("xmlns=\"http://www.w3.org/2000/svg\"").count(),
        "only SVG namespaces may name a URL"
    );
    for tag in ["<img", "<link", "<iframe", "src=", "@import", "url("] {
        assert!(
            !html.contains(tag),
            "external asset construct `{tag}` in the page"
        );
    }
    // The parts: summary per backend, the matrix with a failing cell linking to its details,
    // heatmaps and acceptance plots for the compare funcs.
    assert!(html.contains("<table id=\"summary\""));
    assert!(html.contains("<table id=\"matrix\""));
    assert!(
        html.contains("<td class=f><a href=\"#d"),
        "a fail cell links to its details"
    );
    assert!(
        html.contains("<td class=w><a href=\"#d"),
        "a warn cell links to its details"
    );
    assert!(
        html.contains("shadowcheck run --backend"),
        "details carry the re-run command"
    );
    assert!(html.contains("class=\"heatmap\"") && html.contains("class=\"plot\""));
    assert!(html.contains("id=\"func-lequal\""));
    assert!(
        html.len() < 5 << 20,
        "a thousand cases on two backends stay well under 5 MB ({} bytes)",
        html.len()
    );

    let Some(chromium) = find_chromium() else {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("CI=true but no `chromium` on PATH: .ci/run must `apt-get install -y chromium`");
        }
        // Straight to the stderr handle: libtest captures eprintln!, which would hide the skip.
        use std::io::Write as _;
        let _ = writeln!(
            std::io::stderr(),
            "\n*** SKIPPED the headless-Chromium half of {}: `chromium` is not installed (apt-get install -y chromium). ***\n",
            module_path!()
        );
        return;
    };
    let url = format!("file://{}", page.display());
    let shot = tmp.join("shot.png");
    let (code, _) = chromium_run(
        &chromium,
        &tmp.join("profile-shot"),
        &[
            &format!("--screenshot={}", shot.display()),
            "--window-size=1280,2000",
            &url,
        ],
    );
    assert_eq!(code, Some(0), "chromium --screenshot failed");
    let (w, h, rgb) = decode_png(&shot);
    assert_eq!((w, h), (1280, 2000));
    let pixels = rgb.len() / 3;
    let mut colours = std::collections::HashSet::new();
    let (mut non_white, mut fail_red) = (0usize, 0usize);
    for p in rgb.chunks_exact(3) {
        colours.insert((p[0], p[1], p[2]));
        if p.iter().any(|&c| c < 240) {
            non_white += 1;
        }
        // The matrix's fail cells (#f4a3a3), give or take anti-aliasing.
        if p[0].abs_diff(0xf4) < 6 && p[1].abs_diff(0xa3) < 6 && p[2].abs_diff(0xa3) < 6 {
            fail_red += 1;
        }
    }
    assert!(
        colours.len() > 50,
        "a rendered page has text, tables and pictures: {} colours",
        colours.len()
    );
    assert!(
        non_white * 20 > pixels,
        "more than 5% of the screenshot is not white: {non_white} of {pixels}"
    );
    assert!(
        fail_red > 2000,
        "the matrix's fail cells are visible: {fail_red} pixels"
    );

    // The DOM after the page's script ran: the matrix table with its rows and linked cells.
    let (code, dom) = chromium_run(&chromium, &tmp.join("profile-dom"), &["--dump-dom", &url]);
    assert_eq!(code, Some(0), "chromium --dump-dom failed");
    assert!(
        dom.contains("<table id=\"matrix\""),
        "matrix table in the DOM"
    );
    let fail_cells = dom.matches("<td class=\"f\"><a href=\"#d").count();
    assert!(
        fail_cells >= 2,
        "fail cells (D16 and D24 LEQUAL rows at least) in the DOM: {fail_cells}"
    );
    assert!(
        dom.contains("soft:gl46") && dom.contains(MOCK),
        "one column per backend"
    );
    let _ = std::fs::remove_dir_all(&tmp);
}

fn find_chromium() -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    for dir in std::env::split_paths(&path) {
        for name in ["chromium", "chromium-browser"] {
            let p = dir.join(name);
            if p.is_file() {
                return Some(p);
            }
        }
    }
    None
}

/// Runs headless Chromium with a fresh profile and no network-facing background work; returns
/// the exit code (None if it had to be killed after two minutes) and stdout.
fn chromium_run(chromium: &Path, profile: &Path, args: &[&str]) -> (Option<i32>, String) {
    let _ = std::fs::remove_dir_all(profile);
    std::fs::create_dir_all(profile).unwrap();
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let start = Instant::now();
    let code = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st.code();
        }
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    (code, reader.join().unwrap())
}

/// Width, height and 8-bit RGB pixels of a PNG.
fn decode_png(path: &Path) -> (u32, u32, Vec<u8>) {
    let mut dec = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let n = info.color_type.samples();
    let rgb: Vec<u8> = buf[..info.buffer_size()]
        .chunks_exact(n)
        .flat_map(|p| match n {
            1 | 2 => [p[0], p[0], p[0]],
            _ => [p[0], p[1], p[2]],
        })
        .collect();
    (info.width, info.height, rgb)
}
