//! Modelica identifiers for bodies, joints and everything derived from them.
//!
//! Rules: `[A-Za-z_][A-Za-z0-9_]*`, never a keyword, unique in the model's scope, and unique
//! case-insensitively too (shape files named after bodies must not collide on Windows).
//! Names come from CAD names; duplicates get a suffix derived from the `node_id` (never from file
//! order), so a re-export gives every unchanged body and joint the same name.

use std::collections::{BTreeMap, HashSet};

use crate::pipeline::ir::Model;

/// Modelica 3.x keywords.
pub const KEYWORDS: &[&str] = &[
    "algorithm",
    "and",
    "annotation",
    "block",
    "break",
    "class",
    "connect",
    "connector",
    "constant",
    "constrainedby",
    "der",
    "discrete",
    "each",
    "else",
    "elseif",
    "elsewhen",
    "encapsulated",
    "end",
    "enumeration",
    "equation",
    "expandable",
    "extends",
    "external",
    "false",
    "final",
    "flow",
    "for",
    "function",
    "if",
    "import",
    "impure",
    "in",
    "initial",
    "inner",
    "input",
    "loop",
    "model",
    "not",
    "operator",
    "or",
    "outer",
    "output",
    "package",
    "parameter",
    "partial",
    "protected",
    "public",
    "pure",
    "record",
    "redeclare",
    "replaceable",
    "return",
    "stream",
    "then",
    "true",
    "type",
    "when",
    "while",
    "within",
];

/// Names the model itself uses.
const RESERVED: &[&str] = &["world", "Components", "Modelica", "Mechanics", "Mechatronics", "time"];

/// Turns any text into an identifier: runs of other characters become `_`, a leading digit gets
/// `prefix`, keywords get a trailing `_`. Empty input gives `prefix`.
pub fn sanitize(text: &str, prefix: &str) -> String {
    let mut s = String::with_capacity(text.len());
    let mut gap = false;
    for c in text.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            if gap && !s.is_empty() {
                s.push('_');
            }
            gap = false;
            s.push(c);
        } else {
            gap = true;
        }
    }
    if s.is_empty() {
        return prefix.to_string();
    }
    if s.as_bytes()[0].is_ascii_digit() {
        s = format!("{prefix}{s}");
    }
    if KEYWORDS.contains(&s.as_str()) {
        s.push('_');
    }
    s
}

/// A set of identifiers taken in one scope, compared case-insensitively.
#[derive(Default, Clone, Debug)]
pub struct Scope {
    taken: HashSet<String>,
}

impl Scope {
    pub fn new() -> Self {
        let mut s = Scope::default();
        for r in RESERVED {
            s.taken.insert(r.to_lowercase());
        }
        s
    }

    pub fn is_taken(&self, name: &str) -> bool {
        self.taken.contains(&name.to_lowercase())
    }

    /// Takes `name`, or `name_2`, `name_3`, ... — the first that is free. Deterministic for a
    /// deterministic call order.
    pub fn take(&mut self, name: &str) -> String {
        let mut candidate = name.to_string();
        let mut k = 2;
        while self.is_taken(&candidate) {
            candidate = format!("{name}_{k}");
            k += 1;
        }
        self.taken.insert(candidate.to_lowercase());
        candidate
    }
}

/// Names of bodies and joints, indexed like `Model::bodies` / `Model::joints`.
#[derive(Clone, Debug)]
pub struct Names {
    pub bodies: Vec<String>,
    pub joints: Vec<String>,
    pub scope: Scope,
}

/// The part of `node_id` that tells two same-named entities apart: the node ID without the CAD
/// name in it (`ARM/RootPart` for `RootPart` gives `ARM`).
fn distinguishing(node_id: &str, cad_name: &str) -> String {
    let stripped = node_id.replacen(cad_name, "", 1);
    let s = sanitize(&stripped, "n");
    if s == "n" {
        sanitize(node_id, "n")
    } else {
        s
    }
}

/// FNV-1a, for a last-resort suffix that depends only on the node ID.
fn short_hash(s: &str) -> String {
    let mut h: u32 = 0x811c_9dc5;
    for b in s.bytes() {
        h ^= u32::from(b);
        h = h.wrapping_mul(0x0100_0193);
    }
    format!("{:06x}", h & 0xff_ffff)
}

/// Assigns names to bodies and joints (see [`assign_with_hints`]). Identity is (kind, node_id); entities are processed sorted
/// by it, so the result does not depend on file order.
///
/// A CAD name used once gives the plain name. Same-named entities (every subsystem has its own
/// `RootPart`) get a suffix: the name of the innermost enclosing subsystem when that tells them
/// apart, otherwise the distinguishing part of their node ID.
/// Names an earlier version of the model used, by node ID: a body or joint whose CAD name
/// changed keeps its Modelica name, so drive assignments and user code that refer to it survive.
#[derive(Clone, Debug, Default)]
pub struct Hints {
    pub bodies: BTreeMap<String, String>,
    pub joints: BTreeMap<String, String>,
    /// Diagram groups' (column, row) by node ID (see `diagram::plan`).
    pub diagram: BTreeMap<String, (i32, i32)>,
}

/// As [`assign`], but an entity whose node ID has a hint gets that name first (when it is a valid
/// identifier and still free).
pub fn assign_with_hints(model: &Model, hints: &Hints) -> Names {
    struct Entity<'a> {
        is_joint: bool,
        index: usize,
        node_id: &'a str,
        cad_name: &'a str,
        subsystem: Option<&'a String>,
        base: String,
    }
    let mut entities: Vec<Entity> = Vec::new();
    for (i, b) in model.bodies.iter().enumerate() {
        entities.push(Entity {
            is_joint: false,
            index: i,
            node_id: &b.node_id,
            cad_name: &b.cad_name,
            subsystem: b.subsystem_path.last(),
            base: sanitize(&b.cad_name, "b"),
        });
    }
    for (i, j) in model.joints.iter().enumerate() {
        entities.push(Entity {
            is_joint: true,
            index: i,
            node_id: &j.node_id,
            cad_name: &j.cad_name,
            subsystem: j.subsystem_path.last(),
            base: sanitize(&j.cad_name, "j"),
        });
    }
    entities.sort_by(|a, b| (a.is_joint, a.node_id).cmp(&(b.is_joint, b.node_id)));
    let mut groups: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    for (k, e) in entities.iter().enumerate() {
        groups.entry(e.base.to_lowercase()).or_default().push(k);
    }
    // Preferred name of each entity.
    let mut wanted: Vec<String> = vec![String::new(); entities.len()];
    for members in groups.values() {
        if let [only] = members.as_slice() {
            wanted[*only] = entities[*only].base.clone();
            continue;
        }
        let by_subsystem: Vec<Option<String>> =
            members.iter().map(|k| entities[*k].subsystem.map(|s| format!("{}_{}", entities[*k].base, sanitize(s, "s")))).collect();
        for (m, k) in members.iter().enumerate() {
            let e = &entities[*k];
            let unique = by_subsystem[m].as_ref().filter(|name| {
                by_subsystem.iter().filter(|o| o.as_deref().map(str::to_lowercase) == Some(name.to_lowercase())).count() == 1
            });
            wanted[*k] = match unique {
                Some(name) => name.clone(),
                None => format!("{}_{}", e.base, distinguishing(e.node_id, e.cad_name)),
            };
        }
    }
    let mut scope = Scope::new();
    let mut bodies = vec![String::new(); model.bodies.len()];
    let mut joints = vec![String::new(); model.joints.len()];
    // Hinted names first, then plain names, so that a suffixed duplicate can never take one.
    let hint_of = |e: &Entity| {
        let map = if e.is_joint { &hints.joints } else { &hints.bodies };
        map.get(e.node_id).filter(|h| sanitize(h, "x") == **h).cloned()
    };
    let mut order: Vec<usize> = (0..entities.len()).collect();
    order.sort_by_key(|k| (hint_of(&entities[*k]).is_none(), groups[&entities[*k].base.to_lowercase()].len() > 1));
    for k in order {
        if let Some(h) = hint_of(&entities[k]) {
            if !scope.is_taken(&h) {
                wanted[k] = h;
            }
        }
        let e = &entities[k];
        let mut name = wanted[k].clone();
        if scope.is_taken(&name) {
            name = format!("{}_{}", e.base, short_hash(e.node_id));
        }
        let name = scope.take(&name);
        if e.is_joint {
            joints[e.index] = name;
        } else {
            bodies[e.index] = name;
        }
    }
    Names { bodies, joints, scope }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sanitizing() {
        assert_eq!(sanitize("ICUB3_HIP_FLEX-EXT_LEFT", "b"), "ICUB3_HIP_FLEX_EXT_LEFT");
        assert_eq!(sanitize("RootPart--SIM_I_WRIST", "j"), "RootPart_SIM_I_WRIST");
        assert_eq!(sanitize("3DPART", "b"), "b3DPART");
        assert_eq!(sanitize("model", "b"), "model_");
        assert_eq!(sanitize("--", "j"), "j");
        assert_eq!(sanitize("Bügel 2", "b"), "B_gel_2");
    }

    #[test]
    fn scope_is_case_insensitive() {
        let mut s = Scope::new();
        assert_eq!(s.take("Arm"), "Arm");
        assert_eq!(s.take("ARM"), "ARM_2");
        assert_eq!(s.take("World"), "World_2");
    }

    #[test]
    fn distinguishing_parts() {
        assert_eq!(distinguishing("ARM/RootPart", "RootPart"), "ARM");
        assert_eq!(distinguishing("59", "LINK"), "n59");
        assert_eq!(distinguishing("63:-:66", "A--B"), "n63_66");
    }
}
