//! From the element tree to the IR: units, the instance tree, parts, rigid groups, joints
//! (Onshape) and joints inferred from mates (SolidWorks, Creo).

use std::collections::{BTreeMap, HashMap};

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3, Vector6};

use super::error::Simscape2Error;
use super::mates::{self, Geom, GeomKind, MateKind, Reduction};
use crate::pipeline::front::simmechanics::dom::{Doc, NodeId};
use crate::pipeline::ir::{
    self, Body, BodyId, Frame, FrameId, FrameOwner, Ground, GroundId, Joint, Material, Model, Primitive, PrimitiveKind, SourceInfo,
    SourceLoc, Warning,
};

type Result<T> = std::result::Result<T, Simscape2Error>;
/// A joint's primitives: kind and world axis.
type Prims = Vec<(PrimitiveKind, Vector3<f64>)>;

/// How far (m, and rad-ish for rotation-matrix entries) an Onshape joint's follower frame may sit
/// from where its joint kind allows, relative to its base frame, before we warn.
const FRAME_TOL: f64 = 1e-6;
/// A transform's rotation may deviate this much (largest entry) from the nearest rotation
/// before we warn (the exporters print 9 to 17 digits).
const ORTHO_TOL: f64 = 1e-5;
/// Beyond this deviation from the nearest rotation the matrix is no rotation written with
/// rounding (even 4 significant digits stay below 1e-4): an error naming the transform.
const ROTATION_REFUSED: f64 = 1e-3;
/// The dummy axis of weld primitives (as first-generation exports write it).
const WELD_AXIS: f64 = 0.577_350_269_189_625_8;

/// Separator of instance uids in node IDs (uids may contain `/`, `+` and spaces).
const PATH_SEP: &str = "|";

struct Inst {
    name: String,
    uid: String,
    entity: String,
    grounded: bool,
    rigid: bool,
    node: NodeId,
    parent: Option<usize>,
    children: Vec<usize>,
    part: Option<usize>,
    material: Option<Material>,
    world: Isometry3<f64>,
    /// Uids from the root, joined: the node ID of the instance.
    path_id: String,
    /// Names of the enclosing assembly instances, outermost first.
    subsystem_path: Vec<String>,
}

struct Part {
    name: String,
    mass: f64,
    com: Vector3<f64>,
    inertia: Matrix3<f64>,
    geometry: Option<(String, String)>,
    material: Option<Material>,
    node: NodeId,
    geometry_warned: bool,
}

/// Who a joint end attaches to.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Owner {
    Body(BodyId),
    World,
}

/// A mate before reduction.
struct Mate {
    kind: String,
    name: String,
    node: NodeId,
    geoms: Vec<(usize, Geom, String)>,
}

/// Union-find over instance nodes plus the root assembly frame (index `insts.len()`).
struct Groups {
    parent: Vec<usize>,
}

impl Groups {
    fn find(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            // Keep the smaller index as the root: deterministic.
            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
            self.parent[hi] = lo;
        }
    }
}

pub(super) struct Lower<'a, 'd> {
    file: &'a str,
    doc: &'d Doc<'a>,
    length: f64,
    mass: f64,
    insts: Vec<Inst>,
    parts: Vec<Part>,
    part_by_uid: HashMap<String, usize>,
    assemblies: HashMap<String, NodeId>,
    root: NodeId,
    root_uid: String,
    body_of: Vec<Option<BodyId>>,
    model: Model,
    warnings: Vec<Warning>,
    joint_ids: HashMap<String, usize>,
}

/// Local name of an element (namespace prefix dropped).
fn local(name: &[u8]) -> &[u8] {
    match name.iter().rposition(|&b| b == b':') {
        Some(i) => &name[i + 1..],
        None => name,
    }
}

/// The nearest rotation (polar decomposition) and how far `m` was from it.
fn nearest_rotation(m: &Matrix3<f64>) -> Option<(Rotation3<f64>, f64)> {
    if !m.iter().all(|x| x.abs() <= 2.0) {
        return None;
    }
    let svd = m.try_svd(true, true, f64::EPSILON, 1000)?;
    let (u, v_t) = (svd.u?, svd.v_t?);
    let r = u * v_t;
    if r.determinant() <= 0.0 {
        return None;
    }
    let dev = (r - m).abs().max();
    Some((Rotation3::from_matrix_unchecked(r), dev))
}

fn unit_factor_length(u: &str) -> Option<f64> {
    Some(match u.trim().to_ascii_lowercase().as_str() {
        "meter" | "meters" | "metre" | "m" => 1.0,
        "millimeter" | "millimeters" | "millimetre" | "mm" => 1e-3,
        "centimeter" | "centimeters" | "centimetre" | "cm" => 1e-2,
        "inch" | "inches" | "in" => 0.0254,
        "foot" | "feet" | "ft" => 0.3048,
        _ => return None,
    })
}

fn unit_factor_mass(u: &str) -> Option<f64> {
    Some(match u.trim().to_ascii_lowercase().as_str() {
        "kilogram" | "kilograms" | "kg" => 1.0,
        "gram" | "grams" | "g" => 1e-3,
        "pound" | "pounds" | "lbm" | "lb" => 0.453_592_37,
        "slug" | "slugs" => 14.593_902_9,
        _ => return None,
    })
}

impl<'a, 'd> Lower<'a, 'd> {
    pub(super) fn new(file: &'a str, doc: &'d Doc<'a>) -> Self {
        Lower {
            file,
            doc,
            length: 1.0,
            mass: 1.0,
            insts: Vec::new(),
            parts: Vec::new(),
            part_by_uid: HashMap::new(),
            assemblies: HashMap::new(),
            root: 0,
            root_uid: String::new(),
            body_of: Vec::new(),
            model: Model::default(),
            warnings: Vec::new(),
            joint_ids: HashMap::new(),
        }
    }

    // ----- element access ----------------------------------------------------------------

    fn kids(&self, node: NodeId, name: &'static [u8]) -> Vec<NodeId> {
        self.doc.children(node).filter(|&c| local(self.doc.name(c)) == name).collect()
    }

    fn child(&self, node: NodeId, name: &'static [u8]) -> Option<NodeId> {
        self.doc.children(node).find(|&c| local(self.doc.name(c)) == name)
    }

    fn req(&self, node: NodeId, name: &'static str) -> Result<NodeId> {
        self.child(node, name.as_bytes()).ok_or_else(|| self.err(node, format!("missing element <{name}>")))
    }

    fn attr(&self, node: NodeId, key: &str) -> Result<Option<String>> {
        let raw = self.doc.attr(node, key.as_bytes()).map_err(|m| self.err(node, format!("malformed attributes: {m}")))?;
        let Some(raw) = raw else { return Ok(None) };
        let s = std::str::from_utf8(raw).map_err(|_| self.err(node, format!("attribute {key} is not valid UTF-8")))?;
        let s = quick_xml::escape::unescape(s).map_err(|e| self.err(node, format!("attribute {key}: {e}")))?;
        Ok(Some(s.into_owned()))
    }

    fn req_attr(&self, node: NodeId, key: &str) -> Result<String> {
        self.attr(node, key)?.ok_or_else(|| self.err(node, format!("missing attribute {key}=\"...\"")))
    }

    fn flag(&self, node: NodeId, key: &str) -> Result<bool> {
        Ok(match self.attr(node, key)? {
            None => false,
            Some(v) => match v.trim() {
                "true" | "1" => true,
                "false" | "0" | "" => false,
                other => return Err(self.err(node, format!("attribute {key}=\"{}\" is not true or false", ir::clip(other, 40)))),
            },
        })
    }

    fn text(&self, node: NodeId) -> Result<String> {
        let raw = self.doc.text(node).trim_ascii();
        let s = std::str::from_utf8(raw).map_err(|_| self.err(node, "text is not valid UTF-8".into()))?;
        let s = quick_xml::escape::unescape(s).map_err(|e| self.err(node, e.to_string()))?;
        Ok(s.into_owned())
    }

    /// Exactly `n` whitespace-separated finite numbers.
    fn numbers(&self, node: NodeId, n: usize) -> Result<Vec<f64>> {
        let text = self.text(node)?;
        let mut out = Vec::with_capacity(n);
        for piece in text.split(|c: char| c.is_whitespace() || c == ',').filter(|p| !p.is_empty()) {
            let v: f64 = piece.parse().map_err(|_| self.err(node, format!("cannot read \"{}\" as a number", ir::clip(piece, 40))))?;
            if !v.is_finite() {
                return Err(self.err(node, format!("non-finite number \"{}\"", ir::clip(piece, 40))));
            }
            out.push(v);
        }
        if out.len() != n {
            return Err(self.err(node, format!("expected {n} numbers, found {}", out.len())));
        }
        Ok(out)
    }

    fn vec3(&self, node: NodeId) -> Result<Vector3<f64>> {
        let v = self.numbers(node, 3)?;
        Ok(Vector3::new(v[0], v[1], v[2]))
    }

    /// A `<Transform>` child: rotation (9 numbers, row-major: p_parent = R p + t) and
    /// translation (data length unit).
    fn transform(&mut self, parent: NodeId) -> Result<Isometry3<f64>> {
        let t = self.req(parent, "Transform")?;
        let rn = self.req(t, "Rotation")?;
        let r = self.numbers(rn, 9)?;
        let m = Matrix3::from_row_slice(&r);
        let Some((rot, dev)) = nearest_rotation(&m) else {
            return Err(self.err(rn, "the rotation is not a rotation (mirrored or singular)".into()));
        };
        if dev > ROTATION_REFUSED {
            return Err(self.err(
                rn,
                format!(
                    "the rotation is {dev:.3e} from the nearest rotation (determinant {:.6}): far beyond rounding (refused above 1e-3)",
                    m.determinant()
                ),
            ));
        }
        if dev > ORTHO_TOL {
            self.warn(
                "transform-not-orthonormal",
                format!("rotation differs from the nearest rotation by {dev:.3e}; the nearest rotation is used"),
                rn,
            );
        }
        let p = self.vec3(self.req(t, "Translation")?)? * self.length;
        Ok(Isometry3::from_parts(Translation3::from(p), UnitQuaternion::from_rotation_matrix(&rot)))
    }

    // ----- diagnostics -------------------------------------------------------------------

    /// `Instance "Arm 01 <1>" / Transform / Rotation`: the path from the nearest element with a
    /// `name` attribute.
    fn describe(&self, node: NodeId) -> String {
        let mut segs = Vec::new();
        let mut cur = Some(node);
        while let Some(id) = cur {
            let tag = String::from_utf8_lossy(local(self.doc.name(id))).into_owned();
            let name = self.doc.attr(id, b"name").ok().flatten().map(|n| {
                let s = String::from_utf8_lossy(n);
                quick_xml::escape::unescape(&s).map(|c| c.into_owned()).unwrap_or_else(|_| s.into_owned())
            });
            match name {
                Some(n) => {
                    segs.push(format!("{tag} \"{}\"", ir::clip(&n, 120)));
                    break;
                }
                None => segs.push(tag),
            }
            cur = self.doc.parent(id);
            if segs.len() > 12 {
                segs.push("...".into());
                break;
            }
        }
        segs.reverse();
        segs.join(" / ")
    }

    fn err(&self, node: NodeId, message: String) -> Simscape2Error {
        Simscape2Error::at(self.file, self.doc.bytes, self.doc.offset(node), self.describe(node), message)
    }

    fn loc(&self, node: NodeId) -> SourceLoc {
        let (line, column) = crate::pipeline::front::simmechanics::error::line_col(self.doc.bytes, self.doc.offset(node));
        SourceLoc { file: self.file.to_owned(), line, column }
    }

    fn location(&self, node: NodeId) -> String {
        format!("{}: {}", self.loc(node), self.describe(node))
    }

    fn warn(&mut self, code: &'static str, message: String, node: NodeId) {
        let location = self.location(node);
        self.warnings.push(Warning::new(code, message, location));
    }

    // ----- reading -----------------------------------------------------------------------

    pub(super) fn run(mut self) -> Result<(Model, Vec<Warning>)> {
        let root = self.doc.root();
        let rname = String::from_utf8_lossy(local(self.doc.name(root))).into_owned();
        let mut info = SourceInfo {
            file: self.file.to_owned(),
            format_version: self.attr(root, "version")?.unwrap_or_default(),
            container: rname,
            format: "simscape2".into(),
            ..SourceInfo::default()
        };
        if let Some(c) = self.child(root, b"Created") {
            info.created_by = self.attr(c, "by")?.unwrap_or_default();
            info.created_from = self.attr(c, "from")?.unwrap_or_default();
            info.created_on = self.attr(c, "on")?.unwrap_or_default();
            info.created_using = self.attr(c, "using")?.unwrap_or_default();
        }
        self.units(root)?;
        let ra = self.req(root, "RootAssembly")?;
        self.root = ra;
        self.root_uid = self.attr(ra, "uid")?.unwrap_or_default();
        self.model.name = self.attr(ra, "name")?.unwrap_or_default();
        self.model.source = info;
        self.model.length_scale = self.length;
        if let Some(ps) = self.child(root, b"Parts") {
            for p in self.kids(ps, b"Part") {
                self.part(p)?;
            }
        }
        if let Some(asms) = self.child(root, b"Assemblies") {
            for a in self.kids(asms, b"Assembly") {
                let uid = self.req_attr(a, "uid")?;
                self.assemblies.entry(uid).or_insert(a);
            }
        }
        let tree = self.req(ra, "InstanceTree")?;
        for i in self.kids(tree, b"Instance") {
            self.instance(i, None, Isometry3::identity(), String::new(), Vec::new())?;
        }
        self.bodies()?;
        self.connect()?;
        Ok((self.model, self.warnings))
    }

    /// `DataUnits` when present (the numbers' units), else `ModelUnits` (the Creo plug-in
    /// writes only those, abbreviated).
    fn units(&mut self, root: NodeId) -> Result<()> {
        let node = match self.child(root, b"DataUnits") {
            Some(d) => d,
            None => self
                .child(root, b"ModelUnits")
                .ok_or_else(|| self.err(root, "neither <DataUnits> nor <ModelUnits>: the units of the numbers are unknown".into()))?,
        };
        let l = self.req_attr(node, "length")?;
        let m = self.req_attr(node, "mass")?;
        self.length = unit_factor_length(&l).ok_or_else(|| {
            self.err(node, format!("unknown length unit \"{}\" (expected meter, millimeter, centimeter, inch or foot)", ir::clip(&l, 40)))
        })?;
        self.mass = unit_factor_mass(&m).ok_or_else(|| {
            self.err(node, format!("unknown mass unit \"{}\" (expected kilogram, gram, pound or slug)", ir::clip(&m, 40)))
        })?;
        Ok(())
    }

    fn material(&self, node: NodeId) -> Result<Option<Material>> {
        let Some(vp) = self.child(node, b"VisualProperties") else { return Ok(None) };
        let Some(d) = self.child(vp, b"Diffuse") else { return Ok(None) };
        let comp = |k: &str| -> Result<f64> {
            let s = self.attr(d, k)?.unwrap_or_else(|| "1".into());
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| self.err(d, format!("attribute {k}=\"{}\" is not a number", ir::clip(&s, 40))))
        };
        let color = [comp("r")?, comp("g")?, comp("b")?];
        let alpha = comp("a")?;
        let specular = match self.child(vp, b"Specular") {
            Some(s) => {
                let mut sum = 0.0;
                for k in ["r", "g", "b"] {
                    sum += self.attr(s, k)?.and_then(|v| v.trim().parse::<f64>().ok()).filter(|v| v.is_finite()).unwrap_or(0.0);
                }
                sum / 3.0
            }
            None => 0.0,
        };
        Ok(Some(Material { color, transparency: (1.0 - alpha).clamp(0.0, 1.0), specular }))
    }

    fn part(&mut self, node: NodeId) -> Result<()> {
        let uid = self.req_attr(node, "uid")?;
        let name = self.attr(node, "name")?.unwrap_or_else(|| uid.clone());
        let mp = self.req(node, "MassProperties")?;
        let mass = self.numbers(self.req(mp, "Mass")?, 1)?[0] * self.mass;
        let com = self.vec3(self.req(mp, "CenterOfMass")?)? * self.length;
        // Ixx Iyy Izz Iyz Izx Ixy: the tensor's entries (products with the minus sign included),
        // about the centre of mass, in the part frame's axes (verified against STL meshes of the
        // same Onshape parts; see the module documentation).
        let i = self.numbers(self.req(mp, "Inertia")?, 6)?;
        let f = self.mass * self.length * self.length;
        let inertia = Matrix3::new(i[0], i[5], i[4], i[5], i[1], i[3], i[4], i[3], i[2]) * f;
        let geometry = match self.child(node, b"GeometryFile") {
            Some(g) => {
                let n = self.attr(g, "name")?.unwrap_or_default();
                let t = self.attr(g, "type")?.unwrap_or_default();
                (!n.trim().is_empty()).then_some((n, t))
            }
            None => None,
        };
        let material = self.material(node)?;
        if self.part_by_uid.contains_key(&uid) {
            return Err(self.err(node, format!("a second <Part> with uid \"{}\"", ir::clip(&uid, 80))));
        }
        self.part_by_uid.insert(uid, self.parts.len());
        self.parts.push(Part { name, mass, com, inertia, geometry, material, node, geometry_warned: false });
        Ok(())
    }

    fn instance(
        &mut self,
        node: NodeId,
        parent: Option<usize>,
        parent_world: Isometry3<f64>,
        parent_id: String,
        subsystem_path: Vec<String>,
    ) -> Result<()> {
        let uid = self.req_attr(node, "uid")?;
        let name = self.attr(node, "name")?.unwrap_or_else(|| uid.clone());
        let entity = self.attr(node, "entityUid")?.unwrap_or_default();
        let grounded = self.flag(node, "grounded")?;
        let rigid = self.flag(node, "rigid")?;
        let rel = self.transform(node)?;
        let world = parent_world * rel;
        let material = self.material(node)?;
        let path_id = if parent_id.is_empty() { uid.clone() } else { format!("{parent_id}{PATH_SEP}{uid}") };
        let children = self.kids(node, b"Instance");
        let part = self.part_by_uid.get(&entity).copied();
        let idx = self.insts.len();
        if let Some(p) = parent {
            if self.insts[p].children.iter().any(|&c| self.insts[c].uid == uid) {
                return Err(self.err(node, format!("a second instance with uid \"{}\" under the same parent", ir::clip(&uid, 80))));
            }
            self.insts[p].children.push(idx);
        } else if self.insts.iter().any(|i| i.parent.is_none() && i.uid == uid) {
            return Err(self.err(node, format!("a second top-level instance with uid \"{}\"", ir::clip(&uid, 80))));
        }
        if part.is_some() && !children.is_empty() {
            return Err(self.err(node, format!("instance of part \"{}\" has child instances", ir::clip(&entity, 80))));
        }
        if part.is_none() && children.is_empty() {
            if self.assemblies.contains_key(&entity) {
                self.warn("empty-sub-assembly", "sub-assembly instance without any part: ignored".into(), node);
            } else {
                return Err(
                    self.err(node, format!("entityUid \"{}\" names no <Part> and the instance has no children", ir::clip(&entity, 80)))
                );
            }
        }
        self.insts.push(Inst {
            name: name.clone(),
            uid,
            entity,
            grounded,
            rigid,
            node,
            parent,
            children: Vec::new(),
            part,
            material,
            world,
            path_id: path_id.clone(),
            subsystem_path: subsystem_path.clone(),
        });
        let mut sub = subsystem_path;
        sub.push(name);
        for c in children {
            self.instance(c, Some(idx), world, path_id.clone(), sub.clone())?;
        }
        Ok(())
    }

    /// One body per part instance: CS1 = the part frame in the world, CG at the centre of mass
    /// with the part frame's axes.
    fn bodies(&mut self) -> Result<()> {
        self.body_of = vec![None; self.insts.len()];
        for i in 0..self.insts.len() {
            let Some(p) = self.insts[i].part else { continue };
            let (world, com) = (self.insts[i].world, self.parts[p].com);
            let bid = BodyId(self.model.bodies.len() as u32);
            let node_id = self.insts[i].path_id.clone();
            let loc = self.loc(self.insts[i].node);
            let cs1 = self.push_frame(FrameOwner::Body(bid), "CS1", "", format!("{node_id}::CS1"), world, loc.clone());
            let cg_pose =
                Isometry3::from_parts(Translation3::from(world.transform_point(&nalgebra::Point3::from(com)).coords), world.rotation);
            let cg = self.push_frame(FrameOwner::Body(bid), "CG", "", format!("{node_id}::CG"), cg_pose, loc.clone());
            let geometry_file = match &self.parts[p].geometry {
                Some((name, _)) => {
                    let lower = name.to_ascii_lowercase();
                    (lower.ends_with(".stl") || lower.ends_with(".obj") || lower.ends_with(".step") || lower.ends_with(".stp"))
                        .then(|| name.clone())
                }
                None => None,
            };
            let inst = &self.insts[i];
            let part = &self.parts[p];
            self.model.bodies.push(Body {
                cad_name: inst.name.clone(),
                node_id,
                subsystem_path: inst.subsystem_path.clone(),
                mass: part.mass,
                inertia_cg: part.inertia,
                volume: None,
                surface_area: None,
                cg,
                cs1,
                frames: vec![cs1, cg],
                geometry_file,
                mesh: None,
                geometry_sources: Vec::new(),
                material: inst.material.clone().or_else(|| part.material.clone()),
                loc,
            });
            self.body_of[i] = Some(bid);
            self.geometry_warning(p);
        }
        Ok(())
    }

    /// One `geometry-unsupported` warning per part whose geometry cannot be read (neither STL,
    /// OBJ nor STEP by its name).
    fn geometry_warning(&mut self, p: usize) {
        let part = &self.parts[p];
        if part.geometry_warned {
            return;
        }
        let Some((name, ty)) = part.geometry.clone() else { return };
        let lower = name.to_ascii_lowercase();
        if [".stl", ".obj", ".step", ".stp"].iter().any(|e| lower.ends_with(e)) {
            return;
        }
        let node = part.node;
        let pname = part.name.clone();
        self.parts[p].geometry_warned = true;
        self.warn(
            "geometry-unsupported",
            format!("part \"{pname}\" names geometry \"{name}\" of type \"{ty}\", which is not read (only STL, OBJ and STEP by the name's extension are); its bodies convert without a shape"),
            node,
        );
    }

    fn push_frame(
        &mut self,
        owner: FrameOwner,
        name: &str,
        display: &str,
        node_id: String,
        pose: Isometry3<f64>,
        loc: SourceLoc,
    ) -> FrameId {
        let id = FrameId(self.model.frames.len() as u32);
        self.model.frames.push(Frame { name: name.into(), display_name: display.into(), node_id, owner, ref_id: None, pose, loc });
        id
    }

    /// A frame for a joint end: on a body (appended to its frames) or on a new ground.
    fn end_frame(&mut self, owner: Owner, pose: Isometry3<f64>, joint_node: &str, side: &str, display: &str, loc: &SourceLoc) -> FrameId {
        match owner {
            Owner::Body(b) => {
                let n = self.model.bodies[b.index()].frames.len();
                let f =
                    self.push_frame(FrameOwner::Body(b), &format!("CS{n}"), display, format!("{joint_node}::{side}"), pose, loc.clone());
                self.model.bodies[b.index()].frames.push(f);
                f
            }
            Owner::World => {
                let g = GroundId(self.model.grounds.len() as u32);
                let node_id = format!("ground:{joint_node}");
                let f = self.push_frame(FrameOwner::Ground(g), "World", display, format!("{node_id}::frame"), pose, loc.clone());
                self.model.grounds.push(Ground { name: "World".into(), node_id, frame: f, loc: loc.clone() });
                f
            }
        }
    }

    /// A unique joint node ID: `base`, then `base#2`, `base#3` ... for repeats.
    fn joint_id(&mut self, base: String) -> String {
        let n = self.joint_ids.entry(base.clone()).or_insert(0);
        *n += 1;
        if *n == 1 {
            base
        } else {
            format!("{base}#{n}")
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn add_joint(
        &mut self,
        cad_name: String,
        node_id: String,
        subsystem_path: Vec<String>,
        base: Owner,
        follower: Owner,
        pose: Isometry3<f64>,
        primitives: Prims,
        node: NodeId,
    ) {
        let loc = self.loc(node);
        let b = self.end_frame(base, pose, &node_id, "base", &format!("{cad_name} base"), &loc);
        let f = self.end_frame(follower, pose, &node_id, "follower", &format!("{cad_name} follower"), &loc);
        let primitives = primitives
            .into_iter()
            .map(|(kind, axis_world)| Primitive { kind, axis_world, losses: Default::default(), loc: loc.clone() })
            .collect();
        self.model.joints.push(Joint { cad_name, node_id, subsystem_path, base: b, follower: f, primitives, limits: None, loc });
    }

    // ----- connecting ---------------------------------------------------------------------

    /// Index of the root assembly's frame among the group nodes.
    fn root_node(&self) -> usize {
        self.insts.len()
    }

    /// World pose of a group node (an instance, or the root frame = the world).
    fn node_world(&self, n: usize) -> Isometry3<f64> {
        self.insts.get(n).map_or(Isometry3::identity(), |i| i.world)
    }

    /// Resolves an instance path inside a container (`None` = the root assembly) to a group
    /// node. An empty path (or one naming the container itself) is the container's frame.
    fn resolve(&self, container: Option<usize>, path: &[String]) -> Option<usize> {
        let mut at = container;
        let mut rest = path;
        if let Some(first) = rest.first() {
            let own = match container {
                None => first == &self.root_uid,
                Some(c) => first == &self.insts[c].entity || first == &self.insts[c].uid,
            };
            if own && self.child_by_uid(container, first).is_none() {
                rest = &rest[1..];
            }
        }
        for uid in rest {
            at = Some(self.child_by_uid(at, uid)?);
        }
        Some(at.unwrap_or(self.root_node()))
    }

    fn child_by_uid(&self, at: Option<usize>, uid: &str) -> Option<usize> {
        match at {
            Some(a) => self.insts[a].children.iter().copied().find(|&c| self.insts[c].uid == uid),
            None => (0..self.insts.len()).find(|&i| self.insts[i].parent.is_none() && self.insts[i].uid == uid),
        }
    }

    fn read_path(&self, node: NodeId) -> Result<Vec<String>> {
        self.kids(node, b"Uid").into_iter().map(|u| self.text(u)).collect()
    }

    /// Containers of joints and constraints: the root assembly, and every instance of an
    /// assembly whose definition is in `<Assemblies>` (its paths are relative to the instance).
    fn containers(&self) -> Vec<(Option<usize>, NodeId)> {
        let mut out = vec![(None, self.root)];
        for (i, inst) in self.insts.iter().enumerate() {
            if inst.part.is_none() {
                if let Some(&a) = self.assemblies.get(&inst.entity) {
                    out.push((Some(i), a));
                }
            }
        }
        out
    }

    fn connect(&mut self) -> Result<()> {
        let n = self.insts.len();
        let mut groups = Groups { parent: (0..=n).collect() };
        // Grounded instances are fixed to their parent assembly's frame (the root's = the world);
        // rigid sub-assemblies move as one.
        for i in 0..n {
            if self.insts[i].grounded {
                groups.union(i, self.insts[i].parent.unwrap_or(n));
            }
            if self.insts[i].rigid {
                let mut stack = self.insts[i].children.clone();
                while let Some(c) = stack.pop() {
                    groups.union(i, c);
                    stack.extend(self.insts[c].children.iter().copied());
                }
            }
        }
        // Joints (Onshape) and mates (SolidWorks, Creo), per container.
        let mut joints = Vec::new();
        let mut mates = Vec::new();
        for (container, node) in self.containers() {
            if let Some(js) = self.child(node, b"Joints") {
                for j in self.doc.children(js).collect::<Vec<_>>() {
                    joints.push((container, j));
                }
            }
            if let Some(cs) = self.child(node, b"Constraints") {
                for m in self.doc.children(cs).collect::<Vec<_>>() {
                    if let Some(mate) = self.mate(container, m, &mut groups)? {
                        mates.push(mate);
                    }
                }
            }
        }
        let mut members: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for i in 0..=n {
            let g = groups.find(i);
            members.entry(g).or_default().push(i);
        }
        let grounded = groups.find(n);
        // The body standing for each group: its first part instance; the world for the root's.
        let mut rep: HashMap<usize, Owner> = HashMap::new();
        for (&g, ms) in &members {
            if g == grounded {
                rep.insert(g, Owner::World);
            } else if let Some(b) = ms.iter().find_map(|&m| self.body_of.get(m).copied().flatten()) {
                rep.insert(g, Owner::Body(b));
            }
        }
        // Welds holding each group together.
        for (&g, ms) in &members {
            let Some(&anchor) = rep.get(&g) else { continue };
            for &m in ms {
                let Some(b) = self.body_of.get(m).copied().flatten() else { continue };
                if anchor == Owner::Body(b) {
                    continue;
                }
                let inst = &self.insts[m];
                let cad_name = if g == grounded { format!("{} (grounded)", inst.name) } else { format!("{} (rigid)", inst.name) };
                let (sub, pose, node, path_id) = (inst.subsystem_path.clone(), inst.world, inst.node, inst.path_id.clone());
                let node_id = self.joint_id(format!("weld:{path_id}"));
                self.add_joint(
                    cad_name,
                    node_id,
                    sub,
                    anchor,
                    Owner::Body(b),
                    pose,
                    vec![(PrimitiveKind::Weld, Vector3::repeat(WELD_AXIS))],
                    node,
                );
            }
        }
        for (container, j) in joints {
            self.onshape_joint(container, j, &mut groups, &rep)?;
        }
        self.reduce_mates(mates, &mut groups, &rep);
        if self.model.grounds.is_empty() && !self.model.bodies.is_empty() {
            let root = self.root;
            self.warn(
                "no-ground",
                "no instance is grounded and nothing is fixed to the assembly's frame: every body group floats freely from its CAD pose"
                    .into(),
                root,
            );
        }
        Ok(())
    }

    /// Where a joint end or mate geometry attaches: the part's own body, or the body (or world)
    /// standing for the group of an assembly frame.
    fn owner_of(&self, node: usize, groups: &mut Groups, rep: &HashMap<usize, Owner>) -> Option<Owner> {
        if let Some(Some(b)) = self.body_of.get(node) {
            return Some(Owner::Body(*b));
        }
        rep.get(&groups.find(node)).copied()
    }

    fn onshape_joint(&mut self, container: Option<usize>, j: NodeId, groups: &mut Groups, rep: &HashMap<usize, Owner>) -> Result<()> {
        let tag = String::from_utf8_lossy(local(self.doc.name(j))).into_owned();
        let z = |pose: &Isometry3<f64>, k: usize| pose.rotation * Vector3::ith(k, 1.0);
        let kind = match tag.as_str() {
            "Weld" | "Rigid" | "Fastened" => "weld",
            "Revolute" | "Pin" => "revolute",
            "Prismatic" | "Slider" => "prismatic",
            "Cylindrical" => "cylindrical",
            "Planar" => "planar",
            "Spherical" | "Ball" => "spherical",
            _ => {
                return Err(self.err(
                    j,
                    format!(
                        "unknown joint kind <{}> (supported: Weld, Revolute, Prismatic, Cylindrical, Planar, Spherical)",
                        ir::clip(&tag, 60)
                    ),
                ))
            }
        };
        let name = self.attr(j, "name")?.unwrap_or_else(|| tag.clone());
        let mut ends = Vec::new();
        for side in ["BaseFrame", "FollowerFrame"] {
            let f = self.req(j, side)?;
            let path = match self.child(f, b"InstancePath") {
                Some(p) => self.read_path(p)?,
                None => Vec::new(),
            };
            let Some(target) = self.resolve(container, &path) else {
                // Real exports do this (Tumbller: a weld to an instance missing from the tree).
                self.warn(
                    "joint-dangling",
                    format!(
                        "joint \"{}\": instance path {} names no instance in the tree; the joint is left out",
                        self.attr(j, "name")?.unwrap_or_default(),
                        ir::clip(&path.join(" / "), 300)
                    ),
                    f,
                );
                return Ok(());
            };
            let pose = self.node_world(target) * self.transform(f)?;
            let Some(owner) = self.owner_of(target, groups, rep) else {
                return Err(self.err(
                    f,
                    "the frame belongs to a sub-assembly that no part is fixed to (no grounded or rigid member): nothing to attach the joint to".into(),
                ));
            };
            ends.push((owner, pose));
        }
        let (base, bpose) = ends[0];
        let (follower, fpose) = ends[1];
        if base == Owner::World && follower == Owner::World {
            self.warn("joint-skipped", format!("joint \"{name}\" connects the world to itself: skipped"), j);
            return Ok(());
        }
        // The follower frame must sit where the joint kind allows relative to the base frame.
        let rel = bpose.inverse() * fpose;
        let t = rel.translation.vector;
        let rm = rel.rotation.to_rotation_matrix().into_inner();
        let z_off = (rm.column(2) - Vector3::z()).norm();
        let any_rot = (rm - Matrix3::identity()).abs().max();
        let (rot_bad, trans_bad) = match kind {
            "weld" => (any_rot, t.norm()),
            "revolute" => (z_off, t.norm()),
            "prismatic" => (any_rot, t.xy().norm()),
            "cylindrical" => (z_off, t.xy().norm()),
            "planar" => (z_off, t.z.abs()),
            _ => (0.0, t.norm()),
        };
        if rot_bad > FRAME_TOL || trans_bad > FRAME_TOL {
            self.warn(
                "joint-frames-mismatch",
                format!(
                    "{kind} joint \"{name}\": the follower frame is {trans_bad:.3e} m and {rot_bad:.3e} (rotation) away from where a {kind} joint allows relative to the base frame; the joint is placed at the base frame"
                ),
                j,
            );
        }
        let (x, y, zz) = (z(&bpose, 0), z(&bpose, 1), z(&bpose, 2));
        let prims = match kind {
            "weld" => vec![(PrimitiveKind::Weld, Vector3::repeat(WELD_AXIS))],
            "revolute" => vec![(PrimitiveKind::Revolute, zz)],
            "prismatic" => vec![(PrimitiveKind::Prismatic, zz)],
            "cylindrical" => vec![(PrimitiveKind::Prismatic, zz), (PrimitiveKind::Revolute, zz)],
            "planar" => vec![(PrimitiveKind::Prismatic, x), (PrimitiveKind::Prismatic, y), (PrimitiveKind::Revolute, zz)],
            _ => vec![(PrimitiveKind::Spherical, Vector3::repeat(WELD_AXIS))],
        };
        let prefix = container.map(|c| format!("{}{PATH_SEP}", self.insts[c].path_id)).unwrap_or_default();
        let node_id = self.joint_id(format!("joint:{prefix}{name}"));
        let sub = container.map(|c| {
            let mut s = self.insts[c].subsystem_path.clone();
            s.push(self.insts[c].name.clone());
            s
        });
        self.add_joint(name, node_id, sub.unwrap_or_default(), base, follower, bpose, prims, j);
        Ok(())
    }

    /// Reads one mate. Rigid mates merge groups here and return `None`.
    fn mate(&mut self, container: Option<usize>, m: NodeId, groups: &mut Groups) -> Result<Option<Mate>> {
        let kind = String::from_utf8_lossy(local(self.doc.name(m))).into_owned();
        let name = self.attr(m, "name")?.unwrap_or_else(|| kind.clone());
        if kind == "Rigid" || kind == "Lock" {
            let mut nodes = Vec::new();
            for p in self.kids(m, b"InstancePath") {
                let path = self.read_path(p)?;
                match self.resolve(container, &path) {
                    Some(t) => nodes.push(t),
                    None => {
                        let msg = format!(
                            "mate \"{name}\": instance path {} names no instance in the tree; the mate is left out",
                            ir::clip(&path.join(" / "), 300)
                        );
                        self.warn("mate-dangling", msg, p);
                        return Ok(None);
                    }
                }
            }
            for w in nodes.windows(2) {
                groups.union(w[0], w[1]);
            }
            return Ok(None);
        }
        let mut geoms = Vec::new();
        for g in self.kids(m, b"ConstraintGeometry") {
            let path = match self.child(g, b"InstancePath") {
                Some(p) => self.read_path(p)?,
                None => Vec::new(),
            };
            let Some(target) = self.resolve(container, &path) else {
                let msg = format!(
                    "mate \"{name}\": instance path {} names no instance in the tree; the mate is left out",
                    ir::clip(&path.join(" / "), 300)
                );
                self.warn("mate-dangling", msg, g);
                return Ok(None);
            };
            let gt = self.attr(g, "geomType")?.unwrap_or_default();
            let pose = self.node_world(target);
            let pos = pose * nalgebra::Point3::from(self.vec3(self.req(g, "Position")?)? * self.length);
            let axis = match self.child(g, b"Axis") {
                Some(a) => pose.rotation * self.vec3(a)?,
                None => Vector3::zeros(),
            };
            let gk = GeomKind::from_attr(&gt);
            let needs_axis = !matches!(gk, Some(GeomKind::Point) | None);
            let geom = match gk {
                Some(kind) if !needs_axis || axis.norm() > 1e-12 => {
                    Some(Geom { kind, point: pos.coords, axis: if axis.norm() > 1e-12 { axis.normalize() } else { axis } })
                }
                _ => None,
            };
            match geom {
                Some(geom) => geoms.push((target, geom, gt)),
                None => {
                    // Recorded with a placeholder: the pair will be reported, never guessed.
                    geoms.push((
                        target,
                        Geom { kind: GeomKind::Point, point: pos.coords, axis: Vector3::zeros() },
                        format!("unsupported:{gt}"),
                    ));
                }
            }
        }
        Ok(Some(Mate { kind, name, node: m, geoms }))
    }

    fn group_name(&self, g: usize, groups: &mut Groups) -> String {
        if groups.find(self.root_node()) == g {
            return "the ground".into();
        }
        let names: Vec<String> = (0..self.insts.len())
            .filter(|&i| self.insts[i].part.is_some() && groups.find(i) == g)
            .map(|i| format!("\"{}\"", self.insts[i].name))
            .collect();
        format!("group [{}]", ir::bounded_list(&names, 4))
    }

    /// Groups the mates by pair of rigid groups and reduces each pair to a joint.
    fn reduce_mates(&mut self, mates: Vec<Mate>, groups: &mut Groups, rep: &HashMap<usize, Owner>) {
        let root = self.root_node();
        let grounded = groups.find(root);
        // Order of groups: the ground first, then by first member.
        let key = |g: usize| if g == grounded { 0 } else { g + 1 };
        let mut pairs: BTreeMap<(usize, usize), Vec<Mate>> = BTreeMap::new();
        for mate in mates {
            if mate.geoms.len() != 2 {
                let n = mate.geoms.len();
                self.warn("mate-unsupported", format!("mate \"{}\" has {n} geometries (expected 2): ignored", mate.name), mate.node);
                continue;
            }
            let ga = groups.find(mate.geoms[0].0);
            let gb = groups.find(mate.geoms[1].0);
            if ga == gb {
                continue; // inside one rigid group: nothing left to constrain
            }
            if !rep.contains_key(&ga) || !rep.contains_key(&gb) {
                let floating = if rep.contains_key(&ga) { mate.geoms[1].0 } else { mate.geoms[0].0 };
                let sub = self.insts.get(floating).map_or_else(String::new, |i| format!(" \"{}\" ({})", i.name, i.path_id));
                self.warn(
                    "mate-unsupported",
                    format!(
                        "mate \"{}\" refers to the frame of sub-assembly instance{sub}, which no part is fixed to (it would be a massless body): the mate is left out",
                        mate.name
                    ),
                    mate.node,
                );
                continue;
            }
            let (lo, hi) = if key(ga) <= key(gb) { (ga, gb) } else { (gb, ga) };
            pairs.entry((lo, hi)).or_default().push(mate);
        }
        for ((ga, gb), ms) in pairs {
            let names: Vec<String> = ms.iter().map(|m| format!("{} \"{}\"", m.kind, m.name)).collect();
            let node = ms[0].node;
            let (na, nb) = (self.group_name(ga, groups), self.group_name(gb, groups));
            let mut rows: Vec<Vector6<f64>> = Vec::new();
            let mut points = Vec::new();
            let mut worst: (f64, String) = (0.0, String::new());
            let mut unsupported = Vec::new();
            for m in &ms {
                let Some(kind) = MateKind::from_tag(&m.kind) else {
                    unsupported.push(format!("{} \"{}\" (mate kind not supported)", m.kind, m.name));
                    continue;
                };
                if let Some((_, _, gt)) = m.geoms.iter().find(|g| g.2.starts_with("unsupported:")) {
                    unsupported.push(format!("{} \"{}\" (geometry type \"{}\")", m.kind, m.name, gt.trim_start_matches("unsupported:")));
                    continue;
                }
                match mates::mate_rows(kind, &m.geoms[0].1, &m.geoms[1].1) {
                    Ok(r) => {
                        rows.extend(r.rows);
                        points.push(m.geoms[0].1.point);
                        points.push(m.geoms[1].1.point);
                        if let Some(res) = r.residual {
                            if res > worst.0 {
                                worst = (res, format!("{} \"{}\"", m.kind, m.name));
                            }
                        }
                    }
                    Err(e) => unsupported.push(format!("{} \"{}\" ({e})", m.kind, m.name)),
                }
            }
            if !unsupported.is_empty() {
                self.warn(
                    "mate-unsupported",
                    format!(
                        "mates between {na} and {nb} include ones the joint inference does not handle: {}; no joint is made between them (all mates: {})",
                        ir::bounded_list(&unsupported, 5),
                        ir::bounded_list(&names, 8)
                    ),
                    node,
                );
                continue;
            }
            if worst.0 > mates::CONSISTENCY_TOL {
                self.warn(
                    "mate-inconsistent",
                    format!(
                        "mates between {na} and {nb} do not hold at the assembly pose ({} is off by {:.3e}); the joint is inferred from them as they are (mates: {})",
                        worst.1,
                        worst.0,
                        ir::bounded_list(&names, 8)
                    ),
                    node,
                );
            }
            let red = mates::reduce(&rows, &points);
            let (base, follower) = (rep[&ga], rep[&gb]);
            let (prims, origin, axis): (Prims, Vector3<f64>, Vector3<f64>) = match &red {
                Reduction::Free => {
                    self.warn(
                        "mate-free",
                        format!(
                            "mates between {na} and {nb} leave all six degrees of freedom: no joint (mates: {})",
                            ir::bounded_list(&names, 8)
                        ),
                        node,
                    );
                    continue;
                }
                Reduction::Unreducible { what } => {
                    self.warn(
                        "mate-unreducible",
                        format!(
                            "mates between {na} and {nb} leave {what} free, which no single joint allows; no joint is made between them (mates: {})",
                            ir::bounded_list(&names, 8)
                        ),
                        node,
                    );
                    continue;
                }
                Reduction::Weld { origin } => (vec![(PrimitiveKind::Weld, Vector3::repeat(WELD_AXIS))], *origin, Vector3::z()),
                Reduction::Revolute { origin, axis } => (vec![(PrimitiveKind::Revolute, *axis)], *origin, *axis),
                Reduction::Prismatic { origin, axes } => (axes.iter().map(|a| (PrimitiveKind::Prismatic, *a)).collect(), *origin, axes[0]),
                Reduction::Cylindrical { origin, axis } => {
                    (vec![(PrimitiveKind::Prismatic, *axis), (PrimitiveKind::Revolute, *axis)], *origin, *axis)
                }
                Reduction::Planar { origin, normal, in_plane } => (
                    vec![
                        (PrimitiveKind::Prismatic, in_plane[0]),
                        (PrimitiveKind::Prismatic, in_plane[1]),
                        (PrimitiveKind::Revolute, *normal),
                    ],
                    *origin,
                    *normal,
                ),
                Reduction::Universal { origin, axes } => {
                    (vec![(PrimitiveKind::Revolute, axes[0]), (PrimitiveKind::Revolute, axes[1])], *origin, axes[0])
                }
                Reduction::Spherical { origin } => (vec![(PrimitiveKind::Spherical, Vector3::repeat(WELD_AXIS))], *origin, Vector3::z()),
            };
            let pose = Isometry3::from_parts(Translation3::from(origin), mates::frame_along(&axis));
            let id_of = |o: Owner, m: &Model| match o {
                Owner::Body(b) => m.bodies[b.index()].node_id.clone(),
                Owner::World => "ground".into(),
            };
            let node_id = self.joint_id(format!("mates:{}~{}", id_of(base, &self.model), id_of(follower, &self.model)));
            let cad_name = format!("{} {}--{}", red.name(), owner_name(base, &self.model), owner_name(follower, &self.model));
            self.add_joint(cad_name, node_id, Vec::new(), base, follower, pose, prims, node);
        }
    }
}

fn owner_name(o: Owner, m: &Model) -> String {
    match o {
        Owner::Body(b) => m.bodies[b.index()].cad_name.clone(),
        Owner::World => "World".into(),
    }
}
