// The Results tab of a model version: upload a simulation result (.mat from Dymola or
// OpenModelica), list and delete the version's results, and open one: its summary (where each
// body's pose came from, the self-checks), the CAD meshes animated in the 3D view from the
// result's pose stream with a timeline (play, pause, scrub, speed, loop), uPlot charts of any
// variables with a cursor at the 3D time, and a CSV of the plotted signals.

import { api, enc } from '../api.js';
import { h, fill, errorBox, confirmAction, num, bytes, when, plural } from '../ui.js';
import { parsePoses, posesAt, missingJoints } from './results-data.js';
import { resultUpload, resultTable, resultPlayer, resultCharts, deleteResult } from './result-kit.js';

/**
 * @param {HTMLElement} panel  the tab panel
 * @param {{modelId: string, versionNumber: number, viewer: object, stage: HTMLElement, say: Function, select: Function}} ctx
 * @returns {{shown(on: boolean): void, dispose(): void}}
 */
export function renderResults(panel, ctx) {
  const { viewer } = ctx;
  const listUrl = `/api/models/${enc(ctx.modelId)}/versions/${ctx.versionNumber}/results`;
  let results = [];
  let current = null; // the open Result
  let stream = null; // its parsed pose stream
  let poseBuf = null;
  let shown = false;
  let disposed = false;
  let opening = 0;

  const uploadBox = h('section', { class: 'results-upload', 'aria-label': 'Upload a result' });
  const listBox = h('div', { class: 'results-list-box' });
  const summaryBox = h('div', { class: 'result-summary-box' });
  const playerBox = h('div', { class: 'player-box results-player' });
  const plotsBox = h('div', { class: 'result-plots' });
  fill(panel, h('h2', {}, 'Results'), uploadBox, listBox, summaryBox);
  fill(ctx.stage, playerBox, plotsBox);

  const player = resultPlayer(playerBox, {
    times: () => stream?.times,
    onTime(t) {
      if (shown && stream?.bodies.length) viewer.setBodyPoses(stream.bodies, posesAt(stream, t, poseBuf));
      if (shown) viewer.setSceneTime?.(t);
      plots.update();
    },
  });
  const plots = resultCharts(plotsBox, { result: () => current, time: () => player.time, seek: (t) => player.seek(t), say: ctx.say });

  resultUpload(uploadBox, {
    url: listUrl,
    hint: `Drop a .mat file here, or press to choose one: a Dymola or OpenModelica result of this model (v${ctx.versionNumber}).`,
    say: ctx.say,
    done(created) {
      results = [created, ...results.filter((r) => r.id !== created.id)];
      renderList();
      open(created);
      return `${created.name}: ${plural(created.variables, 'variable')}, ${plural(created.instants, 'instant')}, ${plural(created.bodies.length, 'body', 'bodies')} with poses.`;
    },
  });

  // ---------------------------------------------------------------- list
  async function load() {
    delete listBox.dataset.state;
    fill(listBox, h('p', { class: 'muted' }, 'Loading the results…'));
    try {
      results = await api(listUrl);
    } catch (e) {
      fill(listBox, errorBox(e, 'The results could not be listed'));
      return;
    }
    if (disposed) return;
    renderList();
  }

  function renderList() {
    listBox.dataset.state = 'listed'; // the e2e run waits for it (the list loads after the tab opens)
    if (!results.length) {
      fill(listBox, h('p', { class: 'muted' }, 'No results for this version yet.'));
      return;
    }
    fill(listBox, resultTable(results, { current, open, remove }));
  }

  async function remove(r) {
    if (!(await deleteResult(r, ctx.say, confirmAction))) return;
    results = results.filter((x) => x.id !== r.id);
    if (current?.id === r.id) close();
    renderList();
  }

  // ---------------------------------------------------------------- open / summary
  async function open(r) {
    const mine = ++opening;
    player.stop();
    current = r;
    stream = null;
    renderList();
    renderSummary(r);
    player.clear(h('p', { role: 'status' }, `Loading the poses of ${r.name}…`));
    plots.clear();
    let s;
    try {
      const buf = await api(`/api/results/${enc(r.id)}/poses`, { accept: 'application/octet-stream' });
      s = parsePoses(buf, r.bodies);
    } catch (e) {
      if (mine === opening) player.clear(errorBox(e, 'The poses could not be loaded'));
      return;
    }
    if (mine !== opening || disposed) return;
    stream = s;
    poseBuf = new Float64Array(s.bodies.length * 7);
    plots.show();
    player.show(
      r,
      h('h3', {}, `Play ${r.name} `, h('small', { class: 'muted' }, `${num(r.stop - r.start)} s, ${plural(stream.bodies.length, 'body', 'bodies')} animated`)),
      stream.bodies.length ? null : h('p', { class: 'warning' }, 'This result has no body poses: the 3D view keeps the joint sliders’ pose.'),
      // Some joint angles but not all: the bodies they would move need the missing ones too.
      (() => {
        const lacking = r.joints_found?.length ? missingJoints(ctx.viewer?.report, r.joints_found) : [];
        return lacking.length
          ? h('p', { class: 'warning missing-joints' }, `This result holds ${plural(r.joints_found.length, 'joint coordinate')} of the model but not ${lacking.join(', ')}: bodies that depend on ${lacking.length === 1 ? 'it' : 'them'} are not animated.`)
          : null;
      })(),
    );
  }

  function close() {
    opening += 1;
    current = null;
    stream = null;
    player.clear();
    plots.clear();
    fill(summaryBox);
    viewer.setBodyPoses(null);
  }

  function renderSummary(r) {
    const rows = [];
    const row = (k, ...v) => rows.push(h('tr', {}, h('th', { scope: 'row' }, k), h('td', {}, ...v)));
    const bodyList = (names, cls) =>
      names.length
        ? h(
            'ul',
            { class: `inline-list ${cls}` },
            names.map((n) => h('li', {}, h('button', { type: 'button', class: 'link', 'aria-label': `Show body ${n} in 3D`, onclick: () => ctx.select?.({ kind: 'body', name: n }) }, n))),
          )
        : h('span', { class: 'muted' }, 'none');
    row('Variables', String(r.variables));
    row('Instants', String(r.instants));
    row('Time span', `${num(r.start)} … ${num(r.stop)} s`);
    row('Precision', r.precision);
    row('File', `${bytes(r.size)}, uploaded ${when(r.created_at)}`);
    row('Poses from frames', bodyList(r.from_frames || [], 'from-frames'));
    row('Poses from joint coordinates', bodyList(r.from_joints || [], 'from-joints'));
    row('Bodies missing', r.missing?.length ? h('span', { class: 'warn' }, bodyList(r.missing, 'missing')) : h('span', { class: 'ok' }, 'none'));
    row('Joints found', r.joints_found?.length ? r.joints_found.join(', ') : h('span', { class: 'muted' }, 'none'));
    // Self-checks: null when the file has nothing to check them on.
    const c = r.checks || {};
    const check = (label, v, text) => row(label, v === undefined || v === null ? h('span', { class: 'muted' }, 'not checked') : text(v));
    check('Orthonormality', c.orthonormality, (v) => `largest |R·Rᵀ − I| = ${num(v)}`);
    check('Rigidity', c.rigidity, (v) => `fixed translations stay within ${num(v * 1000)} mm`);
    check('Kinematics', c.kinematics, (v) => `frames within ${num(v * 1000)} mm of our kinematics of the file’s joint values`);
    for (const [k, v] of Object.entries(c)) if (!['orthonormality', 'rigidity', 'kinematics'].includes(k)) row(k, typeof v === 'number' ? num(v) : JSON.stringify(v));
    fill(
      summaryBox,
      h('h3', {}, `Result ${r.name}`),
      h('table', { class: 'details-table result-summary', 'aria-label': `Summary of result ${r.name}` }, h('tbody', {}, rows)),
      r.missing?.length ? h('p', { class: 'muted' }, 'Bodies without poses stay where the joint sliders put them.') : null,
    );
  }

  load();
  return {
    /** The tab was shown or hidden: the result's poses apply only while it is shown. */
    shown(on) {
      shown = on;
      if (on) {
        if (current && stream) player.setTime(player.time);
      } else {
        player.stop();
        viewer.setBodyPoses(null);
      }
    },
    dispose() {
      disposed = true;
      player.stop();
      plots.dispose();
    },
  };
}
