//! The Whitted ray tracer (Section 4.4): camera rays through each pixel, the nearest hit shaded
//! by the core's own [`crate::core::shade()`] with shadow rays, and reflection rays
//! R_V = V − 2(N·V)N (Eq. 4.17) followed while their level ≤ the maximum level and their weight
//! w_s = w_p·max(O_r) exceeds the minimum weight (docs/conventions.md, "Recursion level" and
//! "Weight").
//!
//! - `camera`: pixel → primary ray.
//! - `sampler`: where in the pixel each sample goes (stratified, deterministic).
//! - `trace`: one ray's path (the hot path, and the same path recorded for an explanation).
//! - [`render`](mod@render): the image, rows in parallel, bytes independent of the thread count.
//! - `wide`: the same paths traced in packets of lanes, queues per bounce (the default engine).
//! - `explain`: one pixel's derivation, every ray solved by the solver.
//! - [`output`]: PNG and PPM files.

pub(crate) mod camera;
pub(crate) mod explain;
pub(crate) mod faults;
pub mod output;
pub mod render;
pub(crate) mod sampler;
pub(crate) mod trace;
pub(crate) mod wide;

pub use camera::CameraRays;
pub use explain::{explain_pixel, PixelExplanation, RayExplanation, SampleExplanation};
pub use render::{render, render_with, Image};
pub(crate) use render::{render_linear_with, LinearImage};
pub use trace::{
    Counts, PathRecorder, RayKind, RayRecord, Refraction, Scene, Spawn, Stop, Tracer,
    TransmissionRecord,
};
pub use wide::Engine;
