//! One ray's tree through the scene, Section 4.4. At each hit a Whitted tracer spawns at most
//! a reflection ray (Eq. 4.17, where O_r ≠ 0) and a transmission ray ("idem para a transmissão
//! ou refração, se considerada": where O_t ≠ 0, bent by Snell's law; docs/conventions.md,
//! "Transmission"). A ray's colour is C = C_local + O_r C_r + O_t C_t; unrolled, the pixel's
//! colour is Σ factor·C_local over the tree's rays, each ray's factor the product of the O_r
//! and O_t on its way from the primary ray. The rays are taken breadth first, reflection before
//! transmission at each hit: the order in which the wide tracer's queues take them, so that both
//! add the same shares in the same order. Where nothing transmits the tree is a chain and is
//! traced with no queue and no allocation.
//!
//! The local colour of every hit is the core's [`shade()`], with the core's gating, given the
//! hit's shadow rays ([`crate::geometry::SurfaceHit::shadow_rays`]); the normal facing the ray
//! and the secondary rays' origins are the hit's too, as in the solver's ray problems.

use std::collections::VecDeque;

use crate::core::vector::normalize;
use crate::core::{shade, Material, NoRecord, Real, ShadingPoint, Transmission, Vector, V3};
use crate::geometry::{Aggregate, AggregateHit, Ray, SurfaceHit};
use crate::problem::Problem;

/// The geometry and materials of a scene, built once for a render.
pub struct Scene<R: Real> {
    /// Every surface, in a BVH (planes apart): what rays and shadow rays ask for hits.
    pub aggregate: Aggregate<R>,
    /// The material of surface i is `materials[material_of[i]]` (a mesh's triangles each
    /// have their mesh's): a scene of 100,000 spheres holds a handful of materials, not
    /// 100,000 copies.
    pub material_of: Vec<u32>,
    /// The distinct materials (equal to the bit in every field), in order of first appearance.
    pub materials: Vec<Material<R>>,
}

impl<R: Real> Scene<R> {
    /// The problem's surfaces, in a BVH.
    pub fn new(problem: &Problem<R>) -> Self {
        let (material_of, materials) = distinct(
            problem.surfaces().iter().map(|s| &*s.material.material),
            material_bits,
        );
        Scene {
            aggregate: crate::solve::aggregate(problem),
            material_of,
            materials,
        }
    }

    /// The material of surface `index`.
    #[inline]
    pub fn material(&self, index: usize) -> &Material<R> {
        &self.materials[self.material_of[index] as usize]
    }
}

/// Every field of a material by its bits (O_a, O_d, O_s, n_s, O_r, O_t, η; 1 where an
/// optional one is present): materials with the same key compute the same bits.
fn material_bits<R: Real>(m: &Material<R>) -> [u64; 22] {
    let mut k = [0u64; 22];
    let mut put = |i: usize, v: Option<V3<R>>| {
        if let Some(v) = v {
            k[i] = 1;
            for (j, c) in v.to_array().iter().enumerate() {
                k[i + 1 + j] = c.to_f64().to_bits();
            }
        }
    };
    put(0, m.o_a);
    put(4, m.o_d);
    put(8, m.o_s);
    put(12, m.o_r);
    put(16, m.transmission.map(|t| t.o_t));
    k[20] = m.n_s.to_f64().to_bits();
    k[21] = m.transmission.map_or(0, |t| t.eta.to_f64().to_bits());
    k
}

/// Each item as an index into the distinct ones (equal keys), and the distinct ones in order
/// of first appearance. A scene has a handful of distinct materials (a mesh's triangles repeat
/// their own), most shared by many surfaces: an item met before at the same address first (no
/// key computed), then the previous item's key, then a look along the few found, a map past 16.
pub(crate) fn distinct<'a, T: Copy + 'a, K: Copy + Eq + std::hash::Hash>(
    all: impl ExactSizeIterator<Item = &'a T>,
    key: impl Fn(&T) -> K,
) -> (Vec<u32>, Vec<T>) {
    let mut items: Vec<T> = Vec::new();
    let mut keys: Vec<K> = Vec::new();
    let mut index: std::collections::HashMap<K, u32> = std::collections::HashMap::new();
    let mut last: Option<(K, u32)> = None;
    // The first 16 addresses met, with their index: the same address holds the same item.
    let mut seen: Vec<(&'a T, u32)> = Vec::new();
    let mut of = Vec::with_capacity(all.len());
    for m in all {
        if let Some(&(_, i)) = seen.iter().find(|(x, _)| std::ptr::eq(*x, m)) {
            of.push(i);
            continue;
        }
        let k = key(m);
        if let Some((lk, li)) = last {
            if lk == k {
                of.push(li);
                continue;
            }
        }
        let found = if keys.len() <= 16 {
            keys.iter().position(|x| *x == k).map(|i| i as u32)
        } else {
            index.get(&k).copied()
        };
        let i = found.unwrap_or_else(|| {
            items.push(*m);
            keys.push(k);
            let i = u32::try_from(items.len() - 1).expect("fewer than 2^32 items");
            if keys.len() == 17 {
                index.extend(keys.iter().enumerate().map(|(j, x)| (*x, j as u32)));
            } else if keys.len() > 17 {
                index.insert(k, i);
            }
            i
        });
        last = Some((k, i));
        if seen.len() < 16 {
            seen.push((m, i));
        }
        of.push(i);
    }
    (of, items)
}

pub use crate::core::secondary::{RayKind, Refraction, Stop};

/// A hit's transmission ray, as the explanation shows it: O_t, Snell's law there, the child's
/// weight and why it was not traced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransmissionRecord<R: Real> {
    /// O_t at the hit.
    pub o_t: V3<R>,
    /// Snell's law at the hit.
    pub refraction: Refraction<R>,
    /// w_t = w_p·max(O_t), the weight the transmission ray has.
    pub weight: R,
    /// Why no transmission ray follows, or `None` when one does.
    pub stop: Option<Stop>,
}

/// How many rays of each kind were traced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Counts {
    /// Primary rays, one per sample.
    pub primary: u64,
    /// Reflection rays (Eq. 4.17).
    pub reflection: u64,
    /// Transmission rays (Snell's law).
    pub transmission: u64,
    /// Shadow rays, from hit points to lights.
    pub shadow: u64,
}

impl Counts {
    /// Every ray traced, of all four kinds.
    pub fn total(&self) -> u64 {
        self.primary + self.reflection + self.transmission + self.shadow
    }
}

impl std::ops::AddAssign for Counts {
    fn add_assign(&mut self, o: Counts) {
        self.primary += o.primary;
        self.reflection += o.reflection;
        self.transmission += o.transmission;
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

/// One ray of a tree, as the explanation shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayRecord<R: Real> {
    /// Primary, reflection or transmission.
    pub kind: RayKind,
    /// The index of the ray it was spawned from among its tree's records; `None` for the
    /// primary ray.
    pub parent: Option<u32>,
    /// 1 for the primary ray.
    pub level: u32,
    /// w: 1 for the primary ray, w_p·max(O_r) for a reflection ray, w_p·max(O_t) for a
    /// transmission ray.
    pub weight: R,
    /// The product of the O_r and O_t on the way from the primary ray: its colour's factor in
    /// the pixel.
    pub factor: V3<R>,
    /// The ray itself (unit direction).
    pub ray: Ray<R>,
    /// For a secondary ray, where it left from.
    pub spawn: Option<Spawn<R>>,
    /// The nearest hit with t > 0; `None` on a miss.
    pub hit: Option<AggregateHit<R>>,
    /// The local colour (Eq. 4.16) at the hit, or the background on a miss.
    pub local: V3<R>,
    /// O_r at the hit, when the material has one.
    pub o_r: Option<V3<R>>,
    /// The weight a reflection ray would have, when there is one to weigh.
    pub next_weight: Option<R>,
    /// Why no reflection ray follows (on a miss: [`Stop::Miss`]), or `None` when one does.
    pub stop: Option<Stop>,
    /// The transmission ray, where the material has a transmissivity.
    pub transmission: Option<TransmissionRecord<R>>,
}

impl<R: Real> RayRecord<R> {
    /// Whether no ray is spawned from this one: the tree ends here.
    pub fn is_leaf(&self) -> bool {
        self.stop.is_some() && self.transmission.is_none_or(|t| t.stop.is_some())
    }
}

/// Receives each ray of a path; the hot path passes `()`, which records nothing.
pub trait PathRecorder<R: Real> {
    /// Whether the records are kept: when not, the tracer does not gather what only a record
    /// shows (where a reflection ray left from).
    const RECORDS: bool = true;

    /// Receives one ray's record, in the tree's order (breadth first, reflection before
    /// transmission).
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
/// scalar [`Tracer::trace`] keeps a queue of them when the tree branches (one when it does not);
/// the wide tracer keeps a queue of them per bounce (`tracer::wide`), both stepping them with
/// [`Tracer::step`]. Where a secondary ray left from ([`Spawn`]) is not carried: only a record
/// shows it, and [`Tracer::trace`] keeps it beside the path when its recorder records.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PathState<R: Real> {
    /// The ray to trace next.
    pub ray: Ray<R>,
    /// The product of the O_r and O_t on the way from the primary ray.
    pub factor: V3<R>,
    /// w: 1 for the primary ray, w_p·max(O_r) or w_p·max(O_t) for a secondary ray.
    pub weight: R,
    /// 1 for the primary ray.
    pub level: u32,
    /// Primary, reflection or transmission.
    pub kind: RayKind,
    /// The parent's index among the tree's records (only a recorder reads it).
    pub parent: u32,
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
            kind: RayKind::Primary,
            parent: u32::MAX,
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
    /// The colour seen along a primary ray, unclamped: the shares of its tree's rays, breadth
    /// first.
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
        // The ray to trace now, with where it left from (for the record: a secondary ray's
        // only); the rays waiting behind it, only once the tree branches.
        let mut current = Some((PathState::primary(primary), None));
        let mut pending: VecDeque<(PathState<R>, Option<Spawn<R>>)> = VecDeque::new();
        let mut recorded = 0u32;
        counts.primary += 1;
        while let Some((mut path, spawn)) = current.take() {
            // The nearest hit in front of the origin; a miss sees the background.
            let found = aggregate.nearest(&path.ray, infinity);
            // The rays the hit spawns: its reflection ray, then its transmission ray.
            let mut children: [Option<PathState<R>>; 2] = [None, None];
            let mut spawned_count = 0;
            let share = self.bounce(
                &mut path,
                spawn,
                found,
                |h| h.shadow_rays(aggregate),
                counts,
                rec,
                &mut |child| {
                    children[spawned_count] = Some(child);
                    spawned_count += 1;
                },
            );
            color += share;
            let here = recorded;
            recorded = recorded.wrapping_add(1);
            let mut spawned = children.into_iter().flatten().map(|mut child| {
                child.parent = here;
                let spawn = if P::RECORDS {
                    found.map(|h| Spawn {
                        from: h.hit.p,
                        p_error: h.hit.p_error,
                        normal: h.hit.normal,
                        origin: child.ray.origin,
                    })
                } else {
                    None
                };
                (child, spawn)
            });
            // A chain (the only child, nothing waiting) goes on without the queue.
            match (spawned.next(), spawned.next()) {
                (Some(only), None) if pending.is_empty() => current = Some(only),
                (first, second) => {
                    pending.extend(first);
                    pending.extend(second);
                    current = pending.pop_front();
                }
            }
        }
        color
    }

    /// One step of a path whose ray found `found` (its nearest hit, or a miss): the ray's share
    /// of the pixel (the factor times the local colour, or times the background on a miss); the
    /// rays it spawns go to `push`, reflection first. `shadows` makes the hit's shadow rays
    /// (asked only with shadows on). `spawn` is where the ray left from, for the record.
    #[inline]
    // Each part by itself: the wide engine passes its own (no recorder, its queue's push).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn bounce<V: CountedVisibility<R>>(
        &self,
        path: &mut PathState<R>,
        spawn: Option<Spawn<R>>,
        found: Option<AggregateHit<R>>,
        shadows: impl FnOnce(&SurfaceHit<R>) -> V,
        counts: &mut Counts,
        rec: &mut impl PathRecorder<R>,
        push: &mut impl FnMut(PathState<R>),
    ) -> V3<R> {
        let Some(h) = found else {
            return self.miss(path, spawn, rec);
        };
        let m = self.scene.material(h.index);
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
        self.step(path, spawn, &h, (n, local), counts, rec, push)
    }

    /// The share of a ray that missed: the factor times the background. `spawn` is where the
    /// ray left from, for the record.
    #[inline]
    pub(crate) fn miss(
        &self,
        path: &PathState<R>,
        spawn: Option<Spawn<R>>,
        rec: &mut impl PathRecorder<R>,
    ) -> V3<R> {
        rec.ray(&RayRecord {
            kind: path.kind,
            parent: (path.parent != u32::MAX).then_some(path.parent),
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
            transmission: None,
        });
        path.factor * self.problem.background
    }

    /// The rest of [`Tracer::bounce`] once the hit `h` is shaded (`shaded`: the normal facing
    /// the ray and the core's colour there), for both engines: the ray's share, the stop rules
    /// and the rays it spawns, given to `push`, reflection first. `spawn` is where the ray left
    /// from, for the record.
    #[inline]
    // Each part by itself: the wide engine passes its own (no recorder, its queue's push).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn step(
        &self,
        path: &PathState<R>,
        spawn: Option<Spawn<R>>,
        h: &AggregateHit<R>,
        shaded: (V3<R>, V3<R>),
        counts: &mut Counts,
        rec: &mut impl PathRecorder<R>,
        push: &mut impl FnMut(PathState<R>),
    ) -> V3<R> {
        let (n, local) = shaded;
        let PathState {
            ray,
            factor,
            weight,
            level,
            kind,
            parent,
        } = *path;
        let m = self.scene.material(h.index);
        let share = factor * local;
        let settings = &self.problem.render;
        // A child is traced only where its colour (O_r, O_t) ≠ 0, its level ≤ the maximum and
        // its weight w_p·max(O) above the minimum (docs/conventions.md, "Recursion level",
        // "Weight", "Transmission").
        let rules = |o: V3<R>| {
            let w = weight * o.max_element();
            let stop = if level >= settings.max_level {
                Some(Stop::MaxLevel)
            } else if w <= settings.min_weight {
                Some(Stop::MinWeight)
            } else {
                None
            };
            (w, stop)
        };
        let mut record = RayRecord {
            kind,
            parent: (parent != u32::MAX).then_some(parent),
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
            transmission: None,
        };
        record.stop = match m.o_r {
            None => Some(Stop::NotReflective),
            Some(o_r) if o_r == V3::<R>::ZERO => Some(Stop::NotReflective),
            Some(o_r) => {
                let (w_s, stop) = rules(o_r);
                record.next_weight = Some(w_s);
                stop
            }
        };
        if record.stop.is_none() {
            let o_r = m.o_r.expect("a reflection ray needs O_r");
            // The reflection direction R_V = V − 2(N·V)N, Eq. 4.17.
            let r_v = ray.direction - n * (R::TWO * n.dot(ray.direction));
            if let Some(r_v) = normalize::<R>(r_v) {
                push(PathState {
                    ray: h.hit.spawn_ray(r_v.unit),
                    factor: factor * o_r,
                    weight: weight * o_r.max_element(),
                    level: level + 1,
                    kind: RayKind::Reflection,
                    parent: u32::MAX,
                });
                counts.reflection += 1;
            }
        }
        if let Some(Transmission { o_t, eta }) = m.transmission {
            let (w_t, mut stop) = if o_t == V3::<R>::ZERO {
                (R::ZERO, Some(Stop::NotTransmissive))
            } else {
                rules(o_t)
            };
            // Snell's law only where a ray may follow, or where the record shows it.
            let refraction = (stop.is_none() || rec_records(rec))
                .then(|| Refraction::at(ray.direction, h.hit.normal, n, eta));
            if let Some(r) = refraction {
                match (stop, r.direction) {
                    (None, Some(t)) => {
                        push(PathState {
                            ray: h.hit.spawn_ray(t),
                            factor: factor * o_t,
                            weight: w_t,
                            level: level + 1,
                            kind: RayKind::Transmission,
                            parent: u32::MAX,
                        });
                        counts.transmission += 1;
                    }
                    (None, None) => stop = Some(Stop::TotalInternalReflection),
                    _ => {}
                }
                record.transmission = Some(TransmissionRecord {
                    o_t,
                    refraction: r,
                    weight: w_t,
                    stop,
                });
            }
        }
        rec.ray(&record);
        share
    }
}

/// Whether `rec` keeps what it receives.
#[inline(always)]
fn rec_records<R: Real, P: PathRecorder<R>>(_: &P) -> bool {
    P::RECORDS
}
