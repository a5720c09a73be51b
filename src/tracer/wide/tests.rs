//! The wide engine (packets of 8 × f32 or 4 or 8 × f64 lanes, queues per bounce) renders the
//! scalar engine's image bit for bit: every bundled scene, both precisions, the pixel means before
//! rounding compared by their bits, and the ray counts equal. No operation of the wide path is
//! allowed to differ from the scalar one: the lanes do IEEE +, −, ×, ÷, √ in the scalar order
//! (the shading is the core's one source in lanes), and everything else (hit points, pow, the
//! cone's atan2, the shadow rays' origins) is the scalar code itself, lane by lane.

use std::path::{Path, PathBuf};

use crate::core::Real;
use crate::problem::{self, validate, Camera, Problem};
use crate::tracer::render::render_linear_with;
use crate::tracer::{Engine, Scene};

#[path = "../../../scenes/many_spheres.rs"]
mod many_spheres;

fn scenes() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("scenes/")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

/// Renders with both engines and compares every mean's bits and the counts.
fn same_by_both_engines<R: Real>(name: &str, problem: &Problem<R>, camera: &Camera<R>) {
    let scene = Scene::new(problem);
    let (scalar, scalar_counts) =
        render_linear_with(Engine::Scalar, problem, camera, &scene, &|| {});
    let (wide, wide_counts) = render_linear_with(Engine::Wide, problem, camera, &scene, &|| {});
    assert_eq!(
        scalar_counts,
        wide_counts,
        "{name} ({}): ray counts",
        R::NAME
    );
    assert_eq!(scalar.rgb.len(), wide.rgb.len());
    let differing = scalar
        .rgb
        .iter()
        .zip(&wide.rgb)
        .position(|(a, b)| a.to_bits() != b.to_bits());
    if let Some(i) = differing {
        let (x, y) = ((i / 3) as u32 % camera.width, (i / 3) as u32 / camera.width);
        panic!(
            "{name} ({}): pixel ({x}, {y}) channel {}: scalar {} wide {}",
            R::NAME,
            i % 3,
            scalar.rgb[i],
            wide.rgb[i]
        );
    }
    // The 8-bit image is these means rounded (render_with is render_linear_with, rounded).
}

fn bundled_scenes_in<R: Real>() {
    let mut rendered = 0;
    for path in scenes() {
        let Ok(problem::SceneFile {
            problem, camera, ..
        }) = problem::load_scene_for::<R>(&path, validate::Work::Image)
        else {
            continue; // a ray or point problem, not a scene
        };
        same_by_both_engines::<R>(&path.display().to_string(), &problem, &camera);
        rendered += 1;
    }
    assert!(rendered >= 4, "only {rendered} scenes rendered");
}

#[test]
fn every_bundled_scene_renders_the_same_bits_by_both_engines_in_f32() {
    bundled_scenes_in::<f32>();
}

#[test]
fn every_bundled_scene_renders_the_same_bits_by_both_engines_in_f64() {
    bundled_scenes_in::<f64>();
}

fn load<R: Real>(json: &str) -> Problem<R> {
    let file = problem::parse_str(Path::new("many.json"), json).expect("a valid scene");
    validate::validate_in::<R>(&file, None).expect("a valid scene")
}

/// A handful of spheres (packets) and enough for a BVH (the aggregate's own intersection in
/// the same queues), with several samples per pixel, with and without shadows, small images.
fn varied_scenes_in<R: Real>() {
    for n in [5usize, 40] {
        let mut problem = load::<R>(&many_spheres::scene(n).to_string());
        let mut camera = problem.camera.expect("a camera");
        camera.width = 61;
        camera.height = 37;
        for (samples, shadows) in [(1, true), (3, true), (4, false)] {
            problem.render.samples = samples;
            problem.render.shadows = shadows;
            let name = format!("{n} spheres, {samples} samples, shadows {shadows}");
            same_by_both_engines::<R>(&name, &problem, &camera);
        }
    }
}

#[test]
fn packets_and_bvh_scenes_with_samples_render_the_same_bits_in_both_precisions() {
    varied_scenes_in::<f32>();
    varied_scenes_in::<f64>();
}

/// The instances of the bounce loop without reflection (shadows on and off): the many-spheres
/// scene with every reflectivity taken out, so that nothing reflects.
fn unreflective_scenes_in<R: Real>() {
    let mut json = many_spheres::scene(5);
    for m in json["materials"]
        .as_object_mut()
        .expect("materials")
        .values_mut()
    {
        m.as_object_mut()
            .expect("a material")
            .remove("reflectivity");
    }
    let mut problem = load::<R>(&json.to_string());
    assert!(problem
        .surfaces()
        .iter()
        .all(|s| s.material.material.o_r.is_none()));
    let mut camera = problem.camera.expect("a camera");
    camera.width = 53;
    camera.height = 29;
    for shadows in [true, false] {
        problem.render.shadows = shadows;
        let name = format!("5 spheres, nothing reflects, shadows {shadows}");
        same_by_both_engines::<R>(&name, &problem, &camera);
    }
}

#[test]
fn scenes_where_nothing_reflects_render_the_same_bits_in_both_precisions() {
    unreflective_scenes_in::<f32>();
    unreflective_scenes_in::<f64>();
}

/// Materials shaded together are equal in what shading reads, past the 16 the plan looks
/// through before it keeps a map: 40 materials, 20 distinct (n_s 1 to 20), each twice, the
/// second time with another O_r (which shading does not read).
#[test]
fn the_plan_groups_exactly_the_equal_materials() {
    use crate::core::real::v3;
    use crate::core::Material;
    let m = |i: usize, o_r: f64| Material::<f64> {
        o_a: Some(v3::<f64>([0.1; 3])),
        o_d: Some(v3::<f64>([0.5, 0.4, 0.3])),
        o_s: (!i.is_multiple_of(3)).then(|| v3::<f64>([0.2; 3])),
        n_s: (i + 1) as f64,
        o_r: Some(v3::<f64>([o_r; 3])),
        transmission: None,
    };
    let all: Vec<Material<f64>> = (0..40).map(|i| m(i % 20, (i / 20) as f64 * 0.5)).collect();
    let (of, distinct) = super::distinct(all.iter(), super::shading_bits);
    assert_eq!(distinct.len(), 20);
    for (i, id) in of.iter().enumerate() {
        assert_eq!(*id as usize, i % 20, "material {i}");
        let d = distinct[*id as usize];
        assert_eq!(
            (d.o_a, d.o_d, d.o_s, d.n_s),
            (all[i].o_a, all[i].o_d, all[i].o_s, all[i].n_s)
        );
    }
}

/// Items met again at the same address (the surfaces sharing one material) take the index
/// their key gave the first time, and equal items at other addresses still meet them by key.
#[test]
fn items_at_one_address_and_equal_items_elsewhere_share_one_index() {
    use crate::core::real::v3;
    use crate::core::Material;
    let m = |n_s: f64| Material::<f64> {
        o_a: Some(v3::<f64>([0.1; 3])),
        o_d: Some(v3::<f64>([0.5, 0.4, 0.3])),
        o_s: None,
        n_s,
        o_r: None,
        transmission: None,
    };
    let (a, a_again, c) = (m(10.0), m(10.0), m(30.0));
    // 40 items, more than the 16 addresses kept: a, c, a's equal at another address, a, ...
    let all: Vec<&Material<f64>> = (0..40).map(|i| [&a, &c, &a_again][i % 3]).collect();
    let (of, distinct) = super::distinct(all.iter().copied(), super::shading_bits);
    assert_eq!(distinct.len(), 2);
    let expected: Vec<u32> = (0..40).map(|i| [0, 1, 0][i % 3]).collect();
    assert_eq!(of, expected);
}

/// Triangles (the torus mesh of scenes/mesh.json, the smooth sphere of scenes/smooth.json: SoA
/// triangle leaves of the wide BVH) with several samples, small image, with and without shadows.
fn mesh_scene_in<R: Real>(file: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    let problem::SceneFile {
        mut problem,
        mut camera,
        ..
    } = problem::load_scene_for::<R>(&path, validate::Work::Image).expect(file);
    camera.width = 53;
    camera.height = 41;
    for (samples, shadows) in [(3, true), (2, false)] {
        problem.render.samples = samples;
        problem.render.shadows = shadows;
        let name = format!("{file}, {samples} samples, shadows {shadows}");
        same_by_both_engines::<R>(&name, &problem, &camera);
    }
}

#[test]
fn the_mesh_scene_with_samples_renders_the_same_bits_in_both_precisions() {
    mesh_scene_in::<f32>("scenes/mesh.json");
    mesh_scene_in::<f64>("scenes/mesh.json");
}

#[test]
fn the_smooth_mesh_scene_with_samples_renders_the_same_bits_in_both_precisions() {
    mesh_scene_in::<f32>("scenes/smooth.json");
    mesh_scene_in::<f64>("scenes/smooth.json");
}

/// The many-spheres scene with glass among its materials: each material's first sphere material
/// (the "mirror" and every other one) given a transmissivity, so that hits spawn two rays and
/// the queues hold trees, in packets (5 spheres) and through the BVH (40).
fn glass_scenes_in<R: Real>() {
    for n in [5usize, 40] {
        let mut json = many_spheres::scene(n);
        let materials = json["materials"].as_object_mut().expect("materials");
        for (k, (_, m)) in materials.iter_mut().enumerate() {
            if k % 2 == 0 {
                m["transmissivity"] = serde_json::json!([0.7, 0.8, 0.9]);
                m["ior"] = serde_json::json!(1.0 + 0.25 * k as f64);
            }
        }
        let mut problem = load::<R>(&json.to_string());
        let mut camera = problem.camera.expect("a camera");
        camera.width = 53;
        camera.height = 31;
        for (samples, shadows) in [(1, true), (2, false)] {
            problem.render.samples = samples;
            problem.render.shadows = shadows;
            let name = format!("{n} spheres with glass, {samples} samples, shadows {shadows}");
            same_by_both_engines::<R>(&name, &problem, &camera);
        }
    }
}

#[test]
fn ray_trees_render_the_same_bits_by_both_engines_in_both_precisions() {
    glass_scenes_in::<f32>();
    glass_scenes_in::<f64>();
}

/// The scene holds each distinct material once (the many-spheres scene's five: the floor and
/// four for the spheres), and every surface's is its own material to the bit.
#[test]
fn the_scene_holds_each_material_once_and_each_surface_its_own() {
    let mut problem = load::<f64>(&many_spheres::scene(200).to_string());
    let scene = Scene::new(&problem);
    assert_eq!(scene.materials.len(), 5);
    let bits = |m: &crate::core::Material<f64>| format!("{m:?}");
    for (i, s) in problem.surfaces().iter().enumerate() {
        assert_eq!(
            bits(scene.material(i)),
            bits(&s.material.material),
            "surface {i}"
        );
    }
    // A surface whose material is changed is its own material afterwards, and no other's.
    let problem::Target::Scene { surfaces, .. } = &mut problem.target else {
        panic!("a scene")
    };
    let before = *surfaces[2].material.material;
    surfaces[1].material.material.n_s = 7.0;
    assert_eq!(*surfaces[2].material.material, before);
    let scene = Scene::new(&problem);
    assert_eq!(scene.materials.len(), 6);
    assert_eq!(scene.material(1).n_s, 7.0);
    for (i, s) in problem.surfaces().iter().enumerate() {
        assert_eq!(
            bits(scene.material(i)),
            bits(&s.material.material),
            "surface {i}"
        );
    }
}

/// The counting sort of a queue's hits by material gives the comparison sort's order: queues
/// of every length up to a block, with and without misses, few and many materials.
#[test]
fn hits_are_grouped_by_material_as_a_sort_orders_them() {
    let mut rng = crate::geometry::bounds::test_rng::Rng::new(7);
    let mut next = |n: u64| rng.next_u64() % n;
    let (mut materials, mut groups) = (Vec::new(), Vec::new());
    for round in 0..2000 {
        let len = next(super::BLOCK as u64 + 1) as usize;
        let kinds = [1, 2, 3, 5, 64, 1000][round % 6];
        let hits: Vec<Option<u32>> = (0..len)
            .map(|_| (next(4) != 0).then(|| next(kinds) as u32))
            .collect();
        let mut expected: Vec<(u32, u32)> = hits
            .iter()
            .enumerate()
            .filter_map(|(i, m)| m.map(|m| (m, i as u32)))
            .collect();
        expected.sort();
        super::sort_by_material(hits.iter().copied(), &mut materials, &mut groups);
        assert_eq!(groups, expected, "{hits:?}");
    }
}
