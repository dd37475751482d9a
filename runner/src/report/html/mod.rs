//! The self-contained HTML report (`shadowcheck report`): summary per backend, cross-driver
//! matrix, per-cell details, and SVG pictures (heatmaps, acceptance plots). Being built.
