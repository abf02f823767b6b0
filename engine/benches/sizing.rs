//! Drive sizing benchmark: a 10 s motion sampled at 1 kHz (10,001 samples) on 6 axes (5 revolute
//! arm joints and one prismatic axis), each sized with its assigned motor and gear and ranked
//! against every real motor × gear combination of the seed library (each gear at its catalogue
//! ratio), and against a catalogue of the size (48 motors × 36 gears, every check's
//! value present: the seed's parts repeated with every datasheet value filled in, for timing
//! only), with an amplifier and a brake resistor set so every check runs. The loads are
//! synthetic but shaped like an arm's: a smooth back-and-forth motion per axis, torque from
//! inertia, gravity on the link and viscous friction. The time of one full sizing is printed
//! before the criterion measurement.

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

use cad2mo_engine::library::{seed, Library};
use cad2mo_engine::pipeline::back::modelica::mechatronics::JointKind;
use cad2mo_engine::sizing::{self, Amplifier, AxisLoad, Brake, Catalog, DriveSizing, Gear, Motor, PartRef, Settings};
use criterion::{criterion_group, criterion_main, Criterion};

struct Axis {
    name: String,
    kind: JointKind,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
    inertia: f64,
}

fn axes(t: &[f64]) -> Vec<Axis> {
    (0..6)
        .map(|k| {
            let prismatic = k == 5;
            let (amp, period) = if prismatic { (0.2, 4.0) } else { (1.0 + 0.2 * k as f64, 2.5 + 0.5 * k as f64) };
            let w = 2.0 * PI / period;
            // Link inertia (kg·m²) and gravity moment (N·m); the slide's mass (kg) and weight (N).
            let (j, mgl, visc) = if prismatic { (8.0, 8.0 * 9.81, 20.0) } else { (2.0 / (1.0 + k as f64), 30.0 / (1.0 + k as f64), 0.5) };
            let (mut qd, mut qdd, mut tau) = (Vec::new(), Vec::new(), Vec::new());
            for &x in t {
                let q = amp * (w * x).sin();
                let v = amp * w * (w * x).cos();
                let a = -amp * w * w * (w * x).sin();
                let g = if prismatic { mgl } else { mgl * q.cos() };
                qd.push(v);
                qdd.push(a);
                tau.push(j * a + g + visc * v);
            }
            Axis {
                name: format!("J{}", k + 1),
                kind: if prismatic { JointKind::Prismatic } else { JointKind::Revolute },
                qd,
                qdd,
                tau,
                inertia: j,
            }
        })
        .collect()
}

fn part(lib: &Library, id: &str) -> (cad2mo_engine::library::Class, cad2mo_engine::library::Instance) {
    let i = lib.instances.iter().find(|i| i.id == id).expect("instance").clone();
    (lib.class(&i.class_id).expect("class").clone(), i)
}

fn settings() -> Settings {
    Settings {
        dwell: 1.0,
        amplifier: Some(Amplifier {
            part: PartRef { id: "amp".into(), name: "bench amplifier".into() },
            u_supply: Some(48.0),
            u_min: None,
            u_max: None,
            i_cont: Some(10.0),
            i_peak: Some(30.0),
            source: "bench".into(),
        }),
        brake: Some(Brake::Resistor { power: 100.0 }),
        ..Settings::default()
    }
}

fn size_all(t: &[f64], axes: &[Axis], drives: &[(Motor, Gear)], catalog: &Catalog, threads: usize) -> Vec<DriveSizing> {
    let settings = settings();
    let jobs: Vec<sizing::DriveJob> = axes
        .iter()
        .zip(drives)
        .map(|(a, (m, g))| sizing::DriveJob {
            load: AxisLoad { joint: &a.name, kind: a.kind, t, qd: &a.qd, qdd: &a.qdd, tau: &a.tau, load_inertia: a.inertia },
            motor: m.clone(),
            gear: g.clone(),
        })
        .collect();
    sizing::size_drives(&jobs, Some(catalog), &settings, sizing::TOP, threads).into_iter().map(|r| r.expect("sizes")).collect()
}

/// The catalogue size, for timing: the seed's motors and gears repeated (48 motors, 36
/// gears, 4 of them screws) with every value a check reads filled in, so no check is skipped.
fn full_catalog(seed: &Catalog) -> Catalog {
    let motors = (0..48)
        .map(|i| {
            let m = &seed.motors[i % seed.motors.len()];
            Motor {
                part: PartRef { id: format!("m{i}"), name: format!("{} #{i}", m.part.name) },
                t_nom: Some(m.t_nom.unwrap_or(0.1) * (1.0 + i as f64 * 0.1)),
                t_stall: Some(m.t_nom.unwrap_or(0.1) * 8.0),
                w_max: Some(m.w_max.unwrap_or(1000.0)),
                tau_th_w: Some(10.0 + i as f64),
                mass: Some(0.1 * (1 + i % 7) as f64),
                ..m.clone()
            }
        })
        .collect();
    let rotary: Vec<&Gear> = seed.gears.iter().filter(|g| g.lead.is_none()).collect();
    let screws: Vec<&Gear> = seed.gears.iter().filter(|g| g.lead.is_some()).collect();
    let gears = (0..36)
        .map(|i| {
            let g = if i < 32 { rotary[i % rotary.len()] } else { screws[i % screws.len()] };
            let ratio = if g.lead.is_some() { 1.0 } else { [5.0, 10.0, 30.0, 50.0, 80.0, 100.0, 120.0, 160.0][i % 8] };
            Gear {
                part: PartRef { id: format!("g{i}"), name: format!("{} #{i}", g.part.name) },
                ratio,
                catalog_ratio: ratio,
                t_rated: if g.lead.is_some() { None } else { Some(30.0) },
                t_avg_max: if g.lead.is_some() { None } else { Some(50.0) },
                out_peak: Some(if g.lead.is_some() { 5000.0 } else { 70.0 }),
                w_in_max: Some(800.0),
                j_in: Some(1e-6 * (1 + i % 5) as f64),
                mass: Some(0.2),
                ..g.clone()
            }
        })
        .collect();
    Catalog { motors, gears, skipped: Vec::new() }
}

fn bench(c: &mut Criterion) {
    let lib = seed::library().expect("seed");
    let catalog = Catalog::from_library(&lib);
    let (mc, mi) = part(&lib, seed::MAXON_RE40);
    let (gc, gi) = part(&lib, seed::MAXON_GP42C_74);
    let (sc, si) = part(&lib, seed::BALL_SCREW_16X5);
    let motor = sizing::parts::motor(&mc, &mi, &[]).expect("motor");
    let gear = sizing::parts::gear(&gc, &gi, &[]).expect("gear");
    let screw = sizing::parts::gear(&sc, &si, &[]).expect("screw");
    let drives: Vec<(Motor, Gear)> = (0..6).map(|k| (motor.clone(), if k == 5 { screw.clone() } else { gear.clone() })).collect();
    let t: Vec<f64> = (0..=10_000).map(|i| i as f64 * 1e-3).collect();
    let axes = axes(&t);
    let big = full_catalog(&catalog);
    let threads = sizing::sizing_threads();
    for (what, cat) in [("the seed library", &catalog), ("a 48-motor x 36-gear catalogue", &big)] {
        let combos = cat.gears.len() * cat.motors.len();
        for n in [1, threads] {
            let start = Instant::now();
            let runs = 10;
            for _ in 0..runs {
                black_box(size_all(&t, &axes, &drives, cat, n));
            }
            let per = start.elapsed().as_secs_f64() / runs as f64;
            println!(
                "sizing: 6 axes x {} samples against {combos} motor x gear combinations of {what} (each axis tries those whose gear fits it), {n} thread(s): {:.1} ms per full sizing",
                t.len(),
                per * 1e3,
            );
        }
    }
    assert_eq!(
        size_all(&t, &axes, &drives, &catalog, 1),
        size_all(&t, &axes, &drives, &catalog, threads),
        "the same on one thread and on several"
    );
    c.bench_function("sizing/6 axes, 10 s at 1 kHz, whole seed library", |b| {
        b.iter(|| black_box(size_all(&t, &axes, &drives, &catalog, threads)))
    });
    c.bench_function("sizing/6 axes, 10 s at 1 kHz, 48 motors x 36 gears", |b| {
        b.iter(|| black_box(size_all(&t, &axes, &drives, &big, threads)))
    });
}

/// The service's whole path for one motion on a real mechanism: plan a 10 s motion of the
/// generated 6-DoF arm (PTP segments through four keyframes and dwells), sample it at 1 kHz,
/// run the inverse dynamics with gravity at every sample, and size a drive on every joint
/// against the seed library (what `GET .../motions/{id}/sizing` computes).
fn bench_full(c: &mut Criterion) {
    use cad2mo_engine::mechanism::Mechanism;
    use cad2mo_engine::motion::plan::{self as mplan, Interpolation, Keyframe, MotionSpec, Target};
    use cad2mo_engine::pipeline::front::bundle::Bundle;
    let bundle = Bundle::from_files("gen", [("arm.xml".to_string(), gen::serial_arm_xml(6).into_bytes())]).expect("bundle");
    let a = cad2mo_engine::pipeline::analyse(&bundle, &cad2mo_engine::pipeline::Options::default()).expect("analyses");
    let mech = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    let axes = mplan::axes(&mech, &Default::default());
    let key = |f: f64| Keyframe {
        target: Target::Joints {
            values: axes.iter().enumerate().map(|(i, ax)| (ax.name.clone(), ax.q0 + f * (0.3 + 0.1 * i as f64))).collect(),
        },
        interpolation: Interpolation::Ptp,
        duration: Some(2.0),
        dwell: Some(0.5),
    };
    let spec = MotionSpec { name: "cycle".into(), keyframes: vec![key(0.0), key(1.0), key(-1.0), key(0.5), key(0.0)] };
    let lib = seed::library().expect("seed");
    let catalog = Catalog::from_library(&lib);
    let (mc, mi) = part(&lib, seed::MAXON_RE40);
    let (gc, gi) = part(&lib, seed::GEAR_100);
    let motor = sizing::parts::motor(&mc, &mi, &[]).expect("motor");
    let gear = sizing::parts::gear(&gc, &gi, &[]).expect("gear");
    let g = nalgebra::Vector3::new(0.0, 0.0, -9.81);
    let full = || {
        let p = mplan::plan(&mech, &axes, &spec).expect("plans");
        let s = p.closed_samples(&mech, 1000.0).expect("samples");
        let (tau, inertia) = mplan::inverse_dynamics(&mech, &s, &g, 10).expect("inverse dynamics");
        // As the service does: every drive at once on the machine's cores.
        let jobs: Vec<sizing::DriveJob> = axes
            .iter()
            .enumerate()
            .map(|(i, ax)| sizing::DriveJob {
                load: AxisLoad {
                    joint: &ax.name,
                    kind: JointKind::Revolute,
                    t: &s.t,
                    qd: &s.qd[i],
                    qdd: &s.qdd[i],
                    tau: &tau[i],
                    load_inertia: inertia[i],
                },
                motor: motor.clone(),
                gear: gear.clone(),
            })
            .collect();
        let out: Vec<DriveSizing> = sizing::size_drives(&jobs, Some(&catalog), &settings(), sizing::TOP, sizing::sizing_threads())
            .into_iter()
            .map(|r| r.expect("sizes"))
            .collect();
        (s.t.len(), out)
    };
    let (n, _) = full();
    let start = Instant::now();
    for _ in 0..5 {
        black_box(full());
    }
    println!(
        "sizing (full path): plan + {n} samples + inverse dynamics + 6 drives against the seed library: {:.1} ms",
        start.elapsed().as_secs_f64() / 5.0 * 1e3
    );
    c.bench_function("sizing/full path, 6-DoF arm, 10 s at 1 kHz", |b| b.iter(|| black_box(full())));
}

#[path = "support/gen.rs"]
#[allow(dead_code)]
mod gen;

criterion_group!(benches, bench, bench_full);
criterion_main!(benches);
