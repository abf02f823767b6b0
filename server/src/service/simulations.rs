//! Closed-loop simulations of a model's drives (issue 28): the glue between the stored drives,
//! motions and library and [`cad2mo_engine::simulation`]. No HTTP, no SQL of its own (rows are
//! `store::simulations`', the result file goes through [`super::results::upload`]).
//!
//! A run is synchronous and tightly bounded, so it needs no job: at most [`MAX_DURATION`] s of
//! simulated time, [`MAX_STEPS`] solver steps, at most [`MAX_SAMPLES`] output samples and
//! [`MAX_RESULT_VALUES`] numbers in the result file, and a wall-clock limit (the caller's
//! `deadline`); the caller's `cancel` flag (set when the HTTP client goes away) stops it at the
//! next step. What it answers: per drive the tracking error (max, RMS, at each keyframe),
//! current and voltage against their limits and the saturation intervals; the tool frame's error;
//! a verdict against the user's tolerances. The run itself is written as a MAT v4 result with
//! the package's variable names and stored like an uploaded one.

use std::collections::BTreeMap;
use std::net::ToSocketAddrs;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

use super::collisions::{along_run, Edits, RunCollisions, VersionShapes};
use super::drives::{DriveError, ReferenceSpec, ResolvedDrive};
use super::motions::{self, Kinematic, MotionError};
use super::results::ResultError;
use super::FieldError;
use crate::store::StoreError;
use cad2mo_engine::live;
use cad2mo_engine::mechanism::CoordKind;
use cad2mo_engine::motion::plan::{LimitsEdit, MotionSpec, Target};
use cad2mo_engine::pipeline::back::modelica::mechatronics::JointKind;
use cad2mo_engine::simulation::{self as sim, Reference, SimulationError as EngineError};

/// Longest simulated time of a request, s.
pub const MAX_DURATION: f64 = 60.0;
/// Solver steps of one run at most.
pub const MAX_STEPS: u32 = 400_000;
/// Output samples of one run at most (the result file's instants).
pub const MAX_SAMPLES: usize = 2001;
/// Numbers in one result file at most (variables × instants): 80 MB of float64.
pub const MAX_RESULT_VALUES: usize = 10_000_000;
/// The reference of a motion is sampled at this rate (fewer samples for long motions).
pub const REFERENCE_RATE: f64 = 1000.0;
/// Most reference samples per axis.
const MAX_REFERENCE_SAMPLES: usize = 200_000;
/// The solver's tolerances (relative, absolute), stated with every answer.
pub const RTOL: f64 = 1e-6;
pub const ATOL: f64 = 1e-8;
/// Simulated time between live frames by default, s (the packages' `livePeriod`).
pub const LIVE_PERIOD: f64 = 0.02;
/// The shortest time between live frames, s (simulated, and wall-clock when not paced): 60 frames/s.
pub const LIVE_MIN_PERIOD: f64 = 1.0 / 60.0;

/// What a request asks: `{"duration": s, "drives": bool, "motion_id"?: id, "start"?: {joint: value},
/// "max_joint_error"?: rad or m, "max_tool_error"?: m, "tool"?: frame node id}`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SimulationRequest {
    pub duration: f64,
    /// Whether the model's drives act (false: a passive run under gravity and joint losses).
    #[serde(default = "yes")]
    pub drives: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion_id: Option<String>,
    /// Start values of joints (rad or m) by name; the others start at the motion's start or the
    /// CAD pose.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub start: BTreeMap<String, f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_joint_error: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_tool_error: Option<f64>,
    /// The tool frame (CAD node ID) whose error is measured; default: the frame of the motion's
    /// first tool keyframe.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool: Option<String>,
    /// Send the bodies' poses to the live view while the run runs (frames as a package's C
    /// sender makes them, to the service's live port).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub live: bool,
    /// Simulated time between two frames, s ([`LIVE_MIN_PERIOD`] ..= 1; default
    /// [`LIVE_PERIOD`], the packages' `livePeriod`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub live_period: Option<f64>,
    /// Pace the run to the wall clock while it sends frames (default true: the Live tab shows
    /// the motion at its real speed); false: frames as fast as the run makes them, at most one
    /// per [`LIVE_MIN_PERIOD`] of wall-clock time.
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub live_real_time: bool,
}

fn yes() -> bool {
    true
}

fn is_true(b: &bool) -> bool {
    *b
}

/// Why a simulation use case failed.
#[derive(Debug, thiserror::Error)]
pub enum SimulationError {
    /// The request (or the drives it would use) is not usable: each problem names its field.
    #[error("the simulation request is not valid: {}", .0.iter().map(|e| format!("{}: {}", e.field, e.message)).collect::<Vec<_>>().join("; "))]
    Invalid(Vec<FieldError>),
    /// The run hit a bound (steps, wall-clock time) or the integration failed.
    #[error("the simulation stopped: {0}")]
    Stopped(String),
    /// Cancelled by the caller.
    #[error("the simulation was cancelled at t = {0} s")]
    Cancelled(f64),
    #[error("simulation {0} not found")]
    NotFound(String),
    #[error(transparent)]
    Motion(#[from] MotionError),
    #[error(transparent)]
    Drive(#[from] DriveError),
    #[error(transparent)]
    Result(#[from] ResultError),
    #[error(transparent)]
    Store(#[from] StoreError),
    #[error("internal error")]
    Internal(#[from] anyhow::Error),
}

/// One drive's answer.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DriveAnswer {
    pub joint: String,
    pub unit: String,
    pub max_error: f64,
    pub rms_error: f64,
    /// (keyframe time s, error) pairs.
    pub at_keyframes: Vec<[f64; 2]>,
    pub max_current: f64,
    pub i_max: f64,
    pub max_voltage: f64,
    pub v_max: f64,
    /// [from, to] s where the current command or the voltage was limited.
    pub saturated: Vec<[f64; 2]>,
}

/// The tool frame's error along the run: simulated pose against the pose at the references.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ToolAnswer {
    pub frame: String,
    pub max_position_error: f64,
    pub rms_position_error: f64,
    pub max_orientation_error: f64,
}

/// The answer of a run, stored with it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Answer {
    pub ok: bool,
    pub reasons: Vec<String>,
    pub max_joint_error: Option<f64>,
    pub max_tool_error: Option<f64>,
    pub duration: f64,
    pub samples: usize,
    pub keyframes: Vec<f64>,
    pub drives: Vec<DriveAnswer>,
    pub tool: Option<ToolAnswer>,
    /// Independent joints without a drive (they move freely), and drives of joints the version
    /// does not have.
    pub undriven: Vec<String>,
    pub orphaned: Vec<String>,
    /// How it was integrated.
    pub solver: String,
    pub steps: u32,
    pub rejected_steps: u32,
    pub evaluations: u32,
    pub wall_time_s: f64,
    /// Contacts along the simulated motion (bodies and scene objects under the model's
    /// allowed-collision matrix, issue 29); absent in runs stored before it existed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub collisions: Option<RunCollisions>,
    /// What the run sent to the live view, when asked.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub live: Option<LiveSent>,
}

/// The frames a run sent to the live view.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LiveSent {
    /// The frames' run id (docs/live-protocol.md).
    pub run: u32,
    /// Frames sent, and sends the socket refused (a full buffer: the frame is lost).
    pub frames: u32,
    pub send_errors: u32,
    /// Simulated time between frames, s: a whole number of output intervals.
    pub period: f64,
    pub real_time: bool,
    /// Where they went (`host:port`).
    pub to: String,
}

/// Where a run's live frames go, and what they name.
#[derive(Clone, Debug)]
pub struct LiveTarget {
    /// The live view's UDP address as packages reach it (`--live-host`, the bound port).
    pub host: String,
    pub port: u16,
    pub model: [u8; 16],
    pub version: u32,
    /// The version's bodies as the relay knows them (the report's, in order).
    pub bodies: Vec<String>,
    /// The caller's API token where the relay requires signed frames (only its SHA-256 keys the
    /// signature, as in the C sender; the token is not sent).
    pub token: Option<String>,
}

/// What the blocking part of a run makes: the answer and the result file.
pub struct Ran {
    pub answer: Answer,
    pub file: Vec<u8>,
}

/// The inputs of a run besides the request (read from the store by the caller).
pub struct Inputs {
    pub kinematic: Arc<Kinematic>,
    pub motion: Option<(String, MotionSpec)>,
    pub edits: BTreeMap<String, LimitsEdit>,
    pub drives: Vec<ResolvedDrive>,
    /// The version's collision shapes with the model's scene, and the allowed-collision edits:
    /// the simulated motion is checked against them.
    pub collisions: Option<(Arc<VersionShapes>, Edits)>,
    /// Where live frames go when the request asks for them.
    pub live: Option<LiveTarget>,
}

fn kind_of(k: CoordKind) -> JointKind {
    match k {
        CoordKind::Revolute => JointKind::Revolute,
        CoordKind::Prismatic => JointKind::Prismatic,
    }
}

/// Checks the request's own fields (before anything is loaded).
pub fn check_request(req: &SimulationRequest) -> Result<(), SimulationError> {
    let mut errors = Vec::new();
    if !(req.duration.is_finite() && req.duration > 0.0 && req.duration <= MAX_DURATION) {
        errors.push(FieldError { field: "duration".into(), message: format!("must be in (0, {MAX_DURATION}] s, got {}", req.duration) });
    }
    for (name, v) in [("max_joint_error", req.max_joint_error), ("max_tool_error", req.max_tool_error)] {
        if let Some(v) = v {
            if !(v.is_finite() && v > 0.0) {
                errors.push(FieldError { field: name.into(), message: format!("must be a positive number, got {v}") });
            }
        }
    }
    if let Some(p) = req.live_period {
        if !(p.is_finite() && (LIVE_MIN_PERIOD..=1.0).contains(&p)) {
            errors.push(FieldError { field: "live_period".into(), message: format!("must be in [1/60, 1] s, got {p}") });
        }
    }
    for (j, v) in &req.start {
        if !v.is_finite() {
            errors.push(FieldError { field: format!("start.{j}"), message: "must be a finite number".into() });
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(SimulationError::Invalid(errors))
    }
}

/// Runs the simulation (blocking: call it off the runtime). `cancel` stops it at the next step;
/// beyond `deadline` of wall-clock time it stops with [`SimulationError::Stopped`].
pub fn run(req: &SimulationRequest, inputs: &Inputs, cancel: &AtomicBool, deadline: Duration) -> Result<Ran, SimulationError> {
    check_request(req)?;
    let k = &inputs.kinematic;
    let m = &k.mech;
    let coords = m.coordinates();
    let n = m.dof();
    // The reference of a motion, sampled.
    let (planned, samples) = match &inputs.motion {
        None => (None, None),
        Some((name, spec)) => {
            let p = motions::plan_motion(k, &inputs.edits, spec)?;
            let rate = REFERENCE_RATE.min(MAX_REFERENCE_SAMPLES as f64 / p.duration.max(1e-9)).max(1.0);
            let s = p.closed_samples(m, rate).map_err(|i| motions::invalid(&format!("motion \"{name}\" cannot be planned"), i))?;
            (Some(p), Some(s))
        }
    };
    // Start: the motion's start (else the CAD pose), with the request's values.
    let mut q = match &samples {
        Some(s) => (0..n).map(|i| s.q.get(i).and_then(|a| a.first()).copied().unwrap_or(coords[i].q0)).collect(),
        None => m.q0(),
    };
    let mut errors = Vec::new();
    for (j, v) in &req.start {
        match coords.iter().position(|c| &c.name == j) {
            Some(i) if coords[i].independent => q[i] = *v,
            Some(_) => errors.push(FieldError {
                field: format!("start.{j}"),
                message: "follows other joints (a loop or a mimic coupling): give the independent ones".into(),
            }),
            None => errors.push(FieldError {
                field: format!("start.{j}"),
                message: format!(
                    "is not a joint of the model (its joints: {})",
                    coords.iter().map(|c| c.name.as_str()).collect::<Vec<_>>().join(", ")
                ),
            }),
        }
    }
    // Drives.
    let mut drives = Vec::new();
    let mut names = Vec::new();
    let mut orphaned = Vec::new();
    if req.drives {
        for d in &inputs.drives {
            let Some(c) = coords.iter().position(|c| c.name == d.joint) else {
                orphaned.push(d.joint.clone());
                continue;
            };
            if !coords[c].independent {
                errors.push(FieldError {
                    field: format!("drives.{}", d.joint),
                    message: "drives a joint that follows others (loop or mimic): the simulation drives independent joints only".into(),
                });
                continue;
            }
            let reference = match (&samples, &d.reference) {
                (Some(s), _) => Reference::Motion { t: s.t.clone(), q: s.q[c].clone(), qd: s.qd[c].clone() },
                (None, ReferenceSpec::Constant { value }) => Reference::Constant(*value),
                (None, ReferenceSpec::Table { points }) => Reference::Table(points.iter().map(|p| (p[0], p[1])).collect()),
            };
            match sim::drive_of(&format!("drives.{}", d.joint), c, kind_of(coords[c].kind), &d.motor, &d.gear, &d.controller, reference) {
                Ok(x) => {
                    drives.push(x);
                    names.push(d.joint.clone());
                }
                Err(EngineError::Field { field, message }) => errors.push(FieldError { field, message }),
                Err(e) => return Err(SimulationError::Internal(anyhow::anyhow!(e.to_string()))),
            }
        }
    }
    // The tool frame.
    let tool_name = req.tool.clone().or_else(|| {
        inputs.motion.as_ref().and_then(|(_, spec)| {
            spec.keyframes.iter().find_map(|kf| match &kf.target {
                Target::Tool { frame, .. } => Some(frame.clone()),
                Target::Joints { .. } => None,
            })
        })
    });
    let tool = match &tool_name {
        None => None,
        Some(f) => match m.frame_by_node_id(f) {
            Ok(id) => Some((f.clone(), id)),
            Err(e) => {
                errors.push(FieldError { field: "tool".into(), message: e.to_string() });
                None
            }
        },
    };
    if req.max_tool_error.is_some() && tool_name.is_none() {
        errors.push(FieldError {
            field: "max_tool_error".into(),
            message: "needs a tool frame (tool, or a motion with a tool keyframe)".into(),
        });
    }
    let live = match (&req.live, &inputs.live) {
        (false, _) => None,
        (true, None) => {
            errors.push(FieldError { field: "live".into(), message: "the service's live view is off".into() });
            None
        }
        (true, Some(target)) if target.bodies.len() > live::MAX_BODIES => {
            errors.push(FieldError {
                field: "live".into(),
                message: format!("the model has {} bodies: a live frame holds at most {}", target.bodies.len(), live::MAX_BODIES),
            });
            None
        }
        (true, Some(target)) if target.bodies != m.body_names() => {
            errors.push(FieldError {
                field: "live".into(),
                message: "the version's bodies as the live view knows them differ from the simulated mechanism's".into(),
            });
            None
        }
        (true, Some(target)) => match (target.host.as_str(), target.port).to_socket_addrs().map(|mut a| a.next()) {
            Ok(Some(addr)) => Some((target, addr)),
            Ok(None) | Err(_) => {
                errors.push(FieldError {
                    field: "live".into(),
                    message: format!("the live view's address {}:{} does not resolve", target.host, target.port),
                });
                None
            }
        },
    };
    if !errors.is_empty() {
        return Err(SimulationError::Invalid(errors));
    }
    // Output samples within the file's bound.
    let placed = (0..m.body_names().len()).filter(|&b| m.body_attachment(cad2mo_engine::pipeline::ir::BodyId(b as u32)).is_some()).count();
    // Per drive 12 signals, 17 with the MSL machine's own names.
    let variables = 1 + 3 * n + 17 * drives.len() + 12 * placed;
    let instants = MAX_SAMPLES.min(MAX_RESULT_VALUES / variables.max(1)).max(2);
    let opts = sim::Options {
        duration: req.duration,
        output_interval: req.duration / (instants - 1) as f64,
        rtol: RTOL,
        atol: ATOL,
        max_steps: MAX_STEPS,
        h_max: 0.0,
    };
    let started = Instant::now();
    let timed_out = AtomicBool::new(false);
    let stop = || {
        if started.elapsed() > deadline {
            timed_out.store(true, Ordering::Relaxed);
            return true;
        }
        cancel.load(Ordering::Relaxed)
    };
    let start = sim::Start { q, qd: vec![0.0; n] };
    let losses = sim::JointLosses(m);
    let mut sender = match live {
        None => None,
        Some((target, addr)) => Some(LiveSender::new(m, target, addr, req, opts.output_interval, cancel).map_err(|e| {
            SimulationError::Invalid(vec![FieldError { field: "live".into(), message: format!("cannot send to the live view: {e}") }])
        })?),
    };
    let observer = sender.as_mut().map(|s| s as &mut dyn sim::Observer);
    let run = match sim::simulate_observed(m, &k.gravity, &drives, &losses, &start, &opts, &stop, observer) {
        Ok(r) => r,
        Err(EngineError::Cancelled { t }) if timed_out.load(Ordering::Relaxed) => {
            return Err(SimulationError::Stopped(format!(
                "the run took longer than its time limit of {} s (reached t = {t:.4} s of {} s): shorten the duration",
                deadline.as_secs_f64(),
                req.duration
            )))
        }
        Err(EngineError::Cancelled { t }) => return Err(SimulationError::Cancelled(t)),
        Err(EngineError::Field { field, message }) => return Err(SimulationError::Invalid(vec![FieldError { field, message }])),
        Err(EngineError::Integration { t, message }) => return Err(SimulationError::Stopped(format!("at t = {t} s: {message}"))),
        Err(EngineError::Mechanism(e)) => return Err(SimulationError::Stopped(e.to_string())),
    };
    let wall_time_s = started.elapsed().as_secs_f64();
    // The answer.
    let keyframes: Vec<f64> = planned.as_ref().map(|p| p.keyframes.iter().map(|kf| kf.time).collect()).unwrap_or_default();
    let tracking = run.tracking(&drives, &keyframes);
    let tool_errors = match &tool {
        Some((_, id)) => Some(run.tool_error(m, &drives, *id).map_err(|e| SimulationError::Stopped(e.to_string()))?),
        None => None,
    };
    let all_names: Vec<String> = coords.iter().map(|c| c.name.clone()).collect();
    let tol = sim::Tolerances { max_joint_error: req.max_joint_error.unwrap_or(f64::INFINITY), max_tool_error: req.max_tool_error };
    let mut verdict = sim::verdict(&tracking, &all_names, tool_errors.as_deref(), &tol);
    // The simulated (not the planned) motion against the bodies and the scene.
    let collisions = match &inputs.collisions {
        Some((shapes, edits)) => Some(along_run(m, shapes, edits, &run.t, &run.q).map_err(|e| SimulationError::Stopped(e.to_string()))?),
        None => None,
    };
    if let Some(c) = collisions.as_ref().and_then(|c| c.first_contact.as_ref()) {
        verdict.ok = false;
        verdict.reasons.push(format!("{} touches {} at t = {:.4} s", c.a, c.b, c.time));
    }
    let unit = |c: usize| if coords[c].kind == CoordKind::Prismatic { "m" } else { "rad" };
    let answer = Answer {
        ok: verdict.ok,
        reasons: verdict.reasons,
        max_joint_error: req.max_joint_error,
        max_tool_error: req.max_tool_error,
        duration: req.duration,
        samples: run.t.len(),
        keyframes,
        drives: tracking
            .iter()
            .map(|t| DriveAnswer {
                joint: all_names[t.coordinate].clone(),
                unit: unit(t.coordinate).into(),
                max_error: t.max_error,
                rms_error: t.rms_error,
                at_keyframes: t.at_keyframes.iter().map(|(a, b)| [*a, *b]).collect(),
                max_current: t.max_current,
                i_max: t.i_max,
                max_voltage: t.max_voltage,
                v_max: t.v_max,
                saturated: t.saturated.iter().map(|(a, b)| [*a, *b]).collect(),
            })
            .collect(),
        tool: tool.as_ref().zip(tool_errors.as_ref()).map(|((name, _), e)| ToolAnswer {
            frame: name.clone(),
            max_position_error: e.iter().fold(0.0f64, |a, x| a.max(x.0)),
            rms_position_error: (e.iter().map(|x| x.0 * x.0).sum::<f64>() / e.len().max(1) as f64).sqrt(),
            max_orientation_error: e.iter().fold(0.0f64, |a, x| a.max(x.1)),
        }),
        undriven: coords
            .iter()
            .enumerate()
            .filter(|(i, c)| c.independent && !drives.iter().any(|d| d.coordinate == *i))
            .map(|(_, c)| c.name.clone())
            .collect(),
        orphaned,
        solver: format!("Dormand-Prince 5(4) with error control, breakpoints at the reference samples and saturation events (simulation::integrate), rtol {RTOL:e}, atol {ATOL:e}"),
        steps: run.accepted_steps,
        rejected_steps: run.rejected_steps,
        evaluations: run.evaluations,
        wall_time_s,
        collisions,
        live: sender.map(|s| s.sent()),
    };
    let file = sim::result_file(m, &run, &drives).map_err(|e| SimulationError::Internal(anyhow::anyhow!(e.to_string())))?;
    Ok(Ran { answer, file })
}

/// Sends a run's body poses to the live view as the packages' C sender does
/// (`Resources/Include/cad2mo_live.c`, docs/live-protocol.md): one UDP datagram per frame, never
/// blocking (a full buffer loses that frame), signed with the caller's token where the relay
/// requires it, the last one `FINAL`. A frame at every `stride`-th output sample, `stride` the
/// fewest output intervals that make up the requested period; paced to the wall clock unless
/// the request says otherwise (then at most one frame per [`LIVE_MIN_PERIOD`] of wall-clock time).
struct LiveSender<'a> {
    m: &'a cad2mo_engine::mechanism::Mechanism,
    socket: std::net::UdpSocket,
    to: std::net::SocketAddr,
    header: live::Header,
    token: Option<&'a str>,
    stride: usize,
    period: f64,
    real_time: bool,
    started: Instant,
    last_sent: Option<Instant>,
    frames: u32,
    send_errors: u32,
    cancel: &'a AtomicBool,
}

impl<'a> LiveSender<'a> {
    fn new(
        m: &'a cad2mo_engine::mechanism::Mechanism,
        target: &'a LiveTarget,
        to: std::net::SocketAddr,
        req: &SimulationRequest,
        interval: f64,
        cancel: &'a AtomicBool,
    ) -> std::io::Result<LiveSender<'a>> {
        let local: std::net::SocketAddr = if to.is_ipv4() { ([0u8; 4], 0).into() } else { ([0u16; 8], 0).into() };
        let socket = std::net::UdpSocket::bind(local)?;
        socket.set_nonblocking(true)?;
        let wanted = req.live_period.unwrap_or(LIVE_PERIOD);
        let stride = ((wanted / interval) * (1.0 - 1e-12)).ceil().max(1.0) as usize;
        let id = uuid::Uuid::new_v4();
        let run = u32::from_le_bytes([id.as_bytes()[0], id.as_bytes()[1], id.as_bytes()[2], id.as_bytes()[3]]);
        let header = live::Header {
            model: target.model,
            version: target.version,
            layout: live::layout_id(&target.bodies),
            run,
            seq: 0,
            time: 0.0,
            last: false,
        };
        Ok(LiveSender {
            m,
            socket,
            to,
            header,
            token: target.token.as_deref(),
            stride,
            period: stride as f64 * interval,
            real_time: req.live_real_time,
            started: Instant::now(),
            last_sent: None,
            frames: 0,
            send_errors: 0,
            cancel,
        })
    }

    fn sent(&self) -> LiveSent {
        LiveSent {
            run: self.header.run,
            frames: self.frames,
            send_errors: self.send_errors,
            period: self.period,
            real_time: self.real_time,
            to: self.to.to_string(),
        }
    }
}

impl sim::Observer for LiveSender<'_> {
    fn wants(&mut self, index: usize, _t: f64, last: bool) -> bool {
        if last {
            return true;
        }
        if index % self.stride != 0 {
            return false;
        }
        self.real_time || self.last_sent.is_none_or(|w| w.elapsed().as_secs_f64() >= LIVE_MIN_PERIOD)
    }

    fn sample(&mut self, _index: usize, t: f64, last: bool, q: &[f64]) {
        if self.real_time {
            // Not ahead of the wall clock; a cancelled run stops waiting.
            let due = self.started + Duration::from_secs_f64(t);
            while let Some(wait) = due.checked_duration_since(Instant::now()) {
                if self.cancel.load(Ordering::Relaxed) {
                    return;
                }
                std::thread::sleep(wait.min(Duration::from_millis(50)));
            }
        }
        let Ok(bodies) = sim::body_frames(self.m, q) else { return };
        self.header.time = t;
        self.header.last = last;
        let frame = live::encode(&self.header, &bodies, self.token);
        match self.socket.send_to(&frame, self.to) {
            Ok(_) => self.frames += 1,
            Err(_) => self.send_errors += 1,
        }
        self.header.seq = self.header.seq.wrapping_add(1);
        self.last_sent = Some(Instant::now());
    }
}

/// A stored simulation as served.
#[derive(Clone, Debug, Serialize)]
pub struct SimulationView {
    pub id: String,
    pub model_id: String,
    pub version: i64,
    pub motion_id: Option<String>,
    pub result_id: Option<String>,
    pub created_at: String,
    pub request: serde_json::Value,
    #[serde(flatten)]
    pub answer: Answer,
}

impl TryFrom<crate::store::simulations::SimulationRow> for SimulationView {
    type Error = SimulationError;

    fn try_from(r: crate::store::simulations::SimulationRow) -> Result<Self, SimulationError> {
        let corrupt = |e: serde_json::Error| SimulationError::Internal(anyhow::anyhow!("stored simulation {}: {e}", r.id));
        let request = serde_json::from_str(&r.request_json).map_err(corrupt)?;
        let answer = serde_json::from_str(&r.answer_json).map_err(corrupt)?;
        Ok(SimulationView {
            id: r.id,
            model_id: r.model_id,
            version: r.version,
            motion_id: r.motion_id,
            result_id: r.result_id,
            created_at: r.created_at,
            request,
            answer,
        })
    }
}

/// Stores a finished run: its result file (like an uploaded result of the version, summarised
/// against the mechanism) and its row.
pub async fn store_run(
    store: &crate::store::Store,
    blobs: &crate::store::blobs::Blobs,
    model_id: &str,
    version: i64,
    req: &SimulationRequest,
    kinematic: Arc<Kinematic>,
    ran: Ran,
) -> Result<SimulationView, SimulationError> {
    let label = req.motion_id.as_deref().map(|m| format!("motion-{}", &m[..m.len().min(8)])).unwrap_or_else(|| "drives".into());
    let name = format!("simulation-{label}.mat");
    let stored = super::results::upload(store, blobs, Some((model_id, version)), name, ran.file, move |t, name| {
        cad2mo_engine::results::summarise(t, &kinematic.mech, name).map(|(s, _)| s)
    })
    .await?;
    let request_json = serde_json::to_string(req).map_err(|e| SimulationError::Internal(e.into()))?;
    let answer_json = serde_json::to_string(&ran.answer).map_err(|e| SimulationError::Internal(e.into()))?;
    let row = crate::store::simulations::insert(
        store,
        model_id,
        version,
        req.motion_id.as_deref(),
        Some(&stored.row.id),
        &request_json,
        &answer_json,
    )
    .await?;
    SimulationView::try_from(row)
}

/// A model's simulation `id`.
pub async fn get(store: &crate::store::Store, model_id: &str, id: &str) -> Result<SimulationView, SimulationError> {
    let row = crate::store::simulations::get(store, model_id, id).await?.ok_or_else(|| SimulationError::NotFound(id.to_string()))?;
    SimulationView::try_from(row)
}

/// A model's simulations (of one motion when given), oldest first.
pub async fn list(store: &crate::store::Store, model_id: &str, motion_id: Option<&str>) -> Result<Vec<SimulationView>, SimulationError> {
    crate::store::simulations::list(store, model_id, motion_id).await?.into_iter().map(SimulationView::try_from).collect()
}
