//! Inverse kinematics of a tool frame: Levenberg-Marquardt with Chan-Vinod damping
//! (`lambda = k * E`, `E = ½|e|²`, as the Robotics Toolbox's `IK_LM`), joint limits by clamping,
//! and random restarts inside the limits from a seeded generator (deterministic).
//!
//! The error is `[rotation vector of R_target * Rᵀ; p_target - p]` in world coordinates (rad, m),
//! matching the Jacobian's `[angular; linear]` rows; position-only targets use the linear rows.

use nalgebra::{DMatrix, DVector, Isometry3, Vector3};

use super::{element_motion, CoordKind, Mechanism, MechanismError, XorShift};
use crate::pipeline::ir::FrameId;

/// What the tool frame should reach.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum IkTarget {
    /// Position and orientation (world).
    Pose(Isometry3<f64>),
    /// The origin only (world, m).
    Position(Vector3<f64>),
}

/// Solver settings.
#[derive(Clone, Debug)]
pub struct IkOptions {
    /// Iterations per attempt.
    pub max_iterations: usize,
    /// Attempts from random starting points after the first (from the given seed).
    pub restarts: usize,
    /// Success: position error below this (m) ...
    pub tol_position: f64,
    /// ... and rotation error below this (rad, full-pose targets).
    pub tol_rotation: f64,
    /// Damping gain `k` (`lambda = k * E`).
    pub damping: f64,
    /// Limits per tree coordinate; `None`: [`Mechanism::default_limits`].
    pub limits: Option<Vec<(f64, f64)>>,
}

impl Default for IkOptions {
    fn default() -> Self {
        IkOptions { max_iterations: 30, restarts: 100, tol_position: 1e-6, tol_rotation: 1e-6, damping: 1.0, limits: None }
    }
}

/// The outcome of a solve.
#[derive(Clone, Debug, PartialEq)]
pub struct IkResult {
    /// The best coordinates found (every tree coordinate; those not moving the tool keep the
    /// starting value).
    pub q: Vec<f64>,
    pub success: bool,
    /// Iterations over all attempts.
    pub iterations: usize,
    /// Random restarts used.
    pub restarts: usize,
    /// Final position error, m.
    pub position_error: f64,
    /// Final rotation error, rad (0 for position targets).
    pub rotation_error: f64,
}

impl Mechanism {
    /// Limits for IK when none are given (CAD exports carry none): a full turn centred on the
    /// CAD pose for revolute coordinates, ±0.1 m around it for prismatic ones.
    pub fn default_limits(&self) -> Vec<(f64, f64)> {
        self.coordinates
            .iter()
            .map(|c| match c.kind {
                CoordKind::Revolute => (c.q0 - std::f64::consts::PI, c.q0 + std::f64::consts::PI),
                CoordKind::Prismatic => (c.q0 - 0.1, c.q0 + 0.1),
            })
            .collect()
    }

    /// Solves for tree coordinates that bring CAD frame `tool` to `target`, starting from `seed`
    /// (length [`Mechanism::dof`]); restarts draw from `rng`. Mechanisms with loop closures are
    /// refused ([`MechanismError::ClosedLoops`]).
    pub fn inverse_kinematics(
        &self,
        tool: FrameId,
        target: &IkTarget,
        seed: &[f64],
        opts: &IkOptions,
        rng: &mut XorShift,
    ) -> Result<IkResult, MechanismError> {
        if self.has_loops() {
            return Err(MechanismError::ClosedLoops);
        }
        self.check_len("seed", seed)?;
        let at = *self.frame_attachment(tool).ok_or_else(|| MechanismError::Internal(format!("no frame {}", tool.0)))?;
        let limits = match &opts.limits {
            Some(l) => {
                self.check_len("limits", &l.iter().map(|x| x.0).collect::<Vec<_>>())?;
                l.clone()
            }
            None => self.default_limits(),
        };
        // The links moving the tool, root first.
        let mut path = Vec::new();
        let mut cur = at.link;
        while let Some(i) = cur {
            path.push(i);
            cur = self.links.get(i).and_then(|l| l.parent);
        }
        path.reverse();
        let n = path.len();
        let rows = if matches!(target, IkTarget::Pose(_)) { 6 } else { 3 };
        let mut q = seed.to_vec();
        for &i in &path {
            q[i] = q[i].clamp(limits[i].0, limits[i].1);
        }
        let mut poses = vec![Isometry3::identity(); n];
        let mut jac = DMatrix::<f64>::zeros(rows, n);
        let mut e = DVector::<f64>::zeros(rows);
        // Tool pose and error at q (over the path only).
        let evaluate = |q: &[f64], poses: &mut [Isometry3<f64>], e: &mut DVector<f64>| -> (f64, f64) {
            let mut parent = Isometry3::identity();
            for (k, &i) in path.iter().enumerate() {
                let l = &self.links[i];
                parent = parent * l.x_tree * element_motion(l.prismatic, &l.axis, q[i]);
                poses[k] = parent;
            }
            let tool_pose = parent * at.offset;
            let p = tool_pose.translation.vector;
            match target {
                IkTarget::Pose(t) => {
                    let rot = (t.rotation * tool_pose.rotation.inverse()).scaled_axis();
                    let dp = t.translation.vector - p;
                    e.fixed_rows_mut::<3>(0).copy_from(&rot);
                    e.fixed_rows_mut::<3>(3).copy_from(&dp);
                    (dp.norm(), rot.norm())
                }
                IkTarget::Position(t) => {
                    let dp = t - p;
                    e.fixed_rows_mut::<3>(0).copy_from(&dp);
                    (dp.norm(), 0.0)
                }
            }
        };
        let mut total = 0;
        let mut best: Option<(f64, Vec<f64>, f64, f64)> = None;
        for attempt in 0..=opts.restarts {
            if attempt > 0 {
                for &i in &path {
                    q[i] = rng.range(limits[i].0, limits[i].1);
                }
            }
            let (mut dp, mut dr) = evaluate(&q, &mut poses, &mut e);
            for _ in 0..opts.max_iterations {
                if dp < opts.tol_position && dr < opts.tol_rotation {
                    break;
                }
                total += 1;
                let p = poses.last().map_or_else(Isometry3::identity, |x| *x * at.offset).translation.vector;
                for (k, &i) in path.iter().enumerate() {
                    let l = &self.links[i];
                    let a = poses[k].rotation * l.axis;
                    let (ang, lin) = if l.prismatic { (Vector3::zeros(), a) } else { (a, a.cross(&(p - poses[k].translation.vector))) };
                    if rows == 6 {
                        jac.fixed_view_mut::<3, 1>(0, k).copy_from(&ang);
                        jac.fixed_view_mut::<3, 1>(3, k).copy_from(&lin);
                    } else {
                        jac.fixed_view_mut::<3, 1>(0, k).copy_from(&lin);
                    }
                }
                let energy = 0.5 * e.norm_squared();
                let mut a = jac.tr_mul(&jac);
                for d in 0..n {
                    a[(d, d)] += opts.damping * energy;
                }
                let g = jac.tr_mul(&e);
                let Some(chol) = a.cholesky() else { break };
                let step = chol.solve(&g);
                for (k, &i) in path.iter().enumerate() {
                    q[i] = (q[i] + step[k]).clamp(limits[i].0, limits[i].1);
                }
                (dp, dr) = evaluate(&q, &mut poses, &mut e);
            }
            let success = dp < opts.tol_position && dr < opts.tol_rotation;
            let score = dp + dr;
            if best.as_ref().is_none_or(|b| score < b.0) {
                best = Some((score, q.clone(), dp, dr));
            }
            if success {
                return Ok(IkResult { q, success, iterations: total, restarts: attempt, position_error: dp, rotation_error: dr });
            }
        }
        let (_, q, dp, dr) = best.ok_or_else(|| MechanismError::Internal("no IK attempt".into()))?;
        Ok(IkResult { q, success: false, iterations: total, restarts: opts.restarts, position_error: dp, rotation_error: dr })
    }
}
