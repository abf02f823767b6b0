//! The VRML front end's output: a flattened scene graph with global transforms.
//!
//! Every grouping node (Transform, Group, Separator, Inline root, PROTO instance, ...) becomes a
//! [`SceneNode`] in an arena; geometry nodes become [`ShapeGeom`]s attached to their nearest
//! grouping ancestor. Coordinates are in the VRML file's own units (VRML has none: the matching
//! pass finds the scale to metres).

use nalgebra::Matrix4;

use crate::pipeline::ir::Mesh;

/// Index into [`Scene::nodes`].
pub type NodeId = usize;

/// One grouping node.
#[derive(Clone, Debug)]
pub struct SceneNode {
    /// `None` for a root (a top-level node of the main file).
    pub parent: Option<NodeId>,
    /// The DEF name when the node has one, else its type (`Transform`, `Group`, `Inline`, or the
    /// PROTO's name).
    pub name: String,
    /// Whether `name` is a DEF name (user- or exporter-given) rather than a type name.
    pub named: bool,
    /// The node path: names from the root down, `/`-separated, with `[k]` for the k-th unnamed
    /// child of its parent, e.g. `ASM/Obj01/Transform[0]`. Unique in the scene and stable for
    /// an unchanged file: `matching.json` pins refer to it.
    pub path: String,
    /// The bundle file the node is written in.
    pub file: String,
    /// 1-based line of the node in `file` (0 when unknown).
    pub line: u32,
    /// Transform from this node's coordinate system to the scene root (file units), including
    /// every ancestor's Transform (VRML 97: T * C * R * SR * S * -SR * -C).
    pub global: Matrix4<f64>,
    /// Geometry directly inside this node (not in child grouping nodes).
    pub shapes: Vec<ShapeGeom>,
    /// Child grouping nodes, in file order.
    pub children: Vec<NodeId>,
}

/// One geometry node, triangulated, in its grouping node's local coordinates.
#[derive(Clone, Debug)]
pub struct ShapeGeom {
    /// Triangles in the owning node's coordinate system (file units).
    pub mesh: Mesh,
    /// Diffuse colour of the shape's Material (or its first face/vertex colour), 0..=1.
    pub color: Option<[f32; 3]>,
    /// `IndexedFaceSet`, `Box`, `Sphere`, `Cylinder`, `Cone` (VRML 1.0: `IndexedFaceSet`, `Cube`, ...).
    pub kind: &'static str,
    /// 1-based line of the geometry node.
    pub line: u32,
}

/// A parsed VRML export: every root of the main file and everything it inlines.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    pub nodes: Vec<SceneNode>,
    pub roots: Vec<NodeId>,
    /// The files read (main first), bundle paths.
    pub files: Vec<String>,
}

impl Scene {
    /// Every shape at or below `node`, with the node it hangs from.
    pub fn shapes_below(&self, node: NodeId) -> Vec<(NodeId, &ShapeGeom)> {
        let mut out = Vec::new();
        let mut stack = vec![node];
        while let Some(n) = stack.pop() {
            for s in &self.nodes[n].shapes {
                out.push((n, s));
            }
            stack.extend(self.nodes[n].children.iter().rev());
        }
        out
    }

    /// Adds another scene's nodes (e.g. a second main file) as further roots.
    pub fn append(&mut self, other: Scene) {
        let base = self.nodes.len();
        for mut n in other.nodes {
            n.parent = n.parent.map(|p| p + base);
            for c in &mut n.children {
                *c += base;
            }
            self.nodes.push(n);
        }
        self.roots.extend(other.roots.into_iter().map(|r| r + base));
        self.files.extend(other.files);
    }

    /// Total triangles in the scene.
    pub fn triangle_count(&self) -> usize {
        self.nodes.iter().flat_map(|n| &n.shapes).map(|s| s.mesh.triangles.len()).sum()
    }
}
