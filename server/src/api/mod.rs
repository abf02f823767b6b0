//! The HTTP API: the only module that knows HTTP. Each resource module owns its `router()`;
//! they are merged here in reading order. DTOs are private to their modules, never IR types.

mod auth;
mod cache;
mod collision;
mod drives;
pub mod error;
mod extract;
mod guard;
mod health;
mod jobs;
mod library;
mod live;
mod models;
mod motions;
mod openapi;
mod results;
mod scene;
pub mod serve;
mod simulations;
mod web;

use axum::Router;

pub use error::ApiError;

use crate::app::AppState;

/// Every route of the service.
pub fn router(state: AppState) -> Router {
    Router::new()
        .merge(health::router())
        .merge(openapi::router())
        .merge(models::router())
        .merge(jobs::router())
        .merge(library::router())
        .merge(drives::router())
        .merge(motions::router())
        .merge(results::router())
        .merge(simulations::router())
        .merge(live::router())
        .merge(collision::router())
        .merge(scene::router())
        .merge(web::router())
        .layer(axum::middleware::from_fn_with_state(cache::LibraryCache::default(), cache::library_cache))
        .layer(axum::middleware::from_fn_with_state(
            auth::Guard { hosts: guard::Hosts::new(state.addr, &state.settings.allowed_hosts), state: state.clone() },
            auth::guard,
        ))
        .with_state(state)
}
