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

use super::extract::{Path, Query};
use super::models::{invalid, multipart_error, multipart_upload, safe_file_name};
use super::ApiError;
use crate::app::AppState;
use crate::service::{self, results::ResultError, results::Stored};
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

impl From<Stored> for ResultDto {
    fn from(Stored { row: r, summary }: Stored) -> Self {
        ResultDto { id: r.id, model_id: r.model_id, version: r.version, name: r.name, size: r.size, created_at: r.created_at, summary }
    }
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

type Created = (StatusCode, [(header::HeaderName, String); 1], Json<ResultDto>);

async fn upload(
    State(state): State<AppState>,
    Path((model_id, version)): Path<(String, i64)>,
    up: ResultUpload,
) -> Result<Created, ApiError> {
    let (version, k) = super::motions::kinematic_at(&state, &model_id, Some(version)).await?;
    let stored =
        service::results::upload(&state.store, &state.blobs, Some((&model_id, version)), up.name, Vec::from(up.bytes), move |t, name| {
            results::summarise(t, &k.mech, name).map(|(summary, _)| summary)
        })
        .await?;
    Ok(created(stored))
}

/// A result of any Modelica model: read, summarised (its shapes and frames), stored.
async fn upload_standalone(State(state): State<AppState>, up: ResultUpload) -> Result<Created, ApiError> {
    let stored =
        service::results::upload(&state.store, &state.blobs, None, up.name, Vec::from(up.bytes), |t, _| Ok(results::standalone(t))).await?;
    Ok(created(stored))
}

fn created(stored: Stored) -> Created {
    let location = format!("/api/results/{}", stored.row.id);
    (StatusCode::CREATED, [(header::LOCATION, location)], Json(stored.into()))
}

async fn list_standalone(State(state): State<AppState>) -> Result<Json<Vec<ResultDto>>, ApiError> {
    Ok(Json(service::results::list_standalone(&state.store).await?.into_iter().map(ResultDto::from).collect()))
}

async fn list(State(state): State<AppState>, Path((model_id, version)): Path<(String, i64)>) -> Result<Json<Vec<ResultDto>>, ApiError> {
    Ok(Json(service::results::list(&state.store, &model_id, version).await?.into_iter().map(ResultDto::from).collect()))
}

async fn find(state: &AppState, id: &str) -> Result<store::results::ResultRow, ApiError> {
    Ok(service::results::find(&state.store, id).await?)
}

async fn get_one(State(state): State<AppState>, Path(id): Path<String>) -> Result<Json<ResultDto>, ApiError> {
    Ok(Json(Stored::try_from(find(&state, &id).await?)?.into()))
}

async fn delete(State(state): State<AppState>, Path(id): Path<String>) -> Result<StatusCode, ApiError> {
    service::results::delete(&state.store, &id).await?;
    Ok(StatusCode::NO_CONTENT)
}

/// Runs `f` on the stored file of result `row`.
async fn with_file<T: Send + 'static>(
    state: &AppState,
    row: store::results::ResultRow,
    f: impl FnOnce(&Trajectory) -> Result<T, ResultError> + Send + 'static,
) -> Result<T, ApiError> {
    Ok(service::results::with_file(&state.blobs, row, f).await?)
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
            let v = t.find(&n).ok_or_else(|| ResultError::NotFound(format!("variable \"{n}\" in the result")))?;
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
