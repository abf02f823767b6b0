//! Throughput and memory of the VRML front end.
//!
//! Inputs, generated in memory (nothing is written unless asked): (a) a ~100 MB VRML 97 file of
//! IndexedFaceSet grids (`%.6f` coordinates, triangles), throughput in bytes of the file;
//! (b) a 5,000-part Inline assembly: a main file of 5,000 `Transform { Inline }` and 5,000 small
//! part files in one bundle; and the largest VRML fixture when the fixtures are present.
//!
//! Before the timings, the bench parses (a) once and prints the peak memory of that parse:
//! the process's peak RSS is reset (`/proc/self/clear_refs`), then `VmHWM - VmRSS(before)` is
//! compared with the file size and with the mesh arrays produced.
//!
//! `CAD2MO_BENCH_VTK=1` also writes (a) to a temporary file and times VTK's vtkVRMLImporter on it
//! with `tests/tools/vtk_check.py` (python3 and `pip install vtk`).
//!
//! `cargo bench -p cad2mo-engine --bench vrml`. `CAD2MO_BENCH_VRML_MB` sets the size of (a) (default
//! 100).

use std::time::Instant;

use cad2mo_engine::pipeline::front::bundle::Bundle;
use cad2mo_engine::pipeline::front::vrml;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

#[path = "support/mod.rs"]
mod support;

use support::vrml_gen;

/// A `kB` field of `/proc/self/status`, in bytes.
fn status_kb(field: &str) -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with(field))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

fn mesh_bytes(scene: &vrml::Scene) -> u64 {
    scene.nodes.iter().flat_map(|n| &n.shapes).map(|s| (s.mesh.vertices.len() * 12 + s.mesh.triangles.len() * 12) as u64).sum()
}

/// Parses once and reports the peak memory of the parse.
fn report_memory(bundle: &Bundle, main: &str, file_bytes: u64) {
    let reset = std::fs::write("/proc/self/clear_refs", "5").is_ok();
    let (Some(before), true) = (status_kb("VmRSS:"), reset) else {
        println!("memory: /proc/self/status or clear_refs unavailable; not measured");
        return;
    };
    let t = Instant::now();
    let result = vrml::parse(bundle, main);
    let secs = t.elapsed().as_secs_f64();
    let Some(hwm) = status_kb("VmHWM:") else { return };
    match result {
        Ok((scene, _)) => {
            let peak = hwm.saturating_sub(before);
            let mesh = mesh_bytes(&scene);
            let mb = |b: u64| b as f64 / 1e6;
            println!(
                "memory: file {:.1} MB, {} triangles, one parse {:.2} s ({:.0} MB/s); peak above the input {:.1} MB = mesh arrays {:.1} MB + {:.1} MB ({:.2} x the file size)",
                mb(file_bytes),
                scene.triangle_count(),
                secs,
                mb(file_bytes) / secs,
                mb(peak),
                mb(mesh),
                mb(peak.saturating_sub(mesh)),
                peak.saturating_sub(mesh) as f64 / file_bytes as f64
            );
        }
        Err(e) => println!("memory: parse failed: {e}"),
    }
}

/// Times VTK on the generated file (opt-in).
fn time_vtk(bytes: &[u8]) {
    if std::env::var("CAD2MO_BENCH_VTK").map_or(true, |v| v != "1") {
        return;
    }
    let path = std::env::temp_dir().join(format!("cad2mo-bench-{}.wrl", std::process::id()));
    if std::fs::write(&path, bytes).is_err() {
        println!("VTK: cannot write {}", path.display());
        return;
    }
    let script = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/tools/vtk_check.py");
    let t = Instant::now();
    let out = std::process::Command::new("python3").arg(&script).arg(&path).output();
    let wall = t.elapsed().as_secs_f64();
    let _ = std::fs::remove_file(&path);
    match out {
        Ok(o) => println!(
            "VTK vtkVRMLImporter on the generated file: {} (script wall time {wall:.1} s for two readings)",
            String::from_utf8_lossy(&o.stdout).trim()
        ),
        Err(e) => println!("VTK: python3 failed: {e}"),
    }
}

fn bench(c: &mut Criterion) {
    let mb: usize = std::env::var("CAD2MO_BENCH_VRML_MB").ok().and_then(|v| v.parse().ok()).unwrap_or(100);
    let big = vrml_gen::ifs_file(mb * 1_000_000);
    let big_len = big.len() as u64;
    println!("generated IndexedFaceSet file: {big_len} bytes");
    time_vtk(&big);
    let big_bundle = match Bundle::from_files("bench", [("big.wrl".to_string(), big)]) {
        Ok(b) => b,
        Err(e) => panic!("bundle: {e}"),
    };
    report_memory(&big_bundle, "big.wrl", big_len);

    let parts = vrml_gen::inline_assembly(5000);
    let asm_bytes: u64 = parts.iter().map(|(_, b)| b.len() as u64).sum();
    let asm = match Bundle::from_files("asm", parts) {
        Ok(b) => b,
        Err(e) => panic!("bundle: {e}"),
    };
    println!("generated assembly: {} files, {asm_bytes} bytes", asm.len());

    let mut g = c.benchmark_group("vrml");
    g.sample_size(10);
    g.throughput(Throughput::Bytes(big_len));
    g.bench_function("ifs_100MB", |b| b.iter(|| vrml::parse(&big_bundle, "big.wrl").map(|(s, _)| s.nodes.len())));
    g.throughput(Throughput::Bytes(asm_bytes));
    g.bench_function("inline_assembly_5000", |b| b.iter(|| vrml::parse(&asm, "asm.wrl").map(|(s, _)| s.nodes.len())));
    if let Some(dir) = support::fixtures() {
        let mut files = support::files_with_ext(&dir.join("vrml"), "wrl");
        files.sort_by_key(|p| std::cmp::Reverse(std::fs::metadata(p).map(|m| m.len()).unwrap_or(0)));
        if let Some(p) = files.first() {
            if let Ok(bytes) = std::fs::read(p) {
                println!("fixture_largest: {} ({} bytes)", p.display(), bytes.len());
                let len = bytes.len() as u64;
                if let Ok(b) = Bundle::from_files("fixture", [("f.wrl".to_string(), bytes)]) {
                    g.throughput(Throughput::Bytes(len));
                    g.bench_function("fixture_largest", |bch| bch.iter(|| vrml::parse(&b, "f.wrl").map(|(s, _)| s.nodes.len())));
                }
            }
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
