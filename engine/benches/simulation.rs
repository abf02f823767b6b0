//! Simulation benchmark (issue 28's goal: a 6-axis arm with drives, 10 s of motion, in under
//! 1 s): the generated 6-DoF arm, a drive on every joint (the default motor of the library's
//! `DCPermanentMagnet`, gear ratio 100, `CascadePPI`) following a quintic motion of 2 s per
//! segment back and forth for 10 s, gravity -y; rtol 1e-6, atol 1e-8, output every 10 ms.
//! Steps, evaluations and the worst tracking error are printed before the measurement.

use std::time::Instant;

use cad2mo_engine::mechanism::Mechanism;
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options};
use cad2mo_engine::simulation::{self, Controller, Drive, Motor, MotorKind, NoForces, Reference, Start, Transmission};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Vector3;

#[path = "support/mod.rs"]
mod support;
use support::gen;

fn arm() -> Mechanism {
    let bundle = Bundle::from_files("b", [("arm.xml".to_string(), gen::serial_arm_xml(6).into_bytes())]).expect("bundle");
    let a = pipeline::analyse(&bundle, &Options::default()).expect("analyse");
    Mechanism::from_validated(&a.model, &a.validated).expect("mechanism")
}

fn drives(m: &Mechanism) -> Vec<Drive> {
    let q0 = m.q0();
    let ts: Vec<f64> = (0..=1000).map(|k| k as f64 * 0.01).collect();
    // 0 -> 1 -> 0 ... every 2 s, quintic.
    let s = |t: f64| {
        let (seg, u) = ((t / 2.0).floor(), (t / 2.0).fract());
        let p = 10.0 * u.powi(3) - 15.0 * u.powi(4) + 6.0 * u.powi(5);
        let v = (30.0 * u.powi(2) - 60.0 * u.powi(3) + 30.0 * u.powi(4)) / 2.0;
        if seg as i64 % 2 == 0 {
            (p, v)
        } else {
            (1.0 - p, -v)
        }
    };
    (0..m.dof())
        .map(|k| {
            let amp = 0.5 - 0.05 * k as f64;
            Drive {
                coordinate: k,
                motor: Motor {
                    kind: MotorKind::DcPermanentMagnet,
                    r: 0.299,
                    l: 8.2e-5,
                    k: 0.0302,
                    j: 1.42e-5,
                    d: 0.0,
                    v_max: 48.0,
                    i_max: 30.0,
                    tc: 0.001,
                },
                transmission: Transmission { ratio: 100.0, eta: 1.0 },
                controller: Controller { kp: 10.0, ks: 0.5, ts: 0.05 },
                reference: Reference::Motion {
                    t: ts.clone(),
                    q: ts.iter().map(|t| q0[k] + amp * s(*t).0).collect(),
                    qd: ts.iter().map(|t| amp * s(*t).1).collect(),
                },
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let m = arm();
    let d = drives(&m);
    let g = Vector3::new(0.0, -9.81, 0.0);
    let start = Start { q: m.q0(), qd: vec![0.0; m.dof()] };
    let opts = simulation::Options { duration: 10.0, output_interval: 0.01, rtol: 1e-6, atol: 1e-8, ..Default::default() };
    let never = || false;
    let t0 = Instant::now();
    let run = simulation::simulate(&m, &g, &d, &NoForces, &start, &opts, &never).expect("runs");
    let worst = run.tracking(&d, &[]).iter().map(|t| t.max_error).fold(0.0f64, f64::max);
    println!(
        "6-axis arm, 6 drives, 10 s: {} steps ({} rejected), {} evaluations, worst tracking error {worst:.3e} rad, one run {:.3} s",
        run.accepted_steps,
        run.rejected_steps,
        run.evaluations,
        t0.elapsed().as_secs_f64()
    );
    let mut group = c.benchmark_group("simulation");
    group.sample_size(10);
    group.bench_function("arm6_drives_10s", |b| {
        b.iter(|| simulation::simulate(&m, &g, &d, &NoForces, &start, &opts, &never).expect("runs"))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
