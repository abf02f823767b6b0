//! OBJ through the `tobj` crate: `v` and `f` records of every object and group (polygons
//! fan-triangulated by `tobj`; negative, relative indices resolved), everything else ignored
//! (normals, texture coordinates, points, lines, materials: `mtllib` is not opened).

use super::{MeshError, MeshErrorKind, MAX_TRIANGLES};
use crate::pipeline::ir;
use std::io::{BufRead, Read};

/// The bytes, handed to `tobj` line by line, counting how far it has read: when it stops on a
/// syntax error, the line it last read is the bad one.
struct Lines<'a> {
    bytes: &'a [u8],
    pos: usize,
}

impl Lines<'_> {
    /// 1-based number of the line read last.
    fn line(&self) -> u32 {
        let read = &self.bytes[..self.pos.min(self.bytes.len())];
        let breaks = read.iter().filter(|&&b| b == b'\n').count();
        let n = if read.last().is_some_and(|&b| b != b'\n') { breaks + 1 } else { breaks };
        u32::try_from(n).unwrap_or(u32::MAX)
    }
}

impl Read for Lines<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let rest = self.fill_buf()?;
        let n = rest.len().min(buf.len());
        buf[..n].copy_from_slice(&rest[..n]);
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for Lines<'_> {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        Ok(self.bytes.get(self.pos..).unwrap_or(&[]))
    }
    fn consume(&mut self, amt: usize) {
        self.pos = (self.pos + amt).min(self.bytes.len());
    }
}

/// What `tobj` says, in words that say which record is wrong; `true` when the error comes from the
/// line just read (syntax), `false` when it is found later (indices are checked per object).
fn describe(e: &tobj::LoadError) -> (String, bool) {
    use tobj::LoadError as E;
    match e {
        E::ReadError => ("the line is not UTF-8 text".to_string(), true),
        E::PositionParseError => ("bad vertex record (\"v x y z\" needs three numbers)".to_string(), true),
        E::ScalingByZeroError => ("vertex weight w is 0".to_string(), true),
        E::NormalParseError => ("bad normal record (\"vn\")".to_string(), true),
        E::TexcoordParseError => ("bad texture coordinate record (\"vt\")".to_string(), true),
        E::ColorParseError => ("bad vertex colour".to_string(), true),
        E::FaceParseError => ("bad face record (\"f\" needs vertex indices like 1, 1/2, 1//3 or 1/2/3)".to_string(), true),
        E::UnrecognizedCharacter | E::InvalidObjectName | E::MaterialParseError => (e.to_string(), true),
        E::FaceVertexOutOfBounds => ("a face refers to a vertex that does not exist".to_string(), false),
        E::FaceTexCoordOutOfBounds => ("a face refers to a texture coordinate that does not exist".to_string(), false),
        E::FaceNormalOutOfBounds => ("a face refers to a normal that does not exist".to_string(), false),
        E::InvalidPolygon => ("a face has fewer than three vertices".to_string(), false),
        _ => (e.to_string(), false),
    }
}

/// Reads an OBJ file; the caller checks the invariants ([`super::finish`]).
pub(super) fn read(file: &str, bytes: &[u8]) -> Result<ir::Mesh, MeshError> {
    let opts = tobj::LoadOptions { triangulate: true, single_index: false, ignore_points: true, ignore_lines: true };
    let mut lines = Lines { bytes, pos: 0 };
    let (models, _materials) = match tobj::load_obj_buf(&mut lines, &opts, |_| Err(tobj::LoadError::OpenFileFailed)) {
        Ok(r) => r,
        Err(e) => {
            let (what, at_line) = describe(&e);
            let line = if at_line { lines.line() } else { 0 };
            return Err(MeshError::new(file, line, MeshErrorKind::Obj(what)));
        }
    };
    let mut mesh = ir::Mesh::default();
    for m in &models {
        let base = mesh.vertices.len();
        if mesh.triangles.len() + m.mesh.indices.len() / 3 > MAX_TRIANGLES {
            return Err(MeshError::new(file, 0, MeshErrorKind::TooManyTriangles { max: MAX_TRIANGLES }));
        }
        mesh.vertices.extend(m.mesh.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
        let n = m.mesh.positions.len() / 3;
        for t in m.mesh.indices.chunks_exact(3) {
            let mut tri = [0u32; 3];
            for (o, &i) in tri.iter_mut().zip(t) {
                if i as usize >= n {
                    return Err(MeshError::new(file, 0, MeshErrorKind::BadIndex { index: i, vertices: n }));
                }
                *o = u32::try_from(base + i as usize)
                    .map_err(|_| MeshError::new(file, 0, MeshErrorKind::TooManyTriangles { max: MAX_TRIANGLES }))?;
            }
            mesh.triangles.push(tri);
        }
    }
    Ok(mesh)
}
