//! Joint limits, motions, trajectories, live inverse kinematics and sizing of a model:
//! `GET /api/models/{model_id}/joints`, `PUT|DELETE .../joints/{joint}/limits`,
//! `GET|POST .../motions`, `GET|PUT|DELETE .../motions/{motion_id}`,
//! `GET .../motions/{motion_id}/trajectory?rate=`, `GET .../motions/{motion_id}/sizing`,
//! `POST .../ik`.
//!
//! Everything is computed on the latest converted version (as drives are); limits and motions
//! belong to the model and name joints by their stable Modelica names, so they survive CAD
//! changes (a motion naming a joint that vanished gets a 422 naming the keyframe and joint).

use std::collections::BTreeMap;
use std::sync::Arc;

use axum::extract::rejection::JsonRejection;
use axum::extract::State;
use axum::http::StatusCode;
use axum::routing::{get, post, put};
use axum::{Json, Router};
use serde::{Deserialize, Serialize};

use super::error::blocking;
use super::extract::{Path, Query};
use super::ApiError;
use crate::app::AppState;
use crate::service::export::ExportOptions;
use crate::service::motions::{self, Kinematic};
use crate::store;
use cad2mo_engine::motion::plan::{self, LimitsEdit, MotionSpec};

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/joints", get(joints))
        .route("/api/models/{model_id}/joints/{joint}/limits", put(put_limits).delete(delete_limits))
        .route("/api/models/{model_id}/motions", get(list).post(create))
        .route("/api/models/{model_id}/motions/{motion_id}", get(get_one).put(update).delete(delete))
        .route("/api/models/{model_id}/motions/{motion_id}/trajectory", get(trajectory))
        .route("/api/models/{model_id}/motions/{motion_id}/sizing", get(sizing))
        .route("/api/models/{model_id}/ik", post(ik))
}

pub(super) async fn model_exists(state: &AppState, model_id: &str) -> Result<(), ApiError> {
    match store::models::get_model(&state.store.pool, model_id).await? {
        Some(_) => Ok(()),
        None => Err(ApiError::NotFound(format!("model {model_id}"))),
    }
}

/// The latest converted version of a model, analysed (cached by its bundle, options and report).
pub(super) async fn kinematic(state: &AppState, model_id: &str) -> Result<(i64, Arc<Kinematic>), ApiError> {
    kinematic_at(state, model_id, None).await
}

/// A converted version of a model (`None`: the latest converted one): 404 for an unknown model
/// or version, 409 while it converts or when none has converted (`lacking` says what is unknown
/// then, e.g. "its joints are unknown").
pub(super) async fn converted_version(
    state: &AppState,
    model_id: &str,
    version: Option<i64>,
    lacking: &str,
) -> Result<store::models::VersionRow, ApiError> {
    model_exists(state, model_id).await?;
    let versions = store::models::list_versions(&state.store.pool, model_id).await?;
    let v = match version {
        None => versions.into_iter().filter(|v| v.report_sha256.is_some()).max_by_key(|v| v.version),
        Some(n) => {
            let v = versions
                .into_iter()
                .find(|v| v.version == n)
                .ok_or_else(|| ApiError::NotFound(format!("version {n} of model {model_id}")))?;
            if v.report_sha256.is_none() {
                return Err(ApiError::Conflict(format!("version {n} of model {model_id} is not converted (yet)")));
            }
            Some(v)
        }
    };
    v.ok_or_else(|| ApiError::Conflict(format!("model {model_id} has no converted version yet: {lacking}")))
}

/// [`kinematic`] of a given version (`None`: the latest converted one); 404 for an unknown
/// version, 409 while it converts.
pub(super) async fn kinematic_at(state: &AppState, model_id: &str, version: Option<i64>) -> Result<(i64, Arc<Kinematic>), ApiError> {
    let v = converted_version(state, model_id, version, "its joints are unknown").await?;
    let report_sha = v.report_sha256.clone().unwrap_or_default();
    let key = format!("{}/{}/{}", v.bundle_sha256, report_sha, v.options_json);
    if let Some(k) = state.kinematics.get(&key) {
        return Ok((v.version, k));
    }
    let (blobs, bundle_sha, bundle_name, options_json, version) =
        (state.blobs.clone(), v.bundle_sha256.clone(), v.bundle_name.clone(), v.options_json.clone(), v.version);
    let k = blocking(move || {
        let missing = |what: &str| ApiError::Internal(anyhow::anyhow!("{what} of version {version} is missing"));
        let bundle = blobs.get(&bundle_sha).map_err(|e| ApiError::Internal(e.into()))?.ok_or_else(|| missing("bundle"))?;
        let report = blobs.get(&report_sha).map_err(|e| ApiError::Internal(e.into()))?.ok_or_else(|| missing("report"))?;
        let report: serde_json::Value = serde_json::from_slice(&report).map_err(|e| ApiError::Internal(e.into()))?;
        let options: ExportOptions =
            serde_json::from_str(&options_json).map_err(|e| ApiError::Internal(anyhow::anyhow!("stored options: {e}")))?;
        Ok(Kinematic::load(&bundle, &bundle_name, &options, &report)?)
    })
    .await?;
    let k = Arc::new(k);
    state.kinematics.put(key, k.clone());
    Ok((v.version, k))
}

async fn joints(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<motions::JointsView>, ApiError> {
    let (version, k) = kinematic(&state, &model_id).await?;
    let edits = store::motions::limits(&state.store, &model_id).await?;
    Ok(Json(motions::joints_view(&k, version, &edits)))
}

/// axum's default limit on a JSON body (2 MiB), which these routes keep.
const JSON_BODY_LIMIT: u64 = 2 << 20;

/// A JSON object body as `T` (serde would also take an array for a struct: refused here).
pub(super) fn body<T: serde::de::DeserializeOwned>(what: &str, b: Result<Json<serde_json::Value>, JsonRejection>) -> Result<T, ApiError> {
    let v = b.map(|Json(v)| v).map_err(|e| {
        if e.status() == axum::http::StatusCode::PAYLOAD_TOO_LARGE {
            ApiError::PayloadTooLarge { limit: JSON_BODY_LIMIT }
        } else {
            ApiError::BadRequest(format!("invalid {what}: {}", e.body_text()))
        }
    })?;
    if !v.is_object() {
        return Err(ApiError::BadRequest(format!("invalid {what}: expected a JSON object")));
    }
    serde_json::from_value(v).map_err(|e| ApiError::BadRequest(format!("invalid {what}: {e}")))
}

fn issues_invalid(what: String, issues: Vec<cad2mo_engine::library::Issue>) -> ApiError {
    let detail = match issues.first() {
        Some(i) => format!("{what}: {} {}", i.field, i.message),
        None => what,
    };
    ApiError::Invalid {
        detail,
        errors: issues.into_iter().map(|i| super::error::FieldError { field: i.field, message: i.message }).collect(),
    }
}

async fn put_limits(
    State(state): State<AppState>,
    Path((model_id, joint)): Path<(String, String)>,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<Json<motions::JointView>, ApiError> {
    let edit: LimitsEdit = body("joint limits", b)?;
    let (version, k) = kinematic(&state, &model_id).await?;
    let Some(c) = k.mech.coordinates().iter().find(|c| c.name == joint) else {
        let names: Vec<&str> = k.mech.coordinates().iter().map(|c| c.name.as_str()).collect();
        return Err(ApiError::NotFound(format!("joint {joint} in version {version} (its joints are: {})", names.join(", "))));
    };
    let mut issues = edit.check();
    if let Some([lo, hi]) = edit.position {
        if issues.is_empty() && !(lo..=hi).contains(&c.q0) {
            issues.push(cad2mo_engine::library::Issue::new(
                "position",
                format!("the range [{lo}, {hi}] must contain the CAD pose {} (the motion's start)", c.q0),
            ));
        }
    }
    if !issues.is_empty() {
        return Err(issues_invalid(format!("the limits of joint {joint} are not valid"), issues));
    }
    store::motions::put_limits(&state.store, &model_id, &joint, &edit).await?;
    let edits = store::motions::limits(&state.store, &model_id).await?;
    let view = motions::joints_view(&k, version, &edits);
    view.joints.into_iter().find(|j| j.name == joint).map(Json).ok_or_else(|| ApiError::Internal(anyhow::anyhow!("joint {joint} vanished")))
}

async fn delete_limits(State(state): State<AppState>, Path((model_id, joint)): Path<(String, String)>) -> Result<StatusCode, ApiError> {
    model_exists(&state, &model_id).await?;
    if store::motions::delete_limits(&state.store, &model_id, &joint).await? {
        Ok(StatusCode::NO_CONTENT)
    } else {
        Err(ApiError::NotFound(format!("limits of joint {joint}")))
    }
}

fn check_form(spec: &MotionSpec) -> Result<(), ApiError> {
    let issues = plan::check_spec(spec);
    if issues.is_empty() {
        Ok(())
    } else {
        Err(issues_invalid(format!("motion \"{}\" is not valid", spec.name), issues))
    }
}

async fn list(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<Vec<store::motions::Motion>>, ApiError> {
    model_exists(&state, &model_id).await?;
    let all = store::motions::list(&state.store, &model_id).await?;
    Ok(Json(all))
}

async fn create(
    State(state): State<AppState>,
    Path(model_id): Path<String>,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<(StatusCode, Json<store::motions::Motion>), ApiError> {
    let spec: MotionSpec = body("motion", b)?;
    model_exists(&state, &model_id).await?;
    check_form(&spec)?;
    let motion = store::motions::create(&state.store, &model_id, &spec).await.map_err(|e| name_taken(e, &model_id, &spec))?;
    Ok((StatusCode::CREATED, Json(motion)))
}

/// A store error, the unique name saying which name is taken.
fn name_taken(e: store::StoreError, model_id: &str, spec: &MotionSpec) -> ApiError {
    if e.is_unique_violation() {
        ApiError::Conflict(format!("model {model_id} already has a motion named \"{}\"", spec.name))
    } else {
        e.into()
    }
}

pub(super) async fn find(state: &AppState, model_id: &str, motion_id: &str) -> Result<store::motions::Motion, ApiError> {
    model_exists(state, model_id).await?;
    store::motions::get(&state.store, model_id, motion_id).await?.ok_or_else(|| ApiError::NotFound(format!("motion {motion_id}")))
}

async fn get_one(
    State(state): State<AppState>,
    Path((model_id, motion_id)): Path<(String, String)>,
) -> Result<Json<store::motions::Motion>, ApiError> {
    Ok(Json(find(&state, &model_id, &motion_id).await?))
}

async fn update(
    State(state): State<AppState>,
    Path((model_id, motion_id)): Path<(String, String)>,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<Json<store::motions::Motion>, ApiError> {
    let spec: MotionSpec = body("motion", b)?;
    model_exists(&state, &model_id).await?;
    check_form(&spec)?;
    let motion = store::motions::update(&state.store, &model_id, &motion_id, &spec)
        .await
        .map_err(|e| name_taken(e, &model_id, &spec))?
        .ok_or_else(|| ApiError::NotFound(format!("motion {motion_id}")))?;
    Ok(Json(motion))
}

async fn delete(State(state): State<AppState>, Path((model_id, motion_id)): Path<(String, String)>) -> Result<StatusCode, ApiError> {
    model_exists(&state, &model_id).await?;
    if store::motions::delete(&state.store, &model_id, &motion_id).await? {
        Ok(StatusCode::NO_CONTENT)
    } else {
        Err(ApiError::NotFound(format!("motion {motion_id}")))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RateQuery {
    rate: Option<f64>,
}

async fn trajectory(
    State(state): State<AppState>,
    Path((model_id, motion_id)): Path<(String, String)>,
    Query(q): Query<RateQuery>,
) -> Result<Json<motions::TrajectoryView>, ApiError> {
    let m = find(&state, &model_id, &motion_id).await?;
    let (version, k) = kinematic(&state, &model_id).await?;
    let edits = store::motions::limits(&state.store, &model_id).await?;
    let rate = q.rate.unwrap_or(100.0);
    let view = blocking(move || {
        let p = motions::plan_motion(&k, &edits, &m.spec)?;
        Ok(motions::trajectory(&k, version, &m.name, &p, rate)?)
    })
    .await?;
    Ok(Json(view))
}

/// `?reserve=&dwell=&amplifier=&supply_voltage=&brake_power=&bus_capacitance=&bus_voltage_max=&screw_life=`
/// (each optional; see `motions::SizingRequest`).
async fn sizing(
    State(state): State<AppState>,
    Path((model_id, motion_id)): Path<(String, String)>,
    Query(q): Query<motions::SizingRequest>,
) -> Result<Json<motions::SizingReport>, ApiError> {
    let m = find(&state, &model_id, &motion_id).await?;
    let library = store::library::export(&state.store).await?;
    let settings = motions::sizing_settings(&q, &library)?;
    let (version, k) = kinematic(&state, &model_id).await?;
    let edits = store::motions::limits(&state.store, &model_id).await?;
    let drives = motions::drive_parts(&state.store, &model_id).await?;
    let report = blocking(move || {
        let catalog = cad2mo_engine::sizing::Catalog::from_library(&library);
        let p = motions::plan_motion(&k, &edits, &m.spec)?;
        Ok(motions::sizing(&k.mech, &k.gravity, version, &m.name, &p, &drives, &catalog, &settings)?)
    })
    .await?;
    Ok(Json(report))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct IkBody {
    frame: String,
    position: [f64; 3],
    #[serde(default)]
    rotation: Option<[[f64; 3]; 3]>,
    #[serde(default)]
    seed: BTreeMap<String, f64>,
}

/// The farthest IK target from the world origin on any axis, m: the errors of a solution stay
/// finite numbers (the schema's `position_error` is a number, never null).
const MAX_IK_POSITION: f64 = 1e6;

#[derive(Serialize)]
struct IkDto {
    success: bool,
    q: BTreeMap<String, f64>,
    iterations: usize,
    position_error: f64,
    rotation_error: f64,
}

async fn ik(
    State(state): State<AppState>,
    Path(model_id): Path<String>,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<Json<IkDto>, ApiError> {
    let b: IkBody = body("inverse kinematics request", b)?;
    let (_, k) = kinematic(&state, &model_id).await?;
    let edits = store::motions::limits(&state.store, &model_id).await?;
    let out = blocking(move || {
        let axes = plan::axes(&k.mech, &edits);
        let mut issues = Vec::new();
        if b.position.iter().any(|v| !(v.is_finite() && v.abs() <= MAX_IK_POSITION)) {
            issues.push(cad2mo_engine::library::Issue::new("position", format!("must be 3 finite numbers within ±{MAX_IK_POSITION} m")));
        }
        let target = plan::ik_target(&b.position, &b.rotation);
        if target.is_none() {
            issues.push(cad2mo_engine::library::Issue::new(
                "rotation",
                "must be a rotation matrix (orthonormal to 1e-6, determinant +1), rows first",
            ));
        }
        let mut seed: Vec<f64> = axes.iter().map(|a| a.q0).collect();
        for (name, v) in &b.seed {
            match axes.iter().position(|a| &a.name == name) {
                Some(i) if v.is_finite() => seed[i] = v.clamp(axes[i].limits.position[0], axes[i].limits.position[1]),
                Some(_) => issues.push(cad2mo_engine::library::Issue::new(format!("seed.{name}"), "must be a finite number")),
                None => issues.push(cad2mo_engine::library::Issue::new(format!("seed.{name}"), "is not a joint of the model")),
            }
        }
        let (Some(target), true) = (target, issues.is_empty()) else {
            return Err(issues_invalid("the inverse kinematics request is not valid".into(), issues));
        };
        let (q, r, success) = plan::solve_tool(&k.mech, &axes, &b.frame, &target, &seed).map_err(|e| {
            issues_invalid("the inverse kinematics request is not valid".into(), vec![cad2mo_engine::library::Issue::new("frame", e)])
        })?;
        if !(r.position_error.is_finite() && r.rotation_error.is_finite()) {
            return Err(issues_invalid(
                "the inverse kinematics request is not valid".into(),
                vec![cad2mo_engine::library::Issue::new("position", "the solution's error is not finite (the target is out of any reach)")],
            ));
        }
        Ok(IkDto {
            success,
            q: axes.iter().zip(q).map(|(a, v)| (a.name.clone(), v)).collect(),
            iterations: r.iterations,
            position_error: r.position_error,
            rotation_error: r.rotation_error,
        })
    })
    .await?;
    Ok(Json(out))
}
