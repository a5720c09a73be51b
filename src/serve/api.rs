//! The JSON API: `POST /api/solve` and `POST /api/check`, answering what `phong solve --format
//! json` and `phong check --format json` print.

use axum::Router;

use super::Shared;

/// The API's routes.
pub(crate) fn routes() -> Router<Shared> {
    Router::new()
}
