//! Motors and gears as the sizing sees them, read from library instances (class, instance and
//! per-drive overrides, through [`library::resolved_values`]).

use std::f64::consts::PI;

use super::{PartRef, SizingError};
use crate::library::{self, Class, Instance, Library, Value};
use crate::pipeline::back::modelica::mechatronics::JointKind;

/// The motor classes the sizing knows.
pub const DC_MOTOR_CLASS: &str = "cad2mo.Drives.Motors.DCPermanentMagnet";
pub const MSL_DC_CLASS: &str = "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet";
pub const SERVO_MOTOR_CLASS: &str = "cad2mo.Drives.Motors.ServoMotor";
/// The gear classes the sizing knows.
pub const IDEAL_GEAR_CLASS: &str = "Modelica.Mechanics.Rotational.Components.IdealGear";
pub const EFFICIENCY_GEAR_CLASS: &str = "cad2mo.Drives.Gears.Efficiency";
pub const LEAD_SCREW_CLASS: &str = "cad2mo.Drives.Gears.LeadScrew";

/// A DC motor: the electrical and mechanical model and the datasheet limits.
#[derive(Clone, Debug, PartialEq)]
pub struct Motor {
    pub part: PartRef,
    /// Armature resistance (Ω) at the operating temperature; `None` for an AC servo motor, whose
    /// datasheet gives none (its voltage and braking checks are then not evaluated).
    pub r: Option<f64>,
    /// Torque constant = back-EMF constant (N·m/A), > 0.
    pub k: f64,
    /// Rotor inertia (kg·m²).
    pub j: f64,
    /// Viscous friction of the rotor (N·m·s/rad).
    pub d: f64,
    /// Datasheet: nominal (continuous) torque, the maker's short-time (peak) torque limit, the
    /// stall torque at the nominal voltage (N·m), maximum speed (rad/s).
    pub t_nom: Option<f64>,
    pub t_peak: Option<f64>,
    pub t_stall: Option<f64>,
    pub w_max: Option<f64>,
    /// Datasheet: thermal time constant of the winding (s).
    pub tau_th_w: Option<f64>,
    /// Datasheet: mass (kg), price class (1 cheapest), mounting code.
    pub mass: Option<f64>,
    pub price_class: Option<i64>,
    pub mount: Option<String>,
    /// The instance's `source` (where its values come from).
    pub source: String,
}

/// Where the peak torque limit of a motor comes from: the same rule for every motor class.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PeakRule {
    /// The maker's short-time (peak) torque limit, `T_peak`.
    ShortTime(f64),
    /// Without one, the stall torque at the nominal voltage, `T_stall`: the most the motor
    /// delivers at that voltage.
    Stall(f64),
}

impl PeakRule {
    pub fn value(self) -> f64 {
        match self {
            PeakRule::ShortTime(x) | PeakRule::Stall(x) => x,
        }
    }

    /// The datasheet parameter the limit is.
    pub fn parameter(self) -> &'static str {
        match self {
            PeakRule::ShortTime(_) => "T_peak",
            PeakRule::Stall(_) => "T_stall",
        }
    }
}

impl Motor {
    /// The peak torque limit: the datasheet `T_peak` when given, else `T_stall`; never a
    /// current limit (`k·I_max` is the continuous current's torque).
    pub fn peak_rule(&self) -> Option<PeakRule> {
        match (self.t_peak, self.t_stall) {
            (Some(t), _) => Some(PeakRule::ShortTime(t)),
            (None, Some(t)) => Some(PeakRule::Stall(t)),
            (None, None) => None,
        }
    }
}

/// A drive amplifier: the user's supply voltage and the amplifier's datasheet currents.
#[derive(Clone, Debug, PartialEq)]
pub struct Amplifier {
    pub part: PartRef,
    /// The supply (DC bus) voltage the user sets (V); checked against `U_min`/`U_max`.
    pub u_supply: Option<f64>,
    pub u_min: Option<f64>,
    pub u_max: Option<f64>,
    /// Datasheet: continuous and peak output current (A).
    pub i_cont: Option<f64>,
    pub i_peak: Option<f64>,
    pub source: String,
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
    /// The ratio of the library instance itself; its datasheet ratings hold at this ratio only.
    pub catalog_ratio: f64,
    /// Datasheet: rated (continuous) output torque (N·m; rotary gears only).
    pub t_rated: Option<f64>,
    /// Datasheet: limit for the average output torque (N·m), where the maker gives one.
    pub t_avg_max: Option<f64>,
    /// Datasheet: repeated peak output torque (N·m), or for a screw its static axial limit (N):
    /// the basic static axial load rating `C_0a`, else a library's older `F_peak`.
    pub out_peak: Option<f64>,
    /// Screws: the basic dynamic axial load rating `C_a` (N; 10⁶ revolutions of nominal life,
    /// ISO 3408-5) and whether `out_peak` is the static rating `C_0a` (else `F_peak`).
    pub c_a: Option<f64>,
    pub out_peak_is_c0a: bool,
    /// Datasheet: maximum input speed (rad/s).
    pub w_in_max: Option<f64>,
    /// Datasheet: inertia referred to the input shaft (kg·m²); missing when not given (never 0).
    pub j_in: Option<f64>,
    /// Datasheet: mass (kg), price class, the mounting codes of the motors it mounts on.
    pub mass: Option<f64>,
    pub price_class: Option<i64>,
    pub motor_mounts: Option<Vec<String>>,
    pub source: String,
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

    /// Whether `motor` mounts on this gear: where the gear names the motors it mounts on
    /// (`motor_mounts`), only a motor whose `mount` is one of them; else any motor.
    pub fn mounts(&self, motor: &Motor) -> bool {
        match (&self.motor_mounts, &motor.mount) {
            (None, _) => true,
            (Some(list), Some(m)) => list.iter().any(|x| x.eq_ignore_ascii_case(m.trim())),
            (Some(_), None) => false,
        }
    }

    /// The name of the output limit parameter (`T_peak`; for screws `C_0a`, or a library's older
    /// `F_peak` where the instance has no `C_0a`).
    pub fn out_peak_name(&self) -> &'static str {
        match (self.lead.is_some(), self.out_peak_is_c0a || self.out_peak.is_none()) {
            (false, _) => "T_peak",
            (true, true) => "C_0a",
            (true, false) => "F_peak",
        }
    }
}

fn real(values: &[(String, Value)], name: &str) -> Option<f64> {
    values.iter().find(|(n, _)| n == name).and_then(|(_, v)| v.as_f64())
}

fn integer(values: &[(String, Value)], name: &str) -> Option<i64> {
    values.iter().find(|(n, _)| n == name).and_then(|(_, v)| match v {
        Value::Integer(i) => Some(*i),
        _ => None,
    })
}

fn text(values: &[(String, Value)], name: &str) -> Option<String> {
    values.iter().find(|(n, _)| n == name).and_then(|(_, v)| match v {
        Value::String(s) if !s.trim().is_empty() => Some(s.trim().to_string()),
        _ => None,
    })
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
pub(crate) fn convert_resistance(r: f64, t_ref: f64, alpha20: f64, t: f64) -> f64 {
    let alpha_ref = alpha20 / (1.0 + alpha20 * (t_ref - 293.15));
    r * (1.0 + alpha_ref * (t - t_ref))
}

/// A motor from a library instance with a drive's overrides (checked ones, from
/// [`library::validate_overrides`]).
pub fn motor(class: &Class, instance: &Instance, overrides: &[(String, Value)]) -> Result<Motor, SizingError> {
    let part = PartRef { id: instance.id.clone(), name: instance.name.clone() };
    let v = library::resolved_values(class, instance, overrides);
    // The electrical and mechanical constants by class (r: winding resistance, where the class
    // has one); the datasheet values are the same parameters in every motor class.
    let (r, k, j, d) = match class.modelica_class.as_str() {
        DC_MOTOR_CLASS => {
            let k = positive(&part, "k", need(&part, &v, "k")?)?;
            let r = need(&part, &v, "R")?;
            (Some(r), k, need(&part, &v, "J")?, real(&v, "d").unwrap_or(0.0))
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
            (Some(convert_resistance(ra, t_ref, alpha, t_op)), k, need(&part, &v, "Jr")?, 0.0)
        }
        SERVO_MOTOR_CLASS => (None, positive(&part, "k", need(&part, &v, "k")?)?, need(&part, &v, "J")?, 0.0),
        other => return Err(SizingError::UnknownClass { part: part.name, class: other.to_string(), slot: "motor" }),
    };
    let datasheet = |n: &str| real(&v, n);
    Ok(Motor {
        r,
        k,
        j,
        d,
        t_nom: datasheet("T_nom"),
        t_peak: datasheet("T_peak"),
        t_stall: datasheet("T_stall"),
        w_max: datasheet("w_max"),
        tau_th_w: datasheet("tau_th_w"),
        mass: datasheet("mass"),
        price_class: integer(&v, "price_class"),
        mount: text(&v, "mount"),
        source: instance.source.clone(),
        part,
    })
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
    // The catalogue's ratings, efficiency and inertia hold at the instance's own ratio: at a
    // ratio a drive overrides, they are not known (named missing, never carried over).
    let catalog_ratio =
        library::resolved_values(class, instance, &[]).iter().find(|(n, _)| n == "ratio").and_then(|(_, v)| v.as_f64()).unwrap_or(ratio);
    let rated = |name: &str| if ratio == catalog_ratio { real(&v, name) } else { None };
    // A screw's static limit: its basic static axial load rating C_0a; a library entered before
    // C_0a existed may have an F_peak instead, which stays the limit there.
    let c_0a = if lead.is_some() { rated("C_0a") } else { None };
    let out_peak = if lead.is_some() { c_0a.or_else(|| rated("F_peak")) } else { rated("T_peak") };
    let motor_mounts = text(&v, "motor_mounts")
        .map(|s| s.split(';').map(|x| x.trim().to_string()).filter(|x| !x.is_empty()).collect::<Vec<_>>())
        .filter(|l| !l.is_empty());
    Ok(Gear {
        ratio,
        catalog_ratio,
        eta,
        lead,
        ratio_editable: rp.is_some_and(|p| p.editable),
        ratio_min: rp.and_then(|p| p.min),
        ratio_max: rp.and_then(|p| p.max),
        t_rated: if lead.is_some() { None } else { rated("T_rated") },
        t_avg_max: if lead.is_some() { None } else { rated("T_avg_max") },
        out_peak,
        c_a: if lead.is_some() { rated("C_a") } else { None },
        out_peak_is_c0a: c_0a.is_some(),
        w_in_max: rated("w_in_max"),
        j_in: rated("J_in"),
        mass: real(&v, "mass"),
        price_class: integer(&v, "price_class"),
        motor_mounts,
        source: instance.source.clone(),
        part,
    })
}

/// An amplifier from a library instance, with the supply voltage the user sets.
pub fn amplifier(class: &Class, instance: &Instance, u_supply: Option<f64>) -> Result<Amplifier, SizingError> {
    let part = PartRef { id: instance.id.clone(), name: instance.name.clone() };
    if class.domain != "amplifier" {
        return Err(SizingError::UnknownClass { part: part.name, class: class.modelica_class.clone(), slot: "amplifier" });
    }
    let v = library::resolved_values(class, instance, &[]);
    Ok(Amplifier {
        u_supply,
        u_min: real(&v, "U_min"),
        u_max: real(&v, "U_max"),
        i_cont: real(&v, "I_cont"),
        i_peak: real(&v, "I_peak"),
        source: instance.source.clone(),
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
