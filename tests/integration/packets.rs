//! The packet searches of the wide BVH (`Aggregate::nearest_packet`, `occluded_packet`) give,
//! ray for ray, what the one-ray searches (`Aggregate::nearest`, `occluded`) give: the same
//! shape, the same t and point bit for bit, the same occlusion. The scene is a BVH scene of
//! both kinds (a field of spheres, a grid of triangles sharing edges, a floor plane, and exact
//! duplicates for ties); the packets are tiles of coherent rays as the wide engine makes them,
//! rays that miss everything, rays parallel to the axes (±0 components), rays from inside
//! boxes (sphere centres, triangle corners), mixed octants, every packet size.

use phong::core::{Real, Vector, Wide, V3};
use phong::geometry::{Aggregate, AggregateHit, Plane, Ray, Shape, Sphere, Triangle};

/// SplitMix64 (Steele et al. 2014): the same cases on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    fn pick(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn direction(&mut self) -> [f64; 3] {
        loop {
            let d = [0, 1, 2].map(|_| self.range(-1.0, 1.0));
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if l > 0.1 && l <= 1.0 {
                return d.map(|x| x / l);
            }
        }
    }
}

fn v<R: Real>(a: [f64; 3]) -> V3<R> {
    V3::<R>::new(R::from_f64(a[0]), R::from_f64(a[1]), R::from_f64(a[2]))
}

fn unit(d: [f64; 3]) -> [f64; 3] {
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    d.map(|x| x / l)
}

/// 1,500 spheres on a 40 × 40 field, a 12 × 12 grid of triangle pairs beside it (shared edges
/// and corners: ties), a floor, and a few exact duplicates.
fn scene<R: Real>(rng: &mut Rng) -> Vec<Shape<R>> {
    let mut shapes = vec![Shape::Plane(Plane {
        point: v::<R>([0.0, -0.5, 0.0]),
        normal: v::<R>([0.0, 1.0, 0.0]),
    })];
    for i in 0..1500 {
        let (gx, gz) = ((i % 40) as f64, (i / 40) as f64);
        let r = rng.range(0.1, 0.6);
        shapes.push(Shape::Sphere(Sphere {
            center: v::<R>([
                gx - 20.0 + rng.range(-0.3, 0.3),
                r,
                -gz + rng.range(-0.3, 0.3),
            ]),
            radius: R::from_f64(r),
        }));
    }
    let p = |i: usize, j: usize| v::<R>([20.0 + i as f64, 0.0, -(j as f64)]);
    for i in 0..12 {
        for j in 0..12 {
            shapes.push(Shape::Triangle(Triangle::new(
                p(i, j),
                p(i + 1, j),
                p(i + 1, j + 1),
            )));
            // Every other triangle smooth: its hits carry an interpolated shading normal.
            let mut smooth = Triangle::new(p(i, j), p(i + 1, j + 1), p(i, j + 1));
            let tilt = |k: usize| {
                let a = 0.3 * ((i + j + k) % 5) as f64 / 4.0;
                v::<R>([a.sin(), a.cos(), 0.0])
            };
            smooth.normals = Some(std::sync::Arc::new([tilt(0), tilt(1), tilt(2)]));
            shapes.push(Shape::Triangle(smooth));
        }
    }
    for k in 0..40 {
        shapes.push(shapes[1 + k * 37 % (shapes.len() - 1)].clone());
    }
    shapes
}

/// A packet of `len` rays of one of several kinds.
fn packet<R: Real>(rng: &mut Rng, shapes: &[Shape<R>], len: usize) -> Vec<Ray<R>> {
    let any_origin = |rng: &mut Rng| {
        [
            rng.range(-25.0, 35.0),
            rng.range(-1.0, 6.0),
            rng.range(-42.0, 3.0),
        ]
    };
    let inside = |rng: &mut Rng| match &shapes[1 + rng.pick(shapes.len() - 1)] {
        Shape::Sphere(s) => s.center.to_array().map(|x| x.to_f64()),
        Shape::Triangle(t) => t.p[rng.pick(3)].to_array().map(|x| x.to_f64()),
        Shape::Plane(p) => p.point.to_array().map(|x| x.to_f64()),
    };
    let ray = |o: [f64; 3], d: [f64; 3]| Ray {
        origin: v::<R>(o),
        direction: v::<R>(d),
    };
    match rng.pick(6) {
        // A tile of primary rays from one eye, over the field and the grid
        0 => {
            let eye = [rng.range(-10.0, 30.0), 6.0, 6.0];
            let (x0, y0) = (rng.range(-0.6, 0.6), rng.range(-0.5, -0.05));
            (0..len)
                .map(|k| ray(eye, unit([x0 + 0.004 * k as f64, y0, -1.0])))
                .collect()
        }
        // Coherent shadow rays towards a directional light, from nearby points
        1 => {
            let o = any_origin(rng);
            let to_sun = unit([-0.4, 1.0, 0.6]);
            (0..len)
                .map(|k| ray([o[0] + 0.05 * k as f64, 0.0, o[2]], to_sun))
                .collect()
        }
        // Rays that miss everything (up, away), mixed with ones that do not
        2 => (0..len)
            .map(|k| {
                let d = if k % 3 == 0 {
                    rng.direction()
                } else {
                    unit([rng.range(-1.0, 1.0), 1.0, rng.range(-1.0, 1.0)])
                };
                ray([rng.range(-20.0, 30.0), 8.0, rng.range(-40.0, 0.0)], d)
            })
            .collect(),
        // Parallel to the axes, with ±0 components: 1/D = ±∞, NaN slabs at box faces
        3 => {
            let o = any_origin(rng);
            let a = rng.pick(3);
            (0..len)
                .map(|k| {
                    let zero = if k % 2 == 0 { 0.0 } else { -0.0 };
                    let mut d = [zero, -zero, zero];
                    d[a] = if rng.unit() < 0.5 { 1.0 } else { -1.0 };
                    // Some on a box face: integer grid coordinates
                    let o = if k % 3 == 0 { o.map(f64::round) } else { o };
                    ray([o[0] + 0.5 * k as f64, o[1], o[2]], d)
                })
                .collect()
        }
        // From inside boxes: sphere centres and triangle corners, any direction
        4 => (0..len)
            .map(|_| ray(inside(rng), rng.direction()))
            .collect(),
        // Straight down onto the grid's shared edges and corners (ties): ±0 across, the same
        // for the whole packet (one octant: the lanes go down together) or lane by lane
        _ => {
            let (sign, mixed) = (rng.pick(2), rng.pick(3) == 0);
            (0..len)
                .map(|k| {
                    let zero = if (if mixed { k % 2 } else { sign }) == 0 {
                        0.0
                    } else {
                        -0.0
                    };
                    ray(
                        [
                            20.0 + 0.5 * rng.pick(24) as f64,
                            3.0,
                            -0.5 * rng.pick(24) as f64,
                        ],
                        [zero, -1.0, zero],
                    )
                })
                .collect()
        }
    }
}

type Bits = Option<(usize, u64, [u64; 3], [u64; 3])>;

fn bits<R: Real>(h: &Option<AggregateHit<R>>) -> Bits {
    h.map(|h| {
        (
            h.index,
            h.hit.t.to_f64().to_bits(),
            h.hit.p.to_array().map(|x| x.to_f64().to_bits()),
            h.hit.shading.to_array().map(|x| x.to_f64().to_bits()),
        )
    })
}

fn packets_are_the_one_ray_searches<R: Real>(seed: u64) {
    let lanes = <R::Wide as Wide>::LANES;
    let mut rng = Rng(seed);
    let shapes = scene::<R>(&mut rng);
    let agg = Aggregate::new(shapes.clone());
    let (mut hits, mut blocked_lanes, mut lanes_seen) = (0, 0, 0);
    for p in 0..3000 {
        let len = 1 + p % lanes;
        let rays = packet::<R>(&mut rng, &shapes, len);
        // A shadow ray's t_max: to a light somewhere along the ray, or for ever.
        let t_max: Vec<R> = (0..len)
            .map(|k| {
                if (p + k) % 3 == 0 {
                    R::from_f64(f64::INFINITY)
                } else {
                    R::from_f64(rng.range(0.0, 30.0))
                }
            })
            .collect();
        let mut got = vec![None; len];
        agg.nearest_packet(&rays, &mut got);
        let want_mask = (1u32 << len) - 1;
        let blocked = agg.occluded_packet(&rays, &t_max, want_mask);
        for (k, ray) in rays.iter().enumerate() {
            let one = agg.nearest(ray, R::from_f64(f64::INFINITY));
            assert_eq!(
                bits(&got[k]),
                bits(&one),
                "{}: packet {p}, lane {k} of {len}: {ray:?}",
                R::NAME
            );
            let occluded = agg.occluded(ray, t_max[k]);
            assert_eq!(
                blocked & (1 << k) != 0,
                occluded,
                "{}: packet {p}, lane {k} of {len}: {ray:?} to {}",
                R::NAME,
                t_max[k]
            );
            hits += usize::from(one.is_some());
            blocked_lanes += usize::from(occluded);
            lanes_seen += 1;
        }
    }
    // The cases are not all of one kind: some rays hit and some miss, some are blocked and
    // some are not.
    assert!(
        hits > lanes_seen / 5 && hits < lanes_seen * 9 / 10,
        "{hits} hits of {lanes_seen}"
    );
    assert!(
        blocked_lanes > lanes_seen / 10 && blocked_lanes < lanes_seen * 9 / 10,
        "{blocked_lanes} blocked of {lanes_seen}"
    );
}

#[test]
fn packet_searches_are_the_one_ray_searches_in_f32() {
    packets_are_the_one_ray_searches::<f32>(17);
}

#[test]
fn packet_searches_are_the_one_ray_searches_in_f64() {
    packets_are_the_one_ray_searches::<f64>(71);
}
