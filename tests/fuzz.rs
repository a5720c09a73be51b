//! Fuzzing of the input: arbitrary and mutated problem and scene files go through the real paths
//! of `phong`, in both precisions — parse and validate; solve to the JSON document, the text
//! report and the four explanation layouts (English and Portuguese); `phong check` when the file
//! has an answer key; for a file with a camera, a tiny render (at most 8×6 pixels, 4 samples,
//! level 3), one explained pixel and the POV-Ray export. For every case:
//!
//! - nothing panics (each path runs under `catch_unwind`; a panic fails the case, and proptest
//!   shrinks the input to a minimal one);
//! - whatever is accepted carries no NaN and no infinity: the JSON documents are serialised into
//!   a tree that keeps them (`serde-value`: serde_json would write them as `null`, which looks
//!   like an absent quantity), and the text, Markdown, LaTeX, HTML and SDL show neither; no
//!   traced colour is NaN (the image would hide it as black);
//! - whatever is rejected says so clearly: the message starts with the file's path; a syntax
//!   error gives line and column and a fix; a validation error names a field of the format that
//!   the file has (or is missing there) and a fix; no number of hundreds of digits.
//!
//! The inputs come from three generators:
//! - [`arbitrary_json`]: JSON of any shape, whose field names and words are mostly the format's
//!   own (so that the parser goes deep) and whose numbers are the awkward ones: −0, 1e308, 1e400,
//!   5e−324, −1e−320, integers beyond 2^53, u64 and i64, …;
//! - [`almost_json`]: bytes: valid files cut short, with bad UTF-8, stray brackets or quotes,
//!   nested up to 100,000 deep, and plain random bytes;
//! - [`mutated_file`]: every bundled exercise and scene (and 4.1–4.3 with their answer keys) with
//!   one to four [`Mutation`]s — a field removed, duplicated or added, a number made extreme, a
//!   type swapped, a word changed, a vector made zero or parallel to another, a field set to a
//!   value at the edge of a validation rule, an answer key added — so that cases reach
//!   validation, the solver and the tracer, not only the parser.
//!
//! Some rejected cases also go through the `phong` binary: exit code 2, `error: FILE…` on
//! standard error, and no output file left behind.
//!
//! The same cases on every machine. Each fuzz test runs one round of `PHONG_FUZZ_CASES` cases
//! (default: its own count, [`CASES_MUTATED`] and the others; 10 to 13 s for the file in the
//! debug profile) from a fixed seed, so a plain `cargo test` is deterministic.
//! `PHONG_FUZZ_ROUNDS=N` runs N rounds (the seed plus 0, 1, …, N − 1): `.ci/run` sets it, so CI
//! tests the same cases however fast or loaded the machine is. Exploration is apart:
//! `.ci/fuzz-explore` sets `PHONG_FUZZ_SEED=random` and `PHONG_FUZZ_SECONDS=N` (rounds until N
//! seconds have passed), which is refused under `CI=true`. `PHONG_FUZZ_SEED` sets the first
//! round's seed (`random`: from the clock). A failure
//! names its round's seed, prints the minimised input and saves it under
//! `target/fuzz-failures/`; proptest also records the case's seed in
//! `proptest-regressions/fuzz.txt` (committed), which every later round replays first. A bug
//! found here gets a plain `#[test]` with the minimised input at the end of this file.

// `support::phong()`, the binary with the caller's locale cleared; the HTTP client and the
// server for the fuzz test of `phong serve`'s API (tests/support/).
#[path = "support/mod.rs"]
#[allow(dead_code)]
mod support;

use std::collections::BTreeSet;
use std::fmt;
use std::fs;
use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::sample::{select, Index};
use proptest::test_runner::{
    Config, FileFailurePersistence, RngSeed, TestCaseError, TestError, TestRunner,
};
use serde_json::Value;
use tempfile::TempDir;

use phong::check::{self, CheckOptions, Scale};
use phong::core::{Real, Vector};
use phong::problem::{self, ProblemError};
use phong::report::lang::Lang;
use phong::report::{self as reports};
use phong::tracer::{self, Counts, Tracer};

// ---------------------------------------------------------------------------------------------
// JSON as written: numbers kept as text, keys in order and possibly repeated
// ---------------------------------------------------------------------------------------------

/// A JSON document as a file may write it. Unlike `serde_json::Value`, a number is kept as the
/// text it was written with (so a case can hold `1e400`, `-0` or `18446744073709551616`), and an
/// object is a list of fields (so a key can appear twice).
#[derive(Clone, Debug, PartialEq)]
enum J {
    Null,
    Bool(bool),
    Num(String),
    Str(String),
    Arr(Vec<J>),
    Obj(Vec<(String, J)>),
}

impl J {
    fn from_value(v: &Value) -> J {
        match v {
            Value::Null => J::Null,
            Value::Bool(b) => J::Bool(*b),
            Value::Number(n) => J::Num(n.to_string()),
            Value::String(s) => J::Str(s.clone()),
            Value::Array(items) => J::Arr(items.iter().map(J::from_value).collect()),
            Value::Object(map) => J::Obj(
                map.iter()
                    .map(|(k, v)| (k.clone(), J::from_value(v)))
                    .collect(),
            ),
        }
    }

    /// A value written in a table of this file: JSON text, or a bare number that may lie beyond
    /// f64 (`1e400`), which serde_json cannot hold.
    fn raw(text: &str) -> J {
        match serde_json::from_str::<Value>(text) {
            Ok(v) if !matches!(v, Value::Number(_)) => J::from_value(&v),
            _ => J::Num(text.to_owned()),
        }
    }

    fn text(&self) -> String {
        let mut out = String::new();
        self.write(&mut out);
        out
    }

    fn write(&self, out: &mut String) {
        let string = |out: &mut String, s: &str| {
            out.push_str(&serde_json::to_string(s).expect("a string serialises"));
        };
        match self {
            J::Null => out.push_str("null"),
            J::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
            J::Num(n) => out.push_str(n),
            J::Str(s) => string(out, s),
            J::Arr(items) => {
                out.push('[');
                for (i, item) in items.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    item.write(out);
                }
                out.push(']');
            }
            J::Obj(fields) => {
                out.push('{');
                for (i, (k, v)) in fields.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    string(out, k);
                    out.push_str(": ");
                    v.write(out);
                }
                out.push('}');
            }
        }
    }

    /// The paths (child positions from the root) of every node for which `keep` holds.
    fn paths(&self, keep: &dyn Fn(&J) -> bool) -> Vec<Vec<usize>> {
        fn walk(j: &J, at: &mut Vec<usize>, keep: &dyn Fn(&J) -> bool, out: &mut Vec<Vec<usize>>) {
            if keep(j) {
                out.push(at.clone());
            }
            let children: Vec<&J> = match j {
                J::Arr(items) => items.iter().collect(),
                J::Obj(fields) => fields.iter().map(|(_, v)| v).collect(),
                _ => Vec::new(),
            };
            for (i, c) in children.into_iter().enumerate() {
                at.push(i);
                walk(c, at, keep, out);
                at.pop();
            }
        }
        let mut out = Vec::new();
        walk(self, &mut Vec::new(), keep, &mut out);
        out
    }

    fn at(&self, path: &[usize]) -> &J {
        path.iter().fold(self, |j, &i| match j {
            J::Arr(items) => &items[i],
            J::Obj(fields) => &fields[i].1,
            _ => unreachable!("a path leads through arrays and objects"),
        })
    }

    fn at_mut(&mut self, path: &[usize]) -> &mut J {
        path.iter().fold(self, |j, &i| match j {
            J::Arr(items) => &mut items[i],
            J::Obj(fields) => &mut fields[i].1,
            _ => unreachable!("a path leads through arrays and objects"),
        })
    }

    /// The three numbers of a 3-vector `[x, y, z]`, when they are finite f64.
    fn triple(&self) -> Option<[f64; 3]> {
        match self {
            J::Arr(items) if items.len() == 3 => {
                let mut v = [0.0; 3];
                for (x, item) in v.iter_mut().zip(items) {
                    match item {
                        J::Num(n) => *x = n.parse::<f64>().ok().filter(|x| x.is_finite())?,
                        _ => return None,
                    }
                }
                Some(v)
            }
            _ => None,
        }
    }

    fn is_triple(&self) -> bool {
        matches!(self, J::Arr(items) if items.len() == 3 && items.iter().all(|i| matches!(i, J::Num(_))))
    }

    fn from_triple(v: [f64; 3]) -> J {
        J::Arr(
            v.iter()
                .map(|x| {
                    J::Num(if x.is_finite() {
                        format!("{x:?}")
                    } else {
                        // Beyond f64: the parser must say so.
                        "1e999".into()
                    })
                })
                .collect(),
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Vocabulary: the format's own names and words, and awkward numbers
// ---------------------------------------------------------------------------------------------

/// Every field name of the problem format (src/problem/format.rs), so that generated objects
/// are mostly made of names the parser knows; the top-level fields first (see [`TOP_LEVEL`]).
const FIELD_NAMES: &[&str] = &[
    "$schema",
    "title",
    "title_pt",
    "question",
    "question_pt",
    "materials",
    "lights",
    "viewer",
    "point",
    "ray",
    "surfaces",
    "camera",
    "background",
    "render",
    "answer",
    "type",
    "name",
    "name_pt",
    "color",
    "position",
    "direction",
    "axis",
    "angle",
    "exponent",
    "falloff",
    "normal",
    "material",
    "center",
    "radius",
    "vertices",
    "file",
    "origin",
    "ambient",
    "diffuse",
    "specular",
    "shininess",
    "reflectivity",
    "transmissivity",
    "ior",
    "k",
    "eye",
    "look_at",
    "up",
    "fov",
    "width",
    "height",
    "max_level",
    "min_weight",
    "shadows",
    "samples",
    "scale",
    "tolerance",
];

/// The top-level fields, which every field path of an error starts with: the first 15 of
/// [`FIELD_NAMES`], which lists them first.
const TOP_LEVEL: &[&str] = FIELD_NAMES.split_at(15).0;

/// Mesh paths relative to the case's folder: the fixtures of [`Workspace::new`], missing files,
/// folders and `..`.
const MESH_PATHS: &[&str] = &[
    "torus.obj",
    "sub/../torus.obj",
    "../torus.obj",
    "../../../../../../etc/hostname",
    "missing.obj",
    "sub",
    ".",
    "",
    "/",
    "/nonexistent/mesh.obj",
    "garbage.obj",
    "degenerate.obj",
    "no-faces.obj",
    "huge.obj",
    "far-index.obj",
    "zero-index.obj",
    "negative-index.obj",
    "overflow-index.obj",
    "binary.obj",
];

/// Words a string may become: every `type`, the word "specular", the bundled files' material
/// names, colours, mesh paths and a few awkward strings.
const WORDS: &[&str] = &[
    "ambient",
    "point",
    "directional",
    "spot",
    "plane",
    "sphere",
    "triangle",
    "mesh",
    "specular",
    "Specular",
    "cone",
    "M",
    "floor",
    "mirror",
    "red",
    "green",
    "brass",
    "blue",
    "plastic",
    "matte",
    "card",
    "ceiling",
    "copper",
    "glow",
    "chalk",
    "missing",
    "#000000",
    "#ffffff",
    "#FfA0b1",
    "#fff",
    "#gggggg",
    "#1234567",
    "ffffff",
    "#",
    "torus.obj",
    "missing.obj",
    "../torus.obj",
    "",
    " ",
    "ünïcødé 🎨",
    "\u{202e}reversed",
    "a\u{0}b",
    "\\",
    "\"",
    "$ref",
    "0.5 0.5 0.5",
];

/// Numbers as written: signed zeros, limits and just-beyond-limits of f64, f32, u32, u64, i64
/// and 2^53, subnormals, values at the edges of validation rules, and forms JSON allows.
const AWKWARD_NUMBERS: &[&str] = &[
    "0",
    "-0",
    "-0.0",
    "0e0",
    "-0E-0",
    "1",
    "-1",
    "0.5",
    "2",
    "3",
    "90",
    "91",
    "180",
    "255",
    "256",
    "1e308",
    "-1e308",
    "1.7976931348623157e308",
    "1.7976931348623159e308",
    "1e309",
    "-1e400",
    "1e-320",
    "-1e-320",
    "5e-324",
    "2.4e-324",
    "1e-400",
    "3.4028235e38",
    "3.5e38",
    "-1e39",
    "1e-40",
    "1e-46",
    "1.401298464324817e-45",
    "9007199254740993",
    "4294967295",
    "4294967296",
    "-4294967296",
    "16384",
    "16385",
    "4096",
    "4097",
    "18446744073709551615",
    "18446744073709551616",
    "-9223372036854775808",
    "-9223372036854775809",
    "123456789012345678901234567890",
    "1e300",
    "1e-300",
    "0.1",
    "1E2",
    "1e+2",
    "0.000000000000000000000000000000000000000001",
];

/// Stand-ins for numbers that are not numbers: JSON has no NaN or infinity.
const NOT_NUMBERS: &[&str] = &[
    "NaN",
    "Infinity",
    "-Infinity",
    "\"NaN\"",
    "\"inf\"",
    "\"1\"",
    "nan",
    "+1",
    "01",
    "1.",
    ".5",
    "0x10",
    "1e",
    "--1",
];

/// 3-vectors at the ends of f64 and f32 (opposite signs make differences overflow), tiny and
/// subnormal ones, zero.
const EXTREME_VECTORS: &[&str] = &[
    "[1e308, 1e308, 1e308]",
    "[-1e308, -1e308, -1e308]",
    "[1.7976931348623157e308, 0, 0]",
    "[-1.7976931348623157e308, 0, 0]",
    "[0, -1.7976931348623157e308, 1.7976931348623157e308]",
    "[3e38, 0, 0]",
    "[-3e38, 3e38, 0]",
    "[1e20, 1e20, -1e20]",
    "[1e-20, 0, 0]",
    "[1e-320, 0, 0]",
    "[5e-324, 5e-324, 5e-324]",
    "[1e-45, 0, 0]",
    "[0, 0, 1e-300]",
    "[0, 0, 0]",
    "[-0, 0, -0]",
];

/// Fields and values chosen to sit on (or just past) the edge of a validation rule or to reach a
/// corner of the solver or the tracer.
const FIELD_VALUES: &[(&str, &[&str])] = &[
    ("eye", EXTREME_VECTORS),
    ("look_at", EXTREME_VECTORS),
    ("up", EXTREME_VECTORS),
    ("center", EXTREME_VECTORS),
    ("origin", EXTREME_VECTORS),
    ("direction", EXTREME_VECTORS),
    ("position", EXTREME_VECTORS),
    ("normal", EXTREME_VECTORS),
    ("axis", EXTREME_VECTORS),
    ("viewer", EXTREME_VECTORS),
    ("background", EXTREME_VECTORS),
    (
        "shininess",
        &["0", "-1", "1e308", "1e-300", "0.5", "1e6", "-0", "3.5e38"],
    ),
    (
        "falloff",
        &[
            "3",
            "0.5",
            "-1",
            "2",
            "1",
            "0",
            "1e308",
            "\"2\"",
            "2.0000000000000004",
        ],
    ),
    (
        "angle",
        &[
            "91",
            "-1",
            "0",
            "90",
            "1e-10",
            "89.99999999",
            "180",
            "-0",
            "1e308",
        ],
    ),
    (
        "exponent",
        &["0", "-1", "1e308", "1e-300", "0.5", "1000", "3.5e38"],
    ),
    (
        "radius",
        &[
            "0", "-1", "1e-300", "1e300", "1e-40", "-0", "1e-320", "1e308",
        ],
    ),
    (
        "fov",
        &[
            "0",
            "180",
            "179.9999999",
            "179.999999999",
            "1e-300",
            "1e-46",
            "-45",
            "1e308",
            "90",
        ],
    ),
    (
        "width",
        &[
            "0",
            "1",
            "16384",
            "16385",
            "4294967295",
            "4294967296",
            "-1",
            "2.5",
            "1e10",
        ],
    ),
    (
        "height",
        &[
            "0",
            "1",
            "16384",
            "16385",
            "4294967295",
            "4294967296",
            "-1",
            "2.5",
            "1e10",
        ],
    ),
    ("samples", &["0", "1", "4", "4096", "4097", "4294967296"]),
    ("max_level", &["0", "1", "3", "4294967295", "-1"]),
    (
        "min_weight",
        &["0", "-1", "1e308", "1", "2", "1e-300", "-0"],
    ),
    ("shadows", &["false", "true", "0", "\"yes\"", "null"]),
    ("k", &["0", "1", "1.5", "-0.5", "1e308", "1e-320"]),
    (
        "scale",
        &["1", "255", "0", "2", "-255", "1e300", "254.99999999999997"],
    ),
    ("tolerance", &["0", "-1", "1e308", "1e-320", "0.5", "1e300"]),
    (
        "transmissivity",
        &[
            "[0.9, 0.9, 0.9]",
            "[0, 0, 0]",
            "[1, 1, 1]",
            "[-1, 0, 0]",
            "[1e308, 1, 1]",
        ],
    ),
    ("ior", &["1.5", "1", "0", "-1.5", "1e-320", "1e308", "0.5"]),
    (
        "reflectivity",
        &[
            "\"specular\"",
            "\"Specular\"",
            "[1, 1, 1]",
            "[0, 0, 0]",
            "[2, 2, 2]",
            "[-1, 0, 0]",
        ],
    ),
    (
        "material",
        &["\"M\"", "\"nope\"", "{}", "\"\"", "\"floor\""],
    ),
    (
        "type",
        &[
            "\"ambient\"",
            "\"point\"",
            "\"directional\"",
            "\"spot\"",
            "\"plane\"",
            "\"sphere\"",
            "\"triangle\"",
            "\"mesh\"",
            "\"cone\"",
        ],
    ),
    (
        "color",
        &[
            "[0, 0, 0]",
            "[1e308, 1e308, 1e308]",
            "[3.4e38, 0, 0]",
            "[1e30, 1e30, 1e30]",
            "[-0, 0, 0]",
            "[1, 1]",
            "\"#ffffff\"",
        ],
    ),
    (
        "file",
        &[
            "\"torus.obj\"",
            "\"missing.obj\"",
            "\"../torus.obj\"",
            "\"sub\"",
            "\"\"",
            "\"degenerate.obj\"",
            "\"huge.obj\"",
            "\"far-index.obj\"",
            "\"zero-index.obj\"",
            "\"negative-index.obj\"",
            "\"overflow-index.obj\"",
            "\"binary.obj\"",
        ],
    ),
];

// ---------------------------------------------------------------------------------------------
// Generator (a): arbitrary JSON
// ---------------------------------------------------------------------------------------------

fn number() -> impl Strategy<Value = J> {
    prop_oneof![
        4 => select(AWKWARD_NUMBERS).prop_map(|n| J::Num(n.into())),
        1 => select(NOT_NUMBERS).prop_map(|n| J::Num(n.into())),
        2 => any::<f64>().prop_map(|x| J::Num(if x.is_finite() { format!("{x:?}") } else { "0".into() })),
        1 => any::<i64>().prop_map(|x| J::Num(x.to_string())),
        1 => any::<u64>().prop_map(|x| J::Num(x.to_string())),
        3 => (-3i32..=3).prop_map(|x| J::Num(x.to_string())),
        3 => (0.0..1.0f64).prop_map(|x| J::Num(format!("{x:?}"))),
    ]
}

fn word() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => select(WORDS).prop_map(String::from),
        1 => select(FIELD_NAMES).prop_map(String::from),
        1 => select(MESH_PATHS).prop_map(String::from),
        1 => "\\PC{0,12}",
        1 => "[\\x00-\\x1f\"\\\\/\u{2028}\u{fffd}]{0,4}",
    ]
}

fn key() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => select(FIELD_NAMES).prop_map(String::from),
        1 => word(),
    ]
}

/// A 3-vector of small numbers (most vectors and colours of the format).
fn triple() -> impl Strategy<Value = J> {
    prop::collection::vec(
        prop_oneof![
            4 => (-4i32..=4).prop_map(|x| J::Num(x.to_string())),
            2 => (-2.0..2.0f64).prop_map(|x| J::Num(format!("{x:?}"))),
            1 => number(),
        ],
        3,
    )
    .prop_map(J::Arr)
}

fn leaf() -> impl Strategy<Value = J> {
    prop_oneof![
        1 => Just(J::Null),
        1 => any::<bool>().prop_map(J::Bool),
        4 => number(),
        3 => word().prop_map(J::Str),
        3 => triple(),
    ]
}

/// Any JSON value, mostly made of the format's names, words and awkward numbers.
fn json_value(depth: u32) -> impl Strategy<Value = J> {
    leaf().prop_recursive(depth, 64, 6, |inner| {
        prop_oneof![
            1 => prop::collection::vec(inner.clone(), 0..6).prop_map(J::Arr),
            2 => prop::collection::vec((key(), inner), 0..7).prop_map(J::Obj),
        ]
    })
}

/// Generator (a): a document of any shape, most often an object of top-level fields.
fn arbitrary_json() -> impl Strategy<Value = Input> {
    let top = prop::collection::vec(
        (
            prop_oneof![4 => select(TOP_LEVEL).prop_map(String::from), 1 => key()],
            json_value(4),
        ),
        0..9,
    )
    .prop_map(J::Obj);
    prop_oneof![4 => top, 1 => json_value(4)].prop_map(|j| Input {
        what: "arbitrary JSON".into(),
        bytes: j.text().into_bytes(),
    })
}

// ---------------------------------------------------------------------------------------------
// Generator (b): almost JSON
// ---------------------------------------------------------------------------------------------

/// Byte sequences spliced into a file: bad UTF-8 (a lone continuation byte, a truncated
/// sequence, an overlong form, a surrogate), a byte order mark, NUL, escapes, stray brackets.
const SPLICES: &[&[u8]] = &[
    b"\xff",
    b"\xfe\xff",
    b"\xc3",
    b"\xe2\x82",
    b"\xc0\xaf",
    b"\xed\xa0\x80",
    b"\xef\xbb\xbf",
    b"\x00",
    b"\\u",
    b"\"\\ud800\"",
    b"\"",
    b",",
    b",,",
    b"]",
    b"}",
    b"{",
    b"[",
    b":",
    b"/* comment */",
    b"// comment\n",
    b"\t\r\n",
    b"\xe2\x80\xa8",
    b"1e999",
    b"-",
    b"NaN",
];

/// How one edit changes the bytes of a file.
#[derive(Clone, Debug)]
enum ByteEdit {
    /// Cut the file short here.
    Truncate(Index),
    /// Splice these bytes in here.
    Insert(Index, &'static [u8]),
    /// Remove up to this many bytes from here.
    Delete(Index, u8),
    /// Replace one byte.
    Replace(Index, u8),
    /// Nest the rest of the file `depth` levels deep in `open` (closed again or not).
    Nest {
        at: Index,
        depth: u32,
        open: &'static str,
        close: bool,
    },
}

fn byte_edit() -> impl Strategy<Value = ByteEdit> {
    let depth = prop_oneof![
        Just(127u32),
        Just(128),
        Just(129),
        1u32..300,
        Just(10_000),
        Just(100_000),
    ];
    prop_oneof![
        2 => any::<Index>().prop_map(ByteEdit::Truncate),
        3 => (any::<Index>(), select(SPLICES)).prop_map(|(i, s)| ByteEdit::Insert(i, s)),
        2 => (any::<Index>(), 1u8..40).prop_map(|(i, n)| ByteEdit::Delete(i, n)),
        2 => (any::<Index>(), any::<u8>()).prop_map(|(i, b)| ByteEdit::Replace(i, b)),
        1 => (any::<Index>(), depth, select(&["[", "{\"lights\": ", "{\"a\": [", "[{\"\": "][..]), any::<bool>())
            .prop_map(|(at, depth, open, close)| ByteEdit::Nest { at, depth, open, close }),
    ]
}

impl ByteEdit {
    fn apply(&self, bytes: &mut Vec<u8>) {
        let at = |i: &Index, len: usize| if len == 0 { 0 } else { i.index(len + 1) };
        match self {
            ByteEdit::Truncate(i) => bytes.truncate(at(i, bytes.len())),
            ByteEdit::Insert(i, s) => {
                let k = at(i, bytes.len());
                bytes.splice(k..k, s.iter().copied());
            }
            ByteEdit::Delete(i, n) => {
                let k = at(i, bytes.len());
                let end = (k + *n as usize).min(bytes.len());
                bytes.drain(k..end);
            }
            ByteEdit::Replace(i, b) => {
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] = *b;
                }
            }
            ByteEdit::Nest {
                at: i,
                depth,
                open,
                close,
            } => {
                let k = at(i, bytes.len());
                let mut out = bytes[..k].to_vec();
                out.extend(open.as_bytes().repeat(*depth as usize));
                out.extend_from_slice(&bytes[k..]);
                if *close {
                    let closer: String = open
                        .chars()
                        .rev()
                        .filter_map(|c| match c {
                            '[' => Some(']'),
                            '{' => Some('}'),
                            _ => None,
                        })
                        .collect();
                    out.extend(closer.as_bytes().repeat(*depth as usize));
                }
                *bytes = out;
            }
        }
    }
}

/// Generator (b): bundled files and arbitrary JSON with byte edits, and plain random bytes.
fn almost_json() -> impl Strategy<Value = Input> {
    let n = bases().len();
    prop_oneof![
        1 => prop::collection::vec(any::<u8>(), 0..200).prop_map(|bytes| Input {
            what: "random bytes".into(),
            bytes,
        }),
        4 => (0..n, prop::collection::vec(byte_edit(), 1..4)).prop_map(|(i, edits)| {
            let base = &bases()[i];
            let mut bytes = base.text.clone().into_bytes();
            for e in &edits {
                e.apply(&mut bytes);
            }
            Input {
                what: format!("{} with byte edits {edits:?}", base.name),
                bytes,
            }
        }),
        1 => (arbitrary_json(), prop::collection::vec(byte_edit(), 1..3)).prop_map(|(input, edits)| {
            let mut bytes = input.bytes;
            for e in &edits {
                e.apply(&mut bytes);
            }
            Input {
                what: format!("arbitrary JSON with byte edits {edits:?}"),
                bytes,
            }
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// Generator (c): mutated bundled files
// ---------------------------------------------------------------------------------------------

/// A bundled exercise or scene.
struct Base {
    name: String,
    text: String,
    json: J,
}

/// Every `exercises/*.json` and `scenes/*.json`, and 4.1–4.3 with their answer key in each of
/// its other forms (`"#RRGGBB"`, `{"color", "scale", "tolerance"}`), read once.
fn bases() -> &'static [Base] {
    static BASES: OnceLock<Vec<Base>> = OnceLock::new();
    BASES.get_or_init(|| {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut out = Vec::new();
        for dir in ["exercises", "scenes"] {
            let mut files: Vec<PathBuf> = fs::read_dir(root.join(dir))
                .expect("the bundled folder is readable")
                .map(|e| e.expect("an entry").path())
                .filter(|p| p.extension().is_some_and(|e| e == "json"))
                .collect();
            files.sort();
            for path in files {
                let text = fs::read_to_string(&path).expect("a bundled file is readable");
                let value: Value = serde_json::from_str(&text).expect("a bundled file is JSON");
                out.push(Base {
                    name: format!("{dir}/{}", path.file_name().unwrap().to_string_lossy()),
                    json: J::from_value(&value),
                    text,
                });
            }
        }
        let keyed: Vec<(String, J)> = out
            .iter()
            .filter(|b| b.name.starts_with("exercises/4."))
            .map(|b| (b.name.clone(), b.json.clone()))
            .collect();
        for (name, json) in keyed {
            for (form, key) in [
                ("hex key", "\"#808080\""),
                (
                    "key object",
                    "{\"color\": [128, 7, 0], \"scale\": 255, \"tolerance\": 2}",
                ),
                (
                    "unit key object",
                    "{\"color\": [0.5, 0.7, 0.3], \"tolerance\": 0.01}",
                ),
            ] {
                let mut json = json.clone();
                set_field(&mut json, "answer", J::raw(key));
                out.push(Base {
                    name: format!("{name} ({form})"),
                    text: json.text(),
                    json,
                });
            }
        }
        assert!(
            out.len() >= 20,
            "the bundled exercises and scenes are found"
        );
        out
    })
}

/// Sets (or adds) a field of a top-level object.
fn set_field(j: &mut J, key: &str, value: J) {
    if let J::Obj(fields) = j {
        match fields.iter_mut().find(|(k, _)| k == key) {
            Some((_, v)) => *v = value,
            None => fields.push((key.to_owned(), value)),
        }
    }
}

/// How an array changes length.
#[derive(Clone, Debug)]
enum Resize {
    Pop(Index),
    Repeat(Index),
    Push(J),
    Clear,
    KeepTwo,
}

/// How a 3-vector changes: made zero, tiny or huge, or parallel to another 3-vector of the file
/// (a copy, its negation, a multiple, or the difference of two: `up = look_at − eye`).
#[derive(Clone, Debug)]
enum VectorOp {
    Zero,
    Scale(&'static str),
    Copy(Index),
    Negate(Index),
    Multiple(Index, &'static str),
    Difference(Index, Index),
}

/// One change to a valid file.
#[derive(Clone, Debug)]
enum Mutation {
    /// Any value becomes another of any type (a type swap).
    Replace { at: Index, with: J },
    /// A number becomes an awkward one (or a stand-in for NaN or infinity).
    Number { at: Index, text: &'static str },
    /// An object loses a field.
    Remove { at: Index, key: Index },
    /// An object has a field twice, the second time with another value.
    Duplicate { at: Index, key: Index, with: J },
    /// An object gains a field: a name of the format (perhaps out of place) or an unknown one.
    Add { at: Index, key: String, with: J },
    /// An array loses, repeats or gains an element, or is emptied.
    Resize { at: Index, how: Resize },
    /// A string becomes another word: a type, a material name, a colour, a mesh path.
    Word { at: Index, word: String },
    /// A 3-vector becomes zero, tiny, huge, or parallel to another.
    Vector { at: Index, how: VectorOp },
    /// Wherever this field appears (one of its appearances), it takes this value.
    Field {
        at: Index,
        key: &'static str,
        value: &'static str,
    },
    /// The file gains (or changes) its answer key.
    Answer { with: J },
}

fn vector_op() -> impl Strategy<Value = VectorOp> {
    let factor = select(&["1e-300", "1e-310", "1e300", "1e38", "1e-38", "-1", "1e-16"][..]);
    prop_oneof![
        2 => Just(VectorOp::Zero),
        2 => factor.clone().prop_map(VectorOp::Scale),
        2 => any::<Index>().prop_map(VectorOp::Copy),
        2 => any::<Index>().prop_map(VectorOp::Negate),
        1 => (any::<Index>(), factor).prop_map(|(i, f)| VectorOp::Multiple(i, f)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| VectorOp::Difference(a, b)),
    ]
}

fn answer_key() -> impl Strategy<Value = J> {
    let component = prop_oneof![
        3 => (0.0..1.0f64).prop_map(|x| J::Num(format!("{x:?}"))),
        1 => select(AWKWARD_NUMBERS).prop_map(|n| J::Num(n.into())),
    ];
    let rgb = prop::collection::vec(component, 3).prop_map(J::Arr);
    let hex = select(
        &[
            "#808080", "#000000", "#ffffff", "#fff", "#zzzzzz", "808080", "#1234567", "",
        ][..],
    )
    .prop_map(|s| J::Str(s.into()));
    let color = prop_oneof![rgb.clone(), hex.clone()];
    let object = (
        color,
        prop::option::of(select(&["1", "255", "0", "2", "-1", "1e300"][..])),
        prop::option::of(select(&["0", "0.005", "1", "-1", "1e308", "1e300"][..])),
    )
        .prop_map(|(c, s, t)| {
            let mut fields = vec![("color".to_owned(), c)];
            if let Some(s) = s {
                fields.push(("scale".into(), J::Num(s.into())));
            }
            if let Some(t) = t {
                fields.push(("tolerance".into(), J::Num(t.into())));
            }
            J::Obj(fields)
        });
    prop_oneof![rgb, hex, object, json_value(2)]
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let field = select(FIELD_VALUES).prop_flat_map(|(key, values)| {
        (any::<Index>(), select(values)).prop_map(move |(at, value)| Mutation::Field {
            at,
            key,
            value,
        })
    });
    let resize = prop_oneof![
        any::<Index>().prop_map(Resize::Pop),
        any::<Index>().prop_map(Resize::Repeat),
        leaf().prop_map(Resize::Push),
        Just(Resize::Clear),
        Just(Resize::KeepTwo),
    ];
    prop_oneof![
        2 => (any::<Index>(), json_value(2)).prop_map(|(at, with)| Mutation::Replace { at, with }),
        4 => (any::<Index>(), prop_oneof![4 => select(AWKWARD_NUMBERS), 1 => select(NOT_NUMBERS)])
            .prop_map(|(at, text)| Mutation::Number { at, text }),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(at, key)| Mutation::Remove { at, key }),
        1 => (any::<Index>(), any::<Index>(), leaf())
            .prop_map(|(at, key, with)| Mutation::Duplicate { at, key, with }),
        2 => (any::<Index>(), key(), leaf()).prop_map(|(at, key, with)| Mutation::Add { at, key, with }),
        2 => (any::<Index>(), resize).prop_map(|(at, how)| Mutation::Resize { at, how }),
        2 => (any::<Index>(), word()).prop_map(|(at, word)| Mutation::Word { at, word }),
        5 => (any::<Index>(), vector_op()).prop_map(|(at, how)| Mutation::Vector { at, how }),
        6 => field,
        1 => answer_key().prop_map(|with| Mutation::Answer { with }),
    ]
}

impl Mutation {
    /// Applies the mutation; a mutation with nothing to act on (no number in the file, say)
    /// leaves the file as it is.
    fn apply(&self, root: &mut J) {
        let pick = |root: &J, i: &Index, keep: &dyn Fn(&J) -> bool| {
            let paths = root.paths(keep);
            (!paths.is_empty()).then(|| paths[i.index(paths.len())].clone())
        };
        let is_obj = |j: &J| matches!(j, J::Obj(f) if !f.is_empty());
        match self {
            Mutation::Replace { at, with } => {
                if let Some(p) = pick(root, at, &|_| true) {
                    *root.at_mut(&p) = with.clone();
                }
            }
            Mutation::Number { at, text } => {
                if let Some(p) = pick(root, at, &|j| matches!(j, J::Num(_))) {
                    *root.at_mut(&p) = J::Num((*text).into());
                }
            }
            Mutation::Remove { at, key } => {
                if let Some(p) = pick(root, at, &is_obj) {
                    if let J::Obj(fields) = root.at_mut(&p) {
                        let k = key.index(fields.len());
                        fields.remove(k);
                    }
                }
            }
            Mutation::Duplicate { at, key, with } => {
                if let Some(p) = pick(root, at, &is_obj) {
                    if let J::Obj(fields) = root.at_mut(&p) {
                        let name = fields[key.index(fields.len())].0.clone();
                        fields.push((name, with.clone()));
                    }
                }
            }
            Mutation::Add { at, key, with } => {
                if let Some(p) = pick(root, at, &|j| matches!(j, J::Obj(_))) {
                    if let J::Obj(fields) = root.at_mut(&p) {
                        fields.push((key.clone(), with.clone()));
                    }
                }
            }
            Mutation::Resize { at, how } => {
                if let Some(p) = pick(root, at, &|j| matches!(j, J::Arr(_))) {
                    if let J::Arr(items) = root.at_mut(&p) {
                        match how {
                            Resize::Pop(i) if !items.is_empty() => {
                                let k = i.index(items.len());
                                items.remove(k);
                            }
                            Resize::Repeat(i) if !items.is_empty() => {
                                let k = i.index(items.len());
                                items.insert(k, items[k].clone());
                            }
                            Resize::Push(j) => items.push(j.clone()),
                            Resize::Clear => items.clear(),
                            Resize::KeepTwo => items.truncate(2),
                            _ => {}
                        }
                    }
                }
            }
            Mutation::Word { at, word } => {
                if let Some(p) = pick(root, at, &|j| matches!(j, J::Str(_))) {
                    *root.at_mut(&p) = J::Str(word.clone());
                }
            }
            Mutation::Vector { at, how } => {
                let vectors = root.paths(&J::is_triple);
                if vectors.is_empty() {
                    return;
                }
                let target = vectors[at.index(vectors.len())].clone();
                let get = |i: &Index| root.at(&vectors[i.index(vectors.len())]).triple();
                let factor = |f: &str| f.parse::<f64>().expect("a factor");
                let new = match how {
                    VectorOp::Zero => Some([0.0; 3]),
                    VectorOp::Scale(f) => {
                        root.at(&target).triple().map(|v| v.map(|x| x * factor(f)))
                    }
                    VectorOp::Copy(i) => get(i),
                    VectorOp::Negate(i) => get(i).map(|v| v.map(|x| -x)),
                    VectorOp::Multiple(i, f) => get(i).map(|v| v.map(|x| x * factor(f))),
                    VectorOp::Difference(a, b) => get(a)
                        .zip(get(b))
                        .map(|(a, b)| [a[0] - b[0], a[1] - b[1], a[2] - b[2]]),
                };
                if let Some(v) = new {
                    *root.at_mut(&target) = J::from_triple(v);
                }
            }
            Mutation::Field { at, key, value } => {
                let has_key =
                    |j: &J| matches!(j, J::Obj(fields) if fields.iter().any(|(k, _)| k == key));
                if let Some(p) = pick(root, at, &has_key) {
                    if let J::Obj(fields) = root.at_mut(&p) {
                        for (k, v) in fields.iter_mut() {
                            if k == key {
                                *v = J::raw(value);
                            }
                        }
                    }
                }
            }
            Mutation::Answer { with } => set_field(root, "answer", with.clone()),
        }
    }
}

/// Generator (c): a bundled file with one to four mutations (most often one, so that many
/// cases pass validation); scenes as often as exercises, though there are fewer of them.
fn mutated_file() -> impl Strategy<Value = Input> {
    let (scenes, exercises): (Vec<usize>, Vec<usize>) =
        (0..bases().len()).partition(|&i| bases()[i].name.starts_with("scenes/"));
    let base = prop_oneof![select(scenes), select(exercises)];
    let mutations = prop_oneof![
        3 => prop::collection::vec(mutation(), 1..=1),
        2 => prop::collection::vec(mutation(), 2..=4),
    ];
    (base, mutations).prop_map(|(i, mutations)| {
        let base = &bases()[i];
        let mut json = base.json.clone();
        for m in &mutations {
            m.apply(&mut json);
        }
        Input {
            what: format!("{} with {mutations:?}", base.name),
            bytes: json.text().into_bytes(),
        }
    })
}

// ---------------------------------------------------------------------------------------------
// One case: every path, both precisions
// ---------------------------------------------------------------------------------------------

/// A generated file: what it is (the base and the mutations) and its bytes.
#[derive(Clone)]
struct Input {
    what: String,
    bytes: Vec<u8>,
}

impl fmt::Debug for Input {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        const SHOWN: usize = 3000;
        let text = String::from_utf8_lossy(&self.bytes);
        let cut: String = text.chars().take(SHOWN).collect();
        write!(f, "{}\n--- {} bytes:\n{cut}", self.what, self.bytes.len())?;
        if cut.len() < text.len() {
            write!(f, "… (cut)")?;
        }
        Ok(())
    }
}

/// A folder for one test's cases, with the mesh fixtures that `file` fields may name.
struct Workspace {
    dir: TempDir,
    case: PathBuf,
}

impl Workspace {
    fn new() -> Workspace {
        let dir = tempfile::Builder::new()
            .prefix("phong-fuzz-")
            .tempdir()
            .expect("a temporary folder");
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        fs::copy(root.join("scenes/torus.obj"), dir.path().join("torus.obj"))
            .expect("the torus is copied");
        fs::create_dir(dir.path().join("sub")).expect("a sub-folder");
        let triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        let fixtures: &[(&str, &[u8])] = &[
            ("garbage.obj", b"v 1 2\nf 1 2 3 x\nvt\nusemtl\n\x01\x02"),
            ("degenerate.obj", b"v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"),
            ("no-faces.obj", triangle.as_bytes()),
            ("huge.obj", b"v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nf 1 2 3\n"),
            ("far-index.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
            ("zero-index.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
            (
                "negative-index.obj",
                b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -9\n",
            ),
            (
                "overflow-index.obj",
                b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 18446744073709551617\n",
            ),
            ("binary.obj", b"\xff\xfe\x00v 0 0 0\n\xc3f 1 2 3\n"),
        ];
        for (name, bytes) in fixtures {
            fs::write(dir.path().join(name), bytes).expect("a fixture is written");
        }
        // A name with a space and an accent, so messages show paths as they are.
        let case = dir.path().join("cáse 1.json");
        Workspace { dir, case }
    }
}

/// What happened to one case, counted for the summary.
#[derive(Default)]
struct Tally {
    cases: AtomicUsize,
    rejected: AtomicUsize,
    solved: AtomicUsize,
    checked: AtomicUsize,
    rendered: AtomicUsize,
}

impl Tally {
    fn add(counter: &AtomicUsize) {
        counter.fetch_add(1, Ordering::Relaxed);
    }
}

/// Runs `f`, turning a panic into a failure that names the path.
fn guarded<T>(label: &str, f: impl FnOnce() -> T) -> Result<T, String> {
    panic::catch_unwind(AssertUnwindSafe(f)).map_err(|p| {
        let what = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "(no message)".into());
        format!("{label} panicked: {what}")
    })
}

impl Workspace {
    /// Writes a case file. The old one is removed first: ext4 flushes a file rewritten in
    /// place on close (`auto_da_alloc`), which made the cases wait on the disk.
    fn write(&self, bytes: &[u8]) -> Result<(), String> {
        let _ = fs::remove_file(&self.case);
        fs::write(&self.case, bytes).map_err(|e| format!("cannot write the case: {e}"))
    }
}

/// Runs every path of `phong` on one input; `Err` describes the first broken promise.
fn run_case(ws: &Workspace, input: &Input, tally: &Tally) -> Result<(), String> {
    Tally::add(&tally.cases);
    ws.write(&input.bytes)?;
    let json: Option<Shape> = serde_json::from_slice(&input.bytes).ok();
    let context = Context {
        path: &ws.case,
        input: &input.bytes,
        json: json.as_ref(),
    };
    let accepted64 = precision::<f64>(&context, tally)?;
    let accepted32 = precision::<f32>(&context, tally)?;
    if !accepted64 && !accepted32 {
        Tally::add(&tally.rejected);
    }
    if matches!(&json, Some(Shape::Obj(fields)) if fields.iter().any(|(k, _)| k == "answer")) {
        check_path(&context, tally)?;
    }
    Ok(())
}

/// The input of one case, as the checks need it.
struct Context<'a> {
    path: &'a Path,
    input: &'a [u8],
    /// The input's shape, when it is JSON.
    json: Option<&'a Shape>,
}

/// Solve, explain and (for a file with a camera) render in precision `R`. Returns whether the
/// file was accepted by the loader.
fn precision<R: Real>(c: &Context, tally: &Tally) -> Result<bool, String> {
    let p = R::NAME;
    let solved = guarded(&format!("solve ({p})"), || {
        phong::solve::solve_file::<R>(c.path)
    })?;
    match solved {
        Ok((problem, solution)) => {
            Tally::add(&tally.solved);
            let file = c.path.display().to_string();
            guarded(&format!("the reports ({p})"), || -> Result<(), String> {
                let doc = reports::json::document(&file, &problem, &solution);
                finite_tree(&doc, &format!("the JSON document ({p})"))?;
                serde_json::to_value(&doc).map_err(|e| format!("the JSON document ({p}): {e}"))?;
                no_nan_text(
                    &reports::text::render(&file, &problem, &solution),
                    &format!("the text report ({p})"),
                    c,
                )?;
                for lang in [Lang::En, Lang::Pt] {
                    let x = reports::explain::explain(&file, &problem, &solution, lang);
                    let xs = std::slice::from_ref(&x);
                    let label = |f: &str| format!("the {f} explanation ({p}, {lang:?})");
                    no_nan_text(
                        &reports::text::write_explanation(&x, true),
                        &label("text"),
                        c,
                    )?;
                    no_nan_text(&reports::markdown::write_all(xs), &label("Markdown"), c)?;
                    no_nan_text(
                        &reports::latex::write_all(
                            xs,
                            reports::latex::LatexOptions { fragment: false },
                        ),
                        &label("LaTeX"),
                        c,
                    )?;
                    no_nan_text(
                        &reports::html::write_all(
                            xs,
                            reports::html::HtmlOptions { fragment: false },
                            lang,
                        ),
                        &label("HTML"),
                        c,
                    )?;
                }
                Ok(())
            })??;
        }
        Err(e) => error_is_clear(&e, c, &format!("solve ({p})"))?,
    }
    let loaded = guarded(&format!("load ({p})"), || problem::load::<R>(c.path))?;
    match loaded {
        Ok((_, problem)) => {
            if problem.camera.is_some() && !problem.surfaces().is_empty() {
                Tally::add(&tally.rendered);
                guarded(&format!("render ({p})"), || render_tiny(problem, c))??;
            }
            Ok(true)
        }
        Err(e) => {
            error_is_clear(&e, c, &format!("load ({p})"))?;
            Ok(false)
        }
    }
}

/// A render of at most 8×6 pixels (4 samples, level 3), every pixel's colour checked; the
/// centre pixel explained (text and JSON); the POV-Ray export in f64.
fn render_tiny<R: Real>(mut problem: problem::Problem<R>, c: &Context) -> Result<(), String> {
    let p = R::NAME;
    let file = c.path.display().to_string();
    let mut camera = problem.camera.expect("a scene has a camera");
    camera.width = camera.width.min(8);
    camera.height = camera.height.min(6);
    problem.camera = Some(camera);
    problem.render.samples = problem.render.samples.min(4);
    problem.render.max_level = problem.render.max_level.min(3);

    let scene = tracer::Scene::new(&problem);
    let (image, _) = tracer::render(&problem, &camera, &scene, &|| {});
    if image.rgb.len() != camera.width as usize * camera.height as usize * 3 {
        return Err(format!(
            "render ({p}): the image has {} bytes",
            image.rgb.len()
        ));
    }
    // The image clamps each colour to [0, 1], and NaN becomes black there: look before.
    let rays = tracer::CameraRays::new(&camera);
    let tracer = Tracer {
        scene: &scene,
        problem: &problem,
    };
    for y in 0..camera.height {
        for x in 0..camera.width {
            let color = tracer.trace(rays.ray(x, y, 0.5, 0.5), &mut Counts::default(), &mut ());
            if color.to_array().iter().any(|v| v.to_f64().is_nan()) {
                return Err(format!("render ({p}): pixel {x},{y} traced to NaN"));
            }
        }
    }
    let (x, y) = (camera.width / 2, camera.height / 2);
    match tracer::explain_pixel(&problem, &camera, &scene, x, y) {
        Ok(e) => {
            let doc = reports::pixel::document(&file, &problem, &e);
            finite_tree(&doc, &format!("the pixel's JSON ({p})"))?;
            serde_json::to_value(&doc).map_err(|e| format!("the pixel's JSON ({p}): {e}"))?;
            no_nan_text(
                &reports::pixel::render_text(&file, &problem, &e),
                &format!("the pixel's text ({p})"),
                c,
            )?;
        }
        Err(e) => error_is_clear(&e.at(c.path), c, &format!("explain-pixel ({p})"))?,
    }
    if R::NAME == "f64" {
        let (_, problem64) = problem::load::<f64>(c.path).map_err(|e| e.to_string())?;
        match phong::export::pov::export(&problem64) {
            Ok(sdl) => no_nan_text(&sdl, "the POV-Ray SDL", c)?,
            Err(e) => {
                if e.what.is_empty() || e.why().is_empty() || e.fix().is_empty() {
                    return Err(format!("export-pov: an unclear refusal: {e:?}"));
                }
            }
        }
    }
    Ok(())
}

/// `phong check FILE` with the file's answer key.
fn check_path(c: &Context, tally: &Tally) -> Result<(), String> {
    let options = CheckOptions {
        answer: None,
        scale: Some(Scale::Unit),
        ..Default::default()
    };
    let checked = guarded("check", || check::check_file(c.path, &options))?;
    match &checked.outcome {
        Ok(_) => {
            Tally::add(&tally.checked);
            guarded("the check reports", || -> Result<(), String> {
                for lang in [Lang::En, Lang::Pt] {
                    no_nan_text(&check::report::text(&checked, lang), "the check's text", c)?;
                }
                let doc = check::report::json(&checked);
                finite_tree(&doc, "the check's JSON")?;
                serde_json::to_value(&doc).map_err(|e| format!("the check's JSON: {e}"))?;
                Ok(())
            })??;
        }
        Err(f) => {
            let file = c.path.display().to_string();
            let message = f.message.to_string();
            let known = ["read", "syntax", "invalid", "answer", "no_answer"];
            if !known.contains(&f.kind.code()) {
                return Err(format!("check: unknown failure kind {:?}", f.kind));
            }
            if !message.starts_with(&file) {
                return Err(format!(
                    "check: the message does not start with the file: {f:?}"
                ));
            }
            if f.kind.code() == "answer" && !message.contains("answer") {
                return Err(format!(
                    "check: the message does not name the answer: {f:?}"
                ));
            }
            message_is_tidy(&message, c, "check")?;
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// The promises: no NaN or infinity, clear errors
// ---------------------------------------------------------------------------------------------

/// Every number of a serialised report is finite (serde-value keeps NaN and infinity as such).
fn finite_tree(doc: &impl serde::Serialize, label: &str) -> Result<(), String> {
    use serde_value::Value as V;
    fn walk(v: &V, at: &mut String) -> Result<(), String> {
        let bad = |x: f64| (!x.is_finite()).then(|| format!("{x} at {at}"));
        match v {
            V::F64(x) => bad(*x).map_or(Ok(()), Err),
            V::F32(x) => bad(f64::from(*x)).map_or(Ok(()), Err),
            V::Option(Some(v)) | V::Newtype(v) => walk(v, at),
            V::Seq(items) => {
                for (i, item) in items.iter().enumerate() {
                    let len = at.len();
                    at.push_str(&format!("[{i}]"));
                    walk(item, at)?;
                    at.truncate(len);
                }
                Ok(())
            }
            V::Map(map) => {
                for (k, item) in map {
                    let len = at.len();
                    match k {
                        V::String(s) => at.push_str(&format!(".{s}")),
                        other => at.push_str(&format!(".{other:?}")),
                    }
                    walk(item, at)?;
                    at.truncate(len);
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
    let tree = serde_value::to_value(doc).map_err(|e| format!("{label}: {e}"))?;
    walk(&tree, &mut String::new()).map_err(|e| format!("{label} holds {e}"))
}

/// The words NaN and inf as a number would be printed (`NaN`, `inf`, `-inf`), not inside a word
/// ("infinite"). Words are runs of ASCII letters and digits, as numbers are printed: in
/// `NaN\ensuremath{\gamma}` (LaTeX) and `NaNγ` (the same text in the input) the word is `NaN`.
fn nan_tokens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_ascii_alphanumeric() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_alphanumeric() {
                i += 1;
            }
            let w: String = chars[start..i].iter().collect();
            let lower = w.to_lowercase();
            if lower == "nan" || lower == "inf" || lower == "infinity" {
                out.push(w);
            }
        } else {
            i += 1;
        }
    }
    out
}

/// No NaN or inf in a report, unless the input itself holds that word (a title, a name).
fn no_nan_text(text: &str, label: &str, c: &Context) -> Result<(), String> {
    let found = nan_tokens(text);
    if found.is_empty() {
        return Ok(());
    }
    let input = nan_tokens(&String::from_utf8_lossy(c.input));
    if found.iter().all(|w| input.contains(w)) {
        return Ok(());
    }
    let at = text
        .find(found[0].as_str())
        .map_or(0, |i| i.saturating_sub(200));
    let excerpt: String = text[at..].chars().take(400).collect();
    Err(format!("{label} shows {:?}: …{excerpt}…", found[0]))
}

/// No number of dozens of digits in a message (a number is written as a person would: 1e300),
/// and no NaN or inf, unless the input holds it.
fn message_is_tidy(message: &str, c: &Context, label: &str) -> Result<(), String> {
    let input = String::from_utf8_lossy(c.input);
    for run in message.split(|ch: char| !ch.is_ascii_digit()) {
        if run.len() > 30 && !input.contains(run) {
            return Err(format!(
                "{label}: a number of {} digits in: {message}",
                run.len()
            ));
        }
    }
    no_nan_text(message, &format!("{label}: the message"), c)
}

/// A rejection names the file, where (line and column, or a field of the format) and the fix.
fn error_is_clear(e: &ProblemError, c: &Context, label: &str) -> Result<(), String> {
    let shown = e.to_string();
    let file = c.path.display().to_string();
    let fail = |why: &str| Err(format!("{label}: {why}: {shown}"));
    if !shown.starts_with(&file) {
        return fail("the message does not start with the file's path");
    }
    match e {
        ProblemError::Syntax {
            line,
            column,
            field,
            ..
        } => {
            let (message, fix) = (e.message(), e.fix());
            if *line == 0 || !shown.starts_with(&format!("{file}:{line}:{column}: ")) {
                return fail("a syntax error without its line and column");
            }
            if message.trim().is_empty() || fix.trim().is_empty() {
                return fail("a syntax error without a message or a fix");
            }
            if let Some(f) = field {
                // An unknown field is named by its own name, which may hold any character:
                // what leads to it must be known.
                let unknown = message
                    .split_once("unknown field `")
                    .and_then(|(_, rest)| rest.rsplit_once("`, expected"))
                    .and_then(|(name, _)| f.strip_suffix(name));
                match unknown {
                    Some("") => {}
                    Some(parent) => {
                        field_is_known(parent.trim_end_matches('.'), c).or_else(|why| fail(&why))?
                    }
                    None => field_is_known(f, c).or_else(|why| fail(&why))?,
                }
            }
        }
        ProblemError::Invalid { field, .. } => {
            let (message, fix) = (e.message(), e.fix());
            if message.trim().is_empty() || fix.trim().is_empty() {
                return fail("a validation error without a message or a fix");
            }
            if !shown.contains(&format!(": {field}: ")) {
                return fail("the message does not show the field");
            }
            field_is_known(field, c).or_else(|why| fail(&why))?;
        }
        ProblemError::Read { .. } => return fail("a file that was just written is unreadable"),
        ProblemError::Usage { .. } => return fail("a file's error is reported as a usage error"),
    }
    message_is_tidy(&shown, c, label)
}

/// A field path of an error (`lights[1].falloff`, `materials.M.diffuse.k`) starts with a
/// top-level field of the format and, when the file is JSON, leads through the file: every part
/// but the last exists (the last may be the missing field).
fn field_is_known(field: &str, c: &Context) -> Result<(), String> {
    if field.is_empty() {
        return Err("an empty field".into());
    }
    let first = field
        .split(['.', '['])
        .next()
        .expect("split gives at least one part");
    if !TOP_LEVEL.contains(&first) && !first.is_empty() {
        return Err(format!("the field {field:?} is not a field of the format"));
    }
    match c.json {
        Some(json) if !resolves(json, field) => Err(format!(
            "the field {field:?} does not lead through the file"
        )),
        _ => Ok(()),
    }
}

/// The shape of a JSON document with every key kept, repeated ones too (serde_json's map keeps
/// only the last), to follow an error's field path through the file as written.
enum Shape {
    Leaf,
    Arr(Vec<Shape>),
    Obj(Vec<(String, Shape)>),
}

impl<'de> serde::Deserialize<'de> for Shape {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Shape, D::Error> {
        use serde::de::{MapAccess, SeqAccess, Visitor};
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Shape;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("JSON")
            }
            fn visit_bool<E>(self, _: bool) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_i64<E>(self, _: i64) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_u64<E>(self, _: u64) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_f64<E>(self, _: f64) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_str<E>(self, _: &str) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_unit<E>(self) -> Result<Shape, E> {
                Ok(Shape::Leaf)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Shape, A::Error> {
                let mut items = Vec::new();
                while let Some(item) = seq.next_element()? {
                    items.push(item);
                }
                Ok(Shape::Arr(items))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Shape, A::Error> {
                let mut fields = Vec::new();
                while let Some(field) = map.next_entry()? {
                    fields.push(field);
                }
                Ok(Shape::Obj(fields))
            }
        }
        d.deserialize_any(V)
    }
}

/// Whether every part of `path` but the last exists in `v`, through any of a repeated key's
/// values. Keys are matched whole, so a material named "a.b" is found.
fn resolves(v: &Shape, path: &str) -> bool {
    if path.is_empty() {
        return true;
    }
    if let Some(rest) = path.strip_prefix('[') {
        let Some((index, after)) = rest.split_once(']') else {
            return false;
        };
        let Ok(i) = index.parse::<usize>() else {
            return false;
        };
        return match v {
            Shape::Arr(items) => match items.get(i) {
                Some(item) => resolves(item, after),
                None => after.is_empty(),
            },
            _ => after.is_empty(),
        };
    }
    let rest = path.strip_prefix('.').unwrap_or(path);
    if let Shape::Obj(fields) = v {
        for (k, child) in fields {
            if let Some(after) = rest.strip_prefix(k.as_str()) {
                if (after.is_empty() || after.starts_with(['.', '['])) && resolves(child, after) {
                    return true;
                }
            }
        }
    }
    // Not found: only the last part may be missing.
    !rest.contains(['.', '['])
}

// ---------------------------------------------------------------------------------------------
// Running a fuzz test within its budget
// ---------------------------------------------------------------------------------------------

// Cases per round of each fuzz test when `PHONG_FUZZ_CASES` is not set. In the debug profile
// (`cargo test`) on 2 cores the file takes 10 to 13 s: arbitrary JSON runs at about 1,000 cases/s,
// almost-JSON bytes at 500, mutated files (which solve, check and render) at 75, and the binary
// (six runs of `phong` per rejected file, most cases rejected) at 45 (README "Tests").
const CASES_ARBITRARY: u32 = 2000;
const CASES_ALMOST: u32 = 2000;
const CASES_MUTATED: u32 = 1000;
const CASES_BINARY: u32 = 128;
// `phong serve`'s API (a debug server on loopback): each case is sent to /api/check and
// /api/solve; about 350 cases/s, so `.ci/run`'s 40 rounds take about 35 s.
#[cfg(feature = "serve")]
const CASES_SERVE: u32 = 300;

fn env_number(name: &str) -> Option<u64> {
    let v = std::env::var(name).ok()?;
    Some(
        v.trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v:?} is not a whole number")),
    )
}

/// The first round's seed: `PHONG_FUZZ_SEED` (a number, or `random` for the clock), else fixed.
fn first_seed() -> u64 {
    match std::env::var("PHONG_FUZZ_SEED") {
        Ok(s) if s.trim() == "random" => std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(1, |d| d.as_nanos() as u64),
        Ok(s) => s
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("PHONG_FUZZ_SEED={s:?} is not a number or `random`")),
        Err(_) => 0x5eed_f022,
    }
}

/// How many rounds a fuzz test runs, and whether a clock may decide it.
enum Rounds {
    /// Exactly this many rounds, seeds `first`, `first + 1`, …: the same cases on every machine
    /// (plain `cargo test`: 1; `.ci/run`: `PHONG_FUZZ_ROUNDS`).
    Fixed(u64),
    /// Rounds until this much time has passed (`PHONG_FUZZ_SECONDS`): exploration only, by
    /// `.ci/fuzz-explore`. Which cases run then depends on the machine's speed, so it is refused
    /// under `CI=true`.
    Timed(Duration),
}

fn rounds() -> Rounds {
    let fixed = env_number("PHONG_FUZZ_ROUNDS");
    match env_number("PHONG_FUZZ_SECONDS") {
        Some(_) if fixed.is_some() => {
            panic!("PHONG_FUZZ_ROUNDS and PHONG_FUZZ_SECONDS are alternatives: set one of them")
        }
        Some(_) if std::env::var("CI").is_ok_and(|v| v == "true") => panic!(
            "PHONG_FUZZ_SECONDS is for exploration (.ci/fuzz-explore), never for CI: with a time \
             budget the cases tested depend on the machine's speed. Use PHONG_FUZZ_ROUNDS"
        ),
        Some(secs) => Rounds::Timed(Duration::from_secs(secs)),
        None => Rounds::Fixed(fixed.unwrap_or(1).max(1)),
    }
}

/// Runs rounds of `cases` cases of `strategy` through `test` ([`rounds`]: one round by default),
/// and panics with the seed and the minimised input on a failure.
fn fuzz<S>(
    name: &str,
    strategy: S,
    cases_default: u32,
    test: impl Fn(&S::Value) -> Result<(), String>,
) where
    S: Strategy,
    S::Value: Clone + fmt::Debug + AsRef<[u8]>,
{
    let cases = env_number("PHONG_FUZZ_CASES").map_or(cases_default, |n| n as u32);
    let rounds = rounds();
    let first = first_seed();
    // Each test draws from its own stream.
    let salt = name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    });
    let started = Instant::now();
    let mut round = 0u64;
    let mut total = 0u64;
    loop {
        let seed = first.wrapping_add(round);
        let config = Config {
            cases,
            max_shrink_iters: 2048,
            failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
                "proptest-regressions/fuzz.txt",
            ))),
            max_shrink_time: 120_000,
            source_file: Some(file!()),
            rng_seed: RngSeed::Fixed(seed ^ salt),
            ..Config::default()
        };
        let mut runner = TestRunner::new(config);
        let result = runner.run(&strategy, |input| test(&input).map_err(TestCaseError::fail));
        total += u64::from(cases);
        if let Err(e) = result {
            let (why, input) = match e {
                TestError::Fail(why, input) => (why.to_string(), Some(input)),
                TestError::Abort(why) => (why.to_string(), None),
            };
            let shown = match &input {
                Some(i) => format!(
                    "minimal input (saved as {}):\n{i:?}",
                    save_failure(name, i.as_ref()).display()
                ),
                None => String::new(),
            };
            panic!(
                "fuzz test {name} failed in round {round} (seed {seed}: rerun with \
                 PHONG_FUZZ_SEED={seed} PHONG_FUZZ_CASES={cases} cargo test --test fuzz {name}).\n\
                 {why}\n\n{shown}"
            );
        }
        round += 1;
        let more = match rounds {
            Rounds::Fixed(n) => round < n,
            Rounds::Timed(budget) => started.elapsed() < budget,
        };
        if !more {
            break;
        }
    }
    let secs = started.elapsed().as_secs_f64();
    eprintln!(
        "fuzz {name}: {total} cases in {round} round(s) from seed {first} in {secs:.1} s ({:.1} cases/s)",
        total as f64 / secs
    );
}

fn save_failure(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fuzz-failures");
    let path = dir.join(format!("{name}.json"));
    let _ = fs::create_dir_all(&dir).and_then(|()| fs::write(&path, bytes));
    path
}

impl AsRef<[u8]> for Input {
    fn as_ref(&self) -> &[u8] {
        &self.bytes
    }
}

fn report(name: &str, tally: &Tally) {
    let n = |c: &AtomicUsize| c.load(Ordering::Relaxed);
    eprintln!(
        "fuzz {name}: {} cases: {} rejected in both precisions, {} solves, {} checks, {} renders",
        n(&tally.cases),
        n(&tally.rejected),
        n(&tally.solved),
        n(&tally.checked),
        n(&tally.rendered)
    );
}

fn fuzz_paths(name: &str, strategy: impl Strategy<Value = Input>, cases: u32) {
    let ws = Workspace::new();
    let tally = Tally::default();
    fuzz(name, strategy, cases, |input| run_case(&ws, input, &tally));
    report(name, &tally);
}

// ---------------------------------------------------------------------------------------------
// The fuzz tests
// ---------------------------------------------------------------------------------------------

#[test]
fn arbitrary_json_never_panics_and_every_rejection_is_clear() {
    fuzz_paths("arbitrary_json", arbitrary_json(), CASES_ARBITRARY);
}

#[test]
fn almost_json_bytes_never_panic_and_every_rejection_is_clear() {
    fuzz_paths("almost_json", almost_json(), CASES_ALMOST);
}

#[test]
fn mutated_files_solve_render_and_check_without_panic_or_nan() {
    fuzz_paths("mutated_files", mutated_file(), CASES_MUTATED);
}

/// The binary on rejected inputs: exit code 2, `error: FILE…` on standard error, no panic, and
/// no output file for `solve`, `render`, `export-pov` and `check` (with `--format json`, `solve`
/// writes the complete document with its `"error"` object, as tests/bad_input.rs requires).
#[test]
fn the_binary_exits_2_and_writes_nothing_for_a_rejected_file() {
    let ws = Workspace::new();
    let strategy = prop_oneof![3 => mutated_file(), 1 => almost_json()];
    let ran = AtomicUsize::new(0);
    fuzz("binary", strategy, CASES_BINARY, |input| {
        ws.write(&input.bytes)?;
        if problem::load::<f64>(&ws.case).is_ok() {
            return Ok(());
        }
        ran.fetch_add(1, Ordering::Relaxed);
        binary_rejects(&ws)
    });
    eprintln!(
        "fuzz binary: {} rejected files through the binary",
        ran.load(Ordering::Relaxed)
    );
}

fn binary_rejects(ws: &Workspace) -> Result<(), String> {
    let case = ws.case.to_str().expect("a UTF-8 path");
    let out_dir = ws.dir.path().join("out");
    let _ = fs::remove_dir_all(&out_dir);
    fs::create_dir(&out_dir).map_err(|e| e.to_string())?;
    let out = |name: &str| out_dir.join(name).to_str().expect("UTF-8").to_owned();
    let runs: Vec<(&str, Vec<String>, Option<String>)> = vec![
        (
            "solve",
            vec!["solve".into(), case.into(), "-o".into(), out("solve.txt")],
            None,
        ),
        (
            "solve --format html",
            vec![
                "solve".into(),
                case.into(),
                "--format".into(),
                "html".into(),
                "-o".into(),
                out("solve.html"),
            ],
            None,
        ),
        (
            "solve --format json",
            vec![
                "solve".into(),
                case.into(),
                "--format".into(),
                "json".into(),
                "-o".into(),
                out("solve.json"),
            ],
            Some(out("solve.json")),
        ),
        (
            "render",
            vec!["render".into(), case.into(), "-o".into(), out("image.png")],
            None,
        ),
        (
            "export-pov",
            vec![
                "export-pov".into(),
                case.into(),
                "-o".into(),
                out("scene.pov"),
            ],
            None,
        ),
        (
            "check",
            vec!["check".into(), case.into(), "-o".into(), out("check.txt")],
            None,
        ),
    ];
    for (label, args, json_out) in runs {
        let output = support::phong()
            .args(&args)
            .output()
            .map_err(|e| e.to_string())?;
        let stderr = String::from_utf8_lossy(&output.stderr);
        let code = output.status.code();
        // `check` of a file without a key is also exit 2 (nothing to check).
        if code != Some(2) {
            return Err(format!(
                "{label}: exit code {code:?}, not 2; stderr: {stderr}"
            ));
        }
        if stderr.contains("panicked") {
            return Err(format!("{label}: panicked: {stderr}"));
        }
        if !stderr.starts_with(&format!("error: {case}")) {
            return Err(format!(
                "{label}: stderr does not start with `error: FILE`: {stderr}"
            ));
        }
        if !output.stdout.is_empty() {
            return Err(format!("{label}: wrote to standard output"));
        }
        let written: BTreeSet<String> = fs::read_dir(&out_dir)
            .map_err(|e| e.to_string())?
            .map(|e| {
                e.expect("an entry")
                    .path()
                    .to_str()
                    .expect("UTF-8")
                    .to_owned()
            })
            .collect();
        match &json_out {
            None if !written.is_empty() => {
                return Err(format!("{label}: wrote {written:?} for a rejected file"));
            }
            Some(p) if written.len() > 1 => {
                return Err(format!("{label}: wrote {written:?}, more than {p}"));
            }
            Some(p) if written.contains(p) => {
                let doc: Value =
                    serde_json::from_str(&fs::read_to_string(p).map_err(|e| e.to_string())?)
                        .map_err(|e| {
                            format!("{label}: the output is not one JSON document: {e}")
                        })?;
                if doc
                    .pointer("/error/message")
                    .and_then(Value::as_str)
                    .is_none()
                {
                    return Err(format!("{label}: the document has no error message: {doc}"));
                }
                fs::remove_file(p).map_err(|e| e.to_string())?;
            }
            _ => {}
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Regressions: what the fuzz tests found, each with its minimised input
// ---------------------------------------------------------------------------------------------

/// Writes `bytes` as a case file in a fresh workspace and loads it in f64.
fn load_bytes(bytes: &[u8]) -> (Workspace, Result<problem::Problem<f64>, ProblemError>) {
    let ws = Workspace::new();
    fs::write(&ws.case, bytes).expect("the case is written");
    let loaded = problem::load::<f64>(&ws.case).map(|(_, p)| p);
    (ws, loaded)
}

/// The syntax error of a file that must be rejected: (line, column, message, fix), the
/// message after its field when it has one (`viewer: too many elements: …`).
fn syntax_error(bytes: &[u8]) -> (usize, usize, String, String) {
    match load_bytes(bytes).1 {
        Err(e @ ProblemError::Syntax { .. }) => {
            let ProblemError::Syntax {
                line,
                column,
                ref field,
                ..
            } = e
            else {
                unreachable!()
            };
            // The message as the user reads it: after its field, when the parser knows it.
            let message = match field {
                Some(f) => format!("{f}: {}", e.message()),
                None => e.message(),
            };
            (line, column, message, e.fix())
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

#[test]
fn a_file_that_is_not_utf8_gets_the_position_of_the_bad_byte_not_check_the_path() {
    // Found as a one-byte file 0xFF; it was "cannot read the file … Fix: check the path".
    // `{"title": "` is 11 bytes, so the bad byte is column 12 of line 2 here.
    let (line, column, message, fix) = syntax_error(b"{\n{\"title\": \"\xff\"}");
    assert_eq!((line, column), (2, 12));
    assert!(
        message.contains("0xFF") && message.contains("UTF-8"),
        "{message}"
    );
    assert!(fix.contains("save the file as UTF-8"), "{fix}");
}

#[test]
fn a_byte_order_mark_is_skipped() {
    let mut bytes = b"\xef\xbb\xbf".to_vec();
    bytes.extend_from_slice(bases()[0].text.as_bytes());
    assert!(load_bytes(&bytes).1.is_ok(), "{}", bases()[0].name);
}

#[test]
fn a_file_that_is_an_array_says_a_problem_is_one_object() {
    // It was "[0]: invalid type: map, expected a string": serde read the array as the fields
    // in order, the first being `$schema`.
    let (line, column, message, _) = syntax_error(b"\n  [{\"title\": \"x\"}]");
    assert_eq!((line, column), (2, 3));
    assert!(message.contains("the file is an array"), "{message}");
    let (_, _, message, _) = syntax_error(b"42");
    assert!(message.contains("the file is a number"), "{message}");
}

#[test]
fn an_object_of_the_format_written_as_an_array_is_rejected_and_named() {
    // `"ray": [[0, 0, 5], [0, 0, -1]]` was read as a ray, and `"point": [3, 1, 3]` failed with
    // "point[0]: expected an array of length 3".
    for (text, field, what) in [
        (
            r#"{"ray": [[0, 0, 5], [0, 0, -1]], "surfaces": []}"#,
            "ray",
            "the ray: an object",
        ),
        (r#"{"point": [3, 1, 3]}"#, "point", "the point: an object"),
        (
            r#"{"render": [5]}"#,
            "render",
            "the render settings: an object",
        ),
        (
            r#"{"lights": [[1, 1, 1]]}"#,
            "lights[0]",
            "a light: an object",
        ),
        (
            r#"{"materials": {"M": [0.5, 0.5, 0.5]}}"#,
            "materials.M",
            "a material: an object",
        ),
    ] {
        let (_, _, message, _) = syntax_error(text.as_bytes());
        assert!(
            message.starts_with(&format!("{field}: invalid type: sequence")),
            "{message}"
        );
        assert!(message.contains(what), "{message}");
    }
}

#[test]
fn a_type_that_is_not_a_word_names_the_words_not_the_json_syntax() {
    // `"type": 5` was "expected value. Fix: check the JSON just before this position".
    let (_, _, message, fix) = syntax_error(br#"{"lights": [{"type": 5}]}"#);
    assert!(
        message.starts_with("lights[0].type: invalid type: integer `5`"),
        "{message}"
    );
    assert!(
        message.contains(r#""ambient", "point", "directional", "spot""#),
        "{message}"
    );
    assert!(!fix.contains("missing comma"), "{fix}");
}

#[test]
fn a_vector_of_four_numbers_is_too_many_elements_not_trailing_characters() {
    // It was "point.normal: trailing characters. Fix: check the JSON just before this position".
    let (line, column, message, fix) = syntax_error(br#"{"viewer": [1, 2, 3, 4]}"#);
    assert_eq!((line, column), (1, 22));
    assert_eq!(
        message,
        "viewer: too many elements: expected an array of length 3"
    );
    assert!(fix.contains("three numbers"), "{fix}");
}

#[test]
fn nan_and_infinity_in_a_file_are_named_in_the_fix() {
    for (text, word) in [
        (r#"{"viewer": [NaN, 1, 2]}"#, "NaN"),
        (r#"{"viewer": [nan, 1, 2]}"#, "nan"),
        (r#"{"viewer": [1, -Infinity, 2]}"#, "Infinity"),
    ] {
        let (_, _, _, fix) = syntax_error(text.as_bytes());
        assert!(
            fix.starts_with(&format!("JSON has no {word}:")),
            "{text}: {fix}"
        );
    }
}

#[test]
fn a_duplicated_field_says_to_give_it_once() {
    let (_, _, message, fix) = syntax_error(br#"{"lights": [], "lights": []}"#);
    assert_eq!(message, "duplicate field `lights`");
    assert!(fix.starts_with("give the field once"), "{fix}");
}

#[test]
fn a_material_defined_twice_is_an_error_not_the_last_one() {
    // `"materials": {"M": {…}, "M": {…}}` used the second M silently.
    let (_, _, message, fix) =
        syntax_error(br#"{"materials": {"M": {}, "M": {"ambient": [1, 1, 1]}}}"#);
    assert_eq!(message, "materials: duplicate material `M`");
    assert!(fix.starts_with("give each material its own name"), "{fix}");
}

#[test]
fn an_answer_scale_of_1e300_is_written_1e300_not_301_digits() {
    let ws = Workspace::new();
    let mut json = bases()
        .iter()
        .find(|b| b.name == "exercises/4.1.json")
        .expect("4.1 is bundled")
        .json
        .clone();
    set_field(
        &mut json,
        "answer",
        J::raw(r#"{"color": [0, 0, 0], "scale": 1e300}"#),
    );
    fs::write(&ws.case, json.text()).expect("written");
    let options = CheckOptions {
        answer: None,
        scale: Some(Scale::Unit),
        ..Default::default()
    };
    let failure = check::check_file(&ws.case, &options)
        .outcome
        .expect_err("scale 1e300 is refused");
    assert!(
        failure
            .message
            .to_string()
            .contains("answer.scale: 1e300 is not a scale"),
        "{}",
        failure.message
    );
}

#[test]
fn a_subnormal_diffuse_colour_exports_to_pov_ray_without_infinity() {
    // O_a·I_a / O_d overflowed: `emission rgb <0.0, 0.0, inf>`.
    let ws = Workspace::new();
    let text = r#"{"lights": [{"type": "ambient", "color": [0.3, 0.3, 0.3]}],
        "materials": {"blue": {"ambient": [0, 0, 0.1], "diffuse": [1e-311, 2e-311, 7e-311]}},
        "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "blue"}],
        "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45, "width": 8, "height": 6}}"#;
    fs::write(&ws.case, text).expect("written");
    let (_, problem) = problem::load::<f64>(&ws.case).expect("a valid scene");
    let sdl = phong::export::pov::export(&problem).expect("exportable");
    assert_eq!(nan_tokens(&sdl), Vec::<String>::new(), "{sdl}");
}

#[test]
fn a_point_so_far_that_the_mirrored_light_overflows_has_no_light_reversed_reading() {
    // 4.2 with P = (3, 1e308, 3): the light lies behind the surface, and the reading "L
    // reversed" mirrored it to 2P − P_l = (5, 2e308, 5), written as null (infinity) in the JSON.
    let ws = Workspace::new();
    let json = &bases()
        .iter()
        .find(|b| b.name == "exercises/4.2.json")
        .expect("4.2 is bundled")
        .json;
    let text = json.text().replace("[3, 1, 3]", "[3, 1e308, 3]");
    assert!(text.contains("\"position\": [3, 1e308, 3]"), "{text}");
    fs::write(&ws.case, &text).expect("written");
    let (problem, solution) = phong::solve::solve_file::<f64>(&ws.case).expect("solved");
    let doc = reports::json::document("4.2", &problem, &solution);
    finite_tree(&doc, "the JSON document").expect("finite");
    assert!(
        solution
            .readings
            .iter()
            .all(|r| r.code != phong::solve::ReadingCode::LightReversed),
        "the mirrored light is beyond f64"
    );
}

/// `phong solve`, `check` and `render` with `-o` and a rejected file write no output file.
#[test]
fn a_rejected_file_leaves_no_output_file() {
    // Found: `phong solve BAD -o out.txt` wrote an empty out.txt (exit 2).
    let ws = Workspace::new();
    fs::write(&ws.case, b"{\"lights\": 5}").expect("written");
    binary_rejects(&ws).expect("rejected cleanly");
}

/// `text` with its camera's eye (and look-at point) at the extreme coordinates `eye`
/// (`look_at`), which validation now refuses (beyond `±1e100`, where the intersection tests
/// could overflow: `tests/integration/bad_input.rs`): the file is refused naming the eye, and the
/// problem loaded with the camera of `text` is given them directly, so that the tracer's own
/// robustness at the ends of f64 is still tested.
fn with_far_camera(
    ws: &Workspace,
    text: &str,
    eye: [f64; 3],
    look_at: Option<[f64; 3]>,
) -> problem::Problem<f64> {
    use phong::core::V3;
    fs::write(&ws.case, text).expect("written");
    let (_, mut problem) = problem::load::<f64>(&ws.case).expect("a valid scene");
    let mut camera = problem.camera.expect("a camera");
    camera.eye = V3::<f64>::new(eye[0], eye[1], eye[2]);
    if let Some(l) = look_at {
        camera.look_at = V3::<f64>::new(l[0], l[1], l[2]);
    }
    problem.camera = Some(camera);
    let mut far: Value = serde_json::from_str(text).expect("JSON");
    far["camera"]["eye"] = serde_json::json!(eye);
    if let Some(l) = look_at {
        far["camera"]["look_at"] = serde_json::json!(l);
    }
    fs::write(&ws.case, far.to_string()).expect("written");
    match problem::load::<f64>(&ws.case) {
        Err(e @ ProblemError::Invalid { .. }) => {
            assert!(
                e.field().is_some_and(|f| f.starts_with("camera.")),
                "{eye:?}: {e}"
            );
            assert!(e.to_string().contains("within ±1e100"), "{e}");
        }
        other => panic!("the eye at {eye:?} was not refused: {other:?}"),
    }
    problem
}

#[test]
fn a_camera_whose_eye_and_look_at_are_near_opposite_ends_of_f64_renders() {
    // look_at − eye overflowed in the tracer's camera (validation computed it robustly), and
    // `phong render` panicked with "validated camera". Such a camera is now refused by
    // validation; the tracer is still given it directly.
    let ws = Workspace::new();
    let text = r#"{"lights": [{"type": "ambient", "color": [0.3, 0.3, 0.3]}],
        "materials": {"m": {"ambient": [0.5, 0.5, 0.5]}},
        "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
        "camera": {"eye": [-1, 0, 0], "look_at": [1, 0, 0], "fov": 45, "width": 8,
                   "height": 6}}"#;
    let problem = with_far_camera(&ws, text, [-1e308, 0.0, 0.0], Some([1e308, 0.0, 0.0]));
    let camera = problem.camera.expect("a camera");
    // Looking along +x from the far left, the sphere at the centre is in front of the eye.
    let rays = tracer::CameraRays::new(&camera);
    assert_eq!(rays.forward.to_array(), [1.0, 0.0, 0.0]);
    let scene = tracer::Scene::new(&problem);
    let (image, _) = tracer::render(&problem, &camera, &scene, &|| {});
    // The sphere, 1e308 away, is far smaller than a pixel: no pixel's centre ray meets it
    // (the nearest passes at an angle of about 0.05 rad), so the image is the black background.
    assert!(image.rgb.iter().all(|&b| b == 0));
}

#[test]
fn a_field_of_view_that_rounds_to_180_in_f32_is_refused_there() {
    // 179.999999999 is below 180 in f64 but rounds to 180 in f32, where tan(fov/2) is negative:
    // the f32 image came out upside down and mirrored.
    let ws = Workspace::new();
    let classic = &bases()
        .iter()
        .find(|b| b.name == "scenes/classic.json")
        .expect("the classic scene is bundled")
        .text;
    // (1e-46 rounds to 0 in f32.)
    for (fov, f32_ok) in [("179.999999999", false), ("179", true), ("1e-46", false)] {
        fs::write(
            &ws.case,
            classic.replace("\"fov\": 40", &format!("\"fov\": {fov}")),
        )
        .expect("written");
        assert!(
            problem::load::<f64>(&ws.case).is_ok(),
            "{fov} is a field of view in f64"
        );
        match problem::load::<f32>(&ws.case) {
            Ok(_) => assert!(f32_ok, "{fov} accepted in f32"),
            Err(e) => {
                assert!(!f32_ok, "{fov}: {e}");
                let why = if fov == "1e-46" {
                    "too small"
                } else {
                    "too close to 180"
                };
                let expected = format!("camera.fov: {fov} degrees is {why} for f32");
                assert!(e.to_string().contains(&expected), "{e}");
            }
        }
    }
}

#[test]
fn a_direction_whose_length_overflows_is_refused_not_reported_as_infinite() {
    // The ray direction (0, −1.8e308, 1.8e308) has a length of 2.5e308, beyond f64: the finding
    // "direction normalised" reported its length as infinity (null in the JSON).
    let (_, loaded) = load_bytes(
        br#"{"ray": {"origin": [8, 4, 6], "direction": [0, -1.7976931348623157e308, 1.7976931348623157e308]},
            "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [1, 1, 1], "material": {}}]}"#,
    );
    match loaded {
        Err(e @ ProblemError::Invalid { .. }) => {
            assert_eq!(e.field(), Some("ray.direction"));
            assert_eq!(
                e.message(),
                "the ray's direction is too long for f64: its length overflows"
            );
        }
        other => panic!("expected a validation error, got {other:?}"),
    }
}

#[test]
fn a_reflection_from_a_point_seen_from_1e308_away_leaves_from_a_finite_origin() {
    // The eye at y = 1e308 above the reflective floor: the floor's error bound summed
    // |O| + |Q| + |tD| = 2e308 before scaling it by γ₇, overflowed, and the reflection ray left
    // from (NaN, inf, NaN). Such an eye is now refused by validation; the tracer is still
    // given it directly.
    let ws = Workspace::new();
    let text = bundled("scenes/pov-materials.json");
    assert!(text.contains("\"eye\": [0, 2, 7]"), "the eye moved");
    let problem = with_far_camera(&ws, text, [0.0, 1e308, 7.0], None);
    let camera = problem.camera.expect("a camera");
    let scene = tracer::Scene::new(&problem);
    let e = tracer::explain_pixel(&problem, &camera, &scene, 160, 120).expect("explained");
    let doc = reports::pixel::document("pov-materials", &problem, &e);
    finite_tree(&doc, "the pixel's JSON").expect("every number finite");
    let rays = serde_json::to_value(&doc).expect("serialises")["samples"][0]["rays"].clone();
    assert!(
        rays.as_array().is_some_and(|r| r.len() >= 2),
        "a reflection ray: {rays}"
    );
}

#[test]
fn nesting_100000_deep_is_a_syntax_error_not_a_stack_overflow() {
    // A stack overflow would abort this test's process. The parser stops at the first level the
    // format does not allow (here the second), long before serde_json's limit of 128 levels.
    for (open, message) in [
        ("[", "lights[0]: invalid type: sequence, expected a light"),
        ("{\"a\": ", "lights: invalid type: map, expected a sequence"),
        ("[{\"type\": ", "lights[0].type: invalid type: sequence"),
    ] {
        let text = format!("{{\"lights\": {}", open.repeat(100_000));
        let (line, _, shown, _) = syntax_error(text.as_bytes());
        assert_eq!(line, 1);
        assert!(shown.starts_with(message), "{shown}");
    }
    let ws = Workspace::new();
    ws.write(format!("{{\"lights\": {}", "[".repeat(100_000)).as_bytes())
        .expect("written");
    binary_rejects(&ws).expect("rejected cleanly by the binary");
}

#[test]
fn an_unknown_field_named_like_a_path_is_named_whole() {
    // `{"a.?": 0}` was reported at field "a": the parser trimmed a trailing ".?", the path's
    // mark for an unknown position, from the field's own name.
    let ws = Workspace::new();
    ws.write(br#"{"a.?": 0}"#).expect("written");
    match problem::load::<f64>(&ws.case) {
        Err(e @ ProblemError::Syntax { .. }) => {
            assert_eq!(e.field(), Some("a.?"));
            // The field is the error's own part; the message is what is wrong with it.
            assert!(e.to_string().contains(": a.?: unknown field `a.?`"), "{e}");
            assert!(e.message().starts_with("unknown field `a.?`"), "{e}");
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

#[test]
fn a_huge_negative_colour_is_shown_as_written_not_in_40_digits() {
    // Found by the mutated-files round: a colour's negative component was echoed with `{}`,
    // which writes -1e39 as 40 digits; it is shown as the file writes it.
    let ws = Workspace::new();
    let text = bundled("exercises/4.1.json").replacen("[1, 1, 1]", "[-1e39, 0, 0]", 1);
    assert!(text.contains("-1e39"));
    ws.write(text.as_bytes()).expect("written");
    match problem::load::<f64>(&ws.case) {
        Err(e) => {
            let m = e.to_string();
            assert!(m.contains("[-1e39, 0, 0]"), "{m}");
        }
        Ok(_) => panic!("a negative colour was accepted"),
    }
}

/// A bundled file's text, by its path in the repository.
fn bundled(name: &str) -> &'static str {
    &bases()
        .iter()
        .find(|b| b.name == name)
        .expect("bundled")
        .text
}

/// `text` as a scene at the fuzz's tiny render settings (8×6 pixels, 4 samples, level 3), in
/// f64: the problem, its camera and its scene.
fn tiny_scene(
    ws: &Workspace,
    text: &str,
) -> (
    problem::Problem<f64>,
    problem::Camera<f64>,
    tracer::Scene<f64>,
) {
    fs::write(&ws.case, text).expect("written");
    let (_, mut problem) = problem::load::<f64>(&ws.case).expect("a valid scene");
    let mut camera = problem.camera.expect("a camera");
    (camera.width, camera.height) = (8, 6);
    problem.camera = Some(camera);
    problem.render.samples = 4;
    problem.render.max_level = 3;
    let scene = tracer::Scene::new(&problem);
    (problem, camera, scene)
}

#[test]
fn a_floor_met_beyond_the_range_of_f64_is_not_met() {
    // Round 18 of CI's extended fuzz (seed 1592651828): the classic scene seen from (1e308,
    // 1e308, 1e308) with a field of view of 179.9999999°. A corner ray runs almost parallel to
    // the floor and meets it at a finite t where O + tD is beyond f64 (x = −inf); the explained
    // pixel's JSON printed that hit point (`"point": [null, 0.0, 6.3e307]`). A meeting point
    // that cannot be represented is no meeting point (docs/conventions.md): the ray misses.
    // Such an eye is now refused by validation; the tracer is still given it directly.
    let ws = Workspace::new();
    let text = bundled("scenes/classic.json").replace("\"fov\": 40", "\"fov\": 179.9999999");
    assert!(text.contains("179.9999999"), "the fov was replaced");
    let (mut problem, _, _) = tiny_scene(&ws, &text);
    let mut camera = with_far_camera(&ws, &text, [1e308; 3], None)
        .camera
        .expect("a camera");
    (camera.width, camera.height) = (8, 6);
    problem.camera = Some(camera);
    let scene = tracer::Scene::new(&problem);
    for (x, y) in [(4, 3), (0, 0), (7, 5), (0, 5), (7, 0)] {
        let e = tracer::explain_pixel(&problem, &camera, &scene, x, y).expect("explained");
        let doc = reports::pixel::document("classic", &problem, &e);
        finite_tree(&doc, &format!("pixel {x},{y}'s JSON")).expect("every number finite");
    }
}

#[test]
fn a_pixel_whose_reflections_overflow_is_refused_not_shown_as_infinite() {
    // Found by .ci/fuzz-explore (round 272 of seed 1796145228465987254): the classic scene with
    // the mirror's reflectivity scaled to 9.5e299 and the floor's ambient O_a = 3.4028235e38.
    // Each ray's own colour is finite (the floor's ambient term is 0.2·3.4e38 = 6.8e37), but the
    // mirror's reflection adds O_r·C_r ≈ 9.5e299 · 6.8e37 ≈ 6.5e337, beyond f64: the explained
    // pixel's JSON held `"color": [inf, …]`. The solver refuses a colour that overflows; so
    // does the pixel's explanation now, naming a surface whose reflection overflowed.
    let ws = Workspace::new();
    let text = bundled("scenes/classic.json")
        .replace(
            "\"reflectivity\": [0.95, 0.95, 0.95]",
            "\"reflectivity\": [9.5e299, 9.5e299, 9.5e299]",
        )
        // The first material is the floor's.
        .replacen(
            "\"ambient\": [0.1, 0.1, 0.1]",
            "\"ambient\": [3.4028235e38, 0.1, 0.1]",
            1,
        );
    assert!(
        text.contains("9.5e299") && text.contains("3.4028235e38"),
        "{text}"
    );
    let (problem, camera, scene) = tiny_scene(&ws, &text);
    match tracer::explain_pixel(&problem, &camera, &scene, 4, 3) {
        Ok(e) => panic!(
            "explained with colour {:?}",
            e.samples.iter().map(|s| s.color).collect::<Vec<_>>()
        ),
        Err(e) => {
            assert!(
                e.field == "surfaces[0]" || e.field == "surfaces[1]",
                "the floor or the mirror: {e:?}"
            );
            assert!(e.message().contains("overflows f64"), "{e:?}");
            assert!(e.fix().contains("reflectivity"), "{e:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Answers, grading CSVs and numeric flags (issue 12)
// ---------------------------------------------------------------------------------------------

/// A fixed-seed runner of `cases` cases, for the small fuzz tests below.
fn small_runner(cases: u32, seed: u64) -> TestRunner {
    TestRunner::new(Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..Config::default()
    })
}

/// Text that is almost an answer: numbers (huge, tiny, signed, with decimal commas, Unicode
/// minus, full-width digits), separators, brackets and stray characters, up to 400 pieces.
fn almost_answer() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        Just("0.5".to_owned()),
        Just("1e400".to_owned()),
        Just("-1e-400".to_owned()),
        Just("0,245".to_owned()),
        Just("\u{2212}0.5".to_owned()),
        Just("\u{FF10}.5".to_owned()),
        Just("3/0".to_owned()),
        Just("255".to_owned()),
        Just("#80B34D".to_owned()),
        "[ ,;()\\[\\]{}#/+\\-eE.]".prop_map(|s: String| s),
        "\\PC{0,3}",
        "[0-9]{1,400}",
    ];
    proptest::collection::vec(piece, 0..400).prop_map(|v| v.join(" "))
}

#[test]
fn fuzz_answers_never_panic_and_their_errors_stay_short() {
    small_runner(300, 41)
        .run(&(almost_answer(), any::<bool>()), |(text, bits)| {
            let scale = if bits { Scale::Bits8 } else { Scale::Unit };
            match check::answer::parse(&text, scale) {
                Ok(a) => prop_assert!(a.values.iter().flatten().all(|v| v.is_finite()), "{:?}", a),
                // The answer is echoed shortened: a message of at most a few hundred characters
                // whatever was typed.
                Err(e) => prop_assert!(
                    e.to_string().chars().count() < 600,
                    "{}",
                    e.to_string().len()
                ),
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn fuzz_grading_arbitrary_bytes_never_panics_and_keeps_every_line() {
    let options = check::grade::Options {
        exercises: std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises"),
        scale: None,
        delimiter: None,
        ..check::grade::Options::default()
    };
    let byte = prop_oneof![
        Just(b','),
        Just(b';'),
        Just(b'\t'),
        Just(b'"'),
        Just(b'\n'),
        Just(b'\r'),
        Just(0u8),
        Just(0xFF),
        Just(b's'),
        Just(b'4'),
        Just(b'.'),
        Just(b'1'),
        Just(b' '),
        any::<u8>(),
    ];
    small_runner(300, 42)
        .run(&proptest::collection::vec(byte, 0..400), |bytes| {
            let report = check::grade::grade_bytes(&bytes, &options);
            // No more rows than lines, numbered 1, 2, … and at increasing lines.
            let lines = check::grade::lines(&check::grade::decode(&bytes)).count() as u64;
            prop_assert!(report.rows.len() as u64 <= lines);
            for (i, w) in report.rows.windows(2).enumerate() {
                prop_assert!(w[0].line < w[1].line, "rows {} and {}", i + 1, i + 2);
            }
            let csv = check::grade::rows_csv(&report);
            prop_assert!(!csv.contains(&0), "a NUL copied through");
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}

// ---------------------------------------------------------------------------------------------
// phong serve's API (issue 19)
// ---------------------------------------------------------------------------------------------

// Without the `serve` feature (on by default) there is no server to fuzz.
#[cfg(feature = "serve")]
use support::{http, server};

/// The generators of the file's other fuzz tests, sent to a running `phong serve` as the
/// `problem` of `POST /api/check` and `POST /api/solve` (raw bytes that are not UTF-8 or not
/// JSON as the whole body): every answer is a 200 or a 4xx with a JSON `error` and a message of
/// bounded size, never a 5xx or a dropped connection; a 200 from /api/check is byte for byte
/// the library's check of the same text ([`check::report::document`]); the server is alive at
/// the end.
#[cfg(feature = "serve")]
#[test]
fn serve_api_answers_every_generated_problem_with_json_and_never_a_5xx() {
    let mut server = server::Server::start(&[]);
    let addr = server.addr;
    let client = std::sync::Mutex::new(http::Client::connect(addr).expect("a connection"));
    let strategy = prop_oneof![
        2 => mutated_file(),
        1 => arbitrary_json(),
        1 => almost_json(),
    ];
    let options = CheckOptions {
        answer: Some("0.245 0.28 0.21".into()),
        scale: Some(Scale::Unit),
        ..Default::default()
    };
    fuzz("serve", strategy, CASES_SERVE, |input| {
        let mut c = client.lock().unwrap_or_else(|p| p.into_inner());
        let text = std::str::from_utf8(&input.bytes).ok();
        for path in ["/api/check", "/api/solve"] {
            let body = match text {
                Some(t) if path == "/api/check" => {
                    format!("{{\"problem\": {t}, \"answer\": \"0.245 0.28 0.21\"}}").into_bytes()
                }
                Some(t) => format!("{{\"problem\": {t}}}").into_bytes(),
                None => input.bytes.clone(),
            };
            let r = match c.send("POST", path, Some("application/json"), &body) {
                Ok(r) => r,
                Err(e) => {
                    *c = http::Client::connect(addr).map_err(|e| e.to_string())?;
                    // A body over the 64 kB limit: answered 413 and closed before all of it
                    // was written, its answer lost with the connection's reset.
                    if body.len() > 64 * 1024 {
                        continue;
                    }
                    return Err(format!("{path}: no response: {e}"));
                }
            };
            if !matches!(r.status, 200 | 400 | 413 | 422) {
                return Err(format!("{path}: status {}: {}", r.status, r.text()));
            }
            let doc: Value = serde_json::from_slice(&r.body)
                .map_err(|e| format!("{path}: {} is not JSON ({e}): {}", r.status, r.text()))?;
            if r.status != 200 {
                let e = if doc["error"].is_object() {
                    &doc["error"]
                } else {
                    &doc["steps_error"]
                };
                let m = e["message"].as_str().unwrap_or("");
                if m.is_empty() || m.len() > body.len() + 2000 {
                    return Err(format!("{path}: {}: unclear error: {doc}", r.status));
                }
            }
            if r.status == 200 && path == "/api/check" {
                let t = text.unwrap_or_default();
                let source = problem::Source::Text {
                    name: Path::new("problem"),
                    text: t,
                };
                let checked = check::check_source(source, &options);
                let expected = check::report::document(Some(&checked), None)
                    .map(|v| format!("{}\n", serde_json::to_string_pretty(&v).unwrap_or_default()));
                if expected.as_deref() != Some(r.text().as_str()) {
                    return Err(format!("/api/check differs from the library: {}", r.text()));
                }
            }
        }
        Ok(())
    });
    assert!(server.alive(), "the server is still running");
    let r = http::post_json(addr, "/api/check", "{\"exercise\": \"4.2\"}");
    assert_eq!(r.status, 200);
}
