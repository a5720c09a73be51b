//! What `phong serve` writes down: one line per request on standard error (method, path,
//! status, time in µs; never a query string, a body or an answer), and, only with
//! `--log-answers PATH`, one JSON line per checked answer appended to `PATH`.

use std::fs::File;
use std::io::Write;
use std::path::Path;
use std::sync::Mutex;
use std::time::Instant;

use axum::extract::Request;
use axum::middleware::Next;
use axum::response::Response;

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

/// The file of `--log-answers`, appended to one whole line at a time.
#[derive(Debug)]
pub(crate) struct AnswerLog {
    file: Mutex<File>,
}

/// One checked answer, as a line of the log.
#[derive(Debug, serde::Serialize)]
pub(crate) struct AnswerEntry<'a> {
    /// Seconds since 1970-01-01 UTC.
    pub(crate) time: u64,
    /// The exercise's id, for one of the server's exercises.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) exercise: Option<&'a str>,
    /// A problem sent with the request: its text's hash ([`problem_hash`]), not the text.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) problem: Option<String>,
    /// The answer as written (`null`: the key was checked).
    pub(crate) answer: Option<&'a str>,
    /// The steps as sent, when there were.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) steps: Option<&'a serde_json::value::RawValue>,
    /// `right`, `reading`, `wrong` or `invalid`, as in the check's JSON.
    pub(crate) verdict: &'a str,
}

impl AnswerLog {
    /// Opens `path` for appending (created if missing).
    pub(crate) fn open(path: &Path) -> std::io::Result<AnswerLog> {
        let file = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)?;
        Ok(AnswerLog {
            file: Mutex::new(file),
        })
    }

    /// Appends `entry` as one line. The line is written whole under the lock (and the file is
    /// in append mode), so lines from concurrent requests never interleave. A failed write is
    /// said on standard error; the student's answer is still checked.
    pub(crate) fn record(&self, entry: &AnswerEntry<'_>) {
        let mut line = match serde_json::to_vec(entry) {
            Ok(l) => l,
            Err(_) => return,
        };
        line.push(b'\n');
        let mut file = match self.file.lock() {
            Ok(f) => f,
            // A thread that panicked while writing left at worst a partial line; go on.
            Err(poisoned) => poisoned.into_inner(),
        };
        if let Err(e) = file.write_all(&line) {
            eprintln!("--log-answers: cannot write: {e}");
        }
    }
}

/// The seconds since 1970-01-01 UTC.
pub(crate) fn now() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// A problem's text as 16 hex digits: its 64-bit FNV-1a hash (fixed and documented, so an
/// instructor can hash a file and find its lines).
pub(crate) fn problem_hash(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}
