//! Extractors that answer in problem+json: axum's own `Path` and `Query` reject with a
//! `text/plain` body; these wrap them so a bad path or query parameter is a 400 problem document
//! (`/problems/bad-request`) like every other error. Handlers use these, never axum's directly
//! (or take `Result<axum::extract::Path<_>, PathRejection>` and map it themselves).

use axum::extract::FromRequestParts;

use super::ApiError;

/// `axum::extract::Path`, rejecting with [`ApiError::BadRequest`].
#[derive(FromRequestParts)]
#[from_request(via(axum::extract::Path), rejection(ApiError))]
pub struct Path<T>(pub T);

/// `axum::extract::Query`, rejecting with [`ApiError::BadRequest`].
#[derive(FromRequestParts)]
#[from_request(via(axum::extract::Query), rejection(ApiError))]
pub struct Query<T>(pub T);
