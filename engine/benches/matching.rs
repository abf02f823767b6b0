//! VRML-to-body matching at scale: 10,000 bodies (generated XML) against a scene of 10,000 part
//! groups holding 100,000 shapes, plus 10,000 decoy groups placed between the parts.

use std::collections::BTreeMap;

use cad2mo_engine::pipeline::front::simmechanics;
use cad2mo_engine::pipeline::front::vrml::{Scene, SceneNode, ShapeGeom};
use cad2mo_engine::pipeline::ir::Mesh;
use cad2mo_engine::pipeline::passes::geometry_match::{match_scene, MatchOptions};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Matrix4, Vector3};

#[path = "support/mod.rs"]
mod support;

fn push(s: &mut Scene, parent: Option<usize>, name: String, global: Matrix4<f64>, shapes: usize) -> usize {
    let id = s.nodes.len();
    let shape = ShapeGeom {
        mesh: Mesh { vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], triangles: vec![[0, 1, 2]] },
        color: None,
        kind: "IndexedFaceSet",
        line: 0,
    };
    let path = match parent {
        Some(p) => format!("{}/{name}", s.nodes[p].path),
        None => name.clone(),
    };
    s.nodes.push(SceneNode {
        parent,
        name,
        named: true,
        path,
        file: "asm.wrl".into(),
        line: 0,
        global,
        shapes: vec![shape; shapes],
        children: vec![],
    });
    match parent {
        Some(p) => s.nodes[p].children.push(id),
        None => s.roots.push(id),
    }
    id
}

fn bench(c: &mut Criterion) {
    let xml = support::gen::tree_xml(10_000);
    let (model, _) = simmechanics::parse("tree.xml", xml.as_bytes()).expect("generated XML parses");
    let mut scene = Scene::default();
    let root = push(&mut scene, None, "ASM".into(), Matrix4::identity(), 0);
    for (i, b) in model.bodies.iter().enumerate().filter(|(_, b)| b.cad_name != "RootPart") {
        let pose = model.frame(b.cs1).pose;
        let mut m = pose.to_homogeneous();
        m.fixed_view_mut::<3, 1>(0, 3).scale_mut(1e3); // the scene is in mm, like the XML
        let part = push(&mut scene, Some(root), format!("PRT{i:05}"), m, 0);
        for k in 0..10 {
            push(&mut scene, Some(part), format!("S{k}"), m, 1);
        }
        let decoy = m * Matrix4::new_translation(&Vector3::new(37.0, 11.0, 5.0));
        push(&mut scene, Some(root), format!("DECOY{i:05}"), decoy, 1);
    }
    assert!(scene.nodes.iter().map(|n| n.shapes.len()).sum::<usize>() >= 100_000);
    let mut g = c.benchmark_group("matching");
    g.sample_size(10);
    g.bench_function("10k_bodies_100k_shapes", |bch| {
        bch.iter_batched(
            || model.clone(),
            |mut m| {
                let (rep, _) = match_scene(&mut m, &scene, &BTreeMap::new(), &MatchOptions::default()).expect("matches");
                assert_eq!(rep.bodies.len(), 10_000);
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
