//! A ray: an origin and a unit direction.

use crate::core::lanes::{W, W3};
use crate::core::{Real, V3};

/// A ray O + tD with a unit direction D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<R: Real> {
    /// O, where the ray starts.
    pub origin: V3<R>,
    /// Unit length.
    pub direction: V3<R>,
}

impl<R: Real> Ray<R> {
    /// The point O + tD.
    #[inline]
    pub(crate) fn at(&self, t: R) -> V3<R> {
        self.origin + self.direction * t
    }
}

/// A packet of rays in lanes: the origins and the directions, lane k holding ray k.
pub(crate) type RayLanes<R> = (W3<W<R>>, W3<W<R>>);

/// Ray k of a packet in lanes, as its lanes hold it.
#[inline(always)]
pub(crate) fn lane_ray<R: Real>((o, d): RayLanes<R>, k: usize) -> Ray<R> {
    Ray {
        origin: o.at(k),
        direction: d.at(k),
    }
}
