//! `phong grade` from the outside: every input row appears in the report exactly once, in input
//! order, whatever is wrong with it; the summary per exercise; CSV and JSON; exit codes.

use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

fn phong() -> Command {
    Command::cargo_bin("phong").unwrap()
}

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

/// Rows of every kind (student names a..o in order), with bad UTF-8 in row "h".
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
        [
            "a",
            "b",
            "c",
            "d",
            "e",
            "f",
            "g",
            "h\u{FFFD}",
            "i",
            "j",
            "k",
            "l",
            "m",
            "n",
            "o"
        ]
    );
    let numbers: Vec<String> = rows.iter().map(|r| r[0].to_owned()).collect();
    let expected: Vec<String> = (1..=15).map(|i| i.to_string()).collect();
    assert_eq!(numbers, expected);
    let verdicts: Vec<&str> = rows.iter().map(|r| &r[5]).collect();
    assert_eq!(
        verdicts,
        [
            "right", "wrong", "reading", "reading", "invalid", "invalid", "invalid", "invalid",
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
    assert!(reason(7).contains("not valid UTF-8"), "{}", reason(7));
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
    let s41 = of("4.1");
    assert_eq!(
        (s41["rows"].as_u64(), s41["invalid"].as_u64()),
        (Some(6), Some(4))
    );
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
