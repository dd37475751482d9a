//! Which backends share texture-unit code (and API front-end code), so that the review queue counts
//! independent implementations, not backends.

/// One lineage rule: backends whose name is `prefix` or starts with `prefix:` sample with `unit`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Lineage {
    pub prefix: &'static str,
    pub unit: &'static str,
    /// The API front end above the unit (the code that validates state, decides completeness,
    /// routes DEPTH_TEXTURE_MODE and runs fixed function): `mesa` for every Mesa driver, zink on
    /// any Vulkan driver included; `""` where there is none (a Vulkan driver driven directly).
    pub front_end: &'static str,
    /// Why the backend samples with that unit's code.
    pub why: &'static str,
}

/// Which backends share texture-unit code, and so count as one voice.
///
/// Kept here, not as a column of `backend::kinds::KINDS`: a kind says how a backend is *opened*,
/// and lineage follows the driver inside the name. `egl:*` is one kind for every driver EGL loads
/// (`egl:llvmpipe` and `egl:softpipe`: one kind, two lineages), while `egl:zink` and
/// `osmesa:llvmpipe` are two kinds of one lineage; a per-kind column could not say either. No
/// opener needs the lineage either: only this argument about independence does.
///
/// A backend no rule names (`exec:...`, `mock:...`, `egl@DIR:native:*`, `vk:native`) is its own unit, named by its backend string: unknown code is assumed independent.
/// `egl@DIR:` is matched as `egl:` (another build of the same driver is the same code).
pub const LINEAGE: &[Lineage] = &[
    Lineage {
        prefix: "soft",
        unit: "soft",
        front_end: "soft",
        why: "the project's own texture unit (soft/), written from the specifications",
    },
    Lineage {
        prefix: "egl:llvmpipe",
        unit: "gallivm",
        front_end: "mesa",
        why: "llvmpipe samples with gallivm's code generator (lp_bld_sample)",
    },
    Lineage {
        prefix: "osmesa:llvmpipe",
        unit: "gallivm",
        front_end: "mesa",
        why: "llvmpipe, only the context comes from OSMesa",
    },
    Lineage {
        prefix: "egl:zink",
        unit: "gallivm",
        front_end: "mesa",
        why: "zink over lavapipe: lavapipe is llvmpipe's Vulkan driver and shares gallivm's sampler",
    },
    Lineage {
        prefix: "vk:lavapipe",
        unit: "gallivm",
        front_end: "",
        why: "lavapipe shares llvmpipe's gallivm sampler",
    },
    Lineage {
        prefix: "egl:softpipe",
        unit: "softpipe",
        front_end: "mesa",
        why: "softpipe's own C sampler (sp_tex_sample.c)",
    },
    Lineage {
        prefix: "osmesa:softpipe",
        unit: "softpipe",
        front_end: "mesa",
        why: "softpipe, only the context comes from OSMesa",
    },
    Lineage {
        prefix: "egl:swiftshader",
        unit: "swiftshader",
        front_end: "swiftshader-gles",
        why: "SwiftShader's own OpenGL ES driver",
    },
    Lineage {
        prefix: "egl:zink+swiftshader",
        unit: "swiftshader",
        front_end: "mesa",
        why: "zink over SwiftShader's Vulkan driver, whose sampler descends from the same code as its GLES driver",
    },
    Lineage {
        prefix: "vk:swiftshader",
        unit: "swiftshader",
        front_end: "",
        why: "SwiftShader's Vulkan driver, whose sampler descends from the same code as its GLES driver",
    },
    Lineage {
        prefix: "webgl:chromium",
        unit: "swiftshader",
        front_end: "angle",
        why: "ANGLE over SwiftShader: ANGLE translates, the lookups are SwiftShader's",
    },
    Lineage {
        prefix: "webgl:chromium-gles",
        unit: "gallivm",
        front_end: "angle",
        why: "ANGLE's OpenGL ES back end over Mesa's llvmpipe: ANGLE translates (and Mesa's GLES front end validates under it), the lookups are gallivm's",
    },
    Lineage {
        prefix: "webgl:chromium-lavapipe",
        unit: "gallivm",
        front_end: "angle",
        why: "ANGLE's Vulkan back end over lavapipe: ANGLE translates, the lookups are gallivm's",
    },
    Lineage {
        prefix: "webgpu:chromium",
        unit: "swiftshader",
        front_end: "dawn",
        why: "Dawn's Vulkan backend over SwiftShader: Dawn validates and translates WGSL, the lookups are SwiftShader's",
    },
    Lineage {
        prefix: "webgpu:chromium-compat",
        unit: "swiftshader",
        front_end: "dawn-angle",
        why: "Dawn's OpenGL ES backend over ANGLE's Vulkan back end over SwiftShader: the lookups are SwiftShader's",
    },
];

/// The lineage rule of `backend`, if one names it.
pub fn lineage_of(backend: &str) -> Option<&'static Lineage> {
    // `egl@<lib-dir>:<driver>:...` is matched as `egl:<driver>:...`.
    let name: String = match backend.split_once(':') {
        Some((kind, rest)) if kind.starts_with("egl@") => format!("egl:{rest}"),
        _ => backend.to_string(),
    };
    LINEAGE.iter().find(|l| {
        name == l.prefix
            || name
                .strip_prefix(l.prefix)
                .is_some_and(|rest| rest.starts_with(':'))
    })
}

/// The texture unit `backend` samples with: its lineage's unit, else the backend itself.
pub fn unit_of(backend: &str) -> String {
    lineage_of(backend).map_or_else(|| backend.to_string(), |l| l.unit.to_string())
}

/// The API front end `backend` runs under: its lineage's, else the backend itself (unknown code
/// is assumed to have a front end of its own).
pub fn front_end_of(backend: &str) -> String {
    match lineage_of(backend) {
        Some(l) if !l.front_end.is_empty() => l.front_end.to_string(),
        _ => backend.to_string(),
    }
}
