//! `phong new`: fresh problems, printed (one JSON document, or an array for several) or written
//! one file each into a folder.

use crate::cli::args::NewArgs;
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::generate;

pub(crate) fn run(args: &NewArgs) -> Result<Exit, CliError> {
    let problems = generate::generate(
        args.kind,
        args.count,
        args.seed,
        args.lang == crate::text::lang::Lang::Pt,
    );
    // `-o -` is standard output, as for every command.
    let Some(dir) = args.output.as_ref().filter(|d| !output::is_dash(d)) else {
        output::emit(None, &generate::text_of_all(&problems))?;
        return Ok(Exit::Success);
    };
    // `afile/` names the file `afile` (its trailing `/` is left out here, where the system
    // would say only that it is not a directory).
    let bare: std::path::PathBuf = dir.components().collect();
    if std::fs::metadata(&bare).is_ok_and(|m| !m.is_dir()) {
        return Err(CliError::not_a_folder(
            dir.clone(),
            "-o",
            CliFault::ProblemsNotAFolder,
        ));
    }
    std::fs::create_dir_all(dir).map_err(|source| CliError::CreateFolder {
        path: dir.clone(),
        source,
    })?;
    // A file that cannot be written does not stop the others.
    let mut exit = Exit::Success;
    for p in problems {
        let written = output::emit(Some(&dir.join(&p.file_name)), &p.text());
        exit = exit.max(error::carry_on_in(written, args.lang));
    }
    Ok(exit)
}
