//! A load driver for `phong serve`: `clients` threads, each on its own keep-alive connection,
//! send their share of a list of requests and time each one. Loopback only, bounded in count.
#![allow(dead_code)]

use std::net::SocketAddr;
use std::time::{Duration, Instant};

use super::http;

/// One request of the mix, and the status it must get.
#[derive(Clone, Debug)]
pub struct Shot {
    pub method: &'static str,
    pub path: &'static str,
    pub content_type: Option<&'static str>,
    pub body: String,
    pub status: u16,
}

/// What a run measured.
#[derive(Debug)]
pub struct Run {
    /// Requests sent.
    pub sent: usize,
    /// Responses received (a lost response is one sent and never answered).
    pub answered: usize,
    /// Responses whose status was not the one expected, with the first few described.
    pub wrong: usize,
    pub wrong_examples: Vec<String>,
    /// Each answered request's time, sorted.
    pub latencies: Vec<Duration>,
    /// Wall-clock time of the whole run.
    pub elapsed: Duration,
}

impl Run {
    pub fn throughput(&self) -> f64 {
        self.answered as f64 / self.elapsed.as_secs_f64()
    }

    pub fn p(&self, percentile: f64) -> Duration {
        http::percentile(&self.latencies, percentile)
    }

    /// `20000 requests, 64 clients: 8123 req/s, p50 3.1 ms, p99 9.8 ms, max 20.1 ms`.
    pub fn summary(&self, clients: usize) -> String {
        format!(
            "{} requests, {clients} clients, {:.2} s: {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms; {} wrong, {} lost",
            self.sent,
            self.elapsed.as_secs_f64(),
            self.throughput(),
            self.p(50.0).as_secs_f64() * 1e3,
            self.p(99.0).as_secs_f64() * 1e3,
            self.latencies.last().copied().unwrap_or_default().as_secs_f64() * 1e3,
            self.wrong,
            self.sent - self.answered,
        )
    }
}

/// Sends `total` requests, request `i` being `mix[i % mix.len()]`, from `clients` threads.
/// A client whose connection fails reconnects once per request (and the failure counts as a
/// lost response).
pub fn run(addr: SocketAddr, mix: &[Shot], total: usize, clients: usize) -> Run {
    let start = Instant::now();
    let results: Vec<(usize, usize, Vec<String>, Vec<Duration>)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..clients)
            .map(|k| {
                scope.spawn(move || {
                    let mut client = http::Client::connect(addr).ok();
                    let (mut answered, mut wrong) = (0, 0);
                    let mut examples = Vec::new();
                    let mut times = Vec::with_capacity(total / clients + 1);
                    for i in (k..total).step_by(clients) {
                        let shot = &mix[i % mix.len()];
                        if client.is_none() {
                            client = http::Client::connect(addr).ok();
                        }
                        let Some(c) = client.as_mut() else { continue };
                        let t = Instant::now();
                        match c.send(
                            shot.method,
                            shot.path,
                            shot.content_type,
                            shot.body.as_bytes(),
                        ) {
                            Ok(r) => {
                                times.push(t.elapsed());
                                answered += 1;
                                if r.status != shot.status {
                                    wrong += 1;
                                    if examples.len() < 3 {
                                        examples.push(format!(
                                            "{} {}: {} instead of {}: {}",
                                            shot.method,
                                            shot.path,
                                            r.status,
                                            shot.status,
                                            r.text()
                                        ));
                                    }
                                }
                                if r.header("connection") == Some("close") {
                                    client = None;
                                }
                            }
                            Err(e) => {
                                if examples.len() < 3 {
                                    examples.push(format!("{} {}: {e}", shot.method, shot.path));
                                }
                                client = None;
                            }
                        }
                    }
                    (answered, wrong, examples, times)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a client thread"))
            .collect()
    });
    let elapsed = start.elapsed();
    let mut run = Run {
        sent: total,
        answered: 0,
        wrong: 0,
        wrong_examples: Vec::new(),
        latencies: Vec::with_capacity(total),
        elapsed,
    };
    for (a, w, ex, t) in results {
        run.answered += a;
        run.wrong += w;
        run.wrong_examples.extend(ex);
        run.latencies.extend(t);
    }
    run.latencies.sort();
    run
}

/// The mixed requests of the load test: checks (right, wrong, a slip, with steps, a problem
/// sent), solves, the list, and refusals (4xx expected).
pub fn mixed(exercise_42: &str) -> Vec<Shot> {
    let json = Some("application/json");
    let post = |path, body: String, status| Shot {
        method: "POST",
        path,
        content_type: json,
        body,
        status,
    };
    vec![
        post("/api/check", "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\"}".into(), 200),
        post("/api/check", format!("{{\"problem\": {exercise_42}, \"answer\": \"0 0 0\"}}"), 200),
        post("/api/check", "{\"exercise\": \"4.1\", \"answer\": \"0.5 0.7 0.3\", \"lang\": \"pt\"}".into(), 200),
        post("/api/check", "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\", \"steps\": {\"cos_theta\": \"0.98995\"}}".into(), 200),
        post("/api/solve", "{\"exercise\": \"4.3\", \"lang\": \"pt\"}".into(), 200),
        post("/api/solve", format!("{{\"problem\": {exercise_42}, \"precision\": \"f32\"}}"), 200),
        Shot { method: "GET", path: "/api/exercises", content_type: None, body: String::new(), status: 200 },
        post("/api/check", "{\"exercise\": \"4.2\", \"answer\": \"abc\"}".into(), 422),
        post("/api/check", "{\"exercise\": ".into(), 400),
        Shot { method: "POST", path: "/api/check", content_type: Some("text/plain"), body: "x".into(), status: 415 },
        Shot { method: "GET", path: "/nope", content_type: None, body: String::new(), status: 404 },
    ]
}

/// Only `/api/check` on 4.2, the problem sent with each request (the speed goal's request).
pub fn check_42(exercise_42: &str) -> Vec<Shot> {
    vec![Shot {
        method: "POST",
        path: "/api/check",
        content_type: Some("application/json"),
        body: format!("{{\"problem\": {exercise_42}, \"answer\": \"0.245 0.28 0.21\"}}"),
        status: 200,
    }]
}

/// `/api/check` on 4.2 named as the server's exercise (solved once at start-up).
pub fn check_42_named() -> Vec<Shot> {
    vec![Shot {
        method: "POST",
        path: "/api/check",
        content_type: Some("application/json"),
        body: "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\"}".into(),
        status: 200,
    }]
}
