//! Bearer-token authentication. When the service listens beyond loopback (or with
//! `--require-auth`), every request needs `Authorization: Bearer <token>` except the health check,
//! the OpenAPI document, the browser UI's static files and reads of the motor library.

use axum::extract::{Request, State};
use axum::http::{header, Method};
use axum::middleware::Next;
use axum::response::Response;

use super::ApiError;
use crate::app::AppState;

fn is_public(method: &Method, path: &str) -> bool {
    let read = method == Method::GET || method == Method::HEAD;
    path == "/api/health" || path == "/openapi.yaml" || !path.starts_with("/api/") || (read && path.starts_with("/api/library/"))
}

pub async fn require_token(State(state): State<AppState>, req: Request, next: Next) -> Result<Response, ApiError> {
    if !state.settings.requires_auth() || is_public(req.method(), req.uri().path()) {
        return Ok(next.run(req).await);
    }
    let token = req
        .headers()
        .get(header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.strip_prefix("Bearer "))
        .map(str::trim)
        .ok_or(ApiError::Unauthorized)?;
    if crate::store::tokens::verify(&state.store, token).await? {
        Ok(next.run(req).await)
    } else {
        Err(ApiError::Unauthorized)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn public_routes() {
        assert!(is_public(&Method::GET, "/api/health"));
        assert!(is_public(&Method::GET, "/api/library/classes"));
        assert!(!is_public(&Method::POST, "/api/library/instances"));
        assert!(!is_public(&Method::GET, "/api/models"));
        assert!(is_public(&Method::GET, "/"));
    }
}
