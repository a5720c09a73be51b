//! `phong grade`'s points: what each exercise is worth (`--points 4.1=1,4.2=2` or a rubric
//! file), the share of them an answer in the likely intended reading earns, and which of a
//! student's answers to one exercise counts when there are several.

use std::collections::BTreeMap;

/// The share of an exercise's points that an answer matching its likely intended reading earns
/// by default: half (the arithmetic is right, the reading of the statement is not).
pub const DEFAULT_READING_CREDIT: f64 = 0.5;

/// What each exercise is worth.
#[derive(Clone, Debug, PartialEq)]
pub struct Rubric {
    /// Points per exercise, by name without `.json`.
    pub points: BTreeMap<String, f64>,
    /// The points of an exercise the rubric does not name (1).
    pub default: f64,
    /// The share of the points a `reading` verdict earns, 0 to 1 ([`DEFAULT_READING_CREDIT`]);
    /// under `--strict` a reading earns nothing.
    pub reading_credit: f64,
}

impl Default for Rubric {
    fn default() -> Self {
        Rubric {
            points: BTreeMap::new(),
            default: 1.0,
            reading_credit: DEFAULT_READING_CREDIT,
        }
    }
}

/// A rubric file: `{"points": {"4.1": 1, "4.2": 2}, "default": 1, "reading_credit": 0.5}`,
/// every field optional.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RubricFile {
    #[serde(default)]
    points: BTreeMap<String, f64>,
    default: Option<f64>,
    reading_credit: Option<f64>,
}

crate::messages! {
    /// Why a rubric (a file, `--points`, `--reading-credit`) is refused; the command adds the fix.
    #[allow(missing_docs)]
    pub enum RubricError {
        /// An exercise's points that are not a number 0 or more (`points`: as Rust writes it).
        BadPoints { exercise: String, points: String } =>
            "the points of {exercise} ({points}) must be a number 0 or more",
            "os pontos de {exercise} ({points}) devem ser um número 0 ou mais";
        /// The points of the exercises the rubric does not name, likewise.
        BadDefault { points: String } =>
            "the points of an exercise the rubric does not name ({points}) must be a number 0 or \
             more",
            "os pontos de um exercício que a rubrica não nomeia ({points}) devem ser um número 0 \
             ou mais";
        /// A reading credit outside 0 to 1.
        BadCredit { credit: String } =>
            "the reading credit is {credit}: it is a share of the points, 0 to 1 (0.5 for half)",
            "o crédito da leitura é {credit}: é uma fração dos pontos, de 0 a 1 (0.5 para metade)";
        /// A rubric file that is not a rubric's JSON (`error`: the JSON parser's words).
        NotARubric { error: crate::problem::JsonError } =>
            "{error} (a rubric is {{\"points\": {{\"4.1\": 1, \"4.2\": 2}}, \"default\": 1, \
             \"reading_credit\": 0.5}}, every field optional)",
            "{error} (uma rubrica é {{\"points\": {{\"4.1\": 1, \"4.2\": 2}}, \"default\": 1, \
             \"reading_credit\": 0.5}}, todos os campos opcionais)";
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

impl std::fmt::Display for RubricError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::text::Message::text(self, crate::text::Lang::En))
    }
}

/// Points must be finite and at least 0.
fn points_of(name: Option<&str>, p: f64) -> Result<f64, RubricError> {
    if p.is_finite() && p >= 0.0 {
        Ok(p)
    } else {
        let points = p.to_string();
        Err(match name {
            Some(exercise) => RubricError::BadPoints {
                exercise: exercise.to_owned(),
                points,
            },
            None => RubricError::BadDefault { points },
        })
    }
}

/// A share of the points: 0 to 1.
pub fn credit(c: f64) -> Result<f64, RubricError> {
    if (0.0..=1.0).contains(&c) {
        Ok(c)
    } else {
        Err(RubricError::BadCredit {
            credit: c.to_string(),
        })
    }
}

/// Transitional, for the command line (cli/commands/grade.rs): [`credit`], its error in
/// English.
pub fn check_credit(c: f64) -> Result<f64, String> {
    credit(c).map_err(|e| e.to_string())
}

impl Rubric {
    /// The points of `exercise` (with or without `.json`).
    pub fn points_of(&self, exercise: &str) -> f64 {
        let key = exercise.strip_suffix(".json").unwrap_or(exercise);
        self.points.get(key).copied().unwrap_or(self.default)
    }

    /// Transitional, for the command line: [`Rubric::read_json`], its error in English.
    pub fn from_json(text: &str) -> Result<Rubric, String> {
        Rubric::read_json(text).map_err(|e| e.to_string())
    }

    /// Reads a rubric file's text.
    pub fn read_json(text: &str) -> Result<Rubric, RubricError> {
        let file: RubricFile = serde_json::from_str(text).map_err(|e| RubricError::NotARubric {
            error: crate::problem::JsonError::of(&e),
        })?;
        let mut rubric = Rubric::default();
        for (name, p) in file.points {
            let p = points_of(Some(&name), p)?;
            rubric
                .points
                .insert(name.strip_suffix(".json").unwrap_or(&name).to_owned(), p);
        }
        if let Some(d) = file.default {
            rubric.default = points_of(None, d)?;
        }
        if let Some(c) = file.reading_credit {
            rubric.reading_credit = credit(c)?;
        }
        Ok(rubric)
    }

    /// Transitional, for the command line: [`Rubric::give_points`], its error in English.
    pub fn add_points(&mut self, spec: &str) -> Result<(), String> {
        self.give_points(spec).map_err(|e| e.to_string())
    }

    /// Adds `--points 4.1=1,4.2=2` (over a rubric file's points). A decimal comma is read as one
    /// (`4.1=0,5,4.2=2` gives 4.1 half a point): the comma separates the items, but a fragment of
    /// digits alone right after a whole number of points, with no space, can only be its
    /// decimals. An error names the item as written, with its decimals.
    pub fn give_points(&mut self, spec: &str) -> Result<(), RubricError> {
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
                return Err(RubricError::NotExercisePoints { item: written });
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
                .map_err(|_| RubricError::PointsNotANumber { item: written })?;
            let p = points_of(Some(name), value)?;
            self.points
                .insert(name.strip_suffix(".json").unwrap_or(name).to_owned(), p);
        }
        Ok(())
    }
}

/// Which of a student's answers to one exercise counts when there are several.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Duplicates {
    /// The first in the file.
    First,
    /// The last in the file (a later answer replaces an earlier one): the default.
    #[default]
    Last,
    /// The one with the most points (the first of those on a tie).
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

    #[test]
    fn points_with_a_decimal_comma() {
        // QA report A, finding 6: 4.1=0,5 is half a point, beside other items.
        let mut r = Rubric::default();
        r.add_points("4.1=0,5,4.2=2").unwrap();
        assert_eq!(r.points["4.1"], 0.5);
        assert_eq!(r.points["4.2"], 2.0);
        let mut r = Rubric::default();
        r.add_points("4.1=0,5").unwrap();
        assert_eq!(r.points["4.1"], 0.5);
        // A fragment that cannot be decimals is named as written, with what came before it.
        let e = Rubric::default().add_points("4.1=0.5,5").unwrap_err();
        assert_eq!(e, "\"4.1=0.5,5\" is not EXERCISE=POINTS");
        let e = Rubric::default().add_points("4.1=x,5").unwrap_err();
        assert_eq!(e, "\"4.1=x\": the points are not a number");
    }

    #[test]
    fn points_from_the_flag_and_the_file() {
        let mut r =
            Rubric::from_json(r#"{"points": {"4.1.json": 2}, "reading_credit": 0.25}"#).unwrap();
        // A decimal comma is read as one (it used to be refused).
        r.add_points("4.2=3, 4.3=0,5").unwrap();
        assert_eq!(r.points_of("4.3"), 0.5);
        r.add_points("4.2=3,4.3=1.5").unwrap();
        assert_eq!(r.points_of("4.1"), 2.0);
        assert_eq!(r.points_of("4.2.json"), 3.0);
        assert_eq!(r.points_of("4.3"), 1.5);
        assert_eq!(r.points_of("4.9"), 1.0);
        assert_eq!(r.reading_credit, 0.25);
        assert!(Rubric::from_json(r#"{"point": {}}"#).is_err());
        assert!(Rubric::from_json(r#"{"reading_credit": 2}"#).is_err());
        assert!(Rubric::from_json(r#"{"points": {"4.1": -1}}"#).is_err());
    }

    #[test]
    fn a_rubrics_errors_read_in_both_languages() {
        use crate::text::{Lang, Message};
        let e = Rubric::read_json(r#"{"points": {"4.1": -1}}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the points of 4.1 (-1) must be a number 0 or more"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "os pontos de 4.1 (-1) devem ser um número 0 ou mais"
        );
        let e = Rubric::read_json(r#"{"default": -2}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the points of an exercise the rubric does not name (-2) must be a number 0 or more"
        );
        let e = credit(2.0).unwrap_err();
        assert_eq!(
            e.text(Lang::Pt),
            "o crédito da leitura é 2: é uma fração dos pontos, de 0 a 1 (0.5 para metade)"
        );
        let e = Rubric::default().give_points("4.1=x").unwrap_err();
        assert_eq!(e.text(Lang::Pt), "\"4.1=x\": os pontos não são um número");
    }
}
