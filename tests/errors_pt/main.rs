//! QA report A, findings 1 and 4: with `--lang pt` a problem file's errors are wholly
//! Portuguese (no English word of the message survives, and the Portuguese the code writes as
//! an aside is used), and a decimal comma in a problem file is named as such, with its fix.

// One test binary for every message said in Portuguese (one crate links once): the modules
// below are each area's, beside this file's own tests of a problem file's errors.
#[path = "../support/mod.rs"]
#[allow(dead_code)]
mod support;

mod check_pt;
mod grade_reasons;
mod parse_pt;
mod solve_serve_pt;
mod validate_pt;

use std::path::Path;

/// Exercise 4.2 with `from` replaced by `to` (once; the text must hold it).
fn exercise_with(from: &str, to: &str) -> String {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.2.json"))
            .unwrap();
    assert!(text.contains(from), "4.2.json has no {from:?}");
    text.replacen(from, to, 1)
}

/// Runs `phong solve FILE --lang LANG` on `text`: the exit code and standard error.
fn solve(name: &str, text: &str, lang: &str) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    let out = support::phong()
        .current_dir(dir.path())
        .args(["solve", name, "--lang", lang])
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The cases of finding 1: one change each to 4.2.json.
fn finding_1_cases() -> Vec<(&'static str, String)> {
    vec![
        // The light at the point: lights[0].position = point.position.
        (
            "light_at_p.json",
            exercise_with(r#""position": [1, 1, 1]"#, r#""position": [3, 1, 3]"#),
        ),
        (
            "viewer_at_p.json",
            exercise_with(r#""viewer": [5, 4, 6]"#, r#""viewer": [3, 1, 3]"#),
        ),
        (
            "frac.json",
            exercise_with(r#""position": [3, 1, 3]"#, r#""position": [3/5, 1, 3]"#),
        ),
        (
            "normal_str.json",
            exercise_with(r#""normal": [0.6, 0, 0.8]"#, r#""normal": "3/5 0 4/5""#),
        ),
        (
            "badtype.json",
            exercise_with(r#""type": "point""#, r#""type": "pontual""#),
        ),
        (
            "strcolor.json",
            exercise_with(r#""color": [1, 1, 1]"#, r#""color": "white""#),
        ),
    ]
}

/// English words (and word pairs) of the messages of finding 1 that must not survive in
/// Portuguese.
const ENGLISH: &[&str] = &[
    "the",
    "light",
    "viewer",
    "point",
    "move",
    "write",
    "expected",
    "fractions",
    "unknown",
    "variant",
    "array",
    "length",
    "of",
    "away",
    "from",
    "so",
    "is",
    "undefined",
    "fix",
    "Português",
];

/// The prose of a message: what is between quotes or backticks (the file's own words, such as
/// `pontual` or "white"), the file's name and the field (`point.position:`,
/// `lights[0].type:`) left out.
fn prose(message: &str, file: &str) -> String {
    let mut out = String::new();
    let mut quote: Option<char> = None;
    for c in message.replace(file, " ").chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '`' => quote = Some(c),
            None => out.push(c),
        }
    }
    out.split_whitespace()
        .filter(|w| {
            !(w.ends_with(':')
                && w.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "_.[]:?".contains(c)))
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The English words of [`ENGLISH`] in `message`.
fn english_in(message: &str, file: &str) -> Vec<String> {
    prose(message, file)
        .split(|c: char| !c.is_alphabetic())
        .filter(|w| ENGLISH.iter().any(|e| e.eq_ignore_ascii_case(w)))
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_errors_of_finding_1_are_wholly_portuguese() {
    let mut failures = Vec::new();
    for (name, text) in finding_1_cases() {
        let (code, stderr) = solve(name, &text, "pt");
        assert_eq!(code, 2, "{name}: {stderr}");
        assert!(stderr.starts_with("erro: "), "{name}: {stderr}");
        assert!(stderr.contains("Correção: "), "{name}: no fix in {stderr}");
        let found = english_in(&stderr, name);
        if !found.is_empty() {
            failures.push(format!("{name}: {found:?} in {stderr}"));
        }
    }
    assert!(
        failures.is_empty(),
        "English with --lang pt:\n{}",
        failures.join("\n")
    );
}

#[test]
fn a_fraction_s_fix_is_wholly_portuguese_and_wholly_english() {
    // The fix is one value with both languages: the Portuguese says it all, the English too.
    let (_, pt) = solve(
        "frac.json",
        &exercise_with(r#""position": [3, 1, 3]"#, r#""position": [3/5, 1, 3]"#),
        "pt",
    );
    assert!(
        pt.contains("Correção: o JSON não aceita frações: escreva 3/5 como decimal, 0.6"),
        "{pt}"
    );
    assert!(!pt.contains("(Português"), "{pt}");
    // In English the fix is English alone.
    let (_, en) = solve(
        "frac.json",
        &exercise_with(r#""position": [3, 1, 3]"#, r#""position": [3/5, 1, 3]"#),
        "en",
    );
    assert!(en.contains("write 3/5 as a decimal, 0.6"), "{en}");
    assert!(!en.contains("Português"), "{en}");
}

#[test]
fn a_string_of_numbers_for_a_vector_names_every_fraction() {
    // "3/5 0 4/5" is three numbers written as text: the fix gives the array, 3/5 = 0.6 and
    // 4/5 = 0.8 both.
    let text = exercise_with(r#""normal": [0.6, 0, 0.8]"#, r#""normal": "3/5 0 4/5""#);
    let (_, en) = solve("normal_str.json", &text, "en");
    assert!(en.contains("[0.6, 0, 0.8]"), "{en}");
    let (_, pt) = solve("normal_str.json", &text, "pt");
    assert!(pt.contains("[0.6, 0, 0.8]"), "{pt}");
}

/// Finding 4: a decimal comma in a problem file is named as such: the field, what was
/// written, and the number with a decimal point, in both languages.
#[test]
fn a_decimal_comma_in_a_problem_file_is_named_with_its_fix() {
    // "shininess": 0,5 is read as 0 and a key 5: the field is shininess, not materials.M.
    let text = exercise_with(r#""shininess": 1"#, r#""shininess": 0,5"#);
    let (code, en) = solve("comma.json", &text, "en");
    assert_eq!(code, 2, "{en}");
    assert!(
        en.contains("materials.M.shininess: 0,5 is written with a decimal comma"),
        "{en}"
    );
    assert!(en.contains("a JSON number takes a decimal point"), "{en}");
    assert!(en.contains("Fix: write 0.5"), "{en}");
    let (_, pt) = solve("comma.json", &text, "pt");
    assert!(
        pt.contains("materials.M.shininess: 0,5 está escrito com vírgula decimal"),
        "{pt}"
    );
    assert!(pt.contains("Correção: escreva 0.5"), "{pt}");
    assert!(english_in(&pt, "comma.json").is_empty(), "{pt}");
    // [0,5, 0,4, 0,6] is read as six numbers: the three as written, and with points.
    let text = exercise_with(
        r#""ambient": [0.5, 0.4, 0.6]"#,
        r#""ambient": [0,5, 0,4, 0,6]"#,
    );
    let (code, en) = solve("comma2.json", &text, "en");
    assert_eq!(code, 2, "{en}");
    assert!(
        en.contains(
            "materials.M.ambient: [0,5, 0,4, 0,6] has numbers written with a decimal comma"
        ),
        "{en}"
    );
    assert!(en.contains("Fix: write [0.5, 0.4, 0.6]"), "{en}");
    assert!(!en.contains("exactly three numbers"), "{en}");
    let (_, pt) = solve("comma2.json", &text, "pt");
    assert!(pt.contains("Correção: escreva [0.5, 0.4, 0.6]"), "{pt}");
    assert!(english_in(&pt, "comma2.json").is_empty(), "{pt}");
    // A compact array of integers is no decimal comma: [1,1,1,1] is too long, as before.
    let text = exercise_with(r#""color": [1, 1, 1]"#, r#""color": [1,1,1,1]"#);
    let (_, en) = solve("four.json", &text, "en");
    assert!(!en.contains("decimal comma"), "{en}");
}

/// Finding 9: with several files, each warning names the file it is about, in both languages.
#[test]
fn a_warning_names_its_file_among_several() {
    let dir = tempfile::tempdir().unwrap();
    let c255 = exercise_with(
        r#""diffuse": [0.7, 0.8, 0.6]"#,
        r#""diffuse": [178, 204, 153]"#,
    );
    std::fs::write(dir.path().join("c255.json"), c255).unwrap();
    let ok = exercise_with(r#""title""#, r#""title""#);
    std::fs::write(dir.path().join("ok.json"), ok).unwrap();
    for (lang, word) in [("en", "warning"), ("pt", "aviso")] {
        let out = support::phong()
            .current_dir(dir.path())
            .args([
                "solve",
                "ok.json",
                "c255.json",
                "--lang",
                lang,
                "-o",
                "out.txt",
            ])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{err}");
        assert!(
            err.starts_with(&format!("{word}: c255.json: materials.M.diffuse: ")),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}

/// Finding 7: an output path in a missing folder: the message names the path given (not the
/// temporary file's random name) and the fix, in both languages; nothing is written.
#[test]
fn an_output_in_a_missing_folder_names_the_path_and_the_fix() {
    let dir = tempfile::tempdir().unwrap();
    let exercise = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.1.json");
    for (command, output) in [("solve", "nodir/x.txt"), ("moodle", "nodir/q.xml")] {
        for lang in ["en", "pt"] {
            let out = support::phong()
                .current_dir(dir.path())
                .arg(command)
                .arg(&exercise)
                .args(["--lang", lang, "-o", output])
                .output()
                .unwrap();
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{err}");
            assert!(!err.contains(".phong-"), "{err}");
            assert!(!err.contains(".tmp"), "{err}");
            let expected = match lang {
                "en" => format!(
                    "error: cannot write {output}: the folder nodir does not exist. Fix: create \
                     it first (mkdir -p nodir), or give a path in a folder that exists"
                ),
                _ => format!(
                    "erro: não é possível escrever {output}: a pasta nodir não existe. Correção: \
                     crie-a antes (mkdir -p nodir), ou dê um caminho numa pasta que existe"
                ),
            };
            assert!(err.starts_with(&expected), "{err}");
        }
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}

/// Finding 6: a decimal comma in a flag that takes one number is read as one, as `--answer`
/// reads it; `--reading-credit` out of range says what a share is, in Portuguese too.
#[test]
fn a_numeric_flag_takes_a_decimal_comma() {
    let exercise = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.1.json");
    let run = |extra: &[&str]| {
        let out = support::phong()
            .arg("check")
            .arg(&exercise)
            .args(extra)
            .output()
            .unwrap();
        (
            out.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    // 4.1's key is (0.5, 0.7, 0.3)... whatever it is, --tolerance 0,01 and 0.01 agree.
    let (comma, out_comma, err) = run(&[
        "--answer",
        "0 0 0",
        "--tolerance",
        "0,01",
        "--format",
        "json",
    ]);
    assert_ne!(comma, 2, "{err}");
    let (point, out_point, _) = run(&[
        "--answer",
        "0 0 0",
        "--tolerance",
        "0.01",
        "--format",
        "json",
    ]);
    assert_eq!((comma, out_comma), (point, out_point));
}

/// Runs `phong ARGS` in `dir` with `stdin` on standard input: the exit code and standard error.
fn phong_in(dir: &Path, args: &[&str], stdin: &[u8]) -> (i32, String) {
    let out = support::phong()
        .current_dir(dir)
        .args(args)
        .write_stdin(stdin)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `scenes/mesh.json` as a JSON value, its mesh named `obj`.
fn mesh_scene(obj: &str) -> serde_json::Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/mesh.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["surfaces"][1]["file"] = obj.into();
    v
}

#[test]
fn a_scenes_errors_are_wholly_portuguese_and_say_what_fits() {
    // QA report B, findings 3, 6, 7, 8 and 20: each render error in Portuguese, with no English
    // word left, and with words that fit the case.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let classic: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/classic.json"))
            .unwrap(),
    )
    .unwrap();
    let mut nocam = classic.clone();
    nocam.as_object_mut().unwrap().remove("camera");
    std::fs::write(d.join("nocam.json"), nocam.to_string()).unwrap();
    let mut bg = classic.clone();
    bg["background"] = serde_json::json!([2, 0, -1]);
    std::fs::write(d.join("bg.json"), bg.to_string()).unwrap();
    std::fs::write(d.join("nan.obj"), "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    std::fs::write(d.join("nan.json"), mesh_scene("nan.obj").to_string()).unwrap();
    let big = format!(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n{}",
        "f 1 2 3\n".repeat(1_000_001)
    );
    std::fs::write(d.join("big.obj"), big).unwrap();
    std::fs::write(d.join("big.json"), mesh_scene("big.obj").to_string()).unwrap();
    let stdin_scene = mesh_scene("absent.obj").to_string();

    let cases: [(&str, &[u8], &[&str]); 5] = [
        // No camera: the field is the camera, not "point".
        ("nocam.json", b"", &["camera: ausente"]),
        // The background is not a light, and its numbers are shown as written.
        ("bg.json", b"", &["a cor de fundo", "[2, 0, -1]"]),
        // A NaN vertex in f64: no advice to use f64.
        (
            "nan.json",
            b"",
            &["não é finito em f64", "dê coordenadas finitas"],
        ),
        // Over a million triangles: the fix in Portuguese too.
        ("big.json", b"", &["dê uma malha de até 1000000 triângulos"]),
        // A scene on standard input: its mesh is relative to the working folder.
        (
            "-",
            stdin_scene.as_bytes(),
            &["pasta de trabalho", "entrada padrão"],
        ),
    ];
    for (file, stdin, wanted) in cases {
        let args = ["render", file, "-o", "out.png", "--lang", "pt"];
        let (code, stderr) = phong_in(d, &args, stdin);
        assert_eq!(code, 2, "{file}: {stderr}");
        for w in wanted {
            assert!(stderr.contains(w), "{file}: no {w:?} in {stderr}");
        }
        assert!(!stderr.contains("--precision f64"), "{file}: {stderr}");
        let found = english_in(&stderr, file);
        assert!(found.is_empty(), "{file}: {found:?} in {stderr}");
        assert!(!d.join("out.png").exists(), "{file}: an image was written");
    }
    // In f32 the other precision is a way out, and the fix says so.
    let (_, stderr) = phong_in(
        d,
        &["render", "nan.json", "-o", "o.png", "--precision", "f32"],
        b"",
    );
    assert!(stderr.contains("(or use --precision f64)"), "{stderr}");
}

#[test]
fn an_explained_mesh_pixel_names_its_triangle_in_portuguese() {
    // QA report B, finding 4: "triangle (surfaces[1] (mesh), triangle 1557)" in Portuguese;
    // issue 29: named as a person would, "O triângulo 1557 da malha".
    let out = support::phong()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args([
            "render",
            "scenes/mesh.json",
            "--explain-pixel",
            "240,150",
            "--lang",
            "pt",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("O triângulo 1557 da malha: "), "{text}");
    assert!(
        !text.contains("triangle") && !text.contains("(mesh)"),
        "{text}"
    );
}

#[test]
fn a_degenerate_obj_face_is_named_without_tobjs_placeholder() {
    // QA report B, finding 22: "(model \"unnamed_object\")" named an object the file never
    // gives; a file's own `o name` is still named, as an object.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let flat = "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
    std::fs::write(d.join("flat.obj"), flat).unwrap();
    std::fs::write(d.join("named.obj"), format!("o wing\n{flat}")).unwrap();
    std::fs::write(d.join("flat.json"), mesh_scene("flat.obj").to_string()).unwrap();
    std::fs::write(d.join("named.json"), mesh_scene("named.obj").to_string()).unwrap();
    let (code, stderr) = phong_in(d, &["render", "flat.json", "-o", "o.png"], b"");
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("is degenerate in f64"), "{stderr}");
    assert!(
        !stderr.contains("unnamed_object") && !stderr.contains("model"),
        "{stderr}"
    );
    let (_, stderr) = phong_in(
        d,
        &["render", "named.json", "-o", "o.png", "--lang", "pt"],
        b"",
    );
    assert!(stderr.contains("(objeto \"wing\")"), "{stderr}");
}

/// Runs phong from the crate's folder with `args` in the locale `lang` (`LANG`; `LC_ALL` and
/// `LC_MESSAGES` unset): the exit code, standard output and standard error.
fn phong_with_locale(lang: &str, args: &[&str]) -> (i32, String, String) {
    let out = support::phong()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", lang)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Issue 27: clap's usage errors are rebuilt in Portuguese from clap's context (the argument,
/// the value, the valid values, the suggestion), one kind each; exit 2 as clap's own.
#[test]
fn clap_usage_errors_are_said_in_portuguese() {
    const MORE: &str = "\n\nPara mais informações, tente '--help'.\n";
    let cases: Vec<(Vec<&str>, String)> = vec![
        // InvalidValue, with the valid values and clap's suggestion.
        (
            vec![
                "solve",
                "exercises/4.1.json",
                "--format",
                "jsn",
                "--lang",
                "pt",
            ],
            format!(
                "erro: valor inválido 'jsn' para '--format <FORMAT>'\n  [valores possíveis: \
                 text, markdown, latex, html, json]\n\n  dica: há um valor parecido: 'json'{MORE}"
            ),
        ),
        // InvalidValue with no value at all.
        (
            vec!["check", "exercises/4.1.json", "--lang=pt", "--format"],
            format!(
                "erro: '--format <FORMAT>' precisa de um valor, e nenhum foi dado\n  [valores \
                 possíveis: text, json, html, markdown]{MORE}"
            ),
        ),
        // ValueValidation: phong's own parser's reason, in Portuguese.
        (
            vec![
                "check",
                "exercises/4.1.json",
                "--answer",
                "0 0 0",
                "--tolerance",
                "abc",
                "--lang",
                "pt",
            ],
            format!(
                "erro: valor inválido 'abc' para '--tolerance <T>': \"abc\" não é uma \
                 tolerância. Correção: dê a maior diferença aceita por canal, um número ≥ 0 (por \
                 exemplo 0.005 na escala 0–1, 1 na escala 255){MORE}"
            ),
        ),
        (
            vec![
                "render",
                "scenes/4.3.json",
                "--samples",
                "0",
                "-o",
                "x.png",
                "--lang",
                "pt",
            ],
            format!(
                "erro: valor inválido '0' para '--samples <N>': 0 está fora de 1 a 4096. \
                 Correção: dê as amostras por pixel de 1 a 4096{MORE}"
            ),
        ),
        (
            vec![
                "render",
                "scenes/4.3.json",
                "--explain-pixel",
                "3,b",
                "--lang",
                "pt",
            ],
            format!(
                "erro: valor inválido '3,b' para '--explain-pixel <X,Y>': \"b\" não é uma \
                 coordenada de pixel (um número inteiro ≥ 0){MORE}"
            ),
        ),
        // UnknownArgument, with clap's suggestion.
        (
            vec![
                "check",
                "exercises/4.1.json",
                "--tolerence",
                "1",
                "--lang",
                "pt",
            ],
            format!(
                "erro: argumento inesperado '--tolerence'\n\n  dica: há um argumento parecido: \
                 '--tolerance'{MORE}"
            ),
        ),
        // MissingRequiredArgument.
        (
            vec!["render", "scenes/4.3.json", "--lang", "pt"],
            format!("erro: faltam os argumentos obrigatórios:\n  --output <PATH>{MORE}"),
        ),
        // ArgumentConflict: with one flag, with several, and a flag given twice.
        (
            vec![
                "check",
                "exercises/4.1.json",
                "--slips",
                "--answer",
                "0",
                "--lang",
                "pt",
            ],
            format!("erro: o argumento '--slips' não pode ser usado com '--answer <ANSWER>'{MORE}"),
        ),
        (
            vec![
                "check",
                "exercises/4.1.json",
                "--slips",
                "--format",
                "json",
                "--answer",
                "0",
                "--lang",
                "pt",
            ],
            format!(
                "erro: o argumento '--slips' não pode ser usado com:\n  --format <FORMAT>\n  \
                 --answer <ANSWER>{MORE}"
            ),
        ),
        (
            vec![
                "check",
                "exercises/4.1.json",
                "--answer",
                "0",
                "--answer",
                "1",
                "--lang",
                "pt",
            ],
            format!(
                "erro: o argumento '--answer <ANSWER>' não pode ser usado mais de uma vez{MORE}"
            ),
        ),
        // A whole number outside the range of one of clap's own parsers (`new --count`: 1 to
        // 10000), and not a whole number at all.
        (
            vec!["new", "--count", "0", "--lang", "pt"],
            format!(
                "erro: valor inválido '0' para '--count <COUNT>': 0 está fora do intervalo de 1 \
                 a 10000{MORE}"
            ),
        ),
        (
            vec!["new", "--count", "abc", "--lang", "pt"],
            format!(
                "erro: valor inválido 'abc' para '--count <COUNT>': há um caractere que não é \
                 um algarismo: dê um número inteiro{MORE}"
            ),
        ),
        // InvalidSubcommand, with clap's suggestions.
        (
            vec!["chek", "--lang", "pt"],
            format!(
                "erro: subcomando desconhecido 'chek'\n\n  dica: há subcomandos parecidos: \
                 'schema', 'check'{MORE}"
            ),
        ),
    ];
    for (args, expected) in cases {
        let (code, stdout, stderr) = phong_with_locale("C", &args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert_eq!(stdout, "", "{args:?}");
        assert_eq!(stderr, expected, "{args:?}");
        for english in ["error", "invalid", "tip:", "Usage", "argument '", "found"] {
            assert!(
                !stderr.contains(english),
                "{args:?}: {english:?} in {stderr}"
            );
        }
    }
}

/// Issue 27: without `--lang`, a Portuguese locale gives Portuguese and any other English
/// (clap's own text, untouched); `--lang en` overrides a Portuguese locale. The help follows
/// the locale as well.
#[test]
fn the_locale_chooses_the_language_and_lang_overrides_it() {
    let args = ["check", "exercises/4.1.json", "--tolerence", "1"];
    let english = "error: unexpected argument '--tolerence' found\n\n  tip: a similar argument \
                   exists: '--tolerance'\n\nUsage: phong check --tolerance <T> <FILE>...\n\nFor \
                   more information, try '--help'.\n";
    let portuguese = "erro: argumento inesperado '--tolerence'\n\n  dica: há um argumento \
                      parecido: '--tolerance'\n\nPara mais informações, tente '--help'.\n";
    let (code, _, stderr) = phong_with_locale("pt_BR.UTF-8", &args);
    assert_eq!((code, stderr.as_str()), (2, portuguese));
    let (code, _, stderr) = phong_with_locale("C", &args);
    assert_eq!((code, stderr.as_str()), (2, english));
    let with_en = [&args[..], &["--lang", "en"]].concat();
    let (code, _, stderr) = phong_with_locale("pt_BR.UTF-8", &with_en);
    assert_eq!((code, stderr.as_str()), (2, english));

    // A command's own error follows the locale too.
    let render = ["render", "scenes/4.3.json", "-o", "x.jpg"];
    let (code, _, stderr) = phong_with_locale("pt_BR.UTF-8", &render);
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "erro: --output: x.jpg não termina em .png ou .ppm. Correção: dê à imagem um nome *.png \
         ou *.ppm, ou dê --image-format png|ppm\n"
    );
    let (_, _, stderr) = phong_with_locale("C", &render);
    assert_eq!(
        stderr,
        "error: --output: x.jpg does not end in .png or .ppm. Fix: name the image *.png or \
         *.ppm, or give --image-format png|ppm\n"
    );
    let (_, _, stderr) =
        phong_with_locale("pt_BR.UTF-8", &[&render[..], &["--lang", "en"]].concat());
    assert!(
        stderr.starts_with("error: --output: x.jpg does not end"),
        "{stderr}"
    );

    // The help follows the locale too (tests/integration/help.rs: every help in both).
    let (code, help_pt, _) = phong_with_locale("pt_BR.UTF-8", &["check", "--help"]);
    let (_, help_c, _) = phong_with_locale("C", &["check", "--help"]);
    assert_eq!(code, 0);
    assert!(help_pt.starts_with("Confere uma resposta"), "{help_pt}");
    assert!(help_c.starts_with("Check an answer"), "{help_c}");
}

/// Issue 27: the command line's own errors (flags that do not go together, a flag's value
/// refused after parsing, output that cannot be written, a folder that is not one) are typed
/// values said wholly in Portuguese.
#[test]
fn command_line_errors_are_said_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("file");
    std::fs::write(&file, "x").unwrap();
    let file = file.to_str().unwrap().to_owned();
    let inside = format!("{file}/x.txt");
    let input = dir.path().join("input.json");
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.1.json"),
        &input,
    )
    .unwrap();
    let input = input.to_str().unwrap().to_owned();
    let cases: Vec<(Vec<&str>, String)> =
        vec![
        (
            vec!["check", "exercises/4.1.json", "exercises/4.2.json", "--answer", "0"],
            "erro: --answer confere um arquivo, e 2 foram dados. Correção: confira um arquivo \
             por vez, ou ponha a resposta de cada arquivo em seu campo \"answer\" e tire --answer"
                .into(),
        ),
        (
            vec!["solve", "exercises/4.1.json", "--fragment"],
            "erro: --fragment vale só para --format latex e html. Correção: tire --fragment, ou \
             use --format latex ou html"
                .into(),
        ),
        (
            vec!["solve", &input, "-o", &input],
            format!(
                "erro: --output {input} é a entrada {input}: escrever nele substituiria o que \
                 está sendo lido. Correção: dê outro arquivo a --output"
            ),
        ),
        // 4.3's camera is 320×240: pixels 0 to 319 across, 0 to 239 down.
        (
            vec!["render", "scenes/4.3.json", "--explain-pixel", "5000,5000"],
            "erro: --explain-pixel: o pixel 5000,5000 está fora da imagem 320×240. Correção: dê \
             X de 0 a 319 e Y de 0 a 239"
                .into(),
        ),
        (
            vec!["grade", "x.csv", "--exercises", "README.md"],
            "erro: README.md: --exercises: não é uma pasta. Correção: dê a pasta que tem os \
             arquivos dos exercícios (o exercício 4.2 é DIR/4.2.json)"
                .into(),
        ),
        (
            vec!["grade", "x.csv", "--exercises", "exercises", "--rubric", &inside],
            format!(
                "erro: --policy {inside}: não é possível ler a política do curso: não é uma pasta \
                 (erro 20 do sistema). Correção: dê a --policy o caminho de um arquivo de política \
                 do curso (`phong policy > course-policy.json` escreve um com todos os campos)"
            ),
        ),
        (
            vec!["check", "exercises/4.1.json", "--steps", &inside],
            format!(
                "erro: --steps: {inside}: não é possível ler o arquivo: não é uma pasta (erro 20 \
                 do sistema). Correção: confira o caminho, e que o arquivo existe e é texto UTF-8"
            ),
        ),
        (
            vec!["solve", "exercises/4.1.json", "-o", &inside],
            format!("erro: não é possível escrever {inside}: não é uma pasta (erro 20 do sistema)"),
        ),
        (
            vec!["new", "--kind", "ambient", "-o", &file],
            format!(
                "erro: {file}: -o: é um arquivo, não uma pasta. Correção: dê uma pasta para os \
                 arquivos dos problemas (criada se faltar), ou - para mostrá-los"
            ),
        ),
        // `tradeoff` and `export-pov` have no --lang: the locale decides.
        (
            vec!["tradeoff", "scenes/4.3.json", "--plot", "x.png"],
            "erro: --plot: x.png não termina em .svg. Correção: dê ao gráfico um nome *.svg (ele \
             é escrito em SVG)"
                .into(),
        ),
        (
            vec!["export-pov", "scenes/4.3.json", "--samples", "4"],
            "erro: scenes/4.3.json: render.samples: não pode ser expresso em POV-Ray 3.7: phong \
             faz a média de 4 amostras estratificadas por pixel, e o anti-aliasing do POV-Ray \
             amostra de outro modo. Correção: exporte com --samples 1 (o POV-Ray então traça o \
             centro de cada pixel, como phong faz)"
                .into(),
        ),
    ];
    for (args, expected) in cases {
        let (code, _, stderr) = phong_with_locale("pt_BR.UTF-8", &args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert_eq!(stderr, format!("{expected}\n"), "{args:?}");
        for english in [
            " the ", " is ", " cannot ", "Fix:", "error", " and ", " give ",
        ] {
            assert!(
                !stderr.contains(english),
                "{args:?}: {english:?} in {stderr}"
            );
        }
    }
    // Nothing was written over the input, nor into the file taken for a folder.
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "x");
}
