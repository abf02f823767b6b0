//! The diagrams of the packages we write, checked on every golden case and real fixture:
//! - no two component extents overlap;
//! - every connect has a `Line`, its points are orthogonal, its end points lie on the two
//!   connectors (positions from MSL's own placements, tabled here, and for our own classes read
//!   from the package's class files);
//! - no line passes through a component's extent;
//! - the layout is deterministic, and stable: a second version with one body renamed and one
//!   joint removed keeps every other placement.
//!
//! It also draws the iCub and LEGS diagrams to `target/ui-screenshots/` (SVG), beside the UI
//! screenshots.

use std::collections::BTreeMap;
use std::path::Path;

use cad2mo::pipeline::back::modelica::diagram::svg::{self, Drawing};
use cad2mo::pipeline::front::bundle::Bundle;
use cad2mo::pipeline::{self, Options, Output};
use cad2mo_tests::common::{convert_path, files_with_ext, fixture_bundle, fixture_urdfs, fixtures_dir, sorted_dirs, urdf_bundle, workspace_root};
use cad2mo_tests::fk::parse_mechanics;

type Pt = (f64, f64);

/// MSL connectors' centres in icon coordinates, from the MSL 4.0 sources' `Placement`s.
fn msl_port(class: &str, connector: &str) -> Option<Pt> {
    let last = class.rsplit('.').next()?;
    let left = (-100.0, 0.0);
    let right = (100.0, 0.0);
    Some(match (last, connector) {
        ("World", "frame_b") => right,
        ("WorldForceAndTorque", "frame_b") => right,
        ("WorldForceAndTorque", "force") => (-120.0, 60.0),
        ("WorldForceAndTorque", "torque") => (-120.0, -60.0),
        ("IdealGear", "flange_a") | ("IdealGearR2T", "flangeR") => left,
        ("IdealGear", "flange_b") | ("IdealGearR2T", "flangeT") => right,
        (_, "frame_a") => left,
        (_, "frame_b") => right,
        _ => return None,
    })
}

/// Our own classes' connectors: every component with a placement in the package's class files
/// (nested classes too), inherited through `extends` within the package.
fn own_ports(out: &Output) -> BTreeMap<(String, String), Pt> {
    let mut ports: BTreeMap<(String, String), Pt> = BTreeMap::new();
    let mut extends: Vec<(String, String)> = Vec::new();
    let mut read_class = |class: &str, text: &str| {
        for c in svg::read(text).components {
            let centre = ((c.extent[0].0 + c.extent[1].0) / 2.0, (c.extent[0].1 + c.extent[1].1) / 2.0);
            ports.insert((class.to_string(), c.name.clone()), centre);
        }
        for line in text.lines() {
            if let Some(rest) = line.trim().strip_prefix("extends ") {
                let base = rest.split(['(', ';', ' ']).next().unwrap_or("").to_string();
                extends.push((class.to_string(), base));
            }
        }
    };
    for (path, bytes) in &out.files {
        if !path.ends_with(".mo") || path.ends_with("Mechanics.mo") || path.ends_with("Mechatronics.mo") {
            continue;
        }
        let text = String::from_utf8_lossy(bytes);
        let class = path.trim_end_matches(".mo").trim_end_matches("/package").replace('/', ".");
        // Nested classes: `model NAME ... end NAME;` below the file's own class.
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate().skip(1) {
            let t = line.trim_start();
            let Some(name) = ["model ", "block ", "connector "].iter().find_map(|k| t.strip_prefix(k)).and_then(|r| r.split_whitespace().next()) else { continue };
            if let Some(end) = lines[i..].iter().position(|l| l.trim() == format!("end {name};")) {
                read_class(&format!("{class}.{name}"), &lines[i..i + end].join("\n"));
            }
        }
        if !text.contains("package ") {
            read_class(&class, &text);
        }
    }
    // Inherited connectors (bases named by full path or relative to the package).
    for _ in 0..4 {
        for (class, base) in &extends {
            let pkg = class.split('.').next().unwrap_or("");
            let full = if base.starts_with(&format!("{pkg}.")) { base.clone() } else { format!("{pkg}.{base}") };
            let inherited: Vec<(String, Pt)> = ports.iter().filter(|((c, _), _)| *c == full).map(|((_, n), p)| (n.clone(), *p)).collect();
            for (n, p) in inherited {
                ports.entry((class.clone(), n)).or_insert(p);
            }
        }
    }
    ports
}

fn inside(p: Pt, e: &[Pt; 2]) -> bool {
    let (x1, x2) = (e[0].0.min(e[1].0), e[0].0.max(e[1].0));
    let (y1, y2) = (e[0].1.min(e[1].1), e[0].1.max(e[1].1));
    x1 + 1e-9 < p.0 && p.0 < x2 - 1e-9 && y1 + 1e-9 < p.1 && p.1 < y2 - 1e-9
}

/// Whether an axis-parallel segment enters the open rectangle `e`.
fn crosses(a: Pt, b: Pt, e: &[Pt; 2]) -> bool {
    let (x1, x2) = (e[0].0.min(e[1].0), e[0].0.max(e[1].0));
    let (y1, y2) = (e[0].1.min(e[1].1), e[0].1.max(e[1].1));
    let (lx, hx) = (a.0.min(b.0), a.0.max(b.0));
    let (ly, hy) = (a.1.min(b.1), a.1.max(b.1));
    lx < x2 - 1e-9 && hx > x1 + 1e-9 && ly < y2 - 1e-9 && hy > y1 + 1e-9
}

/// The layout errors of one model's drawing (`base` holds the components it inherits).
fn check_drawing(label: &str, d: &Drawing, base: Option<&Drawing>, ports: &BTreeMap<(String, String), Pt>) -> Vec<String> {
    let mut errors = Vec::new();
    let mut comps: Vec<&svg::Component> = base.map(|b| b.components.iter().collect()).unwrap_or_default();
    comps.extend(d.components.iter());
    let by_name: BTreeMap<&str, &svg::Component> = comps.iter().map(|c| (c.name.as_str(), *c)).collect();
    if by_name.len() != comps.len() {
        errors.push(format!("{label}: component names repeat"));
    }
    // Overlaps: sort by left edge, compare while the next starts before this one ends.
    let mut boxes: Vec<(f64, f64, f64, f64, &str)> = comps
        .iter()
        .map(|c| {
            let e = c.extent;
            (e[0].0.min(e[1].0), e[0].0.max(e[1].0), e[0].1.min(e[1].1), e[0].1.max(e[1].1), c.name.as_str())
        })
        .collect();
    boxes.sort_by(|a, b| a.0.total_cmp(&b.0));
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            if boxes[j].0 >= boxes[i].1 {
                break;
            }
            if boxes[i].2 < boxes[j].3 && boxes[j].2 < boxes[i].3 {
                errors.push(format!("{label}: {} and {} overlap", boxes[i].4, boxes[j].4));
            }
        }
    }
    for (a, b) in &d.unrouted {
        errors.push(format!("{label}: connect({a}, {b}) has no Line"));
    }
    let port_of = |arg: &str| -> Result<Pt, String> {
        let (comp, conn) = arg.split_once('.').ok_or(format!("{arg}: no connector"))?;
        let conn = conn.split('[').next().unwrap_or(conn).trim();
        let c = by_name.get(comp).ok_or(format!("{arg}: component {comp} has no placement"))?;
        let icon = ports
            .get(&(c.class.clone(), conn.to_string()))
            .copied()
            .or_else(|| msl_port(&c.class, conn))
            .ok_or(format!("{arg}: connector {conn} of {} unknown", c.class))?;
        let [(x1, y1), (x2, y2)] = c.extent;
        Ok((x1 + (icon.0 + 100.0) / 200.0 * (x2 - x1), y1 + (icon.1 + 100.0) / 200.0 * (y2 - y1)))
    };
    for l in &d.lines {
        let what = format!("{label}: connect({}, {})", l.a, l.b);
        for w in l.points.windows(2) {
            if (w[0].0 - w[1].0).abs() > 1e-9 && (w[0].1 - w[1].1).abs() > 1e-9 {
                errors.push(format!("{what}: segment {:?} -> {:?} is not orthogonal", w[0], w[1]));
            }
            for c in &comps {
                if crosses(w[0], w[1], &c.extent) {
                    errors.push(format!("{what}: segment {:?} -> {:?} passes through {}", w[0], w[1], c.name));
                }
            }
        }
        for (end, arg) in [(l.points.first(), &l.a), (l.points.last(), &l.b)] {
            match (end, port_of(arg)) {
                (Some(p), Ok(q)) if (p.0 - q.0).abs() < 0.051 && (p.1 - q.1).abs() < 0.051 => {}
                (p, Ok(q)) => errors.push(format!("{what}: ends at {p:?}, connector {arg} is at {q:?}")),
                (_, Err(e)) => errors.push(format!("{label}: {e}")),
            }
        }
        for p in &l.points {
            for c in &comps {
                if inside(*p, &c.extent) {
                    errors.push(format!("{what}: point {p:?} inside {}", c.name));
                }
            }
        }
    }
    errors
}

/// Every layout error of a converted package.
fn check_package(label: &str, out: &Output) -> Vec<String> {
    let text = |suffix: &str| out.files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, b)| String::from_utf8_lossy(b).to_string());
    let Some(mechanics) = text("/Mechanics.mo") else { return vec![format!("{label}: no Mechanics.mo")] };
    let ports = own_ports(out);
    let m = svg::read(&mechanics);
    let mut errors = check_drawing(&format!("{label} Mechanics"), &m, None, &ports);
    // The connects the drawing found are all the model's connects (an independent parser).
    match parse_mechanics(&mechanics) {
        Ok(parsed) if parsed.connects.len() == m.lines.len() + m.unrouted.len() => {}
        Ok(parsed) => errors.push(format!("{label}: {} connects parsed, {} read with their lines", parsed.connects.len(), m.lines.len())),
        Err(e) => errors.push(format!("{label}: Mechanics.mo: {e}")),
    }
    if m.extent.is_none() {
        errors.push(format!("{label}: Mechanics has no Diagram coordinate system"));
    }
    if let Some(mt) = text("/Mechatronics.mo") {
        errors.extend(check_drawing(&format!("{label} Mechatronics"), &svg::read(&mt), Some(&m), &ports));
    }
    errors
}

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
        checked += 1;
    }
    assert!(checked >= 20, "only {checked} cases converted");
    assert!(failures.is_empty(), "{} layout errors:\n{}", failures.len(), failures.join("\n"));
}

/// Every real fixture: first-generation XML, URDF with meshes, second-generation XML.
fn fixture_outputs(fx: &Path) -> Vec<(String, Output)> {
    let mut outs = Vec::new();
    for xml in files_with_ext(&fx.join("xml"), &[".xml"]) {
        let rel = xml.strip_prefix(fx).expect("under").display().to_string();
        let (bundle, _tmp) = fixture_bundle(&xml);
        if let Ok(out) = convert_path(&bundle, &options()) {
            outs.push((rel, out));
        }
    }
    for (urdf, set) in fixture_urdfs(fx) {
        let rel = urdf.strip_prefix(fx).expect("under").display().to_string();
        if let Ok(out) = pipeline::convert(&urdf_bundle(&urdf, &set), &options()) {
            outs.push((rel, out));
        }
    }
    for xml in files_with_ext(&fx.join("xml2"), &[".xml"]) {
        let rel = xml.strip_prefix(fx).expect("under").display().to_string();
        let name = xml.file_name().expect("name").to_string_lossy().to_string();
        let bundle = Bundle::from_files("xml2", [(name, std::fs::read(&xml).expect("read"))]).expect("bundle");
        if let Ok(out) = pipeline::convert(&bundle, &options()) {
            outs.push((rel, out));
        }
    }
    outs
}

#[test]
fn fixtures_have_clean_diagrams() {
    let Some(fx) = fixtures_dir("fixture diagrams") else { return };
    let outs = fixture_outputs(&fx);
    let mut failures = Vec::new();
    for (rel, out) in &outs {
        let errors = check_package(rel, out);
        let bodies = out.report.bodies.len();
        println!("{rel}: {bodies} bodies, {} layout errors", errors.len());
        failures.extend(errors.into_iter().take(5));
    }
    assert!(outs.len() >= 40, "only {} fixtures converted", outs.len());
    assert!(failures.is_empty(), "layout errors (first 5 per fixture):\n{}", failures.join("\n"));
    // The pictures beside the UI screenshots.
    let dir = workspace_root().join("target/ui-screenshots");
    std::fs::create_dir_all(&dir).expect("screenshot folder");
    for (stem, needle) in [("diagram-icub", "ICUB_2-5_BB_SIM_MODEL.xml"), ("diagram-legs", "a83a61f/LEGS_MECHANISM.xml")] {
        let (rel, out) = outs.iter().find(|(r, _)| r.ends_with(needle)).unwrap_or_else(|| panic!("{needle} converted"));
        let text = |suffix: &str| out.files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, b)| String::from_utf8_lossy(b).to_string());
        let m = svg::read(&text("/Mechanics.mo").expect("Mechanics"));
        let picture = svg::svg(&[&m], &format!("{} Mechanics ({rel})", out.report.package_name));
        std::fs::write(dir.join(format!("{stem}.svg")), picture).expect("write svg");
    }
}

#[test]
fn the_layout_is_deterministic_and_kept_across_versions() {
    let case = workspace_root().join("tests/in/arm_subsystems");
    let xml = std::fs::read_to_string(case.join("ARM_SIM_MODEL.xml")).expect("xml");
    let first = convert_path(&case, &options()).expect("v1");
    let again = convert_path(&case, &options()).expect("v1 again");
    assert_eq!(first.files, again.files, "the same input gave another package");

    // Version 2: the body BASE renamed and the forearm's joint removed.
    let removed = "LINK--LINK";
    let start = xml.find(&format!("<name>\"{removed}\"</name>")).expect("joint");
    let open = xml[..start].rfind("<SimpleJoint>").expect("open");
    let close = start + xml[start..].find("</SimpleJoint>").expect("close") + "</SimpleJoint>".len();
    let v2 = format!("{}{}", &xml[..open], &xml[close..]).replacen("<name>\"BASE\"</name>", "<name>\"BASE_PLATE\"</name>", 1);
    let tmp = tempfile::tempdir().expect("tmp");
    std::fs::write(tmp.path().join("ARM_SIM_MODEL.xml"), v2).expect("write");
    copy_dir(&case.join("meshes"), &tmp.path().join("meshes"));
    let report = serde_json::to_value(&first.report).expect("report json");
    let opts = Options { name_hints: pipeline::name_hints(&report), ..options() };
    let second = convert_path(tmp.path(), &opts).expect("v2");

    let placements = |out: &Output| -> BTreeMap<String, [Pt; 2]> {
        let text = out.files.iter().find(|(p, _)| p.ends_with("/Mechanics.mo")).map(|(_, b)| String::from_utf8_lossy(b).to_string()).expect("Mechanics");
        svg::read(&text).components.into_iter().map(|c| (c.name, c.extent)).collect()
    };
    let (a, b) = (placements(&first), placements(&second));
    // The joint's follower side is now free: those bodies and what hangs on them may move.
    let free = &second.report.free_bodies;
    assert!(!free.is_empty(), "removing {removed} frees the forearm");
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
    assert!(b.contains_key("BASE"), "the renamed body keeps its Modelica name: {:?}", b.keys().collect::<Vec<_>>());
    assert!(kept >= 8, "only {kept} placements compared");
    assert!(moved.is_empty(), "placements moved by an unrelated change:\n{}", moved.join("\n"));
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
