//! `phong serve` under load, side by side in one run: the check of exercise 4.2 called in
//! process (the work of one request: solved for the request, or prepared once), then `POST
//! /api/check` on 4.2 over HTTP from 64 keep-alive clients on loopback (the speed goal: ≥ 5,000
//! requests/s with p99 ≤ 20 ms on two cores), the problem sent with each request and named as
//! the server's exercise, then the mixed requests of the load test.
//!
//! `cargo bench --bench serve` (release). `PHONG_BENCH_REQUESTS=N` sets the HTTP requests per
//! run (default 50,000); `PHONG_BENCH_CLIENTS=N` the clients (default 64).

#[path = "../tests/support/http.rs"]
mod http;
#[path = "../tests/support/load.rs"]
mod load;
#[path = "../tests/support/server.rs"]
#[allow(dead_code)]
mod server;

use std::path::Path;
use std::time::Instant;

fn env(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument selects nothing here.
    let requests = env("PHONG_BENCH_REQUESTS", 50_000);
    let clients = env("PHONG_BENCH_CLIENTS", 64).max(1);
    let e42 = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/exercises/4.2.json"))
        .expect("exercise 4.2");

    // In process: the library call a request makes.
    let options = phong::check::CheckOptions {
        answer: Some("0.245 0.28 0.21".into()),
        scale: Some(phong::check::Scale::Unit),
        ..Default::default()
    };
    let source = phong::problem::Source::Text {
        name: Path::new("problem"),
        text: &e42,
    };
    let n = 20_000;
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(phong::check::check_source(source, &options));
    }
    let per = t.elapsed().as_secs_f64() / f64::from(n);
    println!(
        "in process   check_source(4.2)         {:>8.1} µs/call  ({:.0} calls/s on one core)",
        per * 1e6,
        1.0 / per
    );
    let prepared = phong::check::Prepared::of(source);
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(phong::check::check_prepared(&prepared, &options));
    }
    let per = t.elapsed().as_secs_f64() / f64::from(n);
    println!(
        "in process   check_prepared(4.2)       {:>8.1} µs/call  ({:.0} calls/s on one core)",
        per * 1e6,
        1.0 / per
    );

    let server = server::Server::start(&[]);
    // Warm-up: connections, allocator, caches.
    load::run(server.addr, &load::check_42(&e42), 2_000, clients);
    for (name, mix) in [
        ("/api/check 4.2 sent", load::check_42(&e42)),
        ("/api/check \"4.2\" named", load::check_42_named()),
        ("mixed", load::mixed(&e42)),
    ] {
        let run = load::run(server.addr, &mix, requests, clients);
        assert_eq!(run.answered, run.sent, "{:?}", run.wrong_examples);
        assert_eq!(run.wrong, 0, "{:?}", run.wrong_examples);
        println!("over HTTP    {name:<26}{}", run.summary(clients));
    }
}
