//! What `phong serve` writes down: one line per request on standard error (method, path,
//! status, time in µs; never a query string, a body or an answer), and, only with
//! `--log-answers PATH`, one JSON line per checked answer appended to `PATH`: at most the
//! first [`ANSWER_PREFIX`] characters of the answer, with its length and hash, and the file
//! rotated to `PATH.1` before it would pass `--log-answers-max`, so that what the log holds is
//! bounded whatever the clients send.

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use axum::extract::Request;
use axum::middleware::Next;
use axum::response::Response;

use crate::text::io::IoCause;

/// Logs one request on standard error once it is answered: `GET /exercise/4.2 200 153µs`. The
/// path only (a page's query may hold an answer); a path is cut to 200 characters.
pub(crate) async fn request(request: Request, next: Next) -> Response {
    let start = Instant::now();
    let method = request.method().clone();
    let path = crate::text::number::shorten(request.uri().path(), 200);
    let response = next.run(request).await;
    let micros = start.elapsed().as_micros();
    // Control characters in a path are shown escaped: a request cannot forge a log line.
    eprintln!(
        "{method} {} {} {micros}µs",
        path.escape_debug(),
        response.status().as_u16()
    );
    response
}

/// The most characters of an answer a line of the log keeps (`answer`); the whole answer is
/// known by its length in bytes (`answer_bytes`) and its hash (`answer_hash`, [`problem_hash`]).
pub(crate) const ANSWER_PREFIX: usize = 64;

/// The longest steps a line keeps as sent (their JSON text, in bytes); longer ones are known
/// by their length (`steps_bytes`) and hash (`steps_hash`).
pub(crate) const STEPS_KEPT: usize = 512;

/// `PATH.1`, the older file a full log at `path` becomes: written too, so no input of the
/// server may be it either.
pub(crate) fn older(path: &std::path::Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(".1");
    PathBuf::from(name)
}

/// The file of `--log-answers`, appended to one whole line at a time, and rotated to `PATH.1`
/// before a line would make it larger than its limit.
#[derive(Debug)]
pub(crate) struct AnswerLog {
    file: Mutex<Open>,
    path: PathBuf,
    max_bytes: u64,
}

/// The log file open, and its size.
#[derive(Debug)]
struct Open {
    file: File,
    size: u64,
}

/// One checked answer, as the handlers give it.
#[derive(Debug)]
pub(crate) struct AnswerEntry<'a> {
    /// Seconds since 1970-01-01 UTC.
    pub(crate) time: u64,
    /// The exercise's id, for one of the server's exercises.
    pub(crate) exercise: Option<&'a str>,
    /// A problem sent with the request: its text's hash ([`problem_hash`]), not the text.
    pub(crate) problem: Option<String>,
    /// The answer as written (`null`: the key was checked).
    pub(crate) answer: Option<&'a str>,
    /// The steps as sent, when there were.
    pub(crate) steps: Option<&'a serde_json::value::RawValue>,
    /// `right`, `reading`, `wrong` or `invalid`, as in the check's JSON.
    pub(crate) verdict: &'a str,
}

/// One checked answer, as a line of the log.
#[derive(Debug, serde::Serialize)]
struct Line<'a> {
    time: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    exercise: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    problem: Option<&'a str>,
    /// The answer's first [`ANSWER_PREFIX`] characters (`null`: the key was checked).
    answer: Option<&'a str>,
    /// The answer's length in bytes (UTF-8).
    #[serde(skip_serializing_if = "Option::is_none")]
    answer_bytes: Option<usize>,
    /// The answer's [`problem_hash`].
    #[serde(skip_serializing_if = "Option::is_none")]
    answer_hash: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    steps: Option<&'a serde_json::value::RawValue>,
    /// Steps longer than [`STEPS_KEPT`]: their length in bytes, and their hash.
    #[serde(skip_serializing_if = "Option::is_none")]
    steps_bytes: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    steps_hash: Option<String>,
    verdict: &'a str,
}

impl<'a> Line<'a> {
    fn of(entry: &'a AnswerEntry<'a>) -> Line<'a> {
        let long_steps = entry.steps.filter(|s| s.get().len() > STEPS_KEPT);
        Line {
            time: entry.time,
            exercise: entry.exercise,
            problem: entry.problem.as_deref(),
            answer: entry
                .answer
                .map(|a| match a.char_indices().nth(ANSWER_PREFIX) {
                    Some((end, _)) => &a[..end],
                    None => a,
                }),
            answer_bytes: entry.answer.map(str::len),
            answer_hash: entry.answer.map(problem_hash),
            steps: entry.steps.filter(|s| s.get().len() <= STEPS_KEPT),
            steps_bytes: long_steps.map(|s| s.get().len()),
            steps_hash: long_steps.map(|s| problem_hash(s.get())),
            verdict: entry.verdict,
        }
    }
}

crate::messages! {
    /// What the answers' log says on standard error.
    pub(crate) enum LogMessage {
        /// The log cannot be rotated: the line is not written, so that the file stays within
        /// its limit.
        CannotRotate { path: PathBuf, error: IoCause } =>
            "--log-answers: cannot move {path} to {path}.1 ({error}): the answer is not logged, \
             so that the file stays within --log-answers-max",
            "--log-answers: não é possível mover {path} para {path}.1 ({error}): a resposta não \
             é registrada, para que o arquivo não passe de --log-answers-max";
    }
}

impl AnswerLog {
    /// Opens `path` for appending (created if missing); the file is rotated before it would
    /// pass `max_kb` kB (1,000 bytes each).
    pub(crate) fn open(path: &Path, max_kb: u64) -> std::io::Result<AnswerLog> {
        let file = Self::append(path)?;
        let size = file.metadata().map_or(0, |m| m.len());
        Ok(AnswerLog {
            file: Mutex::new(Open { file, size }),
            path: path.to_owned(),
            max_bytes: max_kb.saturating_mul(1000),
        })
    }

    fn append(path: &Path) -> std::io::Result<File> {
        std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
    }

    /// Appends `entry` as one line. The line is written whole under the lock (and the file is
    /// in append mode), so lines from concurrent requests never interleave. When the line would
    /// make the file larger than its limit, the file becomes `PATH.1` (replacing the older one)
    /// and a new `PATH` is begun. A failed write is said on standard error; the student's
    /// answer is still checked.
    pub(crate) fn record(&self, entry: &AnswerEntry<'_>) {
        let mut line = match serde_json::to_vec(&Line::of(entry)) {
            Ok(l) => l,
            Err(_) => return,
        };
        line.push(b'\n');
        let mut open = match self.file.lock() {
            Ok(f) => f,
            // A thread that panicked while writing left at worst a partial line; go on.
            Err(poisoned) => poisoned.into_inner(),
        };
        if open.size > 0 && open.size + line.len() as u64 > self.max_bytes {
            let rotated = std::fs::rename(&self.path, older(&self.path))
                .and_then(|()| Self::append(&self.path));
            match rotated {
                Ok(file) => *open = Open { file, size: 0 },
                Err(error) => {
                    let m = LogMessage::CannotRotate {
                        path: self.path.clone(),
                        error: IoCause::of(&error),
                    };
                    // The server's own language: the locale's (docs: "Serving the checker").
                    let lang = crate::text::Lang::from_locale();
                    eprintln!("{}", crate::text::Message::text(&m, lang));
                    return;
                }
            }
        }
        match open.file.write_all(&line) {
            Ok(()) => open.size += line.len() as u64,
            Err(e) => eprintln!("--log-answers: cannot write: {e}"),
        }
    }
}

/// The seconds since 1970-01-01 UTC.
pub(crate) fn now() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// A problem's text (or an answer's, or long steps') as 16 hex digits: its 64-bit FNV-1a hash
/// (offset basis 0xcbf29ce484222325, prime 0x100000001b3, over the UTF-8 bytes; fixed and
/// documented, so an instructor can hash a file or an answer and find its lines).
pub(crate) fn problem_hash(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}
