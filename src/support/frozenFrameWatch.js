// `sss.enabled = false` skips the pass, and where nothing else draws the scene the composer shows
// its last frame, frozen. A disabled pass is never called, but EffectComposer reads `enabled` every
// frame: on a read after a new frame (info.render.frame) the accessor asks whether anything drew the
// scene in between (scene.onAfterRender). Two frames in a row without: one console warning. The
// scene's hook is there only while the pass is disabled.

/** Frames in a row without a draw of the scene before it counts as frozen. */
const FROZEN_FRAMES = 2;

/** pass → the renderer of its last frame. */
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

  start(scene) {
    this.stop();
    if (this.warned) return;
    this.frame = this.renderer.info.render.frame;
    this.frozen = 0;
    this.hook(scene);
  }

  /** Chained to whatever onAfterRender the scene had. */
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

  /** A read of `enabled` (false): counts once a frame. */
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
 * Wraps `prototype`'s `enabled` accessor (booleanFields') to warn once with `message`; the pass
 * calls `watchRendered` from render() and `stopWatching` from dispose().
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

export function watchRendered(pass, renderer) {
  renderers.set(pass, renderer);
}

export function stopWatching(pass) {
  watches.get(pass)?.stop();
}
