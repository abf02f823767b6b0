// The Results tab of a model version: upload a simulation result (.mat from Dymola or
// OpenModelica), list and delete the version's results, and open one: its summary (where each
// body's pose came from, the self-checks), the CAD meshes animated in the 3D view from the
// result's pose stream with a timeline (play, pause, scrub, speed, loop), uPlot charts of any
// variables with a cursor at the 3D time, and a CSV of the plotted signals.

import { api, upload, enc, ApiError } from '../api.js';
import { h, fill, errorBox, confirmAction, num, bytes, when, plural, newId, unitLabel } from '../ui.js';
import { parsePoses, posesAt, valueAt, advance, SPEEDS, signalsCsv, csvName } from './results-data.js';

const SEARCH_LIMIT = 50;

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
  let time = 0;
  let playing = false;
  let raf = 0;
  let speed = 1;
  let loop = false;
  let shown = false;
  let disposed = false;
  let opening = 0;
  let charts = [];
  let chartSeq = 0;

  const uploadBox = h('section', { class: 'results-upload', 'aria-label': 'Upload a result' });
  const listBox = h('div', { class: 'results-list-box' });
  const summaryBox = h('div', { class: 'result-summary-box' });
  const playerBox = h('div', { class: 'player-box results-player', dataset: { playing: 'false' } });
  const chartsBox = h('div', { class: 'result-charts' });
  const plotsBox = h('div', { class: 'result-plots' });
  fill(panel, h('h2', {}, 'Results'), uploadBox, listBox, summaryBox);
  fill(ctx.stage, playerBox, plotsBox);

  // ---------------------------------------------------------------- upload
  const inputId = newId('result');
  const input = h('input', { type: 'file', id: inputId, accept: '.mat', class: 'visually-hidden' });
  const bar = h('progress', { max: 1, value: 0, class: 'upload-progress', hidden: true, 'aria-label': 'Upload' });
  const state = h('p', { class: 'upload-state', 'aria-live': 'polite' });
  const uploadOut = h('div', { class: 'upload-out' });
  const zone = h(
    'label',
    { for: inputId, class: 'dropzone', tabindex: '-1' },
    h('span', { class: 'dropzone-main' }, 'Upload a simulation result'),
    h('span', { class: 'muted' }, `Drop a .mat file here, or press to choose one: a Dymola or OpenModelica result of this model (v${ctx.versionNumber}).`),
  );
  let busy = false;
  input.addEventListener('change', () => {
    send(input.files[0]);
    input.value = '';
  });
  input.addEventListener('focus', () => zone.classList.add('focus'));
  input.addEventListener('blur', () => zone.classList.remove('focus'));
  zone.addEventListener('dragover', (e) => {
    e.preventDefault();
    zone.classList.add('over');
  });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('over');
    send(e.dataTransfer?.files?.[0]);
  });
  fill(uploadBox, input, zone, bar, state, uploadOut);

  async function send(file) {
    if (busy || !file) return;
    busy = true;
    fill(uploadOut);
    zone.classList.add('busy');
    bar.hidden = false;
    bar.value = 0;
    state.textContent = `Uploading ${file.name} (${bytes(file.size)})…`;
    const form = new FormData();
    form.append('file', file, file.name);
    try {
      const created = await upload(listUrl, form, (f) => {
        bar.value = f;
        state.textContent = f < 1 ? `Uploading ${file.name}: ${Math.round(f * 100)} %` : `Reading ${file.name}…`;
      });
      state.textContent = `${created.name}: ${plural(created.variables, 'variable')}, ${plural(created.instants, 'instant')}, ${plural(created.bodies.length, 'body', 'bodies')} with poses.`;
      ctx.say(`Result ${created.name} uploaded.`, 'ok');
      results = [created, ...results.filter((r) => r.id !== created.id)];
      renderList();
      open(created);
    } catch (e) {
      state.textContent = '';
      fill(uploadOut, errorBox(refusal(e, file), `${file.name} was refused`));
    } finally {
      busy = false;
      bar.hidden = true;
      zone.classList.remove('busy');
    }
  }

  /** The service's problem, or words for a refusal that came without one (a proxy's 413). */
  function refusal(e, file) {
    if (!(e instanceof ApiError)) return e;
    if (e.status === 413 && !e.detail) {
      return new ApiError(413, { title: 'File too large', detail: `${file.name} (${bytes(file.size)}) is larger than the service accepts.` });
    }
    // The file's field error repeats the detail: shown once.
    const errors = e.errors.filter((x) => !(x.field === 'file' && e.detail && x.message.endsWith(e.detail)));
    return new ApiError(e.status, { title: e.title, detail: e.detail, errors, diagnostics: e.diagnostics });
  }

  // ---------------------------------------------------------------- list
  async function load() {
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
    if (!results.length) {
      fill(listBox, h('p', { class: 'muted' }, 'No results for this version yet.'));
      return;
    }
    const rows = results.map((r) =>
      h(
        'tr',
        { dataset: { resultId: r.id }, class: current?.id === r.id ? 'selected' : null, 'aria-current': current?.id === r.id ? 'true' : null },
        h('th', { scope: 'row' }, h('button', { type: 'button', class: 'link', 'aria-label': `Open result ${r.name}`, onclick: () => open(r) }, r.name)),
        h('td', { class: 'num' }, String(r.instants)),
        h('td', { class: 'nowrap' }, `${num(r.start)} … ${num(r.stop)} s`),
        h('td', { class: 'num' }, bytes(r.size)),
        h('td', {}, h('small', {}, when(r.created_at))),
        h('td', { class: 'actions' }, h('button', { type: 'button', class: 'danger', 'aria-label': `Delete result ${r.name}`, onclick: () => remove(r) }, 'Delete')),
      ),
    );
    fill(
      listBox,
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          { class: 'results' },
          h('thead', {}, h('tr', {}, ['Result', 'Instants', 'Time', 'Size', 'Uploaded', ''].map((c) => h('th', { scope: 'col' }, c)))),
          h('tbody', {}, rows),
        ),
      ),
    );
  }

  async function remove(r) {
    if (!(await confirmAction(`Delete the result ${r.name}?`))) return;
    try {
      await api(`/api/results/${enc(r.id)}`, { method: 'DELETE' });
    } catch (e) {
      ctx.say(e.message, 'error');
      return;
    }
    results = results.filter((x) => x.id !== r.id);
    if (current?.id === r.id) close();
    renderList();
    ctx.say(`Deleted the result ${r.name}.`, 'ok');
  }

  // ---------------------------------------------------------------- open / summary
  async function open(r) {
    const mine = ++opening;
    stop();
    current = r;
    stream = null;
    renderList();
    renderSummary(r);
    fill(playerBox, h('p', { role: 'status' }, `Loading the poses of ${r.name}…`));
    destroyCharts();
    fill(plotsBox);
    let s;
    try {
      const buf = await api(`/api/results/${enc(r.id)}/poses`, { accept: 'application/octet-stream' });
      s = parsePoses(buf, r.bodies);
    } catch (e) {
      if (mine === opening) fill(playerBox, errorBox(e, 'The poses could not be loaded'));
      return;
    }
    if (mine !== opening || disposed) return;
    stream = s;
    poseBuf = new Float64Array(s.bodies.length * 7);
    time = r.start;
    renderPlayer();
    renderPlots();
    addChart();
    setTime(time);
  }

  function close() {
    opening += 1;
    stop();
    current = null;
    stream = null;
    destroyCharts();
    fill(summaryBox);
    fill(playerBox);
    fill(plotsBox);
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

  // ---------------------------------------------------------------- player
  let scrub = null;
  let clock = null;
  let playBtn = null;

  function renderPlayer() {
    const r = current;
    scrub = h('input', { type: 'range', id: 'results-scrub', min: String(r.start), max: String(r.stop), step: 'any', value: String(r.start) });
    scrub.addEventListener('input', () => {
      stop();
      setTime(Number(scrub.value));
    });
    clock = h('output', { for: scrub.id, class: 'motion-clock' });
    playBtn = h('button', { type: 'button', id: 'results-play', onclick: () => (playing ? stop() : play()) }, 'Play');
    const speedSel = h(
      'select',
      { id: 'results-speed' },
      SPEEDS.map((s) => h('option', { value: String(s), selected: s === speed }, `${s}×`)),
    );
    speedSel.addEventListener('change', () => {
      speed = Number(speedSel.value);
      if (playing) {
        stop();
        play();
      }
    });
    const loopBox = h('input', { type: 'checkbox', id: 'results-loop', checked: loop });
    loopBox.addEventListener('change', () => (loop = loopBox.checked));
    fill(
      playerBox,
      h('h3', {}, `Play ${r.name} `, h('small', { class: 'muted' }, `${num(r.stop - r.start)} s, ${plural(stream.bodies.length, 'body', 'bodies')} animated`)),
      stream.bodies.length ? null : h('p', { class: 'warning' }, 'This result has no body poses: the 3D view keeps the joint sliders’ pose.'),
      h('div', { class: 'player row' }, playBtn, h('label', { for: scrub.id, class: 'visually-hidden' }, 'Result time'), scrub, clock),
      h(
        'div',
        { class: 'row player-options' },
        h('label', { for: speedSel.id }, 'Speed'),
        speedSel,
        h('span', { class: 'check' }, loopBox, h('label', { for: loopBox.id }, 'Loop')),
      ),
    );
  }

  function setTime(t) {
    if (!current) return;
    time = Math.max(current.start, Math.min(t, current.stop));
    if (shown && stream?.bodies.length) viewer.setBodyPoses(stream.bodies, posesAt(stream, time, poseBuf));
    if (scrub && document.activeElement !== scrub) scrub.value = String(time);
    if (clock) clock.textContent = `${time.toFixed(3)} s / ${num(current.stop)} s`;
    playerBox.dataset.time = String(time);
    for (const c of charts) showTime(c);
  }

  function seek(t) {
    stop();
    setTime(t);
  }

  function play() {
    if (!current || !stream) return;
    if (time >= current.stop && !loop) time = current.start;
    playing = true;
    playerBox.dataset.playing = 'true';
    if (playBtn) playBtn.textContent = 'Pause';
    let last = performance.now();
    const tick = (now) => {
      if (!playing) return;
      const { t, ended } = advance(time, (now - last) / 1000, { speed, start: current.start, stop: current.stop, loop });
      last = now;
      setTime(t);
      if (ended) return stop();
      raf = requestAnimationFrame(tick);
    };
    raf = requestAnimationFrame(tick);
  }

  function stop() {
    playing = false;
    cancelAnimationFrame(raf);
    playerBox.dataset.playing = 'false';
    if (playBtn) playBtn.textContent = 'Play';
  }

  // ---------------------------------------------------------------- plots
  function renderPlots() {
    const add = h('button', { type: 'button', id: 'results-add-chart', onclick: () => addChart() }, 'Add chart');
    const csv = h('button', { type: 'button', id: 'results-csv', onclick: () => exportCsv(csv) }, 'Export CSV');
    fill(plotsBox, h('h3', {}, 'Plots'), h('div', { class: 'row' }, add, csv), chartsBox);
    fill(chartsBox);
  }

  function destroyCharts() {
    for (const c of charts) c.plot?.destroy();
    charts = [];
    chartSeq = 0;
  }

  function addChart() {
    chartSeq += 1;
    const n = chartSeq;
    const c = { n, signals: [], plot: null };
    const search = h('input', { type: 'search', id: `chart-${n}-search`, placeholder: 'name or description', autocomplete: 'off' });
    const count = h('p', { class: 'var-count muted', 'aria-live': 'polite' });
    const matches = h('ul', { class: 'var-matches', 'aria-label': `Variables matching the search for chart ${n}` });
    const chips = h('ul', { class: 'chips', 'aria-label': `Variables on chart ${n}` });
    const plotBox = h('div', { class: 'plot', dataset: { chart: String(n) } });
    const readout = h('p', { class: 'readout' });
    const el = h(
      'section',
      { class: 'result-chart card', dataset: { chart: String(n) }, 'aria-label': `Chart ${n}` },
      h(
        'div',
        { class: 'row chart-head' },
        h('h4', {}, `Chart ${n}`),
        h('button', { type: 'button', class: 'danger', 'aria-label': `Remove chart ${n}`, onclick: () => removeChart(c) }, 'Remove chart'),
      ),
      h('div', { class: 'field var-search' }, h('label', { for: search.id }, `Add a variable to chart ${n}`), search, count, matches),
      chips,
      plotBox,
      readout,
    );
    Object.assign(c, { el, search, count, matches, chips, plotBox, readout });
    let timer = 0;
    let asked = 0;
    const find = async () => {
      const q = search.value.trim();
      const mine = ++asked;
      if (!q) {
        fill(matches);
        count.textContent = '';
        return;
      }
      try {
        const found = await api(`/api/results/${enc(current.id)}/variables?search=${enc(q)}&limit=${SEARCH_LIMIT}`);
        if (mine !== asked) return;
        count.textContent = `${found.variables.length} of ${plural(found.total, 'match', 'matches')} shown`;
        fill(
          matches,
          found.variables.map((v) =>
            h(
              'li',
              {},
              h(
                'button',
                {
                  type: 'button',
                  class: 'var-pick',
                  dataset: { var: v.name },
                  disabled: c.signals.some((s) => s.name === v.name),
                  'aria-label': `Plot ${v.name} on chart ${n}`,
                  onclick: () => addSignal(c, v),
                },
                h('code', {}, v.name),
                unitLabel(v.unit) ? ` [${v.unit}]` : '',
                v.constant ? h('small', { class: 'muted' }, ' constant') : null,
              ),
              v.description ? h('small', { class: 'muted' }, ` ${v.description}`) : null,
            ),
          ),
        );
      } catch (e) {
        if (mine === asked) fill(matches, h('li', {}, errorBox(e, 'The variables could not be searched')));
      }
    };
    search.addEventListener('input', () => {
      clearTimeout(timer);
      timer = setTimeout(find, 200);
    });
    search.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') {
        e.preventDefault();
        clearTimeout(timer);
        find();
      }
    });
    c.find = find;
    charts.push(c);
    chartsBox.append(el);
    drawChart(c);
    return c;
  }

  function removeChart(c) {
    c.plot?.destroy();
    c.el.remove();
    charts = charts.filter((x) => x !== c);
  }

  async function addSignal(c, v) {
    if (c.signals.some((s) => s.name === v.name)) return;
    c.signals.push({ name: v.name, unit: v.unit || '', t: [], y: [] });
    await fetchSeries(c);
  }

  function removeSignal(c, name) {
    c.signals = c.signals.filter((s) => s.name !== name);
    drawChart(c);
  }

  async function fetchSeries(c) {
    if (!c.signals.length) return drawChart(c);
    const width = Math.max(10, Math.min(10000, Math.round(c.plotBox.clientWidth || 800)));
    const q = c.signals.map((s) => `name=${enc(s.name)}`).join('&');
    c.readout.textContent = 'Loading…';
    try {
      const got = await api(`/api/results/${enc(current.id)}/series?${q}&width=${width}`);
      const by = new Map(got.variables.map((s) => [s.name, s]));
      c.signals = c.signals.map((s) => by.get(s.name) || s);
    } catch (e) {
      fill(c.readout, errorBox(e, 'The series could not be loaded'));
      return;
    }
    drawChart(c);
  }

  function drawChart(c) {
    c.plot?.destroy();
    c.plot = null;
    // Variables already on the chart cannot be added twice.
    for (const b of c.matches.querySelectorAll('button.var-pick')) {
      const on = c.signals.some((s) => s.name === b.dataset.var);
      b.disabled = on;
      b.title = on ? 'Plotted on this chart' : '';
    }
    fill(
      c.chips,
      c.signals.map((s) =>
        h(
          'li',
          { dataset: { var: s.name } },
          h('code', {}, s.name),
          unitLabel(s.unit) ? ` [${s.unit}]` : '',
          h('button', { type: 'button', class: 'chip-remove', 'aria-label': `Remove ${s.name} from chart ${c.n}`, onclick: () => removeSignal(c, s.name) }, '×'),
        ),
      ),
    );
    fill(c.plotBox);
    if (!c.signals.length) {
      fill(c.readout, h('span', { class: 'muted' }, 'Search for a variable above to plot it.'));
      return;
    }
    import('./plots.js').then(({ signalPlot }) => {
      if (disposed || !charts.includes(c)) return;
      c.plot?.destroy();
      fill(c.plotBox);
      c.plot = signalPlot(c.plotBox, { title: `Chart ${c.n}`, signals: c.signals, onSeek: seek });
      showTime(c);
    });
  }

  /** The cursor and the values at the 3D time under a chart. */
  function showTime(c) {
    c.plot?.setTime(time);
    if (!c.signals.length) return;
    fill(
      c.readout,
      h('span', { class: 'muted' }, `at ${num(time)} s: `),
      c.signals.map((s, i) => {
        const v = valueAt(s, time);
        return h('span', { class: 'reading', dataset: { var: s.name, value: v === null ? '' : String(v) } }, i ? ' · ' : '', `${s.name} = ${num(v)}${unitLabel(s.unit) ? ' ' + s.unit : ''}`);
      }),
    );
  }

  /** Downloads the plotted signals (every chart's, once each) as CSV, at full resolution. */
  async function exportCsv(button) {
    const names = [...new Set(charts.flatMap((c) => c.signals.map((s) => s.name)))];
    if (!names.length) {
      ctx.say('Plot a variable first: the CSV holds the plotted signals.', 'error');
      return;
    }
    button.disabled = true;
    try {
      const q = names.map((n) => `name=${enc(n)}`).join('&');
      const got = await api(`/api/results/${enc(current.id)}/series?${q}&width=10000`);
      const blob = new Blob([signalsCsv(got.variables)], { type: 'text/csv' });
      const a = h('a', { href: URL.createObjectURL(blob), download: csvName(current.name) });
      document.body.append(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
      ctx.say(`Exported ${plural(names.length, 'signal')} as CSV.`, 'ok');
    } catch (e) {
      ctx.say(e.message, 'error');
    } finally {
      button.disabled = false;
    }
  }

  load();
  return {
    /** The tab was shown or hidden: the result's poses apply only while it is shown. */
    shown(on) {
      shown = on;
      if (on) {
        if (current && stream) setTime(time);
      } else {
        stop();
        viewer.setBodyPoses(null);
      }
    },
    dispose() {
      disposed = true;
      stop();
      destroyCharts();
    },
  };
}
