//! The wide tracer: the same paths as [`Tracer::trace`], traced a packet at a time.
//!
//! A row's samples are taken in blocks of [`BLOCK`] (a strip of neighbouring pixels, so the
//! primary rays of a packet are coherent). Each block keeps a queue of live paths per bounce
//! (a wavefront): the queue's rays are intersected [`Wide::LANES`] at a time against a
//! [`FlatScene`] (8 rays per instruction in f32, 4 or 8 in f64); the hits are grouped by material
//! and shaded a register at a time by the core's own arithmetic ([`shade_lanes`], of which the
//! scalar [`crate::core::shade()`] is the one-lane instance), their shadow rays built as
//! `ShadowRays` builds them and tested as packets, any hit ([`FlatScene::occluded_lanes`]);
//! then each path is stepped by the scalar tracer's own [`Tracer::step`] (the stop rules, the
//! reflection and transmission rays), and the rays it spawns form the next bounce's queue, in
//! order, reflection first. The loop is one of six instances ([`Plan`]), chosen once per render
//! by whether the scene has shadows and secondary rays. Each queue entry carries the sample it
//! adds to and its own factor, so a ray tree fits the same queues: they hold its rays breadth
//! first, the order in which [`Tracer::trace`] takes them.
//!
//! The shares of a sample are added in bounce order (breadth first), as [`Tracer::trace`] adds
//! them, and a
//! pixel's samples in sample order, as [`super::render::pixel_mean`] does; the packet
//! intersection is the aggregate's to the bit ([`FlatScene`]). So the image is the scalar
//! tracer's, byte for byte, in both precisions (src/tracer/wide/tests.rs). Scenes the packets do not cover
//! (more than a handful of spheres, which the aggregate puts in a BVH, or triangles) take the
//! same queues and the same shading in lanes with the aggregate's packet searches of its wide
//! BVH ([`Aggregate::nearest_packet`], [`Aggregate::occluded_packet`]), each ray's answer the
//! one-ray search's to the bit.

use super::camera::CameraRays;
use super::render::{clamped, mean};
use super::sampler::sample;
use super::trace::{distinct, Counts, PathState, Scene, Tracer};
use crate::core::lanes::{mask_of, Wide, W, W3};
use crate::core::light::LaneArrival;
use crate::core::rounding::gamma;
use crate::core::shade::{shade_lanes, LanePoint, LaneSide, LaneTerm};
use crate::core::vector::between_lanes;
use crate::core::{Chapter, Light, Material, Real, Vector, V3};
use crate::geometry::hit::offset_origin_lanes;
use crate::geometry::soa::FlatScene;
use crate::geometry::{Aggregate, AggregateHit, Ray};
use crate::problem::Problem;

/// Samples traced together: a strip of a row (one sample per pixel: 64 pixels).
pub const BLOCK: usize = 64;

/// Which tracer renders an image: the same image either way. `Scalar` is `Tracer::trace`, one
/// ray at a time; `Wide` is this module's, the default.
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
#[allow(missing_docs)]
pub enum Engine {
    Scalar,
    #[default]
    Wide,
}

impl Engine {
    /// "scalar" or "wide", as `--engine` writes it.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Scalar => "scalar",
            Engine::Wide => "wide",
        }
    }
}

/// A live path in a bounce's queue: the sample it adds to and where it stands.
#[derive(Clone, Copy, Debug)]
struct Entry<R: Real> {
    /// The sample's place in its block.
    slot: u32,
    path: PathState<R>,
}

/// What the wide engine decides once per render: the flat scene in lanes (when the scene is
/// flat), each surface's material as an index into the distinct materials (the hits of a bounce
/// are shaded together by material), and which instance of the bounce loop the scene needs.
pub(crate) struct Plan<R: Real> {
    flat: Option<FlatScene<R>>,
    /// The material of surface i is `materials[material_of[i]]`.
    material_of: Vec<u32>,
    materials: Vec<Material<R>>,
    /// The instance of the bounce loop the scene needs.
    model: Model,
}

/// The monomorphised instances of the bounce loop, chosen once per render by what the scene
/// contains: shadow rays only with shadows on, the step of secondary rays only where some
/// surface reflects or transmits. (The spot cone and the specular term are decided by the core per light and per
/// material, once for a register of hits, never per ray.)
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Model {
    /// Shadows on, some surface transmits: ray trees (the glass scene).
    ShadowsTrees,
    /// Shadows on, some surface reflects, none transmits: paths (the classic scene).
    ShadowsReflections,
    /// Shadows on, nothing reflects or transmits: one bounce.
    Shadows,
    /// Shadows off, some surface transmits.
    Trees,
    /// Shadows off, some surface reflects, none transmits.
    Reflections,
    /// Shadows off, nothing reflects or transmits.
    Local,
}

impl<R: Real> Plan<R> {
    /// The plan for rendering `scene` with `problem`'s settings.
    pub(crate) fn new(scene: &Scene<R>, problem: &Problem<R>) -> Self {
        // The scene's distinct materials, merged where shading reads the same, then each
        // surface's index composed with it.
        let (shading_of, materials) = distinct(scene.materials.iter(), shading_bits);
        let material_of = (scene.material_of.iter())
            .map(|&i| shading_of[i as usize])
            .collect();
        let reflects = (scene.materials.iter()).any(|m| m.o_r.is_some_and(|o| o != V3::<R>::ZERO));
        let transmits = (scene.materials.iter())
            .any(|m| m.transmission.is_some_and(|t| t.o_t != V3::<R>::ZERO));
        let model = match (problem.render.shadows, transmits, reflects) {
            (true, true, _) => Model::ShadowsTrees,
            (true, false, true) => Model::ShadowsReflections,
            (true, false, false) => Model::Shadows,
            (false, true, _) => Model::Trees,
            (false, false, true) => Model::Reflections,
            (false, false, false) => Model::Local,
        };
        Plan {
            flat: FlatScene::new(&scene.aggregate),
            material_of,
            materials,
            model,
        }
    }
}

/// What shading reads of a material (O_a, O_d, O_s, n_s) by its bits (1 where a colour is
/// present); O_r is the step's, read from the surface itself.
fn shading_bits<R: Real>(m: &Material<R>) -> [u64; 13] {
    let mut k = [0u64; 13];
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
    k[12] = m.n_s.to_f64().to_bits();
    k
}

/// The wide engine's side of the core's [`shade_lanes`]: the shadow rays of a register of hits
/// on one material, built in lanes as [`crate::geometry::shadow::ShadowRays::ray`] builds each
/// one (the origin by [`offset_origin_lanes`], the direction and length to a light by
/// [`between_lanes`]: the same operations, so every lane holds the scalar ray's bits) and tested
/// as a packet ([`FlatScene::occluded_lanes`], in the lanes as built, or
/// [`Aggregate::occluded_packet`] through the wide BVH for scenes in a BVH), counted as the
/// scalar engine counts them.
struct WideSide<'a, R: Real, const SHADOWS: bool> {
    aggregate: &'a Aggregate<R>,
    flat: Option<&'a FlatScene<R>>,
    /// The hits' error bounds on P, per lane.
    p_error: W3<W<R>>,
    /// The hits' own normals (not turned to the ray), per lane.
    normal: W3<W<R>>,
    /// The shadow rays traced.
    traced: u64,
}

impl<R: Real, const SHADOWS: bool> LaneSide<W<R>> for WideSide<'_, R, SHADOWS> {
    const DETAIL: bool = false;

    #[inline]
    fn visible(
        &mut self,
        need: W<R>,
        p: W3<W<R>>,
        light: &Light<R>,
        arrival: &LaneArrival<W<R>>,
    ) -> W<R> {
        if !SHADOWS {
            return need;
        }
        self.traced += u64::from(need.bits().count_ones());
        // ShadowRays::ray in lanes: from the offset origin towards the light, to a hair short
        // of a positioned light, for ever to a directional one.
        let l = arrival.l;
        let towards = W3 {
            x: l.x.neg(),
            y: l.y.neg(),
            z: l.z.neg(),
        };
        let origin = offset_origin_lanes::<W<R>>(p, self.p_error, self.normal, towards);
        let (direction, t_max, want) = match light.position() {
            None => (towards, W::<R>::splat(R::from_f64(f64::INFINITY)), need),
            Some(pos) => {
                let to_light = between_lanes::<W<R>>(origin, W3::splat(pos));
                let short = W::<R>::splat(R::ONE - gamma::<R>(64));
                (
                    to_light.unit,
                    to_light.length * short,
                    need.and(to_light.found),
                )
            }
        };
        let want: u32 = Wide::bits(want);
        if want == 0 {
            return need;
        }
        let blocked = match self.flat {
            // The rays as they are, in lanes.
            Some(flat) => flat.occluded_lanes(origin, direction, t_max, want),
            // The rays as they are, in lanes, made one by one only where the one-ray code
            // needs them.
            None => self
                .aggregate
                .occluded_packet_in((origin, direction), &t_max.to_array(), want),
        };
        need.and(mask_of::<W<R>>(blocked).not())
    }

    #[inline(always)]
    fn light(&mut self, _: usize, _: &Light<R>, _: &LanePoint<W<R>>, _: LaneTerm<W<R>>) {}
}

/// The queues and buffers of one row, allocated once per row and reused by its blocks.
struct Buffers<R: Real> {
    /// The live paths of the bounce being traced, in sample order.
    queue: Vec<Entry<R>>,
    /// The rays the bounce spawns, in the same order: the next bounce's queue.
    next: Vec<Entry<R>>,
    colors: Vec<V3<R>>,
    /// The nearest hit of each queue entry.
    found: Vec<Option<AggregateHit<R>>>,
    /// The normal facing the ray and the local colour of each queue entry with a hit.
    shaded: Vec<(V3<R>, V3<R>)>,
    /// (material, entry) of the entries with a hit, sorted: the groups shaded together.
    groups: Vec<(u32, u32)>,
    /// The materials of the queue's hits, each with its count, then its place in `groups`.
    materials: Vec<(u32, u32)>,
    rays: Vec<Ray<R>>,
    /// Sample i of the row's pixels: its sx and its [`CameraRays::up_term`].
    samples: Vec<(f64, V3<R>)>,
}

/// Pixel means of row `y`, each mapped by `each` and appended to `out`: the row
/// [`super::render::pixel_mean`] gives pixel by pixel, traced in packets.
pub(crate) fn row<R: Real, T: Copy>(
    tracer: &Tracer<R>,
    plan: &Plan<R>,
    camera: &CameraRays<R>,
    y: u32,
    counts: &mut Counts,
    each: &impl Fn([f64; 3]) -> [T; 3],
    out: &mut Vec<T>,
) {
    match plan.model {
        Model::ShadowsTrees => {
            row_in::<R, T, true, true, true>(tracer, plan, camera, y, counts, each, out)
        }
        Model::ShadowsReflections => {
            row_in::<R, T, true, true, false>(tracer, plan, camera, y, counts, each, out)
        }
        Model::Shadows => {
            row_in::<R, T, true, false, false>(tracer, plan, camera, y, counts, each, out)
        }
        Model::Trees => {
            row_in::<R, T, false, true, true>(tracer, plan, camera, y, counts, each, out)
        }
        Model::Reflections => {
            row_in::<R, T, false, true, false>(tracer, plan, camera, y, counts, each, out)
        }
        Model::Local => {
            row_in::<R, T, false, false, false>(tracer, plan, camera, y, counts, each, out)
        }
    }
}

/// [`row`] in the instance the scene needs: `SHADOWS` (shadow rays), `SECONDARY` (some surface
/// reflects or transmits: the stop rules and the queue of secondary rays), `TREES` (some
/// surface transmits, so a hit may spawn two rays: the next bounce's queue built apart; else
/// the paths that go on are moved down the queue in place).
fn row_in<R: Real, T: Copy, const SHADOWS: bool, const SECONDARY: bool, const TREES: bool>(
    tracer: &Tracer<R>,
    plan: &Plan<R>,
    camera: &CameraRays<R>,
    y: u32,
    counts: &mut Counts,
    each: &impl Fn([f64; 3]) -> [T; 3],
    out: &mut Vec<T>,
) {
    let lanes = <R::Wide as Wide>::LANES;
    let n = tracer.problem.render.samples;
    let width = camera.width;
    let total = width as usize * n as usize;
    let mut b = Buffers {
        queue: Vec::with_capacity(BLOCK),
        next: Vec::with_capacity(BLOCK),
        colors: vec![V3::<R>::ZERO; BLOCK],
        found: Vec::with_capacity(BLOCK),
        shaded: vec![(V3::<R>::ZERO, V3::<R>::ZERO); BLOCK],
        groups: Vec::with_capacity(BLOCK),
        materials: Vec::with_capacity(FEW_MATERIALS),
        rays: Vec::with_capacity(lanes),
        samples: Vec::with_capacity(n as usize),
    };
    // The row's samples: each one's sx and the height of its rays, the same for every pixel.
    b.samples.extend((0..n).map(|i| {
        let (sx, sy) = sample(i, n);
        (sx, camera.up_term(y, sy))
    }));
    let aggregate = &tracer.scene.aggregate;
    let flat = plan.flat.as_ref();
    let mut sum = [0.0f64; 3];
    for start in (0..total).step_by(BLOCK) {
        let end = (start + BLOCK).min(total);
        // Primary rays, pixel by pixel and sample by sample, as pixel_mean takes them.
        b.queue.clear();
        // Sample s is sample i of pixel x: counted along rather than divided out per sample (a
        // 64-bit division's latency each).
        let (mut x, mut i) = ((start / n as usize) as u32, start % n as usize);
        for s in start..end {
            let (sx, up_term) = b.samples[i];
            b.queue.push(Entry {
                slot: (s - start) as u32,
                path: PathState::primary(camera.ray_across(up_term, x, sx)),
            });
            b.colors[s - start] = V3::<R>::ZERO;
            i += 1;
            if i == n as usize {
                (x, i) = (x + 1, 0);
            }
        }
        counts.primary += (end - start) as u64;
        // One bounce per pass: the queue's nearest hits a packet at a time; the hits shaded
        // by material, a register at a time; then each path stepped and its child queued.
        while !b.queue.is_empty() {
            // Each packet's hits written straight into their places in `found`.
            b.found.clear();
            b.found.resize(b.queue.len(), None);
            // A tree's bounce may hold more rays than the block has samples.
            if b.shaded.len() < b.queue.len() {
                b.shaded
                    .resize(b.queue.len(), (V3::<R>::ZERO, V3::<R>::ZERO));
            }
            for (packet, out) in b.queue.chunks(lanes).zip(b.found.chunks_mut(lanes)) {
                b.rays.clear();
                b.rays.extend(packet.iter().map(|e| e.path.ray));
                match flat {
                    Some(flat) => flat.nearest(aggregate, &b.rays, out),
                    None => aggregate.nearest_packet(&b.rays, out),
                }
            }
            shade_queue::<R, SHADOWS>(tracer, plan, &mut b, counts);
            if TREES {
                // Each path stepped where it stands in the queue, and the rays it spawns queued
                // behind each other in order, reflection first: the next bounce's queue.
                b.next.clear();
                for i in 0..b.queue.len() {
                    let e = &b.queue[i];
                    let share = match &b.found[i] {
                        None => tracer.miss(&e.path, None, &mut ()),
                        Some(h) => {
                            let (slot, next) = (e.slot, &mut b.next);
                            let shaded = b.shaded[i];
                            tracer.step(&e.path, None, h, shaded, counts, &mut (), &mut |path| {
                                next.push(Entry { slot, path })
                            })
                        }
                    };
                    b.colors[e.slot as usize] += share;
                }
                std::mem::swap(&mut b.queue, &mut b.next);
            } else {
                // At most one child per path: each path stepped where it stands, and the paths
                // that go on moved down to the queue's front, in order.
                let mut kept = 0;
                for i in 0..b.queue.len() {
                    let e = b.queue[i];
                    let mut child = None;
                    let share = match &b.found[i] {
                        None => tracer.miss(&e.path, None, &mut ()),
                        Some(h) if SECONDARY => {
                            let shaded = b.shaded[i];
                            tracer.step(&e.path, None, h, shaded, counts, &mut (), &mut |path| {
                                child = Some(path)
                            })
                        }
                        Some(_) => e.path.factor * b.shaded[i].1,
                    };
                    b.colors[e.slot as usize] += share;
                    if let Some(path) = child {
                        b.queue[kept] = Entry { slot: e.slot, path };
                        kept += 1;
                    }
                }
                b.queue.truncate(kept);
            }
        }
        // The samples in order: each pixel's sum, then its mean, as pixel_mean forms them.
        let mut i = start % n as usize;
        for c in &b.colors[..end - start] {
            let c = clamped::<R>(*c);
            for k in 0..3 {
                sum[k] += c[k];
            }
            i += 1;
            if i == n as usize {
                out.extend_from_slice(&each(mean(sum, n)));
                (sum, i) = ([0.0; 3], 0);
            }
        }
    }
}

/// The local colour of every queue entry with a hit, by the core's [`shade_lanes`]: the hits
/// grouped by material (in queue order within a material), each group a register of lanes at a
/// time; the normal facing each ray and the colour go to `b.shaded`.
#[inline]
fn shade_queue<R: Real, const SHADOWS: bool>(
    tracer: &Tracer<R>,
    plan: &Plan<R>,
    b: &mut Buffers<R>,
    counts: &mut Counts,
) {
    let lanes = W::<R>::LANES;
    let material_of = b
        .found
        .iter()
        .map(|h| h.as_ref().map(|h| plan.material_of[h.index]));
    sort_by_material(material_of, &mut b.materials, &mut b.groups);
    let lights = &tracer.problem.lights;
    let mut at = 0;
    while at < b.groups.len() {
        let material = b.groups[at].0;
        let mut len = 1;
        while len < lanes && at + len < b.groups.len() && b.groups[at + len].0 == material {
            len += 1;
        }
        let group = &b.groups[at..at + len];
        at += len;
        // Lanes past the group's end repeat its last hit (and are not active).
        let mut hit = [Lane3::<R>::default(); 5];
        for k in 0..lanes {
            let i = group[k.min(len - 1)].1 as usize;
            let (Some(h), d) = (&b.found[i], b.queue[i].path.ray.direction) else {
                unreachable!("a group holds hits")
            };
            hit[0].set(k, h.hit.p);
            hit[1].set(k, h.hit.p_error);
            hit[2].set(k, h.hit.normal);
            hit[3].set(k, d);
            hit[4].set(k, h.hit.shading);
        }
        let [p, p_error, normal, v, shading] = hit.map(Lane3::lanes);
        // The shading normal turned to face the incoming ray by the geometric normal's test
        // (`SurfaceHit::facing`); V is the ray's direction (Eq. 4.10).
        let reversed = normal.dot(v).gt(W::<R>::splat(R::ZERO));
        let n = W3 {
            x: reversed.select(shading.x.neg(), shading.x),
            y: reversed.select(shading.y.neg(), shading.y),
            z: reversed.select(shading.z.neg(), shading.z),
        };
        let point = LanePoint::<W<R>> { p, n, v: Some(v) };
        let mut side = WideSide::<R, SHADOWS> {
            aggregate: &tracer.scene.aggregate,
            flat: plan.flat.as_ref(),
            p_error,
            normal,
            traced: 0,
        };
        let active = mask_of::<W<R>>((1u32 << len) - 1);
        let m = &plan.materials[material as usize];
        // The local colour, Eq. 4.16, by the core, in lanes.
        let s = shade_lanes::<W<R>, Chapter, _>(Chapter, &point, active, m, lights, &mut side);
        counts.shadow += side.traced;
        let (nx, ny, nz) = (n.x.to_array(), n.y.to_array(), n.z.to_array());
        let (cx, cy, cz) = (
            s.color.x.to_array(),
            s.color.y.to_array(),
            s.color.z.to_array(),
        );
        for (k, &(_, i)) in group.iter().enumerate() {
            b.shaded[i as usize] = (
                V3::<R>::new(nx.as_ref()[k], ny.as_ref()[k], nz.as_ref()[k]),
                V3::<R>::new(cx.as_ref()[k], cy.as_ref()[k], cz.as_ref()[k]),
            );
        }
    }
}

/// The most materials [`sort_by_material`] counts; a queue that meets more is sorted by
/// comparisons.
const FEW_MATERIALS: usize = 8;

/// (material, entry) of each queue entry with a hit (`material_of`: entry i's hit's material,
/// `None` without a hit), sorted as `slice::sort` would: by material, then entry. A counting sort
/// over the few materials a queue meets (`materials`: each one met and its count), the entries
/// taken in order (the comparison sort of up to [`BLOCK`] pairs cost 2.6 % of a 10,000-sphere
/// render's instructions, this 1.5 %); past [`FEW_MATERIALS`], the comparison sort.
fn sort_by_material(
    material_of: impl Iterator<Item = Option<u32>> + Clone,
    materials: &mut Vec<(u32, u32)>,
    groups: &mut Vec<(u32, u32)>,
) {
    let place = |materials: &[(u32, u32)], m: u32| materials.iter().position(|e| e.0 == m);
    materials.clear();
    for m in material_of.clone().flatten() {
        match place(materials, m) {
            Some(j) => materials[j].1 += 1,
            None if materials.len() < FEW_MATERIALS => materials.push((m, 1)),
            None => {
                // Many materials (a colour per sphere): the lookups would cost more than the
                // comparison sort.
                groups.clear();
                let hits = material_of.enumerate();
                groups.extend(hits.filter_map(|(i, m)| m.map(|m| (m, i as u32))));
                groups.sort_unstable();
                return;
            }
        }
    }
    materials.sort_unstable();
    // Each material's first place in `groups`
    let mut next = 0;
    for e in materials.iter_mut() {
        (e.1, next) = (next, next + e.1);
    }
    groups.clear();
    groups.resize(next as usize, (0, 0));
    for (i, m) in material_of.enumerate() {
        if let Some(m) = m {
            let Some(j) = place(materials, m) else {
                unreachable!("every material met was counted")
            };
            groups[materials[j].1 as usize] = (m, i as u32);
            materials[j].1 += 1;
        }
    }
}

/// A vector per lane being filled lane by lane: the three components' arrays.
#[derive(Clone, Copy, Default)]
struct Lane3<R: Real> {
    x: <W<R> as Wide>::Array,
    y: <W<R> as Wide>::Array,
    z: <W<R> as Wide>::Array,
}

impl<R: Real> Lane3<R> {
    /// Lane k holds `v`.
    #[inline(always)]
    fn set(&mut self, k: usize, v: V3<R>) {
        self.x.as_mut()[k] = v.x();
        self.y.as_mut()[k] = v.y();
        self.z.as_mut()[k] = v.z();
    }

    /// The registers.
    #[inline(always)]
    fn lanes(self) -> W3<W<R>> {
        W3 {
            x: W::<R>::from_array(self.x),
            y: W::<R>::from_array(self.y),
            z: W::<R>::from_array(self.z),
        }
    }
}

#[cfg(test)]
mod tests;
