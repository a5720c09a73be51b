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

/// Points must be finite and at least 0.
fn check_points(name: &str, p: f64) -> Result<f64, String> {
    if p.is_finite() && p >= 0.0 {
        Ok(p)
    } else {
        Err(format!(
            "the points of {name} ({p}) must be a number 0 or more"
        ))
    }
}

/// A share of the points: 0 to 1.
pub fn check_credit(c: f64) -> Result<f64, String> {
    if (0.0..=1.0).contains(&c) {
        Ok(c)
    } else {
        Err(format!(
            "the reading credit is {c}: it is a share of the points, 0 to 1 (0.5 for half)"
        ))
    }
}

impl Rubric {
    /// The points of `exercise` (with or without `.json`).
    pub fn points_of(&self, exercise: &str) -> f64 {
        let key = exercise.strip_suffix(".json").unwrap_or(exercise);
        self.points.get(key).copied().unwrap_or(self.default)
    }

    /// Reads a rubric file's text.
    pub fn from_json(text: &str) -> Result<Rubric, String> {
        let file: RubricFile = serde_json::from_str(text).map_err(|e| {
            format!(
                "{e} (a rubric is {{\"points\": {{\"4.1\": 1, \"4.2\": 2}}, \"default\": 1, \
                 \"reading_credit\": 0.5}}, every field optional)"
            )
        })?;
        let mut rubric = Rubric::default();
        for (name, p) in file.points {
            let p = check_points(&name, p)?;
            rubric
                .points
                .insert(name.strip_suffix(".json").unwrap_or(&name).to_owned(), p);
        }
        if let Some(d) = file.default {
            rubric.default = check_points("an exercise the rubric does not name", d)?;
        }
        if let Some(c) = file.reading_credit {
            rubric.reading_credit = check_credit(c)?;
        }
        Ok(rubric)
    }

    /// Adds `--points 4.1=1,4.2=2` (over a rubric file's points). A decimal comma is read as one
    /// (`4.1=0,5,4.2=2` gives 4.1 half a point): the comma separates the items, but a fragment of
    /// digits alone right after a whole number of points, with no space, can only be its
    /// decimals. An error names the item as written, with its decimals.
    pub fn add_points(&mut self, spec: &str) -> Result<(), String> {
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
                return Err(format!("\"{written}\" is not EXERCISE=POINTS"));
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
                .map_err(|_| format!("\"{written}\": the points are not a number"))?;
            let p = check_points(name, value)?;
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
}
