//! The tracer, end to end through the `phong` binary: pixels explained exactly as the solver
//! explains the equivalent ray problem; closed-form pixels worked out by hand (shadow, reflection
//! and the level and weight rules); the same image at every scale and with any thread count;
//! and bad scenes refused with exit code 2 and no image written.

use std::fs;
use std::path::{Path, PathBuf};

use crate::support::phong;
use serde_json::{json, Value};
use tempfile::TempDir;

const BAD_INPUT: i32 = 2;

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

fn write(dir: &TempDir, name: &str, v: &Value) -> PathBuf {
    let p = dir.path().join(name);
    fs::write(&p, serde_json::to_string_pretty(v).unwrap()).unwrap();
    p
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&fs::read_to_string(path).unwrap()).unwrap()
}

/// Runs `phong render SCENE ARGS… -o DIR/name.ppm` and returns the image's (width, height, rgb).
fn render_ppm(scene: &Path, dir: &TempDir, name: &str, args: &[&str]) -> (u32, u32, Vec<u8>) {
    let out = dir.path().join(name);
    phong()
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(&out)
        .args(args)
        .assert()
        .success();
    let bytes = fs::read(&out).unwrap();
    let img = phong::tracer::output::decode_ppm(&bytes).expect("a P6 image");
    (img.width, img.height, img.rgb)
}

fn explain_json(scene: &Path, x: u32, y: u32, args: &[&str]) -> Value {
    let out = phong()
        .arg("render")
        .arg(scene)
        .arg("--explain-pixel")
        .arg(format!("{x},{y}"))
        .args(["--format", "json"])
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn solve_json(problem: &Path) -> Value {
    let out = phong()
        .arg("solve")
        .arg(problem)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The scene turned into the ray problem of one ray: same lights, materials and surfaces, no
/// camera, the ray given, no viewer (V is the ray's direction, as for every ray of the tracer).
fn ray_problem(scene: &Value, origin: &Value, direction: &Value) -> Value {
    let mut p = scene.clone();
    let o = p.as_object_mut().unwrap();
    o.remove("camera");
    o.remove("background");
    o.remove("viewer");
    o.insert(
        "ray".into(),
        json!({ "origin": origin, "direction": direction }),
    );
    p
}

fn without_file(mut v: Value) -> Value {
    v.as_object_mut().unwrap().remove("file");
    v
}

// ---------------------------------------------------------------------------------------------
// Explained pixels are the solver's solutions
// ---------------------------------------------------------------------------------------------

#[test]
fn every_ray_of_an_explained_pixel_is_what_phong_solve_says_of_that_ray() {
    let dir = TempDir::new().unwrap();
    let scene_path = repo("scenes/classic.json");
    let scene = read_json(&scene_path);
    // (320, 300): the mirror sphere, whose reflection ray hits the floor, which reflects again.
    // (100, 250): the red sphere. (600, 20): the background.
    for (x, y) in [(320, 300), (100, 250), (500, 280), (600, 20)] {
        let e = explain_json(&scene_path, x, y, &[]);
        let rays = e["samples"][0]["rays"].as_array().unwrap();
        assert!(!rays.is_empty());
        for (k, ray) in rays.iter().enumerate() {
            let problem = ray_problem(&scene, &ray["origin"], &ray["direction"]);
            let path = write(&dir, &format!("ray-{x}-{y}-{k}.json"), &problem);
            let mut solved = solve_json(&path);
            if ray["hit"].as_bool().unwrap() {
                // A ray problem's ray is a primary ray, and `phong solve` shows the rays it
                // would spawn at level 2; the pixel's tree shows each ray's own children, so its
                // `solve` leaves them out (docs/conventions.md, "Secondary rays of a ray
                // problem").
                solved.as_object_mut().unwrap().remove("secondary_rays");
                assert_eq!(
                    without_file(ray["solve"].clone()),
                    without_file(solved),
                    "pixel ({x}, {y}), ray {k}"
                );
                // The tracer's own (unrecorded) local colour is the solver's colour.
                assert_eq!(
                    ray["local"], ray["solve"]["solution"]["color"]["unclamped"],
                    "pixel ({x}, {y}), ray {k}"
                );
            } else {
                assert!(solved["solution"].is_null(), "a miss has nothing to shade");
            }
        }
    }
}

#[test]
fn an_explained_pixel_has_the_colour_the_image_gives_it() {
    let dir = TempDir::new().unwrap();
    let scene = repo("scenes/classic.json");
    let (w, _, rgb) = render_ppm(&scene, &dir, "classic.ppm", &[]);
    for (x, y) in [
        (320, 300),
        (100, 250),
        (500, 280),
        (600, 20),
        (0, 479),
        (639, 0),
    ] {
        let e = explain_json(&scene, x, y, &[]);
        let i = 3 * (y as usize * w as usize + x as usize);
        let expected: Vec<Value> = rgb[i..i + 3].iter().map(|&c| json!(c)).collect();
        assert_eq!(e["rgb8"], Value::Array(expected), "pixel ({x}, {y})");
    }
}

// ---------------------------------------------------------------------------------------------
// Pixels worked out by hand
// ---------------------------------------------------------------------------------------------

/// A 1×1 image whose only ray, through the pixel's centre, goes from (3, 0, 5) to the origin,
/// where it meets the plane z = 0 (normal +z). A directional light shines straight down.
fn plane_scene(material: Value, extra_surfaces: Vec<Value>, background: [f64; 3]) -> Value {
    let mut surfaces = vec![json!({
        "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": material
    })];
    surfaces.extend(extra_surfaces);
    json!({
        "lights": [
            { "type": "ambient", "color": [1, 1, 1] },
            { "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] }
        ],
        "surfaces": surfaces,
        "camera": { "eye": [3, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 30,
                    "width": 1, "height": 1 },
        "background": background
    })
}

fn path_color(e: &Value) -> [f64; 3] {
    let c = e["samples"][0]["color"].as_array().unwrap();
    [0, 1, 2].map(|i| c[i].as_f64().unwrap())
}

fn assert_close(a: [f64; 3], b: [f64; 3]) {
    for i in 0..3 {
        assert!((a[i] - b[i]).abs() < 1e-12, "{a:?} ≠ {b:?}");
    }
}

#[test]
fn a_sphere_between_the_light_and_the_point_leaves_only_ambient_light() {
    let dir = TempDir::new().unwrap();
    let matte = json!({ "ambient": [0.2, 0.2, 0.2], "diffuse": [0.4, 0.4, 0.4],
                        "specular": [0, 0, 0], "shininess": 1 });
    // The sphere at (0, 0, 2), radius 0.5, is straight above the origin, in the light's way,
    // and 1.2 from the camera ray (at (1.2, 0, 2)), so the camera sees past it.
    let blocker =
        json!({ "type": "sphere", "center": [0, 0, 2], "radius": 0.5, "material": matte });
    let scene = write(
        &dir,
        "shadow.json",
        &plane_scene(matte.clone(), vec![blocker], [0.0; 3]),
    );
    // In shadow: O_a I_a = 0.2. Without shadow rays: 0.2 + 0.4·1·cos 0 = 0.6.
    let e = explain_json(&scene, 0, 0, &[]);
    assert_close(path_color(&e), [0.2; 3]);
    assert_eq!(
        e["samples"][0]["rays"][0]["solve"]["solution"]["lights"][0]["status"],
        "in_shadow"
    );
    assert_eq!(e["rgb8"], json!([51, 51, 51]));
    let e = explain_json(&scene, 0, 0, &["--shadows", "off"]);
    assert_close(path_color(&e), [0.6; 3]);
    assert_eq!(e["rgb8"], json!([153, 153, 153]));
}

#[test]
fn a_reflective_plane_adds_its_reflectivity_times_the_background() {
    let dir = TempDir::new().unwrap();
    let mirror = json!({ "ambient": [0.1, 0.1, 0.1], "diffuse": [0.3, 0.3, 0.3],
                         "specular": [0, 0, 0], "shininess": 1,
                         "reflectivity": [0.5, 0.25, 0.5] });
    let scene = write(
        &dir,
        "mirror.json",
        &plane_scene(mirror, vec![], [0.2, 0.6, 1.0]),
    );
    // Local: 0.1 + 0.3·cos 0 = 0.4. The reflection ray R_V = V − 2(N·V)N leaves upwards and
    // sees the background: C = 0.4 + O_r·(0.2, 0.6, 1.0) = (0.5, 0.55, 0.9).
    let e = explain_json(&scene, 0, 0, &[]);
    assert_close(path_color(&e), [0.5, 0.55, 0.9]);
    let rays = e["samples"][0]["rays"].as_array().unwrap();
    assert_eq!(rays.len(), 2);
    assert_eq!(rays[1]["level"], 2);
    assert_eq!(rays[1]["weight"], 0.5, "w_s = 1·max(O_r)");
    assert_eq!(rays[1]["stop"], "miss");
    // R_V: V = (−3, 0, −5)/√34, N = (0, 0, 1): R_V = (−3, 0, 5)/√34.
    let d = rays[1]["direction"].as_array().unwrap();
    let s = 34f64.sqrt();
    assert_close(
        [0, 1, 2].map(|i| d[i].as_f64().unwrap()),
        [-3.0 / s, 0.0, 5.0 / s],
    );
    // It leaves from just above the origin: the offset is tiny and on the ray's side.
    let z = rays[1]["origin"][2].as_f64().unwrap();
    assert!(z > 0.0 && z < 1e-12, "origin z = {z}");

    // Maximum level 1: primary rays only, C = 0.4.
    let e = explain_json(&scene, 0, 0, &["--max-level", "1"]);
    assert_close(path_color(&e), [0.4; 3]);
    assert_eq!(e["samples"][0]["rays"][0]["stop"], "max_level");
    // Minimum weight 0.5: w_s = 0.5 is not above it, so no reflection ray.
    let e = explain_json(&scene, 0, 0, &["--min-weight", "0.5"]);
    assert_close(path_color(&e), [0.4; 3]);
    assert_eq!(e["samples"][0]["rays"][0]["stop"], "min_weight");
    // Just below 0.5, the ray is traced.
    let e = explain_json(&scene, 0, 0, &["--min-weight", "0.4999"]);
    assert_close(path_color(&e), [0.5, 0.55, 0.9]);
}

#[test]
fn two_facing_mirrors_stop_at_the_maximum_level_or_when_the_weight_runs_out() {
    let dir = TempDir::new().unwrap();
    // The camera, at z = 1 between the mirrors z = 0 and z = 2, looks straight down: its ray
    // bounces up and down between them for ever. Each mirror has O_a = 1 and O_r = 0.5; the
    // only light is an ambient 0.1 and the background is black.
    let m = json!({ "ambient": [1, 1, 1], "reflectivity": [0.5, 0.5, 0.5] });
    let scene = json!({
        "lights": [{ "type": "ambient", "color": [0.1, 0.1, 0.1] }],
        "surfaces": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": m },
            { "type": "plane", "point": [0, 0, 2], "normal": [0, 0, 1], "material": m }
        ],
        "camera": { "eye": [0, 0, 1], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 30,
                    "width": 1, "height": 1 }
    });
    let path = write(&dir, "mirrors.json", &scene);
    // Each hit adds 0.1, weighted by 0.5^(level − 1): with n levels C = 0.1·(1 − 0.5^n)/(1 − 0.5).
    for n in [1u32, 2, 5, 10] {
        let e = explain_json(
            &path,
            0,
            0,
            &["--max-level", &n.to_string(), "--min-weight", "0"],
        );
        let rays = e["samples"][0]["rays"].as_array().unwrap();
        assert_eq!(rays.len(), n as usize, "level {n}");
        let expected = 0.2 * (1.0 - 0.5f64.powi(n as i32));
        assert_close(path_color(&e), [expected; 3]);
        assert_eq!(rays[n as usize - 1]["stop"], "max_level");
    }
    // Minimum weight 0.1: weights 1, 0.5, 0.25, 0.125 are traced, 0.0625 is not.
    let e = explain_json(&path, 0, 0, &["--max-level", "100", "--min-weight", "0.1"]);
    let rays = e["samples"][0]["rays"].as_array().unwrap();
    assert_eq!(rays.len(), 4);
    assert_eq!(rays[3]["stop"], "min_weight");
    assert_eq!(rays[3]["next_weight"], 0.0625);
}

// ---------------------------------------------------------------------------------------------
// Scale and threads
// ---------------------------------------------------------------------------------------------

/// The classic scene with every length multiplied by `s`; a light with falloff f has its colour
/// multiplied by s^f, so that C/d^f, and so the image, is unchanged.
fn scaled(scene: &Value, s: f64) -> Value {
    let mut v = scene.clone();
    let scale = |a: &mut Value| {
        for x in a.as_array_mut().unwrap() {
            *x = json!(x.as_f64().unwrap() * s);
        }
    };
    for light in v["lights"].as_array_mut().unwrap() {
        if light.get("position").is_some() {
            scale(&mut light["position"]);
            let f = light["falloff"].as_f64().unwrap();
            for c in light["color"].as_array_mut().unwrap() {
                *c = json!(c.as_f64().unwrap() * s.powf(f));
            }
        }
    }
    for surface in v["surfaces"].as_array_mut().unwrap() {
        for key in ["point", "center"] {
            if surface.get(key).is_some() {
                scale(&mut surface[key]);
            }
        }
        if let Some(r) = surface.get("radius").and_then(Value::as_f64) {
            surface["radius"] = json!(r * s);
        }
    }
    scale(&mut v["camera"]["eye"]);
    scale(&mut v["camera"]["look_at"]);
    v["camera"]["width"] = json!(160);
    v["camera"]["height"] = json!(120);
    v
}

#[test]
fn the_same_scene_scaled_by_a_thousandth_or_a_million_renders_the_same_image() {
    let dir = TempDir::new().unwrap();
    let classic = read_json(&repo("scenes/classic.json"));
    let base = write(&dir, "s1.json", &scaled(&classic, 1.0));
    let (_, _, reference) = render_ppm(&base, &dir, "s1.ppm", &[]);
    for (name, s) in [("milli", 1e-3), ("mega", 1e6)] {
        let path = write(&dir, &format!("{name}.json"), &scaled(&classic, s));
        let (_, _, img) = render_ppm(&path, &dir, &format!("{name}.ppm"), &[]);
        let differ: Vec<usize> = (0..img.len()).filter(|&i| img[i] != reference[i]).collect();
        let worst = differ
            .iter()
            .map(|&i| (i32::from(img[i]) - i32::from(reference[i])).abs())
            .max()
            .unwrap_or(0);
        assert!(
            differ.is_empty(),
            "scale {s}: {} of {} channels differ, by up to {worst}",
            differ.len(),
            img.len()
        );
    }
}

#[test]
fn any_number_of_threads_writes_the_same_bytes() {
    let dir = TempDir::new().unwrap();
    let classic = read_json(&repo("scenes/classic.json"));
    let scene = write(&dir, "small.json", &scaled(&classic, 1.0));
    let one = render_ppm(
        &scene,
        &dir,
        "t1.ppm",
        &["--threads", "1", "--samples", "4"],
    );
    for t in ["2", "3", "7"] {
        let other = render_ppm(
            &scene,
            &dir,
            &format!("t{t}.ppm"),
            &["--threads", t, "--samples", "4"],
        );
        assert!(one == other, "--threads {t} changed the image");
    }
    // And PNG is the same pixels.
    let png = dir.path().join("t.png");
    phong()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(&png)
        .assert()
        .success();
    assert!(fs::read(&png).unwrap().starts_with(b"\x89PNG\r\n\x1a\n"));
}

/// FNV-1a, 64 bits, of a file's bytes.
fn fnv1a(bytes: &[u8]) -> u64 {
    (bytes.iter()).fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Each bundled scene, f32 and f64, renders the bytes a build for any x86-64 CPU (SSE2 lanes,
/// two halves per register) wrote: this build is for the machine's own CPU (`.cargo/config.toml`:
/// AVX2 lanes where it has them), and the image must not depend on which lanes run.
///
/// The digests are FNV-1a of the PPM files of a release build of main at d1ad6a4 with
/// `RUSTFLAGS="-C target-cpu=x86-64"` (before phong was built for the machine's CPU), computed
/// by a Python FNV-1a, not by this code: `phong render scenes/S.json -o S-P.ppm --precision P`.
/// A change that means to change the images changes them here too, saying why.
#[test]
fn every_bundled_scene_renders_the_bytes_of_the_build_for_any_x86_64_cpu() {
    const PORTABLE: [(&str, &str, u64); 14] = [
        ("4.3", "f32", 0x5178c7d210548db9),
        ("4.3", "f64", 0xef9fc166be7c9104),
        ("classic", "f32", 0xf1a02e2614f3a790),
        ("classic", "f64", 0x40346521941f5eda),
        ("glass", "f32", 0x84cd1ad55fd609a7),
        ("glass", "f64", 0x947bd1066d461a90),
        ("mesh", "f32", 0xdcaf3827bc4ffb6b),
        ("mesh", "f64", 0xf7729114e7b11a6a),
        ("pov-lights", "f32", 0x7f023c05e839048b),
        ("pov-lights", "f64", 0x6ce9f5b126a3b451),
        ("pov-materials", "f32", 0xe70c9ee9827f5b0d),
        ("pov-materials", "f64", 0x084a04e989cacdf8),
        ("smooth", "f32", 0x87f88778c3f9f6bd),
        ("smooth", "f64", 0xaed83355e01e48c2),
    ];
    let dir = TempDir::new().unwrap();
    let mut differ = Vec::new();
    for (scene, precision, digest) in PORTABLE {
        for engine in ["wide", "scalar"] {
            let out = dir.path().join(format!("{scene}-{precision}-{engine}.ppm"));
            phong()
                .arg("render")
                .arg(repo(&format!("scenes/{scene}.json")))
                .arg("-o")
                .arg(&out)
                .args(["--precision", precision, "--engine", engine])
                .assert()
                .success();
            let got = fnv1a(&fs::read(&out).unwrap());
            if got != digest {
                differ.push(format!("{scene} {precision} {engine}: {got:016x}"));
            }
        }
    }
    assert!(
        differ.is_empty(),
        "images not the portable build's: {differ:#?}"
    );
}

// ---------------------------------------------------------------------------------------------
// Bad scenes
// ---------------------------------------------------------------------------------------------

/// Runs `phong render` on a scene that must be refused: exit 2, stderr naming the file and
/// `field`, a fix, no panic, and no image written.
fn refused(dir: &TempDir, scene: &Value, extra: &[&str], field: &str) {
    let path = write(dir, "bad.json", scene);
    let out_path = dir.path().join("out.png");
    let _ = fs::remove_file(&out_path);
    let out = phong()
        .arg("render")
        .arg(&path)
        .arg("-o")
        .arg(&out_path)
        .args(extra)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(BAD_INPUT), "{stderr}");
    assert!(stderr.contains(field), "names {field}: {stderr}");
    assert!(stderr.contains("Fix:"), "says how to fix it: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out_path.exists(), "no image is written: {stderr}");
    let leftovers: Vec<_> = fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "no temporary file is left behind");
}

fn small_scene() -> Value {
    json!({
        "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
        "surfaces": [{ "type": "sphere", "center": [0, 0, 0], "radius": 1,
                       "material": { "ambient": [0.5, 0.5, 0.5] } }],
        "camera": { "eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "width": 8, "height": 6 }
    })
}

#[test]
fn a_scene_without_a_camera_cannot_be_rendered() {
    let dir = TempDir::new().unwrap();
    let mut s = small_scene();
    s.as_object_mut().unwrap().remove("camera");
    s["ray"] = json!({ "origin": [0, 0, 5], "direction": [0, 0, -1] });
    refused(&dir, &s, &[], "camera");
}

#[test]
fn image_sizes_of_zero_or_over_16384_are_refused() {
    let dir = TempDir::new().unwrap();
    for (key, n) in [
        ("width", 0),
        ("height", 0),
        ("width", 16385),
        ("height", 100000),
    ] {
        let mut s = small_scene();
        s["camera"][key] = json!(n);
        refused(&dir, &s, &[], &format!("camera.{key}"));
    }
}

#[test]
fn more_than_4096_samples_are_refused_in_the_file_and_on_the_command_line() {
    let dir = TempDir::new().unwrap();
    let mut s = small_scene();
    s["render"] = json!({ "samples": 4097 });
    refused(&dir, &s, &[], "render.samples");
    refused(&dir, &small_scene(), &["--samples", "5000"], "--samples");
    refused(&dir, &small_scene(), &["--samples", "0"], "--samples");
    refused(&dir, &small_scene(), &["--max-level", "0"], "--max-level");
    refused(&dir, &small_scene(), &["--min-weight=-1"], "--min-weight");
    refused(&dir, &small_scene(), &["--threads", "0"], "--threads");
}

#[test]
fn a_degenerate_triangle_is_refused() {
    let dir = TempDir::new().unwrap();
    let mut s = small_scene();
    s["surfaces"] = json!([{ "type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]],
                             "material": { "ambient": [0.5, 0.5, 0.5] } }]);
    refused(&dir, &s, &[], "surfaces[0].vertices");
}

#[test]
fn unreadable_or_malformed_obj_files_are_refused() {
    let dir = TempDir::new().unwrap();
    let mesh = |file: &str| {
        let mut s = small_scene();
        s["surfaces"] = json!([{ "type": "mesh", "file": file,
                                 "material": { "ambient": [0.5, 0.5, 0.5] } }]);
        s
    };
    refused(&dir, &mesh("missing.obj"), &[], "surfaces[0].file");
    fs::write(dir.path().join("broken.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 7\n").unwrap();
    refused(&dir, &mesh("broken.obj"), &[], "surfaces[0].file");
    fs::write(dir.path().join("garbage.obj"), "v zero one two\nf 1 2 3\n").unwrap();
    refused(&dir, &mesh("garbage.obj"), &[], "surfaces[0].file");
    fs::write(dir.path().join("empty.obj"), "# nothing\n").unwrap();
    refused(&dir, &mesh("empty.obj"), &[], "surfaces[0].file");
    fs::write(
        dir.path().join("flat.obj"),
        "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n",
    )
    .unwrap();
    refused(&dir, &mesh("flat.obj"), &[], "surfaces[0].file");
}

#[test]
fn an_existing_image_is_left_untouched_when_the_scene_is_bad() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("keep.png");
    fs::write(&out, b"previous image").unwrap();
    let mut s = small_scene();
    s["camera"]["width"] = json!(0);
    let path = write(&dir, "bad.json", &s);
    phong()
        .arg("render")
        .arg(&path)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(BAD_INPUT);
    assert_eq!(fs::read(&out).unwrap(), b"previous image");
}

#[test]
fn a_pixel_outside_the_image_cannot_be_explained() {
    let dir = TempDir::new().unwrap();
    let path = write(&dir, "s.json", &small_scene());
    let out = phong()
        .arg("render")
        .arg(&path)
        .args(["--explain-pixel", "8,0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(BAD_INPUT));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--explain-pixel"));
}

#[test]
fn solving_a_scene_without_a_ray_says_to_render_it() {
    let dir = TempDir::new().unwrap();
    let path = write(&dir, "s.json", &small_scene());
    let out = phong().arg("solve").arg(&path).output().unwrap();
    assert_eq!(out.status.code(), Some(BAD_INPUT));
    assert!(String::from_utf8_lossy(&out.stderr).contains("phong render"));
}

#[test]
fn an_explanation_is_written_to_a_file_of_any_name() {
    // README's `--explain-pixel … --format html -o pixel.html`: with --explain-pixel, --output
    // names the explanation's file, so its extension need not be an image's.
    let dir = TempDir::new().unwrap();
    let path = write(&dir, "s.json", &small_scene());
    for (format, name) in [
        ("html", "pixel.html"),
        ("json", "pixel.json"),
        ("text", "p.txt"),
    ] {
        let shown = phong()
            .arg("render")
            .arg(&path)
            .args(["--explain-pixel", "1,1", "--format", format])
            .output()
            .unwrap();
        assert!(shown.status.success());
        let out = dir.path().join(name);
        phong()
            .arg("render")
            .arg(&path)
            .args(["--explain-pixel", "1,1", "--format", format, "-o"])
            .arg(&out)
            .assert()
            .success();
        assert_eq!(fs::read(&out).unwrap(), shown.stdout, "{name}");
    }
}

#[test]
fn render_stats_speak_the_language_of_lang() {
    let dir = TempDir::new().unwrap();
    let path = write(&dir, "s.json", &small_scene());
    let out = dir.path().join("s.png");
    let stats = |lang: &str| {
        let o = phong()
            .arg("render")
            .arg(&path)
            .args(["--stats", "--threads", "1", "--lang", lang, "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(o.status.success());
        String::from_utf8(o.stderr).unwrap()
    };
    let (en, pt) = (stats("en"), stats("pt"));
    assert!(en.contains(" rays (") && en.contains("1 thread(s)"), "{en}");
    for english in [
        "rays", "read and", "traced", "primary", "shadow", "engine", "sample(",
    ] {
        assert!(!pt.contains(english), "{english:?} in {pt}");
    }
    assert!(
        pt.contains("raios traçados") && pt.contains("lido e validado"),
        "{pt}"
    );
}

#[test]
fn no_output_replaces_a_mesh_the_scene_reads() {
    // A scene's OBJ file is an input of the run as much as the scene: `-o torus.obj` would
    // destroy it, so each command refuses it (exit 2) before writing anything. `check` and
    // `grade` replaced it (exit 0) until they too counted it as an input.
    let dir = TempDir::new().unwrap();
    let obj = dir.path().join("torus.obj");
    fs::copy(repo("scenes/torus.obj"), &obj).unwrap();
    let before = fs::read(&obj).unwrap();
    let mut scene = read_json(&repo("scenes/mesh.json"));
    scene["camera"]["width"] = json!(16);
    scene["camera"]["height"] = json!(12);
    let path = write(&dir, "mesh.json", &scene);
    let mut ray = scene.clone();
    ray.as_object_mut().unwrap().remove("camera");
    ray["ray"] = json!({"origin": [0, 1, 6], "direction": [0, 0, -1]});
    let ray_path = write(&dir, "mesh-ray.json", &ray);
    fs::write(dir.path().join("subs.csv"), "ana,mesh-ray,none\n").unwrap();
    let runs: [Vec<&str>; 8] = [
        vec![
            "render",
            "mesh.json",
            "--image-format",
            "ppm",
            "-o",
            "torus.obj",
        ],
        vec!["export-pov", "mesh.json", "-o", "torus.obj"],
        vec![
            "tradeoff",
            "mesh.json",
            "--size",
            "8x6",
            "--runs",
            "1",
            "--levels",
            "1",
            "--samples",
            "1",
            "--precisions",
            "f64",
            "--min-weights",
            "0",
            "--reference-samples",
            "1",
            "-o",
            "torus.obj",
        ],
        vec!["solve", "mesh-ray.json", "-o", "torus.obj"],
        vec![
            "check",
            "mesh-ray.json",
            "--answer",
            "none",
            "-o",
            "torus.obj",
        ],
        vec!["check", "mesh-ray.json", "--slips", "-o", "torus.obj"],
        vec!["moodle", "mesh-ray.json", "-o", "torus.obj"],
        vec![
            "grade",
            "subs.csv",
            "--exercises",
            ".",
            "--summary",
            "torus.obj",
        ],
    ];
    assert!(path.exists() && ray_path.exists());
    for args in runs {
        let out = phong()
            .current_dir(dir.path())
            .args(&args)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(BAD_INPUT), "{args:?}: {stderr}");
        assert!(stderr.contains("torus.obj"), "{args:?}: {stderr}");
        assert_eq!(
            fs::read(&obj).unwrap(),
            before,
            "{args:?} replaced the mesh"
        );
    }
}

#[test]
fn a_reflection_ray_is_not_said_to_come_from_the_eye() {
    // The classic scene's pixel 320,300 hits the floor and sends a reflection ray: V = D there
    // is the reflection ray's direction, which no eye looks along.
    let out = phong()
        .arg("render")
        .arg(repo("scenes/classic.json"))
        .args(["--explain-pixel", "320,300"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let secondary = text
        .split_once("Ray 2 (reflection)")
        .expect("a reflection ray")
        .1;
    assert!(!secondary.contains("from the eye"), "{secondary}");
}

#[test]
fn an_explained_pixel_states_the_readings_of_level_and_weight() {
    // docs/conventions.md, "Recursion level" and "Weight": "≤" for the chapter's "menor que"
    // and O_r for its max(C_r) are readings, and the explanation says so, in both languages.
    for (lang, level, weight) in [
        (
            "en",
            "\"menor que\" read as ≤",
            "max(C_r) read as the reflectivity O_r",
        ),
        (
            "pt",
            "\"menor que\" do capítulo lido como ≤",
            "max(C_r) do capítulo lido como a reflexividade O_r",
        ),
    ] {
        let out = phong()
            .arg("render")
            .arg(repo("scenes/classic.json"))
            .args(["--explain-pixel", "320,300", "--lang", lang])
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap().replace('\n', " ");
        assert!(
            text.contains(level) && text.contains(weight),
            "{lang}: {text}"
        );
    }
}

#[test]
fn export_pov_help_offers_only_the_samples_it_can_export() {
    // `export-pov --samples 4` is refused (POV-Ray cannot average phong's samples), so its help
    // must not offer render's "1 to 4096".
    // The short help writes a flag's text on its line; the long help (export-pov has a long
    // one) on the lines below it, up to a blank line.
    for flag in ["-h", "--help"] {
        let out = phong().args(["export-pov", flag]).output().unwrap();
        let help = String::from_utf8(out.stdout).unwrap();
        let from = help.find("--samples").unwrap();
        let entry = help[from..].split("\n\n").next().unwrap();
        assert!(
            entry.contains("only 1") && !entry.contains("4096"),
            "{flag}: {entry}"
        );
    }
}

/// The triangle (0,0,0), (1,0,0), (0,1,0) with vertex normals N₀ = (0, 0, 1), N₁ = (0.6, 0, 0.8),
/// N₂ = (0, 0.6, 0.8): a smooth face.
const SMOOTH_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0.6 0 0.8\nvn 0 0.6 0.8\n\
                          f 1//1 2//2 3//3\n";

/// A ray problem on the face of `obj` (written as `smooth.obj`), straight down onto
/// (0.25, 0.25, 0), lit by a directional light along −z.
fn smooth_ray_problem(dir: &TempDir, obj: &str) -> PathBuf {
    fs::write(dir.path().join("smooth.obj"), obj).unwrap();
    let problem = json!({
        "lights": [{ "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] }],
        "surfaces": [{ "type": "mesh", "file": "smooth.obj",
                       "material": { "diffuse": [0.5, 0.5, 0.5], "specular": [0, 0, 0],
                                     "shininess": 1 } }],
        "ray": { "origin": [0.25, 0.25, 1], "direction": [0, 0, -1] }
    });
    write(dir, "smooth-ray.json", &problem)
}

#[test]
fn a_ray_on_a_smooth_face_is_shaded_with_the_interpolated_normal_worked_by_hand() {
    let dir = TempDir::new().unwrap();
    let path = smooth_ray_problem(&dir, SMOOTH_OBJ);
    let s = solve_json(&path);
    // By hand: P = (0.25, 0.25, 0), b = (1 − x − y, x, y) = (0.5, 0.25, 0.25);
    // ΣbN = (0.15, 0.15, 0.5 + 0.2 + 0.2) = (0.15, 0.15, 0.9), ‖ΣbN‖ = √0.855;
    // cos θ = −N·L = N_z = 0.9/√0.855 = 0.97332852…; diffuse 0.5·cos θ = 0.48666426….
    let len = 0.855f64.sqrt();
    let want_n = [0.15 / len, 0.15 / len, 0.9 / len];
    let normal = &s["solution"]["normal"];
    for (i, want) in want_n.iter().enumerate() {
        let got = normal["n"][i].as_f64().unwrap();
        assert!((got - want).abs() < 1e-15, "N = {normal}");
    }
    // The geometric normal is the winding's, (0, 0, 1), and it is not reversed.
    assert_eq!(normal["given"], json!([0.0, 0.0, 1.0]));
    assert_eq!(normal["reversed"], json!(false));
    let smooth = &normal["smooth"];
    for (i, want) in [0.5, 0.25, 0.25].iter().enumerate() {
        let got = smooth["barycentric"][i].as_f64().unwrap();
        assert!((got - want).abs() < 1e-15, "{smooth}");
    }
    assert_eq!(smooth["clamped"], json!(false));
    assert_eq!(smooth["vertex_normals"][1], json!([0.6, 0.0, 0.8]));
    let diffuse = 0.5 * 0.9 / len;
    assert!((diffuse - 0.486_664_26).abs() < 1e-8);
    for c in 0..3 {
        let got = s["solution"]["color"]["unclamped"][c].as_f64().unwrap();
        assert!((got - diffuse).abs() < 1e-15, "{}", s["solution"]["color"]);
    }
    // The text says where N came from, in both languages.
    for (lang, words) in [
        (
            "en",
            "interpolated from the triangle's three vertex normals",
        ),
        (
            "pt",
            "interpolada das normais dos três vértices do triângulo",
        ),
    ] {
        let out = phong()
            .arg("solve")
            .arg(&path)
            .args(["--lang", lang])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success() && text.contains(words), "{text}");
        assert!(text.contains("(0.5, 0.25, 0.25)"), "{text}");
    }
}

#[test]
fn a_flat_mesh_s_json_has_no_smooth_normal() {
    let dir = TempDir::new().unwrap();
    let path = smooth_ray_problem(&dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let s = solve_json(&path);
    let normal = &s["solution"]["normal"];
    assert!(normal.get("smooth").is_none(), "{normal}");
    assert_eq!(normal["n"], json!([0.0, 0.0, 1.0]));
}

#[test]
fn bad_vertex_normals_are_refused_naming_the_obj_file_and_line() {
    let dir = TempDir::new().unwrap();
    let scene = |file: &str| {
        let mut s = small_scene();
        s["surfaces"] = json!([{ "type": "mesh", "file": file,
                                 "material": { "ambient": [0.5, 0.5, 0.5] } }]);
        s
    };
    let corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (name, body, words, pt) in [
        (
            "zero.obj",
            "vn 0 0 0\nf 1//1 2//1 3//1\n",
            "line 4: the vertex normal",
            "linha 4: a normal de vértice \"vn 0 0 0\" tem comprimento zero em f64",
        ),
        (
            "nan.obj",
            "vn 0 nan 1\nf 1//1 2//1 3//1\n",
            "line 4: the vertex normal",
            "linha 4: a normal de vértice \"vn 0 nan 1\" não é finita em f64",
        ),
        (
            "partial.obj",
            "vn 0 0 1\nf 1//1 2 3//1\n",
            "line 5: the face",
            "dá normais de vértice para 2 de seus 3 vértices",
        ),
        (
            "index.obj",
            "vn 0 0 1\nf 1//1 2//1 3//2\n",
            "line 5: the face",
            "se refere à normal de vértice 2 (em 3//2), e 1 normais de vértice vêm antes dela",
        ),
    ] {
        fs::write(dir.path().join(name), format!("{corners}{body}")).unwrap();
        refused(&dir, &scene(name), &[], "surfaces[0].file");
        let path = write(&dir, "bad.json", &scene(name));
        let out = phong()
            .arg("render")
            .arg(&path)
            .arg("-o")
            .arg(dir.path().join("out.png"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains(name) && stderr.contains(words) && !stderr.contains("Português"),
            "{name}: {stderr}"
        );
        let out = phong()
            .arg("render")
            .arg(&path)
            .arg("-o")
            .arg(dir.path().join("out.png"))
            .args(["--lang", "pt"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.code() == Some(BAD_INPUT)
                && stderr.contains(pt)
                && stderr.contains("Correção"),
            "{name}: {stderr}"
        );
    }
}

#[test]
fn an_explained_smooth_mesh_pixel_says_which_normal_it_shades_with() {
    let path = repo("scenes/smooth.json");
    // Pixel (100, 100) of the 320×240 scene is on the mesh sphere.
    let v = explain_json(&path, 100, 100, &[]);
    let solve = &v["samples"][0]["rays"][0]["solve"];
    assert_eq!(
        solve["intersection"]["surface_type"],
        json!("triangle"),
        "{solve}"
    );
    let ray = &solve["solution"];
    let smooth = &ray["normal"]["smooth"];
    let b: Vec<f64> = (0..3)
        .map(|i| smooth["barycentric"][i].as_f64().unwrap())
        .collect();
    assert!(b.iter().all(|&x| x >= 0.0) && (b.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    // The interpolation by hand from the weights and the vertex normals given.
    let mut sum = [0.0; 3];
    for (k, bk) in b.iter().enumerate() {
        for (i, s) in sum.iter_mut().enumerate() {
            *s += bk * smooth["vertex_normals"][k][i].as_f64().unwrap();
        }
    }
    let len = (sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]).sqrt();
    for (i, s) in sum.iter().enumerate() {
        let n = ray["normal"]["n"][i].as_f64().unwrap();
        assert!((n - s / len).abs() < 1e-12, "{}", ray["normal"]);
    }
    for (lang, words) in [("en", "N_g = "), ("pt", "a normal geométrica do triângulo")] {
        let out = phong()
            .arg("render")
            .arg(&path)
            .args(["--explain-pixel", "100,100", "--lang", lang])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success() && text.contains(words), "{text}");
    }
}

/// The pixel's explanation through the same layout as `phong solve`'s: each ray's solver
/// explanation sits below the ray's heading in every format (Markdown `#####` under `####`,
/// HTML `<h4>` under `<h3>`, LaTeX `\paragraph*` under `\subsubsection*`), and the HTML's
/// elements are balanced.
#[test]
fn a_pixels_explanation_nests_each_rays_solution_below_the_ray() {
    let explain = |format: &str| {
        let out = phong()
            .arg("render")
            .arg(repo("scenes/glass.json"))
            .args(["--explain-pixel", "320,240", "--format", format])
            .args(["--lang", "en"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{format}");
        String::from_utf8(out.stdout).unwrap()
    };
    let md = explain("markdown");
    let headings: Vec<&str> = md.lines().filter(|l| l.starts_with('#')).collect();
    assert!(
        headings[0].starts_with("## Pixel (320, 240)"),
        "{headings:?}"
    );
    for h in &headings[1..] {
        let level = h.chars().take_while(|&c| c == '#').count();
        let expected = if h.starts_with("### Sample") {
            3
        } else if h.starts_with("#### Ray ") {
            4
        } else {
            5
        };
        assert_eq!(level, expected, "{h}");
    }
    assert!(md.contains("\n##### Findings\n"));
    let html = explain("html");
    for tag in ["article", "section", "ul", "ol"] {
        assert_eq!(
            html.matches(&format!("<{tag}")).count(),
            html.matches(&format!("</{tag}>")).count(),
            "<{tag}>"
        );
    }
    assert!(html.contains("<h4>Findings</h4>") && html.contains("<h5>Given</h5>"));
    assert!(!html.contains("<h2>Findings</h2>"));
    let latex = explain("latex");
    assert!(latex.contains("\\paragraph*{Findings}") && latex.contains("\\subparagraph{Given}"));
    assert!(!latex.contains("\\subsection*{Findings}"));
}

/// The pixel's colour from its explanation's samples alone: the mean of each sample's colour
/// clamped to [0, 1].
fn pixel_color(e: &Value) -> [f64; 3] {
    let samples = e["samples"].as_array().unwrap();
    let mut sum = [0.0; 3];
    for s in samples {
        for (k, c) in s["color"].as_array().unwrap().iter().enumerate() {
            sum[k] += c.as_f64().unwrap().clamp(0.0, 1.0);
        }
    }
    sum.map(|c| c / samples.len() as f64)
}

fn explain_text(scene: &Path, pixel: &str, args: &[&str]) -> String {
    let out = phong()
        .arg("render")
        .arg(scene)
        .args(["--explain-pixel", pixel])
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap().replace('\n', " ")
}

#[test]
fn a_pixel_explained_in_f32_shows_its_difference_from_f64() {
    // The classic scene's pixel 320,300 hits the floor and reflects; four samples. Its f64
    // colour and f32 − f64 are recomputed here from each run's own samples.
    let scene = repo("scenes/classic.json");
    let args = ["--samples", "4"];
    let e32 = explain_json(
        &scene,
        320,
        300,
        &[&args[..], &["--precision", "f32"]].concat(),
    );
    let e64 = explain_json(&scene, 320, 300, &args);
    assert!(e64.get("versus_f64").is_none(), "f64 has no versus_f64");
    let v = &e32["versus_f64"];
    let tolerance = v["tolerance"].as_f64().unwrap();
    assert_eq!(tolerance, phong::solve::CHECK_TOLERANCE);
    let (c32, c64) = (pixel_color(&e32), pixel_color(&e64));
    for k in 0..3 {
        let f64_color = v["f64_color"][k].as_f64().unwrap();
        assert!((f64_color - c64[k]).abs() < 1e-15, "f64 colour {k}");
        let d = v["color"][k].as_f64().unwrap();
        assert!((d - (c32[k] - c64[k])).abs() < 1e-15, "difference {k}");
        assert!(d.abs() <= tolerance, "within the tolerance: {d}");
        // The 8-bit colours: f64's is round(255·c) of its colour, and their difference.
        let rgb64 = (255.0 * c64[k]).round() as i64;
        assert_eq!(v["f64_rgb8"][k].as_i64().unwrap(), rgb64);
        assert_eq!(e64["rgb8"][k].as_i64().unwrap(), rgb64);
        let rgb32 = e32["rgb8"][k].as_i64().unwrap();
        assert_eq!(v["rgb8"][k].as_i64().unwrap(), rgb32 - rgb64);
    }
    // The text says the difference under the colour, in both languages, and no warning.
    for (lang, line, warning) in [
        (
            "en",
            "f32 − f64 of the colour: (",
            "--precision f64 answers it",
        ),
        (
            "pt",
            "f32 − f64 da cor: (",
            "--precision f64 dá a resposta certa",
        ),
    ] {
        let f32_text = explain_text(&scene, "320,300", &["--precision", "f32", "--lang", lang]);
        assert!(f32_text.contains(line), "{lang}: {f32_text}");
        assert!(!f32_text.contains(warning), "{lang}: {f32_text}");
        let f64_text = explain_text(&scene, "320,300", &["--lang", lang]);
        assert!(!f64_text.contains(line), "{lang}: {f64_text}");
        assert!(!f64_text.contains("f32 − f64"), "{lang}: {f64_text}");
    }
}

#[test]
fn a_pixel_explained_in_f64_says_nothing_of_f32_in_any_format() {
    let scene = repo("scenes/classic.json");
    for format in ["text", "markdown", "latex", "html", "json"] {
        let out = phong()
            .arg("render")
            .arg(&scene)
            .args(["--explain-pixel", "160,150", "--format", format])
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(!text.contains("versus_f64"), "{format}");
        assert!(!text.contains("f32 − f64"), "{format}");
        assert!(!text.contains("f32 &minus; f64"), "{format}");
    }
}

/// Every command takes `--lang`: `export-pov`, `schema` and `policy`, whose outputs are the
/// same in any language, write their errors in the one asked for, over the locale's.
#[test]
fn export_pov_schema_and_policy_write_their_errors_in_the_lang_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let runs: [&[&str]; 3] = [
        &["export-pov", "naoexiste.json"],
        &["schema", "-o", "naoexiste/esquema.json"],
        &["policy", "naoexiste/"],
    ];
    for args in runs {
        let run = |lang: &str, locale: &str| {
            let out = phong()
                .current_dir(dir.path())
                .env("LANG", locale)
                .args(args)
                .args(["--lang", lang])
                .output()
                .unwrap();
            assert_eq!(out.status.code(), Some(2), "{args:?}");
            assert!(out.stdout.is_empty(), "{args:?}");
            String::from_utf8(out.stderr).unwrap()
        };
        // (--lang, a locale of the other language, the error's start, its fix, the other fix)
        for (lang, locale, start, fix, other) in [
            ("pt", "C.UTF-8", "erro: ", "Correção: ", "Fix: "),
            ("en", "pt_BR.UTF-8", "error: ", "Fix: ", "Correção"),
        ] {
            let err = run(lang, locale);
            assert!(
                err.starts_with(start)
                    && err.contains("naoexiste")
                    && err.contains(fix)
                    && !err.contains(other),
                "{args:?}: {err}"
            );
        }
    }
}
