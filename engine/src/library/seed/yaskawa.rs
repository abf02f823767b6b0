//! The Yaskawa Σ-7 AC servo motors of the seed catalogue (issue 27): the ratings tables of the
//! rotary servomotor product manual, one column per motor, each motor once without and once
//! with its holding brake (the table prints the moment of inertia of both).

use serde_json::json;

use super::{printed, values, NamedInstance, AC_SERVO};

/// The Yaskawa servomotors, two per table column: without holding brake, then with it
/// (see [`tables`] for which is which).
pub const YASKAWA_SERVOS: [&str; 30] = [
    "955da737-a8a0-40e5-b52e-39248e90f375",
    "3e29ebac-3921-4828-9faf-86b854a1958d",
    "e6335759-5918-4cfb-8c4c-b0a113d69923",
    "6735ef9b-54be-4ca1-bc1f-bb10af876fd6",
    "477ac963-8512-424f-9214-4950804f8446",
    "5607597a-166c-4045-bb0e-0962458d8fdc",
    "47be0ce0-65a4-4aa1-baf9-ffb59343da80",
    "f11bf07e-6191-4f97-8cb8-26fe847efcbc",
    "c2bfb2e5-192f-4b6d-bf8a-0ef0df40d761",
    "248fbbd7-69c5-45c9-bb2e-ee93248560bf",
    "5de6bc5f-bc75-4047-a0f1-bdf51052cd59",
    "c66db67b-f40e-4a00-95cd-101ac048b9a9",
    "63b82073-a276-4722-ba01-51af9e4f7168",
    "30063005-6527-453f-9522-e8da74063370",
    "6ee71d7c-7a1c-4195-8e2e-ee33e61d2950",
    "cab63e14-291b-401e-b115-712ccd5201c7",
    "e469cbc8-f163-4219-831c-f95c1f1a3be1",
    "c4b57fa4-4205-4040-a96d-46ceff66a1a8",
    "efca9dd6-424c-4fe5-bb2a-2faaa148ce98",
    "eb8bd98b-34f7-4d2f-b52d-ae67e2492e86",
    "ca64e7f4-a118-4f16-bb61-b348e72db913",
    "31051bea-11bc-41b5-a333-236683982f2b",
    "723d5a31-6fc1-44dc-b35b-1e7e326fdd91",
    "54d254c3-e495-4ea3-88a4-87b20dbe8171",
    "7c3eb8fa-1712-44cd-ac29-f3aaeee4eb7e",
    "7aa96c93-2edc-4ff7-8ebf-78d6aa947555",
    "08824dc6-6e9d-4007-b2cc-4297f27500e1",
    "dca9b5ba-8300-4aec-90bf-ded607f96eb6",
    "ba4da3d6-51cc-40f5-89f2-03fa8ce0dc92",
    "39ac5962-7947-44a3-b126-c128b275ca48",
];

/// One ratings table of the manual, columns as printed (every row one value per column).
struct Table {
    series: &'static str,
    /// Section, title and page of the table in the manual, and where the stored copy is.
    section: &'static str,
    url: &'static str,
    /// Model suffixes (`01A`), rated output (W), rated torque and instantaneous maximum torque
    /// (N·m), rated current and instantaneous maximum current (Arms), torque constant
    /// (N·m/Arms), motor moment of inertia without and with holding brake (×10⁻⁴ kg·m²).
    model: &'static [&'static str],
    output_w: &'static [&'static str],
    output_printed: &'static [&'static str],
    t_rated: &'static [&'static str],
    t_max: &'static [&'static str],
    i_rated: &'static [&'static str],
    i_max: &'static [&'static str],
    k: &'static [&'static str],
    j: &'static [&'static str],
    j_brake: &'static [&'static str],
    /// Rated motor speed (min⁻¹), one value for the whole table.
    n_rated: &'static str,
    /// Maximum motor speed (min⁻¹), or why it is left out.
    n_max: Result<&'static str, &'static str>,
    ids: &'static [&'static str],
}

/// The manual the tables come from.
const DOC: &str = "Document: Yaskawa \"Σ-7-Series AC Servo Drive, Rotary Servomotor Product Manual\" (manual no. SIEP S800001 36), as published page by page at";

fn tables() -> Vec<Table> {
    vec![
        Table {
            series: "SGM7J",
            section: "section 4.2.2 \"Ratings of Servomotors without Gears\", page 4-4, table for the 200 V class (column 50 W, SGM7J-A5A, left out: below 100 W)",
            url: "https://manualshive.com/ru/manual/yaskawa/sgmmv/sgmmv_product-manual_907516-55.html",
            model: &["01A", "C2A", "02A", "04A", "06A", "08A"],
            output_w: &["100", "150", "200", "400", "600", "750"],
            output_printed: &["100 W", "150 W", "200 W", "400 W", "600 W", "750 W"],
            t_rated: &["0.318", "0.477", "0.637", "1.27", "1.91", "2.39"],
            t_max: &["1.11", "1.67", "2.23", "4.46", "6.69", "8.36"],
            i_rated: &["0.85", "1.6", "1.6", "2.5", "4.2", "4.4"],
            i_max: &["3.1", "5.7", "5.8", "9.3", "15.3", "16.9"],
            k: &["0.413", "0.321", "0.444", "0.544", "0.493", "0.584"],
            j: &["0.0659", "0.0915", "0.263", "0.486", "0.800", "1.59"],
            j_brake: &["0.0739", "0.0995", "0.333", "0.556", "0.870", "1.77"],
            n_rated: "3000",
            n_max: Ok("6000"),
            ids: &YASKAWA_SERVOS[0..12],
        },
        Table {
            series: "SGM7A",
            section: "section 5.2.4 \"Ratings of Servomotors without Gears for the SGM7A-15 to -70\", page 5-7, 200 V (columns 4.0 to 7.0 kW left out: above 3 kW)",
            url: "https://manualshive.com/en/manual/yaskawa/sgmmv/907516?page=82",
            model: &["15A", "20A", "25A", "30A"],
            output_w: &["1500", "2000", "2500", "3000"],
            output_printed: &["1.5 kW", "2.0 kW", "2.5 kW", "3.0 kW"],
            t_rated: &["4.90", "6.36", "7.96", "9.80"],
            t_max: &["14.7", "19.1", "23.9", "29.4"],
            i_rated: &["9.3", "12.1", "15.6", "17.9"],
            i_max: &["28", "42", "51", "56"],
            k: &["0.590", "0.561", "0.538", "0.582"],
            j: &["2.00", "2.47", "3.19", "7.00"],
            j_brake: &["2.25", "2.72", "3.44", "9.20"],
            n_rated: "3000",
            n_max: Err(
                "w_max missing: the table prints the maximum motor speed 6000 min⁻¹ with footnote *9, whose text (on the page of notes the table refers to) is not in the stored copy, so the speed check is not evaluated rather than run against a limit that may not hold for these motors.",
            ),
            ids: &YASKAWA_SERVOS[12..20],
        },
        Table {
            series: "SGM7G",
            section: "section 7.2.2 \"Servomotor Ratings of the SGM7G-03 to -20\", page 7-4, 200 V (the values in parentheses are for servomotors with holding brakes)",
            url: "https://manualshive.com/ru/manual/yaskawa/sgmmv/907516?page=134",
            model: &["03A", "05A", "09A", "13A", "20A"],
            output_w: &["300", "450", "850", "1300", "1800"],
            output_printed: &["0.3 kW", "0.45 kW", "0.85 kW", "1.3 kW", "1.8 kW"],
            t_rated: &["1.96", "2.86", "5.39", "8.34", "11.5"],
            t_max: &["5.88", "8.92", "14.2", "23.3", "28.7"],
            i_rated: &["2.8", "3.8", "6.9", "10.7", "16.7"],
            i_max: &["8.0", "11", "17", "28", "42"],
            k: &["0.776", "0.854", "0.859", "0.891", "0.748"],
            j: &["2.48", "3.33", "13.9", "19.9", "26.0"],
            j_brake: &["2.73", "3.58", "16.0", "22.0", "28.1"],
            n_rated: "1500",
            n_max: Ok("3000"),
            ids: &YASKAWA_SERVOS[20..30],
        },
    ]
}

/// The Yaskawa AC servo motors: (id, class id, name, source, values).
pub(super) fn catalogue() -> Vec<NamedInstance> {
    let mut out = Vec::new();
    for t in tables() {
        for c in 0..t.model.len() {
            for (b, brake) in [false, true].into_iter().enumerate() {
                let id = t.ids[2 * c + b];
                let (j, j_row, variant) = if brake {
                    (t.j_brake[c], "row \"Motor Moment of Inertia, With Holding Brake\"", "with holding brake")
                } else {
                    (t.j[c], "row \"Motor Moment of Inertia\" (without holding brake)", "without holding brake")
                };
                let model = format!("{}-{}", t.series, t.model[c]);
                let w_max = match t.n_max {
                    Ok(n) => format!("w_max = Maximum Motor Speed {n} min⁻¹;"),
                    Err(why) => why.to_string(),
                };
                let source = format!(
                    "Yaskawa Σ-7 rotary servomotor {model}, {variant} (permanent-magnet AC servo motor, 200 V class, without gears). {DOC} {url}, {section}, column {model}. Values: P_nom = Rated Output {output}; T_nom = Rated Torque {tr} N·m; T_peak = Instantaneous Maximum Torque {tm} N·m; I_nom = Rated Current {ir} Arms; I_max = Instantaneous Maximum Current {im} Arms (the current limit of the generated drive); w_nom = Rated Motor Speed {nr} min⁻¹; {w_max} k = Torque Constant {k} N·m/Arms; J = {j_row} {j} ×10⁻⁴ kg·m²; U_class = Voltage 200 V. The table's values hold with a SERVOPACK at an armature winding temperature of 100 °C (other items at 20 °C), typical values. Tc = 0.001 s is the class's drive-setting default, not a motor value. mass missing: the ratings table prints no mass. tau_th_w and T_stall missing: the table prints no thermal time constant and no stall torque (T_peak is the maker's short-time limit).",
                    url = t.url,
                    section = t.section,
                    output = t.output_printed[c],
                    tr = t.t_rated[c],
                    tm = t.t_max[c],
                    ir = t.i_rated[c],
                    im = t.i_max[c],
                    nr = t.n_rated,
                    k = t.k[c],
                );
                let mut v = json!({
                    "k": {"value": printed(t.k[c]), "unit": "N.m/A"},
                    "J": {"value": printed(j), "unit": "kg.cm2"},
                    "I_max": {"value": printed(t.i_max[c]), "unit": "A"},
                    "Tc": 0.001,
                    "T_nom": {"value": printed(t.t_rated[c]), "unit": "N.m"},
                    "T_peak": {"value": printed(t.t_max[c]), "unit": "N.m"},
                    "w_nom": {"value": printed(t.n_rated), "unit": "rpm"},
                    "I_nom": {"value": printed(t.i_rated[c]), "unit": "A"},
                    "P_nom": {"value": printed(t.output_w[c]), "unit": "W"},
                    "U_class": {"value": 200, "unit": "V"}
                });
                if let Ok(n) = t.n_max {
                    v["w_max"] = json!({"value": printed(n), "unit": "rpm"});
                }
                out.push((id, AC_SERVO, format!("Yaskawa {model} ({variant})"), source, values(v)));
            }
        }
    }
    out
}
