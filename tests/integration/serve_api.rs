//! `phong serve`'s JSON API, over HTTP: `POST /api/solve` and `POST /api/check` answer what
//! `phong solve --format json` and `phong check --format json` print for the same problem (the
//! CLI is run beside the server and the two outputs compared byte for byte, the `file` name
//! apart), errors are 4xx with the CLI's message, and `--log-answers` keeps one line per check.

#![cfg(feature = "serve")]

use crate::support;
use crate::support::http;
use crate::support::server;

use std::path::Path;

use serde_json::Value;

use server::Server;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The text of a bundled exercise.
fn exercise(id: &str) -> String {
    std::fs::read_to_string(root().join(format!("exercises/{id}.json"))).expect("an exercise")
}

/// What `phong ARGS…` prints, run from the crate's folder (so that the file is named
/// `exercises/4.2.json`, as the server names its bundled exercises).
fn cli(args: &[&str]) -> String {
    let out = support::phong()
        .current_dir(root())
        .args(args)
        .output()
        .expect("phong runs");
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// `{"problem": TEXT, …rest}`: the problem file's text sent as it is, so that the line numbers
/// of its errors are the file's.
fn with_problem(text: &str, rest: &str) -> String {
    if rest.is_empty() {
        format!("{{\"problem\": {text}}}")
    } else {
        format!("{{\"problem\": {text}, {rest}}}")
    }
}

/// The CLI's output for `exercises/ID.json` as it names a problem sent with a request.
fn as_sent(cli_out: &str, id: &str) -> String {
    cli_out.replacen(
        &format!("\"file\": \"exercises/{id}.json\""),
        "\"file\": \"problem\"",
        1,
    )
}

#[test]
fn solve_answers_what_the_cli_prints_for_every_bundled_exercise() {
    let server = Server::start(&[]);
    for id in ["4.1", "4.2", "4.3"] {
        let file = format!("exercises/{id}.json");
        for precision in ["f64", "f32"] {
            let expected = cli(&["solve", &file, "--format", "json", "--precision", precision]);
            assert!(expected.contains("\"format_version\""), "{expected}");
            // The problem sent with the request.
            let sent = http::post_json(
                server.addr,
                "/api/solve",
                &with_problem(&exercise(id), &format!("\"precision\": \"{precision}\"")),
            );
            assert_eq!(sent.status, 200, "{}", sent.text());
            assert_eq!(sent.text(), as_sent(&expected, id), "{id} {precision}");
            // The server's own exercise: byte for byte, its name included.
            let named = http::post_json(
                server.addr,
                "/api/solve",
                &format!(
                    "{{\"exercise\": \"{id}\", \"precision\": \"{precision}\", \"lang\": \"pt\"}}"
                ),
            );
            assert_eq!(named.status, 200);
            assert_eq!(named.text(), expected, "{id} {precision}");
        }
    }
}

#[test]
fn checking_the_flipped_normal_slip_of_4_2_answers_what_the_cli_prints() {
    let server = Server::start(&[]);
    let answer = "0.245 0.28 0.21";
    let expected = cli(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        answer,
        "--format",
        "json",
    ]);
    let r = http::post_json(
        server.addr,
        "/api/check",
        &with_problem(&exercise("4.2"), &format!("\"answer\": \"{answer}\"")),
    );
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.text(), as_sent(&expected, "4.2"));
    // By hand: the light at (1, 1, 1) is behind the surface at P(3, 1, 3) (N·(light − P) =
    // 0.6·(−2) + 0.8·(−2) < 0), so the key is black. With the normal reversed, cos θ = 1.4/√2 and
    // the linear falloff is 1/|P − light| = 1/(2√2): the diffuse term is k_d·0.35, and the
    // specular term is 0 (R·V < 0), which is the answer given.
    let doc = r.json();
    assert_eq!(doc["verdict"], "wrong");
    assert_eq!(doc["accepted"], false);
    assert_eq!(doc["expected"]["color"], serde_json::json!([0.0, 0.0, 0.0]));
    assert_eq!(doc["reading"]["code"], "normal_reversed");
    let flipped = doc["diagnosis"]
        .as_array()
        .and_then(|d| {
            d.iter()
                .find(|s| s["slips"] == serde_json::json!(["normal_reversed"]))
        })
        .expect("the reversed normal is among the slips");
    let by_hand = [0.7 * 0.35, 0.8 * 0.35, 0.6 * 0.35];
    for (c, h) in flipped["color"]
        .as_array()
        .expect("a colour")
        .iter()
        .zip(by_hand)
    {
        assert!(
            (c.as_f64().expect("a number") - h).abs() < 1e-12,
            "{c} vs {h}"
        );
    }
    // The same, named as the server's exercise: the CLI's bytes exactly.
    let named = http::post_json(
        server.addr,
        "/api/check",
        &format!("{{\"exercise\": \"4.2\", \"answer\": \"{answer}\"}}"),
    );
    assert_eq!(named.status, 200);
    assert_eq!(named.text(), expected);
}

#[test]
fn steps_are_merged_into_the_check_as_the_cli_merges_them() {
    let server = Server::start(&[]);
    let answer = "0.245 0.28 0.21";
    // With an answer: the verdict with the steps under "steps".
    let expected = cli(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        answer,
        "--step",
        "cos_theta=0.98995",
        "--format",
        "json",
    ]);
    let r = http::post_json(
        server.addr,
        "/api/check",
        &with_problem(
            &exercise("4.2"),
            &format!("\"answer\": \"{answer}\", \"steps\": {{\"cos_theta\": \"0.98995\"}}"),
        ),
    );
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.text(), as_sent(&expected, "4.2"));
    // cos θ = −N·L = −(0.6·0.7071 + 0.8·0.7071) = −0.98995 as written: the positive value given
    // is the sign of a reading.
    let doc = r.json();
    assert_eq!(doc["steps"]["steps"][0]["verdict"], "reading");
    assert!(
        (doc["steps"]["steps"][0]["expected"].as_f64().unwrap() + 1.4 / 2f64.sqrt()).abs() < 1e-9
    );
    // Steps alone: the steps' own document.
    let expected = cli(&[
        "check",
        "exercises/4.2.json",
        "--step",
        "cos_theta=-0.98995",
        "--format",
        "json",
    ]);
    let r = http::post_json(
        server.addr,
        "/api/check",
        "{\"exercise\": \"4.2\", \"steps\": {\"cos_theta\": -0.98995}}",
    );
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.text(), expected);
    assert_eq!(r.json()["verdict"], "right");
}

#[test]
fn the_key_is_checked_when_no_answer_is_given() {
    let server = Server::start(&[]);
    let r = http::post_json(server.addr, "/api/check", "{\"exercise\": \"4.2\"}");
    assert_eq!(r.status, 200);
    assert_eq!(
        r.text(),
        cli(&["check", "exercises/4.2.json", "--format", "json"])
    );
    assert_eq!(r.json()["verdict"], "right");
    // "no hit" and the 255 scale, as the CLI reads them.
    let r = http::post_json(
        server.addr,
        "/api/check",
        "{\"exercise\": \"4.2\", \"answer\": \"0 0 0\", \"scale\": 255}",
    );
    assert_eq!(
        r.text(),
        cli(&[
            "check",
            "exercises/4.2.json",
            "--answer",
            "0 0 0",
            "--scale",
            "255",
            "--format",
            "json"
        ])
    );
}

#[test]
fn an_answer_that_cannot_be_read_is_a_422_with_the_cli_message_in_either_language() {
    let server = Server::start(&[]);
    let expected = cli(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        "0.2x",
        "--format",
        "json",
    ]);
    let r = http::post_json(
        server.addr,
        "/api/check",
        "{\"exercise\": \"4.2\", \"answer\": \"0.2x\"}",
    );
    assert_eq!(r.status, 422);
    assert_eq!(r.text(), expected);
    let doc = r.json();
    assert_eq!(doc["error"]["kind"], "answer");
    assert_eq!(doc["error"]["field"], "--answer");
    // In Portuguese: the sentence the CLI prints with --lang pt.
    let pt = http::post_json(
        server.addr,
        "/api/check",
        "{\"exercise\": \"4.2\", \"answer\": \"0.2x\", \"lang\": \"pt\"}",
    );
    assert_eq!(pt.status, 422);
    let message = pt.json()["error"]["message"].as_str().unwrap().to_owned();
    assert!(message.contains("não são três números"), "{message}");
    let stderr = support::phong()
        .current_dir(root())
        .args([
            "check",
            "exercises/4.2.json",
            "--answer",
            "0.2x",
            "--lang",
            "pt",
        ])
        .output()
        .unwrap()
        .stderr;
    let stderr = String::from_utf8(stderr).unwrap();
    assert_eq!(stderr.trim_end(), format!("erro: {message}"));
}

#[test]
fn a_problem_with_a_syntax_error_names_the_cli_field_line_and_column() {
    let server = Server::start(&[]);
    // An error on line 3 of the file; sent as it is, the problem's text has the file's lines.
    let text = "{\n  \"lights\": [],\n  \"viewer\": [1, 2],\n  \"point\": {}\n}";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.json");
    std::fs::write(&path, text).unwrap();
    let out = support::phong()
        .args(["solve", path.to_str().unwrap(), "--format", "json"])
        .output()
        .unwrap();
    let expected: Value = serde_json::from_slice(&out.stdout).unwrap();
    let r = http::post_json(server.addr, "/api/solve", &with_problem(text, ""));
    assert_eq!(r.status, 422, "{}", r.text());
    let doc = r.json();
    assert_eq!(doc["error"]["kind"], expected["error"]["kind"]);
    assert_eq!(doc["error"]["field"], "viewer");
    assert_eq!(doc["error"]["field"], expected["error"]["field"]);
    let cli_message = expected["error"]["message"].as_str().unwrap();
    assert_eq!(
        doc["error"]["message"].as_str().unwrap(),
        cli_message.replacen(path.to_str().unwrap(), "problem", 1)
    );
    assert!(cli_message.contains(":3:"), "{cli_message}");
}

#[test]
fn a_problem_larger_than_the_limits_is_a_422_naming_the_field_and_the_limit() {
    let server = Server::start(&[]);
    let mut doc: Value = serde_json::from_str(&exercise("4.2")).unwrap();
    let light = doc["lights"][0].clone();
    doc["lights"] = Value::Array(vec![light; 17]);
    let text = doc.to_string();
    let r = http::post_json(
        server.addr,
        "/api/check",
        &with_problem(&text, "\"answer\": \"0 0 0\""),
    );
    assert_eq!(r.status, 422, "{}", r.text());
    let doc = r.json();
    assert_eq!(doc["error"]["field"], "lights");
    assert_eq!(doc["error"]["kind"], "invalid");
    let m = doc["error"]["message"].as_str().unwrap();
    assert!(m.contains("17 lights are more than the 16"), "{m}");
}

#[test]
fn a_mesh_is_refused_without_reading_a_file() {
    let server = Server::start(&[]);
    for file in ["torus.obj", "/etc/passwd", "../../../etc/passwd"] {
        let problem = format!(
            "{{\"lights\": [{{\"type\": \"point\", \"position\": [1, 1, 1], \"color\": [1, 1, 1]}}], \
             \"materials\": {{\"M\": {{\"diffuse\": [1, 1, 1]}}}}, \
             \"surfaces\": [{{\"type\": \"mesh\", \"file\": \"{file}\", \"material\": \"M\"}}], \
             \"camera\": {{\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 60, \"width\": 4, \"height\": 4}}}}"
        );
        let r = http::post_json(server.addr, "/api/solve", &with_problem(&problem, ""));
        assert_eq!(r.status, 422, "{}", r.text());
        let doc = r.json();
        assert_eq!(doc["error"]["field"], "surfaces[0].file", "{doc}");
        let m = doc["error"]["message"].as_str().unwrap();
        assert!(m.contains("cannot name a mesh file"), "{m}");
        assert!(!m.contains("root:"), "{m}");
    }
}

#[test]
fn the_exercises_are_listed_with_their_titles() {
    let server = Server::start(&[]);
    let r = http::once(server.addr, "GET", "/api/exercises", None, b"");
    assert_eq!(r.status, 200);
    let doc = r.json();
    let ids: Vec<&str> = doc
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["id"].as_str().unwrap())
        .collect();
    assert_eq!(ids, ["4.1", "4.2", "4.3"]);
    assert_eq!(doc[1]["title_pt"], "Exercício 4.2");
    let r = http::post_json(server.addr, "/api/check", "{\"exercise\": \"9.9\"}");
    assert_eq!(r.status, 404);
    assert!(r.json()["error"]["message"]
        .as_str()
        .unwrap()
        .contains("4.1, 4.2, 4.3"));
}

#[test]
fn an_instructors_folder_replaces_the_bundled_exercises() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("week3.json"), exercise("4.2")).unwrap();
    let server = Server::start(&["--exercises", dir.path().to_str().unwrap()]);
    let r = http::once(server.addr, "GET", "/api/exercises", None, b"");
    assert_eq!(r.json()[0]["id"], "week3");
    assert_eq!(r.json().as_array().unwrap().len(), 1);
    let r = http::post_json(
        server.addr,
        "/api/check",
        "{\"exercise\": \"week3\", \"answer\": \"0 0 0\"}",
    );
    assert_eq!(r.json()["verdict"], "right");
}

#[test]
fn log_answers_appends_one_line_per_check_from_concurrent_requests() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("answers.jsonl");
    let server = Server::start(&["--log-answers", log.to_str().unwrap()]);
    let addr = server.addr;
    let threads: Vec<_> = (0..8)
        .map(|i| {
            std::thread::spawn(move || {
                let mut c = http::Client::connect(addr).unwrap();
                for _ in 0..10 {
                    let body = if i % 2 == 0 {
                        "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\"}".to_owned()
                    } else {
                        with_problem(&exercise("4.2"), "\"answer\": \"0 0 0\"")
                    };
                    assert_eq!(c.post_json("/api/check", &body).unwrap().status, 200);
                }
            })
        })
        .collect();
    for t in threads {
        t.join().unwrap();
    }
    // A solve is not a checked answer.
    http::post_json(addr, "/api/solve", "{\"exercise\": \"4.2\"}");
    let text = std::fs::read_to_string(&log).unwrap();
    let lines: Vec<Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).expect("each line is JSON"))
        .collect();
    assert_eq!(lines.len(), 80);
    let by_id = lines.iter().filter(|l| l["exercise"] == "4.2").count();
    assert_eq!(by_id, 40);
    assert!(lines
        .iter()
        .filter(|l| l["exercise"] == "4.2")
        .all(|l| l["verdict"] == "wrong" && l["answer"] == "0.245 0.28 0.21"));
    // A problem sent is kept as its hash, never its text.
    let sent: Vec<&Value> = lines
        .iter()
        .filter(|l| l.get("problem").is_some())
        .collect();
    assert_eq!(sent.len(), 40);
    assert!(sent
        .iter()
        .all(|l| l["problem"].as_str().unwrap().len() == 16 && l["verdict"] == "right"));
    assert!(!text.contains("materials"));
}

#[cfg(unix)]
#[test]
fn sigterm_stops_accepting_lets_the_request_in_flight_finish_and_exits_0() {
    use std::io::Write;
    let mut server = Server::start(&["--timeout", "3"]);
    let addr = server.addr;
    let body = "{\"exercise\": \"4.2\", \"answer\": \"0 0 0\"}";
    // A request whose body is still arriving when the signal comes.
    let mut busy = http::Client::connect(addr).unwrap();
    busy.stream()
        .write_all(
            format!(
                "POST /api/check HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n\
                 Content-Length: {}\r\n\r\n{}",
                body.len(),
                &body[..10]
            )
            .as_bytes(),
        )
        .unwrap();
    // An idle keep-alive connection.
    let mut idle = http::Client::connect(addr).unwrap();
    assert_eq!(idle.post_json("/api/check", body).unwrap().status, 200);
    let killed = std::process::Command::new("kill")
        .args(["-TERM", &server.pid().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    std::thread::sleep(std::time::Duration::from_millis(300));
    // Still running: a request is in flight. The idle connection is closed, and no new one is
    // accepted.
    assert!(server.alive());
    assert!(idle.post_json("/api/check", body).is_err());
    assert!(http::Client::connect(addr)
        .and_then(|mut c| c.post_json("/api/check", body))
        .is_err());
    // The request in flight is answered, then the server exits 0.
    busy.stream().write_all(&body.as_bytes()[10..]).unwrap();
    let r = busy.read().unwrap();
    assert_eq!(r.status, 200);
    assert_eq!(r.json()["verdict"], "right");
    let status = server
        .exited_within(std::time::Duration::from_secs(2))
        .expect("the server exits once the request is answered");
    assert!(status.success(), "{status:?}");
}

#[test]
fn the_request_log_has_one_line_per_request_and_no_answer() {
    let server = Server::start(&[]);
    let secret = "0.123456 0.654321 0.111111";
    let r = http::post_json(
        server.addr,
        "/api/check",
        &format!("{{\"exercise\": \"4.2\", \"answer\": \"{secret}\"}}"),
    );
    assert_eq!(r.status, 200);
    let r = http::once(
        server.addr,
        "GET",
        "/nope?answer=0.5%200.5%200.5",
        None,
        b"",
    );
    assert_eq!(r.status, 404);
    // The lines arrive through a pipe: wait for both.
    let start = std::time::Instant::now();
    let mut log = server.log();
    while log.len() < 2 && start.elapsed() < std::time::Duration::from_secs(5) {
        std::thread::sleep(std::time::Duration::from_millis(20));
        log = server.log();
    }
    assert_eq!(log.len(), 2, "{log:?}");
    assert!(
        log[0].starts_with("POST /api/check 200 ") && log[0].ends_with("µs"),
        "{log:?}"
    );
    assert!(log[1].starts_with("GET /nope 404 "), "{log:?}");
    let all = log.join("\n");
    assert!(
        !all.contains("0.123456") && !all.contains("answer"),
        "{all}"
    );
}

/// 64-bit FNV-1a of `bytes` (offset basis 0xcbf29ce484222325, prime 0x100000001b3), as the
/// README documents the log's hashes: written here from the algorithm, not from phong.
fn fnv1a(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// Issue 30, item 6: a line of the answers' log keeps at most the answer's first 64 characters,
/// with its length in bytes and its hash (a 60,000-character answer added 60 kB a line).
#[test]
fn the_answers_log_keeps_a_prefix_the_length_and_the_hash_of_an_answer() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("answers.jsonl");
    let server = Server::start(&["--log-answers", log.to_str().unwrap()]);
    // 3 × 20,000 characters, "é" two bytes each: 80,000 bytes would pass the 64 kB body
    // limit, so 9,000 of each: 27,000 characters, 36,000 bytes.
    let answer = format!(
        "{} {} {}",
        "1".repeat(9000),
        "é".repeat(9000),
        "0".repeat(8998)
    );
    assert_eq!(answer.chars().count(), 27_000);
    assert_eq!(answer.len(), 9000 + 1 + 18_000 + 1 + 8998);
    let body = format!("{{\"exercise\": \"4.2\", \"answer\": \"{answer}\"}}");
    // Not an answer phong can read (422), logged all the same.
    assert_eq!(
        http::post_json(server.addr, "/api/check", &body).status,
        422
    );
    let short = "{\"exercise\": \"4.2\", \"answer\": \"0.245 0.28 0.21\"}";
    assert_eq!(
        http::post_json(server.addr, "/api/check", short).status,
        200
    );
    let text = std::fs::read_to_string(&log).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(lines[0].len() < 400, "a line of {} bytes", lines[0].len());
    let long: Value = serde_json::from_str(lines[0]).unwrap();
    assert_eq!(long["answer"], "1".repeat(64));
    assert_eq!(long["answer_bytes"], 36_000);
    assert_eq!(long["answer_hash"], fnv1a(answer.as_bytes()));
    let short: Value = serde_json::from_str(lines[1]).unwrap();
    assert_eq!(short["answer"], "0.245 0.28 0.21");
    assert_eq!(short["answer_bytes"], 15);
    assert_eq!(short["answer_hash"], fnv1a(b"0.245 0.28 0.21"));
}

/// Issue 30, item 6: `--log-answers-max KB` bounds the log: before a line would make it larger,
/// it becomes `PATH.1` and a new file is begun; every line of both is whole.
#[test]
fn the_answers_log_is_rotated_before_it_passes_its_limit() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("answers.jsonl");
    let older = dir.path().join("answers.jsonl.1");
    let server = Server::start(&[
        "--log-answers",
        log.to_str().unwrap(),
        "--log-answers-max",
        "2",
    ]);
    let mut c = http::Client::connect(server.addr).unwrap();
    // A long answer each time (its line about 200 bytes): 100 lines are about 20 kB, ten
    // times the limit of 2 kB.
    for i in 0..100 {
        let body = format!(
            "{{\"exercise\": \"4.2\", \"answer\": \"{i} {}\"}}",
            "9".repeat(5000)
        );
        assert_eq!(c.post_json("/api/check", &body).unwrap().status, 422);
    }
    for file in [&log, &older] {
        let text = std::fs::read_to_string(file).unwrap();
        assert!(
            text.len() <= 2000,
            "{}: {} bytes",
            file.display(),
            text.len()
        );
        assert!(text.ends_with('\n'));
        for line in text.lines() {
            let v: Value = serde_json::from_str(line).expect("each line is JSON");
            assert_eq!(
                v["answer_bytes"].as_u64().unwrap() as usize,
                line_answer_len(&v)
            );
        }
    }
    // The newest answer is the last line of the log.
    let text = std::fs::read_to_string(&log).unwrap();
    let last: Value = serde_json::from_str(text.lines().last().unwrap()).unwrap();
    assert!(
        last["answer"].as_str().unwrap().starts_with("99 999"),
        "{last}"
    );
}

/// The length of the answer a line of the rotation test stands for: "I " and 5,000 nines.
fn line_answer_len(v: &Value) -> usize {
    let prefix = v["answer"].as_str().unwrap();
    let number = prefix.split(' ').next().unwrap();
    number.len() + 1 + 5000
}
