//! URDF's geometric primitives as closed triangle meshes, centred at the origin, triangles wound
//! counter-clockwise seen from outside (so the signed volume is positive). Sizes in metres; the
//! caller checks that they are finite and positive.

use crate::pipeline::ir;
use std::f64::consts::PI;

/// Segments around a cylinder.
pub const CYLINDER_SEGMENTS: usize = 32;
/// Segments of a sphere around its z axis (longitude).
pub const SPHERE_SLICES: usize = 32;
/// Segments of a sphere from pole to pole (latitude).
pub const SPHERE_STACKS: usize = 16;

fn v(x: f64, y: f64, z: f64) -> [f32; 3] {
    [x as f32, y as f32, z as f32]
}

/// URDF `<box size="x y z">`: edges along the axes, `size` the full edge lengths.
pub fn box_mesh(size: [f64; 3]) -> ir::Mesh {
    let [hx, hy, hz] = size.map(|s| s / 2.0);
    // Corner k has x = ±hx by bit 0, y by bit 1, z by bit 2.
    let vertices = (0..8)
        .map(|k| v(if k & 1 == 0 { -hx } else { hx }, if k & 2 == 0 { -hy } else { hy }, if k & 4 == 0 { -hz } else { hz }))
        .collect();
    let quads: [[u32; 4]; 6] = [
        [0, 2, 3, 1], // -z
        [4, 5, 7, 6], // +z
        [0, 1, 5, 4], // -y
        [2, 6, 7, 3], // +y
        [0, 4, 6, 2], // -x
        [1, 3, 7, 5], // +x
    ];
    let triangles = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    ir::Mesh { vertices, triangles }
}

/// URDF `<cylinder radius length>`: axis along z, from `-length/2` to `length/2`, capped;
/// [`CYLINDER_SEGMENTS`] segments around (the polygon's corners lie on the circle).
pub fn cylinder_mesh(radius: f64, length: f64) -> ir::Mesh {
    let n = CYLINDER_SEGMENTS;
    let h = length / 2.0;
    let mut vertices = Vec::with_capacity(2 * n + 2);
    for z in [-h, h] {
        for i in 0..n {
            let a = 2.0 * PI * i as f64 / n as f64;
            vertices.push(v(radius * a.cos(), radius * a.sin(), z));
        }
    }
    let (bottom, top) = (2 * n as u32, 2 * n as u32 + 1);
    vertices.push(v(0.0, 0.0, -h));
    vertices.push(v(0.0, 0.0, h));
    let mut triangles = Vec::with_capacity(4 * n);
    for i in 0..n as u32 {
        let j = (i + 1) % n as u32;
        let (b0, b1, t0, t1) = (i, j, i + n as u32, j + n as u32);
        triangles.push([b0, b1, t1]);
        triangles.push([b0, t1, t0]);
        triangles.push([top, t0, t1]);
        triangles.push([bottom, b1, b0]);
    }
    ir::Mesh { vertices, triangles }
}

/// URDF `<sphere radius>`: a UV sphere of [`SPHERE_SLICES`] × [`SPHERE_STACKS`] segments, poles on
/// the z axis (corners on the sphere).
pub fn sphere_mesh(radius: f64) -> ir::Mesh {
    let (slices, stacks) = (SPHERE_SLICES as u32, SPHERE_STACKS as u32);
    let mut vertices = vec![v(0.0, 0.0, radius)];
    for k in 1..stacks {
        let theta = PI * f64::from(k) / f64::from(stacks);
        for j in 0..slices {
            let phi = 2.0 * PI * f64::from(j) / f64::from(slices);
            vertices.push(v(radius * theta.sin() * phi.cos(), radius * theta.sin() * phi.sin(), radius * theta.cos()));
        }
    }
    let south = vertices.len() as u32;
    vertices.push(v(0.0, 0.0, -radius));
    // Ring k (1-based, from the north) starts at 1 + (k - 1) × slices.
    let ring = |k: u32, j: u32| 1 + (k - 1) * slices + j % slices;
    let mut triangles = Vec::with_capacity(2 * (slices * (stacks - 1)) as usize);
    for j in 0..slices {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        for k in 1..stacks - 1 {
            let (a, b, c, d) = (ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
        triangles.push([ring(stacks - 1, j), south, ring(stacks - 1, j + 1)]);
    }
    ir::Mesh { vertices, triangles }
}
