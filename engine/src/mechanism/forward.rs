//! Forward dynamics: the accelerations that given generalised forces produce.
//!
//! - **Trees**: the articulated-body algorithm (Featherstone, "Rigid Body Dynamics Algorithms",
//!   ch. 7), O(n), with the conventions of [`Mechanism::inverse_dynamics`] (`dynamics.rs`):
//!   each link's quantities in its own frame (element frame_b), spatial vectors
//!   `[angular; linear]` about the link origin, gravity as a base acceleration. ABA rather than
//!   CRBA + Cholesky: it needs no n×n matrix (large URDF trees stay linear in time and memory)
//!   and it is what Pinocchio's `aba` computes, so the cross-check compares like with like.
//! - **Closed loops**: coordinate partitioning with the independent (driven) coordinates that
//!   the loop pass chose, as in `driven.rs`: with `x = (q, cut)` and `G = ∂x/∂x_i`, the
//!   dependent accelerations are `ẍ = G ẍ_i + a₀` (`a₀` the closure's velocity-product term,
//!   from [`Mechanism::close`] at `ẍ_i = 0`), and virtual work on the closed mechanism gives
//!   `(Gᵀ M G) ẍ_i = Gᵀ (τ − ID(q, q̇, a₀))`, solved by Cholesky. Positions of the dependent
//!   coordinates are found by assembly from the independent ones at every evaluation
//!   (projection to the constraint manifold), so closure never drifts: an integrator only
//!   carries the independent coordinates and speeds.
//!
//! Generalised forces `tau` are the caller's: actuator torques plus any passive ones (joint
//! damping, friction) it adds per coordinate; the closing joints of loops carry none.

use nalgebra::{DMatrix, DVector, Matrix3, Matrix6, Vector3, Vector6};

use super::{ClosedState, Mechanism, MechanismError, Workspace};

/// Scratch space for [`Mechanism::forward_dynamics`]: no allocation per call.
#[derive(Clone, Debug)]
pub struct ForwardWorkspace {
    r_tree: Vec<Matrix3<f64>>,
    p_tree: Vec<Vector3<f64>>,
    /// Motion transform parent -> link.
    x: Vec<Matrix6<f64>>,
    s: Vec<Vector6<f64>>,
    v: Vec<Vector6<f64>>,
    c: Vec<Vector6<f64>>,
    ia: Vec<Matrix6<f64>>,
    pa: Vec<Vector6<f64>>,
    u_vec: Vec<Vector6<f64>>,
    d: Vec<f64>,
    u: Vec<f64>,
    a: Vec<Vector6<f64>>,
}

fn skew(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

/// Spatial cross product for motion vectors: `v ×ₘ m`.
pub(super) fn cross_motion(v: &Vector6<f64>, m: &Vector6<f64>) -> Vector6<f64> {
    let (w, vl) = (v.fixed_rows::<3>(0), v.fixed_rows::<3>(3));
    let (mw, mv) = (m.fixed_rows::<3>(0), m.fixed_rows::<3>(3));
    let a = w.cross(&mw);
    let b = w.cross(&mv) + vl.cross(&mw);
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

/// Spatial cross product for forces: `v ×* f`.
fn cross_force(v: &Vector6<f64>, f: &Vector6<f64>) -> Vector6<f64> {
    let (w, vl) = (v.fixed_rows::<3>(0), v.fixed_rows::<3>(3));
    let (n, fl) = (f.fixed_rows::<3>(0), f.fixed_rows::<3>(3));
    let a = w.cross(&n) + vl.cross(&fl);
    let b = w.cross(&fl);
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

/// A pivot of the articulated inertia below this fraction of its link's scale (or of 1e-300)
/// means the coordinate moves nothing with mass: the accelerations are undetermined.
const SINGULAR: f64 = 1e-14;

impl Mechanism {
    /// Scratch space for [`Mechanism::forward_dynamics`].
    pub fn forward_workspace(&self) -> ForwardWorkspace {
        let n = self.links.len();
        let z6 = vec![Vector6::zeros(); n];
        ForwardWorkspace {
            r_tree: self.links.iter().map(|l| l.x_tree.rotation.to_rotation_matrix().into_inner()).collect(),
            p_tree: self.links.iter().map(|l| l.x_tree.translation.vector).collect(),
            x: vec![Matrix6::identity(); n],
            s: self
                .links
                .iter()
                .map(|l| {
                    let a = l.axis;
                    if l.prismatic {
                        Vector6::new(0.0, 0.0, 0.0, a.x, a.y, a.z)
                    } else {
                        Vector6::new(a.x, a.y, a.z, 0.0, 0.0, 0.0)
                    }
                })
                .collect(),
            v: z6.clone(),
            c: z6.clone(),
            ia: vec![Matrix6::zeros(); n],
            pa: z6.clone(),
            u_vec: z6.clone(),
            d: vec![0.0; n],
            u: vec![0.0; n],
            a: z6,
        }
    }

    /// The accelerations `qdd` that generalised forces `tau` (N·m or N per coordinate) produce
    /// at coordinates `q` and speeds `qd` under `gravity` (world, m/s²), on the spanning tree
    /// (loop closures ignored: see [`Mechanism::closed_forward_dynamics`]). Every slice has
    /// length [`Mechanism::dof`]; `ws` comes from [`Mechanism::forward_workspace`].
    /// The inverse of [`Mechanism::inverse_dynamics`].
    pub fn forward_dynamics(
        &self,
        q: &[f64],
        qd: &[f64],
        tau: &[f64],
        gravity: &Vector3<f64>,
        ws: &mut ForwardWorkspace,
        qdd: &mut [f64],
    ) -> Result<(), MechanismError> {
        self.forward_dynamics_armature(q, qd, tau, &[], gravity, ws, qdd)
    }

    /// [`Mechanism::forward_dynamics`] with an extra inertia `armature[i]` (kg·m² or kg) on each
    /// coordinate's own axis, as a motor rotor reflected through its gear adds (`J·ratio²`):
    /// `(M + diag(armature)) q̈ = τ − C(q, q̇) − g(q)`. An empty `armature` adds nothing.
    #[allow(clippy::too_many_arguments)]
    pub fn forward_dynamics_armature(
        &self,
        q: &[f64],
        qd: &[f64],
        tau: &[f64],
        armature: &[f64],
        gravity: &Vector3<f64>,
        ws: &mut ForwardWorkspace,
        qdd: &mut [f64],
    ) -> Result<(), MechanismError> {
        if !armature.is_empty() {
            self.check_len("armature", armature)?;
        }
        self.check_len("coordinates", q)?;
        self.check_len("speeds", qd)?;
        self.check_len("torques", tau)?;
        self.check_len("accelerations", qdd)?;
        let n = self.links.len();
        if ws.x.len() != n {
            return Err(MechanismError::Length { what: "workspace", expected: n, got: ws.x.len() });
        }
        // Pass 1: velocities, velocity-product accelerations, rigid-body inertias and bias forces.
        for i in 0..n {
            let l = &self.links[i];
            let a = l.axis;
            let (r, p) = if l.prismatic {
                (ws.r_tree[i], ws.p_tree[i] + ws.r_tree[i] * (a * q[i]))
            } else {
                (ws.r_tree[i] * super::dynamics::rotation(&a, q[i]), ws.p_tree[i])
            };
            let rt = r.transpose();
            let mut x = Matrix6::zeros();
            x.fixed_view_mut::<3, 3>(0, 0).copy_from(&rt);
            x.fixed_view_mut::<3, 3>(3, 3).copy_from(&rt);
            x.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-rt * skew(&p)));
            let v_parent = l.parent.map(|pi| ws.v[pi]).unwrap_or_else(Vector6::zeros);
            let vj = ws.s[i] * qd[i];
            let v = x * v_parent + vj;
            ws.c[i] = cross_motion(&v, &vj);
            let mut inertia = Matrix6::zeros();
            inertia.fixed_view_mut::<3, 3>(0, 0).copy_from(&l.inertia_o);
            inertia.fixed_view_mut::<3, 3>(0, 3).copy_from(&skew(&l.h));
            inertia.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-skew(&l.h)));
            inertia.fixed_view_mut::<3, 3>(3, 3).copy_from(&(Matrix3::identity() * l.mass));
            ws.pa[i] = cross_force(&v, &(inertia * v));
            ws.ia[i] = inertia;
            ws.x[i] = x;
            ws.v[i] = v;
        }
        // Pass 2: articulated inertias and bias forces, leaves to root.
        for i in (0..n).rev() {
            let u_vec = ws.ia[i] * ws.s[i];
            let d = ws.s[i].dot(&u_vec) + armature.get(i).copied().unwrap_or(0.0);
            let scale = ws.ia[i].abs().max() + armature.get(i).copied().unwrap_or(0.0);
            if d.partial_cmp(&(SINGULAR * scale)) != Some(std::cmp::Ordering::Greater) || !d.is_finite() || d < 1e-300 {
                return Err(MechanismError::Singular { coordinate: self.coordinates[i].name.clone() });
            }
            let u = tau[i] - ws.s[i].dot(&ws.pa[i]);
            ws.u_vec[i] = u_vec;
            ws.d[i] = d;
            ws.u[i] = u;
            if let Some(pi) = self.links[i].parent {
                let ia = ws.ia[i] - u_vec * u_vec.transpose() / d;
                let pa = ws.pa[i] + ia * ws.c[i] + u_vec * (u / d);
                let xt = ws.x[i].transpose();
                ws.ia[pi] += xt * ia * ws.x[i];
                ws.pa[pi] += xt * pa;
            }
        }
        // Pass 3: accelerations, root to leaves (gravity as the base's upward acceleration).
        let base = Vector6::new(0.0, 0.0, 0.0, -gravity.x, -gravity.y, -gravity.z);
        for (i, out) in qdd.iter_mut().enumerate().take(n) {
            let a_parent = self.links[i].parent.map(|pi| ws.a[pi]).unwrap_or(base);
            let a = ws.x[i] * a_parent + ws.c[i];
            *out = (ws.u[i] - ws.u_vec[i].dot(&a)) / ws.d[i];
            ws.a[i] = a + ws.s[i] * *out;
        }
        Ok(())
    }

    /// Forward dynamics of a mechanism with loop closures, by coordinate partitioning (see the
    /// module docs). In: `state.q` and `state.qd` hold the independent coordinates and speeds
    /// ([`Mechanism::driven`]; the others are a starting guess for assembly), `state.cut` a
    /// guess of the cut coordinates; `tau` the generalised forces on the tree coordinates
    /// (length [`Mechanism::dof`]). Out: the state completed (every position assembled, every
    /// speed and acceleration consistent with the closures). `armature` as in
    /// [`Mechanism::forward_dynamics_armature`] (empty: none). Without loops this is
    /// [`Mechanism::forward_dynamics_armature`].
    pub fn closed_forward_dynamics(
        &self,
        state: &mut ClosedState,
        tau: &[f64],
        armature: &[f64],
        gravity: &Vector3<f64>,
        ws: &mut Workspace,
        fws: &mut ForwardWorkspace,
    ) -> Result<(), MechanismError> {
        self.check_len("torques", tau)?;
        if !armature.is_empty() {
            self.check_len("armature", armature)?;
        }
        if self.closures.is_empty() {
            self.check_len("coordinates", &state.q)?;
            self.check_len("speeds", &state.qd)?;
            state.qdd.resize(self.dof(), 0.0);
            return self.forward_dynamics_armature(&state.q, &state.qd, tau, armature, gravity, fws, &mut state.qdd);
        }
        let n = self.dof();
        state.qdd.clear();
        state.qdd.resize(n, 0.0);
        // Positions, speeds and the closure's own accelerations a₀ (ẍ_i = 0).
        let g = self.close_linearised(state)?.ok_or_else(|| MechanismError::Internal("loops without a linearisation".into()))?.g;
        let driven = self.driven();
        let mut bias = vec![0.0; n];
        self.inverse_dynamics(&state.q, &state.qd, &state.qdd, gravity, ws, &mut bias)?;
        let k = driven.len();
        let mut rhs = DVector::zeros(k);
        for c in 0..k {
            rhs[c] = (0..n).map(|i| g[(i, c)] * (tau[i] - bias[i])).sum();
        }
        // Gᵀ M G, column by column: M g_c = ID(q, 0, g_c) without gravity.
        let zero = vec![0.0; n];
        let mut mg = vec![0.0; n];
        let mut reduced = DMatrix::zeros(k, k);
        for c in 0..k {
            let col: Vec<f64> = (0..n).map(|i| g[(i, c)]).collect();
            self.inverse_dynamics(&state.q, &zero, &col, &Vector3::zeros(), ws, &mut mg)?;
            for r in 0..k {
                reduced[(r, c)] = (0..n).map(|i| g[(i, r)] * (mg[i] + armature.get(i).copied().unwrap_or(0.0) * g[(i, c)])).sum();
            }
        }
        let reduced = (&reduced + reduced.transpose()) * 0.5;
        let chol = reduced.cholesky().ok_or_else(|| MechanismError::Singular {
            coordinate: driven.first().map(|&i| self.coordinates[i].name.clone()).unwrap_or_default(),
        })?;
        let xdd_i = chol.solve(&rhs);
        for i in 0..n {
            state.qdd[i] += (0..k).map(|c| g[(i, c)] * xdd_i[c]).sum::<f64>();
        }
        Ok(())
    }
}
