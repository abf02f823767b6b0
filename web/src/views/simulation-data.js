// Closed-loop simulation (issue 28): the request body from the form and the rows of the answer's
// per-drive table. Pure functions (tested in simulation-data.test.js).

/**
 * The POST body of `/api/models/{id}/simulations` for a motion: the run lasts the motion plus
 * half a second of settling; tolerances only when set (joint error in mrad/mm, tool error in mm);
 * `live`: the run sends its poses to the Live tab while it runs (paced to the wall clock).
 * @param {{motionId: string, motionDuration: number, maxJointErrorMilli: string|number, maxToolErrorMm: string|number, live?: boolean}} f
 */
export function simulationBody(f) {
  const body = { duration: Math.min(60, Math.max(0.01, Number(f.motionDuration) + 0.5)), drives: true, motion_id: f.motionId };
  if (f.live) body.live = true;
  const j = Number(f.maxJointErrorMilli);
  if (f.maxJointErrorMilli !== '' && Number.isFinite(j) && j > 0) body.max_joint_error = j / 1000;
  const t = Number(f.maxToolErrorMm);
  if (f.maxToolErrorMm !== '' && Number.isFinite(t) && t > 0) body.max_tool_error = t / 1000;
  return body;
}

/**
 * One row per drive: joint, errors, current and voltage against their limits (with the share of
 * the limit used), and where the motor saturated.
 * @param {object} answer the service's answer
 */
export function driveRows(answer) {
  return (answer.drives || []).map((d) => ({
    joint: d.joint,
    unit: d.unit,
    maxError: d.max_error,
    rmsError: d.rms_error,
    current: `${d.max_current.toPrecision(3)} / ${d.i_max.toPrecision(3)} A`,
    currentShare: d.i_max > 0 ? d.max_current / d.i_max : null,
    voltage: `${d.max_voltage.toPrecision(3)} / ${d.v_max.toPrecision(3)} V`,
    voltageShare: d.v_max > 0 ? d.max_voltage / d.v_max : null,
    saturated: d.saturated.length ? d.saturated.map(([a, b]) => `${a.toFixed(3)}–${b.toFixed(3)} s`).join(', ') : 'never',
  }));
}

/** The result variable of a joint coordinate's position: `<joint>.phi`, or `<joint>.s` for a prismatic one (unit m). */
export function positionVariable(joint, unit) {
  return `${joint}.${unit === 'm' ? 's' : 'phi'}`;
}

/** The value of series {t, y} at time `t` by linear interpolation, clamped to its ends; null when empty. */
export function valueAt(series, t) {
  const ts = series?.t;
  if (!ts?.length) return null;
  if (t <= ts[0]) return series.y[0];
  const n = ts.length - 1;
  if (t >= ts[n]) return series.y[n];
  let lo = 0;
  let hi = n;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (ts[mid] <= t) lo = mid;
    else hi = mid;
  }
  const f = (t - ts[lo]) / (ts[hi] - ts[lo] || 1);
  return series.y[lo] + f * (series.y[hi] - series.y[lo]);
}

/**
 * The tracking error on the planned trajectory's grid: for each joint of `traj` whose simulated
 * position is in `simulated` (by variable name), simulated − planned at every planned instant up
 * to the run's end. Returns {t, names, units, series} (SI) for a time plot; joints the run lacks
 * are listed in `missing`.
 */
export function trackingErrors(traj, simulated) {
  const names = [];
  const units = [];
  const series = [];
  const missing = [];
  const end = Math.min(...traj.joints.map((j, i) => simulated.get(positionVariable(j, traj.units[i]))?.t?.at(-1) ?? Infinity), traj.t.at(-1) ?? 0);
  const k = traj.t.findLastIndex((t) => t <= end + 1e-12) + 1;
  const t = traj.t.slice(0, k);
  traj.joints.forEach((j, i) => {
    const s = simulated.get(positionVariable(j, traj.units[i]));
    if (!s) {
      missing.push(j);
      return;
    }
    names.push(j);
    units.push(traj.units[i]);
    series.push(t.map((x, n) => valueAt(s, x) - traj.q[i][n]));
  });
  return { t, names, units, series, missing };
}

/**
 * The line on contacts along the simulated motion (issue 29): the first contact's pair and time
 * and how many pairs touch, or that none does among the checked pairs; null when the answer has
 * no check (runs stored before it).
 * @param {object} answer the service's answer
 */
export function contactLine(answer) {
  const c = answer?.collisions;
  if (!c) return null;
  if (c.not_checked) return { contact: false, text: `Contacts not checked: ${c.not_checked}.` };
  if (!c.first_contact) return { contact: false, text: `No contact along the simulated motion (${c.pairs_checked} checked pairs, ${c.samples} samples).` };
  const f = c.first_contact;
  const more = c.contacts.length > 1 ? ` ${c.contacts.length} pairs touch: ${c.contacts.map((p) => `${p.a}/${p.b} at ${p.first_contact.toFixed(3)} s`).join(', ')}.` : '';
  return { contact: true, text: `First contact along the simulated motion: ${f.a} touches ${f.b} at ${f.time.toFixed(3)} s.${more}` };
}
