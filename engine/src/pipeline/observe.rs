//! Watching a conversion as it runs: where it is (for progress displays) and, once the report
//! exists, which drives `Mechatronics.mo` gets (the service decides them from the joints the
//! report names, so it converts once instead of twice).
//!
//! The pipeline still performs no IO: an observer is a plain callback object, and the default
//! one ([`Quiet`]) does nothing and takes `Options::drives` as they are.

use super::back::modelica::mechatronics::{DrivePlan, MotionTable};
use super::back::modelica::Layout;
use super::ir::Model;
use super::report::Report;
use super::valid::Validated;

/// A step of a conversion, in the order they run. Not every conversion passes every stage (no
/// VRML, no shapes), and a stage may report progress several times (`done` of `total`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// The SimMechanics XML (front end).
    Xml,
    /// STL meshes named by the XML, one body at a time.
    Meshes,
    /// The VRML export and its matching to bodies.
    Vrml,
    /// Lumping, hierarchy, kinematics and validation.
    Analysis,
    /// The Modelica package text.
    Modelica,
    /// Collision shapes (hulls, decompositions, primitives) and interferences at the CAD pose.
    Collision,
    /// DXF and STL shape files, one body at a time.
    Shapes,
    /// `report.json`.
    Report,
}

impl Stage {
    /// Every stage, in the order they run (`Stage::X as usize` is its place here).
    pub const ALL: [Stage; 8] =
        [Stage::Xml, Stage::Meshes, Stage::Vrml, Stage::Analysis, Stage::Modelica, Stage::Collision, Stage::Shapes, Stage::Report];
}

/// Receives a conversion's progress and may choose its drives.
pub trait Observer {
    /// `stage` has `done` of `total` units behind it (`total` is at least 1).
    fn progress(&mut self, _stage: Stage, _done: usize, _total: usize) {}

    /// The drives for `Mechatronics.mo`, decided once the report (joint names, kinds, start
    /// values) exists. `planned` are `Options::drives`; the default keeps them.
    fn drives(&mut self, _report: &Report, planned: &[DrivePlan]) -> Vec<DrivePlan> {
        planned.to_vec()
    }

    /// The motions for `Mechatronics.mo` and extra files for the package (paths in the zip),
    /// decided once the model is analysed and named (the service plans its users' motions
    /// here). The default adds nothing.
    fn extras(&mut self, _view: &ModelView<'_>, _drives: &[DrivePlan]) -> Extras {
        Extras::default()
    }
}

/// The converted model as the back ends see it.
pub struct ModelView<'a> {
    pub model: &'a Model,
    pub validated: &'a Validated,
    pub layout: &'a Layout,
    pub package_name: &'a str,
}

/// What an observer adds to a package.
#[derive(Default)]
pub struct Extras {
    pub motions: Vec<MotionTable>,
    pub files: Vec<(String, Vec<u8>)>,
}

/// The observer that watches nothing and keeps the planned drives.
pub struct Quiet;

impl Observer for Quiet {}
