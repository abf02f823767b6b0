//! A drive of the package (its classes' paths and parameter values, as `Mechatronics.mo` gets
//! them) as the simulation's [`Drive`]: only the classes whose equations [`super`] integrates.

use crate::pipeline::back::modelica::mechatronics::{ClassChoice, JointKind, ParamValue};

use super::{field, Controller, Drive, Motor, Reference, SimulationError, Transmission};

fn real(c: &ClassChoice, name: &str, default: f64, field_prefix: &str) -> Result<f64, SimulationError> {
    match c.params.iter().find(|(n, _)| n == name).map(|(_, v)| v) {
        None => Ok(default),
        Some(ParamValue::Real(x)) => Ok(*x),
        Some(ParamValue::Integer(i)) => Ok(*i as f64),
        Some(_) => Err(field(format!("{field_prefix}.{name}"), "must be a number")),
    }
}

/// The drive of `coordinate` (of `kind`) from its three class choices; `at` prefixes the
/// field names of errors (e.g. `drives.J1`). The defaults are the classes' own.
pub fn drive_of(
    at: &str,
    coordinate: usize,
    kind: JointKind,
    motor: &ClassChoice,
    gear: &ClassChoice,
    controller: &ClassChoice,
    reference: Reference,
) -> Result<Drive, SimulationError> {
    let (pm, pg, pc) = (format!("{at}.motor"), format!("{at}.gear"), format!("{at}.controller"));
    if motor.modelica_class != "cad2mo.Drives.Motors.DCPermanentMagnet" {
        return Err(field(
            pm,
            format!("the simulation knows the motor class cad2mo.Drives.Motors.DCPermanentMagnet only, not {}", motor.modelica_class),
        ));
    }
    if controller.modelica_class != "cad2mo.Drives.Controllers.CascadePPI" {
        return Err(field(
            pc,
            format!(
                "the simulation knows the controller class cad2mo.Drives.Controllers.CascadePPI only, not {}",
                controller.modelica_class
            ),
        ));
    }
    let m = Motor {
        r: real(motor, "R", 0.299, &pm)?,
        l: real(motor, "L", 8.2e-5, &pm)?,
        k: real(motor, "k", 0.0302, &pm)?,
        j: real(motor, "J", 1.42e-5, &pm)?,
        d: real(motor, "d", 0.0, &pm)?,
        v_max: real(motor, "V_max", 24.0, &pm)?,
        i_max: real(motor, "I_max", 10.0, &pm)?,
        tc: real(motor, "Tc", 0.001, &pm)?,
    };
    let transmission = match (gear.modelica_class.as_str(), kind) {
        ("Modelica.Mechanics.Rotational.Components.IdealGear", JointKind::Revolute) => {
            Transmission { ratio: real(gear, "ratio", 1.0, &pg)?, eta: 1.0 }
        }
        ("cad2mo.Drives.Gears.Efficiency", JointKind::Revolute) => {
            Transmission { ratio: real(gear, "ratio", 1.0, &pg)?, eta: real(gear, "eta", 1.0, &pg)? }
        }
        ("cad2mo.Drives.Gears.LeadScrew", JointKind::Prismatic) => {
            let lead = real(gear, "lead", 0.005, &pg)?;
            if !(lead.is_finite() && lead != 0.0) {
                return Err(field(format!("{pg}.lead"), "must be finite and non-zero"));
            }
            Transmission { ratio: 2.0 * std::f64::consts::PI * real(gear, "ratio", 1.0, &pg)? / lead, eta: 1.0 }
        }
        (other, _) => {
            return Err(field(pg, format!("the simulation has no equations for the gear class {other} on a {kind:?} joint")));
        }
    };
    let c = Controller {
        kp: real(controller, "kp", 10.0, &pc)?,
        ks: real(controller, "ks", 0.05, &pc)?,
        ts: real(controller, "Ts", 0.05, &pc)?,
    };
    Ok(Drive { coordinate, motor: m, transmission, controller: c, reference })
}
