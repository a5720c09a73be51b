//! phong: solve, check and explain the illumination exercises of Chapter 4 ("Modelos de
//! Iluminação") and render their scenes with the same shading core.
//!
//! - [`text`]: how phong speaks: the language, numbers as people write them, and messages as
//!   values rendered in English or Portuguese.
//! - [`check`]: checks answers against a solution and names the slips that explain a wrong one.
//! - [`core`]: the Phong model itself, pure, generic over f32/f64.
//! - [`geometry`]: rays, planes, spheres, triangles, their intersections and the BVH.
//! - [`problem`]: the JSON problem format, its parsing and validation.
//! - [`solve`]: turns a validated problem into a solution with every intermediate.
//! - [`report`]: explains a solution (text, Markdown, LaTeX, HTML; English or Portuguese) or
//!   writes it as stable JSON.
//! - [`tracer`]: the Whitted ray tracer, shading with the same core.
//! - [`export`]: the scene for other renderers (POV-Ray), to cross-check the tracer.
//!
//! The binary's own modules are not part of the library's interface: `generate` (fresh problems
//! friendly to hand calculation, `phong new`), `tradeoff` (what each tracer setting costs in time
//! and buys in accuracy, `phong tradeoff`), `serve` (the checker as a web application, `phong
//! serve`, with the default feature `serve`) and `cli` (the `phong` command line; public only so
//! that `src/main.rs` can call `cli::main`, and hidden from the documentation).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod check;
#[doc(hidden)]
pub mod cli;
pub mod core;
pub mod export;
pub(crate) mod generate;
pub mod geometry;
pub mod problem;
pub mod report;
#[cfg(feature = "serve")]
pub(crate) mod serve;
pub mod solve;
pub mod text;
pub mod tracer;
pub(crate) mod tradeoff;

#[cfg(test)]
mod layers;
#[cfg(test)]
mod walk;
