// Closed-loop simulation (issue 28): the request body from the form and the rows of the answer's
// per-drive table. Pure functions (tested in simulation-data.test.js).

/**
 * The POST body of `/api/models/{id}/simulations` for a motion: the run lasts the motion plus
 * half a second of settling; tolerances only when set (joint error in mrad/mm, tool error in mm).
 * @param {{motionId: string, motionDuration: number, maxJointErrorMilli: string|number, maxToolErrorMm: string|number}} f
 */
export function simulationBody(f) {
  const body = { duration: Math.min(60, Math.max(0.01, Number(f.motionDuration) + 0.5)), drives: true, motion_id: f.motionId };
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
