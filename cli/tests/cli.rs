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

/// Runs `cmd` for at most 20 s (a read of a FIFO would block forever).
fn run_bounded(cmd: &mut Command) -> std::process::Output {
    let mut child = cmd.stdout(std::process::Stdio::piped()).stderr(std::process::Stdio::piped()).spawn().expect("spawn");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
    while child.try_wait().expect("wait").is_none() {
        if std::time::Instant::now() > deadline {
            let _ = child.kill();
            panic!("the command did not finish in 20 s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

#[test]
fn convert_refuses_to_write_over_its_input() {
    let dir = tempfile::tempdir().expect("tempdir");
    let files: Vec<(String, Vec<u8>)> = ["PENDULUM.xml", "meshes/LINK_prt.stl"]
        .iter()
        .map(|f| (f.to_string(), std::fs::read(case("pendulum").join(f)).expect("read")))
        .collect();
    let input = dir.path().join("in.zip");
    let original = cad2mo_engine::pipeline::back::bundle::write_zip(&files).expect("zip");
    std::fs::write(&input, &original).expect("write");
    let link = dir.path().join("link.zip");
    std::os::unix::fs::symlink(&input, &link).expect("symlink");

    // The same path, the same file through a symlink (either side), and a file of an input folder.
    let folder = dir.path().join("bundle");
    std::fs::create_dir_all(folder.join("meshes")).expect("mkdir");
    for (name, bytes) in &files {
        std::fs::write(folder.join(name), bytes).expect("write");
    }
    let cases = [
        (input.clone(), input.clone()),
        (input.clone(), link.clone()),
        (link.clone(), input.clone()),
        (input.clone(), dir.path().join(".").join("in.zip")),
        (folder.clone(), folder.join("PENDULUM.xml")),
    ];
    for (from, to) in cases {
        let st = bin().arg("convert").arg(&from).arg("-o").arg(&to).output().expect("run");
        let err = String::from_utf8_lossy(&st.stderr);
        assert_eq!(st.status.code(), Some(2), "{} -> {}: {err}", from.display(), to.display());
        assert!(err.contains("is the input bundle"), "{err}");
    }
    assert_eq!(std::fs::read(&input).expect("input"), original, "the input is untouched");
    assert_eq!(std::fs::read(folder.join("PENDULUM.xml")).expect("xml"), files[0].1);

    // Another name next to it is fine, and so is a new file in the input folder.
    let st = bin().arg("convert").arg(&input).arg("-o").arg(dir.path().join("out.zip")).output().expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
    let st = bin().arg("convert").arg(&folder).arg("-o").arg(folder.join("out.zip")).output().expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
}

#[test]
fn fifos_and_devices_are_refused_not_read() {
    let dir = tempfile::tempdir().expect("tempdir");
    let fifo = dir.path().join("bundle.zip");
    let st = Command::new("mkfifo").arg(&fifo).status().expect("mkfifo");
    assert!(st.success());
    for input in [fifo.clone(), PathBuf::from("/dev/zero")] {
        for sub in ["inspect", "convert"] {
            let mut cmd = bin();
            cmd.arg(sub).arg(&input);
            if sub == "convert" {
                cmd.arg("-o").arg(dir.path().join("out.zip"));
            }
            let out = run_bounded(&mut cmd);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{sub} {}: {err}", input.display());
            assert!(err.contains("not a regular file"), "{err}");
        }
    }
    // A FIFO inside a bundle folder is skipped (only regular files are read).
    let folder = dir.path().join("bundle");
    std::fs::create_dir_all(folder.join("meshes")).expect("mkdir");
    for f in ["PENDULUM.xml", "meshes/LINK_prt.stl"] {
        std::fs::copy(case("pendulum").join(f), folder.join(f)).expect("copy");
    }
    assert!(Command::new("mkfifo").arg(folder.join("extra.stl")).status().expect("mkfifo").success());
    let out = run_bounded(bin().arg("inspect").arg(&folder));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn token_list_and_revoke_never_show_tokens() {
    let dir = tempfile::tempdir().expect("tempdir");
    let create = |name: &str, extra: &[&str]| {
        let st = bin().args(["token", "create", "--name", name]).args(extra).arg("--data-dir").arg(dir.path()).output().expect("run");
        assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
        String::from_utf8_lossy(&st.stdout).trim().to_string()
    };
    let ci = create("ci", &[]);
    let laptop = create("laptop", &["--expires-in", "30d"]);
    let list = || {
        let st = bin().args(["token", "list", "--data-dir"]).arg(dir.path()).output().expect("run");
        assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
        String::from_utf8_lossy(&st.stdout).to_string()
    };
    let text = list();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(lines[0].contains("  ci  ") && lines[0].contains("expires never"), "{text}");
    assert!(lines[1].contains("  laptop  ") && !lines[1].contains("expires never"), "{text}");
    assert!(!text.contains(&ci) && !text.contains(&laptop), "tokens are never shown: {text}");
    let hash_tail = |t: &str| {
        use sha2::Digest;
        let h = hex::encode(sha2::Sha256::digest(t.as_bytes()));
        h[h.len() - 8..].to_string()
    };
    assert!(lines[0].ends_with(&hash_tail(&ci)), "{text}");

    // Revoke by name, then by id; unknown names fail, a duplicated name asks for the id.
    let revoke = |what: &str| bin().args(["token", "revoke", what, "--data-dir"]).arg(dir.path()).output().expect("run");
    assert!(revoke("ci").status.success());
    assert!(!list().contains("  ci  "));
    let id = list().split_whitespace().next().expect("id").to_string();
    assert!(revoke(&id).status.success());
    assert_eq!(list(), "");
    let st = revoke("nope");
    assert_eq!(st.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&st.stderr).contains("no token"));
    create("twin", &[]);
    create("twin", &[]);
    let st = revoke("twin");
    assert_eq!(st.status.code(), Some(2), "ambiguous");
    assert!(String::from_utf8_lossy(&st.stderr).contains("by id"));

    // Bad expiries are usage errors.
    for bad in ["30", "0d", "3y", "-1d", "d"] {
        let st = bin().args(["token", "create", "--expires-in", bad, "--data-dir"]).arg(dir.path()).output().expect("run");
        assert_eq!(st.status.code(), Some(2), "--expires-in {bad}");
    }
}

#[test]
fn token_create_says_which_database_it_wrote_to() {
    let dir = tempfile::tempdir().expect("tempdir");
    // Without --data-dir: the default `data` folder of the working directory.
    let st = bin()
        .args(["token", "create"])
        .current_dir(dir.path())
        .env_remove("CAD2MO_DATA_DIR")
        .env_remove("CAD2MO_DATABASE_URL")
        .output()
        .expect("run");
    assert!(st.status.success(), "{}", String::from_utf8_lossy(&st.stderr));
    let err = String::from_utf8_lossy(&st.stderr);
    let db = dir.path().canonicalize().expect("canonical").join("data").join("cad2mo.db");
    assert!(err.contains(&db.display().to_string()), "{err}");
    assert!(db.exists());
    assert!(!String::from_utf8_lossy(&st.stdout).contains("data"), "stdout is only the token");
}
