//! What clap reads a flag's value as: a number or fraction ≥ 0 (`1/255`), an image size
//! (`320x240`), a pixel (`X,Y`), and the hand-written [`ValueEnum`] of [`Precision`] (which lives
//! in the core, outside clap). A value refused is a [`BadValue`], said in the user's language
//! where clap's error is printed ([`super::usage`]).

use std::fmt;

use clap::ValueEnum;

use crate::core::Precision;
use crate::text::number::NotANumber;
use crate::text::{Echo, In, Lang, Message, Show};

/// How long a value is echoed back in its error.
const ECHOED: usize = 40;

/// `s` with its decimal comma as a point, when `s` is one number written with one (`0,5`,
/// `-1,25`: digits, a comma, digits), as a spreadsheet in Portuguese writes it; else `s`. Only
/// a flag that takes one number reads it so: in a list (`--min-weights 0,1/255`) the comma
/// separates the items.
fn with_decimal_point(s: &str) -> std::borrow::Cow<'_, str> {
    let t = s.trim();
    let digits = |d: &str| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit());
    match t.strip_prefix('-').unwrap_or(t).split_once(',') {
        Some((a, b)) if digits(a) && digits(b) => t.replacen(',', ".", 1).into(),
        _ => s.into(),
    }
}

/// Why a text that looks like a number is not one ([`crate::text::number::not_a_number`]).
fn hint(s: &str) -> Option<Hint> {
    crate::text::number::not_a_number(s.trim()).map(Hint)
}

/// A number ≥ 0 written as a decimal (with a point, or a decimal comma: `0,05`) or a fraction
/// (1/255).
pub(super) fn parse_fraction(s: &str) -> Result<f64, BadValue> {
    let text = Echo::new(s, ECHOED);
    if let Some(hint) = hint(s) {
        return Err(BadValue::FractionHint { text, hint });
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if x >= 0.0 => Ok(x),
        _ => Err(BadValue::NotAFraction { text: Quoted(text) }),
    }
}

/// A share of the points (`--reading-credit`): a number from 0 to 1, written as a decimal
/// (`0.5`, or with a decimal comma `0,5`) or a fraction (`1/2`); the error says what a share is
/// (the fix of [`parse_fraction`] is a minimum weight's).
pub(super) fn parse_share(s: &str) -> Result<f64, BadValue> {
    let text = Echo::new(s, ECHOED);
    if let Some(hint) = hint(s) {
        return Err(BadValue::ShareHint { text, hint });
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if (0.0..=1.0).contains(&x) => Ok(x),
        _ => Err(BadValue::NotAShare { text }),
    }
}

/// A tolerance: a number ≥ 0 (a decimal, with a point or a decimal comma `0,01`, or a fraction
/// 1/255), finite; a number beyond the range of f64 (`1e400`) is said to be out of range, not
/// infinite.
pub(super) fn parse_tolerance(s: &str) -> Result<f64, BadValue> {
    let text = Echo::new(s, ECHOED);
    if let Some(hint) = hint(s) {
        return Err(BadValue::ToleranceHint { text, hint });
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if x >= 0.0 => Ok(x),
        _ => Err(BadValue::NotATolerance { text }),
    }
}

/// `--delimiter`: `,`, `;`, or a tab (`tab`, `\t` or the character itself).
pub(super) fn parse_delimiter(s: &str) -> Result<u8, BadValue> {
    match s {
        "," => Ok(b','),
        ";" => Ok(b';'),
        "tab" | "\\t" | "\t" => Ok(b'\t'),
        _ => Err(BadValue::NotASeparator { text: s.to_owned() }),
    }
}

/// A whole number from `lo` to `hi`, or the error that says so with the range and the fix
/// (`4294967296 is outside 1 to 4096`: the text as typed, not clap's type's range).
fn whole(s: &str, lo: u64, hi: u64, what: Whole) -> Result<u64, BadValue> {
    let t = s.trim();
    if t.is_empty() || !t.bytes().all(|b| b.is_ascii_digit()) {
        let text = Echo::new(s, ECHOED);
        return Err(match hint(t) {
            Some(hint) => BadValue::WholeHint {
                text,
                hint,
                what,
                lo,
                hi,
            },
            None => BadValue::NotWhole { text, what, lo, hi },
        });
    }
    match t.parse::<u64>() {
        Ok(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => Err(BadValue::Outside {
            text: Echo::new(t, ECHOED),
            what,
            lo,
            hi,
        }),
    }
}

/// A maximum level: 1 to [`crate::problem::model::MAX_LEVEL`].
pub(super) fn parse_level(s: &str) -> Result<u32, BadValue> {
    let max = crate::problem::model::MAX_LEVEL;
    whole(s, 1, max.into(), Whole::Level).map(|n| n as u32)
}

/// Samples per pixel: 1 to [`crate::problem::model::MAX_SAMPLES`].
pub(super) fn parse_samples(s: &str) -> Result<u32, BadValue> {
    let max = crate::problem::model::MAX_SAMPLES;
    whole(s, 1, max.into(), Whole::Samples).map(|n| n as u32)
}

/// Renders per setting: 1 to [`crate::tradeoff::MAX_RUNS`].
pub(super) fn parse_runs(s: &str) -> Result<u32, BadValue> {
    let max = crate::tradeoff::MAX_RUNS;
    whole(s, 1, max.into(), Whole::Runs).map(|n| n as u32)
}

/// The most worker threads: 1024, more than any machine the course runs on has cores (each
/// thread reserves its stack).
pub(crate) const MAX_THREADS: u64 = 1024;

/// Worker threads: 1 to [`MAX_THREADS`].
pub(super) fn parse_threads(s: &str) -> Result<usize, BadValue> {
    whole(s, 1, MAX_THREADS, Whole::Threads).map(|n| n as usize)
}

/// WxH, each 1 to the largest image side.
pub(super) fn parse_size(s: &str) -> Result<(u32, u32), BadValue> {
    let max = crate::problem::model::MAX_IMAGE_SIDE;
    let parsed = s
        .split_once(['x', '×'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)));
    match parsed {
        Some((w, h)) if (1..=max).contains(&w) && (1..=max).contains(&h) => Ok((w, h)),
        _ => Err(BadValue::NotASize {
            text: Quoted(Echo::new(s, usize::MAX)),
            max,
        }),
    }
}

/// X,Y: a pixel, from the top-left corner, 0-based.
pub(super) fn parse_pixel(s: &str) -> Result<(u32, u32), BadValue> {
    let (x, y) = s
        .split_once(',')
        .ok_or_else(|| BadValue::NotAPixel { text: s.to_owned() })?;
    let int = |t: &str| {
        t.trim()
            .parse::<u32>()
            .map_err(|_| BadValue::NotACoordinate { text: t.to_owned() })
    };
    Ok((int(x)?, int(y)?))
}

/// `--precision f32|f64`.
impl ValueEnum for Precision {
    fn value_variants<'a>() -> &'a [Self] {
        &[Precision::F32, Precision::F64]
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
    }
}

/// Why a text that looks like a number is not one, in a value's error.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Hint(NotANumber);

impl Default for Hint {
    fn default() -> Self {
        Hint(NotANumber::OutOfRange)
    }
}

impl Show for Hint {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.text(lang))
    }
}

/// A value echoed in double quotes, as Rust's `{:?}` writes a string (its quotes and
/// backslashes escaped).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Quoted(Echo);

impl Show for Quoted {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", In(&self.0, lang).to_string())
    }
}

crate::messages! {
    /// What a whole number given to a flag counts.
    #[derive(Default)]
    pub(crate) enum Whole {
        /// `--max-level`.
        #[default]
        Level => "a maximum level (1 = primary rays only)", "um nível máximo (1 = só os raios primários)";
        /// `--samples`.
        Samples => "samples per pixel", "as amostras por pixel";
        /// `--runs`.
        Runs => "the renders per setting", "as renderizações por configuração";
        /// `--threads`.
        Threads => "worker threads", "as threads de trabalho";
    }
}

crate::messages! {
    /// A flag's value that its parser refuses, with what would fix it (clap writes it after
    /// `invalid value 'VALUE' for 'FLAG': `).
    pub(crate) enum BadValue {
        /// A minimum weight that looks like a number and is not one.
        FractionHint { text: Echo, hint: Hint } =>
            "\"{text}\" {hint}. Fix: write a decimal (0.05) or a fraction (1/255)",
            "\"{text}\" {hint}. Correção: escreva um decimal (0.05) ou uma fração (1/255)";
        /// A minimum weight that is not a number ≥ 0.
        NotAFraction { text: Quoted } =>
            "{text} is not a number ≥ 0. Fix: write a decimal (0.05) or a fraction (1/255)",
            "{text} não é um número ≥ 0. Correção: escreva um decimal (0.05) ou uma fração \
             (1/255)";
        /// A share of the points that looks like a number and is not one.
        ShareHint { text: Echo, hint: Hint } =>
            "\"{text}\" {hint}. Fix: give a share of the points from 0 to 1, such as 0.5 (half) \
             or 1/3",
            "\"{text}\" {hint}. Correção: dê uma fração dos pontos de 0 a 1, como 0.5 (metade) \
             ou 1/3";
        /// A share of the points out of 0 to 1.
        NotAShare { text: Echo } =>
            "\"{text}\" is not a number from 0 to 1. Fix: give a share of the points from 0 to \
             1, such as 0.5 (half) or 1/3",
            "\"{text}\" não é um número de 0 a 1. Correção: dê uma fração dos pontos de 0 a 1, \
             como 0.5 (metade) ou 1/3";
        /// A tolerance that looks like a number and is not one.
        ToleranceHint { text: Echo, hint: Hint } =>
            "\"{text}\" {hint}. Fix: give a number ≥ 0 (e.g. 0.005 on the 0–1 scale)",
            "\"{text}\" {hint}. Correção: dê um número ≥ 0 (por exemplo 0.005 na escala 0–1)";
        /// A tolerance that is not a number ≥ 0.
        NotATolerance { text: Echo } =>
            "\"{text}\" is not a tolerance. Fix: give the largest difference accepted per \
             channel, a number ≥ 0 (e.g. 0.005 on the 0–1 scale, 1 on the 255 scale)",
            "\"{text}\" não é uma tolerância. Correção: dê a maior diferença aceita por canal, \
             um número ≥ 0 (por exemplo 0.005 na escala 0–1, 1 na escala 255)";
        /// A CSV separator other than `,`, `;` or a tab.
        NotASeparator { text: String } =>
            "\"{text}\" is not a separator: give , or ; or tab",
            "\"{text}\" não é um separador: dê , ou ; ou tab";
        /// A whole number that looks like a number and is not one.
        WholeHint { text: Echo, hint: Hint, what: Whole, lo: u64, hi: u64 } =>
            "\"{text}\" {hint}. Fix: give {what} from {lo} to {hi}",
            "\"{text}\" {hint}. Correção: dê {what} de {lo} a {hi}";
        /// Not a whole number.
        NotWhole { text: Echo, what: Whole, lo: u64, hi: u64 } =>
            "\"{text}\" is not a whole number. Fix: give {what} from {lo} to {hi}",
            "\"{text}\" não é um número inteiro. Correção: dê {what} de {lo} a {hi}";
        /// A whole number out of its range.
        Outside { text: Echo, what: Whole, lo: u64, hi: u64 } =>
            "{text} is outside {lo} to {hi}. Fix: give {what} from {lo} to {hi}",
            "{text} está fora de {lo} a {hi}. Correção: dê {what} de {lo} a {hi}";
        /// Not WIDTHxHEIGHT.
        NotASize { text: Quoted, max: u32 } =>
            "{text} is not a size; write WIDTHxHEIGHT, each 1 to {max} (e.g. 320x240)",
            "{text} não é um tamanho; escreva LARGURAxALTURA, cada um de 1 a {max} (por exemplo \
             320x240)";
        /// Not X,Y.
        NotAPixel { text: String } =>
            "\"{text}\" is not X,Y (two whole numbers and a comma, e.g. 320,240)",
            "\"{text}\" não é X,Y (dois números inteiros e uma vírgula, por exemplo 320,240)";
        /// A pixel's coordinate that is not a whole number ≥ 0.
        NotACoordinate { text: String } =>
            "\"{text}\" is not a pixel coordinate (a whole number ≥ 0)",
            "\"{text}\" não é uma coordenada de pixel (um número inteiro ≥ 0)";
    }
}

/// clap prints a refused value's error by its `Display`: the English.
impl fmt::Display for BadValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text(Lang::En))
    }
}

impl std::error::Error for BadValue {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_single_number_flag_takes_a_decimal_comma() {
        // QA report A, finding 6: 0,01 is 0.01 and 0,5 is 0.5, as --answer reads them.
        assert_eq!(parse_tolerance("0,01"), Ok(0.01));
        assert_eq!(parse_fraction("0,5"), Ok(0.5));
        assert_eq!(parse_share("0,5"), Ok(0.5));
        assert_eq!(parse_share("1/2"), Ok(0.5));
        // Not one number with one comma: refused as before.
        assert!(parse_tolerance("0,0,1").is_err());
        assert!(parse_fraction(",5").is_err());
        assert!(parse_tolerance("-0,5").is_err());
    }

    #[test]
    fn a_share_out_of_range_says_what_a_share_is() {
        let e = parse_share("1,5").unwrap_err().to_string();
        assert!(e.starts_with("\"1,5\" is not a number from 0 to 1"), "{e}");
        assert!(
            e.contains("Fix: give a share of the points from 0 to 1"),
            "{e}"
        );
        assert!(!e.contains("1/255"), "{e}");
        let pt = parse_share("1,5").unwrap_err().text(Lang::Pt);
        assert_eq!(
            pt,
            "\"1,5\" não é um número de 0 a 1. Correção: dê uma fração dos pontos de 0 a 1, \
             como 0.5 (metade) ou 1/3"
        );
    }

    #[test]
    fn a_refused_value_reads_as_before_in_english_and_wholly_in_portuguese() {
        let cases: [(BadValue, &str, &str); 6] = [
            (
                parse_samples("0").unwrap_err(),
                "0 is outside 1 to 4096. Fix: give samples per pixel from 1 to 4096",
                "0 está fora de 1 a 4096. Correção: dê as amostras por pixel de 1 a 4096",
            ),
            (
                parse_threads("x").unwrap_err(),
                "\"x\" is not a whole number. Fix: give worker threads from 1 to 1024",
                "\"x\" não é um número inteiro. Correção: dê as threads de trabalho de 1 a 1024",
            ),
            (
                parse_fraction("a\"b").unwrap_err(),
                "\"a\\\"b\" is not a number ≥ 0. Fix: write a decimal (0.05) or a fraction \
                 (1/255)",
                "\"a\\\"b\" não é um número ≥ 0. Correção: escreva um decimal (0.05) ou uma \
                 fração (1/255)",
            ),
            (
                parse_tolerance("1e400").unwrap_err(),
                "\"1e400\" is out of range: beyond ±1.8e308, the largest number f64 holds. Fix: \
                 give a number ≥ 0 (e.g. 0.005 on the 0–1 scale)",
                "\"1e400\" está fora do alcance: além de ±1.8e308, o maior número de f64. \
                 Correção: dê um número ≥ 0 (por exemplo 0.005 na escala 0–1)",
            ),
            (
                parse_size("0x5").unwrap_err(),
                "\"0x5\" is not a size; write WIDTHxHEIGHT, each 1 to 16384 (e.g. 320x240)",
                "\"0x5\" não é um tamanho; escreva LARGURAxALTURA, cada um de 1 a 16384 (por \
                 exemplo 320x240)",
            ),
            (
                parse_pixel("3,b").unwrap_err(),
                "\"b\" is not a pixel coordinate (a whole number ≥ 0)",
                "\"b\" não é uma coordenada de pixel (um número inteiro ≥ 0)",
            ),
        ];
        for (e, en, pt) in cases {
            assert_eq!(e.to_string(), en);
            assert_eq!(e.text(Lang::Pt), pt);
        }
    }

    #[test]
    fn a_long_value_is_cut_with_its_length_in_the_language() {
        let long = "9".repeat(50) + "x";
        let e = parse_tolerance(&long).unwrap_err();
        assert!(e.to_string().contains("… (51 characters)\" is not"), "{e}");
        assert!(
            e.text(Lang::Pt).contains("… (51 caracteres)\" não é"),
            "{e}"
        );
    }
}
