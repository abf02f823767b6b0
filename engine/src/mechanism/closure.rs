//! Loop closure: the cut equations the loop pass chose, and assembly by Newton iteration.
//!
//! The unknowns are the dependent tree coordinates (those whose Modelica start value is not
//! fixed) and the coordinates of plainly emitted closing joints; the independent coordinates
//! are kept. Equations, per cut:
//! - plain joint: the closing joint's chain from its base frame must reach its follower frame:
//!   position difference (m) and rotation vector (rad), world axes, 6 equations;
//! - `RevolutePlanarLoopConstraint`: frame_b's origin, in frame_a, has no component
//!   perpendicular to the axis `n` (2 equations);
//! - `Joints.Constraints.*`: the locked components of frame_b's origin in frame_a, and for
//!   `Revolute` the axis `n` kept (2), for `Prismatic` no relative rotation (3), for `Universal`
//!   `n_a ⟂ n_b` (1);
//! - and per mimic coupling (`CoordCoupling`): `q_f - m q_l - offset` (1, linear: its Jacobian
//!   rows are set exactly, never differenced).

use nalgebra::{DMatrix, DVector, Vector3};

use super::{element_motion, Closure, ClosureForm, ConstraintClass, Kinematics, Mechanism, MechanismError};

/// Closure residuals below this (max-norm, m or rad) count as assembled.
pub const ASSEMBLY_TOL: f64 = 1e-12;
/// Newton iterations before giving up.
pub const MAX_ITERATIONS: usize = 50;

/// How an assembly went.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Assembly {
    pub iterations: usize,
    /// Largest closure residual at the end (m or rad).
    pub residual: f64,
}

/// Two unit vectors perpendicular to unit `n` and to each other.
pub(super) fn perpendiculars(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let e1 = crate::pipeline::passes::loops::perpendicular(n);
    (e1, n.cross(&e1))
}

impl Closure {
    /// Number of this closure's equations.
    pub(super) fn equations(&self) -> usize {
        match &self.form {
            ClosureForm::Plain { .. } => 6,
            ClosureForm::Planar { .. } => 2,
            ClosureForm::Constraint { class, locked, .. } => locked.iter().filter(|l| **l).count() + class.rotation_equations(),
        }
    }
}

impl Mechanism {
    /// Number of closure equations.
    pub fn closure_equations(&self) -> usize {
        self.closures.iter().map(Closure::equations).sum::<usize>() + self.couplings.len()
    }

    /// The closure residuals at tree coordinates `q` and cut coordinates `cut`.
    pub fn closure_residual(&self, q: &[f64], cut: &[f64]) -> Result<Vec<f64>, MechanismError> {
        self.check_len("coordinates", q)?;
        if cut.len() != self.cut_coordinates.len() {
            return Err(MechanismError::Length { what: "cut coordinates", expected: self.cut_coordinates.len(), got: cut.len() });
        }
        let k = if self.closures.is_empty() { Kinematics::default() } else { self.forward(q)? };
        let mut out = Vec::with_capacity(self.closure_equations());
        self.residual_into(&k, q, cut, &mut out);
        Ok(out)
    }

    /// The residuals: the loops' (in order), then one per mimic coupling, `q_f - m q_l - offset`.
    fn residual_into(&self, k: &Kinematics, q: &[f64], cut: &[f64], out: &mut Vec<f64>) {
        out.clear();
        for c in &self.closures {
            let a = self.attachment_pose(k, &c.a);
            let b = self.attachment_pose(k, &c.b);
            match &c.form {
                ClosureForm::Plain { elements, residual } => {
                    let mut x = a;
                    for (prismatic, axis, i) in elements {
                        x *= element_motion(*prismatic, axis, cut.get(*i).copied().unwrap_or(0.0));
                    }
                    x *= residual;
                    out.extend((b.translation.vector - x.translation.vector).iter());
                    out.extend((b.rotation * x.rotation.inverse()).scaled_axis().iter());
                }
                ClosureForm::Planar { n } => {
                    let d = a.rotation.inverse() * (b.translation.vector - a.translation.vector);
                    let (e1, e2) = perpendiculars(n);
                    out.push(e1.dot(&d));
                    out.push(e2.dot(&d));
                }
                ClosureForm::Constraint { class, locked, n, n_b } => {
                    let d = a.rotation.inverse() * (b.translation.vector - a.translation.vector);
                    out.extend((0..3).filter(|i| locked[*i]).map(|i| d[i]));
                    let rel = a.rotation.inverse() * b.rotation;
                    match class {
                        ConstraintClass::Spherical => {}
                        ConstraintClass::Revolute => {
                            let (e1, e2) = perpendiculars(n);
                            let m = rel * n;
                            out.push(e1.dot(&m));
                            out.push(e2.dot(&m));
                        }
                        ConstraintClass::Prismatic => out.extend(rel.scaled_axis().iter()),
                        ConstraintClass::Universal => out.push(n.dot(&(rel * n_b))),
                    }
                }
            }
        }
        for c in &self.couplings {
            out.push(q[c.follower] - c.multiplier * q[c.leader] - c.offset);
        }
    }

    /// Solves the dependent tree coordinates of `q` and the cut coordinates `cut` (both used as
    /// the starting guess) so that every loop closes, keeping the independent coordinates.
    /// Newton iteration with a least-squares step (SVD) and step halving.
    pub fn assemble(&self, q: &mut [f64], cut: &mut [f64]) -> Result<Assembly, MechanismError> {
        self.check_len("coordinates", q)?;
        // Mimic followers exactly from their leaders first (the loops, if any, may move them on).
        self.propagate_couplings(q, true);
        let mut r = self.closure_residual(q, cut)?;
        let unknowns: Vec<(bool, usize)> = (0..q.len())
            .filter(|&i| !self.coordinates[i].independent)
            .map(|i| (true, i))
            .chain((0..cut.len()).map(|i| (false, i)))
            .collect();
        let norm = |r: &[f64]| r.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut res = norm(&r);
        let mut k = Kinematics::default();
        let mut scratch = Vec::new();
        let eval = |q: &[f64], cut: &[f64], k: &mut Kinematics, out: &mut Vec<f64>| {
            self.forward_into(q, k);
            self.residual_into(k, q, cut, out);
        };
        let get = |q: &[f64], cut: &[f64], u: (bool, usize)| if u.0 { q[u.1] } else { cut[u.1] };
        fn set(q: &mut [f64], cut: &mut [f64], u: (bool, usize), x: f64) {
            if u.0 {
                q[u.1] = x;
            } else {
                cut[u.1] = x;
            }
        }
        for it in 0..MAX_ITERATIONS {
            if res <= ASSEMBLY_TOL {
                return Ok(Assembly { iterations: it, residual: res });
            }
            if unknowns.is_empty() {
                break;
            }
            // The exact Jacobian (`rates.rs`), its unknowns' columns.
            self.forward_into(q, &mut k);
            let full = self.closure_jacobian_at(&k, cut);
            let n = q.len();
            let jac = DMatrix::from_fn(r.len(), unknowns.len(), |row, c| {
                let (tree, i) = unknowns[c];
                full[(row, if tree { i } else { n + i })]
            });
            let svd = jac.svd(true, true);
            let eps = svd.singular_values.max() * 1e-10;
            let step = svd.solve(&(-DVector::from_column_slice(&r)), eps).map_err(|e| MechanismError::Internal(e.to_string()))?;
            let start: Vec<f64> = unknowns.iter().map(|&u| get(q, cut, u)).collect();
            let mut t = 1.0;
            loop {
                for (c, &u) in unknowns.iter().enumerate() {
                    set(q, cut, u, start[c] + t * step[c]);
                }
                eval(q, cut, &mut k, &mut scratch);
                let new = norm(&scratch);
                if new < res || t < 1e-3 {
                    r.clone_from(&scratch);
                    res = new;
                    break;
                }
                t *= 0.5;
            }
        }
        if res <= ASSEMBLY_TOL {
            return Ok(Assembly { iterations: MAX_ITERATIONS, residual: res });
        }
        Err(MechanismError::NotAssembled { residual: res, iterations: MAX_ITERATIONS })
    }
}
