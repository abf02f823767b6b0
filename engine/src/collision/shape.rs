//! A body's collision shape from its CAD mesh: a primitive (box, cylinder, sphere, capsule) where
//! one fits, else the convex hull, else (hull much bigger than the mesh) a convex decomposition.

use std::collections::HashMap;
use std::f64::consts::PI;

use nalgebra::{Matrix3, Matrix4, Point3, SymmetricEigen, Vector3, Vector4};
use parry3d_f64::transformation::try_convex_hull;
use parry3d_f64::transformation::vhacd::{VHACDParameters, VHACD};

use super::ConvexPart;
use crate::pipeline::ir::Mesh;

type P3 = Point3<f64>;
type V3 = Vector3<f64>;

/// Thresholds of [`body_shape`]. The defaults are the values named in each field's doc.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeOptions {
    /// A primitive is used when its fit error is at most
    /// `max(primitive_abs_tolerance, primitive_rel_tolerance × bounding-box diagonal)`
    /// (defaults 1 mm and 2 %) ...
    pub primitive_abs_tolerance: f64,
    pub primitive_rel_tolerance: f64,
    /// ... and its volume ratio lies within `[1 / (1 + v), 1 + v]`, v = this (default 0.15).
    pub primitive_volume_tolerance: f64,
    /// Hull volume / mesh volume above this (default 1.25) → convex decomposition (closed meshes).
    pub decompose_ratio: f64,
    /// Most parts of a decomposition (default 16).
    pub max_parts: u32,
    /// Highest VHACD voxel resolution (default 40: a third of the time of 64 on the left-hand
    /// fixture's fingers, fit errors within 2.3 mm of it); lower when the work budget requires it.
    pub vhacd_resolution: u32,
    /// Work budget of one body's decomposition, in estimated work units ([`decomposition_work`],
    /// about a microsecond each; default 180,000: resolution 40 up to 8,400 triangles). The voxel resolution is the highest (in steps
    /// of 8, at least 16) whose estimate fits, for the mesh's triangle count and the depth that
    /// `max_parts` needs. A mesh whose triangles alone take more than half the budget is first
    /// simplified by vertex clustering to fit; if nothing fits, the body keeps its hull. Each is
    /// warned. Deterministic: the same mesh and options always give the same plan (no clock).
    pub decomposition_budget: u64,
    /// Sides of the polygon prism standing for a cylinder (default 24); the prism circumscribes
    /// the cylinder, its extra size (R·(1/cos(π/n) − 1), 0.9 % of R) is part of the fit error.
    pub cylinder_sides: usize,
    /// A mesh with more triangles (default 100,000) is simplified by vertex clustering first.
    pub max_triangles: usize,
    /// Clustering grid for simplification: cells per bounding-box diagonal (default 100).
    pub simplify_cells: f64,
    /// Most vertices of a hull or decomposition part (default 96, so that GJK's support
    /// function, a scan over the vertices, stays cheap); bigger hulls are rebuilt from their
    /// vertices clustered on a coarser grid (warned).
    pub max_hull_vertices: usize,
    /// Thickness of the fallback shape of a flat mesh, and radius for a line or point (default 1 mm).
    pub thin_thickness: f64,
}

impl Default for ShapeOptions {
    fn default() -> Self {
        ShapeOptions {
            primitive_abs_tolerance: 1e-3,
            primitive_rel_tolerance: 0.02,
            primitive_volume_tolerance: 0.15,
            decompose_ratio: 1.25,
            max_parts: 16,
            vhacd_resolution: 40,
            decomposition_budget: 180_000,
            cylinder_sides: 24,
            max_triangles: 100_000,
            simplify_cells: 100.0,
            max_hull_vertices: 96,
            thin_thickness: 1e-3,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeKind {
    Box,
    Cylinder,
    Sphere,
    Capsule,
    Hull,
    Decomposition,
}

impl ShapeKind {
    pub fn name(&self) -> &'static str {
        match self {
            ShapeKind::Box => "box",
            ShapeKind::Cylinder => "cylinder",
            ShapeKind::Sphere => "sphere",
            ShapeKind::Capsule => "capsule",
            ShapeKind::Hull => "hull",
            ShapeKind::Decomposition => "decomposition",
        }
    }
}

/// A body's collision shape, in its frame_a (CS1), metres.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyShape {
    pub kind: ShapeKind,
    /// What distances use. Box: 8 vertices; cylinder: a circumscribed prism; sphere: 1 vertex and a
    /// radius; capsule: 2 vertices and a radius. Empty when the mesh had no usable vertex (warned).
    pub parts: Vec<ConvexPart>,
    /// Vertices over all parts.
    pub vertex_count: usize,
    /// Metres: the largest distance from a mesh sample (every vertex and every triangle centroid)
    /// to the shape's surface (the shape contains the mesh, so this is how far the mesh surface
    /// lies inside the shape at worst). For a decomposition: to the nearest part's surface.
    /// One-sided: shape surface far from every mesh sample is caught by `volume_ratio`.
    pub fit_error: f64,
    /// Shape volume / mesh volume. Mesh volume: the enclosed volume of a closed, consistently
    /// oriented mesh; otherwise (open or non-manifold, warned) the hull's volume. Decomposition:
    /// the sum of the parts' volumes (overlaps count twice).
    pub volume_ratio: f64,
    pub source_triangles: usize,
    pub warnings: Vec<String>,
}

/// A candidate shape while fitting.
struct Cand {
    kind: ShapeKind,
    parts: Vec<ConvexPart>,
    err: f64,
    vol: f64,
}

/// The collision shape of a mesh. Never panics: bad meshes give a fallback shape and warnings.
///
/// 1. Identical vertices are welded; non-finite vertices and triangles with bad or repeated
///    indices are dropped (warned). No usable vertex: no parts (warned).
/// 2. More than `max_triangles`: vertex clustering first (warned, with the vertex counts and how
///    far vertices moved); no decomposition then.
/// 3. Flat (thickness ≤ 1e-6 × diagonal) or fewer than 4 points: the points extruded by
///    ± thin_thickness/2 along the normal (kind hull); a line: a capsule, a point: a sphere of
///    radius thin_thickness (warned "degenerate").
/// 4. Candidates: sphere (least squares), boxes (frame axes, principal axes, largest hull faces;
///    the smallest), cylinders (box edges and principal axes), capsules (principal axes); the
///    candidate with the smallest fit error among those within the tolerances of
///    [`ShapeOptions`] wins.
/// 5. Else the convex hull (parry), at most `max_hull_vertices`; if the mesh is closed and the
///    hull exceeds `decompose_ratio` × the mesh volume: VHACD (parry) parts, each the hull of the
///    mesh triangles in a voxel part. A mesh that is not a closed 2-manifold (warned) keeps
///    the hull: its volume is unknown.
pub fn body_shape(mesh: &Mesh, opts: &ShapeOptions) -> BodyShape {
    let source_triangles = mesh.triangles.len();
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| shape_inner(mesh, opts))) {
        Ok(s) => s,
        Err(_) => BodyShape {
            kind: ShapeKind::Hull,
            parts: Vec::new(),
            vertex_count: 0,
            fit_error: 0.0,
            volume_ratio: 0.0,
            source_triangles,
            warnings: vec!["internal error while making the collision shape: no collision shape".into()],
        },
    }
}

fn shape_inner(mesh: &Mesh, opts: &ShapeOptions) -> BodyShape {
    let source_triangles = mesh.triangles.len();
    let mut warnings = Vec::new();
    // Weld identical vertices, drop non-finite ones and triangles with bad indices.
    let mut index: HashMap<[u32; 3], u32> = HashMap::new();
    let mut pts: Vec<P3> = Vec::new();
    let mut remap: Vec<Option<u32>> = Vec::with_capacity(mesh.vertices.len());
    let mut non_finite = 0usize;
    for v in &mesh.vertices {
        if !v.iter().all(|c| c.is_finite()) {
            non_finite += 1;
            remap.push(None);
            continue;
        }
        let key = [v[0].to_bits(), v[1].to_bits(), v[2].to_bits()];
        let id = *index.entry(key).or_insert_with(|| {
            pts.push(P3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2])));
            (pts.len() - 1) as u32
        });
        remap.push(Some(id));
    }
    if non_finite > 0 {
        warnings.push(format!("{non_finite} non-finite vertices ignored"));
    }
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(mesh.triangles.len());
    let mut bad = 0usize;
    for t in &mesh.triangles {
        let m = |i: u32| remap.get(i as usize).copied().flatten();
        match (m(t[0]), m(t[1]), m(t[2])) {
            (Some(a), Some(b), Some(c)) if a != b && b != c && a != c => tris.push([a, b, c]),
            _ => bad += 1,
        }
    }
    if bad > 0 {
        warnings.push(format!("{bad} degenerate or invalid triangles ignored"));
    }
    if pts.is_empty() {
        warnings.push("no usable vertices: no collision shape".into());
        return finish(Cand { kind: ShapeKind::Hull, parts: Vec::new(), err: 0.0, vol: 0.0 }, 0.0, source_triangles, warnings);
    }
    let (lo, hi) = bounds(&pts);
    let diag = (hi - lo).norm();
    // Closedness and volume on the welded mesh (before any simplification).
    let (closed, open_edges) = closed_manifold(&tris);
    let mesh_volume = signed_volume(&pts, &tris).abs();
    let huge = source_triangles > opts.max_triangles;
    if huge {
        let cell = diag / opts.simplify_cells.max(1.0);
        let before = pts.len();
        let (p2, t2) = cluster(&pts, &tris, cell);
        pts = p2;
        tris = t2;
        warnings.push(format!(
            "huge mesh ({source_triangles} triangles) simplified by vertex clustering: {before} → {} vertices, {} triangles (vertices moved ≤ {:.2e} m)",
            pts.len(),
            tris.len(),
            cell * 3f64.sqrt()
        ));
    }
    let samples = sample_points(&pts, &tris);
    // Flat / line / point?
    let (axes, extents) = principal(&pts);
    let scale = diag.max(1e-9);
    let flat_tol = 1e-6 * scale;
    let t = opts.thin_thickness.max(1e-9);
    if extents[2] <= flat_tol || pts.len() < 4 {
        let what;
        let cand = if extents[1] <= flat_tol {
            if extents[0] <= flat_tol {
                what = "a point";
                let c = centroid(&pts);
                Cand { kind: ShapeKind::Sphere, parts: vec![part_of(&[c], Vec::new(), t)], err: t, vol: sphere_volume(t) }
            } else {
                what = "a line";
                let u = axes.column(0).into_owned();
                let c = centroid(&pts);
                let (mn, mx) = pts.iter().fold((f64::MAX, f64::MIN), |(a, b), p| {
                    let h = (p - c).dot(&u);
                    (a.min(h), b.max(h))
                });
                let (a, b) = (c + u * mn, c + u * mx);
                let len = (b - a).norm();
                Cand {
                    kind: ShapeKind::Capsule,
                    parts: vec![part_of(&[a, b], Vec::new(), t)],
                    err: t,
                    vol: PI * t * t * len + sphere_volume(t),
                }
            }
        } else {
            what = "flat";
            let n = axes.column(2).into_owned();
            let mut ext: Vec<P3> = Vec::with_capacity(pts.len() * 2);
            for p in &pts {
                ext.push(p + n * (t / 2.0));
                ext.push(p - n * (t / 2.0));
            }
            match hull_part(&ext) {
                Some(part) => {
                    let vol = part_volume(&part);
                    Cand { kind: ShapeKind::Hull, parts: vec![part], err: t / 2.0, vol }
                }
                None => {
                    let c = centroid(&pts);
                    let r = pts.iter().map(|p| (p - c).norm()).fold(t, f64::max);
                    Cand { kind: ShapeKind::Sphere, parts: vec![part_of(&[c], Vec::new(), r)], err: r, vol: sphere_volume(r) }
                }
            }
        };
        warnings.push(format!("degenerate mesh ({what}, {} vertices): a thin fallback shape {:.1e} m thick", pts.len(), t));
        let vol = cand.vol;
        return finish(cand, vol, source_triangles, warnings);
    }
    // The hull's simplification warning only matters if the hull is the shape.
    let mut hull_warnings = Vec::new();
    let Some(full) = hull_part(&pts) else {
        warnings.push("convex hull failed: a bounding box instead".into());
        let b = box_from_axes(&pts, &Matrix3::identity());
        let vol = b.vol;
        return finish(b, vol, source_triangles, warnings);
    };
    // The exact hull's volume decides about decomposition; the shape is the capped hull.
    let full_vol = part_volume(&full);
    let mut simplified = Simplified::default();
    let hull = capped(full, opts.max_hull_vertices, &mut simplified);
    simplified.warn("hull", 1, &mut hull_warnings);
    let hull_vol = part_volume(&hull);
    let use_mesh_volume = closed && mesh_volume > 1e-9 * full_vol;
    let denom = if use_mesh_volume {
        mesh_volume
    } else {
        warnings
            .push(format!("mesh not closed ({open_edges} open or non-manifold edges): volume ratio against the hull, no decomposition"));
        full_vol
    };
    let tol = opts.primitive_abs_tolerance.max(opts.primitive_rel_tolerance * diag);
    let v = opts.primitive_volume_tolerance;
    let ok = |c: &Cand| {
        let r = c.vol / denom;
        c.err.is_finite() && c.err <= tol && r <= 1.0 + v && r >= 1.0 / (1.0 + v)
    };
    let mut cands: Vec<Cand> = Vec::new();
    let hull_pts: Vec<P3> = hull.vertices.iter().map(|v| P3::from(*v)).collect();
    if let Some(c) = fit_sphere(&hull_pts, &samples) {
        cands.push(c);
    }
    let mut frames = vec![Matrix3::identity(), axes];
    frames.extend(face_frames(&hull, 8));
    let mut best_box: Option<Cand> = None;
    for f in &frames {
        let b = box_from_axes(&hull_pts, f);
        if best_box.as_ref().is_none_or(|x| b.vol < x.vol) {
            best_box = Some(b);
        }
    }
    if let Some(mut b) = best_box {
        b.err = shape_error_limited(&b.parts, &samples, tol);
        // Cylinder axes: the best box's edges (corners 1, 2, 4 from corner 0) and the principal axes.
        let mut cyl_axes: Vec<V3> = Vec::new();
        if let Some(part) = b.parts.first() {
            let p0 = P3::from(part.vertices[0]);
            for i in [1, 2, 4] {
                let d = P3::from(part.vertices[i]) - p0;
                if d.norm() > 1e-12 {
                    cyl_axes.push(d.normalize());
                }
            }
        }
        for i in 0..3 {
            cyl_axes.push(axes.column(i).into_owned());
        }
        for a in &cyl_axes {
            if let Some(c) = fit_cylinder(&hull_pts, &samples, a, opts.cylinder_sides.max(6), tol) {
                cands.push(c);
            }
        }
        cands.push(b);
    }
    for i in 0..3 {
        if let Some(c) = fit_capsule(&hull_pts, &samples, &axes.column(i).into_owned()) {
            cands.push(c);
        }
    }
    let best = cands.into_iter().filter(|c| ok(c)).min_by(|a, b| a.err.total_cmp(&b.err));
    if let Some(c) = best {
        return finish(c, denom, source_triangles, warnings);
    }
    let hull_err = shape_error(std::slice::from_ref(&hull), &samples);
    let hull_cand = Cand { kind: ShapeKind::Hull, parts: vec![hull], err: hull_err, vol: hull_vol };
    if use_mesh_volume && full_vol / denom > opts.decompose_ratio {
        if huge {
            warnings.push("hull much bigger than the mesh, but the mesh is huge: hull, no decomposition".into());
        } else if let Some((plan, dpts, dtris, moved)) = decomposition_input(&pts, &tris, diag, opts) {
            match decompose(&dpts, &dtris, opts, &plan) {
                Some(parts) if parts.len() >= 2 => {
                    if let Some(moved) = moved {
                        warnings.push(format!(
                            "mesh of {} triangles simplified to {} by vertex clustering for the convex decomposition, to stay within its work budget (vertices moved ≤ {moved:.2e} m)",
                            tris.len(),
                            dtris.len()
                        ));
                    }
                    if plan.resolution < opts.vhacd_resolution {
                        warnings.push(format!(
                            "convex decomposition at voxel resolution {} instead of {} to stay within its work budget ({} triangles): coarser parts",
                            plan.resolution, opts.vhacd_resolution, dtris.len()
                        ));
                    }
                    let mut simplified = Simplified::default();
                    let parts: Vec<ConvexPart> = parts.into_iter().map(|p| capped(p, opts.max_hull_vertices, &mut simplified)).collect();
                    simplified.warn("decomposition part", parts.len(), &mut warnings);
                    let vol: f64 = parts.iter().map(part_volume).sum();
                    let err = shape_error(&parts, &samples);
                    return finish(Cand { kind: ShapeKind::Decomposition, parts, err, vol }, denom, source_triangles, warnings);
                }
                _ => warnings.push(format!("hull is {:.2}× the mesh volume but the convex decomposition failed: hull", full_vol / denom)),
            }
        } else {
            warnings.push(format!(
                "hull is {:.2}× the mesh volume, but a convex decomposition of {} triangles exceeds its work budget even simplified and at voxel resolution {MIN_RESOLUTION}: hull",
                full_vol / denom,
                tris.len()
            ));
        }
    }
    warnings.extend(hull_warnings);
    finish(hull_cand, denom, source_triangles, warnings)
}

fn finish(c: Cand, denom: f64, source_triangles: usize, warnings: Vec<String>) -> BodyShape {
    BodyShape {
        kind: c.kind,
        vertex_count: c.parts.iter().map(|p| p.vertices.len()).sum(),
        parts: c.parts,
        fit_error: c.err,
        volume_ratio: if denom > 0.0 { c.vol / denom } else { 0.0 },
        source_triangles,
        warnings,
    }
}

fn bounds(pts: &[P3]) -> (P3, P3) {
    let mut lo = P3::new(f64::MAX, f64::MAX, f64::MAX);
    let mut hi = P3::new(f64::MIN, f64::MIN, f64::MIN);
    for p in pts {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    (lo, hi)
}

fn centroid(pts: &[P3]) -> P3 {
    let s = pts.iter().fold(V3::zeros(), |s, p| s + p.coords);
    P3::from(s / pts.len().max(1) as f64)
}

/// Principal axes (columns, largest extent first) and extents along them.
fn principal(pts: &[P3]) -> (Matrix3<f64>, [f64; 3]) {
    let c = centroid(pts);
    let mut cov = Matrix3::zeros();
    for p in pts {
        let d = p - c;
        cov += d * d.transpose();
    }
    let eig = SymmetricEigen::new(cov);
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let mut axes = Matrix3::zeros();
    let mut ext = [0.0; 3];
    for (k, &i) in idx.iter().enumerate() {
        let u = eig.eigenvectors.column(i).normalize();
        axes.set_column(k, &u);
        let (mn, mx) = pts.iter().fold((f64::MAX, f64::MIN), |(a, b), p| {
            let h = (p - c).dot(&u);
            (a.min(h), b.max(h))
        });
        ext[k] = (mx - mn).max(0.0);
    }
    // Right-handed, third axis exact.
    let z = axes.column(0).cross(&axes.column(1));
    if z.norm() > 0.5 {
        axes.set_column(2, &z.normalize());
    }
    (axes, ext)
}

/// Closed, consistently oriented 2-manifold? And the number of edges that are not.
fn closed_manifold(tris: &[[u32; 3]]) -> (bool, usize) {
    let mut edges: HashMap<(u32, u32), (i32, i32)> = HashMap::with_capacity(tris.len() * 2);
    for t in tris {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let e = edges.entry((a.min(b), a.max(b))).or_insert((0, 0));
            e.0 += 1;
            e.1 += if a < b { 1 } else { -1 };
        }
    }
    let bad = edges.values().filter(|&&(n, o)| n != 2 || o != 0).count();
    (bad == 0 && !tris.is_empty(), bad)
}

fn signed_volume(pts: &[P3], tris: &[[u32; 3]]) -> f64 {
    let c = pts.first().map(|p| p.coords).unwrap_or_else(V3::zeros);
    tris.iter()
        .map(|t| {
            let a = pts[t[0] as usize].coords - c;
            let b = pts[t[1] as usize].coords - c;
            let d = pts[t[2] as usize].coords - c;
            a.dot(&b.cross(&d)) / 6.0
        })
        .sum()
}

/// Vertex clustering on a grid of `cell`: one vertex per occupied cell (the first one met).
fn cluster(pts: &[P3], tris: &[[u32; 3]], cell: f64) -> (Vec<P3>, Vec<[u32; 3]>) {
    let cell = cell.max(1e-12);
    let mut map: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut out = Vec::new();
    let remap: Vec<u32> = pts
        .iter()
        .map(|p| {
            let k = ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64, (p.z / cell).floor() as i64);
            *map.entry(k).or_insert_with(|| {
                out.push(*p);
                (out.len() - 1) as u32
            })
        })
        .collect();
    let mut seen = std::collections::HashSet::new();
    let mut t2 = Vec::new();
    for t in tris {
        let n = [remap[t[0] as usize], remap[t[1] as usize], remap[t[2] as usize]];
        if n[0] != n[1] && n[1] != n[2] && n[0] != n[2] {
            let mut key = n;
            key.sort_unstable();
            if seen.insert(key) {
                t2.push(n);
            }
        }
    }
    (out, t2)
}

/// What [`capped`] did to the parts of one shape, for one warning per shape.
#[derive(Default)]
struct Simplified {
    parts: usize,
    /// Largest vertex count before, largest after.
    before: usize,
    after: usize,
    /// Farthest a dropped vertex lies outside its simplified part, m.
    outside: f64,
}

impl Simplified {
    /// One warning: `what` (`hull`, `decomposition part`) of `of` simplified.
    fn warn(&self, what: &str, of: usize, warnings: &mut Vec<String>) {
        if self.parts == 0 {
            return;
        }
        let which = if of == 1 { what.to_string() } else { format!("{} of {of} {what}s", self.parts) };
        warnings.push(format!(
            "{which} simplified to at most {} vertices (from up to {}; the exact hull reaches ≤ {:.2e} m beyond it): faster contacts",
            self.after, self.before, self.outside
        ));
    }
}

/// A hull part with at most `max` vertices (noted in `simplified`): a subset of its vertices,
/// chosen greedily (the six extremes along the axes, then the vertices farthest outside the
/// hull so far, a quarter of the room left at a time), so the simplified hull lies inside the
/// exact one and misses little of it. Unchanged when small enough or when a hull fails.
fn capped(part: ConvexPart, max: usize, simplified: &mut Simplified) -> ConvexPart {
    let max = max.max(8);
    if part.vertices.len() <= max || part.radius != 0.0 {
        return part;
    }
    let pts: Vec<P3> = part.vertices.iter().map(|v| P3::from(*v)).collect();
    let mut chosen: Vec<usize> = Vec::with_capacity(max);
    for axis in 0..3 {
        let by = |a: &&P3, b: &&P3| a[axis].total_cmp(&b[axis]);
        let lo = pts.iter().enumerate().min_by(|a, b| by(&a.1, &b.1)).map(|(i, _)| i);
        let hi = pts.iter().enumerate().max_by(|a, b| by(&a.1, &b.1)).map(|(i, _)| i);
        chosen.extend(lo.into_iter().chain(hi).filter(|i| !chosen.contains(i)).collect::<Vec<_>>());
    }
    // The farthest point from the first (a tetrahedron at least, for a flat set of extremes).
    if let Some(far) = (0..pts.len()).max_by(|&a, &b| (pts[a] - pts[chosen[0]]).norm().total_cmp(&(pts[b] - pts[chosen[0]]).norm())) {
        if !chosen.contains(&far) {
            chosen.push(far);
        }
    }
    let mut best: Option<(ConvexPart, f64)> = None;
    // Candidates: every vertex, or for a big hull one per cell of a grid coarse enough to leave
    // at most 8 × max (still vertices of the exact hull). Points inside a hull stay inside the
    // later ones (each hull contains the one before): they are dropped as they are passed.
    let mut open: Vec<usize> = (0..pts.len()).collect();
    if pts.len() > 8 * max {
        let (lo, hi) = bounds(&pts);
        let diag = (hi - lo).norm().max(1e-12);
        let mut cells = 256.0f64;
        while cells >= 2.0 {
            let cell = diag / cells;
            let mut seen = std::collections::HashSet::new();
            let sub: Vec<usize> = (0..pts.len())
                .filter(|&i| {
                    seen.insert(((pts[i].x / cell).floor() as i64, (pts[i].y / cell).floor() as i64, (pts[i].z / cell).floor() as i64))
                })
                .collect();
            if sub.len() <= 8 * max {
                open = sub;
                break;
            }
            cells /= 1.25;
        }
    }
    while chosen.len() <= max {
        let sub: Vec<P3> = chosen.iter().map(|&i| pts[i]).collect();
        let Some(h) = hull_part(&sub) else { break };
        if h.vertices.len() > max {
            break;
        }
        let pl = planes(&h);
        let mut outside: Vec<(f64, usize)> = open
            .iter()
            .map(|&i| (pl.iter().map(|(n, d)| n.dot(&pts[i].coords) - d).fold(f64::MIN, f64::max), i))
            .filter(|&(d, i)| d > 0.0 && !chosen.contains(&i))
            .collect();
        open = outside.iter().map(|&(_, i)| i).collect();
        outside.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        best = Some((h, outside.first().map_or(0.0, |o| o.0)));
        // The farthest first; several at a time while far from the cap (fewer hulls to build).
        let room = max - chosen.len();
        if outside.is_empty() || room == 0 {
            break;
        }
        chosen.extend(outside.iter().take((room / 4).max(1)).map(|&(_, i)| i));
    }
    match best {
        Some((h, out)) => {
            // How far the exact hull reaches beyond (over every vertex, not just the candidates).
            let pl = planes(&h);
            let out =
                pts.iter().map(|p| pl.iter().map(|(n, d)| n.dot(&p.coords) - d).fold(f64::MIN, f64::max)).fold(out, f64::max).max(0.0);
            simplified.parts += 1;
            simplified.before = simplified.before.max(part.vertices.len());
            simplified.after = simplified.after.max(h.vertices.len());
            simplified.outside = simplified.outside.max(out);
            h
        }
        None => part,
    }
}

/// Fit samples: every vertex and every triangle centroid.
fn sample_points(pts: &[P3], tris: &[[u32; 3]]) -> Vec<P3> {
    let mut s = pts.to_vec();
    s.extend(tris.iter().map(|t| P3::from((pts[t[0] as usize].coords + pts[t[1] as usize].coords + pts[t[2] as usize].coords) / 3.0)));
    s
}

fn part_of(vs: &[P3], faces: Vec<[u32; 3]>, radius: f64) -> ConvexPart {
    ConvexPart { vertices: vs.iter().map(|p| [p.x, p.y, p.z]).collect(), faces, radius }
}

/// The convex hull of points as a part (None: degenerate input).
pub(crate) fn hull_part(pts: &[P3]) -> Option<ConvexPart> {
    if pts.len() < 4 {
        return None;
    }
    let (vs, faces) = try_convex_hull(pts).ok()?;
    if vs.len() < 4 || faces.len() < 4 {
        return None;
    }
    let part = part_of(&vs, faces, 0.0);
    (part_volume(&part) > 0.0).then_some(part)
}

fn sphere_volume(r: f64) -> f64 {
    4.0 / 3.0 * PI * r * r * r
}

/// Volume of a part: polytope by its faces, sphere, capsule.
pub(crate) fn part_volume(p: &ConvexPart) -> f64 {
    match p.vertices.len() {
        0 => 0.0,
        1 => sphere_volume(p.radius),
        2 => {
            let l = (V3::from(p.vertices[1]) - V3::from(p.vertices[0])).norm();
            PI * p.radius * p.radius * l + sphere_volume(p.radius)
        }
        _ => {
            let pts: Vec<P3> = p.vertices.iter().map(|v| P3::from(*v)).collect();
            signed_volume(&pts, &p.faces).abs()
        }
    }
}

/// Outward planes (n, d: n·x ≤ d inside) of a polytope part.
fn planes(p: &ConvexPart) -> Vec<(V3, f64)> {
    let c = p.vertices.iter().fold(V3::zeros(), |s, v| s + V3::from(*v)) / p.vertices.len().max(1) as f64;
    p.faces
        .iter()
        .filter_map(|f| {
            let a = V3::from(p.vertices[f[0] as usize]);
            let b = V3::from(p.vertices[f[1] as usize]);
            let e = V3::from(p.vertices[f[2] as usize]);
            let n = (b - a).cross(&(e - a));
            let len = n.norm();
            if len <= 1e-300 {
                return None;
            }
            let mut n = n / len;
            let mut d = n.dot(&a);
            if n.dot(&c) > d {
                n = -n;
                d = -d;
            }
            Some((n, d))
        })
        .collect()
}

/// Signed distance of x to a part (negative inside; outside a polytope a lower bound).
fn part_sd(p: &ConvexPart, pl: &[(V3, f64)], x: &P3) -> f64 {
    match p.vertices.len() {
        0 => f64::INFINITY,
        1 => (x.coords - V3::from(p.vertices[0])).norm() - p.radius,
        2 => seg_dist(&P3::from(p.vertices[0]), &P3::from(p.vertices[1]), x) - p.radius,
        _ => pl.iter().map(|(n, d)| n.dot(&x.coords) - d).fold(f64::MIN, f64::max) - p.radius,
    }
}

fn seg_dist(a: &P3, b: &P3, x: &P3) -> f64 {
    let ab = b - a;
    let l2 = ab.norm_squared();
    let s = if l2 > 0.0 { ((x - a).dot(&ab) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (x - (a + ab * s)).norm()
}

/// Largest over samples of the distance to the nearest part's surface.
fn shape_error(parts: &[ConvexPart], samples: &[P3]) -> f64 {
    shape_error_limited(parts, samples, f64::INFINITY)
}

/// As [`shape_error`], but stops at the first sample beyond `limit` (returning that sample's
/// error, > limit): candidates that cannot be accepted are rejected early.
fn shape_error_limited(parts: &[ConvexPart], samples: &[P3], limit: f64) -> f64 {
    let pls: Vec<Vec<(V3, f64)>> = parts.iter().map(planes).collect();
    let mut worst = 0.0f64;
    for x in samples {
        let e = parts.iter().zip(&pls).map(|(p, pl)| part_sd(p, pl, x).abs()).fold(f64::INFINITY, f64::min);
        worst = worst.max(e);
        if worst > limit {
            break;
        }
    }
    worst
}

/// The box with the given axes (columns) containing the points.
fn box_from_axes(pts: &[P3], axes: &Matrix3<f64>) -> Cand {
    let mut lo = [f64::MAX; 3];
    let mut hi = [f64::MIN; 3];
    for p in pts {
        for i in 0..3 {
            let h = axes.column(i).dot(&p.coords);
            lo[i] = lo[i].min(h);
            hi[i] = hi[i].max(h);
        }
    }
    let mut corners = Vec::with_capacity(8);
    for k in 0..8 {
        let c: [f64; 3] = std::array::from_fn(|i| if k & (1 << i) != 0 { hi[i] } else { lo[i] });
        corners.push(P3::from(axes * V3::new(c[0], c[1], c[2])));
    }
    let vol = (0..3).map(|i| (hi[i] - lo[i]).max(0.0)).product();
    // Faces of the box (corner k: bit i set = hi on axis i), outward for a right-handed frame.
    let faces: Vec<[u32; 3]> = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6], // z lo, z hi
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7], // y lo, y hi
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5], // x lo, x hi
    ];
    let mut faces = faces;
    if axes.determinant() < 0.0 {
        for f in &mut faces {
            f.swap(1, 2);
        }
    }
    Cand { kind: ShapeKind::Box, parts: vec![part_of(&corners, faces, 0.0)], err: f64::INFINITY, vol }
}

/// Frames from the largest hull faces: normal, longest edge, their cross product.
fn face_frames(hull: &ConvexPart, n: usize) -> Vec<Matrix3<f64>> {
    let mut faces: Vec<(f64, V3, [V3; 3])> = hull
        .faces
        .iter()
        .filter_map(|f| {
            let a = V3::from(hull.vertices[f[0] as usize]);
            let b = V3::from(hull.vertices[f[1] as usize]);
            let c = V3::from(hull.vertices[f[2] as usize]);
            let nrm = (b - a).cross(&(c - a));
            let area = nrm.norm();
            if area <= 1e-300 {
                return None;
            }
            Some((area, nrm / area, [b - a, c - b, a - c]))
        })
        .collect();
    faces.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut out = Vec::new();
    for (_, z, edges) in faces.into_iter().take(n) {
        for e in edges {
            let x = e - z * z.dot(&e);
            if x.norm() <= 1e-300 {
                continue;
            }
            let x = x.normalize();
            out.push(Matrix3::from_columns(&[x, z.cross(&x), z]));
        }
    }
    out
}

/// Least-squares sphere through the hull vertices; radius: the largest distance (contains all).
fn fit_sphere(hull_pts: &[P3], samples: &[P3]) -> Option<Cand> {
    let c0 = centroid(hull_pts);
    let mut ata = Matrix4::zeros();
    let mut atb = Vector4::zeros();
    for p in hull_pts {
        let d = p - c0;
        let row = Vector4::new(2.0 * d.x, 2.0 * d.y, 2.0 * d.z, 1.0);
        ata += row * row.transpose();
        atb += row * d.norm_squared();
    }
    let sol = ata.try_inverse()? * atb;
    let c = c0 + V3::new(sol[0], sol[1], sol[2]);
    let r = hull_pts.iter().map(|p| (p - c).norm()).fold(0.0, f64::max);
    let err = samples.iter().map(|p| (r - (p - c).norm()).abs()).fold(0.0, f64::max);
    Some(Cand { kind: ShapeKind::Sphere, parts: vec![part_of(&[c], Vec::new(), r)], err, vol: sphere_volume(r) })
}

/// Centre (in the plane ⟂ axis, as a 3-D point on the axis line at height 0) of a least-squares
/// circle through the points projected along `u`.
fn circle_centre(pts: &[P3], u: &V3) -> Option<(V3, V3, P3)> {
    let e1 = if u.x.abs() < 0.9 { V3::x() } else { V3::y() };
    let e1 = (e1 - u * u.dot(&e1)).normalize();
    let e2 = u.cross(&e1);
    let c0 = centroid(pts);
    let mut ata = Matrix3::zeros();
    let mut atb = V3::zeros();
    for p in pts {
        let d = p - c0;
        let (x, y) = (d.dot(&e1), d.dot(&e2));
        let row = V3::new(2.0 * x, 2.0 * y, 1.0);
        ata += row * row.transpose();
        atb += row * (x * x + y * y);
    }
    let s = ata.try_inverse()? * atb;
    Some((e1, e2, c0 + e1 * s[0] + e2 * s[1]))
}

/// Cylinder about axis `u` containing the points, as a circumscribed prism with `sides` sides.
fn fit_cylinder(hull_pts: &[P3], samples: &[P3], u: &V3, sides: usize, limit: f64) -> Option<Cand> {
    let (e1, e2, c) = circle_centre(hull_pts, u)?;
    let (mut h0, mut h1, mut r) = (f64::MAX, f64::MIN, 0.0f64);
    for p in hull_pts {
        let d = p - c;
        let h = d.dot(u);
        h0 = h0.min(h);
        h1 = h1.max(h);
        r = r.max((d - u * h).norm());
    }
    if r <= 0.0 || h1 <= h0 {
        return None;
    }
    let rc = r / (PI / sides as f64).cos();
    let mut vs = Vec::with_capacity(2 * sides);
    for h in [h0, h1] {
        for k in 0..sides {
            let a = 2.0 * PI * k as f64 / sides as f64;
            vs.push(c + u * h + (e1 * a.cos() + e2 * a.sin()) * rc);
        }
    }
    let part = hull_part(&vs)?;
    let vol = part_volume(&part);
    // One-sided error, and the prism's edges stand off the round mesh by at least rc − r.
    let err = shape_error_limited(std::slice::from_ref(&part), samples, limit).max(rc - r);
    Some(Cand { kind: ShapeKind::Cylinder, parts: vec![part], err, vol })
}

/// Capsule along axis `u` containing the points (None when it would be a sphere).
fn fit_capsule(hull_pts: &[P3], samples: &[P3], u: &V3) -> Option<Cand> {
    let (_, _, c) = circle_centre(hull_pts, u)?;
    let (mut h0, mut h1, mut r0) = (f64::MAX, f64::MIN, 0.0f64);
    for p in hull_pts {
        let d = p - c;
        let h = d.dot(u);
        h0 = h0.min(h);
        h1 = h1.max(h);
        r0 = r0.max((d - u * h).norm());
    }
    if h1 - h0 <= 2.0 * r0 * 1.05 {
        return None;
    }
    let (a, b) = (c + u * (h0 + r0), c + u * (h1 - r0));
    let r = hull_pts.iter().map(|p| seg_dist(&a, &b, p)).fold(0.0, f64::max);
    let err = samples.iter().map(|p| (r - seg_dist(&a, &b, p)).abs()).fold(0.0, f64::max);
    let vol = PI * r * r * (b - a).norm() + sphere_volume(r);
    Some(Cand { kind: ShapeKind::Capsule, parts: vec![part_of(&[a, b], Vec::new(), r)], err, vol })
}

/// The decomposition that a body's budget allows: VHACD voxel resolution and the split depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DecompositionPlan {
    pub resolution: u32,
    /// Binary split levels parry's VHACD makes for `max_parts` (up to 2^depth parts).
    pub depth: u32,
    /// Estimated work units (compared with [`ShapeOptions::decomposition_budget`]).
    pub work: u64,
}

/// Lowest voxel resolution a decomposition is tried at.
const MIN_RESOLUTION: u32 = 16;

/// Estimated work of a VHACD decomposition (parry 0.22) at resolution `r` of a mesh of
/// `triangles` triangles into up to 2^`depth` parts, in units of about a microsecond of one core
/// of the reference machine (calibrated on the left-hand and UR5 fixtures: a split level clips
/// the voxels against ~r candidate planes, hulling the two sides, which grows about as r²; every
/// triangle is voxelized, clipped against the parts it meets and sampled for the fit error).
/// A count, not a clock: the same mesh always gets the same estimate.
pub fn decomposition_work(r: u32, depth: u32, triangles: usize) -> u64 {
    let r = u64::from(r);
    12 * u64::from(depth) * r * r + 10 * triangles as u64
}

/// The plan for a mesh of `triangles` triangles: the highest resolution (from
/// `opts.vhacd_resolution` down in steps of 8, not below 16) whose estimated work fits
/// `opts.decomposition_budget`; `None` when even the lowest does not fit.
pub fn decomposition_plan(triangles: usize, opts: &ShapeOptions) -> Option<DecompositionPlan> {
    let max_parts = opts.max_parts.max(2);
    // As parry's VHACD: levels until 2^depth ≥ max_parts, plus one.
    let (mut count, mut depth) = (2u32, 1u32);
    while max_parts > count {
        depth += 1;
        count = count.saturating_mul(2);
    }
    depth += 1;
    let top = opts.vhacd_resolution.max(MIN_RESOLUTION);
    let mut r = top;
    loop {
        let work = decomposition_work(r, depth, triangles);
        if work <= opts.decomposition_budget {
            return Some(DecompositionPlan { resolution: r, depth, work });
        }
        if r <= MIN_RESOLUTION {
            return None;
        }
        r = r.saturating_sub(8).max(MIN_RESOLUTION);
    }
}

/// What is decomposed and how: the mesh itself, or (its triangles alone taking more than half
/// the budget) the mesh clustered on ever coarser grids until they fit, with how far vertices
/// moved; `None` when even then no plan fits the budget.
#[allow(clippy::type_complexity)]
fn decomposition_input(
    pts: &[P3],
    tris: &[[u32; 3]],
    diag: f64,
    opts: &ShapeOptions,
) -> Option<(DecompositionPlan, Vec<P3>, Vec<[u32; 3]>, Option<f64>)> {
    if decomposition_work(0, 0, tris.len()) <= opts.decomposition_budget / 2 {
        return decomposition_plan(tris.len(), opts).map(|p| (p, pts.to_vec(), tris.to_vec(), None));
    }
    let mut cells = opts.simplify_cells.max(8.0);
    while cells >= 8.0 {
        let cell = diag / cells;
        let (p2, t2) = cluster(pts, tris, cell);
        if decomposition_work(0, 0, t2.len()) <= opts.decomposition_budget / 2 && t2.len() >= 4 {
            return decomposition_plan(t2.len(), opts).map(|p| (p, p2, t2, Some(cell * 3f64.sqrt())));
        }
        cells /= 1.25;
    }
    None
}

/// VHACD convex decomposition; parts are hulls of the original triangles in each voxel part.
fn decompose(pts: &[P3], tris: &[[u32; 3]], opts: &ShapeOptions, plan: &DecompositionPlan) -> Option<Vec<ConvexPart>> {
    let params = VHACDParameters { resolution: plan.resolution, max_convex_hulls: opts.max_parts.max(2), ..VHACDParameters::default() };
    let v = VHACD::decompose(&params, pts, tris, true);
    let parts: Vec<ConvexPart> = v.compute_exact_convex_hulls(pts, tris).into_iter().filter_map(|(vs, _)| hull_part(&vs)).collect();
    (!parts.is_empty()).then_some(parts)
}

/// Wavefront OBJ of a shape: one `o` per part; spheres, capsules and rounded parts tessellated.
pub fn obj_text(shape: &BodyShape, name: &str) -> String {
    use crate::numtext::{push_disp, push_uint};
    // Numbers straight into the text (`core::fmt` was a third of writing a large package's
    // shape files).
    let mut s = format!("# cad2mo collision shape: {} ({})\n", name, shape.kind.name());
    let mut base = 1usize;
    for (k, p) in shape.parts.iter().enumerate() {
        let (vs, fs): (Vec<[f64; 3]>, Vec<[u32; 3]>) = if p.radius > 0.0 || p.faces.is_empty() {
            let mut pts = Vec::new();
            let (nu, nv) = (8usize, 16usize);
            for v in &p.vertices {
                let c = V3::from(*v);
                for i in 0..=nu {
                    let th = PI * i as f64 / nu as f64;
                    for j in 0..nv {
                        let ph = 2.0 * PI * j as f64 / nv as f64;
                        let d = V3::new(th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos());
                        pts.push(P3::from(c + d * p.radius));
                    }
                }
            }
            match try_convex_hull(&pts) {
                Ok((v, f)) => (v.iter().map(|p| [p.x, p.y, p.z]).collect(), f),
                Err(_) => (p.vertices.clone(), p.faces.clone()),
            }
        } else {
            (p.vertices.clone(), p.faces.clone())
        };
        s.push_str("o ");
        s.push_str(name);
        s.push('_');
        push_uint(&mut s, k as u64);
        s.push('\n');
        for v in &vs {
            for (i, &x) in v.iter().enumerate() {
                s.push_str(if i == 0 { "v " } else { " " });
                push_disp(&mut s, x);
            }
            s.push('\n');
        }
        for f in &fs {
            for (i, &x) in f.iter().enumerate() {
                s.push_str(if i == 0 { "f " } else { " " });
                push_uint(&mut s, (x as usize + base) as u64);
            }
            s.push('\n');
        }
        base += vs.len();
    }
    s
}
