//! The wide BVH: the binary SAH tree of [`Bvh`] collapsed so that each node holds up to
//! [`Wide::LANES`] children (8 in f32; 8 or 4 in f64, [`crate::core::lanes::F64Lanes`]) whose
//! boxes sit in lanes, tested against one ray by one slab test per node; its leaves hold up to
//! [`Wide::LANES`] spheres or triangles in structure-of-arrays blocks, tested against the ray in
//! lanes, with no dispatch on the kind.
//! One ray at a time (the scalar engine, the solver), or a packet of up to [`Wide::LANES`] rays
//! (the wide engine's queues and shadow rays: see "Packets" below); a wide tree pays for every
//! ray, a packet only for coherent rays, so a packet's last ray goes on alone ([`FEW`],
//! docs/benchmarks.md).
//!
//! **The binary tree's answer, to the bit.** The search visits the binary tree's leaves in the
//! binary traversal's order with the same t_max at each, so the nearest (primitive, t), ties
//! included, is [`Bvh::nearest`]'s:
//! - a node's children are visited in the order the binary traversal would visit them (near
//!   child first by the sign of D along each collapsed node's split axis), precomputed for
//!   each of the 8 octants of D;
//! - each child's slab test is [`Aabb::hit`]'s arithmetic in lanes, and the child's t₀ is kept
//!   on the stack: when it is taken off, t₀ ≤ t_max (the current, perhaps lowered, t_max) is
//!   exactly the binary test of that box at that moment (the far side was checked already and
//!   does not depend on t_max). The collapsed binary nodes between a node and its children need
//!   no test: their boxes contain the children's and were tested with a t_max no smaller, so a
//!   child that passes implies they pass;
//! - a leaf's primitives are taken in the binary leaf's order with the strict "nearer than the
//!   best so far" rule; the lanes compute [`Shape::hit_t`]'s arithmetic at the t_max the leaf
//!   was entered with, which is exact for the first hit a leaf accepts; a later lane is checked
//!   against the lowered t_max (a sphere's t does not depend on t_max; a triangle is asked
//!   again by the scalar code), and lanes the fast formulas cannot decide go to the scalar code,
//!   as in [`super::soa`].
//!
//! Shadow rays ask [`WideBvh::occluded`]: whether some primitive in a leaf whose box the ray
//! meets before t_max is hit. That set does not depend on the order of the visit, so it is
//! `Bvh::any`'s answer too.

use smallvec::SmallVec;

use super::bounds::{inverse, Aabb};
use super::bvh::Bvh;
use super::ray::{lane_ray, RayLanes};
use super::soa::{sphere_hit_t, sphere_hit_t_in};
use super::triangle::Shear;
use super::{Ray, Shape};
use crate::core::lanes::{lanes_of, mask_of, Lanes, Wide, W, W3};
use crate::core::rounding::gamma;
use crate::core::{Real, Vector, V3};

/// The widest node: 8 children (f32's lanes, and f64's with AVX-512).
const MAX_WIDTH: usize = 8;
/// Entries held in place on a traversal stack before it spills to the heap. A level of the path
/// leaves one entry per child met beyond the first (LANES − 1 at most), so a ray needs many
/// levels each meeting most children to spill (then correct, only slower: it allocates).
const STACK: usize = 32;

/// A reference to a node or a leaf: the kind in the top two bits, the index below.
type Ref = u32;
const KIND: u32 = 30;
const NODE: u32 = 0;
const SPHERES: u32 = 1;
const TRIANGLES: u32 = 2;
const MIXED: u32 = 3;
const INDEX: u32 = (1 << KIND) - 1;

fn reference(kind: u32, index: usize) -> Ref {
    let index = u32::try_from(index)
        .ok()
        .filter(|&i| i <= INDEX)
        .expect("fewer than 2^30 nodes and leaves");
    (kind << KIND) | index
}

/// A node: its children's boxes in lanes (empty lanes past the count), their references, and
/// the order in which the binary traversal would visit them for each octant of D. Four cache
/// lines in either precision (the boxes take three): 256 bytes, aligned to them (a node of 288
/// bytes, 32-aligned, straddled five lines; the 100,000-sphere trace took 1–2 % longer).
#[derive(Clone, Debug)]
#[repr(align(64))]
struct Node<R: Real> {
    /// The children's boxes: `bounds[0]` the minima, `bounds[1]` the maxima, by axis.
    bounds: [[W<R>; 3]; 2],
    child: <W<R> as Wide>::Indices,
    /// For octant o (bit a set where D's component a is negative, as 1/D's sign says), the
    /// children in reverse visiting order (the order they are pushed in), 3 bits each, the
    /// last visited in the lowest bits (24 bits for 8 children); the top 8 bits of every word
    /// hold the number of children (the order is read `count` times 3 bits, never up to them).
    order: [u32; 8],
}

/// Where [`Node::order`] keeps the number of children.
const COUNT_SHIFT: u32 = 24;

impl<R: Real> Node<R> {
    /// The number of children (lanes 0 to count − 1).
    #[inline(always)]
    fn count(&self) -> usize {
        (self.order[0] >> COUNT_SHIFT) as usize
    }

    /// The mask of the lanes that hold a child.
    #[inline(always)]
    fn used(&self) -> u32 {
        (1u32 << self.count()) - 1
    }

    /// Each child of the lanes in `met` (children some ray met), for the octant `octant`, in
    /// the order a traversal pushes them (the last the binary traversal visits first): its
    /// lane and reference to `push`.
    #[inline(always)]
    fn push_met(&self, octant: usize, met: u32, mut push: impl FnMut(usize, Ref)) {
        let mut order = self.order[octant];
        for _ in 0..self.count() {
            let k = (order & 7) as usize;
            order >>= 3;
            if met & (1 << k) != 0 {
                push(k, self.child.as_ref()[k]);
            }
        }
    }
}

/// Up to [`Wide::LANES`] spheres of one binary leaf, in its order.
#[derive(Clone, Debug)]
struct SphereLeaf<R: Real> {
    center: W3<W<R>>,
    /// r², as the scalar code forms it.
    r2: W<R>,
    used: u32,
    /// Each lane's shape index (in the aggregate's order).
    shape: <W<R> as Wide>::Indices,
}

/// Up to [`Wide::LANES`] triangles of one binary leaf, in its order: corner i, axis a.
#[derive(Clone, Debug)]
struct TriangleLeaf<R: Real> {
    p: [[W<R>; 3]; 3],
    /// The lanes that hold a triangle the scalar test can hit (not degenerate).
    used: u32,
    /// The lanes that hold a triangle (for the tests).
    #[cfg_attr(not(test), allow(dead_code))]
    held: u32,
    shape: <W<R> as Wide>::Indices,
}

/// A binary BVH collapsed into [`Wide::LANES`]-wide nodes with SoA leaves.
#[derive(Clone, Debug)]
pub(crate) struct WideBvh<R: Real> {
    nodes: Vec<Node<R>>,
    spheres: Vec<SphereLeaf<R>>,
    triangles: Vec<TriangleLeaf<R>>,
    /// Leaves that hold both kinds: ranges of `mixed_shapes`, tested by the scalar code.
    mixed: Vec<(u32, u32)>,
    mixed_shapes: Vec<u32>,
    /// The root, and its box (tested when the root is a leaf).
    root: Option<(Ref, Aabb<R>)>,
}

/// |x| per lane, +0 for ±0, as the scalar `abs` gives.
#[inline(always)]
fn abs<L: Wide>(x: L) -> L {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    x.gt(zero).select(x, zero - x)
}

/// max(a, b) per lane, the scalar `max` of numbers that are not NaN.
#[inline(always)]
fn max<L: Wide>(a: L, b: L) -> L {
    a.lt(b).select(b, a)
}

/// a ≤ b per lane (false where either is NaN), by one comparison.
#[inline(always)]
fn le<L: Lanes<Mask = L>>(a: L, b: L) -> L {
    a.at_most(b)
}

/// One end of a slab interval narrowed by a plane's distance: `t` where `t < end`, else `end`
/// (a NaN `t`, from 0·∞, leaves the end as it is), by one minimum instruction rather than a
/// comparison and a blend. The interval's far end narrows as [`Aabb::hit`]'s `t_far < t1`;
/// its near end is kept negated, −t₀, so that "t_near > t₀" becomes "−t_near < −t₀", and
/// −t_near is computed as (O − near)·(1/D), which is −((near − O)·(1/D)) to the bit (IEEE
/// rounding is symmetric), so the negated end is the scalar end, negated, to the bit.
#[inline(always)]
fn narrow<L: Lanes>(t: L, end: L) -> L {
    t.minimum(end)
}

/// The ray as the traversal uses it: per-axis origin and 1/D in lanes, the octant, and the
/// sphere and triangle tests' forms.
struct Prepared<R: Real> {
    o: [W<R>; 3],
    inv: [W<R>; 3],
    /// Per axis, which of a node's `bounds` is the near side (1 where 1/D < 0).
    near: [usize; 3],
    octant: usize,
    o3: W3<W<R>>,
    d3: W3<W<R>>,
    shear: Shear<R>,
}

impl<R: Real> Prepared<R> {
    /// The ray's forms; the shear only when `triangles` (three divisions saved otherwise).
    #[inline]
    fn of(ray: &Ray<R>, triangles: bool) -> Self {
        let inv = inverse::<R>(ray.direction).to_array();
        let o = ray.origin.to_array();
        let neg = inv.map(|x| x < R::ZERO);
        let o = o.map(W::<R>::splat);
        Prepared {
            o,
            inv: inv.map(W::<R>::splat),
            near: neg.map(usize::from),
            octant: usize::from(neg[0]) | (usize::from(neg[1]) << 1) | (usize::from(neg[2]) << 2),
            o3: W3 {
                x: o[0],
                y: o[1],
                z: o[2],
            },
            d3: W3::splat(ray.direction),
            shear: if triangles {
                Shear::of(ray)
            } else {
                Shear {
                    k: [0, 1, 2],
                    sx: R::ZERO,
                    sy: R::ZERO,
                    sz: R::ZERO,
                }
            },
        }
    }
}

/// [`Aabb::hit`] of each child box of a node: the mask of children met within [0, t_max] and
/// each lane's t₀.
#[inline(always)]
fn slab<R: Real>(node: &Node<R>, r: &Prepared<R>, t_max: R) -> (u32, W<R>) {
    let widen = W::<R>::splat(R::ONE + R::TWO * gamma::<R>(3));
    // −t₀, so that both ends narrow by a minimum (see `narrow`)
    let mut t0 = W::<R>::splat(-R::ZERO);
    let mut t1 = W::<R>::splat(t_max);
    for a in 0..3 {
        // Near and far planes by the sign of 1/D, as the scalar test picks them
        let near = node.bounds[r.near[a] & 1][a];
        let far = node.bounds[(r.near[a] & 1) ^ 1][a];
        let t_near = (r.o[a] - near) * r.inv[a];
        let t_far = (far - r.o[a]) * r.inv[a] * widen;
        t0 = narrow(t_near, t0);
        t1 = narrow(t_far, t1);
    }
    let t0 = Wide::neg(t0);
    // t0 ≤ t1, as the scalar test ends (t0 cannot be NaN)
    (le(t0, t1).bits() & node.used(), t0)
}

/// [`Shape::hit_t`] of each triangle of a leaf against one ray (the watertight test of
/// [`super::Triangle::intersect`], operation for operation): the mask of hits with
/// 0 < t < `t_max`, their t, and the lanes left to the scalar code (f32 edge functions of 0,
/// which the scalar code recomputes in f64).
#[inline(always)]
fn triangle_hit_t<R: Real>(leaf: &TriangleLeaf<R>, r: &Prepared<R>, t_max: R) -> (u32, W<R>, u32) {
    let zero = W::<R>::splat(R::ZERO);
    let [kx, ky, kz] = r.shear.k;
    let (sx, sy, sz) = (
        W::<R>::splat(r.shear.sx),
        W::<R>::splat(r.shear.sy),
        W::<R>::splat(r.shear.sz),
    );
    // Translate to the origin, permute, shear
    let q = leaf
        .p
        .map(|c| [c[0] - r.o[0], c[1] - r.o[1], c[2] - r.o[2]]);
    let x = q.map(|c| c[kx] + sx * c[kz]);
    let y = q.map(|c| c[ky] + sy * c[kz]);
    let e = [
        x[1] * y[2] - y[1] * x[2],
        x[2] * y[0] - y[2] * x[0],
        x[0] * y[1] - y[0] * x[1],
    ];
    let slow = if R::EPSILON.to_f64() > f64::EPSILON {
        e[0].eq(zero).or(e[1].eq(zero)).or(e[2].eq(zero)).bits() & leaf.used
    } else {
        0
    };
    let any_neg = e[0].lt(zero).or(e[1].lt(zero)).or(e[2].lt(zero));
    let any_pos = e[0].gt(zero).or(e[1].gt(zero)).or(e[2].gt(zero));
    let det = e[0] + e[1] + e[2];
    // Most lanes miss most triangles by the edge tests: where none is left, stop here.
    let inside = any_neg.and(any_pos).not().and(det.eq(zero).not());
    if inside.bits() & leaf.used & !slow == 0 {
        return (0, zero, slow);
    }
    let z = q.map(|c| c[kz] * sz);
    let t_scaled = e[0] * z[0] + e[1] * z[1] + e[2] * z[2];
    // The scaled distance against the ray's range (NaN fails both branches)
    let t_max_w = W::<R>::splat(t_max);
    let limit = t_max_w * det;
    let in_range = det.gt(zero).select(
        t_scaled.gt(zero).and(le(t_scaled, limit)),
        t_scaled.lt(zero).and(le(limit, t_scaled)),
    );
    let inv_det = W::<R>::splat(R::ONE) / det;
    let t = t_scaled * inv_det;
    // t conservatively greater than zero (§6.8.4), as the scalar code bounds it
    let max_abs = |v: [W<R>; 3]| max(max(abs(v[0]), abs(v[1])), abs(v[2]));
    let g = |n| W::<R>::splat(gamma::<R>(n));
    let max_zt = max_abs(z);
    let delta_z = g(3) * max_zt;
    let (max_xt, max_yt) = (max_abs(x), max_abs(y));
    let delta_x = g(5) * (max_xt + max_zt);
    let delta_y = g(5) * (max_yt + max_zt);
    let delta_e =
        W::<R>::splat(R::TWO) * (g(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    let max_e = max_abs(e);
    let delta_t = W::<R>::splat(R::from_f64(3.0))
        * (g(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e)
        * abs(inv_det);
    let hit = inside.and(in_range).and(t.lt(t_max_w)).and(t.gt(delta_t));
    (hit.bits() & leaf.used & !slow, t, slow)
}

/// A node under construction: the binary nodes that become its children.
struct Cut {
    nodes: Vec<usize>,
}

/// A binary leaf's shapes, in its order.
#[derive(Clone, Copy)]
struct Ids<'a> {
    prims: &'a [u32],
    shape_of: &'a [u32],
}

impl Ids<'_> {
    fn len(&self) -> usize {
        self.prims.len()
    }

    fn iter(&self) -> impl Iterator<Item = u32> + '_ {
        self.prims.iter().map(|&p| self.shape_of[p as usize])
    }
}

impl<R: Real> WideBvh<R> {
    /// The wide tree of `bvh`, whose primitive k is `shapes[shape_of[k]]` (a sphere or a
    /// triangle). `bvh` should have leaves of at most [`Wide::LANES`] primitives
    /// ([`Bvh::build_with_leaves`]); bigger leaves are tested by the scalar code.
    pub(crate) fn new(bvh: &Bvh<R>, shape_of: &[u32], shapes: &[Shape<R>]) -> Self {
        let mut w = WideBvh {
            nodes: Vec::new(),
            spheres: Vec::new(),
            triangles: Vec::new(),
            mixed: Vec::new(),
            mixed_shapes: Vec::new(),
            root: None,
        };
        if let Some(root) = bvh.nodes().first() {
            // At most one node per binary interior node (leaves − 1 of them; pages never
            // written are never resident), one leaf per binary leaf.
            let leaves = bvh.nodes().iter().filter(|n| n.count > 0).count();
            w.nodes.reserve(leaves);
            w.spheres.reserve(leaves);
            let r = w.collapse(bvh, 0, shape_of, shapes);
            w.root = Some((r, root.bounds));
        }
        w
    }

    /// The surface area of a binary node's box, in f64 (only compared).
    fn area(bvh: &Bvh<R>, i: usize) -> f64 {
        let b = &bvh.nodes()[i].bounds;
        let (lo, hi) = (b.min.to_array(), b.max.to_array());
        let d = [0, 1, 2].map(|a| hi[a].to_f64() - lo[a].to_f64());
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    }

    /// The binary node `i` as a reference: a leaf as it is, an interior node collapsed with
    /// its descendants into a wide node.
    fn collapse(&mut self, bvh: &Bvh<R>, i: usize, shape_of: &[u32], shapes: &[Shape<R>]) -> Ref {
        let lanes = W::<R>::LANES;
        let node = bvh.nodes()[i];
        if node.count > 0 {
            let first = node.offset as usize;
            let prims = &bvh.prims()[first..first + node.count as usize];
            return self.leaf(prims, shape_of, shapes);
        }
        // Open the interior node of largest area until the node is full (the first on a tie);
        // the cut stays in depth-first order.
        let mut cut = Cut {
            nodes: vec![i + 1, node.offset as usize],
        };
        while cut.nodes.len() < lanes {
            let mut best: Option<(usize, f64)> = None;
            for (k, &n) in cut.nodes.iter().enumerate() {
                if bvh.nodes()[n].count == 0 {
                    let a = Self::area(bvh, n);
                    if best.is_none_or(|(_, b)| a > b) {
                        best = Some((k, a));
                    }
                }
            }
            let Some((k, _)) = best else { break };
            let n = cut.nodes[k];
            let second = bvh.nodes()[n].offset as usize;
            cut.nodes.splice(k..=k, [n + 1, second]);
        }
        // The binary traversal's order of the cut, for each octant of D
        let (order, _) = visit_orders(bvh, i, &cut.nodes);
        let at = self.nodes.len();
        let empty = Aabb::<R>::empty();
        let mut min = [<W<R> as Wide>::Array::default(); 3];
        let mut max = [<W<R> as Wide>::Array::default(); 3];
        for k in 0..lanes {
            let b = cut.nodes.get(k).map_or(empty, |&n| bvh.nodes()[n].bounds);
            let (lo, hi) = (b.min.to_array(), b.max.to_array());
            for a in 0..3 {
                min[a].as_mut()[k] = lo[a];
                max[a].as_mut()[k] = hi[a];
            }
        }
        let count = (cut.nodes.len() as u32) << COUNT_SHIFT;
        self.nodes.push(Node {
            bounds: [min.map(W::<R>::from_array), max.map(W::<R>::from_array)],
            child: Default::default(),
            order: order.map(|o| o | count),
        });
        for (k, &n) in cut.nodes.iter().enumerate() {
            let r = self.collapse(bvh, n, shape_of, shapes);
            self.nodes[at].child.as_mut()[k] = r;
        }
        reference(NODE, at)
    }

    /// A leaf of the binary leaf's primitives `prims` (in its order), primitive k being
    /// `shapes[shape_of[k]]`.
    fn leaf(&mut self, prims: &[u32], shape_of: &[u32], shapes: &[Shape<R>]) -> Ref {
        let lanes = W::<R>::LANES;
        let ids = Ids { prims, shape_of };
        let all = |f: fn(&Shape<R>) -> bool| ids.iter().all(|i| f(&shapes[i as usize]));
        let mut shape = <W<R> as Wide>::Indices::default();
        if ids.len() <= lanes && all(|s| matches!(s, Shape::Sphere(_))) {
            let mut c = [<W<R> as Wide>::Array::default(); 3];
            let mut r2 = <W<R> as Wide>::Array::default();
            for (k, i) in ids.iter().enumerate() {
                let Shape::Sphere(s) = shapes[i as usize] else {
                    unreachable!("all spheres")
                };
                let p = s.center.to_array();
                for a in 0..3 {
                    c[a].as_mut()[k] = p[a];
                }
                r2.as_mut()[k] = s.radius * s.radius;
                shape.as_mut()[k] = i;
            }
            let [x, y, z] = c.map(W::<R>::from_array);
            self.spheres.push(SphereLeaf {
                center: W3 { x, y, z },
                r2: W::<R>::from_array(r2),
                used: (1u32 << ids.len()) - 1,
                shape,
            });
            return reference(SPHERES, self.spheres.len() - 1);
        }
        if ids.len() <= lanes && all(|s| matches!(s, Shape::Triangle(_))) {
            let mut p = [[<W<R> as Wide>::Array::default(); 3]; 3];
            let mut used = 0;
            for (k, i) in ids.iter().enumerate() {
                let Shape::Triangle(t) = &shapes[i as usize] else {
                    unreachable!("all triangles")
                };
                for (corner, v) in t.p.iter().enumerate() {
                    let v = v.to_array();
                    for a in 0..3 {
                        p[corner][a].as_mut()[k] = v[a];
                    }
                }
                // The scalar test's first step: a triangle with a zero cross product is never hit.
                let [p0, p1, p2] = t.p;
                if (p2 - p0).cross(p1 - p0) != V3::<R>::ZERO {
                    used |= 1 << k;
                }
                shape.as_mut()[k] = i;
            }
            self.triangles.push(TriangleLeaf {
                p: p.map(|c| c.map(W::<R>::from_array)),
                used,
                held: (1u32 << ids.len()) - 1,
                shape,
            });
            return reference(TRIANGLES, self.triangles.len() - 1);
        }
        let first = self.mixed_shapes.len() as u32;
        self.mixed_shapes.extend(ids.iter());
        self.mixed.push((first, ids.len() as u32));
        reference(MIXED, self.mixed.len() - 1)
    }

    /// Visits the leaves the ray meets within [0, t_max] in the binary traversal's order until
    /// `leaf` returns true; `leaf` may lower t_max, which prunes the rest.
    #[inline(always)]
    fn traverse(
        &self,
        r: &Prepared<R>,
        ray: &Ray<R>,
        t_max: R,
        mut leaf: impl FnMut(Ref, &mut R) -> bool,
    ) {
        let Some((root, root_box)) = self.root else {
            return;
        };
        let mut t_max = t_max;
        if root >> KIND != NODE {
            if root_box.hit(ray.origin, inverse::<R>(ray.direction), t_max) {
                leaf(root, &mut t_max);
            }
            return;
        }
        self.traverse_from(r, &mut Stack::new(), root, t_max, leaf);
    }

    /// [`WideBvh::traverse`] of the subtree under `start` (a node or a leaf the ray has
    /// reached with this t_max), as the whole search would visit it, on `stack` (emptied
    /// first: the packet searches lend one stack to all the rays they send on alone, which
    /// saves clearing a new one for each).
    #[inline(always)]
    fn traverse_from(
        &self,
        r: &Prepared<R>,
        stack: &mut Stack<R>,
        start: Ref,
        t_max: R,
        mut leaf: impl FnMut(Ref, &mut R) -> bool,
    ) {
        let mut t_max = t_max;
        stack.clear();
        let mut cur = start;
        loop {
            if cur >> KIND == NODE {
                let node = &self.nodes[(cur & INDEX) as usize];
                let (hit, t0) = slab(node, r, t_max);
                if hit != 0 && hit & (hit - 1) == 0 {
                    // One child met: straight into it (t_max has not changed since its test)
                    cur = node.child.as_ref()[hit.trailing_zeros() as usize];
                    continue;
                }
                if hit != 0 {
                    let t0 = t0.to_array();
                    // Pushed last to first, so the first in the binary order comes off first
                    node.push_met(r.octant, hit, |k, child| stack.push(child, t0.as_ref()[k]));
                }
            } else if leaf(cur, &mut t_max) {
                return;
            }
            // The next child whose box is still met before the (perhaps lowered) t_max
            loop {
                match stack.pop() {
                    None => return,
                    Some((next, t0)) if t0 <= t_max => {
                        cur = next;
                        break;
                    }
                    Some(_) => {}
                }
            }
        }
    }

    /// The nearest hit with 0 < t < `t_max`, its shape index and t: [`Bvh::nearest`] over the
    /// tree this one was collapsed from, with [`Shape::hit_t`] as the test, to the bit.
    #[inline]
    pub(crate) fn nearest(&self, shapes: &[Shape<R>], ray: &Ray<R>, t_max: R) -> Option<(u32, R)> {
        let r = Prepared::of(ray, !self.triangles.is_empty());
        let mut best = None;
        self.traverse(&r, ray, t_max, |leaf, t_max| {
            if let Some(i) = self.nearest_leaf(shapes, &r, ray, leaf, t_max) {
                best = Some((i, *t_max));
            }
            false
        });
        best
    }

    /// The shapes of `leaf` against one ray, in the binary leaf's order, each hit nearer than
    /// `t_max` lowering it: the last shape accepted (its t is then `t_max`), if any.
    #[inline(always)]
    fn nearest_leaf(
        &self,
        shapes: &[Shape<R>],
        r: &Prepared<R>,
        ray: &Ray<R>,
        leaf: Ref,
        t_max: &mut R,
    ) -> Option<u32> {
        let index = (leaf & INDEX) as usize;
        let mut best = None;
        match leaf >> KIND {
            SPHERES => {
                let l = &self.spheres[index];
                let (hit, t, slow) =
                    sphere_hit_t(r.o3, r.d3, l.center, l.r2, W::<R>::splat(*t_max));
                let (hit, slow) = (hit.bits() & l.used, slow.bits() & l.used);
                if hit | slow != 0 {
                    let t = t.to_array();
                    for k in lanes_of(hit | slow) {
                        let found = if slow & (1 << k) != 0 {
                            shapes[l.shape.as_ref()[k] as usize].hit_t(ray, *t_max)
                        } else {
                            // A sphere's t does not depend on t_max: only whether it counts.
                            Some(t.as_ref()[k]).filter(|&t| t < *t_max)
                        };
                        if let Some(t) = found {
                            *t_max = t;
                            best = Some(l.shape.as_ref()[k]);
                        }
                    }
                }
            }
            TRIANGLES => {
                let l = &self.triangles[index];
                let (hit, t, slow) = triangle_hit_t(l, r, *t_max);
                if hit | slow != 0 {
                    let t = t.to_array();
                    let mut lowered = false;
                    for k in lanes_of(hit | slow) {
                        let found = if lowered || slow & (1 << k) != 0 {
                            shapes[l.shape.as_ref()[k] as usize].hit_t(ray, *t_max)
                        } else {
                            Some(t.as_ref()[k])
                        };
                        if let Some(t) = found {
                            *t_max = t;
                            lowered = true;
                            best = Some(l.shape.as_ref()[k]);
                        }
                    }
                }
            }
            _ => {
                let (first, count) = self.mixed[index];
                for &i in &self.mixed_shapes[first as usize..(first + count) as usize] {
                    if let Some(t) = shapes[i as usize].hit_t(ray, *t_max) {
                        *t_max = t;
                        best = Some(i);
                    }
                }
            }
        }
        best
    }

    /// Whether some shape meets the ray with 0 < t < `t_max` (shadow rays), stopping at the
    /// first: `Bvh::any`'s answer over the tree this one was collapsed from.
    #[inline]
    pub(crate) fn occluded(&self, shapes: &[Shape<R>], ray: &Ray<R>, t_max: R) -> bool {
        let r = Prepared::of(ray, !self.triangles.is_empty());
        let mut found = false;
        self.traverse(&r, ray, t_max, |leaf, t_max| {
            found = self.occluded_leaf(shapes, &r, ray, leaf, *t_max);
            found
        });
        found
    }

    /// Whether some shape of `leaf` meets the ray with 0 < t < `t_max`.
    #[inline(always)]
    fn occluded_leaf(
        &self,
        shapes: &[Shape<R>],
        r: &Prepared<R>,
        ray: &Ray<R>,
        leaf: Ref,
        t_max: R,
    ) -> bool {
        let index = (leaf & INDEX) as usize;
        let scalar = |i: u32| shapes[i as usize].hit_t(ray, t_max).is_some();
        match leaf >> KIND {
            SPHERES => {
                let l = &self.spheres[index];
                let (hit, _, slow) = sphere_hit_t(r.o3, r.d3, l.center, l.r2, W::<R>::splat(t_max));
                hit.bits() & l.used != 0
                    || lanes_of(slow.bits() & l.used).any(|k| scalar(l.shape.as_ref()[k]))
            }
            TRIANGLES => {
                let l = &self.triangles[index];
                let (hit, _, slow) = triangle_hit_t(l, r, t_max);
                hit != 0 || lanes_of(slow).any(|k| scalar(l.shape.as_ref()[k]))
            }
            _ => {
                let (first, count) = self.mixed[index];
                self.mixed_shapes[first as usize..(first + count) as usize]
                    .iter()
                    .any(|&i| scalar(i))
            }
        }
    }
}

/// A packet of rays in lanes (lane k the packet's ray k): origins, 1/D and directions, for the
/// slab tests of one child box against every ray and the sphere tests of one sphere against
/// every ray. Lanes past the packet's end repeat its first ray and are never active.
struct Packet<R: Real> {
    inv: [W<R>; 3],
    o3: W3<W<R>>,
    d3: W3<W<R>>,
    /// Per axis, the mask of the rays whose 1/D is negative: ray k's octant of D, as
    /// [`Prepared`] has it, is bit k of each (kept as three masks: spreading them into a byte
    /// per ray was a quarter of the packet's making).
    neg: [u32; 3],
}

impl<R: Real> Packet<R> {
    /// The packet of the rays whose origins and directions are `o3` and `d3` in lanes (the
    /// caller's gather, which its planes' test used first): 1/D by a division in lanes, each
    /// lane's the scalar `inverse`'s to the bit.
    #[inline(always)]
    fn of(o3: W3<W<R>>, d3: W3<W<R>>) -> Self {
        let one = W::<R>::splat(R::ONE);
        let inv = [one / d3.x, one / d3.y, one / d3.z];
        let zero = W::<R>::splat(R::ZERO);
        let neg = inv.map(|i| i.lt(zero).bits());
        Packet { inv, o3, d3, neg }
    }

    /// Ray k, as its lanes hold it.
    #[inline(always)]
    fn ray(&self, k: usize) -> Ray<R> {
        lane_ray((self.o3, self.d3), k)
    }

    /// Ray k's octant of D.
    #[inline(always)]
    fn octant(&self, k: usize) -> u8 {
        (0..3).fold(0, |o, a| o | ((self.neg[a] >> k & 1) as u8) << a)
    }

    /// The lanes of `live` whose ray has octant `o`.
    #[inline(always)]
    fn lanes_in(&self, o: u8, live: u32) -> u32 {
        (0..3).fold(live, |m, a| {
            m & if o >> a & 1 == 1 {
                self.neg[a]
            } else {
                !self.neg[a]
            }
        })
    }
}

/// [`Aabb::hit`] of one box against every ray of a packet whose rays share the octant whose
/// near sides are `near` (the box's near and far planes by axis): the mask of the rays that
/// meet it within [0, t_max] and each ray's t₀. Lane for lane, the arithmetic of [`slab`].
#[inline(always)]
fn slab_rays<R: Real>(near: [R; 3], far: [R; 3], p: &Packet<R>, t_max: W<R>) -> (u32, W<R>) {
    let widen = W::<R>::splat(R::ONE + R::TWO * gamma::<R>(3));
    let mut t0 = W::<R>::splat(-R::ZERO);
    let mut t1 = t_max;
    let o = [p.o3.x, p.o3.y, p.o3.z];
    for a in 0..3 {
        let t_near = (o[a] - W::<R>::splat(near[a])) * p.inv[a];
        let t_far = (W::<R>::splat(far[a]) - o[a]) * p.inv[a] * widen;
        t0 = narrow(t_near, t0);
        t1 = narrow(t_far, t1);
    }
    let t0 = Wide::neg(t0);
    (le(t0, t1).bits(), t0)
}

/// Rays the packet traversal takes on together: with this many or fewer, each ray goes on by
/// itself (the lanes of the rays that left would be computed for nothing). A packet goes on
/// with 2 rays or more, in every width. In instructions (callgrind, AVX2 build) 8 lanes paid
/// with 4 rays or more (with 2: 1.5 % more instructions); in time the packet pays sooner, as a
/// ray alone first makes its own forms of the ray (850 bytes in f64 of 8 lanes) and branches
/// more: medians of 9-11 alternating rounds of the 10,000- and 100,000-sphere traces, one
/// thread, going on alone with 3 rays left or fewer against 1: f64 in 8 lanes (AVX-512)
/// 0.070 / 0.074 s against 0.066 / 0.070 s; f32 built for AVX-512 0.060 / 0.063 s against
/// 0.058 / 0.060 s, built for AVX2 0.060 / 0.064 s against 0.056 / 0.061 s. (f64 in 4 lanes
/// had the rule already.)
const FEW: usize = 1;

/// The nearest-hit packet search's stack: references with the mask of the rays that met the box
/// and each ray's t₀ of it (as an array: a register's alignment would pad each entry to twice
/// its size).
struct PacketStack<R: Real>(SmallVec<[(LaneArray<R>, Ref, u32); STACK]>);

/// A register of `R` as an array.
type LaneArray<R> = <W<R> as Wide>::Array;

impl<R: Real> PacketStack<R> {
    #[inline(always)]
    fn new() -> Self {
        PacketStack(SmallVec::new())
    }

    #[inline(always)]
    fn push(&mut self, r: Ref, mask: u32, t0: W<R>) {
        self.0.push((t0.to_array(), r, mask));
    }

    /// Pops entries until one has a ray, of its mask, whose box it met at a t₀ ≤ that ray's
    /// (perhaps lowered) `t_max`: that entry's node and those rays; `None` once the stack is
    /// empty.
    #[inline(always)]
    fn pop_met(&mut self, t_max: W<R>) -> Option<(Ref, u32)> {
        while let Some((t0, next, mask)) = self.0.pop() {
            let still = mask & le(W::<R>::from_array(t0), t_max).bits();
            if still != 0 {
                return Some((next, still));
            }
        }
        None
    }
}

/// The any-hit packet search's stack: references with the mask of the rays that met the box.
/// No t₀: a ray's t_max does not change in this search, and each entry's rays met its box
/// within it.
struct OpenStack(SmallVec<[(Ref, u32); STACK]>);

impl OpenStack {
    #[inline(always)]
    fn new() -> Self {
        OpenStack(SmallVec::new())
    }

    #[inline(always)]
    fn push(&mut self, r: Ref, mask: u32) {
        self.0.push((r, mask));
    }

    /// Pops entries until one has a ray of its mask not in `done` (the rays already blocked):
    /// that entry's node and those rays; `None` once the stack is empty.
    #[inline(always)]
    fn pop_open(&mut self, done: u32) -> Option<(Ref, u32)> {
        while let Some((next, mask)) = self.0.pop() {
            if mask & !done != 0 {
                return Some((next, mask & !done));
            }
        }
        None
    }
}

/// Each ray's one-ray form, made when a leaf of triangles (or of both kinds) first needs it.
struct Lazy<R: Real> {
    prepared: [Option<Prepared<R>>; MAX_WIDTH],
}

impl<R: Real> Lazy<R> {
    fn new() -> Self {
        Lazy {
            prepared: std::array::from_fn(|_| None),
        }
    }

    #[inline]
    fn get(&mut self, k: usize, ray: &Ray<R>, triangles: bool) -> &Prepared<R> {
        self.prepared[k].get_or_insert_with(|| Prepared::of(ray, triangles))
    }
}

/// **Packets.** A packet of up to [`Wide::LANES`] rays goes down the tree together, one octant
/// of D at a time (the rays of other octants wait for their own pass): each child box is
/// tested against every ray of the packet in lanes, and each ray goes on only into the boxes
/// its own test passed. For one octant the binary traversal's order of a node's children is
/// the same for every ray, so each ray meets its leaves in its own one-ray order with its own
/// t_max at each (the rays' searches only interleave), and its answer is the one-ray search's,
/// to the bit: the nearest (shape, t), ties included, and the same occlusion.
impl<R: Real> WideBvh<R> {
    /// [`WideBvh::nearest`] of each ray of `rays` (at most [`Wide::LANES`]) in `live`, from its
    /// `t_max[k]`: where the search accepts a hit, `t_max[k]` becomes its t and `best[k]` its
    /// shape.
    pub(crate) fn nearest_packet(
        &self,
        shapes: &[Shape<R>],
        rays: &[Ray<R>],
        (o3, d3): RayLanes<R>,
        live: u32,
        t_max: &mut [R],
        best: &mut [Option<u32>],
    ) {
        let Some((root, _)) = self.root else {
            return;
        };
        if root >> KIND != NODE || live.count_ones() < 2 {
            for k in lanes_of(live) {
                if let Some((i, t)) = self.nearest(shapes, &rays[k], t_max[k]) {
                    (t_max[k], best[k]) = (t, Some(i));
                }
            }
            return;
        }
        let p = Packet::of(o3, d3);
        let mut tm = <W<R> as Wide>::Array::default();
        tm.as_mut()[..rays.len()].copy_from_slice(&t_max[..rays.len()]);
        let mut tm = W::<R>::from_array(tm);
        let mut lazy = Lazy::new();
        let mut left = live;
        while left != 0 {
            let octant = p.octant(left.trailing_zeros() as usize);
            let group = p.lanes_in(octant, left);
            left &= !group;
            self.nearest_group(shapes, rays, &p, &mut lazy, octant, group, &mut tm, best);
        }
        let tm = tm.to_array();
        for k in lanes_of(live) {
            t_max[k] = tm.as_ref()[k];
        }
    }

    /// One octant's pass of [`WideBvh::nearest_packet`]: the rays of `group`, with their t_max
    /// in `tm`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn nearest_group(
        &self,
        shapes: &[Shape<R>],
        rays: &[Ray<R>],
        p: &Packet<R>,
        lazy: &mut Lazy<R>,
        octant: u8,
        group: u32,
        tm: &mut W<R>,
        best: &mut [Option<u32>],
    ) {
        let Some((root, _)) = self.root else {
            return;
        };
        let mut stack = PacketStack::<R>::new();
        let mut alone = Stack::<R>::new();
        let (mut cur, mut active) = (root, group);
        let mut masks = [0u32; MAX_WIDTH];
        let mut t0 = [W::<R>::splat(R::ZERO); MAX_WIDTH];
        loop {
            if active.count_ones() as usize <= FEW {
                // Too few rays left for lanes to pay: each finishes this subtree alone.
                let mut a = tm.to_array();
                for k in lanes_of(active) {
                    let r = lazy.get(k, &rays[k], !self.triangles.is_empty());
                    let ray = &rays[k];
                    let mut t_k = a.as_ref()[k];
                    self.traverse_from(r, &mut alone, cur, t_k, |leaf, t_max| {
                        if let Some(i) = self.nearest_leaf(shapes, r, ray, leaf, t_max) {
                            best[k] = Some(i);
                            t_k = *t_max;
                        }
                        false
                    });
                    a.as_mut()[k] = t_k;
                }
                *tm = W::<R>::from_array(a);
            } else if cur >> KIND == NODE {
                let node = &self.nodes[(cur & INDEX) as usize];
                let met = self.children(node, p, octant, active, *tm, &mut masks, &mut t0);
                if met != 0 && met & (met - 1) == 0 {
                    // One child met by any ray: straight into it with the rays that met it.
                    let k = met.trailing_zeros() as usize;
                    (cur, active) = (node.child.as_ref()[k], masks[k]);
                    continue;
                }
                if met != 0 {
                    node.push_met(octant as usize, met, |k, child| {
                        stack.push(child, masks[k], t0[k]);
                    });
                }
            } else {
                self.nearest_leaf_packet(shapes, rays, p, lazy, cur, active, tm, best);
            }
            // The next entry with a ray whose box is still met before its (perhaps lowered)
            // t_max
            match stack.pop_met(*tm) {
                None => return,
                Some(next) => (cur, active) = next,
            }
        }
    }

    /// Each child box of `node` against the rays of `active` (of one octant): per child, the
    /// rays that meet it (`masks`) and their t₀; the mask of the children some ray meets.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn children(
        &self,
        node: &Node<R>,
        p: &Packet<R>,
        octant: u8,
        active: u32,
        tm: W<R>,
        masks: &mut [u32; MAX_WIDTH],
        t0: &mut [W<R>; MAX_WIDTH],
    ) -> u32 {
        let side = [0, 1, 2].map(|a| usize::from(octant >> a & 1));
        // Read in place, child by child (copied out, the 24 numbers were loaded at once and
        // spilled)
        let near = [0, 1, 2].map(|a| node.bounds[side[a]][a].as_array());
        let far = [0, 1, 2].map(|a| node.bounds[side[a] ^ 1][a].as_array());
        let mut met = 0;
        for c in 0..node.count() {
            let (m, t) = slab_rays(
                [
                    near[0].as_ref()[c],
                    near[1].as_ref()[c],
                    near[2].as_ref()[c],
                ],
                [far[0].as_ref()[c], far[1].as_ref()[c], far[2].as_ref()[c]],
                p,
                tm,
            );
            masks[c] = m & active;
            t0[c] = t;
            met |= u32::from(masks[c] != 0) << c;
        }
        met
    }

    /// The shapes of `leaf` against the rays of `active`: a leaf of spheres one sphere at a
    /// time against the packet in lanes (each ray's hits in the leaf's order, as the one-ray
    /// test takes them), other leaves by the one-ray test, ray by ray.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn nearest_leaf_packet(
        &self,
        shapes: &[Shape<R>],
        rays: &[Ray<R>],
        p: &Packet<R>,
        lazy: &mut Lazy<R>,
        leaf: Ref,
        active: u32,
        tm: &mut W<R>,
        best: &mut [Option<u32>],
    ) {
        if leaf >> KIND == SPHERES {
            let l = &self.spheres[(leaf & INDEX) as usize];
            let (cx, cy, cz) = (
                l.center.x.as_array(),
                l.center.y.as_array(),
                l.center.z.as_array(),
            );
            let r2 = l.r2.as_array();
            let lanes = mask_of::<W<R>>(active);
            for s in lanes_of(l.used) {
                let c = W3 {
                    x: W::<R>::splat(cx.as_ref()[s]),
                    y: W::<R>::splat(cy.as_ref()[s]),
                    z: W::<R>::splat(cz.as_ref()[s]),
                };
                // Past the cheap test only where some ray of the packet that met the leaf
                // may hit the sphere.
                let Some((hit, t, slow)) =
                    sphere_hit_t_in(p.o3, p.d3, c, W::<R>::splat(r2.as_ref()[s]), *tm, active)
                else {
                    continue;
                };
                let (hit_bits, slow) = (hit.bits() & active, slow.bits() & active);
                if hit_bits | slow == 0 {
                    continue;
                }
                let shape = l.shape.as_ref()[s];
                if hit_bits != 0 {
                    let take = hit.and(lanes);
                    *tm = take.select(t, *tm);
                    for k in lanes_of(hit_bits) {
                        best[k] = Some(shape);
                    }
                }
                if slow != 0 {
                    let mut a = tm.to_array();
                    for k in lanes_of(slow) {
                        if let Some(t) = shapes[shape as usize].hit_t(&rays[k], a.as_ref()[k]) {
                            a.as_mut()[k] = t;
                            best[k] = Some(shape);
                        }
                    }
                    *tm = W::<R>::from_array(a);
                }
            }
            return;
        }
        let mut a = tm.to_array();
        for k in lanes_of(active) {
            let r = lazy.get(k, &rays[k], !self.triangles.is_empty());
            if let Some(i) = self.nearest_leaf(shapes, r, &rays[k], leaf, &mut a.as_mut()[k]) {
                best[k] = Some(i);
            }
        }
        *tm = W::<R>::from_array(a);
    }

    /// [`WideBvh::occluded`] of each ray in lanes (`o3`, `d3`; lane k the ray k) in `live`, ray
    /// k to lane k of `t_max`: the mask of the rays something blocks. A ray leaves the packet at
    /// the first shape that blocks it; a ray is made from its lanes only where the one-ray code
    /// needs it.
    pub(crate) fn occluded_packet(
        &self,
        shapes: &[Shape<R>],
        (o3, d3): RayLanes<R>,
        t_max: &LaneArray<R>,
        live: u32,
    ) -> u32 {
        let Some((root, _)) = self.root else {
            return 0;
        };
        if root >> KIND != NODE || live.count_ones() < 2 {
            return lanes_of(live)
                .filter(|&k| self.occluded(shapes, &lane_ray((o3, d3), k), t_max.as_ref()[k]))
                .fold(0, |m, k| m | 1 << k);
        }
        let p = Packet::of(o3, d3);
        let tm = W::<R>::from_array(*t_max);
        let mut lazy = Lazy::new();
        let mut blocked = 0;
        let mut left = live;
        while left != 0 {
            let octant = p.octant(left.trailing_zeros() as usize);
            let group = p.lanes_in(octant, left);
            left &= !group;
            blocked |= self.occluded_group(shapes, &p, &mut lazy, octant, group, tm);
        }
        blocked
    }

    /// One octant's pass of [`WideBvh::occluded_packet`]: the mask of the rays of `group`
    /// something blocks. (The answer does not depend on the order of the visit; the octant's
    /// is taken for its near and far sides.)
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn occluded_group(
        &self,
        shapes: &[Shape<R>],
        p: &Packet<R>,
        lazy: &mut Lazy<R>,
        octant: u8,
        group: u32,
        tm: W<R>,
    ) -> u32 {
        let Some((root, _)) = self.root else {
            return 0;
        };
        let mut stack = OpenStack::new();
        let mut alone = Stack::<R>::new();
        let (mut cur, mut active) = (root, group);
        let mut blocked = 0u32;
        let t_max = tm.to_array();
        let mut masks = [0u32; MAX_WIDTH];
        let mut t0 = [W::<R>::splat(R::ZERO); MAX_WIDTH];
        loop {
            if active.count_ones() as usize <= FEW {
                // Too few rays left for lanes to pay: each searches this subtree alone.
                for k in lanes_of(active) {
                    let (ray, t_k) = (p.ray(k), t_max.as_ref()[k]);
                    let r = lazy.get(k, &ray, !self.triangles.is_empty());
                    let mut found = false;
                    self.traverse_from(r, &mut alone, cur, t_k, |leaf, t_max| {
                        found = self.occluded_leaf(shapes, r, &ray, leaf, *t_max);
                        found
                    });
                    blocked |= u32::from(found) << k;
                }
                if group & !blocked == 0 {
                    return blocked;
                }
            } else if cur >> KIND == NODE {
                let node = &self.nodes[(cur & INDEX) as usize];
                let met = self.children(node, p, octant, active, tm, &mut masks, &mut t0);
                if met != 0 && met & (met - 1) == 0 {
                    let k = met.trailing_zeros() as usize;
                    (cur, active) = (node.child.as_ref()[k], masks[k]);
                    continue;
                }
                node.push_met(octant as usize, met, |k, child| stack.push(child, masks[k]));
            } else {
                let b = self.occluded_leaf_packet(shapes, p, lazy, cur, active, tm, &t_max);
                blocked |= b;
                if group & !blocked == 0 {
                    return blocked;
                }
            }
            // The rays not yet blocked
            match stack.pop_open(blocked) {
                None => return blocked,
                Some(next) => (cur, active) = next,
            }
        }
    }

    /// The rays of `active` some shape of `leaf` blocks.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn occluded_leaf_packet(
        &self,
        shapes: &[Shape<R>],
        p: &Packet<R>,
        lazy: &mut Lazy<R>,
        leaf: Ref,
        active: u32,
        tm: W<R>,
        t_max: &<W<R> as Wide>::Array,
    ) -> u32 {
        let mut blocked = 0;
        if leaf >> KIND == SPHERES {
            let l = &self.spheres[(leaf & INDEX) as usize];
            let (cx, cy, cz) = (
                l.center.x.as_array(),
                l.center.y.as_array(),
                l.center.z.as_array(),
            );
            let r2 = l.r2.as_array();
            for s in lanes_of(l.used) {
                let c = W3 {
                    x: W::<R>::splat(cx.as_ref()[s]),
                    y: W::<R>::splat(cy.as_ref()[s]),
                    z: W::<R>::splat(cz.as_ref()[s]),
                };
                let open = active & !blocked;
                let Some((hit, _, slow)) =
                    sphere_hit_t_in(p.o3, p.d3, c, W::<R>::splat(r2.as_ref()[s]), tm, open)
                else {
                    continue;
                };
                blocked |= hit.bits() & open;
                for k in lanes_of(slow.bits() & open) {
                    if shapes[l.shape.as_ref()[s] as usize]
                        .hit_t(&p.ray(k), t_max.as_ref()[k])
                        .is_some()
                    {
                        blocked |= 1 << k;
                    }
                }
                if active & !blocked == 0 {
                    break;
                }
            }
            return blocked;
        }
        for k in lanes_of(active) {
            let ray = p.ray(k);
            let r = lazy.get(k, &ray, !self.triangles.is_empty());
            if self.occluded_leaf(shapes, r, &ray, leaf, t_max.as_ref()[k]) {
                blocked |= 1 << k;
            }
        }
        blocked
    }
}

/// For each octant of D, the positions in `cut` of the nodes under binary node `i` in the order
/// the binary traversal visits them, 3 bits each, the last visited in the lowest bits (a
/// [`Node`]'s `order`); and how many they are. One walk gives all eight octants: at each
/// binary node the two children's orders are put one after the other, the near child's first
/// (the first child's unless D is negative along the node's axis).
fn visit_orders<R: Real>(bvh: &Bvh<R>, i: usize, cut: &[usize]) -> ([u32; 8], u32) {
    if let Some(k) = cut.iter().position(|&n| n == i) {
        return ([k as u32; 8], 1);
    }
    let node = &bvh.nodes()[i];
    let (first, n_first) = visit_orders(bvh, i + 1, cut);
    let (second, n_second) = visit_orders(bvh, node.offset as usize, cut);
    let order = std::array::from_fn(|octant| {
        if octant >> node.axis & 1 == 1 {
            (second[octant] << (3 * n_first)) | first[octant]
        } else {
            (first[octant] << (3 * n_second)) | second[octant]
        }
    });
    (order, n_first + n_second)
}

/// The traversal stack: references with their box's t₀, [`STACK`] in place, more (never seen
/// in practice) on the heap. A `SmallVec`, so that starting a search writes nothing: a zeroed
/// array was a `memset` per search (2.5 % of a 10,000-sphere render's instructions, with the
/// packet stack's).
struct Stack<R: Real>(SmallVec<[(Ref, R); STACK]>);

impl<R: Real> Stack<R> {
    #[inline(always)]
    fn new() -> Self {
        Stack(SmallVec::new())
    }

    /// Empties the stack.
    #[inline(always)]
    fn clear(&mut self) {
        self.0.clear();
    }

    #[inline(always)]
    fn push(&mut self, r: Ref, t0: R) {
        self.0.push((r, t0));
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<(Ref, R)> {
        self.0.pop()
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngSeed, TestRunner};

    use super::*;
    use crate::core::real::v3;
    use crate::geometry::aggregate::Aggregate;
    use crate::geometry::bounds::test_rng::Rng;
    use crate::geometry::{Plane, Sphere, Triangle};

    /// What the soup is made of.
    #[derive(Clone, Copy, Debug)]
    enum Soup {
        Spheres,
        Triangles,
        /// Both kinds scattered together (leaves of both kinds, tested by the scalar code).
        Mixed,
        /// Spheres and a triangle grid apart (leaves of one kind each), and a plane.
        Apart,
    }

    /// The order of a cut for one octant by the binary traversal itself: descend, near child
    /// first, and note each node of the cut met (the reference of [`visit_orders`]).
    fn walk_order<R: Real>(
        bvh: &Bvh<R>,
        i: usize,
        cut: &[usize],
        octant: usize,
        out: &mut Vec<u32>,
    ) {
        if let Some(k) = cut.iter().position(|&n| n == i) {
            out.push(k as u32);
            return;
        }
        let node = &bvh.nodes()[i];
        let (first, second) = (i + 1, node.offset as usize);
        let (near, far) = if octant >> node.axis & 1 == 1 {
            (second, first)
        } else {
            (first, second)
        };
        walk_order(bvh, near, cut, octant, out);
        walk_order(bvh, far, cut, octant, out);
    }

    /// The nodes `levels` levels below binary node `i` (fewer where a leaf comes first).
    fn cut_below<R: Real>(bvh: &Bvh<R>, i: usize, levels: u32, out: &mut Vec<usize>) {
        let node = &bvh.nodes()[i];
        if levels == 0 || node.count > 0 {
            out.push(i);
            return;
        }
        cut_below(bvh, i + 1, levels - 1, out);
        cut_below(bvh, node.offset as usize, levels - 1, out);
    }

    #[test]
    fn one_walk_gives_the_binary_traversals_order_of_a_cut_for_every_octant() {
        let mut rng = Rng::new(11);
        let bounds: Vec<Aabb<f64>> = (0..500)
            .map(|_| {
                sphere::<f64>(&mut rng, 1.0)
                    .bounds()
                    .expect("a sphere has a box")
            })
            .collect();
        let bvh = Bvh::build_with_leaves(bounds.iter().copied(), 2);
        let mut checked = 0;
        for i in 0..bvh.nodes().len() {
            for levels in 1..=3 {
                let mut cut = Vec::new();
                cut_below(&bvh, i, levels, &mut cut);
                if cut.len() < 2 {
                    continue;
                }
                let (orders, n) = visit_orders(&bvh, i, &cut);
                assert_eq!(n as usize, cut.len());
                for (octant, &packed) in orders.iter().enumerate() {
                    let mut seq = Vec::new();
                    walk_order(&bvh, i, &cut, octant, &mut seq);
                    // Packed as a node's `order`: the last visited in the lowest bits
                    let expected = seq
                        .iter()
                        .rev()
                        .enumerate()
                        .map(|(pos, &k)| k << (3 * pos))
                        .sum::<u32>();
                    assert_eq!(packed, expected, "node {i}, cut {cut:?}, octant {octant}");
                }
                checked += 1;
            }
        }
        assert!(checked > 500, "{checked} cuts");
    }

    fn sphere<R: Real>(rng: &mut Rng, scale: f64) -> Shape<R> {
        Shape::Sphere(Sphere {
            center: v3::<R>([0, 1, 2].map(|_| scale * rng.range(-10.0, 10.0))),
            radius: R::from_f64(scale * rng.range(0.05, 1.5)),
        })
    }

    fn triangle<R: Real>(rng: &mut Rng, scale: f64) -> Shape<R> {
        let c = [0, 1, 2].map(|_| scale * rng.range(-10.0, 10.0));
        let corner =
            |rng: &mut Rng| v3::<R>([0, 1, 2].map(|a| c[a] + scale * rng.range(-2.0, 2.0)));
        Shape::Triangle(Triangle::new(corner(rng), corner(rng), corner(rng)))
    }

    /// A grid of squares at y = 0, each two triangles sharing a diagonal: rays through the
    /// shared edges and corners meet two or more triangles at the same t.
    fn grid<R: Real>(n: usize, scale: f64) -> Vec<Shape<R>> {
        let p = |i: usize, j: usize| v3::<R>([scale * i as f64, 0.0, scale * j as f64]);
        let mut out = Vec::new();
        for i in 0..n {
            for j in 0..n {
                out.push(Shape::Triangle(Triangle::new(
                    p(i, j),
                    p(i + 1, j),
                    p(i + 1, j + 1),
                )));
                out.push(Shape::Triangle(Triangle::new(
                    p(i, j),
                    p(i + 1, j + 1),
                    p(i, j + 1),
                )));
            }
        }
        out
    }

    fn soup<R: Real>(rng: &mut Rng, kind: Soup, n: usize, scale: f64) -> Vec<Shape<R>> {
        let mut shapes: Vec<Shape<R>> = match kind {
            Soup::Spheres => (0..n).map(|_| sphere(rng, scale)).collect(),
            Soup::Triangles => (0..n).map(|_| triangle(rng, scale)).collect(),
            Soup::Mixed => (0..n)
                .map(|i| {
                    if i % 2 == 0 {
                        sphere(rng, scale)
                    } else {
                        triangle(rng, scale)
                    }
                })
                .collect(),
            Soup::Apart => {
                let mut s: Vec<Shape<R>> = (0..n / 2).map(|_| sphere(rng, scale)).collect();
                s.extend(grid((n / 4).max(3).isqrt() + 1, scale));
                s.push(Shape::Plane(Plane {
                    point: v3::<R>([0.0, -12.0 * scale, 0.0]),
                    normal: v3::<R>([0.0, 1.0, 0.0]),
                }));
                s
            }
        };
        // Exact duplicates, and a degenerate triangle: ties broken by the order of the visit.
        for k in 0..shapes.len() / 10 {
            shapes.push(shapes[k * 7 % shapes.len()].clone());
        }
        shapes.push(Shape::Triangle(Triangle::new(
            v3::<R>([0.0, 0.0, 0.0]),
            v3::<R>([scale, scale, 0.0]),
            v3::<R>([2.0 * scale, 2.0 * scale, 0.0]),
        )));
        shapes
    }

    /// A ray of one of several awkward kinds.
    fn ray<R: Real>(rng: &mut Rng, shapes: &[Shape<R>], scale: f64) -> Ray<R> {
        let mut d = rng.direction();
        let mut o = [0, 1, 2].map(|_| scale * rng.range(-14.0, 14.0));
        match rng.next_u64() % 6 {
            // Zero (and negative zero) components of D.
            0 => {
                let a = (rng.next_u64() % 3) as usize;
                d[a] = if rng.unit() < 0.5 { 0.0 } else { -0.0 };
                let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                d = d.map(|x| x / l);
            }
            1 => {
                let a = (rng.next_u64() % 3) as usize;
                d = [0.0, 0.0, 0.0];
                d[a] = if rng.unit() < 0.5 { 1.0 } else { -1.0 };
                let b = (a + 1) % 3;
                d[b] = -0.0;
            }
            // From inside a shape's box (its centre, a corner).
            2 | 3 => {
                let s = &shapes[(rng.next_u64() % shapes.len() as u64) as usize];
                let c = match s {
                    Shape::Sphere(s) => s.center,
                    Shape::Triangle(t) => t.p[(rng.next_u64() % 3) as usize],
                    Shape::Plane(p) => p.point,
                };
                o = c.to_array().map(|x| x.to_f64());
            }
            // Straight down onto the grid's edges and corners (y = 0, integer multiples).
            4 => {
                let step = |rng: &mut Rng| scale * ((rng.next_u64() % 8) as f64 * 0.5);
                o = [step(rng), 5.0 * scale, step(rng)];
                // ±0 across: the binary order of the grid's leaves depends on those signs.
                let zero = |rng: &mut Rng| if rng.unit() < 0.5 { 0.0 } else { -0.0 };
                d = [zero(rng), -1.0, zero(rng)];
            }
            _ => {}
        }
        Ray {
            origin: v3::<R>(o),
            direction: v3::<R>(d),
        }
    }

    /// The wide search's nearest (shape, t) and occlusion against the binary search's, bit for
    /// bit, over one soup.
    fn agrees<R: Real>(seed: u64, kind: Soup, n: usize, scale: f64, rays: usize) {
        let mut rng = Rng::new(seed);
        let shapes = soup::<R>(&mut rng, kind, n, scale);
        let agg = Aggregate::new(shapes.clone());
        for k in 0..rays {
            let ray = ray::<R>(&mut rng, &shapes, scale);
            let t_max = match k % 3 {
                0 => R::from_f64(f64::INFINITY),
                1 => R::from_f64(scale * rng.range(0.0, 20.0)),
                _ => R::from_f64(scale * rng.range(0.0, 1.0)),
            };
            let want = agg.nearest_binary(&ray, t_max);
            let got = agg.nearest(&ray, t_max).map(|h| (h.index, h.hit.t));
            let want_hit = want.and_then(|(i, t)| shapes[i].hit_at(&ray, t).map(|h| (i, h.t)));
            let bits = |h: Option<(usize, R)>| h.map(|(i, t)| (i, t.to_f64().to_bits()));
            assert_eq!(
                bits(got),
                bits(want_hit),
                "{kind:?} n = {n} scale {scale} {} {ray:?} t_max {t_max}",
                R::NAME
            );
            assert_eq!(
                agg.occluded(&ray, t_max),
                agg.occluded_binary(&ray, t_max),
                "{kind:?} n = {n} {} {ray:?} t_max {t_max}",
                R::NAME
            );
            // Nothing is missed: the brute-force nearest t, where the binary tree finds one.
            if let Some((_, t)) = want {
                let brute = shapes
                    .iter()
                    .filter_map(|s| s.hit_t(&ray, t_max))
                    .fold(t_max, |a, b| if b < a { b } else { a });
                assert_eq!(t, brute, "{kind:?} n = {n} {ray:?}");
            }
        }
        packets_agree::<R>(&mut rng, &agg, &shapes, kind, n, scale, rays / 4 + 1);
    }

    /// A packet of `lanes` rays: awkward ones of every kind mixed (octants, ±0 components,
    /// origins inside boxes), or a coherent bundle from one point (a tile of primary rays),
    /// perhaps with a lane or two of another kind.
    fn packet<R: Real>(
        rng: &mut Rng,
        shapes: &[Shape<R>],
        scale: f64,
        lanes: usize,
    ) -> Vec<Ray<R>> {
        let mut rays: Vec<Ray<R>> = match rng.next_u64() % 3 {
            0 => (0..lanes).map(|_| ray::<R>(rng, shapes, scale)).collect(),
            _ => {
                let o = ray::<R>(rng, shapes, scale).origin;
                let d = rng.direction();
                (0..lanes)
                    .map(|_| {
                        let e = rng.direction();
                        let d = [0, 1, 2].map(|a| d[a] + 0.05 * e[a]);
                        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                        Ray {
                            origin: o,
                            direction: v3::<R>(d.map(|x| x / l)),
                        }
                    })
                    .collect()
            }
        };
        if rng.unit() < 0.3 {
            let k = (rng.next_u64() % lanes as u64) as usize;
            rays[k] = ray::<R>(rng, shapes, scale);
        }
        rays
    }

    /// The packet searches against the one-ray searches (and so the binary ones), ray for ray:
    /// the nearest (shape, t) and the hit's point bit for bit, and occlusion, with t_max
    /// limits, over packets of every size.
    fn packets_agree<R: Real>(
        rng: &mut Rng,
        agg: &Aggregate<R>,
        shapes: &[Shape<R>],
        kind: Soup,
        n: usize,
        scale: f64,
        packets: usize,
    ) {
        let lanes = W::<R>::LANES;
        for p in 0..packets {
            let len = 1 + p % lanes;
            let rays = packet::<R>(rng, shapes, scale, len);
            let t_max: Vec<R> = (0..len)
                .map(|k| match (p + k) % 4 {
                    0 | 1 => R::from_f64(f64::INFINITY),
                    2 => R::from_f64(scale * rng.range(0.0, 20.0)),
                    _ => R::from_f64(scale * rng.range(0.0, 1.0)),
                })
                .collect();
            let mut got = vec![None; len];
            agg.nearest_packet_within(&rays, &t_max, &mut got);
            let want = (1u32 << len) - 1;
            let blocked = agg.occluded_packet(&rays, &t_max, want);
            let bits = |h: &Option<crate::geometry::AggregateHit<R>>| {
                h.map(|h| {
                    let p = h.hit.p.to_array().map(|x| x.to_f64().to_bits());
                    (h.index, h.hit.t.to_f64().to_bits(), p)
                })
            };
            for (k, ray) in rays.iter().enumerate() {
                let one = agg.nearest(ray, t_max[k]);
                assert_eq!(
                    bits(&got[k]),
                    bits(&one),
                    "{kind:?} n = {n} scale {scale} {}: lane {k} of {len}, {ray:?} t_max {}",
                    R::NAME,
                    t_max[k]
                );
                assert_eq!(
                    blocked & (1 << k) != 0,
                    agg.occluded(ray, t_max[k]),
                    "{kind:?} n = {n} {}: lane {k} of {len}, {ray:?} t_max {}",
                    R::NAME,
                    t_max[k]
                );
            }
            // Only the lanes asked about are answered.
            let some = want & 0b1011_0101;
            assert_eq!(agg.occluded_packet(&rays, &t_max, some), blocked & some);
        }
    }

    #[test]
    fn the_wide_search_is_the_binary_search_on_fixed_soups() {
        for (i, kind) in [Soup::Spheres, Soup::Triangles, Soup::Mixed, Soup::Apart]
            .into_iter()
            .enumerate()
        {
            for n in [9, 40, 300, 2000] {
                for scale in [1.0, 1e-3, 1e4] {
                    agrees::<f32>(i as u64 * 100 + n as u64, kind, n, scale, 300);
                    agrees::<f64>(i as u64 * 100 + n as u64 + 1, kind, n, scale, 300);
                }
            }
        }
    }

    #[test]
    fn the_wide_search_is_the_binary_search_on_random_soups() {
        let kinds = prop_oneof![
            Just(Soup::Spheres),
            Just(Soup::Triangles),
            Just(Soup::Mixed),
            Just(Soup::Apart)
        ];
        let scales = prop_oneof![Just(1.0), Just(1e-2), Just(1e5)];
        TestRunner::new(Config {
            cases: 48,
            rng_seed: RngSeed::Fixed(17),
            failure_persistence: None,
            ..Config::default()
        })
        .run(
            &(any::<u64>(), kinds, 9usize..400, scales),
            |(seed, kind, n, scale)| {
                agrees::<f32>(seed, kind, n, scale, 60);
                agrees::<f64>(seed, kind, n, scale, 60);
                Ok(())
            },
        )
        .unwrap();
    }

    fn collapsed_nodes_are_full_and_cover_every_shape<R: Real>() {
        let mut rng = Rng::new(9);
        let shapes = soup::<R>(&mut rng, Soup::Apart, 3000, 1.0);
        let boxes: Vec<Aabb<R>> = shapes.iter().filter_map(Shape::bounds).collect();
        let ids: Vec<u32> = (0..shapes.len() as u32)
            .filter(|&i| !matches!(shapes[i as usize], Shape::Plane(_)))
            .collect();
        let bvh = Bvh::build_with_leaves(boxes.iter().copied(), W::<R>::LANES);
        let w = WideBvh::new(&bvh, &ids, &shapes);
        // Every shape in exactly one leaf.
        let mut seen = vec![0; shapes.len()];
        for l in &w.spheres {
            for k in lanes_of(l.used) {
                seen[l.shape.as_ref()[k] as usize] += 1;
            }
        }
        for l in &w.triangles {
            for k in lanes_of(l.held) {
                seen[l.shape.as_ref()[k] as usize] += 1;
            }
        }
        for &(first, count) in &w.mixed {
            for &i in &w.mixed_shapes[first as usize..(first + count) as usize] {
                seen[i as usize] += 1;
            }
        }
        for (i, s) in shapes.iter().enumerate() {
            let want = usize::from(!matches!(s, Shape::Plane(_)));
            assert_eq!(seen[i], want, "shape {i}");
        }
        // A node with c children stands for c − 1 binary interior nodes, each exactly once.
        let interior = bvh.nodes().iter().filter(|n| n.count == 0).count();
        let absorbed: usize = w.nodes.iter().map(|n| n.count() - 1).sum();
        assert_eq!(absorbed, interior);
        assert!(w
            .nodes
            .iter()
            .all(|n| (2..=W::<R>::LANES).contains(&n.count())));
        // Nodes hold three children or more on average (the small ones sit at the bottom).
        assert!(
            absorbed >= 2 * w.nodes.len(),
            "{absorbed} in {}",
            w.nodes.len()
        );
        // Each octant's order is a permutation of the children.
        for n in &w.nodes {
            for o in n.order {
                let c = n.count() as u32;
                assert_eq!(o >> COUNT_SHIFT, c, "each word holds the count");
                let mut s: Vec<u32> = (0..c).map(|p| (o >> (3 * p)) & 7).collect();
                s.sort_unstable();
                assert_eq!(s, (0..c).collect::<Vec<_>>());
            }
        }
    }

    #[test]
    fn a_node_is_whole_cache_lines_with_none_to_spare() {
        // Six registers of bounds, a u32 per lane, eight order words: 6·32 + 32 + 32 = 256
        // bytes in f32; 6·32 + 16 + 32 = 240, so 256, in f64 of 4 lanes; 6·64 + 32 + 32 = 448
        // in f64 of 8 (AVX-512). Four cache lines, or seven.
        assert_eq!(std::mem::size_of::<Node<f32>>(), 256);
        let f64_size = if W::<f64>::LANES == 4 { 256 } else { 448 };
        assert_eq!(std::mem::size_of::<Node<f64>>(), f64_size);
        assert_eq!(std::mem::align_of::<Node<f64>>(), 64);
        assert_eq!(std::mem::align_of::<Node<f32>>(), 64);
    }

    #[test]
    fn the_stack_spills_beyond_its_place_and_still_pops_in_order() {
        let mut stack = Stack::<f64>::new();
        for i in 0..3 * STACK as u32 {
            stack.push(i, f64::from(i) / 2.0);
        }
        for i in (0..3 * STACK as u32).rev() {
            assert_eq!(stack.pop(), Some((i, f64::from(i) / 2.0)));
        }
        assert_eq!(stack.pop(), None);
    }

    fn coincident<R: Real>() {
        // 3000 equal spheres and 3000 equal triangles: every child met at every level (the
        // stack at its deepest), every shape at the same t; the binary order picks the winner.
        let s = Shape::Sphere(Sphere {
            center: v3::<R>([1.0, 2.0, 3.0]),
            radius: R::ONE,
        });
        let t = Shape::Triangle(Triangle::new(
            v3::<R>([-1.0, -1.0, 9.0]),
            v3::<R>([3.0, -1.0, 9.0]),
            v3::<R>([1.0, 4.0, 9.0]),
        ));
        for shapes in [vec![s; 3000], vec![t; 3000]] {
            let agg = Aggregate::new(shapes);
            let mut rng = Rng::new(21);
            let mut rays = Vec::new();
            for _ in 0..64 {
                let d = rng.direction();
                let ray = Ray {
                    origin: v3::<R>([1.0, 1.0, -4.0]),
                    direction: v3::<R>([d[0] * 0.1, d[1] * 0.1, 1.0]),
                };
                let inf = R::from_f64(f64::INFINITY);
                let want = agg.nearest_binary(&ray, inf);
                assert_eq!(agg.nearest(&ray, inf).map(|h| (h.index, h.hit.t)), want);
                assert_eq!(agg.occluded(&ray, inf), agg.occluded_binary(&ray, inf));
                // Packets of one octant (the lanes go down together), each octant in turn.
                let (dx, dy) = ((d[0] * 0.1).abs(), (d[1] * 0.1).abs());
                let octant = rays.len() / W::<R>::LANES % 4;
                let sx = if octant & 1 == 0 { dx } else { -dx };
                let sy = if octant & 2 == 0 { dy } else { -dy };
                rays.push(Ray {
                    origin: ray.origin,
                    direction: v3::<R>([sx, sy, 1.0]),
                });
            }
            // In packets too: every ray meets every shape at the same t, and each lane's
            // winner is its own binary search's.
            for packet in rays.chunks(W::<R>::LANES) {
                let mut got = vec![None; packet.len()];
                agg.nearest_packet(packet, &mut got);
                for (ray, got) in packet.iter().zip(&got) {
                    let want = agg.nearest_binary(ray, R::from_f64(f64::INFINITY));
                    assert_eq!(got.map(|h| (h.index, h.hit.t)), want);
                }
            }
        }
    }

    #[test]
    fn coincident_shapes_give_the_binary_searchs_winner() {
        coincident::<f32>();
        coincident::<f64>();
    }

    #[test]
    fn collapsed_nodes_cover_every_shape_once_in_both_precisions() {
        collapsed_nodes_are_full_and_cover_every_shape::<f32>();
        collapsed_nodes_are_full_and_cover_every_shape::<f64>();
    }
}
