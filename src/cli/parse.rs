//! What clap reads a flag's value as: a number or fraction ≥ 0 (`1/255`), an image size
//! (`320x240`), a pixel (`X,Y`), and the hand-written [`ValueEnum`] of [`Precision`] (which lives
//! in the core, outside clap).

use clap::ValueEnum;

use crate::core::Precision;

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

/// A number ≥ 0 written as a decimal (with a point, or a decimal comma: `0,05`) or a fraction
/// (1/255).
pub(super) fn parse_fraction(s: &str) -> Result<f64, String> {
    if let Some(hint) = crate::check::answer::not_a_number_hint(s.trim()) {
        return Err(format!(
            "\"{}\" {hint}. Fix: write a decimal (0.05) or a fraction (1/255)",
            crate::text::number::shorten(s, 40)
        ));
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if x >= 0.0 => Ok(x),
        _ => Err(format!(
            "{:?} is not a number ≥ 0. Fix: write a decimal (0.05) or a fraction (1/255)",
            crate::text::number::shorten(s, 40)
        )),
    }
}

/// A share of the points (`--reading-credit`): a number from 0 to 1, written as a decimal
/// (`0.5`, or with a decimal comma `0,5`) or a fraction (`1/2`); the error says what a share is
/// (the fix of [`parse_fraction`] is a minimum weight's).
pub(super) fn parse_share(s: &str) -> Result<f64, String> {
    let shown = crate::text::number::shorten(s, 40);
    let fix = crate::report::messages::both(
        "give a share of the points from 0 to 1, such as 0.5 (half) or 1/3",
        "dê uma fração dos pontos de 0 a 1, como 0.5 (metade) ou 1/3",
    );
    if let Some(hint) = crate::check::answer::not_a_number_hint(s.trim()) {
        return Err(format!("\"{shown}\" {hint}. Fix: {fix}"));
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if (0.0..=1.0).contains(&x) => Ok(x),
        _ => Err(format!(
            "{}. Fix: {fix}",
            crate::report::messages::both(
                &format!("\"{shown}\" is not a number from 0 to 1"),
                &format!("\"{shown}\" não é um número de 0 a 1"),
            )
        )),
    }
}

/// A tolerance: a number ≥ 0 (a decimal, with a point or a decimal comma `0,01`, or a fraction
/// 1/255), finite; a number beyond the range of f64 (`1e400`) is said to be out of range, not
/// infinite.
pub(super) fn parse_tolerance(s: &str) -> Result<f64, String> {
    if let Some(hint) = crate::check::answer::not_a_number_hint(s.trim()) {
        return Err(format!(
            "\"{}\" {hint}. Fix: give a number ≥ 0 (e.g. 0.005 on the 0–1 scale)",
            crate::text::number::shorten(s, 40)
        ));
    }
    match crate::text::number::number(&with_decimal_point(s)) {
        Some(x) if x >= 0.0 => Ok(x),
        _ => Err(format!(
            "\"{}\" is not a tolerance. Fix: give the largest difference accepted per channel, \
             a number ≥ 0 (e.g. 0.005 on the 0–1 scale, 1 on the 255 scale)",
            crate::text::number::shorten(s, 40)
        )),
    }
}

/// `--delimiter`: `,`, `;`, or a tab (`tab`, `\t` or the character itself).
pub(super) fn parse_delimiter(s: &str) -> Result<u8, String> {
    match s {
        "," => Ok(b','),
        ";" => Ok(b';'),
        "tab" | "\\t" | "\t" => Ok(b'\t'),
        _ => Err(format!("\"{s}\" is not a separator: give , or ; or tab")),
    }
}

/// A whole number from `lo` to `hi`, or the error that says so with the range and the fix
/// (`4294967296 is outside 1 to 4096`: the text as typed, not clap's type's range).
fn whole(s: &str, lo: u64, hi: u64, what: &str) -> Result<u64, String> {
    let t = s.trim();
    let fix = format!("Fix: give {what} from {lo} to {hi}");
    if t.is_empty() || !t.bytes().all(|b| b.is_ascii_digit()) {
        let hint = crate::check::answer::not_a_number_hint(t)
            .unwrap_or_else(|| "is not a whole number".into());
        return Err(format!(
            "\"{}\" {hint}. {fix}",
            crate::text::number::shorten(s, 40)
        ));
    }
    match t.parse::<u64>() {
        Ok(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => Err(format!(
            "{} is outside {lo} to {hi}. {fix}",
            crate::text::number::shorten(t, 40)
        )),
    }
}

/// A maximum level: 1 to [`crate::problem::model::MAX_LEVEL`].
pub(super) fn parse_level(s: &str) -> Result<u32, String> {
    let max = crate::problem::model::MAX_LEVEL;
    whole(s, 1, max.into(), "a maximum level (1 = primary rays only)").map(|n| n as u32)
}

/// Samples per pixel: 1 to [`crate::problem::model::MAX_SAMPLES`].
pub(super) fn parse_samples(s: &str) -> Result<u32, String> {
    let max = crate::problem::model::MAX_SAMPLES;
    whole(s, 1, max.into(), "samples per pixel").map(|n| n as u32)
}

/// Renders per setting: 1 to [`crate::tradeoff::MAX_RUNS`].
pub(super) fn parse_runs(s: &str) -> Result<u32, String> {
    let max = crate::tradeoff::MAX_RUNS;
    whole(s, 1, max.into(), "the renders per setting").map(|n| n as u32)
}

/// The most worker threads: 1024, more than any machine the course runs on has cores (each
/// thread reserves its stack).
pub(crate) const MAX_THREADS: u64 = 1024;

/// Worker threads: 1 to [`MAX_THREADS`].
pub(super) fn parse_threads(s: &str) -> Result<usize, String> {
    whole(s, 1, MAX_THREADS, "worker threads").map(|n| n as usize)
}

/// WxH, each 1 to the largest image side.
pub(super) fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let max = crate::problem::model::MAX_IMAGE_SIDE;
    let parsed = s
        .split_once(['x', '×'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)));
    match parsed {
        Some((w, h)) if (1..=max).contains(&w) && (1..=max).contains(&h) => Ok((w, h)),
        _ => Err(format!(
            "{s:?} is not a size; write WIDTHxHEIGHT, each 1 to {max} (e.g. 320x240)"
        )),
    }
}

/// X,Y: a pixel, from the top-left corner, 0-based.
pub(super) fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s.split_once(',').ok_or_else(|| {
        format!("\"{s}\" is not X,Y (two whole numbers and a comma, e.g. 320,240)")
    })?;
    let int = |t: &str| {
        t.trim()
            .parse::<u32>()
            .map_err(|_| format!("\"{t}\" is not a pixel coordinate (a whole number ≥ 0)"))
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
        let e = parse_share("1,5").unwrap_err();
        assert!(e.starts_with("\"1,5\" is not a number from 0 to 1"), "{e}");
        assert!(
            e.contains("Fix: give a share of the points from 0 to 1"),
            "{e}"
        );
        assert!(!e.contains("1/255"), "{e}");
        let pt = crate::report::messages::error_in(&e, crate::text::lang::Lang::Pt);
        assert_eq!(
            pt,
            "\"1,5\" não é um número de 0 a 1. Correção: dê uma fração dos pontos de 0 a 1, \
             como 0.5 (metade) ou 1/3"
        );
    }
}
