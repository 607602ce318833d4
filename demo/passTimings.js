// The demo's timing readout: per-stage GPU times from the pipeline's stage timer
// (dev/gpuTimer.js; the median of the last 30 of each), the CPU time of the render call, the frame
// rate and a history of frame times for the plot. On a software renderer (SwiftShader, llvmpipe)
// the "GPU" is the CPU, so the timer queries measure CPU time: `software` says so.
import { GpuStageTimer, median } from '../dev/gpuTimer.js';

const WINDOW = 30;
const HISTORY = 120;

/** The pipeline's stages in the order a frame runs them. */
export const STAGES = Object.freeze(['lightDepth', 'scene', 'blurH', 'blurV', 'dense', 'compose', 'transparent']);

/** Whether the WebGL context runs on a software rasterizer, from its renderer string. */
export function isSoftwareRenderer(rendererName) {
  return /swiftshader|llvmpipe|softpipe|software|basic render driver/i.test(rendererName ?? '');
}

/** The WebGL context's renderer string (unmasked where the browser allows). */
export function rendererName(gl) {
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER) ?? '');
}

/** A stage timer that measures nothing (GpuStageTimer's interface, no timer queries). */
const NO_STAGE_TIMER = Object.freeze({ available: false, begun: new Set(), poll() {}, medians: () => ({}), begin() {}, end() {} });

export class PassTimings {
  /**
   * @param {import('three').WebGLRenderer | import('three/webgpu').WebGPURenderer} renderer
   * @param {import('../src/SubsurfaceScattering.js').SubsurfaceScattering} sss timed through its stageTimer
   */
  constructor(renderer, sss) {
    // WebGPURenderer (?renderer=webgpu) has no stage timer here: the frame's CPU time only.
    this.stages = renderer.isWebGLRenderer ? new GpuStageTimer(renderer, { window: WINDOW }) : NO_STAGE_TIMER;
    // Each light's map is a stage of its own: counted, so the frame's light depth is their sum.
    this.mapsNow = 0;
    /** The light depth maps the last frame drew. */
    this.maps = 0;
    sss.stageTimer = {
      begin: (stage) => { if (stage === 'lightDepth') this.mapsNow++; this.stages.begin(stage); },
      end: (stage) => this.stages.end(stage),
    };
    this.sss = sss;
    this.renderer = renderer.isWebGLRenderer ? rendererName(renderer.getContext()) : `WebGPURenderer, ${renderer.backend.isWebGPUBackend ? 'WebGPU' : 'WebGL 2'} backend`;
    this.software = isSoftwareRenderer(this.renderer);
    this.frameTimes = [];
    this.frameIntervals = [];
    /** The last HISTORY frame intervals, ms (the plot). */
    this.history = [];
    this.lastFrame = null;
    /** The stages the last frame ran (the light depth pass is skipped while no light comes through). */
    this.ran = new Set();
  }

  /** True when per-stage times can be measured at all (timer queries). */
  get gpu() {
    return this.stages.available;
  }

  /** Call once per frame with the CPU time the frame's render call took. */
  frame(cpuMs) {
    const now = performance.now();
    if (this.lastFrame !== null) {
      keepLast(this.frameIntervals, now - this.lastFrame, WINDOW);
      keepLast(this.history, now - this.lastFrame, HISTORY);
    }
    this.lastFrame = now;
    keepLast(this.frameTimes, cpuMs, WINDOW);
    this.ran = new Set(this.stages.begun);
    this.stages.begun.clear();
    [this.maps, this.mapsNow] = [this.mapsNow, 0];
    this.stages.poll();
  }

  /** { stage: median ms, ..., cpu: ms, fps, skipped: stages timed before but not run by the last frame } */
  summary() {
    const medians = this.stages.medians();
    // Timed before and not now, or the light depth pass of a pipeline with a light (skipped while
    // the light reaches no subsurface mesh from behind, and with transmittance off).
    // Nothing is timed without a stage timer (WebGPU): no stage can be told skipped either.
    const skipped = this.lastFrame === null || this.stages === NO_STAGE_TIMER ? [] : STAGES.filter((s) => !this.ran.has(s)
      && (s in medians || (s === 'lightDepth' && this.sss.light !== null)));
    for (const s of skipped) delete medians[s];
    if (medians.lightDepth !== undefined) medians.lightDepth *= Math.max(1, this.maps); // the median map, times the maps drawn
    return { ...medians, skipped, cpu: median(this.frameTimes), fps: 1000 / median(this.frameIntervals) };
  }
}

function keepLast(list, value, length) {
  list.push(value);
  if (list.length > length) list.shift();
}
