//! Motion and torques of mechanisms with closed loops, driven at their independent coordinates.
//!
//! The driven joints are the independent coordinates (those whose Modelica start value is fixed:
//! every tree coordinate outside loops, and in each loop the ones the loop pass chose). The
//! others, and the coordinates of plainly emitted closing joints, follow from the closure
//! equations `Φ(x) = 0`, `x = (q, cut)`:
//! - position: [`Mechanism::assemble`];
//! - velocity: `Φ_u ẋ_u = -Φ_i ẋ_i` (`u` the followers, `i` the driven coordinates);
//! - acceleration: `Φ_u ẍ_u = -Φ_i ẍ_i - (Φ_x ẋ)_x ẋ`, the last term the second derivative of `Φ`
//!   along `ẋ`;
//! - torques (ideal constraints, virtual work): with `G = ∂x/∂x_i = [I; -Φ_u⁺ Φ_i]`, the driven
//!   torques are `τ_i = Gᵀ τ_tree`, `τ_tree` the tree's inverse dynamics at `(q, q̇, q̈)` (the
//!   closing joints carry no mass); the followers carry none.
//! - mimic couplings (`q_f = m q_l + offset`) are closure equations too, linear and exact: the
//!   follower is dependent, its torque lands on its leader (`τ_l += m τ_f`).
//!
//! The closure's Jacobian `Φ_x` and its velocity-product term `(Φ_x ẋ)_x ẋ` are exact, by
//! spatial-vector algebra (`rates.rs`), for every closure form; checked against differences of
//! the residual and of the Jacobian (`tests.rs`) and by the energy balance.

use nalgebra::{DMatrix, DVector, Vector3};

use super::{Mechanism, MechanismError, Workspace};

/// Where every coordinate of a loop mechanism is, and how it moves.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedState {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// Coordinates of plainly emitted closing joints.
    pub cut: Vec<f64>,
}

/// See [`Mechanism::linearise`].
pub(super) struct Linearised {
    pub(super) g: DMatrix<f64>,
    phi_i: DMatrix<f64>,
    svd: nalgebra::SVD<f64, nalgebra::Dyn, nalgebra::Dyn>,
    eps: f64,
}

impl Mechanism {
    /// Indices of the driven (independent) tree coordinates.
    pub fn driven(&self) -> Vec<usize> {
        (0..self.coordinates.len()).filter(|&i| self.coordinates[i].independent).collect()
    }

    pub(super) fn x_split(&self) -> (Vec<usize>, Vec<usize>) {
        let n = self.coordinates.len();
        let driven = self.driven();
        let follow: Vec<usize> = (0..n).filter(|i| !self.coordinates[*i].independent).chain(n..n + self.cut_coordinates.len()).collect();
        (driven, follow)
    }

    /// `∂Φ/∂x` at `x = (q, cut)`, exact (`rates.rs`).
    fn closure_jacobian(&self, x: &[f64]) -> Result<DMatrix<f64>, MechanismError> {
        let n = self.coordinates.len();
        let k = self.forward(&x[..n])?;
        Ok(self.closure_jacobian_at(&k, &x[n..]))
    }

    /// The closure linearised at `x`: `G = ∂x/∂x_i` (columns: driven coordinates), and `Φ_i` and
    /// the SVD of `Φ_u` for solving the followers' accelerations.
    pub(super) fn linearise(&self, x: &[f64], driven: &[usize], follow: &[usize]) -> Result<Linearised, MechanismError> {
        self.linearised(&self.closure_jacobian(x)?, driven, follow)
    }

    /// [`Mechanism::linearise`] from the closure's Jacobian `jac` there.
    fn linearised(&self, jac: &DMatrix<f64>, driven: &[usize], follow: &[usize]) -> Result<Linearised, MechanismError> {
        let phi_u = jac.select_columns(follow);
        let phi_i = jac.select_columns(driven);
        let svd = phi_u.svd(true, true);
        let eps = svd.singular_values.max() * 1e-10;
        let sol = svd.solve(&(-&phi_i), eps).map_err(|e| MechanismError::Internal(e.to_string()))?;
        let mut g = DMatrix::zeros(jac.ncols(), driven.len());
        for (k, &i) in driven.iter().enumerate() {
            g[(i, k)] = 1.0;
        }
        for (r, &u) in follow.iter().enumerate() {
            for k in 0..driven.len() {
                g[(u, k)] = sol[(r, k)];
            }
        }
        Ok(Linearised { g, phi_i, svd, eps })
    }

    /// Completes a state from its driven coordinates: `state.q`, `qd`, `qdd` hold the driven
    /// values (others are a starting guess for the position and are overwritten), `state.cut` a
    /// guess of the cut coordinates.
    pub fn close(&self, state: &mut ClosedState) -> Result<(), MechanismError> {
        self.close_linearised(state).map(|_| ())
    }

    /// [`Mechanism::close`], returning the closure linearised at the state's position (`None`
    /// without loops).
    pub(super) fn close_linearised(&self, state: &mut ClosedState) -> Result<Option<Linearised>, MechanismError> {
        self.check_len("coordinates", &state.q)?;
        self.check_len("speeds", &state.qd)?;
        self.check_len("accelerations", &state.qdd)?;
        self.assemble(&mut state.q, &mut state.cut)?;
        if self.closures.is_empty() {
            // Mimic couplings only: linear, so speeds and accelerations follow exactly.
            self.propagate_couplings(&mut state.qd, false);
            self.propagate_couplings(&mut state.qdd, false);
            return Ok(None);
        }
        let n = self.coordinates.len();
        let (driven, follow) = self.x_split();
        let k = self.forward(&state.q)?;
        let lin = self.linearised(&self.closure_jacobian_at(&k, &state.cut), &driven, &follow)?;
        let qd_i = DVector::from_iterator(driven.len(), driven.iter().map(|&i| state.qd[i]));
        let xd = &lin.g * &qd_i;
        // (Φ_x ẋ)_x ẋ, exact (`rates.rs`).
        let curv = self.closure_curvature(&k, &state.cut, &xd.as_slice()[..n], &xd.as_slice()[n..]);
        let qdd_i = DVector::from_iterator(driven.len(), driven.iter().map(|&i| state.qdd[i]));
        let rhs = -(&lin.phi_i * qdd_i) - curv;
        let xdd_u = lin.svd.solve(&rhs, lin.eps).map_err(|e| MechanismError::Internal(e.to_string()))?;
        for (r, &u) in follow.iter().enumerate() {
            if u < n {
                state.qd[u] = xd[u];
                state.qdd[u] = xdd_u[r];
            }
        }
        Ok(Some(lin))
    }

    /// Torques (N·m or N) at the driven coordinates of a closed state, in the order of
    /// [`Mechanism::driven`]; `tree` receives the tree's own inverse dynamics with the joints'
    /// losses ([`Mechanism::inverse_dynamics_with_losses`], length `dof`). A mimic follower's
    /// torque is carried by its leader (`τ_l += m τ_f`, virtual work): the leader's drive moves
    /// both through the coupling gear, as in the Modelica model.
    pub fn driven_torques(
        &self,
        state: &ClosedState,
        gravity: &Vector3<f64>,
        ws: &mut Workspace,
        tree: &mut [f64],
    ) -> Result<Vec<f64>, MechanismError> {
        self.inverse_dynamics_with_losses(&state.q, &state.qd, &state.qdd, gravity, ws, tree)?;
        self.project(state, tree)
    }

    /// `Gᵀ τ` for tree torques `tau` at the state's position.
    fn project(&self, state: &ClosedState, tau: &[f64]) -> Result<Vec<f64>, MechanismError> {
        let (driven, follow) = self.x_split();
        if !self.has_dependent() {
            return Ok(driven.iter().map(|&i| tau[i]).collect());
        }
        let x: Vec<f64> = state.q.iter().chain(&state.cut).copied().collect();
        let g = self.linearise(&x, &driven, &follow)?.g;
        let mut full = DVector::zeros(x.len());
        for (i, t) in tau.iter().enumerate() {
            full[i] = *t;
        }
        Ok((g.transpose() * full).iter().copied().collect())
    }

    /// The inertia each driven coordinate sees at a closed state's position (diagonal of
    /// `Gᵀ M G`), kg·m² or kg.
    pub fn driven_inertia(&self, state: &ClosedState, ws: &mut Workspace) -> Result<Vec<f64>, MechanismError> {
        let (driven, follow) = self.x_split();
        let n = self.coordinates.len();
        let x: Vec<f64> = state.q.iter().chain(&state.cut).copied().collect();
        let g = if !self.has_dependent() {
            let mut g = DMatrix::zeros(n, driven.len());
            for (k, &i) in driven.iter().enumerate() {
                g[(i, k)] = 1.0;
            }
            g
        } else {
            self.linearise(&x, &driven, &follow)?.g
        };
        let zero = vec![0.0; n];
        let mut tau = vec![0.0; n];
        let mut out = Vec::with_capacity(driven.len());
        for k in 0..driven.len() {
            let acc: Vec<f64> = (0..n).map(|i| g[(i, k)]).collect();
            self.inverse_dynamics(&state.q, &zero, &acc, &Vector3::zeros(), ws, &mut tau)?;
            out.push((0..n).map(|i| g[(i, k)] * tau[i]).sum());
        }
        Ok(out)
    }
}
