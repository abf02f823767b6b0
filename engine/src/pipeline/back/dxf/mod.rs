//! DXF back end: a mesh as a minimal AutoCAD R12 (`AC1009`) ASCII DXF of `3DFACE`s, the shape
//! format of `Modelica.Mechanics.MultiBody.Visualizers.FixedShape`. See [`write()`].
//!
//! # What is written
//! A DXF file is a sequence of (group code, value) pairs, each on its own line; codes are written
//! right-aligned in three columns as AutoCAD does, lines end with `\n`.
//! - `HEADER`: `$ACADVER` = `AC1009`, `$INSUNITS` = 6 (metres), and `$EXTMIN`/`$EXTMAX` (the mesh
//!   bounds) when the mesh has vertices. `$INSUNITS` dates from R2000; R12 readers skip header
//!   variables they do not know, and ezdxf reads it from an R12 file (units = metres, clean audit),
//!   though its own R12 writer leaves it out. MSL reads DXF coordinates as metres either way.
//! - `TABLES`: an `LTYPE` table with `CONTINUOUS`, and a `LAYER` table with layer `0` and the
//!   shape's layer, coloured with the nearest AutoCAD Color Index ([`nearest_aci`]) to the CAD
//!   colour. R12 has no true colour (group 420 is R2004+).
//! - `ENTITIES`: one `3DFACE` per triangle, in mesh order, on the shape's layer with colour 256
//!   (BYLAYER), corners 10/20/30, 11/21/31, 12/22/32 and the third corner repeated as the fourth
//!   (13/23/33), as MSL and AutoCAD expect for triangles.
//! - `EOF`.
//!
//! Coordinates are the mesh's `f32` values (metres, body frame) in the shortest decimal form that
//! reads back to the same `f32` (Rust's `Display`: no exponent). Each vertex is formatted once and
//! its text reused by every face that shares it. A non-finite coordinate or a corner index out of
//! range (neither is allowed by the IR) is written as `0`.
//!
//! Layer names follow the R12 rule for table names: at most 31 characters from `A-Z a-z 0-9 _ - $`;
//! other characters become `_`, an empty name becomes `0`.

mod aci;

pub use aci::nearest_aci;

use crate::pipeline::ir;
use std::io::Write;

/// `name` as an R12 table name.
fn layer_name(name: &str) -> String {
    let s: String =
        name.chars().take(31).map(|c| if c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '$') { c } else { '_' }).collect();
    if s.is_empty() {
        "0".to_string()
    } else {
        s
    }
}

/// Appends a group: code right-aligned in three columns, then the value.
fn group(out: &mut Vec<u8>, code: u16, value: &str) {
    // Writing to a Vec cannot fail.
    let _ = writeln!(out, "{code:>3}\n{value}");
}

/// The shortest round-trip decimal of a finite `f32`, `0` otherwise.
fn number(out: &mut Vec<u8>, x: f32) {
    if x.is_finite() {
        crate::numtext::push_disp32(out, x);
    } else {
        out.push(b'0');
    }
}

fn point(out: &mut Vec<u8>, code: u16, p: [f32; 3]) {
    for (k, x) in p.into_iter().enumerate() {
        let _ = writeln!(out, "{:>3}", code + 10 * k as u16);
        number(out, x);
        out.push(b'\n');
    }
}

/// The mesh as an R12 DXF of `3DFACE`s on layer `layer` coloured like `color` (sRGB).
pub fn write(mesh: &ir::Mesh, color: [u8; 3], layer: &str) -> Vec<u8> {
    let layer = layer_name(layer);

    // Every vertex's coordinates as text, formatted once: `text[offs[3v + k]..offs[3v + k + 1]]`.
    let mut text = Vec::with_capacity(mesh.vertices.len() * 3 * 12);
    let mut offs = Vec::with_capacity(mesh.vertices.len() * 3 + 1);
    offs.push(0usize);
    for v in &mesh.vertices {
        for &x in v {
            number(&mut text, x);
            offs.push(text.len());
        }
    }
    let coord = |v: u32, k: usize| -> &[u8] {
        let i = v as usize * 3 + k;
        match (offs.get(i), offs.get(i + 1)) {
            (Some(&a), Some(&b)) => &text[a..b],
            _ => b"0",
        }
    };

    let mut face_head = Vec::new();
    group(&mut face_head, 0, "3DFACE");
    group(&mut face_head, 8, &layer);
    group(&mut face_head, 62, "256");
    const CODES: [[&[u8]; 3]; 4] =
        [[b" 10\n", b" 20\n", b" 30\n"], [b" 11\n", b" 21\n", b" 31\n"], [b" 12\n", b" 22\n", b" 32\n"], [b" 13\n", b" 23\n", b" 33\n"]];
    let avg_coord = text.len() / offs.len().max(1) + 1;
    let per_face = face_head.len() + 12 * (4 + avg_coord + 1);
    let mut out = Vec::with_capacity(1024 + per_face * mesh.triangles.len());

    group(&mut out, 0, "SECTION");
    group(&mut out, 2, "HEADER");
    group(&mut out, 9, "$ACADVER");
    group(&mut out, 1, "AC1009");
    group(&mut out, 9, "$INSUNITS");
    group(&mut out, 70, "6");
    if let Some((lo, hi)) = mesh.bounds() {
        group(&mut out, 9, "$EXTMIN");
        point(&mut out, 10, lo);
        group(&mut out, 9, "$EXTMAX");
        point(&mut out, 10, hi);
    }
    group(&mut out, 0, "ENDSEC");

    group(&mut out, 0, "SECTION");
    group(&mut out, 2, "TABLES");
    group(&mut out, 0, "TABLE");
    group(&mut out, 2, "LTYPE");
    group(&mut out, 70, "1");
    group(&mut out, 0, "LTYPE");
    group(&mut out, 2, "CONTINUOUS");
    group(&mut out, 70, "0");
    group(&mut out, 3, "Solid line");
    group(&mut out, 72, "65");
    group(&mut out, 73, "0");
    group(&mut out, 40, "0.0");
    group(&mut out, 0, "ENDTAB");
    group(&mut out, 0, "TABLE");
    group(&mut out, 2, "LAYER");
    let aci = nearest_aci(color).to_string();
    let layers: Vec<(&str, &str)> = if layer == "0" { vec![("0", &aci)] } else { vec![("0", "7"), (&layer, &aci)] };
    group(&mut out, 70, &layers.len().to_string());
    for (name, colour) in layers {
        group(&mut out, 0, "LAYER");
        group(&mut out, 2, name);
        group(&mut out, 70, "0");
        group(&mut out, 62, colour);
        group(&mut out, 6, "CONTINUOUS");
    }
    group(&mut out, 0, "ENDTAB");
    group(&mut out, 0, "ENDSEC");

    group(&mut out, 0, "SECTION");
    group(&mut out, 2, "ENTITIES");
    for t in &mesh.triangles {
        out.extend_from_slice(&face_head);
        for (c, codes) in CODES.iter().enumerate() {
            let v = t[c.min(2)];
            for (k, code) in codes.iter().enumerate() {
                out.extend_from_slice(code);
                out.extend_from_slice(coord(v, k));
                out.push(b'\n');
            }
        }
    }
    group(&mut out, 0, "ENDSEC");
    group(&mut out, 0, "EOF");
    out
}

#[cfg(test)]
mod tests;
