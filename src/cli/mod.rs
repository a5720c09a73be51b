//! The `phong` command line: parse the arguments, run the command, map the outcome to an exit
//! code (0 solved, 2 bad input or usage). Output files are written atomically.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::core::Real;
use crate::problem::{self, ProblemError};
use crate::report;
use crate::solve;

/// Solve and explain the illumination exercises of Chapter 4 (Phong's model).
#[derive(Debug, Parser)]
#[command(name = "phong", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve problem files, printing every intermediate quantity with its equation.
    Solve(SolveArgs),
    /// Print the JSON Schema of the problem format.
    Schema(SchemaArgs),
}

#[derive(Debug, Args)]
pub struct SolveArgs {
    /// Problem files (JSON). Each is solved even when another one is bad.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
    /// Output format: text for people, json for scripts (stable field names, format_version).
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Floating-point precision of the whole calculation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
    /// Write the output to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct SchemaArgs {
    /// Write the schema to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    F32,
    F64,
}

/// Exit code: everything solved.
pub const EXIT_OK: u8 = 0;
/// Exit code: bad input (a file that cannot be read, parsed or validated) or bad usage.
pub const EXIT_BAD_INPUT: u8 = 2;

/// The program: parse the arguments and run.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    ExitCode::from(run(&cli))
}

/// Runs a parsed command line and returns the exit code.
pub fn run(cli: &Cli) -> u8 {
    match &cli.command {
        Command::Solve(args) => solve_command(args),
        Command::Schema(args) => {
            let mut text = problem::schema_json();
            text.push('\n');
            emit(args.output.as_deref(), &text)
        }
    }
}

fn solve_command(args: &SolveArgs) -> u8 {
    let mut failed = false;
    let mut docs = Vec::new();
    let mut text = String::new();
    for path in &args.files {
        let result = match args.format {
            Format::Json => solve_json(path, args.precision).map(|v| docs.push(v)),
            Format::Text => solve_text(path, args.precision).map(|t| {
                if !text.is_empty() {
                    text.push('\n');
                }
                text.push_str(&t);
            }),
        };
        if let Err(e) = result {
            failed = true;
            eprintln!("error: {e}");
            if args.format == Format::Json {
                docs.push(error_json(path, &e));
            }
        }
    }
    let out = match args.format {
        Format::Text => text,
        Format::Json => {
            let value = if docs.len() == 1 {
                docs.pop().expect("one document")
            } else {
                serde_json::Value::Array(docs)
            };
            let mut s = serde_json::to_string_pretty(&value).expect("JSON values serialise");
            s.push('\n');
            s
        }
    };
    let code = emit(args.output.as_deref(), &out);
    if failed {
        EXIT_BAD_INPUT
    } else {
        code
    }
}

/// Solves one file and returns its stable JSON document.
pub fn solve_json(path: &Path, precision: Precision) -> Result<serde_json::Value, ProblemError> {
    fn go<R: Real>(path: &Path) -> Result<serde_json::Value, ProblemError> {
        let (problem, solution) = solve_file::<R>(path)?;
        let doc = report::json::document(&path.display().to_string(), &problem, &solution);
        Ok(serde_json::to_value(doc).expect("the solution serialises"))
    }
    match precision {
        Precision::F32 => go::<f32>(path),
        Precision::F64 => go::<f64>(path),
    }
}

/// Solves one file and returns its text report.
pub fn solve_text(path: &Path, precision: Precision) -> Result<String, ProblemError> {
    fn go<R: Real>(path: &Path) -> Result<String, ProblemError> {
        let (problem, solution) = solve_file::<R>(path)?;
        Ok(report::text::render(
            &path.display().to_string(),
            &problem,
            &solution,
        ))
    }
    match precision {
        Precision::F32 => go::<f32>(path),
        Precision::F64 => go::<f64>(path),
    }
}

/// Loads, validates and solves one file in precision `R`.
pub fn solve_file<R: Real>(
    path: &Path,
) -> Result<(problem::Problem<R>, solve::Solution<R>), ProblemError> {
    let (_, problem) = problem::load::<R>(path)?;
    let solution = solve::solve(&problem).map_err(|e| e.at(path))?;
    Ok((problem, solution))
}

fn error_json(path: &Path, e: &ProblemError) -> serde_json::Value {
    serde_json::json!({
        "format_version": report::json::FORMAT_VERSION,
        "file": path.display().to_string(),
        "error": {
            "kind": e.kind(),
            "field": e.field(),
            "message": e.to_string(),
        }
    })
}

/// Writes the output to stdout, or atomically to a file (a temporary file in the same folder,
/// renamed into place), so that a failure never leaves a half-written file.
fn emit(path: Option<&Path>, text: &str) -> u8 {
    let result = match path {
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(text.as_bytes()).and_then(|_| out.flush())
        }
        Some(p) => write_atomically(p, text.as_bytes()),
    };
    match result {
        Ok(()) => EXIT_OK,
        // A closed pipe (`phong solve … | head`) is not an error of ours.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => EXIT_OK,
        Err(e) => {
            let what = path.map_or("standard output".into(), |p| p.display().to_string());
            eprintln!("error: cannot write {what}: {e}");
            EXIT_BAD_INPUT
        }
    }
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
    tmp.write_all(bytes)?;
    // A temporary file is private (0600); the result should have an ordinary file's mode.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map_or(0o644, |m| m.permissions().mode());
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))?;
    }
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
