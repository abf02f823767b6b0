//! Motors and gears as the sizing sees them, read from library instances (class, instance and
//! per-drive overrides, through [`library::resolved_values`]).

use std::f64::consts::PI;

use super::{PartRef, SizingError};
use crate::library::{self, Class, Instance, Library, Value};
use crate::pipeline::back::modelica::mechatronics::JointKind;

/// The motor classes the sizing knows.
pub const DC_MOTOR_CLASS: &str = "cad2mo.Drives.Motors.DCPermanentMagnet";
pub const MSL_DC_CLASS: &str = "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet";
/// The gear classes the sizing knows.
pub const IDEAL_GEAR_CLASS: &str = "Modelica.Mechanics.Rotational.Components.IdealGear";
pub const EFFICIENCY_GEAR_CLASS: &str = "cad2mo.Drives.Gears.Efficiency";
pub const LEAD_SCREW_CLASS: &str = "cad2mo.Drives.Gears.LeadScrew";

/// A DC motor: the electrical and mechanical model and the datasheet limits.
#[derive(Clone, Debug, PartialEq)]
pub struct Motor {
    pub part: PartRef,
    /// Armature resistance (Ω) at the operating temperature.
    pub r: f64,
    /// Torque constant = back-EMF constant (N·m/A), > 0.
    pub k: f64,
    /// Rotor inertia (kg·m²).
    pub j: f64,
    /// Viscous friction of the rotor (N·m·s/rad).
    pub d: f64,
    /// Supply voltage limit (V).
    pub v_max: Option<f64>,
    /// Current limit of the generated drive (A): `DCPermanentMagnet.I_max`.
    pub i_max: Option<f64>,
    /// Datasheet: nominal (continuous) torque, peak torque (N·m), maximum speed (rad/s).
    pub t_nom: Option<f64>,
    pub t_peak: Option<f64>,
    pub w_max: Option<f64>,
}

/// Where the peak torque limit of a motor comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PeakRule {
    /// The datasheet's `T_peak`.
    Datasheet(f64),
    /// `k·I_max`: the most the generated drive's current loop lets the motor deliver.
    CurrentLimit(f64),
}

impl PeakRule {
    pub fn value(self) -> f64 {
        match self {
            PeakRule::Datasheet(x) | PeakRule::CurrentLimit(x) => x,
        }
    }
}

impl Motor {
    /// The peak torque limit: the datasheet `T_peak` when given, else `k·I_max` (our DC class).
    pub fn peak_rule(&self) -> Option<PeakRule> {
        match (self.t_peak, self.i_max) {
            (Some(t), _) => Some(PeakRule::Datasheet(t)),
            (None, Some(i)) => Some(PeakRule::CurrentLimit(self.k * i)),
            (None, None) => None,
        }
    }

    /// No-load speed at the supply voltage, `V_max / k` (rad/s).
    pub fn no_load_speed(&self) -> Option<f64> {
        self.v_max.map(|v| v / self.k)
    }
}

/// A transmission between motor and joint: a rotary gear (revolute joints) or a lead screw
/// behind an optional gear (prismatic joints).
#[derive(Clone, Debug, PartialEq)]
pub struct Gear {
    pub part: PartRef,
    /// Motor speed / output speed (as MSL `IdealGear`); not 0.
    pub ratio: f64,
    /// Efficiency in both directions of power flow, 0 < eta <= 1.
    pub eta: f64,
    /// Screw lead (m per screw revolution), for prismatic joints; not 0.
    pub lead: Option<f64>,
    /// Whether a drive may override the ratio, and its limits.
    pub ratio_editable: bool,
    pub ratio_min: Option<f64>,
    pub ratio_max: Option<f64>,
    /// Datasheet: rated (continuous) output torque (N·m; rotary gears only).
    pub t_rated: Option<f64>,
    /// Datasheet: repeated peak output torque (N·m), or for a screw its axial force limit (N).
    pub out_peak: Option<f64>,
    /// Datasheet: maximum input speed (rad/s).
    pub w_in_max: Option<f64>,
    /// Datasheet: inertia referred to the input shaft (kg·m²); 0 when not given.
    pub j_in: Option<f64>,
}

impl Gear {
    /// The joint kind the gear fits.
    pub fn fits(&self) -> JointKind {
        if self.lead.is_some() {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        }
    }

    /// Motor speed per joint speed: `ratio` (rad/rad), or `ratio·2π/lead` (rad/m) for a screw.
    pub fn transmission(&self, ratio: f64) -> f64 {
        match self.lead {
            Some(lead) => ratio * 2.0 * PI / lead,
            None => ratio,
        }
    }

    /// The name of the output limit parameter (`T_peak` or, for screws, `F_peak`).
    pub fn out_peak_name(&self) -> &'static str {
        if self.lead.is_some() {
            "F_peak"
        } else {
            "T_peak"
        }
    }
}

fn real(values: &[(String, Value)], name: &str) -> Option<f64> {
    values.iter().find(|(n, _)| n == name).and_then(|(_, v)| v.as_f64())
}

fn need(part: &PartRef, values: &[(String, Value)], name: &str) -> Result<f64, SizingError> {
    real(values, name).ok_or_else(|| SizingError::BadPart { part: part.name.clone(), reason: format!("{name} has no value") })
}

fn positive(part: &PartRef, name: &str, x: f64) -> Result<f64, SizingError> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(SizingError::BadPart { part: part.name.clone(), reason: format!("{name} = {x} must be greater than 0") })
    }
}

/// MSL `Machines.Thermal.convertResistance`: `R` given at `t_ref` with the temperature
/// coefficient `alpha20` at 20 °C, at temperature `t` (K).
fn convert_resistance(r: f64, t_ref: f64, alpha20: f64, t: f64) -> f64 {
    let alpha_ref = alpha20 / (1.0 + alpha20 * (t_ref - 293.15));
    r * (1.0 + alpha_ref * (t - t_ref))
}

/// A motor from a library instance with a drive's overrides (checked ones, from
/// [`library::validate_overrides`]).
pub fn motor(class: &Class, instance: &Instance, overrides: &[(String, Value)]) -> Result<Motor, SizingError> {
    let part = PartRef { id: instance.id.clone(), name: instance.name.clone() };
    let v = library::resolved_values(class, instance, overrides);
    let datasheet = |n: &str| real(&v, n);
    match class.modelica_class.as_str() {
        DC_MOTOR_CLASS => {
            let k = positive(&part, "k", need(&part, &v, "k")?)?;
            Ok(Motor {
                r: need(&part, &v, "R")?,
                k,
                j: need(&part, &v, "J")?,
                d: real(&v, "d").unwrap_or(0.0),
                v_max: real(&v, "V_max"),
                i_max: real(&v, "I_max"),
                t_nom: datasheet("T_nom"),
                t_peak: datasheet("T_peak"),
                w_max: datasheet("w_max"),
                part,
            })
        }
        MSL_DC_CLASS => {
            // As the MSL machine: the EMF constant from the nominal point,
            // (VaNominal - Ra(TaNominal)·IaNominal) / wNominal (no brush, core or friction losses).
            let va = need(&part, &v, "VaNominal")?;
            let ia = need(&part, &v, "IaNominal")?;
            let w = positive(&part, "wNominal", need(&part, &v, "wNominal")?)?;
            let ra = need(&part, &v, "Ra")?;
            let t_ref = need(&part, &v, "TaRef")?;
            let alpha = real(&v, "alpha20a").unwrap_or(0.0);
            let t_nominal = real(&v, "TaNominal").unwrap_or(t_ref);
            let t_op = real(&v, "TaOperational").unwrap_or(t_nominal);
            let k = (va - convert_resistance(ra, t_ref, alpha, t_nominal) * ia) / w;
            let k = positive(&part, "the EMF constant (VaNominal - Ra·IaNominal)/wNominal", k)?;
            Ok(Motor {
                r: convert_resistance(ra, t_ref, alpha, t_op),
                k,
                j: need(&part, &v, "Jr")?,
                d: 0.0,
                v_max: Some(va),
                i_max: None,
                t_nom: datasheet("T_nom"),
                t_peak: datasheet("T_peak"),
                w_max: datasheet("w_max"),
                part,
            })
        }
        other => Err(SizingError::UnknownClass { part: part.name, class: other.to_string(), slot: "motor" }),
    }
}

/// A gear from a library instance with a drive's overrides.
pub fn gear(class: &Class, instance: &Instance, overrides: &[(String, Value)]) -> Result<Gear, SizingError> {
    let part = PartRef { id: instance.id.clone(), name: instance.name.clone() };
    let v = library::resolved_values(class, instance, overrides);
    let (eta, lead) = match class.modelica_class.as_str() {
        IDEAL_GEAR_CLASS => (1.0, None),
        EFFICIENCY_GEAR_CLASS => (need(&part, &v, "eta")?, None),
        LEAD_SCREW_CLASS => (1.0, Some(need(&part, &v, "lead")?)),
        other => return Err(SizingError::UnknownClass { part: part.name, class: other.to_string(), slot: "gear" }),
    };
    let eta = positive(&part, "eta", eta)?;
    if eta > 1.0 {
        return Err(SizingError::BadPart { part: part.name, reason: format!("eta = {eta} is above 1") });
    }
    let ratio = need(&part, &v, "ratio")?;
    if ratio == 0.0 || !ratio.is_finite() {
        return Err(SizingError::BadPart { part: part.name, reason: "ratio must not be 0".to_string() });
    }
    if lead.is_some_and(|l| l == 0.0 || !l.is_finite()) {
        return Err(SizingError::BadPart { part: part.name, reason: "lead must not be 0".to_string() });
    }
    let rp = class.parameter("ratio");
    let out_peak = if lead.is_some() { real(&v, "F_peak") } else { real(&v, "T_peak") };
    Ok(Gear {
        ratio,
        eta,
        lead,
        ratio_editable: rp.is_some_and(|p| p.editable),
        ratio_min: rp.and_then(|p| p.min),
        ratio_max: rp.and_then(|p| p.max),
        t_rated: if lead.is_some() { None } else { real(&v, "T_rated") },
        out_peak,
        w_in_max: real(&v, "w_in_max"),
        j_in: real(&v, "J_in"),
        part,
    })
}

/// Every motor and gear of a library the sizing can use, and the instances it cannot (with
/// the reason), for ranking alternatives.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Catalog {
    pub motors: Vec<Motor>,
    pub gears: Vec<Gear>,
    /// Motor and gear instances left out: "name: reason".
    pub skipped: Vec<String>,
}

impl Catalog {
    /// The library's motor and gear instances with their own values (no overrides).
    pub fn from_library(lib: &Library) -> Catalog {
        let mut cat = Catalog::default();
        for inst in &lib.instances {
            let Some(class) = lib.class(&inst.class_id) else { continue };
            match class.domain.as_str() {
                "motor" => match motor(class, inst, &[]) {
                    Ok(m) => cat.motors.push(m),
                    Err(e) => cat.skipped.push(e.to_string()),
                },
                "gear" => match gear(class, inst, &[]) {
                    Ok(g) => cat.gears.push(g),
                    Err(e) => cat.skipped.push(e.to_string()),
                },
                _ => {}
            }
        }
        cat
    }
}
