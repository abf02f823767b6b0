//! The bundle's triangle budget on the SimMechanics path (`passes::geometry`): one STL named by
//! many bodies counts once per body (read once, one mesh shared by the bodies), and the bundle
//! past `MAX_BUNDLE_TRIANGLES` is refused naming the file, the body that crosses it and the
//! limit, before the rest is read. VRML shapes count against the same budget, after the STL
//! meshes, refused before an instance that would pass it is expanded.

#[allow(dead_code)]
#[path = "../benches/support/gen.rs"]
mod gen;

use cad2mo_engine::pipeline::{self, back, front::bundle::Bundle, front::mesh::MAX_BUNDLE_TRIANGLES};

/// A binary STL of `n` small triangles (mm).
fn stl(n: u32) -> Vec<u8> {
    let mesh = cad2mo_engine::pipeline::ir::Mesh {
        vertices: (0..n + 2).map(|i| [i as f32 * 1e-3, (i % 2) as f32 * 0.01, 0.0]).collect(),
        triangles: (0..n).map(|i| [i, i + 1, i + 2]).collect(),
    };
    back::stl::write_binary(&mesh, "part")
}

#[test]
fn one_stl_named_by_many_bodies_counts_per_body_against_the_bundle_budget() {
    let per = 200_000u32;
    let within = MAX_BUNDLE_TRIANGLES / per as usize; // 25 bodies: exactly the budget
    let convert = |bodies: usize| {
        let mut xml = gen::tree_xml_with(bodies, true);
        for i in 0..bodies {
            xml = xml.replace(&format!("\"LINK_{i}.stl\""), "\"PART.stl\"");
        }
        let bundle =
            Bundle::from_files("many", [("tree.xml".to_string(), xml.into_bytes()), ("PART.stl".to_string(), stl(per))]).expect("bundle");
        pipeline::analyse(&bundle, &pipeline::Options::default()).map(|_| ()).map_err(|e| e.to_string())
    };
    convert(within).expect("exactly the budget converts");
    let e = convert(within + 1).expect_err("one body more is over the budget");
    assert!(
        e.contains("PART.stl")
            && e.contains(&format!("{} triangles", (within + 1) * per as usize))
            && e.contains("limit of 5000000 triangles per bundle")
            && e.contains("body \""),
        "{e}"
    );
}

/// `tree.xml` with `bodies` bodies, the first `with_stl` naming `PART.stl` and the others no file.
fn xml_naming_part(bodies: usize, with_stl: usize) -> String {
    let mut xml = gen::tree_xml_with(bodies, true);
    for i in 0..bodies {
        let name = if i < with_stl { "PART.stl" } else { "" };
        xml = xml.replace(&format!("\"LINK_{i}.stl\""), &format!("\"{name}\""));
    }
    xml
}

#[test]
fn one_stl_named_by_many_bodies_is_read_once_and_shared() {
    let xml = xml_naming_part(5, 5);
    let bundle =
        Bundle::from_files("many", [("tree.xml".to_string(), xml.into_bytes()), ("PART.stl".to_string(), stl(1_000))]).expect("bundle");
    let a = pipeline::analyse(&bundle, &pipeline::Options::default()).expect("converts");
    let meshes: Vec<_> = a.model.bodies.iter().filter_map(|b| b.mesh.clone()).collect();
    assert_eq!(meshes.len(), 5);
    assert!(meshes.iter().all(|m| std::sync::Arc::ptr_eq(m, &meshes[0]) && m.triangles.len() == 1_000));
}

/// A VRML file whose one shape (a convex polygon of `per + 2` corners: `per` triangles) is
/// placed `instances` times: the DEF and `instances - 1` USEs.
fn vrml_instances(per: usize, instances: usize) -> Vec<u8> {
    use std::fmt::Write as _;
    let mut s = String::from("#VRML V2.0 utf8\nDEF BIG Shape { geometry IndexedFaceSet { coord Coordinate { point [\n");
    for k in 0..per + 2 {
        let a = std::f64::consts::TAU * k as f64 / (per + 2) as f64;
        let _ = writeln!(s, "{:.6} {:.6} 0,", a.cos(), a.sin());
    }
    s.push_str("] }\ncoordIndex [");
    for k in 0..per + 2 {
        let _ = write!(s, "{k} ");
    }
    s.push_str("-1] } }\n");
    for i in 1..instances {
        let _ = writeln!(s, "Transform {{ translation 0 0 {i} children [ USE BIG ] }}");
    }
    s.into_bytes()
}

#[test]
fn vrml_shapes_count_against_the_bundle_budget_after_the_stl_meshes() {
    let per = 100_000;
    // 51 instances: 5.1 M triangles, refused at the Transform (holding a USE) that passes the
    // budget, before expanding it.
    let bundle = Bundle::from_files(
        "vrml",
        [("tree.xml".to_string(), xml_naming_part(3, 0).into_bytes()), ("big.wrl".to_string(), vrml_instances(per, 51))],
    )
    .expect("bundle");
    let e = pipeline::analyse(&bundle, &pipeline::Options::default()).map(|_| ()).expect_err("over the budget");
    let text = e.to_string();
    assert!(
        text.starts_with("big.wrl:")
            && text.contains("Transform would expand to 5100000 triangles (limit 5000000)")
            && text.contains("limit of 5000000 triangles per bundle")
            && text.contains("0 of them are taken by the STL meshes"),
        "{text}"
    );
    let d = &e.diagnostics()[0];
    assert!(d.file == "big.wrl" && d.line > 0 && d.message.starts_with("Transform would expand"), "{d:?}");
    // 30 instances (3 M) fit alone, but not after two bodies with 1.1 M triangles of STL each: the
    // 29th is refused.
    let bundle = Bundle::from_files(
        "vrml",
        [
            ("tree.xml".to_string(), xml_naming_part(3, 2).into_bytes()),
            ("PART.stl".to_string(), stl(1_100_000)),
            ("big.wrl".to_string(), vrml_instances(per, 30)),
        ],
    )
    .expect("bundle");
    let text = pipeline::analyse(&bundle, &pipeline::Options::default()).map(|_| ()).expect_err("over the budget").to_string();
    assert!(
        text.contains("would expand to 2900000 triangles (limit 2800000)") && text.contains("2200000 of them are taken by the STL meshes"),
        "{text}"
    );
}
