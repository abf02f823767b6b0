//! COLLADA (`.dae`) geometry: triangles in metres, Z up. See [`read`].
//!
//! # What is read
//! - `<asset><unit meter="...">`: metres per unit (absent: 1). `<asset><up_axis>`: `Z_UP`,
//!   `Y_UP` or `X_UP` (absent: `Y_UP`, the specification's default).
//! - The scene: `<scene><instance_visual_scene url>`, else the first `<visual_scene>`. Its node
//!   tree: each `<node>`'s `<matrix>` (16 numbers, row-major), `<translate>`, `<rotate>` (axis and
//!   angle in degrees) and `<scale>`, composed in document order onto the parent's transform;
//!   `<instance_geometry url>` places a geometry, `<instance_node url>` a node of
//!   `<library_nodes>` (at most 64 levels of such instancing). A file without any visual scene
//!   gives every `<geometry>` of `<library_geometries>` untransformed. `<lookat>` and `<skew>`
//!   are refused; controllers (skinning), cameras and lights are ignored.
//! - Each instanced `<geometry><mesh>`: its `<triangles>`, `<polylist>` (with `<vcount>`),
//!   `<polygons>` (each `<p>`, and the outer `<p>` of a `<ph>`: holes are not cut), `<trifans>`
//!   and `<tristrips>`. Inputs share the `<p>` list by their `offset`; the `VERTEX` input (through
//!   `<vertices>`' `POSITION` input, or a `POSITION` source named directly) gives the corners.
//!   Polygons are fan-triangulated; strips alternate their corner order so every triangle keeps
//!   the strip's orientation. `<lines>`, `<linestrips>` and non-mesh geometry give no triangles.
//! - A node transform that mirrors (negative determinant) reverses its triangles' corner order,
//!   so triangles stay wound the way the file's surfaces face.
//!
//! The result is `Up × unit × node transforms × source positions`, where `Up` turns the file's up
//! axis into +Z: `Y_UP` maps (x, y, z) to (x, −z, y) (a quarter turn about +X), `X_UP` maps it to
//! (−y, −z, x) (the COLLADA 1.4.1 specification's axis table: for `Y_UP` right is +X, up +Y and
//! in +Z; for `X_UP` right is −Y, up +X, in +Z; for `Z_UP` right +X, up +Z, in −Y).
//!
//! # Why the up axis is applied (evidence)
//! Tools differ on this (some URDF viewers rotate a `Y_UP` file, others read the numbers as they
//! are). The fixtures decide it: the iCub meshes (`icub_description/meshes/upmc`, `Y_UP`, no
//! unit) placed by `icub.urdf`'s `<visual><origin>` put the link's `<inertial><origin>` (its centre
//! of mass) inside the part's bounding box for `chest`, `l_upper_arm`, `l_forearm`,
//! `l_upper_leg`, `l_lower_leg` and their right-hand twins only when the `Y_UP` → Z up turn is
//! applied; read as they are, the centres of mass of those nine links lie 10 to 20 cm from
//! their parts' boxes (e.g. `l_upper_leg`: 32 mm from the box centre turned, 209 mm unturned).
//! `tests::up_axis_evidence_icub` pins this; the UR5 meshes (`Z_UP`, unit 1 m, node matrices) are
//! checked the same way by `tests::ur5_parts_contain_their_centres_of_mass`.
//!
//! # Why our own reader (not the `dae-parser` crate)
//! `dae-parser` 0.11 reads every fixture, but it validates the whole document against the
//! COLLADA 1.4.1 schema: it refuses COLLADA 1.5 files ("Unsupported COLLADA version"), files
//! without the namespace, an `<asset>` without `<created>`, and any element it does not know
//! ("unexpected element foo"), which exporters add freely; its errors carry no line; and it
//! parses nested nodes recursively, so a 60 KB file of 10,000 nested `<node>`s overflows the
//! stack (an abort, not an error). This reader uses the element tree the SimMechanics front end
//! already builds over quick-xml (nesting and size bounded, every element's offset known for line
//! numbers), reads only what it needs and ignores the rest.
//!
//! # Bounds and errors
//! At most [`super::MAX_TRIANGLES`] triangles in all (counted before any vertex is placed), at
//! most 250,000 node visits and as many geometry instances. An index outside its source, an
//! accessor reading past its array, a `<p>` whose length does not fit its inputs, a bad number or
//! an unresolvable `url` is an error naming the element's line.

use super::{MeshError, MeshErrorKind, MAX_TRIANGLES};
use crate::pipeline::front::simmechanics::dom::{Doc, NodeId};
use crate::pipeline::front::stl::number::parse_f64;
use crate::pipeline::ir;
use nalgebra::{Matrix3, Matrix4, Unit, Vector3};
use std::collections::hash_map::Entry;
use std::collections::HashMap;

/// Deepest `<instance_node>` chain (a cycle would otherwise never end).
const MAX_INSTANCE_DEPTH: u32 = 64;
/// Most node visits, and most geometry instances (instancing can multiply both).
const MAX_NODE_VISITS: usize = 250_000;

/// Reads a COLLADA file, applying its unit, up axis and node transforms (see the module docs).
pub fn read(file: &str, bytes: &[u8]) -> Result<ir::Mesh, MeshError> {
    read_with(file, bytes, true)
}

/// [`read`], with the up-axis turn optional (`apply_up_axis = false` reads the file as if it were
/// `Z_UP`; for the evidence test of the module docs).
pub(crate) fn read_with(file: &str, bytes: &[u8], apply_up_axis: bool) -> Result<ir::Mesh, MeshError> {
    let bytes = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(bytes);
    if u32::try_from(bytes.len()).is_err() {
        return Err(MeshError::new(file, 0, MeshErrorKind::Collada("file larger than 4 GB".into())));
    }
    let doc = match Doc::build(bytes) {
        Ok(d) => d,
        Err(e) => return Err(MeshError::new(file, line_at(bytes, e.offset), MeshErrorKind::Xml(e.message))),
    };
    let r = Reader::new(file, doc)?;
    r.mesh(apply_up_axis)
}

/// 1-based line of byte `offset`.
fn line_at(bytes: &[u8], offset: usize) -> u32 {
    let n = bytes[..offset.min(bytes.len())].iter().filter(|&&b| b == b'\n').count() + 1;
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// An element name without its namespace prefix.
fn local(name: &[u8]) -> &[u8] {
    match name.iter().rposition(|&b| b == b':') {
        Some(i) => &name[i + 1..],
        None => name,
    }
}

/// Whitespace-separated tokens of raw text.
fn tokens(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    text.split(|b| b.is_ascii_whitespace()).filter(|t| !t.is_empty())
}

fn show(token: &[u8]) -> String {
    ir::clip(&String::from_utf8_lossy(token), 40)
}

/// The corners of one geometry, in file units, and its triangles.
#[derive(Default)]
struct Geometry {
    points: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
}

struct Reader<'a> {
    file: &'a str,
    doc: Doc<'a>,
    ids: HashMap<&'a [u8], NodeId>,
}

impl<'a> Reader<'a> {
    fn new(file: &'a str, doc: Doc<'a>) -> Result<Self, MeshError> {
        let root = doc.root();
        let mut r = Reader { file, doc, ids: HashMap::new() };
        if local(r.doc.name(root)) != b"COLLADA" {
            let name = show(r.doc.name(root));
            return Err(r.err(root, format!("the root element is <{name}>, not <COLLADA>")));
        }
        // Every id, first one wins (walk without recursion).
        let mut ids = HashMap::new();
        let mut stack = vec![root];
        while let Some(n) = stack.pop() {
            if let Ok(Some(id)) = r.doc.attr(n, b"id") {
                ids.entry(id).or_insert(n);
            }
            stack.extend(r.doc.children(n));
        }
        r.ids = ids;
        Ok(r)
    }

    fn err(&self, at: NodeId, what: String) -> MeshError {
        let line = line_at(self.doc.bytes, self.doc.offset(at));
        MeshError::new(self.file, line, MeshErrorKind::Collada(what))
    }

    fn name(&self, n: NodeId) -> &'a [u8] {
        local(self.doc.name(n))
    }

    fn kids(&self, n: NodeId, name: &'static [u8]) -> impl Iterator<Item = NodeId> + '_ {
        self.doc.children(n).filter(move |&c| self.name(c) == name)
    }

    fn kid(&self, n: NodeId, name: &'static [u8]) -> Option<NodeId> {
        self.kids(n, name).next()
    }

    fn attr(&self, n: NodeId, key: &[u8]) -> Result<Option<&'a [u8]>, MeshError> {
        self.doc.attr(n, key).map_err(|e| self.err(n, e))
    }

    /// A non-negative integer attribute, `default` when absent.
    fn uint_attr(&self, n: NodeId, key: &str, default: u64) -> Result<u64, MeshError> {
        match self.attr(n, key.as_bytes())? {
            None => Ok(default),
            Some(v) => std::str::from_utf8(v).ok().and_then(|s| s.trim().parse::<u64>().ok()).ok_or_else(|| {
                self.err(n, format!("attribute {key}=\"{}\" of <{}> is not a non-negative integer", show(v), show(self.name(n))))
            }),
        }
    }

    /// The element a `url`/`source` attribute (`#id`) names.
    fn resolve(&self, n: NodeId, key: &str) -> Result<NodeId, MeshError> {
        let what = show(self.name(n));
        let Some(url) = self.attr(n, key.as_bytes())? else {
            return Err(self.err(n, format!("<{what}> has no {key} attribute")));
        };
        let Some(id) = url.strip_prefix(b"#") else {
            return Err(self
                .err(n, format!("{key}=\"{}\" of <{what}> is not a reference into this file (#id): other files are not read", show(url))));
        };
        self.ids
            .get(id)
            .copied()
            .ok_or_else(|| self.err(n, format!("{key}=\"{}\" of <{what}>: no element has id \"{}\"", show(url), show(id))))
    }

    fn floats(&self, n: NodeId) -> Result<Vec<f64>, MeshError> {
        let mut out = Vec::new();
        for t in tokens(self.doc.text(n)) {
            let v = match parse_f64(t, 0) {
                Some((v, end)) if end == t.len() => v,
                _ => std::str::from_utf8(t)
                    .ok()
                    .and_then(|s| s.parse::<f64>().ok())
                    .ok_or_else(|| self.err(n, format!("bad number \"{}\" in <{}>", show(t), show(self.name(n)))))?,
            };
            out.push(v);
        }
        Ok(out)
    }

    /// Exactly `count` numbers.
    fn floats_n(&self, n: NodeId, count: usize) -> Result<Vec<f64>, MeshError> {
        let v = self.floats(n)?;
        if v.len() != count {
            return Err(self.err(n, format!("<{}> needs {count} numbers, found {}", show(self.name(n)), v.len())));
        }
        Ok(v)
    }

    fn uints(&self, n: NodeId) -> Result<Vec<u32>, MeshError> {
        tokens(self.doc.text(n))
            .map(|t| {
                std::str::from_utf8(t).ok().and_then(|s| s.parse::<u32>().ok()).ok_or_else(|| {
                    self.err(n, format!("bad index \"{}\" in <{}> (not a non-negative integer)", show(t), show(self.name(n))))
                })
            })
            .collect()
    }

    /// The whole scene as one mesh.
    fn mesh(&self, apply_up_axis: bool) -> Result<ir::Mesh, MeshError> {
        let root = self.doc.root();
        let asset = self.kid(root, b"asset");
        let unit = match asset.and_then(|a| self.kid(a, b"unit")) {
            None => 1.0,
            Some(u) => match self.attr(u, b"meter")? {
                None => 1.0,
                Some(m) => std::str::from_utf8(m)
                    .ok()
                    .and_then(|s| s.trim().parse::<f64>().ok())
                    .filter(|m| m.is_finite() && *m > 0.0)
                    .ok_or_else(|| self.err(u, format!("<unit meter=\"{}\"> is not a positive number", show(m))))?,
            },
        };
        let up = match asset.and_then(|a| self.kid(a, b"up_axis")) {
            None => Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0),
            Some(u) => {
                let t = self.doc.text(u).trim_ascii();
                if t.eq_ignore_ascii_case(b"Z_UP") {
                    Matrix3::identity()
                } else if t.eq_ignore_ascii_case(b"Y_UP") {
                    Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0)
                } else if t.eq_ignore_ascii_case(b"X_UP") {
                    Matrix3::new(0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0)
                } else {
                    return Err(self.err(u, format!("<up_axis> \"{}\" is not X_UP, Y_UP or Z_UP", show(t))));
                }
            }
        };
        let up = if apply_up_axis { up } else { Matrix3::identity() };
        let mut pre = Matrix4::identity();
        pre.fixed_view_mut::<3, 3>(0, 0).copy_from(&(up * unit));

        let instances = self.instances()?;
        let mut geoms: HashMap<NodeId, Geometry> = HashMap::new();
        let mut total_triangles = 0usize;
        let mut total_points = 0usize;
        for &(g, _) in &instances {
            let geom = match geoms.entry(g) {
                Entry::Occupied(e) => e.into_mut(),
                Entry::Vacant(e) => e.insert(self.geometry(g)?),
            };
            total_triangles += geom.triangles.len();
            total_points += geom.points.len();
            if total_triangles > MAX_TRIANGLES {
                return Err(MeshError::new(self.file, 0, MeshErrorKind::TooManyTriangles { max: MAX_TRIANGLES }));
            }
            if total_points > 3 * MAX_TRIANGLES {
                return Err(self.err(g, format!("more than {} vertices in all", 3 * MAX_TRIANGLES)));
            }
        }
        let mut mesh = ir::Mesh { vertices: Vec::with_capacity(total_points), triangles: Vec::with_capacity(total_triangles) };
        for (g, m) in &instances {
            let Some(geom) = geoms.get(g) else { continue };
            let t = pre * m;
            let base = mesh.vertices.len() as u32;
            for p in &geom.points {
                let q = [0, 1, 2].map(|r| t[(r, 0)] * p[0] + t[(r, 1)] * p[1] + t[(r, 2)] * p[2] + t[(r, 3)]);
                mesh.vertices.push(q.map(|x| x as f32));
            }
            let mirrored = t.fixed_view::<3, 3>(0, 0).determinant() < 0.0;
            mesh.triangles.extend(geom.triangles.iter().map(|tr| {
                let [a, b, c] = tr.map(|i| i + base);
                if mirrored {
                    [a, c, b]
                } else {
                    [a, b, c]
                }
            }));
        }
        Ok(mesh)
    }

    /// Every geometry the scene places, with its transform (file units, file axes).
    fn instances(&self) -> Result<Vec<(NodeId, Matrix4<f64>)>, MeshError> {
        let root = self.doc.root();
        let scene = match self.kid(root, b"scene").and_then(|s| self.kid(s, b"instance_visual_scene")) {
            Some(ivs) => Some(self.resolve(ivs, "url")?),
            None => self.kid(root, b"library_visual_scenes").and_then(|l| self.kid(l, b"visual_scene")),
        };
        let mut out = Vec::new();
        let Some(scene) = scene else {
            for lib in self.kids(root, b"library_geometries") {
                out.extend(self.kids(lib, b"geometry").map(|g| (g, Matrix4::identity())));
            }
            return Ok(out);
        };
        let mut stack: Vec<(NodeId, Matrix4<f64>, u32)> = Vec::new();
        let roots: Vec<NodeId> = self.kids(scene, b"node").collect();
        stack.extend(roots.iter().rev().map(|&n| (n, Matrix4::identity(), 0)));
        let mut visits = 0usize;
        while let Some((node, parent, depth)) = stack.pop() {
            visits += 1;
            if visits > MAX_NODE_VISITS {
                return Err(self.err(node, format!("more than {MAX_NODE_VISITS} node visits (instancing too deep or too wide)")));
            }
            let m = parent * self.local_transform(node)?;
            let mut sub = Vec::new();
            for c in self.doc.children(node) {
                match self.name(c) {
                    b"instance_geometry" => {
                        let g = self.resolve(c, "url")?;
                        if self.name(g) != b"geometry" {
                            return Err(
                                self.err(c, format!("url of <instance_geometry> names a <{}>, not a <geometry>", show(self.name(g))))
                            );
                        }
                        if out.len() >= MAX_NODE_VISITS {
                            return Err(self.err(c, format!("more than {MAX_NODE_VISITS} geometry instances")));
                        }
                        out.push((g, m));
                    }
                    b"instance_node" => {
                        let n = self.resolve(c, "url")?;
                        if self.name(n) != b"node" {
                            return Err(self.err(c, format!("url of <instance_node> names a <{}>, not a <node>", show(self.name(n)))));
                        }
                        if depth + 1 > MAX_INSTANCE_DEPTH {
                            return Err(self.err(c, format!("<instance_node> nested more than {MAX_INSTANCE_DEPTH} deep (a cycle?)")));
                        }
                        sub.push((n, m, depth + 1));
                    }
                    b"node" => sub.push((c, m, depth)),
                    _ => {}
                }
            }
            stack.extend(sub.into_iter().rev());
        }
        Ok(out)
    }

    /// A node's own transform: its transform elements composed in document order.
    fn local_transform(&self, node: NodeId) -> Result<Matrix4<f64>, MeshError> {
        let mut m = Matrix4::identity();
        for c in self.doc.children(node) {
            let step = match self.name(c) {
                b"matrix" => Matrix4::from_row_slice(&self.floats_n(c, 16)?),
                b"translate" => {
                    let v = self.floats_n(c, 3)?;
                    Matrix4::new_translation(&Vector3::new(v[0], v[1], v[2]))
                }
                b"scale" => {
                    let v = self.floats_n(c, 3)?;
                    Matrix4::new_nonuniform_scaling(&Vector3::new(v[0], v[1], v[2]))
                }
                b"rotate" => {
                    let v = self.floats_n(c, 4)?;
                    let axis = Vector3::new(v[0], v[1], v[2]);
                    if v[3] == 0.0 {
                        Matrix4::identity()
                    } else {
                        let Some(axis) = Unit::try_new(axis, 1e-12) else {
                            return Err(self.err(c, "<rotate> has a zero axis".into()));
                        };
                        Matrix4::from_axis_angle(&axis, v[3].to_radians())
                    }
                }
                b"lookat" | b"skew" => {
                    return Err(self.err(c, format!("<{}> node transforms are not supported", show(self.name(c)))));
                }
                _ => continue,
            };
            m *= step;
        }
        Ok(m)
    }

    /// The source a primitive's `VERTEX` (or `POSITION`) input reads corners from.
    fn position_source(&self, input: NodeId) -> Result<NodeId, MeshError> {
        let target = self.resolve(input, "source")?;
        match self.name(target) {
            b"source" => Ok(target),
            b"vertices" => {
                for i in self.kids(target, b"input") {
                    if self.attr(i, b"semantic")? == Some(b"POSITION") {
                        return self.position_source(i);
                    }
                }
                Err(self.err(target, "<vertices> has no POSITION input".into()))
            }
            other => Err(self.err(input, format!("the VERTEX input names a <{}>, not <vertices> or <source>", show(other)))),
        }
    }

    /// A source's points (x, y, z: the first three values of each accessor element).
    fn points(&self, source: NodeId) -> Result<Vec<[f64; 3]>, MeshError> {
        let id = show(self.attr(source, b"id")?.unwrap_or_default());
        let Some(array) = self.kid(source, b"float_array") else {
            return Err(self.err(source, format!("source \"{id}\" has no <float_array>")));
        };
        let values = self.floats(array)?;
        let accessor = self.kid(source, b"technique_common").and_then(|t| self.kid(t, b"accessor"));
        let (count, stride, offset) = match accessor {
            None => (values.len() as u64 / 3, 3, 0),
            Some(a) => {
                let stride = self.uint_attr(a, "stride", 1)?;
                let count = self.uint_attr(a, "count", values.len() as u64 / stride.max(1))?;
                (count, stride, self.uint_attr(a, "offset", 0)?)
            }
        };
        if stride < 3 {
            return Err(self.err(accessor.unwrap_or(source), format!("source \"{id}\" has stride {stride}: positions need 3 values")));
        }
        let need = if count == 0 { 0 } else { offset.saturating_add((count - 1).saturating_mul(stride)).saturating_add(3) };
        if need > values.len() as u64 {
            return Err(self.err(
                accessor.unwrap_or(source),
                format!(
                    "source \"{id}\" reads past its <float_array>: {count} points of stride {stride} from offset {offset} need {need} values, the array has {}",
                    values.len()
                ),
            ));
        }
        Ok((0..count as usize)
            .map(|k| {
                let o = offset as usize + k * stride as usize;
                [values[o], values[o + 1], values[o + 2]]
            })
            .collect())
    }

    /// One `<geometry>`'s triangles (none when it is not a `<mesh>`).
    fn geometry(&self, g: NodeId) -> Result<Geometry, MeshError> {
        let mut geom = Geometry::default();
        let Some(mesh) = self.kid(g, b"mesh") else { return Ok(geom) };
        // Where each position source's points start in `geom.points`.
        let mut bases: HashMap<NodeId, (u32, u32)> = HashMap::new();
        for prim in self.doc.children(mesh) {
            let kind = self.name(prim);
            if !matches!(kind, b"triangles" | b"polylist" | b"polygons" | b"trifans" | b"tristrips") {
                continue;
            }
            let mut stride = 0u64;
            let mut vertex = None;
            for i in self.kids(prim, b"input") {
                let offset = self.uint_attr(i, "offset", 0)?;
                stride = stride.max(offset.saturating_add(1));
                let semantic = self.attr(i, b"semantic")?;
                if vertex.is_none() && matches!(semantic, Some(b"VERTEX") | Some(b"POSITION")) {
                    vertex = Some((i, offset));
                }
            }
            let Some((input, voff)) = vertex else {
                return Err(self.err(prim, format!("<{}> has no VERTEX input", show(kind))));
            };
            if stride > 1_000 {
                return Err(self.err(prim, format!("<{}> has an input offset of {}: too large", show(kind), stride - 1)));
            }
            let source = self.position_source(input)?;
            let (base, npoints) = match bases.get(&source) {
                Some(&b) => b,
                None => {
                    let pts = self.points(source)?;
                    let b = (u32::try_from(geom.points.len()).unwrap_or(u32::MAX), u32::try_from(pts.len()).unwrap_or(u32::MAX));
                    if geom.points.len() + pts.len() > 3 * MAX_TRIANGLES {
                        return Err(self.err(source, format!("more than {} vertices", 3 * MAX_TRIANGLES)));
                    }
                    geom.points.extend(pts);
                    bases.insert(source, b);
                    b
                }
            };
            let prims = Prim { r: self, kind, stride: stride as usize, voff: voff as usize, base, npoints };
            match kind {
                b"triangles" => {
                    if let Some(p) = self.kid(prim, b"p") {
                        let c = prims.corners(p)?;
                        if c.len() % 3 != 0 {
                            return Err(self.err(p, format!("<triangles> has {} corners, not a multiple of 3", c.len())));
                        }
                        for t in c.chunks_exact(3) {
                            prims.push(&mut geom.triangles, [t[0], t[1], t[2]])?;
                        }
                    }
                }
                b"polylist" => {
                    let Some(p) = self.kid(prim, b"p") else { continue };
                    let counts = match self.kid(prim, b"vcount") {
                        Some(v) => self.uints(v)?,
                        None => return Err(self.err(prim, "<polylist> has no <vcount>".into())),
                    };
                    let c = prims.corners(p)?;
                    let sum: u64 = counts.iter().map(|&n| u64::from(n)).sum();
                    if sum != c.len() as u64 {
                        return Err(self.err(
                            p,
                            format!(
                                "<vcount> adds up to {sum} corners but <p> has {} ({} indices for {stride} inputs)",
                                c.len(),
                                c.len() * stride as usize
                            ),
                        ));
                    }
                    let mut at = 0usize;
                    for &n in &counts {
                        let poly = &c[at..at + n as usize];
                        at += n as usize;
                        prims.fan(&mut geom.triangles, poly)?;
                    }
                }
                b"polygons" | b"trifans" | b"tristrips" => {
                    for child in self.doc.children(prim) {
                        let p = match self.name(child) {
                            b"p" => child,
                            b"ph" if kind == b"polygons" => match self.kid(child, b"p") {
                                Some(p) => p,
                                None => continue,
                            },
                            _ => continue,
                        };
                        let c = prims.corners(p)?;
                        if kind == b"tristrips" {
                            for k in 0..c.len().saturating_sub(2) {
                                let t = if k % 2 == 0 { [c[k], c[k + 1], c[k + 2]] } else { [c[k + 1], c[k], c[k + 2]] };
                                prims.push(&mut geom.triangles, t)?;
                            }
                        } else {
                            prims.fan(&mut geom.triangles, &c)?;
                        }
                    }
                }
                _ => {}
            }
        }
        Ok(geom)
    }
}

/// How one primitive element's `<p>` lists are read.
struct Prim<'r, 'a> {
    r: &'r Reader<'a>,
    kind: &'a [u8],
    stride: usize,
    voff: usize,
    /// Where the position source's points start in the geometry, and how many there are.
    base: u32,
    npoints: u32,
}

impl Prim<'_, '_> {
    /// The corner (geometry point) indices of one `<p>`.
    fn corners(&self, p: NodeId) -> Result<Vec<u32>, MeshError> {
        let idx = self.r.uints(p)?;
        if idx.len() % self.stride != 0 {
            return Err(self
                .r
                .err(p, format!("<p> of <{}> has {} indices, not a multiple of its {} inputs", show(self.kind), idx.len(), self.stride)));
        }
        idx.chunks_exact(self.stride)
            .map(|c| {
                let i = c[self.voff];
                if i >= self.npoints {
                    Err(self.r.err(p, format!("<p> index {i} is out of range: the position source has {} points", self.npoints)))
                } else {
                    Ok(self.base + i)
                }
            })
            .collect()
    }

    fn push(&self, out: &mut Vec<[u32; 3]>, t: [u32; 3]) -> Result<(), MeshError> {
        if out.len() >= MAX_TRIANGLES {
            return Err(MeshError::new(self.r.file, 0, MeshErrorKind::TooManyTriangles { max: MAX_TRIANGLES }));
        }
        out.push(t);
        Ok(())
    }

    /// A polygon as a fan from its first corner (fewer than 3 corners: nothing).
    fn fan(&self, out: &mut Vec<[u32; 3]>, poly: &[u32]) -> Result<(), MeshError> {
        for k in 1..poly.len().saturating_sub(1) {
            self.push(out, [poly[0], poly[k], poly[k + 1]])?;
        }
        Ok(())
    }
}
