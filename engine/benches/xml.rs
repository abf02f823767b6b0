//! Throughput of the first-generation SimMechanics XML front end alone (bytes in, IR out):
//! (a) the largest XML fixture, ergoCub 1.0 (423 KB, 67 bodies), when the fixtures are present;
//! (b) a generated 2,000-body tree (`support/gen.rs`, shared with the conversion benchmark).
//!
//! `cargo bench -p cad2mo-engine --bench xml`. Fixtures default to `../shared/fixtures` next to the
//! workspace; override with `CAD2MO_FIXTURES`.

use cad2mo_engine::pipeline::front::simmechanics;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "support/mod.rs"]
mod support;
use support::{fixtures, gen};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("xml");

    if let Some(dir) = fixtures() {
        let path = dir.join("xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml");
        match std::fs::read(&path) {
            Ok(bytes) => {
                let (m, _) = simmechanics::parse("SIM_ERGOCUB_1-0.xml", &bytes).expect("fixture parses");
                assert_eq!(m.bodies.len(), 67);
                g.throughput(Throughput::Bytes(bytes.len() as u64));
                g.bench_function("ergocub_1fe125d3", |b| b.iter(|| simmechanics::parse("SIM_ERGOCUB_1-0.xml", &bytes).expect("parses")));
            }
            Err(e) => println!("NOTICE: {} not readable ({e}); skipped", path.display()),
        }
    }

    let xml = gen::tree_xml(2000);
    let (m, _) = simmechanics::parse("tree.xml", xml.as_bytes()).expect("generated tree parses");
    assert_eq!((m.bodies.len(), m.joints.len()), (2001, 2001));
    g.throughput(Throughput::Bytes(xml.len() as u64));
    g.bench_function("tree_2000_bodies", |b| b.iter(|| simmechanics::parse("tree.xml", xml.as_bytes()).expect("parses")));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
