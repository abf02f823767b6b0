//! Bytes of one file to its [`ParsedFile`]: VRML 97 and VRML 1.0 parsers over one [`Lexer`],
//! PROTO/EXTERNPROTO expansion, and the [`Loader`] that reads (and caches) bundle files.

use std::cell::Cell;
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

use nalgebra::Matrix4;

use super::ast::*;
use super::lexer::{LexError, Lexer};
use super::resolve::resolve_url;
use super::xform;
use super::{Limits, VrmlError, VrmlErrorKind, MAX_DEPTH};
use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::ir::Warning;

/// Reads bundle files, parses each once, and collects warnings.
pub(super) struct Loader<'b> {
    pub bundle: &'b Bundle,
    cache: HashMap<String, Rc<ParsedFile>>,
    /// Files read, in order.
    pub files: Vec<String>,
    /// Files being parsed (for EXTERNPROTO cycles).
    loading: Vec<String>,
    pub warnings: Vec<Warning>,
    /// Files that already got their `vrml-ignored-geometry` warning.
    ignored_warned: HashSet<Rc<str>>,
    parsed_nodes: u64,
    pub limits: Limits,
    gz: &'b super::Gunzip,
}

/// Decompresses gzip data (decided by the magic bytes), with a size cap (tests; the loader
/// goes through its [`super::Gunzip`]).
#[cfg(test)]
pub(super) fn decode(bytes: &[u8]) -> Result<std::borrow::Cow<'_, [u8]>, VrmlErrorKind> {
    use super::MAX_FILE_BYTES;
    use std::borrow::Cow;
    use std::io::Read;
    if !bytes.starts_with(&[0x1f, 0x8b]) {
        return Ok(Cow::Borrowed(bytes));
    }
    let mut out = Vec::new();
    flate2::read::MultiGzDecoder::new(bytes)
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut out)
        .map_err(|e| VrmlErrorKind::Gzip { message: e.to_string() })?;
    if out.len() as u64 > MAX_FILE_BYTES {
        return Err(VrmlErrorKind::TooLarge { limit: MAX_FILE_BYTES });
    }
    Ok(Cow::Owned(out))
}

/// The file's VRML version from its header line, and where its text starts (after a BOM).
pub(super) fn detect(bytes: &[u8]) -> (Version, usize) {
    let start = if bytes.starts_with(&[0xEF, 0xBB, 0xBF]) { 3 } else { 0 };
    let rest = &bytes[start..];
    let ws = rest.iter().take_while(|c| c.is_ascii_whitespace()).count();
    let rest = &rest[ws..];
    if let Some(after) = rest.strip_prefix(b"#") {
        let line_end = after.iter().position(|&c| c == b'\n' || c == b'\r').unwrap_or(after.len());
        let line = &after[..line_end];
        let t = line.iter().skip_while(|c| c.is_ascii_whitespace()).copied().collect::<Vec<u8>>();
        if t.len() >= 8 && t[..8].eq_ignore_ascii_case(b"VRML V1.") {
            return (Version::V1, start);
        }
    }
    (Version::V2, start)
}

impl<'b> Loader<'b> {
    pub fn new(bundle: &'b Bundle, limits: Limits, gz: &'b super::Gunzip) -> Self {
        Loader {
            bundle,
            cache: HashMap::new(),
            files: Vec::new(),
            loading: Vec::new(),
            warnings: Vec::new(),
            ignored_warned: HashSet::new(),
            parsed_nodes: 0,
            limits,
            gz,
        }
    }

    fn whole_file_error(path: &str, kind: VrmlErrorKind) -> Box<VrmlError> {
        Box::new(VrmlError { file: path.to_string(), line: 0, column: 0, kind })
    }

    /// The parsed file at bundle path `path` (parsed on first use).
    pub fn load(&mut self, path: &str) -> R<Rc<ParsedFile>> {
        if let Some(f) = self.cache.get(path) {
            return Ok(f.clone());
        }
        if let Some(i) = self.loading.iter().position(|p| p == path) {
            let mut chain = self.loading[i..].to_vec();
            chain.push(path.to_string());
            return Err(Self::whole_file_error(path, VrmlErrorKind::ExternProtoCycle { chain }));
        }
        let bundle = self.bundle;
        let raw = bundle.get(path).ok_or_else(|| Self::whole_file_error(path, VrmlErrorKind::NotFound))?;
        let data = self.gz.text(path, raw).map_err(|k| Self::whole_file_error(path, k))?;
        if u32::try_from(data.len()).is_err() {
            return Err(Self::whole_file_error(path, VrmlErrorKind::TooLarge { limit: u64::from(u32::MAX) }));
        }
        self.files.push(path.to_string());
        self.loading.push(path.to_string());
        let result = parse_text(self, path, &data);
        self.loading.pop();
        let parsed = Rc::new(result?);
        self.cache.insert(path.to_string(), parsed.clone());
        Ok(parsed)
    }

    fn warn_ignored(&mut self, file: &Rc<str>, type_name: &str, line: u32, col: u32) {
        if self.ignored_warned.insert(file.clone()) {
            self.warnings.push(Warning::new(
                "vrml-ignored-geometry",
                format!(
                    "{type_name} (and any other line, point, text, ElevationGrid or Extrusion geometry in this file) is not triangulated and is ignored"
                ),
                format!("{file}:{line}:{col}"),
            ));
        }
    }
}

/// Parses one file's text.
fn parse_text(ld: &mut Loader<'_>, path: &str, text: &[u8]) -> R<ParsedFile> {
    let (version, start) = detect(text);
    let mut p = Parser {
        ld,
        lx: Lexer::new(text, start, 1, 0),
        file: Rc::from(path),
        version,
        defs: HashMap::new(),
        protos: ProtoScope::default(),
        env: None,
        depth: 0,
        costing: false,
    };
    let roots = p.top_level()?;
    Ok(ParsedFile { version, roots, protos: p.protos.clone() })
}

/// Results inside the front end: errors boxed, so recursive frames stay small.
pub(super) type R<T> = Result<T, Box<VrmlError>>;

/// IS values of the PROTO instance whose body is being parsed.
type Env = Rc<Vec<(String, Value)>>;

/// Field values of one known node while it is parsed.
struct Vals(Vec<(&'static str, Value)>);

impl Vals {
    fn take(&mut self, key: &str) -> Option<Value> {
        let i = self.0.iter().rposition(|(k, _)| *k == key)?;
        Some(self.0.swap_remove(i).1)
    }
    fn nodes(&mut self, key: &str) -> Vec<NodeRef> {
        match self.take(key) {
            Some(Value::Nodes(n)) => n,
            _ => Vec::new(),
        }
    }
    fn node(&mut self, key: &str) -> Option<NodeRef> {
        self.nodes(key).into_iter().next()
    }
    fn floats<const N: usize>(&mut self, key: &str, default: [f64; N]) -> [f64; N] {
        match self.take(key) {
            Some(Value::Floats(v)) if v.len() >= N => {
                let mut out = default;
                out.copy_from_slice(&v[..N]);
                out
            }
            _ => default,
        }
    }
    fn float(&mut self, key: &str, default: f64) -> f64 {
        self.floats(key, [default])[0]
    }
    fn bool(&mut self, key: &str, default: bool) -> bool {
        match self.take(key) {
            Some(Value::Bools(v)) => v.first().copied().unwrap_or(default),
            _ => default,
        }
    }
    fn int(&mut self, key: &str, default: i32) -> i32 {
        match self.take(key) {
            Some(Value::Ints(v)) => v.first().copied().unwrap_or(default),
            _ => default,
        }
    }
    fn ints(&mut self, key: &str) -> Vec<i32> {
        match self.take(key) {
            Some(Value::Ints(v)) => v,
            _ => Vec::new(),
        }
    }
    fn points(&mut self, key: &str) -> Vec<[f32; 3]> {
        match self.take(key) {
            Some(Value::Vec3(v)) => v,
            Some(Value::Floats(v)) => v.chunks_exact(3).map(|c| [c[0] as f32, c[1] as f32, c[2] as f32]).collect(),
            _ => Vec::new(),
        }
    }
    fn strings(&mut self, key: &str) -> Vec<String> {
        match self.take(key) {
            Some(Value::Strings(v)) => v,
            _ => Vec::new(),
        }
    }
}

/// The node types this reader understands (both versions).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kt {
    Transform,
    Group,
    Anchor,
    Collision,
    Billboard,
    Switch,
    Lod,
    Inline,
    Shape,
    Appearance,
    Material,
    Ifs,
    Coordinate,
    Color,
    Box,
    Sphere,
    Cylinder,
    Cone,
    /// Geometry that is skipped with a warning.
    Ignored,
    V1Separator,
    V1TransformSeparator,
    V1Group,
    V1Switch,
    V1Lod,
    V1Transform,
    V1Matrix,
    V1Translation,
    V1Rotation,
    V1Scale,
    V1Coordinate3,
    V1Material,
    V1ShapeHints,
    V1Ifs,
    V1FaceSet,
    V1Cube,
    V1Sphere,
    V1Cylinder,
    V1Cone,
    V1Inline,
}

fn known_type(version: Version, name: &[u8]) -> Option<Kt> {
    use Kt::*;
    Some(match version {
        Version::V2 => match name {
            b"Transform" => Transform,
            b"Group" | b"StaticGroup" => Group,
            b"Anchor" => Anchor,
            b"Collision" => Collision,
            b"Billboard" => Billboard,
            b"Switch" => Switch,
            b"LOD" => Lod,
            b"Inline" => Inline,
            b"Shape" => Shape,
            b"Appearance" => Appearance,
            b"Material" => Material,
            b"IndexedFaceSet" => Ifs,
            b"Coordinate" => Coordinate,
            b"Color" => Color,
            b"Box" => Box,
            b"Sphere" => Sphere,
            b"Cylinder" => Cylinder,
            b"Cone" => Cone,
            b"IndexedLineSet" | b"PointSet" | b"ElevationGrid" | b"Extrusion" | b"Text" | b"LineSet" => Ignored,
            _ => return None,
        },
        Version::V1 => match name {
            b"Separator" => V1Separator,
            b"TransformSeparator" => V1TransformSeparator,
            b"Group" | b"WWWAnchor" => V1Group,
            b"Switch" => V1Switch,
            b"LOD" => V1Lod,
            b"Transform" => V1Transform,
            b"MatrixTransform" => V1Matrix,
            b"Translation" => V1Translation,
            b"Rotation" => V1Rotation,
            b"Scale" => V1Scale,
            b"Coordinate3" => V1Coordinate3,
            b"Material" => V1Material,
            b"ShapeHints" => V1ShapeHints,
            b"IndexedFaceSet" => V1Ifs,
            b"FaceSet" => V1FaceSet,
            b"Cube" => V1Cube,
            b"Sphere" => V1Sphere,
            b"Cylinder" => V1Cylinder,
            b"Cone" => V1Cone,
            b"WWWInline" => V1Inline,
            b"IndexedLineSet" | b"PointSet" | b"AsciiText" => Ignored,
            _ => return None,
        },
    })
}

/// The fields of known node types that the reader keeps (canonical name, type); others are
/// skipped.
fn field_of(kt: Kt, name: &[u8]) -> Option<(&'static str, FieldType)> {
    use FieldType::*;
    use Kt::*;
    let f = |n: &'static str, t| Some((n, t));
    match (kt, name) {
        (Transform, b"translation") => f("translation", SFVec3f),
        (Transform, b"rotation") => f("rotation", SFRotation),
        (Transform, b"scale") => f("scale", SFVec3f),
        (Transform, b"scaleOrientation") => f("scaleOrientation", SFRotation),
        (Transform, b"center") => f("center", SFVec3f),
        (Transform | Group | Anchor | Collision | Billboard, b"children") => f("children", MFNode),
        (Switch, b"choice" | b"children") => f("choice", MFNode),
        (Switch, b"whichChoice") => f("whichChoice", SFInt32),
        (Lod, b"level" | b"children") => f("level", MFNode),
        (Inline, b"url") => f("url", MFString),
        (Shape, b"appearance") => f("appearance", SFNode),
        (Shape, b"geometry") => f("geometry", SFNode),
        (Appearance, b"material") => f("material", SFNode),
        (Material, b"diffuseColor") => f("diffuseColor", SFColor),
        (Ifs, b"coord") => f("coord", SFNode),
        (Ifs, b"coordIndex") => f("coordIndex", MFInt32),
        (Ifs, b"ccw") => f("ccw", SFBool),
        (Ifs, b"color") => f("color", SFNode),
        (Coordinate | V1Coordinate3, b"point") => f("point", MFVec3f),
        (Color, b"color") => f("color", MFColor),
        (Box, b"size") => f("size", SFVec3f),
        (Sphere | Cylinder | V1Sphere | V1Cylinder, b"radius") => f("radius", SFFloat),
        (Cylinder | Cone | V1Cylinder | V1Cone | V1Cube, b"height") => f("height", SFFloat),
        (Cylinder | Cone, b"bottom") => f("bottom", SFBool),
        (Cylinder, b"top") => f("top", SFBool),
        (Cylinder | Cone, b"side") => f("side", SFBool),
        (Cone | V1Cone, b"bottomRadius") => f("bottomRadius", SFFloat),
        (V1Transform | V1Translation, b"translation") => f("translation", SFVec3f),
        (V1Transform | V1Rotation, b"rotation") => f("rotation", SFRotation),
        (V1Transform | V1Scale, b"scaleFactor") => f("scale", SFVec3f),
        (V1Transform, b"scaleOrientation") => f("scaleOrientation", SFRotation),
        (V1Transform, b"center") => f("center", SFVec3f),
        (V1Matrix, b"matrix") => f("matrix", SFMatrix),
        (V1Material, b"diffuseColor") => f("diffuseColor", MFColor),
        (V1ShapeHints, b"vertexOrdering") => f("vertexOrdering", SFEnum),
        (V1Ifs, b"coordIndex") => f("coordIndex", MFInt32),
        (V1FaceSet, b"startIndex") => f("startIndex", SFInt32),
        (V1FaceSet, b"numVertices") => f("numVertices", MFInt32),
        (V1Cube, b"width") => f("width", SFFloat),
        (V1Cube, b"depth") => f("depth", SFFloat),
        (V1Cylinder | V1Cone, b"parts") => f("parts", SFEnum),
        (V1Inline, b"name") => f("name", SFString),
        (V1Switch, b"whichChild") => f("whichChild", SFInt32),
        _ => None,
    }
}

/// Whether a VRML 1.0 bit mask names `part` (or ALL).
fn has_part(parts: &[String], part: &str) -> bool {
    parts.is_empty() || parts.iter().any(|p| p == part || p == "ALL")
}

/// A VRML 1.0 material's first diffuse colour.
const DEFAULT_DIFFUSE: [f32; 3] = [0.8, 0.8, 0.8];

struct Parser<'a, 'b, 's> {
    ld: &'a mut Loader<'b>,
    lx: Lexer<'s>,
    file: Rc<str>,
    version: Version,
    defs: HashMap<Vec<u8>, NodeRef>,
    protos: ProtoScope,
    env: Option<Env>,
    depth: u32,
    /// Measuring a PROTO body's parse cost: nested instances are not expanded (their memoised
    /// cost is counted instead), no warnings, no limit checks.
    costing: bool,
}

impl<'s> Parser<'_, '_, 's> {
    fn err_at(&self, line: u32, column: u32, kind: VrmlErrorKind) -> Box<VrmlError> {
        Box::new(VrmlError { file: self.file.to_string(), line, column, kind })
    }

    fn err(&self, kind: VrmlErrorKind) -> Box<VrmlError> {
        let (line, col) = self.lx.loc();
        self.err_at(line, col, kind)
    }

    fn lex(&self, e: LexError) -> Box<VrmlError> {
        self.err(match e {
            LexError::BadNumber(text) => VrmlErrorKind::BadNumber { text },
            LexError::UnterminatedString => VrmlErrorKind::UnterminatedString,
            LexError::Expected { expected, found } => VrmlErrorKind::Expected { expected: expected.to_string(), found },
        })
    }

    fn expected(&mut self, what: &'static str) -> Box<VrmlError> {
        let e = self.lx.expected(what);
        self.lex(e)
    }

    fn want(&mut self, c: u8, what: &'static str) -> R<()> {
        if self.lx.eat(c) {
            Ok(())
        } else {
            Err(self.expected(what))
        }
    }

    /// Position of the next token.
    fn here(&mut self) -> (u32, u32) {
        self.lx.ws();
        self.lx.loc()
    }

    fn word(&mut self, what: &'static str) -> R<&'s [u8]> {
        match self.lx.word() {
            Some(w) => Ok(w),
            None => Err(self.expected(what)),
        }
    }

    fn warn(&mut self, code: &'static str, message: String, line: u32, col: u32) {
        if self.costing {
            return;
        }
        let loc = format!("{}:{line}:{col}", self.file);
        self.ld.warnings.push(Warning::new(code, message, loc));
    }

    fn enter(&mut self) -> R<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.err(VrmlErrorKind::TooDeep { limit: MAX_DEPTH }));
        }
        Ok(())
    }

    fn count_node(&mut self) -> R<()> {
        self.ld.parsed_nodes = self.ld.parsed_nodes.saturating_add(1);
        if !self.costing && self.ld.parsed_nodes > self.ld.limits.parsed_nodes {
            return Err(self.err(VrmlErrorKind::TooManyNodes { limit: self.ld.limits.parsed_nodes }));
        }
        Ok(())
    }

    /// The statements of a whole file.
    fn top_level(&mut self) -> R<Vec<NodeRef>> {
        let mut roots = Vec::new();
        let mut total = Cost::default();
        loop {
            match self.lx.peek() {
                None => return Ok(roots),
                Some(b'}' | b']') if self.version == Version::V1 => {
                    // Some VRML 1.0 writers leave a stray closing brace at the end.
                    self.lx.pos += 1;
                }
                _ => {
                    let at = self.child_start();
                    if let Some(n) = self.statement()? {
                        self.attach(&mut total, &n, at)?;
                        roots.push(n);
                    }
                }
            }
        }
    }

    /// Where the next child node starts, and whether it is a USE (for [`Parser::attach`]).
    fn child_start(&mut self) -> (u32, u32, bool) {
        let (line, col) = self.here();
        (line, col, self.lx.peek_word() == Some(b"USE"))
    }

    /// Adds child `n` (starting at `at`) to the expanded cost `total` of its parent's list,
    /// refusing it when that passes a scene limit: a USE'd node costs its whole expansion.
    fn attach(&self, total: &mut Cost, n: &Node, at: (u32, u32, bool)) -> R<()> {
        if self.costing {
            return Ok(());
        }
        if let Some((unit, projected, limit)) = self.ld.limits.exceeded(*total, n.cost) {
            let what = match (&n.def, at.2) {
                (Some(d), true) => format!("USE {d}"),
                _ => describe_node(n),
            };
            return Err(self.err_at(at.0, at.1, VrmlErrorKind::Expansion { what, unit, projected, limit }));
        }
        *total = total.add(n.cost);
        Ok(())
    }

    /// One statement: a node, a PROTO or EXTERNPROTO declaration, a ROUTE, or (X3D classic)
    /// a header statement.
    fn statement(&mut self) -> R<Option<NodeRef>> {
        if self.version == Version::V1 {
            return self.node();
        }
        match self.lx.peek_word() {
            Some(b"PROTO") => {
                self.lx.word();
                self.proto_decl()?;
                Ok(None)
            }
            Some(b"EXTERNPROTO") => {
                self.lx.word();
                self.externproto_decl()?;
                Ok(None)
            }
            Some(b"ROUTE") => {
                self.lx.word();
                self.word("a ROUTE source")?;
                self.word("TO")?;
                self.word("a ROUTE destination")?;
                Ok(None)
            }
            Some(b"PROFILE" | b"COMPONENT") => {
                self.lx.word();
                self.word("a name")?;
                Ok(None)
            }
            Some(b"META") => {
                self.lx.word();
                self.lx.string().map_err(|e| self.lex(e))?;
                self.lx.string().map_err(|e| self.lex(e))?;
                Ok(None)
            }
            Some(b"UNIT") => {
                self.lx.word();
                self.word("a unit category")?;
                self.word("a unit name")?;
                self.lx.float().map_err(|e| self.lex(e))?;
                Ok(None)
            }
            Some(b"IMPORT" | b"EXPORT") => {
                self.lx.word();
                self.word("a name")?;
                if self.lx.peek_word() == Some(b"AS") {
                    self.lx.word();
                    self.word("a name")?;
                }
                Ok(None)
            }
            _ => self.node(),
        }
    }

    /// A node: `NULL`, `USE name`, `DEF name Type { ... }` or `Type { ... }`.
    fn node(&mut self) -> R<Option<NodeRef>> {
        self.enter()?;
        let r = self.node_inner();
        self.depth -= 1;
        r
    }

    fn node_inner(&mut self) -> R<Option<NodeRef>> {
        let (line, col) = self.here();
        let w = self.word("a node")?;
        match w {
            b"NULL" => Ok(None),
            b"USE" => {
                let name = self.word("a DEF name after USE")?;
                match self.defs.get(name) {
                    Some(n) => Ok(Some(n.clone())),
                    None => {
                        let name = String::from_utf8_lossy(name).into_owned();
                        self.warn("vrml-undefined-use", format!("USE {name}: no node was DEF'd with that name before; ignored"), line, col);
                        Ok(None)
                    }
                }
            }
            b"DEF" => {
                let name = self.word("a name after DEF")?.to_vec();
                let ty = self.word("a node type")?;
                let n = self.node_body(ty, Some(&name), line, col)?;
                self.defs.insert(name, n.clone());
                Ok(Some(n))
            }
            ty => Ok(Some(self.node_body(ty, None, line, col)?)),
        }
    }

    /// The `{ ... }` of a node of type `ty`.
    fn node_body(&mut self, ty: &[u8], def: Option<&[u8]>, line: u32, col: u32) -> R<NodeRef> {
        let type_name: Rc<str> = Rc::from(String::from_utf8_lossy(ty).as_ref());
        self.want(b'{', "\"{\" after a node type")?;
        self.count_node()?;
        let kind = if let Some(proto) = (self.version == Version::V2).then(|| self.protos.find(ty)).flatten() {
            self.instance(&proto, line, col)?
        } else {
            match known_type(self.version, ty) {
                Some(Kt::Ignored) => {
                    if !self.costing {
                        let file = self.file.clone();
                        self.ld.warn_ignored(&file, &type_name, line, col);
                    }
                    self.skip_body()?;
                    Kind::IgnoredGeometry
                }
                Some(kt @ (Kt::V1Separator | Kt::V1TransformSeparator | Kt::V1Group | Kt::V1Switch | Kt::V1Lod)) => self.v1_group(kt)?,
                Some(kt) => self.known_body(kt)?,
                None => {
                    self.skip_body()?;
                    Kind::Other
                }
            }
        };
        let height = kind.height();
        if height > MAX_DEPTH {
            return Err(self.err_at(line, col, VrmlErrorKind::TooDeep { limit: MAX_DEPTH }));
        }
        let node = Node {
            def: def.map(|d| Rc::from(String::from_utf8_lossy(d).as_ref())),
            type_name,
            file: self.file.clone(),
            line,
            col,
            height,
            cost: kind.cost(),
            kind,
        };
        if !self.costing {
            // IS values are not attached through a node list: check the node as a whole.
            if let Some((unit, projected, limit)) = self.ld.limits.exceeded(Cost::default(), node.cost) {
                let what = describe_node(&node);
                return Err(self.err_at(line, col, VrmlErrorKind::Expansion { what, unit, projected, limit }));
            }
        }
        Ok(Rc::new(node))
    }

    /// The IS value named `name` in the current PROTO body (`None` outside a body or for an
    /// event).
    fn is_value(&mut self) -> R<Option<Value>> {
        self.lx.word();
        let name = self.word("a PROTO field name after IS")?;
        Ok(self.env.as_ref().and_then(|env| env.iter().find(|(n, _)| n.as_bytes() == name).map(|(_, v)| v.clone())))
    }

    /// Fields of a known node up to its closing brace.
    fn known_body(&mut self, kt: Kt) -> R<Kind> {
        let mut vals = Vals(Vec::new());
        loop {
            match self.lx.peek() {
                Some(b'}') => {
                    self.lx.pos += 1;
                    break;
                }
                None => return Err(self.expected("a field name or \"}\"")),
                _ => {}
            }
            let name = self.word("a field name or \"}\"")?;
            match field_of(kt, name) {
                Some((key, ty)) => {
                    if self.lx.peek_word() == Some(b"IS") {
                        if let Some(v) = self.is_value()? {
                            vals.0.push((key, v));
                        }
                    } else if key == "children" {
                        // Every child of a grouping node is expanded: check them as they come.
                        let v = self.node_value(true, true)?;
                        vals.0.push((key, v));
                    } else {
                        let v = self.value(ty)?;
                        vals.0.push((key, v));
                    }
                }
                None => self.skip_value()?,
            }
        }
        Ok(build(kt, vals))
    }

    /// A VRML 1.0 group node's body: fields and child nodes, mixed.
    fn v1_group(&mut self, kt: Kt) -> R<Kind> {
        let mut children = Vec::new();
        let mut total = Cost::default();
        let mut which = -1;
        loop {
            match self.lx.peek() {
                Some(b'}') => {
                    self.lx.pos += 1;
                    break;
                }
                None => return Err(self.expected("a node, a field or \"}\"")),
                _ => {}
            }
            let w = self.lx.peek_word();
            let is_node = matches!(w, Some(b"DEF" | b"USE")) || self.lx.peek_second_byte() == Some(b'{');
            if is_node {
                let at = self.child_start();
                if let Some(n) = self.node()? {
                    // Switch and LOD expand one child: their node's cost is checked as a whole.
                    if !matches!(kt, Kt::V1Switch | Kt::V1Lod) {
                        self.attach(&mut total, &n, at)?;
                    }
                    children.push(n);
                }
                continue;
            }
            let name = self.word("a node, a field or \"}\"")?;
            match field_of(kt, name) {
                Some((_, ty)) => {
                    if let Value::Ints(v) = self.value(ty)? {
                        which = v.first().copied().unwrap_or(-1);
                    }
                }
                None => self.skip_value()?,
            }
        }
        let kind = match kt {
            Kt::V1Separator => V1GroupKind::Separator,
            Kt::V1TransformSeparator => V1GroupKind::TransformSeparator,
            Kt::V1Switch => V1GroupKind::Switch(which),
            Kt::V1Lod => V1GroupKind::Lod,
            _ => V1GroupKind::Group,
        };
        Ok(Kind::V1Group { kind, children })
    }

    fn bool(&mut self) -> R<bool> {
        match self.lx.peek_word() {
            Some(b"TRUE" | b"true" | b"1") => {
                self.lx.word();
                Ok(true)
            }
            Some(b"FALSE" | b"false" | b"0") => {
                self.lx.word();
                Ok(false)
            }
            _ => Err(self.expected("TRUE or FALSE")),
        }
    }

    fn float(&mut self) -> R<f64> {
        self.lx.float().map_err(|e| self.lex(e))
    }

    fn int(&mut self) -> R<i32> {
        self.lx.int().map_err(|e| self.lex(e))
    }

    /// Floats up to the closing bracket (the `[` consumed).
    fn float_list(&mut self, out: &mut Vec<f64>) -> R<()> {
        loop {
            if self.lx.peek() == Some(b']') {
                self.lx.pos += 1;
                return Ok(());
            }
            out.push(self.float()?);
        }
    }

    /// A value of type `ty`.
    fn value(&mut self, ty: FieldType) -> R<Value> {
        match ty {
            FieldType::SFNode | FieldType::MFNode => self.node_value(ty == FieldType::MFNode, false),
            _ => self.plain_value(ty),
        }
    }

    /// An SFNode or MFNode value; with `expanded` (a grouping node's children), the expansion
    /// of the nodes read so far is checked at each one.
    fn node_value(&mut self, multi: bool, expanded: bool) -> R<Value> {
        let mut v = Vec::new();
        let mut total = Cost::default();
        if multi && self.lx.eat(b'[') {
            loop {
                if self.lx.peek() == Some(b']') {
                    self.lx.pos += 1;
                    break;
                }
                let at = self.child_start();
                if let Some(n) = self.node()? {
                    if expanded {
                        self.attach(&mut total, &n, at)?;
                    }
                    v.push(n);
                }
            }
        } else if let Some(n) = self.node()? {
            v.push(n);
        }
        Ok(Value::Nodes(v))
    }

    /// A value of a type other than SFNode / MFNode (not recursive: kept out of the recursive
    /// frames).
    #[inline(never)]
    fn plain_value(&mut self, ty: FieldType) -> R<Value> {
        use FieldType::*;
        Ok(match ty {
            SFBool => Value::Bools(vec![self.bool()?]),
            SFInt32 => Value::Ints(vec![self.int()?]),
            SFString => Value::Strings(vec![self.lx.string().map_err(|e| self.lex(e))?]),
            SFEnum => Value::Strings(self.enum_value()?),
            SFImage => {
                let w = self.int()?;
                let h = self.int()?;
                self.int()?;
                let mut left = i64::from(w.max(0)) * i64::from(h.max(0));
                while left > 0 && self.lx.at_number() {
                    self.int()?;
                    left -= 1;
                }
                Value::Skipped
            }
            SFFloat | SFTime | SFVec2f | SFVec3f | SFVec4f | SFColor | SFRotation | SFMatrix => {
                let mut v = Vec::with_capacity(ty.arity());
                for _ in 0..ty.arity() {
                    v.push(self.float()?);
                }
                Value::Floats(v)
            }
            MFString => {
                let mut v = Vec::new();
                if self.lx.eat(b'[') {
                    while !self.lx.eat(b']') {
                        v.push(self.lx.string().map_err(|e| self.lex(e))?);
                    }
                } else {
                    v.push(self.lx.string().map_err(|e| self.lex(e))?);
                }
                Value::Strings(v)
            }
            MFInt32 => {
                let mut v = Vec::new();
                if self.lx.eat(b'[') {
                    loop {
                        if self.lx.peek() == Some(b']') {
                            self.lx.pos += 1;
                            break;
                        }
                        v.push(self.int()?);
                    }
                } else {
                    v.push(self.int()?);
                }
                Value::Ints(v)
            }
            MFBool => {
                let mut v = Vec::new();
                if self.lx.eat(b'[') {
                    while !self.lx.eat(b']') {
                        v.push(self.bool()?);
                    }
                } else {
                    v.push(self.bool()?);
                }
                Value::Bools(v)
            }
            MFVec3f | MFColor => Value::Vec3(self.vec3_list()?),
            SFNode | MFNode => Value::Skipped,
            MFFloat | MFTime | MFVec2f | MFRotation => {
                let mut v = Vec::new();
                if self.lx.eat(b'[') {
                    self.float_list(&mut v)?;
                } else {
                    for _ in 0..ty.arity() {
                        v.push(self.float()?);
                    }
                }
                Value::Floats(v)
            }
        })
    }

    /// MFVec3f: straight into `f32` triples.
    fn vec3_list(&mut self) -> R<Vec<[f32; 3]>> {
        let mut v = Vec::new();
        if !self.lx.eat(b'[') {
            let x = self.float()?;
            let y = self.float()?;
            let z = self.float()?;
            v.push([x as f32, y as f32, z as f32]);
            return Ok(v);
        }
        loop {
            if self.lx.peek() == Some(b']') {
                self.lx.pos += 1;
                return Ok(v);
            }
            let x = self.float()?;
            let y = self.float()?;
            let z = self.float()?;
            v.push([x as f32, y as f32, z as f32]);
        }
    }

    /// A VRML 1.0 SFEnum / SFBitMask: `WORD` or `( A | B )`.
    fn enum_value(&mut self) -> R<Vec<String>> {
        let mut out = Vec::new();
        if self.lx.peek() == Some(b'(') || self.lx.peek_word().is_some_and(|w| w.starts_with(b"(")) {
            // Words may be glued to the parentheses and bars: split the raw text.
            let start = self.lx.pos;
            let Some(close) = self.lx.b[start..].iter().position(|&c| c == b')') else {
                return Err(self.expected("\")\" closing a bit mask"));
            };
            let inner = &self.lx.b[start + 1..start + close];
            if inner.iter().any(|&c| c == b'\n' || c == b'{' || c == b'}') {
                return Err(self.expected("a bit mask on one line"));
            }
            for part in inner.split(|&c| c == b'|') {
                let t = String::from_utf8_lossy(part).trim().to_string();
                if !t.is_empty() {
                    out.push(t);
                }
            }
            self.lx.pos = start + close + 1;
            return Ok(out);
        }
        let w = self.word("an enum value")?;
        out.push(String::from_utf8_lossy(w).into_owned());
        Ok(out)
    }

    /// Skips a field value of unknown type (after the field name): a bracketed list, numbers,
    /// a string, a keyword, an enum (VRML 1.0), or a node (parsed, so DEFs inside register).
    fn skip_value(&mut self) -> R<()> {
        match self.lx.peek() {
            None | Some(b'}') => Ok(()),
            Some(b'[' | b'{') => {
                self.lx.pos += 1;
                self.skip_balanced()
            }
            Some(b'"') => self.lx.skip_string().map_err(|e| self.lex(e)),
            Some(b'(') => {
                self.enum_value()?;
                Ok(())
            }
            Some(b'0'..=b'9' | b'-' | b'+' | b'.') => {
                while self.lx.at_number() {
                    self.lx.skip_token();
                }
                Ok(())
            }
            Some(_) => {
                let Some(w) = self.lx.peek_word() else {
                    self.lx.skip_token();
                    return Ok(());
                };
                match w {
                    b"IS" => {
                        self.lx.word();
                        self.word("a PROTO field name after IS")?;
                    }
                    b"TRUE" | b"FALSE" | b"NULL" => {
                        self.lx.word();
                    }
                    b"USE" | b"DEF" => {
                        self.node()?;
                    }
                    _ if self.lx.peek_second_byte() == Some(b'{') => {
                        self.node()?;
                    }
                    _ if self.version == Version::V1 && w.iter().all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || *c == b'_') => {
                        self.lx.word();
                    }
                    // Not a value: the next field name.
                    _ => {}
                }
                Ok(())
            }
        }
    }

    /// Skips an unknown node's body (the `{` consumed) to its closing brace. DEF'd nodes inside
    /// are parsed and registered, so a later USE finds them.
    fn skip_body(&mut self) -> R<()> {
        self.skip_balanced()
    }

    fn skip_balanced(&mut self) -> R<()> {
        let mut depth = 1u32;
        loop {
            self.lx.ws();
            let Some(&c) = self.lx.b.get(self.lx.pos) else {
                return Err(self.expected("a closing \"}\" or \"]\""));
            };
            match c {
                b'{' | b'[' => {
                    depth += 1;
                    self.lx.pos += 1;
                }
                b'}' | b']' => {
                    self.lx.pos += 1;
                    depth -= 1;
                    if depth == 0 {
                        return Ok(());
                    }
                }
                b'"' => self.lx.skip_string().map_err(|e| self.lex(e))?,
                b'D' | b'P' => match self.lx.peek_word() {
                    Some(b"DEF") => {
                        self.node()?;
                    }
                    Some(b"PROTO") => {
                        // A PROTO inside a skipped node: its body is not this file's scope.
                        self.lx.word();
                        self.word("a PROTO name")?;
                        self.want(b'[', "\"[\" opening a PROTO interface")?;
                        self.lx.skip_balanced_raw().map_err(|e| self.lex(e))?;
                        self.want(b'{', "\"{\" opening a PROTO body")?;
                        self.lx.skip_balanced_raw().map_err(|e| self.lex(e))?;
                    }
                    _ => self.lx.skip_token(),
                },
                _ => self.lx.skip_token(),
            }
        }
    }

    /// `PROTO name [ interface ] { body }` (the keyword consumed).
    fn proto_decl(&mut self) -> R<()> {
        let name: Rc<str> = Rc::from(String::from_utf8_lossy(self.word("a PROTO name")?).as_ref());
        self.want(b'[', "\"[\" opening a PROTO interface")?;
        // Defaults have their own DEF namespace.
        let saved_defs = std::mem::take(&mut self.defs);
        let saved_env = self.env.take();
        let fields = self.interface(true);
        self.defs = saved_defs;
        self.env = saved_env;
        let fields = fields?;
        self.want(b'{', "\"{\" opening a PROTO body")?;
        let line = self.lx.line;
        let line_start = self.lx.line_start;
        let start = self.lx.pos;
        self.lx.skip_balanced_raw().map_err(|e| self.lex(e))?;
        let end = self.lx.pos - 1;
        let body = ProtoBody { text: Rc::from(&self.lx.b[line_start..end]), start: start - line_start, line, file: self.file.clone() };
        let def = ProtoDef { name, fields, body: Some(body), scope: self.protos.clone(), parse_cost: Cell::new(None) };
        self.protos = self.protos.push(Rc::new(def));
        Ok(())
    }

    /// Interface declarations up to `]` (the `[` consumed).
    fn interface(&mut self, with_defaults: bool) -> R<Vec<FieldDecl>> {
        let mut fields = Vec::new();
        loop {
            if self.lx.eat(b']') {
                return Ok(fields);
            }
            let access = self.word("a field declaration or \"]\"")?;
            let has_default = match access {
                b"field" | b"exposedField" | b"initializeOnly" | b"inputOutput" => with_defaults,
                b"eventIn" | b"eventOut" | b"inputOnly" | b"outputOnly" => false,
                _ => {
                    let (line, col) = self.lx.loc();
                    let found = Some(String::from_utf8_lossy(access).into_owned());
                    return Err(self.err_at(
                        line,
                        col.saturating_sub(access.len() as u32),
                        VrmlErrorKind::Expected { expected: "field, exposedField, eventIn or eventOut".into(), found },
                    ));
                }
            };
            let (line, col) = self.here();
            let ty_name = self.word("a field type")?;
            let Some(ty) = FieldType::from_name(ty_name) else {
                let name = String::from_utf8_lossy(ty_name).into_owned();
                return Err(self.err_at(line, col, VrmlErrorKind::UnknownFieldType { name }));
            };
            let name = String::from_utf8_lossy(self.word("a field name")?).into_owned();
            let default = if has_default { Some(self.value(ty)?) } else { None };
            fields.push(FieldDecl { name, ty, default });
        }
    }

    /// `EXTERNPROTO name [ interface ] urls` (the keyword consumed): the PROTO is looked up in
    /// the bundle now; when it cannot be found, instances become Groups over their `children`.
    fn externproto_decl(&mut self) -> R<()> {
        let (line, col) = self.here();
        let name_bytes = self.word("an EXTERNPROTO name")?.to_vec();
        let name: Rc<str> = Rc::from(String::from_utf8_lossy(&name_bytes).as_ref());
        self.want(b'[', "\"[\" opening an EXTERNPROTO interface")?;
        let fields = self.interface(false)?;
        let urls = match self.value(FieldType::MFString)? {
            Value::Strings(v) => v,
            _ => Vec::new(),
        };
        let mut found = None;
        for url in &urls {
            let (file_part, frag) = url.split_once('#').unwrap_or((url.as_str(), ""));
            let wanted = if frag.is_empty() { name_bytes.as_slice() } else { frag.as_bytes() };
            if file_part.trim().is_empty() {
                found = self.protos.find(wanted);
            } else {
                let target = resolve_url(self.ld.bundle, &self.file, file_part)
                    .map_err(|e| self.err_at(line, col, VrmlErrorKind::Bundle { message: e.to_string() }))?;
                let Some(path) = target else { continue };
                if *path == *self.file {
                    found = self.protos.find(wanted);
                } else {
                    let parsed = self.ld.load(&path)?;
                    found = parsed.protos.find(wanted).or_else(|| if frag.is_empty() { parsed.protos.first() } else { None });
                }
            }
            if found.is_some() {
                break;
            }
        }
        let def = match found {
            Some(ext) => ProtoDef {
                name,
                fields: ext.fields.clone(),
                body: ext.body.clone(),
                scope: ext.scope.clone(),
                parse_cost: Cell::new(ext.parse_cost.get()),
            },
            None => {
                self.warn(
                    "vrml-externproto-unresolved",
                    format!(
                        "EXTERNPROTO {name}: none of its urls ({}) names a PROTO in the bundle; its instances are read as Groups of their children",
                        urls.iter().map(|u| format!("\"{u}\"")).collect::<Vec<_>>().join(", ")
                    ),
                    line,
                    col,
                );
                ProtoDef { name, fields, body: None, scope: ProtoScope::default(), parse_cost: Cell::new(None) }
            }
        };
        self.protos = self.protos.push(Rc::new(def));
        Ok(())
    }

    /// The nodes one instance of `def` parses (memoised): its body's first node parsed once
    /// without expanding the instances in it, whose own costs are added instead.
    fn proto_cost(&mut self, def: &Rc<ProtoDef>) -> R<u64> {
        if let Some(c) = def.parse_cost.get() {
            return Ok(c);
        }
        let Some(body) = &def.body else {
            def.parse_cost.set(Some(0));
            return Ok(0);
        };
        let before = self.ld.parsed_nodes;
        let r = self.body_first_node(def, body, None, true);
        let cost = self.ld.parsed_nodes.saturating_sub(before);
        self.ld.parsed_nodes = before;
        r?;
        def.parse_cost.set(Some(cost));
        Ok(cost)
    }

    /// A PROTO instance's fields (the `{` consumed), then its body parsed with them. The
    /// instance (at `line`:`col`) is refused before its body is parsed when the nodes it would
    /// parse pass the limit.
    fn instance(&mut self, def: &Rc<ProtoDef>, line: u32, col: u32) -> R<Kind> {
        let mut given: Vec<(usize, Value)> = Vec::new();
        loop {
            match self.lx.peek() {
                Some(b'}') => {
                    self.lx.pos += 1;
                    break;
                }
                None => return Err(self.expected("a field name or \"}\"")),
                _ => {}
            }
            let name = self.word("a field name or \"}\"")?;
            match def.fields.iter().position(|f| f.name.as_bytes() == name) {
                Some(i) => {
                    if self.lx.peek_word() == Some(b"IS") {
                        if let Some(v) = self.is_value()? {
                            given.push((i, v));
                        }
                    } else {
                        let v = self.value(def.fields[i].ty)?;
                        given.push((i, v));
                    }
                }
                None => self.skip_value()?,
            }
        }
        let mut env: Vec<(String, Value)> = Vec::with_capacity(def.fields.len());
        for (i, f) in def.fields.iter().enumerate() {
            let v = given.iter().rev().find(|(k, _)| *k == i).map(|(_, v)| v.clone()).or_else(|| f.default.clone());
            if let Some(v) = v {
                env.push((f.name.clone(), v));
            }
        }
        let cost = self.proto_cost(def)?;
        if self.costing {
            self.ld.parsed_nodes = self.ld.parsed_nodes.saturating_add(cost);
            return Ok(Kind::Instance(None));
        }
        let projected = self.ld.parsed_nodes.saturating_add(cost);
        if projected > self.ld.limits.parsed_nodes {
            let what = format!("PROTO instance {}", def.name);
            let (unit, limit) = ("parsed nodes", self.ld.limits.parsed_nodes);
            return Err(self.err_at(line, col, VrmlErrorKind::Expansion { what, unit, projected, limit }));
        }
        let Some(body) = &def.body else {
            let children = env
                .into_iter()
                .find(|(n, _)| n == "children")
                .and_then(|(_, v)| if let Value::Nodes(n) = v { Some(n) } else { None })
                .unwrap_or_default();
            return Ok(Kind::Group { children, matrix: None });
        };
        let first = self.body_first_node(def, body, Some(Rc::new(env)), false)?;
        Ok(Kind::Instance(first))
    }

    /// The first node of a PROTO body, read by a parser of its own in the PROTO's scope: with the
    /// instance's fields as `env`, or (`costing`) only to count what one instance parses.
    fn body_first_node(&mut self, def: &Rc<ProtoDef>, body: &ProtoBody, env: Option<Env>, costing: bool) -> R<Option<NodeRef>> {
        let text = body.text.clone();
        let mut sub = Parser {
            ld: &mut *self.ld,
            lx: Lexer::new(&text, body.start, body.line, 0),
            file: body.file.clone(),
            version: Version::V2,
            defs: HashMap::new(),
            protos: def.scope.clone(),
            env,
            depth: self.depth,
            costing,
        };
        sub.first_node()
    }

    /// The first node of a PROTO body (declarations before it are processed; the rest of the
    /// body is not read).
    fn first_node(&mut self) -> R<Option<NodeRef>> {
        loop {
            if self.lx.peek().is_none() {
                return Ok(None);
            }
            let before = self.lx.pos;
            if let Some(n) = self.statement()? {
                return Ok(Some(n));
            }
            if self.lx.pos == before {
                return Ok(None);
            }
        }
    }
}

/// How a node is named in messages: its type and DEF name.
fn describe_node(n: &Node) -> String {
    match &n.def {
        Some(d) => format!("{} \"{d}\"", n.type_name),
        None => n.type_name.to_string(),
    }
}

/// Builds a known node from its field values.
fn build(kt: Kt, mut v: Vals) -> Kind {
    match kt {
        Kt::Transform => {
            let m = xform::vrml_transform(
                v.floats("translation", [0.0; 3]),
                v.floats("rotation", [0.0, 0.0, 1.0, 0.0]),
                v.floats("scale", [1.0; 3]),
                v.floats("scaleOrientation", [0.0, 0.0, 1.0, 0.0]),
                v.floats("center", [0.0; 3]),
            );
            Kind::Group { children: v.nodes("children"), matrix: Some(Box::new(m)) }
        }
        Kt::Group | Kt::Anchor | Kt::Collision | Kt::Billboard => Kind::Group { children: v.nodes("children"), matrix: None },
        Kt::Switch => Kind::Switch { which: v.int("whichChoice", -1), choice: v.nodes("choice") },
        Kt::Lod => Kind::Lod { level: v.nodes("level") },
        Kt::Inline => Kind::Inline { urls: v.strings("url") },
        Kt::Shape => Kind::Shape { appearance: v.node("appearance"), geometry: v.node("geometry") },
        Kt::Appearance => Kind::Appearance { material: v.node("material") },
        Kt::Material => {
            let c = v.floats("diffuseColor", [0.8, 0.8, 0.8]);
            Kind::Material { diffuse: [c[0] as f32, c[1] as f32, c[2] as f32] }
        }
        Kt::V1Material => {
            let c = v.points("diffuseColor");
            Kind::Material { diffuse: c.first().copied().unwrap_or(DEFAULT_DIFFUSE) }
        }
        Kt::Ifs => Kind::Ifs(Box::new(Ifs {
            coord: v.node("coord"),
            coord_index: v.ints("coordIndex"),
            ccw: v.bool("ccw", true),
            color: v.node("color"),
        })),
        Kt::Coordinate | Kt::V1Coordinate3 => Kind::Coordinate { points: v.points("point") },
        Kt::Color => Kind::Color { colors: v.points("color") },
        Kt::Box => Kind::Prim(Prim::Box { size: v.floats("size", [2.0; 3]) }),
        Kt::Sphere | Kt::V1Sphere => Kind::Prim(Prim::Sphere { radius: v.float("radius", 1.0) }),
        Kt::Cylinder => Kind::Prim(Prim::Cylinder {
            radius: v.float("radius", 1.0),
            height: v.float("height", 2.0),
            bottom: v.bool("bottom", true),
            top: v.bool("top", true),
            side: v.bool("side", true),
        }),
        Kt::Cone => Kind::Prim(Prim::Cone {
            bottom_radius: v.float("bottomRadius", 1.0),
            height: v.float("height", 2.0),
            side: v.bool("side", true),
            bottom: v.bool("bottom", true),
        }),
        Kt::V1Cube => Kind::Prim(Prim::Box { size: [v.float("width", 2.0), v.float("height", 2.0), v.float("depth", 2.0)] }),
        Kt::V1Cylinder => {
            let parts = v.strings("parts");
            Kind::Prim(Prim::Cylinder {
                radius: v.float("radius", 1.0),
                height: v.float("height", 2.0),
                bottom: has_part(&parts, "BOTTOM"),
                top: has_part(&parts, "TOP"),
                side: has_part(&parts, "SIDES"),
            })
        }
        Kt::V1Cone => {
            let parts = v.strings("parts");
            Kind::Prim(Prim::Cone {
                bottom_radius: v.float("bottomRadius", 1.0),
                height: v.float("height", 2.0),
                side: has_part(&parts, "SIDES"),
                bottom: has_part(&parts, "BOTTOM"),
            })
        }
        Kt::V1Transform => Kind::V1Xform(Box::new(xform::vrml_transform(
            v.floats("translation", [0.0; 3]),
            v.floats("rotation", [0.0, 0.0, 1.0, 0.0]),
            v.floats("scale", [1.0; 3]),
            v.floats("scaleOrientation", [0.0, 0.0, 1.0, 0.0]),
            v.floats("center", [0.0; 3]),
        ))),
        Kt::V1Translation => Kind::V1Xform(Box::new(xform::translation(v.floats("translation", [0.0; 3])))),
        Kt::V1Rotation => Kind::V1Xform(Box::new(xform::rotation(v.floats("rotation", [0.0, 0.0, 1.0, 0.0])))),
        Kt::V1Scale => Kind::V1Xform(Box::new(xform::scale(v.floats("scale", [1.0; 3])))),
        Kt::V1Matrix => {
            let m = v.floats("matrix", [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
            // Row vectors, translation in the last row: the column-vector matrix is the transpose.
            Kind::V1Xform(Box::new(Matrix4::from_row_slice(&m).transpose()))
        }
        Kt::V1ShapeHints => {
            let ordering = v.strings("vertexOrdering");
            let clockwise = ordering.first().map(|o| o == "CLOCKWISE");
            Kind::V1ShapeHints { clockwise }
        }
        Kt::V1Ifs => Kind::V1Ifs { coord_index: v.ints("coordIndex") },
        Kt::V1FaceSet => Kind::V1FaceSet { start: v.int("startIndex", 0), num_vertices: v.ints("numVertices") },
        Kt::V1Inline => Kind::V1Inline { name: v.strings("name").into_iter().next().unwrap_or_default() },
        // Grouping nodes of VRML 1.0 and ignored geometry are built elsewhere.
        _ => Kind::Other,
    }
}
