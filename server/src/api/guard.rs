//! Safe by default on loopback: without a token, any web page the user opens could otherwise
//! drive the service (cross-site requests, DNS rebinding). Three rules, applied by the one
//! request layer in `auth.rs`:
//!
//! 1. **Host**: the `Host` header must name this service: the bound address (`localhost`,
//!    `127.0.0.1` and `[::1]` too when bound to loopback) with the bound port, or a configured
//!    `--allowed-host` (`name` for any port, `name:port` for one). Otherwise 421
//!    `/problems/misdirected-request`: a rebound DNS name reaches nothing. Bound to an unspecified
//!    address (`0.0.0.0`, `::`) with no allowed hosts configured, any host is accepted (tokens
//!    are required there anyway).
//! 2. **Origin**: a state-changing request (POST, PUT, PATCH, DELETE) whose `Origin` is present
//!    must come from one of our own origins (the request's own host, or an allowed one): 403
//!    `/problems/cross-origin`.
//! 3. **Client header**: without a valid token, a state-changing request must carry
//!    `X-Requested-With` (any value) or a content type a cross-site form cannot send (anything
//!    but `text/plain`, `multipart/form-data`, `application/x-www-form-urlencoded`, and not
//!    none): 403 `/problems/client-header-required`. A browser only sends those cross-site after
//!    a CORS preflight, which this service never grants. The browser UI sends the header.
//!
//! Rules 2 and 3 do not apply to requests with a valid bearer token (a page cannot have it).
//! Where tokens are required, a request without one is refused (401) before rules 2 and 3.

use std::net::{IpAddr, SocketAddr};

use axum::http::{header, HeaderMap, Method};

/// The header the browser UI (and scripts without a token) send on state-changing requests.
pub const CLIENT_HEADER: &str = "x-requested-with";

/// The names and port this service answers to.
#[derive(Clone, Debug)]
pub struct Hosts {
    port: u16,
    /// Built in: the bound address (and the loopback names): must come with `port`.
    own: Vec<String>,
    /// Configured: a name, and a port or any port.
    extra: Vec<(String, Option<u16>)>,
    /// Bound to an unspecified address and nothing configured: every host.
    any: bool,
}

/// `host[:port]` lower-cased, without a trailing dot, IPv6 kept in brackets. `None` if malformed.
fn split_authority(a: &str) -> Option<(String, Option<u16>)> {
    let a = a.trim();
    if a.is_empty() || a.contains(['/', '@', ' ']) {
        return None;
    }
    let (host, port) = if a.starts_with('[') {
        let end = a.find(']')?;
        let rest = &a[end + 1..];
        let port = match rest.strip_prefix(':') {
            Some(p) => Some(p.parse().ok()?),
            None if rest.is_empty() => None,
            None => return None,
        };
        (&a[..=end], port)
    } else {
        match a.rsplit_once(':') {
            Some((h, p)) => (h, Some(p.parse().ok()?)),
            None => (a, None),
        }
    };
    let host = host.trim_end_matches('.').to_ascii_lowercase();
    (!host.is_empty()).then_some((host, port))
}

fn ip_name(ip: IpAddr) -> String {
    match ip {
        IpAddr::V4(v4) => v4.to_string(),
        IpAddr::V6(v6) => format!("[{v6}]"),
    }
}

impl Hosts {
    /// For a service listening on `addr` with the configured extra names.
    pub fn new(addr: SocketAddr, allowed: &[String]) -> Hosts {
        let mut own = Vec::new();
        if !addr.ip().is_unspecified() {
            own.push(ip_name(addr.ip()));
        }
        if addr.ip().is_loopback() {
            own.extend(["localhost", "127.0.0.1", "[::1]"].map(String::from));
        }
        let extra: Vec<(String, Option<u16>)> = allowed.iter().filter_map(|a| split_authority(a)).collect();
        Hosts { port: addr.port(), own, any: addr.ip().is_unspecified() && extra.is_empty(), extra }
    }

    /// Whether `authority` (a `Host` header, or an origin's authority with `default_port` for
    /// its scheme) names this service.
    fn allows(&self, authority: &str, default_port: u16) -> bool {
        if self.any {
            return true;
        }
        let Some((host, port)) = split_authority(authority) else { return false };
        let port = port.unwrap_or(default_port);
        (port == self.port && self.own.contains(&host)) || self.extra.iter().any(|(h, p)| *h == host && p.is_none_or(|p| p == port))
    }

    /// Rule 1: the request's host (`Host`, or the URI's authority in HTTP/2). `Err` says why not.
    pub fn check_host(&self, headers: &HeaderMap, uri_authority: Option<&str>) -> Result<String, String> {
        let host = headers.get(header::HOST).and_then(|v| v.to_str().ok()).or(uri_authority);
        match host {
            Some(h) if self.allows(h, 80) => Ok(h.to_string()),
            Some(h) => Err(format!(
                "this service does not answer to the host \"{h}\"; use the address it listens on, or start it with --allowed-host NAME"
            )),
            None => Err("the request has no Host header".to_string()),
        }
    }

    /// Rule 2: an `Origin` of one of our own origins (or none).
    pub fn check_origin(&self, headers: &HeaderMap, host: &str) -> Result<(), String> {
        let Some(origin) = headers.get(header::ORIGIN) else { return Ok(()) };
        let text = origin.to_str().unwrap_or("(not text)");
        let ours = origin.to_str().ok().and_then(|o| {
            let (authority, default_port) =
                if let Some(a) = o.strip_prefix("http://") { (a, 80) } else { (o.strip_prefix("https://")?, 443) };
            Some(authority.eq_ignore_ascii_case(host) || (!self.any && self.allows(authority, default_port)))
        });
        if ours == Some(true) {
            Ok(())
        } else {
            Err(format!("requests that change data are refused from the web origin {text}: only pages of this service may send them"))
        }
    }
}

/// Whether `method` changes data.
pub fn changes_state(method: &Method) -> bool {
    matches!(*method, Method::POST | Method::PUT | Method::PATCH | Method::DELETE)
}

/// Rule 3: the client header, or a content type no cross-site form or simple request can send.
pub fn check_client(headers: &HeaderMap) -> Result<(), String> {
    if headers.get(CLIENT_HEADER).is_some_and(|v| !v.is_empty()) {
        return Ok(());
    }
    let essence = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .map(|v| v.split(';').next().unwrap_or_default().trim().to_ascii_lowercase());
    match essence.as_deref() {
        Some(t) if !t.is_empty() && !["text/plain", "multipart/form-data", "application/x-www-form-urlencoded"].contains(&t) => Ok(()),
        _ => Err(format!(
            "without an API token, requests that change data must send the header `X-Requested-With: cad2mo` \
             (or a JSON/XML body with its Content-Type); got Content-Type {}",
            essence.map_or_else(|| "none".to_string(), |t| format!("\"{t}\""))
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn headers(pairs: &[(&'static str, &str)]) -> HeaderMap {
        let mut h = HeaderMap::new();
        for (k, v) in pairs {
            h.insert(*k, v.parse().unwrap());
        }
        h
    }

    #[test]
    fn hosts_on_loopback() {
        let h = Hosts::new("127.0.0.1:8080".parse().unwrap(), &["cad.example.org".into(), "box:9000".into()]);
        for ok in
            ["127.0.0.1:8080", "localhost:8080", "LOCALHOST.:8080", "[::1]:8080", "cad.example.org", "cad.example.org:443", "box:9000"]
        {
            assert!(h.allows(ok, 80), "{ok}");
        }
        for bad in ["evil.com:8080", "localhost:8081", "localhost", "127.0.0.1", "box:9001", "", "a@localhost:8080", "[::1"] {
            assert!(!h.allows(bad, 80), "{bad}");
        }
        let any = Hosts::new("0.0.0.0:80".parse().unwrap(), &[]);
        assert!(any.allows("whatever.example", 80));
        let named = Hosts::new("0.0.0.0:80".parse().unwrap(), &["cad.example.org".into()]);
        assert!(named.allows("cad.example.org", 80) && !named.allows("evil.com", 80));
    }

    #[test]
    fn origins_and_client_headers() {
        let h = Hosts::new("127.0.0.1:8080".parse().unwrap(), &[]);
        assert!(h.check_origin(&headers(&[]), "127.0.0.1:8080").is_ok());
        assert!(h.check_origin(&headers(&[("origin", "http://127.0.0.1:8080")]), "127.0.0.1:8080").is_ok());
        assert!(h.check_origin(&headers(&[("origin", "http://localhost:8080")]), "127.0.0.1:8080").is_ok());
        for bad in ["http://evil.com", "null", "http://127.0.0.1:8081", "file://", "http://127.0.0.1:8080.evil.com"] {
            assert!(h.check_origin(&headers(&[("origin", bad)]), "127.0.0.1:8080").is_err(), "{bad}");
        }
        assert!(check_client(&headers(&[("x-requested-with", "cad2mo")])).is_ok());
        assert!(check_client(&headers(&[("content-type", "application/json")])).is_ok());
        assert!(check_client(&headers(&[("content-type", "application/xml; charset=utf-8")])).is_ok());
        for simple in ["text/plain", "Text/Plain;charset=UTF-8", "multipart/form-data; boundary=x", "application/x-www-form-urlencoded"] {
            assert!(check_client(&headers(&[("content-type", simple)])).is_err(), "{simple}");
        }
        assert!(check_client(&headers(&[])).is_err());
    }
}
