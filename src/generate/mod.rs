//! `phong new`: fresh problems whose numbers are friendly to hand calculation, each with its
//! answer key (computed by the solver), reproducible from a seed.
//!
//! Friendly means: every direction is a unit vector with exact two-decimal components, from a
//! Pythagorean triple or quadruple ((3, 4, 0)/5, (7, 24, 0)/25, (12, 15, 16)/25, (9, 12, 20)/25,
//! with components permuted and signs flipped); every point is P + d·u with integer P and
//! integer distance d, so d = ‖P_l − P‖ is an integer and every cosine is a short fraction;
//! colours and coefficients have one decimal. Lights face the surface (cos θ ≥ 0.2), so the
//! generated problems have no trap: they practise the calculation.
//!
//! Reproducible: ChaCha8 (a fixed, documented algorithm) seeded with `seed`, one stream per
//! problem, and integers drawn by our own arithmetic, so the same seed gives the same bytes on
//! every platform and in every version of this program that keeps this module's draws.

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

/// The kinds of problem `phong new` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Kind {
    /// Ambient light only, like exercise 4.1.
    Ambient,
    /// A point light, a point with its normal, and a viewer, like exercise 4.2.
    Point,
    /// A ray meeting a plane (in front of its origin), like exercise 4.3.
    RayPlane,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Ambient => "ambient",
            Kind::Point => "point",
            Kind::RayPlane => "ray-plane",
        }
    }
}

/// One generated problem.
pub struct Generated {
    /// `KIND-SEED-NNN.json`.
    pub file_name: String,
    problem: ProblemOut,
}

impl Generated {
    /// The file's text: pretty JSON (fields in the order a person reads them) and a newline.
    pub fn text(&self) -> String {
        let mut s = serde_json::to_string_pretty(&self.problem).expect("a problem serialises");
        s.push('\n');
        s
    }
}

/// Several problems as one text: one JSON document, or an array for several.
pub fn text_of_all(problems: &[Generated]) -> String {
    let mut s = if problems.len() == 1 {
        serde_json::to_string_pretty(&problems[0].problem)
    } else {
        let all: Vec<&ProblemOut> = problems.iter().map(|p| &p.problem).collect();
        serde_json::to_string_pretty(&all)
    }
    .expect("problems serialise");
    s.push('\n');
    s
}

/// A number written as a person would: `4`, not `4.0`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Num(f64);

impl Serialize for Num {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.0.fract() == 0.0 && self.0.abs() < 1e15 {
            s.serialize_i64(self.0 as i64)
        } else {
            s.serialize_f64(self.0)
        }
    }
}

type N3 = [Num; 3];

fn n3(v: [f64; 3]) -> N3 {
    v.map(|x| Num(if x == 0.0 { 0.0 } else { x }))
}

/// Unit vectors with exact two-decimal components: integer numerators over a denominator.
const UNITS: [([i64; 3], i64); 4] = [
    ([3, 4, 0], 5),
    ([7, 24, 0], 25),
    ([12, 15, 16], 25),
    ([9, 12, 20], 25),
];

/// A direction as integers over a denominator (exact), and as f64.
#[derive(Clone, Copy, Debug)]
struct Unit {
    num: [i64; 3],
    den: i64,
}

impl Unit {
    fn f(self) -> [f64; 3] {
        self.num.map(|x| x as f64 / self.den as f64)
    }
    /// The dot product, exactly, as a fraction over den·den'.
    fn dot(self, o: Unit) -> f64 {
        let n: i64 = (0..3).map(|i| self.num[i] * o.num[i]).sum();
        n as f64 / (self.den * o.den) as f64
    }
}

/// Integer draws from ChaCha8.
struct Draw(ChaCha8Rng);

impl Draw {
    /// An integer in [0, n), by Lemire's multiply-shift (the bias, below 2^-55, is immaterial).
    fn below(&mut self, n: u64) -> u64 {
        ((u128::from(self.0.next_u64()) * u128::from(n)) >> 64) as u64
    }
    /// An integer in [lo, hi].
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }
    /// A unit vector from [`UNITS`], its components permuted and their signs drawn.
    fn unit(&mut self) -> Unit {
        let (n, den) = self.pick(&UNITS);
        const PERMS: [[usize; 3]; 6] = [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ];
        let p = self.pick(&PERMS);
        let mut num = [n[p[0]], n[p[1]], n[p[2]]];
        for x in &mut num {
            if self.below(2) == 1 {
                *x = -*x;
            }
        }
        Unit { num, den }
    }
    /// A unit vector u with u·N ≥ `min` (on N's side of the surface, not grazing it).
    fn unit_facing(&mut self, n: Unit, min: f64) -> Unit {
        loop {
            let u = self.unit();
            if u.dot(n) >= min {
                return u;
            }
        }
    }
    /// A colour with one decimal per channel, each in [lo, hi] tenths.
    fn color(&mut self, lo: i64, hi: i64) -> N3 {
        n3([0; 3].map(|_| self.range(lo, hi) as f64 / 10.0))
    }
    /// An integer point with coordinates in [−r, r].
    fn point(&mut self, r: i64) -> [i64; 3] {
        [0; 3].map(|_| self.range(-r, r))
    }
}

/// P + d·u, exactly (every coordinate a short decimal).
fn offset(p: [i64; 3], d: i64, u: Unit) -> N3 {
    n3([0, 1, 2].map(|i| (p[i] * u.den + d * u.num[i]) as f64 / u.den as f64))
}

fn f3(p: [i64; 3]) -> N3 {
    n3(p.map(|x| x as f64))
}

#[derive(Serialize)]
struct LightOut {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    position: Option<N3>,
    color: N3,
    #[serde(skip_serializing_if = "Option::is_none")]
    falloff: Option<u8>,
}

#[derive(Serialize)]
struct MaterialOut {
    ambient: N3,
    #[serde(skip_serializing_if = "Option::is_none")]
    diffuse: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    specular: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    shininess: Option<u32>,
}

#[derive(Serialize)]
struct PointOut {
    #[serde(skip_serializing_if = "Option::is_none")]
    position: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<N3>,
    material: &'static str,
}

#[derive(Serialize)]
struct RayOut {
    origin: N3,
    direction: N3,
}

#[derive(Serialize)]
struct PlaneOut {
    #[serde(rename = "type")]
    kind: &'static str,
    point: N3,
    normal: N3,
    material: &'static str,
}

#[derive(Serialize)]
struct ProblemOut {
    title: String,
    question: &'static str,
    materials: std::collections::BTreeMap<&'static str, MaterialOut>,
    lights: Vec<LightOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    viewer: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<PointOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ray: Option<RayOut>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    surfaces: Vec<PlaneOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    answer: Option<N3>,
}

/// Writes `count` problems of `kind` from `seed`.
pub fn generate(kind: Kind, count: u32, seed: u64) -> Vec<Generated> {
    (1..=count)
        .map(|i| {
            // One stream per kind and problem: problem i is the same whatever the count.
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            rng.set_stream((kind as u64) << 32 | u64::from(i));
            let mut problem = draw(kind, &mut Draw(rng), i, seed);
            problem.answer = Some(n3(answer_key(&problem)));
            Generated {
                file_name: format!("{}-{seed}-{i:03}.json", kind.name()),
                problem,
            }
        })
        .collect()
}

fn draw(kind: Kind, r: &mut Draw, i: u32, seed: u64) -> ProblemOut {
    let title = format!("Generated {} problem {i} (seed {seed})", kind.name());
    let mut materials = std::collections::BTreeMap::new();
    match kind {
        Kind::Ambient => {
            let mut lights = vec![LightOut {
                kind: "ambient",
                position: None,
                color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
                falloff: None,
            }];
            if r.below(2) == 1 {
                lights.push(LightOut {
                    kind: "ambient",
                    position: None,
                    color: n3([0; 3].map(|_| r.pick(&[0.0, 0.5]))),
                    falloff: None,
                });
            }
            materials.insert(
                "M",
                MaterialOut {
                    ambient: r.color(1, 9),
                    diffuse: None,
                    specular: None,
                    shininess: None,
                },
            );
            ProblemOut {
                title,
                question: "What is the colour of any point of the object (Eq. 4.6)?",
                materials,
                lights,
                viewer: None,
                point: Some(PointOut {
                    position: None,
                    normal: None,
                    material: "M",
                }),
                ray: None,
                surfaces: Vec::new(),
                answer: None,
            }
        }
        Kind::Point | Kind::RayPlane => {
            let p = r.point(4);
            let n = r.unit();
            let light_dir = r.unit_facing(n, 0.2);
            let d = r.range(1, 5);
            let falloff = r.below(3) as u8;
            let mut lights = Vec::new();
            if kind == Kind::RayPlane || r.below(2) == 1 {
                lights.push(LightOut {
                    kind: "ambient",
                    position: None,
                    color: n3([0; 3].map(|_| r.pick(&[0.0, 0.5, 1.0]))),
                    falloff: None,
                });
            }
            lights.push(LightOut {
                kind: "point",
                position: Some(offset(p, d, light_dir)),
                color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
                falloff: Some(falloff),
            });
            materials.insert(
                "M",
                MaterialOut {
                    ambient: r.color(1, 9),
                    diffuse: Some(r.color(1, 9)),
                    specular: Some(r.color(1, 5)),
                    shininess: Some(r.range(1, 3) as u32),
                },
            );
            let viewer_dir = r.unit_facing(n, 0.2);
            let e = r.range(1, 5);
            let viewer = offset(p, e, viewer_dir);
            if kind == Kind::Point {
                ProblemOut {
                    title,
                    question: "What is the colour of P seen by the viewer, by Phong's model \
                               (Eq. 4.16)?",
                    materials,
                    lights,
                    viewer: Some(viewer),
                    point: Some(PointOut {
                        position: Some(f3(p)),
                        normal: Some(n3(n.f())),
                        material: "M",
                    }),
                    ray: None,
                    surfaces: Vec::new(),
                    answer: None,
                }
            } else {
                // The ray arrives from N's side: its origin is P + t·u with u·N > 0, D = −u.
                let toward = r.unit_facing(n, 0.2);
                let t = r.range(2, 6);
                // The plane through a point Q of it other than P: Q = P ± T, T an integer
                // tangent.
                let tangent = tangent(n.num);
                let k = r.pick(&[-1, 1]);
                let q = [0, 1, 2].map(|i| p[i] + k * tangent[i]);
                let with_viewer = r.below(2) == 1;
                ProblemOut {
                    title,
                    question: "What is the colour where the ray meets the plane, by Phong's model \
                               (Eq. 4.16)? Without a viewer, the ray comes from the eye.",
                    materials,
                    lights,
                    viewer: with_viewer.then_some(viewer),
                    point: None,
                    ray: Some(RayOut {
                        origin: offset(p, t, toward),
                        direction: n3(toward.f().map(|x| -x)),
                    }),
                    surfaces: vec![PlaneOut {
                        kind: "plane",
                        point: f3(q),
                        normal: n3(n.f()),
                        material: "M",
                    }],
                    answer: None,
                }
            }
        }
    }
}

/// The shortest integer vector perpendicular to `n` among (b, −a, 0), (0, c, −b), (c, 0, −a),
/// each divided by the gcd of its components.
fn tangent(n: [i64; 3]) -> [i64; 3] {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 {
            a.abs()
        } else {
            gcd(b, a % b)
        }
    }
    let [a, b, c] = n;
    [[b, -a, 0], [0, c, -b], [c, 0, -a]]
        .into_iter()
        .filter(|t| t.iter().any(|&x| x != 0))
        .map(|t| {
            let g = gcd(gcd(t[0], t[1]), t[2]);
            t.map(|x| x / g)
        })
        .min_by_key(|t| t.iter().map(|x| x * x).sum::<i64>())
        .expect("a unit vector has a non-zero component")
}

/// The answer key: the solver's colour (clamped), rounded to six decimals.
fn answer_key(problem: &ProblemOut) -> [f64; 3] {
    let text = serde_json::to_string(problem).expect("a problem serialises");
    let file = crate::problem::parse_str(std::path::Path::new("generated"), &text)
        .expect("a generated problem parses");
    let p = crate::problem::validate::validate::<f64>(&file).expect("a generated problem is valid");
    let s = crate::solve::solve(&p).expect("a generated problem solves");
    let e = s
        .evaluation
        .expect("a generated problem has a point to shade");
    use crate::core::Vector;
    e.clamped.to_array().map(|x| {
        let r: f64 = format!("{x:.6}").parse().expect("a number");
        if r == 0.0 {
            0.0
        } else {
            r
        }
    })
}
