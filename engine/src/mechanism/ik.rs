//! Inverse kinematics of a tool frame: Levenberg-Marquardt with Chan-Vinod damping
//! (`lambda = k * E`, `E = ½|e|²`, as the Robotics Toolbox's `IK_LM`), joint limits by clamping,
//! and random restarts inside the limits from a seeded generator (deterministic).
//!
//! The error is `[rotation vector of R_target * Rᵀ; p_target - p]` in world coordinates (rad, m),
//! matching the Jacobian's `[angular; linear]` rows; position-only targets use the linear rows.

use nalgebra::{DMatrix, DVector, Isometry3, Vector3};

use super::{element_motion, Attachment, CoordKind, Mechanism, MechanismError, XorShift};
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
    /// How many independent directions the driven coordinates move the tool in at `q` (rank of
    /// the tool's Jacobian through the closure, over the target's rows: 6 for a pose, 3 for a
    /// position). Below the target's rows, only a subset of targets is reachable.
    pub mobility: usize,
}

impl Mechanism {
    /// The tool's attachment and the joint limits of an IK request, its lengths checked.
    fn ik_inputs(&self, tool: FrameId, seed: &[f64], opts: &IkOptions) -> Result<(Attachment, Vec<(f64, f64)>), MechanismError> {
        self.check_len("seed", seed)?;
        let at = *self.frame_attachment(tool).ok_or_else(|| MechanismError::Internal(format!("no frame {}", tool.0)))?;
        let limits = match &opts.limits {
            Some(l) => {
                self.check_len("limits", &l.iter().map(|x| x.0).collect::<Vec<_>>())?;
                l.clone()
            }
            None => self.default_limits(),
        };
        Ok((at, limits))
    }

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
    /// (length [`Mechanism::dof`]); restarts draw from `rng`. Mechanisms with dependent
    /// coordinates (loops, mimic couplings) are solved over their driven coordinates with the
    /// closure kept ([`Mechanism::inverse_kinematics_closed`]).
    pub fn inverse_kinematics(
        &self,
        tool: FrameId,
        target: &IkTarget,
        seed: &[f64],
        opts: &IkOptions,
        rng: &mut XorShift,
    ) -> Result<IkResult, MechanismError> {
        if self.has_dependent() {
            return self.inverse_kinematics_closed(tool, target, seed, opts, rng);
        }
        let (at, limits) = self.ik_inputs(tool, seed, opts)?;
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
            target_error(target, &(parent * at.offset), e)
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
                let mobility = self.tool_mobility(&q, &[], tool, rows)?;
                return Ok(IkResult { q, success, iterations: total, restarts: attempt, position_error: dp, rotation_error: dr, mobility });
            }
        }
        let (_, q, dp, dr) = best.ok_or_else(|| MechanismError::Internal("no IK attempt".into()))?;
        let mobility = self.tool_mobility(&q, &[], tool, rows)?;
        Ok(IkResult { q, success: false, iterations: total, restarts: opts.restarts, position_error: dp, rotation_error: dr, mobility })
    }

    /// The tool's Jacobian with respect to the driven coordinates at an assembled `(q, cut)`:
    /// `J_tree G` (`G = ∂x/∂x_i` through the closure), `rows` of it (6: `[angular; linear]`,
    /// 3: linear).
    fn driven_jacobian(&self, q: &[f64], cut: &[f64], tool: FrameId, rows: usize) -> Result<DMatrix<f64>, MechanismError> {
        let at = *self.frame_attachment(tool).ok_or_else(|| MechanismError::Internal(format!("no frame {}", tool.0)))?;
        let k = self.forward(q)?;
        let mut jt = nalgebra::Matrix6xX::zeros(self.links.len());
        self.jacobian_into(&k, &at, &mut jt);
        let n = self.links.len();
        let g = if self.has_dependent() {
            let (driven, follow) = self.x_split();
            let x: Vec<f64> = q.iter().chain(cut).copied().collect();
            self.linearise(&x, &driven, &follow)?.g.rows(0, n).into_owned()
        } else {
            DMatrix::identity(n, n)
        };
        let full = DMatrix::from_column_slice(6, n, jt.as_slice()) * g;
        Ok(if rows == 6 { full } else { full.rows(3, 3).into_owned() })
    }

    /// Rank of [`Self::driven_jacobian`] (singular values above 1e-9 of the largest, and above
    /// 1e-12 absolutely).
    fn tool_mobility(&self, q: &[f64], cut: &[f64], tool: FrameId, rows: usize) -> Result<usize, MechanismError> {
        let cut: Vec<f64> = if cut.len() == self.cut_coordinates.len() { cut.to_vec() } else { self.cut_q0() };
        let j = self.driven_jacobian(q, &cut, tool, rows)?;
        let sv = j.singular_values();
        let top = sv.max();
        Ok(sv.iter().filter(|s| **s > 1e-9 * top && **s > 1e-12).count())
    }

    /// Inverse kinematics of a mechanism with dependent coordinates (loops, mimic couplings):
    /// Levenberg-Marquardt as for trees, over the driven coordinates only, each iterate closed by
    /// [`Mechanism::assemble`] (the closure is kept exactly; the tool's Jacobian is `J_tree G`).
    /// A trial point where the loops cannot be assembled halves the step (up to 8 times) and
    /// otherwise ends the attempt; restarts draw the driven coordinates inside their limits.
    /// The returned `q` is assembled (every follower consistent). Dependent coordinates are not
    /// clamped to their limits here (the motion planner checks them).
    pub fn inverse_kinematics_closed(
        &self,
        tool: FrameId,
        target: &IkTarget,
        seed: &[f64],
        opts: &IkOptions,
        rng: &mut XorShift,
    ) -> Result<IkResult, MechanismError> {
        let (at, limits) = self.ik_inputs(tool, seed, opts)?;
        let driven = self.driven();
        let nd = driven.len();
        if nd == 0 {
            return Err(MechanismError::IkUnsupported("the mechanism has no driven joint".into()));
        }
        let rows = if matches!(target, IkTarget::Pose(_)) { 6 } else { 3 };
        let error = |q: &[f64], e: &mut DVector<f64>| -> Result<(f64, f64), MechanismError> {
            let k = self.forward(q)?;
            Ok(target_error(target, &self.attachment_pose(&k, &at), e))
        };
        let mut e = DVector::<f64>::zeros(rows);
        let mut total = 0;
        // (score, q, cut, position error, rotation error) of the best attempt.
        type Best = (f64, Vec<f64>, Vec<f64>, f64, f64);
        let mut best: Option<Best> = None;
        for attempt in 0..=opts.restarts {
            let mut q = if attempt == 0 { seed.to_vec() } else { self.q0() };
            for &i in &driven {
                q[i] = if attempt == 0 { q[i].clamp(limits[i].0, limits[i].1) } else { rng.range(limits[i].0, limits[i].1) };
            }
            let mut cut = self.cut_q0();
            if self.assemble(&mut q, &mut cut).is_err() {
                continue;
            }
            let (mut dp, mut dr) = error(&q, &mut e)?;
            for _ in 0..opts.max_iterations {
                if dp < opts.tol_position && dr < opts.tol_rotation {
                    break;
                }
                total += 1;
                let jac = self.driven_jacobian(&q, &cut, tool, rows)?;
                let energy = 0.5 * e.norm_squared();
                let mut a = jac.tr_mul(&jac);
                for d in 0..nd {
                    a[(d, d)] += opts.damping * energy;
                }
                let g = jac.tr_mul(&e);
                let Some(chol) = a.cholesky() else { break };
                let step = chol.solve(&g);
                let mut t = 1.0;
                let mut moved = false;
                for _ in 0..8 {
                    let (mut qt, mut ct) = (q.clone(), cut.clone());
                    for (k, &i) in driven.iter().enumerate() {
                        qt[i] = (q[i] + t * step[k]).clamp(limits[i].0, limits[i].1);
                    }
                    if self.assemble(&mut qt, &mut ct).is_ok() {
                        q = qt;
                        cut = ct;
                        moved = true;
                        break;
                    }
                    t *= 0.5;
                }
                if !moved {
                    break;
                }
                (dp, dr) = error(&q, &mut e)?;
            }
            let success = dp < opts.tol_position && dr < opts.tol_rotation;
            let score = dp + dr;
            if best.as_ref().is_none_or(|b| score < b.0) {
                best = Some((score, q.clone(), cut.clone(), dp, dr));
            }
            if success {
                let mobility = self.tool_mobility(&q, &cut, tool, rows)?;
                return Ok(IkResult { q, success, iterations: total, restarts: attempt, position_error: dp, rotation_error: dr, mobility });
            }
        }
        let Some((_, q, cut, dp, dr)) = best else {
            return Err(MechanismError::IkUnsupported(
                "the loops could not be assembled at the starting joint values nor at any restart inside the driven joints' limits".into(),
            ));
        };
        let mobility = self.tool_mobility(&q, &cut, tool, rows)?;
        Ok(IkResult { q, success: false, iterations: total, restarts: opts.restarts, position_error: dp, rotation_error: dr, mobility })
    }
}

/// The error of `tool_pose` from `target` into `e` (`[rotation; position]` for a pose, the
/// position alone for a point): (position error m, rotation error rad).
fn target_error(target: &IkTarget, tool_pose: &Isometry3<f64>, e: &mut DVector<f64>) -> (f64, f64) {
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
}
