// The pieces both results screens share (a version's Results tab and the standalone Results
// page): the .mat upload with its refusals, the timeline player (the dock player, player.js)
// and the charts of searched variables with the cursor at the player's time and the CSV
// export. Each is a small factory over a container element; the screens wire them together.

import { api, upload, enc, ApiError } from '../api.js';
import { h, fill, errorBox, num, bytes, when, plural, newId, unitLabel } from '../ui.js';
import { valueAt, signalsCsv, csvName } from './results-data.js';
import { SPEEDS } from './player-data.js';
import { createPlayer } from './player.js';

const SEARCH_LIMIT = 50;

/** The service's problem, or words for a refusal that came without one (a proxy's 413). */
export function refusal(e, file) {
  if (!(e instanceof ApiError)) return e;
  if (e.status === 413 && !e.detail) {
    return new ApiError(413, { title: 'File too large', detail: `${file.name} (${bytes(file.size)}) is larger than the service accepts.` });
  }
  // The file's field error repeats the detail: shown once.
  const errors = e.errors.filter((x) => !(x.field === 'file' && e.detail && x.message.endsWith(e.detail)));
  return new ApiError(e.status, { title: e.title, detail: e.detail, errors, diagnostics: e.diagnostics });
}

/**
 * The table of results (name, instants, time span, size, upload time) with Open and Delete.
 * @param {object[]} results
 * @param {{current: object|null, open: Function, remove: Function}} o
 */
export function resultTable(results, { current, open, remove }) {
  const rows = results.map((r) =>
    h(
      'tr',
      { dataset: { resultId: r.id }, class: current?.id === r.id ? 'selected' : null, 'aria-current': current?.id === r.id ? 'true' : null },
      // The name with its instants, time span and size under it (a column each ran the table
      // out of the side panel and squeezed the name to a letter per line).
      h(
        'th',
        { scope: 'row' },
        h('button', { type: 'button', class: 'link', 'aria-label': `Open result ${r.name}`, onclick: () => open(r) }, r.name),
        h('small', { class: 'result-meta muted' }, `${r.instants} instants · ${num(r.start)} … ${num(r.stop)} s · ${bytes(r.size)}`),
      ),
      h('td', {}, h('small', {}, when(r.created_at))),
      h('td', { class: 'actions' }, h('button', { type: 'button', class: 'danger', 'aria-label': `Delete result ${r.name}`, onclick: () => remove(r) }, 'Delete')),
    ),
  );
  return h(
    'div',
    { class: 'scroll' },
    h(
      'table',
      { class: 'results' },
      h('thead', {}, h('tr', {}, ['Result', 'Uploaded', ''].map((c) => h('th', { scope: 'col' }, c)))),
      h('tbody', {}, rows),
    ),
  );
}

/**
 * A drop zone and file input that POST a .mat to `url` as multipart "file", with progress; a
 * refusal is shown under the zone.
 * @param {HTMLElement} box
 * @param {{url: string, hint: string, say: Function, done: (created: object) => string}} o
 *   `done` gets the created result and returns the line shown under the zone.
 */
export function resultUpload(box, { url, hint, say, done }) {
  const inputId = newId('result');
  const input = h('input', { type: 'file', id: inputId, accept: '.mat', class: 'visually-hidden' });
  const bar = h('progress', { max: 1, value: 0, class: 'upload-progress', hidden: true, 'aria-label': 'Upload' });
  const state = h('p', { class: 'upload-state', 'aria-live': 'polite' });
  const out = h('div', { class: 'upload-out' });
  const zone = h(
    'label',
    { for: inputId, class: 'dropzone', tabindex: '-1' },
    h('span', { class: 'dropzone-main' }, 'Upload a simulation result'),
    h('span', { class: 'muted' }, hint),
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
  fill(box, input, zone, bar, state, out);

  async function send(file) {
    if (busy || !file) return;
    busy = true;
    fill(out);
    zone.classList.add('busy');
    bar.hidden = false;
    bar.value = 0;
    state.textContent = `Uploading ${file.name} (${bytes(file.size)})…`;
    const form = new FormData();
    form.append('file', file, file.name);
    try {
      const created = await upload(url, form, (f) => {
        bar.value = f;
        state.textContent = f < 1 ? `Uploading ${file.name}: ${Math.round(f * 100)} %` : `Reading ${file.name}…`;
      });
      say(`Result ${created.name} uploaded.`, 'ok');
      state.textContent = done(created) || '';
    } catch (e) {
      state.textContent = '';
      fill(out, errorBox(refusal(e, file), `${file.name} was refused`));
    } finally {
      busy = false;
      bar.hidden = true;
      zone.classList.remove('busy');
    }
  }
}

/**
 * The timeline of an open result: the dock player (player.js: Play/Pause, the scrubber, the
 * clock, a step back and forward to the neighbouring sample, speed 0.1×–10× and loop). The box
 * carries data-time and data-playing (read by the end-to-end tests).
 * @param {HTMLElement} box
 * @param {{onTime: (t: number) => void, times?: () => ArrayLike<number> | undefined}} o
 *   onTime: called whenever the time changes; times: the result's sample instants (for Step)
 */
export function resultPlayer(box, { onTime, times = () => undefined }) {
  const player = createPlayer(box, { id: 'results', label: 'Result time', onTime, speeds: SPEEDS, clockDigits: 3 });
  return {
    /** Shows the player for result `r` (heading and notes above the controls), at its start. */
    show: (r, ...head) => player.show({ start: r.start, stop: r.stop, times: times() }, ...head),
    clear: (...content) => player.clear(...content),
    stop: () => player.pause(),
    setTime: (t) => player.setTime(t),
    /** Stops and goes to time t (a click on a chart). */
    seek: (t) => player.seek(t),
    get time() {
      return player.time;
    },
  };
}

/**
 * "Plots": any number of charts, each with a variable search, the plotted variables as chips, a
 * uPlot chart whose cursor follows the player and whose clicks seek it, and the values at the
 * cursor; an "Export CSV" of every plotted signal at full resolution.
 * @param {HTMLElement} box
 * @param {{result: () => object|null, time: () => number, seek: (t: number) => void, say: Function}} o
 */
export function resultCharts(box, { result, time, seek, say }) {
  let charts = [];
  let seq = 0;
  let alive = true;
  const chartsBox = h('div', { class: 'result-charts' });

  function show() {
    destroy();
    const add = h('button', { type: 'button', id: 'results-add-chart', onclick: () => addChart() }, 'Add chart');
    const csv = h('button', { type: 'button', id: 'results-csv', onclick: () => exportCsv(csv) }, 'Export CSV');
    fill(box, h('h3', {}, 'Plots'), h('div', { class: 'row' }, add, csv), chartsBox);
    fill(chartsBox);
    addChart();
  }

  function destroy() {
    for (const c of charts) c.plot?.destroy();
    charts = [];
    seq = 0;
    fill(box);
  }

  function addChart() {
    seq += 1;
    const n = seq;
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
      h('div', { class: 'row chart-head' }, h('h4', {}, `Chart ${n}`), h('button', { type: 'button', class: 'danger', 'aria-label': `Remove chart ${n}`, onclick: () => removeChart(c) }, 'Remove chart')),
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
        const found = await api(`/api/results/${enc(result().id)}/variables?search=${enc(q)}&limit=${SEARCH_LIMIT}`);
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
      const got = await api(`/api/results/${enc(result().id)}/series?${q}&width=${width}`);
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
      if (!alive || !charts.includes(c)) return;
      c.plot?.destroy();
      fill(c.plotBox);
      c.plot = signalPlot(c.plotBox, { title: `Chart ${c.n}`, signals: c.signals, onSeek: seek });
      showTime(c);
    });
  }

  /** The cursor and the values at the player's time under a chart. */
  function showTime(c) {
    const t = time();
    c.plot?.setTime(t);
    if (!c.signals.length) return;
    fill(
      c.readout,
      h('span', { class: 'muted' }, `at ${num(t)} s: `),
      c.signals.map((s, i) => {
        const v = valueAt(s, t);
        return h('span', { class: 'reading', dataset: { var: s.name, value: v === null ? '' : String(v) } }, i ? ' · ' : '', `${s.name} = ${num(v)}${unitLabel(s.unit) ? ' ' + s.unit : ''}`);
      }),
    );
  }

  /** Downloads the plotted signals (every chart's, once each) as CSV, at full resolution. */
  async function exportCsv(button) {
    const names = [...new Set(charts.flatMap((c) => c.signals.map((s) => s.name)))];
    if (!names.length) {
      say('Plot a variable first: the CSV holds the plotted signals.', 'error');
      return;
    }
    button.disabled = true;
    try {
      const r = result();
      const q = names.map((n) => `name=${enc(n)}`).join('&');
      const got = await api(`/api/results/${enc(r.id)}/series?${q}&width=10000`);
      const blob = new Blob([signalsCsv(got.variables)], { type: 'text/csv' });
      const a = h('a', { href: URL.createObjectURL(blob), download: csvName(r.name) });
      document.body.append(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
      say(`Exported ${plural(names.length, 'signal')} as CSV.`, 'ok');
    } catch (e) {
      say(e.message, 'error');
    } finally {
      button.disabled = false;
    }
  }

  return {
    /** Shows the plots of the open result: one empty chart. */
    show,
    /** Removes every chart. */
    clear: destroy,
    /** The player's time changed: every chart's cursor and readout follow. */
    update() {
      for (const c of charts) showTime(c);
    },
    dispose() {
      alive = false;
      destroy();
    },
  };
}

/**
 * Deletes result `r` after asking; false when the user declined or the service refused (said).
 * @returns {Promise<boolean>}
 */
export async function deleteResult(r, say, confirmAction) {
  if (!(await confirmAction(`Delete the result ${r.name}?`))) return false;
  try {
    await api(`/api/results/${enc(r.id)}`, { method: 'DELETE' });
  } catch (e) {
    say(e.message, 'error');
    return false;
  }
  say(`Deleted the result ${r.name}.`, 'ok');
  return true;
}
