//! Simulation results of a model version (issue 13):
//! `GET|POST /api/models/{model_id}/versions/{version}/results`,
//! `GET|DELETE /api/results/{result_id}`, `GET /api/results/{result_id}/variables?search=&limit=`,
//! `GET /api/results/{result_id}/series?name=..&width=`, `GET /api/results/{result_id}/poses`.
//!
//! An upload is read completely before anything is stored: a file that is not a MAT v4
//! trajectory, is truncated, or matches none of the version's bodies and joints is a 422 naming
//! the file; beyond `--max-upload` a 413.

use axum::body::Bytes;
use axum::extract::{FromRequest, Request, State};
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Json, Router};
use serde::{Deserialize, Serialize};

use super::error::{blocking, FieldError};
use super::extract::{Path, Query};
use super::models::{invalid, multipart_error, multipart_upload, safe_file_name};
use super::ApiError;
use crate::app::AppState;
use crate::store;
use cad2mo_engine::results::{self, mat::Trajectory};

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/versions/{version}/results", get(list).post(upload))
        .route("/api/results", get(list_standalone).post(upload_standalone))
        .route("/api/results/{result_id}", get(get_one).delete(delete))
        .route("/api/results/{result_id}/shapes", get(shapes))
        .route("/api/results/{result_id}/shape-poses", get(shape_poses))
        .route("/api/results/{result_id}/variables", get(variables))
        .route("/api/results/{result_id}/series", get(series))
        .route("/api/results/{result_id}/poses", get(poses))
}

#[derive(Serialize)]
struct ResultDto {
    id: String,
    /// `None` for a standalone result.
    model_id: Option<String>,
    version: Option<i64>,
    name: String,
    size: i64,
    created_at: String,
    #[serde(flatten)]
    summary: results::Summary,
}

fn dto(r: store::results::ResultRow) -> Result<ResultDto, ApiError> {
    let summary: results::Summary =
        serde_json::from_str(&r.summary_json).map_err(|e| ApiError::Internal(anyhow::anyhow!("summary of result {}: {e}", r.id)))?;
    Ok(ResultDto { id: r.id, model_id: r.model_id, version: r.version, name: r.name, size: r.size, created_at: r.created_at, summary })
}

/// The uploaded file: multipart part `file`, optional `name`.
struct ResultUpload {
    bytes: Bytes,
    name: String,
}

impl FromRequest<AppState> for ResultUpload {
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &AppState) -> Result<Self, ApiError> {
        let (mut multipart, limit) = multipart_upload(req, state, "file").await?;
        let (mut file, mut name): (Option<(Bytes, String)>, Option<String>) = (None, None);
        while let Some(field) = multipart.next_field().await.map_err(|e| multipart_error(e, limit))? {
            let part = field.name().unwrap_or_default().to_string();
            match part.as_str() {
                "file" if file.is_none() => {
                    let file_name = safe_file_name(field.file_name().unwrap_or_default());
                    let bytes = field.bytes().await.map_err(|e| multipart_error(e, limit))?;
                    file = Some((bytes, file_name));
                }
                "name" if name.is_none() => {
                    let text = field.text().await.map_err(|e| multipart_error(e, limit))?;
                    let text = text.trim();
                    if text.chars().count() > 200 || text.chars().any(char::is_control) {
                        return Err(invalid("name", "at most 200 characters, no control characters"));
                    }
                    if !text.is_empty() {
                        name = Some(text.to_string());
                    }
                }
                "file" | "name" => return Err(invalid(&part, "given more than once")),
                _ => return Err(invalid(&part, "unknown part (expected file, name)")),
            }
        }
        let Some((bytes, file_name)) = file else {
            return Err(invalid("file", "missing: upload the result file (.mat) as the part `file`"));
        };
        Ok(ResultUpload { bytes, name: name.unwrap_or(file_name) })
    }
}

fn unreadable(name: &str, message: String) -> ApiError {
    ApiError::Invalid { detail: message.clone(), errors: vec![FieldError { field: "file".into(), message: format!("{name}: {message}") }] }
}

type Created = (StatusCode, [(header::HeaderName, String); 1], Json<ResultDto>);

async fn upload(
    State(state): State<AppState>,
    Path((model_id, version)): Path<(String, i64)>,
    up: ResultUpload,
) -> Result<Created, ApiError> {
    let (version, k) = super::motions::kinematic_at(&state, &model_id, Some(version)).await?;
    store_upload(&state, up, Some((&model_id, version)), move |t, name| {
        results::summarise(t, &k.mech, name).map(|(summary, _)| summary).map_err(|m| unreadable(name, m))
    })
    .await
}

/// A result of any Modelica model: read, summarised (its shapes and frames), stored.
async fn upload_standalone(State(state): State<AppState>, up: ResultUpload) -> Result<Created, ApiError> {
    store_upload(&state, up, None, |t, _| Ok(results::standalone(t))).await
}

/// Reads an upload (a 422 naming the file when it is not a result), summarises it with
/// `summarise`, then stores the file and its row: nothing is stored for a refused file.
async fn store_upload(
    state: &AppState,
    up: ResultUpload,
    owner: Option<(&str, i64)>,
    summarise: impl FnOnce(&Trajectory, &str) -> Result<results::Summary, ApiError> + Send + 'static,
) -> Result<Created, ApiError> {
    let (name, bytes) = (up.name.clone(), up.bytes.clone());
    let summary = blocking(move || {
        let t = Trajectory::read(&bytes, &name).map_err(|e| unreadable(&name, e.to_string()))?;
        t.check_finite(&name).map_err(|e| unreadable(&name, e.to_string()))?;
        summarise(&t, &name)
    })
    .await?;
    let (blobs, bytes) = (state.blobs.clone(), up.bytes.clone());
    let sha = blocking(move || blobs.put(&bytes).map_err(|e| ApiError::Internal(e.into()))).await?;
    let summary_json = serde_json::to_string(&summary).map_err(|e| ApiError::Internal(e.into()))?;
    // Stored only when it reads back (a summary that cannot be served is never stored).
    serde_json::from_str::<results::Summary>(&summary_json)
        .map_err(|e| ApiError::Internal(anyhow::anyhow!("summary of {}: {e}", up.name)))?;
    let (model_id, version) = (owner.map(|o| o.0), owner.map(|o| o.1));
    let row = store::results::insert(&state.store, model_id, version, &up.name, up.bytes.len() as i64, &sha, &summary_json).await?;
    let location = format!("/api/results/{}", row.id);
    Ok((StatusCode::CREATED, [(header::LOCATION, location)], Json(dto(row)?)))
}

/// The rows that can be served: one stored before its summary was checked and that no longer
/// reads is left out of the list (logged with its id; it answers alone at its own URL and can
/// be deleted), never failing the list for everyone.
fn servable(rows: Vec<store::results::ResultRow>) -> Vec<ResultDto> {
    rows.into_iter()
        .filter_map(|r| {
            let id = r.id.clone();
            dto(r).map_err(|e| tracing::warn!(result = %id, error = %e, "a stored result cannot be listed")).ok()
        })
        .collect()
}

async fn list_standalone(State(state): State<AppState>) -> Result<Json<Vec<ResultDto>>, ApiError> {
    let rows = store::results::list_standalone(&state.store).await?;
    Ok(Json(servable(rows)))
}

async fn list(State(state): State<AppState>, Path((model_id, version)): Path<(String, i64)>) -> Result<Json<Vec<ResultDto>>, ApiError> {
    let versions = store::models::list_versions(&state.store.pool, &model_id).await?;
    if !versions.iter().any(|v| v.version == version) {
        return Err(ApiError::NotFound(format!("version {version} of model {model_id}")));
    }
    let rows = store::results::list(&state.store, &model_id, version).await?;
    Ok(Json(servable(rows)))
}

async fn find(state: &AppState, id: &str) -> Result<store::results::ResultRow, ApiError> {
    store::results::get(&state.store, id).await?.ok_or_else(|| ApiError::NotFound(format!("result {id}")))
}

async fn get_one(State(state): State<AppState>, Path(id): Path<String>) -> Result<Json<ResultDto>, ApiError> {
    Ok(Json(dto(find(&state, &id).await?)?))
}

async fn delete(State(state): State<AppState>, Path(id): Path<String>) -> Result<StatusCode, ApiError> {
    if store::results::delete(&state.store, &id).await? {
        Ok(StatusCode::NO_CONTENT)
    } else {
        Err(ApiError::NotFound(format!("result {id}")))
    }
}

/// Runs `f` on the stored file of result `row`.
async fn with_file<T: Send + 'static>(
    state: &AppState,
    row: store::results::ResultRow,
    f: impl FnOnce(&Trajectory) -> Result<T, ApiError> + Send + 'static,
) -> Result<T, ApiError> {
    let blobs = state.blobs.clone();
    blocking(move || {
        let bytes = blobs
            .get(&row.blob_sha256)
            .map_err(|e| ApiError::Internal(e.into()))?
            .ok_or_else(|| ApiError::Internal(anyhow::anyhow!("the file of result {} is missing", row.id)))?;
        let t = Trajectory::read(&bytes, &row.name).map_err(|e| ApiError::Internal(anyhow::anyhow!("stored result: {e}")))?;
        f(&t)
    })
    .await
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct VariablesQuery {
    search: Option<String>,
    limit: Option<usize>,
}

#[derive(Serialize)]
struct VariablesDto {
    total: usize,
    variables: Vec<results::VariableInfo>,
}

async fn variables(
    State(state): State<AppState>,
    Path(id): Path<String>,
    Query(q): Query<VariablesQuery>,
) -> Result<Json<VariablesDto>, ApiError> {
    let limit = q.limit.unwrap_or(200);
    if !(1..=1000).contains(&limit) {
        return Err(ApiError::BadRequest(format!("limit must be between 1 and 1000 (is {limit})")));
    }
    let row = find(&state, &id).await?;
    let search = q.search.unwrap_or_default();
    let (total, variables) = with_file(&state, row, move |t| Ok(results::search(t, &search, limit))).await?;
    Ok(Json(VariablesDto { total, variables }))
}

#[derive(Serialize)]
struct SeriesDto {
    name: String,
    unit: String,
    t: Vec<f64>,
    y: Vec<f64>,
}

#[derive(Serialize)]
struct SeriesList {
    variables: Vec<SeriesDto>,
}

/// `?name=a&name=b&width=800`: repeated `name`s, parsed from the raw query.
async fn series(State(state): State<AppState>, Path(id): Path<String>, uri: axum::http::Uri) -> Result<Json<SeriesList>, ApiError> {
    let mut names = Vec::new();
    let mut width = 1000usize;
    for (k, v) in url_pairs(uri.query().unwrap_or_default()) {
        match k.as_str() {
            "name" => names.push(v),
            "width" => {
                width = v.parse().ok().filter(|w| (10..=10_000).contains(w)).ok_or_else(|| {
                    ApiError::BadRequest(format!("width must be a whole number of pixels between 10 and 10000 (is \"{v}\")"))
                })?
            }
            other => return Err(ApiError::BadRequest(format!("unknown query parameter \"{other}\" (expected name, width)"))),
        }
    }
    if names.is_empty() || names.len() > 50 {
        return Err(ApiError::BadRequest("give 1 to 50 variables as name=...".into()));
    }
    let row = find(&state, &id).await?;
    let out = with_file(&state, row, move |t| {
        let time = t.time();
        let mut list = Vec::with_capacity(names.len());
        for n in names {
            let v = t.find(&n).ok_or_else(|| ApiError::NotFound(format!("variable \"{n}\" in the result")))?;
            let (dt, dy) = results::decimate(&time, &t.series(v), width);
            let unit = t.variables[v].unit().to_string();
            list.push(SeriesDto { name: t.variables[v].name.clone(), unit, t: dt, y: dy });
        }
        Ok(list)
    })
    .await?;
    Ok(Json(SeriesList { variables: out }))
}

/// `k=v` pairs of a query string, percent-decoded (`+` is a space).
fn url_pairs(q: &str) -> Vec<(String, String)> {
    form_urlencoded::parse(q.as_bytes()).map(|(k, v)| (k.into_owned(), v.into_owned())).collect()
}

async fn poses(State(state): State<AppState>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let row = find(&state, &id).await?;
    let (Some(model_id), Some(version)) = (row.model_id.clone(), row.version) else {
        return Err(ApiError::Conflict(format!("result {id} belongs to no model: its bodies are unknown (see /shapes and /shape-poses)")));
    };
    let (_, k) = super::motions::kinematic_at(&state, &model_id, Some(version)).await?;
    let bytes = with_file(&state, row, move |t| Ok(results::poses::stream(&results::poses::extract(t, &k.mech)))).await?;
    Ok(([(header::CONTENT_TYPE, "application/octet-stream")], bytes).into_response())
}

#[derive(Serialize)]
struct ShapesDto {
    shapes: Vec<results::shapes::Shape>,
    frames: Vec<String>,
}

async fn shapes(State(state): State<AppState>, Path(id): Path<String>) -> Result<Json<ShapesDto>, ApiError> {
    let row = find(&state, &id).await?;
    let out = with_file(&state, row, |t| {
        let s = results::shapes::Scene::find(t);
        Ok(ShapesDto { shapes: s.shapes, frames: s.frames })
    })
    .await?;
    Ok(Json(out))
}

async fn shape_poses(State(state): State<AppState>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let row = find(&state, &id).await?;
    let bytes = with_file(&state, row, |t| Ok(results::shapes::Scene::find(t).stream(t))).await?;
    Ok(([(header::CONTENT_TYPE, "application/octet-stream")], bytes).into_response())
}
