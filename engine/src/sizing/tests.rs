//! Unit tests of the sizing: numbers against hand-computed formulas, one test (at least) per
//! check that fails when the check's rule is changed.

use std::f64::consts::PI;

use super::*;
use crate::library::{seed, Value};

mod worked_example;

fn part(name: &str) -> PartRef {
    PartRef { id: format!("id-{name}"), name: name.to_string() }
}

/// R = 1 Ω, k = 0.1 N·m/A, J = 1e-4 kg·m², d = 0; T_nom 0.2 N·m, T_stall 0.5 N·m, 300 rad/s.
fn motor() -> Motor {
    Motor {
        part: part("M"),
        r: Some(1.0),
        k: 0.1,
        j: 1e-4,
        d: 0.0,
        t_nom: Some(0.2),
        t_peak: None,
        t_stall: Some(0.5),
        w_max: Some(300.0),
        tau_th_w: None,
        mass: None,
        price_class: None,
        mount: None,
        source: "test motor".into(),
    }
}

fn gear(ratio: f64, eta: f64) -> Gear {
    Gear {
        part: part("G"),
        ratio,
        catalog_ratio: ratio,
        eta,
        lead: None,
        ratio_editable: false,
        ratio_min: None,
        ratio_max: None,
        t_rated: Some(10.0),
        t_avg_max: None,
        out_peak: Some(20.0),
        c_a: None,
        out_peak_is_c0a: false,
        w_in_max: Some(500.0),
        j_in: Some(0.0),
        mass: None,
        price_class: None,
        motor_mounts: None,
        source: "test gear".into(),
    }
}

/// 24 V supply, 3 A continuous, 6 A peak.
fn amplifier() -> Amplifier {
    Amplifier {
        part: part("A"),
        u_supply: Some(24.0),
        u_min: Some(10.0),
        u_max: Some(50.0),
        i_cont: Some(3.0),
        i_peak: Some(6.0),
        source: "test amplifier".into(),
    }
}

fn with_amp() -> Settings {
    Settings { amplifier: Some(amplifier()), ..Settings::default() }
}

struct Samples {
    t: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
}

impl Samples {
    /// `n` uniform samples over [0, 1] s.
    fn new(n: usize, f: impl Fn(f64) -> (f64, f64, f64)) -> Samples {
        Samples::over(n, 1.0, f)
    }

    /// `n` uniform samples over [0, end] s.
    fn over(n: usize, end: f64, f: impl Fn(f64) -> (f64, f64, f64)) -> Samples {
        let t: Vec<f64> = (0..n).map(|i| end * i as f64 / (n - 1) as f64).collect();
        let (mut qd, mut qdd, mut tau) = (Vec::new(), Vec::new(), Vec::new());
        for &x in &t {
            let (a, b, c) = f(x);
            qd.push(a);
            qdd.push(b);
            tau.push(c);
        }
        Samples { t, qd, qdd, tau }
    }

    fn load(&self, kind: JointKind, load_inertia: f64) -> AxisLoad<'_> {
        AxisLoad { joint: "J1", kind, t: &self.t, qd: &self.qd, qdd: &self.qdd, tau: &self.tau, load_inertia }
    }
}

fn check<'a>(d: &'a DriveSizing, name: &str) -> &'a Check {
    d.checks.iter().find(|c| c.check == name).unwrap_or_else(|| panic!("no check {name}: {:#?}", d.checks))
}

fn value(d: &DriveSizing, name: &str) -> f64 {
    check(d, name).value.unwrap_or_else(|| panic!("{name} not evaluated: {:#?}", check(d, name)))
}

fn close(a: f64, b: f64, rel: f64) {
    assert!((a - b).abs() <= rel * b.abs().max(1e-300), "{a} vs {b}");
}

fn size(s: &Samples, kind: JointKind, jl: f64, m: &Motor, g: &Gear, settings: &Settings) -> DriveSizing {
    size_drive(s.load(kind, jl), m, g, None, settings, TOP).expect("sizes")
}

/// Constant speed against a constant driving load: T_m = τ/(n·η) + d·ω_m everywhere.
#[test]
fn constant_speed() {
    let s = Samples::new(101, |_| (5.0, 0.0, 2.0));
    let m = Motor { d: 1e-5, ..motor() };
    let g = gear(10.0, 0.8);
    let d = size(&s, JointKind::Revolute, 0.5, &m, &g, &with_amp());
    let w_m = 50.0;
    let t_m = 2.0 / (10.0 * 0.8) + 1e-5 * w_m;
    close(value(&d, "peak_torque"), t_m, 1e-12);
    close(value(&d, "rms_torque"), t_m, 1e-12);
    close(value(&d, "motor_speed"), w_m, 1e-12);
    close(value(&d, "gear_input_speed"), w_m, 1e-12);
    close(value(&d, "voltage"), 1.0 * t_m / 0.1 + 0.1 * w_m, 1e-12);
    close(value(&d, "peak_current"), t_m / 0.1, 1e-12);
    close(value(&d, "rms_current"), t_m / 0.1, 1e-12);
    close(value(&d, "gear_peak_torque"), 2.0, 1e-12);
    close(value(&d, "gear_rms_torque"), 2.0, 1e-12);
    close(value(&d, "inertia_ratio"), 0.5 / (100.0 * 1e-4), 1e-12);
    // Peak limit: the stall torque (no T_peak); margin (limit - value)/limit.
    let peak = check(&d, "peak_torque");
    assert_eq!(peak.limit, Some(0.5));
    close(peak.margin.expect("margin"), (0.5 - t_m) / 0.5, 1e-12);
    assert!(peak.detail.contains("T_stall") && peak.source.as_deref() == Some("motor \"M\": T_stall (datasheet)"), "{peak:?}");
    assert_eq!(check(&d, "voltage").limit, Some(24.0));
    assert_eq!(check(&d, "peak_current").limit, Some(6.0));
    assert_eq!(check(&d, "rms_current").limit, Some(3.0));
    // RMS 0.2505 > T_nom 0.2: fails; the inertia ratio 50 > 10 fails too.
    assert_eq!(check(&d, "rms_torque").status, Status::Fail);
    assert!(!check(&d, "inertia_ratio").pass);
    assert!(!d.pass && !d.passes_with_reserve);
    // No winding time constant, no average torque limit: not evaluated, not missing.
    assert_eq!(check(&d, "thermal_torque").status, Status::NotEvaluated);
    assert_eq!(check(&d, "gear_avg_torque").status, Status::NotEvaluated);
    assert!(d.missing.is_empty(), "{:?}", d.missing);
    assert_eq!(value(&d, "braking"), 0.0);
    assert_eq!(d.envelope.no_load_speed, Some(240.0));
    assert_eq!(d.envelope.peak_torque, Some(0.5));
}

/// The peak limit is the maker's short-time limit T_peak where given, else the stall torque;
/// never the continuous current's torque k·I_max, and the same for both motor classes.
#[test]
fn peak_rule_is_the_datasheets_not_the_class() {
    let s = Samples::new(11, |_| (1.0, 0.0, 4.0));
    let g = gear(10.0, 1.0);
    let short_time = Motor { t_peak: Some(0.3), ..motor() };
    let d = size(&s, JointKind::Revolute, 0.0, &short_time, &g, &with_amp());
    let peak = check(&d, "peak_torque");
    assert_eq!((peak.limit, peak.status), (Some(0.3), Status::Fail), "{peak:?}");
    assert!(peak.source.as_deref().is_some_and(|x| x.contains("T_peak")), "{peak:?}");
    let stall = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &with_amp());
    assert_eq!(check(&stall, "peak_torque").limit, Some(0.5));
    assert_eq!(check(&stall, "peak_torque").status, Status::Pass);
    let none = Motor { t_stall: None, ..motor() };
    let d = size(&s, JointKind::Revolute, 0.0, &none, &g, &with_amp());
    assert_eq!(check(&d, "peak_torque").status, Status::NotEvaluated);
    assert_eq!(d.missing, vec!["motor.T_peak or motor.T_stall"]);

    // The seed's maxon RE 40 as our DC class and as the MSL machine, with its datasheet stall
    // torque added: the same limit, whatever the class.
    let lib = seed::library().expect("seed");
    let inst = |id: &str| {
        let mut i = lib.instances.iter().find(|i| i.id == id).expect("instance").clone();
        i.values.push(("T_stall".into(), Value::Real(2.28)));
        (lib.class(&i.class_id).expect("class").clone(), i)
    };
    let (c, i) = inst(seed::MAXON_RE40);
    let dc = parts::motor(&c, &i, &[]).expect("RE 40");
    let (c, i) = inst(seed::MAXON_RE40_MSL);
    let msl = parts::motor(&c, &i, &[]).expect("RE 40 MSL");
    assert_eq!(dc.peak_rule(), Some(PeakRule::Stall(2.28)));
    assert_eq!(msl.peak_rule(), dc.peak_rule());
}

/// Constant acceleration from rest of a pure inertia: T_m(t) = J_L·a/n + (J_m + J_g)·n·a +
/// d·n·a·t, a straight line c + e·t, so RMS² = c² + c·e + e²/3 over one second; the speed and
/// the voltage peak at the end.
#[test]
fn constant_acceleration() {
    let (a, jl, n) = (2.0, 0.02, 5.0);
    let s = Samples::new(1001, |t| (a * t, a, jl * a));
    let m = Motor { d: 2e-4, ..motor() };
    let g = Gear { j_in: Some(2e-5), ..gear(n, 1.0) };
    let d = size(&s, JointKind::Revolute, jl, &m, &g, &with_amp());
    let c = jl * a / n + (1e-4 + 2e-5) * n * a;
    let e = 2e-4 * n * a;
    close(value(&d, "peak_torque"), c + e, 1e-12);
    close(value(&d, "rms_torque"), (c * c + c * e + e * e / 3.0).sqrt(), 1e-6);
    close(value(&d, "motor_speed"), n * a, 1e-12);
    close(value(&d, "voltage"), (c + e) / 0.1 + 0.1 * n * a, 1e-12);
    assert!(check(&d, "voltage").detail.contains("t = 1 s"), "{}", check(&d, "voltage").detail);
    // The gear's input inertia on the load side: (J_L/n² + J_g)/J_m.
    close(value(&d, "inertia_ratio"), (jl / (n * n) + 2e-5) / 1e-4, 1e-12);
    assert!(d.pass, "{:#?}", d.checks);
    assert_eq!(d.operating_points.t.len(), 1001);
}

/// Efficiency in the direction of power flow: a driving load costs τ/(n·η), a load that drives
/// the motor back (lowering a weight) gives only τ·η/n, and what the motor feeds back (its
/// mechanical power less the copper losses R·I²) goes to the brake resistor or the DC bus.
#[test]
fn efficiency_follows_the_power_flow_and_braking() {
    let g = gear(10.0, 0.8);
    let drive = Samples::new(11, |_| (5.0, 0.0, 2.0));
    let d = size(&drive, JointKind::Revolute, 0.0, &motor(), &g, &with_amp());
    close(value(&d, "peak_torque"), 2.0 / (10.0 * 0.8), 1e-12);
    let back = Samples::new(11, |_| (5.0, 0.0, -2.0));
    let d = size(&back, JointKind::Revolute, 0.0, &motor(), &g, &with_amp());
    close(value(&d, "peak_torque"), 2.0 * 0.8 / 10.0, 1e-12);
    close(d.operating_points.torque[3], -0.16, 1e-12);
    // P_el = T·ω + R·T²/k² = -0.16·50 + 1·0.16²/0.01 = -8 + 2.56 = -5.44 W for 1 s: 5.44 J.
    let fed_back = 8.0 - 2.56;
    let b = check(&d, "braking");
    assert_eq!(b.status, Status::NotEvaluated);
    assert_eq!(d.missing, vec!["brake (resistor power or DC-bus capacitance)"]);
    // A resistor: mean power over the cycle; a dwell of 1 s halves it.
    let resistor = Settings { brake: Some(Brake::Resistor { power: 5.0 }), ..with_amp() };
    let d = size(&back, JointKind::Revolute, 0.0, &motor(), &g, &resistor);
    close(value(&d, "braking"), fed_back, 1e-12);
    assert_eq!(check(&d, "braking").status, Status::Fail);
    let dwell = Settings { dwell: 1.0, ..resistor };
    let d = size(&back, JointKind::Revolute, 0.0, &motor(), &g, &dwell);
    close(value(&d, "braking"), fed_back / 2.0, 1e-12);
    assert_eq!(check(&d, "braking").status, Status::Pass);
    // The DC bus: C·(U_max² - U²)/2 = 0.001·(30² - 24²)/2 = 0.162 J < 5.44 J.
    let bus = Settings { brake: Some(Brake::Bus { capacitance: 0.001, voltage_max: 30.0 }), ..with_amp() };
    let d = size(&back, JointKind::Revolute, 0.0, &motor(), &g, &bus);
    let b = check(&d, "braking");
    close(value(&d, "braking"), fed_back, 1e-12);
    close(b.limit.expect("limit"), 0.5 * 0.001 * (900.0 - 576.0), 1e-12);
    assert_eq!(b.status, Status::Fail);
    // Two braking intervals: the bus takes the largest, not their sum.
    let two = Samples::new(21, |t| (5.0, 0.0, if t <= 0.3 || t >= 0.7 { -2.0 } else { 2.0 }));
    let d = size(&two, JointKind::Revolute, 0.0, &motor(), &g, &bus);
    let per_sample = |t0: f64, t1: f64| (t1 - t0) * fed_back;
    let e = value(&d, "braking");
    assert!(e < per_sample(0.0, 0.6) && e >= per_sample(0.0, 0.3), "{e}");
}

/// A lead screw: ω_m = ratio·2π/lead·ṡ, T_m = F·lead/(2π·ratio); its static limit C_0a and
/// its life check's C_a and required life are named missing.
#[test]
fn lead_screw_converts_force_to_torque() {
    let lead = 0.005;
    let s = Samples::new(11, |_| (0.1, 0.0, 100.0));
    let screw = Gear { lead: Some(lead), t_rated: None, out_peak: None, ..gear(2.0, 1.0) };
    let m = Motor { w_max: None, ..motor() };
    let d = size(&s, JointKind::Prismatic, 3.0, &m, &screw, &with_amp());
    close(value(&d, "peak_torque"), 100.0 * lead / (2.0 * PI * 2.0), 1e-12);
    close(value(&d, "gear_input_speed"), 2.0 * 2.0 * PI / lead * 0.1, 1e-12);
    let n = 2.0 * 2.0 * PI / lead;
    close(value(&d, "inertia_ratio"), 3.0 / (n * n * 1e-4), 1e-12);
    assert!(d.checks.iter().all(|c| c.check != "gear_rms_torque"));
    assert_eq!(d.missing, vec!["motor.w_max", "gear.C_0a", "gear.C_a", "screw_life"]);
    assert!(d.checks.iter().all(|c| c.check != "gear_peak_torque" && c.check != "gear_avg_torque"));
    // A screw on a revolute joint (and a rotary gear on a prismatic one) is refused.
    let e = size_drive(s.load(JointKind::Revolute, 3.0), &m, &screw, None, &with_amp(), TOP).expect_err("does not fit");
    assert!(e.to_string().contains("fits prismatic joints"), "{e}");
}

/// A missing datasheet value leaves its check not evaluated and names the value; a gear
/// without its input inertia is never counted as 0: every check of the motor torque waits.
#[test]
fn missing_values_are_named_never_defaulted() {
    let s = Samples::new(11, |_| (1.0, 0.0, 1.0));
    let m = Motor { t_nom: None, ..motor() };
    let g = Gear { t_rated: None, ..gear(10.0, 1.0) };
    let d = size(&s, JointKind::Revolute, 0.0, &m, &g, &Settings::default());
    assert_eq!(d.missing, vec!["motor.T_nom", "amplifier", "gear.T_rated"]);
    for gone in ["rms_torque", "voltage", "peak_current", "rms_current", "gear_rms_torque"] {
        let c = check(&d, gone);
        assert!(c.status == Status::NotEvaluated && c.value.is_none() && c.pass, "{c:?}");
    }
    assert_eq!(d.envelope.continuous_torque, None);
    // Without J_in.
    let no_j = Gear { j_in: None, ..gear(10.0, 1.0) };
    let d = size(&s, JointKind::Revolute, 0.5, &motor(), &no_j, &with_amp());
    assert_eq!(d.missing, vec!["gear.J_in"]);
    for waits in ["peak_torque", "rms_torque", "thermal_torque", "voltage", "peak_current", "rms_current", "inertia_ratio", "braking"] {
        let c = check(&d, waits);
        assert_eq!((c.status, c.missing.as_slice()), (Status::NotEvaluated, &["gear.J_in".to_string()][..]), "{c:?}");
    }
    // The speed and the gear's own checks do not need it.
    assert_eq!(check(&d, "motor_speed").status, Status::Pass);
    assert_eq!(check(&d, "gear_peak_torque").status, Status::Pass);
    assert!(d.operating_points.t.is_empty());
    assert!(d.pass && !d.passes_with_reserve);
    // An amplifier without the user's supply voltage or a datasheet current.
    let bare = Settings { amplifier: Some(Amplifier { u_supply: None, i_peak: None, ..amplifier() }), ..Settings::default() };
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &gear(10.0, 1.0), &bare);
    assert_eq!(d.missing, vec!["supply_voltage", "amplifier.I_peak"]);
}

/// A drive's ratio override is not the catalogue's gear: its ratings are unknown there.
#[test]
fn an_overridden_ratio_drops_the_ratings() {
    let lib = seed::library().expect("seed");
    let i = lib.instances.iter().find(|i| i.id == seed::GEAR_100).expect("gear");
    let c = lib.class(&i.class_id).expect("class");
    let own = parts::gear(c, i, &[]).expect("gear");
    // Its torque ratings are missing (see its source); its speed and inertia are given.
    assert_eq!((own.t_rated, own.out_peak, own.catalog_ratio), (None, None, 100.0));
    assert!(own.j_in.is_some() && own.w_in_max.is_some());
    let other = parts::gear(c, i, &[("ratio".into(), Value::Real(50.0))]).expect("gear");
    assert_eq!((other.t_rated, other.out_peak, other.w_in_max, other.j_in), (None, None, None, None));
    let s = Samples::new(11, |_| (1.0, 0.0, 1.0));
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &other, &with_amp());
    assert!(d.missing.iter().any(|m| m == "gear ratings at the overridden ratio"), "{:?}", d.missing);
}

/// The duty cycle: the motion repeated with a dwell holding the last pose; RMS values over
/// motion + dwell.
#[test]
fn duty_cycle_with_dwell() {
    // 1 s at 0.3 N·m motor torque, ending at rest with the joint holding 1 N·m (0.1 N·m at the
    // motor through 10:1); 3 s dwell.
    let s = Samples::new(101, |t| if t < 0.995 { (1.0, 0.0, 3.0) } else { (0.0, 0.0, 1.0) });
    let g = gear(10.0, 1.0);
    let dwell = Settings { dwell: 3.0, ..with_amp() };
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &dwell);
    // Trapezoid: the last step (0.99..1.0) averages 0.3² and 0.1²; the dwell holds 0.1 N·m.
    let motion: f64 = 0.99 * 0.09 + 0.005 * 0.09 + 0.005 * 0.01;
    let rms = ((motion + 3.0 * 0.01) / 4.0).sqrt();
    close(value(&d, "rms_torque"), rms, 1e-12);
    close(value(&d, "rms_current"), rms / 0.1, 1e-12);
    let tau_rms = (((0.99_f64 + 0.005) * 9.0 + 0.005 + 3.0) / 4.0).sqrt();
    close(value(&d, "gear_rms_torque"), tau_rms, 1e-12);
    assert!(check(&d, "rms_torque").detail.contains("dwell 3 s"), "{}", check(&d, "rms_torque").detail);
    let no_dwell = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &with_amp());
    close(value(&no_dwell, "rms_torque"), motion.sqrt(), 1e-12);
    let u = undriven(s.load(JointKind::Revolute, 0.0), 3.0).expect("figures");
    close(u.rms_torque, tau_rms, 1e-12);
}

/// The winding's thermal model: a constant torque heats it to exactly that torque; an on/off
/// cycle reaches the closed-form periodic maximum of a first-order lag.
#[test]
fn thermal_time_constant() {
    let m = Motor { tau_th_w: Some(2.0), ..motor() };
    let g = gear(10.0, 1.0);
    let steady = Samples::new(101, |_| (1.0, 0.0, 1.5));
    let d = size(&steady, JointKind::Revolute, 0.0, &m, &g, &with_amp());
    close(value(&d, "thermal_torque"), 0.15, 1e-12);
    assert_eq!(check(&d, "thermal_torque").limit, Some(0.2));
    // On for 1 s at T (the motion), off for the dwell b (holding 0): θ_max = T²·(1 - e^(-1/τ)) /
    // (1 - e^(-(1 + b)/τ)) in the periodic steady state.
    let on = Samples::new(100_001, |t| if t < 1.0 { (1.0, 0.0, 2.0) } else { (0.0, 0.0, 0.0) });
    for (tau, b) in [(2.0, 3.0), (0.5, 1.0), (50.0, 9.0)] {
        let m = Motor { tau_th_w: Some(tau), ..motor() };
        let d = size(&on, JointKind::Revolute, 0.0, &m, &g, &Settings { dwell: b, ..with_amp() });
        let t2 = 0.2 * 0.2;
        let exact = (t2 * (1.0 - (-1.0 / tau).exp()) / (1.0 - (-(1.0 + b) / tau).exp())).sqrt();
        close(value(&d, "thermal_torque"), exact, 1e-4);
        // Between the cycle's RMS and its peak.
        let rms = value(&d, "rms_torque");
        let th = value(&d, "thermal_torque");
        assert!(th >= rms && th <= 0.2 + 1e-12, "{rms} {th}");
    }
}

/// The gear's average torque (Harmonic Drive), weighted by the output speed, where a limit is
/// given.
#[test]
fn gear_average_torque() {
    // Half the time at 2 rad/s with 3 N·m, half at 1 rad/s with 6 N·m.
    let s = Samples::new(1001, |t| if t <= 0.5 { (2.0, 0.0, 3.0) } else { (1.0, 0.0, 6.0) });
    let g = Gear { t_avg_max: Some(4.0), ..gear(10.0, 1.0) };
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &with_amp());
    let exact = ((2.0_f64 * 27.0 * 0.5 + 1.0 * 216.0 * 0.5) / (2.0 * 0.5 + 1.0 * 0.5)).cbrt();
    close(value(&d, "gear_avg_torque"), exact, 2e-3);
    assert_eq!(check(&d, "gear_avg_torque").status, Status::Fail);
}

/// Settings with a bad value are refused naming the field.
#[test]
fn settings_are_checked() {
    let bad = Settings {
        reserve: 1.5,
        dwell: -1.0,
        amplifier: Some(Amplifier { u_supply: Some(60.0), ..amplifier() }),
        brake: Some(Brake::Bus { capacitance: 0.0, voltage_max: 20.0 }),
        screw_life: Some(0.0),
    };
    let fields: Vec<String> = bad.check().into_iter().map(|i| i.field).collect();
    assert_eq!(fields, vec!["reserve", "dwell", "supply_voltage", "bus_capacitance", "bus_voltage_max", "screw_life"]);
    assert_eq!(Settings { screw_life: Some(f64::INFINITY), ..Settings::default() }.check()[0].field, "screw_life");
    assert!(Settings { screw_life: Some(20_000.0), ..Settings::default() }.check().is_empty());
    let bus = Settings { brake: Some(Brake::Bus { capacitance: 0.01, voltage_max: 20.0 }), ..with_amp() };
    assert_eq!(bus.check()[0].field, "bus_voltage_max");
    assert_eq!(Settings { brake: Some(Brake::Resistor { power: f64::NAN }), ..Settings::default() }.check()[0].field, "brake_power");
    assert!(with_amp().check().is_empty());
}

/// The reserve: a check that passes with a margin below it passes, but not with the reserve.
#[test]
fn reserve() {
    // RMS 0.15 N·m against T_nom 0.2: margin 25 %.
    let s = Samples::new(11, |_| (1.0, 0.0, 1.5));
    let g = Gear { j_in: Some(0.0), ..gear(10.0, 1.0) };
    let quiet = Settings { brake: Some(Brake::Resistor { power: 1.0 }), ..with_amp() };
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &quiet);
    assert!(d.pass && d.passes_with_reserve, "{:#?}", d.checks);
    let strict = Settings { reserve: 0.3, ..quiet };
    let d = size(&s, JointKind::Revolute, 0.0, &motor(), &g, &strict);
    assert!(d.pass && !d.passes_with_reserve);
    assert_eq!(check(&d, "rms_torque").within_reserve, Some(false));
    assert_eq!(check(&d, "inertia_ratio").within_reserve, None);
}

/// Motors and gears from the seed library; classes the sizing does not know are refused.
#[test]
fn parts_from_the_seed_library() {
    let lib = seed::library().expect("seed");
    let inst = |id: &str| {
        let i = lib.instances.iter().find(|i| i.id == id).expect("instance");
        (lib.class(&i.class_id).expect("class"), i)
    };
    let (c, i) = inst(seed::MAXON_RE40);
    let re40 = parts::motor(c, i, &[]).expect("RE 40");
    assert_eq!((re40.k, re40.t_nom), (0.0302, Some(0.17)));
    close(re40.w_max.expect("w_max"), 12000.0 * PI / 30.0, 1e-12);
    assert!(re40.source.contains("148877"));
    let (c, i) = inst(seed::MAXON_RE40_MSL);
    let msl = parts::motor(c, i, &[]).expect("RE 40 MSL");
    close(msl.k, (24.0 - 0.317 * 5.77) / (6940.0 * PI / 30.0), 1e-12);
    let (c, i) = inst(seed::MAXON_GP42C_74);
    let gp = parts::gear(c, i, &[]).expect("GP 42 C");
    assert_eq!((gp.ratio, gp.eta, gp.t_rated, gp.out_peak), (74.0, 0.72, Some(15.0), Some(22.5)));
    let (c, i) = inst(seed::BALL_SCREW_16X5);
    let screw = parts::gear(c, i, &[]).expect("screw");
    assert_eq!((screw.lead, screw.fits()), (Some(0.005), JointKind::Prismatic));
    let (c, i) = inst(seed::ROBOT_R3_CONTROLLER);
    let e = parts::motor(c, i, &[]).expect_err("a controller is no motor");
    assert!(e.to_string().contains("not a motor the sizing knows"), "{e}");
    let e = parts::gear(c, i, &[]).expect_err("a controller is no gear");
    assert!(matches!(e, SizingError::UnknownClass { slot: "gear", .. }), "{e}");
    let e = parts::amplifier(c, i, Some(24.0)).expect_err("a controller is no amplifier");
    assert!(matches!(e, SizingError::UnknownClass { slot: "amplifier", .. }), "{e}");
    let amp_class = lib.class(seed::SERVO_AMPLIFIER).expect("amplifier class");
    assert_eq!(amp_class.domain, "amplifier");
    assert!(amp_class.parameters.iter().all(|p| p.datasheet));
    let cat = Catalog::from_library(&lib);
    assert!(cat.skipped.is_empty(), "{:?}", cat.skipped);
    assert_eq!(cat.motors.len(), lib.instances.iter().filter(|i| lib.class(&i.class_id).is_some_and(|c| c.domain == "motor")).count());
    // 5 motors of the first seed, 14 catalogue DC motors and 30 AC servo motors; 3 gears of the
    // first seed, 60 catalogue gear units and 3 catalogue ball screws.
    assert_eq!((cat.motors.len(), cat.gears.len()), (49, 66));
    // A catalogue ball screw: its lead and its load ratings C_a and C_0a, in N.
    let (c, i) = inst(seed::PBSA_SCREWS[1]);
    let pbsa = parts::gear(c, i, &[]).expect("PBSA 20");
    assert_eq!((pbsa.lead, pbsa.c_a, pbsa.out_peak, pbsa.out_peak_name()), (Some(0.02), Some(5900.0), Some(12200.0), "C_0a"));
    assert_eq!((pbsa.j_in, pbsa.w_in_max, pbsa.fits()), (None, None, JointKind::Prismatic));
    // A screw of a library entered before C_0a existed: its F_peak is the static limit.
    let (c, i) = inst(seed::BALL_SCREW_16X5);
    let mut older = i.clone();
    older.values.push(("F_peak".to_string(), Value::Real(5000.0)));
    let g = parts::gear(c, &older, &[]).expect("older screw");
    assert_eq!((g.out_peak, g.out_peak_name(), g.c_a), (Some(5000.0), "F_peak", None));
    let bare = parts::gear(c, i, &[]).expect("screw without ratings");
    assert_eq!((bare.out_peak, bare.out_peak_name()), (None, "C_0a"));
}

/// Ranking: real combinations only (each gear at its catalogue ratio, motors that mount on the
/// gear where it says so), passing with the reserve first, then passing, then incomplete, then
/// failing; the smallest rotor first, then the lighter, then the cheaper.
#[test]
fn ranking_order() {
    let s = Samples::new(201, |t| (2.0 * t, 2.0, 0.4 + 0.02 * 2.0));
    let settings = Settings { brake: Some(Brake::Resistor { power: 10.0 }), ..with_amp() };
    let tiny = Motor { part: part("tiny"), j: 1e-6, t_nom: Some(0.001), ..motor() };
    let mid_heavy = Motor { part: part("mid heavy"), j: 2e-5, mass: Some(0.5), ..motor() };
    let mid_light = Motor { part: part("mid light"), j: 2e-5, mass: Some(0.3), ..motor() };
    let mid_unknown = Motor { part: part("mid unknown"), j: 2e-5, ..motor() };
    let big = Motor { part: part("big"), j: 5e-5, mass: Some(0.1), mount: Some("flange A".into()), ..motor() };
    let incomplete = Motor { part: part("incomplete"), j: 1e-5, t_nom: None, ..motor() };
    let g20 = Gear { part: part("fixed 20"), mass: Some(0.2), ..gear(20.0, 0.9) };
    let mounted = Gear { part: part("mounted 20"), motor_mounts: Some(vec!["Flange A".into()]), mass: Some(0.2), ..gear(20.0, 0.9) };
    let editable = Gear {
        part: part("editable 12"),
        ratio_editable: true,
        ratio_min: Some(1.0),
        ratio_max: Some(100.0),
        mass: Some(0.2),
        ..gear(12.0, 1.0)
    };
    let screw = Gear { part: part("screw"), lead: Some(0.01), ..gear(1.0, 1.0) };
    let cat = Catalog {
        motors: vec![big.clone(), incomplete, tiny, mid_heavy, mid_unknown, mid_light],
        gears: vec![screw, editable, g20, mounted],
        skipped: vec![],
    };
    let alts = rank(s.load(JointKind::Revolute, 0.02), &cat, &settings, 100).expect("ranks");
    // 6 motors × 2 free gears + the one motor that mounts on "mounted 20"; no screw, and each
    // gear at its own ratio only.
    assert_eq!(alts.len(), 6 * 2 + 1, "{alts:#?}");
    assert!(alts.iter().all(|a| a.gear.name != "screw"));
    assert!(alts.iter().filter(|a| a.gear.name == "mounted 20").all(|a| a.motor.name == "big"));
    assert!(alts.iter().all(|a| a.ratio == if a.gear.name.starts_with("editable") { 12.0 } else { 20.0 }));
    for (i, a) in alts.iter().enumerate() {
        assert_eq!(a.rank, i + 1);
        assert!(!a.why.is_empty() && a.limiting.is_some(), "{a:?}");
    }
    let standings: Vec<Standing> = alts.iter().map(|a| a.standing).collect();
    let mut sorted = standings.clone();
    sorted.sort();
    assert_eq!(standings, sorted);
    assert!(standings.contains(&Standing::PassesWithReserve) && standings.contains(&Standing::Fails), "{standings:?}");
    // Within a passing standing, the smallest rotor first.
    for w in alts.windows(2).filter(|w| w[0].standing == w[1].standing && w[0].standing != Standing::Fails) {
        assert!(w[0].rotor_inertia <= w[1].rotor_inertia, "{w:#?}");
    }
    let first: Vec<(&str, &str)> = alts.iter().take(3).map(|a| (a.motor.name.as_str(), a.gear.name.as_str())).collect();
    // Among the passing mids: the lighter first (mass motor + gear), unknown mass last.
    let mids: Vec<&str> = alts
        .iter()
        .filter(|a| a.standing == Standing::PassesWithReserve && a.gear.name == "fixed 20" && a.motor.name.starts_with("mid"))
        .map(|a| a.motor.name.as_str())
        .collect();
    assert_eq!(&mids[..3], ["mid light", "mid heavy", "mid unknown"], "{first:?} {mids:?}");
    let inc = alts.iter().find(|a| a.motor.name == "incomplete").expect("incomplete");
    assert_eq!(inc.standing, Standing::Incomplete);
    assert!(inc.why.contains("motor.T_nom"), "{}", inc.why);
    let tiny = alts.iter().find(|a| a.motor.name == "tiny").expect("tiny");
    assert_eq!(tiny.standing, Standing::Fails);
    assert!(tiny.failed.contains(&"rms_torque") && tiny.why.starts_with("fails"), "{tiny:?}");
    // Every alternative sized as the drive gives the same standing.
    for a in &alts {
        let m = cat.motors.iter().find(|m| m.part == a.motor).expect("motor");
        let g = cat.gears.iter().find(|g| g.part == a.gear).expect("gear");
        let d = size_drive(s.load(JointKind::Revolute, 0.02), m, g, None, &settings, TOP).expect("sizes");
        assert_eq!(d.pass, a.pass, "{a:?}");
        assert_eq!(d.passes_with_reserve, a.standing == Standing::PassesWithReserve, "{a:?}");
    }
    // The top k are the first k of the whole ranking, whatever k (the ranking stops early).
    for k in 1..=alts.len() {
        let top = rank(s.load(JointKind::Revolute, 0.02), &cat, &settings, k).expect("ranks");
        assert_eq!(top.as_slice(), &alts[..k], "top {k}");
    }
    // And when most fail (a reserve no combination keeps, a heavier load): the failing ones
    // closest first, the same with and without the early stop.
    let heavy = Samples::new(201, |t| (2.0 * t, 2.0, 3.0 + 0.02 * 2.0));
    let all = rank(heavy.load(JointKind::Revolute, 0.02), &cat, &settings, 100).expect("ranks");
    assert!(all.iter().filter(|a| a.standing == Standing::Fails).count() >= 5, "{all:#?}");
    for k in 1..=all.len() {
        let top = rank(heavy.load(JointKind::Revolute, 0.02), &cat, &settings, k).expect("ranks");
        assert_eq!(top.as_slice(), &all[..k], "top {k}");
    }
    // A larger reserve moves combinations from the first group to the second.
    let strict = rank(s.load(JointKind::Revolute, 0.02), &cat, &Settings { reserve: 0.9, ..settings.clone() }, 100).expect("ranks");
    let count = |v: &[Alternative], st: Standing| v.iter().filter(|a| a.standing == st).count();
    assert!(count(&strict, Standing::PassesWithReserve) < count(&alts, Standing::PassesWithReserve));
    assert!(count(&strict, Standing::Passes) > count(&alts, Standing::Passes));
    let _ = big;
}

/// 10,001 samples are decimated to at most 2000 points that keep the extremes.
#[test]
fn operating_points_keep_the_extremes() {
    let s = Samples::new(10_001, |t| ((7.0 * t).sin() * 3.0, (13.0 * t).cos() * 40.0, (31.0 * t).sin() + 0.3));
    let d = size(&s, JointKind::Revolute, 0.1, &motor(), &gear(10.0, 0.9), &with_amp());
    let p = &d.operating_points;
    assert!(p.t.len() <= MAX_POINTS && p.t.len() > MAX_POINTS / 4, "{}", p.t.len());
    assert!(p.t.windows(2).all(|w| w[0] < w[1]));
    let peak = p.torque.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert_eq!(peak, value(&d, "peak_torque"));
    let top = p.speed.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert_eq!(top, value(&d, "motor_speed"));
}

#[test]
fn undriven_joints_and_bad_input() {
    let s = Samples::new(3, |t| (-3.0 * t, 0.0, 4.0 - 8.0 * t));
    let u = undriven(s.load(JointKind::Revolute, 0.0), 0.0).expect("figures");
    assert_eq!((u.peak_torque, u.max_speed), (4.0, 3.0));
    // Trapezoid over [0, 0.5, 1] of τ² = 16, 0, 16 with weights 0.25, 0.5, 0.25.
    close(u.rms_torque, 8.0_f64.sqrt(), 1e-12);
    let nan = [0.0, f64::NAN, 0.0];
    let bad = AxisLoad { qd: &nan, ..s.load(JointKind::Revolute, 0.0) };
    let e = undriven(bad, 0.0).expect_err("NaN");
    assert!(e.to_string().contains("qd[1]"), "{e}");
    let short_tau = AxisLoad { tau: &nan[..2], ..s.load(JointKind::Revolute, 0.0) };
    assert!(undriven(short_tau, 0.0).is_err());
    let empty = AxisLoad { t: &[], qd: &[], qdd: &[], tau: &[], ..s.load(JointKind::Revolute, 0.0) };
    assert!(undriven(empty, 0.0).is_err());
    assert!(undriven(s.load(JointKind::Revolute, 0.0), f64::NAN).is_err());
    let json = serde_json::to_value(&u).expect("json");
    assert_eq!(json["joint"], "J1");
}

/// A published worked example: Honpine, "How to Selection Harmonic Reduction Gear?" (2026,
/// https://www.honpine.com/news/Product-News/How-to-Selection-Harmonic-Reduction-Gear-.html),
/// step 2: the load torque pattern T1 = 150 N·m for 0.2 s at 10 r/min (start), T2 = 82 N·m for
/// 3 s at 20 r/min (constant speed), T3 = 130 N·m for 0.3 s at 10 r/min (stop), T4 = 0 for 0.2 s
/// at rest gives the average load torque "Tav = 89 N·m", below the 140 N·m FSG-25 allows. Our
/// gear_avg_torque check on the same pattern (each segment held constant: the boundary samples
/// are doubled so every segment integrates exactly) prints the same to its precision.
#[test]
fn published_example_harmonic_gear_average_torque() {
    let rpm = PI / 30.0;
    let segments = [(150.0, 0.2, 10.0), (82.0, 3.0, 20.0), (130.0, 0.3, 10.0), (0.0, 0.2, 0.0)];
    let (mut t, mut qd, mut tau) = (Vec::new(), Vec::new(), Vec::new());
    let mut start = 0.0;
    for (torque, dt, n) in segments {
        for x in [start, start + dt] {
            t.push(x);
            qd.push(n * rpm);
            tau.push(torque);
        }
        start += dt;
    }
    let qdd = vec![0.0; t.len()];
    let load = AxisLoad { joint: "J1", kind: JointKind::Revolute, t: &t, qd: &qd, qdd: &qdd, tau: &tau, load_inertia: 0.0 };
    // FSG-25: the 140 N·m the example compares with; the other ratings are out of this test.
    let g = Gear { t_avg_max: Some(140.0), t_rated: None, out_peak: None, w_in_max: None, ..gear(100.0, 1.0) };
    let d = size_drive(load, &motor(), &g, None, &with_amp(), TOP).expect("sizes");
    let avg = value(&d, "gear_avg_torque");
    assert_eq!(avg.round(), 89.0, "{avg}");
    // The formula, written out: (Σ n·t·T³ / Σ n·t)^(1/3).
    let exact = ((10.0 * 0.2 * 150f64.powi(3) + 20.0 * 3.0 * 82f64.powi(3) + 10.0 * 0.3 * 130f64.powi(3))
        / (10.0 * 0.2 + 20.0 * 3.0 + 10.0 * 0.3))
        .cbrt();
    close(avg, exact, 1e-12);
    assert_eq!(check(&d, "gear_avg_torque").status, Status::Pass);
}

/// An AC servo motor (no winding resistance in its datasheet): the torque, speed and current
/// checks against its datasheet; the voltage and braking checks name `motor.R` as missing.
#[test]
fn ac_servo_without_resistance() {
    let lib = seed::library().expect("seed");
    let id = seed::YASKAWA_SERVOS[6]; // SGM7J-04A without holding brake.
    let i = lib.instances.iter().find(|i| i.id == id).expect("SGM7J-04A");
    let m = parts::motor(lib.class(&i.class_id).expect("class"), i, &[]).expect("servo");
    assert_eq!((m.r, m.k, m.t_nom, m.t_peak), (None, 0.544, Some(1.27), Some(4.46)));
    assert!((m.j - 0.486e-4).abs() <= 1e-16, "{}", m.j);
    let back = Samples::new(11, |_| (5.0, 0.0, -20.0));
    let bus = Settings { brake: Some(Brake::Bus { capacitance: 0.001, voltage_max: 30.0 }), ..with_amp() };
    let d = size(&back, JointKind::Revolute, 0.0, &m, &gear(10.0, 0.8), &bus);
    // T_m = 20·0.8/10 = 1.6 N·m against T_peak 4.46 N·m; I = 1.6/0.544 A.
    close(value(&d, "peak_torque"), 1.6, 1e-12);
    close(check(&d, "peak_torque").limit.expect("T_peak"), 4.46, 1e-12);
    close(value(&d, "peak_current"), 1.6 / 0.544, 1e-12);
    for name in ["voltage", "braking"] {
        let c = check(&d, name);
        assert_eq!((c.status, c.missing.clone()), (Status::NotEvaluated, vec!["motor.R".to_string()]), "{name}");
    }
    // A DC motor with the same numbers has both checks.
    let dc = Motor { r: Some(1.0), ..m };
    let d = size(&back, JointKind::Revolute, 0.0, &dc, &gear(10.0, 0.8), &bus);
    assert!(check(&d, "voltage").value.is_some() && check(&d, "braking").value.is_some());
}

/// Several drives sized at once on several threads: the same results, in the order given, as
/// sized one by one against the seed catalogue (a drive that does not fit stays an error in its
/// place).
#[test]
fn drives_sized_together_on_threads() {
    let cat = Catalog::from_library(&seed::library().expect("seed"));
    let loads: Vec<Samples> = (0..5).map(|k| Samples::new(301, move |t| (1.0 + k as f64 * t, 2.0, 0.05 * (1 + k) as f64))).collect();
    let jobs: Vec<DriveJob> = loads
        .iter()
        .enumerate()
        .map(|(k, s)| DriveJob {
            load: AxisLoad { joint: ["J1", "J2", "J3", "J4", "J5"][k], ..s.load(JointKind::Revolute, 0.01 * (1 + k) as f64) },
            motor: motor(),
            // The fourth drive's gear is a screw: it does not fit a revolute joint.
            gear: if k == 3 { Gear { lead: Some(0.005), ..gear(10.0, 0.9) } } else { gear(10.0 + k as f64, 0.9) },
        })
        .collect();
    let one: Vec<_> = jobs.iter().map(|j| size_drive(j.load, &j.motor, &j.gear, Some(&cat), &with_amp(), TOP)).collect();
    for threads in [1, 2, 3, 8] {
        let together = size_drives(&jobs, Some(&cat), &with_amp(), TOP, threads);
        assert_eq!(together, one, "{threads} threads");
    }
    assert!(one[3].is_err() && one.iter().filter(|r| r.is_ok()).count() == 4);
    let names: Vec<&str> = one.iter().filter_map(|r| r.as_ref().ok()).map(|d| d.joint.as_str()).collect();
    assert_eq!(names, ["J1", "J2", "J3", "J5"]);
    assert!(one[0].as_ref().expect("J1").alternatives.len() == TOP, "ranked against the catalogue");
}

/// A ball screw's checks by hand (ISO 3408-5 as the screw makers print it): the static check
/// max |F| <= C_0a, and the nominal life L10 = (C_a/F_m)³·10⁶ revolutions against the required
/// life, checked as F_m <= C_a·(10⁶/L_req)^(1/3).
#[test]
fn screw_static_load_and_life() {
    let lead = 0.016;
    // 1 s at 0.1 m/s, then at 0.3 m/s for 1 s, with forces 1000 N and 500 N; a 2 s dwell.
    let s = Samples::over(2001, 2.0, |t| if t < 1.0 { (0.1, 0.0, 1000.0) } else { (0.3, 0.0, -500.0) });
    let screw = Gear {
        lead: Some(lead),
        t_rated: None,
        out_peak: Some(6800.0),
        out_peak_is_c0a: true,
        c_a: Some(3800.0),
        w_in_max: Some(10_000.0),
        ..gear(1.0, 1.0)
    };
    // F_m ≈ 700 N; 20 000 h of the 4 s cycle are 4.5·10⁸ revolutions: C_a allows ≈ 496 N.
    let life = Settings { dwell: 2.0, screw_life: Some(20_000.0), ..with_amp() };
    let d = size(&s, JointKind::Prismatic, 1.0, &motor(), &screw, &life);
    let st = check(&d, "screw_static_load");
    assert_eq!((st.value, st.limit, st.status, st.unit), (Some(1000.0), Some(6800.0), Status::Pass, "N"));
    assert!(st.source.as_deref().is_some_and(|x| x.contains("C_0a")) && st.rule.contains("C_0a"), "{st:?}");
    // By hand: the trapezoid weights give the two halves 0.1·(1 - 0.0005) + ... : the travel is
    // Σ|v|·w and F_m³ = Σ|v|·|F|³·w / Σ|v|·w, with w = 1 ms (0.5 ms at both ends) and the sample
    // at t = 1 s in the second half.
    let w = |i: usize| if i == 0 || i == 2000 { 0.0005 } else { 0.001 };
    let (mut travel, mut num) = (0.0, 0.0);
    for i in 0..2001 {
        let (v, f) = (s.qd[i].abs(), s.tau[i].abs());
        travel += v * w(i);
        num += v * f.powi(3) * w(i);
    }
    let f_m = (num / travel).cbrt();
    let revs = travel / lead;
    let required = 20_000.0 * 3600.0 / 4.0 * revs;
    let l = check(&d, "screw_life");
    close(l.value.expect("F_m"), f_m, 1e-12);
    close(l.limit.expect("allowed"), 3800.0 * (1e6 / required).cbrt(), 1e-12);
    assert_eq!(l.status, Status::Fail, "{l:?}");
    // The life in the detail: (C_a/F_m)³·10⁶ revolutions.
    let l10 = (3800.0 / f_m).powi(3) * 1e6;
    assert!(l.detail.contains(&short(l10)), "{} vs {}", l.detail, short(l10));
    // A 2000 h life passes (≈ 1068 N): the limit grows as the cube root of the shorter life.
    let short_life = Settings { screw_life: Some(2000.0), ..life.clone() };
    let d = size(&s, JointKind::Prismatic, 1.0, &motor(), &screw, &short_life);
    let l = check(&d, "screw_life");
    close(l.limit.expect("allowed"), 3800.0 * (1e6 / (required / 10.0)).cbrt(), 1e-12);
    assert_eq!(l.status, Status::Pass);
    // Over C_0a the static check fails.
    let heavy = Samples::new(11, |_| (0.1, 0.0, 7000.0));
    let d = size(&heavy, JointKind::Prismatic, 1.0, &motor(), &screw, &life);
    assert_eq!(check(&d, "screw_static_load").status, Status::Fail);
    // A library entered before C_0a: its F_peak stays the static limit, named as such.
    let older = Gear { out_peak: Some(5000.0), out_peak_is_c0a: false, c_a: None, ..screw.clone() };
    let d = size(&heavy, JointKind::Prismatic, 1.0, &motor(), &older, &life);
    let st = check(&d, "screw_static_load");
    assert!(st.limit == Some(5000.0) && st.source.as_deref().is_some_and(|x| x.contains("F_peak")), "{st:?}");
    assert_eq!(d.missing, vec!["gear.C_a"]);
    // A screw that never turns does not wear: not evaluated, nothing missing.
    let still = Samples::new(11, |_| (0.0, 0.0, 100.0));
    let d = size(&still, JointKind::Prismatic, 1.0, &motor(), &screw, &Settings { screw_life: None, ..life });
    assert_eq!(check(&d, "screw_life").status, Status::NotEvaluated);
    assert!(d.missing.is_empty(), "{:?}", d.missing);
}

/// The seed's catalogue ball screws in the ranking of a prismatic joint: chosen where they carry
/// the load, refused where it exceeds their static rating C_0a.
#[test]
fn catalogue_screws_are_chosen_and_refused() {
    let lib = seed::library().expect("seed");
    let cat = Catalog::from_library(&lib);
    let pbsa = |name: &str| name.starts_with("PBSA ball screw");
    let settings = Settings { screw_life: Some(5000.0), ..with_amp() };
    // 2 kN at 0.05 m/s: every PBSA screw carries it (C_0a 6.8 to 19.1 kN).
    let light = Samples::new(101, |_| (0.05, 0.0, 2000.0));
    let alts = rank(light.load(JointKind::Prismatic, 5.0), &cat, &settings, 10_000).expect("ranks");
    assert!(alts.iter().all(|a| cat.gears.iter().any(|g| g.part.id == a.gear.id && g.lead.is_some())));
    let chosen: Vec<&Alternative> = alts.iter().filter(|a| pbsa(&a.gear.name)).collect();
    assert_eq!(chosen.len(), 3 * cat.motors.len(), "each PBSA screw with every motor");
    assert!(chosen.iter().all(|a| !a.failed.contains(&"screw_static_load") && !a.missing.iter().any(|m| m == "gear.C_0a")));
    // Their life: 5000 h of 1 s cycles at 0.05 m/s are 3.125, 2.5 and 2 revolutions per cycle
    // (leads 16, 20, 25 mm), so C_a·(10⁶/L_req)^(1/3) allows 992 N, 1658 N and 2696 N: only the
    // 25 mm screw lasts 5000 h under 2 kN.
    for a in &chosen {
        assert_eq!(a.failed.contains(&"screw_life"), !a.gear.name.contains("25x25"), "{}: {:?}", a.gear.name, a.failed);
    }
    // The best-ranked alternative with a PBSA screw: its static and life checks pass.
    let best = chosen.iter().min_by_key(|a| a.rank).expect("a PBSA alternative");
    let m = cat.motors.iter().find(|m| m.part.id == best.motor.id).expect("motor");
    let g = cat.gears.iter().find(|g| g.part.id == best.gear.id).expect("screw");
    let d = size_drive(light.load(JointKind::Prismatic, 5.0), m, g, None, &settings, TOP).expect("sizes");
    assert_eq!(check(&d, "screw_static_load").status, Status::Pass);
    assert_eq!(check(&d, "screw_life").status, Status::Pass, "{:?}", check(&d, "screw_life"));
    // 10 kN: over the 16 mm screw's C_0a (6.8 kN), within the 20 and 25 mm ones' (12.2, 19.1 kN);
    // 25 kN is over all three.
    let heavy = Samples::new(101, |_| (0.05, 0.0, 10_000.0));
    let alts = rank(heavy.load(JointKind::Prismatic, 5.0), &cat, &settings, 10_000).expect("ranks");
    for a in alts.iter().filter(|a| pbsa(&a.gear.name)) {
        let refused = a.failed.contains(&"screw_static_load");
        assert_eq!(refused, a.gear.name.contains("16x16"), "{}: {:?}", a.gear.name, a.failed);
        if refused {
            assert_eq!(a.standing, Standing::Fails);
        }
    }
    let crushing = Samples::new(101, |_| (0.05, 0.0, 25_000.0));
    let alts = rank(crushing.load(JointKind::Prismatic, 5.0), &cat, &settings, 10_000).expect("ranks");
    assert!(alts.iter().filter(|a| pbsa(&a.gear.name)).all(|a| a.failed.contains(&"screw_static_load")));
}
