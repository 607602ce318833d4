// The lab's leaves (issue 41), on `window.lab` beside its other scenes: thin DoubleSide planes 2 cm
// across (10 mm per unit), their front faces to a directional light of intensity π straight behind
// them (the camera, in front, sees their back faces), white unless tinted. Nothing here is part of
// the library.
//   swayingLeaves: two leaves, each bent towards or away from the light by a wind sway of the
//     user's (onBeforeCompile, each its own source, a `time` uniform made in the hook and kept the
//     way three's examples keep it), against the same bends made on the CPU (plain three.js geometry)
//   leafCopies: an original, its clone (tinted), its copy (.copy), an explicit twin of the clone and
//     a leaf carrying the mark of a material this page never made subsurface
//   uncomposedLeaf: one leaf whose hook inlines a chunk the split goes in at, beside three's own draw
import * as THREE from 'three';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';

/** The leaves' sways: GLSL for the hooks (in their source: two hooks, two sources) and the same on the CPU. */
const SWAYS = {
  a: (p, time) => { p.z += 0.15 * Math.sin(time + 3 * p.y); },
  b: (p, time) => { p.z += 0.25 * Math.cos(1.7 * time + 2 * p.x); },
};

function swayA(shader) {
  shader.uniforms.time = { value: 0 };
  shader.vertexShader = `uniform float time;\n${shader.vertexShader.replace('#include <begin_vertex>', '#include <begin_vertex>\n\ttransformed.z += 0.15 * sin( time + 3.0 * position.y );')}`;
  this.userData.shader = shader; // three's examples keep the shader to animate its uniforms
}

function swayB(shader) {
  shader.uniforms.time = { value: 0 };
  shader.vertexShader = `uniform float time;\n${shader.vertexShader.replace('#include <begin_vertex>', '#include <begin_vertex>\n\ttransformed.z += 0.25 * cos( 1.7 * time + 2.0 * position.x );')}`;
  this.userData.shader = shader;
}

const HOOKS = { a: swayA, b: swayB };

/** A leaf at (x, y): a plane `size` across, its front face to the light (−z). */
function leaf(material, x, y, size = 2, segments = 24) {
  const mesh = new THREE.Mesh(new THREE.PlaneGeometry(size, size, segments, segments), material);
  mesh.position.set(x, y, 0);
  mesh.rotation.y = Math.PI;
  return mesh;
}

/** The scene around leaves: the light straight behind, the camera in front. */
function leafScene(...meshes) {
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(30, 16 / 9, 1, 20);
  camera.position.set(0, 0, 8);
  const light = new THREE.DirectionalLight(0xffffff, Math.PI);
  light.position.set(0, 0, -10);
  Object.assign(light.shadow.camera, { left: -3, right: 3, bottom: -3, top: 3 });
  scene.add(light, light.target, ...meshes);
  return { scene, camera, light };
}

const white = (options = {}) => new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0, side: THREE.DoubleSide, ...options });

/** The lab's helpers (lab.js) bound to these scenes. */
export function leafScenes({ SSS, createRenderer, createComposer, read }) {
  const release = (...parts) => {
    for (const part of parts) part.dispose();
    parts.at(-1).forceContextLoss(); // the renderer, last
  };
  const diffuseOf = (renderer, sss) => read(renderer, sss._scenePass.renderTarget, ATTACHMENTS.DIFFUSE);

  /**
   * Two swaying leaves through the pipeline, hooked (`hooks`: 'before' or 'after' makeSubsurface,
   * per leaf) and bent on the CPU: the diffuse light (transmittance: the light straight behind) of
   * each, at `time` (set as an app does before each frame, once the hook kept its shader), and with
   * `remake` that of the hooked leaves after leaf b was removed and made subsurface again.
   */
  async function swayingLeaves({ width = 96, height = 54, hooks = { a: 'before', b: 'after' }, time = 1.3, remake = false } = {}) {
    const renderer = createRenderer(width, height);
    const composer = createComposer(renderer, { type: THREE.FloatType });
    const materials = { a: white(), b: white() };
    const hooked = leafScene(leaf(materials.a, -1.1, 0), leaf(materials.b, 1.1, 0));
    const sss = new SSS.SubsurfaceScattering({ ...hooked, worldUnitInMm: 10, type: THREE.FloatType });
    composer.addPass(sss);
    for (const name of ['a', 'b']) if (hooks[name] === 'before') materials[name].onBeforeCompile = HOOKS[name];
    for (const name of ['a', 'b']) sss.makeSubsurface(materials[name]);
    for (const name of ['a', 'b']) if (hooks[name] === 'after') materials[name].onBeforeCompile = HOOKS[name];
    const frame = () => {
      for (const material of Object.values(materials)) if (material.userData.shader) material.userData.shader.uniforms.time.value = time;
      composer.render();
    };
    frame(); // compiles: the hooks keep their shaders
    frame();
    const result = { width, height, hooked: await diffuseOf(renderer, sss), glError: renderer.getContext().getError() };
    if (remake) {
      sss.removeSubsurface(materials.b);
      sss.makeSubsurface(materials.b);
      frame();
      frame();
      result.remade = await diffuseOf(renderer, sss);
    }
    // The truth: the same bends made in the geometry (its normals as they were, as the hooks leave
    // them). A hooked mesh is fitted into the light's view by its bounding sphere (its hook may move
    // it anywhere): the truth keeps the unbent sphere and a hook that moves nothing, so both fall on
    // the same light texels.
    const bent = (name, x) => {
      const mesh = leaf(white(), x, 0);
      mesh.geometry.computeBoundingSphere();
      const position = mesh.geometry.attributes.position;
      const p = new THREE.Vector3();
      for (let i = 0; i < position.count; i++) {
        SWAYS[name](p.fromBufferAttribute(position, i), time);
        position.setXYZ(i, p.x, p.y, p.z);
      }
      mesh.geometry.computeBoundingBox();
      mesh.material.onBeforeCompile = () => {};
      sss.makeSubsurface(mesh.material);
      return mesh;
    };
    const truth = leafScene(bent('a', -1.1), bent('b', 1.1));
    Object.assign(sss, truth);
    composer.render();
    result.truth = await diffuseOf(renderer, sss);
    result.glError ||= renderer.getContext().getError();
    result.problems = [...sss.problems];
    release(sss, composer, renderer);
    return result;
  }

  /**
   * Copies of a subsurface leaf (three columns, two rows, as the camera sees them): the original
   * (upper left), its clone tinted 0.5 (upper middle), a copy made with .copy() (upper right), an
   * explicit twin of the clone (lower left), a leaf with the mark of a material this page never
   * made subsurface (lower middle). The diffuse light of a frame, of the next (the problems and
   * the materials the pipeline holds then), and after the original is removed.
   */
  async function leafCopies({ width = 96, height = 54 } = {}) {
    const renderer = createRenderer(width, height);
    const composer = createComposer(renderer, { type: THREE.FloatType });
    const original = white();
    const built = leafScene();
    const sss = new SSS.SubsurfaceScattering({ ...built, worldUnitInMm: 10, type: THREE.FloatType });
    composer.addPass(sss);
    sss.makeSubsurface(original, { widthMm: 0.5 });
    const clone = original.clone();
    clone.color.setScalar(0.5);
    const copy = white().copy(original);
    const twin = white({ color: new THREE.Color().setScalar(0.5) });
    sss.makeSubsurface(twin, { widthMm: 0.5 });
    const stranger = white();
    stranger.userData['three-separable-sss'] = THREE.MathUtils.generateUUID(); // as saved by another page
    stranger.name = 'Stranger';
    built.scene.add(leaf(original, -1.2, 0.6, 1, 1), leaf(clone, 0, 0.6, 1, 1), leaf(copy, 1.2, 0.6, 1, 1), leaf(twin, -1.2, -0.6, 1, 1), leaf(stranger, 0, -0.6, 1, 1));
    composer.render();
    const result = { width, height, first: await diffuseOf(renderer, sss), firstProblems: [...sss.problems] };
    composer.render();
    Object.assign(result, { second: await diffuseOf(renderer, sss), problems: [...sss.problems], materials: sss.materials.size });
    sss.removeSubsurface(original);
    composer.render();
    Object.assign(result, { removed: await diffuseOf(renderer, sss), materialsAfter: sss.materials.size, glError: renderer.getContext().getError() });
    release(sss, composer, renderer);
    return result;
  }

  /**
   * A leaf lit from the camera's side too, whose onBeforeCompile inlines three's
   * lights_fragment_end chunk (as three-custom-shader-material's expansion maps do), through the
   * pipeline and through three's RenderPass: both outputs, the problems of two frames.
   */
  async function uncomposedLeaf({ width = 96, height = 54 } = {}) {
    const renderer = createRenderer(width, height);
    const material = white({ name: 'Inlined' });
    material.onBeforeCompile = (shader) => {
      shader.fragmentShader = shader.fragmentShader.replace('#include <lights_fragment_end>', THREE.ShaderChunk.lights_fragment_end);
    };
    const built = leafScene(leaf(material, 0, 0));
    const front = new THREE.DirectionalLight(0xffffff, 2);
    front.position.set(1, 1, 10);
    built.scene.add(front);
    const outputOf = async (pass) => {
      const composer = createComposer(renderer, { type: THREE.FloatType });
      composer.addPass(pass);
      composer.render();
      composer.render();
      const output = await read(renderer, composer.readBuffer);
      composer.dispose();
      return output;
    };
    const sss = new SSS.SubsurfaceScattering({ ...built, worldUnitInMm: 10, type: THREE.FloatType });
    sss.makeSubsurface(material);
    const result = { width, height, output: await outputOf(sss), problems: [...sss.problems], glError: renderer.getContext().getError() };
    sss.dispose();
    result.three = await outputOf(new RenderPass(built.scene, built.camera));
    renderer.dispose();
    renderer.forceContextLoss();
    return result;
  }

  /**
   * A leaf whose hook reads a uniform of three's MeshStandardMaterial shader (its `diffuse`), which
   * the light's depth shader has not: the problems and the GL error of two frames.
   */
  async function throwingHookLeaf({ width = 96, height = 54 } = {}) {
    const renderer = createRenderer(width, height);
    const composer = createComposer(renderer, { type: THREE.FloatType });
    const material = white({ name: 'Tinted' });
    material.onBeforeCompile = (shader) => {
      shader.uniforms.diffuse.value.multiplyScalar(0.9);
      shader.vertexShader = shader.vertexShader.replace('#include <begin_vertex>', '#include <begin_vertex>\n\ttransformed.z += 0.1;');
    };
    const sss = new SSS.SubsurfaceScattering({ ...leafScene(leaf(material, 0, 0)), worldUnitInMm: 10, type: THREE.FloatType });
    composer.addPass(sss);
    sss.makeSubsurface(material);
    composer.render();
    composer.render();
    const result = { problems: [...sss.problems], glError: renderer.getContext().getError(), diffuse: await diffuseOf(renderer, sss) };
    release(sss, composer, renderer);
    return result;
  }

  return { swayingLeaves, leafCopies, uncomposedLeaf, throwingHookLeaf, leafScene, leaf, white };
}
