//! Unit tests of the mesh readers: test-only code, declared by the parent under `#[cfg(test)]`.

use super::*;
use crate::pipeline::front::simmechanics::dom::{Doc, NodeId};
use nalgebra::{Point3, Rotation3, Vector3};
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------- helpers

/// Signed volume enclosed by the triangles (positive when wound outward).
fn volume(m: &ir::Mesh) -> f64 {
    let p = |i: u32| {
        let v = m.vertices[i as usize];
        Vector3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))
    };
    m.triangles.iter().map(|t| p(t[0]).dot(&p(t[1]).cross(&p(t[2]))) / 6.0).sum()
}

/// Every directed edge appears once and its reverse once: closed and consistently wound.
fn assert_closed(m: &ir::Mesh) {
    let mut edges = std::collections::HashMap::new();
    for t in &m.triangles {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1, "edge {a}-{b} used {n} times in one direction");
        assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} has no opposite edge");
    }
}

fn bounds(m: &ir::Mesh) -> ([f64; 3], [f64; 3]) {
    let (lo, hi) = m.bounds().expect("mesh has vertices");
    (lo.map(f64::from), hi.map(f64::from))
}

fn assert_bounds(m: &ir::Mesh, lo: [f64; 3], hi: [f64; 3]) {
    let (l, h) = bounds(m);
    for k in 0..3 {
        assert!((l[k] - lo[k]).abs() < 1e-5 && (h[k] - hi[k]).abs() < 1e-5, "bounds {l:?}..{h:?}, expected {lo:?}..{hi:?}");
    }
}

fn kind(e: &MeshError) -> &MeshErrorKind {
    &e.kind
}

// ---------------------------------------------------------------- COLLADA documents of our own

/// A COLLADA document: `asset` inside `<asset>`, `geoms` inside `<library_geometries>`, `scene`
/// (the `<node>`s) inside a visual scene when given.
fn dae(asset: &str, geoms: &str, scene: Option<&str>) -> String {
    let scene = scene
        .map(|s| {
            format!(
                "<library_visual_scenes><visual_scene id=\"Scene\">{s}</visual_scene></library_visual_scenes>\n\
                 <scene><instance_visual_scene url=\"#Scene\"/></scene>"
            )
        })
        .unwrap_or_default();
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n\
         <COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n\
         <asset>{asset}</asset>\n<library_geometries>\n{geoms}\n</library_geometries>\n{scene}\n</COLLADA>\n"
    )
}

/// A box from the origin to `size` as a `<polylist>` of six quads (outward), with normals
/// interleaved at offset 1 when `normals`.
fn box_geometry(id: &str, size: [f64; 3], normals: bool) -> String {
    let mut pos = String::new();
    for k in 0..8 {
        let c = [k & 1, (k >> 1) & 1, (k >> 2) & 1];
        for j in 0..3 {
            pos += &format!("{} ", c[j] as f64 * size[j]);
        }
    }
    let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let mut p = String::new();
    for (f, q) in quads.iter().enumerate() {
        for i in q {
            p += &if normals { format!("{i} {f} ") } else { format!("{i} ") };
        }
    }
    let norm_src = if normals {
        format!(
            "<source id=\"{id}-n\"><float_array id=\"{id}-n-a\" count=\"18\">0 0 -1 0 0 1 0 -1 0 0 1 0 -1 0 0 1 0 0</float_array>\
             <technique_common><accessor source=\"#{id}-n-a\" count=\"6\" stride=\"3\"/></technique_common></source>"
        )
    } else {
        String::new()
    };
    let norm_in = if normals { format!("<input semantic=\"NORMAL\" source=\"#{id}-n\" offset=\"1\"/>") } else { String::new() };
    format!(
        "<geometry id=\"{id}\"><mesh>\n\
         <source id=\"{id}-p\"><float_array id=\"{id}-p-a\" count=\"24\">{pos}</float_array>\n\
         <technique_common><accessor source=\"#{id}-p-a\" count=\"8\" stride=\"3\">\
         <param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n\
         {norm_src}\n\
         <vertices id=\"{id}-v\"><input semantic=\"POSITION\" source=\"#{id}-p\"/></vertices>\n\
         <polylist count=\"6\" material=\"m\"><input semantic=\"VERTEX\" source=\"#{id}-v\" offset=\"0\"/>{norm_in}\n\
         <vcount>4 4 4 4 4 4</vcount>\n<p>{p}</p>\n</polylist>\n</mesh></geometry>"
    )
}

fn node(transforms: &str, url: &str) -> String {
    format!("<node id=\"n-{url}\">{transforms}<instance_geometry url=\"#{url}\"/></node>")
}

// ---------------------------------------------------------------- COLLADA

#[test]
fn dae_unit_and_y_up() {
    // A 1000 × 2000 × 3000 mm box in a Y_UP file: metres, and (x, y, z) -> (x, -z, y).
    let text = dae(
        "<unit name=\"millimeter\" meter=\"0.001\"/><up_axis>Y_UP</up_axis>",
        &box_geometry("b", [1000.0, 2000.0, 3000.0], true),
        Some(&node("", "b")),
    );
    let m = read("parts/box.DAE", text.as_bytes()).expect("reads");
    assert_eq!(m.triangles.len(), 12);
    assert_eq!(m.vertices.len(), 8);
    assert_bounds(&m, [0.0, -3.0, 0.0], [1.0, 0.0, 2.0]);
    assert!((volume(&m) - 6.0).abs() < 1e-4, "outward, 6 m³: {}", volume(&m));
    assert_closed(&m);
}

#[test]
fn dae_default_up_axis_is_y_and_unit_is_metre() {
    // No <unit>, no <up_axis>: metres, Y up (the specification's defaults).
    let text = dae("", &box_geometry("b", [1.0, 2.0, 3.0], false), Some(&node("", "b")));
    let m = read("box.dae", text.as_bytes()).expect("reads");
    assert_bounds(&m, [0.0, -3.0, 0.0], [1.0, 0.0, 2.0]);
    // Z_UP leaves the numbers; X_UP maps (x, y, z) -> (-y, -z, x).
    let z = dae("<up_axis>Z_UP</up_axis>", &box_geometry("b", [1.0, 2.0, 3.0], false), Some(&node("", "b")));
    assert_bounds(&read("box.dae", z.as_bytes()).expect("reads"), [0.0, 0.0, 0.0], [1.0, 2.0, 3.0]);
    let x = dae("<up_axis>X_UP</up_axis>", &box_geometry("b", [1.0, 2.0, 3.0], false), Some(&node("", "b")));
    let mx = read("box.dae", x.as_bytes()).expect("reads");
    assert_bounds(&mx, [-2.0, -3.0, 0.0], [0.0, 0.0, 1.0]);
    assert!(volume(&mx) > 5.99, "a rotation keeps the orientation");
    // read_with(false) ignores the up axis.
    let raw = collada::read_with("box.dae", text.as_bytes(), false).expect("reads");
    assert_bounds(&raw, [0.0, 0.0, 0.0], [1.0, 2.0, 3.0]);
}

/// What the `dae-parser` crate refuses (see `collada`'s docs) reads here: COLLADA 1.5, no
/// namespace, no `<created>`, unknown elements, a byte order mark.
#[test]
fn dae_tolerates_versions_and_unknown_elements() {
    let text = dae("<up_axis>Z_UP</up_axis>", &box_geometry("b", [1.0; 3], false), Some(&node("<foo_bar/>", "b")));
    let variants = [
        text.replace("2005/11/COLLADASchema\" version=\"1.4.1\"", "2008/03/COLLADASchema\" version=\"1.5.0\""),
        text.replace(" xmlns=\"http://www.collada.org/2005/11/COLLADASchema\"", ""),
        text.replace(
            "<library_geometries>",
            "<library_cameras><camera id=\"c\"/></library_cameras><extra_stuff a=\"1\"/><library_geometries>",
        ),
        format!("\u{feff}{text}"),
    ];
    for v in variants {
        let m = read("v.dae", v.as_bytes()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.triangles.len(), 12);
        assert_bounds(&m, [0.0; 3], [1.0; 3]);
    }
}

#[test]
fn dae_node_transforms_compose_in_document_order() {
    // Unit cube, scaled by 2, turned 90° about z, moved 10 along x: p' = T R S p.
    let s = node("<translate>10 0 0</translate><rotate>0 0 1 90</rotate><scale>2 2 2</scale>", "b");
    let text = dae("<up_axis>Z_UP</up_axis>", &box_geometry("b", [1.0; 3], false), Some(&s));
    let m = read("t.dae", text.as_bytes()).expect("reads");
    assert_bounds(&m, [8.0, 0.0, 0.0], [10.0, 2.0, 2.0]);
    // <matrix> is row-major: the translation is the last column. Nested nodes compose.
    let s = "<node><matrix>1 0 0 1  0 1 0 2  0 0 1 3  0 0 0 1</matrix>\
             <node><translate>0 0 10</translate><instance_geometry url=\"#b\"/></node></node>";
    let text = dae("<up_axis>Z_UP</up_axis>", &box_geometry("b", [1.0; 3], false), Some(s));
    assert_bounds(&read("t.dae", text.as_bytes()).expect("reads"), [1.0, 2.0, 13.0], [2.0, 3.0, 14.0]);
    // A mirroring scale keeps the triangles outward.
    let s = node("<scale>-1 1 1</scale>", "b");
    let text = dae("<up_axis>Z_UP</up_axis>", &box_geometry("b", [1.0; 3], false), Some(&s));
    let m = read("t.dae", text.as_bytes()).expect("reads");
    assert_bounds(&m, [-1.0, 0.0, 0.0], [0.0, 1.0, 1.0]);
    assert!((volume(&m) - 1.0).abs() < 1e-6, "mirrored but outward: {}", volume(&m));
}

#[test]
fn dae_instance_node_and_two_instances() {
    let geoms = box_geometry("b", [1.0; 3], false);
    let lib = "<library_nodes><node id=\"part\"><translate>0 0 5</translate><instance_geometry url=\"#b\"/></node></library_nodes>";
    let scene = "<node><instance_node url=\"#part\"/></node><node><translate>3 0 0</translate><instance_geometry url=\"#b\"/></node>";
    let text = dae("<up_axis>Z_UP</up_axis>", &geoms, Some(scene)).replace("<library_geometries>", &format!("{lib}<library_geometries>"));
    let m = read("t.dae", text.as_bytes()).expect("reads");
    assert_eq!(m.triangles.len(), 24);
    assert_bounds(&m, [0.0, 0.0, 0.0], [4.0, 1.0, 6.0]);
    // A cycle of instance_node is an error, not a hang.
    let lib = "<library_nodes><node id=\"a\"><instance_node url=\"#a\"/></node></library_nodes>";
    let text = dae("", &geoms, Some("<node><instance_node url=\"#a\"/></node>"))
        .replace("<library_geometries>", &format!("{lib}<library_geometries>"));
    let e = read("cycle.dae", text.as_bytes()).expect_err("cycle");
    assert!(e.to_string().contains("nested more than 64 deep"), "{e}");
    // Instancing that multiplies (ten of the next level, eight levels: 10^8 nodes) is refused
    // after 250,000 visits.
    let mut lib = String::from("<library_nodes>");
    for level in 0..8 {
        lib += &format!("<node id=\"l{level}\">{}</node>", format!("<instance_node url=\"#l{}\"/>", level + 1).repeat(10));
    }
    lib += "<node id=\"l8\"><instance_geometry url=\"#b\"/></node></library_nodes>";
    let text = dae("", &geoms, Some("<node><instance_node url=\"#l0\"/></node>"))
        .replace("<library_geometries>", &format!("{lib}<library_geometries>"));
    let e = read("bomb.dae", text.as_bytes()).expect_err("bomb");
    assert!(e.to_string().contains("more than 250000 node visits"), "{e}");
}

#[test]
fn dae_without_scene_uses_every_geometry() {
    let geoms = format!("{}{}", box_geometry("a", [1.0; 3], false), box_geometry("b", [2.0; 3], false));
    let m = read("t.dae", dae("<up_axis>Z_UP</up_axis>", &geoms, None).as_bytes()).expect("reads");
    assert_eq!(m.triangles.len(), 24);
    assert!((volume(&m) - 9.0).abs() < 1e-5);
}

/// A tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with the primitive element `prim`.
fn tetra(prim: &str) -> String {
    let g = format!(
        "<geometry id=\"t\"><mesh><source id=\"t-p\"><float_array id=\"t-a\" count=\"12\">0 0 0 1 0 0 0 1 0 0 0 1</float_array>\
         <technique_common><accessor source=\"#t-a\" count=\"4\" stride=\"3\"/></technique_common></source>\
         <vertices id=\"t-v\"><input semantic=\"POSITION\" source=\"#t-p\"/></vertices>\n{prim}\n</mesh></geometry>"
    );
    dae("<up_axis>Z_UP</up_axis>", &g, Some(&node("", "t")))
}

const V: &str = "<input semantic=\"VERTEX\" source=\"#t-v\" offset=\"0\"/>";

#[test]
fn dae_primitive_kinds() {
    // Outward tetrahedron faces: 0 2 1, 0 1 3, 0 3 2, 1 2 3. Volume 1/6.
    let cases = [
        format!("<triangles count=\"4\">{V}<p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>"),
        // Interleaved: a TEXCOORD at offset 1 (values ignored).
        format!(
            "<triangles count=\"4\">{V}<input semantic=\"TEXCOORD\" source=\"#t-p\" offset=\"1\" set=\"0\"/>\
             <p>0 9 2 9 1 9 0 9 1 9 3 9 0 9 3 9 2 9 1 9 2 9 3 9</p></triangles>"
        ),
        format!("<polygons count=\"4\">{V}<p>0 2 1</p><p>0 1 3</p><ph><p>0 3 2</p><h>0 0 0</h></ph><p>1 2 3</p></polygons>"),
        format!("<trifans count=\"2\">{V}<p>0 2 1 3 2</p><p>1 2 3</p></trifans>"),
        // The strip 1 0 2 3 1 is (1 0 2), (2 0 3) (second triangle reversed), (2 3 1).
        format!("<tristrips count=\"2\">{V}<p>1 0 2 3 1</p><p>0 1 3</p></tristrips>"),
        format!("<polylist count=\"4\">{V}<vcount>3 3 3 3</vcount><p>0 2 1 0 1 3 0 3 2 1 2 3</p></polylist>"),
    ];
    for (k, prim) in cases.iter().enumerate() {
        let m = read("t.dae", tetra(prim).as_bytes()).unwrap_or_else(|e| panic!("case {k}: {e}"));
        assert_eq!(m.triangles.len(), 4, "case {k}");
        assert!((volume(&m) - 1.0 / 6.0).abs() < 1e-6, "case {k}: volume {}", volume(&m));
        assert_closed(&m);
    }
}

#[test]
fn dae_errors_name_file_line_and_problem() {
    let cases: Vec<(String, &str)> = vec![
        // Index 7 of a 4-point source (the <p> is on line 6 of the document).
        (
            tetra(&format!("<triangles count=\"4\">{V}<p>0 2 1 0 1 7 0 3 2 1 2 3</p></triangles>")),
            "t.dae:6: COLLADA: <p> index 7 is out of range: the position source has 4 points",
        ),
        (tetra(&format!("<triangles count=\"1\">{V}<p>0 2 1 0</p></triangles>")), "not a multiple of 3"),
        (
            tetra(&format!("<polylist count=\"1\">{V}<vcount>4</vcount><p>0 2 1</p></polylist>")),
            "<vcount> adds up to 4 corners but <p> has 3",
        ),
        (tetra(&format!("<polylist count=\"1\">{V}<p>0 2 1</p></polylist>")), "<polylist> has no <vcount>"),
        (tetra(&format!("<triangles count=\"1\">{V}<p>0 x 1</p></triangles>")), "bad index \"x\""),
        (tetra(&format!("<triangles count=\"1\">{V}<p>0 -1 1</p></triangles>")), "bad index \"-1\""),
        (tetra("<triangles count=\"1\"><p>0 1 2</p></triangles>"), "<triangles> has no VERTEX input"),
        (
            tetra(&format!("<triangles count=\"1\">{}<p>0 1 2</p></triangles>", V.replace("#t-v", "#nowhere"))),
            "no element has id \"nowhere\"",
        ),
        (
            tetra(&format!("<triangles count=\"1\">{}<p>0 1 2</p></triangles>", V.replace("#t-v", "other.dae#t-v"))),
            "other files are not read",
        ),
        (
            tetra(&format!("<triangles>{V}<p>0 2 3</p></triangles>")).replace("0 0 1</float_array>", "0 0 nan</float_array>"),
            "t.dae: vertex 3 is not finite",
        ),
        (tetra(&format!("<triangles>{V}<p>0 2 3</p></triangles>")).replace("0 0 1</float_array>", "0 0 1e999</float_array>"), "not finite"),
        (
            tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>")).replace("0 0 1</float_array>", "0 0 1,5</float_array>"),
            "bad number \"1,5\" in <float_array>",
        ),
        (
            tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>")).replace("count=\"4\" stride", "count=\"5\" stride"),
            "reads past its <float_array>",
        ),
        (tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>")).replace("stride=\"3\"", "stride=\"2\""), "stride 2"),
        (
            tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>")).replace("<up_axis>Z_UP", "<unit meter=\"-1\"/><up_axis>Z_UP"),
            "<unit meter=\"-1\"> is not a positive number",
        ),
        (tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>")).replace("Z_UP", "W_UP"), "<up_axis> \"W_UP\" is not X_UP"),
        (
            tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>"))
                .replace("<node id=\"n-t\">", "<node id=\"n-t\"><lookat>0 0 0 1 0 0 0 0 1</lookat>"),
            "<lookat> node transforms are not supported",
        ),
        (
            tetra(&format!("<triangles>{V}<p>0 2 1</p></triangles>"))
                .replace("<node id=\"n-t\">", "<node id=\"n-t\"><matrix>1 0 0</matrix>"),
            "<matrix> needs 16 numbers, found 3",
        ),
        (tetra(&format!("<triangles>{V}<p></p></triangles>")), "t.dae: no triangles in the file"),
        ("<COLLADA><asset></asset><library_geometries>".to_string(), "t.dae:1: XML: unexpected end of file"),
        ("<html><body/></html>".to_string(), "the root element is <html>, not <COLLADA>"),
        ("\u{0}\u{1}garbage\u{ff}".to_string(), "t.dae:1: XML"),
        (String::new(), "t.dae:1: XML"),
    ];
    for (text, want) in cases {
        let e = read("t.dae", text.as_bytes()).expect_err(want);
        assert!(e.to_string().contains(want), "want {want:?}, got {e}");
    }
    // The line points at the bad element.
    let text = tetra(&format!("<triangles count=\"1\">{V}\n\n<p>0 2 9</p></triangles>"));
    let e = read("t.dae", text.as_bytes()).expect_err("index");
    assert_eq!(e.line, 8, "{e}");
    assert!(matches!(kind(&e), MeshErrorKind::Collada(_)));
}

#[test]
fn dae_truncated_or_mutated_never_panics() {
    let text = dae(
        "<unit meter=\"0.001\"/><up_axis>Y_UP</up_axis>",
        &box_geometry("b", [1.0, 2.0, 3.0], true),
        Some(&node("<rotate>1 0 0 30</rotate>", "b")),
    );
    let bytes = text.as_bytes();
    for cut in 0..bytes.len() {
        let _ = read("t.dae", &bytes[..cut]);
    }
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for _ in 0..3000 {
        let mut b = bytes.to_vec();
        for _ in 0..3 {
            let k = (rnd() % b.len() as u64) as usize;
            b[k] = b"0123456789 -.e<>/\"#x"[(rnd() % 20) as usize];
        }
        if let Ok(m) = read("t.dae", &b) {
            assert!(m.vertices.iter().flatten().all(|x| x.is_finite()));
            assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.vertices.len()));
        }
    }
    // Deep nesting is refused, not a stack overflow.
    let deep = format!("<COLLADA>{}{}</COLLADA>", "<node>".repeat(100_000), "</node>".repeat(100_000));
    assert!(read("deep.dae", deep.as_bytes()).is_err());
}

// ---------------------------------------------------------------- OBJ

#[test]
fn obj_quad_objects_and_negative_indices() {
    let text = "# a unit square and a triangle\nmtllib x.mtl\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n\
                f 1//1 2//1 3//1 4//1\no tri\nv 0 0 5\nv 1 0 5\nv 0 1 5\nf -3 -2 -1\nl 1 2\n";
    let m = read("m/Shape.OBJ", text.as_bytes()).expect("reads");
    assert_eq!(m.triangles.len(), 3, "the quad is two triangles, the objects are appended");
    assert_bounds(&m, [0.0, 0.0, 0.0], [1.0, 1.0, 5.0]);
    // Orientation kept: both faces wind counter-clockwise about +z.
    for t in &m.triangles {
        let p = t.map(|i| Vector3::from(m.vertices[i as usize].map(f64::from)));
        assert!((p[1] - p[0]).cross(&(p[2] - p[0])).z > 0.0);
    }
}

#[test]
fn obj_errors() {
    let cases = [
        ("v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n", "t.obj:3: OBJ: bad vertex record"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n", "t.obj:4: OBJ: bad face record"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "t.obj: OBJ: a face refers to a vertex that does not exist"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n", "t.obj: vertex 3 is not finite"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "t.obj: no triangles in the file"),
        ("", "no triangles"),
    ];
    for (text, want) in cases {
        let e = read("t.obj", text.as_bytes()).expect_err(want);
        assert!(e.to_string().contains(want), "want {want:?}, got {e}");
    }
    // Invalid UTF-8 and random bytes: errors, never panics.
    let e = read("t.obj", b"v 0 0 0\nv \xff\xfe 1 0\n").expect_err("utf8");
    assert_eq!(e.line, 2, "{e}");
    let text = "o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf -1 -2 -3\n";
    for cut in 0..text.len() {
        let _ = read("t.obj", &text.as_bytes()[..cut]);
    }
    let mut seed = 12345u64;
    for _ in 0..3000 {
        let mut b = text.as_bytes().to_vec();
        for _ in 0..3 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let k = (seed % b.len() as u64) as usize;
            b[k] = b"0123456789 -./\nfv#"[(seed >> 32) as usize % 18];
        }
        if let Ok(m) = read("t.obj", &b) {
            assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.vertices.len()));
        }
    }
}

// ---------------------------------------------------------------- dispatch, STL

#[test]
fn dispatch_by_extension() {
    let stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
    assert_eq!(read("a/b.STL", stl.as_bytes()).expect("stl").triangles.len(), 1);
    let e = read("a/b.stl", b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n").expect_err("bad stl");
    assert!(e.to_string().starts_with("a/b.stl:5: expected a number"), "{e}");
    for name in ["x.ply", "x", "x.", "dir.obj/x.3ds"] {
        let e = read(name, b"").expect_err("unsupported");
        assert!(e.to_string().contains("supported are .stl, .obj, .dae (COLLADA) and .step/.stp"), "{e}");
    }
    assert!(read("x.ply", b"").expect_err("").to_string().contains("\".ply\""));
}

// ---------------------------------------------------------------- primitives, scale

#[test]
fn primitives_are_closed_outward_and_of_the_right_volume() {
    let b = box_mesh([0.1, 0.2, 0.3]);
    assert_closed(&b);
    assert_bounds(&b, [-0.05, -0.1, -0.15], [0.05, 0.1, 0.15]);
    assert!((volume(&b) - 0.006).abs() < 1e-9, "{}", volume(&b));

    let (r, l) = (0.05, 0.4);
    let c = cylinder_mesh(r, l);
    assert_closed(&c);
    assert_eq!(c.triangles.len(), 4 * CYLINDER_SEGMENTS);
    assert_bounds(&c, [-r, -r, -l / 2.0], [r, r, l / 2.0]);
    let n = CYLINDER_SEGMENTS as f64;
    let polygon = n / 2.0 * r * r * (2.0 * std::f64::consts::PI / n).sin() * l;
    assert!((volume(&c) - polygon).abs() < 1e-6 * polygon, "{} vs {polygon}", volume(&c));
    assert!((volume(&c) / (std::f64::consts::PI * r * r * l) - 1.0).abs() < 0.01);

    let r = 0.3;
    let s = sphere_mesh(r);
    assert_closed(&s);
    assert_bounds(&s, [-r, -r, -r], [r, r, r]);
    let exact = 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
    assert!(volume(&s) > 0.95 * exact && volume(&s) < exact, "{} vs {exact}", volume(&s));
}

#[test]
fn scaled_is_componentwise_and_keeps_outward_winding() {
    let b = box_mesh([1.0, 1.0, 1.0]);
    let s = scaled("b.obj", &b, [0.2, 0.4, 0.05]).expect("finite");
    assert_bounds(&s, [-0.1, -0.2, -0.025], [0.1, 0.2, 0.025]);
    assert!((volume(&s) - 0.004).abs() < 1e-9);
    let m = scaled("b.obj", &b, [-1.0, 1.0, 2.0]).expect("finite");
    assert!((volume(&m) - 2.0).abs() < 1e-9, "mirrored, still outward: {}", volume(&m));
    let e = scaled("b.obj", &b, [f64::NAN, 1.0, 1.0]).expect_err("nan");
    assert_eq!(e.to_string(), "b.obj: vertex 1 is not finite (NaN or infinite coordinate, in the file or after scaling)");
}

// ---------------------------------------------------------------- fixtures

fn urdf_fixtures() -> Option<PathBuf> {
    crate::pipeline::testutil::fixtures_dir().map(|d| d.join("urdf")).filter(|d| d.is_dir())
}

/// Every mesh under `fixtures/urdf` reads: triangles, finite, smaller than 2 m (2.5 m: the
/// quadruped's `cylinder.obj` is a unit shape 2 m tall that its URDF scales down).
#[test]
fn fixture_meshes_read() {
    let Some(dir) = urdf_fixtures() else { return };
    let mut files = Vec::new();
    for ext in ["dae", "obj", "stl"] {
        files.extend(crate::pipeline::testutil::files_with_ext(&dir, ext));
    }
    assert!(files.len() >= 130, "{} mesh files", files.len());
    let mut solid_headers = 0;
    for f in &files {
        let bytes = std::fs::read(f).expect("read fixture");
        // Binary STLs whose header begins with "solid" (Solo12, Robotiq) read as binary: all the
        // triangles the header declares.
        if bytes.starts_with(b"solid") && crate::pipeline::front::stl::is_binary(&bytes) {
            solid_headers += 1;
            let declared = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
            let m = read(&f.to_string_lossy(), &bytes).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(m.triangles.len(), declared, "{}", f.display());
        }
        let name = f.strip_prefix(&dir).unwrap_or(f).to_string_lossy().into_owned();
        let m = read(&name, &bytes).unwrap_or_else(|e| panic!("{e}"));
        assert!(!m.triangles.is_empty(), "{name}");
        let (lo, hi) = bounds(&m);
        let extent = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
        assert!(extent > 1e-3 && extent < 2.5, "{name}: extent {extent} m");
    }
    assert!(solid_headers >= 5, "{solid_headers} binary STLs with a solid header");
}

/// URDF `xyz`/`rpy` attributes of an `<origin>` child as a transform (identity when absent).
fn origin(doc: &Doc, el: NodeId) -> nalgebra::Isometry3<f64> {
    let nums = |key: &[u8]| -> [f64; 3] {
        let v: Vec<f64> = doc
            .child(el, b"origin")
            .and_then(|o| doc.attr(o, key).ok().flatten())
            .map(|s| String::from_utf8_lossy(s).split_whitespace().map(|t| t.parse().expect("number")).collect())
            .unwrap_or_else(|| vec![0.0; 3]);
        [v[0], v[1], v[2]]
    };
    let (xyz, rpy) = (nums(b"xyz"), nums(b"rpy"));
    nalgebra::Isometry3::from_parts(
        nalgebra::Translation3::new(xyz[0], xyz[1], xyz[2]),
        Rotation3::from_euler_angles(rpy[0], rpy[1], rpy[2]).into(),
    )
}

/// For each link of `urdf` with a `.dae` visual: (name, is its centre of mass inside the visual
/// mesh's box in the link frame, distance from the centre of mass to the box centre), reading
/// the meshes with or without the up-axis turn.
fn com_in_parts(urdf: &Path, root: &Path, apply_up_axis: bool) -> Vec<(String, bool, f64)> {
    let bytes = std::fs::read(urdf).expect("urdf");
    let doc = Doc::build(&bytes).unwrap_or_else(|_| panic!("parse {}", urdf.display()));
    let mut out = Vec::new();
    for link in doc.children(doc.root()).filter(|&c| doc.name(c) == b"link") {
        let (Some(vis), Some(inertial)) = (doc.child(link, b"visual"), doc.child(link, b"inertial")) else { continue };
        let Some(file) = doc.descend(vis, &[b"geometry", b"mesh"]).and_then(|m| doc.attr(m, b"filename").ok().flatten()) else {
            continue;
        };
        let file = String::from_utf8_lossy(file);
        let Some(rel) = file.strip_prefix("package://example-robot-data/") else { continue };
        if !rel.ends_with(".dae") {
            continue;
        }
        let mesh = collada::read_with(rel, &std::fs::read(root.join(rel)).expect("mesh"), apply_up_axis).expect("dae");
        let place = origin(&doc, vis);
        let pts: Vec<Point3<f64>> =
            mesh.vertices.iter().map(|v| place * Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))).collect();
        let lo = pts.iter().fold(Point3::from([f64::MAX; 3]), |a, p| a.inf(p));
        let hi = pts.iter().fold(Point3::from([f64::MIN; 3]), |a, p| a.sup(p));
        let com = origin(&doc, inertial).translation.vector;
        let inside = (0..3).all(|k| com[k] >= lo[k] - 1e-4 && com[k] <= hi[k] + 1e-4);
        let name = String::from_utf8_lossy(doc.attr(link, b"name").ok().flatten().unwrap_or_default()).into_owned();
        out.push((name, inside, (com - nalgebra::center(&lo, &hi).coords).norm()));
    }
    out
}

/// The evidence of `collada`'s module docs: iCub's Y_UP meshes contain their links' centres of
/// mass only when turned to Z up.
#[test]
fn up_axis_evidence_icub() {
    let Some(dir) = urdf_fixtures() else { return };
    let root = dir.join("Gepetto+example-robot-data/39aa9437");
    let urdf = root.join("robots/icub_description/robots/icub.urdf");
    let turned = com_in_parts(&urdf, &root, true);
    let raw = com_in_parts(&urdf, &root, false);
    assert!(turned.len() >= 20, "{} iCub links with meshes", turned.len());
    let decisive =
        ["chest", "l_upper_arm", "l_forearm", "l_upper_leg", "l_lower_leg", "r_upper_arm", "r_forearm", "r_upper_leg", "r_lower_leg"];
    for name in decisive {
        let t = turned.iter().find(|l| l.0 == name).expect("link");
        let r = raw.iter().find(|l| l.0 == name).expect("link");
        assert!(t.1 && !r.1, "{name}: inside turned {} ({:.3} m), unturned {} ({:.3} m)", t.1, t.2, r.1, r.2);
        assert!(t.2 < 0.05 && r.2 > 0.09, "{name}: {:.3} m turned vs {:.3} m unturned", t.2, r.2);
    }
    // Over all links, turning never loses a centre of mass the unturned reading had inside
    // (except r_shoulder_1, a placeholder disc that contains its centre of mass either way not).
    let inside = |v: &[(String, bool, f64)]| v.iter().filter(|l| l.1).count();
    assert!(inside(&turned) >= inside(&raw) + 9, "{} vs {}", inside(&turned), inside(&raw));
}

/// UR5 (Z_UP, unit 1 m, node matrices): each link's visual COLLADA part has the box of its
/// collision STL (an independent file of the same part, in the same link frame) to 5 mm. (UR5's
/// inertials are nominal, centres of mass at the joints, so they cannot serve here.)
#[test]
fn ur5_visual_parts_match_their_collision_stls() {
    let Some(dir) = urdf_fixtures() else { return };
    let meshes = dir.join("Gepetto+example-robot-data/39aa9437/robots/ur_description/meshes/ur5");
    for part in ["base", "shoulder", "upperarm", "forearm", "wrist1", "wrist2", "wrist3"] {
        let read_at = |rel: String| {
            let bytes = std::fs::read(meshes.join(&rel)).expect("fixture");
            bounds(&read(&rel, &bytes).unwrap_or_else(|e| panic!("{e}")))
        };
        let (vlo, vhi) = read_at(format!("visual/{part}.dae"));
        let (clo, chi) = read_at(format!("collision/{part}.stl"));
        for k in 0..3 {
            assert!(
                (vlo[k] - clo[k]).abs() < 0.005 && (vhi[k] - chi[k]).abs() < 0.005,
                "{part}: visual {vlo:?}..{vhi:?}, collision {clo:?}..{chi:?}"
            );
        }
    }
}

/// Release timing of the biggest COLLADA fixture (run with `--release -- --ignored --nocapture`).
#[test]
#[ignore]
fn time_biggest_dae() {
    let Some(dir) = urdf_fixtures() else { return };
    let f = dir.join("Gepetto+example-robot-data/39aa9437/robots/ur_description/meshes/ur5/visual/upperarm.dae");
    let bytes = std::fs::read(&f).expect("fixture");
    let n = 20;
    let t = std::time::Instant::now();
    let mut tris = 0;
    for _ in 0..n {
        tris = read("upperarm.dae", &bytes).expect("reads").triangles.len();
    }
    println!("upperarm.dae ({} bytes, {tris} triangles): {:.2} ms per read", bytes.len(), t.elapsed().as_secs_f64() * 1e3 / n as f64);
}

/// A longer in-process mutation run over the fixture COLLADA files (small ones), for when the
/// libFuzzer target cannot be built: `cargo test -p cad2mo --lib soak -- --ignored`.
#[test]
#[ignore]
fn soak_mutated_fixture_daes() {
    let Some(dir) = urdf_fixtures() else { return };
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let alphabet = b"0123456789 -.e<>/\"#=xpn\n";
    let mut runs = 0;
    for f in crate::pipeline::testutil::files_with_ext(&dir, "dae") {
        let bytes = std::fs::read(&f).expect("fixture");
        if bytes.len() > 300_000 {
            continue;
        }
        for _ in 0..300 {
            let mut b = bytes.clone();
            for _ in 0..1 + rnd() % 4 {
                let k = (rnd() % b.len() as u64) as usize;
                match rnd() % 3 {
                    0 => b[k] = alphabet[(rnd() % alphabet.len() as u64) as usize],
                    1 => {
                        let l = ((rnd() % 64) as usize).min(b.len() - k);
                        b.drain(k..k + l);
                    }
                    _ => {
                        let l = ((rnd() % 64) as usize).min(b.len() - k);
                        let chunk = b[k..k + l].to_vec();
                        b.splice(k..k, chunk);
                    }
                }
                if b.is_empty() {
                    break;
                }
            }
            let r = std::panic::catch_unwind(|| read("soak.dae", &b));
            match r {
                Err(_) => {
                    std::fs::write("/tmp/mesh-soak-panic.dae", &b).expect("write");
                    panic!("panic on a mutation of {} (saved to /tmp/mesh-soak-panic.dae)", f.display());
                }
                Ok(Ok(m)) => {
                    assert!(m.vertices.iter().flatten().all(|x| x.is_finite()));
                    assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.vertices.len()));
                }
                Ok(Err(e)) => {
                    let _ = e.to_string();
                }
            }
            runs += 1;
            if b.is_empty() {
                break;
            }
        }
    }
    println!("soak: {runs} mutated files read without a panic");
}

// ---------------------------------------------------------------- STEP

/// A hand-written AP214 B-rep tetrahedron (four planes, six lines, one closed shell; the same
/// construction as fuzz/make_seeds.py's seed): edges `len` long along the axes from the origin,
/// in the length unit `unit` (the complex entity's unit part, e.g. `SI_UNIT(.MILLI.,.METRE.)`),
/// followed by `extra` entities.
fn tetra_step(unit: &str, len: f64, extra: &str) -> String {
    let mut ents: Vec<String> = Vec::new();
    let mut add = |e: String| {
        ents.push(e);
        format!("#{}", ents.len())
    };
    let pts = [[0.0, 0.0, 0.0], [len, 0.0, 0.0], [0.0, len, 0.0], [0.0, 0.0, len]];
    let cp: Vec<String> = pts.iter().map(|p| add(format!("CARTESIAN_POINT('',({:?},{:?},{:?}))", p[0], p[1], p[2]))).collect();
    let vp: Vec<String> = cp.iter().map(|c| add(format!("VERTEX_POINT('',{c})"))).collect();
    let mut edges = std::collections::HashMap::new();
    for i in 0..4 {
        for j in i + 1..4 {
            let d = Vector3::from(pts[j]) - Vector3::from(pts[i]);
            let n = d.norm();
            let dir = add(format!("DIRECTION('',({:?},{:?},{:?}))", d.x / n, d.y / n, d.z / n));
            let vec = add(format!("VECTOR('',{dir},{n:?})"));
            let line = add(format!("LINE('',{},{vec})", cp[i]));
            edges.insert((i, j), add(format!("EDGE_CURVE('',{},{},{line},.T.)", vp[i], vp[j])));
        }
    }
    let mut faces = Vec::new();
    for [a, b, c] in [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] {
        let oes: Vec<String> = [(a, b), (b, c), (c, a)]
            .iter()
            .map(|&(i, j)| add(format!("ORIENTED_EDGE('',*,*,{},{})", edges[&(i.min(j), i.max(j))], if i < j { ".T." } else { ".F." })))
            .collect();
        let lp = add(format!("EDGE_LOOP('',({}))", oes.join(",")));
        let bound = add(format!("FACE_OUTER_BOUND('',{lp},.T.)"));
        let u = Vector3::from(pts[b]) - Vector3::from(pts[a]);
        let n = u.cross(&(Vector3::from(pts[c]) - Vector3::from(pts[a]))).normalize();
        let u = u.normalize();
        let nd = add(format!("DIRECTION('',({:?},{:?},{:?}))", n.x, n.y, n.z));
        let rd = add(format!("DIRECTION('',({:?},{:?},{:?}))", u.x, u.y, u.z));
        let ax = add(format!("AXIS2_PLACEMENT_3D('',{},{nd},{rd})", cp[a]));
        let plane = add(format!("PLANE('',{ax})"));
        faces.push(add(format!("ADVANCED_FACE('',({bound}),{plane},.T.)")));
    }
    let shell = add(format!("CLOSED_SHELL('',({}))", faces.join(",")));
    let solid = add(format!("MANIFOLD_SOLID_BREP('tetra',{shell})"));
    let lu = add(format!("( LENGTH_UNIT() NAMED_UNIT(*) {unit} )"));
    let au = add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )".into());
    let ctx =
        add(format!("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT(({lu},{au})) REPRESENTATION_CONTEXT('','') )"));
    add(format!("ADVANCED_BREP_SHAPE_REPRESENTATION('',({solid}),{ctx})"));
    let body: Vec<String> = ents.iter().enumerate().map(|(k, e)| format!("#{}={e};", k + 1)).collect();
    format!(
        "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('t','',(''),(''),'','','');\nFILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n{}\n{extra}ENDSEC;\nEND-ISO-10303-21;\n",
        body.join("\n")
    )
}

/// Volume and centroid of a whole mesh.
fn volume_centroid(m: &ir::Mesh) -> (f64, Vector3<f64>) {
    let p = |i: u32| {
        let v = m.vertices[i as usize];
        Vector3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))
    };
    let mut vol = 0.0;
    let mut c = Vector3::zeros();
    for t in &m.triangles {
        let v6 = p(t[0]).dot(&p(t[1]).cross(&p(t[2])));
        vol += v6 / 6.0;
        c += (p(t[0]) + p(t[1]) + p(t[2])) * (v6 / 24.0);
    }
    (vol, c / vol)
}

#[test]
fn step_tetrahedron_in_millimetres() {
    let text = tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, "");
    let m = step::read("t.step", text.as_bytes()).expect("tetra");
    assert_eq!((m.faces, m.failed_faces, m.solids.len()), (4, 0, 1), "{:?}", m.warnings);
    let (v, c) = volume_centroid(&m.mesh);
    // 10 mm edges: 1000/6 mm^3, outward wound (positive); centroid at a quarter of the edges.
    assert!((v - 1e-6 / 6.0).abs() < 1e-12, "{v}");
    assert!((c - Vector3::repeat(0.0025)).norm() < 1e-9, "{c}");
    // Through the extension dispatch too.
    let mesh = read("parts/T.STEP", text.as_bytes()).expect("by extension");
    assert_eq!(mesh.triangles.len(), m.mesh.triangles.len());
    // The faces are joined: every edge is shared by exactly two triangles, in opposite
    // directions (a closed, consistently wound mesh), and the four corners are four vertices.
    let mut edges: std::collections::HashMap<(u32, u32), i32> = std::collections::HashMap::new();
    for t in &m.mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_default() += if a < b { 1 } else { -1 };
        }
    }
    let uses = |e: &(u32, u32)| {
        m.mesh.triangles.iter().filter(|t| (0..3).any(|k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])) == *e)).count()
    };
    assert!(edges.iter().all(|(e, d)| *d == 0 && uses(e) == 2), "open edges: {edges:?}");
    assert_eq!(m.mesh.vertices.len(), 4, "{:?}", m.mesh.vertices);
}

#[test]
fn step_conversion_based_inch_unit() {
    let extra =
        "#999=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#998);\n#998=( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n";
    let text = tetra_step("CONVERSION_BASED_UNIT('INCH',#999)", 1.0, extra);
    let m = step::read("t.step", text.as_bytes()).expect("tetra in inches");
    let (v, _) = volume_centroid(&m.mesh);
    assert!((v - 0.0254f64.powi(3) / 6.0).abs() < 1e-12, "{v}");
    // A unit defined through itself, and a unit we do not know: errors naming the unit.
    let cyc = text.replace("LENGTH_MEASURE(25.4),#998", "LENGTH_MEASURE(25.4),#999");
    let e = step::read("t.step", cyc.as_bytes()).expect_err("cycle");
    assert!(e.to_string().starts_with("t.step: STEP: length unit #"), "{e}");
    let fathom = tetra_step("SI_UNIT(.FATHOM.,.METRE.)", 1.0, "");
    let e = step::read("t.step", fathom.as_bytes()).expect_err("unknown prefix");
    assert!(e.to_string().contains("is not one we know"), "{e}");
}

#[test]
fn step_mapped_item_places_the_solid() {
    // The tetrahedron's representation mapped into a second one, turned 90 degrees about z and
    // moved 100 mm along x (the origin of the map at the tetrahedron's origin).
    let extra = "#900=CARTESIAN_POINT('',(0.0,0.0,0.0));\n#901=AXIS2_PLACEMENT_3D('',#900,$,$);\n\
                 #902=CARTESIAN_POINT('',(100.0,0.0,0.0));\n#903=DIRECTION('',(0.0,0.0,1.0));\n#904=DIRECTION('',(0.0,1.0,0.0));\n\
                 #905=AXIS2_PLACEMENT_3D('',#902,#903,#904);\n#906=REPRESENTATION_MAP(#901,#REP);\n#907=MAPPED_ITEM('',#906,#905);\n\
                 #908=SHAPE_REPRESENTATION('',(#907),#CTX);\n";
    let base = tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, "");
    let n = base.matches('=').count();
    // The representation is the last entity, the context the one before it.
    let text =
        tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, &extra.replace("#REP", &format!("#{n}")).replace("#CTX", &format!("#{}", n - 1)));
    let m = step::read("t.step", text.as_bytes()).expect("mapped");
    assert_eq!(m.solids.len(), 1, "one placement: the mapped one (the tetrahedron's own representation is not a root)");
    let (v, c) = volume_centroid(&m.mesh);
    assert!((v - 1e-6 / 6.0).abs() < 1e-12, "{v}");
    // (2.5, 2.5, 2.5) mm turned +90 degrees about z is (-2.5, 2.5, 2.5), then +100 mm in x.
    assert!((c - Vector3::new(0.0975, 0.0025, 0.0025)).norm() < 1e-7, "{c}");
}

#[test]
fn step_limits_and_garbage_are_errors_naming_the_file() {
    let e = step::read("a/b.stp", b"solid x\nendsolid").expect_err("not STEP");
    assert!(e.to_string().starts_with("a/b.stp: STEP: not an ISO 10303-21 file"), "{e}");
    let text = tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, "");
    for cut in [text.len() / 3, text.len() / 2, text.len() - 20] {
        let e = step::read("a/b.stp", &text.as_bytes()[..cut]).expect_err("truncated");
        assert!(e.to_string().starts_with("a/b.stp: STEP: "), "{e}");
    }
    let e = step::read_with("a/b.stp", text.as_bytes(), std::time::Duration::ZERO).expect_err("time");
    assert!(e.to_string().contains("meshing took longer than the limit of 0 s"), "{e}");
    // A face whose surface is of a type the reader does not know: a warning naming the face
    // and its solid, the other three faces kept.
    let broken = text.replacen("PLANE('',", "PLANEX('',", 1);
    let m = step::read("a/b.stp", broken.as_bytes()).expect("three faces");
    assert_eq!((m.faces, m.failed_faces), (4, 1), "{:?}", m.warnings);
    assert_eq!(m.warnings.len(), 1, "{:?}", m.warnings);
    assert!(
        m.warnings[0].starts_with("a/b.stp: face #") && m.warnings[0].contains("PLANEX") && m.warnings[0].contains("MANIFOLD_SOLID_BREP #"),
        "{}",
        m.warnings[0]
    );
    assert!(!m.mesh.triangles.is_empty());
}

/// The entity id of the `k`-th entity named `name` in a STEP text (`#n=NAME(`).
fn entity_id(text: &str, name: &str, k: usize) -> u64 {
    let ids: Vec<u64> = text
        .lines()
        .filter_map(|l| {
            let (id, rest) = l.strip_prefix('#')?.split_once('=')?;
            rest.starts_with(&format!("{name}(")).then(|| id.parse().ok()).flatten()
        })
        .collect();
    ids[k]
}

/// A surface style chain from entity `#n` on: `#n+6` is the `PRESENTATION_STYLE_ASSIGNMENT` of
/// colour entity `colour` (written as `#n`).
fn surface_style(n: u64, colour: &str) -> String {
    format!(
        "#{n}={colour};\n#{}=FILL_AREA_STYLE_COLOUR('',#{n});\n#{}=FILL_AREA_STYLE('',(#{}));\n#{}=SURFACE_STYLE_FILL_AREA(#{});\n\
         #{}=SURFACE_SIDE_STYLE('',(#{}));\n#{}=SURFACE_STYLE_USAGE(.BOTH.,#{});\n#{}=PRESENTATION_STYLE_ASSIGNMENT((#{}));\n",
        n + 1,
        n + 2,
        n + 1,
        n + 3,
        n + 2,
        n + 4,
        n + 3,
        n + 5,
        n + 4,
        n + 6,
        n + 5
    )
}

/// The tetrahedron with its solid (or shell) styled `COLOUR_RGB(0.2, 0.4, 0.6)`, the faces of
/// `red` (indices in file order) over-ridden with the predefined colour red, and face 0 given an
/// edge colour (a curve style: not a surface colour).
fn coloured_tetra(on: &str, red: &[usize]) -> String {
    let plain = tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, "");
    let target = entity_id(&plain, on, 0);
    let mut extra = surface_style(900, "COLOUR_RGB('',0.2,0.4,0.6)");
    extra += &format!("#907=STYLED_ITEM('',(#906),#{target});\n");
    extra += &surface_style(910, "DRAUGHTING_PRE_DEFINED_COLOUR('red')");
    for (k, f) in red.iter().enumerate() {
        extra += &format!("#{}=OVER_RIDING_STYLED_ITEM('',(#916),#{},#907);\n", 920 + k, entity_id(&plain, "ADVANCED_FACE", *f));
    }
    extra += "#930=COLOUR_RGB('',0.0,1.0,0.0);\n#931=CURVE_STYLE('',$,$,#930);\n#932=PRESENTATION_STYLE_ASSIGNMENT((#931));\n";
    extra += &format!("#933=STYLED_ITEM('',(#932),#{});\n", entity_id(&plain, "ADVANCED_FACE", 0));
    extra += "#934=MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION('',(#907,#920,#933),#999);\n";
    tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, &extra)
}

/// The colour of each triangle of a STEP mesh (`None`: uncoloured).
fn triangle_colours(m: &step::StepMesh) -> Vec<Option<[f64; 3]>> {
    let mut out = vec![None; m.mesh.triangles.len()];
    for (r, c) in &m.colours {
        for t in r.clone() {
            out[t] = Some(*c);
        }
    }
    out
}

#[test]
fn step_colours_per_face_over_their_solid() {
    const BLUE: [f64; 3] = [0.2, 0.4, 0.6];
    const RED: [f64; 3] = [1.0, 0.0, 0.0];
    // No style: no colour.
    let plain = step::read("t.step", tetra_step("SI_UNIT(.MILLI.,.METRE.)", 10.0, "").as_bytes()).expect("plain");
    assert_eq!((plain.colour, plain.colours.len()), (None, 0));
    // The slanted face (the last, 86.6 mm^2) red over a blue solid (three faces of 50 mm^2): the
    // body's colour is the solid's, the red face's triangles are red, the edge style is ignored.
    for on in ["MANIFOLD_SOLID_BREP", "CLOSED_SHELL"] {
        let m = step::read("t.step", coloured_tetra(on, &[3]).as_bytes()).expect("coloured");
        assert_eq!(m.warnings, Vec::<String>::new());
        let per = triangle_colours(&m);
        assert!(per.iter().all(Option::is_some), "every face coloured through its {on}: {per:?}");
        let red = per.iter().filter(|c| **c == Some(RED)).count();
        assert!(red >= 1 && red < per.len(), "{on}: {red} of {} triangles red", per.len());
        // Faces are meshed in order: the last face's triangles are the red ones.
        assert_eq!(per.last().copied().flatten(), Some(RED), "{on}");
        assert_eq!(per[0], Some(BLUE), "{on}: face 0 keeps its solid's colour (an edge colour is not a surface colour)");
        assert_eq!(m.colour, Some(BLUE), "{on}: the blue faces have the larger area");
    }
    // Two faces red (136.6 mm^2) against two blue (100 mm^2): the body is red.
    let m = step::read("t.step", coloured_tetra("MANIFOLD_SOLID_BREP", &[1, 3]).as_bytes()).expect("coloured");
    assert_eq!(m.colour, Some(RED));
    // Only the faces styled, the larger part of the surface unstyled: no body colour.
    let only_face = coloured_tetra("MANIFOLD_SOLID_BREP", &[3]).replace("#907=STYLED_ITEM('',(#906),", "#907=STYLED_ITEM('',(#999),");
    let m = step::read("t.step", only_face.as_bytes()).expect("face only");
    assert!(triangle_colours(&m).iter().any(Option::is_none), "the solid is not styled: faces without a colour");
    assert_eq!(m.colour, None, "86.6 mm^2 red against 150 mm^2 without a colour");
}

/// A second-generation export of one part, its geometry `T.step`; `visual` goes into the part
/// (a `VisualProperties` element or nothing).
fn one_part_export(visual: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<SimscapeMultibodyImportXML xmlns="urn:mathworks:SimscapeMultibody:import" version="2.0">
  <Created by="t" from="Onshape" on="1/1/25" using="Simscape Multibody Exporter"/>
  <ModelUnits length="millimeter" mass="kilogram"/>
  <DataUnits length="meter" mass="kilogram"/>
  <RootAssembly name="tet" uid="A">
    <InstanceTree>
      <Instance entityUid="P1" grounded="true" name="Base &lt;1&gt;" uid="b">
        <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0</Translation></Transform>
      </Instance>
      <Instance entityUid="P1" name="Arm &lt;1&gt;" uid="a">
        <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0.02</Translation></Transform>
      </Instance>
    </InstanceTree>
    <Joints>
      <Revolute name="j1">
        <BaseFrame><InstancePath><Uid>b</Uid></InstancePath>
          <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0.02</Translation></Transform></BaseFrame>
        <FollowerFrame><InstancePath><Uid>a</Uid></InstancePath>
          <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0</Translation></Transform></FollowerFrame>
      </Revolute>
    </Joints>
  </RootAssembly>
  <Parts>
    <Part name="P" uid="P1">
      <MassProperties><Mass>0.0005</Mass><CenterOfMass>0.0025 0.0025 0.0025</CenterOfMass><Inertia>1e-8 1e-8 1e-8 0 0 0</Inertia></MassProperties>
      <GeometryFile name="T.step" type="STEP"/>
      {visual}
    </Part>
  </Parts>
</SimscapeMultibodyImportXML>"#
    )
}

#[test]
fn step_colour_reaches_the_body_and_the_step_cache_counts_tessellations() {
    use crate::pipeline::front::bundle::Bundle;
    use crate::pipeline::{self, Options};
    let bundle = |visual: &str, step: &str| {
        Bundle::from_files(
            "b",
            [("tet.xml".to_string(), one_part_export(visual).into_bytes()), ("T.step".to_string(), step.as_bytes().to_vec())],
        )
        .expect("bundle")
    };
    let red_faces = coloured_tetra("MANIFOLD_SOLID_BREP", &[1, 3]);
    // No Diffuse in the XML: both bodies take the STEP file's colour (report, Modelica).
    let out = pipeline::convert(&bundle("", &red_faces), &Options::default()).expect("converts");
    assert_eq!(out.report.bodies.len(), 2);
    assert!(
        out.report.bodies.iter().all(|b| b.color == [1.0, 0.0, 0.0]),
        "{:?}",
        out.report.bodies.iter().map(|b| b.color).collect::<Vec<_>>()
    );
    let mech = out
        .files
        .iter()
        .find(|(p, _)| p.ends_with("/Mechanics.mo"))
        .map(|(_, b)| String::from_utf8_lossy(&b.bytes()).to_string())
        .expect("Mechanics.mo");
    assert!(mech.contains("{255, 0, 0}"), "the shapes are drawn red");
    // One file named by two bodies: meshed once.
    assert_eq!(out.step, pipeline::passes::geometry::StepCounts { meshed: 1, cached: 0 });
    // The XML's Diffuse stays.
    let diffuse = r#"<VisualProperties><Diffuse r="0" g="0.5" b="0" a="1"/></VisualProperties>"#;
    let out = pipeline::convert(&bundle(diffuse, &red_faces), &Options::default()).expect("converts");
    assert!(out.report.bodies.iter().all(|b| b.color == [0.0, 0.5, 0.0]));

    // The cache: a second conversion of the same files meshes nothing; a changed file is meshed.
    let cache = std::sync::Arc::new(step::MemoryStepCache::default());
    let shared: std::sync::Arc<dyn step::StepCache> = cache.clone();
    let opts = Options { step_cache: Some(shared), write_shapes: false, ..Options::default() };
    let first = pipeline::convert(&bundle("", &red_faces), &opts).expect("converts");
    assert_eq!((first.step.meshed, first.step.cached), (1, 0));
    let again = pipeline::convert(&bundle("", &red_faces), &opts).expect("converts");
    assert_eq!((again.step.meshed, again.step.cached), (0, 1), "the same STEP file again is not meshed");
    assert!(again.files == first.files, "the same package from the cache");
    let other = coloured_tetra("MANIFOLD_SOLID_BREP", &[3]);
    let changed = pipeline::convert(&bundle("", &other), &opts).expect("converts");
    assert_eq!((changed.step.meshed, changed.step.cached), (1, 0), "a changed file is meshed");
    assert!(changed.report.bodies.iter().all(|b| b.color == [0.2, 0.4, 0.6]));
    let (hits, misses, entries, _) = cache.stats();
    assert_eq!((hits, misses, entries), (1, 2, 2), "one lookup per distinct file and conversion");
}

/// Every directed edge has its reverse exactly once: a closed, consistently wound mesh.
fn is_closed(m: &ir::Mesh) -> bool {
    let mut edges: std::collections::HashMap<(u32, u32), usize> = std::collections::HashMap::new();
    for t in &m.triangles {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    edges.iter().all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
}

/// A T-junction as the STEP tessellator leaves one: a unit cube whose top face has a corner in
/// the middle of the edge it shares with the front face (the front face's edge does not have
/// it). The repair splits the front face's triangle there: closed, the volume unchanged, the
/// colour runs following the split; a vertex off the edge by more than the chord is left alone.
#[test]
fn step_t_junctions_are_closed() {
    let corner = |i: u32| [(i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32];
    let mut vertices: Vec<[f32; 3]> = (0..8).map(corner).collect();
    vertices.push([0.5, 0.0, 1.0]); // 8: on the top face's front edge, 4-5
                                    // Faces as quads (corner indices), the top one as a fan from vertex 8.
    let quads: [[u32; 4]; 5] = [[0, 1, 3, 2], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6]];
    let mut triangles: Vec<[u32; 3]> = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    triangles.extend([[8, 5, 7], [8, 7, 6], [8, 6, 4]]);
    let p = |i: u32| Vector3::from(vertices[i as usize].map(f64::from));
    for t in &mut triangles {
        let n = (p(t[1]) - p(t[0])).cross(&(p(t[2]) - p(t[0])));
        let out = (p(t[0]) + p(t[1]) + p(t[2])) / 3.0 - Vector3::repeat(0.5);
        if n.dot(&out) < 0.0 {
            t.swap(1, 2);
        }
    }
    let cube = ir::Mesh { vertices, triangles };
    assert!(!is_closed(&cube), "the T-junction leaves the cube open");
    // Colour runs: the five side faces red, the top blue.
    let mut m = cube.clone();
    let mut runs = vec![(0..10, [1.0, 0.0, 0.0]), (10..13, [0.0, 0.0, 1.0])];
    let n = step::close_t_junctions(&mut m, &mut runs, 1e-4);
    assert_eq!(n, 1);
    assert!(is_closed(&m), "{:?}", m.triangles);
    assert_eq!(m.triangles.len(), 14, "the front face's triangle on that edge is split in two");
    assert_eq!(runs, vec![(0..11, [1.0, 0.0, 0.0]), (11..14, [0.0, 0.0, 1.0])]);
    let (v, c) = volume_centroid(&m);
    assert!((v - 1.0).abs() < 1e-12 && (c - Vector3::repeat(0.5)).norm() < 1e-12, "{v} {c}");
    // The same vertex 1 mm off the edge of a 1 m cube, with a chord of 0.1 mm: not on it.
    let mut off = cube.clone();
    off.vertices[8] = [0.5, 0.0, 1.001];
    assert_eq!(step::close_t_junctions(&mut off, &mut [], 1e-4), 0);
    assert!(!is_closed(&off));
}

/// Neighbouring faces whose shared corners were evaluated a few µm apart (as on trimmed B-spline
/// faces): the top face of a 10 cm cube on its own four corners 3 µm off the sides' corners.
/// Joined, the cube is closed with its 8 corners; 30 µm apart (more than the gap), left open.
#[test]
fn step_open_corners_a_few_micrometres_apart_are_joined() {
    let cube = |gap: f32| {
        let corner = |i: u32| [0.1 * (i & 1) as f32, 0.1 * ((i >> 1) & 1) as f32, 0.1 * ((i >> 2) & 1) as f32];
        let mut vertices: Vec<[f32; 3]> = (0..8).map(corner).collect();
        // 8..12: the top face's own copies of corners 4..8.
        vertices.extend((4..8).map(|i| {
            let c = corner(i);
            [c[0] + gap, c[1], c[2] - gap]
        }));
        let quads: [[u32; 4]; 6] = [[0, 1, 3, 2], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6], [8, 9, 11, 10]];
        let mut triangles: Vec<[u32; 3]> = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
        let p = |i: u32| Vector3::from(vertices[i as usize].map(f64::from));
        for t in &mut triangles {
            let n = (p(t[1]) - p(t[0])).cross(&(p(t[2]) - p(t[0])));
            let out = (p(t[0]) + p(t[1]) + p(t[2])) / 3.0 - Vector3::repeat(0.05);
            if n.dot(&out) < 0.0 {
                t.swap(1, 2);
            }
        }
        ir::Mesh { vertices, triangles }
    };
    let mut m = cube(3e-6);
    assert!(!is_closed(&m));
    let mut runs = vec![(0..12, [0.5, 0.5, 0.5])];
    assert_eq!(step::join_open_corners(&mut m, &mut runs, 5e-5), 4);
    assert!(is_closed(&m), "{:?}", m.triangles);
    assert_eq!((m.vertices.len(), m.triangles.len(), runs[0].0.clone()), (8, 12, 0..12));
    // A chord of 5 µm allows 2.5 µm: the 3 µm gap stays, as does a 30 µm one at any chord.
    let mut fine = cube(3e-6);
    assert_eq!(step::join_open_corners(&mut fine, &mut [], 5e-6), 0);
    let mut far = cube(3e-5);
    assert_eq!(step::join_open_corners(&mut far, &mut [], 5e-5), 0);
    assert!(!is_closed(&far));
}
