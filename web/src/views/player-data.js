// The dock player's clock (pure, unit-tested; player.js draws its controls). One clock serves
// every timeline of the workspace: a planned motion and its simulated run, a result, and the
// live view's recording. The time stays within [start, stop]; Play advances it at 0.1×–4× real
// time (10× for long results), stopping at the end or looping; Step goes to the neighbouring
// sample (or by a fixed step); a live clock follows the newest frame of a recording that grows
// at its end, and Pause, a step or the scrubber leave it on a recorded frame until Go live.

/** The playback speeds offered (× real time): 0.1× to 4× everywhere, 10× for long results. */
export const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4, 10];

/**
 * The playback clock: the next time after `dt` seconds of wall time at `speed`, within
 * [start, stop]; with `loop` it wraps to the start, without it stops at the end.
 * @returns {{t: number, ended: boolean}}
 */
export function advance(t, dt, { speed, start, stop, loop }) {
  const span = stop - start;
  let next = t + dt * speed;
  if (!(span > 0)) return { t: start, ended: !loop };
  if (next < stop) return { t: Math.max(start, next), ended: false };
  if (!loop) return { t: stop, ended: true };
  next = start + ((next - start) % span);
  return { t: next, ended: false };
}

/**
 * The time one step from `t` (`dir` +1 forward, −1 back): the first sample of ascending `times`
 * after t (before it, going back), within [start, stop]; at the last (first) sample it stays.
 * Without samples, a hundredth of the span.
 */
export function stepTime(times, t, dir, { start, stop }) {
  const clampT = (x) => Math.max(start, Math.min(stop, x));
  const n = times?.length ?? 0;
  if (!n) return clampT(t + (dir * (stop - start)) / 100);
  const eps = 1e-9 * Math.max(1, Math.abs(stop - start));
  if (dir > 0) {
    for (let i = 0; i < n; i++) if (times[i] > t + eps) return clampT(times[i]);
    return clampT(times[n - 1]);
  }
  for (let i = n - 1; i >= 0; i--) if (times[i] < t - eps) return clampT(times[i]);
  return clampT(times[0]);
}

/**
 * A timeline's clock. `load` sets the timeline; `play`, `pause`, `seek`, `step`, `goLive` change
 * the state; `tick(dt)` advances it by `dt` seconds of wall time while playing.
 *
 * States: paused (at `time`), playing (advancing at `speed`), and for a live clock following
 * (the time is the recording's newest instant, `stop`, wherever it moves). A live clock that
 * plays the recording to its end goes back to following (it has caught up with the stream).
 */
export class PlayerClock {
  /** @param {{speed?: number, loop?: boolean, live?: boolean}} o */
  constructor({ speed = 1, loop = false, live = false } = {}) {
    this.start = 0;
    this.stop = 0;
    this.time = 0;
    this.speed = speed;
    this.loop = loop;
    this.live = live;
    this.playing = false;
    this.following = live;
    this.times = null; // ascending sample instants (Step goes from one to the next), or a function giving them
    this.dt = 0; // or a fixed step (s) where the samples are evenly spaced
  }

  /** Playing or following: the Play button offers Pause. */
  get running() {
    return this.playing || this.following;
  }

  clamp(t) {
    return Math.max(this.start, Math.min(this.stop, t));
  }

  /**
   * A new timeline [start, stop] with its sample instants `times` (or a function giving them,
   * for a recording that grows) or a fixed step `dt`, paused
   * at `at` (default its start); a live clock follows its end instead.
   */
  load({ start = 0, stop = 0, times = null, dt = 0, at } = {}) {
    this.start = start;
    this.stop = Math.max(start, stop);
    this.times = times;
    this.dt = dt > 0 ? dt : 0;
    this.playing = false;
    this.following = this.live && at === undefined;
    this.time = this.following ? this.stop : this.clamp(Number.isFinite(at) ? at : start);
    return this.time;
  }

  /**
   * The live recording's span moved (frames arrived, the oldest were dropped): following, the
   * time is its new end; otherwise it stays, moved into the span if the span left it behind.
   */
  extend(start, stop) {
    this.start = start;
    this.stop = Math.max(start, stop);
    this.time = this.following ? this.stop : this.clamp(this.time);
    return this.time;
  }

  /** Goes to time `t` (clamped) and holds there. */
  seek(t) {
    this.playing = false;
    this.following = false;
    this.time = this.clamp(Number.isFinite(t) ? t : this.time);
    return this.time;
  }

  /** One step forward (`dir` 1) or back (−1): the fixed step, or the neighbouring sample. */
  step(dir) {
    const d = dir < 0 ? -1 : 1;
    const times = typeof this.times === 'function' ? this.times() : this.times;
    return this.seek(this.dt > 0 ? this.time + d * this.dt : stepTime(times, this.time, d, this));
  }

  /** Plays from the time shown; at the end without loop from the start (a live clock goes live). */
  play() {
    if (this.following) return;
    if (this.time >= this.stop && !this.loop) {
      if (this.live) return this.goLive();
      this.time = this.start;
    }
    this.playing = true;
  }

  /** Holds the time shown (a live clock stops following; the recording goes on). */
  pause() {
    this.playing = false;
    this.following = false;
  }

  toggle() {
    if (this.running) this.pause();
    else this.play();
  }

  /** A live clock: back to the newest frame, following the stream. */
  goLive() {
    if (!this.live) return;
    this.playing = false;
    this.following = true;
    this.time = this.stop;
  }

  /** One of SPEEDS (anything else is ignored). */
  setSpeed(s) {
    const x = Number(s);
    if (SPEEDS.includes(x)) this.speed = x;
    return this.speed;
  }

  /**
   * `dt` seconds of wall time passed: while playing the time advances at the speed. Returns
   * true when playing ended (at the end without loop; a live clock then follows again).
   */
  tick(dt) {
    if (!this.playing) return false;
    const { t, ended } = advance(this.time, Math.max(0, dt), this);
    this.time = t;
    if (ended) {
      this.playing = false;
      if (this.live) this.goLive();
    }
    return ended;
  }
}
