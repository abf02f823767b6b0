// Motion: the model's motions (create, rename, delete) and their keyframes (joint values,
// captured from the sliders, or a tool pose reached by inverse kinematics, with a gizmo that
// solves IK live while it is dragged), played in 3D at real speed with a scrub slider, plotted
// (q, qd, qdd, torque; motor operating points against each drive's envelope), sized (checks and
// ranked alternatives one can apply), checked for collisions (first contact, per pair minimum
// distance, markers on the timeline and plots, closest-point lines in 3D), and the joints' limits.

import { api, enc } from '../api.js';
import { h, fill, errorBox, num, field, confirmAction, newId, unitLabel } from '../ui.js';
import { sampleAt, keyframeProblems, throttle, applyAlternative, rotationRows, freshName, bodyDepths, defaultToolFrame } from './motion-data.js';
import { sizingQuery, verdict, standingLabel, limitingText } from './sizing-data.js';
import { simulationBody, driveRows, trackingErrors, positionVariable, valueAt, contactLine } from './simulation-data.js';
import { sweepRows, firstContactText, contactMarkers, touchedBy, witnessLine, pairKey } from './collision-data.js';
import { createPlayer } from './player.js';
import { getUnits, factorOf, symbolOf } from '../units.js';
import { abbreviateAll, filterRows } from '../layout-data.js';

const INTERPOLATIONS = [
  ['ptp', 'Point to point (speed/acceleration limits)'],
  ['quintic', 'Quintic polynomial'],
  ['jerk', 'Jerk-limited, time-optimal'],
];
const RATE = 100; // Hz of the trajectory the player and plots use

/**
 * @param {HTMLElement} panel
 * @param {{modelId: string, report: object, viewer: object, setJoints: Function, currentJoints: Function, say: Function}} ctx
 * @returns {{poseChanged(): void, dispose(): void}}
 */
export function renderMotion(panel, ctx) {
  const { modelId, viewer } = ctx;
  const base = `/api/models/${enc(modelId)}`;
  let joints = null; // GET /joints
  let motions = [];
  let current = null; // the stored motion being edited
  let spec = null; // its editable spec
  let dirty = false;
  let traj = null;
  let sizing = null;
  // The sizing's settings (the form under "Drive sizing"): kept while the view lives.
  const sizingSettings = { reservePercent: 20, dwell: 0, amplifier: '', supplyVoltage: '', brake: 'none', brakePower: '', busCapacitance: '', busVoltageMax: '', screwLife: '' };
  let amplifiers = null;
  let collisions = null; // GET …/collisions of the current motion
  let contactPair = null; // the pair whose closest points are drawn (its key)
  let problems = new Map();
  let time = 0;
  let plots = [];
  let gizmo = null;
  let disposed = false;

  const listBox = h('div', { class: 'motion-list-box' });
  const editorBox = h('div', { class: 'motion-editor-box' });
  const gizmoBox = h('div', { class: 'gizmo-box' });
  const playerBox = h('div', { class: 'player-box' });
  const plotsBox = h('div', { class: 'plots-box' });
  const sizingBox = h('div', { class: 'sizing-box' });
  // The closed-loop simulation of the drives along the motion (issue 28), beside the sizing.
  const simBox = h('div', { class: 'simulation-box' });
  const simForm = { maxJointErrorMilli: '', maxToolErrorMm: '', live: false };
  const collisionBox = h('div', { class: 'motion-collisions', 'aria-live': 'polite' });
  const limitsBox = h('div', { class: 'limits-box' });
  fill(panel, h('h2', {}, 'Motions'), listBox, editorBox, gizmoBox, h('h2', {}, 'Joint limits'), limitsBox);
  // Under the 3D view (wider), or in the tab where there is no such place.
  if (ctx.stage) fill(ctx.stage, playerBox, plotsBox, sizingBox, simBox, collisionBox);
  else panel.append(playerBox, plotsBox, sizingBox, simBox, collisionBox);

  const jointInfo = (name) => joints?.joints.find((j) => j.name === name);
  // Keyframes set the independent joints; in a closed loop the others follow.
  const driven = () => (joints?.joints || []).filter((j) => j.independent !== false);
  const captured = () => {
    const now = ctx.currentJoints();
    const out = {};
    for (const j of driven()) if (Number.isFinite(now[j.name])) out[j.name] = now[j.name];
    return out;
  };
  // Joint values in the units chosen in the toolbar (degrees or radians, mm or m).
  const scaleOf = (name) => factorOf(jointInfo(name)?.unit || 'rad', getUnits());
  const unitOf = (name) => symbolOf(jointInfo(name)?.unit || 'rad', getUnits());
  const displayScale = (unit) => factorOf(unit, getUnits());
  const displayUnit = (unit) => symbolOf(unit, getUnits());
  let jointFilter = ''; // the keyframe table's joint search
  // The last closed-loop run of this motion: its answer, its series by name, and whether the
  // player shows it (the simulated motion, with the planned one as a ghost).
  let sim = null;
  let simView = false;
  let simPlots = [];

  // ---------------------------------------------------------------- loading
  async function load() {
    fill(listBox, h('p', {}, 'Loading motions…'));
    try {
      [joints, motions] = await Promise.all([api(`${base}/joints`), api(`${base}/motions`)]);
    } catch (e) {
      fill(listBox, errorBox(e, 'Motions are not available for this model'));
      return;
    }
    if (disposed) return;
    renderList();
    renderGizmo();
    renderLimits();
    renderEditor();
  }

  // ---------------------------------------------------------------- motion list
  function renderList() {
    const name = h('input', { type: 'text', id: 'motion-new-name', value: freshName('motion', motions.map((m) => m.name)), autocomplete: 'off' });
    const items = motions.map((m) =>
      h(
        'li',
        { dataset: { motion: m.name }, class: current?.id === m.id ? 'selected' : '' },
        h('button', { type: 'button', class: 'pick', 'aria-pressed': String(current?.id === m.id), onclick: () => open(m.id) }, m.name),
      ),
    );
    fill(
      listBox,
      items.length ? h('ul', { class: 'picklist motion-list', 'aria-label': 'Motions of this model' }, items) : h('p', { class: 'muted' }, 'No motions yet.'),
      h(
        'form',
        { class: 'row new-motion', onsubmit: (e) => (e.preventDefault(), create(name.value.trim())) },
        field('New motion name', name),
        h('button', { type: 'submit' }, 'New motion'),
      ),
    );
  }

  async function create(name) {
    if (!name) return ctx.say('A motion needs a name', 'error');
    // From the CAD pose to the pose the sliders show now.
    const body = {
      name,
      keyframes: [
        { kind: 'joints', values: {} },
        { kind: 'joints', values: captured(), interpolation: 'ptp', duration: null, dwell: null },
      ],
    };
    try {
      const m = await api(`${base}/motions`, { method: 'POST', body });
      motions.push(m);
      ctx.say(`Created the motion ${m.name}`, 'ok');
      await open(m.id, m);
    } catch (e) {
      listBox.append(errorBox(e, 'The motion was not created'));
    }
  }

  async function open(id, known) {
    if (dirty && current && current.id !== id && !(await confirmAction(`Discard the unsaved changes to ${current.name}?`, 'Discard'))) return;
    stop();
    try {
      current = known || (await api(`${base}/motions/${enc(id)}`));
    } catch (e) {
      fill(editorBox, errorBox(e, 'Could not open the motion'));
      return;
    }
    spec = structuredClone(current.spec);
    spec.name = current.name;
    dirty = false;
    traj = null;
    sizing = null;
    problems = new Map();
    time = 0;
    resetCollisions();
    renderList();
    renderEditor();
    await plan();
  }

  // ---------------------------------------------------------------- keyframe editor
  function markDirty() {
    dirty = true;
    editorBox.querySelector('.motion-dirty')?.removeAttribute('hidden');
  }

  function renderEditor() {
    if (!current) {
      fill(editorBox, joints ? h('p', { class: 'muted' }, 'Choose a motion or create one: it starts at the CAD pose and goes to the pose the joint sliders show.') : null);
      return;
    }
    const name = h('input', { type: 'text', id: 'motion-name', value: spec.name, autocomplete: 'off', oninput: () => ((spec.name = name.value), markDirty()) });
    const kfs = spec.keyframes.map((kf, k) => keyframeItem(kf, k));
    fill(
      editorBox,
      h(
        'form',
        { class: 'card motion-editor', 'aria-label': `Motion ${current.name}`, novalidate: true, onsubmit: (e) => (e.preventDefault(), save()) },
        field('Motion name', name),
        h('h3', {}, `Keyframes (${spec.keyframes.length})`),
        keyframeTable(),
        h('ol', { class: 'keyframes', start: '0' }, kfs),
        h(
          'div',
          { class: 'row' },
          h('button', { type: 'button', onclick: addCaptured }, 'Add keyframe from the current pose'),
          h('button', { type: 'button', onclick: addToolKeyframe }, 'Add tool keyframe from the gizmo'),
        ),
        h(
          'div',
          { class: 'row' },
          h('button', { type: 'submit', id: 'motion-save' }, 'Save motion'),
          h('button', { type: 'button', class: 'danger', onclick: remove }, 'Delete motion'),
          h('span', { class: 'motion-dirty warn', hidden: !dirty }, 'Unsaved changes'),
        ),
        h('div', { class: 'motion-out', 'aria-live': 'polite' }),
      ),
    );
  }

  function numberInput(id, value, scale, onValue, { placeholder, label } = {}) {
    const input = h('input', {
      type: 'text',
      inputmode: 'decimal',
      id,
      value: value === null || value === undefined ? '' : String(num(value * scale)),
      placeholder: placeholder ?? '',
      autocomplete: 'off',
      'aria-label': label,
    });
    input.addEventListener('change', () => {
      const t = input.value.trim();
      const x = t === '' ? null : Number(t);
      const bad = t !== '' && !Number.isFinite(x);
      input.setAttribute('aria-invalid', String(bad));
      if (!bad) onValue(x === null ? null : x / scale);
      markDirty();
    });
    return input;
  }

  function keyframeItem(kf, k) {
    const id = newId('kf');
    const kind = h(
      'select',
      { id: `${id}-kind` },
      h('option', { value: 'joints', selected: kf.kind === 'joints' }, 'Joint values'),
      h('option', { value: 'tool', selected: kf.kind === 'tool' }, 'Tool pose (inverse kinematics)'),
    );
    kind.addEventListener('change', () => {
      const tool = kind.value === 'tool' && toolKeyframeNow(kf.frame);
      if (kind.value === 'tool' && !tool) {
        kind.value = 'joints';
        return ctx.say('A tool keyframe needs a CAD frame and the 3D view', 'error');
      }
      if (tool) Object.assign(kf, tool, { kind: 'tool', values: undefined });
      else Object.assign(kf, { kind: 'joints', values: captured(), frame: undefined, position: undefined, rotation: undefined });
      markDirty();
      renderEditor();
    });
    let body;
    if (kf.kind === 'tool') {
      const frames = joints?.frames || [];
      const sel = h(
        'select',
        { id: `${id}-frame` },
        frames.map((f) => h('option', { value: f.node_id, selected: f.node_id === kf.frame }, frameLabel(f))),
        frames.some((f) => f.node_id === kf.frame) ? null : h('option', { value: kf.frame, selected: true }, `${kf.frame} (not in the model)`),
      );
      sel.addEventListener('change', () => ((kf.frame = sel.value), markDirty()));
      const pos = [0, 1, 2].map((i) =>
        numberInput(`${id}-p${i}`, kf.position?.[i], 1000, (v) => (kf.position[i] = v ?? 0), { label: `Keyframe ${k} tool ${'xyz'[i]} [mm]` }),
      );
      const orient = h('input', { type: 'checkbox', id: `${id}-rot`, checked: !!kf.rotation });
      orient.addEventListener('change', () => {
        kf.rotation = orient.checked ? toolKeyframeNow(kf.frame, true)?.rotation ?? null : null;
        markDirty();
      });
      body = [
        field('Tool frame', sel),
        h('div', { class: 'xyz' }, h('span', { class: 'muted' }, 'Position [mm]'), pos),
        h('span', { class: 'check' }, orient, h('label', { for: orient.id }, 'Orientation too (else position only)')),
      ];
    } else {
      const dependent = (joints?.joints || []).filter((j) => j.independent === false);
      const loopFollowers = dependent.filter((j) => !j.mimic);
      const mimicFollowers = dependent.filter((j) => j.mimic);
      body = [
        h('p', { class: 'muted kf-values-note' }, `Joint values: column ${k} of the table above.`),
        loopFollowers.length ? h('p', { class: 'muted' }, `${loopFollowers.map((j) => j.name).join(', ')} follow the loops.`) : null,
        mimicFollowers.length
          ? h('p', { class: 'muted' }, `${mimicFollowers.map((j) => `${j.name} follows ${j.mimic.leader}`).join(', ')} (mimic coupling).`)
          : null,
      ];
    }
    const timing =
      k === 0
        ? [field('Dwell [s]', numberInput(`${id}-dwell`, kf.dwell, 1, (v) => (kf.dwell = v), { placeholder: '0' }))]
        : [
            field(
              'Interpolation',
              (() => {
                const s = h('select', { id: `${id}-interp` }, INTERPOLATIONS.map(([v, l]) => h('option', { value: v, selected: (kf.interpolation || 'ptp') === v }, l)));
                s.addEventListener('change', () => ((kf.interpolation = s.value), markDirty()));
                return s;
              })(),
            ),
            field('Duration [s]', numberInput(`${id}-duration`, kf.duration, 1, (v) => (kf.duration = v), { placeholder: 'fastest' })),
            field('Dwell [s]', numberInput(`${id}-dwell`, kf.dwell, 1, (v) => (kf.dwell = v), { placeholder: '0' })),
          ];
    const at = traj?.keyframes?.find((x) => x.index === k);
    const issue = problems.get(k);
    return h(
      'li',
      { class: `keyframe${issue ? ' invalid' : ''}`, dataset: { keyframe: String(k) }, 'aria-label': `Keyframe ${k}` },
      h(
        'div',
        { class: 'kf-head' },
        h('strong', {}, `Keyframe ${k}`),
        at ? h('small', { class: 'muted kf-time' }, ` at ${num(at.time)} s${at.ik ? ` · IK ${at.ik.iterations} it., ${num(at.ik.position_error * 1000)} mm` : ''}`) : null,
        k === 0 ? h('small', { class: 'muted' }, ' (start pose)') : null,
      ),
      field('Kind', kind),
      body,
      h('div', { class: 'timing' }, timing),
      issue ? h('div', { class: 'error kf-problem', role: 'alert' }, issue.map((m) => h('p', {}, m))) : null,
      h(
        'div',
        { class: 'row kf-actions' },
        h('button', { type: 'button', onclick: () => goTo(k), 'aria-label': `Show keyframe ${k} in 3D` }, 'Show'),
        h('button', { type: 'button', onclick: () => capture(k), 'aria-label': `Capture the current pose into keyframe ${k}` }, 'Capture current pose'),
        h('button', { type: 'button', disabled: k === 0, onclick: () => move(k, -1), 'aria-label': `Move keyframe ${k} up` }, '↑'),
        h('button', { type: 'button', disabled: k === spec.keyframes.length - 1, onclick: () => move(k, 1), 'aria-label': `Move keyframe ${k} down` }, '↓'),
        h('button', { type: 'button', class: 'danger', disabled: spec.keyframes.length <= 2, onclick: () => removeKf(k), 'aria-label': `Remove keyframe ${k}` }, 'Remove'),
      ),
    );
  }

  /**
   * The joint values of every keyframe as one table: a row per driven joint (filtered by the
   * search), a column per keyframe; tool keyframes' columns are solved by IK and show no fields.
   * The table scrolls inside its box when there are many keyframes; the joint column stays.
   */
  function keyframeTable() {
    const all = driven();
    const shortName = abbreviateAll(all.map((j) => j.name), 30); // never two rows alike
    const search = h('input', { type: 'search', id: 'kf-filter', value: jointFilter, autocomplete: 'off', placeholder: 'name or part of it' });
    const count = h('small', { class: 'muted kf-filter-count' });
    const body = h('tbody');
    const draw = () => {
      const rows = filterRows(all, jointFilter, (j) => j.name);
      count.textContent = `${rows.length} of ${all.length} joints`;
      fill(
        body,
        rows.map((j) =>
          h(
            'tr',
            { dataset: { joint: j.name } },
            h('th', { scope: 'row', title: j.name }, h('span', { class: 'name', title: j.name }, shortName.get(j.name)), h('small', { class: 'muted' }, ` [${unitOf(j.name)}]`)),
            spec.keyframes.map((kf, k) =>
              h(
                'td',
                { dataset: { keyframe: String(k) } },
                kf.kind === 'tool'
                  ? h('span', { class: 'muted', title: 'A tool keyframe: the joints come from inverse kinematics' }, 'IK')
                  : numberInput(`kf${k}-${j.name}`, kf.values?.[j.name], scaleOf(j.name), (v) => {
                      kf.values ??= {};
                      if (v === null) delete kf.values[j.name];
                      else kf.values[j.name] = v;
                    }, { placeholder: k === 0 ? 'CAD' : 'prev.', label: `Keyframe ${k} ${j.name} [${unitOf(j.name)}]` }),
              ),
            ),
          ),
        ),
      );
    };
    search.addEventListener('input', () => {
      jointFilter = search.value;
      draw();
    });
    draw();
    return h(
      'div',
      { class: 'kf-table-wrap' },
      h('div', { class: 'row kf-filter' }, h('label', { for: search.id }, 'Filter joints'), search, count),
      h(
        'div',
        { class: 'scroll kf-table-box' },
        h(
          'table',
          { class: 'keyframe-table' },
          h('caption', { class: 'visually-hidden' }, 'Joint values per keyframe (empty: the CAD pose in keyframe 0, else the previous keyframe)'),
          h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Joint'), spec.keyframes.map((kf, k) => h('th', { scope: 'col', class: 'num' }, `${k}${kf.kind === 'tool' ? ' (tool)' : ''}`)))),
          body,
        ),
      ),
    );
  }

  const frameLabel = (f) => `${f.body} · ${f.name}`;

  function capture(k) {
    const kf = spec.keyframes[k];
    Object.assign(kf, { kind: 'joints', values: captured() });
    delete kf.frame;
    delete kf.position;
    delete kf.rotation;
    markDirty();
    renderEditor();
  }

  function move(k, d) {
    const ks = spec.keyframes;
    [ks[k], ks[k + d]] = [ks[k + d], ks[k]];
    problems = new Map();
    markDirty();
    renderEditor();
  }

  function removeKf(k) {
    spec.keyframes.splice(k, 1);
    problems = new Map();
    markDirty();
    renderEditor();
  }

  function addCaptured() {
    spec.keyframes.push({ kind: 'joints', values: captured(), interpolation: 'ptp', duration: null, dwell: null });
    markDirty();
    renderEditor();
  }

  /** A tool keyframe at the gizmo's pose (or the chosen frame's pose now). */
  function toolKeyframeNow(frameId, withRotation = !!gizmoOrient?.checked) {
    const f = frameById(frameId || gizmoFrame());
    if (!f) return null;
    const m = gizmo && gizmoFrame() === f.node_id ? gizmo.matrix() : viewer.frameNow(f);
    if (!m) return null; // no 3D view
    const e = m.elements;
    return { kind: 'tool', frame: f.node_id, position: [e[12], e[13], e[14]], rotation: withRotation ? rotationRows(e) : null };
  }

  function addToolKeyframe() {
    const kf = toolKeyframeNow();
    if (!kf) return ctx.say('This model has no CAD frames for a tool keyframe', 'error');
    spec.keyframes.push({ ...kf, interpolation: 'ptp', duration: null, dwell: null });
    markDirty();
    renderEditor();
    ctx.say(`Added a tool keyframe for ${frameLabel(frameById(kf.frame))}`, 'ok');
  }

  /** Shows keyframe k: joint values as planned (trajectory) or as given. */
  function goTo(k) {
    const at = traj?.keyframes?.find((x) => x.index === k);
    if (at && !dirty) return seek(at.time);
    const kf = spec.keyframes[k];
    if (kf.kind === 'tool') {
      // Not planned yet: solve the pose here, from the current pose.
      api(`${base}/ik`, { method: 'POST', body: { frame: kf.frame, position: kf.position, rotation: kf.rotation ?? null, seed: ctx.currentJoints() } })
        .then((r) => {
          ctx.setJoints(r.q);
          poseChanged();
          if (!r.success) ctx.say(`Keyframe ${k}: the tool pose is out of reach (${num(r.position_error * 1000)} mm off)`, 'error');
        })
        .catch((e) => ctx.say(e.message, 'error'));
      return;
    }
    const values = {};
    for (const j of joints?.joints || []) values[j.name] = j.q0;
    for (let i = 0; i <= k; i++) if (spec.keyframes[i].kind === 'joints') Object.assign(values, spec.keyframes[i].values || {});
    ctx.setJoints(values);
    poseChanged();
  }

  async function save() {
    const out = editorBox.querySelector('.motion-out');
    if (editorBox.querySelector('[aria-invalid="true"]')) {
      fill(out, h('div', { class: 'error', role: 'alert' }, h('strong', {}, 'Not saved'), h('p', {}, 'Some values are not numbers.')));
      return;
    }
    try {
      const stored = await api(`${base}/motions/${enc(current.id)}`, { method: 'PUT', body: spec });
      current = { ...current, ...stored };
      motions = motions.map((m) => (m.id === current.id ? current : m));
      dirty = false;
      renderList();
      ctx.say(`Saved the motion ${current.name}`, 'ok');
      await plan();
    } catch (e) {
      problems = keyframeProblems(e);
      renderEditor();
      fill(editorBox.querySelector('.motion-out'), errorBox(e, 'The motion was not saved'));
    }
  }

  async function remove() {
    if (!(await confirmAction(`Delete the motion ${current.name}?`))) return;
    try {
      await api(`${base}/motions/${enc(current.id)}`, { method: 'DELETE' });
      ctx.say(`Deleted the motion ${current.name}`, 'ok');
      motions = motions.filter((m) => m.id !== current.id);
      current = null;
      spec = null;
      dirty = false;
      traj = null;
      sizing = null;
      resetCollisions();
      stop();
      renderList();
      renderEditor();
      renderPlayer();
      renderPlots();
      renderSizing();
    } catch (e) {
      fill(editorBox.querySelector('.motion-out'), errorBox(e));
    }
  }

  // ---------------------------------------------------------------- planning: trajectory and sizing
  async function plan() {
    stop();
    clearSim();
    traj = null;
    sizing = null;
    problems = new Map();
    player.clear(h('p', { role: 'status' }, 'Planning the trajectory…'));
    fill(plotsBox);
    fill(sizingBox);
    resetCollisions();
    try {
      traj = await api(`${base}/motions/${enc(current.id)}/trajectory?rate=${RATE}`);
    } catch (e) {
      problems = keyframeProblems(e);
      renderEditor();
      player.clear(errorBox(e, 'The motion cannot be planned'));
      if (problems.size) editorBox.querySelector('.kf-problem')?.scrollIntoView({ block: 'nearest' });
      return;
    }
    if (disposed) return;
    time = 0;
    renderEditor();
    renderPlayer();
    renderPlots();
    renderCollisions();
    seek(0);
    renderSimulate(null);
    await loadSizing();
  }

  // ---------------------------------------------------------------- simulation
  /** The Simulate form, and the answer of the last run (verdict, per-drive table, result link). */
  function renderSimulate(answer) {
    if (!traj || !current) {
      fill(simBox);
      return;
    }
    const input = (key, label) =>
      h('label', {}, `${label} `, h('input', { type: 'number', min: '0', step: 'any', value: simForm[key], size: 6, oninput: (e) => (simForm[key] = e.currentTarget.value) }));
    const out = [];
    if (answer) {
      out.push(
        h('p', { class: `verdict ${answer.ok ? 'ok' : 'fail'}`, role: 'status' }, h('span', { class: `badge ${answer.ok ? 'badge-succeeded' : 'badge-failed'}` }, answer.ok ? 'holds the path' : 'does not hold the path'), answer.reasons.length ? ` ${answer.reasons.join('; ')}` : ''),
        h(
          'div',
          { class: 'scroll' },
          h(
            'table',
            { class: 'simulation-drives' },
            h('thead', {}, h('tr', {}, ['Joint', 'Max error', 'RMS error', 'Current / limit', 'Voltage / limit', 'Limited during'].map((c) => h('th', { scope: 'col' }, c)))),
            h(
              'tbody',
              {},
              driveRows(answer).map((r) =>
                h(
                  'tr',
                  { dataset: { joint: r.joint } },
                  h('th', { scope: 'row' }, r.joint),
                  h('td', { class: 'num' }, `${num(r.maxError)} ${unitLabel(r.unit)}`),
                  h('td', { class: 'num' }, `${num(r.rmsError)} ${unitLabel(r.unit)}`),
                  h('td', { class: `num ${r.currentShare >= 1 - 1e-9 ? 'fail' : ''}` }, r.current),
                  h('td', { class: `num ${r.voltageShare >= 1 - 1e-9 ? 'fail' : ''}` }, r.voltage),
                  h('td', {}, r.saturated),
                ),
              ),
            ),
          ),
        ),
        (() => {
          const c = contactLine(answer);
          return c ? h('p', { class: `contact-line ${c.contact ? 'fail' : 'muted'}` }, c.text) : null;
        })(),
        answer.tool ? h('p', { class: 'muted tool-error' }, `Tool ${answer.tool.frame}: position error up to ${num(answer.tool.max_position_error * 1000)} mm, orientation up to ${num(answer.tool.max_orientation_error)} rad.`) : null,
        h('p', { class: 'muted' }, `${answer.solver}; ${answer.steps} steps in ${num(answer.wall_time_s)} s. The run is stored as result `, h('code', {}, answer.result_id || '—'), ': open it under Results to animate and plot it.'),
        answer.result_id ? simulatedView() : null,
      );
    }
    fill(
      simBox,
      h('h3', {}, 'Closed-loop simulation'),
      h(
        'form',
        { class: 'simulate-form', onsubmit: (e) => (e.preventDefault(), simulate()) },
        input('maxJointErrorMilli', 'Max joint error (mrad or mm)'),
        ' ',
        input('maxToolErrorMm', 'Max tool error (mm)'),
        ' ',
        h('label', { title: 'The run sends its poses to the Live tab while it runs, at the speed of the wall clock' }, h('input', { type: 'checkbox', class: 'simulate-live', checked: !!simForm.live, onchange: (e) => (simForm.live = e.currentTarget.checked) }), ' Show in the Live tab'),
        ' ',
        h('button', { type: 'submit', class: 'simulate' }, 'Simulate'),
      ),
      h('div', { class: 'simulation-out', 'aria-live': 'polite' }, out),
    );
  }

  async function simulate() {
    const box = simBox.querySelector('.simulation-out');
    fill(box, h('p', { role: 'status' }, 'Simulating the drives…'));
    clearSim();
    try {
      const answer = await api(`${base}/simulations`, { method: 'POST', body: simulationBody({ motionId: current.id, motionDuration: traj.duration, ...simForm }) });
      if (disposed) return;
      sim = { answer, series: new Map() };
      if (answer.result_id) await loadSimSeries(sim);
      if (!disposed && sim?.answer === answer) renderSimulate(answer);
    } catch (e) {
      fill(box, errorBox(e, 'The simulation did not run'));
    }
  }

  /** The run's joint positions, motor currents and voltages, read back from its stored result. */
  async function loadSimSeries(run) {
    const wanted = traj.joints.map((j, i) => positionVariable(j, traj.units[i]));
    const perDrive = run.answer.drives.flatMap((d) => [`drive_${d.joint}.motor.i`, `drive_${d.joint}.motor.v`]);
    for (const names of [wanted, perDrive]) {
      for (let k = 0; k < names.length; k += 50) {
        const q = names.slice(k, k + 50).map((n) => `name=${enc(n)}`).join('&');
        try {
          const got = await api(`/api/results/${enc(run.answer.result_id)}/series?${q}&width=2000`);
          for (const v of got.variables) run.series.set(v.name, v);
        } catch (e) {
          run.problem = e.message;
        }
      }
    }
  }

  function clearSim() {
    for (const p of simPlots) p.destroy();
    simPlots = [];
    if (simView) ctx.setGhost?.(null);
    simView = false;
    sim = null;
  }

  /** The simulated motion's joint values at time t (SI, by joint name). */
  function simulatedAt(t) {
    const out = {};
    traj.joints.forEach((j, i) => {
      const v = valueAt(sim.series.get(positionVariable(j, traj.units[i])), t);
      if (v !== null) out[j] = v;
    });
    return out;
  }

  /**
   * The run's plots (tracking error per joint, motor current and voltage against their limits)
   * and the switch that animates the simulated motion with the planned one as a ghost.
   */
  function simulatedView() {
    for (const p of simPlots) p.destroy();
    simPlots = [];
    if (!sim) return null;
    const toggle = h('input', { type: 'checkbox', id: 'sim-animate', checked: simView });
    toggle.addEventListener('change', () => {
      simView = toggle.checked;
      if (!simView) ctx.setGhost?.(null);
      setTime(time);
    });
    const plotsEl = h('div', { class: 'plots-box sim-plots' });
    const errors = trackingErrors(traj, sim.series);
    const draw = async () => {
      const { timePlot, signalPlot } = await import('./plots.js');
      if (disposed || !sim) return;
      if (errors.names.length) {
        const box = h('div', { class: 'plot', dataset: { plot: 'tracking' } });
        plotsEl.append(box);
        const series = errors.series.map((ys, i) => ys.map((y) => y * displayScale(errors.units[i])));
        simPlots.push(timePlot(box, { title: 'Tracking error (simulated − planned)', t: errors.t, series, names: errors.names, units: errors.units.map(displayUnit), onSeek: (t) => seek(t), marks: () => [] }));
      }
      for (const [key, title, unit, limit] of [
        ['i', 'Motor current against its limit', 'A', 'i_max'],
        ['v', 'Motor voltage against its limit', 'V', 'v_max'],
      ]) {
        const signals = [];
        for (const d of sim.answer.drives) {
          const s = sim.series.get(`drive_${d.joint}.motor.${key}`);
          if (!s) continue;
          signals.push({ name: `${d.joint} ${key}`, unit, t: s.t, y: s.y });
          const lim = d[limit];
          if (Number.isFinite(lim) && lim > 0) {
            const span = [s.t[0], s.t.at(-1)];
            signals.push({ name: `${d.joint} +limit`, unit, t: span, y: [lim, lim] }, { name: `${d.joint} −limit`, unit, t: span, y: [-lim, -lim] });
          }
        }
        if (!signals.length) continue;
        const box = h('div', { class: 'plot', dataset: { plot: `sim-${key}` } });
        plotsEl.append(box);
        simPlots.push(signalPlot(box, { title, signals, onSeek: (t) => seek(t) }));
      }
      for (const p of simPlots) p.setTime(time);
    };
    draw();
    return h(
      'div',
      { class: 'sim-view' },
      h('span', { class: 'check' }, toggle, h('label', { for: toggle.id }, 'Play the simulated motion (the planned one as a ghost)')),
      errors.missing.length ? h('p', { class: 'warning' }, `The run has no positions of ${errors.missing.join(', ')}.`) : null,
      sim.problem ? h('p', { class: 'warning' }, `Some series of the run could not be read: ${sim.problem}`) : null,
      plotsEl,
    );
  }

  async function loadSizing() {
    fill(sizingBox, h('p', { role: 'status' }, 'Sizing the drives…'));
    try {
      if (!amplifiers) amplifiers = await api('/api/library/instances?domain=amplifier').catch(() => []);
      sizing = await api(`${base}/motions/${enc(current.id)}/sizing${sizingQuery(sizingSettings)}`);
    } catch (e) {
      // 409: the service cannot size (yet, or while the model converts): a note, not an error.
      // 422: a setting is refused: the form stays, with the problem.
      if (e.status === 422) {
        sizing = null;
        fill(sizingBox, h('h3', {}, 'Drive sizing'), settingsForm(), errorBox(e, 'The sizing settings are refused'));
        return;
      }
      fill(sizingBox, e.status === 409 ? h('p', { class: 'muted sizing-unavailable' }, `Drive sizing is not available: ${e.message}`) : errorBox(e, 'The drives could not be sized'));
      return;
    }
    if (disposed) return;
    renderSizing();
    renderPlots();
    setTime(time);
  }

  // ---------------------------------------------------------------- player
  // The dock player (player.js), shared with results and the live view: the planned motion or,
  // with "Play the simulated motion", the closed-loop run, at 0.1×–4×, a sample per step.
  const player = createPlayer(playerBox, { id: 'motion', label: 'Motion time', onTime: setTime, clockDigits: 2, timeDigits: 3 });
  let timelineCursor = null;

  function renderPlayer() {
    if (!traj) {
      player.clear();
      return;
    }
    const d = traj.duration;
    timelineCursor = h('div', { class: 'timeline-cursor', 'aria-hidden': 'true' });
    const marks = traj.keyframes.map((k) =>
      h(
        'button',
        {
          type: 'button',
          class: `timeline-mark${problems.has(k.index) ? ' invalid' : ''}`,
          style: `left: ${d > 0 ? (k.time / d) * 100 : 0}%`,
          title: `Keyframe ${k.index} at ${num(k.time)} s`,
          'aria-label': `Keyframe ${k.index} at ${num(k.time)} s`,
          onclick: () => seek(k.time),
        },
        String(k.index),
      ),
    );
    player.show(
      { start: 0, stop: d, dt: 1 / traj.rate, at: time },
      h('h3', {}, `Play ${traj.motion} `, h('small', { class: 'muted' }, `${num(d)} s, planned on v${traj.version}`)),
      ctx.versionNumber && traj.version !== ctx.versionNumber
        ? h('p', { class: 'warning' }, `Motions are planned on the latest version (v${traj.version}); this page shows v${ctx.versionNumber}, whose joints may differ.`)
        : null,
      h('div', { class: 'timeline', role: 'group', 'aria-label': 'Keyframe and first-contact times' }, marks, contactMarks(d), timelineCursor),
    );
  }

  /** Shows the motion at time t (the player's time: called by the player). */
  function setTime(t) {
    if (!traj) return;
    time = Math.max(0, Math.min(t, traj.duration));
    if (simView && sim) {
      // The simulated motion moves the model; the planned one is the ghost.
      ctx.setJoints(simulatedAt(time));
      ctx.setGhost?.(sampleAt(traj, time));
    } else ctx.setJoints(sampleAt(traj, time));
    // Moving scene objects follow the same clock.
    viewer.setSceneTime?.(time);
    for (const p of simPlots) p.setTime(time);
    if (timelineCursor) timelineCursor.style.left = `${traj.duration > 0 ? (time / traj.duration) * 100 : 0}%`;
    for (const p of plots) p.setTime(time);
    markTouched();
    poseChanged();
  }

  function seek(t) {
    if (traj) player.seek(t);
  }

  function stop() {
    player.pause();
  }

  // ---------------------------------------------------------------- plots
  async function renderPlots() {
    for (const p of plots) p.destroy();
    plots = [];
    fill(plotsBox);
    if (!traj) return;
    const { timePlot, torqueSpeedPlot } = await import('./plots.js');
    if (disposed || !traj) return;
    for (const p of plots) p.destroy();
    plots = [];
    fill(plotsBox, h('h3', {}, 'Plots'));
    const names = traj.joints;
    // q, qd and qdd in the toolbar's units (as the sliders and keyframes show them).
    const units = (suffix) => traj.units.map((u) => `${displayUnit(u)}${suffix}`);
    const scaled = (series) => series.map((ys, i) => {
      const f = displayScale(traj.units[i]);
      return f === 1 ? ys : ys.map((y) => y * f);
    });
    const tauUnits = traj.units.map((u) => (u === 'rad' ? 'N·m' : 'N'));
    const seekTo = (t) => seek(t);
    for (const [key, title, us, scale] of [
      ['q', 'Position q', units(''), true],
      ['qd', 'Speed qd', units('/s'), true],
      ['qdd', 'Acceleration qdd', units('/s²'), true],
      ['tau', 'Torque / force', tauUnits, false],
    ]) {
      if (!traj[key]) continue;
      const box = h('div', { class: 'plot', dataset: { plot: key } });
      plotsBox.append(box);
      plots.push(timePlot(box, { title, t: traj.t, series: scale ? scaled(traj[key]) : traj[key], names, units: us, onSeek: seekTo, marks: () => contactMarkers(collisions, traj?.duration || 0).map((m) => m.time) }));
    }
    for (const d of sizing?.drives || []) {
      if (!d.operating_points?.speed?.length) {
        // The motor torque needs every value it is made of (the gear's input inertia): no points
        // are drawn from a guess.
        const missing = (d.checks || []).find((c) => c.check === 'peak_torque')?.missing || [];
        plotsBox.append(h('p', { class: 'muted ts-missing', dataset: { joint: d.joint } }, `${d.joint}: no torque–speed plot: the motor torque is not evaluated${missing.length ? ` (missing ${missing.join(', ')})` : ''}.`));
        continue;
      }
      const box = h('div', { class: 'plot', dataset: { plot: `ts-${d.joint}` } });
      plotsBox.append(box);
      plots.push(torqueSpeedPlot(box, { title: `${d.joint}: ${d.motor?.name || 'motor'} torque–speed`, op: d.operating_points, envelope: d.envelope }));
    }
    for (const p of plots) p.setTime(time);
  }

  // ---------------------------------------------------------------- sizing
  function renderSizing() {
    if (!sizing) {
      fill(sizingBox);
      return;
    }
    const drives = sizing.drives.map((d) => {
      const rows = d.checks.map((c) => {
        const v = verdict(c);
        const cls = c.status === 'not_evaluated' ? 'info' : c.pass ? (c.within_reserve === false ? 'pass below-reserve' : 'pass') : 'fail';
        const value = (x) => (x === null || x === undefined ? '—' : `${num(x)} ${unitLabel(c.unit)}`);
        return h(
          'tr',
          { class: cls, dataset: { check: c.check } },
          h('th', { scope: 'row' }, c.label || c.check, c.detail ? h('small', { class: 'muted' }, ` ${c.detail}`) : null, c.rule ? h('small', { class: 'muted rule' }, ` Rule: ${c.rule}`) : null),
          h('td', { class: 'num' }, value(c.value)),
          h('td', { class: 'num' }, value(c.limit)),
          h('td', { class: 'source lib-small' }, c.source || (c.missing?.length ? `missing: ${c.missing.join(', ')}` : '—')),
          h('td', { class: 'num' }, c.margin === null || c.margin === undefined ? '—' : `${num(Math.round(c.margin * 1000) / 10)} %`),
          h('td', { class: 'verdict' }, v),
        );
      });
      const alts = (d.alternatives || []).map((a) =>
        h(
          'li',
          { dataset: { rank: String(a.rank), standing: a.standing } },
          h('strong', {}, `${a.motor.name} + ${a.gear.name}`),
          a.ratio !== null && a.ratio !== undefined ? ` · ratio ${num(a.ratio)} · ` : ' · ',
          h('span', { class: `standing ${a.standing}` }, standingLabel(a.standing)),
          ` · limited by ${limitingText(a)} `,
          a.pass ? h('button', { type: 'button', onclick: (e) => apply(d, a, e.currentTarget), 'aria-label': `Apply ${a.motor.name} with ${a.gear.name} to ${d.joint}` }, 'Apply') : null,
          h('br'),
          h('small', { class: 'muted why' }, a.why),
        ),
      );
      return h(
        'section',
        { class: `sizing card ${d.pass ? 'pass' : 'fail'}`, dataset: { joint: d.joint }, 'aria-label': `Sizing of the drive of ${d.joint}` },
        h('h4', {}, `${d.joint}: ${d.motor?.name || '—'} + ${d.gear?.name || '—'}${d.ratio ? ` (ratio ${num(d.ratio)})` : ''} `, h('span', { class: `badge ${d.pass ? 'badge-succeeded' : 'badge-failed'}` }, d.pass ? 'pass' : 'fail')),
        h(
          'div',
          { class: 'scroll' },
          h(
            'table',
            { class: 'checks' },
            h('thead', {}, h('tr', {}, ['Check', 'Value', 'Limit', 'Source of the limit', 'Margin', 'Result'].map((c) => h('th', { scope: 'col' }, c)))),
            h('tbody', {}, rows),
          ),
        ),
        d.missing?.length ? h('div', { class: 'warning missing' }, h('strong', {}, 'Not evaluated, missing data: '), d.missing.join(', ')) : null,
        h('p', { class: `muted reserve-verdict` }, d.passes_with_reserve ? `Passes every check with the ${num(Math.round(sizing.settings.reserve * 1000) / 10)} % reserve.` : d.pass ? `No check fails, but not every check is evaluated or keeps the ${num(Math.round(sizing.settings.reserve * 1000) / 10)} % reserve.` : 'At least one check fails.'),
        alts.length
          ? [h('h5', {}, 'Ranked alternatives'), sizing.ranking ? h('p', { class: 'muted ranking' }, `Ranked by ${sizing.ranking}.`) : null, h('ol', { class: 'alternatives' }, alts)]
          : h('p', { class: 'muted' }, 'The library has no motor and gear for this joint.'),
      );
    });
    const undriven = sizing.undriven || [];
    fill(
      sizingBox,
      h('h3', {}, 'Drive sizing ', h('small', { class: 'muted' }, `at ${sizing.rate} Hz over ${num(sizing.duration)} s`)),
      settingsForm(),
      settingsSummary(sizing.settings),
      drives.length ? drives : h('p', { class: 'muted' }, 'No joint has a drive: add one under Drives to size it.'),
      sizing.not_sized?.length
        ? h('div', { class: 'warning not-sized' }, h('strong', {}, 'Drives not sized: '), h('ul', {}, sizing.not_sized.map((x) => h('li', {}, `${x.joint}: ${x.problem}`))))
        : null,
      sizing.orphaned?.length ? h('p', { class: 'muted' }, `Drives of joints this version lacks (not sized): ${sizing.orphaned.join(', ')}.`) : null,
      undriven.length
        ? [
            h('h4', {}, 'Joints without a drive'),
            h(
              'table',
              { class: 'undriven' },
              h('thead', {}, h('tr', {}, ['Joint', 'Peak torque', 'RMS torque', 'Max speed'].map((c) => h('th', { scope: 'col' }, c)))),
              h('tbody', {}, undriven.map((u) => h('tr', {}, h('th', { scope: 'row' }, u.joint), h('td', { class: 'num' }, num(u.peak_torque)), h('td', { class: 'num' }, num(u.rms_torque)), h('td', { class: 'num' }, num(u.max_speed))))),
            ),
          ]
        : null,
      h('div', { class: 'sizing-out', 'aria-live': 'polite' }),
    );
  }

  /** The amplifier, duty cycle, reserve and brake the sizing runs with. */
  function settingsForm() {
    const s = sizingSettings;
    // No min/max here: the service checks the settings and its 422 names the field.
    const input = (name, label, value, attrs = {}) => {
      const el = h('input', { name, type: 'number', step: 'any', value: value ?? '', ...attrs });
      el.addEventListener('change', () => (s[name] = el.value === '' ? '' : Number(el.value)));
      return h('label', { class: 'field' }, label, ' ', el);
    };
    const amp = h('select', { name: 'amplifier', 'aria-label': 'Amplifier' }, h('option', { value: '' }, 'none (voltage and current not evaluated)'), (amplifiers || []).map((a) => h('option', { value: a.id }, a.name)));
    amp.value = s.amplifier;
    amp.addEventListener('change', () => (s.amplifier = amp.value));
    const brake = h('select', { name: 'brake', 'aria-label': 'Brake' }, h('option', { value: 'none' }, 'none'), h('option', { value: 'resistor' }, 'brake resistor'), h('option', { value: 'bus' }, 'DC bus capacitors'));
    brake.value = s.brake;
    brake.addEventListener('change', () => (s.brake = brake.value));
    return h(
      'form',
      {
        class: 'sizing-settings row',
        'aria-label': 'Sizing settings',
        onsubmit: (e) => {
          e.preventDefault();
          loadSizing();
        },
      },
      h('label', { class: 'field' }, 'Amplifier ', amp),
      input('supplyVoltage', 'Supply voltage (V)', s.supplyVoltage),
      input('reservePercent', 'Reserve (%)', s.reservePercent),
      input('dwell', 'Dwell between repetitions (s)', s.dwell),
      h('label', { class: 'field' }, 'Brake ', brake),
      input('brakePower', 'Resistor power (W)', s.brakePower),
      input('busCapacitance', 'Bus capacitance (F)', s.busCapacitance),
      input('busVoltageMax', 'Bus max voltage (V)', s.busVoltageMax),
      input('screwLife', 'Required screw life (h)', s.screwLife, { title: 'Ball and lead screws: the nominal life L10 = (C_a/F_m)³·10⁶ revolutions must cover this many hours of the repeated motion; empty: not checked' }),
      h('button', { type: 'submit' }, 'Size again'),
    );
  }

  /** What the report says it ran with. */
  function settingsSummary(st) {
    if (!st) return null;
    const a = st.amplifier;
    const brake = !st.brake ? 'no brake set' : st.brake.kind === 'resistor' ? `brake resistor ${num(st.brake.power)} W` : `DC bus ${num(st.brake.capacitance)} F up to ${num(st.brake.voltage_max)} V`;
    return h(
      'p',
      { class: 'muted sizing-summary' },
      `Reserve ${num(Math.round(st.reserve * 1000) / 10)} % · duty cycle: motion ${num(sizing.duration)} s + dwell ${num(st.dwell)} s · `,
      a ? `amplifier ${a.name} at ${a.supply_voltage === null ? '(no supply voltage set)' : `${num(a.supply_voltage)} V`} (${a.i_cont === null ? '?' : num(a.i_cont)} A continuous, ${a.i_peak === null ? '?' : num(a.i_peak)} A peak)` : 'no amplifier',
      ` · ${brake}`,
      st.screw_life ? ` · required screw life ${num(st.screw_life)} h` : '',
      a?.source ? h('small', { title: a.source }, ' (amplifier source)') : null,
    );
  }

  async function apply(d, alt, button) {
    const out = sizingBox.querySelector('.sizing-out');
    button.disabled = true;
    try {
      const [data, instances] = await Promise.all([api(`${base}/drives`), api('/api/library/instances')]);
      const drive = data.drives.find((x) => x.joint === d.joint);
      if (!drive) throw new Error(`${d.joint} has no drive any more`);
      const gearRatio = instances.find((i) => i.id === alt.gear.id)?.values?.ratio;
      await api(`${base}/drives/${enc(d.joint)}`, { method: 'PUT', body: applyAlternative(drive, alt, gearRatio) });
      ctx.drivesChanged?.();
      ctx.say(`Applied ${alt.motor.name} with ${alt.gear.name} to ${d.joint}`, 'ok');
      await loadSizing();
      fill(sizingBox.querySelector('.sizing-out'), h('p', { class: 'ok applied' }, `Applied ${alt.motor.name} with ${alt.gear.name} to ${d.joint}.`));
    } catch (e) {
      fill(out, errorBox(e, 'Could not apply the alternative'));
      button.disabled = false;
    }
  }

  // ---------------------------------------------------------------- collisions along the motion
  function resetCollisions() {
    collisions = null;
    if (contactPair) viewer.setContacts?.([], []);
    contactPair = null;
    fill(collisionBox);
  }

  function renderCollisions() {
    if (!traj) {
      fill(collisionBox);
      return;
    }
    const check = h('button', { type: 'button', id: 'motion-check-collisions', onclick: (e) => checkCollisions(e.currentTarget) }, collisions ? 'Check collisions again' : 'Check collisions');
    if (!collisions) {
      fill(collisionBox, h('h3', {}, 'Collisions'), h('p', { class: 'muted' }, 'Check the checked pairs of the collision matrix along this motion.'), check);
      return;
    }
    const c = collisions;
    const rows = sweepRows(c).map((r) => {
      const on = r.key === contactPair;
      return h(
        'tr',
        { dataset: { a: r.a, b: r.b }, class: `${r.touches ? 'fail' : 'pass'}${on ? ' selected' : ''}` },
        h(
          'th',
          { scope: 'row' },
          h('button', { type: 'button', class: 'link', 'aria-pressed': String(on), onclick: () => showPair(r.pair), 'aria-label': `Show the closest points of ${r.a} and ${r.b} at ${num(r.at)} s` }, `${r.a} — ${r.b}`),
        ),
        h('td', { class: 'num' }, `${num(r.minDistanceMm)} mm`),
        h('td', { class: 'num' }, `${num(r.at)} s`),
        h('td', { class: 'num' }, r.firstContact === null ? '—' : `${num(r.firstContact)} s`),
        h('td', { class: 'num' }, r.touches ? `${num(r.maxDepthMm)} mm` : '—'),
        h('td', { class: 'verdict' }, r.touches ? 'contact' : 'clear'),
      );
    });
    fill(
      collisionBox,
      h('h3', {}, 'Collisions ', h('small', { class: 'muted' }, `${c.samples} samples at ${num(c.rate_hz)} Hz, on v${c.version}`)),
      h('p', { class: `first-contact ${c.first_contact ? 'warning' : 'ok'}` }, firstContactText(c)),
      rows.length
        ? h(
            'div',
            { class: 'scroll' },
            h(
              'table',
              { class: 'checks motion-collisions-table', 'aria-label': 'Collisions along the motion' },
              h('thead', {}, h('tr', {}, ['Pair', 'Min distance', 'At', 'First contact', 'Max depth', 'Result'].map((x) => h('th', { scope: 'col' }, x)))),
              h('tbody', {}, rows),
            ),
          )
        : h('p', { class: 'muted' }, 'No checked pair has shapes on both sides: nothing to check (see the Collision tab).'),
      h('p', { class: 'muted guarantee' }, h('strong', {}, 'Guarantee: '), c.guarantee),
      check,
    );
    markTouched();
  }

  async function checkCollisions(button) {
    if (!current) return;
    if (button) button.disabled = true;
    const id = current.id;
    try {
      const c = await api(`${base}/motions/${enc(id)}/collisions`);
      if (disposed || current?.id !== id) return;
      collisions = c;
      contactPair = null;
      viewer.setContacts?.([], []);
      renderCollisions();
      renderPlayer();
      setTime(time);
      // A passing note (it clears itself), not an error that outlives the model: the finding stays in the table.
      ctx.say(firstContactText(c), c.first_contact ? 'info' : 'ok');
    } catch (e) {
      if (button) button.disabled = false;
      collisionBox.append(errorBox(e, 'The collisions could not be checked'));
    }
  }

  /** The pair's closest points: the player goes to the time of its minimum distance. */
  function showPair(p) {
    seek(p.at);
    contactPair = pairKey(p.a, p.b);
    viewer.setContacts?.([p.a, p.b], [witnessLine(p)]);
    renderCollisions();
  }

  function contactMarks(d) {
    return contactMarkers(collisions, d).map((m) =>
      h(
        'button',
        {
          type: 'button',
          class: 'timeline-mark contact-mark',
          style: `left: ${m.left}%`,
          dataset: { time: String(m.time), a: m.a, b: m.b },
          title: `First contact of ${m.a} and ${m.b} at ${num(m.time)} s`,
          'aria-label': `First contact of ${m.a} and ${m.b} at ${num(m.time)} s`,
          onclick: () => seek(m.time),
        },
        '!',
      ),
    );
  }

  /** Table rows of pairs that have touched by the player's time. */
  function markTouched() {
    if (!collisions) return;
    const now = new Set(touchedBy(collisions, time).map((p) => pairKey(p.a, p.b)));
    for (const tr of collisionBox.querySelectorAll('tr[data-a]')) tr.classList.toggle('touched', now.has(pairKey(tr.dataset.a, tr.dataset.b)));
    collisionBox.dataset.touched = String(now.size);
  }

  // ---------------------------------------------------------------- gizmo and live IK
  let gizmoFrameSel = null;
  let gizmoOrient = null;
  let gizmoMode = null;
  let gizmoOn = null;
  let ikOut = null;
  let ikSeq = 0;

  const frameById = (id) => joints?.frames?.find((f) => f.node_id === id);
  const gizmoFrame = () => gizmoFrameSel?.value || joints?.frames?.[0]?.node_id;

  function renderGizmo() {
    const frames = joints?.frames || [];
    if (!frames.length) {
      fill(gizmoBox, h('p', { class: 'muted' }, 'The model has no CAD frames for a tool gizmo.'));
      return;
    }
    const preferred = defaultToolFrame(frames, bodyDepths(ctx.report));
    gizmoFrameSel = h('select', { id: 'gizmo-frame' }, frames.map((f) => h('option', { value: f.node_id, selected: f === preferred }, frameLabel(f))));
    gizmoOn = h('input', { type: 'checkbox', id: 'gizmo-on' });
    gizmoOrient = h('input', { type: 'checkbox', id: 'gizmo-orient' });
    gizmoMode = h('select', { id: 'gizmo-mode' }, h('option', { value: 'translate' }, 'Move'), h('option', { value: 'rotate' }, 'Rotate'));
    ikOut = h('output', { class: 'ik-out', 'aria-live': 'polite' });
    gizmoOn.addEventListener('change', () => (gizmoOn.checked ? showGizmo() : hideGizmo()));
    gizmoFrameSel.addEventListener('change', () => gizmoOn.checked && showGizmo());
    gizmoMode.addEventListener('change', () => {
      gizmo?.setMode(gizmoMode.value);
      if (gizmoMode.value === 'rotate') gizmoOrient.checked = true;
    });
    fill(
      gizmoBox,
      h(
        'fieldset',
        { class: 'gizmo card' },
        h('legend', {}, 'Tool gizmo'),
        field('Tool frame', gizmoFrameSel),
        h('div', { class: 'row' }, h('span', { class: 'check' }, gizmoOn, h('label', { for: 'gizmo-on' }, 'Show the gizmo in 3D')), field('Gizmo mode', gizmoMode)),
        h('span', { class: 'check' }, gizmoOrient, h('label', { for: 'gizmo-orient' }, 'Solve for orientation too')),
        h('p', { class: 'muted' }, 'Drag the gizmo: inverse kinematics moves the model live; on release the gizmo snaps to the pose reached.'),
        ikOut,
      ),
    );
  }

  function showGizmo() {
    const f = frameById(gizmoFrame());
    if (!f) return;
    hideGizmo();
    const m = viewer.frameNow(f);
    if (!m) return;
    gizmo = viewer.showGizmo(m, {
      onDrag: (mat) => {
        stop();
        ikLive(mat);
      },
      onEnd: async (mat) => {
        await ikLive.flush?.();
        await solve(mat);
        gizmo?.setPose(viewer.frameNow(f));
      },
    });
    gizmo?.setMode(gizmoMode.value);
    if (gizmoOn) gizmoOn.checked = true;
    window.cad2moGizmo = gizmo;
  }

  function hideGizmo() {
    viewer.hideGizmo();
    gizmo = null;
    delete window.cad2moGizmo;
  }

  async function solve(mat) {
    const f = gizmoFrame();
    const e = mat.elements;
    const body = { frame: f, position: [e[12], e[13], e[14]], rotation: gizmoOrient?.checked ? rotationRows(e) : null, seed: ctx.currentJoints() };
    const seq = ++ikSeq;
    const run = (async () => {
      try {
        const r = await api(`${base}/ik`, { method: 'POST', body });
        if (disposed) return;
        ctx.setJoints(r.q);
        if (ikOut) {
          ikOut.textContent = `IK ${r.success ? 'reached' : 'closest pose'}: ${num(r.position_error * 1000)} mm, ${num((r.rotation_error * 180) / Math.PI)}°, ${r.iterations} iterations`;
          ikOut.dataset.count = String((Number(ikOut.dataset.count) || 0) + 1);
          ikOut.dataset.success = String(!!r.success);
        }
      } catch (err) {
        if (ikOut && seq === ikSeq) ikOut.textContent = `IK failed: ${err.message}`;
      }
    })();
    return run;
  }
  const ikLive = throttle((mat) => solve(mat), 80);

  /** The sliders or the player moved the model: the gizmo follows its frame. */
  function poseChanged() {
    if (!gizmo || gizmo.controls?.dragging) return;
    const f = frameById(gizmoFrame());
    const m = f && viewer.frameNow(f);
    if (m) gizmo.setPose(m);
  }

  // ---------------------------------------------------------------- joint limits
  const LIMIT_FIELDS = [
    ['lo', 'Lower position', (l) => l.position?.[0], ''],
    ['hi', 'Upper position', (l) => l.position?.[1], ''],
    ['speed', 'Speed', (l) => l.speed, '/s'],
    ['acceleration', 'Acceleration', (l) => l.acceleration, '/s²'],
    ['jerk', 'Jerk', (l) => l.jerk, '/s³'],
  ];

  function renderLimits() {
    if (!joints) return;
    const rows = joints.joints.map((j) => {
      const s = displayScale(j.unit);
      const u = displayUnit(j.unit);
      const inputs = {};
      const cells = LIMIT_FIELDS.map(([key, label, get, suffix]) => {
        const def = get(j.defaults);
        const eff = get(j.limits);
        const custom = j.custom && eff !== undefined && eff !== null && Math.abs(eff - def) > 1e-12 * Math.max(1, Math.abs(def));
        const input = h('input', {
          type: 'text',
          inputmode: 'decimal',
          name: key,
          value: custom ? String(num(eff * s)) : '',
          placeholder: def === undefined || def === null ? '' : String(num(def * s)),
          'aria-label': `${j.name} ${label.toLowerCase()} [${u}${suffix}] (empty: default ${num(def * s)})`,
          autocomplete: 'off',
          class: 'limit',
        });
        inputs[key] = input;
        return h('td', {}, input);
      });
      const msg = h('div', { class: 'field-msg' });
      const saveLimits = async () => {
        const body = {};
        const val = (k) => {
          const t = inputs[k].value.trim();
          if (t === '') return null;
          const x = Number(t);
          inputs[k].setAttribute('aria-invalid', String(!Number.isFinite(x)));
          if (!Number.isFinite(x)) throw new Error(`${j.name}: "${t}" is not a number`);
          return x / s;
        };
        try {
          const lo = val('lo');
          const hi = val('hi');
          if (lo !== null || hi !== null) body.position = [lo ?? j.defaults.position[0], hi ?? j.defaults.position[1]];
          for (const k of ['speed', 'acceleration', 'jerk']) {
            const x = val(k);
            if (x !== null) body[k] = x;
          }
          const stored = await api(`${base}/joints/${enc(j.name)}/limits`, { method: 'PUT', body });
          Object.assign(j, stored && stored.name ? stored : { limits: { ...j.defaults, ...body }, custom: true });
          fill(msg, h('span', { class: 'ok' }, 'Saved'));
          ctx.say(`Saved the limits of ${j.name}`, 'ok');
          renderLimits();
        } catch (e) {
          fill(msg, errorBox(e, `The limits of ${j.name} were not saved`));
        }
      };
      const reset = async () => {
        try {
          await api(`${base}/joints/${enc(j.name)}/limits`, { method: 'DELETE' });
          Object.assign(j, { limits: structuredClone(j.defaults), custom: false });
          ctx.say(`The limits of ${j.name} are the defaults again`, 'ok');
          renderLimits();
        } catch (e) {
          fill(msg, errorBox(e));
        }
      };
      return h(
        'tr',
        { dataset: { joint: j.name }, class: j.custom ? 'custom' : '' },
        h('th', { scope: 'row' }, j.name, h('small', { class: 'muted' }, ` ${j.kind} [${u}]`), j.custom ? h('small', { class: 'badge' }, 'custom') : null, msg),
        cells,
        h(
          'td',
          { class: 'limit-actions' },
          h('button', { type: 'button', onclick: saveLimits, 'aria-label': `Save the limits of ${j.name}` }, 'Save'),
          j.custom ? h('button', { type: 'button', class: 'danger', onclick: reset, 'aria-label': `Reset the limits of ${j.name} to the defaults` }, 'Defaults') : null,
        ),
      );
    });
    const orphans = (joints.orphans || []).map((o) =>
      h(
        'li',
        { dataset: { joint: o.joint } },
        `${o.joint}: `,
        h('code', {}, JSON.stringify(o.limits)),
        ' ',
        h(
          'button',
          {
            type: 'button',
            class: 'danger',
            'aria-label': `Remove the orphaned limits of ${o.joint}`,
            onclick: async () => {
              try {
                await api(`${base}/joints/${enc(o.joint)}/limits`, { method: 'DELETE' });
                joints.orphans = joints.orphans.filter((x) => x.joint !== o.joint);
                renderLimits();
              } catch (e) {
                ctx.say(e.message, 'error');
              }
            },
          },
          'Remove',
        ),
      ),
    );
    fill(
      limitsBox,
      h('p', { class: 'muted' }, `Joints of v${joints.version}. Empty fields use the default shown greyed; units are degrees or millimetres.`),
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          { class: 'limits' },
          h('thead', {}, h('tr', {}, ['Joint', 'Min', 'Max', 'Speed', 'Accel.', 'Jerk', ''].map((c) => h('th', { scope: 'col' }, c)))),
          h('tbody', {}, rows),
        ),
      ),
      orphans.length ? h('div', { class: 'warning orphans' }, h('strong', {}, 'Limits of joints gone from the model: '), h('ul', { class: 'orphaned-limits' }, orphans)) : null,
    );
  }

  load();
  return {
    poseChanged,
    /** The toolbar's units changed: keyframes, limits and plots are drawn in the new ones. */
    unitsChanged() {
      if (disposed || !joints) return;
      renderEditor();
      renderLimits();
      renderPlots();
    },
    shown(on) {
      // The ghost belongs to this tab.
      if (!on) ctx.setGhost?.(null);
      // The closest-point line belongs to this tab.
      if (!on && contactPair) {
        contactPair = null;
        viewer.setContacts?.([], []);
        renderCollisions();
      }
    },
    dispose() {
      disposed = true;
      player.dispose();
      clearSim();
      hideGizmo();
      for (const p of plots) p.destroy();
      plots = [];
    },
  };
}
