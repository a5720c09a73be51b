//! Answers as people write them: three numbers separated by spaces, commas or semicolons,
//! optionally in parentheses or brackets (`0.52 0.03 0`, `(0.52, 0.03, 0)`, `[0.52;0.03;0]`,
//! `0,52 0,03 0` with decimal commas, `3/5` fractions), 8-bit integers with `--scale 255`,
//! `#RRGGBB`, or a word saying that the ray hits nothing (`none`, `nenhuma`, `sem interseção`,
//! `no hit`, `—`: `is_no_hit`). The tolerance an answer is compared under has a default per
//! scale.

use crate::problem::format::{AnswerColor, AnswerSpec};
use crate::problem::validate::show;
use crate::text::number::{not_a_number, NotANumber};
pub use crate::text::number::{number, shorten};
use crate::text::{Echo, In, Lang, Num, Show};

/// The scale an answer is written on: `Unit` (`--scale 1`) or `Bits8` (`--scale 255`), by
/// the factor of [`Scale::factor`].
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, clap::ValueEnum)]
#[allow(missing_docs)]
pub enum Scale {
    #[value(name = "1")]
    #[serde(rename = "1")]
    Unit,
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

/// [`parse`] with a course's own words for "no hit" (folded, `fold`).
pub fn parse_with<S: AsRef<str>>(
    text: &str,
    scale: Scale,
    no_hit: &[S],
) -> Result<Answer, BadAnswer> {
    let t = text.trim();
    if t.is_empty() {
        return Err(bad(AnswerFault::Empty {
            forms: Forms::of(no_hit),
        }));
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
    // A long answer is echoed shortened (a 100 kB cell would otherwise fill the screen).
    let shown = Echo::new(t, 80);
    // "I = (0.5, 0.7, 0.3)", "C: 0.5 0.7 0.3": the name of the quantity before the numbers.
    let unlabelled = strip_label(t);
    if unlabelled != t {
        if is_no_hit_in(unlabelled, no_hit) {
            return Ok(Answer::no_hit(scale));
        }
        if let Some(hex) = unlabelled.strip_prefix('#') {
            return parse_hex(hex).map(|values| Answer {
                values: Some(values),
                scale: Scale::Bits8,
            });
        }
    }
    let inner = strip_brackets(unlabelled);
    // "R = 0.5, G = 0.7, B = 0.3", "r=0,5; g=0,7; b=0,3": each channel named.
    if let Some(channels) = channels(inner) {
        let values = channels_values(channels, &shown, no_hit)?;
        check_scale(values, scale, &shown)?;
        return Ok(Answer {
            values: Some(values),
            scale,
        });
    }
    let tokens = split(inner).ok_or_else(|| {
        bad(AnswerFault::NotThree {
            shown: shown.clone(),
            hint: Hint(not_a_number(inner)),
            read: Read(numbers_read(inner)),
            forms: Forms::of(no_hit),
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
                forms: Forms::of(no_hit),
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

/// Three numbers written as an answer's are (a name before them, brackets, commas, semicolons,
/// decimal commas, fractions), or `None`.
pub(crate) fn three(text: &str) -> Option<[f64; 3]> {
    let tokens = split(strip_brackets(strip_label(text.trim())))?;
    let mut values = [0.0; 3];
    for (v, tok) in values.iter_mut().zip(&tokens) {
        *v = token_number(tok)?;
    }
    Some(values)
}

/// Removes the name of the quantity written before the numbers, and its `=` or `:`
/// ("I = (0.5, 0.7, 0.3)", "I(P) = …", "C_total: …", "cor = …"): a text before a single `=`
/// (or, without one, a single `:`) that holds a letter and no digit outside parentheses and
/// subscripts is such a name. Channel names ("R = 0.5, G = 0.7, B = 0.3") have an `=` each and
/// are left for [`channels`].
fn strip_label(t: &str) -> &str {
    let sep = if t.contains('=') { '=' } else { ':' };
    if t.matches(sep).count() != 1 {
        return t;
    }
    let (name, rest) = t.split_once(sep).expect("one separator");
    let name = name.trim();
    let looks_like_a_name = !name.is_empty()
        && name.chars().count() <= 24
        && name.chars().any(char::is_alphabetic)
        && name
            .chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '(')
        && name
            .chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '_' | '(' | ')' | ' ' | '\'' | '.' | ','));
    if looks_like_a_name && !is_channel(name) {
        rest.trim()
    } else {
        t
    }
}

/// Whether `name` is a channel's name: R, G or B in either case.
fn is_channel(name: &str) -> bool {
    matches!(name, "R" | "G" | "B" | "r" | "g" | "b")
}

/// An answer that names its channels ("R = 0.5, G = 0.7, B = 0.3", "r=0,5; g=0,7; b=0,3",
/// "R: 0.5 G: 0.7 B: 0.3"): each name and the text of its value, in the order written; `None`
/// when the text does not begin with a channel's name and `=` or `:`.
fn channels(t: &str) -> Option<Vec<(char, &str)>> {
    // Where each "X =" begins and where its value begins.
    let mut labels: Vec<(char, usize, usize)> = Vec::new();
    let chars: Vec<(usize, char)> = t.char_indices().collect();
    for (k, &(i, c)) in chars.iter().enumerate() {
        if !"RGBrgb".contains(c) {
            continue;
        }
        if k > 0 && chars[k - 1].1.is_alphanumeric() {
            continue;
        }
        let mut j = k + 1;
        while j < chars.len() && chars[j].1.is_whitespace() {
            j += 1;
        }
        if j < chars.len() && matches!(chars[j].1, '=' | ':') {
            let value = chars.get(j + 1).map_or(t.len(), |&(v, _)| v);
            labels.push((c.to_ascii_uppercase(), i, value));
        }
    }
    let first = labels.first()?;
    if !t[..first.1].trim().is_empty() {
        return None;
    }
    Some(
        labels
            .iter()
            .enumerate()
            .map(|(n, &(c, _, from))| {
                let to = labels.get(n + 1).map_or(t.len(), |l| l.1);
                let value = t[from..to].trim().trim_end_matches([',', ';']).trim();
                (c, value)
            })
            .collect(),
    )
}

/// The colour of an answer that names its channels, or what is wrong with it: a value that is
/// not a number, a channel named twice, a channel missing (saying what was read).
fn channels_values<S: AsRef<str>>(
    channels: Vec<(char, &str)>,
    shown: &Echo,
    no_hit: &[S],
) -> Result<[f64; 3], BadAnswer> {
    let mut read = Channels::default();
    for (c, value) in channels {
        let x = token_number(value).ok_or_else(|| {
            bad(AnswerFault::NotANumber {
                token: Echo::new(value, 40),
                shown: shown.clone(),
                why: Why(not_a_number(&value.replace(',', "."))),
                forms: Forms::of(no_hit),
            })
        })?;
        let k = match c {
            'R' => 0,
            'G' => 1,
            _ => 2,
        };
        if read.given[k] {
            return Err(bad(AnswerFault::ChannelTwice {
                shown: shown.clone(),
                channel: c,
            }));
        }
        read.values[k] = x;
        read.given[k] = true;
    }
    if read.given == [true; 3] {
        Ok(read.values)
    } else {
        Err(bad(AnswerFault::ChannelMissing {
            shown: shown.clone(),
            read,
            forms: Forms::of(no_hit),
        }))
    }
}

/// The numbers that can be read in a text that is not three numbers (separated by spaces,
/// commas or semicolons, a decimal comma read where semicolons separate), to say what was
/// understood.
fn numbers_read(s: &str) -> Vec<Num> {
    let parts: Vec<&str> = if s.contains(';') {
        s.split(';').collect()
    } else {
        s.split(|c: char| c == ',' || c.is_whitespace()).collect()
    };
    parts
        .into_iter()
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .filter_map(token_number)
        .map(Num)
        .collect()
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
        NotThree { shown: Echo, hint: Hint, read: Read, forms: Forms } =>
            "\"{shown}\" is not three numbers{hint}{read}",
            "\"{shown}\" não são três números{hint}{read}";
            fix "{forms}", "{forms}";
        /// Channels named, one of them twice ("R = 0.5, R = 0.7, B = 0.3").
        ChannelTwice { shown: Echo, channel: char } =>
            "\"{shown}\" gives {channel} twice",
            "\"{shown}\" dá {channel} duas vezes";
            fix "give each of R, G and B once, as in \"R = 0.5, G = 0.7, B = 0.3\"",
                "dê R, G e B uma vez cada, como em \"R = 0,5; G = 0,7; B = 0,3\"";
        /// Channels named, one of them missing ("R = 0.5, G = 0.7").
        ChannelMissing { shown: Echo, read: Channels, forms: Forms } =>
            "\"{shown}\" does not give every channel: {read}",
            "\"{shown}\" não dá todos os canais: {read}";
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

/// The word for "the ray hits nothing" said in `lang`: the language's own ("none", "nenhuma")
/// where `words` (the course's no-hit words, [`crate::check::policy::Policy::no_hit`]) take it,
/// else the course's first word; the language's own when `words` is empty.
pub(crate) fn no_hit_word<S: AsRef<str>>(lang: Lang, words: &[S]) -> String {
    let own = match lang {
        Lang::En => "none",
        Lang::Pt => "nenhuma",
    };
    match words.first() {
        Some(first) if !is_no_hit_in(own, words) => first.as_ref().to_owned(),
        _ => own.to_owned(),
    }
}

/// The forms an answer may take, as the fix of an answer that cannot be read says them, with
/// the course's word for "no hit" in each language.
#[derive(Clone, Debug, PartialEq)]
pub struct Forms {
    // Boxed: an answer's error stays small (its `Result` is returned on every answer read).
    none: Box<[String; 2]>,
}

impl Forms {
    /// The forms under the course's no-hit `words`.
    pub(crate) fn of<S: AsRef<str>>(words: &[S]) -> Forms {
        Forms {
            none: Box::new([Lang::En, Lang::Pt].map(|lang| no_hit_word(lang, words))),
        }
    }
}

impl Default for Forms {
    /// The forms under the default words (every message is walked with its fields' defaults,
    /// under test).
    fn default() -> Forms {
        Forms::of(&NO_HIT_WORDS)
    }
}

impl Show for Forms {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match lang {
            Lang::En => write!(
                f,
                "write three numbers such as \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \
                 \"[0.52; 0.03; 0]\", three integers 0–255 with --scale 255, \"#RRGGBB\", or \
                 \"{}\" when the ray hits nothing",
                self.none[0]
            ),
            Lang::Pt => write!(
                f,
                "escreva três números como \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" ou \
                 \"[0.52; 0.03; 0]\", três inteiros 0–255 com --scale 255, \"#RRGGBB\", ou \
                 \"{}\" quando o raio não atinge nada",
                self.none[1]
            ),
        }
    }
}

/// What was read of a text that is not three numbers, after a semicolon (`; read 2 numbers:
/// 0.5, 0.7`), or that no number was.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Read(pub Vec<Num>);

impl Show for Read {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // The first few numbers only: the message stays short whatever was typed (an answer of
        // hundreds of numbers is echoed shortened too).
        const SHOWN: usize = 6;
        let list = |f: &mut std::fmt::Formatter<'_>| -> std::fmt::Result {
            for (i, x) in self.0.iter().take(SHOWN).enumerate() {
                if i > 0 {
                    f.write_str(", ")?;
                }
                x.show(lang, f)?;
            }
            if self.0.len() > SHOWN {
                f.write_str(", …")?;
            }
            Ok(())
        };
        match (self.0.len(), lang) {
            (0, Lang::En) => f.write_str("; no number could be read in it"),
            (0, Lang::Pt) => f.write_str("; nenhum número pôde ser lido nela"),
            (1, Lang::En) => f
                .write_str("; one number was read: ")
                .and_then(|()| list(f)),
            (1, Lang::Pt) => f.write_str("; um número foi lido: ").and_then(|()| list(f)),
            (n, Lang::En) => write!(f, "; {n} numbers were read: ").and_then(|()| list(f)),
            (n, Lang::Pt) => write!(f, "; {n} números foram lidos: ").and_then(|()| list(f)),
        }
    }
}

/// The channels read of an answer that names them, and those it does not give
/// (`read R = 0.5 and G = 0.7, B is missing`): R, G, B, each with whether it was given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Channels {
    /// The values read, in the order R, G, B (0 where not given).
    pub values: [f64; 3],
    /// Whether each was given.
    pub given: [bool; 3],
}

impl Channels {
    /// Channel `k` (0 R, 1 G, 2 B), where given.
    fn get(&self, k: usize) -> Option<Num> {
        self.given[k].then_some(Num(self.values[k]))
    }
}

impl Show for Channels {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let named = [('R', self.get(0)), ('G', self.get(1)), ('B', self.get(2))];
        let given: Vec<String> = named
            .iter()
            .filter_map(|(c, x)| x.map(|x| format!("{c} = {}", In(&x, lang))))
            .collect();
        let missing: Vec<String> = named
            .iter()
            .filter(|(_, x)| x.is_none())
            .map(|(c, _)| c.to_string())
            .collect();
        let and = match lang {
            Lang::En => " and ",
            Lang::Pt => " e ",
        };
        if given.is_empty() {
            return f.write_str(match lang {
                Lang::En => "no channel was read",
                Lang::Pt => "nenhum canal foi lido",
            });
        }
        let (were, are) = (given.len() > 1, missing.len() > 1);
        let given = given.join(and);
        let missing = missing.join(and);
        match lang {
            Lang::En => write!(
                f,
                "{given} {} read, {missing} {} missing",
                if were { "were" } else { "was" },
                if are { "are" } else { "is" }
            ),
            Lang::Pt => write!(
                f,
                "{} {given}, {} {missing}",
                if were { "foram lidos" } else { "foi lido" },
                if are { "faltam" } else { "falta" }
            ),
        }
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
    fn answers_as_students_write_them_are_read() {
        // Issue 29, item 7: the colour named, Portuguese decimal commas between semicolons,
        // each channel named (in any case, with = or :, separated by commas, semicolons or
        // spaces).
        let want = [0.5, 0.7, 0.3];
        for text in [
            "I = (0.5, 0.7, 0.3)",
            "I=(0.5,0.7,0.3)",
            "I(P) = (0.5, 0.7, 0.3)",
            "C: 0.5 0.7 0.3",
            "cor = [0,5; 0,7; 0,3]",
            "(R, G, B) = (0.5, 0.7, 0.3)",
            "(0,5; 0,7; 0,3)",
            "R = 0.5, G = 0.7, B = 0.3",
            "r=0.5, g=0.7, b=0.3",
            "R = 0,5; G = 0,7; B = 0,3",
            "R: 0.5 G: 0.7 B: 0.3",
            "(R = 0.5, G = 0.7, B = 0.3)",
            "B = 0.3, R = 0.5, G = 0.7",
            "R = 1/2, G = 0.7, B = 3/10",
        ] {
            assert_eq!(unit(text), want, "{text}");
        }
        // The same forms on the 255 scale, and "none" or a hex colour named.
        assert_eq!(
            parse("R = 128, G = 179, B = 77", Scale::Bits8)
                .unwrap()
                .values,
            Some([128.0, 179.0, 77.0])
        );
        assert_eq!(parse("I = nenhuma", Scale::Unit).unwrap().values, None);
        let hex = parse("C = #FF8000", Scale::Unit).unwrap();
        assert_eq!(
            (hex.values, hex.scale),
            (Some([255.0, 128.0, 0.0]), Scale::Bits8)
        );
        // A step's vector may be named too.
        assert_eq!(three("L = (0.6, 0, 0.8)"), Some([0.6, 0.0, 0.8]));
    }

    #[test]
    fn what_was_read_is_said_in_a_few_numbers_whatever_was_typed() {
        // The CI fuzz found an answer of hundreds of numbers whose message listed them all (608
        // characters); only the first six are said, and how many there were.
        let many = vec!["255"; 300].join(" ");
        let e = parse(&many, Scale::Unit).unwrap_err().to_string();
        assert!(
            e.contains("; 300 numbers were read: 255, 255, 255, 255, 255, 255, …:"),
            "{e}"
        );
        assert!(e.chars().count() < 600, "{}", e.chars().count());
    }

    #[test]
    fn an_answer_that_cannot_be_read_says_what_was_understood() {
        use crate::text::Message;
        let e = parse("I = (0.5, 0.7)", Scale::Unit).unwrap_err();
        assert!(
            e.text(Lang::En).starts_with(
                "\"I = (0.5, 0.7)\" is not three numbers; 2 numbers were read: 0.5, 0.7: write"
            ),
            "{e}"
        );
        assert!(
            e.text(Lang::Pt).starts_with(
                "\"I = (0.5, 0.7)\" não são três números; 2 números foram lidos: 0.5, 0.7: \
                 escreva"
            ),
            "{}",
            e.text(Lang::Pt)
        );
        let e = parse("0.5 0.7 0.3 0.1", Scale::Unit).unwrap_err();
        assert!(
            e.to_string()
                .contains("; 4 numbers were read: 0.5, 0.7, 0.3, 0.1"),
            "{e}"
        );
        let e = parse("0.5", Scale::Unit).unwrap_err();
        assert!(e.to_string().contains("; one number was read: 0.5"), "{e}");
        let e = parse("vermelho", Scale::Unit).unwrap_err();
        assert!(
            e.text(Lang::Pt)
                .contains("; nenhum número pôde ser lido nela"),
            "{e}"
        );
        // Channels named: the one missing, the one given twice, the value that is not a number.
        let e = parse("R = 0.5, G = 0.7", Scale::Unit).unwrap_err();
        assert!(
            e.text(Lang::En).starts_with(
                "\"R = 0.5, G = 0.7\" does not give every channel: R = 0.5 and G = 0.7 were \
                 read, B is missing: write"
            ),
            "{e}"
        );
        assert!(
            e.text(Lang::Pt).starts_with(
                "\"R = 0.5, G = 0.7\" não dá todos os canais: foram lidos R = 0.5 e G = 0.7, \
                 falta B: escreva"
            ),
            "{}",
            e.text(Lang::Pt)
        );
        let e = parse("R = 0,5", Scale::Unit).unwrap_err();
        assert!(
            e.to_string()
                .contains("R = 0.5 was read, G and B are missing"),
            "{e}"
        );
        let e = parse("R = 0.5, R = 0.7, B = 0.3", Scale::Unit).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("\"R = 0.5, R = 0.7, B = 0.3\" gives R twice: give each"),
            "{e}"
        );
        let e = parse("R = 0.5, G = x, B = 0.3", Scale::Unit).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("\"x\" in \"R = 0.5, G = x, B = 0.3\" is not a number"),
            "{e}"
        );
        // A channel out of the 255 scale is refused as any such answer.
        assert!(parse("R = 128, G = 300, B = 0", Scale::Bits8).is_err());
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
