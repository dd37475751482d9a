//! Delivered lookup values (`lookup.delivery`: uniforms, flat inputs, values that differ between
//! the fragments of the pixel quad) on the Mesa drivers: the result is the literal lookup's, by
//! the values alone (GLSL 4.60 §8.9.4: textureGatherOffset's offset "can be variable (non
//! constant)"). The expected values are worked out by hand from the texels.
//! A missing driver is a loud skip here, a failure under CI=true (see gl_support).
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

const KINDS: [Delivery; 4] = [
    Delivery::Literal,
    Delivery::Uniform,
    Delivery::Flat,
    Delivery::PerFragment,
];

#[test]
fn delivered_reference_lod_and_coordinates_are_the_literal_values() {
    // Level 1 of a NEAREST_MIPMAP_NEAREST chain alone holds 1.0: λ = 1 reads it (r = 1), λ = 0 and
    // λ = 2 do not; per fragment, the quad's other fragments ask for λ + 0.25 and Dref + 0.25.
    for b in backends("core", false) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        let mut cases = Vec::new();
        for d in KINDS {
            for (lod, want) in [(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)] {
                let id = format!("lod={lod}/delivery={d}");
                let mut c = mip_case(&id, Spec::Gl46, &[ApiPath::GlslCore], Target::T2d, lod, 0.0);
                c.lookup.delivery = d;
                cases.push((c, want));
            }
        }
        let (cs, want): (Vec<Case>, Vec<f64>) = cases.into_iter().unzip();
        let answers = s.run(&cs);
        for ((c, w), a) in cs.iter().zip(want).zip(&answers) {
            assert_eq!(
                Session::rgba(a, ApiPath::GlslCore)[0],
                w,
                "{b} {}: {a}",
                c.id
            );
        }
    }
}

#[test]
fn a_variable_gather_offset_moves_the_footprint() {
    // A 4x2 D16 image [0, ¼, 1, 1 / ¾, 1, 1, 1] gathered at u = v = 1 with LEQUAL Dref ½: offset
    // (1, 0) makes the footprint texels 1 and 2 of both rows, (τi0j1, τi1j1, τi1j0, τi0j0) =
    // (1, 1, 1, ¼) → (1, 1, 1, 0); offset 0 would give (1, 1, 0, 0).
    let q = |x: f64| (x * 65535.0).round() as u32;
    for b in backends("core", false) {
        let Some(mut s) = Session::start(&b) else {
            continue;
        };
        if !s.caps("features").contains(&"gather".to_string()) {
            // softpipe has no shadow gather (its every gather case is a Skip).
            continue;
        }
        let mut cs = Vec::new();
        for d in KINDS {
            let mut c = d16_case(
                &format!("gather/delivery={d}"),
                Spec::Gl46,
                &[ApiPath::GlslCore],
                Target::T2d,
                0,
                0.5,
            );
            c.texture.levels[0] = Level {
                width: 4,
                height: 2,
                layers: 1,
                depth: Texels::Unorm(vec![0, q(0.25), 65535, 65535, q(0.75), 65535, 65535, 65535]),
                stencil: None,
            };
            c.lookup.coord = [0.25, 0.5, 0.0, 1.0];
            c.lookup.gather = Some(Gather { offsets: None });
            c.lookup.offset = [1, 0, 0];
            c.lookup.delivery = d;
            cs.push(c);
        }
        let answers = s.run(&cs);
        for (c, a) in cs.iter().zip(&answers) {
            assert_eq!(
                Session::rgba(a, ApiPath::GlslCore),
                [1.0, 1.0, 1.0, 0.0],
                "{b} {}: {a}",
                c.id
            );
        }
    }
}
