//! The library a new installation starts with: the classes the Modelica generator knows
//! (`pipeline::back::modelica::mechatronics::known_classes`, checked by a test) and instances
//! from real datasheets. Values are written as the datasheets print them (`30.2 mNm/A`,
//! `134 g.cm2`, `6940 rpm`) and go through the same checks and unit conversions as any API input.
//!
//! Ids are fixed, so every installation has the same seed ids and an exported seed library is
//! the same file everywhere.
//!
//! Motor and gear classes also declare datasheet parameters (`T_nom`, `T_peak`, `w_max`;
//! `T_rated`, `T_peak`, `w_in_max`, `J_in`; a screw's `C_a` and `C_0a`) for the drive sizing. An instance
//! carries only the ones its source prints and we could verify; its `source` says which, and why
//! the others are left out. Migration 0005 brings installations seeded before them to this seed.

use serde_json::{json, Map, Value as Json};

use super::{check_class, check_instance, ClassDraft, InstanceDraft, Issue, Library, ParameterDraft};

mod screws;
mod yaskawa;

pub use screws::PBSA_SCREWS;
pub use yaskawa::YASKAWA_SERVOS;

pub const DC_MOTOR: &str = "93162c18-a028-4dbb-a9a7-c37bb6da9e15";
pub const MSL_DC_MACHINE: &str = "22a8fc74-4da7-4531-a1a0-75fb5313705d";
pub const IDEAL_GEAR: &str = "081e59da-554a-4b0c-bd5a-7f03409fb279";
pub const EFFICIENCY_GEAR: &str = "10ace2d9-1eef-4be8-b0c1-ba992d043a94";
pub const LEAD_SCREW: &str = "1d6bd1fa-9a39-47b1-86dc-e0162feea6eb";
pub const CASCADE_PPI: &str = "0f2fa95d-0f54-42fb-88f8-831a624c2754";
/// Classes added to the seed after the first one: an installation seeded before receives each
/// once (the service's `seed_new_classes`).
pub const ADDED_CLASSES: [&str; 2] = [SERVO_AMPLIFIER, AC_SERVO];

/// Datasheet parameters added to the seed's classes after the first seed (issue 27's checks and
/// ranking): an installation seeded before receives each once, in every seed class that has it.
pub const ADDED_DATASHEET: [&str; 10] =
    ["T_stall", "tau_th_w", "mass", "price_class", "mount", "T_avg_max", "motor_mounts", "backlash", "C_a", "C_0a"];

/// The drive amplifier class (sizing only: every parameter a datasheet value, no Modelica class).
pub const SERVO_AMPLIFIER: &str = "5b0b3c0e-3f7e-4d43-9a53-2f1f0f7c9a27";

/// The AC servo motor class (permanent-magnet synchronous motor under field-oriented current
/// control, as servo makers rate it: torque constant per A rms, no winding resistance).
pub const AC_SERVO: &str = "f54cddfa-bad3-4e78-9dfb-88462b8458a2";

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

/// The FAULHABER catalogue motors.
pub const FAULHABER_MOTORS: [&str; 8] = [
    FAULHABER_1331_006,
    FAULHABER_1331_012,
    FAULHABER_2232_012_BX4_S,
    FAULHABER_2232_024_BX4_S,
    FAULHABER_2232_012_BX4,
    FAULHABER_2232_024_BX4,
    FAULHABER_2250_024_BX4_S,
    FAULHABER_2250_024_BX4,
];

/// The Beckhoff catalogue gear units, one per ratio (see [`gear_pages`] for which is which).
pub const BECKHOFF_GEARS: [&str; 60] = [
    "03812aa0-626d-4ec4-98bd-71c1e47137c7",
    "6bff9ebd-9c4a-4c4b-b234-050687cdd658",
    "1eb690b1-17e6-4582-a04b-b17a09ddf74d",
    "49fdf49d-1a6b-4463-badd-af6362ec7288",
    "67613915-8a54-48a9-b641-a26c46234aa3",
    "1f0765fe-aa88-43b0-af47-9778999716d5",
    "1e83b19c-5b44-4f3a-981d-168936dd9dc5",
    "41c3d2d9-73e4-4e19-8657-1dedde8cee2f",
    "a49d4f39-19f0-4aa3-9f88-8c4730b84732",
    "22025ec6-1ea2-4b0f-b248-c621a9f16e0e",
    "40f1e6b6-f642-4b45-8830-2573b4737ea1",
    "436a6855-e261-4894-959a-e4385ab633c1",
    "2b47afb8-5ac6-4f52-9eb7-d3ad3c3e500c",
    "773e658b-1d6c-4d96-b28e-7728862156e3",
    "064ae630-3966-4140-b07e-e5ca98193e53",
    "4ecdf98f-7e78-4822-834e-b29b42a11f55",
    "2100c7ee-2e02-45f7-921f-2c3d58116d7d",
    "5877c27c-9da5-4753-837c-074a471d02f6",
    "b215eb3f-310c-4367-a012-e00a3f8dbb21",
    "63ffed98-aa95-4536-82ce-8380fc287d32",
    "97cbfc11-e855-4fb1-9e1e-a1c7e7eb312b",
    "14c82607-842e-4b1c-a265-4025d8e772a5",
    "f3ed1e70-b7bc-429f-b2be-1a021c4cac08",
    "abc3bd0b-b982-45a7-ba00-c74ec4f50a95",
    "6afda997-d464-4578-927b-52ec4755e1d7",
    "23750000-6ad9-4312-a631-aa6e5667442d",
    "1dd1d18e-81ee-427d-8542-e857a719b1e1",
    "558b6ea5-4670-4597-aed6-979f050e7f91",
    "7f9db8e2-2a02-49b4-b6a0-5562bc50c622",
    "44801b01-e2e8-478e-8b34-5d7e5e6c559d",
    "563b73a5-bb75-40d0-997d-69192c4ab422",
    "c7fc1662-154f-4bde-bb13-96b667dd1443",
    "cbba194a-3938-4bc1-8404-3114f4d98c3f",
    "7742759d-28c7-4593-9853-269037650903",
    "d18406e3-2663-4083-8067-4ed21e43f69d",
    "2c2fdc60-dbfb-4a68-b59e-8680f11453cc",
    "4c0b3faf-df75-4506-9afc-23b936b86347",
    "4463a131-b551-45d5-9496-4e65917d870b",
    "69c26ec0-abc0-42f1-9233-5150ed6c77d1",
    "b35f4b5a-2b5f-4c4f-b54e-59ebb01fc0e6",
    "ca20b6d8-7d50-4346-aa73-c096ac7a880f",
    "14b325c6-3cb9-4274-8139-4602abee7512",
    "c0433e94-d4d1-4c94-b915-e2dc2fbf668c",
    "7c7552a7-531d-4037-b190-f8a8d824b311",
    "3f9dba31-3a03-4b62-9ab7-92adfeb88bf3",
    "ac2c9d80-ce39-4e8b-838b-4ef68d97d4ac",
    "f2655fac-804a-498f-ad0e-6beb846fad31",
    "00deb50b-6881-46d1-8eaa-703f0f94e6d1",
    "14ce9152-8a95-4cab-98e9-8949677d99fa",
    "1f88cccb-4286-4d16-86c2-afa9dfcd1720",
    "845e2528-3a6b-40bc-8e01-bf314617ae44",
    "7de9bb09-daac-497e-bc16-5732da8ac59c",
    "b1829783-d332-422d-83e7-a59690fee6dc",
    "11c5108b-d9c1-4738-9879-3feec0413259",
    "2c6b7403-f8ff-446e-9757-3c794b6a730d",
    "6a835606-5c82-49b1-9166-cef557a0288e",
    "74758d41-0f6e-459b-a017-176cc251fc80",
    "04dbba19-c4f2-47e5-97f4-13614c2b8861",
    "61e7144b-7def-40c2-b796-0018587a4ff2",
    "ec427b59-3ca9-4ba4-a3b5-9ca6189dfde0",
];

/// The maxon catalogue motors: EC 45 flat 30 W (12, 24, 36 V) and EC 45 flat 70 W (36, 48, 60 V).
pub const MAXON_EC45_FLAT_MOTORS: [&str; 6] = [
    "2d92b77d-262f-443b-beaa-f2561563bc3f",
    "59013709-bdad-43e9-b8bc-c5b1169419cc",
    "e9bd32e0-e445-4f7f-a2a2-bffd3eb020fa",
    "a1b3f114-64b3-4919-bf15-ac51818261e5",
    "12d8bee7-de2d-4a10-a4ef-24b121b08d2e",
    "c8e0ff26-f568-402a-b244-dfae326a950a",
];

/// The catalogue instances of the seed (see above); `seed::library` holds them all.
pub const CATALOGUE: [&str; 107] = concat::<104, 3, 107>(
    concat::<74, 30, 104>(concat::<14, 60, 74>(concat(FAULHABER_MOTORS, MAXON_EC45_FLAT_MOTORS), BECKHOFF_GEARS), YASKAWA_SERVOS),
    PBSA_SCREWS,
);

/// `a` then `b`, in a constant.
const fn concat<const A: usize, const B: usize, const C: usize>(a: [&'static str; A], b: [&'static str; B]) -> [&'static str; C] {
    assert!(A + B == C, "the lengths add up");
    let mut out = [""; C];
    let mut i = 0;
    while i < A {
        out[i] = a[i];
        i += 1;
    }
    let mut j = 0;
    while j < B {
        out[A + j] = b[j];
        j += 1;
    }
    out
}

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
fn gear_datasheet() -> [ParameterDraft; 9] {
    [
        datasheet("T_rated", "N.m", "Datasheet: rated (max. continuous) output torque"),
        datasheet("T_peak", "N.m", "Datasheet: limit for repeated peak output torque (intermittent)"),
        datasheet("w_in_max", "rad/s", "Datasheet: maximum input speed"),
        datasheet("J_in", "kg.m2", "Datasheet: moment of inertia of the gear referred to its input (motor) shaft"),
        datasheet("backlash", "rad", "Datasheet: maximum torsional backlash at the output (standard version)"),
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
            AC_SERVO,
            class(
                "AC servo motor",
                "motor",
                "cad2mo.Drives.Motors.ServoMotor",
                "Permanent-magnet AC servo motor (synchronous motor) with its servo amplifier's field-oriented current control, as servo makers rate it: torque = torque constant × RMS phase current, the current following the command with a time constant and limited to the maximum current. Servo datasheets print no winding resistance for the drive, so the motor voltage is not modelled. Our own class, generated into each package's Components/Drives.",
                vec![
                    nameplate("k", "N.m/A", "Torque constant (per A rms of the phase current)"),
                    nameplate("J", "kg.m2", "Motor (rotor) moment of inertia, with the holding brake where the motor has one"),
                    nameplate("I_max", "A", "Current limit: the maximum (instantaneous) current, A rms"),
                    real("Tc", "s", Some(0.0), None, true, Some(0.001), "Time constant of the current loop (a drive setting, not a motor value)"),
                ]
                .into_iter()
                .chain([
                    datasheet("w_nom", "rad/s", "Datasheet: rated speed"),
                    datasheet("I_nom", "A", "Datasheet: rated current, A rms"),
                    datasheet("P_nom", "W", "Datasheet: rated output"),
                    datasheet("U_class", "V", "Datasheet: voltage class (supply voltage, AC)"),
                ])
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
                    // Superseded by C_0a; kept (with migration 0005's comment) so that libraries that
                    // have F_peak values keep them: the static check's limit where there is no C_0a.
                    datasheet("F_peak", "N", "Datasheet: maximum axial force of screw, nut and bearings"),
                    datasheet("w_in_max", "rad/s", "Datasheet: maximum input (screw or gearbox input) speed"),
                    datasheet("J_in", "kg.m2", "Datasheet: moment of inertia referred to the input (motor) shaft"),
                    datasheet("mass", "kg", "Datasheet: mass of screw, nut and bearings"),
                    price_class(),
                    // Added after the first seed (ADDED_DATASHEET), in the order an installation seeded
                    // before receives them (after mass and price_class, before motor_mounts).
                    datasheet(
                        "C_a",
                        "N",
                        "Datasheet: basic dynamic axial load rating Ca of the screw and nut (ISO 3408-5: 10^6 revolutions of nominal life L10)",
                    ),
                    datasheet("C_0a", "N", "Datasheet: basic static axial load rating C0a of the screw and nut (ISO 3408-5)"),
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
            "maxon RE 40 Ø40 mm, graphite brushes, 150 W, order number 148877 (24 V winding), maxon catalog motor data, nominal values at 24 V and 25 °C: terminal resistance 0.317 Ω, terminal inductance 0.0823 mH, torque constant 30.2 mNm/A, rotor inertia 134 gcm², nominal voltage 24 V, nominal (max. continuous) current 5.77 A. d is estimated from the no-load current 137 mA at the no-load speed 7580 rpm (d = I0·k/ω0). Datasheet values for the drive sizing (same catalog): nominal torque (max. continuous torque) 170 mNm (= 30.2 mNm/A · (5.77 A - 0.137 A)), max. permissible speed 12000 rpm. T_peak and T_stall missing: maxon prints no short-time torque limit, and the catalog's stall torque (2280 mNm at 24 V) is not entered here because this first-seed entry's page was not checked again; without either the sizing's peak check is not evaluated and names motor.T_peak or motor.T_stall as missing (never k·I_max, the continuous current's torque, which is only the generated drive's current limit).",
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
            "Reduction 100:1 as of a strain-wave gear Harmonic Drive CSF-17-100 (catalog reduction ratio 100), modelled without losses. Datasheet values for the drive sizing as the first seed gave them from the Harmonic Drive CSF component set catalog, size 17 (values of the size, the same at every ratio; not checked again against a page): maximum input speed 7300 rpm (grease lubrication), moment of inertia 0.079·10⁻⁴ kg·m² (input side). T_rated and T_peak missing: the first seed entered 31 Nm rated torque and 70 Nm repeated peak torque (51 Nm average, 143 Nm momentary peak) as this size and ratio's, but a public transcription of Harmonic Drive's CSF-17-100-2UH product page prints other ratings (24 Nm rated, 54 Nm repeated peak, 108 Nm momentary peak) and no maker's page at hand settles which are right, so neither is entered; the gear's torque checks are then not evaluated and name gear.T_rated and gear.T_peak as missing.",
            values(json!({
                "ratio": 100,
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
    let all = instances().into_iter().map(|(id, class, name, source, values)| (id, class, name.to_string(), source.to_string(), values));
    let all = all
        .chain(catalogue().into_iter().map(|(id, class, name, source, values)| (id, class, name.to_string(), source, values)))
        .chain(maxon_catalogue())
        .chain(gear_catalogue())
        .chain(yaskawa::catalogue())
        .chain(screws::catalogue());
    for (id, class_id, name, source, values) in all {
        let Some(class) = lib.class(class_id) else {
            issues.push(Issue::new(format!("seed instance {name}"), format!("no seed class {class_id}")));
            continue;
        };
        let draft = InstanceDraft { name: name.clone(), source, values };
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

/// (id, class id, name, source, values) with a name made from the document's words.
type NamedInstance = (&'static str, &'static str, String, String, Map<String, Json>);

/// (id, class id, name, source, values), the source made from the document's words.
type CatalogueInstance = (&'static str, &'static str, &'static str, String, Map<String, Json>);

/// Catalogue instances: values exactly as the datasheet prints them, with the line each one is.
fn catalogue() -> Vec<CatalogueInstance> {
    let not_peak = |stall: &str| {
        format!("T_peak missing: FAULHABER prints no short-time torque limit. T_stall = stall torque {stall} at the nominal voltage (a point of the speed-torque line: the most the motor delivers at that voltage), the peak check's limit where the maker gives no short-time limit.")
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
    let dc = |r: f64, l: f64, k: f64, j: f64, d: Option<f64>, u: f64, i: f64, m: f64, n: f64, stall: f64| {
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
            "w_max": {"value": n, "unit": "rpm"},
            "T_stall": {"value": stall, "unit": "mNm"}
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
            dc(2.83, 70.0, 5.35, 0.71, None, 6.0, 0.81, 3.2, 12000.0, 11.2),
        ),
        (
            FAULHABER_1331_012,
            DC_MOTOR,
            "Faulhaber 1331 T 012 SR",
            sr("012", "1331 T 012 SR", "13,7", "310", "11,4", "0,67", "12", "0,37", "9,90 mNm"),
            dc(13.7, 310.0, 11.4, 0.67, None, 12.0, 0.37, 3.2, 12000.0, 9.9),
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
            dc(3.5, 130.0, 8.14, 4.2, Some(5.5e-5), 12.0, 0.99, 7.0, 16700.0, 27.3),
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
            dc(12.4, 470.0, 15.5, 4.2, Some(5.5e-5), 24.0, 0.52, 7.0, 16700.0, 29.4),
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
            dc(3.5, 120.0, 16.5, 5.2, Some(1.5e-4), 12.0, 0.95, 13.0, 10500.0, 55.7),
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
            dc(12.4, 440.0, 31.4, 5.2, Some(1.5e-4), 24.0, 0.5, 13.0, 10500.0, 59.9),
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
            dc(5.9, 250.0, 21.1, 5.3, Some(1.4e-4), 24.0, 0.79, 14.0, 12300.0, 84.7),
        ),
        (
            FAULHABER_2250_024_BX4,
            DC_MOTOR,
            "Faulhaber 2250 S 024 BX4",
            bx4("2250 S 024 BX4", p46, "2250 S 024 BX4", "5.9", "240", "36.9", "10", "2.4·10⁻⁴", "24", "0.74", "23", "9 000", "149 mNm"),
            dc(5.9, 240.0, 36.9, 10.0, Some(2.4e-4), 24.0, 0.74, 23.0, 9000.0, 149.0),
        ),
    ]
}

/// One page of Beckhoff's Information System with the "Mechanical data" table of a 1-stage gear
/// unit: one column per ratio, every value as the page prints it (merged cells repeated per column).
struct GearPage {
    /// The operating instructions the page belongs to (`AG2400`, ...).
    family: &'static str,
    series: &'static str,
    url: &'static str,
    /// Efficiency under full load, %.
    eta: &'static str,
    /// Weight, kg.
    weight: &'static str,
    /// The clamping hub whose mass moment of inertia row is entered (the page lists several).
    hub: &'static str,
    /// Maximum torsional backlash of the standard version, arcmin (and of the reduced version).
    backlash: &'static str,
    reduced: Option<&'static str>,
    /// Maximum input speed n1Max, min⁻¹.
    n1_max: &'static str,
    ratio: &'static [&'static str],
    /// Maximum torque T2a, nominal output torque T2N, maximum acceleration torque T2B, EMERGENCY
    /// STOP torque, all Nm; nominal input speed n1N, min⁻¹; J1 of the `hub` row, kgcm².
    t2a: &'static [&'static str],
    t2n: &'static [&'static str],
    t2b: &'static [&'static str],
    emergency: &'static [&'static str],
    n1n: &'static [&'static str],
    j1: &'static [&'static str],
    ids: &'static [&'static str],
    /// The 2-stage columns, when the page has both 1- and 2-stage ones.
    second: Option<SecondStage>,
}

/// The 2-stage columns of a page (from column `from` on) and the values the page prints for
/// them instead of the 1-stage ones.
struct SecondStage {
    from: usize,
    eta: &'static str,
    n1_max: &'static str,
    backlash: &'static str,
    weight: &'static str,
    /// How the page tells the stages apart.
    how: &'static str,
}

/// The Beckhoff gear unit pages the catalogue takes its gears from (each column checked against
/// the page by eye; the table's column order is the ratio row's).
fn gear_pages() -> Vec<GearPage> {
    vec![
        GearPage {
            family: "AG2400",
            series: "TP004 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag2400_ba/8995082251.html",
            eta: "97",
            weight: "1.4",
            hub: "C = 14 mm",
            backlash: "4",
            reduced: Some("2"),
            n1_max: "7500",
            ratio: &["4", "5", "7", "8", "10"],
            t2a: &["83", "83", "83", "56", "56"],
            t2n: &["27", "27", "26", "26", "27"],
            t2b: &["66", "66", "66", "42", "42"],
            emergency: &["100", "100", "100", "100", "100"],
            n1n: &["3300", "3300", "4000", "4000", "4000"],
            j1: &["0.25", "0.21", "0.18", "0.18", "0.17"],
            second: None,
            ids: &BECKHOFF_GEARS[0..5],
        },
        GearPage {
            family: "AG2400",
            series: "TP010 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag2400_ba/8995369483.html",
            eta: "97",
            weight: "3.8",
            hub: "E = 19 mm",
            backlash: "3",
            reduced: Some("1"),
            n1_max: "7500",
            ratio: &["4", "5", "7", "8", "10"],
            t2a: &["185", "210", "210", "168", "168"],
            t2n: &["84", "81", "81", "80", "81"],
            t2b: &["172", "172", "172", "126", "126"],
            emergency: &["250", "250", "251", "251", "251"],
            n1n: &["2600", "2900", "3100", "3100", "3100"],
            j1: &["0.95", "0.79", "0.64", "0.64", "0.57"],
            second: None,
            ids: &BECKHOFF_GEARS[5..10],
        },
        GearPage {
            family: "AG2400",
            series: "TP050 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag2400_ba/8995561355.html",
            eta: "97",
            weight: "14",
            hub: "K = 38 mm",
            backlash: "3",
            reduced: Some("1"),
            n1_max: "5000",
            ratio: &["4", "5", "7", "8", "10"],
            t2a: &["992", "992", "868", "720", "720"],
            t2n: &["345", "337", "322", "316", "331"],
            t2b: &["840", "840", "840", "648", "648"],
            emergency: &["1250", "1250", "1250", "1250", "1250"],
            n1n: &["1900", "2000", "2500", "2500", "2500"],
            j1: &["13.7", "12.1", "10.6", "10.6", "9.78"],
            second: None,
            ids: &BECKHOFF_GEARS[10..15],
        },
        GearPage {
            family: "AG3300",
            series: "NPS015 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3300_ba/8881782411.html",
            eta: "97",
            weight: "1.8",
            hub: "C = 14 mm",
            backlash: "8",
            reduced: None,
            n1_max: "8000",
            ratio: &["3", "4", "5", "7", "8", "10"],
            t2a: &["51", "56", "64", "64", "56", "56"],
            t2n: &["17", "18", "21", "21", "19", "19"],
            t2b: &["32", "35", "40", "40", "35", "35"],
            emergency: &["80", "80", "80", "80", "80", "80"],
            n1n: &["2900", "3100", "3300", "3600", "3600", "3800"],
            j1: &["0.34", "0.28", "0.26", "0.24", "0.23", "0.23"],
            second: None,
            ids: &BECKHOFF_GEARS[15..21],
        },
        GearPage {
            family: "AG3400",
            series: "NPT005 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3400_ba/9187662731.html",
            eta: "97",
            weight: "0.9",
            hub: "B = 11 mm",
            backlash: "10",
            reduced: None,
            n1_max: "10000",
            ratio: &["4", "5", "7", "8", "10"],
            t2a: &["18", "22", "22", "21", "21"],
            t2n: &["5.1", "6.5", "6.5", "6", "6"],
            t2b: &["11", "14", "14", "13", "13"],
            emergency: &["26", "26", "26", "26", "26"],
            n1n: &["3800", "4000", "4300", "4400", "4600"],
            j1: &["0.06", "0.05", "0.05", "0.04", "0.04"],
            second: None,
            ids: &BECKHOFF_GEARS[21..26],
        },
        GearPage {
            family: "AG3400",
            series: "NPT025 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3400_ba/9187803147.html",
            eta: "97",
            weight: "4.4",
            hub: "E = 19 mm",
            backlash: "8",
            reduced: None,
            n1_max: "7000",
            ratio: &["3", "4", "5", "7", "8", "10"],
            t2a: &["128", "152", "160", "160", "144", "144"],
            t2n: &["40", "48", "50", "50", "45", "45"],
            t2b: &["80", "95", "100", "100", "90", "90"],
            emergency: &["190", "190", "190", "190", "190", "190"],
            n1n: &["3100", "3300", "3400", "3600", "3700", "3900"],
            j1: &["0.99", "0.8", "0.67", "0.56", "0.53", "0.5"],
            second: None,
            ids: &BECKHOFF_GEARS[26..32],
        },
        GearPage {
            family: "AG3400",
            series: "NPT035 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3400_ba/9197685643.html",
            eta: "97",
            weight: "9.4",
            hub: "G = 24 mm",
            backlash: "8",
            reduced: None,
            n1_max: "6000",
            ratio: &["3", "4", "5", "7", "8", "10"],
            t2a: &["320", "365", "365", "365", "352", "352"],
            t2n: &["102", "130", "125", "125", "110", "110"],
            t2b: &["200", "255", "250", "250", "220", "220"],
            emergency: &["480", "480", "480", "480", "480", "480"],
            n1n: &["2300", "2500", "2600", "2800", "2900", "3000"],
            j1: &["4", "2.8", "2.4", "1.9", "1.8", "1.7"],
            second: None,
            ids: &BECKHOFF_GEARS[32..38],
        },
        GearPage {
            family: "AG3300",
            series: "NPS045 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3300_ba/8882147979.html",
            eta: "97",
            weight: "19",
            hub: "K = 38 mm",
            backlash: "8",
            reduced: None,
            n1_max: "4000",
            ratio: &["5", "8", "10", "25", "32", "50", "64", "100"],
            t2a: &[],
            t2n: &["350", "200", "200", "350", "200", "350", "200", "200"],
            t2b: &["500", "400", "400", "500", "400", "500", "400", "400"],
            emergency: &["1000", "1000", "1000", "1000", "1000", "1000", "1000", "1000"],
            n1n: &["1800", "1900", "2000", "2600", "2500", "3000", "2900", "3000"],
            j1: &["8.7", "7.3", "7.2", "7", "6.9", "6.8", "6.6", "6.5"],
            second: Some(SecondStage {
                from: 3,
                eta: "95",
                n1_max: "6000",
                backlash: "10",
                weight: "19",
                how: "the page heads its columns 1-stage and 2-stage and prints the maximum input speed per column, 4000 min⁻¹ for ratios 5, 8, 10 and 6000 min⁻¹ for ratios 25 to 100, so ratios 5, 8, 10 are the 1-stage columns; the page prints no maximum torque T2a row",
            }),
            ids: &BECKHOFF_GEARS[38..46],
        },
        GearPage {
            family: "AG3400",
            series: "NPT045 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3400_ba/9187952779.html",
            eta: "97",
            weight: "19",
            hub: "K = 38 mm",
            backlash: "8",
            reduced: None,
            n1_max: "4000",
            ratio: &["5", "8", "10", "25", "32", "50", "64", "100"],
            t2a: &["700", "640", "640", "700", "640", "700", "640", "640"],
            t2n: &["350", "200", "350", "200", "350", "200", "200", "200"],
            t2b: &["500", "400", "400", "500", "400", "500", "400", "400"],
            emergency: &["1000", "1000", "1000", "1000", "1000", "1000", "1000", "1000"],
            n1n: &["2000", "2200", "2300", "2600", "2500", "3000", "2900", "3000"],
            j1: &["9.8", "7.8", "7.4", "7", "6.9", "6.8", "6.6", "6.5"],
            second: Some(SecondStage {
                from: 3,
                eta: "95",
                n1_max: "6000",
                backlash: "10",
                weight: "20",
                how: "the page heads its columns 1-stage and 2-stage and prints one value per stage for efficiency, weight, maximum input speed and backlash; ratios 5, 8, 10 are the 1-stage columns, the only ones whose J1 rows for the clamping hubs E to I print no value",
            }),
            ids: &BECKHOFF_GEARS[46..54],
        },
        GearPage {
            family: "AG3400",
            series: "NPT015 MF",
            url: "https://infosys.beckhoff.com/content/1033/ag3400_ba/9187734283.html",
            eta: "97",
            weight: "2",
            hub: "C = 14 mm",
            backlash: "8",
            reduced: None,
            n1_max: "8000",
            ratio: &["3", "4", "5", "7", "8", "10"],
            t2a: &["51", "56", "60", "60", "56", "56"],
            t2n: &["17", "18", "21", "21", "19", "19"],
            t2b: &["32", "35", "40", "40", "35", "35"],
            emergency: &["75", "75", "75", "75", "75", "75"],
            n1n: &["3300", "3500", "3700", "4000", "4100", "4300"],
            j1: &["0.41", "0.32", "0.28", "0.25", "0.24", "0.23"],
            second: None,
            ids: &BECKHOFF_GEARS[54..60],
        },
    ]
}

/// A printed number (a typo in the table above is a NaN, which the seed's own check refuses).
fn printed(x: &str) -> f64 {
    x.parse().unwrap_or(f64::NAN)
}

/// The Beckhoff gear units, one instance per ratio column of each page: (id, class id, name,
/// source, values).
fn gear_catalogue() -> Vec<NamedInstance> {
    let mut out = Vec::new();
    for p in gear_pages() {
        for (c, id) in p.ids.iter().enumerate() {
            let (r, t2n, t2b, es, n1n, j1) = (p.ratio[c], p.t2n[c], p.t2b[c], p.emergency[c], p.n1n[c], p.j1[c]);
            let (stage, eta, n1_max, backlash, weight, how) = match &p.second {
                Some(s) if c >= s.from => ("2-stage", s.eta, s.n1_max, s.backlash, s.weight, format!(" (2-stage: {})", s.how)),
                Some(s) => ("1-stage", p.eta, p.n1_max, p.backlash, p.weight, format!(" (1-stage: {})", s.how)),
                None => ("1-stage", p.eta, p.n1_max, p.backlash, p.weight, String::new()),
            };
            let t2a = p.t2a.get(c).map(|t| format!("maximum torque T2a {t} Nm, ")).unwrap_or_default();
            let reduced = p.reduced.map(|x| format!(", reduced version ≤ {x} arcmin")).unwrap_or_default();
            let source = format!(
                "Beckhoff gear unit {series}, {stage}, ratio {r}, with clamping hub {hub}. Document: Beckhoff Information System, operating instructions {family} ({url}), page \"{series}\", table \"Mechanical data\", column ratio {r}{how}. Values: ratio = Ratio {r}; eta = Efficiency under full load η {eta} %; T_rated = Nominal output torque T2N at n1N {t2n} Nm; T_peak = Maximum acceleration torque T2B (maximum 1000 cycles per hour) {t2b} Nm, the page's limit for cyclic (repeated) peaks; w_in_max = Maximum input speed n1Max {n1max} min⁻¹ (in rad/s by ω = 2π·n/60); J_in = Mass moment of inertia J1 based on the drive, clamping hub {hub}: {j1} kgcm² (the page lists other hubs too); backlash = Maximum torsional backlash jt, standard version, ≤ {backlash} arcmin (an upper limit{reduced}); mass = Weight {weight} kg (the page: depending on the clamping hub diameter and selected adapter plate). Printed, without a parameter here: {t2a}EMERGENCY STOP torque {es} Nm (1000 times during the service life of the gear unit), nominal input speed n1N {n1n} min⁻¹, idle torque T012, torsional rigidity Ct21.",
                series = p.series,
                hub = p.hub,
                family = p.family,
                url = p.url,
                n1max = n1_max,
            );
            let values = values(json!({
                "ratio": printed(r),
                "eta": {"value": printed(eta), "unit": "%"},
                "T_rated": {"value": printed(t2n), "unit": "N.m"},
                "T_peak": {"value": printed(t2b), "unit": "N.m"},
                "w_in_max": {"value": printed(n1_max), "unit": "rpm"},
                "J_in": {"value": printed(j1), "unit": "kg.cm2"},
                "backlash": {"value": printed(backlash), "unit": "arcmin"},
                "mass": {"value": printed(weight), "unit": "kg"}
            }));
            let name = format!("Beckhoff {} i={r}, clamping hub {}", p.series, p.hub);
            out.push((*id, EFFICIENCY_GEAR, name, source, values));
        }
    }
    out
}

/// One winding (column) of a maxon motor data table, every value as printed.
struct MaxonColumn {
    id: &'static str,
    /// Line 1 nominal voltage, V.
    u: &'static str,
    /// Line 5 nominal torque, mNm; line 6 nominal current, A; line 7 stall torque, mNm.
    t_nom: &'static str,
    i_nom: &'static str,
    stall: &'static str,
    /// Lines 10-12: terminal resistance and inductance phase to phase (Ω, mH), torque constant (mNm/A).
    r: &'static str,
    l: &'static str,
    k: &'static str,
    /// Line 15 mechanical time constant, ms (printed; the column check R·J/k² uses it).
    tau_m: &'static str,
}

/// The maxon EC 45 flat motors: the catalogue page of each, its columns, and what it lacks.
fn maxon_catalogue() -> Vec<NamedInstance> {
    let ids = MAXON_EC45_FLAT_MOTORS;
    let w30 = [
        MaxonColumn { id: ids[0], u: "12", t_nom: "55.5", i_nom: "2.03", stall: "241", r: "1.2", l: "0.56", k: "25.5", tau_m: "17.1" },
        MaxonColumn { id: ids[1], u: "24", t_nom: "55.3", i_nom: "1.01", stall: "239", r: "4.83", l: "2.24", k: "51", tau_m: "17.2" },
        MaxonColumn { id: ids[2], u: "36", t_nom: "66.6", i_nom: "0.849", stall: "337", r: "6.69", l: "4.29", k: "70.6", tau_m: "12.4" },
    ];
    let w70 = [
        MaxonColumn { id: ids[3], u: "36", t_nom: "110", i_nom: "1.97", stall: "1320", r: "1.560", l: "0.601", k: "57", tau_m: "8.680" },
        MaxonColumn { id: ids[4], u: "48", t_nom: "112", i_nom: "1.41", stall: "1260", r: "3.070", l: "1.210", k: "80.8", tau_m: "8.510" },
        MaxonColumn { id: ids[5], u: "60", t_nom: "143", i_nom: "0.92", stall: "1240", r: "7.370", l: "4.270", k: "152", tau_m: "5.770" },
    ];
    let mut out = Vec::new();
    #[allow(clippy::too_many_arguments)]
    let mut push = |c: &MaxonColumn, title: &str, doc: &str, j: &str, w_max: &str, thermal: &str, tau_w: &str, column: &str| {
        let source = format!(
            "maxon {title}, {u} V winding (block-commutated brushless, modelled as a DC motor with the phase-to-phase values). {doc} Values ({column}): V_max = line 1 nominal voltage {u} V; R = line 10 terminal resistance phase to phase {r} Ω; L = line 11 terminal inductance phase to phase {l} mH; k = line 12 torque constant {k} mNm/A; J = line 16 rotor inertia {j} gcm²; I_max = line 6 nominal current (max. continuous current) {i} A; T_nom = line 5 nominal torque (max. continuous torque) {t} mNm; {w_max} The column's own consistency: R·J/k² = line 15 mechanical time constant {tau} ms. d = 0: the page prints no viscous friction coefficient, and d = 0 is the class's rule for that case. Tc = 0.001 s is the class's drive-setting default, not a motor value. T_peak missing: maxon prints no short-time torque limit, only that the motor may be briefly overloaded (recurring) without a figure. T_stall = line 7 stall torque {stall} mNm (a point of the speed-torque line at nominal voltage: the most the motor delivers at that voltage), the peak check's limit where the maker gives no short-time limit. tau_th_w = line 19 thermal time constant winding {tau_w} s (the sizing's thermal check). Printed, without a parameter here: {thermal}.",
            u = c.u,
            r = c.r,
            l = c.l,
            k = c.k,
            i = c.i_nom,
            t = c.t_nom,
            tau = c.tau_m,
            stall = c.stall,
        );
        let mut v = json!({
            "R": {"value": printed(c.r), "unit": "Ohm"},
            "L": {"value": printed(c.l), "unit": "mH"},
            "k": {"value": printed(c.k), "unit": "mNm/A"},
            "J": {"value": printed(j), "unit": "g.cm2"},
            "d": 0,
            "V_max": {"value": printed(c.u), "unit": "V"},
            "I_max": {"value": printed(c.i_nom), "unit": "A"},
            "Tc": 0.001,
            "T_nom": {"value": printed(c.t_nom), "unit": "mNm"},
            "T_stall": {"value": printed(c.stall), "unit": "mNm"},
            "tau_th_w": {"value": printed(tau_w), "unit": "s"}
        });
        if w_max.starts_with("w_max = ") {
            v["w_max"] = json!({"value": 10000, "unit": "rpm"});
        }
        out.push((c.id, DC_MOTOR, format!("maxon {title}, {} V", c.u), source, values(v)));
    };
    let doc30 = "Document: maxon catalogue page \"EC 45 flat Ø42.9 mm, brushless, 30 Watt\" (maxon EC motor, May 2012 edition, catalogue page 193), motor data table, values at nominal voltage, as published at https://vdocuments.us/ec-45-flat-429-mm-brushless-30-generator-30wpdf-ec-45-flat-429-mm-brushless.html (the stored copy prints lines 1-16 as rows of six columns: two columns per nominal voltage 12, 12, 24, 24, 36, 36 V; this instance is the first column of its voltage's pair, and which of the page's two variants, with Hall sensors or sensorless, that column is the stored copy does not say).";
    let thermal30 = "thermal resistances housing-ambient 5.7 K/W and winding-housing 3.96 K/W (lines 17, 18), thermal time constant motor 251 s (line 20)";
    let no_w30 =
        "w_max missing: line 23 (max. permissible speed) is cut off in the stored copy of the page, so the speed check is not evaluated.";
    for (c, col) in w30.iter().zip(["column 1", "column 3", "column 5"]) {
        push(c, "EC 45 flat Ø42.9 mm, 30 W", doc30, "92.5", no_w30, thermal30, "11.5", col);
    }
    let doc70 = "Document: maxon catalogue page \"EC 45 flat Ø43.5 mm, brushless, 70 watt\", Motor Data (provisional), values at nominal voltage 24, 36, 48, 60 V, as published in the online flipbook https://online.flippingbook.com/view/1042987/324 (page 324). The stored copy prints the table one winding at a time without line labels; each winding's numbers were matched to the lines by the page's own relations (line 13 speed constant × line 1 nominal voltage ≈ line 2 no load speed, nominal voltage / line 10 terminal resistance ≈ line 8 stall current, R·J/k² = line 15), and its 24 V column agrees with the first seed's EC 45 flat 70 W (24 V).";
    let thermal70 = "thermal resistances 2.55 K/W and 6.64 K/W (lines 17, 18), thermal time constant motor 127 s (line 20)";
    let w70_max = "w_max = line 23 max. speed 10 000 rpm.";
    for c in &w70 {
        let col = format!("{} V winding", c.u);
        push(c, "EC 45 flat Ø43.5 mm, 70 W", doc70, "181", w70_max, thermal70, "43.1", &col);
    }
    out
}
