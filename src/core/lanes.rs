//! Lanes: several numbers of one precision in one register, for the wide tracer
//! (`tracer::wide`). 8 lanes of f32 (`wide`'s `f32x8`, 256 bits); f64 in as many lanes as a
//! register of the CPU phong is built for holds ([`F64Lanes`]): 8 (`f64x8`) with AVX-512's
//! 512-bit registers, else 4 (`f64x4`: one register with AVX2, two SSE2 halves without).
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

use wide::{f32x8, f64x4, f64x8};

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
    /// A u32 per lane, `[u32; LANES]` (a wide node's children, a leaf's shapes: no room kept
    /// for lanes the precision does not have).
    type Indices: Copy + Default + Debug + Send + Sync + AsRef<[u32]> + AsMut<[u32]>;
    /// How many lanes: 8 for f32; 8 or 4 for f64 (`F64Lanes`).
    const LANES: usize;

    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// The lanes from an array, lane 0 first.
    fn from_array(a: Self::Array) -> Self;
    /// The lanes as an array, lane 0 first.
    fn to_array(self) -> Self::Array;
    /// The lanes in place, as an array: read where they are, not copied out first.
    fn as_array(&self) -> &Self::Array;
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
            type Indices = [u32; $n];
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
            fn as_array(&self) -> &[$s; $n] {
                <$w>::as_array(self)
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
                self.simd_lt(o)
            }
            #[inline(always)]
            fn gt(self, o: Self) -> Self {
                self.simd_gt(o)
            }
            #[inline(always)]
            fn eq(self, o: Self) -> Self {
                self.simd_eq(o)
            }
            #[inline(always)]
            fn finite(self) -> Self {
                // x − x is +0 exactly for a finite x and NaN for ±∞ or NaN: two float
                // operations, where the bit test on the exponent needs 64-bit integer
                // comparisons that SSE2 does not have.
                (self - self).simd_eq(<$w>::splat(0.0))
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
                <$w>::select(self, t, f)
            }
            #[inline(always)]
            fn bits(self) -> u32 {
                self.to_bitmask() as u32
            }
        }
    };
}

impl_wide!(f32x8, f32, 8);
impl_wide!(f64x4, f64, 4);
impl_wide!(f64x8, f64, 8);

/// f64's lanes ([`Real::Wide`] of f64): 8 where the build's CPU has AVX-512 (one 512-bit
/// register; the 100,000-sphere trace 11 % faster than in 4 lanes), else 4 (8 lanes in two
/// halves cost 5-8 % with SSE2 and bought nothing sure with AVX2). docs/benchmarks.md, "f64
/// lanes". The images are the same bytes either way (the lanes compute the scalar bits; the
/// wide tree's answer is the binary tree's whatever its width).
#[cfg(target_feature = "avx512f")]
pub type F64Lanes = f64x8;
/// f64's lanes ([`Real::Wide`] of f64): see the AVX-512 build's note.
#[cfg(not(target_feature = "avx512f"))]
pub type F64Lanes = f64x4;

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
        // By zipped iterators, not indices: no bounds checks and no `Option` per lane (a
        // packet's two gathers were 210 instructions for 8 rays).
        let mut n = 0;
        for (((x, y), z), v) in xs.iter_mut().zip(ys.iter_mut()).zip(zs.iter_mut()).zip(vs) {
            (*x, *y, *z) = (v.x(), v.y(), v.z());
            n += 1;
        }
        for ((x, y), z) in xs[n..].iter_mut().zip(&mut ys[n..]).zip(&mut zs[n..]) {
            (*x, *y, *z) = (fill.x(), fill.y(), fill.z());
        }
        W3 {
            x: L::from_array(x),
            y: L::from_array(y),
            z: L::from_array(z),
        }
    }

    /// Lane k's vector.
    #[inline(always)]
    pub fn at(self, k: usize) -> V3<L::Scalar> {
        let (x, y, z) = (self.x.to_array(), self.y.to_array(), self.z.to_array());
        V3::<L::Scalar>::new(x.as_ref()[k], y.as_ref()[k], z.as_ref()[k])
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

    /// The mask of lanes whose three components are all finite: (x − x) + (y − y) + (z − z)
    /// is +0 exactly where they are, NaN where one is ±∞ or NaN.
    #[inline(always)]
    #[allow(clippy::eq_op)] // x − x is the test itself, not a slip.
    pub fn finite(self) -> L {
        let zero = L::splat(<L::Scalar as Real>::ZERO);
        ((self.x - self.x) + (self.y - self.y) + (self.z - self.z)).eq(zero)
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

/// A mask over [`Lanes`]: `bool` for one number, a lane mask (all bits set where true) for a
/// register. The core's gates are written with these, so one source serves both.
pub trait Mask: Copy + Debug {
    /// Both masks.
    fn both(self, o: Self) -> Self;
    /// Either mask.
    fn either(self, o: Self) -> Self;
    /// The complement.
    fn invert(self) -> Self;
    /// The set lanes as bits, lane 0 in bit 0.
    fn lane_bits(self) -> u32;
    /// Whether any lane is set: the scalar's own `if`, a register's "does any lane need it".
    #[inline(always)]
    fn any(self) -> bool {
        self.lane_bits() != 0
    }
}

impl Mask for bool {
    #[inline(always)]
    fn both(self, o: Self) -> Self {
        self && o
    }
    #[inline(always)]
    fn either(self, o: Self) -> Self {
        self || o
    }
    #[inline(always)]
    fn invert(self) -> Self {
        !self
    }
    #[inline(always)]
    fn lane_bits(self) -> u32 {
        u32::from(self)
    }
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
}

/// The numbers the core's arithmetic is written over once ([`crate::core::shade()`] and the
/// lights' arrival): one [`Real`] (its masks `bool`, its vectors glam's) or a register of
/// [`Wide`] lanes (its masks lane masks, its vectors `W3`). Every operation is the IEEE
/// operation of each lane in the order written, so a lane computes the scalar's bits; a step the
/// lanes cannot do to the bit (pow, atan2, the robust branches of a length) is done lane by lane
/// with the scalar code itself ([`Lanes::map_lanes`]), only on the lanes that need it.
pub trait Lanes:
    Copy + Debug + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// The precision of each lane.
    type Scalar: Real;
    /// The masks of the gates: `bool` or a lane mask.
    type Mask: Mask;
    /// A vector per lane: glam's `Vec3`/`DVec3` or `W3`.
    type V: LaneVec<Self>;
    /// How many lanes (1 for a scalar).
    const COUNT: usize;
    /// Every lane `x`.
    fn broadcast(x: Self::Scalar) -> Self;
    /// −x (the sign bit flipped).
    fn negated(self) -> Self;
    /// |x|.
    fn absolute(self) -> Self;
    /// √x, correctly rounded.
    fn root(self) -> Self;
    /// The mask of lanes where `self < o`.
    fn less(self, o: Self) -> Self::Mask;
    /// The mask of lanes where `self > o`.
    fn greater(self, o: Self) -> Self::Mask;
    /// The mask of lanes where `self == o`.
    fn equals(self, o: Self) -> Self::Mask;
    /// The mask of lanes where `self <= o`.
    fn at_most(self, o: Self) -> Self::Mask;
    /// The smaller of the two in each lane, as [`Real::min`] where neither is NaN nor are
    /// they two zeros (such a lane may give either).
    fn minimum(self, o: Self) -> Self;
    /// Per lane: the next number after `self` towards +∞ where `o > 0` ([`Real::next_up`]),
    /// towards −∞ where `o < 0` ([`Real::next_down`]), `self` where `o` is 0 or NaN: a
    /// coordinate rounded one step further the way its offset went.
    fn next_away(self, o: Self) -> Self;
    /// Per lane: `t` where `m` is set, `f` elsewhere.
    fn pick(m: Self::Mask, t: Self, f: Self) -> Self;
    /// Per lane: the mask `t` where `m` is set, `f` elsewhere.
    fn pick_mask(m: Self::Mask, t: Self::Mask, f: Self::Mask) -> Self::Mask;
    /// Every lane set.
    fn all_lanes() -> Self::Mask;
    /// Lane k (from 0).
    fn lane(self, k: usize) -> Self::Scalar;
    /// `f(k, lane k)` in each lane k set in `m`, the lane as it was elsewhere: the scalar code
    /// run lane by lane where the lanes cannot compute its bits.
    fn map_lanes(self, m: Self::Mask, f: impl FnMut(usize, Self::Scalar) -> Self::Scalar) -> Self;
}

/// A vector per lane of a [`Lanes`] type (glam's vector for a scalar, `W3` for a register):
/// component-wise IEEE operations in glam's order.
pub trait LaneVec<L: Lanes>: Copy + Debug {
    /// Every lane `v`.
    fn broadcast(v: V3<L::Scalar>) -> Self;
    /// The vector of three components.
    fn from_parts(x: L, y: L, z: L) -> Self;
    /// The three components.
    fn parts(self) -> (L, L, L);
    /// Lane k's vector.
    fn lane(self, k: usize) -> V3<L::Scalar>;
    /// Component-wise sum.
    #[inline(always)]
    fn plus(self, o: Self) -> Self {
        let ((a, b, c), (x, y, z)) = (self.parts(), o.parts());
        Self::from_parts(a + x, b + y, c + z)
    }
    /// Component-wise difference.
    #[inline(always)]
    fn minus(self, o: Self) -> Self {
        let ((a, b, c), (x, y, z)) = (self.parts(), o.parts());
        Self::from_parts(a - x, b - y, c - z)
    }
    /// Component-wise product (the chapter's product of colours).
    #[inline(always)]
    fn times(self, o: Self) -> Self {
        let ((a, b, c), (x, y, z)) = (self.parts(), o.parts());
        Self::from_parts(a * x, b * y, c * z)
    }
    /// Each component times `s`.
    #[inline(always)]
    fn scaled(self, s: L) -> Self {
        let (a, b, c) = self.parts();
        Self::from_parts(a * s, b * s, c * s)
    }
    /// Each component divided by `s`.
    #[inline(always)]
    fn divided(self, s: L) -> Self {
        let (a, b, c) = self.parts();
        Self::from_parts(a / s, b / s, c / s)
    }
    /// Each component negated.
    #[inline(always)]
    fn negated(self) -> Self {
        let (a, b, c) = self.parts();
        Self::from_parts(a.negated(), b.negated(), c.negated())
    }
    /// The dot product, summed as glam sums it: (x·x′ + y·y′) + z·z′.
    #[inline(always)]
    fn dot3(self, o: Self) -> L {
        let ((a, b, c), (x, y, z)) = (self.parts(), o.parts());
        a * x + b * y + c * z
    }
    /// Per lane: `t` where `m` is set, `f` elsewhere.
    #[inline(always)]
    fn pick3(m: L::Mask, t: Self, f: Self) -> Self {
        let ((a, b, c), (x, y, z)) = (t.parts(), f.parts());
        Self::from_parts(L::pick(m, a, x), L::pick(m, b, y), L::pick(m, c, z))
    }
    /// Each component's absolute value.
    #[inline(always)]
    fn absolute(self) -> Self {
        let (a, b, c) = self.parts();
        Self::from_parts(a.absolute(), b.absolute(), c.absolute())
    }
    /// The mask of lanes where every component is 0 (either sign).
    #[inline(always)]
    fn zero_mask(self) -> L::Mask {
        let zero = L::broadcast(<L::Scalar as Real>::ZERO);
        let (a, b, c) = self.parts();
        a.equals(zero).both(b.equals(zero)).both(c.equals(zero))
    }
    /// `f(k, lane k's vector)` in each lane k set in `m`, the lane as it was elsewhere.
    fn map_lanes(self, m: L::Mask, f: impl FnMut(usize, V3<L::Scalar>) -> V3<L::Scalar>) -> Self;
}

/// One number is one lane: the scalar instantiation of the core's arithmetic.
impl<R: Real> Lanes for R {
    type Scalar = R;
    type Mask = bool;
    type V = V3<R>;
    const COUNT: usize = 1;
    #[inline(always)]
    fn broadcast(x: R) -> Self {
        x
    }
    #[inline(always)]
    fn negated(self) -> Self {
        -self
    }
    #[inline(always)]
    fn absolute(self) -> Self {
        Real::abs(self)
    }
    #[inline(always)]
    fn root(self) -> Self {
        Real::sqrt(self)
    }
    #[inline(always)]
    fn less(self, o: Self) -> bool {
        self < o
    }
    #[inline(always)]
    fn greater(self, o: Self) -> bool {
        self > o
    }
    #[inline(always)]
    fn equals(self, o: Self) -> bool {
        self == o
    }
    #[inline(always)]
    fn at_most(self, o: Self) -> bool {
        self <= o
    }
    #[inline(always)]
    fn minimum(self, o: Self) -> Self {
        Real::min(self, o)
    }
    #[inline(always)]
    fn next_away(self, o: Self) -> Self {
        if o > R::ZERO {
            self.next_up()
        } else if o < R::ZERO {
            self.next_down()
        } else {
            self
        }
    }
    #[inline(always)]
    fn pick(m: bool, t: Self, f: Self) -> Self {
        if m {
            t
        } else {
            f
        }
    }
    #[inline(always)]
    fn pick_mask(m: bool, t: bool, f: bool) -> bool {
        if m {
            t
        } else {
            f
        }
    }
    #[inline(always)]
    fn all_lanes() -> bool {
        true
    }
    #[inline(always)]
    fn lane(self, _: usize) -> R {
        self
    }
    #[inline(always)]
    fn map_lanes(self, m: bool, mut f: impl FnMut(usize, R) -> R) -> Self {
        if m {
            f(0, self)
        } else {
            self
        }
    }
}

macro_rules! impl_lane_vec_scalar {
    ($v:ty, $s:ty) => {
        impl LaneVec<$s> for $v {
            #[inline(always)]
            fn broadcast(v: $v) -> Self {
                v
            }
            #[inline(always)]
            fn from_parts(x: $s, y: $s, z: $s) -> Self {
                <$v>::new(x, y, z)
            }
            #[inline(always)]
            fn parts(self) -> ($s, $s, $s) {
                (self.x, self.y, self.z)
            }
            #[inline(always)]
            fn lane(self, _: usize) -> $v {
                self
            }
            #[inline(always)]
            fn pick3(m: bool, t: Self, f: Self) -> Self {
                if m {
                    t
                } else {
                    f
                }
            }

            #[inline(always)]
            fn map_lanes(self, m: bool, mut f: impl FnMut(usize, $v) -> $v) -> Self {
                if m {
                    f(0, self)
                } else {
                    self
                }
            }
        }
    };
}

impl_lane_vec_scalar!(glam::Vec3A, f32);
impl_lane_vec_scalar!(glam::DVec3, f64);

macro_rules! impl_lanes_wide {
    ($w:ty, $s:ty, $i:ty) => {
        impl Mask for $w {
            #[inline(always)]
            fn both(self, o: Self) -> Self {
                self & o
            }
            #[inline(always)]
            fn either(self, o: Self) -> Self {
                self | o
            }
            #[inline(always)]
            fn invert(self) -> Self {
                !self
            }
            #[inline(always)]
            fn lane_bits(self) -> u32 {
                self.to_bitmask() as u32
            }
        }

        impl Lanes for $w {
            type Scalar = $s;
            type Mask = $w;
            type V = W3<$w>;
            const COUNT: usize = <$w as Wide>::LANES;
            #[inline(always)]
            fn broadcast(x: $s) -> Self {
                <$w>::splat(x)
            }
            #[inline(always)]
            fn negated(self) -> Self {
                Wide::neg(self)
            }
            #[inline(always)]
            fn absolute(self) -> Self {
                <$w>::abs(self)
            }
            #[inline(always)]
            fn root(self) -> Self {
                Wide::sqrt(self)
            }
            #[inline(always)]
            fn less(self, o: Self) -> Self {
                Wide::lt(self, o)
            }
            #[inline(always)]
            fn greater(self, o: Self) -> Self {
                Wide::gt(self, o)
            }
            #[inline(always)]
            fn equals(self, o: Self) -> Self {
                Wide::eq(self, o)
            }
            #[inline(always)]
            fn at_most(self, o: Self) -> Self {
                self.simd_le(o)
            }
            #[inline(always)]
            fn minimum(self, o: Self) -> Self {
                <$w>::fast_min(self, o)
            }
            #[inline(always)]
            fn next_away(self, o: Self) -> Self {
                // On the bits: a finite non-zero number one step further from 0 is its bits + 1,
                // one step nearer 0 its bits − 1 (−TINY → −0, MAX → ∞, as next_up and next_down
                // give); a mask lane is all ones, −1 as an integer. Zeros (whose next number
                // has the other sign's bits) and infinities or NaNs, where a step is asked, take
                // the scalar's next_up/next_down lane by lane.
                let zero = <$w>::splat(0.0);
                let (up, down) = (Wide::gt(o, zero), Wide::lt(o, zero));
                let (pos, neg) = (Wide::gt(self, zero), Wide::lt(self, zero));
                let away = (up & pos) | (down & neg);
                let nearer = (up & neg) | (down & pos);
                let bits: $i = bytemuck::cast(self);
                let stepped: $w = bytemuck::cast(
                    bits - bytemuck::cast::<$w, $i>(away) + bytemuck::cast::<$w, $i>(nearer),
                );
                let odd = (up | down) & !(Wide::finite(self) & (pos | neg));
                let stepped = <$w>::select(odd, self, stepped);
                stepped.map_lanes(odd, |k, x| {
                    if o.to_array()[k] > 0.0 {
                        x.next_up()
                    } else {
                        x.next_down()
                    }
                })
            }
            #[inline(always)]
            fn pick(m: Self, t: Self, f: Self) -> Self {
                <$w>::select(m, t, f)
            }
            #[inline(always)]
            fn pick_mask(m: Self, t: Self, f: Self) -> Self {
                <$w>::select(m, t, f)
            }
            #[inline(always)]
            fn all_lanes() -> Self {
                Wide::eq(<$w>::splat(0.0), <$w>::splat(0.0))
            }
            #[inline(always)]
            fn lane(self, k: usize) -> $s {
                self.to_array()[k]
            }
            #[inline(always)]
            fn map_lanes(self, m: Self, mut f: impl FnMut(usize, $s) -> $s) -> Self {
                let bits = m.lane_bits();
                if bits == 0 {
                    return self;
                }
                let mut a = self.to_array();
                for k in lanes_of(bits) {
                    a[k] = f(k, a[k]);
                }
                <$w>::new(a)
            }
        }

        impl LaneVec<$w> for W3<$w> {
            #[inline(always)]
            fn broadcast(v: V3<$s>) -> Self {
                W3::splat(v)
            }
            #[inline(always)]
            fn from_parts(x: $w, y: $w, z: $w) -> Self {
                W3 { x, y, z }
            }
            #[inline(always)]
            fn parts(self) -> ($w, $w, $w) {
                (self.x, self.y, self.z)
            }
            #[inline(always)]
            fn lane(self, k: usize) -> V3<$s> {
                V3::<$s>::new(
                    self.x.to_array()[k],
                    self.y.to_array()[k],
                    self.z.to_array()[k],
                )
            }
            #[inline(always)]
            fn map_lanes(self, m: $w, mut f: impl FnMut(usize, V3<$s>) -> V3<$s>) -> Self {
                let bits = m.lane_bits();
                if bits == 0 {
                    return self;
                }
                let (mut x, mut y, mut z) =
                    (self.x.to_array(), self.y.to_array(), self.z.to_array());
                for k in lanes_of(bits) {
                    let v = f(k, V3::<$s>::new(x[k], y[k], z[k]));
                    (x[k], y[k], z[k]) = (v.x, v.y, v.z);
                }
                W3 {
                    x: <$w>::new(x),
                    y: <$w>::new(y),
                    z: <$w>::new(z),
                }
            }
        }
    };
}

impl_lanes_wide!(f32x8, f32, wide::i32x8);
impl_lanes_wide!(f64x4, f64, wide::i64x4);
impl_lanes_wide!(f64x8, f64, wide::i64x8);

/// The lane mask with lane k set where bit k of `bits` is.
#[inline(always)]
pub(crate) fn mask_of<L: Wide>(bits: u32) -> L {
    let mut a = L::Array::default();
    for (k, x) in a.as_mut().iter_mut().enumerate() {
        *x = if bits & (1 << k) != 0 {
            <L::Scalar as Real>::ONE
        } else {
            <L::Scalar as Real>::ZERO
        };
    }
    L::from_array(a).gt(L::splat(<L::Scalar as Real>::ZERO))
}

/// The set lanes of a mask's bits, lowest first.
#[inline(always)]
pub(crate) fn lanes_of(mut bits: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (bits != 0).then(|| {
            let k = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            k
        })
    })
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

    /// Numbers where a step on the bits goes wrong if done naively: zeros of both signs, the
    /// smallest subnormals, the largest finite numbers, infinities, NaN, and ordinary ones.
    fn awkward<R: Real>() -> Vec<R> {
        let tiny = R::from_f64(f64::from(f32::from_bits(1)));
        let tiny = if R::NAME == "f64" {
            R::from_f64(f64::from_bits(1))
        } else {
            tiny
        };
        let max = if R::NAME == "f64" {
            R::from_f64(f64::MAX)
        } else {
            R::from_f64(f64::from(f32::MAX))
        };
        let mut xs = vec![
            R::ZERO,
            -R::ZERO,
            tiny,
            -tiny,
            max,
            -max,
            R::from_f64(f64::INFINITY),
            R::from_f64(f64::NEG_INFINITY),
            R::from_f64(f64::NAN),
            R::ONE,
            -R::ONE,
            R::EPSILON,
        ];
        xs.extend(
            (0..40).map(|i| R::from_f64((f64::from(i) - 19.5) * 0.37e-3 * 10f64.powi(i % 7))),
        );
        xs
    }

    /// `next_away` in lanes is the scalar's next_up / next_down / identity to the bit, for
    /// every pairing of an awkward number and an offset's sign (0, ±0, NaN included).
    fn next_away_in_lanes_is_the_scalar_step<R: Real>() {
        let xs = awkward::<R>();
        let offsets = [
            R::ONE,
            -R::ONE,
            R::ZERO,
            -R::ZERO,
            R::from_f64(f64::NAN),
            R::from_f64(1e-30),
        ];
        let lanes = W::<R>::LANES;
        let bits = |x: R| x.to_f64().to_bits();
        let mut stepped = 0;
        for o in offsets {
            for group in xs.chunks(lanes) {
                let mut a = <W<R> as Wide>::Array::default();
                for (k, x) in group.iter().enumerate() {
                    a.as_mut()[k] = *x;
                }
                let got = Lanes::next_away(W::<R>::from_array(a), W::<R>::splat(o)).to_array();
                for (k, &x) in group.iter().enumerate() {
                    let want = if o > R::ZERO {
                        x.next_up()
                    } else if o < R::ZERO {
                        x.next_down()
                    } else {
                        x
                    };
                    let g = got.as_ref()[k];
                    if want.to_f64().is_nan() {
                        assert!(g.to_f64().is_nan(), "{x:?} by {o:?}");
                    } else {
                        assert_eq!(bits(g), bits(want), "{x:?} by {o:?}: {g:?}, not {want:?}");
                    }
                    stepped += usize::from(bits(want) != bits(x));
                }
            }
        }
        assert!(stepped > xs.len(), "the cases step: {stepped}");
    }

    /// Repeated squaring over lanes gives each lane the scalar `Real::powi`'s bits, and the
    /// scalar one gives the platform's `powi` (compiler-rt's `__powi?f2`, the same algorithm).
    fn powi_in_lanes_is_the_scalar_powi<R: Real>() {
        let xs = awkward::<R>();
        let lanes = W::<R>::LANES;
        let bits = |x: R| x.to_f64().to_bits();
        for n in (-40..=40).chain([-1024, -1000, 255, 256, 511, 1000, 1024]) {
            for group in xs.chunks(lanes) {
                let mut a = <W<R> as Wide>::Array::default();
                for (k, x) in group.iter().enumerate() {
                    a.as_mut()[k] = *x;
                }
                let one = W::<R>::splat(R::ONE);
                let got = crate::core::real::powi_by_squaring(W::<R>::from_array(a), one, n);
                for (k, &x) in group.iter().enumerate() {
                    let want = x.powi(n);
                    let g = got.to_array().as_ref()[k];
                    let platform = if R::NAME == "f64" {
                        x.to_f64().powi(n)
                    } else {
                        f64::from((x.to_f64() as f32).powi(n))
                    };
                    if want.to_f64().is_nan() {
                        assert!(g.to_f64().is_nan() && platform.is_nan(), "{x:?}^{n}");
                    } else {
                        assert_eq!(bits(g), bits(want), "{x:?}^{n} in lanes");
                        assert_eq!(bits(want), platform.to_bits(), "{x:?}^{n} against powi");
                    }
                }
            }
        }
    }

    /// `finite` in lanes (one register, and a vector's three) is the scalar `is_finite` of
    /// every awkward number: ±∞ and NaN out, the largest finite numbers and subnormals in.
    fn finite_in_lanes_is_the_scalar_test<R: Real>() {
        let xs = awkward::<R>();
        let lanes = W::<R>::LANES;
        for group in xs.chunks(lanes) {
            let mut a = <W<R> as Wide>::Array::default();
            a.as_mut()[..group.len()].copy_from_slice(group);
            let w = W::<R>::from_array(a);
            let got = w.finite().bits();
            for (k, &x) in group.iter().enumerate() {
                assert_eq!(got & (1 << k) != 0, x.is_finite(), "{x:?}");
            }
            // Each awkward number in turn as the x, y and z of an otherwise ordinary vector.
            let one = W::<R>::splat(R::ONE);
            for v in [
                W3 {
                    x: w,
                    y: one,
                    z: one,
                },
                W3 {
                    x: one,
                    y: w,
                    z: one,
                },
                W3 {
                    x: one,
                    y: one,
                    z: w,
                },
            ] {
                let got = v.finite().bits();
                for (k, &x) in group.iter().enumerate() {
                    assert_eq!(got & (1 << k) != 0, x.is_finite(), "{x:?} in a vector");
                }
            }
        }
    }

    #[test]
    fn finite_in_lanes_in_both_precisions() {
        finite_in_lanes_is_the_scalar_test::<f32>();
        finite_in_lanes_is_the_scalar_test::<f64>();
    }

    #[test]
    fn next_away_and_powi_in_lanes_in_both_precisions() {
        next_away_in_lanes_is_the_scalar_step::<f32>();
        next_away_in_lanes_is_the_scalar_step::<f64>();
        powi_in_lanes_is_the_scalar_powi::<f32>();
        powi_in_lanes_is_the_scalar_powi::<f64>();
    }
}
