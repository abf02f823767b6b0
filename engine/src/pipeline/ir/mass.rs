//! A body's mass properties in its `CS1` frame: what the Modelica back end emits (`m`, `r_CM`,
//! `I_11..I_32`) and what every other consumer (MJCF, `mechanism`) must use, computed in one place.

use nalgebra::{Matrix3, Vector3};

use super::{BodyId, Model};

/// Mass, centre of gravity and inertia of one body, resolved in its CS1 frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// kg.
    pub mass: f64,
    /// Centre of gravity in CS1 coordinates, m.
    pub r_cm: Vector3<f64>,
    /// Inertia about the centre of gravity in CS1 axes, kg·m², symmetrised (`(I + Iᵀ)/2`).
    pub inertia: Matrix3<f64>,
}

impl Model {
    /// The mass properties of body `b` in its CS1 frame (the CAD inertia is given in CG axes).
    pub fn mass_properties_cs1(&self, b: BodyId) -> MassProperties {
        let body = self.body(b);
        let cs1 = self.frame(body.cs1).pose;
        let cg = self.frame(body.cg).pose;
        let r_cm = cs1.rotation.inverse() * (cg.translation.vector - cs1.translation.vector);
        let rc = cs1.rotation.to_rotation_matrix().into_inner();
        let rg = cg.rotation.to_rotation_matrix().into_inner();
        let sym = (body.inertia_cg + body.inertia_cg.transpose()) * 0.5;
        let inertia = rc.transpose() * rg * sym * rg.transpose() * rc;
        MassProperties { mass: body.mass, r_cm, inertia }
    }
}
