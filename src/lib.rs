//! phong: solve, check and explain the illumination exercises of Chapter 4 ("Modelos de
//! Iluminação") and, later, render their scenes with the same shading core.
//!
//! - [`check`]: checks answers against a solution and names the slips that explain a wrong one.
//! - [`core`]: the Phong model itself, pure, generic over f32/f64.
//! - [`generate`]: fresh problems friendly to hand calculation (`phong new`).
//! - [`geometry`]: rays, planes, spheres and their intersections.
//! - [`problem`]: the JSON problem format, its parsing and validation.
//! - [`solve`]: turns a validated problem into a solution with every intermediate.
//! - [`report`]: writes a solution as text or as stable JSON.
//! - [`cli`]: the `phong` command line.

pub mod check;
pub mod cli;
pub mod core;
pub mod generate;
pub mod geometry;
pub mod problem;
pub mod report;
pub mod solve;
