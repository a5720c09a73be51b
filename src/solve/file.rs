//! A problem file solved: read, validated and solved in one call, the path the command line,
//! the tests and the benchmarks all take.

use std::path::Path;

use crate::core::Real;
use crate::problem::{Problem, ProblemError, Source};

use super::{solve, Solution};

/// Loads, validates and solves one file in precision `R`.
pub fn solve_file<R: Real>(path: &Path) -> Result<(Problem<R>, Solution<R>), ProblemError> {
    solve_source::<R>(Source::File(path))
}

/// [`solve_file`] for a problem from any [`Source`] (text held in memory, for `phong serve`).
pub fn solve_source<R: Real>(
    source: Source<'_>,
) -> Result<(Problem<R>, Solution<R>), ProblemError> {
    if R::NAME == <f64 as Real>::NAME {
        let (_, problem) = source.load::<R>()?;
        let solution = solve(&problem).map_err(|e| e.at(source.name()))?;
        return Ok((problem, solution));
    }
    // f32: solved in f64 too, from the same text, to say what f32 cost.
    let text = source.text()?;
    let problem = source.validate_text::<R>(&source.parse_text(&text)?, &text)?;
    let mut solution = solve(&problem).map_err(|e| e.at(source.name()))?;
    super::versus::compare(&source, &text, &problem, &mut solution);
    Ok((problem, solution))
}
