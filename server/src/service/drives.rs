//! Drive assignments: which motor, gear and controller from the motor library drive which joint,
//! and how they become the pipeline's [`DrivePlan`]s for `Mechatronics.mo`.
//!
//! An assignment is keyed by the joint's stable Modelica name (the element name in the report),
//! so it survives CAD changes: a new version of the model keeps every assignment whose joint still
//! exists; the others are reported as orphaned and left out of the generated model (never
//! deleted, so a joint that comes back gets its drive back).

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value as Json};

use super::FieldError;
use crate::store::StoreError;
use cad2mo_engine::library::{Class, Instance, Issue, Value};
use cad2mo_engine::pipeline::back::modelica::mechatronics::{ClassChoice, DrivePlan, JointKind, MechatronicsError, ParamValue, Reference};

/// The reference a joint follows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum ReferenceSpec {
    /// A constant joint angle (rad) or position (m).
    Constant { value: f64 },
    /// `[[time s, value], ...]`, times non-decreasing.
    Table { points: Vec<[f64; 2]> },
}

/// A stored drive assignment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Assignment {
    pub joint: String,
    pub joint_node_id: String,
    pub motor_instance: String,
    pub gear_instance: String,
    pub controller_instance: String,
    /// Overrides of editable parameters: `{"motor": {"R": 0.3}, "gear": {"ratio": 100}, ...}`.
    pub overrides: Map<String, Json>,
    pub reference: ReferenceSpec,
}

/// The slots of a drive and the library domain each accepts.
pub const SLOTS: [(&str, &str); 3] = [("motor", "motor"), ("gear", "gear"), ("controller", "controller")];

fn to_param(v: &Value) -> ParamValue {
    match v {
        Value::Real(x) => ParamValue::Real(*x),
        Value::Integer(i) => ParamValue::Integer(*i),
        Value::Boolean(b) => ParamValue::Boolean(*b),
        Value::String(s) => ParamValue::String(s.clone()),
    }
}

/// The request field a refusal of the Mechatronics generator is about, so that a form shows it
/// at its control: `overrides.<slot>.<param>` for a parameter of the class chosen for a slot
/// (`classes`: slot and Modelica class, e.g. `("gear", "cad2mo.Drives.Gears.Efficiency")`),
/// `<slot>_instance` for a class that does not fit, `reference` for the reference, else `drive`.
pub fn generator_field(e: &MechatronicsError, classes: &[(&str, &str)]) -> String {
    let slot_of = |class: &str| classes.iter().find(|(_, c)| *c == class).map(|(s, _)| *s);
    let param = match e {
        MechatronicsError::OutOfRange { class, param, .. }
        | MechatronicsError::WrongType { class, param, .. }
        | MechatronicsError::UnknownParameter { class, param, .. }
        | MechatronicsError::DuplicateParameter { class, param, .. } => slot_of(class).map(|s| format!("overrides.{s}.{param}")),
        MechatronicsError::UnknownClass { slot, .. } => Some(format!("{slot}_instance")),
        MechatronicsError::GearDoesNotFitJoint { .. } => Some("gear_instance".to_string()),
        MechatronicsError::BadReference { .. } => Some("reference".to_string()),
        _ => None,
    };
    param.unwrap_or_else(|| "drive".to_string())
}

/// Checks a reference: finite values, non-decreasing times.
pub fn check_reference(r: &ReferenceSpec) -> Vec<Issue> {
    let mut out = Vec::new();
    match r {
        ReferenceSpec::Constant { value } if !value.is_finite() => out.push(Issue::new("reference.value", "must be a finite number")),
        ReferenceSpec::Table { points } => {
            if points.is_empty() {
                out.push(Issue::new("reference.points", "needs at least one [time, value] point"));
            }
            if points.iter().flatten().any(|x| !x.is_finite()) {
                out.push(Issue::new("reference.points", "every time and value must be finite"));
            }
            if points.windows(2).any(|w| w[1][0] < w[0][0]) {
                out.push(Issue::new("reference.points", "times must not decrease"));
            }
        }
        _ => {}
    }
    out
}

/// The instance of each slot with its class, and the slot's overrides, checked: domains match
/// the slots and overrides touch editable parameters only, with valid values.
pub fn check_slots(instances: &[(&str, &Instance, &Class)], overrides: &Map<String, Json>) -> Vec<Issue> {
    let mut out = Vec::new();
    for key in overrides.keys() {
        if !SLOTS.iter().any(|(s, _)| s == key) {
            out.push(Issue::new(format!("overrides.{key}"), "unknown slot (motor, gear or controller)"));
        }
    }
    for (slot, inst, class) in instances {
        let domain = SLOTS.iter().find(|(s, _)| s == slot).map(|(_, d)| *d).unwrap_or("");
        if class.domain != domain {
            out.push(Issue::new(
                format!("{slot}_instance"),
                format!("instance \"{}\" is a {} (class \"{}\"), not a {domain}", inst.name, class.domain, class.name),
            ));
        }
        if let Some(o) = overrides.get(*slot) {
            match o.as_object() {
                Some(map) => {
                    if let Err(issues) = cad2mo_engine::library::validate_overrides(class, map) {
                        out.extend(issues.into_iter().map(|i| Issue::new(format!("overrides.{slot}.{}", i.field), i.message)));
                    }
                }
                None => out.push(Issue::new(format!("overrides.{slot}"), "must be an object {\"parameter\": value}")),
            }
        }
    }
    out
}

/// The class path and values of one slot: the instance's values with the overrides applied.
/// Datasheet values are not Modelica parameters and are left out.
pub fn choice(class: &Class, inst: &Instance, overrides: Option<&Json>) -> Result<ClassChoice, Vec<Issue>> {
    let over = match overrides.and_then(Json::as_object) {
        Some(map) => cad2mo_engine::library::validate_overrides(class, map)?,
        None => Vec::new(),
    };
    let params = inst
        .values
        .iter()
        .filter(|(name, _)| !class.parameter(name).is_some_and(|p| p.datasheet))
        .map(|(name, v)| {
            let v = over.iter().find(|(n, _)| n == name).map(|(_, o)| o).unwrap_or(v);
            (name.clone(), to_param(v))
        })
        .collect();
    Ok(ClassChoice { modelica_class: class.modelica_class.clone(), params, instance: inst.name.clone() })
}

/// A joint element of a converted model that can carry a drive.
pub struct DrivableJoint {
    pub name: String,
    pub node_id: String,
    pub kind: JointKind,
    pub start: f64,
    pub label: String,
}

/// Every revolute and prismatic element of a report (`report.json` as JSON). Loop cuts emitted
/// as constraints (`revolute-planar-loop-constraint`, `constraint-*`) or omitted have no flange.
pub fn drivable_joints(report: &Json) -> Vec<DrivableJoint> {
    let mut out = Vec::new();
    for j in report["joints"].as_array().into_iter().flatten() {
        let emitted = j["emitted_as"].as_str().unwrap_or_default();
        if emitted == "revolute-planar-loop-constraint" || emitted.starts_with("constraint-") || emitted.starts_with("omitted") {
            continue;
        }
        let cad = j["cad_name"].as_str().unwrap_or_default();
        let node = j["node_id"].as_str().unwrap_or_default();
        for e in j["elements"].as_array().into_iter().flatten() {
            let kind = match e["kind"].as_str() {
                Some("revolute") => JointKind::Revolute,
                Some("prismatic") => JointKind::Prismatic,
                _ => continue,
            };
            out.push(DrivableJoint {
                name: e["modelica_name"].as_str().unwrap_or_default().to_string(),
                node_id: node.to_string(),
                kind,
                start: e["initial_q"].as_f64().unwrap_or(0.0),
                label: format!("joint {cad} (nodeID {node})"),
            });
        }
    }
    out
}

/// A drive resolved against the library: everything but what the converted model tells.
#[derive(Clone, Debug)]
pub struct ResolvedDrive {
    pub joint: String,
    pub motor: ClassChoice,
    pub gear: ClassChoice,
    pub controller: ClassChoice,
    pub reference: ReferenceSpec,
}

/// Plans for the joints of `report`, and the joints of `drives` it no longer has (orphans).
pub fn plans(report: &Json, drives: &[ResolvedDrive]) -> (Vec<DrivePlan>, Vec<String>) {
    let joints = drivable_joints(report);
    let mut plans = Vec::new();
    let mut orphans = Vec::new();
    for d in drives {
        let Some(j) = joints.iter().find(|j| j.name == d.joint) else {
            orphans.push(d.joint.clone());
            continue;
        };
        plans.push(DrivePlan {
            joint: j.name.clone(),
            kind: j.kind,
            start: j.start,
            motor: d.motor.clone(),
            gear: d.gear.clone(),
            controller: d.controller.clone(),
            reference: match &d.reference {
                ReferenceSpec::Constant { value } => Reference::Constant(*value),
                ReferenceSpec::Table { points } => Reference::Table(points.iter().map(|p| (p[0], p[1])).collect()),
            },
            label: j.label.clone(),
        });
    }
    (plans, orphans)
}

/// Why a model's drives cannot be resolved against the library.
#[derive(Debug, thiserror::Error)]
pub enum DriveError {
    /// An assignment names a library instance that was deleted since.
    #[error("drive of joint {joint}: library instance {instance} is gone")]
    InstanceGone { joint: String, instance: String },
    /// An assignment's overrides no longer validate against its (changed) library class.
    #[error("drive of joint {joint}: its {slot} overrides no longer fit the library")]
    Overrides { joint: String, slot: &'static str, errors: Vec<FieldError> },
    #[error(transparent)]
    Store(#[from] StoreError),
}

/// Every assignment of a model resolved against the current library (instances' values with
/// the assignment's overrides). An assignment whose overrides no longer validate (the library
/// changed) is an error naming it.
pub async fn resolve_for_model(store: &crate::store::Store, model_id: &str) -> Result<Vec<ResolvedDrive>, DriveError> {
    let mut out = Vec::new();
    for a in crate::store::drives::list(store, model_id).await? {
        let mut picked = Vec::new();
        for (slot, id) in [("motor", &a.motor_instance), ("gear", &a.gear_instance), ("controller", &a.controller_instance)] {
            let (inst, class) = crate::store::library::get_instance(store, id)
                .await?
                .ok_or_else(|| DriveError::InstanceGone { joint: a.joint.clone(), instance: id.clone() })?;
            let c = choice(&class, &inst, a.overrides.get(slot)).map_err(|issues| DriveError::Overrides {
                joint: a.joint.clone(),
                slot,
                errors: issues
                    .into_iter()
                    .map(|i| FieldError { field: format!("{}.{slot}.{}", a.joint, i.field), message: i.message })
                    .collect(),
            })?;
            picked.push(c);
        }
        let mut it = picked.into_iter();
        let (Some(motor), Some(gear), Some(controller)) = (it.next(), it.next(), it.next()) else { continue };
        out.push(ResolvedDrive { joint: a.joint, motor, gear, controller, reference: a.reference });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cad2mo_engine::pipeline::front::bundle::Bundle;

    /// Datasheet values are no Modelica parameters: a drive's class choice leaves them out.
    #[test]
    fn datasheet_values_are_not_modifiers() {
        let lib = cad2mo_engine::library::seed::library().expect("seed");
        let re40 = lib.instances.iter().find(|i| i.id == cad2mo_engine::library::seed::MAXON_RE40).expect("RE 40");
        let class = lib.class(&re40.class_id).expect("class");
        assert!(re40.value("T_nom").is_some());
        let c = choice(class, re40, None).expect("choice");
        let names: Vec<&str> = c.params.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["R", "L", "k", "J", "d", "V_max", "I_max", "Tc"]);
    }

    /// Loop cuts emitted as constraints have no drive flange, so they are never offered.
    #[test]
    fn loop_cuts_are_not_drivable() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in");
        for (case, cut, other) in [("immobile_leg", "SHANK_RootPart", "RootPart_HIP"), ("slider_crank", "ROD_PISTON", "PISTON_RootPart")] {
            let files = std::fs::read_dir(root.join(case))
                .expect("case folder")
                .map(|e| e.expect("entry").path())
                .map(|p| (p.file_name().expect("name").to_string_lossy().into_owned(), std::fs::read(&p).expect("read")));
            let bundle = Bundle::from_files(case, files).expect("bundle");
            let opts = cad2mo_engine::pipeline::Options { write_shapes: false, ..Default::default() };
            let out = cad2mo_engine::pipeline::convert(&bundle, &opts).expect("converts");
            let report = serde_json::to_value(&out.report).expect("json");
            let names: Vec<String> = drivable_joints(&report).into_iter().map(|j| j.name).collect();
            assert!(!names.iter().any(|n| n == cut), "{case}: {names:?}");
            assert!(names.iter().any(|n| n == other), "{case}: {names:?}");
        }
    }
}
