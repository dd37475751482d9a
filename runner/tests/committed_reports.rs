//! What is committed under reports/ and README.md's result tables: the tables are those of the
//! committed reference results (regenerating them from reports/headline.json and
//! reports/*/SUMMARY.md changes nothing), and no report shadowcheck wrote names a path of the
//! machine that made it.
use shadowcheck_runner::report::headline;
use std::path::Path;

#[test]
fn readme_result_tables_match_the_committed_summaries() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = root.join("README.md");
    let committed = std::fs::read_to_string(&readme).unwrap();
    let regenerated = headline::regenerate(&readme, &root.join("reports")).unwrap();
    assert!(
        committed == regenerated,
        "README.md's result tables differ from reports/*/SUMMARY.md: run \
         `shadowcheck summarize --update-readme README.md` and commit"
    );
    let spec = headline::load_spec(&root.join("reports/headline.json")).unwrap();
    assert!(spec.tables.len() >= 2);
    for t in &spec.tables {
        assert!(committed.contains(&headline::begin(&t.name)), "{}", t.name);
    }
}

/// The subcommand: `summarize --update-readme` alone rewrites only the tables of a README copy.
#[test]
fn summarize_update_readme_rewrites_a_stale_table() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let dir = std::env::temp_dir().join(format!("sc-headline-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("reports")).unwrap();
    let spec = headline::load_spec(&root.join("reports/headline.json")).unwrap();
    std::fs::copy(
        root.join("reports/headline.json"),
        dir.join("reports/headline.json"),
    )
    .unwrap();
    let mut readme = String::from("# copy\n");
    for t in &spec.tables {
        readme += &format!(
            "\n{}\n| stale |\n{}\n",
            headline::begin(&t.name),
            headline::end(&t.name)
        );
    }
    for t in &spec.tables {
        for r in &t.rows {
            for sel in r.of.iter().chain(r.same_as.iter().flatten()).flatten() {
                let folder = sel.split('/').next().unwrap();
                let _ = std::fs::create_dir_all(dir.join("reports").join(folder));
                let _ = std::fs::copy(
                    root.join("reports").join(folder).join("SUMMARY.md"),
                    dir.join("reports").join(folder).join("SUMMARY.md"),
                );
            }
        }
    }
    std::fs::write(dir.join("README.md"), &readme).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
        .args(["summarize", "--update-readme"])
        .arg(dir.join("README.md"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let new = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(
        !new.contains("| stale |") && new.starts_with("# copy\n"),
        "{new}"
    );
    // A summary whose counts no longer agree with a row's claim of equal counts is an error
    // naming the row, and leaves the README as it was.
    let es3 = dir.join("reports/mesa-22.3.6/SUMMARY.md");
    let text = std::fs::read_to_string(&es3).unwrap();
    let changed = text.replace("| egl-zink-es3 | es300 | ", "| egl-zink-es3 | es300 | 1");
    assert_ne!(text, changed);
    std::fs::write(&es3, changed).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
        .args(["summarize", "--update-readme"])
        .arg(dir.join("README.md"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(96), "{stderr}");
    assert!(stderr.contains("claims equal counts"), "{stderr}");
    assert_eq!(std::fs::read_to_string(dir.join("README.md")).unwrap(), new);
    let _ = std::fs::remove_dir_all(&dir);
}

/// No file under reports/ (the summaries, reports, HTML page, review queues, benchmark and mutant
/// reports that shadowcheck writes, and the run scripts, reproducers and their outputs written by
/// hand or by `repro`) names an absolute path of the machine that made it: a reader's checkout has
/// none of them, and a build.sh that writes to /tmp runs differently elsewhere.
#[test]
fn committed_reports_name_no_machine_path() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut stack = vec![root.join("reports")];
    let mut checked = 0;
    let mut found = vec![];
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            // Text files only (a built reproducer binary left beside its source is no report).
            let Ok(text) = std::fs::read_to_string(&p) else {
                continue;
            };
            checked += 1;
            for bad in ["/tmp/", "/root/", "/home/", "/work/", "/var/tmp/"] {
                if let Some(at) = text.find(bad) {
                    let end = (at + 60).min(text.len());
                    let end = (end..text.len())
                        .find(|&i| text.is_char_boundary(i))
                        .unwrap_or(text.len());
                    found.push(format!("{}: {}", p.display(), &text[at..end]));
                }
            }
        }
    }
    assert!(checked >= 100, "only {checked} files found under reports/");
    assert!(
        found.is_empty(),
        "machine paths in committed reports:\n{}",
        found.join("\n")
    );
}
