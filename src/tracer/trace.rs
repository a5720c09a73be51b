//! One ray's path through the scene, Section 4.4. A Whitted tracer with reflection only follows
//! a single path: the primary ray, then at each hit at most one reflection ray. Its colour is
//! C = C_local,1 + O_r,1 (C_local,2 + O_r,2 (…)), accumulated front to back as
//! Σ_k (O_r,1 ⋯ O_r,k−1) C_local,k, so no recursion and no allocation; the explanation shows
//! each ray's factor and share.
//!
//! The local colour of every hit is the core's [`shade`], with the core's gating, given the
//! hit's shadow rays ([`crate::geometry::SurfaceHit::shadow_rays`]); the normal facing the ray
//! and the reflection ray's origin are the hit's too, as in the solver's ray problems.

use crate::core::vector::normalize;
use crate::core::{shade, Material, NoRecord, Real, ShadingPoint, Vector, V3};
use crate::geometry::{Aggregate, AggregateHit, Ray, SurfaceHit};
use crate::problem::Problem;

/// The geometry and materials of a scene, built once for a render.
pub struct Scene<R: Real> {
    /// Every surface, in a BVH (planes apart): what rays and shadow rays ask for hits.
    pub aggregate: Aggregate<R>,
    /// The material of each surface, by index (a mesh's triangles each have their mesh's).
    pub materials: Vec<Material<R>>,
}

impl<R: Real> Scene<R> {
    /// The problem's surfaces, in a BVH.
    pub fn new(problem: &Problem<R>) -> Self {
        Scene {
            aggregate: crate::solve::aggregate(problem),
            materials: problem
                .surfaces()
                .iter()
                .map(|s| s.material.material)
                .collect(),
        }
    }
}

/// Why a path ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The ray hit nothing: its colour is the background.
    Miss,
    /// The surface has no reflectivity (O_r absent or zero): no reflection ray.
    NotReflective,
    /// The reflection ray's level would exceed the maximum level.
    MaxLevel,
    /// The reflection ray's weight w_s = w_p·max(O_r) would not exceed the minimum weight.
    MinWeight,
}

/// How many rays of each kind were traced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Counts {
    /// Primary rays, one per sample.
    pub primary: u64,
    /// Reflection rays (Eq. 4.17).
    pub reflection: u64,
    /// Shadow rays, from hit points to lights.
    pub shadow: u64,
}

impl Counts {
    /// Every ray traced, of all three kinds.
    pub fn total(&self) -> u64 {
        self.primary + self.reflection + self.shadow
    }
}

impl std::ops::AddAssign for Counts {
    fn add_assign(&mut self, o: Counts) {
        self.primary += o.primary;
        self.reflection += o.reflection;
        self.shadow += o.shadow;
    }
}

/// Where a secondary ray left from: the hit point, its error bound, the surface's own normal,
/// and the offset origin (pbrt's `OffsetRayOrigin`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spawn<R: Real> {
    /// The hit point it leaves.
    pub from: V3<R>,
    /// The bound on the error of each component of that point.
    pub p_error: V3<R>,
    /// The surface's own normal there (not turned to face the ray).
    pub normal: V3<R>,
    /// The ray's origin: the point offset along the normal by its error bound, rounded outward.
    pub origin: V3<R>,
}

/// One ray of a path, as the explanation shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayRecord<R: Real> {
    /// 1 for the primary ray.
    pub level: u32,
    /// w: 1 for the primary ray, w_p·max(O_r) for a reflection ray.
    pub weight: R,
    /// The product of the O_r of the hits before this ray: its colour's factor in the pixel.
    pub factor: V3<R>,
    /// The ray itself (unit direction).
    pub ray: Ray<R>,
    /// For a reflection ray, where it left from.
    pub spawn: Option<Spawn<R>>,
    /// The nearest hit with t > 0; `None` on a miss.
    pub hit: Option<AggregateHit<R>>,
    /// The local colour (Eq. 4.16) at the hit, or the background on a miss.
    pub local: V3<R>,
    /// O_r at the hit, when the material has one.
    pub o_r: Option<V3<R>>,
    /// The weight a reflection ray would have, when there is one to weigh.
    pub next_weight: Option<R>,
    /// Why the path ended here, or `None` when a reflection ray follows.
    pub stop: Option<Stop>,
}

/// Receives each ray of a path; the hot path passes `()`, which records nothing.
pub trait PathRecorder<R: Real> {
    /// Whether the records are kept: when not, the tracer does not gather what only a record
    /// shows (where a reflection ray left from).
    const RECORDS: bool = true;

    /// Receives one ray's record, in path order.
    fn ray(&mut self, record: &RayRecord<R>);
}

impl<R: Real> PathRecorder<R> for () {
    const RECORDS: bool = false;

    #[inline(always)]
    fn ray(&mut self, _: &RayRecord<R>) {}
}

impl<R: Real> PathRecorder<R> for Vec<RayRecord<R>> {
    fn ray(&mut self, record: &RayRecord<R>) {
        self.push(*record);
    }
}

/// Traces paths through a scene with a problem's lights and render settings.
pub struct Tracer<'a, R: Real> {
    /// The surfaces and their materials.
    pub scene: &'a Scene<R>,
    /// The lights, the background and the render settings.
    pub problem: &'a Problem<R>,
}

/// Where a path stands between two bounces: the ray to trace next and what it carries. The
/// scalar [`Tracer::trace`] keeps one; the wide tracer keeps a queue of them per bounce
/// (`tracer::wide`), both stepping them with [`Tracer::step`]. Where a reflection ray left
/// from ([`Spawn`]) is not carried: only a record shows it, and [`Tracer::trace`] keeps it
/// beside the path when its recorder records.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PathState<R: Real> {
    /// The ray to trace next.
    pub ray: Ray<R>,
    /// The product of the O_r of the hits before this ray.
    pub factor: V3<R>,
    /// w: 1 for the primary ray, w_p·max(O_r) for a reflection ray.
    pub weight: R,
    /// 1 for the primary ray.
    pub level: u32,
}

impl<R: Real> PathState<R> {
    /// A path at its primary ray.
    #[inline]
    pub(crate) fn primary(ray: Ray<R>) -> Self {
        PathState {
            ray,
            factor: V3::<R>::splat(R::ONE),
            weight: R::ONE,
            level: 1,
        }
    }
}

/// A hit's shadow rays as the core asks them ([`crate::core::Visibility`]), and how many were
/// traced.
pub(crate) trait CountedVisibility<R: Real>: crate::core::Visibility<R> {
    /// The shadow rays traced so far.
    fn traced(&self) -> u64;
}

impl<R: Real> CountedVisibility<R> for crate::geometry::shadow::ShadowRays<'_, R> {
    #[inline]
    fn traced(&self) -> u64 {
        self.traced
    }
}

impl<R: Real> Tracer<'_, R> {
    /// The colour seen along a primary ray, unclamped.
    #[inline]
    pub fn trace<P: PathRecorder<R>>(
        &self,
        primary: Ray<R>,
        counts: &mut Counts,
        rec: &mut P,
    ) -> V3<R> {
        let infinity = R::from_f64(f64::INFINITY);
        let aggregate = &self.scene.aggregate;
        let mut color = V3::<R>::ZERO;
        let mut path = PathState::primary(primary);
        // Where the current ray left from, for the record (a reflection ray's only).
        let mut spawn = None;
        counts.primary += 1;
        loop {
            // The nearest hit in front of the origin; a miss sees the background.
            let found = aggregate.nearest(&path.ray, infinity);
            let (share, more) = self.bounce(
                &mut path,
                spawn,
                found,
                |h| h.shadow_rays(aggregate),
                counts,
                rec,
            );
            color += share;
            if !more {
                return color;
            }
            if P::RECORDS {
                spawn = found.map(|h| Spawn {
                    from: h.hit.p,
                    p_error: h.hit.p_error,
                    normal: h.hit.normal,
                    origin: path.ray.origin,
                });
            }
        }
    }

    /// One step of a path whose ray found `found` (its nearest hit, or a miss): the ray's share
    /// of the pixel (the factor times the local colour, or times the background on a miss), and
    /// whether a reflection ray follows, in which case `path` now holds it. `shadows` makes the
    /// hit's shadow rays (asked only with shadows on). `spawn` is where the ray left from, for
    /// the record.
    #[inline]
    pub(crate) fn bounce<V: CountedVisibility<R>>(
        &self,
        path: &mut PathState<R>,
        spawn: Option<Spawn<R>>,
        found: Option<AggregateHit<R>>,
        shadows: impl FnOnce(&SurfaceHit<R>) -> V,
        counts: &mut Counts,
        rec: &mut impl PathRecorder<R>,
    ) -> (V3<R>, bool) {
        let Some(h) = found else {
            return self.miss(path, spawn, rec);
        };
        let m = &self.scene.materials[h.index];
        // N turned to face the incoming ray; V is the ray's direction (Eq. 4.10).
        let n = h.hit.facing(path.ray.direction).normal;
        let at = ShadingPoint {
            p: h.hit.p,
            n,
            v: Some(path.ray.direction),
        };
        // The local colour, Eq. 4.16, by the core.
        let mut shadows = self.problem.render.shadows.then(|| shadows(&h.hit));
        let local = shade(&at, m, &self.problem.lights, &mut shadows, &mut NoRecord).color;
        counts.shadow += shadows.as_ref().map_or(0, |s| s.traced());
        self.step(path, spawn, &h, (n, local), counts, rec)
    }

    /// The step of a path whose ray missed: its share is the factor times the background.
    /// `spawn` is where the ray left from, for the record.
    #[inline]
    pub(crate) fn miss(
        &self,
        path: &PathState<R>,
        spawn: Option<Spawn<R>>,
        rec: &mut impl PathRecorder<R>,
    ) -> (V3<R>, bool) {
        rec.ray(&RayRecord {
            level: path.level,
            weight: path.weight,
            factor: path.factor,
            ray: path.ray,
            spawn,
            hit: None,
            local: self.problem.background,
            o_r: None,
            next_weight: None,
            stop: Some(Stop::Miss),
        });
        (path.factor * self.problem.background, false)
    }

    /// The rest of [`Tracer::bounce`] once the hit `h` is shaded (`shaded`: the normal facing
    /// the ray and the core's colour there), for both engines: the ray's share, the stop
    /// rules and the reflection ray. `spawn` is where the ray left from, for the record.
    #[inline]
    pub(crate) fn step(
        &self,
        path: &mut PathState<R>,
        spawn: Option<Spawn<R>>,
        h: &AggregateHit<R>,
        shaded: (V3<R>, V3<R>),
        counts: &mut Counts,
        rec: &mut impl PathRecorder<R>,
    ) -> (V3<R>, bool) {
        let (n, local) = shaded;
        let PathState {
            ray,
            factor,
            weight,
            level,
        } = *path;
        let m = &self.scene.materials[h.index];
        let share = factor * local;
        let mut record = RayRecord {
            level,
            weight,
            factor,
            ray,
            spawn,
            hit: Some(*h),
            local,
            o_r: m.o_r,
            next_weight: None,
            stop: None,
        };
        // A reflection ray only where O_r ≠ 0, its level ≤ the maximum and its weight
        // w_s = w_p·max(O_r) above the minimum (docs/conventions.md, "Recursion level",
        // "Weight").
        record.stop = match m.o_r {
            None => Some(Stop::NotReflective),
            Some(o_r) if o_r == V3::<R>::ZERO => Some(Stop::NotReflective),
            Some(o_r) => {
                let w_s = weight * o_r.max_element();
                record.next_weight = Some(w_s);
                if level >= self.problem.render.max_level {
                    Some(Stop::MaxLevel)
                } else if w_s <= self.problem.render.min_weight {
                    Some(Stop::MinWeight)
                } else {
                    None
                }
            }
        };
        rec.ray(&record);
        if record.stop.is_some() {
            return (share, false);
        }
        let o_r = m.o_r.expect("a reflection ray needs O_r");
        // The reflection direction R_V = V − 2(N·V)N, Eq. 4.17.
        let r_v = ray.direction - n * (R::TWO * n.dot(ray.direction));
        let Some(r_v) = normalize::<R>(r_v) else {
            return (share, false);
        };
        let next = h.hit.spawn_ray(r_v.unit);
        *path = PathState {
            ray: next,
            factor: factor * o_r,
            weight: weight * o_r.max_element(),
            level: level + 1,
        };
        counts.reflection += 1;
        (share, true)
    }
}
