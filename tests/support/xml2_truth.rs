//! Ground truth read straight from a second-generation Simscape Multibody XML, independently
//! of `front::simscape2`: a plain tag scanner (no XML library, no code shared with the front
//! end) that composes the instance transforms down the tree (parent * child, rotations
//! row-major, each orthonormalised like any reader must) and places every part instance's CS1
//! frame, centre of mass and world inertia (`Ixx Iyy Izz Iyz Izx Ixy`, tensor entries about the
//! centre of mass in part axes). Node IDs are the instance uids from the root joined by `|`.

use std::collections::BTreeMap;

use nalgebra::{Matrix3, Vector3};

use crate::check::nearest_rotation;
use crate::truth::TruthFrame;

/// Whether `xml` is a second-generation file (its root element).
pub fn is_second_generation(xml: &str) -> bool {
    xml.contains("<SimscapeMultibodyImportXML") || xml.contains("<SimMechanicsImportXML")
}

/// What the scanner finds: per part instance (node ID = uids joined by `|`), the CS1 pose, the
/// CG and the mass with the world inertia.
#[derive(Default)]
pub struct Truth {
    pub frames: BTreeMap<String, TruthFrame>,
    pub cgs: BTreeMap<String, Vector3<f64>>,
    pub mass: BTreeMap<String, (f64, Matrix3<f64>)>,
    /// Joint elements under `<Joints>` by tag, whole file (root and sub-assembly definitions).
    pub joint_tags: BTreeMap<String, usize>,
    pub part_instances: usize,
}

fn decode(s: &str) -> String {
    s.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&apos;", "'").replace("&amp;", "&")
}

fn attr(tag: &str, key: &str) -> Option<String> {
    let pat = format!(" {key}=\"");
    let start = tag.find(&pat)? + pat.len();
    let end = tag[start..].find('"')? + start;
    Some(decode(&tag[start..end]))
}

fn nums(s: &str) -> Vec<f64> {
    s.split_whitespace().map(|x| x.parse::<f64>().expect("number")).collect()
}

fn length_unit(u: &str) -> f64 {
    match u {
        "meter" | "m" => 1.0,
        "millimeter" | "mm" => 1e-3,
        "inch" => 0.0254,
        other => panic!("scanner: length unit {other}"),
    }
}

fn mass_unit(u: &str) -> f64 {
    match u {
        "kilogram" | "kg" => 1.0,
        "pound" | "lbm" => 0.45359237,
        other => panic!("scanner: mass unit {other}"),
    }
}

/// Scans tags and text in order: `(tag text without <>, text after it up to the next <)`.
fn tokens(xml: &str) -> Vec<(&str, &str)> {
    let mut out = Vec::new();
    let mut rest = xml;
    while let Some(i) = rest.find('<') {
        let Some(j) = rest[i..].find('>') else { break };
        let tag = &rest[i + 1..i + j];
        rest = &rest[i + j + 1..];
        let text = &rest[..rest.find('<').unwrap_or(rest.len())];
        out.push((tag, text.trim()));
    }
    out
}

pub fn scan(xml: &str) -> Truth {
    let toks = tokens(xml);
    let units_tag = toks
        .iter()
        .find(|(t, _)| t.starts_with("DataUnits"))
        .or_else(|| toks.iter().find(|(t, _)| t.starts_with("ModelUnits")))
        .expect("units");
    let (lu, mu) = (length_unit(&attr(units_tag.0, "length").expect("length")), mass_unit(&attr(units_tag.0, "mass").expect("mass")));
    // Parts.
    let mut parts: BTreeMap<String, (f64, Vector3<f64>, Matrix3<f64>)> = BTreeMap::new();
    let mut current: Option<String> = None;
    let (mut m, mut c, mut i6) = (0.0, Vector3::zeros(), vec![0.0; 6]);
    let mut truth = Truth::default();
    let mut in_joints = 0usize;
    for (tag, text) in &toks {
        if tag.starts_with("Part ") {
            current = attr(tag, "uid");
        } else if *tag == "Mass" && current.is_some() {
            m = nums(text)[0] * mu;
        } else if *tag == "CenterOfMass" && current.is_some() {
            let v = nums(text);
            c = Vector3::new(v[0], v[1], v[2]) * lu;
        } else if *tag == "Inertia" && current.is_some() {
            i6 = nums(text).iter().map(|x| x * mu * lu * lu).collect();
        } else if *tag == "/Part" {
            let i = Matrix3::new(i6[0], i6[5], i6[4], i6[5], i6[1], i6[3], i6[4], i6[3], i6[2]);
            parts.insert(current.take().expect("part uid"), (m, c, i));
        } else if *tag == "Joints" {
            in_joints += 1;
        } else if *tag == "/Joints" {
            in_joints -= 1;
        } else if in_joints > 0 && !tag.starts_with('/') && tag.contains("name=") {
            let kind = tag.split_whitespace().next().expect("tag").to_string();
            *truth.joint_tags.entry(kind).or_default() += 1;
        }
    }
    // The instance tree: transforms composed parent * child, rotations row-major.
    let start = toks.iter().position(|(t, _)| *t == "InstanceTree").expect("InstanceTree");
    let mut stack: Vec<(String, String, Matrix3<f64>, Vector3<f64>)> = Vec::new(); // (path, entity, R, p)
    let (mut rot, mut tr) = (None, None);
    for (tag, text) in &toks[start + 1..] {
        if *tag == "/InstanceTree" {
            break;
        }
        if tag.starts_with("Instance ") {
            let uid = attr(tag, "uid").expect("uid");
            let entity = attr(tag, "entityUid").unwrap_or_default();
            let path = match stack.last() {
                Some((p, ..)) => format!("{p}|{uid}"),
                None => uid,
            };
            stack.push((path, entity, Matrix3::identity(), Vector3::zeros()));
        } else if *tag == "Rotation" {
            rot = Some(nearest_rotation(&Matrix3::from_row_slice(&nums(text))));
        } else if *tag == "Translation" {
            let v = nums(text);
            tr = Some(Vector3::new(v[0], v[1], v[2]) * lu);
        } else if *tag == "/Transform" {
            let (r, p) = (rot.take().expect("rotation"), tr.take().expect("translation"));
            let n = stack.len();
            let (pr, pp) = if n >= 2 { (stack[n - 2].2, stack[n - 2].3) } else { (Matrix3::identity(), Vector3::zeros()) };
            let top = stack.last_mut().expect("instance");
            top.2 = pr * r;
            top.3 = pp + pr * p;
            if let Some((mass, com, inertia)) = parts.get(&top.1) {
                truth.part_instances += 1;
                truth.frames.insert(format!("{}::CS1", top.0), TruthFrame { position: top.3, rotation: top.2 });
                truth.cgs.insert(top.0.clone(), top.3 + top.2 * com);
                truth.mass.insert(top.0.clone(), (*mass, top.2 * inertia * top.2.transpose()));
            }
        } else if *tag == "/Instance" {
            stack.pop();
        }
    }
    truth
}
