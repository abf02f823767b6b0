//! Body poses of a converted model from a result file.
//!
//! A body's pose is that of its Modelica `frame_a` (the CAD `CS1`, the frame its shape is in):
//! from the result's `<body>.frame_a.r_0[i]` and `<body>.frame_a.R.T[i,j]` when the file has
//! them (MSL 4.0: a body-fixed point `p` is at `r_0 + transpose(R.T)·p`; rotations written in
//! float32 are re-orthonormalised), otherwise from our forward kinematics of the file's joint
//! coordinates (`<joint>.phi`, `<joint>.s`; output filters often keep only those). Self-checks:
//! the orthonormality residual of the stored rotations, the rigidity of bodies whose `frame_b`
//! is in the file too, and, where both are available, the distance between the file's poses and
//! our forward kinematics of the file's joint values.

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use serde::Serialize;

use super::mat::Trajectory;
use crate::mechanism::{CoordKind, Mechanism};
use crate::pipeline::ir::BodyId;

/// What the poses of a result are made of, for the upload's report.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PoseSummary {
    /// Bodies in the order of the pose stream.
    pub bodies: Vec<String>,
    pub from_frames: Vec<String>,
    pub from_joints: Vec<String>,
    pub missing: Vec<String>,
    /// Joint coordinates found in the file.
    pub joints_found: Vec<String>,
    pub checks: PoseChecks,
}

/// Self-checks of the poses (each `None` when nothing could be checked).
#[derive(Clone, Debug, Default, PartialEq, Serialize, serde::Deserialize)]
pub struct PoseChecks {
    /// Largest `|R·Rᵀ - I|` of the stored rotations.
    pub orthonormality: Option<f64>,
    /// Largest change (m) of a body's `frame_b` seen from its `frame_a` over the run.
    pub rigidity: Option<f64>,
    /// Largest distance (m) between the file's `frame_a` origins and our forward kinematics of the
    /// file's joint values.
    pub kinematics: Option<f64>,
}

/// Poses per instant: `data[(step * bodies + b) * 7 ..]` = x, y, z, qx, qy, qz, qw.
#[derive(Clone, Debug, PartialEq)]
pub struct Poses {
    pub summary: PoseSummary,
    pub t: Vec<f64>,
    pub data: Vec<f32>,
}

/// The variable indices of a frame's `r_0` and `R.T`.
type FrameVars = ([usize; 3], [[usize; 3]; 3]);

/// The variable indices of a frame's `r_0` and `R.T`, when all twelve are in the file.
fn frame_vars(t: &Trajectory, frame: &str) -> Option<FrameVars> {
    let r = [1, 2, 3].map(|i| t.find(&format!("{frame}.r_0[{i}]")));
    let m = [1, 2, 3].map(|i| [1, 2, 3].map(|j| t.find(&format!("{frame}.R.T[{i},{j}]"))));
    let r = [r[0]?, r[1]?, r[2]?];
    let row = |k: usize| -> Option<[usize; 3]> { Some([m[k][0]?, m[k][1]?, m[k][2]?]) };
    Some((r, [row(0)?, row(1)?, row(2)?]))
}

fn frame_at(t: &Trajectory, v: &FrameVars, i: usize) -> (Vector3<f64>, Matrix3<f64>) {
    let r = Vector3::new(t.value(v.0[0], i), t.value(v.0[1], i), t.value(v.0[2], i));
    let m = Matrix3::from_fn(|a, b| t.value(v.1[a][b], i));
    (r, m)
}

/// The pose (frame -> world) of a frame given by `r_0` and `R.T`, and its orthonormality residual.
pub(crate) fn pose_of(r: Vector3<f64>, t: Matrix3<f64>) -> (Isometry3<f64>, f64) {
    let residual = (t * t.transpose() - Matrix3::identity()).amax();
    // Float32 rotations are orthonormal to ~1e-7: the quaternion of the matrix (Shepperd's
    // method), normalised, is the nearest rotation to that order, without an iteration.
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(t.transpose()));
    let q = UnitQuaternion::new_normalize(q.into_inner());
    (Isometry3::from_parts(Translation3::from(r), q), residual)
}

/// Poses of every body of `mech` (named as in its package) at every instant of `t`.
pub fn extract(t: &Trajectory, mech: &Mechanism) -> Poses {
    let n = t.len();
    let names = mech.body_names();
    let coords = mech.coordinates();
    let coord_vars: Vec<Option<usize>> = coords
        .iter()
        .map(|c| {
            let field = if c.kind == CoordKind::Prismatic { "s" } else { "phi" };
            t.find(&format!("{}.{field}", c.name))
        })
        .collect();
    let all_coords = coord_vars.iter().all(Option::is_some);
    let mut summary = PoseSummary {
        joints_found: coords.iter().zip(&coord_vars).filter(|(_, v)| v.is_some()).map(|(c, _)| c.name.clone()).collect(),
        ..PoseSummary::default()
    };
    // Bodies with an attachment (every body the mechanism places), in order.
    let placed: Vec<usize> = (0..names.len()).filter(|&b| mech.body_attachment(BodyId(b as u32)).is_some()).collect();
    let frames: Vec<Option<FrameVars>> = placed.iter().map(|&b| frame_vars(t, &format!("{}.frame_a", names[b]))).collect();
    let mut stream: Vec<(usize, Option<usize>)> = Vec::new(); // (body, index into frames when from the file)
    for (k, &b) in placed.iter().enumerate() {
        if frames[k].is_some() {
            summary.from_frames.push(names[b].clone());
            stream.push((b, Some(k)));
        } else if all_coords && !coords.is_empty() {
            summary.from_joints.push(names[b].clone());
            stream.push((b, None));
        } else {
            summary.missing.push(names[b].clone());
        }
    }
    summary.bodies = stream.iter().map(|(b, _)| names[*b].clone()).collect();
    let mut data = Vec::with_capacity(n * stream.len() * 7);
    let (mut ortho, mut kin): (Option<f64>, Option<f64>) = (None, None);
    let mut q = mech.q0();
    for i in 0..n {
        let k = if all_coords && !coords.is_empty() {
            for (c, v) in coord_vars.iter().enumerate() {
                if let Some(v) = v {
                    q[c] = t.value(*v, i);
                }
            }
            mech.forward(&q).ok()
        } else {
            None
        };
        for (b, fk) in &stream {
            let fk_pose = k.as_ref().and_then(|k| mech.body_pose(k, BodyId(*b as u32)).ok());
            let pose = match fk {
                Some(f) => {
                    let (r, m) = frames[*f].as_ref().map_or((Vector3::zeros(), Matrix3::identity()), |v| frame_at(t, v, i));
                    let (pose, res) = pose_of(r, m);
                    ortho = Some(ortho.unwrap_or(0.0).max(res));
                    if let Some(fp) = &fk_pose {
                        let d = (fp.translation.vector - pose.translation.vector).norm();
                        kin = Some(kin.unwrap_or(0.0).max(d));
                    }
                    pose
                }
                None => fk_pose.unwrap_or_else(Isometry3::identity),
            };
            let (p, r) = (pose.translation.vector, pose.rotation);
            data.extend([p.x, p.y, p.z, r.i, r.j, r.k, r.w].map(|x| x as f32));
        }
    }
    // Rigidity: frame_b seen from frame_a keeps its place.
    let mut rigid: Option<f64> = None;
    for &b in &placed {
        let (Some(a), Some(bf)) = (frame_vars(t, &format!("{}.frame_a", names[b])), frame_vars(t, &format!("{}.frame_b", names[b]))) else {
            continue;
        };
        let mut first: Option<Vector3<f64>> = None;
        for i in 0..n {
            let (ra, ma) = frame_at(t, &a, i);
            let (rb, _) = frame_at(t, &bf, i);
            let rel = ma * (rb - ra);
            match first {
                None => first = Some(rel),
                Some(f) => rigid = Some(rigid.unwrap_or(0.0).max((rel - f).norm())),
            }
        }
    }
    summary.checks = PoseChecks { orthonormality: ortho, rigidity: rigid, kinematics: kin };
    Poses { summary, t: t.time(), data }
}

/// The binary pose stream of the API (little-endian): `C2MP`, u32 version 1, u32 body count,
/// u32 step count, then per step f32 time and per body 7 f32 (position, quaternion x y z w).
pub fn stream(p: &Poses) -> Vec<u8> {
    let b = p.summary.bodies.len();
    let mut out = Vec::with_capacity(16 + p.t.len() * (4 + 28 * b));
    out.extend_from_slice(b"C2MP");
    for w in [1u32, b as u32, p.t.len() as u32] {
        out.extend_from_slice(&w.to_le_bytes());
    }
    for (i, t) in p.t.iter().enumerate() {
        out.extend_from_slice(&(*t as f32).to_le_bytes());
        for x in &p.data[i * b * 7..(i + 1) * b * 7] {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    out
}

#[cfg(test)]
mod tests;
