//! Mesh files named by URDF (and primitives of URDF shapes): bytes in, an [`ir::Mesh`] out.
//! See [`read`].
//!
//! # Formats, by extension (case-insensitive)
//! - `.stl`: our own reader, [`super::stl::parse`] (binary files whose header begins with `solid`
//!   are binary by the size rule).
//! - `.obj`: the `tobj` crate, polygons fan-triangulated, every object and group of the file
//!   appended; vertices as written (OBJ has no unit: metres). Materials (`mtllib`) are not read.
//! - `.dae`: COLLADA 1.4 and 1.5, our own reader over quick-xml ([`collada`], which says why not
//!   the `dae-parser` crate): `<unit meter>`, `<up_axis>`, the visual scene's node transforms and
//!   the triangles, polylists, polygons, triangle fans and strips of every instanced geometry.
//! - `.step`, `.stp`: ISO 10303-21 B-rep (AP203, AP214, AP242), tessellated by [`step`]: units,
//!   assembly placements applied; its warnings (faces that could not be meshed) are dropped by
//!   [`read`], callers that report them use [`step::read`].
//!
//! # Output
//! Vertices in metres in the mesh file's own frame with Z up (a COLLADA `Y_UP` or `X_UP` file is
//! turned to Z up the way the COLLADA specification says, see [`collada`] for the evidence), every
//! coordinate finite, every index in range, at least one triangle; vertices no triangle uses are
//! dropped (OBJ, COLLADA). The reader does not apply URDF's `<mesh scale>`: see [`scaled`].
//!
//! # Errors
//! A [`MeshError`] names the file, the 1-based line where one is known (XML syntax and COLLADA
//! elements; OBJ syntax; ASCII STL) and what is wrong, e.g.
//! `meshes/arm.dae:40: <p> index 95 is out of range: source "arm-positions" has 8 points`.
//! No input makes the readers panic; a file that would give more than [`MAX_TRIANGLES`]
//! triangles is refused.

pub mod collada;
mod obj;
mod primitives;
pub mod step;
#[cfg(test)]
mod tests;

pub use primitives::{box_mesh, cylinder_mesh, sphere_mesh, CYLINDER_SEGMENTS, SPHERE_SLICES, SPHERE_STACKS};

use crate::pipeline::ir;

/// Upper bound on the triangles read from one mesh file.
pub const MAX_TRIANGLES: usize = 10_000_000;

/// At most this many triangles in all the bodies' meshes of one bundle, counted after
/// instancing (a file named by several bodies counts once per use), by the URDF front end before
/// any copy is made and by `passes::geometry` as each STL is read. A conversion holds its output
/// in memory, about 190 bytes per triangle (binary STL and DXF text of every shape besides the
/// meshes): 5 M triangles convert within about 1.2 GB (README, "Limits").
pub const MAX_BUNDLE_TRIANGLES: usize = 5_000_000;

/// A mesh file that could not be read.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}{kind}", location(.file, .line))]
pub struct MeshError {
    /// The name the caller gave (a bundle path).
    pub file: String,
    /// 1-based line; 0 when not known (binary files, whole-file errors).
    pub line: u32,
    pub kind: MeshErrorKind,
}

fn location(file: &str, line: &u32) -> String {
    if *line == 0 {
        format!("{file}: ")
    } else {
        format!("{file}:{line}: ")
    }
}

/// What is wrong with a mesh file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshErrorKind {
    #[error("unsupported mesh format {}: supported are .stl, .obj, .dae (COLLADA) and .step/.stp", ext_text(.ext))]
    UnsupportedFormat { ext: String },
    /// The STL reader's error (its line is the [`MeshError`]'s).
    #[error("{0}")]
    Stl(super::stl::ErrorKind),
    /// The OBJ reader's complaint (`tobj`'s words).
    #[error("OBJ: {0}")]
    Obj(String),
    /// Not well-formed XML.
    #[error("XML: {0}")]
    Xml(String),
    /// Well-formed XML that is not usable COLLADA.
    #[error("COLLADA: {0}")]
    Collada(String),
    /// STEP: syntax, limits, nothing meshable.
    #[error("STEP: {0}")]
    Step(String),
    #[error("no triangles in the file")]
    Empty,
    /// `vertex` counts from 1 in the order of the output mesh.
    #[error("vertex {vertex} is not finite (NaN or infinite coordinate, in the file or after scaling)")]
    NonFinite { vertex: usize },
    #[error("triangle index {index} is out of range: {vertices} vertices")]
    BadIndex { index: u32, vertices: usize },
    #[error("more than {max} triangles")]
    TooManyTriangles { max: usize },
}

fn ext_text(ext: &str) -> String {
    if ext.is_empty() {
        "(no extension)".to_string()
    } else {
        format!("\".{}\"", ir::clip(ext, 40))
    }
}

impl MeshError {
    pub(crate) fn new(file: &str, line: u32, kind: MeshErrorKind) -> Self {
        MeshError { file: file.to_string(), line, kind }
    }
}

/// The extension of `path` (after the last `.` of its last component), lower case.
fn extension(path: &str) -> String {
    let name = path.rsplit(['/', '\\']).next().unwrap_or(path);
    match name.rfind('.') {
        Some(i) if i + 1 < name.len() => name[i + 1..].to_ascii_lowercase(),
        _ => String::new(),
    }
}

/// Reads a mesh file, choosing the reader by the extension of `path` (case-insensitive): `.stl`,
/// `.obj`, `.dae`, `.step` or `.stp`. `path` also names the file in errors. See the module docs for the output.
pub fn read(path: &str, bytes: &[u8]) -> Result<ir::Mesh, MeshError> {
    let mesh = match extension(path).as_str() {
        "stl" => super::stl::parse(path, bytes, 1.0).map_err(|e| MeshError::new(path, e.line, MeshErrorKind::Stl(e.kind)))?,
        "obj" => obj::read(path, bytes)?,
        "dae" => collada::read(path, bytes)?,
        "step" | "stp" => step::read(path, bytes)?.mesh,
        other => return Err(MeshError::new(path, 0, MeshErrorKind::UnsupportedFormat { ext: other.to_string() })),
    };
    finish(path, mesh)
}

/// Checks the [`ir::Mesh`] invariants (finite vertices, indices in range), at least one triangle,
/// at most [`MAX_TRIANGLES`]; drops vertices no triangle uses.
pub(crate) fn finish(path: &str, mesh: ir::Mesh) -> Result<ir::Mesh, MeshError> {
    let err = |kind| MeshError::new(path, 0, kind);
    if mesh.triangles.is_empty() {
        return Err(err(MeshErrorKind::Empty));
    }
    if mesh.triangles.len() > MAX_TRIANGLES {
        return Err(err(MeshErrorKind::TooManyTriangles { max: MAX_TRIANGLES }));
    }
    let n = mesh.vertices.len();
    let mut map = vec![u32::MAX; n];
    let mut vertices = Vec::with_capacity(n);
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    for t in &mesh.triangles {
        let mut out = [0u32; 3];
        for (o, &i) in out.iter_mut().zip(t) {
            let Some(slot) = map.get_mut(i as usize) else {
                return Err(err(MeshErrorKind::BadIndex { index: i, vertices: n }));
            };
            if *slot == u32::MAX {
                let v = mesh.vertices[i as usize];
                if !v.iter().all(|x| x.is_finite()) {
                    return Err(err(MeshErrorKind::NonFinite { vertex: vertices.len() + 1 }));
                }
                *slot = vertices.len() as u32;
                vertices.push(v);
            }
            *o = *slot;
        }
        triangles.push(out);
    }
    Ok(ir::Mesh { vertices, triangles })
}

/// `mesh` with every vertex multiplied component-wise by `scale` (URDF's `<mesh scale>`, which may
/// be non-uniform or negative: an odd number of negative factors mirrors the mesh, so the
/// triangles' corner order is reversed to keep them outward-wound). `file` names the mesh in the
/// error returned when a scaled coordinate is not finite (a scale factor that is NaN or infinite,
/// or a result beyond `f32`).
pub fn scaled(file: &str, mesh: &ir::Mesh, scale: [f64; 3]) -> Result<ir::Mesh, MeshError> {
    let mut vertices = Vec::with_capacity(mesh.vertices.len());
    for (k, v) in mesh.vertices.iter().enumerate() {
        let s = [0, 1, 2].map(|j| (f64::from(v[j]) * scale[j]) as f32);
        if !s.iter().all(|x| x.is_finite()) {
            return Err(MeshError::new(file, 0, MeshErrorKind::NonFinite { vertex: k + 1 }));
        }
        vertices.push(s);
    }
    let mirrored = scale.iter().filter(|s| **s < 0.0).count() % 2 == 1;
    let triangles = if mirrored { mesh.triangles.iter().map(|t| [t[0], t[2], t[1]]).collect() } else { mesh.triangles.clone() };
    Ok(ir::Mesh { vertices, triangles })
}
