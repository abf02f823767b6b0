//! Modelica back end: a structured package per `shared/guides/modelica-output.md`.
//!
//! ```text
//! <Pkg>/package.mo, package.order
//! <Pkg>/Mechanics.mo                 world, bodies, frames, joints, shapes, connects
//! <Pkg>/Components/{package.mo, package.order, Revolute.mo, Prismatic.mo}
//! ```
//! Shape files (`Resources/Shapes/<body>.dxf|.stl`) are written by the caller from [`Layout`].
//!
//! Frames: every body's frame_a is its CS1. Other frames hang off it through fixed transforms;
//! joints run base -> follower as a chain of elements (see `passes::kinematics`), with the CAD
//! offset as start values and any residual as a fixed transform, so forward kinematics of the
//! emitted model at its start values reproduces the CAD pose.
//!
//! The output is deterministic: no clock, no file order dependence beyond the IR's.

pub mod diagram;
pub mod doc;
pub mod mechatronics;
mod names;
mod write;

pub use names::{assign_with_hints, sanitize, Hints, Names, Scope, KEYWORDS};
pub use write::{provenance_html as provenance, shape_stems, write, write_named, Experiment, Layout, Options, Package};
