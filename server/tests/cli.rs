//! The command line: exit codes, atomic output, inspect.

use std::path::PathBuf;
use std::process::Command;

fn workspace_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_cad2mo"))
}

fn case(name: &str) -> PathBuf {
    workspace_root().join("tests/in").join(name)
}

#[test]
fn convert_writes_a_zip_and_inspect_prints_json() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("pendulum.zip");
    let st = bin().args(["convert"]).arg(case("pendulum")).arg("-o").arg(&out).output().expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
    let bytes = std::fs::read(&out).expect("zip written");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(bytes)).expect("valid zip");
    assert!(z.by_name("report.json").is_ok());
    let names: Vec<String> = z.file_names().map(String::from).collect();
    assert!(names.iter().any(|n| n.ends_with("/Mechanics.mo")), "{names:?}");
    assert!(names.iter().any(|n| n.ends_with(".dxf")), "{names:?}");
    // No temporary files left behind.
    let left: Vec<_> = std::fs::read_dir(dir.path()).expect("ls").flatten().map(|e| e.file_name()).collect();
    assert_eq!(left.len(), 1, "{left:?}");

    let st = bin().arg("inspect").arg(case("pendulum")).output().expect("run");
    assert!(st.status.success());
    let report: serde_json::Value = serde_json::from_slice(&st.stdout).expect("json on stdout");
    assert!(report["bodies"].as_array().is_some_and(|b| !b.is_empty()));
}

#[test]
fn conversion_error_exits_1_and_leaves_no_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("broken.zip");
    let st = bin().arg("convert").arg(case("broken_dangling_ref")).arg("-o").arg(&out).output().expect("run");
    assert_eq!(st.status.code(), Some(1));
    let err = String::from_utf8_lossy(&st.stderr);
    assert!(err.contains("error:"), "{err}");
    assert!(!out.exists());
    assert_eq!(std::fs::read_dir(dir.path()).expect("ls").count(), 0);
}

#[test]
fn bad_usage_exits_2() {
    let st = bin().arg("convert").output().expect("run");
    assert_eq!(st.status.code(), Some(2));
    let st = bin().args(["convert", "x", "-o", "y.zip", "--gravity", "1,2"]).output().expect("run");
    assert_eq!(st.status.code(), Some(2));
    let st = bin().args(["convert", "x", "-o", "y.zip", "--package-name", "9lives"]).output().expect("run");
    assert_eq!(st.status.code(), Some(2));
    let st = bin().arg("frobnicate").output().expect("run");
    assert_eq!(st.status.code(), Some(2));
}

#[test]
fn missing_input_exits_1() {
    let st = bin().args(["inspect", "/nonexistent/bundle.zip"]).output().expect("run");
    assert_eq!(st.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&st.stderr).contains("/nonexistent/bundle.zip"));
}

#[test]
fn token_create_prints_a_token_once() {
    let dir = tempfile::tempdir().expect("tempdir");
    let st = bin().args(["token", "create", "--name", "ci", "--data-dir"]).arg(dir.path()).output().expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
    let token = String::from_utf8_lossy(&st.stdout).trim().to_string();
    assert!(token.starts_with("c2m_") && token.len() > 40, "{token}");
    assert!(dir.path().join("cad2mo.db").exists());
}

#[test]
fn reexport_runs_with_a_progress_bar_and_reports_unknown_models() {
    let dir = tempfile::tempdir().expect("tempdir");
    let st = bin().args(["reexport", "--all", "--data-dir"]).arg(dir.path()).output().expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
    assert!(String::from_utf8_lossy(&st.stderr).contains("re-exported 0 of 0 models"));
    let st = bin().args(["reexport", "--model", "nope", "--data-dir"]).arg(dir.path()).output().expect("run");
    assert_eq!(st.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&st.stderr).contains("no model nope"));
    let st = bin().args(["reexport", "--data-dir"]).arg(dir.path()).output().expect("run");
    assert_eq!(st.status.code(), Some(2), "--all or --model is required");
}
