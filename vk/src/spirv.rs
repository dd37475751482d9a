//! GLSL 4.50 for Vulkan to SPIR-V, by `glslangValidator -V` (Debian package glslang-tools), at
//! run time. Vulkan 1.3 §9 "Shaders" takes SPIR-V words only.

use crate::VkError;
use std::io::Write;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The compiler's program name.
pub const GLSLANG: &str = "glslangValidator";
/// What installs it.
pub const GLSLANG_INSTALL: &str = "apt-get install -y glslang-tools";

/// `Ok(version line)` when the compiler runs, else the setup error naming the package.
pub fn check_compiler() -> Result<String, VkError> {
    let out = Command::new(GLSLANG)
        .arg("--version")
        .stdin(Stdio::null())
        .output()
        .map_err(|e| {
            VkError::Glslang(format!("cannot run {GLSLANG} ({e}); `{GLSLANG_INSTALL}`"))
        })?;
    let text = String::from_utf8_lossy(&out.stdout);
    Ok(text.lines().next().unwrap_or("").trim().to_string())
}

static COUNTER: AtomicUsize = AtomicUsize::new(0);

/// The SPIR-V words of `source` for `stage` (`vert`, `frag` or `comp`).
pub fn compile(source: &str, stage: &str) -> Result<Vec<u32>, VkError> {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!(
        "shadowcheck-vk-{}-{n}.{stage}.spv",
        std::process::id()
    ));
    let result = run(source, stage, &path);
    let _ = std::fs::remove_file(&path);
    result
}

fn run(source: &str, stage: &str, path: &std::path::Path) -> Result<Vec<u32>, VkError> {
    let mut child = Command::new(GLSLANG)
        .args(["-V", "--stdin", "-S", stage, "-o"])
        .arg(path)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| {
            VkError::Glslang(format!("cannot run {GLSLANG} ({e}); `{GLSLANG_INSTALL}`"))
        })?;
    if let Some(mut stdin) = child.stdin.take() {
        stdin
            .write_all(source.as_bytes())
            .map_err(|e| VkError::Glslang(e.to_string()))?;
    }
    let out = child
        .wait_with_output()
        .map_err(|e| VkError::Glslang(e.to_string()))?;
    if !out.status.success() {
        let log = String::from_utf8_lossy(&out.stdout);
        let errors: Vec<&str> = log.lines().filter(|l| l.contains("ERROR")).collect();
        return Err(VkError::Glslang(format!(
            "{stage} shader does not compile: {}\n{source}",
            errors.join(" | ")
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| VkError::Glslang(e.to_string()))?;
    ash::util::read_spv(&mut std::io::Cursor::new(bytes))
        .map_err(|e| VkError::Glslang(format!("bad SPIR-V: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_of_a_case_compiles_when_the_compiler_is_installed() {
        if check_compiler().is_err() {
            eprintln!("SKIP: {GLSLANG} not installed; `{GLSLANG_INSTALL}`");
            return;
        }
        use shadowcheck_model::{ApiPath, Target};
        use shadowcheck_plan::{paths, shaders, test_case::case};
        for (t, layers) in [
            (Target::T1d, 1),
            (Target::T2d, 1),
            (Target::Cube, 6),
            (Target::T1dArray, 2),
            (Target::T2dArray, 2),
            (Target::CubeArray, 12),
        ] {
            let c = case(t, 4, if t.dims() == 1 { 1 } else { 4 }, layers);
            let plan = paths::plan(ApiPath::Vulkan, &c).expect("plan");
            let (vs, fs) = shaders::vulkan::glsl(&plan.key, shadowcheck_plan::layout::FB_SIZE);
            let v = compile(&vs, "vert").expect("vertex");
            let f = compile(&fs, "frag").expect("fragment");
            assert_eq!((v[0], f[0]), (0x0723_0203, 0x0723_0203), "SPIR-V magic");
            // The same lookup, and a gather where the target has one, in a compute shader.
            let mut c = c;
            c.lookup.stage = shadowcheck_model::Stage::Compute;
            let mut keys = vec![paths::plan(ApiPath::Vulkan, &c).expect("compute plan").key];
            if matches!(t, Target::T2d | Target::Cube | Target::CubeArray) {
                c.lookup.gather = Some(shadowcheck_model::Gather { offsets: None });
                keys.push(
                    paths::plan(ApiPath::Vulkan, &c)
                        .expect("compute gather")
                        .key,
                );
            }
            for key in keys {
                let cs = shaders::vulkan::compute_glsl(&key);
                assert_eq!(
                    compile(&cs, "comp").expect("compute")[0],
                    0x0723_0203,
                    "{cs}"
                );
            }
        }
    }
}
