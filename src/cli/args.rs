//! The command line's definition: every subcommand, flag and default, as clap's derive types.
//! What a value is read as (`1/255`, `320x240`, `X,Y`, `f32`) is in [`super::parse`]; what a
//! command does with its arguments, in [`super::commands`]; what the help says of each command,
//! flag and value, in English and Portuguese, in [`super::help`] (keyed by the command's name
//! and the field's).
//!
//! A doc comment on these types would be clap's help text (a field's, a variant's, or for a
//! struct the about of the command it is flattened into), in English only: they carry plain
//! comments instead, and a new flag's help is written in `super::help` (a test fails on a flag
//! without help in both languages).

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

// The top level: its about is `help::CommonHelp::Phong`, the package's description.
#[derive(Debug, Parser)]
#[command(name = "phong", version)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    Solve(SolveArgs),
    Render(RenderArgs),
    Schema(SchemaArgs),
    ExportPov(ExportPovArgs),
    Check(CheckArgs),
    Grade(GradeArgs),
    New(NewArgs),
    Moodle(MoodleArgs),
    Policy(PolicyCmdArgs),
    Tradeoff(TradeoffArgs),
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
    Auto,
    Always,
    Never,
}
