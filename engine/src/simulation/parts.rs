//! A drive of the package (its classes' paths and parameter values, as `Mechatronics.mo` gets
//! them) as the simulation's [`Drive`]: only the classes whose equations [`super`] integrates.

use crate::pipeline::back::modelica::mechatronics::{ClassChoice, JointKind, ParamValue};

use crate::sizing::parts::{convert_resistance, MSL_DC_CLASS, SERVO_MOTOR_CLASS};

use super::{field, Controller, Drive, Motor, MotorKind, Reference, SimulationError, Transmission};

const DC_PERMANENT_MAGNET: &str = "cad2mo.Drives.Motors.DCPermanentMagnet";

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
    if controller.modelica_class != "cad2mo.Drives.Controllers.CascadePPI" {
        return Err(field(
            pc,
            format!(
                "the simulation knows the controller class cad2mo.Drives.Controllers.CascadePPI only, not {}",
                controller.modelica_class
            ),
        ));
    }
    // The defaults are the classes' own (`mechatronics.rs`'s parameter tables).
    let m = match motor.modelica_class.as_str() {
        DC_PERMANENT_MAGNET => Motor {
            kind: MotorKind::DcPermanentMagnet,
            r: real(motor, "R", 0.299, &pm)?,
            l: real(motor, "L", 8.2e-5, &pm)?,
            k: real(motor, "k", 0.0302, &pm)?,
            j: real(motor, "J", 1.42e-5, &pm)?,
            d: real(motor, "d", 0.0, &pm)?,
            v_max: real(motor, "V_max", 24.0, &pm)?,
            i_max: real(motor, "I_max", 10.0, &pm)?,
            tc: real(motor, "Tc", 0.001, &pm)?,
        },
        // `Motors.MSL_DC_PermanentMagnet`: the MSL machine with the class's (and MSL's) zero brush,
        // core, stray-load and friction losses is the DC motor above with R = Ra at TaOperational,
        // L = La, k = psi = (VaNominal - Ra(TaNominal)*IaNominal)/wNominal (MSL's turnsRatio with
        // its unit excitation flux), J = Jr (the stator is fixed), d = 0; the wrapper's current
        // loop and limits (V_max = VaNominal, I_max = IaNominal, Tc = 0.001) are the same.
        MSL_DC_CLASS => {
            let va = real(motor, "VaNominal", 100.0, &pm)?;
            let ia = real(motor, "IaNominal", 100.0, &pm)?;
            let w_nominal = real(motor, "wNominal", 1425.0 * std::f64::consts::PI / 30.0, &pm)?;
            let t_ref = real(motor, "TaRef", 293.15, &pm)?;
            let t_nominal = real(motor, "TaNominal", 293.15, &pm)?;
            let ra = real(motor, "Ra", 0.05, &pm)?;
            let alpha = real(motor, "alpha20a", 0.0, &pm)?;
            if !(w_nominal.is_finite() && w_nominal > 0.0) {
                return Err(field(format!("{pm}.wNominal"), format!("must be positive, got {w_nominal}")));
            }
            let psi = (va - convert_resistance(ra, t_ref, alpha, t_nominal) * ia) / w_nominal;
            if !(psi.is_finite() && psi > 0.0) {
                return Err(field(
                    format!("{pm}.VaNominal"),
                    format!("the machine's EMF constant (VaNominal - Ra(TaNominal)*IaNominal)/wNominal is {psi}: it must be positive"),
                ));
            }
            Motor {
                kind: MotorKind::MslDcPermanentMagnet,
                r: convert_resistance(ra, t_ref, alpha, real(motor, "TaOperational", 293.15, &pm)?),
                l: real(motor, "La", 0.0015, &pm)?,
                k: psi,
                j: real(motor, "Jr", 0.15, &pm)?,
                d: 0.0,
                v_max: real(motor, "V_max", va, &pm)?,
                i_max: real(motor, "I_max", ia, &pm)?,
                tc: real(motor, "Tc", 0.001, &pm)?,
            }
        }
        // `Motors.ServoMotor`: `Tc*der(i) = i_cmd - i`, `tau = k*i`, `J*der(w) = tau + flange.tau`.
        SERVO_MOTOR_CLASS => Motor {
            kind: MotorKind::Servo,
            r: 0.0,
            l: 0.0,
            k: real(motor, "k", 0.544, &pm)?,
            j: real(motor, "J", 4.86e-5, &pm)?,
            d: 0.0,
            v_max: 0.0,
            i_max: real(motor, "I_max", 9.3, &pm)?,
            tc: real(motor, "Tc", 0.001, &pm)?,
        },
        other => {
            return Err(field(
                pm,
                format!(
                "the simulation knows the motor classes {DC_PERMANENT_MAGNET}, {MSL_DC_CLASS} and {SERVO_MOTOR_CLASS} only, not {other}"
            ),
            ))
        }
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
