//! The closure equations' rates, exactly: their Jacobian `Φ_x` and their velocity-product term
//! `(Φ_x ẋ)_x ẋ` (the second time derivative of `Φ` along `ẋ` at `ẍ = 0`), by spatial-vector
//! algebra: no differences, for every closure form and joint type (tree links and plain cut
//! elements are revolute or prismatic; spherical elements are refused by the mechanism).
//!
//! **Motions** are world spatial vectors `[angular; linear]`, the linear part the velocity of
//! the body point at the world origin, so one vector serves every frame of a rigid body. A tree
//! link moves at `V_i = V_p + S_i q̇_i` and, with `q̈ = 0`, accelerates at
//! `A_i = A_p + V_i ×ₘ S_i q̇_i`, with `S_i = [a; p × a]` (revolute about world axis `a` through
//! its frame's origin `p`) or `[0; a]` (prismatic). A plain cut's chain extends its base frame's
//! motion the same way, its coordinates at their speeds (accelerations zero). A frame's origin
//! `p` then moves at `v = V_lin + ω × p` and accelerates at `A_lin + α × p + ω × v` (classical).
//!
//! **Each equation's rates** follow from those of the cut's two frames (`a` the base side, for a
//! plain cut the end of its chain; `ω`, `α`, `v`, `acc` as above):
//! - position difference `Δ = p_b − p_a`: `Δ̇ = v_b − v_a`, `Δ̈ = acc_b − acc_a`;
//! - a vector in frame a's axes, `d = R_aᵀ Δ`: `ḋ = R_aᵀ(Δ̇ − ω_a × Δ)`,
//!   `d̈ = R_aᵀ(Δ̈ − α_a × Δ − 2 ω_a × Δ̇ + ω_a × (ω_a × Δ))`;
//! - an axis of frame b in frame a's axes, `m = R_aᵀ R_b n`: with `n_w = R_b n`,
//!   `u = ω_b − ω_a`, `g = u × n_w`: `ṁ = R_aᵀ g`,
//!   `m̈ = R_aᵀ((α_b − α_a) × n_w + u × (ω_b × n_w) − ω_a × g)`;
//! - a rotation vector `φ = log E` with `Ė = [w] E` (`E = R_b R_xᵀ`: `w = ω_b − E ω_x`;
//!   `E = R_aᵀ R_b`: `w = R_aᵀ u`): `φ̇ = J⁻¹(φ) w` and `φ̈ = J⁻¹(φ) ẇ + J̇⁻¹ w`, `J` the left
//!   Jacobian of SO(3), `J⁻¹(φ) = I − ½[φ] + c(θ)[φ]²`, `c = 1/θ² − cot(θ/2)/(2θ)` (by its
//!   series below 0.1 rad, where the closed form cancels).
//!
//! Every first rate is linear in the speeds, so the Jacobian's column of a coordinate is the
//! first rate its unit speed gives; the velocity-product term is the second rate at the actual
//! speeds. The mimic couplings' rows are linear: exact columns, no curvature.

use nalgebra::{DMatrix, DVector, Isometry3, Vector3, Vector6};

use super::{closure::perpendiculars, element_motion, forward::cross_motion, Closure, ClosureForm, ConstraintClass, Kinematics, Mechanism};

/// A rigid body's world spatial velocity `v` and velocity-product acceleration `a` (see the
/// module docs).
#[derive(Clone, Copy, Debug, Default)]
struct Motion {
    v: Vector6<f64>,
    a: Vector6<f64>,
}

/// Classical rates of a frame's origin and orientation (world).
struct PointRates {
    w: Vector3<f64>,
    alpha: Vector3<f64>,
    v: Vector3<f64>,
    acc: Vector3<f64>,
}

fn top(v: &Vector6<f64>) -> Vector3<f64> {
    v.fixed_rows::<3>(0).into_owned()
}

fn bottom(v: &Vector6<f64>) -> Vector3<f64> {
    v.fixed_rows::<3>(3).into_owned()
}

/// The rates of the origin `p` of a frame moving with `m`.
fn point(m: &Motion, p: &Vector3<f64>) -> PointRates {
    let (w, alpha) = (top(&m.v), top(&m.a));
    let v = bottom(&m.v) + w.cross(p);
    let acc = bottom(&m.a) + alpha.cross(p) + w.cross(&v);
    PointRates { w, alpha, v, acc }
}

/// The world spatial axis of a revolute (about `axis`, in the frame at `pose`, through its
/// origin) or prismatic element.
fn spatial_axis(pose: &Isometry3<f64>, axis: &Vector3<f64>, prismatic: bool) -> Vector6<f64> {
    let a = pose.rotation * axis;
    if prismatic {
        Vector6::new(0.0, 0.0, 0.0, a.x, a.y, a.z)
    } else {
        let pa = pose.translation.vector.cross(&a);
        Vector6::new(a.x, a.y, a.z, pa.x, pa.y, pa.z)
    }
}

/// `c(θ)` of `J⁻¹` and `c'(θ)/θ`.
fn log_coefficients(theta: f64) -> (f64, f64) {
    if theta < 0.1 {
        let t2 = theta * theta;
        let c = 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 / 1_209_600.0));
        let d = 1.0 / 360.0 + t2 * (1.0 / 7560.0 + t2 / 201_600.0);
        (c, d)
    } else {
        let half = 0.5 * theta;
        let cot = half.cos() / half.sin();
        let csc2 = 1.0 / (half.sin() * half.sin());
        let t2 = theta * theta;
        let c = 1.0 / t2 - cot / (2.0 * theta);
        let dc = -2.0 / (t2 * theta) + csc2 / (4.0 * theta) + cot / (2.0 * t2);
        (c, dc / theta)
    }
}

/// First and second rates of `φ = log E` given `Ė = [w] E` and `ẇ` (see the module docs).
fn log_rates(phi: &Vector3<f64>, w: &Vector3<f64>, wd: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let (c, d) = log_coefficients(phi.norm());
    let jinv = |v: &Vector3<f64>| v - 0.5 * phi.cross(v) + c * phi.cross(&phi.cross(v));
    let phid = jinv(w);
    // d/dt J⁻¹ = −½[φ̇] + c'θ̇ [φ]² + c([φ̇][φ] + [φ][φ̇]), c'θ̇ = (c'/θ)(φ·φ̇).
    let jdot_w =
        -0.5 * phid.cross(w) + d * phi.dot(&phid) * phi.cross(&phi.cross(w)) + c * (phid.cross(&phi.cross(w)) + phi.cross(&phid.cross(w)));
    (phid, jinv(wd) + jdot_w)
}

impl Mechanism {
    /// Appends to `d1` and `d2` the first and second rates of closure `c`'s equations (in the
    /// order of the residual) at link poses `k` and cut coordinates `cut`, its frame a's link
    /// moving with `ma`, frame b's with `mb`, the cut coordinates at speeds `cut_rate`.
    #[allow(clippy::too_many_arguments)]
    fn closure_rates(
        &self,
        c: &Closure,
        k: &Kinematics,
        cut: &[f64],
        ma: &Motion,
        mb: &Motion,
        cut_rate: &[f64],
        d1: &mut Vec<f64>,
        d2: &mut Vec<f64>,
    ) {
        let pa = self.attachment_pose(k, &c.a);
        let pb = self.attachment_pose(k, &c.b);
        let rb = point(mb, &pb.translation.vector);
        match &c.form {
            ClosureForm::Plain { elements, residual } => {
                let (mut x, mut mx) = (pa, *ma);
                for (prismatic, axis, i) in elements {
                    let sv = spatial_axis(&x, axis, *prismatic) * cut_rate.get(*i).copied().unwrap_or(0.0);
                    mx.v += sv;
                    mx.a += cross_motion(&mx.v, &sv);
                    x *= element_motion(*prismatic, axis, cut.get(*i).copied().unwrap_or(0.0));
                }
                x *= residual;
                let rx = point(&mx, &x.translation.vector);
                d1.extend((rb.v - rx.v).iter());
                d2.extend((rb.acc - rx.acc).iter());
                let e = pb.rotation * x.rotation.inverse();
                let ewx = e * rx.w;
                let w = rb.w - ewx;
                let wd = rb.alpha - w.cross(&ewx) - e * rx.alpha;
                let (r1, r2) = log_rates(&e.scaled_axis(), &w, &wd);
                d1.extend(r1.iter());
                d2.extend(r2.iter());
            }
            ClosureForm::Planar { n } => {
                let (v1, v2) = self.offset_rates(&pa, ma, &pb, &rb);
                let (e1, e2) = perpendiculars(n);
                d1.extend([e1.dot(&v1), e2.dot(&v1)]);
                d2.extend([e1.dot(&v2), e2.dot(&v2)]);
            }
            ClosureForm::Constraint { class, locked, n, n_b } => {
                let (v1, v2) = self.offset_rates(&pa, ma, &pb, &rb);
                for i in (0..3).filter(|i| locked[*i]) {
                    d1.push(v1[i]);
                    d2.push(v2[i]);
                }
                let ra = point(ma, &pa.translation.vector);
                let inv = pa.rotation.inverse();
                let u = rb.w - ra.w;
                let ud = rb.alpha - ra.alpha;
                // m = R_aᵀ R_b n_local: first and second rates.
                let axis_rates = |n_local: &Vector3<f64>| {
                    let nw = pb.rotation * n_local;
                    let g = u.cross(&nw);
                    (inv * g, inv * (ud.cross(&nw) + u.cross(&rb.w.cross(&nw)) - ra.w.cross(&g)))
                };
                match class {
                    ConstraintClass::Spherical => {}
                    ConstraintClass::Revolute => {
                        let (m1, m2) = axis_rates(n);
                        let (e1, e2) = perpendiculars(n);
                        d1.extend([e1.dot(&m1), e2.dot(&m1)]);
                        d2.extend([e1.dot(&m2), e2.dot(&m2)]);
                    }
                    ConstraintClass::Prismatic => {
                        let rel = inv * pb.rotation;
                        let w = inv * u;
                        let wd = inv * (ud - ra.w.cross(&u));
                        let (r1, r2) = log_rates(&rel.scaled_axis(), &w, &wd);
                        d1.extend(r1.iter());
                        d2.extend(r2.iter());
                    }
                    ConstraintClass::Universal => {
                        let (m1, m2) = axis_rates(n_b);
                        d1.push(n.dot(&m1));
                        d2.push(n.dot(&m2));
                    }
                }
            }
        }
    }

    /// First and second rates of `d = R_aᵀ (p_b − p_a)`.
    fn offset_rates(&self, pa: &Isometry3<f64>, ma: &Motion, pb: &Isometry3<f64>, rb: &PointRates) -> (Vector3<f64>, Vector3<f64>) {
        let ra = point(ma, &pa.translation.vector);
        let delta = pb.translation.vector - pa.translation.vector;
        let dv = rb.v - ra.v;
        let da = rb.acc - ra.acc;
        let inv = pa.rotation.inverse();
        let w = ra.w;
        (inv * (dv - w.cross(&delta)), inv * (da - ra.alpha.cross(&delta) - 2.0 * w.cross(&dv) + w.cross(&w.cross(&delta))))
    }

    /// The tree links above `link` (itself included), leaf first.
    fn path_to_root(&self, link: Option<usize>) -> Vec<usize> {
        let mut out = Vec::new();
        let mut cur = link;
        while let Some(i) = cur {
            out.push(i);
            cur = self.links.get(i).and_then(|l| l.parent);
        }
        out
    }

    /// `∂Φ/∂x` (rows: [`Mechanism::closure_equations`]; columns: the tree coordinates, then the
    /// cut coordinates) at the link poses `k` of tree coordinates `q` and cut coordinates `cut`.
    pub(super) fn closure_jacobian_at(&self, k: &Kinematics, cut: &[f64]) -> DMatrix<f64> {
        let n = self.links.len();
        let rows = self.closure_equations();
        let mut jac = DMatrix::zeros(rows, n + self.cut_coordinates.len());
        let (mut d1, mut d2) = (Vec::new(), Vec::new());
        let zero = Motion::default();
        let mut unit = vec![0.0; self.cut_coordinates.len()];
        let mut row = 0;
        for c in &self.closures {
            let on_a = self.path_to_root(c.a.link);
            let on_b = self.path_to_root(c.b.link);
            let mut links: Vec<usize> = on_a.iter().chain(&on_b).copied().collect();
            links.sort_unstable();
            links.dedup();
            for j in links {
                let (Some(l), Some(pose)) = (self.links.get(j), k.links.get(j)) else { continue };
                let s = Motion { v: spatial_axis(pose, &l.axis, l.prismatic), a: Vector6::zeros() };
                let ma = if on_a.contains(&j) { s } else { zero };
                let mb = if on_b.contains(&j) { s } else { zero };
                d1.clear();
                self.closure_rates(c, k, cut, &ma, &mb, &[], &mut d1, &mut d2);
                for (r, v) in d1.iter().enumerate() {
                    jac[(row + r, j)] = *v;
                }
            }
            if let ClosureForm::Plain { elements, .. } = &c.form {
                for (_, _, i) in elements {
                    unit.fill(0.0);
                    if let Some(u) = unit.get_mut(*i) {
                        *u = 1.0;
                    }
                    d1.clear();
                    self.closure_rates(c, k, cut, &zero, &zero, &unit, &mut d1, &mut d2);
                    for (r, v) in d1.iter().enumerate() {
                        jac[(row + r, n + i)] = *v;
                    }
                }
            }
            row += c.equations();
        }
        for (r, c) in self.couplings.iter().enumerate() {
            jac[(row + r, c.follower)] += 1.0;
            jac[(row + r, c.leader)] -= c.multiplier;
        }
        jac
    }

    /// `(Φ_x ẋ)_x ẋ`: the closure equations' second time derivative along the speeds
    /// `ẋ = (qd, cut_d)` with `ẍ = 0`, at the link poses `k` of tree coordinates `q` and cut
    /// coordinates `cut` (zero on the couplings' rows, which are linear).
    pub(super) fn closure_curvature(&self, k: &Kinematics, cut: &[f64], qd: &[f64], cut_d: &[f64]) -> DVector<f64> {
        let mut motions: Vec<Motion> = Vec::with_capacity(self.links.len());
        for (i, l) in self.links.iter().enumerate() {
            let parent = l.parent.and_then(|p| motions.get(p)).copied().unwrap_or_default();
            let pose = k.links.get(i).copied().unwrap_or_else(Isometry3::identity);
            let sv = spatial_axis(&pose, &l.axis, l.prismatic) * qd.get(i).copied().unwrap_or(0.0);
            let v = parent.v + sv;
            motions.push(Motion { v, a: parent.a + cross_motion(&v, &sv) });
        }
        let motion_of = |link: Option<usize>| link.and_then(|l| motions.get(l)).copied().unwrap_or_default();
        let (mut d1, mut d2) = (Vec::new(), Vec::with_capacity(self.closure_equations()));
        for c in &self.closures {
            self.closure_rates(c, k, cut, &motion_of(c.a.link), &motion_of(c.b.link), cut_d, &mut d1, &mut d2);
        }
        d2.resize(self.closure_equations(), 0.0);
        DVector::from_vec(d2)
    }
}
