//! Reads the mesh file each body names (`geometryFileName`, a second-generation part's
//! `GeometryFile`) from the bundle into the body's mesh. A file named by several bodies is read
//! once and shared (all bodies are in the export's one length unit, so their meshes are the same).
//!
//! Meshes from SimMechanics Link are in the body's CS1 frame, in the export's length unit; the
//! STL front end scales them to metres. STEP files (second-generation exports) carry their own
//! unit and are tessellated by `front::mesh::step`, in the part's frame; each file's content is
//! meshed once per conversion however many bodies name it (keyed by SHA-256 of its bytes), and
//! each face it could not mesh is a `step-face` warning. A part the XML gives no colour
//! (`Diffuse`) takes its STEP file's (the colour of the largest area of its faces). A named file that is missing from the
//! bundle is a warning (the model converts without that shape); two candidates for one name, or a
//! corrupt STL or STEP file, are errors.

use std::collections::HashMap;
use std::sync::Arc;

use crate::pipeline::front::bundle::{Bundle, BundleError};
use crate::pipeline::front::mesh::step::{StepCache, StepKey};
use crate::pipeline::front::mesh::{self, MeshError, MAX_BUNDLE_TRIANGLES};
use crate::pipeline::front::stl::{self, StlError};
use crate::pipeline::ir::{self, Mesh, Model, Warning};

#[derive(Debug, thiserror::Error)]
pub enum GeometryError {
    #[error(transparent)]
    Bundle(#[from] BundleError),
    #[error(transparent)]
    Stl(#[from] StlError),
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error(
        "{file}: body \"{body}\" brings the bundle to {total} triangles, over the limit of {max} triangles per bundle \
         (every body naming a file counts its triangles again)"
    )]
    TriangleBudget { file: String, body: String, total: usize, max: usize },
}

/// How a conversion got its STEP tessellations (distinct file contents: a file named by several
/// bodies counts once): meshed, or served by the STEP cache. Not in the report (the output is
/// the same either way).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepCounts {
    pub meshed: usize,
    pub cached: usize,
}

/// Fills `Body::mesh` for every body whose STL is in the bundle. `xml_path` is the XML's path in
/// the bundle (references are resolved from its folder). STEP tessellations are taken from and
/// put into `step_cache` when given. `done(i, n)` is told after each of the `n` bodies that name
/// a file.
pub fn read_meshes(
    model: &mut Model,
    bundle: &Bundle,
    xml_path: &str,
    step_cache: Option<&dyn StepCache>,
    done: &mut dyn FnMut(usize, usize),
) -> Result<(Vec<Warning>, StepCounts), GeometryError> {
    let mut warnings = Vec::new();
    let mut counts = StepCounts::default();
    let scale = model.length_scale;
    let total = model.bodies.iter().filter(|b| b.geometry_file.is_some()).count();
    // Triangles of the bodies' meshes so far, a shared file counted once per body
    // (`MAX_BUNDLE_TRIANGLES`).
    let mut triangles = 0usize;
    let mut read: HashMap<&str, Arc<Mesh>> = HashMap::new();
    // STEP meshes by file content, for this conversion (the cache may be shared or absent).
    let mut step_meshes: HashMap<StepKey, (Arc<Mesh>, Option<[f64; 3]>)> = HashMap::new();
    let (mut fresh, mut cached) = mesh_step_files(model, bundle, xml_path, step_cache);
    let mut parsed = parse_stl_files(model, bundle, xml_path, scale);
    for (i, body) in model.bodies.iter_mut().filter(|b| b.geometry_file.is_some()).enumerate() {
        done(i, total);
        let Some(name) = body.geometry_file.clone() else { continue };
        match bundle.resolve(xml_path, &name)? {
            Some(path) => {
                let bytes = bundle.get(path).unwrap_or_default();
                let mesh = if is_step(path) {
                    let key = StepKey::of(bytes);
                    let (mesh, colour) = match step_meshes.get(&key) {
                        Some(m) => m.clone(),
                        None => {
                            // Meshed by `mesh_step_files` for this conversion, else from the
                            // cache, else (a thread of `mesh_step_files` failed) meshed here.
                            let tess = match fresh.remove(&key) {
                                Some(r) => {
                                    counts.meshed += 1;
                                    let t = Arc::new(r?);
                                    if let Some(c) = step_cache {
                                        c.put(key, t.clone());
                                    }
                                    t
                                }
                                None => match cached.remove(&key) {
                                    Some(t) => {
                                        counts.cached += 1;
                                        t
                                    }
                                    None => {
                                        counts.meshed += 1;
                                        let t = Arc::new(mesh::step::read(path, bytes)?);
                                        if let Some(c) = step_cache {
                                            c.put(key, t.clone());
                                        }
                                        t
                                    }
                                },
                            };
                            for w in &tess.warnings {
                                warnings.push(Warning::new("step-face", w.clone(), body.loc.to_string()));
                            }
                            let m = Arc::new(mesh::finish(path, tess.mesh.clone())?);
                            step_meshes.insert(key, (m.clone(), tess.colour));
                            (m, tess.colour)
                        }
                    };
                    // The file's colour where the XML gives the part none (an XML `Diffuse`
                    // stays, as the VRML colours do not replace a CAD material).
                    if body.material.is_none() {
                        body.material = colour.map(|color| ir::Material { color, transparency: 0.0, specular: 0.0 });
                    }
                    mesh
                } else {
                    match read.get(path) {
                        Some(m) => m.clone(),
                        None => {
                            let m = Arc::new(match parsed.remove(path) {
                                Some(r) => r?,
                                None => stl::parse(path, bytes, scale)?,
                            });
                            read.insert(path, m.clone());
                            m
                        }
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
    Ok((warnings, counts))
}

/// STEP files meshed by this conversion, by content (each result kept for the body loop).
type Meshed = HashMap<StepKey, Result<mesh::step::StepMesh, MeshError>>;
/// STEP tessellations the cache held, by content.
type Cached = HashMap<StepKey, Arc<mesh::step::StepMesh>>;

/// The distinct STEP files the bodies name: those the cache holds (looked up once each), and the
/// others meshed on up to two threads (the STEP files of an export are meshed in about half the
/// time on this project's 2-core machine; each file is still meshed by one thread). Errors are
/// kept for the body loop, which reports the first in body order.
fn mesh_step_files(model: &Model, bundle: &Bundle, xml_path: &str, step_cache: Option<&dyn StepCache>) -> (Meshed, Cached) {
    let mut todo: Vec<(StepKey, &str, &[u8])> = Vec::new();
    let mut cached = HashMap::new();
    for body in &model.bodies {
        let Some(name) = &body.geometry_file else { continue };
        let Ok(Some(path)) = bundle.resolve(xml_path, name) else { continue };
        if !is_step(path) {
            continue;
        }
        let bytes = bundle.get(path).unwrap_or_default();
        let key = StepKey::of(bytes);
        if todo.iter().any(|(k, _, _)| *k == key) || cached.contains_key(&key) {
            continue;
        }
        if let Some(t) = step_cache.and_then(|c| c.get(&key)) {
            cached.insert(key, t);
            continue;
        }
        todo.push((key, path, bytes));
    }
    todo.sort_by_key(|(_, _, b)| std::cmp::Reverse(b.len()));
    // `read` contains its own panics.
    let out = on_two_threads(&todo, || true, |&(k, p, b)| (k, mesh::step::read(p, b))).into_iter().collect();
    (out, cached)
}

/// `work` on each item of `todo` (in that order: largest first balances the threads), on up to
/// two threads that each take the next item while `go_on()`. A thread that panicked leaves its
/// items out: the body loop reads their files again and reports the error.
fn on_two_threads<T: Sync, R: Send>(todo: &[T], go_on: impl Fn() -> bool + Sync, work: impl Fn(&T) -> R + Sync) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let next = AtomicUsize::new(0);
    let run = || {
        let mut mine = Vec::new();
        while go_on() {
            let Some(item) = todo.get(next.fetch_add(1, Ordering::Relaxed)) else { break };
            mine.push(work(item));
        }
        mine
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    if threads < 2 || todo.len() < 2 {
        return std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)).unwrap_or_default();
    }
    std::thread::scope(|scope| {
        let helper = scope.spawn(run);
        let mut out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)).unwrap_or_default();
        if let Ok(v) = helper.join() {
            out.extend(v);
        }
        out
    })
}

/// Parses the distinct STL files the bodies name on up to two threads (37 MB of ASCII STL for
/// 2,000 bodies took a sixth of a conversion's time on one thread). Files are taken largest
/// first; the threads stop taking files once those parsed hold more than the bundle's triangle
/// budget, so a hostile bundle is not read further than the body loop would read it (the loop
/// parses any file left here itself and reports the budget in body order). Errors are kept for
/// the body loop, which reports the first in body order.
fn parse_stl_files<'b>(model: &Model, bundle: &'b Bundle, xml_path: &str, scale: f64) -> HashMap<&'b str, Result<Mesh, StlError>> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let mut todo: Vec<(&'b str, &'b [u8])> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for body in &model.bodies {
        let Some(name) = &body.geometry_file else { continue };
        let Ok(Some(path)) = bundle.resolve(xml_path, name) else { continue };
        if is_step(path) || !seen.insert(path) {
            continue;
        }
        todo.push((path, bundle.get(path).unwrap_or_default()));
    }
    todo.sort_by_key(|(_, b)| std::cmp::Reverse(b.len()));
    let triangles = AtomicUsize::new(0);
    let go_on = || triangles.load(Ordering::Relaxed) <= MAX_BUNDLE_TRIANGLES;
    on_two_threads(&todo, go_on, |&(path, bytes)| {
        let r = stl::parse(path, bytes, scale);
        if let Ok(m) = &r {
            triangles.fetch_add(m.triangles.len(), Ordering::Relaxed);
        }
        (path, r)
    })
    .into_iter()
    .collect()
}

/// A STEP file, by its extension.
pub fn is_step(path: &str) -> bool {
    let lower = path.to_ascii_lowercase();
    lower.ends_with(".step") || lower.ends_with(".stp")
}
