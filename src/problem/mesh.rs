//! Wavefront OBJ meshes: read with `tobj`, polygons split into triangles, each triangle checked
//! to have an area in the chosen precision. Materials of the OBJ file (`.mtl`) are not read:
//! a mesh has the one material its surface entry names.

use std::path::Path;

use crate::core::{Real, Vector, V3};
use crate::geometry::Triangle;

/// Why a mesh could not be used: a message and how to fix it.
#[derive(Debug)]
pub struct MeshError {
    pub message: String,
    pub fix: String,
}

/// Reads the triangles of an OBJ file, in the file's order.
pub fn load_obj<R: Real>(path: &Path) -> Result<Vec<Triangle<R>>, MeshError> {
    let file = std::fs::File::open(path).map_err(|e| MeshError {
        message: format!("cannot be read: {e}"),
        fix: "check the path; it is relative to the scene file's folder".into(),
    })?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    // The material loader is never asked to read anything: `.mtl` files are ignored.
    let (models, _) = tobj::load_obj_buf(&mut std::io::BufReader::new(file), &options, |_| {
        Ok(Default::default())
    })
    .map_err(|e| MeshError {
        message: format!("is not a valid Wavefront OBJ file: {e}"),
        fix: "give an OBJ file with `v x y z` vertices and `f i j k` faces".into(),
    })?;
    let mut out = Vec::new();
    for model in &models {
        let pos = &model.mesh.positions;
        let corner = |i: u32| -> Result<V3<R>, MeshError> {
            let k = 3 * i as usize;
            let xyz = pos.get(k..k + 3).ok_or_else(|| MeshError {
                message: format!("a face refers to vertex {} which does not exist", i + 1),
                fix: "correct the face's vertex indices".into(),
            })?;
            let v = V3::<R>::new(
                R::from_f64(xyz[0]),
                R::from_f64(xyz[1]),
                R::from_f64(xyz[2]),
            );
            if !crate::core::Vector::is_finite(v) {
                return Err(MeshError {
                    message: format!("vertex {} is not finite in {}", i + 1, R::NAME),
                    fix: "give finite coordinates (or use --precision f64)".into(),
                });
            }
            Ok(v)
        };
        for face in model.mesh.indices.chunks_exact(3) {
            let t = Triangle {
                p: [corner(face[0])?, corner(face[1])?, corner(face[2])?],
            };
            if t.normal().is_none() {
                return Err(MeshError {
                    message: format!(
                        "triangle {} (model \"{}\", vertices {}, {}, {}) is degenerate in {}: its \
                         corners lie on one line",
                        out.len(),
                        model.name,
                        face[0] + 1,
                        face[1] + 1,
                        face[2] + 1,
                        R::NAME
                    ),
                    fix: "remove the degenerate face from the OBJ file".into(),
                });
            }
            out.push(t);
        }
    }
    if out.is_empty() {
        return Err(MeshError {
            message: "has no faces".into(),
            fix: "give an OBJ file with at least one face (`f i j k`)".into(),
        });
    }
    Ok(out)
}
