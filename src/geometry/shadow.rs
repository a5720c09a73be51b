//! The shadow rays from a hit, as the core's [`Visibility`]: built by
//! [`SurfaceHit::shadow_rays`] for the tracer and for the solver's ray problems alike, so a
//! pixel and the equivalent ray problem see the same lights.

use super::aggregate::Aggregate;
use super::hit::SurfaceHit;
use super::Ray;
use crate::core::rounding::gamma;
use crate::core::vector::between;
use crate::core::{Arrival, Light, Real, Visibility, V3};

/// Shadow rays from a hit point: each one leaves from the hit's offset origin towards the light
/// ([`SurfaceHit::spawn_origin`]); to a point or spot light it stops a relative hair short of
/// the light (pbrt's `1 − ShadowEpsilon`), to a directional light it goes on for ever.
pub struct ShadowRays<'a, R: Real> {
    pub aggregate: &'a Aggregate<R>,
    /// The hit the rays leave from: its point, error bound and own normal.
    pub from: SurfaceHit<R>,
    /// How many shadow rays were traced.
    pub traced: u64,
}

/// One shadow ray and how far it may go before it reaches its light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowRay<R: Real> {
    pub ray: Ray<R>,
    pub t_max: R,
}

impl<R: Real> ShadowRays<'_, R> {
    /// The shadow ray towards a light whose L (light to point) is `l`; `None` when the light is
    /// too close to the point to be told apart.
    pub(crate) fn ray(&self, light: &Light<R>, l: V3<R>) -> Option<ShadowRay<R>> {
        let towards = -l;
        match light.position() {
            None => Some(ShadowRay {
                ray: self.from.spawn_ray(towards),
                t_max: R::from_f64(f64::INFINITY),
            }),
            Some(pos) => {
                let origin = self.from.spawn_origin(towards);
                let to_light = between::<R>(origin, pos)?;
                Some(ShadowRay {
                    ray: Ray {
                        origin,
                        direction: to_light.unit,
                    },
                    t_max: to_light.length * (R::ONE - gamma::<R>(64)),
                })
            }
        }
    }
}

impl<R: Real> Visibility<R> for ShadowRays<'_, R> {
    /// `p` is the point the core shades, the hit's own.
    #[inline]
    fn visible(&mut self, p: V3<R>, light: &Light<R>, arrival: &Arrival<R>) -> bool {
        debug_assert!(
            p == self.from.p,
            "shadow rays from {:?}, not {p:?}",
            self.from.p
        );
        self.traced += 1;
        match self.ray(light, arrival.l) {
            Some(s) => !self.aggregate.occluded(&s.ray, s.t_max),
            None => true,
        }
    }
}
