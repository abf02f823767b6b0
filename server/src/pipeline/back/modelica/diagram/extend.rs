//! The diagram of `Mechatronics`, which extends `Mechanics`: its own components are placed
//! around the inherited ones (a drive above the joint it acts on, a contact force beside its
//! body, reference tables and the collision and live-view blocks in a column left of the world)
//! and its connects are routed among all of them.
//!
//! The Mechatronics writer emits every component with the placeholder placement
//! [`PLACEHOLDER`] and its connects bare; [`lay_out`] gives each its place and line.

use super::{Class, Rect, Sheet, Style, Want};

/// The placement the Mechatronics writers emit, replaced here.
pub const PLACEHOLDER: &str = "annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={0,0})))";

/// A declaration's class and name from its first line (`  [inner ]Class name(` or
/// `  Class name if ...`), when the line starts one.
fn declaration(line: &str) -> Option<(&str, &str)> {
    let t = line.strip_prefix("  ")?;
    if t.starts_with(' ') || t.starts_with("//") {
        return None;
    }
    let mut words = t.split_whitespace();
    let class = words.next()?;
    if matches!(class, "parameter" | "connect(" | "extends" | "equation" | "public" | "protected" | "annotation") || class.starts_with("connect(") {
        return None;
    }
    let name = words.next()?.split(['(', ';', '[']).next()?;
    let ok = |s: &str| s.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.');
    (ok(class) && ok(name)).then_some((class, name))
}

/// Where a Mechatronics component wants to stand.
fn want(class: &str, name: &str, base: &Sheet, left: &mut i32, top: i32) -> (Class, Want) {
    if class.contains(".Components.Drives.") {
        if let Some(j) = name.strip_prefix("drive_").and_then(|j| base.placed.get(j)) {
            return (Class::Drive, Want { x: j.x - 40, y: j.y + 55, half: 10, flip: false });
        }
    }
    if class.ends_with("Forces.WorldForceAndTorque") {
        if let Some(b) = name.strip_prefix("collisionForce_").and_then(|b| base.placed.get(b)) {
            return (Class::WorldForce, Want { x: b.x - 60, y: b.y + 50, half: 10, flip: true });
        }
    }
    let class_kind = if class.ends_with("Collision.World") { Class::CollisionWorld } else { Class::Other };
    let y = top - 60 * *left;
    *left += 1;
    (class_kind, Want { x: base.extent(0).x1 - 80, y, half: 15, flip: false })
}

/// How a connect between these connectors is drawn.
fn style(a: &str, b: &str) -> Style {
    if a.contains(".frame_") || b.contains(".frame_") {
        Style::Frame
    } else if a.contains(".force") || a.contains(".torque") {
        Style::Signal
    } else {
        Style::Flange
    }
}

/// Places the components and routes the connects of a Mechatronics text written with
/// placeholders; the text with placements and lines, and the extent of the whole diagram.
pub fn lay_out(text: &str, base: &Sheet) -> (String, Rect) {
    let mut sheet = base.clone();
    let top = base.extent(0).y2 - 20;
    let mut left = 0;
    let mut out = String::with_capacity(text.len() * 2);
    let mut current: Option<(String, String)> = None;
    let from = sheet.wires.len();
    let mut connects = Vec::new();
    // First every component, so the routes know them all.
    let mut lines: Vec<String> = Vec::new();
    for line in text.lines() {
        if let Some((c, n)) = declaration(line) {
            current = Some((c.to_string(), n.to_string()));
        }
        if let (Some(at), Some((class, name))) = (line.find(PLACEHOLDER), current.as_ref()) {
            let (kind, w) = want(class, name, base, &mut left, top);
            let placed = sheet.add(name, kind, w);
            lines.push(format!("{}{}{}", &line[..at], placed.annotation(), &line[at + PLACEHOLDER.len()..]));
            continue;
        }
        lines.push(line.to_string());
    }
    for line in &lines {
        let t = line.trim();
        if let Some(args) = t.strip_prefix("connect(").and_then(|r| r.strip_suffix(");")) {
            // The split is at the comma outside brackets (`f.force[2, :]`).
            let mut depth = 0;
            let split = args.char_indices().find(|&(_, c)| {
                match c {
                    '[' | '(' => depth += 1,
                    ']' | ')' => depth -= 1,
                    _ => {}
                }
                c == ',' && depth == 0
            });
            if let Some((i, _)) = split {
                connects.push((args[..i].trim().to_string(), args[i + 1..].trim().to_string()));
            }
        }
    }
    for (a, b) in &connects {
        sheet.connect(a, b, style(a, b));
    }
    let mut routed = sheet.wires[from..].iter();
    for line in lines {
        let t = line.trim();
        if t.starts_with("connect(") && t.ends_with(");") {
            if let Some(w) = routed.next() {
                let indent = &line[..line.len() - line.trim_start().len()];
                let eq = w.equation();
                out.push_str(indent);
                out.push_str(eq.trim_start());
                continue;
            }
        }
        out.push_str(&line);
        out.push('\n');
    }
    (out, sheet.extent(40))
}
