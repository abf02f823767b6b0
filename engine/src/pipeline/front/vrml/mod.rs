//! VRML front end (VRML 97 and VRML 1.0): bundle files in, a [`Scene`] out.
//!
//! [`parse`] reads the main file and everything it Inlines from the [`Bundle`] (no IO), and
//! returns the scene with warnings. [`main_files`] lists the VRML files of a bundle that no other
//! VRML file references; [`is_vrml`] sniffs a header.
//!
//! # Files
//! - **gzip** is decided by the magic bytes `1f 8b`, whatever the extension (`.wrz`, or `.wrl`
//!   holding gzip data); at most [`MAX_FILE_BYTES`] after decompression, and the gzip files
//!   of one bundle at most [`MAX_GZIP_BYTES`] together ([`Gunzip`]: each decompressed once,
//!   stopping at the budget).
//! - **Header**: `#VRML V1.0 ascii` selects VRML 1.0. `#VRML V2.0 utf8`, `# VRML V2.0 utf8`
//!   (OpenHRP), `#X3D V3.x utf8` and a missing header (headerless part files) read as VRML 97.
//!   Each file is read by its own version: a VRML 1.0 file can be inlined into a VRML 97 scene.
//!   A UTF-8 byte order mark is skipped; CRLF, LF and CR line ends are all whitespace.
//! - **Tokens**: comments `#` to end of line, commas are whitespace, strings with `\"` and `\\`
//!   escapes, numbers as `str::parse::<f64>` reads them (`1e-5`, `.5`, `-.5e+3`), integers
//!   decimal or `0x` hex. The tokenizer works on the byte slice (no token vector); coordinates
//!   and indices go straight into `f32`/`i32` arrays.
//!
//! # VRML 97
//! - Grouping nodes (each becomes a [`SceneNode`]): `Transform` (translation, rotation,
//!   scale, scaleOrientation, center: `P' = T·C·R·SR·S·SR⁻¹·C⁻¹·P`), `Group`, `Anchor`,
//!   `Collision`, `Billboard` (as Group), `Switch` (`whichChoice`; `-1` or out of range: no
//!   child), `LOD` (the first `level`, the highest detail), `Inline`, and PROTO instances whose
//!   body's first node is one of these.
//! - `Shape` with `Appearance`/`Material` (`diffuseColor`) and geometry `IndexedFaceSet`
//!   (`coord` Coordinate `point`, `coordIndex` polygons of any size separated by `-1`, a
//!   trailing `-1` optional; `ccw FALSE` flips the winding; `color` Color: its first colour
//!   when the shape has no Material), `Box`, `Sphere`, `Cylinder`, `Cone` (tessellated with
//!   24 segments around the axis, 12 latitude bands for the sphere, honouring size, radius,
//!   height and the bottom/top/side flags). Convex polygons are fanned; concave ones (up to 512
//!   corners) are ear-clipped in the plane of their Newell normal; larger or self-intersecting
//!   ones fall back to a fan. Polygons of fewer than 3 indices are skipped; an index outside
//!   the Coordinate is an error naming the node. Points no triangle uses are dropped. Normals,
//!   texture coordinates, `solid`, `creaseAngle` are not needed and skipped.
//! - `IndexedLineSet`, `PointSet`, `ElevationGrid`, `Extrusion`, `Text`: ignored, with one
//!   `vrml-ignored-geometry` warning per file.
//! - `DEF`/`USE`: a USE shares the DEF'd node; a USE'd grouping node appears again in the scene
//!   with its own path and global transform. A USE of an unknown name is a warning
//!   (`vrml-undefined-use`) and stands for nothing.
//! - `Inline` `url` (MFString or SFString): the first entry found in the bundle, relative to the
//!   file that contains the Inline (see `resolve` for the lookup: `..`, case-insensitive, by
//!   file name in sub-folders). Missing: warning `vrml-inline-missing`, the Inline node is kept
//!   empty. A cycle of Inlines is an error.
//! - `PROTO` with interface fields and defaults; an instance parses the PROTO body again with
//!   its field values bound to `IS` (any field, including MFNode `children`, at any depth of
//!   the body, and inside nested PROTO instances); the body's first node is the instance's
//!   node, named by the instance's DEF name or the PROTO's name. An empty body stands for
//!   nothing. `EXTERNPROTO`: the url (`file.wrl#Name`; without `#Name` the PROTO of the same
//!   name, else the file's first PROTO) is read from the bundle and its PROTO used; when none
//!   resolves, warning `vrml-externproto-unresolved` and instances are Groups over their
//!   `children` field.
//! - Unknown node types (vendor nodes, sensors, Script, ...) and unknown fields of known nodes
//!   are skipped generically (balanced brackets and braces); DEFs inside skipped parts are
//!   still registered. `ROUTE`, `WorldInfo`, `Viewpoint`, `NavigationInfo`, `Background`,
//!   `TimeSensor`, ... are skipped.
//!
//! # VRML 1.0
//! `Separator` (pushes and pops the state), `TransformSeparator` (the transform only), `Group`
//! and `WWWAnchor` (state leaks out), `Switch` (`whichChild`; -3 all), `LOD` (first child) —
//! each a scene node; `Transform` (translation, rotation, scaleFactor, scaleOrientation,
//! center), `MatrixTransform` (row vectors: the matrix as written is transposed), `Translation`,
//! `Rotation`, `Scale` post-multiplied into the current matrix in file order; `Coordinate3`,
//! `Material` (first `diffuseColor`), `ShapeHints` (`vertexOrdering CLOCKWISE` flips the
//! winding), `IndexedFaceSet` (`coordIndex`), `FaceSet`, `Cube`/`Sphere`/`Cylinder`/`Cone`
//! (with `parts`), `WWWInline` (`name`), DEF/USE. A node's frame: the matrix in force where it
//! starts, times — for Separator, TransformSeparator and Group — the transform nodes it begins
//! with (before its first shape, group or inline; property nodes such as Material or
//! Coordinate3 may come between), the idiom `Separator { Transform {...} geometry }` placing a
//! part. Later transforms are baked into the geometry that follows them, so shapes are in
//! their scene node's coordinates; state changes leak out of Groups as VRML 1.0 says. Unknown
//! nodes (with or without a `fields [...]` declaration) are skipped.
//!
//! # Output
//! See [`scene`]. A Shape (VRML 1.0: a shape node) at the top level of the main file, outside
//! any grouping node, becomes a root of its own named by its DEF name or type. Path segments
//! are the DEF name, or `Type[k]` for the k-th unnamed child of the parent; a name already used
//! by a sibling gets `[n]` appended (n = 1, 2, ...); `%`, `/`, `[`, `]` in names are written
//! `%25`, `%2F`, `%5B`, `%5D`. Paths depend only on the files' text, so they are stable.
//!
//! # Limits (errors, never panics)
//! Nesting deeper than [`MAX_DEPTH`] (in the text, through USE chains, PROTO bodies or
//! Inlines), more than [`MAX_PARSED_NODES`] parsed nodes (PROTO expansion included),
//! [`MAX_SCENE_NODES`] scene nodes, [`MAX_SHAPES`] shapes or [`MAX_TRIANGLES`] triangles.
//! Errors name the file, line and column ([`VrmlError`]).
//!
//! Expansions are counted before they are made, so a small file that would expand
//! exponentially (PROTOs instantiating PROTOs, DEF/USE doubling) is refused at the size of
//! its text ([`VrmlErrorKind::Expansion`], naming the USE, PROTO instance, Inline or node and
//! the projected count):
//! - every parsed node carries what it expands to in the scene (grouping nodes, shapes, an
//!   upper bound of triangles: `k - 2` per polygon of `k` corners, the primitives' fixed
//!   counts), summed from the nodes it holds, so a USE costs its DEF's expansion without
//!   expanding it. The children of a grouping node and the roots of a file are summed as they
//!   are read (the error names the child that passes the limit); any node whose own
//!   expansion passes a limit is refused, even when nothing uses it;
//! - a PROTO memoises the nodes one instance parses (its body parsed once with the instances
//!   in it counted by their own memo, not expanded; IS values are shared, not parsed, so
//!   every instance parses the same number), and an instance is refused before its body is
//!   parsed when the parsed-node count would pass the limit;
//! - an Inline's file is parsed, then its roots' expansion is checked against what the scene
//!   already holds before it is expanded.

mod ast;
mod eval;
mod geom;
mod lexer;
mod parse;
mod resolve;
pub mod scene;
mod xform;

use std::fmt;

pub use scene::{NodeId, Scene, SceneNode, ShapeGeom};

use crate::pipeline::front::bundle::Bundle;
use crate::pipeline::ir::Warning;

/// Nesting depth limit (nodes in the text, USE chains, PROTO bodies and Inlines together).
pub const MAX_DEPTH: u32 = 200;
/// Limit on nodes parsed, PROTO bodies counted once per instance.
pub const MAX_PARSED_NODES: u64 = 2_000_000;
/// Limit on grouping nodes in the scene.
pub const MAX_SCENE_NODES: usize = 2_000_000;
/// Limit on shapes in the scene.
pub const MAX_SHAPES: usize = 10_000_000;
/// Limit on triangles in the scene.
pub const MAX_TRIANGLES: usize = 100_000_000;
/// Limit on one file's size after gzip decompression.
pub const MAX_FILE_BYTES: u64 = 1 << 30;
/// Limit on what the gzip files of one bundle decompress to, all together (the main-file
/// search and parsing share it through a [`Gunzip`]; each file is decompressed once).
pub const MAX_GZIP_BYTES: u64 = 256 << 20;

/// Decompresses the gzip files of one bundle, each once (kept for the next use), within a total
/// budget: create one per bundle and pass it to [`main_files_in`] and [`parse_in`].
pub struct Gunzip {
    left: std::cell::Cell<u64>,
    limit: u64,
    done: std::cell::RefCell<std::collections::HashMap<String, std::rc::Rc<[u8]>>>,
}

impl Default for Gunzip {
    fn default() -> Self {
        Gunzip::new(MAX_GZIP_BYTES)
    }
}

impl Gunzip {
    /// A budget of `limit` decompressed bytes.
    pub fn new(limit: u64) -> Self {
        Gunzip { left: std::cell::Cell::new(limit), limit, done: Default::default() }
    }

    /// Bytes decompressed so far.
    pub fn used(&self) -> u64 {
        self.limit - self.left.get()
    }

    /// The text of bundle file `path` (`raw`): decompressed when it is gzip (by the magic
    /// bytes), stopping at the budget.
    fn text<'a>(&self, path: &str, raw: &'a [u8]) -> Result<Text<'a>, VrmlErrorKind> {
        use std::io::Read;
        if !raw.starts_with(&[0x1f, 0x8b]) {
            return Ok(Text::Plain(raw));
        }
        if let Some(t) = self.done.borrow().get(path) {
            return Ok(Text::Gzip(t.clone()));
        }
        let left = self.left.get();
        let cap = left.min(MAX_FILE_BYTES);
        let mut out = Vec::new();
        flate2::read::MultiGzDecoder::new(raw)
            .take(cap + 1)
            .read_to_end(&mut out)
            .map_err(|e| VrmlErrorKind::Gzip { message: e.to_string() })?;
        let n = out.len() as u64;
        if n > MAX_FILE_BYTES {
            return Err(VrmlErrorKind::TooLarge { limit: MAX_FILE_BYTES });
        }
        if n > left {
            self.left.set(0);
            return Err(VrmlErrorKind::GzipBudget { limit: self.limit });
        }
        self.left.set(left - n);
        let rc: std::rc::Rc<[u8]> = out.into();
        self.done.borrow_mut().insert(path.to_string(), rc.clone());
        Ok(Text::Gzip(rc))
    }
}

/// A file's text: the bundle's bytes, or a gzip file's decompressed bytes.
enum Text<'a> {
    Plain(&'a [u8]),
    Gzip(std::rc::Rc<[u8]>),
}

impl std::ops::Deref for Text<'_> {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        match self {
            Text::Plain(b) => b,
            Text::Gzip(b) => b,
        }
    }
}

/// The count limits (the defaults are the `MAX_*` constants; tests use smaller ones).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    pub parsed_nodes: u64,
    pub scene_nodes: usize,
    pub shapes: usize,
    pub triangles: usize,
}

impl Limits {
    /// The first scene limit `cost`, added to what the scene already holds (`have`), would
    /// exceed: its unit, the projected count and the limit.
    fn exceeded(&self, have: ast::Cost, cost: ast::Cost) -> Option<(&'static str, u64, u64)> {
        let total = have.add(cost);
        [
            ("grouping nodes", total.scene, self.scene_nodes as u64),
            ("shapes", total.shapes, self.shapes as u64),
            ("triangles", total.triangles, self.triangles as u64),
        ]
        .into_iter()
        .find(|&(_, n, limit)| n > limit)
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits { parsed_nodes: MAX_PARSED_NODES, scene_nodes: MAX_SCENE_NODES, shapes: MAX_SHAPES, triangles: MAX_TRIANGLES }
    }
}

/// A file that could not be read, with the position of the problem.
///
/// Displays as `parts/J1.wrl:12:5: IndexedFaceSet "_1": coordIndex 57 is out of range (20
/// points)`; `line` and `column` are 0 (and omitted) for whole-file problems.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", DisplayError(self))]
pub struct VrmlError {
    /// Bundle path of the file.
    pub file: String,
    /// 1-based line (0 when the problem concerns the whole file).
    pub line: u32,
    /// 1-based column in bytes.
    pub column: u32,
    pub kind: VrmlErrorKind,
}

struct DisplayError<'e>(&'e VrmlError);

impl fmt::Display for DisplayError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = self.0;
        crate::pipeline::ir::fmt_location(f, &e.file, e.line, e.column)?;
        write!(f, ": {}", e.kind)
    }
}

fn found_text(found: &Option<String>) -> String {
    match found {
        Some(t) => format!("\"{t}\""),
        None => "end of file".to_string(),
    }
}

/// What is wrong.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VrmlErrorKind {
    /// A token other than the grammar allows; `found` is `None` at the end of the file.
    #[error("expected {expected}, found {}", found_text(.found))]
    Expected { expected: String, found: Option<String> },
    #[error("bad number \"{text}\"")]
    BadNumber { text: String },
    #[error("string without its closing quote")]
    UnterminatedString,
    #[error("unknown field type \"{name}\"")]
    UnknownFieldType { name: String },
    /// A coordIndex entry that names no point (or a negative one other than the `-1` separator).
    #[error("{node}: coordIndex {index} is out of range ({count} points)")]
    IndexOutOfRange { node: String, index: i64, count: usize },
    #[error("Inline cycle: {}", .chain.join(" -> "))]
    InlineCycle { chain: Vec<String> },
    #[error("EXTERNPROTO cycle: {}", .chain.join(" -> "))]
    ExternProtoCycle { chain: Vec<String> },
    /// A reference the bundle cannot resolve uniquely.
    #[error("{message}")]
    Bundle { message: String },
    #[error("no such file in the bundle")]
    NotFound,
    #[error("corrupt gzip data: {message}")]
    Gzip { message: String },
    #[error("larger than {limit} bytes")]
    TooLarge { limit: u64 },
    /// The bundle's gzip files decompress to more than the budget ([`MAX_GZIP_BYTES`]) together.
    #[error("the bundle's gzip VRML files decompress to more than {limit} bytes together")]
    GzipBudget { limit: u64 },
    #[error("nested deeper than {limit} levels")]
    TooDeep { limit: u32 },
    #[error("more than {limit} triangles")]
    TooManyTriangles { limit: usize },
    #[error("more than {limit} nodes")]
    TooManyNodes { limit: u64 },
    /// A USE, PROTO instance, Inline or node whose expansion would pass a limit, refused
    /// before it is expanded; `what` names it (`USE N16`, `PROTO instance P39`, ...).
    #[error("{what} would expand to {projected} {unit} (limit {limit})")]
    Expansion { what: String, unit: &'static str, projected: u64, limit: u64 },
}

/// Reads the VRML scene whose main file is the bundle path `main`, following Inlines and
/// EXTERNPROTOs inside the bundle. Returns the scene and the warnings.
pub fn parse(bundle: &Bundle, main: &str) -> Result<(Scene, Vec<Warning>), VrmlError> {
    parse_in(bundle, main, &Gunzip::default())
}

/// [`parse`], decompressing gzip files through `gz` (shared by the bundle's main files).
pub fn parse_in(bundle: &Bundle, main: &str, gz: &Gunzip) -> Result<(Scene, Vec<Warning>), VrmlError> {
    parse_with(bundle, main, Limits::default(), gz)
}

/// [`parse_in`] holding at most `triangles` triangles in the scene (fewer than
/// [`MAX_TRIANGLES`]: what is left of the bundle's triangle budget once the other meshes are
/// counted). A USE, PROTO instance or Inline that would pass it is refused before it is
/// expanded, as for the other limits.
pub fn parse_within(bundle: &Bundle, main: &str, gz: &Gunzip, triangles: usize) -> Result<(Scene, Vec<Warning>), VrmlError> {
    parse_with(bundle, main, Limits { triangles: triangles.min(MAX_TRIANGLES), ..Limits::default() }, gz)
}

/// [`parse_in`] with other limits.
pub(crate) fn parse_with(bundle: &Bundle, main: &str, limits: Limits, gz: &Gunzip) -> Result<(Scene, Vec<Warning>), VrmlError> {
    let mut ld = parse::Loader::new(bundle, limits, gz);
    let file = ld.load(main).map_err(|e| *e)?;
    let scene = {
        let mut ev = eval::Eval::new(&mut ld, main);
        ev.run(&file).map_err(|e| *e)?;
        std::mem::take(&mut ev.scene)
    };
    let mut scene = scene;
    scene.files = std::mem::take(&mut ld.files);
    Ok((scene, std::mem::take(&mut ld.warnings)))
}

/// Whether `path` has a VRML extension (`.wrl`, `.wrz`, `.vrml`, `.wrl.gz`).
fn vrml_extension(path: &str) -> bool {
    let p = path.to_ascii_lowercase();
    [".wrl", ".wrz", ".vrml", ".wrl.gz"].iter().any(|e| p.ends_with(e))
}

/// The quoted strings of a VRML text (outside comments).
fn quoted_strings(text: &[u8]) -> Vec<String> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < text.len() {
        match text[i] {
            b'#' => {
                while i < text.len() && text[i] != b'\n' {
                    i += 1;
                }
            }
            b'"' => {
                let mut s = Vec::new();
                i += 1;
                while i < text.len() && text[i] != b'"' {
                    if text[i] == b'\\' {
                        i += 1;
                    }
                    if let Some(&c) = text.get(i) {
                        s.push(c);
                    }
                    i += 1;
                }
                i += 1;
                out.push(String::from_utf8_lossy(&s).into_owned());
            }
            _ => i += 1,
        }
    }
    out
}

/// The VRML files of the bundle (by extension: `.wrl`, `.wrz`, `.vrml`, `.wrl.gz`; gzip or not)
/// that no other VRML file of the bundle references (Inline, WWWInline, EXTERNPROTO: every
/// quoted string naming a file with a VRML extension is resolved like a url), sorted. Every
/// VRML file is read (gzip ones decompressed): a corrupt one, or gzip files together past the
/// budget, is an error naming the file.
pub fn main_files(bundle: &Bundle) -> Result<Vec<String>, VrmlError> {
    main_files_in(bundle, &Gunzip::default())
}

/// [`main_files`], decompressing through `gz` (which then holds the texts for [`parse_in`]).
pub fn main_files_in(bundle: &Bundle, gz: &Gunzip) -> Result<Vec<String>, VrmlError> {
    let vrml: Vec<&str> = bundle.paths().filter(|p| vrml_extension(p)).collect();
    let mut referenced = std::collections::HashSet::new();
    for &path in &vrml {
        let Some(raw) = bundle.get(path) else { continue };
        let text = gz.text(path, raw).map_err(|kind| VrmlError { file: path.to_string(), line: 0, column: 0, kind })?;
        for s in quoted_strings(&text) {
            let file_part = s.split('#').next().unwrap_or("");
            if !vrml_extension(file_part.trim()) {
                continue;
            }
            if let Ok(Some(target)) = resolve::resolve_url(bundle, path, file_part) {
                if target != path {
                    referenced.insert(target);
                }
            }
        }
    }
    let mut out: Vec<String> = vrml.into_iter().filter(|p| !referenced.contains(*p)).map(String::from).collect();
    out.sort();
    Ok(out)
}

/// Whether `bytes` begin with a VRML header (`#VRML V1.0`, `#VRML V2.0`, `# VRML V2.0`,
/// `#X3D V3`), after an optional BOM and whitespace; gzip data (magic `1f 8b`) is decompressed
/// far enough to see. Header-less files (legal for inlined parts) are not recognised.
pub fn is_vrml(bytes: &[u8]) -> bool {
    use std::io::Read;
    let mut head = Vec::new();
    let data: &[u8] = if bytes.starts_with(&[0x1f, 0x8b]) {
        let _ = flate2::read::MultiGzDecoder::new(bytes).take(256).read_to_end(&mut head);
        &head
    } else {
        &bytes[..bytes.len().min(256)]
    };
    let data = data.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(data);
    let ws = data.iter().take_while(|c| c.is_ascii_whitespace()).count();
    let Some(rest) = data[ws..].strip_prefix(b"#") else { return false };
    let sp = rest.iter().take_while(|&&c| c == b' ' || c == b'\t').count();
    let rest = &rest[sp..];
    let starts = |p: &[u8]| rest.len() >= p.len() && rest[..p.len()].eq_ignore_ascii_case(p);
    starts(b"VRML V1.") || starts(b"VRML V2.") || starts(b"X3D V")
}

#[cfg(test)]
mod tests;
