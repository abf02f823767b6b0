//! The difference between two conversions of a model: two `report.json` documents in, the bodies
//! and joints added, removed and changed out. Pure (no IO), on the report's JSON so it works on
//! stored reports of any converter version.
//!
//! Matching: bodies by `node_id` (the CAD's stable ID); joints by `node_id`, then the remaining
//! ones by `modelica_name` (a joint whose node ID changed but kept its name is "changed", with
//! `node_id` among its changes). Compared fields: bodies' `cad_name`, `modelica_name`, `mass`,
//! `cg_world`, `inertia_cg`; joints' `node_id`, `cad_name`, `modelica_name`, `primitives`,
//! `axis_world`, `base_body`, `follower_body`. Numbers are equal within 1e-9 (relative to their
//! size, absolute below 1). Every change carries the old and the new value.

use std::collections::{HashMap, HashSet};

use serde::Serialize;
use serde_json::Value;

/// Body fields compared.
const BODY_FIELDS: &[&str] = &["cad_name", "modelica_name", "mass", "cg_world", "inertia_cg"];
/// Joint fields compared.
const JOINT_FIELDS: &[&str] = &["node_id", "cad_name", "modelica_name", "primitives", "axis_world", "base_body", "follower_body"];
/// Tolerance on numbers.
const EPS: f64 = 1e-9;

/// The difference between two reports.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Diff {
    pub bodies: Changes,
    pub joints: Changes,
}

/// Added, removed and changed items of one kind.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Changes {
    pub added: Vec<Item>,
    pub removed: Vec<Item>,
    pub changed: Vec<Changed>,
}

/// A body or joint, by its identifiers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Item {
    pub node_id: String,
    pub modelica_name: String,
    pub cad_name: String,
}

/// An item present in both reports whose compared fields differ (identifiers: the new ones).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Changed {
    pub node_id: String,
    pub modelica_name: String,
    pub cad_name: String,
    pub changes: Vec<FieldChange>,
}

/// One field's old and new value.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FieldChange {
    pub field: String,
    pub old: Value,
    pub new: Value,
}

impl Diff {
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty() && self.joints.is_empty()
    }
}

impl Changes {
    pub fn is_empty(&self) -> bool {
        self.added.is_empty() && self.removed.is_empty() && self.changed.is_empty()
    }
}

/// Diffs report `old` against report `new`.
pub fn diff(old: &Value, new: &Value) -> Diff {
    Diff {
        bodies: diff_items(items(old, "bodies"), items(new, "bodies"), BODY_FIELDS, false),
        joints: diff_items(items(old, "joints"), items(new, "joints"), JOINT_FIELDS, true),
    }
}

fn items<'a>(report: &'a Value, key: &str) -> &'a [Value] {
    report.get(key).and_then(Value::as_array).map_or(&[], Vec::as_slice)
}

fn text(v: &Value, key: &str) -> String {
    v.get(key).and_then(Value::as_str).unwrap_or_default().to_string()
}

fn item(v: &Value) -> Item {
    Item { node_id: text(v, "node_id"), modelica_name: text(v, "modelica_name"), cad_name: text(v, "cad_name") }
}

fn diff_items(old: &[Value], new: &[Value], fields: &[&str], by_name_too: bool) -> Changes {
    // new index -> old index
    let mut pairs: Vec<Option<usize>> = vec![None; new.len()];
    let mut used: HashSet<usize> = HashSet::new();
    let mut by_id: HashMap<String, usize> = HashMap::new();
    for (i, o) in old.iter().enumerate() {
        by_id.entry(text(o, "node_id")).or_insert(i);
    }
    for (k, n) in new.iter().enumerate() {
        if let Some(&i) = by_id.get(&text(n, "node_id")) {
            if used.insert(i) {
                pairs[k] = Some(i);
            }
        }
    }
    if by_name_too {
        let mut by_name: HashMap<String, usize> = HashMap::new();
        for (i, o) in old.iter().enumerate() {
            if !used.contains(&i) {
                by_name.entry(text(o, "modelica_name")).or_insert(i);
            }
        }
        for (k, n) in new.iter().enumerate() {
            if pairs[k].is_some() {
                continue;
            }
            if let Some(&i) = by_name.get(&text(n, "modelica_name")) {
                if used.insert(i) {
                    pairs[k] = Some(i);
                }
            }
        }
    }
    let mut changes = Changes::default();
    for (k, n) in new.iter().enumerate() {
        match pairs[k] {
            None => changes.added.push(item(n)),
            Some(i) => {
                let o = &old[i];
                let field_changes: Vec<FieldChange> = fields
                    .iter()
                    .filter_map(|f| {
                        let (a, b) = (o.get(*f).unwrap_or(&Value::Null), n.get(*f).unwrap_or(&Value::Null));
                        (!same(a, b)).then(|| FieldChange { field: (*f).to_string(), old: a.clone(), new: b.clone() })
                    })
                    .collect();
                if !field_changes.is_empty() {
                    let it = item(n);
                    changes.changed.push(Changed {
                        node_id: it.node_id,
                        modelica_name: it.modelica_name,
                        cad_name: it.cad_name,
                        changes: field_changes,
                    });
                }
            }
        }
    }
    changes.removed = old.iter().enumerate().filter(|(i, _)| !used.contains(i)).map(|(_, o)| item(o)).collect();
    changes
}

/// JSON equality with a tolerance on numbers.
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => (x - y).abs() <= EPS * x.abs().max(y.abs()).max(1.0),
            _ => x == y,
        },
        (Value::Array(x), Value::Array(y)) => x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same(p, q)),
        (Value::Object(x), Value::Object(y)) => x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w))),
        _ => a == b,
    }
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    fn body(id: &str, name: &str, mass: f64) -> Value {
        json!({"node_id": id, "modelica_name": name.to_lowercase(), "cad_name": name, "mass": mass,
               "cg_world": [0.0, 0.1, 0.0], "inertia_cg": [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]})
    }

    fn joint(id: &str, name: &str, axis: [f64; 3]) -> Value {
        json!({"node_id": id, "modelica_name": name, "cad_name": name, "primitives": ["revolute"],
               "axis_world": axis, "base_body": "a", "follower_body": "b"})
    }

    #[test]
    fn identical_reports_have_no_diff() {
        let r = json!({"bodies": [body("1", "A", 1.0)], "joints": [joint("j", "rev", [0.0, 0.0, 1.0])]});
        assert!(diff(&r, &r).is_empty());
        assert!(diff(&json!({}), &json!({})).is_empty());
    }

    #[test]
    fn added_removed_changed() {
        let old = json!({
            "bodies": [body("1", "A", 1.0), body("2", "B", 2.0)],
            "joints": [joint("j1", "rev1", [0.0, 0.0, 1.0]), joint("j2", "rev2", [1.0, 0.0, 0.0]),
                       joint("j3", "rev3", [1.0, 0.0, 0.0])]
        });
        let new = json!({
            "bodies": [body("1", "A", 1.0 + 1e-12), body("2", "C", 2.5), body("3", "D", 1.0)],
            "joints": [joint("j1", "rev1", [0.0, 1.0, 0.0]), joint("j9", "rev3", [1.0, 0.0, 0.0])]
        });
        let d = diff(&old, &new);
        assert_eq!(d.bodies.added, vec![Item { node_id: "3".into(), modelica_name: "d".into(), cad_name: "D".into() }]);
        assert!(d.bodies.removed.is_empty());
        assert_eq!(d.bodies.changed.len(), 1);
        let c = &d.bodies.changed[0];
        assert_eq!(c.node_id, "2");
        let fields: Vec<&str> = c.changes.iter().map(|f| f.field.as_str()).collect();
        assert_eq!(fields, ["cad_name", "modelica_name", "mass"]);
        assert_eq!((c.changes[2].old.clone(), c.changes[2].new.clone()), (json!(2.0), json!(2.5)));

        assert_eq!(d.joints.removed.iter().map(|i| i.node_id.as_str()).collect::<Vec<_>>(), ["j2"]);
        assert!(d.joints.added.is_empty());
        assert_eq!(d.joints.changed.len(), 2);
        assert_eq!(d.joints.changed[0].changes[0].field, "axis_world");
        // Matched by Modelica name: the node ID is the change.
        assert_eq!(d.joints.changed[1].changes[0], FieldChange { field: "node_id".into(), old: json!("j3"), new: json!("j9") });
    }
}
