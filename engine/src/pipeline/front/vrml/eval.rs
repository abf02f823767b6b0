//! Parsed files to the [`Scene`]: grouping nodes become scene nodes with global transforms,
//! geometry is triangulated, Inlines are followed.

use std::collections::HashSet;

use nalgebra::Matrix4;

use super::ast::*;
use super::geom::{self, BadIndex};
use super::parse::{Loader, R};
use super::resolve::resolve_url;
use super::scene::{NodeId, Scene, SceneNode, ShapeGeom};
use super::{VrmlError, VrmlErrorKind, MAX_DEPTH};
use crate::pipeline::ir::{Mesh, Warning};

/// VRML 1.0 traversal state. `m` is relative to the scene node being filled.
#[derive(Clone)]
struct V1State {
    m: Matrix4<f64>,
    coords: Option<NodeRef>,
    color: Option<[f32; 3]>,
    clockwise: bool,
}

impl V1State {
    fn new() -> Self {
        V1State { m: Matrix4::identity(), coords: None, color: None, clockwise: false }
    }
}

pub(super) struct Eval<'l, 'b> {
    ld: &'l mut Loader<'b>,
    pub scene: Scene,
    /// Path segments used by each node's children (last entry: the roots).
    used: Vec<HashSet<String>>,
    unnamed: Vec<u32>,
    root_used: HashSet<String>,
    root_unnamed: u32,
    inline_stack: Vec<String>,
    triangles: usize,
    shapes: usize,
}

fn node_error(n: &Node, kind: VrmlErrorKind) -> Box<VrmlError> {
    Box::new(VrmlError { file: n.file.to_string(), line: n.line, column: n.col, kind })
}

/// The node a PROTO instance stands for.
fn unwrap(mut n: &NodeRef) -> &NodeRef {
    while let Kind::Instance(Some(inner)) = &n.kind {
        n = inner;
    }
    n
}

/// `%`, `/`, `[` and `]` escaped, so a name cannot fake a path separator or an index.
fn escape(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    for c in name.chars() {
        match c {
            '%' => out.push_str("%25"),
            '/' => out.push_str("%2F"),
            '[' => out.push_str("%5B"),
            ']' => out.push_str("%5D"),
            c => out.push(c),
        }
    }
    out
}

/// How a node is named in messages: its type and DEF name.
fn describe(n: &Node) -> String {
    match &n.def {
        Some(d) => format!("{} \"{d}\"", n.type_name),
        None => n.type_name.to_string(),
    }
}

/// `m * p` for an affine `m`.
fn bake(mesh: &mut Mesh, m: &Matrix4<f64>) {
    if *m == Matrix4::identity() {
        return;
    }
    for v in &mut mesh.vertices {
        let p = [f64::from(v[0]), f64::from(v[1]), f64::from(v[2])];
        let mut q = [0.0f32; 3];
        for (r, out) in q.iter_mut().enumerate() {
            *out = (m[(r, 0)] * p[0] + m[(r, 1)] * p[1] + m[(r, 2)] * p[2] + m[(r, 3)]) as f32;
        }
        *v = q;
    }
}

impl<'l, 'b> Eval<'l, 'b> {
    pub fn new(ld: &'l mut Loader<'b>, main: &str) -> Self {
        Eval {
            ld,
            scene: Scene::default(),
            used: Vec::new(),
            unnamed: Vec::new(),
            root_used: HashSet::new(),
            root_unnamed: 0,
            inline_stack: vec![main.to_string()],
            triangles: 0,
            shapes: 0,
        }
    }

    /// Evaluates the main file's roots.
    pub fn run(&mut self, main: &ParsedFile) -> R<()> {
        self.file_roots(main, None, &Matrix4::identity(), 0)
    }

    /// A new scene node named after `ident` (its DEF name or type).
    fn add_node(&mut self, parent: Option<NodeId>, ident: &Node, global: Matrix4<f64>) -> R<NodeId> {
        let limit = self.ld.limits.scene_nodes;
        if self.scene.nodes.len() >= limit {
            return Err(node_error(ident, VrmlErrorKind::TooManyNodes { limit: limit as u64 }));
        }
        let (name, named) = match &ident.def {
            Some(d) => (d.to_string(), true),
            None => (ident.type_name.to_string(), false),
        };
        let (used, unnamed) = match parent {
            Some(p) => (&mut self.used[p], &mut self.unnamed[p]),
            None => (&mut self.root_used, &mut self.root_unnamed),
        };
        let base = escape(&name);
        let mut seg = if named {
            base.clone()
        } else {
            *unnamed += 1;
            format!("{base}[{}]", *unnamed - 1)
        };
        let mut n = 1;
        while used.contains(&seg) {
            seg = format!("{base}[{n}]");
            n += 1;
        }
        used.insert(seg.clone());
        let path = match parent {
            Some(p) => format!("{}/{seg}", self.scene.nodes[p].path),
            None => seg,
        };
        let id = self.scene.nodes.len();
        self.scene.nodes.push(SceneNode {
            parent,
            name,
            named,
            path,
            file: ident.file.to_string(),
            line: ident.line,
            global,
            shapes: Vec::new(),
            children: Vec::new(),
        });
        self.used.push(HashSet::new());
        self.unnamed.push(0);
        match parent {
            Some(p) => self.scene.nodes[p].children.push(id),
            None => self.scene.roots.push(id),
        }
        Ok(id)
    }

    /// Hangs a shape from `parent`, or from a new root named after `ident` at the top level.
    fn attach(&mut self, parent: Option<NodeId>, ident: &Node, shape: ShapeGeom) -> R<()> {
        self.shapes += 1;
        self.triangles += shape.mesh.triangles.len();
        let limits = self.ld.limits;
        if self.triangles > limits.triangles {
            return Err(node_error(ident, VrmlErrorKind::TooManyTriangles { limit: limits.triangles }));
        }
        if self.shapes > limits.shapes {
            return Err(node_error(ident, VrmlErrorKind::TooManyNodes { limit: limits.shapes as u64 }));
        }
        let id = match parent {
            Some(p) => p,
            None => self.add_node(None, ident, Matrix4::identity())?,
        };
        self.scene.nodes[id].shapes.push(shape);
        Ok(())
    }

    fn file_roots(&mut self, file: &ParsedFile, parent: Option<NodeId>, global: &Matrix4<f64>, depth: u32) -> R<()> {
        match file.version {
            Version::V2 => {
                for r in &file.roots {
                    self.node2(r, r, parent, global, depth)?;
                }
            }
            Version::V1 => {
                let mut st = V1State::new();
                for r in &file.roots {
                    self.node1(r, &mut st, parent, global, depth)?;
                }
            }
        }
        Ok(())
    }

    /// A VRML 97 node. `ident` names the scene node it makes (the outermost PROTO instance
    /// when `n` is an instance's body).
    fn node2(&mut self, n: &Node, ident: &Node, parent: Option<NodeId>, pglobal: &Matrix4<f64>, depth: u32) -> R<()> {
        if depth > MAX_DEPTH {
            return Err(node_error(n, VrmlErrorKind::TooDeep { limit: MAX_DEPTH }));
        }
        match &n.kind {
            Kind::Group { children, matrix } => {
                let g = match matrix {
                    Some(m) => pglobal * **m,
                    None => *pglobal,
                };
                let id = self.add_node(parent, ident, g)?;
                for c in children {
                    self.node2(c, c, Some(id), &g, depth + 1)?;
                }
            }
            Kind::Switch { which, choice } => {
                let id = self.add_node(parent, ident, *pglobal)?;
                if let Some(c) = usize::try_from(*which).ok().and_then(|w| choice.get(w)) {
                    self.node2(c, c, Some(id), pglobal, depth + 1)?;
                }
            }
            Kind::Lod { level } => {
                let id = self.add_node(parent, ident, *pglobal)?;
                if let Some(c) = level.first() {
                    self.node2(c, c, Some(id), pglobal, depth + 1)?;
                }
            }
            Kind::Inline { urls } => {
                let id = self.add_node(parent, ident, *pglobal)?;
                self.inline(urls, n, id, pglobal, depth)?;
            }
            Kind::Shape { .. } => {
                if let Some(s) = self.shape2(n)? {
                    self.attach(parent, ident, s)?;
                }
            }
            Kind::Instance(Some(inner)) => self.node2(inner, ident, parent, pglobal, depth + 1)?,
            _ => {}
        }
        Ok(())
    }

    /// A VRML 97 Shape's geometry and colour (`None` when it has no triangles).
    fn shape2(&mut self, shape: &Node) -> R<Option<ShapeGeom>> {
        let Kind::Shape { appearance, geometry } = &shape.kind else { return Ok(None) };
        let Some(geom) = geometry.as_ref().map(unwrap) else { return Ok(None) };
        let material = appearance
            .as_ref()
            .map(unwrap)
            .and_then(|a| match &a.kind {
                Kind::Appearance { material } => material.as_ref().map(unwrap),
                _ => None,
            })
            .and_then(|m| match m.kind {
                Kind::Material { diffuse } => Some(diffuse),
                _ => None,
            });
        let (mesh, color, kind) = match &geom.kind {
            Kind::Ifs(ifs) => {
                let points = ifs.coord.as_ref().map(unwrap).and_then(|c| match &c.kind {
                    Kind::Coordinate { points } => Some(points.as_slice()),
                    _ => None,
                });
                let mesh = ifs_mesh(geom, points.unwrap_or(&[]), &ifs.coord_index, ifs.ccw)?;
                let first = ifs.color.as_ref().map(unwrap).and_then(|c| match &c.kind {
                    Kind::Color { colors } => colors.first().copied(),
                    _ => None,
                });
                (mesh, material.or(first), "IndexedFaceSet")
            }
            Kind::Prim(p) => (geom::primitive(p), material, p.kind(false)),
            _ => return Ok(None),
        };
        if mesh.triangles.is_empty() {
            return Ok(None);
        }
        Ok(Some(ShapeGeom { mesh, color, kind, line: geom.line }))
    }

    /// A VRML 1.0 node, updating the traversal state.
    fn node1(&mut self, n: &NodeRef, st: &mut V1State, parent: Option<NodeId>, pglobal: &Matrix4<f64>, depth: u32) -> R<()> {
        if depth > MAX_DEPTH {
            return Err(node_error(n, VrmlErrorKind::TooDeep { limit: MAX_DEPTH }));
        }
        match &n.kind {
            Kind::V1Group { kind, children } => {
                // The transforms a Separator or Group starts with (before its first shape, group
                // or inline; property nodes may come between) place the node itself: they go
                // into its global transform instead of its geometry.
                let folds = matches!(kind, V1GroupKind::Separator | V1GroupKind::TransformSeparator | V1GroupKind::Group);
                let mut lead = Matrix4::identity();
                let mut skip = 0;
                if folds {
                    for c in children {
                        match &c.kind {
                            Kind::V1Xform(m) => lead *= **m,
                            Kind::Coordinate { .. }
                            | Kind::Material { .. }
                            | Kind::V1ShapeHints { .. }
                            | Kind::Other
                            | Kind::IgnoredGeometry => {}
                            _ => break,
                        }
                        skip += 1;
                    }
                }
                let g = pglobal * st.m * lead;
                let id = self.add_node(parent, n, g)?;
                let mut inner = V1State { m: Matrix4::identity(), ..st.clone() };
                let selected = kind.traversed(children);
                for (i, c) in selected.iter().enumerate() {
                    if i < skip && matches!(c.kind, Kind::V1Xform(_)) {
                        continue; // already in `lead`
                    }
                    self.node1(c, &mut inner, Some(id), &g, depth + 1)?;
                }
                match kind {
                    V1GroupKind::Separator => {}
                    V1GroupKind::TransformSeparator => {
                        st.coords = inner.coords;
                        st.color = inner.color;
                        st.clockwise = inner.clockwise;
                    }
                    _ => {
                        let m = st.m * lead * inner.m;
                        *st = V1State { m, ..inner };
                    }
                }
            }
            Kind::V1Xform(m) => st.m *= **m,
            Kind::Coordinate { .. } => st.coords = Some(n.clone()),
            Kind::Material { diffuse } => st.color = Some(*diffuse),
            Kind::V1ShapeHints { clockwise: Some(cw) } => st.clockwise = *cw,
            Kind::V1Ifs { coord_index } => {
                let coords = st.coords.clone();
                let points = match coords.as_deref().map(|c| &c.kind) {
                    Some(Kind::Coordinate { points }) => points.as_slice(),
                    _ => &[],
                };
                let mut mesh = ifs_mesh(n, points, coord_index, !st.clockwise)?;
                bake(&mut mesh, &st.m);
                self.v1_shape(n, mesh, st, parent)?;
            }
            Kind::V1FaceSet { start, num_vertices } => {
                let coords = st.coords.clone();
                let points = match coords.as_deref().map(|c| &c.kind) {
                    Some(Kind::Coordinate { points }) => points.as_slice(),
                    _ => &[],
                };
                // Faces take consecutive points from startIndex; check the total before
                // building the index list (a corrupt count must not allocate billions).
                let total: i64 = num_vertices.iter().map(|&k| i64::from(k.max(0))).sum();
                let end = i64::from(*start) + total;
                if *start < 0 || end > points.len() as i64 {
                    let index = if *start < 0 { i64::from(*start) } else { end - 1 };
                    return Err(node_error(n, VrmlErrorKind::IndexOutOfRange { node: describe(n), index, count: points.len() }));
                }
                let mut index = Vec::with_capacity(total as usize + num_vertices.len());
                let mut next = *start;
                for &k in num_vertices {
                    for _ in 0..k.max(0) {
                        index.push(next);
                        next += 1;
                    }
                    index.push(-1);
                }
                let mut mesh = ifs_mesh(n, points, &index, !st.clockwise)?;
                bake(&mut mesh, &st.m);
                self.v1_shape(n, mesh, st, parent)?;
            }
            Kind::Prim(p) => {
                let mut mesh = geom::primitive(p);
                bake(&mut mesh, &st.m);
                self.v1_shape(n, mesh, st, parent)?;
            }
            Kind::V1Inline { name } => {
                let g = pglobal * st.m;
                let id = self.add_node(parent, n, g)?;
                self.inline(std::slice::from_ref(name), n, id, &g, depth)?;
            }
            _ => {}
        }
        Ok(())
    }

    fn v1_shape(&mut self, n: &Node, mesh: Mesh, st: &V1State, parent: Option<NodeId>) -> R<()> {
        if mesh.triangles.is_empty() {
            return Ok(());
        }
        let kind = match &n.kind {
            Kind::Prim(p) => p.kind(true),
            Kind::V1FaceSet { .. } => "FaceSet",
            _ => "IndexedFaceSet",
        };
        self.attach(parent, n, ShapeGeom { mesh, color: st.color, kind, line: n.line })
    }

    /// Follows an Inline (VRML 97 `url`, VRML 1.0 `name`): the first url found in the bundle is
    /// read and its roots hang from `parent`.
    fn inline(&mut self, urls: &[String], at: &Node, parent: NodeId, g: &Matrix4<f64>, depth: u32) -> R<()> {
        let mut target = None;
        for u in urls {
            match resolve_url(self.ld.bundle, &at.file, u) {
                Ok(Some(p)) => {
                    target = Some(p);
                    break;
                }
                Ok(None) => {}
                Err(e) => return Err(node_error(at, VrmlErrorKind::Bundle { message: e.to_string() })),
            }
        }
        let Some(path) = target else {
            let list = urls.iter().map(|u| format!("\"{u}\"")).collect::<Vec<_>>().join(", ");
            let what = if list.is_empty() { "no url".to_string() } else { list };
            self.ld.warnings.push(Warning::new(
                "vrml-inline-missing",
                format!("{} {what}: not found in the bundle; the node is kept without geometry", at.type_name),
                format!("{}:{}:{}", at.file, at.line, at.col),
            ));
            return Ok(());
        };
        if let Some(i) = self.inline_stack.iter().position(|p| *p == path) {
            let mut chain = self.inline_stack[i..].to_vec();
            chain.push(path);
            return Err(node_error(at, VrmlErrorKind::InlineCycle { chain }));
        }
        let file = self.ld.load(&path)?;
        // The inlined file's expansion is known from its parse: refuse it before expanding it.
        let have = Cost { scene: self.scene.nodes.len() as u64, shapes: self.shapes as u64, triangles: self.triangles as u64 };
        if let Some((unit, projected, limit)) = self.ld.limits.exceeded(have, Cost::sum(&file.roots)) {
            let what = format!("{} \"{path}\"", at.type_name);
            return Err(node_error(at, VrmlErrorKind::Expansion { what, unit, projected, limit }));
        }
        self.inline_stack.push(path);
        let r = self.file_roots(&file, Some(parent), g, depth + 1);
        self.inline_stack.pop();
        r
    }
}

/// The triangles of an indexed face set, or an error naming the node.
fn ifs_mesh(n: &Node, points: &[[f32; 3]], index: &[i32], ccw: bool) -> R<Mesh> {
    geom::indexed_mesh(points, index, ccw).map_err(|BadIndex { index, count }| {
        node_error(n, VrmlErrorKind::IndexOutOfRange { node: describe(n), index: i64::from(index), count })
    })
}
