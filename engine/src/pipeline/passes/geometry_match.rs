//! Matching VRML geometry to XML bodies, as Juhász & Schmucker (2008) do it.
//!
//! VRML exports carry their own auto-generated names (`Obj01`) that do not match the XML's
//! (`Obj`, `Obj-1`); what they share is geometry placement: the global pose of a part's group
//! in the VRML equals the CS1 frame of its body in the XML.
//!
//! 0. **Units**: VRML has none. The XML's length unit is assumed first; when that matches
//!    poorly, the scale (metres per VRML unit) under which most CS1 origins find a group is used.
//! 1. **Position**: candidates are grouping nodes with geometry below them whose global origin
//!    lies within a tolerance of the body's CS1 origin (a hash grid makes this O(1) per body).
//!    A candidate that contains another body's candidate (an assembly group) is dropped, and
//!    of nested candidates of one body the outermost is kept, so sibling shapes are not lost.
//! 2. **Orientation**: of several candidates, those whose rotation is within a tolerance of
//!    CS1's.
//! 3. **Name**: of several still, those whose name without digits and punctuation equals the
//!    body's (`Obj01` ~ `Obj`, `Obj-1`, `obj_1`).
//! 4. Still ambiguous: an error naming the body and the nodes, unless `matching.json` pins it.
//!
//! Pins (`matching.json` in the bundle: `{"<body nodeID>": "<node path>" | ["<path>", ...]}`)
//! are applied before the automatic rules. Every shape below a matched node merges into the
//! body's mesh, transformed into CS1 and metres.

use std::collections::{BTreeMap, HashMap, HashSet};

use nalgebra::{Matrix3, Matrix4, Point3, Rotation3, Vector3};
use serde::Serialize;

use crate::pipeline::front::vrml::{NodeId, Scene};
use crate::pipeline::ir::{Mesh, Model, Warning};
use crate::pipeline::valid::is_root_part;

/// How a body got a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Rule {
    Pinned,
    Position,
    Orientation,
    Name,
}

/// One matched node of a body.
#[derive(Clone, Debug, Serialize)]
pub struct NodeMatch {
    pub node_path: String,
    pub file: String,
    pub rule: Rule,
    /// Distance between the node's origin and CS1's, m.
    pub distance_m: f64,
    /// Angle between the node's rotation and CS1's, rad.
    pub angle_rad: f64,
    pub triangles: usize,
}

/// The outcome of matching.
#[derive(Clone, Debug, Default, Serialize)]
pub struct MatchReport {
    pub files: Vec<String>,
    /// Metres per VRML unit used.
    pub scale: f64,
    /// Bodies whose CS1 found a candidate at that scale / bodies tried.
    pub scale_score: (usize, usize),
    pub tolerance_m: f64,
    /// Per body node ID.
    pub bodies: BTreeMap<String, Vec<NodeMatch>>,
    /// Paths of nodes with geometry that no body took.
    pub unmatched: Vec<String>,
}

/// Options of the matcher.
#[derive(Clone, Debug, Default)]
pub struct MatchOptions {
    /// Position tolerance, m; default 1e-4 of the assembly's size (at least 1 µm).
    pub tolerance_m: Option<f64>,
    /// Orientation tolerance, rad; default 1e-3.
    pub angle_tolerance: Option<f64>,
}

/// Why matching failed.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum MatchError {
    #[error("matching.json: {0}")]
    BadPins(String),
    #[error("matching.json: body nodeID \"{0}\" is not in the XML")]
    UnknownPinnedBody(String),
    #[error("matching.json: VRML node \"{path}\" (pinned to body nodeID \"{body}\") is not in the VRML scene")]
    UnknownPinnedNode { body: String, path: String },
    #[error("ambiguous geometry for body \"{body}\" (nodeID \"{node_id}\"): VRML nodes {} match it equally by position, orientation and name; pin one in matching.json", candidates.join(", "))]
    Ambiguous { body: String, node_id: String, candidates: Vec<String> },
    #[error("VRML node \"{path}\" matches both body \"{first}\" and body \"{second}\"; pin them in matching.json")]
    Shared { path: String, first: String, second: String },
}

/// Parses `matching.json`: body node ID -> node paths.
pub fn parse_pins(bytes: &[u8]) -> Result<BTreeMap<String, Vec<String>>, MatchError> {
    let v: serde_json::Value = serde_json::from_slice(bytes).map_err(|e| MatchError::BadPins(e.to_string()))?;
    let obj = v.as_object().ok_or_else(|| MatchError::BadPins("expected an object {\"body nodeID\": \"node path\"}".into()))?;
    let mut out = BTreeMap::new();
    for (k, v) in obj {
        let paths = match v {
            serde_json::Value::String(s) => vec![s.clone()],
            serde_json::Value::Array(a) => a
                .iter()
                .map(|x| x.as_str().map(String::from).ok_or_else(|| MatchError::BadPins(format!("\"{k}\": paths must be strings"))))
                .collect::<Result<_, _>>()?,
            _ => return Err(MatchError::BadPins(format!("\"{k}\": expected a node path or a list of them"))),
        };
        out.insert(k.clone(), paths);
    }
    Ok(out)
}

/// Rotation part of a transform that may carry scale (polar decomposition).
fn rotation_of(m: &Matrix4<f64>) -> Rotation3<f64> {
    let a: Matrix3<f64> = m.fixed_view::<3, 3>(0, 0).into_owned();
    let svd = a.svd(true, true);
    match (svd.u, svd.v_t) {
        (Some(u), Some(v_t)) => {
            let mut r = u * v_t;
            if r.determinant() < 0.0 {
                // Mirrored: keep the proper rotation part.
                let mut u2 = u;
                u2.column_mut(2).neg_mut();
                r = u2 * v_t;
            }
            Rotation3::from_matrix_unchecked(r)
        }
        _ => Rotation3::identity(),
    }
}

/// Angle between two rotations, accurate near zero (nalgebra's `angle_to` takes an `acos` that
/// turns NaN for equal rotations).
fn angle_between(a: &Rotation3<f64>, b: &Rotation3<f64>) -> f64 {
    crate::pipeline::passes::kinematics::rotation_angle(&nalgebra::UnitQuaternion::from_rotation_matrix(&(a.inverse() * b)))
}

/// `Obj01`, `obj_1`, `Obj-1` -> `obj`.
pub fn name_stem(name: &str) -> String {
    let lower: String = name.chars().filter(|c| c.is_ascii_alphanumeric()).map(|c| c.to_ascii_lowercase()).collect();
    lower.trim_end_matches(|c: char| c.is_ascii_digit()).to_string()
}

struct Grid {
    cell: f64,
    map: HashMap<(i64, i64, i64), Vec<usize>>,
}

impl Grid {
    fn key(&self, p: &Vector3<f64>) -> (i64, i64, i64) {
        ((p.x / self.cell).floor() as i64, (p.y / self.cell).floor() as i64, (p.z / self.cell).floor() as i64)
    }
    fn new(cell: f64, points: &[Vector3<f64>]) -> Grid {
        let mut g = Grid { cell, map: HashMap::new() };
        for (i, p) in points.iter().enumerate() {
            let k = g.key(p);
            g.map.entry(k).or_default().push(i);
        }
        g
    }
    /// Indices of points within `r` (<= cell) of `p`.
    fn near(&self, points: &[Vector3<f64>], p: &Vector3<f64>, r: f64) -> Vec<usize> {
        let (x, y, z) = self.key(p);
        let mut out = Vec::new();
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(v) = self.map.get(&(x + dx, y + dy, z + dz)) {
                        out.extend(v.iter().copied().filter(|&i| (points[i] - p).norm() <= r));
                    }
                }
            }
        }
        out.sort_unstable();
        out
    }
}

/// Matches `scene` to the bodies of `model` that have no mesh yet, fills their meshes and returns
/// the report and warnings.
pub fn match_scene(
    model: &mut Model,
    scene: &Scene,
    pins: &BTreeMap<String, Vec<String>>,
    opts: &MatchOptions,
) -> Result<(MatchReport, Vec<Warning>), MatchError> {
    let n = scene.nodes.len();
    // Euler tour for subtree tests, and which nodes have geometry below them.
    let mut tin = vec![0usize; n];
    let mut tout = vec![0usize; n];
    let mut has_geometry = vec![false; n];
    let mut clock = 0;
    for &root in &scene.roots {
        let mut stack = vec![(root, false)];
        while let Some((v, done)) = stack.pop() {
            if done {
                tout[v] = clock;
                has_geometry[v] = !scene.nodes[v].shapes.is_empty() || scene.nodes[v].children.iter().any(|c| has_geometry[*c]);
                continue;
            }
            tin[v] = clock;
            clock += 1;
            stack.push((v, true));
            for c in scene.nodes[v].children.iter().rev() {
                stack.push((*c, false));
            }
        }
    }
    let contains = |a: NodeId, b: NodeId| tin[a] <= tin[b] && tin[b] < tout[a] && a != b;
    let geo_nodes: Vec<NodeId> = (0..n).filter(|&v| has_geometry[v]).collect();
    let raw_origins: Vec<Vector3<f64>> = geo_nodes.iter().map(|&v| scene.nodes[v].global.fixed_view::<3, 1>(0, 3).into_owned()).collect();
    let rotations: Vec<Rotation3<f64>> = geo_nodes.iter().map(|&v| rotation_of(&scene.nodes[v].global)).collect();

    // Bodies to match: those without a mesh, except RootParts.
    let targets: Vec<usize> =
        (0..model.bodies.len()).filter(|&i| model.bodies[i].mesh.is_none() && !is_root_part(&model.bodies[i])).collect();
    let cs1_poses: Vec<nalgebra::Isometry3<f64>> = model.bodies.iter().map(|b| model.frame(b.cs1).pose).collect();
    let cs1 = |i: usize| cs1_poses[i];
    let size = {
        let pts: Vec<Vector3<f64>> = targets.iter().map(|&i| cs1(i).translation.vector).collect();
        let mut lo = Vector3::repeat(f64::INFINITY);
        let mut hi = Vector3::repeat(f64::NEG_INFINITY);
        for p in &pts {
            lo = lo.inf(p);
            hi = hi.sup(p);
        }
        if pts.is_empty() {
            0.0
        } else {
            (hi - lo).norm()
        }
    };
    let tol = opts.tolerance_m.unwrap_or((size * 1e-4).max(1e-6));
    let angle_tol = opts.angle_tolerance.unwrap_or(1e-3);

    // 0. Scale: the XML unit first, then common alternatives; the best hit count wins.
    let ls = if model.length_scale > 0.0 { model.length_scale } else { 1.0 };
    let mut scales = vec![ls, 1.0, 1e-3, 1e-2, 0.0254, 0.3048, ls * 1e-3, ls * 1e3, ls * 25.4, ls / 25.4];
    scales.dedup_by(|a, b| ((*a - *b) / *b).abs() < 1e-12);
    let mut best = (ls, 0usize);
    for (k, &s) in scales.iter().enumerate() {
        let origins: Vec<Vector3<f64>> = raw_origins.iter().map(|p| p * s).collect();
        let grid = Grid::new(tol.max(1e-12), &origins);
        let hits = targets.iter().filter(|&&i| !grid.near(&origins, &cs1(i).translation.vector, tol).is_empty()).count();
        if hits > best.1 || (k == 0 && hits == best.1) {
            best = (s, hits);
        }
        if hits == targets.len() {
            break;
        }
    }
    let scale = best.0;
    let origins: Vec<Vector3<f64>> = raw_origins.iter().map(|p| p * scale).collect();
    let grid = Grid::new(tol.max(1e-12), &origins);

    // Pins first.
    let path_index: HashMap<&str, NodeId> = scene.nodes.iter().enumerate().map(|(i, nd)| (nd.path.as_str(), i)).collect();
    let body_by_node: HashMap<&str, usize> = model.bodies.iter().enumerate().map(|(i, b)| (b.node_id.as_str(), i)).collect();
    let mut chosen: BTreeMap<usize, Vec<(NodeId, Rule)>> = BTreeMap::new();
    let mut pinned_nodes: HashSet<NodeId> = HashSet::new();
    for (body, paths) in pins {
        let &bi = body_by_node.get(body.as_str()).ok_or_else(|| MatchError::UnknownPinnedBody(body.clone()))?;
        for p in paths {
            let &node = path_index.get(p.as_str()).ok_or_else(|| MatchError::UnknownPinnedNode { body: body.clone(), path: p.clone() })?;
            pinned_nodes.insert(node);
            chosen.entry(bi).or_default().push((node, Rule::Pinned));
        }
    }

    // 1-3. Candidates per body: by position, narrowed by orientation and then by name whenever
    // that leaves some (the right group has CS1's exact orientation, and usually a name with
    // the body's stem), before nested and shared groups are sorted out.
    let body_rot = |i: usize| cs1(i).rotation.to_rotation_matrix();
    let mut candidates: BTreeMap<usize, (Vec<usize>, Rule)> = BTreeMap::new();
    for &i in &targets {
        if chosen.contains_key(&i) {
            continue;
        }
        let pos: Vec<usize> = grid
            .near(&origins, &cs1(i).translation.vector, tol)
            .into_iter()
            .filter(|k| !pinned_nodes.iter().any(|&p| p == geo_nodes[*k] || contains(p, geo_nodes[*k]) || contains(geo_nodes[*k], p)))
            .collect();
        if pos.is_empty() {
            continue;
        }
        let r = body_rot(i);
        let oriented: Vec<usize> = pos.iter().copied().filter(|k| angle_between(&r, &rotations[*k]) <= angle_tol).collect();
        let (mut c, mut rule) =
            if !oriented.is_empty() && oriented.len() < pos.len() { (oriented, Rule::Orientation) } else { (pos, Rule::Position) };
        let stem = name_stem(&model.bodies[i].cad_name);
        let named: Vec<usize> = c.iter().copied().filter(|k| name_stem(&scene.nodes[geo_nodes[*k]].name) == stem).collect();
        if !named.is_empty() && named.len() < c.len() {
            c = named;
            rule = Rule::Name;
        }
        candidates.insert(i, (c, rule));
    }
    // Candidate nodes of all bodies sorted by tour entry, with "next index of another body".
    let mut tour: Vec<(usize, usize)> = Vec::new();
    for (b, (ks, _)) in &candidates {
        tour.extend(ks.iter().map(|k| (tin[geo_nodes[*k]], *b)));
    }
    tour.sort_unstable();
    let mut next_other = vec![tour.len(); tour.len()];
    for i in (0..tour.len()).rev() {
        next_other[i] = if i + 1 < tour.len() && tour[i + 1].1 != tour[i].1 {
            i + 1
        } else if i + 1 < tour.len() {
            next_other[i + 1]
        } else {
            tour.len()
        };
    }
    // Whether a strict descendant of `node` is another body's candidate (an assembly group).
    let holds_other = |node: NodeId, body: usize| -> bool {
        let start = tour.partition_point(|(t, _)| *t <= tin[node]);
        if start >= tour.len() || tour[start].0 >= tout[node] {
            return false;
        }
        let j = if tour[start].1 != body { start } else { next_other[start] };
        j < tour.len() && tour[j].0 < tout[node]
    };
    for (&i, (ks, rule)) in &candidates {
        let mut c: Vec<usize> = ks.iter().copied().filter(|k| !holds_other(geo_nodes[*k], i)).collect();
        // Outermost of nested candidates, so sibling shapes of a part are not lost.
        c.sort_by_key(|k| tin[geo_nodes[*k]]);
        let mut kept: Vec<usize> = Vec::new();
        for k in c {
            if !kept.iter().any(|&o| contains(geo_nodes[o], geo_nodes[k])) {
                kept.push(k);
            }
        }
        match kept.as_slice() {
            [] => {}
            [one] => chosen.entry(i).or_default().push((geo_nodes[*one], *rule)),
            _ => {
                // Name each candidate by its outermost ancestor holding no other candidate: the
                // part's own group, which is what a user pins.
                let nodes: Vec<NodeId> = kept.iter().map(|k| geo_nodes[*k]).collect();
                let outer = |mut v: NodeId| {
                    while let Some(p) = scene.nodes[v].parent {
                        if nodes.iter().any(|&o| o != v && contains(p, o) && !contains(v, o)) {
                            break;
                        }
                        v = p;
                    }
                    scene.nodes[v].path.clone()
                };
                return Err(MatchError::Ambiguous {
                    body: model.bodies[i].cad_name.clone(),
                    node_id: model.bodies[i].node_id.clone(),
                    candidates: nodes.iter().map(|&v| outer(v)).collect(),
                });
            }
        }
    }

    // A node (or its subtree) taken by two bodies is ambiguous.
    let mut owner: BTreeMap<usize, usize> = BTreeMap::new();
    for (&i, nodes) in &chosen {
        for (node, rule) in nodes {
            if *rule == Rule::Pinned {
                continue;
            }
            if let Some(&other) = owner.get(&tin[*node]) {
                return Err(MatchError::Shared {
                    path: scene.nodes[*node].path.clone(),
                    first: model.bodies[other].cad_name.clone(),
                    second: model.bodies[i].cad_name.clone(),
                });
            }
            owner.insert(tin[*node], i);
        }
    }

    // Merge shapes into meshes in CS1, metres.
    let mut report =
        MatchReport { files: scene.files.clone(), scale, scale_score: (best.1, targets.len()), tolerance_m: tol, ..MatchReport::default() };
    let mut covered = vec![false; n];
    for (&i, nodes) in &chosen {
        let pose = cs1(i);
        let inv = pose.inverse();
        let mut mesh = Mesh::default();
        let mut color = None;
        let mut matches = Vec::new();
        for (node, rule) in nodes {
            let mut tris = 0;
            for (owner_node, shape) in scene.shapes_below(*node) {
                covered[owner_node] = true;
                let g = scene.nodes[owner_node].global;
                let mut m = shape.mesh.clone();
                for v in &mut m.vertices {
                    let p = g.transform_point(&Point3::new(v[0] as f64, v[1] as f64, v[2] as f64));
                    let q = inv * Point3::from(p.coords * scale);
                    *v = [q.x as f32, q.y as f32, q.z as f32];
                }
                tris += m.triangles.len();
                mesh.append(&m);
                if color.is_none() {
                    color = shape.color;
                }
            }
            let o = scene.nodes[*node].global.fixed_view::<3, 1>(0, 3).into_owned() * scale;
            matches.push(NodeMatch {
                node_path: scene.nodes[*node].path.clone(),
                file: scene.nodes[*node].file.clone(),
                rule: *rule,
                distance_m: (o - pose.translation.vector).norm(),
                angle_rad: angle_between(&body_rot(i), &rotation_of(&scene.nodes[*node].global)),
                triangles: tris,
            });
        }
        let body = &mut model.bodies[i];
        body.geometry_sources = matches.iter().map(|m| format!("{}#{}", m.file, m.node_path)).collect();
        if body.material.is_none() {
            if let Some(c) = color {
                body.material = Some(crate::pipeline::ir::Material {
                    color: [c[0] as f64, c[1] as f64, c[2] as f64],
                    transparency: 0.0,
                    specular: 0.0,
                });
            }
        }
        body.mesh = Some(std::sync::Arc::new(mesh));
        report.bodies.insert(body.node_id.clone(), matches);
    }
    let mut warnings = Vec::new();
    report.unmatched = (0..n).filter(|&v| !scene.nodes[v].shapes.is_empty() && !covered[v]).map(|v| scene.nodes[v].path.clone()).collect();
    if !report.unmatched.is_empty() {
        warnings.push(Warning::new(
            "vrml-unmatched",
            format!(
                "{} VRML nodes with geometry match no body: {}",
                report.unmatched.len(),
                report.unmatched.iter().take(50).cloned().collect::<Vec<_>>().join(", ")
            ),
            scene.files.first().cloned().unwrap_or_default(),
        ));
    }
    if (scale - ls).abs() > 1e-12 * ls {
        warnings.push(Warning::new(
            "vrml-scale",
            format!(
                "VRML coordinates matched the XML at {scale} m per unit, not in the XML's length unit ({ls} m): that scale is used ({} of {} bodies placed)",
                best.1,
                targets.len()
            ),
            scene.files.first().cloned().unwrap_or_default(),
        ));
    }
    Ok((report, warnings))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::front::vrml::{SceneNode, ShapeGeom};
    use crate::pipeline::ir::*;
    use nalgebra::{Isometry3, Translation3, UnitQuaternion};

    fn body(m: &mut Model, name: &str, node: &str, pose: Isometry3<f64>) {
        let b = BodyId(m.bodies.len() as u32);
        let f = FrameId(m.frames.len() as u32);
        m.frames.push(Frame {
            name: "CS1".into(),
            display_name: String::new(),
            node_id: format!("{node}::CS1"),
            owner: FrameOwner::Body(b),
            ref_id: None,
            pose,
            loc: SourceLoc::default(),
        });
        m.bodies.push(Body {
            cad_name: name.into(),
            node_id: node.into(),
            subsystem_path: vec![],
            mass: 1.0,
            inertia_cg: Matrix3::identity(),
            volume: None,
            surface_area: None,
            cg: f,
            cs1: f,
            frames: vec![f],
            geometry_file: None,
            mesh: None,
            geometry_sources: vec![],
            material: None,
            loc: SourceLoc::default(),
        });
    }

    fn tri() -> ShapeGeom {
        ShapeGeom {
            mesh: Mesh { vertices: vec![[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [0.0, 5.0, 0.0]], triangles: vec![[0, 1, 2]] },
            color: Some([1.0, 0.0, 0.0]),
            kind: "IndexedFaceSet",
            line: 1,
        }
    }

    /// Adds a node under `parent` with `local` (file units) and optional shape.
    fn node(s: &mut Scene, parent: Option<NodeId>, name: &str, local: Matrix4<f64>, shape: bool) -> NodeId {
        let id = s.nodes.len();
        let global = parent.map_or(local, |p| s.nodes[p].global * local);
        let path = parent.map_or(name.to_string(), |p| format!("{}/{name}", s.nodes[p].path));
        s.nodes.push(SceneNode {
            parent,
            name: name.into(),
            named: true,
            path,
            file: "main.wrl".into(),
            line: 1,
            global,
            shapes: if shape { vec![tri()] } else { vec![] },
            children: vec![],
        });
        match parent {
            Some(p) => s.nodes[p].children.push(id),
            None => s.roots.push(id),
        }
        id
    }

    fn pose_mm(x: f64, y: f64, z: f64, rz: f64) -> (Isometry3<f64>, Matrix4<f64>) {
        let r = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rz);
        let iso = Isometry3::from_parts(Translation3::new(x * 1e-3, y * 1e-3, z * 1e-3), r);
        let m = Isometry3::from_parts(Translation3::new(x, y, z), r).to_homogeneous();
        (iso, m)
    }

    fn mm_model() -> Model {
        Model { length_scale: 1e-3, ..Model::default() }
    }

    #[test]
    fn assembly_by_position_and_mesh_lands_in_cs1() {
        let mut m = mm_model();
        let (pa, ma) = pose_mm(100.0, 0.0, 0.0, 0.5);
        let (pb, mb) = pose_mm(0.0, 200.0, 0.0, 0.0);
        let (pc, mc) = pose_mm(0.0, 0.0, 0.0, 0.0);
        body(&mut m, "Obj", "1", pa);
        body(&mut m, "Obj-1", "2", pb);
        body(&mut m, "BASE", "3", pc);
        let mut s = Scene::default();
        let asm = node(&mut s, None, "ASM", Matrix4::identity(), false);
        let a = node(&mut s, Some(asm), "Obj01", ma, false);
        node(&mut s, Some(a), "Part", Matrix4::identity(), true);
        node(&mut s, Some(a), "Sub", Matrix4::new_translation(&Vector3::new(0.0, 0.0, 7.0)), true);
        node(&mut s, Some(asm), "Obj02", mb, true);
        node(&mut s, Some(asm), "Base01", mc, true);
        let (rep, w) = match_scene(&mut m, &s, &BTreeMap::new(), &MatchOptions::default()).unwrap();
        assert!(w.is_empty(), "{w:?}");
        assert_eq!(rep.scale, 1e-3);
        assert_eq!(rep.bodies["1"][0].node_path, "ASM/Obj01");
        assert_eq!(rep.bodies["1"][0].triangles, 2, "child shapes merge into the body");
        assert_eq!(rep.bodies["2"][0].node_path, "ASM/Obj02");
        assert_eq!(rep.bodies["3"][0].node_path, "ASM/Base01");
        // The merged mesh, moved back by the CS1 pose, lands on the VRML global position.
        let mesh = m.bodies[0].mesh.as_ref().unwrap();
        for (k, v) in mesh.vertices.iter().enumerate() {
            let world = pa * Point3::new(v[0] as f64, v[1] as f64, v[2] as f64);
            let local = tri().mesh.vertices[k % 3];
            let z = if k >= 3 { 7.0 } else { 0.0 };
            let expect = ma.transform_point(&Point3::new(local[0] as f64, local[1] as f64, local[2] as f64 + z)) * 1e-3;
            assert!((world.coords - expect.coords).norm() < 1e-9, "{k}: {world} vs {expect}");
        }
        assert_eq!(m.bodies[0].material.as_ref().unwrap().color, [1.0, 0.0, 0.0]);
    }

    #[test]
    fn same_pose_told_apart_by_orientation_then_name() {
        let mut m = mm_model();
        let (p, mm) = pose_mm(50.0, 0.0, 0.0, 0.0);
        body(&mut m, "BOLT", "1", p);
        body(&mut m, "NUT", "2", p);
        let mut s = Scene::default();
        let asm = node(&mut s, None, "ASM", Matrix4::identity(), false);
        // Each part keeps its shapes in nested groups at the part's own pose, as exporters do.
        let nut = node(&mut s, Some(asm), "NUT01", mm, false);
        node(&mut s, Some(nut), "Shape", Matrix4::identity(), true);
        let bolt = node(&mut s, Some(asm), "BOLT01", mm, false);
        node(&mut s, Some(bolt), "Shape", Matrix4::identity(), true);
        node(&mut s, Some(bolt), "Shape2", Matrix4::identity(), true);
        let (rep, w) = match_scene(&mut m, &s, &BTreeMap::new(), &MatchOptions::default()).unwrap();
        assert!(w.is_empty(), "{w:?}");
        assert_eq!(rep.bodies["1"][0].node_path, "ASM/BOLT01");
        assert_eq!(rep.bodies["1"][0].triangles, 2);
        assert_eq!(rep.bodies["1"][0].rule, Rule::Name);
        assert_eq!(rep.bodies["2"][0].node_path, "ASM/NUT01");

        let mut m = mm_model();
        let (p2, m2) = pose_mm(50.0, 0.0, 0.0, 1.0);
        body(&mut m, "LINK", "1", p2);
        let mut s = Scene::default();
        let asm = node(&mut s, None, "ASM", Matrix4::identity(), false);
        node(&mut s, Some(asm), "A", mm, true);
        node(&mut s, Some(asm), "B", m2, true);
        let (rep, w) = match_scene(&mut m, &s, &BTreeMap::new(), &MatchOptions::default()).unwrap();
        assert_eq!(rep.bodies["1"][0].node_path, "ASM/B");
        assert_eq!(rep.bodies["1"][0].rule, Rule::Orientation);
        assert_eq!(w.len(), 1, "the other node is reported unmatched");
        assert_eq!(w[0].code, "vrml-unmatched");
    }

    #[test]
    fn ambiguity_is_an_error_unless_pinned() {
        let mut m = mm_model();
        let (p, mm) = pose_mm(50.0, 0.0, 0.0, 0.0);
        body(&mut m, "Obj", "7", p);
        let mut s = Scene::default();
        let asm = node(&mut s, None, "ASM", Matrix4::identity(), false);
        node(&mut s, Some(asm), "Obj01", mm, true);
        node(&mut s, Some(asm), "Obj02", mm, true);
        let err = match_scene(&mut m.clone(), &s, &BTreeMap::new(), &MatchOptions::default()).unwrap_err();
        assert!(err.to_string().contains("ASM/Obj01, ASM/Obj02"), "{err}");
        let pins = parse_pins(br#"{"7": "ASM/Obj02"}"#).unwrap();
        let (rep, _) = match_scene(&mut m, &s, &pins, &MatchOptions::default()).unwrap();
        assert_eq!(rep.bodies["7"][0].rule, Rule::Pinned);
        assert_eq!(rep.bodies["7"][0].node_path, "ASM/Obj02");
        assert!(matches!(parse_pins(b"[1]"), Err(MatchError::BadPins(_))));
        let bad = parse_pins(br#"{"7": "ASM/Nope"}"#).unwrap();
        assert!(matches!(match_scene(&mut mm_model(), &s, &bad, &MatchOptions::default()), Err(MatchError::UnknownPinnedBody(_))));
    }

    #[test]
    fn scale_is_found_when_vrml_is_in_metres() {
        let mut m = mm_model();
        let (pa, _) = pose_mm(100.0, 20.0, 0.0, 0.0);
        let (pb, _) = pose_mm(-40.0, 0.0, 300.0, 0.0);
        body(&mut m, "A", "1", pa);
        body(&mut m, "B", "2", pb);
        let mut s = Scene::default();
        let root = node(&mut s, None, "ROOT", Matrix4::identity(), false);
        node(&mut s, Some(root), "A1", Matrix4::new_translation(&Vector3::new(0.1, 0.02, 0.0)), true);
        node(&mut s, Some(root), "B1", Matrix4::new_translation(&Vector3::new(-0.04, 0.0, 0.3)), true);
        let (rep, w) = match_scene(&mut m, &s, &BTreeMap::new(), &MatchOptions::default()).unwrap();
        assert_eq!(rep.scale, 1.0);
        assert_eq!(rep.scale_score, (2, 2));
        assert!(w.iter().any(|w| w.code == "vrml-scale"));
        assert_eq!(m.bodies[0].mesh.as_ref().unwrap().vertices[1], [10.0, 0.0, 0.0], "metres kept as metres");
    }

    #[test]
    fn name_stems() {
        assert_eq!(name_stem("Obj01"), "obj");
        assert_eq!(name_stem("Obj-1"), "obj");
        assert_eq!(name_stem("obj_1"), "obj");
        assert_eq!(name_stem("ARM_2B"), "arm2b");
    }
}
