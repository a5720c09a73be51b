//! `phong check` under `--lang pt` (or a Portuguese locale): an answer, a step or an answer key
//! that cannot be read is said in Portuguese throughout, composed from typed values (issue 27),
//! and the English stays as it was.

use crate::support;

use std::path::Path;

fn exercise(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("exercises")
        .join(name)
        .display()
        .to_string()
}

/// Runs `phong ARGS` with the locale `lang` (`LC_ALL`, `LANG`): exit code and standard error.
fn run(args: &[&str], locale: &str) -> (i32, String) {
    let out = support::phong()
        .env_remove("LC_MESSAGES")
        .env("LC_ALL", locale)
        .env("LANG", locale)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// English words that a Portuguese sentence never holds (outside quotes, where a user's text
/// and a file's field names stand).
const ENGLISH: &[&str] = &[
    "the", "is", "are", "and", "not", "give", "write", "Fix", "of", "or", "when", "such", "has",
    "no", "error", "missing", "number", "numbers", "light",
];

/// `text` without what stands between double quotes.
fn outside_quotes(text: &str) -> String {
    let mut inside = false;
    text.chars()
        .filter(|&c| {
            if c == '"' {
                inside = !inside;
            }
            !inside && c != '"'
        })
        .collect()
}

fn assert_portuguese(stderr: &str) {
    let words = outside_quotes(stderr);
    let english: Vec<&str> = words
        .split(|c: char| !c.is_alphanumeric() && c != '_')
        .filter(|w| ENGLISH.contains(w))
        .collect();
    assert!(english.is_empty(), "English {english:?} in {stderr:?}");
}

const FORMS_PT: &str = "escreva três números como \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" ou \
                        \"[0.52; 0.03; 0]\", três inteiros 0–255 com --scale 255, \"#RRGGBB\", ou \
                        \"nenhuma\" quando o raio não atinge nada";

#[test]
fn an_answer_that_cannot_be_read_is_portuguese_throughout() {
    let file = exercise("4.2.json");
    let (code, err) = run(
        &["check", &file, "--answer", "0,5 abc 1", "--lang", "pt"],
        "C",
    );
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!("erro: {file}: --answer: \"abc\" em \"0,5 abc 1\" não é um número: {FORMS_PT}\n")
    );
    assert_portuguese(&err);
    for (answer, what) in [
        ("", "a resposta está vazia".to_owned()),
        ("0.5 0.5", "\"0.5 0.5\" não são três números".to_owned()),
        (
            "0 −1",
            "\"0 −1\" não são três números (tem um sinal de menos ou travessão Unicode (−, –): \
             escreva o menos como o hífen ASCII -)"
                .to_owned(),
        ),
    ] {
        let (code, err) = run(&["check", &file, "--answer", answer, "--lang", "pt"], "C");
        assert_eq!(code, 2, "{answer}");
        assert!(
            err.starts_with(&format!("erro: {file}: --answer: {what}")),
            "{err}"
        );
        assert!(err.ends_with(&format!(": {FORMS_PT}\n")), "{err}");
        assert_portuguese(&err);
    }
    let (_, err) = run(
        &[
            "check", &file, "--answer", "300 1 1", "--scale", "255", "--lang", "pt",
        ],
        "C",
    );
    assert_eq!(
        err,
        format!(
            "erro: {file}: --answer: \"300 1 1\" não são três inteiros 0–255, como --scale 255 \
             espera: dê valores de 8 bits, ou tire --scale para componentes em [0, 1]\n"
        )
    );
    assert_portuguese(&err);
}

#[test]
fn the_locale_chooses_portuguese_and_lang_en_keeps_the_english() {
    let file = exercise("4.2.json");
    let (code, err) = run(&["check", &file, "--answer", "0,5 abc 1"], "pt_BR.UTF-8");
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!("erro: {file}: --answer: \"abc\" em \"0,5 abc 1\" não é um número: {FORMS_PT}\n")
    );
    let (_, err) = run(
        &["check", &file, "--answer", "0,5 abc 1", "--lang", "en"],
        "pt_BR.UTF-8",
    );
    assert_eq!(
        err,
        format!(
            "error: {file}: --answer: \"abc\" in \"0,5 abc 1\" is not a number: write three \
             numbers such as \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \"[0.52; 0.03; 0]\", three \
             integers 0–255 with --scale 255, \"#RRGGBB\", or \"none\" when the ray hits nothing\n"
        )
    );
}

#[test]
fn an_answer_key_that_cannot_be_read_or_is_missing_is_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(exercise("4.2.json")).unwrap();
    let scaled = dir.path().join("scaled.json");
    std::fs::write(
        &scaled,
        text.replace(
            "\"answer\": [0, 0, 0]",
            "\"answer\": {\"color\": [1, 2, 3], \"scale\": 100}",
        ),
    )
    .unwrap();
    let keyless = dir.path().join("keyless.json");
    std::fs::write(&keyless, text.replace(",\n  \"answer\": [0, 0, 0]", "")).unwrap();
    let scaled = scaled.display().to_string();
    let (code, err) = run(&["check", &scaled, "--lang", "pt"], "C");
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!(
            "erro: {scaled}: answer.scale: 100 não é uma escala: use 1 (componentes em [0, 1]) \
             ou 255 (8 bits)\n"
        )
    );
    assert_portuguese(&err);
    let keyless = keyless.display().to_string();
    let (code, err) = run(&["check", &keyless, "--lang", "pt"], "C");
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!(
            "erro: {keyless}: answer: ausente: o arquivo não tem gabarito para conferir. \
             Correção: passe --answer \"r g b\", ou acrescente \"answer\": [r, g, b] ao arquivo\n"
        )
    );
    assert_portuguese(&err);
}

#[test]
fn a_step_that_cannot_be_read_or_judged_is_portuguese() {
    let file = exercise("4.2.json");
    // One point light, lights[0]: there is no lights[3].
    let (code, err) = run(
        &["check", &file, "--step", "cos_theta[3]=1", "--lang", "pt"],
        "C",
    );
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!(
            "erro: {file}: --step: cos_theta[3]: não há lights[3]: o arquivo tem 1 fonte de luz, \
             a partir de lights[0]. Correção: use cos_theta[0] ou cos_theta\n"
        )
    );
    assert_portuguese(&err);
    let (code, err) = run(&["check", &file, "--step", "foo=1", "--lang", "pt"], "C");
    assert_eq!(code, 2);
    assert!(
        err.starts_with(&format!(
            "erro: {file}: --step: \"foo\" não é o nome de um passo. Correção: use um de t, P, N,"
        )),
        "{err}"
    );
    assert!(
        err.ends_with(" (os passos de uma fonte de luz com [i], como cos_theta[1])\n"),
        "{err}"
    );
    let dir = tempfile::tempdir().unwrap();
    let steps = dir.path().join("steps.json");
    std::fs::write(&steps, r#"{"cos_theta": "sim"}"#).unwrap();
    let steps = steps.display().to_string();
    let (code, err) = run(&["check", &file, "--steps", &steps, "--lang", "pt"], "C");
    assert_eq!(code, 2);
    assert_eq!(
        err,
        format!(
            "erro: --steps: {steps}: \"cos_theta\": \"sim\" não é um valor para cos_theta: \
             escreva um número, como 0.98995 ou 3/5. Correção: um objeto JSON de nomes e valores, \
             como {{\"cos_theta\": 0.98995}}\n"
        )
    );
}

/// `phong ARGS --lang pt`: exit code and standard output.
fn out_pt(args: &[&str]) -> (i32, String) {
    let out = support::phong()
        .args(args)
        .args(["--lang", "pt"])
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

// Issue 28, item 4, in Portuguese. 4.3's ray meets its plane at t = −90 (18 + 0.2 t = 0):
// the reversed ray's hit is at t = +90 (the likely intended reading), and black is the background of a ray that hits
// nothing, whose answer is "nenhuma".
#[test]
fn black_and_the_reversed_ray_are_said_in_portuguese() {
    let e = exercise("4.3.json");
    let (code, out) = out_pt(&["check", &e, "--answer", "0 0 0"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains(": errada\n"), "{out}");
    assert!(
        out.contains(
            "\n  preto é o fundo, a cor vista por um raio que não encontra nada: como enunciado \
             o raio não atinge nada (t > 0), então não há cor a dar, e a resposta é \
             \"nenhuma\" (nenhuma interseção)\n"
        ),
        "{out}"
    );
    assert!(
        !out.contains("ambiente") && !out.contains("mais perto"),
        "{out}"
    );
    // The reversed ray is the likely intended reading: its t = 90 is right in it.
    let (code, out) = out_pt(&["check", &e, "--step", "t=90"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains(
            "nessa leitura o raio é invertido (O − tD): ele encontra a superfície em t = 90 ao \
             longo de −D, que é t = -90 ao longo de D"
        ),
        "{out}"
    );
    assert!(!out.contains("t < 0"), "{out}");
}

// A near miss of 4.3's likely intended reading, (0.523920, 0.027337, 0) by hand (see
// tests/check_fixsteps.rs): (0.53, 0.03, 0) is 0.00608 off, just outside ±0.005.
#[test]
fn a_near_miss_names_the_reading_in_portuguese() {
    let (code, out) = out_pt(&["check", &exercise("4.3.json"), "--answer", "0.53 0.03 0"]);
    assert_eq!(code, 1, "{out}");
    let line = out
        .lines()
        .find(|l| l.starts_with("  perto "))
        .unwrap_or_else(|| panic!("{out}"));
    let rest = line
        .strip_prefix(
            "  perto da leitura provavelmente pretendida \"a interseção da reta atrás da origem \
             do raio\": no máximo ",
        )
        .unwrap_or_else(|| panic!("{line}"));
    let (away, tail) = rest.split_once(' ').unwrap();
    assert!(
        (away.parse::<f64>().unwrap() - 0.00608).abs() < 1e-5,
        "{line}"
    );
    assert_eq!(tail, "de diferença por canal (tolerância ±0.005)");
}

#[test]
fn a_course_policy_that_is_not_an_object_is_said_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    let policy = dir.path().join("politica.json");
    std::fs::write(&policy, "[]").unwrap();
    let policy = policy.display().to_string();
    let (code, stderr) = run(
        &[
            "check",
            &exercise("4.1.json"),
            "--answer",
            "0.5 0.7 0.3",
            "--policy",
            &policy,
        ],
        "pt_BR.UTF-8",
    );
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.starts_with(&format!(
            "erro: --policy {policy}: o arquivo é uma lista [ … ], e uma política do curso é um \
             objeto JSON {{ … }}"
        )),
        "{stderr}"
    );
    // `phong policy` in the example is a command, as written; the file's name is the user's.
    assert_portuguese(
        &stderr
            .replace(&policy, " ")
            .replace("`phong policy`", " ")
            .replace("phong policy", " "),
    );
}
