//! cad2mo: converts CAD assembly exports into Modelica packages.
//!
//! - [`pipeline`]: the converter itself. Bytes and options in, files and diagnostics out; no IO.
//! - [`cli`]: the command line (reads bundles from disk, writes zips atomically).

pub mod cli;
pub mod pipeline;
