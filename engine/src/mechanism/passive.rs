//! Passive joint losses: viscous damping and Coulomb friction on each coordinate (URDF
//! `<dynamics damping friction>`, carried by `ir::Losses`).
//!
//! The law, per coordinate `i` with damping `d` and friction `f`, is the generalised force the
//! drive must add to overcome the bearing:
//!
//! ```text
//! tau_passive = d * qd + f * s,   s = sign(qd)     if |qd| > REST_SPEED
//!                                 s = sign(qdd)    if |qd| <= REST_SPEED (breaking away)
//!                                 s = 0            if both are zero (at rest, not accelerating)
//! ```
//!
//! `sign` is not regularised: the friction is the full `f` as soon as the joint moves. At rest
//! the friction opposes the acceleration (the joint breaks away the way it accelerates, as
//! MSL's `BearingFriction` in its forward/backward start modes); a joint at rest that does not
//! accelerate is stuck, where the friction could hold anything up to `f`: it is counted as 0
//! (the drive holds the whole static load; friction's static reserve is not credited).
//! This deviates from MuJoCo's `frictionloss` (a soft constraint whose force depends on the
//! solver's impedance) and from a smoothed `tanh` sign: both give less than `f` near rest.

use super::{Mechanism, MechanismError};

/// Speeds at or below this (rad/s or m/s, absolute) count as rest for the friction's sign.
pub const REST_SPEED: f64 = 1e-9;

/// The sign the friction force takes (see the module docs).
pub fn friction_sign(qd: f64, qdd: f64) -> f64 {
    if qd.abs() > REST_SPEED {
        qd.signum()
    } else if qdd != 0.0 {
        qdd.signum()
    } else {
        0.0
    }
}

impl Mechanism {
    /// Whether any tree coordinate has damping or friction.
    pub fn has_losses(&self) -> bool {
        self.coordinates.iter().any(|c| !c.losses.is_zero())
    }

    /// The passive torques (N·m or N) the drives must add at each tree coordinate to overcome
    /// the joints' damping and friction at speeds `qd` and accelerations `qdd` (both of length
    /// [`Mechanism::dof`]; `qdd` only decides the friction's direction at rest: pass zeros where
    /// it is unknown, e.g. in forward dynamics). The law is in the module docs of `passive.rs`:
    /// `d * qd + f * sign(qd)`, `sign(qdd)` at rest. The result is to be *added* to
    /// [`Mechanism::inverse_dynamics`].
    pub fn passive_torques(&self, qd: &[f64], qdd: &[f64], out: &mut [f64]) -> Result<(), MechanismError> {
        self.check_len("speeds", qd)?;
        self.check_len("accelerations", qdd)?;
        self.check_len("torques", out)?;
        for (i, c) in self.coordinates.iter().enumerate() {
            let l = c.losses;
            out[i] = l.damping * qd[i] + l.friction * friction_sign(qd[i], qdd[i]);
        }
        Ok(())
    }

    /// [`Mechanism::inverse_dynamics`] plus [`Mechanism::passive_torques`]: the torques the drives
    /// apply to move the spanning tree with its joint losses.
    pub fn inverse_dynamics_with_losses(
        &self,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        gravity: &nalgebra::Vector3<f64>,
        ws: &mut super::Workspace,
        tau: &mut [f64],
    ) -> Result<(), MechanismError> {
        self.inverse_dynamics(q, qd, qdd, gravity, ws, tau)?;
        for (i, c) in self.coordinates.iter().enumerate() {
            let l = c.losses;
            if !l.is_zero() {
                tau[i] += l.damping * qd[i] + l.friction * friction_sign(qd[i], qdd[i]);
            }
        }
        Ok(())
    }
}
