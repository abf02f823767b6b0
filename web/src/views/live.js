// The Live tab of a model version: a running simulation of the version's package (Mechatronics
// with liveView=true) sends its bodies' poses to the service, which relays them here over a
// WebSocket (docs/live-protocol.md). The tab says how to start a stream, shows the connection,
// the newest stream's simulated time, frames per second, lost and stale frames, the real-time
// factor and its end, lists the version's active runs, and moves the meshes in the 3D view:
// frames are decoded in place into reused arrays and drawn at most once per animation frame
// (the newest wins). Every frame of the followed run is also recorded (the last 60 s, at most
// 64 MB: FrameRecorder), and the dock player (player.js) replays the recording: Pause holds the
// frame shown while frames keep arriving, step back and forward frame by frame, scrub, replay at
// 0.1×–4× (between frames the poses are interpolated as a result's are), then Go live. The
// socket is open only while the tab is shown, and reconnects with backoff when it closes
// unexpectedly.

import { api, enc, token } from '../api.js';
import { h, fill, errorBox, num, plural } from '../ui.js';
import { liveUrl, liveProtocols, newFrame, decodeFrame, copyFrame, parseMessage, RateMeter, LiveRuns, backoff, splitHostPort, startModifier, FrameRecorder, RECORD_SECONDS, RECORD_BYTES } from './live-data.js';
import { posesAt } from './results-data.js';
import { createPlayer } from './player.js';

const POLL_MS = 2000;

/** `x` to `digits` decimals (null stays null). */
const round = (x, digits) => (Number.isFinite(x) ? Math.round(x * 10 ** digits) / 10 ** digits : null);

/**
 * @param {HTMLElement} panel  the tab panel
 * @param {{modelId: string, versionNumber: number, viewer: object, stage: HTMLElement, say: Function}} ctx
 * @returns {{shown(on: boolean): void, dispose(): void}}
 */
export function renderLive(panel, ctx) {
  const { viewer } = ctx;
  const base = `/api/models/${enc(ctx.modelId)}/versions/${ctx.versionNumber}/live`;
  let shown = false;
  let disposed = false;
  let epoch = 0; // bumped at every show and hide: stale polls and sockets stop
  let socket = null;
  let retry = 0; // reconnection attempt
  let retryTimer = 0;
  let retryAt = 0;
  let pollTimer = 0;
  let tickTimer = 0;
  let raf = 0;
  let connection = 'closed';
  let closeNote = '';
  let bodies = null; // the hello's body names, the frames' order
  let unknown = [];
  let mismatched = 0;
  let off = null; // why the live view is unavailable here

  // Three frames, reused: the next decode, the newest received, the one the 3D view shows.
  let spare = newFrame();
  let latest = newFrame();
  const held = newFrame();
  let fresh = false; // latest is newer than held
  const runs = new LiveRuns();
  const rate = new RateMeter(1);
  // The followed run's frames, for the player; `replay` when the player shows a recorded time.
  const recorder = new FrameRecorder();
  let recorded = -1; // the recorder's version the player knows
  let replay = false;
  let drawing = false;

  // ---- the panel: how to start a stream, the active runs, the service's counters
  const howBox = h('section', { class: 'live-how', 'aria-label': 'Start a live stream' }, h('p', { class: 'muted' }, 'Asking the service about its live view…'));
  const runsBox = h('section', { class: 'live-runs', 'aria-label': 'Active runs' });
  const serviceBox = h('section', { class: 'live-service', 'aria-label': 'Live service counters' });
  fill(panel, h('h2', {}, 'Live view'), howBox, runsBox, serviceBox);

  // ---- under the 3D view: the player over the recording, the live numbers
  const value = (key) => h('span', { class: 'live-value', dataset: { live: key } }, '—');
  const cells = {};
  const item = (key, label) => {
    cells[key] = value(key);
    return h('div', { class: 'live-item' }, h('span', { class: 'live-label' }, label), cells[key]);
  };
  const note = h('p', { class: 'live-note' });
  const status = h(
    'div',
    { class: 'live-status', role: 'status', 'aria-label': 'Live stream', dataset: { connection, frames: '0', ended: 'false', held: 'false' } },
    h(
      'div',
      { class: 'live-items' },
      item('connection', 'Connection'),
      item('stream', 'Stream'),
      item('time', 'Simulated time (s)'),
      item('frames', 'Frames received'),
      item('fps', 'Frames per second'),
      item('lost', 'Lost'),
      item('stale', 'Stale'),
      item('rtf', 'Real-time factor'),
      item('recorded', 'Recorded'),
    ),
    note,
  );
  const playerBox = h('div', { class: 'player-box live-player' });
  fill(ctx.stage, playerBox, status);
  const player = createPlayer(playerBox, {
    id: 'live',
    label: 'Recorded time',
    live: true,
    unit: 'frame',
    onTime() {
      // Following: the newest frame is drawn; otherwise the recording at the player's time.
      if (player.following) {
        if (replay && latest.n) fresh = true;
        replay = false;
      } else replay = true;
      if (!drawing) schedule();
    },
  });
  player.show(
    { start: 0, stop: 0, times: () => recorder.times },
    h(
      'h3',
      {},
      'Live stream ',
      h('small', { class: 'muted' }, `the last ${RECORD_SECONDS} s are recorded (at most ${Math.round(RECORD_BYTES / 2 ** 20)} MB): pause, step back frame by frame or replay, then Go live`),
    ),
  );

  // ---- the socket
  function connect() {
    if (!shown || disposed || socket || off) return;
    clearTimeout(retryTimer);
    retryTimer = 0;
    let ws;
    try {
      ws = new WebSocket(liveUrl(location, ctx.modelId, ctx.versionNumber), liveProtocols(token()));
    } catch (e) {
      closeNote = e.message;
      return reconnectLater();
    }
    ws.binaryType = 'arraybuffer';
    socket = ws;
    setConnection('connecting');
    ws.onopen = () => ws === socket && setConnection('open');
    ws.onmessage = (e) => {
      if (ws !== socket) return;
      if (typeof e.data === 'string') onText(e.data);
      else onFrame(e.data);
    };
    ws.onclose = (e) => {
      if (ws !== socket) return;
      socket = null;
      closeNote = e.code === 1000 || e.code === 1001 ? '' : `code ${e.code}${e.reason ? `: ${e.reason}` : ''}`;
      reconnectLater();
    };
  }

  function reconnectLater() {
    if (!shown || disposed || off) return setConnection('closed');
    const wait = backoff(retry++);
    retryAt = performance.now() + wait;
    retryTimer = setTimeout(() => {
      retryTimer = 0;
      connect();
    }, wait);
    setConnection('reconnecting');
  }

  function disconnect() {
    clearTimeout(retryTimer);
    retryTimer = 0;
    const ws = socket;
    socket = null;
    if (ws) {
      // Closing a socket still connecting logs an error in Chromium: it closes once open instead.
      if (ws.readyState === WebSocket.CONNECTING) ws.onopen = () => ws.close(1000, 'the Live tab was left');
      else ws.close(1000, 'the Live tab was left');
    }
    setConnection('closed');
  }

  function setConnection(c) {
    connection = c;
    schedule();
  }

  function onText(text) {
    const m = parseMessage(text);
    if (!m) return;
    if (m.type === 'hello') {
      bodies = m.bodies;
      unknown = bodies.filter((b) => viewer.bodies && !viewer.bodies.has(b));
      retry = 0; // a working connection: the next loss reconnects quickly again
      setConnection('open');
      return;
    }
    if (runs.message(m)) {
      if (m.type === 'end') {
        ctx.say?.(`The live stream ended at ${num(runs.endTime)} s.`, 'ok');
        refresh(epoch, false);
      }
      schedule();
    }
  }

  function onFrame(buffer) {
    if (!decodeFrame(buffer, spare)) return;
    const now = performance.now() / 1000;
    const before = runs.run;
    if (!runs.accept(spare.run, now)) return;
    if (runs.run !== before) rate.reset();
    if (bodies && spare.n !== bodies.length) {
      mismatched += 1;
      return;
    }
    rate.tick(now);
    if (runs.run !== before) {
      // A new run: its own recording, followed live.
      recorder.reset();
      player.goLive();
    }
    runs.frame(spare, now);
    spare.received = runs.frames;
    recorder.push(spare);
    [spare, latest] = [latest, spare];
    fresh = true;
    schedule();
  }

  // ---- drawing: at most once per animation frame, the newest frame wins
  function schedule() {
    if (!raf && shown && !disposed) raf = requestAnimationFrame(draw);
  }

  function draw() {
    raf = 0;
    if (!shown || disposed) return;
    drawing = true;
    if (recorder.version !== recorded) {
      recorded = recorder.version;
      player.extend(recorder.start, recorder.stop);
    }
    drawing = false;
    if (player.following) {
      if (fresh && bodies) {
        copyFrame(latest, held);
        fresh = false;
        viewer.setBodyPoses(bodies, held.poses);
      }
    } else if (replay && bodies && recorder.count && recorder.n === bodies.length) {
      // The recorded frame at the player's time (interpolated between two frames).
      const n = recorder.n;
      if (held.poses.length < n * 7) held.poses = new Float64Array(n * 7);
      posesAt(recorder.stream(bodies), player.time, held.poses);
      held.n = n;
      held.time = player.time;
      replay = false;
      viewer.setBodyPoses(bodies, held.poses);
    }
    showNumbers();
  }

  function showNumbers() {
    const now = performance.now() / 1000;
    const s = runs.stats;
    const text = {
      connection: {
        off: 'live view off',
        connecting: 'connecting…',
        open: 'connected',
        reconnecting: `reconnecting in ${Math.max(0, Math.ceil((retryAt - performance.now()) / 1000))} s`,
        closed: 'closed',
      }[connection],
      stream: runs.run === null ? 'waiting for a stream' : `run ${runs.run}${runs.ended ? ', ended' : ''}`,
      time: held.n ? num(held.time) : '—',
      frames: String(runs.frames),
      fps: runs.run === null ? '—' : num(round(rate.rate(now), 1)),
      lost: s ? String(s.lost ?? '—') : '—',
      stale: s ? String(s.stale ?? '—') : '—',
      rtf: s && Number.isFinite(s.realtime_factor) ? num(round(s.realtime_factor, 3)) : '—',
      recorded: recorder.count ? `${plural(recorder.count, 'frame')}, ${num(round(recorder.stop - recorder.start, 2))} s` : '—',
    };
    for (const [k, v] of Object.entries(text)) if (cells[k].textContent !== v) cells[k].textContent = v;
    const d = status.dataset;
    d.connection = connection;
    d.frames = String(runs.frames);
    d.ended = String(runs.ended);
    d.held = String(!player.following);
    d.recorded = String(recorder.count);
    if (held.n) d.time = String(held.time);
    else delete d.time;
    const lines = [];
    if (off) lines.push(off);
    if (connection === 'reconnecting' && closeNote) lines.push(`The connection closed (${closeNote}).`);
    if (runs.ended) lines.push(`Stream ended at ${num(runs.endTime)} s.`);
    if (!player.following && held.n) {
      lines.push(`Paused: the 3D view shows the recorded frame at ${num(held.time)} s while ${runs.ended ? 'the stream has ended' : 'frames keep arriving (and are recorded)'}; Go live follows them again.`);
    }
    if (mismatched) lines.push(`${plural(mismatched, 'frame')} with another body count than this version's ${bodies?.length} ignored.`);
    if (unknown.length) lines.push(`Not in the 3D view: ${unknown.join(', ')}.`);
    const joined = lines.join(' ');
    if (note.textContent !== joined) note.textContent = joined;
    note.classList.toggle('ended', runs.ended);
  }

  // ---- the info endpoints, polled while the tab is shown
  async function refresh(mine, again = true) {
    let info = null;
    let service = null;
    try {
      [info, service] = await Promise.all([api(base), api('/api/live').catch(() => null)]);
    } catch (e) {
      if (mine !== epoch || disposed) return;
      if (e.status === 404 || e.status === 405) {
        off = 'This service has no live view.';
        fill(howBox, h('p', { class: 'muted' }, 'This service has no live view (it predates it, or it is not enabled).'));
        disconnect();
        showNumbers();
        return;
      }
      fill(runsBox, errorBox(e, 'The live view could not be asked'));
    }
    if (mine !== epoch || disposed) return;
    if (info) {
      off = service && service.enabled === false ? 'The live view is off on this service.' : null;
      renderHow(info, service);
      renderRuns(info.streams || []);
      renderService(service);
      if (off) disconnect();
      else connect();
      schedule();
    }
    if (again) {
      clearTimeout(pollTimer);
      pollTimer = setTimeout(() => refresh(mine), POLL_MS);
    }
  }

  let howKey = '';
  function renderHow(info, service) {
    const key = JSON.stringify([info.udp, info.auth_required, info.layout, info.bodies?.length, service?.enabled]);
    if (key === howKey) return;
    howKey = key;
    if (service?.enabled === false) {
      fill(howBox, h('h3', {}, 'Start a stream'), h('p', { class: 'warning' }, 'The live view is off on this service: start it with a live address (cad2mo serve --live-bind).'));
      return;
    }
    const addr = splitHostPort(info.udp);
    fill(
      howBox,
      h('h3', {}, 'Start a stream'),
      h('p', {}, 'Simulate this version’s package with the live view on: set ', h('code', {}, 'liveView = true'), ' on its ', h('code', {}, 'Mechatronics'), ' model, for example with this modifier:'),
      h('pre', { class: 'live-modifier' }, h('code', {}, startModifier(info, location.hostname))),
      h(
        'ul',
        { class: 'report-list' },
        h('li', {}, 'Frames go by UDP to ', h('strong', { class: 'live-udp' }, info.udp || '—'), addr ? ` (livePort = ${addr.port}; liveHost is this service’s host as the simulation reaches it).` : '.'),
        info.auth_required
          ? h('li', { class: 'live-auth' }, h('strong', {}, 'A token is needed: '), 'set ', h('code', {}, 'liveToken'), ' to one of your API tokens (Settings). Frames are signed with its hash; the token itself is never sent.')
          : h('li', { class: 'live-auth' }, h('strong', {}, 'No token needed'), ' on this service (it listens on loopback only); ', h('code', {}, 'liveToken'), ' may stay empty.'),
        h('li', {}, h('code', {}, 'livePeriod'), ' is the simulated time between frames; ', h('code', {}, 'liveRealTime = true'), ' paces the simulation at real time, so the motion plays at its own speed.'),
        h('li', { class: 'muted' }, `${plural(info.bodies?.length || 0, 'body', 'bodies')} per frame, layout ${info.layout || '—'}.`),
      ),
    );
  }

  function renderRuns(streams) {
    if (!streams.length) {
      fill(runsBox, h('h3', {}, 'Active runs'), h('p', { class: 'muted' }, 'No simulation is sending to this version now.'));
      return;
    }
    const rows = streams.map((s) =>
      h(
        'tr',
        { dataset: { run: String(s.run) }, class: s.run === runs.run ? 'selected' : null },
        h('th', { scope: 'row' }, String(s.run)),
        h('td', { class: 'num' }, String(s.frames)),
        h('td', { class: 'num' }, String(s.lost)),
        h('td', { class: 'num' }, String(s.stale)),
        h('td', { class: 'num' }, num(s.time)),
        h('td', { class: 'num' }, num(round(s.rate_hz, 1))),
        h('td', { class: 'num' }, num(round(s.realtime_factor, 3))),
        h('td', {}, s.ended ? 'ended' : `live, seen ${num(round(s.last_seen_s, 1))} s ago`),
      ),
    );
    fill(
      runsBox,
      h('h3', {}, 'Active runs'),
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          { class: 'live-runs-table' },
          h('thead', {}, h('tr', {}, ['Run', 'Frames', 'Lost', 'Stale', 'Time (s)', 'Rate (Hz)', 'Real time ×', 'State'].map((c) => h('th', { scope: 'col' }, c)))),
          h('tbody', {}, rows),
        ),
      ),
    );
  }

  function renderService(service) {
    if (!service?.counters) {
      fill(serviceBox);
      return;
    }
    const c = service.counters;
    const dropped = Object.entries(c.dropped || {}).filter(([, n]) => n > 0);
    fill(
      serviceBox,
      h('h3', {}, 'The service'),
      h(
        'p',
        { class: 'muted', dataset: { relayed: String(c.relayed) } },
        `${plural(c.received, 'frame')} received, ${c.relayed} relayed, ${c.lost} lost; dropped: `,
        dropped.length ? dropped.map(([k, n]) => `${n} ${k}`).join(', ') : 'none',
        '.',
      ),
    );
  }

  return {
    /** The tab was shown or hidden: the socket is open and the stream's poses apply only while it is shown. */
    shown(on) {
      if (on === shown) return;
      shown = on;
      epoch += 1;
      clearTimeout(pollTimer);
      clearInterval(tickTimer);
      if (on) {
        retry = 0;
        if (held.n && bodies) viewer.setBodyPoses(bodies, held.poses);
        refresh(epoch);
        tickTimer = setInterval(schedule, 500); // the rate and the countdown age without frames
        schedule();
      } else {
        cancelAnimationFrame(raf);
        raf = 0;
        // A replay stops with the tab (following the stream goes on when it is shown again).
        if (player.playing) player.pause();
        disconnect();
        viewer.setBodyPoses(null);
        showNumbers(); // hidden, but its numbers say the socket is closed
      }
    },
    dispose() {
      this.shown(false);
      player.dispose();
      disposed = true;
    },
  };
}
