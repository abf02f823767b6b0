//! Tidy: architecture invariants enforced by a test, not by reviewers.

use std::path::Path;

use cad2mo_tests::common::{files_with_ext, workspace_root};

/// Non-test source of a Rust file: everything before its first `#[cfg(test)]`.
fn non_test_source(path: &Path) -> String {
    let text = std::fs::read_to_string(path).expect("read source");
    match text.find("#[cfg(test)]") {
        Some(i) => text[..i].to_string(),
        None => text,
    }
}

/// The computation crate cannot reach a runtime, a web framework, a database or the network: its
/// manifest has none of them, so the compiler enforces the rest.
#[test]
fn engine_manifest_has_no_io_frameworks() {
    let manifest = std::fs::read_to_string(workspace_root().join("engine/Cargo.toml")).expect("engine/Cargo.toml");
    let mut section = "";
    let mut deps = Vec::new();
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            section = line;
        } else if section == "[dependencies]" && !line.is_empty() && !line.starts_with('#') {
            deps.push(line.split(['=', '.']).next().unwrap_or("").trim().to_string());
        }
    }
    assert!(deps.len() > 5 && deps.iter().any(|d| d == "nalgebra"), "engine dependencies not found: {deps:?}");
    for banned in ["tokio", "axum", "sqlx", "object_store", "hyper", "reqwest", "tower", "tower-http", "tracing", "cad2mo-server", "cad2mo"]
    {
        assert!(!deps.iter().any(|d| d == banned), "engine/Cargo.toml depends on {banned}: computation must stay free of IO frameworks");
    }
}

/// Every engine module: no file system, network, processes, environment or printing in its
/// non-test code (inputs are bytes, warnings are returned).
#[test]
fn engine_has_no_io() {
    let root = workspace_root().join("engine/src");
    let mut modules = cad2mo_tests::common::sorted_dirs(&root);
    modules.push(root.join("diff.rs"));
    assert!(modules.len() >= 8, "engine modules not found under {}", root.display());
    for m in modules {
        let name = m.file_name().expect("name").to_string_lossy().into_owned();
        check_module(&m, &name, &IO, 0);
    }
}

/// The pipeline never panics on input (no unwrap/expect) and never prints.
#[test]
fn pipeline_has_no_io_and_no_panics() {
    no_io_and_no_panics("pipeline", 10);
}

/// The drive sizing follows the pipeline's rules.
#[test]
fn sizing_has_no_io_and_no_panics() {
    no_io_and_no_panics("sizing", 1);
}

const IO: [&str; 14] = [
    "std::fs",
    "std::net",
    "std::process",
    "std::env",
    "File::",
    "tokio",
    "axum",
    "sqlx",
    "hyper",
    "println!",
    "eprintln!",
    "print!(",
    "dbg!",
    "std::io::stdin",
];

fn no_io_and_no_panics(module: &str, min_files: usize) {
    let mut forbidden = IO.to_vec();
    forbidden.extend([".unwrap()", ".expect(", "todo!", "unimplemented!"]);
    check_module(&workspace_root().join("engine/src").join(module), module, &forbidden, min_files);
}

fn check_module(root: &Path, module: &str, forbidden: &[&str], min_files: usize) {
    let mut problems = Vec::new();
    let files = if root.is_file() { vec![root.to_path_buf()] } else { files_with_ext(root, &[".rs"]) };
    assert!(files.len() > min_files, "{module} sources not found under {}", root.display());
    for f in files {
        // Unit tests kept in their own `tests.rs`, its sub-modules under `tests/` and the shared
        // `testutil.rs` (all declared under `#[cfg(test)]`) may do anything.
        let under_tests =
            f.strip_prefix(root).is_ok_and(|rel| rel.parent().is_some_and(|p| p.components().any(|c| c.as_os_str() == "tests")));
        if under_tests || f.file_name().is_some_and(|n| n == "tests.rs" || n == "testutil.rs") {
            continue;
        }
        let src = non_test_source(&f);
        for (n, line) in src.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for &word in forbidden {
                if code.contains(word) {
                    problems.push(format!("{}:{}: `{word}` in {module} code: {}", f.display(), n + 1, line.trim()));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{module} tidy violations:\n{}", problems.join("\n"));
}

/// Only `store` speaks SQL; nothing else in any crate mentions sqlx.
#[test]
fn sql_only_in_store() {
    let mut seen = 0;
    for krate in ["engine", "server", "cli"] {
        let root = workspace_root().join(krate).join("src");
        for f in files_with_ext(&root, &[".rs"]) {
            seen += 1;
            let rel = f.strip_prefix(&root).expect("under src").to_string_lossy().replace('\\', "/");
            if krate == "server" && rel.starts_with("store/") {
                continue;
            }
            let src = non_test_source(&f);
            assert!(!src.contains("sqlx::"), "{krate}/src/{rel} uses sqlx outside store/");
        }
    }
    assert!(seen > 100, "sources not found");
}

/// Only `api` knows HTTP: nothing outside `server/src/api/` (and `app.rs`, which mounts the
/// router) imports it or axum. The use cases (`service/`) return their own errors, which
/// `api::error` maps to problem+json in one place.
#[test]
fn only_api_knows_http() {
    let root = workspace_root().join("server/src");
    let mut problems = Vec::new();
    for f in files_with_ext(&root, &[".rs"]) {
        let rel = f.strip_prefix(&root).expect("under src").to_string_lossy().replace('\\', "/");
        if rel.starts_with("api/") || rel == "app.rs" {
            continue;
        }
        let src = std::fs::read_to_string(&f).expect("read source");
        for (n, line) in src.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for word in ["crate::api", "axum", "StatusCode", "problem_json"] {
                if code.contains(word) {
                    problems.push(format!("server/src/{rel}:{}: `{word}`: {}", n + 1, line.trim()));
                }
            }
        }
    }
    for krate in ["engine", "cli"] {
        for f in files_with_ext(&workspace_root().join(krate).join("src"), &[".rs"]) {
            let src = std::fs::read_to_string(&f).expect("read source");
            if src.contains("cad2mo_server::api") || src.contains("axum") {
                problems.push(format!("{}: imports the HTTP layer", f.display()));
            }
        }
    }
    assert!(problems.is_empty(), "the HTTP layer leaks:\n{}", problems.join("\n"));
}

/// ARCHITECTURE.md's code map names every pipeline phase folder that exists.
#[test]
fn architecture_map_is_current() {
    let arch = std::fs::read_to_string(workspace_root().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let pipeline = workspace_root().join("engine/src/pipeline");
    for phase in ["front", "passes", "back"] {
        for dir in cad2mo_tests::common::sorted_dirs(&pipeline.join(phase)) {
            let name = format!("{phase}/{}", dir.file_name().expect("name").to_string_lossy());
            assert!(arch.contains(&name), "ARCHITECTURE.md does not mention {name}");
        }
    }
}
