//! Validation's errors (problem/validate.rs, problem/faults.rs) under `--lang pt` and a
//! Brazilian locale: each written wholly in Portuguese, with the light's kind in its label
//! (`lights[0] (pontual)`) and the numbers of the file; in English, as before.

use crate::support;

use serde_json::{json, Value};

/// Runs phong in a folder holding `bad.json` (the problem `problem`), with `args` (`FILE` stands
/// for the problem) and the environment `env`: the exit code and standard error.
fn run(problem: &Value, args: &[&str], env: &[(&str, &str)]) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.json"), problem.to_string()).unwrap();
    let mut cmd = support::phong();
    cmd.current_dir(dir.path())
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C");
    for (k, v) in env {
        cmd.env(k, v);
    }
    let args: Vec<&str> = args
        .iter()
        .map(|a| if *a == "FILE" { "bad.json" } else { a })
        .collect();
    let out = cmd.args(&args).output().unwrap();
    assert!(!dir.path().join("out.png").exists(), "an image was written");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// English words that no Portuguese message of validation holds outside quotes.
const ENGLISH: &[&str] = &[
    "the",
    "is",
    "are",
    "of",
    "and",
    "give",
    "add",
    "missing",
    "needs",
    "need",
    "light",
    "lights",
    "has",
    "no",
    "remove",
    "takes",
    "it",
    "fix",
    "more",
    "than",
    "rays",
    "samples",
    "not",
    "to",
    "or",
    "with",
    "for",
    "its",
    "in",
    "at",
    "named",
    "negative",
    "positive",
    "degrees",
    "field",
    "view",
    "vector",
    "level",
    "weight",
    "tree",
    "which",
    "must",
    "one",
    "define",
    "Português",
];

/// The prose of a message: without what stands between quotes or backticks (a field's name,
/// an example), the file's name, and the field or flag before a colon (`lights[0].exponent:`,
/// `--max-level:`).
fn prose(message: &str) -> String {
    let mut out = String::new();
    let mut quote: Option<char> = None;
    for c in message.replace("bad.json", " ").chars() {
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
                    .all(|c| c.is_ascii_alphanumeric() || "_.[]:-".contains(c)))
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The English words of [`ENGLISH`] in `message`, but for the light labels' `lights[i]`.
fn english_in(message: &str) -> Vec<String> {
    prose(&message.replace("lights[", "["))
        .split(|c: char| !c.is_alphabetic())
        .filter(|w| ENGLISH.iter().any(|e| e.eq_ignore_ascii_case(w)))
        .map(str::to_owned)
        .collect()
}

/// A point problem lit by `light`, with a full material.
fn point_problem(light: Value, point: Value) -> Value {
    json!({
        "materials": {
            "M": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5],
                   "specular": [0.2, 0.2, 0.2], "shininess": 2 }
        },
        "lights": [light],
        "point": point,
    })
}

/// A one-sphere scene of `material`, with `render` settings and a camera of `width`×`height`.
fn scene(material: Value, render: Value, (width, height): (u32, u32)) -> Value {
    json!({
        "lights": [{ "type": "point", "position": [0, 5, 5], "color": [1, 1, 1], "falloff": 0 }],
        "surfaces": [{ "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": material }],
        "camera": { "eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45,
                    "width": width, "height": height },
        "render": render,
    })
}

/// A material whose every term is given.
fn matte() -> Value {
    json!({ "ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5],
            "specular": [0.2, 0.2, 0.2], "shininess": 2 })
}

/// The bad problems: each with its command, and what its Portuguese error must say.
fn cases() -> Vec<(
    &'static str,
    Value,
    &'static [&'static str],
    Vec<&'static str>,
)> {
    let point_light = json!({ "type": "point", "position": [1, 1, 1], "color": [1, 1, 1],
                              "falloff": 0 });
    let solve: &'static [&'static str] = &["solve", "FILE"];
    let render: &'static [&'static str] = &["render", "FILE", "-o", "out.png"];
    let mut glass = matte();
    glass["transmissivity"] = json!([0.9, 0.9, 0.9]);
    let mut bad_ior = glass.clone();
    bad_ior["ior"] = json!(-1.5);
    // O_r = O_t = 1: every hit spawns two rays of weight 1, so with a minimum weight of 0 a
    // tree of 21 levels holds 1 + 2 + … + 2^20 = 2^21 − 1 = 2097151 rays, past 2^20.
    let mut mirror_glass = matte();
    mirror_glass["reflectivity"] = json!([1, 1, 1]);
    mirror_glass["transmissivity"] = json!([1, 1, 1]);
    mirror_glass["ior"] = json!(1.5);
    vec![
        (
            "a light that needs P",
            point_problem(
                point_light.clone(),
                json!({ "normal": [0, 0, 1], "material": "M" }),
            ),
            solve,
            vec!["point.position: ausente: lights[0] (pontual) precisa de P para L e d (Eq. 4.1)"],
        ),
        (
            "a light that needs N",
            point_problem(
                json!({ "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] }),
                json!({ "position": [0, 0, 0], "material": "M" }),
            ),
            solve,
            vec![
                "point.normal: ausente: lights[0] (direcional) precisa de N para cos θ = −N·L",
                "Correção: acrescente \"normal\": [x, y, z] a \"point\"",
            ],
        ),
        (
            "a field a point light does not take",
            point_problem(
                json!({ "type": "point", "position": [1, 1, 1], "color": [1, 1, 1],
                        "falloff": 0, "angle": 30 }),
                json!({ "position": [0, 0, 0], "normal": [0, 0, 1], "material": "M" }),
            ),
            solve,
            vec![
                "lights[0].angle: uma luz pontual não tem \"angle\"",
                "Correção: remova-o; uma luz pontual aceita \"position\", \"color\", \"falloff\"",
            ],
        ),
        (
            "a spot light without its exponent",
            point_problem(
                json!({ "type": "spot", "position": [1, 1, 1], "axis": [0, 0, -1],
                        "angle": 30, "color": [1, 1, 1], "falloff": 0 }),
                json!({ "position": [0, 0, 0], "normal": [0, 0, 1], "material": "M" }),
            ),
            solve,
            vec![
                "lights[0].exponent: ausente: uma luz spot precisa de \"exponent\": dá o \
                 expoente e do spot em cos(ψ)^e (Eq. 4.4)",
                "Correção: acrescente \"exponent\"",
            ],
        ),
        (
            "a zero normal",
            point_problem(
                point_light.clone(),
                json!({ "position": [0, 0, 0], "normal": [0, 0, 0], "material": "M" }),
            ),
            solve,
            vec![
                "a normal N é o vetor nulo (em f64), que não tem direção. Correção: dê um vetor \
                  não nulo",
            ],
        ),
        (
            "a material no one defined",
            point_problem(
                point_light.clone(),
                json!({ "position": [0, 0, 0], "normal": [0, 0, 1], "material": "vidro" }),
            ),
            solve,
            vec![
                "point.material: não há material chamado \"vidro\"",
                "Correção: use um de \"M\", ou defina-o em \"materials\"",
            ],
        ),
        (
            "a sphere with a normal",
            {
                let mut s = scene(matte(), json!({}), (4, 3));
                s["surfaces"][0]["normal"] = json!([0, 0, 1]);
                s
            },
            render,
            vec![
                "surfaces[0].normal: uma esfera não tem \"normal\"",
                "remova-o; uma esfera aceita",
            ],
        ),
        (
            "a transmissivity without its index",
            scene(glass, json!({}), (4, 3)),
            render,
            vec!["surfaces[0].material.ior: falta, e o material tem uma transmissividade"],
        ),
        (
            "a negative index",
            scene(bad_ior, json!({}), (4, 3)),
            render,
            vec!["-1.5 não é um número positivo. Correção: um índice de refração é > 0"],
        ),
        (
            "a tree too large",
            scene(
                mirror_glass,
                json!({ "max_level": 21, "min_weight": 0 }),
                (4, 3),
            ),
            render,
            vec![
                "render.max_level: o nível máximo 21 com o peso mínimo 0 deixa a árvore de raios \
                 de uma amostra ter 2097151 raios",
                "mais que os 1048576 (2^20)",
            ],
        ),
        (
            "a tree too large for the command line's settings",
            {
                let mut m = matte();
                m["reflectivity"] = json!([1, 1, 1]);
                m["transmissivity"] = json!([1, 1, 1]);
                m["ior"] = json!(1.5);
                scene(m, json!({}), (4, 3))
            },
            &[
                "render",
                "FILE",
                "-o",
                "out.png",
                "--max-level",
                "21",
                "--min-weight",
                "0",
            ],
            vec![
                "--max-level: o nível máximo 21 com o peso mínimo 0 deixa a árvore de raios de \
                 uma amostra ter 2097151 raios",
            ],
        ),
        (
            "too many samples",
            // 1000 × 1000 × 2000 = 2·10^9 primary rays, past 2^30 = 1073741824; at this size
            // 2^30 / 10^6 = 1073.7…: 1073 samples fit.
            scene(matte(), json!({ "samples": 2000 }), (1000, 1000)),
            render,
            vec![
                "render.samples: 1000×1000 pixels × 2000 amostras são 2000000000 raios primários",
                "Correção: dê até 1073 amostras por pixel neste tamanho, ou uma imagem menor",
            ],
        ),
        (
            "a triangle too large for the ray–triangle test",
            {
                let mut s = scene(matte(), json!({}), (4, 3));
                s["surfaces"][0] = json!({ "type": "triangle",
                    "vertices": [[-1e300, -1e300, 0], [1e300, -1e300, 0], [0, 1e300, 0]],
                    "material": matte() });
                s
            },
            render,
            vec![
                "surfaces[0].vertices[0][0]: -1e300 é grande demais para um vértice de \
                 triângulo em f64",
                "Correção: dê coordenadas dentro de ±1e100 (reduza a escala da cena)",
            ],
        ),
        (
            "a camera too far for the intersection tests",
            {
                let mut s = scene(matte(), json!({}), (4, 3));
                s["camera"]["eye"] = json!([0, 0, 1e200]);
                s
            },
            render,
            vec![
                "camera.eye[2]: 1e200 é grande demais para o olho da câmera em f64: os testes \
                 de interseção multiplicam coordenadas",
                "Correção: dê coordenadas dentro de ±1e100 (reduza a escala da cena)",
            ],
        ),
        (
            "a sphere too large for the ray–sphere test",
            {
                let mut s = scene(matte(), json!({}), (4, 3));
                s["surfaces"][0] = json!({ "type": "sphere", "center": [0, 0, 0],
                    "radius": 1e200, "material": matte() });
                s
            },
            render,
            vec![
                "surfaces[0].radius: 1e200 é grande demais para o raio de uma esfera em f64",
                "Correção: dê um raio de até 1e100 (reduza a escala da cena)",
            ],
        ),
        (
            "a field of view of 0",
            {
                let mut s = scene(matte(), json!({}), (4, 3));
                s["camera"]["fov"] = json!(0);
                s
            },
            render,
            vec!["camera.fov: 0 graus não é um campo de visão"],
        ),
    ]
}

#[test]
fn validations_errors_are_wholly_portuguese() {
    let mut failures = Vec::new();
    for (name, problem, args, wanted) in cases() {
        let mut args = args.to_vec();
        args.extend(["--lang", "pt"]);
        let (code, stderr) = run(&problem, &args, &[]);
        if code != 2 {
            failures.push(format!("{name}: exit {code}: {stderr}"));
            continue;
        }
        for w in wanted {
            if !stderr.contains(w) {
                failures.push(format!("{name}: no {w:?} in {stderr}"));
            }
        }
        let found = english_in(&stderr);
        if !found.is_empty() {
            failures.push(format!("{name}: English {found:?} in {stderr}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_brazilian_locale_reads_validation_in_portuguese() {
    // No --lang: the locale decides.
    let problem = point_problem(
        json!({ "type": "spot", "position": [1, 1, 1], "axis": [0, 0, -1], "angle": 30,
                "color": [1, 1, 1], "falloff": 0, "exponent": 1 }),
        json!({ "normal": [0, 0, 1], "material": "M" }),
    );
    let (code, stderr) = run(&problem, &["solve", "FILE"], &[("LANG", "pt_BR.UTF-8")]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("ausente: lights[0] (spot) precisa de P para L e d (Eq. 4.1)"),
        "{stderr}"
    );
    assert!(english_in(&stderr).is_empty(), "{stderr}");
    // The same file with --lang en: the English of before.
    let (_, stderr) = run(
        &problem,
        &["solve", "FILE", "--lang", "en"],
        &[("LANG", "pt_BR.UTF-8")],
    );
    assert!(
        stderr.contains(
            "point.position: missing: lights[0] (spot) needs P for L and d (Eq. 4.1). Fix: add \
             \"position\": [x, y, z] to \"point\""
        ),
        "{stderr}"
    );
}

#[test]
fn validations_errors_in_english_are_as_before() {
    // The English of each case, whole, as phong wrote it before its messages were typed.
    let mut glass = matte();
    glass["ior"] = json!(1.5);
    let (_, stderr) = run(
        &scene(glass, json!({}), (4, 3)),
        &["render", "FILE", "-o", "out.png"],
        &[],
    );
    assert!(
        stderr.contains(
            "bad.json: surfaces[0].material.transmissivity: is missing, and the material has an \
             index of refraction. Fix: give the transmissivity O_t as [r, g, b] (e.g. [0.9, 0.9, \
             0.9]), or remove \"ior\": without O_t no ray is transmitted"
        ) && !stderr.contains("Português"),
        "{stderr}"
    );
    let (_, stderr) = run(
        &point_problem(
            json!({ "type": "ambient", "color": [1, 1, 1], "falloff": 1 }),
            json!({ "material": "M" }),
        ),
        &["solve", "FILE"],
        &[],
    );
    assert!(
        stderr.contains(
            "lights[0].falloff: a ambient light has no \"falloff\". Fix: remove it; a ambient \
             light takes \"color\""
        ),
        "{stderr}"
    );
}

/// A number below the smallest f64 above 0, read as 0, is said as the file writes it, why it
/// was read as 0 and what its 0 gave, wholly in Portuguese (a JSON value cannot hold 1e-330:
/// the file is written as text).
#[test]
fn a_number_read_as_zero_is_said_as_written_in_portuguese() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = scene(matte(), json!({}), (4, 3));
    s["camera"]["fov"] = json!(45.5);
    let text = s.to_string().replace("45.5", "1e-330");
    assert!(text.contains("1e-330"), "{text}");
    std::fs::write(dir.path().join("bad.json"), text).unwrap();
    let out = support::phong()
        .current_dir(dir.path())
        .args(["render", "bad.json", "-o", "out.png", "--lang", "pt"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(
            "camera.fov: 1e-330 é pequeno demais para ser representado (o menor número acima de \
             0 é cerca de 4.9e-324), e é lido como 0: 0 graus não é um campo de visão. \
             Correção: dê o campo de visão vertical em graus"
        ),
        "{stderr}"
    );
    assert!(english_in(&stderr).is_empty(), "{stderr}");
    assert!(!dir.path().join("out.png").exists());
}
