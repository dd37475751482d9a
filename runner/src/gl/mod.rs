//! GL driver backends (EGL, OSMesa) — being built.
