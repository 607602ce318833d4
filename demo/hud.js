// The timings overlay: frame rate, per-pass milliseconds as bars (timer queries; marked as CPU
// times on a software renderer) and a plot of the last frame times. Updated twice a second.
import { STAGES } from './passTimings.js';

const NAMES = {
  lightDepth: 'light depth', scene: 'scene', blurH: 'blur H', blurV: 'blur V', dense: 'dense',
  compose: 'compose', transparent: 'transparent',
};

/** An element with text (no HTML strings: the demo runs under Trusted Types) and a class. */
function element(tag, text, className) {
  const e = document.createElement(tag);
  e.textContent = text;
  if (className) e.className = className;
  return e;
}

const format = (ms) => (ms >= 100 ? ms.toFixed(0) : ms >= 10 ? ms.toFixed(1) : ms.toFixed(2));

export class TimingsHud {
  /**
   * @param {HTMLElement} root the #hud element (holds .hud-fps, .hud-kind, .hud-passes, canvas)
   * @param {import('./passTimings.js').PassTimings} timings
   */
  constructor(root, timings) {
    this.root = root;
    this.timings = timings;
    this.fps = root.querySelector('.hud-fps');
    this.kind = root.querySelector('.hud-kind');
    this.passes = root.querySelector('.hud-passes');
    this.plot = root.querySelector('canvas');
    root.dataset.software = String(timings.software);
    this.kind.textContent = !timings.gpu
      ? 'no timer queries here: frame CPU time only'
      : timings.software
        ? 'software renderer: CPU ms per pass'
        : 'GPU ms per pass (timer queries)';
    this.kind.title = timings.renderer;
  }

  update() {
    const t = this.timings.summary();
    const fps = Number.isFinite(t.fps) ? t.fps.toFixed(t.fps >= 10 ? 0 : t.fps >= 1 ? 1 : 2) : '…';
    const cpu = Number.isFinite(t.cpu) ? format(t.cpu) : '…';
    const sub = element('span', `· render() ${cpu} ms`, 'hud-sub');
    sub.title = 'CPU time of the render call';
    this.fps.replaceChildren(element('b', fps), ' fps ', sub);
    const stages = STAGES.filter((s) => Number.isFinite(t[s]));
    const total = stages.reduce((sum, s) => sum + t[s], 0);
    const row = (s) => {
      const skipped = t.skipped.includes(s);
      const line = element('div', '', skipped ? 'hud-pass hud-skipped' : 'hud-pass');
      line.dataset.stage = s;
      if (skipped) {
        line.title = s === 'lightDepth'
          ? 'not run this frame: the light reaches no subsurface mesh from behind (or transmittance is off), so no map is needed'
          : 'not run this frame';
      }
      const bar = element('span', '', 'hud-bar');
      bar.style.setProperty('--share', !skipped && total > 0 ? (t[s] / total).toFixed(3) : '0');
      line.append(element('span', NAMES[s]), bar, element('span', skipped ? 'skipped' : format(t[s]), 'hud-ms'));
      return line;
    };
    this.passes.replaceChildren(...STAGES.filter((s) => stages.includes(s) || t.skipped.includes(s)).map(row));
    if (stages.length > 1) {
      const totalRow = element('div', '', 'hud-pass hud-total');
      totalRow.append(element('span', 'all passes'), element('span', '', 'hud-bar'), element('span', format(total), 'hud-ms'));
      this.passes.append(totalRow);
    }
    this.drawPlot();
  }

  /** Frame times of the last frames, newest on the right; the dashed line is the median. */
  drawPlot() {
    const { plot } = this;
    const history = this.timings.history;
    const ctx = plot.getContext('2d');
    const { width, height } = plot;
    ctx.clearRect(0, 0, width, height);
    if (history.length < 2) return;
    const max = Math.max(...history) * 1.1;
    const x = (i) => width - (history.length - 1 - i) * (width / 119);
    const y = (ms) => height - 2 - (ms / max) * (height - 12);
    ctx.strokeStyle = '#7fd1ff';
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    history.forEach((ms, i) => (i ? ctx.lineTo(x(i), y(ms)) : ctx.moveTo(x(i), y(ms))));
    ctx.stroke();
    ctx.fillStyle = '#aaa';
    ctx.font = '10px system-ui, sans-serif';
    ctx.fillText(`frame ms (max ${format(max / 1.1)})`, 2, 10);
  }
}
