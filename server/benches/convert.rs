//! End-to-end conversion benchmarks: a generated 2,000-body tree (no meshes, and with 37 MB of
//! ASCII STL), the largest XML
//! fixture, and the largest fixture bundle with STL meshes (DXF + STL written); and the service's
//! whole package build (conversion with a drive, zip) of that bundle.

use cad2mo::drives::{ReferenceSpec, ResolvedDrive};
use cad2mo::export::{build_package, ExportOptions};
use cad2mo::pipeline::back::modelica::mechatronics::{ClassChoice, ParamValue};
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

    // The same tree with an ASCII STL per body (37 MB): meshes read, collision shapes made (on
    // every core), interferences checked, both diagrams laid out, DXF and STL shapes written.
    let files = gen::tree_with_stl(2000);
    let stl_bytes: usize = files.iter().filter(|(p, _)| p.ends_with(".stl")).map(|(_, b)| b.len()).sum();
    let bundle = Bundle::from_files("gen", files).expect("bundle");
    let out = pipeline::convert(&bundle, &Options::default()).expect("generated tree with meshes converts");
    assert_eq!(out.report.bodies.len(), 2001);
    g.sample_size(10);
    g.throughput(Throughput::Bytes(stl_bytes as u64));
    g.bench_function("tree_2000_bodies_with_37MB_of_stl", |b| b.iter(|| pipeline::convert(&bundle, &Options::default()).expect("converts")));
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
            let cache: std::sync::Arc<dyn cad2mo::collision::ShapeCache> = std::sync::Arc::new(cad2mo::collision::MemoryShapeCache::default());
            let cached = Options { shape_cache: Some(cache), ..Options::default() };
            assert_eq!(pipeline::convert(&bundle, &cached).expect("converts").shapes.cached, 0);
            g.bench_function("left_hand_with_11MB_of_stl_shapes_cached", |b| {
                b.iter(|| {
                    let out = pipeline::convert(&bundle, &cached).expect("converts");
                    assert_eq!(out.shapes.computed, 0);
                    out
                })
            });
            // The job's whole build: one conversion that plans the drive from its report, then
            // the zip (deflate of the DXF text dominates).
            let files: Vec<(String, Vec<u8>)> = bundle.paths().map(|p| (p.to_string(), bundle.get(p).unwrap_or_default().to_vec())).collect();
            let zip = cad2mo::pipeline::back::bundle::write_zip(&files).expect("zip");
            let report = serde_json::to_value(&pipeline::convert(&bundle, &Options::default()).expect("converts").report).expect("json");
            let joint = cad2mo::drives::drivable_joints(&report).first().expect("a drivable joint").name.clone();
            let choice = |class: &str, params: &[(&str, f64)]| ClassChoice {
                modelica_class: class.to_string(),
                params: params.iter().map(|(n, v)| (n.to_string(), ParamValue::Real(*v))).collect(),
                instance: String::new(),
            };
            let drive = ResolvedDrive {
                joint,
                motor: choice("cad2mo.Drives.Motors.DCPermanentMagnet", &[("R", 0.317), ("k", 0.0302)]),
                gear: choice("Modelica.Mechanics.Rotational.Components.IdealGear", &[("ratio", 100.0)]),
                controller: choice("cad2mo.Drives.Controllers.CascadePPI", &[("kp", 10.0)]),
                reference: ReferenceSpec::Constant { value: 0.0 },
            };
            let built = build_package(&zip, "hand.zip", &ExportOptions::default(), std::slice::from_ref(&drive), &Default::default(), &Default::default(), &mut |_| {})
                .expect("builds");
            assert!(String::from_utf8_lossy(&built.report_json).contains(&format!("\"active\": [\n      \"{}\"", drive.joint)));
            g.throughput(Throughput::Bytes(zip.len() as u64));
            g.bench_function("left_hand_package_with_a_drive", |b| {
                b.iter(|| {
                    build_package(&zip, "hand.zip", &ExportOptions::default(), std::slice::from_ref(&drive), &Default::default(), &Default::default(), &mut |_| {})
                        .expect("builds")
                })
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
