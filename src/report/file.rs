//! A problem file solved and reported in one call, in a precision chosen at run time: its
//! explanation (text, Markdown, LaTeX, HTML), its text report, its JSON document, or the JSON
//! document of why it could not be solved.

use crate::text::Message;
use std::path::Path;

use crate::core::{Precision, Real};
use crate::problem::{ProblemError, Source};
use crate::solve::solve_source;

use super::explain::Explanation;
use crate::text::lang::Lang;

/// Solves one file and returns its explanation in `lang`, for the text, Markdown, LaTeX and
/// HTML formats.
pub fn explain_file(
    path: &Path,
    precision: Precision,
    lang: Lang,
) -> Result<Explanation, ProblemError> {
    explain_source(Source::File(path), precision, lang)
}

/// [`explain_file`] for a problem from any [`Source`] (text held in memory, for `phong serve`).
pub fn explain_source(
    source: Source<'_>,
    precision: Precision,
    lang: Lang,
) -> Result<Explanation, ProblemError> {
    fn go<R: Real>(source: Source<'_>, lang: Lang) -> Result<Explanation, ProblemError> {
        let (problem, solution) = solve_source::<R>(source)?;
        Ok(super::explain::explain(
            &source.name().display().to_string(),
            &problem,
            &solution,
            lang,
        ))
    }
    match precision {
        Precision::F32 => go::<f32>(source, lang),
        Precision::F64 => go::<f64>(source, lang),
    }
}

/// Solves one file and returns its stable JSON document.
pub fn solve_json(path: &Path, precision: Precision) -> Result<serde_json::Value, ProblemError> {
    solve_json_source(Source::File(path), precision)
}

/// [`solve_json`] for a problem from any [`Source`] (text held in memory, for `phong serve`).
pub fn solve_json_source(
    source: Source<'_>,
    precision: Precision,
) -> Result<serde_json::Value, ProblemError> {
    solve_json_warned(source, precision, Lang::En).map(|(doc, _)| doc)
}

/// [`solve_json`], with the file's likely unit mistakes as sentences in `lang` (for standard
/// error; the document has them in English).
pub(crate) fn solve_json_warned(
    source: Source<'_>,
    precision: Precision,
    lang: Lang,
) -> Result<(serde_json::Value, Vec<String>), ProblemError> {
    fn go<R: Real>(
        source: Source<'_>,
        lang: Lang,
    ) -> Result<(serde_json::Value, Vec<String>), ProblemError> {
        let (problem, solution) = solve_source::<R>(source)?;
        let doc = super::json::document(&source.name().display().to_string(), &problem, &solution);
        let warnings = problem.warnings.iter().map(|w| w.text(lang)).collect();
        Ok((
            serde_json::to_value(doc).expect("the solution serialises"),
            warnings,
        ))
    }
    match precision {
        Precision::F32 => go::<f32>(source, lang),
        Precision::F64 => go::<f64>(source, lang),
    }
}

/// Solves one file and returns its text report.
pub fn solve_text(path: &Path, precision: Precision) -> Result<String, ProblemError> {
    fn go<R: Real>(path: &Path) -> Result<String, ProblemError> {
        let (problem, solution) = solve_source::<R>(Source::File(path))?;
        Ok(super::text::render(
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

/// The JSON document of a file that could not be solved: its kind, field and message, in
/// place of the solution (`phong solve --format json` writes one per bad file).
pub(crate) fn error_json(path: &Path, e: &ProblemError) -> serde_json::Value {
    serde_json::json!({
        "format_version": super::json::FORMAT_VERSION,
        "file": path.display().to_string(),
        "error": {
            "kind": e.kind(),
            "field": e.field(),
            "message": e.to_string(),
        }
    })
}
