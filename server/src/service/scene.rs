//! The service's glue for scenes (issue 29; no HTTP, no SQL of its own): a model's stored scene
//! checked against a version's bodies, and its objects added to the version's collision data
//! ([`with_scene`]) so the CAD-pose interferences, the allowed-collision matrix and the checks
//! along motions name them like bodies.

use nalgebra::Isometry3;
use serde::Serialize;

use cad2mo_engine::scene::{self, Issue, Meshes, SceneMesh, SceneObject, SceneSpec};

use crate::service::collisions::VersionShapes;
use crate::service::FieldError;

/// A scene object among a version's collision bodies.
#[derive(Clone, Debug)]
pub struct Placed {
    pub object: SceneObject,
    /// The body it is attached to (an index into the version's bodies).
    pub body: Option<usize>,
}

/// Why a scene cannot be stored.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("the scene is not valid: {}", first(.0))]
    Invalid(Vec<FieldError>),
}

fn first(errors: &[FieldError]) -> String {
    errors.first().map(|e| format!("{} {}", e.field, e.message)).unwrap_or_default()
}

impl From<Vec<Issue>> for SceneError {
    fn from(issues: Vec<Issue>) -> Self {
        SceneError::Invalid(issues.into_iter().map(FieldError::from).collect())
    }
}

/// Checks a scene the user gives against the bodies of the model's latest converted version.
pub fn check(spec: &SceneSpec, bodies: &[String], meshes: &Meshes) -> Result<(), SceneError> {
    scene::check_with(spec, bodies, meshes)?;
    Ok(())
}

/// An uploaded scene mesh named `name` from the file `file` (its extension chooses the reader):
/// refused with an issue naming `name` (a bad name) or `file` (not a readable mesh, too big).
pub fn read_mesh(name: &str, file: &str, bytes: &[u8]) -> Result<SceneMesh, SceneError> {
    if !scene::valid_name(name) {
        let shown = cad2mo_engine::pipeline::ir::clip(name, 70);
        return Err(vec![Issue::new(
            "name",
            format!("{shown:?} is not a valid mesh name: a letter, then letters, digits or _, at most {} characters", scene::MAX_NAME),
        )]
        .into());
    }
    scene::mesh::read(file, bytes).map_err(|m| vec![Issue::new("file", m)].into())
}

/// The stored meshes from their blobs (`get`: a blob's bytes by hash), by name.
pub fn load_meshes(rows: &[(String, String)], get: impl Fn(&str) -> std::io::Result<Option<Vec<u8>>>) -> anyhow::Result<Meshes> {
    let mut out = Meshes::new();
    for (name, hash) in rows {
        let bytes = get(hash)?.ok_or_else(|| anyhow::anyhow!("the blob {hash} of scene mesh {name} is missing"))?;
        let mesh = scene::mesh::from_stl(&bytes).map_err(|e| anyhow::anyhow!("scene mesh {name} is corrupt: {e}"))?;
        out.insert(name.clone(), mesh);
    }
    Ok(out)
}

/// A scene object left out of a version's checks, and why.
#[derive(Clone, Debug, Serialize)]
pub struct LeftOut {
    pub field: String,
    pub message: String,
}

/// The version's collision data with the scene's objects after its bodies: each object's shape,
/// its pose at t = 0 (an attached object: its body's CAD pose times its own), and the pairs
/// allowed by default (an object and the body it is attached to; two objects fixed in the
/// world). Objects this version cannot take (their name is now a body's, their body is gone)
/// are left out and returned.
pub fn with_scene(v: &VersionShapes, spec: &SceneSpec, meshes: &Meshes) -> (VersionShapes, Vec<LeftOut>) {
    let model = &v.bodies[..v.model_bodies];
    let (scene, left_out) = scene::check_stored(spec, model, meshes);
    let left_out = left_out.into_iter().map(|i| LeftOut { field: i.field, message: i.message }).collect();
    let mut out = VersionShapes {
        bodies: model.to_vec(),
        shapes: v.shapes[..v.model_bodies].to_vec(),
        joined: v.joined.clone(),
        cad: v.cad[..v.model_bodies].to_vec(),
        report_bodies: v.report_bodies.clone(),
        model_bodies: v.model_bodies,
        scene: Vec::new(),
    };
    for o in scene.objects {
        let i = out.bodies.len();
        let body = o.attached_to.as_ref().and_then(|b| model.iter().position(|x| x == b));
        if let Some(b) = body {
            out.joined.insert((b.min(i), b.max(i)), format!("{} is attached to {}", o.name, model[b]));
        }
        if o.fixed_in_world() {
            for (k, p) in out.scene.iter().enumerate() {
                if p.object.fixed_in_world() {
                    let j = v.model_bodies + k;
                    out.joined.insert((j, i), format!("{} and {} are both fixed in the world", p.object.name, o.name));
                }
            }
        }
        out.bodies.push(o.name.clone());
        out.shapes.push(Some(o.shape()));
        out.cad.push(match body {
            Some(b) => v.cad[b] * o.pose_at(0.0),
            None => o.pose_at(0.0),
        });
        out.scene.push(Placed { object: o, body });
    }
    (out, left_out)
}

/// Every collision body's pose at time `t`: the model's (`model`, one per model body) followed
/// by the scene's.
pub fn poses(v: &VersionShapes, mut model: Vec<Isometry3<f64>>, t: f64) -> Vec<Isometry3<f64>> {
    model.truncate(v.model_bodies);
    for p in &v.scene {
        let own = p.object.pose_at(t);
        let world = match p.body {
            Some(b) => model[b] * own,
            None => own,
        };
        model.push(world);
    }
    model
}
