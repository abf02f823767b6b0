//! Ground truth read straight from an XML export, independently of the converter: every frame's
//! world pose by node ID, in metres. A deliberately simple scanner (the format has one value per
//! element, no attributes other than `ref`), so it shares no code with the front end.

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

/// Every `<Frame>` with a position, keyed by its nodeID. Node IDs that occur twice with
/// different poses are dropped (ambiguous).
pub fn xml_frames(xml: &str) -> BTreeMap<String, TruthFrame> {
    let mut out: BTreeMap<String, TruthFrame> = BTreeMap::new();
    let mut dropped = Vec::new();
    let mut rest = xml;
    while let Some(i) = rest.find("<Frame") {
        rest = &rest[i + 6..];
        let Some(end) = rest.find("</Frame>") else { break };
        let block = &rest[..end];
        rest = &rest[end..];
        let (Some(node), Some(pos), Some(orient)) =
            (element(block, "nodeID"), element(block, "position"), element(block, "orientation"))
        else {
            continue;
        };
        let scale = metres_per(element(block, "positionUnits").unwrap_or("m"));
        let p = numbers(pos);
        let o = numbers(orient);
        if p.len() != 3 || o.len() != 9 {
            continue;
        }
        let rotation = Matrix3::from_column_slice(&o);
        let f = TruthFrame { position: Vector3::new(p[0], p[1], p[2]) * scale, rotation };
        if let Some(prev) = out.get(node) {
            if (prev.position - f.position).norm() > 1e-12 || (prev.rotation - f.rotation).norm() > 1e-12 {
                dropped.push(node.to_string());
            }
        } else {
            out.insert(node.to_string(), f);
        }
    }
    for d in dropped {
        out.remove(&d);
    }
    out
}

/// Body CG positions (m) by body nodeID: the `CG` frame of each `<Body>`.
pub fn xml_cgs(xml: &str) -> BTreeMap<String, Vector3<f64>> {
    let mut out = BTreeMap::new();
    for body in xml.split("<Body>").skip(1) {
        let body = body.split("</Body>").next().unwrap_or(body);
        let Some(node) = element(body, "nodeID") else { continue };
        for frame in body.split("<Frame").skip(1) {
            if element(frame, "name") == Some("CG") {
                if let (Some(pos), Some(unit)) = (element(frame, "position"), element(frame, "positionUnits")) {
                    let p = numbers(pos);
                    if p.len() == 3 {
                        out.insert(node.to_string(), Vector3::new(p[0], p[1], p[2]) * metres_per(unit));
                    }
                }
            }
        }
    }
    out
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
/// `R_cg * I * R_cgᵀ` with the CG frame's orientation as written (orthonormalised).
pub fn xml_mass_properties(xml: &str) -> BTreeMap<String, (f64, Matrix3<f64>)> {
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
        let Some(cg) = body.split("<Frame").skip(1).find(|f| element(f, "name") == Some("CG")) else { continue };
        let o = numbers(element(cg, "orientation").unwrap_or(""));
        if o.len() != 9 {
            continue;
        }
        let r = crate::check::nearest_rotation(&Matrix3::from_column_slice(&o));
        let i = Matrix3::from_row_slice(&i) * inertia_factor(iu);
        let i = (i + i.transpose()) * 0.5;
        out.insert(node.to_string(), (m * kg_per(mu), r * i * r.transpose()));
    }
    out
}
