//! Where the commands' output goes: standard output, or a file by the rules of [`super::files`];
//! messages on standard error that never fail; JSON as the commands print it; the progress bar;
//! whether text is coloured.

use std::fmt::Display;
use std::io::Write;
use std::path::Path;

use super::args::ColorChoice;
use super::error::CliError;

// What the commands call on their way to writing: the safety checks live with the files.
pub(crate) use super::files::{distinct, guard_signals, Batch};

/// Writes `line` and a newline to standard error. A closed or broken standard error (`2>&-`,
/// `2>&1 | true`) is ignored: a message that cannot be shown must not stop the command (as
/// `eprintln!` would, by panicking).
pub(crate) fn say(line: &dyn Display) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{line}");
    let _ = err.flush();
}

/// Whether `path` is `-`, standard input or output.
pub(crate) fn is_dash(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Writes `text` to standard output, or atomically to `path`.
pub(crate) fn emit(path: Option<&Path>, text: &str) -> Result<(), CliError> {
    emit_bytes(path, text.as_bytes())
}

/// Writes `bytes` to standard output (no path, or `-`), or atomically to `path`. A closed pipe
/// (`phong solve … | head`) is not an error of ours.
pub(crate) fn emit_bytes(path: Option<&Path>, bytes: &[u8]) -> Result<(), CliError> {
    emit_with(path, &mut |w| w.write_all(bytes))
}

/// Writes to standard output (no path, or `-`), or to `path` by the rules of
/// [`super::files`], what `write` writes, as it writes it (a report of a million rows is never
/// whole in memory). A regular file is still replaced atomically: an error leaves it as it was.
pub(crate) fn emit_with(
    path: Option<&Path>,
    write: super::files::Writer<'_>,
) -> Result<(), CliError> {
    let result = match path {
        Some(p) if !is_dash(p) => super::files::write_target_with(p, write),
        _ => to_stdout(write),
    };
    result.map_err(|e| CliError::Write {
        path: path.filter(|p| !is_dash(p)).map(Path::to_owned),
        source: e,
    })
}

/// Standard output; a reader that has gone (EPIPE) is not an error of ours.
fn to_stdout(write: super::files::Writer<'_>) -> std::io::Result<()> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    match write(&mut out).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// Writes `bytes` to the file `path` (an image, a plot) by the rules of [`emit_bytes`].
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    emit_bytes(Some(path), bytes)
}

/// A progress bar on stderr when it is a terminal; hidden otherwise (and under CI). `work`, when
/// given, is the estimate shown beside it (`about 2.1e9 rays`), with the time left.
pub(crate) fn progress_bar(rows: u64, work: Option<&str>) -> indicatif::ProgressBar {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(rows);
    let template = match work {
        Some(w) => format!(
            "rendering {{bar:40}} {{pos}}/{{len}} rows {{elapsed}}, ETA {{eta}} ({})",
            w.replace('{', "{{").replace('}', "}}")
        ),
        None => "rendering {bar:40} {pos}/{len} rows {elapsed}".to_owned(),
    };
    if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
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
