//! Shared helpers for the GL integration tests: start a real `shadowcheck gl-worker`, speak the
//! protocol, and build hand-made cases. A missing driver is a loud skip, or a failure under CI=true.
#![allow(dead_code)]

use serde_json::{json, Value};
use shadowcheck_model::*;
use std::io::{BufRead, BufReader, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, ChildStdout, Stdio};

pub struct Session {
    pub backend: String,
    child: Child,
    stdin: Option<ChildStdin>,
    stdout: BufReader<ChildStdout>,
    pub hello: Value,
}

fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true")
}

/// A driver is missing: panic under CI=true, otherwise say so loudly and let the test pass.
pub fn unavailable(backend: &str, why: &str) {
    let msg = format!(
        "GL backend {backend} unavailable: {why}\n  install the Mesa runtime: apt-get install -y libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers"
    );
    if in_ci() {
        panic!("{msg} (CI=true: a missing driver is a failure)");
    }
    // Straight to the stderr handle: libtest captures eprintln!, which would hide the skip.
    use std::io::Write as _;
    let _ = writeln!(std::io::stderr(), "SKIPPED (not a pass): {msg}");
}

impl Session {
    /// Starts the worker; `None` when the backend is unavailable (after `unavailable`).
    pub fn start(backend: &str) -> Option<Session> {
        Session::start_with_env(backend, &[])
    }

    /// [`Session::start`] with extra environment variables for the worker.
    pub fn start_with_env(backend: &str, extra: &[(&str, &str)]) -> Option<Session> {
        let mut wc = match shadowcheck_runner::backend::gl::worker_command(backend) {
            Ok(wc) => wc,
            Err(e) => {
                unavailable(backend, &e.to_string());
                return None;
            }
        };
        wc.program = PathBuf::from(env!("CARGO_BIN_EXE_shadowcheck"));
        wc.env
            .extend(extra.iter().map(|(k, v)| (k.to_string(), v.to_string())));
        let mut child = wc
            .to_command()
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("spawn gl-worker");
        let stdin = child.stdin.take();
        let stdout = BufReader::new(child.stdout.take().expect("stdout"));
        let mut s = Session {
            backend: backend.to_string(),
            child,
            stdin,
            stdout,
            hello: Value::Null,
        };
        s.send(&json!({"type": "hello", "protocol": 1}));
        match s.read() {
            Some(h) => {
                assert_eq!(h["type"], "hello", "{h}");
                s.hello = h;
                Some(s)
            }
            None => {
                let mut err = String::new();
                if let Some(mut e) = s.child.stderr.take() {
                    let _ = std::io::Read::read_to_string(&mut e, &mut err);
                }
                let _ = s.child.wait();
                unavailable(backend, err.trim());
                None
            }
        }
    }

    fn send(&mut self, v: &Value) {
        if let Some(i) = self.stdin.as_mut() {
            let _ = writeln!(i, "{v}");
            let _ = i.flush();
        }
    }

    fn read(&mut self) -> Option<Value> {
        let mut line = String::new();
        match self.stdout.read_line(&mut line) {
            Ok(0) | Err(_) => None,
            Ok(_) => Some(
                serde_json::from_str(&line)
                    .unwrap_or_else(|e| panic!("bad line from worker: {e}: {line}")),
            ),
        }
    }

    pub fn caps(&self, list: &str) -> Vec<String> {
        self.hello["capabilities"][list]
            .as_array()
            .map(|a| {
                a.iter()
                    .filter_map(|v| v.as_str().map(String::from))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// Sends the cases and a flush; returns one answer per case, in order.
    pub fn run(&mut self, cases: &[Case]) -> Vec<Value> {
        for c in cases {
            self.send(&json!({"type": "case", "case": c}));
        }
        self.send(&json!({"type": "flush"}));
        let answers: Vec<Value> = (0..cases.len())
            .map(|_| self.read().expect("worker died"))
            .collect();
        for (c, a) in cases.iter().zip(&answers) {
            assert_eq!(a["case_id"], c.id.as_str(), "answers in order");
        }
        answers
    }

    /// The rgba of `api` in an observation (panics on skip/error, showing it).
    pub fn rgba(answer: &Value, api: ApiPath) -> [f64; 4] {
        assert_eq!(answer["type"], "observation", "{answer}");
        let r = answer["results"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["api"] == api.key())
            .unwrap_or_else(|| panic!("no {api} result in {answer}"));
        let v: Vec<f64> = r["rgba"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        [v[0], v[1], v[2], v[3]]
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let _ = self.child.wait();
    }
}

/// Each backend of a context kind, for the tests to loop over.
pub fn backends(api: &str, with_osmesa: bool) -> Vec<String> {
    let mut v: Vec<String> = ["llvmpipe", "softpipe", "zink"]
        .iter()
        .map(|d| format!("egl:{d}:{api}"))
        .collect();
    if with_osmesa {
        v.extend(
            ["llvmpipe", "softpipe"]
                .iter()
                .map(|d| format!("osmesa:{d}:{api}")),
        );
    }
    v
}

/// A D16 texture of one level with every texel `c`, and a nearest LEQUAL compare sampler.
pub fn d16_case(id: &str, spec: Spec, api: &[ApiPath], target: Target, c: u32, dref: f64) -> Case {
    let (w, h, layers) = match target {
        Target::T1d => (2, 1, 1),
        Target::T1dArray => (2, 1, 3),
        Target::Cube => (2, 2, 6),
        Target::CubeArray => (2, 2, 12),
        Target::T2dArray => (2, 2, 3),
        _ => (2, 2, 1),
    };
    let n = (w * h * layers) as usize;
    let coord = match target {
        Target::Rect => [1.0, 1.0, 0.0, 1.0],
        Target::Cube | Target::CubeArray => [0.25, 0.5, 1.0, 1.0],
        Target::T1dArray => [0.25, 1.0, 0.0, 1.0],
        Target::T2dArray => [0.25, 0.5, 2.0, 1.0],
        _ => [0.25, 0.75, 0.0, 1.0],
    };
    Case {
        sweep: vec![],
        id: id.to_string(),
        spec,
        api: api.to_vec(),
        texture: Texture {
            target,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: w,
                height: h,
                layers,
                depth: Texels::Unorm(vec![c; n]),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest),
        lookup: Lookup {
            coord,
            layer: if target == Target::CubeArray {
                1.0
            } else {
                0.0
            },
            dref,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: None,
    }
}

/// A 4x4 2D (or cube / array) texture with three mip levels whose texels are 0, 65535, 0 by level,
/// sampled with NEAREST_MIPMAP_NEAREST and LEQUAL against 0.5: r = 1 exactly when level 1 is chosen.
pub fn mip_case(
    id: &str,
    spec: Spec,
    api: &[ApiPath],
    target: Target,
    lod: f64,
    bias: f64,
) -> Case {
    let layers = match target {
        Target::Cube => 6,
        Target::CubeArray => 12,
        Target::T2dArray => 2,
        _ => 1,
    };
    let mut c = d16_case(id, spec, api, target, 0, 0.5);
    c.texture.levels = [4u32, 2, 1]
        .iter()
        .enumerate()
        .map(|(i, &s)| Level {
            width: s,
            height: s,
            layers,
            depth: Texels::Unorm(vec![
                if i == 1 { 65535 } else { 0 };
                (s * s * layers) as usize
            ]),
            stencil: None,
        })
        .collect();
    c.sampler = Sampler::new(
        CompareMode::Compare,
        CompareFunc::Lequal,
        Filter::NearestMipmapNearest,
    );
    if target == Target::T2dArray {
        c.lookup.coord = [0.25, 0.5, 1.0, 1.0];
    }
    c.lookup.lod = lod;
    c.lookup.bias = bias;
    c
}

/// Can this machine build a reproducer (a C compiler and the EGL/GL headers)?
pub fn can_build(backend: &str) -> bool {
    let header = if backend.starts_with("osmesa:") {
        "/usr/include/GL/osmesa.h"
    } else {
        "/usr/include/EGL/egl.h"
    };
    let cc = std::process::Command::new("cc").arg("--version").output();
    if !matches!(cc, Ok(o) if o.status.success()) || !std::path::Path::new(header).is_file() {
        unavailable(
            backend,
            &format!("no C compiler or no {header} to build the reproducer (apt-get install -y gcc libegl-dev libgles-dev libgl-dev libosmesa6-dev)"),
        );
        return false;
    }
    true
}
