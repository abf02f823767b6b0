//! `GET /openapi.yaml`: the HTTP contract (the workspace's `openapi.yaml`, embedded at build
//! time). Public, like the health check; `tests/openapi.rs` keeps it in step with the routes.

use axum::http::header;
use axum::response::IntoResponse;
use axum::routing::get;
use axum::Router;

use crate::app::AppState;

/// The document, as in the repository.
pub const SPEC: &str = include_str!("../../../openapi.yaml");

pub fn router() -> Router<AppState> {
    Router::new().route("/openapi.yaml", get(spec))
}

async fn spec() -> impl IntoResponse {
    ([(header::CONTENT_TYPE, "application/yaml")], SPEC)
}
