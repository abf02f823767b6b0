// The service's 422 problem documents name each refused field (`errors: [{field, message}]`):
// these pure parts decide which form control shows which message, so it appears next to the
// control it is about rather than only in a box at the end of the form.

/**
 * Groups `errors` by the control that shows them: `controlFor(field)` gives a control key, or
 * null when the form has no control for that field. Returns {at: Map<key, messages[]>, rest: errors[]}.
 */
export function placeFieldErrors(errors, controlFor) {
  const at = new Map();
  const rest = [];
  for (const e of errors || []) {
    const key = e?.field ? controlFor(e.field) : null;
    if (key === null || key === undefined) {
      rest.push(e);
      continue;
    }
    if (!at.has(key)) at.set(key, []);
    if (!at.get(key).includes(e.message)) at.get(key).push(e.message);
  }
  return { at, rest };
}

/**
 * The drive editor's control for a field of PUT /drives/{joint}: `overrides.<slot>.<param>` is
 * the parameter's input (named `<slot>.<param>`), `<slot>_instance` the slot's instance choice
 * (`<slot>`), `reference` and `reference.*` the reference position; anything else has none.
 */
export function driveControl(field) {
  const o = /^overrides\.(motor|gear|controller)\.([A-Za-z_][\w.]*)$/.exec(field);
  if (o) return `${o[1]}.${o[2]}`;
  const i = /^(motor|gear|controller)_instance$/.exec(field);
  if (i) return i[1];
  if (field === 'reference' || field.startsWith('reference.')) return 'reference';
  return null;
}
