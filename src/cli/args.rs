//! The command line's definition: every subcommand, flag, default and help text, as clap's
//! derive types. What a value is read as (`1/255`, `320x240`, `X,Y`, `f32`) is in
//! [`super::parse`]; what a command does with its arguments, in [`super::commands`].

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

use super::parse::{
    parse_delimiter, parse_fraction, parse_level, parse_pixel, parse_runs, parse_samples,
    parse_share, parse_size, parse_threads, parse_tolerance,
};
use crate::check;
use crate::core::Precision;
use crate::generate;
use crate::report::document::Contents;
use crate::text::lang::Lang;
use crate::tracer::output::ImageFormat;

mod answers;
mod documents;
#[cfg(feature = "serve")]
mod serve;
#[cfg(test)]
mod tests;
mod trace;

pub(crate) use answers::*;
pub(crate) use documents::*;
#[cfg(feature = "serve")]
pub(crate) use serve::*;
pub(crate) use trace::*;

/// Solve and explain the illumination exercises of Chapter 4 (Phong's model).
#[derive(Debug, Parser)]
#[command(name = "phong", version, about, long_about = None)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Solve problem files, printing every intermediate quantity with its equation.
    Solve(SolveArgs),
    /// Render a scene (a problem file with a camera) with the Whitted ray tracer, or explain
    /// one pixel of it step by step.
    Render(RenderArgs),
    /// Print the JSON Schema of the problem format.
    Schema(SchemaArgs),
    /// Write a scene as POV-Ray 3.7 SDL that computes the same model (for cross-checking),
    /// or say why POV-Ray cannot express it (exit 2).
    ///
    /// A transmitting material is exported only where total internal reflection cannot occur
    /// (POV-Ray traces a reflection ray there, phong nothing): on a sphere or a plane with
    /// "ior" ≥ 1, seen from outside, that no reflecting or transmitting surface enters; with
    /// shadows on, it casts phong's full shadow through a copy only POV-Ray's shadow rays see.
    ExportPov(ExportPovArgs),
    /// Check an answer (or each file's answer key) and name the slips behind a wrong one.
    Check(CheckArgs),
    /// Grade a CSV of answers (student, exercise, answer): one verdict per row, a summary per exercise.
    Grade(GradeArgs),
    /// Write fresh problems with numbers friendly to hand calculation, each with its answer key.
    New(NewArgs),
    /// Write problem files (or what `phong new` prints, `-` for standard input) as a Moodle XML
    /// quiz: one Cloze question per problem, the slips as 0 % answers, the solution as feedback.
    Moodle(MoodleArgs),
    /// Print the course policy in force (tolerances, the reading's credit, 8-bit answers, the
    /// words for "no hit", points, duplicates) as a policy file writes it: the folder's
    /// course-policy.json over the defaults. `phong policy > exercises/course-policy.json`
    /// starts one.
    Policy(PolicyCmdArgs),
    /// Measure what each tracer setting (precision, level, minimum weight, samples) costs in
    /// time and buys in accuracy against a reference render; name the fastest within a budget.
    Tradeoff(TradeoffArgs),
    /// Serve the exercises as a web application: a student checks an answer (and its steps) in
    /// a browser, Portuguese or English, with nothing installed; a JSON API mirrors
    /// `solve --format json` and `check --format json`.
    #[cfg(feature = "serve")]
    Serve(ServeArgs),
}

impl Command {
    /// The language the command's messages (its errors included) are written in: `--lang`
    /// where the command has it, else the locale's ([`Lang::from_locale`]).
    pub fn lang(&self) -> Lang {
        match self {
            Command::Solve(a) => a.lang,
            Command::Render(a) => a.lang,
            Command::Check(a) => a.lang,
            Command::Moodle(a) => a.lang,
            Command::New(a) => a.lang,
            Command::Grade(a) => a.lang,
            Command::Tradeoff(a) => a.lang,
            Command::ExportPov(a) => a.lang,
            Command::Policy(a) => a.lang,
            Command::Schema(a) => a.lang,
            #[cfg(feature = "serve")]
            Command::Serve(_) => Lang::from_locale(),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Format {
    Text,
    Markdown,
    Latex,
    Html,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ColorChoice {
    /// Colour when writing to a terminal and NO_COLOR is not set.
    Auto,
    Always,
    Never,
}
