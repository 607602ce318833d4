// The demo's timing readout: per-stage GPU times from the pipeline's stage timer
// (dev/gpuTimer.js; the median of the last 30 of each), the CPU time of the render call and the
// frame rate.
import { GpuStageTimer, median } from '../dev/gpuTimer.js';

const WINDOW = 30;

export class PassTimings {
  /**
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('../src/SubsurfaceScattering.js').SubsurfaceScattering} sss timed through its stageTimer
   */
  constructor(renderer, sss) {
    this.stages = new GpuStageTimer(renderer, { window: WINDOW });
    sss.stageTimer = this.stages;
    this.frameTimes = [];
    this.frameIntervals = [];
    this.lastFrame = null;
  }

  /** True when per-stage GPU times can be measured. */
  get gpu() {
    return this.stages.available;
  }

  /** Call once per frame with the CPU time the frame's render call took. */
  frame(cpuMs) {
    const now = performance.now();
    if (this.lastFrame !== null) keepLast(this.frameIntervals, now - this.lastFrame);
    this.lastFrame = now;
    keepLast(this.frameTimes, cpuMs);
    this.stages.poll();
  }

  /** { stage: median ms, ..., cpu: ms, fps } */
  summary() {
    return { ...this.stages.medians(), cpu: median(this.frameTimes), fps: 1000 / median(this.frameIntervals) };
  }
}

function keepLast(list, value) {
  list.push(value);
  if (list.length > WINDOW) list.shift();
}
