//! The library a new installation starts with: the classes the Modelica generator knows
//! (`pipeline::back::modelica::mechatronics::known_classes`, checked by a test) and instances
//! from real datasheets. Values are written as the datasheets print them (`30.2 mNm/A`,
//! `134 g.cm2`, `6940 rpm`) and go through the same checks and unit conversions as any API input.
//!
//! Ids are fixed, so every installation has the same seed ids and an exported seed library is
//! the same file everywhere.
//!
//! Motor and gear classes also declare datasheet parameters (`T_nom`, `T_peak`, `w_max`;
//! `T_rated`, `T_peak`, `w_in_max`, `J_in`; a screw's `F_peak`) for the drive sizing. An instance
//! carries only the ones its source prints and we could verify; its `source` says which, and why
//! the others are left out. Migration 0005 brings installations seeded before them to this seed.

use serde_json::{json, Map, Value as Json};

use super::{check_class, check_instance, ClassDraft, InstanceDraft, Issue, Library, ParameterDraft};

pub const DC_MOTOR: &str = "93162c18-a028-4dbb-a9a7-c37bb6da9e15";
pub const MSL_DC_MACHINE: &str = "22a8fc74-4da7-4531-a1a0-75fb5313705d";
pub const IDEAL_GEAR: &str = "081e59da-554a-4b0c-bd5a-7f03409fb279";
pub const EFFICIENCY_GEAR: &str = "10ace2d9-1eef-4be8-b0c1-ba992d043a94";
pub const LEAD_SCREW: &str = "1d6bd1fa-9a39-47b1-86dc-e0162feea6eb";
pub const CASCADE_PPI: &str = "0f2fa95d-0f54-42fb-88f8-831a624c2754";
/// Classes added to the seed after the first one: an installation seeded before receives each
/// once (the service's `seed_new_classes`).
pub const ADDED_CLASSES: [&str; 1] = [SERVO_AMPLIFIER];

/// Datasheet parameters added to the seed's classes after the first seed (issue 27's checks and
/// ranking): an installation seeded before receives each once, in every seed class that has it.
pub const ADDED_DATASHEET: [&str; 7] = ["T_stall", "tau_th_w", "mass", "price_class", "mount", "T_avg_max", "motor_mounts"];

/// The drive amplifier class (sizing only: every parameter a datasheet value, no Modelica class).
pub const SERVO_AMPLIFIER: &str = "5b0b3c0e-3f7e-4d43-9a53-2f1f0f7c9a27";

/// Instance ids.
pub const MAXON_RE40: &str = "a204da99-dd36-4642-91d0-a61534935347";
pub const MAXON_EC45_FLAT: &str = "3cc686f6-fa23-4afb-9f9b-fe3c2b0b7a56";
pub const FAULHABER_1331: &str = "ff8d8ade-6252-45e7-9e97-204bce4f2f2d";
pub const FAULHABER_3564: &str = "ae1c622f-2892-40d8-95ef-0f7390777269";
pub const MAXON_RE40_MSL: &str = "05ea8371-f744-4b39-8683-e42bcf2a4e2a";
pub const GEAR_100: &str = "114caede-7ffb-45ea-b87d-177f3f8c80cd";
pub const MAXON_GP42C_74: &str = "7255aafb-a3a5-4ca2-83a5-e57f136ff918";
pub const BALL_SCREW_16X5: &str = "111ab6e0-9fec-4319-a1f0-7823f62e5ae4";
pub const ROBOT_R3_CONTROLLER: &str = "42d928a7-a033-47a5-8545-33f2b4153faa";

/// Catalogue instances (issue 27): every value copied from a maker's datasheet, each source names
/// the maker, the document (title and URL) and the page or table, and says for every value which
/// datasheet line it is (`R = ...`) and for every datasheet value left out why (`T_peak missing: ...`).
pub const FAULHABER_1331_006: &str = "da1dde4d-e9b1-4281-9921-d1d0b0fdf19f";
pub const FAULHABER_1331_012: &str = "950945b9-8dd7-4d7a-89bd-f9ffd9a7ea50";
pub const FAULHABER_2232_012_BX4_S: &str = "54ecc996-330c-49c3-bd20-795783a35323";
pub const FAULHABER_2232_024_BX4_S: &str = "1d2c3b37-7d3c-44a9-9545-8c0e9674fe40";
pub const FAULHABER_2232_012_BX4: &str = "3585e02d-f18d-4661-aadd-156bbfa1cd03";
pub const FAULHABER_2232_024_BX4: &str = "faafd86a-a4ab-4bab-839c-2cb26e26da09";
pub const FAULHABER_2250_024_BX4_S: &str = "fe020295-15b6-41b6-9eb1-90b054352db7";
pub const FAULHABER_2250_024_BX4: &str = "7d376960-2b76-4917-9ff3-217613970da5";

/// The catalogue instances of the seed (see above); `seed::library` holds them all.
pub const CATALOGUE: [&str; 8] = [
    FAULHABER_1331_006,
    FAULHABER_1331_012,
    FAULHABER_2232_012_BX4_S,
    FAULHABER_2232_024_BX4_S,
    FAULHABER_2232_012_BX4,
    FAULHABER_2232_024_BX4,
    FAULHABER_2250_024_BX4_S,
    FAULHABER_2250_024_BX4,
];

/// A Real parameter: (name, unit, min, max, editable, default, comment).
fn real(name: &str, unit: &str, min: Option<f64>, max: Option<f64>, editable: bool, default: Option<f64>, comment: &str) -> ParameterDraft {
    ParameterDraft {
        name: name.to_string(),
        ty: "Real".to_string(),
        unit: unit.to_string(),
        min,
        max,
        editable,
        datasheet: false,
        default: default.map(|d| json!(d)),
        comment: comment.to_string(),
    }
}

/// A nameplate value: not editable, no default, >= 0.
fn nameplate(name: &str, unit: &str, comment: &str) -> ParameterDraft {
    real(name, unit, Some(0.0), None, false, None, comment)
}

/// A datasheet value (not a Modelica parameter; read by the drive sizing): not editable, no
/// default, >= 0, optional per instance.
fn datasheet(name: &str, unit: &str, comment: &str) -> ParameterDraft {
    ParameterDraft { datasheet: true, ..nameplate(name, unit, comment) }
}

/// A datasheet text (a String the drive sizing reads, e.g. a mounting code): optional per instance.
fn datasheet_text(name: &str, comment: &str) -> ParameterDraft {
    ParameterDraft { ty: "String".to_string(), unit: String::new(), min: None, max: None, ..datasheet(name, "", comment) }
}

/// The price class where a maker or distributor gives one: 1 (cheapest) to 5.
fn price_class() -> ParameterDraft {
    ParameterDraft {
        ty: "Integer".to_string(),
        unit: "1".to_string(),
        min: Some(1.0),
        max: Some(5.0),
        ..datasheet("price_class", "1", "Price class where known: 1 (cheapest) to 5; the ranking's last criterion")
    }
}

/// The datasheet values of every motor class (`crate::sizing` reads them by these names).
fn motor_datasheet() -> [ParameterDraft; 8] {
    [
        datasheet("T_nom", "N.m", "Datasheet: nominal torque (max. continuous torque, S1)"),
        datasheet("T_peak", "N.m", "Datasheet: peak torque allowed for short times (intermittent operation)"),
        datasheet("w_max", "rad/s", "Datasheet: maximum permissible speed"),
        datasheet(
            "T_stall",
            "N.m",
            "Datasheet: stall torque at the nominal voltage (the peak limit where the maker states no short-time limit)",
        ),
        datasheet("tau_th_w", "s", "Datasheet: thermal time constant of the winding"),
        datasheet("mass", "kg", "Datasheet: motor mass (weight)"),
        price_class(),
        datasheet_text("mount", "Datasheet: the motor's mounting code, as gears name it in motor_mounts (e.g. \"maxon RE 40\")"),
    ]
}

/// The datasheet values of the rotary gear classes.
fn gear_datasheet() -> [ParameterDraft; 8] {
    [
        datasheet("T_rated", "N.m", "Datasheet: rated (max. continuous) output torque"),
        datasheet("T_peak", "N.m", "Datasheet: limit for repeated peak output torque (intermittent)"),
        datasheet("w_in_max", "rad/s", "Datasheet: maximum input speed"),
        datasheet("J_in", "kg.m2", "Datasheet: moment of inertia of the gear referred to its input (motor) shaft"),
        datasheet("T_avg_max", "N.m", "Datasheet: limit for the average output torque (Harmonic Drive's cubic mean), where given"),
        datasheet("mass", "kg", "Datasheet: gear mass (weight)"),
        price_class(),
        datasheet_text(
            "motor_mounts",
            "Datasheet: mounting codes (motor mount) of the motors this gear mounts on, separated by \";\"; empty: any motor",
        ),
    ]
}

fn class(name: &str, domain: &str, modelica_class: &str, description: &str, parameters: Vec<ParameterDraft>) -> ClassDraft {
    ClassDraft {
        name: name.to_string(),
        domain: domain.to_string(),
        modelica_class: modelica_class.to_string(),
        description: description.to_string(),
        parameters,
    }
}

/// The largest transmission ratio a gear takes (either sign): beyond any gearbox built.
const RATIO_LIMIT: f64 = 10_000.0;

fn classes() -> Vec<(&'static str, ClassDraft)> {
    let ratio = || {
        real(
            "ratio",
            "1",
            Some(-RATIO_LIMIT),
            Some(RATIO_LIMIT),
            true,
            Some(1.0),
            "Transmission ratio: motor speed / output speed (as MSL IdealGear); negative reverses; must not be 0",
        )
    };
    vec![
        (
            DC_MOTOR,
            class(
                "DC permanent-magnet motor",
                "motor",
                "cad2mo.Drives.Motors.DCPermanentMagnet",
                "Brushed (or block-commutated brushless) DC motor with permanent magnets: armature resistance and inductance, torque constant = back-EMF constant, rotor inertia and viscous friction, driven through an inner current loop with voltage and current limits. Our own class, generated into each package's Components/Drives.",
                vec![
                    nameplate("R", "Ohm", "Terminal (armature) resistance"),
                    nameplate("L", "H", "Terminal (armature) inductance"),
                    nameplate("k", "N.m/A", "Torque constant (= back-EMF constant in V.s/rad)"),
                    nameplate("J", "kg.m2", "Rotor inertia"),
                    real("d", "N.m.s/rad", Some(0.0), None, false, Some(0.0), "Viscous friction of the rotor (0 when the datasheet gives none)"),
                    nameplate("V_max", "V", "Nominal (supply) voltage: limit of the armature voltage"),
                    nameplate("I_max", "A", "Current limit: the nominal (max. continuous) current"),
                    real("Tc", "s", Some(0.0), None, true, Some(0.001), "Time constant of the inner current loop (a drive setting, not a motor value)"),
                ]
                .into_iter()
                .chain(motor_datasheet())
                .collect(),
            ),
        ),
        (
            MSL_DC_MACHINE,
            class(
                "MSL DC permanent-magnet machine",
                "motor",
                "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet",
                "The Modelica Standard Library's DC machine with permanent magnets, parametrised by its nominal operating point: the machine derives its EMF constant from (VaNominal - Ra*IaNominal)/wNominal.",
                vec![
                    nameplate("VaNominal", "V", "Nominal armature voltage"),
                    nameplate("IaNominal", "A", "Nominal armature current (> 0: motor)"),
                    nameplate("wNominal", "rad/s", "Nominal speed"),
                    nameplate("TaNominal", "K", "Nominal armature temperature"),
                    nameplate("Ra", "Ohm", "Armature resistance at TaRef"),
                    nameplate("TaRef", "K", "Reference temperature of the armature resistance"),
                    real("alpha20a", "1/K", None, None, false, Some(0.0), "Temperature coefficient of the armature resistance at 20 degC (0: no temperature dependence; copper: 3.93e-3)"),
                    nameplate("La", "H", "Armature inductance"),
                    nameplate("Jr", "kg.m2", "Rotor inertia"),
                    nameplate("Js", "kg.m2", "Stator inertia (the stator is fixed in the drive)"),
                    real("TaOperational", "K", Some(0.0), None, true, Some(293.15), "Operational armature temperature"),
                ]
                .into_iter()
                .chain(motor_datasheet())
                .collect(),
            ),
        ),
        (
            IDEAL_GEAR,
            class(
                "Ideal gear",
                "gear",
                "Modelica.Mechanics.Rotational.Components.IdealGear",
                "Lossless gear of the MSL (flange_a.phi = ratio * flange_b.phi), for revolute joints.",
                std::iter::once(ratio()).chain(gear_datasheet()).collect(),
            ),
        ),
        (
            EFFICIENCY_GEAR,
            class(
                "Gear with efficiency",
                "gear",
                "cad2mo.Drives.Gears.Efficiency",
                "Gear with a constant efficiency in both directions of power flow (MSL LossyGear with lossTable [0, eta, eta, 0, 0]), for revolute joints.",
                vec![
                    ratio(),
                    real("eta", "1", Some(0.0), Some(1.0), true, Some(1.0), "Efficiency, 0 < eta <= 1 (the generator refuses 0)"),
                ]
                .into_iter()
                .chain(gear_datasheet())
                .collect(),
            ),
        ),
        (
            LEAD_SCREW,
            class(
                "Lead screw",
                "gear",
                "cad2mo.Drives.Gears.LeadScrew",
                "Ideal gearbox and lead screw (MSL IdealGearR2T) for prismatic joints.",
                vec![
                    ratio(),
                    real("lead", "m", None, None, false, None, "Screw lead: travel per screw revolution (negative: left-hand thread; must not be 0)"),
                    datasheet("F_peak", "N", "Datasheet: maximum axial force of screw, nut and bearings"),
                    datasheet("w_in_max", "rad/s", "Datasheet: maximum input (screw or gearbox input) speed"),
                    datasheet("J_in", "kg.m2", "Datasheet: moment of inertia referred to the input (motor) shaft"),
                    datasheet("mass", "kg", "Datasheet: mass of screw, nut and bearings"),
                    price_class(),
                    datasheet_text("motor_mounts", "Datasheet: mounting codes (motor mount) of the motors this screw mounts on, separated by \";\"; empty: any motor"),
                ],
            ),
        ),
        (
            SERVO_AMPLIFIER,
            class(
                "Servo amplifier",
                "amplifier",
                "cad2mo.Sizing.ServoAmplifier",
                "A drive amplifier (servo controller, power stage) as the drive sizing sees it: its supply voltage range and its continuous and peak output current. Not a Modelica class: the sizing reads its datasheet values; the generated model's motor has its own voltage and current limits.",
                vec![
                    datasheet("U_min", "V", "Datasheet: lowest supply (DC bus) voltage"),
                    datasheet("U_max", "V", "Datasheet: highest supply (DC bus) voltage"),
                    datasheet("I_cont", "A", "Datasheet: maximum continuous output current"),
                    datasheet("I_peak", "A", "Datasheet: peak (short-time) output current"),
                    price_class(),
                ],
            ),
        ),
        (
            CASCADE_PPI,
            class(
                "Cascade P/PI controller",
                "controller",
                "cad2mo.Drives.Controllers.CascadePPI",
                "Position P loop and speed PI loop on the motor side, commanding the armature current (as the axis controller of the MSL example RobotR3).",
                vec![
                    real("kp", "1/s", Some(0.0), None, true, Some(10.0), "Gain of the position controller"),
                    real("ks", "A.s/rad", Some(0.0), None, true, Some(0.5), "Gain of the speed controller"),
                    real("Ts", "s", Some(0.0), None, true, Some(0.05), "Time constant of the speed controller's integrator"),
                ],
            ),
        ),
    ]
}

fn values(v: Json) -> Map<String, Json> {
    match v {
        Json::Object(m) => m,
        _ => Map::new(),
    }
}

/// (id, class id, name, source, values).
type SeedInstance = (&'static str, &'static str, &'static str, &'static str, Map<String, Json>);

fn instances() -> Vec<SeedInstance> {
    vec![
        (
            MAXON_RE40,
            DC_MOTOR,
            "maxon RE 40 148877 (24 V)",
            "maxon RE 40 Ø40 mm, graphite brushes, 150 W, order number 148877 (24 V winding), maxon catalog motor data, nominal values at 24 V and 25 °C: terminal resistance 0.317 Ω, terminal inductance 0.0823 mH, torque constant 30.2 mNm/A, rotor inertia 134 gcm², nominal voltage 24 V, nominal (max. continuous) current 5.77 A. d is estimated from the no-load current 137 mA at the no-load speed 7580 rpm (d = I0·k/ω0). Datasheet values for the drive sizing (same catalog): nominal torque (max. continuous torque) 170 mNm (= 30.2 mNm/A · (5.77 A - 0.137 A)), max. permissible speed 12000 rpm. maxon prints no peak torque besides the stall torque 2280 mNm at 24 V (the sizing's voltage check covers the speed-torque line), so T_peak is left empty: the peak check then uses k·I_max, the current limit of the generated drive.",
            values(json!({
                "R": {"value": 0.317, "unit": "Ohm"},
                "L": {"value": 0.0823, "unit": "mH"},
                "k": {"value": 30.2, "unit": "mNm/A"},
                "J": {"value": 134, "unit": "g.cm2"},
                "d": 5.21e-6,
                "V_max": 24,
                "I_max": 5.77,
                "Tc": 0.001,
                "T_nom": {"value": 170, "unit": "mNm"},
                "w_max": {"value": 12000, "unit": "rpm"}
            })),
        ),
        (
            MAXON_EC45_FLAT,
            DC_MOTOR,
            "maxon EC 45 flat 70 W (24 V)",
            "maxon EC 45 flat Ø43.5 mm, brushless, 70 W, 24 V winding with Hall sensors, maxon catalog motor data (values at nominal voltage): terminal resistance phase to phase 0.573 Ω, terminal inductance phase to phase 0.301 mH, torque constant 40.4 mNm/A, rotor inertia 181 gcm², nominal current 3.29 A. A block-commutated brushless motor behaves as a DC motor with the phase-to-phase values. d is estimated from the no-load current 270 mA at the no-load speed 5600 rpm. Datasheet values for the drive sizing (nominal torque, peak torque, max. speed) are not entered: not verified against the catalog.",
            values(json!({
                "R": 0.573,
                "L": {"value": 0.301, "unit": "mH"},
                "k": {"value": 40.4, "unit": "mNm/A"},
                "J": {"value": 181, "unit": "g.cm2"},
                "d": 1.86e-5,
                "V_max": 24,
                "I_max": 3.29,
                "Tc": 0.001
            })),
        ),
        (
            FAULHABER_1331,
            DC_MOTOR,
            "Faulhaber 1331 T 024 SR",
            "FAULHABER DC-Micromotor series 1331 T ... SR (precious metal commutation), type 1331 T 024 SR, data sheet values at nominal voltage 24 V: terminal resistance 52.9 Ω, rotor inductance 1100 µH, torque constant 21.8 mNm/A, rotor inertia 0.63 gcm², current up to 0.19 A (thermal limit). d is estimated from the no-load current 0.0055 A at the no-load speed 10400 rpm. Datasheet values for the drive sizing (rated torque, peak torque, max. speed) are not entered: not verified against the data sheet.",
            values(json!({
                "R": 52.9,
                "L": {"value": 1100, "unit": "uH"},
                "k": {"value": 21.8, "unit": "mNm/A"},
                "J": {"value": 0.63, "unit": "g.cm2"},
                "d": 1.1e-7,
                "V_max": 24,
                "I_max": 0.19,
                "Tc": 0.001
            })),
        ),
        (
            FAULHABER_3564,
            DC_MOTOR,
            "Faulhaber 3564 K 024 B",
            "FAULHABER Brushless DC-Servomotor series 3564 K ... B, type 3564 K 024 B, data sheet values at nominal voltage 24 V: terminal resistance phase-phase 1.2 Ω, terminal inductance phase-phase 194 µH, torque constant 20.12 mNm/A, rotor inertia 34 gcm², dynamic friction torque 2.4·10⁻⁴ mNm/rpm (d), current up to 2.50 A (thermal limit). Datasheet values for the drive sizing (rated torque, peak torque, max. speed) are not entered: not verified against the data sheet.",
            values(json!({
                "R": 1.2,
                "L": {"value": 194, "unit": "uH"},
                "k": {"value": 20.12, "unit": "mNm/A"},
                "J": {"value": 34, "unit": "g.cm2"},
                "d": {"value": 2.4e-4, "unit": "mNm/rpm"},
                "V_max": 24,
                "I_max": 2.5,
                "Tc": 0.001
            })),
        ),
        (
            MAXON_RE40_MSL,
            MSL_DC_MACHINE,
            "maxon RE 40 148877 (24 V), nominal point",
            "maxon RE 40 Ø40 mm, graphite brushes, 150 W, order number 148877 (24 V winding), maxon catalog motor data at the nominal operating point: 24 V, nominal current 5.77 A, nominal speed 6940 rpm; terminal resistance 0.317 Ω and inductance 0.0823 mH, rotor inertia 134 gcm², all at 25 °C (temperature dependence off). The MSL machine derives its EMF constant (24 - 0.317·5.77)/726.7 rad/s = 0.0305 V·s/rad from this point (datasheet torque constant 30.2 mNm/A; the difference is the no-load loss). The stator inertia is set equal to the rotor's (the stator is fixed). Datasheet values for the drive sizing (same catalog): nominal torque (max. continuous torque) 170 mNm, max. permissible speed 12000 rpm; no peak torque (maxon prints only the stall torque 2280 mNm at 24 V), so T_peak is left empty.",
            values(json!({
                "VaNominal": 24,
                "IaNominal": 5.77,
                "wNominal": {"value": 6940, "unit": "rpm"},
                "TaNominal": {"value": 25, "unit": "degC"},
                "Ra": 0.317,
                "TaRef": {"value": 25, "unit": "degC"},
                "alpha20a": 0,
                "La": {"value": 0.0823, "unit": "mH"},
                "Jr": {"value": 134, "unit": "g.cm2"},
                "Js": {"value": 134, "unit": "g.cm2"},
                "TaOperational": {"value": 25, "unit": "degC"},
                "T_nom": {"value": 170, "unit": "mNm"},
                "w_max": {"value": 12000, "unit": "rpm"}
            })),
        ),
        (
            GEAR_100,
            IDEAL_GEAR,
            "Ideal gear 100:1",
            "Reduction 100:1 as of a strain-wave gear Harmonic Drive CSF-17-100 (catalog reduction ratio 100), modelled without losses. Datasheet values for the drive sizing, Harmonic Drive CSF component set catalog, size 17, ratio 100: rated torque at 2000 rpm input 31 Nm, limit for repeated peak torque 70 Nm, maximum input speed 7300 rpm (grease lubrication), moment of inertia 0.079·10⁻⁴ kg·m² (input side). Not used: limit for average torque 51 Nm, momentary peak torque 143 Nm, limit for average input speed 3500 rpm (grease). The ratings hold for ratio 100; at other ratios they differ.",
            values(json!({
                "ratio": 100,
                "T_rated": 31,
                "T_peak": 70,
                "w_in_max": {"value": 7300, "unit": "rpm"},
                "J_in": {"value": 0.079, "unit": "kg.cm2"}
            })),
        ),
        (
            MAXON_GP42C_74,
            EFFICIENCY_GEAR,
            "maxon GP 42 C 74:1",
            "maxon planetary gearhead GP 42 C Ø42 mm, 3.0-15.0 Nm, ceramic version, 3 stages, reduction 74:1 (nominal; the catalog also lists the exact absolute reduction), max. efficiency 72 % (catalog value for 3 stages). Datasheet values for the drive sizing (same catalog, 3 stages): max. continuous torque 15 Nm, intermittently permissible torque at the gear output 22.5 Nm, max. motor shaft (input) speed 8000 rpm. The mass inertia is not entered (not verified).",
            values(json!({
                "ratio": 74,
                "eta": {"value": 72, "unit": "%"},
                "T_rated": 15,
                "T_peak": 22.5,
                "w_in_max": {"value": 8000, "unit": "rpm"}
            })),
        ),
        (
            BALL_SCREW_16X5,
            LEAD_SCREW,
            "Ball screw 16x5, direct drive",
            "Ball screw of 16 mm nominal diameter and 5 mm lead (standard size of ISO 3408, e.g. Bosch Rexroth FEM-E-S 16x5), motor coupled directly (ratio 1; set the ratio for a belt or gearbox in between). No datasheet values for the drive sizing: axial load ratings, critical speed and inertia depend on the length, nut and bearings.",
            values(json!({"ratio": 1, "lead": {"value": 5, "unit": "mm"}})),
        ),
        (
            ROBOT_R3_CONTROLLER,
            CASCADE_PPI,
            "RobotR3 axis controller",
            "Gains in the style of the axis controllers of the MSL example Modelica.Mechanics.MultiBody.Examples.Systems.RobotR3 (P position loop kp, PI speed loop ks and Ts; fullRobot uses ks = 0.5 and Ts = 0.05 s): starting values, to be tuned per drive.",
            values(json!({"kp": 10, "ks": 0.5, "Ts": 0.05})),
        ),
    ]
}

/// The seed library, checked by the same rules as any input (a failure is a bug, caught by a
/// unit test).
pub fn library() -> Result<Library, Vec<Issue>> {
    let mut lib = Library::default();
    let mut issues = Vec::new();
    for (id, draft) in classes() {
        match check_class(id, &draft) {
            Ok(c) => lib.classes.push(c),
            Err(e) => issues.extend(e.into_iter().map(|i| Issue::new(format!("seed class {}: {}", draft.name, i.field), i.message))),
        }
    }
    let all =
        instances().into_iter().map(|(id, class, name, source, values)| (id, class, name, source.to_string(), values)).chain(catalogue());
    for (id, class_id, name, source, values) in all {
        let Some(class) = lib.class(class_id) else {
            issues.push(Issue::new(format!("seed instance {name}"), format!("no seed class {class_id}")));
            continue;
        };
        let draft = InstanceDraft { name: name.to_string(), source, values };
        match check_instance(id, class, &draft) {
            Ok(i) => lib.instances.push(i),
            Err(e) => issues.extend(e.into_iter().map(|i| Issue::new(format!("seed instance {name}: {}", i.field), i.message))),
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    lib.sort();
    Ok(lib)
}

/// The FAULHABER DC-Micromotor series 1331 … SR data sheet (one page, lines 1–29).
const FAULHABER_1331_DOC: &str = "Document: FAULHABER data sheet \"DC-Micromotors, Precious Metal Commutation, 3,2 mNm, Series 1331 … SR\" (https://paperzz.com/doc/7782699/3-2-mnm-dc-micromotors), data sheet table lines 1–29.";

/// The FAULHABER manual of the 2232 … BX4 S and 2250 … BX4 S series, chapter 7 Technical Data.
const FAULHABER_BX4_DOC: &str = "FAULHABER technical manual of the Brushless DC-Servomotor series 2232 … BX4 S / 2250 … BX4 S (as published at https://manualshive.com/ru/manual/faulhaber/2232-bx4s-series/3671951), chapter 7 Technical Data";

/// (id, class id, name, source, values), the source made from the document's words.
type CatalogueInstance = (&'static str, &'static str, &'static str, String, Map<String, Json>);

/// Catalogue instances: values exactly as the datasheet prints them, with the line each one is.
fn catalogue() -> Vec<CatalogueInstance> {
    let not_peak = |stall: &str| {
        format!("T_peak missing: FAULHABER prints no short-time torque limit, only the stall torque {stall} at the nominal voltage (a point of the speed-torque line, not a permitted load), so the peak check is not evaluated.")
    };
    let sr = |winding: &str, col: &str, r: &str, l: &str, k: &str, j: &str, u: &str, i: &str, stall: &str| {
        format!(
            "FAULHABER DC-Micromotor 1331 T {winding} SR (brushed, precious metal commutation). {FAULHABER_1331_DOC} Values (column {col}): V_max = line 1 nominal voltage {u} V; R = line 2 terminal resistance {r} Ω; k = line 11 torque constant {k} mNm/A; L = line 14 rotor inductance {l} µH; J = line 16 rotor inertia {j} gcm²; w_max = line 27 speed up to 12 000 rpm; T_nom = line 28 torque up to (thermal limit, recommended continuous value) 3,2 mNm; I_max = line 29 current up to (thermal limit) {i} A. d = 0: the data sheet prints only a (Coulomb) friction torque of 0,12 mNm (line 8), no viscous coefficient, and d = 0 is the class's rule for that case. Tc = 0.001 s is the class's drive-setting default, not a motor value. {}",
            not_peak(stall)
        )
    };
    #[allow(clippy::too_many_arguments)]
    let bx4 = |name: &str,
               section: &str,
               col: &str,
               r: &str,
               l: &str,
               k: &str,
               j: &str,
               cv: &str,
               u: &str,
               i: &str,
               m: &str,
               n: &str,
               stall: &str| {
        format!(
            "FAULHABER Brushless DC-Servomotor {name} (block-commutated brushless, modelled as a DC motor with the phase-phase values). {FAULHABER_BX4_DOC}, {section}, operating data table. Values (column {col}): V_max = nominal voltage {u} V; R = terminal resistance phase-phase {r} Ω; d = friction torque, dynamic {cv} mNm/rpm; k = torque constant {k} mNm/A; L = terminal inductance phase-phase {l} µH; J = rotor inertia {j} gcm²; w_max = speed up to {n} rpm; T_nom = torque up to (recommended continuous value at 5 000 rpm, thermal resistance Rth2 not reduced) {m} mNm; I_max = current up to (same conditions) {i} A. Tc = 0.001 s is the class's drive-setting default, not a motor value. {}",
            not_peak(stall)
        )
    };
    let p40 = "7.2 \"Motor 2232 … BX4 with encoder IE3\", page 40";
    let p46 = "7.5 \"Motor 2250 … BX4 without attachment\", page 46";
    #[allow(clippy::too_many_arguments)]
    let dc = |r: f64, l: f64, k: f64, j: f64, d: Option<f64>, u: f64, i: f64, m: f64, n: f64| {
        let mut v = json!({
            "R": {"value": r, "unit": "Ohm"},
            "L": {"value": l, "unit": "uH"},
            "k": {"value": k, "unit": "mNm/A"},
            "J": {"value": j, "unit": "g.cm2"},
            "d": 0,
            "V_max": {"value": u, "unit": "V"},
            "I_max": {"value": i, "unit": "A"},
            "Tc": 0.001,
            "T_nom": {"value": m, "unit": "mNm"},
            "w_max": {"value": n, "unit": "rpm"}
        });
        if let Some(d) = d {
            v["d"] = json!({"value": d, "unit": "mNm/rpm"});
        }
        values(v)
    };
    vec![
        (
            FAULHABER_1331_006,
            DC_MOTOR,
            "Faulhaber 1331 T 006 SR",
            sr("006", "1331 T 006 SR", "2,83", "70", "5,35", "0,71", "6", "0,81", "11,20 mNm"),
            dc(2.83, 70.0, 5.35, 0.71, None, 6.0, 0.81, 3.2, 12000.0),
        ),
        (
            FAULHABER_1331_012,
            DC_MOTOR,
            "Faulhaber 1331 T 012 SR",
            sr("012", "1331 T 012 SR", "13,7", "310", "11,4", "0,67", "12", "0,37", "9,90 mNm"),
            dc(13.7, 310.0, 11.4, 0.67, None, 12.0, 0.37, 3.2, 12000.0),
        ),
        (
            FAULHABER_2232_012_BX4_S,
            DC_MOTOR,
            "Faulhaber 2232 S 012 BX4 S with encoder IE3",
            bx4(
                "2232 S 012 BX4 S with encoder IE3",
                p40,
                "2232 S 012 BX4 S",
                "3.5",
                "130",
                "8.14",
                "4.2",
                "5.5·10⁻⁵",
                "12",
                "0.99",
                "7",
                "16 700",
                "27.3 mNm",
            ),
            dc(3.5, 130.0, 8.14, 4.2, Some(5.5e-5), 12.0, 0.99, 7.0, 16700.0),
        ),
        (
            FAULHABER_2232_024_BX4_S,
            DC_MOTOR,
            "Faulhaber 2232 S 024 BX4 S with encoder IE3",
            bx4(
                "2232 S 024 BX4 S with encoder IE3",
                p40,
                "2232 S 024 BX4 S",
                "12.4",
                "470",
                "15.50",
                "4.2",
                "5.5·10⁻⁵",
                "24",
                "0.52",
                "7",
                "16 700",
                "29.4 mNm",
            ),
            dc(12.4, 470.0, 15.5, 4.2, Some(5.5e-5), 24.0, 0.52, 7.0, 16700.0),
        ),
        (
            FAULHABER_2232_012_BX4,
            DC_MOTOR,
            "Faulhaber 2232 S 012 BX4 with encoder IE3",
            bx4(
                "2232 S 012 BX4 with encoder IE3",
                p40,
                "2232 S 012 BX4",
                "3.5",
                "120",
                "16.50",
                "5.2",
                "1.5·10⁻⁴",
                "12",
                "0.95",
                "13",
                "10 500",
                "55.7 mNm",
            ),
            dc(3.5, 120.0, 16.5, 5.2, Some(1.5e-4), 12.0, 0.95, 13.0, 10500.0),
        ),
        (
            FAULHABER_2232_024_BX4,
            DC_MOTOR,
            "Faulhaber 2232 S 024 BX4 with encoder IE3",
            bx4(
                "2232 S 024 BX4 with encoder IE3",
                p40,
                "2232 S 024 BX4",
                "12.4",
                "440",
                "31.40",
                "5.2",
                "1.5·10⁻⁴",
                "24",
                "0.50",
                "13",
                "10 500",
                "59.9 mNm",
            ),
            dc(12.4, 440.0, 31.4, 5.2, Some(1.5e-4), 24.0, 0.5, 13.0, 10500.0),
        ),
        (
            FAULHABER_2250_024_BX4_S,
            DC_MOTOR,
            "Faulhaber 2250 S 024 BX4 S",
            bx4(
                "2250 S 024 BX4 S",
                p46,
                "2250 S 024 BX4 S",
                "5.9",
                "250",
                "21.1",
                "5.3",
                "1.4·10⁻⁴",
                "24",
                "0.79",
                "14",
                "12 300",
                "84,7 mNm",
            ),
            dc(5.9, 250.0, 21.1, 5.3, Some(1.4e-4), 24.0, 0.79, 14.0, 12300.0),
        ),
        (
            FAULHABER_2250_024_BX4,
            DC_MOTOR,
            "Faulhaber 2250 S 024 BX4",
            bx4("2250 S 024 BX4", p46, "2250 S 024 BX4", "5.9", "240", "36.9", "10", "2.4·10⁻⁴", "24", "0.74", "23", "9 000", "149 mNm"),
            dc(5.9, 240.0, 36.9, 10.0, Some(2.4e-4), 24.0, 0.74, 23.0, 9000.0),
        ),
    ]
}
