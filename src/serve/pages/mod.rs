//! The HTML pages: the list of exercises, an exercise with its answer form, one's own problem.

use axum::Router;

use super::Shared;

/// The pages' routes.
pub(crate) fn routes() -> Router<Shared> {
    Router::new()
}
