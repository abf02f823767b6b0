//! VRML transforms as 4x4 matrices (column vectors: `p' = M p`).

use nalgebra::{Matrix4, Unit, Vector3};

/// Translation by `t`.
pub(super) fn translation(t: [f64; 3]) -> Matrix4<f64> {
    Matrix4::new_translation(&Vector3::new(t[0], t[1], t[2]))
}

/// Rotation by `r = [x, y, z, angle]` (axis need not be unit; a zero axis is no rotation).
pub(super) fn rotation(r: [f64; 4]) -> Matrix4<f64> {
    let axis = Vector3::new(r[0], r[1], r[2]);
    let n = axis.norm();
    if n.is_nan() || n <= 1e-300 || !r[3].is_finite() || r[3] == 0.0 {
        return Matrix4::identity();
    }
    nalgebra::Rotation3::from_axis_angle(&Unit::new_unchecked(axis / n), r[3]).to_homogeneous()
}

/// Scale by `s`.
pub(super) fn scale(s: [f64; 3]) -> Matrix4<f64> {
    Matrix4::new_nonuniform_scaling(&Vector3::new(s[0], s[1], s[2]))
}

/// The VRML 97 Transform: `T * C * R * SR * S * -SR * -C`.
pub(super) fn vrml_transform(t: [f64; 3], r: [f64; 4], s: [f64; 3], sr: [f64; 4], c: [f64; 3]) -> Matrix4<f64> {
    let srm = rotation(sr);
    translation(t) * translation(c) * rotation(r) * srm * scale(s) * srm.transpose() * translation([-c[0], -c[1], -c[2]])
}
