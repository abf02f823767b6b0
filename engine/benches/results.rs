//! Result files: reading and indexing a 100 MB Dymola-style file (float32, binTrans), and the
//! poses of a 50-body model over 10,000 steps. Files are generated in memory.

use std::hint::black_box;
use std::time::Instant;

use cad2mo_engine::mechanism::Mechanism;
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::ir::BodyId;
use cad2mo_engine::results::mat::Trajectory;
use cad2mo_engine::results::poses;
use cad2mo_engine::results::write::trajectory;
use criterion::{criterion_group, criterion_main, Criterion};

#[path = "support/gen.rs"]
#[allow(dead_code)]
mod gen;

fn bench(c: &mut Criterion) {
    // 100 MB: 2,500 variables x 10,000 instants of float32.
    let time: Vec<f64> = (0..10_000).map(|i| f64::from(i) * 1e-3).collect();
    let series: Vec<(String, Vec<f64>)> = (0..2_499)
        .map(|k| {
            (format!("model.component{}.sub.signal[{}, {}]", k / 9, k % 3 + 1, k % 9 / 3 + 1), time.iter().map(|t| t * k as f64).collect())
        })
        .collect();
    let big = trajectory(&time, &series, true);
    let start = Instant::now();
    let t = Trajectory::read(&big, "big.mat").expect("reads");
    let read = start.elapsed();
    println!(
        "results: {} MB, {} variables x {} instants read and indexed in {:.1} ms",
        big.len() / 1_000_000,
        t.variables.len(),
        t.len(),
        read.as_secs_f64() * 1e3
    );
    let mut g = c.benchmark_group("results");
    g.sample_size(10);
    g.bench_function("read and index a 100 MB result", |b| {
        b.iter(|| black_box(Trajectory::read(&big, "big.mat").expect("reads").variables.len()))
    });

    // Poses: a 50-body tree, every body's frame_a over 10,000 steps.
    let bundle = Bundle::from_files("gen", [("tree.xml".to_string(), gen::tree_xml(50).into_bytes())]).expect("bundle");
    let a = cad2mo_engine::pipeline::analyse(&bundle, &cad2mo_engine::pipeline::Options::default()).expect("analyses");
    let mech = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    let k = mech.forward(&mech.q0()).expect("fk");
    let mut frames: Vec<(String, Vec<f64>)> = Vec::new();
    for (b, name) in mech.body_names().iter().enumerate() {
        let Ok(p) = mech.body_pose(&k, BodyId(b as u32)) else { continue };
        let r = p.rotation.to_rotation_matrix();
        for i in 0..3 {
            frames.push((format!("{name}.frame_a.r_0[{}]", i + 1), time.iter().map(|t| p.translation.vector[i] + 0.01 * t).collect()));
            for j in 0..3 {
                frames.push((format!("{name}.frame_a.R.T[{}, {}]", i + 1, j + 1), vec![r[(j, i)]; time.len()]));
            }
        }
    }
    let file = trajectory(&time, &frames, true);
    let t = Trajectory::read(&file, "poses.mat").expect("reads");
    let start = Instant::now();
    let p = poses::extract(&t, &mech);
    println!(
        "results: poses of {} bodies x {} steps extracted in {:.1} ms",
        p.summary.from_frames.len(),
        p.t.len(),
        start.elapsed().as_secs_f64() * 1e3
    );
    g.bench_function("poses of 50 bodies x 10,000 steps", |b| b.iter(|| black_box(poses::extract(&t, &mech).data.len())));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
