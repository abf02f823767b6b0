//! The diagram layout check (issue 17), shared by the tests that convert the golden cases and
//! the real fixtures: no two component extents overlap; every connect has a `Line` whose points
//! are orthogonal and whose end points lie on the two connectors (MSL's own placements, tabled
//! here, and for our own classes read from the package's class files); no line passes through a
//! component's extent.

use std::collections::BTreeMap;

use cad2mo_engine::pipeline::back::modelica::diagram::svg::{self, Drawing};
use cad2mo_engine::pipeline::Output;

use crate::fk::parse_mechanics;

pub type Pt = (f64, f64);

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
        ("BearingFriction" | "SupportFriction", "flange_a") => left,
        ("BearingFriction" | "SupportFriction", "flange_b") => right,
        ("LinearSpeedDependentTorque" | "LinearSpeedDependentForce", "flange") => right,
        (_, "frame_a") => left,
        (_, "frame_b") => right,
        _ => return None,
    })
}

/// Our own classes' connectors: every component with a placement in the package's class files
/// (nested classes too), inherited through `extends` within the package.
fn own_ports(files: &[(String, Vec<u8>)]) -> BTreeMap<(String, String), Pt> {
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
    for (path, bytes) in files {
        if !path.ends_with(".mo") || path.ends_with("Mechanics.mo") || path.ends_with("Mechatronics.mo") {
            continue;
        }
        let text = String::from_utf8_lossy(bytes);
        let class = path.trim_end_matches(".mo").trim_end_matches("/package").replace('/', ".");
        // Nested classes: `model NAME ... end NAME;` below the file's own class.
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate().skip(1) {
            let t = line.trim_start();
            let Some(name) =
                ["model ", "block ", "connector "].iter().find_map(|k| t.strip_prefix(k)).and_then(|r| r.split_whitespace().next())
            else {
                continue;
            };
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
pub fn check_package(label: &str, out: &Output) -> Vec<String> {
    // The package's text (the shape files play no part in the layout).
    let plain: Vec<(String, Vec<u8>)> = out
        .files
        .iter()
        .filter(|(p, _)| !p.contains("/Resources/Shapes/") && !p.contains("/Resources/Collision/"))
        .map(|(p, b)| (p.clone(), b.bytes().into_owned()))
        .collect();
    check_files(label, &plain)
}

/// Every layout error of a package's files (`<Pkg>/Mechanics.mo`, `Mechatronics.mo` and the
/// class files).
pub fn check_files(label: &str, files: &[(String, Vec<u8>)]) -> Vec<String> {
    let text = |suffix: &str| files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, b)| String::from_utf8_lossy(b).to_string());
    let Some(mechanics) = text("/Mechanics.mo") else { return vec![format!("{label}: no Mechanics.mo")] };
    let ports = own_ports(files);
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

/// Classes of the package whose header has no description string (`model X "..."`).
pub fn undescribed_classes(out: &Output) -> Vec<String> {
    let mut missing = Vec::new();
    for (path, bytes) in &out.files {
        if !path.ends_with(".mo") {
            continue;
        }
        for (i, line) in String::from_utf8_lossy(&bytes.bytes()).lines().enumerate() {
            let words: Vec<&str> = line.split_whitespace().collect();
            let Some(k) =
                words.iter().position(|w| matches!(*w, "model" | "block" | "package" | "connector" | "function" | "record" | "class"))
            else {
                continue;
            };
            // A class header: only prefixes before the keyword, a name after it.
            let prefixes_only = words[..k]
                .iter()
                .all(|w| matches!(*w, "partial" | "encapsulated" | "impure" | "pure" | "operator" | "expandable" | "replaceable"));
            let Some(name) = words.get(k + 1) else { continue };
            if !prefixes_only || name.starts_with('"') || *name == "=" || words.get(k + 2) == Some(&"=") {
                continue;
            }
            if !words.get(k + 2).is_some_and(|w| w.starts_with('"')) && !name.contains('=') {
                missing.push(format!("{path}:{}: {}", i + 1, line.trim()));
            }
        }
    }
    missing
}
