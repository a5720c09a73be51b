//! Wavefront OBJ meshes: read with `tobj`, polygons split into triangles, each triangle checked
//! to have an area in the chosen precision. Materials of the OBJ file (`.mtl`) are not read:
//! a mesh has the one material its surface entry names. Vertex normals (`vn`, faces `f v//vn` or
//! `f v/vt/vn`) make the faces that give them smooth triangles (docs/conventions.md, "Smooth
//! meshes"); they are read by this module's own first pass, since `tobj` drops a missing normal
//! of a face silently and misaligns the rest.

use std::path::Path;

use crate::core::vector::normalize;
use crate::core::{Real, Vector, V3};
use crate::geometry::Triangle;
use crate::text::{Echo, Num};

pub use super::mesh_faults::{MeshError, MeshFault};
use super::mesh_faults::{ObjError, Object, OrF64};
use super::reading::{Cause, Input, Limit, ReadFix};

/// The largest OBJ file read: 256 MiB (a million triangles are about 60 MB of text).
pub const MAX_MESH_BYTES: u64 = 256 << 20;

/// The most triangles a scene holds, its meshes' and its own together: 1,000,000 (each costs
/// about half a kilobyte once validated, with its share of the BVH).
pub const MAX_TRIANGLES: usize = 1_000_000;

/// What the first pass over an OBJ file found: where each face is, so that a triangle can be
/// named by the line of its face.
struct Faces<R: Real> {
    /// The line of each face and how many triangles it gives, in the file's order.
    lines: Vec<(usize, usize)>,
    /// The file's vertex normals (`vn`), each normalised in `R`.
    normals: Vec<V3<R>>,
    /// Each triangle's vertex normals as indices into `normals` (0-based), in the order of its
    /// corners, or `None` for a face without normals; triangles in the file's order, a
    /// polygon's fan (p₀, p_i, p_{i+1}) as `tobj` splits it.
    triangle_normals: Vec<Option<[u32; 3]>>,
}

impl<R: Real> Faces<R> {
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

/// Whether precision `R` is f32, whose range a coordinate can leave while finite in f64: only
/// there is the other precision a way out.
fn or_f64<R: Real>() -> OrF64 {
    OrF64(R::NAME == "f32")
}

/// The first pass: every vertex is three numbers finite in `R`, every vertex normal three
/// numbers finite in `R` of a length that is not zero there, every face has at least three
/// vertices that exist and either a normal for each of them or none, there are at most
/// [`MAX_TRIANGLES`] triangles; each mistake named by its line (`tobj` says only which kind of
/// line failed).
/// The statements of the OBJ format (Wavefront's specification, appendix B1): those read
/// (`v`, `vn`, `f`; `vt`, `g`, `o`, `s`, `usemtl` and `mtllib` taken or ignored by the reader)
/// and those of curves, surfaces and display attributes, ignored. A line starting with any
/// other word is refused ([`MeshFault::UnknownStatement`]).
const STATEMENTS: [&str; 37] = [
    "v",
    "vt",
    "vn",
    "vp",
    "f",
    "l",
    "p",
    "g",
    "o",
    "s",
    "mg",
    "usemtl",
    "mtllib",
    "cstype",
    "deg",
    "bmat",
    "step",
    "curv",
    "curv2",
    "surf",
    "parm",
    "trim",
    "hole",
    "scrv",
    "sp",
    "end",
    "con",
    "bevel",
    "c_interp",
    "d_interp",
    "lod",
    "shadow_obj",
    "trace_obj",
    "ctech",
    "stech",
    "maplib",
    "usemap",
];

fn scan<R: Real>(text: &str) -> Result<Faces<R>, MeshError> {
    let mut vertices: usize = 0;
    let mut triangles: usize = 0;
    let mut faces = Faces {
        lines: Vec::new(),
        normals: Vec::new(),
        triangle_normals: Vec::new(),
    };
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let mut words = line.split_whitespace();
        let v = || Echo::new(line.trim(), 60);
        let refuse = |fault: MeshFault| Err(MeshError::at_line(n, fault));
        let precision = || R::NAME.to_owned();
        match words.next() {
            Some("v") => {
                let xyz: Vec<&str> = words.by_ref().take(3).collect();
                let numbers: Option<Vec<f64>> = (xyz.len() == 3)
                    .then(|| xyz.iter().map(|w| w.parse::<f64>().ok()).collect())
                    .flatten();
                let Some(numbers) = numbers else {
                    return refuse(MeshFault::VertexNotXyz { v: v() });
                };
                if numbers
                    .iter()
                    .any(|&x| !(x.is_finite() && R::from_f64(x).is_finite()))
                {
                    return refuse(MeshFault::VertexNotFinite {
                        v: v(),
                        precision: precision(),
                        or_f64: or_f64::<R>(),
                    });
                }
                vertices += 1;
            }
            Some("vn") => {
                let xyz: Vec<&str> = words.by_ref().take(3).collect();
                let numbers: Option<Vec<f64>> = (xyz.len() == 3)
                    .then(|| xyz.iter().map(|w| w.parse::<f64>().ok()).collect())
                    .flatten();
                let Some(numbers) = numbers else {
                    return refuse(MeshFault::NormalNotXyz { v: v() });
                };
                if numbers
                    .iter()
                    .any(|&x| !(x.is_finite() && R::from_f64(x).is_finite()))
                {
                    return refuse(MeshFault::NormalNotFinite {
                        v: v(),
                        precision: precision(),
                    });
                }
                let normal = V3::<R>::new(
                    R::from_f64(numbers[0]),
                    R::from_f64(numbers[1]),
                    R::from_f64(numbers[2]),
                );
                let Some(unit) = normalize::<R>(normal) else {
                    return refuse(MeshFault::NormalZero {
                        v: v(),
                        precision: precision(),
                        or_f64: or_f64::<R>(),
                    });
                };
                faces.normals.push(unit.unit);
            }
            Some("l") => return refuse(MeshFault::LineElement { v: v() }),
            Some("f") => {
                let refs: Vec<&str> = words.collect();
                if refs.len() < 3 {
                    return refuse(MeshFault::FewVertices {
                        v: v(),
                        n: refs.len(),
                    });
                }
                // Each vertex's normal index (`v//vn`, `v/vt/vn`), when it gives one.
                let mut vn: Vec<Option<u32>> = Vec::with_capacity(refs.len());
                for r in &refs {
                    let Some(word) = r.split('/').nth(2).filter(|w| !w.is_empty()) else {
                        vn.push(None);
                        continue;
                    };
                    let known = faces.normals.len() as i64;
                    let resolved = word
                        .parse::<i64>()
                        .ok()
                        .map(|k| if k < 0 { known + 1 + k } else { k })
                        .filter(|&k| k >= 1 && k <= known);
                    let Some(k) = resolved else {
                        return refuse(MeshFault::NormalIndex {
                            v: v(),
                            word: word.to_owned(),
                            r: (*r).to_owned(),
                            known,
                        });
                    };
                    vn.push(Some((k - 1) as u32));
                }
                let given = vn.iter().flatten().count();
                if given != 0 && given != vn.len() {
                    return refuse(MeshFault::PartialNormals {
                        v: v(),
                        given,
                        n: vn.len(),
                    });
                }
                for r in &refs {
                    let index = r.split('/').next().and_then(|v| v.parse::<i64>().ok());
                    // Negative indices count back from the last vertex so far (-1 is the last).
                    let resolved = index.map(|k| if k < 0 { vertices as i64 + 1 + k } else { k });
                    if !resolved.is_some_and(|k| k >= 1 && k <= vertices as i64) {
                        return refuse(MeshFault::VertexIndex {
                            v: v(),
                            r: (*r).to_owned(),
                            vertices,
                        });
                    }
                }
                triangles += refs.len() - 2;
                if triangles > MAX_TRIANGLES {
                    return refuse(MeshFault::TooManyTriangles { max: MAX_TRIANGLES });
                }
                faces.lines.push((n, refs.len() - 2));
                // The fan tobj splits the face into: (0, i, i + 1).
                for i in 1..refs.len() - 1 {
                    faces
                        .triangle_normals
                        .push(match (vn[0], vn[i], vn[i + 1]) {
                            (Some(a), Some(b), Some(c)) => Some([a, b, c]),
                            _ => None,
                        });
                }
            }
            None => {}
            Some(word) if word.starts_with('#') || STATEMENTS.contains(&word) => {}
            Some(word) => {
                return refuse(MeshFault::UnknownStatement {
                    v: v(),
                    word: Echo::new(word, 20),
                })
            }
        }
    }
    Ok(faces)
}

/// Reads the triangles of an OBJ file, in the file's order; a face with vertex normals gives
/// smooth triangles ([`Triangle::normals`]).
pub fn load_obj<R: Real>(path: &Path) -> Result<Vec<Triangle<R>>, MeshError> {
    let bytes = super::read_limited(path, MAX_MESH_BYTES, Input::Mesh).map_err(|e| {
        MeshError::of(MeshFault::Unreadable {
            cause: Cause::of(&e),
            fix: match ReadFix::of(&e) {
                ReadFix::CheckPath => ReadFix::CheckMeshPath,
                fix => fix,
            },
        })
    })?;
    let text = String::from_utf8_lossy(&bytes);
    // A byte order mark (as some Windows editors save UTF-8) is not part of the first line:
    // read with it, a first `v` line would be no statement.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let faces = scan::<R>(text)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    // The material loader is never asked to read anything: `.mtl` files are ignored.
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default()))
            .map_err(|e| MeshError::of(MeshFault::NotObj { error: ObjError(e) }))?;
    let mut out = Vec::new();
    let count: usize = faces.lines.iter().map(|&(_, n)| n).sum();
    crate::text::memory::handled(|| out.try_reserve_exact(count)).map_err(|_| {
        MeshError::of(MeshFault::OutOfMemory {
            memory: Limit::Memory {
                needs: super::reading::Bytes(
                    count.saturating_mul(std::mem::size_of::<Triangle<R>>()),
                ),
            },
        })
    })?;
    for model in &models {
        let pos = &model.mesh.positions;
        let corner = |i: u32| -> Result<V3<R>, MeshError> {
            let k = 3 * i as usize;
            let xyz = pos.get(k..k + 3).ok_or_else(|| {
                MeshError::of(MeshFault::MissingVertex {
                    index: i as usize + 1,
                })
            })?;
            let v = V3::<R>::new(
                R::from_f64(xyz[0]),
                R::from_f64(xyz[1]),
                R::from_f64(xyz[2]),
            );
            if !crate::core::Vector::is_finite(v) {
                return Err(MeshError::of(MeshFault::CornerNotFinite {
                    index: i as usize + 1,
                    precision: R::NAME.to_owned(),
                    or_f64: or_f64::<R>(),
                }));
            }
            // Within the bound the ray–triangle test can multiply (see `max_coordinate`).
            let max = crate::geometry::max_coordinate::<R>();
            if xyz.iter().any(|x| x.abs() > max) {
                return Err(MeshError::of(MeshFault::CornerTooLarge {
                    index: i as usize + 1,
                    precision: R::NAME.to_owned(),
                    max: Num(max),
                    or_f64: or_f64::<R>(),
                }));
            }
            Ok(v)
        };
        for face in model.mesh.indices.chunks_exact(3) {
            let normals = faces
                .triangle_normals
                .get(out.len())
                .copied()
                .flatten()
                .map(|k| k.map(|j| faces.normals[j as usize]));
            let t = Triangle {
                p: [corner(face[0])?, corner(face[1])?, corner(face[2])?],
                normals: normals.map(std::sync::Arc::new),
            };
            if t.normal().is_none() {
                // The object's name when the file gives one (`o name`); tobj's placeholder for
                // a file without `o` lines is not the user's word.
                let object = Object(match model.name.as_str() {
                    "unnamed_object" | "" => None,
                    name => Some(name.to_owned()),
                });
                return Err(MeshError::at_line(
                    faces.line_of(out.len()),
                    MeshFault::Degenerate {
                        k: out.len(),
                        object,
                        precision: R::NAME.to_owned(),
                    },
                ));
            }
            out.push(t);
        }
    }
    if out.is_empty() {
        return Err(MeshError::of(MeshFault::NoFaces));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::{Fault, Lang};

    /// The error message of scanning `text` in precision `R`.
    fn refused<R: Real>(text: &str) -> MeshError {
        match scan::<R>(text) {
            Ok(_) => panic!("{text:?} was accepted in {}", R::NAME),
            Err(e) => e,
        }
    }

    const CORNERS: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    #[test]
    fn vertex_normals_are_read_per_corner_through_a_polygon_s_fan() {
        // A quad with a normal at each corner, given by index and by negative index, then a
        // flat triangle: the fan (0, 1, 2), (0, 2, 3) as tobj splits it.
        let text = format!(
            "{CORNERS}vn 0 0 2\nvn 0 0.6 0.8\nvn 0.6 0 0.8\nf 1//1 2//2 3/7/3 4//-3\nf 1 2 3\n"
        );
        let faces = scan::<f64>(&text).unwrap();
        assert_eq!(
            faces.triangle_normals,
            vec![Some([0, 1, 2]), Some([0, 2, 0]), None]
        );
        // Each normal is normalised: (0, 0, 2) → (0, 0, 1).
        assert_eq!(faces.normals[0], V3::<f64>::new(0.0, 0.0, 1.0));
        assert_eq!(faces.lines, vec![(8, 2), (9, 1)]);
    }

    #[test]
    fn bad_vertex_normals_are_refused_naming_the_line_and_the_fix() {
        let zero = refused::<f64>(&format!("{CORNERS}vn 0 0 0\nf 1//1 2//1 3//1\n"));
        assert!(zero.message().starts_with("line 5: "), "{}", zero.message());
        assert!(zero.message().contains("length zero"), "{}", zero.message());
        assert!(
            zero.fix(Lang::En).contains("nonzero length"),
            "{}",
            zero.fix(Lang::En)
        );
        let nan = refused::<f64>(&format!("{CORNERS}vn nan 0 1\n"));
        assert!(nan
            .message()
            .contains("line 5: the vertex normal \"vn nan 0 1\" is not finite"));
        let inf = refused::<f64>(&format!("{CORNERS}vn 0 inf 1\n"));
        assert!(
            inf.message().contains("is not finite in f64"),
            "{}",
            inf.message()
        );
        let short = refused::<f64>(&format!("{CORNERS}vn 0 1\n"));
        assert!(
            short.message().contains("is not `vn x y z`"),
            "{}",
            short.message()
        );
        // Finite in f64 but not in f32; nonzero in f64 but zero in f32.
        assert!(scan::<f64>(&format!("{CORNERS}vn 0 1e39 1\n")).is_ok());
        let big = refused::<f32>(&format!("{CORNERS}vn 0 1e39 1\n"));
        assert!(
            big.message().contains("is not finite in f32"),
            "{}",
            big.message()
        );
        assert!(scan::<f64>(&format!("{CORNERS}vn 0 1e-50 0\n")).is_ok());
        let tiny = refused::<f32>(&format!("{CORNERS}vn 0 1e-50 0\n"));
        assert!(
            tiny.message().contains("length zero in f32"),
            "{}",
            tiny.message()
        );
        assert!(
            tiny.fix(Lang::En).contains("--precision f64"),
            "{}",
            tiny.fix(Lang::En)
        );
    }

    #[test]
    fn a_corner_past_the_largest_coordinate_is_refused_as_too_large_not_as_degenerate() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("m.obj");
        let face = |x: &str| format!("v -{x} -{x} 0\nv {x} -{x} 0\nv 0 {x} 0\nf 1 2 3\n");
        // ±1e308: the edges overflow, and the face was refused as degenerate.
        std::fs::write(&path, face("1e308")).unwrap();
        let e = load_obj::<f64>(&path).unwrap_err();
        assert!(
            e.message()
                .contains("vertex 1 is too large for a triangle in f64"),
            "{}",
            e.message()
        );
        assert_eq!(
            e.fix(Lang::En),
            "give coordinates within ±1e100 (scale the mesh down)"
        );
        std::fs::write(&path, face("1e13")).unwrap();
        assert!(load_obj::<f64>(&path).is_ok());
        let e = load_obj::<f32>(&path).unwrap_err();
        assert_eq!(
            e.fix(Lang::Pt),
            "dê coordenadas dentro de ±1e12 (reduza a escala da malha) (ou use --precision f64)"
        );
    }

    #[test]
    fn faces_with_missing_or_partial_normals_are_refused_naming_the_line() {
        let missing = refused::<f64>(&format!("{CORNERS}vn 0 0 1\nf 1//1 2//2 3//1\n"));
        assert!(
            missing
                .message()
                .contains("line 6: the face \"f 1//1 2//2 3//1\" refers to vertex normal 2"),
            "{}",
            missing.message()
        );
        assert!(missing
            .message()
            .contains("1 vertex normals come before it"));
        let ahead = refused::<f64>(&format!("{CORNERS}f 1//1 2//1 3//1\nvn 0 0 1\n"));
        assert!(
            ahead.message().starts_with("line 5: "),
            "{}",
            ahead.message()
        );
        let partial = refused::<f64>(&format!("{CORNERS}vn 0 0 1\nf 1//1 2 3//1\n"));
        assert!(
            partial
                .message()
                .contains("gives vertex normals for 2 of its 3 vertices"),
            "{}",
            partial.message()
        );
        assert!(
            partial.message().starts_with("line 6: "),
            "{}",
            partial.message()
        );
        assert!(
            partial.fix(Lang::En).contains("or none"),
            "{}",
            partial.fix(Lang::En)
        );
        // A texture coordinate without a normal is not a normal.
        let faces = scan::<f64>(&format!("{CORNERS}f 1/1 2/1 3/1\n")).unwrap();
        assert_eq!(faces.triangle_normals, vec![None]);
    }
}
