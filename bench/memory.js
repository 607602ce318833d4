// The memory the pipeline allocates (browser side; bench/memoryRun.js drives it): the head drawn by
// a plain RenderPass, then by the pipeline in its place, in one composer on a WebGL 2 context
// whose storage calls are counted (dev/glAllocations.js). What the pipeline's frames add is its
// own: per pixel (textures and renderbuffers of the frame's size), the light maps (lightDepthSize²
// each, a point light's six faces 3 × 2 of them) and the small tables (the profiles', the
// footprints', the kernels').
import {
  DirectionalLight, HalfFloatType, Mesh, MeshStandardMaterial, SphereGeometry, SpotLight, Vector3, WebGLRenderTarget, WebGLRenderer,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { SubsurfaceScattering } from '/src/index.js';
import { HEAD_CENTRE, setLightDirection } from '/demo/headScene.js';
import { trackAllocations } from '/dev/glAllocations.js';
import { buildScene } from './scenes.js';

/** Two more lights behind the head beside the rig's key spot and the point light behind its ear. */
function extraLights(scene) {
  return [[-12, 6, -12], [12, 6, -12]].map((offset, i) => {
    const light = i === 0 ? new DirectionalLight(0xffffff, 1.5) : new SpotLight(0xffffff, 40, 0, Math.PI / 8);
    light.position.copy(HEAD_CENTRE).add(new Vector3(...offset));
    light.target.position.copy(HEAD_CENTRE);
    scene.add(light, light.target);
    return light;
  });
}

/** A marble and a milk ball beside the head, each its own profile. */
function profileBalls(scene) {
  const geometry = new SphereGeometry(1.1, 32, 16);
  return [['marble', -4.2], ['milk', 4.2]].map(([profile, x]) => {
    const ball = new Mesh(geometry, new MeshStandardMaterial({ color: 0xf2efe8 }));
    ball.position.copy(HEAD_CENTRE).add(new Vector3(x, -2.6, 1.5));
    scene.add(ball);
    return { ball, profile };
  });
}

/**
 * @param {object} o
 * @param {number} o.width @param {number} o.height
 * @param {number} [o.samples=0] MSAA of the composer's buffers (multisampling 'auto' follows it)
 * @param {number} [o.lights=1] transmitting lights, all behind the head: the key spot, the point
 *   light behind the ear, a directional and a spot light
 * @param {number} [o.profiles=1] 1, or 3: a marble and a milk ball beside the head in their own profiles
 * @param {object} [o.settings] pipeline settings
 * @param {boolean} [o.scatteringOff=false] then `scattering` false, and a frame more
 * @returns {Promise<object>} bytes per pixel, of the light maps and of the tables, and the allocations
 */
export async function measureMemory({ width, height, samples = 0, lights = 1, profiles = 1, settings = {}, scatteringOff = false }) {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2', { antialias: false });
  const tracker = trackAllocations(gl);
  const renderer = new WebGLRenderer({ canvas, context: gl });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  const built = await buildScene('head', { aspect: width / height });
  const { scene, camera, rig } = built;
  setLightDirection(rig, 175, 15); // from behind: each light's map is drawn
  rig.pointLight.visible = lights > 1;
  const lightList = [built.light, rig.pointLight, ...(lights > 2 ? extraLights(scene) : [])];
  const balls = profiles > 1 ? profileBalls(scene) : [];
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(width, height, { type: HalfFloatType, samples }));
  composer.renderToScreen = false;
  const plain = new RenderPass(scene, camera);
  composer.addPass(plain);
  composer.render();
  const before = new Set(tracker.live());
  const plainBytes = [...before].reduce((sum, a) => sum + a.bytes, 0);
  composer.removePass(plain);
  const sss = new SubsurfaceScattering({ scene, camera, light: lights === 0 ? null : lightList.slice(0, lights), worldUnitInMm: built.worldUnitInMm, ...settings });
  for (const material of built.subsurface) sss.makeSubsurface(material, { widthMm: built.widthMm });
  for (const { ball, profile } of balls) sss.makeSubsurface(ball.material, { widthMm: built.widthMm, profile });
  composer.addPass(sss);
  composer.render();
  composer.render();
  if (scatteringOff) {
    sss.scattering = false;
    composer.render();
  }
  const added = tracker.live().filter((a) => !before.has(a));
  // A point light's map holds its six faces side by side: its size is its target's.
  const mapSizes = new Set(sss._lightDepths.map(({ renderTarget }) => `${renderTarget.width}x${renderTarget.height}`));
  const kindOf = (a) => (a.width === width && a.height === height ? 'pixel' : mapSizes.has(`${a.width}x${a.height}`) ? 'lightMap' : 'table');
  const sum = (kind) => added.filter((a) => kindOf(a) === kind).reduce((total, a) => total + a.bytes, 0);
  const result = {
    width, height, samples, lights, profiles, settings, scatteringOff,
    plan: { blur: sss.plan.blur, groups: sss.plan.groups },
    lightMapsDrawn: sss._lightDepths.filter((lightDepth) => lightDepth.valid).length,
    bytesPerPixel: sum('pixel') / (width * height),
    lightMapBytes: sum('lightMap'),
    tableBytes: sum('table'),
    plainBytesPerPixel: plainBytes / (width * height), // the composer's buffers and three's (a RenderPass allocates none)
    allocations: added.map((a) => ({ kind: a.kind, size: `${a.width}x${a.height}`, samples: a.samples, internalFormat: `0x${a.internalFormat.toString(16)}`, bytes: a.bytes, of: kindOf(a) })),
    glError: gl.getError(),
  };
  sss.dispose();
  composer.dispose();
  balls[0]?.ball.geometry.dispose();
  for (const { ball } of balls) ball.material.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  return result;
}
