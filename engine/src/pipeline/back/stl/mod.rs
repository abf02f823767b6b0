//! STL back end: a mesh as a binary STL file. See [`write_binary`].
//!
//! Layout (little endian): an 80-byte header, the `u32` triangle count, then 50 bytes a triangle:
//! the unit normal (3 × `f32`), the three corners (9 × `f32`) and a `u16` attribute (0).
//!
//! - The header is `cad2mo <name>` padded with spaces; bytes of the name outside printable ASCII
//!   become `_` and it is cut to fit. It never begins with `solid`, so readers that sniff the first
//!   word do not take the file for ASCII.
//! - The normal is `(b - a) × (c - a)` normalised (right-hand rule on the corner order, computed in
//!   `f64`); degenerate triangles get the zero vector.
//! - Coordinates are written as they are in the mesh (metres, body frame). A corner index out of
//!   range (which the IR does not allow) is written as the origin.

use crate::pipeline::ir;

const HEADER_PREFIX: &[u8] = b"cad2mo ";

/// The 80-byte header for `solid_name`.
fn header(solid_name: &str) -> [u8; 80] {
    let mut h = [b' '; 80];
    h[..HEADER_PREFIX.len()].copy_from_slice(HEADER_PREFIX);
    for (dst, &c) in h[HEADER_PREFIX.len()..].iter_mut().zip(solid_name.as_bytes()) {
        *dst = if (0x20..0x7f).contains(&c) { c } else { b'_' };
    }
    h
}

/// Unit normal of a triangle, zero when degenerate.
fn normal(t: [[f32; 3]; 3]) -> [f32; 3] {
    let p = t.map(|v| v.map(f64::from));
    let e1 = [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]];
    let e2 = [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]];
    let n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        n.map(|x| (x / len) as f32)
    } else {
        [0.0; 3]
    }
}

/// The mesh as a binary STL named `solid_name` (the name goes into the header only).
pub fn write_binary(mesh: &ir::Mesh, solid_name: &str) -> Vec<u8> {
    let count = u32::try_from(mesh.triangles.len()).unwrap_or(u32::MAX);
    let mut out = Vec::with_capacity(84 + 50 * count as usize);
    out.extend_from_slice(&header(solid_name));
    out.extend_from_slice(&count.to_le_bytes());
    let corner = |i: u32| mesh.vertices.get(i as usize).copied().unwrap_or([0.0; 3]);
    for t in mesh.triangles.iter().take(count as usize) {
        let c = t.map(corner);
        let mut rec = [0u8; 50];
        let floats = normal(c).into_iter().chain(c.into_iter().flatten());
        for (dst, x) in rec.chunks_exact_mut(4).zip(floats) {
            dst.copy_from_slice(&x.to_le_bytes());
        }
        out.extend_from_slice(&rec);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mesh() -> ir::Mesh {
        ir::Mesh {
            vertices: vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [4.0, 0.0, 0.0]],
            triangles: vec![[0, 1, 2], [0, 2, 1], [0, 1, 3]],
        }
    }

    fn f32_at(b: &[u8], o: usize) -> f32 {
        f32::from_le_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]])
    }

    #[test]
    fn layout_header_count_normals() {
        let b = write_binary(&mesh(), "solid arm\u{e9}\n");
        assert_eq!(b.len(), 84 + 3 * 50);
        assert!(b.starts_with(b"cad2mo solid arm___    "));
        assert!(b[..80].iter().all(|c| (0x20..0x7f).contains(c)));
        assert!(!b.starts_with(b"solid"));
        assert_eq!(u32::from_le_bytes([b[80], b[81], b[82], b[83]]), 3);
        let n = |t: usize| [0, 1, 2].map(|k| f32_at(&b, 84 + 50 * t + 4 * k));
        assert_eq!(n(0), [0.0, 0.0, 1.0]);
        assert_eq!(n(1), [0.0, 0.0, -1.0]);
        assert_eq!(n(2), [0.0, 0.0, 0.0], "degenerate");
        assert_eq!(f32_at(&b, 84 + 50 + 12 + 12 + 4), 3.0, "second corner of triangle 1 is vertex 2");
        assert_eq!(&b[84 + 48..84 + 50], &[0, 0]);
    }

    #[test]
    fn long_name_is_cut_and_empty_mesh_is_valid() {
        let b = write_binary(&mesh(), &"x".repeat(200));
        assert_eq!(&b[..7], b"cad2mo ");
        assert_eq!(b[79], b'x');
        let e = write_binary(&ir::Mesh::default(), "");
        assert_eq!(e.len(), 84);
        assert!(crate::pipeline::front::stl::is_binary(&e));
    }
}
