//! The many-spheres scene: `n` spheres of four materials scattered on a grid over a reflective
//! floor, from a fixed linear congruential sequence, so the same `n` always gives the same scene.
//! Shared by `examples/many_spheres.rs` (writes the scene file) and `benches/render.rs`.

use serde_json::{json, Value};

/// The scene with `n` spheres, as the JSON a scene file holds.
pub fn scene(n: usize) -> Value {
    // Knuth's MMIX LCG; the top 53 bits as a number in [0, 1).
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let side = (n as f64).sqrt().ceil() as usize;
    let spacing = 1.0;
    let half = side as f64 * spacing / 2.0;
    let round = |x: f64| (x * 1e4).round() / 1e4;
    let mut surfaces = vec![json!({
        "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"
    })];
    for i in 0..n {
        let (gx, gz) = ((i % side) as f64, (i / side) as f64);
        let r = round(0.15 + 0.3 * next());
        let x = round(gx * spacing - half + 0.5 + 0.2 * (next() - 0.5));
        let z = round(-(gz * spacing) + 0.2 * (next() - 0.5));
        let material = ["red", "green", "blue", "chrome"][(next() * 4.0) as usize % 4];
        surfaces.push(json!({
            "type": "sphere", "center": [x, r, z], "radius": r, "material": material
        }));
    }
    let depth = side as f64 * spacing;
    json!({
        "title": format!("{n} spheres"),
        "question": "A field of spheres on a reflective floor: the BVH keeps the cost of a ray \
                     about logarithmic in the number of surfaces.",
        "materials": {
            "floor": { "ambient": [0.05, 0.05, 0.05], "diffuse": [0.4, 0.4, 0.4],
                       "specular": [0, 0, 0], "shininess": 1, "reflectivity": [0.2, 0.2, 0.2] },
            "red": { "ambient": [0.1, 0, 0], "diffuse": [0.7, 0.1, 0.1],
                     "specular": [0.4, 0.4, 0.4], "shininess": 30 },
            "green": { "ambient": [0, 0.1, 0], "diffuse": [0.1, 0.6, 0.2],
                       "specular": [0.4, 0.4, 0.4], "shininess": 30 },
            "blue": { "ambient": [0, 0, 0.1], "diffuse": [0.1, 0.2, 0.7],
                      "specular": [0.4, 0.4, 0.4], "shininess": 30 },
            "chrome": { "ambient": [0, 0, 0], "diffuse": [0.05, 0.05, 0.05],
                        "specular": [0.8, 0.8, 0.8], "shininess": 100,
                        "reflectivity": [0.8, 0.8, 0.8] }
        },
        "lights": [
            { "type": "ambient", "color": [0.2, 0.2, 0.2] },
            { "type": "directional", "direction": [0.4, -1, -0.6], "color": [0.9, 0.9, 0.85],
              "name": "sun" },
            { "type": "point", "position": [0, 6, 4], "color": [0.4, 0.4, 0.45], "falloff": 0,
              "name": "fill" }
        ],
        "surfaces": surfaces,
        "camera": { "eye": [0, 6, 6], "look_at": [0, 0, -depth / 3.0], "up": [0, 1, 0],
                    "fov": 50, "width": 640, "height": 480 },
        "background": [0.4, 0.5, 0.7],
        "render": { "max_level": 5 }
    })
}
