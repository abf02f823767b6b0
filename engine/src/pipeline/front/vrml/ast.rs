//! The parsed form of one file: the nodes the scene needs, shared by DEF/USE (`Rc`), with
//! everything else dropped at parse time.

use std::cell::Cell;
use std::rc::Rc;

use nalgebra::Matrix4;

/// A node shared by DEF/USE.
pub(super) type NodeRef = Rc<Node>;

/// Which VRML the file is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Version {
    V1,
    V2,
}

/// One parsed node.
#[derive(Debug)]
pub(super) struct Node {
    /// The DEF name, when it has one.
    pub def: Option<Rc<str>>,
    /// The node type as written (`Transform`, a PROTO's name, ...).
    pub type_name: Rc<str>,
    /// The bundle file it is written in.
    pub file: Rc<str>,
    pub line: u32,
    pub col: u32,
    /// 1 + the largest height of the nodes it holds (bounds recursion in evaluation and drop).
    pub height: u32,
    /// What evaluating the node adds to the scene (USE'd nodes counted as often as they are
    /// used), known before anything is expanded.
    pub cost: Cost,
    pub kind: Kind,
}

/// What a node expands to in the scene: grouping nodes, shapes and triangles (saturating
/// sums; an upper bound for triangles). Inlined files are not included (they are read during
/// evaluation, which checks their cost before expanding them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Cost {
    pub scene: u64,
    pub shapes: u64,
    pub triangles: u64,
}

impl Cost {
    pub fn add(self, o: Cost) -> Cost {
        Cost {
            scene: self.scene.saturating_add(o.scene),
            shapes: self.shapes.saturating_add(o.shapes),
            triangles: self.triangles.saturating_add(o.triangles),
        }
    }

    pub fn sum<'a>(nodes: impl IntoIterator<Item = &'a NodeRef>) -> Cost {
        nodes.into_iter().fold(Cost::default(), |acc, n| acc.add(n.cost))
    }
}

/// Triangles of `-1`-separated polygons (k corners make k - 2; fewer than 3 make none).
pub(super) fn polygon_triangles(index: &[i32]) -> u64 {
    let mut total = 0u64;
    let mut k = 0u64;
    for &i in index.iter().chain(std::iter::once(&-1)) {
        if i == -1 {
            total += k.saturating_sub(2);
            k = 0;
        } else {
            k += 1;
        }
    }
    total
}

impl Kind {
    /// Every node this node holds.
    pub fn nodes(&self) -> Vec<&NodeRef> {
        match self {
            Kind::Group { children, .. } | Kind::V1Group { children, .. } => children.iter().collect(),
            Kind::Switch { choice, .. } => choice.iter().collect(),
            Kind::Lod { level } => level.iter().collect(),
            Kind::Shape { appearance, geometry } => appearance.iter().chain(geometry.iter()).collect(),
            Kind::Appearance { material } => material.iter().collect(),
            Kind::Ifs(ifs) => ifs.coord.iter().chain(ifs.color.iter()).collect(),
            Kind::Instance(inner) => inner.iter().collect(),
            _ => Vec::new(),
        }
    }

    /// The height of a node of this kind.
    pub fn height(&self) -> u32 {
        1 + self.nodes().iter().map(|n| n.height).max().unwrap_or(0)
    }

    /// What a node of this kind adds to the scene, from what it holds (evaluation follows the
    /// same rules: a Switch its chosen child, an LOD its first level).
    pub fn cost(&self) -> Cost {
        let one = Cost { scene: 1, shapes: 0, triangles: 0 };
        let shape = |triangles: u64| {
            if triangles == 0 {
                Cost::default()
            } else {
                Cost { scene: 0, shapes: 1, triangles }
            }
        };
        match self {
            Kind::Group { children, .. } => one.add(Cost::sum(children)),
            Kind::Switch { which, choice } => one.add(Cost::sum(usize::try_from(*which).ok().and_then(|w| choice.get(w)))),
            Kind::Lod { level } => one.add(Cost::sum(level.first())),
            Kind::Inline { .. } | Kind::V1Inline { .. } => one,
            Kind::Shape { geometry, .. } => {
                let mut g = geometry.as_ref();
                while let Some(Kind::Instance(Some(inner))) = g.map(|n| &n.kind) {
                    g = Some(inner);
                }
                match g.map(|n| &n.kind) {
                    Some(Kind::Ifs(ifs)) => shape(polygon_triangles(&ifs.coord_index)),
                    Some(Kind::Prim(p)) => shape(p.triangles()),
                    _ => Cost::default(),
                }
            }
            Kind::Instance(Some(inner)) => inner.cost,
            Kind::V1Group { kind, children } => {
                let selected = kind.traversed(children);
                one.add(Cost::sum(selected))
            }
            Kind::Prim(p) => shape(p.triangles()),
            Kind::V1Ifs { coord_index } => shape(polygon_triangles(coord_index)),
            Kind::V1FaceSet { num_vertices, .. } => {
                shape(num_vertices.iter().map(|&k| u64::try_from(k).unwrap_or(0).saturating_sub(2)).sum())
            }
            _ => Cost::default(),
        }
    }
}

/// VRML 1.0 grouping nodes, which differ in how they treat the traversal state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum V1GroupKind {
    /// Saves and restores the whole state.
    Separator,
    /// Saves and restores the transform only.
    TransformSeparator,
    /// State changes inside leak out (Group, WWWAnchor).
    Group,
    /// Like Group, traversing only child `which` (-1 none, -3 all).
    Switch(i32),
    /// Like Group, traversing only the first child (the highest detail).
    Lod,
}

impl V1GroupKind {
    /// The children a traversal visits.
    pub(super) fn traversed(self, children: &[NodeRef]) -> &[NodeRef] {
        match self {
            V1GroupKind::Switch(-3) => children,
            V1GroupKind::Switch(w) => match usize::try_from(w) {
                Ok(w) if w < children.len() => &children[w..=w],
                _ => &[],
            },
            V1GroupKind::Lod => &children[..children.len().min(1)],
            _ => children,
        }
    }
}

/// A primitive shape with its VRML parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Prim {
    Box { size: [f64; 3] },
    Sphere { radius: f64 },
    Cylinder { radius: f64, height: f64, bottom: bool, top: bool, side: bool },
    Cone { bottom_radius: f64, height: f64, side: bool, bottom: bool },
}

impl Prim {
    /// Triangles of its tessellation (see `geom::primitive`).
    pub fn triangles(&self) -> u64 {
        let seg = super::geom::SEGMENTS as u64;
        let rings = super::geom::RINGS as u64;
        match *self {
            Prim::Box { .. } => 12,
            Prim::Sphere { .. } => seg * 2 * (rings - 1),
            Prim::Cylinder { top, bottom, side, .. } => seg * (2 * u64::from(side) + u64::from(top) + u64::from(bottom)),
            Prim::Cone { side, bottom, .. } => seg * (u64::from(side) + u64::from(bottom)),
        }
    }

    pub fn kind(&self, v1: bool) -> &'static str {
        match self {
            Prim::Box { .. } if v1 => "Cube",
            Prim::Box { .. } => "Box",
            Prim::Sphere { .. } => "Sphere",
            Prim::Cylinder { .. } => "Cylinder",
            Prim::Cone { .. } => "Cone",
        }
    }
}

/// An IndexedFaceSet (VRML 97).
#[derive(Debug)]
pub(super) struct Ifs {
    pub coord: Option<NodeRef>,
    pub coord_index: Vec<i32>,
    pub ccw: bool,
    pub color: Option<NodeRef>,
}

#[derive(Debug)]
pub(super) enum Kind {
    /// Transform (with its matrix), Group, Anchor, Collision, Billboard, and the instances of
    /// an unresolved EXTERNPROTO.
    Group {
        children: Vec<NodeRef>,
        matrix: Option<Box<Matrix4<f64>>>,
    },
    Switch {
        which: i32,
        choice: Vec<NodeRef>,
    },
    Lod {
        level: Vec<NodeRef>,
    },
    Inline {
        urls: Vec<String>,
    },
    Shape {
        appearance: Option<NodeRef>,
        geometry: Option<NodeRef>,
    },
    Appearance {
        material: Option<NodeRef>,
    },
    Material {
        diffuse: [f32; 3],
    },
    /// Coordinate (VRML 97) or Coordinate3 (VRML 1.0).
    Coordinate {
        points: Vec<[f32; 3]>,
    },
    Color {
        colors: Vec<[f32; 3]>,
    },
    Ifs(Box<Ifs>),
    Prim(Prim),
    /// A PROTO instance: the body's first node (`None` for an empty body).
    Instance(Option<NodeRef>),
    /// Geometry this reader does not triangulate (IndexedLineSet, PointSet, ...).
    IgnoredGeometry,
    /// Anything else: skipped.
    Other,
    // VRML 1.0
    V1Group {
        kind: V1GroupKind,
        children: Vec<NodeRef>,
    },
    V1Inline {
        name: String,
    },
    /// Transform, MatrixTransform, Translation, Rotation, Scale: post-multiplied into the state.
    V1Xform(Box<Matrix4<f64>>),
    /// ShapeHints: `Some(true)` for CLOCKWISE vertex ordering.
    V1ShapeHints {
        clockwise: Option<bool>,
    },
    /// IndexedFaceSet over the current Coordinate3.
    V1Ifs {
        coord_index: Vec<i32>,
    },
    /// FaceSet over the current Coordinate3.
    V1FaceSet {
        start: i32,
        num_vertices: Vec<i32>,
    },
}

/// A field's declared type (VRML 97, plus the VRML 1.0 types the reader needs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FieldType {
    SFBool,
    SFColor,
    SFFloat,
    SFImage,
    SFInt32,
    SFNode,
    SFRotation,
    SFString,
    SFTime,
    SFVec2f,
    SFVec3f,
    SFVec4f,
    SFMatrix,
    /// VRML 1.0 SFEnum / SFBitMask: words, `(A | B)`.
    SFEnum,
    MFBool,
    MFColor,
    MFFloat,
    MFInt32,
    MFNode,
    MFRotation,
    MFString,
    MFTime,
    MFVec2f,
    MFVec3f,
}

impl FieldType {
    pub fn from_name(name: &[u8]) -> Option<FieldType> {
        use FieldType::*;
        Some(match name {
            b"SFBool" => SFBool,
            b"SFColor" | b"SFColorRGBA" => SFColor,
            b"SFFloat" | b"SFDouble" => SFFloat,
            b"SFImage" => SFImage,
            b"SFInt32" | b"SFLong" => SFInt32,
            b"SFNode" => SFNode,
            b"SFRotation" => SFRotation,
            b"SFString" => SFString,
            b"SFTime" => SFTime,
            b"SFVec2f" | b"SFVec2d" => SFVec2f,
            b"SFVec3f" | b"SFVec3d" => SFVec3f,
            b"SFVec4f" | b"SFVec4d" => SFVec4f,
            b"SFMatrix" => SFMatrix,
            b"SFEnum" | b"SFBitMask" => SFEnum,
            b"MFBool" => MFBool,
            b"MFColor" => MFColor,
            b"MFFloat" | b"MFDouble" | b"MFColorRGBA" | b"MFVec4f" | b"MFVec2d" => MFFloat,
            b"MFInt32" | b"MFLong" | b"MFImage" => MFInt32,
            b"MFNode" => MFNode,
            b"MFRotation" => MFRotation,
            b"MFString" => MFString,
            b"MFTime" => MFTime,
            b"MFVec2f" => MFVec2f,
            b"MFVec3f" | b"MFVec3d" => MFVec3f,
            _ => return None,
        })
    }

    /// Numbers in one value of a fixed-size numeric type.
    pub fn arity(self) -> usize {
        use FieldType::*;
        match self {
            SFFloat | SFTime | MFFloat | MFTime => 1,
            SFVec2f | MFVec2f => 2,
            SFColor | SFVec3f | MFColor | MFVec3f => 3,
            SFRotation | MFRotation | SFVec4f => 4,
            SFMatrix => 16,
            _ => 1,
        }
    }
}

/// A parsed field value.
#[derive(Clone, Debug)]
pub(super) enum Value {
    Bools(Vec<bool>),
    Floats(Vec<f64>),
    /// MFVec3f / MFColor, straight into `f32` triples (mesh precision).
    Vec3(Vec<[f32; 3]>),
    Ints(Vec<i32>),
    Strings(Vec<String>),
    Nodes(Vec<NodeRef>),
    /// A value that was skipped (SFImage).
    Skipped,
}

/// One interface declaration of a PROTO.
#[derive(Clone, Debug)]
pub(super) struct FieldDecl {
    pub name: String,
    pub ty: FieldType,
    /// The default (`None` for eventIn/eventOut and EXTERNPROTO declarations).
    pub default: Option<Value>,
}

/// A PROTO body kept as text, parsed again for every instance (so each instance has its own DEF
/// namespace and IS values).
#[derive(Clone, Debug)]
pub(super) struct ProtoBody {
    /// The body's text, from the start of the line where it begins to its closing brace.
    pub text: Rc<[u8]>,
    /// Offset of the body's first byte (after `{`) in `text`.
    pub start: usize,
    /// Line of `text`'s first byte.
    pub line: u32,
    pub file: Rc<str>,
}

/// A PROTO (or a resolved EXTERNPROTO).
#[derive(Debug)]
pub(super) struct ProtoDef {
    pub name: Rc<str>,
    pub fields: Vec<FieldDecl>,
    /// `None` for an EXTERNPROTO that could not be resolved: instances become Groups.
    pub body: Option<ProtoBody>,
    /// The PROTOs visible where this one was declared.
    pub scope: ProtoScope,
    /// Nodes parsed by one instance (its body's first node, nested instances expanded),
    /// memoised on first use. The same for every instance: IS values are shared, not parsed.
    pub parse_cost: Cell<Option<u64>>,
}

/// PROTOs in scope: a persistent list, newest first.
#[derive(Clone, Debug, Default)]
pub(super) struct ProtoScope(pub Option<Rc<ProtoLink>>);

#[derive(Debug)]
pub(super) struct ProtoLink {
    pub def: Rc<ProtoDef>,
    pub next: ProtoScope,
}

impl Drop for ProtoLink {
    /// Iterative, so a file with very many PROTOs cannot overflow the stack when dropped.
    fn drop(&mut self) {
        let mut next = self.next.0.take();
        while let Some(rc) = next {
            match Rc::try_unwrap(rc) {
                Ok(mut link) => next = link.next.0.take(),
                Err(_) => break,
            }
        }
    }
}

impl ProtoScope {
    pub fn find(&self, name: &[u8]) -> Option<Rc<ProtoDef>> {
        let mut cur = self.0.as_ref();
        while let Some(link) = cur {
            if link.def.name.as_bytes() == name {
                return Some(link.def.clone());
            }
            cur = link.next.0.as_ref();
        }
        None
    }

    pub fn push(&self, def: Rc<ProtoDef>) -> ProtoScope {
        ProtoScope(Some(Rc::new(ProtoLink { def, next: self.clone() })))
    }

    /// The oldest PROTO (the first declared in the file), for an EXTERNPROTO url without
    /// a `#name`.
    pub fn first(&self) -> Option<Rc<ProtoDef>> {
        let mut cur = self.0.as_ref();
        let mut last = None;
        while let Some(link) = cur {
            last = Some(link.def.clone());
            cur = link.next.0.as_ref();
        }
        last
    }
}

/// One parsed file.
#[derive(Debug)]
pub(super) struct ParsedFile {
    pub version: Version,
    pub roots: Vec<NodeRef>,
    /// PROTOs declared at the top level (for EXTERNPROTO lookups into this file).
    pub protos: ProtoScope,
}
