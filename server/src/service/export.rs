//! Building a version's package from its stored bundle: the service's one way from an upload to
//! `package.zip` + `report.json`.
//!
//! [`build_package`]: read the zip ([`read_bundle`], with the service's limits), convert it once
//! with [`pipeline::convert_observed`] (the observer turns the model's drive assignments into
//! drive plans as soon as the report names the joints, and passes the stages on as
//! [`BuildStep`]s), add the report's `drives` section, zip the files ([`write_files_observed`]).
//! Everything here is synchronous and CPU-bound: callers run it off the async runtime (the job
//! workers, `api::blocking`).
//!
//! Deterministic: the same bundle and options give byte-identical outputs, so re-running a job
//! (after a restart) is harmless.

use serde::{Deserialize, Serialize};

use cad2mo_engine::pipeline::back::bundle::write_files_observed;
use cad2mo_engine::pipeline::back::modelica::mechatronics::DrivePlan;
use cad2mo_engine::pipeline::front::bundle::{Bundle, BundleError, Limits};
use cad2mo_engine::pipeline::observe::{Observer, Stage};
use cad2mo_engine::pipeline::report::Report;
use cad2mo_engine::pipeline::{self, ConvertError};

/// Conversion options of a version, as stored with it (`versions.options_json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ExportOptions {
    /// Modelica package name; `None` derives it from the assembly's name.
    pub package_name: Option<String>,
    /// Gravity in world coordinates, m/s²; `None`: the source's convention.
    pub gravity: Option<[f64; 3]>,
    /// Merge bodies joined by welds.
    pub lump_welds: bool,
}

impl Default for ExportOptions {
    fn default() -> Self {
        let d = pipeline::Options::default();
        ExportOptions { package_name: d.package_name, gravity: d.gravity, lump_welds: d.lump_welds }
    }
}

impl ExportOptions {
    /// The pipeline's options (shapes always written for packages).
    pub fn pipeline(&self) -> pipeline::Options {
        pipeline::Options {
            package_name: self.package_name.clone(),
            gravity: self.gravity,
            lump_welds: self.lump_welds,
            write_shapes: true,
            ..pipeline::Options::default()
        }
    }
}

/// Counts from a version's report, kept with the version for listings (`versions.summary_json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub model_name: String,
    pub package_name: String,
    pub bodies: usize,
    pub joints: usize,
    pub loops: usize,
    pub free_bodies: usize,
    pub warnings: usize,
}

impl Summary {
    pub fn of(r: &Report) -> Summary {
        Summary {
            model_name: r.model_name.clone(),
            package_name: r.package_name.clone(),
            bodies: r.bodies.len(),
            joints: r.joints.len(),
            loops: r.loops.len(),
            free_bodies: r.free_bodies.len(),
            warnings: r.warnings.len(),
        }
    }
}

/// A built package.
#[derive(Debug)]
pub struct Built {
    /// The output zip: the Modelica package and `report.json`.
    pub package_zip: Vec<u8>,
    /// `report.json`, byte-identical to the copy inside the zip.
    pub report_json: Vec<u8>,
    pub summary: Summary,
    /// Collision shapes computed by this build and served by the shape cache.
    pub shapes: pipeline::back::collision_shapes::ShapeCounts,
    /// STEP files meshed by this build and served by the STEP cache.
    pub step: pipeline::passes::geometry::StepCounts,
}

/// What a bundle check found (the upload-time analysis).
#[derive(Debug, Clone)]
pub struct Checked {
    /// The assembly's name from the XML (the model's default name).
    pub model_name: String,
    pub warnings: usize,
    /// The bodies' triangles counted after instancing (a mesh once per body that uses it) and the
    /// bundle's inflated bytes: what the job's memory estimate is made of
    /// ([`pipeline::peak_memory_estimate`]).
    pub triangles: u64,
    pub bundle_bytes: u64,
}

/// Why a package could not be built.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The upload is not a readable, safe zip (not a zip, unsafe paths, zip bomb, ...).
    #[error(transparent)]
    Bundle(#[from] BundleError),
    /// The bundle's content does not convert (diagnostics with file and position).
    #[error(transparent)]
    Convert(#[from] ConvertError),
    /// Writing the output zip failed (not the input's fault).
    #[error("writing the package zip: {0}")]
    Zip(#[source] std::io::Error),
}

/// Limits for uploaded zips: the pipeline's defaults (1 GiB uncompressed, 20,000 entries,
/// 1000x compression ratio).
pub fn limits() -> Limits {
    Limits::default()
}

/// Reads an uploaded bundle zip safely.
pub fn read_bundle(bundle_bytes: &[u8], bundle_name: &str) -> Result<Bundle, BundleError> {
    Bundle::from_zip(bundle_name, bundle_bytes, &limits())
}

/// Upload-time check: the zip reads safely and its XML parses, resolves and validates
/// ([`pipeline::analyse`], no back ends). Fast; bad input is refused before anything is stored.
/// The STEP parts it meshes go into `step_cache` (the service's, which its jobs share: the
/// conversion that follows the upload meshes them no more).
pub fn check_bundle(
    bundle_bytes: &[u8],
    bundle_name: &str,
    options: &ExportOptions,
    step_cache: Option<std::sync::Arc<dyn cad2mo_engine::pipeline::front::mesh::step::StepCache>>,
) -> Result<Checked, ExportError> {
    let bundle = read_bundle(bundle_bytes, bundle_name)?;
    let mut opts = options.pipeline();
    opts.step_cache = step_cache;
    let a = pipeline::analyse(&bundle, &opts)?;
    Ok(Checked {
        model_name: a.model.name.clone(),
        warnings: a.warnings.len(),
        triangles: a.model.bodies.iter().filter_map(|b| b.mesh.as_ref()).map(|m| m.triangles.len() as u64).sum(),
        bundle_bytes: bundle.total_bytes(),
    })
}

/// Where a package build is: a stage of the conversion, or zipping its files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BuildStage {
    Convert(Stage),
    Package,
}

/// One progress report of [`build_package`]: `done` of `total` units of `stage`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuildStep {
    pub stage: BuildStage,
    pub done: usize,
    pub total: usize,
}

/// Builds a version's package from its bundle, keeping the Modelica names of the context's
/// `name_hints` (the previous version's) for unchanged node IDs, with `Mechatronics.mo` driving the joints of
/// `drives` that the converted model has. The report gains a `drives` section listing the
/// active and the orphaned assignments (joints the model no longer has). `progress` hears every
/// step.
pub fn build_package(
    bundle_bytes: &[u8],
    bundle_name: &str,
    options: &ExportOptions,
    drives: &[crate::service::drives::ResolvedDrive],
    motions: &MotionsInput,
    context: &Context,
    progress: &mut dyn FnMut(BuildStep),
) -> Result<Built, ExportError> {
    let bundle = read_bundle(bundle_bytes, bundle_name)?;
    let mut opts = options.pipeline();
    opts.name_hints = context.name_hints.clone();
    opts.live = context.live.clone();
    opts.collision_edits = context.collision_edits.clone();
    opts.shape_cache = context.shape_cache.clone();
    opts.step_cache = context.step_cache.clone();
    opts.scene = context.scene.clone();
    opts.scene_meshes = context.scene_meshes.clone();
    let mut obs = BuildObserver {
        drives,
        motions,
        gravity: options.gravity,
        active: Vec::new(),
        orphaned: Vec::new(),
        written: Vec::new(),
        skipped: Vec::new(),
        failed: None,
        progress,
    };
    let out = pipeline::convert_observed(&bundle, &opts, &mut obs)?;
    let BuildObserver { active, orphaned, written, skipped, failed, progress, .. } = obs;
    if let Some(e) = failed {
        return Err(ExportError::Zip(std::io::Error::other(e)));
    }
    let mut files = out.files;
    let mut report = serde_json::to_value(&out.report).map_err(|e| ExportError::Zip(std::io::Error::other(e)))?;
    report["drives"] = serde_json::json!({ "active": active, "orphaned": orphaned });
    if !motions.specs.is_empty() {
        report["motions"] = serde_json::json!({ "written": written, "skipped": skipped });
    }
    let report_json = cad2mo_engine::jsontext::to_vec(&report).map_err(|e| ExportError::Zip(std::io::Error::other(e)))?;
    match files.iter_mut().find(|(path, _)| path == "report.json") {
        Some((_, bytes)) => *bytes = report_json.clone().into(),
        None => return Err(ExportError::Zip(std::io::Error::other("the conversion wrote no report.json"))),
    }
    let package_zip = write_files_observed(files, &mut |done, total| progress(BuildStep { stage: BuildStage::Package, done, total }))
        .map_err(ExportError::Zip)?;
    Ok(Built { package_zip, report_json, summary: Summary::of(&out.report), shapes: out.shapes, step: out.step })
}

/// What a version's package is written for beyond its bundle and options: the Modelica names of
/// the version before it (kept for unchanged node IDs), the service's live view, and the
/// model's allowed-collision edits.
#[derive(Clone, Debug, Default)]
pub struct Context {
    pub name_hints: pipeline::back::modelica::Hints,
    pub live: Option<pipeline::back::modelica::mechatronics::live::LiveTarget>,
    /// The model's allowed-collision edits.
    pub collision_edits: pipeline::back::collision_shapes::AllowedEdits,
    /// The process's collision shapes by mesh content (see [`pipeline::Options::shape_cache`]).
    pub shape_cache: Option<std::sync::Arc<dyn cad2mo_engine::collision::ShapeCache>>,
    /// The process's STEP tessellations by file content (see [`pipeline::Options::step_cache`]).
    pub step_cache: Option<std::sync::Arc<dyn cad2mo_engine::pipeline::front::mesh::step::StepCache>>,
    /// The model's scene (its objects go into `Mechatronics.mo` and the MJCF).
    pub scene: cad2mo_engine::scene::SceneSpec,
    /// The meshes uploaded for the scene, by name.
    pub scene_meshes: cad2mo_engine::scene::Meshes,
}

/// The model's motions and joint limits, for the package's `Motions` and sizing files.
#[derive(Clone, Debug, Default)]
pub struct MotionsInput {
    pub specs: Vec<cad2mo_engine::motion::plan::MotionSpec>,
    pub limits: std::collections::BTreeMap<String, cad2mo_engine::motion::plan::LimitsEdit>,
    /// The version being built (named in the sizing files).
    pub version: i64,
    /// The model's drives and the library, for `Resources/Sizing/<motion>.json`.
    pub drives: Vec<crate::service::motions::DriveParts>,
    pub catalog: cad2mo_engine::sizing::Catalog,
}

/// Passes the conversion's stages on, plans the drives from its report and the motions on the
/// named model.
struct BuildObserver<'a> {
    drives: &'a [crate::service::drives::ResolvedDrive],
    motions: &'a MotionsInput,
    gravity: Option<[f64; 3]>,
    active: Vec<String>,
    orphaned: Vec<String>,
    /// Motions written into `Mechatronics.mo`, and those this version cannot plan.
    written: Vec<String>,
    skipped: Vec<crate::service::motions::Skipped>,
    /// The report could not be read for planning (then no drive is planned and the build fails).
    failed: Option<serde_json::Error>,
    progress: &'a mut dyn FnMut(BuildStep),
}

impl Observer for BuildObserver<'_> {
    fn progress(&mut self, stage: Stage, done: usize, total: usize) {
        (self.progress)(BuildStep { stage: BuildStage::Convert(stage), done, total: total.max(1) });
    }

    fn drives(&mut self, report: &Report, _planned: &[DrivePlan]) -> Vec<DrivePlan> {
        if self.drives.is_empty() {
            return Vec::new();
        }
        let json = match serde_json::to_value(report) {
            Ok(j) => j,
            Err(e) => {
                self.failed = Some(e);
                return Vec::new();
            }
        };
        let (plans, orphans) = crate::service::drives::plans(&json, self.drives);
        self.active = plans.iter().map(|d| d.joint.clone()).collect();
        self.orphaned = orphans;
        plans
    }

    fn extras(&mut self, view: &pipeline::observe::ModelView<'_>, _drives: &[DrivePlan]) -> pipeline::observe::Extras {
        let (mech, planned, skipped) = crate::service::motions::for_package(view, &self.motions.specs, &self.motions.limits);
        self.written = planned.iter().map(|p| p.table.label.clone()).collect();
        self.skipped = skipped;
        let tables: Vec<_> = planned.iter().map(|p| p.table.clone()).collect();
        let files = match (mech, pipeline::back::modelica::mechatronics::motion_class_names(&tables)) {
            (Some(mech), Ok(names)) => crate::service::motions::sizing_files(
                &mech,
                &nalgebra::Vector3::from(self.gravity.unwrap_or_else(|| pipeline::default_gravity(view.model))),
                self.motions.version,
                view.package_name,
                &planned,
                &names,
                &self.motions.drives,
                &self.motions.catalog,
            ),
            _ => Vec::new(),
        };
        pipeline::observe::Extras { motions: tables, files }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cad2mo_engine::pipeline::back::bundle::write_zip;

    fn pendulum_zip() -> Vec<u8> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/pendulum");
        let files = vec![
            ("PENDULUM.xml".to_string(), std::fs::read(root.join("PENDULUM.xml")).unwrap()),
            ("meshes/LINK_prt.stl".to_string(), std::fs::read(root.join("meshes/LINK_prt.stl")).unwrap()),
        ];
        write_zip(&files).unwrap()
    }

    #[test]
    fn builds_deterministically() {
        let zip = pendulum_zip();
        let opts = ExportOptions::default();
        let a = build_package(&zip, "p.zip", &opts, &[], &MotionsInput::default(), &Context::default(), &mut |_| {}).unwrap();
        let b = build_package(&zip, "p.zip", &opts, &[], &MotionsInput::default(), &Context::default(), &mut |_| {}).unwrap();
        assert_eq!(a.package_zip, b.package_zip);
        assert_eq!(a.summary.package_name, "PENDULUM");
        assert_eq!((a.summary.bodies, a.summary.joints), (2, 2));
        let report: serde_json::Value = serde_json::from_slice(&a.report_json).unwrap();
        assert_eq!(report["package_name"], "PENDULUM");
        assert_eq!(check_bundle(&zip, "p.zip", &opts, None).unwrap().model_name, "PENDULUM");
    }

    /// A second-generation bundle of one part whose geometry is the fuzz seed's hand-written
    /// STEP tetrahedron (10 mm edges, millimetres).
    fn step_part_zip() -> Vec<u8> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let step = std::fs::read(root.join("fuzz/seeds/step/tetra_mm.step")).unwrap();
        let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<SimscapeMultibodyImportXML xmlns="urn:mathworks:SimscapeMultibody:import" version="2.0">
  <Created by="t" from="Onshape" on="1/1/25" using="Simscape Multibody Exporter"/>
  <ModelUnits length="millimeter" mass="kilogram"/>
  <DataUnits length="meter" mass="kilogram"/>
  <RootAssembly name="tet" uid="A">
    <InstanceTree>
      <Instance entityUid="P1" grounded="true" name="Base &lt;1&gt;" uid="b">
        <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0</Translation></Transform>
      </Instance>
    </InstanceTree>
  </RootAssembly>
  <Parts>
    <Part name="P" uid="P1">
      <MassProperties><Mass>0.0005</Mass><CenterOfMass>0.0025 0.0025 0.0025</CenterOfMass><Inertia>1e-8 1e-8 1e-8 0 0 0</Inertia></MassProperties>
      <GeometryFile name="T.step" type="STEP"/>
    </Part>
  </Parts>
</SimscapeMultibodyImportXML>"#;
        write_zip(&[("tet.xml".to_string(), xml.as_bytes().to_vec()), ("T.step".to_string(), step)]).unwrap()
    }

    #[test]
    fn the_upload_check_leaves_its_step_meshes_to_the_build() {
        use cad2mo_engine::pipeline::front::mesh::step::{MemoryStepCache, StepCache};
        let zip = step_part_zip();
        let opts = ExportOptions::default();
        let build = |context: &Context| build_package(&zip, "t.zip", &opts, &[], &MotionsInput::default(), context, &mut |_| {}).unwrap();
        // Without a cache the build meshes the STEP file itself.
        let alone = build(&Context::default());
        assert_eq!((alone.step.meshed, alone.step.cached), (1, 0));
        // The service's path: the upload check meshes it into the shared cache, the job's build
        // takes it from there, and the package is the same.
        let cache = std::sync::Arc::new(MemoryStepCache::default());
        let shared: std::sync::Arc<dyn StepCache> = cache.clone();
        check_bundle(&zip, "t.zip", &opts, Some(shared.clone())).unwrap();
        assert_eq!(cache.stats().2, 1, "the check left the tetrahedron in the cache");
        let built = build(&Context { step_cache: Some(shared), ..Context::default() });
        assert_eq!((built.step.meshed, built.step.cached), (0, 1), "the build meshed no STEP file");
        assert_eq!(built.package_zip, alone.package_zip);
    }

    #[test]
    fn options_round_trip_with_defaults() {
        let o: ExportOptions = serde_json::from_str("{}").unwrap();
        assert_eq!(o, ExportOptions::default());
        let o = ExportOptions { package_name: Some("P".into()), gravity: Some([0.0, 0.0, -9.81]), lump_welds: true };
        assert_eq!(serde_json::from_str::<ExportOptions>(&serde_json::to_string(&o).unwrap()).unwrap(), o);
    }
}
