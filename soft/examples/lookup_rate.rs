//! Raw single-thread lookup rate of the soft texture unit on one prepared texture.
//! `cargo run --release -p shadowcheck-soft --example lookup_rate [size] [lookups]`

use shadowcheck_model::{Filter, Spec};
use shadowcheck_soft::bench::Workload;
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let size: u32 = args.next().and_then(|a| a.parse().ok()).unwrap_or(256);
    let n: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(4_000_000);
    for filter in [Filter::Nearest, Filter::Linear, Filter::LinearMipmapLinear] {
        let w = match Workload::new(Spec::Gl46, size, filter, n) {
            Ok(w) => w,
            Err(e) => {
                eprintln!("{filter}: {e}");
                continue;
            }
        };
        let _ = w.run(); // warm-up
        let t = Instant::now();
        let sum = w.run();
        let s = t.elapsed().as_secs_f64();
        println!(
            "{filter:>8}: {:>8.1} M lookups/s ({n} lookups, {size}x{size} d24, checksum {sum:.3})",
            n as f64 / s / 1e6
        );
    }
}
