//! Generated VRML 97 for benchmarks: an IndexedFaceSet-heavy file of a given size, and an Inline
//! assembly of many small part files.

use std::fmt::Write as _;

/// One part: a `Transform` with a wavy `n x n` grid as an IndexedFaceSet (`(n+1)^2` points,
/// `2 n^2` triangles), numbers written `%.6f` like CAD exporters do.
fn grid_part(out: &mut String, k: usize, n: usize) {
    let a = k as f64 * 0.37;
    let _ = write!(
        out,
        "DEF Part_{k} Transform {{\n  translation {:.4} {:.4} 0\n  rotation 0 0 1 {a:.5}\n  children [\n    Shape {{\n      appearance Appearance {{ material Material {{ diffuseColor 0.8 0.3 0.2 }} }}\n      geometry IndexedFaceSet {{\n        solid FALSE\n        coord Coordinate {{\n          point [\n",
        (k % 10) as f64 * 120.0,
        (k / 10) as f64 * 120.0
    );
    for i in 0..=n {
        for j in 0..=n {
            let x = i as f64 / n as f64 * 100.0 - 50.0;
            let y = j as f64 / n as f64 * 100.0 - 50.0;
            let z = 5.0 * (x * 0.1 + a).sin() * (y * 0.13).cos();
            let _ = writeln!(out, "            {x:.6} {y:.6} {z:.6},");
        }
    }
    out.push_str("          ]\n        }\n        coordIndex [\n");
    let id = |i: usize, j: usize| i * (n + 1) + j;
    for i in 0..n {
        for j in 0..n {
            let _ = writeln!(
                out,
                "          {}, {}, {}, -1, {}, {}, {}, -1,",
                id(i, j),
                id(i + 1, j),
                id(i + 1, j + 1),
                id(i, j),
                id(i + 1, j + 1),
                id(i, j + 1)
            );
        }
    }
    out.push_str("        ]\n      }\n    }\n  ]\n}\n");
}

/// A VRML 97 file of about `target_bytes`: parts of 100 x 100 grids (20,000 triangles each).
pub fn ifs_file(target_bytes: usize) -> Vec<u8> {
    let mut s = String::with_capacity(target_bytes + (1 << 20));
    s.push_str("#VRML V2.0 utf8\n# generated: IndexedFaceSet-heavy benchmark input\n");
    let mut k = 0;
    while s.len() < target_bytes {
        grid_part(&mut s, k, 100);
        k += 1;
    }
    s.into_bytes()
}

/// A main file with `parts` `Transform { Inline }` entries and `parts` small part files (a
/// 4 x 4 grid each, 32 triangles): `(bundle path, bytes)`, main first.
pub fn inline_assembly(parts: usize) -> Vec<(String, Vec<u8>)> {
    let mut main = String::from("#VRML V2.0 utf8\nDEF ASM Group {\n  children [\n");
    let mut files = Vec::with_capacity(parts + 1);
    for k in 0..parts {
        let _ = writeln!(
            main,
            "    DEF P{k} Transform {{ translation {} {} {} rotation 0 1 0 {:.4} children [ Inline {{ url \"parts/part{k}.wrl\" }} ] }}",
            k % 100,
            k / 100,
            k % 7,
            k as f64 * 0.01
        );
        let mut part = String::from("#VRML V2.0 utf8\n");
        grid_part(&mut part, k, 4);
        files.push((format!("parts/part{k}.wrl"), part.into_bytes()));
    }
    main.push_str("  ]\n}\n");
    files.insert(0, ("asm.wrl".to_string(), main.into_bytes()));
    files
}
