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
    let mut words = t.split_whitespace().skip_while(|w| matches!(*w, "inner" | "outer"));
    let class = words.next()?;
    if matches!(class, "parameter" | "connect(" | "extends" | "equation" | "public" | "protected" | "annotation")
        || class.starts_with("connect(")
    {
        return None;
    }
    let name = words.next()?.split(['(', ';', '[']).next()?;
    let ok = |s: &str| {
        s.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
    };
    (ok(class) && ok(name)).then_some((class, name))
}

/// Where a Mechatronics component wants to stand; `left` is the x of the left column (left of
/// everything `base` holds), `row` counts the components already standing in it.
fn want(class: &str, name: &str, base: &Sheet, row: &mut i32, left: i32, top: i32) -> (Class, Want) {
    if class.contains(".Components.Drives.") {
        if let Some(j) = name.strip_prefix("drive_").and_then(|j| base.placed.get(j)) {
            return (Class::Drive, Want { x: j.x - 40, y: j.y + 55, half: 10, flip: false });
        }
    }
    let body = name.strip_prefix("collisionForce_").and_then(|b| base.placed.get(b));
    if class.ends_with(".Components.Collision.BodyForce") {
        // Above the body's left end, its frame_b straight above the body's frame_a: in the gap
        // between two rows, where only drives and contact forces stand.
        if let Some(b) = body {
            return (Class::TwoPort, Want { x: b.x - b.half - 20, y: b.y + 50, half: 10, flip: false });
        }
    }
    if class.ends_with("Forces.WorldForceAndTorque") {
        if let Some(b) = body {
            return (Class::WorldForce, Want { x: b.x - 60, y: b.y + 50, half: 10, flip: true });
        }
    }
    // The collision world of the writer that wires it to every contact force (its outputs);
    // one whose forces reach them as an outer component has no connection drawn.
    let class_kind = if class.ends_with("Collision.World") { Class::CollisionWorld } else { Class::Other };
    let y = top - 60 * *row;
    *row += 1;
    (class_kind, Want { x: left - 80, y, half: 15, flip: false })
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
/// placeholders among those of `base` (the Mechanics diagram, extended here: taken, not copied,
/// since a 2,000-body sheet is megabytes); the text with placements and lines, and the extent
/// of the whole diagram.
pub fn lay_out(text: &str, base: Sheet) -> (String, Rect) {
    let (text, extent, _) = lay_out_counted(text, base);
    (text, extent)
}

/// [`lay_out`], with the routing work it did (see [`Sheet::work`]).
pub fn lay_out_counted(text: &str, base: Sheet) -> (String, Rect, u64) {
    let base_work = base.work();
    let base_extent = base.extent(0);
    // The components of `base` keep their places: where a Mechatronics component wants to
    // stand is read from them, and they are the same in the growing sheet.
    let mut sheet = base;
    let top = base_extent.y2 - 20;
    let mut row = 0;
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
            let (kind, w) = want(class, name, &sheet, &mut row, base_extent.x1, top);
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
    let work = sheet.work() - base_work;
    (out, sheet.extent(40), work)
}
