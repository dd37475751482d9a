//! Evaluates every case of a grid and tallies the oracle's errors by message pattern (to find the
//! combinations a grid must filter). `cargo run -p shadowcheck-cases --example oracle_probe -- default`
use std::collections::BTreeMap;
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "default".into());
    let files = shadowcheck_cases::grids::unfilled(&name, 0).unwrap_or_else(|e| panic!("{e}"));
    let mut tally: BTreeMap<String, (usize, String)> = BTreeMap::new();
    let mut ok = 0;
    let mut bytes = 0;
    for (_, mut f) in files {
        for c in &mut f.cases {
            match shadowcheck_oracle::evaluate(c) {
                Ok(ev) => {
                    ok += 1;
                    c.expect = Some(ev.expect);
                }
                Err(e) => {
                    let msg = e.to_string();
                    let key = msg
                        .split_once(": ")
                        .map(|x| x.1.to_string())
                        .unwrap_or(msg.clone());
                    let slot = tally.entry(key).or_insert((0, c.id.clone()));
                    slot.0 += 1;
                }
            }
        }
        bytes += shadowcheck_cases::fixtures::to_string(&f)
            .map(|s| s.len())
            .unwrap_or(0);
    }
    for (k, (n, id)) in &tally {
        println!("{n:6}  {k}\n        e.g. {id}");
    }
    println!("{ok} ok, {bytes} bytes");
}
