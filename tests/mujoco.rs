//! Cross-check of `mechanism`'s inverse dynamics (RNEA) against MuJoCo's `mj_inverse` on the MJCF
//! the pipeline writes (`<Pkg>/<Pkg>.mjcf.xml`), for generated trees and arms and the real tree
//! fixtures. Random states (q, qd, qdd) by joint name; agreement required per coordinate:
//! `|tau - tau_mujoco| <= 1e-9 * |tau_mujoco| + 1e-9 * max_k |tau_mujoco_k| + 1e-12`.
//! The second term is the absolute floor: torques that nearly cancel (a joint carrying little
//! of a large load) keep only the digits of the sample's largest torque.
//! Body poses (MuJoCo's `xpos`/`xquat` against our FK of each CS1 frame) must agree to 1e-12 m
//! and 1e-12 rad: MuJoCo's `qpos` is the Modelica coordinate.
//! Skips with a NOTICE when mujoco cannot be imported, unless CAD2MO_REQUIRE_TOOLS=1.

use std::path::Path;
use std::process::Command;

use cad2mo_engine::mechanism::{Mechanism, XorShift};
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options};
use cad2mo_tests::common::{files_with_ext, fixtures_dir, python_check, tools_required, use_package_names};
use nalgebra::Vector3;

#[path = "../engine/benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

const REL: f64 = 1e-9;

/// The bundle's mechanism (tree only: `None` for loops, free bodies, sphericals) with the
/// package's names, and the package's MJCF text.
fn prepare(name: &str, xml: &str) -> Option<(Mechanism, String)> {
    let bundle = Bundle::from_files("x", [(name.to_string(), xml.as_bytes().to_vec())]).ok()?;
    let opts = Options { write_shapes: false, ..Options::default() };
    let a = pipeline::analyse(&bundle, &opts).ok()?;
    let mut m = Mechanism::from_validated(&a.model, &a.validated).ok()?;
    if m.has_loops() || m.dof() == 0 {
        return None;
    }
    let out = pipeline::convert(&bundle, &opts).ok()?;
    let (_, mjcf) = out.files.iter().find(|(p, _)| p.ends_with(".mjcf.xml"))?;
    use_package_names(&mut m, &a, &out);
    Some((m, String::from_utf8(mjcf.bytes().into_owned()).ok()?))
}

/// Runs the comparison; `Err` with the worst mismatch. `None` when mujoco is unavailable.
fn compare(label: &str, m: &Mechanism, mjcf: &str, samples: usize, seed: u64) -> Option<Result<f64, String>> {
    compare_with(label, m, mjcf, samples, seed, false)
}

/// [`compare`]; with `losses`, ours is [`Mechanism::inverse_dynamics_with_losses`] and MuJoCo keeps
/// the MJCF's joint `damping` (its `qfrc_inverse` then includes `damping * qvel`), while the
/// Coulomb friction is added to MuJoCo's torque here by our own formula,
/// `frictionloss * sign(qvel)` with the MJCF's `frictionloss` (MuJoCo's frictionloss is a soft
/// constraint, not this law; it is disabled in the script). Samples have random nonzero speeds.
fn compare_with(label: &str, m: &Mechanism, mjcf: &str, samples: usize, seed: u64, losses: bool) -> Option<Result<f64, String>> {
    let dir = tempfile::tempdir().expect("tempdir");
    let model_path = dir.path().join("model.mjcf.xml");
    std::fs::write(&model_path, mjcf).expect("write mjcf");
    // The MJCF's own gravity (-y for SimMechanics XML, -z for URDF).
    let g = mjcf
        .split("<option gravity=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .map(|t| t.split_whitespace().map(|x| x.parse::<f64>().expect("gravity")).collect::<Vec<_>>())
        .map(|v| Vector3::new(v[0], v[1], v[2]))
        .expect("the MJCF states its gravity");
    let mut rng = XorShift::new(seed);
    let mut ws = m.workspace();
    let n = m.dof();
    let mut ours = Vec::new();
    let mut qs = Vec::new();
    let mut qds = Vec::new();
    let mut spec = Vec::new();
    for _ in 0..samples {
        let q: Vec<f64> = m.q0().iter().map(|q| q + rng.range(-1.0, 1.0)).collect();
        let qd: Vec<f64> = (0..n).map(|_| rng.range(-2.0, 2.0)).collect();
        let qdd: Vec<f64> = (0..n).map(|_| rng.range(-5.0, 5.0)).collect();
        let mut tau = vec![0.0; n];
        if losses {
            m.inverse_dynamics_with_losses(&q, &qd, &qdd, &g, &mut ws, &mut tau).expect("rnea");
        } else {
            m.inverse_dynamics(&q, &qd, &qdd, &g, &mut ws, &mut tau).expect("rnea");
        }
        let by_name = |v: &[f64]| -> serde_json::Map<String, serde_json::Value> {
            m.coordinates().iter().zip(v).map(|(c, x)| (c.name.clone(), serde_json::json!(x))).collect()
        };
        spec.push(serde_json::json!({"q": by_name(&q), "qd": by_name(&qd), "qdd": by_name(&qdd)}));
        ours.push(tau);
        qs.push(q);
        qds.push(qd);
    }
    let spec = serde_json::json!({"model": model_path, "samples": spec, "keep_damping": losses});
    let result = python_check(dir.path(), "mujoco_check.py", &spec, label, "MuJoCo cross-check (python3 -m pip install mujoco)")?;
    assert_eq!(result["nv"].as_u64(), Some(n as u64), "{label}: MuJoCo has a different number of dofs");
    let mut worst_rel = 0.0f64;
    for (s, q) in qs.iter().enumerate() {
        let k = m.forward(q).expect("fk");
        for (b, name) in m.body_names().iter().enumerate() {
            let (Some(p), Some(r)) = (result["xpos"][s][name].as_array(), result["xquat"][s][name].as_array()) else {
                return Some(Err(format!("{label}: body {name} not in the MJCF model")));
            };
            let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
            let pose = m.body_pose(&k, cad2mo_engine::pipeline::ir::BodyId(b as u32)).expect("pose");
            let dp = (pose.translation.vector - Vector3::new(f(&p[0]), f(&p[1]), f(&p[2]))).norm();
            let theirs = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(f(&r[0]), f(&r[1]), f(&r[2]), f(&r[3])));
            let dr = pose.rotation.angle_to(&theirs);
            if !(dp < 1e-12 && dr < 1e-12) {
                return Some(Err(format!("{label}: sample {s}, body {name}: MuJoCo pose off by {dp:e} m, {dr:e} rad")));
            }
        }
    }
    for (s, tau) in ours.iter().enumerate() {
        let friction = |c: &cad2mo_engine::mechanism::Coordinate| {
            if losses {
                result["frictionloss"][&c.name].as_f64().unwrap_or(f64::NAN)
            } else {
                0.0
            }
        };
        let theirs: Vec<f64> = m
            .coordinates()
            .iter()
            .zip(&qds[s])
            .map(|(c, v)| result["tau"][s][&c.name].as_f64().unwrap_or(f64::NAN) + friction(c) * v.signum())
            .collect();
        let scale = theirs.iter().fold(0.0f64, |a, t| a.max(t.abs()));
        for (k, (a, b)) in tau.iter().zip(&theirs).enumerate() {
            let err = (a - b).abs();
            let allowed = REL * b.abs() + REL * scale + 1e-12;
            worst_rel = worst_rel.max(err / (scale + 1e-12));
            if err.is_nan() || err > allowed {
                return Some(Err(format!(
                    "{label}: sample {s}, {} ({:?}): ours {a:.15e}, MuJoCo {b:.15e}, error {err:.3e} > {allowed:.3e}",
                    m.coordinates()[k].name,
                    m.coordinates()[k].kind
                )));
            }
        }
    }
    println!("{label}: {n} coordinates, {samples} samples, MuJoCo {}: body poses within 1e-12; worst torque error {worst_rel:.3e} of the sample's largest torque", result["mujoco"]);
    Some(Ok(worst_rel))
}

#[test]
fn rnea_agrees_with_mujoco_on_generated_and_real_trees() {
    let mut models: Vec<(String, String)> =
        vec![("arm6".into(), gen::serial_arm_xml(6)), ("arm7".into(), gen::serial_arm_xml(7)), ("tree50".into(), gen::tree_xml(50))];
    if let Some(fx) = fixtures_dir("rnea_agrees_with_mujoco") {
        for xml in files_with_ext(&fx.join("xml"), &[".xml"]) {
            let text = std::fs::read_to_string(&xml).expect("read");
            if text.contains("<PhysicalModelingXMLFile") {
                models.push((xml.strip_prefix(&fx).unwrap_or(&xml).display().to_string(), text));
            }
        }
    }
    let mut compared = 0;
    for (label, xml) in &models {
        let Some((m, mjcf)) =
            prepare(&format!("{}.xml", Path::new(label).file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default()), xml)
        else {
            println!("{label}: not a tree mechanism; skipped");
            continue;
        };
        match compare(label, &m, &mjcf, 20, 11) {
            None => return,
            Some(Ok(_)) => compared += 1,
            Some(Err(e)) => panic!("{e}"),
        }
    }
    assert!(compared >= 3, "only {compared} models compared");
}

/// A URDF with a virtual link of 1e-7 kg and a singular inertia (MuJoCo: "inertia must have
/// positive eigenvalues") and a `mimic`: the MJCF loads, the floor is stated on the body, and
/// the coupling is a joint equality `q_f = 2 q_l` that MuJoCo enforces.
#[test]
fn mimic_and_degenerate_virtual_links_load_in_mujoco() {
    let urdf = r#"<robot name="virt">
  <link name="world"/>
  <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="virtual"><inertial><mass value="1e-7"/><inertia ixx="1e-9" ixy="1e-9" ixz="0" iyy="1e-9" iyz="0" izz="1e-9"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0.2 0 0"/><mass value="1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="lead" type="revolute"><parent link="base"/><child link="virtual"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="follow" type="revolute"><parent link="virtual"/><child link="arm"/><origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/><mimic joint="lead" multiplier="2"/></joint>
</robot>"#;
    let bundle = Bundle::from_files("x", [("virt.urdf".to_string(), urdf.as_bytes().to_vec())]).expect("bundle");
    let out = pipeline::convert(&bundle, &Options { write_shapes: false, ..Options::default() }).expect("convert");
    let (_, mjcf) = out.files.iter().find(|(p, _)| p.ends_with(".mjcf.xml")).expect("mjcf");
    let mjcf = String::from_utf8(mjcf.bytes().into_owned()).expect("utf-8");
    assert!(mjcf.contains("boundmass=\"1e-9\" boundinertia=\"1e-14\" balanceinertia=\"true\""), "{mjcf}");
    assert!(mjcf.contains("smallest principal moment"), "the floor is stated on the body: {mjcf}");
    assert!(mjcf.contains("<joint name=\"follow_mimic\" joint1=\"follow\" joint2=\"lead\" polycoef=\"0.0 2.0 0 0 0\"/>"), "{mjcf}");
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("virt.mjcf.xml");
    std::fs::write(&path, &mjcf).expect("write");
    // Drive the leader to 0.3 rad by its own position and let the equality pull the follower.
    let script = r#"
import sys
try:
    import mujoco
except Exception as e:
    print("mujoco not importable:", e); sys.exit(3)
m = mujoco.MjModel.from_xml_path(sys.argv[1])
d = mujoco.MjData(m)
lead = m.joint("lead").qposadr[0]; follow = m.joint("follow").qposadr[0]
m.opt.gravity[:] = 0
for _ in range(4000):
    d.qpos[lead] = 0.3; d.qvel[:] = 0
    mujoco.mj_step(m, d)
print(m.neq, d.qpos[lead], d.qpos[follow])
"#;
    let Some(text) = run_mujoco_script(script, &path, "load check", "model") else { return };
    let v: Vec<f64> = text.split_whitespace().map(|t| t.parse().expect("number")).collect();
    assert_eq!(v[0], 1.0, "one equality: {text}");
    assert!((v[2] - 2.0 * v[1]).abs() < 1e-3, "the follower tracks 2 x the leader: {text}");
    println!("MuJoCo: leader {:.6} rad, follower {:.6} rad (mimic 2x)", v[1], v[2]);
}

/// An iiwa-like 7-axis arm as URDF (axes z, y, z, y, z, y, z; masses and inertias of the
/// iiwa's order of magnitude, principal moments within MuJoCo's `A + B >= C`) with `<dynamics damping friction>` on every joint. The values
/// are the test's own, not KUKA's.
fn iiwa_like_urdf() -> String {
    let mut s = String::from("<robot name=\"iiwa_like\">\n  <link name=\"world\"/>\n");
    let masses = [5.76, 6.35, 3.5, 3.5, 3.5, 1.8, 1.2, 0.3];
    for (i, m) in masses.iter().enumerate() {
        s.push_str(&format!(
            "  <link name=\"link_{i}\"><inertial><origin xyz=\"0.0{i} -0.03 0.12\" rpy=\"0.{i} 0.2 -0.1\"/><mass value=\"{m}\"/><inertia ixx=\"0.02{i}\" ixy=\"0.001\" ixz=\"-0.0005\" iyy=\"0.03\" iyz=\"0.0007\" izz=\"0.015{i}\"/></inertial></link>\n"
        ));
    }
    s.push_str("  <joint name=\"base\" type=\"fixed\"><parent link=\"world\"/><child link=\"link_0\"/></joint>\n");
    for i in 1..8 {
        let axis = if i % 2 == 1 { "0 0 1" } else { "0 1 0" };
        let z = if i == 1 { 0.1575 } else { 0.2 };
        s.push_str(&format!(
            "  <joint name=\"joint_{i}\" type=\"revolute\"><parent link=\"link_{}\"/><child link=\"link_{i}\"/><origin xyz=\"0 0 {z}\" rpy=\"0 0 0.{i}\"/><axis xyz=\"{axis}\"/><limit lower=\"-2.9\" upper=\"2.9\" effort=\"300\" velocity=\"10\"/><dynamics damping=\"{}\" friction=\"{}\"/></joint>\n",
            i - 1,
            0.5 + 0.1 * i as f64,
            0.2 * i as f64
        ));
    }
    s.push_str("</robot>\n");
    s
}

/// Inverse dynamics with joint damping and Coulomb friction (`Mechanism::inverse_dynamics_with_losses`)
/// against MuJoCo's `mj_inverse` with the MJCF's `damping` (from the URDF's own `<dynamics>`)
/// and our friction formula on MuJoCo's side: the iiwa-like arm and the Panda fixture (its
/// fingers' mimic equality disabled: the tree's own dynamics).
#[test]
fn rnea_with_urdf_dynamics_agrees_with_mujoco() {
    let mut models = vec![("iiwa_like.urdf".to_string(), iiwa_like_urdf())];
    if let Some(fx) = fixtures_dir("rnea_with_urdf_dynamics_agrees_with_mujoco") {
        let panda = fx.join("urdf/Gepetto+example-robot-data/39aa9437/robots/panda_description/urdf/panda.urdf");
        models.push(("panda.urdf".to_string(), std::fs::read_to_string(&panda).expect("panda.urdf")));
    }
    for (label, text) in &models {
        let (m, mjcf) = prepare(label, text).unwrap_or_else(|| panic!("{label}: prepared"));
        assert!(m.has_losses(), "{label}: the URDF's <dynamics> reach the mechanism");
        assert!(mjcf.contains(" damping=\""), "{label}: the MJCF keeps the damping");
        if label.starts_with("iiwa") {
            assert!(mjcf.contains(" frictionloss=\""), "{label}: the MJCF keeps the friction");
        }
        match compare_with(label, &m, &mjcf, 30, 5, true) {
            None => return,
            Some(Ok(_)) => {}
            Some(Err(e)) => panic!("{e}"),
        }
    }
}

/// The losses reach every back end: `Mechanics.mo` (a `LinearSpeedDependentTorque` / `Force`,
/// `-d * speed`, and a `BearingFriction` / `SupportFriction` on the drive flange, classes and parameters checked by
/// msl-check), the URDF (`<dynamics>`) and the MJCF (`damping`, `frictionloss`).
#[test]
fn losses_reach_modelica_urdf_and_mjcf() {
    let urdf = r#"<robot name="slide">
  <link name="world"/>
  <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0.2 0 0"/><mass value="1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="carriage"><inertial><mass value="0.5"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="turn" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="10" velocity="2"/><dynamics damping="0.6" friction="0.2"/></joint>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="carriage"/><origin xyz="0.3 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.2" effort="100" velocity="1"/><dynamics damping="12.5" friction="3"/></joint>
</robot>"#;
    let bundle = Bundle::from_files("x", [("slide.urdf".to_string(), urdf.as_bytes().to_vec())]).expect("bundle");
    let out = pipeline::convert(&bundle, &Options { write_shapes: false, ..Options::default() }).expect("convert");
    let text = |suffix: &str| {
        let (_, b) = out.files.iter().find(|(p, _)| p.ends_with(suffix)).unwrap_or_else(|| panic!("no {suffix}"));
        String::from_utf8(b.bytes().into_owned()).expect("utf-8")
    };
    let mo = text("/Mechanics.mo");
    for want in [
        "Modelica.Mechanics.Rotational.Sources.LinearSpeedDependentTorque turn_damper(tau_nominal=-0.6, w_nominal=1, TorqueDirection=false)",
        "Modelica.Mechanics.Rotational.Components.BearingFriction turn_friction(tau_pos=[0, 0.2], peak=1)",
        "Modelica.Mechanics.Translational.Sources.LinearSpeedDependentForce slide_damper(f_nominal=-12.5, v_nominal=1, ForceDirection=false)",
        "Modelica.Mechanics.Translational.Components.SupportFriction slide_friction(f_pos=[0, 3.0], peak=1)",
        "connect(turn_damper.flange, turn.drive)",
        "connect(turn.drive, turn_friction.flange_a)",
        "connect(slide_damper.flange, slide.drive)",
        "connect(slide.drive, slide_friction.flange_a)",
    ] {
        assert!(mo.contains(want), "Mechanics.mo lacks {want}:\n{mo}");
    }
    let robot = text("/slide.urdf");
    assert!(
        robot.contains(r#"<dynamics damping="0.6" friction="0.2"/>"#) && robot.contains(r#"<dynamics damping="12.5" friction="3.0"/>"#),
        "{robot}"
    );
    let mjcf = text(".mjcf.xml");
    assert!(mjcf.contains(r#"damping="0.6" frictionloss="0.2""#) && mjcf.contains(r#"damping="12.5" frictionloss="3.0""#), "{mjcf}");
    let dir = tempfile::tempdir().expect("tempdir");
    cad2mo_tests::common::write_output(&out, dir.path());
    if let Some(r) = cad2mo_tests::common::msl_check(dir.path()) {
        assert!(r.is_ok(), "msl-check: {}", r.unwrap_or_else(|e| e));
    }
}

/// The scene in the package (issue 29): a static table, a free pallet above it, a conveyor
/// moving at constant velocity, a box following a pose table and a tool attached to the arm.
/// Mechatronics.mo holds them (msl-check and rumoca clean); the MJCF loads in MuJoCo with the
/// scene's bodies, and the pallet dropped from 2.5 cm comes to rest on the table.
#[test]
fn scene_is_in_the_package_and_a_free_pallet_rests_on_the_table_in_mujoco() {
    let urdf = r#"<robot name="cell">
  <link name="world"/>
  <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry><box size="0.2 0.2 0.1"/></geometry></visual></link>
  <link name="arm"><inertial><origin xyz="0.2 0 0"/><mass value="1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><origin xyz="0.2 0 0"/><geometry><box size="0.4 0.05 0.05"/></geometry></visual></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="J1" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>"#;
    let scene: cad2mo_engine::scene::SceneSpec = serde_json::from_value(serde_json::json!({"objects": [
        {"name": "table", "shape": {"kind": "box", "size": [0.6, 0.4, 0.04]}, "position": [1.0, 0, 0.4], "color": [0.6, 0.4, 0.2]},
        {"name": "pallet", "shape": {"kind": "box", "size": [0.2, 0.2, 0.05]}, "position": [1.0, 0, 0.47], "kind": "free", "mass": 1.5,
         "rotation": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]},
        {"name": "conveyor", "shape": {"kind": "box", "size": [0.3, 0.3, 0.1]}, "position": [0, 1.5, 0.05], "kind": "moving",
         "motion": {"velocity": [0.1, 0, 0]}},
        {"name": "gate", "shape": {"kind": "cylinder", "radius": 0.05, "length": 0.5}, "position": [0, -1, 0.25], "kind": "moving",
         "motion": {"poses": [{"time": 0, "position": [0, -1, 0.25]},
                              {"time": 2, "position": [0, -1, 0.5], "rotation": [[1, 0, 0], [0, 0, -1], [0, 1, 0]]}]}},
        {"name": "tool", "shape": {"kind": "capsule", "radius": 0.01, "length": 0.1}, "position": [0.4, 0, 0], "attached_to": "arm"},
        {"name": "floor", "shape": {"kind": "plane"}, "position": [0, 0, 0]}
    ]}))
    .expect("scene");
    let bundle = Bundle::from_files("x", [("cell.urdf".to_string(), urdf.as_bytes().to_vec())]).expect("bundle");
    let opts = Options { write_shapes: false, scene, ..Options::default() };
    let out = pipeline::convert(&bundle, &opts).expect("convert");
    let file = |suffix: &str| {
        let (_, b) = out.files.iter().find(|(p, _)| p.ends_with(suffix)).unwrap_or_else(|| panic!("{suffix}"));
        String::from_utf8(b.bytes().into_owned()).expect("utf-8")
    };
    let mech = file("/Mechatronics.mo");
    for needle in [
        "Modelica.Mechanics.MultiBody.Parts.Body scene_pallet(m=1.5,",
        "scene_table_shape(shapeType=\"box\"",
        "scene_conveyor_shape(",
        "{0.0, 1.5, 0.05} + {0.1, 0.0, 0.0}*time",
        "CombiTimeTable scene_gate_path(",
        "FixedTranslation scene_tool_frame(r={0.4, 0.0, 0.0}",
        "connect(arm.frame_a, scene_tool_frame.frame_a);",
        "connect(collisionForce_scene_pallet.frame_b, scene_pallet.frame_a);",
        "connect(collisionForce_scene_tool.frame_b, scene_tool_frame.frame_b);",
        "parameter Boolean collisions = true",
    ] {
        assert!(mech.contains(needle), "Mechatronics.mo lacks {needle}:\n{mech}");
    }
    assert!(!mech.contains("collisionForce_scene_table"), "a static object gets no force");
    let contact = file("/Resources/Collision/contact.txt");
    assert!(contact.contains("\nbodies 8\n") && contact.contains(" scene_pallet\n") && contact.contains(" scene_floor\n"), "{contact}");
    // The package as a folder: msl-check and rumoca.
    let dir = tempfile::tempdir().expect("tempdir");
    for (p, b) in &out.files {
        let path = dir.path().join(p);
        std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
        std::fs::write(&path, b.bytes()).expect("write");
    }
    let pkg = dir.path().join(&out.report.package_name);
    match cad2mo_tests::common::msl_check(&pkg) {
        Some(r) => {
            let text = r.unwrap_or_else(|e| panic!("msl-check: {e}"));
            assert!(text.contains(" 0 problems"), "msl-check: {text}");
        }
        None => assert!(!tools_required(), "msl-check is required"),
    }
    if let Some(errors) = cad2mo_tests::common::modelica_syntax_errors(&pkg) {
        assert!(errors.is_empty(), "rumoca parse errors:\n{}", errors.join("\n"));
    }
    // MuJoCo: the scene's bodies load; the pallet falls 2.5 cm onto the table and stays there.
    let mjcf = file(".mjcf.xml");
    assert!(mjcf.contains("<geom name=\"table\" type=\"box\" size=\"0.3 0.2 0.02\""), "{mjcf}");
    let path = dir.path().join("cell.mjcf.xml");
    std::fs::write(&path, &mjcf).expect("write");
    let script = r#"
import sys
try:
    import mujoco
except Exception as e:
    print("mujoco not importable:", e); sys.exit(3)
m = mujoco.MjModel.from_xml_path(sys.argv[1])
d = mujoco.MjData(m)
names = [m.body(i).name for i in range(m.nbody)]
geoms = [m.geom(i).name for i in range(m.ngeom)]
p = m.body("pallet").id
assert m.body("conveyor").mocapid[0] >= 0, "conveyor is a mocap body"
assert m.body_mass[p] == 1.5, m.body_mass[p]
mujoco.mj_forward(m, d)
tool = d.geom_xpos[m.geom("tool").id].copy()
while d.time < 1.5:
    mujoco.mj_step(m, d)
print(" ".join(names)); print(" ".join(g for g in geoms if g))
print(d.xpos[p][0], d.xpos[p][1], d.xpos[p][2], abs(d.qvel[m.joint("pallet_free").dofadr[0]:][:6]).max(), tool[0], tool[2])
"#;
    let Some(text) = run_mujoco_script(script, &path, "scene check", "scene") else { return };
    let lines: Vec<&str> = text.lines().collect();
    for b in ["pallet", "conveyor", "gate", "base", "arm"] {
        assert!(lines[0].split_whitespace().any(|n| n == b), "body {b} in MuJoCo: {text}");
    }
    for g in ["table", "floor", "tool"] {
        assert!(lines[1].split_whitespace().any(|n| n == g), "geom {g} in MuJoCo: {text}");
    }
    let v: Vec<f64> = lines[2].split_whitespace().map(|t| t.parse().expect("number")).collect();
    // Table top at 0.42 m; the pallet's centre rests 0.025 m above it.
    println!("pallet after 1.5 s: ({:.5}, {:.5}, {:.5}) m, largest speed {:.2e}", v[0], v[1], v[2], v[3]);
    assert!((v[2] - 0.445).abs() < 2e-3, "pallet at rest on the table: z = {}", v[2]);
    assert!((v[0] - 1.0).abs() < 1e-3 && v[1].abs() < 1e-3, "pallet stays over the table: {v:?}");
    assert!(v[3] < 1e-2, "pallet at rest: {}", v[3]);
    // The tool stands 0.4 m along the arm, which is 0.3 m above the base.
    assert!((v[4] - 0.4).abs() < 1e-9 && (v[5] - 0.3).abs() < 1e-9, "tool on the arm: {v:?}");
}

/// Runs a Python `script` (which exits 3 when `mujoco` cannot be imported) on the file `path`
/// and returns its standard output; `None` (with a notice) when python3 or mujoco is missing and
/// the tools are not required. `check` names the check for the notice, `what` the file for the
/// failure message.
fn run_mujoco_script(script: &str, path: &Path, check: &str, what: &str) -> Option<String> {
    let run = match Command::new("python3").arg("-c").arg(script).arg(path).output() {
        Ok(r) => r,
        Err(e) => {
            assert!(!tools_required(), "python3 not runnable: {e}");
            return None;
        }
    };
    if run.status.code() == Some(3) {
        assert!(!tools_required(), "{}", String::from_utf8_lossy(&run.stdout));
        println!("NOTICE: mujoco not importable; {check} skipped");
        return None;
    }
    let text = String::from_utf8_lossy(&run.stdout).to_string();
    assert!(run.status.success(), "MuJoCo refused the {what}: {text}{}", String::from_utf8_lossy(&run.stderr));
    Some(text)
}
