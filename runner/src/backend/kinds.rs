//! The backend kinds, as a table: the name pattern each answers to, what it opens, one help line.
//! [`open`](super::open), the unknown-backend error and `run --help` all read [`KINDS`]; adding a
//! kind is one entry here and one module beside this one.

use super::exec::{self, ExecBackend, ProcessCommand};
use super::{mock, soft, Backend, BackendError, Options};

/// Opens a backend of one kind: the full name, the part after the first `:` (empty when none),
/// and the options of child-process backends.
pub type Opener = fn(&str, &str, &Options) -> Result<Box<dyn Backend>, BackendError>;

/// One kind of backend.
pub struct BackendKind {
    /// The part of the name before the first `:`.
    pub prefix: &'static str,
    /// The names it answers to, as written in errors and help.
    pub pattern: &'static str,
    /// One line for `run --help`.
    pub help: &'static str,
    pub open: Opener,
}

/// Every backend kind, in the order help and errors list them.
pub const KINDS: &[BackendKind] = &[
    BackendKind {
        prefix: "soft",
        pattern: "soft, soft:<spec>",
        help: "the project's own texture unit (each case under its own spec, or one spec only)",
        open: open_soft,
    },
    BackendKind {
        prefix: "exec",
        pattern: "exec:<command>",
        help: "an external implementation speaking runner/PROTOCOL.md",
        open: open_exec,
    },
    BackendKind {
        prefix: "egl",
        pattern: "egl:*",
        help: "egl[@<lib-dir>]:<driver>:<api>[:<form>], a GL driver through EGL (surfaceless, or EGL 1.4 pbuffer) in a gl-worker child",
        open: open_gl,
    },
    BackendKind {
        prefix: "osmesa",
        pattern: "osmesa:*",
        help: "osmesa:<driver>:<api>[:<form>], a Mesa driver through OSMesa in a gl-worker child",
        open: open_gl,
    },
    BackendKind {
        prefix: "webgl",
        pattern: "webgl:chromium",
        help: "WebGL 2.0 in headless Chromium (ANGLE on SwiftShader), the es300 path, in a webgl-worker child",
        open: open_webgl,
    },
    BackendKind {
        prefix: "mock",
        pattern: "mock:<script>",
        help: "a scripted implementation for testing the runner itself",
        open: open_mock,
    },
];

/// The kind a backend name belongs to.
pub fn kind_of(name: &str) -> Option<&'static BackendKind> {
    let prefix = name.split_once(':').map_or(name, |(k, _)| k);
    // `egl@<lib-dir>:...`: an EGL backend with its library directory.
    let prefix = prefix.split_once('@').map_or(prefix, |(k, _)| k);
    KINDS.iter().find(|k| k.prefix == prefix)
}

/// The name patterns, comma-separated (`soft, soft:<spec>, exec:<command>, ...`).
pub fn patterns() -> String {
    KINDS
        .iter()
        .map(|k| k.pattern)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The `--backend` help of `shadowcheck run`: the patterns, then one line per kind.
pub fn help() -> String {
    let mut s = format!(
        "Backend to run (repeatable): {}. Default: soft plus every GL driver found on this machine.",
        patterns()
    );
    for k in KINDS {
        s.push_str(&format!("\n  {}: {}", k.pattern, k.help));
    }
    s
}

fn setup(name: &str, msg: impl ToString) -> BackendError {
    BackendError::Setup {
        backend: name.into(),
        msg: msg.to_string(),
    }
}

fn open_soft(name: &str, rest: &str, _: &Options) -> Result<Box<dyn Backend>, BackendError> {
    Ok(Box::new(soft::SoftBackend::new(name, rest)?))
}

fn open_exec(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let argv = exec::split_command(rest).map_err(|msg| setup(name, msg))?;
    let Some((program, args)) = argv.split_first() else {
        return Err(setup(name, "empty command"));
    };
    let cmd = ProcessCommand {
        program: program.into(),
        args: args.to_vec(),
        env: vec![],
    };
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_gl(name: &str, _: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let mut cmd = super::gl::worker_command(name).map_err(|e| setup(name, e))?;
    if opts.fast_compile {
        cmd.env.push(("GALLIVM_PERF".into(), "nopt".into()));
    }
    let compiles = super::gl::compiles_per_state(name);
    Ok(Box::new(
        ExecBackend::start(name, cmd, opts)?.with_compiles_per_state(compiles),
    ))
}

fn open_webgl(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let cmd = super::webgl::worker_command(rest).map_err(|e| setup(name, e))?;
    Ok(Box::new(ExecBackend::start(name, cmd, opts)?))
}

fn open_mock(name: &str, rest: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let exe = std::env::current_exe().map_err(|e| setup(name, e))?;
    mock::Script::parse(rest).map_err(|msg| setup(name, msg))?;
    let cmd = ProcessCommand {
        program: exe,
        args: vec!["mock-worker".into(), rest.to_string()],
        env: vec![],
    };
    Ok(Box::new(
        ExecBackend::start(name, cmd, opts)?.with_compiles_per_state(false),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unknown_backend_error_lists_every_kind() {
        assert_eq!(
            patterns(),
            "soft, soft:<spec>, exec:<command>, egl:*, osmesa:*, webgl:chromium, mock:<script>"
        );
        assert!(kind_of("egl:llvmpipe:core").is_some_and(|k| k.prefix == "egl"));
        assert!(kind_of("soft").is_some_and(|k| k.prefix == "soft"));
        assert!(kind_of("nonsense:x").is_none());
        assert!(kind_of("egl@/opt/vendor/lib:native:es3").is_some_and(|k| k.prefix == "egl"));
        assert_eq!(help().lines().count(), KINDS.len() + 1);
    }
}
