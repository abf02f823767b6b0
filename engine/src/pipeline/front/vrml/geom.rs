//! Triangulation of indexed polygons and tessellation of the primitive shapes.

use std::f64::consts::TAU;

use super::ast::Prim;
use crate::pipeline::ir::Mesh;

/// Segments around the axis of a Sphere, Cylinder or Cone.
pub(super) const SEGMENTS: usize = 24;
/// Latitude bands of a Sphere.
pub(super) const RINGS: usize = 12;
/// Polygons with more corners than this are fanned without the concavity check.
const MAX_EAR_CLIP: usize = 512;

/// An index that names no point: the index as written, and the number of points.
#[derive(Debug, PartialEq)]
pub(super) struct BadIndex {
    pub index: i32,
    pub count: usize,
}

/// Triangles of the polygons in `index` (`-1`-separated, a trailing `-1` optional) over
/// `points`. Polygons of fewer than 3 indices are skipped. Convex polygons are fanned; concave
/// ones ear-clipped in the plane of their Newell normal. `ccw = false` flips every triangle.
/// Points no triangle uses are dropped (indices renumbered in order).
pub(super) fn indexed_mesh(points: &[[f32; 3]], index: &[i32], ccw: bool) -> Result<Mesh, BadIndex> {
    let count = points.len();
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(index.len() / 4 + 1);
    let mut poly: Vec<u32> = Vec::new();
    let mut start = 0;
    while start < index.len() {
        let end = index[start..].iter().position(|&i| i == -1).map_or(index.len(), |p| start + p);
        let face = &index[start..end];
        for &i in face {
            if i < 0 || i as usize >= count {
                return Err(BadIndex { index: i, count });
            }
        }
        match face.len() {
            0..=2 => {}
            3 => tris.push([face[0] as u32, face[1] as u32, face[2] as u32]),
            _ => {
                poly.clear();
                poly.extend(face.iter().map(|&i| i as u32));
                polygon(&poly, points, &mut tris);
            }
        }
        start = end + 1;
    }
    if !ccw {
        for t in &mut tris {
            t.swap(1, 2);
        }
    }
    Ok(compact(points, tris))
}

/// A mesh of `tris` over only the points they use.
fn compact(points: &[[f32; 3]], mut tris: Vec<[u32; 3]>) -> Mesh {
    let mut used = vec![false; points.len()];
    for t in &tris {
        for &i in t {
            used[i as usize] = true;
        }
    }
    if used.iter().all(|&u| u) {
        return Mesh { vertices: points.to_vec(), triangles: tris };
    }
    let mut map = vec![u32::MAX; points.len()];
    let mut vertices = Vec::new();
    for (i, p) in points.iter().enumerate() {
        if used[i] {
            map[i] = vertices.len() as u32;
            vertices.push(*p);
        }
    }
    for t in &mut tris {
        for i in t.iter_mut() {
            *i = map[*i as usize];
        }
    }
    Mesh { vertices, triangles: tris }
}

fn p64(p: [f32; 3]) -> [f64; 3] {
    [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])]
}

/// Triangulates one polygon of 4 or more corners (indices into `points`).
fn polygon(poly: &[u32], points: &[[f32; 3]], out: &mut Vec<[u32; 3]>) {
    let fan = |out: &mut Vec<[u32; 3]>, idx: &[u32]| {
        for k in 1..idx.len() - 1 {
            out.push([idx[0], idx[k], idx[k + 1]]);
        }
    };
    let n = poly.len();
    if n > MAX_EAR_CLIP {
        fan(out, poly);
        return;
    }
    // Newell normal, then 2D coordinates in which the polygon runs counter-clockwise.
    let mut nrm = [0.0f64; 3];
    for k in 0..n {
        let a = p64(points[poly[k] as usize]);
        let b = p64(points[poly[(k + 1) % n] as usize]);
        nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    let ax = (0..3).max_by(|&i, &j| nrm[i].abs().total_cmp(&nrm[j].abs())).unwrap_or(2);
    if nrm[ax].abs() <= 0.0 || !nrm[ax].is_finite() {
        fan(out, poly);
        return;
    }
    let (u, v) = match ax {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    };
    let flip = nrm[ax] < 0.0;
    let pts: Vec<[f64; 2]> = poly
        .iter()
        .map(|&i| {
            let p = p64(points[i as usize]);
            if flip {
                [p[v], p[u]]
            } else {
                [p[u], p[v]]
            }
        })
        .collect();
    let cross = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    let convex = (0..n).all(|k| cross(pts[(k + n - 1) % n], pts[k], pts[(k + 1) % n]) >= 0.0);
    if convex {
        fan(out, poly);
        return;
    }
    // Ear clipping.
    let mut idx: Vec<usize> = (0..n).collect();
    while idx.len() > 3 {
        let m = idx.len();
        let mut clipped = false;
        for k in 0..m {
            let (ia, ib, ic) = (idx[(k + m - 1) % m], idx[k], idx[(k + 1) % m]);
            let (a, b, c) = (pts[ia], pts[ib], pts[ic]);
            if cross(a, b, c) <= 0.0 {
                continue;
            }
            let blocked = idx.iter().any(|&j| {
                if j == ia || j == ib || j == ic {
                    return false;
                }
                let p = pts[j];
                if p == a || p == b || p == c {
                    return false;
                }
                cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0
            });
            if blocked {
                continue;
            }
            out.push([poly[ia], poly[ib], poly[ic]]);
            idx.remove(k);
            clipped = true;
            break;
        }
        if !clipped {
            // Self-intersecting or degenerate: fan what is left.
            let rest: Vec<u32> = idx.iter().map(|&i| poly[i]).collect();
            fan(out, &rest);
            return;
        }
    }
    out.push([poly[idx[0]], poly[idx[1]], poly[idx[2]]]);
}

/// Outward-facing, counter-clockwise triangles of a primitive centred on the origin (the
/// Cylinder's and Cone's axis along y).
pub(super) fn primitive(p: &Prim) -> Mesh {
    let mut m = Mesh { vertices: Vec::new(), triangles: Vec::new() };
    let vert = |m: &mut Mesh, x: f64, y: f64, z: f64| {
        m.vertices.push([x as f32, y as f32, z as f32]);
        (m.vertices.len() - 1) as u32
    };
    let ring = |k: usize| {
        let a = TAU * k as f64 / SEGMENTS as f64;
        (a.sin(), a.cos())
    };
    match *p {
        Prim::Box { size } => {
            let [hx, hy, hz] = [size[0] / 2.0, size[1] / 2.0, size[2] / 2.0];
            for k in 0..8 {
                let x = if k & 1 == 0 { -hx } else { hx };
                let y = if k & 2 == 0 { -hy } else { hy };
                let z = if k & 4 == 0 { -hz } else { hz };
                vert(&mut m, x, y, z);
            }
            // Faces as quads (corner bits x=1, y=2, z=4), counter-clockwise seen from outside.
            for q in [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]] {
                m.triangles.push([q[0], q[1], q[2]]);
                m.triangles.push([q[0], q[2], q[3]]);
            }
        }
        Prim::Sphere { radius: r } => {
            let top = vert(&mut m, 0.0, r, 0.0);
            for i in 1..RINGS {
                let phi = std::f64::consts::PI * i as f64 / RINGS as f64;
                for k in 0..SEGMENTS {
                    let (s, c) = ring(k);
                    vert(&mut m, r * phi.sin() * s, r * phi.cos(), r * phi.sin() * c);
                }
            }
            let bottom = vert(&mut m, 0.0, -r, 0.0);
            let at = |i: usize, k: usize| (1 + (i - 1) * SEGMENTS + k % SEGMENTS) as u32;
            for k in 0..SEGMENTS {
                m.triangles.push([top, at(1, k), at(1, k + 1)]);
                for i in 1..RINGS - 1 {
                    m.triangles.push([at(i, k), at(i + 1, k), at(i + 1, k + 1)]);
                    m.triangles.push([at(i, k), at(i + 1, k + 1), at(i, k + 1)]);
                }
                m.triangles.push([at(RINGS - 1, k), bottom, at(RINGS - 1, k + 1)]);
            }
        }
        Prim::Cylinder { radius: r, height: h, bottom, top, side } => {
            let base = m.vertices.len() as u32;
            for k in 0..SEGMENTS {
                let (s, c) = ring(k);
                vert(&mut m, r * s, h / 2.0, r * c);
                vert(&mut m, r * s, -h / 2.0, r * c);
            }
            let up = |k: usize| base + 2 * (k % SEGMENTS) as u32;
            let down = |k: usize| base + 2 * (k % SEGMENTS) as u32 + 1;
            if side {
                for k in 0..SEGMENTS {
                    m.triangles.push([up(k), down(k), down(k + 1)]);
                    m.triangles.push([up(k), down(k + 1), up(k + 1)]);
                }
            }
            if top {
                let c = vert(&mut m, 0.0, h / 2.0, 0.0);
                for k in 0..SEGMENTS {
                    m.triangles.push([c, up(k), up(k + 1)]);
                }
            }
            if bottom {
                let c = vert(&mut m, 0.0, -h / 2.0, 0.0);
                for k in 0..SEGMENTS {
                    m.triangles.push([c, down(k + 1), down(k)]);
                }
            }
        }
        Prim::Cone { bottom_radius: r, height: h, side, bottom } => {
            let base = m.vertices.len() as u32;
            for k in 0..SEGMENTS {
                let (s, c) = ring(k);
                vert(&mut m, r * s, -h / 2.0, r * c);
            }
            let rim = |k: usize| base + (k % SEGMENTS) as u32;
            if side {
                let apex = vert(&mut m, 0.0, h / 2.0, 0.0);
                for k in 0..SEGMENTS {
                    m.triangles.push([apex, rim(k), rim(k + 1)]);
                }
            }
            if bottom {
                let c = vert(&mut m, 0.0, -h / 2.0, 0.0);
                for k in 0..SEGMENTS {
                    m.triangles.push([c, rim(k + 1), rim(k)]);
                }
            }
        }
    }
    compact(&m.vertices, m.triangles)
}
