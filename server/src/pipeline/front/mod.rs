//! Front ends: source formats in, IR out.

pub mod bundle;
pub mod mesh;
pub mod simmechanics;
pub mod stl;
pub mod vrml;
