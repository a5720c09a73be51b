//! A bounding volume hierarchy over primitive boxes (pbrt-v4 §7.3): built top-down with the
//! binned surface area heuristic, flattened into depth-first order (`LinearBVHNode`), and
//! traversed front to back with a fixed stack.
//!
//! The BVH knows only boxes and primitive indices; what a primitive is and how a ray meets it
//! is the caller's closure. The build is deterministic (same boxes, same tree), single-threaded,
//! and its depth is bounded (SAH down to [`SAH_DEPTH`], median splits below, which halve the
//! count), so the traversal stack cannot overflow and degenerate inputs (all centroids equal,
//! geometric spacing) still build in O(n log n).

use std::cmp::Ordering;

use super::bounds::{greater, inverse, lesser, Aabb};
use super::ray::Ray;
use crate::core::{Real, Vector, V3};

/// The most primitives a leaf holds; every node with this many or fewer is a leaf. (Letting
/// the SAH split such nodes further, as pbrt does, tripled the node count and cost 40 % more
/// build instructions, for the same instructions per query on 100,000 spheres.)
pub(crate) const MAX_LEAF: usize = 4;
/// Centroid bins of the SAH split search (pbrt-v4 uses 12).
const BINS: usize = 12;
/// Depth to which splits are chosen by the SAH. Deeper, a node is split at its median
/// centroid, halving its count, so with fewer than 2³² primitives no path is longer than
/// SAH_DEPTH + 31 nodes.
pub(crate) const SAH_DEPTH: usize = 32;
/// The traversal stack: one entry per level at most, and levels ≤ SAH_DEPTH + 31 < 64.
const STACK: usize = 64;

/// One node of the flattened tree, in depth-first order: an interior node's first child
/// follows it directly, its second child is at `offset` (pbrt-v4 `LinearBVHNode`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BvhNode<R: Real> {
    pub bounds: Aabb<R>,
    /// A leaf's first entry in [`Bvh::prims`]; an interior node's second child.
    pub offset: u32,
    /// The number of primitives of a leaf (1 to [`MAX_LEAF`], or the count the tree was built
    /// with); 0 for an interior node.
    pub count: u16,
    /// An interior node's split axis (0 = x, 1 = y, 2 = z): its first child holds the
    /// primitives with the smaller centroids along it.
    pub axis: u8,
}

/// A flattened BVH over the boxes it was built from.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh<R: Real> {
    nodes: Vec<BvhNode<R>>,
    /// The primitives' indices (into the slice given to [`Bvh::build`]) in leaf order.
    prims: Vec<u32>,
}

/// The nearest primitive a ray hits, and its t.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhHit<R: Real> {
    /// The primitive's index in the slice given to [`Bvh::build`].
    pub prim: u32,
    /// The ray parameter of its hit.
    pub t: R,
}

/// A primitive during the build: its box, its index, and its bin in the current node.
#[derive(Clone, Copy)]
struct Item<R: Real> {
    bounds: Aabb<R>,
    index: u32,
    bin: u8,
}

/// Items gathered together: how many, the union of their boxes, the box of their centroids.
#[derive(Clone, Copy)]
struct Bin<R: Real> {
    count: usize,
    bounds: Aabb<R>,
    centroids: Aabb<R>,
}

impl<R: Real> Bin<R> {
    fn empty() -> Self {
        Bin {
            count: 0,
            bounds: Aabb::empty(),
            centroids: Aabb::empty(),
        }
    }

    #[inline]
    fn add(&mut self, it: &Item<R>) {
        self.count += 1;
        self.bounds = self.bounds.union(it.bounds);
        self.centroids = self.centroids.union_point(it.bounds.centroid());
    }

    /// Adds the items of `o`, in place (the sides of a split gather up to [`BINS`] bins each).
    #[inline]
    fn merge(&mut self, o: &Self) {
        self.count += o.count;
        self.bounds = self.bounds.union(o.bounds);
        self.centroids = self.centroids.union(o.centroids);
    }

    /// The extent of `items`, by a pass over them.
    fn of(items: &[Item<R>]) -> Self {
        let mut b = Bin::empty();
        for it in items {
            b.add(it);
        }
        b
    }
}

/// The centroid's component along `axis`, computed exactly as [`Aabb::centroid`] does.
#[inline]
fn centroid_on<R: Real>(b: &Aabb<R>, axis: usize) -> R {
    let half = R::ONE / R::TWO;
    b.min.to_array()[axis] * half + b.max.to_array()[axis] * half
}

/// BINS equal slices of a node's centroid box along its longest axis (in f64, so that f32 and
/// f64 share the arithmetic).
struct Binning {
    axis: usize,
    min: f64,
    scale: f64,
}

impl Binning {
    /// `None` when the centroids coincide: nothing to split on.
    fn of<R: Real>(centroids: &Aabb<R>) -> Option<Self> {
        let axis = centroids.longest_axis();
        let lo = centroids.min.to_array()[axis].to_f64();
        let hi = centroids.max.to_array()[axis].to_f64();
        let separable = lo < hi; // false for NaN too
        separable.then(|| Binning {
            axis,
            min: lo,
            scale: BINS as f64 / (hi - lo),
        })
    }

    /// Puts each item in its bin, noting the bin in the item for [`partition`].
    ///
    /// The bins are gathered component by component in arrays, not as [`Bin`]s: a `Bin` written
    /// in pieces and read back whole a few items later (12 bins, so often) cannot be forwarded
    /// from the store buffer, and waiting for it took a quarter of this loop's time (a fifth of
    /// the loop is saved at 100,000 spheres). The unions are [`Aabb::union`]'s and
    /// [`Aabb::union_point`]'s, component by component in the same order, so the bins are the
    /// same to the bit.
    fn fill<R: Real>(&self, items: &mut [Item<R>]) -> [Bin<R>; BINS] {
        let empty = Bin::<R>::empty();
        let (lo, hi) = (empty.bounds.min.to_array(), empty.bounds.max.to_array());
        let mut count = [0usize; BINS];
        let (mut bmin, mut bmax) = ([lo; BINS], [hi; BINS]);
        let (mut cmin, mut cmax) = ([lo; BINS], [hi; BINS]);
        for it in items {
            // The centroid once, for the bin and the bin's centroid box (its component along
            // the axis is `centroid_on`'s, to the bit)
            let c = it.bounds.centroid().to_array();
            // `as i32` saturates (NaN gives 0) and is much cheaper than `as usize`
            let k = (c[self.axis].to_f64() - self.min) * self.scale;
            let k = (k as i32).clamp(0, BINS as i32 - 1) as usize;
            it.bin = k as u8;
            count[k] += 1;
            let (l, h) = (it.bounds.min.to_array(), it.bounds.max.to_array());
            for a in 0..3 {
                bmin[k][a] = lesser(bmin[k][a], l[a]);
                bmax[k][a] = greater(bmax[k][a], h[a]);
                cmin[k][a] = lesser(cmin[k][a], c[a]);
                cmax[k][a] = greater(cmax[k][a], c[a]);
            }
        }
        let v = |[x, y, z]: [R; 3]| V3::<R>::new(x, y, z);
        std::array::from_fn(|k| Bin {
            count: count[k],
            bounds: Aabb {
                min: v(bmin[k]),
                max: v(bmax[k]),
            },
            centroids: Aabb {
                min: v(cmin[k]),
                max: v(cmax[k]),
            },
        })
    }
}

/// The cheapest boundary between bins by the SAH (pbrt-v4 §7.3.2): the one minimising
/// n_L·A_L + n_R·A_R (the first on a tie), with the two sides' extents. `None` when no
/// boundary has items on both sides (impossible for a separable node; kept for safety).
fn cheapest<R: Real>(bins: &[Bin<R>; BINS], bounds: &Aabb<R>) -> Option<(usize, [Bin<R>; 2])> {
    // Surface areas relative to the node's largest extent (in f64: no overflow for huge
    // coordinates; only their ratios matter)
    let (nlo, nhi) = (bounds.min.to_array(), bounds.max.to_array());
    let ext = [0, 1, 2].map(|a| nhi[a].to_f64() - nlo[a].to_f64());
    let inv = 1.0 / ext[0].max(ext[1]).max(ext[2]);
    let area = |b: &Aabb<R>| {
        let (l, h) = (b.min.to_array(), b.max.to_array());
        let d = [0, 1, 2].map(|a| (h[a].to_f64() - l[a].to_f64()) * inv);
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    };

    // Sweep from the right: the count and box above each boundary
    let mut above = [(0usize, Aabb::<R>::empty()); BINS];
    let mut acc = (0usize, Aabb::<R>::empty());
    for i in (1..BINS).rev() {
        if bins[i].count > 0 {
            acc = (acc.0 + bins[i].count, acc.1.union(bins[i].bounds));
        }
        above[i - 1] = acc;
    }

    // Sweep from the left, pricing the boundary after each non-empty bin (after an empty one
    // the sides are those of the boundary before)
    let mut best: Option<(usize, f64)> = None;
    let mut below = (0usize, Aabb::<R>::empty());
    for i in 0..BINS - 1 {
        if bins[i].count == 0 {
            continue;
        }
        below = (below.0 + bins[i].count, below.1.union(bins[i].bounds));
        let up = above[i];
        if up.0 == 0 {
            break;
        }
        let cost = below.0 as f64 * area(&below.1) + up.0 as f64 * area(&up.1);
        // (A NaN cost, from a node of zero or overflowing extent, still yields a split.)
        if best.is_none_or(|(_, c)| cost < c) {
            best = Some((i, cost));
        }
    }

    // The two sides of the cheapest boundary, with their centroid boxes
    let (split, _) = best?;
    let mut sides = [Bin::empty(), Bin::empty()];
    for (i, b) in bins.iter().enumerate() {
        if b.count > 0 {
            sides[usize::from(i > split)].merge(b);
        }
    }
    Some((split, sides))
}

/// Moves the items whose noted bin is ≤ `split` to the front (Hoare's scheme); returns how
/// many they are.
fn partition<R: Real>(items: &mut [Item<R>], split: usize) -> usize {
    let is_left = |it: &Item<R>| usize::from(it.bin) <= split;
    let (mut i, mut j) = (0, items.len());
    loop {
        while i < j && is_left(&items[i]) {
            i += 1;
        }
        while i < j && !is_left(&items[j - 1]) {
            j -= 1;
        }
        if i >= j {
            return i;
        }
        items.swap(i, j - 1);
        i += 1;
        j -= 1;
    }
}

/// Splits at the median centroid along `axis` (pbrt's `EqualCounts`); deterministic, as
/// `select_nth_unstable_by` uses no randomness.
fn median<R: Real>(items: &mut [Item<R>], axis: usize) -> usize {
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        centroid_on(&a.bounds, axis)
            .partial_cmp(&centroid_on(&b.bounds, axis))
            .unwrap_or(Ordering::Equal)
    });
    mid
}

/// The recursive build, writing nodes in depth-first order.
struct Builder<R: Real> {
    nodes: Vec<BvhNode<R>>,
    /// Nodes with this many primitives or fewer become leaves.
    max_leaf: usize,
}

impl<R: Real> Builder<R> {
    /// Builds the subtree of `items`, which start at `first` in the final order and whose
    /// extent is `extent`.
    fn node(&mut self, items: &mut [Item<R>], first: usize, extent: Bin<R>, depth: usize) {
        let n = items.len();
        let bounds = extent.bounds;

        // A leaf when the items fit in one
        if n <= self.max_leaf {
            self.nodes.push(BvhNode {
                bounds,
                offset: first as u32,
                count: n as u16,
                axis: 0,
            });
            return;
        }

        // Choose the split: halves in place when all centroids coincide, the median deep in
        // the tree, the binned SAH otherwise
        let (axis, mid, sides) = match Binning::of(&extent.centroids) {
            None => (0, n / 2, None),
            Some(b) if depth >= SAH_DEPTH => (b.axis, median(items, b.axis), None),
            Some(b) => match cheapest(&b.fill(items), &bounds) {
                Some((split, sides)) => {
                    let mid = partition(items, split);
                    debug_assert_eq!(mid, sides[0].count);
                    (b.axis, mid, Some(sides))
                }
                None => (b.axis, median(items, b.axis), None),
            },
        };

        // Children's extents, from the bins or by a pass over the items
        let [left, right] =
            sides.unwrap_or_else(|| [Bin::of(&items[..mid]), Bin::of(&items[mid..])]);

        // Emit the interior node, its first child right after it, then its second child
        let this = self.nodes.len();
        self.nodes.push(BvhNode {
            bounds,
            offset: 0,
            count: 0,
            axis: axis as u8,
        });
        let (l, r) = items.split_at_mut(mid);
        self.node(l, first, left, depth + 1);
        self.nodes[this].offset = self.nodes.len() as u32;
        self.node(r, first + mid, right, depth + 1);
    }
}

impl<R: Real> Bvh<R> {
    /// Builds the BVH of `bounds` (primitive i has box `bounds[i]`); deterministic.
    ///
    /// # Panics
    /// With 2³² primitives or more (their indices are u32).
    pub fn build(bounds: &[Aabb<R>]) -> Self {
        let mut bvh = Self::build_with_leaves(bounds.iter().copied(), MAX_LEAF);
        // A tree built to be kept holds no room for the 2N − 1 nodes it was given.
        bvh.nodes.shrink_to_fit();
        bvh
    }

    /// [`Bvh::build`] of the boxes `bounds` yields, with leaves of up to `max_leaf` primitives
    /// (1 to 255) instead of [`MAX_LEAF`]: the wide BVH ([`super::wbvh`]) asks for one
    /// primitive per lane. (The boxes are taken as they come: the aggregate's 100,000 boxes
    /// were a vector of their own, 4.8 MB written and read once.)
    pub(crate) fn build_with_leaves(
        bounds: impl ExactSizeIterator<Item = Aabb<R>>,
        max_leaf: usize,
    ) -> Self {
        assert!(
            (1..=255).contains(&max_leaf),
            "leaves of 1 to 255 primitives"
        );
        let n = bounds.len();
        assert!(
            u32::try_from(n).is_ok(),
            "a BVH holds fewer than 2^32 primitives"
        );
        let mut items: Vec<Item<R>> = bounds
            .enumerate()
            .map(|(i, b)| Item {
                bounds: b,
                index: i as u32,
                bin: 0,
            })
            .collect();
        // At most 2n − 1 nodes; pages never written are never resident.
        let mut builder = Builder {
            nodes: Vec::with_capacity((2 * n).saturating_sub(1)),
            max_leaf,
        };
        if n > 0 {
            let root = Bin::of(&items);
            builder.node(&mut items, 0, root, 0);
        }
        // (Not shrunk here: the aggregate keeps this tree only while it builds the wide one,
        // and a shrink copied every node into a new allocation; `build` shrinks its own.)
        let nodes = builder.nodes;
        let prims = items.iter().map(|it| it.index).collect();
        Bvh { nodes, prims }
    }

    /// The nodes in depth-first order (the root first); empty for no primitives.
    pub(crate) fn nodes(&self) -> &[BvhNode<R>] {
        &self.nodes
    }

    /// The primitive indices in leaf order.
    pub(crate) fn prims(&self) -> &[u32] {
        &self.prims
    }

    /// The box of every primitive (empty for none).
    #[cfg(test)]
    pub(crate) fn bounds(&self) -> Aabb<R> {
        self.nodes.first().map_or(Aabb::empty(), |n| n.bounds)
    }

    /// The number of nodes on the longest path from the root to a leaf (0 when empty).
    #[cfg(test)]
    pub(crate) fn depth(&self) -> usize {
        fn walk<R: Real>(nodes: &[BvhNode<R>], i: usize) -> usize {
            let n = &nodes[i];
            if n.count > 0 {
                1
            } else {
                1 + walk(nodes, i + 1).max(walk(nodes, n.offset as usize))
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            walk(&self.nodes, 0)
        }
    }

    /// Visits the leaves whose boxes the ray meets within (0, t_max], near child first, until
    /// `leaf` returns true; `leaf` may lower t_max, which prunes the rest.
    #[inline]
    fn traverse(&self, ray: &Ray<R>, t_max: R, mut leaf: impl FnMut(u32, &mut R) -> bool) {
        if self.nodes.is_empty() {
            return;
        }
        let inv = inverse::<R>(ray.direction);
        let neg = inv.to_array().map(|x| x < R::ZERO);
        let mut t_max = t_max;
        let mut stack = [0u32; STACK];
        let mut sp = 0;
        let mut cur = 0usize;
        loop {
            let node = &self.nodes[cur];
            if node.bounds.hit(ray.origin, inv, t_max) {
                if node.count > 0 {
                    // Test the leaf's primitives
                    let first = node.offset as usize;
                    for &prim in &self.prims[first..first + node.count as usize] {
                        if leaf(prim, &mut t_max) {
                            return;
                        }
                    }
                } else {
                    // Visit the near child first, the far one later (by D's sign on the axis)
                    let second = node.offset as usize;
                    let (near, far) = if neg[node.axis as usize] {
                        (second, cur + 1)
                    } else {
                        (cur + 1, second)
                    };
                    stack[sp] = far as u32;
                    sp += 1;
                    cur = near;
                    continue;
                }
            }
            // Take the next node from the stack, or stop
            if sp == 0 {
                return;
            }
            sp -= 1;
            cur = stack[sp] as usize;
        }
    }

    /// The nearest hit with t < `t_max`. `hit(prim, t_max_now)` tests one primitive and
    /// returns its t only for a hit with 0 < t < t_max_now; the search then continues with
    /// t_max_now = t, so every hit it reports is nearer than the one before.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray<R>,
        t_max: R,
        mut hit: impl FnMut(u32, R) -> Option<R>,
    ) -> Option<BvhHit<R>> {
        let mut best = None;
        self.traverse(ray, t_max, |prim, t_max| {
            if let Some(t) = hit(prim, *t_max) {
                debug_assert!(t < *t_max, "the hit callback returned t ≥ t_max");
                if t < *t_max {
                    *t_max = t;
                    best = Some(BvhHit { prim, t });
                }
            }
            false
        });
        best
    }

    /// Whether `test(prim, t_max)` holds for some primitive whose box the ray meets before
    /// `t_max` (shadow rays); stops at the first.
    #[cfg(test)]
    pub(crate) fn any(&self, ray: &Ray<R>, t_max: R, mut test: impl FnMut(u32, R) -> bool) -> bool {
        let mut found = false;
        self.traverse(ray, t_max, |prim, t_max| {
            found = test(prim, *t_max);
            found
        });
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::v3;
    use crate::core::V3;
    use crate::geometry::bounds::test_rng::Rng;
    use crate::geometry::Sphere;

    fn spheres<R: Real>(rng: &mut Rng, n: usize, scale: f64, offset: f64) -> Vec<Sphere<R>> {
        // Radii shrink with the count so that the set stays about equally crowded.
        let r_max = 3.0 / (n.max(1) as f64).cbrt();
        (0..n)
            .map(|_| Sphere {
                center: v3::<R>([0, 1, 2].map(|_| offset + scale * rng.range(-10.0, 10.0))),
                radius: R::from_f64(scale * rng.range(0.05, 1.0) * r_max),
            })
            .collect()
    }

    fn boxes<R: Real>(s: &[Sphere<R>]) -> Vec<Aabb<R>> {
        s.iter()
            .map(|s| Aabb::of_sphere(s.center, s.radius))
            .collect()
    }

    /// The sphere's nearest t in (0, t_max), the one test both searches use.
    fn sphere_t<R: Real>(s: &Sphere<R>, ray: &Ray<R>, t_max: R) -> Option<R> {
        s.intersect_line(ray)
            .nearest_in_front()
            .filter(|&t| t < t_max)
    }

    fn brute_nearest<R: Real>(s: &[Sphere<R>], ray: &Ray<R>, t_max: R) -> Option<BvhHit<R>> {
        let mut best: Option<BvhHit<R>> = None;
        for (i, sp) in s.iter().enumerate() {
            let limit = best.map_or(t_max, |b| b.t);
            if let Some(t) = sphere_t(sp, ray, limit) {
                best = Some(BvhHit { prim: i as u32, t });
            }
        }
        best
    }

    fn random_ray<R: Real>(rng: &mut Rng, scale: f64, offset: f64) -> Ray<R> {
        Ray {
            origin: v3::<R>([0, 1, 2].map(|_| offset + scale * rng.range(-15.0, 15.0))),
            direction: v3::<R>(rng.direction()),
        }
    }

    /// `Binning::fill` gathers its bins component by component; they are the bins
    /// [`Bin::add`] gives item by item, to the bit (the tree depends on them).
    fn fill_matches_adding_item_by_item<R: Real>() {
        let mut rng = Rng::new(7);
        let s = spheres::<R>(&mut rng, 2000, 1.0, 0.0);
        let mut items: Vec<Item<R>> = boxes(&s)
            .into_iter()
            .enumerate()
            .map(|(i, bounds)| Item {
                bounds,
                index: i as u32,
                bin: 0,
            })
            .collect();
        let binning = Binning::of(&Bin::of(&items).centroids).unwrap();
        let bins = binning.fill(&mut items);
        let mut expected = [Bin::<R>::empty(); BINS];
        for it in &items {
            expected[usize::from(it.bin)].add(it);
        }
        let bits = |v: V3<R>| v.to_array().map(|x| x.to_f64().to_bits());
        for (b, e) in bins.iter().zip(&expected) {
            assert_eq!(b.count, e.count);
            for (x, y) in [
                (b.bounds.min, e.bounds.min),
                (b.bounds.max, e.bounds.max),
                (b.centroids.min, e.centroids.min),
                (b.centroids.max, e.centroids.max),
            ] {
                assert_eq!(bits(x), bits(y));
            }
        }
        // Every bin used: the test covers them all
        assert!(bins.iter().all(|b| b.count > 0));
    }

    #[test]
    fn binning_by_components_gives_the_bins_of_adding_items_one_by_one() {
        fill_matches_adding_item_by_item::<f32>();
        fill_matches_adding_item_by_item::<f64>();
    }

    /// Checks the tree's invariants: every primitive in exactly one leaf, leaves of at most
    /// MAX_LEAF, children's boxes inside their parent's, primitives' boxes inside their leaf's.
    fn check_structure<R: Real>(bvh: &Bvh<R>, b: &[Aabb<R>]) {
        let mut seen = vec![false; b.len()];
        for (i, node) in bvh.nodes().iter().enumerate() {
            if node.count > 0 {
                assert!(node.count as usize <= MAX_LEAF);
                let first = node.offset as usize;
                for &p in &bvh.prims()[first..first + node.count as usize] {
                    assert!(!seen[p as usize], "primitive {p} in two leaves");
                    seen[p as usize] = true;
                    assert!(node.bounds.contains(&b[p as usize]));
                }
            } else {
                let second = &bvh.nodes()[node.offset as usize];
                assert!(node.offset as usize > i + 1);
                assert!(node.bounds.contains(&bvh.nodes()[i + 1].bounds));
                assert!(node.bounds.contains(&second.bounds));
            }
        }
        assert!(seen.iter().all(|&s| s), "a primitive is in no leaf");
        assert!(bvh.depth() < STACK);
    }

    fn agrees_with_brute_force<R: Real>(seed: u64, sizes: &[usize], rays: usize) {
        let mut rng = Rng::new(seed);
        for (scale, offset) in [(1.0, 0.0), (1e-3, 0.0), (1e-3, 1.0), (1.0, 1e6)] {
            for &n in sizes {
                let s = spheres::<R>(&mut rng, n, scale, offset);
                let b = boxes(&s);
                let bvh = Bvh::build(&b);
                check_structure(&bvh, &b);
                for k in 0..rays {
                    let ray = random_ray::<R>(&mut rng, scale, offset);
                    let t_max = if k % 2 == 0 {
                        R::from_f64(f64::INFINITY)
                    } else {
                        R::from_f64(scale * rng.range(0.0, 30.0))
                    };
                    let want = brute_nearest(&s, &ray, t_max);
                    let got = bvh.nearest(&ray, t_max, |p, t| sphere_t(&s[p as usize], &ray, t));
                    assert_eq!(got, want, "n = {n}, scale {scale}, offset {offset}");
                    let any = bvh.any(&ray, t_max, |p, t| {
                        sphere_t(&s[p as usize], &ray, t).is_some()
                    });
                    assert_eq!(any, want.is_some(), "n = {n}");
                }
            }
        }
    }

    #[test]
    fn nearest_and_any_agree_with_brute_force_over_random_sphere_sets() {
        let sizes = [0, 1, 2, 3, 4, 5, 7, 16, 100, 500, 2000];
        agrees_with_brute_force::<f32>(1, &sizes, 300);
        agrees_with_brute_force::<f64>(2, &sizes, 300);
    }

    fn coincident<R: Real>() {
        // 1000 identical spheres: no centroid split exists, yet the build ends, the leaves stay
        // small and the nearest t is the sphere's.
        let s = vec![
            Sphere {
                center: v3::<R>([1.0, 2.0, 3.0]),
                radius: R::ONE,
            };
            1000
        ];
        let b = boxes(&s);
        let bvh = Bvh::build(&b);
        check_structure(&bvh, &b);
        assert!(bvh.depth() <= 10, "depth {}", bvh.depth());
        let ray = Ray {
            origin: v3::<R>([1.0, 2.0, -5.0]),
            direction: v3::<R>([0.0, 0.0, 1.0]),
        };
        let inf = R::from_f64(f64::INFINITY);
        let hit = bvh
            .nearest(&ray, inf, |p, t| sphere_t(&s[p as usize], &ray, t))
            .unwrap();
        assert_eq!(hit.t, R::from_f64(7.0));
        // Exactly one hit is accepted per distinct t: the first primitive tested.
        let mut calls = 0;
        bvh.nearest(&ray, inf, |p, t| {
            calls += 1;
            sphere_t(&s[p as usize], &ray, t)
        });
        assert_eq!(calls, 1000, "all boxes equal, so all are tested");
    }

    #[test]
    fn identical_boxes_build_a_shallow_tree_that_still_finds_the_hit() {
        coincident::<f32>();
        coincident::<f64>();
    }

    fn geometric<R: Real>(count: i32) {
        // Centres at 2^i: every SAH bin but the last holds almost everything, which would make
        // an unbounded tree as deep as the count.
        let s: Vec<Sphere<R>> = (0..count)
            .map(|i| {
                let x = 2f64.powi(i);
                Sphere {
                    center: v3::<R>([x, 0.0, 0.0]),
                    radius: R::from_f64(0.25 * x),
                }
            })
            .collect();
        let b = boxes(&s);
        let bvh = Bvh::build(&b);
        check_structure(&bvh, &b);
        let mut rng = Rng::new(3);
        for _ in 0..200 {
            let i = (rng.unit() * count as f64) as i32;
            let x = 2f64.powi(i);
            let ray = Ray {
                origin: v3::<R>([x * rng.range(0.9, 1.1), x * rng.range(-0.2, 0.2), -x]),
                direction: v3::<R>([0.0, 0.0, 1.0]),
            };
            let inf = R::from_f64(f64::INFINITY);
            let want = brute_nearest(&s, &ray, inf);
            assert_eq!(
                bvh.nearest(&ray, inf, |p, t| sphere_t(&s[p as usize], &ray, t)),
                want
            );
        }
    }

    #[test]
    fn geometrically_spaced_spheres_keep_the_tree_within_the_traversal_stack() {
        geometric::<f32>(120);
        geometric::<f64>(1000);
    }

    #[test]
    fn the_same_boxes_build_the_same_tree() {
        let mut rng = Rng::new(4);
        let s = spheres::<f32>(&mut rng, 5000, 1.0, 0.0);
        let b = boxes(&s);
        assert_eq!(Bvh::build(&b), Bvh::build(&b));
    }

    #[test]
    fn a_tree_built_to_be_kept_holds_no_spare_room() {
        // Built with room for 2N − 1 nodes; 5,000 spheres in leaves of up to MAX_LEAF make far
        // fewer, and a tree `build` returns is kept.
        let mut rng = Rng::new(5);
        let b = boxes(&spheres::<f64>(&mut rng, 5000, 1.0, 0.0));
        let bvh = Bvh::build(&b);
        assert!(bvh.nodes.len() < 2 * b.len() - 1);
        assert_eq!(bvh.nodes.capacity(), bvh.nodes.len());
    }

    fn empty_and_single<R: Real>() {
        let inf = R::from_f64(f64::INFINITY);
        let ray = Ray {
            origin: V3::<R>::ZERO,
            direction: v3::<R>([1.0, 0.0, 0.0]),
        };
        let none = Bvh::<R>::build(&[]);
        assert!(none.nodes().is_empty() && none.bounds().is_empty());
        assert_eq!(none.nearest(&ray, inf, |_, _| Some(R::ONE)), None);
        assert!(!none.any(&ray, inf, |_, _| true));
        let one = Bvh::build(&[Aabb::of_sphere(v3::<R>([5.0, 0.0, 0.0]), R::ONE)]);
        assert_eq!(one.nodes().len(), 1);
        assert_eq!(
            one.nearest(&ray, inf, |p, _| (p == 0).then_some(R::from_f64(4.0))),
            Some(BvhHit {
                prim: 0,
                t: R::from_f64(4.0)
            })
        );
        // The box lies beyond t_max = 3: the primitive is never asked.
        assert!(!one.any(&ray, R::from_f64(3.0), |_, _| panic!("pruned")));
    }

    #[test]
    fn no_primitives_and_one_primitive_are_handled() {
        empty_and_single::<f32>();
        empty_and_single::<f64>();
    }

    /// Peak resident memory of this process (VmHWM), in MiB.
    fn peak_rss_mib() -> f64 {
        let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
        status
            .lines()
            .find_map(|l| l.strip_prefix("VmHWM:"))
            .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
            .map_or(f64::NAN, |kb| kb / 1024.0)
    }

    fn million<R: Real>() -> f64 {
        let mut rng = Rng::new(5);
        let b = boxes(&spheres::<R>(&mut rng, 1_000_000, 10.0, 0.0));
        let start = std::time::Instant::now();
        let bvh = Bvh::build(&b);
        let took = start.elapsed().as_secs_f64();
        let peak = peak_rss_mib();
        println!(
            "{}: 1e6 sphere boxes, {} nodes, depth {}, build {took:.3} s, peak RSS so far \
             {peak:.1} MiB",
            R::NAME,
            bvh.nodes().len(),
            bvh.depth(),
        );
        peak
    }

    #[test]
    #[ignore = "measurement, run by hand in release: cargo test --release --lib \
                geometry::bvh::tests::a_million -- --ignored --nocapture"]
    fn a_million_sphere_boxes_build_within_the_memory_budget() {
        // f32 first: the peak after f64 then covers both.
        million::<f32>();
        let peak = million::<f64>();
        assert!(peak < 300.0, "peak RSS {peak} MiB");
    }
}
