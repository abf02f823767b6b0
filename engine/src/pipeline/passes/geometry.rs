//! Reads the STL file each body names (`geometryFileName`) from the bundle into the body's mesh.
//! A file named by several bodies is read once and shared (all bodies are in the export's one
//! length unit, so their meshes are the same).
//!
//! Meshes from SimMechanics Link are in the body's CS1 frame, in the export's length unit; the
//! STL front end scales them to metres. A named file that is missing from the bundle is a warning
//! (the model converts without that shape); two candidates for one name, or a corrupt STL, are
//! errors.

use std::collections::HashMap;
use std::sync::Arc;

use crate::pipeline::front::bundle::{Bundle, BundleError};
use crate::pipeline::front::mesh::MAX_BUNDLE_TRIANGLES;
use crate::pipeline::front::stl::{self, StlError};
use crate::pipeline::ir::{self, Mesh, Model, Warning};

#[derive(Debug, thiserror::Error)]
pub enum GeometryError {
    #[error(transparent)]
    Bundle(#[from] BundleError),
    #[error(transparent)]
    Stl(#[from] StlError),
    #[error(
        "{file}: body \"{body}\" brings the bundle to {total} triangles, over the limit of {max} triangles per bundle \
         (every body naming a file counts its triangles again)"
    )]
    TriangleBudget { file: String, body: String, total: usize, max: usize },
}

/// Fills `Body::mesh` for every body whose STL is in the bundle. `xml_path` is the XML's path in
/// the bundle (references are resolved from its folder). `done(i, n)` is told after each of the
/// `n` bodies that name a file.
pub fn read_meshes(
    model: &mut Model,
    bundle: &Bundle,
    xml_path: &str,
    done: &mut dyn FnMut(usize, usize),
) -> Result<Vec<Warning>, GeometryError> {
    let mut warnings = Vec::new();
    let scale = model.length_scale;
    let total = model.bodies.iter().filter(|b| b.geometry_file.is_some()).count();
    // Triangles of the bodies' meshes so far, a shared file counted once per body
    // (`MAX_BUNDLE_TRIANGLES`).
    let mut triangles = 0usize;
    let mut read: HashMap<&str, Arc<Mesh>> = HashMap::new();
    for (i, body) in model.bodies.iter_mut().filter(|b| b.geometry_file.is_some()).enumerate() {
        done(i, total);
        let Some(name) = body.geometry_file.clone() else { continue };
        match bundle.resolve(xml_path, &name)? {
            Some(path) => {
                let mesh = match read.get(path) {
                    Some(m) => m.clone(),
                    None => {
                        let m = Arc::new(stl::parse(path, bundle.get(path).unwrap_or_default(), scale)?);
                        read.insert(path, m.clone());
                        m
                    }
                };
                triangles = triangles.saturating_add(mesh.triangles.len());
                if triangles > MAX_BUNDLE_TRIANGLES {
                    return Err(GeometryError::TriangleBudget {
                        file: ir::clip(path, 300),
                        body: ir::clip(&body.cad_name, 200),
                        total: triangles,
                        max: MAX_BUNDLE_TRIANGLES,
                    });
                }
                body.mesh = Some(mesh);
                body.geometry_sources = vec![path.to_string()];
            }
            None => warnings.push(Warning::new(
                "geometry-missing",
                format!(
                    "body \"{}\" names geometry file \"{name}\", which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape",
                    body.cad_name
                ),
                body.loc.to_string(),
            )),
        }
    }
    Ok(warnings)
}
