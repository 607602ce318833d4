// Warm-up (SubsurfaceScattering.compileAsync): the programs a frame draws with, compiled before the
// frame, through three's own renderer.compileAsync (in parallel where KHR_parallel_shader_compile
// exists). three keys a program by its shaders, defines and the state it is drawn in (the target
// bound: tone mapping and output colour space on the screen only), not by the material, and keeps
// it while a material uses it: a full-screen quad drawn with a pass's material into the pass's
// target compiles the program the pass then finds in three's cache.
import { BufferGeometry, Float32BufferAttribute, Mesh, OrthographicCamera, Scene } from 'three';

/** A quad with the attributes of three's FullScreenQuad (position, uv): the same program keys. */
const quad = new BufferGeometry();
quad.setAttribute('position', new Float32BufferAttribute([-1, 3, 0, -1, -1, 0, 3, -1, 0], 3));
quad.setAttribute('uv', new Float32BufferAttribute([0, 2, 0, 0, 2, 0], 2));
const quadCamera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);

/**
 * Compiles what `scene` draws from `camera` into `target` (null: the screen), through three's
 * renderer.compileAsync with the target bound (its state is part of the programs' keys).
 * @param {import('three').WebGLRenderer} renderer
 * @param {import('three').Object3D} scene
 * @param {import('three').Camera} camera
 * @param {import('three').WebGLRenderTarget|null} target
 * @returns {Promise<unknown>} resolved once every program is ready to draw with
 */
export function compileSceneInto(renderer, scene, camera, target) {
  const previous = renderer.getRenderTarget();
  renderer.setRenderTarget(target);
  try {
    return renderer.compileAsync(scene, camera);
  } finally {
    renderer.setRenderTarget(previous);
  }
}

/**
 * Compiles `materials` as full-screen passes drawn into `target` (null: the screen).
 * @param {import('three').WebGLRenderer} renderer
 * @param {Iterable<import('three').Material>} materials
 * @param {import('three').WebGLRenderTarget|null} target
 * @returns {Promise<unknown>}
 */
export function compilePassPrograms(renderer, materials, target) {
  const scene = new Scene();
  for (const material of materials) scene.add(new Mesh(quad, material));
  return compileSceneInto(renderer, scene, quadCamera, target);
}

/**
 * A copy of a ShaderMaterial with `defines` set over its own, sharing its uniforms (clone() would
 * copy them, and warns at render targets' textures): kept alive, it keeps the program of a variant
 * the material switches to per frame compiled until the material draws with it.
 * @param {import('three').ShaderMaterial} material
 * @param {Record<string, number|string>} defines
 * @returns {import('three').ShaderMaterial}
 */
export function definesVariant(material, defines) {
  const { uniforms } = material;
  material.uniforms = {};
  let copy;
  try {
    copy = material.clone();
  } finally {
    material.uniforms = uniforms;
  }
  copy.uniforms = uniforms;
  copy.defines = { ...material.defines, ...defines };
  return copy;
}
