//! The arguments of `phong serve`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct ServeArgs {
    /// The address to listen on; port 0 picks a free port (printed at start-up). Behind a
    /// reverse proxy, keep the loopback address.
    #[arg(long, value_name = "IP:PORT", default_value = "127.0.0.1:8080")]
    pub(crate) addr: std::net::SocketAddr,
    /// Serve every *.json problem of this folder (each checked at start-up) instead of the
    /// bundled exercises.
    #[arg(long, value_name = "DIR")]
    pub(crate) exercises: Option<PathBuf>,
    /// The course policy answers are judged by [default: course-policy.json in --exercises,
    /// else the defaults].
    #[arg(long, value_name = "FILE")]
    pub(crate) policy: Option<PathBuf>,
    /// Append each checked answer to this file, one JSON line each (the answer's first 64
    /// characters, its length and its hash); without it, no answer is kept.
    #[arg(long, value_name = "PATH")]
    pub(crate) log_answers: Option<PathBuf>,
    /// The most kB (1,000 bytes) the answers' log holds: before a line would pass it, PATH is
    /// renamed PATH.1 (replacing the older one) and a new PATH begun, so the two hold at most
    /// twice this. Default 65536 (64 MiB).
    #[arg(long, value_name = "KB", default_value_t = 65_536, value_parser = clap::value_parser!(u64).range(1..=1_073_741_824))]
    pub(crate) log_answers_max: u64,
    /// The most requests handled at once; more are refused with 503 at once.
    #[arg(long, value_name = "N", default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..=65536))]
    pub(crate) max_concurrent: u32,
    /// The most connections open at once (idle keep-alive ones included); more are closed as
    /// soon as they are accepted.
    #[arg(long, value_name = "N", default_value_t = 1024, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) max_connections: u32,
    /// The most connections open at once from one client address (an IPv6 client's /64); more
    /// are closed as soon as they are accepted. Behind a reverse proxy every client is the
    /// proxy: give it --max-connections, and limit clients in the proxy.
    #[arg(long, value_name = "N", default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) max_connections_per_client: u32,
    /// The most seconds a request may take (its body's arrival included).
    #[arg(long, value_name = "SECONDS", default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=3600))]
    pub(crate) timeout: u32,
    /// The most seconds a client may take to send a request's headers, or leave a connection
    /// idle between requests (at most --timeout).
    #[arg(long, value_name = "SECONDS", default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=3600))]
    pub(crate) header_timeout: u32,
}
