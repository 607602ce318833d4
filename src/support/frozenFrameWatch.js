// Upgrading from 0.1, where `sss.enabled = false` turned the blur off: since 0.2 it skips the
// pass, as for any pass, and where nothing else draws the scene the composer shows its last frame,
// frozen. A disabled pass is never called, but EffectComposer reads `pass.enabled` every frame, so
// the accessor watches: on a read after the renderer has drawn something (info.render.frame moved)
// it asks whether anything drew the pass's scene in between (three calls scene.onAfterRender on
// every renderer.render(scene, ...)). Two such frames in a row without it: one console warning.
// A RenderPass drawing the scene each frame never leaves two in a row, whatever the pass order.
// While the pass is enabled nothing is watched; the scene's hook is there only while it is disabled.

/** Frames in a row without a draw of the scene before it counts as frozen. */
const FROZEN_FRAMES = 2;

/** pass → the renderer of its last frame (set by watchRendered). */
const renderers = new WeakMap();
/** pass → its watch, from the first time it is disabled after a frame. */
const watches = new WeakMap();

class FrozenFrameWatch {
  /** @param {import('three').WebGLRenderer} renderer @param {string} message @param {boolean} [warned] */
  constructor(renderer, message, warned = false) {
    this.renderer = renderer;
    this.message = message;
    this.warned = warned;
    this.scene = null;
    this.unhook = null;
  }

  /** Starts watching `scene` (the pass was just disabled). */
  start(scene) {
    this.stop();
    if (this.warned) return;
    this.frame = this.renderer.info.render.frame;
    this.frozen = 0;
    this.hook(scene);
  }

  /** Marks draws of `scene` through its onAfterRender, chained to whatever it had. */
  hook(scene) {
    const watch = this;
    const own = Object.hasOwn(scene, 'onAfterRender');
    const previous = scene.onAfterRender;
    const hooked = function (...args) {
      watch.drawn = true;
      return previous.apply(this, args);
    };
    scene.onAfterRender = hooked;
    this.scene = scene;
    this.drawn = false;
    this.unhook = () => {
      if (scene.onAfterRender !== hooked) return; // replaced by its owner since: leave theirs
      if (own) scene.onAfterRender = previous;
      else delete scene.onAfterRender;
    };
  }

  stop() {
    this.unhook?.();
    this.unhook = null;
    this.scene = null;
  }

  /** One read of `enabled` (false) by the composer, or by anyone: counts only once a frame was drawn. */
  check(scene) {
    if (this.scene === null) return;
    if (scene !== this.scene) this.start(scene); // the pass's scene was reassigned meanwhile
    const { frame } = this.renderer.info.render;
    if (frame === this.frame) return;
    this.frame = frame;
    this.frozen = this.drawn ? 0 : this.frozen + 1;
    this.drawn = false;
    if (this.frozen < FROZEN_FRAMES) return;
    this.warned = true;
    this.stop();
    console.warn(this.message);
  }
}

/**
 * Wraps the `enabled` accessor of `prototype` (booleanFields' boolean-only one) so that a disabled
 * pass whose scene nothing draws warns once with `message`. The pass calls `watchRendered` from
 * render() (the renderer whose frames to count) and `stopWatching` from dispose().
 * @param {object} prototype
 * @param {string} message
 */
export function warnWhenDisabledFreezes(prototype, message) {
  const { get, set } = Object.getOwnPropertyDescriptor(prototype, 'enabled');
  Object.defineProperty(prototype, 'enabled', {
    configurable: true,
    enumerable: false,
    get() {
      const enabled = get.call(this);
      if (enabled === false) watches.get(this)?.check(this.scene);
      return enabled;
    },
    set(value) {
      set.call(this, value);
      if (value) {
        watches.get(this)?.stop();
        return;
      }
      const renderer = renderers.get(this);
      if (!renderer) return; // never rendered: nothing on screen to freeze
      let watch = watches.get(this);
      if (watch?.renderer !== renderer) watches.set(this, (watch = new FrozenFrameWatch(renderer, message, watch?.warned)));
      watch.start(this.scene);
    },
  });
}

/** From the pass's render(): the renderer its frames go through. */
export function watchRendered(pass, renderer) {
  renderers.set(pass, renderer);
}

/** From the pass's dispose(): the scene's hook removed. */
export function stopWatching(pass) {
  watches.get(pass)?.stop();
}
