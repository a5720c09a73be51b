//! Where the samples of a pixel go: the Hammersley point set shifted to the middle of its
//! strata, (i + ½)/n across and the radical inverse of i (plus 1/(2n)) down. Stratified in both
//! directions, deterministic (no random numbers: the same image on every run), and one sample
//! is the pixel's centre.

/// The position of sample `i` of `n` within the pixel, in [0, 1)².
#[inline]
pub fn sample(i: u32, n: u32) -> (f64, f64) {
    let n = f64::from(n);
    let x = (f64::from(i) + 0.5) / n;
    let y = (radical_inverse(i) + 0.5 / n).fract();
    (x, y)
}

/// The bits of i mirrored about the binary point (van der Corput): 1 → ½, 2 → ¼, 3 → ¾, …
#[inline]
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) / 4_294_967_296.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sample_is_the_pixel_centre() {
        assert_eq!(sample(0, 1), (0.5, 0.5));
    }

    #[test]
    fn four_samples_fall_one_in_each_quarter_row_and_column() {
        let s: Vec<_> = (0..4).map(|i| sample(i, 4)).collect();
        // By hand: radical inverses 0, ½, ¼, ¾, each + ⅛.
        assert_eq!(
            s,
            vec![
                (0.125, 0.125),
                (0.375, 0.625),
                (0.625, 0.375),
                (0.875, 0.875)
            ]
        );
    }

    #[test]
    fn every_stratum_holds_exactly_one_sample_in_each_direction() {
        for n in [2u32, 8, 16, 64, 256] {
            let mut xs = vec![0; n as usize];
            let mut ys = vec![0; n as usize];
            for i in 0..n {
                let (x, y) = sample(i, n);
                assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                xs[(x * f64::from(n)) as usize] += 1;
                ys[(y * f64::from(n)) as usize] += 1;
            }
            assert!(xs.iter().all(|&c| c == 1), "n = {n}: {xs:?}");
            assert!(ys.iter().all(|&c| c == 1), "n = {n}: {ys:?}");
        }
    }
}
