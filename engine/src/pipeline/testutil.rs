//! Test-only helpers shared by the pipeline's unit tests (declared under `#[cfg(test)]`).

use std::path::{Path, PathBuf};

/// The shared fixtures folder (`CAD2MO_FIXTURES` overrides `../shared/fixtures`); `None` with a
/// printed notice when absent, so the calling test skips.
pub(crate) fn fixtures_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("CAD2MO_FIXTURES")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/fixtures"));
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("NOTICE: fixtures folder {} not found; skipping (set CAD2MO_FIXTURES)", dir.display());
        None
    }
}

/// Every file under `dir` whose extension is `ext` (case-insensitive), sorted.
pub(crate) fn files_with_ext(dir: &Path, ext: &str) -> Vec<PathBuf> {
    fn walk(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
        let Ok(rd) = std::fs::read_dir(dir) else { return };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, ext, out);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case(ext)) {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, ext, &mut out);
    out.sort();
    out
}
