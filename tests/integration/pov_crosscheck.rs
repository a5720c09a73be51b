//! The tracer cross-checked with POV-Ray: each bundled scene is rendered by `phong render` and,
//! exported by `phong export-pov`, by POV-Ray 3.7; every 8-bit channel of every pixel must agree
//! within 1. POV-Ray is an independent implementation of the same model (the mapping is in
//! `src/export/pov.rs`), so a difference is a bug in one of the two or in the mapping.
//!
//! Images are rendered smaller than the scenes ask (a modified copy of each scene in a temporary
//! folder) to keep the run short. On failure the test reports how many pixels differ, the worst
//! one, and writes both images and an amplified difference image to a kept temporary folder.
//!
//! POV-Ray comes from Debian's `povray` package, which `.ci/run` installs. Without it the tests
//! are skipped with a message, except under CI (`CI=true`), where a missing POV-Ray fails them.

use crate::support;

use std::path::{Path, PathBuf};
use std::process::Command;

use phong::export::pov::povray_args;
use phong::tracer::output::decode_ppm;
use phong::tracer::render::Image;
use serde_json::Value;

/// The folder of the bundled scenes.
fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// Whether POV-Ray can run here: always true, since a missing POV-Ray is a failure. The tests
/// that compare with it are `#[ignore = "needs povray: …"]`, so they run only when asked for
/// (`cargo test --test integration -- --ignored`, as `.ci/run` does), and then must run.
fn povray_available() -> bool {
    let found = Command::new("povray").arg("--version").output().is_ok();
    assert!(
        found,
        "`povray` is not installed, and this test needs it: .ci/run installs it \
         (apt-get install -y --no-install-recommends povray); `cargo test` without \
         --ignored lists this test as ignored"
    );
    found
}

/// A copy of `scene` in `dir` with the image `width` wide (height in proportion) and mesh
/// files made absolute, so the copy reads the same OBJ files as the original.
fn scaled_copy(scene: &Path, width: u32, dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(scene).expect("a bundled scene");
    let mut v: Value = serde_json::from_str(&text).expect("a bundled scene is JSON");
    let camera = &mut v["camera"];
    let (w, h) = (
        camera["width"].as_u64().expect("width"),
        camera["height"].as_u64().expect("height"),
    );
    camera["width"] = Value::from(u64::from(width));
    camera["height"] = Value::from((u64::from(width) * h / w).max(1));
    if let Some(surfaces) = v["surfaces"].as_array_mut() {
        for s in surfaces {
            if let Some(file) = s.get("file").and_then(Value::as_str) {
                let absolute = scene.parent().expect("a folder").join(file);
                s["file"] = Value::from(absolute.to_str().expect("a UTF-8 path"));
            }
        }
    }
    let out = dir.join(scene.file_name().expect("a file name"));
    std::fs::write(&out, serde_json::to_string_pretty(&v).unwrap()).unwrap();
    out
}

fn run(cmd: &mut Command, what: &str) {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("{what}: cannot start: {e}"));
    assert!(
        out.status.success(),
        "{what} failed ({}):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

fn read_ppm(path: &Path) -> Image {
    decode_ppm(&std::fs::read(path).unwrap())
        .unwrap_or_else(|| panic!("{} is not a binary PPM", path.display()))
}

/// Both images of a scene: phong's with `phong_flags`, POV-Ray's of the export with
/// `export_flags`.
struct Pair {
    phong: Image,
    povray: Image,
    dir: tempfile::TempDir,
}

/// The folder of the scenes written for these tests alone, apart from phong's own.
fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

/// A scene by name: a bundled one, or one of `tests/data` (named with its folder).
fn scene_path(scene: &str) -> PathBuf {
    match scene.strip_prefix("data/") {
        Some(name) => data().join(name),
        None => scenes().join(scene),
    }
}

fn render_both(scene: &str, width: u32, phong_flags: &[&str], export_flags: &[&str]) -> Pair {
    render_both_edited(scene, width, phong_flags, export_flags, |sdl| sdl)
}

/// `render_both`, with the exported SDL changed by `edit` before POV-Ray reads it (for the
/// controls, which break one part of the mapping on purpose).
fn render_both_edited(
    scene: &str,
    width: u32,
    phong_flags: &[&str],
    export_flags: &[&str],
    edit: impl Fn(String) -> String,
) -> Pair {
    let dir = tempfile::tempdir().unwrap();
    let copy = scaled_copy(&scene_path(scene), width, dir.path());
    let phong_ppm = dir.path().join("phong.ppm");
    let pov = dir.path().join("scene.pov");
    let pov_ppm = dir.path().join("povray.ppm");
    run(
        support::phong_std()
            .arg("render")
            .arg(&copy)
            .arg("-o")
            .arg(&phong_ppm)
            .args(["--threads", "1"])
            .args(phong_flags),
        "phong render",
    );
    run(
        support::phong_std()
            .arg("export-pov")
            .arg(&copy)
            .arg("-o")
            .arg(&pov)
            .args(export_flags),
        "phong export-pov",
    );
    let sdl = std::fs::read_to_string(&pov).unwrap();
    std::fs::write(&pov, edit(sdl)).unwrap();
    let image = read_ppm(&phong_ppm);
    run(
        Command::new("povray")
            .current_dir(dir.path())
            .args(povray_args(image.width, image.height))
            // One render thread: with several, POV-Ray 3.7's output is not the same from run to
            // run (on the mesh scene at 240×180, 3 of 8 runs moved one pixel by 3 steps), which
            // made this comparison fail now and then; single-threaded it gave the same pixels
            // in every run.
            .arg("+WT1")
            .arg("+FP")
            .arg(format!("+O{}", pov_ppm.display()))
            .arg(&pov),
        "povray",
    );
    Pair {
        phong: image,
        povray: read_ppm(&pov_ppm),
        dir,
    }
}

/// How two images differ: pixels with some channel off by exactly 1 (the most off by 1) and
/// by more than 1, and the worst pixel.
#[derive(Debug)]
struct Difference {
    by_one: usize,
    over_one: usize,
    worst: u8,
    worst_at: (u32, u32),
}

fn compare(a: &Image, b: &Image) -> Difference {
    assert_eq!((a.width, a.height), (b.width, b.height), "image sizes");
    let mut d = Difference {
        by_one: 0,
        over_one: 0,
        worst: 0,
        worst_at: (0, 0),
    };
    for (i, (p, q)) in a.rgb.chunks(3).zip(b.rgb.chunks(3)).enumerate() {
        let diff = (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap();
        if diff == 1 {
            d.by_one += 1;
        }
        if diff > 1 {
            d.over_one += 1;
        }
        if diff > d.worst {
            d.worst = diff;
            d.worst_at = (i as u32 % a.width, i as u32 / a.width);
        }
    }
    d
}

/// Requires every channel within 1; otherwise keeps both images and a difference image
/// (|a − b|·32) and reports where they are.
fn assert_within_one(scene: &str, width: u32, phong_flags: &[&str], export_flags: &[&str]) {
    if !povray_available() {
        return;
    }
    let pair = render_both(scene, width, phong_flags, export_flags);
    let d = compare(&pair.phong, &pair.povray);
    // Shown with --nocapture: how close the two are where they agree within 1.
    eprintln!(
        "{scene} {phong_flags:?}: {} of {} pixels differ by 1, {} by more",
        d.by_one,
        pair.phong.width * pair.phong.height,
        d.over_one
    );
    if d.over_one == 0 {
        return;
    }
    let (x, y) = d.worst_at;
    let at = ((y * pair.phong.width + x) * 3) as usize;
    let diff = Image {
        width: pair.phong.width,
        height: pair.phong.height,
        rgb: pair
            .phong
            .rgb
            .iter()
            .zip(&pair.povray.rgb)
            .map(|(p, q)| p.abs_diff(*q).saturating_mul(32))
            .collect(),
    };
    let kept = pair.dir.keep();
    let diff_path = kept.join("difference.ppm");
    std::fs::write(
        &diff_path,
        phong::tracer::output::encode(&diff, phong::tracer::output::ImageFormat::Ppm),
    )
    .unwrap();
    panic!(
        "{scene} {phong_flags:?}: {} of {} pixels differ by more than 1; worst {} at ({x}, {y}): \
         phong {:?}, POV-Ray {:?}. Images and difference.ppm (×32) in {}",
        d.over_one,
        pair.phong.width * pair.phong.height,
        d.worst,
        &pair.phong.rgb[at..at + 3],
        &pair.povray.rgb[at..at + 3],
        kept.display()
    );
}

/// The same flags for both renderers.
fn same(scene: &str, width: u32, flags: &[&str]) {
    assert_within_one(scene, width, flags, flags);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_classic_scene_matches_povray_within_one_step() {
    same("classic.json", 320, &[]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_classic_scene_matches_povray_at_every_recursion_setting() {
    same("classic.json", 200, &["--max-level", "1"]);
    same(
        "classic.json",
        200,
        &["--max-level", "2", "--shadows", "off"],
    );
    same("classic.json", 200, &["--min-weight", "0.2"]);
    same(
        "classic.json",
        200,
        &["--min-weight", "0", "--max-level", "12"],
    );
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn exercise_4_3_rendered_matches_povray_with_its_coloured_specular_colour() {
    same("4.3.json", 320, &[]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_mesh_scene_matches_povray() {
    same("mesh.json", 240, &[]);
    same("mesh.json", 160, &["--shadows", "off", "--max-level", "1"]);
}

/// Whether the pixel (x, y) of `scene` (in the pair's folder), rendered with `flags`, sees a
/// smooth triangle from the side its geometric normal faces but its interpolated normal does
/// not (N_g·D < 0 < N·V) on some ray: where phong turns the shading normal with the geometric
/// normal's test (docs/conventions.md, "Smooth meshes") and POV-Ray's `smooth_triangle` turns it
/// by its own sign, so that POV-Ray shades the other side.
fn smooth_normal_turned_away(dir: &Path, scene: &str, flags: &[&str], x: u32, y: u32) -> bool {
    let out = support::phong_std()
        .arg("render")
        .arg(dir.join(scene))
        .args(["--explain-pixel", &format!("{x},{y}"), "--format", "json"])
        .args(flags)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let rays = v["samples"][0]["rays"].as_array().expect("the rays");
    rays.iter().any(|r| {
        let s = &r["solve"]["solution"];
        let n_dot_v = s["viewer"]["n_dot_v"].as_f64().unwrap_or(0.0);
        let (ng, d) = (&s["normal"]["given"], &s["viewer"]["v"]);
        let ng_dot_d: f64 = (0..3)
            .map(|i| ng[i].as_f64().unwrap_or(0.0) * d[i].as_f64().unwrap_or(0.0))
            .sum();
        s["normal"].get("smooth").is_some() && n_dot_v > 0.0 && ng_dot_d < 0.0
    })
}

/// Vertex normals exported as POV-Ray's `smooth_triangle`: the same interpolated shading, every
/// pixel within 1 except on the mesh's silhouette (and its reflection), where the interpolated
/// normal turns away from the viewer while the face itself still faces it: there POV-Ray flips
/// the interpolated normal to the viewer and shades the back of it (ambient only, the lights
/// behind), phong keeps it on the geometric normal's side (see
/// [`smooth_normal_turned_away`]). Each such pixel is checked to be one of those.
#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_smooth_mesh_scene_matches_povray_but_where_the_smooth_normal_turns_away() {
    if !povray_available() {
        return;
    }
    for (width, flags) in [
        (320, &[][..]),
        (160, &["--shadows", "off", "--max-level", "1"][..]),
    ] {
        let pair = render_both("smooth.json", width, flags, flags);
        let mut away = 0;
        for (i, (p, q)) in pair
            .phong
            .rgb
            .chunks(3)
            .zip(pair.povray.rgb.chunks(3))
            .enumerate()
        {
            if (0..3).all(|c| p[c].abs_diff(q[c]) <= 1) {
                continue;
            }
            let (x, y) = (i as u32 % pair.phong.width, i as u32 / pair.phong.width);
            assert!(
                smooth_normal_turned_away(pair.dir.path(), "smooth.json", flags, x, y),
                "smooth.json {flags:?}: pixel ({x}, {y}) differs (phong {p:?}, POV-Ray {q:?}) \
                 and is not on the silhouette"
            );
            away += 1;
        }
        // On the silhouette only: well under 1 % of the image (32 of 76,800 pixels at 320).
        let pixels = (pair.phong.width * pair.phong.height) as usize;
        assert!(away * 200 < pixels, "{flags:?}: {away} of {pixels} pixels");
    }
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn spot_lights_and_falloffs_match_povray() {
    same("pov-lights.json", 320, &[]);
    same("pov-lights.json", 160, &["--shadows", "off"]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn layered_materials_and_the_weight_rule_match_povray() {
    same("pov-materials.json", 320, &[]);
    same("pov-materials.json", 160, &["--min-weight", "0.3"]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_comparison_catches_a_different_recursion_level() {
    // A control: the same scene with the mirror traced to level 1 by phong and to level 5 by
    // POV-Ray must differ, or the comparison could not fail.
    if !povray_available() {
        return;
    }
    let pair = render_both(
        "classic.json",
        160,
        &["--max-level", "1"],
        &["--max-level", "5"],
    );
    let d = compare(&pair.phong, &pair.povray);
    assert!(d.over_one > 100, "{d:?}");
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_glass_scene_matches_povray_with_and_without_shadows() {
    // A grey O_t (one layer, `transmit`), Snell's law through a sphere, the shadow of glass
    // (phong: a full shadow; POV-Ray: the black copy that only shadow rays see).
    same("glass.json", 320, &[]);
    same("glass.json", 200, &["--shadows", "off"]);
    same(
        "glass.json",
        200,
        &["--max-level", "3", "--min-weight", "0.5"],
    );
    // The same glass with its own ambient and diffuse colour: one layer still, the emission
    // and the diffuse light divided by the opacity 1 − T = 0.15 through the pigment.
    same("data/pov-glass-ambient.json", 240, &[]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn glass_spheres_before_a_checker_of_spheres_match_povray() {
    // Written apart from phong's scenes: a grey O_t of 0.9 (ior 1.5), a tinted O_t with a
    // coloured specular colour (layers, `filter`; ior 1.7), an O_t of 1 with a diffuse colour
    // (layers; ior 1.2), in front of 24 coloured spheres on a reflecting floor.
    same("data/pov-glass-checker.json", 240, &[]);
    same("data/pov-glass-checker.json", 240, &["--shadows", "off"]);
    same("data/pov-glass-checker.json", 160, &["--min-weight", "0.5"]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn a_glass_half_space_seen_at_an_angle_matches_povray() {
    // Written apart from phong's scenes: a plane with a coloured O_t and ior 1.33 (water),
    // matte spheres and a matte floor inside it, a mirror sphere above, seen from above at an
    // angle: the spheres are bent by Snell's law at the plane.
    same("data/pov-glass-plane.json", 240, &[]);
    same("data/pov-glass-plane.json", 240, &["--shadows", "off"]);
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_comparison_catches_shadows_let_through_glass() {
    // A control: without the black copies that block the shadow rays, POV-Ray lets light
    // through the glass spheres (attenuated by their filCol), and phong's full shadows (docs/
    // conventions.md, "Transmission") must then differ from its image.
    if !povray_available() {
        return;
    }
    let pair = render_both_edited("data/pov-glass-checker.json", 160, &[], &[], |sdl| {
        let kept: Vec<&str> = sdl
            .lines()
            .filter(|l| !l.contains("no_image no_reflection"))
            .collect();
        assert!(
            kept.len() < sdl.lines().count(),
            "the export has shadow copies"
        );
        kept.join("\n").replace(" no_shadow", "")
    });
    let d = compare(&pair.phong, &pair.povray);
    assert!(d.over_one > 100, "{d:?}");
}

#[test]
#[ignore = "needs povray: apt-get install povray (.ci/run does)"]
fn the_comparison_catches_povrays_own_dimming_of_glass() {
    // A control: the grey glass's pigment (O_d = 0.02, T = 0.9) written as O_d itself, as a
    // plain export would, instead of O_d/(1 − T) = 0.2: POV-Ray then dims its diffuse light
    // by the opacity 1 − T, and the image must differ from phong's.
    if !povray_available() {
        return;
    }
    let pair = render_both_edited("data/pov-glass-checker.json", 160, &[], &[], |sdl| {
        let divided = "rgbt <0.20000000000000004, 0.20000000000000004, 0.20000000000000004, 0.9>";
        assert!(sdl.contains(divided), "the glass is exported as one layer");
        sdl.replace(divided, "rgbt <0.02, 0.02, 0.02, 0.9>")
    });
    let d = compare(&pair.phong, &pair.povray);
    assert!(d.over_one > 100, "{d:?}");
}

/// `phong export-pov` on `scenes/glass.json` changed by `edit`: its exit code and standard
/// error. (No POV-Ray needed: these are the export's own refusals.)
fn export_glass(edit: impl FnOnce(&mut Value), flags: &[&str]) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(scenes().join("glass.json")).unwrap();
    let mut v: Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    let path = dir.path().join("edited.json");
    std::fs::write(&path, serde_json::to_string_pretty(&v).unwrap()).unwrap();
    let out = support::phong_std()
        .arg("export-pov")
        .arg(&path)
        .args(flags)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn add_surface(v: &mut Value, surface: Value) {
    v["surfaces"].as_array_mut().unwrap().push(surface);
}

/// The refusal names the file, the place and why, and its fix.
fn assert_refused(got: (i32, String), place: &str, why: &str) {
    let (code, err) = got;
    assert_eq!(code, 2, "{err}");
    for part in [
        "edited.json",
        place,
        why,
        "cannot be expressed in POV-Ray 3.7",
        "Fix:",
    ] {
        assert!(err.contains(part), "{part:?} missing from: {err}");
    }
}

#[test]
fn export_refuses_a_transmitting_triangle() {
    let got = export_glass(
        |v| {
            add_surface(
                v,
                serde_json::json!({"type": "triangle", "vertices": [[3, 0.1, 3], [4, 0.1, 3],
                    [3, 1, 3]], "material": "glass"}),
            )
        },
        &[],
    );
    assert_refused(got, "surfaces[5]", "total internal reflection");
}

#[test]
fn export_refuses_an_eye_inside_a_glass_sphere() {
    let got = export_glass(
        |v| v["camera"]["eye"] = serde_json::json!([0.9, 0.65, 3.0]),
        &[],
    );
    assert_refused(got, "surfaces[4]", "the eye is inside");
}

#[test]
fn export_refuses_a_mirror_inside_a_glass_sphere_but_takes_a_matte_one() {
    let inside = |material: &str| {
        let material = material.to_owned();
        move |v: &mut Value| {
            add_surface(
                v,
                serde_json::json!({"type": "sphere", "center": [0.9, 0.65, 2.9], "radius": 0.2,
                    "material": material}),
            )
        }
    };
    assert_refused(
        export_glass(inside("mirror"), &[]),
        "surfaces[4]",
        "reaches inside this transmitting sphere",
    );
    let (code, err) = export_glass(inside("green"), &[]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn export_refuses_an_index_below_one() {
    let got = export_glass(|v| v["materials"]["glass"]["ior"] = Value::from(0.8), &[]);
    assert_refused(got, "material \"glass\": \"ior\"", "below 1");
}

#[test]
fn export_refuses_a_transmissivity_povray_would_not_trace() {
    // Greyscale 0.114 · 0.02 = 0.00228, below the minimum weight 1/255 ≈ 0.00392, which the
    // largest component 0.02 exceeds: phong traces the ray, POV-Ray would not.
    let dim = |v: &mut Value| {
        v["materials"]["glass"]["transmissivity"] = serde_json::json!([0, 0, 0.02]);
    };
    assert_refused(
        export_glass(dim, &[]),
        "material \"glass\": \"transmissivity\"",
        "greyscale",
    );
    // At level 1 no transmission ray is traced: nothing to refuse.
    let (code, err) = export_glass(dim, &["--max-level", "1"]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn export_refuses_a_glass_plane_seen_from_behind_or_over_a_mirror() {
    let water = |v: &mut Value| v["surfaces"][0]["material"] = Value::from("glass");
    // The mirror sphere stands on the floor, in front of it: accepted as it is.
    let (code, err) = export_glass(water, &[]);
    assert_eq!(code, 0, "{err}");
    let behind = |v: &mut Value| {
        water(v);
        v["camera"]["eye"] = serde_json::json!([0, -2.5, 8]);
    };
    assert_refused(
        export_glass(behind, &[]),
        "surfaces[0]",
        "the eye is behind",
    );
    let sunk = |v: &mut Value| {
        water(v);
        v["surfaces"][1]["center"] = serde_json::json!([0, 0.5, 0]);
    };
    assert_refused(export_glass(sunk, &[]), "surfaces[0]", "reaches behind");
}
