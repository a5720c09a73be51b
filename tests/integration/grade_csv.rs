//! The submissions CSV of `phong grade` as people's spreadsheets write it: separators, encodings,
//! headers in English and Portuguese, line ends, quoting mistakes, hostile cells; and the
//! property that every input line holding data is one row of the report, exactly once, in order,
//! over generated hostile files (random quoting, separators, line ends, encodings, blank lines,
//! NUL bytes and bad UTF-8).

use crate::support;

use std::path::{Path, PathBuf};

use phong::check::grade::{grade_bytes, rows_csv, Options, Report, RowOut};
use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, RngSeed, TestRunner};

fn folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises")
}

fn options(delimiter: Option<u8>) -> Options {
    Options {
        exercises: folder(),
        scale: None,
        delimiter,
        ..Options::default()
    }
}

fn grade(bytes: &[u8]) -> Report {
    grade_bytes(bytes, &options(None))
}

/// (line, student, verdict) of each row.
fn summary(report: &Report) -> Vec<(u64, String, &'static str)> {
    report
        .rows
        .iter()
        .map(|r| (r.line, r.student.clone(), r.verdict))
        .collect()
}

fn row(line: u64, student: &str, verdict: &'static str) -> (u64, String, &'static str) {
    (line, student.to_owned(), verdict)
}

// 4.1's colour is O_a·I_a = (0.5, 0.7, 0.3) under a white ambient light.
const RIGHT: &str = "0.5 0.7 0.3";

#[test]
fn a_brazilian_spreadsheet_export_is_graded_row_by_row() {
    // `;` between fields, decimal commas in the answers, a Portuguese header, CRLF.
    let csv = "aluno;exercicio;resposta\r\nana;4.1;0,5 0,7 0,3\r\nbia;4.1;0,4 0,7 0,3\r\n";
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [row(2, "ana", "right"), row(3, "bia", "wrong")]
    );
    // The header's other names, accents and capitals, in another order.
    let csv = "Resposta;Aluno;Questão\n0,5 0,7 0,3;ana;4.1\n";
    assert_eq!(summary(&grade(csv.as_bytes())), [row(2, "ana", "right")]);
    let csv = "ESTUDANTE\tEXERCÍCIO\tRESPOSTA\nana\t4.1\t0.5 0.7 0.3\n";
    assert_eq!(summary(&grade(csv.as_bytes())), [row(2, "ana", "right")]);
}

#[test]
fn tabs_and_a_forced_separator_are_read() {
    let csv = format!("ana\t4.1\t{RIGHT}\nbia\t4.1\t0 0 0\n");
    assert_eq!(
        summary(&grade(csv.as_bytes())),
        [row(1, "ana", "right"), row(2, "bia", "wrong")]
    );
    // Forced: a comma file read with `;` has one field per row, and the reason says why.
    let r = grade_bytes(
        format!("ana,4.1,{RIGHT}\n").as_bytes(),
        &options(Some(b';')),
    );
    let reason = r.rows[0].reason.as_ref().unwrap().to_string();
    assert!(
        reason.contains("1 field") && reason.contains("--delimiter ,"),
        "{reason}"
    );
}

#[test]
fn utf8_with_a_bom_and_utf16_with_a_bom_are_decoded() {
    let text = format!("student,exercise,answer\r\nana,4.1,{RIGHT}\r\nbia,4.1,0 0 0\r\n");
    let want = [row(2, "ana", "right"), row(3, "bia", "wrong")];
    let mut bom8 = b"\xEF\xBB\xBF".to_vec();
    bom8.extend_from_slice(text.as_bytes());
    assert_eq!(summary(&grade(&bom8)), want);
    let mut le = vec![0xFF, 0xFE];
    let mut be = vec![0xFE, 0xFF];
    for u in text.encode_utf16() {
        le.extend_from_slice(&u.to_le_bytes());
        be.extend_from_slice(&u.to_be_bytes());
    }
    assert_eq!(summary(&grade(&le)), want);
    assert_eq!(summary(&grade(&be)), want);
}

#[test]
fn an_unterminated_quote_is_its_own_row_and_eats_nothing() {
    let csv = format!("s1,4.1,\"0 0 0\ns2,4.1,{RIGHT}\ns3,4.1,{RIGHT}\ns4,4.1,{RIGHT}\n");
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [
            row(1, "s1", "invalid"),
            row(2, "s2", "right"),
            row(3, "s3", "right"),
            row(4, "s4", "right")
        ]
    );
    let reason = r.rows[0].reason.as_ref().unwrap().to_string();
    assert!(reason.contains("quote"), "{reason}");
}

/// The students of a report, in order.
fn students(report: &Report) -> Vec<&str> {
    report.students.iter().map(|s| s.student.as_str()).collect()
}

/// Issue 30, item 8: `"s⏎2",4.1,…` is a quoted cell holding a line break (RFC 4180 allows it;
/// a spreadsheet writes one for a cell typed with Alt+Enter). A row is one line, so neither line
/// is a row: both are invalid, each with its reason, and the second line's `2"` is no student.
/// Every line that holds data is still one row of the report (3 lines in, 3 rows out).
#[test]
fn a_quoted_line_break_invents_no_student() {
    let csv = format!("\"s\n2\",4.1,{RIGHT}\ns3,4.1,{RIGHT}\n");
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [
            row(1, "", "invalid"),
            row(2, "", "invalid"),
            row(3, "s3", "right")
        ]
    );
    assert_eq!(students(&r), ["s3"]);
    let reason = |i: usize| r.rows[i].reason.as_ref().unwrap().to_string();
    // Line 1 says its cell holds a line break that closes on line 2; line 2 that it is the rest
    // of line 1's field 1.
    assert!(
        reason(0).contains("line break") && reason(0).contains("line 2"),
        "{}",
        reason(0)
    );
    assert!(reason(1).contains("field 1 of line 1"), "{}", reason(1));
    assert!(!r.rows[1].counted);

    // In the answer, with CRLF and a blank line inside the cell: the student of line 1 is read
    // (the cells before the broken one are whole); the blank line is no row; line 4 is a row.
    let csv = format!("s1,4.1,\"0.5\r\n\r\n0.7 0.3\"\r\ns2,4.1,{RIGHT}\r\n");
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [
            row(1, "s1", "invalid"),
            row(3, "", "invalid"),
            row(4, "s2", "right")
        ]
    );
    assert_eq!(students(&r), ["s1", "s2"]);
}

/// A quote left alone in a field that does not start with one (what is left of a cell cut by
/// a line break, when its first line is gone) makes the line invalid, its student not read.
#[test]
fn a_stray_quote_invents_no_student() {
    let csv = format!("s1,4.1,{RIGHT}\n2\",4.1,{RIGHT}\ns3,4.1,0.5\" 0.7 0.3\n");
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [
            row(1, "s1", "right"),
            row(2, "", "invalid"),
            row(3, "s3", "invalid")
        ]
    );
    assert_eq!(students(&r), ["s1", "s3"]);
    for i in [1, 2] {
        let reason = r.rows[i].reason.as_ref().unwrap().to_string();
        assert!(reason.contains("quote"), "{reason}");
    }
    // Quotes that pair up inside a field are kept as written (a formula's, a nickname's).
    let r = grade(format!("ana \"a\" b,4.1,{RIGHT}\n").as_bytes());
    assert_eq!(summary(&r), [row(1, "ana \"a\" b", "right")]);
}

#[test]
fn text_after_a_closing_quote_is_refused_not_glued_on() {
    let r = grade(format!("\"s2\"x,4.1,{RIGHT}\n").as_bytes());
    assert_eq!(r.rows.len(), 1);
    assert_eq!(r.rows[0].verdict, "invalid");
    assert_ne!(r.rows[0].student, "s2x");
    assert!(r.rows[0]
        .reason
        .as_ref()
        .unwrap()
        .to_string()
        .contains("after its closing quote"));
    // A quote that is doubled inside a quoted field is one quote.
    let r = grade(format!("\"a \"\"b\"\"\",4.1,{RIGHT}\n").as_bytes());
    assert_eq!(summary(&r), [row(1, "a \"b\"", "right")]);
}

#[test]
fn a_student_called_student_is_a_row_unless_the_whole_row_is_a_header() {
    let r = grade(format!("Student,4.1,{RIGHT}\nana,4.1,{RIGHT}\n").as_bytes());
    assert_eq!(
        summary(&r),
        [row(1, "Student", "right"), row(2, "ana", "right")]
    );
}

#[test]
fn line_numbers_count_blank_lines_and_any_line_end() {
    let csv = format!(
        "student,exercise,answer\r\n\r\na,4.1,{RIGHT}\r\n\r\n   \r\nb,4.1,{RIGHT}\rc,4.1,{RIGHT}\n,,\nd,4.1,{RIGHT}"
    );
    assert_eq!(
        summary(&grade(csv.as_bytes())),
        [
            row(3, "a", "right"),
            row(6, "b", "right"),
            row(7, "c", "right"),
            row(9, "d", "right")
        ]
    );
}

#[test]
fn nul_bytes_are_refused_and_never_copied_through() {
    let r = grade(format!("a\0b,4.1,{RIGHT}\n").as_bytes());
    assert_eq!(r.rows[0].verdict, "invalid");
    assert_eq!(r.rows[0].student, "a\u{FFFD}b");
    assert!(!rows_csv(&r).contains(&0));
}

#[test]
fn cells_a_spreadsheet_would_run_as_formulas_are_written_as_text() {
    let csv = "=HYPERLINK(\"http://x\"),4.1,0.5 0.7 0.3\n@SUM(A1),+4.1,-0.5 0.7 0.3\n";
    let r = grade(csv.as_bytes());
    let out = String::from_utf8(rows_csv(&r)).unwrap();
    let mut reader = csv::Reader::from_reader(out.as_bytes());
    let cells: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(&cells[0][2], "'=HYPERLINK(\"http://x\")");
    assert_eq!(&cells[1][2], "'@SUM(A1)");
    assert_eq!(&cells[1][3], "'+4.1");
    assert_eq!(&cells[1][4], "'-0.5 0.7 0.3");
    // The JSON report keeps them as written.
    assert_eq!(r.rows[0].student, "=HYPERLINK(\"http://x\")");
}

#[test]
fn an_exercise_named_with_or_without_json_is_one_exercise() {
    let r = grade(format!("a,4.1,{RIGHT}\nb,4.1.json,{RIGHT}\n").as_bytes());
    assert_eq!(r.summary.len(), 1);
    assert_eq!(
        (r.summary[0].exercise.as_str(), r.summary[0].rows),
        ("4.1", 2)
    );
}

#[cfg(unix)]
#[test]
fn links_out_of_the_folder_loops_and_fifos_are_refused_with_their_reason() {
    let dir = tempfile::tempdir().unwrap();
    let outside = tempfile::tempdir().unwrap();
    std::fs::copy(folder().join("4.1.json"), outside.path().join("4.1.json")).unwrap();
    std::fs::copy(folder().join("4.1.json"), dir.path().join("real.json")).unwrap();
    let link = |to: &Path, name: &str| std::os::unix::fs::symlink(to, dir.path().join(name));
    link(&outside.path().join("4.1.json"), "out.json").unwrap();
    link(Path::new("real.json"), "in.json").unwrap();
    link(Path::new("loop.json"), "loop.json").unwrap();
    assert!(std::process::Command::new("mkfifo")
        .arg(dir.path().join("fifo.json"))
        .status()
        .unwrap()
        .success());
    let o = Options {
        exercises: dir.path().to_owned(),
        ..options(None)
    };
    let csv = format!("a,out,{RIGHT}\nb,in,{RIGHT}\nc,loop,{RIGHT}\nd,fifo,{RIGHT}\n");
    let r = grade_bytes(csv.as_bytes(), &o);
    let reasons: Vec<String> = r
        .rows
        .iter()
        .map(|r| {
            r.reason
                .as_ref()
                .map(ToString::to_string)
                .unwrap_or_default()
        })
        .collect();
    assert!(
        reasons[0].contains("link out of the exercises folder"),
        "{}",
        reasons[0]
    );
    assert_eq!(r.rows[1].verdict, "right", "{}", reasons[1]);
    assert!(reasons[2].contains("cannot be followed"), "{}", reasons[2]);
    assert!(reasons[3].contains("not a regular file"), "{}", reasons[3]);
}

#[test]
fn the_report_is_written_before_the_summary_line_and_a_semicolon_file_exits_0() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("turma.csv");
    std::fs::write(&input, "aluno;exercício;resposta\nana;4.1;0,5 0,7 0,3\n").unwrap();
    support::phong()
        .arg("grade")
        .arg(&input)
        .arg("--exercises")
        .arg(folder())
        .assert()
        .code(0)
        .stdout(predicates::str::contains(
            "1,2,ana,4.1,\"0,5 0,7 0,3\",right",
        ))
        .stderr(predicates::str::contains("graded 1 row: 1 right"));
}

#[test]
fn the_summary_line_of_one_row_is_in_the_singular_in_both_languages() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("turma.csv");
    std::fs::write(&input, "aluno;exercício;resposta\nana;4.1;0,5 0,7 0,3\n").unwrap();
    for (lang, line) in [
        (
            "en",
            "graded 1 row: 1 right, 0 by the likely intended reading, 0 wrong, 0 invalid",
        ),
        (
            "pt",
            "1 linha avaliada: 1 certa, 0 pela leitura provavelmente pretendida, 0 erradas, \
             0 inválidas",
        ),
    ] {
        support::phong()
            .args(["grade", "--lang", lang, "--exercises"])
            .arg(folder())
            .arg(&input)
            .assert()
            .code(0)
            .stderr(predicates::str::contains(line));
    }
}

// ---------------------------------------------------------------- the property

/// One generated line: its text (without the line end) and whether it holds data.
#[derive(Clone, Debug)]
struct Line {
    bytes: Vec<u8>,
    data: bool,
}

/// A field: plain, quoted (with the separator and doubled quotes inside), an unterminated
/// quote, text after a closing quote, a NUL, bad UTF-8 (UTF-8 files only), a formula, empty.
fn field(sep: u8, utf8: bool) -> impl Strategy<Value = Vec<u8>> {
    let plain = "[a-z0-9 .]{0,8}".prop_map(String::into_bytes);
    let answer = prop_oneof![
        Just(b"0.5 0.7 0.3".to_vec()),
        Just(b"0,5 0,7 0,3".to_vec()),
        Just(b"(0.5, 0.7, 0.3)".to_vec()),
    ];
    let quoted = "[a-z0-9 .,;\t\"]{0,8}".prop_map(move |s| {
        let mut v = vec![b'"'];
        v.extend(s.replace('"', "\"\"").bytes());
        v.push(sep);
        v.push(b'"');
        v
    });
    let unterminated = "[a-z0-9 ]{0,6}".prop_map(|s| format!("\"{s}").into_bytes());
    let after_quote = "[a-z]{1,4}".prop_map(|s| format!("\"{s}\"x").into_bytes());
    let nul = "[a-z]{0,3}".prop_map(|s| format!("{s}\0z").into_bytes());
    let bad = Just(if utf8 {
        b"h\xFF".to_vec()
    } else {
        b"h".to_vec()
    });
    let formula = prop_oneof![
        Just(b"=1+2".to_vec()),
        Just(b"-0.5 0 0".to_vec()),
        Just(b"@x".to_vec())
    ];
    prop_oneof![
        4 => plain,
        3 => answer,
        2 => quoted,
        1 => unterminated,
        1 => after_quote,
        1 => nul,
        1 => bad,
        1 => formula,
        1 => Just(Vec::new()),
    ]
}

/// A data line: a student that is always there (`s` and digits: never a header word, never
/// blank), an exercise, then one to three more fields (usually two: the answer and nothing).
fn data_line(sep: u8, utf8: bool) -> impl Strategy<Value = Line> {
    let student = "s[0-9]{1,3}".prop_map(String::into_bytes);
    let exercise = prop_oneof![
        Just(b"4.1".to_vec()),
        Just(b"4.1.json".to_vec()),
        Just(b"4.2".to_vec()),
        Just(b"nope".to_vec()),
        field(sep, utf8),
    ];
    let rest = prop_oneof![
        6 => proptest::collection::vec(field(sep, utf8), 1..=1),
        1 => proptest::collection::vec(field(sep, utf8), 0..=3),
    ];
    (student, exercise, rest).prop_map(move |(s, e, rest)| {
        let mut bytes = s;
        for f in std::iter::once(e).chain(rest) {
            bytes.push(sep);
            bytes.extend(f);
        }
        Line { bytes, data: true }
    })
}

/// A blank line: empty or spaces.
fn blank_line() -> impl Strategy<Value = Line> {
    "[ ]{0,3}".prop_map(|s| Line {
        bytes: s.into_bytes(),
        data: false,
    })
}

/// A whole file: its bytes and the numbers of the lines that hold data, in order.
#[derive(Debug)]
struct File {
    bytes: Vec<u8>,
    data_lines: Vec<u64>,
    forced: Option<u8>,
}

fn file() -> impl Strategy<Value = File> {
    (
        prop_oneof![Just(b','), Just(b';'), Just(b'\t')],
        0..4u8,
        any::<bool>(),
        any::<bool>(),
    )
        .prop_flat_map(|(sep, encoding, header, forced)| {
            let utf8 = encoding < 2;
            let line = prop_oneof![3 => data_line(sep, utf8), 1 => blank_line()];
            let ends = proptest::collection::vec(
                prop_oneof![Just(&b"\n"[..]), Just(&b"\r\n"[..]), Just(&b"\r"[..])],
                0..=30,
            );
            (proptest::collection::vec(line, 0..=30), ends, any::<bool>()).prop_map(
                move |(mut lines, ends, last_end)| {
                    if header {
                        let names = [&b"student"[..], b"exercise", b"answer"];
                        lines.insert(
                            0,
                            Line {
                                bytes: names.join(&sep),
                                data: false,
                            },
                        );
                    }
                    let mut text = Vec::new();
                    let mut data_lines = Vec::new();
                    for (i, l) in lines.iter().enumerate() {
                        if l.data {
                            data_lines.push(i as u64 + 1);
                        }
                        text.extend_from_slice(&l.bytes);
                        let last = i + 1 == lines.len();
                        if last && !last_end {
                            break;
                        }
                        let mut end = ends.get(i).copied().unwrap_or(b"\n");
                        // "\r" then an empty line's "\n" would read as one "\r\n".
                        if end == b"\r" && lines.get(i + 1).is_some_and(|n| n.bytes.is_empty()) {
                            end = b"\r\n";
                        }
                        text.extend_from_slice(end);
                    }
                    let bytes = match encoding {
                        0 => text,
                        1 => [&b"\xEF\xBB\xBF"[..], &text].concat(),
                        2 | 3 => {
                            let s = String::from_utf8(text).expect("UTF-16 cases are text");
                            let mut out = if encoding == 2 {
                                vec![0xFF, 0xFE]
                            } else {
                                vec![0xFE, 0xFF]
                            };
                            for u in s.encode_utf16() {
                                out.extend(if encoding == 2 {
                                    u.to_le_bytes()
                                } else {
                                    u.to_be_bytes()
                                });
                            }
                            out
                        }
                        _ => unreachable!(),
                    };
                    File {
                        bytes,
                        data_lines,
                        forced: forced.then_some(sep),
                    }
                },
            )
        })
}

fn check(f: &File) -> Result<(), TestCaseError> {
    let report = grade_bytes(&f.bytes, &options(f.forced));
    let lines: Vec<u64> = report.rows.iter().map(|r| r.line).collect();
    prop_assert_eq!(&lines, &f.data_lines);
    for (i, r) in report.rows.iter().enumerate() {
        prop_assert_eq!(r.row, i + 1);
        let texts = |r: &RowOut| [r.student.clone(), r.exercise.clone(), r.answer.clone()];
        for t in texts(r) {
            prop_assert!(!t.contains('\0'), "a NUL copied through: {:?}", t);
        }
        // Every student begins with "s" and digits, whatever else the line holds.
        prop_assert!(
            r.student.starts_with('s') || r.verdict == "invalid",
            "{:?}",
            r
        );
    }
    // The CSV report reads back as one record per row, after its header.
    let out = rows_csv(&report);
    prop_assert!(!out.contains(&0));
    let records = csv::Reader::from_reader(&out[..]).records().count();
    prop_assert_eq!(records, report.rows.len());
    let total: usize = report.summary.iter().map(|s| s.rows).sum();
    prop_assert_eq!(total, report.rows.len());
    Ok(())
}

#[test]
fn every_line_that_holds_data_is_one_row_exactly_once_in_order() {
    let config = Config {
        cases: 256,
        rng_seed: RngSeed::Fixed(12),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/grade_csv.txt",
        ))),
        ..Config::default()
    };
    let mut runner = TestRunner::new(config);
    runner
        .run(&file(), |f| check(&f))
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn an_exercise_written_with_a_decimal_comma_is_that_exercise() {
    // QA finding 5: a Brazilian spreadsheet exports the number cell 4.1 as `4,1` in its `;`
    // CSV. No exercise file may be named with a comma, so `4,1` can only mean 4.1: it is graded
    // as 4.1 (right: 4.1's colour is (0.5, 0.7, 0.3)), under 4.1 in the summary and the totals,
    // and the reason says what was written and how it was read. `4,9` has no 4.9 to mean: it
    // stays an unknown exercise.
    let csv = "aluno;exercício;resposta\nbia;4,1;0,5 0,7 0,3\nbia;4,9;0 0 0\ncaio;4,1;\"0,5 0,7\n";
    let r = grade(csv.as_bytes());
    assert_eq!(
        summary(&r),
        [
            row(2, "bia", "right"),
            row(3, "bia", "invalid"),
            row(4, "caio", "invalid")
        ]
    );
    let bia = &r.rows[0];
    assert_eq!(bia.exercise, "4.1");
    assert_eq!(bia.points, 1.0);
    let reason = bia.reason.as_ref().unwrap().to_string();
    assert!(
        reason.contains("\"4,1\"") && reason.contains("read as 4.1"),
        "{reason}"
    );
    assert!(r.rows[1]
        .reason
        .as_ref()
        .unwrap()
        .to_string()
        .starts_with("unknown exercise"));
    // A row that cannot be read as CSV stands under 4.1 too.
    assert_eq!(r.rows[2].exercise, "4.1");
    assert_eq!(r.summary.len(), 2, "{:?}", r.summary);
    assert_eq!(
        (r.summary[0].exercise.as_str(), r.summary[0].rows),
        ("4.1", 2)
    );
    assert_eq!(r.students[0].exercises["4.1"], Some(1.0));
}

#[test]
fn an_answer_that_is_not_a_number_is_echoed_as_typed() {
    // QA finding 13: the reason names `0,2x` as the student typed it, not the converted `0.2x`.
    let r = grade("aluno;exercício;resposta\nfabio;4.2;0,2x 0 0\n".as_bytes());
    let reason = r.rows[0].reason.as_ref().unwrap().to_string();
    assert!(
        reason.contains("\"0,2x\" in \"0,2x 0 0\" is not a number"),
        "{reason}"
    );
}
