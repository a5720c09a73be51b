//! Lanes: several numbers of one precision in one register, for the wide tracer
//! (`tracer::wide`). 8 lanes of f32 or 4 of f64 in 256 bits (`wide`'s `f32x8`, `f64x4`), so that
//! f32 does twice the work per instruction.
//!
//! Every operation here is the IEEE operation of each lane: +, −, ×, ÷ and √ are correctly
//! rounded in a lane exactly as in a scalar, negation flips the sign bit as a scalar's does, and
//! nothing is fused (no FMA). Code written with [`Wide`] in the same order as the scalar code
//! therefore computes the scalar code's bits in every lane: that is what lets the wide tracer's
//! image equal the scalar one's byte for byte (src/tracer/wide/tests.rs). Comparisons give masks (all bits
//! set where true, as the hardware does), [`Wide::select`] picks per lane; a NaN compares false,
//! as a scalar's comparison does.

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Sub};

use wide::{f32x8, f64x4, CmpEq, CmpGt, CmpLt};

use super::real::{Real, Vector, V3};

/// A register of [`Wide::LANES`] numbers of one precision ([`Real::Wide`]), with masks of the
/// same type.
pub trait Wide:
    Copy
    + Debug
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
{
    /// The precision of each lane.
    type Scalar: Real;
    /// The lanes as an array, `[Scalar; LANES]`.
    type Array: Copy + Default + Debug + AsRef<[Self::Scalar]> + AsMut<[Self::Scalar]>;
    /// How many lanes: 8 for f32, 4 for f64.
    const LANES: usize;

    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// The lanes from an array, lane 0 first.
    fn from_array(a: Self::Array) -> Self;
    /// The lanes as an array, lane 0 first.
    fn to_array(self) -> Self::Array;
    /// −x in each lane (the sign bit flipped, as a scalar's negation: −0 stays distinct).
    fn neg(self) -> Self;
    /// √x in each lane, correctly rounded.
    fn sqrt(self) -> Self;
    /// The mask of lanes where `self < o`.
    fn lt(self, o: Self) -> Self;
    /// The mask of lanes where `self > o`.
    fn gt(self, o: Self) -> Self;
    /// The mask of lanes where `self == o`.
    fn eq(self, o: Self) -> Self;
    /// The mask of lanes where `self` is finite.
    fn finite(self) -> Self;
    /// Both masks.
    fn and(self, o: Self) -> Self;
    /// Either mask.
    fn or(self, o: Self) -> Self;
    /// The mask's complement.
    fn not(self) -> Self;
    /// Per lane: `t` where the mask `self` is set, `f` elsewhere.
    fn select(self, t: Self, f: Self) -> Self;
    /// The mask's lanes as bits, lane 0 in bit 0.
    fn bits(self) -> u32;
}

macro_rules! impl_wide {
    ($w:ty, $s:ty, $n:literal) => {
        impl Wide for $w {
            type Scalar = $s;
            type Array = [$s; $n];
            const LANES: usize = $n;

            #[inline(always)]
            fn splat(x: $s) -> Self {
                <$w>::splat(x)
            }
            #[inline(always)]
            fn from_array(a: [$s; $n]) -> Self {
                <$w>::new(a)
            }
            #[inline(always)]
            fn to_array(self) -> [$s; $n] {
                <$w>::to_array(self)
            }
            #[inline(always)]
            fn neg(self) -> Self {
                self ^ <$w>::splat(-0.0)
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$w>::sqrt(self)
            }
            #[inline(always)]
            fn lt(self, o: Self) -> Self {
                self.cmp_lt(o)
            }
            #[inline(always)]
            fn gt(self, o: Self) -> Self {
                self.cmp_gt(o)
            }
            #[inline(always)]
            fn eq(self, o: Self) -> Self {
                self.cmp_eq(o)
            }
            #[inline(always)]
            fn finite(self) -> Self {
                <$w>::is_finite(self)
            }
            #[inline(always)]
            fn and(self, o: Self) -> Self {
                self & o
            }
            #[inline(always)]
            fn or(self, o: Self) -> Self {
                self | o
            }
            #[inline(always)]
            fn not(self) -> Self {
                !self
            }
            #[inline(always)]
            fn select(self, t: Self, f: Self) -> Self {
                self.blend(t, f)
            }
            #[inline(always)]
            fn bits(self) -> u32 {
                self.move_mask() as u32
            }
        }
    };
}

impl_wide!(f32x8, f32, 8);
impl_wide!(f64x4, f64, 4);

/// Shorthand for the lanes of a precision.
pub type W<R> = <R as Real>::Wide;

/// Three registers: a vector per lane, structure of arrays.
#[derive(Clone, Copy, Debug)]
pub struct W3<L: Wide> {
    /// The x components.
    pub x: L,
    /// The y components.
    pub y: L,
    /// The z components.
    pub z: L,
}

impl<L: Wide> W3<L> {
    /// The same vector in every lane.
    #[inline(always)]
    pub fn splat(v: V3<L::Scalar>) -> Self {
        W3 {
            x: L::splat(v.x()),
            y: L::splat(v.y()),
            z: L::splat(v.z()),
        }
    }

    /// Lane k holds `vs[k]`; lanes past the slice's end hold `fill`.
    #[inline]
    pub fn gather(vs: impl Iterator<Item = V3<L::Scalar>>, fill: V3<L::Scalar>) -> Self {
        let (mut x, mut y, mut z) = (
            L::Array::default(),
            L::Array::default(),
            L::Array::default(),
        );
        let (xs, ys, zs) = (x.as_mut(), y.as_mut(), z.as_mut());
        let mut vs = vs;
        for k in 0..L::LANES {
            let v = vs.next().unwrap_or(fill);
            xs[k] = v.x();
            ys[k] = v.y();
            zs[k] = v.z();
        }
        W3 {
            x: L::from_array(x),
            y: L::from_array(y),
            z: L::from_array(z),
        }
    }

    /// Each component times the lane's `s`.
    #[inline(always)]
    pub fn scale(self, s: L) -> Self {
        W3 {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    /// The dot product in each lane, summed as glam sums it: (x·x′ + y·y′) + z·z′.
    #[inline(always)]
    pub fn dot(self, o: Self) -> L {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// The mask of lanes whose three components are all finite.
    #[inline(always)]
    pub fn finite(self) -> L {
        self.x.finite().and(self.y.finite()).and(self.z.finite())
    }
}

impl<L: Wide> Sub for W3<L> {
    type Output = Self;
    /// Lane-wise difference.
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        W3 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

impl<L: Wide> Add for W3<L> {
    type Output = Self;
    /// Lane-wise sum.
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        W3 {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::v3;

    /// The lanes compute the scalar bits: a dot product, a quotient, a root and a negation of
    /// awkward numbers in every lane.
    fn lanes_compute_the_scalar_bits<R: Real>() {
        let vs: Vec<V3<R>> = (0..W::<R>::LANES)
            .map(|k| {
                let k = k as f64;
                v3::<R>([0.1 + k / 3.0, -7.0 / (k + 1.0), 1e-3 * k - 0.7])
            })
            .collect();
        let w = W3::<W<R>>::gather(vs.iter().copied(), V3::<R>::ZERO);
        let o = W3::<W<R>>::splat(v3::<R>([0.3, 0.2, -1.1]));
        let dot = w.dot(o);
        let q = (dot / w.x).neg();
        let root = w.dot(w).sqrt();
        for (k, v) in vs.iter().enumerate() {
            let d = v.dot(o_scalar::<R>());
            assert_eq!(
                dot.to_array().as_ref()[k].to_f64().to_bits(),
                d.to_f64().to_bits()
            );
            let qs = -(d / v.x());
            assert_eq!(
                q.to_array().as_ref()[k].to_f64().to_bits(),
                qs.to_f64().to_bits()
            );
            let rs = v.dot(*v).sqrt();
            assert_eq!(
                root.to_array().as_ref()[k].to_f64().to_bits(),
                rs.to_f64().to_bits()
            );
        }
        let zero = W::<R>::splat(R::ZERO);
        assert_eq!(
            zero.neg().to_array().as_ref()[0].to_f64().to_bits(),
            (-0.0f64).to_bits()
        );
        let nan = W::<R>::splat(R::from_f64(f64::NAN));
        assert_eq!(nan.lt(zero).or(nan.gt(zero)).or(nan.eq(nan)).bits(), 0);
        assert_eq!(nan.finite().bits(), 0);
        assert_eq!(zero.finite().bits(), (1u32 << W::<R>::LANES) - 1);
    }

    fn o_scalar<R: Real>() -> V3<R> {
        v3::<R>([0.3, 0.2, -1.1])
    }

    #[test]
    fn lanes_compute_the_scalar_bits_in_both_precisions() {
        lanes_compute_the_scalar_bits::<f32>();
        lanes_compute_the_scalar_bits::<f64>();
    }
}
