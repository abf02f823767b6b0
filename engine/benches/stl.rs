//! Throughput of the mesh IO: STL reading (binary, ASCII), DXF and binary STL writing.
//!
//! Inputs: a generated torus of 200,000 triangles in mm (100,000 shared vertices), as binary STL
//! and as ASCII STL laid out like Creo's (`%e` numbers, two-space indents); and the largest ASCII
//! and binary fixture STLs when the fixtures are present. Throughput is in bytes of the STL read,
//! or of the file written.
//!
//! `cargo bench -p cad2mo-engine --bench stl`. Fixtures default to `../shared/fixtures` next to the
//! workspace; override with `CAD2MO_FIXTURES`.

use std::fmt::Write as _;
use std::path::PathBuf;

use cad2mo_engine::pipeline::back::{dxf, stl as stl_out};
use cad2mo_engine::pipeline::front::stl;
use cad2mo_engine::pipeline::ir::Mesh;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "support/mod.rs"]
mod support;

/// A torus of `2 * nu * nv` triangles, radii 80 and 25 mm.
fn torus(nu: u32, nv: u32) -> Mesh {
    let mut vertices = Vec::with_capacity((nu * nv) as usize);
    for i in 0..nu {
        let u = f64::from(i) / f64::from(nu) * std::f64::consts::TAU;
        for j in 0..nv {
            let v = f64::from(j) / f64::from(nv) * std::f64::consts::TAU;
            let r = 80.0 + 25.0 * v.cos();
            vertices.push([(r * u.cos()) as f32, (r * u.sin()) as f32, (25.0 * v.sin()) as f32]);
        }
    }
    let id = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut triangles = Vec::with_capacity((2 * nu * nv) as usize);
    for i in 0..nu {
        for j in 0..nv {
            triangles.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            triangles.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    Mesh { vertices, triangles }
}

/// C's `%e`: six decimals, exponent with sign and at least two digits.
fn c_exp(out: &mut String, x: f32) {
    let s = format!("{x:.6e}");
    let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
    let (sign, digits) = e.strip_prefix('-').map_or(('+', e), |d| ('-', d));
    let _ = write!(out, "{m}e{sign}{digits:0>2}");
}

/// The mesh as ASCII STL, laid out like Creo's export.
fn ascii(mesh: &Mesh, name: &str) -> Vec<u8> {
    let mut s = String::with_capacity(mesh.triangles.len() * 260);
    let _ = writeln!(s, "solid {name}");
    for t in &mesh.triangles {
        s.push_str("  facet normal ");
        for k in 0..3 {
            if k > 0 {
                s.push(' ');
            }
            c_exp(&mut s, [0.0, 0.0, 1.0][k]);
        }
        s.push_str("\n    outer loop\n");
        for &i in t {
            s.push_str("      vertex ");
            for k in 0..3 {
                if k > 0 {
                    s.push(' ');
                }
                c_exp(&mut s, mesh.vertices[i as usize][k]);
            }
            s.push('\n');
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    let _ = writeln!(s, "endsolid {name}");
    s.into_bytes()
}

fn bench(c: &mut Criterion) {
    let mesh = torus(400, 250);
    let binary = stl_out::write_binary(&mesh, "torus");
    let text = ascii(&mesh, "TORUS");
    println!("generated: {} triangles; binary STL {} bytes, ASCII STL {} bytes", mesh.triangles.len(), binary.len(), text.len());

    let mut g = c.benchmark_group("stl_read");
    g.sample_size(20);
    g.throughput(Throughput::Bytes(binary.len() as u64));
    g.bench_function("binary_200k", |b| b.iter(|| stl::parse("torus.stl", &binary, 0.001)));
    g.throughput(Throughput::Bytes(text.len() as u64));
    g.bench_function("ascii_200k", |b| b.iter(|| stl::parse("torus.stl", &text, 0.001)));
    if let Some(dir) = support::fixtures() {
        let files = support::files_with_ext(&dir.join("stl"), "stl");
        let mut loaded: Vec<(PathBuf, Vec<u8>)> = files.into_iter().filter_map(|p| Some((p.clone(), std::fs::read(&p).ok()?))).collect();
        loaded.sort_by_key(|(_, b)| std::cmp::Reverse(b.len()));
        for (label, want_binary) in [("fixture_ascii_largest", false), ("fixture_binary_largest", true)] {
            if let Some((p, bytes)) = loaded.iter().find(|(_, b)| stl::is_binary(b) == want_binary) {
                println!("{label}: {} ({} bytes)", p.display(), bytes.len());
                let name = p.display().to_string();
                g.throughput(Throughput::Bytes(bytes.len() as u64));
                g.bench_function(label, |b| b.iter(|| stl::parse(&name, bytes, 0.001)));
            }
        }
    }
    g.finish();

    let metres = stl::parse("torus.stl", &binary, 0.001).unwrap_or_default();
    let dxf_len = dxf::write(&metres, [179, 179, 179], "torus").len();
    println!("DXF of the torus: {dxf_len} bytes");
    let mut g = c.benchmark_group("mesh_write");
    g.sample_size(20);
    g.throughput(Throughput::Bytes(dxf_len as u64));
    g.bench_function("dxf_200k", |b| b.iter(|| dxf::write(&metres, [179, 179, 179], "torus")));
    g.throughput(Throughput::Bytes(binary.len() as u64));
    g.bench_function("stl_binary_200k", |b| b.iter(|| stl_out::write_binary(&metres, "torus")));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
