//! Drive sizing: does a motor and gear from the library move a joint through a motion, and
//! which combinations of the library would? No IO, no HTTP, no SQL, no panics.
//!
//! Input per driven axis: an [`AxisLoad`], the joint's speed, acceleration and torque (or force)
//! samples from the motion's inverse dynamics (gravity included) and the largest joint-space
//! inertia `M_jj` over the motion. Motors and gears come from library instances
//! ([`parts::motor`], [`parts::gear`]; their classes must be ones the sizing knows, see
//! [`parts`]); datasheet parameters of the library give the limits.
//!
//! The load is reflected through the gear to the motor shaft, sample by sample:
//!
//! - transmission `n = ratio` (revolute) or `n = ratio·2π/lead` (rad/m, lead screw); motor speed
//!   `ω_m = n·q̇`;
//! - load torque at the motor `τ/(n·η)` while the motor drives the load (joint power
//!   `P = τ·q̇ >= 0`, standstill included) and `τ·η/n` while the load drives the motor back
//!   (`P < 0`): losses always cost the motor, in both directions of power flow;
//! - motor torque `T_m = load torque + (J_motor + J_gear,in)·n·q̈ + d·ω_m`;
//! - motor voltage `U = R·T_m/k + k·ω_m`.
//!
//! The checks (each [`Check`] with value, limit, margin `(limit - value)/limit` and where the
//! worst sample is):
//!
//! | check | value | limit |
//! |---|---|---|
//! | `peak_torque` | max `|T_m|` | motor `T_peak`; without it `k·I_max` (the generated drive's current limit) |
//! | `rms_torque` | `sqrt(∫T_m² dt / T)` (trapezoidal) | motor `T_nom` |
//! | `motor_speed` | max `|ω_m|` | motor `w_max` |
//! | `voltage` | max `|U|` | motor `V_max` (MSL machine: `VaNominal`) |
//! | `gear_input_speed` | max `|ω_m|` | gear `w_in_max` |
//! | `gear_peak_torque` | max `|τ|` at the output (N·m, or N for a screw) | gear `T_peak` (screw: `F_peak`) |
//! | `gear_rms_torque` | RMS of `τ` | gear `T_rated` (rotary gears) |
//! | `inertia_ratio` | `J_load / (n²·J_motor)` | 10 (≤ 3 good, 3–5 common, 5–10 needs stiff mechanics) |
//! | `braking_energy` | energy the motor shaft takes back (`∫ min(T_m·ω_m, 0) dt`) | information only |
//!
//! A check whose limit is a datasheet value the instance lacks is not evaluated: the parameter
//! is listed in `missing` (`motor.T_nom`, `gear.w_in_max`).
//!
//! Ranking ([`rank`]): every motor × gear of the [`Catalog`] whose gear fits the joint kind
//! (prismatic joints: screws; revolute joints: the others), each gear at its own ratio and, when
//! its ratio is editable, also at the [`STANDARD_RATIOS`] inside the parameter's limits (a gear's
//! datasheet ratings are then kept as they are: ratings differ between ratios of one series, so
//! an alternative at another ratio needs its own catalog check). Combinations that pass every
//! evaluated check are ranked: first those with no missing datasheet value, then by rotor
//! inertia ascending (the smallest motor), then by minimum margin descending, then by names and
//! ratio.

pub mod parts;
#[cfg(test)]
mod tests;

use serde::Serialize;

use crate::pipeline::back::modelica::mechatronics::JointKind;
pub use parts::{Catalog, Gear, Motor, PeakRule};

/// Ratios tried for gears whose ratio is editable (within the parameter's limits).
pub const STANDARD_RATIOS: [f64; 13] = [1.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 30.0, 50.0, 74.0, 100.0, 120.0, 160.0];

/// The inertia ratio limit; ≤ [`INERTIA_RATIO_GOOD`] is good.
pub const INERTIA_RATIO_LIMIT: f64 = 10.0;
pub const INERTIA_RATIO_GOOD: f64 = 3.0;

/// At most this many operating points are returned.
pub const MAX_POINTS: usize = 2000;

/// How many alternatives [`size_drive`] returns by default.
pub const TOP: usize = 10;

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

/// One check of a drive.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Check {
    pub check: &'static str,
    pub label: &'static str,
    pub value: f64,
    /// `None` for information (braking energy).
    pub limit: Option<f64>,
    pub unit: &'static str,
    /// `(limit - value) / limit`; `None` without a limit.
    pub margin: Option<f64>,
    pub pass: bool,
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
    pub no_load_speed: Option<f64>,
}

/// A motor × gear combination that passes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Alternative {
    pub motor: PartRef,
    pub gear: PartRef,
    pub ratio: f64,
    /// The smallest margin of the evaluated checks.
    pub margin: f64,
    /// 1 = best.
    pub rank: usize,
    /// Datasheet values the combination lacks (those checks were not evaluated).
    pub missing: Vec<String>,
}

/// The sizing of one drive: the contract's `drives[]` entry.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DriveSizing {
    pub joint: String,
    pub motor: PartRef,
    pub gear: PartRef,
    pub ratio: f64,
    /// Every evaluated pass/fail check passes.
    pub pass: bool,
    pub checks: Vec<Check>,
    pub missing: Vec<String>,
    pub operating_points: OperatingPoints,
    pub envelope: Envelope,
    pub alternatives: Vec<Alternative>,
}

/// A joint without a drive: what a drive would have to deliver at the joint.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Undriven {
    pub joint: String,
    /// max `|τ|` (N·m or N), RMS of `τ`, max `|q̇|` (rad/s or m/s).
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
    Check {
        check: "joint-effort",
        label: "Joint effort limit (source)",
        value: peak,
        limit: Some(effort),
        unit,
        margin: (effort > 0.0).then(|| (effort - peak) / effort),
        pass: peak <= effort,
        detail: format!("peak joint load {peak:.4} {unit} against the effort limit {effort} {unit} the source states"),
    }
}

// ---------------------------------------------------------------------------------------------
// The axis, checked once

/// An axis with its integration weights and joint-side figures.
struct Axis<'a> {
    load: AxisLoad<'a>,
    /// Trapezoidal weights (s); their sum is the cycle time (1 for a single sample).
    w: Vec<f64>,
    cycle: f64,
    peak_tau: (f64, usize),
    rms_tau: f64,
    max_qd: (f64, usize),
}

fn kind_name(k: JointKind) -> &'static str {
    match k {
        JointKind::Revolute => "revolute",
        JointKind::Prismatic => "prismatic",
    }
}

impl<'a> Axis<'a> {
    fn new(load: AxisLoad<'a>) -> Result<Axis<'a>, SizingError> {
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
        let mut w = vec![0.0; n];
        for i in 0..n.saturating_sub(1) {
            let h = 0.5 * (load.t[i + 1] - load.t[i]);
            w[i] += h;
            w[i + 1] += h;
        }
        let mut cycle: f64 = w.iter().sum();
        if cycle <= 0.0 {
            // One sample, or all at one instant: plain averages.
            w.iter_mut().for_each(|x| *x = 1.0);
            cycle = n as f64;
        }
        let peak_tau = argmax_abs(load.tau);
        let rms_tau = (load.tau.iter().zip(&w).map(|(x, w)| x * x * w).sum::<f64>() / cycle).sqrt();
        let max_qd = argmax_abs(load.qd);
        Ok(Axis { load, w, cycle, peak_tau, rms_tau, max_qd })
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

/// The motor-side figures of one combination over the whole motion.
#[derive(Clone, Copy, Debug, Default)]
struct Stats {
    peak_t: (f64, usize),
    sum_t2: f64,
    max_w: (f64, usize),
    max_u: (f64, usize),
    /// ∫ min(P, 0) dt (J, <= 0) and the most negative power (W).
    e_neg: f64,
    p_neg: (f64, usize),
}

/// Motor speed and torque at sample `i` for transmission `n`.
#[inline]
fn motor_point(axis: &Axis, motor: &Motor, gear: &Gear, n: f64, i: usize) -> (f64, f64) {
    let l = &axis.load;
    let (tau, qd) = (l.tau[i], l.qd[i]);
    let w = n * qd;
    // Efficiency in the direction of power flow: the motor pays the losses both ways.
    let load = if tau * qd >= 0.0 { tau / (n * gear.eta) } else { tau * gear.eta / n };
    let inertia = (motor.j + gear.j_in.unwrap_or(0.0)) * n * l.qdd[i];
    (w, load + inertia + motor.d * w)
}

fn reflect(axis: &Axis, motor: &Motor, gear: &Gear, n: f64) -> Stats {
    let mut s = Stats::default();
    let (r_k, k) = (motor.r / motor.k, motor.k);
    for i in 0..axis.w.len() {
        let (w, t) = motor_point(axis, motor, gear, n, i);
        let (ta, wa, ua) = (t.abs(), w.abs(), (r_k * t + k * w).abs());
        if ta > s.peak_t.0 {
            s.peak_t = (ta, i);
        }
        if wa > s.max_w.0 {
            s.max_w = (wa, i);
        }
        if ua > s.max_u.0 {
            s.max_u = (ua, i);
        }
        s.sum_t2 += t * t * axis.w[i];
        let p = t * w;
        if p < 0.0 {
            s.e_neg += p * axis.w[i];
            if p < s.p_neg.0 {
                s.p_neg = (p, i);
            }
        }
    }
    s
}

// ---------------------------------------------------------------------------------------------
// Checks

struct Outcome {
    checks: Vec<Check>,
    missing: Vec<String>,
}

impl Outcome {
    fn pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }

    fn min_margin(&self) -> f64 {
        self.checks.iter().filter_map(|c| c.margin).fold(f64::INFINITY, f64::min)
    }

    #[allow(clippy::too_many_arguments)]
    fn limit(
        &mut self,
        check: &'static str,
        label: &'static str,
        value: f64,
        limit: Option<f64>,
        missing: &str,
        unit: &'static str,
        detail: String,
    ) {
        match limit {
            Some(limit) => {
                let margin = if limit > 0.0 {
                    (limit - value) / limit
                } else if value > 0.0 {
                    f64::NEG_INFINITY
                } else {
                    0.0
                };
                // An infinite margin cannot be written as JSON: clamp to the worst finite one.
                let margin = margin.max(-f64::MAX);
                self.checks.push(Check {
                    check,
                    label,
                    value,
                    limit: Some(limit),
                    unit,
                    margin: Some(margin),
                    pass: value <= limit,
                    detail,
                });
            }
            None => self.missing.push(missing.to_string()),
        }
    }
}

fn evaluate(axis: &Axis, motor: &Motor, gear: &Gear, ratio: f64) -> Outcome {
    let n = gear.transmission(ratio);
    let s = reflect(axis, motor, gear, n);
    let mut o = Outcome { checks: Vec::with_capacity(9), missing: Vec::new() };
    let (out_unit, out_what) = match gear.lead {
        Some(_) => ("N", "force"),
        None => ("N.m", "torque"),
    };

    let peak = motor.peak_rule();
    let peak_detail = match peak {
        Some(PeakRule::Datasheet(_)) => format!("{}; limit: datasheet T_peak", axis.at(s.peak_t.1)),
        Some(PeakRule::CurrentLimit(_)) => {
            format!("{}; limit: k·I_max, the generated drive's current limit (no datasheet T_peak)", axis.at(s.peak_t.1))
        }
        None => String::new(),
    };
    o.limit("peak_torque", "Peak motor torque", s.peak_t.0, peak.map(PeakRule::value), "motor.T_peak", "N.m", peak_detail);
    let rms = (s.sum_t2 / axis.cycle).sqrt();
    o.limit(
        "rms_torque",
        "RMS motor torque",
        rms,
        motor.t_nom,
        "motor.T_nom",
        "N.m",
        format!("over the cycle of {} s; limit: nominal (continuous) torque", short(axis.cycle)),
    );
    o.limit("motor_speed", "Maximum motor speed", s.max_w.0, motor.w_max, "motor.w_max", "rad/s", axis.at(s.max_w.1));
    o.limit("voltage", "Motor voltage U = R·T/k + k·ω", s.max_u.0, motor.v_max, "motor.V_max", "V", axis.at(s.max_u.1));
    o.limit("gear_input_speed", "Gear input speed", s.max_w.0, gear.w_in_max, "gear.w_in_max", "rad/s", axis.at(s.max_w.1));
    let missing_peak = format!("gear.{}", gear.out_peak_name());
    o.limit(
        "gear_peak_torque",
        if gear.lead.is_some() { "Peak axial force" } else { "Peak gear output torque" },
        axis.peak_tau.0,
        gear.out_peak,
        &missing_peak,
        out_unit,
        format!("{}; output {out_what} = joint {out_what}", axis.at(axis.peak_tau.1)),
    );
    if gear.lead.is_none() {
        o.limit(
            "gear_rms_torque",
            "RMS gear output torque",
            axis.rms_tau,
            gear.t_rated,
            "gear.T_rated",
            "N.m",
            "limit: rated (continuous) output torque".to_string(),
        );
    }
    let reflected = n * n * motor.j;
    let ratio_value = if reflected > 0.0 { axis.load.load_inertia / reflected } else { f64::MAX };
    let quality = if ratio_value <= INERTIA_RATIO_GOOD {
        "good (≤ 3)"
    } else if ratio_value <= 5.0 {
        "common (3–5)"
    } else if ratio_value <= INERTIA_RATIO_LIMIT {
        "needs stiff mechanics (5–10)"
    } else {
        "risky (> 10)"
    };
    o.limit(
        "inertia_ratio",
        "Inertia ratio J_load / (n²·J_motor)",
        ratio_value,
        Some(INERTIA_RATIO_LIMIT),
        "",
        "1",
        format!("{quality}; J_load = max M_jj over the motion"),
    );
    let braking = -s.e_neg;
    o.checks.push(Check {
        check: "braking_energy",
        label: "Braking energy (motor shaft)",
        value: braking,
        limit: None,
        unit: "J",
        margin: None,
        pass: true,
        detail: if braking > 0.0 {
            format!(
                "the load drives the motor back; peak braking power {} W {}: needs a braking resistor or regeneration",
                short(-s.p_neg.0),
                axis.at(s.p_neg.1)
            )
        } else {
            "the motor never brakes".to_string()
        },
    });
    o
}

/// Keeps at most [`MAX_POINTS`] samples: the samples are cut into buckets and each bucket keeps
/// its smallest and largest torque and speed, so every extreme of the cycle stays.
fn operating_points(axis: &Axis, motor: &Motor, gear: &Gear, n: f64) -> OperatingPoints {
    let len = axis.w.len();
    let points: Vec<(f64, f64)> = (0..len).map(|i| motor_point(axis, motor, gear, n, i)).collect();
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

/// Sizes the drive of one joint (motor and gear with the drive's overrides applied) and, with a
/// catalog, ranks the `top` best alternatives of the library for the same joint.
pub fn size_drive(load: AxisLoad, motor: &Motor, gear: &Gear, catalog: Option<&Catalog>, top: usize) -> Result<DriveSizing, SizingError> {
    let axis = Axis::new(load)?;
    check_fit(&axis, gear)?;
    let o = evaluate(&axis, motor, gear, gear.ratio);
    let alternatives = match catalog {
        Some(c) => rank_axis(&axis, c, top),
        None => Vec::new(),
    };
    Ok(DriveSizing {
        joint: load.joint.to_string(),
        motor: motor.part.clone(),
        gear: gear.part.clone(),
        ratio: gear.ratio,
        pass: o.pass(),
        operating_points: operating_points(&axis, motor, gear, gear.transmission(gear.ratio)),
        envelope: Envelope {
            continuous_torque: motor.t_nom,
            peak_torque: motor.peak_rule().map(PeakRule::value),
            max_speed: motor.w_max,
            no_load_speed: motor.no_load_speed(),
        },
        checks: o.checks,
        missing: o.missing,
        alternatives,
    })
}

/// The `top` best motor × gear combinations of `catalog` for a joint (see the module doc for
/// the order).
pub fn rank(load: AxisLoad, catalog: &Catalog, top: usize) -> Result<Vec<Alternative>, SizingError> {
    Ok(rank_axis(&Axis::new(load)?, catalog, top))
}

/// The ratios tried for a gear: its own, and the standard ones when the ratio is editable
/// (same sign as its own, within the parameter's limits).
pub fn ratios(gear: &Gear) -> Vec<f64> {
    let mut out = vec![gear.ratio];
    if gear.ratio_editable {
        let sign = gear.ratio.signum();
        for r in STANDARD_RATIOS.iter().map(|r| r * sign) {
            let inside = gear.ratio_min.is_none_or(|lo| r >= lo) && gear.ratio_max.is_none_or(|hi| r <= hi);
            if inside && r != gear.ratio {
                out.push(r);
            }
        }
    }
    out
}

fn rank_axis(axis: &Axis, catalog: &Catalog, top: usize) -> Vec<Alternative> {
    struct Found<'c> {
        motor: &'c Motor,
        gear: &'c Gear,
        ratio: f64,
        margin: f64,
        missing: Vec<String>,
    }
    let mut found: Vec<Found> = Vec::new();
    for gear in catalog.gears.iter().filter(|g| g.fits() == axis.load.kind) {
        for ratio in ratios(gear) {
            for motor in &catalog.motors {
                let o = evaluate(axis, motor, gear, ratio);
                if o.pass() {
                    found.push(Found { motor, gear, ratio, margin: o.min_margin(), missing: o.missing });
                }
            }
        }
    }
    found.sort_by(|a, b| {
        (!a.missing.is_empty())
            .cmp(&!b.missing.is_empty())
            .then(a.motor.j.total_cmp(&b.motor.j))
            .then(b.margin.total_cmp(&a.margin))
            .then_with(|| a.motor.part.name.cmp(&b.motor.part.name))
            .then_with(|| a.gear.part.name.cmp(&b.gear.part.name))
            .then(a.ratio.total_cmp(&b.ratio))
    });
    found
        .into_iter()
        .take(top)
        .enumerate()
        .map(|(i, f)| Alternative {
            motor: f.motor.part.clone(),
            gear: f.gear.part.clone(),
            ratio: f.ratio,
            margin: f.margin,
            rank: i + 1,
            missing: f.missing,
        })
        .collect()
}

/// What a joint without a drive asks of one: peak and RMS torque (or force), top speed.
pub fn undriven(load: AxisLoad) -> Result<Undriven, SizingError> {
    let axis = Axis::new(load)?;
    Ok(Undriven {
        joint: load.joint.to_string(),
        peak_torque: axis.peak_tau.0,
        rms_torque: axis.rms_tau,
        max_speed: axis.max_qd.0,
        effort_limit: None,
        within_effort: None,
    })
}
