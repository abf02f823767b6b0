//! Dormand–Prince 5(4) with error control (Hairer's PI step-size controller), its continuous
//! extension of order 4, time breakpoints and state events.
//!
//! The right-hand side is smooth between *breakpoints* (times where it kinks, e.g. the
//! corners of a linearly interpolated reference) and between *events* (zero crossings of the
//! problem's switching functions, e.g. a limiter's input crossing its limit): a step never
//! crosses either. A step ends exactly on the next breakpoint; a step across which a switching
//! function changes sign, and after which the problem wants another mode, is cut back to the
//! crossing (Illinois root finding on the continuous extension, to [`EVENT_TIME_TOL`]), the
//! problem switches its mode there and the integration restarts (the derivative recomputed).
//! Within a mode the problem evaluates its equations without switching (a limiter stays linear
//! or saturated while a trial stage overshoots), so the error estimate sees a smooth function
//! and no mode chatters: a mode changes only at a located crossing.

/// Event times are located to this width (s), relative to max(1, |t|).
pub const EVENT_TIME_TOL: f64 = 1e-12;

/// A problem for [`integrate`]: `dy = f(t, y)` in the current mode, with switching functions.
pub trait Problem {
    /// `dy` and the switching functions `g` at `(t, y)` in the current mode.
    fn eval(&self, t: f64, y: &[f64], dy: &mut [f64], g: &mut [f64]);
    /// Number of switching functions.
    fn switches(&self) -> usize;
    /// Whether the switching functions `g` call for another mode than the current one.
    fn wants_switch(&self, g: &[f64]) -> bool;
    /// Switch to the mode `g` calls for.
    fn switch(&self, g: &[f64]);
    /// The first breakpoint strictly after `t` (infinity when none).
    fn next_break(&self, t: f64) -> f64;
    /// Called at each output time (in increasing order) with the state there.
    fn sample(&self, t: f64, y: &[f64]);
    /// Asked after every accepted step: true stops the integration.
    fn stop(&self, t: f64) -> bool;
}

/// Integration settings.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    pub rtol: f64,
    pub atol: f64,
    pub h_max: f64,
    pub max_steps: u32,
    /// Output times are `k·output_interval` up to `t_end`.
    pub output_interval: f64,
}

/// Counters of a finished integration.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    pub accepted: u32,
    pub rejected: u32,
    pub events: u32,
    /// Crossings right after an event that did not switch (see [`integrate`]).
    pub held: u32,
}

/// Why the integration ended early.
#[derive(Clone, Debug, PartialEq)]
pub enum Failure {
    /// The step budget ran out at `t`.
    MaxSteps { t: f64, steps: u32 },
    /// The step size fell below what `t` resolves.
    StepUnderflow { t: f64 },
    /// A non-finite derivative or error estimate at `t`.
    NotFinite { t: f64 },
    /// [`Problem::stop`] answered true.
    Stopped { t: f64 },
}

const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A2: [f64; 1] = [1.0 / 5.0];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0];
const A6: [f64; 5] = [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0];
/// The 5th-order weights (also the 7th stage's row: first same as last).
const B: [f64; 6] = [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0];
/// Error weights: 5th minus 4th order.
const E: [f64; 7] = [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];
/// Continuous extension (Hairer, Nørsett & Wanner, Solving ODEs I, dopri5's `contd5`).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// The continuous extension of one step from `t0` over `h`.
struct Dense {
    t0: f64,
    h: f64,
    r: [Vec<f64>; 5],
}

impl Dense {
    fn new(n: usize) -> Self {
        Dense { t0: 0.0, h: 0.0, r: std::array::from_fn(|_| vec![0.0; n]) }
    }

    fn build(&mut self, t0: f64, h: f64, y0: &[f64], y1: &[f64], k: &[Vec<f64>; 7]) {
        self.t0 = t0;
        self.h = h;
        for i in 0..y0.len() {
            let dy = y1[i] - y0[i];
            let bspl = h * k[0][i] - dy;
            self.r[0][i] = y0[i];
            self.r[1][i] = dy;
            self.r[2][i] = bspl;
            self.r[3][i] = dy - h * k[6][i] - bspl;
            self.r[4][i] = h * (D[0] * k[0][i] + D[2] * k[2][i] + D[3] * k[3][i] + D[4] * k[4][i] + D[5] * k[5][i] + D[6] * k[6][i]);
        }
    }

    fn at(&self, t: f64, out: &mut [f64]) {
        let th = if self.h == 0.0 { 1.0 } else { (t - self.t0) / self.h };
        let th1 = 1.0 - th;
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.r[0][i] + th * (self.r[1][i] + th1 * (self.r[2][i] + th * (self.r[3][i] + th1 * self.r[4][i])));
        }
    }
}

fn rms(n: usize, f: impl Fn(usize) -> f64) -> f64 {
    ((0..n).map(|i| f(i).powi(2)).sum::<f64>() / n.max(1) as f64).sqrt()
}

/// Integrates `p` from `(0, y)` to `t_end`; `y` holds the final state on return (or the state
/// where it stopped). Samples go to [`Problem::sample`] at every multiple of the output
/// interval up to `t_end` (the last one within 1e-9 relative of `t_end` included).
pub fn integrate<P: Problem>(p: &P, y: &mut [f64], t_end: f64, s: &Settings) -> Result<Stats, Failure> {
    let n = y.len();
    let ng = p.switches();
    let mut stats = Stats::default();
    let mut k: [Vec<f64>; 7] = std::array::from_fn(|_| vec![0.0; n]);
    let (mut y1, mut ys, mut yerr) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut g0, mut g1, mut gs) = (vec![0.0; ng], vec![0.0; ng], vec![0.0; ng]);
    let mut dense = Dense::new(n);
    let h_max = if s.h_max > 0.0 { s.h_max } else { t_end };
    let mut t = 0.0f64;
    p.eval(t, y, &mut k[0], &mut g0);
    if !k[0].iter().all(|x| x.is_finite()) {
        return Err(Failure::NotFinite { t });
    }
    if p.wants_switch(&g0) {
        p.switch(&g0);
        p.eval(t, y, &mut k[0], &mut g0);
    }
    let mut next_out = 0usize;
    let out_time = |k: usize| k as f64 * s.output_interval;
    let t_last = t_end * (1.0 + 1e-9);
    while out_time(next_out) <= t_last && out_time(next_out) <= 0.0 {
        p.sample(0.0, y);
        next_out += 1;
    }
    let (k0, rest) = k.split_at_mut(1);
    let mut h = initial_step(p, y, &k0[0], s, h_max, &mut y1, &mut rest[0], &mut gs);
    let mut facold = 1e-4f64;
    let mut last_rejected = false;
    let mut after_event = false;
    let expo1 = 0.2 - 0.04 * 0.75;
    while t < t_end {
        if stats.accepted + stats.rejected >= s.max_steps {
            return Err(Failure::MaxSteps { t, steps: stats.accepted + stats.rejected });
        }
        // Never step across a breakpoint or the end.
        let mut bp = p.next_break(t);
        let tiny = 1e-13 * t.abs().max(1.0);
        while bp <= t + tiny {
            bp = p.next_break(bp.max(t) + tiny);
        }
        let stop_at = bp.min(t_end);
        h = h.min(h_max);
        let mut hits = false;
        if t + h * 1.01 >= stop_at {
            h = stop_at - t;
            hits = true;
        }
        if h <= 1e-14 * t.abs().max(1.0) {
            return Err(Failure::StepUnderflow { t });
        }
        // The stages.
        stage(n, y, h, &k, &A2, &mut ys);
        p.eval(t + C[1] * h, &ys, &mut k[1], &mut gs);
        stage(n, y, h, &k, &A3, &mut ys);
        p.eval(t + C[2] * h, &ys, &mut k[2], &mut gs);
        stage(n, y, h, &k, &A4, &mut ys);
        p.eval(t + C[3] * h, &ys, &mut k[3], &mut gs);
        stage(n, y, h, &k, &A5, &mut ys);
        p.eval(t + C[4] * h, &ys, &mut k[4], &mut gs);
        stage(n, y, h, &k, &A6, &mut ys);
        p.eval(t + h, &ys, &mut k[5], &mut gs);
        stage(n, y, h, &k, &B, &mut y1);
        let t1 = if hits { stop_at } else { t + h };
        p.eval(t1, &y1, &mut k[6], &mut g1);
        for i in 0..n {
            yerr[i] = h * (E[0] * k[0][i] + E[2] * k[2][i] + E[3] * k[3][i] + E[4] * k[4][i] + E[5] * k[5][i] + E[6] * k[6][i]);
        }
        let err = rms(n, |i| yerr[i] / (s.atol + s.rtol * y[i].abs().max(y1[i].abs())));
        if !err.is_finite() {
            // A stage left the domain (or the problem failed): retry smaller, then give up.
            stats.rejected += 1;
            h *= 0.1;
            last_rejected = true;
            if !k[0].iter().all(|x| x.is_finite()) {
                return Err(Failure::NotFinite { t });
            }
            continue;
        }
        let fac11 = err.powf(expo1);
        if err > 1.0 {
            stats.rejected += 1;
            h /= (fac11 / 0.9).min(5.0);
            last_rejected = true;
            continue;
        }
        // Accepted: the next step size (PI control).
        let fac = (fac11 / facold.powf(0.04) / 0.9).clamp(0.1, 5.0);
        let mut h_new = h / fac;
        if last_rejected {
            h_new = h_new.min(h);
        }
        facold = err.max(1e-4);
        last_rejected = false;
        stats.accepted += 1;
        dense.build(t, if hits { stop_at - t } else { h }, y, &y1, &k);
        // An event within the step: cut it back to the first crossing.
        let mut t_step_end = t1;
        let mut switched = false;
        let crosses = |j: usize| (g0[j] > 0.0) != (g1[j] > 0.0) || (g0[j] < 0.0) != (g1[j] < 0.0);
        if ng > 0 && (0..ng).any(crosses) && p.wants_switch(&g1) {
            let mut first = t1;
            for j in 0..ng {
                if crosses(j) {
                    let r = locate(p, &dense, j, t, g0[j], t1, g1[j], &mut ys, &mut k[1], &mut gs);
                    first = first.min(r);
                }
            }
            // A crossing right at the start of the step after an event: the new mode's switching
            // function calls for the old mode at once (e.g. a lossy gear between its two power
            // flows, which MSL's LossyGear locks). The mode holds (no zero-length ping-pong)
            // until one of its switching functions crosses again.
            if after_event && first - t <= 10.0 * EVENT_TIME_TOL * t.abs().max(1.0) {
                stats.held += 1;
            } else {
                t_step_end = first;
                switched = true;
            }
        }
        after_event = switched;
        // Output samples within (t, t_step_end].
        while next_out as f64 * s.output_interval <= t_last && out_time(next_out) <= t_step_end.min(t_last) {
            let to = out_time(next_out).min(t_end);
            if to >= t1 {
                p.sample(to, &y1);
            } else {
                dense.at(to, &mut ys);
                p.sample(to, &ys);
            }
            next_out += 1;
        }
        if switched && t_step_end < t1 {
            stats.events += 1;
            dense.at(t_step_end, y);
            t = t_step_end;
            p.eval(t, y, &mut k[0], &mut gs);
            p.switch(&gs);
            p.eval(t, y, &mut k[0], &mut g0);
            h = h_new.min(h);
        } else {
            y.copy_from_slice(&y1);
            t = t1;
            if switched {
                stats.events += 1;
                p.switch(&g1);
                p.eval(t, y, &mut k[0], &mut g0);
            } else {
                k.swap(0, 6);
                g0.copy_from_slice(&g1);
            }
            h = h_new;
        }
        if !k[0].iter().all(|x| x.is_finite()) {
            return Err(Failure::NotFinite { t });
        }
        if p.stop(t) {
            return Err(Failure::Stopped { t });
        }
    }
    Ok(stats)
}

fn stage(n: usize, y: &[f64], h: f64, k: &[Vec<f64>; 7], a: &[f64], out: &mut [f64]) {
    for i in 0..n {
        let mut acc = 0.0;
        for (j, aj) in a.iter().enumerate() {
            acc += aj * k[j][i];
        }
        out[i] = y[i] + h * acc;
    }
}

/// Hairer's starting step.
#[allow(clippy::too_many_arguments)]
fn initial_step<P: Problem>(p: &P, y: &[f64], f0: &[f64], s: &Settings, h_max: f64, y1: &mut [f64], f1: &mut [f64], g: &mut [f64]) -> f64 {
    let n = y.len();
    let sc = |i: usize| s.atol + s.rtol * y[i].abs();
    let d0 = rms(n, |i| y[i] / sc(i));
    let d1 = rms(n, |i| f0[i] / sc(i));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 }.min(h_max);
    for i in 0..n {
        y1[i] = y[i] + h0 * f0[i];
    }
    p.eval(h0, y1, f1, g);
    let d2 = rms(n, |i| (f1[i] - f0[i]) / sc(i)) / h0;
    let h1 = if d1.max(d2) <= 1e-15 { (h0 * 1e-3).max(1e-6) } else { (0.01 / d1.max(d2)).powf(0.2) };
    (100.0 * h0).min(h1).min(h_max)
}

/// The first time in (a, b] where switching function `j` has the sign it has at `b`: Illinois
/// on the continuous extension, to [`EVENT_TIME_TOL`]; returns the right end of the bracket.
#[allow(clippy::too_many_arguments)]
fn locate<P: Problem>(
    p: &P,
    dense: &Dense,
    j: usize,
    mut a: f64,
    mut ga: f64,
    mut b: f64,
    mut gb: f64,
    y: &mut [f64],
    dy: &mut [f64],
    g: &mut [f64],
) -> f64 {
    let tol = EVENT_TIME_TOL * b.abs().max(1.0);
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= tol {
            break;
        }
        let mut t = if ga != gb { b - gb * (b - a) / (gb - ga) } else { 0.5 * (a + b) };
        // Keep the new point well inside the bracket.
        if !(t > a + 0.5 * tol && t < b - 0.5 * tol) {
            t = 0.5 * (a + b);
        }
        dense.at(t, y);
        p.eval(t, y, dy, g);
        let gt = g[j];
        if (gt > 0.0) == (gb > 0.0) && (gt < 0.0) == (gb < 0.0) {
            b = t;
            gb = gt;
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            a = t;
            ga = gt;
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use std::cell::{Cell, RefCell};

    use super::*;

    /// y' = -y + u, u = limit(5·(1 - y)·... ) : a saturating feedback whose kink time is known.
    struct Sat {
        mode: Cell<i8>,
        samples: RefCell<Vec<(f64, f64)>>,
        evals: Cell<u32>,
    }

    impl Problem for Sat {
        fn eval(&self, t: f64, _y: &[f64], dy: &mut [f64], g: &mut [f64]) {
            self.evals.set(self.evals.get() + 1);
            // u = t² until it reaches 1, then 1: a kink at t = 1.
            let u = if self.mode.get() == 1 { 1.0 } else { t * t };
            dy[0] = u;
            g[0] = t * t - 1.0;
        }
        fn switches(&self) -> usize {
            1
        }
        fn wants_switch(&self, g: &[f64]) -> bool {
            (g[0] > 0.0) != (self.mode.get() == 1)
        }
        fn switch(&self, g: &[f64]) {
            self.mode.set(if g[0] > 0.0 { 1 } else { 0 });
        }
        fn next_break(&self, _t: f64) -> f64 {
            f64::INFINITY
        }
        fn sample(&self, t: f64, y: &[f64]) {
            self.samples.borrow_mut().push((t, y[0]));
        }
        fn stop(&self, _t: f64) -> bool {
            false
        }
    }

    fn exact(t: f64) -> f64 {
        if t <= 1.0 {
            t.powi(3) / 3.0
        } else {
            1.0 / 3.0 + (t - 1.0)
        }
    }

    #[test]
    fn a_saturation_is_an_event_and_the_solution_is_exact_across_it() {
        let p = Sat { mode: Cell::new(0), samples: RefCell::new(Vec::new()), evals: Cell::new(0) };
        let mut y = vec![0.0];
        let s = Settings { rtol: 1e-10, atol: 1e-12, h_max: 0.0, max_steps: 10_000, output_interval: 0.25 };
        let stats = integrate(&p, &mut y, 2.0, &s).expect("integrates");
        assert_eq!(stats.events, 1, "{stats:?}");
        let samples = p.samples.borrow();
        assert_eq!(samples.len(), 9, "{samples:?}");
        for &(t, v) in samples.iter() {
            assert!((v - exact(t)).abs() < 1e-12, "t = {t}: {v} vs {}", exact(t));
        }
        assert!((y[0] - exact(2.0)).abs() < 1e-12);
        // Piecewise polynomial of degree <= 3: a handful of steps, no rejections near the kink.
        assert!(stats.accepted < 40 && stats.rejected <= 2, "{stats:?}");
    }

    #[test]
    fn the_continuous_extension_is_fourth_order() {
        // y' = cos t: the extension between steps is within the tolerance of sin t.
        struct Cos(RefCell<Vec<(f64, f64)>>);
        impl Problem for Cos {
            fn eval(&self, t: f64, _y: &[f64], dy: &mut [f64], _g: &mut [f64]) {
                dy[0] = t.cos();
            }
            fn switches(&self) -> usize {
                0
            }
            fn wants_switch(&self, _g: &[f64]) -> bool {
                false
            }
            fn switch(&self, _g: &[f64]) {}
            fn next_break(&self, t: f64) -> f64 {
                // A breakpoint every 0.7 s: steps end there exactly.
                ((t / 0.7).floor() + 1.0) * 0.7
            }
            fn sample(&self, t: f64, y: &[f64]) {
                self.0.borrow_mut().push((t, y[0]));
            }
            fn stop(&self, _t: f64) -> bool {
                false
            }
        }
        let p = Cos(RefCell::new(Vec::new()));
        let mut y = vec![0.0];
        let s = Settings { rtol: 1e-9, atol: 1e-12, h_max: 0.0, max_steps: 10_000, output_interval: 0.01 };
        integrate(&p, &mut y, 3.0, &s).expect("integrates");
        let samples = p.0.borrow();
        assert_eq!(samples.len(), 301);
        let worst = samples.iter().map(|(t, v)| (v - t.sin()).abs()).fold(0.0f64, f64::max);
        assert!(worst < 1e-8, "{worst}");
    }
}
