//! The layout of a batch: every (case, API path) owns one 2x2 pixel quad of the result image and
//! its result is the quad's lower-left pixel ("slots", taken in order and read back together); a
//! batched draw gives case k two triangles over its quad, its values as per-vertex attributes
//! (corner, (x, k), P, dx, dy: [`PARAM_ATTRIBS`]).

use crate::shaders::{self, PARAM_FLOATS};
use crate::{Plan, ShaderKey};

/// Width and height of the result framebuffer in pixels.
pub const FB_SIZE: i32 = 256;
/// Quads (2x2 pixels, one per (case, path)) in a row of the framebuffer.
pub const QUADS_PER_ROW: i32 = FB_SIZE / 2;
/// (case, path) results the framebuffer holds.
pub const CAPACITY: usize = (QUADS_PER_ROW * QUADS_PER_ROW) as usize;
/// The pixel holding slot `slot`'s result: the lower-left pixel of its quad.
pub fn pixel(slot: usize) -> (i32, i32) {
    let s = slot as i32;
    (2 * (s % QUADS_PER_ROW), 2 * (s / QUADS_PER_ROW))
}

/// Most cases one batched draw serves (its quads must fit the framebuffer: `CAPACITY`).
pub const DRAW_CASES: usize = 1024;

/// One batched draw: a program (`key` on `units` samplers), the (case, plan, unit) triples it serves
/// (slot k of the draw is item k; unit: the texture unit holding the case's state, see `units.rs`),
/// and where item 0's values are in the parameter buffer (in cases).
pub struct Batch<'p> {
    pub key: ShaderKey,
    pub units: usize,
    pub items: Vec<(usize, &'p Plan, usize)>,
    pub first: usize,
}

/// The parameter values of a worker batch: six vertices per case ([`PARAM_FLOATS`] each).
#[derive(Default)]
pub struct ParamStaging {
    values: Vec<f32>,
}

impl ParamStaging {
    /// The staged values, case after case, six vertices each.
    pub fn values(&self) -> &[f32] {
        &self.values
    }
}

/// Vertices per case: two triangles covering its quad.
pub const CASE_VERTICES: usize = 6;
/// The quad's corners, as two triangles of the same winding.
pub const CORNERS: [[f32; 2]; CASE_VERTICES] = [
    [0.0, 0.0],
    [1.0, 0.0],
    [0.0, 1.0],
    [0.0, 1.0],
    [1.0, 0.0],
    [1.0, 1.0],
];

impl ParamStaging {
    /// Stages the values of one draw's `items`; returns the index of the first in the buffer (in
    /// cases). Each vertex of case k of the draw: corner, (x, k, unit), P, dx, dy.
    fn stage(&mut self, items: &[(usize, &Plan, usize)]) -> usize {
        let first = self.values.len() / (PARAM_FLOATS * CASE_VERTICES);
        for (k, (_, p, unit)) in items.iter().enumerate() {
            for corner in CORNERS {
                self.values.extend_from_slice(&corner);
                self.values
                    .extend_from_slice(&[p.x, k as f32, *unit as f32]);
                self.values.extend_from_slice(&p.p);
                self.values.extend_from_slice(&p.dx);
                self.values.extend_from_slice(&p.dy);
            }
        }
        first
    }
}

/// The batched draws of a bundle (`units.rs`): the lookups of `key` on the bundle's texture
/// states (state i, a group of (case, plans) sharing one texture, on unit i; a program of as
/// many samplers), in state order, at
/// most [`DRAW_CASES`] a draw, their values staged in `staging`. A batchable key is always drawn
/// batched, even alone, so the driver compiles one variant per (program, states), not a batched
/// and a single-pixel one; for another key this is empty.
pub fn batches_of<'p>(
    key: ShaderKey,
    bundle: &[&'p [(usize, Vec<Plan>)]],
    staging: &mut ParamStaging,
) -> Vec<Batch<'p>> {
    if !shaders::batchable(&key) {
        return Vec::new();
    }
    let units = bundle.len().max(1);
    let mut items: Vec<(usize, &Plan, usize)> = Vec::new();
    for (unit, group) in bundle.iter().enumerate() {
        for (ci, plans) in group.iter() {
            for plan in plans.iter().filter(|p| p.key == key) {
                items.push((*ci, plan, unit));
            }
        }
    }
    let mut out = Vec::new();
    for chunk in items.chunks(DRAW_CASES) {
        let first = staging.stage(chunk);
        out.push(Batch {
            key,
            units,
            items: chunk.to_vec(),
            first,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paths;
    use crate::shaders::PARAM_ATTRIBS;

    #[test]
    fn slots_are_the_lower_left_pixels_of_quads_row_by_row() {
        assert_eq!(pixel(0), (0, 0));
        assert_eq!(pixel(1), (2, 0));
        assert_eq!(pixel(QUADS_PER_ROW as usize - 1), (FB_SIZE - 2, 0));
        assert_eq!(pixel(QUADS_PER_ROW as usize), (0, 2));
        assert_eq!(pixel(CAPACITY - 1), (FB_SIZE - 2, FB_SIZE - 2));
    }
    use shadowcheck_model::{ApiPath, Target};

    /// `n` cases of one program, case k with P.x = k + offset (so each value names its case).
    fn group(n: usize, first_ci: usize, offset: f32) -> Vec<(usize, Vec<Plan>)> {
        let case = crate::test_case::case(Target::T2d, 2, 2, 1);
        (0..n)
            .map(|k| {
                let mut p = paths::plan(ApiPath::GlslCore, &case).expect("core plan");
                p.p[0] = k as f32 + offset;
                (first_ci + k, vec![p])
            })
            .collect()
    }

    #[test]
    fn staged_values_sit_where_each_draw_reads_them() {
        let a = group(1500, 0, 0.0);
        let b = group(30, 1500, 5000.0);
        let mut staging = ParamStaging::default();
        let key = a[0].1[0].key;
        let ba = batches_of(key, &[&a], &mut staging);
        let bb = batches_of(key, &[&b[..10], &b[10..]], &mut staging);
        assert!(shaders::batchable(&a[0].1[0].key));
        // A group is split at DRAW_CASES; the second group's values follow the first's.
        assert_eq!(
            ba.iter()
                .chain(&bb)
                .map(|b| (b.items.len(), b.first))
                .collect::<Vec<_>>(),
            vec![(DRAW_CASES, 0), (1500 - DRAW_CASES, DRAW_CASES), (30, 1500)]
        );
        // The second group's two states are units 0 and 1 of a two-unit program.
        assert_eq!((ba[0].units, bb[0].units), (1, 2));
        assert!(bb[0].items[..10].iter().all(|i| i.2 == 0));
        assert!(bb[0].items[10..].iter().all(|i| i.2 == 1));
        assert_eq!(staging.values.len(), 1530 * CASE_VERTICES * PARAM_FLOATS);
        // Every vertex of case k of a draw (case first + k of the buffer) carries its corner,
        // (x, k), P, dx and dy where PARAM_ATTRIBS says.
        let attrib = |name: &str| {
            let (_, _, size, at) = PARAM_ATTRIBS.into_iter().find(|a| a.1 == name).expect(name);
            at..at + size as usize
        };
        for batch in ba.iter().chain(&bb) {
            for (k, (_, plan, unit)) in batch.items.iter().enumerate() {
                for (vi, corner) in CORNERS.iter().enumerate() {
                    let at = ((batch.first + k) * CASE_VERTICES + vi) * PARAM_FLOATS;
                    let v = &staging.values[at..at + PARAM_FLOATS];
                    assert_eq!(v[attrib("a_pos")], corner[..]);
                    assert_eq!(v[attrib("a_x")], [plan.x, k as f32, *unit as f32]);
                    assert_eq!(v[attrib("a_p")], plan.p);
                    assert_eq!(v[attrib("a_dx")], plan.dx);
                    assert_eq!(v[attrib("a_dy")], plan.dy);
                }
            }
        }
    }
}
