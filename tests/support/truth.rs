//! Ground truth read straight from an XML export, independently of the converter: every frame's
//! world pose by node ID, in metres. A deliberately simple scanner (the format has one value per
//! element, no attributes other than `ref`), so it shares no code with the front end.
//!
//! Frames given relative to other frames are resolved here too, by the SimMechanics Body block's
//! rule: the position starts at the `positionOrigin` frame's origin with components in the
//! `positionReferenceFrame`'s axes, the orientation is relative to `orientationReferenceFrame`;
//! each is `WORLD`, a frame of the same body or ground by name, or `ADJOINING` (the frame at the
//! other end of the joint naming this frame's `ref`).

use std::collections::BTreeMap;

use nalgebra::{Matrix3, Vector3};

#[derive(Clone, Debug)]
pub struct TruthFrame {
    pub position: Vector3<f64>,
    /// Columns: the frame's axes in world coordinates.
    pub rotation: Matrix3<f64>,
}

fn element<'a>(block: &'a str, tag: &str) -> Option<&'a str> {
    let open = format!("<{tag}>");
    let start = block.find(&open)? + open.len();
    let end = block[start..].find(&format!("</{tag}>"))? + start;
    Some(block[start..end].trim().trim_matches('"'))
}

fn numbers(s: &str) -> Vec<f64> {
    s.split(',').filter_map(|x| x.trim().parse::<f64>().ok()).collect()
}

fn metres_per(unit: &str) -> f64 {
    match unit {
        "mm" => 1e-3,
        "cm" => 1e-2,
        "m" => 1.0,
        "in" => 0.0254,
        "ft" => 0.3048,
        other => panic!("truth scanner: unknown length unit {other:?}"),
    }
}

/// The `ref="N"` attribute of the start tag at the beginning of `tag_and_rest`.
fn ref_attr(tag_and_rest: &str) -> Option<&str> {
    let head = &tag_and_rest[..tag_and_rest.find('>')?];
    let at = head.find("ref=\"")? + 5;
    Some(head[at..].split('"').next()?.trim())
}

/// Byte ranges of every `<tag>...</tag>` (not nested).
fn spans(xml: &str, tag: &str) -> Vec<(usize, usize)> {
    let (open, close) = (format!("<{tag}>"), format!("</{tag}>"));
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(i) = xml[at..].find(&open) {
        let start = at + i;
        let Some(len) = xml[start..].find(&close) else { break };
        out.push((start, start + len));
        at = start + len;
    }
    out
}

/// One `<Frame>` with a position, as written.
struct Raw {
    node: String,
    name: String,
    /// Index of the enclosing `<Body>` or `<Ground>` span, if any.
    owner: Option<usize>,
    owner_node: String,
    ref_id: Option<String>,
    position: Vector3<f64>,
    rotation: Matrix3<f64>,
    /// positionOrigin, positionReferenceFrame, orientationReferenceFrame.
    refs: [String; 3],
}

fn scan(xml: &str) -> Vec<Raw> {
    let owners: Vec<(usize, usize)> = {
        let mut o = spans(xml, "Body");
        o.extend(spans(xml, "Ground"));
        o
    };
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(i) = xml[at..].find("<Frame") {
        let start = at + i;
        let Some(len) = xml[start..].find("</Frame>") else { break };
        let block = &xml[start..start + len];
        at = start + len;
        let (Some(node), Some(pos), Some(orient)) = (element(block, "nodeID"), element(block, "position"), element(block, "orientation"))
        else {
            continue;
        };
        let scale = metres_per(element(block, "positionUnits").unwrap_or("m"));
        let (p, o) = (numbers(pos), numbers(orient));
        if p.len() != 3 || o.len() != 9 {
            continue;
        }
        let owner = owners.iter().position(|&(a, b)| a < start && start < b);
        let owner_node = owner.and_then(|k| element(&xml[owners[k].0..owners[k].1], "nodeID")).unwrap_or("");
        let reference = |tag| element(block, tag).unwrap_or("WORLD").to_string();
        out.push(Raw {
            node: node.to_string(),
            name: element(block, "name").unwrap_or("").to_string(),
            owner,
            owner_node: owner_node.to_string(),
            ref_id: ref_attr(block).map(str::to_string),
            position: Vector3::new(p[0], p[1], p[2]) * scale,
            rotation: Matrix3::from_column_slice(&o),
            refs: [reference("positionOrigin"), reference("positionReferenceFrame"), reference("orientationReferenceFrame")],
        });
    }
    out
}

/// For each frame `ref`, the other side's `ref` of every joint naming it.
fn joint_partners(xml: &str) -> BTreeMap<String, Vec<String>> {
    let mut out: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (a, b) in spans(xml, "SimpleJoint") {
        let joint = &xml[a..b];
        let side = |tag: &str| {
            let (s, e) = spans(joint, tag).first().copied()?;
            let block = &joint[s..e];
            ref_attr(&block[block.find("<Frame")?..]).map(str::to_string)
        };
        if let (Some(base), Some(follower)) = (side("base"), side("follower")) {
            out.entry(base.clone()).or_default().push(follower.clone());
            out.entry(follower).or_default().push(base);
        }
    }
    out
}

/// World poses of all frames of `raw`, in order.
fn resolve(xml: &str, raw: &[Raw]) -> Vec<TruthFrame> {
    let partners = joint_partners(xml);
    let by_ref: BTreeMap<&str, usize> = raw.iter().enumerate().filter_map(|(i, f)| Some((f.ref_id.as_deref()?, i))).collect();
    let target = |i: usize, reference: &str| -> Option<usize> {
        let f = &raw[i];
        match reference {
            "WORLD" => None,
            "ADJOINING" => {
                let others = &partners[f.ref_id.as_deref().expect("ADJOINING frame without ref")];
                assert_eq!(others.len(), 1, "truth scanner: {} is ADJOINING to {} joints", f.node, others.len());
                Some(by_ref[others[0].as_str()])
            }
            name => Some(
                (0..raw.len())
                    .find(|&k| f.owner.is_some() && raw[k].owner == f.owner && raw[k].name == name)
                    .unwrap_or_else(|| panic!("truth scanner: {} refers to missing {name}", f.node)),
            ),
        }
    };
    fn place(
        i: usize,
        raw: &[Raw],
        target: &dyn Fn(usize, &str) -> Option<usize>,
        memo: &mut Vec<Option<TruthFrame>>,
        depth: usize,
    ) -> TruthFrame {
        if let Some(f) = &memo[i] {
            return f.clone();
        }
        assert!(depth <= raw.len(), "truth scanner: frame reference cycle at {}", raw[i].node);
        let f = &raw[i];
        let placed = if f.refs.iter().all(|r| r == "WORLD") {
            TruthFrame { position: f.position, rotation: f.rotation }
        } else {
            let mut world = |r: &str| target(i, r).map(|t| place(t, raw, target, memo, depth + 1));
            let origin = world(&f.refs[0]).map_or(Vector3::zeros(), |t| t.position);
            let axes = world(&f.refs[1]).map_or(Matrix3::identity(), |t| crate::check::nearest_rotation(&t.rotation));
            let orientation = world(&f.refs[2]).map_or(Matrix3::identity(), |t| crate::check::nearest_rotation(&t.rotation));
            TruthFrame { position: origin + axes * f.position, rotation: orientation * crate::check::nearest_rotation(&f.rotation) }
        };
        memo[i] = Some(placed.clone());
        placed
    }
    let mut memo = vec![None; raw.len()];
    (0..raw.len()).map(|i| place(i, raw, &target, &mut memo, 0)).collect()
}

/// Every `<Frame>` with a position, keyed by its nodeID, in world coordinates. Node IDs that
/// occur twice with different poses are dropped (ambiguous).
pub fn xml_frames(xml: &str) -> BTreeMap<String, TruthFrame> {
    let raw = scan(xml);
    let mut out: BTreeMap<String, TruthFrame> = BTreeMap::new();
    let mut dropped = Vec::new();
    for (r, f) in raw.iter().zip(resolve(xml, &raw)) {
        if let Some(prev) = out.get(&r.node) {
            if (prev.position - f.position).norm() > 1e-12 || (prev.rotation - f.rotation).norm() > 1e-12 {
                dropped.push(r.node.clone());
            }
        } else {
            out.insert(r.node.clone(), f);
        }
    }
    for d in dropped {
        out.remove(&d);
    }
    out
}

/// World pose of each `<Body>`'s `CG` frame by body nodeID.
fn xml_cg_frames(xml: &str) -> BTreeMap<String, TruthFrame> {
    let raw = scan(xml);
    let bodies = spans(xml, "Body").len();
    raw.iter()
        .zip(resolve(xml, &raw))
        .filter(|(r, _)| r.name == "CG" && r.owner.is_some_and(|o| o < bodies))
        .map(|(r, f)| (r.owner_node.clone(), f))
        .collect()
}

/// Body CG positions (m) by body nodeID: the `CG` frame of each `<Body>`.
pub fn xml_cgs(xml: &str) -> BTreeMap<String, Vector3<f64>> {
    xml_cg_frames(xml).into_iter().map(|(k, f)| (k, f.position)).collect()
}

fn kg_per(unit: &str) -> f64 {
    match unit {
        "kg" => 1.0,
        "g" => 1e-3,
        "lbm" => 0.453_592_37,
        "slug" => 14.593_902_937_2,
        other => panic!("truth scanner: unknown mass unit {other:?}"),
    }
}

fn inertia_factor(unit: &str) -> f64 {
    let (m, l) = unit.split_once('*').unwrap_or_else(|| panic!("truth scanner: inertia unit {unit:?}"));
    let l = l.strip_suffix("^2").unwrap_or_else(|| panic!("truth scanner: inertia unit {unit:?}"));
    kg_per(m) * metres_per(l).powi(2)
}

/// Mass (kg) and inertia about the CG resolved in world axes (kg m^2), by body nodeID:
/// `R_cg * I * R_cgᵀ` with the CG frame's world orientation (orthonormalised).
pub fn xml_mass_properties(xml: &str) -> BTreeMap<String, (f64, Matrix3<f64>)> {
    let cg_frames = xml_cg_frames(xml);
    let mut out = BTreeMap::new();
    for body in xml.split("<Body>").skip(1) {
        let body = body.split("</Body>").next().unwrap_or(body);
        let (Some(node), Some(mass), Some(mu), Some(inertia), Some(iu)) = (
            element(body, "nodeID"),
            element(body, "mass"),
            element(body, "massUnits"),
            element(body, "inertia"),
            element(body, "inertiaUnits"),
        ) else {
            continue;
        };
        let i = numbers(inertia);
        let Ok(m) = mass.parse::<f64>() else { continue };
        if i.len() != 9 {
            continue;
        }
        let Some(cg) = cg_frames.get(node) else { continue };
        let r = crate::check::nearest_rotation(&cg.rotation);
        let i = Matrix3::from_row_slice(&i) * inertia_factor(iu);
        let i = (i + i.transpose()) * 0.5;
        out.insert(node.to_string(), (m * kg_per(mu), r * i * r.transpose()));
    }
    out
}
