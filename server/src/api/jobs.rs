//! The jobs resource: `GET /api/jobs/{job_id}`, the status of a conversion (poll it after an
//! upload's 202): `{id, kind, model_id, version, status, error?, created_at, started_at,
//! finished_at}` with `status` one of `queued`, `running`, `succeeded`, `failed`, and `error` the
//! problem document of a failed job. A queued job also has `queue` (jobs ahead of it, jobs
//! running), a running one `progress` (stage, `done` of `total`, overall `fraction`).

use axum::extract::rejection::PathRejection;
use axum::extract::{Path, State};
use axum::routing::get;
use axum::{Json, Router};
use serde::Serialize;
use serde_json::Value;

use super::ApiError;
use crate::app::AppState;
use crate::jobs::JobProgress;
use crate::store::models as db;

pub fn router() -> Router<AppState> {
    Router::new().route("/api/jobs", get(list_jobs)).route("/api/jobs/{job_id}", get(get_job))
}

#[derive(Serialize)]
struct JobView {
    id: String,
    kind: String,
    model_id: String,
    version: i64,
    status: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    queue: Option<QueueView>,
    #[serde(skip_serializing_if = "Option::is_none")]
    progress: Option<JobProgress>,
    created_at: String,
    started_at: Option<String>,
    finished_at: Option<String>,
}

#[derive(Serialize)]
struct QueueView {
    /// Queued jobs that will be claimed before this one.
    ahead: i64,
    /// Jobs converting now (at most the number of workers).
    running: i64,
}

/// Jobs listed by `GET /api/jobs`.
const LISTED: i64 = 50;

#[derive(Serialize)]
struct JobList {
    /// The latest jobs, newest first.
    jobs: Vec<JobView>,
    /// Jobs quarantined for stopping the service while running alone (`conversion-aborted`).
    quarantined: Vec<JobView>,
}

/// `GET /api/jobs`: the latest jobs and the quarantined ones (a stored row that cannot be shown
/// is left out and logged, never failing the list).
async fn list_jobs(State(state): State<AppState>) -> Result<Json<JobList>, ApiError> {
    let view = |rows: Vec<db::JobRow>| {
        rows.into_iter()
            .filter_map(|job| {
                let error = match job.error_json.as_deref().map(serde_json::from_str::<Value>).transpose() {
                    Ok(e) => e,
                    Err(e) => {
                        tracing::error!(job_id = %job.id, error = %e, "stored problem is corrupt: job left out of the list");
                        return None;
                    }
                };
                Some(JobView {
                    id: job.id,
                    kind: job.kind,
                    model_id: job.model_id,
                    version: job.version,
                    status: job.status,
                    error,
                    queue: None,
                    progress: None,
                    created_at: job.created_at,
                    started_at: job.started_at,
                    finished_at: job.finished_at,
                })
            })
            .collect()
    };
    let jobs = view(db::recent_jobs(&state.store.pool, LISTED).await?);
    let quarantined = view(db::quarantined_jobs(&state.store.pool, crate::jobs::MAX_ABORTS, LISTED).await?);
    Ok(Json(JobList { jobs, quarantined }))
}

async fn get_job(State(state): State<AppState>, path: Result<Path<String>, PathRejection>) -> Result<Json<JobView>, ApiError> {
    let Path(id) = path.map_err(|e| ApiError::BadRequest(e.body_text()))?;
    let job = db::get_job(&state.store.pool, &id).await?.ok_or_else(|| ApiError::NotFound(format!("job {id}")))?;
    let error = job
        .error_json
        .as_deref()
        .map(serde_json::from_str)
        .transpose()
        .map_err(|e| ApiError::Internal(anyhow::anyhow!("stored problem is corrupt: {e}")))?;
    let queue = match job.status.as_str() {
        "queued" => db::queue_position(&state.store.pool, &job.id).await?.map(|(ahead, running)| QueueView { ahead, running }),
        _ => None,
    };
    // This instance's own running jobs from memory; another instance's from the progress it wrote.
    let progress = if job.status == "running" {
        state.jobs.progress(&job.id).or_else(|| job.progress_json.as_deref().and_then(JobProgress::from_json))
    } else {
        None
    };
    Ok(Json(JobView {
        id: job.id,
        kind: job.kind,
        model_id: job.model_id,
        version: job.version,
        status: job.status,
        error,
        queue,
        progress,
        created_at: job.created_at,
        started_at: job.started_at,
        finished_at: job.finished_at,
    }))
}
