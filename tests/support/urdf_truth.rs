//! Ground truth read straight from a URDF, independently of the converter's front end: each
//! link's frame (`<link>::CS1`) and inertial frame (`<link>::CG`) in the world at given joint
//! values (the zero configuration unless the model had to be assembled to close Drake loops), composed along the tree with rotation matrices written out here (R = Rz(yaw)
//! Ry(pitch) Rx(roll)), the centre of mass and the inertia resolved in world axes.

use std::collections::BTreeMap;

use nalgebra::{Matrix3, Vector3};

use crate::truth::TruthFrame;

/// Frames by node ID (`<link>::CS1`, `<link>::CG`), CGs and (mass, world inertia) by link name.
#[derive(Debug, Default)]
pub struct UrdfTruth {
    pub frames: BTreeMap<String, TruthFrame>,
    pub cgs: BTreeMap<String, Vector3<f64>>,
    pub mass: BTreeMap<String, (f64, Matrix3<f64>)>,
    /// Joint name -> (type, parent, child), `<joint>` and `<drake:joint>` alike.
    pub joints: BTreeMap<String, (String, String, String)>,
    /// Per Drake `<loop_joint>`: the world positions of its frame on each link.
    pub loop_frames: BTreeMap<String, (Vector3<f64>, Vector3<f64>)>,
}

/// Rotation by `angle` about the unit `axis` (Rodrigues), written out.
fn axis_angle(axis: [f64; 3], angle: f64) -> Matrix3<f64> {
    let n = Vector3::from(axis).normalize();
    let k = Matrix3::new(0.0, -n.z, n.y, n.z, 0.0, -n.x, -n.y, n.x, 0.0);
    Matrix3::identity() + k * angle.sin() + k * k * (1.0 - angle.cos())
}

fn nums(s: Option<&str>, default: [f64; 3]) -> [f64; 3] {
    match s {
        Some(t) => {
            let v: Vec<f64> = t.split_whitespace().map(|x| x.parse().expect("number")).collect();
            [v[0], v[1], v[2]]
        }
        None => default,
    }
}

/// Rz(y) Ry(p) Rx(r), written out.
pub fn rpy_matrix(r: f64, p: f64, y: f64) -> Matrix3<f64> {
    let (sr, cr) = r.sin_cos();
    let (sp, cp) = p.sin_cos();
    let (sy, cy) = y.sin_cos();
    Matrix3::new(
        cy * cp,
        cy * sp * sr - sy * cr,
        cy * sp * cr + sy * sr,
        sy * cp,
        sy * sp * sr + cy * cr,
        sy * sp * cr - cy * sr,
        -sp,
        cp * sr,
        cp * cr,
    )
}

fn origin(n: Option<roxmltree::Node>) -> (Vector3<f64>, Matrix3<f64>) {
    match n {
        Some(o) => {
            let t = nums(o.attribute("xyz"), [0.0; 3]);
            let r = nums(o.attribute("rpy"), [0.0; 3]);
            (Vector3::from(t), rpy_matrix(r[0], r[1], r[2]))
        }
        None => (Vector3::zeros(), Matrix3::identity()),
    }
}

fn child<'a, 'i>(n: roxmltree::Node<'a, 'i>, tag: &str) -> Option<roxmltree::Node<'a, 'i>> {
    n.children().find(|c| c.is_element() && c.tag_name().name() == tag)
}

/// [`urdf_truth_at`] the zero configuration.
pub fn urdf_truth(text: &str) -> UrdfTruth {
    urdf_truth_at(text, &BTreeMap::new())
}

/// Truth with revolute/continuous joints turned and prismatic joints moved by `q` (by joint
/// name; absent = 0).
pub fn urdf_truth_at(text: &str, q: &BTreeMap<String, f64>) -> UrdfTruth {
    let doc = roxmltree::Document::parse(text).expect("URDF parses");
    let root = doc.root_element();
    let mut parent: BTreeMap<String, (String, Vector3<f64>, Matrix3<f64>)> = BTreeMap::new();
    let mut out = UrdfTruth::default();
    for j in root.children().filter(|n| n.is_element() && n.tag_name().name() == "joint") {
        let p = child(j, "parent").and_then(|c| c.attribute("link")).expect("parent").to_string();
        let c = child(j, "child").and_then(|c| c.attribute("link")).expect("child").to_string();
        let (mut t, mut r) = origin(child(j, "origin"));
        let kind = j.attribute("type").unwrap_or("");
        if let Some(v) = q.get(j.attribute("name").unwrap_or("")) {
            let axis = nums(child(j, "axis").and_then(|a| a.attribute("xyz")), [1.0, 0.0, 0.0]);
            match kind {
                "revolute" | "continuous" => r *= axis_angle(axis, *v),
                "prismatic" => t += r * Vector3::from(axis).normalize() * *v,
                _ => {}
            }
        }
        out.joints
            .insert(j.attribute("name").expect("name").to_string(), (j.attribute("type").unwrap_or("").to_string(), p.clone(), c.clone()));
        parent.insert(c, (p, t, r));
    }
    let world_of = |link: &str| -> (Vector3<f64>, Matrix3<f64>) {
        let (mut t, mut r) = (Vector3::zeros(), Matrix3::identity());
        let mut cur = link.to_string();
        let mut guard = 0;
        // p_world = R_parent * (R_o p + t_o) + t_parent, walking up.
        while let Some((p, ot, or)) = parent.get(&cur) {
            t = or * t + ot;
            r = or * r;
            cur = p.clone();
            guard += 1;
            assert!(guard < 10_000, "cycle");
        }
        (t, r)
    };
    for l in root.children().filter(|n| n.is_element() && n.tag_name().name() == "loop_joint") {
        let end = |tag: &str| {
            let c = child(l, tag).expect("loop link");
            let (t, r) = world_of(c.attribute("link").expect("link"));
            let (ot, _) = origin(Some(c));
            r * ot + t
        };
        out.loop_frames.insert(l.attribute("name").expect("name").to_string(), (end("link1"), end("link2")));
    }
    for l in root.children().filter(|n| n.is_element() && n.tag_name().name() == "link") {
        let name = l.attribute("name").expect("link name");
        if name == "world" {
            continue;
        }
        let (t, r) = world_of(name);
        out.frames.insert(format!("{name}::CS1"), TruthFrame { position: t, rotation: r });
        let inertial = child(l, "inertial");
        let (ct, cr) = origin(inertial.and_then(|i| child(i, "origin")));
        let (cg_p, cg_r) = (r * ct + t, r * cr);
        out.frames.insert(format!("{name}::CG"), TruthFrame { position: cg_p, rotation: cg_r });
        out.cgs.insert(name.to_string(), cg_p);
        let mass = inertial.and_then(|i| child(i, "mass")).and_then(|m| m.attribute("value")).map_or(0.0, |v| v.parse().expect("mass"));
        let i = inertial.and_then(|i| child(i, "inertia"));
        let g = |k: &str| i.and_then(|i| i.attribute(k)).map_or(0.0, |v| v.trim().parse::<f64>().expect("inertia"));
        let ic = Matrix3::new(g("ixx"), g("ixy"), g("ixz"), g("ixy"), g("iyy"), g("iyz"), g("ixz"), g("iyz"), g("izz"));
        out.mass.insert(name.to_string(), (mass, cg_r * ic * cg_r.transpose()));
    }
    out
}

/// The joint values a conversion started from (each single-coordinate joint's start value, by
/// CAD name), for [`urdf_truth_at`].
pub fn start_values(report: &cad2mo_engine::pipeline::report::Report) -> BTreeMap<String, f64> {
    report.joints.iter().filter(|j| j.initial_q.len() == 1).map(|j| (j.cad_name.clone(), j.initial_q[0])).collect()
}

/// Checks that every loop joint's two frames coincide in the truth (to 1e-9 m).
pub fn loops_closed(t: &UrdfTruth) -> Result<usize, String> {
    for (name, (a, b)) in &t.loop_frames {
        let d = (a - b).norm();
        if d.is_nan() || d >= 1e-9 {
            return Err(format!("loop joint {name}: frames {d:e} m apart"));
        }
    }
    Ok(t.loop_frames.len())
}
