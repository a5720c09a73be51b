//! The errors of reading and parsing a problem file, and of reading its meshes, in Portuguese
//! (problem/syntax.rs, problem/reading.rs, problem/mesh_faults.rs): each bad input is run
//! through the binary with `--lang pt` (one with the locale alone), and no English word of
//! the message's prose survives. serde's own words (`invalid type`, `expected one of`, `EOF
//! while parsing`) were English under `--lang pt` before they were read into values.

use crate::support;

use std::path::Path;

/// English words the messages of these errors hold in English; none may survive in Portuguese
/// outside quotes and backticks (where the file's own words stand). Words that are Portuguese
/// too (`a`, `no`, `os`, `face`, `byte`, `decimal`, `escape`) are not listed.
const ENGLISH: &[&str] = &[
    "the",
    "is",
    "are",
    "expected",
    "invalid",
    "type",
    "unknown",
    "field",
    "variant",
    "missing",
    "duplicate",
    "string",
    "integer",
    "floating",
    "sequence",
    "map",
    "boolean",
    "EOF",
    "while",
    "parsing",
    "trailing",
    "characters",
    "comma",
    "value",
    "key",
    "must",
    "number",
    "numbers",
    "array",
    "length",
    "elements",
    "too",
    "many",
    "file",
    "cannot",
    "read",
    "such",
    "directory",
    "permission",
    "denied",
    "error",
    "line",
    "vertex",
    "vertices",
    "refers",
    "has",
    "which",
    "not",
    "of",
    "give",
    "write",
    "add",
    "remove",
    "check",
    "correct",
    "Fix",
    "an",
    "to",
    "for",
    "from",
    "it",
    "this",
    "that",
    "with",
    "or",
    "and",
    "one",
    "words",
    "object",
    "written",
    "without",
    "quotes",
    "belongs",
    "here",
    "word",
    "fractions",
    "point",
    "light",
    "camera",
    "rendering",
    "needs",
    "surfaces",
    "scene",
    "mesh",
    "control",
    "ident",
    "out",
    "range",
    "beyond",
    "every",
    "finite",
    "save",
    "text",
    "degenerate",
    "its",
    "corners",
    "lie",
    "on",
    "path",
    "relative",
    "folder",
    "Português",
    "colour",
    "kind",
    "schema",
    "see",
    "form",
];

use super::prose;

/// The words of [`ENGLISH`] in the prose of `message`.
fn english_in(message: &str, file: &str) -> Vec<String> {
    prose(message, file)
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| ENGLISH.contains(w))
        .map(str::to_owned)
        .collect()
}

/// Runs `phong ARGS` in `dir` with the locale `lang` (`LANG`, no `LC_*`): the exit code and
/// standard error.
fn run(dir: &Path, args: &[&str], lang: &str) -> (i32, String) {
    let out = support::phong()
        .current_dir(dir)
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

/// `phong solve NAME --lang pt` on `bytes`: the exit code and standard error.
fn solve_pt(name: &str, bytes: &[u8]) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(name), bytes).unwrap();
    run(dir.path(), &["solve", name, "--lang", "pt"], "C")
}

/// Asserts that `stderr` is a Portuguese error with its fix, holding `holds` and no English.
fn wholly_portuguese(name: &str, stderr: &str, holds: &str, failures: &mut Vec<String>) {
    if !stderr.starts_with("erro: ") {
        failures.push(format!("{name}: not an error in Portuguese: {stderr}"));
    }
    if !stderr.contains(holds) {
        failures.push(format!("{name}: no {holds:?} in {stderr}"));
    }
    let found = english_in(stderr, name);
    if !found.is_empty() {
        failures.push(format!("{name}: English {found:?} in {stderr}"));
    }
}

/// Problem files that do not parse, and a part of the Portuguese each must hold.
fn bad_files() -> Vec<(&'static str, Vec<u8>, String)> {
    let cases: Vec<(&str, &[u8], &str)> = vec![
        (
            "unknown_field.json",
            br#"{"lihgts": []}"#,
            "campo desconhecido `lihgts`, esperado um de `$schema`",
        ),
        (
            "pontual.json",
            br#"{"lights": [{"type": "pontual"}]}"#,
            "escreva \"point\" para \"pontual\"",
        ),
        (
            "type_5.json",
            br#"{"lights": [{"type": 5}]}"#,
            "tipo inválido: inteiro `5`, esperada uma das palavras \"ambient\", \"point\"",
        ),
        (
            "no_direction.json",
            br#"{"ray": {"origin": [0, 0, 0]}}"#,
            "campo ausente `direction`. Correção: acrescente \"direction\": dá a direção",
        ),
        (
            "twice.json",
            br#"{"viewer": [1, 2, 3], "viewer": [1, 2, 3]}"#,
            "campo repetido `viewer`",
        ),
        (
            "material_twice.json",
            br#"{"materials": {"M": {}, "M": {}}}"#,
            "material repetido `M`",
        ),
        (
            "white.json",
            br#"{"viewer": "white"}"#,
            "tipo inválido: texto \"white\", esperada uma lista de comprimento 3",
        ),
        (
            "lots.json",
            br#"{"materials": {"M": {"shininess": "lots"}}}"#,
            "aqui vai um número, não a palavra \"lots\"",
        ),
        (
            "quoted.json",
            br#"{"materials": {"M": {"shininess": "10"}}}"#,
            "um número se escreve sem aspas: 10",
        ),
        (
            "title_5.json",
            br#"{"title": 5}"#,
            "tipo inválido: inteiro `5`, esperado um texto",
        ),
        (
            "ray_array.json",
            br#"{"ray": [[0, 0, 5], [0, 0, -1]]}"#,
            "tipo inválido: lista, esperado o raio: um objeto",
        ),
        (
            "render_true.json",
            br#"{"render": true}"#,
            "tipo inválido: booleano `true`, esperadas as configurações",
        ),
        (
            "map.json",
            br#"{"viewer": {"x": 1}}"#,
            "tipo inválido: objeto, esperada uma lista",
        ),
        (
            "minus_one.json",
            br#"{"render": {"max_level": -1}}"#,
            "valor inválido: inteiro `-1`, esperado um número inteiro",
        ),
        (
            "two.json",
            br#"{"viewer": [1, 2]}"#,
            "comprimento 2 inválido, esperada uma lista de comprimento 3",
        ),
        (
            "four.json",
            br#"{"viewer": [1, 2, 3, 4]}"#,
            "elementos demais: esperada uma lista de comprimento 3",
        ),
        (
            "trailing.json",
            br#"{"viewer": [1, 2, 3]} x"#,
            "caracteres a mais depois do fim do documento JSON",
        ),
        (
            "eof.json",
            br#"{"viewer": [1, 2"#,
            "fim do arquivo em meio a uma lista. Correção: o arquivo termina cedo demais",
        ),
        ("bracket.json", br#"{"viewer": ]}"#, "esperado um valor"),
        (
            "comma.json",
            br#"{"viewer": [1, 2 3]}"#,
            "esperado `,` ou `]`",
        ),
        (
            "trailing_comma.json",
            br#"{"viewer": [1, 2, 3],}"#,
            "vírgula a mais antes de `]` ou `}`",
        ),
        (
            "tru.json",
            br#"{"render": {"shadows": tru}}"#,
            "esperada uma palavra do JSON (true, false ou null)",
        ),
        (
            "escape.json",
            br#"{"title": "\q"}"#,
            "sequência de escape inválida",
        ),
        (
            "control.json",
            b"{\"title\": \"a\nb\"}",
            "caractere de controle",
        ),
        (
            "range.json",
            br#"{"viewer": [1e999, 0, 0]}"#,
            "número fora do alcance. Correção: o número está além do alcance de f64",
        ),
        (
            "nan.json",
            br#"{"viewer": [NaN, 0, 0]}"#,
            "o JSON não tem NaN: todo número deve ser finito",
        ),
        // 3/5 = 0.6.
        (
            "fraction.json",
            br#"{"viewer": [3/5, 0, 0]}"#,
            "escreva 3/5 como decimal, 0.6",
        ),
        // 0,5 is 0.5 with a decimal point.
        (
            "comma_key.json",
            br#"{"materials": {"M": {"shininess": 0,5}}}"#,
            "0,5 está escrito com vírgula decimal",
        ),
        (
            "array.json",
            b"[1]",
            "o arquivo é uma lista [ … ], e um arquivo de problema é um objeto JSON",
        ),
        // `{"title": "caf` is 14 bytes: the bad byte 0xE9 is column 15 of line 1.
        (
            "latin1.json",
            b"{\"title\": \"caf\xe9\"}",
            ":1:15: o byte 0xE9 não é texto UTF-8. Correção: salve o arquivo como UTF-8",
        ),
    ];
    let long = "a".repeat(81);
    let mut out: Vec<(&str, Vec<u8>, String)> = cases
        .into_iter()
        .map(|(n, b, h)| (n, b.to_vec(), h.to_owned()))
        .collect();
    // A word of 81 characters is shortened to 59 and its length, said in Portuguese. (Not an
    // unknown field: its name is also the error's field, `aaa… (81 characters):`, which
    // ProblemError keeps as an English string.)
    out.push((
        "long.json",
        format!("{{\"lights\": [{{\"type\": \"{long}\"}}]}}").into_bytes(),
        format!("valor desconhecido `{}… (81 caracteres)`", &long[..59]),
    ));
    out
}

#[test]
fn a_file_that_does_not_parse_is_refused_wholly_in_portuguese() {
    let mut failures = Vec::new();
    for (name, bytes, holds) in bad_files() {
        let (code, stderr) = solve_pt(name, &bytes);
        if code != 2 {
            failures.push(format!("{name}: exit {code}: {stderr}"));
        }
        wholly_portuguese(name, &stderr, &holds, &mut failures);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_file_that_cannot_be_read_says_why_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("folder.json")).unwrap();
    let mut failures = Vec::new();
    for (name, holds) in [
        (
            "absent.json",
            "não é possível ler o arquivo: arquivo ou pasta inexistente",
        ),
        ("folder.json", "não é possível ler o arquivo: é uma pasta"),
    ] {
        let (code, stderr) = run(dir.path(), &["solve", name, "--lang", "pt"], "C");
        assert_eq!(code, 2, "{name}: {stderr}");
        wholly_portuguese(name, &stderr, holds, &mut failures);
        assert!(stderr.contains("Correção: verifique o caminho"), "{stderr}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_locale_alone_gives_a_parse_error_in_portuguese_and_lang_en_overrides_it() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("f.json"), br#"{"viewer": [1, 2]}"#).unwrap();
    let (code, stderr) = run(dir.path(), &["solve", "f.json"], "pt_BR.UTF-8");
    assert_eq!(code, 2);
    let mut failures = Vec::new();
    wholly_portuguese(
        "f.json",
        &stderr,
        "f.json:1:17: viewer: comprimento 2 inválido, esperada uma lista de comprimento 3",
        &mut failures,
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let (_, stderr) = run(
        dir.path(),
        &["solve", "f.json", "--lang", "en"],
        "pt_BR.UTF-8",
    );
    assert_eq!(
        stderr,
        "error: f.json:1:17: viewer: invalid length 2, expected an array of length 3. Fix: see \
         `phong schema` for the expected form\n"
    );
}

/// A scene of one mesh, `NAME.obj` holding `obj` (nothing written when `obj` is `None`).
fn mesh_scene(dir: &Path, name: &str, obj: Option<&str>) -> String {
    if let Some(obj) = obj {
        std::fs::write(dir.join(format!("{name}.obj")), obj).unwrap();
    }
    let scene = format!("{name}.json");
    std::fs::write(
        dir.join(&scene),
        format!(
            r#"{{"camera": {{"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "width": 4,
            "height": 4}}, "lights": [{{"type": "ambient", "color": [1, 1, 1]}}],
            "surfaces": [{{"type": "mesh", "file": "{name}.obj",
            "material": {{"ambient": [1, 1, 1]}}}}]}}"#
        ),
    )
    .unwrap();
    scene
}

#[test]
fn a_mesh_that_cannot_be_used_is_refused_wholly_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    let corners = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
    let cases = [
        (
            "absent",
            None,
            "absent.obj: não pode ser lido: arquivo ou pasta inexistente".to_owned(),
        ),
        (
            "short",
            Some("v 0 0\n".to_owned()),
            "short.obj: linha 1: o vértice \"v 0 0\" não é `v x y z` (três números)".to_owned(),
        ),
        // Three vertices come before the face that names the seventh.
        (
            "index",
            Some(format!("{corners}f 1 2 7\n")),
            "linha 4: a face \"f 1 2 7\" se refere ao vértice 7, e 3 vértices vêm antes dela"
                .to_owned(),
        ),
        // (0,0,0), (1,0,0), (2,0,0) lie on the x axis.
        (
            "line",
            Some("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n".to_owned()),
            "linha 4: o triângulo 0 da face é degenerado em f64".to_owned(),
        ),
        // ±1e300: past what the ray–triangle test can multiply.
        (
            "huge",
            Some("v -1e300 -1e300 0\nv 1e300 -1e300 0\nv 0 1e300 0\nf 1 2 3\n".to_owned()),
            "o vértice 1 é grande demais para um triângulo em f64".to_owned(),
        ),
        (
            "empty",
            Some("v 0 0 0\n".to_owned()),
            "empty.obj: não tem faces".to_owned(),
        ),
        (
            "edge",
            Some(format!("{corners}l 1 2\n")),
            "linha 4: \"l 1 2\" é um elemento de linha".to_owned(),
        ),
        (
            "zero",
            Some(format!("{corners}vn 0 0 0\nf 1//1 2//1 3//1\n")),
            "linha 4: a normal de vértice \"vn 0 0 0\" tem comprimento zero em f64".to_owned(),
        ),
    ];
    let mut failures = Vec::new();
    for (name, obj, holds) in cases {
        let scene = mesh_scene(dir.path(), name, obj.as_deref());
        let (code, stderr) = run(
            dir.path(),
            &["render", &scene, "-o", "out.png", "--lang", "pt"],
            "C",
        );
        if code != 2 {
            failures.push(format!("{name}: exit {code}: {stderr}"));
        }
        let shown = stderr.replace(&format!("{name}.obj"), " ");
        wholly_portuguese(
            &scene,
            &shown,
            &holds.replace(&format!("{name}.obj"), " "),
            &mut failures,
        );
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_scene_without_a_camera_or_surfaces_is_refused_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("point.json"),
        br#"{"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "width": 4,
            "height": 4}, "lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [1, 1, 1]}}}"#,
    )
    .unwrap();
    std::fs::write(
        dir.path().join("nocamera.json"),
        br#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [1, 1, 1]}}}"#,
    )
    .unwrap();
    let mut failures = Vec::new();
    for (name, holds) in [
        (
            "nocamera.json",
            "camera: ausente: a renderização precisa de uma câmera",
        ),
        (
            "point.json",
            "surfaces: ausente: uma cena precisa de superfícies para seus raios atingirem",
        ),
    ] {
        let (code, stderr) = run(
            dir.path(),
            &["render", name, "-o", "out.png", "--lang", "pt"],
            "C",
        );
        assert_eq!(code, 2, "{name}: {stderr}");
        wholly_portuguese(name, &stderr, holds, &mut failures);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
