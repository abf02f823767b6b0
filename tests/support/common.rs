//! Locating fixtures and tools; converting bundles; writing packages to disk.

use std::path::{Path, PathBuf};
use std::process::Command;

use cad2mo_engine::mechanism::Mechanism;
use cad2mo_engine::pipeline::front::bundle::Limits;
use cad2mo_engine::pipeline::{self, Analysed, Options, Output};

/// The workspace root (the folder holding `Cargo.toml`, `server/`, `tests/`).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("tests/ has a parent").to_path_buf()
}

/// `../shared` beside the project, when present.
pub fn shared_dir() -> Option<PathBuf> {
    let d = workspace_root().join("../shared");
    d.is_dir().then_some(d)
}

/// The real CAD exports: `$CAD2MO_FIXTURES` or `../shared/fixtures`. `None` (with a printed
/// notice) when absent, so tests can skip.
pub fn fixtures_dir(test: &str) -> Option<PathBuf> {
    let d = std::env::var_os("CAD2MO_FIXTURES").map(PathBuf::from).unwrap_or_else(|| workspace_root().join("../shared/fixtures"));
    if d.is_dir() {
        Some(d)
    } else {
        println!("NOTICE: {test} skipped: fixtures not found at {} (set CAD2MO_FIXTURES)", d.display());
        None
    }
}

/// Whether a missing external tool must fail the test (the README's test command sets this).
pub fn tools_required() -> bool {
    std::env::var("CAD2MO_REQUIRE_TOOLS").is_ok_and(|v| v == "1")
}

/// Runs one of `tests/tools/`'s Python checks: writes `spec` to `in.json` in `dir`, runs
/// `python3 tests/tools/<script> in.json out.json` and returns `out.json`'s value. `None` (with a
/// notice naming `check`) when python3 or the module the script needs is missing (the script
/// exits 3), unless the tools are required; a failed run fails the test with its output.
pub fn python_check(dir: &Path, script: &str, spec: &serde_json::Value, label: &str, check: &str) -> Option<serde_json::Value> {
    let (input, output) = (dir.join("in.json"), dir.join("out.json"));
    std::fs::write(&input, spec.to_string()).expect("write spec");
    let script_path = workspace_root().join("tests/tools").join(script);
    let run = match std::process::Command::new("python3").arg(&script_path).arg(&input).arg(&output).output() {
        Ok(r) => r,
        Err(e) => {
            assert!(!tools_required(), "python3 not runnable: {e}");
            println!("NOTICE: python3 not runnable ({e}); {check} skipped");
            return None;
        }
    };
    let stdout = String::from_utf8_lossy(&run.stdout);
    if run.status.code() == Some(3) {
        assert!(!tools_required(), "{}", stdout.trim());
        println!("NOTICE: {}; {check} skipped", stdout.trim());
        return None;
    }
    assert!(run.status.success(), "{label}: {script} failed:\n{stdout}{}", String::from_utf8_lossy(&run.stderr));
    Some(serde_json::from_str(&std::fs::read_to_string(&output).expect("read out")).expect("json"))
}

/// Gives `m` the coordinate names of the package `out` holds (its Modelica layout: the joint
/// names the package's Mechanics uses), as the service does for motions; returns that package.
pub fn use_package_names(m: &mut Mechanism, a: &Analysed, out: &Output) -> pipeline::back::modelica::Package {
    let pkg = pipeline::back::modelica::write(
        &a.model,
        &a.validated,
        &pipeline::back::modelica::Options {
            package_name: out.report.package_name.clone(),
            gravity: out.report.options.gravity,
            converter_version: String::new(),
            name_hints: Default::default(),
        },
    );
    m.use_layout_names(&pkg.layout);
    pkg
}

/// Reads a bundle from disk and converts it.
pub fn convert_path(path: &Path, opts: &Options) -> Result<Output, String> {
    let bundle = cad2mo::read_bundle(path, &Limits::default())?;
    pipeline::convert(&bundle, opts).map_err(|e| e.to_string())
}

/// Writes every output file under `dir`.
pub fn write_output(out: &Output, dir: &Path) {
    for (path, bytes) in &out.files {
        let p = dir.join(path);
        std::fs::create_dir_all(p.parent().expect("file has a folder")).expect("create folder");
        std::fs::write(&p, bytes.bytes()).expect("write file");
    }
}

/// The text of one output file (inflated where the conversion deflated it ahead).
pub fn file_text(out: &Output, suffix: &str) -> Option<String> {
    // Files may come deflated (`FileData::bytes` inflates them).
    out.files.iter().find(|(p, _)| p.ends_with(suffix)).and_then(|(_, b)| String::from_utf8(b.bytes().into_owned()).ok())
}

/// Runs `../shared/tools/msl-check` on `dir`. `None` (with a notice) when the tool is absent;
/// `Some(Err(output))` when it reports problems.
pub fn msl_check(dir: &Path) -> Option<Result<String, String>> {
    let tool = shared_dir()?.join("tools/msl-check");
    if !tool.is_file() {
        println!("NOTICE: msl-check not found at {}", tool.display());
        return None;
    }
    let out = Command::new("python3").arg(&tool).arg(dir).output().ok()?;
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    Some(if out.status.success() { Ok(text) } else { Err(text) })
}

/// Every sub-directory of `dir`, sorted.
pub fn sorted_dirs(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> =
        std::fs::read_dir(dir).map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.is_dir()).collect()).unwrap_or_default();
    v.sort();
    v
}

/// Every file under `dir` (recursively) whose name ends with one of `exts` (lowercase), sorted.
pub fn files_with_ext(dir: &Path, exts: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(rd) = std::fs::read_dir(&d) else { continue };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let name = p.file_name().map(|n| n.to_string_lossy().to_lowercase()).unwrap_or_default();
                if exts.iter().any(|x| name.ends_with(x)) {
                    out.push(p);
                }
            }
        }
    }
    out.sort();
    out
}

/// Runs the independent Modelica parser `rumoca-lint` (crate rumoca) on `dir` and returns its
/// parse errors. Its reference checks do not follow MSL and give false positives, so only
/// `[parse-error]` findings count. `None` (with a notice) when the tool is not installed.
pub fn modelica_syntax_errors(dir: &Path) -> Option<Vec<String>> {
    let candidates = [
        PathBuf::from("rumoca-lint"),
        std::env::var_os("CARGO_HOME")
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from(std::env::var_os("HOME").unwrap_or_default()).join(".cargo"))
            .join("bin/rumoca-lint"),
    ];
    for tool in candidates {
        let Ok(out) = Command::new(&tool).args(["-l", "error", "-f", "compact"]).arg(dir).output() else { continue };
        let text = String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
        return Some(text.lines().filter(|l| l.contains("parse-error")).map(String::from).collect());
    }
    assert!(!tools_required(), "rumoca-lint is required (CAD2MO_REQUIRE_TOOLS=1) but not installed");
    println!("NOTICE: rumoca-lint not installed; Modelica syntax check skipped");
    None
}

/// The bundle a fixture XML converts from: its folder when the XML is alone there, else a
/// temporary folder holding only the XML. Keep the returned guard alive while the path is used.
pub fn fixture_bundle(xml: &Path) -> (PathBuf, Option<tempfile::TempDir>) {
    let dir = xml.parent().expect("folder");
    if files_with_ext(dir, &[".xml"]).len() == 1 {
        return (dir.to_path_buf(), None);
    }
    let tmp = tempfile::tempdir().expect("tempdir");
    std::fs::copy(xml, tmp.path().join(xml.file_name().expect("name"))).expect("copy");
    (tmp.path().to_path_buf(), Some(tmp))
}

/// Every URDF under `urdf/` with the root of its set (`urdf/<owner+repo>/<commit>/`).
pub fn fixture_urdfs(fx: &Path) -> Vec<(PathBuf, PathBuf)> {
    let mut out = Vec::new();
    let mut stack = vec![fx.join("urdf")];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "urdf") {
                let rel = p.strip_prefix(fx.join("urdf")).expect("under urdf");
                let set: PathBuf = rel.iter().take(2).collect();
                out.push((p.clone(), fx.join("urdf").join(set)));
            }
        }
    }
    out.sort();
    out
}

/// The URDF and every mesh file of its set, at their paths in the set (so `package://` URIs
/// resolve as they do in the source repository).
pub fn urdf_bundle(urdf: &Path, set: &Path) -> cad2mo_engine::pipeline::front::bundle::Bundle {
    let mut files = Vec::new();
    let mut stack = vec![set.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            let ext = p.extension().map(|x| x.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
            if p.is_dir() {
                stack.push(p);
            } else if p == urdf || matches!(ext.as_str(), "stl" | "dae" | "obj") {
                let rel = p.strip_prefix(set).expect("under set").to_string_lossy().replace('\\', "/");
                files.push((rel, std::fs::read(&p).expect("read")));
            }
        }
    }
    cad2mo_engine::pipeline::front::bundle::Bundle::from_files("urdf-set", files).expect("bundle")
}
