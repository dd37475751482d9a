//! The vertex stage (GLSL 4.60 / GLSL ES 3.20 §8.9): "Other shaders operate as though the base
//! level-of-detail were computed as zero" (reading A, the spec value) and "If it is mipmapped and
//! running in a non-fragment shader, then the base texture is used" (reading B), both accepted
//! (contradiction `non-fragment-base-texture`).

mod common;

use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{contradictions, evaluate_reading};

/// A NEAREST_MIPMAP_NEAREST 4x4 → 2x2 → 1x1 D32F chain whose level 1 alone holds 1.0, LEQUAL Dref
/// ½ (r = 1 at level 1 only), looked up at fragment λ `lod` in `stage`.
fn chain(spec: Spec, stage: Stage, lod: f64) -> Case {
    let mut c = case2d(
        spec,
        Format::D32f,
        CompareFunc::Lequal,
        Filter::NearestMipmapNearest,
        4,
        4,
        &[0.0; 16],
        (0.5, 0.5),
        0.5,
    );
    for (size, v) in [(2u32, 1.0), (1, 0.0)] {
        c.texture.levels.push(Level {
            width: size,
            height: size,
            layers: 1,
            depth: Texels::Float(vec![v; (size * size) as usize]),
            stencil: None,
        });
    }
    c.lookup.lod = lod;
    c.lookup.stage = stage;
    c
}

/// r at the strict tier: (accepts 0, accepts 1).
fn accepts(c: &Case) -> (bool, bool) {
    let e = eval(c).expect;
    let api = c.api[0];
    let ok = |v: f64| {
        e.accepts(Profile::Strict, api, [v, 0.0, 0.0, 1.0])
            .unwrap_or_else(|| panic!("{}: no layout", c.id))
    };
    (ok(0.0), ok(1.0))
}

#[test]
fn the_vertex_stage_takes_lambda_base_zero_whatever_the_fragment_lambda() {
    for spec in [Spec::Gl46, Spec::Gles32] {
        assert_eq!(value(&chain(spec, Stage::Fragment, 1.0)), 1.0, "{spec}");
        for lod in [0.5, 1.0, 2.0] {
            let c = chain(spec, Stage::Vertex, lod);
            assert_eq!(value(&c), 0.0, "{spec} λ {lod}");
            assert_eq!(accepts(&c), (true, false), "{spec} λ {lod}: level 0 only");
            // Both readings give level 0 here: the case meets the contradiction, no note names it.
            assert!(contradictions::touching(&c)
                .iter()
                .any(|x| x.id == "non-fragment-base-texture"));
            let e = eval(&c).expect;
            assert!(
                !e.implementation_defined
                    .as_deref()
                    .is_some_and(|n| n.contains("non-fragment-base-texture")),
                "{:?}",
                e.implementation_defined
            );
        }
    }
}

#[test]
fn min_lod_one_tells_the_readings_apart_and_both_are_accepted() {
    // λ_base 0 clamped to MIN_LOD 1 selects level 1 (reading A: r = 1); the base texture gives 0.
    let mut c = chain(Spec::Gl46, Stage::Vertex, 2.0);
    c.sampler.min_lod = 1.0;
    assert_eq!(value(&c), 1.0);
    assert_eq!(accepts(&c), (true, true));
    let e = eval(&c).expect;
    assert!(
        e.implementation_defined
            .as_deref()
            .is_some_and(|n| n.contains("non-fragment-base-texture")),
        "{:?}",
        e.implementation_defined
    );
    assert!(contradictions::touching(&c)
        .iter()
        .any(|x| x.id == "non-fragment-base-texture"));
    let other = evaluate_reading(&c, "non-fragment-base-texture")
        .expect("an alternative rule")
        .expect("evaluates");
    assert_eq!(other.expect.spec_value, Some(0.0));
    // TEXTURE_LOD_BIAS 1 likewise.
    let mut c = chain(Spec::Gl46, Stage::Vertex, 2.0);
    c.sampler.lod_bias = 1.0;
    assert_eq!((value(&c), accepts(&c)), (1.0, (true, true)));
}

#[test]
fn the_compute_stage_reads_the_same_sentences_as_the_vertex_stage() {
    // "Other shaders": a compute shader as much as a vertex shader (GLSL 4.60 / GLSL ES 3.20 §8.9).
    for spec in [Spec::Gl46, Spec::Gles32] {
        for lod in [0.5, 1.0, 2.0] {
            let c = chain(spec, Stage::Compute, lod);
            assert_eq!(value(&c), 0.0, "{spec} λ {lod}");
            assert_eq!(accepts(&c), (true, false), "{spec} λ {lod}: level 0 only");
        }
    }
    // MIN_LOD 1: reading A's level 1 and the base texture, both accepted and named.
    let mut c = chain(Spec::Gles32, Stage::Compute, 2.0);
    c.sampler.min_lod = 1.0;
    assert_eq!((value(&c), accepts(&c)), (1.0, (true, true)));
    let e = eval(&c).expect;
    let cites = e.citations.join(" ");
    assert!(cites.contains("GLSL ES 3.20 §8.9"), "{cites}");
    assert!(
        !cites.contains("GLSL ES 3.00 §8.8"),
        "ES 3.00 has no compute shader: {cites}"
    );
}
