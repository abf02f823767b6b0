//! Scenes over HTTP (issue 29): a model's scene objects, read, replaced and removed as a whole.
//! A bad scene is a 422 naming the field (`objects[2].rotation`), parse errors included.

use axum::body::Bytes;
use axum::extract::{DefaultBodyLimit, State};
use axum::http::{header, StatusCode};
use axum::response::IntoResponse;
use axum::routing::{get, put};
use axum::{Json, Router};

use super::collision::shapes;
use super::error::blocking;
use super::error::FieldError;
use super::extract::Path;
use super::motions::model_exists;
use super::ApiError;
use crate::app::AppState;
use crate::service;
use crate::store;
use cad2mo_engine::scene::mesh::MAX_MESH_BYTES;
use cad2mo_engine::scene::{Meshes, SceneSpec};

/// Largest scene body (a full pose table of 10,000 rows fits).
const SCENE_BODY_LIMIT: usize = 4 << 20;

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/scene", get(get_scene).put(put_scene).delete(delete_scene))
        .layer(DefaultBodyLimit::max(SCENE_BODY_LIMIT + 1))
        .merge(
            Router::new()
                .route("/api/models/{model_id}/scene/meshes", get(list_meshes))
                .route("/api/models/{model_id}/scene/meshes/{name}", put(put_mesh).get(get_mesh))
                .layer(DefaultBodyLimit::max(MAX_MESH_BYTES + 1)),
        )
}

/// The meshes uploaded for a model's scene, read from their blobs.
pub async fn meshes(state: &AppState, model_id: &str) -> Result<Meshes, ApiError> {
    let rows: Vec<(String, String)> =
        store::scene::meshes(&state.store, model_id).await?.into_iter().map(|r| (r.name, r.blob_sha256)).collect();
    if rows.is_empty() {
        return Ok(Meshes::new());
    }
    let blobs = state.blobs.clone();
    blocking(move || Ok(service::scene::load_meshes(&rows, |h| blobs.get(h))?)).await
}

#[derive(serde::Deserialize)]
struct MeshQuery {
    /// The uploaded file's name: its extension chooses the reader (default: `mesh.wrl` or
    /// `mesh.dae` for a body that begins like VRML or COLLADA, else `mesh.stl`).
    file: Option<String>,
}

/// One uploaded mesh as the API shows it.
#[derive(serde::Serialize)]
struct MeshView {
    name: String,
    triangles: i64,
}

async fn list_meshes(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<serde_json::Value>, ApiError> {
    model_exists(&state, &model_id).await?;
    let rows = store::scene::meshes(&state.store, &model_id).await?;
    let meshes: Vec<_> = rows.into_iter().map(|r| serde_json::json!({"name": r.name, "triangles": r.triangles})).collect();
    Ok(Json(serde_json::json!({ "meshes": meshes })))
}

/// Uploads (or replaces) a scene mesh: the body is the file (STL binary or ASCII, OBJ, COLLADA,
/// VRML), `?file=` its name (without it, the body's first bytes choose). A bad name, an unreadable or too large file: 422/413
/// naming `name` or `file`.
async fn put_mesh(
    State(state): State<AppState>,
    Path((model_id, name)): Path<(String, String)>,
    axum::extract::Query(q): axum::extract::Query<MeshQuery>,
    body: Bytes,
) -> Result<(StatusCode, Json<MeshView>), ApiError> {
    model_exists(&state, &model_id).await?;
    if body.len() > MAX_MESH_BYTES {
        return Err(ApiError::PayloadTooLarge { limit: MAX_MESH_BYTES as u64 });
    }
    let file = q.file.unwrap_or_else(|| cad2mo_engine::scene::mesh::default_file(&body).into());
    let blobs = state.blobs.clone();
    let n = name.clone();
    let (hash, triangles) = blocking(move || {
        let mesh = service::scene::read_mesh(&n, &file, &body)?;
        let hash = blobs.put(&mesh.stl).map_err(|e| ApiError::Internal(e.into()))?;
        Ok((hash, mesh.triangles))
    })
    .await?;
    store::scene::put_mesh(&state.store, &model_id, &name, &hash, triangles as i64).await?;
    Ok((StatusCode::OK, Json(MeshView { name, triangles: triangles as i64 })))
}

/// One uploaded mesh's file as stored: a binary STL in the file's own units (the 3D view draws
/// mesh objects from it). An unknown mesh: 404.
async fn get_mesh(State(state): State<AppState>, Path((model_id, name)): Path<(String, String)>) -> Result<impl IntoResponse, ApiError> {
    model_exists(&state, &model_id).await?;
    let row = store::scene::meshes(&state.store, &model_id)
        .await?
        .into_iter()
        .find(|r| r.name == name)
        .ok_or_else(|| ApiError::NotFound(format!("scene mesh {name}")))?;
    let blobs = state.blobs.clone();
    let hash = row.blob_sha256.clone();
    let bytes = blocking(move || {
        blobs
            .get(&hash)
            .map_err(|e| ApiError::Internal(e.into()))?
            .ok_or_else(|| ApiError::Internal(anyhow::anyhow!("the blob {hash} of a scene mesh is missing")))
    })
    .await?;
    Ok(([(header::CONTENT_TYPE, "model/stl".to_string()), (header::ETAG, format!("\"{}\"", row.blob_sha256))], bytes))
}

async fn get_scene(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<Json<SceneSpec>, ApiError> {
    model_exists(&state, &model_id).await?;
    Ok(Json(store::scene::get(&state.store, &model_id).await?))
}

/// The scene in a request body: JSON errors name the field they are in (`objects[0].position`).
fn parse(body: &[u8]) -> Result<SceneSpec, ApiError> {
    if body.len() > SCENE_BODY_LIMIT {
        return Err(ApiError::PayloadTooLarge { limit: SCENE_BODY_LIMIT as u64 });
    }
    let invalid = |field: String, message: String| ApiError::Invalid {
        detail: format!("the scene is not valid: {field} {message}"),
        errors: vec![FieldError { field, message }],
    };
    let v: serde_json::Value = serde_json::from_slice(body).map_err(|e| invalid("scene".into(), format!("is not JSON: {e}")))?;
    if !v.is_object() {
        return Err(invalid("scene".into(), "must be a JSON object with objects".into()));
    }
    serde_path_to_error::deserialize::<_, SceneSpec>(v).map_err(|e| {
        let field = e.path().to_string();
        invalid(if field == "." { "scene".to_string() } else { field }, e.inner().to_string())
    })
}

async fn put_scene(State(state): State<AppState>, Path(model_id): Path<String>, body: Bytes) -> Result<Json<SceneSpec>, ApiError> {
    model_exists(&state, &model_id).await?;
    let spec = parse(&body)?;
    // Names are checked against the bodies of the latest converted version.
    let (_, s) = shapes(&state, &model_id, None).await?;
    let meshes = meshes(&state, &model_id).await?;
    service::scene::check(&spec, &s.bodies[..s.model_bodies], &meshes)?;
    store::scene::put(&state.store, &model_id, &spec).await?;
    Ok(Json(store::scene::get(&state.store, &model_id).await?))
}

async fn delete_scene(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<StatusCode, ApiError> {
    model_exists(&state, &model_id).await?;
    store::scene::put(&state.store, &model_id, &SceneSpec::default()).await?;
    Ok(StatusCode::NO_CONTENT)
}
