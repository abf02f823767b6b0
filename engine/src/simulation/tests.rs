//! Unit tests of the simulation: energy of passive runs (trees and loops), closure, bounds and
//! errors naming their field, cancellation, a drive holding a pendulum against gravity within
//! its current limit.

use std::path::Path;

use nalgebra::Vector3;

use super::*;
use crate::mechanism::Mechanism;
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::{self, Analysed, Options as PipelineOptions};
use crate::testgen as gen;

fn mechanism_of(a: &Analysed) -> Mechanism {
    Mechanism::from_validated(&a.model, &a.validated).expect("mechanism")
}

fn case(name: &str) -> Mechanism {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in").join(name);
    let bundle = crate::test_bundle_of_dir(&dir).expect("bundle");
    mechanism_of(&pipeline::analyse(&bundle, &PipelineOptions::default()).expect("analyses"))
}

fn arm(n: usize) -> Mechanism {
    let bundle = Bundle::from_files("gen", [("arm.xml".to_string(), gen::serial_arm_xml(n).into_bytes())]).expect("bundle");
    mechanism_of(&pipeline::analyse(&bundle, &PipelineOptions::default()).expect("analyses"))
}

/// Kinetic plus potential energy at a full state.
fn energy(m: &Mechanism, g: &Vector3<f64>, q: &[f64], qd: &[f64]) -> f64 {
    let n = m.dof();
    let mut ws = m.workspace();
    let mut tau = vec![0.0; n];
    m.inverse_dynamics(q, &vec![0.0; n], qd, &Vector3::zeros(), &mut ws, &mut tau).expect("rnea");
    let kinetic = 0.5 * qd.iter().zip(&tau).map(|(a, b)| a * b).sum::<f64>();
    let k = m.forward(q).expect("fk");
    let potential: f64 = m
        .links
        .iter()
        .zip(&k.links)
        .filter(|(l, _)| l.mass > 0.0)
        .map(|(l, pose)| -l.mass * g.dot(&(pose * nalgebra::Point3::from(l.h / l.mass)).coords))
        .sum();
    kinetic + potential
}

fn never() -> bool {
    false
}

#[test]
fn passive_runs_conserve_energy_on_trees_and_loops() {
    let g = Vector3::new(0.0, -9.81, 0.0);
    for (name, m) in [("arm6", arm(6)), ("fourbar", case("fourbar")), ("slider_crank", case("slider_crank"))] {
        let n = m.dof();
        let mut q = m.q0();
        for (i, c) in m.coordinates().iter().enumerate() {
            if c.independent {
                q[i] += 0.3;
            }
        }
        let start = Start { q, qd: vec![0.0; n] };
        let opts = Options { duration: 1.0, output_interval: 0.05, rtol: 1e-10, atol: 1e-12, ..Options::default() };
        let run = simulate(&m, &g, &[], &NoForces, &start, &opts, &never).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(run.t.len(), 21, "{name}: {:?}", run.t);
        assert!(run.t[0] == 0.0 && (run.t[20] - 1.0).abs() < 1e-12, "{name}: {:?}", run.t);
        let e: Vec<f64> = run.q.iter().zip(&run.qd).map(|(q, qd)| energy(&m, &g, q, qd)).collect();
        let swing = run.qd.iter().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
        assert!(swing > 0.1, "{name}: it should move ({swing})");
        // Scale: the largest kinetic energy reached (potential energy has an arbitrary zero).
        let kin_max =
            run.q.iter().zip(&run.qd).map(|(q, qd)| energy(&m, &g, q, qd) - energy(&m, &g, q, &vec![0.0; n])).fold(0.0f64, f64::max);
        let drift = e.iter().map(|x| (x - e[0]).abs()).fold(0.0f64, f64::max) / kin_max;
        let closure = run
            .q
            .iter()
            .zip(&run.cut)
            .map(|(q, c)| m.closure_residual(q, c).expect("residual").iter().fold(0.0f64, |a, b| a.max(b.abs())))
            .fold(0.0f64, f64::max);
        println!(
            "{name}: {} steps ({} rejected), {} evaluations: energy drift {drift:.2e} of the largest kinetic energy, closure {closure:.1e}",
            run.accepted_steps, run.rejected_steps, run.evaluations
        );
        // The integrator's tolerance, loops included: their closure rates are exact
        // (`mechanism/rates.rs`). Measured 1.6e-10 (arm6), 3.3e-10 (four-bar), 4.4e-10
        // (slider-crank); 1.4e-7 and 4.6e-7 for the loops with the central differences before.
        assert!(drift < 1e-9, "{name}: energy drift {drift:e}");
        assert!(closure < 1e-9, "{name}: closure {closure:e}");
    }
}

fn pendulum_drive(m: &Mechanism, i_max: f64, eta: f64, reference: Reference) -> Drive {
    let _ = m;
    Drive {
        coordinate: 0,
        motor: Motor {
            kind: MotorKind::DcPermanentMagnet,
            r: 0.299,
            l: 8.2e-5,
            k: 0.0302,
            j: 1.42e-5,
            d: 0.0,
            v_max: 24.0,
            i_max,
            tc: 0.001,
        },
        transmission: Transmission { ratio: 50.0, eta },
        controller: Controller { kp: 10.0, ks: 0.05, ts: 0.05 },
        reference,
    }
}

#[test]
fn a_drive_holds_the_reference_within_its_current_limit() {
    let m = arm(1);
    let g = Vector3::new(0.0, -9.81, 0.0);
    let q0 = m.q0()[0];
    let start = Start { q: m.q0(), qd: vec![0.0] };
    let opts = Options { duration: 2.0, output_interval: 0.01, rtol: 1e-8, atol: 1e-10, ..Options::default() };
    let target = q0 + 0.5;
    let drive = pendulum_drive(&m, 10.0, 1.0, Reference::Constant(target));
    let run = simulate(&m, &g, std::slice::from_ref(&drive), &NoForces, &start, &opts, &never).expect("runs");
    let last = run.q.last().expect("samples")[0];
    assert!((last - target).abs() < 1e-3, "ends at {last}, reference {target}");
    let tr = run.tracking(std::slice::from_ref(&drive), &[0.0, 2.0]);
    assert!(tr[0].max_current <= 10.0 + 1e-6, "{tr:?}");
    println!(
        "1-DoF drive: final error {:.2e} rad, max current {:.3} A, saturated {:?}, {} steps",
        last - target,
        tr[0].max_current,
        tr[0].saturated,
        run.accepted_steps
    );
    // A current limit below what the step needs saturates, and the current stays within it.
    let tight = pendulum_drive(&m, 1.0, 1.0, Reference::Constant(target));
    let run = simulate(&m, &g, std::slice::from_ref(&tight), &NoForces, &start, &opts, &never).expect("runs");
    let tr = run.tracking(std::slice::from_ref(&tight), &[]);
    assert!(!tr[0].saturated.is_empty(), "{tr:?}");
    assert!(tr[0].max_current <= 1.0 + 1e-6, "{tr:?}");
}

#[test]
fn bad_input_names_its_field_and_runs_are_bounded_and_cancellable() {
    let m = arm(2);
    let g = Vector3::new(0.0, -9.81, 0.0);
    let start = Start { q: m.q0(), qd: vec![0.0; 2] };
    let field_of = |e: SimulationError| match e {
        SimulationError::Field { field, .. } => field,
        other => panic!("{other}"),
    };
    let run = |drives: &[Drive], start: &Start, opts: &Options| simulate(&m, &g, drives, &NoForces, start, opts, &never);
    let o = |d: f64| Options { duration: d, ..Options::default() };
    assert_eq!(field_of(run(&[], &start, &o(-1.0)).unwrap_err()), "duration");
    assert_eq!(field_of(run(&[], &start, &o(f64::NAN)).unwrap_err()), "duration");
    assert_eq!(field_of(run(&[], &start, &o(1e9)).unwrap_err()), "duration");
    assert_eq!(field_of(run(&[], &start, &Options { output_interval: 1e-9, ..Options::default() }).unwrap_err()), "output_interval");
    assert_eq!(field_of(run(&[], &Start { q: vec![0.0], qd: vec![0.0; 2] }, &o(1.0)).unwrap_err()), "start.q");
    assert_eq!(field_of(run(&[], &Start { q: m.q0(), qd: vec![0.0, f64::INFINITY] }, &o(1.0)).unwrap_err()), "start.qd[1]");
    let mut d = pendulum_drive(&m, 10.0, 1.0, Reference::Constant(0.0));
    d.motor.l = 0.0;
    assert_eq!(field_of(run(std::slice::from_ref(&d), &start, &o(1.0)).unwrap_err()), "drives[0].motor.L");
    let mut d = pendulum_drive(&m, 10.0, 1.5, Reference::Constant(0.0));
    assert_eq!(field_of(run(std::slice::from_ref(&d), &start, &o(1.0)).unwrap_err()), "drives[0].gear.eta");
    d.transmission.eta = 1.0;
    d.coordinate = 7;
    assert_eq!(field_of(run(std::slice::from_ref(&d), &start, &o(1.0)).unwrap_err()), "drives[0].coordinate");
    d.coordinate = 0;
    d.reference = Reference::Table(vec![(1.0, 0.0), (0.5, 1.0)]);
    assert_eq!(field_of(run(std::slice::from_ref(&d), &start, &o(1.0)).unwrap_err()), "drives[0].reference");
    // Step budget.
    let e = run(&[], &start, &Options { max_steps: 3, ..Options::default() }).unwrap_err();
    assert!(matches!(&e, SimulationError::Integration { message, .. } if message.starts_with("max_steps")), "{e}");
    // Cancellation after a few steps.
    let calls = std::cell::Cell::new(0);
    let cancel = || {
        calls.set(calls.get() + 1);
        calls.get() > 5
    };
    let e = simulate(&m, &g, &[], &NoForces, &start, &o(10.0), &cancel).unwrap_err();
    assert!(matches!(e, SimulationError::Cancelled { t } if t < 10.0), "{e}");
}

/// The run's result file reads back through `results` with the package's names: every body's
/// pose from its `frame_a` equals our forward kinematics of the simulated joint angles, and the
/// drive's current is there under `drive_<joint>.motor.i`.
#[test]
fn the_result_file_reads_back_with_the_packages_names() {
    let m = arm(2);
    let g = Vector3::new(0.0, -9.81, 0.0);
    let start = Start { q: m.q0(), qd: vec![0.0; 2] };
    let opts = Options { duration: 0.5, output_interval: 0.05, ..Options::default() };
    let drive = pendulum_drive(&m, 10.0, 1.0, Reference::Constant(m.q0()[0] + 0.3));
    let run = simulate(&m, &g, std::slice::from_ref(&drive), &NoForces, &start, &opts, &never).expect("runs");
    let bytes = result_file(&m, &run, std::slice::from_ref(&drive)).expect("file");
    let t = crate::results::mat::Trajectory::read(&bytes, "sim.mat").expect("reads");
    let joint = &m.coordinates()[0].name;
    let i = t.find(&format!("drive_{joint}.motor.i")).expect("current");
    assert!((t.value(i, 5) - run.drives[0][5].i).abs() < 1e-12);
    let p = crate::results::poses::extract(&t, &m);
    assert!(p.summary.missing.is_empty() && p.summary.from_joints.is_empty(), "{:?}", p.summary);
    assert_eq!(
        p.summary.bodies.len(),
        m.body_names().iter().enumerate().filter(|(b, _)| m.body_attachment(crate::pipeline::ir::BodyId(*b as u32)).is_some()).count()
    );
    assert!(p.summary.checks.kinematics.expect("checked") < 1e-9, "{:?}", p.summary.checks);
    // The stream against FK of the run's angles (f32 stream: 1e-6).
    let nb = p.summary.bodies.len();
    let names = m.body_names();
    for (k, q) in run.q.iter().enumerate() {
        let fk = m.forward(q).expect("fk");
        for (j, body) in p.summary.bodies.iter().enumerate() {
            let b = names.iter().position(|n| n == body).expect("body");
            let pose = m.body_pose(&fk, crate::pipeline::ir::BodyId(b as u32)).expect("pose");
            let d = &p.data[(k * nb + j) * 7..(k * nb + j) * 7 + 7];
            let pos = nalgebra::Vector3::new(f64::from(d[0]), f64::from(d[1]), f64::from(d[2]));
            assert!((pos - pose.translation.vector).norm() < 1e-6, "{body} at {k}");
            let q = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                f64::from(d[6]),
                f64::from(d[3]),
                f64::from(d[4]),
                f64::from(d[5]),
            ));
            assert!(q.angle_to(&pose.rotation) < 1e-5, "{body} at {k}");
        }
    }
}

#[test]
fn the_servo_motor_class_and_the_msl_machine_are_simulated_and_other_motors_refused_by_name() {
    use crate::pipeline::back::modelica::mechatronics::{ClassChoice, JointKind, ParamValue};
    let choice = |class: &str, params: &[(&str, f64)]| ClassChoice {
        modelica_class: class.to_string(),
        params: params.iter().map(|(n, v)| (n.to_string(), ParamValue::Real(*v))).collect(),
        instance: String::new(),
    };
    let gear = choice("Modelica.Mechanics.Rotational.Components.IdealGear", &[("ratio", 50.0)]);
    let controller = choice("cad2mo.Drives.Controllers.CascadePPI", &[("kp", 10.0), ("ks", 0.05), ("Ts", 0.05)]);
    let servo = choice("cad2mo.Drives.Motors.ServoMotor", &[("k", 0.05), ("J", 1.42e-5), ("I_max", 5.0)]);
    let m = arm(1);
    let target = m.q0()[0] + 0.5;
    let drive = drive_of("drives.J1", 0, JointKind::Revolute, &servo, &gear, &controller, Reference::Constant(target)).expect("servo");
    assert_eq!(drive.motor.kind, MotorKind::Servo);
    assert_eq!((drive.motor.k, drive.motor.i_max, drive.motor.tc), (0.05, 5.0, 0.001));
    // The servo drive holds the pendulum at the reference: Tc·di/dt = i_cmd − i, τ = k·i.
    let g = Vector3::new(0.0, -9.81, 0.0);
    let opts = Options { duration: 2.0, output_interval: 0.01, rtol: 1e-8, atol: 1e-10, ..Options::default() };
    let run = simulate(&m, &g, std::slice::from_ref(&drive), &NoForces, &Start { q: m.q0(), qd: vec![0.0] }, &opts, &never).expect("runs");
    let last = run.q.last().expect("samples")[0];
    assert!((last - target).abs() < 1e-3, "ends at {last}, reference {target}");
    let s = run.drives[0].last().expect("samples");
    assert!((s.tau - 0.05 * s.i).abs() < 1e-15 && s.v == 0.0, "{s:?}");
    // The MSL machine (Motors.MSL_DC_PermanentMagnet): its constants from the nominal point at
    // the armature's temperatures, as MSL's convertResistance and turnsRatio compute them.
    let msl = choice(
        "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet",
        &[
            ("VaNominal", 24.0),
            ("IaNominal", 2.0),
            ("wNominal", 300.0),
            ("TaNominal", 353.15),
            ("Ra", 1.0),
            ("TaRef", 293.15),
            ("alpha20a", 0.004),
            ("La", 2e-4),
            ("Jr", 2e-5),
            ("TaOperational", 373.15),
        ],
    );
    let d = drive_of("drives.J1", 0, JointKind::Revolute, &msl, &gear, &controller, Reference::Constant(target)).expect("the MSL machine");
    // Ra(T) = Ra·(1 + 0.004·(T − 293.15)): 1.24 Ω at 353.15 K, 1.32 Ω at 373.15 K.
    let want = Motor {
        kind: MotorKind::MslDcPermanentMagnet,
        r: 1.32,
        l: 2e-4,
        k: (24.0 - 1.24 * 2.0) / 300.0,
        j: 2e-5,
        d: 0.0,
        v_max: 24.0,
        i_max: 2.0,
        tc: 0.001,
    };
    for (got, w, what) in [(d.motor.r, want.r, "R"), (d.motor.k, want.k, "k")] {
        assert!((got - w).abs() < 1e-12, "{what}: {got}, want {w}");
    }
    assert_eq!((d.motor.l, d.motor.j, d.motor.v_max, d.motor.i_max, d.motor.tc), (want.l, want.j, want.v_max, want.i_max, want.tc));
    let run = simulate(&m, &g, std::slice::from_ref(&d), &NoForces, &Start { q: m.q0(), qd: vec![0.0] }, &opts, &never).expect("runs");
    let last = run.q.last().expect("samples")[0];
    assert!((last - target).abs() < 1e-3, "the MSL machine ends at {last}, reference {target}");
    assert_eq!(d.motor.kind, want.kind);
    // The same run as the DC motor class with the derived constants; the result file names the
    // MSL machine's variables too.
    let mut dc = d.clone();
    dc.motor.kind = MotorKind::DcPermanentMagnet;
    let dc_run = simulate(&m, &g, std::slice::from_ref(&dc), &NoForces, &Start { q: m.q0(), qd: vec![0.0] }, &opts, &never).expect("runs");
    assert_eq!(dc_run.q, run.q);
    let names: Vec<String> = series(&m, &run, std::slice::from_ref(&d)).expect("series").into_iter().map(|(n, _)| n).collect();
    let joint = &m.coordinates()[0].name;
    for v in ["motor.i", "motor.dcpm.ia", "motor.dcpm.wMechanical", "motor.dcpm.tauElectrical", "motor.supply.v"] {
        assert!(names.contains(&format!("drive_{joint}.{v}")), "{v} in {names:?}");
    }
    let bad =
        choice("Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet", &[("VaNominal", 1.0), ("IaNominal", 100.0)]);
    let err = drive_of("drives.J1", 0, JointKind::Revolute, &bad, &gear, &controller, Reference::Constant(0.0)).expect_err("refused");
    assert!(matches!(&err, SimulationError::Field { field, .. } if field == "drives.J1.motor.VaNominal"), "{err}");
    let other = choice("Modelica.Electrical.Machines.BasicMachines.InductionMachines.IM_SquirrelCage", &[]);
    let err = drive_of("drives.J1", 0, JointKind::Revolute, &other, &gear, &controller, Reference::Constant(0.0)).expect_err("refused");
    assert!(matches!(&err, SimulationError::Field { field, .. } if field == "drives.J1.motor"), "{err}");
}

/// Collects what an observer hears: every third sample and the last.
struct Every3 {
    heard: Vec<(usize, f64, bool, Vec<f64>)>,
}

impl Observer for Every3 {
    fn wants(&mut self, index: usize, _t: f64, last: bool) -> bool {
        index % 3 == 0 || last
    }
    fn sample(&mut self, index: usize, t: f64, last: bool, q: &[f64]) {
        self.heard.push((index, t, last, q.to_vec()));
    }
}

#[test]
fn an_observer_hears_the_samples_of_the_run_while_it_runs() {
    let m = arm(2);
    let g = Vector3::new(0.0, -9.81, 0.0);
    let start = Start { q: m.q0(), qd: vec![0.0; 2] };
    // 0.5 s at 0.035 s: the last sample (14, 0.49 s) is not at the duration.
    let opts = Options { duration: 0.5, output_interval: 0.035, ..Options::default() };
    let drive = pendulum_drive(&m, 10.0, 0.9, Reference::Constant(m.q0()[0] + 0.3));
    let mut o = Every3 { heard: Vec::new() };
    let run = simulate_observed(&m, &g, std::slice::from_ref(&drive), &NoForces, &start, &opts, &never, Some(&mut o)).expect("runs");
    let plain = simulate(&m, &g, std::slice::from_ref(&drive), &NoForces, &start, &opts, &never).expect("runs");
    assert_eq!(run, plain, "observing changes nothing");
    let wanted: Vec<usize> = (0..run.t.len()).filter(|i| i % 3 == 0 || *i == run.t.len() - 1).collect();
    assert_eq!(o.heard.iter().map(|h| h.0).collect::<Vec<_>>(), wanted);
    for (index, t, last, q) in &o.heard {
        assert_eq!(*t, run.t[*index]);
        assert_eq!(q, &run.q[*index], "sample {index}");
        assert_eq!(*last, *index == run.t.len() - 1);
    }
    // The bodies' frames as the result file has them.
    let series = series(&m, &run, std::slice::from_ref(&drive)).expect("series");
    let (index, _, _, q) = o.heard.last().expect("heard");
    let frames = body_frames(&m, q).expect("frames");
    assert_eq!(frames.len(), m.body_names().len());
    for (b, name) in m.body_names().iter().enumerate() {
        let r1 = series.iter().find(|(n, _)| *n == format!("{name}.frame_a.r_0[1]")).expect("r_0");
        let t23 = series.iter().find(|(n, _)| *n == format!("{name}.frame_a.R.T[2,3]")).expect("R.T");
        assert_eq!((frames[b][0], frames[b][3 + 5]), (r1.1[*index], t23.1[*index]), "{name}");
    }
}
