//! Reads the STL file each body names (`geometryFileName`) from the bundle into the body's mesh.
//!
//! Meshes from SimMechanics Link are in the body's CS1 frame, in the export's length unit; the
//! STL front end scales them to metres. A named file that is missing from the bundle is a warning
//! (the model converts without that shape); two candidates for one name, or a corrupt STL, are
//! errors.

use crate::pipeline::front::bundle::{Bundle, BundleError};
use crate::pipeline::front::stl::{self, StlError};
use crate::pipeline::ir::{Model, Warning};

#[derive(Debug, thiserror::Error)]
pub enum GeometryError {
    #[error(transparent)]
    Bundle(#[from] BundleError),
    #[error(transparent)]
    Stl(#[from] StlError),
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
    for (i, body) in model.bodies.iter_mut().filter(|b| b.geometry_file.is_some()).enumerate() {
        done(i, total);
        let Some(name) = body.geometry_file.clone() else { continue };
        match bundle.resolve(xml_path, &name)? {
            Some(path) => {
                let bytes = bundle.get(path).unwrap_or_default();
                body.mesh = Some(stl::parse(path, bytes, scale)?);
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
