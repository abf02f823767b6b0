//! Unit tests of the mechanism: FK against the CAD, Jacobians (geometric, and the closure's
//! exact rates) against finite differences, loop assembly, IK, and the inverse dynamics' own
//! consistency (gravity as the gradient of the potential energy; power balance).

use std::path::{Path, PathBuf};

use nalgebra::{DMatrix, DVector, Isometry3, Vector3};

use super::*;
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::{self, Analysed, Options};

use crate::testgen as gen;

fn analyse_dir(dir: &Path) -> Option<Analysed> {
    let bundle = crate::test_bundle_of_dir(dir).ok()?;
    pipeline::analyse(&bundle, &Options::default()).ok()
}

fn analyse_xml(name: &str, xml: &str) -> Analysed {
    let bundle = Bundle::from_files("gen", [(name.to_string(), xml.as_bytes().to_vec())]).expect("bundle");
    pipeline::analyse(&bundle, &Options::default()).expect("analyses")
}

fn case(name: &str) -> (Analysed, Mechanism) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in").join(name);
    let a = analyse_dir(&dir).expect("case analyses");
    let m = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    (a, m)
}

/// Every analysable golden case and first-generation fixture XML (alone, without meshes).
fn all_models() -> Vec<(String, Analysed)> {
    let mut out = Vec::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in");
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(&root).expect("tests/in").flatten().map(|e| e.path()).collect();
    dirs.sort();
    for d in dirs {
        if let Some(a) = analyse_dir(&d) {
            out.push((d.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default(), a));
        }
    }
    if let Some(fx) = crate::pipeline::testutil::fixtures_dir() {
        for xml in crate::pipeline::testutil::files_with_ext(&fx, "xml") {
            let Ok(text) = std::fs::read_to_string(&xml) else { continue };
            if !text.contains("<PhysicalModelingXMLFile") {
                continue;
            }
            let name = xml.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default();
            let Ok(bundle) = Bundle::from_files("fx", [(name.clone(), text.into_bytes())]) else { continue };
            if let Ok(a) = pipeline::analyse(&bundle, &Options::default()) {
                out.push((xml.strip_prefix(&fx).unwrap_or(&xml).display().to_string(), a));
            }
        }
    }
    out
}

fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    let dp = (a.translation.vector - b.translation.vector).norm();
    let dr = crate::pipeline::passes::kinematics::rotation_angle(&(a.rotation.inverse() * b.rotation));
    (dp, dr)
}

#[test]
fn fk_at_start_values_reproduces_every_cad_frame() {
    let mut checked = 0;
    for (name, a) in all_models() {
        let m = match Mechanism::from_validated(&a.model, &a.validated) {
            Ok(m) => m,
            Err(e @ (MechanismError::FreeBody { .. } | MechanismError::Spherical { .. })) => {
                println!("{name}: skipped: {e}");
                continue;
            }
            Err(e) => panic!("{name}: {e}"),
        };
        let k = m.forward(&m.q0()).expect("fk");
        let mut worst = (0.0f64, 0.0f64);
        for (i, f) in a.model.frames.iter().enumerate() {
            let (dp, dr) = pose_error(&m.frame_pose(&k, FrameId(i as u32)).expect("frame"), &f.pose);
            worst = (worst.0.max(dp), worst.1.max(dr));
            assert!(dp < 1e-12 && dr < 1e-12, "{name}: frame {} off by {dp:e} m, {dr:e} rad", f.node_id);
        }
        println!("{name}: {} frames, {} coordinates, worst {:e} m {:e} rad", a.model.frames.len(), m.dof(), worst.0, worst.1);
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} models checked");
}

#[test]
fn jacobian_matches_central_differences() {
    let mut rng = XorShift::new(7);
    for (name, a) in all_models() {
        let Ok(m) = Mechanism::from_validated(&a.model, &a.validated) else { continue };
        let q: Vec<f64> = m.q0().iter().map(|q| q + rng.range(-0.5, 0.5)).collect();
        let k = m.forward(&q).expect("fk");
        let h = 1e-6;
        for (fi, _) in a.model.frames.iter().enumerate().step_by(3) {
            let f = FrameId(fi as u32);
            let j = m.jacobian(&k, f).expect("jacobian");
            for c in 0..m.dof() {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[c] += h;
                qm[c] -= h;
                let pp = m.frame_pose(&m.forward(&qp).expect("fk"), f).expect("pose");
                let pm = m.frame_pose(&m.forward(&qm).expect("fk"), f).expect("pose");
                let lin = (pp.translation.vector - pm.translation.vector) / (2.0 * h);
                let ang = (pp.rotation * pm.rotation.inverse()).scaled_axis() / (2.0 * h);
                let col = j.column(c);
                let scale = col.norm().max(1.0);
                let err = (col.fixed_rows::<3>(0) - ang).norm().max((col.fixed_rows::<3>(3) - lin).norm());
                assert!(err <= 1e-6 * scale, "{name}: frame {fi}, column {c}: {err:e} (|J| {scale})");
            }
        }
    }
}

#[test]
fn loops_close_at_start_values_and_after_moving_the_crank() {
    for name in ["fourbar", "slider_crank", "sixbar_6digit", "immobile_leg"] {
        let (_, m) = case(name);
        assert!(m.has_loops(), "{name}: no closure");
        let (q0, c0) = (m.q0(), m.cut_q0());
        let r0 = m.closure_residual(&q0, &c0).expect("residual");
        let r0 = r0.iter().fold(0.0f64, |x, r| x.max(r.abs()));
        assert!(r0 < 1e-10, "{name}: residual {r0:e} at the start values");
        let (mut q, mut c) = (q0.clone(), c0.clone());
        let mut moved = 0;
        for (i, coord) in m.coordinates().iter().enumerate() {
            if coord.independent {
                q[i] += 0.1;
                moved += 1;
            } else {
                q[i] += 0.02; // a worse guess for the dependent ones
            }
        }
        let asm = m.assemble(&mut q, &mut c).unwrap_or_else(|e| panic!("{name}: {e}"));
        let r = m.closure_residual(&q, &c).expect("residual");
        let r = r.iter().fold(0.0f64, |x, r| x.max(r.abs()));
        assert!(r < 1e-10, "{name}: residual {r:e} after assembly");
        // Independent coordinates kept.
        for (i, coord) in m.coordinates().iter().enumerate() {
            if coord.independent {
                assert_eq!(q[i], q0[i] + 0.1);
            }
        }
        println!(
            "{name}: {} equations, moved {moved} independent coordinates, {} iterations, residual {r:e}",
            m.closure_equations(),
            asm.iterations
        );
    }
}

#[test]
fn an_impossible_pose_is_refused_with_its_residual() {
    let (_, mut m) = case("fourbar");
    // The cut's frame_b moved 10 m away: no crank angle closes the loop.
    m.closures[0].b.offset = Isometry3::translation(10.0, 0.0, 0.0) * m.closures[0].b.offset;
    let (mut q, mut c) = (m.q0(), m.cut_q0());
    let e = m.assemble(&mut q, &mut c).expect_err("cannot assemble");
    assert!(matches!(e, MechanismError::NotAssembled { .. }));
    assert!(e.to_string().starts_with("the pose cannot be assembled: residual"), "{e}");
}

#[test]
fn free_bodies_and_spherical_joints_are_refused_by_name() {
    for (name, a) in all_models() {
        match Mechanism::from_validated(&a.model, &a.validated) {
            Err(MechanismError::FreeBody { body, .. }) => assert!(!body.is_empty(), "{name}"),
            Err(MechanismError::Spherical { joint, .. }) => assert!(!joint.is_empty(), "{name}"),
            _ => {}
        }
    }
}

fn arm(n: usize) -> (Analysed, Mechanism) {
    let a = analyse_xml("arm.xml", &gen::serial_arm_xml(n));
    let m = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    assert_eq!(m.dof(), n);
    (a, m)
}

#[test]
fn ik_reaches_random_reachable_targets() {
    for n in [6, 7] {
        let (_, m) = arm(n);
        let tool = m.frame_by_node_id("TOOL").expect("tool");
        let limits = m.default_limits();
        let mut rng = XorShift::new(42);
        let mut ik_rng = XorShift::new(43);
        let (mut ok, trials) = (0, 300);
        for _ in 0..trials {
            let q: Vec<f64> = limits.iter().map(|(lo, hi)| rng.range(*lo, *hi)).collect();
            let target = m.frame_pose(&m.forward(&q).expect("fk"), tool).expect("pose");
            let r = m.inverse_kinematics(tool, &IkTarget::Pose(target), &m.q0(), &IkOptions::default(), &mut ik_rng).expect("ik");
            if r.success {
                let got = m.frame_pose(&m.forward(&r.q).expect("fk"), tool).expect("pose");
                let (dp, dr) = pose_error(&got, &target);
                assert!(dp < 1e-6 && dr < 1e-6, "claimed success at {dp:e} m {dr:e} rad");
                ok += 1;
            }
        }
        assert!(ok as f64 >= 0.995 * trials as f64, "{n}-DoF: {ok} of {trials}");
        // Position only.
        let q: Vec<f64> = limits.iter().map(|(lo, hi)| rng.range(*lo, *hi)).collect();
        let p = m.frame_pose(&m.forward(&q).expect("fk"), tool).expect("pose").translation.vector;
        let r = m.inverse_kinematics(tool, &IkTarget::Position(p), &m.q0(), &IkOptions::default(), &mut ik_rng).expect("ik");
        assert!(r.success && r.position_error < 1e-6, "{r:?}");
    }
}

/// The potential energy `V = -Σ m g·c` of every body at coordinates `q`.
fn potential_energy(a: &Analysed, m: &Mechanism, g: &Vector3<f64>, q: &[f64]) -> f64 {
    let k = m.forward(q).expect("fk");
    (0..a.model.bodies.len())
        .map(|b| {
            let mp = a.model.mass_properties_cs1(BodyId(b as u32));
            let c = m.body_pose(&k, BodyId(b as u32)).expect("pose") * nalgebra::Point3::from(mp.r_cm);
            -mp.mass * g.dot(&c.coords)
        })
        .sum()
}

/// Gravity torques are the gradient of the potential energy `V = -Σ m g·c`; with gravity off,
/// `qd·tau = dT/dt` for the kinetic energy `T = ½ qd·M qd` (M from the same RNEA, columns at zero
/// speed), which checks the velocity-product terms.
#[test]
fn inverse_dynamics_is_consistent_with_energy() {
    let (a, m) = arm(7);
    let g = Vector3::new(0.3, -9.81, 0.7);
    let n = m.dof();
    let mut ws = m.workspace();
    let mut rng = XorShift::new(3);
    let q: Vec<f64> = m.q0().iter().map(|q| q + rng.range(-1.0, 1.0)).collect();
    let zero = vec![0.0; n];
    let mut tau = vec![0.0; n];
    m.inverse_dynamics(&q, &zero, &zero, &g, &mut ws, &mut tau).expect("rnea");
    let potential = |q: &[f64]| potential_energy(&a, &m, &g, q);
    for i in 0..n {
        let h = 1e-6;
        let (mut qp, mut qm) = (q.clone(), q.clone());
        qp[i] += h;
        qm[i] -= h;
        let dv = (potential(&qp) - potential(&qm)) / (2.0 * h);
        assert!((dv - tau[i]).abs() < 1e-6 * dv.abs().max(1.0), "gravity {i}: {dv} vs {}", tau[i]);
    }
    let g0 = Vector3::zeros();
    let mass_matrix = |q: &[f64], ws: &mut Workspace| {
        let mut mm = nalgebra::DMatrix::<f64>::zeros(n, n);
        let mut col = vec![0.0; n];
        for j in 0..n {
            let mut e = vec![0.0; n];
            e[j] = 1.0;
            m.inverse_dynamics(q, &zero, &e, &g0, ws, &mut col).expect("rnea");
            for i in 0..n {
                mm[(i, j)] = col[i];
            }
        }
        mm
    };
    let mm = mass_matrix(&q, &mut ws);
    assert!((mm.clone() - mm.transpose()).amax() < 1e-12 * mm.amax(), "M not symmetric");
    let qd: Vec<f64> = (0..n).map(|_| rng.range(-2.0, 2.0)).collect();
    let qdd: Vec<f64> = (0..n).map(|_| rng.range(-5.0, 5.0)).collect();
    m.inverse_dynamics(&q, &qd, &qdd, &g0, &mut ws, &mut tau).expect("rnea");
    let power: f64 = qd.iter().zip(&tau).map(|(a, b)| a * b).sum();
    let kinetic = |t: f64, ws: &mut Workspace| {
        let qt: Vec<f64> = (0..n).map(|i| q[i] + qd[i] * t + 0.5 * qdd[i] * t * t).collect();
        let qdt = nalgebra::DVector::from_iterator(n, (0..n).map(|i| qd[i] + qdd[i] * t));
        0.5 * (qdt.transpose() * mass_matrix(&qt, ws) * &qdt)[(0, 0)]
    };
    let dt = 1e-5;
    let dtdt = (kinetic(dt, &mut ws) - kinetic(-dt, &mut ws)) / (2.0 * dt);
    assert!((power - dtdt).abs() < 1e-6 * power.abs().max(1.0), "power {power} vs dT/dt {dtdt}");
}

#[test]
fn lengths_are_checked() {
    let (_, m) = arm(6);
    assert!(matches!(m.forward(&[0.0; 3]), Err(MechanismError::Length { expected: 6, got: 3, .. })));
}

/// Loops driven at their independent coordinates: the driven torques are the gradient of the
/// potential energy along the closed mechanism (statics), and their power is the rate of change
/// of the total energy (dynamics), on every loop case.
#[test]
fn driven_loop_torques_balance_energy() {
    for name in ["fourbar", "crank_rocker_noise", "slider_crank", "sixbar_6digit"] {
        let (a, m) = case(name);
        assert!(m.has_loops(), "{name}");
        let n = m.dof();
        let driven = m.driven();
        assert!(!driven.is_empty() && driven.len() < n, "{name}: driven {driven:?}");
        let g = Vector3::new(0.3, -9.81, 0.7);
        let mut ws = m.workspace();
        let potential = |q: &[f64]| potential_energy(&a, &m, &g, q);
        let kinetic = |s: &ClosedState, ws: &mut Workspace| -> f64 {
            // ½ q̇ᵀ M q̇ = ½ q̇ · τ(q, 0, q̇) with gravity off.
            let mut tau = vec![0.0; n];
            m.inverse_dynamics(&s.q, &vec![0.0; n], &s.qd, &Vector3::zeros(), ws, &mut tau).expect("rnea");
            0.5 * s.qd.iter().zip(&tau).map(|(a, b)| a * b).sum::<f64>()
        };
        let closed = |t: f64, qd_i: &[f64], qdd_i: &[f64]| -> ClosedState {
            let mut s = ClosedState { q: m.q0(), qd: vec![0.0; n], qdd: vec![0.0; n], cut: m.cut_q0() };
            for (k, &i) in driven.iter().enumerate() {
                s.q[i] += qd_i[k] * t + 0.5 * qdd_i[k] * t * t;
                s.qd[i] = qd_i[k] + qdd_i[k] * t;
                s.qdd[i] = qdd_i[k];
            }
            m.close(&mut s).expect("closes");
            s
        };
        let mut rng = XorShift::new(11);
        let qd_i: Vec<f64> = driven.iter().map(|_| rng.range(-0.5, 0.5)).collect();
        let qdd_i: Vec<f64> = driven.iter().map(|_| rng.range(-1.0, 1.0)).collect();
        // Statics: at rest, τ_i = ∂V/∂q_i on the closed mechanism.
        let zero = vec![0.0; driven.len()];
        let rest = closed(0.0, &zero, &zero);
        let mut tree = vec![0.0; n];
        let tau = m.driven_torques(&rest, &g, &mut ws, &mut tree).expect("torques");
        for (k, &i) in driven.iter().enumerate() {
            let h = 1e-5;
            let mut dir = zero.clone();
            dir[k] = 1.0;
            let vp = potential(&closed(h, &dir, &zero).q);
            let vm = potential(&closed(-h, &dir, &zero).q);
            let dv = (vp - vm) / (2.0 * h);
            assert!((dv - tau[k]).abs() < 1e-5 * dv.abs().max(1e-3), "{name}: gravity at {i}: dV/dq {dv} vs {}", tau[k]);
        }
        // Dynamics: τ·q̇ = d(T + V)/dt along the closed motion.
        let s0 = closed(0.0, &qd_i, &qdd_i);
        let tau = m.driven_torques(&s0, &g, &mut ws, &mut tree).expect("torques");
        let power: f64 = tau.iter().zip(&qd_i).map(|(a, b)| a * b).sum();
        let dt = 1e-4;
        let e = |t: f64, ws: &mut Workspace| {
            let s = closed(t, &qd_i, &qdd_i);
            kinetic(&s, ws) + potential(&s.q)
        };
        let de = (e(dt, &mut ws) - e(-dt, &mut ws)) / (2.0 * dt);
        assert!((power - de).abs() < 1e-5 * de.abs().max(power.abs()).max(1e-3), "{name}: power {power} vs dE/dt {de}");
        // Followers move consistently: their speeds are the time derivative of their positions.
        let (p, mm) = (closed(dt, &qd_i, &qdd_i), closed(-dt, &qd_i, &qdd_i));
        for i in 0..n {
            let fd = (p.q[i] - mm.q[i]) / (2.0 * dt);
            assert!((fd - s0.qd[i]).abs() < 1e-6 * fd.abs().max(1.0), "{name}: speed of {i}: {fd} vs {}", s0.qd[i]);
            let fdd = (p.qd[i] - mm.qd[i]) / (2.0 * dt);
            assert!((fdd - s0.qdd[i]).abs() < 1e-4 * fdd.abs().max(1.0), "{name}: acceleration of {i}: {fdd} vs {}", s0.qdd[i]);
        }
        let inertia = m.driven_inertia(&s0, &mut ws).expect("inertia");
        assert!(inertia.iter().all(|x| *x > 0.0), "{name}: {inertia:?}");
    }
}

/// Every tree mechanism we can build: generated arms and trees, the golden cases and fixture
/// XMLs, and the fixture URDFs (text alone).
fn tree_mechanisms() -> Vec<(String, Mechanism)> {
    let mut models: Vec<(String, Analysed)> = vec![
        ("arm6".into(), analyse_xml("arm.xml", &gen::serial_arm_xml(6))),
        ("tree50".into(), analyse_xml("tree.xml", &gen::tree_xml(50))),
    ];
    models.extend(all_models());
    if let Some(fx) = crate::pipeline::testutil::fixtures_dir() {
        for urdf in crate::pipeline::testutil::files_with_ext(&fx.join("urdf"), "urdf") {
            let Ok(text) = std::fs::read(&urdf) else { continue };
            let Ok(bundle) = Bundle::from_files("fx", [("robot.urdf".to_string(), text)]) else { continue };
            if let Ok(a) = pipeline::analyse(&bundle, &Options { write_shapes: false, ..Options::default() }) {
                models.push((urdf.strip_prefix(&fx).unwrap_or(&urdf).display().to_string(), a));
            }
        }
    }
    models
        .into_iter()
        .filter_map(|(name, a)| {
            let m = Mechanism::from_validated(&a.model, &a.validated).ok()?;
            (!m.has_loops() && m.dof() > 0).then_some((name, m))
        })
        .collect()
}

/// `forward_dynamics(q, q̇, inverse_dynamics(q, q̇, q̈)) == q̈` at random states of every tree.
#[test]
fn forward_dynamics_inverts_inverse_dynamics() {
    let g = Vector3::new(0.3, -9.81, 0.7);
    let mut rng = XorShift::new(5);
    let (mut checked, mut urdfs, mut worst) = (0, 0, 0.0f64);
    for (name, m) in tree_mechanisms() {
        let n = m.dof();
        let (mut ws, mut fws) = (m.workspace(), m.forward_workspace());
        for _ in 0..5 {
            let q: Vec<f64> = m.q0().iter().map(|q| q + rng.range(-1.0, 1.0)).collect();
            let qd: Vec<f64> = (0..n).map(|_| rng.range(-2.0, 2.0)).collect();
            let qdd: Vec<f64> = (0..n).map(|_| rng.range(-5.0, 5.0)).collect();
            let mut tau = vec![0.0; n];
            m.inverse_dynamics(&q, &qd, &qdd, &g, &mut ws, &mut tau).expect("rnea");
            let mut back = vec![0.0; n];
            match m.forward_dynamics(&q, &qd, &tau, &g, &mut fws, &mut back) {
                Ok(()) => {}
                Err(MechanismError::Singular { coordinate }) => {
                    println!("{name}: singular at {coordinate} (a coordinate moving no mass): skipped");
                    break;
                }
                Err(e) => panic!("{name}: {e}"),
            }
            for k in 0..n {
                let err = (back[k] - qdd[k]).abs() / 5.0;
                worst = worst.max(err);
                assert!(err < 1e-9, "{name}: coordinate {}: {} vs {} (relative {err:e})", m.coordinates()[k].name, back[k], qdd[k]);
            }
        }
        checked += 1;
        urdfs += usize::from(name.ends_with(".urdf"));
    }
    println!("{checked} trees ({urdfs} fixture URDFs): worst |q̈ - q̈'| {worst:e} of the 5 rad/s² range");
    assert!(checked >= 5, "{checked}");
}

/// Closed loops: the accelerations the driven torques of `driven.rs` (energy-checked above)
/// produce are the ones they were computed for, and the completed state closes.
#[test]
fn closed_forward_dynamics_inverts_driven_torques() {
    for name in ["fourbar", "crank_rocker_noise", "slider_crank", "sixbar_6digit", "urdf_fourbar"] {
        let (_, m) = case(name);
        assert!(m.has_loops(), "{name}");
        let n = m.dof();
        let driven = m.driven();
        let g = Vector3::new(0.3, -9.81, 0.7);
        let (mut ws, mut fws) = (m.workspace(), m.forward_workspace());
        let mut rng = XorShift::new(17);
        for _ in 0..3 {
            let mut s = ClosedState { q: m.q0(), qd: vec![0.0; n], qdd: vec![0.0; n], cut: m.cut_q0() };
            for &i in &driven {
                s.q[i] += rng.range(-0.3, 0.3);
                s.qd[i] = rng.range(-1.0, 1.0);
                s.qdd[i] = rng.range(-3.0, 3.0);
            }
            m.close(&mut s).expect("closes");
            let mut tree = vec![0.0; n];
            let tau_i = m.driven_torques(&s, &g, &mut ws, &mut tree).expect("torques");
            let mut tau = vec![0.0; n];
            for (k, &i) in driven.iter().enumerate() {
                tau[i] = tau_i[k];
            }
            let mut f = ClosedState { q: s.q.clone(), qd: s.qd.clone(), qdd: vec![], cut: s.cut.clone() };
            for i in 0..n {
                if !m.coordinates()[i].independent {
                    f.q[i] += 0.01; // a guess only
                    f.qd[i] = 0.0;
                }
            }
            m.closed_forward_dynamics(&mut f, &tau, &[], &g, &mut ws, &mut fws).expect("forward");
            for i in 0..n {
                assert!((f.q[i] - s.q[i]).abs() < 1e-10, "{name}: position {i}: {} vs {}", f.q[i], s.q[i]);
                assert!((f.qd[i] - s.qd[i]).abs() < 1e-7 * s.qd[i].abs().max(1.0), "{name}: speed {i}: {} vs {}", f.qd[i], s.qd[i]);
                assert!(
                    (f.qdd[i] - s.qdd[i]).abs() < 1e-5 * s.qdd[i].abs().max(1.0),
                    "{name}: acceleration {i}: {} vs {}",
                    f.qdd[i],
                    s.qdd[i]
                );
            }
            let r = m.closure_residual(&f.q, &f.cut).expect("residual");
            assert!(r.iter().all(|x| x.abs() < 1e-10), "{name}: residual {r:?}");
        }
    }
}

/// The closure's forms as the loop cases have them, and every other form put on the four-bar's
/// cut: each `Joints.Constraints` class (with different locked axes), and a plain cut of a
/// revolute and a prismatic element, its residual the CAD pose's (so it closes there).
fn closure_form_cases() -> Vec<(String, Mechanism)> {
    let mut out = Vec::new();
    for name in ["fourbar", "crank_rocker_noise", "slider_crank", "sixbar_6digit", "immobile_leg", "urdf_fourbar"] {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in").join(name);
        let a = analyse_dir(&dir).expect("case analyses");
        let m = Mechanism::from_validated(&a.model, &a.validated).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(m.has_dependent(), "{name}");
        let forms: Vec<String> =
            m.closures.iter().map(|c| format!("{:?}", c.form).split([' ', '{']).next().unwrap_or("").to_string()).collect();
        println!("{name}: closures {forms:?}, {} couplings", m.couplings.len());
        out.push((name.to_string(), m));
    }
    let (_, base) = case("fourbar");
    let n_axis = Vector3::new(0.3, -0.2, 0.93).normalize();
    let n_b = crate::pipeline::passes::loops::perpendicular(&n_axis);
    for (class, locked) in [
        (ConstraintClass::Spherical, [true, true, true]),
        (ConstraintClass::Revolute, [true, false, true]),
        (ConstraintClass::Prismatic, [false, true, true]),
        (ConstraintClass::Universal, [true, true, false]),
    ] {
        let mut m = base.clone();
        m.closures[0].form = ClosureForm::Constraint { class, locked, n: n_axis, n_b };
        out.push((format!("fourbar as {class:?}"), m));
    }
    let mut m = base.clone();
    let k = m.forward(&m.q0()).expect("fk");
    let (a, b) = (m.attachment_pose(&k, &m.closures[0].a), m.attachment_pose(&k, &m.closures[0].b));
    let elements = vec![(false, Vector3::new(0.0, 0.6, 0.8), 0), (true, Vector3::new(1.0, 0.0, 0.0), 1)];
    m.closures[0].form = ClosureForm::Plain { elements, residual: a.inverse() * b };
    let mut c = m.coordinates[0].clone();
    c.q0 = 0.0;
    c.independent = false;
    m.cut_coordinates = vec![c.clone(), Coordinate { kind: CoordKind::Prismatic, ..c }];
    out.push(("fourbar as a plain revolute + prismatic cut".into(), m));
    out
}

/// The exact closure rates (`rates.rs`) against differences, at random states (not closed: the
/// rates hold anywhere) moved 0.5, 0.05 and 0.002 off the CAD pose (the rotation vectors'
/// closed form and series): the Jacobian against central differences of the residual (step
/// 1e-6), and the velocity-product term `(Φ_x ẋ)_x ẋ` against a central difference of the exact
/// Jacobian along `ẋ`, both within 1e-7 of their largest entry.
#[test]
fn closure_rates_match_differences() {
    let mut rng = XorShift::new(29);
    let (mut worst_j, mut worst_c) = (0.0f64, 0.0f64);
    for (name, m) in closure_form_cases() {
        let (n, nc) = (m.dof(), m.cut_coordinates().len());
        let x0: Vec<f64> = m.q0().into_iter().chain(m.cut_q0()).collect();
        let jac = |x: &[f64]| m.closure_jacobian_at(&m.forward(&x[..n]).expect("fk"), &x[n..]);
        let residual = |x: &[f64]| DVector::from_vec(m.closure_residual(&x[..n], &x[n..]).expect("residual"));
        for (s, spread) in [0.5, 0.5, 0.05, 0.002].into_iter().enumerate() {
            let x: Vec<f64> = x0.iter().map(|v| v + rng.range(-spread, spread)).collect();
            let xd: Vec<f64> = x.iter().map(|_| rng.range(-2.0, 2.0)).collect();
            let j = jac(&x);
            let h = 1e-6;
            let mut fd = DMatrix::zeros(j.nrows(), n + nc);
            for c in 0..n + nc {
                let (mut p, mut q) = (x.clone(), x.clone());
                p[c] += h;
                q[c] -= h;
                fd.set_column(c, &((residual(&p) - residual(&q)) / (2.0 * h)));
            }
            let scale = j.amax();
            let err = (&j - &fd).amax() / scale;
            assert!(err < 1e-7, "{name}, state {s}: Jacobian off by {err:e} of {scale}\nexact {j}\ndifferences {fd}");
            worst_j = worst_j.max(err);
            let curv = m.closure_curvature(&m.forward(&x[..n]).expect("fk"), &x[n..], &xd[..n], &xd[n..]);
            let along = |t: f64| -> Vec<f64> { x.iter().zip(&xd).map(|(a, b)| a + t * b).collect() };
            let fd_curv = (jac(&along(h)) - jac(&along(-h))) / (2.0 * h) * DVector::from_column_slice(&xd);
            let scale = curv.amax();
            let err = (&curv - &fd_curv).amax() / scale;
            assert!(err < 1e-7, "{name}, state {s}: velocity-product term off by {err:e} of {scale}: exact {curv}, differences {fd_curv}");
            worst_c = worst_c.max(err);
        }
    }
    println!("closure rates: Jacobians within {worst_j:.1e}, velocity-product terms within {worst_c:.1e} of their largest entry");
}
