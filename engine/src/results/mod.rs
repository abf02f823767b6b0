//! Simulation results brought back to a converted model (issue 13, started): the MATLAB v4
//! trajectory files of Dymola and OpenModelica ([`mat`]) and the body poses in them ([`poses`]). No IO, no HTTP, no SQL.

pub mod mat;
pub mod poses;
pub mod shapes;
pub mod write;

use serde::Serialize;

use crate::mechanism::Mechanism;
use mat::{Source, Trajectory};

/// What an uploaded result holds, kept with it.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct Summary {
    pub variables: usize,
    pub instants: usize,
    pub start: f64,
    pub stop: f64,
    /// `float32` (Dymola) or `float64` (OpenModelica).
    pub precision: String,
    pub bodies: Vec<String>,
    pub from_frames: Vec<String>,
    pub from_joints: Vec<String>,
    pub missing: Vec<String>,
    pub joints_found: Vec<String>,
    pub checks: poses::PoseChecks,
    /// Dymola visual shapes and frames with `r_0`/`R.T` in the file ([`shapes`]).
    #[serde(default)]
    pub shapes: usize,
    #[serde(default)]
    pub frames: usize,
}

/// Reads a result against a version's mechanism. `Err` when the file matches nothing of the
/// model: the message says which names the file has.
pub fn summarise(t: &Trajectory, mech: &Mechanism, file: &str) -> Result<(Summary, poses::Poses), String> {
    let p = poses::extract(t, mech);
    if p.summary.bodies.is_empty() && p.summary.joints_found.is_empty() {
        let mut tops: Vec<&str> = t.variables.iter().skip(1).map(|v| v.name.split(['.', '[']).next().unwrap_or("")).collect();
        tops.sort_unstable();
        tops.dedup();
        let some: Vec<&str> = tops.into_iter().take(8).collect();
        let bodies: Vec<&str> = mech.body_names().iter().take(5).map(String::as_str).collect();
        return Err(format!(
            "{file}: none of the model's bodies (e.g. {}) or joints has variables in the file: it looks like a result of another model (its components: {})",
            bodies.join(", "),
            some.join(", ")
        ));
    }
    let s = Summary {
        bodies: p.summary.bodies.clone(),
        from_frames: p.summary.from_frames.clone(),
        from_joints: p.summary.from_joints.clone(),
        missing: p.summary.missing.clone(),
        joints_found: p.summary.joints_found.clone(),
        checks: p.summary.checks.clone(),
        ..standalone(t)
    };
    Ok((s, p))
}

/// The summary of a result of any model (no bodies of ours): its size, span and shapes.
pub fn standalone(t: &Trajectory) -> Summary {
    let scene = shapes::Scene::find(t);
    let time = t.time();
    Summary {
        variables: t.variables.len(),
        instants: t.len(),
        start: time.first().copied().unwrap_or(0.0),
        stop: time.last().copied().unwrap_or(0.0),
        precision: if t.precision_bytes == 4 { "float32".into() } else { "float64".into() },
        bodies: Vec::new(),
        from_frames: Vec::new(),
        from_joints: Vec::new(),
        missing: Vec::new(),
        joints_found: Vec::new(),
        checks: poses::PoseChecks::default(),
        shapes: scene.shapes.len(),
        frames: scene.frames.len(),
    }
}

/// A variable for listings.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VariableInfo {
    pub name: String,
    pub description: String,
    pub unit: String,
    pub constant: bool,
}

/// Variables whose name or description contains `search` (case-insensitive), at most `limit`,
/// and how many matched.
pub fn search(t: &Trajectory, search: &str, limit: usize) -> (usize, Vec<VariableInfo>) {
    let needle = search.to_lowercase();
    let mut total = 0;
    let mut out = Vec::new();
    for v in &t.variables {
        if needle.is_empty() || v.name.to_lowercase().contains(&needle) || v.description.to_lowercase().contains(&needle) {
            total += 1;
            if out.len() < limit {
                out.push(VariableInfo {
                    name: v.name.clone(),
                    description: v.description.clone(),
                    unit: v.unit().to_string(),
                    constant: matches!(v.source, Source::Constant(_)),
                });
            }
        }
    }
    (total, out)
}

/// A series thinned for `width` pixels: in each of `width` equal time intervals the smallest and
/// the largest value are kept, in the order they occur, so a line plot looks like the full data.
pub fn decimate(t: &[f64], y: &[f64], width: usize) -> (Vec<f64>, Vec<f64>) {
    let n = t.len().min(y.len());
    if n <= 2 * width.max(1) {
        return (t[..n].to_vec(), y[..n].to_vec());
    }
    let (t0, t1) = (t[0], t[n - 1]);
    let span = (t1 - t0).max(f64::MIN_POSITIVE);
    let (mut ot, mut oy) = (Vec::with_capacity(2 * width + 2), Vec::with_capacity(2 * width + 2));
    let mut i = 0;
    for bucket in 0..width {
        let end = if bucket + 1 == width { t1 } else { t0 + span * (bucket + 1) as f64 / width as f64 };
        let start = i;
        while i < n && (t[i] < end || (bucket + 1 == width)) {
            i += 1;
        }
        if i == start {
            continue;
        }
        let (mut lo, mut hi) = (start, start);
        for k in start..i {
            if y[k] < y[lo] {
                lo = k;
            }
            if y[k] > y[hi] {
                hi = k;
            }
        }
        for k in if lo <= hi { [lo, hi] } else { [hi, lo] } {
            if ot.last() != Some(&t[k]) || oy.last() != Some(&y[k]) {
                ot.push(t[k]);
                oy.push(y[k]);
            }
        }
    }
    (ot, oy)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_every_extreme_in_order() {
        let t: Vec<f64> = (0..10_000).map(|i| f64::from(i) * 1e-3).collect();
        let mut y: Vec<f64> = t.iter().map(|x| (x * 7.0).sin()).collect();
        y[5000] = 9.0; // a spike
        y[7001] = -9.0;
        let (dt, dy) = decimate(&t, &y, 100);
        assert!(dt.len() <= 200 && dt.len() >= 100, "{}", dt.len());
        assert!(dt.windows(2).all(|w| w[1] >= w[0]));
        assert!(dy.contains(&9.0) && dy.contains(&-9.0));
        assert_eq!((dt[0], *dt.last().expect("last")), (0.0, 9.999));
        let max = dy.iter().copied().fold(f64::MIN, f64::max);
        assert_eq!(max, 9.0);
        // Short series come back whole.
        assert_eq!(decimate(&t[..50], &y[..50], 100).0.len(), 50);
    }
}
