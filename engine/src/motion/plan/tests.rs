//! Planning on a generated 6-DoF arm: keyframes, IK keyframes, limits, durations, dwell and
//! the problems users see.

use super::*;
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::{self, Options};

use crate::testgen as gen;

fn arm() -> Mechanism {
    let bundle = Bundle::from_files("gen", [("arm.xml".to_string(), gen::serial_arm_xml(6).into_bytes())]).expect("bundle");
    let a = pipeline::analyse(&bundle, &Options::default()).expect("analyses");
    Mechanism::from_validated(&a.model, &a.validated).expect("mechanism")
}

fn joints(values: &[(&str, f64)], interpolation: Interpolation, duration: Option<f64>) -> Keyframe {
    Keyframe {
        target: Target::Joints { values: values.iter().map(|(n, v)| (n.to_string(), *v)).collect() },
        interpolation,
        duration,
        dwell: None,
    }
}

fn names(m: &Mechanism) -> Vec<String> {
    m.coordinates().iter().map(|c| c.name.clone()).collect()
}

#[test]
fn ptp_segments_match_kinematic_ptp2_and_chain() {
    let m = arm();
    let axes = axes(&m, &BTreeMap::new());
    let n = names(&m);
    let spec = MotionSpec {
        name: "m".into(),
        keyframes: vec![
            joints(&[], Interpolation::Ptp, None),
            joints(&[(&n[0], 1.0), (&n[1], -0.5)], Interpolation::Ptp, None),
            Keyframe { dwell: Some(0.25), ..joints(&[(&n[0], 0.0)], Interpolation::Quintic, Some(2.0)) },
        ],
    };
    let p = plan(&m, &axes, &spec).expect("plans");
    // Axis 0 moves 1 rad (limits 3 rad/s, 15 rad/s²) and sets the pace: 3/15 = 0.2 s to top
    // speed, 0.3 rad in each of acceleration and deceleration, 0.4 rad at 3 rad/s.
    let t1 = 0.4 + 0.4 / 3.0;
    assert!((p.keyframes[1].time - t1).abs() < 1e-12, "{}", p.keyframes[1].time);
    assert!((p.keyframes[2].time - (t1 + 2.0)).abs() < 1e-12);
    assert!((p.duration - (t1 + 2.25)).abs() < 1e-12);
    // Continuity at keyframes; the untouched joint stays; the second keyframe's J2 kept.
    let s = p.sample(t1);
    assert!((s.q[0] - 1.0).abs() < 1e-12 && (s.q[1] - (-0.5)).abs() < 1e-12);
    assert_eq!(s.q[2], m.coordinates()[2].q0);
    let end = p.sample(p.duration + 1.0);
    assert!((end.q[0]).abs() < 1e-12 && (end.q[1] + 0.5).abs() < 1e-12 && end.qd.iter().all(|v| *v == 0.0));
    // Peak speed of the PTP segment is the limit, of the quintic 15/8 Δq/T.
    let s = p.samples(1000.0);
    assert_eq!(s.t.len(), p.sample_count(1000.0));
    assert!((s.t.last().copied().unwrap_or_default() - p.duration).abs() < 1e-12);
    let vmax = s.qd[0].iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    assert!((vmax - 3.0).abs() < 1e-9, "{vmax}");
    let v_quintic = s.qd[0].iter().zip(&s.t).filter(|(_, t)| **t > t1).fold(0.0_f64, |a, (v, _)| a.max(v.abs()));
    assert!((v_quintic - 15.0 / 16.0).abs() < 1e-4, "{v_quintic}");
}

#[test]
fn a_longer_ptp_duration_slows_the_profile_and_a_shorter_one_is_refused() {
    let m = arm();
    let axes = axes(&m, &BTreeMap::new());
    let n = names(&m);
    let spec = |d| MotionSpec {
        name: "m".into(),
        keyframes: vec![joints(&[], Interpolation::Ptp, None), joints(&[(&n[0], 1.0)], Interpolation::Ptp, Some(d))],
    };
    let p = plan(&m, &axes, &spec(3.0)).expect("plans");
    assert!((p.duration - 3.0).abs() < 1e-12, "{}", p.duration);
    let e = plan(&m, &axes, &spec(0.1)).err().expect("too short");
    assert_eq!(e[0].field, "keyframes[1].duration");
    assert!(e[0].message.contains("at least 0.533333 s"), "{}", e[0].message);
}

#[test]
fn ik_keyframes_reach_their_target_and_report_the_solve() {
    let m = arm();
    let axes = axes(&m, &BTreeMap::new());
    let tool = m.frame_by_node_id("TOOL").expect("tool");
    let goal: Vec<f64> = m.coordinates().iter().enumerate().map(|(i, c)| c.q0 + 0.2 * (i as f64 + 1.0) - 0.5).collect();
    let pose = m.frame_pose(&m.forward(&goal).expect("fk"), tool).expect("pose");
    let r = pose.rotation.to_rotation_matrix();
    let rows = [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[(i, j)]));
    let p = pose.translation.vector;
    let spec = MotionSpec {
        name: "ik".into(),
        keyframes: vec![
            joints(&[], Interpolation::Ptp, None),
            Keyframe {
                target: Target::Tool { frame: "TOOL".into(), position: [p.x, p.y, p.z], rotation: Some(rows) },
                interpolation: Interpolation::Jerk,
                duration: None,
                dwell: None,
            },
        ],
    };
    let planned = plan(&m, &axes, &spec).expect("plans");
    let ik = planned.keyframes[1].ik.clone().expect("ik report");
    assert!(ik.position_error < 1e-6 && ik.rotation_error < 1e-6);
    let q_end = planned.sample(planned.duration).q;
    let reached = m.frame_pose(&m.forward(&q_end).expect("fk"), tool).expect("pose");
    assert!((reached.translation.vector - p).norm() < 1e-6);
    // Jerk-limited: within every limit along the way.
    let s = planned.samples(1000.0);
    for (i, a) in axes.iter().enumerate() {
        assert!(s.qd[i].iter().all(|v| v.abs() <= a.limits.speed * (1.0 + 1e-6)));
        assert!(s.qdd[i].iter().all(|v| v.abs() <= a.limits.acceleration * (1.0 + 1e-6)));
    }
}

#[test]
fn problems_name_the_keyframe_and_joint() {
    let m = arm();
    let n = names(&m);
    let mut edits = BTreeMap::new();
    edits.insert(n[1].clone(), LimitsEdit { position: Some([-1.0, 1.0]), ..LimitsEdit::default() });
    let axes = axes(&m, &edits);
    let spec = MotionSpec {
        name: "bad".into(),
        keyframes: vec![
            joints(&[], Interpolation::Ptp, None),
            joints(&[("GONE", 1.0)], Interpolation::Ptp, None),
            joints(&[(&n[1], 2.5)], Interpolation::Ptp, None),
            Keyframe {
                target: Target::Tool { frame: "TOOL".into(), position: [50.0, 0.0, 0.0], rotation: None },
                interpolation: Interpolation::Ptp,
                duration: None,
                dwell: None,
            },
            joints(&[(&n[0], 1.0)], Interpolation::Quintic, Some(0.1)),
        ],
    };
    let e = plan(&m, &axes, &spec).err().expect("refused");
    let text: Vec<String> = e.iter().map(|i| format!("{}: {}", i.field, i.message)).collect();
    assert!(text.iter().any(|t| t.starts_with("keyframes[1].values.GONE") && t.contains("not a joint")), "{text:?}");
    assert!(
        text.iter()
            .any(|t| t.starts_with("keyframes[2]") && t.contains(&format!("{} = 2.5 rad is outside its position limits [-1, 1]", n[1]))),
        "{text:?}"
    );
    assert!(text.iter().any(|t| t.starts_with("keyframes[3]") && t.contains("inverse kinematics failed for frame \"TOOL\"")), "{text:?}");
    // The quintic's speed problem only shows once positions are fine.
    let spec2 = MotionSpec { name: "q".into(), keyframes: vec![spec.keyframes[0].clone(), spec.keyframes[4].clone()] };
    let e = plan(&m, &axes, &spec2).err().expect("too fast");
    assert!(e[0].message.contains("above its speed limit 3"), "{:?}", e);
    let form = check_spec(&MotionSpec { name: " ".into(), keyframes: vec![spec.keyframes[0].clone()] });
    assert_eq!(form.len(), 2, "{form:?}");
}

#[test]
fn gravity_torques_along_a_motion_match_a_static_solve() {
    let m = arm();
    let axes = axes(&m, &BTreeMap::new());
    let n = names(&m);
    let spec = MotionSpec {
        name: "m".into(),
        keyframes: vec![
            joints(&[], Interpolation::Ptp, None),
            Keyframe { dwell: Some(1.0), ..joints(&[(&n[1], 0.3)], Interpolation::Ptp, None) },
        ],
    };
    let p = plan(&m, &axes, &spec).expect("plans");
    let s = p.samples(100.0);
    let g = Vector3::new(0.0, 0.0, -9.81);
    let (tau, inertia) = inverse_dynamics(&m, &s, &g, 10).expect("id");
    // During the dwell the torques are the static gravity torques of the final pose.
    let last = s.t.len() - 1;
    let q: Vec<f64> = (0..m.dof()).map(|a| s.q[a][last]).collect();
    let mut ws = m.workspace();
    let mut st = vec![0.0; m.dof()];
    m.inverse_dynamics(&q, &vec![0.0; m.dof()], &vec![0.0; m.dof()], &g, &mut ws, &mut st).expect("static");
    for a in 0..m.dof() {
        assert!((tau[a][last] - st[a]).abs() < 1e-12 * st[a].abs().max(1.0));
        assert!(inertia[a] > 0.0, "axis {a}");
    }
}

#[test]
fn loop_mechanisms_are_driven_at_their_independent_joints() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/fourbar");
    let bundle = crate::test_bundle_of_dir(&dir).expect("bundle");
    let a = pipeline::analyse(&bundle, &Options::default()).expect("analyses");
    let m = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    let axes = axes(&m, &BTreeMap::new());
    let driven = m.driven();
    assert_eq!(driven.len(), 1, "a four-bar has one degree of freedom");
    let d = axes[driven[0]].name.clone();
    let follower = axes.iter().enumerate().find(|(i, _)| !driven.contains(i)).map(|(_, a)| a.name.clone()).expect("a follower");
    let spec = MotionSpec {
        name: "crank".into(),
        keyframes: vec![
            joints(&[], Interpolation::Ptp, None),
            joints(&[(&d, axes[driven[0]].q0 + 0.3)], Interpolation::Quintic, Some(1.0)),
        ],
    };
    let p = plan(&m, &axes, &spec).expect("plans");
    let s = p.closed_samples(&m, 100.0).expect("closes");
    for i in 0..s.t.len() {
        let q: Vec<f64> = (0..m.dof()).map(|a| s.q[a][i]).collect();
        let r = m.closure_residual(&q, &s.cut[i]).expect("residual");
        assert!(r.iter().all(|x| x.abs() < 1e-9), "t = {}: {r:?}", s.t[i]);
    }
    // The followers move; the torques sit at the driven joint only.
    let f = axes.iter().position(|a| a.name == follower).expect("index");
    assert!((s.q[f][s.t.len() - 1] - s.q[f][0]).abs() > 1e-3);
    let (tau, inertia) = inverse_dynamics(&m, &s, &Vector3::new(0.0, -9.81, 0.0), 10).expect("id");
    assert!(tau[f].iter().all(|t| *t == 0.0));
    assert!(tau[driven[0]].iter().any(|t| t.abs() > 0.0) && inertia[driven[0]] > 0.0);
    // A keyframe on a follower is refused, naming the driven joints.
    let bad = MotionSpec {
        name: "x".into(),
        keyframes: vec![joints(&[], Interpolation::Ptp, None), joints(&[(&follower, 0.1)], Interpolation::Ptp, None)],
    };
    let e = plan(&m, &axes, &bad).err().expect("refused");
    assert!(e[0].message.contains("follows the closure of a kinematic loop") && e[0].message.contains(&d), "{e:?}");
}
