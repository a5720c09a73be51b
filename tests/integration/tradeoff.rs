//! `phong tradeoff` end to end through the binary: errors, rays and budgets worked out by hand on
//! a scene whose every pixel has a closed form (two facing mirrors); the 8-bit share checked
//! against images written by `phong render`; the same numbers for any thread count; the table,
//! CSV and plot, in English and in Portuguese; bad flags refused with exit code 2 and nothing
//! written.

use std::fs;
use std::path::{Path, PathBuf};

use crate::support::phong;
use serde_json::{json, Value};
use tempfile::TempDir;

const BAD_INPUT: i32 = 2;

fn write(dir: &TempDir, name: &str, v: &Value) -> PathBuf {
    let p = dir.path().join(name);
    fs::write(&p, serde_json::to_string_pretty(v).unwrap()).unwrap();
    p
}

/// Runs `phong tradeoff SCENE --format json ARGS…` and returns the document.
fn tradeoff_json(scene: &Path, args: &[&str]) -> Value {
    let out = phong()
        .arg("tradeoff")
        .arg(scene)
        .args(["--format", "json"])
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "phong tradeoff failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The camera, at z = 1 between the mirrors z = 0 and z = 2, looks straight down; every ray
/// bounces between them for ever. Each mirror has O_a = 1 and O_r = 0.5; the only light is an
/// ambient 0.1 and the background is black. A path of m rays (levels 1..m) sees
/// C_m = Σ_{k<m} 0.5^k · 0.1 = 0.2·(1 − 0.5^m) in every pixel, whatever the sample position.
fn mirrors(dir: &TempDir) -> PathBuf {
    let m = json!({ "ambient": [1, 1, 1], "reflectivity": [0.5, 0.5, 0.5] });
    let scene = json!({
        "lights": [{ "type": "ambient", "color": [0.1, 0.1, 0.1] }],
        "surfaces": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": m },
            { "type": "plane", "point": [0, 0, 2], "normal": [0, 0, 1], "material": m }
        ],
        "camera": { "eye": [0, 0, 1], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 30,
                    "width": 4, "height": 3 }
    });
    write(dir, "mirrors.json", &scene)
}

/// The number of rays a path traces at maximum level n and minimum weight w: ray k (weight
/// 0.5^(k−1)) is traced while k ≤ n and, for k > 1, 0.5^(k−1) > w.
fn path_length(n: u32, w: f64) -> u32 {
    (1..=n)
        .take_while(|&k| k == 1 || 0.5f64.powi(k as i32 - 1) > w)
        .count() as u32
}

/// The bundled classic scene at `width`×`height`, written into `dir`.
fn classic_at(dir: &TempDir, width: u32, height: u32) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut classic: Value =
        serde_json::from_str(&fs::read_to_string(root.join("scenes/classic.json")).unwrap())
            .unwrap();
    classic["camera"]["width"] = json!(width);
    classic["camera"]["height"] = json!(height);
    write(dir, "classic.json", &classic)
}

#[test]
fn errors_rays_and_the_budget_match_the_closed_form_of_two_mirrors() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let doc = tradeoff_json(
        &scene,
        &[
            "--levels",
            "1,3,7",
            "--min-weights",
            "0,0.1",
            "--samples",
            "1,2",
            "--runs",
            "2",
            "--reference-level",
            "64",
            "--reference-samples",
            "2",
            "--metric",
            "max-abs",
            "--budget",
            "1/255",
        ],
    );
    // The reference: 64 rays, C = 0.2·(1 − 0.5^64), which is 0.2 to within 1e-20.
    let pixels = 12u64;
    assert_eq!(doc["reference"]["rays"]["primary"], pixels * 2);
    assert_eq!(doc["reference"]["rays"]["reflection"], pixels * 2 * 63);
    let settings = doc["settings"].as_array().unwrap();
    assert_eq!(settings.len(), 2 * 3 * 2 * 2, "every combination once");
    let mut within = Vec::new();
    for (i, row) in settings.iter().enumerate() {
        let s = &row["setting"];
        let n = s["max_level"].as_u64().unwrap() as u32;
        let w = s["min_weight"].as_f64().unwrap();
        let spp = s["samples"].as_u64().unwrap();
        let m = path_length(n, w);
        // Every channel of every pixel is off by 0.2 − C_m = 0.2·0.5^m, so the max and the
        // RMSE are that, and PSNR = −20·log10 of it.
        let expected = 0.2 * 0.5f64.powi(m as i32);
        let tol = if s["precision"] == "f32" { 1e-6 } else { 1e-14 };
        let e = &row["errors"];
        for key in ["max_abs", "rmse"] {
            let got = e[key].as_f64().unwrap();
            assert!(
                (got - expected).abs() <= tol,
                "{key} of {s}: {got}, by hand {expected}"
            );
        }
        let psnr = e["psnr_db"].as_f64().unwrap();
        assert!((psnr + 20.0 * expected.log10()).abs() < 1e-3, "{psnr}");
        // 8 bits: 255·C_m = 51 − 51·0.5^m rounds to the reference's 51 exactly when
        // 51·0.5^m < 0.5, i.e. m ≥ 7.
        let differ = if m >= 7 { 0.0 } else { 1.0 };
        assert_eq!(e["pixels_differ"], differ, "{s}");
        assert_eq!(row["rays"]["primary"], pixels * spp);
        assert_eq!(row["rays"]["reflection"], pixels * spp * u64::from(m - 1));
        assert_eq!(row["rays"]["shadow"], 0);
        assert_eq!(row["times_s"].as_array().unwrap().len(), 2, "--runs 2");
        // Within 1/255 ≈ 3.92e-3: 0.2·0.5^6 = 3.1e-3 is, 0.2·0.5^5 = 6.3e-3 is not.
        assert_eq!(row["within_budget"], m >= 6, "{s}");
        if m >= 6 {
            within.push(i);
        }
        // f32 against the f64 image of the same setting: both are C_m to within f32 rounding.
        if s["precision"] == "f32" {
            assert!(row["vs_f64"]["max_abs"].as_f64().unwrap() <= 1e-6);
        } else {
            assert!(row["vs_f64"].is_null());
        }
    }
    // Only level 7 with weight 0 gets 7 rays; with weight 0.1 a path stops after 4.
    assert_eq!(within.len(), 4);
    let choice = doc["fastest_within_budget"].as_u64().unwrap() as usize;
    assert!(within.contains(&choice));
    let time = |i: usize| settings[i]["median_s"].as_f64().unwrap();
    assert!(within.iter().all(|&i| time(choice) <= time(i)));
}

#[test]
fn the_pareto_front_holds_exactly_the_rows_nothing_beats() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let doc = tradeoff_json(
        &scene,
        &[
            "--levels",
            "1,2,4,8",
            "--min-weights",
            "0",
            "--samples",
            "1",
            "--runs",
            "1",
        ],
    );
    let rows = doc["settings"].as_array().unwrap();
    let key = |r: &Value| {
        (
            r["median_s"].as_f64().unwrap(),
            r["errors"]["rmse"].as_f64().unwrap(),
        )
    };
    let front: Vec<u64> = doc["pareto"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    for (i, r) in rows.iter().enumerate() {
        let (t, e) = key(r);
        let beaten = rows.iter().any(|o| {
            let (to, eo) = key(o);
            to <= t && eo <= e && (to < t || eo < e)
        });
        assert_eq!(front.contains(&(i as u64)), !beaten, "row {i}");
        assert_eq!(r["pareto"], !beaten);
    }
    // The most accurate row (level 8) is never beaten on error, so one of the level-8 rows
    // (f32 or f64) is on the front.
    assert!(front
        .iter()
        .any(|&i| rows[i as usize]["setting"]["max_level"] == 8));
}

/// Reads a binary PPM (P6) written by `phong render`.
fn ppm(path: &Path) -> Vec<u8> {
    let bytes = fs::read(path).unwrap();
    let image = phong::tracer::output::decode_ppm(&bytes).expect("a P6 image");
    image.rgb
}

#[test]
fn the_8_bit_share_equals_the_share_of_pixels_phong_render_writes_differently() {
    // The classic scene at 48×36: the sweep's 8-bit share must be what comparing the images of
    // `phong render` (the other path to the same pixels) gives.
    let dir = TempDir::new().unwrap();
    let scene = classic_at(&dir, 48, 36);
    let doc = tradeoff_json(
        &scene,
        &[
            "--levels",
            "1,3",
            "--min-weights",
            "1/255",
            "--samples",
            "1,4",
            "--precisions",
            "f32",
            "--runs",
            "1",
            "--reference-level",
            "20",
            "--reference-samples",
            "16",
        ],
    );
    let render = |name: &str, args: &[&str]| {
        let out = dir.path().join(name);
        phong()
            .arg("render")
            .arg(&scene)
            .arg("-o")
            .arg(&out)
            .args(args)
            .assert()
            .success();
        ppm(&out)
    };
    let reference = render(
        "ref.ppm",
        &["--max-level", "20", "--min-weight", "0", "--samples", "16"],
    );
    let weight = (1.0f64 / 255.0).to_string();
    for row in doc["settings"].as_array().unwrap() {
        let s = &row["setting"];
        let (n, spp) = (s["max_level"].to_string(), s["samples"].to_string());
        let image = render(
            "x.ppm",
            &[
                "--precision",
                "f32",
                "--max-level",
                &n,
                "--min-weight",
                &weight,
                "--samples",
                &spp,
            ],
        );
        let differ = image
            .chunks_exact(3)
            .zip(reference.chunks_exact(3))
            .filter(|(a, b)| a != b)
            .count();
        let share = differ as f64 / (48.0 * 36.0);
        assert_eq!(
            row["errors"]["pixels_differ"].as_f64().unwrap(),
            share,
            "{s}"
        );
        // max abs ≥ the largest 8-bit step seen, less the half level each rounding can hide.
        let step = image
            .iter()
            .zip(&reference)
            .map(|(a, b)| (f64::from(*a) - f64::from(*b)).abs())
            .fold(0.0, f64::max);
        let max_abs = row["errors"]["max_abs"].as_f64().unwrap();
        assert!(
            max_abs >= (step - 1.0) / 255.0,
            "{max_abs} against step {step}"
        );
        assert!(
            max_abs <= (step + 1.0) / 255.0,
            "{max_abs} against step {step}"
        );
    }
}

/// The document without what depends on the clock or the thread count.
fn without_times(mut doc: Value) -> Value {
    doc.as_object_mut().unwrap().remove("threads");
    doc.as_object_mut().unwrap().remove("build_s");
    doc.as_object_mut().unwrap().remove("pareto");
    doc.as_object_mut().unwrap().remove("fastest_within_budget");
    doc["reference"].as_object_mut().unwrap().remove("time_s");
    for row in doc["settings"].as_array_mut().unwrap() {
        let r = row.as_object_mut().unwrap();
        r.remove("median_s");
        r.remove("times_s");
        r.remove("pareto");
    }
    doc
}

#[test]
fn errors_and_rays_are_the_same_for_any_thread_count() {
    let dir = TempDir::new().unwrap();
    let scene = classic_at(&dir, 40, 30);
    let args = [
        "--levels",
        "2,5",
        "--samples",
        "1,2",
        "--runs",
        "1",
        "--reference-samples",
        "4",
        "--reference-level",
        "10",
    ];
    let one = tradeoff_json(&scene, &[&args[..], &["--threads", "1"]].concat());
    let three = tradeoff_json(&scene, &[&args[..], &["--threads", "3"]].concat());
    assert_eq!(one["threads"], 1);
    assert_eq!(three["threads"], 3);
    assert_eq!(without_times(one), without_times(three));
}

#[test]
fn both_engines_give_the_same_errors_and_rays() {
    let dir = TempDir::new().unwrap();
    let scene = classic_at(&dir, 24, 18);
    let args = [
        "--levels",
        "1,5",
        "--samples",
        "1,4",
        "--runs",
        "1",
        "--reference-samples",
        "4",
        "--reference-level",
        "10",
        "--threads",
        "2",
    ];
    let wide = tradeoff_json(&scene, &[&args[..], &["--engine", "wide"]].concat());
    let scalar = tradeoff_json(&scene, &[&args[..], &["--engine", "scalar"]].concat());
    // The default is the wide engine, as for `phong render`.
    let default = tradeoff_json(&scene, &args);
    // Something was traced past the primary rays (reflections and shadows), in both precisions.
    let rows = wide["settings"].as_array().unwrap();
    assert_eq!(rows.len(), 2 * 2 * 3 * 2, "{wide}");
    assert!(
        rows.iter()
            .any(|r| r["rays"]["reflection"].as_u64() > Some(0)),
        "{wide}"
    );
    assert!(
        rows.iter().any(|r| r["rays"]["shadow"].as_u64() > Some(0)),
        "{wide}"
    );
    let wide = without_times(wide);
    assert_eq!(wide, without_times(scalar));
    assert_eq!(wide, without_times(default));

    let out = phong()
        .arg("tradeoff")
        .arg(&scene)
        .args(["--engine", "simd"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--engine") && err.contains("scalar"), "{err}");
}

#[test]
fn the_table_csv_and_plot_are_written() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let plot = dir.path().join("trade.svg");
    let table = dir.path().join("table.txt");
    phong()
        .arg("tradeoff")
        .arg(&scene)
        .args(["--levels", "1,7", "--min-weights", "0", "--samples", "1"])
        .args(["--runs", "1", "--budget", "0.01", "--metric", "max-abs"])
        .arg("--plot")
        .arg(&plot)
        .arg("-o")
        .arg(&table)
        .assert()
        .success();
    let text = fs::read_to_string(&table).unwrap();
    assert!(text.contains("Reference: f64, level 64, min weight 0, 64 samples"));
    assert!(
        text.contains("Fastest within max abs error ≤ 0.01"),
        "{text}"
    );
    // Level 1 is off by 0.1, level 7 by 0.2·0.5^7 ≈ 1.6e-3: only level 7 is within 0.01.
    assert!(text.contains("level 7, min weight 0, 1 sample)"), "{text}");
    let svg = fs::read_to_string(&plot).unwrap();
    assert!(svg.starts_with("<svg"), "{}", &svg[..80.min(svg.len())]);
    assert!(svg.contains("Pareto front") && svg.contains("median time (ms)"));

    let out = phong()
        .arg("tradeoff")
        .arg(&scene)
        .args([
            "--levels",
            "1,7",
            "--min-weights",
            "0,0.1",
            "--samples",
            "1",
        ])
        .args(["--runs", "1", "--format", "csv"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let csv = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 2 * 2 * 2, "a header and a row per setting");
    assert!(lines[0].starts_with("precision,max_level,min_weight,samples,median_s"));
    assert!(lines[1].starts_with("f32,1,0,1,"));
}

/// With `--lang pt` (or a Portuguese locale and no `--lang`) the table, its verdict and the
/// plot are in Portuguese, with the same settings and numbers; the JSON is the same document in
/// either language.
#[test]
fn the_table_and_plot_speak_portuguese_with_lang_pt() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let plot = dir.path().join("troca.svg");
    let args = [
        "--levels",
        "1,7",
        "--min-weights",
        "0",
        "--samples",
        "1",
        "--runs",
        "1",
        "--budget",
        "0.01",
        "--metric",
        "max-abs",
    ];
    // The table, with `extra` flags and `locale` as LANG.
    let table = |extra: &[&str], locale: &str| {
        let out = phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(args)
            .args(extra)
            .env("LANG", locale)
            .output()
            .unwrap();
        assert!(out.status.success(), "{extra:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    let plot_arg = plot.to_str().unwrap();
    let text = table(&["--lang", "pt", "--plot", plot_arg], "C.UTF-8");
    assert!(
        text.contains("Referência: f64, nível 64, peso mínimo 0, 64 amostras"),
        "{text}"
    );
    assert!(text.contains("nível") && text.contains("amostras") && text.contains("fronteira"));
    // Level 1 is off by 0.1, level 7 by 0.2·0.5^7 ≈ 1.6e-3: only level 7 is within 0.01.
    assert!(
        text.contains("A mais rápida dentro de erro absoluto máximo ≤ 0.01: #"),
        "{text}"
    );
    assert!(
        text.contains("nível 7, peso mínimo 0, 1 amostra)"),
        "{text}"
    );
    assert!(
        !text.contains("Reference") && !text.contains("Fastest"),
        "{text}"
    );
    let svg = fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("fronteira de Pareto") && svg.contains("tempo mediano (ms)"));
    assert!(!svg.contains("Pareto front") && !svg.contains("median time"));

    // The locale decides where --lang is not given.
    let by_locale = table(&[], "pt_BR.UTF-8");
    assert!(
        by_locale.starts_with("Velocidade contra precisão em "),
        "{by_locale}"
    );

    let json = |lang: &str| {
        let mut a = args.to_vec();
        a.extend(["--lang", lang]);
        without_times(tradeoff_json(&scene, &a))
    };
    assert_eq!(json("pt"), json("en"), "the JSON does not depend on --lang");
}

/// The table and the plot are written all or nothing: a table that cannot be written (its path
/// a folder) leaves the old plot as it was, as a plot that cannot be written leaves the old
/// table (before, the plot was put in place first and stayed replaced).
#[test]
fn a_table_that_cannot_be_written_keeps_the_old_plot() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let plot = dir.path().join("p.svg");
    let table = dir.path().join("t.txt");
    // A folder, named as a plot may be.
    let taken = dir.path().join("taken.svg");
    fs::create_dir(&taken).unwrap();
    for (plot_to, table_to, kept) in [(&plot, &taken, &plot), (&taken, &table, &table)] {
        fs::write(kept, "OLD").unwrap();
        let out = phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(["--levels", "1", "--min-weights", "0", "--samples", "1"])
            .args([
                "--runs",
                "1",
                "--reference-level",
                "2",
                "--reference-samples",
                "1",
            ])
            .arg("--plot")
            .arg(plot_to)
            .arg("-o")
            .arg(table_to)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(BAD_INPUT), "{err}");
        assert!(err.contains("taken"), "{err}");
        assert_eq!(
            fs::read_to_string(kept).unwrap(),
            "OLD",
            "{}",
            kept.display()
        );
    }
}

#[test]
fn bad_flags_exit_2_name_the_flag_and_write_nothing() {
    let dir = TempDir::new().unwrap();
    let scene = mirrors(&dir);
    let plot = dir.path().join("p.svg");
    for (args, names) in [
        (vec!["--runs", "0"], "--runs"),
        (vec!["--levels", "0,3"], "--levels"),
        (vec!["--samples", "5000"], "--samples"),
        (vec!["--reference-samples", "0"], "--reference-samples"),
        (vec!["--min-weights=-1"], "--min-weights"),
        (vec!["--budget", "abc"], "--budget"),
        (vec!["--size", "0x5"], "--size"),
        (vec!["--threads", "0"], "--threads"),
    ] {
        let out = phong()
            .arg("tradeoff")
            .arg(&scene)
            .args(&args)
            .arg("--plot")
            .arg(&plot)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(BAD_INPUT), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(names), "{args:?}: {err}");
        assert!(!plot.exists(), "{args:?} wrote a plot");
    }
    let out = phong()
        .arg("tradeoff")
        .arg(&scene)
        .args(["--plot", "p.png"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(BAD_INPUT));
    assert!(String::from_utf8_lossy(&out.stderr).contains(".svg"));
    // A point problem is not a scene.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = phong()
        .arg("tradeoff")
        .arg(root.join("exercises/4.2.json"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(BAD_INPUT));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("4.2.json") && err.contains("camera"), "{err}");
}
