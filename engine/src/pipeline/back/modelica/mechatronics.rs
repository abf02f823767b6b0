//! The mechatronic model: `<Pkg>/Mechatronics.mo` and the drive library `<Pkg>/Components/Drives/`.
//!
//! `Mechatronics extends Mechanics` and, for every joint the user gave a drive, declares one
//! `Drives.JointDrive` (revolute) or `Drives.LinearJointDrive` (prismatic) with the motor, gear and
//! controller classes and parameter values chosen in the motor library, and
//! `connect(drive_<joint>.flange, <joint>.drive)`. It names joints only, so a `Mechanics.mo`
//! regenerated after a CAD change slots under it unchanged (the paper's idea).
//!
//! ```text
//! reference (Constant | CombiTimeTable) ─▶ controller ─i_ref▶ motor ─flange▶ gear ─▶ joint.drive
//!                                            ▲    ▲                 │
//!                                  phi_motor │    │ w_motor ◀───────┘ (motor-side sensors)
//! ```
//!
//! Conventions (documented again in the generated classes):
//! - the motor command is the armature current `i_ref` in A; every motor has an inner current
//!   loop with current and voltage limits;
//! - gear `ratio` = motor speed / joint speed, as MSL `IdealGear` (flange_a.phi = ratio *
//!   flange_b.phi); for a prismatic joint the transmission is in rad/m (`LeadScrew`);
//! - the controller measures the motor angle and speed and scales the joint reference by the
//!   transmission, so it works in motor radians; it drives the joint coordinate to the reference.
//!
//! The library classes that a drive may refer to are listed by [`known_classes`]: a class path
//! starting with `cad2mo.` is our own class under `<Pkg>.Components`; a `Modelica.` path is the
//! MSL model our wrapper embeds (its parameters forwarded 1:1).
//!
//! Plain data in, files out: no IO, no panics.

pub mod collision;
pub mod live;

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::sync::OnceLock;

use super::diagram::extend::PLACEHOLDER;
use super::diagram::Sheet;
use super::names::KEYWORDS;
use super::write::Experiment;

mod classes;
#[cfg(test)]
mod tests;

/// The kind of joint a drive actuates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    Revolute,
    Prismatic,
}

impl JointKind {
    fn name(self) -> &'static str {
        match self {
            JointKind::Revolute => "revolute",
            JointKind::Prismatic => "prismatic",
        }
    }

    fn unit(self) -> &'static str {
        match self {
            JointKind::Revolute => "rad",
            JointKind::Prismatic => "m",
        }
    }
}

/// A parameter value from the motor library.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    Real(f64),
    Integer(i64),
    Boolean(bool),
    String(String),
}

impl ParamValue {
    fn type_name(&self) -> &'static str {
        match self {
            ParamValue::Real(_) => "Real",
            ParamValue::Integer(_) => "Integer",
            ParamValue::Boolean(_) => "Boolean",
            ParamValue::String(_) => "String",
        }
    }
}

/// A class for one slot (motor, gear or controller) with its parameter values.
#[derive(Clone, Debug, PartialEq)]
pub struct ClassChoice {
    /// A class path of [`known_classes`].
    pub modelica_class: String,
    pub params: Vec<(String, ParamValue)>,
    /// The motor library instance it comes from (its name; empty when none).
    pub instance: String,
}

/// The joint reference: angle in rad (revolute) or position in m (prismatic).
#[derive(Clone, Debug, PartialEq)]
pub enum Reference {
    /// Held from t = 0 (a step from the joint's start value when they differ).
    Constant(f64),
    /// (time in s, value) points, times non-decreasing (a time may repeat once, for a jump);
    /// linear interpolation, last value held. A table starting after t = 0 is preceded by
    /// (0, start); an empty table holds `start`; a single point at t <= 0 is a constant.
    Table(Vec<(f64, f64)>),
}

/// A motion's reference trajectory, sampled: the `Motions` sub-package of `Mechatronics.mo` gets
/// one table per motion (columns: time, then q, qd and qdd of every axis), and every drive whose
/// joint is an axis follows the selected motion's position with its speed fed forward.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionTable {
    /// The user's name (shown in the selection and the documentation).
    pub label: String,
    /// Joint names (Modelica component names), one per axis.
    pub axes: Vec<String>,
    /// Sample times from 0, increasing, s.
    pub t: Vec<f64>,
    /// Per axis, per sample: rad or m, and their derivatives.
    pub q: Vec<Vec<f64>>,
    pub qd: Vec<Vec<f64>>,
    pub qdd: Vec<Vec<f64>>,
}

/// One joint's drive, as assigned in the service.
#[derive(Clone, Debug, PartialEq)]
pub struct DrivePlan {
    /// Modelica name of the joint component in Mechanics (e.g. "RootPart_LINK").
    pub joint: String,
    pub kind: JointKind,
    /// The joint's start value (rad or m) from the report: where the reference starts.
    pub start: f64,
    pub motor: ClassChoice,
    pub gear: ClassChoice,
    pub controller: ClassChoice,
    pub reference: Reference,
    /// Human text for the description string, e.g. "joint RootPart--LINK (nodeID 23:-:1)".
    pub label: String,
}

/// A class the motor library may refer to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KnownClass {
    pub modelica_class: &'static str,
    /// `motor`, `gear` or `controller`.
    pub domain: &'static str,
    /// (name, Modelica type `Real|Integer|Boolean|String`, unit).
    pub params: &'static [(&'static str, &'static str, &'static str)],
}

/// Why a drive cannot be written.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MechatronicsError {
    #[error("package name \"{0}\" is not a Modelica identifier")]
    BadPackageName(String),
    #[error("drive of joint \"{joint}\": the joint name is not a Modelica identifier")]
    BadJointName { joint: String },
    #[error("joint {joint} has more than one drive")]
    DuplicateJoint { joint: String },
    #[error("drive of joint {joint}: \"{class}\" is not a known {slot} class{found}")]
    UnknownClass { joint: String, slot: &'static str, class: String, found: String },
    #[error("drive of joint {joint}: gear class {class} is for {fits} joints, not for the {kind} joint")]
    GearDoesNotFitJoint { joint: String, class: String, fits: &'static str, kind: &'static str },
    #[error("drive of joint {joint}: {class} has no parameter \"{param}\" (known: {known})")]
    UnknownParameter { joint: String, class: String, param: String, known: String },
    #[error("drive of joint {joint}: parameter {param} of {class} is given twice")]
    DuplicateParameter { joint: String, class: String, param: String },
    #[error("drive of joint {joint}: parameter {param} of {class} is a {expected}, got a {got}")]
    WrongType { joint: String, class: String, param: String, expected: &'static str, got: &'static str },
    #[error("drive of joint {joint}: parameter {param} of {class} = {value} {rule}")]
    OutOfRange { joint: String, class: String, param: String, value: String, rule: &'static str },
    #[error("drive of joint {joint}: reference: {reason}")]
    BadReference { joint: String, reason: String },
    #[error("motion \"{motion}\": {reason}")]
    BadMotion { motion: String, reason: String },
    #[error("live view: {0}")]
    LiveView(String),
}

// ---------------------------------------------------------------------------------------------
// The class table: one entry per library class; the Modelica parameter declarations, the Rust
// validation and `known_classes` all come from it.

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Domain {
    Motor,
    Gear,
    Controller,
}

impl Domain {
    fn name(self) -> &'static str {
        match self {
            Domain::Motor => "motor",
            Domain::Gear => "gear",
            Domain::Controller => "controller",
        }
    }
}

// Every library parameter is a Real so far; the other types are supported by the validation and
// by `known_classes` for classes to come.
#[allow(dead_code)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ty {
    Real,
    Integer,
    Boolean,
    String,
}

impl Ty {
    fn name(self) -> &'static str {
        match self {
            Ty::Real => "Real",
            Ty::Integer => "Integer",
            Ty::Boolean => "Boolean",
            Ty::String => "String",
        }
    }
}

/// Allowed values of a numeric parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Range {
    Any,
    Positive,
    NonNegative,
    NonZero,
    /// 0 < x <= 1 (efficiencies).
    Efficiency,
}

impl Range {
    /// The rule broken by `x`, if any.
    fn violated(self, x: f64) -> Option<&'static str> {
        if !x.is_finite() {
            return Some("is not finite");
        }
        match self {
            Range::Any => None,
            Range::Positive if x <= 0.0 => Some("must be > 0"),
            Range::NonNegative if x < 0.0 => Some("must be >= 0"),
            Range::NonZero if x == 0.0 => Some("must not be 0"),
            Range::Efficiency if x <= 0.0 || x > 1.0 => Some("must be in (0, 1]"),
            _ => None,
        }
    }

    /// Modelica `min`/`max` attributes.
    fn attributes(self) -> &'static str {
        match self {
            Range::Positive | Range::NonNegative => "min=0",
            Range::Efficiency => "min=0, max=1",
            Range::Any | Range::NonZero => "",
        }
    }
}

/// A parameter of a library class.
#[derive(Clone, Copy, Debug)]
struct Param {
    name: &'static str,
    ty: Ty,
    /// Modelica unit string ("" for none).
    unit: &'static str,
    /// Declared type in the generated class (`SI.Resistance`, `Real`, ...).
    mtype: &'static str,
    /// Default value (a Modelica expression) in the generated class.
    default: &'static str,
    range: Range,
    doc: &'static str,
    /// Declared in the slot's interface (e.g. the gear `ratio`), not in the class itself.
    inherited: bool,
}

/// A library class.
#[derive(Clone, Copy, Debug)]
struct Spec {
    /// Library class path: `cad2mo.Drives...` (ours) or an MSL path (the model we wrap).
    path: &'static str,
    domain: Domain,
    /// The generated class, relative to `<Pkg>.Components.Drives`.
    class: &'static str,
    /// The joint kind a gear fits (`None`: any joint).
    fits: Option<JointKind>,
    doc: &'static str,
    params: &'static [Param],
}

const fn real(
    name: &'static str,
    unit: &'static str,
    mtype: &'static str,
    default: &'static str,
    range: Range,
    doc: &'static str,
) -> Param {
    Param { name, ty: Ty::Real, unit, mtype, default, range, doc, inherited: false }
}

const fn inherited(p: Param) -> Param {
    Param { inherited: true, ..p }
}

const RATIO: Param = real("ratio", "1", "Real", "1", Range::NonZero, "Transmission ratio: motor speed / joint speed");

static SPECS: &[Spec] = &[
    Spec {
        path: "cad2mo.Drives.Motors.DCPermanentMagnet",
        domain: Domain::Motor,
        class: "Motors.DCPermanentMagnet",
        fits: None,
        doc: "DC permanent-magnet motor with an inner current loop and voltage and current limits (our own equations)",
        params: &[
            real("R", "Ohm", "SI.Resistance", "0.299", Range::NonNegative, "Armature resistance"),
            real("L", "H", "SI.Inductance", "8.2e-5", Range::Positive, "Armature inductance"),
            real("k", "N.m/A", "SI.ElectricalTorqueConstant", "0.0302", Range::Positive, "Torque constant = back-EMF constant (V.s/rad)"),
            real("J", "kg.m2", "SI.Inertia", "1.42e-5", Range::Positive, "Rotor inertia"),
            real("d", "N.m.s/rad", "SI.RotationalDampingConstant", "0", Range::NonNegative, "Viscous friction of the rotor"),
            real("V_max", "V", "SI.Voltage", "24", Range::Positive, "Supply voltage: limit of the armature voltage"),
            real("I_max", "A", "SI.Current", "10", Range::Positive, "Current limit of the drive"),
            real("Tc", "s", "SI.Time", "0.001", Range::Positive, "Time constant of the current loop (proportional gain L/Tc)"),
        ],
    },
    Spec {
        path: "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet",
        domain: Domain::Motor,
        class: "Motors.MSL_DC_PermanentMagnet",
        fits: None,
        doc: "The MSL DC permanent-magnet machine fed by a controlled voltage source with a current loop",
        params: &[
            real("VaNominal", "V", "SI.Voltage", "100", Range::Positive, "Nominal armature voltage"),
            real("IaNominal", "A", "SI.Current", "100", Range::Positive, "Nominal armature current (> 0: motor)"),
            real("wNominal", "rad/s", "SI.AngularVelocity", "149.22565104551518", Range::Positive, "Nominal speed (1425 rpm by default)"),
            real("TaNominal", "K", "SI.Temperature", "293.15", Range::Positive, "Nominal armature temperature"),
            real("Ra", "Ohm", "SI.Resistance", "0.05", Range::NonNegative, "Armature resistance at TaRef"),
            real("TaRef", "K", "SI.Temperature", "293.15", Range::Positive, "Reference temperature of the armature resistance"),
            real(
                "alpha20a",
                "1/K",
                "Modelica.Electrical.Machines.Thermal.LinearTemperatureCoefficient20",
                "0",
                Range::Any,
                "Temperature coefficient of the armature resistance at 20 degC",
            ),
            real("La", "H", "SI.Inductance", "0.0015", Range::Positive, "Armature inductance"),
            real("Jr", "kg.m2", "SI.Inertia", "0.15", Range::Positive, "Rotor inertia"),
            real("Js", "kg.m2", "SI.Inertia", "Jr", Range::Positive, "Stator inertia (the stator is fixed here)"),
            real("TaOperational", "K", "SI.Temperature", "293.15", Range::Positive, "Operational armature temperature"),
        ],
    },
    Spec {
        path: "cad2mo.Drives.Motors.ServoMotor",
        domain: Domain::Motor,
        class: "Motors.ServoMotor",
        fits: None,
        doc: "Permanent-magnet AC servo motor with field-oriented current control: torque = k*i, the current following the limited command (our own equations)",
        params: &[
            real("k", "N.m/A", "SI.ElectricalTorqueConstant", "0.544", Range::Positive, "Torque constant (per A rms)"),
            real("J", "kg.m2", "SI.Inertia", "4.86e-5", Range::Positive, "Motor moment of inertia"),
            real("I_max", "A", "SI.Current", "9.3", Range::Positive, "Current limit: the maximum (instantaneous) current, A rms"),
            real("Tc", "s", "SI.Time", "0.001", Range::Positive, "Time constant of the current loop"),
        ],
    },
    Spec {
        path: "Modelica.Mechanics.Rotational.Components.IdealGear",
        domain: Domain::Gear,
        class: "Gears.Ideal",
        fits: Some(JointKind::Revolute),
        doc: "Ideal gear (MSL IdealGear)",
        params: &[inherited(RATIO)],
    },
    Spec {
        path: "cad2mo.Drives.Gears.Efficiency",
        domain: Domain::Gear,
        class: "Gears.Efficiency",
        fits: Some(JointKind::Revolute),
        doc: "Gear with a constant efficiency (MSL LossyGear, lossTable=[0, eta, eta, 0, 0])",
        params: &[inherited(RATIO), real("eta", "1", "Real", "1", Range::Efficiency, "Efficiency in both directions of power flow")],
    },
    Spec {
        path: "cad2mo.Drives.Gears.LeadScrew",
        domain: Domain::Gear,
        class: "Gears.LeadScrew",
        fits: Some(JointKind::Prismatic),
        doc: "Ideal gearbox and lead screw for prismatic joints (MSL IdealGearR2T)",
        params: &[
            real("ratio", "1", "Real", "1", Range::NonZero, "Gearbox ratio: motor speed / screw speed"),
            real("lead", "m", "SI.Length", "0.005", Range::NonZero, "Screw lead: joint travel per screw revolution"),
        ],
    },
    Spec {
        path: "cad2mo.Drives.Controllers.CascadePPI",
        domain: Domain::Controller,
        class: "Controllers.CascadePPI",
        fits: None,
        doc: "Cascade controller: P position loop, PI speed loop (as MSL RobotR3.Components.Controller)",
        params: &[
            real("kp", "1/s", "Real", "10", Range::NonNegative, "Gain of the position controller"),
            real("ks", "A.s/rad", "Real", "0.05", Range::NonNegative, "Gain of the speed controller"),
            real("Ts", "s", "SI.Time", "0.05", Range::Positive, "Time constant of the speed controller's integrator"),
        ],
    },
];

fn spec(path: &str) -> Option<&'static Spec> {
    SPECS.iter().find(|s| s.path == path)
}

/// The classes the motor library may refer to, with their parameters.
pub fn known_classes() -> Vec<KnownClass> {
    type Params = Vec<(&'static str, &'static str, &'static str)>;
    static PARAMS: OnceLock<Vec<Params>> = OnceLock::new();
    let params = PARAMS.get_or_init(|| SPECS.iter().map(|s| s.params.iter().map(|p| (p.name, p.ty.name(), p.unit)).collect()).collect());
    SPECS
        .iter()
        .zip(params.iter())
        .map(|(s, p)| KnownClass { modelica_class: s.path, domain: s.domain.name(), params: p.as_slice() })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Text helpers.

/// Shortest round-trip decimal; `-0` prints as `0`.
fn num(x: f64) -> String {
    crate::numtext::dbg(x)
}

/// A trajectory sample: 12 significant digits (far below any controller's resolution), the
/// shortest decimal that reads back to that, `1` for `1.0`; tables of thousands of rows stay small.
fn tnum(x: f64) -> String {
    if x == 0.0 {
        return "0".to_string();
    }
    let rounded: f64 = format!("{x:.11e}").parse().unwrap_or(x);
    let s = crate::numtext::dbg(rounded);
    match s.strip_suffix(".0") {
        Some(whole) => whole.to_string(),
        None => s,
    }
}

/// The external-function annotation body that compiles `<Pkg>/Resources/Include/<file>` into
/// the simulation (the C sources the live view and the contact forces ship).
fn include_annotation(pkg: &str, file: &str) -> String {
    format!("Include=\"#include \\\"{file}\\\"\", IncludeDirectory=\"modelica://{pkg}/Resources/Include\"")
}

/// Escapes text for a Modelica string literal.
fn mstr(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}

/// Escapes text for HTML inside a Modelica string literal.
fn html(s: &str) -> String {
    mstr(&s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;"))
}

/// `[A-Za-z_][A-Za-z0-9_]*`, not a keyword.
fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    first_ok && chars.all(|c| c.is_ascii_alphanumeric() || c == '_') && !KEYWORDS.contains(&s)
}

fn value_text(v: &ParamValue) -> String {
    match v {
        ParamValue::Real(x) => num(*x),
        ParamValue::Integer(i) => i.to_string(),
        ParamValue::Boolean(b) => b.to_string(),
        ParamValue::String(s) => format!("\"{}\"", mstr(s)),
    }
}

// ---------------------------------------------------------------------------------------------
// Validation.

/// A validated slot: the class and its modifiers in the class table's order.
struct Slot {
    spec: &'static Spec,
    /// The library instance's name (empty when none).
    instance: String,
    /// (name, Modelica value text).
    values: Vec<(&'static str, String)>,
}

fn slot(joint: &str, kind: JointKind, domain: Domain, choice: &ClassChoice) -> Result<Slot, MechatronicsError> {
    let class = choice.modelica_class.as_str();
    let spec = match spec(class) {
        Some(s) if s.domain == domain => s,
        other => {
            return Err(MechatronicsError::UnknownClass {
                joint: joint.to_string(),
                slot: domain.name(),
                class: class.to_string(),
                found: other.map(|s| format!(" (it is a {} class)", s.domain.name())).unwrap_or_default(),
            })
        }
    };
    if let Some(fits) = spec.fits {
        if fits != kind {
            return Err(MechatronicsError::GearDoesNotFitJoint {
                joint: joint.to_string(),
                class: class.to_string(),
                fits: fits.name(),
                kind: kind.name(),
            });
        }
    }
    let mut given: Vec<Option<String>> = vec![None; spec.params.len()];
    for (name, value) in &choice.params {
        let Some(i) = spec.params.iter().position(|p| p.name == name) else {
            return Err(MechatronicsError::UnknownParameter {
                joint: joint.to_string(),
                class: class.to_string(),
                param: name.clone(),
                known: spec.params.iter().map(|p| p.name).collect::<Vec<_>>().join(", "),
            });
        };
        let p = &spec.params[i];
        if given[i].is_some() {
            return Err(MechatronicsError::DuplicateParameter { joint: joint.to_string(), class: class.to_string(), param: name.clone() });
        }
        // Modelica widens Integer to Real; every other mismatch is an error.
        let x = match (p.ty, value) {
            (Ty::Real, ParamValue::Real(x)) => Some(*x),
            (Ty::Real, ParamValue::Integer(i)) => Some(*i as f64),
            (Ty::Integer, ParamValue::Integer(i)) => Some(*i as f64),
            (Ty::Boolean, ParamValue::Boolean(_)) | (Ty::String, ParamValue::String(_)) => None,
            _ => {
                return Err(MechatronicsError::WrongType {
                    joint: joint.to_string(),
                    class: class.to_string(),
                    param: name.clone(),
                    expected: p.ty.name(),
                    got: value.type_name(),
                })
            }
        };
        if let Some(x) = x {
            if let Some(rule) = p.range.violated(x) {
                return Err(MechatronicsError::OutOfRange {
                    joint: joint.to_string(),
                    class: class.to_string(),
                    param: name.clone(),
                    value: num(x),
                    rule,
                });
            }
        }
        given[i] = Some(match (p.ty, value) {
            (Ty::Real, ParamValue::Integer(i)) => num(*i as f64),
            _ => value_text(value),
        });
    }
    let values = spec.params.iter().zip(given).filter_map(|(p, v)| v.map(|v| (p.name, v))).collect();
    Ok(Slot { spec, instance: choice.instance.clone(), values })
}

/// The reference as emitted: a constant or a table whose first point is at t <= 0.
enum Ref {
    Constant(f64),
    Table(Vec<(f64, f64)>),
}

fn reference(joint: &str, start: f64, r: &Reference) -> Result<Ref, MechatronicsError> {
    let bad = |reason: String| MechatronicsError::BadReference { joint: joint.to_string(), reason };
    if !start.is_finite() {
        return Err(bad(format!("the joint's start value {start} is not finite")));
    }
    match r {
        Reference::Constant(c) if c.is_finite() => Ok(Ref::Constant(*c)),
        Reference::Constant(c) => Err(bad(format!("constant {c} is not finite"))),
        Reference::Table(points) if points.is_empty() => Ok(Ref::Constant(start)),
        Reference::Table(points) => {
            for (k, (t, y)) in points.iter().enumerate() {
                if !t.is_finite() || !y.is_finite() {
                    return Err(bad(format!("point {} ({t}, {y}) is not finite", k + 1)));
                }
                if k > 0 && *t < points[k - 1].0 {
                    return Err(bad(format!("time {t} of point {} is before the time of point {k}", k + 1)));
                }
                if k > 1 && *t == points[k - 1].0 && *t == points[k - 2].0 {
                    return Err(bad(format!("time {t} appears more than twice")));
                }
            }
            let mut table = Vec::with_capacity(points.len() + 1);
            if points[0].0 > 0.0 {
                table.push((0.0, start));
            }
            table.extend_from_slice(points);
            match table.as_slice() {
                // One point at t <= 0: a constant (CombiTimeTable wants two rows).
                [(_, y)] => Ok(Ref::Constant(*y)),
                _ => Ok(Ref::Table(table)),
            }
        }
    }
}

struct Drive<'a> {
    plan: &'a DrivePlan,
    motor: Slot,
    gear: Slot,
    controller: Slot,
    reference: Ref,
}

fn validate(drives: &[DrivePlan]) -> Result<Vec<Drive<'_>>, MechatronicsError> {
    let mut seen = BTreeSet::new();
    let mut out = Vec::with_capacity(drives.len());
    for plan in drives {
        let joint = plan.joint.as_str();
        if !is_identifier(joint) {
            return Err(MechatronicsError::BadJointName { joint: joint.to_string() });
        }
        if !seen.insert(joint) {
            return Err(MechatronicsError::DuplicateJoint { joint: joint.to_string() });
        }
        out.push(Drive {
            plan,
            motor: slot(joint, plan.kind, Domain::Motor, &plan.motor)?,
            gear: slot(joint, plan.kind, Domain::Gear, &plan.gear)?,
            controller: slot(joint, plan.kind, Domain::Controller, &plan.controller)?,
            reference: reference(joint, plan.start, &plan.reference)?,
        });
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------------
// Mechatronics.mo

/// `redeclare <class> <name>(p=v, ...)`, one modifier a line.
fn redeclare(pkg: &str, name: &str, slot: &Slot) -> String {
    let class = format!("{pkg}.Components.Drives.{}", slot.spec.class);
    if slot.values.is_empty() {
        return format!("    redeclare {class} {name}");
    }
    let mods: Vec<String> = slot.values.iter().map(|(n, v)| format!("      {n}={v}")).collect();
    format!("    redeclare {class} {name}(\n{})", mods.join(",\n"))
}

fn table_text(points: &[(f64, f64)]) -> String {
    let rows: Vec<String> = points.iter().map(|(t, y)| format!("{}, {}", num(*t), num(*y))).collect();
    format!("[{}]", rows.join("; "))
}

fn slot_html(slot: &Slot) -> String {
    let values = if slot.values.is_empty() {
        "defaults".to_string()
    } else {
        slot.values
            .iter()
            .map(|(n, v)| {
                let unit = slot.spec.params.iter().find(|p| p.name == *n).map_or("", |p| p.unit);
                if unit.is_empty() || unit == "1" {
                    format!("{n}={}", html(v))
                } else {
                    format!("{n}={} {}", html(v), html(unit))
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    if slot.instance.is_empty() {
        format!("<code>{}</code> ({values})", html(slot.spec.class))
    } else {
        format!("{}: <code>{}</code> ({values})", html(&slot.instance), html(slot.spec.class))
    }
}

fn reference_html(r: &Ref, kind: JointKind, start: f64) -> String {
    let u = kind.unit();
    match r {
        Ref::Constant(c) if *c == start => format!("constant {} {u} (holds the start value)", num(*c)),
        Ref::Constant(c) => format!("constant {} {u} (a step from the start value {} {u} at t = 0)", num(*c), num(start)),
        Ref::Table(t) => {
            let (t0, t1) = (t[0].0, t[t.len() - 1].0);
            format!("table of {} points from t = {} s to {} s (linear, last value held)", t.len(), num(t0), num(t1))
        }
    }
}

/// What `Mechatronics` may declare beyond drives and motions.
#[derive(Clone, Debug, Default)]
pub struct Additions<'a> {
    /// The live view: where it sends, and the bodies in package order.
    pub live: Option<(&'a live::LiveTarget, &'a [String])>,
    /// The contact forces' declarations and shape file ([`collision::declarations`]); their
    /// package files are written with them.
    pub collision: Option<&'a collision::Contacts>,
    /// The scene's declarations (`crate::scene::package::Modelica::declarations`: its objects'
    /// shapes, tables, free bodies; their contacts come with `collision`).
    pub scene: Option<&'a str>,
    /// The Mechanics diagram, which Mechatronics places its components around (extended in
    /// place: taken, not copied).
    pub diagram: Option<Sheet>,
    /// The experiment Mechanics runs (Mechatronics runs it too unless a motion or a reference
    /// table is longer).
    pub experiment: Option<&'a Experiment>,
}

/// The icon `Mechatronics` adds to the one it inherits: a motor with its shaft.
const MECHATRONICS_ICON: &str = "\n      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),\n      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),\n      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)";

/// Writes `<pkg>/Mechatronics.mo`: Mechanics plus one drive per plan. `provenance_html` is the
/// HTML paragraph saying where the model came from (it is escaped for the string literal only).
pub fn mechatronics(
    pkg: &str,
    drives: &[DrivePlan],
    motions: &[MotionTable],
    additions: Additions<'_>,
    provenance_html: &str,
) -> Result<Vec<(String, Vec<u8>)>, MechatronicsError> {
    let live = additions.live;
    if !is_identifier(pkg) {
        return Err(MechatronicsError::BadPackageName(pkg.to_string()));
    }
    let drives = validate(drives)?;
    let motion_names = check_motions(motions)?;
    let mut decl = String::new();
    let mut conn = String::new();
    let mut rows = String::new();
    let mut stop_time: f64 = 1.0;
    if let Some(first) = motions.first() {
        // As RobotR3's fullRobot: the motion, then half a second to settle.
        stop_time = first.t.last().copied().unwrap_or(0.0) + 0.5;
    }
    for d in drives.iter() {
        let p = d.plan;
        let joint = &p.joint;
        let name = format!("drive_{joint}");
        let model = match p.kind {
            JointKind::Revolute => "JointDrive",
            JointKind::Prismatic => "LinearJointDrive",
        };
        let follows = !motions.is_empty() && motions.iter().all(|m| m.axes.iter().any(|a| a == joint));
        let reference = match &d.reference {
            _ if follows => "    useMotion=true".to_string(),
            Ref::Constant(c) => format!("    useTable=false,\n    q_constant={}", num(*c)),
            Ref::Table(t) => {
                if let Some(last) = t.last() {
                    stop_time = stop_time.max(last.0);
                }
                format!("    useTable=true,\n    table={}", table_text(t))
            }
        };
        let label = if p.label.trim().is_empty() { format!("joint {joint}") } else { p.label.clone() };
        let _ = writeln!(
            decl,
            "  {pkg}.Components.Drives.{model} {name}(\n{},\n{},\n{},\n{})\n    \"Drive of {}\"\n    {PLACEHOLDER};",
            redeclare(pkg, "motor", &d.motor),
            redeclare(pkg, "gear", &d.gear),
            redeclare(pkg, "controller", &d.controller),
            reference,
            mstr(&label)
        );
        let _ = writeln!(conn, "  connect({name}.flange, {joint}.drive);");
        if follows {
            let pick = |col: usize| -> String {
                let mut e = String::new();
                for (k, (m, mname)) in motions.iter().zip(&motion_names).enumerate() {
                    let a = m.axes.iter().position(|x| x == joint).unwrap_or(0);
                    let y = format!("motion_{mname}.y[{}]", col * m.axes.len() + a + 1);
                    if k + 1 == motions.len() {
                        e.push_str(&y);
                    } else {
                        let _ = write!(e, "if motion == {} then {y} else ", k + 1);
                    }
                }
                e
            };
            let _ = writeln!(conn, "  {name}.q_motion = {};", pick(0));
            let _ = writeln!(conn, "  {name}.qd_motion = {};", pick(1));
        }
        let _ = write!(
            rows,
            "\n<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            html(joint),
            html(&label),
            slot_html(&d.motor),
            slot_html(&d.gear),
            slot_html(&d.controller),
            html(&if follows {
                "the selected motion (position, speed fed forward)".to_string()
            } else {
                reference_html(&d.reference, p.kind, p.start)
            })
        );
    }
    let mut motion_decl = String::new();
    let mut motion_rows = String::new();
    if !motions.is_empty() {
        let choices: Vec<String> =
            motion_names.iter().zip(motions).enumerate().map(|(k, (_, m))| format!("choice={} \"{}\"", k + 1, mstr(&m.label))).collect();
        let _ = writeln!(
            motion_decl,
            "\n  // Motions: the drives follow the selected one (Motions package)\n  parameter Integer motion(min=1, max={}) = 1 \"The motion the drives follow\"\n    annotation (choices({}));",
            motions.len(),
            choices.join(", ")
        );
        for (k, (m, mname)) in motions.iter().zip(&motion_names).enumerate() {
            let _ = writeln!(motion_decl, "  Motions.{mname} motion_{mname} \"Motion {}\"\n    {PLACEHOLDER};", mstr(&m.label));
            let _ = write!(
                motion_rows,
                "\n<tr><td>{}</td><td><code>Motions.{mname}</code></td><td>{}</td><td>{}</td></tr>",
                k + 1,
                html(&m.label),
                num(m.t.last().copied().unwrap_or(0.0))
            );
        }
    }
    let body = if drives.is_empty() {
        "<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>".to_string()
    } else {
        format!(
            "<p>Drives (motor, gear and controller classes under <code>Components.Drives</code>; the controllers drive the joint angle or position to the reference):</p>\n<table border='1' cellspacing='0' cellpadding='2'>\n<tr><th>Joint</th><th>CAD joint</th><th>Motor</th><th>Gear</th><th>Controller</th><th>Reference</th></tr>{rows}\n</table>"
        )
    };
    let count = match drives.len() {
        0 => "no joint drive".to_string(),
        1 => "1 joint drive".to_string(),
        n => format!("{n} joint drives"),
    };
    let decl = if drives.is_empty() {
        String::new()
    } else {
        format!("\n  // Drives: reference -> controller -> motor -> gear -> joint drive flange\n{}", decl.trim_end_matches('\n'))
    };
    let mut decl = format!("{}{decl}", motion_decl.trim_end_matches('\n'));
    if let Some((target, bodies)) = live {
        if bodies.is_empty() || bodies.len() > live::MAX_BODIES {
            return Err(MechatronicsError::LiveView(format!(
                "{} bodies: a live view frame carries 1 to {}",
                bodies.len(),
                live::MAX_BODIES
            )));
        }
        decl.push_str(live::declarations(pkg, target, bodies).trim_end_matches('\n'));
    }
    if let Some(scene) = additions.scene {
        decl.push_str(scene.trim_end_matches('\n'));
    }
    if let Some(c) = additions.collision {
        decl.push_str(c.declarations.trim_end_matches('\n'));
    }
    let body = if motions.is_empty() {
        body
    } else {
        format!(
            "{body}\n<p>Motions (parameter <code>motion</code> selects the one the drives follow; tables in <code>Motions</code>: time, then the position, speed and acceleration of every joint):</p>\n<table border='1' cellspacing='0' cellpadding='2'>\n<tr><th>motion</th><th>Table</th><th>Name</th><th>Duration, s</th></tr>{motion_rows}\n</table>"
        )
    };
    let experiment = match (motions.first(), additions.experiment) {
        (Some(first), _) => Experiment::of(
            stop_time,
            format!(
                "Experiment: {} s, the motion {} ({} s) and half a second to settle; 500 output intervals, tolerance 1e-6.",
                num(stop_time),
                first.label,
                num(first.t.last().copied().unwrap_or(0.0))
            ),
        ),
        (None, Some(e)) if e.stop >= stop_time => Experiment::of(e.stop, e.why.clone()),
        (None, _) => Experiment::of(
            stop_time,
            format!("Experiment: {} s, the longest reference table; 500 output intervals, tolerance 1e-6.", num(stop_time)),
        ),
    };
    let text = format!(
        "within {pkg};\nmodel Mechatronics \"Mechatronic model of {pkg}: Mechanics with {count}\"\n  extends {pkg}.Mechanics;\n{decl}\nequation\n{conn}  annotation (\n    {},\n    Diagram(\u{1}),\n    Icon(graphics={{{MECHATRONICS_ICON}}}),\n    Documentation(info=\"<html>\n{}\n<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo {}.</p>\n{}\n<p>{}</p>\n<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>\n</html>\"));\nend Mechatronics;\n",
        experiment.annotation(),
        mstr(provenance_html),
        html(crate::pipeline::VERSION),
        body,
        mstr(&html(&experiment.why))
    );
    let (text, extent) = super::diagram::extend::lay_out(&text, additions.diagram.unwrap_or_default());
    let text = text.replacen("Diagram(\u{1})", &format!("Diagram({})", super::diagram::coordinate_system(&extent)), 1);
    let mut files = vec![(format!("{pkg}/Mechatronics.mo"), text.into_bytes())];
    if !motions.is_empty() {
        files.extend(motions_package(pkg, motions, &motion_names));
    }
    if live.is_some() {
        files.extend(live::files(pkg));
    }
    if let Some(c) = additions.collision {
        files.extend(collision::files(pkg));
        files.push((format!("{pkg}/{}", collision::SHAPE_FILE), c.shape_file.clone()));
    }
    Ok(files)
}

/// The Modelica class names `Motions` gives the motions (distinct, from their labels).
pub fn motion_class_names(motions: &[MotionTable]) -> Result<Vec<String>, MechatronicsError> {
    check_motions(motions)
}

/// Checks the tables (sizes, finite numbers, increasing times, joint names) and gives each motion
/// a distinct Modelica class name.
fn check_motions(motions: &[MotionTable]) -> Result<Vec<String>, MechatronicsError> {
    let mut names: Vec<String> = Vec::with_capacity(motions.len());
    for m in motions {
        let bad = |reason: String| MechatronicsError::BadMotion { motion: m.label.clone(), reason };
        let n = m.t.len();
        if n == 0 {
            return Err(bad("the table has no samples".into()));
        }
        if m.axes.is_empty() || m.axes.iter().any(|a| !is_identifier(a)) {
            return Err(bad("every axis must be a joint's Modelica name".into()));
        }
        for (what, cols) in [("q", &m.q), ("qd", &m.qd), ("qdd", &m.qdd)] {
            if cols.len() != m.axes.len() || cols.iter().any(|c| c.len() != n) {
                return Err(bad(format!("{what} must have {} samples for each of {} axes", n, m.axes.len())));
            }
            if cols.iter().flatten().any(|v| !v.is_finite()) {
                return Err(bad(format!("{what} has a number that is not finite")));
            }
        }
        if m.t.iter().any(|t| !t.is_finite()) || m.t[0] != 0.0 || m.t.windows(2).any(|w| w[1] <= w[0]) {
            return Err(bad("times must start at 0 and increase".into()));
        }
        let base = super::sanitize(&m.label, "Motion");
        let base = if base.is_empty() { "Motion".to_string() } else { base };
        let base = if is_identifier(&base) { base } else { format!("Motion_{base}") };
        let mut name = base.clone();
        let mut k = 2;
        while names.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        names.push(name);
    }
    Ok(names)
}

/// `<pkg>/Motions/`: one `CombiTimeTable` block per motion, its data inline.
fn motions_package(pkg: &str, motions: &[MotionTable], names: &[String]) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    let mut order = String::new();
    for (m, name) in motions.iter().zip(names) {
        let n = m.axes.len();
        let mut table = String::new();
        for i in 0..m.t.len() {
            if i > 0 {
                table.push_str(";\n      ");
            }
            table.push_str(&tnum(m.t[i]));
            for cols in [&m.q, &m.qd, &m.qdd] {
                for c in cols.iter() {
                    table.push_str(", ");
                    table.push_str(&tnum(c[i]));
                }
            }
        }
        let columns: Vec<String> = ["q", "qd", "qdd"]
            .iter()
            .enumerate()
            .flat_map(|(k, what)| m.axes.iter().enumerate().map(move |(a, j)| format!("y[{}] = {what} of {j}", k * n + a + 1)))
            .collect();
        let text = format!(
            "within {pkg}.Motions;\nblock {name} \"Motion {}: {} s, {n} joints\"\n  extends Modelica.Blocks.Sources.CombiTimeTable(\n    final tableOnFile=false,\n    final table=[{table}],\n    final smoothness=Modelica.Blocks.Types.Smoothness.LinearSegments,\n    final extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint);\n  annotation (Documentation(info=\"<html>\n<p>The motion <b>{}</b> sampled at {} points from t = 0 to {} s (linear interpolation, last values held). Outputs: {}.</p>\n</html>\"));\nend {name};\n",
            mstr(&m.label),
            num(m.t[m.t.len() - 1]),
            html(&m.label),
            m.t.len(),
            num(m.t[m.t.len() - 1]),
            html(&columns.join(", "))
        );
        files.push((format!("{pkg}/Motions/{name}.mo"), text.into_bytes()));
        let _ = writeln!(order, "{name}");
    }
    let package = format!(
        "within {pkg};\npackage Motions \"Reference trajectories of the model's motions (from cad2mo)\"\n  extends Modelica.Icons.Package;\n  annotation (Documentation(info=\"<html>\n<p>One table per motion defined in cad2mo: column 1 is the time in s, then the position (rad or m), speed and acceleration of every joint of the motion. <code>Mechatronics</code> instantiates each and its drives follow the one its parameter <code>motion</code> selects.</p>\n</html>\"));\nend Motions;\n"
    );
    files.push((format!("{pkg}/Motions/package.mo"), package.into_bytes()));
    files.push((format!("{pkg}/Motions/package.order"), order.into_bytes()));
    files
}

/// The drive library, `<pkg>/Components/Drives/...`: written into every package (the line
/// `Drives` belongs in `<pkg>/Components/package.order`).
pub fn components(pkg: &str) -> Vec<(String, Vec<u8>)> {
    classes::files(pkg)
}
