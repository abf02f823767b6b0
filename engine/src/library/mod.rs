//! The motor library (the paper's object library): its types and rules. No SQL, no HTTP.
//!
//! - A [`Class`] stands for one Modelica class (`cad2mo.Drives.Motors.DCPermanentMagnet` is our
//!   own class, generated into each package's `Components/`; `Modelica.` paths are MSL models)
//!   and declares typed [`Parameter`]s: the Modelica parameters it sets, each with an SI unit,
//!   inclusive limits, an editable flag and an optional default.
//! - A *datasheet* parameter ([`Parameter::datasheet`]) is not a Modelica parameter of the class:
//!   a catalog value that only the drive sizing reads (a motor's nominal torque, a gear's rated
//!   output torque). It is stored, checked, shown and exchanged like the others, but never
//!   becomes a Modelica modifier, and an instance may lack it (the sizing then names it as
//!   missing).
//! - An [`Instance`] is a class with a value for every Modelica parameter (and for the datasheet
//!   parameters it knows), e.g. one motor from its datasheet; `source` says where the values
//!   come from.
//! - Values arrive as JSON ([`check_value`]): a number, boolean or string in the parameter's unit,
//!   or `{"value": 82, "unit": "uH"}`, converted to the parameter's SI unit by the table in
//!   [`units`]. Every check returns *all* the problems it finds as [`Issue`]s.
//! - Nameplate values (non-editable parameters) are fixed once an instance exists
//!   ([`check_instance_update`]); per-drive overrides may only touch editable parameters
//!   ([`validate_overrides`], [`resolved_values`]).
//! - [`xml`] reads and writes the library's XML exchange format (`docs/library-xml.md`);
//!   [`plan_import`] validates a whole file against the current library before anything is
//!   written. [`seed`] is the library a new installation starts with.

pub mod seed;
pub mod units;
mod validate;
pub mod xml;

#[cfg(test)]
mod tests;

use serde::Serialize;

pub use validate::{
    check_class, check_instance, check_instance_update, check_value, check_values, migrate_instance, plan_import, resolved_values,
    validate_overrides, ClassDraft, ImportCounts, ImportPlan, InstanceDraft, ParameterDraft,
};

/// The Modelica type of a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParamType {
    Real,
    Integer,
    Boolean,
    String,
}

impl ParamType {
    pub const ALL: [ParamType; 4] = [ParamType::Real, ParamType::Integer, ParamType::Boolean, ParamType::String];

    pub fn as_str(self) -> &'static str {
        match self {
            ParamType::Real => "Real",
            ParamType::Integer => "Integer",
            ParamType::Boolean => "Boolean",
            ParamType::String => "String",
        }
    }

    pub fn parse(s: &str) -> Option<ParamType> {
        ParamType::ALL.into_iter().find(|t| t.as_str() == s)
    }

    /// Real and Integer parameters carry units and limits.
    pub fn is_numeric(self) -> bool {
        matches!(self, ParamType::Real | ParamType::Integer)
    }
}

/// A checked parameter value, in the parameter's unit.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Real(f64),
    Integer(i64),
    Boolean(bool),
    String(String),
}

impl Value {
    pub fn param_type(&self) -> ParamType {
        match self {
            Value::Real(_) => ParamType::Real,
            Value::Integer(_) => ParamType::Integer,
            Value::Boolean(_) => ParamType::Boolean,
            Value::String(_) => ParamType::String,
        }
    }

    /// The number, for Real and Integer values.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Real(x) => Some(*x),
            Value::Integer(i) => Some(*i as f64),
            _ => None,
        }
    }

    /// The JSON form: a number, boolean or string. Checked Reals are finite, so this is lossless.
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            Value::Real(x) => serde_json::Number::from_f64(*x).map_or(serde_json::Value::Null, serde_json::Value::Number),
            Value::Integer(i) => serde_json::Value::from(*i),
            Value::Boolean(b) => serde_json::Value::Bool(*b),
            Value::String(s) => serde_json::Value::String(s.clone()),
        }
    }

    /// The text form used in XML: Reals in Rust's shortest round-trip notation (`8.2e-5`,
    /// `0.317`, `100`), so parsing the text gives back the same `f64` bit for bit.
    pub fn to_text(&self) -> String {
        match self {
            Value::Real(x) => {
                let s = format!("{x:?}");
                match s.strip_suffix(".0") {
                    Some(whole) => whole.to_string(),
                    None => s,
                }
            }
            Value::Integer(i) => i.to_string(),
            Value::Boolean(b) => b.to_string(),
            Value::String(s) => s.clone(),
        }
    }

    /// Human form for messages: `8.2e-5 H`, `true`, `"text"`.
    pub fn describe(&self, unit: &str) -> String {
        match self {
            Value::String(s) => format!("{s:?}"),
            Value::Boolean(b) => b.to_string(),
            _ if unit.is_empty() || unit == "1" => self.to_text(),
            _ => format!("{} {unit}", self.to_text()),
        }
    }

    /// Equal as stored values; Reals compare with a relative tolerance of 1e-12, so a nameplate
    /// value sent back in another unit (82 uH for 8.2e-5 H) counts as unchanged.
    pub fn same(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Real(a), Value::Real(b)) => a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
            _ => self == other,
        }
    }
}

impl Serialize for Value {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_json().serialize(s)
    }
}

/// A parameter of a class: the Modelica parameter it sets, or a datasheet value.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    /// The Modelica parameter name; unique in its class.
    pub name: String,
    pub ty: ParamType,
    /// SI unit (see [`units::is_si`]); `""` for none (always for Boolean and String).
    pub unit: String,
    /// Inclusive limits, in `unit`.
    pub min: Option<f64>,
    pub max: Option<f64>,
    /// Editable parameters may change on an existing instance and be overridden per drive;
    /// the others are nameplate values.
    pub editable: bool,
    /// A datasheet value, not a Modelica parameter: optional per instance, never written into
    /// the generated model (read by [`crate::sizing`]).
    pub datasheet: bool,
    pub default: Option<Value>,
    pub comment: String,
}

/// A library class.
#[derive(Clone, Debug, PartialEq)]
pub struct Class {
    pub id: String,
    /// Unique in the library.
    pub name: String,
    /// `motor`, `gear`, `controller`, ...
    pub domain: String,
    /// The Modelica class path; `cad2mo.` means our own classes under `<Pkg>.Components`.
    pub modelica_class: String,
    pub description: String,
    /// In display order.
    pub parameters: Vec<Parameter>,
}

impl Class {
    pub fn parameter(&self, name: &str) -> Option<&Parameter> {
        self.parameters.iter().find(|p| p.name == name)
    }
}

/// A library instance: a class with a value for every Modelica parameter and for the datasheet
/// parameters it knows.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    pub id: String,
    pub class_id: String,
    /// Unique within the class.
    pub name: String,
    /// Where the values come from (datasheet, catalog page, measurement).
    pub source: String,
    /// In the class's parameter order, each in its parameter's unit; datasheet parameters may be
    /// absent.
    pub values: Vec<(String, Value)>,
}

impl Instance {
    pub fn value(&self, name: &str) -> Option<&Value> {
        self.values.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }
}

/// The whole library: what is exported, imported and seeded.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Library {
    pub classes: Vec<Class>,
    pub instances: Vec<Instance>,
}

impl Library {
    pub fn class(&self, id: &str) -> Option<&Class> {
        self.classes.iter().find(|c| c.id == id)
    }

    /// Classes by name, instances by class name then name (ids break ties): the export order.
    pub fn sort(&mut self) {
        self.classes.sort_by(|a, b| (&a.name, &a.id).cmp(&(&b.name, &b.id)));
        let rank: std::collections::HashMap<&str, usize> = self.classes.iter().enumerate().map(|(i, c)| (c.id.as_str(), i)).collect();
        self.instances.sort_by(|a, b| {
            let ra = rank.get(a.class_id.as_str()).copied().unwrap_or(usize::MAX);
            let rb = rank.get(b.class_id.as_str()).copied().unwrap_or(usize::MAX);
            (ra, &a.name, &a.id).cmp(&(rb, &b.name, &b.id))
        });
    }
}

/// One problem with the input: which field (`values.L`, `parameters[2].unit`,
/// `line 12 <value param="L">`) and what is wrong. Checks return all of them at once.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Issue {
    pub field: String,
    pub message: String,
}

impl Issue {
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Issue {
        Issue { field: field.into(), message: message.into() }
    }
}

/// A new id (UUID v4, lower-case, hyphenated).
pub fn new_id() -> String {
    uuid::Uuid::new_v4().to_string()
}

/// The canonical form of an id, if it is a UUID.
pub fn parse_id(s: &str) -> Option<String> {
    uuid::Uuid::parse_str(s.trim()).ok().map(|u| u.hyphenated().to_string())
}
