//! `phong moodle`: the quiz is well formed XML (roxmltree, and xmllint in a test of its own,
//! ignored unless its program is asked for), every question passes a validator
//! written here from the Cloze grammar and Moodle's import rules (the course's platform notes,
//! read from `question/format/xml/format.php` and `question/type/multianswer/questiontype.php`),
//! the validator rejects Moodle's own broken cases, and every answer option, checked with
//! `phong check`, gets the verdict and the slip its feedback names.

use crate::support;

use std::path::{Path, PathBuf};

use crate::support::phong;
use serde_json::Value;

/// The fractions Moodle's importer accepts (and their negatives).
const GRADES: [f64; 21] = [
    100.0, 90.0, 83.33333, 80.0, 75.0, 70.0, 66.66667, 60.0, 50.0, 40.0, 33.33333, 30.0, 25.0,
    20.0, 16.66667, 14.28571, 12.5, 11.11111, 10.0, 5.0, 0.0,
];

const TYPES: [&str; 18] = [
    "NUMERICAL",
    "NM",
    "MULTICHOICE",
    "MC",
    "MULTICHOICE_V",
    "MCV",
    "MULTICHOICE_H",
    "MCH",
    "MULTICHOICE_S",
    "MCS",
    "MULTICHOICE_VS",
    "MCVS",
    "MULTICHOICE_HS",
    "MCHS",
    "SHORTANSWER",
    "SA",
    "SHORTANSWER_C",
    "SAC",
];

/// One alternative of a sub-question, unescaped.
#[derive(Debug, Clone)]
struct Alt {
    fraction: f64,
    answer: String,
    tolerance: Option<f64>,
    feedback: String,
}

#[derive(Debug, Clone)]
struct Sub {
    /// Its weight: Moodle's importer reads an empty weight (or 0) as 1, and makes the
    /// question's mark the sum of its parts' weights.
    weight: u64,
    kind: String,
    alts: Vec<Alt>,
}

/// Splits `s` at `sep` not preceded by a backslash.
fn split_unescaped(s: &str, sep: char) -> Vec<String> {
    let mut parts = vec![String::new()];
    let mut prev = '\0';
    for c in s.chars() {
        if c == sep && prev != '\\' {
            parts.push(String::new());
        } else {
            parts.last_mut().unwrap().push(c);
        }
        prev = c;
    }
    parts
}

fn unescape(s: &str) -> String {
    s.replace("\\}", "}").replace("\\#", "#")
}

fn html_text(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&#126;", "~")
        .replace("&#92;", "\\")
        .replace("&amp;", "&")
}

/// The grammar's `number`: "-"? ( [0-9]+ [.,]? [0-9]* | [.,] [0-9]+ ) ( [eE] [-+]? [0-9]+ )?
fn is_number(s: &str) -> bool {
    let s = s.strip_prefix('-').unwrap_or(s);
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], Some(&s[i + 1..])),
        None => (s, None),
    };
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let ok_mantissa = match mantissa.find(['.', ',']) {
        Some(i) => {
            let (a, b) = (&mantissa[..i], &mantissa[i + 1..]);
            (digits(a) && (b.is_empty() || digits(b))) || (a.is_empty() && digits(b))
        }
        None => digits(mantissa),
    };
    let ok_exponent = exponent.is_none_or(|e| digits(e.strip_prefix(['-', '+']).unwrap_or(e)));
    ok_mantissa && ok_exponent
}

/// One alternative: [fraction] answer [# feedback].
fn alternative(text: &str, numerical: bool) -> Result<Alt, String> {
    let (fraction, rest) = if let Some(r) = text.strip_prefix('=') {
        (100.0, r)
    } else if let Some(r) = text.strip_prefix('%') {
        let end = r
            .find('%')
            .ok_or(format!("unclosed fraction in {text:?}"))?;
        let f: f64 = r[..end]
            .replace(',', ".")
            .parse()
            .map_err(|_| format!("fraction {:?} is not a number", &r[..end]))?;
        if !GRADES.iter().any(|g| (g - f.abs()).abs() < 1e-9) {
            return Err(format!("fraction {f} is not one of Moodle's grades"));
        }
        (f, &r[end + 1..])
    } else {
        (0.0, text)
    };
    let pieces = split_unescaped(rest, '#');
    if pieces.len() > 2 {
        return Err(format!("an unescaped # in the feedback of {text:?}"));
    }
    let (mut answer, feedback) = (
        pieces[0].clone(),
        pieces.get(1).cloned().unwrap_or_default(),
    );
    if answer.trim().is_empty() {
        return Err(format!("an empty answer in {text:?}"));
    }
    let mut tolerance = None;
    if numerical && answer != "*" {
        if let Some((a, t)) = answer.clone().split_once(':') {
            if !is_number(t) {
                return Err(format!("tolerance {t:?} is not a number"));
            }
            tolerance = Some(t.replace(',', ".").parse().unwrap());
            answer = a.to_owned();
        }
        if !is_number(&answer) {
            return Err(format!("NUMERICAL answer {answer:?} is not a number"));
        }
    }
    Ok(Alt {
        fraction,
        answer: unescape(&answer),
        tolerance,
        feedback: html_text(&unescape(&feedback)),
    })
}

/// The sub-questions of a Cloze question text, or why Moodle would refuse it.
fn cloze(text: &str) -> Result<Vec<Sub>, String> {
    let mut subs = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find('{') {
        let after = &rest[start + 1..];
        // A sub-question is "{" weight ":" TYPE ":" …; other braces are text.
        let Some((weight, tail)) = after.split_once(':') else {
            rest = after;
            continue;
        };
        let Some((kind, body_and_more)) = tail.split_once(':') else {
            rest = after;
            continue;
        };
        if !TYPES.contains(&kind) {
            rest = after;
            continue;
        }
        if !weight.bytes().all(|b| b.is_ascii_digit()) {
            return Err(format!("weight {weight:?} is not an integer"));
        }
        // The body ends at the first "}" not preceded by "\".
        let bytes = body_and_more.as_bytes();
        let end = (0..bytes.len())
            .find(|&i| bytes[i] == b'}' && (i == 0 || bytes[i - 1] != b'\\'))
            .ok_or("an unclosed sub-question")?;
        let body = &body_and_more[..end];
        if body.trim().is_empty() {
            return Err("an empty sub-question".into());
        }
        let numerical = kind == "NUMERICAL" || kind == "NM";
        let alts = split_unescaped(body, '~')
            .iter()
            .map(|a| alternative(a, numerical))
            .collect::<Result<Vec<_>, _>>()?;
        if !alts.iter().any(|a| (a.fraction - 100.0).abs() < 1e-9) {
            return Err("no 100 % answer".into());
        }
        subs.push(Sub {
            weight: weight.parse().ok().filter(|&w| w > 0).unwrap_or(1),
            kind: kind.to_owned(),
            alts,
        });
        rest = &body_and_more[end + 1..];
    }
    if subs.is_empty() {
        return Err("a Cloze question without sub-questions".into());
    }
    Ok(subs)
}

/// The text between `open` and `close` after `from`.
fn between<'a>(s: &'a str, open: &str, close: &str) -> Option<&'a str> {
    let a = s.find(open)? + open.len();
    let b = s[a..].find(close)? + a;
    Some(&s[a..b])
}

fn cdata(s: &str) -> &str {
    s.strip_prefix("<![CDATA[")
        .and_then(|t| t.strip_suffix("]]>"))
        .unwrap_or(s)
}

/// A whole quiz against the import rules: the first line, the root, each question's name and
/// text, each category's path, each picture's file; the Cloze questions' sub-questions.
fn validate(xml: &str) -> Result<Vec<Vec<Sub>>, String> {
    if !xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n") {
        return Err("the XML declaration is not the very first line".into());
    }
    let body = between(xml, "<quiz>", "</quiz>").ok_or("no <quiz> root")?;
    let mut questions = Vec::new();
    let mut categories = 0;
    for q in body.split("<question type=\"").skip(1) {
        let (kind, q) = q.split_once('"').ok_or("a question without a type")?;
        match kind {
            "category" => {
                let path = between(q, "<category><text>", "</text>").ok_or("a bare category")?;
                if !path.starts_with("$course$/top/") {
                    return Err(format!("category {path:?} is not under $course$/top"));
                }
                categories += 1;
            }
            "cloze" | "multianswer" => {
                if categories == 0 {
                    return Err("a question before any category".into());
                }
                let name = between(q, "<name><text>", "</text></name>").ok_or("no name")?;
                if name.trim().is_empty() {
                    return Err("an empty name".into());
                }
                let text = between(q, "<questiontext format=\"html\"><text>", "</text>")
                    .ok_or("no question text")?;
                questions.push(cloze(cdata(text)).map_err(|e| format!("{name}: {e}"))?);
                let feedback =
                    between(q, "<generalfeedback format=\"html\">", "</generalfeedback>")
                        .ok_or("no general feedback")?;
                let html = cdata(between(feedback, "<text>", "</text>").unwrap_or(""));
                // MathJax: \( \) only; a lone $ would be shown as it is.
                if html.contains('$') {
                    return Err(format!("{name}: a $ in the feedback"));
                }
                for reference in html.split("@@PLUGINFILE@@/").skip(1) {
                    let file = reference.split('"').next().unwrap();
                    let tag = format!("<file name=\"{file}\" path=\"/\" encoding=\"base64\">");
                    let data = between(feedback, &tag, "</file>")
                        .ok_or(format!("{name}: {file} is shown but not embedded"))?;
                    let b64 =
                        |c: u8| c.is_ascii_alphanumeric() || c == b'+' || c == b'/' || c == b'=';
                    if data.is_empty() || data.len() % 4 != 0 || !data.bytes().all(b64) {
                        return Err(format!("{name}: {file} is not base64"));
                    }
                }
            }
            other => return Err(format!("an unexpected question type {other:?}")),
        }
    }
    if questions.is_empty() {
        return Err("no questions".into());
    }
    Ok(questions)
}

#[test]
fn the_validator_rejects_moodles_broken_cloze_cases() {
    let ok = "R = {1:NUMERICAL:=0.52:0.005#Correto~%0%0.65:0.005#Faltou o decaimento (Eq. 4.2)~*#Revise R}";
    let subs = cloze(ok).unwrap();
    assert_eq!(subs.len(), 1);
    assert_eq!(subs[0].alts.len(), 3);
    assert_eq!(subs[0].alts[1].answer, "0.65");
    assert_eq!(subs[0].alts[1].tolerance, Some(0.005));
    for (broken, why) in [
        ("{1:NUMERICAL:}", "empty sub-question"),
        ("{1:NUMERICAL:%50%0.5:0.01#half~*#no}", "no 100 %"),
        ("{1:NUMERICAL:=abc:0.01}", "not a number"),
        ("{1:NUMERICAL:=0.5:x}", "not a number"),
        ("{0.5:NUMERICAL:=0.5:0.01}", "not an integer"),
        (
            "{1:NUMERICAL:=0.5:0.01~%33%0.4:0.01}",
            "not one of Moodle's grades",
        ),
        ("{1:SHORTANSWER:=a#x#y}", "unescaped #"),
        ("no sub-question at all", "without sub-questions"),
    ] {
        let e = cloze(broken).expect_err(broken);
        assert!(e.contains(why), "{broken}: {e}");
    }
    // The grades Moodle lists are accepted, negatives too; escaped specials are text.
    assert!(cloze("{2:NUMERICAL:=1:0~%33.33333%2:0~%-50%3:0~*}").is_ok());
    let fb = &cloze("{:SA:=a\\}b#x \\} \\# y}").unwrap()[0].alts[0];
    assert_eq!(
        (fb.answer.as_str(), fb.feedback.as_str()),
        ("a}b", "x } # y")
    );
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn moodle(files: &[PathBuf], lang: &str, stdin: Option<&[u8]>) -> String {
    let mut c = phong();
    c.arg("moodle").args(files).args(["--lang", lang]);
    if let Some(s) = stdin {
        c.write_stdin(s.to_vec());
    }
    let out = c.assert().code(0).get_output().stdout.clone();
    String::from_utf8(out).unwrap()
}

fn new(kind: &str, count: u32, seed: u64, lang: Option<&str>) -> Vec<u8> {
    let mut c = phong();
    let (count, seed) = (count.to_string(), seed.to_string());
    c.args(["new", "--kind", kind]);
    c.args(["--count", &count, "--seed", &seed]);
    if let Some(l) = lang {
        c.args(["--lang", l]);
    }
    c.assert().code(0).get_output().stdout.clone()
}

fn exercises() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("exercises"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
}

/// The kinds `phong new` makes, each piped into `phong moodle` below.
const KINDS: [&str; 7] = [
    "spot",
    "ambient",
    "point",
    "ray-plane",
    "directional",
    "several",
    "sphere",
];

/// The first diagram embedded in 4.2's quiz (in Portuguese), decoded.
fn diagram_svg() -> String {
    let xml = moodle(&[root().join("exercises/4.2.json")], "pt", None);
    let tag = "encoding=\"base64\">";
    let data = between(&xml, tag, "</file>").expect("a diagram");
    String::from_utf8(unbase64(data)).unwrap()
}

/// The quiz of ten problems of `kind` from `phong new --seed 1 --lang pt`, piped in.
fn generated_quiz(kind: &str) -> String {
    let problems = new(kind, 10, 1, Some("pt"));
    moodle(&[PathBuf::from("-")], "pt", Some(&problems))
}

/// Standard base64 decoded (RFC 4648), for the embedded diagrams.
fn unbase64(s: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let mut out = Vec::new();
    for chunk in s.as_bytes().chunks(4) {
        let n = chunk
            .iter()
            .filter(|&&c| c != b'=')
            .enumerate()
            .fold(0u32, |n, (i, &c)| n | u32::from(value(c)) << (18 - 6 * i));
        let bytes = chunk.iter().filter(|&&c| c != b'=').count() - 1;
        out.extend_from_slice(&n.to_be_bytes()[1..=bytes]);
    }
    out
}

#[test]
fn the_embedded_diagrams_are_svg_files_of_their_own() {
    let svg = diagram_svg();
    assert!(svg.starts_with("<svg ") && svg.contains("xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(svg.contains("<style>") && svg.trim_end().ends_with("</svg>"));
    support::roxmltree_well_formed(&svg, "4.2's diagram");
}

#[test]
fn every_bundled_exercise_makes_a_well_formed_valid_quiz_in_both_languages() {
    for lang in ["en", "pt"] {
        let xml = moodle(&exercises(), lang, None);
        support::roxmltree_well_formed(&xml, &format!("the exercises' quiz (--lang {lang})"));
        let questions = validate(&xml).unwrap_or_else(|e| panic!("{lang}: {e}"));
        assert_eq!(questions.len(), exercises().len());
        assert_eq!(
            xml.matches("<question type=\"category\">").count(),
            exercises().len()
        );
        // Colour problems: three NUMERICAL parts of weight 1 with absolute tolerances (each
        // question's mark 3, its default point times 3); the no-hit problem (4.3 as written):
        // one MULTICHOICE_VS part of weight 3 whose full-credit choice is
        // the language's word for "no hit" and whose half-credit choice is a colour (the
        // likely intended reading), so that either earns what `phong check` gives it.
        let none = if lang == "pt" { "nenhuma" } else { "none" };
        for subs in &questions {
            assert_eq!(subs.iter().map(|s| s.weight).sum::<u64>(), 3);
            match subs.len() {
                3 => assert!(subs.iter().all(|s| s.kind == "NUMERICAL"
                    && s.alts.last().unwrap().answer == "*"
                    && s.alts[0].tolerance == Some(0.005))),
                1 => {
                    assert_eq!(subs[0].kind, "MULTICHOICE_VS");
                    let at = |f: f64| -> Vec<&str> {
                        subs[0]
                            .alts
                            .iter()
                            .filter(|a| a.fraction == f)
                            .map(|a| a.answer.as_str())
                            .collect()
                    };
                    assert_eq!(at(100.0), [none]);
                    assert_eq!(at(50.0), ["(0.524, 0.027, 0)"]);
                    assert!(at(0.0).contains(&"(0, 0, 0)"), "{:?}", at(0.0));
                }
                n => panic!("{n} sub-questions"),
            }
        }
        assert!(xml.contains("@@PLUGINFILE@@/") && xml.contains("\\("));
        // The quiz's own words in the chosen language only.
        let (ours, theirs) = if lang == "pt" {
            (
                ["Erro provável:", "Correto.", "Solução comentada"],
                ["Likely slip:", "Right.", "Worked solution"],
            )
        } else {
            (
                ["Likely slip:", "Right.", "Worked solution"],
                ["Erro provável:", "Correto.", "Solução comentada"],
            )
        };
        for (a, b) in ours.iter().zip(theirs) {
            assert!(xml.contains(a) && !xml.contains(b), "{lang}: {a} / {b}");
        }
    }
}

#[test]
fn generated_problems_piped_in_make_a_valid_quiz() {
    // The issue's "done when": `phong new --kind spot --count 10 --seed 1 --lang pt` piped to
    // `phong moodle`, and so for every kind.
    for kind in KINDS {
        let xml = generated_quiz(kind);
        support::roxmltree_well_formed(&xml, &format!("the quiz of {kind} problems"));
        let questions = validate(&xml).unwrap_or_else(|e| panic!("{kind}: {e}"));
        assert_eq!(questions.len(), 10, "{kind}");
        assert!(xml.contains("Problemas gerados"));
    }
}

fn check(file: &Path, answer: [f64; 3]) -> Value {
    let a = format!("{} {} {}", answer[0], answer[1], answer[2]);
    let out = phong()
        .args(["check", "--format", "json", "--answer", &a])
        .arg(file)
        .output()
        .unwrap();
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Each channel's first alternative after the first at `fraction` on the 0–1 scale (its
/// tolerance the right answer's), else `fallback`'s.
fn alternative_colour(subs: &[Sub], fraction: f64, fallback: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|c| {
        subs[c].alts[1..]
            .iter()
            .find(|a| a.fraction == fraction && a.tolerance == subs[c].alts[0].tolerance)
            .map_or(fallback[c], |a| a.answer.parse().unwrap())
    })
}

/// Whether an alternative is on the 255 scale (its English feedback says so).
fn is_8bit(a: &Alt) -> bool {
    a.feedback.contains("8-bit")
}

/// The whole numbers a student types for the colour at `fraction` on the 255 scale: in each
/// channel with an alternative there, its number rounded (the alternative takes whole numbers
/// above 1 only, so its middle is within 0.5 of one it takes); in a channel where `colour` (0–1)
/// is below 1 on the 255 scale (no whole number above 1 within 1 of it, so no alternative: a
/// part graded alone reads such a number on the 0–1 scale), that value rounded. `None` when a
/// channel has neither, or none has an alternative.
fn alternative_8bit(subs: &[Sub], fraction: f64, colour: [f64; 3]) -> Option<[f64; 3]> {
    let found = [0, 1, 2].map(|c| {
        subs[c]
            .alts
            .iter()
            .find(|a| a.fraction == fraction && is_8bit(a))
            .map(|a| a.answer.parse::<f64>().unwrap().round())
    });
    if found.iter().all(Option::is_none) {
        return None;
    }
    let mut out = [0.0; 3];
    for c in 0..3 {
        let dark = colour[c] * 255.0 < 1.0;
        out[c] = found[c].or(dark.then(|| (colour[c] * 255.0).round()))?;
    }
    Some(out)
}

fn right_value(sub: &Sub) -> f64 {
    sub.alts[0].answer.parse().unwrap()
}

/// Every option: the right answer is right, the reading's is a reading, and each slip's
/// colour (its own number in each channel that has one, the right answer's or the reading's
/// elsewhere, which the slip is within tolerance of) is wrong with that slip diagnosed.
#[test]
fn every_answer_option_round_trips_through_phong_check() {
    let dir = tempfile::tempdir().unwrap();
    let mut files = exercises();
    for kind in [
        "point",
        "directional",
        "spot",
        "several",
        "sphere",
        "ray-plane",
    ] {
        phong()
            .args(["new", "--kind", kind, "--count", "3", "--seed", "5", "-o"])
            .arg(dir.path())
            .assert()
            .code(0);
    }
    let mut generated: Vec<PathBuf> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    generated.sort();
    files.extend(generated);
    let xml = moodle(&files, "en", None);
    let questions = validate(&xml).unwrap();
    let mut slips_seen = 0;
    for (file, subs) in files.iter().zip(&questions) {
        if subs.len() != 3 {
            // The no-hit choices: "none" right, the reading's colour a reading, every other
            // colour wrong, as Moodle's Responses export writes the choice.
            for a in &subs[0].alts {
                let v = phong()
                    .args(["check", "--format", "json", "--answer", &a.answer])
                    .arg(file)
                    .output()
                    .unwrap();
                let v: Value = serde_json::from_slice(&v.stdout).unwrap();
                let verdict = match a.fraction {
                    100.0 => "right",
                    50.0 => "reading",
                    _ => "wrong",
                };
                assert_eq!(v["verdict"], verdict, "{}: {}", file.display(), a.answer);
            }
            continue;
        }
        let right = [0, 1, 2].map(|c| right_value(&subs[c]));
        assert_eq!(check(file, right)["verdict"], "right", "{}", file.display());
        // A second 100 % alternative is the value before the clamp: the unclamped colour; a
        // 50 % one, the likely intended reading.
        for (fraction, verdict) in [(100.0, "right"), (50.0, "reading")] {
            let colour = alternative_colour(subs, fraction, right);
            if colour != right {
                let v = check(file, colour);
                assert_eq!(v["verdict"], verdict, "{}", file.display());
            }
        }
        // The same on the 255 scale: the whole numbers a student types, read as 8-bit values.
        let reading = alternative_colour(subs, 50.0, right);
        for (fraction, verdict, fill) in [(100.0, "right", right), (50.0, "reading", reading)] {
            if let Some(colour) = alternative_8bit(subs, fraction, fill) {
                let v = check(file, colour);
                assert_eq!(v["verdict"], verdict, "{}: {colour:?}", file.display());
                // Three whole numbers are read as 8-bit values when one is above 1 (else they
                // are a 0–1 colour, and the same one: 0 and 1 are 0 and 1/255 apart).
                let as_8bit = colour.iter().any(|&x| x > 1.0);
                assert_eq!(v["answer"]["read_as_8bit"], as_8bit, "{}", file.display());
            }
        }
        // Each slip's sentence, as the feedback says it.
        let mut sentences: Vec<String> = Vec::new();
        for sub in subs {
            for a in sub
                .alts
                .iter()
                .filter(|a| a.fraction == 0.0 && a.answer != "*")
            {
                for s in a.feedback.split("Likely slip: ").skip(1) {
                    let s = s.trim().to_owned();
                    if !sentences.contains(&s) {
                        sentences.push(s);
                    }
                }
            }
        }
        for sentence in &sentences {
            let own = |c: usize| {
                subs[c]
                    .alts
                    .iter()
                    .find(|a| a.fraction == 0.0 && a.feedback.contains(sentence.as_str()))
                    .map(|a| a.answer.parse::<f64>().unwrap())
            };
            let fills = [right, reading];
            let diagnosed = (0..8).any(|choice: usize| {
                let colour = [0, 1, 2].map(|c| own(c).unwrap_or(fills[(choice >> c) & 1][c]));
                let v = check(file, colour);
                v["verdict"] == "wrong"
                    && v["diagnosis"].as_array().unwrap().iter().any(|d| {
                        d["slips"].as_array().unwrap().len() == 1
                            && sentence.starts_with(d["description"].as_str().unwrap())
                    })
            });
            assert!(diagnosed, "{}: {sentence}", file.display());
            slips_seen += 1;
        }
    }
    assert!(slips_seen > 20, "only {slips_seen} slip options");
}

#[test]
fn a_file_that_is_not_a_question_is_refused_by_name() {
    let out = phong()
        .args(["moodle", "scenes/classic.json"])
        .assert()
        .code(2)
        .get_output()
        .clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("scenes/classic.json") && err.contains("no point or ray"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    // An array whose second problem is broken names it.
    let out = phong()
        .args(["moodle", "-"])
        .write_stdin(r#"[{"lights": [], "point": {"material": "M"}, "materials": {"M": {"ambient": [0.5, 0.5, 0.5]}}}, {"bogus": 1}]"#)
        .assert()
        .code(2)
        .get_output()
        .clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("-[2]") && err.contains("bogus"), "{err}");
}

/// QA: `phong moodle a.json ok.json b.json -o quiz.xml` said only a.json's error. Every bad
/// file's error is said, in the order given (one found reading the file and one found making
/// its question: a scene has no point or ray), and nothing is written: the old quiz is kept.
/// The problem files, and the course policy, are inputs no quiz may replace.
#[test]
fn every_bad_file_is_said_in_order_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("a.json");
    std::fs::write(&bad, "{ \"lights\": [").unwrap();
    let good = dir.path().join("ok.json");
    std::fs::copy(root().join("exercises/4.1.json"), &good).unwrap();
    let scene = dir.path().join("b.json");
    std::fs::copy(root().join("scenes/classic.json"), &scene).unwrap();
    let quiz = dir.path().join("quiz.xml");
    std::fs::write(&quiz, "OLD").unwrap();
    let out = phong()
        .arg("moodle")
        .args([&bad, &good, &scene])
        .arg("-o")
        .arg(&quiz)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(
        lines[0].starts_with(&format!("error: {}:", bad.display())),
        "{err}"
    );
    assert!(
        lines[1].starts_with(&format!("error: {}:", scene.display())),
        "{err}"
    );
    assert!(lines[1].contains("no point or ray"), "{err}");
    assert!(!err.contains("ok.json"), "{err}");
    assert_eq!(std::fs::read_to_string(&quiz).unwrap(), "OLD");
    assert!(out.stdout.is_empty());

    // An output that is an input: refused, the file kept.
    let text = std::fs::read(&good).unwrap();
    let out = phong()
        .arg("moodle")
        .arg(&good)
        .arg("-o")
        .arg(&good)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is the input"));
    assert_eq!(std::fs::read(&good).unwrap(), text);
}

// QA A #10. A problem's own text is text: a Cloze sub-question written in its title, question
// or a light's name (`{2:SHORTANSWER:=x}`), or LaTeX-ish braces (`\frac{1}{2}`) with `~`, `#`
// and `=` around them, must not become a sub-question of the quiz. 4.2 is a colour problem:
// its quiz has exactly phong's three NUMERICAL parts (R, G, B), whatever its text holds.
#[test]
fn cloze_syntax_in_a_problems_text_stays_text() {
    let dir = tempfile::tempdir().unwrap();
    let file = cloze_problem(dir.path());
    for lang in ["pt", "en"] {
        let xml = moodle(std::slice::from_ref(&file), lang, None);
        support::roxmltree_well_formed(&xml, &format!("the quiz of evil.json (--lang {lang})"));
        let questions = validate(&xml).unwrap_or_else(|e| panic!("{lang}: {e}"));
        assert_eq!(questions.len(), 1, "{lang}");
        let subs = &questions[0];
        assert_eq!(subs.len(), 3, "{lang}: {subs:?}");
        assert!(
            subs.iter().all(|s| s.kind == "NUMERICAL"),
            "{lang}: {subs:?}"
        );
        // The text is still there, shown as written: its braces as HTML references.
        let text = between(&xml, "<questiontext format=\"html\"><text>", "</text>").unwrap();
        assert!(
            text.contains("&#123;2:SHORTANSWER:=x&#125;") && text.contains("\\frac&#123;1&#125;"),
            "{lang}: {text}"
        );
    }
}

/// 4.2 with Cloze syntax and LaTeX-ish braces in its title, question and light's name, written
/// to `dir/evil.json`.
fn cloze_problem(dir: &Path) -> PathBuf {
    let mut problem: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("exercises/4.2.json")).unwrap())
            .unwrap();
    let evil = "Pergunta com ]]> e {2:SHORTANSWER:=x} e {:NM:=1:0} e ~ # } = \\frac{1}{2} {";
    problem["question"] = Value::from(evil);
    problem["question_pt"] = Value::from(evil);
    problem["title_pt"] = Value::from("Exercício {1:SHORTANSWER:=x}");
    problem["lights"][0]["name_pt"] = Value::from("luz {1:NUMERICAL:=0.5:1}");
    problem["lights"][0]["name"] = Value::from("light {1:NUMERICAL:=0.5:1}");
    let file = dir.join("evil.json");
    std::fs::write(&file, problem.to_string()).unwrap();
    file
}

/// The documents of the tests above (the diagram, the bundled exercises' quiz in both languages,
/// each kind's generated quiz, the quiz of Cloze syntax in a problem's text), read by xmllint
/// too: a second parser after roxmltree.
#[test]
#[ignore = "needs xmllint: apt-get install libxml2-utils"]
fn xmllint_reads_every_quiz_and_diagram_as_well_formed() {
    support::xmllint_well_formed(&diagram_svg(), "4.2's diagram");
    for lang in ["en", "pt"] {
        let xml = moodle(&exercises(), lang, None);
        support::xmllint_well_formed(&xml, &format!("the exercises' quiz (--lang {lang})"));
    }
    for kind in KINDS {
        let xml = generated_quiz(kind);
        support::xmllint_well_formed(&xml, &format!("the quiz of {kind} problems"));
    }
    let dir = tempfile::tempdir().unwrap();
    let file = cloze_problem(dir.path());
    for lang in ["pt", "en"] {
        let xml = moodle(std::slice::from_ref(&file), lang, None);
        support::xmllint_well_formed(&xml, &format!("the quiz of evil.json (--lang {lang})"));
    }
}

/// Every alternative of a NUMERICAL part but `*`: its number and its tolerance.
fn numbers(sub: &Sub) -> Vec<(f64, f64, &str)> {
    sub.alts
        .iter()
        .filter(|a| a.answer != "*")
        .map(|a| {
            (
                a.answer.parse::<f64>().unwrap(),
                a.tolerance.unwrap(),
                a.feedback.as_str(),
            )
        })
        .collect()
}

/// Issue 28. Moodle grades a NUMERICAL part by the first alternative within its tolerance
/// (`question/type/numerical/question.php`: `get_matching_answer` walks the answers in order;
/// `within_tolerance` is `min <= value <= max`, the interval the answer ± its tolerance plus
/// 1e-14·max(1, |answer|)). So an alternative whose number lies in an earlier one's interval,
/// or whose interval holds an earlier one's number, names a slip the student is never shown
/// (or shows it for the wrong one). Every kind `phong new` makes, seeds 1 to 30.
#[test]
fn no_two_alternatives_of_a_part_lie_within_its_tolerance() {
    let kinds = [
        "ambient",
        "point",
        "ray-plane",
        "directional",
        "spot",
        "several",
        "sphere",
        "secondary",
    ];
    let mut parts = 0;
    for kind in kinds {
        let problems: Vec<Value> = (1..=30)
            .map(|seed| serde_json::from_slice(&new(kind, 1, seed, None)).unwrap())
            .collect();
        let input = serde_json::to_vec(&problems).unwrap();
        let xml = moodle(&[PathBuf::from("-")], "en", Some(&input));
        let questions = validate(&xml).unwrap_or_else(|e| panic!("{kind}: {e}"));
        assert_eq!(questions.len(), 30, "{kind}");
        for (i, subs) in questions.iter().enumerate() {
            for sub in subs.iter().filter(|s| s.kind == "NUMERICAL") {
                parts += 1;
                // The 0–1 scale's alternatives (the right answer's tolerance), then the 255
                // scale's (after them all): apart within each scale. A number a 0–1 alternative
                // takes is judged on the 0–1 scale first, as `phong check` reads three numbers
                // that are not all whole on the 0–1 scale.
                let all = numbers(sub);
                let tolerance = all[0].1;
                let (bits8, alts): (Vec<_>, Vec<_>) =
                    all.iter().partition(|&&(_, _, f)| f.contains("8-bit"));
                let first8 = all.iter().position(|&(_, _, f)| f.contains("8-bit"));
                assert!(first8.is_none_or(|f| f == alts.len()), "{kind}: 8-bit last");
                for (j, &&(a, ta, fa)) in bits8.iter().enumerate() {
                    // Within 1 of the value, and above 1 only: a part is graded alone, and
                    // `phong check` reads a number up to 1 on the 0–1 scale (three whole
                    // numbers are 8-bit values only when one is above 1). A part whose 8-bit
                    // alternative reached down to 1 gave full marks to any 0–1 number every
                    // 0–1 alternative missed.
                    assert!(ta <= 1.0, "{kind} seed {}: {fa}", i + 1);
                    assert!(a - ta > 1.0, "{kind} seed {}: {a} ± {ta} ({fa})", i + 1);
                    // Reachable: not inside an earlier one's interval.
                    for &&(b, tb, fb) in &bits8[j + 1..] {
                        let inside = a - ta <= b - tb && b + tb <= a + ta;
                        assert!(!inside, "{kind} seed {}: {fa} / {fb}", i + 1);
                    }
                }
                for (j, &&(a, ta, fa)) in alts.iter().enumerate() {
                    assert_eq!(ta, tolerance, "{kind} seed {}: one tolerance", i + 1);
                    for &&(b, _, fb) in &alts[j + 1..] {
                        let reach = tolerance + 1e-14 * a.abs().max(b.abs()).max(1.0);
                        assert!(
                            (a - b).abs() > reach,
                            "{kind} seed {}: {a} ({fa}) and {b} ({fb}) lie within {tolerance}",
                            i + 1
                        );
                    }
                }
            }
        }
    }
    assert!(parts > 400, "only {parts} parts");
}

/// Issue 28's example: in `phong new --kind point --count 30 --seed 16`'s first problem, the
/// red part's "cos φ not raised to n_s" lies within the tolerance of "Blinn's half vector",
/// which comes first: one alternative, whose feedback names both slips.
#[test]
fn slips_within_the_tolerance_share_one_alternative_naming_each() {
    let dir = tempfile::tempdir().unwrap();
    phong()
        .args([
            "new", "--kind", "point", "--count", "30", "--seed", "16", "-o",
        ])
        .arg(dir.path())
        .assert()
        .code(0);
    let xml = moodle(&[dir.path().join("point-16-001.json")], "en", None);
    let questions = validate(&xml).unwrap();
    let red = &questions[0][0];
    let named = |words: &str| {
        red.alts
            .iter()
            .filter(|a| a.feedback.contains(words))
            .count()
    };
    assert_eq!(named("Blinn"), 1, "{red:?}");
    assert_eq!(named("not raised to n_s"), 1, "{red:?}");
    let blinn = red
        .alts
        .iter()
        .find(|a| a.feedback.contains("Blinn"))
        .unwrap();
    assert!(blinn.feedback.contains("not raised to n_s"), "{red:?}");
    assert_eq!(blinn.fraction, 0.0);
}

/// A category path as Moodle's importer splits it (`question/format.php`,
/// `split_category_path`): at each `/` with no `/` on either side; then each `//` is one `/`
/// and each name is trimmed.
fn moodle_category_names(path: &str) -> Vec<String> {
    let chars: Vec<char> = path.chars().collect();
    let mut names = vec![String::new()];
    for (i, &c) in chars.iter().enumerate() {
        let lone = c == '/'
            && (i == 0 || chars[i - 1] != '/')
            && chars.get(i + 1).is_none_or(|&n| n != '/');
        if lone {
            names.push(String::new());
        } else {
            names.last_mut().unwrap().push(c);
        }
    }
    names
        .iter()
        .map(|n| n.replace("//", "/").trim().to_owned())
        .collect()
}

fn category_of(xml: &str) -> Vec<String> {
    let path = between(xml, "<category><text>", "</text>").unwrap();
    let path = path
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    moodle_category_names(&path)
}

/// Issue 28: `--category 'A/B 50%'` is one category named "A/B 50%", not "A" › "B 50%"; so is
/// a name that starts or ends with `/`, and the default name is unchanged.
#[test]
fn a_category_name_with_slashes_is_one_category() {
    // The splitter against Moodle's own test of its path functions
    // (question/tests/importexport_test.php).
    assert_eq!(
        moodle_category_names(
            "$course$/Tim's questions/Tricky things like // //// and so on/Category name ending in // / // and one that starts with one"
        ),
        [
            "$course$",
            "Tim's questions",
            "Tricky things like / // and so on",
            "Category name ending in /",
            "/ and one that starts with one"
        ]
    );
    let file = root().join("exercises/4.2.json");
    for (name, expected) in [
        ("A/B 50%", "A/B 50%"),
        ("/a//b/", "/a//b/"),
        (
            "Cap. 4 - Modelos de Iluminação",
            "Cap. 4 - Modelos de Iluminação",
        ),
    ] {
        let out = phong()
            .args(["moodle", "--lang", "en", "--category", name])
            .arg(&file)
            .assert()
            .code(0)
            .get_output()
            .stdout
            .clone();
        let xml = String::from_utf8(out).unwrap();
        validate(&xml).unwrap();
        assert_eq!(
            category_of(&xml),
            ["$course$", "top", expected, "4.2"],
            "{name}"
        );
    }
    // The default: the course's chapter, then the file's name.
    let xml = moodle(&[file], "en", None);
    assert_eq!(
        category_of(&xml),
        ["$course$", "top", "Cap. 4 - Modelos de Iluminação", "4.2"]
    );
}

#[cfg(feature = "serve")]
use crate::support::http;
#[cfg(feature = "serve")]
use crate::support::server;

/// Issue 28's table: one answer, one verdict and one credit on every surface (needs `phong
/// serve`, so the `serve` feature).
#[cfg(feature = "serve")]
mod one_verdict {
    use super::*;

    /// A number as Moodle's NUMERICAL part reads a response: `-`, digits, one `.` or `,` (the
    /// decimal separators of the English and Portuguese language packs); anything else is no
    /// number, and the part is not answered.
    fn moodle_number(s: &str) -> Option<f64> {
        let t = s.trim();
        let ok = !t.is_empty()
            && t.trim_start_matches('-')
                .chars()
                .all(|c| c.is_ascii_digit() || c == '.' || c == ',')
            && t.chars().filter(|c| *c == '.' || *c == ',').count() <= 1;
        ok.then(|| t.replace(',', ".").parse().ok()).flatten()
    }

    /// Moodle's grade of a NUMERICAL part (`question/type/numerical/question.php`,
    /// `get_matching_answer`): the first alternative whose interval, answer ± tolerance plus
    /// 1e-14·max(1, |answer|), holds the number (`*` holds every number); `None` for a response
    /// that is not a number.
    fn moodle_part(sub: &Sub, response: &str) -> Option<f64> {
        let x = moodle_number(response)?;
        let hit = sub.alts.iter().find(|a| {
            a.answer == "*" || {
                let v: f64 = a.answer.parse().unwrap();
                let t = a.tolerance.unwrap_or(0.0) + 1e-14 * v.abs().max(1.0);
                (v - t..=v + t).contains(&x)
            }
        });
        Some(hit.map_or(0.0, |a| a.fraction / 100.0))
    }

    /// The three numbers a student types in the quiz's R, G and B boxes for `answer`: its numbers
    /// as written (a `#RRGGBB` answer as its three 8-bit values, since a box takes a number).
    fn boxes(answer: &str) -> Vec<String> {
        if let Some(hex) = answer.trim().strip_prefix('#') {
            return (0..3)
                .map(|i| {
                    u8::from_str_radix(&hex[2 * i..2 * i + 2], 16)
                        .unwrap()
                        .to_string()
                })
                .collect();
        }
        let t = answer.trim().trim_start_matches('(').trim_end_matches(')');
        let parts: Vec<&str> = t
            .split_whitespace()
            .map(|p| p.trim_end_matches([',', ';']))
            .collect();
        let parts = if parts.len() == 3 {
            parts
        } else {
            t.split([',', ';']).map(str::trim).collect()
        };
        parts.into_iter().map(str::to_owned).collect()
    }

    /// The colour an answer gives on the 0–1 scale, by this test's own reading (three numbers,
    /// 8-bit when all are whole and one is above 1, `#RRGGBB`), to find the choice a student
    /// would click in the no-hit question; `None` for text that is no colour.
    fn colour_of(answer: &str) -> Option<[f64; 3]> {
        let b = boxes(answer);
        let v: Vec<f64> = b.iter().filter_map(|s| moodle_number(s)).collect();
        if v.len() != 3 {
            return None;
        }
        let bits8 = answer.trim().starts_with('#')
            || (v.iter().all(|x| x.fract() == 0.0) && v.iter().any(|&x| x > 1.0));
        let k = if bits8 { 255.0 } else { 1.0 };
        Some([v[0] / k, v[1] / k, v[2] / k])
    }

    /// What the quiz gives `answer`: the grade of its question (the mean of its parts weighted
    /// by their weights, as Moodle's Cloze question grades), and whether the student could give it at all as a number in
    /// each box (a colour question) or as one of the choices (the no-hit question).
    fn moodle_grade(subs: &[Sub], answer: &str) -> (f64, bool) {
        if subs.len() == 3 {
            let b = boxes(answer);
            if b.len() != 3 {
                return (0.0, false);
            }
            let parts: Vec<Option<f64>> = (0..3).map(|c| moodle_part(&subs[c], &b[c])).collect();
            let given = parts.iter().all(Option::is_some);
            let weighed: f64 = (0..3)
                .map(|c| parts[c].unwrap_or(0.0) * subs[c].weight as f64)
                .sum();
            let mark: u64 = subs.iter().map(|s| s.weight).sum();
            (weighed / mark as f64, given)
        } else {
            let choices = &subs[0].alts;
            let none = ["none", "nenhuma", "sem interseção"].contains(&answer.trim());
            let chosen = if none {
                choices.iter().find(|a| a.fraction == 100.0)
            } else {
                colour_of(answer).and_then(|c| {
                    choices.iter().find(|a| {
                        colour_of(&a.answer)
                            .is_some_and(|k| (0..3).all(|i| (k[i] - c[i]).abs() <= 0.005))
                    })
                })
            };
            chosen.map_or((0.0, false), |a| (a.fraction / 100.0, true))
        }
    }

    /// Issue 28, "one verdict everywhere": each answer of a table of 30 (right answers written
    /// every way, on the 0–1 and 255 scales and as `#RRGGBB`; the likely intended readings, on
    /// both scales; slips; "no hit" in words of both languages; text that is no answer) goes
    /// through `phong check`, a `phong grade` row, `/api/check` of `phong serve` and the Moodle
    /// quiz of the same exercises, all under one course policy written beside them
    /// (`course-policy.json`: a reading earns a quarter, 4.2 is worth 2 points), and each gives
    /// the verdict and the credit worked out here by hand:
    ///
    /// - 4.1: O_a·I_a = (0.5, 0.7, 0.3)·(1, 1, 1) = (0.5, 0.7, 0.3), on the 255 scale (127.5,
    ///   178.5, 76.5): 128 179 77 and #80B34D are within 1;
    /// - 4.2: as written the light is behind the surface (cos θ < 0): black; the likely intended
    ///   reading (L reversed) is (0.299153, 0.361229, 0.318306) (docs/conventions.md), on the 255
    ///   scale (76.28, 92.11, 81.17): 76 92 81 is within 1; 0.245 0.28 0.21 is |cos θ| (a slip);
    /// - 4.3: the ray meets the plane at t = −90, behind its origin: "none"; the line's hit is the
    ///   likely intended reading, (0.523919, 0.0273364, 0), on the 255 scale (133.6, 6.97, 0):
    ///   134 7 0 is within 1; black is the background, wrong.
    ///
    /// Moodle's quiz has no "invalid": a box that holds no number earns nothing, as an answer that
    /// cannot be read earns nothing elsewhere; so the quiz is held to the same credit, and to
    /// accepting exactly the answers phong accepts. One difference is Moodle's own and is asserted
    /// as such: a Cloze question grades each box apart, so a wrong colour with right channels
    /// earns their share in the quiz (the last row), where phong judges the colour whole; the
    /// course's verdict on such an answer is `phong grade --input moodle` of the Responses export.
    #[test]
    fn one_answer_gets_one_verdict_and_one_credit_from_check_grade_serve_and_moodle() {
        const Q: f64 = 0.25;
        // (exercise, answer, verdict, credit; the quiz's credit where Moodle's differs).
        let table: [(&str, &str, &str, f64, Option<f64>); 30] = [
            ("4.1", "0.5 0.7 0.3", "right", 1.0, None),
            ("4.1", "(0.5, 0.7, 0.3)", "right", 1.0, None),
            ("4.1", "0,5 0,7 0,3", "right", 1.0, None),
            ("4.1", "0.503 0.702 0.296", "right", 1.0, None),
            ("4.1", "128 179 77", "right", 1.0, None),
            ("4.1", "#80B34D", "right", 1.0, None),
            ("4.1", "0 0 0", "wrong", 0.0, None),
            ("4.1", "0.6 0.8 0.4", "wrong", 0.0, None),
            ("4.1", "nenhuma", "wrong", 0.0, None),
            ("4.1", "abc", "invalid", 0.0, None),
            ("4.2", "0 0 0", "right", 1.0, None),
            ("4.2", "0.004 0 0.003", "right", 1.0, None),
            ("4.2", "0.3 0.36 0.32", "reading", Q, None),
            ("4.2", "0,299 0,361 0,318", "reading", Q, None),
            ("4.2", "76 92 81", "reading", Q, None),
            ("4.2", "0.245 0.28 0.21", "wrong", 0.0, None),
            ("4.2", "0.5 0.4 0.6", "wrong", 0.0, None),
            // Read on the 0–1 scale (no number above 1): wrong, in the quiz too, where each
            // part's 8-bit alternative for the black key (0 ± 1) once took them as right.
            ("4.2", "0.7 0.7 0.7", "wrong", 0.0, None),
            ("4.2", "1 1 1", "wrong", 0.0, None),
            ("4.2", "none", "wrong", 0.0, None),
            ("4.3", "nenhuma", "right", 1.0, None),
            ("4.3", "none", "right", 1.0, None),
            ("4.3", "sem interseção", "right", 1.0, None),
            ("4.3", "0.524 0.027 0", "reading", Q, None),
            ("4.3", "134 7 0", "reading", Q, None),
            ("4.3", "0 0 0", "wrong", 0.0, None),
            ("4.3", "0.5 0 0", "wrong", 0.0, None),
            ("4.3", "0.9 0.9 0.9", "wrong", 0.0, None),
            ("4.3", "xyz", "invalid", 0.0, None),
            // Two channels right, one wrong: wrong, and two thirds in Moodle's per-box grading.
            ("4.1", "0.52 0.7 0.3", "wrong", 0.0, Some(2.0 / 3.0)),
        ];
        let dir = tempfile::tempdir().unwrap();
        for id in ["4.1", "4.2", "4.3"] {
            let name = format!("{id}.json");
            std::fs::copy(root().join("exercises").join(&name), dir.path().join(&name)).unwrap();
        }
        std::fs::write(
            dir.path().join("course-policy.json"),
            r#"{"reading_credit": 0.25, "points": {"4.2": 2}}"#,
        )
        .unwrap();
        let file = |id: &str| dir.path().join(format!("{id}.json"));

        // The Moodle quiz, one question per exercise in order.
        let xml = moodle(&[file("4.1"), file("4.2"), file("4.3")], "pt", None);
        let questions = validate(&xml).unwrap();
        let question =
            |id: &str| &questions[["4.1", "4.2", "4.3"].iter().position(|x| *x == id).unwrap()];
        // The quiz weighs each question by the policy's points, as the grade report does: a
        // Cloze question's mark is the sum of its parts' weights, so 4.1 : 4.2 : 4.3 is
        // 1 : 2 : 1 (4.3's one part weighs what 4.1's three do).
        let mark = |id: &str| question(id).iter().map(|s| s.weight).sum::<u64>();
        assert_eq!((mark("4.1"), mark("4.2"), mark("4.3")), (3, 6, 3));

        // The grade report, one row per answer (student i answers row i).
        let mut csv = String::from("aluno;exercicio;resposta\n");
        for (i, (id, answer, ..)) in table.iter().enumerate() {
            csv.push_str(&format!("s{i};{id};\"{answer}\"\n"));
        }
        let submissions = dir.path().join("respostas.csv");
        std::fs::write(&submissions, csv).unwrap();
        let out = phong()
            .args(["grade", "--format", "json", "--exercises"])
            .arg(dir.path())
            .arg(&submissions)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        let report: Value = serde_json::from_slice(&out.stdout).unwrap();
        let rows = report["rows"].as_array().unwrap();
        assert_eq!(rows.len(), table.len());

        let server = super::server::Server::start(&["--exercises", dir.path().to_str().unwrap()]);
        for (i, &(id, answer, verdict, credit, quiz)) in table.iter().enumerate() {
            let what = format!("{id} {answer:?}");
            // phong check.
            let out = phong()
                .args(["check", "--format", "json", "--answer", answer])
                .arg(file(id))
                .output()
                .unwrap();
            let c: Value = serde_json::from_slice(&out.stdout).unwrap();
            assert_eq!(c["verdict"], verdict, "check {what}");
            assert_eq!(c["credit"].as_f64().unwrap_or(0.0), credit, "check {what}");
            let code = match verdict {
                "invalid" => 2,
                _ if credit > 0.0 => 0,
                _ => 1,
            };
            assert_eq!(out.status.code(), Some(code), "check {what}");
            // A phong grade row.
            let row = &rows[i];
            assert_eq!(row["verdict"], verdict, "grade {what}");
            let max = row["max_points"].as_f64().unwrap_or(0.0);
            assert_eq!(max, if id == "4.2" { 2.0 } else { 1.0 }, "grade {what}");
            assert_eq!(
                row["points"].as_f64().unwrap(),
                credit * max,
                "grade {what}"
            );
            // /api/check.
            let body = serde_json::json!({"exercise": id, "answer": answer}).to_string();
            let r = super::http::post_json(server.addr, "/api/check", &body).json();
            assert_eq!(r["verdict"], verdict, "api {what}: {r}");
            assert_eq!(r["credit"].as_f64().unwrap_or(0.0), credit, "api {what}");
            // The Moodle quiz.
            let (grade, given) = moodle_grade(question(id), answer);
            let expected = quiz.unwrap_or(credit);
            assert!((grade - expected).abs() < 1e-9, "moodle {what}: {grade}");
            if credit > 0.0 {
                assert!(
                    given,
                    "moodle {what}: an accepted answer the quiz cannot take"
                );
            }
        }
    }
}

/// Points finer than a thousandth of a point: the quiz's whole weights would round them (0.0001
/// to 0, which Moodle reads as 1; 0.3333 to 333 beside 1,000 for a point), so they are refused,
/// exit 2, naming the policy, the problem and the points, and nothing is written; a thousandth
/// is kept exactly: 0.333 weighs 333 per part beside 1,000 for 1 point.
#[test]
fn points_finer_than_a_thousandth_are_refused_for_the_quiz() {
    let dir = tempfile::tempdir().unwrap();
    for id in ["4.1", "4.2"] {
        let name = format!("{id}.json");
        std::fs::copy(root().join("exercises").join(&name), dir.path().join(&name)).unwrap();
    }
    let policy = dir.path().join("course-policy.json");
    let quiz = dir.path().join("quiz.xml");
    for (points, lang, says) in [
        (
            "0.0001",
            "en",
            "4.2.json is worth 0.0001 points, finer than a thousandth of a point",
        ),
        (
            "0.3333",
            "pt",
            "4.2.json vale 0.3333 pontos, mais fino que um milésimo de ponto",
        ),
    ] {
        std::fs::write(&policy, format!(r#"{{"points": {{"4.2": {points}}}}}"#)).unwrap();
        let out = phong()
            .args(["moodle", "--lang", lang, "-o"])
            .arg(&quiz)
            .arg(dir.path().join("4.1.json"))
            .arg(dir.path().join("4.2.json"))
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains("course-policy.json") && err.contains(says),
            "{err}"
        );
        assert!(!quiz.exists());
    }
    std::fs::write(&policy, r#"{"points": {"4.2": 0.333}}"#).unwrap();
    let xml = moodle(
        &[dir.path().join("4.1.json"), dir.path().join("4.2.json")],
        "en",
        None,
    );
    let questions = validate(&xml).unwrap();
    let weights = |q: &Vec<Sub>| q.iter().map(|s| s.weight).collect::<Vec<_>>();
    assert_eq!(weights(&questions[0]), [1000, 1000, 1000]);
    assert_eq!(weights(&questions[1]), [333, 333, 333]);
}
