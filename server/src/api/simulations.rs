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
use axum::http::{header, StatusCode};
use axum::routing::get;
use axum::{Json, Router};
use serde::Deserialize;

use super::error::FieldError;
use super::extract::{Path, Query};
use super::ApiError;
use crate::app::AppState;
use crate::service::simulations::{self, Inputs, SimulationRequest, SimulationView};
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
    let permit =
        state.simulations.clone().try_acquire_owned().map_err(|_| ApiError::SimulationsBusy { limit: state.settings.workers.max(1) })?;
    let cancel = Arc::new(AtomicBool::new(false));
    let _guard = CancelOnDrop(cancel.clone());
    let inputs = Inputs { kinematic: k.clone(), motion, edits, drives };
    let (req2, flag) = (req.clone(), cancel.clone());
    let ran = crate::service::blocking(move || {
        // The permit is held until the run ends, also when the client has gone.
        let _permit = permit;
        simulations::run(&req2, &inputs, &flag, TIME_LIMIT)
    })
    .await?;
    let view = simulations::store_run(&state.store, &state.blobs, &model_id, version, &req, k, ran).await?;
    let location = format!("/api/models/{model_id}/simulations/{}", view.id);
    Ok((StatusCode::CREATED, [(header::LOCATION, location)], Json(view)))
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
