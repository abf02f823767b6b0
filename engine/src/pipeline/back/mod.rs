//! Back ends: validated IR (plus the passes' side tables) in, bytes out.

pub mod bundle;
pub mod collision_shapes;
pub mod dxf;
pub mod mjcf;
pub mod modelica;
pub mod stl;
pub mod urdf;
