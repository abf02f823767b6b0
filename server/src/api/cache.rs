//! A response cache for the motor library's reads: the library changes rarely and is read on
//! every page of the UI and by scripts. Successful `GET /api/library/...` responses are kept by
//! URI; any successful write under `/api/library/` clears the cache. Bounded in entries, and in
//! size: a response whose body is larger than 16 MiB (or of unknown size) is served as it is,
//! uncached (a huge library still lists, it is just not kept in memory twice).

use std::collections::HashMap;
use std::sync::{Arc, RwLock};

use axum::body::{to_bytes, Body, Bytes, HttpBody};
use axum::extract::{Request, State};
use axum::http::{header, HeaderValue, Method, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

const MAX_ENTRIES: usize = 256;
const MAX_BODY: usize = 16 * 1024 * 1024;

#[derive(Clone, Default)]
pub struct LibraryCache(Arc<RwLock<HashMap<String, (HeaderValue, Bytes)>>>);

impl LibraryCache {
    fn clear(&self) {
        if let Ok(mut m) = self.0.write() {
            m.clear();
        }
    }
}

pub async fn library_cache(State(cache): State<LibraryCache>, req: Request, next: Next) -> Response {
    if !req.uri().path().starts_with("/api/library/") {
        return next.run(req).await;
    }
    if req.method() != Method::GET {
        let resp = next.run(req).await;
        if resp.status().is_success() {
            cache.clear();
        }
        return resp;
    }
    let key = req.uri().to_string();
    if let Some((ct, body)) = cache.0.read().ok().and_then(|m| m.get(&key).cloned()) {
        return ([(header::CONTENT_TYPE, ct)], body).into_response();
    }
    let resp = next.run(req).await;
    if resp.status() != StatusCode::OK {
        return resp;
    }
    let (parts, body) = resp.into_parts();
    if body.size_hint().exact().is_none_or(|n| n > MAX_BODY as u64) {
        return Response::from_parts(parts, body);
    }
    let bytes = match to_bytes(body, MAX_BODY).await {
        Ok(b) => b,
        Err(e) => return super::ApiError::Internal(anyhow::anyhow!("reading a library response: {e}")).into_response(),
    };
    if let (Some(ct), Ok(mut m)) = (parts.headers.get(header::CONTENT_TYPE).cloned(), cache.0.write()) {
        if m.len() >= MAX_ENTRIES {
            m.clear();
        }
        m.insert(key, (ct, bytes.clone()));
    }
    Response::from_parts(parts, Body::from(bytes))
}
