//! Reads the meshes a URDF's links name from the bundle into each body's mesh (link frame =
//! CS1, metres), and tessellates its box, cylinder and sphere primitives. A mesh file is read
//! once; links whose geometry is that one file with the same origin and scale share one mesh.

use std::collections::HashMap;
use std::sync::Arc;

use nalgebra::Point3;

use super::{GeometryRef, Shape, Urdf};
use crate::pipeline::front::bundle::{Bundle, BundleError};
use crate::pipeline::front::mesh::{self, MeshError};
use crate::pipeline::ir::{self, Mesh, Warning};

#[derive(Debug, thiserror::Error)]
pub enum UrdfGeometryError {
    #[error(transparent)]
    Bundle(#[from] BundleError),
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error(
        "{file}: link \"{link}\" brings the bundle to {total} triangles, over the limit of {max} triangles per bundle \
         (every link and visual naming a mesh counts its triangles again)"
    )]
    TriangleBudget { file: String, link: String, total: usize, max: usize },
}

/// At most this many triangles in all the bodies' meshes of one bundle, counted after
/// instancing: a mesh file named by several links or visuals counts once per use (whether the
/// links share one placed mesh or each holds its own), checked before any is placed.
pub use crate::pipeline::front::mesh::MAX_BUNDLE_TRIANGLES;

/// Finds the bundle file a URDF mesh `filename` names, as seen from the URDF at `urdf_path`:
/// `package://NAME/rest` is the file whose path ends with `rest` (preferring one under a folder
/// `NAME` when several do), `package:///file` and relative names are relative to the URDF's
/// folder, `file://` URIs are looked up by their path's end; all case-insensitively, then by file
/// name anywhere in the bundle (two candidates are an error).
pub fn locate<'b>(bundle: &'b Bundle, urdf_path: &str, filename: &str) -> Result<Option<&'b str>, BundleError> {
    let (package, rest) = if let Some(rest) = filename.strip_prefix("package://") {
        match rest.split_once('/') {
            Some(("", path)) => (None, path.trim_start_matches('/')),
            Some((pkg, path)) => (Some(pkg), path),
            None => (None, rest),
        }
    } else if let Some(rest) = filename.strip_prefix("file://") {
        (None, rest.trim_start_matches('/'))
    } else {
        return bundle.resolve(urdf_path, filename);
    };
    let rel = if package.is_none() && !filename.starts_with("file://") { bundle.resolve(urdf_path, rest)? } else { None };
    if rel.is_some() {
        return Ok(rel);
    }
    let lower = rest.to_lowercase();
    let suffix = format!("/{lower}");
    let by_suffix: Vec<&str> = bundle
        .paths()
        .filter(|p| {
            let p = p.to_lowercase();
            p == lower || p.ends_with(&suffix)
        })
        .collect();
    let chosen: Vec<&str> = match (by_suffix.len(), package) {
        (0, _) => Vec::new(),
        (1, _) => by_suffix,
        (_, Some(pkg)) => {
            let seg = format!("/{}/", pkg.to_lowercase());
            let start = format!("{}/", pkg.to_lowercase());
            let under: Vec<&str> = by_suffix
                .iter()
                .copied()
                .filter(|p| {
                    let p = p.to_lowercase();
                    p.contains(&seg) || p.starts_with(&start)
                })
                .collect();
            if under.is_empty() {
                by_suffix
            } else {
                under
            }
        }
        _ => by_suffix,
    };
    match chosen.len() {
        0 => bundle.resolve(urdf_path, rest),
        1 => Ok(Some(chosen[0])),
        _ => Err(BundleError::Ambiguous {
            referenced_from: urdf_path.to_string(),
            name: filename.to_string(),
            candidates: chosen.into_iter().map(String::from).collect(),
        }),
    }
}

/// Fills every body's mesh from its geometry references: visuals where at least one can be
/// read, otherwise collisions. `done(i, n)` is told after each of the `n` bodies with geometry.
pub fn attach_meshes(
    urdf: &mut Urdf,
    bundle: &Bundle,
    urdf_path: &str,
    done: &mut dyn FnMut(usize, usize),
) -> Result<Vec<Warning>, UrdfGeometryError> {
    let mut warnings = Vec::new();
    let mut cache: HashMap<String, Arc<Mesh>> = HashMap::new();
    // Placed meshes of bodies whose geometry is one mesh file, by (file, scale, origin): links
    // naming the same file the same way share the result.
    let mut placed: HashMap<(String, [u64; 10]), Arc<Mesh>> = HashMap::new();
    // Triangles after instancing (the geometry each body will use: its visuals that can be read,
    // else its collisions), counted before any copy is made.
    let mut triangles = 0usize;
    for (b, refs) in urdf.geometry.iter().enumerate() {
        let mut body_total = 0usize;
        for collision in [false, true] {
            if body_total > 0 {
                break;
            }
            for g in refs.iter().filter(|g| g.collision == collision) {
                let (file, n) = match &g.shape {
                    Shape::Mesh { filename, .. } => {
                        let Some(path) = locate(bundle, urdf_path, filename)? else { continue };
                        if !cache.contains_key(path) {
                            let read = mesh::read(path, bundle.get(path).unwrap_or_default())?;
                            cache.insert(path.to_string(), Arc::new(read));
                        }
                        (path, cache[path].triangles.len())
                    }
                    Shape::Box(size) => (urdf_path, mesh::box_mesh(*size).triangles.len()),
                    Shape::Cylinder { radius, length } => (urdf_path, mesh::cylinder_mesh(*radius, *length).triangles.len()),
                    Shape::Sphere(r) => (urdf_path, mesh::sphere_mesh(*r).triangles.len()),
                };
                body_total += n;
                triangles = triangles.saturating_add(n);
                if triangles > MAX_BUNDLE_TRIANGLES {
                    return Err(UrdfGeometryError::TriangleBudget {
                        file: ir::clip(file, 300),
                        link: ir::clip(&urdf.model.bodies[b].cad_name, 200),
                        total: triangles,
                        max: MAX_BUNDLE_TRIANGLES,
                    });
                }
            }
        }
    }
    let total = urdf.geometry.iter().filter(|g| !g.is_empty()).count();
    let mut k = 0;
    for (b, refs) in urdf.geometry.iter().enumerate() {
        if refs.is_empty() {
            continue;
        }
        done(k, total);
        k += 1;
        let body = &mut urdf.model.bodies[b];
        if let Some((g, path, key)) = single_mesh(refs, bundle, urdf_path, &cache)? {
            let shared = match placed.get(&(path.to_string(), key)) {
                Some(m) => m.clone(),
                None => {
                    let mut m = Mesh::clone(&cache[path]);
                    if let Shape::Mesh { scale, .. } = &g.shape {
                        scale_mesh(&mut m, *scale);
                    }
                    m.transform(&g.origin);
                    let m = Arc::new(m);
                    placed.insert((path.to_string(), key), m.clone());
                    m
                }
            };
            body.mesh = Some(shared);
            body.geometry_sources = vec![path.to_string()];
            continue;
        }
        let mut mesh = Mesh::default();
        let mut sources = Vec::new();
        let mut missing = Vec::new();
        for collision in [false, true] {
            let set: Vec<&GeometryRef> = refs.iter().filter(|g| g.collision == collision).collect();
            if set.is_empty() || !mesh.triangles.is_empty() {
                continue;
            }
            for g in set {
                let mut part = match &g.shape {
                    Shape::Mesh { filename, scale } => {
                        let Some(path) = locate(bundle, urdf_path, filename)? else {
                            missing.push((filename.clone(), g.loc.clone(), collision));
                            continue;
                        };
                        if !cache.contains_key(path) {
                            let read = mesh::read(path, bundle.get(path).unwrap_or_default())?;
                            cache.insert(path.to_string(), Arc::new(read));
                        }
                        sources.push(path.to_string());
                        let mut m = Mesh::clone(&cache[path]);
                        scale_mesh(&mut m, *scale);
                        m
                    }
                    Shape::Box(size) => mesh::box_mesh(*size),
                    Shape::Cylinder { radius, length } => mesh::cylinder_mesh(*radius, *length),
                    Shape::Sphere(r) => mesh::sphere_mesh(*r),
                };
                part.transform(&g.origin);
                mesh.append(&part);
            }
        }
        for (name, loc, collision) in missing {
            let used = if mesh.triangles.is_empty() {
                "the body converts without a shape"
            } else if collision {
                "the other geometry is used"
            } else {
                "its other geometry is used"
            };
            warnings.push(Warning::new(
                "geometry-missing",
                format!(
                    "link \"{}\" names {} mesh \"{}\", which is not in the bundle (looked up case-insensitively, package:// by path suffix); {used}",
                    ir::clip(&body.cad_name, 200),
                    if collision { "collision" } else { "visual" },
                    ir::clip(&name, 300)
                ),
                loc.to_string(),
            ));
        }
        if !mesh.triangles.is_empty() {
            body.mesh = Some(Arc::new(mesh));
            sources.dedup();
            body.geometry_sources = sources;
        }
    }
    Ok(warnings)
}

/// A body's one mesh reference, its file's bundle path and the key of its scale and origin.
type SingleMesh<'r, 'b> = (&'r GeometryRef, &'b str, [u64; 10]);

/// When the geometry a body uses (its visuals, or its collisions when it has no visual) is one
/// mesh file found in the bundle and read with triangles (in `cache`): that reference, the
/// file's bundle path and the key of its scale and origin (their bits). Bodies with the same
/// path and key can share one placed mesh; any other body is placed on its own.
fn single_mesh<'r, 'b>(
    refs: &'r [GeometryRef],
    bundle: &'b Bundle,
    urdf_path: &str,
    cache: &HashMap<String, Arc<Mesh>>,
) -> Result<Option<SingleMesh<'r, 'b>>, BundleError> {
    let visuals = refs.iter().filter(|g| !g.collision).count();
    let mut used = refs.iter().filter(|g| g.collision == (visuals == 0));
    let (Some(g), None) = (used.next(), used.next()) else { return Ok(None) };
    let Shape::Mesh { filename, scale } = &g.shape else { return Ok(None) };
    let Some(path) = locate(bundle, urdf_path, filename)? else { return Ok(None) };
    if cache.get(path).is_none_or(|m| m.triangles.is_empty()) {
        return Ok(None);
    }
    let (t, q) = (g.origin.translation.vector, g.origin.rotation.coords);
    let key = [scale[0], scale[1], scale[2], t.x, t.y, t.z, q.x, q.y, q.z, q.w].map(f64::to_bits);
    Ok(Some((g, path, key)))
}

/// Scales vertices per axis; a mirroring scale (odd number of negative factors) reverses the
/// triangles so they stay outward-wound.
fn scale_mesh(m: &mut Mesh, s: [f64; 3]) {
    if s == [1.0; 3] {
        return;
    }
    for v in &mut m.vertices {
        let p = Point3::new(v[0] as f64 * s[0], v[1] as f64 * s[1], v[2] as f64 * s[2]);
        *v = [p.x as f32, p.y as f32, p.z as f32];
    }
    if s[0] * s[1] * s[2] < 0.0 {
        for t in &mut m.triangles {
            t.swap(1, 2);
        }
    }
}
