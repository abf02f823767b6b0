//! Golden-file tests: every bundle in `tests/in/<case>` converts to exactly what
//! `tests/out/<case>/` holds (an IR dump, the Modelica files, the report, the file list), or
//! fails with exactly the error in `tests/out/<case>/error.txt`.
//!
//! Bless changes with `UPDATE_EXPECT=1 cargo test -p cad2mo-tests --test golden`, then review the
//! diff of `tests/out` like code. CI fails on any uncommitted difference there.

use std::path::Path;

use cad2mo_engine::pipeline::front::bundle::Limits;
use cad2mo_engine::pipeline::{self, ir, Options};
use cad2mo_tests::common::{file_text, modelica_syntax_errors, msl_check, sorted_dirs, workspace_root, write_output};
use serde_json::Value;

/// Options from `tests/in/<case>/options.json`, when present.
fn case_options(case: &Path) -> Options {
    let mut opts = Options::default();
    let Ok(text) = std::fs::read_to_string(case.join("options.json")) else { return opts };
    let v: Value = serde_json::from_str(&text).expect("options.json is JSON");
    if let Some(b) = v["lump_welds"].as_bool() {
        opts.lump_welds = b;
    }
    if let Some(p) = v["package_name"].as_str() {
        opts.package_name = Some(p.to_string());
    }
    if let Some(g) = v["gravity"].as_array() {
        let g: Vec<f64> = g.iter().filter_map(Value::as_f64).collect();
        opts.gravity = Some([g[0], g[1], g[2]]);
    }
    opts
}

fn expect_json(case: &Path) -> Value {
    std::fs::read_to_string(case.join("expect.json")).map(|t| serde_json::from_str(&t).expect("expect.json is JSON")).unwrap_or(Value::Null)
}

/// Compares `actual` with the file, or writes it when blessing. Returns a mismatch message.
fn check_file(path: &Path, actual: &str, bless: bool) -> Option<String> {
    if bless {
        std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
        std::fs::write(path, actual).expect("write expectation");
        return None;
    }
    let expected = std::fs::read_to_string(path).unwrap_or_default();
    if expected == actual {
        return None;
    }
    let line =
        expected.lines().zip(actual.lines()).position(|(a, b)| a != b).unwrap_or(expected.lines().count().min(actual.lines().count()));
    Some(format!(
        "{} differs at line {}:\n  expected: {}\n  actual:   {}",
        path.display(),
        line + 1,
        expected.lines().nth(line).unwrap_or("<end of file>"),
        actual.lines().nth(line).unwrap_or("<end of file>")
    ))
}

#[test]
fn golden() {
    let bless = std::env::var("UPDATE_EXPECT").is_ok_and(|v| v == "1");
    let root = workspace_root();
    let cases = sorted_dirs(&root.join("tests/in"));
    assert!(cases.len() >= 10, "expected the golden cases under tests/in, found {}", cases.len());
    let mut problems = Vec::new();
    for case in &cases {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        let out_dir = root.join("tests/out").join(&name);
        let opts = case_options(case);
        let expect = expect_json(case);
        let bundle = cad2mo::read_bundle(case, &Limits::default()).expect("read bundle");
        match pipeline::convert(&bundle, &opts) {
            Err(e) => {
                let mut text = format!("{e}\n");
                for d in e.diagnostics() {
                    text.push_str(&format!("diagnostic: {}:{}:{}: {}\n", d.file, d.line, d.column, d.message));
                }
                problems.extend(check_file(&out_dir.join("error.txt"), &text, bless));
                match expect["error_contains"].as_str() {
                    Some(want) if text.contains(want) => {}
                    Some(want) => problems.push(format!("{name}: error does not contain {want:?}: {text}")),
                    None => problems.push(format!("{name}: unexpected conversion error: {text}")),
                }
            }
            Ok(out) => {
                if let Some(want) = expect["error_contains"].as_str() {
                    problems.push(format!("{name}: converted, but an error containing {want:?} was expected"));
                }
                let analysed = pipeline::analyse(&bundle, &opts).expect("analyse succeeds when convert did");
                problems.extend(check_file(&out_dir.join("ir.txt"), &ir::dump::dump(&analysed.model), bless));
                for f in ["Mechanics.mo", "Mechatronics.mo", "package.mo", "report.json"] {
                    let text = file_text(&out, &format!("/{f}")).or_else(|| file_text(&out, f)).expect("file present");
                    problems.extend(check_file(&out_dir.join(f), &text, bless));
                }
                if let Some(mjcf) = file_text(&out, ".mjcf.xml") {
                    problems.extend(check_file(&out_dir.join("model.mjcf.xml"), &mjcf, bless));
                }
                let list: String = out.files.iter().map(|(p, b)| format!("{p} {}\n", b.len())).collect();
                problems.extend(check_file(&out_dir.join("files.txt"), &list, bless));
                let (nb, nj) = (out.report.bodies.len() as u64, out.report.joints.len() as u64);
                if !opts.lump_welds {
                    if let Some(b) = expect["bodies"].as_u64() {
                        if b != nb {
                            problems.push(format!("{name}: {nb} bodies, expected {b}"));
                        }
                    }
                }
                // Every CAD joint is reported, welds absorbed by lumping included.
                if let Some(j) = expect["joints"].as_u64() {
                    if j != nj {
                        problems.push(format!("{name}: {nj} joints in the report, expected {j}"));
                    }
                }
                // Loop cases state how their loop must be cut.
                if let Some(want) = expect["expected_cut"].as_object() {
                    for l in &out.report.loops {
                        for (key, value) in want {
                            let got = match key.as_str() {
                                "cut" => Value::from(l.cut.clone()),
                                "kind" => Value::from(l.kind),
                                "mobility" => Value::from(l.mobility),
                                other => Value::from(format!("unknown key {other}")),
                            };
                            if got != *value {
                                problems.push(format!("{name}: loop closed by {}: {key} is {got}, expected {value}", l.closing_joint));
                            }
                        }
                    }
                }
                if let Some(l) = expect["loops"].as_u64() {
                    let got = out.report.loops.len() as u64;
                    if l != got {
                        problems.push(format!("{name}: {got} loops, expected {l}"));
                    }
                }
                let dir = tempfile::tempdir().expect("tempdir");
                write_output(&out, dir.path());
                if let Some(Err(msg)) = msl_check(dir.path()) {
                    problems.push(format!("{name}: msl-check: {msg}"));
                }
                if let Some(errors) = modelica_syntax_errors(dir.path()) {
                    if !errors.is_empty() {
                        problems.push(format!("{name}: Modelica syntax errors:\n{}", errors.join("\n")));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{} golden problems:\n{}", problems.len(), problems.join("\n\n"));
}

/// The cases under tests/in are exactly what `tests/tools/make_fixtures.py` writes, and its
/// independent checker `check_fixtures.py` accepts them (poses, masses, meshes, each broken case's
/// one flaw).
#[test]
fn golden_inputs_are_what_the_generator_writes() {
    let root = workspace_root();
    let tmp = tempfile::tempdir().expect("tempdir");
    let run = |script: &str, arg: &Path| {
        let out = std::process::Command::new("python3").arg(root.join("tests/tools").join(script)).arg(arg).output().expect("python3 runs");
        assert!(out.status.success(), "{script}: {}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    };
    run("make_fixtures.py", tmp.path());
    let mut compared = 0;
    for case in sorted_dirs(tmp.path()) {
        for entry in walk(&case) {
            let rel = entry.strip_prefix(tmp.path()).expect("under tmp");
            let committed = std::fs::read(root.join("tests/in").join(rel)).unwrap_or_default();
            assert!(
                std::fs::read(&entry).expect("read") == committed,
                "tests/in/{} differs from the generator's output: run python3 tests/tools/make_fixtures.py",
                rel.display()
            );
            compared += 1;
        }
    }
    assert!(compared > 50, "only {compared} files compared");
    run("check_fixtures.py", &root.join("tests/in"));
}

fn walk(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).expect("read_dir").flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}
