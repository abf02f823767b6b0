//! Complete loads: joint losses (damping, Coulomb friction), mimic couplings as dependent
//! coordinates, and inverse kinematics through loop closures.

use std::collections::BTreeMap;
use std::path::Path;

use nalgebra::Vector3;

use super::*;
use crate::motion::plan::{self, Interpolation, Keyframe, MotionSpec, Target};
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::{self, Analysed, Options};

fn analyse_urdf(text: &str) -> Analysed {
    let bundle = Bundle::from_files("u", [("robot.urdf".to_string(), text.as_bytes().to_vec())]).expect("bundle");
    pipeline::analyse(&bundle, &Options { write_shapes: false, ..Options::default() }).expect("analyses")
}

/// A base, an arm on a revolute (damping 0.7, friction 0.25), a slider on it (damping 3,
/// friction 1.5) and a second slider and a second revolute coupled by mimic to the first ones
/// (multipliers 1 and -2, as Panda's finger and a geared wrist).
const GRIPPER: &str = r#"<robot name="gripper">
  <link name="world"/>
  <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0.2 0.01 0.03" rpy="0.1 0.2 0.3"/><mass value="1.3"/><inertia ixx="0.002" ixy="0.0001" ixz="0" iyy="0.01" iyz="0.0002" izz="0.011"/></inertial></link>
  <link name="finger1"><inertial><origin xyz="0.01 0.02 0.0"/><mass value="0.2"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/></inertial></link>
  <link name="finger2"><inertial><origin xyz="0.01 -0.02 0.0"/><mass value="0.25"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/></inertial></link>
  <link name="wrist"><inertial><origin xyz="0.05 0 0.02"/><mass value="0.4"/><inertia ixx="0.0003" ixy="0" ixz="0" iyy="0.0004" iyz="0" izz="0.0005"/></inertial></link>
  <link name="tool"><inertial><origin xyz="0.03 0 0"/><mass value="0.3"/><inertia ixx="0.0002" ixy="0" ixz="0" iyy="0.0002" iyz="0" izz="0.0002"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="50" velocity="2"/><dynamics damping="0.7" friction="0.25"/></joint>
  <joint name="finger_joint1" type="prismatic"><parent link="arm"/><child link="finger1"/><origin xyz="0.4 0 0"/><axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.2"/><dynamics damping="3" friction="1.5"/></joint>
  <joint name="finger_joint2" type="prismatic"><parent link="arm"/><child link="finger2"/><origin xyz="0.4 0 0"/><axis xyz="0 -1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.2"/><dynamics damping="0.3"/><mimic joint="finger_joint1"/></joint>
  <joint name="wrist_joint" type="revolute"><parent link="arm"/><child link="wrist"/><origin xyz="0.3 0 0.05"/><axis xyz="1 0 0"/><limit lower="-3" upper="3" effort="5" velocity="3"/></joint>
  <joint name="tool_joint" type="revolute"><parent link="wrist"/><child link="tool"/><origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="5" velocity="3"/><dynamics friction="0.05"/><mimic joint="wrist_joint" multiplier="-2"/></joint>
</robot>"#;

fn gripper() -> (Analysed, Mechanism) {
    let a = analyse_urdf(GRIPPER);
    let m = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    (a, m)
}

fn index(m: &Mechanism, joint: &str, a: &Analysed) -> usize {
    m.coordinates().iter().position(|c| a.model.joint(c.joint).cad_name == joint).unwrap_or_else(|| panic!("no {joint}"))
}

#[test]
fn urdf_dynamics_reach_the_coordinates_and_the_passive_law_holds() {
    let (a, m) = gripper();
    let (s, f1, f2, w, t) = (
        index(&m, "shoulder", &a),
        index(&m, "finger_joint1", &a),
        index(&m, "finger_joint2", &a),
        index(&m, "wrist_joint", &a),
        index(&m, "tool_joint", &a),
    );
    let l = |i: usize| m.coordinates()[i].losses;
    assert_eq!(l(s), crate::pipeline::ir::Losses { damping: 0.7, friction: 0.25 });
    assert_eq!(l(f1), crate::pipeline::ir::Losses { damping: 3.0, friction: 1.5 });
    assert_eq!(l(f2), crate::pipeline::ir::Losses { damping: 0.3, friction: 0.0 });
    assert!(l(w).is_zero());
    assert_eq!(l(t), crate::pipeline::ir::Losses { damping: 0.0, friction: 0.05 });
    // The law, coordinate by coordinate: d qd + f sign(qd); at rest sign(qdd); stuck 0.
    let n = m.dof();
    let mut qd = vec![0.0; n];
    let mut qdd = vec![0.0; n];
    qd[s] = 0.5;
    qd[f1] = -0.02;
    qd[f2] = 0.0;
    qdd[f2] = 1.0;
    qd[t] = 0.0;
    qdd[t] = -3.0;
    let mut out = vec![f64::NAN; n];
    m.passive_torques(&qd, &qdd, &mut out).expect("passive");
    assert_eq!(out[s], 0.7 * 0.5 + 0.25);
    assert_eq!(out[f1], 3.0 * -0.02 - 1.5);
    assert_eq!(out[f2], 0.0, "no friction: breaking away costs nothing");
    assert_eq!(out[w], 0.0);
    assert_eq!(out[t], -0.05, "at rest the friction opposes the acceleration");
    qdd[t] = 0.0;
    m.passive_torques(&qd, &qdd, &mut out).expect("passive");
    assert_eq!(out[t], 0.0, "stuck and not accelerating: no friction counted");
    // With losses = rigid + passive, exactly.
    let q: Vec<f64> = m.q0().iter().enumerate().map(|(i, q)| q + 0.01 * i as f64).collect();
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut ws = m.workspace();
    let (mut rigid, mut full) = (vec![0.0; n], vec![0.0; n]);
    m.inverse_dynamics(&q, &qd, &qdd, &g, &mut ws, &mut rigid).expect("id");
    m.inverse_dynamics_with_losses(&q, &qd, &qdd, &g, &mut ws, &mut full).expect("id");
    m.passive_torques(&qd, &qdd, &mut out).expect("passive");
    for i in 0..n {
        assert_eq!(full[i], rigid[i] + out[i], "coordinate {i}");
    }
    assert!(m.passive_torques(&qd[1..], &qdd, &mut out).is_err(), "lengths are checked");
}

#[test]
fn negative_dynamics_are_refused_naming_the_attribute() {
    let bad = GRIPPER.replace(r#"damping="0.7""#, r#"damping="-0.7""#);
    let bundle = Bundle::from_files("u", [("robot.urdf".to_string(), bad.into_bytes())]).expect("bundle");
    let Err(e) = pipeline::analyse(&bundle, &Options::default()) else { panic!("refused") };
    let e = e.to_string();
    assert!(e.contains("damping") && e.contains("negative"), "{e}");
}

#[test]
fn mimic_followers_are_dependent_and_load_their_leaders() {
    let (a, m) = gripper();
    let (s, f1, f2, w, t) = (
        index(&m, "shoulder", &a),
        index(&m, "finger_joint1", &a),
        index(&m, "finger_joint2", &a),
        index(&m, "wrist_joint", &a),
        index(&m, "tool_joint", &a),
    );
    assert!(!m.has_loops() && m.has_dependent());
    assert_eq!(m.driven(), {
        let mut d = vec![s, f1, w];
        d.sort();
        d
    });
    assert_eq!(m.coupling_of(f2).map(|c| (c.leader, c.multiplier)), Some((f1, 1.0)));
    assert_eq!(m.coupling_of(t).map(|c| (c.leader, c.multiplier)), Some((w, -2.0)));
    let n = m.dof();
    let mut rng = XorShift::new(7);
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut ws = m.workspace();
    for _ in 0..20 {
        let mut st = ClosedState { q: m.q0(), qd: vec![0.0; n], qdd: vec![0.0; n], cut: m.cut_q0() };
        for &i in &m.driven() {
            st.q[i] = rng.range(-0.5, 0.5) * if i == f1 { 0.05 } else { 1.0 };
            st.qd[i] = rng.range(-1.0, 1.0);
            st.qdd[i] = rng.range(-3.0, 3.0);
        }
        // Followers start anywhere: closing sets them.
        st.q[f2] = 9.0;
        st.qd[t] = 5.0;
        m.close(&mut st).expect("closes");
        for (x, v) in [(&st.q, "q"), (&st.qd, "qd"), (&st.qdd, "qdd")] {
            assert_eq!(x[f2], x[f1], "{v}: finger 2 = finger 1");
            assert_eq!(x[t], -2.0 * x[w], "{v}: tool = -2 wrist");
        }
        // Virtual work: the leader carries its follower's torque times the multiplier.
        let mut tree = vec![0.0; n];
        let driven = m.driven_torques(&st, &g, &mut ws, &mut tree).expect("torques");
        let mut own = vec![0.0; n];
        m.inverse_dynamics_with_losses(&st.q, &st.qd, &st.qdd, &g, &mut ws, &mut own).expect("id");
        let by = |i: usize| driven[m.driven().iter().position(|d| *d == i).expect("driven")];
        let scale = own.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        assert!((by(s) - own[s]).abs() <= 1e-12 * scale, "shoulder");
        assert!((by(f1) - (own[f1] + own[f2])).abs() <= 1e-12 * scale, "finger: {} vs {}", by(f1), own[f1] + own[f2]);
        assert!((by(w) - (own[w] - 2.0 * own[t])).abs() <= 1e-12 * scale, "wrist: {} vs {}", by(w), own[w] - 2.0 * own[t]);
        // Power balance: the drives' power is the tree's.
        let p_tree: f64 = (0..n).map(|i| own[i] * st.qd[i]).sum();
        let p_drv: f64 = m.driven().iter().zip(&driven).map(|(i, tau)| tau * st.qd[*i]).sum();
        assert!((p_tree - p_drv).abs() <= 1e-12 * scale, "{p_tree} vs {p_drv}");
    }
}

#[test]
fn a_mimic_cycle_is_refused_by_name() {
    let cyc = GRIPPER.replace(
        r#"<limit lower="-3" upper="3" effort="5" velocity="3"/></joint>
  <joint name="tool_joint""#,
        r#"<limit lower="-3" upper="3" effort="5" velocity="3"/><mimic joint="tool_joint" multiplier="3"/></joint>
  <joint name="tool_joint""#,
    );
    assert_ne!(cyc, GRIPPER);
    let a = analyse_urdf(&cyc);
    if a.model.couplings.len() < 3 {
        // The front end dropped the cycle (with a warning): nothing left to refuse here.
        return;
    }
    let e = Mechanism::from_validated(&a.model, &a.validated).expect_err("refused");
    assert!(matches!(&e, MechanismError::Coupling { why, .. } if why.contains("cycle")), "{e}");
}

#[test]
fn ik_solves_only_leaders_and_keeps_the_couplings() {
    let (a, m) = gripper();
    let (f1, f2, w, t) =
        (index(&m, "finger_joint1", &a), index(&m, "finger_joint2", &a), index(&m, "wrist_joint", &a), index(&m, "tool_joint", &a));
    let tool = a.model.bodies.iter().position(|b| b.cad_name == "tool").expect("tool");
    let tool_frame = a.model.bodies[tool].cs1;
    let mut rng = XorShift::new(3);
    let mut solved = 0;
    for _ in 0..10 {
        let mut q = m.q0();
        for &i in &m.driven() {
            q[i] = rng.range(-1.0, 1.0) * if i == f1 { 0.02 } else { 1.0 };
        }
        let mut cut = m.cut_q0();
        m.assemble(&mut q, &mut cut).expect("assembles");
        let k = m.forward(&q).expect("fk");
        let target = IkTarget::Pose(m.frame_pose(&k, tool_frame).expect("pose"));
        let r = m.inverse_kinematics(tool_frame, &target, &m.q0(), &IkOptions::default(), &mut rng).expect("ik");
        assert!(r.success, "{r:?}");
        assert_eq!(r.q[t], -2.0 * r.q[w], "the follower is the coupling's");
        assert_eq!(r.q[f2], r.q[f1]);
        let k = m.forward(&r.q).expect("fk");
        let p = m.frame_pose(&k, tool_frame).expect("pose");
        let IkTarget::Pose(goal) = target else { unreachable!() };
        assert!((p.translation.vector - goal.translation.vector).norm() < 1e-6);
        solved += 1;
    }
    assert_eq!(solved, 10);
}

fn finger_spec(values: &[(&str, f64)]) -> MotionSpec {
    MotionSpec {
        name: "grip".into(),
        keyframes: vec![
            Keyframe { target: Target::Joints { values: BTreeMap::new() }, interpolation: Interpolation::Ptp, duration: None, dwell: None },
            Keyframe {
                target: Target::Joints { values: values.iter().map(|(n, v)| (n.to_string(), *v)).collect() },
                interpolation: Interpolation::Quintic,
                duration: Some(1.0),
                dwell: None,
            },
        ],
    }
}

#[test]
fn motions_move_followers_with_their_leaders_and_refuse_contradictions() {
    let (a, m) = gripper();
    let (f1, f2, w, t) =
        (index(&m, "finger_joint1", &a), index(&m, "finger_joint2", &a), index(&m, "wrist_joint", &a), index(&m, "tool_joint", &a));
    let axes = plan::axes(&m, &BTreeMap::new());
    let name = |i: usize| axes[i].name.clone();
    // The leader alone, or with a consistent follower, plans; the follower moves along.
    for values in [vec![(name(f1), 0.03), (name(w), 0.4)], vec![(name(f1), 0.03), (name(f2), 0.03), (name(w), 0.4), (name(t), -0.8)]] {
        let v: Vec<(&str, f64)> = values.iter().map(|(n, x)| (n.as_str(), *x)).collect();
        let p = plan::plan(&m, &axes, &finger_spec(&v)).expect("plans");
        let s = p.closed_samples(&m, 200.0).expect("closes");
        let last = s.t.len() - 1;
        assert!((s.q[f2][last] - 0.03).abs() < 1e-12 && (s.q[t][last] + 0.8).abs() < 1e-12);
        for i in 0..s.t.len() {
            assert_eq!(s.q[f2][i], s.q[f1][i]);
            assert_eq!(s.qd[t][i], -2.0 * s.qd[w][i]);
        }
        // Sizing sees the leaders only: the follower's torque is on the leader.
        let (tau, _) = plan::inverse_dynamics(&m, &s, &Vector3::new(0.0, 0.0, -9.81), 10).expect("id");
        assert!(tau[f2].iter().all(|x| *x == 0.0) && tau[t].iter().all(|x| *x == 0.0));
        assert!(tau[f1].iter().any(|x| x.abs() > 0.0));
    }
    // Panda's bug: finger1 = 0.04 and finger2 = 0 is refused, naming the coupling.
    let bad = finger_spec(&[(&name(f1), 0.04), (&name(f2), 0.0)]);
    let Err(issues) = plan::plan(&m, &axes, &bad) else { panic!("refused") };
    assert_eq!(issues.len(), 1, "{issues:?}");
    assert_eq!(issues[0].field, format!("keyframes[1].values.{}", name(f2)));
    assert!(issues[0].message.contains("mimic coupling") && issues[0].message.contains(&name(f1)), "{}", issues[0].message);
}

#[test]
fn ik_on_a_four_bar_keeps_the_loop_closed() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/fourbar");
    let bundle = crate::test_bundle_of_dir(&dir).expect("bundle");
    let a = pipeline::analyse(&bundle, &Options::default()).expect("analyses");
    let m = Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
    assert!(m.has_loops());
    let driven = m.driven();
    assert_eq!(driven.len(), 1);
    // The crank moved by 0.3 rad: the frame that moves most is the target's.
    let mut q1 = m.q0();
    q1[driven[0]] += 0.3;
    let mut cut = m.cut_q0();
    m.assemble(&mut q1, &mut cut).expect("assembles");
    let (k0, k1) = (m.forward(&m.q0()).expect("fk"), m.forward(&q1).expect("fk"));
    let frame = (0..a.model.frames.len())
        .map(|i| FrameId(i as u32))
        .max_by(|x, y| {
            let d = |f: FrameId| {
                (m.frame_pose(&k1, f).expect("p").translation.vector - m.frame_pose(&k0, f).expect("p").translation.vector).norm()
            };
            d(*x).total_cmp(&d(*y))
        })
        .expect("a frame");
    let goal = m.frame_pose(&k1, frame).expect("pose");
    let mut rng = XorShift::new(1);
    let r =
        m.inverse_kinematics(frame, &IkTarget::Position(goal.translation.vector), &m.q0(), &IkOptions::default(), &mut rng).expect("ik");
    assert!(r.success, "{r:?}");
    assert_eq!(r.mobility, 1, "a four-bar moves a point along one curve");
    let k = m.forward(&r.q).expect("fk");
    assert!((m.frame_pose(&k, frame).expect("p").translation.vector - goal.translation.vector).norm() < 1e-6);
    let mut cut = m.cut_q0();
    let mut qc = r.q.clone();
    m.assemble(&mut qc, &mut cut).expect("assembles");
    let res = m.closure_residual(&r.q, &cut).expect("residual");
    assert!(res.iter().all(|x| x.abs() < 1e-10), "the loop stays closed: {res:?}");
    // The full pose off the coupler curve: not reachable, and the reason is the mobility.
    let off = nalgebra::Isometry3::from_parts((goal.translation.vector + Vector3::new(0.05, 0.05, 0.05)).into(), goal.rotation);
    let opts = IkOptions { restarts: 5, ..IkOptions::default() };
    let r = m.inverse_kinematics(frame, &IkTarget::Pose(off), &m.q0(), &opts, &mut rng).expect("ik runs");
    assert!(!r.success && r.mobility < 6, "{r:?}");
    // Through the planner: a 422-style issue that says why.
    let axes = plan::axes(&m, &BTreeMap::new());
    let node = a.model.frame(frame).node_id.clone();
    let r = off.rotation.to_rotation_matrix();
    let spec = MotionSpec {
        name: "reach".into(),
        keyframes: vec![
            Keyframe { target: Target::Joints { values: BTreeMap::new() }, interpolation: Interpolation::Ptp, duration: None, dwell: None },
            Keyframe {
                target: Target::Tool {
                    frame: node,
                    position: [off.translation.x, off.translation.y, off.translation.z],
                    rotation: Some([0, 1, 2].map(|i| [0, 1, 2].map(|j| r[(i, j)]))),
                },
                interpolation: Interpolation::Ptp,
                duration: None,
                dwell: None,
            },
        ],
    };
    let Err(issues) = plan::plan(&m, &axes, &spec) else { panic!("refused") };
    assert!(issues[0].message.contains("independent direction"), "{}", issues[0].message);
}
