//! `phong serve` as people use it: Debian's `chromium`, headless, driven through WebDriver
//! (Debian's `chromium-driver`, `chromedriver`), opens exercise 4.2 in Portuguese, types
//! "0.245 0.28 0.21" into the answer box, presses the button, and the verdict names the normal
//! slip in `phong check --lang pt`'s words; then the same for a step (cos θ). No JavaScript of
//! the page is involved: there is none; the browser only fills and submits the form.
//!
//! With `PHONG_UPDATE_SCREENSHOT=1` the verdict's screenshot is written to `docs/serve-4.2.png`
//! (the README shows it); otherwise the screenshot is only checked not to be blank.
//!
//! The WebDriver protocol is plain JSON over HTTP, so it is spoken here with `std::net` and
//! `serde_json` (a client crate would bring a second HTTP stack into the tests for six calls).
//! `.ci/run` installs chromium and chromium-driver; under `CI=true` a missing one fails.

// `phong serve` exists only with the `serve` feature (on by default).
#![cfg(feature = "serve")]

use crate::support;
use crate::support::screenshot;
// Shared with the other tests of phong serve; not every test uses every helper.
#[allow(dead_code)]
use crate::support::server;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::{json, Value};
use server::Server;

const INSTALL: &str = "apt-get install -y --no-install-recommends chromium chromium-driver";

/// A `chromedriver` process on a free loopback port, killed when dropped.
struct Driver {
    child: Child,
    addr: SocketAddr,
}

impl Driver {
    fn start(program: &Path) -> Driver {
        let port = TcpListener::bind("127.0.0.1:0")
            .unwrap()
            .local_addr()
            .unwrap()
            .port();
        let mut child = Command::new(program)
            .arg(format!("--port={port}"))
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("chromedriver starts");
        // Its standard output is drained so that it never blocks on a full pipe.
        let out = child.stdout.take().unwrap();
        std::thread::spawn(move || for _ in BufReader::new(out).lines() {});
        let addr = SocketAddr::from(([127, 0, 0, 1], port));
        let deadline = Instant::now() + Duration::from_secs(30);
        while TcpStream::connect(addr).is_err() {
            assert!(Instant::now() < deadline, "chromedriver did not listen");
            std::thread::sleep(Duration::from_millis(100));
        }
        Driver { child, addr }
    }

    /// One WebDriver command: its `value`, or a panic with the driver's error.
    fn call(&self, method: &str, path: &str, body: Option<Value>) -> Value {
        let body = body.map(|b| b.to_string()).unwrap_or_default();
        let mut s = TcpStream::connect(self.addr).unwrap();
        s.set_read_timeout(Some(Duration::from_secs(120))).unwrap();
        let request = format!(
            "{method} {path} HTTP/1.1\r\nHost: {}\r\nConnection: close\r\n\
             Content-Type: application/json; charset=utf-8\r\nContent-Length: {}\r\n\r\n{body}",
            self.addr,
            body.len()
        );
        s.write_all(request.as_bytes()).unwrap();
        let rest = read_reply(&mut s);
        let v: Value = serde_json::from_str(&rest)
            .unwrap_or_else(|e| panic!("{method} {path}: not JSON ({e}): {rest}"));
        let value = v["value"].clone();
        assert!(
            value.get("error").is_none(),
            "{method} {path}: {}",
            value["message"]
        );
        value
    }
}

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A reply's body: chromedriver keeps the connection open after it (whatever the request's
/// `Connection: close`), so it is read by its `Content-Length`, or its chunks.
fn read_reply(s: &mut TcpStream) -> String {
    let mut raw = Vec::new();
    let mut buf = [0u8; 8192];
    let head_end = loop {
        if let Some(at) = raw.windows(4).position(|w| w == b"\r\n\r\n") {
            break at + 4;
        }
        let n = s.read(&mut buf).unwrap();
        assert!(n > 0, "chromedriver closed the connection before its reply");
        raw.extend_from_slice(&buf[..n]);
    };
    let head = String::from_utf8_lossy(&raw[..head_end]).to_ascii_lowercase();
    let length = head
        .lines()
        .find_map(|l| l.strip_prefix("content-length:"))
        .and_then(|v| v.trim().parse::<usize>().ok());
    let chunked = head.contains("transfer-encoding: chunked");
    loop {
        let body = &raw[head_end..];
        let done = match length {
            Some(n) => body.len() >= n,
            None if chunked => body.windows(5).any(|w| w == b"0\r\n\r\n"),
            None => false,
        };
        if done {
            break;
        }
        let n = s.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        raw.extend_from_slice(&buf[..n]);
    }
    let body = String::from_utf8(raw[head_end..].to_vec()).unwrap();
    match length {
        Some(n) => body[..n.min(body.len())].to_owned(),
        None if chunked => dechunk(&body),
        None => body,
    }
}

fn dechunk(mut s: &str) -> String {
    let mut out = String::new();
    while let Some((size, rest)) = s.split_once("\r\n") {
        let n = usize::from_str_radix(size.trim(), 16).unwrap_or(0);
        if n == 0 {
            break;
        }
        out.push_str(&rest[..n]);
        s = &rest[n + 2..];
    }
    out
}

/// A browser session on `driver`, closed when dropped.
struct Session<'a> {
    driver: &'a Driver,
    id: String,
}

impl<'a> Session<'a> {
    fn new(driver: &'a Driver, browser: &Path, profile: &Path) -> Session<'a> {
        let caps = json!({
            "capabilities": { "alwaysMatch": {
                "browserName": "chrome",
                "goog:chromeOptions": {
                    "binary": browser,
                    "args": [
                        "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                        "--no-first-run", "--disable-background-networking",
                        "--disable-component-update", "--disable-sync", "--hide-scrollbars",
                        "--lang=pt-BR", "--window-size=1000,1400",
                        format!("--user-data-dir={}", profile.display()),
                    ],
                    "prefs": { "intl.accept_languages": "pt-BR,pt" }
                }
            }}
        });
        let v = driver.call("POST", "/session", Some(caps));
        Session {
            driver,
            id: v["sessionId"].as_str().expect("a session id").to_owned(),
        }
    }

    fn call(&self, method: &str, path: &str, body: Option<Value>) -> Value {
        self.driver
            .call(method, &format!("/session/{}{path}", self.id), body)
    }

    fn go(&self, url: &str) {
        self.call("POST", "/url", Some(json!({ "url": url })));
    }

    /// The element `css` selects.
    fn find(&self, css: &str) -> String {
        let v = self.call(
            "POST",
            "/element",
            Some(json!({ "using": "css selector", "value": css })),
        );
        v.as_object()
            .and_then(|o| o.values().next())
            .and_then(Value::as_str)
            .unwrap_or_else(|| panic!("no {css}"))
            .to_owned()
    }

    /// Waits (at most 60 s) until `css` selects something: the page a click submitted has
    /// loaded (the old page may still be there when the click returns).
    fn wait_for(&self, css: &str) {
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            let found = self.call(
                "POST",
                "/elements",
                Some(json!({ "using": "css selector", "value": css })),
            );
            if found.as_array().is_some_and(|a| !a.is_empty()) {
                return;
            }
            assert!(Instant::now() < deadline, "{css} never appeared");
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    /// How many elements `css` selects.
    fn count(&self, css: &str) -> usize {
        self.call(
            "POST",
            "/elements",
            Some(json!({ "using": "css selector", "value": css })),
        )
        .as_array()
        .map_or(0, Vec::len)
    }

    fn type_into(&self, css: &str, text: &str) {
        let e = self.find(css);
        self.call("POST", &format!("/element/{e}/clear"), Some(json!({})));
        self.call(
            "POST",
            &format!("/element/{e}/value"),
            Some(json!({ "text": text })),
        );
    }

    fn click(&self, css: &str) {
        let e = self.find(css);
        self.call("POST", &format!("/element/{e}/click"), Some(json!({})));
    }

    fn text(&self, css: &str) -> String {
        let e = self.find(css);
        self.call("GET", &format!("/element/{e}/text"), None)
            .as_str()
            .unwrap_or_default()
            .to_owned()
    }

    fn url(&self) -> String {
        self.call("GET", "/url", None)
            .as_str()
            .unwrap_or_default()
            .to_owned()
    }

    fn screenshot(&self) -> Vec<u8> {
        let b64 = self.call("GET", "/screenshot", None);
        base64(b64.as_str().expect("a screenshot"))
    }
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            self.driver
                .call("DELETE", &format!("/session/{}", self.id), None)
        }));
    }
}

/// Standard base64 (the screenshot's PNG).
fn base64(s: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => Some(c - b'A'),
        b'a'..=b'z' => Some(c - b'a' + 26),
        b'0'..=b'9' => Some(c - b'0' + 52),
        b'+' => Some(62),
        b'/' => Some(63),
        _ => None,
    };
    let mut out = Vec::with_capacity(s.len() * 3 / 4);
    let (mut acc, mut bits) = (0u32, 0);
    for v in s.bytes().filter_map(value) {
        acc = (acc << 6) | u32::from(v);
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
        }
    }
    out
}

/// The share of pixels that are white, in a PNG.
fn white_share(png_bytes: &[u8]) -> f64 {
    let (white, total) = screenshot::pixels_of(png_bytes, [255, 255, 255]);
    white as f64 / total as f64
}

/// `phong check ARGS…`'s standard output.
fn check(args: &[&str]) -> String {
    let out = support::phong().arg("check").args(args).output().unwrap();
    String::from_utf8(out.stdout).unwrap()
}

#[test]
#[ignore = "needs chromium and chromedriver: apt-get install chromium chromium-driver fonts-dejavu-core (.ci/run does)"]
fn a_browser_fills_the_4_2_form_and_reads_the_slip_and_a_step() {
    let Some(browser) = support::require("chromium", INSTALL) else {
        return;
    };
    let Some(driver) = support::require("chromedriver", INSTALL) else {
        return;
    };
    let server = Server::start(&[]);
    let driver = Driver::start(&driver);
    let profile = tempfile::tempdir().unwrap();
    let s = Session::new(&driver, &browser, profile.path());

    // The list, in Portuguese from the browser's Accept-Language; the link to 4.2.
    s.go(&server.url("/"));
    s.click("a[href^=\"/exercise/4.2\"]");
    s.wait_for("form.answer");
    assert!(s.url().contains("/exercise/4.2?lang=pt"), "{}", s.url());
    assert_eq!(s.text("h1"), "Exercício 4.2");

    // The answer, typed and submitted with the button.
    s.type_into("#answer", "0.245 0.28 0.21");
    s.click("form.answer button[type=submit]");
    s.wait_for("#verdict .verdict");
    let verdict = s.text("#verdict");
    let cli = check(&[
        "exercises/4.2.json",
        "--answer",
        "0.245 0.28 0.21",
        "--lang",
        "pt",
    ]);
    let slip = cli
        .lines()
        .find(|l| l.trim_start().starts_with("- "))
        .expect("phong check names a slip");
    let slip = slip.trim_start().trim_start_matches("- ");
    let slip = &slip[..slip.find(':').unwrap()];
    assert!(slip.contains("normal"), "{slip}");
    assert!(
        verdict.contains(slip),
        "the verdict lacks {slip:?}:\n{verdict}"
    );
    assert!(
        verdict.contains("Errada") || verdict.contains("errad"),
        "{verdict}"
    );
    // Issue 33: the verdict is a page, not terminal text: the answer's and the expected colour
    // as swatches (each an image with a text alternative), the channels in a table, each slip
    // linked to its step of the worked solution; no <pre>.
    assert_eq!(
        s.count("#verdict .colours svg[role=\"img\"][aria-label]"),
        2
    );
    assert_eq!(s.count("#verdict table.channels tr"), 4);
    assert!(s.count("#verdict ul.matches a[href*=\"#part-0-0-eq-4-7\"]") >= 1);
    assert_eq!(s.count("#verdict pre"), 0);
    let shot = s.screenshot();
    if std::env::var("PHONG_UPDATE_SCREENSHOT").is_ok_and(|v| v == "1") {
        std::fs::write("docs/serve-4.2.png", &shot).unwrap();
    }
    assert!(white_share(&shot) < 0.97, "the screenshot is blank");

    // A step: the box is in the closed "steps" section, opened by a click on its summary.
    s.type_into("#answer", "");
    s.click("details.steps summary");
    s.type_into("form.answer input[name=\"step:cos_theta\"]", "0,98995");
    s.click("form.answer button[type=submit]");
    s.wait_for("#verdict table.judged");
    let steps = s.text("#verdict table.judged");
    let cli = check(&[
        "exercises/4.2.json",
        "--step",
        "cos_theta=0.98995",
        "--lang",
        "pt",
    ]);
    let line = cli.lines().nth(1).expect("a step line");
    let said = line
        .split("  ")
        .filter(|p| !p.is_empty())
        .last()
        .unwrap()
        .trim();
    assert!(steps.contains(said), "the steps lack {said:?}:\n{steps}");

    // The keyboard alone: Enter in the answer box submits the form (a decimal comma too).
    s.type_into("form.answer input[name=\"step:cos_theta\"]", "");
    s.type_into("#answer", "0,245 0,28 0,21\u{E007}");
    s.wait_for("#verdict .colours");
    assert!(
        s.text("#verdict").contains(slip),
        "Enter did not check the answer"
    );

    // The switch to English keeps the answer: the verdict again, in phong check's English.
    s.click("nav.lang button");
    s.wait_for("html[lang=\"en\"] #verdict .colours");
    let cli = check(&["exercises/4.2.json", "--answer", "0.245 0.28 0.21"]);
    let slip = cli
        .lines()
        .find(|l| l.trim_start().starts_with("- "))
        .expect("phong check names a slip");
    let slip = slip.trim_start().trim_start_matches("- ");
    let slip = &slip[..slip.find(':').unwrap()];
    assert!(s.text("#verdict").contains(slip), "no {slip:?} in English");
}
