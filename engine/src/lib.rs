//! cad2mo's computation: bytes in, values out. No file system, no network, no async runtime, no
//! HTTP and no SQL (this crate's `Cargo.toml` has none of them; the service is `cad2mo-server`,
//! the command line `cad2mo`).
//!
//! - [`pipeline`]: the converter itself. A bundle (the CAD export's files) and options in,
//!   package files and diagnostics out.
//! - [`mechanism`]: motion and inverse dynamics of a validated model (kinematics, loop assembly,
//!   IK, RNEA), in the emitted Modelica model's joint coordinates.
//! - [`motion`]: motion planning (keyframes, limits, jerk-limited profiles, IK targets).
//! - [`sizing`]: drive sizing of a motion's joint loads against the motor library (checks,
//!   operating points, ranked alternatives).
//! - [`library`]: the motor library's rules (classes, instances, parameters, import plans).
//! - [`collision`]: collision shapes, distances and sweeps along a motion.
//! - [`results`]: simulation result files (MAT v4, CSV) read into time series and body poses.
//! - [`live`]: the live view's frames (decoding and verifying what a running model sends).
//! - [`scene`]: a model's environment (scene objects: primitives, static, moving or free).
//! - [`diff`]: what changed between two conversions.
//! - [`par`]: work spread over scoped threads, results in order.

pub mod collision;
pub mod diff;
pub mod jsontext;
pub mod library;
pub mod live;
pub mod mechanism;
pub mod motion;
pub mod numtext;
pub mod par;
pub mod pipeline;
pub mod results;
pub mod scene;
pub mod simulation;
pub mod sizing;

/// Generated test models (shared with the benchmarks).
#[cfg(test)]
#[path = "../benches/support/gen.rs"]
#[allow(dead_code)]
pub(crate) mod testgen;

/// A bundle folder of the test inputs read into a [`pipeline::front::bundle::Bundle`] named after
/// the folder.
#[cfg(test)]
pub(crate) fn test_bundle_of_dir(dir: &std::path::Path) -> Result<pipeline::front::bundle::Bundle, pipeline::front::bundle::BundleError> {
    let name = dir.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    pipeline::front::bundle::Bundle::from_files(&name, testgen::files_under(dir))
}
