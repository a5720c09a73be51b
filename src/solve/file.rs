//! A problem file solved: read, validated and solved in one call, the path the command line,
//! the tests and the benchmarks all take.

use std::path::Path;

use crate::core::Real;
use crate::problem::{self, Problem, ProblemError};

use super::{solve, Solution};

/// Loads, validates and solves one file in precision `R`.
pub fn solve_file<R: Real>(path: &Path) -> Result<(Problem<R>, Solution<R>), ProblemError> {
    let (_, problem) = problem::load::<R>(path)?;
    let solution = solve(&problem).map_err(|e| e.at(path))?;
    Ok((problem, solution))
}
