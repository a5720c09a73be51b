//! The JSON API: `POST /api/solve` and `POST /api/check`, answering what `phong solve --format
//! json` and `phong check --format json` print, and `GET /api/exercises`, the exercises served.
//!
//! A request names its problem either as the JSON of a problem file (`"problem": {…}`, kept as
//! the text it was sent, so that an error names the line and column of that text) or as one of
//! the server's exercises (`"exercise": "4.2"`). Statuses:
//! - 200: solved, or checked (right, a reading, or wrong);
//! - 400: the request is not the API's JSON (its own fields, not the problem's);
//! - 404: no such exercise;
//! - 413: the body is larger than [`Limits::body_bytes`](super::limits::Limits);
//! - 415: the body is not `application/json`;
//! - 422: the problem, the answer or the steps are invalid, or the problem is larger than this
//!   server solves (lights, surfaces): the CLI's own error document (`{"error": {"kind",
//!   "field", "message"}}`), its message in Portuguese with `"lang": "pt"` where the CLI has one.

// A refusal is the response itself, built once per refused request and returned at once:
// boxing it would buy nothing.
#![allow(clippy::result_large_err)]

use std::path::Path;
use std::sync::Arc;

use axum::body::Bytes;
use axum::extract::State;
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::Router;
use serde::Deserialize;
use serde_json::value::RawValue;

use super::faults::{ApiText, Items, TooMany};
use super::log::{problem_hash, AnswerEntry};
use super::Shared;
use crate::check;
use crate::core::Precision;
use crate::problem::{ProblemError, Source};
use crate::text::lang::Lang;
use crate::text::{Echo, Message};

/// The name a problem sent with a request has in messages and in the `file` field.
pub(crate) const PROBLEM_NAME: &str = "problem";

/// The API's routes.
pub(crate) fn routes() -> Router<Shared> {
    Router::new()
        .route("/api/solve", post(solve))
        .route("/api/check", post(check))
        .route("/api/exercises", get(exercises))
}

/// `POST /api/solve`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SolveRequest<'a> {
    #[serde(borrow)]
    problem: Option<&'a RawValue>,
    exercise: Option<String>,
    lang: Option<String>,
    precision: Option<String>,
}

/// `POST /api/check`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CheckRequest<'a> {
    #[serde(borrow)]
    problem: Option<&'a RawValue>,
    exercise: Option<String>,
    answer: Option<String>,
    #[serde(borrow)]
    steps: Option<&'a RawValue>,
    scale: Option<ScaleField>,
    tolerance: Option<f64>,
    #[serde(default)]
    strict: bool,
    lang: Option<String>,
}

/// `"scale": 255` or `"scale": "255"`.
#[derive(Deserialize)]
#[serde(untagged)]
enum ScaleField {
    Number(u32),
    Text(String),
}

/// `GET /api/exercises`: each exercise's id and titles.
async fn exercises(State(state): State<Shared>) -> Response {
    let list: Vec<serde_json::Value> = state
        .catalogue
        .exercises
        .iter()
        .map(|e| {
            serde_json::json!({
                "id": e.id,
                "title": e.file.title,
                "title_pt": e.file.title_pt,
            })
        })
        .collect();
    json_response(StatusCode::OK, &list)
}

/// `POST /api/solve`: what `phong solve --format json` prints for the problem.
async fn solve(State(state): State<Shared>, headers: HeaderMap, body: Bytes) -> Response {
    solved(&state, &headers, &body).unwrap_or_else(|refused| refused)
}

/// [`solve`]'s answer, or the response that refuses the request.
fn solved(state: &Shared, headers: &HeaderMap, body: &Bytes) -> Result<Response, Response> {
    let request: SolveRequest<'_> = envelope(headers, body, Shape::Solve)?;
    let lang = lang(request.lang.as_deref(), headers)?;
    let precision = match request.precision.as_deref() {
        None | Some("f64") => Precision::F64,
        Some("f32") => Precision::F32,
        Some(other) => {
            return Err(error(
                StatusCode::BAD_REQUEST,
                "usage",
                Some("precision"),
                ApiText::NotAPrecision {
                    value: Echo::new(other, 40),
                }
                .text(lang),
            ))
        }
    };
    let problem = Problem::of(state, request.problem, request.exercise.as_deref(), lang)?;
    let source = problem.source();
    if let Err(e) = problem.admit(state) {
        return Err(problem_error(&e, source.name(), lang));
    }
    match crate::report::file::solve_json_warned(source, precision, lang) {
        Ok((doc, _warnings)) => Ok(json_response(StatusCode::OK, &doc)),
        Err(e) => Err(problem_error(&e, source.name(), lang)),
    }
}

/// `POST /api/check`: what `phong check --format json` prints for the problem and the answer
/// (and the steps, merged in as `phong check --step` merges them).
async fn check(State(state): State<Shared>, headers: HeaderMap, body: Bytes) -> Response {
    checked(&state, &headers, &body).unwrap_or_else(|refused| refused)
}

/// [`check()`]'s answer, or the response that refuses the request.
fn checked(state: &Shared, headers: &HeaderMap, body: &Bytes) -> Result<Response, Response> {
    let request: CheckRequest<'_> = envelope(headers, body, Shape::Check)?;
    let lang = lang(request.lang.as_deref(), headers)?;
    // No scale: the 0–1 scale, with 8-bit values read as the course policy says.
    let scale = match &request.scale {
        None => None,
        Some(ScaleField::Number(1)) => Some(check::Scale::Unit),
        Some(ScaleField::Number(255)) => Some(check::Scale::Bits8),
        Some(ScaleField::Text(t)) if t == "1" => Some(check::Scale::Unit),
        Some(ScaleField::Text(t)) if t == "255" => Some(check::Scale::Bits8),
        Some(_) => {
            return Err(error(
                StatusCode::BAD_REQUEST,
                "usage",
                Some("scale"),
                ApiText::NotAScale.text(lang),
            ))
        }
    };
    if let Some(t) = request.tolerance {
        if let Err(e) = check::answer::check_tolerance(t) {
            return Err(error(
                StatusCode::UNPROCESSABLE_ENTITY,
                "usage",
                Some("tolerance"),
                format!("tolerance: {}", e.text(lang)),
            ));
        }
    }
    let steps = match request.steps.map(|raw| given_steps(raw.get())) {
        None => Vec::new(),
        Some(Ok(s)) => s,
        Some(Err(e)) => {
            return Err(error(
                StatusCode::UNPROCESSABLE_ENTITY,
                "usage",
                Some("steps"),
                format!("steps: {}", e.text(lang)),
            ))
        }
    };
    let problem = Problem::of(state, request.problem, request.exercise.as_deref(), lang)?;
    let source = problem.source();
    if let Err(e) = problem.admit(state) {
        return Err(problem_error(&e, source.name(), lang));
    }
    // The request's `tolerance` and `strict` go over the course policy, as the flags do.
    let policy = if request.tolerance.is_some() || request.strict {
        let mut p = (*state.policy).clone();
        p.tolerance_forced = request.tolerance.or(p.tolerance_forced);
        p.strict |= request.strict;
        Arc::new(p)
    } else {
        state.policy.clone()
    };
    let strict = policy.strict;
    let options = check::CheckOptions {
        answer: request.answer.clone(),
        scale,
        policy,
    };
    // One of the server's exercises was solved once, at start-up; a problem sent is solved now.
    let check_answer = || match problem {
        Problem::Exercise(e) => check::check_prepared(&e.prepared, &options),
        Problem::Sent(_) => check::check_source(source, &options),
    };
    // As `phong check`: with steps, the answer is checked only when one is given.
    let (answer, steps) = if steps.is_empty() {
        (Some(check_answer()), None)
    } else {
        let judged = check::steps::check_steps_source(source, &steps, strict);
        let answer = options.answer.is_some().then(check_answer);
        (answer, Some(judged))
    };
    let unchecked = answer
        .iter()
        .map(check::report::Checked::status)
        .chain(steps.iter().map(check::steps::StepsChecked::status))
        .any(|s| s == check::report::Status::Unchecked);
    let Some(mut doc) = check::report::document(answer.as_ref(), steps.as_ref()) else {
        // Not reached: without steps there is always an answer's verdict.
        return Err(error(
            StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            None,
            ApiText::NothingChecked.text(lang),
        ));
    };
    if let Some(log) = &state.answers {
        log.record(&AnswerEntry {
            time: super::log::now(),
            exercise: problem.exercise_id(),
            problem: problem.text().map(problem_hash),
            answer: request.answer.as_deref(),
            steps: request.steps,
            verdict: doc["verdict"].as_str().unwrap_or("invalid"),
        });
    }
    if unchecked {
        let failures: Vec<&check::report::Failure> = answer
            .iter()
            .filter_map(|c| c.outcome.as_ref().err())
            .chain(steps.iter().filter_map(|s| s.outcome.as_ref().err()))
            .collect();
        say_failures_in(&mut doc, &failures, lang);
        Ok(json_response(StatusCode::UNPROCESSABLE_ENTITY, &doc))
    } else {
        Ok(json_response(StatusCode::OK, &doc))
    }
}

/// The steps of a request, read as `phong check --steps FILE` reads its file; `{}` is no step.
fn given_steps(text: &str) -> Result<Vec<check::steps::GivenStep>, check::steps::BadStep> {
    if serde_json::from_str::<serde_json::Map<String, serde_json::Value>>(text)
        .is_ok_and(|m| m.is_empty())
    {
        return Ok(Vec::new());
    }
    check::steps::parse_steps_json(text)
}

/// The problem a request names: sent with it, or one of the server's exercises.
enum Problem<'a> {
    /// The JSON of a problem file, as sent.
    Sent(&'a str),
    /// One of the server's exercises.
    Exercise(&'a super::catalogue::Exercise),
}

impl<'a> Problem<'a> {
    /// The problem of `problem` or `exercise` (exactly one of them); a refusal in `lang`.
    fn of(
        state: &'a super::State,
        problem: Option<&'a RawValue>,
        exercise: Option<&str>,
        lang: Lang,
    ) -> Result<Problem<'a>, Response> {
        match (problem, exercise) {
            (Some(p), None) => Ok(Problem::Sent(p.get())),
            (None, Some(id)) => state
                .catalogue
                .get(id)
                .map(Problem::Exercise)
                .ok_or_else(|| {
                    let ids: Vec<&str> = state
                        .catalogue
                        .exercises
                        .iter()
                        .map(|e| e.id.as_str())
                        .collect();
                    error(
                        StatusCode::NOT_FOUND,
                        "usage",
                        Some("exercise"),
                        ApiText::NoSuchExercise {
                            id: Echo::new(id, 40),
                            ids: ids.join(", "),
                        }
                        .text(lang),
                    )
                }),
            (Some(_), Some(_)) => Err(error(
                StatusCode::BAD_REQUEST,
                "usage",
                Some("exercise"),
                ApiText::ProblemAndExercise.text(lang),
            )),
            (None, None) => Err(error(
                StatusCode::BAD_REQUEST,
                "usage",
                Some("problem"),
                ApiText::NoProblem.text(lang),
            )),
        }
    }

    fn source(&self) -> Source<'a> {
        match *self {
            Problem::Sent(text) => Source::Text {
                name: Path::new(PROBLEM_NAME),
                text,
            },
            Problem::Exercise(e) => e.source(),
        }
    }

    fn exercise_id(&self) -> Option<&'a str> {
        match *self {
            Problem::Sent(_) => None,
            Problem::Exercise(e) => Some(&e.id),
        }
    }

    fn text(&self) -> Option<&'a str> {
        match *self {
            Problem::Sent(text) => Some(text),
            Problem::Exercise(_) => None,
        }
    }

    /// Refuses a sent problem with more lights or surfaces than the server solves for one
    /// request. A problem that does not parse is let through: solving it reports its error as
    /// the CLI does. The server's own exercises are the instructor's, and always admitted.
    fn admit(&self, state: &super::State) -> Result<(), ProblemError> {
        let Problem::Sent(_) = self else {
            return Ok(());
        };
        let source = self.source();
        let Ok(file) = source.parse() else {
            return Ok(());
        };
        let limits = &state.limits;
        let over = |field: &str, what: Items, n: usize, max: usize| {
            crate::problem::Invalid::of(field, TooMany::Items { n, what, max }).at(source.name())
        };
        if file.lights.len() > limits.lights {
            return Err(over(
                "lights",
                Items::Lights,
                file.lights.len(),
                limits.lights,
            ));
        }
        if file.surfaces.len() > limits.surfaces {
            return Err(over(
                "surfaces",
                Items::Surfaces,
                file.surfaces.len(),
                limits.surfaces,
            ));
        }
        Ok(())
    }
}

use super::faults::Shape;

/// The request's JSON body read into `T`: 415 when it is not JSON's content type, 400 when it
/// is not the API's JSON (the message names the line, the column and what was expected). The
/// request's `lang` is not read yet: these refusals are in the language of its
/// `Accept-Language` header, as the pages choose theirs (English without one).
fn envelope<'a, T: Deserialize<'a>>(
    headers: &HeaderMap,
    body: &'a [u8],
    shape: Shape,
) -> Result<T, Response> {
    let lang = header_lang(headers);
    let json = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.split(';').next())
        .is_some_and(|v| {
            let v = v.trim();
            v.eq_ignore_ascii_case("application/json")
        });
    if !json {
        return Err(error(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "usage",
            None,
            ApiText::NotJson { shape }.text(lang),
        ));
    }
    let text = std::str::from_utf8(body).map_err(|e| {
        error(
            StatusCode::BAD_REQUEST,
            "syntax",
            None,
            ApiText::NotUtf8 {
                byte: e.valid_up_to(),
            }
            .text(lang),
        )
    })?;
    let refused = |field: Option<String>, inner: &serde_json::Error| {
        let reason = Reason {
            field: field.clone(),
            error: crate::problem::JsonError::of(inner),
        };
        error(
            StatusCode::BAD_REQUEST,
            "syntax",
            field.as_deref(),
            ApiText::NotTheApis { reason, shape }.text(lang),
        )
    };
    if !text.trim_start().starts_with('{') {
        return Err(error(
            StatusCode::BAD_REQUEST,
            "syntax",
            None,
            ApiText::NotAnObject { shape }.text(lang),
        ));
    }
    let mut de = serde_json::Deserializer::from_str(text);
    let value: T = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let field = e.path().to_string();
        if field == "problem" || field.starts_with("problem.") || field.starts_with("problem[") {
            if let Some(refusal) = broken_problem(text, lang) {
                return refusal;
            }
        }
        refused((field != "." && field != "?").then_some(field), e.inner())
    })?;
    de.end().map_err(|e| refused(None, &e))?;
    Ok(value)
}

/// A request whose `problem` is not JSON (`NaN`, a missing comma): the problem's text from its
/// first character on, read as the CLI reads a file, for the CLI's message and fix (`JSON has
/// no NaN`), its line and column counted from the problem's first line (a file's lines, when
/// the file was sent as it is). `None` when the problem reads well (the envelope is what is
/// broken, after it).
fn broken_problem(text: &str, lang: Lang) -> Option<Response> {
    let key = text.find("\"problem\"")?;
    let rest = text[key + "\"problem\"".len()..].trim_start();
    let rest = rest.strip_prefix(':')?.trim_start();
    let name = Path::new(PROBLEM_NAME);
    match crate::problem::parse_str(name, rest) {
        Err(e @ ProblemError::Syntax { .. }) if !is_trailing(&e) => {
            Some(problem_error(&e, name, lang))
        }
        _ => None,
    }
}

/// The language of a request's `Accept-Language` header (English without one): what the
/// refusals said before its `lang` is read speak.
fn header_lang(headers: &HeaderMap) -> Lang {
    headers
        .get(header::ACCEPT_LANGUAGE)
        .and_then(|v| v.to_str().ok())
        .and_then(super::pages::lang::accept_language)
        .unwrap_or(Lang::En)
}

/// Why a body is not the API's JSON: serde's words read into a value, after the field where
/// the reading stopped (`exercise: invalid type: …`).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Reason {
    field: Option<String>,
    error: crate::problem::JsonError,
}

impl Message for Reason {
    fn text(&self, lang: Lang) -> String {
        match &self.field {
            Some(f) => format!("{f}: {}", self.error.text(lang)),
            None => self.error.text(lang),
        }
    }
}

/// Whether a syntax error is only the rest of the envelope after the problem.
fn is_trailing(e: &ProblemError) -> bool {
    e.is_trailing()
}

/// The `lang` of a request: English unless `"pt"` (a code that is none is refused in the
/// language of its `Accept-Language`).
fn lang(text: Option<&str>, headers: &HeaderMap) -> Result<Lang, Response> {
    match text {
        None => Ok(Lang::En),
        Some(code) => Lang::from_code(code).ok_or_else(|| {
            error(
                StatusCode::BAD_REQUEST,
                "usage",
                Some("lang"),
                ApiText::NotALanguage {
                    code: Echo::new(code, 40),
                }
                .text(header_lang(headers)),
            )
        }),
    }
}

/// A problem that cannot be solved, as `phong solve --format json` writes it (422), its
/// message in `lang`.
fn problem_error(e: &ProblemError, name: &Path, lang: Lang) -> Response {
    let mut doc = crate::report::file::error_json(name, e);
    doc["error"]["message"] = serde_json::Value::String(e.text(lang));
    json_response(StatusCode::UNPROCESSABLE_ENTITY, &doc)
}

/// The sentences of `phong check`'s document that say why something could not be checked
/// (`error.message`, `steps_error.message`, and an invalid verdict's `message`, which is the
/// error's own sentence) in `lang`: each is the English of one of `failures`, said again.
fn say_failures_in(doc: &mut serde_json::Value, failures: &[&check::report::Failure], lang: Lang) {
    let places: [&[&str]; 3] = [
        &["error", "message"],
        &["steps_error", "message"],
        &["message"],
    ];
    for place in places {
        let Some(slot) = place.iter().try_fold(&mut *doc, |v, key| v.get_mut(*key)) else {
            continue;
        };
        let said = slot.as_str().and_then(|english| {
            failures
                .iter()
                .find(|f| f.message.text(Lang::En) == english)
                .map(|f| f.message.text(lang))
        });
        if let Some(said) = said {
            *slot = serde_json::Value::String(said);
        }
    }
}

/// An error of the API: `{"error": {"kind", "field", "message"}}` with `status`.
pub(crate) fn error(
    status: StatusCode,
    kind: &str,
    field: Option<&str>,
    message: String,
) -> Response {
    json_response(
        status,
        &serde_json::json!({
            "error": { "kind": kind, "field": field, "message": message }
        }),
    )
}

/// `value` as the CLI prints JSON: pretty, keys in order, a final newline.
fn json_response(status: StatusCode, value: &impl serde::Serialize) -> Response {
    let mut text = serde_json::to_string_pretty(value).unwrap_or_else(|_| "null".into());
    text.push('\n');
    (
        status,
        [(header::CONTENT_TYPE, "application/json; charset=utf-8")],
        text,
    )
        .into_response()
}
