//! The answer of a run: per drive the tracking error, current and voltage against the limits
//! and the saturation intervals; the tool frame's error; a verdict against the user's tolerances.

use crate::mechanism::{Mechanism, MechanismError};
use crate::pipeline::ir::FrameId;

use super::{Drive, Run};

/// One drive's tracking over a run (errors `q − q_ref`, rad or m, at the output samples).
#[derive(Clone, Debug, PartialEq)]
pub struct Tracking {
    pub coordinate: usize,
    pub max_error: f64,
    pub rms_error: f64,
    /// (keyframe time, error there, interpolated between the samples around it).
    pub at_keyframes: Vec<(f64, f64)>,
    /// Largest |armature current| and |applied voltage|, with the limits.
    pub max_current: f64,
    pub i_max: f64,
    pub max_voltage: f64,
    pub v_max: f64,
    /// Intervals (s) where the current command or the voltage was limited.
    pub saturated: Vec<(f64, f64)>,
}

/// The user's tolerances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Largest joint error, rad or m (applied to every drive).
    pub max_joint_error: f64,
    /// Largest tool position error, m.
    pub max_tool_error: Option<f64>,
}

/// Whether the machine holds its path, and why not.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    pub ok: bool,
    pub reasons: Vec<String>,
}

/// The intervals of `t` where `flag` holds (from the first flagged sample to the last one of each
/// run of flagged samples).
pub fn saturation_intervals(t: &[f64], flag: &[bool]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut open: Option<f64> = None;
    for (k, (&tk, &f)) in t.iter().zip(flag).enumerate() {
        match (f, open) {
            (true, None) => open = Some(tk),
            (false, Some(s)) => {
                out.push((s, t[k - 1]));
                open = None;
            }
            _ => {}
        }
    }
    if let (Some(s), Some(&last)) = (open, t.last()) {
        out.push((s, last));
    }
    out
}

impl Run {
    /// Tracking of each drive, with errors at `keyframes` (s).
    pub fn tracking(&self, drives: &[Drive], keyframes: &[f64]) -> Vec<Tracking> {
        drives
            .iter()
            .enumerate()
            .map(|(d, drive)| {
                let c = drive.coordinate;
                let samples = &self.drives[d];
                let err: Vec<f64> = samples.iter().zip(&self.q).map(|(s, q)| q[c] - s.q_ref).collect();
                let max_error = err.iter().fold(0.0f64, |m, e| m.max(e.abs()));
                let rms_error = (err.iter().map(|e| e * e).sum::<f64>() / err.len().max(1) as f64).sqrt();
                let at_keyframes = keyframes.iter().map(|&tk| (tk, super::interpolate(&self.t, &err, tk))).collect();
                let flag: Vec<bool> = samples.iter().map(|s| s.i_cmd != s.i_ref || s.v != s.v_cmd).collect();
                Tracking {
                    coordinate: c,
                    max_error,
                    rms_error,
                    at_keyframes,
                    max_current: samples.iter().fold(0.0f64, |m, s| m.max(s.i.abs())),
                    i_max: drive.motor.i_max,
                    max_voltage: samples.iter().fold(0.0f64, |m, s| m.max(s.v.abs())),
                    v_max: drive.motor.v_max,
                    saturated: saturation_intervals(&self.t, &flag),
                }
            })
            .collect()
    }

    /// Position (m) and orientation (rad) error of a frame per sample: its pose at the simulated
    /// coordinates against its pose with every driven coordinate at its reference (trees: every
    /// coordinate; with loops the dependent ones stay as simulated).
    pub fn tool_error(&self, m: &Mechanism, drives: &[Drive], frame: FrameId) -> Result<Vec<(f64, f64)>, MechanismError> {
        let mut out = Vec::with_capacity(self.t.len());
        for (k, q) in self.q.iter().enumerate() {
            let mut planned = q.clone();
            for (d, drive) in drives.iter().enumerate() {
                planned[drive.coordinate] = self.drives[d][k].q_ref;
            }
            let a = m.frame_pose(&m.forward(q)?, frame)?;
            let b = m.frame_pose(&m.forward(&planned)?, frame)?;
            out.push(((a.translation.vector - b.translation.vector).norm(), a.rotation.angle_to(&b.rotation)));
        }
        Ok(out)
    }
}

/// The verdict of tracking (and the tool error, when computed) against the tolerances.
pub fn verdict(tracking: &[Tracking], names: &[String], tool_error: Option<&[(f64, f64)]>, tol: &Tolerances) -> Verdict {
    let mut reasons = Vec::new();
    for tr in tracking {
        let name = names.get(tr.coordinate).map(String::as_str).unwrap_or("?");
        // NaN counts as a failure.
        if tr.max_error.partial_cmp(&tol.max_joint_error).is_none_or(|o| o == std::cmp::Ordering::Greater) {
            reasons.push(format!("{name}: joint error {:.3e} above {:.3e}", tr.max_error, tol.max_joint_error));
        }
        if !tr.saturated.is_empty() {
            reasons.push(format!(
                "{name}: current or voltage limited during {} interval(s), from t = {} s",
                tr.saturated.len(),
                tr.saturated[0].0
            ));
        }
    }
    if let (Some(errors), Some(max)) = (tool_error, tol.max_tool_error) {
        let worst = errors.iter().fold(0.0f64, |m, e| m.max(e.0));
        if worst.partial_cmp(&max).is_none_or(|o| o == std::cmp::Ordering::Greater) {
            reasons.push(format!("tool position error {worst:.3e} m above {max:.3e} m"));
        }
    }
    Verdict { ok: reasons.is_empty(), reasons }
}
