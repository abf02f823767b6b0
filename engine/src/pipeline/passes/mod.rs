//! Passes over the IR. Each computes a side table (or, for lumping, a new IR) and never does IO.
//!
//! - [`hierarchy`]: spanning tree from the grounds, loops, free bodies.
//! - [`kinematics`]: each joint's primitive chain, start coordinates and residual offset.
//! - [`loops`]: loop analysis by rank: where each loop is cut, the MSL form of the cut that
//!   imposes exactly the independent equations, planar loops made exactly planar, fixed start
//!   values.
//! - [`lump`]: optional merge of welded groups into single bodies.
//! - [`geometry`]: reads each body's STL named by the XML from the bundle.
//! - [`geometry_match`]: matches VRML groups to bodies by CS1 position, orientation and name.

pub mod geometry;
pub mod geometry_match;
pub mod hierarchy;
pub mod kinematics;
pub mod loops;
pub mod lump;
