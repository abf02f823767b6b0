//! STEP (ISO 10303-21) B-rep geometry: bytes in, triangles out. See [`read`].
//!
//! # Why these crates
//! The exchange structure is parsed by `ruststep` 0.4 (the RICOS STEP toolkit's parser); the
//! faces, edges and surfaces of each shell are turned into `truck` B-rep by `truck-stepio` 0.3
//! and tessellated by `truck-meshalgo` 0.4 (`robust_triangulation`, a chordal tolerance). Tried on
//! the 16 STEP parts of the Onshape arm (`xml2/ErroujiOussama+Arm-Robot`): every shell and every
//! face meshes, volumes and centroids agree with OpenCASCADE's reading (tests/step.rs). Writing
//! our own AP203/214 reader for planes, cylinders, cones, spheres, tori and trimmed B-spline
//! surfaces would have been thousands of lines of trimming and tessellation code with none of
//! that evidence behind it. `truck-stepio` reads only geometry and topology, so what it does not
//! do is done here, over `ruststep`'s entity records: the length unit of each representation
//! context (SI prefixes and conversion-based units such as inches), assembly placements
//! (`REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION` + `ITEM_DEFINED_TRANSFORMATION`, and
//! `MAPPED_ITEM`), and colours.
//!
//! # Colours
//! Surface colours styled onto solids, shells and faces (`STYLED_ITEM` and the
//! `OVER_RIDING_STYLED_ITEM`s Onshape writes for faces coloured apart from their part, through
//! `PRESENTATION_STYLE_ASSIGNMENT` / `SURFACE_STYLE_USAGE` / `SURFACE_SIDE_STYLE` /
//! `SURFACE_STYLE_FILL_AREA` / `FILL_AREA_STYLE` / `FILL_AREA_STYLE_COLOUR` (or AP242's
//! `SURFACE_STYLE_RENDERING`) to a `COLOUR_RGB` or a `DRAUGHTING_PRE_DEFINED_COLOUR`) are read per
//! face: a face takes its own colour, else its shell's, else its solid's ([`StepMesh::colours`],
//! runs of triangles). The pipeline's shapes have one colour each (Modelica's `FixedShape`, the
//! 3D view, the report), so [`StepMesh::colour`] is the colour of the largest area.
//!
//! # Tessellation
//! Each shell within a chordal deviation of [`CHORDAL_TOLERANCE`] (0.05 mm) or, for large parts,
//! [`RELATIVE_TOLERANCE`] of the shell's bounding-box diagonal, whichever is larger; but at most
//! [`ANGULAR_TOLERANCE`] of the smallest radius of its cylinders, spheres and tori (not below
//! 0.025 mm), so small round parts keep their volume (a 10 mm cylinder at 0.05 mm loses 0.7 %).
//! Every face the crates cannot mesh (a surface type they do not know, a boundary loop they
//! cannot read) is a warning naming the face's entity (`#id`) and its solid, and the rest of the
//! part is kept; a shell that cannot be converted at all is a warning naming it. A face meshed
//! over a hole it should have cut is caught by comparing the length of the face mesh's rim with
//! its boundary loops' and warned about, naming the face ([`MIN_BOUNDARY_RATIO`]).
//!
//! A solid's faces are joined afterwards: corners within 0.1 µm ([`weld`]), then corners of open
//! edges within 10 µm ([`join_open_corners`]: a shared edge evaluated on two trimmed B-spline
//! surfaces) and T-junctions ([`close_t_junctions`]: an edge sampled more densely on one side),
//! so a closed B-rep gives a closed mesh (collision shapes decompose it instead of taking its
//! hull).
//!
//! Periodic B-spline edges: `truck-stepio` keeps an edge's B-spline curve whole and
//! `truck-meshalgo` samples it over its whole knot vector; for an unclamped (periodic) knot
//! vector the ends of that range lie outside the curve's domain and fall to the origin, so the
//! edge's polyline started and ended at (0, 0, 0) and both faces it bounds were meshed over the
//! hole it cuts (the Onshape arm's `Arm 011.step`, +42 % volume, and `Base.step`, +0.65 %). Such
//! edges are cut to their domain before meshing (`trim_unclamped_edges`).
//!
//! # Bounds
//! Checked before parsing: at most [`MAX_STEP_BYTES`] bytes and [`MAX_STEP_ENTITIES`] entity
//! instances; while meshing: at most [`super::MAX_TRIANGLES`] triangles after placement, at most
//! [`MAX_PLACEMENTS`] placed instances, and [`MAX_STEP_SECONDS`] of meshing, checked after every
//! shell (one shell is not interrupted: its size is bounded by the entity limit). Each limit
//! exceeded is an error naming the file and the limit. A panic inside the third-party crates on
//! hostile input is caught and reported as an error naming the file (the crates assert internally
//! on degenerate geometry); no input makes this reader panic.

use std::collections::{HashMap, HashSet};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use nalgebra::{Isometry3, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};
use ruststep::ast::{EntityInstance, Parameter, Record};
use truck_meshalgo::tessellation::RobustMeshableShape;
use truck_stepio::r#in::Table;

use super::{MeshError, MeshErrorKind};
use crate::pipeline::ir;

/// Largest STEP file read.
pub const MAX_STEP_BYTES: usize = 256 << 20;
/// Most entity instances (`#n = ...`) in one STEP file.
pub const MAX_STEP_ENTITIES: usize = 4_000_000;
/// Most placed instances of solids in one file (an assembly placing a part many times).
pub const MAX_PLACEMENTS: usize = 100_000;
/// Longest meshing of one file, checked after each shell.
pub const MAX_STEP_SECONDS: u64 = 60;
/// Default chordal deviation, metres.
pub const CHORDAL_TOLERANCE: f64 = 0.05e-3;
/// Chordal deviation relative to a shell's bounding-box diagonal for large parts.
pub const RELATIVE_TOLERANCE: f64 = 5e-4;
/// Chordal deviation relative to the smallest radius of a shell's cylinders, spheres and tori
/// (about 0.3 % of a full circle's area lost at most).
pub const ANGULAR_TOLERANCE: f64 = 2e-3;
/// A face whose mesh rim is shorter than this fraction of its B-rep boundary is warned about
/// (see `boundary_ratio`; 0.29 to 0.66 on the faces found wrong against OpenCASCADE before
/// periodic B-spline edges were cut to their domain, 0.97 or more on faithful ones, except six
/// small B-spline faces of the MG996R servo at 0.59 whose part's volume is right: warned, a false
/// alarm we prefer to a silent hole).
pub const MIN_BOUNDARY_RATIO: f64 = 0.8;
/// Deepest chain of placements (assembly nesting) followed.
const MAX_DEPTH: usize = 64;

/// A STEP file's tessellation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StepMesh {
    /// Every solid (and shell-based surface model) of the file, placed, in metres.
    pub mesh: ir::Mesh,
    /// The colour of the largest part of the file's surface (by area, placed), RGB in 0..1;
    /// `None` when that part has no colour (a file without styles, or mostly unstyled faces).
    pub colour: Option<[f64; 3]>,
    /// The coloured triangles of `mesh`: runs of triangles and their colour, in triangle order
    /// (a face's own style first, else its shell's, else its solid's; see [`Styles`]).
    pub colours: Vec<(std::ops::Range<usize>, [f64; 3])>,
    /// The triangles of each placed solid in `mesh` (a part placed twice: two ranges).
    pub solids: Vec<std::ops::Range<usize>>,
    /// Faces meshed, and faces that could not be (each also a warning).
    pub faces: usize,
    pub failed_faces: usize,
    /// Faces whose mesh lacks part of their boundary (each also a warning naming the face).
    pub suspect_faces: usize,
    /// B-spline edge curves restricted to their knot vector's valid domain (see
    /// `trim_unclamped_edges`).
    pub trimmed_edges: usize,
    /// Vertices of one face inserted into the edge of its neighbour that passes through them
    /// (T-junctions, see [`close_t_junctions`]).
    pub t_junctions: usize,
    /// Corners on open edges joined to one within a few µm (see [`join_open_corners`]).
    pub joined_corners: usize,
    /// What could not be meshed faithfully (faces, shells), each naming the entity.
    pub warnings: Vec<String>,
}

fn err(path: &str, kind: MeshErrorKind) -> MeshError {
    MeshError::new(path, 0, kind)
}

fn step_err(path: &str, msg: impl Into<String>) -> MeshError {
    err(path, MeshErrorKind::Step(msg.into()))
}

/// Reads and tessellates a STEP file (AP203, AP214, AP242 as CAD tools write them). `path` names
/// the file in errors and warnings. See the module docs.
pub fn read(path: &str, bytes: &[u8]) -> Result<StepMesh, MeshError> {
    read_with(path, bytes, Duration::from_secs(MAX_STEP_SECONDS))
}

/// [`read`] with a given meshing time budget (tests).
pub fn read_with(path: &str, bytes: &[u8], budget: Duration) -> Result<StepMesh, MeshError> {
    if bytes.len() > MAX_STEP_BYTES {
        return Err(step_err(path, format!("{} bytes, over the limit of {MAX_STEP_BYTES} bytes per STEP file", bytes.len())));
    }
    // Entity instances start with `#`; a bound on '#' bounds them (references too, so it is safe).
    let hashes = bytes.iter().filter(|b| **b == b'#').count();
    if hashes > MAX_STEP_ENTITIES * 8 {
        return Err(step_err(path, format!("more than {MAX_STEP_ENTITIES} entity instances, the limit per STEP file")));
    }
    let text = String::from_utf8_lossy(bytes);
    if !text.trim_start().starts_with("ISO-10303-21") {
        return Err(step_err(path, "not an ISO 10303-21 file (no \"ISO-10303-21;\" at the start)"));
    }
    let exchange = match catch_unwind(AssertUnwindSafe(|| ruststep::parser::parse(&text))) {
        Ok(Ok(x)) => x,
        Ok(Err(e)) => return Err(step_err(path, format!("syntax: {}", ir::clip(&e.to_string(), 300)))),
        Err(_) => return Err(step_err(path, "the STEP parser failed on this file")),
    };
    let Some(data) = exchange.data.first() else { return Err(step_err(path, "no DATA section")) };
    if data.entities.len() > MAX_STEP_ENTITIES {
        return Err(step_err(
            path,
            format!("{} entity instances, over the limit of {MAX_STEP_ENTITIES} per STEP file", data.entities.len()),
        ));
    }
    let file = Entities::new(&data.entities);
    let mut table = Table::default();
    let mut warnings = Vec::new();
    let mut skipped = 0usize;
    for e in &data.entities {
        match catch_unwind(AssertUnwindSafe(|| table.push_instance(e))) {
            Ok(Ok(())) => {}
            _ => skipped += 1,
        }
    }
    if skipped > 0 {
        warnings.push(format!("{skipped} entity instances could not be read as geometry and were skipped"));
    }
    let mut out = StepMesh { warnings, ..StepMesh::default() };
    let start = Instant::now();
    let solids = file.solids();
    if solids.is_empty() {
        return Err(step_err(path, "no solid or shell (MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS, SHELL_BASED_SURFACE_MODEL) in the file"));
    }
    let styles = file.styles();
    let mut placements_total = 0usize;
    for solid in &solids {
        let placements = file.placements(solid.rep, path)?;
        placements_total = placements_total.saturating_add(placements.len());
        if placements_total > MAX_PLACEMENTS {
            return Err(step_err(path, format!("more than {MAX_PLACEMENTS} placed solids, the limit per STEP file")));
        }
        let scale = file.length_scale(solid.rep).map_err(|e| step_err(path, e))?;
        let mut local = ir::Mesh::default();
        let mut local_colours: Vec<(std::ops::Range<usize>, [f64; 3])> = Vec::new();
        // The largest chordal deviation the solid's shells were meshed with (m).
        let mut chord = 0.0f64;
        for &(shell, flip) in &solid.shells {
            if start.elapsed() > budget {
                return Err(step_err(path, format!("meshing took longer than the limit of {} s per STEP file", budget.as_secs())));
            }
            let shell_colour = styles.of(shell).or_else(|| styles.of(solid.id));
            let mut sink = Sink { mesh: &mut local, colours: &mut local_colours, colour: shell_colour, styles: &styles };
            if let Some(t) = mesh_shell(&table, &file, path, solid, shell, flip, scale, &mut sink, &mut out) {
                chord = chord.max(t);
            }
            if local.triangles.len().saturating_mul(placements.len().max(1)) > super::MAX_TRIANGLES {
                return Err(err(path, MeshErrorKind::TooManyTriangles { max: super::MAX_TRIANGLES }));
            }
        }
        weld(&mut local, &mut local_colours);
        out.joined_corners += join_open_corners(&mut local, &mut local_colours, chord);
        out.t_junctions += close_t_junctions(&mut local, &mut local_colours, chord);
        for p in &placements {
            let first = out.mesh.triangles.len();
            let base = out.mesh.vertices.len() as u32;
            for v in &local.vertices {
                let q = p.transform_point(&Point3::new(v[0] as f64, v[1] as f64, v[2] as f64));
                out.mesh.vertices.push([q.x as f32, q.y as f32, q.z as f32]);
            }
            out.mesh.triangles.extend(local.triangles.iter().map(|t| [t[0] + base, t[1] + base, t[2] + base]));
            out.solids.push(first..out.mesh.triangles.len());
            for (r, c) in &local_colours {
                push_run(&mut out.colours, r.start + first..r.end + first, *c);
            }
            if out.mesh.triangles.len() > super::MAX_TRIANGLES {
                return Err(err(path, MeshErrorKind::TooManyTriangles { max: super::MAX_TRIANGLES }));
            }
        }
    }
    if start.elapsed() > budget {
        return Err(step_err(path, format!("meshing took longer than the limit of {} s per STEP file", budget.as_secs())));
    }
    out.colour = dominant_colour(&out.mesh, &out.colours);
    Ok(out)
}

/// Distance within which the corners of neighbouring faces are one vertex: far below the chordal
/// tolerance (0.025 mm at the finest), far above the rounding of a point evaluated on two faces'
/// surfaces.
const WELD_DISTANCE: f32 = 1e-7;

/// Joins the faces of a solid: the tessellator meshes each face with its own vertices, though
/// neighbouring faces take their shared edge's points from the same polyline (evaluated on each
/// face's surface, so equal up to rounding). Corners within [`WELD_DISTANCE`] become one vertex,
/// so a closed B-rep gives a closed mesh (collision shapes decompose it instead of taking its
/// hull); triangles left with two equal corners are dropped and the colour runs follow.
fn weld(mesh: &mut ir::Mesh, runs: &mut [(std::ops::Range<usize>, [f64; 3])]) {
    let cell = |v: &[f32; 3]| v.map(|x| (x / WELD_DISTANCE).floor() as i64);
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::with_capacity(mesh.vertices.len());
    let mut vertices: Vec<[f32; 3]> = Vec::with_capacity(mesh.vertices.len() / 2 + 1);
    let mut map: Vec<u32> = Vec::with_capacity(mesh.vertices.len());
    for v in &mesh.vertices {
        let c = cell(v);
        let found = near_in_grid(&grid, c, |k| {
            let w = vertices[k as usize];
            (0..3).all(|i| (w[i] - v[i]).abs() <= WELD_DISTANCE)
        });
        let k = found.unwrap_or_else(|| {
            vertices.push(*v);
            let k = vertices.len() as u32 - 1;
            grid.entry(c).or_default().push(k);
            k
        });
        map.push(k);
    }
    mesh.vertices = vertices;
    remap_corners(mesh, runs, |i| map.get(i as usize).copied().unwrap_or(0));
}

/// The first vertex of the grid cells around `c` (its own and the 26 next to it) that `hit`
/// accepts.
fn near_in_grid(grid: &HashMap<[i64; 3], Vec<u32>>, c: [i64; 3], mut hit: impl FnMut(u32) -> bool) -> Option<u32> {
    for dx in -1..=1 {
        for dy in -1..=1 {
            for dz in -1..=1 {
                for &k in grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]).map_or(&[][..], Vec::as_slice) {
                    if hit(k) {
                        return Some(k);
                    }
                }
            }
        }
    }
    None
}

/// Rebuilds the triangles, each replaced by those `emit` pushes for it (none, itself, or
/// pieces), and moves the colour runs with them.
fn rebuild_triangles(
    mesh: &mut ir::Mesh,
    runs: &mut [(std::ops::Range<usize>, [f64; 3])],
    mut emit: impl FnMut(usize, &[u32; 3], &mut Vec<[u32; 3]>),
) {
    // kept[k]: triangles made from the first k.
    let mut kept = Vec::with_capacity(mesh.triangles.len() + 1);
    kept.push(0usize);
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    for (ti, t) in mesh.triangles.iter().enumerate() {
        emit(ti, t, &mut triangles);
        kept.push(triangles.len());
    }
    for (r, _) in runs.iter_mut() {
        *r = kept[r.start.min(kept.len() - 1)]..kept[r.end.min(kept.len() - 1)];
    }
    mesh.triangles = triangles;
}

/// Every corner `i` becomes `to(i)`; triangles left with two equal corners are dropped.
fn remap_corners(mesh: &mut ir::Mesh, runs: &mut [(std::ops::Range<usize>, [f64; 3])], to: impl Fn(u32) -> u32) {
    rebuild_triangles(mesh, runs, |_, t, out| {
        let w = t.map(&to);
        if w[0] != w[1] && w[1] != w[2] && w[0] != w[2] {
            out.push(w);
        }
    });
}

/// The open edges of `mesh` (directed edges without their reverse): (triangle, corner where the
/// edge starts).
fn open_edges(mesh: &ir::Mesh) -> Vec<(usize, usize)> {
    let mut directed: HashSet<(u32, u32)> = HashSet::with_capacity(mesh.triangles.len() * 3);
    for t in &mesh.triangles {
        for k in 0..3 {
            directed.insert((t[k], t[(k + 1) % 3]));
        }
    }
    let mut open = Vec::new();
    for (ti, t) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            if !directed.contains(&(t[(k + 1) % 3], t[k])) {
                open.push((ti, k));
            }
        }
    }
    open
}

/// Vertex `i` of `mesh` in f64 (the origin for an index out of range).
fn point(mesh: &ir::Mesh, i: u32) -> Vector3<f64> {
    mesh.vertices.get(i as usize).map_or(Vector3::zeros(), |v| Vector3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2])))
}

/// Farthest apart two corners on the open edges of a solid's mesh may be and still be joined by
/// [`join_open_corners`]: the tessellator evaluates a shared edge's points on each face's own
/// surface, and on trimmed B-spline faces the two evaluations differ by up to a few µm (the
/// Onshape arm: 1–10 µm); below the finest chordal tolerance (25 µm), so no feature the
/// tessellation keeps is narrower.
const GAP_DISTANCE: f64 = 1e-5;

/// Joins the corners of open edges (directed edges without their reverse) that lie within
/// `min(GAP_DISTANCE, chord / 2)` of each other, the first in vertex order standing for the
/// others: the gaps [`weld`] leaves between neighbouring faces whose shared edge points were
/// evaluated a few µm apart. Corners inside a face's mesh are never moved. Triangles left with
/// two equal corners are dropped, the colour runs follow, unused vertices are removed. Returns
/// how many corners were joined to another.
pub(super) fn join_open_corners(mesh: &mut ir::Mesh, runs: &mut [(std::ops::Range<usize>, [f64; 3])], chord: f64) -> usize {
    let dist = GAP_DISTANCE.min(chord / 2.0);
    if dist <= 0.0 || !dist.is_finite() {
        return 0;
    }
    let mut open: Vec<u32> = open_edges(mesh)
        .into_iter()
        .flat_map(|(ti, k)| {
            let t = mesh.triangles[ti];
            [t[k], t[(k + 1) % 3]]
        })
        .collect();
    open.sort_unstable();
    open.dedup();
    let cell = |p: &Vector3<f64>| [p.x, p.y, p.z].map(|x| (x / dist).floor() as i64);
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::with_capacity(open.len());
    let mut map: HashMap<u32, u32> = HashMap::new();
    for &v in &open {
        let p = point(mesh, v);
        let c = cell(&p);
        match near_in_grid(&grid, c, |k| (point(mesh, k) - p).norm() <= dist) {
            Some(k) => {
                map.insert(v, k);
            }
            None => grid.entry(c).or_default().push(v),
        }
    }
    if map.is_empty() {
        return 0;
    }
    remap_corners(mesh, runs, |i| map.get(&i).copied().unwrap_or(i));
    // Keep the vertices still used, in their order.
    let mut used = vec![false; mesh.vertices.len()];
    for &i in mesh.triangles.iter().flatten() {
        if let Some(u) = used.get_mut(i as usize) {
            *u = true;
        }
    }
    let mut new_index = vec![u32::MAX; mesh.vertices.len()];
    let mut vertices = Vec::with_capacity(mesh.vertices.len());
    for (i, v) in mesh.vertices.iter().enumerate() {
        if used[i] {
            new_index[i] = vertices.len() as u32;
            vertices.push(*v);
        }
    }
    mesh.vertices = vertices;
    for t in &mut mesh.triangles {
        *t = t.map(|i| new_index[i as usize]);
    }
    map.len()
}

/// Most open edges times open-edge vertices [`close_t_junctions`] compares in one pass; a solid
/// with more keeps its T-junctions (its collision shape is then its hull, as before).
const MAX_JUNCTION_PAIRS: usize = 20_000_000;

/// Closes T-junctions: the tessellator samples an edge shared by two faces separately for each
/// face where the faces need different densities, so one face's corner lies on the other face's
/// triangle edge instead of being a corner of it, and the welded mesh stays open there. Each open
/// edge (a directed edge without its reverse) gets every open-edge vertex lying on it inserted:
/// within `chord` (the chordal deviation the solid was meshed with: one face's corner is on the
/// curve, the other face's chord up to that far from it) of the segment, strictly between its
/// ends, and with an open edge of its own along the segment (within about 37°); its triangle is
/// split into a fan from the opposite corner, keeping its winding. Repeated (a triangle with
/// several such edges) up to four passes. Returns how many vertices were inserted.
pub(super) fn close_t_junctions(mesh: &mut ir::Mesh, runs: &mut [(std::ops::Range<usize>, [f64; 3])], chord: f64) -> usize {
    let mut inserted = 0usize;
    for _pass in 0..4 {
        // The open edges, and the open-edge vertices with their open edges' directions.
        let open = open_edges(mesh);
        let mut dirs: HashMap<u32, Vec<Vector3<f64>>> = HashMap::new();
        for &(ti, k) in &open {
            let t = mesh.triangles[ti];
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let d = (point(mesh, b) - point(mesh, a)).normalize();
            dirs.entry(a).or_default().push(d);
            dirs.entry(b).or_default().push(d);
        }
        if open.is_empty() || open.len().saturating_mul(dirs.len()) > MAX_JUNCTION_PAIRS {
            break;
        }
        let mut verts: Vec<(u32, Vector3<f64>)> = dirs.keys().map(|&v| (v, point(mesh, v))).collect();
        verts.sort_by_key(|(v, _)| *v);
        // Per triangle: the first open edge with vertices on it, and those vertices in order.
        let mut splits: HashMap<usize, (usize, Vec<u32>)> = HashMap::new();
        for &(ti, k) in &open {
            if splits.contains_key(&ti) {
                continue;
            }
            let t = mesh.triangles[ti];
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let (pa, pb) = (point(mesh, a), point(mesh, b));
            let d = pb - pa;
            let len2 = d.norm_squared();
            if len2 <= 0.0 {
                continue;
            }
            let len = len2.sqrt();
            let mut on: Vec<(f64, u32)> = Vec::new();
            for &(v, pv) in &verts {
                if v == a || v == b {
                    continue;
                }
                let s = (pv - pa).dot(&d) / len2;
                if s * len <= 1e-6 || (1.0 - s) * len <= 1e-6 || (pv - pa - d * s).norm() > chord {
                    continue;
                }
                let along = dirs.get(&v).is_some_and(|ds| ds.iter().any(|e| e.dot(&d).abs() >= 0.8 * len));
                if along {
                    on.push((s, v));
                }
            }
            if !on.is_empty() {
                on.sort_by(|x, y| x.0.total_cmp(&y.0));
                splits.insert(ti, (k, on.into_iter().map(|(_, v)| v).collect()));
            }
        }
        if splits.is_empty() {
            break;
        }
        rebuild_triangles(mesh, runs, |ti, t, out| match splits.get(&ti) {
            Some((k, on)) => {
                let (a, b, c) = (t[*k], t[(k + 1) % 3], t[(k + 2) % 3]);
                let chain: Vec<u32> = std::iter::once(a).chain(on.iter().copied()).chain(std::iter::once(b)).collect();
                out.extend(chain.windows(2).map(|w| [w[0], w[1], c]));
                inserted += on.len();
            }
            None => out.push(*t),
        });
    }
    inserted
}

/// Appends a run of coloured triangles, merged with the last run when it continues it.
fn push_run(runs: &mut Vec<(std::ops::Range<usize>, [f64; 3])>, r: std::ops::Range<usize>, c: [f64; 3]) {
    if r.is_empty() {
        return;
    }
    if let Some((last, lc)) = runs.last_mut() {
        if last.end == r.start && *lc == c {
            last.end = r.end;
            return;
        }
    }
    runs.push((r, c));
}

/// The colour of the largest area of `mesh`, counting the uncoloured triangles as one more
/// candidate (`None` when they win or nothing is coloured).
fn dominant_colour(mesh: &ir::Mesh, runs: &[(std::ops::Range<usize>, [f64; 3])]) -> Option<[f64; 3]> {
    if runs.is_empty() {
        return None;
    }
    let area = |t: &[u32; 3]| {
        let p = t.map(|i| point(mesh, i));
        (p[1] - p[0]).cross(&(p[2] - p[0])).norm() / 2.0
    };
    let total: f64 = mesh.triangles.iter().map(area).sum();
    let mut by_colour: Vec<([f64; 3], f64)> = Vec::new();
    for (r, c) in runs {
        let a: f64 = mesh.triangles.get(r.clone()).unwrap_or_default().iter().map(area).sum();
        match by_colour.iter_mut().find(|(k, _)| k == c) {
            Some((_, s)) => *s += a,
            None => by_colour.push((*c, a)),
        }
    }
    let coloured: f64 = by_colour.iter().map(|(_, a)| a).sum();
    let (best, a) = by_colour.into_iter().fold(None::<([f64; 3], f64)>, |m, (c, a)| match m {
        Some((_, b)) if b >= a => m,
        _ => Some((c, a)),
    })?;
    (a >= total - coloured).then_some(best)
}

/// Where [`mesh_shell`] puts a shell's triangles: the solid's mesh, its colour runs, the colour
/// of the shell (its own style, else its solid's) and the file's styles for its faces.
struct Sink<'a> {
    mesh: &'a mut ir::Mesh,
    colours: &'a mut Vec<(std::ops::Range<usize>, [f64; 3])>,
    colour: Option<[f64; 3]>,
    styles: &'a Styles,
}

/// Meshes one shell into `local` (metres, the solid's representation frame).
#[allow(clippy::too_many_arguments)]
fn mesh_shell(
    table: &Table,
    file: &Entities,
    path: &str,
    solid: &Solid,
    shell: u64,
    flip: bool,
    scale: f64,
    sink: &mut Sink,
    out: &mut StepMesh,
) -> Option<f64> {
    let local = &mut *sink.mesh;
    let what = format!("shell #{shell} of {} #{}", solid.kind, solid.id);
    let Some(holder) = table.shell.get(&shell) else {
        out.warnings.push(format!("{path}: {what} is not a shell the geometry reader knows; the solid has no shape from it"));
        return None;
    };
    let face_ids = file.shell_faces(shell);
    let converted = catch_unwind(AssertUnwindSafe(|| table.to_compressed_shell(holder).map_err(|e| format!("{e:?}"))));
    let compressed = match converted {
        Ok(Ok(c)) => c,
        Ok(Err(e)) => {
            out.warnings.push(format!("{path}: {what} could not be converted ({}); the solid has no shape from it", ir::clip(&e, 200)));
            return None;
        }
        Err(_) => {
            out.warnings.push(format!("{path}: {what} made the B-rep reader fail; the solid has no shape from it"));
            return None;
        }
    };
    // `truck-stepio` leaves out, without a word, every face whose surface it cannot convert and
    // every boundary loop it cannot read: account for each here. Faces whose surface entity it
    // has no table for are the ones left out; the rest keep their order.
    let known: Vec<u64> = face_ids.iter().copied().filter(|f| file.face_surface(*f).is_some_and(|s| surface_known(table, s))).collect();
    for f in face_ids.iter().filter(|f| !known.contains(f)) {
        out.faces += 1;
        out.failed_faces += 1;
        out.warnings.push(format!(
            "{path}: face #{f} ({}) of {what} has a surface the B-rep reader does not support; the part's shape has a hole there",
            file.face_surface_kind(Some(*f))
        ));
    }
    let names: Vec<Option<u64>> = if compressed.faces.len() == known.len() {
        known.iter().map(|f| Some(*f)).collect()
    } else {
        let lost = known.len().saturating_sub(compressed.faces.len());
        out.faces += lost;
        out.failed_faces += lost;
        out.warnings.push(format!(
            "{path}: {lost} of the {} faces of {what} could not be converted; the part's shape has holes there",
            face_ids.len()
        ));
        vec![None; compressed.faces.len()]
    };
    for (face, id) in compressed.faces.iter().zip(&names) {
        let Some(id) = id else { continue };
        let bounds = file.face_bounds(*id);
        if face.boundaries.len() < bounds {
            out.warnings.push(format!(
                "{path}: face #{id} of {what}: {} of its {bounds} boundary loops could not be read; the face is meshed without them",
                bounds - face.boundaries.len()
            ));
        }
    }
    let mut compressed = compressed;
    // `cut` asserts on degenerate knot vectors: a panic leaves the shell's edges as read.
    let mut edges = compressed.edges.clone();
    match catch_unwind(AssertUnwindSafe(|| trim_unclamped_edges(&mut edges))) {
        Ok(n) => {
            out.trimmed_edges += n;
            compressed.edges = edges;
        }
        Err(_) => {
            out.warnings.push(format!("{path}: {what}: its periodic B-spline edges could not be cut to their domain; meshed as read"))
        }
    }
    let diag = bbox_diagonal(&compressed.vertices) * scale;
    let mut tol = CHORDAL_TOLERANCE.max(RELATIVE_TOLERANCE * diag);
    // Small round faces: a chord 0.05 mm off a 10 mm cylinder loses 0.7 % of its section;
    // bound the deviation by the smallest radius too (not below half the default: finer
    // costs seconds on parts with small holes).
    if let Some(r) = file.min_radius(&face_ids) {
        tol = tol.min((ANGULAR_TOLERANCE * r * scale).max(CHORDAL_TOLERANCE / 2.0));
    }
    let chord = tol;
    let tol = tol / scale;
    let meshed = catch_unwind(AssertUnwindSafe(|| compressed.robust_triangulation(tol)));
    let poly = match meshed {
        Ok(p) => p,
        Err(_) => {
            out.warnings.push(format!("{path}: {what} made the tessellator fail; the solid has no shape from it"));
            return None;
        }
    };
    for (k, face) in poly.faces.iter().enumerate() {
        out.faces += 1;
        let id = names.get(k).copied().flatten();
        let face_name = id.map(|id| format!("face #{id}")).unwrap_or_else(|| format!("face {} of the shell", k + 1));
        let Some(surface) = &face.surface else {
            out.failed_faces += 1;
            out.warnings.push(format!(
                "{path}: {face_name} ({}) of {what} could not be meshed; the part's shape has a hole there",
                file.face_surface_kind(id)
            ));
            continue;
        };
        let reverse = face.orientation == flip;
        let base = local.vertices.len() as u32;
        let positions = surface.positions();
        let mut bad = false;
        for p in positions {
            let v = [(p.x * scale) as f32, (p.y * scale) as f32, (p.z * scale) as f32];
            bad |= !v.iter().all(|x| x.is_finite());
            local.vertices.push(v);
        }
        if bad {
            local.vertices.truncate(base as usize);
            out.failed_faces += 1;
            out.warnings.push(format!("{path}: {face_name} of {what} meshed to non-finite points; left out"));
            continue;
        }
        let n = positions.len();
        let first = local.triangles.len();
        for tri in surface.faces().triangle_iter() {
            let idx = [tri[0].pos, tri[1].pos, tri[2].pos];
            if idx.iter().any(|&i| i >= n) {
                continue;
            }
            let t = idx.map(|i| base + i as u32);
            local.triangles.push(if reverse { [t[0], t[2], t[1]] } else { t });
        }
        let tris: Vec<[usize; 3]> = surface.faces().triangle_iter().map(|t| [t[0].pos, t[1].pos, t[2].pos]).collect();
        let ratio = boundary_ratio(positions, &tris, &face.boundaries, &poly.edges);
        if ratio < MIN_BOUNDARY_RATIO {
            out.suspect_faces += 1;
            out.warnings.push(format!(
                "{path}: {face_name} ({}) of {what} may be meshed over a hole it should have cut (its mesh's rim is {:.0} % of its boundary loops' length); the part's volume there is not faithful",
                file.face_surface_kind(id),
                ratio * 100.0
            ));
        }
        // The face's own colour (its entity, or the face an ORIENTED_FACE uses), else the shell's.
        let colour = id.and_then(|f| sink.styles.of(f).or_else(|| file.face_record_id(f).and_then(|g| sink.styles.of(g)))).or(sink.colour);
        if let Some(c) = colour {
            push_run(sink.colours, first..local.triangles.len(), c);
        }
    }
    Some(chord)
}

/// Restricts every B-spline edge curve with an unclamped knot vector (a periodic curve: Onshape
/// writes the closed intersection curve of two cylinders as `B_SPLINE_CURVE_WITH_KNOTS` with
/// single knots from -0.0068 on) to the domain where its basis functions sum to one,
/// `[t_p, t_(m-p)]` for degree p and knots t_0..t_m. `truck-stepio` keeps such a curve whole and
/// `truck-meshalgo` samples it over `[t_0, t_m]`, where the curve falls towards the origin: the
/// edge's polyline then starts and ends at (0, 0, 0), and both faces bounded by it lose the hole
/// it cuts (`Arm 011.step`, `Base.step`). Returns how many edges were trimmed.
fn trim_unclamped_edges(edges: &mut [truck_topology::compress::CompressedEdge<truck_stepio::r#in::alias::Curve3D>]) -> usize {
    use truck_meshalgo::rexport_polymesh::Cut;
    use truck_stepio::r#in::alias::Curve3D;
    let mut n = 0;
    for e in edges {
        let (p, first, lo, hi, last) = match &e.curve {
            Curve3D::BSplineCurve(c) => {
                let k = c.knot_vec();
                let (p, m) = (c.degree(), k.len() - 1);
                if m < 2 * p + 1 {
                    continue;
                }
                (p, k[0], k[p], k[m - p], k[m])
            }
            Curve3D::NurbsCurve(c) => {
                let k = c.knot_vec();
                let (p, m) = (c.degree(), k.len() - 1);
                if m < 2 * p + 1 {
                    continue;
                }
                (p, k[0], k[p], k[m - p], k[m])
            }
            _ => continue,
        };
        if p == 0 || lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) || (first >= lo && last <= hi) {
            continue;
        }
        match &mut e.curve {
            Curve3D::BSplineCurve(c) => {
                let mut mid = if first < lo { c.cut(lo) } else { c.clone() };
                if last > hi {
                    mid.cut(hi);
                }
                *c = mid;
            }
            Curve3D::NurbsCurve(c) => {
                let mut mid = if first < lo { c.cut(lo) } else { c.clone() };
                if last > hi {
                    mid.cut(hi);
                }
                *c = mid;
            }
            _ => continue,
        }
        n += 1;
    }
    n
}

type MeshedEdge =
    truck_topology::compress::CompressedEdge<truck_meshalgo::rexport_polymesh::PolylineCurve<truck_meshalgo::rexport_polymesh::Point3>>;

/// The length of a face's boundary in its mesh (triangle edges used once) over the length of its
/// B-rep boundary loops (the edges' polylines, shared with the neighbouring faces). A face
/// meshed over a hole it should have cut (seen in `truck-meshalgo` on trimmed B-spline and
/// cylinder faces with inner loops) lacks the hole's rim: the ratio falls below one.
fn boundary_ratio(
    p: &[truck_meshalgo::rexport_polymesh::Point3],
    triangles: &[[usize; 3]],
    loops: &[Vec<truck_topology::compress::CompressedEdgeIndex>],
    edges: &[MeshedEdge],
) -> f64 {
    // Vertices welded by position (a periodic surface's mesh repeats its seam's vertices), to
    // 1e-9 of the face's size.
    let size = p.iter().flat_map(|q| [q.x.abs(), q.y.abs(), q.z.abs()]).fold(0.0f64, f64::max).max(1e-300);
    let mut ids: HashMap<[i64; 3], usize> = HashMap::new();
    let welded: Vec<usize> = p
        .iter()
        .map(|q| {
            let k = [q.x, q.y, q.z].map(|x| (x / size * 1e9).round() as i64);
            let n = ids.len();
            *ids.entry(k).or_insert(n)
        })
        .collect();
    let mut count: HashMap<(usize, usize), (u32, usize, usize)> = HashMap::new();
    for t in triangles {
        for k in 0..3 {
            let (i, j) = (t[k], t[(k + 1) % 3]);
            let (Some(&a), Some(&b)) = (welded.get(i), welded.get(j)) else { continue };
            if a != b {
                count.entry((a.min(b), a.max(b))).or_insert((0, i, j)).0 += 1;
            }
        }
    }
    let dist = |a: &truck_meshalgo::rexport_polymesh::Point3, b: &truck_meshalgo::rexport_polymesh::Point3| {
        ((a.x - b.x).powi(2) + (a.y - b.y).powi(2) + (a.z - b.z).powi(2)).sqrt()
    };
    let mesh_len: f64 = count.values().filter(|(n, _, _)| *n == 1).filter_map(|(_, a, b)| Some(dist(p.get(*a)?, p.get(*b)?))).sum();
    // A seam edge (used twice by the face's loops) is inside the welded mesh: not counted.
    let mut uses: HashMap<usize, u32> = HashMap::new();
    for e in loops.iter().flatten() {
        *uses.entry(e.index).or_default() += 1;
    }
    let brep_len: f64 = uses
        .iter()
        .filter(|(_, n)| **n == 1)
        .filter_map(|(i, _)| edges.get(*i))
        .map(|e| e.curve.0.windows(2).map(|w| dist(&w[0], &w[1])).sum::<f64>())
        .sum();
    if brep_len > 0.0 {
        mesh_len / brep_len
    } else {
        1.0
    }
}

/// Whether `truck-stepio` read entity `id` as a surface it converts.
fn surface_known(t: &Table, id: u64) -> bool {
    t.plane.contains_key(&id)
        || t.spherical_surface.contains_key(&id)
        || t.cylindrical_surface.contains_key(&id)
        || t.toroidal_surface.contains_key(&id)
        || t.conical_surface.contains_key(&id)
        || t.b_spline_surface_with_knots.contains_key(&id)
        || t.uniform_surface.contains_key(&id)
        || t.quasi_uniform_surface.contains_key(&id)
        || t.bezier_surface.contains_key(&id)
        || t.rational_b_spline_surface.contains_key(&id)
        || t.surface_of_linear_extrusion.contains_key(&id)
        || t.surface_of_revolution.contains_key(&id)
}

fn bbox_diagonal(points: &[truck_meshalgo::rexport_polymesh::Point3]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let d = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    if d.is_finite() {
        d
    } else {
        0.0
    }
}

/// A solid (or surface model) and the representation that holds it.
struct Solid {
    id: u64,
    kind: String,
    /// Representation whose items include the solid (its context gives the unit).
    rep: u64,
    /// Shells, with `true` for a shell used reversed (a void of `BREP_WITH_VOIDS`).
    shells: Vec<(u64, bool)>,
}

/// The entity records by id, and the relations between representations.
struct Entities<'a> {
    by_id: HashMap<u64, &'a EntityInstance>,
    /// Representation -> (parent representation, child-to-parent placement in metres).
    parents: HashMap<u64, Vec<(u64, Edge)>>,
}

/// How a representation sits in another.
#[derive(Clone, Copy)]
enum Edge {
    Identity,
    /// Placement axes: `from` in the child's context, `to` in the parent's.
    Axes {
        from: u64,
        to: u64,
    },
}

fn params(r: &Record) -> &[Parameter] {
    match &r.parameter {
        Parameter::List(v) => v,
        p => std::slice::from_ref(p),
    }
}

fn as_ref(p: &Parameter) -> Option<u64> {
    match p {
        Parameter::Ref(ruststep::ast::Name::Entity(id)) => Some(*id),
        _ => None,
    }
}

fn as_refs(p: &Parameter) -> Vec<u64> {
    match p {
        Parameter::List(v) => v.iter().filter_map(as_ref).collect(),
        p => as_ref(p).into_iter().collect(),
    }
}

fn as_real(p: &Parameter) -> Option<f64> {
    match p {
        Parameter::Real(x) => Some(*x),
        Parameter::Integer(i) => Some(*i as f64),
        Parameter::Typed { parameter, .. } => as_real(parameter),
        _ => None,
    }
}

fn records(e: &EntityInstance) -> &[Record] {
    match e {
        EntityInstance::Simple { record, .. } => std::slice::from_ref(record),
        EntityInstance::Complex { subsuper, .. } => &subsuper.0,
    }
}

fn instance_id(e: &EntityInstance) -> u64 {
    match e {
        EntityInstance::Simple { id, .. } | EntityInstance::Complex { id, .. } => *id,
    }
}

fn is_representation(name: &str) -> bool {
    name.ends_with("REPRESENTATION") && !name.ends_with("PROPERTY_DEFINITION_REPRESENTATION") && name != "DEFINITIONAL_REPRESENTATION"
}

impl<'a> Entities<'a> {
    fn new(entities: &'a [EntityInstance]) -> Self {
        let by_id: HashMap<u64, &EntityInstance> = entities.iter().map(|e| (instance_id(e), e)).collect();
        let mut parents: HashMap<u64, Vec<(u64, Edge)>> = HashMap::new();
        for e in entities {
            let recs = records(e);
            let rel = recs.iter().find(|r| r.name == "REPRESENTATION_RELATIONSHIP" || r.name == "SHAPE_REPRESENTATION_RELATIONSHIP");
            let with = recs.iter().find(|r| r.name == "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
            if let Some(rel) = rel {
                let p = params(rel);
                let (Some(r1), Some(r2)) = (p.get(2).and_then(as_ref), p.get(3).and_then(as_ref)) else { continue };
                match with.and_then(|w| params(w).first().and_then(as_ref)) {
                    Some(t) => {
                        // ITEM_DEFINED_TRANSFORMATION(name, description, item_1, item_2): rep_1
                        // (the component) placed in rep_2 so that item_1 lands on item_2.
                        let Some(idt) = by_id.get(&t).and_then(|e| records(e).iter().find(|r| r.name == "ITEM_DEFINED_TRANSFORMATION"))
                        else {
                            continue;
                        };
                        let q = params(idt);
                        if let (Some(a), Some(b)) = (q.get(2).and_then(as_ref), q.get(3).and_then(as_ref)) {
                            parents.entry(r1).or_default().push((r2, Edge::Axes { from: a, to: b }));
                        }
                    }
                    None if with.is_none() => {
                        // A plain relationship (a part's shape representation and its B-rep):
                        // the same coordinates, either way round.
                        parents.entry(r2).or_default().push((r1, Edge::Identity));
                        parents.entry(r1).or_default().push((r2, Edge::Identity));
                    }
                    None => {}
                }
            }
        }
        // MAPPED_ITEM(name, REPRESENTATION_MAP(origin, mapped_rep), target) in a representation's
        // items places mapped_rep in that representation.
        for e in entities {
            for r in records(e) {
                if !is_representation(&r.name) {
                    continue;
                }
                let p = params(r);
                for item in p.get(1).map(as_refs).unwrap_or_default() {
                    let Some(mi) = by_id.get(&item).and_then(|e| records(e).iter().find(|r| r.name == "MAPPED_ITEM")) else { continue };
                    let q = params(mi);
                    let (Some(map), Some(target)) = (q.get(1).and_then(as_ref), q.get(2).and_then(as_ref)) else { continue };
                    let Some(rm) = by_id.get(&map).and_then(|e| records(e).iter().find(|r| r.name == "REPRESENTATION_MAP")) else {
                        continue;
                    };
                    let m = params(rm);
                    if let (Some(origin), Some(mapped)) = (m.first().and_then(as_ref), m.get(1).and_then(as_ref)) {
                        parents.entry(mapped).or_default().push((instance_id(e), Edge::Axes { from: origin, to: target }));
                    }
                }
            }
        }
        Entities { by_id, parents }
    }

    fn record(&self, id: u64, name: &str) -> Option<&'a Record> {
        self.by_id.get(&id).and_then(|e| records(e).iter().find(|r| r.name == name))
    }

    /// Every solid and surface model in a representation's items.
    fn solids(&self) -> Vec<Solid> {
        let mut out = Vec::new();
        let mut seen = HashSet::new();
        let mut ids: Vec<u64> = self.by_id.keys().copied().collect();
        ids.sort_unstable();
        for rep in ids {
            let Some(r) = records(self.by_id[&rep]).iter().find(|r| is_representation(&r.name)) else { continue };
            for item in params(r).get(1).map(as_refs).unwrap_or_default() {
                let Some(e) = self.by_id.get(&item) else { continue };
                let Some(rec) = records(e).first() else { continue };
                let p = params(rec);
                let shells: Vec<(u64, bool)> = match rec.name.as_str() {
                    "MANIFOLD_SOLID_BREP" => p.get(1).and_then(as_ref).map(|s| self.shell_ref(s)).into_iter().collect(),
                    "BREP_WITH_VOIDS" => {
                        let mut v: Vec<(u64, bool)> = p.get(1).and_then(as_ref).map(|s| self.shell_ref(s)).into_iter().collect();
                        v.extend(p.get(2).map(as_refs).unwrap_or_default().into_iter().map(|s| self.shell_ref(s)));
                        v
                    }
                    "SHELL_BASED_SURFACE_MODEL" => {
                        p.get(1).map(as_refs).unwrap_or_default().into_iter().map(|s| self.shell_ref(s)).collect()
                    }
                    _ => continue,
                };
                if seen.insert((rep, item)) {
                    out.push(Solid { id: item, kind: rec.name.clone(), rep, shells });
                }
            }
        }
        out
    }

    /// A shell id, through `ORIENTED_CLOSED_SHELL` (reversed when its orientation is `.F.`).
    fn shell_ref(&self, id: u64) -> (u64, bool) {
        // ORIENTED_CLOSED_SHELL(name, *, closed_shell_element, orientation).
        if let Some(r) = self.record(id, "ORIENTED_CLOSED_SHELL") {
            let p = params(r);
            if let Some(inner) = p.iter().find_map(as_ref) {
                let reversed = matches!(p.last(), Some(Parameter::Enumeration(s)) if s.trim_matches('.') == "F");
                return (inner, reversed);
            }
        }
        (id, false)
    }

    /// The face entity ids of a shell, in the order `truck-stepio` converts them.
    fn shell_faces(&self, shell: u64) -> Vec<u64> {
        self.by_id.get(&shell).and_then(|e| records(e).first()).and_then(|r| params(r).get(1).map(as_refs)).unwrap_or_default()
    }

    /// A face entity's record, through `ORIENTED_FACE`.
    fn face_record(&self, face: u64) -> Option<&'a Record> {
        let rec = self.by_id.get(&face).and_then(|e| records(e).first())?;
        if rec.name == "ORIENTED_FACE" {
            let inner = params(rec).get(2).and_then(as_ref)?;
            return self.by_id.get(&inner).and_then(|e| records(e).first());
        }
        Some(rec)
    }

    /// The face an `ORIENTED_FACE` uses (`None` for any other entity).
    fn face_record_id(&self, face: u64) -> Option<u64> {
        params(self.record(face, "ORIENTED_FACE")?).get(2).and_then(as_ref)
    }

    /// The surface entity of a face (`ADVANCED_FACE(name, bounds, surface, same_sense)`).
    fn face_surface(&self, face: u64) -> Option<u64> {
        params(self.face_record(face)?).get(2).and_then(as_ref)
    }

    /// The smallest radius (file units) of the cylinders, spheres and tori the faces lie on.
    fn min_radius(&self, faces: &[u64]) -> Option<f64> {
        let mut min: Option<f64> = None;
        for f in faces {
            let Some(s) = self.face_surface(*f) else { continue };
            let Some(rec) = self.by_id.get(&s).and_then(|e| records(e).first()) else { continue };
            let p = params(rec);
            let r = match rec.name.as_str() {
                "CYLINDRICAL_SURFACE" | "SPHERICAL_SURFACE" => p.get(2).and_then(as_real),
                "TOROIDAL_SURFACE" => p.get(3).and_then(as_real),
                _ => None,
            };
            if let Some(r) = r.filter(|r| r.is_finite() && *r > 0.0) {
                min = Some(min.map_or(r, |m: f64| m.min(r)));
            }
        }
        min
    }

    /// How many boundary loops a face names.
    fn face_bounds(&self, face: u64) -> usize {
        self.face_record(face).and_then(|r| params(r).get(1).map(|b| as_refs(b).len())).unwrap_or(0)
    }

    /// The surface entity name of a face, for warnings.
    fn face_surface_kind(&self, face: Option<u64>) -> String {
        let Some(face) = face else { return "unknown surface".into() };
        match self.face_surface(face).and_then(|s| self.by_id.get(&s)) {
            Some(e) => records(e).iter().map(|r| r.name.as_str()).collect::<Vec<_>>().join(" "),
            None => "unknown surface".into(),
        }
    }

    /// Metres per length unit of a representation's context: an error naming the context when it
    /// states no length unit or one we do not know (a guess would scale the part silently).
    fn length_scale(&self, rep: u64) -> Result<f64, String> {
        let ctx = self
            .by_id
            .get(&rep)
            .and_then(|e| records(e).iter().find(|r| is_representation(&r.name)))
            .and_then(|r| params(r).get(2).and_then(as_ref));
        let Some(ctx) = ctx else { return Err(format!("representation #{rep} names no context")) };
        let units = self.record(ctx, "GLOBAL_UNIT_ASSIGNED_CONTEXT").map(|r| params(r).first().map(as_refs).unwrap_or_default());
        for u in units.unwrap_or_default() {
            if self.record(u, "LENGTH_UNIT").is_some() {
                return self.unit_scale(u, 0).ok_or_else(|| format!("length unit #{u} of context #{ctx} is not one we know"));
            }
        }
        Err(format!("context #{ctx} (of representation #{rep}) states no length unit"))
    }

    /// Metres per unit for a `LENGTH_UNIT` entity; `None` for other units.
    fn unit_scale(&self, id: u64, depth: usize) -> Option<f64> {
        if depth > 8 {
            return None;
        }
        self.record(id, "LENGTH_UNIT")?;
        if let Some(si) = self.record(id, "SI_UNIT") {
            let p = params(si);
            let prefix = match p.first() {
                Some(Parameter::Enumeration(s)) => s.trim_matches('.').to_ascii_uppercase(),
                _ => String::new(),
            };
            let f = match prefix.as_str() {
                "" => 1.0,
                "MILLI" => 1e-3,
                "CENTI" => 1e-2,
                "DECI" => 1e-1,
                "MICRO" => 1e-6,
                "NANO" => 1e-9,
                "KILO" => 1e3,
                _ => return None,
            };
            return Some(f);
        }
        let cbu = self.record(id, "CONVERSION_BASED_UNIT")?;
        let m = params(cbu).get(1).and_then(as_ref)?;
        let mwu = self.by_id.get(&m).and_then(|e| records(e).iter().find(|r| r.name.ends_with("MEASURE_WITH_UNIT")))?;
        let q = params(mwu);
        let value = q.first().and_then(as_real)?;
        let base = self.unit_scale(q.get(1).and_then(as_ref)?, depth + 1)?;
        let s = value * base;
        (s.is_finite() && s > 0.0).then_some(s)
    }

    /// An `AXIS2_PLACEMENT_3D` as an isometry, its location scaled by `scale`.
    fn axes(&self, id: u64, scale: f64) -> Option<Isometry3<f64>> {
        let r = self.record(id, "AXIS2_PLACEMENT_3D")?;
        let p = params(r);
        let loc = self.point(p.get(1).and_then(as_ref)?)? * scale;
        let z = p.get(2).and_then(as_ref).and_then(|d| self.direction(d)).unwrap_or_else(Vector3::z);
        let xr = p.get(3).and_then(as_ref).and_then(|d| self.direction(d)).unwrap_or_else(Vector3::x);
        let z = z.try_normalize(1e-12)?;
        let x = (xr - z * xr.dot(&z)).try_normalize(1e-12).or_else(|| {
            let a = if z.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
            (a - z * a.dot(&z)).try_normalize(1e-12)
        })?;
        let y = z.cross(&x);
        let rot = Rotation3::from_basis_unchecked(&[x, y, z]);
        Some(Isometry3::from_parts(Translation3::from(loc), UnitQuaternion::from_rotation_matrix(&rot)))
    }

    fn point(&self, id: u64) -> Option<Vector3<f64>> {
        let r = self.record(id, "CARTESIAN_POINT")?;
        let c: Vec<f64> = match params(r).get(1)? {
            Parameter::List(v) => v.iter().filter_map(as_real).collect(),
            _ => return None,
        };
        let v = Vector3::new(*c.first()?, c.get(1).copied().unwrap_or(0.0), c.get(2).copied().unwrap_or(0.0));
        v.iter().all(|x| x.is_finite()).then_some(v)
    }

    fn direction(&self, id: u64) -> Option<Vector3<f64>> {
        let r = self.record(id, "DIRECTION")?;
        let c: Vec<f64> = match params(r).get(1)? {
            Parameter::List(v) => v.iter().filter_map(as_real).collect(),
            _ => return None,
        };
        let v = Vector3::new(*c.first()?, c.get(1).copied().unwrap_or(0.0), c.get(2).copied().unwrap_or(0.0));
        v.iter().all(|x| x.is_finite()).then_some(v)
    }

    /// Every placement of representation `rep` in the file's root representations (metres):
    /// one per path up the assembly graph; the identity when it is itself a root.
    fn placements(&self, rep: u64, path: &str) -> Result<Vec<Isometry3<f64>>, MeshError> {
        let mut out = Vec::new();
        let mut stack = vec![(rep, Isometry3::identity(), vec![rep])];
        while let Some((r, pose, trail)) = stack.pop() {
            let ups: Vec<&(u64, Edge)> =
                self.parents.get(&r).map(|v| v.iter().filter(|(p, _)| !trail.contains(p)).collect()).unwrap_or_default();
            if ups.is_empty() || trail.len() > MAX_DEPTH {
                out.push(pose);
                if out.len() > MAX_PLACEMENTS {
                    return Err(step_err(path, format!("more than {MAX_PLACEMENTS} placed solids, the limit per STEP file")));
                }
                continue;
            }
            for (parent, edge) in ups {
                let step = match *edge {
                    Edge::Identity => Isometry3::identity(),
                    Edge::Axes { from, to } => {
                        let child = self.length_scale(r).map_err(|e| step_err(path, e))?;
                        let up = self.length_scale(*parent).map_err(|e| step_err(path, e))?;
                        let (Some(a), Some(b)) = (self.axes(from, child), self.axes(to, up)) else {
                            return Err(step_err(path, format!("placement #{from} or #{to} is not an AXIS2_PLACEMENT_3D we can read")));
                        };
                        b * a.inverse()
                    }
                };
                let mut t = trail.clone();
                t.push(*parent);
                stack.push((*parent, step * pose, t));
                if stack.len() > MAX_PLACEMENTS {
                    return Err(step_err(path, format!("more than {MAX_PLACEMENTS} placed solids, the limit per STEP file")));
                }
            }
        }
        // Identity links make the same placement reachable twice (B-rep <-> shape representation
        // <-> assembly); keep distinct placements.
        let mut distinct: Vec<Isometry3<f64>> = Vec::new();
        for p in out {
            if !distinct
                .iter()
                .any(|q| (q.translation.vector - p.translation.vector).norm() < 1e-12 && q.rotation.angle_to(&p.rotation) < 1e-12)
            {
                distinct.push(p);
            }
        }
        Ok(distinct)
    }

    /// Every surface colour styled onto an item of the file (see [`Styles`]).
    fn styles(&self) -> Styles {
        let mut out = Styles::default();
        let mut ids: Vec<u64> = self.by_id.keys().copied().collect();
        ids.sort_unstable();
        for id in ids {
            for r in records(self.by_id[&id]) {
                // STYLED_ITEM(name, styles, item); its subtypes OVER_RIDING_STYLED_ITEM(..,
                // over_ridden_style) and CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM(.., style_context).
                let rank = match r.name.as_str() {
                    "STYLED_ITEM" => 0,
                    "OVER_RIDING_STYLED_ITEM" | "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM" => 1,
                    _ => continue,
                };
                let p = params(r);
                let Some(item) = p.get(2).and_then(as_ref) else { continue };
                let Some(c) = p.get(1).map(as_refs).unwrap_or_default().into_iter().find_map(|s| self.assignment_colour(s)) else {
                    continue;
                };
                match out.by_item.get(&item) {
                    Some((r0, _)) if *r0 > rank => {}
                    // The same rank twice: the first in file order stays.
                    Some((r0, _)) if *r0 == rank => {}
                    _ => {
                        out.by_item.insert(item, (rank, c));
                    }
                }
            }
        }
        out
    }

    /// The surface colour of a `PRESENTATION_STYLE_ASSIGNMENT` (or `PRESENTATION_STYLE_BY_CONTEXT`):
    /// `SURFACE_STYLE_USAGE(side, SURFACE_SIDE_STYLE(name, (SURFACE_STYLE_FILL_AREA(
    /// FILL_AREA_STYLE(name, (FILL_AREA_STYLE_COLOUR(name, colour)))), ...)))`, or a
    /// `SURFACE_STYLE_RENDERING(method, colour)` among the side style's elements (AP242). Curve
    /// and point styles (edge colours) are not surface colours and are not taken.
    fn assignment_colour(&self, psa: u64) -> Option<[f64; 3]> {
        let rec = self.record(psa, "PRESENTATION_STYLE_ASSIGNMENT").or_else(|| self.record(psa, "PRESENTATION_STYLE_BY_CONTEXT"))?;
        for style in params(rec).first().map(as_refs).unwrap_or_default() {
            let Some(usage) = self.record(style, "SURFACE_STYLE_USAGE") else { continue };
            let Some(side) = params(usage).get(1).and_then(as_ref).and_then(|s| self.record(s, "SURFACE_SIDE_STYLE")) else { continue };
            for element in params(side).get(1).map(as_refs).unwrap_or_default() {
                let colour = if let Some(fill) = self.record(element, "SURFACE_STYLE_FILL_AREA") {
                    params(fill)
                        .first()
                        .and_then(as_ref)
                        .and_then(|f| self.record(f, "FILL_AREA_STYLE"))
                        .map(|f| params(f).get(1).map(as_refs).unwrap_or_default())
                        .unwrap_or_default()
                        .into_iter()
                        .filter_map(|c| self.record(c, "FILL_AREA_STYLE_COLOUR"))
                        .find_map(|c| params(c).get(1).and_then(as_ref).and_then(|c| self.colour_value(c)))
                } else {
                    let rendering = self
                        .record(element, "SURFACE_STYLE_RENDERING")
                        .or_else(|| self.record(element, "SURFACE_STYLE_RENDERING_WITH_PROPERTIES"));
                    rendering.and_then(|r| params(r).get(1).and_then(as_ref)).and_then(|c| self.colour_value(c))
                };
                if colour.is_some() {
                    return colour;
                }
            }
        }
        None
    }

    /// A `COLOUR_RGB` (components clamped to 0..1), or a `DRAUGHTING_PRE_DEFINED_COLOUR` by
    /// name (ISO 10303-46's eight: red, green, blue, yellow, magenta, cyan, black, white).
    fn colour_value(&self, id: u64) -> Option<[f64; 3]> {
        if let Some(r) = self.record(id, "COLOUR_RGB") {
            let q = params(r);
            let c = [1, 2, 3].map(|k| q.get(k).and_then(as_real).unwrap_or(f64::NAN));
            return c.iter().all(|x| x.is_finite()).then(|| c.map(|x| x.clamp(0.0, 1.0)));
        }
        let r = self.record(id, "DRAUGHTING_PRE_DEFINED_COLOUR")?;
        let Some(Parameter::String(name)) = params(r).first() else { return None };
        Some(match name.trim().trim_matches('\'').to_ascii_lowercase().as_str() {
            "red" => [1.0, 0.0, 0.0],
            "green" => [0.0, 1.0, 0.0],
            "blue" => [0.0, 0.0, 1.0],
            "yellow" => [1.0, 1.0, 0.0],
            "magenta" => [1.0, 0.0, 1.0],
            "cyan" => [0.0, 1.0, 1.0],
            "black" => [0.0, 0.0, 0.0],
            "white" => [1.0, 1.0, 1.0],
            _ => return None,
        })
    }
}

/// The surface colours styled onto a file's items (solids, shells, faces), by item entity: an
/// `OVER_RIDING_STYLED_ITEM` (Onshape, SolidWorks: a face coloured apart from its part) before a
/// plain `STYLED_ITEM`, else the first in file order. Which presentation representation lists
/// the styled item (`MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION`, a
/// `DRAUGHTING_MODEL`) does not matter: every styled item of the file is taken.
#[derive(Default)]
struct Styles {
    by_item: HashMap<u64, (u8, [f64; 3])>,
}

impl Styles {
    fn of(&self, item: u64) -> Option<[f64; 3]> {
        self.by_item.get(&item).map(|(_, c)| *c)
    }
}

/// Bumped whenever [`read`] changes what it returns for the same bytes (the crates' versions,
/// the tolerances), so a cache never serves meshes of another algorithm.
const ALGORITHM: &[u8] = b"cad2mo STEP mesh v1 truck-stepio 0.3 truck-meshalgo 0.4";

/// SHA-256 of a STEP file's bytes and of everything [`read`] depends on besides them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StepKey(pub [u8; 32]);

impl StepKey {
    pub fn of(bytes: &[u8]) -> StepKey {
        use sha2::{Digest, Sha256};
        let mut h = Sha256::new();
        h.update(ALGORITHM);
        for x in [CHORDAL_TOLERANCE, RELATIVE_TOLERANCE] {
            h.update(x.to_bits().to_le_bytes());
        }
        for n in [MAX_STEP_BYTES, MAX_STEP_ENTITIES, MAX_PLACEMENTS, super::MAX_TRIANGLES] {
            h.update((n as u64).to_le_bytes());
        }
        h.update((bytes.len() as u64).to_le_bytes());
        h.update(bytes);
        StepKey(h.finalize().into())
    }
}

/// Where STEP tessellations are kept between conversions, by [`StepKey`] (the file's content):
/// a re-export or a new CAD version with unchanged parts is not meshed again. Implementations
/// return exactly what was put under a key, or nothing. Only successful reads are kept.
pub trait StepCache: Send + Sync + std::fmt::Debug {
    fn get(&self, key: &StepKey) -> Option<std::sync::Arc<StepMesh>>;
    fn put(&self, key: StepKey, mesh: std::sync::Arc<StepMesh>);
}

/// A bounded in-memory LRU of STEP meshes by approximate size, one per process.
#[derive(Debug)]
pub struct MemoryStepCache {
    max_bytes: usize,
    lru: std::sync::Mutex<StepLru>,
}

#[derive(Debug, Default)]
struct StepLru {
    map: HashMap<StepKey, (std::sync::Arc<StepMesh>, usize, u64)>,
    order: std::collections::BTreeMap<u64, StepKey>,
    bytes: usize,
    clock: u64,
    hits: u64,
    misses: u64,
}

/// The default budget of [`MemoryStepCache`]: 256 MB.
pub const DEFAULT_STEP_CACHE_BYTES: usize = 256 << 20;

impl Default for MemoryStepCache {
    fn default() -> Self {
        MemoryStepCache::new(DEFAULT_STEP_CACHE_BYTES)
    }
}

fn step_mesh_bytes(m: &StepMesh) -> usize {
    std::mem::size_of::<StepMesh>()
        + m.mesh.vertices.capacity() * 12
        + m.mesh.triangles.capacity() * 12
        + m.solids.capacity() * 16
        + m.warnings.iter().map(|w| w.capacity() + 24).sum::<usize>()
}

impl MemoryStepCache {
    /// A cache holding at most about `max_bytes` of meshes (0: holds nothing).
    pub fn new(max_bytes: usize) -> MemoryStepCache {
        MemoryStepCache { max_bytes, lru: std::sync::Mutex::new(StepLru::default()) }
    }

    /// (hits, misses, entries, bytes) since it was made.
    pub fn stats(&self) -> (u64, u64, usize, usize) {
        let l = self.lru.lock().unwrap_or_else(|p| p.into_inner());
        (l.hits, l.misses, l.map.len(), l.bytes)
    }
}

impl StepCache for MemoryStepCache {
    fn get(&self, key: &StepKey) -> Option<std::sync::Arc<StepMesh>> {
        // Every update completes before anything can panic: a poisoned lock is consistent.
        let mut l = self.lru.lock().unwrap_or_else(|p| p.into_inner());
        l.clock += 1;
        let now = l.clock;
        let Some(entry) = l.map.get_mut(key) else {
            l.misses += 1;
            return None;
        };
        let old = std::mem::replace(&mut entry.2, now);
        let mesh = entry.0.clone();
        l.order.remove(&old);
        l.order.insert(now, *key);
        l.hits += 1;
        Some(mesh)
    }

    fn put(&self, key: StepKey, mesh: std::sync::Arc<StepMesh>) {
        let bytes = step_mesh_bytes(&mesh);
        if bytes > self.max_bytes {
            return;
        }
        let mut l = self.lru.lock().unwrap_or_else(|p| p.into_inner());
        l.clock += 1;
        let now = l.clock;
        if let Some((_, b, used)) = l.map.remove(&key) {
            l.order.remove(&used);
            l.bytes -= b;
        }
        while l.bytes + bytes > self.max_bytes {
            let Some((_, oldest)) = l.order.pop_first() else { break };
            if let Some((_, b, _)) = l.map.remove(&oldest) {
                l.bytes -= b;
            }
        }
        l.map.insert(key, (mesh, bytes, now));
        l.order.insert(now, key);
        l.bytes += bytes;
    }
}
