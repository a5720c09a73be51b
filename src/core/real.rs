//! One source for f32 and f64: the [`Real`] scalar trait and its [`Vector`] type.
//!
//! The core is written once against these two traits and instantiated for `f32` (with glam's
//! `Vec3`) and `f64` (with glam's `DVec3`). Only the operations the core uses are here. The trait
//! is sealed: the core's robustness arguments (ulps, ranges) are made for these two types only.

use std::fmt::{Debug, Display};
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A floating-point scalar the core can run in: `f32` or `f64`.
pub trait Real:
    sealed::Sealed
    + Copy
    + Debug
    + Display
    + Default
    + PartialOrd
    + Send
    + Sync
    + serde::Serialize
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The three-component vector of this precision (also used for RGB colours).
    type Vec3: Vector<Self> + super::lanes::LaneVec<Self>;
    /// The lanes of this precision in one 256-bit register (8 × f32, 4 × f64), for the wide
    /// tracer ([`Wide`](super::Wide)).
    type Wide: super::lanes::Wide<Scalar = Self>
        + super::lanes::Lanes<Scalar = Self, Mask = Self::Wide, V = super::lanes::W3<Self::Wide>>;
    /// `"f32"` or `"f64"`, as the CLI and the JSON output name it.
    const NAME: &'static str;
    /// The number 0 in this precision.
    const ZERO: Self;
    /// The number 1 in this precision.
    const ONE: Self;
    /// The number 2 in this precision.
    const TWO: Self;
    /// Machine epsilon (the gap between 1 and the next representable number).
    const EPSILON: Self;

    /// Converts from f64, rounding to nearest (may give ±inf for f32; callers check).
    fn from_f64(x: f64) -> Self;
    /// Widens to f64 (exact for both precisions).
    fn to_f64(self) -> f64;
    /// The square root, correctly rounded.
    fn sqrt(self) -> Self;
    /// The absolute value.
    fn abs(self) -> Self;
    /// `self` raised to a real power `e` (the platform's `powf`).
    fn powf(self, e: Self) -> Self;
    /// The larger of the two (the other one where one is NaN).
    fn max(self, o: Self) -> Self;
    /// The smaller of the two (the other one where one is NaN).
    fn min(self, o: Self) -> Self;
    /// Neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// The angle of (x = `other`, y = `self`) in radians, as `f64::atan2`.
    fn atan2(self, other: Self) -> Self;
    /// Degrees to radians.
    fn to_radians(self) -> Self;
    /// Radians to degrees.
    fn to_degrees(self) -> Self;
    /// Cosine of an angle given in degrees; exact at 0°, 60° and 90°, where the chapter's
    /// cone tests most often sit on the edge.
    fn cos_deg(self) -> Self;
    /// Rounds towards zero to an integer value.
    fn trunc(self) -> Self;
    /// Tangent of an angle in radians.
    fn tan(self) -> Self;
    /// The next representable number towards +∞ (towards −∞ for `next_down`): rounding an
    /// offset ray origin outward, as pbrt does.
    fn next_up(self) -> Self;
    /// The next representable number towards −∞ (see [`Real::next_up`]).
    fn next_down(self) -> Self;
    /// Raises to an integer power by repeated multiplication (`powi_by_squaring`).
    fn powi(self, n: i32) -> Self;
    /// e^x.
    fn exp(self) -> Self;
    /// ln(1 + x), accurate for x near 0.
    fn ln_1p(self) -> Self;
    /// x^e as the chapter's exponents need it: by repeated squaring ([`Real::powi`]) when e is a
    /// whole number up to 1024 in magnitude (n_s = 20, a spot's e = 2: faster than `powf`, and
    /// as accurate), by `powf` otherwise.
    #[inline]
    fn pow(self, e: Self) -> Self {
        if e.trunc() == e && e.abs() <= Self::from_f64(1024.0) {
            self.powi(e.to_f64() as i32)
        } else {
            self.powf(e)
        }
    }
    /// Bounds on a squared length inside which x² + y² + z² neither overflows nor loses the
    /// largest component to underflow, so ‖v‖ = √(v·v) directly.
    const SAFE_SQUARED_MIN: Self;
    /// The upper bound of that range (see [`Real::SAFE_SQUARED_MIN`]).
    const SAFE_SQUARED_MAX: Self;
}

/// A 3-vector of [`Real`]s: glam's `Vec3` or `DVec3`. Multiplying two vectors is the
/// component-wise product, which is also the chapter's "multiplication of colours" (Eq. 4.5).
pub trait Vector<R>:
    Copy
    + Debug
    + PartialEq
    + Send
    + Sync
    + serde::Serialize
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<R, Output = Self>
    + Mul<Self, Output = Self>
    + Div<R, Output = Self>
    + AddAssign
{
    /// The zero vector (black, as a colour).
    const ZERO: Self;
    /// The vector (x, y, z) (or the colour (r, g, b)).
    fn new(x: R, y: R, z: R) -> Self;
    /// The vector with all three components `v`.
    fn splat(v: R) -> Self;
    /// The components as `[x, y, z]`.
    fn to_array(self) -> [R; 3];
    /// The dot product.
    fn dot(self, o: Self) -> R;
    /// The cross product, `self × o`.
    fn cross(self, o: Self) -> Self;
    /// The Euclidean length computed naively (may underflow or overflow; see
    /// `core::vector::normalize` for the robust form).
    fn naive_length(self) -> R;
    /// The component-wise absolute value.
    fn abs(self) -> Self;
    /// The largest component.
    fn max_element(self) -> R;
    /// Every component is neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// The first component (x, or red).
    fn x(self) -> R;
    /// The second component (y, or green).
    fn y(self) -> R;
    /// The third component (z, or blue).
    fn z(self) -> R;
}

/// x^n by repeated squaring, written out: the algorithm of compiler-rt's `__powisf2` and
/// `__powidf2` (what `f32::powi` and `f64::powi` call for an exponent known only at run time):
/// r = 1; for each bit of |n| from the lowest, r ·= x where the bit is set, x ·= x before the
/// next; 1/r for a negative n. Written here it is inlined (no call, whose saved registers cost
/// more than the few multiplications), the same bits on every platform, and, over
/// [`crate::core::lanes::Lanes`], the same operations in every lane: the wide tracer raises a
/// register of cosines at once to the material's shared n_s with the scalar's bits.
#[inline(always)]
pub(crate) fn powi_by_squaring<T>(x: T, one: T, n: i32) -> T
where
    T: Copy + std::ops::Mul<Output = T> + std::ops::Div<Output = T>,
{
    let mut base = x;
    let mut bits = n.unsigned_abs();
    let mut r = one;
    loop {
        if bits & 1 != 0 {
            r = r * base;
        }
        bits >>= 1;
        if bits == 0 {
            break;
        }
        base = base * base;
    }
    if n < 0 {
        one / r
    } else {
        r
    }
}

macro_rules! impl_real {
    ($t:ty, $v:ty, $w:ty, $name:literal) => {
        impl Real for $t {
            type Vec3 = $v;
            type Wide = $w;
            const NAME: &'static str = $name;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const EPSILON: Self = <$t>::EPSILON;
            // 2^±(max exponent / 2 − 2): squares of components up to √MAX/4 stay finite, and a
            // component too small to square without underflow is below ε of the largest.
            const SAFE_SQUARED_MIN: Self = <$t>::MIN_POSITIVE * (1.0 / <$t>::EPSILON) * 4.0;
            const SAFE_SQUARED_MAX: Self = <$t>::MAX / 16.0;

            #[inline]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline]
            fn powf(self, e: Self) -> Self {
                <$t>::powf(self, e)
            }
            #[inline]
            fn max(self, o: Self) -> Self {
                <$t>::max(self, o)
            }
            #[inline]
            fn min(self, o: Self) -> Self {
                <$t>::min(self, o)
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
            #[inline]
            fn atan2(self, other: Self) -> Self {
                <$t>::atan2(self, other)
            }
            #[inline]
            fn to_radians(self) -> Self {
                <$t>::to_radians(self)
            }
            #[inline]
            fn to_degrees(self) -> Self {
                <$t>::to_degrees(self)
            }
            fn cos_deg(self) -> Self {
                // Exact values where the decimal angle has an exact cosine; elsewhere the
                // correctly reduced cosine of the radian value.
                if self == 0.0 {
                    1.0
                } else if self == 60.0 {
                    0.5
                } else if self == 90.0 {
                    0.0
                } else {
                    <$t>::cos(self.to_radians())
                }
            }
            #[inline]
            fn trunc(self) -> Self {
                <$t>::trunc(self)
            }
            #[inline]
            fn tan(self) -> Self {
                <$t>::tan(self)
            }
            #[inline]
            fn next_up(self) -> Self {
                <$t>::next_up(self)
            }
            #[inline]
            fn next_down(self) -> Self {
                <$t>::next_down(self)
            }
            #[inline]
            fn powi(self, n: i32) -> Self {
                powi_by_squaring(self, 1.0, n)
            }
            #[inline]
            fn exp(self) -> Self {
                <$t>::exp(self)
            }
            #[inline]
            fn ln_1p(self) -> Self {
                <$t>::ln_1p(self)
            }
        }

        impl Vector<$t> for $v {
            const ZERO: Self = <$v>::ZERO;
            #[inline]
            fn new(x: $t, y: $t, z: $t) -> Self {
                <$v>::new(x, y, z)
            }
            #[inline]
            fn splat(v: $t) -> Self {
                <$v>::splat(v)
            }
            #[inline]
            fn to_array(self) -> [$t; 3] {
                <$v>::to_array(&self)
            }
            #[inline]
            fn dot(self, o: Self) -> $t {
                <$v>::dot(self, o)
            }
            #[inline]
            fn cross(self, o: Self) -> Self {
                <$v>::cross(self, o)
            }
            #[inline]
            fn naive_length(self) -> $t {
                <$v>::length(self)
            }
            #[inline]
            fn abs(self) -> Self {
                <$v>::abs(self)
            }
            #[inline]
            fn max_element(self) -> $t {
                <$v>::max_element(self)
            }
            #[inline]
            fn x(self) -> $t {
                self.x
            }
            #[inline]
            fn y(self) -> $t {
                self.y
            }
            #[inline]
            fn z(self) -> $t {
                self.z
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$v>::is_finite(self)
            }
        }
    };
}

// f32's vector is glam's `Vec3A`: three floats in one 128-bit SIMD register (SSE2 on x86-64,
// NEON on aarch64, a plain struct elsewhere), so a ray's own vector arithmetic (its hit point,
// normal, reflection, the path's step) is one instruction where `Vec3` takes three; each
// operation computes what `Vec3`'s does in the same order (a dot product (x·x + y·y) + z·z,
// a cross product component by component), so the results are the same bits (the image
// tests; docs/benchmarks.md, "f32's vectors in one register"). f64 has no such type: a
// `DVec3` is three scalars.
impl_real!(f32, glam::Vec3A, wide::f32x8, "f32");
impl_real!(f64, glam::DVec3, super::lanes::F64Lanes, "f64");

/// Shorthand for the vector type of a precision.
pub type V3<R> = <R as Real>::Vec3;

/// The precision a whole calculation runs in, chosen at run time (the code is generic over
/// [`Real`]; this names the instance).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// Single precision, `f32` (`--precision f32`).
    F32,
    /// Double precision, `f64` (`--precision f64`, the default).
    F64,
}

impl Precision {
    /// "f32" or "f64", as `--precision` and [`Real::NAME`] write it.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Precision::F32 => f32::NAME,
            Precision::F64 => f64::NAME,
        }
    }
}

/// Builds a vector of precision `R` from f64 components.
#[inline]
pub fn v3<R: Real>(a: [f64; 3]) -> V3<R> {
    V3::<R>::new(R::from_f64(a[0]), R::from_f64(a[1]), R::from_f64(a[2]))
}

/// Widens a vector to f64 components.
#[inline]
pub(crate) fn to_f64_array<R: Real>(v: V3<R>) -> [f64; 3] {
    let a = v.to_array();
    [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]
}
