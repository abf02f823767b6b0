//! Collisions over HTTP (issue 14): a version's collision shapes and interferences at the CAD
//! pose, the model's allowed-collision matrix, and the check along a motion.

use std::collections::BTreeSet;
use std::sync::Arc;

use axum::extract::rejection::JsonRejection;
use axum::extract::State;
use axum::routing::get;
use axum::{Json, Router};
use serde::{Deserialize, Serialize};

use super::error::{blocking, FieldError};
use super::extract::Path;
use super::motions::{converted_version, find as find_motion, kinematic};
use super::ApiError;
use crate::app::AppState;
use crate::service::collisions::{self, Edits, VersionShapes};
use crate::store;
use cad2mo_engine::pipeline::back::collision_shapes::InterferenceReport;

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/versions/{version}/collision", get(version_collision))
        .route("/api/models/{model_id}/collision-matrix", get(get_matrix).put(put_matrix))
        .route("/api/models/{model_id}/motions/{motion_id}/collisions", get(motion_collisions))
}

/// The shapes of a version with the model's scene objects after its bodies (issue 29), and the
/// scene objects this version leaves out.
pub(super) async fn scene_shapes(
    state: &AppState,
    model_id: &str,
    version: Option<i64>,
) -> Result<(i64, Arc<VersionShapes>, Vec<crate::service::scene::LeftOut>), ApiError> {
    let (number, s) = shapes(state, model_id, version).await?;
    let spec = store::scene::get(&state.store, model_id).await?;
    if spec.objects.is_empty() {
        return Ok((number, s, Vec::new()));
    }
    let meshes = super::scene::meshes(state, model_id).await?;
    let (with, left_out) = blocking(move || Ok(crate::service::scene::with_scene(&s, &spec, &meshes))).await?;
    Ok((number, Arc::new(with), left_out))
}

/// The shapes of a version (`None`: the latest converted one), cached by package.
pub(super) async fn shapes(state: &AppState, model_id: &str, version: Option<i64>) -> Result<(i64, Arc<VersionShapes>), ApiError> {
    let v = converted_version(state, model_id, version, "its collision shapes are unknown").await?;
    let (package, report) = (v.package_sha256.clone().unwrap_or_default(), v.report_sha256.clone().unwrap_or_default());
    if let Some(s) = state.collisions.get(&package) {
        return Ok((v.version, s));
    }
    let (blobs, key, number) = (state.blobs.clone(), package.clone(), v.version);
    let s = blocking(move || {
        let missing = |what: &str| ApiError::Internal(anyhow::anyhow!("{what} of version {number} is missing"));
        let zip = blobs.get(&package).map_err(|e| ApiError::Internal(e.into()))?.ok_or_else(|| missing("package"))?;
        let report = blobs.get(&report).map_err(|e| ApiError::Internal(e.into()))?.ok_or_else(|| missing("report"))?;
        let report: serde_json::Value = serde_json::from_slice(&report).map_err(|e| ApiError::Internal(e.into()))?;
        Ok(VersionShapes::load(&report, &zip)?)
    })
    .await?;
    let s = Arc::new(s);
    state.collisions.put(key, s.clone());
    Ok((v.version, s))
}

pub(super) async fn edits(state: &AppState, model_id: &str) -> Result<Edits, ApiError> {
    Ok(store::collision::edits(&state.store, model_id).await?.into_iter().map(|(a, b, x)| ((a, b), x)).collect())
}

#[derive(Serialize)]
struct VersionCollision {
    version: i64,
    /// Per body: kind, parts, vertices, fit error (m), volume ratio, warnings (from the conversion).
    bodies: serde_json::Value,
    /// Checked pairs (the model's current matrix) that intersect at the CAD pose.
    interferences: Vec<InterferenceReport>,
    /// Scene objects this version cannot take, and why (issue 29).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    scene_left_out: Vec<crate::service::scene::LeftOut>,
}

async fn version_collision(
    State(state): State<AppState>,
    Path((model_id, version)): Path<(String, i64)>,
) -> Result<Json<VersionCollision>, ApiError> {
    let (version, s, scene_left_out) = scene_shapes(&state, &model_id, Some(version)).await?;
    let edits = edits(&state, &model_id).await?;
    let shared = s.clone();
    let interferences = blocking(move || Ok(collisions::interferences(&shared, &edits))).await?;
    Ok(Json(VersionCollision { version, bodies: s.report_bodies.clone(), interferences, scene_left_out }))
}

async fn get_matrix(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<collisions::MatrixView>, ApiError> {
    let (_, s, _) = scene_shapes(&state, &model_id, None).await?;
    let edits = edits(&state, &model_id).await?;
    Ok(Json(collisions::matrix(&s, &edits)))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PairEdit {
    a: String,
    b: String,
    /// `null` returns the pair to its default.
    allowed: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MatrixEdit {
    pairs: Vec<PairEdit>,
}

async fn put_matrix(
    State(state): State<AppState>,
    Path(model_id): Path<String>,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<Json<collisions::MatrixView>, ApiError> {
    let v = b.map(|Json(v)| v).map_err(|e| ApiError::BadRequest(format!("invalid collision matrix: {}", e.body_text())))?;
    let edit: MatrixEdit = serde_json::from_value(v).map_err(|e| ApiError::BadRequest(format!("invalid collision matrix: {e}")))?;
    let (_, s, _) = scene_shapes(&state, &model_id, None).await?;
    let with: BTreeSet<&str> = (0..s.bodies.len()).filter(|&i| s.shapes[i].is_some()).map(|i| s.bodies[i].as_str()).collect();
    let mut errors = Vec::new();
    let mut seen = BTreeSet::new();
    for (k, p) in edit.pairs.iter().enumerate() {
        let field = format!("pairs[{k}]");
        if p.a == p.b {
            errors.push(FieldError { field, message: format!("a pair needs two bodies, not {} twice", p.a) });
        } else if let Some(missing) = [&p.a, &p.b].into_iter().find(|n| !with.contains(n.as_str())) {
            let known: Vec<&str> = with.iter().copied().take(20).collect();
            errors.push(FieldError {
                field,
                message: format!("{missing} is not a body with a collision shape (bodies: {})", known.join(", ")),
            });
        } else if !seen.insert(store::collision::ordered(&p.a, &p.b)) {
            errors.push(FieldError { field, message: format!("the pair {} / {} is given twice", p.a, p.b) });
        }
    }
    if !errors.is_empty() {
        let detail = format!("the collision matrix edit is not valid: {} {}", errors[0].field, errors[0].message);
        return Err(ApiError::Invalid { detail, errors });
    }
    let changes: Vec<(String, String, Option<bool>)> = edit.pairs.into_iter().map(|p| (p.a, p.b, p.allowed)).collect();
    store::collision::apply(&state.store, &model_id, &changes).await?;
    let edits = edits(&state, &model_id).await?;
    Ok(Json(collisions::matrix(&s, &edits)))
}

async fn motion_collisions(
    State(state): State<AppState>,
    Path((model_id, motion_id)): Path<(String, String)>,
) -> Result<Json<collisions::MotionCollisions>, ApiError> {
    let m = find_motion(&state, &model_id, &motion_id).await?;
    let (version, k) = kinematic(&state, &model_id).await?;
    let (_, s, _) = scene_shapes(&state, &model_id, Some(version)).await?;
    let limits = store::motions::limits(&state.store, &model_id).await?;
    let edits = edits(&state, &model_id).await?;
    let out = blocking(move || {
        let p = crate::service::motions::plan_motion(&k, &limits, &m.spec)?;
        Ok(collisions::along_motion(&k.mech, &s, &edits, version, &m.name, &p)?)
    })
    .await?;
    Ok(Json(out))
}
