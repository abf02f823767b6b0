//! Drive assignments of a model: `GET /api/models/{model_id}/drives`,
//! `GET|PUT|DELETE /api/models/{model_id}/drives/{joint}`; and regeneration with the current
//! library and drives: `POST /api/models/{model_id}/reexport`, `POST /api/reexport` (every model).
//!
//! Joints are named by their stable Modelica element name from the latest converted version's
//! report; assignments to joints that version no longer has are listed as orphaned.

use axum::extract::State;
use axum::http::StatusCode;
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value as JsonValue};

use super::error::FieldError;
use super::extract::Path;
use super::ApiError;
use crate::app::AppState;
use crate::service::drives::{self, Assignment, ReferenceSpec};
use crate::store;

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/drives", get(list))
        .route("/api/models/{model_id}/drives/{joint}", get(get_one).put(put).delete(delete))
        .route("/api/models/{model_id}/reexport", post(reexport_one))
        .route("/api/reexport", post(reexport_all))
}

#[derive(Serialize)]
struct Queued {
    model_id: String,
    version: i64,
    job_id: String,
}

#[derive(Serialize)]
struct NotQueued {
    model_id: String,
    error: String,
}

#[derive(Serialize)]
struct Batch {
    jobs: Vec<Queued>,
    failed: Vec<NotQueued>,
}

async fn reexport_one(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<(StatusCode, Json<Queued>), ApiError> {
    if store::models::get_model(&state.store.pool, &model_id).await?.is_none() {
        return Err(ApiError::NotFound(format!("model {model_id}")));
    }
    let (version, job_id) = store::models::queue_reexport(&state.store.pool, &model_id)
        .await?
        .ok_or_else(|| ApiError::Conflict(format!("model {model_id} has no version to re-export")))?;
    state.jobs.notify();
    Ok((StatusCode::ACCEPTED, Json(Queued { model_id, version, job_id })))
}

/// Queues a re-export of every model's latest version; a model that cannot be queued is listed
/// in `failed` and does not stop the others (each job then succeeds or fails on its own).
async fn reexport_all(State(state): State<AppState>) -> Result<(StatusCode, Json<Batch>), ApiError> {
    let mut batch = Batch { jobs: Vec::new(), failed: Vec::new() };
    for m in store::models::list_models(&state.store.pool).await? {
        match store::models::queue_reexport(&state.store.pool, &m.id).await {
            Ok(Some((version, job_id))) => batch.jobs.push(Queued { model_id: m.id, version, job_id }),
            Ok(None) => batch.failed.push(NotQueued { model_id: m.id, error: "the model has no version".into() }),
            Err(e) => batch.failed.push(NotQueued { model_id: m.id, error: e.to_string() }),
        }
    }
    state.jobs.notify();
    Ok((StatusCode::ACCEPTED, Json(batch)))
}

#[derive(Serialize)]
struct JointDto {
    name: String,
    node_id: String,
    kind: &'static str,
    start: f64,
    label: String,
    assigned: bool,
}

#[derive(Serialize)]
struct DriveDto {
    #[serde(flatten)]
    assignment: Assignment,
    /// `active`, or `orphaned` when the latest converted version has no such joint.
    status: &'static str,
}

#[derive(Serialize)]
struct DrivesDto {
    model_id: String,
    /// The version the joint list comes from (the latest converted one), if any.
    version: Option<i64>,
    joints: Vec<JointDto>,
    drives: Vec<DriveDto>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PutBody {
    motor_instance: String,
    gear_instance: String,
    controller_instance: String,
    #[serde(default)]
    overrides: Map<String, JsonValue>,
    #[serde(default)]
    reference: Option<ReferenceSpec>,
}

/// The latest converted version of a model and its report (404 for an unknown model).
async fn latest_report(state: &AppState, model_id: &str) -> Result<Option<(i64, JsonValue)>, ApiError> {
    if store::models::get_model(&state.store.pool, model_id).await?.is_none() {
        return Err(ApiError::NotFound(format!("model {model_id}")));
    }
    let versions = store::models::list_versions(&state.store.pool, model_id).await?;
    let Some(v) = versions.iter().filter(|v| v.report_sha256.is_some()).max_by_key(|v| v.version) else {
        return Ok(None);
    };
    let hash = v.report_sha256.clone().unwrap_or_default();
    let blobs = state.blobs.clone();
    let bytes = super::error::blocking(move || blobs.get(&hash).map_err(|e| ApiError::Internal(e.into()))).await?;
    let report = bytes
        .and_then(|b| serde_json::from_slice(&b).ok())
        .ok_or_else(|| ApiError::Internal(anyhow::anyhow!("report of {model_id} v{} is missing", v.version)))?;
    Ok(Some((v.version, report)))
}

fn kind_name(k: cad2mo_engine::pipeline::back::modelica::mechatronics::JointKind) -> &'static str {
    match k {
        cad2mo_engine::pipeline::back::modelica::mechatronics::JointKind::Revolute => "revolute",
        cad2mo_engine::pipeline::back::modelica::mechatronics::JointKind::Prismatic => "prismatic",
    }
}

async fn list(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<DrivesDto>, ApiError> {
    let latest = latest_report(&state, &model_id).await?;
    let assignments = store::drives::list(&state.store, &model_id).await?;
    let joints = latest.as_ref().map(|(_, r)| drives::drivable_joints(r)).unwrap_or_default();
    Ok(Json(DrivesDto {
        model_id,
        version: latest.as_ref().map(|(v, _)| *v),
        joints: joints
            .iter()
            .map(|j| JointDto {
                name: j.name.clone(),
                node_id: j.node_id.clone(),
                kind: kind_name(j.kind),
                start: j.start,
                label: j.label.clone(),
                assigned: assignments.iter().any(|a| a.joint == j.name),
            })
            .collect(),
        drives: assignments
            .into_iter()
            .map(|a| {
                let status = if joints.iter().any(|j| j.name == a.joint) { "active" } else { "orphaned" };
                DriveDto { assignment: a, status }
            })
            .collect(),
    }))
}

async fn get_one(State(state): State<AppState>, Path((model_id, joint)): Path<(String, String)>) -> Result<Json<Assignment>, ApiError> {
    if store::models::get_model(&state.store.pool, &model_id).await?.is_none() {
        return Err(ApiError::NotFound(format!("model {model_id}")));
    }
    store::drives::get(&state.store, &model_id, &joint)
        .await?
        .map(Json)
        .ok_or_else(|| ApiError::NotFound(format!("drive of joint {joint}")))
}

async fn put(
    State(state): State<AppState>,
    Path((model_id, joint)): Path<(String, String)>,
    body: Result<Json<PutBody>, axum::extract::rejection::JsonRejection>,
) -> Result<Json<Assignment>, ApiError> {
    let Json(body) = body.map_err(|e| ApiError::BadRequest(format!("invalid drive assignment: {}", e.body_text())))?;
    let Some((_, report)) = latest_report(&state, &model_id).await? else {
        return Err(ApiError::Conflict(format!("model {model_id} has no converted version yet: its joints are unknown")));
    };
    let joints = drives::drivable_joints(&report);
    let mut errors: Vec<FieldError> = Vec::new();
    let Some(j) = joints.iter().find(|j| j.name == joint) else {
        let names: Vec<&str> = joints.iter().map(|j| j.name.as_str()).collect();
        return Err(ApiError::NotFound(format!("drivable joint {joint} (the model's are: {})", names.join(", "))));
    };
    let mut slots = Vec::new();
    for (slot, id) in [("motor", &body.motor_instance), ("gear", &body.gear_instance), ("controller", &body.controller_instance)] {
        match store::library::get_instance(&state.store, id).await? {
            Some((inst, class)) => slots.push((slot, inst, class)),
            None => errors.push(FieldError { field: format!("{slot}_instance"), message: format!("no library instance {id}") }),
        }
    }
    let refs: Vec<(&str, &cad2mo_engine::library::Instance, &cad2mo_engine::library::Class)> =
        slots.iter().map(|(s, i, c)| (*s, i, c)).collect();
    let reference = body.reference.unwrap_or(ReferenceSpec::Constant { value: j.start });
    let issues = drives::check_slots(&refs, &body.overrides).into_iter().chain(drives::check_reference(&reference));
    errors.extend(issues.map(|i| FieldError { field: i.field, message: i.message }));
    // The generator must accept the classes (e.g. a lead screw only on a prismatic joint).
    if errors.is_empty() {
        let choice = |slot: &str| {
            let (_, inst, class) = slots.iter().find(|(s, _, _)| *s == slot).expect("all slots resolved");
            drives::choice(class, inst, body.overrides.get(slot))
        };
        if let (Ok(motor), Ok(gear), Ok(controller)) = (choice("motor"), choice("gear"), choice("controller")) {
            // Which slot each class fills, so a refused parameter is named by its field.
            let classes = [
                ("motor", motor.modelica_class.clone()),
                ("gear", gear.modelica_class.clone()),
                ("controller", controller.modelica_class.clone()),
            ];
            let resolved = drives::ResolvedDrive { joint: joint.clone(), motor, gear, controller, reference: reference.clone() };
            let (plans, _) = drives::plans(&report, &[resolved]);
            if let Err(e) =
                cad2mo_engine::pipeline::back::modelica::mechatronics::mechatronics("Check", &plans, &[], Default::default(), "")
            {
                let classes: Vec<(&str, &str)> = classes.iter().map(|(s, c)| (*s, c.as_str())).collect();
                errors.push(FieldError { field: drives::generator_field(&e, &classes), message: e.to_string() });
            }
        }
    }
    if !errors.is_empty() {
        let detail = match errors.as_slice() {
            [one] => format!("the drive of joint {joint} is not valid: {}", one.message),
            many => format!("the drive of joint {joint} is not valid ({} problems)", many.len()),
        };
        return Err(ApiError::Invalid { detail, errors });
    }
    let a = Assignment {
        joint: joint.clone(),
        joint_node_id: j.node_id.clone(),
        motor_instance: body.motor_instance,
        gear_instance: body.gear_instance,
        controller_instance: body.controller_instance,
        overrides: body.overrides,
        reference,
    };
    store::drives::put(&state.store, &model_id, &a).await?;
    Ok(Json(a))
}

async fn delete(State(state): State<AppState>, Path((model_id, joint)): Path<(String, String)>) -> Result<StatusCode, ApiError> {
    if store::models::get_model(&state.store.pool, &model_id).await?.is_none() {
        return Err(ApiError::NotFound(format!("model {model_id}")));
    }
    if store::drives::delete(&state.store, &model_id, &joint).await? {
        Ok(StatusCode::NO_CONTENT)
    } else {
        Err(ApiError::NotFound(format!("drive of joint {joint}")))
    }
}
