//! The bundle's triangle budget on the SimMechanics path (`passes::geometry`): one STL named by
//! many bodies counts once per body, and the bundle past `MAX_BUNDLE_TRIANGLES` is refused naming
//! the file, the body that crosses it and the limit, before the rest is read.

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
