//! End-to-end conversion benchmarks: a generated 2,000-body tree (no meshes), the largest XML
//! fixture, and the largest fixture bundle with STL meshes (DXF + STL written).


use cad2mo::pipeline::front::bundle::Bundle;
use cad2mo::pipeline::{self, Options};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "support/mod.rs"]
mod support;
use support::{fixtures, gen};


fn bundle_of_dir(dir: &std::path::Path) -> Bundle {
    cad2mo::cli::read_bundle(dir, &Default::default()).expect("fixture bundle reads")
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

    if let Some(fx) = fixtures() {
        let xml = fx.join("xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml");
        if let Ok(bytes) = std::fs::read(&xml) {
            g.throughput(Throughput::Bytes(bytes.len() as u64));
            let bundle = Bundle::from_files("ergocub", [("SIM_ERGOCUB_1-0.xml".to_string(), bytes)]).expect("bundle");
            g.bench_function("ergocub_67_bodies", |b| b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts")));
        }
        let hand = fx.join("stl/robotology+icub-models-generator/25e4033/left_hand_mk3");
        if hand.is_dir() {
            let bundle = bundle_of_dir(&hand);
            g.throughput(Throughput::Bytes(bundle.total_bytes()));
            g.bench_function("left_hand_with_11MB_of_stl", |b| {
                b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts"))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
