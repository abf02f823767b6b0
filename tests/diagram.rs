//! The diagrams of the packages we write: the layout check (`support/diagram.rs`) on every
//! golden case (the real fixtures are checked where they are converted); the layout is
//! deterministic, and stable: a second version with one body renamed and one joint removed keeps
//! every other placement. It also draws the iCub and LEGS diagrams to `target/ui-screenshots/`
//! (SVG), beside the UI screenshots.

use std::collections::BTreeMap;
use std::path::Path;

use cad2mo_engine::pipeline::back::modelica::diagram::{extend, svg, Class, Sheet};
use cad2mo_engine::pipeline::back::modelica::{self as modelica, mechatronics};
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options, Output};
use cad2mo_tests::common::{convert_path, fixture_bundle, fixtures_dir, sorted_dirs, workspace_root};
use cad2mo_tests::diagram::{check_files, check_package, undescribed_classes};

type Pt = (f64, f64);

fn options() -> Options {
    Options { write_shapes: false, ..Options::default() }
}

#[test]
fn golden_cases_have_clean_diagrams() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        let Ok(out) = convert_path(&case, &options()) else { continue };
        failures.extend(check_package(&name, &out));
        // Every generated class says in one line what it is.
        failures.extend(undescribed_classes(&out).into_iter().map(|c| format!("{name}: class without a description: {c}")));
        checked += 1;
    }
    assert!(checked >= 20, "only {checked} cases converted");
    assert!(failures.is_empty(), "{} layout errors:\n{}", failures.len(), failures.join("\n"));
}

/// The iCub and LEGS diagrams, checked and drawn beside the UI screenshots (every fixture's
/// layout is checked where the fixtures are converted: `structure.rs`, `urdf.rs`, `simscape2.rs`).
#[test]
fn icub_and_legs_diagrams_are_drawn() {
    let Some(fx) = fixtures_dir("fixture diagrams") else { return };
    let dir = workspace_root().join("target/ui-screenshots");
    std::fs::create_dir_all(&dir).expect("screenshot folder");
    for (stem, rel) in [
        ("diagram-icub", "xml/robotology+icub-models-generator/e780c99f/ICUB_2-5_BB_SIM_MODEL.xml"),
        ("diagram-legs", "xml/robotology+simmechanics-to-urdf/a83a61f/LEGS_MECHANISM.xml"),
    ] {
        let (bundle, _tmp) = fixture_bundle(&fx.join(rel));
        let out = convert_path(&bundle, &options()).expect("converts");
        let errors = check_package(rel, &out);
        assert!(errors.is_empty(), "{}", errors.join("\n"));
        let text = |suffix: &str| {
            out.files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, b)| String::from_utf8_lossy(&b.bytes()).to_string())
        };
        let m = svg::read(&text("/Mechanics.mo").expect("Mechanics"));
        println!("{rel}: {} components, {} lines", m.components.len(), m.lines.len());
        let picture = svg::svg(&[&m], &format!("{}.Mechanics ({rel})", out.report.package_name));
        std::fs::write(dir.join(format!("{stem}.svg")), picture).expect("write svg");
    }
}

/// Converts `xml` (in `case`, with its meshes), then a second version with `removed` (a joint's
/// CAD name) taken out and body `renamed` renamed, using the first version's report as hints;
/// every component not on the freed side keeps its placement. Returns how many were compared.
fn kept_across_versions(case: &Path, xml_name: &str, removed: &str, renamed: &str) -> usize {
    let xml = std::fs::read_to_string(case.join(xml_name)).expect("xml");
    let first = convert_path(case, &options()).expect("v1");
    let again = convert_path(case, &options()).expect("v1 again");
    assert_eq!(first.files, again.files, "{xml_name}: the same input gave another package");

    let start = xml.find(&format!("<name>\"{removed}\"</name>")).expect("joint");
    let open = xml[..start].rfind("<SimpleJoint>").expect("open");
    let close = start + xml[start..].find("</SimpleJoint>").expect("close") + "</SimpleJoint>".len();
    let from = format!("<name>\"{renamed}\"</name>");
    assert!(xml.contains(&from), "{xml_name}: body {renamed}");
    let v2 = format!("{}{}", &xml[..open], &xml[close..]).replacen(&from, &format!("<name>\"{renamed}_RENAMED\"</name>"), 1);
    let tmp = tempfile::tempdir().expect("tmp");
    std::fs::write(tmp.path().join(xml_name), v2).expect("write");
    for e in std::fs::read_dir(case).expect("case").flatten() {
        if e.path().is_dir() {
            copy_dir(&e.path(), &tmp.path().join(e.file_name()));
        } else if e.file_name() != xml_name {
            std::fs::copy(e.path(), tmp.path().join(e.file_name())).expect("copy");
        }
    }
    let report = serde_json::to_value(&first.report).expect("report json");
    let opts = Options { name_hints: pipeline::name_hints(&report), ..options() };
    let second = convert_path(tmp.path(), &opts).expect("v2");

    let placements = |out: &Output| -> BTreeMap<String, [Pt; 2]> {
        let text = out
            .files
            .iter()
            .find(|(p, _)| p.ends_with("/Mechanics.mo"))
            .map(|(_, b)| String::from_utf8_lossy(&b.bytes()).to_string())
            .expect("Mechanics");
        svg::read(&text).components.into_iter().map(|c| (c.name, c.extent)).collect()
    };
    let (a, b) = (placements(&first), placements(&second));
    // The joint's follower side is now free: those bodies and what hangs on them may move, and
    // the removed joint's own components are gone.
    let free = &second.report.free_bodies;
    assert!(!free.is_empty(), "{xml_name}: removing {removed} frees a body");
    let renamed_body = first.report.bodies.iter().find(|x| x.cad_name == renamed).map(|x| x.modelica_name.clone()).expect("renamed body");
    assert!(
        second.report.bodies.iter().any(|x| x.modelica_name == renamed_body && x.cad_name.ends_with("_RENAMED")),
        "{xml_name}: the renamed body keeps its Modelica name {renamed_body}"
    );
    let mut kept = 0;
    let mut moved = Vec::new();
    for (name, ea) in &a {
        let Some(eb) = b.get(name) else { continue };
        if free.iter().any(|f| name.starts_with(f.as_str())) {
            continue;
        }
        if ea == eb {
            kept += 1;
        } else {
            moved.push(format!("{name}: {ea:?} -> {eb:?}"));
        }
    }
    assert!(moved.is_empty(), "{xml_name}: placements moved by an unrelated change:\n{}", moved.join("\n"));
    kept
}

#[test]
fn the_layout_is_deterministic_and_kept_across_versions() {
    // Our arm: the forearm's joint removed, the base renamed.
    let kept = kept_across_versions(&workspace_root().join("tests/in/arm_subsystems"), "ARM_SIM_MODEL.xml", "LINK--LINK", "BASE");
    assert!(kept >= 8, "only {kept} placements compared");
    // iCub 2.5: the right arm taken off the chest (its siblings, the left arm and the head, would
    // move up in a fresh layout), the head renamed.
    let Some(fx) = fixtures_dir("diagram stability on iCub") else { return };
    let dir = fx.join("xml/robotology+icub-models-generator/e780c99f");
    let kept =
        kept_across_versions(&dir, "ICUB_2-5_BB_SIM_MODEL.xml", "SIM_SEA_2-5_CHEST_BB--SIM_SEA_2-5_R_SHOULDER_1", "SIM_SEA_2-5_HEAD");
    assert!(kept >= 100, "only {kept} iCub placements compared");
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("mkdir");
    for e in std::fs::read_dir(from).expect("read dir").flatten() {
        let p = e.path();
        if p.is_dir() {
            copy_dir(&p, &to.join(e.file_name()));
        } else {
            std::fs::copy(&p, to.join(e.file_name())).expect("copy");
        }
    }
}

/// A URDF tree of `n` links, each hung from link `(i - 1) / 3` by a revolute joint, with a box
/// visual (a shape in the diagram), as bundle files.
fn urdf_tree(n: usize) -> Vec<(String, Vec<u8>)> {
    use std::fmt::Write as _;
    let mut u = String::from("<?xml version=\"1.0\"?>\n<robot name=\"gen\">\n  <link name=\"world\"/>\n");
    for i in 0..n {
        let parent = if i == 0 { "world".to_string() } else { format!("link_{}", (i - 1) / 3) };
        let axis = ["0 0 1", "0 1 0", "1 0 0"][i % 3];
        let _ = write!(
            u,
            "  <link name=\"link_{i}\">\n    <inertial>\n      <mass value=\"1\"/>\n      <inertia ixx=\"0.002\" ixy=\"0\" ixz=\"0\" iyy=\"0.002\" iyz=\"0\" izz=\"0.001\"/>\n    </inertial>\n    <visual>\n      <origin xyz=\"0 0 0.05\"/>\n      <geometry><box size=\"0.04 0.04 0.1\"/></geometry>\n    </visual>\n  </link>\n  <joint name=\"joint_{i}\" type=\"revolute\">\n    <parent link=\"{parent}\"/>\n    <child link=\"link_{i}\"/>\n    <origin xyz=\"0.01 {} 0.12\"/>\n    <axis xyz=\"{axis}\"/>\n    <limit lower=\"-2\" upper=\"2\" effort=\"50\" velocity=\"3\"/>\n  </joint>\n",
            0.15 * ((i % 3) as f64 - 1.0)
        );
    }
    u.push_str("</robot>\n");
    vec![("gen/gen.urdf".to_string(), u.into_bytes())]
}

/// A Mechatronics text as the writers emit it (placeholder placements, bare connects) over
/// `sheet`: a drive above every joint, the collision world (no connections) and a contact force
/// on every body, bound to the world's rows; or, `wired`, the earlier writer's text: a
/// `WorldForceAndTorque` per body fed by two signal wires from the collision world (long wires
/// across the sheet: a stress case for the budget; its world's connectors are not in today's
/// `Collision.World`, so only its work is counted).
fn mechatronics_text(pkg: &str, sheet: &Sheet, bodies: &[String], wired: bool) -> String {
    use std::fmt::Write as _;
    let ph = extend::PLACEHOLDER;
    let joints: Vec<&String> = sheet.placed.iter().filter(|(_, p)| p.class == Class::Joint).map(|(n, _)| n).collect();
    let mut t = format!("within {pkg};\nmodel Mechatronics \"Generated\"\n  extends {pkg}.Mechanics;\n  parameter Boolean collisions = false \"Contacts\";\n");
    for j in &joints {
        let _ = write!(t, "  {pkg}.Components.Drives.JointDrive drive_{j}(\n    useTable=false)\n    \"Drive of {j}\"\n    {ph};\n");
    }
    let _ = write!(t, "  {pkg}.Components.Collision.World collisionWorld(enabled=collisions, nBodies={}) \"Contact forces between the collision shapes\"\n    {ph};\n", bodies.len());
    for (k, b) in bodies.iter().enumerate() {
        if wired {
            let _ = write!(t, "  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_{b} if collisions \"Contact force and torque on {b}\"\n    {ph};\n");
        } else {
            let _ = write!(t, "  {pkg}.Components.Collision.BodyForce collisionForce_{b}(force=collisionWorld.force[{k1}, :], torque=collisionWorld.torque[{k1}, :]) if collisions \"Contact force and torque on {b}\"\n    {ph};\n", k1 = k + 1);
        }
    }
    t.push_str("equation\n");
    for j in &joints {
        let _ = writeln!(t, "  connect(drive_{j}.flange, {j}.drive);");
    }
    for (k, b) in bodies.iter().enumerate() {
        let _ = writeln!(t, "  connect(collisionForce_{b}.frame_b, {b}.frame_a);");
        if wired {
            let _ = writeln!(t, "  connect(collisionWorld.force[{}, :], collisionForce_{b}.force);", k + 1);
            let _ = writeln!(t, "  connect(collisionWorld.torque[{}, :], collisionForce_{b}.torque);", k + 1);
        }
    }
    t.push_str("end Mechatronics;\n");
    t
}

/// Routing work is linear in the wires (issue 23: A* over the whole sheet made a 2,000-body
/// assembly take more than 20 minutes). The Mechanics and Mechatronics diagrams of generated
/// trees of 250 to 2,000 links (a shape per body, a drive per joint, a contact force per body,
/// and once more with the earlier writer's contact forces wired from the collision world) are
/// laid out; the work (A* expansions and fallback segment checks, `Sheet::work`, not time)
/// per wire stays bounded, and the diagrams pass the layout check.
#[test]
fn routing_work_grows_linearly_with_the_diagram() {
    let mut rows = Vec::new();
    for n in [250usize, 500, 1000, 2000] {
        let bundle = Bundle::from_files("gen", urdf_tree(n)).expect("bundle");
        let a = pipeline::analyse(&bundle, &options()).expect("the generated tree analyses");
        let opts = modelica::Options {
            package_name: "Gen".to_string(),
            gravity: [0.0, 0.0, -9.81],
            converter_version: "test".to_string(),
            name_hints: Default::default(),
        };
        let pkg = modelica::write(&a.model, &a.validated, &opts);
        let sheet = &pkg.layout.diagram;
        let bodies = pkg.layout.names.as_ref().map(|x| x.bodies.clone()).unwrap_or_default();
        assert_eq!(bodies.len(), n);
        let mut wires = sheet.wires.len();
        let mut work = sheet.work();
        let mut parts = vec![format!("Mechanics {}", sheet.work())];
        for wired in [false, true] {
            let text = mechatronics_text("Gen", sheet, &bodies, wired);
            let (mt, _, mt_work) = extend::lay_out_counted(&text, sheet.clone());
            wires += mt.matches("  connect(").count();
            work += mt_work;
            parts.push(format!("Mechatronics{} {mt_work}", if wired { " (wired contact forces)" } else { "" }));
            if n <= 500 && !wired {
                let mut files = pkg.files.clone();
                files.extend(mechatronics::components("Gen"));
                files.extend(mechatronics::collision::files("Gen"));
                files.push(("Gen/Mechatronics.mo".to_string(), mt.into_bytes()));
                let errors = check_files(&format!("tree of {n}{}", if wired { ", wired" } else { "" }), &files);
                assert!(
                    errors.is_empty(),
                    "{} layout errors:\n{}",
                    errors.len(),
                    errors.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
                );
            }
        }
        println!(
            "{n} bodies: {} components, {wires} wires, work {work} ({}), {:.1} per wire",
            sheet.placed.len(),
            parts.join(", "),
            work as f64 / wires as f64
        );
        // Bounded per wire: the sheet's search budget, plus a fallback's checks.
        let bound = wires as u64 * (modelica::diagram::SHEET_EXPANSIONS_PER_WIRE + 200) + 20_000;
        assert!(work <= bound, "{n} bodies: work {work} over {bound} for {wires} wires");
        rows.push((n, wires, work));
    }
    // Linear: four times the bodies, at most 1.3 times four times the work (n log n or worse
    // fails: the old search grew by orders of magnitude).
    let at = |n: usize| rows.iter().find(|r| r.0 == n).map(|r| r.2 as f64).unwrap_or(f64::NAN);
    let ratio = at(2000) / at(500);
    assert!(ratio <= 4.0 * 1.3, "work grew {ratio:.2} times from 500 to 2,000 bodies: {rows:?}");
}

/// The contact forces of `Mechatronics` on a real model with collision shapes (iCub's left hand,
/// 13 bodies, each with a convex shape): one `BodyForce` per body standing beside its body, wired
/// to it by one short frame line, never a bundle of wires across the sheet (issue 30). Short:
/// each line at most 1.5 times the component spacing of `Mechanics` (the median distance from a
/// component to its nearest neighbour) long, ending within that distance of its body, and
/// spanning less than a tenth of the sheet either way.
#[test]
fn contact_force_wires_stay_beside_their_bodies_on_a_real_model() {
    let Some(fx) = fixtures_dir("contact force wiring on iCub's hand") else { return };
    let out = convert_path(&fx.join("stl/robotology+icub-models-generator/25e4033/left_hand_mk3"), &options()).expect("converts");
    let text =
        |suffix: &str| out.files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, b)| String::from_utf8_lossy(&b.bytes()).to_string());
    let mechanics = svg::read(&text("/Mechanics.mo").expect("Mechanics"));
    let mechatronics = svg::read(&text("/Mechatronics.mo").expect("Mechatronics"));
    let errors = check_package("left_hand_mk3", &out);
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    let centre = |e: &[Pt; 2]| ((e[0].0 + e[1].0) / 2.0, (e[0].1 + e[1].1) / 2.0);
    let manhattan = |a: Pt, b: Pt| (a.0 - b.0).abs() + (a.1 - b.1).abs();
    // The component spacing: the median distance from a Mechanics component to its nearest one.
    let centres: Vec<Pt> = mechanics.components.iter().map(|c| centre(&c.extent)).collect();
    let mut nearest: Vec<f64> = centres
        .iter()
        .enumerate()
        .map(|(i, &a)| centres.iter().enumerate().filter(|&(j, _)| j != i).map(|(_, &b)| manhattan(a, b)).fold(f64::INFINITY, f64::min))
        .collect();
    nearest.sort_by(f64::total_cmp);
    let spacing = nearest[nearest.len() / 2];
    let sheet = mechatronics.extent.expect("the Mechatronics diagram's extent");
    let (sheet_w, sheet_h) = ((sheet[1].0 - sheet[0].0).abs(), (sheet[1].1 - sheet[0].1).abs());
    let forces = mechatronics.components.iter().filter(|c| c.class.ends_with(".Components.Collision.BodyForce")).count();
    let mut wires = Vec::new();
    for line in mechatronics.lines.iter().filter(|l| l.a.starts_with("collisionForce_") || l.b.starts_with("collisionForce_")) {
        let (force, body) = if line.a.starts_with("collisionForce_") { (&line.a, &line.b) } else { (&line.b, &line.a) };
        let body = body.split('.').next().expect("component");
        assert_eq!(
            force.split('.').next(),
            Some(format!("collisionForce_{body}").as_str()),
            "a contact force wired to another body: {line:?}"
        );
        let length: f64 = line.points.windows(2).map(|p| manhattan(p[0], p[1])).sum();
        let xs = line.points.iter().map(|p| p.0);
        let ys = line.points.iter().map(|p| p.1);
        let span_x = xs.clone().fold(f64::NEG_INFINITY, f64::max) - xs.fold(f64::INFINITY, f64::min);
        let span_y = ys.clone().fold(f64::NEG_INFINITY, f64::max) - ys.fold(f64::INFINITY, f64::min);
        let body_at = mechanics.components.iter().find(|c| c.name == body).map(|c| centre(&c.extent)).expect("the body in Mechanics");
        let force_at = mechatronics
            .components
            .iter()
            .find(|c| Some(c.name.as_str()) == force.split('.').next())
            .map(|c| centre(&c.extent))
            .expect("the contact force placed");
        assert!(length <= 1.5 * spacing, "{force}: a wire {length} long, component spacing {spacing}: {:?}", line.points);
        assert!(manhattan(force_at, body_at) <= 1.5 * spacing, "{force} stands at {force_at:?}, {body} at {body_at:?} (spacing {spacing})");
        assert!(
            span_x < 0.1 * sheet_w && span_y < 0.1 * sheet_h,
            "{force}: crosses the sheet ({span_x} x {span_y} of {sheet_w} x {sheet_h})"
        );
        wires.push(length);
    }
    println!(
        "{} contact wires ({forces} contact forces), longest {:?}, component spacing {spacing}, sheet {sheet_w} x {sheet_h}",
        wires.len(),
        wires.iter().copied().fold(0.0, f64::max)
    );
    assert!(forces >= 10 && wires.len() == forces, "a wire per contact force: {} wires, {forces} forces", wires.len());
    // No signal wires from the collision world: each force reads its row by binding.
    assert!(
        !mechatronics.lines.iter().any(|l| l.a.starts_with("collisionWorld") || l.b.starts_with("collisionWorld")),
        "wires from the collision world"
    );
}
