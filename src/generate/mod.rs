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

/// The kinds of problem `phong new` writes (`--kind`).
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Kind {
    Ambient,
    Point,
    RayPlane,
    Directional,
    Spot,
    Several,
    Sphere,
    Secondary,
}

impl Kind {
    /// The kind's word, as `--kind` takes it and the file names begin.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Ambient => "ambient",
            Kind::Point => "point",
            Kind::RayPlane => "ray-plane",
            Kind::Directional => "directional",
            Kind::Spot => "spot",
            Kind::Several => "several",
            Kind::Sphere => "sphere",
            Kind::Secondary => "secondary",
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
#[derive(Clone, Copy, Debug, Default, PartialEq)]
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

#[derive(Serialize, Default)]
struct LightOut {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    position: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    direction: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    angle: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    exponent: Option<u32>,
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
    #[serde(skip_serializing_if = "Option::is_none")]
    reflectivity: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    transmissivity: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ior: Option<Num>,
}

/// The render settings of a problem about secondary rays (the format's `render`).
#[derive(Serialize)]
struct RenderOut {
    max_level: u32,
    min_weight: Num,
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
struct SurfaceOut {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    center: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius: Option<Num>,
    material: &'static str,
}

/// Where the problem came from (the format's `generated`): metadata, not part of the question.
#[derive(Serialize)]
struct GeneratedOut {
    kind: &'static str,
    seed: u64,
    index: u32,
}

#[derive(Serialize)]
struct ProblemOut {
    title: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    title_pt: Option<String>,
    question: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    question_pt: Option<String>,
    generated: GeneratedOut,
    materials: std::collections::BTreeMap<&'static str, MaterialOut>,
    lights: Vec<LightOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    viewer: Option<N3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<PointOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ray: Option<RayOut>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    surfaces: Vec<SurfaceOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    render: Option<RenderOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    answer: Option<N3>,
}

/// The languages a statement is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tongue {
    En,
    Pt,
}

/// Writes `count` problems of `kind` from `seed`; with `portuguese`, each has its title and
/// question in Portuguese too (`title_pt`, `question_pt`).
pub fn generate(kind: Kind, count: u32, seed: u64, portuguese: bool) -> Vec<Generated> {
    (1..=count)
        .map(|i| {
            // One stream per kind and problem: problem i is the same whatever the count.
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            rng.set_stream((kind as u64) << 32 | u64::from(i));
            let mut problem = draw(kind, &mut Draw(rng), i, seed);
            problem.question = statement(&problem, Tongue::En);
            if portuguese {
                problem.title_pt = Some(title(kind, i, Tongue::Pt));
                problem.question_pt = Some(statement(&problem, Tongue::Pt));
            }
            problem.answer = Some(n3(answer_key(&problem)));
            Generated {
                file_name: format!("{}-{seed}-{i:03}.json", kind.name()),
                problem,
            }
        })
        .collect()
}

fn title(kind: Kind, i: u32, t: Tongue) -> String {
    let (en, pt) = match kind {
        Kind::Ambient => ("ambient light", "luz ambiente"),
        Kind::Point => ("point light", "luz pontual"),
        Kind::RayPlane => ("ray and plane", "raio e plano"),
        Kind::Directional => ("directional light", "luz direcional"),
        Kind::Spot => ("spot light", "luz spot"),
        Kind::Several => ("several lights", "várias luzes"),
        Kind::Sphere => ("ray and sphere", "raio e esfera"),
        Kind::Secondary => ("secondary rays", "raios secundários"),
    };
    match t {
        Tongue::En => format!("Generated problem {i}: {en}"),
        Tongue::Pt => format!("Problema gerado {i}: {pt}"),
    }
}

fn ambient_light(r: &mut Draw, levels: &[f64]) -> LightOut {
    LightOut {
        kind: "ambient",
        color: n3([0; 3].map(|_| r.pick(levels))),
        ..LightOut::default()
    }
}

fn point_light(p: [i64; 3], n: Unit, r: &mut Draw) -> LightOut {
    let light_dir = r.unit_facing(n, 0.2);
    let d = r.range(1, 5);
    let falloff = r.below(3) as u8;
    LightOut {
        kind: "point",
        position: Some(offset(p, d, light_dir)),
        color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
        falloff: Some(falloff),
        ..LightOut::default()
    }
}

fn directional_light(n: Unit, r: &mut Draw) -> LightOut {
    let toward = r.unit_facing(n, 0.2);
    LightOut {
        kind: "directional",
        direction: Some(n3(toward.f().map(|x| -x))),
        color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
        ..LightOut::default()
    }
}

/// A spot light in front of the surface whose cone holds P (`inside`) or not, with
/// |ψ − γ| ≥ 5°: the cone test is never decided by rounding.
fn spot_light(p: [i64; 3], n: Unit, inside: bool, r: &mut Draw) -> LightOut {
    let light_dir = r.unit_facing(n, 0.2);
    let d = r.range(1, 5);
    let falloff = r.below(3) as u8;
    let angle = r.pick(&[30u32, 45, 60]);
    let gamma = f64::from(angle);
    // From the light to P is −light_dir; ψ is the angle between the axis and it.
    let to_point = Unit {
        num: light_dir.num.map(|x| -x),
        den: light_dir.den,
    };
    // Drawn from the table; should none fit, the axis straight at P (ψ = 0) or away (ψ = 180°).
    let mut axis = if inside { to_point } else { light_dir };
    for _ in 0..10_000 {
        let a = r.unit();
        let psi = a.dot(to_point).clamp(-1.0, 1.0).acos().to_degrees();
        if (inside && psi <= gamma - 5.0) || (!inside && psi >= gamma + 5.0) {
            axis = a;
            break;
        }
    }
    LightOut {
        kind: "spot",
        position: Some(offset(p, d, light_dir)),
        axis: Some(n3(axis.f())),
        angle: Some(angle),
        exponent: Some(r.range(1, 2) as u32),
        color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
        falloff: Some(falloff),
        ..LightOut::default()
    }
}

fn phong_material(r: &mut Draw) -> MaterialOut {
    MaterialOut {
        ambient: r.color(1, 9),
        diffuse: Some(r.color(1, 9)),
        specular: Some(r.color(1, 5)),
        shininess: Some(r.range(1, 3) as u32),
        reflectivity: None,
        transmissivity: None,
        ior: None,
    }
}

fn problem(kind: Kind, i: u32, seed: u64) -> ProblemOut {
    ProblemOut {
        title: title(kind, i, Tongue::En),
        title_pt: None,
        question: String::new(),
        question_pt: None,
        generated: GeneratedOut {
            kind: kind.name(),
            seed,
            index: i,
        },
        materials: std::collections::BTreeMap::new(),
        lights: Vec::new(),
        viewer: None,
        point: None,
        ray: None,
        surfaces: Vec::new(),
        render: None,
        answer: None,
    }
}

fn draw(kind: Kind, r: &mut Draw, i: u32, seed: u64) -> ProblemOut {
    let mut out = problem(kind, i, seed);
    match kind {
        Kind::Ambient => {
            out.lights.push(ambient_light(r, &[0.5, 1.0]));
            if r.below(2) == 1 {
                out.lights.push(ambient_light(r, &[0.0, 0.5]));
            }
            out.materials.insert(
                "M",
                MaterialOut {
                    ambient: r.color(1, 9),
                    diffuse: None,
                    specular: None,
                    shininess: None,
                    reflectivity: None,
                    transmissivity: None,
                    ior: None,
                },
            );
            out.point = Some(PointOut {
                position: None,
                normal: None,
                material: "M",
            });
        }
        Kind::Point | Kind::RayPlane => {
            // The draws in the order of earlier versions: the same seed, the same problem.
            let p = r.point(4);
            let n = r.unit();
            let light_dir = r.unit_facing(n, 0.2);
            let d = r.range(1, 5);
            let falloff = r.below(3) as u8;
            if kind == Kind::RayPlane || r.below(2) == 1 {
                out.lights.push(ambient_light(r, &[0.0, 0.5, 1.0]));
            }
            out.lights.push(LightOut {
                kind: "point",
                position: Some(offset(p, d, light_dir)),
                color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
                falloff: Some(falloff),
                ..LightOut::default()
            });
            out.materials.insert("M", phong_material(r));
            let viewer_dir = r.unit_facing(n, 0.2);
            let e = r.range(1, 5);
            let viewer = offset(p, e, viewer_dir);
            if kind == Kind::Point {
                out.viewer = Some(viewer);
                out.point = Some(PointOut {
                    position: Some(f3(p)),
                    normal: Some(n3(n.f())),
                    material: "M",
                });
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
                out.viewer = with_viewer.then_some(viewer);
                out.ray = Some(RayOut {
                    origin: offset(p, t, toward),
                    direction: n3(toward.f().map(|x| -x)),
                });
                out.surfaces.push(SurfaceOut {
                    kind: "plane",
                    point: Some(f3(q)),
                    normal: Some(n3(n.f())),
                    center: None,
                    radius: None,
                    material: "M",
                });
            }
        }
        Kind::Directional | Kind::Spot | Kind::Several => {
            let p = r.point(4);
            let n = r.unit();
            if r.below(2) == 1 {
                out.lights.push(ambient_light(r, &[0.0, 0.5, 1.0]));
            }
            match kind {
                Kind::Directional => out.lights.push(directional_light(n, r)),
                Kind::Spot => {
                    let inside = r.below(2) == 1;
                    out.lights.push(spot_light(p, n, inside, r));
                }
                _ => {
                    if out.lights.is_empty() {
                        out.lights.push(ambient_light(r, &[0.5, 1.0]));
                    }
                    let first = point_light(p, n, r);
                    let at = first.position;
                    out.lights.push(first);
                    if r.below(2) == 1 {
                        // Two lights at one place would be one light twice: the second is drawn
                        // again until it stands elsewhere (at most a few draws; the next
                        // direction or distance differs almost always).
                        let mut second = point_light(p, n, r);
                        for _ in 0..64 {
                            if second.position != at {
                                break;
                            }
                            second = point_light(p, n, r);
                        }
                        out.lights.push(second);
                    } else {
                        out.lights.push(directional_light(n, r));
                    }
                }
            }
            out.materials.insert("M", phong_material(r));
            let viewer_dir = r.unit_facing(n, 0.2);
            let e = r.range(1, 5);
            out.viewer = Some(offset(p, e, viewer_dir));
            out.point = Some(PointOut {
                position: Some(f3(p)),
                normal: Some(n3(n.f())),
                material: "M",
            });
        }
        Kind::Secondary => draw_secondary(&mut out, r),
        Kind::Sphere => {
            // P = C + ρ·n on the sphere; the ray from P + t·u (u·n ≥ 0.2) along −u meets it
            // first at P (its second hit is 2ρ(u·n) further on).
            let c = r.point(3);
            let radius = r.range(1, 3);
            let n = r.unit();
            let toward = r.unit_facing(n, 0.2);
            let t = r.range(2, 6);
            if r.below(2) == 1 {
                out.lights.push(ambient_light(r, &[0.0, 0.5, 1.0]));
            }
            let light_dir = r.unit_facing(n, 0.2);
            let d = r.range(1, 5);
            out.lights.push(LightOut {
                kind: "point",
                position: Some(offset2(c, radius, n, d, light_dir)),
                color: n3([0; 3].map(|_| r.pick(&[0.5, 1.0]))),
                falloff: Some(r.below(3) as u8),
                ..LightOut::default()
            });
            out.materials.insert("M", phong_material(r));
            out.ray = Some(RayOut {
                origin: offset2(c, radius, n, t, toward),
                direction: n3(toward.f().map(|x| -x)),
            });
            out.surfaces.push(SurfaceOut {
                kind: "sphere",
                point: None,
                normal: None,
                center: Some(f3(c)),
                radius: Some(Num(radius as f64)),
                material: "M",
            });
        }
    }
    out
}

/// A problem about secondary rays: a ray meeting a plane from its normal's side at an integer
/// t (as `ray-plane`'s), a white point light in front, a material with O_r (one decimal, up to
/// 0.5, so that w_s often meets the minimum weight), O_t and a friendly η, and render settings
/// whose level or weight stops a child in about half the problems.
fn draw_secondary(out: &mut ProblemOut, r: &mut Draw) {
    let p = r.point(4);
    let n = r.unit();
    let light_dir = r.unit_facing(n, 0.2);
    let d = r.range(1, 5);
    out.lights.push(ambient_light(r, &[0.0, 0.5, 1.0]));
    out.lights.push(LightOut {
        kind: "point",
        position: Some(offset(p, d, light_dir)),
        color: n3([1.0; 3]),
        falloff: Some(0),
        ..LightOut::default()
    });
    let mut m = phong_material(r);
    m.reflectivity = Some(r.color(0, 5));
    m.transmissivity = Some(r.color(1, 9));
    m.ior = Some(Num(r.pick(&[1.25, 1.5, 2.0])));
    out.materials.insert("M", m);
    let toward = r.unit_facing(n, 0.2);
    let t = r.range(2, 6);
    let tangent = tangent(n.num);
    let k = r.pick(&[-1, 1]);
    let q = [0, 1, 2].map(|i| p[i] + k * tangent[i]);
    out.ray = Some(RayOut {
        origin: offset(p, t, toward),
        direction: n3(toward.f().map(|x| -x)),
    });
    out.surfaces.push(SurfaceOut {
        kind: "plane",
        point: Some(f3(q)),
        normal: Some(n3(n.f())),
        center: None,
        radius: None,
        material: "M",
    });
    out.render = Some(RenderOut {
        max_level: r.pick(&[1, 2, 2, 3]),
        min_weight: Num(r.pick(&[0.1, 0.2, 0.3])),
    });
}

/// C + ρ·n + d·u, exactly.
fn offset2(c: [i64; 3], rho: i64, n: Unit, d: i64, u: Unit) -> N3 {
    let den = n.den * u.den;
    n3([0, 1, 2]
        .map(|i| (c[i] * den + rho * n.num[i] * u.den + d * u.num[i] * n.den) as f64 / den as f64))
}

/// A number in a statement: "4", "0.5", "−1" (Portuguese writes the minus sign).
fn word_num(x: Num, t: Tongue) -> String {
    let s = serde_json::to_string(&x).expect("a number serialises");
    match (t, s.strip_prefix('-')) {
        (Tongue::Pt, Some(rest)) => format!("\u{2212}{rest}"),
        _ => s,
    }
}

fn word_vec(v: &N3, t: Tongue) -> String {
    format!(
        "({}, {}, {})",
        word_num(v[0], t),
        word_num(v[1], t),
        word_num(v[2], t)
    )
}

fn falloff_words(f: u8, t: Tongue) -> &'static str {
    match (t, f) {
        (Tongue::En, 0) => "no falloff (f = 0)",
        (Tongue::En, 1) => "linear falloff (f = 1)",
        (Tongue::En, _) => "quadratic falloff (f = 2)",
        (Tongue::Pt, 0) => "sem decaimento (f = 0)",
        (Tongue::Pt, 1) => "com decaimento linear (f = 1)",
        (Tongue::Pt, _) => "com decaimento quadrático (f = 2)",
    }
}

/// The sentence of two or more ambient lights, each named apart (I_a1, I_a2, …): "Two ambient
/// lights, I_a1 = (1, 0.5, 1) and I_a2 = (0, 0.5, 0.5), light the scene." ("Duas luzes
/// ambientes, … iluminam a cena."). Their sum is the I_a of Eq. 4.6.
fn several_ambient(colours: &[String], t: Tongue) -> String {
    let en = t == Tongue::En;
    let mut named: Vec<String> = colours
        .iter()
        .enumerate()
        .map(|(k, c)| format!("I_a{} = {c}", k + 1))
        .collect();
    let last = named.pop().unwrap_or_default();
    let list = format!(
        "{} {} {last}",
        named.join(", "),
        if en { "and" } else { "e" }
    );
    let count = match (colours.len(), en) {
        (2, true) => "Two".to_owned(),
        (3, true) => "Three".to_owned(),
        (2, false) => "Duas".to_owned(),
        (3, false) => "Três".to_owned(),
        (n, _) => n.to_string(),
    };
    if en {
        format!("{count} ambient lights, {list}, light the scene.")
    } else {
        format!("{count} luzes ambientes, {list}, iluminam a cena.")
    }
}

/// The question with its data in full sentences, in the chapter's style.
fn statement(p: &ProblemOut, t: Tongue) -> String {
    let v = |x: &N3| word_vec(x, t);
    let en = t == Tongue::En;
    let mut s: Vec<String> = Vec::new();
    let ambient: Vec<String> = p
        .lights
        .iter()
        .filter(|l| l.kind == "ambient")
        .map(|l| v(&l.color))
        .collect();
    let mut ambient_said = false;
    // Several lights that are not ambient: each its own symbols, C_l1 and P_l1, C_l2 and D_l2
    // (one C_l for two values would read as a contradiction).
    let others = p.lights.iter().filter(|l| l.kind != "ambient").count();
    let mut other = 0;
    for l in &p.lights {
        let k = if l.kind != "ambient" && others > 1 {
            other += 1;
            other.to_string()
        } else {
            String::new()
        };
        let c = v(&l.color);
        let at = l.position.as_ref().map(v).unwrap_or_default();
        let f = falloff_words(l.falloff.unwrap_or(0), t);
        // Several ambient lights are several values: each its own symbol, in one sentence
        // (one I_a for two values would read as a contradiction).
        if l.kind == "ambient" && ambient.len() > 1 {
            if !ambient_said {
                ambient_said = true;
                s.push(several_ambient(&ambient, t));
            }
            continue;
        }
        // A black ambient light (each channel drawn 0) lights nothing: said as what it is.
        let black = l.color.iter().all(|x| x.0 == 0.0);
        s.push(match (l.kind, en) {
            ("ambient", true) if black => format!("The ambient light is black, I_a = {c}."),
            ("ambient", false) if black => format!("A luz ambiente é preta, I_a = {c}."),
            ("ambient", true) => format!("An ambient light I_a = {c} lights the scene."),
            ("ambient", false) => format!("Uma luz ambiente I_a = {c} ilumina a cena."),
            ("point", true) => {
                format!("A point light of colour C_l{k} = {c} is at P_l{k} = {at}, with {f}.")
            }
            ("point", false) => {
                format!("Uma luz pontual de cor C_l{k} = {c} está em P_l{k} = {at}, {f}.")
            }
            ("directional", true) => format!(
                "A directional light of colour C_l{k} = {c} travels along D_l{k} = {}.",
                v(l.direction.as_ref().expect("a direction"))
            ),
            ("directional", false) => format!(
                "Uma luz direcional de cor C_l{k} = {c} se propaga ao longo de D_l{k} = {}.",
                v(l.direction.as_ref().expect("a direction"))
            ),
            (_, true) => format!(
                "A spot light of colour C_l{k} = {c} is at P_l{k} = {at} and points along D_l{k} = {}, \
                 with half-angle γ = {}°, exponent e = {} and {f}.",
                v(l.axis.as_ref().expect("an axis")),
                l.angle.unwrap_or(0),
                l.exponent.unwrap_or(0)
            ),
            (_, false) => format!(
                "Uma luz spot de cor C_l{k} = {c} está em P_l{k} = {at} e aponta ao longo de D_l{k} = {}, \
                 com ângulo γ = {}°, expoente e = {} e {f}.",
                v(l.axis.as_ref().expect("an axis")),
                l.angle.unwrap_or(0),
                l.exponent.unwrap_or(0)
            ),
        });
    }
    if let Some(m) = p.materials.get("M") {
        let mut terms = vec![format!("O_a = {}", v(&m.ambient))];
        if let Some(d) = &m.diffuse {
            terms.push(format!("O_d = {}", v(d)));
        }
        if let Some(sp) = &m.specular {
            terms.push(format!("O_s = {}", v(sp)));
        }
        if let Some(n) = m.shininess {
            terms.push(format!("n_s = {n}"));
        }
        if let Some(o_r) = &m.reflectivity {
            terms.push(format!("O_r = {}", v(o_r)));
        }
        if let Some(o_t) = &m.transmissivity {
            terms.push(format!("O_t = {}", v(o_t)));
        }
        if let Some(eta) = m.ior {
            terms.push(if en {
                format!("index of refraction η = {}", word_num(eta, t))
            } else {
                format!("índice de refração η = {}", word_num(eta, t))
            });
        }
        let last = terms.pop().expect("O_a");
        let list = if terms.is_empty() {
            last
        } else {
            format!(
                "{} {} {last}",
                terms.join(", "),
                if en { "and" } else { "e" }
            )
        };
        s.push(if en {
            format!("The material M has {list}.")
        } else {
            format!("O material M tem {list}.")
        });
    }
    if let Some(pt) = &p.point {
        if let (Some(at), Some(n)) = (&pt.position, &pt.normal) {
            s.push(if en {
                format!("The point P = {} has the normal N = {}.", v(at), v(n))
            } else {
                format!("O ponto P = {} tem normal N = {}.", v(at), v(n))
            });
        }
    }
    if let Some(ray) = &p.ray {
        let (o, d) = (v(&ray.origin), v(&ray.direction));
        let surface = &p.surfaces[0];
        let what = match (surface.kind, en) {
            ("plane", true) => format!(
                "the plane through Q = {} with normal N = {}",
                v(surface.point.as_ref().expect("a point")),
                v(surface.normal.as_ref().expect("a normal"))
            ),
            ("plane", false) => format!(
                "o plano que passa por Q = {} com normal N = {}",
                v(surface.point.as_ref().expect("a point")),
                v(surface.normal.as_ref().expect("a normal"))
            ),
            (_, true) => format!(
                "the sphere of centre C = {} and radius r = {}",
                v(surface.center.as_ref().expect("a centre")),
                word_num(surface.radius.expect("a radius"), t)
            ),
            (_, false) => format!(
                "a esfera de centro C = {} e raio r = {}",
                v(surface.center.as_ref().expect("a centre")),
                word_num(surface.radius.expect("a radius"), t)
            ),
        };
        s.push(if en {
            format!("A ray leaves O = {o} along D = {d} and meets {what}, of material M.")
        } else {
            format!("Um raio parte de O = {o} na direção D = {d} e atinge {what}, de material M.")
        });
    }
    match (&p.viewer, &p.ray, en) {
        (Some(e), _, true) => s.push(format!("The viewer is at E = {}.", v(e))),
        (Some(e), _, false) => s.push(format!("O observador está em E = {}.", v(e))),
        (None, Some(_), true) => {
            s.push("No viewer is given: the ray comes from the eye (V = D).".into())
        }
        (None, Some(_), false) => {
            s.push("Não é dado observador: o raio vem do olho (V = D).".into())
        }
        _ => {}
    }
    if let Some(settings) = &p.render {
        let (l, w) = (settings.max_level, word_num(settings.min_weight, t));
        s.push(if en {
            format!(
                "The medium on the side the normal points to has index 1. The tracer's maximum level is {l} and \
                 its minimum weight {w}. What colour does the ray see where it meets the \
                 surface (Eq. 4.16)? What are the directions of the reflected ray (Eq. 4.17) \
                 and of the transmitted ray (Snell's law), their levels and weights, and is \
                 each traced?"
            )
        } else {
            format!(
                "O meio do lado para o qual a normal aponta tem índice 1. O nível máximo do traçador é {l} e o seu \
                 peso mínimo, {w}. Que cor o raio vê no ponto em que atinge a superfície \
                 (Eq. 4.16)? Quais são as direções do raio de reflexão (Eq. 4.17) e do raio \
                 de transmissão (lei de Snell), os seus níveis e pesos, e cada um deles é traçado?"
            )
        });
        return s.join(" ");
    }
    s.push(
        match (
            p.point.as_ref().is_some_and(|x| x.position.is_none()),
            p.ray.is_some(),
            en,
        ) {
            (true, _, true) => "What is the colour of any point of the object (Eq. 4.6)?",
            (true, _, false) => "Qual é a cor de qualquer ponto do objeto (Eq. 4.6)?",
            (_, true, true) => {
                "What colour does the ray see where it meets the surface, by Phong's model \
                 (Eq. 4.16)?"
            }
            (_, true, false) => {
                "Que cor o raio vê no ponto em que atinge a superfície, pelo modelo de Phong \
                 (Eq. 4.16)?"
            }
            (_, _, true) => {
                "What is the colour of P seen by the viewer, by Phong's model (Eq. 4.16)?"
            }
            (_, _, false) => {
                "Qual é a cor de P vista pelo observador, pelo modelo de Phong (Eq. 4.16)?"
            }
        }
        .into(),
    );
    s.join(" ")
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
