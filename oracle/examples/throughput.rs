//! Rough throughput of `evaluate` (a measurement, not a test):
//! `cargo run --release -p shadowcheck-oracle --example throughput`.
use shadowcheck_model::*;
use std::time::Instant;

fn case(filter: Filter, i: usize) -> Case {
    let vals: Vec<u32> = (0..16)
        .map(|k| ((k * 7919 + i * 104729) % 65536) as u32)
        .collect();
    let mut levels = vec![Level {
        width: 4,
        height: 4,
        layers: 1,
        depth: Texels::Unorm(vals),
        stencil: None,
    }];
    levels.push(Level {
        width: 2,
        height: 2,
        layers: 1,
        depth: Texels::Unorm(vec![1000, 30000, 50000, 65535]),
        stencil: None,
    });
    levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: Texels::Unorm(vec![32768]),
        stencil: None,
    });
    Case {
        sweep: vec![],
        id: format!("bench/{i}"),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels,
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::CORE[i % 8], filter),
        lookup: Lookup {
            coord: [(i % 97) as f64 / 97.0, (i % 89) as f64 / 89.0, 0.0, 1.0],
            layer: 0.0,
            dref: (i % 101) as f64 / 100.0,
            projective: false,
            lod: (i % 5) as f64 * 0.4,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: None,
    }
}

fn main() {
    for filter in [Filter::Nearest, Filter::Linear, Filter::LinearMipmapLinear] {
        let cases: Vec<Case> = (0..20_000).map(|i| case(filter, i)).collect();
        let t = Instant::now();
        let mut ok = 0;
        for c in &cases {
            ok += shadowcheck_oracle::evaluate(c).is_ok() as usize;
        }
        let dt = t.elapsed();
        println!(
            "{filter:>8}: {} cases ({ok} ok) in {:.3} s = {:.1} µs/case",
            cases.len(),
            dt.as_secs_f64(),
            dt.as_secs_f64() * 1e6 / cases.len() as f64
        );
    }
}
