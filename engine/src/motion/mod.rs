//! Joint-space motion profiles: how a set of axes moves from one keyframe to the next.
//!
//! No IO, no HTTP, no SQL. Positions in rad (revolute) or m (prismatic), per axis; time in s.
//!
//! - [`Ptp2`]: synchronised point-to-point with a trapezoidal (or triangular) velocity profile,
//!   exactly as MSL's `Modelica.Blocks.Sources.KinematicPTP2` (used by the RobotR3 example): all
//!   axes share one path parameter `s` in [0, 1], so they start and arrive together; the path's
//!   speed limit is `1 / max_i |Δq_i / qd_max_i|` and its acceleration limit
//!   `1 / max_i |Δq_i / qdd_max_i|`, so the slowest axis sets the pace. No jerk limit.
//! - [`Quintic`]: a fifth-order polynomial per axis with zero velocity and acceleration at both
//!   ends over a given duration (Robotics Toolbox `jtraj`); the duration may be chosen from the
//!   limits with [`Quintic::fastest`].
//! - [`JerkLimited`]: time-optimal, jerk-limited and synchronised state-to-state motion, computed
//!   by the `rsruckig` crate (a pure-Rust port of Ruckig, Berscheid & Kröger, RSS 2021; the
//!   `ruckig` crate binds the C++ library and needs its build); through via points the motion
//!   stops at each via point (Ruckig's intermediate waypoints are not part of its open version).
//!
//! A [`Profile`] answers `sample(t) -> (q, qd, qdd)` for any `t` (held at the ends outside
//! `[0, duration]`).
//!
//! [`plan`] turns a user's motion (keyframes, with inverse kinematics for tool poses) into one
//! timed joint trajectory of a [`crate::mechanism::Mechanism`] from these profiles.

pub mod plan;

use serde::{Deserialize, Serialize};

/// Positions, speeds and accelerations of every axis at one instant.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct State {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
}

/// Why a profile cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProfileError {
    #[error("axis {axis}: {what} must be a finite number greater than 0 (is {value})")]
    BadLimit { axis: usize, what: &'static str, value: f64 },
    #[error("{what} has {got} values for {axes} axes")]
    Length { what: &'static str, got: usize, axes: usize },
    #[error("axis {axis}: position {value} is not a finite number")]
    BadPosition { axis: usize, value: f64 },
    #[error("duration {0} s must be a finite number of at least 0")]
    BadDuration(f64),
    #[error("jerk-limited profile: {0}")]
    Ruckig(String),
}

/// Something that moves every axis over `[0, duration]`.
pub trait Profile {
    fn duration(&self) -> f64;
    fn sample(&self, t: f64) -> State;
}

fn check_positions(what: &'static str, q: &[f64], axes: usize) -> Result<(), ProfileError> {
    if q.len() != axes {
        return Err(ProfileError::Length { what, got: q.len(), axes });
    }
    match q.iter().position(|v| !v.is_finite()) {
        Some(axis) => Err(ProfileError::BadPosition { axis, value: q[axis] }),
        None => Ok(()),
    }
}

fn check_limits(what: &'static str, l: &[f64], axes: usize) -> Result<(), ProfileError> {
    if l.len() != axes {
        return Err(ProfileError::Length { what, got: l.len(), axes });
    }
    match l.iter().position(|v| !(v.is_finite() && *v > 0.0)) {
        Some(axis) => Err(ProfileError::BadLimit { axis, what, value: l[axis] }),
        None => Ok(()),
    }
}

/// MSL `KinematicPTP2` from `q_begin` to `q_end`, starting at t = 0.
#[derive(Clone, Debug)]
pub struct Ptp2 {
    q_begin: Vec<f64>,
    delta: Vec<f64>,
    /// Path speed and acceleration limits (of s in [0, 1]).
    sd_max: f64,
    sdd_max: f64,
    /// End of acceleration, start of deceleration, end.
    ta: f64,
    tv: f64,
    te: f64,
}

impl Ptp2 {
    pub fn new(q_begin: &[f64], q_end: &[f64], qd_max: &[f64], qdd_max: &[f64]) -> Result<Ptp2, ProfileError> {
        let n = q_begin.len();
        check_positions("start position", q_begin, n)?;
        check_positions("end position", q_end, n)?;
        check_limits("speed limit", qd_max, n)?;
        check_limits("acceleration limit", qdd_max, n)?;
        let delta: Vec<f64> = q_begin.iter().zip(q_end).map(|(b, e)| e - b).collect();
        let sd_max_inv = delta.iter().zip(qd_max).map(|(d, v)| (d / v).abs()).fold(0.0, f64::max);
        let sdd_max_inv = delta.iter().zip(qdd_max).map(|(d, a)| (d / a).abs()).fold(0.0, f64::max);
        let eps = 10.0 * f64::EPSILON;
        if sd_max_inv <= eps || sdd_max_inv <= eps {
            return Ok(Ptp2 { q_begin: q_begin.to_vec(), delta, sd_max: 0.0, sdd_max: 0.0, ta: 0.0, tv: 0.0, te: 0.0 });
        }
        let (sd_max, sdd_max) = (1.0 / sd_max_inv, 1.0 / sdd_max_inv);
        // Triangular when the top speed cannot be reached before half the path.
        let ta1 = (1.0 / sdd_max).sqrt();
        let ta2 = sd_max / sdd_max;
        let (ta, tv, te) = if ta2 >= ta1 { (ta1, ta1, 2.0 * ta1) } else { (ta2, 1.0 / sd_max, 1.0 / sd_max + ta2) };
        Ok(Ptp2 { q_begin: q_begin.to_vec(), delta, sd_max, sdd_max, ta, tv, te })
    }

    /// Path parameter, its speed and acceleration at `t`.
    fn path(&self, t: f64) -> (f64, f64, f64) {
        let a = self.sdd_max;
        if self.te == 0.0 || t <= 0.0 {
            return (0.0, 0.0, 0.0);
        }
        if t >= self.te {
            return (1.0, 0.0, 0.0);
        }
        let v_top = a * self.ta; // the highest path speed reached
        let s_a = 0.5 * a * self.ta * self.ta;
        if t < self.ta {
            (0.5 * a * t * t, a * t, a)
        } else if t < self.tv {
            (s_a + v_top * (t - self.ta), v_top, 0.0)
        } else {
            let s_v = s_a + v_top * (self.tv - self.ta);
            let u = t - self.tv;
            (s_v + v_top * u - 0.5 * a * u * u, v_top - a * u, -a)
        }
    }

    /// The path speed limit actually reached (for reports).
    pub fn path_speed(&self) -> f64 {
        self.sd_max.min(self.sdd_max * self.ta)
    }
}

impl Profile for Ptp2 {
    fn duration(&self) -> f64 {
        self.te
    }

    fn sample(&self, t: f64) -> State {
        let (s, sd, sdd) = self.path(t);
        State {
            q: self.q_begin.iter().zip(&self.delta).map(|(b, d)| b + d * s).collect(),
            qd: self.delta.iter().map(|d| d * sd).collect(),
            qdd: self.delta.iter().map(|d| d * sdd).collect(),
        }
    }
}

/// A quintic polynomial per axis, at rest at both ends.
#[derive(Clone, Debug)]
pub struct Quintic {
    q_begin: Vec<f64>,
    delta: Vec<f64>,
    duration: f64,
}

impl Quintic {
    pub fn new(q_begin: &[f64], q_end: &[f64], duration: f64) -> Result<Quintic, ProfileError> {
        check_positions("start position", q_begin, q_begin.len())?;
        check_positions("end position", q_end, q_begin.len())?;
        if !(duration.is_finite() && duration >= 0.0) {
            return Err(ProfileError::BadDuration(duration));
        }
        Ok(Quintic { q_begin: q_begin.to_vec(), delta: q_begin.iter().zip(q_end).map(|(b, e)| e - b).collect(), duration })
    }

    /// The shortest duration within the limits: the quintic's peak speed is 15/8 Δq/T and its
    /// peak acceleration 10/√3 Δq/T².
    pub fn fastest(q_begin: &[f64], q_end: &[f64], qd_max: &[f64], qdd_max: &[f64]) -> Result<Quintic, ProfileError> {
        let n = q_begin.len();
        check_limits("speed limit", qd_max, n)?;
        check_limits("acceleration limit", qdd_max, n)?;
        check_positions("end position", q_end, n)?;
        let mut t: f64 = 0.0;
        for i in 0..n {
            let d = (q_end[i] - q_begin[i]).abs();
            t = t.max(15.0 / 8.0 * d / qd_max[i]).max((10.0 / 3f64.sqrt() * d / qdd_max[i]).sqrt());
        }
        Quintic::new(q_begin, q_end, t)
    }
}

impl Profile for Quintic {
    fn duration(&self) -> f64 {
        self.duration
    }

    fn sample(&self, t: f64) -> State {
        let n = self.delta.len();
        if self.duration == 0.0 || t >= self.duration {
            let q = self.q_begin.iter().zip(&self.delta).map(|(b, d)| if self.duration == 0.0 && t < 0.0 { *b } else { b + d }).collect();
            return State { q, qd: vec![0.0; n], qdd: vec![0.0; n] };
        }
        let t = t.max(0.0);
        let (tt, big) = (t / self.duration, self.duration);
        // s = 10 τ³ − 15 τ⁴ + 6 τ⁵
        let s = tt * tt * tt * (10.0 + tt * (-15.0 + 6.0 * tt));
        let sd = 30.0 * tt * tt * (1.0 - tt) * (1.0 - tt) / big;
        let sdd = 60.0 * tt * (1.0 - tt) * (1.0 - 2.0 * tt) / (big * big);
        State {
            q: self.q_begin.iter().zip(&self.delta).map(|(b, d)| b + d * s).collect(),
            qd: self.delta.iter().map(|d| d * sd).collect(),
            qdd: self.delta.iter().map(|d| d * sdd).collect(),
        }
    }
}

/// Time-optimal jerk-limited synchronised motion from rest to rest (Ruckig), sampled on a 1 ms
/// grid when made (the trajectory is evaluated at each grid instant).
#[derive(Clone, Debug)]
pub struct JerkLimited {
    duration: f64,
    /// Samples at `step` intervals from 0 to `duration` (last one at `duration`).
    step: f64,
    samples: Vec<State>,
}

/// Limits of one motion.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
pub struct Limits {
    pub qd_max: Vec<f64>,
    pub qdd_max: Vec<f64>,
    /// Only the jerk-limited profile uses it.
    pub qddd_max: Vec<f64>,
}

impl JerkLimited {
    pub fn new(q_begin: &[f64], q_end: &[f64], limits: &Limits) -> Result<JerkLimited, ProfileError> {
        Self::at_least(q_begin, q_end, limits, None)
    }

    /// [`JerkLimited::new`], taking at least `min_duration` seconds when given (Ruckig's
    /// minimum duration: the profile is slowed, not padded with a hold).
    pub fn at_least(q_begin: &[f64], q_end: &[f64], limits: &Limits, min_duration: Option<f64>) -> Result<JerkLimited, ProfileError> {
        let n = q_begin.len();
        if let Some(d) = min_duration {
            if !(d.is_finite() && d >= 0.0) {
                return Err(ProfileError::BadDuration(d));
            }
        }
        check_positions("start position", q_begin, n)?;
        check_positions("end position", q_end, n)?;
        check_limits("speed limit", &limits.qd_max, n)?;
        check_limits("acceleration limit", &limits.qdd_max, n)?;
        check_limits("jerk limit", &limits.qddd_max, n)?;
        if n == 0 {
            return Ok(JerkLimited { duration: 0.0, step: 1e-3, samples: vec![State { q: vec![], qd: vec![], qdd: vec![] }] });
        }
        use rsruckig::prelude::{DataArrayOrVec, InputParameter, Ruckig, ThrowErrorHandler, Trajectory};
        // DOF = 0: the number of axes is given at run time.
        let mut otg = Ruckig::<0, ThrowErrorHandler>::new(Some(n), 1e-3);
        let mut input = InputParameter::<0>::new(Some(n));
        for i in 0..n {
            input.current_position[i] = q_begin[i];
            input.current_velocity[i] = 0.0;
            input.current_acceleration[i] = 0.0;
            input.target_position[i] = q_end[i];
            input.target_velocity[i] = 0.0;
            input.target_acceleration[i] = 0.0;
            input.max_velocity[i] = limits.qd_max[i];
            input.max_acceleration[i] = limits.qdd_max[i];
            input.max_jerk[i] = limits.qddd_max[i];
        }
        input.minimum_duration = min_duration;
        let mut trajectory = Trajectory::<0>::new(Some(n));
        otg.calculate(&input, &mut trajectory).map_err(|e| {
            // Its first line: the rest is the planner's input dump (kilobytes of internal state).
            let m = e.to_string();
            ProfileError::Ruckig(crate::pipeline::ir::clip(m.lines().next().unwrap_or_default(), 300))
        })?;
        let duration = trajectory.get_duration();
        let step = 1e-3;
        let count = (duration / step).ceil() as usize;
        let mut samples = Vec::with_capacity(count + 1);
        let (mut q, mut qd, mut qdd) = (
            DataArrayOrVec::<f64, 0>::new(Some(n), 0.0),
            DataArrayOrVec::<f64, 0>::new(Some(n), 0.0),
            DataArrayOrVec::<f64, 0>::new(Some(n), 0.0),
        );
        for k in 0..=count {
            let t = (k as f64 * step).min(duration);
            trajectory.at_time(t, &mut Some(&mut q), &mut Some(&mut qd), &mut Some(&mut qdd), &mut None, &mut None);
            samples.push(State {
                q: (0..n).map(|i| q[i]).collect(),
                qd: (0..n).map(|i| qd[i]).collect(),
                qdd: (0..n).map(|i| qdd[i]).collect(),
            });
        }
        Ok(JerkLimited { duration, step, samples })
    }
}

impl Profile for JerkLimited {
    fn duration(&self) -> f64 {
        self.duration
    }

    fn sample(&self, t: f64) -> State {
        let k = ((t.max(0.0) / self.step).round() as usize).min(self.samples.len().saturating_sub(1));
        self.samples[k].clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(v: &[f64]) -> Vec<f64> {
        v.iter().map(|d| d.to_radians()).collect()
    }

    /// MSL RobotR3 `fullRobot` defaults: KinematicPTP2 ends at 1.356045 s.
    #[test]
    fn ptp2_matches_msl_robot_r3() {
        let p = Ptp2::new(
            &deg(&[-60.0, 20.0, 90.0, 0.0, -110.0, 0.0]),
            &deg(&[60.0, -70.0, -35.0, 45.0, 110.0, 45.0]),
            &[3.0, 1.5, 5.0, 3.1, 3.1, 4.1],
            &[15.0, 15.0, 15.0, 60.0, 60.0, 60.0],
        )
        .expect("profile");
        assert!((p.duration() - 1.356045).abs() < 5e-7, "{}", p.duration());
        let end = p.sample(p.duration());
        assert!(end.q.iter().zip(deg(&[60.0, -70.0, -35.0, 45.0, 110.0, 45.0])).all(|(a, b)| (a - b).abs() < 1e-12));
        // Continuous position and speed, within every axis's limits, all axes in step.
        let mut prev = p.sample(0.0);
        for k in 1..=2000 {
            let s = p.sample(p.duration() * k as f64 / 2000.0);
            for i in 0..6 {
                assert!(s.qd[i].abs() <= [3.0, 1.5, 5.0, 3.1, 3.1, 4.1][i] + 1e-12);
                assert!(s.qdd[i].abs() <= [15.0, 15.0, 15.0, 60.0, 60.0, 60.0][i] + 1e-12);
                assert!((s.q[i] - prev.q[i]).abs() < 0.01 && (s.qd[i] - prev.qd[i]).abs() < 0.05);
            }
            prev = s;
        }
        // Axis 5 (220 deg at 3.1 rad/s) sets the pace: it reaches its speed limit exactly.
        let mid = p.sample(p.duration() / 2.0);
        assert!((mid.qd[4].abs() - 3.1).abs() < 1e-9, "{:?}", mid.qd);
    }

    #[test]
    fn ptp2_triangular_and_still() {
        // Short move: the top speed is never reached, the profile is a triangle of 2 sqrt(Δ/a).
        let p = Ptp2::new(&[0.0], &[0.01], &[10.0], &[1.0]).expect("profile");
        assert!((p.duration() - 2.0 * 0.01f64.sqrt()).abs() < 1e-12, "{}", p.duration());
        assert!((p.sample(p.duration() / 2.0).q[0] - 0.005).abs() < 1e-12);
        let still = Ptp2::new(&[1.0, 2.0], &[1.0, 2.0], &[1.0, 1.0], &[1.0, 1.0]).expect("profile");
        assert_eq!(still.duration(), 0.0);
        assert_eq!(still.sample(3.0).q, vec![1.0, 2.0]);
    }

    #[test]
    fn quintic_is_at_rest_at_both_ends_and_within_limits() {
        let q = Quintic::fastest(&[0.0, 1.0], &[1.0, -1.0], &[2.0, 2.0], &[5.0, 5.0]).expect("profile");
        let t = q.duration();
        let a = q.sample(0.0);
        let b = q.sample(t);
        assert_eq!((a.qd.clone(), a.qdd.clone()), (vec![0.0, 0.0], vec![0.0, 0.0]));
        assert_eq!(b.q, vec![1.0, -1.0]);
        let peak_v = (0..=1000).map(|k| q.sample(t * k as f64 / 1000.0).qd[1].abs()).fold(0.0, f64::max);
        let peak_a = (0..=1000).map(|k| q.sample(t * k as f64 / 1000.0).qdd[1].abs()).fold(0.0, f64::max);
        assert!(peak_v <= 2.0 + 1e-9 && peak_a <= 5.0 + 1e-6, "{peak_v} {peak_a}");
        assert!(peak_v > 1.99 || peak_a > 4.99, "one limit is reached");
    }

    #[test]
    fn jerk_limited_reaches_the_target_within_limits() {
        let limits = Limits { qd_max: vec![1.0, 2.0], qdd_max: vec![2.0, 2.0], qddd_max: vec![10.0, 10.0] };
        let p = JerkLimited::new(&[0.0, 0.0], &[1.0, -0.5], &limits).expect("profile");
        assert!(p.duration() > 1.0 && p.duration() < 3.0, "{}", p.duration());
        let end = p.sample(p.duration());
        assert!((end.q[0] - 1.0).abs() < 1e-9 && (end.q[1] + 0.5).abs() < 1e-9, "{:?}", end.q);
        for k in 0..=100 {
            let s = p.sample(p.duration() * k as f64 / 100.0);
            assert!(s.qd[0].abs() <= 1.0 + 1e-9 && s.qdd[0].abs() <= 2.0 + 1e-9);
        }
    }

    #[test]
    fn bad_limits_are_named() {
        let e = Ptp2::new(&[0.0, 0.0], &[1.0, 1.0], &[1.0, 0.0], &[1.0, 1.0]).expect_err("refused");
        assert_eq!(e.to_string(), "axis 1: speed limit must be a finite number greater than 0 (is 0)");
        let e = Ptp2::new(&[0.0], &[1.0, 1.0], &[1.0], &[1.0]).expect_err("refused");
        assert!(e.to_string().contains("end position has 2 values for 1 axes"), "{e}");
    }
}
