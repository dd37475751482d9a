//! Unit tests of the page jobs: sharing of textures and draws, Skip reasons, the answers.
use super::*;
use shadowcheck_model::{Case, SweepPoint};
use shadowcheck_plan::{sweep, test_case::case};

fn wgpu_case(target: Target, layers: u32) -> Case {
    let mut c = case(target, 2, 2, layers);
    c.api = vec![ApiPath::Wgsl];
    c
}

fn core() -> DeviceCaps {
    DeviceCaps {
        d32fs8: true,
        cube_array: true,
        max_dimension: 8192,
        max_layers: 256,
    }
}

#[test]
fn a_case_and_its_sweep_share_a_texture_and_one_draw() {
    let mut c = wgpu_case(Target::T2d, 1);
    c.sweep = (0..3)
        .map(|k| SweepPoint {
            coord: [0.25, 0.75, 0.0, 1.0],
            dref: k as f64 / 4.0,
            expect: None,
        })
        .collect();
    let mut other = wgpu_case(Target::T2d, 1);
    other.lookup.lod = 0.5;
    other.sampler.compare_func = shadowcheck_model::CompareFunc::Greater;
    let cases = vec![c, other];
    let jobs = sweep::jobs(&cases);
    let (early, built) = build(&jobs, &core());
    assert!(early.iter().all(Option::is_none));
    assert_eq!(built.len(), 1);
    let p = &built[0].page;
    assert_eq!((p.textures.len(), p.slots, p.modules.len()), (2, 5, 2));
    assert_eq!(p.draws.len(), 2);
    assert_eq!((p.draws[0].first, p.draws[0].count), (0, 4));
    assert_eq!(
        (p.draws[1].texture, p.draws[1].first, p.draws[1].count),
        (1, 4, 1)
    );
    // The second texture's points follow the first's.
    assert_eq!(p.textures[1].subresources[0].first, 4);
    assert!(p.modules[1]
        .wgsl
        .contains("textureSampleCompare(t, s, p.xy, p.z)"));
    assert_eq!(p.stride, 52);
}

#[test]
fn what_cannot_be_drawn_is_skip_with_the_reason() {
    let mut layer = wgpu_case(Target::T2dArray, 3);
    layer.lookup.coord[2] = 0.5;
    let mut s8 = wgpu_case(Target::T2d, 1);
    s8.texture.format = Format::D32fS8;
    s8.texture.levels[0].depth = shadowcheck_model::Texels::Float(vec![0.5; 4]);
    let cube_array = wgpu_case(Target::CubeArray, 6);
    let wide = case(Target::T2d, 8, 1, 1);
    let cases = vec![layer, s8, cube_array, wide];
    let jobs = sweep::jobs(&cases);
    let compat = DeviceCaps {
        max_dimension: 4,
        ..DeviceCaps::default()
    };
    let (early, built) = build(&jobs, &compat);
    assert!(built.is_empty());
    let why = |i: usize| match &early[i] {
        Some(Answer::Skip(w)) => w.clone(),
        other => panic!("{other:?}"),
    };
    assert!(why(0).contains("array_index is an integer"), "{}", why(0));
    assert!(
        why(1).contains("\"depth32float-stencil8\" feature"),
        "{}",
        why(1)
    );
    assert!(why(2).contains("compatibility mode"), "{}", why(2));
    assert!(why(3).contains("maxTextureDimension2D 4"), "{}", why(3));
    let (early, built) = build(&jobs, &core());
    assert!(early[0].is_some() && early[1..].iter().all(Option::is_none));
    assert_eq!(built[0].page.slots, 3);
}

#[test]
fn answers_read_each_slot_and_errors_fail_the_whole_job() {
    let cases = vec![wgpu_case(Target::T2d, 1), wgpu_case(Target::Cube, 6)];
    let jobs = sweep::jobs(&cases);
    let b64 = |v: &[u8]| base64::engine::general_purpose::STANDARD.encode(v);
    let page = |errors: Vec<String>| PageAnswer {
        lost: None,
        errors,
        pixels: Some(b64(&[1.0f32, 0.0, 0.0, 1.0, 0.5, 0.0, 0.0, 1.0]
            .iter()
            .flat_map(|f| f.to_le_bytes())
            .collect::<Vec<u8>>())),
        stored: vec![Some(b64(&[1, 0, 2, 0, 3, 0, 4, 0])), None],
    };
    let (_, mut built) = build(&jobs, &core());
    let a = answers(built.remove(0), &jobs, page(vec![]));
    assert_eq!(a.len(), 2);
    let Answer::Observation(r, _) = &a[1].1 else {
        panic!("{a:?}")
    };
    assert_eq!(r[0].rgba.0, [0.5, 0.0, 0.0, 1.0]);
    assert_eq!(r[0].api, "wgsl");
    let Answer::Observation(r, _) = &a[0].1 else {
        panic!("{a:?}")
    };
    assert_eq!(
        r[0].stored,
        Some(shadowcheck_model::Texels::Unorm(vec![1, 2, 3, 4]))
    );
    let (_, mut built) = build(&jobs, &core());
    let a = answers(
        built.remove(0),
        &jobs,
        page(vec!["validation error: bad sampler".into()]),
    );
    assert!(a.iter().all(|(_, x)| matches!(x, Answer::Error(m) if m.contains("bad sampler") && m.contains("harness bug"))));
}

#[test]
fn compute_lookups_are_dispatches_after_their_textures_fragment_draw() {
    use shadowcheck_model::Stage;
    let frag = wgpu_case(Target::Cube, 6);
    let mut comp = frag.clone();
    comp.lookup.stage = Stage::Compute;
    let mut frag2 = frag.clone();
    frag2.lookup.dref = 0.25;
    let cases = vec![frag, comp, frag2];
    let jobs = sweep::jobs(&cases);
    let (early, built) = build(&jobs, &core());
    assert!(early.iter().all(Option::is_none), "{early:?}");
    assert_eq!(built.len(), 1);
    let p = &built[0].page;
    assert_eq!((p.textures.len(), p.slots, p.modules.len()), (1, 3, 2));
    // The two fragment lookups stay one instanced draw (slots 0 and 1); the compute lookup
    // takes the slot after them, in a compute module.
    assert_eq!(p.draws.len(), 2);
    assert_eq!(
        (p.draws[0].module, p.draws[0].first, p.draws[0].count),
        (0, 0, 2)
    );
    assert_eq!(
        (p.draws[1].module, p.draws[1].first, p.draws[1].count),
        (1, 2, 1)
    );
    assert!(!p.modules[0].compute && p.modules[0].wgsl.contains("fn fs("));
    assert!(p.modules[1].compute && p.modules[1].wgsl.contains("fn cs("));
    assert_eq!(p.compute_bindings, COMPUTE_BINDINGS);
    let json = serde_json::to_string(p).expect("json");
    assert!(
        json.contains("\"computeBindings\":[[\"lookups\",2,\"read-only-storage\"]"),
        "{json}"
    );
    // Slot 2's pixel answers job 1 (the compute case), slot 1's job 2.
    let px: Vec<u8> = [0.5f32, 0.25, 1.0]
        .iter()
        .flat_map(|r| [*r, 0.0, 0.0, 1.0])
        .flat_map(f32::to_le_bytes)
        .collect();
    let b = built.into_iter().next().expect("one job");
    let answer = PageAnswer {
        lost: None,
        errors: vec![],
        pixels: Some(base64::engine::general_purpose::STANDARD.encode(px)),
        stored: vec![],
    };
    let got: Vec<(usize, f64)> = answers(b, &jobs, answer)
        .into_iter()
        .map(|(j, a)| match a {
            Answer::Observation(r, _) => (j, r[0].rgba.0[0]),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(got, vec![(0, 0.5), (2, 0.25), (1, 1.0)]);
}
