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

/// The pipeline has no IO and knows nothing of runtimes, web frameworks or databases; it never
/// panics on input (no unwrap/expect) and never prints (warnings are returned, not logged).
#[test]
fn pipeline_has_no_io_and_no_panics() {
    no_io_and_no_panics("pipeline", 10);
}

/// The drive sizing follows the pipeline's rules.
#[test]
fn sizing_has_no_io_and_no_panics() {
    no_io_and_no_panics("sizing", 1);
}

fn no_io_and_no_panics(module: &str, min_files: usize) {
    let root = workspace_root().join("server/src").join(module);
    let forbidden = [
        "std::fs", "std::net", "std::process", "std::env", "File::", "tokio", "axum", "sqlx", "hyper",
        "println!", "eprintln!", "print!(", "dbg!", ".unwrap()", ".expect(", "todo!", "unimplemented!",
    ];
    let mut problems = Vec::new();
    let files = files_with_ext(&root, &[".rs"]);
    assert!(files.len() > min_files, "{module} sources not found under {}", root.display());
    for f in files {
        // Unit tests kept in their own `tests.rs` and the shared `testutil.rs` (both declared under
        // `#[cfg(test)]`) may do anything.
        if f.file_name().is_some_and(|n| n == "tests.rs" || n == "testutil.rs") {
            continue;
        }
        let src = non_test_source(&f);
        for (n, line) in src.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for word in forbidden {
                if code.contains(word) {
                    problems.push(format!("{}:{}: `{word}` in {module} code: {}", f.display(), n + 1, line.trim()));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{module} tidy violations:\n{}", problems.join("\n"));
}

/// Only `store` (when it exists) speaks SQL; nothing else mentions sqlx.
#[test]
fn sql_only_in_store() {
    let root = workspace_root().join("server/src");
    for f in files_with_ext(&root, &[".rs"]) {
        let rel = f.strip_prefix(&root).expect("under src").to_string_lossy().replace('\\', "/");
        if rel.starts_with("store/") {
            continue;
        }
        let src = non_test_source(&f);
        assert!(!src.contains("sqlx::"), "{rel} uses sqlx outside store/");
    }
}

/// ARCHITECTURE.md's code map names every pipeline phase folder that exists.
#[test]
fn architecture_map_is_current() {
    let arch = std::fs::read_to_string(workspace_root().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let pipeline = workspace_root().join("server/src/pipeline");
    for phase in ["front", "passes", "back"] {
        for dir in cad2mo_tests::common::sorted_dirs(&pipeline.join(phase)) {
            let name = format!("{phase}/{}", dir.file_name().expect("name").to_string_lossy());
            assert!(arch.contains(&name), "ARCHITECTURE.md does not mention {name}");
        }
    }
}
