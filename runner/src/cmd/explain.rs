//! `shadowcheck explain`: what the specifications say about one case — spec value, acceptance per
//! profile, layout per API path, derivation with section citations, footprint and the contradictions
//! the case touches (with the value under the other reading).
//!
//! The case comes from flags (`--spec gl46 --format d24 --func lequal --filter nearest --ref 1.5 --dt 1.0`)
//! or from a JSON file (`--case FILE`, a single case or a fixture file with `--id ID`).
use anyhow::{bail, Context};
use shadowcheck_model::*;
use std::path::PathBuf;
use std::process::ExitCode;

/// Exit code when the case is valid but not a lookup: the implementation may raise a GL error or
/// the result is undefined.
const NOT_A_LOOKUP: u8 = 1;

#[derive(clap::Args)]
pub struct Args {
    /// A JSON case file: one case, or a fixture file (`{"schema_version":1, ..., "cases":[...]}`) with --id.
    #[arg(long, value_name = "FILE")]
    case: Option<PathBuf>,
    /// The case id inside a fixture file.
    #[arg(long)]
    id: Option<String>,
    /// Print the oracle's Evaluation as JSON instead of text.
    #[arg(long)]
    json: bool,
    /// Spec variant: sgix, sgix_ambient, arb, arb_ambient, ext_funcs, es2_ext, gl46, gles32.
    #[arg(long, default_value = "gl46")]
    spec: String,
    /// Texture format: d16, d24, d32, d32f, d24s8, d32fs8, depth, r8.
    #[arg(long, default_value = "d24")]
    format: String,
    /// Target: 1d, 2d, rect, cube, 1darray, 2darray, cubearray.
    #[arg(long, default_value = "2d")]
    target: String,
    /// Compare function (lequal ... always; lequal_r_sgix / gequal_r_sgix). Default: the spec's LEQUAL.
    #[arg(long)]
    func: Option<String>,
    /// Compare mode: compare or none.
    #[arg(long, default_value = "compare")]
    mode: String,
    /// Minification filter (nearest, linear, nmn, lmn, nml, lml); the magnification filter follows it
    /// unless --mag is given.
    #[arg(long, default_value = "nearest")]
    filter: String,
    /// Magnification filter (nearest, linear). Default: the class of --filter.
    #[arg(long)]
    mag: Option<String>,
    /// Wrap mode for s, t and r: edge, repeat, mirror, border, mirror_edge, clamp. Default: edge
    /// (clamp for sgix and sgix_ambient, whose Table 3.8 lists only CLAMP and REPEAT).
    #[arg(long)]
    wrap: Option<String>,
    /// Border depth (TEXTURE_BORDER_COLOR[0]).
    #[arg(long, default_value_t = 0.0)]
    border: f32,
    /// The reference value Dref / R.
    #[arg(long = "ref", default_value_t = 0.5, allow_negative_numbers = true)]
    dref: f64,
    /// Depth texel values, comma-separated (floats; unorm formats store the nearest integer). 1 → 1x1, 2 → 2x1, 4 → 2x2,
    /// n → n x 1 (1D/2D/rect); one value per layer for arrays, per face for cube maps (6 per cube).
    #[arg(long, value_delimiter = ',', num_args = 1, default_values_t = vec![0.5], allow_hyphen_values = true)]
    dt: Vec<f64>,
    /// Stencil values (DEPTH_STENCIL formats), same layout as --dt.
    #[arg(long, value_delimiter = ',', num_args = 1..)]
    st: Vec<u8>,
    /// Texture coordinates s,t,r,q (comma-separated). Default: the centre of the image (cube: +X direction).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    coord: Vec<f64>,
    /// Array layer (cube arrays: the cube index).
    #[arg(long, default_value_t = 0.0)]
    layer: f64,
    /// Projective lookup (coordinates and Dref divided by q).
    #[arg(long)]
    projective: bool,
    /// λ_base (explicit level of detail).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    lod: f64,
    /// Shader bias.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    bias: f64,
    /// Texel offset du,dv[,dw] of the GLSL `*Offset` lookups (GLSL >= 1.30 / ES 3.00 paths; -8..=7).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    offset: Vec<i32>,
    /// How the shader receives the values: literal, uniform, flat, per_fragment (glsl130, core,
    /// es300 paths; changes no expectation, the derivation says why).
    #[arg(long, default_value = "literal")]
    delivery: String,
    /// The shader stage of the lookup: fragment, vertex (glsl120, glsl130, core, es300 paths) or
    /// compute (core, es300); outside the fragment stage λ_base is 0 and --lod is the fragment
    /// shader's (GLSL 4.60 §8.9).
    #[arg(long, default_value = "fragment")]
    stage: String,
    /// TEXTURE_COMPARE_FAIL_VALUE_ARB / SHADOW_AMBIENT_SGIX.
    #[arg(long)]
    fail: Option<f32>,
    /// DEPTH_TEXTURE_MODE: luminance, intensity, alpha, red.
    #[arg(long)]
    depth_mode: Option<String>,
    /// DEPTH_STENCIL_TEXTURE_MODE: depth or stencil.
    #[arg(long)]
    stencil_mode: Option<String>,
    /// API paths (ff, arbfp, glsl120, glsl130, core, es100, es300, vk). Default: one natural path of the spec.
    #[arg(long, value_delimiter = ',', num_args = 1..)]
    api: Vec<String>,
}

fn key<T: std::str::FromStr>(s: &str) -> anyhow::Result<T>
where
    T::Err: std::fmt::Display,
{
    s.parse::<T>().map_err(|e| anyhow::anyhow!("{e}"))
}

fn default_api(spec: Spec, target: Target) -> ApiPath {
    match spec {
        Spec::Sgix | Spec::SgixAmbient | Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs => {
            ApiPath::FixedFunction
        }
        Spec::Es2Ext => ApiPath::Es100Ext,
        Spec::Gles32 => ApiPath::Es300,
        Spec::Vulkan => ApiPath::Vulkan,
        Spec::WebGpu => ApiPath::Wgsl,
        Spec::Gl46 if target == Target::CubeArray => ApiPath::GlslCore,
        Spec::Gl46 => ApiPath::GlslCore,
    }
}

/// Builds a case from the flags.
fn case_from_flags(a: &Args) -> anyhow::Result<Case> {
    let spec: Spec = key(&a.spec)?;
    let format: Format = key(&a.format)?;
    let target: Target = key(&a.target)?;
    let func: CompareFunc = match &a.func {
        Some(f) => key(f)?,
        None if matches!(spec, Spec::Sgix | Spec::SgixAmbient) => CompareFunc::LequalRSgix,
        None => CompareFunc::Lequal,
    };
    let filter: Filter = key(&a.filter)?;
    let mut sampler = Sampler::new(key(&a.mode)?, func, filter);
    if let Some(m) = &a.mag {
        sampler.mag_filter = key(m)?;
    }
    let wrap: Wrap = match &a.wrap {
        Some(w) => key(w)?,
        None if matches!(spec, Spec::Sgix | Spec::SgixAmbient) => Wrap::Clamp,
        None => Wrap::ClampToEdge,
    };
    (sampler.wrap_s, sampler.wrap_t, sampler.wrap_r) = (wrap, wrap, wrap);
    sampler.border = [a.border, 0.0, 0.0, 0.0];
    sampler.fail_value = a.fail;
    sampler.depth_texture_mode = a.depth_mode.as_deref().map(key).transpose()?;
    sampler.depth_stencil_mode = a.stencil_mode.as_deref().map(key).transpose()?;
    let n = a.dt.len() as u32;
    let (width, height, layers) = match target {
        Target::T1d => (n, 1, 1),
        Target::T2d | Target::Rect => match n {
            4 => (2, 2, 1),
            _ => (n, 1, 1),
        },
        Target::T1dArray | Target::T2dArray => (1, 1, n),
        Target::Cube | Target::CubeArray => (1, 1, n.div_ceil(6).max(1) * 6),
    };
    let mut vals = a.dt.clone();
    while (vals.len() as u32) < width * height * layers {
        vals.push(*a.dt.last().unwrap_or(&0.5));
    }
    let depth = match format.unorm_bits() {
        Some(b) => {
            let m = ((1u64 << b) - 1) as f64;
            Texels::Unorm(
                vals.iter()
                    .map(|v| (v.clamp(0.0, 1.0) * m).round() as u32)
                    .collect(),
            )
        }
        None => Texels::Float(vals.iter().map(|v| *v as f32).collect()),
    };
    let stencil = format.has_stencil().then(|| {
        let mut s = a.st.clone();
        s.resize(vals.len(), *a.st.last().unwrap_or(&0));
        s
    });
    let mut coord = match target {
        Target::Cube | Target::CubeArray => [1.0, 0.0, 0.0, 1.0],
        Target::Rect => [width as f64 / 2.0, height as f64 / 2.0, 0.0, 1.0],
        _ => [0.5, 0.5, 0.0, 1.0],
    };
    for (i, c) in a.coord.iter().enumerate() {
        coord[i] = *c;
    }
    if a.offset.len() > 3 {
        anyhow::bail!(
            "--offset takes at most three components (du,dv,dw), got {}",
            a.offset.len()
        );
    }
    let mut offset = [0; 3];
    offset[..a.offset.len()].copy_from_slice(&a.offset);
    let api: Vec<ApiPath> = if a.api.is_empty() && offset != [0; 3] {
        // Only GLSL >= 1.30 and GLSL ES 3.00 have offset lookups.
        vec![if spec == Spec::Gles32 {
            ApiPath::Es300
        } else {
            ApiPath::GlslCore
        }]
    } else if a.api.is_empty() {
        vec![default_api(spec, target)]
    } else {
        a.api
            .iter()
            .map(|s| key(s))
            .collect::<anyhow::Result<_>>()?
    };
    let mut id = format!(
        "explain/{}/{}/{}/{}/{}/ref={}/dt={}",
        spec,
        target,
        format,
        filter,
        func,
        a.dref,
        a.dt.iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join("_")
    );
    if offset != [0; 3] {
        id += &format!("/offset={}_{}_{}", offset[0], offset[1], offset[2]);
    }
    Ok(Case {
        sweep: vec![],
        id,
        spec,
        api,
        texture: Texture {
            target,
            format,
            base_level: 0,
            levels: vec![Level {
                width,
                height,
                layers,
                depth,
                stencil,
            }],
        },
        sampler,
        lookup: Lookup {
            coord,
            layer: a.layer,
            dref: a.dref,
            projective: a.projective,
            lod: a.lod,
            bias: a.bias,
            offset,
            gather: None,
            delivery: key(&a.delivery)?,
            stage: key(&a.stage)?,
        },
        expect: None,
    })
}

/// Reads a case from a JSON file: a single case, or a fixture file's case with the given id.
fn case_from_file(path: &PathBuf, id: Option<&str>) -> anyhow::Result<Case> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    let v: serde_json::Value =
        serde_json::from_str(&text).with_context(|| format!("parsing {}", path.display()))?;
    if let Some(cases) = v.get("cases").and_then(|c| c.as_array()) {
        let pick = match id {
            Some(id) => cases
                .iter()
                .find(|c| c.get("id").and_then(|i| i.as_str()) == Some(id))
                .with_context(|| format!("no case `{id}` in {}", path.display()))?,
            None if cases.len() == 1 => &cases[0],
            None => bail!(
                "{} holds {} cases: choose one with --id",
                path.display(),
                cases.len()
            ),
        };
        return serde_json::from_value(pick.clone())
            .with_context(|| format!("case in {}", path.display()));
    }
    serde_json::from_value(v)
        .with_context(|| format!("{} is neither a case nor a fixture file", path.display()))
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    let case = match &args.case {
        Some(p) => case_from_file(p, args.id.as_deref())?,
        None => case_from_flags(&args)?,
    };
    let result = shadowcheck_oracle::evaluate(&case);
    if args.json {
        let out = match &result {
            Ok(ev) => serde_json::to_string_pretty(ev)?,
            Err(e) => serde_json::to_string_pretty(
                &serde_json::json!({ "case": case.id, "error": e.to_string() }),
            )?,
        };
        super::print_out(&format!("{out}\n"))?;
    } else {
        let mut text = shadowcheck_oracle::explain::render(&case, &result);
        if let (Some(expect), Ok(ev)) = (&case.expect, &result) {
            if expect != &ev.expect {
                text += "note: the expectation stored in the file differs from the oracle's (regenerate the fixtures)\n";
            }
        }
        super::print_out(&text)?;
    }
    Ok(match result {
        Ok(_) => ExitCode::SUCCESS,
        // A GL error or an undefined lookup is a valid answer, but not a lookup: exit 1.
        Err(_) => ExitCode::from(NOT_A_LOOKUP),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: Args,
    }

    fn eval(flags: &str) -> Option<f64> {
        let cli = Cli::try_parse_from(std::iter::once("explain").chain(flags.split_whitespace()))
            .unwrap();
        let case = case_from_flags(&cli.args).unwrap();
        shadowcheck_oracle::evaluate(&case)
            .unwrap()
            .expect
            .spec_value
    }

    #[test]
    fn flags_build_the_brief_examples() {
        assert_eq!(eval("--spec gl46 --format d24 --target 2d --func lequal --filter nearest --ref 1.5 --dt 1.0"), Some(1.0));
        assert_eq!(
            eval("--spec gl46 --format d32f --ref 1.5 --dt 1.0"),
            Some(0.0)
        );
        assert_eq!(
            eval("--spec sgix --format d16 --ref 0.5 --dt 0.3"),
            Some(1.0)
        );
        assert_eq!(
            eval("--spec arb_ambient --fail 0.25 --ref 0.8 --dt 0.3"),
            Some(0.25)
        );
        // A 2x2 footprint sampled at its centre: two of four texels pass.
        assert_eq!(eval("--spec gl46 --format d16 --filter linear --ref 0.5 --dt 0.2,0.4,0.6,0.8 --func gequal"), Some(0.5));
        assert_eq!(
            eval("--spec gl46 --target cube --dt 1,0,0,0,0,0 --ref 0.5"),
            Some(1.0)
        );
    }

    #[test]
    fn fixture_files_are_read_by_id() {
        let dir = std::env::temp_dir().join(format!("shadowcheck-explain-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cli = Cli::try_parse_from(["explain", "--ref", "0.25", "--dt", "0.5"]).unwrap();
        let case = case_from_flags(&cli.args).unwrap();
        let file = dir.join("f.json");
        let fixture = serde_json::json!({ "schema_version": 1, "cases": [case.clone()] });
        std::fs::write(&file, fixture.to_string()).unwrap();
        assert_eq!(case_from_file(&file, Some(&case.id)).unwrap(), case);
        assert!(case_from_file(&file, Some("nope")).is_err());
        let single = dir.join("c.json");
        std::fs::write(&single, serde_json::to_string(&case).unwrap()).unwrap();
        assert_eq!(case_from_file(&single, None).unwrap(), case);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
