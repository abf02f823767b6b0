//! The HTTP contract: `openapi.yaml` and the router agree route for route, the document is valid
//! OpenAPI 3.1, and the service serves it.

use std::collections::BTreeSet;
use std::process::Command;

use cad2mo_tests::app::TestApp;
use cad2mo_tests::common::{files_with_ext, tools_required, workspace_root};

const METHODS: [&str; 5] = ["get", "post", "put", "delete", "patch"];

/// (method, path) of every `.route("PATH", get(..).post(..))` in server/src/api, except the
/// browser UI's static files (`api/web.rs`), which are pages, not part of the API contract.
fn router_routes() -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    for f in files_with_ext(&workspace_root().join("server/src/api"), &[".rs"]) {
        if f.ends_with("web.rs") {
            continue;
        }
        let src = std::fs::read_to_string(&f).expect("source");
        let mut rest = src.as_str();
        while let Some(i) = rest.find(".route(\"") {
            rest = &rest[i + 8..];
            let end = rest.find('"').expect("path end");
            let path = rest[..end].to_string();
            // The handler expression runs to the parenthesis closing `.route(`.
            let mut depth = 1;
            let mut j = end + 1;
            for (k, c) in rest[end + 1..].char_indices() {
                match c {
                    '(' => depth += 1,
                    ')' => {
                        depth -= 1;
                        if depth == 0 {
                            j = end + 1 + k;
                            break;
                        }
                    }
                    _ => {}
                }
            }
            let handlers = &rest[end + 1..j];
            for m in METHODS {
                let call = format!("{m}(");
                let found = handlers
                    .match_indices(&call)
                    .any(|(p, _)| p == 0 || !handlers.as_bytes()[p - 1].is_ascii_alphanumeric() && handlers.as_bytes()[p - 1] != b'_');
                if found {
                    out.insert((m.to_uppercase(), path.clone()));
                }
            }
            rest = &rest[j..];
        }
    }
    out
}

/// (method, path) of the spec's `paths` section (2-space path keys, 4-space method keys).
fn spec_routes(spec: &str) -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    let mut in_paths = false;
    let mut path = String::new();
    for line in spec.lines() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        if !line.starts_with(' ') {
            in_paths = line.starts_with("paths:");
            continue;
        }
        if !in_paths {
            continue;
        }
        if let Some(p) = line.strip_prefix("  /") {
            path = format!("/{}", p.trim_end_matches(':'));
        } else if let Some(m) = line.strip_prefix("    ").and_then(|l| l.strip_suffix(':')) {
            if METHODS.contains(&m) {
                out.insert((m.to_uppercase(), path.clone()));
            }
        }
    }
    out
}

#[test]
fn router_and_spec_agree() {
    let spec = std::fs::read_to_string(workspace_root().join("openapi.yaml")).expect("openapi.yaml");
    let (router, documented) = (router_routes(), spec_routes(&spec));
    assert!(router.len() > 25, "router routes not found: {router:?}");
    let missing: Vec<_> = router.difference(&documented).collect();
    let stale: Vec<_> = documented.difference(&router).collect();
    assert!(missing.is_empty() && stale.is_empty(), "not in the spec: {missing:?}\nnot in the router: {stale:?}");
}

#[test]
fn spec_is_valid_openapi() {
    let have = Command::new("python3").args(["-c", "import openapi_spec_validator"]).status().is_ok_and(|s| s.success());
    if !have {
        assert!(!tools_required(), "openapi-spec-validator is required (CAD2MO_REQUIRE_TOOLS=1)");
        println!("NOTICE: openapi-spec-validator not installed; spec validation skipped");
        return;
    }
    let out = Command::new("python3")
        .args(["-m", "openapi_spec_validator"])
        .arg(workspace_root().join("openapi.yaml"))
        .output()
        .expect("run validator");
    assert!(out.status.success(), "{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}

#[tokio::test]
async fn service_serves_the_spec_and_every_plain_get_exists() {
    let app = TestApp::spawn().await;
    let r = app.get("/openapi.yaml").await;
    assert_eq!(r.status(), 200);
    assert_eq!(r.headers()["content-type"], "application/yaml");
    let text = r.text().await.expect("text");
    assert_eq!(text, std::fs::read_to_string(workspace_root().join("openapi.yaml")).expect("file"));
    for (method, path) in spec_routes(&text) {
        if method == "GET" && !path.contains('{') {
            let status = app.get(&path).await.status().as_u16();
            assert!(status != 404 && status != 405, "GET {path}: {status}");
        }
    }
}
