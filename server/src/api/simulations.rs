//! Closed-loop simulations of a model's drives (issue 28):
//! `GET|POST /api/models/{model_id}/simulations`, `GET /api/models/{model_id}/simulations/{simulation_id}`.
//!
//! A run is synchronous (201 with the answer and the `result_id` of its MAT v4 result): it is
//! bounded in simulated time, steps, samples and wall-clock time (`service::simulations`), at
//! most `--workers` run at once (503 beyond), and it is cancelled when the client goes away.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

use axum::extract::rejection::JsonRejection;
use axum::extract::State;
use axum::http::{header, HeaderMap, StatusCode};
use axum::routing::get;
use axum::{Json, Router};
use serde::Deserialize;

use super::error::FieldError;
use super::extract::{Path, Query};
use super::ApiError;
use crate::app::AppState;
use crate::service::simulations::{self, Inputs, LiveTarget, SimulationRequest, SimulationView};
use crate::store;

/// Wall-clock time of one run at most.
pub const TIME_LIMIT: Duration = Duration::from_secs(30);

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/simulations", get(list).post(create))
        .route("/api/models/{model_id}/simulations/{simulation_id}", get(get_one))
}

/// Sets the run's cancel flag when the request's future is dropped (the client went away).
struct CancelOnDrop(Arc<AtomicBool>);

impl Drop for CancelOnDrop {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

type Created = (StatusCode, [(header::HeaderName, String); 1], Json<SimulationView>);

async fn create(
    State(state): State<AppState>,
    Path(model_id): Path<String>,
    headers: HeaderMap,
    b: Result<Json<serde_json::Value>, JsonRejection>,
) -> Result<Created, ApiError> {
    let req: SimulationRequest = super::motions::body("simulation request", b)?;
    simulations::check_request(&req)?;
    let (version, k) = super::motions::kinematic(&state, &model_id).await?;
    let motion = match &req.motion_id {
        None => None,
        Some(id) => match store::motions::get(&state.store, &model_id, id).await? {
            Some(m) => Some((m.name, m.spec)),
            None => {
                return Err(ApiError::Invalid {
                    detail: format!("motion_id: model {model_id} has no motion {id}"),
                    errors: vec![FieldError { field: "motion_id".into(), message: format!("model {model_id} has no motion {id}") }],
                })
            }
        },
    };
    let edits = store::motions::limits(&state.store, &model_id).await?;
    let drives = if req.drives { crate::service::drives::resolve_for_model(&state.store, &model_id).await? } else { Vec::new() };
    // The simulated motion is checked against the version's bodies and the model's scene.
    let (_, shapes, _) = super::collision::scene_shapes(&state, &model_id, Some(version)).await?;
    let collisions = Some((shapes, super::collision::edits(&state, &model_id).await?));
    let live = if req.live { Some(live_target(&state, &model_id, version, &headers).await?) } else { None };
    // A run paced to the wall clock takes its duration on top of the computing time.
    let limit = if req.live && req.live_real_time { TIME_LIMIT + Duration::from_secs_f64(req.duration) } else { TIME_LIMIT };
    let permit =
        state.simulations.clone().try_acquire_owned().map_err(|_| ApiError::SimulationsBusy { limit: state.settings.workers.max(1) })?;
    let cancel = Arc::new(AtomicBool::new(false));
    let _guard = CancelOnDrop(cancel.clone());
    let inputs = Inputs { kinematic: k.clone(), motion, edits, drives, collisions, live };
    let (req2, flag) = (req.clone(), cancel.clone());
    let ran = crate::service::blocking(move || {
        // The permit is held until the run ends, also when the client has gone.
        let _permit = permit;
        simulations::run(&req2, &inputs, &flag, limit)
    })
    .await?;
    let view = simulations::store_run(&state.store, &state.blobs, &model_id, version, &req, k, ran).await?;
    let location = format!("/api/models/{model_id}/simulations/{}", view.id);
    Ok((StatusCode::CREATED, [(header::LOCATION, location)], Json(view)))
}

/// Where a run's live frames go: the relay's port at the host packages send to, the version's
/// bodies as the relay knows them, the caller's token where frames must be signed.
async fn live_target(state: &AppState, model_id: &str, version: i64, headers: &HeaderMap) -> Result<LiveTarget, ApiError> {
    let off =
        |why: String| ApiError::Invalid { detail: format!("live: {why}"), errors: vec![FieldError { field: "live".into(), message: why }] };
    let Some(addr) = state.relay.addr() else {
        return Err(off(format!("the service's live view is off ({})", state.relay.off_reason().unwrap_or("not listening"))));
    };
    let number = u32::try_from(version).map_err(|_| off(format!("version {version} has no live view")))?;
    let bodies = state.relay.bodies(model_id, number).await?.ok_or_else(|| off(format!("version {version} has no converted report")))?;
    let model = uuid::Uuid::parse_str(model_id).map_err(|_| off(format!("model id {model_id} is not a UUID")))?;
    let token = if state.relay.requires_auth() { super::auth::bearer(headers).map(str::to_string) } else { None };
    Ok(LiveTarget {
        host: state.settings.live_host(),
        port: addr.port(),
        model: model.into_bytes(),
        version: number,
        bodies: bodies.bodies.clone(),
        token,
    })
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ListQuery {
    motion_id: Option<String>,
}

async fn list(
    State(state): State<AppState>,
    Path(model_id): Path<String>,
    Query(q): Query<ListQuery>,
) -> Result<Json<Vec<SimulationView>>, ApiError> {
    super::motions::model_exists(&state, &model_id).await?;
    Ok(Json(simulations::list(&state.store, &model_id, q.motion_id.as_deref()).await?))
}

async fn get_one(State(state): State<AppState>, Path((model_id, id)): Path<(String, String)>) -> Result<Json<SimulationView>, ApiError> {
    super::motions::model_exists(&state, &model_id).await?;
    Ok(Json(simulations::get(&state.store, &model_id, &id).await?))
}
