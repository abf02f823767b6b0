//! Collision geometry in the package (issue 14): each body's convex shape from its mesh
//! ([`crate::collision::body_shape`]), written as `Resources/Collision/<body>.obj` (for people
//! and tools) and `Resources/Collision/shapes.json` (the exact parts, for the service), the
//! report's `collision` section, and the pairs that interfere at the CAD pose.
//!
//! Which pairs are checked: bodies joined by a joint may touch (allowed) unless the user said
//! otherwise; every other pair is checked unless the user allowed it. Edits are keyed by the
//! bodies' Modelica names, so they survive CAD changes.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use nalgebra::Isometry3;
use serde::Serialize;

use crate::collision::{self, BodyShape, ConvexPart, ShapeCache, ShapeKey, ShapeOptions};
use crate::pipeline::back::bundle::{Deflater, FileData};
use crate::pipeline::ir::{FrameOwner, Mesh, Model, Warning};

/// Interferences (the deepest) and collision shape warnings (the first, by body) given a
/// warning each; the rest get one summary warning.
pub const MAX_LISTED: usize = 20;

/// The user's edits of the allowed-collision matrix: (a, b) with a < b → allowed.
pub type AllowedEdits = BTreeMap<(String, String), bool>;

/// The collision geometry of a model and the rule for its pairs.
pub struct Collision {
    pub shapes: Vec<Option<BodyShape>>,
    /// Pairs allowed to touch by default, and why: joined by a joint, or welded together.
    joined: BTreeMap<(usize, usize), String>,
    edits: BTreeMap<(usize, usize), bool>,
    /// Shapes computed by this conversion and shapes served by the cache.
    pub counts: ShapeCounts,
}

/// A pair allowed to touch by default.
#[derive(Serialize, Debug, Clone)]
pub struct AllowedPair {
    pub a: String,
    pub b: String,
    pub why: String,
}

#[derive(Serialize, Debug, Clone)]
pub struct BodyCollisionReport {
    pub body: String,
    /// `box`, `cylinder`, `sphere`, `capsule`, `hull`, `decomposition`, or `none` (no mesh).
    pub kind: &'static str,
    pub parts: usize,
    pub vertices: usize,
    /// m.
    pub fit_error: f64,
    pub volume_ratio: f64,
    pub source_triangles: usize,
    pub warnings: Vec<String>,
}

#[derive(Serialize, Debug, Clone)]
pub struct InterferenceReport {
    pub a: String,
    pub b: String,
    /// Penetration depth, m (> 0).
    pub depth: f64,
    /// Witness points in world coordinates at the CAD pose, m.
    pub point_a: [f64; 3],
    pub point_b: [f64; 3],
    /// Unit normal from a to b.
    pub normal: [f64; 3],
}

#[derive(Serialize, Debug, Clone, Default)]
pub struct CollisionReport {
    pub bodies: Vec<BodyCollisionReport>,
    /// Checked pairs that intersect at the CAD pose.
    pub interferences: Vec<InterferenceReport>,
    /// How many pairs of bodies with shapes are checked (the others are allowed to touch).
    pub checked_pairs: usize,
    /// Pairs of bodies with shapes allowed to touch by default (the user may change them).
    pub default_allowed: Vec<AllowedPair>,
}

/// How a conversion got its shapes (distinct meshes: bodies with the same mesh share one):
/// computed, or served by the shape cache.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShapeCounts {
    pub computed: usize,
    pub cached: usize,
}

/// Every body's shape (None: no mesh), with how many were computed and how many came from
/// `cache`. Distinct meshes (by [`ShapeKey`]) are taken from a shared counter by as many threads
/// as there are cores, the largest first, so a cluster of expensive bodies spreads over the
/// threads; each result lands at its bodies' indices, so the output does not depend on the
/// threads.
pub fn body_shapes(model: &Model, opts: &ShapeOptions, cache: Option<&dyn ShapeCache>) -> (Vec<Option<BodyShape>>, ShapeCounts) {
    // Bodies with the same mesh (a hand's identical fingers) share one computation.
    let mut unique: BTreeMap<ShapeKey, (usize, &Mesh)> = BTreeMap::new();
    let mut key_of: Vec<Option<ShapeKey>> = vec![None; model.bodies.len()];
    // A mesh the bodies share (one `Arc`) is hashed once.
    let mut hashed: HashMap<*const Mesh, ShapeKey> = HashMap::new();
    for (i, b) in model.bodies.iter().enumerate() {
        if let Some(m) = &b.mesh {
            let k = *hashed.entry(Arc::as_ptr(m)).or_insert_with(|| ShapeKey::of(m, opts));
            key_of[i] = Some(k);
            unique.entry(k).or_insert((i, &**m));
        }
    }
    let shape_of = |key: &ShapeKey, mesh: &Mesh| -> (BodyShape, bool) {
        if let Some(s) = cache.and_then(|c| c.get(key)) {
            return (s, true);
        }
        let mut s = collision::body_shape(mesh, opts);
        // Mesh coordinates are f32: written with the digits they have (0.06, not
        // 0.05999999865889549); computed corners move by less than 1e-7 of their size.
        for p in &mut s.parts {
            for v in &mut p.vertices {
                *v = v.map(tidy);
            }
            p.radius = tidy(p.radius);
        }
        if let Some(c) = cache {
            c.put(*key, &s);
        }
        (s, false)
    };
    // Largest meshes first (ties by body index).
    let mut order: Vec<(ShapeKey, usize, &Mesh)> = unique.iter().map(|(k, &(i, m))| (*k, i, m)).collect();
    order.sort_by_key(|&(_, i, m)| (std::cmp::Reverse(m.triangles.len()), i));
    let done = crate::par::map_ordered(
        &order,
        crate::par::threads(usize::MAX),
        || (),
        |_, (k, _, m)| {
            let (s, hit) = shape_of(k, m);
            (*k, s, hit)
        },
    );
    let mut counts = ShapeCounts::default();
    let mut by_key: BTreeMap<ShapeKey, BodyShape> = BTreeMap::new();
    for (k, s, hit) in done {
        if hit {
            counts.cached += 1;
        } else {
            counts.computed += 1;
        }
        by_key.insert(k, s);
    }
    let shapes = key_of.iter().map(|k| k.as_ref().and_then(|k| by_key.get(k).cloned())).collect();
    (shapes, counts)
}

impl Collision {
    /// The collision world of the bodies' shapes as [`body_shapes`] made them (it needs no
    /// names, so a conversion makes them while it writes the Modelica text): pairs joined by a
    /// joint; the user's edits by name.
    pub fn from_shapes(
        (shapes, counts): (Vec<Option<BodyShape>>, ShapeCounts),
        model: &Model,
        names: &[String],
        joint_names: &[String],
        edits: &AllowedEdits,
    ) -> Collision {
        let body_of = |f| match model.frame(f).owner {
            FrameOwner::Body(b) => Some(b.index()),
            FrameOwner::Ground(_) => None,
        };
        // Welded bodies move as one: a rigid group. Bodies of one group, and of two groups joined
        // by a joint, may touch by default.
        let n = model.bodies.len();
        let mut group: Vec<usize> = (0..n).collect();
        fn root(g: &mut [usize], mut i: usize) -> usize {
            while g[i] != i {
                g[i] = g[g[i]];
                i = g[i];
            }
            i
        }
        for j in model.joints.iter().filter(|j| j.is_weld()) {
            if let (Some(a), Some(b)) = (body_of(j.base), body_of(j.follower)) {
                let (ra, rb) = (root(&mut group, a), root(&mut group, b));
                group[ra] = rb;
            }
        }
        let mut links: BTreeMap<(usize, usize), String> = BTreeMap::new();
        for (k, j) in model.joints.iter().enumerate().filter(|(_, j)| !j.is_weld()) {
            if let (Some(a), Some(b)) = (body_of(j.base), body_of(j.follower)) {
                let (ra, rb) = (root(&mut group, a), root(&mut group, b));
                if ra != rb {
                    let name = joint_names.get(k).cloned().unwrap_or_else(|| j.cad_name.clone());
                    links.entry((ra.min(rb), ra.max(rb))).or_insert(name);
                }
            }
        }
        // Only bodies with shapes can touch: pairs among them, by group (no n² walk over bodies).
        let mut members: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for (i, shape) in shapes.iter().enumerate() {
            if shape.is_some() {
                let r = root(&mut group, i);
                members.entry(r).or_default().push(i);
            }
        }
        let mut joined = BTreeMap::new();
        for m in members.values() {
            for (k, &a) in m.iter().enumerate() {
                for &b in &m[k + 1..] {
                    joined.insert((a.min(b), a.max(b)), "welded together (one rigid group)".to_string());
                }
            }
        }
        for ((ga, gb), j) in &links {
            let (Some(ma), Some(mb)) = (members.get(ga), members.get(gb)) else { continue };
            for &a in ma {
                for &b in mb {
                    joined.entry((a.min(b), a.max(b))).or_insert_with(|| format!("joined by {j}"));
                }
            }
        }
        let index: BTreeMap<&str, usize> = names.iter().enumerate().map(|(i, n)| (n.as_str(), i)).collect();
        let edits = edits
            .iter()
            .filter_map(|((a, b), allowed)| {
                let (i, j) = (*index.get(a.as_str())?, *index.get(b.as_str())?);
                Some(((i.min(j), i.max(j)), *allowed))
            })
            .collect();
        Collision { shapes, joined, edits, counts }
    }

    /// Why bodies `a` and `b` may touch by default (`None`: they are checked by default).
    pub fn joined(&self, a: usize, b: usize) -> Option<&str> {
        self.joined.get(&(a.min(b), a.max(b))).map(String::as_str)
    }

    /// Whether the pair is checked (not allowed to touch).
    pub fn checked(&self, a: usize, b: usize) -> bool {
        let key = (a.min(b), a.max(b));
        a != b && !self.edits.get(&key).copied().unwrap_or_else(|| self.joined.contains_key(&key))
    }

    /// The pairs (a < b, both with shapes) allowed to touch, sorted: joined or welded by default,
    /// as the user's edits say otherwise (linear in the allowed pairs and edits, not n²).
    pub fn allowed_pairs(&self) -> Vec<(usize, usize)> {
        let shaped = |i: usize| self.shapes.get(i).is_some_and(Option::is_some);
        let mut out: Vec<(usize, usize)> = self.joined.keys().copied().filter(|k| self.edits.get(k).copied().unwrap_or(true)).collect();
        out.extend(self.edits.iter().filter(|(k, allowed)| **allowed && !self.joined.contains_key(k)).map(|(k, _)| *k));
        out.retain(|&(a, b)| a != b && shaped(a) && shaped(b));
        out.sort_unstable();
        out.dedup();
        out
    }

    /// The convex parts of each body (None: no shape), for the Modelica contact code.
    pub fn parts(&self) -> Vec<Option<Vec<ConvexPart>>> {
        self.shapes.iter().map(|s| s.as_ref().map(|s| s.parts.clone())).collect()
    }

    /// The report section and a warning per interference at `poses` (the CAD pose).
    pub fn report(&self, model: &Model, names: &[String]) -> (CollisionReport, Vec<Warning>) {
        let mut r = CollisionReport::default();
        for (i, s) in self.shapes.iter().enumerate() {
            let body = names.get(i).cloned().unwrap_or_default();
            r.bodies.push(match s {
                Some(s) => BodyCollisionReport {
                    body,
                    kind: s.kind.name(),
                    parts: s.parts.len(),
                    vertices: s.vertex_count,
                    fit_error: s.fit_error,
                    volume_ratio: s.volume_ratio,
                    source_triangles: s.source_triangles,
                    warnings: s.warnings.clone(),
                },
                None => BodyCollisionReport {
                    body,
                    kind: "none",
                    parts: 0,
                    vertices: 0,
                    fit_error: 0.0,
                    volume_ratio: 0.0,
                    source_triangles: 0,
                    warnings: vec!["no mesh: the body has no collision shape".to_string()],
                },
            });
        }
        let with: Vec<usize> = (0..self.shapes.len()).filter(|&i| self.shapes[i].is_some()).collect();
        r.checked_pairs = with.len() * with.len().saturating_sub(1) / 2 - self.allowed_pairs().len();
        // Joined pairs are among bodies with shapes, in (a, b) order.
        for (&(a, b), why) in &self.joined {
            r.default_allowed.push(AllowedPair { a: names[a].clone(), b: names[b].clone(), why: why.clone() });
        }
        let poses = cad_poses(model);
        let mut warnings = Vec::new();
        // Bodies with mass but no mesh cannot collide (massless root parts are frame hubs).
        let bare: Vec<&str> = (0..self.shapes.len())
            .filter(|&i| self.shapes[i].is_none() && model.bodies[i].mass > 0.0)
            .filter_map(|i| names.get(i).map(String::as_str))
            .collect();
        if !bare.is_empty() {
            let shown: Vec<&str> = bare.iter().copied().take(10).collect();
            let more = if bare.len() > shown.len() { format!(" and {} more", bare.len() - shown.len()) } else { String::new() };
            warnings.push(Warning::new(
                "no-collision-shape",
                format!(
                    "{} bod{} with mass but no mesh ha{} no collision shape and cannot collide: {}{more}",
                    bare.len(),
                    if bare.len() == 1 { "y" } else { "ies" },
                    if bare.len() == 1 { "s" } else { "ve" },
                    shown.join(", ")
                ),
                "collision shapes".to_string(),
            ));
        }
        // Shape warnings: each on its own up to MAX_LISTED, then one line for the rest (every
        // one stays in its body's entry of the report's collision section).
        let shape_warnings: Vec<(usize, &String)> =
            self.shapes.iter().enumerate().flat_map(|(i, s)| s.iter().flat_map(move |s| s.warnings.iter().map(move |w| (i, w)))).collect();
        let body = |i: usize| names.get(i).map_or("?", String::as_str);
        for &(i, w) in shape_warnings.iter().take(MAX_LISTED) {
            warnings.push(Warning::new("collision-shape", w.clone(), format!("body {}", body(i))));
        }
        if shape_warnings.len() > MAX_LISTED {
            let rest = &shape_warnings[MAX_LISTED..];
            let mut bodies: Vec<usize> = rest.iter().map(|&(i, _)| i).collect();
            bodies.dedup();
            warnings.push(Warning::new(
                "collision-shape",
                format!(
                    "{} more collision shape warnings on {} bod{} (every one is in report.json, collision.bodies[].warnings)",
                    rest.len(),
                    bodies.len(),
                    if bodies.len() == 1 { "y" } else { "ies" }
                ),
                "collision shapes".to_string(),
            ));
        }
        // Only the bodies of pairs whose boxes meet get parry shapes (the same contacts as
        // `contacts_at` of the whole world).
        for c in collision::contacts_of(&self.shapes, &poses, &|a, b| self.checked(a, b), 0.0) {
            if c.distance >= 0.0 {
                continue;
            }
            let (a, b) = (names[c.a].clone(), names[c.b].clone());
            r.interferences.push(InterferenceReport { a, b, depth: -c.distance, point_a: c.point_a, point_b: c.point_b, normal: c.normal });
        }
        // A warning for each of the deepest MAX_LISTED interferences (deepest first), one for
        // the rest: the report's list keeps every pair.
        let mut deepest: Vec<&InterferenceReport> = r.interferences.iter().collect();
        deepest.sort_by(|x, y| y.depth.total_cmp(&x.depth));
        for i in deepest.iter().take(MAX_LISTED) {
            warnings.push(Warning::new(
                "interference",
                format!(
                    "bodies {} and {} intersect at the CAD pose by {} mm (points {} and {} m in world)",
                    i.a,
                    i.b,
                    mm(i.depth),
                    point(&i.point_a),
                    point(&i.point_b)
                ),
                format!("bodies {} and {}", i.a, i.b),
            ));
        }
        if deepest.len() > MAX_LISTED {
            let rest = &deepest[MAX_LISTED..];
            warnings.push(Warning::new(
                "interference",
                format!(
                    "{} more pairs of bodies intersect at the CAD pose, each by at most {} mm ({} in all; every pair is in report.json, collision.interferences)",
                    rest.len(),
                    mm(rest[0].depth),
                    deepest.len()
                ),
                "collision shapes".to_string(),
            ));
        }
        (r, warnings)
    }
}

/// `Resources/Collision/<body>.obj` per body with a shape, and `shapes.json` (every part's
/// vertices and radius, by body name) for the service, from `shapes` as [`body_shapes`] gives
/// them, deflated for the zip: a conversion writes them as soon as the shapes are made. The OBJ
/// files are written on up to two threads (this one among them) and `shapes.json` on a third
/// beside them; the files are in body order, `shapes.json` last, whatever the threads' timing.
pub fn shape_files(shapes: &[Option<BodyShape>], pkg: &str, names: &[String]) -> Vec<(String, FileData)> {
    // shapes.json, its keys in alphabetical order (as a JSON value's would be).
    #[derive(serde::Serialize)]
    struct Part<'a> {
        radius: f64,
        vertices: &'a [[f64; 3]],
    }
    #[derive(serde::Serialize)]
    struct Body<'a> {
        body: &'a str,
        kind: &'static str,
        parts: Vec<Part<'a>>,
    }
    #[derive(serde::Serialize)]
    struct Shapes<'a> {
        bodies: Vec<Body<'a>>,
    }
    let with: Vec<(&BodyShape, &String)> = shapes.iter().zip(names).filter_map(|(s, n)| Some((s.as_ref()?, n))).collect();
    std::thread::scope(|scope| {
        let json = scope.spawn(|| {
            let bodies: Vec<Body> = with
                .iter()
                .map(|(s, name)| Body {
                    body: name,
                    kind: s.kind.name(),
                    parts: s.parts.iter().map(|p| Part { radius: p.radius, vertices: &p.vertices }).collect(),
                })
                .collect();
            (!bodies.is_empty()).then(|| {
                let text = serde_json::to_vec(&Shapes { bodies }).unwrap_or_default();
                (format!("{pkg}/Resources/Collision/shapes.json"), Deflater::default().file(text))
            })
        });
        let mut files = crate::par::map_ordered(&with, crate::par::threads(2), Deflater::default, |d, (s, name)| {
            (format!("{pkg}/Resources/Collision/{name}.obj"), d.file(collision::obj_text(s, name).into_bytes()))
        });
        files.extend(json.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        files
    })
}

/// The world pose of every body's frame_a (CS1) at the CAD pose.
pub fn cad_poses(model: &Model) -> Vec<Isometry3<f64>> {
    model.bodies.iter().map(|b| model.frame(b.cs1).pose).collect()
}

/// `x` rounded to f32 precision, as the shortest decimal of that f32.
fn tidy(x: f64) -> f64 {
    (x as f32).to_string().parse().unwrap_or(x)
}

fn mm(x: f64) -> String {
    format!("{:.3}", x * 1e3)
}

fn point(p: &[f64; 3]) -> String {
    format!("({:.4}, {:.4}, {:.4})", p[0], p[1], p[2])
}

/// Reads `shapes.json` back (the service's view of a package): body name → parts.
pub fn read_shapes(json: &[u8]) -> Result<BTreeMap<String, Vec<ConvexPart>>, String> {
    let v: serde_json::Value = serde_json::from_slice(json).map_err(|e| format!("shapes.json: {e}"))?;
    let mut out = BTreeMap::new();
    for b in v["bodies"].as_array().ok_or("shapes.json: no bodies")? {
        let name = b["body"].as_str().ok_or("shapes.json: a body without a name")?.to_string();
        let mut parts = Vec::new();
        for p in b["parts"].as_array().ok_or("shapes.json: a body without parts")? {
            let vertices: Vec<[f64; 3]> = serde_json::from_value(p["vertices"].clone()).map_err(|e| format!("shapes.json, {name}: {e}"))?;
            let radius = p["radius"].as_f64().unwrap_or(0.0);
            parts.push(ConvexPart { vertices, faces: Vec::new(), radius });
        }
        out.insert(name, parts);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use crate::collision::{MemoryShapeCache, ShapeCache};
    use crate::pipeline::front::bundle::Bundle;
    use crate::pipeline::{self, Options};

    /// The hand-made arm (three STL links) with the upper link's mesh as given.
    fn arm(upper: &str) -> Bundle {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/arm_subsystems");
        let read = |p: &str| std::fs::read(dir.join(p)).expect("fixture");
        let files = vec![
            ("ARM_SIM_MODEL.xml".to_string(), read("ARM_SIM_MODEL.xml")),
            ("meshes/BASE_prt.stl".to_string(), read("meshes/BASE_prt.stl")),
            ("meshes/fore/LINK-1_prt.stl".to_string(), read("meshes/fore/LINK-1_prt.stl")),
            ("meshes/upper/LINK_prt.stl".to_string(), upper.as_bytes().to_vec()),
        ];
        Bundle::from_files("arm", files).expect("bundle")
    }

    #[test]
    fn collision_shapes_come_from_the_cache_for_unchanged_meshes() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/arm_subsystems");
        let upper = std::fs::read_to_string(dir.join("meshes/upper/LINK_prt.stl")).expect("fixture");
        let cache = Arc::new(MemoryShapeCache::default());
        let shared: Arc<dyn ShapeCache> = cache.clone();
        let opts = Options { shape_cache: Some(shared), ..Options::default() };
        let uncached = pipeline::convert(&arm(&upper), &Options::default()).expect("converts");
        assert_eq!((uncached.shapes.computed, uncached.shapes.cached), (3, 0));

        let first = pipeline::convert(&arm(&upper), &opts).expect("converts");
        assert_eq!((first.shapes.computed, first.shapes.cached), (3, 0));
        let again = pipeline::convert(&arm(&upper), &opts).expect("converts");
        assert_eq!((again.shapes.computed, again.shapes.cached), (0, 3), "the same bundle again computes no shape");
        // The output does not depend on where the shapes came from.
        assert!(first.files == uncached.files && again.files == uncached.files, "same files with and without the cache");

        // A version whose upper link is 1 mm longer: that one shape is computed again.
        let longer = upper.replace("2.660000e+02", "2.670000e+02");
        assert_ne!(longer, upper);
        let changed = pipeline::convert(&arm(&longer), &opts).expect("converts");
        assert_eq!((changed.shapes.computed, changed.shapes.cached), (1, 2), "exactly the changed mesh is recomputed");
        let s = cache.stats();
        assert_eq!((s.hits, s.misses, s.entries), (5, 4, 4), "{s:?}");
    }
}
