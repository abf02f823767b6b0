//! Recursive Newton-Euler inverse dynamics (Featherstone, "Rigid Body Dynamics Algorithms",
//! ch. 5) on the spanning tree, with gravity as a base acceleration.
//!
//! Quantities are kept as pairs of 3-vectors in each link's frame (origin and axes of the
//! element's frame_b): velocity `(w, v)` of the link's origin, spatial acceleration `(dw, dv)`,
//! and the force `(n, f)` the parent exerts on the link's subtree, moment about the link origin.

use nalgebra::{Matrix3, Vector3};

use super::{Mechanism, MechanismError};

/// Scratch space for [`Mechanism::inverse_dynamics`]: no allocation per call.
#[derive(Clone, Debug)]
pub struct Workspace {
    r_tree: Vec<Matrix3<f64>>,
    p_tree: Vec<Vector3<f64>>,
    r: Vec<Matrix3<f64>>,
    p: Vec<Vector3<f64>>,
    w: Vec<Vector3<f64>>,
    v: Vec<Vector3<f64>>,
    dw: Vec<Vector3<f64>>,
    dv: Vec<Vector3<f64>>,
    n: Vec<Vector3<f64>>,
    f: Vec<Vector3<f64>>,
}

/// Rotation by `q` about unit axis `a` (Rodrigues).
pub(super) fn rotation(a: &Vector3<f64>, q: f64) -> Matrix3<f64> {
    let (s, c) = q.sin_cos();
    let k = 1.0 - c;
    Matrix3::new(
        c + k * a.x * a.x,
        k * a.x * a.y - s * a.z,
        k * a.x * a.z + s * a.y,
        k * a.y * a.x + s * a.z,
        c + k * a.y * a.y,
        k * a.y * a.z - s * a.x,
        k * a.z * a.x - s * a.y,
        k * a.z * a.y + s * a.x,
        c + k * a.z * a.z,
    )
}

impl Mechanism {
    /// Scratch space sized for this mechanism.
    pub fn workspace(&self) -> Workspace {
        let n = self.links.len();
        let z = vec![Vector3::zeros(); n];
        Workspace {
            r_tree: self.links.iter().map(|l| l.x_tree.rotation.to_rotation_matrix().into_inner()).collect(),
            p_tree: self.links.iter().map(|l| l.x_tree.translation.vector).collect(),
            r: vec![Matrix3::identity(); n],
            p: z.clone(),
            w: z.clone(),
            v: z.clone(),
            dw: z.clone(),
            dv: z.clone(),
            n: z.clone(),
            f: z,
        }
    }

    /// The generalised forces `tau` (N·m for revolute, N for prismatic coordinates) that produce
    /// accelerations `qdd` at coordinates `q` and speeds `qd` under `gravity` (world, m/s²), on
    /// the spanning tree (loop closures add no forces). `tau` and every input have length
    /// [`Mechanism::dof`]; `ws` must come from [`Mechanism::workspace`] of this mechanism.
    pub fn inverse_dynamics(
        &self,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        gravity: &Vector3<f64>,
        ws: &mut Workspace,
        tau: &mut [f64],
    ) -> Result<(), MechanismError> {
        self.check_len("coordinates", q)?;
        self.check_len("speeds", qd)?;
        self.check_len("accelerations", qdd)?;
        self.check_len("torques", tau)?;
        if ws.r.len() != self.links.len() {
            return Err(MechanismError::Length { what: "workspace", expected: self.links.len(), got: ws.r.len() });
        }
        let n = self.links.len();
        for i in 0..n {
            let l = &self.links[i];
            let a = l.axis;
            // Pose of the link relative to its parent: x_tree * E(q).
            let (r, p) = if l.prismatic {
                (ws.r_tree[i], ws.p_tree[i] + ws.r_tree[i] * (a * q[i]))
            } else {
                (ws.r_tree[i] * rotation(&a, q[i]), ws.p_tree[i])
            };
            let (w_p, v_p, dw_p, dv_p) = match l.parent {
                Some(pi) => (ws.w[pi], ws.v[pi], ws.dw[pi], ws.dv[pi]),
                None => (Vector3::zeros(), Vector3::zeros(), Vector3::zeros(), -gravity),
            };
            let rt = r.transpose();
            let mut w = rt * w_p;
            let mut v = rt * (v_p + w_p.cross(&p));
            let mut dw = rt * dw_p;
            let mut dv = rt * (dv_p + dw_p.cross(&p));
            let s_qd = a * qd[i];
            if l.prismatic {
                dv += a * qdd[i] + w.cross(&s_qd);
                v += s_qd;
            } else {
                dw += a * qdd[i] + w.cross(&s_qd);
                dv += v.cross(&s_qd);
                w += s_qd;
            }
            // Force on the link: I a + v x* (I v).
            let big_k = l.inertia_o * w + l.h.cross(&v);
            let big_l = v * l.mass + w.cross(&l.h);
            ws.n[i] = l.inertia_o * dw + l.h.cross(&dv) + w.cross(&big_k) + v.cross(&big_l);
            ws.f[i] = dv * l.mass + dw.cross(&l.h) + w.cross(&big_l);
            ws.r[i] = r;
            ws.p[i] = p;
            ws.w[i] = w;
            ws.v[i] = v;
            ws.dw[i] = dw;
            ws.dv[i] = dv;
        }
        for i in (0..n).rev() {
            let l = &self.links[i];
            tau[i] = if l.prismatic { l.axis.dot(&ws.f[i]) } else { l.axis.dot(&ws.n[i]) };
            if let Some(pi) = l.parent {
                let f = ws.r[i] * ws.f[i];
                let nn = ws.r[i] * ws.n[i] + ws.p[i].cross(&f);
                ws.f[pi] += f;
                ws.n[pi] += nn;
            }
        }
        Ok(())
    }
}
