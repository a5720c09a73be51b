//! `phong grade`'s reasons for a row, in both languages: a file with a row reaching each reason,
//! graded in Portuguese, has feedback with no English fragment, while the `reason` column (and
//! the JSON's `reason`) stays the English it always was.

use std::path::Path;

use crate::support::phong;
use serde_json::Value;

/// Exercises 4.1 and 4.2, a file that is not a problem, a folder named like an exercise, and
/// (on Unix) a link out of the folder and a link to nothing.
fn exercises() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises");
    for f in ["4.1.json", "4.2.json"] {
        std::fs::copy(src.join(f), dir.path().join(f)).unwrap();
    }
    std::fs::write(dir.path().join("broken.json"), "{\"zzz\": 1}").unwrap();
    std::fs::create_dir(dir.path().join("sub.json")).unwrap();
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(src.join("4.3.json"), dir.path().join("out.json")).unwrap();
        std::os::unix::fs::symlink("/nonexistent/x.json", dir.path().join("gone.json")).unwrap();
    }
    dir
}

/// English words that Portuguese never writes (not `no`, `a`, `byte`, which it does): one of
/// them outside quotes and backticks (where a column's or a file's own names stand) is an
/// untranslated fragment.
const ENGLISH: &[&str] = &[
    "the",
    "is",
    "are",
    "and",
    "not",
    "with",
    "give",
    "write",
    "must",
    "cannot",
    "Fix",
    "of",
    "which",
    "should",
    "an",
    "has",
    "have",
    "from",
    "to",
    "by",
    "it",
    "this",
    "that",
    "be",
    "or",
    "for",
    "only",
    "than",
    "when",
    "where",
    "there",
    "its",
    "was",
    "were",
    "field",
    "fields",
    "row",
    "rows",
    "exercise",
    "exercises",
    "answer",
    "file",
    "folder",
    "quote",
    "quoted",
    "header",
    "column",
    "line",
    "read",
    "written",
    "name",
    "names",
    "expected",
    "separated",
    "empty",
    "valid",
    "holds",
    "refused",
    "copy",
    "regular",
    "device",
    "unknown",
    "replace",
    "followed",
    "export",
    "save",
    "download",
    "report",
    "plain",
    "given",
    "slot",
    "checked",
    "point",
    "points",
    "wrong",
    "right",
    "spreadsheet",
    "order",
    "text",
    "after",
    "closing",
    "inside",
    "whole",
    "character",
    "steps",
    "step",
    "number",
    "numbers",
    "such",
    "three",
    "integers",
    "hits",
    "nothing",
    "ray",
    "one",
    "per",
    "question",
    "check",
    "path",
    "exists",
    "readable",
    "smaller",
];

/// `text` without what stands between quotes or backticks.
fn outside_quotes(text: &str) -> String {
    let mut out = String::new();
    let mut quote: Option<char> = None;
    for c in text.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if matches!(c, '"' | '`') => quote = Some(c),
            None => out.push(c),
        }
    }
    out
}

/// The English words of `text` outside quotes and paths (a file's path names its folders).
fn english_in(text: &str) -> Vec<String> {
    outside_quotes(text)
        .split_whitespace()
        .filter(|chunk| !chunk.contains('/'))
        .flat_map(|chunk| chunk.split(|c: char| !c.is_alphanumeric() && c != '\''))
        .filter(|w| ENGLISH.contains(w))
        .map(str::to_owned)
        .collect()
}

/// The rows of the JSON report of `csv` graded with `args`, and standard error.
fn graded(csv: &[u8], dir: &Path, args: &[&str], env: Option<(&str, &str)>) -> Vec<Value> {
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(input.path(), csv).unwrap();
    let mut cmd = phong();
    cmd.arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir)
        .args(["--format", "json"])
        .args(args)
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C");
    if let Some((k, v)) = env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{e}: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    json["rows"].as_array().unwrap().clone()
}

/// A file of one row per reason a plain CSV can give, with each row's reason in English as
/// phong has always written it (`DIR` for the exercises folder).
fn rows() -> (Vec<u8>, Vec<&'static str>) {
    let mut csv = Vec::new();
    let mut want = Vec::new();
    let mut row = |line: &[u8], reason: &'static str| {
        csv.extend_from_slice(line);
        csv.push(b'\n');
        want.push(reason);
    };
    row(b",4.1,0 0 0", "the student field is empty");
    row(b"a,,0 0 0", "the exercise field is empty");
    row(b"b,4.1,", "the answer field is empty");
    row(
        b"c,9.9,0 0 0",
        "unknown exercise: there is no 9.9.json in the exercises folder DIR. Fix: name an \
         exercise by its file name without .json (e.g. 4.2 for DIR/4.2.json)",
    );
    row(
        b"d,4.1,\"0 0 0",
        "the row cannot be read as CSV: field 3 opens a quote \" that is not closed on its line \
         (a row is one line)",
    );
    row(
        b"e,4.1,\"0 0 0\"x",
        "the row cannot be read as CSV: field 3 has text after its closing quote (\"x\"): quote \
         the whole field, with \"\" for a quote inside",
    );
    row(
        b"f,4.1,0.5,0.5,0.5",
        "the row has 5 fields, expected 3 (student, exercise, answer); an answer written with \
         ',' must be quoted: \"0.52, 0.03, 0\"",
    );
    row(
        b"g;4.1;0 0 0",
        "the row has 1 field, expected 3 (student, exercise, answer); the fields are read as \
         separated by ',', and this row has ';': give --delimiter ;",
    );
    row(
        b"h\t4.1\t0 0 0",
        "the row has 1 field, expected 3 (student, exercise, answer); the fields are read as \
         separated by ',', and this row has a tab character: give --delimiter tab",
    );
    row(
        b"i,4.1",
        "the row has 2 fields, expected 3 (student, exercise, answer)",
    );
    row(
        b"k,4.1,0\x00 0 0",
        "the answer field holds a NUL byte (shown as U+FFFD): is the file UTF-16 without a byte \
         order mark? Save it as UTF-8 (CSV UTF-8 in a spreadsheet)",
    );
    row(
        b"l,4.1,abc",
        "the answer cannot be read: \"abc\" is not three numbers; no number could be read in \
         it: write three numbers such as \
         \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \"[0.52; 0.03; 0]\", three integers 0–255 with \
         --scale 255, \"#RRGGBB\", or \"none\" when the ray hits nothing",
    );
    row(
        b"m,broken,0 0 0",
        "DIR/broken.json:1:6: zzz: unknown field `zzz`, expected one of `$schema`, `title`, \
         `title_pt`, `question`, `question_pt`, `materials`, `lights`, `viewer`, `point`, `ray`, \
         `surfaces`, `camera`, `background`, `render`, `answer`, `generated`. Fix: remove the \
         field or correct its spelling (`phong schema` lists every field)",
    );
    row(
        b"n,sub,0 0 0",
        "DIR/sub.json: the exercise is not a regular file (a folder, a FIFO or a device). \
         Fix: put the exercise's problem file there",
    );
    #[cfg(unix)]
    {
        row(
            b"o,out,0 0 0",
            "DIR/out.json: the exercise file is a link out of the exercises folder (to OUT), \
             which is refused. Fix: copy the file into DIR",
        );
        row(
            b"p,gone,0 0 0",
            "DIR/gone.json: the exercise file cannot be followed: No such file or directory (os \
             error 2). Fix: replace the link by the file",
        );
    }
    (csv, want)
}

/// The reasons and the feedback of `csv` graded in English, in Portuguese by `--lang pt`, and
/// in Portuguese by the locale alone: the English reasons are `want` (with the folder's path
/// for DIR) in every language, and the Portuguese feedback has no English word.
fn check_reasons(csv: &[u8], want: &[&str], dir: &Path, args: &[&str]) {
    let out = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("exercises/4.3.json")
        .canonicalize()
        .unwrap();
    let want: Vec<String> = want
        .iter()
        .map(|w| {
            w.replace("DIR", &dir.display().to_string())
                .replace("OUT", &out.display().to_string())
        })
        .collect();
    let en = graded(csv, dir, args, None);
    let pt_flag = graded(csv, dir, &[args, &["--lang", "pt"]].concat(), None);
    let pt_locale = graded(csv, dir, args, Some(("LANG", "pt_BR.UTF-8")));
    for rows in [&en, &pt_flag, &pt_locale] {
        let reasons: Vec<&str> = rows
            .iter()
            .map(|r| r["reason"].as_str().unwrap_or(""))
            .collect();
        assert_eq!(reasons, want);
    }
    for (e, p) in en.iter().zip(&pt_flag) {
        let en_feedback = e["feedback"].as_str().unwrap();
        assert!(
            !english_in(en_feedback).is_empty(),
            "the list finds English: {en_feedback}"
        );
        let feedback = p["feedback"].as_str().unwrap();
        assert!(
            english_in(feedback).is_empty(),
            "English in the Portuguese feedback {feedback:?}: {:?}",
            english_in(feedback)
        );
        assert!(feedback.starts_with("Não"), "{feedback}");
    }
    assert_eq!(pt_flag, pt_locale);
}

#[test]
fn every_reason_of_a_row_is_portuguese_in_the_feedback_and_english_in_its_column() {
    let dir = exercises();
    let (csv, want) = rows();
    check_reasons(&csv, &want, dir.path(), &[]);
}

#[test]
fn the_steps_reasons_and_a_header_with_steps() {
    let dir = exercises();
    let csv = b"student,exercise,answer,steps\n\
                a,4.1,0 0 0,cos_theta=abc\n\
                b,4.1,0 0 0,foo=1\n\
                c,4.1,0.5,0.5,0.5\n\
                d;4.1\n";
    let want = [
        "the steps of row 1 (line 2, column \"steps\"): \"cos_theta=abc\": \"abc\" is not a value \
         for cos_theta: write one number, such as 0.98995 or 3/5",
        "the steps of row 2 (line 3, column \"steps\"): \"foo=1\": \"foo\" is not the name of a \
         step. Fix: use one of t, P, N, V, I_a, ambient, L, d, falloff_factor, cos_psi, \
         spot_factor, I_l, n_dot_l, cos_theta, diffuse, R, cos_phi, cos_phi_pow, specular, \
         total_diffuse, total_specular, I, r_v, reflection_weight, reflection_traced, \
         cos_theta_i, k, t_direction, transmission_weight, transmission_traced (a light's own \
         with [i], such as cos_theta[1])",
        "the row has 5 fields, expected 4 (student, exercise, answer, steps); an answer or a \
         steps cell written with ',' must be quoted: \"0.52, 0.03, 0\"",
        "the row has 1 field, expected 4 (student, exercise, answer, steps); the fields are read \
         as separated by ',', and this row has ';': give --delimiter ;",
    ];
    check_reasons(csv, &want, dir.path(), &[]);
}

#[test]
fn a_header_phong_refuses_is_said_in_portuguese() {
    let dir = exercises();
    let fix = "Fix: name the columns `student` (or `aluno`), `exercise` (`exercício`) and \
               `answer` (`resposta`), and, if the rows give steps, `steps` (`passos`), each \
               once, in any order";
    let twice = format!("the header names the student column twice. {fix}");
    check_reasons(
        b"student,student,answer\n",
        &[twice.as_str()],
        dir.path(),
        &[],
    );
    let missing = format!("the header names no answer column. {fix}");
    check_reasons(b"aluno;exercicio\n", &[missing.as_str()], dir.path(), &[]);
}

#[test]
fn a_moodle_export_phong_cannot_read_is_said_in_portuguese() {
    let dir = exercises();
    let moodle = ["--input", "moodle", "--questions", "4.1"];
    let cases: [(&[u8], &str); 3] = [
        (
            b"Surname,First name,Email address,State\nSilva,Ana,a@x,x\n",
            "the Moodle export has no \"Response 1\" column. Fix: download the quiz's Responses \
             report as CSV, or give --input csv for a plain CSV",
        ),
        (
            b"Surname,First name,Email address,Response 1,Response 2\nSilva,Ana,a@x,0 0 0,1 1 1\n",
            "the Moodle export has a \"Response 2\" column but only 1 exercise is given: name \
             one per question slot with --questions",
        ),
        // A byte that is not UTF-8 (0xFF): the file is read as Windows-1252 (issue 29), where
        // it is "ÿ", an answer that is no colour.
        (
            b"Surname,First name,Email address,Response 1\nSilva,Ana,a@x,\xff\n",
            "the answer cannot be read: \"\u{ff}\" is not three numbers; no number could be read \
             in it: write three numbers such as \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \"[0.52; 0.03; 0]\", three integers \
             0–255 with --scale 255, \"#RRGGBB\", or \"none\" when the ray hits nothing",
        ),
    ];
    for (csv, want) in cases {
        check_reasons(csv, &[want], dir.path(), &moodle);
    }
}

#[test]
fn a_graded_rows_notes_stay_in_the_reason_column() {
    // A note is no reason to refuse: the row is graded, its feedback the verdict's.
    let dir = exercises();
    let rows = graded(
        "aluno;exercício;resposta\nbia;4,1;128 0 0\n".as_bytes(),
        dir.path(),
        &["--lang", "pt"],
        None,
    );
    assert_eq!(
        rows[0]["reason"],
        "the exercise is written \"4,1\", read as 4.1 (a decimal comma, as a spreadsheet writes \
         the number 4.1; write 4.1 with a point to be sure); read as 8-bit values (0–255): the \
         numbers are whole and one is above 1"
    );
    let feedback = rows[0]["feedback"].as_str().unwrap();
    assert!(feedback.starts_with("Errada"), "{feedback}");
    assert!(english_in(feedback).is_empty(), "{feedback}");
}
