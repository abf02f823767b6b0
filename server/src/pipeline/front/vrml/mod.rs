//! VRML front end (VRML 97 and VRML 1.0): bundle files in, a [`Scene`] out.

pub mod scene;

pub use scene::{NodeId, Scene, SceneNode, ShapeGeom};
