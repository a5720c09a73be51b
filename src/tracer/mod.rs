//! The Whitted ray tracer (Section 4.4): camera rays through each pixel, the nearest hit shaded
//! by the core's own [`crate::core::shade`] with shadow rays, and reflection rays
//! R_V = V − 2(N·V)N (Eq. 4.17) followed while their level ≤ the maximum level and their weight
//! w_s = w_p·max(O_r) exceeds the minimum weight (DESIGN.md).
//!
//! - [`camera`]: pixel → primary ray.
//! - [`sampler`]: where in the pixel each sample goes (stratified, deterministic).
//! - [`trace`]: one ray's path (the hot path, and the same path recorded for an explanation).
//! - [`render`]: the image, rows in parallel, bytes independent of the thread count.
//! - [`wide`]: the same paths traced in packets of lanes, queues per bounce (the default engine).
//! - [`explain`]: one pixel's derivation, every ray solved by the solver.
//! - [`output`]: PNG and PPM files.

pub mod camera;
pub mod explain;
pub mod output;
pub mod render;
pub mod sampler;
pub mod trace;
pub mod wide;

pub use camera::CameraRays;
pub use explain::{explain_pixel, PixelExplanation};
pub use render::{render, render_linear, render_linear_with, render_with, Image, LinearImage};
pub use trace::{Counts, Scene, Stop, Tracer};
pub use wide::Engine;
