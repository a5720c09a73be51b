//! A ray's hit on a surface, with the error bound of the computed point, and the origin of a
//! ray spawned from it (pbrt-v4's `OffsetRayOrigin`): offset along the geometric normal by the
//! error bound, so a secondary or shadow ray never re-hits the surface it leaves, at any scale,
//! without a global epsilon.

pub(crate) use super::bounds::gamma;
use crate::core::{Real, Vector, V3};

/// Where a ray meets a surface (t > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit<R: Real> {
    /// The ray parameter.
    pub t: R,
    /// The hit point, computed the surface's most accurate way (re-projected onto a sphere,
    /// interpolated from a triangle's corners).
    pub p: V3<R>,
    /// A bound on the absolute error of each component of `p`.
    pub p_error: V3<R>,
    /// The surface's own unit normal at `p` (a plane's as given, a sphere's outward, a
    /// triangle's (v1 − v0) × (v2 − v0)); turning it to face the ray is the caller's choice.
    pub normal: V3<R>,
}

/// The origin of a ray leaving `p` in direction `w`: `p` moved off the surface along `n`, to the
/// side `w` goes, by the distance |n|·p_error that the error box of `p` can reach along `n`, each
/// component then rounded one step further away.
#[inline]
pub fn offset_origin<R: Real>(p: V3<R>, p_error: V3<R>, n: V3<R>, w: V3<R>) -> V3<R> {
    let d = n.abs().dot(p_error);
    let mut offset = n * d;
    if w.dot(n) < R::ZERO {
        offset = -offset;
    }
    let po = p + offset;
    // Round away from p so that the rounding of the sum cannot undo the offset.
    let away = |x: R, o: R| {
        if o > R::ZERO {
            x.next_up()
        } else if o < R::ZERO {
            x.next_down()
        } else {
            x
        }
    };
    let (o, q) = (offset.to_array(), po.to_array());
    V3::<R>::new(away(q[0], o[0]), away(q[1], o[1]), away(q[2], o[2]))
}
