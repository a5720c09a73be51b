//! The problem format: reading a JSON problem file, validating it, and the validated model.
//!
//! A problem names only what its question needs (README, "The problem format"): the parser
//! rejects unknown fields, and validation checks that every term the question can compute has
//! its inputs.

pub(crate) mod error;
pub(crate) mod faults;
pub(crate) mod field;
pub mod format;
pub(crate) mod kinds;
pub(crate) mod mesh;
pub(crate) mod mesh_faults;
pub(crate) mod model;
pub(crate) mod reading;
pub(crate) mod syntax;
pub use syntax::JsonError;
pub mod validate;
pub(crate) mod warnings;
pub(crate) mod written;

use std::path::{Path, PathBuf};

pub use error::{Invalid, ProblemError};
pub use format::{schema_json, ProblemFile};
pub(crate) use model::RenderOverrides;
pub use model::{
    AmbientInfo, Camera, GivenVector, LightInfo, NamedMaterial, Problem, ReflectivitySource,
    RenderSettings, Shared, Surface, SurfaceSource, Target,
};
pub use warnings::{Warning, WarningKind};

use crate::core::Real;
use crate::text::{Lang, Message};
use format::{LightSpec, LightType, SurfaceSpec, SurfaceType};
pub use reading::{Counted, Input, ReadFix, TooLarge, TooMany};
use reading::{Limit, SourceFault};
use serde::Deserialize;
use syntax::{Expected, JsonKind, Parse, Purpose, SyntaxFault, SyntaxFix, LONGEST_NAME};

/// The largest problem file read: 64 MiB (a scene of a million spheres is about 100 MB; a
/// chapter's exercise is 1 kB).
pub const MAX_PROBLEM_BYTES: u64 = 64 << 20;

/// The fix for an input that cannot be read, in English (for the messages not yet typed): a
/// smaller file when it is too large, else the path ([`ReadFix`]).
pub fn read_fix(e: &std::io::Error) -> String {
    ReadFix::of(e).text(Lang::En)
}

/// The bytes of the file at `path` (standard input for `-`), refusing a file of more than
/// `limit` bytes with [`TooLarge`] (`/dev/zero` given as a file ends there, not out of memory).
pub fn read_limited(path: &Path, limit: u64, what: Input) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let mut bytes = Vec::new();
    if path.as_os_str() == "-" {
        std::io::stdin()
            .lock()
            .take(limit + 1)
            .read_to_end(&mut bytes)?;
    } else {
        let file = std::fs::File::open(path)?;
        // Read in one piece: `take` hides the file's size from `read_to_end`, which would grow
        // the buffer by doubling (copying a large scene several times over). A size the
        // metadata gets wrong (0 for /proc files and devices) only costs that growth.
        if let Ok(meta) = file.metadata() {
            let _ = crate::text::memory::handled(|| {
                bytes.try_reserve_exact(meta.len().min(limit) as usize + 1)
            });
        }
        file.take(limit + 1).read_to_end(&mut bytes)?;
    }
    if bytes.len() as u64 > limit {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            TooLarge { limit, what },
        ));
    }
    Ok(bytes)
}

/// "out of memory: this needs about 2.1 GB" (or MB), for an allocation of `bytes` refused, in
/// English (for the messages not yet typed; `Limit::Memory` is the value).
pub fn out_of_memory(bytes: usize) -> String {
    Limit::Memory {
        needs: reading::Bytes(bytes),
    }
    .text(Lang::En)
}

/// Reads and parses a problem file (no validation). A leading byte order mark is skipped, as
/// editors on Windows write one.
/// A file `-` is standard input.
pub(crate) fn parse_file(path: &Path) -> Result<ProblemFile, ProblemError> {
    let text = read_text(path)?;
    parse_str(path, text.strip_prefix('\u{feff}').unwrap_or(&text))
}

/// The text of a problem file, read within its size limit and checked to be UTF-8 (a byte
/// order mark kept). A file `-` is standard input.
fn read_text(path: &Path) -> Result<String, ProblemError> {
    let bytes = read_limited(path, MAX_PROBLEM_BYTES, Input::ProblemFile).map_err(|source| {
        ProblemError::Read {
            path: path.to_owned(),
            source,
        }
    })?;
    String::from_utf8(bytes).map_err(|e| not_utf8(path, e.as_bytes(), e.utf8_error()))
}

/// A syntax error at `line`:`column` of the file at `path`.
fn syntax(
    path: &Path,
    line: usize,
    column: usize,
    field: Option<String>,
    what: Parse,
    fix: SyntaxFix,
) -> ProblemError {
    ProblemError::Syntax {
        path: path.to_owned(),
        line,
        column,
        field,
        fault: std::sync::Arc::new(SyntaxFault { what, fix }),
    }
}

/// A file that is not UTF-8 text: the line and column (in bytes) of its first bad byte.
fn not_utf8(path: &Path, bytes: &[u8], e: std::str::Utf8Error) -> ProblemError {
    let good = &bytes[..e.valid_up_to()];
    let line_start = good.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    syntax(
        path,
        1 + good.iter().filter(|&&b| b == b'\n').count(),
        1 + good.len() - line_start,
        None,
        Parse::NotUtf8 {
            byte: syntax::Hex(bytes[e.valid_up_to()]),
        },
        SyntaxFix::Utf8,
    )
}

/// The course policy's file name (`check::policy`), beside the exercises: a folder's
/// `*.json` files but this one are its problems, and this one given as a problem is told apart.
pub const POLICY_FILE: &str = "course-policy.json";

/// Whether `path` is one of a folder's exercises: a `*.json` file other than the course
/// policy ([`POLICY_FILE`]).
pub fn is_exercise_file(path: &Path) -> bool {
    path.extension().is_some_and(|x| x == "json")
        && path.file_name().is_some_and(|n| n != POLICY_FILE)
}

/// Parses the text of a problem file; `path` is only used in error messages.
///
/// A valid file is read once by plain serde_json, which keeps no path: tracking where the
/// parser is (serde_path_to_error records every key and index it passes) cost more than the
/// parse itself on a large scene. Only a file that fails is read again with the path tracked,
/// and that second reading gives the error, so the message names the same field, line and
/// column as before.
pub fn parse_str(path: &Path, source: &str) -> Result<ProblemFile, ProblemError> {
    // The course policy is never a problem, even one that would read as a problem (`{}`, the
    // defaults, reads as an empty problem: "nothing to shade").
    if path.file_name().is_some_and(|n| n == POLICY_FILE) {
        // The fix lists the problems of the folder the file was given in, as written
        // (`exercicios/` of `exercicios/course-policy.json`; nothing for a name alone).
        let written = path.to_string_lossy();
        let folder = written.strip_suffix(POLICY_FILE).unwrap_or("").to_owned();
        return Err(syntax(
            path,
            1,
            1,
            None,
            Parse::CoursePolicy,
            SyntaxFix::LeavePolicyOut { folder },
        ));
    }
    not_an_object(path, source)?;
    let mut de = serde_json::Deserializer::from_str(source);
    if let Ok(file) = ProblemFile::deserialize(&mut de).and_then(|f| de.end().map(|()| f)) {
        return Ok(file);
    }
    parse_tracked(path, source)
}

/// [`parse_str`] with the field path tracked, for the error of a file that failed. serde's
/// message is read into a value ([`Parse::read`]) here, once.
fn parse_tracked(path: &Path, source: &str) -> Result<ProblemFile, ProblemError> {
    let mut de = serde_json::Deserializer::from_str(source);
    let result = serde_path_to_error::deserialize(&mut de)
        .map_err(|e| (field_path(e.path()), e.into_inner()))
        .and_then(|f| de.end().map(|()| f).map_err(|e| (String::new(), e)));
    result.map_err(|(field, inner)| {
        let text = inner.to_string();
        let what = Parse::read(
            text.rsplit_once(" at line ")
                .map_or(text.as_str(), |(m, _)| m),
        );
        let fix = syntax_fix(&inner, &what);
        let mut field = (!field.is_empty()).then_some(field);
        let comma = decimal_comma_at(source, inner.line(), inner.column(), &what);
        let (what, fix) = if let Some(c) = comma {
            if let Some(key) = c.key {
                field = Some(match field {
                    Some(f) if !f.ends_with(&key) => format!("{f}.{key}"),
                    Some(f) => f,
                    None => key,
                });
            }
            (c.what, c.fix)
        } else if what == Parse::TrailingCharacters && field.is_some() {
            // serde_json's words for an array longer than the [x, y, z] it was read into: a
            // triangle's corners, or three numbers.
            let corners = field
                .as_deref()
                .is_some_and(|f| f == "vertices" || f.ends_with(".vertices"));
            let fix = if corners {
                SyntaxFix::ThreeVertices
            } else {
                SyntaxFix::ThreeNumbers
            };
            (Parse::TooManyElements, fix)
        } else if let Some(word) = non_number_at(source, inner.line(), inner.column()) {
            (
                what,
                SyntaxFix::NotFinite {
                    word: word.to_owned(),
                },
            )
        } else if let Some(fix) = string_for_vector(&what) {
            (what, fix)
        } else if let Some(fix) = fraction_at(source, inner.line(), inner.column()) {
            (what, fix)
        } else if let Some(fix) = word_for_number(&what, field.as_deref()) {
            (what, fix)
        } else {
            (what, fix)
        };
        syntax(path, inner.line(), inner.column(), field, what, fix)
    })
}

/// A document that is not an object: serde would read a top-level array as the fields in order
/// and complain about its first element (`[0]: invalid type: map, expected a string`).
fn not_an_object(path: &Path, text: &str) -> Result<(), ProblemError> {
    match top_level(text) {
        Some((kind, line, column)) => Err(syntax(
            path,
            line,
            column,
            None,
            Parse::NotAnObject { kind },
            SyntaxFix::OneObject,
        )),
        None => Ok(()),
    }
}

/// What a JSON document is when its value is not an object, with the line and column (from 1)
/// where that value starts: a problem file or a course policy must be one object, and serde
/// would read an array as a struct's fields in order (and name the struct in its error).
/// `None` for an object, blanks only, or what is not JSON at all (the parser says what it
/// finds).
pub(crate) fn top_level(text: &str) -> Option<(JsonKind, usize, usize)> {
    let at = text.find(|c| !matches!(c, ' ' | '\t' | '\n' | '\r'))?;
    let rest = &text[at..];
    let kind = match rest.as_bytes()[0] {
        b'[' => JsonKind::Array,
        b'"' => JsonKind::Text,
        b'-' | b'0'..=b'9' => JsonKind::Number,
        _ if rest.starts_with("true") || rest.starts_with("false") => JsonKind::Boolean,
        _ if rest.starts_with("null") => JsonKind::Null,
        _ => return None,
    };
    let before = &text[..at];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    Some((kind, 1 + before.matches('\n').count(), 1 + at - line_start))
}

/// The field where the parser stopped, as `lights[1].falloff`; empty at the top level. (The
/// path's own Display writes "." for the top level and "?" for a position it does not know,
/// and a field may itself be named "a.?".)
pub(crate) fn field_path(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } | Segment::Enum { variant: key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(&crate::text::number::shorten(key, LONGEST_NAME));
            }
            Segment::Unknown => {}
        }
    }
    out
}

/// `NaN`, `Infinity` or `inf` at (or just before) the error's position, as written.
fn non_number_at(source: &str, line: usize, column: usize) -> Option<&str> {
    let text = source.lines().nth(line.checked_sub(1)?)?.as_bytes();
    let at = column.checked_sub(1)?.min(text.len());
    let word = |b: &u8| b.is_ascii_alphanumeric();
    let start = text[..at]
        .iter()
        .rposition(|b| !word(b))
        .map_or(0, |i| i + 1);
    let end = text[at..]
        .iter()
        .position(|b| !word(b))
        .map_or(text.len(), |i| at + i);
    let token = std::str::from_utf8(&text[start..end]).ok()?;
    ["nan", "inf", "infinity"]
        .contains(&token.to_ascii_lowercase().as_str())
        .then_some(token)
}

/// A fraction such as `3/5` at (or just before) the error's position: JSON has none. The fix
/// gives the decimal.
fn fraction_at(source: &str, line: usize, column: usize) -> Option<SyntaxFix> {
    let text = source.lines().nth(line.checked_sub(1)?)?;
    let bytes = text.as_bytes();
    let at = column.checked_sub(1)?.min(bytes.len());
    // The slash is where the parser stopped, or a character or two before (spaces).
    let slash = (at.saturating_sub(2)..(at + 2).min(bytes.len())).find(|&i| bytes[i] == b'/')?;
    let is_num = |b: u8| b.is_ascii_digit() || b == b'.';
    let before = text[..slash].trim_end();
    let start = before
        .bytes()
        .rposition(|b| !is_num(b) && b != b'-')
        .map_or(0, |i| i + 1);
    let a = &before[start..];
    let after = text[slash + 1..].trim_start();
    let end = after
        .bytes()
        .position(|b| !is_num(b))
        .unwrap_or(after.len());
    let b = &after[..end];
    let (x, y) = (a.parse::<f64>().ok()?, b.parse::<f64>().ok()?);
    if y == 0.0 {
        return None;
    }
    Some(SyntaxFix::Fraction {
        a: a.to_owned(),
        b: b.to_owned(),
        decimal: six_decimals(x / y),
    })
}

/// `x` rounded to six decimals, as a fix writes a fraction's decimal (`3/7` → 0.428571).
fn six_decimals(x: f64) -> String {
    validate::show((x * 1e6).round() / 1e6)
}

/// A number written with a decimal comma (`"shininess": 0,5`, `"ambient": [0,5, 0,4, 0,6]`),
/// as a parse error finds it: what was written, and its fix.
struct DecimalComma {
    /// The key of the value, when the comma cut an object's value (`shininess`): the parser
    /// stopped at the object, not at its field.
    key: Option<String>,
    /// What is wrong.
    what: Parse,
    /// What would fix it.
    fix: SyntaxFix,
}

/// A decimal comma where the parser stopped, the likeliest mistake of a file written in
/// Portuguese: JSON reads the comma as a separator. Two forms are recognised on the error's
/// line: an object's value cut in two (`0,5` read as `0` and a key `5`, "key must be a
/// string"), and an array of three numbers read as more ("trailing characters") whose items,
/// split at the commas followed by a space, are three numbers, one or more of them with a
/// decimal comma and the others whole or with a decimal point (`[0,5, 0.7, 0.3]`). Only an array
/// that failed as three numbers is read so: `[1, 0,5]` is JSON's valid `[1, 0, 5]`.
fn decimal_comma_at(
    source: &str,
    line: usize,
    column: usize,
    what: &Parse,
) -> Option<DecimalComma> {
    let text = source.lines().nth(line.checked_sub(1)?)?;
    let bytes = text.as_bytes();
    let at = column.checked_sub(1)?.min(bytes.len());
    let digit = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
    let fix = |fixed: String| SyntaxFix::DecimalPoint { fixed };
    if *what == Parse::KeyMustBeAString {
        // The comma is just before where the parser stopped, between two digits.
        let comma = (at.saturating_sub(2)..(at + 1).min(bytes.len()))
            .find(|&i| bytes[i] == b',' && i > 0 && digit(i - 1) && digit(i + 1))?;
        let is_num = |b: u8| b.is_ascii_digit() || b == b'.' || b == b'-';
        let start = text[..comma]
            .bytes()
            .rposition(|b| !is_num(b))
            .map_or(0, |i| i + 1);
        let end = text[comma + 1..]
            .bytes()
            .position(|b| !b.is_ascii_digit())
            .map_or(text.len(), |i| comma + 1 + i);
        let (a, b) = (&text[start..comma], &text[comma + 1..end]);
        let before = text[..start].trim_end().strip_suffix(':')?.trim_end();
        let key = before
            .strip_suffix('"')
            .and_then(|k| k.rsplit_once('"'))
            .map(|(_, k)| crate::text::number::shorten(k, LONGEST_NAME));
        return Some(DecimalComma {
            key,
            what: Parse::DecimalComma {
                written: format!("{a},{b}"),
            },
            fix: fix(format!("{a}.{b}")),
        });
    }
    if *what != Parse::TrailingCharacters {
        return None;
    }
    let open = text[..at].rfind('[')?;
    let close = open + text[open..].find(']')?;
    let inner = &text[open + 1..close];
    // The items: split at each comma followed by a space (the comma of a list as people
    // write it), not at the commas between digits.
    let mut items = Vec::new();
    let mut from = 0;
    for (i, c) in inner.char_indices() {
        if c == ',' && inner[i + 1..].starts_with(char::is_whitespace) {
            items.push(inner[from..i].trim());
            from = i + 1;
        }
    }
    items.push(inner[from..].trim());
    // A number as written: digits, split at most once by a decimal comma or point.
    let number = |t: &str| {
        let t = t.strip_prefix('-').unwrap_or(t);
        !t.is_empty()
            && t.split([',', '.']).count() <= 2
            && t.split([',', '.'])
                .all(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
    };
    if items.len() != 3 || !items.iter().all(|t| number(t)) || !inner.contains(char::is_numeric) {
        return None;
    }
    if !items.iter().any(|t| t.contains(',')) {
        return None;
    }
    let fixed: Vec<String> = items.iter().map(|t| t.replace(',', ".")).collect();
    Some(DecimalComma {
        key: None,
        what: Parse::DecimalCommas {
            written: format!("[{}]", inner.trim()),
        },
        fix: fix(format!("[{}]", fixed.join(", "))),
    })
}

/// A string where an array of three numbers belongs (`"normal": "3/5 0 4/5"`, `"color":
/// "white"`): the array to write, every number (and fraction) of the string in it when it
/// holds three.
fn string_for_vector(what: &Parse) -> Option<SyntaxFix> {
    let text = what.string_for(|e| *e == Expected::Array { len: 3 })?;
    let numbers: Option<Vec<f64>> = text
        .split(|c: char| c.is_whitespace() || c == ';' || c == ',')
        .filter(|t| !t.is_empty())
        .map(crate::text::number::number)
        .collect();
    Some(match numbers.filter(|n| n.len() == 3) {
        Some(n) => SyntaxFix::AsArray {
            array: format!(
                "[{}, {}, {}]",
                six_decimals(n[0]),
                six_decimals(n[1]),
                six_decimals(n[2])
            ),
        },
        None => SyntaxFix::InBrackets,
    })
}

/// A word (a string) where a number belongs: the number it likely means, in plain words.
fn word_for_number(what: &Parse, field: Option<&str>) -> Option<SyntaxFix> {
    let word = what.string_for(|e| {
        matches!(
            e,
            Expected::F64 | Expected::U8 | Expected::U32 | Expected::ANumber
        )
    })?;
    let is_falloff = field.is_some_and(|f| f.ends_with("falloff"));
    let w = word.trim().to_lowercase();
    let falloff = match w.as_str() {
        "none" | "no" | "nenhum" | "nenhuma" | "sem" | "constant" | "constante" => Some(0),
        "linear" => Some(1),
        "quadratic" | "quadrático" | "quadratico" | "square" | "squared" => Some(2),
        _ => None,
    };
    if let (true, Some(f)) = (is_falloff, falloff) {
        return Some(SyntaxFix::FalloffWord {
            f,
            word: word.to_owned(),
        });
    }
    if let Some(x) = crate::text::number::number(word.trim()) {
        return Some(SyntaxFix::Unquoted {
            number: validate::show(x),
        });
    }
    let word = word.to_owned();
    Some(if is_falloff {
        SyntaxFix::NotFalloffWord { word }
    } else {
        SyntaxFix::NotWord { word }
    })
}

fn syntax_fix(e: &serde_json::Error, what: &Parse) -> SyntaxFix {
    use serde_json::error::Category;
    match e.classify() {
        Category::Eof => SyntaxFix::EndsEarly,
        Category::Syntax if *what == Parse::NumberOutOfRange => SyntaxFix::OutOfRange,
        Category::Syntax => SyntaxFix::CheckJson,
        Category::Io => SyntaxFix::Nothing,
        Category::Data => match what {
            Parse::UnknownField { .. } => SyntaxFix::UnknownField,
            Parse::DuplicateField { .. } => SyntaxFix::DuplicateField,
            Parse::DuplicateMaterial { .. } => SyntaxFix::DuplicateMaterial,
            Parse::UnknownVariant { name, .. } => {
                kind_in_portuguese(&crate::text::In(name, Lang::En).to_string())
                    .unwrap_or(SyntaxFix::SeeSchema)
            }
            Parse::MissingField { name } => {
                let name = crate::text::In(name, Lang::En).to_string();
                match field_purpose(&name) {
                    Some(purpose) => SyntaxFix::AddFor { name, purpose },
                    None => SyntaxFix::Add { name },
                }
            }
            _ => SyntaxFix::SeeSchema,
        },
    }
}

/// A light's or a surface's kind written in Portuguese (`"type": "pontual"`): the file's word
/// for it.
fn kind_in_portuguese(word: &str) -> Option<SyntaxFix> {
    let kind = match word.trim().to_lowercase().as_str() {
        "pontual" | "ponto" => "point",
        "direcional" => "directional",
        "ambiente" => "ambient",
        "holofote" => "spot",
        "plano" => "plane",
        "esfera" => "sphere",
        "triângulo" | "triangulo" => "triangle",
        "malha" => "mesh",
        _ => return None,
    };
    Some(SyntaxFix::KindInEnglish {
        kind: kind.to_owned(),
        word: word.to_owned(),
    })
}

/// What a required field of the format is used for, to say why it is needed. A light's and a
/// surface's fields say it in their tables ([`format::LightSpec`], [`format::SurfaceSpec`]); a
/// name means the same wherever it appears (`direction` of a ray, `color` of a coefficient).
pub(crate) fn field_purpose(name: &str) -> Option<Purpose> {
    if let Some(p) = LightSpec::purpose(name).or_else(|| SurfaceSpec::purpose(name)) {
        return Some(p);
    }
    Some(match name {
        "origin" => Purpose::Origin,
        "k" => Purpose::K,
        "type" => Purpose::Kind {
            lights: syntax::OrList(LightType::WORDS),
            surfaces: syntax::OrList(SurfaceType::WORDS),
        },
        "eye" | "look_at" | "fov" | "width" | "height" => Purpose::Camera,
        _ => return None,
    })
}

/// Where a problem comes from: a file, or text held in memory.
#[derive(Clone, Copy, Debug)]
pub enum Source<'a> {
    /// A file (`-` is standard input); a mesh's OBJ file is read from beside it.
    File(&'a Path),
    /// The text of a problem, named `name` in messages (a request to `phong serve`). It may not
    /// name a mesh: reading one would read the file system for whoever sent the text
    /// (docs/conventions.md, "Checking on the server").
    Text {
        /// The name messages give it, in place of a file's path.
        name: &'a Path,
        /// The JSON text.
        text: &'a str,
    },
}

impl<'a> Source<'a> {
    /// The name messages give the problem: the file's path, or the text's name.
    pub fn name(&self) -> &'a Path {
        match *self {
            Source::File(path) => path,
            Source::Text { name, .. } => name,
        }
    }

    /// Reads and parses the problem (no validation).
    pub fn parse(&self) -> Result<ProblemFile, ProblemError> {
        match *self {
            Source::File(path) => parse_file(path),
            Source::Text { name, text } => {
                parse_str(name, text.strip_prefix('\u{feff}').unwrap_or(text))
            }
        }
    }

    /// Reads the problem's text once (a file's bytes as UTF-8, standard input for `-`),
    /// without a leading byte order mark: for a caller that parses it and also needs the text
    /// itself (the f32 solver reads its numbers again, one by one, to find which one lost its
    /// digits). [`Source::parse_text`] parses it as [`Source::parse`] would.
    pub fn text(&self) -> Result<String, ProblemError> {
        let text = match *self {
            Source::File(path) => read_text(path)?,
            Source::Text { text, .. } => text.to_owned(),
        };
        Ok(match text.strip_prefix('\u{feff}') {
            Some(rest) => rest.to_owned(),
            None => text,
        })
    }

    /// Parses text that [`Source::text`] read (no validation).
    pub fn parse_text(&self, text: &str) -> Result<ProblemFile, ProblemError> {
        parse_str(self.name(), text)
    }

    /// Reads, parses and validates the problem in precision `R`.
    pub fn load<R: Real>(&self) -> Result<(ProblemFile, Problem<R>), ProblemError> {
        // Standard input is read once: its text is kept for an error's numbers as the file
        // writes them ([`Source::validate_text`]); a file is read again for them, only then.
        if matches!(*self, Source::File(p) if p.as_os_str() == "-") {
            let text = self.text()?;
            let file = self.parse_text(&text)?;
            let problem = self.validate_text::<R>(&file, &text)?;
            return Ok((file, problem));
        }
        let file = self.parse()?;
        let problem = self.validate::<R>(&file)?;
        Ok((file, problem))
    }

    /// Validates the parsed problem in precision `R`: a file's meshes are read from beside it;
    /// text that names a mesh is refused. An error about a number the file writes but f64
    /// reads as 0 is said of what the file writes (`problem::written`): the text is the
    /// source's own, or the file read again (only then); standard input, read once, cannot be
    /// read again: use [`Source::validate_text`] with the text read.
    pub fn validate<R: Real>(&self, file: &ProblemFile) -> Result<Problem<R>, ProblemError> {
        self.validated::<R>(file).map_err(|e| {
            let e = match *self {
                Source::Text { text, .. } => written::as_written(e, text),
                Source::File(path) if path.as_os_str() != "-" => match read_text(path) {
                    Ok(text) => written::as_written(e, &text),
                    Err(_) => e,
                },
                Source::File(_) => e,
            };
            e.at(self.name())
        })
    }

    /// [`Source::validate`] of a problem parsed from `text` ([`Source::text`]), which an error
    /// is said of.
    pub fn validate_text<R: Real>(
        &self,
        file: &ProblemFile,
        text: &str,
    ) -> Result<Problem<R>, ProblemError> {
        self.validated::<R>(file)
            .map_err(|e| written::as_written(e, text).at(self.name()))
    }

    /// The problem validated, or validation's error as it is.
    fn validated<R: Real>(&self, file: &ProblemFile) -> Result<Problem<R>, Invalid> {
        match *self {
            Source::File(path) => validate::validate_in::<R>(file, path.parent()),
            Source::Text { .. } => {
                no_mesh(file).and_then(|()| validate::validate_in::<R>(file, None))
            }
        }
    }
}

/// Refuses a problem given as text that names a mesh file.
fn no_mesh(file: &ProblemFile) -> Result<(), Invalid> {
    match file
        .surfaces
        .iter()
        .position(|s| s.kind == SurfaceType::Mesh)
    {
        Some(i) => Err(Invalid::of(
            format!("surfaces[{i}].file"),
            SourceFault::MeshInText,
        )),
        None => Ok(()),
    }
}

/// Reads, parses and validates a problem file in precision `R`.
pub fn load<R: Real>(path: &Path) -> Result<(ProblemFile, Problem<R>), ProblemError> {
    Source::File(path).load::<R>()
}

/// The OBJ files a problem file at `path` names (`surfaces[i].file`), as its validation finds
/// them: inputs of the run besides the file itself, which no output of it may replace.
pub fn mesh_files(file: &ProblemFile, path: &Path) -> Vec<PathBuf> {
    file.surfaces
        .iter()
        .filter(|s| s.kind == SurfaceType::Mesh)
        .filter_map(|s| s.file.as_deref())
        .map(|name| validate::mesh_path(path.parent(), name))
        .collect()
}

/// A scene as the tracer's commands read it.
pub(crate) struct SceneFile<R: Real> {
    /// The validated problem.
    pub problem: Problem<R>,
    /// Its camera.
    pub camera: Camera<R>,
    /// The mesh files it names ([`mesh_files`]): inputs no output may replace.
    pub meshes: Vec<PathBuf>,
}

/// Reads a scene: a problem file with a camera and surfaces (what the tracer needs), and the
/// mesh files it names, for `work`: with [`validate::Work::Image`] held to the image's bounds
/// with the file's own settings; with [`validate::Work::Pixel`] (one pixel explained) the
/// image's own bounds (its primary rays, one sample's tree) are left to the pixel's; with
/// [`validate::Work::Rendered`] to the command, which sets its own over the file's.
pub(crate) fn load_scene_for<R: Real>(
    path: &Path,
    work: validate::Work,
) -> Result<SceneFile<R>, ProblemError> {
    let file = parse_file(path)?;
    let problem = validate::validate_for::<R>(&file, path.parent(), work).map_err(|e| {
        // A number the file writes but f64 reads as 0, said as written: the file is read
        // again, only on this path ([`written::as_written`]).
        match read_text(path) {
            Ok(text) => written::as_written(e, &text),
            Err(_) => e,
        }
        .at(path)
    })?;
    let meshes = mesh_files(&file, path);
    let Some(camera) = problem.camera else {
        return Err(Invalid::of("camera", SourceFault::NoCamera).at(path));
    };
    if problem.surfaces().is_empty() {
        return Err(Invalid::of("surfaces", SourceFault::NoSurfaces).at(path));
    }
    Ok(SceneFile {
        problem,
        camera,
        meshes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fraction_or_a_word_where_a_number_belongs_gets_a_fix_in_both_languages() {
        use crate::text::{Lang, Message};
        let path = Path::new("t.json");
        let e = parse_str(
            path,
            r#"{"point": {"normal": [3/5, 0, 4/5], "material": "M"}}"#,
        )
        .unwrap_err();
        let (en, pt) = (e.text(Lang::En), e.text(Lang::Pt));
        // 3/5 = 0.6.
        assert!(en.contains("write 3/5 as a decimal, 0.6"), "{en}");
        assert!(pt.contains("escreva 3/5 como decimal, 0.6"), "{pt}");
        let e = parse_str(
            path,
            r#"{"lights": [{"type": "point", "position": [0, 0, 1], "color": [1, 1, 1],
                "falloff": "linear"}]}"#,
        )
        .unwrap_err();
        let (en, pt) = (e.text(Lang::En), e.text(Lang::Pt));
        assert!(en.contains("lights[0].falloff"), "{en}");
        assert!(en.contains("write 1 for \"linear\""), "{en}");
        assert!(pt.contains("escreva 1 para \"linear\""), "{pt}");
        let e = parse_str(path, r#"{"viewer": ["1", 0, 0]}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("without quotes: 1"), "{e}");
    }

    #[test]
    fn the_purpose_of_type_names_every_kind_of_each_table() {
        let p = field_purpose("type").unwrap();
        assert_eq!(
            p.text(Lang::En),
            "the kind: ambient, point, directional or spot (lights); plane, sphere, triangle or \
             mesh (surfaces)"
        );
        assert_eq!(
            p.text(Lang::Pt),
            "o tipo: ambient, point, directional ou spot (fontes de luz); plane, sphere, \
             triangle ou mesh (superfícies)"
        );
    }

    #[test]
    fn a_field_of_a_table_gives_its_purpose_and_others_keep_theirs() {
        let en = |name: &str| field_purpose(name).map(|p| p.text(Lang::En));
        assert_eq!(
            en("falloff").as_deref(),
            Some("f in I_l = C_l/d^f (Eq. 4.2, 4.3): 0 none, 1 linear, 2 quadratic")
        );
        assert_eq!(en("radius").as_deref(), Some("the sphere"));
        assert_eq!(en("fov").as_deref(), Some("the camera"));
        assert_eq!(en("name"), None);
        assert_eq!(
            field_purpose("falloff").unwrap().text(Lang::Pt),
            "f em I_l = C_l/d^f (Eq. 4.2, 4.3): 0 sem decaimento, 1 linear, 2 quadrático"
        );
    }

    #[test]
    fn every_field_of_the_tables_gives_its_purpose_in_portuguese() {
        let fields = LightType::ALL
            .iter()
            .flat_map(|k| k.fields())
            .chain(SurfaceType::ALL.iter().flat_map(|k| k.fields()));
        for name in fields {
            let p = field_purpose(name).unwrap();
            let (en, pt) = (p.text(Lang::En), p.text(Lang::Pt));
            assert!(!pt.is_empty() && pt != en, "{name}: {en} / {pt}");
        }
    }
}
