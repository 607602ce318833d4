// window.demo: the page's test API, what the browser tests (test/browser/demo/) and the figure
// renderer (scripts/figures.js) drive.
import { readRenderTargetFloats } from '../dev/readback.js';
import { ATTACHMENTS } from '../src/2-scene-split/subsurfaceTarget.js';

/**
 * @param {object} demo the page's parts (demo/main.js)
 * @param {{ onChange: (key: string) => void, onFigure: Function, onPreset: Function, onReset: Function, onHash: () => void }} actions
 * @param {() => void} frame renders one frame
 */
export function testApi(demo, actions, frame) {
  const { renderer, composer, sss, state, panel, hud, outputPass } = demo;
  return {
    rig: demo.rig, renderer, composer, head: demo.head, sss, state, panel, timings: demo.timings, hud,
    /** The swaying leaves (demo/foliage.js): `setTime(seconds)` moves the wind of a still page. */
    foliage: demo.foliage,
    divider: demo.divider, controls: demo.controls,
    isStandIn: demo.head.isStandIn,
    /** 'webgl', or 'webgpu' on index.html?renderer=webgpu where the browser has WebGPU. */
    rendererKind: demo.rendererKind,
    /** The face centre, world units: where tests look for a lit face. */
    facePoint: demo.rig.facePoint,
    /** The messages shown for ignored hash values. */
    get problems() { return demo.problems; },
    /** Stops the animation loop (tests render on demand). */
    stop() { renderer.setAnimationLoop(null); },
    render() { frame(); },
    /** Sets a control's value as the panel would. */
    set(key, value) {
      state[key] = value;
      actions.onChange(key);
      panel.refresh();
    },
    /** Shows the view a URL hash describes, as an edited hash does (tests reuse one page so). */
    show(hash) {
      history.replaceState(null, '', hash ? `#${hash}` : location.pathname + location.search);
      actions.onHash();
    },
    figure: actions.onFigure,
    preset: actions.onPreset,
    reset: actions.onReset,
    /** Shows or hides everything over the image (header, panel, divider, timings, attribution). */
    chrome(visible) { document.body.classList.toggle('no-chrome', !visible); },
    /** Refreshes the timings overlay now (it updates itself twice a second while animating). */
    updateTimings() { hud.update(); },
    /** Reads the scene pass's surface attachment (linear depth, width) of the last frame. */
    readSurface() {
      return readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.SURFACE);
    },
    /** Renders once and reads the linear HDR image that OutputPass would receive. */
    async readHdr() {
      outputPass.enabled = false;
      composer.renderToScreen = false;
      try {
        composer.render();
        const target = composer.readBuffer;
        return { width: target.width, height: target.height, data: await readRenderTargetFloats(renderer, target) };
      } finally {
        outputPass.enabled = true;
        composer.renderToScreen = true;
      }
    },
  };
}
