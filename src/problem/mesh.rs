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

/// The largest OBJ file read: 256 MiB (a million triangles are about 60 MB of text).
pub const MAX_MESH_BYTES: u64 = 256 << 20;

/// The most triangles a scene holds, its meshes' and its own together: 1,000,000 (each costs
/// about half a kilobyte once validated, with its share of the BVH).
pub const MAX_TRIANGLES: usize = 1_000_000;

/// What the first pass over an OBJ file found: where each face is, so that a triangle can be
/// named by the line of its face.
struct Faces {
    /// The line of each face and how many triangles it gives, in the file's order.
    lines: Vec<(usize, usize)>,
}

impl Faces {
    /// The line of the face that gave triangle `k` (0-based, in the file's order).
    fn line_of(&self, k: usize) -> usize {
        let mut first = 0;
        for &(line, n) in &self.lines {
            if k < first + n {
                return line;
            }
            first += n;
        }
        0
    }
}

/// A mistake on line `line` of the OBJ file.
/// The fix for a vertex that is not finite in `R`: f32's range is the one a coordinate can
/// leave while finite in f64, so only in f32 is the other precision a way out.
fn finite_fix<R: Real>() -> &'static str {
    if R::NAME == "f32" {
        "give finite coordinates (or use --precision f64)"
    } else {
        "give finite coordinates"
    }
}

fn at_line(line: usize, message: String, fix: &str) -> MeshError {
    MeshError {
        message: format!("line {line}: {message}"),
        fix: fix.into(),
    }
}

/// The first pass: every vertex is three numbers finite in `R`, every face has at least three
/// vertices that exist, there are at most [`MAX_TRIANGLES`] triangles; each mistake named by its
/// line (`tobj` says only which kind of line failed).
fn scan<R: Real>(text: &str) -> Result<Faces, MeshError> {
    let mut vertices: usize = 0;
    let mut triangles: usize = 0;
    let mut faces = Faces { lines: Vec::new() };
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let mut words = line.split_whitespace();
        let shown = || crate::check::answer::shorten(line.trim(), 60);
        match words.next() {
            Some("v") => {
                let xyz: Vec<&str> = words.by_ref().take(3).collect();
                let numbers: Option<Vec<f64>> = (xyz.len() == 3)
                    .then(|| xyz.iter().map(|w| w.parse::<f64>().ok()).collect())
                    .flatten();
                let Some(numbers) = numbers else {
                    return Err(at_line(
                        n,
                        format!(
                            "the vertex \"{}\" is not `v x y z` (three numbers)",
                            shown()
                        ),
                        "write each vertex as `v x y z`",
                    ));
                };
                if numbers
                    .iter()
                    .any(|&x| !(x.is_finite() && R::from_f64(x).is_finite()))
                {
                    return Err(at_line(
                        n,
                        format!("the vertex \"{}\" is not finite in {}", shown(), R::NAME),
                        finite_fix::<R>(),
                    ));
                }
                vertices += 1;
            }
            Some("l") => {
                return Err(at_line(
                    n,
                    format!(
                        "\"{}\" is a line element, which has no surface to hit",
                        shown()
                    ),
                    "remove the `l` lines (faces are `f i j k`)",
                ))
            }
            Some("f") => {
                let refs: Vec<&str> = words.collect();
                if refs.len() < 3 {
                    return Err(at_line(
                        n,
                        format!(
                            "the face \"{}\" has {} vertices, and a face needs at least 3",
                            shown(),
                            refs.len()
                        ),
                        "give each face three or more vertices (`f i j k`)",
                    ));
                }
                for r in &refs {
                    let index = r.split('/').next().and_then(|v| v.parse::<i64>().ok());
                    // Negative indices count back from the last vertex so far (-1 is the last).
                    let resolved = index.map(|k| if k < 0 { vertices as i64 + 1 + k } else { k });
                    if !resolved.is_some_and(|k| k >= 1 && k <= vertices as i64) {
                        return Err(at_line(
                            n,
                            format!(
                                "the face \"{}\" refers to vertex {r}, and {vertices} vertices \
                                 come before it",
                                shown()
                            ),
                            "correct the face's vertex indices (1 is the first vertex)",
                        ));
                    }
                }
                triangles += refs.len() - 2;
                if triangles > MAX_TRIANGLES {
                    return Err(at_line(
                        n,
                        format!("the mesh has more than {MAX_TRIANGLES} triangles"),
                        &crate::report::messages::both(
                            "give a mesh of at most 1000000 triangles (simplify it, for example \
                             with Blender's Decimate modifier)",
                            "dê uma malha de no máximo 1000000 triângulos (simplifique-a, por \
                             exemplo com o modificador Decimate do Blender)",
                        ),
                    ));
                }
                faces.lines.push((n, refs.len() - 2));
            }
            _ => {}
        }
    }
    Ok(faces)
}

/// Reads the triangles of an OBJ file, in the file's order.
pub fn load_obj<R: Real>(path: &Path) -> Result<Vec<Triangle<R>>, MeshError> {
    let bytes = super::read_limited(path, MAX_MESH_BYTES, "a mesh").map_err(|e| MeshError {
        message: format!("cannot be read: {e}"),
        fix: if super::read_fix(&e).starts_with("check") {
            "check the path; it is relative to the scene file's folder (to the working folder \
             for a scene read from standard input)"
                .into()
        } else {
            super::read_fix(&e).into()
        },
    })?;
    let text = String::from_utf8_lossy(&bytes);
    let faces = scan::<R>(&text)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    // The material loader is never asked to read anything: `.mtl` files are ignored.
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default())).map_err(
            |e| MeshError {
                message: format!("is not a valid Wavefront OBJ file: {e}"),
                fix: "give an OBJ file with `v x y z` vertices and `f i j k` faces".into(),
            },
        )?;
    let mut out = Vec::new();
    let count: usize = faces.lines.iter().map(|&(_, n)| n).sum();
    out.try_reserve_exact(count).map_err(|_| MeshError {
        message: super::out_of_memory(count.saturating_mul(std::mem::size_of::<Triangle<R>>())),
        fix: "give a smaller mesh, or free memory".into(),
    })?;
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
                    fix: finite_fix::<R>().into(),
                });
            }
            Ok(v)
        };
        for face in model.mesh.indices.chunks_exact(3) {
            let t = Triangle {
                p: [corner(face[0])?, corner(face[1])?, corner(face[2])?],
            };
            if t.normal().is_none() {
                // The object's name when the file gives one (`o name`); tobj's placeholder for
                // a file without `o` lines is not the user's word.
                let object = match model.name.as_str() {
                    "unnamed_object" | "" => String::new(),
                    name => format!(" (object \"{name}\")"),
                };
                return Err(MeshError {
                    message: format!(
                        "line {}: the face's triangle {}{object} is degenerate in {}: its corners \
                         lie on one line",
                        faces.line_of(out.len()),
                        out.len(),
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
