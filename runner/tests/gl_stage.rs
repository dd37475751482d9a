//! Vertex- and compute-stage lookups (`lookup.stage`) on the Mesa drivers: the implicit-LOD
//! function in the vertex shader or a compute shader, where "the base level-of-detail" is
//! "computed as zero" (GLSL 4.60 / GLSL ES 3.20 §8.9), whatever λ_base a fragment shader would
//! compute from the case. The expected values
//! are worked out by hand from the texels. A missing driver is a loud skip here, a failure under
//! CI=true (see gl_support).
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

/// Each context kind with the API paths drawn on it and the spec of its cases.
const CONTEXTS: [(&str, Spec, &[ApiPath]); 3] = [
    ("core", Spec::Gl46, &[ApiPath::GlslCore]),
    ("es3", Spec::Gles32, &[ApiPath::Es300]),
    ("compat", Spec::Gl46, &[ApiPath::Glsl120, ApiPath::Glsl130]),
];

#[test]
fn a_vertex_lookup_reads_the_base_level_whatever_the_fragment_lambda() {
    // Level 1 of a NEAREST_MIPMAP_NEAREST 4x4 → 1x1 chain alone holds 1.0 (LEQUAL Dref ½ passes
    // there only). In the fragment stage λ = 1 reads it (r = 1); in the vertex stage λ_base = 0
    // selects level 0 (r = 0) for every fragment λ.
    for (ctx, spec, apis) in CONTEXTS {
        for b in backends(ctx, false) {
            let Some(mut s) = Session::start(&b) else {
                continue;
            };
            for &api in apis {
                let mut cases = Vec::new();
                for (stage, lod, want) in [
                    (Stage::Fragment, 1.0, 1.0),
                    (Stage::Vertex, 0.5, 0.0),
                    (Stage::Vertex, 1.0, 0.0),
                    (Stage::Vertex, 2.0, 0.0),
                ] {
                    let id = format!("{api}/stage={stage}/lod={lod}");
                    let mut c = mip_case(&id, spec, &[api], Target::T2d, lod, 0.0);
                    c.lookup.stage = stage;
                    cases.push((c, want));
                }
                let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
                let answers = s.run(&cs);
                for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
                    assert_eq!(Session::rgba(a, api)[0], w, "{b} {}: {a}", c.id);
                }
            }
        }
    }
}

#[test]
fn min_lod_one_in_the_vertex_stage_is_reading_a_or_b() {
    // The same chain with TEXTURE_MIN_LOD 1: λ_base 0 clamped to 1 selects level 1 (r = 1,
    // reading A, GLSL 4.60 §8.9 "as though the base level-of-detail were computed as zero");
    // "the base texture is used" reads level 0 (r = 0, reading B). Nothing else is accepted;
    // which one each driver takes is printed (contradiction `non-fragment-base-texture`).
    for (ctx, spec, apis) in CONTEXTS {
        for b in backends(ctx, false) {
            let Some(mut s) = Session::start(&b) else {
                continue;
            };
            let api = apis[0];
            let mut c = mip_case(
                "stage=vertex/min_lod=1",
                spec,
                &[api],
                Target::T2d,
                2.0,
                0.0,
            );
            c.lookup.stage = Stage::Vertex;
            c.sampler.min_lod = 1.0;
            let answers = s.run(std::slice::from_ref(&c));
            let r = Session::rgba(&answers[0], api)[0];
            assert!(r == 1.0 || r == 0.0, "{b} {}: {}", c.id, answers[0]);
            eprintln!(
                "{b}: MIN_LOD 1 in the vertex stage reads level {} (reading {})",
                if r == 1.0 { 1 } else { 0 },
                if r == 1.0 { "A" } else { "B" }
            );
        }
    }
}

#[test]
fn a_compute_lookup_reads_the_base_level_and_needs_gl_4_3_or_es_3_1() {
    // The chain of the vertex test, looked up by one compute-shader invocation that stores its
    // result in the result image: λ_base 0 selects level 0 (r = 0) for every fragment λ; with
    // MIN_LOD 1 reading A gives level 1 (r = 1) and reading B level 0 (r = 0). A context without
    // compute shaders (softpipe's GL 3.3 core) answers skip, naming what is missing.
    for (ctx, spec, api) in [
        ("core", Spec::Gl46, ApiPath::GlslCore),
        ("es3", Spec::Gles32, ApiPath::Es300),
    ] {
        for b in backends(ctx, false) {
            let Some(mut s) = Session::start(&b) else {
                continue;
            };
            let mut cases = Vec::new();
            for (lod, min_lod) in [(0.5, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0)] {
                let id = format!("{api}/stage=compute/lod={lod}/min_lod={min_lod}");
                let mut c = mip_case(&id, spec, &[api], Target::T2d, lod, 0.0);
                c.lookup.stage = Stage::Compute;
                c.sampler.min_lod = min_lod;
                cases.push(c);
            }
            let answers = s.run(&cases);
            for (c, a) in cases.iter().zip(&answers) {
                if a["type"] == "skip" {
                    let why = a["reason"].as_str().unwrap_or_default();
                    assert!(
                        why.contains("GL 4.3") && why.contains("ES 3.1"),
                        "{b} {}: {a}",
                        c.id
                    );
                    assert!(!b.contains("llvmpipe"), "llvmpipe has GL 4.5 / ES 3.2: {a}");
                    continue;
                }
                let r = Session::rgba(a, api)[0];
                if c.sampler.min_lod == 0.0 {
                    assert_eq!(r, 0.0, "{b} {}: {a}", c.id);
                } else {
                    assert!(r == 1.0 || r == 0.0, "{b} {}: {a}", c.id);
                    eprintln!(
                        "{b}: MIN_LOD 1 in a compute shader reads level {} (reading {})",
                        r as u32,
                        if r == 1.0 { "A" } else { "B" }
                    );
                }
            }
        }
    }
}
