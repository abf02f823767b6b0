//! Checks a conversion's emitted Modelica against ground truth by forward kinematics.

use std::collections::BTreeMap;

use cad2mo_engine::pipeline::Output;
use nalgebra::{Matrix3, Vector3};

use crate::common::file_text;
use crate::fk;
use crate::truth::TruthFrame;

/// What an FK check compared.
#[derive(Debug, Default)]
pub struct FkStats {
    pub frames: usize,
    pub cgs: usize,
    /// Bodies whose emitted mass and world inertia were compared.
    pub inertias: usize,
    pub loop_checks: usize,
    pub max_position_error: f64,
    pub max_rotation_error: f64,
}

/// Tolerances: 1e-9 m and 1e-9 (rotation-matrix entries ~ rad).
pub const TOL: f64 = 1e-9;

/// Orthonormalises a CAD rotation (printed with 6 digits) the way any reader must: the nearest
/// rotation, by polar decomposition.
pub fn nearest_rotation(m: &Matrix3<f64>) -> Matrix3<f64> {
    let svd = m.svd(true, true);
    match (svd.u, svd.v_t) {
        (Some(u), Some(v_t)) => u * v_t,
        _ => *m,
    }
}

/// Parses `Mechanics.mo` from the output, walks it, and compares every frame the report maps to
/// a connector, and every body's CG, with `frames` / `cgs` (by node ID).
pub fn fk_check(out: &Output, frames: &BTreeMap<String, TruthFrame>, cgs: &BTreeMap<String, Vector3<f64>>) -> Result<FkStats, String> {
    fk_check_with_inertia(out, frames, cgs, &BTreeMap::new())
}

/// As [`fk_check`], and also compares each (unlumped) body's emitted mass and inertia, resolved
/// in world axes through the walked pose, with `mass_props` (relative tolerance 1e-9).
pub fn fk_check_with_inertia(
    out: &Output,
    frames: &BTreeMap<String, TruthFrame>,
    cgs: &BTreeMap<String, Vector3<f64>>,
    mass_props: &BTreeMap<String, (f64, Matrix3<f64>)>,
) -> Result<FkStats, String> {
    let text = file_text(out, "/Mechanics.mo").ok_or("no Mechanics.mo in output")?;
    let model = fk::parse_mechanics(&text)?;
    let poses = fk::forward_kinematics(&model)?;
    let mut stats = FkStats { loop_checks: poses.loop_checks, ..FkStats::default() };
    let mut errors = Vec::new();
    for body in &out.report.bodies {
        for fr in std::iter::once(&body.cs1).chain(body.frames.iter()) {
            let Some(conn) = &fr.connector else { continue };
            let Some(truth) = frames.get(&fr.node_id) else { continue };
            let Some(pose) = poses.connectors.get(conn) else {
                errors.push(format!("{conn} (frame {}) is not reached from the world or a free body's initial pose", fr.node_id));
                continue;
            };
            let dp = (pose.translation.vector - truth.position).norm();
            let r = pose.rotation.to_rotation_matrix().into_inner();
            let dr = (r - nearest_rotation(&truth.rotation)).abs().max();
            stats.frames += 1;
            stats.max_position_error = stats.max_position_error.max(dp);
            stats.max_rotation_error = stats.max_rotation_error.max(dr);
            if dp > TOL || dr > TOL {
                errors.push(format!(
                    "{conn} (body {}, frame {} {}): position off by {dp:e} m, rotation by {dr:e}",
                    body.cad_name, fr.name, fr.node_id
                ));
            }
        }
        if let (Some((mass, inertia)), true) = (mass_props.get(&body.node_id), body.lumped.is_empty()) {
            let comp = model.components.iter().find(|c| c.name == body.modelica_name);
            let m = comp.and_then(|c| match c.params.get("m") {
                Some(fk::Value::Num(m)) => Some(*m),
                _ => None,
            });
            match (m, fk::body_inertia_world(&model, &poses, &body.modelica_name)) {
                (Some(m), Some(i)) => {
                    stats.inertias += 1;
                    let scale = inertia.abs().max().max(1e-300);
                    let di = (i - inertia).abs().max() / scale;
                    if (m - mass).abs() > 1e-12 * mass.max(1.0) || di > 1e-9 {
                        errors.push(format!(
                            "{}: emitted mass {m} kg vs {mass}; world inertia differs by {di:e} (relative)\n  emitted {i:?}\n  truth   {inertia:?}",
                            body.modelica_name
                        ));
                    }
                }
                _ => errors.push(format!("{}: mass or inertia not found in Mechanics.mo", body.modelica_name)),
            }
        }
        if let Some(truth) = cgs.get(&body.node_id) {
            if !body.lumped.is_empty() {
                continue;
            }
            match fk::cg_world(&model, &poses, &body.modelica_name) {
                Some(cg) => {
                    let d = (cg - truth).norm();
                    stats.cgs += 1;
                    stats.max_position_error = stats.max_position_error.max(d);
                    if d > TOL {
                        errors.push(format!("CG of {} off by {d:e} m", body.modelica_name));
                    }
                }
                None => errors.push(format!("CG of {} not computed", body.modelica_name)),
            }
        }
    }
    if errors.is_empty() {
        Ok(stats)
    } else {
        Err(format!("{} FK mismatches:\n{}", errors.len(), errors.join("\n")))
    }
}
