//! The HTML pages: the list of exercises, an exercise with its answer form, one's own problem.
//! They work without JavaScript (there is none) and without CSS (the stylesheet is a file,
//! `/static/phong.css`, as the Content-Security-Policy asks); every fixed string is in both
//! languages ([`lang::Text`]), and the language is the request's ([`lang::of`]).
//!
//! - [`list`]: `GET /`.
//! - [`exercise`]: `GET` and `POST /exercise/{id}`: the statement, the answer and step boxes,
//!   the verdict, the worked solution.
//! - [`own`]: `GET` and `POST /own`, `POST /own/problem.json`: one's own problem as a form.
//! - [`layout`]: the shell of every page, and the stylesheet's route.

pub(crate) mod exercise;
pub(crate) mod lang;
pub(crate) mod layout;
pub(crate) mod list;
pub(crate) mod own;

use axum::routing::{get, post};
use axum::Router;

use super::Shared;

/// The pages' routes.
pub(crate) fn routes() -> Router<Shared> {
    Router::new()
        .route("/", get(list::list))
        .route("/exercise/{id}", get(exercise::get).post(exercise::post))
        .route("/own", get(own::get).post(own::post))
        .route("/own/problem.json", post(own::download))
        .route("/static/phong.css", get(layout::css))
}
