//! The course policy: how a course judges and credits answers, one value that `phong check`,
//! `phong grade`, `phong serve` and `phong moodle` all judge by (docs/conventions.md, "The
//! course policy").
//!
//! An instructor writes it once, as `course-policy.json` beside the exercises; every command
//! that judges finds it there (or takes `--policy FILE`), and its flags (`--tolerance`,
//! `--strict`, `--scale`, `--points`, `--reading-credit`, `--duplicates`) override it. Without
//! a file, the defaults below hold. `phong policy` prints the policy in force.
//!
//! It decides:
//! - the tolerance on each scale (0.005 on the 0–1 scale, 1 on the 255 scale); an exercise
//!   key's own tolerance wins over it, a `--tolerance` flag over both;
//! - whether the likely intended reading is accepted (`strict`), and the share of the points it
//!   earns (`reading_credit`, half);
//! - whether three whole numbers 0–255, one above 1, written without a scale, are read as
//!   8-bit values (`eight_bit`: `read`) or judged on the 0–1 scale with a hint (`hint`);
//! - the words that answer "the ray hits nothing" (`no_hit`);
//! - the points of each exercise (`points`, `default_points`) and which of a student's answers
//!   counts (`duplicates`).
//!
//! A verdict's credit comes from [`Policy::credit`] alone, whichever command shows it.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::answer::{self, Answer, BadAnswer, Scale};
use super::VerdictKind;

pub use crate::problem::POLICY_FILE;

/// The share of an exercise's points that an answer matching its likely intended reading earns
/// by default: half (the arithmetic is right, the reading of the statement is not).
pub const DEFAULT_READING_CREDIT: f64 = 0.5;

/// The most points an exercise may be worth (a policy's `points` and `default_points`,
/// `--points`). A sum phong makes of points (a student's points and maximum, a class's) adds
/// at most one exercise per row of the class (at most 1,000,000 rows, `grade`'s limit) and
/// per exercise a policy (at most 1 MiB) or `--points` names, a few million terms of at most
/// 10^6 each: below 10^13 < 2^44, so finite, and exact at each step for every multiple of 2^-8
/// (whole, half, quarter points), f64 holding every such multiple below 2^44 exactly.
pub const MAX_POINTS: u64 = 1_000_000;

/// How answers written without a scale whose numbers look like 8-bit values are judged.
#[derive(
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    serde::Serialize,
    serde::Deserialize,
    clap::ValueEnum,
)]
#[serde(rename_all = "lowercase")]
pub enum EightBit {
    /// Three whole numbers 0–255, one of them above 1, are read on the 255 scale, and the
    /// feedback says so: the default.
    #[default]
    Read,
    /// They are judged on the 0–1 scale (wrong), with a hint to write them on the 255 scale.
    Hint,
}

/// How a course judges and credits answers (the module's notes).
#[derive(Clone, Debug, PartialEq)]
pub struct Policy {
    /// The tolerance per channel on the 0–1 scale.
    pub tolerance_unit: f64,
    /// The tolerance per channel on the 255 scale.
    pub tolerance_bits8: f64,
    /// `--tolerance`: one tolerance for every answer, over the exercise keys' own.
    pub tolerance_forced: Option<f64>,
    /// Only the problem as written is right: a likely intended reading is refused.
    pub strict: bool,
    /// The share of the points a likely intended reading earns, 0 to 1.
    pub reading_credit: f64,
    /// Whether answers that look like 8-bit values are read as such.
    pub eight_bit: EightBit,
    /// The words (folded: lower case, no accents, single spaces) that answer "no hit".
    pub no_hit: Vec<String>,
    /// Points per exercise, by name without `.json`.
    pub points: BTreeMap<String, f64>,
    /// The points of an exercise `points` does not name.
    pub default_points: f64,
    /// Which answer counts when a student answers an exercise more than once.
    pub duplicates: Duplicates,
    /// The file it was read from; `None` for the defaults.
    pub source: Option<PathBuf>,
}

impl Default for Policy {
    fn default() -> Self {
        Policy {
            tolerance_unit: Scale::Unit.default_tolerance(),
            tolerance_bits8: Scale::Bits8.default_tolerance(),
            tolerance_forced: None,
            strict: false,
            reading_credit: DEFAULT_READING_CREDIT,
            eight_bit: EightBit::Read,
            no_hit: answer::NO_HIT_WORDS
                .iter()
                .map(|w| (*w).to_owned())
                .collect(),
            points: BTreeMap::new(),
            default_points: 1.0,
            duplicates: Duplicates::Last,
            source: None,
        }
    }
}

/// An answer read as the course reads it ([`Policy::read`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Read {
    /// The answer.
    pub answer: Answer,
    /// Its numbers were written without a scale and read as 8-bit values.
    pub as_8bit: bool,
}

/// Three whole numbers 0–255, one of them above 1: 8-bit values rather than a 0–1 colour.
pub(crate) fn looks_8bit(v: &[f64; 3]) -> bool {
    v.iter()
        .all(|x| x.fract() == 0.0 && (0.0..=255.0).contains(x))
        && v.iter().any(|&x| x > 1.0)
}

impl Policy {
    /// Reads an answer: on `scale` when one is given; else on the 0–1 scale, but, when the
    /// policy reads them, three whole numbers 0–255 (one above 1) on the 255 scale.
    pub fn read(&self, text: &str, scale: Option<Scale>) -> Result<Read, BadAnswer> {
        let given = scale.unwrap_or(Scale::Unit);
        let a = answer::parse_with(text, given, &self.no_hit)?;
        // `#RRGGBB` is on the 255 scale as written: only plain numbers are read so.
        if scale.is_none()
            && self.eight_bit == EightBit::Read
            && a.scale == Scale::Unit
            && a.values.is_some_and(|v| looks_8bit(&v))
        {
            if let Ok(b) = answer::parse_with(text, Scale::Bits8, &self.no_hit) {
                return Ok(Read {
                    answer: b,
                    as_8bit: true,
                });
            }
        }
        Ok(Read {
            answer: a,
            as_8bit: false,
        })
    }

    /// The tolerance an answer on `scale` is judged under: `--tolerance`, else the exercise
    /// key's own (`key`, on that scale), else the policy's for the scale.
    pub fn tolerance(&self, scale: Scale, key: Option<f64>) -> f64 {
        self.tolerance_forced.or(key).unwrap_or(match scale {
            Scale::Unit => self.tolerance_unit,
            Scale::Bits8 => self.tolerance_bits8,
        })
    }

    /// The share of an exercise's points a verdict earns: all for `right`, the reading credit
    /// for `reading` (nothing under `strict`), nothing for `wrong`.
    pub fn credit(&self, kind: VerdictKind) -> f64 {
        match kind {
            VerdictKind::Right => 1.0,
            VerdictKind::Reading if !self.strict => self.reading_credit,
            _ => 0.0,
        }
    }

    /// The points of `exercise` (with or without `.json`).
    pub fn points_of(&self, exercise: &str) -> f64 {
        let key = exercise.strip_suffix(".json").unwrap_or(exercise);
        self.points.get(key).copied().unwrap_or(self.default_points)
    }

    /// The policy of the exercises in `folder`: its `course-policy.json` when there is one
    /// ([`Policy::file_in`]), else the defaults.
    pub fn of_folder(folder: &Path) -> Result<Policy, PolicyError> {
        match Policy::file_in(folder) {
            Some(path) => Policy::read_file(&path),
            None => Ok(Policy::default()),
        }
    }

    /// The `course-policy.json` of `folder`, when anything by that name is there: a folder or
    /// a link to nothing by that name is read, and refused as unreadable, rather than taken
    /// for no policy (the course's policy would be ignored without a word).
    pub fn file_in(folder: &Path) -> Option<std::path::PathBuf> {
        let path = folder.join(POLICY_FILE);
        path.symlink_metadata().is_ok().then_some(path)
    }

    /// Reads a policy file (an error says what is wrong in it; the caller names the file).
    pub fn read_file(path: &Path) -> Result<Policy, PolicyError> {
        let bytes = crate::problem::read_limited(path, 1 << 20, crate::problem::Input::Policy)
            .map_err(|error| PolicyError::Unreadable {
                error: crate::text::IoCause::of(&error),
            })?;
        let text = String::from_utf8_lossy(&bytes);
        let mut policy = Policy::read_json(&text)?;
        policy.source = Some(path.to_owned());
        Ok(policy)
    }

    /// Reads a policy file's text (every field optional; a rubric file of earlier versions,
    /// `{"points": …, "default": …, "reading_credit": …}`, is one). An empty text (blanks
    /// only) is the defaults, as `{}` is: `phong policy > course-policy.json` lets the shell
    /// create the file, empty, before phong reads the folder's policy.
    pub fn read_json(text: &str) -> Result<Policy, PolicyError> {
        if text.trim().is_empty() {
            return Ok(Policy::default());
        }
        // Not an object: said so, rather than as serde reads an array into a struct's fields
        // in order ("invalid length 0, expected struct PolicyFile with 9 elements").
        if let Some((kind, _, _)) = crate::problem::top_level(text) {
            return Err(PolicyError::NotAnObject { kind });
        }
        // Read with the field path tracked, so that an error names the field where the parser
        // stopped (`strict: invalid type: …`), as a problem file's does.
        let mut de = serde_json::Deserializer::from_str(text);
        let file: PolicyFile = serde_path_to_error::deserialize(&mut de)
            .map_err(|e| (crate::problem::field_path(e.path()), e.into_inner()))
            .and_then(|f| de.end().map(|()| f).map_err(|e| (String::new(), e)))
            .map_err(|(field, e)| PolicyError::NotAPolicy {
                at: if field.is_empty() {
                    field
                } else {
                    format!("{field}: ")
                },
                error: crate::problem::JsonError::of(&e),
            })?;
        let mut policy = Policy::default();
        for (name, p) in file.points {
            let p = points_of(Some(&name), p)?;
            policy
                .points
                .insert(name.strip_suffix(".json").unwrap_or(&name).to_owned(), p);
        }
        if let Some(d) = file.default_points {
            policy.default_points = points_of(None, d)?;
        }
        if let Some(c) = file.reading_credit {
            policy.reading_credit = credit(c)?;
        }
        if let Some(s) = file.strict {
            policy.strict = s;
        }
        if let Some(t) = file.tolerance {
            for (scale, value, into) in [
                ("1", t.unit, &mut policy.tolerance_unit),
                ("255", t.bits8, &mut policy.tolerance_bits8),
            ] {
                if let Some(v) = value {
                    if !(v.is_finite() && v >= 0.0) {
                        return Err(PolicyError::BadTolerance {
                            scale: scale.to_owned(),
                            tolerance: v.to_string(),
                        });
                    }
                    *into = v;
                }
            }
        }
        if let Some(e) = file.eight_bit {
            policy.eight_bit = e;
        }
        if let Some(words) = file.no_hit {
            let folded: Vec<String> = words
                .iter()
                .map(|w| answer::fold(w))
                .filter(|w| !w.is_empty())
                .collect();
            if folded.is_empty() {
                return Err(PolicyError::NoHitEmpty);
            }
            policy.no_hit = folded;
        }
        if let Some(d) = file.duplicates {
            policy.duplicates = d;
        }
        Ok(policy)
    }

    /// The policy as a policy file writes it (`phong policy`): every field, so an instructor
    /// can start from it.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "tolerance": {"1": self.tolerance_unit, "255": self.tolerance_bits8},
            "strict": self.strict,
            "reading_credit": self.reading_credit,
            "eight_bit": self.eight_bit,
            "no_hit": self.no_hit,
            "points": self.points,
            "default_points": self.default_points,
            "duplicates": self.duplicates,
        })
    }

    /// Adds `--points 4.1=1,4.2=2` (over a rubric file's points). A decimal comma is read as one
    /// (`4.1=0,5,4.2=2` gives 4.1 half a point): the comma separates the items, but a fragment of
    /// digits alone right after a whole number of points, with no space, can only be its
    /// decimals. An error names the item as written, with its decimals.
    pub fn give_points(&mut self, spec: &str) -> Result<(), PolicyError> {
        let fragments: Vec<&str> = spec.split(',').collect();
        let digits = |d: &str| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit());
        let mut i = 0;
        while i < fragments.len() {
            let raw = fragments[i];
            i += 1;
            let item = raw.trim();
            if item.is_empty() {
                continue;
            }
            let Some((name, value)) = item.split_once('=') else {
                let written = match i.checked_sub(2).map(|k| fragments[k].trim()) {
                    Some(previous) if !previous.is_empty() => format!("{previous},{item}"),
                    _ => item.to_owned(),
                };
                return Err(PolicyError::NotExercisePoints { item: written });
            };
            let mut value = value.trim().to_owned();
            let mut written = item.to_owned();
            if let Some(next) = fragments.get(i).filter(|n| digits(n)) {
                if digits(&value) && raw.ends_with(|c: char| c.is_ascii_digit()) {
                    value = format!("{value}.{next}");
                    written = format!("{item},{next}");
                    i += 1;
                }
            }
            let name = name.trim();
            let value: f64 = value
                .parse()
                .map_err(|_| PolicyError::PointsNotANumber { item: written })?;
            let p = points_of(Some(name), value)?;
            self.points
                .insert(name.strip_suffix(".json").unwrap_or(name).to_owned(), p);
        }
        Ok(())
    }
}

/// An optional word of a policy (`"duplicates": "last"`): a string read as the enum reads it,
/// `null` as none, and anything else said with the words it may be, in serde's own terms (so
/// that it is said in Portuguese as serde's other errors are, `problem::syntax`), where
/// serde_json would say only "expected value" of a number. The words are the enum's
/// command-line names, which are its serde names (a test).
fn optional_word<'de, D, T>(d: D) -> Result<Option<T>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::de::DeserializeOwned + clap::ValueEnum,
{
    use serde::de::Error;
    use serde::Deserialize;
    use serde_json::Value;
    let found = match Value::deserialize(d)? {
        Value::Null => return Ok(None),
        Value::String(s) => {
            return T::deserialize(Value::String(s))
                .map(Some)
                .map_err(D::Error::custom)
        }
        Value::Bool(b) => format!("boolean `{b}`"),
        Value::Number(n) if n.is_f64() => format!("floating point `{n}`"),
        Value::Number(n) => format!("integer `{n}`"),
        Value::Array(_) => "sequence".to_owned(),
        Value::Object(_) => "map".to_owned(),
    };
    Err(D::Error::custom(format_args!(
        "invalid type: {found}, expected one of the words {}",
        words::<T>()
    )))
}

/// The words of a policy's enum: `"first", "last", "best"`.
fn words<T: clap::ValueEnum>() -> String {
    T::value_variants()
        .iter()
        .filter_map(|v| v.to_possible_value())
        .map(|p| format!("\"{}\"", p.get_name()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A policy file, every field optional.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct PolicyFile {
    #[serde(default)]
    points: BTreeMap<String, f64>,
    #[serde(alias = "default")]
    default_points: Option<f64>,
    reading_credit: Option<f64>,
    strict: Option<bool>,
    /// An object and nothing else: an array read in order was the tolerances on each scale.
    #[serde(default, deserialize_with = "crate::problem::format::optional_object")]
    tolerance: Option<TolerancesFile>,
    #[serde(default, deserialize_with = "optional_word")]
    eight_bit: Option<EightBit>,
    no_hit: Option<Vec<String>>,
    #[serde(default, deserialize_with = "optional_word")]
    duplicates: Option<Duplicates>,
    /// Free text for the instructor (JSON has no comments); not read.
    #[serde(default, rename = "comment")]
    _comment: serde::de::IgnoredAny,
}

/// `"tolerance": {"1": 0.005, "255": 1}`.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct TolerancesFile {
    #[serde(rename = "1")]
    unit: Option<f64>,
    #[serde(rename = "255")]
    bits8: Option<f64>,
}

impl crate::problem::format::Described for TolerancesFile {
    const WHAT: crate::problem::syntax::Expected = crate::problem::syntax::Expected::Tolerances;
}

crate::messages! {
    /// Why a course policy (a file, or a flag over it) is refused.
    #[allow(missing_docs)]
    pub enum PolicyError {
        /// An exercise's points that are not a number from 0 to `max` ([`MAX_POINTS`];
        /// `points`: as the file writes it).
        BadPoints { exercise: String, points: String, max: u64 } =>
            "points: the points of {exercise} ({points}) must be a number from 0 to {max} (at \
             most {max}, so that every total of a class stays finite and exact)",
            "points: os pontos de {exercise} ({points}) devem ser um número de 0 a {max} (no \
             máximo {max}, para que todo total de uma turma fique finito e exato)";
        /// The points of the exercises the policy does not name, likewise.
        BadDefault { points: String, max: u64 } =>
            "default_points: the points of an exercise the policy does not name ({points}) must \
             be a number from 0 to {max} (at most {max}, so that every total of a class stays \
             finite and exact)",
            "default_points: os pontos de um exercício que a política não nomeia ({points}) \
             devem ser um número de 0 a {max} (no máximo {max}, para que todo total de uma \
             turma fique finito e exato)";
        /// A reading credit outside 0 to 1.
        BadCredit { credit: String } =>
            "reading_credit: the reading credit is {credit}: it is a share of the points, 0 to 1 \
             (0.5 for half)",
            "reading_credit: o crédito da leitura é {credit}: é uma fração dos pontos, de 0 a 1 \
             (0.5 para metade)";
        /// A tolerance that is not a number 0 or more.
        BadTolerance { scale: String, tolerance: String } =>
            "tolerance.{scale}: the tolerance on the {scale} scale is {tolerance}: it must be a \
             number 0 or more (0.005 on the 1 scale, 1 on the 255 scale by default)",
            "tolerance.{scale}: a tolerância na escala {scale} é {tolerance}: deve ser um número \
             0 ou mais (0.005 na escala 1, 1 na escala 255 por padrão)";
        /// `no_hit` without a word.
        NoHitEmpty =>
            "no_hit: the list of words that answer \"no hit\" is empty: give at least one, such \
             as [\"none\", \"nenhuma\"]",
            "no_hit: a lista de palavras que respondem \"nenhuma interseção\" está vazia: dê ao \
             menos uma, como [\"none\", \"nenhuma\"]";
        /// A policy whose JSON is not an object: an array, a number, a string, a boolean,
        /// null.
        NotAnObject { kind: crate::problem::syntax::JsonKind } =>
            "the file is {kind}, and a course policy is one JSON object {{ … }}, such as \
             {{\"tolerance\": {{\"1\": 0.005, \"255\": 1}}, \"reading_credit\": 0.5, \
             \"points\": {{\"4.1\": 1}}}} (every field optional; `phong policy` prints one)",
            "o arquivo é {kind}, e uma política do curso é um objeto JSON {{ … }}, como \
             {{\"tolerance\": {{\"1\": 0.005, \"255\": 1}}, \"reading_credit\": 0.5, \
             \"points\": {{\"4.1\": 1}}}} (todos os campos opcionais; `phong policy` imprime \
             uma)";
        /// A text that is not a policy's JSON (`error`: the JSON parser's words), at the field
        /// where the parser stopped (`at`: `strict: `, `tolerance.1: `, with its colon; empty at
        /// the top level).
        NotAPolicy { at: String, error: crate::problem::JsonError } =>
            "{at}{error} (a course policy is an object such as {{\"tolerance\": {{\"1\": \
             0.005, \"255\": 1}}, \"reading_credit\": 0.5, \"points\": {{\"4.1\": 1}}}}, \
             every field optional; `phong policy` prints one)",
            "{at}{error} (uma política do curso é um objeto como {{\"tolerance\": {{\"1\": \
             0.005, \"255\": 1}}, \"reading_credit\": 0.5, \"points\": {{\"4.1\": 1}}}}, \
             todos os campos opcionais; `phong policy` imprime uma)";
        /// A policy file that cannot be read.
        Unreadable { error: crate::text::IoCause } =>
            "cannot read the course policy: {error}",
            "não é possível ler a política do curso: {error}";
        /// An item of `--points` without `=`.
        NotExercisePoints { item: String } =>
            "\"{item}\" is not EXERCISE=POINTS",
            "\"{item}\" não é EXERCÍCIO=PONTOS";
        /// An item of `--points` whose points are not a number.
        PointsNotANumber { item: String } =>
            "\"{item}\": the points are not a number",
            "\"{item}\": os pontos não são um número";
    }
}

impl std::fmt::Display for PolicyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::text::Message::text(self, crate::text::Lang::En))
    }
}

/// Points must be a number from 0 to [`MAX_POINTS`].
fn points_of(name: Option<&str>, p: f64) -> Result<f64, PolicyError> {
    if (0.0..=MAX_POINTS as f64).contains(&p) {
        Ok(p)
    } else {
        let points = crate::problem::validate::show(p);
        let max = MAX_POINTS;
        Err(match name {
            Some(exercise) => PolicyError::BadPoints {
                exercise: exercise.to_owned(),
                points,
                max,
            },
            None => PolicyError::BadDefault { points, max },
        })
    }
}

/// A share of the points: 0 to 1.
pub fn credit(c: f64) -> Result<f64, PolicyError> {
    if (0.0..=1.0).contains(&c) {
        Ok(c)
    } else {
        Err(PolicyError::BadCredit {
            credit: c.to_string(),
        })
    }
}

/// Which of a student's answers to one exercise counts when there are several (`grade
/// --duplicates`, the policy's `"duplicates"`): `First`, `Last` (the default) or `Best`
/// (the most points).
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    clap::ValueEnum,
    serde::Serialize,
    serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
#[allow(missing_docs)]
pub enum Duplicates {
    First,
    #[default]
    Last,
    Best,
}

impl Duplicates {
    /// The flag's value, as written.
    pub fn word(self) -> &'static str {
        match self {
            Duplicates::First => "first",
            Duplicates::Last => "last",
            Duplicates::Best => "best",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::syntax::JsonKind;
    use crate::text::{Lang, Message};

    /// `optional_word` lists the command-line names as the words a field may be: each one is
    /// the word serde reads and writes for its value.
    #[test]
    fn each_words_command_line_name_is_its_serde_name() {
        fn same<T: clap::ValueEnum + serde::Serialize + serde::de::DeserializeOwned + PartialEq>() {
            for v in T::value_variants() {
                let name = v.to_possible_value().unwrap().get_name().to_owned();
                assert_eq!(serde_json::to_value(v).unwrap(), serde_json::json!(name));
                assert!(serde_json::from_value::<T>(serde_json::json!(name)).unwrap() == *v);
            }
        }
        same::<Duplicates>();
        same::<EightBit>();
    }

    #[test]
    fn points_with_a_decimal_comma() {
        // QA report A, finding 6: 4.1=0,5 is half a point, beside other items.
        let mut p = Policy::default();
        p.give_points("4.1=0,5,4.2=2").unwrap();
        assert_eq!(p.points["4.1"], 0.5);
        assert_eq!(p.points["4.2"], 2.0);
        let mut p = Policy::default();
        p.give_points("4.1=0,5").unwrap();
        assert_eq!(p.points["4.1"], 0.5);
        // A fragment that cannot be decimals is named as written, with what came before it.
        let e = Policy::default().give_points("4.1=0.5,5").unwrap_err();
        assert_eq!(e.to_string(), "\"4.1=0.5,5\" is not EXERCISE=POINTS");
        let e = Policy::default().give_points("4.1=x,5").unwrap_err();
        assert_eq!(e.to_string(), "\"4.1=x\": the points are not a number");
    }

    #[test]
    fn a_rubric_of_earlier_versions_is_a_policy() {
        let mut p = Policy::read_json(
            r#"{"points": {"4.1.json": 2}, "default": 3, "reading_credit": 0.25}"#,
        )
        .unwrap();
        p.give_points("4.2=3, 4.3=0,5").unwrap();
        assert_eq!(p.points_of("4.1"), 2.0);
        assert_eq!(p.points_of("4.2.json"), 3.0);
        assert_eq!(p.points_of("4.3"), 0.5);
        assert_eq!(p.points_of("4.9"), 3.0);
        assert_eq!(p.reading_credit, 0.25);
        assert!(Policy::read_json(r#"{"point": {}}"#).is_err());
        // An empty file is the defaults (the shell's `>` creates it before phong reads it).
        assert_eq!(Policy::read_json(" \n").unwrap(), Policy::default());
        assert!(Policy::read_json(r#"{"reading_credit": 2}"#).is_err());
        assert!(Policy::read_json(r#"{"points": {"4.1": -1}}"#).is_err());
    }

    // The defaults are the chapter's conventions (docs/conventions.md): ±0.005 on the 0–1
    // scale, ±1 on the 255 scale, half credit for the likely intended reading, 8-bit values
    // read, the last answer counting, 1 point each.
    #[test]
    fn the_defaults_and_every_field_of_a_file() {
        let d = Policy::default();
        assert_eq!((d.tolerance_unit, d.tolerance_bits8), (0.005, 1.0));
        assert_eq!(d.reading_credit, 0.5);
        assert!(!d.strict);
        assert_eq!(d.eight_bit, EightBit::Read);
        assert_eq!(d.duplicates, Duplicates::Last);
        assert_eq!(d.points_of("4.1"), 1.0);
        let p = Policy::read_json(
            r#"{"tolerance": {"1": 0.01, "255": 2}, "strict": true, "reading_credit": 0.3,
                "eight_bit": "hint", "no_hit": ["Sem Interseção"], "duplicates": "best",
                "default_points": 2, "comment": {"anything": ["at all"]}}"#,
        )
        .unwrap();
        assert_eq!((p.tolerance_unit, p.tolerance_bits8), (0.01, 2.0));
        assert!(p.strict);
        assert_eq!(p.reading_credit, 0.3);
        assert_eq!(p.eight_bit, EightBit::Hint);
        assert_eq!(p.no_hit, ["sem intersecao"]);
        assert_eq!(p.duplicates, Duplicates::Best);
        assert_eq!(p.points_of("4.1"), 2.0);
        // What phong policy writes reads back as the same policy.
        let again = Policy::read_json(&p.to_json().to_string()).unwrap();
        assert_eq!(again, p);
    }

    // One rule for each surface: the tolerance (flag, then the key's, then the policy's per
    // scale), the credit (1, the reading's share unless strict, 0), the 8-bit reading.
    #[test]
    fn tolerance_credit_and_8bit_reading() {
        let mut p = Policy::default();
        assert_eq!(p.tolerance(Scale::Unit, None), 0.005);
        assert_eq!(p.tolerance(Scale::Bits8, None), 1.0);
        assert_eq!(p.tolerance(Scale::Unit, Some(0.02)), 0.02);
        p.tolerance_forced = Some(0.1);
        assert_eq!(p.tolerance(Scale::Unit, Some(0.02)), 0.1);
        assert_eq!(p.credit(VerdictKind::Right), 1.0);
        assert_eq!(p.credit(VerdictKind::Reading), 0.5);
        assert_eq!(p.credit(VerdictKind::Wrong), 0.0);
        p.strict = true;
        assert_eq!(p.credit(VerdictKind::Reading), 0.0);
        // 128 179 77: three whole numbers, one above 1: 8-bit values unless the policy hints.
        let read = p.read("128 179 77", None).unwrap();
        assert!(read.as_8bit);
        assert_eq!(read.answer.scale, Scale::Bits8);
        assert!(!p.read("128 179 77", Some(Scale::Unit)).unwrap().as_8bit);
        assert!(!p.read("0 1 0", None).unwrap().as_8bit);
        assert!(!p.read("0.5 179 77", None).unwrap().as_8bit);
        // #RRGGBB is on the 255 scale as written, not read so.
        let hex = p.read("#80B34D", None).unwrap();
        assert_eq!((hex.answer.scale, hex.as_8bit), (Scale::Bits8, false));
        p.eight_bit = EightBit::Hint;
        assert_eq!(
            p.read("128 179 77", None).unwrap().answer.scale,
            Scale::Unit
        );
        // The course's own words for "no hit", and only those.
        let q = Policy::read_json(r#"{"no_hit": ["vazio"]}"#).unwrap();
        assert_eq!(q.read("Vazio", None).unwrap().answer.values, None);
        assert!(q.read("nenhuma", None).is_err());
    }

    #[test]
    fn an_exercise_is_worth_at_most_a_million_points() {
        // 1e308 points for each of two exercises made every total inf.
        let mut p = Policy::read_json(r#"{"points": {"4.1": 1000000}, "default_points": 1000000}"#)
            .unwrap();
        p.give_points("4.2=1000000").unwrap();
        assert_eq!(p.points_of("4.2"), 1e6);
        assert_eq!(p.points_of("4.9"), 1e6);
        for file in [
            r#"{"points": {"4.2": 1e308, "4.1": 1e308}}"#,
            r#"{"points": {"4.1": 1000000.5}}"#,
        ] {
            let e = Policy::read_json(file).unwrap_err();
            assert!(matches!(e, PolicyError::BadPoints { .. }), "{e}");
        }
        let e = Policy::read_json(r#"{"default_points": 1e7}"#).unwrap_err();
        assert_eq!(
            e,
            PolicyError::BadDefault {
                points: "10000000".into(),
                max: 1_000_000
            }
        );
        let e = Policy::default()
            .give_points("4.2=1e308,4.1=1e308")
            .unwrap_err();
        assert_eq!(
            e,
            PolicyError::BadPoints {
                exercise: "4.2".into(),
                points: "1e308".into(),
                max: 1_000_000
            }
        );
    }

    #[test]
    fn a_policy_that_is_not_an_object_is_said_so_in_both_languages() {
        for (text, kind) in [
            ("[]", JsonKind::Array),
            ("\n [{\"4.1\": 2}]", JsonKind::Array),
            ("3", JsonKind::Number),
            ("-1", JsonKind::Number),
            ("\"points\"", JsonKind::Text),
            ("null", JsonKind::Null),
            ("false", JsonKind::Boolean),
        ] {
            let e = Policy::read_json(text).unwrap_err();
            assert_eq!(e, PolicyError::NotAnObject { kind }, "{text}");
        }
        let e = Policy::read_json("[]").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("the file is an array [ … ], and a course policy is one JSON object"),
            "{e}"
        );
        assert!(
            e.text(Lang::Pt)
                .starts_with("o arquivo é uma lista [ … ], e uma política do curso é um objeto"),
            "{}",
            e.text(Lang::Pt)
        );
        // Its tolerances are an object too: not read from an array in order, nor named by a
        // type of phong's own.
        for text in [r#"{"tolerance": [0.5, 3]}"#, r#"{"tolerance": 3}"#] {
            let e = Policy::read_json(text).unwrap_err().to_string();
            assert!(
                e.contains("expected the tolerances: an object {\"1\": 0.005, \"255\": 1}")
                    && !e.contains("TolerancesFile"),
                "{e}"
            );
        }
        assert_eq!(
            Policy::read_json(r#"{"tolerance": null}"#).unwrap(),
            Policy::default()
        );
    }

    #[test]
    fn a_policys_errors_read_in_both_languages() {
        let e = Policy::read_json(r#"{"points": {"4.1": -1}}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "points: the points of 4.1 (-1) must be a number from 0 to 1000000 (at most \
             1000000, so that every total of a class stays finite and exact)"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "points: os pontos de 4.1 (-1) devem ser um número de 0 a 1000000 (no máximo \
             1000000, para que todo total de uma turma fique finito e exato)"
        );
        let e = Policy::read_json(r#"{"tolerance": {"255": -1}}"#).unwrap_err();
        assert!(e.to_string().starts_with("tolerance.255: "), "{e}");
        let e = Policy::read_json(r#"{"no_hit": [" "]}"#).unwrap_err();
        assert!(e.text(Lang::Pt).starts_with("no_hit: "), "{e}");
        let e = credit(2.0).unwrap_err();
        assert_eq!(
            e.text(Lang::Pt),
            "reading_credit: o crédito da leitura é 2: é uma fração dos pontos, de 0 a 1 (0.5 \
             para metade)"
        );
    }
}
