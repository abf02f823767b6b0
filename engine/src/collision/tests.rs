use std::f64::consts::PI;

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

use super::*;
use crate::pipeline::ir::Mesh;

fn mesh(vs: &[[f64; 3]], ts: &[[u32; 3]]) -> Mesh {
    Mesh { vertices: vs.iter().map(|v| [v[0] as f32, v[1] as f32, v[2] as f32]).collect(), triangles: ts.to_vec() }
}

/// Axis-aligned box mesh [lo, hi], outward triangles.
fn box_mesh(lo: [f64; 3], hi: [f64; 3]) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let vs: Vec<[f64; 3]> = (0..8).map(|k| std::array::from_fn(|i| if k & (1 << i) != 0 { hi[i] } else { lo[i] })).collect();
    let ts = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    (vs, ts)
}

fn uv_sphere(c: [f64; 3], r: f64, nu: usize, nv: usize) -> Mesh {
    let mut vs = vec![[c[0], c[1], c[2] + r], [c[0], c[1], c[2] - r]];
    for i in 1..nu {
        let th = PI * i as f64 / nu as f64;
        for j in 0..nv {
            let ph = 2.0 * PI * j as f64 / nv as f64;
            vs.push([c[0] + r * th.sin() * ph.cos(), c[1] + r * th.sin() * ph.sin(), c[2] + r * th.cos()]);
        }
    }
    let ring = |i: usize, j: usize| (2 + (i - 1) * nv + j % nv) as u32;
    let mut ts = Vec::new();
    for j in 0..nv {
        ts.push([0, ring(1, j), ring(1, j + 1)]);
        ts.push([1, ring(nu - 1, j + 1), ring(nu - 1, j)]);
    }
    for i in 1..nu - 1 {
        for j in 0..nv {
            ts.push([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)]);
            ts.push([ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)]);
        }
    }
    mesh(&vs, &ts)
}

fn cylinder_mesh(r: f64, h: f64, n: usize) -> Mesh {
    let mut vs = vec![[0.0, 0.0, 0.0], [0.0, 0.0, h]];
    for z in [0.0, h] {
        for j in 0..n {
            let a = 2.0 * PI * j as f64 / n as f64;
            vs.push([r * a.cos(), r * a.sin(), z]);
        }
    }
    let bot = |j: usize| (2 + j % n) as u32;
    let top = |j: usize| (2 + n + j % n) as u32;
    let mut ts = Vec::new();
    for j in 0..n {
        ts.push([0, bot(j + 1), bot(j)]);
        ts.push([1, top(j), top(j + 1)]);
        ts.push([bot(j), bot(j + 1), top(j + 1)]);
        ts.push([bot(j), top(j + 1), top(j)]);
    }
    mesh(&vs, &ts)
}

/// An L: two bars 1 × 0.2 × 0.2 m, as one closed mesh (a prism over an L-shaped polygon).
fn l_mesh() -> Mesh {
    let poly = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.2], [0.2, 0.2], [0.2, 1.0], [0.0, 1.0]];
    let n = poly.len();
    let mut vs = Vec::new();
    for z in [0.0, 0.2] {
        for p in &poly {
            vs.push([p[0], p[1], z]);
        }
    }
    // Caps triangulated by hand (counter-clockwise polygon): 0-1-2-3, 0-3-4-5.
    let caps = [[0u32, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]];
    let mut ts = Vec::new();
    for c in caps {
        ts.push([c[0], c[2], c[1]]); // bottom, facing -z
        ts.push([c[0] + n as u32, c[1] + n as u32, c[2] + n as u32]);
    }
    for j in 0..n {
        let (a, b) = (j as u32, ((j + 1) % n) as u32);
        let (c, d) = (a + n as u32, b + n as u32);
        ts.push([a, b, d]);
        ts.push([a, d, c]);
    }
    mesh(&vs, &ts)
}

fn opts() -> ShapeOptions {
    ShapeOptions::default()
}

#[test]
fn cube_is_a_box_with_zero_fit_error() {
    let (vs, ts) = box_mesh([0.0, 0.0, 0.0], [0.1, 0.2, 0.3]);
    let s = body_shape(&mesh(&vs, &ts), &opts());
    assert_eq!(s.kind, ShapeKind::Box, "{s:?}");
    assert_eq!(s.kind.name(), "box");
    assert_eq!(s.vertex_count, 8);
    assert!(s.fit_error < 1e-6, "{}", s.fit_error);
    assert!((s.volume_ratio - 1.0).abs() < 1e-5, "{}", s.volume_ratio);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.source_triangles, 12);
}

#[test]
fn rotated_cube_is_a_box() {
    let (vs, ts) = box_mesh([-0.05, -0.05, -0.05], [0.05, 0.05, 0.05]);
    let q = UnitQuaternion::from_euler_angles(0.3, 0.5, 0.7);
    let vs: Vec<[f64; 3]> = vs.iter().map(|v| (q * Vector3::from(*v)).into()).collect();
    let s = body_shape(&mesh(&vs, &ts), &opts());
    assert_eq!(s.kind, ShapeKind::Box, "{s:?}");
    assert!(s.fit_error < 1e-5, "{}", s.fit_error);
}

#[test]
fn tessellated_sphere_is_a_sphere() {
    let s = body_shape(&uv_sphere([0.1, 0.2, 0.3], 0.05, 16, 32), &opts());
    assert_eq!(s.kind, ShapeKind::Sphere, "{s:?}");
    assert_eq!(s.parts.len(), 1);
    let p = &s.parts[0];
    assert_eq!(p.vertices.len(), 1);
    assert!((p.radius - 0.05).abs() < 1e-4, "{}", p.radius);
    for (c, e) in p.vertices[0].iter().zip([0.1, 0.2, 0.3]) {
        assert!((c - e).abs() < 1e-5);
    }
    assert!(s.fit_error < 0.05 * 0.02 * 4.0 && s.fit_error > 0.0, "{}", s.fit_error);
}

#[test]
fn cylinder_mesh_is_a_cylinder() {
    let s = body_shape(&cylinder_mesh(0.04, 0.2, 48), &opts());
    assert_eq!(s.kind, ShapeKind::Cylinder, "{s:?}");
    // Prism error R(1/cos(π/24) − 1) ≈ 0.34 mm is counted.
    assert!(s.fit_error > 0.3e-3 && s.fit_error < 1.0e-3, "{}", s.fit_error);
    assert!((s.volume_ratio - 1.0).abs() < 0.05, "{}", s.volume_ratio);
}

#[test]
fn l_shape_is_decomposed() {
    let m = l_mesh();
    let s = body_shape(&m, &opts());
    assert_eq!(s.kind, ShapeKind::Decomposition, "{s:?}");
    assert!(s.parts.len() >= 2);
    assert!(s.volume_ratio < 1.25 && s.volume_ratio > 0.95, "{}", s.volume_ratio);
    // The hull alone would be 0.68 / 0.36 = 1.89 × the mesh volume.
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn flat_quad_gets_a_thin_fallback_with_a_warning() {
    let m = mesh(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2], [0, 2, 3]]);
    let s = body_shape(&m, &opts());
    assert!(s.warnings.iter().any(|w| w.contains("degenerate")), "{:?}", s.warnings);
    assert_eq!(s.parts.len(), 1);
    let zs: Vec<f64> = s.parts[0].vertices.iter().map(|v| v[2]).collect();
    let thick = zs.iter().cloned().fold(f64::MIN, f64::max) - zs.iter().cloned().fold(f64::MAX, f64::min);
    assert!((thick - 1e-3).abs() < 1e-9, "{thick}");
}

#[test]
fn bad_meshes_never_panic() {
    let o = opts();
    // Empty, a point, a line, NaN, bad indices.
    let s = body_shape(&mesh(&[], &[]), &o);
    assert!(s.parts.is_empty() && !s.warnings.is_empty());
    let s = body_shape(&mesh(&[[0.5, 0.5, 0.5]; 3], &[[0, 1, 2]]), &o);
    assert_eq!(s.kind, ShapeKind::Sphere);
    assert!(!s.warnings.is_empty());
    let s = body_shape(&mesh(&[[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]], &[[0, 1, 2]]), &o);
    assert_eq!(s.kind, ShapeKind::Capsule);
    assert!(!s.warnings.is_empty());
    let mut m = uv_sphere([0.0; 3], 0.1, 8, 8);
    m.vertices.push([f32::NAN, 0.0, 0.0]);
    m.triangles.push([0, 1, 9999]);
    let s = body_shape(&m, &o);
    assert!(s.warnings.len() >= 2, "{:?}", s.warnings);
    assert!(!s.parts.is_empty());
}

#[test]
fn open_mesh_gets_hull_and_warning() {
    // A cube with one face missing, and a duplicated triangle (non-manifold edge).
    let (vs, mut ts) = box_mesh([0.0; 3], [1.0, 0.5, 0.25]);
    ts.truncate(10);
    let s = body_shape(&mesh(&vs, &ts), &opts());
    assert!(s.warnings.iter().any(|w| w.contains("not closed")), "{:?}", s.warnings);
    assert!(!s.parts.is_empty());
}

#[test]
/// A mesh over the triangle limit is simplified first (its speed is measured by the collision
/// benchmark, not asserted here: a loaded machine must not fail a test).
fn huge_mesh_is_simplified_first() {
    let m = uv_sphere([0.0; 3], 0.1, 300, 300);
    assert!(m.triangles.len() > 100_000);
    let t = std::time::Instant::now();
    let s = body_shape(&m, &opts());
    let el = t.elapsed().as_secs_f64();
    eprintln!("huge mesh: {} triangles → {} vertices in {el:.2} s (debug build)", m.triangles.len(), s.vertex_count);
    assert!(s.warnings.iter().any(|w| w.contains("simplified")), "{:?}", s.warnings);
    assert!(s.vertex_count > 0);
}

#[test]
fn obj_has_one_object_per_part() {
    let s = body_shape(&l_mesh(), &opts());
    let t = obj_text(&s, "L");
    assert_eq!(t.lines().filter(|l| l.starts_with("o ")).count(), s.parts.len());
    let s = body_shape(&uv_sphere([0.0; 3], 0.1, 8, 16), &opts());
    let t = obj_text(&s, "S");
    assert!(t.lines().filter(|l| l.starts_with("v ")).count() > 50);
    assert!(t.lines().any(|l| l.starts_with("f ")));
}

fn box_shape(h: f64) -> BodyShape {
    let (vs, ts) = box_mesh([-h, -h, -h], [h, h, h]);
    body_shape(&mesh(&vs, &ts), &opts())
}

fn at(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    Isometry3::from(Translation3::new(x, y, z))
}

#[test]
fn contacts_match_hand_computed_distances() {
    let w = World::new(&[Some(box_shape(0.05)), Some(box_shape(0.05)), None, Some(box_shape(0.05))]);
    let all = |_: usize, _: usize| true;
    // Separated by 0.02 along x; penetrating 0.01 along y; body 2 has no shape.
    let poses = [at(0.0, 0.0, 0.0), at(0.12, 0.0, 0.0), at(0.0, 0.0, 0.0), at(0.0, 0.09, 0.0)];
    let c = contacts_at(&w, &poses, &all, 0.0);
    assert_eq!(c.len(), 1, "{c:?}");
    assert_eq!((c[0].a, c[0].b), (0, 3));
    // The meshes are f32: 0.05 is 0.05 ± 1.5e-9.
    assert!((c[0].distance + 0.01).abs() < 1e-8, "{}", c[0].distance);
    assert!((c[0].normal[1] - 1.0).abs() < 1e-9, "{:?}", c[0].normal);
    assert!((c[0].point_a[1] - 0.05).abs() < 1e-8 && (c[0].point_b[1] - 0.04).abs() < 1e-8, "{:?}", c[0]);
    let c = contacts_at(&w, &poses, &all, 0.025);
    let d01 = c.iter().find(|c| c.b == 1).map(|c| c.distance).unwrap_or(0.0);
    assert!((d01 - 0.02).abs() < 1e-8, "{d01}");
    // Pair (1, 3): x gap 0.02, y ranges overlap → 0.02 as well.
    let near: Vec<_> = c.iter().map(|c| (c.a, c.b)).collect();
    assert_eq!(near, vec![(0, 1), (0, 3), (1, 3)], "{c:?}");
    let c = contacts_at(&w, &poses, &|a, b| (a, b) != (0, 3), 0.0);
    assert!(c.is_empty(), "{c:?}");
    // A sphere against a box: centre 0.2 from the box centre along x → 0.2 − 0.05 − r.
    let sph = body_shape(&uv_sphere([0.0; 3], 0.05, 16, 32), &opts());
    let r = sph.parts[0].radius;
    let ws = World::new(&[Some(box_shape(0.05)), Some(sph)]);
    let c = contacts_at(&ws, &[at(0.0, 0.0, 0.0), at(0.2, 0.0, 0.0)], &all, 1.0);
    assert_eq!(c.len(), 1);
    assert!((c[0].distance - (0.2 - 0.05 - r)).abs() < 1e-8, "{c:?}");
    assert!((c[0].point_b[0] - (0.2 - r)).abs() < 1e-8, "{c:?}");
}

#[test]
fn sweep_finds_first_contact_of_approaching_boxes() {
    // Two 0.1 m cubes, centres 1 m apart along x, approaching at 0.5 m/s each (1 m/s relative):
    // the gap 0.9 m closes at t = 0.9 s. Sampled at 1 kHz over 2 s.
    let w = World::new(&[Some(box_shape(0.05)), Some(box_shape(0.05))]);
    let dt = 1e-3;
    let times: Vec<f64> = (0..=2000).map(|k| k as f64 * dt).collect();
    let tt = times.clone();
    let poses = move |k: usize| {
        let t = tt[k];
        vec![at(0.5 * t, 0.0, 0.0), at(1.0 - 0.5 * t, 0.0, 0.0)]
    };
    let s = sweep(&w, &times, &poses, &|_, _| true, &SweepOptions::default());
    assert_eq!(s.samples, 2001);
    assert_eq!(s.pairs.len(), 1);
    let p = &s.pairs[0];
    let fc = p.first_contact.unwrap_or(f64::NAN);
    // Guarantee: the first sample at or after the true contact time.
    assert!(fc >= 0.9 - 1e-9 && fc < 0.9 + dt + 1e-9, "{fc}");
    // And exactly the first sample where the boxes touch (brute force over every sample).
    let brute = (0..times.len()).find(|&k| !contacts_at(&w, &poses(k), &|_, _| true, 0.0).is_empty());
    assert_eq!(Some(fc), brute.map(|k| times[k]), "{}", s.guarantee);
    // The cubes pass through each other: deepest (0.1 m) when the centres meet at t = 1 s.
    assert!(p.max_depth > 0.09, "{}", p.max_depth);
    assert!(p.min_distance < 0.0);
    assert!(s.guarantee.contains("2001 samples"), "{}", s.guarantee);
    // Fewer evaluations than samples: conservative skipping worked.
    let evals: usize = s.guarantee.split(", ").nth(1).and_then(|x| x.split(' ').next()).and_then(|x| x.parse().ok()).unwrap_or(usize::MAX);
    assert!(evals < 2001, "{}", s.guarantee);
}

#[test]
fn sweep_min_distance_of_passing_boxes() {
    // Body 1 passes body 0 along x at y = 0.13 (gap 0.03 m at closest, t = 1 s), never touching.
    let w = World::new(&[Some(box_shape(0.05)), Some(box_shape(0.05)), Some(box_shape(0.05))]);
    let times: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-3).collect();
    let tt = times.clone();
    let poses = move |k: usize| {
        let t = tt[k];
        let q = UnitQuaternion::from_euler_angles(0.0, 0.0, 0.0);
        vec![at(0.0, 0.0, 0.0), Isometry3::from_parts(Translation3::new(t - 1.0, 0.13, 0.0), q), at(5.0, 5.0, 5.0)]
    };
    let o = SweepOptions::default();
    let s = sweep(&w, &times, &poses, &|_, _| true, &o);
    assert_eq!(s.pairs.len(), 3);
    let p = &s.pairs[0];
    assert_eq!((p.a, p.b), (0, 1));
    assert!(p.first_contact.is_none());
    assert!(p.min_distance >= 0.03 - 1e-8 && p.min_distance <= 0.03 + o.abs_tolerance.max(0.03 * o.rel_tolerance), "{p:?}");
    // The far pair: a distance ≥ near_distance.
    assert!(s.pairs[1].min_distance >= o.near_distance);
    // Not checked: left out.
    let s = sweep(&w, &times, &poses, &|a, b| (a, b) != (0, 1), &o);
    assert_eq!(s.pairs.len(), 2);
}

#[test]
fn sweep_with_rotation_does_not_miss_a_sampled_contact() {
    // A long thin box (0.5 × 0.02 × 0.02) spinning about z at its end, a cube at 0.4 m on the
    // y axis: the bar hits it when its angle reaches ~ 90° − small. Evaluations are skipped by the
    // rotation bound; compare with brute force over all samples.
    let (vs, ts) = box_mesh([0.0, -0.01, -0.01], [0.5, 0.01, 0.01]);
    let bar = body_shape(&mesh(&vs, &ts), &opts());
    let w = World::new(&[Some(bar), Some(box_shape(0.05))]);
    let times: Vec<f64> = (0..=3000).map(|k| k as f64 * 1e-3).collect();
    let tt = times.clone();
    let poses = move |k: usize| {
        let q = UnitQuaternion::from_euler_angles(0.0, 0.0, 0.6 * tt[k]);
        vec![Isometry3::from_parts(Translation3::identity(), q), at(0.0, 0.4, 0.0)]
    };
    let s = sweep(&w, &times, &poses, &|_, _| true, &SweepOptions::default());
    let mut brute = None;
    for (k, &t) in times.iter().enumerate() {
        let c = contacts_at(&w, &poses(k), &|_, _| true, 0.0);
        if !c.is_empty() {
            brute = Some(t);
            break;
        }
    }
    assert!(brute.is_some());
    assert_eq!(s.pairs[0].first_contact, brute, "{}", s.guarantee);
}

#[test]
fn huge_bumpy_mesh_gets_a_simplified_capped_hull() {
    // Radial bumps of up to 10 %: no primitive fits; more triangles than the (lowered) limit.
    let mut m = uv_sphere([0.0; 3], 0.1, 100, 100);
    for (i, v) in m.vertices.iter_mut().enumerate() {
        let f = 1.0 + 0.1 * ((i * 7919 % 13) as f32 / 13.0);
        *v = [v[0] * f, v[1] * f, v[2] * f];
    }
    let o = ShapeOptions { max_triangles: 10_000, max_hull_vertices: 200, ..ShapeOptions::default() };
    let s = body_shape(&m, &o);
    assert_eq!(s.kind, ShapeKind::Hull, "{:?}", s.warnings);
    assert!(s.vertex_count <= 200 && s.vertex_count >= 8, "{}", s.vertex_count);
    assert!(s.warnings.iter().any(|w| w.contains("huge mesh")), "{:?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("hull simplified to at most")), "{:?}", s.warnings);
    assert!(s.fit_error > 0.005 && s.fit_error < 0.03, "{}", s.fit_error);
}

/// Six bodies of the tumbling scenes: a box mesh, a sphere, a cylinder, a box, an L
/// decomposition and one without a shape.
fn tumbling_shapes() -> Vec<Option<BodyShape>> {
    let (vs, ts) = box_mesh([-0.04, -0.03, -0.02], [0.04, 0.03, 0.02]);
    vec![
        Some(body_shape(&mesh(&vs, &ts), &opts())),
        Some(body_shape(&uv_sphere([0.0; 3], 0.05, 12, 24), &opts())),
        Some(body_shape(&cylinder_mesh(0.03, 0.1, 32), &opts())),
        Some(box_shape(0.04)),
        Some(body_shape(&l_mesh(), &ShapeOptions::default())),
        None,
    ]
}

#[test]
fn sweep_matches_brute_force_on_a_tumbling_scene() {
    // Six bodies (boxes, a sphere, a cylinder, an L decomposition) swinging and spinning so that
    // several pairs touch: first_contact and max_depth of every pair must equal those of
    // contacts_at evaluated at every sample; min_distance (when below near) within tolerance.
    let shapes = tumbling_shapes();
    assert_eq!(shapes[4].as_ref().map(|s| s.kind), Some(ShapeKind::Decomposition));
    let w = World::new(&shapes);
    let times: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-3).collect();
    let tt = times.clone();
    let poses = move |k: usize| -> Vec<Isometry3<f64>> {
        let t = tt[k];
        (0..6)
            .map(|i| {
                let fi = i as f64;
                let x = 0.12 * fi + 0.05 * (3.0 * t + fi).sin();
                let y = 0.03 * (2.0 * t + 2.0 * fi).cos();
                let q = UnitQuaternion::from_euler_angles(0.7 * t * fi, 0.4 * t, 0.2 * fi);
                Isometry3::from_parts(Translation3::new(x, y, 0.0), q)
            })
            .collect()
    };
    let o = SweepOptions::default();
    let checked = |a: usize, b: usize| (a, b) != (0, 3);
    let s = sweep(&w, &times, &poses, &checked, &o);
    let mut first = std::collections::HashMap::new();
    let mut depth: std::collections::HashMap<(usize, usize), f64> = std::collections::HashMap::new();
    let mut mind: std::collections::HashMap<(usize, usize), f64> = std::collections::HashMap::new();
    for (k, &t) in times.iter().enumerate() {
        for c in contacts_at(&w, &poses(k), &checked, o.near_distance) {
            let e = mind.entry((c.a, c.b)).or_insert(f64::INFINITY);
            *e = e.min(c.distance);
            if c.distance <= 0.0 {
                first.entry((c.a, c.b)).or_insert(t);
                let d = depth.entry((c.a, c.b)).or_insert(0.0);
                *d = d.max(-c.distance);
            }
        }
    }
    assert!(first.len() >= 2, "the scene should have contacts: {first:?}");
    assert_eq!(s.pairs.len(), 9); // 5 bodies with shapes: 10 pairs, less (0, 3)
    for p in &s.pairs {
        let key = (p.a, p.b);
        assert_eq!(p.first_contact, first.get(&key).copied(), "{p:?}");
        let bd = depth.get(&key).copied().unwrap_or(0.0);
        assert!((p.max_depth - bd).abs() < 1e-9, "{p:?} vs {bd}");
        if let Some(&m) = mind.get(&key) {
            let tol = o.abs_tolerance.max(o.rel_tolerance * p.min_distance.abs());
            assert!(p.min_distance >= m - 1e-9 && p.min_distance <= m + tol, "{p:?} vs {m}");
        } else {
            assert!(p.min_distance >= o.near_distance - 1e-9, "{p:?}");
        }
    }
}

#[test]
fn non_finite_poses_are_left_out_and_named() {
    let w = World::new(&[Some(box_shape(0.05)), Some(box_shape(0.05)), Some(box_shape(0.05))]);
    let times: Vec<f64> = (0..=10).map(|k| k as f64 * 1e-3).collect();
    let poses = |k: usize| vec![at(0.0, 0.0, 0.0), at(if k == 5 { f64::NAN } else { 0.05 }, 0.0, 0.0), at(0.08, 0.0, 0.0)];
    let s = sweep(&w, &times, &poses, &|_, _| true, &SweepOptions::default());
    let pairs: Vec<_> = s.pairs.iter().map(|p| (p.a, p.b)).collect();
    assert_eq!(pairs, vec![(0, 2)]);
    assert!(s.guarantee.contains("not checked: [1]"), "{}", s.guarantee);
    assert_eq!(s.pairs[0].first_contact, Some(0.0));
    let c = contacts_at(&w, &poses(5), &|_, _| true, 0.0);
    assert_eq!(c.iter().map(|c| (c.a, c.b)).collect::<Vec<_>>(), vec![(0, 2)]);
}

#[test]
fn broad_phase_scales_with_touching_pairs() {
    // 20 × 10 × 5 = 1,000 cubes of side 0.1: overlapping their x neighbours (pitch 0.095), apart
    // along y and z (pitch 0.12). Touching pairs: 19 × 10 × 5 = 950; all pairs: 499,500.
    let (nx, ny, nz) = (20usize, 10usize, 5usize);
    let cube = box_shape(0.05);
    let shapes: Vec<Option<BodyShape>> = (0..nx * ny * nz).map(|_| Some(cube.clone())).collect();
    let poses: Vec<Isometry3<f64>> =
        (0..nx * ny * nz).map(|k| at((k % nx) as f64 * 0.095, ((k / nx) % ny) as f64 * 0.12, (k / (nx * ny)) as f64 * 0.12)).collect();
    let w = World::new(&shapes);
    check::NARROW_PHASE.with(|n| n.set(0));
    let c = contacts_at(&w, &poses, &|_, _| true, 0.0);
    let narrow = check::NARROW_PHASE.with(|n| n.get());
    let touching = (nx - 1) * ny * nz;
    assert_eq!(c.len(), touching);
    assert!(c.iter().all(|c| c.b == c.a + 1 && (c.distance + 0.005).abs() < 1e-6), "{:?}", &c[..3]);
    assert_eq!(narrow, touching, "the narrow phase sees only the pairs whose boxes overlap");
}

#[test]
fn shape_key_follows_mesh_content_and_options() {
    let (vs, ts) = box_mesh([0.0; 3], [0.1, 0.2, 0.3]);
    let m = mesh(&vs, &ts);
    let k = ShapeKey::of(&m, &opts());
    assert_eq!(k, ShapeKey::of(&m.clone(), &opts()), "same content, same key");
    let mut moved = m.clone();
    moved.vertices[3][1] = f32::from_bits(moved.vertices[3][1].to_bits() + 1);
    assert_ne!(k, ShapeKey::of(&moved, &opts()), "one ulp of one vertex");
    let mut flipped = m.clone();
    flipped.triangles[0].swap(1, 2);
    assert_ne!(k, ShapeKey::of(&flipped, &opts()), "a triangle's winding");
    for o in [
        ShapeOptions { max_hull_vertices: 64, ..opts() },
        ShapeOptions { decomposition_budget: 1, ..opts() },
        ShapeOptions { thin_thickness: 2e-3, ..opts() },
    ] {
        assert_ne!(k, ShapeKey::of(&m, &o), "{o:?}");
    }
}

#[test]
fn memory_cache_keeps_recent_shapes_within_its_bytes() {
    let shape = box_shape(0.05);
    let size = shape_bytes(&shape);
    let key = |i: u8| ShapeKey([i; 32]);
    let c = MemoryShapeCache::new(3 * size);
    for i in 0..3 {
        c.put(key(i), &shape);
    }
    assert_eq!(c.get(&key(0)).as_ref(), Some(&shape));
    // A fourth evicts the least recently used: 1 (0 was just read).
    c.put(key(3), &shape);
    assert!(c.get(&key(1)).is_none());
    assert!(c.get(&key(0)).is_some() && c.get(&key(2)).is_some() && c.get(&key(3)).is_some());
    let s = c.stats();
    assert_eq!((s.hits, s.misses, s.evictions, s.entries), (4, 1, 1, 3), "{s:?}");
    assert!(s.bytes <= 3 * size);
    // Putting a key again replaces it without growing.
    c.put(key(3), &shape);
    assert_eq!(c.stats().bytes, s.bytes);
    // A cache of 0 bytes keeps nothing.
    let none = MemoryShapeCache::new(0);
    none.put(key(9), &shape);
    assert!(none.get(&key(9)).is_none());
}

#[test]
fn decomposition_plan_lowers_resolution_with_triangles_and_gives_up() {
    let o = opts();
    let small = decomposition_plan(1_000, &o).expect("fits");
    assert_eq!(small.resolution, o.vhacd_resolution);
    let mut last = small.resolution;
    for t in [100_000, 200_000, 400_000] {
        match decomposition_plan(t, &o) {
            Some(p) => {
                assert!(p.resolution <= last && p.work <= o.decomposition_budget, "{t}: {p:?}");
                last = p.resolution;
            }
            None => last = 0,
        }
    }
    assert!(last < o.vhacd_resolution, "a big mesh is decomposed coarser, or not at all");
    assert_eq!(decomposition_plan(1_000, &ShapeOptions { decomposition_budget: 0, ..o.clone() }), None);
    // Over budget: the L keeps its hull, and says why.
    let s = body_shape(&l_mesh(), &ShapeOptions { decomposition_budget: 0, ..o });
    assert_eq!(s.kind, ShapeKind::Hull);
    assert!(s.warnings.iter().any(|w| w.contains("exceeds its work budget")), "{:?}", s.warnings);
}

/// Parts prepared for distance queries from their own hull faces measure the same distances as
/// parts hulled again by parry: boxes (also mirrored), cylinders, decompositions, capped hulls
/// and the flat fallback; a part whose faces point inward is hulled again, not taken.
#[test]
fn parts_prepared_from_their_faces_measure_as_hulls() {
    let (vs, ts) = box_mesh([-0.05, -0.02, -0.01], [0.05, 0.02, 0.03]);
    let mirrored: Vec<[f64; 3]> = vs.iter().map(|v| [-v[0], v[1], v[2]]).collect();
    let q = UnitQuaternion::from_euler_angles(0.3, 0.5, 0.7);
    let rotated: Vec<[f64; 3]> = vs.iter().map(|v| (q * Vector3::from(*v)).into()).collect();
    let flat = mesh(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2], [0, 2, 3]]);
    let mut parts = Vec::new();
    for m in [mesh(&vs, &ts), mesh(&mirrored, &ts), mesh(&rotated, &ts), cylinder_mesh(0.04, 0.2, 48), l_mesh(), flat] {
        parts.extend(body_shape(&m, &opts()).parts);
    }
    let mut bumpy = uv_sphere([0.0, 0.0, 0.0], 0.1, 40, 80);
    for (k, v) in bumpy.vertices.iter_mut().enumerate() {
        let s = 1.0 + 0.02 * ((k * 7919 % 13) as f32 / 13.0);
        *v = [v[0] * s, v[1] * s * 0.7, v[2] * s];
    }
    parts.extend(body_shape(&bumpy, &ShapeOptions { max_hull_vertices: 24, ..opts() }).parts);
    let mut inward = parts[0].clone();
    for f in &mut inward.faces {
        f.swap(1, 2);
    }
    assert!(!super::check::outward_faces(&inward.vertices.iter().map(|v| nalgebra::Point3::from(*v)).collect::<Vec<_>>(), &inward.faces));
    parts.push(inward);
    let polytopes = parts.iter().filter(|p| p.vertices.len() > 2 && p.radius == 0.0).count();
    assert!(polytopes >= 8, "{polytopes} polytope parts");
    let mut rng = crate::mechanism::XorShift::new(3);
    for p in &parts {
        let Some((iso, mine)) = super::check::prepared_part(p) else { continue };
        let pts: Vec<nalgebra::Point3<f64>> = p.vertices.iter().map(|v| nalgebra::Point3::from(*v)).collect();
        let hull = match (pts.len(), p.radius) {
            (0..=2, _) => continue,
            (_, r) if r > 0.0 => parry3d_f64::shape::SharedShape::round_convex_hull(&pts, r).unwrap(),
            _ => parry3d_f64::shape::SharedShape::convex_hull(&pts).unwrap(),
        };
        for _ in 0..200 {
            let x = nalgebra::Point3::new(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * 0.6;
            let a = mine.distance_to_point(&iso, &x, true);
            let b = hull.distance_to_point(&Isometry3::identity(), &x, true);
            assert!((a - b).abs() < 1e-9, "{a} vs {b} at {x:?} for a part of {} vertices", pts.len());
        }
    }
}

/// `contacts_of` (the conversion's CAD-pose check: parry shapes only for the bodies the broad
/// phase meets) gives exactly `contacts_at` of the whole world: boxes, a sphere (one point and a
/// radius), a cylinder, an L decomposition, a body without a shape and one whose only part
/// cannot be made, swinging through contact, at two margins.
#[test]
fn contacts_of_equals_contacts_at_of_the_whole_world() {
    let unusable = BodyShape {
        parts: vec![ConvexPart { vertices: vec![[0.0; 3], [0.1, 0.0, 0.0]], faces: Vec::new(), radius: 0.0 }],
        ..box_shape(0.01)
    };
    let mut shapes = tumbling_shapes();
    shapes.push(Some(unusable));
    let w = World::new(&shapes);
    let checked = |a: usize, b: usize| (a, b) != (0, 3);
    let mut met = 0;
    for k in 0..=200 {
        let t = k as f64 * 1e-2;
        let poses: Vec<Isometry3<f64>> = (0..shapes.len())
            .map(|i| {
                let fi = i as f64;
                let x = 0.1 * fi + 0.05 * (3.0 * t + fi).sin();
                let q = UnitQuaternion::from_euler_angles(0.7 * t * fi, 0.4 * t, 0.2 * fi);
                Isometry3::from_parts(Translation3::new(x, 0.03 * (2.0 * t + 2.0 * fi).cos(), 0.0), q)
            })
            .collect();
        for margin in [0.0, 0.02] {
            let all = contacts_at(&w, &poses, &checked, margin);
            assert_eq!(contacts_of(&shapes, &poses, &checked, margin), all, "t = {t}, margin {margin}");
            met += all.len();
        }
    }
    assert!(met > 100, "the scene has contacts: {met}");
}
