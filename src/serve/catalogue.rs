//! The exercises `phong serve` offers: the bundled ones (compiled into the binary, so an
//! installed `phong` serves them from any folder), or every `*.json` problem of the instructor's
//! folder (`--exercises DIR`), read and validated once at start-up.

use std::path::{Path, PathBuf};

use crate::problem::{ProblemError, ProblemFile, Source};

/// One exercise: its name in URLs (`4.2`), its text and its parsed form.
#[derive(Debug)]
pub(crate) struct Exercise {
    /// The file's stem, as it appears in `/exercise/{id}` (`4.2`).
    pub(crate) id: String,
    /// The name in messages (`exercises/4.2.json`).
    pub(crate) name: PathBuf,
    /// The problem's JSON text, as the file holds it.
    pub(crate) text: String,
    /// The parsed file (title, question, answer key).
    pub(crate) file: ProblemFile,
    /// The problem solved once, with its readings and slips, for every answer checked against
    /// it (read-only: no request changes it).
    pub(crate) prepared: crate::check::Prepared,
}

impl Exercise {
    /// The exercise as a problem source (text: it never reads a file again).
    pub(crate) fn source(&self) -> Source<'_> {
        Source::Text {
            name: &self.name,
            text: &self.text,
        }
    }
}

/// The exercises, in the order they are listed.
#[derive(Debug, Default)]
pub(crate) struct Catalogue {
    pub(crate) exercises: Vec<Exercise>,
}

/// The bundled exercises: the chapter's three, then the other worked cases.
const BUNDLED: &[(&str, &str)] = &[
    ("4.1", include_str!("../../exercises/4.1.json")),
    ("4.2", include_str!("../../exercises/4.2.json")),
    ("4.3", include_str!("../../exercises/4.3.json")),
];

impl Catalogue {
    /// The bundled exercises.
    pub(crate) fn bundled() -> Catalogue {
        let exercises = BUNDLED
            .iter()
            .map(|(id, text)| {
                let name = PathBuf::from(format!("exercises/{id}.json"));
                let source = Source::Text { name: &name, text };
                let file = source
                    .parse()
                    .expect("a bundled exercise parses (tests/integration/serve_api.rs)");
                let prepared = crate::check::Prepared::of(source);
                Exercise {
                    id: (*id).to_owned(),
                    name,
                    text: (*text).to_owned(),
                    file,
                    prepared,
                }
            })
            .collect();
        Catalogue { exercises }
    }

    /// Every `*.json` problem of `dir`, sorted by name; the first that cannot be read or is
    /// invalid stops the server before it starts, naming the file, the field and the fix.
    pub(crate) fn folder(dir: &Path) -> Result<Catalogue, ProblemError> {
        let paths = Catalogue::files(dir).map_err(|source| ProblemError::Read {
            path: dir.to_owned(),
            source,
        })?;
        let mut exercises = Vec::with_capacity(paths.len());
        for path in paths {
            // Parsed from the file first, for its errors (size, UTF-8, syntax, with line and
            // column); then kept as text, as the requests' problems are.
            Source::File(&path).parse()?;
            let text = std::fs::read_to_string(&path).map_err(|source| ProblemError::Read {
                path: path.clone(),
                source,
            })?;
            let id = path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            let source = Source::Text {
                name: &path,
                text: &text,
            };
            let file = source.parse()?;
            // Validated now (a mesh refused, as in a request), so that a bad file stops the
            // server before it starts, not a student's request.
            source.validate::<f64>(&file)?;
            let prepared = crate::check::Prepared::of(source);
            exercises.push(Exercise {
                id,
                name: path,
                text,
                file,
                prepared,
            });
        }
        Ok(Catalogue { exercises })
    }

    /// The problem files of `dir` that [`Catalogue::folder`] reads: every `*.json` but the
    /// course policy, sorted by name. Inputs of the server, which no file it writes may
    /// replace (`--log-answers`).
    pub(crate) fn files(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
        let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| crate::problem::is_exercise_file(p) && p.is_file())
            .collect();
        paths.sort();
        Ok(paths)
    }

    /// The exercise named `id` in a URL.
    pub(crate) fn get(&self, id: &str) -> Option<&Exercise> {
        self.exercises.iter().find(|e| e.id == id)
    }
}
