//! Second-generation Simscape Multibody XML (`front::simscape2`) on the real exports in
//! `../shared/fixtures/xml2`: every file converts; the emitted Modelica, walked by the
//! independent FK reader, puts every body's CS1 frame and CG where an independent scan of the XML
//! (instance transforms composed down the tree, below) puts them, to 1e-9 m; masses and world
//! inertias exact; Onshape joint counts and kinds as the files state them; mates of the
//! SolidWorks and Creo files reduce to plausible joints.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use cad2mo_engine::pipeline::front::simscape2;
use cad2mo_engine::pipeline::ir::{Model, PrimitiveKind, Warning};
use cad2mo_engine::pipeline::valid::{Analysis, Validated};
use cad2mo_engine::pipeline::{back, passes, report, valid, Output, VERSION};
use cad2mo_tests::check::fk_check_with_inertia;
use cad2mo_tests::common::fixtures_dir;
use cad2mo_tests::xml2_truth::scan;
use nalgebra::Vector3;

/// The 11 fixture files, relative to `xml2/`.
const FILES: [&str; 11] = [
    "mathworks+Simscape-Backhoe-Arm/ce3ff7e0/CAD/Import/backhoe_arm_OS.xml",
    "ErroujiOussama+Arm-Robot/8d2b4829/Simulation/Simscape/finalAssembly.xml",
    "ASU-ROBO-ARM+Matllab-Project/0a895ecb/Assembly_Model.xml",
    "AreliaEmber+practical_robotic_control/c4802d93/SimulationFast/Tumbller.xml",
    "s-ritwik+Stewart-Platfrom-surge/94cc7b93/Phase 3-simulation/leg3StewartPlatform.xml",
    "s-ritwik+Stewart-Platfrom-surge/94cc7b93/Phase 2-Design of Platform/FinalDesign/assemtest.xml",
    "KalanaRatnayake+SERTS/a9045197/Body/v3.0/matlab/leg_model.xml",
    "KalanaRatnayake+SERTS/a9045197/Body/v4.0/Matlab/Robot/robot.xml",
    "abdul-almusaileem+Shroombot/7e140755/design_files/arm_base_solidworks_to_simulink/Arm Base Assembly_import.xml",
    "robotology+icub-firmware-models/4a3c62ef/wrist_mk2_1/step_files/IC_021_G_207_MECH.xml",
    "robotology+icub-firmware-models/4a3c62ef/wrist_mk2/step_files/SPHERICAL_WRIST_V1.xml",
];

fn xml2_dir(test: &str) -> Option<PathBuf> {
    let d = fixtures_dir(test)?.join("xml2");
    if d.is_dir() {
        Some(d)
    } else {
        println!("NOTICE: {test} skipped: {} not found", d.display());
        None
    }
}

/// Front end, loop planning and validation, as `pipeline::analyse` does for first-generation
/// files (until the dispatch reaches this front end).
fn analyse(path: &Path) -> (Model, Validated, Vec<Warning>) {
    let bytes = std::fs::read(path).expect("read fixture");
    let name = path.file_name().expect("name").to_string_lossy().to_string();
    assert!(simscape2::is_simscape2_xml(&bytes), "{name}: not sniffed as second-generation");
    let (model, mut warnings) = simscape2::parse(&name, &bytes).unwrap_or_else(|e| panic!("{e}"));
    let planned = passes::loops::plan(&model).unwrap_or_else(|e| panic!("{name}: {e}"));
    warnings.extend(planned.warnings);
    let analysis = Analysis { hierarchy: planned.hierarchy, chains: planned.chains, loops: planned.loops };
    let validated = valid::validate(&model, analysis).unwrap_or_else(|e| panic!("{name}: {e}"));
    warnings.extend(validated.warnings.iter().cloned());
    (model, validated, warnings)
}

/// Modelica package and report: the part of `pipeline::convert` the FK check reads.
fn convert(model: &Model, validated: &Validated, warnings: Vec<Warning>) -> Output {
    let package_name = "Xml2".to_string();
    let pkg = back::modelica::write(
        model,
        validated,
        &back::modelica::Options {
            package_name: package_name.clone(),
            gravity: [0.0, -9.81, 0.0],
            converter_version: VERSION.to_string(),
            name_hints: Default::default(),
        },
    );
    let report = report::build(report::ReportInput {
        model,
        validated,
        layout: &pkg.layout,
        package_name: &package_name,
        options: report::ReportOptions { lump_welds: false, gravity: [0.0, -9.81, 0.0] },
        merged: &BTreeMap::new(),
        absorbed: &[],
        vrml: None,
        warnings,
        version: VERSION,
    });
    Output {
        files: pkg.files.into_iter().map(|(p, b)| (p, b.into())).collect(),
        report,
        shapes: Default::default(),
        step: Default::default(),
    }
}

/// Joints of the model by primitive signature (`revolute`, `prismatic+revolute`, ...).
fn joint_kinds(model: &Model) -> BTreeMap<String, usize> {
    let mut out = BTreeMap::new();
    for j in &model.joints {
        let sig: Vec<&str> = j.primitives.iter().map(|p| p.kind.as_str()).collect();
        *out.entry(sig.join("+")).or_default() += 1;
    }
    out
}

fn warning_codes(w: &[Warning]) -> BTreeMap<&'static str, usize> {
    let mut out = BTreeMap::new();
    for w in w {
        *out.entry(w.code).or_default() += 1;
    }
    out
}

/// Mobility of the emitted tree: movable coordinates of the tree joints plus 6 per free group.
fn tree_dof(model: &Model, v: &Validated) -> usize {
    let h = &v.analysis.hierarchy;
    let dof = |p: &PrimitiveKind| match p {
        PrimitiveKind::Revolute | PrimitiveKind::Prismatic => 1,
        PrimitiveKind::Spherical => 3,
        PrimitiveKind::Weld => 0,
    };
    h.tree.iter().map(|j| model.joint(*j).primitives.iter().map(|p| dof(&p.kind)).sum::<usize>()).sum::<usize>() + 6 * h.free_roots.len()
}

#[test]
fn every_xml2_fixture_converts_and_reproduces_the_cad_pose() {
    let Some(dir) = xml2_dir("every_xml2_fixture_converts_and_reproduces_the_cad_pose") else { return };
    let mut failures = Vec::new();
    for rel in FILES {
        let path = dir.join(rel);
        let (model, validated, warnings) = analyse(&path);
        let xml = std::fs::read_to_string(&path).expect("utf-8");
        let truth = scan(&xml);
        let codes = warning_codes(&warnings);
        let out = convert(&model, &validated, warnings);
        let name = path.file_name().expect("name").to_string_lossy().to_string();
        // The diagram's layout (issue 17), on the same conversion.
        failures.extend(cad2mo_tests::diagram::check_package(&name, &out).into_iter().take(5));
        println!(
            "{name}: {} bodies, {} grounds, joints {:?}, {} loops, tree DOF {}, warnings {:?}",
            model.bodies.len(),
            model.grounds.len(),
            joint_kinds(&model),
            validated.analysis.hierarchy.loops.len(),
            tree_dof(&model, &validated),
            codes
        );
        if std::env::var_os("SIMSCAPE2_VERBOSE").is_some() {
            for j in &model.joints {
                let sig: Vec<&str> = j.primitives.iter().map(|p| p.kind.as_str()).collect();
                println!("  joint {} [{}]", j.cad_name, sig.join("+"));
            }
            for w in &out.report.warnings {
                println!("  [{}] {} -- {}", w.code, w.message, w.location);
            }
        }
        assert_eq!(model.bodies.len(), truth.part_instances, "{name}: one body per part instance");
        // Joints inferred from mates, checked by hand against the assemblies (see the report):
        // (kind, count) that must hold, and the number of independent loops.
        let kinds = joint_kinds(&model);
        let inferred: &[(&str, usize)] = match name.as_str() {
            // Three ball joints (sphere-in-socket concentric mates) between the legs and the top.
            "assemtest.xml" => &[("spherical", 3)],
            // The actuator of each of the three legs: a rod turning and sliding in its barrel.
            "leg3StewartPlatform.xml" => &[("prismatic+revolute", 3)],
            // Hip, knee and ankle motors: three revolutes, everything else welded.
            "leg_model.xml" => &[("revolute", 3)],
            // Spherical parallel wrist: three arms on one axis, three rods with a revolute at
            // each end, the platform: nine revolutes, two independent loops.
            "SPHERICAL_WRIST_V1.xml" => &[("revolute", 9)],
            _ => &[],
        };
        for (k, n) in inferred {
            assert_eq!(kinds.get(*k).copied().unwrap_or(0), *n, "{name}: {kinds:?}");
        }
        if name == "SPHERICAL_WRIST_V1.xml" {
            assert_eq!(validated.analysis.hierarchy.loops.len(), 2);
            assert!(!codes.contains_key("mate-unreducible") && !codes.contains_key("free-bodies"), "{codes:?}");
        }
        assert_eq!(model.source.format, "simscape2");
        // Node IDs unique per kind (duplicate joint names such as the ASU arm's two
        // "Revolute1" get "#2"; instance uids repeat across sub-assemblies).
        let unique = |ids: Vec<&str>| {
            let n = ids.len();
            let mut ids = ids;
            ids.sort_unstable();
            ids.dedup();
            ids.len() == n
        };
        assert!(unique(model.bodies.iter().map(|b| b.node_id.as_str()).collect()), "{name}: body node IDs");
        assert!(unique(model.joints.iter().map(|j| j.node_id.as_str()).collect()), "{name}: joint node IDs");
        assert!(unique(model.frames.iter().map(|f| f.node_id.as_str()).collect()), "{name}: frame node IDs");
        assert!(unique(model.grounds.iter().map(|g| g.node_id.as_str()).collect()), "{name}: ground node IDs");
        match fk_check_with_inertia(&out, &truth.frames, &truth.cgs, &truth.mass) {
            Ok(stats) => {
                println!(
                    "  FK: {} frames, {} CGs, {} inertias, {} loop checks, max error {:e} m / {:e}",
                    stats.frames, stats.cgs, stats.inertias, stats.loop_checks, stats.max_position_error, stats.max_rotation_error
                );
                if stats.frames != model.bodies.len() || stats.cgs != model.bodies.len() || stats.inertias != model.bodies.len() {
                    failures.push(format!(
                        "{name}: checked {} frames, {} CGs, {} inertias of {} bodies",
                        stats.frames,
                        stats.cgs,
                        stats.inertias,
                        model.bodies.len()
                    ));
                }
            }
            Err(e) => failures.push(format!("{name}: {}", &e[..e.len().min(3000)])),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The Onshape files' `<Joints>` become joints of the same kinds, one each; grounded instances
/// add one weld each to a ground.
#[test]
fn onshape_joints_match_the_files() {
    let Some(dir) = xml2_dir("onshape_joints_match_the_files") else { return };
    // (file, bodies, grounds, revolute, cylindrical (prismatic+revolute), welds, of which welds
    // of grounded instances to a ground)
    let cases = [
        (FILES[0], 36, 1, 8, 7, 24 + 1, 1),
        (FILES[1], 19, 1, 13, 0, 7 + 1, 1),
        (FILES[2], 48, 1, 6, 0, 41 + 1, 1),
        // Tumbller: no grounded instance, but one weld to the assembly's own frame (the world);
        // of its 27 welds one names an instance missing from the tree (left out, warned).
        (FILES[3], 28, 1, 2, 0, 26, 0),
    ];
    for (rel, bodies, grounds, rev, cyl, weld, ground_welds) in cases {
        let path = dir.join(rel);
        let (model, _, warnings) = analyse(&path);
        let truth = scan(&std::fs::read_to_string(&path).expect("utf-8"));
        let kinds = joint_kinds(&model);
        let get = |k: &str| kinds.get(k).copied().unwrap_or(0);
        assert_eq!(
            (model.bodies.len(), model.grounds.len(), get("revolute"), get("prismatic+revolute"), get("weld")),
            (bodies, grounds, rev, cyl, weld),
            "{rel}: {kinds:?}"
        );
        let tags = &truth.joint_tags;
        assert_eq!(tags.get("Revolute").copied().unwrap_or(0), rev, "{rel}: {tags:?}");
        assert_eq!(tags.get("Cylindrical").copied().unwrap_or(0), cyl, "{rel}: {tags:?}");
        let dangling = warnings.iter().filter(|w| w.code == "joint-dangling").count();
        let file_welds = tags.get("Weld").copied().unwrap_or(0);
        assert_eq!(weld + dangling, file_welds + ground_welds, "{rel}: welds {file_welds} in the file, {dangling} dangling");
        // No joint's frames are off where their kind allows (the exporters are exact).
        assert!(!warnings.iter().any(|w| w.code == "joint-frames-mismatch"), "{rel}: {warnings:?}");
        // Joint frames coincide at the CAD pose.
        for j in &model.joints {
            let (b, f) = (model.frame(j.base).pose, model.frame(j.follower).pose);
            assert!((b.translation.vector - f.translation.vector).norm() < 1e-12, "{rel}: {}", j.cad_name);
        }
    }
}

/// Every part naming a STEP file keeps the name as its bodies' geometry file (read by the
/// geometry pass, tests/step.rs); the front end itself warns about none of them.
#[test]
fn step_geometry_is_named_by_every_body() {
    let Some(dir) = xml2_dir("step_geometry_is_named_by_every_body") else { return };
    let (model, _, warnings) = analyse(&dir.join(FILES[1]));
    assert!(!warnings.iter().any(|w| w.code.starts_with("geometry-")), "{warnings:?}");
    assert_eq!(model.bodies.len(), 19, "19 part instances in finalAssembly.xml");
    assert!(model.bodies.iter().all(|b| b.geometry_file.as_deref().is_some_and(|f| f.ends_with(".step"))));
    assert!(model.bodies.iter().any(|b| b.geometry_file.as_deref() == Some("Servo Motor Micro  9g_1.step")));
    // Names verbatim, node IDs unique.
    assert!(model.bodies.iter().any(|b| b.cad_name == "Servo Motor Micro  9g_1 <4>"));
    let mut ids: Vec<&str> = model.bodies.iter().map(|b| b.node_id.as_str()).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), model.bodies.len());
}

/// Our own hand-made second-generation cases in `tests/in` (`xml2_*`, `broken_xml2_*`): the FK
/// check against the scanner, the joints they are built to give, the broken case's error. (Once
/// the pipeline dispatches second-generation files, tests/golden.rs also pins their output.)
#[test]
fn own_xml2_cases() {
    let root = cad2mo_tests::common::workspace_root().join("tests/in");
    let one_xml = |case: &str| {
        let xml = cad2mo_tests::common::files_with_ext(&root.join(case), &[".xml"]);
        assert_eq!(xml.len(), 1, "{case}");
        xml[0].clone()
    };
    // Onshape: revolute (follower frame turned 15 deg about z), weld, prismatic inside the
    // sub-assembly's definition (follower 0.1 m along the slide), weld.
    let path = one_xml("xml2_onshape");
    let (model, validated, warnings) = analyse(&path);
    let kinds = joint_kinds(&model);
    assert_eq!(kinds, BTreeMap::from([("prismatic".to_string(), 1), ("revolute".to_string(), 1), ("weld".to_string(), 3)]));
    // No warning: the five STEP names are kept for the geometry pass (which warns about files
    // absent from the bundle), so no body is without geometry either.
    assert!(warnings.is_empty(), "{warnings:?}");
    assert!(model.bodies.iter().any(|b| b.cad_name == "Tool (grün) <1>" && b.subsystem_path.is_empty()));
    assert!(model.bodies.iter().any(|b| b.node_id == "MSub1|MCar1" && b.subsystem_path == ["Slide Unit <1>"]));
    let slide = model.joints.iter().find(|j| j.cad_name == "slide").expect("slide");
    assert_eq!(slide.node_id, "joint:MSub1|slide");
    let truth = scan(&std::fs::read_to_string(&path).expect("xml"));
    let out = convert(&model, &validated, warnings);
    let stats = fk_check_with_inertia(&out, &truth.frames, &truth.cgs, &truth.mass).unwrap_or_else(|e| panic!("xml2_onshape: {e}"));
    assert_eq!((stats.frames, stats.cgs, stats.inertias), (5, 5, 5));

    // SolidWorks: a revolute (concentric + face), a planar (one face pair), a weld (three face
    // pairs onto a rigid sub-assembly, itself two bodies welded), and a pin in a slot that no
    // single joint allows (warned, no joint).
    let path = one_xml("xml2_solidworks");
    let (model, validated, warnings) = analyse(&path);
    let kinds = joint_kinds(&model);
    assert_eq!(
        kinds,
        BTreeMap::from([("prismatic+prismatic+revolute".to_string(), 1), ("revolute".to_string(), 1), ("weld".to_string(), 3)]),
        "{warnings:?}"
    );
    let slot: Vec<&Warning> = warnings.iter().filter(|w| w.code == "mate-unreducible").collect();
    assert_eq!(slot.len(), 1, "{warnings:?}");
    assert!(slot[0].message.contains("Coincident \"SlotPin\"") && slot[0].message.contains("\"slider-1\""), "{}", slot[0].message);
    let rev = model.joints.iter().find(|j| j.primitives[0].kind == PrimitiveKind::Revolute && j.primitives.len() == 1).expect("revolute");
    let o = model.frame(rev.base).pose.translation.vector;
    assert!((o.xy() - nalgebra::Vector2::new(0.1, 0.05)).norm() < 1e-12, "pivot {o}");
    assert!((rev.primitives[0].axis_world - Vector3::z()).norm() < 1e-12);
    let truth = scan(&std::fs::read_to_string(&path).expect("xml"));
    let out = convert(&model, &validated, warnings);
    let stats = fk_check_with_inertia(&out, &truth.frames, &truth.cgs, &truth.mass).unwrap_or_else(|e| panic!("xml2_solidworks: {e}"));
    assert_eq!((stats.frames, stats.cgs, stats.inertias), (6, 6, 6));

    // Broken: an unknown joint kind is an error naming the element and its position.
    let path = one_xml("broken_xml2_unknown_joint");
    let e = simscape2::parse("slide_arm.xml", &std::fs::read(&path).expect("xml")).expect_err("unknown joint kind");
    assert_eq!(e.element, "Screw \"shoulder\"");
    assert!(e.to_string().starts_with("slide_arm.xml:"), "{e}");
    assert!(e.message.starts_with("unknown joint kind <Screw>"), "{e}");
}
