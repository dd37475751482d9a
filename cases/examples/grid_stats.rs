//! Prints the size of a grid without evaluating it (no oracle): cases, files and bytes of the
//! fixtures as they would be written, less the expectations.
//! `cargo run -p shadowcheck-cases --example grid_stats -- default`
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "default".into());
    let files = match shadowcheck_cases::grids::unfilled(&name, 0) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let mut bytes = 0;
    let mut cases = 0;
    for (rel, f) in &files {
        let n = shadowcheck_cases::fixtures::to_string(f)
            .map(|s| s.len())
            .unwrap_or(0);
        bytes += n;
        cases += f.cases.len();
        println!("{rel:40} {:>6} cases {:>9} bytes", f.cases.len(), n);
    }
    let cov = shadowcheck_cases::coverage::Coverage::of(files.iter().flat_map(|(_, f)| &f.cases));
    print!("{}", cov.summary());
    println!("missing cells: {}", cov.missing().len());
    println!(
        "{} files, {cases} cases, {bytes} bytes (without expectations)",
        files.len()
    );
}
