//! The live view's receiving path per frame, without the socket: decode, HMAC check and poses
//! for 50 bodies (what the relay does to each datagram before broadcasting it).

use std::hint::black_box;

use cad2mo_engine::live::{self, Header};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use sha2::{Digest, Sha256};

fn bench(c: &mut Criterion) {
    let bodies: Vec<[f64; 12]> = (0..50)
        .map(|i| {
            let a = 0.1 * f64::from(i);
            let (s, co) = a.sin_cos();
            [f64::from(i), 0.5, 0.25, co, s, 0.0, -s, co, 0.0, 0.0, 0.0, 1.0]
        })
        .collect();
    let h = Header { model: [3; 16], version: 1, layout: [1; 8], run: 9, seq: 7, time: 1.5, last: false };
    let plain = live::encode(&h, &bodies, None);
    let signed = live::encode(&h, &bodies, Some("c2m_bench"));
    let key: [u8; 32] = Sha256::digest(b"c2m_bench").into();
    let mut g = c.benchmark_group("live");
    g.throughput(Throughput::Elements(1));
    let mut poses = Vec::with_capacity(350);
    g.bench_function("decode and poses, 50 bodies", |b| {
        b.iter(|| {
            poses.clear();
            let f = live::decode(black_box(&plain)).expect("frame");
            live::poses_into(&f, &mut poses).expect("poses");
            black_box(poses.len())
        })
    });
    g.bench_function("decode, verify and poses, 50 bodies, signed", |b| {
        b.iter(|| {
            poses.clear();
            let f = live::decode(black_box(&signed)).expect("frame");
            assert!(live::verify(&f, &key));
            live::poses_into(&f, &mut poses).expect("poses");
            black_box(poses.len())
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
