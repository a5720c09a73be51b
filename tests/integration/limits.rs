//! No crash, no clobbered file, every run bounded (issue 12): each test is one of the issue's
//! reproductions, run through the binary, with the outcome the README's "Limits and safety"
//! promises: a clear exit-2 error naming the flag or field and the valid range, or the correct
//! result.

use std::path::{Path, PathBuf};
use std::process::{Command as Std, Stdio};

use crate::support::{self, phong};
use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::json;
use tempfile::TempDir;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn exercise(name: &str) -> PathBuf {
    root().join("exercises").join(name)
}

/// A small scene: a sphere in front of the camera, 8×6 pixels.
fn small_scene() -> serde_json::Value {
    json!({
        "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
        "surfaces": [{ "type": "sphere", "center": [0, 0, 0], "radius": 1,
                       "material": { "ambient": [0.5, 0.5, 0.5] } }],
        "camera": { "eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45, "width": 8, "height": 6 }
    })
}

/// The small scene whose file asks for a tree no render may trace: `"max_level": 60,
/// "min_weight": 0` with a material that reflects and transmits (2^60 − 1 rays per sample).
fn deep_scene() -> serde_json::Value {
    let mut s = small_scene();
    s["surfaces"][0]["material"] = json!({
        "ambient": [0.5, 0.5, 0.5], "reflectivity": [0.5, 0.5, 0.5],
        "transmissivity": [0.5, 0.5, 0.5], "ior": 1.5
    });
    s["render"] = json!({ "max_level": 60, "min_weight": 0 });
    s
}

/// The small scene with the largest image a camera may have, 16384² pixels (1.6 GB of image).
fn huge_scene() -> serde_json::Value {
    let mut s = small_scene();
    s["camera"]["width"] = json!(16384);
    s["camera"]["height"] = json!(16384);
    s
}

/// phong under a 1 GiB address space (`ulimit -v`), less than a huge scene's image needs.
#[cfg(target_os = "linux")]
fn phong_in_1_gib() -> Std {
    let mut cmd = support::sh();
    cmd.arg("-c")
        .arg("ulimit -v 1048576; exec \"$0\" \"$@\"")
        .arg(support::phong_path());
    cmd
}

fn write(dir: &TempDir, name: &str, text: &str) -> PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn scene_file(dir: &TempDir, scene: &serde_json::Value) -> PathBuf {
    write(dir, "scene.json", &scene.to_string())
}

/// The small scene with a mesh read from `file` as its one surface.
fn mesh_scene(dir: &TempDir, file: &str) -> PathBuf {
    let mut s = small_scene();
    s["surfaces"] = json!([{ "type": "mesh", "file": file,
                             "material": { "ambient": [0.5, 0.5, 0.5] } }]);
    scene_file(dir, &s)
}

/// `phong render SCENE -o DIR/x.png`.
fn render(dir: &TempDir, scene: &Path) -> Command {
    let mut cmd = phong();
    cmd.arg("render")
        .arg(scene)
        .arg("-o")
        .arg(dir.path().join("x.png"));
    cmd
}

/// Exit 2 with every one of `says` in the error, and no panic.
fn refused(cmd: &mut Command, says: &[&str]) -> String {
    let out = cmd.output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    for s in says {
        assert!(err.contains(s), "expected {s:?} in: {err}");
    }
    err
}

// ---------------------------------------------------------------- crashes

#[test]
fn a_closed_standard_error_neither_panics_nor_costs_the_report() {
    let dir = TempDir::new().unwrap();
    let subs = write(&dir, "subs.csv", "ana,4.1,0.5 0.7 0.3\n");
    let report = dir.path().join("r.csv");
    // The reader of standard error is gone before phong writes to it (`2>&1 | true`).
    let mut child = support::phong_std()
        .arg("grade")
        .arg(&subs)
        .arg("--exercises")
        .arg(root().join("exercises"))
        .arg("-o")
        .arg(&report)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(0));
    let text = std::fs::read_to_string(&report).unwrap();
    assert_eq!(text.lines().count(), 2, "{text}");
    // An error message to a gone reader: still exit 2, not a panic's 101.
    let mut child = support::phong_std()
        .args(["solve", "no-such-file.json"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    assert_eq!(child.wait().unwrap().code(), Some(2));
}

#[test]
fn huge_counts_on_the_command_line_are_refused_with_their_range() {
    let dir = TempDir::new().unwrap();
    let scene = scene_file(&dir, &small_scene());
    refused(
        phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(["--size", "64x48", "--runs", "4294967295"]),
        &["--runs", "1 to 1000"],
    );
    refused(
        phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(["--runs", "100000000"]),
        &["--runs", "1 to 1000"],
    );
    refused(
        phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(["--reference-level", "4294967295"]),
        &["--reference-level", "1 to 1000"],
    );
    refused(
        phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(["--levels", "1,4294967295"]),
        &["--levels", "1 to 1000"],
    );
    let out = dir.path().join("x.png");
    for (flag, value, range) in [
        ("--threads", "100000", "1 to 1024"),
        ("--max-level", "4294967295", "1 to 1000"),
        ("--max-level", "1001", "1 to 1000"),
        ("--samples", "4294967296", "1 to 4096"),
    ] {
        refused(
            phong()
                .arg("render")
                .arg(&scene)
                .arg("-o")
                .arg(&out)
                .args([flag, value]),
            &[flag, range],
        );
    }
    // Explain-pixel on two facing mirrors with no weight limit: bounded by the level's range.
    refused(
        phong().arg("render").arg(&scene).args([
            "--explain-pixel",
            "4,3",
            "--max-level",
            "4294967295",
            "--min-weight",
            "0",
        ]),
        &["--max-level", "1 to 1000"],
    );
    assert!(!out.exists());
}

#[test]
fn an_explained_pixel_that_could_hold_too_many_rays_is_refused_before_anything_is_written() {
    // Four facing planes that reflect and transmit 0.9 (issue: the explanation grew to 23 GB).
    // The camera first looks along the planes, so the pixel's ray misses them all and a run
    // that is let through is cheap: the bound is on what the settings let the trees hold.
    // Minimum weight 0, every ray spawns two: level 14 lets one sample's tree hold
    // 2^14 − 1 = 16383 rays, more than the 8192 (2^13) an explanation may hold.
    let dir = TempDir::new().unwrap();
    let m = json!({ "ambient": [0.1, 0.1, 0.1], "diffuse": [0.3, 0.3, 0.3],
                    "specular": [0.2, 0.2, 0.2], "shininess": 5,
                    "reflectivity": [0.9, 0.9, 0.9], "transmissivity": [0.9, 0.9, 0.9],
                    "ior": 1 });
    let mut s = json!({
        "materials": { "G": m },
        "lights": [{ "type": "ambient", "color": [0.2, 0.2, 0.2] },
                   { "type": "point", "position": [0, 0, 0.5], "color": [1, 1, 1], "falloff": 0 }],
        "surfaces": [
            { "type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "G" },
            { "type": "plane", "point": [0, 0, 1], "normal": [0, 0, -1], "material": "G" },
            { "type": "plane", "point": [0, 0, -2], "normal": [0, 0, 1], "material": "G" },
            { "type": "plane", "point": [0, 0, 2], "normal": [0, 0, -1], "material": "G" }
        ],
        "camera": { "eye": [0, 0, 0], "look_at": [1, 0, 0], "fov": 30, "width": 1, "height": 1 },
        "render": { "max_level": 5, "min_weight": 0 }
    });
    let along = scene_file(&dir, &s);
    let out = dir.path().join("out.txt");
    let explain = |scene: &Path, settings: &[&str]| {
        let mut cmd = phong();
        cmd.arg("render")
            .arg(scene)
            .args(["--explain-pixel", "0,0", "-o"])
            .arg(&out)
            .args(settings);
        cmd
    };
    refused(
        &mut explain(&along, &["--max-level", "14"]),
        &[
            "--explain-pixel",
            "maximum level 14 with minimum weight 0",
            "16383 rays",
            "8192 (2^13)",
            "--min-weight",
        ],
    );
    assert!(!out.exists());
    // Level 13 holds 8191: explained.
    explain(&along, &["--max-level", "13"]).assert().success();
    std::fs::remove_file(&out).unwrap();
    // The issue's own settings, the camera looking into the planes: one sample's tree alone
    // may hold 2^20 − 1 = 1048575 rays, so no number of samples is small enough.
    s["camera"]["look_at"] = json!([0.1, 0, -1]);
    let into = write(&dir, "into.json", &s.to_string());
    let issue = [
        "--max-level",
        "20",
        "--min-weight",
        "0",
        "--samples",
        "4096",
    ];
    let err = refused(
        &mut explain(&into, &issue),
        &[
            "--explain-pixel",
            "maximum level 20 with minimum weight 0",
            "1048575 rays, more than the 8192 (2^13)",
        ],
    );
    assert!(
        err.contains("--max-level") && err.contains("--min-weight") && !err.contains("--samples"),
        "{err}"
    );
    // Level 10: 2^10 − 1 = 1023 rays a sample, 4096·1023 = 4190208 in all; 8·1023 = 8184 fit.
    let ten = [
        "--max-level",
        "10",
        "--min-weight",
        "0",
        "--samples",
        "4096",
    ];
    refused(
        &mut explain(&into, &ten),
        &[
            "--explain-pixel",
            "4096 samples of up to 1023 rays each",
            "4190208 rays",
            "at most 8 samples per pixel (--samples)",
            "--max-level",
            "--min-weight",
        ],
    );
    // In Portuguese too.
    refused(
        &mut explain(&into, &[&ten[..], &["--lang", "pt"]].concat()),
        &[
            "--explain-pixel",
            "4096 amostras de até 1023 raios cada",
            "que uma explicação pode ter",
            "dê até 8 amostras por pixel (--samples)",
        ],
    );
    assert!(!out.exists());
}

#[test]
fn a_huge_level_in_the_file_is_refused_naming_the_field() {
    let dir = TempDir::new().unwrap();
    let mut s = small_scene();
    s["render"] = json!({ "max_level": 4294967295u32 });
    let scene = scene_file(&dir, &s);
    refused(
        phong()
            .arg("render")
            .arg(&scene)
            .arg("-o")
            .arg(dir.path().join("x.png")),
        &["render.max_level", "1 to 1000"],
    );
}

#[test]
fn renders_and_sweeps_beyond_the_work_budget_are_refused_before_any_work() {
    let dir = TempDir::new().unwrap();
    let mut s = huge_scene();
    let big = scene_file(&dir, &s);
    let out = dir.path().join("x.png");
    // 16384² at 4096 samples: 1.1e12 primary rays, days of work.
    refused(
        phong()
            .arg("render")
            .arg(&big)
            .arg("-o")
            .arg(&out)
            .args(["--samples", "4096"]),
        &["--samples", "primary rays", "at most 4 samples per pixel"],
    );
    s["render"] = json!({ "samples": 4096 });
    let big = write(&dir, "big.json", &s.to_string());
    refused(
        phong().arg("render").arg(&big).arg("-o").arg(&out),
        &["render.samples", "primary rays"],
    );
    let small = write(&dir, "small.json", &small_scene().to_string());
    refused(
        phong()
            .arg("tradeoff")
            .arg(&small)
            .args(["--size", "16384x16384"]),
        &["--size", "primary rays"],
    );
    assert!(!out.exists());
}

#[test]
fn a_problem_or_mesh_file_that_never_ends_is_refused_by_its_size() {
    refused(
        phong().args(["solve", "/dev/zero"]),
        &["/dev/zero", "larger than 64 MiB", "smaller file"],
    );
    let dir = TempDir::new().unwrap();
    let scene = mesh_scene(&dir, "/dev/zero");
    refused(
        &mut render(&dir, &scene),
        &["surfaces[0].file", "larger than 256 MiB"],
    );
}

#[test]
fn too_many_lights_or_triangles_are_refused() {
    let dir = TempDir::new().unwrap();
    let lights: Vec<_> = (0..100_001)
        .map(|_| json!({ "type": "directional", "direction": [0, 0, -1], "color": [0, 0, 0] }))
        .collect();
    let p = json!({
        "lights": lights,
        "point": { "position": [0, 0, 0], "normal": [0, 0, 1],
                   "material": { "diffuse": [0.5, 0.5, 0.5] } }
    });
    let file = write(&dir, "lights.json", &p.to_string());
    refused(
        phong().args(["solve", "--format", "json"]).arg(&file),
        &["lights", "100000"],
    );
    refused(
        phong().arg("check").arg(&file).args(["--answer", "0 0 0"]),
        &["lights", "100000"],
    );
    // 1,000,001 triangles, from three vertices: refused at the line that passes the limit.
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for _ in 0..1_000_001 {
        obj.push_str("f 1 2 3\n");
    }
    write(&dir, "big.obj", &obj);
    let scene = mesh_scene(&dir, "big.obj");
    refused(
        &mut render(&dir, &scene),
        &["line 1000004", "more than 1000000 triangles"],
    );
}

#[test]
fn a_submissions_file_of_too_many_rows_is_refused_not_graded_out_of_memory() {
    let dir = TempDir::new().unwrap();
    let subs = write(&dir, "subs.csv", &"s,1,1\n".repeat(1_000_001));
    refused(
        phong()
            .arg("grade")
            .arg(&subs)
            .arg("--exercises")
            .arg(root().join("exercises")),
        &["subs.csv", "more than 1000000 rows", "smaller file"],
    );
}

// ---------------------------------------------------------------- messages

#[test]
fn an_obj_mistake_is_named_by_its_line() {
    let dir = TempDir::new().unwrap();
    let scene = mesh_scene(&dir, "m.obj");
    let render = |obj: &str, says: &[&str]| {
        write(&dir, "m.obj", obj);
        refused(&mut render(&dir, &scene), says)
    };
    let e = render(
        "# two vertices\nv 0 0 0\nv 1 0 0\nf 1 2\n",
        &["line 4", "f 1 2", "has 2 vertices"],
    );
    assert!(!e.contains("degenerate"), "{e}");
    render("v 0 0 0\nv 1 x 0\n", &["line 2", "v 1 x 0"]);
    render(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
        &["line 4", "vertex 9"],
    );
    render(
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
        &["line 4", "degenerate"],
    );
    render("v 0 0 0\nv 1e400 0 0\n", &["line 2", "not finite"]);
    // A line that is no OBJ statement was read past, shifting the vertices after it: `V` for
    // `v` made face 1 2 3 take the fourth vertex as its third.
    for (line, word) in [
        ("V -1 1 0", "`V`"),
        ("vv 0 1 0", "`vv`"),
        ("hello world", "`hello`"),
    ] {
        render(
            &format!("v 0 -1 -1\nv 1 0 0\n{line}\nv 0 1 0\nf 1 2 3\n"),
            &["line 3", line, word, "not an OBJ statement"],
        );
    }
}

/// A UTF-8 byte order mark before the first line (as some Windows editors save) is not part
/// of it: the first vertex was lost and every index after it shifted, so the face took the
/// fourth vertex, and the image differed from the same file without the mark.
#[test]
fn an_obj_files_byte_order_mark_is_not_its_first_line() {
    let dir = TempDir::new().unwrap();
    let obj = "v 0 -1 -1\nv 1 0 0\nv 0 1 0\nv -1 1 0\nf 1 2 3\n";
    let mut images = Vec::new();
    for (name, text) in [
        ("plain.obj", obj.to_owned()),
        ("bom.obj", format!("\u{feff}{obj}")),
    ] {
        write(&dir, name, &text);
        let scene = mesh_scene(&dir, name);
        let out = render(&dir, &scene).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{out:?}");
        images.push(std::fs::read(dir.path().join("x.png")).unwrap());
    }
    assert_eq!(images[0], images[1]);
}

#[test]
fn a_number_beyond_f64_is_said_to_be_out_of_range() {
    let one = exercise("4.1.json");
    refused(
        phong()
            .arg("check")
            .arg(&one)
            .args(["--answer", "1e400 0 0"]),
        &["1e400", "out of range"],
    );
    refused(
        phong()
            .arg("check")
            .arg(&one)
            .args(["--tolerance", "1e400"]),
        &["--tolerance", "1e400", "out of range"],
    );
    refused(
        phong()
            .arg("check")
            .arg(&one)
            .args(["--answer", "\u{2212}0.5 0.7 0.3"]),
        &["Unicode minus"],
    );
    refused(
        phong()
            .arg("check")
            .arg(&one)
            .args(["--answer", "\u{FF10}.5 0.7 0.3"]),
        &["full-width"],
    );
}

#[test]
fn a_long_answer_is_echoed_shortened() {
    // 100,001 characters: 25,000 times "0.5 ", then "0".
    let answer = format!("{}0", "0.5 ".repeat(25_000));
    let err = refused(
        phong()
            .arg("check")
            .arg(exercise("4.1.json"))
            .args(["--answer", &answer]),
        &["100001 characters"],
    );
    assert!(err.len() < 2_000, "{} bytes of error", err.len());
}

// ---------------------------------------------------------------- files

#[test]
fn an_output_that_is_a_folder_is_said_to_be_one() {
    let dir = TempDir::new().unwrap();
    refused(
        phong().current_dir(dir.path()).args(["schema", "-o", "."]),
        &["cannot write .", "it is a folder"],
    );
}

#[test]
fn an_output_that_is_an_input_or_another_output_is_refused_and_nothing_is_written() {
    let dir = TempDir::new().unwrap();
    let subs = write(&dir, "subs.csv", "ana,4.1,0.5 0.7 0.3\n");
    refused(
        phong()
            .arg("grade")
            .arg(&subs)
            .arg("--exercises")
            .arg(root().join("exercises"))
            .arg("-o")
            .arg(&subs),
        &["--output", "is the input"],
    );
    assert_eq!(
        std::fs::read_to_string(&subs).unwrap(),
        "ana,4.1,0.5 0.7 0.3\n"
    );
    let r = dir.path().join("r.csv");
    refused(
        phong()
            .arg("grade")
            .arg(&subs)
            .arg("--exercises")
            .arg(root().join("exercises"))
            .arg("-o")
            .arg(&r)
            .arg("--summary")
            .arg(dir.path().join(".").join("r.csv")),
        &["--output and --summary are the same file"],
    );
    assert!(!r.exists());
    let problem = write(
        &dir,
        "p.json",
        &std::fs::read_to_string(exercise("4.1.json")).unwrap(),
    );
    refused(
        phong().arg("solve").arg(&problem).arg("-o").arg(&problem),
        &["--output", "is the input"],
    );
    assert!(std::fs::read_to_string(&problem)
        .unwrap()
        .contains("Exercise 4.1"));
}

#[cfg(unix)]
#[test]
fn a_fifo_is_written_into_not_replaced() {
    use std::io::Read;
    use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
    let dir = TempDir::new().unwrap();
    let fifo = dir.path().join("fifo");
    assert!(Std::new("mkfifo").arg(&fifo).status().unwrap().success());
    // Opened for reading without waiting for a writer (O_NONBLOCK), so phong's open succeeds.
    let mut reader = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(0o4000)
        .open(&fifo)
        .unwrap();
    phong()
        .arg("solve")
        .arg(exercise("4.1.json"))
        .args(["--format", "json", "-o"])
        .arg(&fifo)
        .assert()
        .code(0);
    assert!(std::fs::symlink_metadata(&fifo)
        .unwrap()
        .file_type()
        .is_fifo());
    let mut got = String::new();
    reader.read_to_string(&mut got).unwrap();
    assert!(got.contains("\"format_version\""), "{got}");
}

#[cfg(unix)]
#[test]
fn a_link_stays_a_link_and_its_target_is_written() {
    let dir = TempDir::new().unwrap();
    let target = write(&dir, "target.json", "old");
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink("target.json", &link).unwrap();
    phong().arg("schema").arg("-o").arg(&link).assert().code(0);
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read_to_string(&target)
        .unwrap()
        .contains("\"$schema\""));
    // Nothing left beside it.
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".tmp") || n.starts_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
}

#[cfg(unix)]
#[test]
fn a_new_file_follows_the_umask_and_an_existing_one_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = TempDir::new().unwrap();
    let new = dir.path().join("new.json");
    let status = support::sh()
        .arg("-c")
        .arg("umask 077; exec \"$0\" schema -o \"$1\"")
        .arg(support::phong_path())
        .arg(&new)
        .status()
        .unwrap();
    assert!(status.success());
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&new), 0o600);
    let old = write(&dir, "old.json", "x");
    std::fs::set_permissions(&old, std::fs::Permissions::from_mode(0o640)).unwrap();
    phong().arg("schema").arg("-o").arg(&old).assert().code(0);
    assert_eq!(mode(&old), 0o640);
}

#[test]
fn a_dash_reads_standard_input() {
    let text = std::fs::read_to_string(exercise("4.1.json")).unwrap();
    phong()
        .args(["solve", "--format", "json", "-"])
        .write_stdin(text.clone())
        .assert()
        .code(0)
        .stdout(predicate::str::contains("\"format_version\""));
    phong()
        .args(["check", "-", "--answer", "0.5 0.7 0.3"])
        .write_stdin(text)
        .assert()
        .code(0);
    phong()
        .args(["grade", "-", "--exercises"])
        .arg(root().join("exercises"))
        .write_stdin("ana,4.1,0.5 0.7 0.3\n")
        .assert()
        .code(0)
        .stdout(predicate::str::contains("ana,4.1,0.5 0.7 0.3,right"));
}

#[test]
fn a_write_over_the_file_size_limit_fails_cleanly_and_leaves_no_temporary_file() {
    // SIGXFSZ while a report is written left a `.tmpXXXXXX` beside the target (issue 12). Under
    // `ulimit -f 1` (one block: 512 bytes in sh, 1 KiB in bash) the HTML explanation of 4.2
    // (tens of kB) cannot be written: the write fails with EFBIG instead of killing the process,
    // the temporary file is removed, and the existing target is left as it was.
    let dir = TempDir::new().unwrap();
    let target = write(&dir, "out.html", "the previous report\n");
    let out = support::sh()
        .arg("-c")
        .arg("ulimit -f 1 && exec \"$0\" solve \"$1\" --format html -o \"$2\"")
        .arg(support::phong_path())
        .arg(exercise("4.2.json"))
        .arg(&target)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.starts_with("error: "), "{stderr}");
    assert!(stderr.contains("out.html"), "{stderr}");
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(left, ["out.html"], "nothing beside the target");
    assert_eq!(
        std::fs::read_to_string(&target).unwrap(),
        "the previous report\n"
    );
}

/// Whether `phong schema`'s JSON Schema accepts `doc`.
fn schema_accepts(doc: &serde_json::Value) -> bool {
    let out = phong().arg("schema").output().unwrap();
    let schema: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    jsonschema::validator_for(&schema).unwrap().is_valid(doc)
}

#[test]
fn the_schema_and_the_validator_agree_at_the_bounds_of_the_image_and_the_render() {
    // The README and the fields' descriptions give the ranges: width and height 1 to 16384,
    // max_level 1 to 1000, samples 1 to 4096. A validator driven by the schema must refuse what
    // phong refuses there (the schema once said "minimum": 0 for each).
    let dir = TempDir::new().unwrap();
    let cases: [(&str, &str, u32, bool); 12] = [
        ("camera", "width", 0, false),
        ("camera", "width", 1, true),
        ("camera", "width", 16385, false),
        ("camera", "height", 0, false),
        ("camera", "height", 16384, true),
        ("camera", "height", 16385, false),
        ("render", "max_level", 0, false),
        ("render", "max_level", 1000, true),
        ("render", "max_level", 1001, false),
        ("render", "samples", 0, false),
        ("render", "samples", 4096, true),
        ("render", "samples", 4097, false),
    ];
    for (object, field, value, valid) in cases {
        let mut scene = small_scene();
        if object == "render" {
            scene["render"] = json!({});
        }
        scene[object][field] = json!(value);
        assert_eq!(
            schema_accepts(&scene),
            valid,
            "schema, {object}.{field} = {value}"
        );
        let path = write(&dir, "s.json", &scene.to_string());
        // One pixel explained: the file is read and validated whole, and little is traced.
        let ok = phong()
            .arg("render")
            .arg(&path)
            .args(["--explain-pixel", "0,0", "--format", "json"])
            .output()
            .unwrap()
            .status
            .success();
        assert_eq!(ok, valid, "phong, {object}.{field} = {value}");
    }
}

/// A class in `dir`: an exercises folder `ex` holding exercise 4.1, and one student's answer
/// to it, `subs.csv`.
fn a_class(dir: &TempDir) -> (PathBuf, PathBuf) {
    let ex = dir.path().join("ex");
    std::fs::create_dir(&ex).unwrap();
    std::fs::copy(exercise("4.1.json"), ex.join("4.1.json")).unwrap();
    (ex, write(dir, "subs.csv", "ana,4.1,0.5 0.7 0.3\n"))
}

/// `phong grade SUBS --exercises EX -o OUT`, refused as an output naming an input.
fn grade_into_an_input(subs: &Path, ex: &Path, out: &Path) {
    refused(
        phong()
            .arg("grade")
            .arg(subs)
            .arg("--exercises")
            .arg(ex)
            .arg("-o")
            .arg(out),
        &["--output", "is the input"],
    );
}

#[test]
fn a_grade_output_may_not_replace_an_exercise_it_grades_against() {
    // `phong grade … --exercises ex -o ex/4.1.json` would replace the exercise with the report.
    let dir = TempDir::new().unwrap();
    let (ex, subs) = a_class(&dir);
    let original = std::fs::read_to_string(exercise("4.1.json")).unwrap();
    grade_into_an_input(&subs, &ex, &ex.join("4.1.json"));
    assert_eq!(
        std::fs::read_to_string(ex.join("4.1.json")).unwrap(),
        original
    );
}

/// `sh -c script` in `dir` with `$PHONG` the binary and `$EX` exercise 4.1; its exit code.
fn shell(dir: &Path, script: &str) -> Option<i32> {
    support::sh()
        .arg("-c")
        .arg(script)
        .current_dir(dir)
        .env("PHONG", support::phong_path())
        .env("EX", exercise("4.1.json"))
        .env("SUBS", "subs.csv")
        .stdin(Stdio::null())
        .status()
        .unwrap()
        .code()
}

/// Issue 30, item 2: `-o /dev/stdout` (or `/dev/stderr`, `/proc/self/fd/N`, `-`) writes into the
/// stream, after what it holds and in order with what comes next; it never replaces the file
/// the stream is redirected to (`>> app.log` lost "old").
#[test]
fn an_output_naming_a_stream_is_written_into_it_in_order() {
    let dir = TempDir::new().unwrap();
    let report = phong()
        .arg("solve")
        .arg(exercise("4.1.json"))
        .output()
        .unwrap();
    assert!(report.status.success());
    let report = String::from_utf8(report.stdout).unwrap();
    assert!(report.len() > 100, "{report}");
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).unwrap();
    for (target, redirect) in [
        ("/dev/stdout", ">>"),
        ("-", ">>"),
        ("/proc/self/fd/1", ">>"),
        ("/dev/fd/1", ">>"),
        ("/proc/self/fd/3", "3>>"),
        ("/dev/stderr", "2>>"),
    ] {
        std::fs::write(dir.path().join("app.log"), "old\n").unwrap();
        let code = shell(
            dir.path(),
            &format!("\"$PHONG\" solve \"$EX\" -o {target} {redirect} app.log"),
        );
        assert_eq!(code, Some(0), "-o {target} {redirect} app.log");
        let got = read("app.log");
        assert!(
            got.starts_with("old\n") && got[4..].starts_with(&report),
            "-o {target} {redirect} app.log: {got}"
        );
        if target != "/dev/stderr" {
            assert_eq!(
                got,
                format!("old\n{report}"),
                "-o {target} {redirect} app.log"
            );
        }
    }
    // A group's output, in order: the line before, the report, the line after.
    let code = shell(
        dir.path(),
        "{ echo BEFORE; \"$PHONG\" solve \"$EX\" -o /dev/stdout; echo AFTER; } > c.txt",
    );
    assert_eq!(code, Some(0));
    assert_eq!(read("c.txt"), format!("BEFORE\n{report}AFTER\n"));
    // Two outputs of one run on the stream (standard output a file): both written, in order,
    // not refused as one file replacing the other.
    std::fs::write(
        dir.path().join("subs.csv"),
        "student,exercise,answer\nana,4.1,0.5 0.7 0.3\n",
    )
    .unwrap();
    let code = shell(
        dir.path(),
        &format!(
            "echo old > both.txt; \"$PHONG\" grade \"$SUBS\" --exercises {} -o /dev/stdout \
             --summary /dev/stdout >> both.txt",
            root().join("exercises").display()
        ),
    );
    assert_eq!(code, Some(0));
    let both = read("both.txt");
    let lines: Vec<&str> = both.lines().collect();
    assert_eq!(lines[0], "old", "{both}");
    assert!(lines[1].starts_with("row,line,student,"), "{both}");
    assert!(lines[2].starts_with("1,2,ana,4.1,"), "{both}");
    assert!(lines[3].starts_with("exercise,rows,right,"), "{both}");
    assert_eq!(lines[4], "4.1,1,1,0,0,0,", "{both}");
    assert_eq!(lines.len(), 5, "{both}");
}

/// An OBJ corner too large for the ray–triangle test of the precision is refused as too large,
/// with the bound that works: at ±1e308 the face was said to be degenerate (its edges
/// overflowed), at ±1e300 the mesh was rendered and every ray missed it.
#[test]
fn an_obj_corner_too_large_for_the_precision_is_refused_with_the_bound() {
    let dir = TempDir::new().unwrap();
    let scene = mesh_scene(&dir, "m.obj");
    let face = |x: &str| format!("v -{x} -{x} 0\nv {x} -{x} 0\nv 0 {x} 0\nf 1 2 3\n");
    for x in ["1e308", "1e300"] {
        write(&dir, "m.obj", &face(x));
        let e = refused(
            &mut render(&dir, &scene),
            &[
                "surfaces[0].file",
                "vertex 1",
                "too large for a triangle in f64",
                "within ±1e100",
            ],
        );
        assert!(
            !e.contains("degenerate") && !e.contains("--precision"),
            "{e}"
        );
    }
    write(&dir, "m.obj", &face("1e13"));
    refused(
        render(&dir, &scene).args(["--precision", "f32"]),
        &["vertex 1", "within ±1e12", "--precision f64"],
    );
    render(&dir, &scene).assert().success();
}
/// A file that cannot be created where the user asked (`/proc` and `/sys` refuse any new file,
/// root's too) is said of the path given, never of the temporary file written first
/// (`at path "/proc/.phong-Ab12Cd.tmp"`, a name the user never gave), and in the user's
/// language.
#[cfg(target_os = "linux")]
#[test]
fn an_output_that_cannot_be_created_is_named_as_given_not_by_its_temporary_file() {
    let dir = TempDir::new().unwrap();
    let scene = scene_file(&dir, &small_scene());
    let subs = write(&dir, "subs.csv", "ana,4.1,0.5 0.7 0.3\n");
    for folder in ["/proc", "/sys"] {
        if !Path::new(folder).is_dir() {
            continue;
        }
        for (name, args) in [
            ("x.txt", vec![exercise("4.1.json").display().to_string()]),
            ("x.png", vec![scene.display().to_string()]),
            (
                "r.csv",
                vec![
                    subs.display().to_string(),
                    "--exercises".to_owned(),
                    root().join("exercises").display().to_string(),
                ],
            ),
        ] {
            let command = match name {
                "x.txt" => "solve",
                "x.png" => "render",
                _ => "grade",
            };
            let out = format!("{folder}/{name}");
            for (lang, says) in [
                ("en", format!("cannot write {out}: ")),
                ("pt", format!("não é possível escrever {out}: ")),
            ] {
                let err = refused(
                    phong()
                        .arg(command)
                        .args(&args)
                        .args(["-o", &out, "--lang", lang]),
                    &[&says],
                );
                assert!(
                    !err.contains(".phong-") && !err.contains("at path"),
                    "{command} -o {out}: {err}"
                );
                if lang == "pt" {
                    assert!(err.contains("do sistema)"), "{command} -o {out}: {err}");
                }
            }
        }
    }
}
/// `phong check`, `phong policy` and `phong serve` read a course policy as `grade` and `moodle`
/// do: it is an input of theirs, and an output naming it (the folder's `course-policy.json` or
/// the file of `--policy`) is refused before anything is written. `check -o
/// ex/course-policy.json` replaced the policy with the check's report.
#[test]
fn an_output_may_not_replace_the_course_policy_the_run_reads() {
    let dir = TempDir::new().unwrap();
    let (ex, subs) = a_class(&dir);
    let policy = "{\"reading_credit\": 0.25, \"comment\": \"the course's own\"}\n";
    let beside = ex.join("course-policy.json");
    std::fs::write(&beside, policy).unwrap();
    let given = write(&dir, "policy.json", policy);
    let check = |policy_flag: Option<&Path>, out: &Path| {
        let mut cmd = phong();
        cmd.arg("check")
            .arg(ex.join("4.1.json"))
            .args(["--answer", "0.5 0.7 0.3"]);
        if let Some(p) = policy_flag {
            cmd.arg("--policy").arg(p);
        }
        cmd.arg("-o").arg(out);
        cmd
    };
    refused(&mut check(None, &beside), &["--output", "is the input"]);
    refused(
        &mut check(Some(&given), &given),
        &["--output", "is the input"],
    );
    let policy_cmd = |policy_flag: Option<&Path>, out: &Path| {
        let mut cmd = phong();
        cmd.arg("policy").arg(&ex);
        if let Some(p) = policy_flag {
            cmd.arg("--policy").arg(p);
        }
        cmd.arg("-o").arg(out);
        refused(&mut cmd, &["--output", "is the input"]);
    };
    policy_cmd(None, &beside);
    policy_cmd(Some(&given), &given);
    // grade and moodle refused it already: held to it.
    grade_into_an_input(&subs, &ex, &beside);
    refused(
        phong()
            .arg("moodle")
            .arg(ex.join("4.1.json"))
            .arg("-o")
            .arg(&beside),
        &["--output", "is the input"],
    );
    // serve appends its answers to --log-answers (and renames it when full): refused before it
    // listens (a server let through would run until the timeout).
    #[cfg(feature = "serve")]
    for (policy_flag, log) in [(None, &beside), (Some(&given), &given)] {
        let mut cmd = phong();
        cmd.arg("serve")
            .arg("--exercises")
            .arg(&ex)
            .args(["--addr", "127.0.0.1:0"]);
        if let Some(p) = policy_flag {
            cmd.arg("--policy").arg(p);
        }
        cmd.arg("--log-answers")
            .arg(log)
            .timeout(std::time::Duration::from_secs(20));
        refused(&mut cmd, &["--log-answers", "is the input"]);
    }
    assert_eq!(std::fs::read_to_string(&beside).unwrap(), policy);
    assert_eq!(std::fs::read_to_string(&given).unwrap(), policy);
}
/// `phong serve --exercises EX --log-answers EX/4.1.json` appended each checked answer to the
/// exercise it serves (the next start refused the file: "trailing characters"): an exercise
/// file is an input of the server as its course policy is, refused before it listens, in
/// English and Portuguese, the file left as it was.
#[cfg(feature = "serve")]
#[test]
fn serve_may_not_log_answers_into_an_exercise_file() {
    let dir = TempDir::new().unwrap();
    let (ex, _) = a_class(&dir);
    let exercise = ex.join("4.1.json");
    let before = std::fs::read_to_string(&exercise).unwrap();
    let serve = |log: &Path, lang: &str| {
        let mut cmd = phong();
        cmd.arg("serve")
            .arg("--exercises")
            .arg(&ex)
            .args(["--addr", "127.0.0.1:0", "--log-answers"])
            .arg(log)
            .env("LANG", lang)
            .timeout(std::time::Duration::from_secs(20));
        cmd
    };
    let en = refused(
        &mut serve(&exercise, "C"),
        &["--log-answers", "is the input"],
    );
    assert!(en.contains("4.1.json"), "{en}");
    refused(
        &mut serve(&exercise, "pt_BR.UTF-8"),
        &["--log-answers", "é a entrada", "4.1.json"],
    );
    assert_eq!(std::fs::read_to_string(&exercise).unwrap(), before);
    // A full log is renamed to PATH.1, replacing what is there: that may not be an input either
    // (the course policy at rules.json.1 beside a log at rules.json).
    let policy = write(&dir, "rules.json.1", "{}\n");
    let err = refused(
        serve(&dir.path().join("rules.json"), "C")
            .arg("--policy")
            .arg(&policy),
        &["--log-answers", "is the input"],
    );
    assert!(err.contains("rules.json.1"), "{err}");
    assert_eq!(std::fs::read_to_string(&policy).unwrap(), "{}\n");
}

/// `phong check --steps FILE -o FILE` would replace the steps it reads with its report: refused
/// as any output naming an input, the file left as it was.
#[test]
fn a_check_output_may_not_replace_its_steps_file() {
    let dir = TempDir::new().unwrap();
    let steps = write(&dir, "steps.json", "{\"cos_theta\": 0.98995}\n");
    refused(
        phong()
            .arg("check")
            .arg(exercise("4.2.json"))
            .arg("--steps")
            .arg(&steps)
            .arg("-o")
            .arg(&steps),
        &["--output", "is the input"],
    );
    assert_eq!(
        std::fs::read_to_string(&steps).unwrap(),
        "{\"cos_theta\": 0.98995}\n"
    );
}

/// `phong render`'s flags are over the file's settings before the image is held to its bounds:
/// a file of maximum level 60 and minimum weight 0 over a material that reflects and transmits
/// (2^60 − 1 rays in one sample's tree, past the 2^20 a tree may hold) renders with
/// `--max-level 3` (at most 2^3 − 1 = 7 rays); it was refused for the file's 60. A bound passed
/// is said of what set it: the file's field, or the flag.
#[test]
fn a_renders_flags_are_over_the_files_settings_before_its_bounds() {
    let dir = TempDir::new().unwrap();
    let mut s = small_scene();
    s["surfaces"][0]["material"] = json!({
        "ambient": [0.5, 0.5, 0.5], "reflectivity": [0.5, 0.5, 0.5],
        "transmissivity": [0.5, 0.5, 0.5], "ior": 1.5
    });
    s["render"] = json!({ "max_level": 60, "min_weight": 0 });
    let deep = scene_file(&dir, &s);
    let out = dir.path().join("deep.png");
    refused(
        phong().arg("render").arg(&deep).arg("-o").arg(&out),
        &["render.max_level: maximum level 60"],
    );
    phong()
        .arg("render")
        .arg(&deep)
        .arg("-o")
        .arg(&out)
        .args(["--max-level", "3"])
        .assert()
        .success();
    assert!(out.exists());
    refused(
        phong()
            .arg("render")
            .arg(&deep)
            .arg("-o")
            .arg(dir.path().join("deeper.png"))
            .args(["--max-level", "40"]),
        &["--max-level: maximum level 40"],
    );
}

/// `phong tradeoff` sets every render's maximum level, minimum weight and samples (its sweep
/// and its reference) and may set the image's size (`--size`): the file's own render settings
/// are never traced, so they do not hold the scene to the image's bounds, as `render`'s flags
/// go over them. A file of maximum level 60 and minimum weight 0 over a material that reflects
/// and transmits (2^60 − 1 rays in one sample's tree, past 2^20) was refused at load
/// ("render.max_level: maximum level 60") though the sweep traced levels 1 to 3, and a 16384²
/// camera at 8 samples (2^31 primary rays, past 2^30) though `--size 8x6` at 1 sample is
/// 48 rays. Both sweep; the sweep's own settings past a bound are refused naming their flags.
#[test]
fn a_tradeoff_holds_the_scene_to_its_sweeps_settings_not_the_files() {
    let dir = TempDir::new().unwrap();
    let deep = write(&dir, "deep.json", &deep_scene().to_string());
    let mut big = huge_scene();
    big["render"] = json!({ "samples": 8 });
    let big = write(&dir, "big.json", &big.to_string());
    let tradeoff = |scene: &Path, levels: &str, reference: &str| {
        let mut cmd = phong();
        cmd.arg("tradeoff")
            .arg(scene)
            .args(["--size", "8x6", "--runs", "1", "--precisions", "f64"])
            .args(["--levels", levels, "--min-weights", "0", "--samples", "1"])
            .args(["--reference-level", reference, "--reference-samples", "1"])
            .args(["--format", "csv"]);
        cmd
    };
    for scene in [&deep, &big] {
        let out = tradeoff(scene, "1,2", "3").output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{scene:?}: {stderr}");
        assert!(!String::from_utf8_lossy(&out.stdout).is_empty());
    }
    // The sweep's own trees are held to the bound, each said of its flag: at level 40 a tree
    // may hold 2^40 − 1 rays.
    let err = refused(
        &mut tradeoff(&deep, "1,40", "3"),
        &["levels", "maximum level 40"],
    );
    assert!(!err.contains("render.max_level"), "{err}");
    let err = refused(
        &mut tradeoff(&deep, "1,2", "40"),
        &["--reference-level", "40"],
    );
    assert!(!err.contains("render.max_level"), "{err}");
}

/// `phong export-pov`, as `phong render`: the flags' settings over the file's, then the bounds.
/// A scene whose file says `"max_level": 60, "min_weight": 0` with a material that reflects and
/// transmits (a tree of 2^60 rays per sample) is exported with `--max-level 3` (7 rays), where
/// it was refused for the file's own level; without the flag it is refused naming the file's
/// field, and with `--max-level 40` naming the flag.
#[test]
fn export_pov_holds_the_scene_to_the_settings_in_force() {
    let dir = TempDir::new().unwrap();
    let deep = write(&dir, "deep.json", &deep_scene().to_string());
    let pov = dir.path().join("deep.pov");
    let export = |extra: &[&str]| {
        let mut cmd = phong();
        cmd.arg("export-pov")
            .arg(&deep)
            .arg("-o")
            .arg(&pov)
            .args(extra);
        cmd
    };
    let out = export(&["--max-level", "3"]).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sdl = std::fs::read_to_string(&pov).unwrap();
    assert!(sdl.contains("max_trace_level 3"), "{sdl}");
    std::fs::remove_file(&pov).unwrap();
    refused(&mut export(&[]), &["render.max_level", "maximum level 60"]);
    let err = refused(
        &mut export(&["--max-level", "40"]),
        &["max-level", "maximum level 40"],
    );
    assert!(!err.contains("render.max_level"), "{err}");
    assert!(!pov.exists());
}

/// A render whose image the system cannot give (16384² pixels, 6 bytes each: 1.6 GB, under a
/// 1 GiB address space) is refused with exit 2, and its fix names what sets a render's image, the
/// camera's "width" and "height": `render` has no `--size` (only `tradeoff` has), though the fix
/// said to give a smaller one.
#[cfg(target_os = "linux")]
#[test]
fn a_render_out_of_memory_names_the_cameras_size_not_a_flag_it_lacks() {
    let dir = TempDir::new().unwrap();
    let mut s = huge_scene();
    s["render"] = json!({ "samples": 1 });
    let big = scene_file(&dir, &s);
    let out = phong_in_1_gib()
        .arg("render")
        .arg(&big)
        .arg("-o")
        .arg(dir.path().join("big.png"))
        .args(["--threads", "1"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("out of memory: this needs about 1.6 GB"),
        "{err}"
    );
    assert!(
        err.contains("give a smaller image (the camera's \"width\" and \"height\""),
        "{err}"
    );
    assert!(!err.contains("--size"), "{err}");
    assert!(!dir.path().join("big.png").exists());
}

/// `--explain-pixel` traces one pixel's rays and nothing else: the image's own bounds (its
/// primary rays within 2^30, its buffer within memory) are not the pixel's, which is bounded by
/// its own (2^13 rays in all its samples, and inside the image). A 16384² image at 8 samples
/// (2^31 primary rays) was refused for the whole image's work; at one sample, under a 1 GiB
/// address space, for the 1.6 GB image it never makes.
#[test]
fn an_explained_pixel_is_held_to_its_own_bounds_not_the_images() {
    let dir = TempDir::new().unwrap();
    let mut s = huge_scene();
    s["render"] = json!({ "samples": 8 });
    let big = scene_file(&dir, &s);
    // The image itself stays refused.
    refused(&mut render(&dir, &big), &["render.samples", "primary rays"]);
    let explain = |scene: &Path, args: &[&str]| {
        let mut cmd = phong();
        cmd.arg("render")
            .arg(scene)
            .args(["--explain-pixel", "8192,8192", "--format", "json"])
            .args(args);
        cmd
    };
    for precision in ["f64", "f32"] {
        let out = explain(&big, &["--precision", precision]).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{precision}: {err}");
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(
            doc["samples"].as_array().map(Vec::len),
            Some(8),
            "{precision}"
        );
        // In f32, the same pixel in f64 beside it: the scene read again in f64 for the pixel.
        assert_eq!(
            doc["versus_f64"].is_object(),
            precision == "f32",
            "{precision}"
        );
    }
    // --samples over the file's: 64 samples of a one-ray tree fit the 8192 rays an explanation
    // may hold, though 16384² × 64 primary rays are far past a render's.
    explain(&big, &["--samples", "64"]).assert().success();
    // The pixel must still be inside the image (the bound on its rays:
    // an_explained_pixel_that_could_hold_too_many_rays_is_refused_before_anything_is_written).
    refused(
        phong()
            .arg("render")
            .arg(&big)
            .args(["--explain-pixel", "16384,0"]),
        &["--explain-pixel", "outside the 16384×16384 image"],
    );
    // Nothing is allocated by the image's size: one sample's pixel under a 1 GiB address space.
    #[cfg(target_os = "linux")]
    {
        s["render"] = json!({ "samples": 1 });
        let one = write(&dir, "one.json", &s.to_string());
        let out = phong_in_1_gib()
            .arg("render")
            .arg(&one)
            .args(["--explain-pixel", "8192,8192", "--threads", "1"])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{err}");
        assert!(
            String::from_utf8_lossy(&out.stdout).contains("8192"),
            "{err}"
        );
    }
}
