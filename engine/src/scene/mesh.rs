//! Scene meshes (issue 29): a mesh the user uploads for scene objects (STL binary or ASCII, OBJ,
//! COLLADA, VRML 97 / 1.0), read by the engine's mesh readers, bounded in size and triangles, and
//! kept as a binary STL in the file's own units (objects scale it by their `unit`): STL, OBJ and
//! VRML have no unit of their own; a COLLADA file's `<unit meter>` and `<up_axis>` are applied by
//! its reader (`front::mesh::collada`), so its STL is in metres, Z up. A VRML file's shapes are
//! placed by their grouping nodes' transforms (`front::vrml`) and merged into one mesh; Inlines
//! and EXTERNPROTOs, which name other files, stand for nothing (one file is uploaded).
//! Collision checks take the mesh's convex hull.

use std::collections::BTreeMap;

use nalgebra::Point3;

use crate::collision::ConvexPart;

/// Largest mesh file, bytes.
pub const MAX_MESH_BYTES: usize = 32 << 20;
/// Most triangles in one mesh.
pub const MAX_MESH_TRIANGLES: usize = 200_000;

/// A stored mesh: its binary STL and the corners of its convex hull (file units).
#[derive(Clone, Debug, PartialEq)]
pub struct SceneMesh {
    pub stl: Vec<u8>,
    pub triangles: usize,
    pub hull: ConvexPart,
}

/// The meshes of a model's scene by name.
pub type Meshes = BTreeMap<String, SceneMesh>;

/// The scale of a mesh unit to metres.
pub fn unit_scale(unit: &str) -> Option<f64> {
    match unit {
        "m" => Some(1.0),
        "mm" => Some(1e-3),
        "cm" => Some(1e-2),
        "in" => Some(0.0254),
        _ => None,
    }
}

/// The file name an upload without one is read as: VRML and COLLADA by their first bytes (a
/// `#VRML` header; `<COLLADA` near the start), anything else STL.
pub fn default_file(bytes: &[u8]) -> &'static str {
    if crate::pipeline::front::vrml::is_vrml(bytes) {
        return "mesh.wrl";
    }
    let head = &bytes[..bytes.len().min(1024)];
    if head.windows(8).any(|w| w.eq_ignore_ascii_case(b"<COLLADA")) {
        "mesh.dae"
    } else {
        "mesh.stl"
    }
}

/// Reads an uploaded mesh; `file` names it and its extension chooses the reader (`.stl`,
/// `.obj`, `.dae`, `.wrl`/`.wrz`/`.vrml`). Errors name the file (and the line where the reader
/// knows it) and say what is wrong (not a mesh, too big, too many triangles, flat).
pub fn read(file: &str, bytes: &[u8]) -> Result<SceneMesh, String> {
    if bytes.len() > MAX_MESH_BYTES {
        return Err(format!("{} bytes is more than the limit of {MAX_MESH_BYTES} bytes", bytes.len()));
    }
    let ext = file.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase()).unwrap_or_default();
    let mesh = match ext.as_str() {
        "stl" | "obj" | "dae" => crate::pipeline::front::mesh::read(file, bytes).map_err(|e| e.to_string())?,
        "wrl" | "wrz" | "vrml" => vrml(file, bytes)?,
        _ => return Err(format!("{file}: a scene mesh is an .stl, .obj, .dae (COLLADA) or .wrl (VRML) file")),
    };
    if mesh.triangles.len() > MAX_MESH_TRIANGLES {
        return Err(format!("{} triangles is more than the limit of {MAX_MESH_TRIANGLES}", mesh.triangles.len()));
    }
    let stl = crate::pipeline::back::stl::write_binary(&mesh, "scene");
    from_stl(&stl)
}

/// A VRML file's shapes in its root coordinates (each grouping node's global transform applied,
/// a mirroring one turning the triangles' corner order), merged into one mesh. Gzip is read
/// (at most [`MAX_MESH_BYTES`] decompressed); more than [`MAX_MESH_TRIANGLES`] triangles is
/// refused before the expansion that would pass it.
fn vrml(file: &str, bytes: &[u8]) -> Result<crate::pipeline::ir::Mesh, String> {
    use crate::pipeline::front::{bundle::Bundle, vrml};
    // The bundle holds the one file under its own name (without folders).
    let name = file.rsplit(['/', '\\']).next().unwrap_or(file);
    let bundle =
        Bundle::from_files("upload", [(name.to_string(), bytes.to_vec())]).map_err(|_| format!("{file}: not a usable file name"))?;
    let gz = vrml::Gunzip::new(MAX_MESH_BYTES as u64);
    let (scene, _) = vrml::parse_within(&bundle, name, &gz, MAX_MESH_TRIANGLES).map_err(|e| e.to_string())?;
    let mut mesh = crate::pipeline::ir::Mesh::default();
    for node in &scene.nodes {
        let g = node.global;
        let mirrored = g.fixed_view::<3, 3>(0, 0).determinant() < 0.0;
        for s in &node.shapes {
            let mut m = s.mesh.clone();
            for v in &mut m.vertices {
                let p = g.transform_point(&Point3::new(v[0] as f64, v[1] as f64, v[2] as f64));
                *v = [p.x as f32, p.y as f32, p.z as f32];
            }
            if mirrored {
                for t in &mut m.triangles {
                    t.swap(1, 2);
                }
            }
            mesh.append(&m);
        }
    }
    crate::pipeline::front::mesh::finish(name, mesh).map_err(|e| e.to_string())
}

/// A stored mesh from its binary STL.
pub fn from_stl(stl: &[u8]) -> Result<SceneMesh, String> {
    let mesh = crate::pipeline::front::stl::parse("mesh.stl", stl, 1.0).map_err(|e| e.to_string())?;
    if mesh.triangles.is_empty() {
        return Err("the mesh has no triangles".into());
    }
    let pts: Vec<Point3<f64>> = mesh.vertices.iter().map(|v| Point3::new(v[0] as f64, v[1] as f64, v[2] as f64)).collect();
    let hull = crate::collision::hull_part(&pts).ok_or("the mesh is flat (its convex hull has no volume)")?;
    Ok(SceneMesh { stl: stl.to_vec(), triangles: mesh.triangles.len(), hull })
}
