// GPU time per pipeline stage from EXT_disjoint_timer_query_webgl2 (which SwiftShader has too), for
// the demo's readout and the bench: set it as `sss.stageTimer` and the orchestrator calls
// begin(stage) / end(stage) around each stage of its frame. Results arrive a few frames late:
// `poll()` gathers the finished ones without waiting (the demo, every frame), `collect()` waits for
// all of them (the bench, between measurements). gl.finish() does not wait in Chromium; a query's
// result does. The extension allows one query at a time, so stages are timed one by one, never
// nested.

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

export class GpuStageTimer {
  /**
   * @param {import('three').WebGLRenderer} renderer
   * @param {{ window?: number, maxPending?: number }} [options] samples kept per stage (median over
   *   them); queries still pending beyond maxPending are given up (e.g. after a context loss)
   */
  constructor(renderer, { window = 30, maxPending = 256 } = {}) {
    this.gl = renderer.getContext();
    this.ext = this.gl.getExtension('EXT_disjoint_timer_query_webgl2');
    this.window = window;
    this.maxPending = maxPending;
    /** false: begin/end do nothing (the bench records only the frames it measures). */
    this.recording = true;
    this.active = null;
    this.pending = [];
    this.samples = new Map(); // stage → last `window` times, ms
    /** The stages begun since the caller last cleared it (the demo: per frame, to tell skipped stages). */
    this.begun = new Set();
  }

  /** True when GPU times can be measured at all. */
  get available() {
    return this.ext !== null;
  }

  begin(stage) {
    this.begun.add(stage);
    if (!this.ext || !this.recording || this.active) return;
    const query = this.gl.createQuery();
    this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, query);
    this.active = { stage, query };
  }

  end(stage) {
    if (!this.active || this.active.stage !== stage) return;
    this.gl.endQuery(this.ext.TIME_ELAPSED_EXT);
    this.pending.push(this.active);
    this.active = null;
    while (this.pending.length > this.maxPending) this.gl.deleteQuery(this.pending.shift().query);
  }

  /** Moves every finished query's time into `samples` (none when the GPU was disjoint). */
  poll() {
    if (!this.ext) return;
    const { gl } = this;
    const disjoint = gl.getParameter(this.ext.GPU_DISJOINT_EXT);
    this.pending = this.pending.filter(({ stage, query }) => {
      if (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) return true;
      if (!disjoint) this._record(stage, gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6);
      gl.deleteQuery(query);
      return false;
    });
  }

  /**
   * Waits for every pending query and returns their times in the order they were taken, then
   * forgets them: [{ stage, ms }] (empty when the extension is missing or the GPU was disjoint).
   */
  async collect() {
    const { gl, pending } = this;
    this.pending = [];
    if (!this.ext || pending.length === 0) return [];
    for (let tries = 0; tries < 2000; tries++) {
      if (gl.getQueryParameter(pending[pending.length - 1].query, gl.QUERY_RESULT_AVAILABLE)) break;
      await nextTask();
    }
    const disjoint = gl.getParameter(this.ext.GPU_DISJOINT_EXT);
    const times = pending.map(({ stage, query }) => ({ stage, ms: gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6 }));
    for (const { query } of pending) gl.deleteQuery(query);
    return disjoint ? [] : times;
  }

  _record(stage, ms) {
    const list = this.samples.get(stage) ?? [];
    list.push(ms);
    if (list.length > this.window) list.shift();
    this.samples.set(stage, list);
  }

  /** { stage: median ms over the kept samples } */
  medians() {
    return Object.fromEntries([...this.samples].map(([stage, list]) => [stage, median(list)]));
  }

  dispose() {
    for (const { query } of this.pending) this.gl.deleteQuery(query);
    this.pending = [];
  }
}

/** The SSS stage's GPU time of each frame or re-run, from collect()'s times: blurH + blurV, or dense. */
export function sssStageTimes(times) {
  const out = [];
  let horizontal = 0;
  for (const { stage, ms } of times) {
    if (stage === 'blurH') horizontal = ms;
    else if (stage === 'blurV') out.push(horizontal + ms);
    else if (stage === 'dense') out.push(ms);
  }
  return out;
}

/** The median of a list (NaN when empty). */
export function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const n = sorted.length;
  return n === 0 ? NaN : n % 2 ? sorted[(n - 1) / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}
