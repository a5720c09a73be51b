//! What one request may ask of `phong serve`, and the layers that enforce it in front of every
//! route: the body's size, the time a request may take, how many are handled at once (the rest
//! are refused with 503 at once rather than queued without bound), strict response headers, and
//! a panic turned into a plain 500.

use std::time::Duration;

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Router;

/// The bounds of one request.
#[derive(Debug, Clone)]
pub(crate) struct Limits {
    /// The largest request body, in bytes.
    pub(crate) body_bytes: usize,
    /// The most lights a problem may have.
    pub(crate) lights: usize,
    /// The most surfaces a problem may have.
    pub(crate) surfaces: usize,
    /// The longest a request may take, its body's arrival included.
    pub(crate) time: Duration,
    /// The most requests handled at once.
    pub(crate) concurrency: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            body_bytes: 64 * 1024,
            lights: 16,
            surfaces: 64,
            time: Duration::from_secs(10),
            concurrency: 256,
        }
    }
}

/// The Content-Security-Policy of every response: nothing from elsewhere, no inline script, no
/// plugins, no framing; forms post only to this server.
pub(crate) const CSP: &str = "default-src 'none'; script-src 'self'; style-src 'self'; \
     img-src 'self' data:; form-action 'self'; frame-ancestors 'none'; base-uri 'none'";

/// `routes` behind the limits and headers.
pub(crate) fn layers(routes: Router, limits: &Limits) -> Router {
    use tower::ServiceBuilder;
    use tower_http::set_header::SetResponseHeaderLayer;
    let headers = ServiceBuilder::new()
        .layer(SetResponseHeaderLayer::overriding(
            header::CONTENT_SECURITY_POLICY,
            HeaderValue::from_static(CSP),
        ))
        .layer(SetResponseHeaderLayer::overriding(
            header::X_CONTENT_TYPE_OPTIONS,
            HeaderValue::from_static("nosniff"),
        ))
        .layer(SetResponseHeaderLayer::overriding(
            header::REFERRER_POLICY,
            HeaderValue::from_static("no-referrer"),
        ))
        .layer(SetResponseHeaderLayer::overriding(
            header::X_FRAME_OPTIONS,
            HeaderValue::from_static("DENY"),
        ))
        .layer(SetResponseHeaderLayer::if_not_present(
            header::CACHE_CONTROL,
            HeaderValue::from_static("no-store"),
        ));
    routes
        .layer(tower_http::limit::RequestBodyLimitLayer::new(limits.body_bytes))
        .layer(tower_http::timeout::TimeoutLayer::with_status_code(
            StatusCode::REQUEST_TIMEOUT,
            limits.time,
        ))
        .layer(
            ServiceBuilder::new()
                .layer(axum::error_handling::HandleErrorLayer::new(overloaded))
                .load_shed()
                .concurrency_limit(limits.concurrency),
        )
        .layer(tower_http::catch_panic::CatchPanicLayer::custom(panicked))
        .layer(headers)
}

/// A request refused because the server is handling as many as it may.
async fn overloaded(_: tower::BoxError) -> Response {
    (
        StatusCode::SERVICE_UNAVAILABLE,
        [(header::RETRY_AFTER, "1")],
        "the server is handling as many requests as it may; try again in a second\n",
    )
        .into_response()
}

/// A handler that panicked: a plain 500, never the panic's message or a dropped connection.
fn panicked(_: Box<dyn std::any::Any + Send + 'static>) -> Response {
    (
        StatusCode::INTERNAL_SERVER_ERROR,
        "internal error: phong could not answer this request; please report it with the \
         request that caused it\n",
    )
        .into_response()
}
