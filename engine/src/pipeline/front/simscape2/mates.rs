//! Joint inference from CAD mates (the SolidWorks and Creo plug-ins write no joints).
//!
//! The mates between two rigid groups A and B constrain B's motion relative to A. At the
//! assembly pose each mate is a set of holonomic equations; their gradients with respect to the
//! relative twist `(ω, v)` of B (the velocity of a point `x` fixed in B is `v + ω × x`) are the
//! rows of the constraint Jacobian `J` (m × 6). The motion the mates leave free, to first order,
//! is the null space of `J` (SVD, relative tolerance [`RANK_TOL`]). That null space is mapped to
//! the one joint that allows exactly that motion:
//!
//! | free twists | joint | primitives |
//! |---|---|---|
//! | none | weld | weld |
//! | 1 rotation about a fixed line | revolute | revolute |
//! | 1..3 translations | prismatic | prismatic per direction |
//! | rotation + translation along the same line | cylindrical | prismatic, revolute |
//! | 2 translations + rotation about their normal | planar | prismatic, prismatic, revolute |
//! | 2 rotations about one point | universal | revolute, revolute |
//! | 3 rotations about one point | spherical | spherical |
//! | everything | no joint | - |
//!
//! Anything else (a screw, a rotation and a translation that are not coaxial, rotations about
//! different points ...) is [`Reduction::Unreducible`]: reported, never guessed.
//!
//! Rows per mate (`g1` on A, `g2` on B; the rows are the same up to sign whichever side owns
//! which geometry, so the order does not matter):
//! - a point `x` staying on a plane with normal `n`: `[x × n, n]`;
//! - a point staying on a line with direction `d`: `[x × e, e]` for the two `e ⊥ d`;
//! - a point staying on a point: `[x × e, e]` for `e` = x, y, z;
//! - a direction `u` staying parallel to `w`: `[u × e, 0]` for the two `e ⊥ u`;
//! - a fixed angle between directions `u` and `w`: `[u × w, 0]` (parallel ones: as above).
//!
//! Geometry: `plane` (point, normal), `line`, `cylinder` and `circle` (point on the axis and the
//! axis), `sphere` and `point` (centre).

use nalgebra::{DMatrix, UnitQuaternion, Vector3, Vector6};

/// Singular values below this (relative to the rows, which are about unit size once lengths are
/// scaled by the pair's extent) count as zero.
pub const RANK_TOL: f64 = 1e-4;
/// A mate whose geometry is further off than this at the assembly pose (m, or rad for
/// directions) is reported as inconsistent.
pub const CONSISTENCY_TOL: f64 = 1e-4;
/// SVD iterations before giving up (nalgebra's default is unbounded).
const MAX_SVD_ITERATIONS: usize = 1000;

/// One mate's geometry, in world coordinates (metres) at the assembly pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geom {
    pub kind: GeomKind,
    pub point: Vector3<f64>,
    /// Unit normal (plane) or axis (line, cylinder, circle); zero for points and spheres.
    pub axis: Vector3<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GeomKind {
    Plane,
    /// A line, a cylinder's axis, or a circle's axis (for concentric mates).
    Line,
    /// A circle: its centre and axis.
    Circle,
    /// A point or a sphere's centre.
    Point,
}

impl GeomKind {
    /// Maps a `geomType` attribute; `None` for kinds not handled.
    pub fn from_attr(s: &str) -> Option<GeomKind> {
        match s.to_ascii_lowercase().as_str() {
            "plane" => Some(GeomKind::Plane),
            "line" | "cylinder" | "axis" => Some(GeomKind::Line),
            "circle" => Some(GeomKind::Circle),
            "sphere" | "point" => Some(GeomKind::Point),
            _ => None,
        }
    }
}

/// Mate kinds the reduction understands (Rigid mates merge groups before this runs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MateKind {
    Coincident,
    Concentric,
    Distance,
    Parallel,
    Perpendicular,
    Angle,
    Tangent,
}

impl MateKind {
    pub fn from_tag(s: &str) -> Option<MateKind> {
        Some(match s {
            "Coincident" => MateKind::Coincident,
            "Concentric" => MateKind::Concentric,
            "Distance" => MateKind::Distance,
            "Parallel" => MateKind::Parallel,
            "Perpendicular" => MateKind::Perpendicular,
            "Angle" => MateKind::Angle,
            "Tangent" => MateKind::Tangent,
            _ => return None,
        })
    }
}

/// The constraint rows of one mate and how far its geometry is from satisfying it at the
/// assembly pose (`None` when the mate does not fix a checkable value, e.g. a distance whose
/// value the file does not give). `Err` for geometry pairs the reduction does not handle.
pub struct MateRows {
    pub rows: Vec<Vector6<f64>>,
    pub residual: Option<f64>,
}

fn row(w: Vector3<f64>, v: Vector3<f64>) -> Vector6<f64> {
    Vector6::new(w.x, w.y, w.z, v.x, v.y, v.z)
}

/// Two unit vectors perpendicular to unit `d` (and to each other).
fn perp_basis(d: &Vector3<f64>) -> [Vector3<f64>; 2] {
    let a = if d.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
    let e1 = d.cross(&a).normalize();
    let e2 = d.cross(&e1);
    [e1, e2]
}

fn point_on_plane(x: &Vector3<f64>, p: &Vector3<f64>, n: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) -> f64 {
    out.push(row(x.cross(n), *n));
    n.dot(&(x - p)).abs()
}

fn point_on_line(x: &Vector3<f64>, p: &Vector3<f64>, d: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) -> f64 {
    for e in perp_basis(d) {
        out.push(row(x.cross(&e), e));
    }
    let r = x - p;
    (r - d * d.dot(&r)).norm()
}

fn point_on_point(x: &Vector3<f64>, p: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) -> f64 {
    for e in [Vector3::x(), Vector3::y(), Vector3::z()] {
        out.push(row(x.cross(&e), e));
    }
    (x - p).norm()
}

fn parallel(u: &Vector3<f64>, w: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) -> f64 {
    for e in perp_basis(u) {
        out.push(row(u.cross(&e), Vector3::zeros()));
    }
    u.cross(w).norm()
}

/// A fixed angle between `u` and `w`: one row, or the parallel rows when they are parallel.
fn angle(u: &Vector3<f64>, w: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) {
    let c = u.cross(w);
    if c.norm() < 1e-6 {
        parallel(u, w, out);
    } else {
        out.push(row(c.normalize(), Vector3::zeros()));
    }
}

fn perpendicular(u: &Vector3<f64>, w: &Vector3<f64>, out: &mut Vec<Vector6<f64>>) -> f64 {
    let c = u.cross(w);
    out.push(row(if c.norm() > 1e-12 { c.normalize() } else { perp_basis(u)[0] }, Vector3::zeros()));
    u.dot(w).abs()
}

/// Rows of one mate between `a` and `b` (either may be on either group).
pub fn mate_rows(kind: MateKind, a: &Geom, b: &Geom) -> Result<MateRows, String> {
    use GeomKind::*;
    // Order the pair so that the "lower" kind comes first: Plane < Line < Circle < Point.
    let rank = |k: GeomKind| match k {
        Plane => 0,
        Line => 1,
        Circle => 2,
        Point => 3,
    };
    let (g1, g2) = if rank(a.kind) <= rank(b.kind) { (a, b) } else { (b, a) };
    let mut rows = Vec::new();
    let r = &mut rows;
    let residual = match (kind, g1.kind, g2.kind) {
        // Planes: coincident or at a distance (the value is not in the file).
        (MateKind::Coincident, Plane, Plane) => {
            let a = parallel(&g2.axis, &g1.axis, r);
            Some(a.max(point_on_plane(&g2.point, &g1.point, &g1.axis, r)))
        }
        (MateKind::Distance, Plane, Plane) => {
            let a = parallel(&g2.axis, &g1.axis, r);
            point_on_plane(&g2.point, &g1.point, &g1.axis, r);
            Some(a)
        }
        (MateKind::Parallel, Plane, Plane) | (MateKind::Parallel, Line, Line) => Some(parallel(&g2.axis, &g1.axis, r)),
        (MateKind::Parallel, Plane, Line) => Some(perpendicular(&g2.axis, &g1.axis, r)),
        (MateKind::Perpendicular, Plane, Plane) | (MateKind::Perpendicular, Line, Line) => Some(perpendicular(&g2.axis, &g1.axis, r)),
        (MateKind::Perpendicular, Plane, Line) => Some(parallel(&g2.axis, &g1.axis, r)),
        (MateKind::Angle, Plane, Plane) | (MateKind::Angle, Line, Line) | (MateKind::Angle, Plane, Line) => {
            angle(&g2.axis, &g1.axis, r);
            None
        }
        // A line (or a cylinder's axis) in a plane.
        (MateKind::Coincident, Plane, Line) => {
            let a = perpendicular(&g2.axis, &g1.axis, r);
            Some(a.max(point_on_plane(&g2.point, &g1.point, &g1.axis, r)))
        }
        // A cylinder touching a plane, or a line at a distance from it: the axis stays parallel
        // to the plane at a fixed distance.
        (MateKind::Tangent | MateKind::Distance, Plane, Line) => {
            let a = perpendicular(&g2.axis, &g1.axis, r);
            point_on_plane(&g2.point, &g1.point, &g1.axis, r);
            Some(a)
        }
        // Coaxial lines, cylinders, circles.
        (MateKind::Coincident | MateKind::Concentric, Line, Line)
        | (MateKind::Concentric, Line, Circle)
        | (MateKind::Concentric, Circle, Circle) => {
            let a = parallel(&g2.axis, &g1.axis, r);
            Some(a.max(point_on_line(&g2.point, &g1.point, &g1.axis, r)))
        }
        // Coincident circles: same centre, same axis.
        (MateKind::Coincident, Circle, Circle) => {
            let a = parallel(&g2.axis, &g1.axis, r);
            Some(a.max(point_on_point(&g2.point, &g1.point, r)))
        }
        // A circle lying in a plane.
        (MateKind::Coincident, Plane, Circle) => {
            let a = parallel(&g2.axis, &g1.axis, r);
            Some(a.max(point_on_plane(&g2.point, &g1.point, &g1.axis, r)))
        }
        (MateKind::Coincident | MateKind::Concentric, Point, Point) => Some(point_on_point(&g2.point, &g1.point, r)),
        (MateKind::Coincident, Plane, Point) => Some(point_on_plane(&g2.point, &g1.point, &g1.axis, r)),
        (MateKind::Coincident | MateKind::Concentric, Line, Point) => Some(point_on_line(&g2.point, &g1.point, &g1.axis, r)),
        (k, k1, k2) => return Err(format!("{k:?} between {k1:?} and {k2:?} geometry is not supported")),
    };
    Ok(MateRows { rows, residual })
}

/// The joint a set of mates reduces to. Axes are unit vectors in world coordinates; `origin` is
/// a point on the joint's axes (the common point of its rotations), metres.
#[derive(Clone, Debug, PartialEq)]
pub enum Reduction {
    /// The mates leave every motion free (no joint between the pair).
    Free,
    Weld {
        origin: Vector3<f64>,
    },
    Revolute {
        origin: Vector3<f64>,
        axis: Vector3<f64>,
    },
    Prismatic {
        origin: Vector3<f64>,
        axes: Vec<Vector3<f64>>,
    },
    Cylindrical {
        origin: Vector3<f64>,
        axis: Vector3<f64>,
    },
    Planar {
        origin: Vector3<f64>,
        normal: Vector3<f64>,
        in_plane: [Vector3<f64>; 2],
    },
    Universal {
        origin: Vector3<f64>,
        axes: [Vector3<f64>; 2],
    },
    Spherical {
        origin: Vector3<f64>,
    },
    /// What the free motion is, in words.
    Unreducible {
        what: String,
    },
}

impl Reduction {
    /// Degrees of freedom the joint leaves.
    pub fn dof(&self) -> usize {
        match self {
            Reduction::Free => 6,
            Reduction::Weld { .. } => 0,
            Reduction::Revolute { .. } => 1,
            Reduction::Prismatic { axes, .. } => axes.len(),
            Reduction::Cylindrical { .. } | Reduction::Universal { .. } => 2,
            Reduction::Planar { .. } | Reduction::Spherical { .. } => 3,
            Reduction::Unreducible { .. } => 0,
        }
    }

    pub fn name(&self) -> &'static str {
        match self {
            Reduction::Free => "free",
            Reduction::Weld { .. } => "weld",
            Reduction::Revolute { .. } => "revolute",
            Reduction::Prismatic { .. } => "prismatic",
            Reduction::Cylindrical { .. } => "cylindrical",
            Reduction::Planar { .. } => "planar",
            Reduction::Universal { .. } => "universal",
            Reduction::Spherical { .. } => "spherical",
            Reduction::Unreducible { .. } => "unreducible",
        }
    }
}

/// A deterministic sign: the largest component positive.
fn canonical(v: Vector3<f64>) -> Vector3<f64> {
    let v = v.normalize();
    let i = v.iamax();
    if v[i] < 0.0 {
        -v
    } else {
        v
    }
}

/// Orthonormal basis of the null space of `m` (rows × cols), by SVD (`tol` relative to 1).
fn null_space(m: &DMatrix<f64>, tol: f64) -> Vec<nalgebra::DVector<f64>> {
    let cols = m.ncols();
    // Pad to at least `cols` rows so V is square.
    let rows = m.nrows().max(cols);
    let mut a = DMatrix::<f64>::zeros(rows, cols);
    a.view_mut((0, 0), (m.nrows(), cols)).copy_from(m);
    let Some(svd) = a.try_svd(false, true, f64::EPSILON, MAX_SVD_ITERATIONS) else { return Vec::new() };
    let Some(v_t) = svd.v_t else { return Vec::new() };
    (0..cols).filter(|&i| svd.singular_values[i] <= tol).map(|i| v_t.row(i).transpose()).collect()
}

/// Reduces constraint rows (twists about the world origin) to a joint. `points` are the mates'
/// geometry points, used to centre and scale the problem (and as the origin of joints that
/// have no fixed point, such as prismatic ones).
///
/// Internally the unknowns are `(ω, u)` with `u = v_c / L`: `v_c` the velocity of the point at
/// the centre `c` of `points`, `L` their extent. A row `[a, b]` on `(ω, v_0)` becomes
/// `[(a - c × b) / L, b]` on `(ω, u)` (then scaled to unit length), so the rank test does not
/// depend on where the assembly sits or on its units.
pub fn reduce(rows: &[Vector6<f64>], points: &[Vector3<f64>]) -> Reduction {
    // Non-finite input (a corrupt file's 1e308s composed into infinities) would stall the SVD.
    if rows.iter().any(|r| !r.iter().all(|x| x.is_finite())) || points.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
        return Reduction::Unreducible { what: "non-finite geometry".into() };
    }
    let n = points.len().max(1) as f64;
    let centre = points.iter().fold(Vector3::zeros(), |a, p| a + p) / n;
    let scale = points.iter().map(|p| (p - centre).norm()).fold(0.0_f64, f64::max).max(1e-3);
    let mut m = DMatrix::<f64>::zeros(rows.len(), 6);
    for (i, r) in rows.iter().enumerate() {
        let a = Vector3::new(r[0], r[1], r[2]);
        let b = Vector3::new(r[3], r[4], r[5]);
        let a = (a - centre.cross(&b)) / scale;
        let row6 = [a.x, a.y, a.z, b.x, b.y, b.z];
        let len = row6.iter().map(|x| x * x).sum::<f64>().sqrt();
        if len > 0.0 {
            for (k, x) in row6.iter().enumerate() {
                m[(i, k)] = x / len;
            }
        }
    }
    let null = null_space(&m, RANK_TOL);
    let k = null.len();
    if k == 0 {
        return Reduction::Weld { origin: centre };
    }
    if k == 6 {
        return Reduction::Free;
    }
    let omega = |x: &nalgebra::DVector<f64>| Vector3::new(x[0], x[1], x[2]);
    let vel = |x: &nalgebra::DVector<f64>| Vector3::new(x[3], x[4], x[5]);
    // Pure translations inside the null space: combinations with ω = 0.
    let mut wmat = DMatrix::<f64>::zeros(3, k);
    for (j, x) in null.iter().enumerate() {
        wmat.set_column(j, &omega(x));
    }
    let combos = null_space(&wmat, RANK_TOL);
    let t = combos.len();
    let r = k - t;
    let mut trans: Vec<Vector3<f64>> = Vec::new();
    for c in &combos {
        let mut v = Vector3::zeros();
        for (j, x) in null.iter().enumerate() {
            v += vel(x) * c[j];
        }
        for u in &trans {
            v -= u * u.dot(&v);
        }
        if v.norm() > 1e-9 {
            trans.push(v.normalize());
        }
    }
    if trans.len() != t {
        return Reduction::Unreducible { what: "degenerate translations".into() };
    }
    if r == 0 {
        if t <= 3 {
            let axes = trans.into_iter().map(canonical).collect();
            return Reduction::Prismatic { origin: centre, axes };
        }
        return Reduction::Unreducible { what: format!("{t} translations") };
    }
    // Rotation directions: the column space of the ω parts.
    let Some(svd) = wmat.clone().try_svd(true, false, f64::EPSILON, MAX_SVD_ITERATIONS) else {
        return Reduction::Unreducible { what: "SVD failed".into() };
    };
    let Some(uw) = svd.u else { return Reduction::Unreducible { what: "SVD failed".into() } };
    let rot_dirs: Vec<Vector3<f64>> = (0..svd.singular_values.len())
        .filter(|&i| svd.singular_values[i] > RANK_TOL)
        .map(|i| Vector3::new(uw[(0, i)], uw[(1, i)], uw[(2, i)]))
        .collect();
    if rot_dirs.len() != r {
        return Reduction::Unreducible { what: "inconsistent rank".into() };
    }
    // Every generator with a rotation: u (translations projected out) = q × ω for one point
    // q (relative to the centre, in units of L). Stacked least squares for q.
    let gens: Vec<(Vector3<f64>, Vector3<f64>)> = null
        .iter()
        .map(|x| {
            let mut v = vel(x);
            for tv in &trans {
                v -= tv * tv.dot(&v);
            }
            (omega(x), v)
        })
        .filter(|(w, _)| w.norm() > 1e-9)
        .collect();
    let mut a = DMatrix::<f64>::zeros(3 * gens.len(), 3);
    let mut b = nalgebra::DVector::<f64>::zeros(3 * gens.len());
    for (i, (w, v)) in gens.iter().enumerate() {
        // q × ω = -ω × q = -[ω]× q.
        a.view_mut((3 * i, 0), (3, 3)).copy_from(&(-w.cross_matrix()));
        b.rows_mut(3 * i, 3).copy_from(v);
    }
    let solved = a.clone().try_svd(true, true, f64::EPSILON, MAX_SVD_ITERATIONS).map(|svd| svd.solve(&b, 1e-9));
    let q = match solved {
        Some(Ok(q)) => Vector3::new(q[0], q[1], q[2]),
        _ => return Reduction::Unreducible { what: "no fixed point".into() },
    };
    let fit = (&a * nalgebra::DVector::from_column_slice(q.as_slice()) - &b).norm();
    if fit > RANK_TOL {
        return Reduction::Unreducible {
            what: format!("{r} rotation(s) and {t} translation(s) whose rotations share no axis or point (a screw-like motion)"),
        };
    }
    let origin = centre + q * scale;
    match (r, t) {
        (1, 0) => Reduction::Revolute { origin, axis: canonical(rot_dirs[0]) },
        (1, 1) => {
            let w = rot_dirs[0].normalize();
            if trans[0].cross(&w).norm() < 1e-6 {
                Reduction::Cylindrical { origin, axis: canonical(w) }
            } else {
                Reduction::Unreducible { what: "a rotation and a translation that are not along one axis".into() }
            }
        }
        (1, 2) => {
            let w = rot_dirs[0].normalize();
            if trans.iter().all(|tv| tv.dot(&w).abs() < 1e-6) {
                Reduction::Planar { origin, normal: canonical(w), in_plane: [trans[0], trans[1]] }
            } else {
                Reduction::Unreducible { what: "a rotation and two translations that do not form a planar joint".into() }
            }
        }
        (2, 0) => Reduction::Universal { origin, axes: [canonical(rot_dirs[0]), canonical(rot_dirs[1])] },
        (3, 0) => Reduction::Spherical { origin },
        _ => Reduction::Unreducible { what: format!("{r} rotation(s) and {t} translation(s)") },
    }
}

/// A rotation whose z axis is `axis` (unit): the frame of a joint at its axis.
pub fn frame_along(axis: &Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::rotation_between(&Vector3::z(), axis)
        .unwrap_or_else(|| UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI))
}
