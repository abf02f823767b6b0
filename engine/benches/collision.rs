//! Issue 14's benchmark: 50 bodies (hulls of ~100 vertices) along a 10 s motion sampled at
//! 1 kHz (10,001 samples), every pair checked: the whole sweep must take < 1 s on one core.

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

use cad2mo_engine::collision::{body_shape, sweep, BodyShape, ShapeOptions, SweepOptions, World};
use cad2mo_engine::pipeline::ir::Mesh;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

/// Deterministic pseudo-random numbers in [0, 1).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A hull of ~100 points on an ellipsoid with half-axes 40..80 mm.
fn body(rng: &mut Lcg) -> BodyShape {
    let ax = [0.04 + 0.04 * rng.next(), 0.04 + 0.04 * rng.next(), 0.04 + 0.04 * rng.next()];
    let vertices: Vec<[f32; 3]> = (0..110)
        .map(|_| {
            let z = 2.0 * rng.next() - 1.0;
            let ph = 2.0 * PI * rng.next();
            let s = (1.0 - z * z).sqrt();
            [(ax[0] * s * ph.cos()) as f32, (ax[1] * s * ph.sin()) as f32, (ax[2] * z) as f32]
        })
        .collect();
    // Triangles only for the fit samples: a fan is enough (the hull comes from the points).
    let triangles = (1..vertices.len() as u32 - 1).map(|i| [0, i, i + 1]).collect();
    body_shape(&Mesh { vertices, triangles }, &ShapeOptions::default())
}

struct Motion {
    base: Vec<Vector3<f64>>,
    dir: Vec<Vector3<f64>>,
    freq: Vec<f64>,
    phase: Vec<f64>,
    axis: Vec<nalgebra::Unit<Vector3<f64>>>,
    spin: Vec<f64>,
}

impl Motion {
    fn new(rng: &mut Lcg, n: usize) -> Motion {
        let mut m = Motion { base: vec![], dir: vec![], freq: vec![], phase: vec![], axis: vec![], spin: vec![] };
        for i in 0..n {
            // A 5 × 10 grid, 0.17 m apart: neighbours (0.08–0.16 m across, ±0.05 m swings) touch.
            m.base.push(Vector3::new(0.17 * (i % 10) as f64, 0.17 * (i / 10) as f64, 0.0));
            let d = Vector3::new(rng.next() - 0.5, rng.next() - 0.5, 0.3 * (rng.next() - 0.5));
            m.dir.push(d.normalize() * 0.05);
            m.freq.push(0.2 + 0.5 * rng.next());
            m.phase.push(2.0 * PI * rng.next());
            m.axis.push(nalgebra::Unit::new_normalize(Vector3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5)));
            m.spin.push(0.5 + rng.next());
        }
        m
    }

    fn poses(&self, t: f64) -> Vec<Isometry3<f64>> {
        (0..self.base.len())
            .map(|i| {
                let p = self.base[i] + self.dir[i] * (2.0 * PI * self.freq[i] * t + self.phase[i]).sin();
                let q = UnitQuaternion::from_axis_angle(&self.axis[i], self.spin[i] * t);
                Isometry3::from_parts(Translation3::from(p), q)
            })
            .collect()
    }
}

fn bench(c: &mut Criterion) {
    let mut rng = Lcg(14);
    let shapes: Vec<Option<BodyShape>> = (0..50).map(|_| Some(body(&mut rng))).collect();
    let verts: usize = shapes.iter().flatten().map(|s| s.vertex_count).sum();
    let world = World::new(&shapes);
    let motion = Motion::new(&mut rng, 50);
    let times: Vec<f64> = (0..=10_000).map(|k| k as f64 * 1e-3).collect();
    let poses = |k: usize| motion.poses(times[k]);
    let all = |_: usize, _: usize| true;
    let opts = SweepOptions::default();
    let t0 = Instant::now();
    let s = sweep(&world, &times, &poses, &all, &opts);
    let el = t0.elapsed().as_secs_f64();
    let touching = s.pairs.iter().filter(|p| p.first_contact.is_some()).count();
    let near = s.pairs.iter().filter(|p| p.min_distance < opts.near_distance).count();
    println!(
        "collision sweep: 50 bodies ({verts} hull vertices), {} samples, {} pairs ({near} near, {touching} touching): {:.3} s (limit 1 s)\n  {}",
        s.samples,
        s.pairs.len(),
        el,
        s.guarantee
    );
    // `cargo test --all-targets` runs benches once, unoptimised: the shape timings below (a
    // minute there) are for `cargo bench` only.
    let timing = std::env::args().any(|a| a == "--bench");
    if timing {
        shape_timings();
    }
    let mut g = c.benchmark_group("collision");
    g.sample_size(10);
    g.bench_function("sweep 50 bodies, 10 s at 1 kHz", |b| b.iter(|| black_box(sweep(&world, &times, &poses, &all, &opts).pairs.len())));
    g.finish();
}

/// How long making a shape takes for a huge mesh and for a concave one (printed, not measured
/// by criterion: one run each).
fn shape_timings() {
    let (nu, nv) = (300usize, 300usize);
    let mut vertices = vec![[0.0f32, 0.0, 0.1], [0.0, 0.0, -0.1]];
    for i in 1..nu {
        let th = PI * i as f64 / nu as f64;
        for j in 0..nv {
            let ph = 2.0 * PI * j as f64 / nv as f64;
            let r = 0.1 * (1.0 + 0.05 * (7.0 * th).sin() * (5.0 * ph).cos());
            vertices.push([(r * th.sin() * ph.cos()) as f32, (r * th.sin() * ph.sin()) as f32, (r * th.cos()) as f32]);
        }
    }
    let ring = |i: usize, j: usize| (2 + (i - 1) * nv + j % nv) as u32;
    let mut triangles = Vec::new();
    for j in 0..nv {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        triangles.push([1, ring(nu - 1, j + 1), ring(nu - 1, j)]);
    }
    for i in 1..nu - 1 {
        for j in 0..nv {
            triangles.push([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)]);
            triangles.push([ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)]);
        }
    }
    let huge = Mesh { vertices, triangles };
    let t0 = Instant::now();
    let hs = body_shape(&huge, &ShapeOptions::default());
    println!(
        "huge mesh: {} triangles → {} ({} vertices) in {:.3} s; warnings: {:?}",
        huge.triangles.len(),
        hs.kind.name(),
        hs.vertex_count,
        t0.elapsed().as_secs_f64(),
        hs.warnings
    );
    // A concave mesh (torus, 20k triangles): hull/mesh volume ratio ≫ 1.25 → VHACD decomposition.
    let (nu, nv) = (100usize, 100usize);
    let (big, small) = (0.1, 0.03);
    let vertices: Vec<[f32; 3]> = (0..nu)
        .flat_map(|i| (0..nv).map(move |j| (i, j)))
        .map(|(i, j)| {
            let (u, v) = (2.0 * PI * i as f64 / nu as f64, 2.0 * PI * j as f64 / nv as f64);
            let r = big + small * v.cos();
            [(r * u.cos()) as f32, (r * u.sin()) as f32, (small * v.sin()) as f32]
        })
        .collect();
    let id = |i: usize, j: usize| ((i % nu) * nv + j % nv) as u32;
    let triangles: Vec<[u32; 3]> = (0..nu)
        .flat_map(|i| (0..nv).map(move |j| (i, j)))
        .flat_map(|(i, j)| [[id(i, j), id(i + 1, j), id(i + 1, j + 1)], [id(i, j), id(i + 1, j + 1), id(i, j + 1)]])
        .collect();
    let torus = Mesh { vertices, triangles };
    let t0 = Instant::now();
    let ts = body_shape(&torus, &ShapeOptions::default());
    println!(
        "torus: {} triangles → {} ({} parts, {} vertices, fit error {:.2e} m, volume ratio {:.3}) in {:.3} s; warnings: {:?}",
        torus.triangles.len(),
        ts.kind.name(),
        ts.parts.len(),
        ts.vertex_count,
        ts.fit_error,
        ts.volume_ratio,
        t0.elapsed().as_secs_f64(),
        ts.warnings
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
