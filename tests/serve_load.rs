//! A bounded load test of `phong serve`: 20,000 mixed requests (checks, solves, the list and
//! refusals) from 64 keep-alive clients on loopback; no error, no lost response. It prints the
//! throughput and the p99 latency (of a debug build here: the speed goal is measured in release
//! by `cargo bench --bench serve`, see docs/benchmarks.md).
//!
//! `PHONG_LOAD_REQUESTS=N` changes the count (at least one per client).

#![cfg(feature = "serve")]

#[path = "support/http.rs"]
mod http;
#[path = "support/load.rs"]
mod load;
#[path = "support/server.rs"]
#[allow(dead_code)]
mod server;

#[test]
fn twenty_thousand_mixed_requests_from_64_clients_are_all_answered() {
    let total: usize = std::env::var("PHONG_LOAD_REQUESTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(20_000)
        .max(64);
    let clients = 64;
    let mut server = server::Server::start(&[]);
    let e42 = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/exercises/4.2.json"))
        .expect("exercise 4.2");
    let mix = load::mixed(&e42);
    let run = load::run(server.addr, &mix, total, clients);
    eprintln!("serve_load: {}", run.summary(clients));
    assert_eq!(
        run.answered, run.sent,
        "lost responses: {:?}",
        run.wrong_examples
    );
    assert_eq!(
        run.wrong, 0,
        "unexpected statuses: {:?}",
        run.wrong_examples
    );
    assert!(server.alive());
}
