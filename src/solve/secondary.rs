//! The secondary rays of a ray problem's hit, as Section 4.4 defines them: the reflection ray
//! R_V = V − 2(N·V)N (Eq. 4.17) where the material has a reflectivity O_r, and the transmitted
//! ray by Snell's law where it has a transmissivity O_t (docs/conventions.md, "Transmission"),
//! each with its level, its weight and whether the tracer would trace it under the problem's
//! `render.max_level` and `render.min_weight` ("Recursion level", "Weight"). The solver shows
//! these rays; it does not trace them (the tracer does).
//!
//! The stop rules are the tracer's (`Tracer::step`), in its order: a zero colour, then the
//! level (the child's level ≤ the maximum), then the weight (w > the minimum), then, for the
//! transmitted ray, total internal reflection. Snell's law is the tracer's own
//! [`Refraction::at`]; R_V is computed with the tracer's expression, and a test holds both to
//! the tracer's recorded rays, bit for bit.

use crate::core::secondary::{Refraction, Stop};
use crate::core::vector::normalize;
use crate::core::{Material, Real, Transmission, Vector, V3};
use crate::geometry::SurfaceHit;
use crate::problem::model::RenderSettings;

/// The level of a ray problem's own ray: it is a primary ray (docs/conventions.md, "Recursion
/// level").
pub const PROBLEM_RAY_LEVEL: u32 = 1;

/// The secondary rays at a ray problem's hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Secondary<R: Real> {
    /// The problem's ray's level: 1, a primary ray.
    pub level: u32,
    /// The problem's ray's weight: 1, a primary ray.
    pub weight: R,
    /// The maximum level of the problem's `render` settings.
    pub max_level: u32,
    /// The minimum weight of the problem's `render` settings.
    pub min_weight: R,
    /// V, the incoming ray's unit direction D.
    pub v: V3<R>,
    /// N, the surface's normal at the hit turned to face the ray.
    pub n: V3<R>,
    /// N·V (negative: N faces the ray).
    pub n_dot_v: R,
    /// The reflection ray, where the material has an O_r.
    pub reflection: Option<ReflectionRay<R>>,
    /// The transmitted ray, where the material has an O_t.
    pub transmission: Option<TransmittedRay<R>>,
}

/// The reflection ray of a hit, Eq. 4.17.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReflectionRay<R: Real> {
    /// O_r at the hit.
    pub o_r: V3<R>,
    /// R_V = V − 2(N·V)N, unit; `None` only where it cannot be normalised (never for a unit V
    /// and N within the precision's range).
    pub direction: Option<V3<R>>,
    /// Its level: the problem's ray's + 1.
    pub level: u32,
    /// w_s = w_p·max(O_r), w_p = 1.
    pub weight: R,
    /// Why the tracer would not trace it, or `None` when it would.
    pub stop: Option<Stop>,
}

/// The transmitted ray of a hit, by Snell's law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransmittedRay<R: Real> {
    /// O_t at the hit.
    pub o_t: V3<R>,
    /// η, the index of refraction of the material's inside.
    pub eta: R,
    /// Snell's law at the hit: the media, cos θ_i, k and T (`None` under total internal
    /// reflection).
    pub refraction: Refraction<R>,
    /// Its level: the problem's ray's + 1.
    pub level: u32,
    /// w_t = w_p·max(O_t), w_p = 1.
    pub weight: R,
    /// Why the tracer would not trace it, or `None` when it would.
    pub stop: Option<Stop>,
}

impl<R: Real> ReflectionRay<R> {
    /// Whether the tracer traces it.
    pub fn traced(&self) -> bool {
        self.stop.is_none()
    }
}

impl<R: Real> TransmittedRay<R> {
    /// Whether the tracer traces it.
    pub fn traced(&self) -> bool {
        self.stop.is_none()
    }
}

/// The level and weight rules of a child of weight `w` spawned from a ray of level `level`:
/// the child is traced only if its level, `level` + 1, is ≤ the maximum level and `w` > the
/// minimum weight. The order and the comparisons are `Tracer::step`'s.
fn rules<R: Real>(level: u32, w: R, settings: &RenderSettings<R>) -> Option<Stop> {
    if level >= settings.max_level {
        Some(Stop::MaxLevel)
    } else if w <= settings.min_weight {
        Some(Stop::MinWeight)
    } else {
        None
    }
}

/// The reflection direction R_V = V − 2(N·V)N of Eq. 4.17, unit: the tracer's expression, for a
/// unit V and a unit N facing it.
pub(crate) fn reflect<R: Real>(v: V3<R>, n: V3<R>) -> Option<V3<R>> {
    normalize::<R>(v - n * (R::TWO * n.dot(v))).map(|r| r.unit)
}

/// The secondary rays at `hit` of a ray along `v` (unit), on a surface of material `m`, under
/// the problem's render `settings`; `None` for an opaque material without O_r (no secondary
/// ray to show).
pub(crate) fn at_hit<R: Real>(
    hit: &SurfaceHit<R>,
    v: V3<R>,
    m: &Material<R>,
    settings: &RenderSettings<R>,
) -> Option<Secondary<R>> {
    if m.o_r.is_none() && m.transmission.is_none() {
        return None;
    }
    let level = PROBLEM_RAY_LEVEL;
    let weight = R::ONE;
    // N turned to face the incoming ray, as the tracer's (docs/conventions.md, "Orientation").
    let n = hit.facing(v).normal;
    let reflection = m.o_r.map(|o_r| {
        let w = weight * o_r.max_element();
        let stop = if o_r == V3::<R>::ZERO {
            Some(Stop::NotReflective)
        } else {
            rules(level, w, settings)
        };
        ReflectionRay {
            o_r,
            direction: reflect::<R>(v, n),
            level: level + 1,
            weight: w,
            stop,
        }
    });
    let transmission = m.transmission.map(|Transmission { o_t, eta }| {
        let refraction = Refraction::at(v, hit.normal, n, eta);
        let zero = o_t == V3::<R>::ZERO;
        let w = if zero {
            R::ZERO
        } else {
            weight * o_t.max_element()
        };
        let stop = if zero {
            Some(Stop::NotTransmissive)
        } else {
            rules(level, w, settings).or_else(|| {
                refraction
                    .direction
                    .is_none()
                    .then_some(Stop::TotalInternalReflection)
            })
        };
        TransmittedRay {
            o_t,
            eta,
            refraction,
            level: level + 1,
            weight: w,
            stop,
        }
    });
    Some(Secondary {
        level,
        weight,
        max_level: settings.max_level,
        min_weight: settings.min_weight,
        v,
        n,
        n_dot_v: n.dot(v),
        reflection,
        transmission,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::Target;
    use crate::tracer::{Counts, RayRecord, Scene, Tracer};

    /// The solver's R_V and T are the tracer's own, bit for bit: the exercise's ray traced
    /// (with every child allowed) gives a reflection ray and a transmission ray whose
    /// directions are the solution's.
    #[test]
    fn the_solvers_secondary_rays_are_the_tracers_in_both_precisions() {
        fn go<R: Real>() {
            let path = std::path::Path::new("exercises/secondary-rays.json");
            let (_, mut problem) = crate::problem::load::<R>(path).unwrap();
            // Let both children through, so that the tracer spawns them.
            problem.render.min_weight = R::ZERO;
            let solution = crate::solve::solve(&problem).unwrap();
            let x = solution.secondary.expect("secondary rays");
            let Target::Ray { ray, .. } = problem.target else {
                panic!("a ray problem")
            };
            let scene = Scene::new(&problem);
            let tracer = Tracer {
                scene: &scene,
                problem: &problem,
            };
            let mut records: Vec<RayRecord<R>> = Vec::new();
            tracer.trace(ray, &mut Counts::default(), &mut records);
            let child = |kind| {
                records
                    .iter()
                    .find(|r| r.kind == kind)
                    .map(|r| (r.ray.direction, r.level, r.weight))
            };
            let r = x.reflection.unwrap();
            let t = x.transmission.unwrap();
            assert!(r.traced() && t.traced());
            assert_eq!(
                child(crate::tracer::trace::RayKind::Reflection),
                Some((r.direction.unwrap(), r.level, r.weight))
            );
            assert_eq!(
                child(crate::tracer::trace::RayKind::Transmission),
                Some((t.refraction.direction.unwrap(), t.level, t.weight))
            );
        }
        go::<f32>();
        go::<f64>();
    }
}
