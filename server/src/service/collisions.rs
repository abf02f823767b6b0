//! The service's glue for collisions (no HTTP, no SQL of its own): a version's collision shapes
//! (read back from its package's `Resources/Collision/shapes.json`), the allowed-collision
//! matrix (defaults from the report's joints, the user's edits by body name), interferences at
//! the CAD pose under the current matrix, and the check along a motion.

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use serde::Serialize;

use cad2mo_engine::collision::{self, BodyShape, ShapeKind, SweepOptions};
use cad2mo_engine::mechanism::Mechanism;
use cad2mo_engine::motion::plan::Planned;
use cad2mo_engine::pipeline::back::collision_shapes::{read_shapes, InterferenceReport};
use cad2mo_engine::pipeline::ir::BodyId;

/// A converted version's collision data.
pub struct VersionShapes {
    /// Every body, in report order (the package's).
    pub bodies: Vec<String>,
    pub shapes: Vec<Option<BodyShape>>,
    /// Pairs allowed to touch by default (indices into `bodies`, a < b), and why.
    pub joined: BTreeMap<(usize, usize), String>,
    /// World pose of each body's frame_a at the CAD pose.
    pub cad: Vec<Isometry3<f64>>,
    /// The report's per-body section (kind, vertices, fit error, warnings).
    pub report_bodies: serde_json::Value,
}

/// Why a collision use case failed.
#[derive(Debug, thiserror::Error)]
pub enum CollisionError {
    /// The version's stored report or package does not hold what the check needs (not the
    /// user's fault: the message says what is missing).
    #[error("{0}")]
    Corrupt(String),
    /// The motion to check cannot be planned.
    #[error(transparent)]
    Motion(#[from] crate::service::motions::MotionError),
}

fn internal(what: String) -> CollisionError {
    CollisionError::Corrupt(what)
}

fn vec3(v: &serde_json::Value) -> Option<Vector3<f64>> {
    let a: [f64; 3] = serde_json::from_value(v.clone()).ok()?;
    Some(Vector3::from(a))
}

impl VersionShapes {
    /// From a version's report and package zip.
    pub fn load(report: &serde_json::Value, package_zip: &[u8]) -> Result<VersionShapes, CollisionError> {
        let bodies: Vec<String> = report["bodies"]
            .as_array()
            .map(|a| a.iter().filter_map(|b| b["modelica_name"].as_str().map(str::to_string)).collect())
            .unwrap_or_default();
        let index: BTreeMap<&str, usize> = bodies.iter().enumerate().map(|(i, n)| (n.as_str(), i)).collect();
        // The pairs allowed by default, as the conversion decided (joints, welded groups).
        let mut joined = BTreeMap::new();
        for p in report["collision"]["default_allowed"].as_array().into_iter().flatten() {
            let (Some(&a), Some(&b)) = (p["a"].as_str().and_then(|n| index.get(n)), p["b"].as_str().and_then(|n| index.get(n))) else {
                continue;
            };
            joined.insert((a.min(b), a.max(b)), p["why"].as_str().unwrap_or("allowed by default").to_string());
        }
        let mut cad = Vec::with_capacity(bodies.len());
        for b in report["bodies"].as_array().into_iter().flatten() {
            let f = &b["cs1"];
            let (Some(p), Some(x), Some(y)) = (vec3(&f["position_world"]), vec3(&f["x_axis_world"]), vec3(&f["y_axis_world"])) else {
                return Err(internal("the report has a body without its CS1 pose".into()));
            };
            let z = x.cross(&y);
            let r = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x, y, z]));
            cad.push(Isometry3::from_parts(Translation3::from(p), UnitQuaternion::from_rotation_matrix(&r)));
        }
        let mut shapes: Vec<Option<BodyShape>> = vec![None; bodies.len()];
        let mut archive = zip::ZipArchive::new(std::io::Cursor::new(package_zip)).map_err(|e| internal(format!("package: {e}")))?;
        let name = archive.file_names().find(|n| n.ends_with("/Resources/Collision/shapes.json")).map(str::to_string);
        if let Some(name) = name {
            let mut text = Vec::new();
            std::io::Read::read_to_end(&mut archive.by_name(&name).map_err(|e| internal(format!("package: {e}")))?, &mut text)
                .map_err(|e| internal(format!("package: {e}")))?;
            for (body, parts) in read_shapes(&text).map_err(internal)? {
                if let Some(&i) = index.get(body.as_str()) {
                    let vertex_count = parts.iter().map(|p| p.vertices.len()).sum();
                    shapes[i] = Some(BodyShape {
                        kind: ShapeKind::Hull,
                        parts,
                        vertex_count,
                        fit_error: 0.0,
                        volume_ratio: 0.0,
                        source_triangles: 0,
                        warnings: Vec::new(),
                    });
                }
            }
        }
        Ok(VersionShapes { bodies, shapes, joined, cad, report_bodies: report["collision"]["bodies"].clone() })
    }
}

/// One pair of the matrix.
#[derive(Clone, Debug, Serialize)]
pub struct PairView {
    pub a: String,
    pub b: String,
    /// May touch (not checked).
    pub allowed: bool,
    pub default: bool,
    pub custom: bool,
    pub why: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct MatrixView {
    /// Bodies with a collision shape, in package order.
    pub bodies: Vec<String>,
    pub pairs: Vec<PairView>,
    /// Edits naming bodies this version lacks (kept for a later version).
    pub orphans: Vec<PairView>,
}

/// The user's edits: (a, b) with a < b by name → allowed.
pub type Edits = BTreeMap<(String, String), bool>;

/// Whether bodies `i` and `j` are checked under `edits`.
pub fn checked(v: &VersionShapes, edits: &Edits, i: usize, j: usize) -> bool {
    if i == j {
        return false;
    }
    let (a, b) = crate::store::collision::ordered(&v.bodies[i], &v.bodies[j]);
    let allowed = edits.get(&(a.to_string(), b.to_string())).copied().unwrap_or_else(|| v.joined.contains_key(&(i.min(j), i.max(j))));
    !allowed
}

pub fn matrix(v: &VersionShapes, edits: &Edits) -> MatrixView {
    let with: Vec<usize> = (0..v.bodies.len()).filter(|&i| v.shapes[i].is_some()).collect();
    let mut pairs = Vec::new();
    let mut seen = BTreeSet::new();
    for (k, &i) in with.iter().enumerate() {
        for &j in &with[k + 1..] {
            let joint = v.joined.get(&(i, j));
            let default = joint.is_some();
            let (a, b) = crate::store::collision::ordered(&v.bodies[i], &v.bodies[j]);
            let key = (a.to_string(), b.to_string());
            seen.insert(key.clone());
            let edit = edits.get(&key).copied();
            let allowed = edit.unwrap_or(default);
            let why = match (edit, joint) {
                (Some(_), _) => "set by the user".to_string(),
                (None, Some(j)) => j.clone(),
                (None, None) => "not joined: checked".to_string(),
            };
            pairs.push(PairView { a: v.bodies[i].clone(), b: v.bodies[j].clone(), allowed, default, custom: edit.is_some(), why });
        }
    }
    let orphans = edits
        .iter()
        .filter(|(k, _)| !seen.contains(*k))
        .map(|((a, b), x)| PairView {
            a: a.clone(),
            b: b.clone(),
            allowed: *x,
            default: false,
            custom: true,
            why: "a body is not in this version".into(),
        })
        .collect();
    MatrixView { bodies: with.iter().map(|&i| v.bodies[i].clone()).collect(), pairs, orphans }
}

/// Interferences of checked pairs at the CAD pose.
pub fn interferences(v: &VersionShapes, edits: &Edits) -> Vec<InterferenceReport> {
    let world = collision::World::new(&v.shapes);
    collision::contacts_at(&world, &v.cad, &|i, j| checked(v, edits, i, j), 0.0)
        .into_iter()
        .filter(|c| c.distance < 0.0)
        .map(|c| InterferenceReport {
            a: v.bodies[c.a].clone(),
            b: v.bodies[c.b].clone(),
            depth: -c.distance,
            point_a: c.point_a,
            point_b: c.point_b,
            normal: c.normal,
        })
        .collect()
}

#[derive(Clone, Debug, Serialize)]
pub struct FirstContact {
    pub a: String,
    pub b: String,
    pub time: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct PairSweepView {
    pub a: String,
    pub b: String,
    #[serde(flatten)]
    pub sweep: collision::PairSweep,
}

#[derive(Clone, Debug, Serialize)]
pub struct MotionCollisions {
    pub motion: String,
    pub version: i64,
    pub samples: usize,
    pub rate_hz: f64,
    pub guarantee: String,
    pub first_contact: Option<FirstContact>,
    /// Checked pairs, the closest first.
    pub pairs: Vec<PairSweepView>,
}

/// The rate motions are checked at.
pub const SWEEP_RATE: f64 = 1000.0;

/// Checks a planned motion: body poses from the mechanism's forward kinematics at every sample
/// (the mechanism's bodies are the package's, in the same order).
pub fn along_motion(
    mech: &Mechanism,
    v: &VersionShapes,
    edits: &Edits,
    version: i64,
    name: &str,
    p: &Planned,
) -> Result<MotionCollisions, CollisionError> {
    let s = p.closed_samples(mech, SWEEP_RATE).map_err(|issues| crate::service::motions::invalid(name, issues))?;
    if mech.body_names() != v.bodies.as_slice() {
        return Err(internal("the mechanism's bodies differ from the package's".into()));
    }
    let n = mech.dof();
    let bodies = v.bodies.len();
    let mut poses: Vec<Vec<Isometry3<f64>>> = Vec::with_capacity(s.t.len());
    let mut q = vec![0.0; n];
    for i in 0..s.t.len() {
        for (a, qa) in q.iter_mut().enumerate() {
            *qa = s.q[a][i];
        }
        let k = mech.forward(&q).map_err(|e| internal(e.to_string()))?;
        let mut row = Vec::with_capacity(bodies);
        for b in 0..bodies {
            row.push(mech.body_pose(&k, BodyId(b as u32)).unwrap_or_else(|_| v.cad[b]));
        }
        poses.push(row);
    }
    let world = collision::World::new(&v.shapes);
    let sweep = collision::sweep(&world, &s.t, &|k| poses[k].clone(), &|i, j| checked(v, edits, i, j), &SweepOptions::default());
    let mut pairs: Vec<PairSweepView> =
        sweep.pairs.iter().map(|p| PairSweepView { a: v.bodies[p.a].clone(), b: v.bodies[p.b].clone(), sweep: p.clone() }).collect();
    pairs.sort_by(|x, y| x.sweep.min_distance.total_cmp(&y.sweep.min_distance));
    let first_contact = pairs
        .iter()
        .filter_map(|p| p.sweep.first_contact.map(|t| FirstContact { a: p.a.clone(), b: p.b.clone(), time: t }))
        .min_by(|x, y| x.time.total_cmp(&y.time));
    Ok(MotionCollisions {
        motion: name.to_string(),
        version,
        samples: sweep.samples,
        rate_hz: SWEEP_RATE,
        guarantee: sweep.guarantee,
        first_contact,
        pairs,
    })
}
