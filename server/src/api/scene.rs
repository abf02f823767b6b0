//! Scenes over HTTP (issue 29): a model's scene objects, read, replaced and removed as a whole.
//! A bad scene is a 422 naming the field (`objects[2].rotation`), parse errors included.

use axum::body::Bytes;
use axum::extract::{DefaultBodyLimit, State};
use axum::http::StatusCode;
use axum::routing::get;
use axum::{Json, Router};

use super::collision::shapes;
use super::error::FieldError;
use super::extract::Path;
use super::motions::model_exists;
use super::ApiError;
use crate::app::AppState;
use crate::service;
use crate::store;
use cad2mo_engine::scene::SceneSpec;

/// Largest scene body (a full pose table of 10,000 rows fits).
const SCENE_BODY_LIMIT: usize = 4 << 20;

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models/{model_id}/scene", get(get_scene).put(put_scene).delete(delete_scene))
        .layer(DefaultBodyLimit::max(SCENE_BODY_LIMIT + 1))
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
    service::scene::check(&spec, &s.bodies[..s.model_bodies])?;
    store::scene::put(&state.store, &model_id, &spec).await?;
    Ok(Json(store::scene::get(&state.store, &model_id).await?))
}

async fn delete_scene(State(state): State<AppState>, Path(model_id): Path<String>) -> Result<StatusCode, ApiError> {
    model_exists(&state, &model_id).await?;
    store::scene::put(&state.store, &model_id, &SceneSpec::default()).await?;
    Ok(StatusCode::NO_CONTENT)
}
