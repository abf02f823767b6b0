//! The ball screws of the seed catalogue (issue 27): the ball-screw table of the PBSA product
//! page (a ball spline combined with a ball screw; the screw's basic dynamic and static axial
//! load ratings `Ca` and `C0a`, one row per screw size), each row its own instance.
//!
//! What the page does not print stays missing: the screw's inertia and mass (they depend on the
//! screw's length; the page gives the shaft's mass per metre) and its maximum speed.

use serde_json::json;

use super::{printed, values, NamedInstance, LEAD_SCREW};

/// The PBSA ball screws, one per row of the page's ball-screw table: sizes 16, 20, 25.
pub const PBSA_SCREWS: [&str; 3] =
    ["d05fd7ca-7c23-42bf-bfe4-18ae21da9e1a", "1de404ec-232f-4a14-a3ac-07c3bc2abf82", "7e27351b-2a38-472a-b1cf-ff31c0a8aaba"];

const URL: &str = "https://www.superslides.in/product/pbsa/";

/// One row of the page's "Ball Screw" table, every value as printed.
struct Row {
    id: &'static str,
    /// Screw size: O.D., inner diameter (the shaft is hollow) and lead, mm.
    od: &'static str,
    inner: &'static str,
    lead: &'static str,
    /// Effective turns, circuit × row.
    turns: &'static str,
    /// Basic load rating Ca and Co, kN.
    ca: &'static str,
    co: &'static str,
    /// Support bearing basic load rating Ca and Co, kN.
    bearing_ca: &'static str,
    bearing_co: &'static str,
    /// Mass: nut (kg) and shaft (kg/m).
    nut: &'static str,
    shaft: &'static str,
}

fn rows() -> [Row; 3] {
    let ids = PBSA_SCREWS;
    [
        Row {
            id: ids[0],
            od: "16",
            inner: "8",
            lead: "16",
            turns: "1.8x1",
            ca: "3.8",
            co: "6.8",
            bearing_ca: "6.74",
            bearing_co: "6.36",
            nut: "0.31",
            shaft: "1.09",
        },
        Row {
            id: ids[1],
            od: "20",
            inner: "10",
            lead: "20",
            turns: "1.8x1",
            ca: "5.9",
            co: "12.2",
            bearing_ca: "7.49",
            bearing_co: "8.16",
            nut: "0.48",
            shaft: "1.76",
        },
        Row {
            id: ids[2],
            od: "25",
            inner: "15",
            lead: "25",
            turns: "1.8x1",
            ca: "8.9",
            co: "19.1",
            bearing_ca: "9.45",
            bearing_co: "10.65",
            nut: "0.66",
            shaft: "2.33",
        },
    ]
}

/// The PBSA ball screws: (id, class id, name, source, values).
pub(super) fn catalogue() -> Vec<NamedInstance> {
    rows()
        .into_iter()
        .map(|r| {
            let source = format!(
                "Ball screw of the PBSA ball spline/ball screw unit, screw size O.D. {od} mm, inner diameter {inner} mm (hollow shaft), lead {lead} mm, effective turns {turns} (circuit × row), motor coupled directly (ratio 1: the screw's own drive; a belt or gearbox in between is another ratio). Document: Super Slides product catalog page \"PBSA\" ({URL}), table \"Ball Screw\", row {od} {inner} {lead}; the stored copy of the page names the seller, Super Slides (superslides.in), and no other manufacturer. Values: ratio = 1 (direct drive, not a catalogue value); lead = Lead {lead} mm; C_a = Basic load rating Ca {ca} kN (the basic dynamic axial load rating: 10⁶ revolutions of nominal life, ISO 3408-5); C_0a = Basic load rating Co {co} kN (the basic static axial load rating). F_peak missing: the page prints no maximum axial force; the sizing's static check uses C_0a. w_in_max missing: the page prints no permissible speed (the critical speed and the DN limit depend on the shaft's length and bearings). J_in missing: the screw's inertia depends on its length, which the page leaves to the order (the page prints the shaft's mass per metre, not its inertia); the sizing names it. Printed, without a parameter here: mass of the nut {nut} kg and of the shaft {shaft} kg/m (mass is left out: it depends on the length), support bearing basic load rating Ca {bca} kN and Co {bco} kN (the page does not say whether axial or radial), and the nut's dimensions.",
                od = r.od,
                inner = r.inner,
                lead = r.lead,
                turns = r.turns,
                ca = r.ca,
                co = r.co,
                nut = r.nut,
                shaft = r.shaft,
                bca = r.bearing_ca,
                bco = r.bearing_co,
            );
            let v = values(json!({
                "ratio": 1,
                "lead": {"value": printed(r.lead), "unit": "mm"},
                "C_a": {"value": printed(r.ca), "unit": "kN"},
                "C_0a": {"value": printed(r.co), "unit": "kN"}
            }));
            (r.id, LEAD_SCREW, format!("PBSA ball screw {}x{} (O.D. {} mm, lead {} mm)", r.od, r.lead, r.od, r.lead), source, v)
        })
        .collect()
}
