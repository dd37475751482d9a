//! The `exhaustive` grid (generated on demand, not committed): every D16 value c in 0..=65535 as a
//! 1x1 texture, against R at c / 65535 (nearest f32) and the adjacent f32 values below and above,
//! for each of the eight compare functions, under GL 4.6 with NEAREST filtering: 1,572,864 cases.
//! Streamed in files of [`CHUNK`] values (`gl46/d16/<func>/<first c>.json`).

use super::draft::{lookup, texture, Cell, Draft};
use crate::build::{self, At, Stored};
use shadowcheck_model::*;

/// Texel values per file.
pub const CHUNK: u32 = 4096;

/// Number of cases the grid holds.
pub fn len() -> usize {
    8 * 65536 * 3
}

/// The files of the grid, in path order, each with its drafts; built lazily one file at a time.
pub fn chunks() -> impl Iterator<Item = (String, Vec<Draft>)> {
    let mut funcs: Vec<CompareFunc> = CompareFunc::CORE.to_vec();
    funcs.sort_by_key(|f| f.key());
    funcs
        .into_iter()
        .flat_map(|func| (0..65536u32 / CHUNK).map(move |k| chunk(func, k * CHUNK)))
}

fn chunk(func: CompareFunc, first: u32) -> (String, Vec<Draft>) {
    let cell = Cell {
        spec: Spec::Gl46,
        target: Target::T2d,
        format: Format::D16,
        filter: Filter::Nearest,
        mode: CompareMode::Compare,
        func,
        dtm: None,
    };
    let mut out = Vec::with_capacity(CHUNK as usize * 3);
    for c in first..first + CHUNK {
        let s = Stored::Unorm(c);
        let tex = texture(&cell, vec![build::level_exact(Format::D16, 1, 1, 1, &[s])]);
        let at = build::f32r(build::real(Format::D16, s));
        for (tag, r) in [
            ("at-", build::f32_next_down(at)),
            ("at", at),
            ("at+", build::f32_next_up(at)),
        ] {
            out.push(Draft::new(
                "all",
                cell,
                tex.clone(),
                lookup(Target::T2d, At::st(0.5, 0.5), 1, 1, r),
                format!("c={c}/ref={tag}"),
            ));
        }
    }
    (format!("gl46/d16/{}/{first:05}.json", func.key()), out)
}
