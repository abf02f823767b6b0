//! Every number the converter writes is finite: the Modelica text, report.json, the DXF and the
//! binary STL shapes of every golden case and every real export in `../shared/fixtures`.
//! (Validation refuses non-finite and implausible input; this checks the outputs themselves.)

use cad2mo_engine::pipeline::{Options, Output};
use cad2mo_tests::common::{convert_path, files_with_ext, fixtures_dir, sorted_dirs, workspace_root};
use serde_json::Value;

/// Report keys whose value may be null (optional facts), never inside an array.
const OPTIONAL: &[&str] = &["vrml", "axis_world", "planar_normal", "lumped_into", "connector", "shape", "package_name"];

fn json_problems(v: &Value, path: &str, out: &mut Vec<String>) {
    match v {
        Value::Array(items) => {
            for (i, x) in items.iter().enumerate() {
                if x.is_null() {
                    out.push(format!("{path}[{i}] is null (a NaN or infinity serialises as null)"));
                }
                json_problems(x, &format!("{path}[{i}]"), out);
            }
        }
        Value::Object(map) => {
            for (k, x) in map {
                if x.is_null() && !OPTIONAL.contains(&k.as_str()) {
                    out.push(format!("{path}.{k} is null"));
                }
                json_problems(x, &format!("{path}.{k}"), out);
            }
        }
        _ => {}
    }
}

/// Words that are not finite numbers, outside string literals (Modelica) or anywhere (DXF).
fn bad_words(text: &str, skip_strings: bool) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_string = false;
    let mut word = String::new();
    let mut prev = '\0';
    for c in text.chars().chain(std::iter::once(' ')) {
        if skip_strings && c == '"' && prev != '\\' {
            in_string = !in_string;
        }
        prev = c;
        if in_string {
            continue;
        }
        if c.is_ascii_alphanumeric() || c == '_' || c == '.' {
            word.push(c);
        } else if !word.is_empty() {
            let w = word.to_ascii_lowercase();
            if ["nan", "inf", "infinity", "-inf"].contains(&w.as_str()) || w.contains("nan(") {
                out.push(word.clone());
            }
            word.clear();
        }
    }
    out
}

fn check(name: &str, out: &Output) -> usize {
    let mut problems = Vec::new();
    let mut numbers = 0;
    for (path, bytes) in &out.files {
        let bytes = &*bytes.bytes();
        if path.ends_with(".mo") {
            let text = std::str::from_utf8(bytes).expect("utf-8");
            problems.extend(bad_words(text, true).into_iter().map(|w| format!("{path}: {w}")));
        } else if path.ends_with(".dxf") {
            let text = String::from_utf8_lossy(bytes);
            problems.extend(bad_words(&text, false).into_iter().map(|w| format!("{path}: {w}")));
        } else if path.ends_with(".stl") && bytes.len() >= 84 {
            for (i, c) in bytes[84..].chunks_exact(50).enumerate() {
                for k in 0..12 {
                    let v = f32::from_le_bytes([c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]]);
                    numbers += 1;
                    if !v.is_finite() {
                        problems.push(format!("{path}: facet {i} value {k} is {v}"));
                    }
                }
            }
        } else if path.ends_with(".json") {
            let v: Value = serde_json::from_slice(bytes).expect("json");
            json_problems(&v, path, &mut problems);
        }
    }
    assert!(problems.is_empty(), "{name}: non-finite numbers:\n{}", problems.join("\n"));
    numbers
}

fn options() -> Options {
    Options::default()
}

#[test]
fn golden_outputs_are_finite() {
    let mut checked = 0;
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        if let Ok(out) = convert_path(&case, &options()) {
            check(&name, &out);
            checked += 1;
        }
    }
    assert!(checked >= 15, "only {checked} cases");
}

#[test]
fn fixture_outputs_are_finite() {
    let Some(fx) = fixtures_dir("fixture_outputs_are_finite") else { return };
    let mut checked = 0;
    for xml in files_with_ext(&fx, &[".xml"]) {
        let text = std::fs::read_to_string(&xml).expect("xml");
        if !text.contains("<PhysicalModelingXMLFile") {
            continue;
        }
        let (bundle, _tmp) = cad2mo_tests::common::fixture_bundle(&xml);
        let out = convert_path(&bundle, &options()).unwrap_or_else(|e| panic!("{}: {e}", xml.display()));
        check(&xml.display().to_string(), &out);
        checked += 1;
    }
    println!("{checked} fixture exports: every written number finite");
}

#[test]
fn the_scanners_see_non_finite_numbers() {
    assert_eq!(bad_words("  r={0.1, NaN, inf} \"not nan here\"", true), ["NaN", "inf"]);
    assert!(bad_words("m=1e-5, n=\"nan\"", true).is_empty());
    let mut p = Vec::new();
    json_problems(&serde_json::json!({"a": [1.0, null], "mass": null, "vrml": null}), "r", &mut p);
    assert_eq!(p, ["r.a[1] is null (a NaN or infinity serialises as null)", "r.mass is null"]);
}
