//! URDF front end: a generated 200-link tree with one binary STL per link (64 triangles each),
//! parsed alone and converted end to end without writing shape files (the target:
//! under 100 ms), plus the real iCub URDF with its 56 COLLADA meshes when the fixtures are there.

use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options};
use criterion::{criterion_group, criterion_main, Criterion};

#[path = "support/mod.rs"]
mod support;
use support::{fixtures, gen};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("urdf");
    g.sample_size(20);
    let files = gen::urdf_tree(200);
    let urdf = files.iter().find(|(p, _)| p.ends_with(".urdf")).expect("urdf").1.clone();
    let bundle = Bundle::from_files("gen", files).expect("bundle");
    let opts = Options { write_shapes: false, ..Options::default() };
    let out = pipeline::convert(&bundle, &opts).expect("generated URDF converts");
    assert_eq!(out.report.bodies.len(), 200);
    assert!(out.report.bodies.iter().all(|b| !b.geometry.is_empty()));
    g.bench_function("parse_200_links", |b| b.iter(|| pipeline::front::urdf::parse("gen_tree.urdf", &urdf).expect("parses")));
    g.bench_function("analyse_200_links_with_meshes", |b| b.iter(|| pipeline::analyse(&bundle, &opts).expect("analyses")));
    g.bench_function("convert_200_links_with_meshes", |b| b.iter(|| pipeline::convert(&bundle, &opts).expect("converts")));
    if let Some(fx) = fixtures() {
        let set = fx.join("urdf/Gepetto+example-robot-data/39aa9437");
        let mut files = Vec::new();
        let dir = set.join("robots/icub_description");
        let mut stack = vec![dir.clone()];
        while let Some(d) = stack.pop() {
            for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
                let p = e.path();
                if p.is_dir() {
                    stack.push(p);
                } else if let Ok(rel) = p.strip_prefix(&set) {
                    files.push((rel.to_string_lossy().replace('\\', "/"), std::fs::read(&p).expect("read")));
                }
            }
        }
        if !files.is_empty() {
            let bundle = Bundle::from_files("icub", files).expect("bundle");
            g.bench_function("icub_56_links_collada", |b| b.iter(|| pipeline::convert(&bundle, &opts).expect("converts")));
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
