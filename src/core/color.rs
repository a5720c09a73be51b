//! A colour for display: clamped to [0, 1], and in 8 bits as round(255·c) of the clamped value
//! (docs/conventions.md, "Colour"). Defined once for the solver's answer, the tracer's pixels and
//! the reports' swatches, so an image and its explanation cannot round differently.

use super::real::{Real, Vector, V3};

/// Each component clamped to [0, 1] (NaN to 0).
#[inline]
pub fn clamp01<R: Real>(c: V3<R>) -> V3<R> {
    let a = c.to_array().map(|x| x.max(R::ZERO).min(R::ONE));
    V3::<R>::new(a[0], a[1], a[2])
}

/// One component in 8 bits: round(255·c) of c clamped to [0, 1] (NaN to 0), computed in f64
/// (an f32 component widens exactly). 0.7·255 = 178.5 is a rounding midpoint: 0.7 in f64 times
/// 255 rounds to 178.5 and gives 179; 0.7 in f32 lies further below 0.7 and gives 178.
///
/// x = 255·c lies in [0, 255] (or is NaN): its whole part i = ⌊x⌋ and x − i, exact (Sterbenz),
/// round half away from zero as `f64::round` does, without the library call that `round` is
/// on x86-64 before SSE4.1 (three a pixel: 2.5 % of the classic scene's f32 render).
#[inline]
pub fn to_8bit(c: f64) -> u8 {
    let x = c.clamp(0.0, 1.0) * 255.0;
    // NaN: `as` gives 0, and NaN − 0 ≥ 0.5 is false.
    let i = x as u8;
    if x - f64::from(i) >= 0.5 {
        i + 1
    } else {
        i
    }
}

/// A colour in 8 bits, [`to_8bit`] per component.
#[inline]
pub fn rgb8(c: [f64; 3]) -> [u8; 3] {
    c.map(to_8bit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eight_bits_round_the_clamped_value() {
        assert_eq!(rgb8([-0.5, 0.5, 1.5]), [0, 128, 255]);
        assert_eq!(
            rgb8([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]),
            [0, 255, 0]
        );
        // Exercise 4.1: 0.7·255 = 178.5 on the midpoint, from either side in f32 and f64.
        assert_eq!(to_8bit(0.7f64), 179);
        assert_eq!(to_8bit(f64::from(0.7f32)), 178);
    }

    #[test]
    fn eight_bits_are_the_rounded_product_everywhere() {
        // Against f64::round itself: every midpoint k + 1/2, its neighbours, and a sweep.
        let mut cs: Vec<f64> = (0..=255)
            .flat_map(|k| {
                let mid = (f64::from(k) + 0.5) / 255.0;
                [mid, mid.next_up(), mid.next_down(), f64::from(k) / 255.0]
            })
            .collect();
        cs.extend((0..=100_000).map(|i| f64::from(i) / 100_000.0));
        cs.extend([
            0.0,
            -0.0,
            1.0,
            1.0f64.next_down(),
            f64::MIN_POSITIVE,
            5e-324,
        ]);
        for c in cs {
            let want = (c.clamp(0.0, 1.0) * 255.0).round() as u8;
            assert_eq!(to_8bit(c), want, "{c:e}");
        }
    }

    #[test]
    fn clamping_keeps_what_is_in_range() {
        let c = clamp01::<f64>(glam::DVec3::new(-1.0, 0.25, 2.0));
        assert_eq!(c, glam::DVec3::new(0.0, 0.25, 1.0));
        let nan = clamp01::<f32>(glam::Vec3A::new(f32::NAN, 1.0, 0.0));
        assert_eq!(nan, glam::Vec3A::new(0.0, 1.0, 0.0));
    }
}
