//! The conversion pipeline: front ends -> IR -> passes -> validation -> back ends.
//!
//! ```text
//! Bundle ──front::simmechanics──▶ ir::Model ──passes::geometry (front::stl)──▶ meshes
//!        ──[passes::lump]──▶ passes::loops (hierarchy + kinematics + cuts) ──valid──▶ Validated
//!        ──back::modelica + back::dxf + back::stl──▶ files ──report──▶ report.json
//! ```
//!
//! Architecture invariant: nothing under `pipeline` performs IO or depends on an async runtime,
//! a web framework or a database. Bytes and options come in, files and diagnostics go out.
//! (`tests/tidy.rs` enforces this.)

pub mod back;
pub mod front;
pub mod ir;
pub mod observe;
pub mod passes;
pub mod report;
#[cfg(test)]
pub(crate) mod testutil;
pub mod valid;

use serde::Serialize;

use front::bundle::{Bundle, BundleError};
use front::simmechanics::XmlError;
use ir::{Model, Warning};
use observe::{Observer, Quiet, Stage};
use passes::geometry::GeometryError;
use valid::{Analysis, Validated, ValidationError};

/// The converter's version, written into every package and report.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// Longest diagnostic message (bytes); longer ones are clipped with a note of what was cut.
pub const MAX_MESSAGE_BYTES: usize = 4096;

/// Conversion options.
#[derive(Clone, Debug)]
pub struct Options {
    /// Modelica package name; `None` derives it from the assembly's name.
    pub package_name: Option<String>,
    /// Gravity in world coordinates, m/s²; `None`: the source's convention ([`default_gravity`]).
    pub gravity: Option<[f64; 3]>,
    /// Merge bodies joined by welds into one body each.
    pub lump_welds: bool,
    /// Write DXF/STL shape files (off for `inspect`).
    pub write_shapes: bool,
    /// Drives for `Mechatronics.mo` (the service fills them from its drive assignments).
    pub drives: Vec<back::modelica::mechatronics::DrivePlan>,
    /// VRML matching tolerances.
    pub matching: passes::geometry_match::MatchOptions,
    /// Modelica names an earlier version used, by node ID (see [`name_hints`]).
    pub name_hints: back::modelica::Hints,
    /// The model in the service that the package is written for: `Mechatronics` gets a live
    /// view sending to it (`None`: no live view, e.g. from the command line).
    pub live: Option<back::modelica::mechatronics::live::LiveTarget>,
    /// The user's allowed-collision edits, by body name (a < b): allowed to touch or not.
    pub collision_edits: back::collision_shapes::AllowedEdits,
    /// Where collision shapes are looked up by mesh content before being computed, and kept
    /// after (`None`: every shape is computed). The caller owns it: the service keeps one per
    /// process for all its jobs; a single conversion (the CLI) has nothing to reuse. Whether a
    /// shape came from the cache never changes the output.
    pub shape_cache: Option<std::sync::Arc<dyn crate::collision::ShapeCache>>,
    /// Where STEP parts' tessellations are looked up by file content before being meshed, and
    /// kept after (`None`: each conversion meshes its STEP files, each distinct file once). Owned
    /// by the caller like `shape_cache`; never changes the output.
    pub step_cache: Option<std::sync::Arc<dyn front::mesh::step::StepCache>>,
    /// The model's scene (issue 29), as stored: checked against the bodies' Modelica names
    /// (objects this version cannot take are left out with a `scene-object-omitted` warning),
    /// then written into `Mechatronics.mo` and the MJCF.
    pub scene: crate::scene::SceneSpec,
    /// The meshes uploaded for the scene by name: mesh objects take their hull for contacts and
    /// the package gets their files under `Resources/Shapes/`.
    pub scene_meshes: crate::scene::Meshes,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            package_name: None,
            gravity: None,
            lump_welds: false,
            write_shapes: true,
            drives: Vec::new(),
            matching: Default::default(),
            name_hints: Default::default(),
            live: None,
            collision_edits: Default::default(),
            shape_cache: None,
            step_cache: None,
            scene: Default::default(),
            scene_meshes: Default::default(),
        }
    }
}

/// One conversion error, by stage. Every variant names the file (and where it can, the line,
/// column and element).
#[derive(Debug, thiserror::Error)]
pub enum ConvertError {
    #[error(transparent)]
    Bundle(#[from] BundleError),
    #[error(transparent)]
    Xml(#[from] XmlError),
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    #[error(transparent)]
    Simscape2(#[from] front::simscape2::Simscape2Error),
    #[error(transparent)]
    Urdf(#[from] front::urdf::UrdfError),
    #[error(transparent)]
    UrdfGeometry(#[from] front::urdf::UrdfGeometryError),
    #[error(transparent)]
    Validation(#[from] ValidationError),
    #[error(transparent)]
    Vrml(#[from] front::vrml::VrmlError),
    #[error("VRML matching: {0}")]
    Matching(#[from] passes::geometry_match::MatchError),
    /// The VRML scene would pass what the bundle's triangle budget leaves once the bodies'
    /// meshes from STL files are counted.
    #[error(
        "{error} (VRML shapes count against the limit of {max} triangles per bundle, after instancing; \
         {stl} of them are taken by the STL meshes)"
    )]
    VrmlTriangleBudget { error: front::vrml::VrmlError, stl: usize, max: usize },
    /// The VRML shapes matched to the bodies (a shape placed under two matched groups counts
    /// for both) pass the bundle's triangle budget.
    #[error("the VRML shapes matched to the bodies bring the bundle to {total} triangles, over the limit of {max} triangles per bundle")]
    MatchedTriangleBudget { total: usize, max: usize },
    #[error("mechatronic model: {0}")]
    Mechatronics(#[from] back::modelica::mechatronics::MechatronicsError),
    #[error(transparent)]
    Loops(#[from] passes::loops::TooManyLoops),
    #[error("invalid option: {0}")]
    Options(String),
}

/// A positioned message, for APIs that list errors.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Diagnostic {
    pub file: String,
    pub line: u32,
    pub column: u32,
    pub message: String,
}

impl ConvertError {
    /// The error as positioned diagnostics: the file, line and column where known, and the
    /// message without them.
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        let d = match self {
            ConvertError::Xml(e) => Diagnostic {
                file: e.file.clone(),
                line: e.line,
                column: e.column,
                message: if e.element.is_empty() { e.kind.to_string() } else { format!("in {}: {}", e.element, e.kind) },
            },
            ConvertError::Simscape2(e) => {
                Diagnostic { file: e.file.clone(), line: e.line, column: e.column, message: e.diagnostic_message() }
            }
            ConvertError::Urdf(e) => Diagnostic {
                file: e.file.clone(),
                line: e.line,
                column: e.column,
                message: if e.element.is_empty() { e.message.clone() } else { format!("in {}: {}", e.element, e.message) },
            },
            ConvertError::Geometry(GeometryError::Stl(e)) => {
                Diagnostic { file: e.file.clone(), line: e.line, column: 0, message: e.kind.to_string() }
            }
            ConvertError::Geometry(GeometryError::Mesh(e)) => {
                Diagnostic { file: e.file.clone(), line: e.line, column: 0, message: e.kind.to_string() }
            }
            ConvertError::Vrml(e) => Diagnostic { file: e.file.clone(), line: e.line, column: e.column, message: e.kind.to_string() },
            ConvertError::VrmlTriangleBudget { error: e, .. } => {
                let text = self.to_string();
                let message = text.strip_prefix(&e.to_string()).map_or(text.clone(), |rest| format!("{}{rest}", e.kind));
                Diagnostic { file: e.file.clone(), line: e.line, column: e.column, message }
            }
            ConvertError::Validation(e) => {
                let loc = e.loc();
                let text = e.to_string();
                let message = text.strip_prefix(&format!("{loc}: ")).unwrap_or(&text).to_string();
                Diagnostic { file: loc.file.clone(), line: loc.line, column: loc.column, message }
            }
            ConvertError::Bundle(BundleError::Ambiguous { referenced_from, .. }) => {
                Diagnostic { file: referenced_from.clone(), line: 0, column: 0, message: self.to_string() }
            }
            _ => Diagnostic { file: String::new(), line: 0, column: 0, message: self.to_string() },
        };
        // Messages stay bounded whatever the input (an element path or a list can be long).
        vec![Diagnostic { message: ir::clip(&d.message, MAX_MESSAGE_BYTES), file: ir::clip(&d.file, 1024), ..d }]
    }
}

/// A finished conversion.
#[derive(Debug)]
pub struct Output {
    /// Every file of the output zip, paths relative to its root: `<Pkg>/...` and `report.json`.
    /// When the package is written (`Options::write_shapes`), the bodies' DXF and STL files come
    /// deflated (`FileData::bytes` reads them), so that a conversion never holds them all as
    /// plain bytes (issue 26, peak memory), and so do the other files: those final when made on
    /// the threads that make them, beside the Modelica writing (`package.mo`'s documentation
    /// beside Mechatronics), the rest (Mechatronics, the `package.order` files, what the
    /// observer adds) before the conversion returns (issue 23). A file deflating does not
    /// shrink stays plain. Which files come deflated does not depend on the threads.
    pub files: Vec<(String, back::bundle::FileData)>,
    pub report: report::Report,
    /// How many collision shapes were computed and how many came from the shape cache (not in
    /// the report: the output is the same either way).
    pub shapes: back::collision_shapes::ShapeCounts,
    /// How many STEP files were meshed and how many came from the STEP cache (likewise).
    pub step: passes::geometry::StepCounts,
}

/// Peak memory of one conversion (`convert` then the zip), estimated from what an upload's check
/// knows: the bodies' triangles counted after instancing and the bundle's inflated bytes.
/// Linear: [`PEAK_BASE_BYTES`] + [`PEAK_BYTES_PER_TRIANGLE`] × triangles + 1.5 × bundle bytes
/// (the bundle is held through the conversion, and distinct meshes are parsed from it). Measured (issue 26, debug build, whole process
/// `cad2mo convert`, `/usr/bin/time -v`, 2026-11-29), each below its estimate:
///
/// | bundle | triangles | bundle bytes | peak | estimate |
/// |---|---|---|---|---|
/// | `gen_bundle urdf-shared 5` (one 199,712-triangle OBJ named by 5 links) | 1.0 M | 8.7 MB | 167 MB | 223 MB |
/// | `urdf-shared 20` | 4.0 M | 8.7 MB | 255 MB | 403 MB |
/// | `urdf-shared 25` | 5.0 M | 8.7 MB | 268 MB | 463 MB |
/// | the same grid as 25 distinct OBJ files | 5.0 M | 218 MB | 640 MB | 777 MB |
/// | the same grid as 25 distinct binary STL files | 5.0 M | 250 MB | 667 MB | 825 MB |
///
/// A mesh read once but named by several bodies costs its output files per use (about 23 bytes
/// per triangle deflated, held until zipped); distinct meshes cost their bundle bytes and their
/// vertices and triangles besides.
pub fn peak_memory_estimate(triangles: u64, bundle_bytes: u64) -> u64 {
    PEAK_BASE_BYTES
        .saturating_add(triangles.saturating_mul(PEAK_BYTES_PER_TRIANGLE))
        .saturating_add(bundle_bytes.saturating_add(bundle_bytes / 2))
}

/// The estimate's fixed part: the process, the libraries, collision shapes and the small files.
pub const PEAK_BASE_BYTES: u64 = 150_000_000;
/// The estimate's bytes per triangle (after instancing).
pub const PEAK_BYTES_PER_TRIANGLE: u64 = 60;

/// The DXF and STL file of every body with a shape (`stems` names them: [`back::modelica::shape_stems`]), in body order,
/// each deflated for the zip as soon as it is written (issue 26, peak memory: the plain bytes of
/// one body's two files at a time per thread, about 240 bytes per triangle, instead of every
/// body's; bodies sharing a mesh still get a file each, named after them), on up to 4 threads
/// ([`crate::par::map_ordered`]). (One core fewer than the machine's, to leave the Modelica
/// text's thread a larger share, was tried: no gain measured on the 2,000-body tree, and the
/// 25 links of 200,000 triangles each took 6 s instead of 4.6 s.)
fn mesh_files(model: &Model, stems: &[Option<String>], pkg_name: &str) -> Vec<(String, back::bundle::FileData)> {
    let dir = format!("{pkg_name}/Resources/Shapes");
    let todo: Vec<(&str, &ir::Body, &ir::Mesh)> =
        stems.iter().zip(&model.bodies).filter_map(|(stem, body)| Some((stem.as_deref()?, body, body.mesh.as_deref()?))).collect();
    let written =
        crate::par::map_ordered(&todo, crate::par::threads(4), back::bundle::Deflater::default, |deflater, &(stem, body, mesh)| {
            let dxf = deflater.file(back::dxf::write(mesh, body.display_rgb(), stem));
            let stl = deflater.file(back::stl::write_binary(mesh, stem));
            (dxf, stl)
        });
    let mut out = Vec::with_capacity(2 * todo.len());
    for ((stem, _, _), (dxf, stl)) in todo.iter().zip(written) {
        out.push((format!("{dir}/{stem}.dxf"), dxf));
        out.push((format!("{dir}/{stem}.stl"), stl));
    }
    out
}

/// Front end and passes up to validation: the model as back ends will see it.
pub struct Analysed {
    pub model: Model,
    pub validated: Validated,
    /// Per lumped body, the node IDs merged into it.
    pub merged: std::collections::BTreeMap<String, Vec<String>>,
    /// Welds absorbed by lumping (reported with the body they went into).
    pub absorbed: Vec<passes::lump::Absorbed>,
    /// Front-end, geometry and validation warnings, in that order.
    pub warnings: Vec<Warning>,
    /// How VRML geometry was matched, when the bundle had VRML.
    pub vrml: Option<passes::geometry_match::MatchReport>,
    /// How many STEP files were meshed and how many came from the STEP cache.
    pub step: passes::geometry::StepCounts,
}

/// Parses and analyses a bundle.
pub fn analyse(bundle: &Bundle, opts: &Options) -> Result<Analysed, ConvertError> {
    analyse_observed(bundle, opts, &mut Quiet)
}

/// [`analyse`], telling `obs` how far it is.
pub fn analyse_observed(bundle: &Bundle, opts: &Options, obs: &mut dyn Observer) -> Result<Analysed, ConvertError> {
    analyse_ahead(bundle, None, opts, obs)
}

/// A model source parsed before the rest of its bundle was read ([`parse_ahead`]): the command
/// line parses the XML while the thousands of mesh files are still being read (issue 23).
pub struct ParsedAhead {
    kind: SourceKind,
    path: String,
    len: usize,
    crc: u32,
    parsed: Result<ParsedSource, ConvertError>,
}

enum ParsedSource {
    Xml(Model, Vec<Warning>),
    Urdf(front::urdf::Urdf),
}

/// The file at `path` (relative to the bundle's root) parsed as the model source it is, or
/// `None` when it is none. The conversion of a bundle holding this file as its one source
/// takes the result instead of parsing it again ([`convert_owned_ahead`]); anything else
/// (another source found, other bytes) is converted as without it.
pub fn parse_ahead(path: &str, bytes: &[u8]) -> Option<ParsedAhead> {
    let path = front::bundle::normalise(path)?;
    let kind = SourceKind::of(&path, bytes)?;
    let parsed = parse_source(kind, &path, bytes);
    Some(ParsedAhead { kind, len: bytes.len(), crc: crc32fast::hash(bytes), path, parsed })
}

fn parse_source(kind: SourceKind, path: &str, bytes: &[u8]) -> Result<ParsedSource, ConvertError> {
    Ok(match kind {
        SourceKind::FirstGeneration => {
            let (model, warnings) = front::simmechanics::parse(path, bytes)?;
            ParsedSource::Xml(model, warnings)
        }
        SourceKind::SecondGeneration => {
            let (model, warnings) = front::simscape2::parse(path, bytes)?;
            ParsedSource::Xml(model, warnings)
        }
        SourceKind::Urdf => ParsedSource::Urdf(front::urdf::parse(path, bytes)?),
    })
}

/// [`analyse_observed`], taking the source parsed ahead when it is the bundle's source.
fn analyse_ahead(bundle: &Bundle, ahead: Option<ParsedAhead>, opts: &Options, obs: &mut dyn Observer) -> Result<Analysed, ConvertError> {
    obs.progress(Stage::Xml, 0, 1);
    let (kind, path) = find_source(bundle)?;
    let bytes = bundle.get(&path).unwrap_or_default();
    let parsed = match ahead {
        Some(a) if a.kind == kind && a.path == path && a.len == bytes.len() && a.crc == crc32fast::hash(bytes) => a.parsed?,
        _ => parse_source(kind, &path, bytes)?,
    };
    let mut step = passes::geometry::StepCounts::default();
    let (mut model, mut warnings) = match parsed {
        // Both XML generations: the parts' meshes are read (STL, STEP) by file name.
        ParsedSource::Xml(mut model, mut warnings) => {
            let (w, counts) = passes::geometry::read_meshes(&mut model, bundle, &path, opts.step_cache.as_deref(), &mut |i, n| {
                obs.progress(Stage::Meshes, i, n)
            })?;
            warnings.extend(w);
            step = counts;
            (model, warnings)
        }
        ParsedSource::Urdf(mut urdf) => {
            let w = front::urdf::attach_meshes(&mut urdf, bundle, &path, &mut |i, n| obs.progress(Stage::Meshes, i, n))?;
            urdf.warnings.extend(w);
            (urdf.model, urdf.warnings)
        }
    };
    let vrml = match_vrml(&mut model, bundle, opts, &mut warnings, obs)?;
    obs.progress(Stage::Analysis, 0, 1);
    let mut merged = Default::default();
    let mut absorbed = Vec::new();
    if opts.lump_welds {
        let h = passes::hierarchy::build(&model);
        let lumped = passes::lump::lump(&model, &h);
        model = lumped.model;
        merged = lumped.merged;
        absorbed = lumped.absorbed;
    }
    let planned = passes::loops::plan(&model)?;
    warnings.extend(planned.warnings);
    let analysis = Analysis { hierarchy: planned.hierarchy, chains: planned.chains, loops: planned.loops };
    let validated = valid::validate(&model, analysis)?;
    warnings.extend(validated.warnings.iter().cloned());
    Ok(Analysed { model, validated, merged, absorbed, warnings, vrml, step })
}

/// Gravity where the user gives none: CAD assemblies (first-generation SimMechanics XML) are
/// drawn with +y up; URDF (ROS's REP 103) and Simscape Multibody models with +z up.
pub fn default_gravity(model: &Model) -> [f64; 3] {
    match model.source.format.as_str() {
        "urdf" | "simscape2" => [0.0, 0.0, -9.81],
        _ => [0.0, -9.81, 0.0],
    }
}

/// The kinds of model source a bundle can hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SourceKind {
    FirstGeneration,
    SecondGeneration,
    Urdf,
}

impl SourceKind {
    pub fn describe(self) -> &'static str {
        match self {
            SourceKind::FirstGeneration => "first-generation SimMechanics XML",
            SourceKind::SecondGeneration => "second-generation Simscape Multibody XML",
            SourceKind::Urdf => "URDF",
        }
    }

    /// What kind of source the file at `path` is, from its extension and root element.
    pub fn of(path: &str, bytes: &[u8]) -> Option<SourceKind> {
        let lower = path.to_ascii_lowercase();
        if !(lower.ends_with(".xml") || lower.ends_with(".urdf")) {
            return None;
        }
        if front::simmechanics::is_physical_modeling_xml(bytes) {
            Some(SourceKind::FirstGeneration)
        } else if front::simscape2::is_simscape2_xml(bytes) {
            Some(SourceKind::SecondGeneration)
        } else if front::urdf::is_urdf(bytes) {
            Some(SourceKind::Urdf)
        } else {
            None
        }
    }
}

/// The bundle's one model source. A bundle with none but a xacro file is told to expand it.
pub fn find_source(bundle: &Bundle) -> Result<(SourceKind, String), ConvertError> {
    match bundle.find_source(SourceKind::of, SourceKind::describe) {
        Ok((k, p)) => Ok((k, p.to_string())),
        Err(e @ BundleError::NoXml { .. }) => {
            if let Some(x) = bundle.paths().find(|p| p.to_ascii_lowercase().ends_with(".xacro")) {
                return Err(front::urdf::parse(x, bundle.get(x).unwrap_or_default()).err().map_or(e.into(), Into::into));
            }
            Err(e.into())
        }
        Err(e) => Err(e.into()),
    }
}

/// The names an earlier version's `report.json` gave its bodies and joints, by node ID.
pub fn name_hints(report: &serde_json::Value) -> back::modelica::Hints {
    let collect = |key: &str| {
        report[key]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|e| Some((e["node_id"].as_str()?.to_string(), e["modelica_name"].as_str()?.to_string())))
            .filter(|(_, name): &(String, String)| !name.is_empty())
            .collect()
    };
    let diagram = report["diagram"]["groups"]
        .as_object()
        .into_iter()
        .flatten()
        .filter_map(|(k, v)| {
            let (c, r) = (v.get(0)?.as_i64()?, v.get(1)?.as_i64()?);
            Some((k.clone(), (i32::try_from(c).ok()?, i32::try_from(r).ok()?)))
        })
        .collect();
    back::modelica::Hints { bodies: collect("bodies"), joints: collect("joints"), diagram }
}

/// Reads the bundle's VRML export (every main file: those no other VRML file inlines) and
/// matches its groups to the bodies that have no mesh yet (not read at all when every body
/// but the RootParts has one). `matching.json` pins come first.
fn match_vrml(
    model: &mut Model,
    bundle: &Bundle,
    opts: &Options,
    warnings: &mut Vec<Warning>,
    obs: &mut dyn Observer,
) -> Result<Option<passes::geometry_match::MatchReport>, ConvertError> {
    // Nothing is decompressed or parsed unless a body the matching would target (one without
    // a mesh, RootParts aside) still needs geometry; gzip files are decompressed once, within
    // one budget for the bundle.
    if !model.bodies.iter().any(|b| b.mesh.is_none() && !valid::is_root_part(b)) {
        return Ok(None);
    }
    let gz = front::vrml::Gunzip::default();
    let mains = front::vrml::main_files_in(bundle, &gz)?;
    if mains.is_empty() {
        return Ok(None);
    }
    // The bundle's triangle budget (after instancing, as for STL files): what the bodies' meshes
    // read from STL files leave is what the scenes of all the main files may hold.
    let max = front::mesh::MAX_BUNDLE_TRIANGLES;
    let triangles = |model: &Model| model.bodies.iter().filter_map(|b| b.mesh.as_ref()).map(|m| m.triangles.len()).sum::<usize>();
    let stl = triangles(model);
    let mut scene = front::vrml::Scene::default();
    for (i, main) in mains.iter().enumerate() {
        obs.progress(Stage::Vrml, i, mains.len() + 1);
        let left = max.saturating_sub(stl).saturating_sub(scene.triangle_count());
        let (s, w) = front::vrml::parse_within(bundle, main, &gz, left).map_err(|error| match &error.kind {
            front::vrml::VrmlErrorKind::TooManyTriangles { .. } | front::vrml::VrmlErrorKind::Expansion { unit: "triangles", .. } => {
                ConvertError::VrmlTriangleBudget { error, stl, max }
            }
            _ => ConvertError::Vrml(error),
        })?;
        warnings.extend(w);
        scene.append(s);
    }
    let pins_path = bundle.paths().find(|p| p.rsplit('/').next().is_some_and(|n| n.eq_ignore_ascii_case("matching.json")));
    let pins = match pins_path {
        Some(p) => passes::geometry_match::parse_pins(bundle.get(p).unwrap_or_default())?,
        None => Default::default(),
    };
    obs.progress(Stage::Vrml, mains.len(), mains.len() + 1);
    let (report, w) = passes::geometry_match::match_scene(model, &scene, &pins, &opts.matching)?;
    let total = triangles(model);
    if total > max {
        return Err(ConvertError::MatchedTriangleBudget { total, max });
    }
    warnings.extend(w);
    Ok(Some(report))
}

/// Converts a bundle into the files of the output zip.
pub fn convert(bundle: &Bundle, opts: &Options) -> Result<Output, ConvertError> {
    convert_observed(bundle, opts, &mut Quiet)
}

/// [`convert`], telling `obs` how far it is and letting it choose the drives once the report
/// exists (the report does not depend on them: drives only make `Mechatronics.mo`).
pub fn convert_observed(bundle: &Bundle, opts: &Options, obs: &mut dyn Observer) -> Result<Output, ConvertError> {
    check_options(opts)?;
    let a = analyse_observed(bundle, opts, obs)?;
    write_output(a, opts, obs)
}

/// [`convert`] of a bundle this call may drop: its files' bytes are freed once they are read
/// (parsed and meshed), so the writers reuse that memory instead of the kernel's fresh pages
/// (the 2,000-body tree's 37 MB of STL: a fifth of the conversion's peak, each page of it
/// faulted in again). What the command line's conversion calls.
pub fn convert_owned(bundle: Bundle, opts: &Options) -> Result<Output, ConvertError> {
    convert_owned_ahead(bundle, None, opts)
}

/// [`convert_owned`], with the bundle's source parsed ahead ([`parse_ahead`]).
pub fn convert_owned_ahead(bundle: Bundle, ahead: Option<ParsedAhead>, opts: &Options) -> Result<Output, ConvertError> {
    check_options(opts)?;
    let a = analyse_ahead(&bundle, ahead, opts, &mut Quiet)?;
    drop(bundle);
    write_output(a, opts, &mut Quiet)
}

fn check_options(opts: &Options) -> Result<(), ConvertError> {
    match opts.gravity.filter(|g| !g.iter().all(|c| c.is_finite())) {
        Some(g) => Err(ConvertError::Options(format!("gravity {g:?} is not finite"))),
        None => Ok(()),
    }
}

/// The files of the output zip of an analysed bundle.
fn write_output(a: Analysed, opts: &Options, obs: &mut dyn Observer) -> Result<Output, ConvertError> {
    let step_counts = a.step;
    let gravity = opts.gravity.unwrap_or_else(|| default_gravity(&a.model));
    let package_name = match &opts.package_name {
        Some(p) if back::modelica::sanitize(p, "P") == *p => p.clone(),
        Some(p) => return Err(ConvertError::Options(format!("package name \"{p}\" is not a Modelica identifier"))),
        None => back::modelica::sanitize(&a.model.name, "P"),
    };
    let package_name = if package_name == "P" { "CadModel".to_string() } else { package_name };
    obs.progress(Stage::Modelica, 0, 1);
    let modelica_options = back::modelica::Options {
        package_name: package_name.clone(),
        gravity,
        converter_version: VERSION.to_string(),
        name_hints: opts.name_hints.clone(),
    };
    let front_warnings = a.warnings;
    // Work that depends on nothing below runs on other threads while this one writes the
    // Modelica text (issue 23: the second core is never left idle): the bodies' collision shapes
    // (they need no names) and the DXF and STL file of every body with a shape (named as the
    // package names them: `shape_stems`, the package's `Layout::shapes`).
    std::thread::scope(|scope| {
        fn join<T>(h: std::thread::ScopedJoinHandle<'_, T>) -> T {
            h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))
        }
        let (model, pkg_name) = (&a.model, &package_name);
        let body_names = back::modelica::assign_with_hints(&a.model, &modelica_options.name_hints);
        // The collision shapes, then their files (`Resources/Collision`, deflated), which need
        // only the shapes and the bodies' names: written while this thread still routes the
        // diagram's wires.
        let shape_names = body_names.bodies.clone();
        let shapes = scope.spawn(move || {
            let shapes = back::collision_shapes::body_shapes(model, &Default::default(), opts.shape_cache.as_deref());
            let files = opts.write_shapes.then(|| back::collision_shapes::shape_files(&shapes.0, pkg_name, &shape_names));
            (shapes, files)
        });
        let stems = back::modelica::shape_stems(&a.model, &body_names);
        let mesh_files = opts.write_shapes.then(|| scope.spawn(move || mesh_files(model, &stems, pkg_name)));
        let back::modelica::Package { files: pkg_files, layout: pkg_layout } =
            back::modelica::write_named(&a.model, &a.validated, &modelica_options, body_names);
        let mut report = report::build(report::ReportInput {
            model: &a.model,
            validated: &a.validated,
            layout: &pkg_layout,
            package_name: &package_name,
            options: report::ReportOptions { lump_welds: opts.lump_welds, gravity },
            merged: &a.merged,
            absorbed: &a.absorbed,
            vrml: a.vrml.as_ref(),
            warnings: front_warnings,
            version: VERSION,
        });
        for (c, done) in a.model.couplings.iter().zip(&pkg_layout.couplings) {
            if let Err(why) = done {
                report.warnings.push(Warning::new("mimic-not-expressible", format!("coupling not emitted: {why}"), c.loc.to_string()));
            }
        }
        // Collision shapes of every body with a mesh; interferences at the CAD pose are warnings.
        obs.progress(Stage::Collision, 0, 1);
        let names: Vec<String> = pkg_layout.names.as_ref().map(|n| n.bodies.clone()).unwrap_or_default();
        let joint_names: Vec<String> = pkg_layout.names.as_ref().map(|n| n.joints.clone()).unwrap_or_default();
        // The shapes are waited for only here: the report above is made meanwhile.
        let (shapes, shape_files) = join(shapes);
        let collision = back::collision_shapes::Collision::from_shapes(shapes, &a.model, &names, &joint_names, &opts.collision_edits);
        // The scene: its objects checked against this version's bodies (those it cannot take left
        // out, named), then its part of Mechatronics and of the MJCF.
        let (scene, omitted) = crate::scene::check_stored(&opts.scene, &names, &opts.scene_meshes);
        // The Mechanics diagram, which Mechatronics extends (taken, not copied).
        let mut pkg_layout = pkg_layout;
        let mechanics_diagram = std::mem::take(&mut pkg_layout.diagram);
        // The MuJoCo and URDF exports depend on nothing below: they are written on other threads
        // while this one checks the CAD pose's interferences and writes Mechatronics.
        std::thread::scope(|inner| {
            let (validated, layout, scene_ref) = (&a.validated, &pkg_layout, &scene);
            // When the package is written (`write_shapes`), files that are final are deflated for
            // the zip where they are made, on the threads beside this one.
            let ahead = |files: Vec<(String, Vec<u8>)>| -> Vec<(String, back::bundle::FileData)> {
                let mut deflater = opts.write_shapes.then(back::bundle::Deflater::default);
                files.into_iter().map(|(p, b)| (p, if let Some(d) = &mut deflater { d.file(b) } else { b.into() })).collect()
            };
            let exports = inner.spawn(move || {
                let mut mjcf = back::mjcf::file(model, validated, layout, pkg_name, gravity, opts.write_shapes);
                if !scene_ref.objects.is_empty() {
                    mjcf.1 = crate::scene::package::mjcf(&String::from_utf8_lossy(&mjcf.1), scene_ref).into_bytes();
                }
                let urdf = back::urdf::file(model, validated, layout, pkg_name, opts.write_shapes);
                ahead(vec![mjcf, back::urdf::relative_file(&urdf, pkg_name), urdf])
            });
            // The package's own files are final but for the package documentation and the
            // package.order files, which get lines below.
            let mut files = pkg_files;
            let final_file = |p: &str| opts.write_shapes && !p.ends_with("/package.order") && *p != format!("{package_name}/package.mo");
            let finished: Vec<usize> = (0..files.len()).filter(|&i| final_file(&files[i].0)).collect();
            let taken: Vec<(String, Vec<u8>)> = finished.iter().map(|&i| (String::new(), std::mem::take(&mut files[i].1))).collect();
            let pkg_deflated = inner.spawn(move || ahead(taken));
            let (collision_report, collision_warnings) = collision.report(&a.model, &names);
            obs.progress(Stage::Collision, 1, 1);
            report.warnings.extend(collision_warnings);
            report.collision = Some(collision_report);
            for i in omitted {
                report.warnings.push(Warning::new(
                    "scene-object-omitted",
                    format!("{} {}: left out of the package", i.field, i.message),
                    "",
                ));
            }
            let scene_modelica = crate::scene::package::modelica(&scene, &package_name);
            let drives = obs.drives(&report, &opts.drives);
            files.extend(back::modelica::mechatronics::components(&package_name));
            if opts.write_shapes {
                files.extend(crate::scene::package::mesh_files(&scene, &opts.scene_meshes, &package_name));
            }
            let extras = obs.extras(
                &observe::ModelView { model: &a.model, validated: &a.validated, layout: &pkg_layout, package_name: &package_name },
                &drives,
            );
            // A live view frame carries at most MAX_BODIES bodies: larger models are written without one.
            let bodies: &[String] = pkg_layout.names.as_ref().map(|n| n.bodies.as_slice()).unwrap_or_default();
            let live = opts
                .live
                .as_ref()
                .filter(|_| (1..=back::modelica::mechatronics::live::MAX_BODIES).contains(&bodies.len()))
                .map(|t| (t, bodies));
            if opts.live.is_some() && live.is_none() {
                report.warnings.push(Warning::new(
                    "live-view-omitted",
                    format!(
                        "{} bodies: a live view frame carries 1 to {}, so the package has no LiveView",
                        bodies.len(),
                        back::modelica::mechatronics::live::MAX_BODIES
                    ),
                    "",
                ));
            }
            // The report is final: its JSON is written beside Mechatronics.
            let report = report;
            let (mut files, json) = std::thread::scope(|last| -> Result<_, ConvertError> {
                let json = last.spawn(|| -> Result<_, ConvertError> {
                    let json = crate::jsontext::to_vec(&report).map_err(|e| ConvertError::Options(e.to_string()))?;
                    Ok(ahead(vec![("report.json".to_string(), json)]))
                });
                // The package documentation lists the report's findings and the drives: written
                // beside Mechatronics too.
                let doc = last.spawn(|| {
                    let text = back::modelica::doc::package_file(&report, &drives, &back::modelica::provenance(&a.model, VERSION), VERSION);
                    ahead(vec![(String::new(), text.into_bytes())]).pop().map(|(_, b)| b)
                });
                let parts = collision.parts();
                let contacts = back::modelica::mechatronics::collision::declarations_with_scene(
                    &package_name,
                    &names,
                    &parts,
                    &collision.allowed_pairs(),
                    &scene_modelica.members,
                );
                files.extend(back::modelica::mechatronics::mechatronics(
                    &package_name,
                    &drives,
                    &extras.motions,
                    back::modelica::mechatronics::Additions {
                        live,
                        collision: contacts.as_ref(),
                        scene: (!scene_modelica.declarations.is_empty()).then_some(scene_modelica.declarations.as_str()),
                        diagram: Some(mechanics_diagram),
                        experiment: Some(&back::modelica::Experiment::for_model(&a.model, gravity)),
                    },
                    &back::modelica::provenance(&a.model, VERSION),
                )?);
                if !extras.motions.is_empty() {
                    if let Some((_, order)) = files.iter_mut().find(|(p, _)| *p == format!("{package_name}/package.order")) {
                        order.extend_from_slice(b"Motions\n");
                    }
                }
                if let Some((_, order)) = files.iter_mut().find(|(p, _)| *p == format!("{package_name}/Components/package.order")) {
                    if live.is_some() {
                        order.extend_from_slice(b"Visualization\n");
                    }
                    if contacts.is_some() {
                        order.extend_from_slice(b"Collision\n");
                    }
                }
                files.extend(extras.files);
                // The files still plain are final now, but for package.mo (the documentation,
                // made beside) and those deflated ahead (`finished`, empty until they come back):
                // deflated here, while the report's JSON may still be written, rather than when
                // the zip is, after everything else.
                let mut deflater = opts.write_shapes.then(back::bundle::Deflater::default);
                let pkg_mo = format!("{package_name}/package.mo");
                let mut files: Vec<(String, back::bundle::FileData)> = files
                    .into_iter()
                    .enumerate()
                    .map(|(i, (p, b))| {
                        let later = p == pkg_mo || finished.binary_search(&i).is_ok();
                        let data = match &mut deflater {
                            Some(d) if !later => d.file(b),
                            _ => b.into(),
                        };
                        (p, data)
                    })
                    .collect();
                if let (Some((_, text)), Some(doc)) = (files.iter_mut().find(|(p, _)| *p == pkg_mo), join(doc)) {
                    *text = doc;
                }
                Ok((files, join(json)?))
            })?;
            for (i, (_, b)) in finished.into_iter().zip(join(pkg_deflated)) {
                files[i].1 = b;
            }
            if let (Some(shape_files), Some(mesh_files)) = (shape_files, mesh_files) {
                files.extend(shape_files);
                // Two files (DXF, STL) per body with a shape, a step each as they join the package.
                let meshes = join(mesh_files);
                let n = meshes.len() / 2;
                for (k, file) in meshes.into_iter().enumerate() {
                    if k % 2 == 0 {
                        obs.progress(Stage::Shapes, k / 2, n);
                    }
                    files.push(file);
                }
            }
            files.extend(join(exports));
            obs.progress(Stage::Report, 0, 1);
            files.extend(json);
            Ok(Output { files, report, shapes: collision.counts, step: step_counts })
        })
    })
}

#[cfg(test)]
mod memory_tests {
    use super::*;

    /// The bodies' DXF and STL files come deflated (issue 26: a conversion never holds them all
    /// as plain bytes), and so do the other files final when made (issue 23); they inflate to
    /// what the writers give, and the zip is the one the plain files give: deflating them early
    /// changes no byte of a package.
    #[test]
    fn shape_files_come_deflated_and_zip_as_plain_ones() {
        let files = crate::testgen::urdf_shared_obj(3, 40);
        let bundle = Bundle::from_files("shared", files).expect("bundle");
        let out = convert(&bundle, &Options { write_shapes: true, ..Options::default() }).expect("converts");
        let shapes: Vec<_> = out.files.iter().filter(|(p, _)| p.ends_with(".dxf") || p.ends_with(".stl")).collect();
        assert_eq!(shapes.len(), 6, "a DXF and an STL per link");
        assert!(shapes.iter().all(|(_, f)| f.is_deflated()), "every shape file deflated");
        // The other files come deflated too (issue 23: on the threads that make them, the
        // package documentation among them, and the last ones before the conversion returns),
        // but for those deflating does not shrink (the package.order files, a few lines).
        let deflated = |suffix: &str| out.files.iter().find(|(p, _)| p.ends_with(suffix)).map(|(_, f)| f.is_deflated());
        for file in ["/Mechanics.mo", "/Mechatronics.mo", "report.json", "/shapes.json", ".mjcf.xml", ".urdf", "/package.mo"] {
            assert_eq!(deflated(file), Some(true), "{file}");
        }
        for (p, f) in &out.files {
            assert!(f.is_deflated() || f.len() < 512, "{p}: {} bytes, plain", f.len());
        }
        // Without the package's shape files (the service's analyses), every file comes plain.
        let text = convert(&bundle, &Options { write_shapes: false, ..Options::default() }).expect("converts");
        assert!(text.files.iter().all(|(p, f)| !f.is_deflated() && !p.ends_with(".dxf")));
        // Each inflates to its writer's bytes.
        let a = analyse(&bundle, &Options::default()).expect("analyses");
        let stl = back::stl::write_binary(a.model.bodies[0].mesh.as_deref().expect("a mesh"), "l0");
        assert_eq!(*out.files.iter().find(|(p, _)| p.ends_with("/l0.stl")).expect("l0.stl").1.bytes(), stl[..]);
        let plain: Vec<(String, Vec<u8>)> = out.files.iter().map(|(p, f)| (p.clone(), f.bytes().into_owned())).collect();
        assert_eq!(back::bundle::write_files(out.files).expect("zip"), back::bundle::write_zip(&plain).expect("zip"));
    }

    /// A source parsed ahead is taken for the bundle's source with the same path and bytes
    /// only: other bytes at that path are parsed again.
    #[test]
    fn a_source_parsed_ahead_is_taken_only_for_its_own_bytes() {
        let files = crate::testgen::urdf_shared_obj(3, 10);
        let (path, bytes) = files.iter().find(|(p, _)| p.ends_with(".urdf")).cloned().expect("a URDF");
        let other = String::from_utf8(bytes.clone()).expect("text").replacen("<robot name=\"shared\"", "<robot name=\"other\"", 1);
        assert_ne!(other.as_bytes(), &bytes[..]);
        let bundle = || Bundle::from_files("b", files.clone()).expect("bundle");
        let plain = convert(&bundle(), &Options::default()).expect("converts").report.model_name;
        assert_eq!(plain, "shared");
        let taken = convert_owned_ahead(bundle(), parse_ahead(&path, &bytes), &Options::default()).expect("converts");
        assert_eq!(taken.report.model_name, plain);
        let stale = convert_owned_ahead(bundle(), parse_ahead(&path, other.as_bytes()), &Options::default()).expect("converts");
        assert_eq!(stale.report.model_name, plain, "other bytes at the path: parsed again");
        assert!(parse_ahead("notes.txt", &bytes).is_none(), "not a source");
    }

    /// The estimate is linear: 150 MB, 60 bytes per triangle and 1.5 bytes per bundle byte, and
    /// above every peak measured (the table of [`peak_memory_estimate`]).
    #[test]
    fn peak_memory_estimate_is_linear_and_above_the_measured_peaks() {
        assert_eq!(peak_memory_estimate(0, 0), 150_000_000);
        assert_eq!(peak_memory_estimate(5_000_000, 0) - peak_memory_estimate(4_000_000, 0), 60_000_000);
        assert_eq!(peak_memory_estimate(0, 2_000_000) - peak_memory_estimate(0, 0), 3_000_000);
        // (triangles, inflated bundle bytes, measured peak)
        for (t, b, peak) in [
            (998_560, 8_743_851, 167_000_000),
            (3_994_240, 8_743_851, 255_000_000),
            (4_992_800, 8_747_947, 268_000_000),
            (4_992_800, 218_061_035, 640_000_000),
            (4_992_800, 249_668_710, 667_000_000),
        ] {
            assert!(peak_memory_estimate(t, b) > peak, "{t} triangles, {b} bytes: {} MB", peak_memory_estimate(t, b) / 1_000_000);
        }
        assert_eq!(peak_memory_estimate(u64::MAX, u64::MAX), u64::MAX, "saturates");
    }
}
