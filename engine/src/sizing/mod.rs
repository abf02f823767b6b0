//! Drive sizing: does a motor and gear from the library move a joint through a motion, and
//! which real combinations of the library would? No IO, no HTTP, no SQL, no panics.
//!
//! Input per driven axis: an [`AxisLoad`], the joint's speed, acceleration and torque (or force)
//! samples from the motion's inverse dynamics (gravity included) and the largest joint-space
//! inertia `M_jj` over the motion. Motors and gears come from library instances
//! ([`parts::motor`], [`parts::gear`]), the drive amplifier too ([`parts::amplifier`]); the
//! user's [`Settings`] add the supply voltage, the reserve, the dwell of the duty cycle and the
//! brake (resistor or DC-bus capacity).
//!
//! **Duty cycle.** The motion is repeated with a dwell of `Settings::dwell` seconds between
//! repetitions, during which the joint holds the motion's last pose: the holding torque is the
//! last sample's `τ` (at rest), so RMS values, the thermal model and the mean braking power are
//! taken over the period `T_cycle = motion + dwell`.
//!
//! **Reflection** through the gear to the motor shaft, sample by sample:
//!
//! - transmission `n = ratio` (revolute) or `n = ratio·2π/lead` (rad/m, lead screw); motor speed
//!   `ω_m = n·q̇`;
//! - load torque at the motor `τ/(n·η)` while the motor drives the load (joint power
//!   `P = τ·q̇ >= 0`, standstill included) and `τ·η/n` while the load drives the motor back
//!   (`P < 0`): losses always cost the motor, in both directions of power flow;
//! - motor torque `T_m = load torque + (J_motor + J_gear,in)·n·q̈ + d·ω_m`; a gear without a
//!   datasheet `J_in` leaves every check of `T_m` not evaluated (`gear.J_in` missing), never 0;
//! - motor current `I = T_m/k`, voltage `U = R·I + k·ω_m`, electrical power `P_el = U·I`.
//!
//! **Checks** (each a [`Check`]: value, limit, the limit's source, margin
//! `(limit - value)/limit`, status; the rule in its `rule` field):
//!
//! | check | value | limit (source) |
//! |---|---|---|
//! | `peak_torque` | max `|T_m|` | motor `T_peak` (the maker's short-time limit), else `T_stall` (stall torque at the nominal voltage); the same rule for every motor class |
//! | `rms_torque` | `sqrt(∫T_m² dt / T_cycle)` over the duty cycle | motor `T_nom` (continuous) |
//! | `thermal_torque` | `sqrt(max θ)`, `θ` the winding's first-order response `τ_w·θ' = T_m² - θ` in the periodic steady state of the duty cycle | motor `T_nom`, with `tau_th_w`; not evaluated where the maker gives no winding time constant |
//! | `motor_speed` | max `|ω_m|` | motor `w_max` |
//! | `voltage` | max `|R·I + k·ω_m|` | the supply voltage the user sets for the amplifier |
//! | `peak_current` | max `|I|` | amplifier `I_peak` |
//! | `rms_current` | RMS of `I` over the duty cycle | amplifier `I_cont` |
//! | `gear_input_speed` | max `|ω_m|` | gear `w_in_max` |
//! | `gear_peak_torque` | max `|τ|` at the output (N·m; rotary gears) | gear `T_peak`, the repeated-peak limit |
//! | `screw_static_load` | max `|F|` at the nut (N; screws) | the screw's basic static axial load rating `C_0a` (ISO 3408-5; the reserve is the static safety factor), else a library's older `F_peak` |
//! | `screw_life` | cubic-mean force `F_m = (Σ|v|·|F|³·Δt / Σ|v|·Δt)^(1/3)` (N; screws) | `C_a·(10⁶/L_req)^(1/3)`: the nominal life `L10 = (C_a/F_m)³·10⁶` revolutions (ISO 3408-5) covers `L_req`, the revolutions of the user's `screw_life` hours of the duty cycle |
//! | `gear_rms_torque` | RMS of `τ` over the duty cycle | gear `T_rated` (rotary gears) |
//! | `gear_avg_torque` | `(Σ|q̇|·|τ|³·Δt / Σ|q̇|·Δt)^(1/3)` (Harmonic Drive's average torque) | gear `T_avg_max`, where the maker gives one |
//! | `inertia_ratio` | `(J_load/n² + J_gear,in) / J_motor`: the gear's input inertia counted on the load side | 10 (≤ 3 good, 3–5 common, 5–10 needs stiff mechanics); the reserve does not apply |
//! | `braking` | DC bus: the largest energy fed back in one braking interval (`∫ -P_el dt` while `P_el < 0`); brake resistor: the energy fed back per cycle / `T_cycle` | bus: `C·(U_max² - U_supply²)/2`; resistor: its continuous power; no braking: passes without a limit |
//!
//! A check whose limit (or whose value's input) is a value the library or the settings lack is
//! reported `not_evaluated` and the value is named in `missing` (`motor.T_nom`, `gear.J_in`,
//! `amplifier.I_peak`, `supply_voltage`, `gear.C_a`, `screw_life`); `where given` checks (`thermal_torque`,
//! `gear_avg_torque`) are `not_evaluated` without being missing. A check passes when
//! `value <= limit`; it keeps the reserve when `margin >= reserve` (default 20 %).
//!
//! **Ranking** ([`rank`]): only real catalogue combinations: every motor × gear of the
//! [`Catalog`] whose gear fits the joint kind (prismatic joints: screws) and mounts on the motor
//! where the gear names the motors it mounts on (`motor_mounts` against the motor's `mount`),
//! each gear at its own catalogue ratio only. Order: (1) passes every check with the reserve,
//! nothing missing; (2) passes, nothing missing, some margin below the reserve; (3) every
//! evaluated check passes but values are missing (the fewest missing first); (4) fails. Within
//! (1)–(3) the smallest first: rotor inertia, then mass (motor + gear, known before unknown), then
//! price class (known before unknown), then names; within (4) the largest smallest margin first. Each [`Alternative`] says
//! its standing, why, and its limiting check.

pub mod parts;
#[cfg(test)]
mod tests;

use serde::Serialize;

use crate::library::Issue;
use crate::pipeline::back::modelica::mechatronics::JointKind;
pub use parts::{Amplifier, Catalog, Gear, Motor, PeakRule};

/// The inertia ratio limit; ≤ [`INERTIA_RATIO_GOOD`] is good.
pub const INERTIA_RATIO_LIMIT: f64 = 10.0;
pub const INERTIA_RATIO_GOOD: f64 = 3.0;

/// The reserve a combination must keep on every capacity check when the user gives none.
pub const DEFAULT_RESERVE: f64 = 0.2;

/// The longest dwell a duty cycle takes (s): a day.
pub const MAX_DWELL: f64 = 86_400.0;

/// The longest required screw life (h): a century of operation.
pub const MAX_SCREW_LIFE: f64 = 876_600.0;

/// At most this many operating points are returned.
pub const MAX_POINTS: usize = 2000;

/// How many alternatives [`size_drive`] returns by default.
pub const TOP: usize = 10;

/// Why a motor without a winding resistance has no voltage or braking check.
const NO_R: &str =
    "the motor's datasheet gives no winding resistance (AC servo motor): the motor voltage and the energy fed back are not known";

/// Why a sizing cannot be done.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SizingError {
    #[error("cannot size: {slot} \"{part}\" is of class {class}, not a {slot} the sizing knows")]
    UnknownClass { part: String, class: String, slot: &'static str },
    #[error("cannot size with \"{part}\": {reason}")]
    BadPart { part: String, reason: String },
    #[error("cannot size joint {joint}: gear \"{gear}\" fits {fits} joints, the joint is {kind}")]
    GearDoesNotFit { joint: String, gear: String, fits: &'static str, kind: &'static str },
    #[error("cannot size joint {joint}: {reason}")]
    BadLoad { joint: String, reason: String },
}

/// How braking energy leaves the DC bus.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Brake {
    /// A brake resistor of this continuous power (W).
    Resistor { power: f64 },
    /// The DC bus's capacitors alone (F), up to the bus's highest voltage (V).
    Bus { capacitance: f64, voltage_max: f64 },
}

/// The user's settings of a sizing.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// The reserve every capacity check must keep, `0 <= reserve < 1` (0.2 = 20 %).
    pub reserve: f64,
    /// The dwell between repetitions of the motion (s): the duty cycle.
    pub dwell: f64,
    /// The drive amplifier, with the supply voltage the user sets.
    pub amplifier: Option<Amplifier>,
    pub brake: Option<Brake>,
    /// The required nominal life of a ball or lead screw (h of the repeated duty cycle); without
    /// it the screw's life check is not evaluated (`screw_life` missing).
    pub screw_life: Option<f64>,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings { reserve: DEFAULT_RESERVE, dwell: 0.0, amplifier: None, brake: None, screw_life: None }
    }
}

impl Settings {
    /// Every problem with the settings, naming the field (`reserve`, `dwell`, `supply_voltage`,
    /// `brake_power`, `bus_capacitance`, `bus_voltage_max`, `screw_life`).
    pub fn check(&self) -> Vec<Issue> {
        let mut out = Vec::new();
        if !(self.reserve.is_finite() && (0.0..1.0).contains(&self.reserve)) {
            out.push(Issue::new("reserve", format!("the reserve {} must be at least 0 and below 1 (0.2 = 20 %)", self.reserve)));
        }
        if !(self.dwell.is_finite() && (0.0..=MAX_DWELL).contains(&self.dwell)) {
            out.push(Issue::new("dwell", format!("the dwell {} s must be between 0 and {MAX_DWELL} s", self.dwell)));
        }
        if let Some(a) = &self.amplifier {
            if let Some(u) = a.u_supply {
                if !(u.is_finite() && u > 0.0) {
                    out.push(Issue::new("supply_voltage", format!("the supply voltage {u} V must be greater than 0")));
                } else if a.u_min.is_some_and(|lo| u < lo) || a.u_max.is_some_and(|hi| u > hi) {
                    let range = match (a.u_min, a.u_max) {
                        (Some(lo), Some(hi)) => format!("{lo} V to {hi} V"),
                        (Some(lo), None) => format!("at least {lo} V"),
                        (None, Some(hi)) => format!("at most {hi} V"),
                        (None, None) => String::new(),
                    };
                    out.push(Issue::new(
                        "supply_voltage",
                        format!("the supply voltage {u} V is outside amplifier \"{}\"'s range {range}", a.part.name),
                    ));
                }
            }
        }
        match self.brake {
            Some(Brake::Resistor { power }) if !(power.is_finite() && power > 0.0) => {
                out.push(Issue::new("brake_power", format!("the brake resistor's power {power} W must be greater than 0")))
            }
            Some(Brake::Bus { capacitance, voltage_max }) => {
                if !(capacitance.is_finite() && capacitance > 0.0) {
                    out.push(Issue::new("bus_capacitance", format!("the DC-bus capacitance {capacitance} F must be greater than 0")));
                }
                let supply = self.amplifier.as_ref().and_then(|a| a.u_supply);
                if !(voltage_max.is_finite() && voltage_max > 0.0) {
                    out.push(Issue::new("bus_voltage_max", format!("the DC bus's highest voltage {voltage_max} V must be greater than 0")));
                } else if let Some(u) = supply.filter(|u| voltage_max <= *u) {
                    out.push(Issue::new(
                        "bus_voltage_max",
                        format!("the DC bus's highest voltage {voltage_max} V must be above the supply voltage {u} V"),
                    ));
                }
            }
            _ => {}
        }
        if let Some(h) = self.screw_life.filter(|h| !(h.is_finite() && *h > 0.0 && *h <= MAX_SCREW_LIFE)) {
            out.push(Issue::new(
                "screw_life",
                format!("the required screw life {h} h must be greater than 0 and at most {MAX_SCREW_LIFE} h"),
            ));
        }
        out
    }
}

/// One driven (or undriven) joint's load over a motion.
#[derive(Clone, Copy, Debug)]
pub struct AxisLoad<'a> {
    pub joint: &'a str,
    pub kind: JointKind,
    /// Sample times (s), non-decreasing (uniform in practice).
    pub t: &'a [f64],
    /// Joint speed (rad/s or m/s) and acceleration (rad/s² or m/s²).
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
    /// Joint torque (N·m) or force (N) the drive must apply (inverse dynamics with gravity).
    pub tau: &'a [f64],
    /// Largest joint-space inertia `M_jj` over the motion (kg·m² or kg).
    pub load_inertia: f64,
}

/// A library instance named in a result.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct PartRef {
    pub id: String,
    pub name: String,
}

/// What came of a check.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Pass,
    Fail,
    /// A value it needs is missing (named in `missing`) or not given by the maker.
    NotEvaluated,
}

/// One check of a drive.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Check {
    pub check: &'static str,
    pub label: &'static str,
    /// The rule, in words.
    pub rule: &'static str,
    /// `None` when not evaluated.
    pub value: Option<f64>,
    pub limit: Option<f64>,
    pub unit: &'static str,
    /// Where the limit comes from: `motor "maxon RE 40": T_stall (datasheet)`, a setting, a rule.
    pub source: Option<String>,
    /// `(limit - value) / limit`.
    pub margin: Option<f64>,
    pub status: Status,
    /// `status != fail`.
    pub pass: bool,
    /// Whether the margin keeps the user's reserve (`None`: not evaluated, or a check the
    /// reserve does not apply to).
    pub within_reserve: Option<bool>,
    /// The values it lacks.
    pub missing: Vec<String>,
    pub detail: String,
}

/// Motor speed and torque per sample, decimated.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct OperatingPoints {
    pub t: Vec<f64>,
    /// rad/s at the motor shaft.
    pub speed: Vec<f64>,
    /// N·m at the motor shaft.
    pub torque: Vec<f64>,
}

/// The motor's limits, for drawing the operating points against.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Envelope {
    pub continuous_torque: Option<f64>,
    pub peak_torque: Option<f64>,
    pub max_speed: Option<f64>,
    /// `U_supply / k`, with an amplifier's supply voltage.
    pub no_load_speed: Option<f64>,
}

/// Where an alternative stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Standing {
    /// Every check evaluated and passed with the reserve.
    PassesWithReserve,
    /// Every check evaluated and passed, some margin below the reserve.
    Passes,
    /// Every evaluated check passes, but values are missing.
    Incomplete,
    Fails,
}

/// The check that limits a combination: its smallest margin (or the check it fails worst).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Limiting {
    pub check: &'static str,
    pub label: &'static str,
    pub margin: f64,
}

/// A real motor × gear combination of the catalogue, ranked.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Alternative {
    pub motor: PartRef,
    pub gear: PartRef,
    /// The gear's own catalogue ratio.
    pub ratio: f64,
    /// 1 = best.
    pub rank: usize,
    pub standing: Standing,
    pub pass: bool,
    /// The smallest margin of the evaluated limit checks.
    pub margin: Option<f64>,
    pub limiting: Option<Limiting>,
    /// Checks failed.
    pub failed: Vec<&'static str>,
    /// Why it ranks where it does.
    pub why: String,
    /// The ranking's keys: rotor inertia (kg·m²), mass of motor and gear (kg) and the larger
    /// price class, where known.
    pub rotor_inertia: f64,
    pub mass: Option<f64>,
    pub price_class: Option<i64>,
    /// Values the combination lacks (those checks were not evaluated).
    pub missing: Vec<String>,
}

/// The sources of the parts' values (the library instances' `source`).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Sources {
    pub motor: String,
    pub gear: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplifier: Option<String>,
}

/// The sizing of one drive: the contract's `drives[]` entry.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DriveSizing {
    pub joint: String,
    pub motor: PartRef,
    pub gear: PartRef,
    pub ratio: f64,
    /// No check fails.
    pub pass: bool,
    /// Every check evaluated, and each capacity check keeps the reserve.
    pub passes_with_reserve: bool,
    pub checks: Vec<Check>,
    pub missing: Vec<String>,
    pub sources: Sources,
    pub operating_points: OperatingPoints,
    pub envelope: Envelope,
    pub alternatives: Vec<Alternative>,
}

/// A joint without a drive: what a drive would have to deliver at the joint.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Undriven {
    pub joint: String,
    /// max `|τ|` (N·m or N), RMS of `τ` over the duty cycle, max `|q̇|` (rad/s or m/s).
    pub peak_torque: f64,
    pub rms_torque: f64,
    pub max_speed: f64,
    /// The joint's effort limit from the source (URDF), and whether the peak stays within it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effort_limit: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub within_effort: Option<bool>,
}

/// The check of a joint's load against the effort limit its source states (URDF `<limit
/// effort>`): the peak `|τ|` at the joint, whatever drives it.
pub fn effort_check(kind: JointKind, tau: &[f64], effort: f64) -> Check {
    let peak = tau.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let unit = if kind == JointKind::Prismatic { "N" } else { "N·m" };
    let pass = peak <= effort;
    Check {
        check: "joint-effort",
        label: "Joint effort limit (source)",
        rule: "max |τ| at the joint <= the effort limit the model's source states",
        value: Some(peak),
        limit: Some(effort),
        unit,
        source: Some("the joint's <limit effort> in the source".to_string()),
        margin: (effort > 0.0).then(|| (effort - peak) / effort),
        status: if pass { Status::Pass } else { Status::Fail },
        pass,
        within_reserve: None,
        missing: Vec::new(),
        detail: format!("peak joint load {peak:.4} {unit} against the effort limit {effort} {unit} the source states"),
    }
}

// ---------------------------------------------------------------------------------------------
// The axis, checked once

/// An axis with its integration weights and joint-side figures over the duty cycle.
struct Axis<'a> {
    load: AxisLoad<'a>,
    /// Trapezoidal weights (s); their sum is the motion's duration (1 per sample for a single
    /// instant).
    w: Vec<f64>,
    /// The motion's duration, the dwell and the period `motion + dwell`.
    motion: f64,
    dwell: f64,
    period: f64,
    /// Whether every step has the same length (the thermal model's decay is then one number).
    uniform: bool,
    /// The joint's holding torque during the dwell (the last sample's).
    tau_hold: f64,
    /// The joint's travel over one motion, `Σ|q̇|·Δt` (rad or m).
    travel: f64,
    peak_tau: (f64, usize),
    rms_tau: f64,
    /// Harmonic Drive's average output torque, `None` when the joint never moves.
    avg_tau: Option<f64>,
    max_qd: (f64, usize),
}

fn kind_name(k: JointKind) -> &'static str {
    match k {
        JointKind::Revolute => "revolute",
        JointKind::Prismatic => "prismatic",
    }
}

impl<'a> Axis<'a> {
    fn new(load: AxisLoad<'a>, dwell: f64) -> Result<Axis<'a>, SizingError> {
        let bad = |reason: String| SizingError::BadLoad { joint: load.joint.to_string(), reason };
        let n = load.t.len();
        if n == 0 {
            return Err(bad("the motion has no samples".into()));
        }
        for (what, s) in [("qd", load.qd), ("qdd", load.qdd), ("tau", load.tau)] {
            if s.len() != n {
                return Err(bad(format!("{what} has {} samples, t has {n}", s.len())));
            }
        }
        for (what, s) in [("t", load.t), ("qd", load.qd), ("qdd", load.qdd), ("tau", load.tau)] {
            if let Some(i) = s.iter().position(|x| !x.is_finite()) {
                return Err(bad(format!("{what}[{i}] = {} is not a finite number", s[i])));
            }
        }
        if let Some(i) = load.t.windows(2).position(|w| w[1] < w[0]) {
            return Err(bad(format!("time goes back at sample {}", i + 1)));
        }
        if !(load.load_inertia.is_finite() && load.load_inertia >= 0.0) {
            return Err(bad(format!("the load inertia {} must be a finite number of at least 0", load.load_inertia)));
        }
        if !(dwell.is_finite() && dwell >= 0.0) {
            return Err(bad(format!("the dwell {dwell} s must be a finite number of at least 0")));
        }
        let mut w = vec![0.0; n];
        for i in 0..n.saturating_sub(1) {
            let h = 0.5 * (load.t[i + 1] - load.t[i]);
            w[i] += h;
            w[i + 1] += h;
        }
        let mut motion: f64 = w.iter().sum();
        if motion <= 0.0 {
            // One sample, or all at one instant: plain averages.
            w.iter_mut().for_each(|x| *x = 1.0);
            motion = n as f64;
        }
        let h0 = if n > 1 { load.t[1] - load.t[0] } else { 0.0 };
        let uniform = load.t.windows(2).all(|p| ((p[1] - p[0]) - h0).abs() <= 1e-9 * h0.abs().max(1e-300));
        let period = motion + dwell;
        let tau_hold = load.tau[n - 1];
        let peak_tau = argmax_abs(load.tau);
        let sum2 = load.tau.iter().zip(&w).map(|(x, w)| x * x * w).sum::<f64>() + tau_hold * tau_hold * dwell;
        let rms_tau = (sum2 / period).sqrt();
        let (mut num, mut den) = (0.0, 0.0);
        for ((qd, tau), w) in load.qd.iter().zip(load.tau).zip(&w) {
            let v = qd.abs() * w;
            num += v * tau.abs().powi(3);
            den += v;
        }
        let avg_tau = (den > 0.0).then(|| (num / den).cbrt());
        let max_qd = argmax_abs(load.qd);
        Ok(Axis { load, w, motion, dwell, period, uniform, tau_hold, peak_tau, rms_tau, avg_tau, travel: den, max_qd })
    }

    fn at(&self, i: usize) -> String {
        format!("at t = {} s", short(self.load.t[i]))
    }
}

fn argmax_abs(x: &[f64]) -> (f64, usize) {
    let mut best = (0.0, 0);
    for (i, v) in x.iter().enumerate() {
        if v.abs() > best.0 {
            best = (v.abs(), i);
        }
    }
    best
}

/// A number for messages: 4 significant digits.
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

// ---------------------------------------------------------------------------------------------
// Reflection through the gear

/// The motor-side load of one gear on one axis, per sample, without the motor's own terms:
/// `T_m = base + J_motor·acc + d·speed`.
struct GearSide {
    n: f64,
    /// Motor speed `n·q̇` (rad/s).
    speed: Vec<f64>,
    /// `n·q̈` (rad/s²).
    acc: Vec<f64>,
    /// Load torque at the motor plus the gear's input inertia term; `None` without `J_in`.
    base: Option<Vec<f64>>,
    /// The motor torque holding the last pose during the dwell (`τ_hold/(n·η)`).
    hold: f64,
    max_speed: (f64, usize),
}

impl GearSide {
    fn new(axis: &Axis, gear: &Gear) -> GearSide {
        let n = gear.transmission(gear.ratio);
        let l = &axis.load;
        let speed: Vec<f64> = l.qd.iter().map(|q| n * q).collect();
        let acc: Vec<f64> = l.qdd.iter().map(|q| n * q).collect();
        let base = gear.j_in.map(|j_in| {
            (0..l.t.len())
                .map(|i| {
                    let (tau, qd) = (l.tau[i], l.qd[i]);
                    // Efficiency in the direction of power flow: the motor pays the losses both ways.
                    let load = if tau * qd >= 0.0 { tau / (n * gear.eta) } else { tau * gear.eta / n };
                    load + j_in * acc[i]
                })
                .collect()
        });
        let max_speed = argmax_abs(&speed);
        GearSide { n, speed, acc, base, hold: axis.tau_hold / (n * gear.eta), max_speed }
    }

    #[inline]
    fn torque(&self, base: &[f64], motor: &Motor, i: usize) -> f64 {
        base[i] + motor.j * self.acc[i] + motor.d * self.speed[i]
    }
}

/// The motor-side figures of one combination over the duty cycle.
#[derive(Clone, Copy, Debug, Default)]
struct Stats {
    peak_t: (f64, usize),
    /// ∫ T_m² dt over the period.
    sum_t2: f64,
    max_u: (f64, usize),
    /// Energy fed back (J, >= 0): in the largest braking interval, and per cycle.
    e_interval: f64,
    e_cycle: f64,
    /// The sample where the largest braking interval ends.
    e_at: usize,
    /// Thermally equivalent torque (N·m), with the winding's time constant.
    thermal: Option<f64>,
}

fn reflect(axis: &Axis, side: &GearSide, base: &[f64], motor: &Motor, t2: &mut Vec<f64>) -> Stats {
    let mut s = Stats::default();
    // Without a winding resistance (AC servo datasheets give none) the copper losses count as 0:
    // the voltage and braking checks that need them are then not evaluated.
    let r = motor.r.unwrap_or(0.0);
    let (r_k, k, r_k2) = (r / motor.k, motor.k, r / (motor.k * motor.k));
    let mut run = 0.0;
    let tau_th = motor.tau_th_w.filter(|x| *x > 0.0 && motor.t_nom.is_some());
    t2.clear();
    for i in 0..axis.w.len() {
        let t = side.torque(base, motor, i);
        if tau_th.is_some() {
            t2.push(t * t);
        }
        let w = side.speed[i];
        let (ta, ua) = (t.abs(), (r_k * t + k * w).abs());
        if ta > s.peak_t.0 {
            s.peak_t = (ta, i);
        }
        if ua > s.max_u.0 {
            s.max_u = (ua, i);
        }
        s.sum_t2 += t * t * axis.w[i];
        let p = t * w + r_k2 * t * t;
        if p < 0.0 {
            run -= p * axis.w[i];
            s.e_cycle -= p * axis.w[i];
        } else if run > 0.0 {
            if run > s.e_interval {
                s.e_interval = run;
                s.e_at = i;
            }
            run = 0.0;
        }
    }
    if run > s.e_interval {
        s.e_interval = run;
        s.e_at = axis.w.len() - 1;
    }
    if axis.dwell > 0.0 {
        let h = side.hold;
        if h.abs() > s.peak_t.0 {
            s.peak_t = (h.abs(), axis.w.len() - 1);
        }
        if (r_k * h).abs() > s.max_u.0 {
            s.max_u = ((r_k * h).abs(), axis.w.len() - 1);
        }
        s.sum_t2 += h * h * axis.dwell;
    }
    if let Some(tau) = tau_th {
        s.thermal = Some(thermal(axis, side.hold, t2, tau));
    }
    s
}

/// The winding's temperature rise as a first-order lag of `T_m²` (`τ_w·θ' = T_m² - θ`, `T_m²`
/// linear between samples' mean over each step), in the periodic steady state of the duty
/// cycle: `sqrt(max θ)`, the torque that would heat the winding as much if held constant.
/// `t2` holds `T_m²` per sample.
fn thermal(axis: &Axis, hold: f64, t2: &[f64], tau: f64) -> f64 {
    let t = axis.load.t;
    let n = t2.len();
    let decay = |h: f64| (-h / tau).exp();
    let a_uniform = if n > 1 { decay(t[1] - t[0]) } else { 1.0 };
    let step = |i: usize| if axis.uniform { a_uniform } else { decay(t[i + 1] - t[i]) };
    let a_dwell = decay(axis.dwell);
    // One period from θ = 0; the response is linear in the start value, so the periodic start
    // is θ_0 = y(P) / (1 - e^(-P/τ)).
    let mut y = 0.0;
    for i in 0..n - 1 {
        let a = step(i);
        y = a * y + (1.0 - a) * 0.5 * (t2[i] + t2[i + 1]);
    }
    y = a_dwell * y + (1.0 - a_dwell) * hold * hold;
    let whole = decay(axis.period);
    let theta0 = if whole < 1.0 { y / (1.0 - whole) } else { y };
    // The cycle again from θ_0, keeping the largest θ (during the dwell θ moves monotonically
    // towards the holding torque's square, so its ends bound it).
    let mut x = theta0;
    let mut max = x;
    for i in 0..n - 1 {
        let a = step(i);
        x = a * x + (1.0 - a) * 0.5 * (t2[i] + t2[i + 1]);
        max = max.max(x);
    }
    max.max(0.0).sqrt()
}

// ---------------------------------------------------------------------------------------------
// Checks

struct Outcome {
    checks: Vec<Check>,
    missing: Vec<String>,
}

/// Rules, as the `rule` field states them.
mod rule {
    pub const PEAK: &str =
        "max |T_m| <= the motor's short-time torque limit T_peak, else its stall torque T_stall (same rule for every motor class)";
    pub const RMS: &str = "sqrt(∫T_m² dt / T_cycle) over the duty cycle (motion + dwell holding the last pose) <= T_nom";
    pub const THERMAL: &str =
        "sqrt(max θ), θ the winding's first-order response τ_w·θ' = T_m² - θ in the periodic steady state of the duty cycle, <= T_nom";
    pub const SPEED: &str = "max |ω_m| <= the motor's maximum permissible speed w_max";
    pub const VOLTAGE: &str = "max |R·T_m/k + k·ω_m| <= the supply voltage set for the amplifier";
    pub const PEAK_CURRENT: &str = "max |T_m/k| <= the amplifier's peak output current I_peak";
    pub const RMS_CURRENT: &str = "RMS of T_m/k over the duty cycle <= the amplifier's continuous output current I_cont";
    pub const GEAR_SPEED: &str = "max |ω_m| <= the gear's maximum input speed w_in_max";
    pub const GEAR_PEAK: &str = "max |τ| at the output <= the gear's repeated-peak limit T_peak";
    pub const SCREW_STATIC: &str = "max |F| at the nut <= the screw's basic static axial load rating C_0a (ISO 3408-5; the user's reserve is the static safety factor: 20 % reserve = f_s 1.25), else a library's older axial force limit F_peak";
    pub const SCREW_LIFE: &str = "cubic-mean axial force F_m = (Σ|v|·|F|³·Δt / Σ|v|·Δt)^(1/3) <= C_a·(10⁶/L_req)^(1/3): the nominal life L10 = (C_a/F_m)³·10⁶ screw revolutions (ISO 3408-5, load factor 1) covers L_req, the revolutions of the required life screw_life (h of the repeated duty cycle)";
    pub const GEAR_RMS: &str = "RMS of τ over the duty cycle <= the gear's rated (continuous) output torque T_rated";
    pub const GEAR_AVG: &str = "(Σ|q̇|·|τ|³·Δt / Σ|q̇|·Δt)^(1/3) <= the gear's limit for average torque T_avg_max, where given";
    pub const INERTIA: &str =
        "(J_load/n² + J_gear,in) / J_motor <= 10: the gear's input inertia counted on the load side; the reserve does not apply";
    pub const BRAKING: &str = "DC bus: the largest energy fed back in one braking interval <= C·(U_max² - U_supply²)/2; brake resistor: energy fed back per cycle / T_cycle <= its continuous power";
}

/// What a check needs and what it found.
struct Spec {
    check: &'static str,
    label: &'static str,
    rule: &'static str,
    unit: &'static str,
    /// Whether the user's reserve applies.
    reserve: bool,
}

impl Outcome {
    fn pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }

    fn with_reserve(&self) -> bool {
        self.missing.is_empty() && self.checks.iter().all(|c| c.pass && c.within_reserve != Some(false))
    }

    /// The limiting check: the one failed worst, else the smallest margin.
    fn limiting(&self) -> Option<Limiting> {
        self.checks.iter().filter_map(|c| c.margin.map(|m| (c, m))).min_by(|a, b| a.1.total_cmp(&b.1)).map(|(c, m)| Limiting {
            check: c.check,
            label: c.label,
            margin: m,
        })
    }

    fn need(&mut self, names: &[&str]) {
        for n in names {
            if !self.missing.iter().any(|m| m == n) {
                self.missing.push(n.to_string());
            }
        }
    }

    fn not_evaluated(&mut self, spec: Spec, missing: &[&str], detail: String) {
        self.need(missing);
        self.checks.push(Check {
            check: spec.check,
            label: spec.label,
            rule: spec.rule,
            value: None,
            limit: None,
            unit: spec.unit,
            source: None,
            margin: None,
            status: Status::NotEvaluated,
            pass: true,
            within_reserve: None,
            missing: missing.iter().map(|m| m.to_string()).collect(),
            detail,
        });
    }

    /// A check of `value` against `limit` (from `source`), or not evaluated with what is
    /// missing.
    #[allow(clippy::too_many_arguments)]
    fn limit(
        &mut self,
        spec: Spec,
        value: Option<f64>,
        limit: Option<f64>,
        source: impl FnOnce() -> String,
        missing: &[&str],
        reserve: f64,
        detail: String,
    ) {
        let (Some(value), Some(limit)) = (value, limit) else {
            let missing: Vec<&str> = missing.to_vec();
            self.not_evaluated(spec, &missing, detail);
            return;
        };
        let margin = if limit > 0.0 {
            (limit - value) / limit
        } else if value > 0.0 {
            f64::NEG_INFINITY
        } else {
            0.0
        };
        // An infinite margin cannot be written as JSON: clamp to the worst finite one.
        let margin = margin.max(-f64::MAX);
        let pass = value <= limit;
        self.checks.push(Check {
            check: spec.check,
            label: spec.label,
            rule: spec.rule,
            value: Some(value),
            limit: Some(limit),
            unit: spec.unit,
            source: Some(source()),
            margin: Some(margin),
            status: if pass { Status::Pass } else { Status::Fail },
            pass,
            within_reserve: spec.reserve.then_some(pass && margin >= reserve),
            missing: Vec::new(),
            detail,
        });
    }
}

/// The screw's nominal life (ISO 3408-5 and the screw makers' catalogues): `L10 = (C_a/F_m)³·10⁶`
/// revolutions under the cubic-mean axial force `F_m` (weighted by the screw's speed), against
/// the revolutions of the required life `screw_life` (hours of the repeated duty cycle), checked
/// as a force: `F_m <= C_a·(10⁶/L_req)^(1/3)`, so the reserve is a reserve of load as elsewhere.
fn screw_life(o: &mut Outcome, axis: &Axis, gear: &Gear, gname: &str, lead: f64, settings: &Settings) {
    let spec =
        Spec { check: "screw_life", label: "Screw nominal life (dynamic load rating)", rule: rule::SCREW_LIFE, unit: "N", reserve: true };
    let Some(f_m) = axis.avg_tau else {
        o.not_evaluated(spec, &[], "the joint never moves: the screw does not turn, so it does not wear".to_string());
        return;
    };
    // Screw revolutions per cycle (the gear ratio in front of the screw does not change them).
    let revs = axis.travel / lead.abs();
    let (Some(c_a), Some(hours)) = (gear.c_a, settings.screw_life) else {
        let mut missing = Vec::new();
        if gear.c_a.is_none() {
            missing.push("gear.C_a");
        }
        if settings.screw_life.is_none() {
            missing.push("screw_life");
        }
        o.not_evaluated(spec, &missing, format!("F_m = {} N over {} screw revolutions per cycle", short(f_m), short(revs)));
        return;
    };
    let required = hours * 3600.0 / axis.period * revs;
    let allowed = c_a * (1e6 / required).cbrt();
    let l10 = if f_m > 0.0 { (c_a / f_m).powi(3) * 1e6 } else { f64::INFINITY };
    let l10_h = l10 / revs * axis.period / 3600.0;
    o.limit(
        spec,
        Some(f_m),
        Some(allowed),
        || format!("gear \"{gname}\": C_a (datasheet) and setting screw_life {} h", short(hours)),
        &[],
        settings.reserve,
        format!(
            "L10 = (C_a/F_m)³·10⁶ = {} revolutions = {} h of the duty cycle ({} screw revolutions per cycle of {} s); required {} h = {} revolutions",
            short(l10),
            short(l10_h),
            short(revs),
            short(axis.period),
            short(hours),
            short(required)
        ),
    );
}

fn of(slot: &str, name: &str, param: &str) -> String {
    format!("{slot} \"{name}\": {param} (datasheet)")
}

/// Evaluates every check of one combination (the gear at its own ratio, `side` made for it).
fn evaluate(axis: &Axis, side: &GearSide, motor: &Motor, gear: &Gear, settings: &Settings, scratch: &mut Vec<f64>) -> Outcome {
    let mut o = Outcome { checks: Vec::with_capacity(14), missing: Vec::new() };
    let reserve = settings.reserve;
    let stats = side.base.as_deref().map(|b| reflect(axis, side, b, motor, scratch));
    let no_j_in: &[&str] = &["gear.J_in"];
    let (mname, gname) = (motor.part.name.as_str(), gear.part.name.as_str());
    let without_j_in = || "not evaluated: the motor torque includes the gear's input inertia, which the library lacks".to_string();
    let (out_unit, out_what) = match gear.lead {
        Some(_) => ("N", "force"),
        None => ("N.m", "torque"),
    };

    // Motor torque.
    let peak = motor.peak_rule();
    let spec = Spec { check: "peak_torque", label: "Peak motor torque", rule: rule::PEAK, unit: "N.m", reserve: true };
    match (&stats, peak) {
        (None, _) => o.not_evaluated(spec, no_j_in, without_j_in()),
        (Some(s), peak) => o.limit(
            spec,
            Some(s.peak_t.0),
            peak.map(PeakRule::value),
            || of("motor", mname, peak.map_or("", PeakRule::parameter)),
            &["motor.T_peak or motor.T_stall"],
            reserve,
            match peak {
                Some(PeakRule::ShortTime(_)) => format!("{}; limit: the maker's short-time torque limit T_peak", axis.at(s.peak_t.1)),
                Some(PeakRule::Stall(_)) => {
                    format!("{}; limit: the stall torque T_stall (the maker states no short-time limit)", axis.at(s.peak_t.1))
                }
                None => "the library has neither T_peak nor T_stall for the motor".to_string(),
            },
        ),
    }
    let duty = if axis.dwell > 0.0 {
        format!("over the duty cycle of {} s (motion {} s + dwell {} s)", short(axis.period), short(axis.motion), short(axis.dwell))
    } else {
        format!("over the motion of {} s, repeated without dwell", short(axis.motion))
    };
    let spec = Spec { check: "rms_torque", label: "RMS motor torque", rule: rule::RMS, unit: "N.m", reserve: true };
    match &stats {
        None => o.not_evaluated(spec, no_j_in, without_j_in()),
        Some(s) => o.limit(
            spec,
            Some((s.sum_t2 / axis.period).sqrt()),
            motor.t_nom,
            || of("motor", mname, "T_nom"),
            &["motor.T_nom"],
            reserve,
            format!("{duty}; limit: nominal (continuous) torque"),
        ),
    }
    let spec = Spec { check: "thermal_torque", label: "Thermal torque (winding)", rule: rule::THERMAL, unit: "N.m", reserve: true };
    match (&stats, motor.tau_th_w) {
        (None, _) => o.not_evaluated(spec, no_j_in, without_j_in()),
        (Some(_), None) => o.not_evaluated(spec, &[], "the maker gives no thermal time constant of the winding (tau_th_w)".to_string()),
        (Some(s), Some(tau)) => o.limit(
            spec,
            s.thermal,
            motor.t_nom,
            || of("motor", mname, "T_nom"),
            &["motor.T_nom"],
            reserve,
            format!("{duty}; winding time constant {} s", short(tau)),
        ),
    }
    o.limit(
        Spec { check: "motor_speed", label: "Maximum motor speed", rule: rule::SPEED, unit: "rad/s", reserve: true },
        Some(side.max_speed.0),
        motor.w_max,
        || of("motor", mname, "w_max"),
        &["motor.w_max"],
        reserve,
        axis.at(side.max_speed.1),
    );

    // The amplifier.
    let amp = settings.amplifier.as_ref();
    let aname = amp.map_or("", |a| a.part.name.as_str());
    let supply = amp.and_then(|a| a.u_supply);
    let spec = Spec { check: "voltage", label: "Motor voltage U = R·I + k·ω", rule: rule::VOLTAGE, unit: "V", reserve: true };
    match (&stats, amp) {
        (None, _) => o.not_evaluated(spec, no_j_in, without_j_in()),
        (Some(_), _) if motor.r.is_none() => o.not_evaluated(spec, &["motor.R"], NO_R.to_string()),
        (Some(_), None) => o.not_evaluated(spec, &["amplifier"], "no amplifier set".to_string()),
        (Some(s), Some(_)) => o.limit(
            spec,
            Some(s.max_u.0),
            supply,
            || format!("setting supply_voltage (amplifier \"{aname}\")"),
            &["supply_voltage"],
            reserve,
            axis.at(s.max_u.1),
        ),
    }
    for (check, label, r, value, limit, param) in [
        (
            "peak_current",
            "Peak motor current",
            rule::PEAK_CURRENT,
            stats.map(|s| s.peak_t.0 / motor.k),
            amp.and_then(|a| a.i_peak),
            "I_peak",
        ),
        (
            "rms_current",
            "RMS motor current",
            rule::RMS_CURRENT,
            stats.map(|s| (s.sum_t2 / axis.period).sqrt() / motor.k),
            amp.and_then(|a| a.i_cont),
            "I_cont",
        ),
    ] {
        let spec = Spec { check, label, rule: r, unit: "A", reserve: true };
        match (&stats, amp) {
            (None, _) => o.not_evaluated(spec, no_j_in, without_j_in()),
            (Some(_), None) => o.not_evaluated(spec, &["amplifier"], "no amplifier set".to_string()),
            (Some(_), Some(_)) => {
                let missing = format!("amplifier.{param}");
                o.limit(
                    spec,
                    value,
                    limit,
                    || of("amplifier", aname, param),
                    &[missing.as_str()],
                    reserve,
                    format!("I = T_m/k, k = {} N·m/A", short(motor.k)),
                )
            }
        }
    }

    // The gear.
    o.limit(
        Spec { check: "gear_input_speed", label: "Gear input speed", rule: rule::GEAR_SPEED, unit: "rad/s", reserve: true },
        Some(side.max_speed.0),
        gear.w_in_max,
        || of("gear", gname, "w_in_max"),
        &["gear.w_in_max"],
        reserve,
        axis.at(side.max_speed.1),
    );
    let missing_peak = format!("gear.{}", gear.out_peak_name());
    o.limit(
        match gear.lead {
            Some(_) => Spec {
                check: "screw_static_load",
                label: "Peak axial force (static load rating)",
                rule: rule::SCREW_STATIC,
                unit: out_unit,
                reserve: true,
            },
            None => {
                Spec { check: "gear_peak_torque", label: "Peak gear output torque", rule: rule::GEAR_PEAK, unit: out_unit, reserve: true }
            }
        },
        Some(axis.peak_tau.0),
        gear.out_peak,
        || of("gear", gname, gear.out_peak_name()),
        &[missing_peak.as_str()],
        reserve,
        format!("{}; output {out_what} = joint {out_what}", axis.at(axis.peak_tau.1)),
    );
    if let Some(lead) = gear.lead {
        screw_life(&mut o, axis, gear, gname, lead, settings);
    }
    if gear.lead.is_none() {
        o.limit(
            Spec { check: "gear_rms_torque", label: "RMS gear output torque", rule: rule::GEAR_RMS, unit: "N.m", reserve: true },
            Some(axis.rms_tau),
            gear.t_rated,
            || of("gear", gname, "T_rated"),
            &["gear.T_rated"],
            reserve,
            format!("{duty}; limit: rated (continuous) output torque"),
        );
        let spec = Spec { check: "gear_avg_torque", label: "Average gear output torque", rule: rule::GEAR_AVG, unit: "N.m", reserve: true };
        match (gear.t_avg_max, axis.avg_tau) {
            (None, _) => o.not_evaluated(spec, &[], "the maker gives no limit for the average torque (T_avg_max)".to_string()),
            (Some(_), None) => o.not_evaluated(spec, &[], "the joint never moves: no average torque".to_string()),
            (Some(lim), Some(v)) => o.limit(
                spec,
                Some(v),
                Some(lim),
                || of("gear", gname, "T_avg_max"),
                &[],
                reserve,
                "weighted by the output speed".to_string(),
            ),
        }
    }
    if gear.ratio != gear.catalog_ratio {
        o.need(&["gear ratings at the overridden ratio"]);
    }

    // Inertia ratio, the gear's input inertia on the load side.
    let spec = Spec {
        check: "inertia_ratio",
        label: "Inertia ratio (J_load/n² + J_gear,in) / J_motor",
        rule: rule::INERTIA,
        unit: "1",
        reserve: false,
    };
    match gear.j_in {
        None => o.not_evaluated(spec, no_j_in, "the gear's input inertia belongs to the load side; the library lacks it".to_string()),
        Some(j_in) => {
            let n = side.n;
            let value = if motor.j > 0.0 { (axis.load.load_inertia / (n * n) + j_in) / motor.j } else { f64::MAX };
            let quality = if value <= INERTIA_RATIO_GOOD {
                "good (≤ 3)"
            } else if value <= 5.0 {
                "common (3–5)"
            } else if value <= INERTIA_RATIO_LIMIT {
                "needs stiff mechanics (5–10)"
            } else {
                "risky (> 10)"
            };
            o.limit(
                spec,
                Some(value),
                Some(INERTIA_RATIO_LIMIT),
                || "rule of thumb: ≤ 3 good, 3–5 common, 5–10 needs stiff mechanics, > 10 risky".to_string(),
                &[],
                reserve,
                format!("{quality}; J_load = max M_jj over the motion; convention: the gear's input inertia on the load side"),
            );
        }
    }

    // Braking.
    let spec = Spec { check: "braking", label: "Braking energy", rule: rule::BRAKING, unit: "J", reserve: true };
    match &stats {
        None => o.not_evaluated(spec, no_j_in, without_j_in()),
        Some(s) if s.e_cycle <= 0.0 => o.checks.push(Check {
            check: spec.check,
            label: spec.label,
            rule: spec.rule,
            value: Some(0.0),
            limit: None,
            unit: spec.unit,
            source: None,
            margin: None,
            status: Status::Pass,
            pass: true,
            within_reserve: None,
            missing: Vec::new(),
            detail: "the motor never feeds energy back: no brake resistor or bus capacity needed".to_string(),
        }),
        Some(_) if motor.r.is_none() => o.not_evaluated(spec, &["motor.R"], NO_R.to_string()),
        Some(s) => match settings.brake {
            None => o.not_evaluated(
                spec,
                &["brake (resistor power or DC-bus capacitance)"],
                format!(
                    "the motor feeds {} J back per cycle ({} J in the largest braking interval)",
                    short(s.e_cycle),
                    short(s.e_interval)
                ),
            ),
            Some(Brake::Bus { capacitance, voltage_max }) => o.limit(
                Spec { label: "Braking energy per interval (DC bus)", ..spec },
                Some(s.e_interval),
                supply.map(|u| 0.5 * capacitance * (voltage_max * voltage_max - u * u)),
                || format!("settings bus_capacitance {capacitance} F, bus_voltage_max {voltage_max} V, supply_voltage"),
                &[if amp.is_none() { "amplifier" } else { "supply_voltage" }],
                reserve,
                format!("the largest braking interval ends {}; {} J per cycle", axis.at(s.e_at), short(s.e_cycle)),
            ),
            Some(Brake::Resistor { power }) => o.limit(
                Spec { label: "Mean braking power (brake resistor)", unit: "W", ..spec },
                Some(s.e_cycle / axis.period),
                Some(power),
                || format!("setting brake_power {power} W"),
                &[],
                reserve,
                format!("{} J fed back per cycle {duty}", short(s.e_cycle)),
            ),
        },
    }
    o
}

/// Keeps at most [`MAX_POINTS`] samples: the samples are cut into buckets and each bucket keeps
/// its smallest and largest torque and speed, so every extreme of the cycle stays. Empty when
/// the motor torque cannot be computed (no gear `J_in`).
fn operating_points(axis: &Axis, side: &GearSide, motor: &Motor) -> OperatingPoints {
    let Some(base) = side.base.as_deref() else { return OperatingPoints::default() };
    let len = axis.w.len();
    let points: Vec<(f64, f64)> = (0..len).map(|i| (side.speed[i], side.torque(base, motor, i))).collect();
    let mut keep: Vec<usize> = Vec::new();
    if len <= MAX_POINTS {
        keep.extend(0..len);
    } else {
        let buckets = MAX_POINTS / 4;
        let size = len.div_ceil(buckets);
        for start in (0..len).step_by(size) {
            let end = (start + size).min(len);
            let by = |f: fn(&(f64, f64)) -> f64, max: bool| {
                (start..end)
                    .max_by(|a, b| {
                        let (x, y) = (f(&points[*a]), f(&points[*b]));
                        if max {
                            x.total_cmp(&y)
                        } else {
                            y.total_cmp(&x)
                        }
                    })
                    .unwrap_or(start)
            };
            let mut idx = [by(|p| p.0, false), by(|p| p.0, true), by(|p| p.1, false), by(|p| p.1, true)];
            idx.sort_unstable();
            for i in idx {
                if keep.last() != Some(&i) {
                    keep.push(i);
                }
            }
        }
    }
    OperatingPoints {
        t: keep.iter().map(|&i| axis.load.t[i]).collect(),
        speed: keep.iter().map(|&i| points[i].0).collect(),
        torque: keep.iter().map(|&i| points[i].1).collect(),
    }
}

fn check_fit(axis: &Axis, gear: &Gear) -> Result<(), SizingError> {
    if gear.fits() != axis.load.kind {
        return Err(SizingError::GearDoesNotFit {
            joint: axis.load.joint.to_string(),
            gear: gear.part.name.clone(),
            fits: kind_name(gear.fits()),
            kind: kind_name(axis.load.kind),
        });
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Public entry points

/// Sizes the drive of one joint (motor and gear with the drive's overrides applied) under the
/// user's settings and, with a catalog, ranks the `top` best real combinations of the library
/// for the same joint.
pub fn size_drive(
    load: AxisLoad,
    motor: &Motor,
    gear: &Gear,
    catalog: Option<&Catalog>,
    settings: &Settings,
    top: usize,
) -> Result<DriveSizing, SizingError> {
    let axis = Axis::new(load, settings.dwell)?;
    check_fit(&axis, gear)?;
    let side = GearSide::new(&axis, gear);
    let o = evaluate(&axis, &side, motor, gear, settings, &mut Vec::new());
    let alternatives = match catalog {
        Some(c) => rank_axis(&axis, c, settings, top),
        None => Vec::new(),
    };
    Ok(DriveSizing {
        joint: load.joint.to_string(),
        motor: motor.part.clone(),
        gear: gear.part.clone(),
        ratio: gear.ratio,
        pass: o.pass(),
        passes_with_reserve: o.with_reserve(),
        operating_points: operating_points(&axis, &side, motor),
        envelope: Envelope {
            continuous_torque: motor.t_nom,
            peak_torque: motor.peak_rule().map(PeakRule::value),
            max_speed: motor.w_max,
            no_load_speed: settings.amplifier.as_ref().and_then(|a| a.u_supply).map(|u| u / motor.k),
        },
        sources: Sources {
            motor: motor.source.clone(),
            gear: gear.source.clone(),
            amplifier: settings.amplifier.as_ref().map(|a| a.source.clone()),
        },
        checks: o.checks,
        missing: o.missing,
        alternatives,
    })
}

/// One drive to size: the joint's load with the drive's motor and gear (overrides applied).
pub struct DriveJob<'a> {
    pub load: AxisLoad<'a>,
    pub motor: Motor,
    pub gear: Gear,
}

/// [`size_drive`] for several drives at once, on up to `threads` threads (each takes the next
/// drive not yet taken; at most one thread per drive). The results are in the order of `jobs`
/// and the same as sizing them one by one: the drives share nothing but the catalog.
pub fn size_drives(
    jobs: &[DriveJob],
    catalog: Option<&Catalog>,
    settings: &Settings,
    top: usize,
    threads: usize,
) -> Vec<Result<DriveSizing, SizingError>> {
    crate::par::map_ordered(jobs, threads, || (), |_, j| size_drive(j.load, &j.motor, &j.gear, catalog, settings, top))
}

/// The number of threads [`size_drives`] should use on this machine: its cores, at most 4.
pub fn sizing_threads() -> usize {
    crate::par::threads(4)
}

/// The `top` best real motor × gear combinations of `catalog` for a joint (see the module doc
/// for the order).
pub fn rank(load: AxisLoad, catalog: &Catalog, settings: &Settings, top: usize) -> Result<Vec<Alternative>, SizingError> {
    Ok(rank_axis(&Axis::new(load, settings.dwell)?, catalog, settings, top))
}

fn ordinal(i: usize) -> String {
    let suffix = match (i % 10, i % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{i}{suffix}")
}

/// The margin `(limit - value)/limit` as the checks write it.
fn margin_of(value: f64, limit: f64) -> f64 {
    if limit > 0.0 {
        (limit - value) / limit
    } else if value > 0.0 {
        -f64::MAX
    } else {
        0.0
    }
}

/// The smallest margin of the checks that need no pass over the samples (motor and gear input
/// speed, the gear's output torques, the inertia ratio): an upper bound of the combination's
/// smallest margin; below 0, the combination fails.
fn cheap_margin(axis: &Axis, side: &GearSide, motor: &Motor, gear: &Gear) -> f64 {
    let mut m = f64::INFINITY;
    let mut check = |v: f64, l: Option<f64>| {
        if let Some(l) = l {
            m = m.min(margin_of(v, l));
        }
    };
    check(side.max_speed.0, motor.w_max);
    check(side.max_speed.0, gear.w_in_max);
    check(axis.peak_tau.0, gear.out_peak);
    if gear.lead.is_none() {
        check(axis.rms_tau, gear.t_rated);
        if let Some(v) = axis.avg_tau {
            check(v, gear.t_avg_max);
        }
    }
    if let Some(j_in) = gear.j_in {
        let ratio = if motor.j > 0.0 { (axis.load.load_inertia / (side.n * side.n) + j_in) / motor.j } else { f64::MAX };
        check(ratio, Some(INERTIA_RATIO_LIMIT));
    }
    m
}

fn rank_axis<'c>(axis: &Axis, catalog: &'c Catalog, settings: &Settings, top: usize) -> Vec<Alternative> {
    struct Found<'c> {
        motor: &'c Motor,
        gear: &'c Gear,
        standing: Standing,
        margin: Option<f64>,
        limiting: Option<Limiting>,
        failed: Vec<&'static str>,
        mass: Option<f64>,
        price: Option<i64>,
        missing: Vec<String>,
    }
    // Known before unknown, then ascending.
    fn known<T: PartialOrd>(a: Option<T>, b: Option<T>) -> std::cmp::Ordering {
        match (a, b) {
            (Some(x), Some(y)) => x.partial_cmp(&y).unwrap_or(std::cmp::Ordering::Equal),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => std::cmp::Ordering::Equal,
        }
    }
    // The order within a standing: the smallest first.
    let smaller = |am: &Motor, ag: &Gear, bm: &Motor, bg: &Gear| {
        let mass = |m: &Motor, g: &Gear| m.mass.zip(g.mass).map(|(a, b)| a + b);
        let price = |m: &Motor, g: &Gear| m.price_class.zip(g.price_class).map(|(a, b)| a.max(b));
        am.j.total_cmp(&bm.j)
            .then_with(|| known(mass(am, ag), mass(bm, bg)))
            .then_with(|| known(price(am, ag), price(bm, bg)))
            .then_with(|| am.part.name.cmp(&bm.part.name))
            .then_with(|| ag.part.name.cmp(&bg.part.name))
    };
    let gears: Vec<(&Gear, GearSide)> =
        catalog.gears.iter().filter(|g| g.fits() == axis.load.kind).map(|g| (g, GearSide::new(axis, g))).collect();
    let mut candidates: Vec<(usize, &Motor)> =
        gears.iter().enumerate().flat_map(|(gi, (g, _))| catalog.motors.iter().filter(|m| g.mounts(m)).map(move |m| (gi, m))).collect();
    candidates.sort_by(|a, b| smaller(a.1, gears[a.0].0, b.1, gears[b.0].0));
    // Evaluated in that order: once `top` combinations pass with the reserve, every later one
    // ranks after them. A combination that fails a check of speed, gear or inertia (cheap: no
    // pass over the samples) is a failing one, evaluated only when fewer than `top` pass.
    let mut found: Vec<Found> = Vec::new();
    let mut deferred: Vec<(usize, &Motor, f64)> = Vec::new();
    let mut scratch = Vec::new();
    let mut keeps = 0;
    let push = |gi: usize, motor: &'c Motor, found: &mut Vec<Found<'c>>, scratch: &mut Vec<f64>| -> Standing {
        let (gear, side) = &gears[gi];
        let o = evaluate(axis, side, motor, gear, settings, scratch);
        let standing = if !o.pass() {
            Standing::Fails
        } else if !o.missing.is_empty() {
            Standing::Incomplete
        } else if o.with_reserve() {
            Standing::PassesWithReserve
        } else {
            Standing::Passes
        };
        let limiting = o.limiting();
        found.push(Found {
            motor,
            gear,
            standing,
            margin: limiting.as_ref().map(|l| l.margin),
            failed: o.checks.iter().filter(|c| !c.pass).map(|c| c.check).collect(),
            limiting,
            mass: motor.mass.zip(gear.mass).map(|(a, b)| a + b),
            price: motor.price_class.zip(gear.price_class).map(|(a, b)| a.max(b)),
            missing: o.missing,
        });
        standing
    };
    for (gi, motor) in candidates {
        if keeps >= top {
            break;
        }
        let bound = cheap_margin(axis, &gears[gi].1, motor, gears[gi].0);
        if bound < 0.0 {
            deferred.push((gi, motor, bound));
            continue;
        }
        if push(gi, motor, &mut found, &mut scratch) == Standing::PassesWithReserve {
            keeps += 1;
        }
    }
    // The failing ones fill what the others leave of `top`, closest first: those that fail a
    // cheap check in the order of that check's margin (an upper bound of their smallest
    // margin), until the next bound is below the margin of the last failing one needed.
    let others = found.iter().filter(|f| f.standing != Standing::Fails).count();
    if keeps < top && others < top {
        let need = top - others;
        deferred.sort_by(|a, b| b.2.total_cmp(&a.2));
        for (gi, motor, bound) in deferred {
            let mut fails: Vec<f64> =
                found.iter().filter(|f| f.standing == Standing::Fails).map(|f| f.margin.unwrap_or(f64::NEG_INFINITY)).collect();
            if fails.len() >= need {
                fails.sort_by(|a, b| b.total_cmp(a));
                if bound < fails[need - 1] {
                    break;
                }
            }
            push(gi, motor, &mut found, &mut scratch);
        }
    }
    found.sort_by(|a, b| {
        a.standing.cmp(&b.standing).then_with(|| {
            if a.standing == Standing::Fails {
                known(b.margin, a.margin).then_with(|| smaller(a.motor, a.gear, b.motor, b.gear))
            } else if a.standing == Standing::Incomplete {
                // The fewer values missing, the more the combination is known to pass.
                a.missing.len().cmp(&b.missing.len()).then_with(|| smaller(a.motor, a.gear, b.motor, b.gear))
            } else {
                smaller(a.motor, a.gear, b.motor, b.gear)
            }
        })
    });
    let reserve = (settings.reserve * 100.0).round();
    let mut in_group = 0;
    let mut group = None;
    found
        .into_iter()
        .take(top)
        .enumerate()
        .map(|(i, f)| {
            if group != Some(f.standing) {
                group = Some(f.standing);
                in_group = 0;
            }
            in_group += 1;
            let limit = f.limiting.as_ref().map_or(String::new(), |l| format!("{} (margin {:.1} %)", l.label, l.margin * 100.0));
            let keys = format!(
                "rotor inertia {} kg·m², mass {}, price class {}",
                short(f.motor.j),
                f.mass.map_or("unknown".to_string(), |m| format!("{} kg", short(m))),
                f.price.map_or("unknown".to_string(), |p| p.to_string())
            );
            let why = match f.standing {
                Standing::PassesWithReserve => format!(
                    "passes every check with the {reserve} % reserve; the {} smallest such combination ({keys}); limited by {limit}",
                    ordinal(in_group)
                ),
                Standing::Passes => format!(
                    "passes every check but not with the {reserve} % reserve: {limit}; after every combination that keeps it; the {} smallest of its kind ({keys})",
                    ordinal(in_group)
                ),
                Standing::Incomplete => format!(
                    "passes the checks it could evaluate, but {} missing: {}; after every complete passing combination ({keys}); limited by {limit}",
                    if f.missing.len() == 1 { "one value is" } else { "values are" },
                    f.missing.join(", ")
                ),
                Standing::Fails => format!("fails {}: after every passing combination, ordered by how close it comes; worst: {limit}", f.failed.join(", ")),
            };
            Alternative {
                motor: f.motor.part.clone(),
                gear: f.gear.part.clone(),
                ratio: f.gear.ratio,
                rank: i + 1,
                standing: f.standing,
                pass: f.standing != Standing::Fails,
                margin: f.margin,
                limiting: f.limiting,
                failed: f.failed,
                why,
                rotor_inertia: f.motor.j,
                mass: f.mass,
                price_class: f.price,
                missing: f.missing,
            }
        })
        .collect()
}

/// What a joint without a drive asks of one: peak and RMS torque (or force) over the duty
/// cycle, top speed.
pub fn undriven(load: AxisLoad, dwell: f64) -> Result<Undriven, SizingError> {
    let axis = Axis::new(load, dwell)?;
    Ok(Undriven {
        joint: load.joint.to_string(),
        peak_torque: axis.peak_tau.0,
        rms_torque: axis.rms_tau,
        max_speed: axis.max_qd.0,
        effort_limit: None,
        within_effort: None,
    })
}
