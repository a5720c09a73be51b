//! Issue 27: the errors of the solver, the tracer and `phong serve` are typed values, said in
//! Portuguese throughout under `--lang pt`, a `pt_BR` locale, or an API request's `"lang":
//! "pt"`, and in English as before (the JSON's English `message` unchanged).

use std::path::Path;

use crate::support;
#[cfg(feature = "serve")]
use crate::support::{http, server};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// English words none of these Portuguese messages may hold outside quotes and backticks
/// (where the file's own words stand); not "no", "as" or "use", which are Portuguese too.
const ENGLISH: &[&str] = &[
    "the",
    "is",
    "are",
    "and",
    "not",
    "with",
    "give",
    "of",
    "which",
    "this",
    "that",
    "or",
    "for",
    "than",
    "overflows",
    "cannot",
    "render",
    "add",
    "scene",
    "request",
    "server",
    "falloff",
    "factor",
    "bring",
    "numbers",
    "range",
    "colour",
    "adds",
    "level",
    "listen",
    "more",
    "Fix",
    "such",
    "names",
    "default",
    "solves",
    "limit",
];

/// The English words of [`ENGLISH`] in `message`, what stands between quotes or backticks
/// and the paths `skip` left out.
fn english_in(message: &str, skip: &[&str]) -> Vec<String> {
    let mut text = message.to_owned();
    for s in skip {
        text = text.replace(s, " ");
    }
    let mut prose = String::new();
    let mut quote: Option<char> = None;
    for c in text.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '`' => quote = Some(c),
            None => prose.push(c),
        }
    }
    prose
        .split(|c: char| !c.is_alphanumeric() && c != '_')
        .filter(|w| ENGLISH.contains(w))
        .map(str::to_owned)
        .collect()
}

/// `phong ARGS…` from the crate's folder with the locale `lang` (`LANG`, the other locale
/// variables cleared): its exit code and standard error.
fn phong_in_locale(lang: &str, args: &[&str]) -> (i32, String) {
    let out = support::phong()
        .current_dir(root())
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", lang)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_scene_given_to_solve_is_refused_in_portuguese_by_flag_and_by_locale() {
    let (code, en) = phong_in_locale("C", &["solve", "scenes/classic.json"]);
    assert_eq!(code, 2, "{en}");
    assert_eq!(
        en.trim_end(),
        "error: scenes/classic.json: ray: this file is a scene (a camera and surfaces): it has \
         no point or ray to solve. Fix: render it with `phong render FILE -o image.png` (and \
         explain one pixel with --explain-pixel X,Y), or add a \"ray\" to solve one ray"
    );
    let (code, pt) = phong_in_locale("C", &["solve", "scenes/classic.json", "--lang", "pt"]);
    assert_eq!(code, 2, "{pt}");
    assert_eq!(
        pt.trim_end(),
        "erro: scenes/classic.json: ray: este arquivo é uma cena (uma câmera e superfícies): não \
         tem ponto nem raio a resolver. Correção: renderize-a com `phong render FILE -o \
         image.png` (e explique um pixel com --explain-pixel X,Y), ou acrescente um \"ray\" para \
         resolver um raio"
    );
    assert_eq!(
        english_in(&pt, &["scenes/classic.json"]),
        Vec::<String>::new()
    );
    // The locale alone, with no --lang.
    let (code, by_locale) = phong_in_locale("pt_BR.UTF-8", &["solve", "scenes/classic.json"]);
    assert_eq!(code, 2);
    assert_eq!(by_locale, pt);
}

/// `phong ARGS` run in `dir`, refused (exit 2): its standard error.
fn refused_in(dir: &Path, args: &[&str]) -> String {
    let out = support::phong()
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    String::from_utf8(out.stderr).unwrap()
}

#[test]
fn a_falloff_that_overflows_f32_is_said_in_portuguese() {
    // A light 1e-20 from P with quadratic falloff: 1/d² = 1e40, beyond f32's 3.4e38.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("near.json"),
        r#"{
  "materials": {"M": {"ambient": [0.5, 0.4, 0.6], "diffuse": [0.7, 0.8, 0.6],
                      "specular": [0.2, 0.3, 0.4], "shininess": 1}},
  "lights": [{"type": "point", "position": [0, 0, 1e-20], "color": [1, 1, 1], "falloff": 2}],
  "viewer": [5, 4, 6],
  "point": {"position": [0, 0, 0], "normal": [0, 0, 1], "material": "M"}
}"#,
    )
    .unwrap();
    let run = |lang: &str| {
        refused_in(
            dir.path(),
            &["solve", "near.json", "--precision", "f32", "--lang", lang],
        )
    };
    let en = run("en");
    assert!(
        en.contains("lights[0]: the falloff factor 1/d^f of lights[0] (point) (d = ")
            && en.contains(") overflows f32. Fix: use --precision f64, or bring the numbers"),
        "{en}"
    );
    let pt = run("pt");
    assert!(
        pt.starts_with("erro: near.json: lights[0]: o termo de decaimento 1/d^f de lights[0]")
            && pt.contains("passa do alcance de f32. Correção: use --precision f64, ou números"),
        "{pt}"
    );
    // "(point)" is the file's own "type".
    assert_eq!(
        english_in(&pt, &["near.json", "(point)", "--precision f64"]),
        Vec::<String>::new(),
        "{pt}"
    );
}

#[test]
fn a_sphere_too_small_for_its_coordinates_is_said_in_portuguese_with_the_fix_of_f64() {
    // A radius of 1e-20 at z = 1, met from z = 5: the hit point rounds to the centre.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("tiny.json"),
        r#"{
  "materials": {"M": {"ambient": [0.5, 0.4, 0.6]}},
  "lights": [{"type": "ambient", "color": [1, 1, 1]}],
  "ray": {"origin": [0, 0, 5], "direction": [0, 0, -1]},
  "surfaces": [{"type": "sphere", "center": [0, 0, 1], "radius": 1e-20, "material": "M"}]
}"#,
    )
    .unwrap();
    let pt = refused_in(dir.path(), &["solve", "tiny.json", "--lang", "pt"]);
    assert!(
        pt.starts_with(
            "erro: tiny.json: surfaces[0]: o ponto de interseção não se distingue do centro da \
             esfera em f64"
        ) && pt.contains("Correção: dê à esfera um raio maior, ou desloque a cena")
            && !pt.contains("--precision"),
        "{pt}"
    );
    assert_eq!(
        english_in(&pt, &["tiny.json"]),
        Vec::<String>::new(),
        "{pt}"
    );
}

#[test]
fn a_pixel_whose_reflection_overflows_is_refused_in_portuguese() {
    // The classic scene with the mirror's reflectivity 9.5e299 and the floor's ambient O_a =
    // 3.4e38: the mirror's reflection adds O_r·C_r ≈ 9.5e299 · 0.2 · 3.4e38 ≈ 6e337 > f64.
    let text = std::fs::read_to_string(root().join("scenes/classic.json"))
        .unwrap()
        .replace(
            "\"reflectivity\": [0.95, 0.95, 0.95]",
            "\"reflectivity\": [9.5e299, 9.5e299, 9.5e299]",
        )
        .replacen(
            "\"ambient\": [0.1, 0.1, 0.1]",
            "\"ambient\": [3.4028235e38, 0.1, 0.1]",
            1,
        );
    assert!(text.contains("9.5e299") && text.contains("3.4028235e38"));
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("hot.json"), text).unwrap();
    let run = |lang: &str| {
        refused_in(
            dir.path(),
            &[
                "render",
                "hot.json",
                "--explain-pixel",
                "320,240",
                "--lang",
                lang,
            ],
        )
    };
    let en = run("en");
    assert!(
        en.contains("adds, O_r·C_r (Eq. 4.17), overflows f64 (material \"")
            && en.contains("Fix: bring the reflectivity O_r and the colours"),
        "{en}"
    );
    let pt = run("pt");
    assert!(
        pt.contains("deste pixel soma, O_r·C_r (Eq. 4.17), passa do alcance de f64 (material \"")
            && pt.contains("Correção: use uma reflexividade O_r e cores"),
        "{pt}"
    );
    assert_eq!(english_in(&pt, &["hot.json"]), Vec::<String>::new(), "{pt}");
}

/// `phong serve` has no `--lang` and its errors are printed in English (cli/args.rs's
/// `Command::lang`); the Portuguese of its start errors is held by serve/faults.rs's tests.
#[cfg(feature = "serve")]
#[test]
fn a_server_that_cannot_listen_says_why() {
    let taken = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = taken.local_addr().unwrap().to_string();
    let (code, en) = phong_in_locale("C", &["serve", "--addr", &addr]);
    assert_eq!(code, 2, "{en}");
    assert!(
        en.starts_with(&format!("error: --addr: cannot listen on {addr}: ")),
        "{en}"
    );
    drop(taken);
}

#[cfg(feature = "serve")]
#[test]
fn the_apis_errors_with_lang_pt_hold_no_english() {
    let server = server::Server::start(&[]);
    let exercise = std::fs::read_to_string(root().join("exercises/4.2.json")).unwrap();
    let scene = std::fs::read_to_string(root().join("scenes/classic.json")).unwrap();
    let mut many: serde_json::Value = serde_json::from_str(&exercise).unwrap();
    let light = many["lights"][0].clone();
    many["lights"] = serde_json::Value::Array(vec![light; 17]);
    let cases: Vec<(&str, String, u16, &str, &str)> = vec![
        (
            "/api/solve",
            "{\"exercise\": \"4.2\", \"precision\": \"f16\", \"lang\": \"pt\"}".into(),
            400,
            "precision: \"f16\" não é uma precisão: dê \"f64\" (o padrão) ou \"f32\"",
            "precision: \"f16\" is not a precision: give \"f64\" (the default) or \"f32\"",
        ),
        (
            "/api/check",
            "{\"exercise\": \"9.9\", \"lang\": \"pt\"}".into(),
            404,
            "exercise: este servidor não tem o exercício \"9.9\"; tem 4.1, 4.2, 4.3 (GET \
             /api/exercises os lista)",
            "exercise: this server has no exercise \"9.9\"; it has 4.1, 4.2, 4.3 (GET \
             /api/exercises lists them)",
        ),
        (
            "/api/solve",
            format!("{{\"exercise\": \"4.2\", \"problem\": {exercise}, \"lang\": \"pt\"}}"),
            400,
            "dê \"problem\" (o JSON de um arquivo de problema) ou \"exercise\" (o id de um dos \
             exercícios deste servidor), não os dois",
            "give either \"problem\" (a problem file's JSON) or \"exercise\" (the id of one of \
             this server's exercises), not both",
        ),
        (
            "/api/check",
            "{\"lang\": \"pt\", \"scale\": 7}".into(),
            400,
            "scale: dê 1 (componentes em [0, 1], o padrão) ou 255 (inteiros de 8 bits)",
            "scale: give 1 (components on [0, 1], the default) or 255 (8-bit integers)",
        ),
        (
            "/api/solve",
            format!("{{\"problem\": {many}, \"lang\": \"pt\"}}"),
            422,
            "problem: lights: 17 fontes de luz são mais que as 16 que este servidor resolve \
             numa requisição. Correção: dê no máximo 16 fontes de luz, ou resolva o problema \
             com o comando phong, que não tem esse limite",
            "problem: lights: 17 lights are more than the 16 this server solves in one request. \
             Fix: give at most 16 lights, or solve the problem with the phong command, which \
             has no such limit",
        ),
        (
            "/api/solve",
            format!("{{\"problem\": {scene}, \"lang\": \"pt\"}}"),
            422,
            "problem: ray: este arquivo é uma cena (uma câmera e superfícies): não tem ponto nem \
             raio a resolver. Correção: renderize-a com `phong render FILE -o image.png` (e \
             explique um pixel com --explain-pixel X,Y), ou acrescente um \"ray\" para resolver \
             um raio",
            "problem: ray: this file is a scene (a camera and surfaces): it has no point or ray \
             to solve. Fix: render it with `phong render FILE -o image.png` (and explain one \
             pixel with --explain-pixel X,Y), or add a \"ray\" to solve one ray",
        ),
    ];
    for (path, body, status, pt, en) in cases {
        let r = http::post_json(server.addr, path, &body);
        assert_eq!(r.status, status, "{path} {body}: {}", r.text());
        let message = r.json()["error"]["message"].as_str().unwrap().to_owned();
        assert_eq!(message, pt);
        assert_eq!(english_in(&message, &["problem:"]), Vec::<String>::new());
        // Without "lang", the English as before.
        let body = body
            .replace(", \"lang\": \"pt\"", "")
            .replace("\"lang\": \"pt\", ", "");
        let r = http::post_json(server.addr, path, &body);
        assert_eq!(r.status, status, "{path} {body}: {}", r.text());
        assert_eq!(r.json()["error"]["message"], en);
    }
}

/// A request sent as written, with its own headers, on a connection of its own.
#[cfg(feature = "serve")]
fn raw(addr: std::net::SocketAddr, head: &str, body: &str) -> http::Response {
    use std::io::Write;
    let mut stream = std::net::TcpStream::connect(addr).unwrap();
    let request = format!(
        "{head}Host: {addr}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    stream.write_all(request.as_bytes()).unwrap();
    http::read_response(&mut std::io::BufReader::new(stream)).unwrap()
}

/// Issue 27: a refusal said before the request's `lang` is read (its body is not JSON, or not
/// the API's) speaks the language of its `Accept-Language`, as the pages choose theirs.
#[cfg(feature = "serve")]
#[test]
fn a_refusal_before_the_body_is_read_speaks_the_accept_language() {
    let server = server::Server::start(&[]);
    let not_json = "POST /api/solve HTTP/1.1\r\nContent-Type: text/plain\r\n";
    let pt = raw(
        server.addr,
        &format!("{not_json}Accept-Language: pt-BR,pt;q=0.9,en;q=0.5\r\n"),
        "{}",
    );
    assert_eq!(pt.status, 415, "{}", pt.text());
    let message = pt.json()["error"]["message"].as_str().unwrap().to_owned();
    assert!(
        message.starts_with("o corpo da requisição deve ser JSON, enviado com o cabeçalho"),
        "{message}"
    );
    assert_eq!(english_in(&message, &[]), Vec::<String>::new());
    let en = raw(server.addr, not_json, "{}");
    let message = en.json()["error"]["message"].as_str().unwrap().to_owned();
    assert!(
        message.starts_with("the request body must be JSON, sent with the header"),
        "{message}"
    );
    // A body that is not the API's JSON: serde's words are said in Portuguese too.
    let json = "POST /api/solve HTTP/1.1\r\nContent-Type: application/json\r\n";
    let pt = raw(
        server.addr,
        &format!("{json}Accept-Language: pt\r\n"),
        "{\"exercise\": 4.2}",
    );
    assert_eq!(pt.status, 400, "{}", pt.text());
    let message = pt.json()["error"]["message"].as_str().unwrap().to_owned();
    assert!(
        message.starts_with("a requisição não é o JSON da API: exercise: "),
        "{message}"
    );
    assert!(message.contains("na linha 1, coluna "), "{message}");
    let en = raw(server.addr, json, "{\"exercise\": 4.2}");
    let message = en.json()["error"]["message"].as_str().unwrap().to_owned();
    assert!(
        message.starts_with("the request is not the API's JSON: exercise: invalid type: "),
        "{message}"
    );
    assert!(message.contains(" at line 1 column "), "{message}");
}
