//! TEMPORARY stub (replaced by the mesh helper's module at merge).
use crate::pipeline::ir::Mesh;

#[derive(Debug, thiserror::Error)]
#[error("{file}: {message}")]
pub struct MeshError {
    pub file: String,
    pub message: String,
}

pub fn read(path: &str, bytes: &[u8]) -> Result<Mesh, MeshError> {
    if path.to_ascii_lowercase().ends_with(".stl") {
        return crate::pipeline::front::stl::parse(path, bytes, 1.0).map_err(|e| MeshError { file: path.into(), message: e.to_string() });
    }
    Err(MeshError { file: path.into(), message: "unsupported".into() })
}
pub fn box_mesh(_s: [f64; 3]) -> Mesh {
    Mesh::default()
}
pub fn cylinder_mesh(_r: f64, _l: f64) -> Mesh {
    Mesh::default()
}
pub fn sphere_mesh(_r: f64) -> Mesh {
    Mesh::default()
}
