//! End-to-end conversion benchmarks: a generated 2,000-body tree (no meshes, and with 37 MB of
//! ASCII STL), the largest XML
//! fixture, and the largest fixture bundle with STL meshes (DXF + STL written). The service's whole package build is
//! `cad2mo-server`'s `package` benchmark.

use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "support/mod.rs"]
mod support;
use support::{fixtures, gen};

fn bundle_of_dir(dir: &std::path::Path) -> Bundle {
    Bundle::from_files("fixture", gen::files_under(dir)).expect("fixture bundle reads")
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("convert");
    g.sample_size(20);
    let xml = gen::tree_xml(2000);
    let bundle = Bundle::from_files("gen", [("tree.xml".to_string(), xml.clone().into_bytes())]).expect("bundle");
    let out = pipeline::convert(&bundle, &Options::default()).expect("generated tree converts");
    assert_eq!(out.report.bodies.len(), 2001);
    g.throughput(Throughput::Bytes(xml.len() as u64));
    g.bench_function("tree_2000_bodies", |b| b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts")));

    // The same tree with an ASCII STL per body (37 MB): meshes read, collision shapes made (on
    // every core), interferences checked, both diagrams laid out, DXF and STL shapes written.
    let files = gen::tree_with_stl(2000);
    let stl_bytes: usize = files.iter().filter(|(p, _)| p.ends_with(".stl")).map(|(_, b)| b.len()).sum();
    let bundle = Bundle::from_files("gen", files).expect("bundle");
    let out = pipeline::convert(&bundle, &Options::default()).expect("generated tree with meshes converts");
    assert_eq!(out.report.bodies.len(), 2001);
    g.sample_size(10);
    g.throughput(Throughput::Bytes(stl_bytes as u64));
    g.bench_function("tree_2000_bodies_with_37MB_of_stl", |b| {
        b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts"))
    });
    g.sample_size(20);

    if let Some(fx) = fixtures() {
        let xml = fx.join("xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml");
        if let Ok(bytes) = std::fs::read(&xml) {
            g.throughput(Throughput::Bytes(bytes.len() as u64));
            let bundle = Bundle::from_files("ergocub", [("SIM_ERGOCUB_1-0.xml".to_string(), bytes)]).expect("bundle");
            g.bench_function("ergocub_67_bodies", |b| b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts")));
        }
        // Closed loops: 4 loops (3 rigid, 1 immobile leg cut by Constraints.Spherical).
        let legs = fx.join("xml/robotology+simmechanics-to-urdf/a83a61f/LEGS_MECHANISM.xml");
        if let Ok(bytes) = std::fs::read(&legs) {
            g.throughput(Throughput::Bytes(bytes.len() as u64));
            let bundle = Bundle::from_files("legs", [("LEGS_MECHANISM.xml".to_string(), bytes)]).expect("bundle");
            g.bench_function("legs_mechanism_29_bodies_4_loops", |b| {
                b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts"))
            });
        }
        let hand = fx.join("stl/robotology+icub-models-generator/25e4033/left_hand_mk3");
        if hand.is_dir() {
            let bundle = bundle_of_dir(&hand);
            g.throughput(Throughput::Bytes(bundle.total_bytes()));
            g.bench_function("left_hand_with_11MB_of_stl", |b| {
                b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts"))
            });
            // The same with every shape served by the shape cache (a re-export in the service).
            let cache: std::sync::Arc<dyn cad2mo_engine::collision::ShapeCache> =
                std::sync::Arc::new(cad2mo_engine::collision::MemoryShapeCache::default());
            let cached = Options { shape_cache: Some(cache), ..Options::default() };
            assert_eq!(pipeline::convert(&bundle, &cached).expect("converts").shapes.cached, 0);
            g.bench_function("left_hand_with_11MB_of_stl_shapes_cached", |b| {
                b.iter(|| {
                    let out = pipeline::convert(&bundle, &cached).expect("converts");
                    assert_eq!(out.shapes.computed, 0);
                    out
                })
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
