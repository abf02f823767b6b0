// The dock player: one set of controls for every timeline of the workspace (a motion and its
// simulated run, a result, the live view's recording): Play/Pause, « Step and Step », the
// scrubber, the clock, speed 0.1×–4× (10× where offered) and loop, and for the live view Go live.
// Its clock (player-data.js) holds the state; this draws it and runs it on animation frames.
// The box carries data-time and data-playing (and data-live for a live player), which the
// end-to-end tests read. Keys, while a control of the player has the focus (see KEYS): Space or
// K plays and pauses, ← → (or comma, period) step, Home and End go to the ends, G goes live.

import { h, fill, num } from '../ui.js';
import { PlayerClock, SPEEDS } from './player-data.js';

/** The player's keys (while one of its controls has the focus; the scrubber keeps its own arrows). */
export const KEYS = {
  ' ': 'toggle',
  k: 'toggle',
  ArrowLeft: 'back',
  ArrowRight: 'forward',
  ',': 'back',
  '.': 'forward',
  Home: 'start',
  End: 'end',
  g: 'live',
};

/**
 * @param {HTMLElement} box  where the controls go (with any heading given to `show`)
 * @param {object} o
 * @param {string} o.id  prefix of the controls' ids: `${id}-play`, `-scrub`, `-step`, `-step-back`, `-speed`, `-loop`, `-live`
 * @param {(t: number) => void} o.onTime  called whenever the time changes
 * @param {string} [o.label]  the scrubber's name (for screen readers)
 * @param {number[]} [o.speeds]  speeds offered (default 0.1×–4×)
 * @param {number} [o.clockDigits]  decimals of the clock
 * @param {number|null} [o.timeDigits]  decimals of data-time (null: the full number)
 * @param {boolean} [o.live]  a live timeline (the recording grows; Go live follows it)
 * @param {string} [o.unit]  what Step moves by, for its tooltip ("sample", "frame")
 */
export function createPlayer(box, { id, onTime, label = 'Time', speeds = SPEEDS.filter((s) => s <= 4), clockDigits = 3, timeDigits = null, live = false, unit = 'sample' }) {
  const clock = new PlayerClock({ live });
  let raf = 0;
  let last = 0;
  let ui = null; // the controls while shown
  box.dataset.playing = 'false';
  if (live) box.dataset.live = 'true';
  box.addEventListener('keydown', (e) => {
    if (!ui || e.ctrlKey || e.metaKey || e.altKey) return;
    // Typing in a field of the box's headings is not a command.
    const t = e.target;
    if (t.isContentEditable || t.tagName === 'TEXTAREA' || (t.tagName === 'INPUT' && !['range', 'checkbox'].includes(t.type))) return;
    const what = KEYS[e.key.length === 1 ? e.key.toLowerCase() : e.key];
    // The scrubber and the speed list keep their arrows, Home and End, the Loop box its Space;
    // Space on a button is taken here (play/pause) instead of clicking it.
    const own = e.target === ui.scrub || e.target.tagName === 'SELECT';
    const check = e.target.type === 'checkbox';
    if (!what || (own && what !== 'toggle' && what !== 'live') || (check && e.key === ' ') || (what === 'live' && !live)) return;
    e.preventDefault();
    const actions = {
      toggle: () => clock.toggle(),
      back: () => clock.step(-1),
      forward: () => clock.step(1),
      start: () => clock.seek(clock.start),
      end: () => clock.seek(clock.stop),
      live: () => clock.goLive(),
    };
    act(actions[what]);
  });
  // Space released on a focused button would click it: the key handler already acted.
  box.addEventListener('keyup', (e) => {
    if (ui && e.key === ' ' && e.target.tagName === 'BUTTON') e.preventDefault();
  });

  function sync() {
    const t = clock.time;
    if (ui) {
      // A scrubber being dragged keeps its own value.
      if (document.activeElement !== ui.scrub || clock.running) ui.scrub.value = String(t);
      ui.clock.textContent = live ? liveClock() : `${t.toFixed(clockDigits)} s / ${num(clock.stop)} s`;
      const text = clock.running ? 'Pause' : 'Play';
      if (ui.play.textContent !== text) ui.play.textContent = text;
      if (ui.live) {
        ui.live.disabled = clock.following;
        ui.live.setAttribute('aria-pressed', String(clock.following));
      }
    }
    box.dataset.time = timeDigits === null ? String(t) : t.toFixed(timeDigits);
    box.dataset.playing = String(clock.playing);
    if (live) box.dataset.live = String(clock.following);
    onTime(t);
  }

  function liveClock() {
    const t = clock.time;
    if (clock.following) return `${t.toFixed(clockDigits)} s · live`;
    const behind = clock.stop - t;
    return `${t.toFixed(clockDigits)} s · ${behind > 0 ? `${num(Number(behind.toFixed(3)))} s behind live` : 'newest frame'}`;
  }

  function frame(now) {
    raf = 0;
    if (!clock.playing) return;
    clock.tick((now - last) / 1000);
    last = now;
    sync();
    if (clock.playing) raf = requestAnimationFrame(frame);
  }

  function run() {
    cancelAnimationFrame(raf);
    raf = 0;
    if (!clock.playing) return;
    last = performance.now();
    raf = requestAnimationFrame(frame);
  }

  function act(f) {
    f();
    run();
    sync();
  }

  /**
   * Shows the controls for the timeline [start, stop] (`times`: its sample instants for Step, or
   * `dt`: a fixed step; `at`: the time to show, default the start) below `head` (headings, notes).
   */
  function show({ start = 0, stop = 0, times = null, dt = 0, at } = {}, ...head) {
    const scrub = h('input', { type: 'range', id: `${id}-scrub`, min: String(start), max: String(Math.max(start, stop)), step: dt > 0 ? String(dt) : 'any', value: String(start) });
    scrub.addEventListener('input', () => act(() => clock.seek(Number(scrub.value))));
    const out = h('output', { for: scrub.id, class: 'motion-clock' });
    const play = h('button', { type: 'button', id: `${id}-play`, title: 'Play or pause (Space, K)', 'aria-keyshortcuts': 'Space K', onclick: () => act(() => clock.toggle()) }, 'Play');
    const back = h('button', { type: 'button', id: `${id}-step-back`, class: 'step', 'aria-label': `Step back one ${unit}`, title: `Step back one ${unit} (←, comma)`, 'aria-keyshortcuts': 'ArrowLeft Comma', onclick: () => act(() => clock.step(-1)) }, '« Step');
    const fwd = h('button', { type: 'button', id: `${id}-step`, class: 'step', 'aria-label': `Step forward one ${unit}`, title: `Step forward one ${unit} (→, period)`, 'aria-keyshortcuts': 'ArrowRight Period', onclick: () => act(() => clock.step(1)) }, 'Step »');
    const speed = h('select', { id: `${id}-speed` }, speeds.map((s) => h('option', { value: String(s), selected: s === clock.speed }, `${s}×`)));
    speed.addEventListener('change', () => clock.setSpeed(speed.value));
    const loop = h('input', { type: 'checkbox', id: `${id}-loop`, checked: clock.loop });
    loop.addEventListener('change', () => (clock.loop = loop.checked));
    const goLive = live
      ? h('button', { type: 'button', id: `${id}-live`, class: 'go-live', title: 'Show the newest frame as it arrives', onclick: () => act(() => clock.goLive()) }, 'Go live')
      : null;
    ui = { scrub, clock: out, play, live: goLive };
    fill(
      box,
      ...head,
      h(
        'div',
        { class: 'player row' },
        play,
        back,
        fwd,
        goLive,
        h('label', { for: scrub.id, class: 'visually-hidden' }, label),
        scrub,
        out,
        h('span', { class: 'player-options' }, h('label', { for: speed.id }, 'Speed'), speed, h('span', { class: 'check' }, loop, h('label', { for: loop.id }, 'Loop'))),
      ),
    );
    clock.load({ start, stop, times, dt, at });
    run();
    sync();
  }

  return {
    show,
    /** Removes the controls (and stops), showing `content` instead. */
    clear(...content) {
      clock.pause();
      run();
      ui = null;
      fill(box, ...content);
      box.dataset.playing = 'false';
    },
    /** Pauses (a live player stops following). */
    pause: () => act(() => clock.pause()),
    /** Goes to time t and holds there (a click on a chart or a timeline mark). */
    seek: (t) => act(() => clock.seek(t)),
    /** Shows time t without changing whether it plays. */
    setTime(t) {
      clock.time = clock.clamp(t);
      sync();
    },
    /** A live player: the recording now spans [start, stop] (with these sample instants, if given). */
    extend(start, stop, times) {
      if (times !== undefined) clock.times = times;
      const before = clock.time;
      clock.extend(start, stop);
      if (ui) {
        ui.scrub.min = String(start);
        ui.scrub.max = String(clock.stop);
      }
      if (clock.time !== before || clock.following) sync();
      else if (ui) ui.clock.textContent = liveClock();
    },
    goLive: () => act(() => clock.goLive()),
    get time() {
      return clock.time;
    },
    get playing() {
      return clock.playing;
    },
    get following() {
      return clock.following;
    },
    dispose() {
      clock.pause();
      run();
      ui = null;
    },
  };
}
