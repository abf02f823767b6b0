//! The deployment example (deploy/compose.yaml, deploy/nginx.conf) cannot run here (no Docker), so
//! it is checked statically: the compose file is valid YAML (read by Python's yaml) with the
//! services docs/deployment.md describes, every CAD2MO_* variable it sets is one `cad2mo serve`
//! accepts, and nginx accepts the uploads the instances accept and proxies to every instance.

use std::collections::BTreeSet;
use std::process::Command;

use cad2mo_tests::common::{tools_required, workspace_root};
use serde_json::Value;

/// deploy/compose.yaml as JSON, read by PyYAML (`None` with a notice when it is not installed).
fn compose() -> Option<Value> {
    let path = workspace_root().join("deploy/compose.yaml");
    let out = Command::new("python3")
        .args(["-c", "import json, sys, yaml; print(json.dumps(yaml.safe_load(open(sys.argv[1]))))"])
        .arg(&path)
        .output();
    match out {
        Ok(o) if o.status.success() => Some(serde_json::from_slice(&o.stdout).expect("json from python")),
        Ok(o) if String::from_utf8_lossy(&o.stderr).contains("No module named 'yaml'") && !tools_required() => {
            println!("NOTICE: deploy/compose.yaml not checked: PyYAML is not installed");
            None
        }
        Ok(o) => panic!("deploy/compose.yaml is not valid YAML:\n{}", String::from_utf8_lossy(&o.stderr)),
        Err(e) => {
            assert!(!tools_required(), "python3: {e}");
            println!("NOTICE: deploy/compose.yaml not checked: no python3 ({e})");
            None
        }
    }
}

/// The services running the cad2mo image.
fn cad2mo_services(c: &Value) -> Vec<(&String, &Value)> {
    c["services"].as_object().expect("services").iter().filter(|(_, s)| s["image"] == "cad2mo:local").collect()
}

#[test]
fn compose_file_is_valid_and_complete() {
    let Some(c) = compose() else { return };
    let services = c["services"].as_object().expect("services");
    for needed in ["postgres", "minio", "nginx"] {
        assert!(services.contains_key(needed), "no {needed} service");
    }
    let instances = cad2mo_services(&c);
    assert!(instances.len() >= 2, "two cad2mo instances: {:?}", instances.iter().map(|i| i.0).collect::<Vec<_>>());
    for (name, s) in &instances {
        let env = s["environment"].as_object().unwrap_or_else(|| panic!("{name}: environment"));
        let get = |k: &str| env.get(k).and_then(Value::as_str).unwrap_or_else(|| panic!("{name}: no {k}"));
        assert!(get("CAD2MO_DATABASE_URL").starts_with("postgres://"), "{name}: PostgreSQL");
        assert!(get("CAD2MO_BLOB_URL").starts_with("s3://"), "{name}: S3 blobs");
        assert!(get("CAD2MO_S3_ENDPOINT").contains("minio"), "{name}: MinIO endpoint");
        assert!(!get("CAD2MO_BIND").starts_with("127."), "{name}: reachable by nginx");
    }
}

#[test]
fn every_cad2mo_variable_is_accepted_by_serve() {
    let Some(c) = compose() else { return };
    let mut vars = BTreeSet::new();
    for (_, s) in c["services"].as_object().expect("services") {
        for k in s["environment"].as_object().into_iter().flat_map(|e| e.keys()) {
            if k.starts_with("CAD2MO_") {
                vars.insert(k.clone());
            }
        }
    }
    assert!(vars.len() >= 8, "{vars:?}");
    let bin = cad2mo_tests::instances::binary();
    let help = Command::new(&bin).args(["serve", "--help"]).output().expect("cad2mo serve --help");
    let help = String::from_utf8_lossy(&help.stdout);
    let unknown: Vec<&String> = vars.iter().filter(|v| !help.contains(&format!("env: {v}"))).collect();
    assert!(unknown.is_empty(), "deploy/compose.yaml sets variables `cad2mo serve` does not read: {unknown:?}");
}

#[test]
fn nginx_takes_the_uploads_and_reaches_every_instance() {
    let Some(c) = compose() else { return };
    let conf = std::fs::read_to_string(workspace_root().join("deploy/nginx.conf")).expect("nginx.conf");
    let body = conf.split("client_max_body_size").nth(1).and_then(|r| r.split(';').next()).expect("client_max_body_size").trim();
    let nginx_bytes: u64 = match body.strip_suffix('m') {
        Some(mb) => mb.parse::<u64>().expect("MB") * 1024 * 1024,
        None => body.parse().expect("bytes"),
    };
    for (name, s) in cad2mo_services(&c) {
        let max: u64 = s["environment"]["CAD2MO_MAX_UPLOAD"].as_str().expect("CAD2MO_MAX_UPLOAD").parse().expect("number");
        assert!(nginx_bytes >= max, "nginx refuses uploads {name} accepts: {nginx_bytes} < {max}");
        assert!(conf.contains(&format!("server {name}:8080")), "nginx has no upstream {name}");
    }
}
