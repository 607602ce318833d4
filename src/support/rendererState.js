// A user's next render must not inherit a stage's clear colour or target: as three's own passes
// do, the stages put back what they change, in a `finally` so an exception does too.
import { Color } from 'three';

/**
 * Runs `draw()` and puts back the renderer's and the scene's state.
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
