//! Numbers as people write and read them: written with six significant digits, no "-0",
//! scientific notation only for very small or very large magnitudes ([`num`]); read as a
//! decimal or a fraction a/b ([`number`]).

/// Formats a number for the text report.
pub fn num(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if !(1e-4..1e7).contains(&a) {
        let s = format!("{x:.5e}");
        // Trim trailing zeros of the mantissa: 1.50000e3 → 1.5e3.
        let (m, e) = s.split_once('e').expect("scientific notation has an e");
        let m = m.trim_end_matches('0').trim_end_matches('.');
        return format!("{m}e{e}");
    }
    let digits = 6 - 1 - a.log10().floor() as i32;
    let decimals = digits.clamp(0, 12) as usize;
    let s = format!("{x:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// Formats a 3-vector as "(x, y, z)".
pub fn vec3(v: [f64; 3]) -> String {
    format!("({}, {}, {})", num(v[0]), num(v[1]), num(v[2]))
}

/// A finite decimal number, or a fraction a/b.
pub fn number(tok: &str) -> Option<f64> {
    let x = match tok.split_once('/') {
        Some((a, b)) => decimal(a)? / decimal(b)?,
        None => decimal(tok)?,
    };
    x.is_finite().then_some(x)
}

/// A decimal number (no "inf", "nan" or hexadecimal).
fn decimal(tok: &str) -> Option<f64> {
    let t = tok.trim();
    let ok = !t.is_empty()
        && t.chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'))
        && t.chars().any(|c| c.is_ascii_digit());
    if ok {
        t.parse().ok()
    } else {
        None
    }
}

/// `text` as it is echoed in a message: whole up to `max` characters, else its first ones and
/// how long it was (`0.5 0.5 0.5 0.5… (100000 characters)`). In a message value, echo with
/// [`Echo`](super::Echo), which says the length in the message's language.
pub fn shorten(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_owned();
    }
    let head: String = text.chars().take(max.saturating_sub(1)).collect();
    format!("{head}… ({n} characters)")
}

crate::messages! {
    /// Why a text that looks like a number is not one, when it has a common cause.
    pub enum NotANumber {
        /// A Unicode minus or dash, as word processors write it.
        UnicodeMinus =>
            "has a Unicode minus or dash (−, –): write the minus as the ASCII hyphen-minus -",
            "tem um sinal de menos ou travessão Unicode (−, –): escreva o menos como o hífen ASCII -";
        /// Full-width digits, as Asian input methods write them.
        FullWidth =>
            "has full-width digits (０-９): write the digits 0-9 and the point . in ASCII",
            "tem dígitos de largura dupla (０-９): escreva os dígitos 0-9 e o ponto . em ASCII";
        /// Beyond the range of f64 (`1e400`).
        OutOfRange =>
            "is out of range: beyond ±1.8e308, the largest number f64 holds",
            "está fora do alcance: além de ±1.8e308, o maior número de f64";
    }
}

/// Why a text that looks like a number is not one, when it has a common cause: beyond the range
/// of f64 (`1e400`), a Unicode minus (U+2212, as word processors write it), or full-width digits
/// (as Asian input methods write them). `None` when there is no such cause.
pub fn not_a_number(text: &str) -> Option<NotANumber> {
    if text.contains(['\u{2212}', '\u{2013}', '\u{FE63}', '\u{FF0D}']) {
        return Some(NotANumber::UnicodeMinus);
    }
    if text
        .chars()
        .any(|c| ('\u{FF10}'..='\u{FF19}').contains(&c) || c == '\u{FF0E}')
    {
        return Some(NotANumber::FullWidth);
    }
    let overflows = |t: &str| {
        let t = t.trim();
        !t.is_empty()
            && t.chars()
                .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'))
            && t.parse::<f64>().is_ok_and(f64::is_infinite)
    };
    let parts: Vec<&str> = text.split('/').collect();
    if parts.len() <= 2 && parts.iter().any(|p| overflows(p)) {
        return Some(NotANumber::OutOfRange);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_as_a_person_writes_them() {
        assert_eq!(num(0.6), "0.6");
        assert_eq!(num(0.35355339059327373), "0.353553");
        assert_eq!(num(-0.9899494936611666), "-0.989949");
        assert_eq!(num(2.8284271247461903), "2.82843");
        assert_eq!(num(-90.00000000000001), "-90");
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-1e-12), "-1e-12");
        assert_eq!(num(1.5e9), "1.5e9");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(-0.0000001), "-1e-7");
    }
}
