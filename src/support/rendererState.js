// The renderer and scene state the stages change while they draw, saved before and restored after
// (in a `finally`, so an exception leaves the renderer as it was): three's own passes restore
// what they touch, and a user's next render must not inherit a stage's clear colour or target.
import { Color } from 'three';

/**
 * Runs `draw()` and puts back the render target, autoClear, clear colour and alpha, the shadow
 * maps' autoUpdate, and the scene's background and overrideMaterial as they were.
 * @param {import('three').WebGLRenderer} renderer
 * @param {import('three').Scene} scene
 * @param {() => T} draw
 * @returns {T}
 * @template T
 */
export function preservingRendererState(renderer, scene, draw) {
  const target = renderer.getRenderTarget();
  const autoClear = renderer.autoClear;
  const clearColor = renderer.getClearColor(new Color());
  const clearAlpha = renderer.getClearAlpha();
  const shadowAutoUpdate = renderer.shadowMap.autoUpdate;
  const { background, overrideMaterial } = scene;
  try {
    return draw();
  } finally {
    scene.background = background;
    scene.overrideMaterial = overrideMaterial;
    renderer.shadowMap.autoUpdate = shadowAutoUpdate;
    renderer.autoClear = autoClear;
    renderer.setClearColor(clearColor, clearAlpha);
    renderer.setRenderTarget(target);
  }
}
