//! The pages of `phong serve`, over HTTP as a browser asks for them: status, headers, language
//! (Accept-Language with q-values, `?lang=`), the 4.2 answer form and its verdict (the same
//! slips as `phong check --format json`, the same sentences as `phong check --lang pt`), a step,
//! decimal commas, "no hit", hostile input echoed escaped, one's own problem (solved; bad
//! numbers refused with 422 and the reader's message naming the field; the file downloaded).
//!
//! The numbers are worked out by hand: exercise 4.2 has L = (P − P_l)/‖P − P_l‖ = (2, 0, 2)/√8
//! = (0.70711, 0, 0.70711), N·L = 0.6·0.70711 + 0.8·0.70711 = 0.98995, so cos θ = −N·L =
//! −0.98995 as written (the light is behind the surface, and there is no ambient light: the
//! colour is (0, 0, 0)). With the normal reversed, cos θ = +0.98995 and I_l = 1/d = 1/√8 =
//! 0.35355 (linear falloff), so the diffuse term is O_d·0.35355·0.98995 = O_d·0.35 =
//! (0.245, 0.28, 0.21); R = L − 2(N'·L)N' = (−0.48083, 0, −0.87681) and V = (P − E)/‖P − E‖ =
//! (−2, −3, −3)/√22, so cos φ = −R·V = −0.76585 < 0: no specular. The answer
//! "0.245 0.28 0.21" is the normal-reversed slip.

// `phong serve` exists only with the `serve` feature (on by default).
#![cfg(feature = "serve")]

// Shared with the other tests of phong serve; not every test uses every helper.
use crate::support;
#[allow(dead_code)]
use crate::support::server;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

use server::Server;

/// A response: its status, headers (names in lower case) and body.
struct Reply {
    status: u16,
    headers: Vec<(String, String)>,
    body: String,
}

impl Reply {
    fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

/// One HTTP/1.1 request (`Connection: close`), read to its end.
fn request(
    server: &Server,
    method: &str,
    path: &str,
    headers: &[(&str, &str)],
    body: &str,
) -> Reply {
    let mut stream = TcpStream::connect(server.addr).expect("connects");
    stream
        .set_read_timeout(Some(Duration::from_secs(60)))
        .unwrap();
    let mut head = format!(
        "{method} {path} HTTP/1.1\r\nHost: {}\r\nConnection: close\r\nContent-Length: {}\r\n",
        server.addr,
        body.len()
    );
    for (n, v) in headers {
        head.push_str(&format!("{n}: {v}\r\n"));
    }
    head.push_str("\r\n");
    stream.write_all(head.as_bytes()).unwrap();
    stream.write_all(body.as_bytes()).unwrap();
    let mut raw = Vec::new();
    stream.read_to_end(&mut raw).unwrap();
    let text = String::from_utf8(raw).expect("UTF-8 response");
    let (head, body) = text.split_once("\r\n\r\n").expect("a header block");
    let mut lines = head.split("\r\n");
    let status = lines
        .next()
        .and_then(|l| l.split(' ').nth(1))
        .and_then(|s| s.parse().ok())
        .expect("a status line");
    let headers: Vec<(String, String)> = lines
        .filter_map(|l| l.split_once(':'))
        .map(|(n, v)| (n.trim().to_ascii_lowercase(), v.trim().to_owned()))
        .collect();
    assert!(
        !headers
            .iter()
            .any(|(n, v)| n == "transfer-encoding" && v.contains("chunked")),
        "the pages are sent whole, with a Content-Length"
    );
    Reply {
        status,
        headers,
        body: body.to_owned(),
    }
}

fn get(server: &Server, path: &str, headers: &[(&str, &str)]) -> Reply {
    request(server, "GET", path, headers, "")
}

/// A form, `application/x-www-form-urlencoded`.
fn post(server: &Server, path: &str, fields: &[(&str, &str)], headers: &[(&str, &str)]) -> Reply {
    let body = fields
        .iter()
        .map(|(k, v)| format!("{}={}", encode(k), encode(v)))
        .collect::<Vec<_>>()
        .join("&");
    let mut h = vec![("Content-Type", "application/x-www-form-urlencoded")];
    h.extend_from_slice(headers);
    request(server, "POST", path, &h, &body)
}

/// Percent-encoding of a form value (spaces as `+`).
fn encode(s: &str) -> String {
    let mut out = String::new();
    for b in s.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'*' => {
                out.push(char::from(b))
            }
            b' ' => out.push('+'),
            _ => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

/// The text HTML escaping gives (as the pages escape).
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&#39;")
}

/// The value of attribute `name` on the first element holding `marker`.
fn attr<'a>(html: &'a str, marker: &str, name: &str) -> &'a str {
    let at = html
        .find(marker)
        .unwrap_or_else(|| panic!("no {marker} in:\n{html}"));
    let tag_start = html[..at].rfind('<').unwrap();
    let tag = &html[tag_start..at + html[at..].find('>').unwrap()];
    let key = format!("{name}=\"");
    let v = &tag[tag
        .find(&key)
        .unwrap_or_else(|| panic!("no {name} in {tag}"))
        + key.len()..];
    &v[..v.find('"').unwrap()]
}

/// `phong check ARGS…`'s standard output (exit 0 or 1: a verdict was given).
fn check(args: &[&str]) -> String {
    let out = support::phong().arg("check").args(args).output().unwrap();
    assert!(
        matches!(out.status.code(), Some(0 | 1)),
        "phong check {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

const PT: (&str, &str) = ("Accept-Language", "pt-BR,pt;q=0.9,en;q=0.8");

#[test]
fn every_page_has_strict_headers_and_the_stylesheet_is_a_cached_file() {
    let server = Server::start(&[]);
    for path in [
        "/",
        "/exercise/4.2",
        "/own",
        "/static/phong.css",
        "/nowhere",
    ] {
        let r = get(&server, path, &[]);
        let csp = r.header("content-security-policy").unwrap_or("");
        assert!(
            csp.contains("script-src 'self'") && csp.contains("style-src 'self'"),
            "{path}: {csp}"
        );
        assert!(!csp.contains("unsafe-inline"), "{path}: {csp}");
        assert_eq!(
            r.header("x-content-type-options"),
            Some("nosniff"),
            "{path}"
        );
    }
    for path in [
        "/",
        "/exercise/4.2",
        "/exercise/4.2?solution=1",
        "/exercise/4.3?solution=1",
        "/own",
    ] {
        let r = get(&server, path, &[]);
        assert_eq!(r.status, 200, "{path}");
        assert_eq!(r.header("content-type"), Some("text/html; charset=utf-8"));
        assert_eq!(r.header("cache-control"), Some("no-store"), "{path}");
        // No script, no inline style, nothing fetched from elsewhere.
        for banned in [
            "<script",
            "<style",
            " style=\"",
            "src=\"http",
            "href=\"http",
            "href=\"//",
            "url(http",
            "url(//",
            "@import",
        ] {
            assert!(!r.body.contains(banned), "{path}: holds {banned}");
        }
        assert!(r
            .body
            .contains("<link rel=\"stylesheet\" href=\"/static/phong.css"));
    }
    let page = get(&server, "/", &[]).body;
    let at = page.find("href=\"/static/phong.css?v=").unwrap() + 6;
    let url = &page[at..at + page[at..].find('"').unwrap()];
    assert_eq!(url.len(), "/static/phong.css?v=".len() + 16, "{url}");
    let css = get(&server, url, &[]);
    assert_eq!(css.status, 200);
    assert_eq!(css.header("content-type"), Some("text/css; charset=utf-8"));
    assert!(css
        .header("cache-control")
        .unwrap()
        .contains("max-age=31536000"));
    assert!(css.body.contains(".verdict") && css.body.contains(".sw{"));
    assert_eq!(get(&server, "/exercise/9.9", &[]).status, 404);
}

#[test]
fn the_language_follows_accept_language_and_the_switch() {
    let server = Server::start(&[]);
    let en = get(&server, "/", &[]);
    assert!(en.body.contains("<html lang=\"en\">"));
    assert!(en.body.contains("Exercise 4.2"));
    let pt = get(&server, "/", &[PT]);
    assert!(pt.body.contains("<html lang=\"pt-BR\">"));
    assert!(pt.body.contains("Exercício 4.2"));
    assert!(pt.body.contains("href=\"/exercise/4.2?lang=pt\""));
    assert_eq!(pt.header("content-language"), Some("pt-BR"));
    // q-values: the higher wins, wherever it is listed; q=0 is a refusal.
    for (value, tag) in [
        ("en;q=0.5, pt;q=0.8", "pt-BR"),
        ("pt;q=0.3, en-GB;q=0.7", "en"),
        ("fr, pt-PT;q=0.9, en;q=0.1", "pt-BR"),
        ("pt;q=0, en", "en"),
        ("de, fr", "en"),
        ("PT-br", "pt-BR"),
    ] {
        let r = get(&server, "/", &[("Accept-Language", value)]);
        assert!(
            r.body.contains(&format!("<html lang=\"{tag}\">")),
            "{value}: not {tag}"
        );
    }
    // The switch: ?lang= beats the header, and every page links to the other language.
    let r = get(&server, "/exercise/4.2?lang=en", &[PT]);
    assert!(r.body.contains("<html lang=\"en\">"));
    assert!(r
        .body
        .contains("href=\"/exercise/4.2?lang=pt\" hreflang=\"pt-BR\""));
    assert!(r.body.contains("action=\"/exercise/4.2?lang=en\""));
    let r = get(&server, "/exercise/4.2?lang=pt", &[]);
    assert!(r.body.contains("<html lang=\"pt-BR\">"));
    assert!(r.body.contains("Enunciado") && r.body.contains("Verificar"));
}

#[test]
fn the_exercise_page_has_labelled_boxes_for_the_steps_it_has() {
    let server = Server::start(&[]);
    let r = get(&server, "/exercise/4.2", &[]);
    let b = &r.body;
    assert!(b.contains("<label for=\"answer\">"));
    assert!(b.contains("role=\"status\""));
    assert!(b.contains("<h1>Exercise 4.2</h1>"));
    // Every input has a label.
    let mut inputs = 0;
    for (at, _) in b.match_indices("<input ") {
        let tag = &b[at..at + b[at..].find('>').unwrap()];
        let id = &tag[tag.find("id=\"").unwrap() + 4..];
        let id = &id[..id.find('"').unwrap()];
        assert!(
            b.contains(&format!("<label for=\"{id}\">")),
            "no label for {id}"
        );
        inputs += 1;
    }
    assert!(inputs > 10, "{inputs} inputs");
    // A point problem with one point light: no t (no ray), no spot; bare names.
    for name in [
        "N",
        "V",
        "L",
        "d",
        "n_dot_l",
        "cos_theta",
        "R",
        "cos_phi",
        "I",
    ] {
        assert!(
            b.contains(&format!("name=\"step:{name}\"")),
            "no box for {name}"
        );
    }
    for name in ["t", "cos_psi", "spot_factor", "cos_theta[0]"] {
        assert!(
            !b.contains(&format!("name=\"step:{name}\"")),
            "a box for {name}"
        );
    }
    // A ray problem: "no hit" is a choice, t a step.
    let r = get(&server, "/exercise/4.3", &[]);
    assert!(r.body.contains("value=\"none\" id=\"kind-none\""));
    assert!(r.body.contains("name=\"step:t\""));
    // Two lights that are not ambient: the per-light names take [i].
    let r = get(&server, "/exercise/4.1", &[]);
    assert_eq!(r.status, 200);
}

#[test]
fn the_4_2_answer_names_the_normal_slip_as_phong_check_does() {
    let server = Server::start(&[]);
    let answer = "0.245 0.28 0.21";
    let r = post(&server, "/exercise/4.2?lang=pt", &[("answer", answer)], &[]);
    assert_eq!(r.status, 200);
    let b = &r.body;
    assert!(b.contains("<html lang=\"pt-BR\">"));
    // The answer is kept in its box.
    assert!(b.contains(&format!("value=\"{answer}\"")));
    assert_eq!(attr(b, "class=\"verdict ", "data-verdict"), "wrong");
    // The slip codes are phong check's.
    let json: serde_json::Value = serde_json::from_str(&check(&[
        "exercises/4.2.json",
        "--answer",
        answer,
        "--format",
        "json",
    ]))
    .unwrap();
    let doc = if json.is_array() { &json[0] } else { &json };
    let codes: Vec<String> = doc["diagnosis"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            d["slips"]
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s.as_str().unwrap())
                .collect::<Vec<_>>()
                .join("+")
        })
        .collect();
    assert!(codes.iter().any(|c| c == "normal_reversed"), "{codes:?}");
    assert_eq!(attr(b, "class=\"verdict ", "data-slips"), codes.join(" "));
    // Issue 33: the verdict is the fragment `phong check --format html` writes (one layout,
    // both uses), not terminal text in a <pre>: the same verdict block, byte for byte, but for
    // its links, which go to the exercise's page with its solution shown.
    assert!(!b.contains("<pre"), "{b}");
    let page = check(&[
        "exercises/4.2.json",
        "--answer",
        answer,
        "--lang",
        "pt",
        "--format",
        "html",
    ]);
    let block = |html: &str| -> String {
        let start = html.find("<div class=\"verdict ").expect("a verdict");
        let end = start + html[start..].find("</section>").expect("its end");
        html[start..end].to_owned()
    };
    assert_eq!(
        block(b),
        block(&page).replace("href=\"#", "href=\"/exercise/4.2?solution=1&amp;lang=pt#")
    );
    // The slip's sentence is phong check's in Portuguese, linked to its step (Eq. 4.7).
    let text = check(&["exercises/4.2.json", "--answer", answer, "--lang", "pt"]);
    let slip = text
        .lines()
        .find(|l| l.trim_start().starts_with("- "))
        .unwrap();
    let slip = slip.trim_start().trim_start_matches("- ");
    assert!(b.contains(&esc(slip)), "the page lacks {slip:?}");
    assert!(b.contains("#part-0-0-eq-4-7\">"), "{b}");
    assert!(b.contains("normal"), "the slip is not named");
    // A decimal comma reads the same.
    let comma = post(
        &server,
        "/exercise/4.2?lang=pt",
        &[("answer", "0,245 0,28 0,21")],
        &[],
    );
    assert_eq!(
        attr(&comma.body, "class=\"verdict ", "data-slips"),
        codes.join(" ")
    );
    // The switch to English sends the same answer again.
    assert!(b.contains("<form method=\"post\" action=\"/exercise/4.2?lang=en\""));
    assert!(b.contains(&format!(
        "<input type=\"hidden\" name=\"answer\" value=\"{answer}\">"
    )));
    let en = post(&server, "/exercise/4.2?lang=en", &[("answer", answer)], &[]);
    assert!(en.body.contains("<html lang=\"en\">"));
    assert_eq!(
        attr(&en.body, "class=\"verdict ", "data-slips"),
        codes.join(" ")
    );
    // The same request gives the same bytes.
    let again = post(&server, "/exercise/4.2?lang=pt", &[("answer", answer)], &[]);
    assert_eq!(again.body, r.body);
    // The likely intended reading (the light taken the other way, worked out above with the
    // specular term): accepted as that reading, as phong check says.
    let reading = "0.299 0.361 0.318";
    let r = post(&server, "/exercise/4.2", &[("answer", reading)], &[]);
    let cli: serde_json::Value = serde_json::from_str(&check(&[
        "exercises/4.2.json",
        "--answer",
        reading,
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(cli["verdict"], "reading");
    assert_eq!(attr(&r.body, "class=\"verdict ", "data-verdict"), "reading");
    assert!(r.body.contains("class=\"verdict reading\""));
    // In 8 bits: round(255·(0.245, 0.28, 0.21)) = (62, 71, 54), the same slip.
    let r = post(
        &server,
        "/exercise/4.2",
        &[("answer", "62 71 54"), ("scale", "255")],
        &[],
    );
    assert_eq!(attr(&r.body, "class=\"verdict ", "data-verdict"), "wrong");
    assert!(attr(&r.body, "class=\"verdict ", "data-slips").contains("normal_reversed"));
    assert!(r.body.contains("value=\"255\" id=\"scale-255\" checked"));
    // The answer key's colour is right.
    let right = post(&server, "/exercise/4.2", &[("answer", "0 0 0")], &[]);
    assert_eq!(
        attr(&right.body, "class=\"verdict ", "data-verdict"),
        "right"
    );
}

#[test]
fn a_step_is_judged_as_phong_check_judges_it() {
    let server = Server::start(&[]);
    // N·L = 0.98995 (right); cos θ = −N·L = −0.98995 as written; +0.98995 is the sign slip
    // (the likely intended reading, the light taken the other way).
    for (name, value) in [
        ("n_dot_l", "0.98995"),
        ("cos_theta", "-0.98995"),
        ("cos_theta", "0.98995"),
        ("d", "2.8284"),
        ("L", "0.7071 0 0.7071"),
    ] {
        let r = post(
            &server,
            "/exercise/4.2",
            &[("answer", ""), (&format!("step:{name}"), value)],
            &[],
        );
        assert_eq!(r.status, 200, "{name}={value}");
        let cli: serde_json::Value = serde_json::from_str(&check(&[
            "exercises/4.2.json",
            "--step",
            &format!("{name}={value}"),
            "--format",
            "json",
        ]))
        .unwrap();
        let doc = if cli.is_array() { &cli[0] } else { &cli };
        let verdict = doc["steps"]["steps"][0]["verdict"]
            .as_str()
            .or_else(|| doc["steps"][0]["verdict"].as_str())
            .unwrap_or_else(|| panic!("{doc}"));
        // Per-light names are labelled with their light, cos_theta[0].
        let marker = format!("data-step=\"{name}");
        assert_eq!(
            attr(&r.body, &marker, "data-verdict"),
            verdict,
            "{name}={value}"
        );
        // The value is kept in its box, and the steps' section is open.
        assert!(r.body.contains(&format!("value=\"{value}\"")));
        assert!(r.body.contains("<details class=\"steps\" open>"));
    }
    let right = post(&server, "/exercise/4.2", &[("step:n_dot_l", "0.99")], &[]);
    assert_eq!(
        attr(&right.body, "data-step=\"n_dot_l", "data-verdict"),
        "right"
    );
    let wrong = post(&server, "/exercise/4.2", &[("step:d", "8")], &[]);
    assert_eq!(attr(&wrong.body, "data-step=\"d[", "data-verdict"), "wrong");
    // In Portuguese, the sentence of phong check --lang pt.
    let r = post(
        &server,
        "/exercise/4.2?lang=pt",
        &[("step:cos_theta", "0.98995")],
        &[],
    );
    let text = check(&[
        "exercises/4.2.json",
        "--step",
        "cos_theta=0.98995",
        "--lang",
        "pt",
    ]);
    // "  cos_theta[0]   = 0.98995  SENTENCE": the sentence after the value.
    let line = text.lines().nth(1).unwrap();
    let sentence = line.split("  ").filter(|p| !p.is_empty()).last().unwrap();
    assert!(
        sentence.starts_with("errado como enunciado, certo na leitura"),
        "{sentence}"
    );
    assert!(r.body.contains(&esc(sentence)), "no {sentence:?}");
}

#[test]
fn no_hit_is_an_answer_for_a_ray_problem() {
    let server = Server::start(&[]);
    let r = post(
        &server,
        "/exercise/4.3",
        &[("kind", "none"), ("answer", "")],
        &[],
    );
    assert_eq!(r.status, 200);
    let cli: serde_json::Value = serde_json::from_str(&check(&[
        "exercises/4.3.json",
        "--answer",
        "none",
        "--format",
        "json",
    ]))
    .unwrap();
    let doc = if cli.is_array() { &cli[0] } else { &cli };
    assert_eq!(
        attr(&r.body, "class=\"verdict ", "data-verdict"),
        doc["verdict"].as_str().unwrap()
    );
    assert!(r.body.contains("value=\"none\" id=\"kind-none\" checked"));
}

#[test]
fn hostile_input_comes_back_escaped() {
    let server = Server::start(&[]);
    let evil = "<script>alert(1)</script>\"'><img src=x>";
    let r = post(
        &server,
        "/exercise/4.2",
        &[
            ("answer", evil),
            ("step:cos_theta", evil),
            ("step:<b>", "1"),
        ],
        &[],
    );
    assert_eq!(r.status, 422);
    let body = &r.body;
    assert!(!body.contains("<script"), "unescaped:\n{body}");
    assert!(!body.contains("<img"), "unescaped");
    assert!(!body.contains("<b>"), "unescaped");
    assert!(body.contains("&lt;script&gt;"));
    // The reader's message says why, in the page's language.
    assert!(r.body.contains("class=\"verdict invalid\""));
    let r = post(
        &server,
        "/own",
        &[("kind", "point"), ("p_normal", evil), ("viewer", evil)],
        &[],
    );
    assert_eq!(r.status, 422);
    assert!(!r.body.contains("<script") && !r.body.contains("<img"));
    assert!(r.body.contains("&lt;script&gt;"));
    // An unknown language or exercise is no way in either.
    let r = get(&server, "/exercise/%3Cscript%3E?lang=%3Cscript%3E", &[]);
    assert_eq!(r.status, 404);
    assert!(!r.body.contains("<script"));
    assert!(server_alive(server));
}

fn server_alive(mut s: Server) -> bool {
    s.alive()
}

#[test]
fn an_empty_form_says_what_to_write() {
    let server = Server::start(&[]);
    let r = post(&server, "/exercise/4.2?lang=pt", &[("answer", "  ")], &[]);
    assert_eq!(r.status, 422);
    assert!(r.body.contains("Escreva uma resposta"));
}

#[test]
fn the_worked_solution_is_the_html_phong_solve_writes() {
    let server = Server::start(&[]);
    let r = get(&server, "/exercise/4.2?solution=1&lang=pt", &[]);
    assert_eq!(r.status, 200);
    let out = support::phong()
        .args([
            "solve",
            "exercises/4.2.json",
            "--format",
            "html",
            "--lang",
            "pt",
        ])
        .output()
        .unwrap();
    let cli = String::from_utf8(out.stdout).unwrap();
    // The CLI's sections (its diagrams, its steps), byte for byte, from the first part on.
    let from = cli.find("<section class=\"part\"").unwrap();
    let to = cli.rfind("</article>").unwrap();
    assert!(r.body.contains(&cli[from..to]), "the solution differs");
    assert!(r.body.contains("<svg id=\"diagram-0-0-light0\""));
    // Asked for in the form too.
    let r = post(
        &server,
        "/exercise/4.2",
        &[("answer", "0 0 0"), ("solution", "1")],
        &[],
    );
    assert!(r.body.contains("id=\"solution\""));
}

#[test]
fn ones_own_problem_is_solved_and_its_file_shown_and_downloaded() {
    let server = Server::start(&[]);
    let form = get(&server, "/own?lang=pt", &[]);
    assert_eq!(form.status, 200);
    assert!(form
        .body
        .contains("<label for=\"p_normal\">Normal N em P</label>"));
    // The form starts with 4.2's data: posted as it is, it is 4.2, colour (0, 0, 0) as written.
    let fields: Vec<(String, String)> = {
        let b = &form.body;
        let mut v = Vec::new();
        for (at, _) in b.match_indices("<input type=\"text\"") {
            let tag = &b[at..at + b[at..].find('>').unwrap()];
            let get = |k: &str| {
                let key = format!("{k}=\"");
                let s = &tag[tag.find(&key).unwrap() + key.len()..];
                s[..s.find('"').unwrap()].to_owned()
            };
            v.push((get("name"), get("value")));
        }
        v
    };
    let mut body: Vec<(&str, &str)> = fields
        .iter()
        .map(|(k, v)| (k.as_str(), v.as_str()))
        .collect();
    body.push(("kind", "point"));
    let r = post(&server, "/own?lang=pt", &body, &[]);
    assert_eq!(r.status, 200, "{}", r.body);
    assert!(r.body.contains("<pre class=\"json\">"));
    assert!(r.body.contains("&quot;normal&quot;: ["));
    assert!(r.body.contains("id=\"solution\""));
    // The likely intended reading (the light taken the other way), worked out by hand:
    // diffuse (0.245, 0.28, 0.21) + specular O_s·0.35355·0.76585 = (0.054, 0.081, 0.108).
    assert!(r.body.contains("0.299"), "no (0.299, 0.361, 0.318)");
    let file = post(&server, "/own/problem.json", &body, &[]);
    assert_eq!(file.status, 200);
    assert_eq!(file.header("content-type"), Some("application/json"));
    assert!(file
        .header("content-disposition")
        .unwrap()
        .contains("filename=\"problem.json\""));
    let doc: serde_json::Value = serde_json::from_str(&file.body).unwrap();
    assert_eq!(doc["point"]["normal"], serde_json::json!([0.6, 0.0, 0.8]));
    // The file solves as the page did.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("problem.json");
    std::fs::write(&path, &file.body).unwrap();
    support::phong().arg("solve").arg(&path).assert().success();
}

#[test]
fn ones_own_spot_light_is_the_spot_exercise() {
    // spot-inside.json as a form: a white spot at (0, 0, 4) along (0, 0, −1), γ = 30°, e = 2,
    // no falloff; P(1, 0, 0), N = (0, 0, 1), seen from (0, 2, 4). By hand: L = (1, 0, −4)/√17,
    // cos ψ = 4/√17 = 0.97014 (ψ = 14.04° < 30°), spot factor 0.94118, cos θ = 0.97014, so
    // the diffuse term is O_d·0.91309 = (0.63916, 0.73047, 0.54785).
    let server = Server::start(&[]);
    let r = post(
        &server,
        "/own",
        &[
            ("kind", "point"),
            ("p_position", "1 0 0"),
            ("p_normal", "0 0 1"),
            ("viewer", "0 2 4"),
            ("l1_kind", "spot"),
            ("l1_position", "0 0 4"),
            ("l1_axis", "0 0 -1"),
            ("l1_angle", "30"),
            ("l1_exponent", "2"),
            ("l1_color", "1 1 1"),
            ("l1_falloff", "0"),
            ("m_ambient", "0.5 0.4 0.6"),
            ("m_diffuse", "0.7 0.8 0.6"),
            ("m_specular", "0.2 0.3 0.4"),
            ("m_shininess", "1"),
        ],
        &[],
    );
    assert_eq!(r.status, 200, "{}", r.body);
    assert!(r.body.contains("&quot;type&quot;: &quot;spot&quot;"));
    assert!(r.body.contains("(0.639"), "no diffuse (0.639, 0.73, 0.548)");
    assert!(r
        .body
        .contains("value=\"spot\" id=\"l1_kind-spot\" checked"));
}

#[test]
fn bad_numbers_in_ones_own_problem_are_refused_naming_the_field() {
    let server = Server::start(&[]);
    for (field, value, named) in [
        ("p_normal", "0.6 zero 0.8", "point.normal"),
        ("p_normal", "0 0 0", "point.normal"),
        ("m_shininess", "-1", "shininess"),
        ("l1_falloff", "um", "lights[0].falloff"),
        ("l1_color", "1 1", "lights[0].color"),
    ] {
        let r = post(
            &server,
            "/own",
            &[
                ("kind", "point"),
                ("p_position", "3 1 3"),
                ("p_normal", "0.6 0 0.8"),
                ("viewer", "5 4 6"),
                ("l1_kind", "point"),
                ("l1_position", "1 1 1"),
                ("l1_color", "1 1 1"),
                ("l1_falloff", "1"),
                ("m_ambient", "0.5 0.4 0.6"),
                ("m_diffuse", "0.7 0.8 0.6"),
                ("m_specular", "0.2 0.3 0.4"),
                ("m_shininess", "1"),
                (field, value),
            ],
            &[],
        );
        assert_eq!(r.status, 422, "{field}={value}");
        let error = &r.body[r.body.find("<p class=\"error\">").expect("an error")..];
        let error = &error[..error.find("</p>").unwrap()];
        assert!(error.contains(named), "{field}={value}: {error}");
    }
}

#[test]
fn an_instructors_folder_is_served_with_a_box_per_light() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["several-lights", "sphere-hit"] {
        std::fs::copy(
            format!("exercises/{name}.json"),
            dir.path().join(format!("{name}.json")),
        )
        .unwrap();
    }
    let server = Server::start(&["--exercises", dir.path().to_str().unwrap()]);
    let list = get(&server, "/", &[]);
    assert!(list
        .body
        .contains("href=\"/exercise/several-lights?lang=en\""));
    assert!(list.body.contains("href=\"/exercise/sphere-hit?lang=en\""));
    assert!(!list.body.contains("/exercise/4.2"));
    // Four lights that are not ambient (lights[1]–[4]): each light's quantities by index,
    // a spot's cone only for the spot (lights[3]), a directional light's no distance.
    let r = get(&server, "/exercise/several-lights", &[]);
    for name in [
        "cos_theta[1]",
        "cos_theta[4]",
        "cos_psi[3]",
        "d[1]",
        "I_a",
        "I",
    ] {
        assert!(
            r.body.contains(&format!("name=\"step:{name}\"")),
            "no {name}"
        );
    }
    for name in ["cos_theta", "cos_theta[0]", "cos_psi[1]", "d[2]", "t"] {
        assert!(
            !r.body.contains(&format!("name=\"step:{name}\"")),
            "a box {name}"
        );
    }
    // A step of the second light, judged as phong check judges it.
    let r = post(
        &server,
        "/exercise/several-lights",
        &[("step:cos_theta[2]", "0.5")],
        &[],
    );
    let path = dir.path().join("several-lights.json");
    let cli: serde_json::Value = serde_json::from_str(&check(&[
        path.to_str().unwrap(),
        "--step",
        "cos_theta[2]=0.5",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(
        attr(&r.body, "data-step=\"cos_theta[2]\"", "data-verdict"),
        cli["steps"]["steps"][0]["verdict"].as_str().unwrap()
    );
    // A ray problem of the folder: t is a step.
    let r = get(&server, "/exercise/sphere-hit?lang=pt", &[]);
    assert!(r.body.contains("<h1>Raio e esfera</h1>"));
    assert!(r.body.contains("name=\"step:t\""));
}

/// `--log-answers` keeps the answers sent through the pages too, one line each, with the
/// verdict `phong check` gives (4.2's normal-reversed answer is wrong); showing the same answer
/// in the other language (the header's switch re-posts the form) is not a second answer.
#[test]
fn answers_sent_through_the_form_are_logged_once() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let log = dir.path().join("answers.jsonl");
    let server = Server::start(&["--log-answers", log.to_str().expect("a UTF-8 path")]);
    let fields = [
        ("answer", "0.245 0.28 0.21"),
        ("scale", "1"),
        ("step:cos_theta", "-0.98995"),
    ];
    let r = post(&server, "/exercise/4.2?lang=pt", &fields, &[]);
    assert_eq!(r.status, 200);
    // The switch to English carries the same fields and `relang`.
    let mut switched: Vec<(&str, &str)> = fields.to_vec();
    switched.push(("relang", "1"));
    let r = post(&server, "/exercise/4.2?lang=en", &switched, &[]);
    assert_eq!(r.status, 200);
    assert!(r.body.contains("relang"), "the switch form carries relang");
    let text = std::fs::read_to_string(&log).expect("the log is written");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1, "{text}");
    let entry: serde_json::Value = serde_json::from_str(lines[0]).expect("a JSON line");
    assert_eq!(entry["exercise"], "4.2");
    assert_eq!(entry["answer"], "0.245 0.28 0.21");
    assert_eq!(entry["verdict"], "wrong");
    assert_eq!(entry["steps"]["cos_theta"], "-0.98995");
}
