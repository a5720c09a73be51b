//! The generated suite of point problems: seeded ordinary problems (ChaCha8, so the same suite on
//! every machine) and every extreme case named by issue 5, each as a group of named cases.
//!
//! A case holds its inputs as f64 numbers; phong reads them from the JSON text it is given (which
//! serde_json writes in the shortest form that reads back to the same f64), so the reference
//! and phong's f64 start from the same binary numbers. phong's f32 starts from those numbers
//! rounded to f32: [`Case::rounded_to_f32`] is that problem, exactly.

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::{json, Value};

/// A light as given in the problem file.
#[derive(Clone, Debug)]
pub enum LightIn {
    Ambient {
        color: [f64; 3],
    },
    Point {
        position: [f64; 3],
        color: [f64; 3],
        falloff: u8,
    },
    Directional {
        direction: [f64; 3],
        color: [f64; 3],
    },
    Spot {
        position: [f64; 3],
        axis: [f64; 3],
        angle: f64,
        exponent: f64,
        color: [f64; 3],
        falloff: u8,
    },
}

/// The material at the point (every colour given, as a product k·O).
#[derive(Clone, Debug)]
pub struct MaterialIn {
    pub ambient: [f64; 3],
    pub diffuse: [f64; 3],
    pub specular: [f64; 3],
    pub shininess: f64,
}

/// One point problem.
#[derive(Clone, Debug)]
pub struct Case {
    /// The row of the report this case belongs to.
    pub group: &'static str,
    pub name: String,
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub viewer: Option<[f64; 3]>,
    pub lights: Vec<LightIn>,
    pub material: MaterialIn,
}

impl Case {
    /// The problem file phong reads.
    pub fn to_json(&self) -> String {
        let lights: Vec<Value> = self
            .lights
            .iter()
            .map(|l| match l {
                LightIn::Ambient { color } => json!({ "type": "ambient", "color": color }),
                LightIn::Point {
                    position,
                    color,
                    falloff,
                } => json!({ "type": "point", "position": position, "color": color,
                             "falloff": falloff }),
                LightIn::Directional { direction, color } => {
                    json!({ "type": "directional", "direction": direction, "color": color })
                }
                LightIn::Spot {
                    position,
                    axis,
                    angle,
                    exponent,
                    color,
                    falloff,
                } => json!({ "type": "spot", "position": position, "axis": axis,
                             "angle": angle, "exponent": exponent, "color": color,
                             "falloff": falloff }),
            })
            .collect();
        let m = &self.material;
        let mut doc = json!({
            "title": self.name,
            "lights": lights,
            "point": {
                "position": self.point,
                "normal": self.normal,
                "material": { "ambient": m.ambient, "diffuse": m.diffuse,
                              "specular": m.specular, "shininess": m.shininess }
            }
        });
        if let Some(e) = self.viewer {
            doc["viewer"] = json!(e);
        }
        doc.to_string()
    }

    /// The same problem with every number rounded to f32, as `--precision f32` reads it.
    pub fn rounded_to_f32(&self) -> Case {
        let r = |x: f64| x as f32 as f64;
        let r3 = |a: [f64; 3]| a.map(r);
        let lights = self
            .lights
            .iter()
            .map(|l| match *l {
                LightIn::Ambient { color } => LightIn::Ambient { color: r3(color) },
                LightIn::Point {
                    position,
                    color,
                    falloff,
                } => LightIn::Point {
                    position: r3(position),
                    color: r3(color),
                    falloff,
                },
                LightIn::Directional { direction, color } => LightIn::Directional {
                    direction: r3(direction),
                    color: r3(color),
                },
                LightIn::Spot {
                    position,
                    axis,
                    angle,
                    exponent,
                    color,
                    falloff,
                } => LightIn::Spot {
                    position: r3(position),
                    axis: r3(axis),
                    angle: r(angle),
                    exponent: r(exponent),
                    color: r3(color),
                    falloff,
                },
            })
            .collect();
        let m = &self.material;
        Case {
            group: self.group,
            name: self.name.clone(),
            point: r3(self.point),
            normal: r3(self.normal),
            viewer: self.viewer.map(r3),
            lights,
            material: MaterialIn {
                ambient: r3(m.ambient),
                diffuse: r3(m.diffuse),
                specular: r3(m.specular),
                shininess: r(m.shininess),
            },
        }
    }

    /// Every light position moved by `offset` (and P and E): the same geometry far from the
    /// origin, as far as the precision lets it stay the same.
    fn translated(&self, offset: [f64; 3], group: &'static str, name: String) -> Case {
        let t = |a: [f64; 3]| add(a, offset);
        let mut c = self.clone();
        c.group = group;
        c.name = name;
        c.point = t(c.point);
        c.viewer = c.viewer.map(t);
        for l in &mut c.lights {
            match l {
                LightIn::Point { position, .. } | LightIn::Spot { position, .. } => {
                    *position = t(*position)
                }
                LightIn::Ambient { .. } | LightIn::Directional { .. } => {}
            }
        }
        c
    }
}

// Small f64 vector helpers for building the cases (not part of any measurement).

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn mul(a: [f64; 3], s: f64) -> [f64; 3] {
    a.map(|x| x * s)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: [f64; 3]) -> [f64; 3] {
    mul(a, 1.0 / dot(a, a).sqrt())
}

/// Seeded draws.
pub struct Draw(ChaCha8Rng);

impl Draw {
    pub fn new(seed: u64) -> Self {
        Draw(ChaCha8Rng::seed_from_u64(seed))
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }

    fn below(&mut self, n: usize) -> usize {
        ((u128::from(self.0.next_u64()) * n as u128) >> 64) as usize
    }

    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len())]
    }

    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// A uniformly random unit direction.
    fn dir(&mut self) -> [f64; 3] {
        loop {
            let v = [
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            ];
            let q = dot(v, v);
            if q > 0.01 && q <= 1.0 {
                return norm(v);
            }
        }
    }

    fn color(&mut self, max: f64) -> [f64; 3] {
        [
            self.range(0.0, max),
            self.range(0.0, max),
            self.range(0.0, max),
        ]
    }

    /// A number as an exercise writes it half of the time (two decimals), raw otherwise.
    fn coord(&mut self, a: f64, b: f64) -> f64 {
        let x = self.range(a, b);
        if self.chance(0.5) {
            (x * 100.0).round() / 100.0
        } else {
            x
        }
    }

    fn point(&mut self, half: f64) -> [f64; 3] {
        [
            self.coord(-half, half),
            self.coord(-half, half),
            self.coord(-half, half),
        ]
    }

    /// A random orthonormal frame (n, t, b).
    fn frame(&mut self) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let n = self.dir();
        let t = loop {
            let c = cross(n, self.dir());
            if dot(c, c) > 0.1 {
                break norm(c);
            }
        };
        (n, t, cross(n, t))
    }

    fn material(&mut self, shininess: f64) -> MaterialIn {
        MaterialIn {
            ambient: self.color(1.0),
            diffuse: self.color(1.0),
            specular: self.color(1.0),
            shininess,
        }
    }
}

/// The f64 quantities the ordinary suite is filtered on (a rough check, not a measurement).
struct Rough {
    cos_theta: f64,
    cos_phi: Option<f64>,
    /// ψ − γ in degrees, and cos ψ, for a spot.
    cone: Option<(f64, f64)>,
}

fn rough(case: &Case, light: &LightIn) -> Option<Rough> {
    let n = norm(case.normal);
    let (l, cone) = match *light {
        LightIn::Ambient { .. } => return None,
        LightIn::Directional { direction, .. } => (norm(direction), None),
        LightIn::Point { position, .. } => (norm(sub(case.point, position)), None),
        LightIn::Spot {
            position,
            axis,
            angle,
            ..
        } => {
            let l = norm(sub(case.point, position));
            let c = dot(norm(axis), l).clamp(-1.0, 1.0);
            (l, Some((c.acos().to_degrees() - angle, c)))
        }
    };
    let cos_theta = -dot(n, l);
    let cos_phi = case.viewer.map(|e| {
        let v = norm(sub(case.point, e));
        let r = sub(l, mul(n, 2.0 * dot(n, l)));
        -dot(r, v)
    });
    Some(Rough {
        cos_theta,
        cos_phi,
        cone,
    })
}

/// Whether every quantity that decides a gate, or that a term is ill-conditioned in, is clear of
/// its critical value: |cos θ|, |cos φ| ≥ 0.05, ψ at least 0.5° from γ, cos ψ ≥ 0.05 inside.
fn well_conditioned(case: &Case) -> bool {
    case.lights.iter().all(|l| match rough(case, l) {
        None => true,
        Some(r) => {
            r.cos_theta.abs() >= 0.05
                && r.cos_phi.is_none_or(|c| c.abs() >= 0.05)
                && r.cone
                    .is_none_or(|(dpsi, c)| dpsi.abs() >= 0.5 && (dpsi > 0.0 || c >= 0.05))
        }
    })
}

/// A random light around P: a point, directional or spot light, usually in front of the surface.
fn random_light(g: &mut Draw, p: [f64; 3], n_unit: [f64; 3]) -> LightIn {
    // u: from P towards the light; in front of the surface three times in four.
    let mut u = g.dir();
    if dot(u, n_unit) < 0.0 && g.chance(0.75) {
        u = mul(u, -1.0);
    }
    let dist = g.range(0.5, 20.0);
    let position = add(p, mul(u, dist));
    let position = position.map(|x| {
        if g.chance(0.5) {
            (x * 100.0).round() / 100.0
        } else {
            x
        }
    });
    let falloff = g.pick(&[0u8, 1, 2]);
    let color = g.color(if falloff == 0 {
        1.0
    } else {
        dist.powi(falloff as i32)
    });
    match g.below(20) {
        0..=7 => LightIn::Point {
            position,
            color,
            falloff,
        },
        8..=12 => LightIn::Directional {
            direction: mul(u, -g.range(0.5, 2.0)),
            color: g.color(1.0),
        },
        _ => {
            let angle = if g.chance(0.5) {
                g.range(5.0, 85.0)
            } else {
                g.pick(&[10.0, 25.0, 30.0, 45.0, 60.0, 75.0, 90.0])
            };
            // The axis: from the apex towards P, turned by up to γ + 15°.
            let turn = g.range(0.0, angle + 15.0).to_radians();
            let (a, b) = {
                let t = norm(cross(u, g.dir()));
                (mul(u, -turn.cos()), mul(t, turn.sin()))
            };
            LightIn::Spot {
                position,
                axis: mul(add(a, b), g.range(0.5, 2.0)),
                angle,
                exponent: g.pick(&[0.0, 1.0, 2.0, 0.5, 5.0, 10.0, 3.7]),
                color,
                falloff,
            }
        }
    }
}

/// An ordinary problem: P in [−5, 5]³, a normal of any length, a viewer (nine times in ten),
/// up to two ambient lights and one to four other lights.
fn ordinary(g: &mut Draw, group: &'static str, name: String) -> Case {
    let p = g.point(5.0);
    let n_unit = g.dir();
    let normal = if g.chance(0.3) {
        n_unit
    } else {
        mul(n_unit, g.range(0.3, 3.0))
    };
    let viewer = g.chance(0.9).then(|| {
        let mut u = g.dir();
        if dot(u, n_unit) < 0.0 && g.chance(0.8) {
            u = mul(u, -1.0);
        }
        add(p, mul(u, g.range(1.0, 30.0)))
    });
    let mut lights = Vec::new();
    for _ in 0..g.below(3) {
        lights.push(LightIn::Ambient {
            color: g.color(0.5),
        });
    }
    for _ in 0..1 + g.below(4) {
        lights.push(random_light(g, p, n_unit));
    }
    let shininess = if g.chance(0.5) {
        g.pick(&[0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0])
    } else {
        g.range(0.0, 100.0)
    };
    Case {
        group,
        name,
        point: p,
        normal,
        viewer,
        lights,
        material: g.material(shininess),
    }
}

fn ordinary_filtered(g: &mut Draw, group: &'static str, name: String) -> Case {
    loop {
        let c = ordinary(g, group, name.clone());
        if well_conditioned(&c) {
            return c;
        }
    }
}

/// The suite's groups, in the report's order.
pub const GROUPS: &[(&str, &str)] = &[
    (
        "ordinary",
        "ordinary problems, every cos θ, cos φ ≥ 0.05 from 0, ψ ≥ 0.5° from γ",
    ),
    ("random", "random problems, unfiltered (any conditioning)"),
    ("grazing", "grazing light, cos θ = ±1e-12"),
    ("tangent", "light exactly in the tangent plane (cos θ = 0)"),
    ("ns0.5", "n_s = 0.5"),
    (
        "ns1e6",
        "n_s = 1e6, viewer within 2e-3 rad of the mirror direction",
    ),
    ("ns1e300", "n_s = 1e300 (f64 only: beyond f32)"),
    (
        "cosphi1",
        "cos φ just below 1 (1 − 5e-11 … 1 − 5e-17), n_s 1 to 1e4",
    ),
    ("d1e-9", "d = 1e-9"),
    ("d1e9", "d = 1e9"),
    ("f2d1e-160", "falloff 2, d = 1e-160"),
    ("f2d1e160", "falloff 2, d = 1e160"),
    ("offset1e12", "coordinates offset by 1e12"),
    ("offset1e6", "coordinates offset by 1e6"),
    ("edge0", "spot, γ = 0°: on the axis, 1e-12 rad off"),
    (
        "edge30",
        "spot, γ = 30°: on the edge, 1e-12 rad inside and outside",
    ),
    (
        "edge45",
        "spot, γ = 45°: on the edge, 1e-12 rad inside and outside",
    ),
    (
        "edge60",
        "spot, γ = 60°: on the edge, 1e-12 rad inside and outside",
    ),
    (
        "edge90",
        "spot, γ = 90°: on the edge, 1e-12 rad inside and outside",
    ),
    ("normal1e-300", "normal of length 1e-300"),
    ("normal1e-6", "normal of length 1e-6"),
    ("normal1e6", "normal of length 1e6"),
    ("normal1e300", "normal of length 1e300"),
];

/// How many ordinary (filtered) and random (unfiltered) problems the suite holds.
pub const ORDINARY: usize = 2000;
pub const RANDOM: usize = 500;

/// The whole suite, deterministic: the same cases, in the same order, on every machine.
pub fn suite() -> Vec<Case> {
    let mut cases = Vec::new();
    let mut g = Draw::new(0x5EED_0005);
    for i in 0..ORDINARY {
        cases.push(ordinary_filtered(
            &mut g,
            "ordinary",
            format!("ordinary #{i}"),
        ));
    }
    for i in 0..RANDOM {
        cases.push(ordinary(&mut g, "random", format!("random #{i}")));
    }
    extremes(&mut g, &mut cases);
    cases
}

impl Case {
    /// A problem with one light and no ambient light.
    fn single(
        group: &'static str,
        name: String,
        point: [f64; 3],
        normal: [f64; 3],
        viewer: Option<[f64; 3]>,
        light: LightIn,
        material: MaterialIn,
    ) -> Case {
        Case {
            group,
            name,
            point,
            normal,
            viewer,
            lights: vec![light],
            material,
        }
    }
}

/// A light of `kind` whose light travels along `travel` (unit) to P from `dist` away: a point
/// light, a directional light, or a spot aimed straight at P (γ = 60°).
fn light_towards(kind: usize, p: [f64; 3], travel: [f64; 3], dist: f64, falloff: u8) -> LightIn {
    let position = sub(p, mul(travel, dist));
    let color = [0.9, 0.7, 0.5];
    match kind {
        0 => LightIn::Point {
            position,
            color,
            falloff,
        },
        1 => LightIn::Directional {
            direction: travel,
            color,
        },
        _ => LightIn::Spot {
            position,
            axis: travel,
            angle: 60.0,
            exponent: 1.0,
            color,
            falloff,
        },
    }
}

const KIND: [&str; 3] = ["point", "directional", "spot"];

fn extremes(g: &mut Draw, cases: &mut Vec<Case>) {
    // Grazing light: travel D = T − c·N̂, so cos θ = −N̂·D̂ = c (to the rounding of the inputs;
    // the reference takes the inputs exactly as they are). O_s = 0: the diffuse term alone.
    for (sign, c) in [("+", 1e-12), ("−", -1e-12)] {
        for (kind, kind_name) in KIND.iter().enumerate() {
            for f in 0..4 {
                let (n, t, b) = g.frame();
                let p = g.point(5.0);
                let travel = sub(t, mul(n, c));
                let light = light_towards(kind, p, travel, g.range(1.0, 10.0), 0);
                let viewer = Some(add(p, mul(add(n, mul(b, 0.5)), 5.0)));
                let mut m = g.material(10.0);
                m.specular = [0.0; 3];
                let normal = mul(n, g.range(0.5, 2.0));
                let name = format!(
                    "grazing cos θ = {sign}1e-12, {} light, frame {f}",
                    kind_name
                );
                cases.push(Case::single("grazing", name, p, normal, viewer, light, m));
            }
        }
    }

    // Exactly in the tangent plane: integer N and T = N × w (integers), P and P_l integers, so
    // N·(P − P_l) = 0 exactly in every precision.
    for f in 0..8 {
        let int = |g: &mut Draw| [0, 1, 2].map(|_| g.range(-5.0, 5.0).round());
        let n = loop {
            let n = int(g);
            if dot(n, n) > 0.0 {
                break n;
            }
        };
        let t = loop {
            let t = cross(n, int(g));
            if dot(t, t) > 0.0 {
                break t;
            }
        };
        let p = int(g);
        for (kind, kind_name) in KIND.iter().enumerate() {
            let position = add(p, mul(t, -2.0));
            let color = [0.9, 0.7, 0.5];
            let light = match kind {
                0 => LightIn::Point {
                    position,
                    color,
                    falloff: 1,
                },
                1 => LightIn::Directional {
                    direction: t,
                    color,
                },
                _ => LightIn::Spot {
                    position,
                    axis: t,
                    angle: 30.0,
                    exponent: 1.0,
                    color,
                    falloff: 1,
                },
            };
            let viewer = Some(add(p, add(mul(n, 3.0), t)));
            let name = format!("tangent plane, {} light, frame {f}", kind_name);
            let m = g.material(10.0);
            cases.push(Case::single("tangent", name, p, n, viewer, light, m));
        }
    }

    // Shininess 0.5 on ordinary problems.
    for i in 0..24 {
        let mut c = ordinary_filtered(g, "ns0.5", format!("n_s = 0.5 #{i}"));
        c.material.shininess = 0.5;
        cases.push(c);
    }

    // Near the mirror direction: cos φ = 1 − α²/2, V = −R turned by α.
    let mirror = |g: &mut Draw, alpha: f64| {
        let (n, t, b) = g.frame();
        let p = g.point(5.0);
        let theta = g.range(0.2, 1.2);
        // The light travels along D = −cos θ·N + sin θ·T; R = D − 2(N·D)N = cos θ·N + sin θ·T.
        let d = add(mul(n, -theta.cos()), mul(t, theta.sin()));
        let r = add(mul(n, theta.cos()), mul(t, theta.sin()));
        // V, from the eye to P, is −R turned by α towards B.
        let v = add(mul(r, -alpha.cos()), mul(b, alpha.sin()));
        let e = sub(p, mul(v, g.range(2.0, 20.0)));
        (n, p, d, e)
    };
    for (group, ns, alphas) in [
        ("ns1e6", 1e6, &[0.0, 1e-4, 1e-3, 2e-3][..]),
        ("ns1e300", 1e300, &[0.0, 1e-8, 1e-3][..]),
    ] {
        for &alpha in alphas {
            for (kind, kind_name) in KIND.iter().enumerate() {
                for f in 0..2 {
                    let (n, p, d, e) = mirror(g, alpha);
                    let light = light_towards(kind, p, d, g.range(1.0, 10.0), 2);
                    let name = format!(
                        "n_s = {ns:e}, α = {alpha:e}, {} light, frame {f}",
                        kind_name
                    );
                    let m = g.material(ns);
                    cases.push(Case::single(group, name, p, n, Some(e), light, m));
                }
            }
        }
        // The mirror direction exactly, in small integers: cos φ = 1 with no rounding at all.
        // N = (0,0,1), P = 0, the light at (3,0,4), the viewer at (−3,0,4).
        let light = LightIn::Point {
            position: [3.0, 0.0, 4.0],
            color: [0.9, 0.7, 0.5],
            falloff: 0,
        };
        let name = format!("n_s = {ns:e}, exact mirror");
        let (p, n, e) = ([0.0; 3], [0.0, 0.0, 1.0], [-3.0, 0.0, 4.0]);
        let m = g.material(ns);
        cases.push(Case::single(group, name, p, n, Some(e), light, m));
    }

    // cos φ just below 1.
    for alpha in [1e-5, 1e-7, 1e-8] {
        for ns in [1.0, 100.0, 1e4] {
            for (kind, kind_name) in KIND.iter().enumerate() {
                let (n, p, d, e) = mirror(g, alpha);
                let light = light_towards(kind, p, d, g.range(1.0, 10.0), 1);
                let name = format!(
                    "cos φ = 1 − {:.0e}, n_s = {ns}, {} light",
                    alpha * alpha / 2.0,
                    kind_name
                );
                let m = g.material(ns);
                cases.push(Case::single("cosphi1", name, p, n, Some(e), light, m));
            }
        }
    }

    // Very near and very far lights: d = 1e-9 and 1e9, P at the origin and at unit scale. C_l is
    // scaled by d^f so that I_l is of order 1.
    for (group, dist) in [("d1e-9", 1e-9), ("d1e9", 1e9)] {
        for at_origin in [true, false] {
            for kind in [0, 2] {
                for falloff in 0..3u8 {
                    let (n, t, _) = g.frame();
                    let p = if at_origin { [0.0; 3] } else { g.point(5.0) };
                    let travel = norm(sub(t, mul(n, g.range(0.3, 3.0))));
                    let mut light = light_towards(kind, p, travel, dist, falloff);
                    if let LightIn::Point { color, .. } | LightIn::Spot { color, .. } = &mut light {
                        *color = mul(*color, dist.powi(falloff as i32));
                    }
                    let viewer = Some(add(p, mul(add(n, t), 3.0)));
                    let at = if at_origin {
                        "at the origin"
                    } else {
                        "at unit scale"
                    };
                    let name = format!(
                        "d = {dist:e}, falloff {falloff}, {} light, P {at}",
                        KIND[kind]
                    );
                    let m = g.material(8.0);
                    cases.push(Case::single(group, name, p, n, viewer, light, m));
                }
            }
        }
    }

    // Falloff 2 at d = 1e-160 (C_l ∝ 1e-300, 1e-200, 1: I_l ~ 1e20, 1e120, 1e320) and at
    // d = 1e160 (C_l ∝ 1e300, 1: I_l ~ 1e-20, 1e-320). P at the origin, or at d's scale.
    for (group, dist, colors) in [
        ("f2d1e-160", 1e-160f64, &[1e-300, 1e-200, 1.0][..]),
        ("f2d1e160", 1e160, &[1e300, 1.0][..]),
    ] {
        for &c in colors {
            for kind in [0, 2] {
                for f in 0..2 {
                    let (n, t, _) = g.frame();
                    let scale = dist.min(1.0);
                    let p = if f == 0 {
                        [0.0; 3]
                    } else {
                        mul(g.point(1.0), scale)
                    };
                    let travel = norm(sub(t, mul(n, g.range(0.3, 3.0))));
                    let mut light = light_towards(kind, p, travel, dist, 2);
                    if let LightIn::Point { color, .. } | LightIn::Spot { color, .. } = &mut light {
                        *color = mul(*color, c);
                    }
                    let viewer = Some(add(p, mul(add(n, t), 3.0 * scale)));
                    let name = format!(
                        "falloff 2, d = {dist:e}, C_l ∝ {c:e}, {} light, #{f}",
                        KIND[kind]
                    );
                    let m = g.material(8.0);
                    cases.push(Case::single(group, name, p, n, viewer, light, m));
                }
            }
        }
    }

    // Far from the origin: ordinary problems moved by ~1e12 and ~1e6.
    for (group, s) in [("offset1e12", 1e12), ("offset1e6", 1e6)] {
        for i in 0..24 {
            let c = ordinary_filtered(g, group, String::new());
            let offset = [s, -0.7 * s, 0.3 * s];
            cases.push(c.translated(offset, group, format!("offset {s:e} #{i}")));
        }
    }

    // The spot's edge: P = A + 4(cos ψ·â + sin ψ·t̂) with ψ = γ (on the edge) or γ ∓ 1e-12 rad.
    // Frame 0 is axis-aligned in integers (apex (0,0,4), â = (0,0,−1), t̂ = (1,0,0)), on the edge
    // exactly for γ = 0°, 45° and 90°; frames 1–3 are random. e = 0 for γ = 90°, where cos ψ = 0
    // on the edge would hide the decision; e = 1 otherwise.
    for (group, gamma) in [
        ("edge0", 0.0f64),
        ("edge30", 30.0),
        ("edge45", 45.0),
        ("edge60", 60.0),
        ("edge90", 90.0),
    ] {
        let sides = [
            ("on the edge", 0.0),
            ("1e-12 inside", -1e-12),
            ("1e-12 outside", 1e-12),
        ];
        for (side, delta) in sides {
            if gamma == 0.0 && delta < 0.0 {
                continue;
            }
            for f in 0..4 {
                let (a_hat, t_hat, apex) = if f == 0 {
                    ([0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 4.0])
                } else {
                    let (n, t, _) = g.frame();
                    (n, t, g.point(5.0))
                };
                let psi = gamma.to_radians() + delta;
                let offset = match (f, delta == 0.0, gamma) {
                    (0, true, 0.0) => [0.0, 0.0, -4.0],
                    (0, true, 45.0) => [4.0, 0.0, -4.0],
                    (0, true, 90.0) => [4.0, 0.0, 0.0],
                    _ => add(mul(a_hat, 4.0 * psi.cos()), mul(t_hat, 4.0 * psi.sin())),
                };
                let p = add(apex, offset);
                // The normal faces the apex (tilted in the random frames), the viewer in front.
                let to_apex = norm(sub(apex, p));
                let normal = if f == 0 {
                    to_apex.map(|x| (x * 8.0).round() / 8.0)
                } else {
                    norm(add(to_apex, mul(g.dir(), 0.2)))
                };
                let viewer = Some(add(p, mul(add(normal, mul(t_hat, 0.3)), 5.0)));
                let light = LightIn::Spot {
                    position: apex,
                    axis: mul(a_hat, 2.0),
                    angle: gamma,
                    exponent: if gamma == 90.0 { 0.0 } else { 1.0 },
                    color: [0.9, 0.7, 0.5],
                    falloff: 0,
                };
                let name = format!("γ = {gamma}°, {side}, frame {f}");
                let m = g.material(10.0);
                cases.push(Case::single(group, name, p, normal, viewer, light, m));
            }
        }
    }

    // Normals of extreme length on ordinary problems.
    for (group, len) in [
        ("normal1e-300", 1e-300),
        ("normal1e-6", 1e-6),
        ("normal1e6", 1e6),
        ("normal1e300", 1e300),
    ] {
        for i in 0..16 {
            let mut c = ordinary_filtered(g, group, format!("‖N‖ = {len:e} #{i}"));
            c.normal = mul(norm(c.normal), len);
            cases.push(c);
        }
    }
}
