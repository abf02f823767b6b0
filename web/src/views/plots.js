// uPlot charts of a motion: joint quantities against time with a time cursor the 3D view
// drives (a click on a chart seeks there), and a drive's motor operating points in the
// torque–speed plane with its envelope and the operating point at the cursor's time.

import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { torqueSpeedData, nearestIndex, tickLabels } from './motion-data.js';

/** Axis tick labels with as many decimals as the tick spacing needs (never a row of "0"). */
const ticks = (u, splits) => tickLabels(splits);

const COLORS = ['#1f5fa8', '#d03030', '#1e7b34', '#8a5a00', '#7030c0', '#0a8a8a', '#c04080', '#555'];
const CURSOR = '#f0a030';
const CONTACT = '#e01010';

function widthOf(el) {
  return Math.max(240, Math.floor(el.clientWidth || el.parentElement?.clientWidth || 400) - 4);
}

/** Keeps a chart as wide as its box. */
function follow(box, u) {
  const ro = new ResizeObserver(() => {
    const w = widthOf(box);
    if (Math.abs(w - u.width) > 2) u.setSize({ width: w, height: u.height });
  });
  ro.observe(box);
  return () => ro.disconnect();
}

/** A vertical line at time `getT()` (x scale) over the plotting area. */
function cursorLine(getT) {
  return (u) => {
    const t = getT();
    if (t === null || t === undefined) return;
    const x = u.valToPos(t, 'x', true);
    const { top, height, left, width } = u.bbox;
    if (x < left - 1 || x > left + width + 1) return;
    const ctx = u.ctx;
    ctx.save();
    ctx.strokeStyle = CURSOR;
    ctx.lineWidth = 2 * uPlot.pxRatio;
    ctx.beginPath();
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + height);
    ctx.stroke();
    ctx.restore();
  };
}

/** Dashed red vertical lines at the times `getTimes()` returns (e.g. first contacts). */
function markLines(getTimes) {
  return (u) => {
    const ts = getTimes?.() || [];
    if (!ts.length) return;
    const { top, height, left, width } = u.bbox;
    const ctx = u.ctx;
    ctx.save();
    ctx.strokeStyle = CONTACT;
    ctx.setLineDash([5 * uPlot.pxRatio, 4 * uPlot.pxRatio]);
    ctx.lineWidth = 1.5 * uPlot.pxRatio;
    for (const t of ts) {
      const x = u.valToPos(t, 'x', true);
      if (x < left - 1 || x > left + width + 1) continue;
      ctx.beginPath();
      ctx.moveTo(x, top);
      ctx.lineTo(x, top + height);
      ctx.stroke();
    }
    ctx.restore();
  };
}

/**
 * A uPlot chart over time in `box`, described for screen readers by `label`; a click seeks there.
 * `keepTime(t)` stores the cursor time its draw hook reads. Returns {u, setTime(t), destroy()}.
 */
function timeChart(box, opts, data, label, onSeek, keepTime) {
  const u = new uPlot(opts, data, box);
  u.root.setAttribute('role', 'img');
  u.root.setAttribute('aria-label', label);
  u.over.addEventListener('click', (e) => onSeek?.(u.posToVal(e.offsetX, 'x')));
  const unfollow = follow(box, u);
  return {
    u,
    setTime(x) {
      keepTime(x);
      u.redraw(false, false);
    },
    destroy() {
      unfollow();
      u.destroy();
    },
  };
}

/** The y axis label when every line has one unit, e.g. "[°/s]". */
function sameUnit(units) {
  const set = new Set(units);
  return set.size === 1 ? `[${units[0]}]` : undefined;
}

/**
 * One chart of `series` (arrays over traj.t), one line per joint; `marks()` gives times to mark
 * (first contacts). Returns {setTime(t), destroy()}.
 * @param {HTMLElement} box
 */
export function timePlot(box, { title, t, series, names, units, onSeek, marks }) {
  let time = 0;
  const opts = {
    title,
    width: widthOf(box),
    height: 200,
    scales: { x: { time: false } },
    cursor: { drag: { x: false, y: false } },
    series: [{ label: 't [s]' }, ...names.map((n, i) => ({ label: `${n} [${units[i]}]`, stroke: COLORS[i % COLORS.length], width: 1.5 }))],
    // The legend names the lines (no column of "--" values while the mouse is elsewhere).
    legend: { live: false },
    axes: [{ label: 't [s]', values: ticks }, { size: 64, values: ticks, label: sameUnit(units) }],
    hooks: { draw: [markLines(marks), cursorLine(() => time)] },
  };
  return timeChart(box, opts, [t, ...series], `${title} against time`, onSeek, (x) => (time = x));
}

/**
 * The torque–speed plane of one drive: operating points, ±continuous and ±peak torque lines,
 * ±max speed lines, and the point at the cursor's time. Returns {setTime(t), destroy()}.
 */
export function torqueSpeedPlot(box, { title, op, envelope }) {
  const { data, order } = torqueSpeedData(op, envelope);
  let marker = null; // index into op at the cursor's time
  const env = envelope || {};
  const line = (label, stroke, dash) => ({ label, stroke, width: 1.5, dash, points: { show: false }, spanGaps: true });
  const opts = {
    title,
    width: widthOf(box),
    height: 220,
    scales: { x: { time: false } },
    cursor: { drag: { x: false, y: false } },
    series: [
      { label: 'motor speed [rad/s]' },
      { label: 'operating points [N·m]', stroke: '#1f5fa8', paths: () => null, points: { show: true, size: 4, fill: '#1f5fa8' } },
      line('continuous torque', '#1e7b34', [6, 4]),
      line('−continuous torque', '#1e7b34', [6, 4]),
      line('peak torque', '#b3261e', []),
      line('−peak torque', '#b3261e', []),
    ],
    legend: { live: false },
    axes: [{ label: 'motor speed [rad/s]', values: ticks }, { label: 'torque [N·m]', size: 64, values: ticks }],
    hooks: {
      draw: [
        (u) => {
          const ctx = u.ctx;
          const { top, height } = u.bbox;
          ctx.save();
          ctx.strokeStyle = '#7030c0';
          ctx.setLineDash([4, 4]);
          ctx.lineWidth = 1.5 * uPlot.pxRatio;
          for (const v of [env.max_speed, env.max_speed == null ? null : -env.max_speed]) {
            if (v === null || v === undefined) continue;
            const x = u.valToPos(v, 'x', true);
            ctx.beginPath();
            ctx.moveTo(x, top);
            ctx.lineTo(x, top + height);
            ctx.stroke();
          }
          ctx.setLineDash([]);
          if (marker !== null && marker >= 0) {
            const x = u.valToPos(op.speed[marker], 'x', true);
            const y = u.valToPos(op.torque[marker], 'y', true);
            ctx.fillStyle = CURSOR;
            ctx.strokeStyle = '#000';
            ctx.lineWidth = 1;
            ctx.beginPath();
            ctx.arc(x, y, 6 * uPlot.pxRatio, 0, 2 * Math.PI);
            ctx.fill();
            ctx.stroke();
          }
          ctx.restore();
        },
      ],
    },
  };
  // The y range includes the envelope's lines.
  const ys = [...op.torque, env.peak_torque, env.continuous_torque].filter((v) => Number.isFinite(v)).map(Math.abs);
  const ymax = Math.max(...ys, 1e-9) * 1.15;
  opts.scales.y = { range: [-ymax, ymax] };
  const u = new uPlot(opts, data, box);
  u.root.setAttribute('role', 'img');
  u.root.setAttribute('aria-label', `${title}: operating points in the torque–speed plane`);
  u.root.dataset.points = String(order.length);
  const unfollow = follow(box, u);
  return {
    u,
    setTime(t) {
      marker = op.t?.length ? nearestIndex(op.t, t) : null;
      u.redraw(false, false);
    },
    destroy() {
      unfollow();
      u.destroy();
    },
  };
}

/**
 * A chart of result signals [{name, unit, t, y}], each with its own instants (joined on one
 * time axis, gaps spanned), with the time cursor; a click seeks there. Returns {setTime(t), destroy()}.
 */
export function signalPlot(box, { title, signals, onSeek }) {
  let time = null;
  const data = signals.length ? uPlot.join(signals.map((s) => [s.t, s.y])) : [[], []];
  const opts = {
    title,
    width: widthOf(box),
    height: 220,
    scales: { x: { time: false } },
    cursor: { drag: { x: false, y: false } },
    series: [
      { label: 't [s]' },
      ...(signals.length
        ? signals.map((s, i) => ({ label: s.unit && s.unit !== '1' ? `${s.name} [${s.unit}]` : s.name, stroke: COLORS[i % COLORS.length], width: 1.5, spanGaps: true, points: { show: false } }))
        : [{ label: '(no variables)' }]),
    ],
    axes: [{ label: 't [s]', values: ticks }, { size: 64, values: ticks }],
    hooks: { draw: [cursorLine(() => time)] },
  };
  return timeChart(box, opts, data, `${title}: ${signals.map((s) => s.name).join(', ') || 'no variables'} against time`, onSeek, (x) => (time = x));
}
