//! phong: solve, check and explain the illumination exercises of Chapter 4 ("Modelos de
//! Iluminação") and render their scenes with the same shading core.
//!
//! - [`check`]: checks answers against a solution and names the slips that explain a wrong one.
//! - [`core`]: the Phong model itself, pure, generic over f32/f64.
//! - [`generate`]: fresh problems friendly to hand calculation (`phong new`).
//! - [`geometry`]: rays, planes, spheres, triangles, their intersections and the BVH.
//! - [`problem`]: the JSON problem format, its parsing and validation.
//! - [`solve`]: turns a validated problem into a solution with every intermediate.
//! - [`report`]: explains a solution (text, Markdown, LaTeX, HTML; English or Portuguese) or
//!   writes it as stable JSON.
//! - [`tracer`]: the Whitted ray tracer, shading with the same core.
//! - [`tradeoff`]: what each tracer setting costs in time and buys in accuracy (`phong tradeoff`).
//! - [`export`]: the scene for other renderers (POV-Ray), to cross-check the tracer.
//! - [`cli`]: the `phong` command line.

pub mod check;
#[doc(hidden)]
pub mod cli;
pub mod core;
pub mod export;
pub(crate) mod generate;
pub mod geometry;
pub mod problem;
pub mod report;
pub mod solve;
pub mod tracer;
pub(crate) mod tradeoff;
