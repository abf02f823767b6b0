//! Shared by the benchmarks: where the real fixtures are, and generated inputs (`gen`).
#![allow(dead_code)] // each benchmark uses part of it

pub mod gen;
pub mod vrml_gen;

use std::path::{Path, PathBuf};

/// `$CAD2MO_FIXTURES` or `../shared/fixtures`; `None` with a notice when absent.
pub fn fixtures() -> Option<PathBuf> {
    let dir = std::env::var_os("CAD2MO_FIXTURES")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/fixtures"));
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("NOTICE: fixtures not found at {}; fixture benchmarks skipped", dir.display());
        None
    }
}

/// Every file under `dir` with extension `ext` (case-insensitive), sorted.
pub fn files_with_ext(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(rd) = std::fs::read_dir(&d) else { continue };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case(ext)) {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}
