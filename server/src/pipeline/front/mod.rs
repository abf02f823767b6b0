//! Front ends: source formats in, IR out.

pub mod bundle;
pub mod simmechanics;
pub mod simscape2;
pub mod stl;
pub mod vrml;
