//! Scene meshes (issue 29): a mesh the user uploads for scene objects (STL binary or ASCII, OBJ,
//! COLLADA), read by the engine's mesh readers, bounded in size and triangles, and kept as a
//! binary STL in the file's own units (objects scale it by their `unit`). Collision checks take
//! its convex hull.

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

/// Reads an uploaded mesh; `file` names it and its extension chooses the reader (`.stl`,
/// `.obj`, `.dae`). Errors say what is wrong (not a mesh, too big, too many triangles, flat).
pub fn read(file: &str, bytes: &[u8]) -> Result<SceneMesh, String> {
    if bytes.len() > MAX_MESH_BYTES {
        return Err(format!("{} bytes is more than the limit of {MAX_MESH_BYTES} bytes", bytes.len()));
    }
    let ext = file.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase()).unwrap_or_default();
    if !matches!(ext.as_str(), "stl" | "obj" | "dae") {
        return Err(format!("{file}: a scene mesh is an .stl, .obj or .dae file"));
    }
    let mesh = crate::pipeline::front::mesh::read(file, bytes).map_err(|e| e.to_string())?;
    if mesh.triangles.len() > MAX_MESH_TRIANGLES {
        return Err(format!("{} triangles is more than the limit of {MAX_MESH_TRIANGLES}", mesh.triangles.len()));
    }
    let stl = crate::pipeline::back::stl::write_binary(&mesh, "scene");
    from_stl(&stl)
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
