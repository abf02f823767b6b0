//! Motions on a converted version: the glue between stored data (limits, motion specs, the
//! version's bundle and names) and the computation modules ([`cad2mo_engine::mechanism`],
//! [`cad2mo_engine::motion`], `cad2mo_engine::sizing`). No HTTP, no SQL: the API and the job worker call it.
//!
//! [`Kinematic::load`] analyses a version's bundle again (front ends, passes, validation; no
//! shapes) and names every coordinate exactly as the version's package does (its report's names
//! are the hints, so the same names come back); the API keeps a few of these in a [`Cache`].

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use nalgebra::Vector3;
use serde::Serialize;

use super::drives::DriveError;
use super::FieldError;
use crate::service::export::{self, ExportOptions};
use crate::store::StoreError;
use cad2mo_engine::library::Issue;
use cad2mo_engine::mechanism::{CoordKind, Mechanism};
use cad2mo_engine::motion::plan::{self, Axis, AxisLimits, LimitsEdit, MotionSpec, Planned, Samples};
use cad2mo_engine::pipeline;
use cad2mo_engine::pipeline::ir::{FrameId, FrameOwner};

/// Highest sampling rate of a trajectory request, Hz.
pub const MAX_RATE: f64 = 10_000.0;
/// The rate of inverse dynamics and sizing, Hz (the issue's 1 kHz).
pub const SIZING_RATE: f64 = 1000.0;
/// The rate of the tables written into `Mechatronics.mo`, Hz (linear interpolation between
/// samples; a 10 s motion of 6 axes is 3 x 6 x 1001 numbers).
pub const TABLE_RATE: f64 = 100.0;

/// A CAD frame a tool can be (a frame on a body), with its pose at the CAD pose.
#[derive(Clone, Debug, Serialize)]
pub struct FrameInfo {
    pub node_id: String,
    /// The Modelica name of its body.
    pub body: String,
    /// `CS2`, or the frame's display name.
    pub name: String,
    pub position: [f64; 3],
    /// Rows of the rotation frame -> world.
    pub rotation: [[f64; 3]; 3],
}

/// A version's mechanism, named as its package.
pub struct Kinematic {
    pub mech: Mechanism,
    /// The CAD node ID of each coordinate's joint.
    pub joint_node_ids: Vec<String>,
    pub frames: Vec<FrameInfo>,
    pub gravity: Vector3<f64>,
}

/// Why a motion use case failed.
#[derive(Debug, thiserror::Error)]
pub enum MotionError {
    /// The model is beyond what the motion analysis handles (the message says what).
    #[error("the motion analysis cannot handle this model: {0}")]
    Unsupported(String),
    /// The motion cannot be planned (IK failed, limits violated, unknown joint, ...).
    #[error("{detail}")]
    CannotPlan { detail: String, errors: Vec<FieldError> },
    /// A request parameter out of range (the message names it and its bounds).
    #[error("{0}")]
    OutOfRange(String),
    /// The sizing's settings are not usable (each problem names its field).
    #[error("the sizing settings are not usable: {}", .0.iter().map(|e| format!("{}: {}", e.field, e.message)).collect::<Vec<_>>().join("; "))]
    BadSettings(Vec<FieldError>),
    /// The inverse dynamics failed on a planned motion (not the user's fault).
    #[error("inverse dynamics: {0}")]
    Dynamics(String),
    /// The version's bundle no longer reads or converts.
    #[error(transparent)]
    Export(#[from] export::ExportError),
    #[error(transparent)]
    Drive(#[from] DriveError),
    #[error(transparent)]
    Store(#[from] StoreError),
}

impl From<pipeline::ConvertError> for MotionError {
    fn from(e: pipeline::ConvertError) -> Self {
        MotionError::Export(export::ExportError::Convert(e))
    }
}

fn unsupported(what: String) -> MotionError {
    MotionError::Unsupported(what)
}

impl Kinematic {
    /// Analyses `bundle` (as stored with the version) with its options; `report` is the version's
    /// report.json (its names are kept).
    pub fn load(bundle: &[u8], bundle_name: &str, options: &ExportOptions, report: &serde_json::Value) -> Result<Kinematic, MotionError> {
        let b = export::read_bundle(bundle, bundle_name).map_err(export::ExportError::from)?;
        let mut opts = options.pipeline();
        opts.write_shapes = false;
        let a = pipeline::analyse(&b, &opts)?;
        let pkg = pipeline::back::modelica::write(
            &a.model,
            &a.validated,
            &pipeline::back::modelica::Options {
                package_name: "P".into(),
                gravity: options.gravity.unwrap_or_else(|| pipeline::default_gravity(&a.model)),
                converter_version: pipeline::VERSION.to_string(),
                name_hints: pipeline::name_hints(report),
            },
        );
        let mut mech = Mechanism::from_validated(&a.model, &a.validated).map_err(|e| unsupported(e.to_string()))?;
        mech.use_layout_names(&pkg.layout);
        let joint_node_ids = mech.coordinates().iter().map(|c| a.model.joints[c.joint.index()].node_id.clone()).collect();
        let k = mech.forward(&mech.q0()).map_err(|e| unsupported(e.to_string()))?;
        let mut frames = Vec::new();
        for (i, f) in a.model.frames.iter().enumerate() {
            let FrameOwner::Body(b) = f.owner else { continue };
            let Ok(pose) = mech.frame_pose(&k, FrameId(i as u32)) else { continue };
            let r = pose.rotation.to_rotation_matrix();
            let p = pose.translation.vector;
            frames.push(FrameInfo {
                node_id: f.node_id.clone(),
                body: mech.body_names().get(b.index()).cloned().unwrap_or_default(),
                name: if f.display_name.is_empty() { f.name.clone() } else { f.display_name.clone() },
                position: [p.x, p.y, p.z],
                rotation: [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[(i, j)])),
            });
        }
        Ok(Kinematic {
            mech,
            joint_node_ids,
            frames,
            gravity: Vector3::from(options.gravity.unwrap_or_else(|| pipeline::default_gravity(&a.model))),
        })
    }
}

/// A few entries (analysed versions, a version's collision shapes), most recently used last:
/// making one takes seconds for a large bundle.
pub struct Cache<T = Kinematic>(Arc<Mutex<Vec<CacheEntry<T>>>>);

type CacheEntry<T> = (String, Arc<T>);

impl<T> Clone for Cache<T> {
    fn clone(&self) -> Self {
        Cache(self.0.clone())
    }
}

impl<T> Default for Cache<T> {
    fn default() -> Self {
        Cache(Arc::new(Mutex::new(Vec::new())))
    }
}

impl<T> Cache<T> {
    const SIZE: usize = 8;

    pub fn get(&self, key: &str) -> Option<Arc<T>> {
        let mut v = self.0.lock().unwrap_or_else(|p| p.into_inner());
        let i = v.iter().position(|(k, _)| k == key)?;
        let e = v.remove(i);
        let out = e.1.clone();
        v.push(e);
        Some(out)
    }

    pub fn put(&self, key: String, k: Arc<T>) {
        let mut v = self.0.lock().unwrap_or_else(|p| p.into_inner());
        v.retain(|(x, _)| *x != key);
        if v.len() >= Self::SIZE {
            v.remove(0);
        }
        v.push((key, k));
    }
}

/// A joint of the joints view.
#[derive(Clone, Debug, Serialize)]
pub struct JointView {
    pub name: String,
    pub joint_node_id: String,
    pub kind: &'static str,
    pub unit: &'static str,
    pub q0: f64,
    pub independent: bool,
    pub limits: AxisLimits,
    pub defaults: AxisLimits,
    /// The joint's effort limit from the source (URDF), N·m or N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effort: Option<f64>,
    pub custom: bool,
    /// Set where the joint follows another by a mimic coupling (then `independent` is false).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mimic: Option<MimicView>,
    /// Viscous damping from the source (URDF `<dynamics damping>`), N·m·s/rad or N·s/m; absent
    /// when zero.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping: Option<f64>,
    /// Coulomb friction from the source (URDF `<dynamics friction>`), N·m or N; absent when zero.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
}

/// A follower's coupling: its value is `multiplier * leader + offset`.
#[derive(Clone, Debug, Serialize)]
pub struct MimicView {
    pub leader: String,
    pub multiplier: f64,
    pub offset: f64,
}

/// Limits stored for a joint the version does not have.
#[derive(Clone, Debug, Serialize)]
pub struct OrphanLimits {
    pub joint: String,
    pub limits: LimitsEdit,
}

#[derive(Clone, Debug, Serialize)]
pub struct JointsView {
    pub version: i64,
    pub joints: Vec<JointView>,
    pub frames: Vec<FrameInfo>,
    pub orphans: Vec<OrphanLimits>,
}

fn kind_unit(k: CoordKind) -> (&'static str, &'static str) {
    match k {
        CoordKind::Revolute => ("revolute", "rad"),
        CoordKind::Prismatic => ("prismatic", "m"),
    }
}

/// The joints of a version with their limits (stored edits applied), its tool frames, and the
/// edits whose joint it lacks.
pub fn joints_view(k: &Kinematic, version: i64, edits: &BTreeMap<String, LimitsEdit>) -> JointsView {
    let axes = plan::axes(&k.mech, edits);
    let joints = k
        .mech
        .coordinates()
        .iter()
        .zip(&axes)
        .zip(&k.joint_node_ids)
        .enumerate()
        .map(|(i, ((c, a), node))| {
            let (kind, unit) = kind_unit(c.kind);
            JointView {
                name: c.name.clone(),
                joint_node_id: node.clone(),
                kind,
                unit,
                q0: c.q0,
                independent: c.independent,
                limits: a.limits,
                defaults: AxisLimits::for_coordinate(c),
                effort: c.source_limits.as_ref().and_then(|l| l.effort),
                custom: edits.contains_key(&c.name),
                mimic: k.mech.coupling_of(i).map(|m| MimicView {
                    leader: k.mech.coordinates().get(m.leader).map(|l| l.name.clone()).unwrap_or_default(),
                    multiplier: m.multiplier,
                    offset: m.offset,
                }),
                damping: Some(c.losses.damping).filter(|d| *d != 0.0),
                friction: Some(c.losses.friction).filter(|f| *f != 0.0),
            }
        })
        .collect();
    let orphans = edits
        .iter()
        .filter(|(j, _)| !k.mech.coordinates().iter().any(|c| &c.name == *j))
        .map(|(j, e)| OrphanLimits { joint: j.clone(), limits: *e })
        .collect();
    JointsView { version, joints, frames: k.frames.clone(), orphans }
}

/// Issues that stop a motion from being planned, with a one-line summary.
pub fn invalid(what: &str, issues: Vec<Issue>) -> MotionError {
    let detail = match issues.first() {
        Some(i) if issues.len() == 1 => format!("{what}: {}", i.message),
        Some(i) => format!("{what}: {} (and {} more problems)", i.message, issues.len() - 1),
        None => what.to_string(),
    };
    MotionError::CannotPlan { detail, errors: issues.into_iter().map(FieldError::from).collect() }
}

/// Plans a stored motion on a version.
pub fn plan_motion(k: &Kinematic, edits: &BTreeMap<String, LimitsEdit>, spec: &MotionSpec) -> Result<Planned, MotionError> {
    let axes: Vec<Axis> = plan::axes(&k.mech, edits);
    plan::plan(&k.mech, &axes, spec).map_err(|i| invalid(&format!("motion \"{}\" cannot be planned", spec.name), i))
}

/// A sampled trajectory with its torques.
#[derive(Clone, Debug, Serialize)]
pub struct TrajectoryView {
    pub motion: String,
    pub version: i64,
    pub duration: f64,
    pub rate: f64,
    pub joints: Vec<String>,
    pub units: Vec<&'static str>,
    #[serde(flatten)]
    pub samples: Samples,
    pub tau: Vec<Vec<f64>>,
    pub keyframes: Vec<plan::PlannedKeyframe>,
}

/// Samples a planned motion at `rate` with the inverse dynamics along it.
pub fn trajectory(k: &Kinematic, version: i64, name: &str, p: &Planned, rate: f64) -> Result<TrajectoryView, MotionError> {
    if !(rate.is_finite() && (1.0..=MAX_RATE).contains(&rate)) {
        return Err(MotionError::OutOfRange(format!("rate must be between 1 and {MAX_RATE} Hz (is {rate})")));
    }
    if p.sample_count(rate) > plan::MAX_SAMPLES {
        return Err(MotionError::OutOfRange(format!(
            "{} samples is more than {}: lower the rate",
            p.sample_count(rate),
            plan::MAX_SAMPLES
        )));
    }
    let samples = p.closed_samples(&k.mech, rate).map_err(|i| invalid(&format!("motion \"{name}\" cannot be planned"), i))?;
    let (tau, _) = plan::inverse_dynamics(&k.mech, &samples, &k.gravity, usize::MAX).map_err(|e| MotionError::Dynamics(e.to_string()))?;
    Ok(TrajectoryView {
        motion: name.to_string(),
        version,
        duration: p.duration,
        rate,
        joints: p.axes.iter().map(|a| a.name.clone()).collect(),
        units: p.axes.iter().map(|a| kind_unit(a.kind).1).collect(),
        samples,
        tau,
        keyframes: p.keyframes.clone(),
    })
}

/// A motion left out of a package, and why.
#[derive(Clone, Debug, Serialize)]
pub struct Skipped {
    pub motion: String,
    pub problem: String,
}

/// Issues in one line for a report, clipped.
fn one_line(issues: &[Issue]) -> String {
    let text = issues.iter().map(|i| i.message.as_str()).collect::<Vec<_>>().join("; ");
    pipeline::ir::clip(&text, 1000)
}

/// A motion planned for a package: its table, and what the sizing needs.
pub struct ForPackage {
    pub table: pipeline::back::modelica::mechatronics::MotionTable,
    pub planned: Planned,
}

/// Plans the model's motions on a converted model (the package being written): tables at
/// [`TABLE_RATE`] for `Mechatronics.mo`; motions that cannot be planned on this version are
/// skipped with their problem (the package is still written).
pub fn for_package(
    view: &pipeline::observe::ModelView<'_>,
    specs: &[MotionSpec],
    edits: &BTreeMap<String, LimitsEdit>,
) -> (Option<Mechanism>, Vec<ForPackage>, Vec<Skipped>) {
    let mut skipped = Vec::new();
    if specs.is_empty() {
        return (None, Vec::new(), skipped);
    }
    let mut mech = match Mechanism::from_validated(view.model, view.validated) {
        Ok(m) => m,
        Err(e) => {
            let problem = format!("the motion analysis cannot handle this model: {e}");
            skipped.extend(specs.iter().map(|s| Skipped { motion: s.name.clone(), problem: problem.clone() }));
            return (None, Vec::new(), skipped);
        }
    };
    mech.use_layout_names(view.layout);
    let axes = plan::axes(&mech, edits);
    let mut out = Vec::new();
    for spec in specs {
        match plan::plan(&mech, &axes, spec) {
            Ok(p) if p.sample_count(TABLE_RATE) <= plan::MAX_SAMPLES => {
                let s = match p.closed_samples(&mech, TABLE_RATE) {
                    Ok(s) => s,
                    Err(issues) => {
                        skipped.push(Skipped { motion: spec.name.clone(), problem: one_line(&issues) });
                        continue;
                    }
                };
                let table = pipeline::back::modelica::mechatronics::MotionTable {
                    label: spec.name.clone(),
                    axes: axes.iter().map(|a| a.name.clone()).collect(),
                    t: s.t,
                    q: s.q,
                    qd: s.qd,
                    qdd: s.qdd,
                };
                out.push(ForPackage { table, planned: p });
            }
            Ok(_) => skipped.push(Skipped { motion: spec.name.clone(), problem: "too long for a table".into() }),
            Err(issues) => skipped.push(Skipped { motion: spec.name.clone(), problem: one_line(&issues) }),
        }
    }
    (Some(mech), out, skipped)
}

/// A drive as stored, with its library parts (for sizing).
#[derive(Clone, Debug)]
pub struct DriveParts {
    pub joint: String,
    pub motor: (cad2mo_engine::library::Instance, cad2mo_engine::library::Class),
    pub gear: (cad2mo_engine::library::Instance, cad2mo_engine::library::Class),
    pub overrides: serde_json::Map<String, serde_json::Value>,
}

/// A drive that cannot be sized, and why.
#[derive(Clone, Debug, Serialize)]
pub struct NotSized {
    pub joint: String,
    pub problem: String,
}

/// The user's sizing settings as a request gives them (no HTTP here): a drive amplifier of the
/// library with the supply voltage, the reserve, the dwell of the duty cycle, and a brake resistor
/// or a DC bus.
#[derive(Clone, Debug, Default, serde::Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SizingRequest {
    /// 0 to below 1; default [`cad2mo_engine::sizing::DEFAULT_RESERVE`].
    pub reserve: Option<f64>,
    /// Seconds between repetitions of the motion; default 0.
    pub dwell: Option<f64>,
    /// A library instance of domain `amplifier`.
    pub amplifier: Option<String>,
    /// The amplifier's supply (DC bus) voltage, V.
    pub supply_voltage: Option<f64>,
    /// A brake resistor's continuous power, W.
    pub brake_power: Option<f64>,
    /// The DC bus's capacitance (F) and highest voltage (V).
    pub bus_capacitance: Option<f64>,
    pub bus_voltage_max: Option<f64>,
    /// The required nominal life of a ball or lead screw, h of the repeated duty cycle.
    pub screw_life: Option<f64>,
}

/// The settings a sizing ran with, as the report states them.
#[derive(Clone, Debug, Serialize)]
pub struct SizingSettings {
    pub reserve: f64,
    pub dwell: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub screw_life: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplifier: Option<AmplifierView>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub brake: Option<cad2mo_engine::sizing::Brake>,
}

/// The amplifier of a sizing: its datasheet values and the supply voltage set.
#[derive(Clone, Debug, Serialize)]
pub struct AmplifierView {
    pub id: String,
    pub name: String,
    pub supply_voltage: Option<f64>,
    pub u_min: Option<f64>,
    pub u_max: Option<f64>,
    pub i_cont: Option<f64>,
    pub i_peak: Option<f64>,
    pub source: String,
}

/// The request's settings against the library: every problem names its field (`reserve`,
/// `amplifier`, `supply_voltage`, `brake_power`, `bus_capacitance`, `bus_voltage_max`).
pub fn sizing_settings(
    req: &SizingRequest,
    library: &cad2mo_engine::library::Library,
) -> Result<cad2mo_engine::sizing::Settings, MotionError> {
    use cad2mo_engine::sizing::{Brake, Settings};
    let mut errors: Vec<FieldError> = Vec::new();
    let amplifier = match &req.amplifier {
        None => {
            if req.supply_voltage.is_some() {
                errors
                    .push(FieldError { field: "supply_voltage".into(), message: "a supply voltage needs an amplifier (amplifier)".into() });
            }
            None
        }
        Some(id) => {
            let found = cad2mo_engine::library::parse_id(id)
                .and_then(|id| library.instances.iter().find(|i| i.id == id))
                .and_then(|i| library.class(&i.class_id).map(|c| (c, i)));
            match found {
                None => {
                    errors.push(FieldError { field: "amplifier".into(), message: format!("no library instance has the id \"{id}\"") });
                    None
                }
                Some((c, i)) => match cad2mo_engine::sizing::parts::amplifier(c, i, req.supply_voltage) {
                    Ok(a) => Some(a),
                    Err(_) => {
                        errors.push(FieldError {
                            field: "amplifier".into(),
                            message: format!("\"{}\" is a {} of class \"{}\", not an amplifier", i.name, c.domain, c.name),
                        });
                        None
                    }
                },
            }
        }
    };
    let brake = match (req.brake_power, req.bus_capacitance, req.bus_voltage_max) {
        (None, None, None) => None,
        (Some(power), None, None) => Some(Brake::Resistor { power }),
        (None, Some(capacitance), Some(voltage_max)) => Some(Brake::Bus { capacitance, voltage_max }),
        (None, Some(_), None) => {
            errors.push(FieldError {
                field: "bus_voltage_max".into(),
                message: "a DC-bus capacitance needs the bus's highest voltage".into(),
            });
            None
        }
        (None, None, Some(_)) => {
            errors.push(FieldError { field: "bus_capacitance".into(), message: "the bus's highest voltage needs its capacitance".into() });
            None
        }
        (Some(_), _, _) => {
            errors.push(FieldError {
                field: "brake_power".into(),
                message: "give a brake resistor (brake_power) or a DC bus (bus_capacitance, bus_voltage_max), not both".into(),
            });
            None
        }
    };
    let settings = Settings {
        reserve: req.reserve.unwrap_or(cad2mo_engine::sizing::DEFAULT_RESERVE),
        dwell: req.dwell.unwrap_or(0.0),
        amplifier,
        brake,
        screw_life: req.screw_life,
    };
    errors.extend(settings.check().into_iter().map(FieldError::from));
    if errors.is_empty() {
        Ok(settings)
    } else {
        Err(MotionError::BadSettings(errors))
    }
}

/// The sizing report of one motion: every drive's checks and ranked alternatives, what the
/// joints without a drive ask of one, and the drives that cannot be sized.
#[derive(Clone, Debug, Serialize)]
pub struct SizingReport {
    pub motion: String,
    pub version: i64,
    pub duration: f64,
    pub rate: f64,
    /// The settings it ran with.
    pub settings: SizingSettings,
    /// How the alternatives are ranked.
    pub ranking: &'static str,
    pub drives: Vec<cad2mo_engine::sizing::DriveSizing>,
    pub undriven: Vec<cad2mo_engine::sizing::Undriven>,
    pub not_sized: Vec<NotSized>,
    /// Drives of joints this version does not have.
    pub orphaned: Vec<String>,
}

const RANKING: &str = "real catalogue combinations only (each gear at its own catalogue ratio, motors that mount on the gear where the catalogue says so): first those passing every check with the reserve, then those passing without it, then those with missing values (the fewest missing first), then the failing ones; within each the smallest first (rotor inertia, then mass, then price class where known), failing ones by their smallest margin";

fn kind_of(k: CoordKind) -> pipeline::back::modelica::mechatronics::JointKind {
    match k {
        CoordKind::Revolute => pipeline::back::modelica::mechatronics::JointKind::Revolute,
        CoordKind::Prismatic => pipeline::back::modelica::mechatronics::JointKind::Prismatic,
    }
}

/// Sizes every drive of a planned motion at [`SIZING_RATE`] against its motor and gear under
/// the user's settings and ranks the catalog's real combinations; joints without a drive get
/// their own load. Loops: only the driven joints carry torque.
#[allow(clippy::too_many_arguments)]
pub fn sizing(
    mech: &Mechanism,
    gravity: &Vector3<f64>,
    version: i64,
    name: &str,
    p: &Planned,
    drives: &[DriveParts],
    catalog: &cad2mo_engine::sizing::Catalog,
    settings: &cad2mo_engine::sizing::Settings,
) -> Result<SizingReport, MotionError> {
    let samples = p.closed_samples(mech, SIZING_RATE).map_err(|i| invalid(&format!("motion \"{name}\" cannot be planned"), i))?;
    let (tau, inertia) = plan::inverse_dynamics(mech, &samples, gravity, 10).map_err(|e| MotionError::Dynamics(e.to_string()))?;
    let mut report = SizingReport {
        motion: name.to_string(),
        version,
        duration: p.duration,
        rate: SIZING_RATE,
        settings: SizingSettings {
            reserve: settings.reserve,
            dwell: settings.dwell,
            screw_life: settings.screw_life,
            amplifier: settings.amplifier.as_ref().map(|a| AmplifierView {
                id: a.part.id.clone(),
                name: a.part.name.clone(),
                supply_voltage: a.u_supply,
                u_min: a.u_min,
                u_max: a.u_max,
                i_cont: a.i_cont,
                i_peak: a.i_peak,
                source: a.source.clone(),
            }),
            brake: settings.brake,
        },
        ranking: RANKING,
        drives: Vec::new(),
        undriven: Vec::new(),
        not_sized: Vec::new(),
        orphaned: Vec::new(),
    };
    let driven: Vec<usize> = mech.driven();
    for d in drives {
        if !p.axes.iter().any(|a| a.name == d.joint) {
            report.orphaned.push(d.joint.clone());
        }
    }
    // Each driven joint's drive is prepared here (in the joints' order), then all are sized at
    // once on the machine's cores; a drive whose parts cannot be read is not sized.
    enum Pending {
        Sized { job: usize, effort: Option<f64> },
        NotSized(NotSized),
    }
    let mut jobs: Vec<cad2mo_engine::sizing::DriveJob> = Vec::new();
    let mut pending: Vec<Pending> = Vec::new();
    for (i, axis) in p.axes.iter().enumerate() {
        if !driven.contains(&i) {
            continue;
        }
        let load = cad2mo_engine::sizing::AxisLoad {
            joint: &axis.name,
            kind: kind_of(axis.kind),
            t: &samples.t,
            qd: &samples.qd[i],
            qdd: &samples.qdd[i],
            tau: &tau[i],
            load_inertia: inertia[i],
        };
        let effort = mech.coordinates().get(i).and_then(|c| c.source_limits.as_ref()).and_then(|l| l.effort).filter(|e| *e > 0.0);
        let Some(d) = drives.iter().find(|d| d.joint == axis.name) else {
            match cad2mo_engine::sizing::undriven(load, settings.dwell) {
                Ok(mut u) => {
                    if let Some(e) = effort {
                        u.effort_limit = Some(e);
                        u.within_effort = Some(u.peak_torque <= e);
                    }
                    report.undriven.push(u)
                }
                Err(e) => pending.push(Pending::NotSized(NotSized { joint: axis.name.clone(), problem: e.to_string() })),
            }
            continue;
        };
        let overrides = |slot: &str,
                         class: &cad2mo_engine::library::Class|
         -> Result<Vec<(String, cad2mo_engine::library::Value)>, String> {
            match d.overrides.get(slot).and_then(serde_json::Value::as_object) {
                Some(map) => cad2mo_engine::library::validate_overrides(class, map)
                    .map_err(|issues| issues.iter().map(|i| format!("{slot} {}: {}", i.field, i.message)).collect::<Vec<_>>().join("; ")),
                None => Ok(Vec::new()),
            }
        };
        let parts = overrides("motor", &d.motor.1)
            .and_then(|mo| cad2mo_engine::sizing::parts::motor(&d.motor.1, &d.motor.0, &mo).map_err(|e| e.to_string()))
            .and_then(|motor| {
                let go = overrides("gear", &d.gear.1)?;
                let gear = cad2mo_engine::sizing::parts::gear(&d.gear.1, &d.gear.0, &go).map_err(|e| e.to_string())?;
                Ok((motor, gear))
            });
        match parts {
            Ok((motor, gear)) => {
                pending.push(Pending::Sized { job: jobs.len(), effort });
                jobs.push(cad2mo_engine::sizing::DriveJob { load, motor, gear });
            }
            Err(problem) => pending.push(Pending::NotSized(NotSized { joint: axis.name.clone(), problem })),
        }
    }
    let threads = cad2mo_engine::sizing::sizing_threads();
    let mut sized = cad2mo_engine::sizing::size_drives(&jobs, Some(catalog), settings, cad2mo_engine::sizing::TOP, threads)
        .into_iter()
        .map(Some)
        .collect::<Vec<_>>();
    for entry in pending {
        match entry {
            Pending::NotSized(n) => report.not_sized.push(n),
            Pending::Sized { job, effort } => {
                let load = &jobs[job].load;
                match sized[job].take() {
                    Some(Ok(mut s)) => {
                        if let Some(e) = effort {
                            let c = cad2mo_engine::sizing::effort_check(load.kind, load.tau, e);
                            s.pass &= c.pass;
                            s.passes_with_reserve &= c.pass;
                            s.checks.push(c);
                        }
                        report.drives.push(s)
                    }
                    Some(Err(e)) => report.not_sized.push(NotSized { joint: load.joint.to_string(), problem: e.to_string() }),
                    None => {}
                }
            }
        }
    }
    Ok(report)
}

/// The model's drives with their motor and gear instances.
pub async fn drive_parts(store: &crate::store::Store, model_id: &str) -> Result<Vec<DriveParts>, DriveError> {
    let mut out = Vec::new();
    for a in crate::store::drives::list(store, model_id).await? {
        let mut parts = Vec::new();
        for id in [&a.motor_instance, &a.gear_instance] {
            let p = crate::store::library::get_instance(store, id)
                .await?
                .ok_or_else(|| DriveError::InstanceGone { joint: a.joint.clone(), instance: id.clone() })?;
            parts.push(p);
        }
        let mut it = parts.into_iter();
        let (Some(motor), Some(gear)) = (it.next(), it.next()) else { continue };
        out.push(DriveParts { joint: a.joint, motor, gear, overrides: a.overrides });
    }
    Ok(out)
}

/// The sizing files of a package: `<pkg>/Resources/Sizing/<motion>.json` for each planned motion
/// (named like its table in `Motions`), when the model has drives or joints to size.
#[allow(clippy::too_many_arguments)]
pub fn sizing_files(
    mech: &Mechanism,
    gravity: &Vector3<f64>,
    version: i64,
    package_name: &str,
    planned: &[ForPackage],
    class_names: &[String],
    drives: &[DriveParts],
    catalog: &cad2mo_engine::sizing::Catalog,
) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    for (p, file) in planned.iter().zip(class_names) {
        // The package's sizing files use the default settings (no amplifier or brake is chosen
        // for a package): the checks those need are reported not evaluated.
        let settings = cad2mo_engine::sizing::Settings::default();
        let json = match sizing(mech, gravity, version, &p.table.label, &p.planned, drives, catalog, &settings) {
            Ok(r) => serde_json::to_vec_pretty(&r),
            Err(e) => serde_json::to_vec_pretty(&serde_json::json!({ "motion": p.table.label, "error": e.to_string() })),
        };
        if let Ok(bytes) = json {
            files.push((format!("{package_name}/Resources/Sizing/{file}.json"), bytes));
        }
    }
    files
}
