//! Unit tests of the sizing: numbers against hand-computed formulas.

use std::f64::consts::PI;

use super::*;
use crate::library::{seed, Value};

fn part(name: &str) -> PartRef {
    PartRef { id: format!("id-{name}"), name: name.to_string() }
}

/// R = 1 Ω, k = 0.1 N·m/A, J = 1e-4 kg·m², d = 0, 24 V, 5 A; T_nom 0.2 N·m, 300 rad/s.
fn motor() -> Motor {
    Motor {
        part: part("M"),
        r: 1.0,
        k: 0.1,
        j: 1e-4,
        d: 0.0,
        v_max: Some(24.0),
        i_max: Some(5.0),
        t_nom: Some(0.2),
        t_peak: None,
        w_max: Some(300.0),
    }
}

fn gear(ratio: f64, eta: f64) -> Gear {
    Gear {
        part: part("G"),
        ratio,
        eta,
        lead: None,
        ratio_editable: false,
        ratio_min: None,
        ratio_max: None,
        t_rated: Some(10.0),
        out_peak: Some(20.0),
        w_in_max: Some(500.0),
        j_in: None,
    }
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
        let t: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
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

fn close(a: f64, b: f64, rel: f64) {
    assert!((a - b).abs() <= rel * b.abs().max(1e-300), "{a} vs {b}");
}

/// Constant speed against a constant driving load: T_m = τ/(n·η) + d·ω_m everywhere.
#[test]
fn constant_speed() {
    let s = Samples::new(101, |_| (5.0, 0.0, 2.0));
    let m = Motor { d: 1e-5, ..motor() };
    let g = gear(10.0, 0.8);
    let d = size_drive(s.load(JointKind::Revolute, 0.5), &m, &g, None, TOP).expect("sizes");
    let w_m = 50.0;
    let t_m = 2.0 / (10.0 * 0.8) + 1e-5 * w_m;
    close(check(&d, "peak_torque").value, t_m, 1e-12);
    close(check(&d, "rms_torque").value, t_m, 1e-12);
    close(check(&d, "motor_speed").value, w_m, 1e-12);
    close(check(&d, "gear_input_speed").value, w_m, 1e-12);
    close(check(&d, "voltage").value, 1.0 * t_m / 0.1 + 0.1 * w_m, 1e-12);
    close(check(&d, "gear_peak_torque").value, 2.0, 1e-12);
    close(check(&d, "gear_rms_torque").value, 2.0, 1e-12);
    close(check(&d, "inertia_ratio").value, 0.5 / (100.0 * 1e-4), 1e-12);
    // Peak limit: k·I_max = 0.5 N·m (no datasheet T_peak); margin (limit - value)/limit.
    let peak = check(&d, "peak_torque");
    assert_eq!(peak.limit, Some(0.5));
    close(peak.margin.expect("margin"), (0.5 - t_m) / 0.5, 1e-12);
    assert!(peak.detail.contains("k·I_max"), "{}", peak.detail);
    // RMS 0.2505 > T_nom 0.2: fails; the inertia ratio 50 > 10 fails too.
    assert!(!check(&d, "rms_torque").pass);
    assert!(!check(&d, "inertia_ratio").pass);
    assert!(!d.pass);
    assert!(d.missing.is_empty(), "{:?}", d.missing);
    assert_eq!(check(&d, "braking_energy").value, 0.0);
    assert_eq!(d.envelope.no_load_speed, Some(240.0));
    assert_eq!(d.envelope.peak_torque, Some(0.5));
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
    let d = size_drive(s.load(JointKind::Revolute, jl), &m, &g, None, TOP).expect("sizes");
    let c = jl * a / n + (1e-4 + 2e-5) * n * a;
    let e = 2e-4 * n * a;
    close(check(&d, "peak_torque").value, c + e, 1e-12);
    close(check(&d, "rms_torque").value, (c * c + c * e + e * e / 3.0).sqrt(), 1e-6);
    close(check(&d, "motor_speed").value, n * a, 1e-12);
    close(check(&d, "voltage").value, (c + e) / 0.1 + 0.1 * n * a, 1e-12);
    assert!(check(&d, "voltage").detail.contains("t = 1 s"), "{}", check(&d, "voltage").detail);
    close(check(&d, "inertia_ratio").value, jl / (n * n * 1e-4), 1e-12);
    assert!(d.pass, "{:#?}", d.checks);
    assert_eq!(d.operating_points.t.len(), 1001);
}

/// Efficiency in the direction of power flow: a driving load costs τ/(n·η), a load that drives
/// the motor back (lowering a weight) gives only τ·η/n, and its power is braking energy.
#[test]
fn efficiency_follows_the_power_flow() {
    let g = gear(10.0, 0.8);
    let drive = Samples::new(11, |_| (5.0, 0.0, 2.0));
    let d = size_drive(drive.load(JointKind::Revolute, 0.0), &motor(), &g, None, TOP).expect("sizes");
    close(check(&d, "peak_torque").value, 2.0 / (10.0 * 0.8), 1e-12);
    let back = Samples::new(11, |_| (5.0, 0.0, -2.0));
    let d = size_drive(back.load(JointKind::Revolute, 0.0), &motor(), &g, None, TOP).expect("sizes");
    close(check(&d, "peak_torque").value, 2.0 * 0.8 / 10.0, 1e-12);
    close(d.operating_points.torque[3], -0.16, 1e-12);
    // Braking power T_m·ω_m = -0.16·50 = -8 W for 1 s.
    let b = check(&d, "braking_energy");
    close(b.value, 8.0, 1e-12);
    assert!(b.pass && b.limit.is_none() && b.margin.is_none());
    assert!(b.detail.contains("braking resistor"), "{}", b.detail);
}

/// A lead screw: ω_m = ratio·2π/lead·ṡ, T_m = F·lead/(2π·ratio); the force limit is F_peak.
#[test]
fn lead_screw_converts_force_to_torque() {
    let lead = 0.005;
    let s = Samples::new(11, |_| (0.1, 0.0, 100.0));
    let screw = Gear { lead: Some(lead), t_rated: None, out_peak: None, ..gear(2.0, 1.0) };
    let m = Motor { w_max: None, ..motor() };
    let d = size_drive(s.load(JointKind::Prismatic, 3.0), &m, &screw, None, TOP).expect("sizes");
    close(check(&d, "peak_torque").value, 100.0 * lead / (2.0 * PI * 2.0), 1e-12);
    close(check(&d, "gear_input_speed").value, 2.0 * 2.0 * PI / lead * 0.1, 1e-12);
    let n = 2.0 * 2.0 * PI / lead;
    close(check(&d, "inertia_ratio").value, 3.0 / (n * n * 1e-4), 1e-12);
    assert!(d.checks.iter().all(|c| c.check != "gear_rms_torque"));
    assert_eq!(d.missing, vec!["motor.w_max", "gear.F_peak"]);
    // A screw on a revolute joint (and a rotary gear on a prismatic one) is refused.
    let e = size_drive(s.load(JointKind::Revolute, 3.0), &m, &screw, None, TOP).expect_err("does not fit");
    assert!(e.to_string().contains("fits prismatic joints"), "{e}");
}

/// A missing datasheet value omits its check and names the parameter.
#[test]
fn missing_datasheet_values_are_named() {
    let s = Samples::new(11, |_| (1.0, 0.0, 1.0));
    let m = Motor { t_nom: None, i_max: None, ..motor() };
    let g = Gear { t_rated: None, ..gear(10.0, 1.0) };
    let d = size_drive(s.load(JointKind::Revolute, 0.0), &m, &g, None, TOP).expect("sizes");
    assert_eq!(d.missing, vec!["motor.T_peak", "motor.T_nom", "gear.T_rated"]);
    for gone in ["peak_torque", "rms_torque", "gear_rms_torque"] {
        assert!(d.checks.iter().all(|c| c.check != gone), "{gone}");
    }
    assert_eq!(d.envelope.continuous_torque, None);
    assert_eq!(d.envelope.peak_torque, None);
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
    assert_eq!((re40.k, re40.t_nom, re40.t_peak), (0.0302, Some(0.17), None));
    close(re40.w_max.expect("w_max"), 12000.0 * PI / 30.0, 1e-12);
    assert_eq!(re40.peak_rule(), Some(PeakRule::CurrentLimit(0.0302 * 5.77)));
    let (c, i) = inst(seed::MAXON_RE40_MSL);
    let msl = parts::motor(c, i, &[]).expect("RE 40 MSL");
    close(msl.k, (24.0 - 0.317 * 5.77) / (6940.0 * PI / 30.0), 1e-12);
    assert_eq!(msl.peak_rule(), None);
    let (c, i) = inst(seed::MAXON_GP42C_74);
    let gp = parts::gear(c, i, &[("ratio".into(), Value::Real(43.0))]).expect("GP 42 C");
    assert_eq!((gp.ratio, gp.eta, gp.t_rated, gp.out_peak), (43.0, 0.72, Some(15.0), Some(22.5)));
    assert!(gp.ratio_editable);
    let (c, i) = inst(seed::BALL_SCREW_16X5);
    let screw = parts::gear(c, i, &[]).expect("screw");
    assert_eq!((screw.lead, screw.fits()), (Some(0.005), JointKind::Prismatic));
    let (c, i) = inst(seed::ROBOT_R3_CONTROLLER);
    let e = parts::motor(c, i, &[]).expect_err("a controller is no motor");
    assert!(e.to_string().contains("not a motor the sizing knows"), "{e}");
    let e = parts::gear(c, i, &[]).expect_err("a controller is no gear");
    assert!(matches!(e, SizingError::UnknownClass { slot: "gear", .. }), "{e}");
    let cat = Catalog::from_library(&lib);
    // 5 motors of the first seed and 14 catalogue motors; 3 gears of the first seed and 60
    // catalogue gear units.
    assert_eq!((cat.motors.len(), cat.gears.len(), cat.skipped.len()), (19, 63, 0));
}

/// Ranking: only passing combinations, complete ones first, then the smallest rotor, then the
/// larger margin; gear ratios tried are the gear's own and the standard ones within limits.
#[test]
fn ranking_order() {
    let s = Samples::new(201, |t| (2.0 * t, 2.0, 0.4 + 0.02 * 2.0));
    let small = Motor { part: part("small"), j: 1e-6, t_nom: Some(0.001), ..motor() };
    let mid = Motor { part: part("mid"), j: 2e-5, ..motor() };
    let big = Motor { part: part("big"), j: 5e-5, ..motor() };
    let unknown = Motor { part: part("unknown"), j: 1e-5, t_nom: None, ..motor() };
    let fixed = Gear { part: part("fixed 20"), ..gear(20.0, 0.9) };
    let free = Gear { part: part("free"), ratio_editable: true, ratio_min: Some(-100.0), ratio_max: Some(50.0), ..gear(12.0, 1.0) };
    let screw = Gear { part: part("screw"), lead: Some(0.01), ..gear(1.0, 1.0) };
    assert_eq!(ratios(&free), vec![12.0, 1.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 30.0, 50.0]);
    let cat = Catalog { motors: vec![big, unknown, small, mid], gears: vec![screw, free, fixed], skipped: vec![] };
    let alts = rank(s.load(JointKind::Revolute, 0.02), &cat, 100).expect("ranks");
    assert!(!alts.is_empty());
    assert!(alts.iter().all(|a| a.gear.name != "screw" && a.motor.name != "small"), "{alts:#?}");
    for (i, a) in alts.iter().enumerate() {
        assert_eq!(a.rank, i + 1);
        assert!(a.margin >= 0.0, "{a:?}");
    }
    let order: Vec<(&str, bool)> = alts.iter().map(|a| (a.motor.name.as_str(), a.missing.is_empty())).collect();
    let first_incomplete = order.iter().position(|(_, complete)| !complete).expect("unknown passes unchecked");
    assert!(order[first_incomplete..].iter().all(|(m, c)| !c && *m == "unknown"), "{order:?}");
    let complete: Vec<&str> = order[..first_incomplete].iter().map(|(m, _)| *m).collect();
    let mids = complete.iter().filter(|m| **m == "mid").count();
    assert!(mids > 0 && complete[..mids].iter().all(|m| *m == "mid"), "{complete:?}");
    for w in alts[..mids].windows(2) {
        assert!(w[0].margin >= w[1].margin, "{alts:#?}");
    }
    // Every alternative really passes when sized as the drive.
    for a in &alts {
        let m = cat.motors.iter().find(|m| m.part == a.motor).expect("motor");
        let g = Gear { ratio: a.ratio, ..cat.gears.iter().find(|g| g.part == a.gear).expect("gear").clone() };
        let d = size_drive(s.load(JointKind::Revolute, 0.02), m, &g, None, TOP).expect("sizes");
        assert!(d.pass, "{a:?}");
        close(d.checks.iter().filter_map(|c| c.margin).fold(f64::INFINITY, f64::min), a.margin, 1e-12);
    }
    let top3 = rank(s.load(JointKind::Revolute, 0.02), &cat, 3).expect("ranks");
    assert_eq!(top3.as_slice(), &alts[..3]);
}

/// 10,001 samples are decimated to at most 2000 points that keep the extremes.
#[test]
fn operating_points_keep_the_extremes() {
    let s = Samples::new(10_001, |t| ((7.0 * t).sin() * 3.0, (13.0 * t).cos() * 40.0, (31.0 * t).sin() + 0.3));
    let d = size_drive(s.load(JointKind::Revolute, 0.1), &motor(), &gear(10.0, 0.9), None, TOP).expect("sizes");
    let p = &d.operating_points;
    assert!(p.t.len() <= MAX_POINTS && p.t.len() > MAX_POINTS / 4, "{}", p.t.len());
    assert!(p.t.windows(2).all(|w| w[0] < w[1]));
    let peak = p.torque.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert_eq!(peak, check(&d, "peak_torque").value);
    let top = p.speed.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert_eq!(top, check(&d, "motor_speed").value);
}

#[test]
fn undriven_joints_and_bad_input() {
    let s = Samples::new(3, |t| (-3.0 * t, 0.0, 4.0 - 8.0 * t));
    let u = undriven(s.load(JointKind::Revolute, 0.0)).expect("figures");
    assert_eq!((u.peak_torque, u.max_speed), (4.0, 3.0));
    // Trapezoid over [0, 0.5, 1] of τ² = 16, 0, 16 with weights 0.25, 0.5, 0.25.
    close(u.rms_torque, 8.0_f64.sqrt(), 1e-12);
    let nan = [0.0, f64::NAN, 0.0];
    let bad = AxisLoad { qd: &nan, ..s.load(JointKind::Revolute, 0.0) };
    let e = undriven(bad).expect_err("NaN");
    assert!(e.to_string().contains("qd[1]"), "{e}");
    let short_tau = AxisLoad { tau: &nan[..2], ..s.load(JointKind::Revolute, 0.0) };
    assert!(undriven(short_tau).is_err());
    let empty = AxisLoad { t: &[], qd: &[], qdd: &[], tau: &[], ..s.load(JointKind::Revolute, 0.0) };
    assert!(undriven(empty).is_err());
    let json = serde_json::to_value(&u).expect("json");
    assert_eq!(json["joint"], "J1");
}
