//! The service's whole package build of the largest fixture bundle with STL meshes (the left hand,
//! 11 MB of STL): one conversion that plans a drive from its report, the report's drives
//! section, then the zip, as a conversion job does it.

use cad2mo_engine::pipeline::back::modelica::mechatronics::{ClassChoice, ParamValue};
use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::{self, Options};
use cad2mo_server::service::drives::{ReferenceSpec, ResolvedDrive};
use cad2mo_server::service::export::{build_package, ExportOptions};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "../../engine/benches/support/mod.rs"]
mod support;
use support::{fixtures, gen};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("convert");
    g.sample_size(20);
    if let Some(fx) = fixtures() {
        let hand = fx.join("stl/robotology+icub-models-generator/25e4033/left_hand_mk3");
        if hand.is_dir() {
            let bundle = Bundle::from_files("left_hand_mk3", gen::files_under(&hand)).expect("fixture bundle reads");
            // The job's whole build: one conversion that plans the drive from its report, then
            // the zip (deflate of the DXF text dominates).
            let files: Vec<(String, Vec<u8>)> =
                bundle.paths().map(|p| (p.to_string(), bundle.get(p).unwrap_or_default().to_vec())).collect();
            let zip = cad2mo_engine::pipeline::back::bundle::write_zip(&files).expect("zip");
            let report = serde_json::to_value(&pipeline::convert(&bundle, &Options::default()).expect("converts").report).expect("json");
            let joint = cad2mo_server::service::drives::drivable_joints(&report).first().expect("a drivable joint").name.clone();
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
            let build = || {
                build_package(
                    &zip,
                    "hand.zip",
                    &ExportOptions::default(),
                    std::slice::from_ref(&drive),
                    &Default::default(),
                    &Default::default(),
                    &mut |_| {},
                )
                .expect("builds")
            };
            let built = build();
            let report: serde_json::Value = serde_json::from_slice(&built.report_json).expect("report.json");
            assert_eq!(report["drives"]["active"], serde_json::json!([drive.joint]), "the drive is active");
            g.throughput(Throughput::Bytes(zip.len() as u64));
            g.bench_function("left_hand_package_with_a_drive", |b| b.iter(build));
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
