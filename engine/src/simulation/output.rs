//! A run as a MAT v4 result with the variable names a Modelica tool writes for our package
//! (`Mechatronics` extends `Mechanics`): `<joint>.phi`/`w`/`a` (`s`/`v`/`a` for prismatic joints),
//! `drive_<joint>.motor.i` (and `i_cmd`, `v`, `v_cmd`, `phi`, `w`, `tau`, the limits `I_max`,
//! `V_max`; for the MSL machine also `motor.dcpm.ia`, `phiMechanical`, `wMechanical`,
//! `tauElectrical` and `motor.supply.v`), `drive_<joint>.controller.q_ref`/`qd_ref`/`i_ref`, and every placed body's
//! `<body>.frame_a.r_0[i]` and `<body>.frame_a.R.T[i,j]` (MSL: `R.T` turns world vectors into
//! frame coordinates, so it is the transpose of the frame -> world rotation). Written in float64
//! (OpenModelica's spelling `R.T[i,j]`), read back by `results::mat` like an uploaded result.
//! Also the joint losses as [`GeneralisedForces`] for the service's runs.

use crate::mechanism::{CoordKind, Mechanism, MechanismError};
use crate::pipeline::ir::BodyId;
use crate::results::write;

use super::{Drive, GeneralisedForces, Run};

/// The series of a run (name, value per sample), in the order they are written.
pub fn series(m: &Mechanism, run: &Run, drives: &[Drive]) -> Result<Vec<(String, Vec<f64>)>, MechanismError> {
    let mut out: Vec<(String, Vec<f64>)> = Vec::new();
    let coords = m.coordinates();
    for (i, c) in coords.iter().enumerate() {
        let (p, v) = match c.kind {
            CoordKind::Revolute => ("phi", "w"),
            CoordKind::Prismatic => ("s", "v"),
        };
        out.push((format!("{}.{p}", c.name), run.q.iter().map(|q| q[i]).collect()));
        out.push((format!("{}.{v}", c.name), run.qd.iter().map(|q| q[i]).collect()));
        out.push((format!("{}.a", c.name), run.qdd.iter().map(|q| q[i]).collect()));
    }
    for (d, drive) in drives.iter().enumerate() {
        let name = &coords[drive.coordinate].name;
        let s = &run.drives[d];
        let col = |f: fn(&super::DriveSample) -> f64| s.iter().map(f).collect::<Vec<f64>>();
        let motor = format!("drive_{name}.motor");
        let ctrl = format!("drive_{name}.controller");
        out.push((format!("{motor}.i"), col(|x| x.i)));
        out.push((format!("{motor}.i_cmd"), col(|x| x.i_cmd)));
        out.push((format!("{motor}.v"), col(|x| x.v)));
        out.push((format!("{motor}.v_cmd"), col(|x| x.v_cmd)));
        out.push((format!("{motor}.phi"), col(|x| x.phi)));
        out.push((format!("{motor}.w"), col(|x| x.w)));
        out.push((format!("{motor}.tau"), col(|x| x.tau)));
        out.push((format!("{motor}.I_max"), vec![drive.motor.i_max; s.len()]));
        out.push((format!("{motor}.V_max"), vec![drive.motor.v_max; s.len()]));
        if drive.motor.kind == super::MotorKind::MslDcPermanentMagnet {
            // The wrapper's MSL machine and power stage by their own names (the names above,
            // which the UI plots, stay for every DC motor).
            out.push((format!("{motor}.dcpm.ia"), col(|x| x.i)));
            out.push((format!("{motor}.dcpm.phiMechanical"), col(|x| x.phi)));
            out.push((format!("{motor}.dcpm.wMechanical"), col(|x| x.w)));
            out.push((format!("{motor}.dcpm.tauElectrical"), col(|x| x.tau)));
            out.push((format!("{motor}.supply.v"), col(|x| x.v)));
        }
        out.push((format!("{ctrl}.q_ref"), col(|x| x.q_ref)));
        out.push((format!("{ctrl}.qd_ref"), col(|x| x.qd_ref)));
        out.push((format!("{ctrl}.i_ref"), col(|x| x.i_ref)));
    }
    let names = m.body_names();
    let placed: Vec<usize> = (0..names.len()).filter(|&b| m.body_attachment(BodyId(b as u32)).is_some()).collect();
    let first = out.len();
    for &b in &placed {
        for i in 1..=3 {
            out.push((format!("{}.frame_a.r_0[{i}]", names[b]), Vec::with_capacity(run.t.len())));
        }
        for i in 1..=3 {
            for j in 1..=3 {
                out.push((format!("{}.frame_a.R.T[{i},{j}]", names[b]), Vec::with_capacity(run.t.len())));
            }
        }
    }
    for q in &run.q {
        let k = m.forward(q)?;
        for (p, &b) in placed.iter().enumerate() {
            let f = frame_a(m, &k, b)?;
            for (x, v) in f.iter().enumerate() {
                out[first + 12 * p + x].1.push(*v);
            }
        }
    }
    Ok(out)
}

/// A placed body's `frame_a.r_0[1..3]` and `frame_a.R.T` row by row (MSL: `R.T` = (frame →
/// world)ᵀ).
fn frame_a(m: &Mechanism, k: &crate::mechanism::Kinematics, b: usize) -> Result<[f64; 12], MechanismError> {
    let pose = m.body_pose(k, BodyId(b as u32))?;
    let r = pose.translation.vector;
    let t = pose.rotation.to_rotation_matrix().into_inner().transpose();
    Ok(std::array::from_fn(|x| if x < 3 { r[x] } else { t[((x - 3) / 3, (x - 3) % 3)] }))
}

/// Every body's `frame_a.r_0` and `R.T` (12 numbers, as [`series`] writes them) at the tree
/// coordinates `q`, in the package's body order: what a live-view frame carries
/// (`live::encode`). An error when a body has no place in the mechanism.
pub fn body_frames(m: &Mechanism, q: &[f64]) -> Result<Vec<[f64; 12]>, MechanismError> {
    let k = m.forward(q)?;
    (0..m.body_names().len()).map(|b| frame_a(m, &k, b)).collect()
}

/// The run as a MAT v4 trajectory file (float64).
pub fn result_file(m: &Mechanism, run: &Run, drives: &[Drive]) -> Result<Vec<u8>, MechanismError> {
    let s = series(m, run, drives)?;
    Ok(write::trajectory(&run.t, &s, false))
}

/// The joints' own damping and friction (URDF `<dynamics>`), as forces opposing the motion:
/// `−(d·q̇ + f·sign(q̇))` (no friction at exact rest: forward dynamics does not know the
/// acceleration's sign before it is computed).
pub struct JointLosses<'a>(pub &'a Mechanism);

impl GeneralisedForces for JointLosses<'_> {
    fn add(&self, _t: f64, _q: &[f64], qd: &[f64], tau: &mut [f64]) {
        let n = qd.len();
        let mut loss = vec![0.0; n];
        if self.0.passive_torques(qd, &vec![0.0; n], &mut loss).is_ok() {
            for (t, l) in tau.iter_mut().zip(&loss) {
                *t -= l;
            }
        }
    }
}
