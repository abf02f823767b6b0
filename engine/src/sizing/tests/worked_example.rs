//! The worked motor-selection example of `docs/sizing-example.md`, computed: every number the
//! walk-through prints is the sizing's own result (or the hand formula the walk-through writes
//! out, held to the sizing's result), so the document cannot drift from the code.
//!
//! The example: a horizontal rotary table (no gravity load) of J_L = 0.005 kg·m² turns 90° in
//! 0.2 s with a symmetric constant-acceleration profile (accelerate 0.1 s, decelerate 0.1 s),
//! then rests 0.3 s: a 0.5 s duty cycle. The drive: a DC motor of the seed catalogue (maxon,
//! FAULHABER) behind a Beckhoff planetary gear unit of the seed catalogue, on the user's 48 V
//! amplifier (10 A continuous, 20 A peak) with a 20 W brake resistor, reserve 20 %.
//!
//! `CAD2MO_PRINT_EXAMPLE=1 cargo test -p cad2mo-engine --lib worked_example -- --nocapture`
//! prints the lines the document must hold (after a catalogue or sizing change, paste them in).

use std::f64::consts::PI;

use crate::library::seed;
use crate::pipeline::back::modelica::mechatronics::JointKind;
use crate::sizing::{rank, size_drive, Amplifier, AxisLoad, Brake, Catalog, Gear, Motor, PartRef, Settings};

const DOC: &str = include_str!("../../../../docs/sizing-example.md");

/// The example's numbers.
const J_LOAD: f64 = 0.005;
const ANGLE: f64 = PI / 2.0;
const T_MOVE: f64 = 0.2;
const DWELL: f64 = 0.3;
/// Samples per second (the service's sizing rate).
const RATE: f64 = 1000.0;

struct Load {
    t: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
}

/// Constant acceleration `a = 4·θ/T²` for T/2, then `-a` until the table rests: the joint's
/// speed, acceleration and torque `τ = J_L·q̈` at 1 kHz.
fn load() -> Load {
    let a = 4.0 * ANGLE / (T_MOVE * T_MOVE);
    let n = (T_MOVE * RATE).round() as usize + 1;
    let t: Vec<f64> = (0..n).map(|i| i as f64 / RATE).collect();
    let half = T_MOVE / 2.0;
    // At the end (the last sample) the table is at rest: no acceleration, no torque.
    let qdd: Vec<f64> = t
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            if i + 1 == n {
                0.0
            } else if x < half {
                a
            } else {
                -a
            }
        })
        .collect();
    let qd: Vec<f64> = t.iter().map(|&x| if x < half { a * x } else { a * (T_MOVE - x) }).collect();
    let tau = qdd.iter().map(|x| J_LOAD * x).collect();
    Load { t, qd, qdd, tau }
}

/// The user's amplifier and brake (settings of the example, not catalogue values).
fn settings() -> Settings {
    let amplifier = Amplifier {
        part: PartRef { id: "example-amplifier".into(), name: "48 V amplifier of the example".into() },
        u_supply: Some(48.0),
        u_min: Some(12.0),
        u_max: Some(60.0),
        i_cont: Some(10.0),
        i_peak: Some(20.0),
        source: "the example's amplifier: 12–60 V supply, 10 A continuous, 20 A peak".into(),
    };
    Settings { reserve: 0.2, dwell: DWELL, amplifier: Some(amplifier), brake: Some(Brake::Resistor { power: 20.0 }), screw_life: None }
}

/// The catalogue of the example: the seed's DC motors from catalogues (maxon EC 45 flat,
/// FAULHABER) and its Beckhoff planetary gear units, each at its own ratio.
fn catalogue() -> Catalog {
    let lib = seed::library().expect("seed");
    let all = Catalog::from_library(&lib);
    let motor_ids: Vec<&str> = seed::MAXON_EC45_FLAT_MOTORS.iter().chain(seed::FAULHABER_MOTORS.iter()).copied().collect();
    Catalog {
        motors: all.motors.into_iter().filter(|m| motor_ids.contains(&m.part.id.as_str())).collect(),
        gears: all.gears.into_iter().filter(|g| seed::BECKHOFF_GEARS.contains(&g.part.id.as_str())).collect(),
        skipped: Vec::new(),
    }
}

/// Three significant digits, as the document prints them.
fn sig(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.digits$}")
}

fn pct(m: f64) -> String {
    format!("{:.1} %", 100.0 * m)
}

/// The lines of the document that carry the sizing's numbers.
fn expected_lines() -> Vec<String> {
    let l = load();
    let axis = AxisLoad { joint: "table", kind: JointKind::Revolute, t: &l.t, qd: &l.qd, qdd: &l.qdd, tau: &l.tau, load_inertia: J_LOAD };
    let cat = catalogue();
    let s = settings();
    let alternatives = rank(axis, &cat, &s, 5).expect("ranks");
    let mut lines = Vec::new();
    for a in &alternatives {
        let limiting = a.limiting.as_ref().map(|x| format!("{} ({})", x.label, pct(x.margin))).unwrap_or_default();
        lines.push(format!("| {} | {} | {} | {:?} | {} |", a.rank, a.motor.name, a.gear.name, a.standing, limiting));
    }
    let best = &alternatives[0];
    let motor = cat.motors.iter().find(|m| m.part.id == best.motor.id).expect("motor");
    let gear = cat.gears.iter().find(|g| g.part.id == best.gear.id).expect("gear");
    let d = size_drive(axis, motor, gear, None, &s, 0).expect("sizes");
    for c in &d.checks {
        let v = c.value.map(sig).unwrap_or_else(|| "–".into());
        let lim = c.limit.map(sig).unwrap_or_else(|| "–".into());
        let m = c.margin.map(pct).unwrap_or_else(|| "–".into());
        lines.push(format!("| {} | {v} | {lim} | {} | {m} | {:?} |", c.label, c.unit, c.status));
    }
    lines
}

/// The hand formulas of the walk-through, for the chosen motor and gear.
struct Hand {
    a: f64,
    w_max: f64,
    tau: f64,
    n: f64,
    t_acc: f64,
    t_dec: f64,
    rms: f64,
    peak: f64,
    w_m: f64,
    ratio: f64,
}

fn hand(motor: &Motor, gear: &Gear) -> Hand {
    let a = 4.0 * ANGLE / (T_MOVE * T_MOVE);
    let tau = J_LOAD * a;
    let n = gear.ratio;
    let j = motor.j + gear.j_in.expect("J_in");
    // Accelerating, the motor drives the load through the losses; braking, the load drives back.
    let t_acc = tau / (n * gear.eta) + j * n * a;
    let t_dec = tau * gear.eta / n + j * n * a;
    // The rotor's viscous friction d·ω_m grows with the speed: T_m = t_acc + e·t accelerating,
    // -t_dec + e·(T - t) braking, e = d·n·a; ∫T_m² over each half h = T/2 in closed form.
    let (e, h) = (motor.d * n * a, T_MOVE / 2.0);
    let sq = t_acc * t_acc * h + t_acc * e * h * h + t_dec * t_dec * h - t_dec * e * h * h + 2.0 * e * e * h * h * h / 3.0;
    let rms = (sq / (T_MOVE + DWELL)).sqrt();
    // The samples' peak: the last accelerating sample is 1 ms before T/2.
    let peak = (t_acc + e * (h - 1.0 / RATE)).max(t_dec);
    Hand {
        a,
        w_max: a * T_MOVE / 2.0,
        tau,
        n,
        t_acc,
        t_dec,
        rms,
        peak,
        w_m: n * a * T_MOVE / 2.0,
        ratio: (J_LOAD / (n * n) + gear.j_in.expect("J_in")) / motor.j,
    }
}

#[test]
fn the_documents_numbers_are_the_sizings() {
    let lines = expected_lines();
    if std::env::var_os("CAD2MO_PRINT_EXAMPLE").is_some() {
        println!("{}", lines.join("\n"));
    }
    for line in &lines {
        assert!(
            DOC.contains(line.as_str()),
            "docs/sizing-example.md lacks the line\n{line}\n(print them with CAD2MO_PRINT_EXAMPLE=1, see this file's doc)"
        );
    }
}

#[test]
fn the_hand_formulas_agree_with_the_sizing() {
    let l = load();
    let axis = AxisLoad { joint: "table", kind: JointKind::Revolute, t: &l.t, qd: &l.qd, qdd: &l.qdd, tau: &l.tau, load_inertia: J_LOAD };
    let cat = catalogue();
    let s = settings();
    let best = rank(axis, &cat, &s, 1).expect("ranks").remove(0);
    let motor = cat.motors.iter().find(|m| m.part.id == best.motor.id).expect("motor");
    let gear = cat.gears.iter().find(|g| g.part.id == best.gear.id).expect("gear");
    let d = size_drive(axis, motor, gear, None, &s, 0).expect("sizes");
    let h = hand(motor, gear);
    let value = |name: &str| d.checks.iter().find(|c| c.check == name).and_then(|c| c.value).expect(name);
    let close = |a: f64, b: f64, rel: f64, what: &str| assert!((a - b).abs() <= rel * b.abs(), "{what}: {a} vs {b}");
    // Exact at the samples: the peaks and the inertia ratio.
    close(value("peak_torque"), h.peak, 1e-12, "peak motor torque");
    close(value("motor_speed"), h.w_m, 1e-12, "motor speed");
    close(value("gear_peak_torque"), h.tau, 1e-12, "gear output torque");
    close(value("inertia_ratio"), h.ratio, 1e-12, "inertia ratio");
    // The RMS integrates 1 kHz samples by the trapezoid rule across the switch at T/2: within
    // the document's three digits of the piecewise-constant formula.
    close(value("rms_torque"), h.rms, 2e-3, "RMS motor torque");
    if std::env::var_os("CAD2MO_PRINT_EXAMPLE").is_some() {
        println!(
            "a = {} rad/s², τ = {}, ω = {}, n = {}, T_acc = {}, T_dec = {}, RMS = {}, ω_m = {}, ratio = {}; motor J = {:e}, gear J_in = {:e}, eta = {}, T_nom = {:?}, T_stall = {:?}, k = {}, R = {:?}",
            sig(h.a),
            sig(h.tau),
            sig(h.w_max),
            sig(h.n),
            sig(h.t_acc),
            sig(h.t_dec),
            sig(h.rms),
            sig(h.w_m),
            sig(h.ratio),
            motor.j,
            gear.j_in.unwrap_or(0.0),
            gear.eta,
            motor.t_nom,
            motor.t_stall,
            motor.k,
            motor.r
        );
    }
    // The walk-through's numbers, to its printed precision.
    for x in [h.a, h.tau, h.w_max, h.n, h.t_acc, h.t_dec, h.rms, h.w_m, h.ratio] {
        assert!(DOC.contains(&sig(x)), "docs/sizing-example.md lacks {} ({x})", sig(x));
    }
}
