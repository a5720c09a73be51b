//! Answers as people write them: three numbers separated by spaces, commas or semicolons,
//! optionally in parentheses or brackets (`0.52 0.03 0`, `(0.52, 0.03, 0)`, `[0.52;0.03;0]`,
//! `0,52 0,03 0` with decimal commas, `3/5` fractions), 8-bit integers with `--scale 255`,
//! `#RRGGBB`, or a word saying that the ray hits nothing (`none`, `nenhuma`, `sem interseção`,
//! `no hit`, `—`: [`is_no_hit`]). The tolerance an answer is compared under has a default per
//! scale.

use crate::problem::format::{AnswerColor, AnswerSpec};
use crate::problem::validate::show;
use crate::text::number::{not_a_number, NotANumber};
pub use crate::text::number::{number, shorten};
use crate::text::{Echo, Lang, Show};

/// The scale an answer is written on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, clap::ValueEnum)]
pub enum Scale {
    /// Components on [0, 1] (unclamped colours may exceed 1 or be negative).
    #[value(name = "1")]
    #[serde(rename = "1")]
    Unit,
    /// 8-bit integers 0–255 (the clamped colour times 255).
    #[value(name = "255")]
    #[serde(rename = "255")]
    Bits8,
}

impl Scale {
    /// 1 or 255.
    pub fn factor(self) -> f64 {
        match self {
            Scale::Unit => 1.0,
            Scale::Bits8 => 255.0,
        }
    }

    /// The default tolerance on this scale (per channel, inclusive):
    /// - 0.005 on [0, 1]: half a unit of the second decimal place, so an answer correctly
    ///   rounded to two decimals (the precision of a hand calculation with a pocket calculator,
    ///   rounding intermediates to three or four digits) is accepted, while the classic slips,
    ///   which change a channel by several hundredths, are not;
    /// - 1 on the 255 scale: round, floor and ceil of 255·c all lie within 1 of 255·c, and
    ///   255·c itself may sit on a rounding midpoint (0.7·255 = 178.5).
    pub fn default_tolerance(self) -> f64 {
        match self {
            Scale::Unit => crate::solve::CHECK_TOLERANCE,
            Scale::Bits8 => 1.0,
        }
    }
}

/// An answer: three numbers on a scale, or "no hit".
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Answer {
    /// The colour; `None` when the answer is that the ray hits nothing ("none", "nenhuma", …).
    pub values: Option<[f64; 3]>,
    /// The scale the numbers are on (0–1, or 0–255).
    pub scale: Scale,
}

impl Answer {
    /// The answer "the ray hits nothing".
    pub(crate) fn no_hit(scale: Scale) -> Self {
        Answer {
            values: None,
            scale,
        }
    }
}

/// The words (accents, case, spaces, hyphens and underscores aside) that answer "the ray hits
/// nothing", in English and Portuguese.
pub(crate) const NO_HIT_WORDS: [&str; 22] = [
    "none",
    "no hit",
    "nohit",
    "no intersection",
    "nothing",
    "no colour",
    "no color",
    "miss",
    "nenhuma",
    "nenhum",
    "nada",
    "nenhuma intersecao",
    "nenhuma interseccao",
    "sem intersecao",
    "sem interseccao",
    "sem cor",
    "nao ha intersecao",
    "nao ha interseccao",
    "nao intercepta",
    "nao atinge",
    "nao ha",
    "n/a",
];

/// Whether `text` says that the ray hits nothing: one of [`NO_HIT_WORDS`] in any case, with or
/// without accents ("sem interseção", "Sem intersecao", "NENHUMA", "no-hit"), or a dash alone
/// ("—", "–", "-").
pub(crate) fn is_no_hit(text: &str) -> bool {
    is_no_hit_in(text, &NO_HIT_WORDS)
}

/// [`is_no_hit`] with a course's own words (folded, [`fold`]).
pub(crate) fn is_no_hit_in<S: AsRef<str>>(text: &str, words: &[S]) -> bool {
    let t = text
        .trim()
        .trim_matches(|c: char| matches!(c, '"' | '\'' | '(' | ')' | '[' | ']' | '.' | '!'))
        .trim();
    if matches!(t, "—" | "–" | "-" | "--" | "∅") {
        return true;
    }
    let folded = fold(t);
    words.iter().any(|w| w.as_ref() == folded)
}

/// A word as the no-hit words are compared: lower case, without accents, hyphens and
/// underscores as spaces, single spaces.
pub(crate) fn fold(text: &str) -> String {
    let folded: String = text
        .trim()
        .to_lowercase()
        .chars()
        .map(|c| match c {
            'á' | 'à' | 'â' | 'ã' | 'ä' => 'a',
            'é' | 'è' | 'ê' | 'ë' => 'e',
            'í' | 'ì' | 'î' | 'ï' => 'i',
            'ó' | 'ò' | 'ô' | 'õ' | 'ö' => 'o',
            'ú' | 'ù' | 'û' | 'ü' => 'u',
            'ç' => 'c',
            '-' | '_' => ' ',
            c => c,
        })
        .collect();
    folded.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Why an answer cannot be read: what is wrong and the forms an answer may take, and the field
/// of the answer key at fault (`answer.scale`), when it is a key's. Its sentence (a
/// [`Message`](crate::text::Message)) is `FIELD: WHAT: FIX`; its `Display` is the English.
#[derive(Clone, Debug, PartialEq)]
pub struct BadAnswer {
    /// The field of the answer key at fault (`answer`, `answer.scale`); `None` for an answer
    /// given as text.
    pub field: Option<&'static str>,
    /// What is wrong, and what an answer may be.
    pub fault: AnswerFault,
}

impl BadAnswer {
    /// The same fault, in the key's field `field`.
    fn at(self, field: &'static str) -> BadAnswer {
        BadAnswer {
            field: Some(field),
            ..self
        }
    }
}

fn bad(fault: AnswerFault) -> BadAnswer {
    BadAnswer { field: None, fault }
}

impl crate::text::Message for BadAnswer {
    fn text(&self, lang: Lang) -> String {
        use crate::text::Fault;
        let field = self.field.map(|f| format!("{f}: ")).unwrap_or_default();
        let what = self.fault.what(lang);
        match self.fault.fix(lang) {
            fix if fix.is_empty() => format!("{field}{what}"),
            fix => format!("{field}{what}: {fix}"),
        }
    }
}

impl std::fmt::Display for BadAnswer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::text::Message::text(self, Lang::En))
    }
}

impl std::error::Error for BadAnswer {}

/// Reads an answer written on `scale` (a `#RRGGBB` answer is always on the 255 scale).
pub fn parse(text: &str, scale: Scale) -> Result<Answer, BadAnswer> {
    parse_with(text, scale, &NO_HIT_WORDS)
}

/// [`parse`] with a course's own words for "no hit" (folded, [`fold`]).
pub fn parse_with<S: AsRef<str>>(
    text: &str,
    scale: Scale,
    no_hit: &[S],
) -> Result<Answer, BadAnswer> {
    let t = text.trim();
    if t.is_empty() {
        return Err(bad(AnswerFault::Empty { forms: Forms }));
    }
    if is_no_hit_in(t, no_hit) {
        return Ok(Answer::no_hit(scale));
    }
    if let Some(hex) = t.strip_prefix('#') {
        return parse_hex(hex).map(|values| Answer {
            values: Some(values),
            scale: Scale::Bits8,
        });
    }
    let inner = strip_brackets(t);
    // A long answer is echoed shortened (a 100 kB cell would otherwise fill the screen).
    let shown = Echo::new(t, 80);
    let tokens = split(inner).ok_or_else(|| {
        bad(AnswerFault::NotThree {
            shown: shown.clone(),
            hint: Hint(not_a_number(inner)),
            forms: Forms,
        })
    })?;
    let mut values = [0.0; 3];
    for (v, tok) in values.iter_mut().zip(&tokens) {
        *v = token_number(tok).ok_or_else(|| {
            // The hint reads the number as converted; the message echoes it as typed (`0,2x`).
            bad(AnswerFault::NotANumber {
                token: Echo::new(tok, 40),
                shown: shown.clone(),
                why: Why(not_a_number(&tok.replace(',', "."))),
                forms: Forms,
            })
        })?;
    }
    check_scale(values, scale, &shown)?;
    Ok(Answer {
        values: Some(values),
        scale,
    })
}

/// Checks that an answer's numbers fit its scale.
fn check_scale(values: [f64; 3], scale: Scale, shown: &Echo) -> Result<(), BadAnswer> {
    if scale == Scale::Bits8
        && !values
            .iter()
            .all(|&x| x.fract() == 0.0 && (0.0..=255.0).contains(&x))
    {
        return Err(bad(AnswerFault::Not8Bit {
            shown: shown.clone(),
        }));
    }
    Ok(())
}

/// An answer with the tolerance it asks to be judged under (a problem file's key; an answer
/// given with `--answer` asks for none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Key {
    /// The colour (or "none") the key gives, on its scale.
    pub answer: Answer,
    /// The key's own tolerance; `None` for the default (`--tolerance`, or the scale's).
    pub tolerance: Option<f64>,
}

impl Key {
    /// The key's own tolerance on `scale` (the key's scale converted: 2 on the 255 scale is
    /// 2/255 on the 0–1 scale); `None` when the key gives none.
    pub(crate) fn tolerance_on(&self, scale: Scale) -> Option<f64> {
        self.tolerance
            .map(|t| t * scale.factor() / self.answer.scale.factor())
    }
}

/// An answer key from a problem file.
pub fn from_key(key: &AnswerSpec) -> Result<Key, BadAnswer> {
    let (color, scale, tolerance) = key.parts();
    let scale = match scale {
        None => None,
        Some(1.0) => Some(Scale::Unit),
        Some(255.0) => Some(Scale::Bits8),
        Some(s) => return Err(bad(AnswerFault::NotAScale { scale: show(s) }).at("answer.scale")),
    };
    let answer = match color {
        AnswerColor::Hex(h) if is_no_hit(h) => Answer::no_hit(scale.unwrap_or(Scale::Unit)),
        AnswerColor::Hex(h) => {
            let hex = h
                .strip_prefix('#')
                .ok_or_else(|| bad(AnswerFault::KeyNotAColour { text: h.clone() }).at("answer"))?;
            if scale == Some(Scale::Unit) {
                return Err(bad(AnswerFault::HexOnUnitScale).at("answer.scale"));
            }
            Answer {
                values: Some(parse_hex(hex).map_err(|e| e.at("answer"))?),
                scale: Scale::Bits8,
            }
        }
        AnswerColor::Rgb(c) => {
            let scale = scale.unwrap_or(Scale::Unit);
            check_scale(*c, scale, &Echo::new(&format!("{c:?}"), usize::MAX))
                .map_err(|e| e.at("answer"))?;
            Answer {
                values: Some(*c),
                scale,
            }
        }
    };
    if let Some(t) = tolerance {
        check_tolerance(t).map_err(|e| e.at("answer.tolerance"))?;
    }
    Ok(Key { answer, tolerance })
}

/// A tolerance must be a finite number ≥ 0.
pub fn check_tolerance(t: f64) -> Result<(), BadAnswer> {
    if t.is_finite() && t >= 0.0 {
        Ok(())
    } else {
        Err(bad(AnswerFault::NotATolerance { tolerance: show(t) }))
    }
}

fn parse_hex(hex: &str) -> Result<[f64; 3], BadAnswer> {
    if hex.len() != 6 || !hex.chars().all(|c| c.is_ascii_hexdigit()) {
        return Err(bad(AnswerFault::NotHex {
            hex: Echo::new(hex, 40),
        }));
    }
    let byte = |i: usize| f64::from(u8::from_str_radix(&hex[i..i + 2], 16).expect("hex digits"));
    Ok([byte(0), byte(2), byte(4)])
}

/// Three numbers written as an answer's are (brackets, commas, semicolons, decimal commas,
/// fractions), or `None`.
pub(crate) fn three(text: &str) -> Option<[f64; 3]> {
    let tokens = split(strip_brackets(text.trim()))?;
    let mut values = [0.0; 3];
    for (v, tok) in values.iter_mut().zip(&tokens) {
        *v = token_number(tok)?;
    }
    Some(values)
}

/// Removes one pair of surrounding brackets: (), [], {}, or a leading "rgb(".
fn strip_brackets(t: &str) -> &str {
    let t = t.strip_prefix("rgb").map_or(t, str::trim_start);
    for (open, close) in [('(', ')'), ('[', ']'), ('{', '}')] {
        if let Some(inner) = t.strip_prefix(open).and_then(|s| s.strip_suffix(close)) {
            return inner.trim();
        }
    }
    t
}

/// Splits into exactly three number tokens, as typed (a decimal comma kept, so that a message
/// echoes `0,2x`; [`token_number`] reads it). Semicolons, when present, are the only separators
/// (and a comma is then a decimal comma). Otherwise spaces and commas separate; if that does not
/// give three tokens, spaces alone with decimal commas ("0,52 0,03 0").
fn split(s: &str) -> Option<Vec<String>> {
    let three = |v: Vec<String>| (v.len() == 3).then_some(v);
    if s.contains(';') {
        return three(s.split(';').map(|x| x.trim().to_owned()).collect());
    }
    let by_both: Vec<String> = s
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|x| !x.is_empty())
        .map(str::to_owned)
        .collect();
    if by_both.len() == 3 {
        return Some(by_both);
    }
    three(
        s.split_whitespace()
            .map(|x| x.trim_end_matches(',').to_owned())
            .collect(),
    )
}

/// A token of an answer as [`split`] gives it: its decimal comma read as a point (`0,52` is
/// 0.52), then a number as [`number`] reads it.
fn token_number(tok: &str) -> Option<f64> {
    number(&tok.replace(',', "."))
}

crate::faults! {
    /// What is wrong with an answer (given as text, or a problem file's key), and what an
    /// answer may be. (Each field is named where the texts write it.)
    #[allow(missing_docs)]
    pub enum AnswerFault {
        /// Nothing written.
        Empty { forms: Forms } =>
            "the answer is empty",
            "a resposta está vazia";
            fix "{forms}", "{forms}";
        /// Not three numbers (with the common cause, where there is one).
        NotThree { shown: Echo, hint: Hint, forms: Forms } =>
            "\"{shown}\" is not three numbers{hint}",
            "\"{shown}\" não são três números{hint}";
            fix "{forms}", "{forms}";
        /// Three parts, one of which is not a number.
        NotANumber { token: Echo, shown: Echo, why: Why, forms: Forms } =>
            "\"{token}\" in \"{shown}\" {why}",
            "\"{token}\" em \"{shown}\" {why}";
            fix "{forms}", "{forms}";
        /// Numbers that are not 8-bit values under `--scale 255` (or a key's scale 255).
        Not8Bit { shown: Echo } =>
            "\"{shown}\" is not three integers 0–255, as --scale 255 expects",
            "\"{shown}\" não são três inteiros 0–255, como --scale 255 espera";
            fix "give 8-bit values, or leave out --scale for components on [0, 1]",
                "dê valores de 8 bits, ou tire --scale para componentes em [0, 1]";
        /// A key's scale other than 1 or 255.
        NotAScale { scale: String } =>
            "{scale} is not a scale",
            "{scale} não é uma escala";
            fix "use 1 (components on [0, 1]) or 255 (8-bit)",
                "use 1 (componentes em [0, 1]) ou 255 (8 bits)";
        /// A key's text that is neither `#RRGGBB` nor "none".
        KeyNotAColour { text: String } =>
            "\"{text}\" is not a colour",
            "\"{text}\" não é uma cor";
            fix "write \"#RRGGBB\" or [r, g, b], or \"none\" when the ray hits nothing",
                "escreva \"#RRGGBB\" ou [r, g, b], ou \"nenhuma\" quando o raio não atinge nada";
        /// A key's `#RRGGBB` with the scale 1.
        HexOnUnitScale =>
            "a \"#RRGGBB\" colour has 8 bits per channel",
            "uma cor \"#RRGGBB\" tem 8 bits por canal";
            fix "remove \"scale\" or set it to 255", "remova \"scale\" ou ponha 255";
        /// `#` followed by something other than six hexadecimal digits.
        NotHex { hex: Echo } =>
            "\"#{hex}\" is not a colour \"#RRGGBB\"",
            "\"#{hex}\" não é uma cor \"#RRGGBB\"";
            fix "six hexadecimal digits after #", "seis dígitos hexadecimais depois de #";
        /// A tolerance that is negative or not finite.
        NotATolerance { tolerance: String } =>
            "{tolerance} is not a tolerance",
            "{tolerance} não é uma tolerância";
            fix "give the largest difference accepted per channel, a number ≥ 0 (e.g. 0.005 on \
                 the 0–1 scale, 1 on the 255 scale)",
                "dê a maior diferença aceita por canal, um número ≥ 0 (por exemplo 0.005 na \
                 escala 0–1, 1 na escala 255)";
    }
}

/// The forms an answer may take, as the fix of an answer that cannot be read says them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Forms;

impl Show for Forms {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match lang {
            Lang::En => {
                "write three numbers such as \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \
                 \"[0.52; 0.03; 0]\", three integers 0–255 with --scale 255, \"#RRGGBB\", or \
                 \"none\" when the ray hits nothing"
            }
            Lang::Pt => {
                "escreva três números como \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" ou \
                 \"[0.52; 0.03; 0]\", três inteiros 0–255 com --scale 255, \"#RRGGBB\", ou \
                 \"nenhuma\" quando o raio não atinge nada"
            }
        })
    }
}

/// The common cause of a text that is not three numbers, in parentheses (` (it has a Unicode
/// minus …)`), or nothing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Hint(pub Option<NotANumber>);

impl Show for Hint {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::text::Message;
        match (&self.0, lang) {
            (None, _) => Ok(()),
            (Some(h), Lang::En) => write!(f, " (it {})", h.text(lang)),
            (Some(h), Lang::Pt) => write!(f, " ({})", h.text(lang)),
        }
    }
}

/// Why a part of an answer is not a number: its common cause, or that it is not one.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Why(pub Option<NotANumber>);

impl Show for Why {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::text::Message;
        match (&self.0, lang) {
            (Some(h), _) => f.write_str(&h.text(lang)),
            (None, Lang::En) => f.write_str("is not a number"),
            (None, Lang::Pt) => f.write_str("não é um número"),
        }
    }
}

/// Transitional: [`crate::text::number::not_a_number`] in English, for the messages not yet
/// written as typed values.
pub fn not_a_number_hint(text: &str) -> Option<String> {
    use crate::text::Message;
    crate::text::number::not_a_number(text).map(|m| m.text(crate::text::Lang::En))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(text: &str) -> [f64; 3] {
        parse(text, Scale::Unit).expect(text).values.expect(text)
    }

    #[test]
    fn the_forms_people_write_all_read_the_same_numbers() {
        let want = [0.52, 0.03, 0.0];
        for text in [
            "0.52 0.03 0",
            "0.52, 0.03, 0",
            "0.52,0.03,0",
            "(0.52, 0.03, 0)",
            "[0.52 0.03 0]",
            "{0.52; 0.03; 0}",
            "  ( 0.52 ,  0.03 , 0 )  ",
            "0,52 0,03 0",
            "0,52; 0,03; 0",
            "rgb(0.52, 0.03, 0)",
            "52e-2 3E-2 -0",
        ] {
            assert_eq!(unit(text), want, "{text}");
        }
        assert_eq!(unit("3/5 0 4/5"), [0.6, 0.0, 0.8]);
        assert_eq!(unit("-0.299 -0.36 -0.25"), [-0.299, -0.36, -0.25]);
    }

    #[test]
    fn a_number_that_is_not_one_is_echoed_as_typed() {
        // QA finding 13: the student wrote `0,2x`; the message names `0,2x`, not the `0.2x` the
        // decimal comma was converted to, in each way of separating the numbers.
        for (text, token) in [
            ("0,2x 0 0", "0,2x"),
            ("0,2x; 0; 0", "0,2x"),
            ("0 1,5e400 0", "1,5e400"),
        ] {
            let e = parse(text, Scale::Unit).unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("\"{token}\" in \"{text}\" ")),
                "{text}: {e}"
            );
        }
        // The hint still reads the converted number: 1,5e400 is out of range.
        let e = parse("0 1,5e400 0", Scale::Unit).unwrap_err().to_string();
        assert!(e.contains("is out of range"), "{e}");
        // And the numbers read are those of the decimal commas.
        assert_eq!(
            parse("0,52 0,03 0", Scale::Unit).unwrap().values,
            Some([0.52, 0.03, 0.0])
        );
    }

    #[test]
    fn a_bad_answer_reads_whole_in_either_language() {
        use crate::text::Message;
        let e = parse("0,5 abc 1", Scale::Unit).unwrap_err();
        assert_eq!(
            e.text(Lang::En),
            "\"abc\" in \"0,5 abc 1\" is not a number: write three numbers such as \"0.52 0.03 0\", \
             \"(0.52, 0.03, 0)\" or \"[0.52; 0.03; 0]\", three integers 0–255 with --scale 255, \
             \"#RRGGBB\", or \"none\" when the ray hits nothing"
        );
        assert_eq!(e.to_string(), e.text(Lang::En));
        assert_eq!(
            e.text(Lang::Pt),
            "\"abc\" em \"0,5 abc 1\" não é um número: escreva três números como \"0.52 0.03 0\", \
             \"(0.52, 0.03, 0)\" ou \"[0.52; 0.03; 0]\", três inteiros 0–255 com --scale 255, \
             \"#RRGGBB\", ou \"nenhuma\" quando o raio não atinge nada"
        );
        // A key's error names its field, in either language.
        let key: AnswerSpec =
            serde_json::from_str(r##"{"color": "#FF8000", "scale": 1}"##).unwrap();
        let e = from_key(&key).unwrap_err();
        assert_eq!(
            e.to_string(),
            "answer.scale: a \"#RRGGBB\" colour has 8 bits per channel: remove \"scale\" or set \
             it to 255"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "answer.scale: uma cor \"#RRGGBB\" tem 8 bits por canal: remova \"scale\" ou ponha 255"
        );
        // A long answer is echoed shortened, its length said in the sentence's language.
        let long = "0.5 ".repeat(30);
        let e = parse(&long, Scale::Unit).unwrap_err().text(Lang::Pt);
        assert!(
            e.contains("… (119 caracteres)\" não são três números"),
            "{e}"
        );
    }

    #[test]
    fn eight_bit_answers_need_integers_from_0_to_255() {
        let a = parse("134 7 0", Scale::Bits8).unwrap();
        assert_eq!(a.values, Some([134.0, 7.0, 0.0]));
        assert!(parse("134 7 256", Scale::Bits8).is_err());
        assert!(parse("0.5 7 0", Scale::Bits8).is_err());
        assert!(parse("-1 7 0", Scale::Bits8).is_err());
    }

    #[test]
    fn a_hex_colour_is_read_on_the_255_scale_whatever_the_flag() {
        let a = parse("#86070a", Scale::Unit).unwrap();
        assert_eq!(a.scale, Scale::Bits8);
        assert_eq!(a.values, Some([134.0, 7.0, 10.0]));
        assert!(parse("#86070", Scale::Unit).is_err());
        assert!(parse("#86070g", Scale::Unit).is_err());
    }

    #[test]
    fn what_is_not_three_finite_numbers_is_refused_with_the_forms_expected() {
        for text in [
            "",
            "0.5 0.5",
            "0.5 0.5 0.5 0.5",
            "a b c",
            "inf 0 0",
            "nan 0 0",
            "1/0 0 0",
            "0x1 0 0",
            "0,5,0,3,0",
        ] {
            let e = parse(text, Scale::Unit).unwrap_err().to_string();
            assert!(
                e.contains("three numbers") || e.contains("not a number") || e.contains("empty"),
                "{text}: {e}"
            );
        }
    }

    #[test]
    fn an_answer_key_reads_its_own_scale_and_tolerance() {
        let key: AnswerSpec =
            serde_json::from_str(r#"{"color": [134, 7, 0], "scale": 255, "tolerance": 2}"#)
                .unwrap();
        let Key {
            answer: a,
            tolerance: t,
        } = from_key(&key).unwrap();
        assert_eq!(
            (a.values, a.scale, t),
            (Some([134.0, 7.0, 0.0]), Scale::Bits8, Some(2.0))
        );
        let key: AnswerSpec = serde_json::from_str(r##""#FF8000""##).unwrap();
        assert_eq!(
            from_key(&key).unwrap().answer.values,
            Some([255.0, 128.0, 0.0])
        );
        let key: AnswerSpec = serde_json::from_str("[0.5, 0.7, 0.3]").unwrap();
        assert_eq!(from_key(&key).unwrap().answer.scale, Scale::Unit);
        let key: AnswerSpec =
            serde_json::from_str(r#"{"color": [1, 2, 3], "scale": 100}"#).unwrap();
        assert!(from_key(&key)
            .unwrap_err()
            .to_string()
            .starts_with("answer.scale: "));
        let key: AnswerSpec =
            serde_json::from_str(r#"{"color": [1, 2, 3], "tolerance": -1}"#).unwrap();
        assert!(from_key(&key)
            .unwrap_err()
            .to_string()
            .starts_with("answer.tolerance: -1 is not a tolerance: give "));
    }

    #[test]
    fn no_hit_is_read_in_either_language_with_or_without_accents() {
        for text in [
            "none",
            "None",
            "NONE",
            "no hit",
            "no-hit",
            "nenhuma",
            "Nenhuma.",
            "nenhum",
            "sem interseção",
            "Sem Intersecao",
            "sem intersecção",
            "não há interseção",
            "—",
            "–",
            "-",
            "\"none\"",
        ] {
            assert_eq!(parse(text, Scale::Unit).expect(text).values, None, "{text}");
        }
        for text in ["non", "nenhumas", "0 0 0", "sem", "hit"] {
            assert!(!is_no_hit(text), "{text}");
        }
        let key: AnswerSpec = serde_json::from_str(r#""none""#).unwrap();
        assert_eq!(from_key(&key).unwrap().answer.values, None);
        let key: AnswerSpec =
            serde_json::from_str(r#"{"color": "nenhuma", "tolerance": 0.01}"#).unwrap();
        assert_eq!(from_key(&key).unwrap().answer.values, None);
    }

    #[test]
    fn a_keys_tolerance_is_converted_to_the_answers_scale() {
        let key: AnswerSpec =
            serde_json::from_str(r#"{"color": [134, 7, 0], "scale": 255, "tolerance": 2}"#)
                .unwrap();
        let k = from_key(&key).unwrap();
        assert_eq!(k.tolerance_on(Scale::Bits8), Some(2.0));
        assert_eq!(k.tolerance_on(Scale::Unit), Some(2.0 / 255.0));
        let key: AnswerSpec = serde_json::from_str("[0.5, 0.7, 0.3]").unwrap();
        assert_eq!(from_key(&key).unwrap().tolerance_on(Scale::Unit), None);
    }
}
