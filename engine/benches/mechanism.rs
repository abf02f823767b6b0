//! Mechanism benchmarks: inverse kinematics (10,000 random reachable targets, made by FK of
//! random joint values inside the limits) on generated 6-DoF and 7-DoF arms and on a real iCub
//! chain; inverse dynamics (RNEA) per sample on the largest real tree fixtures and a generated
//! 50-body tree. Success rates and mean times over the 10,000 targets are printed before the
//! criterion measurements.

use std::time::Instant;

use cad2mo_engine::mechanism::{IkOptions, IkTarget, Mechanism, XorShift};
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::ir::FrameId;
use cad2mo_engine::pipeline::{self, Options};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Isometry3, Vector3};

#[path = "support/mod.rs"]
mod support;
use support::{fixtures, gen};

fn mechanism(name: &str, xml: &str) -> Option<(Mechanism, usize)> {
    let bundle = Bundle::from_files("b", [(name.to_string(), xml.as_bytes().to_vec())]).ok()?;
    let a = pipeline::analyse(&bundle, &Options::default()).ok()?;
    let bodies = a.model.bodies.len();
    Some((Mechanism::from_validated(&a.model, &a.validated).ok()?, bodies))
}

/// The CAD frame moved by the most coordinates (the end of the longest chain).
fn deepest_frame(m: &Mechanism, frames: usize) -> (FrameId, usize) {
    let parents = m.link_parents();
    let depth = |mut l: Option<usize>| {
        let mut d = 0;
        while let Some(i) = l {
            d += 1;
            l = parents[i];
        }
        d
    };
    (0..frames as u32)
        .map(FrameId)
        .map(|f| (f, m.frame_attachment(f).map_or(0, |a| depth(a.link))))
        .max_by_key(|x| x.1)
        .unwrap_or((FrameId(0), 0))
}

fn targets(m: &Mechanism, tool: FrameId, count: usize) -> Vec<Isometry3<f64>> {
    let limits = m.default_limits();
    let mut rng = XorShift::new(2024);
    (0..count)
        .map(|_| {
            let q: Vec<f64> = limits.iter().map(|(lo, hi)| rng.range(*lo, *hi)).collect();
            m.frame_pose(&m.forward(&q).expect("fk"), tool).expect("pose")
        })
        .collect()
}

fn ik_case(c: &mut Criterion, label: &str, m: &Mechanism, tool: FrameId) {
    let ts = targets(m, tool, 10_000);
    let opts = IkOptions::default();
    let mut rng = XorShift::new(99);
    let q0 = m.q0();
    let start = Instant::now();
    let (mut ok, mut iterations, mut restarts) = (0usize, 0usize, 0usize);
    for t in &ts {
        let r = m.inverse_kinematics(tool, &IkTarget::Pose(*t), &q0, &opts, &mut rng).expect("ik");
        ok += usize::from(r.success);
        iterations += r.iterations;
        restarts += r.restarts;
    }
    let mean = start.elapsed().as_secs_f64() / ts.len() as f64;
    println!(
        "IK {label}: {ok} of {} solved ({:.2} %), mean {:.1} us per solve, {:.1} iterations and {:.2} restarts on average",
        ts.len(),
        100.0 * ok as f64 / ts.len() as f64,
        mean * 1e6,
        iterations as f64 / ts.len() as f64,
        restarts as f64 / ts.len() as f64
    );
    let mut g = c.benchmark_group("ik");
    let mut i = 0;
    g.bench_function(label, |b| {
        b.iter(|| {
            i = (i + 1) % ts.len();
            m.inverse_kinematics(tool, &IkTarget::Pose(ts[i]), &q0, &opts, &mut rng).expect("ik")
        })
    });
    g.finish();
}

fn rnea_case(c: &mut Criterion, label: &str, m: &Mechanism) {
    let n = m.dof();
    let mut rng = XorShift::new(5);
    let samples: Vec<[Vec<f64>; 3]> = (0..64)
        .map(|_| {
            [
                m.q0().iter().map(|q| q + rng.range(-1.0, 1.0)).collect(),
                (0..n).map(|_| rng.range(-2.0, 2.0)).collect(),
                (0..n).map(|_| rng.range(-5.0, 5.0)).collect(),
            ]
        })
        .collect();
    let g = Vector3::new(0.0, -9.81, 0.0);
    let mut ws = m.workspace();
    let mut tau = vec![0.0; n];
    let mut i = 0;
    let mut grp = c.benchmark_group("rnea");
    grp.bench_function(label, |b| {
        b.iter(|| {
            i = (i + 1) % samples.len();
            let s = &samples[i];
            m.inverse_dynamics(&s[0], &s[1], &s[2], &g, &mut ws, &mut tau).expect("rnea");
            tau[0]
        })
    });
    grp.finish();
}

fn bench(c: &mut Criterion) {
    for n in [6, 7] {
        let (m, _) = mechanism("arm.xml", &gen::serial_arm_xml(n)).expect("arm");
        let tool = m.frame_by_node_id("TOOL").expect("tool");
        ik_case(c, &format!("arm{n}"), &m, tool);
        rnea_case(c, &format!("arm{n}"), &m);
    }
    let (tree, bodies) = mechanism("tree.xml", &gen::tree_xml(50)).expect("tree");
    rnea_case(c, &format!("generated_tree_{bodies}_bodies_{}_dof", tree.dof()), &tree);
    let Some(fx) = fixtures() else { return };
    let real = [
        ("icub2_5", "xml/robotology+icub-models-generator/e780c99f/ICUB_2-5_BB_SIM_MODEL.xml"),
        ("ergocub", "xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml"),
        ("icub3_upperbody", "xml/robotology+icub-models-generator/2d4a19cf/ICUB3_UPPERBODY_SIM_MODEL.xml"),
    ];
    for (label, rel) in real {
        let Ok(text) = std::fs::read_to_string(fx.join(rel)) else { continue };
        let Some((m, bodies)) = mechanism("model.xml", &text) else { continue };
        rnea_case(c, &format!("{label}_{bodies}_bodies_{}_dof", m.dof()), &m);
        let frames = text.matches("<Frame").count();
        let (tool, dof) = deepest_frame(&m, frames);
        if dof >= 6 && label == "icub3_upperbody" {
            ik_case(c, &format!("{label}_chain_{dof}_dof"), &m, tool);
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
