//! Draws a generated model's diagram as SVG, from the Modelica text alone: every component's
//! `Placement` as a box with its name above it, every `connect`'s `Line` as a polyline in its
//! colour. It reads what a Modelica tool reads, so a package from an earlier version draws too.

use std::fmt::Write as _;

/// A component read from a declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    pub class: String,
    pub name: String,
    /// Extent corners as written (after adding the origin).
    pub extent: [(f64, f64); 2],
}

/// A connect read from an equation.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    pub a: String,
    pub b: String,
    pub points: Vec<(f64, f64)>,
    pub color: (u8, u8, u8),
    pub dashed: bool,
}

/// What a model's text says about its diagram.
#[derive(Clone, Debug, Default)]
pub struct Drawing {
    pub components: Vec<Component>,
    pub lines: Vec<Line>,
    /// Connects without a `Line` annotation.
    pub unrouted: Vec<(String, String)>,
    pub extent: Option<[(f64, f64); 2]>,
}

/// The statements of a class body: split at `;` outside strings and brackets.
fn statements(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut in_str, mut esc, mut start) = (0i32, false, false, 0usize);
    for (i, c) in text.char_indices() {
        if in_str {
            if esc {
                esc = false;
            } else if c == '\\' {
                esc = true;
            } else if c == '"' {
                in_str = false;
            }
            continue;
        }
        match c {
            '"' => in_str = true,
            '(' | '{' | '[' => depth += 1,
            ')' | '}' | ']' => depth -= 1,
            ';' if depth == 0 => {
                out.push(text[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    out
}

/// Removes string literals' contents and `//` comments (so they cannot look like code).
fn strip_strings(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let (mut in_str, mut esc, mut comment) = (false, false, false);
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        if comment {
            if c == '\n' {
                comment = false;
                out.push(c);
            }
            continue;
        }
        if in_str {
            if esc {
                esc = false;
            } else if c == '\\' {
                esc = true;
            } else if c == '"' {
                in_str = false;
                out.push('"');
            }
            continue;
        }
        if c == '"' {
            in_str = true;
        } else if c == '/' && chars.peek() == Some(&'/') {
            comment = true;
            continue;
        }
        out.push(c);
    }
    out
}

/// The numbers of the `{...}` group that follows `key` in `s`.
fn numbers_after(s: &str, key: &str) -> Option<Vec<f64>> {
    let at = s.find(key)? + key.len();
    let rest = &s[at..];
    let (mut depth, mut end) = (0i32, rest.len());
    for (i, c) in rest.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    end = i + 1;
                    break;
                }
            }
            _ if depth == 0 && !c.is_whitespace() => return None,
            _ => {}
        }
    }
    Some(
        rest[..end]
            .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e' || c == 'E'))
            .filter(|t| !t.is_empty())
            .filter_map(|t| t.parse().ok())
            .collect(),
    )
}

/// Reads the diagram of one model's text.
pub fn read(text: &str) -> Drawing {
    let mut d = Drawing::default();
    let body = strip_strings(text);
    for st in statements(&body) {
        let mut st = st.trim_start_matches("equation").trim();
        // The class header before the first declaration: `model Name "description"`.
        for kw in ["model ", "block "] {
            if let Some(rest) = st.strip_prefix(kw) {
                st = rest.find("\"\"").map_or(rest, |i| rest[i + 2..].trim_start());
            }
        }
        if let Some(rest) = st.strip_prefix("extends ") {
            // `extends P.Mechanics;` ends at its own `;`: what follows is the next statement.
            st = rest;
        }
        if let Some(rest) = st.strip_prefix("connect(") {
            // The arguments end at the `)` that closes `connect(`; they split at the comma outside
            // brackets (`f.force[2, :]`).
            let (mut depth, mut comma, mut close) = (0i32, None, rest.len());
            for (i, c) in rest.char_indices() {
                match c {
                    '[' | '(' => depth += 1,
                    ']' => depth -= 1,
                    ')' if depth == 0 => {
                        close = i;
                        break;
                    }
                    ')' => depth -= 1,
                    ',' if depth == 0 && comma.is_none() => comma = Some(i),
                    _ => {}
                }
            }
            let Some(comma) = comma.filter(|&c| c < close) else { continue };
            let (a, b) = (rest[..comma].trim().to_string(), rest[comma + 1..close].trim().to_string());
            match numbers_after(st, "points=") {
                Some(p) if p.len() >= 4 => {
                    let color = numbers_after(st, "color=")
                        .filter(|c| c.len() == 3)
                        .map(|c| (c[0] as u8, c[1] as u8, c[2] as u8))
                        .unwrap_or((0, 0, 0));
                    d.lines.push(Line {
                        a,
                        b,
                        points: p.chunks(2).map(|c| (c[0], c[1])).collect(),
                        color,
                        dashed: st.contains("LinePattern.Dash"),
                    });
                }
                _ => d.unrouted.push((a, b)),
            }
            continue;
        }
        if let Some(ext) = st.find("Diagram(coordinateSystem(").and_then(|i| numbers_after(&st[i..], "extent=")) {
            if ext.len() == 4 {
                d.extent = Some([(ext[0], ext[1]), (ext[2], ext[3])]);
            }
        }
        let Some(p) = st.find("Placement(transformation(") else { continue };
        let head: Vec<&str> = st[..st.find(['(', '"']).unwrap_or(st.len()).min(p)]
            .split_whitespace()
            .filter(|w| !matches!(*w, "inner" | "outer" | "parameter" | "final" | "replaceable" | "protected" | "public"))
            .collect();
        if head.len() < 2 || head[0].starts_with("//") {
            continue;
        }
        let t = &st[p..];
        let Some(e) = numbers_after(t, "extent=").filter(|e| e.len() == 4) else { continue };
        let o = numbers_after(t, "origin=").filter(|o| o.len() == 2).unwrap_or(vec![0.0, 0.0]);
        d.components.push(Component {
            class: head[0].to_string(),
            name: head[1].split('[').next().unwrap_or(head[1]).to_string(),
            extent: [(o[0] + e[0], o[1] + e[1]), (o[0] + e[2], o[1] + e[3])],
        });
    }
    d
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The fill of a component by its class.
fn fill(class: &str) -> &'static str {
    let last = class.rsplit('.').next().unwrap_or(class);
    match last {
        "World" => "#d9e6f2",
        "Body" => "#9cc3e6",
        "FixedTranslation" | "FixedRotation" => "#e0e0e0",
        "Revolute" | "Prismatic" | "Spherical" | "RevolutePlanarLoopConstraint" => "#f4b183",
        "FixedShape" => "#c5e0b4",
        "IdealGear" | "IdealGearR2T" => "#ffe699",
        _ if class.contains("Constraints.") => "#f8cbad",
        _ if class.contains("Drives.") => "#c9b3e6",
        _ => "#f2f2f2",
    }
}

/// The SVG of `drawings` drawn over each other (a model and the one it extends), with `title`.
pub fn svg(drawings: &[&Drawing], title: &str) -> String {
    let mut lo = (f64::INFINITY, f64::INFINITY);
    let mut hi = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut grow = |x: f64, y: f64| {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    };
    for d in drawings {
        for c in &d.components {
            for &(x, y) in &c.extent {
                grow(x, y);
            }
            grow(c.extent[0].0, c.extent[0].1.max(c.extent[1].1) + 12.0);
        }
        for l in &d.lines {
            for &(x, y) in &l.points {
                grow(x, y);
            }
        }
    }
    if !lo.0.is_finite() {
        lo = (-100.0, -100.0);
        hi = (100.0, 100.0);
    }
    let m = 20.0;
    let (x0, y0, w, h) = (lo.0 - m, -(hi.1 + m) - 14.0, hi.0 - lo.0 + 2.0 * m, hi.1 - lo.1 + 2.0 * m + 14.0);
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{x0} {y0} {w} {h}\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\">\n<title>{}</title>\n<rect x=\"{x0}\" y=\"{y0}\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n<text x=\"{}\" y=\"{}\" font-size=\"10\" fill=\"#404040\">{}</text>\n",
        (w * 1.5).round(),
        (h * 1.5).round(),
        esc(title),
        lo.0 - m + 4.0,
        y0 + 11.0,
        esc(title)
    );
    for d in drawings {
        for l in &d.lines {
            let pts: Vec<String> = l.points.iter().map(|(x, y)| format!("{x},{}", -y)).collect();
            let dash = if l.dashed { " stroke-dasharray=\"4 3\"" } else { "" };
            let width = if l.color == (95, 95, 95) || l.color == (238, 46, 47) { 1.2 } else { 0.8 };
            let _ = writeln!(
                s,
                "<polyline points=\"{}\" fill=\"none\" stroke=\"rgb({},{},{})\" stroke-width=\"{width}\"{dash}><title>connect({}, {})</title></polyline>",
                pts.join(" "),
                l.color.0,
                l.color.1,
                l.color.2,
                esc(&l.a),
                esc(&l.b)
            );
        }
    }
    for d in drawings {
        for c in &d.components {
            let (x1, x2) = (c.extent[0].0.min(c.extent[1].0), c.extent[0].0.max(c.extent[1].0));
            let (y1, y2) = (c.extent[0].1.min(c.extent[1].1), c.extent[0].1.max(c.extent[1].1));
            let size = ((x2 - x1) * 1.5 / (0.6 * c.name.chars().count().max(1) as f64)).clamp(2.0, 8.0);
            let _ = writeln!(
                s,
                "<g data-component=\"{}\"><title>{} {}</title><rect x=\"{x1}\" y=\"{}\" width=\"{}\" height=\"{}\" rx=\"2\" fill=\"{}\" stroke=\"#404040\" stroke-width=\"0.6\"/><text x=\"{}\" y=\"{}\" font-size=\"{size:.1}\" text-anchor=\"middle\" fill=\"#0000c0\">{}</text></g>",
                esc(&c.name),
                esc(&c.class),
                esc(&c.name),
                -y2,
                x2 - x1,
                y2 - y1,
                fill(&c.class),
                (x1 + x2) / 2.0,
                -y2 - 2.0,
                esc(&c.name)
            );
        }
    }
    s.push_str("</svg>\n");
    s
}
