//! Front ends: source formats in, IR out.

pub mod bundle;
pub mod mesh;
pub mod simmechanics;
pub mod simscape2;
pub mod stl;
pub mod urdf;
pub mod vrml;
