//! How numbers are written for people: six significant digits, no "-0", scientific notation
//! only for very small or very large magnitudes.

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
