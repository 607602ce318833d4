// A user's next render must not inherit a stage's clear colour or target: as three's own passes
// do, the stages put back what they change, in a `finally` so an exception does too.
import { Color } from 'three';

/** Colours to keep a clear colour in, reused (a frame nests a few of these calls). */
const _clearColors = [];

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
  const clearColor = renderer.getClearColor(_clearColors.pop() ?? new Color()); // nested calls each keep their own
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
    _clearColors.push(clearColor);
    renderer.setRenderTarget(target);
  }
}

/**
 * Runs `draw()` with the scene's world matrices held as they are: each renderer.render(scene)
 * would update them all again (three's matrixWorldAutoUpdate), and a frame's stages render the
 * scene several times after one update (SubsurfaceScenePass.collect).
 * @param {import('three').Object3D} scene
 * @param {() => T} draw
 * @returns {T}
 * @template T
 */
export function holdingMatrices(scene, draw) {
  const auto = scene.matrixWorldAutoUpdate;
  scene.matrixWorldAutoUpdate = false;
  try {
    return draw();
  } finally {
    scene.matrixWorldAutoUpdate = auto;
  }
}
