//! Transmission (Section 4.4, "idem para a transmissão ou refração"; docs/conventions.md,
//! "Transmission") against closed forms worked by hand: a slab of glass seen head-on, a ray
//! through a sphere's centre, Snell's law at 45°, total internal reflection on either side of
//! the critical angle, the level and weight rules, the bound on a tree's size, and the tree of
//! an explained pixel of the bundled glass scene. The tracer is called through the library, so
//! each ray of the tree is read from its record.

use crate::support;

use std::path::Path;

use phong::core::{Vector, V3};
use phong::problem::{self, Problem};
use phong::tracer::{Counts, RayKind, RayRecord, Scene, Stop, Tracer};
use serde_json::{json, Value};

/// A scene from its JSON, in f64.
fn problem(scene: &Value) -> Problem<f64> {
    let file = problem::parse_str(Path::new("glass.json"), &scene.to_string()).expect("parses");
    problem::validate::validate::<f64>(&file).expect("a valid scene")
}

/// The tree of the ray from `origin` along `direction` (unit), and its colour.
fn trace(
    p: &Problem<f64>,
    origin: [f64; 3],
    direction: [f64; 3],
) -> (V3<f64>, Vec<RayRecord<f64>>, Counts) {
    let scene = Scene::new(p);
    let tracer = Tracer {
        scene: &scene,
        problem: p,
    };
    let mut records = Vec::new();
    let mut counts = Counts::default();
    let ray = phong::geometry::Ray {
        origin: phong::core::real::v3::<f64>(origin),
        direction: phong::core::real::v3::<f64>(direction),
    };
    let c = tracer.trace(ray, &mut counts, &mut records);
    (c, records, counts)
}

/// A scene of one surface made of `material`, lit by a white ambient light only (so every local
/// colour is O_a·I_a = O_a), on a background `background`.
fn scene(surface: Value, material: Value, background: [f64; 3], render: Value) -> Value {
    let mut surface = surface;
    surface["material"] = material;
    json!({
        "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
        "surfaces": [surface],
        "camera": { "eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "width": 8, "height": 8 },
        "background": background,
        "render": render,
    })
}

fn close(a: V3<f64>, b: [f64; 3], tol: f64) -> bool {
    a.to_array()
        .iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn a_slab_seen_head_on_adds_o_t_times_the_background_and_does_not_bend_the_ray() {
    // The plane z = 0, glass behind it; the ray comes down the normal. Entering head-on,
    // cos θ_i = 1, k = 1 − η_r²·0 = 1, T = η_r V + (η_r − 1) N = −N: undeviated. It then never
    // meets anything and sees the background. By hand:
    // C = O_a I_a + O_t B = (0.2, 0.1, 0.05) + (0.5·0.3, 0.6·0.4, 0.7·0.5) = (0.35, 0.34, 0.40).
    let p = problem(&scene(
        json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] }),
        json!({ "ambient": [0.2, 0.1, 0.05], "transmissivity": [0.5, 0.6, 0.7], "ior": 1.5 }),
        [0.3, 0.4, 0.5],
        json!({ "max_level": 5, "min_weight": 0 }),
    ));
    let (c, rays, counts) = trace(&p, [0.0, 0.0, 5.0], [0.0, 0.0, -1.0]);
    assert!(close(c, [0.35, 0.34, 0.40], 1e-15), "{c:?}");
    assert_eq!(rays.len(), 2);
    assert_eq!(rays[1].kind, RayKind::Transmission);
    assert_eq!(rays[1].parent, Some(0));
    assert_eq!(rays[1].level, 2);
    assert_eq!(rays[1].weight, 0.7, "w_t = 1·max(O_t)");
    assert!(close(rays[1].ray.direction, [0.0, 0.0, -1.0], 1e-15));
    assert_eq!(rays[1].stop, Some(Stop::Miss));
    let t = rays[0].transmission.expect("a transmission");
    assert!(t.refraction.entering);
    assert_eq!((t.refraction.eta_i, t.refraction.eta_t), (1.0, 1.5));
    assert_eq!(t.stop, None);
    assert_eq!(rays[0].stop, Some(Stop::NotReflective));
    assert_eq!(
        (counts.primary, counts.reflection, counts.transmission),
        (1, 0, 1)
    );
}

#[test]
fn a_ray_through_a_sphere_s_centre_passes_undeviated_and_is_shaded_at_both_walls() {
    // Sphere of radius 1 at the origin, O_a = 0.1, O_t = 0.9, η = 1.5; background 0.2. The ray
    // along −z through the centre enters at (0, 0, 1) and leaves at (0, 0, −1), both head-on:
    // C = 0.1 + 0.9·(0.1 + 0.9·0.2) = 0.1 + 0.9·0.28 = 0.352 in each channel.
    let p = problem(&scene(
        json!({ "type": "sphere", "center": [0, 0, 0], "radius": 1 }),
        json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.9, 0.9, 0.9], "ior": 1.5 }),
        [0.2, 0.2, 0.2],
        json!({ "max_level": 5, "min_weight": 0 }),
    ));
    let (c, rays, _) = trace(&p, [0.0, 0.0, 5.0], [0.0, 0.0, -1.0]);
    assert!(close(c, [0.352; 3], 1e-15), "{c:?}");
    let kinds: Vec<RayKind> = rays.iter().map(|r| r.kind).collect();
    assert_eq!(
        kinds,
        [
            RayKind::Primary,
            RayKind::Transmission,
            RayKind::Transmission
        ]
    );
    let hit = |i: usize| rays[i].hit.expect("a hit").hit.p;
    assert!(close(hit(0), [0.0, 0.0, 1.0], 1e-15));
    assert!(close(hit(1), [0.0, 0.0, -1.0], 1e-15));
    for r in &rays[1..] {
        assert!(close(r.ray.direction, [0.0, 0.0, -1.0], 1e-15), "{r:?}");
    }
    // In at the near wall (1 → 1.5), out at the far one (1.5 → 1).
    let (a, b) = (
        rays[0].transmission.expect("in").refraction,
        rays[1].transmission.expect("out").refraction,
    );
    assert!(a.entering && !b.entering);
    assert_eq!((a.eta_i, a.eta_t, b.eta_i, b.eta_t), (1.0, 1.5, 1.5, 1.0));
    assert_eq!(rays[2].parent, Some(1));
    assert_eq!(rays[2].stop, Some(Stop::Miss));
}

#[test]
fn snell_s_law_at_45_degrees_into_glass() {
    // D = (sin 45°, 0, −cos 45°) onto z = 0 from above, η = 1.5: sin θ_t = sin 45°/1.5 =
    // 0.4714045…, cos θ_t = √(1 − sin²θ_t) = √(1 − 1/4.5) = 0.8819171…; T = (sin θ_t, 0,
    // −cos θ_t); cos θ_i = cos 45°; k = 1 − (1/1.5)²·(1/2) = 1 − 2/9 = 7/9.
    let p = problem(&scene(
        json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] }),
        json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [1, 1, 1], "ior": 1.5 }),
        [0.0; 3],
        json!({ "max_level": 2, "min_weight": 0 }),
    ));
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let (_, rays, _) = trace(&p, [-1.0, 0.0, 1.0], [s, 0.0, -s]);
    let sin_t = s / 1.5;
    let cos_t = (1.0 - 1.0 / 4.5f64).sqrt();
    assert!((sin_t - 0.471_404_520_791_031_7).abs() < 1e-15);
    let f = rays[0].transmission.expect("a transmission").refraction;
    assert!((f.cos_i - s).abs() < 1e-15);
    assert!((f.k - 7.0 / 9.0).abs() < 1e-15, "{}", f.k);
    assert!(close(rays[1].ray.direction, [sin_t, 0.0, -cos_t], 1e-15));
    // Level 2 is the maximum: the transmission ray is traced, its own child is not.
    assert_eq!(rays.len(), 2);
}

/// A ray inside glass (η = 1.5, below the plane z = 0) meeting the surface at `degrees` from
/// its normal: its tree.
fn from_inside(degrees: f64, reflectivity: Option<f64>) -> (Vec<RayRecord<f64>>, Counts) {
    let mut material =
        json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.8, 0.8, 0.8], "ior": 1.5 });
    if let Some(r) = reflectivity {
        material["reflectivity"] = json!([r, r, r]);
    }
    let p = problem(&scene(
        json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] }),
        material,
        [0.0; 3],
        json!({ "max_level": 2, "min_weight": 0 }),
    ));
    let a = degrees.to_radians();
    let (_, rays, counts) = trace(&p, [0.0, 0.0, -1.0], [a.sin(), 0.0, a.cos()]);
    (rays, counts)
}

#[test]
fn total_internal_reflection_begins_at_the_critical_angle() {
    // θ_c = asin(1/1.5) = 41.8103149°. At 41°: k = 1 − 1.5²·sin²41° = 1 − 2.25·0.4304134 =
    // 0.0315698 > 0, and T = (1.5 sin 41°, 0, √k) = (0.9840810, 0, 0.1776788). At 42.5°:
    // k = 1 − 2.25·sin²42.5° = 1 − 2.25·0.4564221 = −0.0269497 < 0: no transmission ray.
    let critical = (1.0f64 / 1.5).asin().to_degrees();
    assert!((critical - 41.810_314_9).abs() < 1e-6);
    let (rays, counts) = from_inside(41.0, None);
    let f = rays[0].transmission.expect("a transmission").refraction;
    assert!(!f.entering, "from the back side: leaving the glass");
    assert_eq!((f.eta_i, f.eta_t), (1.5, 1.0));
    let s41 = 41f64.to_radians().sin();
    let k = 1.0 - 2.25 * s41 * s41;
    assert!(
        (k - 0.031_569_8).abs() < 1e-6 && (f.k - k).abs() < 1e-14,
        "{}",
        f.k
    );
    assert!(close(
        rays[1].ray.direction,
        [1.5 * s41, 0.0, k.sqrt()],
        1e-12
    ));
    assert_eq!(counts.transmission, 1);

    let (rays, counts) = from_inside(42.5, None);
    let t = rays[0].transmission.expect("a transmission record");
    assert_eq!(t.stop, Some(Stop::TotalInternalReflection));
    assert!(t.refraction.direction.is_none());
    let s = 42.5f64.to_radians().sin();
    assert!((t.refraction.k - (1.0 - 2.25 * s * s)).abs() < 1e-14);
    assert!(t.refraction.k < 0.0);
    assert_eq!((rays.len(), counts.transmission), (1, 0));

    // With O_r the reflection ray is traced as ever, and nothing is added in the transmission
    // ray's place (the energy O_t·C_t is lost).
    let (rays, counts) = from_inside(42.5, Some(0.3));
    assert_eq!((counts.reflection, counts.transmission), (1, 0));
    assert_eq!(rays[1].kind, RayKind::Reflection);
    assert!((rays[1].weight - 0.3).abs() < 1e-15);
}

#[test]
fn the_level_and_weight_rules_stop_transmission_rays_as_they_stop_reflection_rays() {
    let run = |render: Value| {
        let p = problem(&scene(
            json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] }),
            json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.9, 0.6, 0.3], "ior": 1.5 }),
            [1.0, 1.0, 1.0],
            render,
        ));
        trace(&p, [0.0, 0.0, 5.0], [0.0, 0.0, -1.0])
    };
    // Maximum level 1: primary rays only. C = local = 0.1.
    let (c, rays, _) = run(json!({ "max_level": 1 }));
    assert_eq!(rays[0].transmission.expect("t").stop, Some(Stop::MaxLevel));
    assert!(close(c, [0.1; 3], 0.0));
    // w_t = max(O_t) = 0.9, not above a minimum weight of 0.9; above 0.89.
    let (_, rays, _) = run(json!({ "max_level": 5, "min_weight": 0.9 }));
    assert_eq!(rays[0].transmission.expect("t").stop, Some(Stop::MinWeight));
    let (c, rays, _) = run(json!({ "max_level": 5, "min_weight": 0.89 }));
    assert_eq!(rays.len(), 2);
    // C = 0.1 + O_t·1.
    assert!(close(c, [1.0, 0.7, 0.4], 1e-15), "{c:?}");
}

#[test]
fn a_tree_that_could_exceed_two_to_the_twenty_rays_is_refused_before_tracing() {
    // O_r = O_t = 1: each hit spawns two rays of weight 1, so a tree of maximum level L may hold
    // 2^L − 1 rays: 2^20 − 1 at level 20 is allowed, 2^21 − 1 at 21 is not; a minimum weight
    // that stops the rays early (O = 0.5: weight 0.5^(d−1) > 0.001 only for d ≤ 10) allows it.
    let with = |o: f64, level: u32, min_weight: f64| {
        let s = scene(
            json!({ "type": "sphere", "center": [0, 0, 0], "radius": 1 }),
            json!({ "ambient": [0.1, 0.1, 0.1], "reflectivity": [o, o, o],
                    "transmissivity": [o, o, o], "ior": 1.5 }),
            [0.0; 3],
            json!({ "max_level": level, "min_weight": min_weight }),
        );
        let file = problem::parse_str(Path::new("tree.json"), &s.to_string()).expect("parses");
        problem::validate::validate::<f64>(&file)
    };
    assert!(with(1.0, 20, 0.0).is_ok());
    let e = with(1.0, 21, 0.0).expect_err("refused");
    let text = format!("{e:?}");
    assert!(text.contains("render.max_level"), "{text}");
    assert!(text.contains("2097151"), "{text}");
    assert!(with(0.5, 40, 0.001).is_ok());
}

#[test]
fn an_explained_pixel_that_could_hold_more_than_two_to_the_thirteen_rays_is_refused() {
    // The bound is on what the settings let the samples' trees hold, so the camera looks away
    // from the sphere: each sample's primary ray misses, and an explanation let through is
    // cheap. O_r = O_t = 1, minimum weight 0: a tree of maximum level L may hold
    // 1 + 2 + … + 2^(L−1) = 2^L − 1 rays, so one sample at level 13 holds 8191 ≤ 2^13 = 8192,
    // one at level 14 16383, and two at level 13 16382 (one sample would fit). A mirror alone
    // (O_r = 1, no O_t) makes a chain of at most L rays: 2048 samples at level 4 are 8192
    // rays, 2049 are 8196 (2048 would fit). With O_r = 0.5 and minimum weight 0.1 the chain's
    // weights are 1, 0.5, 0.25, 0.125, then 0.0625 ≤ 0.1: 4 rays whatever the level. A matte
    // sphere spawns nothing: one ray a sample, so 4096 samples at level 1000 are 4096 rays.
    let glass = json!({ "ambient": [0.1, 0.1, 0.1], "reflectivity": [1, 1, 1],
                        "transmissivity": [1, 1, 1], "ior": 1.5 });
    let mirror = json!({ "ambient": [0.1, 0.1, 0.1], "reflectivity": [1, 1, 1] });
    let half = json!({ "ambient": [0.1, 0.1, 0.1], "reflectivity": [0.5, 0.5, 0.5] });
    let matte = json!({ "ambient": [0.1, 0.1, 0.1] });
    let explain = |material: &Value, level: u32, min_weight: f64, samples: u32| {
        let mut s = scene(
            json!({ "type": "sphere", "center": [0, 0, 0], "radius": 1 }),
            material.clone(),
            [0.0; 3],
            json!({ "max_level": level, "min_weight": min_weight, "samples": samples }),
        );
        s["camera"] = json!({ "eye": [0, 0, 5], "look_at": [0, 0, 10], "fov": 40,
                              "width": 1, "height": 1 });
        let p = problem(&s);
        let camera = p.camera.expect("a camera");
        let scene = Scene::new(&p);
        phong::tracer::explain_pixel(&p, &camera, &scene, 0, 0)
            .map(|e| e.samples.len())
            .map_err(|e| format!("{}: {} Fix: {}", e.field, e.message(), e.fix()))
    };
    assert_eq!(explain(&glass, 13, 0.0, 1), Ok(1));
    let e = explain(&glass, 14, 0.0, 1).expect_err("refused");
    assert!(
        e.contains("16383 rays") && e.contains("8192 (2^13)") && e.contains("--max-level"),
        "{e}"
    );
    let e = explain(&glass, 13, 0.0, 2).expect_err("refused");
    assert!(
        e.contains("16382 rays") && e.contains("at most 1 samples per pixel"),
        "{e}"
    );
    assert_eq!(explain(&mirror, 4, 0.0, 2048), Ok(2048));
    let e = explain(&mirror, 4, 0.0, 2049).expect_err("refused");
    assert!(
        e.contains("2049 samples of up to 4 rays each")
            && e.contains("8196 rays")
            && e.contains("at most 2048 samples per pixel (--samples)"),
        "{e}"
    );
    assert_eq!(explain(&half, 1000, 0.1, 2048), Ok(2048));
    let e = explain(&half, 1000, 0.1, 2049).expect_err("refused");
    assert!(e.contains("2049 samples of up to 4 rays each"), "{e}");
    assert_eq!(explain(&matte, 1000, 0.0, 4096), Ok(4096));
}

#[test]
fn an_explained_pixel_through_the_glass_sphere_shows_its_tree() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/glass.json");
    let out = support::phong()
        .args([
            "render",
            scene,
            "--explain-pixel",
            "440,340",
            "--format",
            "json",
        ])
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let rays = doc["samples"][0]["rays"].as_array().expect("rays");
    let kinds: Vec<&str> = rays
        .iter()
        .map(|r| r["kind"].as_str().expect("kind"))
        .collect();
    assert_eq!(kinds[0], "primary");
    assert!(
        kinds.contains(&"transmission") && kinds.contains(&"reflection"),
        "{kinds:?}"
    );
    // Every ray but the first has a parent before it, one level up, and the weight its
    // parent's times max(O) of the parent's hit (O_r for a reflection, O_t for a transmission).
    let max = |v: &Value| {
        v.as_array()
            .expect("rgb")
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .fold(0.0, f64::max)
    };
    for (i, r) in rays.iter().enumerate().skip(1) {
        let p = r["parent"].as_u64().expect("a parent") as usize;
        assert!(p < i);
        let parent = &rays[p];
        assert_eq!(r["level"], parent["level"].as_u64().expect("level") + 1);
        let o = match r["kind"].as_str() {
            Some("reflection") => max(&parent["reflectivity"]),
            _ => max(&parent["transmission"]["transmissivity"]),
        };
        let w = parent["weight"].as_f64().expect("w") * o;
        assert!(
            (r["weight"].as_f64().expect("w") - w).abs() < 1e-15,
            "ray {i}"
        );
    }
    let counts = &doc["rays"];
    assert!(counts["transmission"].as_u64().expect("count") >= 2);
    // The text says the tree.
    let text = support::phong()
        .args([
            "render",
            scene,
            "--explain-pixel",
            "440,340",
            "--lang",
            "pt",
        ])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("de transmissão, do raio 1"), "{text}");
    assert!(
        text.contains("Lei de Snell: o raio entra no material"),
        "{text}"
    );
    assert!(text.contains("Cor da árvore de raios"), "{text}");
}

/// `phong render` on `scene` written to a temporary file: its exit code and standard error.
fn render_file(scene: &Value, extra: &[&str]) -> (i32, String) {
    let dir = tempfile::TempDir::new().expect("a temporary folder");
    let path = dir.path().join("bad-glass.json");
    std::fs::write(&path, scene.to_string()).expect("written");
    let out = support::phong()
        .arg("render")
        .arg(&path)
        .arg("-o")
        .arg(dir.path().join("x.ppm"))
        .args(extra)
        .output()
        .expect("runs");
    assert!(
        !dir.path().join("x.ppm").exists(),
        "no image is written on bad input"
    );
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_transmissivity_without_its_index_or_a_bad_index_is_refused_naming_the_field() {
    let with = |material: Value| {
        scene(
            json!({ "type": "sphere", "center": [0, 0, 0], "radius": 1 }),
            material,
            [0.0; 3],
            json!({ "max_level": 3 }),
        )
    };
    let (code, err) = render_file(
        &with(json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.5, 0.5, 0.5] })),
        &[],
    );
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("bad-glass.json")
            && err.contains("surfaces[0].material.ior")
            && err.contains("1.5"),
        "{err}"
    );
    let (code, err) = render_file(
        &with(json!({ "ambient": [0.1, 0.1, 0.1], "ior": 1.5 })),
        &[],
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("transmissivity"), "{err}");
    for bad in [json!(0), json!(-1.5)] {
        let (code, err) = render_file(
            &with(
                json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.5, 0.5, 0.5], "ior": bad }),
            ),
            &[],
        );
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("ior") && err.contains("not a positive number"),
            "{err}"
        );
    }
    // Positive but beyond 0.001 to 1000, where η_r² in Snell's law could overflow: refused
    // for a render and for an explained pixel alike, in both precisions.
    for (bad, extra) in [
        ("1e-300", &[][..]),
        ("1e200", &["--explain-pixel", "4,4"][..]),
        ("1e30", &["--precision", "f32"][..]),
    ] {
        let (code, err) = render_file(
            &with(
                json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.5, 0.5, 0.5],
                          "ior": bad.parse::<f64>().unwrap() }),
            ),
            extra,
        );
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("surfaces[0].material.ior")
                && err.contains(&format!("{bad} is outside 0.001 to 1000")),
            "{err}"
        );
    }
    let (code, err) = render_file(
        &with(
            json!({ "ambient": [0.1, 0.1, 0.1], "transmissivity": [0.5, -0.5, 0.5], "ior": 1.5 }),
        ),
        &[],
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("negative"), "{err}");
}

#[test]
fn a_command_line_level_that_lets_a_tree_grow_past_its_bound_is_refused() {
    // O_r = O_t = 0.9 and the default minimum weight 1/255: a ray of level d has weight
    // 0.9^(d−1), above 1/255 while d − 1 ≤ 52, so level 30 lets a tree hold 2^30 − 1 rays.
    let s = scene(
        json!({ "type": "sphere", "center": [0, 0, 0], "radius": 1 }),
        json!({ "ambient": [0.1, 0.1, 0.1], "reflectivity": [0.9, 0.9, 0.9],
                "transmissivity": [0.9, 0.9, 0.9], "ior": 1.5 }),
        [0.0; 3],
        json!({ "max_level": 5 }),
    );
    let (code, err) = render_file(&s, &["--max-level", "30"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--max-level") && err.contains("1073741823"),
        "{err}"
    );
}
