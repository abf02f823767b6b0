//! A user's motion on a mechanism: keyframes (joint values, or a tool pose solved by inverse
//! kinematics) joined by profiles, checked against the joints' limits, sampled at any rate, with
//! the joint torques of the inverse dynamics along it.
//!
//! - The axes are the mechanism's tree coordinates ([`Mechanism::coordinates`]), named by their
//!   Modelica element names (the keys of drives and limits).
//! - The first keyframe is the start pose (missing joints: the CAD pose); every later keyframe
//!   ends a segment made with its own interpolation, then holds for its `dwell`. A joints keyframe
//!   that leaves a joint out keeps that joint where the previous keyframe put it.
//! - `ptp` is MSL `KinematicPTP2` at the joints' speed and acceleration limits; a longer
//!   `duration` slows it by time scaling (limits `qd/k`, `qdd/k²` with `k = duration / natural`),
//!   which keeps its shape. `quintic` takes `duration` (checked against the limits) or the
//!   fastest within them. `jerk` is Ruckig's time-optimal jerk-limited profile, at least
//!   `duration` long when given.
//! - Every problem is an [`Issue`] naming the keyframe (`keyframes[2]`) and joint: nothing is
//!   planned half-way.
//!
//! Mechanisms with closed loops are driven at their independent coordinates
//! ([`Mechanism::driven`]): keyframes set those only, the other joints follow the loop closure at
//! every sample ([`Planned::closed_samples`]), and the torques are those of the driven joints
//! (the followers carry none). Inverse kinematics does not handle closures yet.

use std::collections::BTreeMap;

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use super::{JerkLimited, Limits, Profile, Ptp2, Quintic, State};
use crate::library::Issue;
use crate::mechanism::{ClosedState, CoordKind, IkOptions, IkTarget, Mechanism, XorShift};

/// Most keyframes in one motion.
pub const MAX_KEYFRAMES: usize = 1000;
/// Longest motion, s.
pub const MAX_DURATION: f64 = 3600.0;
/// Most samples one request may ask for.
pub const MAX_SAMPLES: usize = 2_000_000;

/// How a segment moves from the previous keyframe to this one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Interpolation {
    #[default]
    Ptp,
    Quintic,
    Jerk,
}

/// Where a keyframe puts the mechanism.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Target {
    /// Joint values by Modelica name (rad or m); the others stay.
    Joints { values: BTreeMap<String, f64> },
    /// A CAD frame (by node ID) at a world pose, solved by inverse kinematics. `rotation` maps
    /// frame to world; `None`: position only.
    Tool { frame: String, position: [f64; 3], rotation: Option<[[f64; 3]; 3]> },
}

/// One keyframe of a motion.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Keyframe {
    #[serde(flatten)]
    pub target: Target,
    #[serde(default)]
    pub interpolation: Interpolation,
    /// Segment duration, s (see the module doc).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration: Option<f64>,
    /// Hold after arriving, s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dwell: Option<f64>,
}

/// A named motion: what users store.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    pub name: String,
    pub keyframes: Vec<Keyframe>,
}

/// Limits of one axis (rad or m based).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AxisLimits {
    pub position: [f64; 2],
    pub speed: f64,
    pub acceleration: f64,
    pub jerk: f64,
}

/// A user's limits of one joint: each field absent keeps the default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LimitsEdit {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub acceleration: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub jerk: Option<f64>,
}

impl AxisLimits {
    /// Defaults (CAD exports carry no limits): a revolute joint q0 ± π, 3 rad/s, 15 rad/s²,
    /// 150 rad/s³ (the scale of MSL RobotR3's axes); a prismatic one q0 ± 0.1 m, 0.5 m/s, 2 m/s²,
    /// 20 m/s³.
    pub fn defaults(kind: CoordKind, q0: f64) -> AxisLimits {
        match kind {
            CoordKind::Revolute => {
                AxisLimits { position: [q0 - std::f64::consts::PI, q0 + std::f64::consts::PI], speed: 3.0, acceleration: 15.0, jerk: 150.0 }
            }
            CoordKind::Prismatic => AxisLimits { position: [q0 - 0.1, q0 + 0.1], speed: 0.5, acceleration: 2.0, jerk: 20.0 },
        }
    }

    /// The defaults for a coordinate: [`AxisLimits::defaults`], with the position range and
    /// speed the source states (URDF `<limit>`) where it states them. The source's joint
    /// coordinate is the Modelica one (the URDF front end places the base frame at the joint
    /// origin), so its position limits apply as they are, whatever the start value.
    pub fn for_coordinate(c: &crate::mechanism::Coordinate) -> AxisLimits {
        let mut d = AxisLimits::defaults(c.kind, c.q0);
        if let Some(s) = &c.source_limits {
            if let (Some(lo), Some(hi)) = (s.lower, s.upper) {
                if lo < hi {
                    d.position = [lo, hi];
                }
            }
            if let Some(v) = s.velocity.filter(|v| *v > 0.0) {
                d.speed = v;
            }
        }
        d
    }

    /// These limits with a user's edit applied.
    pub fn with(self, e: &LimitsEdit) -> AxisLimits {
        AxisLimits {
            position: e.position.unwrap_or(self.position),
            speed: e.speed.unwrap_or(self.speed),
            acceleration: e.acceleration.unwrap_or(self.acceleration),
            jerk: e.jerk.unwrap_or(self.jerk),
        }
    }
}

impl LimitsEdit {
    /// Every problem with an edit: finite numbers, a non-empty position range, positive rates.
    pub fn check(&self) -> Vec<Issue> {
        let mut out = Vec::new();
        if let Some([lo, hi]) = self.position {
            if !(lo.is_finite() && hi.is_finite()) {
                out.push(Issue::new("position", "both bounds must be finite numbers"));
            } else if lo >= hi {
                out.push(Issue::new("position", format!("the lower bound {lo} must be below the upper bound {hi}")));
            }
        }
        for (field, v) in [("speed", self.speed), ("acceleration", self.acceleration), ("jerk", self.jerk)] {
            if let Some(v) = v {
                if !(v.is_finite() && v > 0.0) {
                    out.push(Issue::new(field, format!("must be a finite number greater than 0 (is {v})")));
                }
            }
        }
        out
    }
}

/// One axis of a motion: a tree coordinate with its limits.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub name: String,
    pub kind: CoordKind,
    pub q0: f64,
    pub limits: AxisLimits,
}

impl Axis {
    fn unit(&self) -> &'static str {
        match self.kind {
            CoordKind::Revolute => "rad",
            CoordKind::Prismatic => "m",
        }
    }
}

/// The axes of a mechanism with the given edits (keyed by Modelica name).
pub fn axes(mech: &Mechanism, edits: &BTreeMap<String, LimitsEdit>) -> Vec<Axis> {
    mech.coordinates()
        .iter()
        .map(|c| {
            let d = AxisLimits::for_coordinate(c);
            let limits = edits.get(&c.name).map_or(d, |e| d.with(e));
            Axis { name: c.name.clone(), kind: c.kind, q0: c.q0, limits }
        })
        .collect()
}

/// What inverse kinematics did at a tool keyframe.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct IkReport {
    pub iterations: usize,
    pub position_error: f64,
    pub rotation_error: f64,
    /// Independent directions the driven joints move the tool in at the solution (see
    /// `IkResult::mobility`); not serialised.
    #[serde(skip)]
    pub mobility: usize,
}

/// A keyframe as planned: its time (arrival) and joint values.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlannedKeyframe {
    pub index: usize,
    pub time: f64,
    pub q: BTreeMap<String, f64>,
    pub ik: Option<IkReport>,
}

enum Shape {
    Ptp(Ptp2),
    Quintic(Quintic),
    Jerk(JerkLimited),
    Hold(Vec<f64>),
}

struct Segment {
    start: f64,
    shape: Shape,
}

impl Segment {
    fn sample(&self, t: f64) -> State {
        let u = t - self.start;
        match &self.shape {
            Shape::Ptp(p) => p.sample(u),
            Shape::Quintic(p) => p.sample(u),
            Shape::Jerk(p) => p.sample(u),
            Shape::Hold(q) => State { q: q.clone(), qd: vec![0.0; q.len()], qdd: vec![0.0; q.len()] },
        }
    }
}

/// A planned motion: sample it anywhere in `[0, duration]`.
pub struct Planned {
    pub axes: Vec<Axis>,
    pub keyframes: Vec<PlannedKeyframe>,
    pub duration: f64,
    segments: Vec<Segment>,
}

/// Samples of a motion at a fixed rate; per axis, `q[axis][sample]`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Samples {
    pub t: Vec<f64>,
    pub q: Vec<Vec<f64>>,
    pub qd: Vec<Vec<f64>>,
    pub qdd: Vec<Vec<f64>>,
    /// Per sample, the coordinates of plainly emitted closing joints (loop mechanisms only).
    #[serde(skip)]
    pub cut: Vec<Vec<f64>>,
}

impl Planned {
    /// The state at `t` (held at the ends).
    pub fn sample(&self, t: f64) -> State {
        let k = self.segments.partition_point(|s| s.start <= t).saturating_sub(1);
        match self.segments.get(k) {
            Some(s) => s.sample(t.min(self.duration)),
            None => {
                let q = self.keyframes.first().map(|k| self.axes.iter().map(|a| k.q[&a.name]).collect()).unwrap_or_default();
                State { qd: vec![0.0; self.axes.len()], qdd: vec![0.0; self.axes.len()], q }
            }
        }
    }

    /// How many samples [`Planned::samples`] gives at `rate` Hz.
    pub fn sample_count(&self, rate: f64) -> usize {
        (self.duration * rate - 1e-9).ceil().max(0.0) as usize + 1
    }

    /// [`Planned::samples`] with every loop closed: the followers' positions, speeds and
    /// accelerations come from the closure at each sample (the profile's values of the driven
    /// joints are kept). For a tree, the samples as they are.
    pub fn closed_samples(&self, mech: &Mechanism, rate: f64) -> Result<Samples, Vec<Issue>> {
        let mut s = self.samples(rate);
        if !mech.has_dependent() {
            return Ok(s);
        }
        let n = self.axes.len();
        let mut state = ClosedState { q: mech.q0(), qd: vec![0.0; n], qdd: vec![0.0; n], cut: mech.cut_q0() };
        let driven = mech.driven();
        for i in 0..s.t.len() {
            for &a in &driven {
                state.q[a] = s.q[a][i];
                state.qd[a] = s.qd[a][i];
                state.qdd[a] = s.qdd[a][i];
            }
            if let Err(e) = mech.close(&mut state) {
                let k = self.keyframes.iter().position(|kf| kf.time >= s.t[i]).unwrap_or(0);
                return Err(vec![Issue::new(
                    format!("keyframes[{k}]"),
                    format!("the loops cannot be closed at t = {} s on the way to keyframe {k}: {e}", fmt(s.t[i])),
                )]);
            }
            for a in 0..n {
                s.q[a][i] = state.q[a];
                s.qd[a][i] = state.qd[a];
                s.qdd[a][i] = state.qdd[a];
            }
            s.cut.push(state.cut.clone());
        }
        Ok(s)
    }

    /// Samples at `t = i / rate` for `i = 0, 1, ...`, the last one at the end of the motion
    /// (the profiles only: see [`Planned::closed_samples`] for loop mechanisms).
    pub fn samples(&self, rate: f64) -> Samples {
        let n = self.sample_count(rate);
        let axes = self.axes.len();
        let mut out = Samples {
            t: Vec::with_capacity(n),
            q: vec![Vec::with_capacity(n); axes],
            qd: vec![Vec::with_capacity(n); axes],
            qdd: vec![Vec::with_capacity(n); axes],
            cut: Vec::new(),
        };
        for i in 0..n {
            let t = ((i as f64) / rate).min(self.duration);
            let s = self.sample(t);
            out.t.push(t);
            for a in 0..axes {
                out.q[a].push(s.q[a]);
                out.qd[a].push(s.qd[a]);
                out.qdd[a].push(s.qdd[a]);
            }
        }
        out
    }
}

fn fmt(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Checks the form of a spec (before it is stored): a name, 2 to [`MAX_KEYFRAMES`] keyframes,
/// finite numbers, non-negative durations and dwells.
pub fn check_spec(spec: &MotionSpec) -> Vec<Issue> {
    let mut out = Vec::new();
    let name = spec.name.trim();
    if name.is_empty() || name.chars().count() > 100 || name.chars().any(char::is_control) {
        out.push(Issue::new("name", "must be 1 to 100 printable characters"));
    }
    if spec.keyframes.len() < 2 {
        out.push(Issue::new("keyframes", "a motion needs at least 2 keyframes (the start and one target)"));
    }
    if spec.keyframes.len() > MAX_KEYFRAMES {
        out.push(Issue::new("keyframes", format!("at most {MAX_KEYFRAMES} keyframes")));
    }
    for (k, kf) in spec.keyframes.iter().enumerate().take(MAX_KEYFRAMES) {
        let at = format!("keyframes[{k}]");
        match &kf.target {
            Target::Joints { values } => {
                for (j, v) in values {
                    if !v.is_finite() {
                        out.push(Issue::new(format!("{at}.values.{j}"), "must be a finite number"));
                    }
                }
            }
            Target::Tool { frame, position, rotation } => {
                if frame.is_empty() {
                    out.push(Issue::new(format!("{at}.frame"), "names the tool frame by its CAD node ID"));
                }
                if position.iter().any(|v| !v.is_finite()) {
                    out.push(Issue::new(format!("{at}.position"), "must be 3 finite numbers (m)"));
                }
                if let Some(r) = rotation {
                    if rotation_of(r).is_none() {
                        out.push(Issue::new(
                            format!("{at}.rotation"),
                            "must be a rotation matrix (orthonormal to 1e-6, determinant +1), rows first",
                        ));
                    }
                }
            }
        }
        for (field, v) in [("duration", kf.duration), ("dwell", kf.dwell)] {
            if let Some(v) = v {
                if !(v.is_finite() && (0.0..=MAX_DURATION).contains(&v)) {
                    out.push(Issue::new(format!("{at}.{field}"), format!("must be between 0 and {MAX_DURATION} s (is {v})")));
                }
            }
        }
    }
    out
}

/// A rotation matrix given row by row, when it is one (to 1e-6), re-orthonormalised.
pub fn rotation_of(r: &[[f64; 3]; 3]) -> Option<Rotation3<f64>> {
    let m = Matrix3::from_fn(|i, j| r[i][j]);
    if m.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let err = (m.transpose() * m - Matrix3::identity()).abs().max();
    if err > 1e-6 || m.determinant() <= 0.0 {
        return None;
    }
    Some(Rotation3::from_matrix(&m))
}

/// The IK target of a tool keyframe.
pub fn ik_target(position: &[f64; 3], rotation: &Option<[[f64; 3]; 3]>) -> Option<IkTarget> {
    let p = Vector3::from(*position);
    match rotation {
        None => Some(IkTarget::Position(p)),
        Some(r) => {
            let r = rotation_of(r)?;
            Some(IkTarget::Pose(Isometry3::from_parts(Translation3::from(p), UnitQuaternion::from_rotation_matrix(&r))))
        }
    }
}

/// Solves a tool target within the axes' position limits, from `seed`. `Err` is the message.
pub fn solve_tool(
    mech: &Mechanism,
    axes: &[Axis],
    frame: &str,
    target: &IkTarget,
    seed: &[f64],
) -> Result<(Vec<f64>, IkReport, bool), String> {
    let tool = mech.frame_by_node_id(frame).map_err(|e| e.to_string())?;
    let opts =
        IkOptions { limits: Some(axes.iter().map(|a| (a.limits.position[0], a.limits.position[1])).collect()), ..IkOptions::default() };
    // Seeded by the frame so that the same spec always plans the same way.
    let seed_rng = frame.bytes().fold(0x9e37_79b9_7f4a_7c15_u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
    let mut rng = XorShift::new(seed_rng);
    let r = mech.inverse_kinematics(tool, target, seed, &opts, &mut rng).map_err(|e| e.to_string())?;
    let report =
        IkReport { iterations: r.iterations, position_error: r.position_error, rotation_error: r.rotation_error, mobility: r.mobility };
    Ok((r.q, report, r.success))
}

/// Plans `spec` on `mech` with `axes` (from [`axes`]). Every problem found is returned.
pub fn plan(mech: &Mechanism, axes: &[Axis], spec: &MotionSpec) -> Result<Planned, Vec<Issue>> {
    let mut issues = check_spec(spec);
    if !issues.is_empty() {
        return Err(issues);
    }
    let loops = mech.has_dependent();
    let driven_names =
        || -> String { mech.driven().iter().map(|&i| axes.get(i).map_or("", |a| a.name.as_str())).collect::<Vec<_>>().join(", ") };
    let index: BTreeMap<&str, usize> = axes.iter().enumerate().map(|(i, a)| (a.name.as_str(), i)).collect();
    let n = axes.len();
    let mut prev: Vec<f64> = axes.iter().map(|a| a.q0).collect();
    let mut poses: Vec<(Vec<f64>, Option<IkReport>)> = Vec::with_capacity(spec.keyframes.len());
    for (k, kf) in spec.keyframes.iter().enumerate() {
        let at = format!("keyframes[{k}]");
        let mut q = prev.clone();
        let mut ik = None;
        match &kf.target {
            Target::Joints { values } => {
                let mut coupled_set = Vec::new();
                for (name, v) in values {
                    match index.get(name.as_str()) {
                        Some(&i) if mech.coupling_of(i).is_some() => {
                            q[i] = *v;
                            coupled_set.push(i);
                        }
                        Some(&i) if loops && !mech.coordinates().get(i).is_some_and(|c| c.independent) => issues.push(Issue::new(
                            format!("{at}.values.{name}"),
                            format!(
                                "keyframe {k}: joint \"{name}\" follows the closure of a kinematic loop; set the driven joints instead: {}",
                                driven_names()
                            ),
                        )),
                        Some(&i) => q[i] = *v,
                        None => issues.push(Issue::new(
                            format!("{at}.values.{name}"),
                            format!("keyframe {k}: joint \"{name}\" is not a joint of this version of the model"),
                        )),
                    }
                }
                // A mimic follower may be given only where it agrees with its leader.
                let mut expected = q.clone();
                mech.apply_couplings(&mut expected);
                for i in coupled_set {
                    let Some(c) = mech.coupling_of(i) else { continue };
                    if (q[i] - expected[i]).abs() > 1e-9 * (1.0 + expected[i].abs()) {
                        let (f, l) = (axes.get(i).map_or("", |a| a.name.as_str()), axes.get(c.leader).map_or("", |a| a.name.as_str()));
                        issues.push(Issue::new(
                            format!("{at}.values.{f}"),
                            format!(
                                "keyframe {k}: {f} = {} contradicts the mimic coupling {f} = {} * {l}{}: with {l} = {} it is {} (set {l} only)",
                                fmt(q[i]),
                                fmt(c.multiplier),
                                if c.offset != 0.0 { format!(" + {}", fmt(c.offset)) } else { String::new() },
                                fmt(expected[c.leader]),
                                fmt(expected[i])
                            ),
                        ));
                    }
                }
            }
            Target::Tool { frame, position, rotation } => {
                let Some(target) = ik_target(position, rotation) else {
                    issues.push(Issue::new(format!("{at}.rotation"), "is not a rotation matrix"));
                    poses.push((q.clone(), None));
                    continue;
                };
                match solve_tool(mech, axes, frame, &target, &prev) {
                    Ok((sol, report, true)) => {
                        q = sol;
                        ik = Some(report);
                    }
                    Ok((_, r, false)) => {
                        let rows = if matches!(target, IkTarget::Pose(_)) { 6 } else { 3 };
                        let why = if r.mobility < rows {
                            format!(
                                "the driven joints ({}) move this frame in only {} independent direction(s) here, the target needs {rows} ({}): only targets on that {}-dimensional set are reachable (try a position-only target or a frame on the set)",
                                driven_names(),
                                r.mobility,
                                if rows == 6 { "position and orientation" } else { "position" },
                                r.mobility
                            )
                        } else {
                            "unreachable within the joints' position limits?".to_string()
                        };
                        issues.push(Issue::new(
                            at.clone(),
                            format!(
                                "keyframe {k}: inverse kinematics failed for frame \"{frame}\": residual {:.3e} m / {:.3e} rad after {} iterations ({why})",
                                r.position_error, r.rotation_error, r.iterations
                            ),
                        ))
                    }
                    Err(e) => issues.push(Issue::new(format!("{at}.frame"), format!("keyframe {k}: {e}"))),
                }
            }
        }
        for (i, a) in axes.iter().enumerate() {
            let [lo, hi] = a.limits.position;
            if q[i] < lo - 1e-12 || q[i] > hi + 1e-12 {
                issues.push(Issue::new(
                    at.clone(),
                    format!(
                        "keyframe {k}: {} = {} {} is outside its position limits [{}, {}]",
                        a.name,
                        fmt(q[i]),
                        a.unit(),
                        fmt(lo),
                        fmt(hi)
                    ),
                ));
            }
        }
        if loops && issues.is_empty() {
            let mut st = ClosedState { q: q.clone(), qd: vec![0.0; n], qdd: vec![0.0; n], cut: mech.cut_q0() };
            match mech.close(&mut st) {
                Ok(()) => q = st.q,
                Err(e) => {
                    issues.push(Issue::new(at.clone(), format!("keyframe {k}: the loops cannot be closed at these joint values: {e}")))
                }
            }
        }
        prev = q.clone();
        poses.push((q, ik));
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    let speeds: Vec<f64> = axes.iter().map(|a| a.limits.speed).collect();
    let accels: Vec<f64> = axes.iter().map(|a| a.limits.acceleration).collect();
    let jerks: Vec<f64> = axes.iter().map(|a| a.limits.jerk).collect();
    let mut segments = Vec::new();
    let mut keyframes = Vec::with_capacity(poses.len());
    let mut t = 0.0;
    for (k, kf) in spec.keyframes.iter().enumerate() {
        let at = format!("keyframes[{k}]");
        let q = &poses[k].0;
        if k > 0 {
            let from = &poses[k - 1].0;
            let shape = match kf.interpolation {
                Interpolation::Ptp => Ptp2::new(from, q, &speeds, &accels)
                    .and_then(|p| match kf.duration {
                        Some(d) if d > p.duration() && p.duration() > 0.0 => {
                            let s = d / p.duration();
                            Ptp2::new(
                                from,
                                q,
                                &speeds.iter().map(|v| v / s).collect::<Vec<_>>(),
                                &accels.iter().map(|v| v / (s * s)).collect::<Vec<_>>(),
                            )
                        }
                        _ => Ok(p),
                    })
                    .map(Shape::Ptp),
                Interpolation::Quintic => match kf.duration {
                    Some(d) => Quintic::new(from, q, d).map(Shape::Quintic),
                    None => Quintic::fastest(from, q, &speeds, &accels).map(Shape::Quintic),
                },
                Interpolation::Jerk => {
                    let limits = Limits { qd_max: speeds.clone(), qdd_max: accels.clone(), qddd_max: jerks.clone() };
                    JerkLimited::at_least(from, q, &limits, kf.duration).map(Shape::Jerk)
                }
            };
            let shape = match shape {
                Ok(s) => s,
                Err(e) => {
                    issues.push(Issue::new(at.clone(), format!("keyframe {k}: {e}")));
                    continue;
                }
            };
            let duration = match &shape {
                Shape::Ptp(p) => p.duration(),
                Shape::Quintic(p) => p.duration(),
                Shape::Jerk(p) => p.duration(),
                Shape::Hold(_) => 0.0,
            };
            if let (Some(d), Interpolation::Ptp) = (kf.duration, kf.interpolation) {
                if d + 1e-9 < duration {
                    issues.push(Issue::new(
                        format!("{at}.duration"),
                        format!(
                            "keyframe {k}: the joints' speed and acceleration limits need at least {} s for this segment; {} s is too short",
                            fmt(duration),
                            fmt(d)
                        ),
                    ));
                }
            }
            if let (Some(d), Interpolation::Quintic) = (kf.duration, kf.interpolation) {
                // Peak speed 15/8 Δq/T and acceleration 10/√3 Δq/T² of the quintic.
                for (i, a) in axes.iter().enumerate() {
                    let dq = (q[i] - from[i]).abs();
                    if dq == 0.0 {
                        continue;
                    }
                    let (v, acc) = (15.0 / 8.0 * dq / d, 10.0 / 3f64.sqrt() * dq / (d * d));
                    if v > a.limits.speed * (1.0 + 1e-9) {
                        issues.push(Issue::new(
                            format!("{at}.duration"),
                            format!(
                                "keyframe {k}: {} reaches {} {}/s at t = {} s, above its speed limit {}",
                                a.name,
                                fmt(v),
                                a.unit(),
                                fmt(t + d / 2.0),
                                fmt(a.limits.speed)
                            ),
                        ));
                    } else if acc > a.limits.acceleration * (1.0 + 1e-9) {
                        issues.push(Issue::new(
                            format!("{at}.duration"),
                            format!(
                                "keyframe {k}: {} reaches {} {}/s² at t = {} s, above its acceleration limit {}",
                                a.name,
                                fmt(acc),
                                a.unit(),
                                fmt(t + d * (0.5 - 3f64.sqrt() / 6.0)),
                                fmt(a.limits.acceleration)
                            ),
                        ));
                    }
                }
            }
            segments.push(Segment { start: t, shape });
            t += duration;
        }
        keyframes.push(PlannedKeyframe {
            index: k,
            time: t,
            q: axes.iter().zip(q).map(|(a, v)| (a.name.clone(), *v)).collect(),
            ik: poses[k].1.clone(),
        });
        if let Some(d) = kf.dwell.filter(|d| *d > 0.0) {
            segments.push(Segment { start: t, shape: Shape::Hold(q.clone()) });
            t += d;
        }
        if t > MAX_DURATION {
            issues.push(Issue::new(at, format!("the motion is longer than {MAX_DURATION} s")));
            break;
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    let planned = Planned { axes: axes.to_vec(), keyframes, duration: t, segments };
    // Jerk-limited profiles are not guaranteed monotone: check positions along the way.
    if n > 0 && spec.keyframes.iter().any(|k| k.interpolation == Interpolation::Jerk) {
        let s = planned.samples(1000.0);
        for (i, a) in axes.iter().enumerate() {
            let [lo, hi] = a.limits.position;
            if let Some(j) = s.q[i].iter().position(|v| *v < lo - 1e-9 || *v > hi + 1e-9) {
                let k = planned.keyframes.iter().position(|kf| kf.time >= s.t[j]).unwrap_or(0);
                issues.push(Issue::new(
                    format!("keyframes[{k}]"),
                    format!("{} leaves its position limits [{}, {}] at t = {} s", a.name, fmt(lo), fmt(hi), fmt(s.t[j])),
                ));
            }
        }
    }
    if issues.is_empty() {
        Ok(planned)
    } else {
        Err(issues)
    }
}

/// Joint torques (N·m or N) along samples, per axis, with `gravity` (world, m/s²); and the
/// largest joint-space inertia `M_jj` each axis sees (kg·m² or kg), from every `stride`-th
/// sample (inertia changes slowly; it is used for the inertia ratio).
pub fn inverse_dynamics(
    mech: &Mechanism,
    s: &Samples,
    gravity: &Vector3<f64>,
    stride: usize,
) -> Result<(Vec<Vec<f64>>, Vec<f64>), crate::mechanism::MechanismError> {
    if mech.has_dependent() {
        return driven_dynamics(mech, s, gravity, stride);
    }
    let n = mech.dof();
    let mut ws = mech.workspace();
    let mut tau = vec![Vec::with_capacity(s.t.len()); n];
    let (mut q, mut qd, mut qdd, mut out) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut inertia = vec![0.0_f64; n];
    let zero = vec![0.0; n];
    for i in 0..s.t.len() {
        for a in 0..n {
            q[a] = s.q[a][i];
            qd[a] = s.qd[a][i];
            qdd[a] = s.qdd[a][i];
        }
        mech.inverse_dynamics_with_losses(&q, &qd, &qdd, gravity, &mut ws, &mut out)?;
        for a in 0..n {
            tau[a].push(out[a]);
        }
        if i % stride.max(1) == 0 || i + 1 == s.t.len() {
            let mut e = vec![0.0; n];
            for a in 0..n {
                e[a] = 1.0;
                mech.inverse_dynamics(&q, &zero, &e, &Vector3::zeros(), &mut ws, &mut out)?;
                inertia[a] = inertia[a].max(out[a]);
                e[a] = 0.0;
            }
        }
    }
    Ok((tau, inertia))
}

/// [`inverse_dynamics`] of a loop mechanism from [`Planned::closed_samples`]: the driven joints'
/// torques (followers 0) and the inertia each driven joint sees.
#[allow(clippy::needless_range_loop)] // samples index every axis's column
fn driven_dynamics(
    mech: &Mechanism,
    s: &Samples,
    gravity: &Vector3<f64>,
    stride: usize,
) -> Result<(Vec<Vec<f64>>, Vec<f64>), crate::mechanism::MechanismError> {
    let n = mech.dof();
    let driven = mech.driven();
    let mut ws = mech.workspace();
    let mut tau = vec![vec![0.0; s.t.len()]; n];
    let mut inertia = vec![0.0_f64; n];
    let mut tree = vec![0.0; n];
    let mut state = ClosedState { q: vec![0.0; n], qd: vec![0.0; n], qdd: vec![0.0; n], cut: Vec::new() };
    for i in 0..s.t.len() {
        for a in 0..n {
            state.q[a] = s.q[a][i];
            state.qd[a] = s.qd[a][i];
            state.qdd[a] = s.qdd[a][i];
        }
        state.cut = s.cut.get(i).cloned().unwrap_or_else(|| mech.cut_q0());
        let t = mech.driven_torques(&state, gravity, &mut ws, &mut tree)?;
        for (k, &a) in driven.iter().enumerate() {
            tau[a][i] = t[k];
        }
        if i % stride.max(1) == 0 || i + 1 == s.t.len() {
            for (k, m) in mech.driven_inertia(&state, &mut ws)?.into_iter().enumerate() {
                inertia[driven[k]] = inertia[driven[k]].max(m);
            }
        }
    }
    Ok((tau, inertia))
}

#[cfg(test)]
mod tests;
