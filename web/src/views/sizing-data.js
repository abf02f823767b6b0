// Pure helpers of the drive sizing view (no DOM): the query of the sizing request from the
// settings form, a check's verdict, an alternative's line, and a library value's own source
// sentence. Unit-tested in sizing-data.test.js.

/**
 * The query string of `GET .../sizing` from the settings: only what is set; the reserve in
 * percent in the form, a fraction in the API.
 */
export function sizingQuery(s) {
  const q = new URLSearchParams();
  const put = (k, v) => {
    if (v !== null && v !== undefined && v !== '' && !Number.isNaN(v)) q.set(k, String(v));
  };
  if (s.reservePercent !== '' && s.reservePercent !== null && s.reservePercent !== undefined) put('reserve', Number(s.reservePercent) / 100);
  put('dwell', s.dwell === '' ? '' : s.dwell);
  if (s.amplifier) {
    put('amplifier', s.amplifier);
    put('supply_voltage', s.supplyVoltage);
  }
  if (s.brake === 'resistor') put('brake_power', s.brakePower);
  if (s.brake === 'bus') {
    put('bus_capacitance', s.busCapacitance);
    put('bus_voltage_max', s.busVoltageMax);
  }
  put('screw_life', s.screwLife);
  const text = q.toString();
  return text ? `?${text}` : '';
}

/** A check's verdict as the table shows it. */
export function verdict(c) {
  if (c.status === 'not_evaluated') return 'not evaluated';
  if (c.status === 'fail' || c.pass === false) return 'FAIL';
  if (c.within_reserve === false) return 'pass, below reserve';
  return 'pass';
}

const STANDING = {
  passes_with_reserve: 'passes with reserve',
  passes: 'passes, below reserve',
  incomplete: 'incomplete data',
  fails: 'fails',
};

/** An alternative's standing in words. */
export function standingLabel(s) {
  return STANDING[s] || s;
}

/** "Peak motor torque (margin 12.5 %)" for the check that limits an alternative. */
export function limitingText(a) {
  if (!a.limiting) return 'no limiting check';
  return `${a.limiting.label} (margin ${Math.round(a.limiting.margin * 1000) / 10} %)`;
}

function escapeRegExp(s) {
  return s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

/**
 * The part of an instance's source that says where one value comes from: catalogue sources
 * write `R = line 2 terminal resistance 2,83 Ω;` for each value. `null` when the source has no
 * such clause for the parameter.
 */
export function valueSource(source, name) {
  const text = String(source || '');
  const m = new RegExp(`(?:^|[\\s;:(])${escapeRegExp(name)} = ([^;]*?)(?:;|\\.(?:\\s|$)|$)`).exec(text);
  return m ? m[1].trim() : null;
}
