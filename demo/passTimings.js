// Per-pass GPU times from EXT_disjoint_timer_query_webgl2 (results arrive a few frames later;
// the median of the last 30 is shown), CPU frame time and fps otherwise.

const WINDOW = 30;
/** Queries older than this many are given up (e.g. after a context loss): bounded memory. */
const MAX_PENDING = 64;

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted.length ? sorted[sorted.length >> 1] : NaN;
}

export class PassTimings {
  /** @param {import('three').WebGLRenderer} renderer */
  constructor(renderer) {
    this.gl = renderer.getContext();
    this.ext = this.gl.getExtension('EXT_disjoint_timer_query_webgl2');
    this.pending = [];
    this.samples = new Map(); // name → last WINDOW times, ms
    this.frameTimes = [];
    this.frameIntervals = [];
    this.lastFrame = null;
  }

  /** True when per-pass GPU times can be measured. */
  get gpu() {
    return this.ext !== null;
  }

  /** Wraps `pass.render` so its GPU time is measured under `name`. */
  wrap(pass, name) {
    const render = pass.render.bind(pass);
    pass.render = (...args) => {
      if (!this.ext || !pass.enabled) return render(...args);
      const query = this.gl.createQuery();
      this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, query);
      try {
        return render(...args);
      } finally {
        this.gl.endQuery(this.ext.TIME_ELAPSED_EXT);
        this.pending.push({ name, query });
        while (this.pending.length > MAX_PENDING) this.gl.deleteQuery(this.pending.shift().query);
      }
    };
  }

  _record(name, ms) {
    const list = this.samples.get(name) ?? [];
    list.push(ms);
    if (list.length > WINDOW) list.shift();
    this.samples.set(name, list);
  }

  /** Call once per frame with the CPU time the frame's render call took. */
  frame(cpuMs) {
    const now = performance.now();
    if (this.lastFrame !== null) {
      this.frameIntervals.push(now - this.lastFrame);
      if (this.frameIntervals.length > WINDOW) this.frameIntervals.shift();
    }
    this.lastFrame = now;
    this.frameTimes.push(cpuMs);
    if (this.frameTimes.length > WINDOW) this.frameTimes.shift();
    if (!this.ext) return;
    const gl = this.gl;
    const disjoint = gl.getParameter(this.ext.GPU_DISJOINT_EXT);
    this.pending = this.pending.filter(({ name, query }) => {
      if (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) return true;
      if (!disjoint) this._record(name, gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6);
      gl.deleteQuery(query);
      return false;
    });
  }

  /** { passName: median ms, ..., cpu: ms, fps } */
  summary() {
    const out = {};
    for (const [name, list] of this.samples) out[name] = median(list);
    out.cpu = median(this.frameTimes);
    out.fps = 1000 / median(this.frameIntervals);
    return out;
  }
}
