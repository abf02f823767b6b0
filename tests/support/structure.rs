//! Structural rank of the emitted mechanism, in maximal coordinates, independent of the converter.
//!
//! A closed kinematic loop must reach Modelica without redundant constraint equations, or the
//! tools refuse the model as structurally singular (a planar four-bar closed by a plain revolute
//! has 3 redundant equations; `RevolutePlanarLoopConstraint` keeps the 2 independent ones). This
//! module counts them, at the start pose, by linear algebra on velocities:
//!
//! - [`model_structure`] reads the parsed `Mechanics.mo` and the walker's connector poses
//!   ([`crate::fk`]). Connectors joined by `connect` form connection sets (a cycle of connects
//!   adds no equation in Modelica); `FixedTranslation`/`FixedRotation` join sets into rigid
//!   groups, and one that joins two connectors already in the same group closes a rigid loop (6
//!   equations, all redundant). The world's group is fixed; every other group has a twist (ω, v
//!   at a reference point c). Each joint or constraint element adds one row `wᵀ(V_b - V_a) = 0`
//!   per constraint wrench w (the force or moment that element transmits), see [`Wrench`].
//! - [`cad_structure`] reads the XML alone: bodies (free) and grounds (fixed); each
//!   `<SimpleJoint>` lets its follower move relative to its base only within the span of its
//!   primitives' twists, so its rows are a basis of the wrenches that annihilate that span.
//!
//! rank = numerical rank of all rows, redundant = rows - rank, and mobility = 6 × free groups -
//! rank (the dimension of the velocities the constraints allow). The model is right when it
//! has no redundant row and the same mobility as the CAD assembly.

use std::collections::BTreeMap;

use nalgebra::{DMatrix, Matrix3, Matrix6, Vector3, Vector6};

use crate::fk::{element, Constraint, CutRotation, Element, Model, Poses};
use crate::truth::xml_frames;

/// Threshold on the singular values of the normalised rows (lengths scaled by the mechanism's
/// characteristic length L, every row of unit norm).
///
/// The XML prints 6 significant digits, so positions and axes carry relative errors up to
/// ~5e-7; a row built from them is perturbed by about that much, and by Weyl's inequality so is
/// each singular value (times √rows, ~1e-5 at most for hundreds of rows). A constraint that is
/// truly independent at a non-singular CAD pose has a singular value of order one, or of order
/// the ratio of its smallest to the largest lever arm (1e-2 .. 1e-3 in real assemblies), far
/// above 1e-4. Dependence hidden under data noise (a planar loop whose axes the export tilts by
/// 1e-6) therefore counts as dependence, which is what a Modelica tool sees too.
pub const TOL_RANK: f64 = 1e-4;

/// A constraint wrench: force `f` through point `p` plus a couple `m` (world axes, SI).
///
/// Its row pairs it with a relative twist (ω, v at c): `f·v + (m + (p - c) × f)·ω`, the power
/// the wrench would absorb. A force through p forbids relative motion of the points at p along
/// f; a pure moment forbids relative rotation about m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wrench {
    pub f: Vector3<f64>,
    pub m: Vector3<f64>,
    pub p: Vector3<f64>,
}

impl Wrench {
    /// A force `f` whose line passes through `p`.
    pub fn force(f: Vector3<f64>, p: Vector3<f64>) -> Self {
        Wrench { f, m: Vector3::zeros(), p }
    }

    /// A pure moment `m`.
    pub fn moment(m: Vector3<f64>) -> Self {
        Wrench { f: Vector3::zeros(), m, p: Vector3::zeros() }
    }

    /// The row in scaled twist coordinates (ω, v / L) about `c`: (moment about c / L, f),
    /// normalised to unit length (a zero row stays zero).
    fn row(&self, c: &Vector3<f64>, l: f64) -> Vector6<f64> {
        let m = self.m / l + ((self.p - c) / l).cross(&self.f);
        let r = Vector6::new(m.x, m.y, m.z, self.f.x, self.f.y, self.f.z);
        let n = r.norm();
        if n > 0.0 {
            r / n
        } else {
            r
        }
    }
}

/// The rows one element (a joint, a constraint, a rigid loop) adds between two groups.
#[derive(Clone, Debug)]
pub struct Coupling {
    /// The element's name (component name or joint name).
    pub name: String,
    /// Its class or kind, for messages.
    pub what: String,
    /// Free group of frame_a (base) and frame_b (follower); `None` is the fixed world.
    pub a: Option<usize>,
    pub b: Option<usize>,
    /// Where it acts, for the mechanism's reference point and length scale.
    pub origin: Option<Vector3<f64>>,
    /// Whether a walk from the world goes through it (false for loop-closing constraint
    /// elements, which are therefore always the ones named as closing their loop).
    pub walked: bool,
    pub wrenches: Vec<Wrench>,
}

/// An element that closed a loop, and what its rows added to the rank.
#[derive(Clone, Debug, PartialEq)]
pub struct Closure {
    pub element: String,
    pub what: String,
    pub rows: usize,
    /// Rows that raised the rank; `rows - independent` of them are redundant.
    pub independent: usize,
}

impl Closure {
    pub fn redundant(&self) -> usize {
        self.rows - self.independent
    }
}

/// The structural count of a model or an assembly.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Structure {
    /// Constraint rows (equations).
    pub rows: usize,
    /// Their numerical rank.
    pub rank: usize,
    /// rows - rank.
    pub redundant: usize,
    /// Rigid groups (model) or bodies and grounds (CAD), the fixed ones included.
    pub groups: usize,
    /// Groups that are not fixed to the world.
    pub free_groups: usize,
    /// 6 × free_groups - rank.
    pub mobility: usize,
    /// The smallest singular value counted in the rank, and the largest one below
    /// [`TOL_RANK`] (0 when none): the margins on either side of the tolerance.
    pub smallest_kept: f64,
    pub largest_dropped: f64,
    /// Every element that closed a loop (its groups were already connected), in order; plus an
    /// entry `spanning tree` when the tree elements' own rows are dependent.
    pub closures: Vec<Closure>,
}

impl Structure {
    /// The loop-closing elements with redundant rows, for messages.
    pub fn offenders(&self) -> String {
        let v: Vec<String> = self
            .closures
            .iter()
            .filter(|c| c.redundant() > 0)
            .map(|c| format!("{} ({}): {} rows, {} redundant", c.element, c.what, c.rows, c.redundant()))
            .collect();
        v.join("; ")
    }
}

/// Union-find over `0..n`.
struct Sets(Vec<usize>);

impl Sets {
    fn new(n: usize) -> Self {
        Sets((0..n).collect())
    }

    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }

    /// Joins the sets of `x` and `y`; false when they were one already.
    fn union(&mut self, x: usize, y: usize) -> bool {
        let (rx, ry) = (self.find(x), self.find(y));
        self.0[rx] = ry;
        rx != ry
    }
}

/// Numerical rank (singular values above [`TOL_RANK`]), with the smallest kept and the
/// largest dropped singular value.
fn rank(rows: &[Vector6<f64>], coupling_cols: &[(Option<usize>, Option<usize>)], columns: usize) -> (usize, f64, f64) {
    if rows.is_empty() || columns == 0 {
        return (0, f64::INFINITY, 0.0);
    }
    let mut m = DMatrix::<f64>::zeros(rows.len(), columns);
    for (i, (r, (a, b))) in rows.iter().zip(coupling_cols).enumerate() {
        if let Some(b) = b {
            for k in 0..6 {
                m[(i, 6 * b + k)] += r[k];
            }
        }
        if let Some(a) = a {
            for k in 0..6 {
                m[(i, 6 * a + k)] -= r[k];
            }
        }
    }
    let sv = m.singular_values();
    let kept = sv.iter().filter(|s| **s > TOL_RANK);
    let smallest = kept.clone().copied().fold(f64::INFINITY, f64::min);
    let dropped = sv.iter().filter(|s| **s <= TOL_RANK).copied().fold(0.0, f64::max);
    (kept.count(), smallest, dropped)
}

/// The couplings in the order a breadth-first walk meets them: from the world (node `free`)
/// over walked couplings (in their order at each node), then from each group not reached yet,
/// then the couplings not walked through. The first coupling to reach a group is part of the
/// spanning tree; one met when both its groups are reached closes a loop.
fn walk_order(free: usize, couplings: &[Coupling]) -> Vec<usize> {
    let mut adjacency = vec![Vec::new(); free + 1];
    for (i, c) in couplings.iter().enumerate().filter(|(_, c)| c.walked) {
        let (a, b) = (c.a.unwrap_or(free), c.b.unwrap_or(free));
        adjacency[a].push(i);
        if b != a {
            adjacency[b].push(i);
        }
    }
    let mut seen = vec![false; free + 1];
    let mut used = vec![false; couplings.len()];
    let mut order = Vec::new();
    for start in std::iter::once(free).chain(0..free) {
        if std::mem::replace(&mut seen[start], true) {
            continue;
        }
        let mut queue = std::collections::VecDeque::from([start]);
        while let Some(x) = queue.pop_front() {
            for &i in &adjacency[x] {
                if std::mem::replace(&mut used[i], true) {
                    continue;
                }
                order.push(i);
                for y in [couplings[i].a.unwrap_or(free), couplings[i].b.unwrap_or(free)] {
                    if !std::mem::replace(&mut seen[y], true) {
                        queue.push_back(y);
                    }
                }
            }
        }
    }
    order.extend((0..couplings.len()).filter(|&i| !used[i]));
    order
}

/// The rank of the couplings' rows over `free` free groups, computed per mechanism (the groups
/// connected without passing through the world), each scaled about its own centroid c of the
/// elements' origins by L, the largest distance of one from c.
pub fn solve(free: usize, groups: usize, couplings: &[Coupling]) -> Structure {
    let mut mech = Sets::new(free);
    for c in couplings {
        if let (Some(a), Some(b)) = (c.a, c.b) {
            mech.union(a, b);
        }
    }
    // Tree or loop-closing, in the order of a breadth-first walk from the world; `free` is the
    // fixed world.
    let mut tree = Sets::new(free + 1);
    let mut closes = vec![false; couplings.len()];
    for i in walk_order(free, couplings) {
        closes[i] = !tree.union(couplings[i].a.unwrap_or(free), couplings[i].b.unwrap_or(free));
    }

    let mut by_mech: BTreeMap<Option<usize>, Vec<usize>> = BTreeMap::new();
    for (i, c) in couplings.iter().enumerate() {
        let key = c.a.or(c.b).map(|g| mech.find(g));
        by_mech.entry(key).or_default().push(i);
    }
    let mut s = Structure { groups, free_groups: free, smallest_kept: f64::INFINITY, ..Structure::default() };
    for (key, members) in by_mech {
        // Local columns: the mechanism's free groups.
        let mut cols: BTreeMap<usize, usize> = BTreeMap::new();
        if key.is_some() {
            for &i in &members {
                for g in [couplings[i].a, couplings[i].b].into_iter().flatten() {
                    let n = cols.len();
                    cols.entry(g).or_insert(n);
                }
            }
        }
        let origins: Vec<Vector3<f64>> = members.iter().filter_map(|&i| couplings[i].origin).collect();
        let c = if origins.is_empty() { Vector3::zeros() } else { origins.iter().sum::<Vector3<f64>>() / origins.len() as f64 };
        let l = origins.iter().map(|o| (o - c).norm()).fold(0.0, f64::max);
        let l = if l > 1e-9 { l } else { 1.0 };

        let mut rows = Vec::new();
        let mut at = Vec::new();
        let push = |i: usize, rows: &mut Vec<Vector6<f64>>, at: &mut Vec<(Option<usize>, Option<usize>)>| {
            let cp = &couplings[i];
            let col = |g: Option<usize>| g.and_then(|g| cols.get(&g).copied());
            for w in &cp.wrenches {
                rows.push(w.row(&c, l));
                at.push((col(cp.a), col(cp.b)));
            }
        };
        let (tree_members, closers): (Vec<usize>, Vec<usize>) = members.iter().partition(|&&i| !closes[i]);
        for &i in &tree_members {
            push(i, &mut rows, &mut at);
        }
        let (mut r, _, _) = rank(&rows, &at, 6 * cols.len());
        if r < rows.len() {
            s.closures.push(Closure {
                element: "spanning tree".into(),
                what: format!("{} elements from {}", tree_members.len(), couplings[tree_members[0]].name),
                rows: rows.len(),
                independent: r,
            });
        }
        for &i in &closers {
            let before = rows.len();
            push(i, &mut rows, &mut at);
            let (r2, _, _) = rank(&rows, &at, 6 * cols.len());
            s.closures.push(Closure {
                element: couplings[i].name.clone(),
                what: couplings[i].what.clone(),
                rows: rows.len() - before,
                independent: r2 - r,
            });
            r = r2;
        }
        let (_, kept, dropped) = rank(&rows, &at, 6 * cols.len());
        s.smallest_kept = s.smallest_kept.min(kept);
        s.largest_dropped = s.largest_dropped.max(dropped);
        s.rows += rows.len();
        s.rank += r;
    }
    s.closures.sort_by_key(|c| couplings.iter().position(|k| k.name == c.element).unwrap_or(usize::MAX));
    s.redundant = s.rows - s.rank;
    s.mobility = 6 * free - s.rank;
    s
}

/// Two unit vectors perpendicular to unit `u` and to each other.
fn perpendicular(u: &Vector3<f64>) -> [Vector3<f64>; 2] {
    let seed = if u.x.abs() < 0.6 { Vector3::x() } else { Vector3::y() };
    let e1 = u.cross(&seed).normalize();
    [e1, u.cross(&e1)]
}

fn axes() -> [Vector3<f64>; 3] {
    [Vector3::x(), Vector3::y(), Vector3::z()]
}

/// The structure of a parsed `Mechanics.mo` at the start poses the walker found.
pub fn model_structure(model: &Model, poses: &Poses) -> Result<Structure, String> {
    let mut elements = Vec::new();
    let mut index: BTreeMap<String, usize> = BTreeMap::new();
    let mut world = None;
    for c in &model.components {
        let e = element(model, c)?;
        for conn in e.connectors() {
            let n = index.len();
            index.insert(format!("{}.{conn}", c.name), n);
        }
        if e == Element::World {
            world = Some(format!("{}.frame_b", c.name));
        }
        elements.push((c, e));
    }
    let world = world.ok_or("no World component")?;
    let id = |r: &str| index.get(r).copied().ok_or_else(|| format!("`{r}` is not a frame connector of the model"));

    // Connection sets, then rigid groups over them.
    let mut sets = Sets::new(index.len());
    // Frame connects only: 1-D couplings between drive flanges (URDF mimic) act on joint
    // coordinates, not on frames.
    for (a, b) in model.connects.iter().filter(|(a, b)| !crate::fk::is_flange(a) && !crate::fk::is_flange(b)) {
        sets.union(id(a)?, id(b)?);
    }
    let pose = |r: &str| poses.get(r).ok_or_else(|| format!("`{r}` has no start pose (not reached from the world)"));
    let mut loops = Vec::new();
    for (c, e) in &elements {
        if let Element::Rigid(_) = e {
            let (fa, fb) = (format!("{}.frame_a", c.name), format!("{}.frame_b", c.name));
            if !sets.union(id(&fa)?, id(&fb)?) {
                loops.push((c, fa));
            }
        }
    }
    let mut dense: BTreeMap<usize, usize> = BTreeMap::new();
    let world_root = sets.find(id(&world)?);
    for i in 0..index.len() {
        let r = sets.find(i);
        if r != world_root && !dense.contains_key(&r) {
            let n = dense.len();
            dense.insert(r, n);
        }
    }
    let free = dense.len();
    let mut group = |r: &str| -> Result<Option<usize>, String> { Ok(dense.get(&sets.find(id(r)?)).copied()) };

    let mut couplings = Vec::new();
    for (c, fa) in loops {
        let g = group(&fa)?;
        let origin = poses.get(&fa).map(|p| p.translation.vector);
        let o = origin.unwrap_or_default();
        let wrenches = axes().iter().map(|e| Wrench::force(*e, o)).chain(axes().map(Wrench::moment)).collect();
        couplings.push(Coupling {
            name: c.name.clone(),
            what: format!("{}, rigid loop", c.class),
            a: g,
            b: g,
            origin,
            walked: true,
            wrenches,
        });
    }
    for (c, e) in &elements {
        let (fa, fb) = (format!("{}.frame_a", c.name), format!("{}.frame_b", c.name));
        let wrenches = match e {
            Element::World | Element::Leaf | Element::Rigid(_) => continue,
            Element::Revolute { n, .. } => {
                let a = pose(&fa)?;
                let (u, p) = (a.rotation * n.into_inner(), a.translation.vector);
                let mut w: Vec<Wrench> = axes().iter().map(|e| Wrench::force(*e, p)).collect();
                w.extend(perpendicular(&u).map(Wrench::moment));
                w
            }
            Element::Prismatic { n, .. } => {
                let a = pose(&fa)?;
                let (u, p) = (a.rotation * n.into_inner(), a.translation.vector);
                let mut w: Vec<Wrench> = axes().map(Wrench::moment).to_vec();
                w.extend(perpendicular(&u).map(|f| Wrench::force(f, p)));
                w
            }
            Element::Spherical => {
                let p = pose(&fa)?.translation.vector;
                axes().iter().map(|e| Wrench::force(*e, p)).collect()
            }
            // Translational equations act at frame_b's origin (the exact linearisation of
            // "r_rel resolved in frame_a along e is zero"; it is frame_a's origin too when the
            // two coincide).
            Element::Constraint(Constraint::PlanarLoop(n)) => {
                let (a, b) = (pose(&fa)?, pose(&fb)?);
                let p = b.translation.vector;
                perpendicular(&(a.rotation * n)).map(|f| Wrench::force(f, p)).to_vec()
            }
            Element::Constraint(Constraint::Cut(cut)) => {
                let (a, b) = (pose(&fa)?, pose(&fb)?);
                let p = b.translation.vector;
                let mut w: Vec<Wrench> =
                    axes().iter().zip(cut.locked).filter(|(_, locked)| *locked).map(|(e, _)| Wrench::force(a.rotation * e, p)).collect();
                match &cut.rotation {
                    CutRotation::Free => {}
                    CutRotation::About(n) => w.extend(perpendicular(&(a.rotation * n)).map(Wrench::moment)),
                    CutRotation::Locked => w.extend(axes().map(Wrench::moment)),
                    CutRotation::Perpendicular { n_a, n_b } => {
                        w.push(Wrench::moment((b.rotation * n_b).cross(&(a.rotation * n_a))));
                    }
                }
                w
            }
        };
        let origin = poses.get(&fa).map(|p| p.translation.vector);
        let walked = e.transform().is_some();
        couplings.push(Coupling { name: c.name.clone(), what: c.class.clone(), a: group(&fa)?, b: group(&fb)?, origin, walked, wrenches });
    }
    Ok(solve(free, free + 1, &couplings))
}

// ---------------------------------------------------------------------------------------------
// The CAD side: a scanner of first-generation SimMechanics XML.

/// The text of the first `<tag>...</tag>` in `block`, trimmed of spaces and quotes.
fn xml_value<'a>(block: &'a str, tag: &str) -> Option<&'a str> {
    let open = format!("<{tag}>");
    let start = block.find(&open)? + open.len();
    let end = block[start..].find(&format!("</{tag}>"))? + start;
    Some(block[start..end].trim().trim_matches('"'))
}

/// Every `<tag>...</tag>` block (the format does not nest an element in itself).
fn xml_blocks<'a>(text: &'a str, tag: &str) -> Vec<&'a str> {
    let close = format!("</{tag}>");
    text.split(&format!("<{tag}>")).skip(1).map(|b| b.split(&close).next().unwrap_or(b)).collect()
}

/// The `ref` of the first `<Frame ref="N">` in `block`.
fn frame_ref(block: &str) -> Option<&str> {
    let start = block.find("<Frame ref=\"")? + 12;
    let end = block[start..].find('"')? + start;
    Some(&block[start..end])
}

/// Frame refs (with the frame's nodeID) owned by each `<Frame ref=..>` in `block`.
fn owned_frames(block: &str) -> Vec<(&str, &str)> {
    block
        .split("<Frame")
        .skip(1)
        .filter_map(|f| {
            let head = &f[..f.find('>')?];
            let r = head.trim().strip_prefix("ref=\"")?.strip_suffix('"')?;
            Some((r, xml_value(f, "nodeID")?))
        })
        .collect()
}

fn vec3(s: &str) -> Option<Vector3<f64>> {
    let v: Vec<f64> = s.split(',').filter_map(|x| x.trim().parse().ok()).collect();
    (v.len() == 3).then(|| Vector3::new(v[0], v[1], v[2]))
}

/// The structure of the assembly in a first-generation SimMechanics XML: bodies are free,
/// grounds fixed; each `<SimpleJoint>` constrains its follower body's twist relative to its base
/// body to the span of its primitives: a revolute about its world axis through the base frame's
/// origin, a prismatic along its axis, a spherical (3 rotations) about the base frame's origin, a
/// weld nothing, a revolute or prismatic whose axis is (0, 0, 0) nothing either (it has no
/// direction to move along). A primitive's `referenceFrame` `BASE` or `FOLLOWER` gives the axis
/// in that frame's axes. The rows are an orthonormal basis of the wrenches annihilating that span.
pub fn cad_structure(xml: &str) -> Result<Structure, String> {
    let poses = xml_frames(xml);
    // Frame ref -> (owner: Some(free body) / None (ground), frame nodeID).
    let mut owner: BTreeMap<&str, (Option<usize>, &str)> = BTreeMap::new();
    let bodies = xml_blocks(xml, "Body");
    for (i, b) in bodies.iter().enumerate() {
        for (r, node) in owned_frames(b) {
            owner.insert(r, (Some(i), node));
        }
    }
    let grounds = xml_blocks(xml, "Ground");
    for g in &grounds {
        for (r, node) in owned_frames(g) {
            owner.insert(r, (None, node));
        }
    }
    let mut couplings = Vec::new();
    for j in xml_blocks(xml, "SimpleJoint") {
        let name = xml_value(j, "nodeID").or(xml_value(j, "name")).unwrap_or("?").to_string();
        // The side's body (None: a ground), its frame's axes and origin.
        type Side = (Option<usize>, Matrix3<f64>, Vector3<f64>);
        let side = |tag: &str| -> Result<Side, String> {
            let r = xml_blocks(j, tag).first().and_then(|s| frame_ref(s)).ok_or_else(|| format!("joint {name}: no {tag} frame"))?;
            let (body, node) = owner.get(r).ok_or_else(|| format!("joint {name}: {tag} frame ref {r} belongs to no body or ground"))?;
            let f = poses.get(*node).ok_or_else(|| format!("joint {name}: no unambiguous pose for frame {node}"))?;
            Ok((*body, f.rotation, f.position))
        };
        let (a, rot_base, p) = side("base")?;
        let (b, rot_follower, _) = side("follower")?;
        let mut twists: Vec<Vector6<f64>> = Vec::new();
        let mut kinds = Vec::new();
        for prim in xml_blocks(j, "Primitive") {
            let kind = xml_value(prim, "name").unwrap_or("");
            let axis = || -> Result<Vector3<f64>, String> {
                let v = xml_value(prim, "axis").and_then(vec3).ok_or_else(|| format!("joint {name}: {kind} without a 3-vector axis"))?;
                let v = match xml_value(prim, "referenceFrame").unwrap_or("WORLD") {
                    "BASE" => rot_base * v,
                    "FOLLOWER" => rot_follower * v,
                    _ => v,
                };
                // An axis (0, 0, 0) has no direction: the primitive allows no motion.
                Ok(v.try_normalize(0.0).unwrap_or_default())
            };
            // Twists at the base frame's origin p: (ω, v_p).
            match kind {
                "revolute" => {
                    let u = axis()?;
                    twists.push(Vector6::new(u.x, u.y, u.z, 0.0, 0.0, 0.0));
                }
                "prismatic" => {
                    let u = axis()?;
                    twists.push(Vector6::new(0.0, 0.0, 0.0, u.x, u.y, u.z));
                }
                "spherical" => twists.extend((0..3).map(|k| Vector6::ith(k, 1.0))),
                "weld" => {}
                other => return Err(format!("joint {name}: unknown primitive {other:?}")),
            }
            kinds.push(kind);
        }
        // The annihilator: eigenvectors of Σ t tᵀ with a zero eigenvalue, as wrenches at p.
        let gram: Matrix6<f64> = twists.iter().map(|t| t * t.transpose()).sum();
        let eig = gram.symmetric_eigen();
        let wrenches = (0..6)
            .filter(|&k| eig.eigenvalues[k] <= TOL_RANK * TOL_RANK)
            .map(|k| {
                let w = eig.eigenvectors.column(k);
                Wrench { m: Vector3::new(w[0], w[1], w[2]), f: Vector3::new(w[3], w[4], w[5]), p }
            })
            .collect();
        couplings.push(Coupling { name, what: kinds.join("+"), a, b, origin: Some(p), walked: true, wrenches });
    }
    Ok(solve(bodies.len(), bodies.len() + grounds.len(), &couplings))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::workspace_root;
    use crate::fk::forward_kinematics;
    use crate::fk::tests::{
        body, cut_constraint, fk_ok, four_bar, mechanics, planar_constraint, prismatic, revolute, spherical, translation, world,
    };
    use crate::modelica::parse_mechanics;

    fn structure_of(text: &str) -> Structure {
        let (model, poses) = fk_ok(text);
        model_structure(&model, &poses).unwrap_or_else(|e| panic!("structure: {e}"))
    }

    #[track_caller]
    fn assert_counts(s: &Structure, rows: usize, redundant: usize, mobility: usize) {
        assert_eq!((s.rows, s.redundant, s.mobility), (rows, redundant, mobility), "rows, redundant, mobility: {s:?}");
        assert_eq!(s.rank, s.rows - s.redundant);
    }

    const I: [f64; 6] = [0.001, 0.001, 0.001, 0.0, 0.0, 0.0];

    #[test]
    fn planar_four_bar_needs_the_planar_loop_constraint() {
        let text = four_bar(0.0, [0.0, 0.0, 1.0], true);
        let s = structure_of(&text);
        // Crank, coupler, rocker: 18 columns; J1, J2, J3 5 rows each, J4 2 rows.
        assert_eq!((s.groups, s.free_groups), (4, 3));
        assert_counts(&s, 17, 0, 1);
        assert_eq!(s.closures.len(), 1);
        assert_eq!(s.closures[0].element, "J4");
        assert_eq!((s.closures[0].rows, s.closures[0].independent), (2, 2));

        // The mutation: the same loop closed by a plain revolute (same start poses). Its 5
        // rows add only the 2 the planar constraint has.
        let (_, poses) = fk_ok(&text);
        let mutated = text.replace(
            "Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint J4(n={0.0, 0.0, 1.0})",
            "Demo.Components.Revolute J4(n={0.0, 0.0, 1.0})",
        );
        assert_ne!(mutated, text);
        let model = parse_mechanics(&mutated).expect("parse");
        let s = model_structure(&model, &poses).expect("structure");
        assert_counts(&s, 20, 3, 1);
        assert_eq!(s.closures[0].redundant(), 3);
        assert_eq!(s.offenders(), "J4 (Demo.Components.Revolute): 5 rows, 3 redundant");
    }

    #[test]
    fn slider_crank_closed_at_a_revolute() {
        // Crank a about z at the origin, coupler b, slider on the x axis; the loop closes at the
        // coupler-slider pin C.
        let (a, b, theta): (f64, f64, f64) = (0.2, 0.7, 0.9);
        let xc = a * theta.cos() + (b * b - (a * theta.sin()).powi(2)).sqrt();
        let psi = (-a * theta.sin()).atan2(xc - a * theta.cos());
        let text = mechanics(
            &[
                world(),
                revolute("J1", [0.0, 0.0, 1.0], theta, false),
                body("crank", [0.1, 0.0, 0.0], I),
                translation("crank_CS2", [a, 0.0, 0.0]),
                revolute("J2", [0.0, 0.0, 1.0], psi - theta, false),
                body("coupler", [0.3, 0.0, 0.0], I),
                translation("coupler_CS2", [b, 0.0, 0.0]),
                prismatic("P", [1.0, 0.0, 0.0], xc),
                body("slider", [0.0; 3], I),
                planar_constraint("J3", [0.0, 0.0, 1.0]),
            ],
            &[
                ("world.frame_b", "J1.frame_a"),
                ("J1.frame_b", "crank.frame_a"),
                ("crank.frame_a", "crank_CS2.frame_a"),
                ("crank_CS2.frame_b", "J2.frame_a"),
                ("J2.frame_b", "coupler.frame_a"),
                ("coupler.frame_a", "coupler_CS2.frame_a"),
                ("world.frame_b", "P.frame_a"),
                ("P.frame_b", "slider.frame_a"),
                ("coupler_CS2.frame_b", "J3.frame_a"),
                ("J3.frame_b", "slider.frame_a"),
            ],
        );
        let s = structure_of(&text);
        assert_counts(&s, 17, 0, 1);
        assert_eq!(s.closures.len(), 1);
        assert_eq!(s.closures[0].element, "J3");
    }

    /// A loop ground -J1- L1 -J2- L2 -J3- L3 -J4- ground through the points `p` (frames stay
    /// world-aligned, every joint starts at 0): link k's frame_a sits at p[k], and `joints[k]`
    /// is the declaration of `Jk+1` between p[k]. `J4.frame_b` is on the ground at p[3].
    fn spatial_loop(p: [[f64; 3]; 4], joints: [String; 4]) -> String {
        let d = |i: usize, j: usize| [p[j][0] - p[i][0], p[j][1] - p[i][1], p[j][2] - p[i][2]];
        let [j1, j2, j3, j4] = joints;
        mechanics(
            &[
                world(),
                translation("G1", p[0]),
                translation("G4", p[3]),
                j1,
                body("L1", [0.0; 3], I),
                translation("L1_CS2", d(0, 1)),
                j2,
                body("L2", [0.0; 3], I),
                translation("L2_CS2", d(1, 2)),
                j3,
                body("L3", [0.0; 3], I),
                translation("L3_CS2", d(2, 3)),
                j4,
            ],
            &[
                ("world.frame_b", "G1.frame_a"),
                ("world.frame_b", "G4.frame_a"),
                ("G1.frame_b", "J1.frame_a"),
                ("J1.frame_b", "L1.frame_a"),
                ("L1.frame_a", "L1_CS2.frame_a"),
                ("L1_CS2.frame_b", "J2.frame_a"),
                ("J2.frame_b", "L2.frame_a"),
                ("L2.frame_a", "L2_CS2.frame_a"),
                ("L2_CS2.frame_b", "J3.frame_a"),
                ("J3.frame_b", "L3.frame_a"),
                ("L3.frame_a", "L3_CS2.frame_a"),
                ("L3_CS2.frame_b", "J4.frame_a"),
                ("J4.frame_b", "G4.frame_b"),
            ],
        )
    }

    const P: [[f64; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.2], [1.1, 0.9, -0.1], [0.1, 1.0, 0.3]];

    fn rev(name: &str, n: [f64; 3]) -> String {
        revolute(name, n, 0.0, false)
    }

    #[test]
    fn immobile_spatial_loop_of_four_revolutes() {
        let (u1, u2, u3, u4) = ([0.0, 0.0, 1.0], [0.3, 1.0, 0.2], [1.0, 0.2, 0.5], [0.1, -0.4, 1.0]);
        // Closed by Constraints.Spherical: 3 x 5 + 3 rows on 3 links, all independent.
        let s = structure_of(&spatial_loop(P, [rev("J1", u1), rev("J2", u2), rev("J3", u3), cut_constraint("J4", "Spherical", "")]));
        assert_counts(&s, 18, 0, 0);
        assert_eq!(s.closures.len(), 1);
        assert_eq!((s.closures[0].element.as_str(), s.closures[0].independent), ("J4", 3));

        // Closed by a plain revolute: 2 of its 5 rows are redundant.
        let s = structure_of(&spatial_loop(P, [rev("J1", u1), rev("J2", u2), rev("J3", u3), rev("J4", u4)]));
        assert_counts(&s, 20, 2, 0);
        // The walk from the world reaches L1 and L3 first, then L2 from L1: J3 closes the loop.
        assert_eq!(s.offenders(), "J3 (Demo.Components.Revolute): 5 rows, 2 redundant");

        // Constraints.Revolute about u4 is the same 5 equations: still 2 redundant.
        let s = structure_of(&spatial_loop(
            P,
            [rev("J1", u1), rev("J2", u2), rev("J3", u3), cut_constraint("J4", "Revolute", "n={0.1, -0.4, 1.0}")],
        ));
        assert_counts(&s, 20, 2, 0);
        // Unlocking two translations leaves 3 independent rows.
        let s = structure_of(&spatial_loop(
            P,
            [
                rev("J1", u1),
                rev("J2", u2),
                rev("J3", u3),
                cut_constraint("J4", "Prismatic", "x_locked=false, y_locked=false, z_locked=false"),
            ],
        ));
        assert_counts(&s, 18, 0, 0);
    }

    #[test]
    fn rssr_closed_by_a_spherical() {
        // Crank about z at P0, coupler between spherical joints at P1 and P2, rocker about a
        // generic axis at P3: one degree of freedom plus the coupler's spin about P1-P2.
        let text =
            spatial_loop(P, [rev("J1", [0.0, 0.0, 1.0]), spherical("J2", false), spherical("J3", false), rev("J4", [0.1, -0.4, 1.0])]);
        let s = structure_of(&text);
        assert_counts(&s, 16, 0, 2);
        // The walker closed the loop through J4 (the last joint reached), a tree element here:
        // the loop closer is whichever element found both groups connected.
        assert_eq!(s.closures.len(), 1);
        assert_eq!(s.closures[0].independent, s.closures[0].rows);
    }

    #[test]
    fn rigid_loop_is_six_redundant_equations() {
        // A pendulum whose link carries two fixed translations to the same point.
        let text = mechanics(
            &[
                world(),
                revolute("J", [0.0, 0.0, 1.0], 0.3, true),
                body("link", [0.5, 0.0, 0.0], I),
                translation("T1", [1.0, 0.0, 0.0]),
                translation("T2", [1.0, 0.0, 0.0]),
                body("tip", [0.0; 3], I),
            ],
            &[
                ("world.frame_b", "J.frame_a"),
                ("J.frame_b", "link.frame_a"),
                ("link.frame_a", "T1.frame_a"),
                ("link.frame_a", "T2.frame_a"),
                ("T1.frame_b", "tip.frame_a"),
                ("T2.frame_b", "tip.frame_a"),
            ],
        );
        let s = structure_of(&text);
        assert_counts(&s, 11, 6, 1);
        assert_eq!(s.offenders(), "T2 (Modelica.Mechanics.MultiBody.Parts.FixedTranslation, rigid loop): 6 rows, 6 redundant");

        // A cycle of plain connects is one connection set: no equation, nothing redundant.
        let text = mechanics(
            &[world(), body("b", [0.0; 3], I), body("c", [0.0; 3], I)],
            &[("world.frame_b", "b.frame_a"), ("b.frame_a", "c.frame_a"), ("c.frame_a", "world.frame_b")],
        );
        let s = structure_of(&text);
        assert_eq!((s.groups, s.rows, s.mobility, s.closures.len()), (1, 0, 0, 0));
    }

    #[test]
    fn free_bodies_and_unreached_joints() {
        // A free body (r_0 start) has 6 degrees of freedom; a joint on a connector the walker
        // never reached is an error naming it.
        let text = mechanics(&[world(), body("b", [0.0; 3], I)], &[]);
        let s = structure_of(&text.replace("m=1.5,", "m=1.5, r_0(start={0.0, 1.0, 0.0}),"));
        assert_eq!((s.free_groups, s.mobility, s.rows), (1, 6, 0));

        let text = mechanics(&[world(), rev("J", [0.0, 0.0, 1.0]), body("b", [0.0; 3], I)], &[("J.frame_b", "b.frame_a")]);
        let model = parse_mechanics(&text).expect("parse");
        let poses = forward_kinematics(&model).expect("fk");
        let e = model_structure(&model, &poses).expect_err("J.frame_a has no pose");
        assert!(e.contains("`J.frame_a` has no start pose"), "{e}");
    }

    #[test]
    fn cad_side_of_the_golden_four_bar_and_composite_joint() {
        let xml = |case: &str| {
            let dir = workspace_root().join("tests/in").join(case);
            let path = crate::common::files_with_ext(&dir, &[".xml"]).pop().expect("an xml");
            std::fs::read_to_string(path).expect("read")
        };
        // RootPart, crank, coupler, rocker; the ground weld (6 rows) and four revolutes (20 rows,
        // 3 of them redundant: the CAD loop is planar).
        let s = cad_structure(&xml("fourbar")).expect("fourbar");
        assert_eq!((s.groups, s.free_groups), (5, 4));
        assert_counts(&s, 26, 3, 1);
        assert_eq!(s.offenders(), "41:-:45 (revolute): 5 rows, 3 redundant");

        // Universal (2 revolutes: 4 rows), free joint (3 prismatic + spherical: 0 rows), a
        // weld and the ground weld; 4 bodies.
        let s = cad_structure(&xml("composite_joint")).expect("composite_joint");
        assert_eq!(s.free_groups, 4);
        assert_eq!(s.redundant, 0);
        assert_eq!(s.mobility, 2 + 6);
    }

    #[test]
    fn wrench_rows_pair_with_twists() {
        // A force along x through (0, 1, 0) absorbs the power of a rotation about z through the
        // origin: v at (0, 1, 0) is z x (0, 1, 0) = (-1, 0, 0).
        let c = Vector3::zeros();
        let w = Wrench::force(Vector3::x(), Vector3::y());
        let r = w.row(&c, 1.0);
        let twist = Vector6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
        assert!((r.dot(&twist) * 2f64.sqrt() + 1.0).abs() < 1e-15, "{r}");
        assert_eq!(Wrench::moment(Vector3::zeros()).row(&c, 2.0), Vector6::zeros());
        let [e1, e2] = perpendicular(&Vector3::new(0.0, 0.6, 0.8));
        assert!(e1.dot(&e2).abs() < 1e-15 && (e1.norm() - 1.0).abs() < 1e-15 && e2.dot(&Vector3::new(0.0, 0.6, 0.8)).abs() < 1e-15);
    }
}
