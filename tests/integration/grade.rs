//! `phong grade` from the outside: every input row appears in the report exactly once, in input
//! order, whatever is wrong with it; the summary per exercise; CSV and JSON; exit codes.

use std::path::Path;

use crate::support::{self, phong};
use predicates::prelude::*;
use serde_json::Value;

/// A folder with the chapter's three exercises and one broken exercise file.
fn exercises() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises");
    for f in ["4.1.json", "4.2.json", "4.3.json"] {
        std::fs::copy(src.join(f), dir.path().join(f)).unwrap();
    }
    std::fs::write(dir.path().join("broken.json"), "{ \"lights\": [").unwrap();
    dir
}

/// Rows of every kind (student names a..o in order), with a byte that is not UTF-8 in row "h"
/// (0xFF: the whole file is then read as Windows-1252, where it is "ÿ").
fn submissions() -> Vec<u8> {
    let mut csv = b"student,exercise,answer\n".to_vec();
    csv.extend_from_slice(
        b"a,4.1,0.5 0.7 0.3\n\
          b,4.2,0.245 0.28 0.21\n\
          c,4.2,\"0.299, 0.361, 0.318\"\n\
          d,4.3,(0.52 0.03 0)\n\
          e,4.9,0 0 0\n\
          f,4.1,0.5,0.7,0.3\n\
          g,4.1\n",
    );
    csv.extend_from_slice(b"h\xff,4.1,0.5 0.7 0.3\n");
    csv.extend_from_slice(
        b"i,../4.1,0.5 0.7 0.3\n\
          j,broken,0 0 0\n\
          k,4.1,half of it\n\
          l,,0 0 0\n\
          m,4.1,#80B34D\n\
          n,4.2,0.245 0.28 0.21\n\
          o,4.1.json,0.4 0.7 0.3\n",
    );
    csv
}

fn grade(csv: &[u8], dir: &Path, format: &str) -> (i32, String) {
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(input.path(), csv).unwrap();
    let out = phong()
        .arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir)
        .args(["--format", format])
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
    )
}

#[test]
fn every_row_appears_once_in_input_order_whatever_is_wrong_with_it() {
    let dir = exercises();
    let (code, out) = grade(&submissions(), dir.path(), "csv");
    assert_eq!(code, 0);
    let mut r = csv::Reader::from_reader(out.as_bytes());
    let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    let students: Vec<String> = rows.iter().map(|r| r[2].to_owned()).collect();
    assert_eq!(
        students,
        ["a", "b", "c", "d", "e", "f", "g", "hÿ", "i", "j", "k", "l", "m", "n", "o"]
    );
    let numbers: Vec<String> = rows.iter().map(|r| r[0].to_owned()).collect();
    let expected: Vec<String> = (1..=15).map(|i| i.to_string()).collect();
    assert_eq!(numbers, expected);
    let verdicts: Vec<&str> = rows.iter().map(|r| &r[5]).collect();
    assert_eq!(
        verdicts,
        [
            "right", "wrong", "reading", "reading", "invalid", "invalid", "invalid", "right",
            "invalid", "invalid", "invalid", "invalid", "right", "wrong", "wrong"
        ]
    );
    let reason = |i: usize| rows[i][17].to_owned();
    assert!(reason(4).contains("unknown exercise"), "{}", reason(4));
    assert!(
        reason(5).contains("5 fields") && reason(5).contains("quoted"),
        "{}",
        reason(5)
    );
    assert!(reason(6).contains("2 fields"), "{}", reason(6));
    // Issue 29: no row is invalid for its encoding alone.
    assert_eq!(reason(7), "");
    assert!(reason(8).contains("unknown exercise"), "{}", reason(8));
    assert!(reason(9).contains("broken.json"), "{}", reason(9));
    assert!(reason(10).contains("cannot be read"), "{}", reason(10));
    assert!(
        reason(11).contains("exercise field is empty"),
        "{}",
        reason(11)
    );
    // The diagnosis of b: the normal reversed, |cos θ|, …
    assert!(
        rows[1][16].starts_with("normal_reversed;abs_cos_theta"),
        "{}",
        &rows[1][16]
    );
}

#[test]
fn the_json_report_has_the_rows_and_a_summary_per_exercise() {
    let dir = exercises();
    let (code, out) = grade(&submissions(), dir.path(), "json");
    assert_eq!(code, 0);
    let json: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["format_version"], 1);
    assert_eq!(json["rows"].as_array().unwrap().len(), 15);
    let summary = json["summary"].as_array().unwrap();
    let of = |name: &str| {
        summary
            .iter()
            .find(|s| s["exercise"] == name)
            .unwrap()
            .clone()
    };
    let s42 = of("4.2");
    assert_eq!(
        (
            s42["rows"].as_u64(),
            s42["right"].as_u64(),
            s42["reading"].as_u64(),
            s42["wrong"].as_u64()
        ),
        (Some(3), Some(0), Some(1), Some(2))
    );
    // Both wrong 4.2 answers are the reversed normal: the most common slip, counted twice.
    assert_eq!(
        s42["slips"][0]["slips"],
        serde_json::json!(["normal_reversed"])
    );
    assert_eq!(s42["slips"][0]["count"], 2);
    // 4.1's rows: a, f, g, h, k, m and o, whose "4.1.json" names the same exercise; f, g and k
    // are invalid (h, read as Windows-1252, is right).
    let s41 = of("4.1");
    assert_eq!(
        (s41["rows"].as_u64(), s41["invalid"].as_u64()),
        (Some(7), Some(3))
    );
    assert!(summary.iter().all(|s| s["exercise"] != "4.1.json"));
    // Every row is counted once in the summary.
    let total: u64 = summary.iter().map(|s| s["rows"].as_u64().unwrap()).sum();
    assert_eq!(total, 15);
}

#[test]
fn the_same_submissions_give_the_same_bytes() {
    let dir = exercises();
    assert_eq!(
        grade(&submissions(), dir.path(), "json").1,
        grade(&submissions(), dir.path(), "json").1
    );
}

#[test]
fn a_file_without_a_header_is_all_rows() {
    let dir = exercises();
    let (_, out) = grade(b"ana,4.1,0.5 0.7 0.3\n", dir.path(), "csv");
    assert_eq!(out.lines().count(), 2, "{out}");
}

#[test]
fn the_report_and_summary_are_written_to_files() {
    let dir = exercises();
    let out_dir = tempfile::tempdir().unwrap();
    let input = out_dir.path().join("in.csv");
    std::fs::write(&input, submissions()).unwrap();
    let report = out_dir.path().join("report.csv");
    let summary = out_dir.path().join("summary.csv");
    phong()
        .arg("grade")
        .arg(&input)
        .arg("--exercises")
        .arg(dir.path())
        .arg("-o")
        .arg(&report)
        .arg("--summary")
        .arg(&summary)
        .assert()
        .code(0)
        .stdout("")
        .stderr(predicate::str::contains("graded 15 rows"));
    assert_eq!(
        std::fs::read_to_string(&report).unwrap().lines().count(),
        16
    );
    let s = std::fs::read_to_string(&summary).unwrap();
    assert!(
        s.starts_with("exercise,rows,right,reading,wrong,invalid,slips\n"),
        "{s}"
    );
    assert!(
        s.contains("4.2,3,0,1,2,0,normal_reversed:2;abs_cos_theta:2"),
        "{s}"
    );
}

#[test]
fn an_unreadable_csv_or_folder_exits_2() {
    let dir = exercises();
    phong()
        .args(["grade", "no-such-file.csv", "--exercises"])
        .arg(dir.path())
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "no-such-file.csv: cannot read the file",
        ));
    phong()
        .args(["grade", "no-such-file.csv", "--exercises", "no-such-folder"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--exercises: not a folder"));
}

#[test]
fn phong_policy_refuses_a_folder_that_does_not_exist_or_is_a_file() {
    // As `--exercises` does: a folder that is not one is named, with the fix, exit 2, and no
    // policy is printed.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("meu.json"), "{}").unwrap();
    for given in ["naoexiste/", "meu.json"] {
        let out = phong()
            .current_dir(dir.path())
            .args(["policy", given])
            .output()
            .unwrap();
        let en = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{given}: {en}");
        assert!(out.stdout.is_empty(), "{given}: a policy was printed");
        assert!(
            en.contains(&format!(
                "{given}: DIR: not a folder. Fix: give the folder that holds the exercise files"
            )),
            "{en}"
        );
        let out = phong()
            .current_dir(dir.path())
            .env("LANG", "pt_BR.UTF-8")
            .args(["policy", given])
            .output()
            .unwrap();
        let pt = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{given}: {pt}");
        assert!(
            pt.contains(&format!(
                "{given}: DIR: não é uma pasta. Correção: dê a pasta que tem os arquivos dos \
                 exercícios"
            )),
            "{pt}"
        );
    }
    // A folder is read as before; none given is the current folder.
    phong()
        .current_dir(dir.path())
        .args(["policy", "."])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("\"reading_credit\": 0.5"));
    phong()
        .current_dir(dir.path())
        .arg("policy")
        .assert()
        .code(0);
}

#[test]
fn grade_honours_each_keys_tolerance_and_accepts_no_hit() {
    let dir = exercises();
    // A key with its own tolerance ±0.05: (0.53, 0.7, 0.3) is 0.03 from (0.5, 0.7, 0.3), right
    // under the key (before the fix grade used the default ±0.005 and called it wrong).
    std::fs::write(
        dir.path().join("loose.json"),
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.7, 0.3]}},
            "answer": {"color": [0.5, 0.7, 0.3], "tolerance": 0.05}}"#,
    )
    .unwrap();
    let csv =
        b"student,exercise,answer\na,loose,0.53 0.7 0.3\nb,4.3,nenhuma\nc,4.3,0.524 0.027 0\n";
    let (code, out) = grade(csv, dir.path(), "json");
    assert_eq!(code, 0);
    let json: Value = serde_json::from_str(&out).unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows[0]["verdict"], "right", "{}", rows[0]);
    assert_eq!(rows[0]["tolerance"], 0.05);
    assert_eq!(rows[1]["verdict"], "right", "{}", rows[1]);
    assert_eq!(rows[2]["verdict"], "reading", "{}", rows[2]);
}

/// A report's CSV read by its header's names: one map per row.
fn by_name(csv_text: &str) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut r = csv::Reader::from_reader(csv_text.as_bytes());
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_owned).collect();
    r.records()
        .map(|rec| {
            header
                .iter()
                .cloned()
                .zip(rec.unwrap().iter().map(str::to_owned))
                .collect()
        })
        .collect()
}

// Exercise 4.2 by hand (as in tests/check.rs): P = (3, 1, 3), P_l = (1, 1, 1), so P − P_l =
// (2, 0, 2), d = 2√2 = 2.828427 and L = (0.707107, 0, 0.707107); N = (0.6, 0, 0.8), so
// N·L = (1.2 + 1.6)/(2√2) = 0.989949 and cos θ = −N·L = −0.989949 (Eq. 4.7): as written the
// light is behind the surface, and cos θ = +0.98995 is the likely intended reading's (L reversed).
// I_l = 1/d = 0.353553 with linear falloff; 1/d² = 0.125 is the quadratic slip. R = L − 2(N·L)N
// = (0.707107 − 1.187939, 0, 0.707107 − 1.583919) = (−0.480833, 0, −0.876812); with L reversed
// R is reversed too, so (−0.48, 0, −0.88) is right only as written. The colour as written is
// (0, 0, 0); the likely intended reading's (0.299, 0.361, 0.318).

#[test]
fn a_steps_column_in_a_comma_file_judges_each_rows_steps() {
    let dir = exercises();
    let csv = "student,exercise,answer,steps\n\
               ana,4.2,0 0 0,n_dot_l=0.98995; cos_theta=-0.98995\n\
               bia,4.2,0.299 0.361 0.318,cos_theta=0.98995\n\
               caio,4.2,0 0 0,I_l=0.125 0.125 0.125; d=2.83\n\
               davi,4.2,0 0 0,cos_thet=0.5\n\
               eva,4.2,0 0 0,cos_theta=abc\n\
               fabio,4.1,0.5 0.7 0.3,\n\
               gil,4.2,0 0 0,\"R=-0.48,0,-0.88\"\n\
               hugo,4.2,0 0 0,R=-0.48,0,-0.88\n\
               ivo,4.1,0.5 0.7 0.3\n";
    let (code, out) = grade(csv.as_bytes(), dir.path(), "csv");
    assert_eq!(code, 0, "{out}");
    let rows = by_name(&out);
    // Every row once, in order: the bad step cells did not stop the batch.
    let students: Vec<&str> = rows.iter().map(|r| r["student"].as_str()).collect();
    assert_eq!(
        students,
        ["ana", "bia", "caio", "davi", "eva", "fabio", "gil", "hugo", "ivo"]
    );
    let col = |i: usize, c: &str| rows[i][c].clone();
    // ana: both steps right as written (in the solution's order: N·L, then cos θ).
    assert_eq!(col(0, "verdict"), "right");
    assert_eq!(col(0, "steps_text"), "n_dot_l=0.98995; cos_theta=-0.98995");
    assert_eq!(
        col(0, "step_verdicts"),
        "n_dot_l[0]=right; cos_theta[0]=right"
    );
    assert_eq!(col(0, "first_wrong_step"), "");
    assert!(
        col(0, "feedback").contains("Every step given is right."),
        "{}",
        col(0, "feedback")
    );
    // bia: +0.98995 is wrong as written, right in the likely intended reading (L reversed).
    assert_eq!(col(1, "step_verdicts"), "cos_theta[0]=reading");
    assert_eq!(col(1, "first_wrong_step"), "cos_theta[0]");
    let f = col(1, "feedback");
    assert!(
        f.contains(
            "Step cos_theta[0] = 0.98995: wrong as written, right in the likely intended reading"
        ),
        "{f}"
    );
    assert!(f.contains("-0.989949 (the sign differs)"), "{f}");
    // caio: 1/d² for 1/d is the quadratic slip; the step does not cost the answer its points.
    assert_eq!(
        col(2, "step_verdicts"),
        "d[0]=right; I_l[0]=wrong(falloff_quadratic_not_linear)"
    );
    assert_eq!(col(2, "first_wrong_step"), "I_l[0]");
    assert_eq!(
        (col(2, "verdict").as_str(), col(2, "points").as_str()),
        ("right", "1")
    );
    assert!(
        col(2, "feedback").contains("First wrong step: I_l[0]"),
        "{}",
        col(2, "feedback")
    );
    // davi and eva: the row's error names the row, the column, what was written and the fix.
    assert_eq!(col(3, "verdict"), "invalid");
    let r = col(3, "reason");
    assert!(r.contains("row 4 (line 5"), "{r}");
    assert!(r.contains("column \"steps\""), "{r}");
    assert!(r.contains("\"cos_thet=0.5\""), "{r}");
    assert!(
        r.contains("is not the name of a step. Fix: use one of"),
        "{r}"
    );
    assert!(r.contains("cos_theta"), "{r}");
    assert_eq!(col(4, "verdict"), "invalid");
    let r = col(4, "reason");
    assert!(
        r.contains("row 5 (line 6") && r.contains("\"abc\" is not a value for cos_theta"),
        "{r}"
    );
    // fabio: an empty cell is no steps; ivo: a row without the last cell is one too.
    for i in [5, 8] {
        assert_eq!(col(i, "verdict"), "right");
        assert_eq!(col(i, "step_verdicts"), "");
    }
    // gil (quoted) and hugo (not quoted: the fields after the answer are the steps cell): R is
    // right as written.
    assert_eq!(col(6, "step_verdicts"), "R[0]=right");
    assert_eq!(col(7, "step_verdicts"), "R[0]=right", "{:?}", rows[7]);
    assert_eq!(col(7, "steps_text"), "R=-0.48,0,-0.88");
}

#[test]
fn a_steps_column_in_a_semicolon_file_with_decimal_commas() {
    let dir = exercises();
    let csv = "aluno;exercício;resposta;passos\n\
               ana;4.2;0 0 0;n_dot_l=0,98995; cos_theta=-0,98995\n\
               bia;4.2;0,299 0,361 0,318;\"cos_theta=0,98995; R=-0,48 0 -0,88\"\n\
               caio;4.2;0 0 0;I_l=0,125 0,125 0,125\n\
               davi;4.2;0 0 0;cos_teta=0,5\n\
               eva;4.2;0 0 0;cos_theta=0,9,8\n\
               fabio;4.1;0,5 0,7 0,3\n";
    let (code, out) = grade(csv.as_bytes(), dir.path(), "json");
    assert_eq!(code, 0, "{out}");
    let json: Value = serde_json::from_str(&out).unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 6);
    let verdicts = |i: usize| -> Vec<(String, String)> {
        rows[i]["steps"]["steps"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| {
                (
                    s["name"].as_str().unwrap().to_owned(),
                    s["verdict"].as_str().unwrap().to_owned(),
                )
            })
            .collect()
    };
    let pair = |n: &str, v: &str| (n.to_owned(), v.to_owned());
    // ana: the `;` inside the unquoted cell separates steps, not fields.
    assert_eq!(
        verdicts(0),
        [pair("n_dot_l", "right"), pair("cos_theta", "right")]
    );
    assert_eq!(rows[0]["steps"]["steps"][0]["given"], 0.98995);
    assert_eq!(rows[0]["steps"]["first_wrong"], Value::Null);
    // bia: cos θ of the likely intended reading, R right as written.
    assert_eq!(
        verdicts(1),
        [pair("cos_theta", "reading"), pair("R", "right")]
    );
    let cos = &rows[1]["steps"]["steps"][0];
    assert_eq!(cos["reading"], "light_reversed");
    assert_eq!(cos["sign_reversed"], true);
    assert_eq!(
        rows[1]["steps"]["steps"][1]["given"],
        serde_json::json!([-0.48, 0.0, -0.88])
    );
    assert_eq!(rows[1]["steps"]["first_wrong"]["name"], "cos_theta");
    assert_eq!(rows[1]["steps"]["first_wrong"]["equation"], "4.7");
    // The answer is the reading's: half of the point, whatever the steps.
    assert_eq!(rows[1]["verdict"], "reading");
    assert_eq!(rows[1]["points"], 0.5);
    // caio: the slip, named.
    assert_eq!(verdicts(2), [pair("I_l", "wrong")]);
    assert_eq!(
        rows[2]["steps"]["steps"][0]["slips"],
        serde_json::json!(["falloff_quadratic_not_linear"])
    );
    assert_eq!(rows[2]["points"], 1.0);
    // davi, eva: invalid, the batch goes on; fabio has no steps.
    assert_eq!(rows[3]["verdict"], "invalid");
    let r = rows[3]["reason"].as_str().unwrap();
    assert!(
        r.contains("column \"passos\"") && r.contains("\"cos_teta\""),
        "{r}"
    );
    assert_eq!(rows[4]["verdict"], "invalid");
    assert!(
        rows[4]["reason"].as_str().unwrap().contains("\"0,9,8\""),
        "{}",
        rows[4]
    );
    assert_eq!(rows[5]["verdict"], "right");
    assert_eq!(rows[5]["steps"], Value::Null);
    assert_eq!(rows[5]["steps_text"], "");
}

#[test]
fn step_feedback_in_portuguese() {
    let dir = exercises();
    let csv = "aluno;exercício;resposta;passos\nbia;4.2;0,299 0,361 0,318;cos_theta=0,98995\n";
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(input.path(), csv).unwrap();
    let out = phong()
        .arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir.path())
        .args(["--format", "json", "--lang", "pt"])
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    let f = json["rows"][0]["feedback"].as_str().unwrap();
    assert!(
        f.contains(
            "Passo cos_theta[0] = 0.98995: errado como enunciado, certo na leitura \
             provavelmente pretendida"
        ),
        "{f}"
    );
    assert!(
        f.contains("Primeiro passo errado como enunciado: cos_theta[0]"),
        "{f}"
    );
}

#[test]
fn a_header_of_column_names_without_the_answer_is_a_row_saying_so() {
    let dir = exercises();
    // Before: "aluno;exercício;passos" was read as a row (exercise "exercício" unknown) and the
    // steps column could not be named. Now it is an invalid line that counts for no one, saying
    // which column is missing, and the rows after it are read as student, exercise, answer.
    let csv = "aluno;exercício;passos\nana;4.1;0,5 0,7 0,3\n";
    let (code, out) = grade(csv.as_bytes(), dir.path(), "json");
    assert_eq!(code, 0);
    let json: Value = serde_json::from_str(&out).unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["verdict"], "invalid");
    assert_eq!(rows[0]["counted"], false);
    let r = rows[0]["reason"].as_str().unwrap();
    assert!(
        r.starts_with("the header names no answer column. Fix: name the columns"),
        "{r}"
    );
    assert!(
        !rows[0]["feedback"].as_str().unwrap().contains("no student"),
        "{}",
        rows[0]
    );
    assert_eq!(rows[1]["verdict"], "right");
    assert_eq!(json["students"].as_array().unwrap().len(), 1);
    // A column named twice.
    let (_, out) = grade(
        b"student,exercise,answer,answer\na,4.1,0.5 0.7 0.3\n",
        dir.path(),
        "json",
    );
    let json: Value = serde_json::from_str(&out).unwrap();
    let r = json["rows"][0]["reason"].as_str().unwrap();
    assert!(
        r.starts_with("the header names the answer column twice"),
        "{r}"
    );
}

#[test]
fn an_output_that_cannot_be_written_stops_before_anything_is_and_says_no_graded_line() {
    // QA finding 8: the folders of -o, --summary and --by-student are checked before anything
    // is written, so a bad --summary leaves no report behind; and after a write that fails,
    // no "graded N rows" line reads as success.
    let (dir, work, input) = a_class_run();
    let run = |args: &[&str]| {
        let out = phong()
            .current_dir(work.path())
            .arg("grade")
            .arg(&input)
            .arg("--exercises")
            .arg(dir.path())
            .args(args)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let (code, err) = run(&["-o", "nodir/r.csv"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("cannot write nodir/r.csv: the folder nodir does not exist"),
        "{err}"
    );
    assert!(
        err.contains("Fix: create it first (mkdir -p nodir)"),
        "{err}"
    );
    assert!(!err.contains("graded"), "{err}");
    let (code, err) = run(&["-o", "r.csv", "--summary", "nodir/s.csv"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("cannot write nodir/s.csv: the folder nodir does not exist"),
        "{err}"
    );
    assert!(
        !work.path().join("r.csv").exists(),
        "the report was written"
    );
    let (code, err) = run(&[
        "--lang",
        "pt",
        "-o",
        "r.csv",
        "--by-student",
        "in.csv/t.csv",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("escrever in.csv/t.csv: ") && err.contains("in.csv não é uma pasta"),
        "{err}"
    );
    assert!(!err.contains("avaliadas"), "{err}");
    assert!(
        !work.path().join("r.csv").exists(),
        "the report was written"
    );
    // A write that fails all the same (the report's path is a folder): the error, then neither
    // the summary nor the graded line.
    std::fs::create_dir(work.path().join("taken")).unwrap();
    let (code, err) = run(&["-o", "taken", "--summary", "s.csv"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("cannot write taken"), "{err}");
    assert!(!err.contains("graded"), "{err}");
    assert!(
        !work.path().join("s.csv").exists(),
        "the summary was written"
    );
}

/// A run's exercises, its working folder and the class's submissions in it (`in.csv`).
fn a_class_run() -> (tempfile::TempDir, tempfile::TempDir, std::path::PathBuf) {
    let dir = exercises();
    let work = tempfile::tempdir().unwrap();
    let input = work.path().join("in.csv");
    std::fs::write(&input, submissions()).unwrap();
    (dir, work, input)
}

/// Files of a folder whose names start with `.phong-` (temporary files left behind).
fn temporary_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".phong-"))
        .collect()
}

/// QA: `echo OLD > r6.csv; phong grade … -o r6.csv --class-report /sys/x.html` exited 2 with
/// r6.csv already replaced, and so did a failing --summary or --by-student after -o. The
/// outputs are all or nothing: whichever one cannot be written (here a path that is a folder,
/// which no check before the writing catches), every other output keeps what it held, no
/// temporary file is left, and no "graded" line is said.
#[test]
fn an_output_that_fails_leaves_every_other_output_as_it_was() {
    let (dir, work, input) = a_class_run();
    std::fs::create_dir(work.path().join("taken")).unwrap();
    let flags = [
        ("-o", "r.csv"),
        ("--summary", "s.csv"),
        ("--by-student", "b.csv"),
        ("--class-report", "c.html"),
    ];
    for failing in flags.map(|(flag, _)| flag) {
        for (_, file) in flags {
            std::fs::write(work.path().join(file), "OLD\n").unwrap();
        }
        let mut cmd = phong();
        cmd.current_dir(work.path())
            .arg("grade")
            .arg(&input)
            .arg("--exercises")
            .arg(dir.path());
        for (flag, file) in flags {
            cmd.arg(flag)
                .arg(if flag == failing { "taken" } else { file });
        }
        let out = cmd.output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{failing}: {err}");
        assert!(err.contains("cannot write taken"), "{failing}: {err}");
        assert!(!err.contains("graded"), "{failing}: {err}");
        for (flag, file) in flags.iter().filter(|(flag, _)| *flag != failing) {
            assert_eq!(
                std::fs::read_to_string(work.path().join(file)).unwrap(),
                "OLD\n",
                "{flag} {file} was replaced though {failing} failed"
            );
        }
        assert_eq!(temporary_files(work.path()), Vec::<String>::new());
    }
}

/// A device that refuses the bytes (/dev/full) fails after every file is written to its
/// temporary file: the files are still not put in place.
#[cfg(target_os = "linux")]
#[test]
fn a_device_that_fails_keeps_the_files_of_the_run_as_they_were() {
    let (dir, work, input) = a_class_run();
    let report = work.path().join("r.csv");
    std::fs::write(&report, "OLD\n").unwrap();
    let out = phong()
        .arg("grade")
        .arg(&input)
        .arg("--exercises")
        .arg(dir.path())
        .arg("-o")
        .arg(&report)
        .args(["--by-student", "/dev/full"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("cannot write /dev/full"), "{err}");
    assert_eq!(std::fs::read_to_string(&report).unwrap(), "OLD\n");
    assert_eq!(temporary_files(work.path()), Vec::<String>::new());
}

/// `--format gradescope -o DIR/`: a run that fails after the students' files were written
/// leaves no folder behind; and a student's file that would replace an input (-o the
/// exercises' folder, a student named "4.2") is refused, the exercise kept.
#[test]
fn a_gradescope_folder_is_all_or_nothing_and_never_replaces_an_exercise() {
    let (dir, work, input) = a_class_run();
    std::fs::create_dir(work.path().join("taken")).unwrap();
    let folder = work.path().join("gs").join("out");
    let out = phong()
        .arg("grade")
        .arg(&input)
        .arg("--exercises")
        .arg(dir.path())
        .args(["--format", "gradescope", "-o"])
        .arg(format!("{}/", folder.display()))
        .arg("--class-report")
        .arg(work.path().join("taken"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        !work.path().join("gs").exists(),
        "the folder was left behind"
    );

    std::fs::write(&input, "student,exercise,answer\n4.2,4.1,0.5 0.7 0.3\n").unwrap();
    let exercise = dir.path().join("4.2.json");
    let before = std::fs::read(&exercise).unwrap();
    let out = phong()
        .arg("grade")
        .arg(&input)
        .arg("--exercises")
        .arg(dir.path())
        .args(["--format", "gradescope", "-o"])
        .arg(format!("{}/", dir.path().display()))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("is the input"), "{err}");
    assert_eq!(std::fs::read(&exercise).unwrap(), before);
}

/// `phong grade` run by `sh` under an address-space limit of `limit_mb` MiB (`ulimit -v`),
/// standard output read as it comes: (exit code, the lines of standard output counted, standard
/// error).
fn grade_limited(limit_mb: u64, args: &[&std::ffi::OsStr]) -> (Option<i32>, usize, String) {
    use std::io::Read;
    let mut child = support::sh()
        .arg("-c")
        .arg(format!("ulimit -v {}; exec \"$0\" \"$@\"", limit_mb * 1024))
        .arg(support::phong_path())
        .arg("grade")
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = child.stdout.take().unwrap();
    let mut lines = 0;
    let mut buf = vec![0u8; 1 << 16];
    loop {
        let n = out.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        lines += buf[..n].iter().filter(|&&b| b == b'\n').count();
    }
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (child.wait().unwrap().code(), lines, err)
}

/// README allows 1,000,000 rows: a header and 1,000,000 rows are graded (they were refused as
/// "more than 1000000 rows": the header was counted), one row more is refused with exit 2.
#[test]
fn a_header_and_a_million_rows_are_graded_and_one_more_is_refused() {
    let dir = exercises();
    let work = tempfile::tempdir().unwrap();
    // The cheapest row to grade: an exercise the folder does not have.
    let mut csv = b"student,exercise,answer\n".to_vec();
    for _ in 0..1_000_000 {
        csv.extend_from_slice(b"s,x,1\n");
    }
    let million = work.path().join("million.csv");
    std::fs::write(&million, &csv).unwrap();
    let (code, lines, err) = grade_limited(
        4096,
        &[
            million.as_os_str(),
            "--exercises".as_ref(),
            dir.path().as_os_str(),
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    // The report's header and a line per row (no cell holds a line break).
    assert_eq!(lines, 1 + 1_000_000);
    assert!(err.contains("graded 1000000 rows"), "{err}");
    // One row more, with or without the header: refused before anything is graded.
    csv.extend_from_slice(b"s,x,1\n");
    let over = work.path().join("over.csv");
    std::fs::write(&over, &csv).unwrap();
    let headless = work.path().join("headless.csv");
    std::fs::write(&headless, &csv[b"student,exercise,answer\n".len()..]).unwrap();
    for file in [&over, &headless] {
        let out = phong()
            .arg("grade")
            .arg(file)
            .arg("--exercises")
            .arg(dir.path())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains("more than 1000000 rows"), "{err}");
        assert!(out.stdout.is_empty());
    }
}

/// The reports are written one row at a time: 250,000 rows of as many students are graded in
/// every format within 400 MiB of address space (the whole report held in memory took about
/// 2.5 kB a row for CSV and 10 kB for Gradescope's results: 600 MB to 2.5 GB here). Every row
/// is in the report.
#[test]
fn a_large_class_is_graded_in_bounded_memory_in_every_format() {
    let dir = exercises();
    let work = tempfile::tempdir().unwrap();
    let rows = 250_000;
    let mut csv = String::from("student,exercise,answer\n");
    for i in 0..rows {
        // One student a row, and an exercise the folder does not have: each row a test of its
        // own in the platforms' reports.
        csv.push_str(&format!("student{i},x,0.5 0.5 0.5\n"));
    }
    let input = work.path().join("class.csv");
    std::fs::write(&input, csv).unwrap();
    for format in ["csv", "json", "junit", "gradescope"] {
        let (code, lines, err) = grade_limited(
            400,
            &[
                input.as_os_str(),
                "--exercises".as_ref(),
                dir.path().as_os_str(),
                "--format".as_ref(),
                format.as_ref(),
            ],
        );
        assert_eq!(code, Some(0), "{format}: {err}");
        assert!(
            err.contains(&format!("graded {rows} rows")),
            "{format}: {err}"
        );
        // Lines per row: CSV 1; JUnit a testsuite per student (2 lines) holding the row's
        // testcase (no exercise was graded: x is none); JSON and Gradescope at least the
        // row's fields, one a line.
        let least = match format {
            "csv" => rows + 1,
            "junit" => rows * 3,
            _ => rows * 10,
        };
        assert!(lines >= least, "{format}: {lines} lines for {rows} rows");
    }
}

// Issue 29: Excel in Brazil saves "CSV" in Windows-1252. "João" is then the bytes 4A 6F E3 6F
// (ã = 0xE3) and "Conceição" has ç = 0xE7 and ã = 0xE3: no UTF-8 text holds them. The file is
// read as Windows-1252, the names come through whole, the rows are graded as any other, and
// standard error says once which encoding was assumed, naming the file.
#[test]
fn a_windows_1252_class_file_keeps_every_name() {
    let dir = exercises();
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(
        input.path(),
        b"aluno;exercicio;resposta\r\nJo\xe3o;4.1;0,5 0,7 0,3\r\nConcei\xe7\xe3o;4.2;0 0 0\r\n\
          Jos\xe9;4.1;abc\r\n",
    )
    .unwrap();
    let out = phong()
        .arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir.path())
        .args(["--lang", "en"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let mut r = csv::Reader::from_reader(&out.stdout[..]);
    let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    let got: Vec<(&str, &str)> = rows.iter().map(|r| (&r[2], &r[5])).collect();
    assert_eq!(
        got,
        [
            ("João", "right"),
            ("Conceição", "right"),
            ("José", "invalid")
        ]
    );
    // José's row is invalid for its answer, not its encoding.
    assert!(rows[2][17].contains("\"abc\""), "{}", &rows[2][17]);
    let err = String::from_utf8(out.stderr).unwrap();
    let warning = format!(
        "warning: {}: the file is not UTF-8: it was read as Windows-1252",
        input.path().display()
    );
    assert_eq!(err.matches(&warning).count(), 1, "{err}");
}

/// The workbook twice, a second apart: the same bytes (QA: docProps/core.xml held the time of
/// the run). With SOURCE_DATE_EPOCH it says that time instead, again the same bytes each run;
/// a SOURCE_DATE_EPOCH that is not a time is refused (exit 2) and the old workbook kept.
#[test]
fn the_grade_workbook_is_the_same_bytes_on_every_run() {
    let dir = exercises();
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(input.path(), submissions()).unwrap();
    let out_dir = tempfile::tempdir().unwrap();
    let book = |name: &str, epoch: Option<&str>| {
        let path = out_dir.path().join(name);
        let mut cmd = phong();
        cmd.env_remove("SOURCE_DATE_EPOCH");
        if let Some(e) = epoch {
            cmd.env("SOURCE_DATE_EPOCH", e);
        }
        let out = cmd
            .arg("grade")
            .arg(input.path())
            .arg("--exercises")
            .arg(dir.path())
            .args(["--format", "xlsx", "-o"])
            .arg(&path)
            .output()
            .unwrap();
        (out.status.code(), std::fs::read(&path).unwrap())
    };
    let (code, first) = book("a.xlsx", None);
    assert_eq!(code, Some(0));
    std::thread::sleep(std::time::Duration::from_millis(1100));
    let (_, second) = book("b.xlsx", None);
    assert!(first == second, "two runs a second apart differ");
    let (code, dated) = book("c.xlsx", Some("1700000000"));
    assert_eq!(code, Some(0));
    assert!(dated != first, "SOURCE_DATE_EPOCH is not in the workbook");
    std::thread::sleep(std::time::Duration::from_millis(1100));
    assert!(book("d.xlsx", Some("1700000000")).1 == dated);
    std::fs::write(out_dir.path().join("e.xlsx"), "OLD").unwrap();
    let (code, kept) = book("e.xlsx", Some("yesterday"));
    assert_eq!(code, Some(2));
    assert_eq!(kept, b"OLD");
}

// Issue 29: `--format xlsx` writes a workbook a spreadsheet opens: read back by a spreadsheet
// reader, its answers' sheet holds numbers as numbers (points, the expected colour, the
// tolerance) and the verdicts in words of the chosen language, and the students' sheet the
// totals worked out by hand: ana 4.1 right (1) + 4.2 |cos θ| wrong (0) = 1 of 3; bia 4.3
// "nenhuma" right (1) + 4.2 the likely intended reading (half of 1) = 1.5 of 3 (three
// exercises graded, 1 point each).
#[test]
fn the_grade_workbook_reads_back_with_numbers_and_totals() {
    use calamine::{open_workbook, Data, Reader, Xlsx};
    let dir = exercises();
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(
        input.path(),
        "aluno;exercicio;resposta\nana;4.1;0,5 0,7 0,3\nana;4.2;0.245 0.28 0.21\n\
         bia;4.3;nenhuma\nbia;4.2;0.3 0.36 0.32\n",
    )
    .unwrap();
    let out_dir = tempfile::tempdir().unwrap();
    let book = out_dir.path().join("notas.xlsx");
    phong()
        .arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir.path())
        .args(["--format", "xlsx", "--lang", "pt", "-o"])
        .arg(&book)
        .assert()
        .code(0);
    let mut wb: Xlsx<_> = open_workbook(&book).unwrap();
    assert_eq!(wb.sheet_names(), ["Respostas", "Alunos", "Resumo", "Turma"]);
    let answers = wb.worksheet_range("Respostas").unwrap();
    let cell = |r: u32, c: u32| answers.get_value((r, c)).cloned();
    assert_eq!(cell(0, 2), Some(Data::String("Aluno".into())));
    assert_eq!(cell(1, 2), Some(Data::String("ana".into())));
    assert_eq!(cell(1, 5), Some(Data::String("certa".into())));
    assert_eq!(cell(1, 6), Some(Data::Float(1.0)));
    assert_eq!(cell(1, 10), Some(Data::Float(0.005)));
    assert_eq!(cell(1, 11), Some(Data::Float(0.5)));
    assert_eq!(cell(2, 5), Some(Data::String("errada".into())));
    assert_eq!(cell(2, 6), Some(Data::Float(0.0)));
    assert_eq!(cell(4, 5), Some(Data::String("leitura".into())));
    assert_eq!(cell(4, 6), Some(Data::Float(0.5)));
    let students = wb.worksheet_range("Alunos").unwrap();
    let row = |r: u32| -> Vec<Data> {
        (0..3)
            .map(|c| students.get_value((r, c)).cloned().unwrap())
            .collect()
    };
    assert_eq!(
        row(1),
        [
            Data::String("ana".into()),
            Data::Float(1.0),
            Data::Float(3.0)
        ]
    );
    assert_eq!(
        row(2),
        [
            Data::String("bia".into()),
            Data::Float(1.5),
            Data::Float(3.0)
        ]
    );
    let summary = wb.worksheet_range("Resumo").unwrap();
    // 4.2: two answers, one wrong, one by the reading.
    let line = (1..summary.height() as u32)
        .find(|&r| summary.get_value((r, 0)) == Some(&Data::String("4.2".into())))
        .unwrap();
    let counts: Vec<Data> = (1..6)
        .map(|c| summary.get_value((line, c)).cloned().unwrap())
        .collect();
    assert_eq!(counts, [2.0, 0.0, 1.0, 1.0, 0.0].map(Data::Float));
}

// Issue 29: what the class got wrong. A class of 30 answering 4.2, counted by hand: 10 black
// (right as written), 6 the likely intended reading (L reversed, (0.299, 0.361, 0.318)), 5
// 0.245 0.28 0.21 (|cos θ|, which is also the normal reversed, and V reversed in the reading:
// three slips, each counted 5 times), 4 0.5 0.4 0.6 (an ambient light assumed), 3 grey 0.9 that
// no slip gives, 2 unreadable. Their totals (1 point each): 10 at 100 %, 6 at 50 %, 14 at 0 %.
#[test]
fn the_class_report_counts_each_slip_as_counted_by_hand() {
    let dir = exercises();
    let mut csv = String::from("aluno;exercicio;resposta\n");
    let answers = [
        ("0 0 0", 10),
        ("0.3 0.36 0.32", 6),
        ("0.245 0.28 0.21", 5),
        ("0.5 0.4 0.6", 4),
        ("0.9 0.9 0.9", 3),
        ("abc", 2),
    ];
    let mut n = 0;
    for (answer, count) in answers {
        for _ in 0..count {
            n += 1;
            csv.push_str(&format!("s{n:02};4.2;{answer}\n"));
        }
    }
    assert_eq!(n, 30);
    let input = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(input.path(), csv).unwrap();
    let out = tempfile::tempdir().unwrap();
    let page = out.path().join("aula.html");
    phong()
        .arg("grade")
        .arg(input.path())
        .arg("--exercises")
        .arg(dir.path())
        .args(["--lang", "pt", "-o"])
        .arg(out.path().join("notas.csv"))
        .arg("--class-report")
        .arg(&page)
        .assert()
        .code(0);
    let html = std::fs::read_to_string(&page).unwrap();
    let count = |kind: &str, words: &str| -> usize {
        let at = html
            .find(&format!("<tr data-kind=\"{kind}\"><td>{words}"))
            .unwrap_or_else(|| panic!("no {kind} {words}:\n{html}"));
        let row = &html[at..at + html[at..].find("</tr>").unwrap()];
        let n = row.rsplit("<td>").next().unwrap().trim_end_matches("</td>");
        n.parse().unwrap()
    };
    assert_eq!(count("right", "certas"), 10);
    assert_eq!(count("reading", "certas pela leitura"), 6);
    assert_eq!(count("slip", "erro: |cos θ|"), 5);
    assert_eq!(count("slip", "erro: a normal invertida"), 5);
    // V reversed in the reading is, against the problem as written, L and V both reversed.
    assert_eq!(
        count(
            "slip",
            "erro: L invertido: tomado do ponto para a luz, o oposto da Eq. 4.1; e V invertido"
        ),
        5
    );
    assert_eq!(count("slip", "erro: um termo ambiente"), 4);
    assert_eq!(count("unnamed", "erradas"), 3);
    assert_eq!(count("invalid", "ilegíveis"), 2);
    for (bin, students) in [
        ("0–9 %", 14),
        ("50–59 %", 6),
        ("90–100 %", 10),
        ("10–19 %", 0),
    ] {
        assert!(
            html.contains(&format!("<tr><td>{bin}</td><td>{students}</td></tr>")),
            "{bin}: {html}"
        );
    }
    assert!(html.contains("30 alunos, 30 respostas"), "{html}");
}

#[test]
fn points_beyond_a_million_are_refused_from_the_policy_and_the_flag_and_a_million_add_up() {
    // 1e308 points each made a student's maximum 2e308 = inf: `--by-student` wrote `inf`,
    // Gradescope `"score": null`. An exercise is worth at most 1,000,000 points.
    let dir = exercises();
    let out_dir = tempfile::tempdir().unwrap();
    let input = out_dir.path().join("in.csv");
    std::fs::write(
        &input,
        "student,exercise,answer\nann,4.1,0.5 0.7 0.3\nann,4.2,0 0 0\n",
    )
    .unwrap();
    let by_student = out_dir.path().join("by-student.csv");
    let run = |extra: &[&str]| {
        phong()
            .arg("grade")
            .arg(&input)
            .arg("--exercises")
            .arg(dir.path())
            .arg("--by-student")
            .arg(&by_student)
            .args(extra)
            .output()
            .unwrap()
    };
    let policy = dir.path().join("course-policy.json");
    std::fs::write(&policy, r#"{"points": {"4.2": 1e308, "4.1": 1e308}}"#).unwrap();
    for (extra, says) in [
        (
            &[][..],
            [
                "course-policy.json: points: the points of 4.1 (1e308)",
                "must be a number from 0 to 1000000",
            ],
        ),
        (
            &["--lang", "pt"][..],
            [
                "course-policy.json: points: os pontos de 4.1 (1e308)",
                "devem ser um número de 0 a 1000000",
            ],
        ),
    ] {
        let out = run(extra);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(says.iter().all(|s| err.contains(s)), "{says:?} in {err}");
    }
    std::fs::write(&policy, r#"{"default_points": 1000000.5}"#).unwrap();
    let out = run(&[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("course-policy.json: default_points: ")
            && err.contains("(1000000.5) must be a number from 0 to 1000000"),
        "{err}"
    );
    std::fs::remove_file(&policy).unwrap();
    let out = run(&["--points", "4.2=1e308,4.1=1e308"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--points: points: the points of 4.2 (1e308)")
            && err.contains("must be a number from 0 to 1000000"),
        "{err}"
    );
    assert!(!by_student.exists());
    // At the most, both right: 1,000,000 + 1,000,000 = 2,000,000 of 2,000,000.
    let out = run(&["--points", "4.1=1000000,4.2=1000000"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let totals = std::fs::read_to_string(&by_student).unwrap();
    assert!(totals.contains("ann,2000000,2000000,"), "{totals}");
}
