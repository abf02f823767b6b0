//! Structural soundness of closed loops: the emitted `Mechanics.mo` has no redundant constraint
//! equation (Dymola and OpenModelica refuse structurally singular models) and the same mobility
//! as the CAD assembly, for every golden case and every real first-generation export.
//!
//! Both sides are computed by `support/structure.rs`, independently of the converter: the model
//! side from the parsed `Mechanics.mo` and its forward kinematics, the CAD side from the XML.
//! Every case is checked and printed (rows, rank, mobility) before the test fails, so one run
//! lists every offending input.

use std::path::Path;

use cad2mo_engine::pipeline::Options;
use cad2mo_tests::common::{convert_path, file_text, files_with_ext, fixtures_dir, sorted_dirs, workspace_root};
use cad2mo_tests::diagram::check_package;
use cad2mo_tests::fk::{forward_kinematics, parse_mechanics};
use cad2mo_tests::structure::{cad_structure, model_structure};
use serde_json::Value;

fn options(case: &Path) -> Options {
    let mut o = Options { write_shapes: false, ..Options::default() };
    if let Ok(t) = std::fs::read_to_string(case.join("options.json")) {
        let v: Value = serde_json::from_str(&t).expect("options.json");
        o.lump_welds = v["lump_welds"].as_bool().unwrap_or(false);
    }
    o
}

/// Checks one converted case; prints its numbers. `Err` names what is wrong.
fn check(name: &str, mechanics: &str, xml: &str) -> Result<(), String> {
    let model = parse_mechanics(mechanics).map_err(|e| format!("{name}: Mechanics.mo: {e}"))?;
    let poses = forward_kinematics(&model).map_err(|e| format!("{name}: forward kinematics: {e}"))?;
    let m = model_structure(&model, &poses).map_err(|e| format!("{name}: model: {e}"))?;
    let cad = cad_structure(xml).map_err(|e| format!("{name}: XML: {e}"))?;
    println!(
        "{name}: model {} rows, rank {}, {} redundant, {} free groups, mobility {}; CAD {} rows, rank {}, {} bodies, \
         mobility {}; singular values kept >= {:.1e} / {:.1e}, dropped <= {:.1e} / {:.1e} (model / CAD)",
        m.rows,
        m.rank,
        m.redundant,
        m.free_groups,
        m.mobility,
        cad.rows,
        cad.rank,
        cad.free_groups,
        cad.mobility,
        m.smallest_kept,
        cad.smallest_kept,
        m.largest_dropped,
        cad.largest_dropped
    );
    let mut errors = Vec::new();
    if m.redundant != 0 {
        errors.push(format!("{} redundant equations in Mechanics.mo: {}", m.redundant, m.offenders()));
    }
    if m.mobility != cad.mobility {
        errors.push(format!(
            "mobility {} in Mechanics.mo, {} in the CAD assembly (loop closures in the model: {:?})",
            m.mobility,
            cad.mobility,
            m.closures.iter().map(|c| format!("{} {}/{} independent", c.element, c.independent, c.rows)).collect::<Vec<_>>()
        ));
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(format!("{name}: {}", errors.join("; ")))
    }
}

#[test]
fn own_cases_have_no_redundant_equations() {
    let mut checked = 0;
    let mut failures = Vec::new();
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        let Ok(out) = convert_path(&case, &options(&case)) else { continue };
        let mechanics = file_text(&out, "/Mechanics.mo").expect("Mechanics.mo");
        let first_gen = files_with_ext(&case, &[".xml"])
            .into_iter()
            .filter_map(|p| std::fs::read_to_string(p).ok())
            .find(|t| t.contains("<PhysicalModelingXMLFile"));
        let result = match first_gen {
            Some(xml) => check(&name, &mechanics, &xml),
            // URDF and second-generation cases: the emitted model alone has no redundant
            // equation (their sources' mobility is checked by their own tests).
            None => parse_mechanics(&mechanics)
                .and_then(|model| {
                    let poses = forward_kinematics(&model)?;
                    model_structure(&model, &poses)
                })
                .map_err(|e| format!("{name}: {e}"))
                .and_then(|m| {
                    if m.redundant == 0 {
                        Ok(())
                    } else {
                        Err(format!("{name}: {} redundant equations: {}", m.redundant, m.offenders()))
                    }
                }),
        };
        if let Err(e) = result {
            failures.push(e);
        }
        checked += 1;
    }
    assert!(checked >= 7, "only {checked} cases converted");
    assert!(failures.is_empty(), "{} of {checked} cases fail:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn every_fixture_xml_has_no_redundant_equations() {
    let Some(fx) = fixtures_dir("every_fixture_xml_has_no_redundant_equations") else { return };
    let mut checked = 0;
    let mut failures = Vec::new();
    for xml in files_with_ext(&fx, &[".xml"]) {
        let text = std::fs::read_to_string(&xml).expect("read xml");
        if !text.contains("<PhysicalModelingXMLFile") {
            continue;
        }
        let rel = xml.strip_prefix(&fx).expect("under fixtures").display().to_string();
        let (bundle, _tmp) = cad2mo_tests::common::fixture_bundle(&xml);
        let out = match convert_path(&bundle, &Options { write_shapes: false, ..Options::default() }) {
            Ok(out) => out,
            Err(e) => {
                failures.push(format!("{rel}: conversion failed: {e}"));
                continue;
            }
        };
        let mechanics = file_text(&out, "/Mechanics.mo").expect("Mechanics.mo");
        if let Err(e) = check(&rel, &mechanics, &text) {
            failures.push(e);
        }
        // The diagram's layout (issue 17), on the same conversion.
        failures.extend(check_package(&rel, &out).into_iter().take(5));
        checked += 1;
    }
    assert!(checked >= 15, "only {checked} fixture XMLs converted");
    assert!(failures.is_empty(), "{} of {checked} fixtures fail:\n{}", failures.len(), failures.join("\n"));
}
