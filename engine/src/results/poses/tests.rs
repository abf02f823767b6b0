//! Poses from a result written here for the generated 6-DoF arm: from frames (float32, as
//! Dymola writes them) and from joint coordinates only, against our own forward kinematics.

use super::*;
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::{self, Options};
use crate::results::write::trajectory;
use crate::testgen as gen;

fn arm() -> Mechanism {
    let bundle = Bundle::from_files("gen", [("arm.xml".to_string(), gen::serial_arm_xml(6).into_bytes())]).expect("bundle");
    let a = pipeline::analyse(&bundle, &Options::default()).expect("analyses");
    Mechanism::from_validated(&a.model, &a.validated).expect("mechanism")
}

/// Joint values at time `t`: every joint moving its own way.
fn q_at(m: &Mechanism, t: f64) -> Vec<f64> {
    m.coordinates().iter().enumerate().map(|(i, c)| c.q0 + 0.5 * ((1.0 + i as f64) * t).sin()).collect()
}

/// A result of the arm: joint angles, and (with `frames`) every body's frame_a from our FK.
fn result(m: &Mechanism, frames: bool) -> (Vec<f64>, Vec<u8>) {
    let time: Vec<f64> = (0..=50).map(|i| f64::from(i) * 0.02).collect();
    let mut series: Vec<(String, Vec<f64>)> = Vec::new();
    for (i, c) in m.coordinates().iter().enumerate() {
        series.push((format!("{}.phi", c.name), time.iter().map(|t| q_at(m, *t)[i]).collect()));
    }
    if frames {
        for (b, name) in m.body_names().iter().enumerate() {
            let poses: Vec<Isometry3<f64>> =
                time.iter().map(|t| m.body_pose(&m.forward(&q_at(m, *t)).expect("fk"), BodyId(b as u32)).expect("pose")).collect();
            for k in 0..3 {
                series.push((format!("{name}.frame_a.r_0[{}]", k + 1), poses.iter().map(|p| p.translation.vector[k]).collect()));
            }
            for a in 0..3 {
                for c in 0..3 {
                    // R.T maps world to frame: the transpose of the frame's rotation.
                    let v = poses.iter().map(|p| p.rotation.to_rotation_matrix()[(c, a)]).collect();
                    series.push((format!("{name}.frame_a.R.T[{}, {}]", a + 1, c + 1), v));
                }
            }
        }
    }
    (time.clone(), trajectory(&time, &series, true))
}

#[test]
fn poses_from_frames_agree_with_our_kinematics() {
    let m = arm();
    let (time, bytes) = result(&m, true);
    let t = Trajectory::read(&bytes, "arm.mat").expect("reads");
    let p = extract(&t, &m);
    assert_eq!(p.summary.from_frames.len(), m.body_names().len());
    assert!(p.summary.from_joints.is_empty() && p.summary.missing.is_empty());
    assert_eq!(p.summary.joints_found.len(), 6);
    let checks = &p.summary.checks;
    assert!(checks.orthonormality.expect("checked") < 1e-6, "{checks:?}");
    assert!(checks.kinematics.expect("checked") < 1e-5, "float32 positions agree with FK: {checks:?}");
    assert_eq!(p.t.len(), time.len());
    // The stream: header, then the last body's pose at the last step is its FK pose.
    let s = stream(&p);
    assert_eq!(&s[..4], b"C2MP");
    let nb = p.summary.bodies.len();
    assert_eq!(s.len(), 16 + time.len() * (4 + 28 * nb));
    let last = m.body_pose(&m.forward(&q_at(&m, time[time.len() - 1])).expect("fk"), BodyId((nb - 1) as u32)).expect("pose");
    let at = p.data.len() - 7;
    let pos = Vector3::new(p.data[at].into(), p.data[at + 1].into(), p.data[at + 2].into());
    assert!((pos - last.translation.vector).norm() < 1e-5);
    let qn = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
        p.data[at + 6].into(),
        p.data[at + 3].into(),
        p.data[at + 4].into(),
        p.data[at + 5].into(),
    ));
    assert!(qn.angle_to(&last.rotation) < 1e-5, "rotation off by {}", qn.angle_to(&last.rotation));
}

#[test]
fn poses_from_joint_coordinates_only() {
    let m = arm();
    let (time, bytes) = result(&m, false);
    let t = Trajectory::read(&bytes, "arm.mat").expect("reads");
    let p = extract(&t, &m);
    assert!(p.summary.from_frames.is_empty());
    assert_eq!(p.summary.from_joints.len(), m.body_names().len());
    assert_eq!(p.summary.checks, PoseChecks::default());
    let i = time.len() / 2;
    let nb = p.summary.bodies.len();
    let pose = m.body_pose(&m.forward(&q_at(&m, time[i])).expect("fk"), BodyId(2)).expect("pose");
    let at = (i * nb + 2) * 7;
    let pos = Vector3::new(p.data[at].into(), p.data[at + 1].into(), p.data[at + 2].into());
    assert!((pos - pose.translation.vector).norm() < 1e-5);
}

#[test]
fn a_result_of_another_model_has_no_poses() {
    let m = arm();
    let bytes = trajectory(&[0.0, 1.0], &[("other.body.frame_a.r_0[1]".into(), vec![0.0, 1.0])], false);
    let t = Trajectory::read(&bytes, "other.mat").expect("reads");
    let p = extract(&t, &m);
    assert!(p.summary.bodies.is_empty() && p.summary.joints_found.is_empty());
    assert_eq!(p.summary.missing.len(), m.body_names().len());
}
