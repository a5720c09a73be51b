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
    /// The most connections open at once (idle keep-alive ones included); a connection beyond
    /// them is closed as soon as it is accepted.
    pub(crate) connections: usize,
    /// The most of them open at once from one client address (an IPv6 client's /64), so that
    /// one address cannot take the whole budget; a connection beyond them is closed as soon as
    /// it is accepted.
    pub(crate) connections_per_client: usize,
    /// The longest a client may take to send a request's headers (slowloris), or leave a
    /// keep-alive connection idle: shorter than `time`, so that a connection that sends no
    /// request frees its slot soon.
    pub(crate) header_time: Duration,
    /// The largest request head (request line and headers), in bytes; a larger one is refused
    /// with 431.
    pub(crate) head_bytes: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            body_bytes: 64 * 1024,
            lights: 16,
            surfaces: 64,
            time: Duration::from_secs(10),
            concurrency: 256,
            connections: 1024,
            connections_per_client: 256,
            header_time: Duration::from_secs(5),
            head_bytes: 16 * 1024,
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
        .layer(tower_http::limit::RequestBodyLimitLayer::new(
            limits.body_bytes,
        ))
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
        .layer(axum::middleware::map_response_with_state(
            Explained {
                body_bytes: limits.body_bytes,
                time: limits.time,
            },
            explain,
        ))
        .layer(headers)
}

/// The limits [`explain`] names.
#[derive(Clone, Copy)]
struct Explained {
    body_bytes: usize,
    time: Duration,
}

/// A refusal by a layer (a body too large, a request too slow), whose own body says little
/// ("length limit exceeded", or nothing), given a sentence that names the limit and the fix:
/// as JSON (`{"error": {…}}`) under `/api/`, else as plain text. A route's own answers are
/// left as they are (they carry their content type).
async fn explain(
    axum::extract::State(limits): axum::extract::State<Explained>,
    uri: axum::http::Uri,
    response: Response,
) -> Response {
    let status = response.status();
    let own = response.headers().contains_key(header::CONTENT_TYPE)
        && !response
            .headers()
            .get(header::CONTENT_TYPE)
            .is_some_and(|v| v.as_bytes().starts_with(b"text/plain"));
    let message = match status {
        StatusCode::PAYLOAD_TOO_LARGE if !own => format!(
            "the request body is larger than the {} bytes ({} kB) this server takes; send one \
             problem at a time, without images or meshes",
            limits.body_bytes,
            limits.body_bytes / 1024
        ),
        StatusCode::REQUEST_TIMEOUT if !own => format!(
            "the request took longer than the {} s this server gives one (its body arrived too \
             slowly); send it again in one go",
            limits.time.as_secs_f64()
        ),
        _ => return response,
    };
    if uri.path().starts_with("/api/") {
        super::api::error(status, "usage", None, message)
    } else {
        (status, format!("{message}\n")).into_response()
    }
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
