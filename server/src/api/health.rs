//! `GET /api/health`: liveness and the converter's version.

use axum::extract::State;
use axum::routing::get;
use axum::{Json, Router};
use serde::Serialize;

use super::ApiError;
use crate::app::AppState;

#[derive(Serialize)]
struct Health {
    status: &'static str,
    version: &'static str,
}

pub fn router() -> Router<AppState> {
    Router::new().route("/api/health", get(health))
}

async fn health(State(state): State<AppState>) -> Result<Json<Health>, ApiError> {
    sqlx_ping(&state).await?;
    Ok(Json(Health { status: "ok", version: cad2mo_engine::pipeline::VERSION }))
}

async fn sqlx_ping(state: &AppState) -> Result<(), ApiError> {
    crate::store::now(&state.store.pool).await?;
    Ok(())
}
