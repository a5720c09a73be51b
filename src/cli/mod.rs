//! The `phong` command line, as ripgrep's `main` and cargo's `commands/` are laid out: parse the
//! arguments (`args`, `parse`; their help in the user's language, `help`), run the command
//! (`commands`, one file each), and map how it ended to an exit code (`exit`: 0 solved or
//! right, 1 a checked answer is wrong, 2 bad input or usage) once. An error that stops a command (`error`) is printed here, once; output
//! goes to standard output or a file written atomically (`output`).

pub(crate) mod args;
mod commands;
pub mod cpu;
pub(crate) mod error;
pub(crate) mod exit;
pub(crate) mod faults;
mod files;
pub(crate) mod help;
pub mod memory;
mod output;
pub(crate) mod parse;
pub(crate) mod usage;

use std::process::ExitCode;

use clap::FromArgMatches;

pub(crate) use args::Cli;
pub(crate) use exit::Exit;

use args::Command;

/// The program: parse the arguments and run.
pub fn main() -> ExitCode {
    memory::prepare(crate::text::Lang::from_locale());
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    // The help is said in the language usage errors are said in (`--lang`, else the locale).
    let mut command = help::command(usage::lang_of(&args));
    let parsed = command
        .try_get_matches_from_mut(&args)
        .and_then(|mut matches| {
            Cli::from_arg_matches_mut(&mut matches).map_err(|e| e.format(&mut command))
        });
    match parsed {
        Ok(cli) => {
            memory::prepare(cli.command.lang());
            // `phong serve` writes no output file, and stops on SIGINT and SIGTERM itself: it
            // finishes the requests being answered and exits 0 (serve::run).
            #[cfg(feature = "serve")]
            let guarded = !matches!(cli.command, Command::Serve(_));
            #[cfg(not(feature = "serve"))]
            let guarded = true;
            if guarded {
                output::guard_signals();
            }
            run(&cli).into()
        }
        Err(e) => match usage::refused(&e, &args) {
            Some(exit) => exit.into(),
            None => e.exit(),
        },
    }
}

/// Runs a parsed command line: how it ended, its error printed if it failed.
pub(crate) fn run(cli: &Cli) -> Exit {
    let result = match &cli.command {
        Command::Solve(args) => commands::solve::run(args),
        Command::Render(args) => commands::render::run(args),
        Command::Tradeoff(args) => commands::tradeoff::run(args),
        Command::Schema(args) => commands::schema::run(args),
        Command::ExportPov(args) => commands::export_pov::run(args),
        Command::Check(args) => commands::check::run(args),
        Command::Grade(args) => commands::grade::run(args),
        Command::New(args) => commands::new::run(args),
        Command::Moodle(args) => commands::moodle::run(args),
        Command::Policy(args) => commands::policy::run(args),
        #[cfg(feature = "serve")]
        Command::Serve(args) => commands::serve::run(args),
    };
    result.unwrap_or_else(|e| error::fail_in(&e, cli.command.lang()))
}
