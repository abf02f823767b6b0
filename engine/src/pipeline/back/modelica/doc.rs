//! The package's `package.mo`: what was converted, from where, with what result, and how to
//! make it again, as the package's `Documentation` (info and revisions).

use std::fmt::Write as _;

use super::mechatronics::DrivePlan;
use super::write::{html, mstr};
use crate::pipeline::report::Report;

/// Warnings listed in full; more are counted.
const MAX_WARNINGS: usize = 200;

/// A short number for a table cell.
fn short(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.abs() >= 1e-3 && x.abs() < 1e6 {
        let s = format!("{x:.6}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{x:.4e}")
    }
}

/// The HTML body of the package documentation.
fn info(report: &Report, drives: &[DrivePlan], provenance: &str) -> String {
    let mut s = String::new();
    let src = &report.source;
    let _ = writeln!(s, "{provenance}");
    let _ = writeln!(
        s,
        "<p>Source: <code>{}</code>, written by {} from the CAD system {}, on {}.</p>",
        html(&src.file),
        html(&src.created_using),
        html(&src.created_from),
        html(&src.created_on)
    );
    let _ = writeln!(
        s,
        "<p><code>Mechanics</code>: {} bodies, {} joints, {} loops, {} free bodies; gravity {{{}, {}, {}}} m/s2. <code>Mechatronics</code>: {} drives.</p>",
        report.bodies.len(),
        report.joints.len(),
        report.loops.len(),
        report.free_bodies.len(),
        short(report.options.gravity[0]),
        short(report.options.gravity[1]),
        short(report.options.gravity[2]),
        drives.len()
    );
    let _ = writeln!(s, "<h4>Bodies</h4>\n<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">\n<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>");
    for b in &report.bodies {
        let _ = writeln!(
            s,
            "<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            html(&b.modelica_name),
            html(&b.cad_name),
            html(&b.node_id),
            short(b.mass),
            b.shape.as_deref().map(html).unwrap_or_else(|| "none".into())
        );
    }
    let _ = writeln!(s, "</table>\n<h4>Joints</h4>\n<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">\n<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>");
    for j in &report.joints {
        let _ = writeln!(
            s,
            "<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            html(&j.modelica_name),
            html(&j.cad_name),
            html(&j.node_id),
            html(&j.emitted_as),
            html(&j.base_body),
            html(&j.follower_body)
        );
    }
    let _ = writeln!(s, "</table>");
    if !report.loops.is_empty() {
        let _ = writeln!(s, "<h4>Loops and how they were closed</h4>\n<ul>");
        for l in &report.loops {
            let _ = writeln!(
                s,
                "<li>{} (a {} loop through {}): {}</li>",
                html(&l.closing_joint),
                html(l.kind),
                html(&l.joints.join(", ")),
                html(&l.why)
            );
        }
        let _ = writeln!(s, "</ul>");
    }
    if !report.free_bodies.is_empty() {
        let _ = writeln!(
            s,
            "<p>Free bodies (no path to the ground; they start at their CAD pose and fall): {}.</p>",
            html(&report.free_bodies.join(", "))
        );
    }
    if !report.warnings.is_empty() {
        let _ = writeln!(s, "<h4>Warnings</h4>\n<ul>");
        for w in report.warnings.iter().take(MAX_WARNINGS) {
            let _ = writeln!(
                s,
                "<li><code>{}</code> {}{}</li>",
                html(w.code),
                if w.location.is_empty() { String::new() } else { format!("{}: ", html(&w.location)) },
                html(&w.message)
            );
        }
        if report.warnings.len() > MAX_WARNINGS {
            let _ = writeln!(s, "<li>and {} more (see report.json)</li>", report.warnings.len() - MAX_WARNINGS);
        }
        let _ = writeln!(s, "</ul>");
    }
    if !drives.is_empty() {
        let _ = writeln!(s, "<h4>Drives</h4>\n<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">\n<tr><th>joint</th><th>motor</th><th>gear</th><th>controller</th></tr>");
        let cell = |c: &super::mechatronics::ClassChoice| {
            if c.instance.is_empty() {
                format!("<code>{}</code>", html(&c.modelica_class))
            } else {
                format!("{} (<code>{}</code>)", html(&c.instance), html(&c.modelica_class))
            }
        };
        for d in drives {
            let _ = writeln!(
                s,
                "<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td></tr>",
                html(&d.joint),
                cell(&d.motor),
                cell(&d.gear),
                cell(&d.controller)
            );
        }
        let _ = writeln!(s, "</table>");
    }
    let _ = writeln!(
        s,
        "<h4>Regenerating</h4>\n<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>"
    );
    s
}

/// `<Pkg>/package.mo` with its documentation.
pub fn package_file(report: &Report, drives: &[DrivePlan], provenance: &str, version: &str) -> String {
    let pkg = &report.package_name;
    format!(
        "within ;\npackage {pkg} \"Modelica model of CAD assembly {}, converted by cad2mo\"\n  extends Modelica.Icons.Package;\n  annotation (\n    uses(Modelica(version=\"4.0.0\")),\n    Documentation(info=\"<html>\n{}</html>\", revisions=\"<html>\n<ul><li>cad2mo {}: converted from <code>{}</code> (exported {}).</li></ul>\n</html>\"));\nend {pkg};\n",
        mstr(&report.model_name),
        mstr(&info(report, drives, provenance)),
        mstr(&html(version)),
        mstr(&html(&report.source.file)),
        mstr(&html(&report.source.created_on))
    )
}
