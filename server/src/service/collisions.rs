//! The service's glue for collisions (no HTTP, no SQL of its own): a version's collision shapes
//! (read back from its package's `Resources/Collision/shapes.json`), the allowed-collision
//! matrix (defaults from the report's joints, the user's edits by body name), interferences at
//! the CAD pose under the current matrix, and the check along a motion.

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

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
    /// The model's bodies are `bodies[..model_bodies]`; the rest are scene objects
    /// (`service::scene::with_scene`), placed by `scene`.
    pub model_bodies: usize,
    pub scene: Vec<crate::service::scene::Placed>,
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
    /// The check would exceed its work or memory budget (the message names the limit).
    #[error("{0}")]
    TooLarge(String),
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
        let model_bodies = bodies.len();
        Ok(VersionShapes {
            bodies,
            shapes,
            joined,
            cad,
            report_bodies: report["collision"]["bodies"].clone(),
            model_bodies,
            scene: Vec::new(),
        })
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

#[derive(Clone, Debug, Serialize, Deserialize)]
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
/// Most samples one check takes: the trajectory route's cap.
pub const MAX_SWEEP_SAMPLES: usize = cad2mo_engine::motion::plan::MAX_SAMPLES;
/// Most body poses one check holds (samples × bodies): with the samples, step bounds and
/// the sweep's state, about 1.5 GB of peak memory for 5 M poses, so 2 M.
pub const MAX_SWEEP_POSES: usize = 2_000_000;
/// Most pair tests one check makes (samples × checked pairs).
pub const MAX_SWEEP_PAIR_SAMPLES: usize = 20_000_000;

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
    let samples = p.sample_count(SWEEP_RATE);
    within_budget(v, edits, samples).map_err(|what| {
        CollisionError::TooLarge(format!(
            "motion \"{}\" ({:.1} s) is too long to check for collisions at {SWEEP_RATE} Hz: {what}; shorten the motion",
            cad2mo_engine::pipeline::ir::clip(name, 200),
            p.duration
        ))
    })?;
    let s = p.closed_samples(mech, SWEEP_RATE).map_err(|issues| crate::service::motions::invalid(name, issues))?;
    let n = mech.dof();
    let (sweep, pairs, first_contact) = sweep_along(mech, v, edits, &s.t, &|i| (0..n).map(|a| s.q[a][i]).collect())?;
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

/// The budgets of a check of `samples` samples: `Err` names the one exceeded.
fn within_budget(v: &VersionShapes, edits: &Edits, samples: usize) -> Result<(), String> {
    let bodies = v.bodies.len();
    let with: Vec<usize> = (0..bodies).filter(|&i| v.shapes[i].is_some()).collect();
    let pairs_checked = with
        .iter()
        .enumerate()
        .flat_map(|(x, &i)| with[x + 1..].iter().map(move |&j| (i, j)))
        .filter(|&(i, j)| checked(v, edits, i, j))
        .count();
    if samples > MAX_SWEEP_SAMPLES {
        return Err(format!("{samples} samples is more than the limit of {MAX_SWEEP_SAMPLES} samples"));
    }
    if samples.saturating_mul(bodies) > MAX_SWEEP_POSES {
        return Err(format!("{samples} samples × {bodies} bodies is more than the limit of {MAX_SWEEP_POSES} body poses per check"));
    }
    if samples.saturating_mul(pairs_checked) > MAX_SWEEP_PAIR_SAMPLES {
        return Err(format!(
            "{samples} samples × {pairs_checked} checked pairs is more than the limit of {MAX_SWEEP_PAIR_SAMPLES} pair tests per check"
        ));
    }
    Ok(())
}

/// The sweep of every checked pair (bodies and scene objects, the current matrix) at `times`,
/// the model's coordinates at sample `i` being `q_at(i)`; the pairs the closest first and the
/// first contact.
fn sweep_along(
    mech: &Mechanism,
    v: &VersionShapes,
    edits: &Edits,
    times: &[f64],
    q_at: &dyn Fn(usize) -> Vec<f64>,
) -> Result<(collision::Sweep, Vec<PairSweepView>, Option<FirstContact>), CollisionError> {
    if mech.body_names() != &v.bodies[..v.model_bodies] {
        return Err(internal("the mechanism's bodies differ from the package's".into()));
    }
    // Poses computed on demand (the sweep asks once per sample), not kept here as well.
    let failed: std::cell::RefCell<Option<String>> = std::cell::RefCell::new(None);
    let pose_at = |i: usize| -> Vec<Isometry3<f64>> {
        match mech.forward(&q_at(i)) {
            Ok(k) => {
                let model: Vec<Isometry3<f64>> =
                    (0..v.model_bodies).map(|b| mech.body_pose(&k, BodyId(b as u32)).unwrap_or_else(|_| v.cad[b])).collect();
                crate::service::scene::poses(v, model, times[i])
            }
            Err(e) => {
                failed.borrow_mut().get_or_insert_with(|| e.to_string());
                v.cad.clone()
            }
        }
    };
    let world = collision::World::new(&v.shapes);
    let sweep = collision::sweep(&world, times, &pose_at, &|i, j| checked(v, edits, i, j), &SweepOptions::default());
    if let Some(e) = failed.into_inner() {
        return Err(internal(e));
    }
    let mut pairs: Vec<PairSweepView> =
        sweep.pairs.iter().map(|p| PairSweepView { a: v.bodies[p.a].clone(), b: v.bodies[p.b].clone(), sweep: p.clone() }).collect();
    pairs.sort_by(|x, y| x.sweep.min_distance.total_cmp(&y.sweep.min_distance));
    let first_contact = pairs
        .iter()
        .filter_map(|p| p.sweep.first_contact.map(|t| FirstContact { a: p.a.clone(), b: p.b.clone(), time: t }))
        .min_by(|x, y| x.time.total_cmp(&y.time));
    Ok((sweep, pairs, first_contact))
}

/// A pair that touches along a simulated run.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RunContact {
    pub a: String,
    pub b: String,
    /// The first output sample where it touches or penetrates, s.
    pub first_contact: f64,
    /// Its deepest penetration over the samples, m.
    pub max_depth: f64,
}

/// The contacts along a simulated run (issue 29): every checked pair of the version's bodies and
/// the model's scene objects (static, attached and moving ones at their poses of the run's time;
/// free ones held at their pose) at the run's output samples.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RunCollisions {
    pub samples: usize,
    /// Checked pairs (both with a collision shape).
    pub pairs_checked: usize,
    pub guarantee: String,
    pub first_contact: Option<FirstContact>,
    /// The pairs that touch, the earliest first.
    pub contacts: Vec<RunContact>,
    /// Why the run was not checked (the check's budget), when it was not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub not_checked: Option<String>,
}

/// Checks a simulated run: the model's coordinates `q[i]` at `times[i]` (its output samples).
pub fn along_run(
    mech: &Mechanism,
    v: &VersionShapes,
    edits: &Edits,
    times: &[f64],
    q: &[Vec<f64>],
) -> Result<RunCollisions, CollisionError> {
    if let Err(what) = within_budget(v, edits, times.len()) {
        // The run stands; only its contacts are unknown.
        return Ok(RunCollisions {
            samples: times.len(),
            pairs_checked: 0,
            guarantee: String::new(),
            first_contact: None,
            contacts: Vec::new(),
            not_checked: Some(format!("the run is too large to check for collisions: {what}")),
        });
    }
    let (sweep, pairs, first_contact) = sweep_along(mech, v, edits, times, &|i| q[i].clone())?;
    let mut contacts: Vec<RunContact> = pairs
        .iter()
        .filter_map(|p| {
            p.sweep.first_contact.map(|t| RunContact { a: p.a.clone(), b: p.b.clone(), first_contact: t, max_depth: p.sweep.max_depth })
        })
        .collect();
    contacts.sort_by(|x, y| x.first_contact.total_cmp(&y.first_contact));
    Ok(RunCollisions {
        samples: sweep.samples,
        pairs_checked: pairs.len(),
        guarantee: sweep.guarantee,
        first_contact,
        contacts,
        not_checked: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shapes(bodies: usize) -> VersionShapes {
        let part = collision::ConvexPart { vertices: vec![[0.0, 0.0, 0.0]], faces: Vec::new(), radius: 0.1 };
        let shape = BodyShape {
            kind: ShapeKind::Hull,
            parts: vec![part],
            vertex_count: 1,
            fit_error: 0.0,
            volume_ratio: 0.0,
            source_triangles: 0,
            warnings: Vec::new(),
        };
        VersionShapes {
            bodies: (0..bodies).map(|b| format!("B{b}")).collect(),
            shapes: vec![Some(shape); bodies],
            joined: BTreeMap::new(),
            cad: vec![Isometry3::identity(); bodies],
            report_bodies: serde_json::Value::Null,
            model_bodies: bodies,
            scene: Vec::new(),
        }
    }

    /// A simulated run beyond the check's budgets is answered without its contacts, saying why
    /// (the run itself stands), and the budget counts checked pairs only.
    #[test]
    fn the_budgets_count_samples_poses_and_checked_pairs() {
        let v = shapes(200);
        // 200 bodies: 19,900 pairs × 2001 samples is beyond 20 M pair tests.
        let err = within_budget(&v, &Edits::new(), 2001).expect_err("too many pair tests");
        assert!(err.contains("19900 checked pairs"), "{err}");
        assert!(within_budget(&v, &Edits::new(), 1000).is_ok());
        assert!(within_budget(&shapes(2), &Edits::new(), MAX_SWEEP_SAMPLES + 1).expect_err("samples").contains("samples"));
        // Pairs allowed by the matrix are not checked, so not counted.
        let mut joined = shapes(200);
        for a in 0..200 {
            for b in a + 1..200 {
                joined.joined.insert((a, b), "test".into());
            }
        }
        assert!(within_budget(&joined, &Edits::new(), 2001).is_ok());
    }
}
