//! Where a backend's EGL library comes from: the system's `libEGL.so.1`, a directory named in the
//! backend name (`egl@<dir>:<driver>:<api>`), or the SwiftShader preset's cache directory.
//!
//! The runner passes the choice to the worker child through [`LIBEGL_ENV`](crate::context::LIBEGL_ENV)
//! and `LD_LIBRARY_PATH` (so that the library's own libGLESv2 is the one it binds); the backend name
//! is what the user writes.

use super::WorkerError;
use std::path::{Path, PathBuf};

/// Names the SwiftShader directory instead of the cache default.
pub const SWIFTSHADER_DIR_ENV: &str = "SHADOWCHECK_SWIFTSHADER_DIR";
/// The libraries the SwiftShader preset loads (from the cefpython3 66.0 wheel).
pub const SWIFTSHADER_LIBS: [&str; 2] = ["libEGL.so", "libGLESv2.so"];
/// How to fetch them (run from the shadowcheck source tree; see runner/README.md, "Backends").
pub const SWIFTSHADER_FETCH: &str = "sh gl/fetch-swiftshader.sh";

/// SwiftShader's directory: `$SHADOWCHECK_SWIFTSHADER_DIR`, else
/// `$XDG_CACHE_HOME/shadowcheck/swiftshader-4.0.0.3` (`~/.cache` when XDG_CACHE_HOME is unset), where
/// `gl/fetch-swiftshader.sh` puts it.
pub fn swiftshader_dir() -> PathBuf {
    if let Some(d) = std::env::var_os(SWIFTSHADER_DIR_ENV) {
        return PathBuf::from(d);
    }
    let cache = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    cache.join("shadowcheck").join("swiftshader-4.0.0.3")
}

/// The libEGL file of a directory: `libEGL.so.1` if present, else `libEGL.so`.
pub fn libegl_in(dir: &Path) -> PathBuf {
    let one = dir.join("libEGL.so.1");
    if one.is_file() {
        one
    } else {
        dir.join("libEGL.so")
    }
}

/// The first library of `libs` missing from `dir`, if any.
pub fn missing_lib(dir: &Path, libs: &[&str]) -> Option<PathBuf> {
    libs.iter().map(|l| dir.join(l)).find(|p| !p.is_file())
}

/// The worker's environment for loading libEGL from `dir`.
pub fn lib_dir_env(dir: &Path) -> Vec<(String, String)> {
    let mut path = dir.display().to_string();
    if let Some(old) = std::env::var_os("LD_LIBRARY_PATH").filter(|o| !o.is_empty()) {
        path = format!("{path}:{}", old.to_string_lossy());
    }
    vec![
        (
            crate::context::LIBEGL_ENV.to_string(),
            libegl_in(dir).display().to_string(),
        ),
        ("LD_LIBRARY_PATH".to_string(), path),
    ]
}

/// Splits `egl@<dir>:<rest>` into the directory and `egl:<rest>`; other names are returned as
/// they are. The directory may not contain `:`.
pub fn split_lib_dir(name: &str) -> Result<(Option<PathBuf>, String), WorkerError> {
    let Some(after) = name.strip_prefix("egl@") else {
        return Ok((None, name.to_string()));
    };
    let bad = |why: &str| WorkerError::BadName {
        name: name.to_string(),
        why: why.to_string(),
    };
    let (dir, rest) = after
        .split_once(':')
        .ok_or_else(|| bad("expected egl@<lib-dir>:<driver>:<api>"))?;
    if dir.is_empty() {
        return Err(bad("the library directory after `egl@` is empty"));
    }
    Ok((Some(PathBuf::from(dir)), format!("egl:{rest}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_library_directory_is_part_of_the_name() {
        let (dir, rest) = split_lib_dir("egl@/opt/vendor/lib:native:es3").unwrap();
        assert_eq!(dir, Some(PathBuf::from("/opt/vendor/lib")));
        assert_eq!(rest, "egl:native:es3");
        assert_eq!(
            split_lib_dir("egl:llvmpipe:core").unwrap(),
            (None, "egl:llvmpipe:core".to_string())
        );
        assert!(split_lib_dir("egl@:native:es3").is_err());
        assert!(split_lib_dir("egl@/x").is_err());
        let env = lib_dir_env(Path::new("/opt/v"));
        assert_eq!(
            env[0],
            ("SHADOWCHECK_LIBEGL".into(), "/opt/v/libEGL.so".into())
        );
        assert!(env[1].1.starts_with("/opt/v"), "{:?}", env[1]);
    }
}
