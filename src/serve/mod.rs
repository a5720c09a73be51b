//! `phong serve`: the checker as a small web application, for a course's own server, so that a
//! student can check an answer (and its steps) with nothing installed.
//!
//! - [`catalogue`]: the exercises served (the bundled ones, or an instructor's folder), read once
//!   at start-up.
//! - [`api`]: `POST /api/solve` and `POST /api/check`, the JSON of `phong solve --format json`
//!   and `phong check --format json`.
//! - [`pages`]: the HTML pages (the list, an exercise with its answer form, one's own problem),
//!   which work without JavaScript.
//! - [`limits`]: what one request may ask of the server (body size, lights, surfaces, time) and
//!   the response headers every page carries.
//!
//! Nothing is kept between requests, and no request reads the file system: a problem arrives as
//! text ([`crate::problem::Source::Text`]), which may not name a mesh file.

pub(crate) mod api;
pub(crate) mod catalogue;
pub(crate) mod limits;
pub(crate) mod pages;

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;

use axum::Router;

use catalogue::Catalogue;
use limits::Limits;

/// How `phong serve` was started.
#[derive(Debug, Clone)]
pub(crate) struct Config {
    /// Where to listen (port 0: any free port, printed at start-up).
    pub(crate) addr: SocketAddr,
    /// The instructor's folder of problem files, in place of the bundled exercises.
    pub(crate) exercises: Option<PathBuf>,
    /// Where to append each checked answer (JSON lines); without it no answer is kept.
    pub(crate) log_answers: Option<PathBuf>,
    /// What one request may ask.
    pub(crate) limits: Limits,
}

/// What every request may read (never write: no state is kept between requests).
#[derive(Debug)]
pub(crate) struct State {
    /// The exercises served.
    pub(crate) catalogue: Catalogue,
    /// What one request may ask.
    pub(crate) limits: Limits,
}

/// Shared by the handlers.
pub(crate) type Shared = Arc<State>;

/// The application: the API and the pages behind the limits and headers of [`limits::layers`].
pub(crate) fn router(state: Shared) -> Router {
    let limits = state.limits.clone();
    let routes = Router::new()
        .merge(api::routes())
        .merge(pages::routes())
        .with_state(state);
    limits::layers(routes, &limits)
}

/// Why the server could not start.
#[derive(Debug, thiserror::Error)]
pub(crate) enum StartError {
    /// An exercise of `--exercises` cannot be read or is invalid.
    #[error("--exercises: {0}")]
    Exercises(#[from] crate::problem::ProblemError),
    /// The address cannot be listened on.
    #[error("--addr: cannot listen on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        #[source]
        source: std::io::Error,
    },
    /// The async runtime or the connection loop failed.
    #[error("the server stopped: {0}")]
    Runtime(#[source] std::io::Error),
}

/// Runs the server until SIGINT or SIGTERM: prints `listening on http://ADDR` on standard
/// error once it accepts connections.
pub(crate) fn run(config: &Config) -> Result<(), StartError> {
    let catalogue = match &config.exercises {
        Some(dir) => Catalogue::folder(dir)?,
        None => Catalogue::bundled(),
    };
    let state = Arc::new(State {
        catalogue,
        limits: config.limits.clone(),
    });
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(StartError::Runtime)?;
    runtime.block_on(async {
        let listener = tokio::net::TcpListener::bind(config.addr)
            .await
            .map_err(|source| StartError::Bind {
                addr: config.addr,
                source,
            })?;
        let local = listener.local_addr().map_err(StartError::Runtime)?;
        eprintln!("listening on http://{local}");
        axum::serve(listener, router(state))
            .with_graceful_shutdown(shutdown())
            .await
            .map_err(StartError::Runtime)
    })
}

/// Resolves on SIGINT (Ctrl-C) or SIGTERM (systemd's stop).
async fn shutdown() {
    let interrupt = tokio::signal::ctrl_c();
    #[cfg(unix)]
    {
        let mut term =
            match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
                Ok(s) => s,
                Err(_) => return interrupt.await.unwrap_or(()),
            };
        tokio::select! {
            _ = interrupt => {},
            _ = term.recv() => {},
        }
    }
    #[cfg(not(unix))]
    interrupt.await.unwrap_or(());
}
