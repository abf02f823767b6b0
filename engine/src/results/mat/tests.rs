//! The reader on every result file in `shared/fixtures/mat` (skipped with a notice when absent)
//! and on files written here byte by byte (truncation, byte order, the refusals).

use super::*;
use nalgebra::{Matrix3, Vector3};

fn fixture(name: &str) -> Option<Vec<u8>> {
    let dir = crate::pipeline::testutil::fixtures_dir()?;
    match std::fs::read(dir.join("mat").join(name)) {
        Ok(b) => Some(b),
        Err(_) => {
            println!("NOTICE: fixture mat/{name} absent; skipped");
            None
        }
    }
}

use crate::results::write::{matrix, text_cols, text_rows};

/// A small binTrans file: time, x (series), k (constant), y = -x (negated alias), `a.der(b)`.
fn small() -> Vec<u8> {
    let mut f = Vec::new();
    text_rows(&mut f, "Aclass", &["Atrajectory", "1.1", "", "binTrans"]);
    text_cols(&mut f, "name", &["Time", "x", "k", "y", "R.T[1, 2]", "a.der(b)"]);
    text_cols(&mut f, "description", &["Time in [s]", "Position [m]", "Gain", "Mirror [m]", "", "Δ speed [m/s]"]);
    // dataInfo 4 x 6 (transposed): block, column, 0, -1.
    let info =
        [0.0, 1.0, 0.0, -1.0, 2.0, 2.0, 0.0, -1.0, 1.0, 1.0, 0.0, -1.0, 2.0, -2.0, 0.0, -1.0, 2.0, 3.0, 0.0, -1.0, 2.0, 4.0, 0.0, -1.0];
    matrix(&mut f, "dataInfo", 2, false, 4, 6, &info);
    matrix(&mut f, "data_1", 1, false, 1, 2, &[2.5, 2.5]);
    // data_2: 4 variables x 3 instants, one instant per column.
    let d2 = [0.0, 1.0, 0.5, 7.0, 0.5, 2.0, 0.5, 8.0, 0.5, 3.0, 0.5, 9.0];
    matrix(&mut f, "data_2", 1, false, 4, 3, &d2);
    f
}

#[test]
fn a_small_file_reads_in_both_spellings() {
    let bytes = small();
    let t = Trajectory::read(&bytes, "small.mat").expect("reads");
    assert_eq!(t.len(), 3);
    assert_eq!(t.time(), vec![0.0, 0.5, 0.5], "duplicate time rows at events are kept");
    let x = t.find("x").expect("x");
    assert_eq!(t.series(x), vec![1.0, 2.0, 3.0]);
    assert_eq!(t.series(t.find("y").expect("y")), vec![-1.0, -2.0, -3.0]);
    assert_eq!(t.series(t.find("k").expect("k")), vec![2.5; 3]);
    assert_eq!(t.find("R.T[1,2]"), t.find("R.T[1, 2]"));
    assert_eq!(t.find("der(a.b)"), t.find("a.der(b)"));
    let d = &t.variables[t.find("der(a.b)").expect("der")];
    assert_eq!((d.description.as_str(), d.unit()), ("Δ speed [m/s]", "m/s"));
    assert_eq!(t.precision_bytes, 4);
    // Every truncation is an error naming the matrix, never a panic.
    for cut in [1, 7, 20, 30, bytes.len() / 2, bytes.len() - 1] {
        let e = Trajectory::read(&bytes[..cut], "small.mat").expect_err("truncated");
        assert!(e.to_string().starts_with("small.mat: truncated") || e.to_string().contains("small.mat"), "{e}");
    }
    // A column beyond data_2 is named.
    let mut bad = bytes.clone();
    let pos = bad.windows(8).position(|w| w == b"dataInfo").expect("dataInfo") + 9;
    bad[pos + 4 * 5..pos + 4 * 6].copy_from_slice(&9i32.to_le_bytes()); // x's column
    let e = Trajectory::read(&bad, "small.mat").expect_err("bad column");
    assert_eq!(e.to_string(), "small.mat: variable \"x\": column 9 of data_2 does not exist");
}

#[test]
fn refusals_say_what_the_file_is() {
    if let Some(b) = fixture("kdavies4+ModelicaRes/missing-Aclass.mat") {
        assert!(matches!(Trajectory::read(&b, "v5.mat"), Err(MatError::MatlabV5 { .. })));
    }
    if let Some(b) = fixture("kdavies4+ModelicaRes/PID_1_dslin.mat") {
        assert!(matches!(Trajectory::read(&b, "dslin.mat"), Err(MatError::Linearisation { .. })));
    }
    assert!(matches!(
        Trajectory::read(b"hello world, not a mat file at all", "x.mat"),
        Err(MatError::BadMatrix { .. } | MatError::Truncated { .. })
    ));
    assert!(Trajectory::read(&[], "empty.mat").is_err());
}

/// (file, variables, time instants, a variable that must exist).
const FILES: [(&str, usize, usize, &str); 15] = [
    ("kdavies4+ModelicaRes/DoublePendulum_Dymola-7.4.mat", 1096, 502, "revolute1.phi"),
    ("kdavies4+ModelicaRes/DoublePendulum_Dymola-2012-SaveAs.mat", 1097, 502, "revolute1.phi"),
    ("kdavies4+ModelicaRes/DoublePendulum_Dymola-2014FD01.mat", 1097, 502, "revolute1.phi"),
    ("kdavies4+ModelicaRes/DoublePendulum_Dymola-2014FD01-ExportAsPlotted.mat", 6, 502, "Time"),
    ("kdavies4+ModelicaRes/unicode.mat", 6, 0, "Time"),
    ("kdavies4+ModelicaRes/ChuaCircuit_2_dsres.mat", 50, 518, "Nr.v"),
    ("kdavies4+ModelicaRes/ThreeTanks.mat", 435, 502, "Time"),
    ("lbl-srg+BuildingsPy/fullRobot.mat", 5902, 97, "axis1.gear.bearingFriction.phi"),
    ("lbl-srg+BuildingsPy/PIDHysteresis.mat", 141, 0, "Time"),
    ("lbl-srg+BuildingsPy/PlotDemo.mat", 100, 504, "Time"),
    ("OpenModelica+OMSimulator/Gain_res.mat", 4, 502, "time"),
    ("OpenModelica+OMSimulator/DualMassOscillator.CoupledSystemEq.mat", 27, 0, "Time"),
    ("OpenModelica+OMSimulator/Stair-me.mat", 3, 55, "time"),
    ("lewinj+testing-CI/BouncingBall_res.mat", 11, 508, "der(h)"),
    ("OpenModelica+OMSimulator/model_res.mat", 6, 0, "time"),
];

#[test]
fn every_fixture_reads() {
    for (name, vars, times, must) in FILES {
        let Some(bytes) = fixture(name) else { continue };
        let t = Trajectory::read(&bytes, name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.variables.len(), vars, "{name}");
        if times > 0 {
            assert_eq!(t.len(), times, "{name}");
        }
        assert!(t.find(must).is_some(), "{name}: {must}");
        let time = t.time();
        assert!(time.windows(2).all(|w| w[1] >= w[0]), "{name}: time goes back");
        for v in 0..t.variables.len() {
            assert!(t.series(v).iter().all(|x| !x.is_nan()), "{name}: {} has NaN", t.variables[v].name);
        }
    }
}

/// `r_0 + transpose(R.T)·p` of a frame at instant `i`.
fn frame(t: &Trajectory, prefix: &str, i: usize) -> (Vector3<f64>, Matrix3<f64>) {
    let get = |n: String| t.value(t.find(&n).unwrap_or_else(|| panic!("{n}")), i);
    let r = Vector3::from_fn(|k, _| get(format!("{prefix}.r_0[{}]", k + 1)));
    let m = Matrix3::from_fn(|a, b| get(format!("{prefix}.R.T[{},{}]", a + 1, b + 1)));
    (r, m)
}

/// The same MultiBody model simulated by OpenModelica 1.19 (float64) and Dymola 2021 (float32):
/// the box's pose agrees at every common instant, and both rotations are orthonormal.
#[test]
fn the_same_model_from_two_tools_has_the_same_poses() {
    let (Some(om), Some(dy)) =
        (fixture("mechanomy+ModelicaMAT/FallingBodyBox_om1.19.0.mat"), fixture("mechanomy+ModelicaMAT/FallingBodyBox_dymola2021.mat"))
    else {
        return;
    };
    let om = Trajectory::read(&om, "om.mat").expect("om");
    let dy = Trajectory::read(&dy, "dymola.mat").expect("dymola");
    assert_eq!((om.precision_bytes, dy.precision_bytes), (8, 4));
    assert_eq!((om.variables.len(), dy.variables.len()), (1317, 746));
    let (to, td) = (om.time(), dy.time());
    let mut compared = 0;
    for (i, t) in to.iter().enumerate() {
        let Some(j) = td.iter().position(|x| (x - t).abs() < 1e-9) else { continue };
        let (ro, mo) = frame(&om, "bodyBox.frame_a", i);
        let (rd, md) = frame(&dy, "bodyBox.frame_a", j);
        assert!((mo * mo.transpose() - Matrix3::identity()).amax() < 1e-12);
        assert!((md * md.transpose() - Matrix3::identity()).amax() < 1e-6);
        // A body-fixed point 0.1 m along x: r_0 + transpose(R.T)·p.
        let p = Vector3::new(0.1, 0.0, 0.0);
        let (po, pd) = (ro + mo.transpose() * p, rd + md.transpose() * p);
        assert!((po - pd).norm() < 1e-4 * (1.0 + po.norm()), "t = {t}: {po} vs {pd}");
        compared += 1;
    }
    assert!(compared > 10, "{compared} common instants");
}

/// RobotR3 from Dymola: points fixed on a link keep their distance to each other over the run
/// (rigidity), with `transpose(R.T)` (the wrong `R.T·p` breaks it).
#[test]
fn robot_r3_links_are_rigid() {
    let Some(bytes) = fixture("lbl-srg+BuildingsPy/fullRobot.mat") else { return };
    let t = Trajectory::read(&bytes, "fullRobot.mat").expect("reads");
    let n = t.len();
    let (ra, ma) = frame(&t, "mechanics.b3.frame_a", 0);
    let (rb, _) = frame(&t, "mechanics.b3.frame_b", 0);
    // frame_b in frame_a coordinates at t = 0 stays the same at every instant.
    let rel0 = ma * (rb - ra);
    let mut worst: f64 = 0.0;
    for i in 0..n {
        let (ra, ma) = frame(&t, "mechanics.b3.frame_a", i);
        let (rb, _) = frame(&t, "mechanics.b3.frame_b", i);
        worst = worst.max((ma * (rb - ra) - rel0).norm());
    }
    assert!(worst < 1e-5, "link b3 deforms by {worst} m");
}
