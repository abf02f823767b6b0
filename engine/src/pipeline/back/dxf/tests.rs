//! Unit tests of the DXF back end: test-only code, declared by the parent under `#[cfg(test)]`.

use super::*;
use std::path::Path;
use std::process::Command;

fn mesh() -> ir::Mesh {
    ir::Mesh {
        vertices: vec![[0.0, 0.0, 0.0], [0.1, 0.0, -0.0], [0.0, 0.2, 1e-7], [-0.123_456_79, 3.5e-9, 12345.678], [0.3, 0.3, 0.3]],
        triangles: vec![[0, 1, 2], [1, 3, 2], [0, 3, 4], [4, 4, 4]],
    }
}

/// (code, value) pairs of a DXF file, checking the two-line layout.
fn pairs(dxf: &[u8]) -> Vec<(u16, String)> {
    let text = std::str::from_utf8(dxf).expect("ASCII");
    assert!(!text.contains('\r'));
    assert!(text.ends_with("EOF\n"));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len() % 2, 0);
    lines
        .chunks(2)
        .map(|p| {
            assert_eq!(p[0].len(), 3, "group code right-aligned in 3 columns: {:?}", p[0]);
            (p[0].trim().parse().expect("group code"), p[1].to_string())
        })
        .collect()
}

#[test]
fn structure_and_faces() {
    let m = mesh();
    let dxf = write(&m, [255, 0, 0], "arm link");
    let p = pairs(&dxf);
    let zeros: Vec<&str> = p.iter().filter(|(c, _)| *c == 0).map(|(_, v)| v.as_str()).collect();
    // Sections in order, balanced.
    let sections: Vec<&str> = p.windows(2).filter(|w| w[0] == (0, "SECTION".into())).map(|w| w[1].1.as_str()).collect();
    assert_eq!(sections, ["HEADER", "TABLES", "ENTITIES"]);
    assert_eq!(zeros.iter().filter(|z| **z == "ENDSEC").count(), 3);
    assert_eq!(zeros.last(), Some(&"EOF"));
    assert!(p.contains(&(1, "AC1009".into())));
    assert!(p.windows(2).any(|w| w[0] == (9, "$INSUNITS".into()) && w[1] == (70, "6".into())));
    // The layer, sanitised, coloured red (ACI 1); faces BYLAYER.
    let layer_at = p.iter().position(|x| *x == (2, "arm_link".into())).expect("layer entry");
    assert_eq!(p[layer_at + 2], (62, "1".into()));
    assert_eq!(zeros.iter().filter(|z| **z == "3DFACE").count(), m.triangles.len());

    // Faces: corners read back to the mesh's f32 values, fourth corner = third.
    let ents = p.iter().position(|x| *x == (2, "ENTITIES".into())).expect("entities");
    let mut faces = Vec::new();
    let mut cur: Option<Vec<(u16, String)>> = None;
    for (c, v) in &p[ents + 1..] {
        if *c == 0 {
            faces.extend(cur.take());
            if v == "3DFACE" {
                cur = Some(Vec::new());
            }
        } else if let Some(f) = cur.as_mut() {
            f.push((*c, v.clone()));
        }
    }
    assert_eq!(faces.len(), m.triangles.len());
    for (f, t) in faces.iter().zip(&m.triangles) {
        let get = |code: u16| -> f32 { f.iter().find(|(c, _)| *c == code).expect("code").1.parse().expect("number") };
        assert_eq!(f.iter().find(|(c, _)| *c == 8).map(|x| x.1.as_str()), Some("arm_link"));
        assert_eq!(f.iter().find(|(c, _)| *c == 62).map(|x| x.1.as_str()), Some("256"));
        for corner in 0..4 {
            let v = m.vertices[t[corner.min(2)] as usize];
            for (k, want) in v.iter().enumerate() {
                let got = get(10 + corner as u16 + 10 * k as u16);
                assert_eq!(got.to_bits(), want.to_bits(), "corner {corner} axis {k}");
            }
        }
    }
    // Shortest round trip, no exponent.
    assert!(p.contains(&(10, "0.1".into())));
    assert!(p.contains(&(32, "0.0000001".into())));
    assert!(p.iter().filter(|(c, _)| (10..=33).contains(c)).all(|(_, v)| !v.contains(['e', 'E'])));
}

#[test]
fn empty_mesh_and_layer_zero() {
    let dxf = write(&ir::Mesh::default(), [0, 0, 0], "");
    let p = pairs(&dxf);
    assert!(!p.iter().any(|(c, v)| *c == 0 && v == "3DFACE"));
    assert!(!p.iter().any(|(_, v)| v == "$EXTMIN"));
    assert_eq!(p.iter().filter(|x| **x == (0, "LAYER".into())).count(), 1);
    assert!(p.contains(&(62, "250".into())));
}

#[test]
fn layer_names() {
    assert_eq!(layer_name("ICUB3_HIP-FLEX$1"), "ICUB3_HIP-FLEX$1");
    assert_eq!(layer_name("a b/é"), "a_b__");
    assert_eq!(layer_name(&"x".repeat(40)).len(), 31);
    assert_eq!(layer_name(""), "0");
}

/// The independent reader: `tests/tools/dxf_check.py` (ezdxf) reads, audits and counts faces.
#[test]
fn ezdxf_reads_the_output() {
    let has_ezdxf = Command::new("python3").args(["-c", "import ezdxf"]).status().is_ok_and(|s| s.success());
    if !has_ezdxf {
        let msg = "python3 with ezdxf not available (pip install ezdxf)";
        assert!(std::env::var("CAD2MO_REQUIRE_TOOLS").map_or(true, |v| v != "1"), "{msg}");
        eprintln!("notice: {msg}; skipping the ezdxf check");
        return;
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/tools/dxf_check.py");
    let dir = tempfile::tempdir().expect("temp dir");
    let mut cases = vec![("small", mesh(), [200u8, 120, 40])];
    // A real mesh when the fixtures are there.
    if let Some(p) = crate::pipeline::front::stl::tests::fixture_stls()
        .into_iter()
        .find(|p| p.file_name().is_some_and(|n| n.to_string_lossy().contains("r_foot")))
    {
        let bytes = std::fs::read(&p).expect("fixture");
        let m = crate::pipeline::front::stl::parse("foot.stl", &bytes, 0.001).expect("parses");
        cases.push(("foot", m, [179, 179, 179]));
    }
    for (name, m, color) in cases {
        let path = dir.path().join(format!("{name}.dxf"));
        std::fs::write(&path, write(&m, color, name)).expect("write");
        let out = Command::new("python3").arg(&script).arg(&path).arg(m.triangles.len().to_string()).output().expect("run dxf_check.py");
        let stdout = String::from_utf8_lossy(&out.stdout);
        eprintln!("{stdout}{}", String::from_utf8_lossy(&out.stderr));
        assert!(out.status.success(), "dxf_check.py failed on {name}");
        // The wrong count must fail.
        let bad =
            Command::new("python3").arg(&script).arg(&path).arg((m.triangles.len() + 1).to_string()).output().expect("run dxf_check.py");
        assert_eq!(bad.status.code(), Some(1));
    }
}
