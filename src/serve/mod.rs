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
//! text ([`crate::problem::Source::Text`]), which may not name a mesh file (docs/conventions.md,
//! "Checking on the server").

pub(crate) mod api;
pub(crate) mod catalogue;
pub(crate) mod faults;
pub(crate) mod limits;
pub(crate) mod log;
pub(crate) mod pages;

use std::net::{IpAddr, Ipv6Addr, SocketAddr};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

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
    /// The most kB (1,000 bytes) the answers' log may hold before it is rotated to `PATH.1`.
    pub(crate) log_answers_max_kb: u64,
    /// What one request may ask.
    pub(crate) limits: Limits,
    /// The course policy answers are judged by.
    pub(crate) policy: Arc<crate::check::policy::Policy>,
}

/// What every request may read (never write: no state is kept between requests).
#[derive(Debug)]
pub(crate) struct State {
    /// The exercises served.
    pub(crate) catalogue: Catalogue,
    /// What one request may ask.
    pub(crate) limits: Limits,
    /// Where checked answers are appended (`--log-answers`); `None`: none is kept.
    pub(crate) answers: Option<log::AnswerLog>,
    /// The course policy answers are judged by.
    pub(crate) policy: Arc<crate::check::policy::Policy>,
}

/// Shared by the handlers.
pub(crate) type Shared = Arc<State>;

/// The application: the API and the pages behind the limits and headers of [`limits::layers`].
pub(crate) fn router(state: Shared) -> Router {
    let limits = state.limits.clone();
    let routes = Router::new()
        .merge(api::routes())
        .merge(pages::routes())
        .fallback(not_found)
        .method_not_allowed_fallback(method_not_allowed)
        .with_state(state);
    limits::layers(routes, &limits).layer(axum::middleware::from_fn(log::request))
}

/// No route has this path: a plain 404 that says where to start.
async fn not_found(uri: axum::http::Uri) -> axum::response::Response {
    use axum::response::IntoResponse;
    (
        axum::http::StatusCode::NOT_FOUND,
        format!(
            "{}: no such page; the exercises are listed at /, and the API is POST /api/solve, \
             POST /api/check and GET /api/exercises\n",
            shown_path(uri.path())
        ),
    )
        .into_response()
}

/// A route exists at this path, but not for this method.
async fn method_not_allowed(
    method: axum::http::Method,
    uri: axum::http::Uri,
) -> axum::response::Response {
    use axum::response::IntoResponse;
    (
        axum::http::StatusCode::METHOD_NOT_ALLOWED,
        format!(
            "{method} {}: this method is not served here; the API takes POST (GET for \
             /api/exercises), the pages GET\n",
            shown_path(uri.path())
        ),
    )
        .into_response()
}

/// A request's path as a message may quote it: at most 100 characters.
fn shown_path(path: &str) -> String {
    crate::text::number::shorten(path, 100)
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
    /// The answers' log cannot be opened for appending.
    #[error("--log-answers: cannot open {} for appending: {source}", path.display())]
    Log {
        path: PathBuf,
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
    let answers = match &config.log_answers {
        Some(path) => Some(
            log::AnswerLog::open(path, config.log_answers_max_kb).map_err(|source| {
                StartError::Log {
                    path: path.clone(),
                    source,
                }
            })?,
        ),
        None => None,
    };
    let state = Arc::new(State {
        catalogue,
        limits: config.limits.clone(),
        answers,
        policy: config.policy.clone(),
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
        accept(listener, router(state), &config.limits).await;
        Ok(())
    })
}

/// Accepts connections until SIGINT or SIGTERM, each served by hyper's HTTP/1 with the limits
/// `axum::serve` does not expose: the time a client may take to send its headers (or leave a
/// keep-alive connection idle), the size of a request head, and the number of connections open
/// at once, in all and from one client address. Then stops accepting, lets each open connection
/// finish its request (at most the request time limit), and returns.
async fn accept(listener: tokio::net::TcpListener, app: Router, limits: &Limits) {
    use hyper_util::rt::{TokioIo, TokioTimer};
    let graceful = hyper_util::server::graceful::GracefulShutdown::new();
    let open = Open::default();
    let mut stop = std::pin::pin!(shutdown());
    loop {
        let (stream, peer) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(accepted) => accepted,
                // Out of file descriptors, or a connection reset before it was accepted: wait a
                // little (other connections close meanwhile) rather than spin.
                Err(e) => {
                    eprintln!("accept: {e}");
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            () = &mut stop => break,
        };
        let Some(slot) = Slot::take(&open, client(peer.ip()), limits) else {
            // As many connections as the server keeps, in all or from this client: this one is
            // closed at once.
            drop(stream);
            continue;
        };
        let _ = stream.set_nodelay(true);
        let app = app.clone();
        let service = hyper::service::service_fn(move |request| {
            tower::ServiceExt::<hyper::Request<hyper::body::Incoming>>::oneshot(
                app.clone(),
                request,
            )
        });
        let mut http = hyper::server::conn::http1::Builder::new();
        http.timer(TokioTimer::new())
            .header_read_timeout(limits.header_time)
            .max_buf_size(limits.head_bytes.max(8192));
        let connection = graceful.watch(http.serve_connection(TokioIo::new(stream), service));
        tokio::spawn(async move {
            // A connection's errors (a client gone, a head too slow or too large) end that
            // connection only; hyper has answered what could be answered.
            let _ = connection.await;
            drop(slot);
        });
    }
    drop(listener);
    tokio::select! {
        () = graceful.shutdown() => {},
        () = tokio::time::sleep(limits.time) => {},
    }
}

/// The connections open: how many in all, and how many from each client address (an entry
/// only while it has one open, so the map holds at most `Limits::connections` entries).
#[derive(Clone, Default)]
struct Open {
    all: Arc<AtomicUsize>,
    by_client: Arc<std::sync::Mutex<std::collections::HashMap<IpAddr, usize>>>,
}

/// The address a client is counted under: an IPv4 address (an IPv4-mapped IPv6 one read as
/// IPv4), or an IPv6 address's /64 prefix, the block one subscriber is given (RFC 6177), so
/// that a client cannot pass the cap by changing the last 64 bits of its address.
fn client(ip: IpAddr) -> IpAddr {
    match ip {
        IpAddr::V6(v6) => match v6.to_ipv4_mapped() {
            Some(v4) => IpAddr::V4(v4),
            None => {
                let s = v6.segments();
                IpAddr::V6(Ipv6Addr::new(s[0], s[1], s[2], s[3], 0, 0, 0, 0))
            }
        },
        v4 => v4,
    }
}

/// One of the open connections the server allows, given back when dropped.
struct Slot {
    open: Open,
    client: IpAddr,
}

impl Slot {
    /// A slot for a connection from `client`, unless `limits.connections` are taken, or
    /// `limits.connections_per_client` by this client.
    fn take(open: &Open, client: IpAddr, limits: &Limits) -> Option<Slot> {
        let mut by_client = open.by_client.lock().unwrap_or_else(|e| e.into_inner());
        let mine = by_client.get(&client).copied().unwrap_or(0);
        if mine >= limits.connections_per_client {
            return None;
        }
        open.all
            .fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| {
                (n < limits.connections).then_some(n + 1)
            })
            .ok()?;
        by_client.insert(client, mine + 1);
        Some(Slot {
            open: open.clone(),
            client,
        })
    }
}

impl Drop for Slot {
    fn drop(&mut self) {
        let mut by_client = self
            .open
            .by_client
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        if let Some(n) = by_client.get_mut(&self.client) {
            *n -= 1;
            if *n == 0 {
                by_client.remove(&self.client);
            }
        }
        drop(by_client);
        self.open.all.fetch_sub(1, Ordering::AcqRel);
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clients_are_ipv4_addresses_and_ipv6_slash_64s() {
        let ip = |s: &str| s.parse::<IpAddr>().unwrap();
        assert_eq!(client(ip("127.0.0.2")), ip("127.0.0.2"));
        assert_eq!(client(ip("::ffff:10.1.2.3")), ip("10.1.2.3"));
        assert_eq!(client(ip("2001:db8:1:2:a:b:c:d")), ip("2001:db8:1:2::"));
        assert_eq!(
            client(ip("2001:db8:1:2:ffff::1")),
            client(ip("2001:db8:1:2::9"))
        );
        assert_ne!(client(ip("2001:db8:1:3::1")), client(ip("2001:db8:1:2::1")));
    }

    #[test]
    fn one_client_takes_at_most_its_share_and_gives_it_back() {
        let limits = Limits {
            connections: 5,
            connections_per_client: 2,
            ..Limits::default()
        };
        let open = Open::default();
        let (a, b) = (IpAddr::from([10, 0, 0, 1]), IpAddr::from([10, 0, 0, 2]));
        let a1 = Slot::take(&open, a, &limits).unwrap();
        let a2 = Slot::take(&open, a, &limits).unwrap();
        assert!(Slot::take(&open, a, &limits).is_none(), "a's third");
        let b_slots: Vec<Slot> = (0..2)
            .map(|_| Slot::take(&open, b, &limits).unwrap())
            .collect();
        let c = Slot::take(&open, IpAddr::from([10, 0, 0, 3]), &limits).unwrap();
        // Five open in all: no one gets a sixth.
        assert!(Slot::take(&open, IpAddr::from([10, 0, 0, 4]), &limits).is_none());
        drop(a1);
        assert!(
            Slot::take(&open, a, &limits).is_some(),
            "a's slot given back"
        );
        drop((a2, b_slots, c));
        assert_eq!(open.all.load(Ordering::SeqCst), 0);
        assert!(open.by_client.lock().unwrap().is_empty());
    }
}
