//! Turning the XML's approximately orthonormal 3x3 orientation into an exact rotation.
//!
//! CAD writes 6 significant digits, so `R` is only orthonormal to ~1e-6. Near-rotations are
//! projected onto the nearest rotation (the orthogonal polar factor) with a few Newton–Schulz
//! steps, which converge quadratically; matrices that are far from a rotation (mirrored,
//! scaled or sheared) go through an SVD and are reported.

use nalgebra::{Matrix3, Rotation3};

/// Beyond this `max |RᵀR − I|` the matrix is not a rotation written with rounding, and the
/// frame is refused (lower.rs). Rounding every entry to 6 significant digits (absolute error
/// at most 5e-7 for entries below 1) moves an entry of `RᵀR` by at most
/// `2 · |column| · |error column| ≤ 2 · √3 · 5e-7 ≈ 1.7e-6`; 1e-3 is some 600 times that, so
/// even 4-digit data (1.7e-4) passes, while a corrupt matrix (a determinant of 1.08 is an error
/// of about 0.2) cannot. Within it, the nearest rotation is used silently; a mirrored but
/// orthonormal matrix converts with a warning.
pub(crate) const TOLERANCE: f64 = 1e-3;

/// Why a matrix needed more than a rounding correction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Defect {
    /// Determinant of the matrix as written.
    pub det: f64,
    /// `max |RᵀR − I|` of the matrix as written.
    pub error: f64,
}

/// The rotation nearest to `m` (Frobenius norm, proper rotations only), and a [`Defect`] when
/// `m` is far from one (mirrored, or columns not unit/orthogonal within [`TOLERANCE`]).
pub(crate) fn nearest_rotation(m: &Matrix3<f64>) -> (Rotation3<f64>, Option<Defect>) {
    let error = orthonormality_error(m);
    if error == 0.0 && is_proper(m) {
        // Exact (identity, axis permutations with +-1): nothing to do.
        return (Rotation3::from_matrix_unchecked(*m), None);
    }
    let det = m.determinant();
    if det > 0.0 && error <= TOLERANCE {
        return (Rotation3::from_matrix_unchecked(newton_schulz(*m)), None);
    }
    (svd_rotation(m), Some(Defect { det, error }))
}

/// `max |MᵀM − I|` over all entries.
fn orthonormality_error(m: &Matrix3<f64>) -> f64 {
    (m.tr_mul(m) - Matrix3::identity()).amax()
}

/// Cheap check that an exactly orthonormal matrix is not a reflection.
fn is_proper(m: &Matrix3<f64>) -> bool {
    m.determinant() > 0.0
}

/// Newton–Schulz iteration `X ← X (3I − XᵀX) / 2` to the orthogonal polar factor; needs
/// `|I − XᵀX| < 1`, which [`TOLERANCE`] guarantees.
fn newton_schulz(mut x: Matrix3<f64>) -> Matrix3<f64> {
    for _ in 0..8 {
        let gram = x.tr_mul(&x);
        if (gram - Matrix3::identity()).amax() <= 4.0 * f64::EPSILON {
            break;
        }
        x = x * (Matrix3::identity() * 3.0 - gram) * 0.5;
    }
    x
}

/// `U diag(1, 1, ±1) Vᵀ` from the SVD of `m`: the nearest proper rotation even for mirrored or
/// degenerate input. Falls back to the identity if the SVD does not converge.
fn svd_rotation(m: &Matrix3<f64>) -> Rotation3<f64> {
    let Some(svd) = nalgebra::linalg::SVD::try_new(*m, true, true, f64::EPSILON, 1000) else {
        return Rotation3::identity();
    };
    let (Some(mut u), Some(v_t)) = (svd.u, svd.v_t) else {
        return Rotation3::identity();
    };
    if (u * v_t).determinant() < 0.0 {
        // Flip the direction of least stretch: the smallest singular value's column.
        let smallest = svd.singular_values.imin();
        let mut col = u.column_mut(smallest);
        col.neg_mut();
    }
    Rotation3::from_matrix_unchecked(u * v_t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_rotation(r: &Rotation3<f64>) -> bool {
        orthonormality_error(r.matrix()) < 1e-14 && (r.matrix().determinant() - 1.0).abs() < 1e-14
    }

    #[test]
    fn identity_and_permutation_pass_through() {
        let (r, d) = nearest_rotation(&Matrix3::identity());
        assert_eq!(r.matrix(), &Matrix3::identity());
        assert!(d.is_none());
        let p = Matrix3::from_column_slice(&[0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        let (r, d) = nearest_rotation(&p);
        assert_eq!(r.matrix(), &p);
        assert!(d.is_none());
    }

    #[test]
    fn six_digit_noise_is_removed() {
        // fourbar.xml: the columns are the frame axes in world.
        let m = Matrix3::from_column_slice(&[-0.319989, 0.947421, 0.0, 0.0, 0.0, 1.0, 0.947421, 0.319989, 0.0]);
        let (r, d) = nearest_rotation(&m);
        assert!(d.is_none());
        assert!(is_rotation(&r));
        assert!((r.matrix() - m).amax() < 1e-5);
    }

    #[test]
    fn mirrored_and_degenerate_are_reported() {
        let mirror = Matrix3::from_diagonal(&nalgebra::Vector3::new(1.0, 1.0, -1.0));
        let (r, d) = nearest_rotation(&mirror);
        assert!(d.is_some_and(|d| d.det < 0.0));
        assert!(is_rotation(&r));
        let scaled = Matrix3::identity() * 2.0;
        let (r, d) = nearest_rotation(&scaled);
        assert!(d.is_some());
        assert!((r.matrix() - Matrix3::identity()).amax() < 1e-12);
        let (r, d) = nearest_rotation(&Matrix3::zeros());
        assert!(d.is_some());
        assert!(is_rotation(&r));
    }
}
