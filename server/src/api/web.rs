//! The browser UI's static files, built from `web/` by `build.rs` and embedded in the binary.
//! Hashed files under `/assets/` are immutable and cached for a year; everything else (the
//! page itself) is revalidated by ETag on every load. Text files go out gzipped (compressed once,
//! at build time) to clients that accept it. The page gets its data from the API only.

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
    let Some((_, bytes, gz, etag)) = assets::ASSETS.iter().find(|(p, _, _, _)| *p == path) else {
        if path == "index.html" {
            return Ok(not_built());
        }
        return Err(ApiError::NotFound(format!("file /{path}")));
    };
    let gzip = gz.filter(|_| accepts_gzip(headers));
    // One ETag per representation: the gzipped body is a different byte sequence.
    let etag = match gzip {
        Some(_) => format!("{}-gz\"", etag.trim_end_matches('"')),
        None => (*etag).to_string(),
    };
    let cache = if path.starts_with("assets/") { "public, max-age=31536000, immutable" } else { "no-cache" };
    let fresh = headers
        .get(header::IF_NONE_MATCH)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.split(',').any(|t| t.trim().trim_start_matches("W/") == etag));
    let mut resp = if fresh {
        StatusCode::NOT_MODIFIED.into_response()
    } else {
        let mime = mime_guess::from_path(path).first_or_octet_stream();
        let mut r = gzip.unwrap_or(bytes).into_response();
        if let Ok(v) = HeaderValue::from_str(mime.as_ref()) {
            r.headers_mut().insert(header::CONTENT_TYPE, v);
        }
        if gzip.is_some() {
            r.headers_mut().insert(header::CONTENT_ENCODING, HeaderValue::from_static("gzip"));
        }
        r
    };
    let h = resp.headers_mut();
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    if gz.is_some() {
        h.insert(header::VARY, HeaderValue::from_static("accept-encoding"));
    }
    if let Ok(v) = HeaderValue::from_str(&etag) {
        h.insert(header::ETAG, v);
    }
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    if path.ends_with(".html") {
        h.insert(header::CONTENT_SECURITY_POLICY, HeaderValue::from_static(CSP));
    }
    Ok(resp)
}

/// Whether `Accept-Encoding` admits gzip (and does not refuse it with `q=0`).
fn accepts_gzip(headers: &HeaderMap) -> bool {
    let Some(v) = headers.get(header::ACCEPT_ENCODING).and_then(|v| v.to_str().ok()) else { return false };
    v.split(',').any(|part| {
        let mut it = part.split(';');
        let coding = it.next().unwrap_or("").trim();
        let q = it.find_map(|p| p.trim().strip_prefix("q=")).and_then(|q| q.trim().parse::<f32>().ok()).unwrap_or(1.0);
        (coding.eq_ignore_ascii_case("gzip") || coding == "*") && q > 0.0
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    fn with(v: &str) -> HeaderMap {
        let mut h = HeaderMap::new();
        h.insert(header::ACCEPT_ENCODING, HeaderValue::from_str(v).expect("header"));
        h
    }

    #[test]
    fn gzip_negotiation() {
        assert!(accepts_gzip(&with("gzip, deflate, br")));
        assert!(accepts_gzip(&with("br;q=1.0, GZIP;q=0.5")));
        assert!(accepts_gzip(&with("*")));
        assert!(!accepts_gzip(&with("gzip;q=0")));
        assert!(!accepts_gzip(&with("br, identity")));
        assert!(!accepts_gzip(&HeaderMap::new()));
    }
}
