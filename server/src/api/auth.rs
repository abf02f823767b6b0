//! The request guard: the host rule of [`super::guard`], then bearer-token authentication, then
//! its origin and client-header rules (safe by default on loopback). When the service listens
//! beyond loopback (or with `--require-auth`), every request needs `Authorization: Bearer <token>`
//! (scheme in any case; an expired token is refused) except the health check, the OpenAPI
//! document, the browser UI's static files and reads of the motor library; without one it is a
//! 401, whatever else it lacks.

use axum::extract::{Request, State};
use axum::http::{header, HeaderMap, Method};
use axum::middleware::Next;
use axum::response::Response;

use super::guard;
use super::ApiError;
use crate::app::AppState;

fn is_public(method: &Method, path: &str) -> bool {
    let read = method == Method::GET || method == Method::HEAD;
    path == "/api/health" || path == "/openapi.yaml" || !path.starts_with("/api/") || (read && path.starts_with("/api/library/"))
}

/// The token of an `Authorization: Bearer <token>` header (scheme case-insensitive), or, since
/// browsers cannot set headers on a WebSocket, of a `bearer.<token>` WebSocket sub-protocol.
pub(super) fn bearer(headers: &HeaderMap) -> Option<&str> {
    if let Some(value) = headers.get(header::AUTHORIZATION) {
        let value = value.to_str().ok()?.trim();
        let (scheme, token) = value.split_once(' ')?;
        let token = token.trim();
        return (scheme.eq_ignore_ascii_case("bearer") && !token.is_empty()).then_some(token);
    }
    headers
        .get_all(header::SEC_WEBSOCKET_PROTOCOL)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(','))
        .find_map(|p| p.trim().strip_prefix("bearer.").filter(|t| !t.is_empty()))
}

/// Whether the request asks to become a WebSocket (which a page of any origin may open).
fn is_websocket(headers: &HeaderMap) -> bool {
    headers.get(header::UPGRADE).and_then(|v| v.to_str().ok()).is_some_and(|v| v.eq_ignore_ascii_case("websocket"))
}

/// What the guard layer needs: the app (settings, tokens) and the names it answers to.
#[derive(Clone)]
pub struct Guard {
    pub state: AppState,
    pub hosts: guard::Hosts,
}

pub async fn guard(State(Guard { state, hosts }): State<Guard>, req: Request, next: Next) -> Result<Response, ApiError> {
    let host = hosts.check_host(req.headers(), req.uri().authority().map(|a| a.as_str())).map_err(ApiError::MisdirectedHost)?;
    let valid = match bearer(req.headers()) {
        Some(token) => crate::store::tokens::verify(&state.store, token).await?,
        None => false,
    };
    // Without a token where one is required, the answer is 401 (what the client lacks), before
    // the origin and client-header rules: those guard requests that would otherwise be served.
    if !valid && state.settings.requires_auth() && !is_public(req.method(), req.uri().path()) {
        return Err(ApiError::Unauthorized);
    }
    if guard::changes_state(req.method()) && !valid {
        hosts.check_origin(req.headers(), &host).map_err(ApiError::CrossOrigin)?;
        guard::check_client(req.headers()).map_err(ApiError::ClientHeaderRequired)?;
    }
    // A WebSocket is opened by a GET that any page may send, and what it carries is read by
    // that page: only our own pages may open one.
    if is_websocket(req.headers()) {
        hosts.check_origin(req.headers(), &host).map_err(ApiError::CrossOrigin)?;
    }
    Ok(next.run(req).await)
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

    #[test]
    fn bearer_scheme_in_any_case() {
        let mut h = HeaderMap::new();
        for (v, want) in [
            ("Bearer abc", Some("abc")),
            ("bearer abc", Some("abc")),
            ("BEARER  abc ", Some("abc")),
            ("Basic abc", None),
            ("Bearer", None),
            ("Bearer ", None),
        ] {
            h.insert(header::AUTHORIZATION, v.parse().unwrap());
            assert_eq!(bearer(&h), want, "{v}");
        }
        let mut w = HeaderMap::new();
        for (v, want) in [("cad2mo.live, bearer.c2m_x", Some("c2m_x")), ("cad2mo.live", None), ("bearer.", None)] {
            w.insert(header::SEC_WEBSOCKET_PROTOCOL, v.parse().unwrap());
            assert_eq!(bearer(&w), want, "{v}");
        }
    }
}
