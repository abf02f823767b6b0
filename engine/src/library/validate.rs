//! The library's rules: classes, values, instances, nameplate values, overrides and imports.
//! Every check collects all the problems it finds.

use std::collections::{BTreeMap, HashMap, HashSet};

use serde::Serialize;
use serde_json::{Map, Value as Json};

use super::units;
use super::xml::{Document, XmlClass, XmlInstance};
use super::{Class, Instance, Issue, Library, ParamType, Parameter, Value};
use crate::pipeline::back::modelica::KEYWORDS;

const MAX_NAME: usize = 200;
const MAX_TEXT: usize = 10_000;
const MAX_PARAMETERS: usize = 200;

/// A parameter as given (before checking).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ParameterDraft {
    pub name: String,
    /// `Real`, `Integer`, `Boolean` or `String`.
    pub ty: String,
    pub unit: String,
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub editable: bool,
    /// A datasheet value (not a Modelica parameter; optional per instance; never editable).
    pub datasheet: bool,
    /// A value as [`check_value`] accepts it.
    pub default: Option<Json>,
    pub comment: String,
}

/// A class as given (before checking).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClassDraft {
    pub name: String,
    pub domain: String,
    pub modelica_class: String,
    pub description: String,
    pub parameters: Vec<ParameterDraft>,
}

/// An instance as given (before checking).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct InstanceDraft {
    pub name: String,
    pub source: String,
    /// `{"param": value}`, each value as [`check_value`] accepts it.
    pub values: Map<String, Json>,
}

fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_') && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn check_name(field: &str, what: &str, name: &str, issues: &mut Vec<Issue>) {
    if name.trim().is_empty() {
        issues.push(Issue::new(field, format!("{what} must not be empty")));
    } else if name.trim() != name {
        issues.push(Issue::new(field, format!("{what} must not start or end with white space")));
    } else if name.chars().count() > MAX_NAME {
        issues.push(Issue::new(field, format!("{what} is longer than {MAX_NAME} characters")));
    } else if name.chars().any(char::is_control) {
        issues.push(Issue::new(field, format!("{what} must not contain control characters")));
    }
}

fn check_text(field: &str, what: &str, text: &str, issues: &mut Vec<Issue>) {
    if text.chars().count() > MAX_TEXT {
        issues.push(Issue::new(field, format!("{what} is longer than {MAX_TEXT} characters")));
    }
}

fn json_kind(v: &Json) -> &'static str {
    match v {
        Json::Null => "null",
        Json::Bool(_) => "a boolean",
        Json::Number(_) => "a number",
        Json::String(_) => "a string",
        Json::Array(_) => "an array",
        Json::Object(_) => "an object",
    }
}

fn describe_number(x: f64, unit: &str) -> String {
    Value::Real(x).describe(unit)
}

/// Checks one value for parameter `p`: a JSON number, boolean or string in the parameter's unit,
/// or `{"value": 82, "unit": "uH"}` (numbers only), converted to the parameter's unit. Then the
/// type (an Integer must be a whole number), finiteness and the inclusive limits. The message
/// names the parameter.
pub fn check_value(p: &Parameter, raw: &Json) -> Result<Value, String> {
    let name = &p.name;
    let (x, given_unit) = match raw {
        Json::Object(m) => {
            let unknown: Vec<&str> = m.keys().map(String::as_str).filter(|k| *k != "value" && *k != "unit").collect();
            if !unknown.is_empty() {
                return Err(format!(
                    "{name}: unexpected key(s) {} in a value object (it has \"value\" and optionally \"unit\")",
                    unknown.iter().map(|k| format!("\"{k}\"")).collect::<Vec<_>>().join(", ")
                ));
            }
            let Some(v) = m.get("value") else {
                return Err(format!("{name}: the value object has no \"value\""));
            };
            let unit = match m.get("unit") {
                None | Some(Json::Null) => None,
                Some(Json::String(s)) if s.is_empty() => None,
                Some(Json::String(s)) => Some(s.as_str()),
                Some(other) => return Err(format!("{name}: \"unit\" must be a string, got {}", json_kind(other))),
            };
            (v, unit)
        }
        other => (other, None),
    };
    let value = match p.ty {
        ParamType::Real | ParamType::Integer => {
            let Json::Number(n) = x else {
                let hint = if p.unit.is_empty() {
                    String::new()
                } else {
                    format!(" in {} (or {{\"value\": <number>, \"unit\": \"...\"}})", p.unit)
                };
                return Err(format!("{name}: expected a number{hint}, got {}", json_kind(x)));
            };
            let exact_int = n.as_i64();
            let Some(given) = n.as_f64() else {
                return Err(format!("{name}: {n} is not a number"));
            };
            let (converted, x_si) = match given_unit {
                Some(u) if u != p.unit => {
                    if p.unit.is_empty() {
                        return Err(format!("{name} has no unit, so \"{u}\" cannot be converted"));
                    }
                    let v = units::convert(given, u, &p.unit).map_err(|e| format!("{name}: {e}"))?;
                    (true, v)
                }
                _ => (false, given),
            };
            if !x_si.is_finite() {
                return Err(format!("{name}: {x_si} is not a finite number"));
            }
            let value = match p.ty {
                ParamType::Integer => match exact_int {
                    Some(i) if !converted => Value::Integer(i),
                    _ if x_si.fract() == 0.0 && x_si.abs() < 9.0e15 => Value::Integer(x_si as i64),
                    _ => return Err(format!("{name}: expected a whole number (Integer), got {}", describe_number(x_si, &p.unit))),
                },
                _ => Value::Real(x_si),
            };
            let v = value.as_f64().unwrap_or(x_si);
            if let Some(min) = p.min {
                if v < min {
                    return Err(format!("{name} = {} is below the minimum {}", value.describe(&p.unit), describe_number(min, &p.unit)));
                }
            }
            if let Some(max) = p.max {
                if v > max {
                    return Err(format!("{name} = {} is above the maximum {}", value.describe(&p.unit), describe_number(max, &p.unit)));
                }
            }
            value
        }
        ParamType::Boolean | ParamType::String => {
            if let Some(u) = given_unit {
                return Err(format!("{name} is a {}: a unit (\"{u}\") applies to numbers only", p.ty.as_str()));
            }
            match (p.ty, x) {
                (ParamType::Boolean, Json::Bool(b)) => Value::Boolean(*b),
                (ParamType::String, Json::String(s)) => Value::String(s.clone()),
                _ => {
                    let want = if p.ty == ParamType::Boolean { "true or false" } else { "a string" };
                    return Err(format!("{name}: expected {want} ({}), got {}", p.ty.as_str(), json_kind(x)));
                }
            }
        }
    };
    Ok(value)
}

/// Checks a class. `id` is kept as given (the caller makes or parses it).
pub fn check_class(id: &str, d: &ClassDraft) -> Result<Class, Vec<Issue>> {
    let mut issues = Vec::new();
    check_name("name", "the class name", &d.name, &mut issues);
    if !(d.domain.len() <= 40
        && d.domain.starts_with(|c: char| c.is_ascii_lowercase())
        && d.domain.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '-'))
    {
        issues
            .push(Issue::new("domain", format!("the domain \"{}\" must be a lower-case word such as motor, gear or controller", d.domain)));
    }
    let segments: Vec<&str> = d.modelica_class.split('.').collect();
    if d.modelica_class.len() > 300 || segments.len() < 2 || !segments.iter().all(|s| is_identifier(s)) {
        issues.push(Issue::new(
            "modelica_class",
            format!(
                "\"{}\" is not a full Modelica class path such as cad2mo.Drives.Motors.DCPermanentMagnet or Modelica.Mechanics.Rotational.Components.IdealGear",
                d.modelica_class
            ),
        ));
    }
    check_text("description", "the description", &d.description, &mut issues);
    if d.parameters.len() > MAX_PARAMETERS {
        issues.push(Issue::new("parameters", format!("a class has at most {MAX_PARAMETERS} parameters")));
    }
    let mut seen: HashMap<&str, usize> = HashMap::new();
    let mut parameters = Vec::with_capacity(d.parameters.len());
    for (i, pd) in d.parameters.iter().enumerate() {
        let field = |f: &str| format!("parameters[{i}].{f}");
        let before = issues.len();
        if !is_identifier(&pd.name) || KEYWORDS.contains(&pd.name.as_str()) {
            issues.push(Issue::new(field("name"), format!("\"{}\" is not a Modelica identifier", pd.name)));
        } else if let Some(j) = seen.insert(pd.name.as_str(), i) {
            issues.push(Issue::new(field("name"), format!("parameter {} is declared twice (also parameters[{j}])", pd.name)));
        }
        let ty = ParamType::parse(&pd.ty);
        match ty {
            None => issues.push(Issue::new(
                field("type"),
                format!("parameter {}: type \"{}\" must be one of Real, Integer, Boolean, String", pd.name, pd.ty),
            )),
            Some(t) if t.is_numeric() => {
                if !pd.unit.is_empty() && !units::is_si(&pd.unit) {
                    let msg = match units::si_of(&pd.unit) {
                        Some(si) => format!(
                            "parameter {}: \"{}\" is not an SI unit; declare \"{si}\" (values may still be given in {})",
                            pd.name, pd.unit, pd.unit
                        ),
                        None => format!("parameter {}: unknown unit \"{}\"; use one of {}", pd.name, pd.unit, units::si_units().join(", ")),
                    };
                    issues.push(Issue::new(field("unit"), msg));
                }
                for (f, limit) in [("min", pd.min), ("max", pd.max)] {
                    if limit.is_some_and(|x| !x.is_finite()) {
                        issues.push(Issue::new(field(f), format!("parameter {}: {f} must be a finite number", pd.name)));
                    }
                }
                if let (Some(lo), Some(hi)) = (pd.min, pd.max) {
                    if lo > hi {
                        issues.push(Issue::new(field("max"), format!("parameter {}: max {hi} is below min {lo}", pd.name)));
                    }
                }
            }
            Some(t) => {
                if !pd.unit.is_empty() {
                    issues.push(Issue::new(field("unit"), format!("parameter {}: a {} has no unit", pd.name, t.as_str())));
                }
                if pd.min.is_some() || pd.max.is_some() {
                    issues.push(Issue::new(field("min"), format!("parameter {}: a {} has no limits", pd.name, t.as_str())));
                }
            }
        }
        if pd.datasheet && pd.editable {
            issues.push(Issue::new(
                field("editable"),
                format!("parameter {}: a datasheet value belongs to the item and cannot be editable", pd.name),
            ));
        }
        check_text(&field("comment"), "the comment", &pd.comment, &mut issues);
        let Some(ty) = ty else { continue };
        if issues.len() > before {
            continue;
        }
        let mut p = Parameter {
            name: pd.name.clone(),
            ty,
            unit: pd.unit.clone(),
            min: pd.min,
            max: pd.max,
            editable: pd.editable,
            datasheet: pd.datasheet,
            default: None,
            comment: pd.comment.clone(),
        };
        if let Some(raw) = &pd.default {
            match check_value(&p, raw) {
                Ok(v) => p.default = Some(v),
                Err(m) => issues.push(Issue::new(field("default"), m)),
            }
        }
        parameters.push(p);
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    Ok(Class {
        id: id.to_string(),
        name: d.name.clone(),
        domain: d.domain.clone(),
        modelica_class: d.modelica_class.clone(),
        description: d.description.clone(),
        parameters,
    })
}

/// Checks every value of `values` against `class`, under `prefix` (`values`, `overrides`):
/// the good values (in class order) and the problems. Every Modelica parameter needs a value;
/// datasheet parameters may be absent.
fn check_map(class: &Class, values: &Map<String, Json>, prefix: &str) -> (Vec<(String, Value)>, Vec<Issue>) {
    let mut good = Vec::new();
    let mut issues = Vec::new();
    for p in &class.parameters {
        let field = format!("{prefix}.{}", p.name);
        match values.get(&p.name) {
            Some(raw) => match check_value(p, raw) {
                Ok(v) => good.push((p.name.clone(), v)),
                Err(m) => issues.push(Issue::new(field, m)),
            },
            None if p.datasheet => {}
            None => {
                let hint = match &p.default {
                    Some(d) => format!(" (the class default is {})", d.describe(&p.unit)),
                    None => String::new(),
                };
                issues.push(Issue::new(
                    field,
                    format!("{} has no value: give one in {}{hint}", p.name, if p.unit.is_empty() { p.ty.as_str() } else { &p.unit }),
                ));
            }
        }
    }
    for key in values.keys() {
        if class.parameter(key).is_none() {
            issues.push(Issue::new(
                format!("{prefix}.{key}"),
                format!("{key} is not a parameter of class \"{}\" (parameters: {})", class.name, param_list(class)),
            ));
        }
    }
    (good, issues)
}

fn param_list(class: &Class) -> String {
    if class.parameters.is_empty() {
        return "none".to_string();
    }
    class.parameters.iter().map(|p| p.name.as_str()).collect::<Vec<_>>().join(", ")
}

/// Checks a complete set of values for `class`: every Modelica parameter needs one (datasheet
/// parameters may be absent), unknown names are errors. Fields are `values.<param>`.
pub fn check_values(class: &Class, values: &Map<String, Json>) -> Result<Vec<(String, Value)>, Vec<Issue>> {
    let (good, issues) = check_map(class, values, "values");
    if issues.is_empty() {
        Ok(good)
    } else {
        Err(issues)
    }
}

/// Checks a new instance of `class`.
pub fn check_instance(id: &str, class: &Class, d: &InstanceDraft) -> Result<Instance, Vec<Issue>> {
    let mut issues = Vec::new();
    check_name("name", "the instance name", &d.name, &mut issues);
    check_text("source", "the source", &d.source, &mut issues);
    let (values, value_issues) = check_map(class, &d.values, "values");
    issues.extend(value_issues);
    if !issues.is_empty() {
        return Err(issues);
    }
    Ok(Instance { id: id.to_string(), class_id: class.id.clone(), name: d.name.clone(), source: d.source.clone(), values })
}

/// Checks a change of an existing instance: its name, source and editable values may change;
/// a nameplate (non-editable) value must stay as it is (given again in any unit is fine; it is
/// kept bit for bit). A datasheet value the instance lacks may be added, one it has may not be
/// removed. A different motor is a new instance.
pub fn check_instance_update(class: &Class, old: &Instance, d: &InstanceDraft) -> Result<Instance, Vec<Issue>> {
    let mut issues = Vec::new();
    check_name("name", "the instance name", &d.name, &mut issues);
    check_text("source", "the source", &d.source, &mut issues);
    let (mut values, value_issues) = check_map(class, &d.values, "values");
    issues.extend(value_issues);
    for (name, v) in values.iter_mut() {
        let Some(p) = class.parameter(name) else { continue };
        if p.editable {
            continue;
        }
        match old.value(name) {
            Some(was) if was.same(v) => *v = was.clone(),
            Some(was) => issues.push(Issue::new(
                format!("values.{name}"),
                format!(
                    "{name} is a nameplate value of \"{}\" (not editable): it stays {}; for a different {} create a new instance",
                    old.name,
                    was.describe(&p.unit),
                    class.domain
                ),
            )),
            None => {}
        }
    }
    for p in class.parameters.iter().filter(|p| p.datasheet && !p.editable) {
        if let (Some(was), None) = (old.value(&p.name), d.values.get(&p.name)) {
            issues.push(Issue::new(
                format!("values.{}", p.name),
                format!(
                    "{} is a nameplate value of \"{}\" (not editable): it stays {}; give it again",
                    p.name,
                    old.name,
                    was.describe(&p.unit)
                ),
            ));
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    Ok(Instance { id: old.id.clone(), class_id: old.class_id.clone(), name: d.name.clone(), source: d.source.clone(), values })
}

/// Checks per-drive overrides of an instance of `class`: only editable parameters may be
/// overridden, each value as [`check_value`] accepts it. Fields are `overrides.<param>`.
/// Returns the checked values in class order.
pub fn validate_overrides(class: &Class, overrides: &Map<String, Json>) -> Result<Vec<(String, Value)>, Vec<Issue>> {
    let mut good = Vec::new();
    let mut issues = Vec::new();
    for (key, raw) in overrides {
        let field = format!("overrides.{key}");
        match class.parameter(key) {
            None => issues.push(Issue::new(
                field,
                format!("{key} is not a parameter of class \"{}\" (parameters: {})", class.name, param_list(class)),
            )),
            Some(p) if !p.editable => issues.push(Issue::new(
                field,
                format!(
                    "{key} is a nameplate value of class \"{}\" and cannot be overridden per drive (editable: {})",
                    class.name,
                    editable_list(class)
                ),
            )),
            Some(p) => match check_value(p, raw) {
                Ok(v) => good.push((key.clone(), v)),
                Err(m) => issues.push(Issue::new(field, m)),
            },
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    good.sort_by_key(|(n, _)| class.parameters.iter().position(|p| &p.name == n));
    Ok(good)
}

fn editable_list(class: &Class) -> String {
    let e: Vec<&str> = class.parameters.iter().filter(|p| p.editable).map(|p| p.name.as_str()).collect();
    if e.is_empty() {
        "none".to_string()
    } else {
        e.join(", ")
    }
}

/// The values a drive uses, in class order: an override (from [`validate_overrides`]; applied
/// to editable parameters only), else the instance's value, else the class default. A parameter
/// with none of these is left out (the generated class's own default applies).
pub fn resolved_values(class: &Class, instance: &Instance, overrides: &[(String, Value)]) -> Vec<(String, Value)> {
    class
        .parameters
        .iter()
        .filter_map(|p| {
            let over = if p.editable { overrides.iter().find(|(n, _)| n == &p.name).map(|(_, v)| v) } else { None };
            over.or_else(|| instance.value(&p.name)).or(p.default.as_ref()).map(|v| (p.name.clone(), v.clone()))
        })
        .collect()
}

/// Carries an instance over to a changed class: values of kept parameters are converted to the
/// new unit and re-checked against the new type and limits, removed parameters are dropped, new
/// parameters take their default (or are a problem; a new datasheet parameter without default is
/// left out). Fields are `instances."<name>".<param>`.
pub fn migrate_instance(old_class: &Class, new_class: &Class, inst: &Instance) -> Result<Instance, Vec<Issue>> {
    let mut values = Vec::new();
    let mut issues = Vec::new();
    for p in &new_class.parameters {
        let field = format!("instances.{:?}.{}", inst.name, p.name);
        let old = inst.value(&p.name).map(|v| (v, old_class.parameter(&p.name).map_or("", |op| op.unit.as_str())));
        match old {
            Some((v, old_unit)) => {
                let raw = match v.as_f64() {
                    Some(_) if !old_unit.is_empty() && old_unit != p.unit => {
                        serde_json::json!({"value": v.to_json(), "unit": old_unit})
                    }
                    _ => v.to_json(),
                };
                match check_value(p, &raw) {
                    Ok(nv) => values.push((p.name.clone(), if nv.same(v) { v.clone() } else { nv })),
                    Err(m) => issues.push(Issue::new(field, format!("instance \"{}\": {m}", inst.name))),
                }
            }
            None => match &p.default {
                Some(d) => values.push((p.name.clone(), d.clone())),
                None if p.datasheet => {}
                None => issues.push(Issue::new(
                    field,
                    format!("instance \"{}\" has no value for the new parameter {}: give the parameter a default", inst.name, p.name),
                )),
            },
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    Ok(Instance { values, class_id: new_class.id.clone(), ..inst.clone() })
}

/// What an import does, in counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct ImportCounts {
    pub classes_created: usize,
    pub classes_updated: usize,
    pub instances_created: usize,
    pub instances_updated: usize,
    /// Instances not in the file whose class the file changed (carried over to it).
    pub instances_migrated: usize,
}

/// The writes of a checked import: classes and instances to create or replace, by id.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ImportPlan {
    pub classes: Vec<Class>,
    pub instances: Vec<Instance>,
    pub counts: ImportCounts,
}

fn class_field(c: &XmlClass, field: &str) -> String {
    // `parameters[3].unit` -> the line of that <parameter>.
    if let Some(rest) = field.strip_prefix("parameters[") {
        if let Some((idx, tail)) = rest.split_once(']') {
            if let Some((line, name)) = idx.parse::<usize>().ok().and_then(|i| c.param_lines.get(i).zip(c.draft.parameters.get(i))) {
                return format!("line {line} <parameter name={:?}>{tail}", name.name);
            }
        }
    }
    format!("line {} <class name={:?}> {field}", c.line, c.draft.name)
}

fn instance_field(i: &XmlInstance, field: &str) -> String {
    if let Some(param) = field.strip_prefix("values.") {
        if let Some(v) = i.values.iter().find(|v| v.param == param) {
            return format!("line {} <value param={:?}>", v.line, v.param);
        }
    }
    format!("line {} <instance name={:?}> {field}", i.line, i.name)
}

/// Checks an imported file against the current library and plans its writes. Classes and
/// instances are matched by id: new ids are created, known ids replaced. Everything is checked
/// before anything is planned: class and instance rules, ids, unique names in the resulting
/// library, instances of changed classes that are not in the file (carried over with
/// [`migrate_instance`]). An instance never moves to another class.
pub fn plan_import(current: &Library, doc: &Document) -> Result<ImportPlan, Vec<Issue>> {
    let mut issues = Vec::new();
    let mut plan = ImportPlan::default();

    // Classes of the file.
    let mut file_classes: BTreeMap<String, Class> = BTreeMap::new();
    let mut first_line: HashMap<String, usize> = HashMap::new();
    for xc in &doc.classes {
        let Some(id) = super::parse_id(&xc.id) else {
            issues.push(Issue::new(format!("line {} <class>", xc.line), format!("id \"{}\" is not a UUID", xc.id)));
            continue;
        };
        if let Some(line) = first_line.insert(id.clone(), xc.line) {
            issues.push(Issue::new(format!("line {} <class>", xc.line), format!("class id {id} appears twice (also line {line})")));
            continue;
        }
        match super::check_class(&id, &xc.draft) {
            Ok(c) => {
                file_classes.insert(id, c);
            }
            Err(errs) => issues.extend(errs.into_iter().map(|e| Issue::new(class_field(xc, &e.field), e.message))),
        }
    }

    // The resulting set of classes, and unique class names in it.
    let mut classes: BTreeMap<String, Class> = current.classes.iter().map(|c| (c.id.clone(), c.clone())).collect();
    for (id, c) in &file_classes {
        if classes.insert(id.clone(), c.clone()).is_some() {
            plan.counts.classes_updated += 1;
        } else {
            plan.counts.classes_created += 1;
        }
    }
    let mut by_name: HashMap<&str, &str> = HashMap::new();
    for c in classes.values() {
        if let Some(other) = by_name.insert(c.name.as_str(), c.id.as_str()) {
            issues.push(Issue::new(
                format!("class {:?}", c.name),
                format!("two classes would be named \"{}\" (ids {other} and {})", c.name, c.id),
            ));
        }
    }

    // Instances of the file.
    let current_instances: HashMap<&str, &Instance> = current.instances.iter().map(|i| (i.id.as_str(), i)).collect();
    let mut instances: BTreeMap<String, Instance> = current.instances.iter().map(|i| (i.id.clone(), i.clone())).collect();
    let mut in_file: HashSet<String> = HashSet::new();
    let mut inst_line: HashMap<String, usize> = HashMap::new();
    for xi in &doc.instances {
        let at = format!("line {} <instance name={:?}>", xi.line, xi.name);
        let Some(id) = super::parse_id(&xi.id) else {
            issues.push(Issue::new(at, format!("id \"{}\" is not a UUID", xi.id)));
            continue;
        };
        if let Some(line) = inst_line.insert(id.clone(), xi.line) {
            issues.push(Issue::new(at, format!("instance id {id} appears twice (also line {line})")));
            continue;
        }
        let Some(class_id) = super::parse_id(&xi.class_id) else {
            issues.push(Issue::new(at, format!("class \"{}\" is not a UUID", xi.class_id)));
            continue;
        };
        let Some(class) = classes.get(&class_id) else {
            issues.push(Issue::new(at, format!("class {class_id} is neither in the file nor in the library")));
            continue;
        };
        if let Some(old) = current_instances.get(id.as_str()) {
            if old.class_id != class_id {
                issues.push(Issue::new(
                    at,
                    format!("instance {id} belongs to class {} in the library; an instance cannot change class", old.class_id),
                ));
                continue;
            }
        }
        let values = match xi.values_json(class) {
            Ok(v) => v,
            Err(errs) => {
                issues.extend(errs);
                continue;
            }
        };
        let draft = InstanceDraft { name: xi.name.clone(), source: xi.source.clone(), values };
        match check_instance(&id, class, &draft) {
            Ok(inst) => {
                if instances.insert(id.clone(), inst).is_some() {
                    plan.counts.instances_updated += 1;
                } else {
                    plan.counts.instances_created += 1;
                }
                in_file.insert(id);
            }
            Err(errs) => issues.extend(errs.into_iter().map(|e| Issue::new(instance_field(xi, &e.field), e.message))),
        }
    }

    // Instances in the library, not in the file, of a class the file changes.
    let old_classes: HashMap<&str, &Class> = current.classes.iter().map(|c| (c.id.as_str(), c)).collect();
    let mut migrated = Vec::new();
    for inst in &current.instances {
        if in_file.contains(&inst.id) {
            continue;
        }
        let (Some(old), Some(new)) = (old_classes.get(inst.class_id.as_str()), file_classes.get(&inst.class_id)) else {
            continue;
        };
        match migrate_instance(old, new, inst) {
            Ok(m) => {
                if &m != inst {
                    plan.counts.instances_migrated += 1;
                    migrated.push(m.id.clone());
                    instances.insert(m.id.clone(), m);
                }
            }
            Err(errs) => issues.extend(
                errs.into_iter()
                    .map(|e| Issue::new(format!("library {}", e.field), format!("{} (the instance is not in the file)", e.message))),
            ),
        }
    }

    // Unique instance names within each class.
    let mut names: HashMap<(&str, &str), &str> = HashMap::new();
    for i in instances.values() {
        if let Some(other) = names.insert((i.class_id.as_str(), i.name.as_str()), i.id.as_str()) {
            let class = classes.get(&i.class_id).map_or(i.class_id.as_str(), |c| c.name.as_str());
            issues.push(Issue::new(
                format!("instance {:?}", i.name),
                format!("two instances of class \"{class}\" would be named \"{}\" (ids {other} and {})", i.name, i.id),
            ));
        }
    }

    if !issues.is_empty() {
        return Err(issues);
    }
    plan.classes = file_classes.into_values().collect();
    plan.instances = instances.into_values().filter(|i| in_file.contains(&i.id) || migrated.contains(&i.id)).collect();
    Ok(plan)
}
