//! Unit tests of the library rules, the XML format and the seed.

use std::collections::HashSet;

use serde_json::{json, Map, Value as Json};

use super::*;

fn obj(v: Json) -> Map<String, Json> {
    match v {
        Json::Object(m) => m,
        other => panic!("not an object: {other}"),
    }
}

fn param(name: &str, ty: ParamType, unit: &str, min: Option<f64>, max: Option<f64>, editable: bool) -> Parameter {
    Parameter { name: name.into(), ty, unit: unit.into(), min, max, editable, datasheet: false, default: None, comment: String::new() }
}

fn motor_class() -> Class {
    Class {
        id: "c1".into(),
        name: "Motor".into(),
        domain: "motor".into(),
        modelica_class: "cad2mo.Drives.Motors.DCPermanentMagnet".into(),
        description: String::new(),
        parameters: vec![
            param("R", ParamType::Real, "Ohm", Some(0.0), None, false),
            param("L", ParamType::Real, "H", Some(0.0), None, false),
            param("ratio", ParamType::Real, "1", None, None, true),
            param("eta", ParamType::Real, "1", Some(0.0), Some(1.0), true),
            param("poles", ParamType::Integer, "1", Some(1.0), None, false),
            param("brushless", ParamType::Boolean, "", None, None, false),
            param("winding", ParamType::String, "", None, None, true),
        ],
    }
}

fn good_values() -> Map<String, Json> {
    obj(json!({
        "R": 0.317, "L": {"value": 82, "unit": "uH"}, "ratio": 74, "eta": {"value": 72, "unit": "%"},
        "poles": 2, "brushless": false, "winding": "24 V"
    }))
}

fn fields(issues: &[Issue]) -> Vec<&str> {
    issues.iter().map(|i| i.field.as_str()).collect()
}

// ---------------------------------------------------------------------------------------------
// Values

#[test]
fn values_in_the_parameter_unit_and_converted() {
    let c = motor_class();
    let v = check_values(&c, &good_values()).expect("valid");
    let get = |n: &str| v.iter().find(|(k, _)| k == n).map(|(_, v)| v.clone()).expect("value");
    assert_eq!(get("R"), Value::Real(0.317));
    assert_eq!(get("L"), Value::Real(8.2e-5));
    assert_eq!(get("ratio"), Value::Real(74.0));
    assert_eq!(get("eta"), Value::Real(0.72));
    assert_eq!(get("poles"), Value::Integer(2));
    assert_eq!(get("brushless"), Value::Boolean(false));
    assert_eq!(get("winding"), Value::String("24 V".into()));
    // In class order.
    let names: Vec<&str> = v.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["R", "L", "ratio", "eta", "poles", "brushless", "winding"]);
}

#[test]
fn a_unit_equal_to_the_parameter_unit_or_empty_is_accepted() {
    let p = param("L", ParamType::Real, "H", Some(0.0), None, false);
    assert_eq!(check_value(&p, &json!({"value": 1e-3, "unit": "H"})), Ok(Value::Real(1e-3)));
    assert_eq!(check_value(&p, &json!({"value": 1e-3, "unit": ""})), Ok(Value::Real(1e-3)));
    assert_eq!(check_value(&p, &json!({"value": 1e-3})), Ok(Value::Real(1e-3)));
}

#[test]
fn value_errors_name_the_parameter() {
    let c = motor_class();
    let cases: Vec<(&str, Json, &str)> = vec![
        ("L", json!({"value": 82, "unit": "rpm"}), "cannot be converted"),
        ("L", json!({"value": 82, "unit": "furlong"}), "unknown unit"),
        ("R", json!("0.3"), "expected a number"),
        ("R", json!(-1), "below the minimum"),
        ("eta", json!(1.5), "above the maximum"),
        ("eta", json!({"value": 150, "unit": "%"}), "above the maximum"),
        ("poles", json!(2.5), "whole number"),
        ("brushless", json!(1), "true or false"),
        ("brushless", json!({"value": true, "unit": "V"}), "numbers only"),
        ("winding", json!(24), "a string"),
        ("R", json!({"value": 1, "units": "Ohm"}), "unexpected key"),
        ("R", json!({"unit": "Ohm"}), "no \"value\""),
        ("R", json!(null), "got null"),
        ("R", json!([1]), "got an array"),
    ];
    for (name, raw, want) in cases {
        let p = c.parameter(name).expect("param");
        let err = check_value(p, &raw).expect_err(&format!("{name} = {raw} must fail"));
        assert!(err.starts_with(name), "{err}");
        assert!(err.contains(want), "{name} = {raw}: {err}");
    }
}

#[test]
fn integers_accept_whole_floats_and_converted_whole_values() {
    let p = param("n", ParamType::Integer, "1", None, None, false);
    assert_eq!(check_value(&p, &json!(3.0)), Ok(Value::Integer(3)));
    assert_eq!(check_value(&p, &json!({"value": 300, "unit": "%"})), Ok(Value::Integer(3)));
    assert!(check_value(&p, &json!({"value": 250, "unit": "%"})).is_err());
}

#[test]
fn all_missing_unknown_and_bad_values_are_listed() {
    let c = motor_class();
    let mut v = good_values();
    v.remove("R");
    v.remove("poles");
    v.insert("Kt".into(), json!(1));
    v.insert("L".into(), json!({"value": 1, "unit": "rpm"}));
    v.insert("eta".into(), json!(2));
    let issues = check_values(&c, &v).expect_err("invalid");
    let f = fields(&issues);
    for want in ["values.R", "values.L", "values.eta", "values.poles", "values.Kt"] {
        assert!(f.contains(&want), "{want} missing in {f:?}");
    }
    assert_eq!(issues.len(), 5, "{issues:?}");
}

// ---------------------------------------------------------------------------------------------
// Classes

fn draft_param(name: &str, ty: &str, unit: &str) -> ParameterDraft {
    ParameterDraft { name: name.into(), ty: ty.into(), unit: unit.into(), ..ParameterDraft::default() }
}

#[test]
fn class_check_lists_every_problem() {
    let d = ClassDraft {
        name: " ".into(),
        domain: "Motor".into(),
        modelica_class: "DCMotor".into(),
        description: String::new(),
        parameters: vec![
            draft_param("L", "Real", "mH"),
            draft_param("L", "Real", "H"),
            draft_param("x", "Float", ""),
            draft_param("flag", "Boolean", "V"),
            ParameterDraft { min: Some(2.0), max: Some(1.0), ..draft_param("y", "Real", "1") },
            ParameterDraft { default: Some(json!("a")), ..draft_param("z", "Real", "1") },
            draft_param("end", "Real", "1"),
            draft_param("w", "Real", "furlong"),
        ],
    };
    let issues = check_class("id", &d).expect_err("invalid");
    let f = fields(&issues);
    for want in [
        "name",
        "domain",
        "modelica_class",
        "parameters[0].unit",
        "parameters[1].name",
        "parameters[2].type",
        "parameters[3].unit",
        "parameters[4].max",
        "parameters[5].default",
        "parameters[6].name",
        "parameters[7].unit",
    ] {
        assert!(f.contains(&want), "{want} missing in {f:?}");
    }
    let mh = issues.iter().find(|i| i.field == "parameters[0].unit").expect("mH issue");
    assert!(mh.message.contains("declare \"H\""), "{}", mh.message);
}

#[test]
fn class_defaults_are_checked_and_converted() {
    let d = ClassDraft {
        name: "Gear".into(),
        domain: "gear".into(),
        modelica_class: "cad2mo.Drives.Gears.Efficiency".into(),
        description: String::new(),
        parameters: vec![ParameterDraft {
            min: Some(0.0),
            max: Some(1.0),
            editable: true,
            default: Some(json!({"value": 90, "unit": "%"})),
            ..draft_param("eta", "Real", "1")
        }],
    };
    let c = check_class("id", &d).expect("valid");
    assert_eq!(c.parameters[0].default, Some(Value::Real(0.9)));
}

// ---------------------------------------------------------------------------------------------
// Instances: nameplate values, overrides, migration

fn instance(c: &Class) -> Instance {
    check_instance("i1", c, &InstanceDraft { name: "RE 40".into(), source: "datasheet".into(), values: good_values() }).expect("valid")
}

#[test]
fn nameplate_values_cannot_change_editable_ones_can() {
    let c = motor_class();
    let old = instance(&c);
    // Same nameplate values (L given in another unit), changed editable values and name.
    let mut v = good_values();
    v.insert("L".into(), json!(8.2e-5));
    v.insert("ratio".into(), json!(100));
    v.insert("winding".into(), json!("48 V"));
    let d = InstanceDraft { name: "RE 40 (renamed)".into(), source: "new source".into(), values: v };
    let new = check_instance_update(&c, &old, &d).expect("editable change is fine");
    assert_eq!(new.value("ratio"), Some(&Value::Real(100.0)));
    assert_eq!(new.value("L"), old.value("L"));
    assert_eq!(new.name, "RE 40 (renamed)");
    // Nameplate changes are refused, each named.
    let mut v = good_values();
    v.insert("R".into(), json!(0.5));
    v.insert("brushless".into(), json!(true));
    let d = InstanceDraft { name: "RE 40".into(), source: String::new(), values: v };
    let issues = check_instance_update(&c, &old, &d).expect_err("nameplate change");
    assert_eq!(fields(&issues), ["values.R", "values.brushless"]);
    assert!(issues[0].message.contains("nameplate"), "{}", issues[0].message);
    assert!(issues[0].message.contains("new instance"), "{}", issues[0].message);
}

/// Datasheet parameters: optional per instance, checked when given, never editable, kept once
/// given, and left out of a migration when new and without default.
#[test]
fn datasheet_values_are_optional_but_checked() {
    let mut c = Class { id: "6f0c0f5e-3a57-4d7e-9a38-1c1b1e8f6d01".into(), ..motor_class() };
    c.parameters.push(Parameter { datasheet: true, ..param("T_nom", ParamType::Real, "N.m", Some(0.0), None, false) });
    let without = instance(&c);
    assert_eq!(without.value("T_nom"), None);
    let mut v = good_values();
    v.insert("T_nom".into(), json!({"value": 170, "unit": "mNm"}));
    let d = InstanceDraft { name: "RE 40".into(), source: String::new(), values: v.clone() };
    let with = check_instance("2a7b9a3c-58f4-4b7a-b5a5-0c7b8f3e9d02", &c, &d).expect("valid");
    assert_eq!(with.value("T_nom"), Some(&Value::Real(0.17)));
    v.insert("T_nom".into(), json!(-1));
    let issues = check_instance("i3", &c, &InstanceDraft { values: v, ..d.clone() }).expect_err("below min");
    assert_eq!(fields(&issues), ["values.T_nom"]);
    // An update may add a datasheet value, not change or remove it.
    assert!(check_instance_update(&c, &without, &d).is_ok());
    let removed = InstanceDraft { values: good_values(), ..d.clone() };
    let issues = check_instance_update(&c, &with, &removed).expect_err("removed");
    assert_eq!(fields(&issues), ["values.T_nom"]);
    // Not overridable per drive (never editable).
    assert!(validate_overrides(&c, &obj(json!({"T_nom": 1}))).is_err());
    // A datasheet parameter cannot be editable.
    let draft = ClassDraft {
        name: "m".into(),
        domain: "motor".into(),
        modelica_class: "cad2mo.Drives.Motors.DCPermanentMagnet".into(),
        description: String::new(),
        parameters: vec![ParameterDraft { datasheet: true, editable: true, ..draft_param("T_nom", "Real", "N.m") }],
    };
    let issues = check_class("c", &draft).expect_err("editable datasheet");
    assert_eq!(fields(&issues), ["parameters[0].editable"]);
    // A class gaining a datasheet parameter without default carries its instances over as they are.
    let old = Class { id: c.id.clone(), ..motor_class() };
    let inst = instance(&old);
    let migrated = migrate_instance(&old, &c, &inst).expect("migrates");
    assert_eq!(migrated.values, inst.values);
    // And the XML says which parameters are datasheet values.
    let lib = Library { classes: vec![c.clone()], instances: vec![with.clone()] };
    let text = xml::write(&lib);
    assert!(text.contains(r#"name="T_nom" type="Real" unit="N.m" min="0" editable="false" datasheet="true""#), "{text}");
    let back = import_into_empty(&text);
    assert_eq!(back.classes[0].parameters, c.parameters);
    assert_eq!(back.instances[0].values, with.values);
}

#[test]
fn overrides_touch_editable_parameters_only() {
    let c = motor_class();
    let inst = instance(&c);
    let ok = validate_overrides(&c, &obj(json!({"eta": {"value": 80, "unit": "%"}, "ratio": 50}))).expect("editable overrides");
    assert_eq!(ok, vec![("ratio".to_string(), Value::Real(50.0)), ("eta".to_string(), Value::Real(0.8))]);
    let issues = validate_overrides(&c, &obj(json!({"R": 1, "nope": 1, "eta": 3}))).expect_err("bad overrides");
    let f = fields(&issues);
    assert!(f.contains(&"overrides.R") && f.contains(&"overrides.nope") && f.contains(&"overrides.eta"), "{f:?}");
    assert!(issues.iter().any(|i| i.field == "overrides.R" && i.message.contains("nameplate")));

    let resolved = resolved_values(&c, &inst, &ok);
    let get = |n: &str| resolved.iter().find(|(k, _)| k == n).map(|(_, v)| v.clone());
    assert_eq!(get("ratio"), Some(Value::Real(50.0)));
    assert_eq!(get("eta"), Some(Value::Real(0.8)));
    assert_eq!(get("R"), Some(Value::Real(0.317)));
    assert_eq!(resolved.len(), c.parameters.len());
    // A (forged) override of a nameplate value is ignored.
    let forged = vec![("R".to_string(), Value::Real(9.0))];
    assert_eq!(resolved_values(&c, &inst, &forged).first(), Some(&("R".to_string(), Value::Real(0.317))));
}

#[test]
fn migration_converts_units_drops_removed_and_defaults_new_parameters() {
    let old = motor_class();
    let inst = instance(&old);
    let mut new = old.clone();
    new.parameters.retain(|p| p.name != "winding");
    new.parameters[1].unit = "H".into();
    new.parameters.push(Parameter { default: Some(Value::Real(0.0)), ..param("d", ParamType::Real, "N.m.s/rad", None, None, false) });
    let m = migrate_instance(&old, &new, &inst).expect("migrates");
    assert_eq!(m.value("winding"), None);
    assert_eq!(m.value("d"), Some(&Value::Real(0.0)));
    assert_eq!(m.value("L"), inst.value("L"));

    // A new parameter without default, and a tighter limit, are problems.
    let mut stricter = old.clone();
    stricter.parameters[0].max = Some(0.1);
    stricter.parameters.push(param("J", ParamType::Real, "kg.m2", None, None, false));
    let issues = migrate_instance(&old, &stricter, &inst).expect_err("cannot migrate");
    assert_eq!(issues.len(), 2, "{issues:?}");
}

// ---------------------------------------------------------------------------------------------
// Seed

#[test]
fn the_seed_is_valid_and_ids_are_unique() {
    let lib = seed::library().unwrap_or_else(|e| panic!("seed invalid: {e:#?}"));
    assert!(lib.classes.len() >= 5);
    let mut ids = HashSet::new();
    for id in lib.classes.iter().map(|c| &c.id).chain(lib.instances.iter().map(|i| &i.id)) {
        assert_eq!(parse_id(id).as_deref(), Some(id.as_str()), "{id} is a canonical UUID");
        assert!(ids.insert(id.clone()), "{id} twice");
    }
    let motors = lib.instances.iter().filter(|i| i.class_id == seed::DC_MOTOR).count();
    assert_eq!(motors, 18, "motors of our own class: 4 of the first seed and 14 catalogue motors");
    assert_eq!(
        lib.instances.len(),
        116,
        "instances: 9 of the first seed, 14 catalogue DC motors, 60 catalogue gear units, 30 AC servo motors and 3 ball screws"
    );
    let servos = lib.instances.iter().filter(|i| i.class_id == seed::AC_SERVO).count();
    assert_eq!(servos, 30, "AC servo motors: 15 Yaskawa Σ-7 models, each without and with holding brake");
    // Every instance beyond the first seed's nine is a catalogue instance (held to its sources).
    let first = [
        seed::MAXON_RE40,
        seed::MAXON_EC45_FLAT,
        seed::FAULHABER_1331,
        seed::FAULHABER_3564,
        seed::MAXON_RE40_MSL,
        seed::GEAR_100,
        seed::MAXON_GP42C_74,
        seed::BALL_SCREW_16X5,
        seed::ROBOT_R3_CONTROLLER,
    ];
    for i in &lib.instances {
        assert!(first.contains(&i.id.as_str()) != seed::CATALOGUE.contains(&i.id.as_str()), "{} is first seed or catalogue", i.name);
    }
    for i in &lib.instances {
        assert!(!i.source.is_empty(), "{} has a source", i.name);
        let class = lib.class(&i.class_id).expect("class");
        for p in class.parameters.iter().filter(|p| !p.datasheet) {
            assert!(i.value(&p.name).is_some(), "{} has a value for {}", i.name, p.name);
        }
    }
    let re40 = lib.instances.iter().find(|i| i.id == seed::MAXON_RE40).expect("RE 40");
    assert_eq!(re40.value("L"), Some(&Value::Real(8.23e-5)));
    assert_eq!(re40.value("k"), Some(&Value::Real(0.0302)));
    assert_eq!(re40.value("J"), Some(&Value::Real(1.34e-5)));
    let msl = lib.instances.iter().find(|i| i.id == seed::MAXON_RE40_MSL).expect("RE 40 MSL");
    assert_eq!(msl.value("TaNominal"), Some(&Value::Real(298.15)));
    let w = msl.value("wNominal").and_then(Value::as_f64).expect("wNominal");
    assert!((w - 6940.0 * std::f64::consts::PI / 30.0).abs() < 1e-9, "{w}");
    let gp42 = lib.instances.iter().find(|i| i.id == seed::MAXON_GP42C_74).expect("GP 42 C");
    assert_eq!(gp42.value("eta"), Some(&Value::Real(0.72)));
    assert_eq!(gp42.value("T_peak"), Some(&Value::Real(22.5)));
    // Datasheet values of the size-17 strain-wave gear, in SI units; its torque ratings are
    // missing (no maker's page at hand for the first seed's figures: its source says why).
    let csf = lib.instances.iter().find(|i| i.id == seed::GEAR_100).expect("CSF-17-100");
    assert_eq!((csf.value("T_rated"), csf.value("T_peak")), (None, None));
    assert!(csf.source.contains("T_rated and T_peak missing"), "{}", csf.source);
    assert_eq!(csf.value("J_in"), Some(&Value::Real(7.9e-6)));
    let w = csf.value("w_in_max").and_then(Value::as_f64).expect("w_in_max");
    assert!((w - 7300.0 * std::f64::consts::PI / 30.0).abs() < 1e-9, "{w}");
    assert_eq!(re40.value("T_nom"), Some(&Value::Real(0.17)));
    assert_eq!(re40.value("T_peak"), None, "maxon prints no peak torque");
    // Gear ratios, efficiencies and controller gains are editable; motor values are not.
    for c in &lib.classes {
        for p in &c.parameters {
            let should = matches!(p.name.as_str(), "ratio" | "eta" | "kp" | "ks" | "Ts" | "Tc" | "TaOperational");
            assert_eq!(p.editable, should, "{}.{}", c.name, p.name);
        }
    }
}

/// The makers a catalogue source may name.
/// Makers, and the one seller whose catalogue page names no other maker (Super Slides' PBSA page).
const MAKERS: [&str; 12] = [
    "FAULHABER",
    "maxon",
    "Portescap",
    "Nanotec",
    "Harmonic Drive",
    "Neugart",
    "Bosch Rexroth",
    "HIWIN",
    "THK",
    "Beckhoff",
    "Yaskawa",
    "Super Slides",
];

/// Why a catalogue instance's source is not good enough, if it is not: it names a maker, a
/// document (a URL) and a page, table or line; says for every value it has which datasheet line it
/// is (`R = ...`) and for every datasheet value it lacks why (`T_peak missing: ...`).
fn catalogue_source_problem(lib: &Library, i: &Instance) -> Option<String> {
    let s = &i.source;
    if s.chars().count() < 200 {
        return Some(format!("{}: source too short ({} characters)", i.name, s.chars().count()));
    }
    if !MAKERS.iter().any(|m| s.contains(m)) {
        return Some(format!("{}: source names no maker", i.name));
    }
    if !s.contains("Document") && !s.contains("manual") && !s.contains("catalog") {
        return Some(format!("{}: source names no document", i.name));
    }
    if !s.contains("https://") {
        return Some(format!("{}: source has no URL of the document", i.name));
    }
    if !["page ", "table", "line "].iter().any(|w| s.contains(w)) {
        return Some(format!("{}: source names no page, table or line", i.name));
    }
    let class = lib.class(&i.class_id)?;
    for p in &class.parameters {
        let has = i.value(&p.name).is_some();
        if has && !s.contains(&format!("{} = ", p.name)) {
            return Some(format!("{}: the source does not say where {} comes from", i.name, p.name));
        }
        // Values a maker gives only sometimes (the sizing's "where given" checks and the ranking's
        // keys) may be absent without a reason; T_stall stands in for T_peak, whose reason counts.
        let optional = ["tau_th_w", "T_avg_max", "mass", "price_class", "mount", "motor_mounts"].contains(&p.name.as_str())
            || (p.name == "T_stall" && (has_value(i, "T_peak") || s.contains("T_peak missing: ")));
        if !has && p.datasheet && !optional && !s.contains(&format!("{} missing: ", p.name)) {
            return Some(format!("{}: the source does not say why {} is missing", i.name, p.name));
        }
    }
    None
}

fn has_value(i: &Instance, name: &str) -> bool {
    i.value(name).is_some()
}

/// Every catalogue instance carries its source: maker, document, page, and a line per value.
#[test]
fn every_catalogue_value_has_a_source() {
    let lib = seed::library().expect("seed");
    for id in seed::CATALOGUE {
        let i = lib.instances.iter().find(|i| i.id == id).unwrap_or_else(|| panic!("{id} in the seed"));
        assert_eq!(catalogue_source_problem(&lib, i), None);
    }
    // Mutations: a blank source, one without its URL, one value's line dropped.
    let i = lib.instances.iter().find(|i| i.id == seed::FAULHABER_2250_024_BX4).expect("2250");
    let blank = Instance { source: String::new(), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &blank).expect("blank").contains("too short"));
    let no_url = Instance { source: i.source.replace("https://", "at "), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_url).expect("no URL").contains("URL"));
    let no_k = Instance { source: i.source.replace("k = ", "k is "), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_k).expect("no k").contains("where k comes from"));
    let no_reason = Instance { source: i.source.replace("T_peak missing: ", ""), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_reason).expect("no reason").contains("why T_peak is missing"));
    // The ball screws too: each load rating's line, and why J_in is missing.
    let i = lib.instances.iter().find(|i| i.id == seed::PBSA_SCREWS[0]).expect("PBSA 16");
    let no_c0a = Instance { source: i.source.replace("C_0a = ", "C_0a is "), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_c0a).expect("no C_0a").contains("where C_0a comes from"));
    let no_ca = Instance { source: i.source.replace("C_a = ", "C_a is "), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_ca).expect("no C_a").contains("where C_a comes from"));
    let no_j = Instance { source: i.source.replace("J_in missing: ", ""), ..i.clone() };
    assert!(catalogue_source_problem(&lib, &no_j).expect("no reason").contains("why J_in is missing"));
}

/// Catalogue values as printed, in SI units (one motor per document).
#[test]
fn catalogue_values_are_the_datasheets() {
    let lib = seed::library().expect("seed");
    let get = |id: &str, p: &str| lib.instances.iter().find(|i| i.id == id).and_then(|i| i.value(p)).and_then(Value::as_f64);
    let close = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() <= 1e-12 * b.abs());
    let m = seed::FAULHABER_1331_012;
    assert!(close(get(m, "R"), 13.7) && close(get(m, "L"), 310e-6) && close(get(m, "k"), 0.0114) && close(get(m, "J"), 0.67e-7));
    assert!(
        close(get(m, "I_max"), 0.37) && close(get(m, "T_nom"), 0.0032) && close(get(m, "w_max"), 12000.0 * std::f64::consts::PI / 30.0)
    );
    assert_eq!(get(m, "T_peak"), None);
    assert_eq!(get(m, "d"), Some(0.0));
    let m = seed::FAULHABER_2250_024_BX4;
    assert!(close(get(m, "R"), 5.9) && close(get(m, "L"), 240e-6) && close(get(m, "k"), 0.0369) && close(get(m, "J"), 1e-6));
    assert!(close(get(m, "d"), 2.4e-7 * 30.0 / std::f64::consts::PI) && close(get(m, "T_nom"), 0.023));
    // The printed stall torques, the peak limit where the maker gives no short-time limit.
    assert!(close(get(m, "T_stall"), 0.149) && close(get(seed::FAULHABER_1331_006, "T_stall"), 0.0112));
    assert!(close(get(seed::MAXON_EC45_FLAT_MOTORS[4], "T_stall"), 1.26));
    // maxon EC 45 flat 70 W, 48 V: phase-to-phase values, and the page's own mechanical time
    // constant R·J/k² (8.510 ms) from them.
    let mx = seed::MAXON_EC45_FLAT_MOTORS[4];
    assert!(close(get(mx, "R"), 3.07) && close(get(mx, "L"), 1.21e-3) && close(get(mx, "k"), 0.0808) && close(get(mx, "J"), 181e-7));
    assert!(close(get(mx, "V_max"), 48.0) && close(get(mx, "I_max"), 1.41) && close(get(mx, "T_nom"), 0.112));
    assert!(close(get(mx, "w_max"), 10000.0 * std::f64::consts::PI / 30.0) && get(mx, "T_peak").is_none());
    let tau = get(mx, "R").unwrap_or(0.0) * get(mx, "J").unwrap_or(0.0) / get(mx, "k").unwrap_or(1.0).powi(2);
    assert!((tau - 8.51e-3).abs() < 0.01e-3, "{tau}");
    // The 30 W page's stored copy lacks the max. speed line: w_max stays missing.
    let mx = seed::MAXON_EC45_FLAT_MOTORS[1];
    assert!(close(get(mx, "R"), 4.83) && close(get(mx, "k"), 0.051) && close(get(mx, "J"), 92.5e-7) && get(mx, "w_max").is_none());
    let tau = get(mx, "R").unwrap_or(0.0) * get(mx, "J").unwrap_or(0.0) / get(mx, "k").unwrap_or(1.0).powi(2);
    assert!((tau - 17.2e-3).abs() < 0.05e-3, "{tau}");
    // A gear unit per ratio (Beckhoff TP010 MF, ratio 7, clamping hub E = 19 mm): every value of
    // its column, in SI units.
    let g = seed::BECKHOFF_GEARS[7];
    assert!(close(get(g, "ratio"), 7.0) && close(get(g, "eta"), 0.97) && close(get(g, "T_rated"), 81.0) && close(get(g, "T_peak"), 172.0));
    assert!(
        close(get(g, "w_in_max"), 7500.0 * std::f64::consts::PI / 30.0) && close(get(g, "J_in"), 0.64e-4) && close(get(g, "mass"), 3.8)
    );
    assert!(close(get(g, "backlash"), 3.0 * std::f64::consts::PI / 10800.0));
    // The PBSA ball screws, one per row: lead, C_a and C_0a of the page's ball-screw table, in N.
    for (id, lead, ca, c0a) in [(0, 0.016, 3800.0, 6800.0), (1, 0.02, 5900.0, 12200.0), (2, 0.025, 8900.0, 19100.0)] {
        let s = seed::PBSA_SCREWS[id];
        assert!(close(get(s, "lead"), lead) && close(get(s, "C_a"), ca) && close(get(s, "C_0a"), c0a), "{id}");
        assert!(close(get(s, "ratio"), 1.0) && get(s, "J_in").is_none() && get(s, "F_peak").is_none() && get(s, "mass").is_none());
    }
    // Its neighbour at ratio 8 has its own ratings (no ratio of a family borrows another's).
    let h = seed::BECKHOFF_GEARS[8];
    assert!(close(get(h, "ratio"), 8.0) && close(get(h, "T_peak"), 126.0) && close(get(h, "T_rated"), 80.0));
    let name = |id: &str| lib.instances.iter().find(|i| i.id == id).map(|i| i.name.clone()).unwrap_or_default();
    assert_eq!(name(g), "Beckhoff TP010 MF i=7, clamping hub E = 19 mm");
    // The last page's last column: NPT035 MF, ratio 10, hub G = 24 mm.
    let z = seed::BECKHOFF_GEARS[37];
    assert!(
        close(get(z, "ratio"), 10.0) && close(get(z, "T_rated"), 110.0) && close(get(z, "T_peak"), 220.0) && close(get(z, "J_in"), 1.7e-4)
    );
    // A page with 1- and 2-stage columns (NPS045 MF): each column takes its own stage's efficiency,
    // maximum input speed and backlash.
    let one = seed::BECKHOFF_GEARS[40];
    let two = seed::BECKHOFF_GEARS[43];
    assert!(
        close(get(one, "ratio"), 10.0) && close(get(one, "eta"), 0.97) && close(get(one, "w_in_max"), 4000.0 * std::f64::consts::PI / 30.0)
    );
    assert!(close(get(one, "backlash"), 8.0 * std::f64::consts::PI / 10800.0) && close(get(one, "T_rated"), 200.0));
    assert!(
        close(get(two, "ratio"), 50.0) && close(get(two, "eta"), 0.95) && close(get(two, "w_in_max"), 6000.0 * std::f64::consts::PI / 30.0)
    );
    assert!(
        close(get(two, "backlash"), 10.0 * std::f64::consts::PI / 10800.0)
            && close(get(two, "T_peak"), 500.0)
            && close(get(two, "J_in"), 6.8e-4)
    );
    // NPT045 MF prints its weight per stage too.
    assert!(close(get(seed::BECKHOFF_GEARS[48], "mass"), 19.0) && close(get(seed::BECKHOFF_GEARS[49], "mass"), 20.0));
    assert!(close(get(seed::BECKHOFF_GEARS[53], "ratio"), 100.0) && close(get(seed::BECKHOFF_GEARS[53], "J_in"), 6.5e-4));
    // The datasheet's own consistency: the mechanical time constant R·J/k² it prints (4.3 ms).
    let tau = get(m, "R").unwrap_or(0.0) * get(m, "J").unwrap_or(0.0) / get(m, "k").unwrap_or(1.0).powi(2);
    assert!((tau - 4.3e-3).abs() < 0.05e-3, "{tau}");
}

/// Every seeded class is a class the Modelica generator knows, with exactly its parameters
/// (names, types and units), so a drive built from the seed can always be generated.
#[test]
fn seeded_classes_match_the_generator() {
    use crate::pipeline::back::modelica::mechatronics::known_classes;
    let known = known_classes();
    let lib = seed::library().unwrap_or_else(|e| panic!("seed invalid: {e:#?}"));
    // The amplifier class is the sizing's alone (every parameter a datasheet value): no Modelica class.
    for c in lib.classes.iter().filter(|c| c.domain != "amplifier") {
        assert!(c.parameters.iter().any(|p| !p.datasheet), "{}", c.name);
        let k = known
            .iter()
            .find(|k| k.modelica_class == c.modelica_class)
            .unwrap_or_else(|| panic!("{} is not a class of known_classes()", c.modelica_class));
        assert_eq!(k.domain, c.domain, "{}", c.modelica_class);
        let ours: Vec<(&str, &str, &str)> =
            c.parameters.iter().filter(|p| !p.datasheet).map(|p| (p.name.as_str(), p.ty.as_str(), p.unit.as_str())).collect();
        let mut theirs: Vec<(&str, &str, &str)> = k.params.to_vec();
        let mut ours_sorted = ours.clone();
        ours_sorted.sort();
        theirs.sort();
        assert_eq!(ours_sorted, theirs, "parameters of {}", c.modelica_class);
    }
    // And every class the generator knows is seeded.
    for k in &known {
        assert!(lib.classes.iter().any(|c| c.modelica_class == k.modelica_class), "{} is not seeded", k.modelica_class);
    }
}

// ---------------------------------------------------------------------------------------------
// XML

fn import_into_empty(text: &str) -> Library {
    let doc = xml::read(text).unwrap_or_else(|e| panic!("read: {e:#?}"));
    let plan = plan_import(&Library::default(), &doc).unwrap_or_else(|e| panic!("plan: {e:#?}"));
    let mut lib = Library { classes: plan.classes, instances: plan.instances };
    lib.sort();
    lib
}

#[test]
fn xml_round_trip_of_the_seed_is_exact() {
    let lib = seed::library().expect("seed");
    let text = xml::write(&lib);
    assert!(text.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<motorLibrary version=\"1\">"), "{text}");
    let back = import_into_empty(&text);
    assert_eq!(back, lib);
    assert_eq!(xml::write(&back), text);
}

#[test]
fn xml_round_trip_of_awkward_text_and_values() {
    let mut c = motor_class();
    c.id = "6f1b7c1e-8a0e-4d55-9d59-5b2b0c7e1a01".into();
    c.name = "Quotes \" ' & <angle> brackets".into();
    c.description = "  leading space\nline two\r\nwith CR LF\tand tab ]]> µ Ω  ".into();
    c.parameters[0].comment = "R <in> \"Ohm\" & more".into();
    c.parameters[2].default = Some(Value::Real(-0.1));
    c.parameters[6].default = Some(Value::String(String::new()));
    let values = obj(json!({
        "R": 0.1 + 0.2, "L": 1e-300, "ratio": -123_456_789.123_456_79, "eta": 5e-324,
        "poles": i64::MAX, "brushless": true, "winding": "a\nb\r\nc\t\"d\" <e> & 'f'  "
    }));
    let i = check_instance(
        "1b4e28ba-2fa1-11d2-883f-0016d3cca427",
        &c,
        &InstanceDraft { name: "x & y <z>".into(), source: "line 1\nline 2\r\n".into(), values },
    )
    .expect("valid");
    let lib = Library { classes: vec![c], instances: vec![i] };
    let text = xml::write(&lib);
    assert_eq!(import_into_empty(&text), lib, "{text}");
}

#[test]
fn xml_syntax_errors_name_the_line() {
    let text = "<?xml version=\"1.0\"?>\n<motorLibrary version=\"1\">\n  <class id=\"x\">\n  </klass>\n</motorLibrary>\n";
    let issues = xml::read(text).expect_err("malformed");
    assert!(issues[0].field.starts_with("line 4"), "{issues:?}");
    assert!(issues[0].message.contains("malformed XML"), "{issues:?}");
}

#[test]
fn xml_structure_errors_are_collected_with_lines_and_elements() {
    let text = r#"<motorLibrary version="1">
  <class id="6f1b7c1e-8a0e-4d55-9d59-5b2b0c7e1a01" name="M" domain="motor" modelicaClass="cad2mo.M" colour="red">
    <parameter name="R" type="Real" unit="Ohm" min="zero" editable="maybe"/>
    <parameter name="L" type="Real" unit="H" editable="false"/>
  </class>
  <instance id="1b4e28ba-2fa1-11d2-883f-0016d3cca427" class="6f1b7c1e-8a0e-4d55-9d59-5b2b0c7e1a01">
    <value param="L">0.1</value>
  </instance>
</motorLibrary>
"#;
    let issues = xml::read(text).expect_err("invalid");
    let f = fields(&issues);
    assert!(f.contains(&"line 2 <class>"), "{issues:?}");
    assert!(f.contains(&"line 3 <parameter>"), "{issues:?}");
    assert!(f.contains(&"line 6 <instance>"), "{issues:?}");
    assert!(issues.iter().any(|i| i.message.contains("colour")), "{issues:?}");
    assert!(issues.iter().any(|i| i.message.contains("zero")), "{issues:?}");
    assert!(issues.iter().any(|i| i.message.contains("maybe")), "{issues:?}");
    assert!(issues.iter().any(|i| i.message.contains("\"name\" is missing")), "{issues:?}");
}

#[test]
fn import_checks_values_against_classes_and_names_the_value_line() {
    let lib = seed::library().expect("seed");
    let text = xml::write(&lib).replace(">0.317<", ">-1<").replace(">0.72<", ">lots<");
    let doc = xml::read(&text).expect("syntax is fine");
    let issues = plan_import(&Library::default(), &doc).expect_err("bad values");
    assert!(issues.iter().any(|i| i.field.contains("<value param=\"R\">") && i.message.contains("minimum")), "{issues:?}");
    assert!(issues.iter().any(|i| i.field.contains("<value param=\"eta\">") && i.message.contains("lots")), "{issues:?}");
    for i in &issues {
        assert!(i.field.starts_with("line "), "{i:?}");
    }
}

#[test]
fn import_updates_by_id_and_migrates_instances_not_in_the_file() {
    let current = seed::library().expect("seed");
    // A file with only the efficiency gear class, its eta no longer editable and a new
    // parameter with a default.
    let mut gear = current.class(seed::EFFICIENCY_GEAR).expect("gear").clone();
    gear.parameters.push(Parameter { default: Some(Value::Real(0.0)), ..param("T_idle", ParamType::Real, "N.m", Some(0.0), None, false) });
    let text = xml::write(&Library { classes: vec![gear], instances: vec![] });
    let doc = xml::read(&text).expect("read");
    let plan = plan_import(&current, &doc).expect("plan");
    assert_eq!(plan.counts.classes_updated, 1);
    assert_eq!(plan.counts.classes_created, 0);
    // The GP 42 C and the 60 catalogue gear units.
    assert_eq!(plan.counts.instances_migrated, 61);
    let gp = plan.instances.iter().find(|i| i.id == seed::MAXON_GP42C_74).expect("migrated");
    assert_eq!(gp.value("T_idle"), Some(&Value::Real(0.0)));

    // The same class under another id but the same name collides.
    let mut twin = current.class(seed::IDEAL_GEAR).expect("gear").clone();
    twin.id = "6f1b7c1e-8a0e-4d55-9d59-5b2b0c7e1a01".into();
    let doc = xml::read(&xml::write(&Library { classes: vec![twin], instances: vec![] })).expect("read");
    let issues = plan_import(&current, &doc).expect_err("name taken");
    assert!(issues[0].message.contains("two classes would be named"), "{issues:?}");
}

#[test]
fn units_in_xml_values_are_converted() {
    let lib = seed::library().expect("seed");
    let text = xml::write(&lib).replace(r#"<value param="L">8.23e-5</value>"#, r#"<value param="L" unit="uH">82.3</value>"#);
    assert!(text.contains("unit=\"uH\""));
    assert_eq!(import_into_empty(&text), lib);
}

/// Issue 27: at least 8 AC servo motors of industrial robot size (rated output 100 W to 3 kW),
/// each model without and with its holding brake, values as the ratings table prints them.
#[test]
fn ac_servo_motors_of_robot_size() {
    let lib = seed::library().expect("seed");
    let servos: Vec<&Instance> = lib.instances.iter().filter(|i| i.class_id == seed::AC_SERVO).collect();
    let get = |i: &Instance, p: &str| i.value(p).and_then(Value::as_f64);
    let in_range = servos.iter().filter(|i| get(i, "P_nom").is_some_and(|p| (100.0..=3000.0).contains(&p))).count();
    assert_eq!(in_range, servos.len(), "every AC servo of the seed is rated 100 W to 3 kW");
    let models: HashSet<&str> = servos.iter().map(|i| i.name.split(" (").next().unwrap_or("")).collect();
    assert!(models.len() >= 8, "{models:?}");
    assert_eq!(servos.iter().filter(|i| i.name.ends_with("(with holding brake)")).count(), models.len());
    // Yaskawa SGM7A-30A with holding brake: the brake's inertia, and no w_max (footnote *9).
    let a30 = lib.instances.iter().find(|i| i.id == seed::YASKAWA_SERVOS[19]).expect("SGM7A-30A");
    assert_eq!(a30.name, "Yaskawa SGM7A-30A (with holding brake)");
    let close = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() <= 1e-12 * b.abs());
    assert!(close(get(a30, "J"), 9.20e-4) && close(get(a30, "k"), 0.582) && close(get(a30, "T_peak"), 29.4));
    assert!(close(get(a30, "T_nom"), 9.80) && close(get(a30, "I_max"), 56.0) && close(get(a30, "P_nom"), 3000.0));
    assert_eq!(get(a30, "w_max"), None);
    let g20 = lib.instances.iter().find(|i| i.id == seed::YASKAWA_SERVOS[28]).expect("SGM7G-20A");
    assert!(close(get(g20, "J"), 26.0e-4) && close(get(g20, "w_max"), 3000.0 * std::f64::consts::PI / 30.0));
}
