//! Unit tests of the mechatronics back end. They may do IO: the generated packages are written to
//! a temporary folder and checked with `msl-check` and `rumoca-lint` (skipped with a notice when
//! the tools are missing, unless `CAD2MO_REQUIRE_TOOLS=1`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use super::*;

const MOTOR: &str = "cad2mo.Drives.Motors.DCPermanentMagnet";
const MSL_MOTOR: &str = "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet";
const SERVO_MOTOR: &str = "cad2mo.Drives.Motors.ServoMotor";
const IDEAL: &str = "Modelica.Mechanics.Rotational.Components.IdealGear";
const EFFICIENCY: &str = "cad2mo.Drives.Gears.Efficiency";
const SCREW: &str = "cad2mo.Drives.Gears.LeadScrew";
const PPI: &str = "cad2mo.Drives.Controllers.CascadePPI";

fn choice(class: &str, params: &[(&str, ParamValue)]) -> ClassChoice {
    ClassChoice {
        modelica_class: class.to_string(),
        params: params.iter().map(|(n, v)| (n.to_string(), v.clone())).collect(),
        instance: String::new(),
    }
}

fn r(x: f64) -> ParamValue {
    ParamValue::Real(x)
}

fn plan(joint: &str) -> DrivePlan {
    DrivePlan {
        joint: joint.to_string(),
        kind: JointKind::Revolute,
        start: 0.0,
        motor: choice(MOTOR, &[("R", r(0.299)), ("k", r(0.0302)), ("I_max", r(10.0))]),
        gear: choice(IDEAL, &[("ratio", r(50.0))]),
        controller: choice(PPI, &[("kp", r(10.0)), ("ks", r(0.05)), ("Ts", r(0.05))]),
        reference: Reference::Constant(0.5),
        label: format!("joint {joint} (nodeID 1:-:2)"),
    }
}

fn text(files: &[(String, Vec<u8>)], path: &str) -> String {
    let (_, bytes) = files.iter().find(|(p, _)| p == path).unwrap_or_else(|| panic!("{path} not written"));
    String::from_utf8(bytes.clone()).expect("utf-8")
}

fn output_text(out: &crate::pipeline::Output, path: &str) -> String {
    let (_, bytes) = out.files.iter().find(|(p, _)| p == path).unwrap_or_else(|| panic!("{path} not written"));
    String::from_utf8(bytes.bytes().into_owned()).expect("utf-8")
}

fn mechatronics_text(drives: &[DrivePlan]) -> String {
    let files = mechatronics("P", drives, &[], Default::default(), "<p>From \"x.xml\".</p>").expect("mechatronics");
    assert_eq!(files.len(), 1);
    text(&files, "P/Mechatronics.mo")
}

// ----------------------------------------------------------------------------------------------
// The class table and known_classes.

#[test]
fn known_classes_cover_every_slot() {
    let known = known_classes();
    let paths: Vec<&str> = known.iter().map(|k| k.modelica_class).collect();
    assert_eq!(paths, [MOTOR, MSL_MOTOR, SERVO_MOTOR, IDEAL, EFFICIENCY, SCREW, PPI]);
    for k in &known {
        assert!(["motor", "gear", "controller"].contains(&k.domain), "{k:?}");
        assert!(!k.params.is_empty(), "{k:?}");
        for (name, ty, _unit) in k.params {
            assert!(is_identifier(name), "{name}");
            assert!(["Real", "Integer", "Boolean", "String"].contains(ty), "{name}: {ty}");
        }
    }
    let ppi = known.iter().find(|k| k.modelica_class == PPI).expect("ppi");
    assert_eq!(ppi.params, &[("kp", "Real", "1/s"), ("ks", "Real", "A.s/rad"), ("Ts", "Real", "s")]);
    // Stable across calls (the parameter lists are built once).
    assert_eq!(known_classes(), known);
}

/// The MSL index, or `None` with a notice.
fn msl_index() -> Option<serde_json::Value> {
    let path = shared().join("msl/msl-4.0.0.json");
    match std::fs::read(&path) {
        Ok(bytes) => Some(serde_json::from_slice(&bytes).expect("MSL index is JSON")),
        Err(e) => {
            assert!(!require_tools(), "MSL index {} not readable: {e}", path.display());
            println!("NOTICE: MSL index {} not found; skipping", path.display());
            None
        }
    }
}

/// Components of an MSL class and its bases: name -> entry.
fn msl_members(classes: &serde_json::Value, path: &str, out: &mut BTreeMap<String, serde_json::Value>) {
    let Some(c) = classes.get(path) else { return };
    if let Some(comps) = c["components"].as_object() {
        for (k, v) in comps {
            out.entry(k.clone()).or_insert_with(|| v.clone());
        }
    }
    for b in c["extends"].as_array().into_iter().flatten() {
        if let Some(b) = b.as_str() {
            msl_members(classes, b, out);
        }
    }
}

#[test]
fn msl_class_parameters_exist_in_msl() {
    let Some(index) = msl_index() else { return };
    let classes = &index["classes"];
    for k in known_classes().iter().filter(|k| k.modelica_class.starts_with("Modelica.")) {
        assert!(classes.get(k.modelica_class).is_some(), "{} not in MSL 4.0.0", k.modelica_class);
        let mut members = BTreeMap::new();
        msl_members(classes, k.modelica_class, &mut members);
        for (name, _, _) in k.params {
            let m = members.get(*name).unwrap_or_else(|| panic!("{} has no {name}", k.modelica_class));
            assert_eq!(m["parameter"], true, "{}.{name} is not a parameter", k.modelica_class);
            assert_eq!(m["protected"], false, "{}.{name} is protected", k.modelica_class);
            assert_eq!(m["final"], false, "{}.{name} is final", k.modelica_class);
        }
    }
}

#[test]
fn every_library_parameter_is_declared_in_its_class() {
    let files = components("P");
    for s in SPECS {
        let class_file = format!("P/Components/Drives/{}.mo", s.class.replace('.', "/"));
        let own = text(&files, &class_file);
        for p in s.params {
            let decl = format!("parameter {} {}", p.mtype, p.name);
            let found = if p.inherited {
                let iface = if s.domain == Domain::Gear { "Gear" } else { "?" };
                text(&files, &format!("P/Components/Drives/Interfaces/{iface}.mo")).contains(&decl)
            } else {
                own.contains(&decl)
            };
            assert!(found, "{}: `{decl}` not declared", s.path);
        }
    }
}

#[test]
fn drive_library_is_a_structured_package() {
    let files = components("Robot");
    let paths: Vec<&str> = files.iter().map(|(p, _)| p.as_str()).collect();
    assert!(paths.iter().all(|p| p.starts_with("Robot/Components/Drives/")), "{paths:?}");
    let mut dirs: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (path, bytes) in &files {
        let s = String::from_utf8(bytes.clone()).expect("utf-8");
        assert!(!s.contains('$'), "{path}: unfilled template placeholder");
        let (dir, file) = path.rsplit_once('/').expect("in a folder");
        let within = dir.replace('/', ".");
        if let Some(name) = file.strip_suffix(".mo") {
            let within = if name == "package" { within.rsplit_once('.').expect("parent").0.to_string() } else { within };
            let name = if name == "package" { dir.rsplit('/').next().expect("dir").to_string() } else { name.to_string() };
            assert!(s.starts_with(&format!("within {within};\n")), "{path}: within");
            assert!(s.trim_end().ends_with(&format!("end {name};")), "{path}: end {name}");
            if file != "package.mo" {
                dirs.entry(dir.to_string()).or_default().push(name);
            }
        }
    }
    // Every package.order lists exactly the classes and sub-packages of its folder.
    for (path, bytes) in files.iter().filter(|(p, _)| p.ends_with("/package.order")) {
        let dir = path.trim_end_matches("/package.order");
        let mut listed: Vec<String> = String::from_utf8(bytes.clone()).expect("utf-8").lines().map(str::to_string).collect();
        let mut present = dirs.get(dir).cloned().unwrap_or_default();
        for (p, _) in &files {
            if let Some(rest) = p.strip_prefix(&format!("{dir}/")) {
                if let Some((sub, "package.mo")) = rest.split_once('/') {
                    present.push(sub.to_string());
                }
            }
        }
        listed.sort();
        present.sort();
        assert_eq!(listed, present, "{path}");
    }
}

/// Splits Modelica text into the code outside string literals (each literal left as `""`) and
/// the literals' raw contents; panics on an unterminated literal.
fn split_strings(s: &str) -> (String, Vec<String>) {
    let mut code = String::new();
    let mut literals = Vec::new();
    let mut current: Option<String> = None;
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        match (&mut current, c) {
            (Some(lit), '\\') => {
                lit.push(c);
                if let Some(next) = chars.next() {
                    lit.push(next);
                }
            }
            (Some(_), '"') => {
                literals.extend(current.take());
                code.push('"');
            }
            (Some(lit), _) => lit.push(c),
            (None, '"') => {
                current = Some(String::new());
                code.push('"');
            }
            (None, _) => code.push(c),
        }
    }
    assert!(current.is_none(), "unterminated string literal");
    (code, literals)
}

#[test]
fn html_stays_inside_string_literals() {
    let mut files = components("P");
    files.extend(mechatronics("P", &[plan("J")], &[], Default::default(), "<p class=\"x\">a \\ b</p>").expect("mechatronics"));
    for (path, bytes) in files.iter().filter(|(p, _)| p.ends_with(".mo")) {
        let (code, literals) = split_strings(&String::from_utf8(bytes.clone()).expect("utf-8"));
        for tag in ["<p", "</", "<html", "<code", "<tr", "<pre", "<table", "<li", "cellspacing"] {
            assert!(!code.contains(tag), "{path}: `{tag}` outside a string literal:\n{code}");
        }
        // An unescaped quote would end the documentation early.
        for lit in literals.iter().filter(|l| l.contains("<html>")) {
            assert!(lit.starts_with("<html>") && lit.ends_with("</html>"), "{path}: broken documentation string:\n{lit}");
        }
    }
    // The check sees the mistake it guards against.
    let (_, lits) = split_strings("annotation (Documentation(info=\"<html><table border=\"1\"></table></html>\"));");
    assert!(!lits[0].ends_with("</html>"));
}

// ----------------------------------------------------------------------------------------------
// Mechatronics.mo

#[test]
fn no_drives_is_still_a_model() {
    let s = mechatronics_text(&[]);
    assert!(
        s.starts_with("within P;\nmodel Mechatronics \"Mechatronic model of P: Mechanics with no joint drive\"\n  extends P.Mechanics;\n"),
        "{s}"
    );
    assert!(s.contains("No drive is assigned"), "{s}");
    assert!(s.contains("<p>From \\\"x.xml\\\".</p>"), "provenance escaped for the string: {s}");
    assert!(s.trim_end().ends_with("end Mechatronics;"));
    assert!(!s.contains("connect("));
}

#[test]
fn one_revolute_drive() {
    let s = mechatronics_text(&[plan("RootPart_LINK")]);
    let expected_decl = "  P.Components.Drives.JointDrive drive_RootPart_LINK(
    redeclare P.Components.Drives.Motors.DCPermanentMagnet motor(
      R=0.299,
      k=0.0302,
      I_max=10.0),
    redeclare P.Components.Drives.Gears.Ideal gear(
      ratio=50.0),
    redeclare P.Components.Drives.Controllers.CascadePPI controller(
      kp=10.0,
      ks=0.05,
      Ts=0.05),
    useTable=false,
    q_constant=0.5)
    \"Drive of joint RootPart_LINK (nodeID 1:-:2)\"
";
    assert!(s.contains(expected_decl), "{s}");
    assert!(s.contains("equation\n  connect(drive_RootPart_LINK.flange, RootPart_LINK.drive);\n  annotation ("), "{s}");
    assert!(s.contains("Mechanics with 1 joint drive\""), "{s}");
    assert!(s.contains("<tr><td><code>RootPart_LINK</code></td>"), "{s}");
    assert!(s.contains("R=0.299 Ohm"), "documentation lists values with units: {s}");
    assert!(s.contains("a step from the start value 0.0 rad"), "{s}");
}

#[test]
fn parameters_follow_the_class_order_and_integers_widen() {
    let mut p = plan("J1");
    p.motor = choice(MOTOR, &[("I_max", ParamValue::Integer(8)), ("R", r(1.5))]);
    p.gear = choice(EFFICIENCY, &[("eta", r(0.9)), ("ratio", ParamValue::Integer(-100))]);
    p.controller = choice(PPI, &[]);
    let s = mechatronics_text(&[p]);
    assert!(s.contains("motor(\n      R=1.5,\n      I_max=8.0)"), "{s}");
    assert!(s.contains("redeclare P.Components.Drives.Gears.Efficiency gear(\n      ratio=-100.0,\n      eta=0.9)"), "{s}");
    assert!(s.contains("redeclare P.Components.Drives.Controllers.CascadePPI controller,\n"), "{s}");
}

#[test]
fn prismatic_drive_and_tables() {
    let mut p = plan("SLIDER");
    p.kind = JointKind::Prismatic;
    p.start = 0.025;
    p.gear = choice(SCREW, &[("ratio", r(2.0)), ("lead", r(0.004))]);
    p.reference = Reference::Table(vec![(0.5, 0.025), (1.5, 0.05), (1.5, 0.06), (3.0, 0.06)]);
    let mut q = plan("ARM");
    q.reference = Reference::Table(vec![(0.0, 0.1), (1.0, -0.2)]);
    let mut e = plan("HELD");
    e.start = 0.3;
    e.reference = Reference::Table(vec![]);
    let mut one = plan("ONE");
    one.reference = Reference::Table(vec![(-1.0, 0.7)]);
    let s = mechatronics_text(&[p, q, e, one]);
    assert!(s.contains("P.Components.Drives.LinearJointDrive drive_SLIDER("), "{s}");
    assert!(s.contains("redeclare P.Components.Drives.Gears.LeadScrew gear(\n      ratio=2.0,\n      lead=0.004)"), "{s}");
    // A table starting after t = 0 is preceded by the start value.
    assert!(s.contains("    useTable=true,\n    table=[0.0, 0.025; 0.5, 0.025; 1.5, 0.05; 1.5, 0.06; 3.0, 0.06])"), "{s}");
    assert!(s.contains("    useTable=true,\n    table=[0.0, 0.1; 1.0, -0.2])"), "{s}");
    // An empty table holds the start value; a one-point table is a constant.
    assert!(s.contains("drive_HELD(") && s.contains("    useTable=false,\n    q_constant=0.3)"), "{s}");
    assert!(s.contains("    useTable=false,\n    q_constant=0.7)"), "{s}");
    // The experiment covers the longest table.
    assert!(s.contains("experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06)"), "{s}");
    assert!(s.contains("Mechanics with 4 joint drives"), "{s}");
    assert!(s.contains("holds the start value"), "{s}");
}

#[test]
fn errors() {
    let err = |plans: &[DrivePlan]| mechatronics("P", plans, &[], Default::default(), "").expect_err("must fail");

    let mut p = plan("J");
    p.motor = choice(IDEAL, &[("ratio", r(2.0))]);
    let e = err(&[p]);
    assert!(matches!(&e, MechatronicsError::UnknownClass { slot: "motor", found, .. } if found.contains("gear class")), "{e:?}");
    assert!(e.to_string().contains("is not a known motor class (it is a gear class)"), "{e}");

    let mut p = plan("J");
    p.controller = choice("cad2mo.Drives.Controllers.Nope", &[]);
    assert!(matches!(err(&[p]), MechatronicsError::UnknownClass { slot: "controller", .. }));

    let mut p = plan("J");
    p.motor = choice(MOTOR, &[("Rx", r(1.0))]);
    let e = err(&[p]);
    assert!(matches!(&e, MechatronicsError::UnknownParameter { param, .. } if param == "Rx"), "{e:?}");
    assert!(e.to_string().contains("known: R, L, k, J, d, V_max, I_max, Tc"), "{e}");

    let mut p = plan("J");
    p.motor = choice(MOTOR, &[("R", r(1.0)), ("R", r(2.0))]);
    assert!(matches!(err(&[p]), MechatronicsError::DuplicateParameter { .. }));

    let mut p = plan("J");
    p.gear = choice(IDEAL, &[("ratio", ParamValue::String("50".into()))]);
    assert!(matches!(err(&[p]), MechatronicsError::WrongType { expected: "Real", got: "String", .. }));
    let mut p = plan("J");
    p.gear = choice(IDEAL, &[("ratio", ParamValue::Boolean(true))]);
    assert!(matches!(err(&[p]), MechatronicsError::WrongType { expected: "Real", got: "Boolean", .. }));

    for (param, value) in [("L", 0.0), ("R", -1.0), ("k", f64::NAN), ("J", f64::INFINITY)] {
        let mut p = plan("J");
        p.motor = choice(MOTOR, &[(param, r(value))]);
        assert!(matches!(err(&[p]), MechatronicsError::OutOfRange { .. }), "{param}={value}");
    }
    for eta in [0.0, 1.2] {
        let mut p = plan("J");
        p.gear = choice(EFFICIENCY, &[("eta", r(eta))]);
        assert!(matches!(err(&[p]), MechatronicsError::OutOfRange { .. }), "eta={eta}");
    }
    let mut p = plan("J");
    p.gear = choice(IDEAL, &[("ratio", r(0.0))]);
    assert!(matches!(err(&[p]), MechatronicsError::OutOfRange { .. }));

    assert!(matches!(err(&[plan("J"), plan("K"), plan("J")]), MechatronicsError::DuplicateJoint { joint } if joint == "J"));
    for bad in ["", "1J", "a-b", "model", "J K", "é"] {
        assert!(matches!(err(&[plan(bad)]), MechatronicsError::BadJointName { .. }), "{bad:?}");
    }

    // Gears fit one kind of joint.
    let mut p = plan("J");
    p.gear = choice(SCREW, &[("lead", r(0.005))]);
    assert!(matches!(err(&[p]), MechatronicsError::GearDoesNotFitJoint { fits: "prismatic", kind: "revolute", .. }));
    let mut p = plan("J");
    p.kind = JointKind::Prismatic;
    assert!(matches!(err(&[p]), MechatronicsError::GearDoesNotFitJoint { fits: "revolute", kind: "prismatic", .. }));

    for table in [vec![(1.0, 0.0), (0.5, 0.0)], vec![(0.0, f64::NAN)], vec![(1.0, 0.0), (1.0, 0.1), (1.0, 0.2)]] {
        let mut p = plan("J");
        p.reference = Reference::Table(table.clone());
        assert!(matches!(err(&[p]), MechatronicsError::BadReference { .. }), "{table:?}");
    }
    let mut p = plan("J");
    p.reference = Reference::Constant(f64::INFINITY);
    assert!(matches!(err(&[p]), MechatronicsError::BadReference { .. }));
    let mut p = plan("J");
    p.start = f64::NAN;
    assert!(matches!(err(&[p]), MechatronicsError::BadReference { .. }));

    assert!(matches!(mechatronics("1P", &[], &[], Default::default(), ""), Err(MechatronicsError::BadPackageName(_))));
}

#[test]
fn labels_and_strings_are_escaped() {
    let mut p = plan("J");
    p.label = "joint \"A<B>\" \\ x".to_string();
    let s = mechatronics_text(&[p]);
    assert!(s.contains("\"Drive of joint \\\"A<B>\\\" \\\\ x\""), "{s}");
    assert!(s.contains("joint \\\"A&lt;B&gt;\\\" \\\\ x"), "{s}");
}

// ----------------------------------------------------------------------------------------------
// Checking with the tools, on real converted packages.

fn require_tools() -> bool {
    std::env::var("CAD2MO_REQUIRE_TOOLS").is_ok_and(|v| v == "1")
}

fn shared() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared")
}

fn rumoca_lint() -> Option<PathBuf> {
    let mut candidates = vec![PathBuf::from("rumoca-lint")];
    if let Some(cargo_home) = std::env::var_os("CARGO_HOME") {
        candidates.push(Path::new(&cargo_home).join("bin/rumoca-lint"));
    }
    if let Some(home) = std::env::var_os("HOME") {
        candidates.push(Path::new(&home).join(".cargo/bin/rumoca-lint"));
    }
    candidates.into_iter().find(|c| Command::new(c).arg("--version").output().is_ok_and(|o| o.status.success()))
}

/// Runs `msl-check` and `rumoca-lint` on `dir`; panics on a problem. Returns the number of tools run.
fn check_with_tools(dir: &Path) -> usize {
    let mut ran = 0;
    let msl_check = shared().join("tools/msl-check");
    match Command::new("python3").arg(&msl_check).arg(dir).output() {
        Ok(o) if msl_check.is_file() => {
            let out = String::from_utf8_lossy(&o.stdout);
            assert!(o.status.success() && out.contains(" 0 problems"), "msl-check {}:\n{out}", dir.display());
            ran += 1;
        }
        _ => {
            assert!(!require_tools(), "msl-check not runnable");
            println!("NOTICE: {} or python3 missing; skipping msl-check", msl_check.display());
        }
    }
    match rumoca_lint() {
        Some(lint) => {
            let o = Command::new(lint).args(["-l", "error", "-f", "compact"]).arg(dir).output().expect("run rumoca-lint");
            let out = String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
            let parse_errors: Vec<&str> = out.lines().filter(|l| l.contains("[parse-error]")).collect();
            assert!(parse_errors.is_empty(), "rumoca-lint {}:\n{}", dir.display(), parse_errors.join("\n"));
            ran += 1;
        }
        None => {
            assert!(!require_tools(), "rumoca-lint not found");
            println!("NOTICE: rumoca-lint not found; skipping the parse check");
        }
    }
    ran
}

/// Converts `tests/in/<case>`, returning its files and report.
fn convert_case(case: &str) -> (Vec<(String, Vec<u8>)>, crate::pipeline::report::Report) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in").join(case);
    let bundle = crate::test_bundle_of_dir(&dir).expect("read bundle");
    let out = crate::pipeline::convert(&bundle, &crate::pipeline::Options::default()).expect("convert");
    (out.files.into_iter().map(|(p, b)| (p, b.into_bytes())).collect(), out.report)
}

/// Writes a converted package plus the drive library and `Mechatronics.mo` to a temporary folder
/// (adding `Drives` to `Components/package.order`, as the lead will in `write.rs`).
fn write_package(files: Vec<(String, Vec<u8>)>, pkg: &str, drives: &[DrivePlan]) -> (tempfile::TempDir, String) {
    write_package_with(files, pkg, drives, &[])
}

fn write_package_with(
    files: Vec<(String, Vec<u8>)>,
    pkg: &str,
    drives: &[DrivePlan],
    motions: &[MotionTable],
) -> (tempfile::TempDir, String) {
    let mut all = files;
    all.extend(components(pkg));
    let mech = mechatronics(pkg, drives, motions, Default::default(), "<p>Converted by cad2mo for a test.</p>").expect("mechatronics");
    let text = String::from_utf8(mech[0].1.clone()).expect("utf-8");
    all.extend(mech);
    let tmp = tempfile::tempdir().expect("tempdir");
    for (path, bytes) in &mut all {
        if path == &format!("{pkg}/Components/package.order") {
            let s = String::from_utf8_lossy(bytes).into_owned();
            if !s.lines().any(|l| l == "Drives") {
                bytes.extend_from_slice(b"Drives\n");
            }
        }
        if path == &format!("{pkg}/package.order") {
            let s = String::from_utf8_lossy(bytes).into_owned();
            if !s.lines().any(|l| l == "Mechatronics") {
                *bytes = s.replace("Mechanics\n", "Mechanics\nMechatronics\n").into_bytes();
            }
            if !motions.is_empty() {
                bytes.extend_from_slice(b"Motions\n");
            }
        }
        let p = tmp.path().join(&*path);
        std::fs::create_dir_all(p.parent().expect("parent")).expect("mkdir");
        std::fs::write(&p, &*bytes).expect("write");
    }
    (tmp, text)
}

/// Drive plans for every revolute and prismatic joint of a report, cycling through the classes.
fn plans_for(report: &crate::pipeline::report::Report) -> Vec<DrivePlan> {
    let mut plans = Vec::new();
    for (n, j) in report.joints.iter().enumerate() {
        let kind = match j.emitted_as.as_str() {
            "revolute" => JointKind::Revolute,
            "prismatic" => JointKind::Prismatic,
            _ => continue,
        };
        let start = j.initial_q[0];
        let motor = if n % 2 == 0 {
            choice(MOTOR, &[("R", r(0.299)), ("L", r(8.2e-5)), ("k", r(0.0302)), ("J", r(1.42e-5)), ("V_max", r(24.0)), ("I_max", r(10.0))])
        } else {
            choice(
                MSL_MOTOR,
                &[
                    ("VaNominal", r(24.0)),
                    ("IaNominal", r(5.77)),
                    ("wNominal", r(726.0)),
                    ("Ra", r(0.299)),
                    ("La", r(8.2e-5)),
                    ("Jr", r(1.42e-5)),
                ],
            )
        };
        let gear = match (kind, n % 2) {
            (JointKind::Prismatic, _) => choice(SCREW, &[("ratio", r(1.0)), ("lead", r(0.005))]),
            (_, 0) => choice(IDEAL, &[("ratio", r(50.0))]),
            _ => choice(EFFICIENCY, &[("ratio", r(100.0)), ("eta", r(0.8))]),
        };
        let reference =
            if n % 2 == 0 { Reference::Constant(start + 0.1) } else { Reference::Table(vec![(0.2, start), (0.8, start + 0.01)]) };
        plans.push(DrivePlan {
            joint: j.elements[0].modelica_name.clone(),
            kind,
            start,
            motor,
            gear,
            controller: choice(PPI, &[("kp", r(10.0)), ("ks", r(0.05)), ("Ts", r(0.05))]),
            reference,
            label: format!("joint {} (nodeID {})", j.cad_name, j.node_id),
        });
    }
    plans
}

#[test]
fn pendulum_with_a_drive_passes_the_tools() {
    let (files, report) = convert_case("pendulum");
    let pkg = report.package_name.clone();
    let plans = plans_for(&report);
    assert_eq!(plans.len(), 1, "the pendulum has one revolute joint");
    assert_eq!(plans[0].joint, "RootPart_LINK");
    let (tmp, text) = write_package(files, &pkg, &plans);
    assert!(text.contains("connect(drive_RootPart_LINK.flange, RootPart_LINK.drive)"), "{text}");
    check_with_tools(&tmp.path().join(&pkg));
}

#[test]
fn revolute_and_prismatic_drives_pass_the_tools() {
    let (files, report) = convert_case("rotated_frames");
    let pkg = report.package_name.clone();
    let plans = plans_for(&report);
    let kinds: Vec<JointKind> = plans.iter().map(|p| p.kind).collect();
    assert!(kinds.contains(&JointKind::Revolute) && kinds.contains(&JointKind::Prismatic), "{kinds:?}");
    let (tmp, text) = write_package(files, &pkg, &plans);
    assert!(text.contains("LinearJointDrive"), "{text}");
    assert!(text.contains("Motors.MSL_DC_PermanentMagnet"), "{text}");
    check_with_tools(&tmp.path().join(&pkg));
}

/// A sampled motion of `axes` (a ramp of `amp` over 1 s, its speed and acceleration).
fn ramp(label: &str, axes: &[&str], amp: f64) -> MotionTable {
    let t: Vec<f64> = (0..=10).map(|i| f64::from(i) / 10.0).collect();
    let col = |f: &dyn Fn(f64) -> f64| -> Vec<Vec<f64>> { axes.iter().map(|_| t.iter().map(|x| f(*x)).collect()).collect() };
    MotionTable {
        label: label.into(),
        axes: axes.iter().map(|a| a.to_string()).collect(),
        q: col(&|x| amp * x * x),
        qd: col(&|x| 2.0 * amp * x),
        qdd: col(&|_| 2.0 * amp),
        t,
    }
}

#[test]
fn drives_following_motions_pass_the_tools() {
    let (files, report) = convert_case("rotated_frames");
    let pkg = report.package_name.clone();
    let plans = plans_for(&report);
    let axes: Vec<&str> = plans.iter().map(|p| p.joint.as_str()).collect();
    // The second motion lists the axes the other way round: each drive picks its own column.
    let reversed: Vec<&str> = axes.iter().rev().copied().collect();
    let motions = [ramp("pick & place", &axes, 0.1), ramp("pick & place", &reversed, 0.05)];
    let (tmp, text) = write_package_with(files, &pkg, &plans, &motions);
    assert!(text.contains("parameter Integer motion(min=1, max=2) = 1"), "{text}");
    assert!(text.contains("choices(choice=1 \"pick & place\", choice=2 \"pick & place\")"), "{text}");
    assert!(text.contains("Motions.pick_place motion_pick_place"), "{text}");
    assert!(text.contains("Motions.pick_place_2 motion_pick_place_2"), "{text}");
    let n = axes.len();
    let first = &plans[0].joint;
    assert!(
        text.contains(&format!("drive_{first}.q_motion = if motion == 1 then motion_pick_place.y[1] else motion_pick_place_2.y[{n}];")),
        "{text}"
    );
    assert!(
        text.contains(&format!(
            "drive_{first}.qd_motion = if motion == 1 then motion_pick_place.y[{}] else motion_pick_place_2.y[{}];",
            n + 1,
            2 * n
        )),
        "{text}"
    );
    assert!(text.contains("useMotion=true") && !text.contains("useTable"), "{text}");
    let table = std::fs::read_to_string(tmp.path().join(&pkg).join("Motions/pick_place.mo")).expect("table");
    assert!(table.contains("extends Modelica.Blocks.Sources.CombiTimeTable("), "{table}");
    // 11 rows of 1 + 3n columns: the last row is t = 1, q = 0.1, qd = 0.2, qdd = 0.2.
    let last = std::iter::once("1".to_string())
        .chain(std::iter::repeat_n("0.1".to_string(), n))
        .chain(std::iter::repeat_n("0.2".to_string(), 2 * n));
    assert!(table.contains(&format!("{}]", last.collect::<Vec<_>>().join(", "))), "{table}");
    assert!(text.contains("experiment(StopTime=1.5, Interval=0.005, Tolerance=1e-06)"), "{text}");
    check_with_tools(&tmp.path().join(&pkg));
    // Bad tables are refused, naming the motion.
    let mut bad = ramp("jumpy", &axes, 0.1);
    bad.t[3] = bad.t[2];
    let e = mechatronics(&pkg, &plans, &[bad], Default::default(), "").expect_err("times must increase");
    assert!(e.to_string().contains("motion \"jumpy\": times must start at 0 and increase"), "{e}");
}

#[test]
fn a_package_without_drives_passes_the_tools() {
    let (files, report) = convert_case("pendulum");
    let pkg = report.package_name.clone();
    let (tmp, _) = write_package(files, &pkg, &[]);
    check_with_tools(&tmp.path().join(&pkg));
}

#[test]
fn the_tools_catch_errors() {
    // The checks above are only worth something if the tools report what is wrong.
    let tmp = tempfile::tempdir().expect("tempdir");
    std::fs::write(
        tmp.path().join("Bad.mo"),
        "model Bad\n  Modelica.Mechanics.Rotational.Components.IdealGear g(ratioo=2);\nequation\n  x = (;\nend Bad;\n",
    )
    .expect("write");
    let msl_check = shared().join("tools/msl-check");
    if msl_check.is_file() {
        let o = Command::new("python3").arg(&msl_check).arg(tmp.path()).output().expect("msl-check");
        assert!(!o.status.success(), "msl-check accepts a wrong modifier");
    }
    if let Some(lint) = rumoca_lint() {
        let o = Command::new(lint).args(["-l", "error", "-f", "compact"]).arg(tmp.path()).output().expect("rumoca-lint");
        assert!(String::from_utf8_lossy(&o.stdout).contains("[parse-error]"), "rumoca-lint accepts a syntax error");
    }
}

// ----------------------------------------------------------------------------------------------
// The physics: the default drive, integrated with the equations of the generated classes, moves a
// pendulum to its reference (no Modelica simulator on this machine; this checks the equations
// and the default tuning, not the Modelica text).

fn default_of(path: &str, name: &str) -> f64 {
    let s = spec(path).expect("class");
    let p = s.params.iter().find(|p| p.name == name).expect("param");
    p.default.parse().unwrap_or_else(|_| panic!("{path}.{name} default {} is not a number", p.default))
}

struct DriveSim {
    ratio: f64,
    kp: f64,
    ks: f64,
    ts: f64,
    r: f64,
    l: f64,
    k: f64,
    jm: f64,
    d: f64,
    v_max: f64,
    i_max: f64,
    tc: f64,
}

impl DriveSim {
    fn defaults(ratio: f64) -> Self {
        let m = |n| default_of(MOTOR, n);
        let c = |n| default_of(PPI, n);
        DriveSim {
            ratio,
            kp: c("kp"),
            ks: c("ks"),
            ts: c("Ts"),
            r: m("R"),
            l: m("L"),
            k: m("k"),
            jm: m("J"),
            d: m("d"),
            v_max: m("V_max"),
            i_max: m("I_max"),
            tc: m("Tc"),
        }
    }

    /// State: joint angle q, joint speed, armature current, PI integrator state.
    fn rhs(&self, s: [f64; 4], q_ref: f64, load: &dyn Fn(f64) -> f64, j_load: f64) -> [f64; 4] {
        let [q, qd, i, _x] = s;
        let n = self.ratio;
        let w = n * qd; // motor speed
        let e = self.kp * (n * q_ref - n * q) - w; // speed error
        let i_ref = self.ks * (e + s[3] / self.ts);
        let i_cmd = i_ref.clamp(-self.i_max, self.i_max);
        let v = (self.r * i_cmd + self.k * w + self.l / self.tc * (i_cmd - i)).clamp(-self.v_max, self.v_max);
        let di = (v - self.r * i - self.k * w) / self.l;
        // Motor torque through the ideal gear: (J_load + n^2 J_m) q'' = n (k i - d w) + load.
        let qdd = (n * (self.k * i - self.d * w) + load(q)) / (j_load + n * n * self.jm);
        [qd, qdd, di, e]
    }

    /// Integrates with RK4; returns the final state and the largest joint angle.
    fn run(&self, q0: f64, q_ref: f64, t_end: f64, load: &dyn Fn(f64) -> f64, j_load: f64) -> ([f64; 4], f64, f64) {
        let dt = 1e-5;
        let mut s = [q0, 0.0, 0.0, 0.0];
        let mut q_max = q0;
        let mut i_peak: f64 = 0.0;
        let add = |a: [f64; 4], b: [f64; 4], h: f64| [a[0] + h * b[0], a[1] + h * b[1], a[2] + h * b[2], a[3] + h * b[3]];
        for _ in 0..(t_end / dt).round() as usize {
            let k1 = self.rhs(s, q_ref, load, j_load);
            let k2 = self.rhs(add(s, k1, dt / 2.0), q_ref, load, j_load);
            let k3 = self.rhs(add(s, k2, dt / 2.0), q_ref, load, j_load);
            let k4 = self.rhs(add(s, k3, dt), q_ref, load, j_load);
            for c in 0..4 {
                s[c] += dt / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
            }
            q_max = q_max.max(s[0]);
            i_peak = i_peak.max(s[2].abs());
        }
        (s, q_max, i_peak)
    }
}

#[test]
fn default_drive_moves_the_pendulum_to_its_reference() {
    // The pendulum of tests/in/pendulum: LINK of 0.2673 kg, centre of gravity 0.15 m from the
    // joint, inertia about the joint I_33 + m r^2.
    let (m, r_cg, g) = (0.2673, 0.15, 9.81);
    let j_load = 0.002445799999999999 + m * r_cg * r_cg;
    let gravity = move |q: f64| -m * g * r_cg * q.cos();
    let sim = DriveSim::defaults(50.0);
    let (s, q_max, i_peak) = sim.run(0.0, 0.5, 2.0, &gravity, j_load);
    assert!((s[0] - 0.5).abs() < 1e-4, "joint angle {} after 2 s, reference 0.5", s[0]);
    assert!(s[1].abs() < 1e-3, "joint still moving: {} rad/s", s[1]);
    assert!(q_max < 0.5 + 0.05, "overshoot: {q_max}");
    assert!(i_peak <= sim.i_max + 1e-6, "current limit exceeded: {i_peak}");
    // At rest the motor holds the gravity torque: k i ratio = m g r cos(q).
    let holding = m * g * r_cg * 0.5f64.cos() / (sim.k * sim.ratio);
    assert!((s[2] - holding).abs() < 1e-3, "current {} vs holding current {holding}", s[2]);

    // A reversed gear (negative ratio) works the same: the controller scales by the ratio.
    let reversed = DriveSim::defaults(-50.0);
    let (s, _, _) = reversed.run(0.0, -0.3, 2.0, &gravity, j_load);
    assert!((s[0] + 0.3).abs() < 1e-4, "reversed gear: {}", s[0]);
}

/// An observer hears every stage once per conversion, in order, and the drives it chooses from
/// the report (the joints' Modelica names and start values) are the ones `Mechatronics.mo` gets.
#[test]
fn an_observer_sees_the_stages_and_chooses_drives_from_the_report() {
    use crate::pipeline::observe::{Observer, Stage};
    struct Watch {
        steps: Vec<(Stage, usize, usize)>,
        joints_seen: Vec<String>,
    }
    impl Observer for Watch {
        fn progress(&mut self, stage: Stage, done: usize, total: usize) {
            self.steps.push((stage, done, total));
        }
        fn drives(&mut self, report: &crate::pipeline::report::Report, planned: &[DrivePlan]) -> Vec<DrivePlan> {
            assert!(planned.is_empty());
            self.joints_seen = report.joints.iter().map(|j| j.modelica_name.clone()).collect();
            let j = report
                .joints
                .iter()
                .find(|j| j.elements.iter().any(|e| e.kind == crate::pipeline::ir::PrimitiveKind::Revolute))
                .expect("a revolute");
            vec![DrivePlan { start: j.elements[0].initial_q, ..plan(&j.modelica_name) }]
        }
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/arm_subsystems");
    let bundle = crate::test_bundle_of_dir(&dir).expect("read bundle");
    let mut w = Watch { steps: Vec::new(), joints_seen: Vec::new() };
    let opts = crate::pipeline::Options { write_shapes: true, ..Default::default() };
    let out = crate::pipeline::convert_observed(&bundle, &opts, &mut w).expect("convert");
    let stages: Vec<Stage> = w.steps.iter().map(|s| s.0).collect();
    assert!(stages.windows(2).all(|p| p[0] <= p[1]), "stages in order: {stages:?}");
    assert_eq!(stages.iter().filter(|s| **s == Stage::Xml).count(), 1, "one conversion: {stages:?}");
    for s in [Stage::Xml, Stage::Meshes, Stage::Analysis, Stage::Modelica, Stage::Shapes, Stage::Report] {
        assert!(stages.contains(&s), "{s:?} reported: {stages:?}");
    }
    let shapes: Vec<_> = w.steps.iter().filter(|s| s.0 == Stage::Shapes).collect();
    assert_eq!(shapes.len(), out.report.bodies.iter().filter(|b| b.shape.is_some()).count(), "a step per shape");
    assert!(shapes.iter().enumerate().all(|(i, s)| s.1 == i && s.2 == shapes.len()));
    assert!(!w.joints_seen.is_empty());
    let pkg = &out.report.package_name;
    let mech = output_text(&out, &format!("{pkg}/Mechatronics.mo"));
    let driven = &w.joints_seen.iter().find(|j| mech.contains(&format!("connect(drive_{j}.flange, {j}.drive)"))).expect("a driven joint");
    assert!(mech.contains(&format!(" drive_{driven}(")), "{mech}");
    // The report itself does not depend on the drives.
    let plain = crate::pipeline::convert(&bundle, &opts).expect("convert");
    assert_eq!(plain.report.joints.len(), out.report.joints.len());
    assert_eq!(output_text(&plain, "report.json"), output_text(&out, "report.json"));
}

/// msl-check knows the MSL, not our own classes: every modifier of an `extends` of one of the
/// drive library's classes must name a parameter that class (or what it extends) declares.
#[test]
fn extends_modifiers_name_declared_parameters() {
    let files = components("P");
    let class_text = |path: &str| -> String {
        let rel = path.trim_start_matches("P.").replace('.', "/");
        text(&files, &format!("P/{rel}.mo"))
    };
    // Parameters declared by a class and the classes it extends.
    fn declared(text: &str, class_text: &dyn Fn(&str) -> String, out: &mut Vec<String>) {
        for line in text.lines().map(str::trim) {
            if let Some(rest) = line.strip_prefix("parameter ") {
                let words: Vec<&str> = rest.split(|c: char| c.is_whitespace() || "[=(;".contains(c)).filter(|w| !w.is_empty()).collect();
                if let Some(name) = words.get(1) {
                    out.push(name.to_string());
                }
            }
            if let Some(base) = line.strip_prefix("extends P.") {
                let base = base.split(['(', ';']).next().unwrap_or_default();
                declared(&class_text(&format!("P.{base}")), class_text, out);
            }
        }
    }
    let mut checked = 0;
    for (path, bytes) in files.iter().filter(|(p, _)| p.ends_with(".mo")) {
        let t = String::from_utf8_lossy(bytes);
        for line in t.lines().map(str::trim).filter(|l| l.starts_with("extends P.") && l.contains('(')) {
            let base = &line["extends ".len()..line.find('(').expect("(")];
            let mods = &line[line.find('(').expect("(") + 1..line.rfind(')').expect(")")];
            let mut names = Vec::new();
            declared(&class_text(base), &class_text, &mut names);
            for m in mods.split(',') {
                let name = m.trim().trim_start_matches("final ").split('=').next().unwrap_or_default().trim();
                assert!(names.iter().any(|n| n == name), "{path}: {base} declares no parameter {name} (it has {names:?})");
                checked += 1;
            }
        }
    }
    assert!(checked >= 3, "checked {checked} modifiers");
}
