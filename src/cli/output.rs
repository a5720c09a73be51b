//! Where the commands' output goes: standard output, or a file written atomically (a temporary
//! file in the same folder, renamed into place, so that a failure never leaves a half-written
//! file); JSON as the commands print it; the progress bar; whether text is coloured.

use std::io::Write;
use std::path::Path;

use super::args::ColorChoice;
use super::error::CliError;

/// Writes `text` to standard output, or atomically to `path`.
pub(crate) fn emit(path: Option<&Path>, text: &str) -> Result<(), CliError> {
    emit_bytes(path, text.as_bytes())
}

/// Writes `bytes` to standard output, or atomically to `path`. A closed pipe (`phong solve … |
/// head`) is not an error of ours.
pub(crate) fn emit_bytes(path: Option<&Path>, bytes: &[u8]) -> Result<(), CliError> {
    let result = match path {
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes).and_then(|_| out.flush())
        }
        Some(p) => write_atomically(p, bytes),
    };
    match result {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::Write {
            path: path.map(Path::to_owned),
            source: e,
        }),
        _ => Ok(()),
    }
}

/// Writes `bytes` atomically to the file `path` (an image, a plot).
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    write_atomically(path, bytes).map_err(|source| CliError::Write {
        path: Some(path.to_owned()),
        source,
    })
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
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

/// One JSON document, or an array for several, pretty-printed with a final newline.
pub(crate) fn json_text(mut docs: Vec<serde_json::Value>) -> String {
    let value = if docs.len() == 1 {
        docs.pop().expect("one document")
    } else {
        serde_json::Value::Array(docs)
    };
    json_pretty(&value)
}

/// `value` pretty-printed with a final newline (a struct's fields in their order, a
/// [`serde_json::Value`]'s keys sorted).
pub(crate) fn json_pretty(value: &impl serde::Serialize) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("the output serialises");
    s.push('\n');
    s
}

/// A progress bar on stderr when it is a terminal; hidden otherwise (and under CI).
pub(crate) fn progress_bar(rows: u64) -> indicatif::ProgressBar {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(rows);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("rendering {bar:40} {pos}/{len} rows {elapsed}")
    {
        bar.set_style(style);
    }
    bar
}

/// Whether the text report is coloured: `always`, `never`, or for `auto` when writing to a
/// terminal (not a file or a pipe), NO_COLOR is unset or empty (no-color.org) and TERM is not
/// "dumb".
pub(crate) fn use_color(choice: ColorChoice, to_file: bool) -> bool {
    use std::io::IsTerminal;
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => {
            let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
            let dumb = std::env::var_os("TERM").is_some_and(|t| t == "dumb");
            !to_file && !no_color && !dumb && std::io::stdout().is_terminal()
        }
    }
}
