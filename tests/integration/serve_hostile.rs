//! Hostile requests to `phong serve`: each gets a 4xx (or its connection closed) with a clear
//! message, and the server is still alive and answers a good request afterwards.

#![cfg(feature = "serve")]

use crate::support::http;
use crate::support::server;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

use server::Server;

const GOOD: &str = "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\"}";

/// The server is running and answers a good check.
fn still_answers(server: &mut Server) {
    assert!(server.alive(), "the server is still running");
    let r = http::post_json(server.addr, "/api/check", GOOD);
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.json()["verdict"], "wrong");
}

/// The `error.message` of a JSON error response with `status`.
fn refused(r: &http::Response, status: u16) -> String {
    assert_eq!(r.status, status, "{}", r.text());
    assert_eq!(r.header("x-content-type-options"), Some("nosniff"));
    r.json()["error"]["message"]
        .as_str()
        .expect("an error message")
        .to_owned()
}

/// `{"problem": TEXT}`.
fn problem(text: &str) -> String {
    format!("{{\"problem\": {text}}}")
}

/// The text of exercise 4.2.
fn e42() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/exercises/4.2.json")).unwrap()
}

/// Whether the server closes `stream` (end of file or a reset) within `within`.
fn closed_within(stream: &mut TcpStream, within: Duration) -> bool {
    stream.set_read_timeout(Some(within)).unwrap();
    let mut buf = [0u8; 4096];
    let start = Instant::now();
    loop {
        match stream.read(&mut buf) {
            Ok(0) => return true,
            // A response (hyper's 408 for a slow head) before the close.
            Ok(_) if start.elapsed() < within => continue,
            Ok(_) => return false,
            Err(e)
                if e.kind() == std::io::ErrorKind::WouldBlock
                    || e.kind() == std::io::ErrorKind::TimedOut =>
            {
                return false
            }
            Err(_) => return true,
        }
    }
}

#[test]
fn bodies_too_large_are_413_with_the_limit_named() {
    let mut server = Server::start(&[]);
    // Declared too large (Content-Length): refused before it is read.
    let big = format!("{{\"answer\": \"{}\"}}", "0".repeat(70_000));
    let m = refused(&http::post_json(server.addr, "/api/check", &big), 413);
    assert!(m.contains("65536 bytes (64 kB)"), "{m}");
    // Sent in chunks, with no length declared: cut at the limit.
    let mut c = http::Client::connect(server.addr).unwrap();
    let mut bytes = b"POST /api/check HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n".to_vec();
    for _ in 0..80 {
        bytes.extend_from_slice(b"400\r\n");
        bytes.extend(std::iter::repeat_n(b' ', 0x400));
        bytes.extend_from_slice(b"\r\n");
    }
    bytes.extend_from_slice(b"0\r\n\r\n");
    // The server may answer and close before the whole body is written.
    let _ = c.stream().write_all(&bytes);
    let r = c.read().unwrap();
    assert!(refused(&r, 413).contains("64 kB"));
    // 10,000 lights: larger than the body limit long before the lights' limit.
    let light = "{\"type\": \"point\", \"position\": [1, 1, 1], \"color\": [1, 1, 1]},";
    let lights = light.repeat(10_000);
    let text = e42().replacen("\"lights\": [", &format!("\"lights\": [{lights}"), 1);
    refused(
        &http::post_json(server.addr, "/api/check", &problem(&text)),
        413,
    );
    // 100,000 opening brackets.
    refused(
        &http::post_json(server.addr, "/api/check", &"[".repeat(100_000)),
        413,
    );
    still_answers(&mut server);
}

#[test]
fn malformed_envelopes_are_400_and_name_the_line_and_column() {
    let mut server = Server::start(&[]);
    let cases: &[(&str, &str)] = &[
        (
            "{\"exercise\": \"4.2\",",
            "EOF while parsing a value at line 1 column 19",
        ),
        (
            "{\"exercise\": 4.2}",
            "exercise: invalid type: floating point `4.2`, expected a string at line 1 column 16",
        ),
        (
            "{\"exercise\": \"4.2\", \"anwser\": \"0 0 0\"}",
            "unknown field `anwser`",
        ),
        (
            "{\"exercise\": \"4.2\"} trailing",
            "trailing characters at line 1 column 21",
        ),
        ("", "must be one JSON object"),
        ("[]", "must be one JSON object"),
        (
            "{\"exercise\": \"4.2\", \"tolerance\": 1e400}",
            "number out of range",
        ),
        (
            "{\"exercise\": \"4.2\", \"lang\": \"fr\"}",
            "lang: \"fr\" is not a language",
        ),
        ("{\"exercise\": \"4.2\", \"scale\": 7}", "scale: give 1"),
        ("{}", "the request names no problem"),
    ];
    for (body, says) in cases {
        let m = refused(&http::post_json(server.addr, "/api/check", body), 400);
        assert!(m.contains(says), "{body}: {m}");
    }
    // Not UTF-8.
    let r = http::once(
        server.addr,
        "POST",
        "/api/check",
        Some("application/json"),
        b"{\"answer\": \"\xff\xfe\"}",
    );
    assert!(refused(&r, 400).contains("not UTF-8"));
    // 60,000 brackets (under the size limit): refused at the first, never a stack overflow;
    // inside the problem, the CLI's message for a file so nested.
    let deep = format!("{{\"lights\": {}", "[".repeat(60_000));
    let m = refused(
        &http::post_json(
            server.addr,
            "/api/check",
            &deep.replacen("\"lights\"", "\"exercise\"", 1),
        ),
        400,
    );
    assert!(
        m.contains("recursion limit exceeded") || m.contains("expected a string"),
        "{m}"
    );
    let r = http::post_json(server.addr, "/api/check", &problem(&deep));
    let m = refused(&r, 422);
    // (The parser stops at the first bracket a light cannot be, long before the depth limit.)
    assert!(
        m.starts_with("problem:1:12: lights[0]: invalid type: sequence, expected a light"),
        "{m}"
    );
    still_answers(&mut server);
}

#[test]
fn a_body_that_is_not_json_is_415() {
    let mut server = Server::start(&[]);
    for ct in [
        None,
        Some("text/plain"),
        Some("application/x-www-form-urlencoded"),
        Some("application/jsonx"),
    ] {
        let r = http::once(server.addr, "POST", "/api/check", ct, GOOD.as_bytes());
        assert!(refused(&r, 415).contains("Content-Type: application/json"));
    }
    // Its parameters are allowed.
    let r = http::once(
        server.addr,
        "POST",
        "/api/check",
        Some("application/json; charset=utf-8"),
        GOOD.as_bytes(),
    );
    assert_eq!(r.status, 200);
    still_answers(&mut server);
}

#[test]
fn hostile_numbers_and_strings_in_a_problem_are_422_with_the_cli_message() {
    let mut server = Server::start(&[]);
    let e = e42();
    let cases: Vec<(String, &str)> = vec![
        // Beyond f64.
        (
            e.replacen("[5, 4, 6]", "[1e400, 4, 6]", 1),
            "number out of range",
        ),
        // Not JSON numbers.
        (e.replacen("[5, 4, 6]", "[NaN, 4, 6]", 1), "JSON has no NaN"),
        (
            e.replacen("[5, 4, 6]", "[Infinity, 4, 6]", 1),
            "JSON has no Infinity",
        ),
        (e.replacen("[5, 4, 6]", "[\"NaN\", 4, 6]", 1), "viewer"),
        // Finite numbers whose sums overflow.
        (
            e.replacen("[5, 4, 6]", "[1.7e308, 1.7e308, 1.7e308]", 1)
                .replacen("[3, 1, 3]", "[-1.7e308, -1.7e308, -1.7e308]", 1),
            "viewer",
        ),
        // A long string where a word is expected.
        (
            e.replacen(
                "\"point\", \"position\"",
                &format!("\"{}\", \"position\"", "p".repeat(30_000)),
                1,
            ),
            "lights[0].type",
        ),
    ];
    for (text, says) in &cases {
        let r = http::post_json(server.addr, "/api/solve", &problem(text));
        let m = refused(&r, 422);
        assert!(m.contains(says), "{says}: {m}");
        // Bounded by the request. (serde's "unknown variant" echoes a long word whole, in the
        // CLI too: the 30,000-character type is the one message longer than a line or two.)
        assert!(
            m.len() < 1000 || (says == &"lights[0].type" && m.len() < 31_000),
            "{}",
            m.len()
        );
    }
    // Answers: NaN-like words, a 60 kB answer, huge numbers.
    for answer in [
        "NaN NaN NaN".to_owned(),
        "inf -inf 0".to_owned(),
        "1e400 0 0".to_owned(),
        "9".repeat(60_000),
    ] {
        let body = format!("{{\"exercise\": \"4.2\", \"answer\": \"{answer}\"}}");
        let r = http::post_json(server.addr, "/api/check", &body);
        assert_eq!(r.status, 422, "{answer:.40}: {}", r.text());
        assert_eq!(r.json()["error"]["kind"], "answer");
        assert!(r.json()["error"]["message"].as_str().unwrap().len() < 1000);
    }
    still_answers(&mut server);
}

#[test]
fn unknown_routes_are_404_and_wrong_methods_405_in_plain_text() {
    let mut server = Server::start(&[]);
    for path in [
        "/nope",
        "/api/",
        "/api/solve/x",
        "/../../etc/passwd",
        "/%2e%2e/%2e%2e/etc/passwd",
    ] {
        let r = http::once(server.addr, "GET", path, None, b"");
        assert_eq!(r.status, 404, "{path}");
        assert!(r.header("content-type").unwrap().starts_with("text/plain"));
        assert!(r.text().contains("no such page"));
        assert!(!r.text().contains("root:"));
    }
    for (method, path) in [
        ("GET", "/api/check"),
        ("PUT", "/api/solve"),
        ("DELETE", "/api/check"),
        ("POST", "/api/exercises"),
    ] {
        let r = http::once(server.addr, method, path, None, b"");
        assert_eq!(r.status, 405, "{method} {path}");
        assert!(r.text().contains("this method is not served here"));
    }
    still_answers(&mut server);
}

#[test]
fn every_response_carries_the_strict_headers() {
    let server = Server::start(&[]);
    for r in [
        http::post_json(server.addr, "/api/check", GOOD),
        http::post_json(server.addr, "/api/check", "{"),
        http::once(server.addr, "GET", "/nope", None, b""),
    ] {
        let csp = r.header("content-security-policy").unwrap();
        assert!(
            csp.contains("default-src 'none'") && !csp.contains("unsafe-inline"),
            "{csp}"
        );
        assert_eq!(r.header("x-content-type-options"), Some("nosniff"));
        assert_eq!(r.header("x-frame-options"), Some("DENY"));
        assert_eq!(r.header("cache-control"), Some("no-store"));
    }
}

#[test]
fn a_header_too_large_is_431() {
    let mut server = Server::start(&[]);
    let mut s = TcpStream::connect(server.addr).unwrap();
    let head = format!(
        "GET /api/exercises HTTP/1.1\r\nHost: x\r\nX-Filler: {}\r\n\r\n",
        "a".repeat(40_000)
    );
    let _ = s.write_all(head.as_bytes());
    let mut reader = std::io::BufReader::new(s);
    let r = http::read_response(&mut reader).unwrap();
    assert_eq!(r.status, 431);
    still_answers(&mut server);
}

#[test]
fn slowloris_headers_are_cut_off_after_the_timeout() {
    let mut server = Server::start(&["--timeout", "2"]);
    let mut s = TcpStream::connect(server.addr).unwrap();
    s.write_all(b"POST /api/check HTTP/1.1\r\nHost: x\r\n")
        .unwrap();
    let start = Instant::now();
    // One byte every 100 ms: the head never completes.
    let mut cut = false;
    for _ in 0..60 {
        if s.write_all(b"X").is_err() {
            cut = true;
            break;
        }
        std::thread::sleep(Duration::from_millis(100));
        // Meanwhile the server answers others.
        if start.elapsed() > Duration::from_millis(500)
            && start.elapsed() < Duration::from_millis(700)
        {
            still_answers(&mut server);
        }
    }
    assert!(
        cut || closed_within(&mut s, Duration::from_secs(1)),
        "the trickling connection was cut"
    );
    let took = start.elapsed();
    assert!(took < Duration::from_secs(5), "cut after {took:?}");
    still_answers(&mut server);
}

#[test]
fn a_slow_body_is_408_after_the_timeout() {
    let mut server = Server::start(&["--timeout", "2"]);
    let mut c = http::Client::connect(server.addr).unwrap();
    let start = Instant::now();
    c.stream()
        .write_all(b"POST /api/check HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 1000\r\n\r\n{\"exer")
        .unwrap();
    let r = c.read().unwrap();
    let m = refused(&r, 408);
    assert!(m.contains("longer than the 2 s"), "{m}");
    assert!(start.elapsed() < Duration::from_secs(5));
    still_answers(&mut server);
}

#[test]
fn idle_connections_beyond_the_cap_are_closed_and_idle_ones_time_out() {
    let mut server = Server::start(&["--timeout", "2", "--max-connections", "50"]);
    let mut idle: Vec<TcpStream> = (0..50)
        .map(|_| TcpStream::connect(server.addr).unwrap())
        .collect();
    // Let the server accept them all.
    std::thread::sleep(Duration::from_millis(300));
    // The 51st is closed at once.
    let mut extra = TcpStream::connect(server.addr).unwrap();
    assert!(
        closed_within(&mut extra, Duration::from_secs(1)),
        "the connection beyond the cap is closed"
    );
    // The idle ones are cut after the timeout; then the server answers again.
    let start = Instant::now();
    for s in &mut idle {
        assert!(
            closed_within(s, Duration::from_secs(5)),
            "an idle connection is cut"
        );
    }
    assert!(start.elapsed() < Duration::from_secs(5));
    std::thread::sleep(Duration::from_millis(100));
    still_answers(&mut server);
}

#[test]
fn pipelined_requests_are_answered_in_order_and_garbage_ends_only_its_connection() {
    let mut server = Server::start(&[]);
    let mut c = http::Client::connect(server.addr).unwrap();
    let one = format!(
        "POST /api/check HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n{GOOD}",
        GOOD.len()
    );
    let list = "GET /api/exercises HTTP/1.1\r\nHost: x\r\n\r\n";
    c.stream()
        .write_all(format!("{one}{list}{one}").as_bytes())
        .unwrap();
    assert_eq!(c.read().unwrap().status, 200);
    assert_eq!(c.read().unwrap().json()[0]["id"], "4.1");
    assert_eq!(c.read().unwrap().json()["verdict"], "wrong");
    // A good request, then garbage: the first is answered, the garbage gets 400 or the close.
    c.stream()
        .write_all(format!("{one}\x00\x01GARBAGE \u{7f} HTTP/9\r\n\r\n\r\n").as_bytes())
        .unwrap();
    assert_eq!(c.read().unwrap().status, 200);
    if let Ok(r) = c.read() {
        assert_eq!(r.status, 400);
    }
    // A Content-Length that lies (shorter than the body): the rest is read as the next request.
    let mut c = http::Client::connect(server.addr).unwrap();
    c.stream()
        .write_all(b"POST /api/check HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 5\r\n\r\n{\"exercise\": \"4.2\"}")
        .unwrap();
    let r = c.read().unwrap();
    assert_eq!(r.status, 400, "{}", r.text());
    still_answers(&mut server);
}
