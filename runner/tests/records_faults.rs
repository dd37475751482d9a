//! What `merge`, `summarize`, `repro --all-failures`, `--resume` and the printing subcommands do
//! with records that are not whole or not theirs, and with outputs that cannot be written: each
//! test injects one fault (a runner killed by the `mock:` worker, a results.jsonl cut or edited, a
//! results.jsonl on /dev/full, a closed stdout) and checks the exit code and what is said.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

fn s(p: &Path) -> String {
    p.display().to_string()
}

fn shadowcheck(args: &[&str]) -> Run {
    Run::of(bin().args(args).output().unwrap())
}

/// Runs `cmd` with a stdout whose reader has gone away (`| head -1` after head exited): every write
/// to it fails with EPIPE.
fn with_closed_stdout(cmd: &mut Command) -> Run {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let o = cmd.stdout(writer).output().unwrap();
    Run::of(o)
}

/// A run of `script` on the fixtures `fx` into `out` (`extra` arguments added), killed by the mock
/// worker (SIGKILL to the runner) when the first case matching `kill` arrives.
fn killed_run(script: &str, fx: &str, out: &Path, extra: &[&str], kill: &str) {
    let o = bin()
        .args(["run", "-b", script, "--fixtures", fx, "--out", &s(out)])
        .args(extra)
        .env("SHADOWCHECK_MOCK_KILL_RUNNER", kill)
        .output()
        .unwrap();
    use std::os::unix::process::ExitStatusExt;
    assert_eq!(
        o.status.signal(),
        Some(9),
        "the runner was not killed: {o:?}"
    );
}

fn copy_run(from: &Path, to: &Path) -> PathBuf {
    std::fs::create_dir_all(to).unwrap();
    std::fs::copy(from.join("results.jsonl"), to.join("results.jsonl")).unwrap();
    to.join("results.jsonl")
}

const SCRIPT: &str = "mock:fail=n=0[0-5].7";

#[test]
fn merge_refuses_a_shard_that_did_not_finish_naming_it_and_what_is_missing() {
    let (dir, fx) = cases_dir("merge-unfinished", 600);
    let s1 = dir.join("s1");
    let r = run(&[
        "-b",
        SCRIPT,
        "--fixtures",
        &fx,
        "--shard",
        "1/2",
        "--out",
        &s(&s1),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    // Shard 2's runner is killed near its end: what it finished is on disk, the rest is not.
    let s2 = dir.join("s2");
    killed_run(SCRIPT, &fx, &s2, &["--shard", "2/2"], "n=05[5-9]");
    let merged = dir.join("merged");
    let r = shadowcheck(&["merge", "-o", &s(&merged), &s(&s1), &s(&s2)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    let named = format!("{}: the run did not finish", s(&s2.join("results.jsonl")));
    assert!(r.stderr.contains(&named), "{}", r.stderr);
    assert!(r.stderr.contains("no closing record"), "{}", r.stderr);
    let written = regex::Regex::new(r"`mock:[^`]*`: (\d+) of (\d+) tests written").unwrap();
    let caps = written
        .captures(&r.stderr)
        .unwrap_or_else(|| panic!("no count of what is missing: {}", r.stderr));
    let (have, of): (usize, usize) = (caps[1].parse().unwrap(), caps[2].parse().unwrap());
    assert!(have < of, "{}", r.stderr);
    assert!(r.stderr.contains("--resume"), "{}", r.stderr);
    assert!(!merged.join("results.csv").exists(), "nothing merged");

    // Finished with --resume, the same shard merges, and every test and Fail is there.
    let r = run(&[
        "-b",
        SCRIPT,
        "--fixtures",
        &fx,
        "--shard",
        "2/2",
        "--out",
        &s(&s2),
        "--resume",
    ]);
    assert!(matches!(r.code, 0 | 100), "{}{}", r.stdout, r.stderr);
    let r = shadowcheck(&["merge", "-o", &s(&merged), &s(&s1), &s(&s2)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let rows = results(&merged);
    assert_eq!(rows.len(), 600);
    assert_eq!(rows.iter().filter(|r| r.1 == "Fail").count(), 60);

    // The finished shard with its last line cut off (killed while writing it).
    let cut = copy_run(&s2, &dir.join("s2-cut"));
    let text = std::fs::read_to_string(&cut).unwrap();
    std::fs::write(&cut, &text[..text.len() - 10]).unwrap();
    let r = shadowcheck(&["merge", "-o", &s(&dir.join("m2")), &s(&s1), &s(&cut)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains(&s(&cut)) && r.stderr.contains("last line is cut off"),
        "{}",
        r.stderr
    );

    // Fewer tests than its closing record says: a line of passing tests taken out of the middle.
    let fewer = copy_run(&s2, &dir.join("s2-fewer"));
    let mut lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.contains(r#""kind":"passed""#))
        .unwrap();
    lines.remove(at);
    std::fs::write(&fewer, lines.join("\n") + "\n").unwrap();
    let r = shadowcheck(&["merge", "-o", &s(&dir.join("m3")), &s(&s1), &s(&fewer)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains(&s(&fewer)), "{}", r.stderr);
    let caps = written
        .captures(&r.stderr)
        .unwrap_or_else(|| panic!("no count of what is missing: {}", r.stderr));
    let (left, all): (usize, usize) = (caps[1].parse().unwrap(), caps[2].parse().unwrap());
    assert!(left < all && all == of, "{}", r.stderr);

    // A schema version this build does not know is refused with the file named.
    let future = copy_run(&s1, &dir.join("s1-v99"));
    let t = std::fs::read_to_string(&future).unwrap();
    assert!(t.contains(r#""schema_version":1,"#));
    std::fs::write(
        &future,
        t.replacen(r#""schema_version":1,"#, r#""schema_version":99,"#, 1),
    )
    .unwrap();
    let r = shadowcheck(&["merge", "-o", &s(&dir.join("m4")), &s(&future), &s(&s2)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains(&s(&future)) && r.stderr.contains("schema_version 99"),
        "{}",
        r.stderr
    );
}

#[test]
fn merge_onto_a_full_device_reports_the_regressions_it_read_and_exits_100_also_96() {
    let (dir, fx) = cases_dir("merge-full", 40);
    let a = dir.join("a");
    let r = run(&["-b", SCRIPT, "--fixtures", &fx, "--out", &s(&a)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let out = dir.join("merged");
    std::fs::create_dir_all(&out).unwrap();
    std::os::unix::fs::symlink("/dev/full", out.join("results.jsonl")).unwrap();
    let r = shadowcheck(&["merge", "-o", &s(&out), &s(&a)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let last = r.stdout.lines().last().unwrap_or_default();
    assert!(
        last.contains("exit code 100 (regressions; also 96: writing")
            && last.contains("results.jsonl"),
        "{last}"
    );
    // The other reports, written beside it, hold the regressions.
    assert_eq!(
        std::fs::read_to_string(out.join("failures.csv")).unwrap(),
        std::fs::read_to_string(a.join("failures.csv")).unwrap()
    );
}

#[test]
fn resume_refuses_a_results_file_without_its_meta_line() {
    let (dir, fx) = cases_dir("resume-no-meta", 8);
    let out = dir.join("out");
    let r = run(&["-b", "mock:", "--fixtures", &fx, "--out", &s(&out)]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let file = out.join("results.jsonl");
    let text = std::fs::read_to_string(&file).unwrap();
    let rest: Vec<&str> = text
        .lines()
        .filter(|l| !l.contains(r#""kind":"meta""#))
        .collect();
    std::fs::write(&file, rest.join("\n") + "\n").unwrap();
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        &s(&out),
        "--resume",
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains(&s(&file)) && r.stderr.contains("no meta line"),
        "{}",
        r.stderr
    );
}

#[test]
fn a_closed_stdout_is_not_a_panic_for_any_printing_subcommand() {
    let (dir, fx) = cases_dir("closed-stdout", 12);
    let a = dir.join("a");
    let r = run(&["-b", SCRIPT, "--fixtures", &fx, "--out", &s(&a)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let html = dir.join("html");
    for (args, code) in [
        (vec!["report", &s(&a), "-o", &s(&html)], 0),
        (vec!["merge", "-o", &s(&dir.join("m")), &s(&a)], 100),
        (vec!["consensus", &s(&a), "--min-units", "1"], 0),
        (
            vec![
                "explain", "--spec", "gl46", "--format", "d24", "--func", "lequal", "--ref", "1.5",
                "--dt", "1.0",
            ],
            0,
        ),
        (
            vec![
                "run",
                "-b",
                SCRIPT,
                "--fixtures",
                &fx,
                "--out",
                &s(&dir.join("b")),
            ],
            100,
        ),
        (vec!["mutants", "--list"], 0),
    ] {
        let r = with_closed_stdout(bin().args(&args));
        assert!(!r.stderr.contains("panicked"), "{args:?}: {}", r.stderr);
        assert_eq!(r.code, code, "{args:?}: {}", r.stderr);
    }
    assert!(html.join("index.html").is_file());
    // `... 2>&1 | head -1` after head exited: stderr's reader is gone too. A panic would exit
    // 101; each command ends with its own code, the lines it could not write lost.
    for (args, code) in [
        (
            vec![
                "run",
                "-b",
                SCRIPT,
                "--fixtures",
                &fx,
                "--out",
                &s(&dir.join("c")),
                "-v",
            ],
            100,
        ),
        (vec!["merge", "-o", &s(&dir.join("m2")), &s(&a)], 100),
        (vec!["report", &s(&a), "-o", &s(&dir.join("html2"))], 0),
        (vec!["run", "-b", "no-such-backend"], 96),
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let err = writer.try_clone().unwrap();
        let o = bin()
            .args(&args)
            .stdout(writer)
            .stderr(err)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(code), "{args:?}");
    }
}

#[test]
fn summarize_labels_from_the_meta_line_and_refuses_a_run_that_did_not_finish() {
    let (dir, fx) = cases_dir("summarize-meta", 40);
    // A run of one backend in a folder named for another.
    let misnamed = dir.join("r-egl-llvmpipe-core");
    let r = run(&["-b", SCRIPT, "--fixtures", &fx, "--out", &s(&misnamed)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let out = dir.join("summary");
    let r = shadowcheck(&[
        "summarize",
        "-o",
        &s(&out),
        &s(&misnamed),
        "--platform",
        "test",
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let label = SCRIPT.replace(':', "-");
    let summary = std::fs::read_to_string(out.join("SUMMARY.md")).unwrap();
    assert!(
        summary.contains(&format!("| {label} | core | 36 | 0 | 4 |")),
        "{summary}"
    );
    assert!(!summary.contains("egl-llvmpipe-core"), "{summary}");
    assert!(
        summary.contains(&format!("- {label}: shadowcheck mock")),
        "{summary}"
    );
    assert!(!out.join("egl-llvmpipe-core").exists());
    let own = std::fs::read_to_string(out.join(&label).join("summary.md")).unwrap();
    assert!(
        own.contains("Implementation (the run's meta line): shadowcheck mock"),
        "{own}"
    );
    assert!(r.stderr.contains("summarized as"), "{}", r.stderr);

    // Its results.jsonl cut in its last line: refused, the file named.
    let cut = dir.join("r-cut");
    copy_run(&misnamed, &cut);
    for f in ["failures.csv", "report.md"] {
        std::fs::copy(misnamed.join(f), cut.join(f)).unwrap();
    }
    let file = cut.join("results.jsonl");
    let text = std::fs::read_to_string(&file).unwrap();
    std::fs::write(&file, &text[..text.len() - 5]).unwrap();
    let r = shadowcheck(&[
        "summarize",
        "-o",
        &s(&dir.join("o2")),
        &s(&cut),
        "--platform",
        "t",
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains(&s(&file)) && r.stderr.contains("last line is cut off"),
        "{}",
        r.stderr
    );

    // A run killed midway: refused, with what is missing.
    let (dir2, fx2) = cases_dir("summarize-killed", 300);
    let killed = dir2.join("r-mock");
    killed_run("mock:", &fx2, &killed, &[], "n=0250");
    let r = shadowcheck(&[
        "summarize",
        "-o",
        &s(&dir2.join("o")),
        &s(&killed),
        "--platform",
        "t",
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains("did not finish") && r.stderr.contains("of 300 tests written"),
        "{}",
        r.stderr
    );
}

#[test]
fn repro_all_failures_with_nothing_it_can_reproduce_says_so_and_links_nothing_missing() {
    let (dir, fx) = cases_dir("repro-none", 12);
    // No Fail at all: nothing to reproduce, nothing written, exit 4.
    let pass = dir.join("pass");
    let r = run(&["-b", "mock:", "--fixtures", &fx, "--out", &s(&pass)]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let r = shadowcheck(&["repro", "--all-failures", &s(&pass)]);
    assert_eq!(r.code, 4, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("no Fail to reproduce"), "{}", r.stderr);
    assert!(!pass.join("repro").exists());

    // Fails of a backend repro cannot write a program for: exit 96, and index.md links no folder.
    let fails = dir.join("fails");
    let r = run(&["-b", SCRIPT, "--fixtures", &fx, "--out", &s(&fails)]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let r = shadowcheck(&["repro", "--all-failures", &s(&fails)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains("no reproducer could be written"),
        "{}",
        r.stderr
    );
    let index = std::fs::read_to_string(fails.join("repro/index.md")).unwrap();
    assert!(index.contains("no reproducer: "), "{index}");
    let link = regex::Regex::new(r"\]\(([^)]*)\)").unwrap();
    for c in link.captures_iter(&index) {
        assert!(
            fails.join("repro").join(&c[1]).exists(),
            "index.md links {} which was not written:\n{index}",
            &c[1]
        );
    }
}

/// `report` and `consensus` read a run that did not finish (killed by the mock worker), and say
/// so: a partial run's answers are worth a look, its missing tests are not in what they show.
#[test]
fn report_and_consensus_say_when_a_run_did_not_finish() {
    let (dir, fx) = cases_dir("partial-read", 200);
    let out = dir.join("killed");
    killed_run(SCRIPT, &fx, &out, &[], "n=0150");
    let r = shadowcheck(&["consensus", &s(&out)]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.contains("the run did not finish") && r.stderr.contains("no closing record"),
        "{}",
        r.stderr
    );
    let html = dir.join("html");
    let r = shadowcheck(&["report", &s(&out), "-o", &s(&html), "--fixtures", &fx]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("a partial run"), "{}", r.stderr);
    let page = std::fs::read_to_string(html.join("index.html")).unwrap();
    assert!(page.contains("<b>Partial run</b>: input 1: "));
    let _ = std::fs::remove_dir_all(&dir);
}
