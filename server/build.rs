//! Builds the browser UI (`web/`, Vite + three.js from npm) and embeds it in the binary, so
//! `cargo run -- serve` serves it with no other step. npm runs only when `web/` changed:
//! `npm ci` when the lockfile is newer than `node_modules`, then `vite build` into `OUT_DIR`.
//! Text files are also gzipped here (best compression, once), so the server never compresses
//! per request. Without npm (or when the build fails) the server still builds, and `/` explains
//! what is missing.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use sha2::{Digest, Sha256};

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let web = manifest.join("../web");
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("OUT_DIR"));
    for f in ["src", "public", "index.html", "package.json", "package-lock.json", "vite.config.js"] {
        println!("cargo:rerun-if-changed={}", web.join(f).display());
    }
    println!("cargo:rerun-if-env-changed=CAD2MO_SKIP_UI");
    let dist = out.join("web-dist");
    let error = if std::env::var_os("CAD2MO_SKIP_UI").is_some() {
        Some("the UI build was skipped (CAD2MO_SKIP_UI is set)".to_string())
    } else {
        build(&web, &dist).err()
    };
    if let Some(e) = &error {
        println!("cargo:warning=browser UI not built: {e}");
    }
    let mut files = Vec::new();
    if error.is_none() {
        collect(&dist, &dist, &mut files);
    }
    files.sort();
    let gz_dir = out.join("web-gz");
    let mut code = String::from("pub static ASSETS: &[super::Asset] = &[\n");
    for (rel, abs) in &files {
        let bytes = std::fs::read(abs).expect("reading a built UI file");
        let etag = hex(&Sha256::digest(&bytes)[..16]);
        let gz = if is_text(rel) && bytes.len() > 1024 {
            let path = gz_dir.join(format!("{rel}.gz"));
            std::fs::create_dir_all(path.parent().expect("parent")).expect("gz folder");
            let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
            std::io::Write::write_all(&mut enc, &bytes).expect("gzip");
            std::fs::write(&path, enc.finish().expect("gzip")).expect("writing a gzipped UI file");
            format!("Some(include_bytes!({:?}))", path.display().to_string())
        } else {
            "None".to_string()
        };
        let _ = writeln!(
            code,
            "    super::Asset {{ path: {rel:?}, bytes: include_bytes!({:?}), gzip: {gz}, etag: \"\\\"{etag}\\\"\" }},",
            abs.display().to_string()
        );
    }
    code.push_str("];\n");
    let _ = writeln!(code, "/// Why the UI is missing, when it is.\npub static BUILD_ERROR: Option<&str> = {error:?};");
    std::fs::write(out.join("web_assets.rs"), code).expect("writing web_assets.rs");
}

fn is_text(path: &str) -> bool {
    [".html", ".js", ".css", ".svg", ".json", ".txt", ".map"].iter().any(|e| path.ends_with(e))
}

fn hex(b: &[u8]) -> String {
    b.iter().fold(String::new(), |mut s, x| {
        let _ = write!(s, "{x:02x}");
        s
    })
}

fn collect(root: &Path, dir: &Path, files: &mut Vec<(String, PathBuf)>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            collect(root, &p, files);
        } else if let Ok(rel) = p.strip_prefix(root) {
            files.push((rel.to_string_lossy().replace('\\', "/"), p));
        }
    }
}

fn mtime(p: &Path) -> Option<std::time::SystemTime> {
    std::fs::metadata(p).and_then(|m| m.modified()).ok()
}

fn run(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd.output().map_err(|e| format!("{what}: cannot start ({e}); install Node.js 20+ and npm"))?;
    if out.status.success() {
        return Ok(());
    }
    let tail = |b: &[u8]| {
        let s = String::from_utf8_lossy(b);
        s.lines().rev().take(15).collect::<Vec<_>>().into_iter().rev().collect::<Vec<_>>().join("\n")
    };
    Err(format!("{what} failed ({}):\n{}\n{}", out.status, tail(&out.stdout), tail(&out.stderr)))
}

fn build(web: &Path, dist: &Path) -> Result<(), String> {
    if !web.join("package.json").exists() {
        return Err(format!("{} has no package.json", web.display()));
    }
    let stamp = web.join("node_modules/.package-lock.json");
    let stale = match (mtime(&stamp), mtime(&web.join("package-lock.json"))) {
        (Some(installed), Some(lock)) => installed < lock,
        _ => true,
    };
    if stale {
        run(Command::new("npm").args(["ci", "--no-audit", "--no-fund", "--loglevel=error"]).current_dir(web), "npm ci")?;
    }
    run(
        Command::new("node")
            .arg("node_modules/vite/bin/vite.js")
            .args(["build", "--logLevel", "warn", "--emptyOutDir", "--outDir"])
            .arg(dist)
            .current_dir(web),
        "vite build",
    )
}
