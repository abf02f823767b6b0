//! The browser UI's static files, built from `web/` by `build.rs` and embedded in the binary.
//! Hashed files under `/assets/` are immutable and cached for a year; everything else (the
//! page itself) is revalidated by ETag on every load. The page gets its data from the API only.

use axum::extract::Path;
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;

use super::ApiError;
use crate::app::AppState;

mod assets {
    include!(concat!(env!("OUT_DIR"), "/web_assets.rs"));
}

/// Scripts, styles and data only from this origin; WebGL needs nothing more.
const CSP: &str = "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'; \
                   connect-src 'self'; worker-src 'self' blob:; object-src 'none'; base-uri 'none'; frame-ancestors 'none'";

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/", get(|h: HeaderMap| async move { serve("index.html", &h) }))
        .route("/assets/{*file}", get(|Path(f): Path<String>, h: HeaderMap| async move { serve(&format!("assets/{f}"), &h) }))
        .route("/{file}", get(|Path(f): Path<String>, h: HeaderMap| async move { serve(&f, &h) }))
}

fn serve(path: &str, headers: &HeaderMap) -> Result<Response, ApiError> {
    let Some((_, bytes, etag)) = assets::ASSETS.iter().find(|(p, _, _)| *p == path) else {
        if path == "index.html" {
            return Ok(not_built());
        }
        return Err(ApiError::NotFound(format!("file /{path}")));
    };
    let cache = if path.starts_with("assets/") { "public, max-age=31536000, immutable" } else { "no-cache" };
    let mut resp = if headers.get(header::IF_NONE_MATCH).and_then(|v| v.to_str().ok()).is_some_and(|v| {
        v.split(',').any(|t| t.trim().trim_start_matches("W/") == *etag)
    }) {
        StatusCode::NOT_MODIFIED.into_response()
    } else {
        let mime = mime_guess::from_path(path).first_or_octet_stream();
        let mut r = (*bytes).into_response();
        if let Ok(v) = HeaderValue::from_str(mime.as_ref()) {
            r.headers_mut().insert(header::CONTENT_TYPE, v);
        }
        r
    };
    let h = resp.headers_mut();
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    if let Ok(v) = HeaderValue::from_str(etag) {
        h.insert(header::ETAG, v);
    }
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    if path.ends_with(".html") {
        h.insert(header::CONTENT_SECURITY_POLICY, HeaderValue::from_static(CSP));
    }
    Ok(resp)
}

/// `/` when the binary was built without the UI (no npm at build time).
fn not_built() -> Response {
    let why = assets::BUILD_ERROR.unwrap_or("the UI has no index.html");
    let text = format!(
        "The cad2mo browser UI was not built into this binary: {why}\n\nInstall Node.js 20+ and npm, then rebuild \
         (cargo build). The API works without it: see /openapi.yaml.\n"
    );
    (StatusCode::SERVICE_UNAVAILABLE, [(header::CONTENT_TYPE, "text/plain; charset=utf-8")], text).into_response()
}
