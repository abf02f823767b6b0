// Drives: a table of the model's drivable joints and, for the chosen joint, an editor that picks
// a motor, a gear and a controller from the library and overrides their editable parameters
// (gear ratio first), with units and limits shown and enforced before anything is sent. Saving
// stores the assignment; "Regenerate package" re-exports the latest version and downloads it.

import { api, download, enc, waitForJob, describeJob } from '../api.js';
import { h, fill, errorBox, say, num, unitLabel, limits, checkValue, field, confirmAction } from '../ui.js';
import { abbreviate, abbreviateAll } from '../layout-data.js';
import { placeFieldErrors, driveControl } from '../field-errors.js';
import { getUnits, toDisplay, fromDisplay, symbolOf, parseNumber } from '../units.js';

const SLOTS = [
  { slot: 'gear', domain: 'gear', label: 'Gear' },
  { slot: 'motor', domain: 'motor', label: 'Motor' },
  { slot: 'controller', domain: 'controller', label: 'Controller' },
];

/**
 * @param {HTMLElement} panel
 * @param {{modelId: string, version: object, report: object, select: Function, onSelect: Function}} ctx
 */
export async function renderDrives(panel, ctx) {
  const { modelId } = ctx;
  fill(panel, h('p', {}, 'Loading drives…'));
  let data;
  let classes;
  let instances;
  try {
    [data, classes, instances] = await Promise.all([
      api(`/api/models/${enc(modelId)}/drives`),
      api('/api/library/classes'),
      api('/api/library/instances'),
    ]);
  } catch (e) {
    fill(panel, errorBox(e, 'Could not load the drives'));
    return;
  }
  const classById = new Map(classes.map((c) => [c.id, c]));
  const instById = new Map(instances.map((i) => [i.id, i]));
  const driveOf = (joint) => data.drives.find((d) => d.joint === joint);

  const tableBox = h('div', { class: 'scroll' });
  const editorBox = h('div', { class: 'drive-editor-box' });
  const note = h('div', { class: 'drive-note', role: 'status' });
  const regenOut = h('div');
  const regen = h('button', { type: 'button', id: 'regenerate', onclick: regenerate }, 'Regenerate and download package');
  let current = null; // joint name being edited

  function renderTable() {
    if (!data.joints.length) {
      fill(tableBox, h('p', { class: 'muted' }, 'This model has no drivable (revolute or prismatic tree) joints.'));
      return;
    }
    const shortName = abbreviateAll(data.joints.map((j) => j.name), 28); // never two rows alike
    const rows = data.joints.map((j) => {
      const d = driveOf(j.name);
      const inst = (id) => {
        const n = instById.get(id)?.name || '—';
        return h('span', { class: 'name', title: n }, abbreviate(n, 30));
      };
      const ratio = d ? d.overrides?.gear?.ratio ?? instById.get(d.gear_instance)?.values?.ratio : null;
      return h(
        'tr',
        { dataset: { joint: j.name }, class: current === j.name ? 'selected' : '' },
        h('th', { scope: 'row' }, h('button', { type: 'button', class: 'link', title: j.name, 'aria-label': `Open the drive of ${j.name}`, onclick: () => open(j.name, true) }, shortName.get(j.name))),
        h('td', { class: 'kind' }, j.kind),
        h('td', {}, d ? inst(d.motor_instance) : h('span', { class: 'muted' }, 'none')),
        h('td', {}, d ? inst(d.gear_instance) : ''),
        h('td', { class: 'num' }, ratio !== null && ratio !== undefined ? num(ratio) : ''),
        h('td', {}, h('button', { type: 'button', 'aria-label': `${d ? 'Edit' : 'Add'} the drive of ${j.name}`, onclick: () => open(j.name, true) }, d ? 'Edit' : 'Add drive')),
      );
    });
    const orphaned = data.drives.filter((d) => d.status === 'orphaned');
    fill(
      tableBox,
      h(
        'table',
        { class: 'drives' },
        h('caption', { class: 'visually-hidden' }, 'Drivable joints and their drives'),
        h('thead', {}, h('tr', {}, ['Joint', 'Kind', 'Motor', 'Gear', 'Ratio', ''].map((c) => h('th', { scope: 'col', class: c === 'Kind' ? 'kind' : null }, c)))),
        h('tbody', {}, rows),
      ),
      orphaned.length
        ? h('div', { class: 'warning' }, h('strong', {}, 'Orphaned drives: '), orphaned.map((o) => o.joint).join(', '), ' (their joints are gone from the latest version; kept, not exported)')
        : null,
    );
  }

  /** Opens the editor for `joint` (and selects it in 3D when asked). */
  function open(joint, selectIn3d) {
    current = joint;
    fill(note);
    if (selectIn3d) ctx.select({ kind: 'joint', name: joint }, { scroll: false });
    renderTable();
    renderEditor(joint);
    editorBox.querySelector('select')?.focus();
  }

  function renderEditor(jointName) {
    const joint = data.joints.find((j) => j.name === jointName);
    if (!joint) {
      fill(editorBox, h('p', { class: 'muted' }, `${jointName} is not a drivable joint; choose one in the table.`));
      return;
    }
    const existing = driveOf(jointName);
    const picks = {};
    const paramsBox = {};
    const inputs = []; // {slot, param, input}
    const out = h('div');

    const section = (spec) => {
      const options = instances.filter((i) => i.domain === spec.domain);
      // A new drive starts with nothing chosen: a joint must not look assigned before it is.
      const chosen = existing?.[`${spec.slot}_instance`] || '';
      const hint = existing ? null : defaultInstance(spec.slot, joint, options);
      const sel = h(
        'select',
        { id: `drive-${spec.slot}`, name: spec.slot, required: true },
        h('option', { value: '' }, `Choose a ${spec.label.toLowerCase()}…`),
        options.map((i) => h('option', { value: i.id, selected: i.id === chosen }, `${i.name} (${i.class_name})`)),
      );
      picks[spec.slot] = sel;
      paramsBox[spec.slot] = h('div', { class: 'params' });
      sel.addEventListener('change', () => renderParams(spec.slot));
      return h(
        'fieldset',
        { class: `slot slot-${spec.slot}` },
        h('legend', {}, spec.label),
        field(`${spec.label} instance`, sel, hint && spec.slot === 'gear' && joint.kind === 'prismatic' && /screw/i.test(hint.class_name) ? `A prismatic joint is usually driven by a lead screw, e.g. ${hint.name}.` : undefined),
        paramsBox[spec.slot],
      );
    };

    // Editable parameters of the chosen instance; overrides kept where the user typed them.
    const renderParams = (slot) => {
      for (let i = inputs.length - 1; i >= 0; i--) if (inputs[i].slot === slot) inputs.splice(i, 1);
      const inst = instById.get(picks[slot].value);
      const cls = inst && classById.get(inst.class_id);
      if (!cls) {
        fill(paramsBox[slot]);
        return;
      }
      const editable = cls.parameters.filter((p) => p.editable && (p.type === 'Real' || p.type === 'Integer'));
      editable.sort((a, b) => (a.name === 'ratio' ? -1 : b.name === 'ratio' ? 1 : 0));
      const rows = editable.map((p) => {
        const override = existing && existing[`${slot}_instance`] === inst.id ? existing.overrides?.[slot]?.[p.name] : undefined;
        const value = override ?? inst.values[p.name] ?? p.default ?? '';
        const unit = unitLabel(p.unit);
        const input = h('input', { type: 'text', inputmode: 'decimal', name: `${slot}.${p.name}`, id: `drive-${slot}-${p.name}`, value: String(value), autocomplete: 'off' });
        const label = p.name === 'ratio' ? 'Gear ratio' : p.name;
        const f = field(`${label}${unit ? ` [${unit}]` : ''}`, input, `${p.comment} · limits ${limits(p)}${unit ? ' ' + unit : ''} · library value ${num(inst.values[p.name])}`);
        const check = () => {
          // A gear ratio of 0 would disconnect the motor: refused here, at the field.
          const msg = checkValue({ ...p, label }, input.value) || (p.name === 'ratio' && Number(input.value) === 0 && input.value.trim() !== '' ? 'Gear ratio must not be 0 (the motor would be disconnected)' : null);
          input.setAttribute('aria-invalid', String(!!msg));
          f.querySelector('.field-msg').textContent = msg || '';
          return msg;
        };
        input.addEventListener('input', check);
        inputs.push({ slot, param: p, input, check, base: inst.values[p.name] });
        return f;
      });
      fill(paramsBox[slot], rows.length ? rows : h('p', { class: 'muted' }, 'No editable parameters (nameplate values only).'));
    };

    const si = joint.kind === 'revolute' ? 'rad' : 'm';
    const units = getUnits();
    const ref = h('input', { type: 'text', inputmode: 'decimal', id: 'drive-reference', name: 'reference', value: existing?.reference?.kind === 'constant' ? String(toDisplay(existing.reference.value, si, units)) : '' });
    const refUnit = symbolOf(si, units);
    const form = h(
      'form',
      { class: 'drive-editor card', 'aria-label': `Drive of ${jointName}`, novalidate: true, onsubmit: save },
      h('h3', { class: 'drive-title' }, `Drive of `, h('span', { class: 'name', title: jointName }, abbreviate(jointName, 36)), ' ', h('small', { class: 'muted' }, `${joint.kind}, start ${num(toDisplay(joint.start, si, units))} ${refUnit}`)),
      SLOTS.map(section),
      field(`Reference position [${refUnit}] (empty: hold the start position)`, ref),
      out,
      h(
        'div',
        { class: 'row' },
        h('button', { type: 'submit', id: 'drive-save' }, 'Save drive'),
        existing ? h('button', { type: 'button', class: 'danger', onclick: remove }, 'Remove drive') : null,
      ),
    );
    fill(editorBox, form);
    for (const s of SLOTS) renderParams(s.slot);

    async function save(e) {
      e.preventDefault();
      fill(out);
      // The service's messages of the last attempt go; the form's own checks run again below.
      for (const m of form.querySelectorAll('.field-msg.from-server')) {
        m.textContent = '';
        m.classList.remove('from-server');
        m.closest('.field')?.querySelector('[aria-invalid="true"]')?.setAttribute('aria-invalid', 'false');
      }
      const problems = [];
      for (const s of SLOTS) if (!picks[s.slot].value) problems.push(`Choose a ${s.label.toLowerCase()} instance`);
      let firstBad = null;
      for (const i of inputs) {
        const msg = i.check();
        if (msg) {
          problems.push(msg);
          firstBad ??= i.input;
        }
      }
      let reference;
      if (ref.value.trim() !== '') {
        const x = parseNumber(ref.value);
        if (!Number.isFinite(x)) problems.push(`Reference position: "${ref.value}" is not a number`);
        else reference = { kind: 'constant', value: fromDisplay(x, si, units) };
      }
      if (problems.length) {
        fill(out, h('div', { class: 'error', role: 'alert' }, h('strong', {}, 'Not saved'), h('ul', {}, problems.map((p) => h('li', {}, p)))));
        (firstBad || form.querySelector('select:invalid, select'))?.focus();
        return;
      }
      const overrides = {};
      for (const i of inputs) {
        const x = Number(i.input.value);
        if (x !== i.base) (overrides[i.slot] ??= {})[i.param.name] = x;
      }
      const body = {
        motor_instance: picks.motor.value,
        gear_instance: picks.gear.value,
        controller_instance: picks.controller.value,
        overrides,
      };
      if (reference) body.reference = reference;
      try {
        const stored = await api(`/api/models/${enc(modelId)}/drives/${enc(jointName)}`, { method: 'PUT', body });
        data.drives = data.drives.filter((d) => d.joint !== jointName).concat([{ ...stored, status: 'active' }]);
        renderTable();
        renderEditor(jointName);
        fill(note, h('p', { class: 'ok' }, `Saved the drive of ${jointName}.`));
        say(`Saved the drive of ${jointName}`, 'ok');
      } catch (err) {
        fill(out, errorBox(err, 'The service refused the drive'));
        // Each refused field's message also goes next to its control, which is marked invalid.
        const { at } = placeFieldErrors(err.errors, driveControl);
        let first = null;
        for (const [key, messages] of at) {
          const control = key === 'reference' ? ref : picks[key] || form.querySelector(`[name="${CSS.escape(key)}"]`);
          const msg = control?.closest('.field')?.querySelector('.field-msg');
          if (!msg) continue;
          control.setAttribute('aria-invalid', 'true');
          msg.textContent = messages.join('; ');
          msg.classList.add('from-server');
          first ??= control;
        }
        first?.focus();
      }
    }

    async function remove() {
      if (!(await confirmAction(`Remove the drive of ${jointName}?`, 'Remove'))) return;
      try {
        await api(`/api/models/${enc(modelId)}/drives/${enc(jointName)}`, { method: 'DELETE' });
        data.drives = data.drives.filter((d) => d.joint !== jointName);
        renderTable();
        renderEditor(jointName);
        say(`Removed the drive of ${jointName}`, 'ok');
      } catch (err) {
        fill(out, errorBox(err));
      }
    }
  }

  async function regenerate() {
    regen.disabled = true;
    // Progress from the first moment: the job's stage and fraction, then the download.
    const bar = h('progress', { 'aria-label': 'Regenerating the package' });
    const state = h('span', { role: 'status' }, 'Asking for a re-export…');
    fill(regenOut, h('div', { class: 'regen-progress' }, bar, state));
    try {
      const q = await api(`/api/models/${enc(modelId)}/reexport`, { method: 'POST' });
      const job = await waitForJob(q.job_id, (j) => {
        if (j.progress && Number.isFinite(j.progress.fraction)) bar.value = j.progress.fraction;
        state.textContent = `Re-export of v${q.version}: ${describeJob(j)}`;
      });
      if (job.status !== 'succeeded') {
        fill(regenOut, errorBox({ message: job.error?.detail || 'the re-export failed' }, 'Re-export failed'));
        return;
      }
      bar.removeAttribute('value');
      state.textContent = `Downloading the package of v${q.version}…`;
      await download(`/api/models/${enc(modelId)}/versions/${q.version}/package.zip`, `package-v${q.version}.zip`);
      fill(regenOut, h('p', { class: 'ok', role: 'status' }, `Package of v${q.version} regenerated with ${data.drives.filter((d) => d.status === 'active').length} drives and downloaded.`));
    } catch (err) {
      fill(regenOut, errorBox(err, 'Could not regenerate'));
    } finally {
      regen.disabled = false;
    }
  }

  fill(
    panel,
    h('h2', {}, 'Drives'),
    h('p', { class: 'muted' }, `Joints of v${data.version ?? '—'}. A drive is a motor, a gear and a controller from the motor library; it is written into Mechatronics.mo.`),
    tableBox,
    editorBox,
    note,
    h('div', { class: 'row' }, regen),
    regenOut,
  );
  renderTable();
  const already = ctx.selected?.();
  if (already?.kind === 'joint' && data.joints.some((j) => j.name === already.name)) open(already.name, false);
  // Selecting a joint anywhere (3D, lists) opens its drive here.
  ctx.onSelect((sel) => {
    if (sel?.kind === 'joint' && data.joints.some((j) => j.name === sel.name) && current !== sel.name) open(sel.name, false);
  });
}

/** A sensible first choice: a lead screw for prismatic joints, else the first instance. */
function defaultInstance(slot, joint, options) {
  if (slot === 'gear') {
    const screw = (i) => /screw/i.test(i.class_name);
    return options.find((i) => (joint.kind === 'prismatic' ? screw(i) : !screw(i))) || options[0];
  }
  return options[0];
}
