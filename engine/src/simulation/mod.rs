//! Closed-loop simulation of a mechanism with its drives (issue 28): forward dynamics
//! ([`Mechanism::closed_forward_dynamics`]) integrated in time with the drives' equations as
//! the package's Modelica classes state them (`pipeline/back/modelica/mechatronics/classes.rs`).
//! No IO; every run is bounded (duration, steps, samples) and can be cancelled.
//!
//! # State
//! `y = (q_i, q̇_i, per drive: i, x)`: the independent coordinates and speeds
//! ([`Mechanism::driven`]: every tree coordinate without loops; with loops the dependent ones are
//! assembled from them at each evaluation, so closure does not drift), then each drive's armature
//! current `i` and speed-controller integrator `x`.
//!
//! # Drives (the equations of the classes we write)
//! With `r` the motor angle per unit of joint coordinate (`Gears.*.ratio`, or
//! `LeadScrew.transmission = 2π·ratio/lead`), `φ = r·q`, `w = r·q̇` (rigid gear, sensors on the
//! motor shaft):
//! - `Controllers.CascadePPI`: `w_cmd = kp·(r·q_ref − φ) + r·q̇_ref`, `e = w_cmd − w`,
//!   `i_ref = ks·(e + x/Ts)`, `ẋ = e` (no anti-windup, as the class says);
//! - `Motors.DCPermanentMagnet`: `i_cmd = limit(i_ref, ±I_max)`,
//!   `v_cmd = R·i_cmd + k·w + L/Tc·(i_cmd − i)`, `v = limit(v_cmd, ±V_max)`,
//!   `L·di/dt = v − R·i − k·w`, `τ = k·i`, `J·ẇ = τ − d·w − τ_a` (`τ_a` the torque into the gear);
//! - `Motors.ServoMotor` (AC servo): `i_cmd = limit(i_ref, ±I_max)`, `Tc·di/dt = i_cmd − i`,
//!   `τ = k·i`, `J·ẇ = τ − τ_a` (no voltage model: servo datasheets give no winding R, L);
//! - `Motors.MSL_DC_PermanentMagnet` (the MSL machine in the wrapper's current loop): with MSL's
//!   default zero brush, core, stray-load and friction losses it is the DC motor above with
//!   `R = Ra(TaOperational)`, `L = La`, `k = (VaNominal − Ra(TaNominal)·IaNominal)/wNominal`,
//!   `J = Jr`, `d = 0` (`parts.rs`);
//! - `Gears.Ideal`/`LeadScrew`: the joint gets `r·τ_a`; `Gears.Efficiency` (MSL `LossyGear`,
//!   `lossTable = [0, η, η, 0, 0]`): `η·r·τ_a` while power flows from the motor to the joint
//!   (`τ_a·w ≥ 0`), `r·τ_a/η` while it flows back. The rotor inertia thus appears on the joint as
//!   an armature `J·r²` (times `η` or `1/η`), added to the mass matrix.
//!
//! # Modes and events
//! The limiters (current, voltage) and a lossy gear's direction of power flow are *modes*
//! (`Mode`): between events the equations are evaluated in fixed modes (a limiter linear or at
//! ±its limit, a gear forward or backward), so the right-hand side is smooth there. The
//! switching functions `i_ref ∓ I_max`, `v_cmd ∓ V_max` and `τ_a·w` are watched by the
//! integrator ([`integrate`]): a step across which one changes sign and after which another mode
//! is called for is cut back to the crossing (located to 1e-12 s), the mode switches there and
//! the integration restarts. The classes write the limiters as `smooth(0, noEvent(...))`
//! (continuous): the mode formulation computes the same function, without a step across its
//! kinks. A lossy gear whose new mode calls for the old one at once (MSL's `LossyGear` would
//! lock: its torque ratio between η and 1/η) keeps its mode until its switching function
//! crosses again; the locked state itself is not modelled. The reference's samples (a motion's
//! or a table's, interpolated linearly) are breakpoints where steps end.
//!
//! An [`Observer`] ([`simulate_observed`]) hears the output samples as the integration reaches
//! them (the service sends live-view frames from them); the engine itself does no IO.
//!
//! Extra generalised forces (joint damping, friction, couplings) enter through
//! [`GeneralisedForces`], added to the drive torques before the forward dynamics.
//!
//! # Integration
//! [`integrate`]: Dormand–Prince 5(4) with Hairer's PI step-size control and its continuous
//! extension (output samples, event location), our own so that steps end at breakpoints and
//! events (`ode_solvers`' `Dopri5`, used before, steps across kinks). The drive equations are
//! mildly stiff (current loop `1/Tc`, electrical `R/L`, ~1000–5000/s), which the explicit
//! method follows at steps near 1 ms, stable under error control; `max_steps` bounds the work.
//! Tolerances are the caller's (`Options::rtol`, `atol`; the service uses 1e-6 and 1e-8; the
//! cross-check with Python 1e-10 and 1e-12).

mod answer;
pub mod integrate;
mod output;
mod parts;

use std::cell::{Cell, RefCell};

use nalgebra::Vector3;

use crate::mechanism::{ClosedState, ForwardWorkspace, Mechanism, MechanismError, Workspace};

pub use answer::{saturation_intervals, verdict, Tolerances, Tracking, Verdict};
pub use output::{body_frames, result_file, series, JointLosses};
pub use parts::drive_of;

/// Longest simulated time, s.
pub const MAX_DURATION: f64 = 3600.0;
/// Most integration steps of one run.
pub const MAX_STEPS: u32 = 2_000_000;
/// Most output samples of one run.
pub const MAX_SAMPLES: usize = 200_000;
/// Most drives (one per coordinate at most).
pub const MAX_DRIVES: usize = 1024;

/// Why a simulation cannot run or stopped.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SimulationError {
    /// Bad input: `field` names it (`duration`, `drives[2].motor.L`, `start.q`, ...).
    #[error("{field}: {message}")]
    Field { field: String, message: String },
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    #[error("the integration stopped at t = {t} s: {message}")]
    Integration { t: f64, message: String },
    #[error("cancelled at t = {t} s")]
    Cancelled { t: f64 },
}

fn field(field: impl Into<String>, message: impl Into<String>) -> SimulationError {
    SimulationError::Field { field: field.into(), message: message.into() }
}

/// Which motor class's equations a [`Motor`] follows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MotorKind {
    /// `Motors.DCPermanentMagnet`: armature circuit `L·di/dt = v − R·i − k·w` fed by the
    /// current loop's voltage, limited to ±`v_max`.
    #[default]
    DcPermanentMagnet,
    /// `Motors.MSL_DC_PermanentMagnet`: the same equations as `DcPermanentMagnet` (the MSL
    /// machine without losses, constants from its nominal point: `parts.rs`); the result file
    /// adds the machine's own variable names (`motor.dcpm.ia`, ...).
    MslDcPermanentMagnet,
    /// `Motors.ServoMotor`: the servo amplifier's current loop as a first-order lag,
    /// `Tc·di/dt = i_cmd − i`; no voltage model (`r`, `l`, `v_max` and `d` unused).
    Servo,
}

/// A motor's parameters (SI): `Motors.DCPermanentMagnet` or `Motors.ServoMotor` by `kind`.
#[derive(Clone, Debug, PartialEq)]
pub struct Motor {
    pub kind: MotorKind,
    /// Armature resistance, Ω.
    pub r: f64,
    /// Armature inductance, H.
    pub l: f64,
    /// Torque constant = back-EMF constant, N·m/A.
    pub k: f64,
    /// Rotor inertia, kg·m².
    pub j: f64,
    /// Viscous friction of the rotor, N·m·s/rad.
    pub d: f64,
    /// Supply voltage limit, V.
    pub v_max: f64,
    /// Current limit, A.
    pub i_max: f64,
    /// Current-loop time constant, s.
    pub tc: f64,
}

/// `Controllers.CascadePPI`'s parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Controller {
    /// Position gain, 1/s.
    pub kp: f64,
    /// Speed gain, A·s/rad.
    pub ks: f64,
    /// Speed integrator time constant, s.
    pub ts: f64,
}

/// The gear: motor angle per unit of joint coordinate and efficiency (1: `Gears.Ideal` or
/// `LeadScrew`; below 1: `Gears.Efficiency`).
#[derive(Clone, Debug, PartialEq)]
pub struct Transmission {
    /// rad/rad for a revolute joint (`ratio`), rad/m for a prismatic one (`2π·ratio/lead`).
    pub ratio: f64,
    pub eta: f64,
}

/// The joint reference, rad or m.
#[derive(Clone, Debug, PartialEq)]
pub enum Reference {
    /// Held from t = 0; no feed-forward.
    Constant(f64),
    /// (time, value) points: linear interpolation, first and last values held; no feed-forward
    /// (`CombiTimeTable`, `LinearSegments`, `HoldLastPoint`).
    Table(Vec<(f64, f64)>),
    /// A motion's samples: position and speed interpolated linearly, the speed fed forward.
    Motion { t: Vec<f64>, q: Vec<f64>, qd: Vec<f64> },
}

/// Linear interpolation in increasing `t`, ends held.
fn interpolate(t: &[f64], v: &[f64], x: f64) -> f64 {
    match t.len() {
        0 => 0.0,
        _ if x <= t[0] => v[0],
        n if x >= t[n - 1] => v[n - 1],
        _ => {
            let k = t.partition_point(|s| *s <= x).clamp(1, t.len() - 1);
            let (t0, t1) = (t[k - 1], t[k]);
            if t1 <= t0 {
                return v[k];
            }
            v[k - 1] + (v[k] - v[k - 1]) * (x - t0) / (t1 - t0)
        }
    }
}

impl Reference {
    /// Position and fed-forward speed at `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        match self {
            Reference::Constant(v) => (*v, 0.0),
            Reference::Table(points) => {
                let value = match points.len() {
                    0 => 0.0,
                    _ if t <= points[0].0 => points[0].1,
                    n if t >= points[n - 1].0 => points[n - 1].1,
                    n => {
                        let k = points.partition_point(|p| p.0 <= t).clamp(1, n - 1);
                        let ((t0, v0), (t1, v1)) = (points[k - 1], points[k]);
                        if t1 <= t0 {
                            v1
                        } else {
                            v0 + (v1 - v0) * (t - t0) / (t1 - t0)
                        }
                    }
                };
                (value, 0.0)
            }
            Reference::Motion { t: ts, q, qd } => (interpolate(ts, q, t), interpolate(ts, qd, t)),
        }
    }

    /// The first time strictly after `t` where the reference kinks (a sample of a table or a
    /// motion), infinity when none: the integrator ends a step there.
    pub fn next_break(&self, t: f64) -> f64 {
        let times = match self {
            Reference::Constant(_) => return f64::INFINITY,
            Reference::Table(p) => return p.get(p.partition_point(|x| x.0 <= t)).map_or(f64::INFINITY, |x| x.0),
            Reference::Motion { t: times, .. } => times,
        };
        times.get(times.partition_point(|x| *x <= t)).copied().unwrap_or(f64::INFINITY)
    }

    fn check(&self, name: &str) -> Result<(), SimulationError> {
        let times_ok = |t: &[f64]| t.iter().all(|x| x.is_finite()) && t.windows(2).all(|w| w[1] >= w[0]);
        match self {
            Reference::Constant(v) if !v.is_finite() => Err(field(name, "not finite")),
            Reference::Table(p) if p.is_empty() || p.iter().any(|(a, b)| !a.is_finite() || !b.is_finite()) => {
                Err(field(name, "a table needs finite (time, value) points"))
            }
            Reference::Table(p) if !times_ok(&p.iter().map(|x| x.0).collect::<Vec<_>>()) => Err(field(name, "times must not decrease")),
            Reference::Motion { t, q, qd } if t.is_empty() || q.len() != t.len() || qd.len() != t.len() => {
                Err(field(name, "a motion needs as many positions and speeds as times"))
            }
            Reference::Motion { t, q, qd } if !times_ok(t) || q.iter().chain(qd).any(|x| !x.is_finite()) => {
                Err(field(name, "times must not decrease and values must be finite"))
            }
            _ => Ok(()),
        }
    }
}

/// One joint drive: controller, motor and gear on a coordinate.
#[derive(Clone, Debug, PartialEq)]
pub struct Drive {
    /// Index of the driven coordinate in [`Mechanism::coordinates`] (an independent one).
    pub coordinate: usize,
    pub motor: Motor,
    pub transmission: Transmission,
    pub controller: Controller,
    pub reference: Reference,
}

/// Generalised forces added on the tree coordinates (N·m or N) besides the drives': joint
/// damping and friction, couplings. `tau` holds the drives' torques on entry.
pub trait GeneralisedForces {
    fn add(&self, t: f64, q: &[f64], qd: &[f64], tau: &mut [f64]);
}

/// Hears the output samples while the run is integrated, as the integration reaches them (the
/// service's live view sends body poses from them). Samples are numbered from 0 at t = 0, every
/// `Options::output_interval`; `last` marks the run's final one.
pub trait Observer {
    /// Whether sample `index` at `t` is wanted: only wanted samples are evaluated for it.
    fn wants(&mut self, index: usize, t: f64, last: bool) -> bool;
    /// A wanted sample: every tree coordinate (`q`, loops closed, exactly as in [`Run::q`] for a
    /// mechanism without loops; with loops the dependent ones agree to the closure's tolerance).
    fn sample(&mut self, index: usize, t: f64, last: bool, q: &[f64]);
}

/// No extra forces.
pub struct NoForces;

impl GeneralisedForces for NoForces {
    fn add(&self, _t: f64, _q: &[f64], _qd: &[f64], _tau: &mut [f64]) {}
}

/// How long and how finely to simulate.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Simulated time, s (0 < duration <= [`MAX_DURATION`]).
    pub duration: f64,
    /// Spacing of the output samples, s (at most [`MAX_SAMPLES`] of them).
    pub output_interval: f64,
    /// Relative and absolute error tolerances of each step.
    pub rtol: f64,
    pub atol: f64,
    /// Step limit (at most [`MAX_STEPS`]).
    pub max_steps: u32,
    /// Largest step, s (0: no limit beyond the duration).
    pub h_max: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options { duration: 1.0, output_interval: 0.01, rtol: 1e-8, atol: 1e-10, max_steps: MAX_STEPS, h_max: 0.0 }
    }
}

/// One drive's signals at one output sample.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DriveSample {
    /// Reference position (rad or m) and speed.
    pub q_ref: f64,
    pub qd_ref: f64,
    /// Controller output, the current command after the limit, the armature current, A.
    pub i_ref: f64,
    pub i_cmd: f64,
    pub i: f64,
    /// Voltage demanded and applied, V.
    pub v_cmd: f64,
    pub v: f64,
    /// Motor angle (rad) and speed (rad/s).
    pub phi: f64,
    pub w: f64,
    /// Electromagnetic torque, N·m.
    pub tau: f64,
}

/// What a run produced: samples at the output interval, from t = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    pub t: Vec<f64>,
    /// Every tree coordinate (dependent ones assembled), speed and acceleration, per sample.
    pub q: Vec<Vec<f64>>,
    pub qd: Vec<Vec<f64>>,
    pub qdd: Vec<Vec<f64>>,
    /// Cut coordinates per sample (loops emitted plainly).
    pub cut: Vec<Vec<f64>>,
    /// Per drive (in the order given), per sample.
    pub drives: Vec<Vec<DriveSample>>,
    /// Accepted and rejected steps, events (mode switches at located crossings), right-hand
    /// side evaluations.
    pub accepted_steps: u32,
    pub rejected_steps: u32,
    pub events: u32,
    pub evaluations: u32,
}

/// Where a run starts: every tree coordinate and speed (the dependent ones of loops are a guess,
/// assembled from the independent ones).
#[derive(Clone, Debug, PartialEq)]
pub struct Start {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
}

/// The mode of one drive's switches: between two events the equations are evaluated in a fixed
/// mode (see [`integrate`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Mode {
    /// Current limiter: 0 linear, +1 at +I_max, −1 at −I_max.
    current: i8,
    /// Voltage limiter, likewise.
    voltage: i8,
    /// Lossy gear: power flows from the joint back to the motor.
    backward: bool,
}

/// Switching functions per drive: `i_ref ∓ I_max`, `v_cmd ∓ V_max`, `τ_a·w`.
const SWITCHES: usize = 5;

fn limiter_class(hi: f64, lo: f64) -> i8 {
    if hi > 0.0 {
        1
    } else if lo < 0.0 {
        -1
    } else {
        0
    }
}

fn limited(x: f64, limit: f64, mode: i8) -> f64 {
    match mode {
        1 => limit,
        -1 => -limit,
        _ => x,
    }
}

impl Mode {
    fn of(g: &[f64], gear: bool) -> Mode {
        Mode { current: limiter_class(g[0], g[1]), voltage: limiter_class(g[2], g[3]), backward: gear && g[4] < 0.0 }
    }
}

struct Scratch {
    state: ClosedState,
    tau: Vec<f64>,
    armature: Vec<f64>,
    modes: Vec<Mode>,
    signals: Vec<DriveSample>,
    ws: Workspace,
    fws: ForwardWorkspace,
    error: Option<MechanismError>,
    evaluations: u32,
}

/// An output sample as the integrator hands it over: time, state, the modes of its step.
type RawSample = (f64, Vec<f64>, Vec<Mode>);

struct Model<'a> {
    m: &'a Mechanism,
    gravity: Vector3<f64>,
    drives: &'a [Drive],
    forces: &'a dyn GeneralisedForces,
    driven: Vec<usize>,
    scratch: RefCell<Scratch>,
    samples: RefCell<Vec<RawSample>>,
    cancel: &'a dyn Fn() -> bool,
    cancelled: Cell<Option<f64>>,
    /// The observer and the index of the run's last sample.
    observer: Option<RefCell<&'a mut dyn Observer>>,
    last_sample: usize,
}

impl Model<'_> {
    /// The derivative `dy` and the switching functions `g` at `(t, y)` in the current modes;
    /// the drives' signals are left in the scratch.
    fn eval(&self, t: f64, y: &[f64], dy: &mut [f64], g: &mut [f64]) -> Result<(), MechanismError> {
        let m = self.m;
        let k = self.driven.len();
        let mut guard = self.scratch.borrow_mut();
        let s = &mut *guard;
        s.evaluations = s.evaluations.saturating_add(1);
        for (p, &i) in self.driven.iter().enumerate() {
            s.state.q[i] = y[p];
            s.state.qd[i] = y[k + p];
        }
        if m.has_loops() {
            // Positions and speeds of the dependent coordinates, for the extra forces.
            s.state.qdd.iter_mut().for_each(|x| *x = 0.0);
            m.close(&mut s.state)?;
        }
        s.tau.iter_mut().for_each(|x| *x = 0.0);
        self.forces.add(t, &s.state.q, &s.state.qd, &mut s.tau);
        s.armature.iter_mut().for_each(|x| *x = 0.0);
        // Drive signals (they do not depend on the acceleration) and the torques on the joints.
        for (d, drive) in self.drives.iter().enumerate() {
            let (mo, c, tr) = (&drive.motor, &drive.controller, &drive.transmission);
            let r = tr.ratio;
            let mode = s.modes[d];
            let (i, x) = (y[2 * k + 2 * d], y[2 * k + 2 * d + 1]);
            let q = s.state.q[drive.coordinate];
            let (phi, w) = (r * q, r * s.state.qd[drive.coordinate]);
            let (q_ref, qd_ref) = drive.reference.at(t);
            let e = c.kp * (r * q_ref - phi) + r * qd_ref - w;
            let i_ref = c.ks * (e + x / c.ts);
            let i_cmd = limited(i_ref, mo.i_max, mode.current);
            let gd = &mut g[SWITCHES * d..SWITCHES * (d + 1)];
            gd[0] = i_ref - mo.i_max;
            gd[1] = i_ref + mo.i_max;
            let (v_cmd, v, di) = match mo.kind {
                MotorKind::DcPermanentMagnet | MotorKind::MslDcPermanentMagnet => {
                    let v_cmd = mo.r * i_cmd + mo.k * w + mo.l / mo.tc * (i_cmd - i);
                    let v = limited(v_cmd, mo.v_max, mode.voltage);
                    gd[2] = v_cmd - mo.v_max;
                    gd[3] = v_cmd + mo.v_max;
                    (v_cmd, v, (v - mo.r * i - mo.k * w) / mo.l)
                }
                MotorKind::Servo => {
                    // No voltage model: the limiter's switches never cross.
                    gd[2] = -1.0;
                    gd[3] = 1.0;
                    (0.0, 0.0, (i_cmd - i) / mo.tc)
                }
            };
            dy[2 * k + 2 * d] = di;
            dy[2 * k + 2 * d + 1] = e;
            s.signals[d] = DriveSample { q_ref, qd_ref, i_ref, i_cmd, i, v_cmd, v, phi, w, tau: mo.k * i };
            let f = if tr.eta >= 1.0 {
                1.0
            } else if mode.backward {
                1.0 / tr.eta
            } else {
                tr.eta
            };
            s.tau[drive.coordinate] += f * r * (mo.k * i - mo.d * w);
            s.armature[drive.coordinate] += f * mo.j * r * r;
        }
        let Scratch { state, tau, armature, ws, fws, .. } = s;
        m.closed_forward_dynamics(state, tau, armature, &self.gravity, ws, fws)?;
        // The direction of power flow in the lossy gears: the sign of τ_a·w, τ_a the torque
        // into the gear.
        for (d, drive) in self.drives.iter().enumerate() {
            let (mo, r) = (&drive.motor, drive.transmission.ratio);
            g[SWITCHES * d + 4] = if drive.transmission.eta >= 1.0 {
                0.0
            } else {
                let w = s.signals[d].w;
                (mo.k * s.signals[d].i - mo.d * w - mo.j * r * s.state.qdd[drive.coordinate]) * w
            };
        }
        for (p, &i) in self.driven.iter().enumerate() {
            dy[p] = s.state.qd[i];
            dy[k + p] = s.state.qdd[i];
        }
        Ok(())
    }
}

impl integrate::Problem for Model<'_> {
    fn eval(&self, t: f64, y: &[f64], dy: &mut [f64], g: &mut [f64]) {
        if let Err(e) = Model::eval(self, t, y, dy, g) {
            let mut s = self.scratch.borrow_mut();
            if s.error.is_none() {
                s.error = Some(e);
            }
            dy.iter_mut().for_each(|x| *x = f64::NAN);
        }
    }

    fn switches(&self) -> usize {
        SWITCHES * self.drives.len()
    }

    fn wants_switch(&self, g: &[f64]) -> bool {
        let s = self.scratch.borrow();
        self.drives.iter().enumerate().any(|(d, drive)| Mode::of(&g[SWITCHES * d..], drive.transmission.eta < 1.0) != s.modes[d])
    }

    fn switch(&self, g: &[f64]) {
        let mut s = self.scratch.borrow_mut();
        for (d, drive) in self.drives.iter().enumerate() {
            s.modes[d] = Mode::of(&g[SWITCHES * d..], drive.transmission.eta < 1.0);
        }
    }

    fn next_break(&self, t: f64) -> f64 {
        self.drives.iter().map(|d| d.reference.next_break(t)).fold(f64::INFINITY, f64::min)
    }

    fn sample(&self, t: f64, y: &[f64]) {
        let modes = self.scratch.borrow().modes.clone();
        let index = self.samples.borrow().len();
        self.samples.borrow_mut().push((t, y.to_vec(), modes));
        if let Some(o) = &self.observer {
            let last = index == self.last_sample;
            if o.borrow_mut().wants(index, t, last) {
                // The sample's coordinates as the run's post-pass evaluates them (same modes).
                let (mut dy, mut g) = (vec![0.0; y.len()], vec![0.0; SWITCHES * self.drives.len()]);
                let evaluations = self.scratch.borrow().evaluations;
                if Model::eval(self, t, y, &mut dy, &mut g).is_ok() {
                    let q = self.scratch.borrow().state.q.clone();
                    o.borrow_mut().sample(index, t, last, &q);
                }
                self.scratch.borrow_mut().evaluations = evaluations;
            }
        }
    }

    fn stop(&self, t: f64) -> bool {
        if self.scratch.borrow().error.is_some() {
            return true;
        }
        if (self.cancel)() {
            self.cancelled.set(Some(t));
            return true;
        }
        false
    }
}

fn positive(name: String, v: f64, zero_ok: bool) -> Result<(), SimulationError> {
    if v.is_finite() && (v > 0.0 || (zero_ok && v == 0.0)) {
        Ok(())
    } else {
        Err(field(name, format!("must be {} and finite, got {v}", if zero_ok { "non-negative" } else { "positive" })))
    }
}

/// Checks every input, naming the field at fault.
fn check(m: &Mechanism, drives: &[Drive], start: &Start, opts: &Options) -> Result<(), SimulationError> {
    if !(opts.duration.is_finite() && opts.duration > 0.0 && opts.duration <= MAX_DURATION) {
        return Err(field("duration", format!("must be in (0, {MAX_DURATION}] s, got {}", opts.duration)));
    }
    if !(opts.output_interval.is_finite() && opts.output_interval > 0.0) || opts.duration / opts.output_interval > MAX_SAMPLES as f64 {
        return Err(field("output_interval", format!("must be positive, with at most {MAX_SAMPLES} samples over the duration")));
    }
    positive("rtol".into(), opts.rtol, false)?;
    positive("atol".into(), opts.atol, false)?;
    positive("h_max".into(), opts.h_max, true)?;
    if opts.max_steps == 0 || opts.max_steps > MAX_STEPS {
        return Err(field("max_steps", format!("must be in 1..={MAX_STEPS}")));
    }
    let n = m.dof();
    for (what, v) in [("start.q", &start.q), ("start.qd", &start.qd)] {
        if v.len() != n {
            return Err(field(what, format!("expected {n} values, got {}", v.len())));
        }
        if let Some(i) = v.iter().position(|x| !x.is_finite()) {
            return Err(field(format!("{what}[{i}]"), "not finite"));
        }
    }
    if drives.len() > MAX_DRIVES {
        return Err(field("drives", format!("at most {MAX_DRIVES}")));
    }
    let mut seen = vec![false; n];
    for (d, drive) in drives.iter().enumerate() {
        let f = |s: &str| format!("drives[{d}].{s}");
        let c = drive.coordinate;
        if c >= n || !m.coordinates()[c].independent {
            return Err(field(f("coordinate"), format!("{c} is not an independent coordinate of the mechanism")));
        }
        if std::mem::replace(&mut seen[c], true) {
            return Err(field(f("coordinate"), format!("coordinate {c} has two drives")));
        }
        let mo = &drive.motor;
        if mo.kind != MotorKind::Servo {
            positive(f("motor.R"), mo.r, true)?;
            positive(f("motor.L"), mo.l, false)?;
            positive(f("motor.d"), mo.d, true)?;
            positive(f("motor.V_max"), mo.v_max, false)?;
        } else if mo.d != 0.0 {
            return Err(field(f("motor.d"), "the servo motor class has no rotor friction"));
        }
        positive(f("motor.k"), mo.k, false)?;
        positive(f("motor.J"), mo.j, false)?;
        positive(f("motor.I_max"), mo.i_max, false)?;
        positive(f("motor.Tc"), mo.tc, false)?;
        let c = &drive.controller;
        positive(f("controller.kp"), c.kp, true)?;
        positive(f("controller.ks"), c.ks, true)?;
        positive(f("controller.Ts"), c.ts, false)?;
        let t = &drive.transmission;
        if !(t.ratio.is_finite() && t.ratio != 0.0) {
            return Err(field(f("gear.ratio"), format!("must be finite and non-zero, got {}", t.ratio)));
        }
        if !(t.eta > 0.0 && t.eta <= 1.0) {
            return Err(field(f("gear.eta"), format!("must be in (0, 1], got {}", t.eta)));
        }
        drive.reference.check(&f("reference"))?;
    }
    Ok(())
}

/// The index of the last output sample (the integrator's rule: times `k·interval` up to the
/// duration, within 1e-9 of it).
fn last_sample(duration: f64, interval: f64) -> usize {
    let t_last = duration * (1.0 + 1e-9);
    let mut k = (t_last / interval).floor().max(0.0) as usize;
    while (k + 1) as f64 * interval <= t_last {
        k += 1;
    }
    while k > 0 && k as f64 * interval > t_last {
        k -= 1;
    }
    k
}

/// Simulates `m` under `gravity` with `drives` (empty: a passive run) and extra `forces`
/// from `start` for `opts.duration`. `cancel` is asked after every step; when it answers true
/// the run stops with [`SimulationError::Cancelled`]. Drive currents and integrators start at 0.
pub fn simulate(
    m: &Mechanism,
    gravity: &Vector3<f64>,
    drives: &[Drive],
    forces: &dyn GeneralisedForces,
    start: &Start,
    opts: &Options,
    cancel: &dyn Fn() -> bool,
) -> Result<Run, SimulationError> {
    simulate_observed(m, gravity, drives, forces, start, opts, cancel, None)
}

/// [`simulate`], handing the output samples to `observer` as the integration reaches them.
#[allow(clippy::too_many_arguments)]
pub fn simulate_observed<'a>(
    m: &'a Mechanism,
    gravity: &Vector3<f64>,
    drives: &'a [Drive],
    forces: &'a dyn GeneralisedForces,
    start: &Start,
    opts: &Options,
    cancel: &'a dyn Fn() -> bool,
    observer: Option<&'a mut (dyn Observer + 'a)>,
) -> Result<Run, SimulationError> {
    check(m, drives, start, opts)?;
    let n = m.dof();
    let driven = m.driven();
    let k = driven.len();
    let mut state = ClosedState { q: start.q.clone(), qd: start.qd.clone(), qdd: vec![0.0; n], cut: m.cut_q0() };
    if m.has_loops() {
        m.close(&mut state)?;
    }
    let mut y = vec![0.0; 2 * k + 2 * drives.len()];
    for (p, &i) in driven.iter().enumerate() {
        y[p] = state.q[i];
        y[k + p] = state.qd[i];
    }
    let model = Model {
        m,
        gravity: *gravity,
        drives,
        forces,
        driven,
        scratch: RefCell::new(Scratch {
            state,
            tau: vec![0.0; n],
            armature: vec![0.0; n],
            modes: vec![Mode::default(); drives.len()],
            signals: vec![DriveSample::default(); drives.len()],
            ws: m.workspace(),
            fws: m.forward_workspace(),
            error: None,
            evaluations: 0,
        }),
        samples: RefCell::new(Vec::new()),
        cancel,
        cancelled: Cell::new(None),
        observer: observer.map(RefCell::new),
        last_sample: last_sample(opts.duration, opts.output_interval),
    };
    let settings = integrate::Settings {
        rtol: opts.rtol,
        atol: opts.atol,
        h_max: opts.h_max,
        max_steps: opts.max_steps,
        output_interval: opts.output_interval,
    };
    let result = integrate::integrate(&model, &mut y, opts.duration, &settings);
    if let Some(e) = model.scratch.borrow_mut().error.take() {
        return Err(e.into());
    }
    if let Some(t) = model.cancelled.get() {
        return Err(SimulationError::Cancelled { t });
    }
    let stats = result.map_err(|f| {
        let (t, message) = match f {
            integrate::Failure::MaxSteps { t, steps } => (t, format!("max_steps: {steps} steps were not enough")),
            integrate::Failure::StepUnderflow { t } => (t, format!("step size underflow at t = {t} s")),
            integrate::Failure::NotFinite { t } => (t, format!("the state became non-finite at t = {t} s")),
            integrate::Failure::Stopped { t } => (t, "stopped".to_string()),
        };
        SimulationError::Integration { t, message }
    })?;
    // Samples: derived quantities re-evaluated at each output point in its step's modes.
    let samples = model.samples.take();
    let mut run = Run {
        t: Vec::with_capacity(samples.len()),
        q: Vec::with_capacity(samples.len()),
        qd: Vec::with_capacity(samples.len()),
        qdd: Vec::with_capacity(samples.len()),
        cut: Vec::with_capacity(samples.len()),
        drives: vec![Vec::with_capacity(samples.len()); drives.len()],
        accepted_steps: stats.accepted,
        rejected_steps: stats.rejected,
        events: stats.events,
        evaluations: 0,
    };
    let mut dy = vec![0.0; y.len()];
    let mut g = vec![0.0; SWITCHES * drives.len()];
    for (t, ys, modes) in &samples {
        model.scratch.borrow_mut().modes.clone_from(modes);
        model.eval(*t, ys, &mut dy, &mut g)?;
        let s = model.scratch.borrow();
        run.t.push(*t);
        run.q.push(s.state.q.clone());
        run.qd.push(s.state.qd.clone());
        run.qdd.push(s.state.qdd.clone());
        run.cut.push(s.state.cut.clone());
        for (d, sample) in s.signals.iter().enumerate() {
            run.drives[d].push(*sample);
        }
    }
    run.evaluations = model.scratch.borrow().evaluations;
    Ok(run)
}

#[cfg(test)]
mod tests;
