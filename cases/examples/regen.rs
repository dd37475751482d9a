//! Regenerates a grid's fixtures without the runner binary (same output as `shadowcheck gen`):
//! `cargo run --release -p shadowcheck-cases --example regen -- default cases/fixtures [README]`
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let grid = args.next().unwrap_or_else(|| "default".into());
    let out = std::path::PathBuf::from(args.next().unwrap_or_else(|| "cases/fixtures".into()));
    let readme = args.next();
    let files = shadowcheck_cases::grids::generate(&grid, shadowcheck_cases::grids::DEFAULT_SEED)?;
    shadowcheck_cases::fixtures::write_dir(&out, &files)?;
    let cov = shadowcheck_cases::coverage::Coverage::of(files.iter().flat_map(|(_, f)| &f.cases));
    if let Some(r) = readme {
        let text = std::fs::read_to_string(&r)?;
        let new = shadowcheck_cases::coverage::replace_section(&text, &cov.markdown())
            .ok_or("no coverage markers")?;
        std::fs::write(&r, new)?;
    }
    print!("{}", cov.summary());
    Ok(())
}
